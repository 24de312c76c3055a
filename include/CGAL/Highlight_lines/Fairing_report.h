// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_FAIRING_REPORT_H
#define CGAL_HIGHLIGHT_LINES_FAIRING_REPORT_H

#include <CGAL/Highlight_lines/Box_QP_report.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Highlight_lines {

/*!
\ingroup PkgHighlightLinesRef

What `fair_with_highlight_lines()` did.
*/
struct Fairing_report
{
  /// How the iteration ended.
  enum class Status {
    /// the largest displacement of a step fell below ε times the mean edge length (eq. 17), or
    /// the steps shrank so fast that all later ones together would stay below it, or the
    /// target value `F` became stationary under steps below 10 ε times it (also tested before
    /// the next program is solved, each step then counted as its program asked for it,
    /// `Iteration::relative_solution_displacement`; the mesh is then the iterate of lowest `F` if
    /// it is one of the last four)
    CONVERGED,
    /// the iteration bound was reached first; the mesh is the iterate of lowest `F`
    ITERATION_LIMIT,
    /// the visitor asked to stop; the mesh is the last iterate
    STOPPED_BY_VISITOR,
    /// two steps in a row could not move any vertex without flipping a face; the mesh is the
    /// iterate of lowest `F`
    STEP_BLOCKED,
    /// `F` stalled: five steps in a row held vertices back against flips, and none of them
    /// lowered `F` by 10^-3 of itself below its lowest value so far (on scans with folded
    /// triangles, whose energy the programs predict poorly, the steps would otherwise shrink
    /// slowly to ε while `F` wanders); the mesh is the iterate of lowest `F`
    STALLED
  };

  /// One iteration (§3.7): the energies of the current mesh when the iteration started, then
  /// the step it took.
  struct Iteration
  {
    /// `q_fair`: the fairness energy of the region chosen with `fairness_energy` (by default the
    /// variation of the mean curvature; the paper's is the discrete Willmore energy, eq. 6).
    double fairness_energy = 0;
    /// `q_diff`: the distance of the highlight lines to their desired OGH curves (eq. 10–14),
    /// divided by the cube of the region's length scale `sqrt(area(R))`.
    double difference_energy = 0;
    /// `F = ω1 q_fair + ω2 q_diff` (eq. 15).
    double target_value = 0;
    /// Largest |x_i| of the step taken.
    double max_displacement = 0;
    /// `max_displacement` divided by the mean edge length in the region: the quantity of the
    /// convergence test (eq. 17).
    double relative_max_displacement = 0;
    /// 1 when the step taken is the solution of a program; otherwise the smallest fraction of
    /// its displacement a vertex was given, where moving it further would have flipped a face.
    double step_scale = 1;
    /// 1 when the step taken is the solution of a program; above 1 where the steps shrank
    /// slowly and the step was accelerated towards the limit their tail predicts (from the
    /// last steps and solutions, within the trust region): the length of the step taken over
    /// the length of the program's solution.
    double extrapolation = 1;
    /// Largest |x_i| of the program's solution (before any extrapolation, and before vertices
    /// were held back against flips) divided by the mean edge length in the region: the step
    /// the program asked for. `CONVERGED`'s test of a stationary `F` measures the steps so.
    double relative_solution_displacement = 0;
    /// Movable vertices held back because the program's solution would have flipped a face
    /// around them (a face whose normal turns by more than 90° from its input normal): their
    /// bounds were tightened and the program solved again, or their displacement was scaled
    /// down. The other vertices move as solved.
    std::size_t restrained_vertices = 0;
    /// Programs solved again with tightened bounds in this iteration.
    std::size_t resolves = 0;
    /// Line pieces whose desired curve was found in the current highlight lines.
    std::size_t lines_targeted = 0;
    /// How the QP solver ended, with its iteration count and KKT residual.
    Box_QP_report solver;
  };

  /// How the iteration ended.
  Status status = Status::ITERATION_LIMIT;
  /// Number of iterations carried out.
  std::size_t iterations = 0;
  /// Number of movable vertices (§3.1).
  std::size_t number_of_movable_vertices = 0;
  /// Number of line pieces crossing the region that received a desired OGH curve.
  std::size_t number_of_lines_targeted = 0;
  /// Of these, the ones whose single OGH segment would have looped (a0 <= 0 or a1 <= 0) and
  /// got a two-segment curve instead.
  std::size_t number_of_two_segment_targets = 0;
  /// Line pieces crossing the region that got no target and rely on fairness alone: their
  /// OGH curve could not be made loop-free, their tangents are undefined, or the line ends
  /// inside the region (mesh border, pole, saddle) or is a loop inside it.
  std::size_t number_of_lines_without_target = 0;
  /// Triangles of the region folded in the input mesh (their normal opposes the vertex
  /// normals at their corners), as sliver triangles of a noisy triangulation can be. The
  /// cotangent weights of a folded triangle give the Willmore energy a large tangential part
  /// that `Fairness_energy::WILLMORE` lowers by bending the surface, at the expense of the
  /// highlight lines: when this is not zero, prefer `Fairness_energy::MEAN_CURVATURE`.
  std::size_t number_of_folded_triangles = 0;
  /// Triangles of the region with a corner below 5 degrees (needles and caps, as scans and
  /// remeshed CAD leave them): their cotangent weights (above 11) dominate the Willmore energy
  /// as folded ones do, if less violently. When this is not zero and the faired surface bends
  /// away from its surroundings, try `Fairness_energy::MEAN_CURVATURE`.
  std::size_t number_of_sliver_triangles = 0;
  /// One entry per iteration, plus a last one with the energies of the mesh returned (its step
  /// fields are zero).
  std::vector<Iteration> history;
  /// Whether the mesh returned is an earlier iterate than the last, because the fairing stopped
  /// short of convergence (`ITERATION_LIMIT`, `STEP_BLOCKED` or `STALLED`), or found `F`
  /// stationary (`CONVERGED`), after a step that raised `F`.
  bool returned_best_iterate = false;

  /// Whether the mesh returned comes from a second run, started from the region filled by
  /// `Polygon_mesh_processing::fair()` with uniform weights (a bi-Laplacian surface; its vertices
  /// also move tangentially). Moving along the vertex normals cannot undo a pit as deep as it is
  /// wide, whose walls' normals point across it: a first run that ends with vertices held back
  /// against flips (in one of its last two steps), two blocked steps, or without lowering `F`
  /// below the input's, is followed by a second one with the iterations it left of the bound,
  /// unless a sharp edge (60°) of the input meets the region's border. The second run is kept
  /// if it flips no face against the input and ends at a quarter of the first run's `F` or
  /// less; `history` then holds both runs' iterations and the energies of the mesh returned.
  /// Otherwise the first run's mesh is restored and this report is the first run's alone
  /// (the visitor has been called for the second run's iterations too).
  bool restarted_from_fill = false;
  /// With `restarted_from_fill`: the iterations of the first run (the first entries of
  /// `history`).
  std::size_t first_run_iterations = 0;

  /// Whether the iteration converged.
  bool converged() const { return status == Status::CONVERGED; }
};

/*!
\ingroup PkgHighlightLinesRef

The name of a fairing status, e.g. `"STEP_BLOCKED"`.
*/
inline const char* to_string(Fairing_report::Status status)
{
  switch (status) {
  case Fairing_report::Status::CONVERGED:
    return "CONVERGED";
  case Fairing_report::Status::ITERATION_LIMIT:
    return "ITERATION_LIMIT";
  case Fairing_report::Status::STOPPED_BY_VISITOR:
    return "STOPPED_BY_VISITOR";
  case Fairing_report::Status::STEP_BLOCKED:
    return "STEP_BLOCKED";
  case Fairing_report::Status::STALLED:
    return "STALLED";
  }
  return "UNKNOWN";
}

/*!
\ingroup PkgHighlightLinesRef

Thrown by `fair_with_highlight_lines()` when an iteration cannot be completed: the QP solver
reports a failure other than reaching its iteration limit (a stall in which no vertex can move
without flipping a face is not a failure: see `Fairing_report::Status::STEP_BLOCKED`). The mesh is
restored to exactly what it was before the call: the iterations listed in `report()`, carried out
before the failure, are undone too.
*/
class Fairing_failure : public std::runtime_error
{
public:
  /// Creates the exception with the text returned by `what()` and the report so far.
  Fairing_failure(const std::string& message, const Fairing_report& report)
      : std::runtime_error(message), report_(report)
  {
  }
  /// The report of the iterations up to the failure.
  const Fairing_report& report() const { return report_; }

private:
  Fairing_report report_;
};

} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_FAIRING_REPORT_H

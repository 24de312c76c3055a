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
    CONVERGED,         ///< the largest displacement fell below ε times the mean edge length
    ITERATION_LIMIT,   ///< the iteration bound was reached first
    STOPPED_BY_VISITOR ///< the visitor asked to stop
  };

  /// One iteration (§3.7): the energies of the current mesh when the iteration started, then
  /// the step it took.
  struct Iteration
  {
    /// `q_fair`: the discrete Willmore energy of the region (eq. 6, standard cotangent formula).
    double fairness_energy = 0;
    /// `q_diff`: the distance of the highlight lines to their desired OGH curves (eq. 10–14),
    /// divided by the cube of the region's length scale `sqrt(area(R))`.
    double difference_energy = 0;
    /// `F = ω1 q_fair + ω2 q_diff` (eq. 15).
    double target_value = 0;
    /// Largest |x_i| of the QP's solution.
    double max_displacement = 0;
    /// `max_displacement` divided by the mean edge length in the region: the quantity of the
    /// convergence test (eq. 17).
    double relative_max_displacement = 0;
    /// The fraction of the solution actually applied: 1, or less where the full step would
    /// have flipped a triangle (then the iteration does not count as converged).
    double step_scale = 1;
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
  /// One entry per iteration, plus a last one with the energies of the final mesh (its step
  /// fields are zero).
  std::vector<Iteration> history;

  /// Whether the iteration converged.
  bool converged() const { return status == Status::CONVERGED; }
};

/*!
\ingroup PkgHighlightLinesRef

Thrown by `fair_with_highlight_lines()` when an iteration cannot be completed (the QP solver
reports a failure other than reaching its iteration limit, or no step avoids flipping a
triangle). The mesh is restored to exactly what it was before the call: the iterations listed
in `report()`, carried out before the failure, are undone too.
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

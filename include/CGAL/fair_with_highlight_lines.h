// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_FAIR_WITH_HIGHLIGHT_LINES_H
#define CGAL_FAIR_WITH_HIGHLIGHT_LINES_H

#include <CGAL/Highlight_lines/Active_set_box_QP_solver.h>
#include <CGAL/Highlight_lines/Fairing_report.h>
#include <CGAL/Highlight_lines/Fairness_energy.h>
#include <CGAL/Highlight_lines/Highlight_line_sweeper.h>
#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/Highlight_lines/Light_setup.h>
#include <CGAL/Highlight_lines/parameters.h>
#include <CGAL/Highlight_lines/internal/fairing/face_region.h>
#include <CGAL/Highlight_lines/internal/fairing/fairing.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <functional>
#include <algorithm>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {

namespace Highlight_lines {
namespace internal {

struct Accept_every_iteration
{
  bool operator()(const Fairing_report::Iteration&) const { return true; }
};

} // namespace internal
} // namespace Highlight_lines

// One \cgalParam... command per line, as in CGAL's reference pages: not reflowed.
// clang-format off
/*!
\ingroup PkgHighlightLinesRef

Fairs a region of a triangle mesh so that the surface becomes fair and its highlight lines
run smoothly through the region (§3 of the paper, as completed by the package's
specification).

Only the movable vertices of the region move, each along its normal (see below); everything
outside their support is left exactly as it was, in particular every vertex outside the region
with its normal, and every highlight node outside the region. Each iteration minimises
`F = ω1 q_fair + ω2 q_diff` (eq. 15) under bounds `|x_i| <= r_i` with a bound-constrained QP
solver, moves the vertices without flipping a face, and recomputes the highlight lines around
the region; it stops when the step's `max |x_i| / ē < ε` (eq. 17, `ē` the mean edge length in
the region), when the steps shrink so fast that all later ones together would stay below
`ε ē` (a geometric tail estimated from the last three steps), when `F` is stationary (over the
last three steps, each below `10 ε ē`, it fell by less than `10^-3` of itself per step; also
tested before the next program is solved, with the steps as the programs asked for them, and
then the iterate of lowest `F` is returned if it is one of the last four), or after the iteration
bound.

- *Step control*: `r_i = μ b_i`, `b_i` eq. 16's bound (half the shortest edge at `V_i`) and
  `μ` a trust-region factor for the whole region: it starts at 2, doubles (up to 64) when a step
  lowered `F` by at least 3/4 of what the program predicted and some vertex used its whole
  bound, and halves when `F` fell by less than 1/4 of it; `r_i` stays between `b_i / 1024` and
  `4 b_i + ē`.
- *No flips*: a face *flips* when its normal turns by more than 90° from its normal in the
  input mesh, or when it degenerates; a face already folded in the input (its normal opposes
  the sum of its corners' vertex normals) only has to stay non-degenerate. Where a step would
  flip faces, only the vertices of those faces are held back (their bounds are tightened and
  the program solved again; failing that, their displacements are scaled down, down to zero):
  one bad triangle never stops the others. The report counts the vertices held back.
- *Stalls are not failures*: if the iteration bound is reached, two steps in a row cannot
  move any vertex, or five steps in a row held back against flips do not lower `F` below its
  lowest value (scans with folded triangles), the fairing stops and leaves the mesh at the
  iterate of lowest `F`, with the report's status saying why (`ITERATION_LIMIT`,
  `STEP_BLOCKED`, `STALLED`).

- *Inside the region*: a vertex is inside when all its faces are in the region and it is not
  on a mesh border; a highlight node is inside when it lies inside an edge whose two faces are
  in the region, or on a vertex inside. *Movable vertices* are the vertices inside whose
  neighbours are all inside: the vertices of the region that are not support vertices of any
  vertex or node outside the region.
- *Desired highlight lines*: each maximal part of a highlight line inside the region between
  two delimiting nodes outside it gets an optimized geometric Hermite (OGH) curve, with end
  tangents estimated from the line outside the region. Where a single OGH segment would loop
  (`a0 <= 0` or `a1 <= 0`), a two-segment curve is used, and if that fails too the part gets
  no target (counted in the report). Lines that end inside the region, and loops inside it,
  get no target.
- *q_fair* is, by default, the variation of the mean curvature over the region (beyond the
  paper: its minimisers continue the surrounding curvature across the region, and end closest
  to the surface that should be there); with `fairness_energy`, the paper's discrete Willmore
  energy with the standard cotangent formula `K = 1/(2A) Σ (cot α + cot β)(V_i − V_j)` (eq. 8 as
  printed lacks the factor 1/2), or its normal part (see `Highlight_lines::Fairness_energy`).
  Weights and areas are held fixed during an iteration. *q_diff* is eq. 10–14 in
Gauss–Newton form, divided by `area(R)^{3/2}` so that the result commutes with uniform scaling of
mesh and lights.

\tparam TriangleMesh a model of `MutableFaceGraph` whose faces are triangles
\tparam FaceRange a range of `face_descriptor`
\tparam GeomTraits a model of `Kernel`

\param tm the mesh, modified in place through the vertex point map
\param region the faces of the region to fair
\param lights the light setup whose highlight lines are to run smoothly
\param np an optional sequence of named parameters among:
  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `tm`; the fairing writes the new positions through it}
      \cgalParamType{a class model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `GeomTraits::Point_3` as value type}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
    \cgalParamNEnd
    \cgalParamNBegin{face_index_map}
      \cgalParamDescription{a property map associating to each face of `tm` a unique index between `0` and `num_faces(tm) - 1`}
      \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type}
      \cgalParamDefault{an internal property map of `tm` if there is one, otherwise a dynamic one initialised here}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_iterations}
      \cgalParamDescription{the bound on the number of iterations}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{`50`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::fairness_weight}
      \cgalParamDescription{ω1, the weight of the fairness term `q_fair` in the target function}
      \cgalParamType{`double`}
      \cgalParamDefault{`1`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::difference_weight}
      \cgalParamDescription{ω2, the weight of the highlight line term `q_diff` in the target function}
      \cgalParamType{`double`}
      \cgalParamDefault{`1`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::fairness_energy}
      \cgalParamDescription{the fairness term: the variation of the mean curvature (curvature-continuous; the closest repair of real surfaces), the Willmore energy of the paper, or its normal part (the squared mean curvature), which slivers and folded triangles do not dominate}
      \cgalParamType{`Highlight_lines::Fairness_energy`}
      \cgalParamDefault{`Highlight_lines::Fairness_energy::CURVATURE_VARIATION`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::convergence_threshold}
      \cgalParamDescription{ε of eq. 17: the fairing has converged when the largest displacement of an iteration is below ε times the mean edge length of the region}
      \cgalParamType{`double`}
      \cgalParamDefault{`0.001`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::qp_solver}
      \cgalParamDescription{the solver of the quadratic program of each iteration, passed with `std::ref`}
      \cgalParamType{a class model of `BoxConstrainedQuadraticProgramSolver`, as a `std::reference_wrapper`}
      \cgalParamDefault{a `Highlight_lines::Active_set_box_QP_solver`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::fairing_visitor}
      \cgalParamDescription{called after each iteration; returning `false` stops the fairing}
      \cgalParamType{a callable with signature `bool(const Highlight_lines::Fairing_report::Iteration&)`}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::neighborhood_rings}
      \cgalParamDescription{rings of faces around the region on which highlight lines are recomputed (the tangents are estimated there)}
      \cgalParamType{`int`}
      \cgalParamDefault{`3`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::keep_completed_iterations}
      \cgalParamDescription{on a failure (an exception from the solver's report, the visitor or the point map), leave the mesh as after the last completed iteration instead of restoring it to what it was before the call}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::level_range}
      \cgalParamDescription{as for `compute_highlight_lines()`}
      \cgalParamType{`std::pair<int, int>`}
      \cgalParamDefault{all lights}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::max_levels_per_edge}
      \cgalParamDescription{as for `compute_highlight_lines()`}
      \cgalParamType{`std::size_t`}
      \cgalParamDefault{`256`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

\returns a report of the iterations.

\throws Highlight_lines::Invalid_input for an empty region, a face not of `tm`, a region
without movable vertex, a non-triangle or degenerate face or a non-finite coordinate around
the region, or an invalid parameter; the mesh is untouched.
\throws Highlight_lines::Fairing_failure if the solver reports a failure (other than its
iteration limit); the mesh is restored to exactly what it was before the call (or, with
`keep_completed_iterations(true)`, to what it was after the last completed iteration). Any
exception thrown by the visitor or the property maps restores the mesh in the same way before it
propagates.
*/
// clang-format on
template <typename TriangleMesh, typename FaceRange, typename GeomTraits,
          typename NamedParameters = parameters::Default_named_parameters>
Highlight_lines::Fairing_report
fair_with_highlight_lines(TriangleMesh& tm, const FaceRange& region,
                          const Highlight_lines::Light_setup<GeomTraits>& lights,
                          const NamedParameters& np = parameters::default_values())
{
  namespace HL = Highlight_lines;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::get_parameter_reference;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::type Vertex_point_map;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point;

  const Vertex_point_map vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                                                get_property_map(CGAL::vertex_point, tm));
  const auto fim = get_initialized_face_index_map(tm, np);

  HL::internal::Fairing_options options;
  options.fairness_weight =
      choose_parameter(get_parameter(np, HL::internal_np::fairness_weight), 1.0);
  options.difference_weight =
      choose_parameter(get_parameter(np, HL::internal_np::difference_weight), 1.0);
  options.fairness_energy = choose_parameter(get_parameter(np, HL::internal_np::fairness_energy),
                                             HL::Fairness_energy::CURVATURE_VARIATION);
  options.convergence_threshold =
      choose_parameter(get_parameter(np, HL::internal_np::convergence_threshold), 0.001);
  const auto iterations =
      choose_parameter(get_parameter(np, internal_np::number_of_iterations), 50);
  options.neighborhood_rings =
      choose_parameter(get_parameter(np, HL::internal_np::neighborhood_rings), 3);
  options.window = HL::Highlight_line_sweeper<TriangleMesh>::level_window(np);
  auto bad = [](const std::string& what) {
    throw HL::Invalid_input(HL::Invalid_input::Problem::INVALID_PARAMETER,
                            "fair_with_highlight_lines(): " + what);
  };
  if (!(options.fairness_weight >= 0) || !(options.difference_weight >= 0) ||
      !std::isfinite(options.fairness_weight) || !std::isfinite(options.difference_weight) ||
      options.fairness_weight + options.difference_weight == 0)
    bad("the weights must be finite, non-negative and not both zero");
  if (!(options.convergence_threshold > 0) || !std::isfinite(options.convergence_threshold))
    bad("the convergence threshold must be a positive number");
  if (!(iterations >= 1))
    bad("number_of_iterations must be at least 1");
  options.max_iterations = std::size_t(iterations);
  if (options.fairness_energy != HL::Fairness_energy::WILLMORE &&
      options.fairness_energy != HL::Fairness_energy::MEAN_CURVATURE &&
      options.fairness_energy != HL::Fairness_energy::CURVATURE_VARIATION)
    bad("fairness_energy must be Fairness_energy::WILLMORE, MEAN_CURVATURE or CURVATURE_VARIATION "
        "(got the value " +
        std::to_string(static_cast<int>(options.fairness_energy)) + ")");
  if (!(options.neighborhood_rings >= 2))
    bad("neighborhood_rings must be at least 2 (tangents need two nodes outside the region)");

  const auto region_set = HL::internal::checked_region(tm, region, fim);
  const auto neighborhood = HL::internal::neighborhood(tm, region_set, options.neighborhood_rings);

  HL::Active_set_box_QP_solver default_solver;
  auto& solver =
      choose_parameter(get_parameter_reference(np, HL::internal_np::qp_solver), default_solver);
  typedef std::remove_reference_t<decltype(solver)> Solver;
  const auto visitor = choose_parameter(get_parameter(np, HL::internal_np::fairing_visitor),
                                        HL::internal::Accept_every_iteration());

  // Everything that can be refused is refused before the mesh is touched.
  HL::internal::Fairing<TriangleMesh, Vertex_point_map, GeomTraits, Solver> fairing(
      tm, region_set, neighborhood, vpm, lights, options, solver);

  // Transaction: only movable vertices are ever written; keep them to restore on failure.
  std::vector<std::pair<vertex_descriptor, Point>> saved;
  for (int v : fairing.region().movable) {
    const vertex_descriptor vd = fairing.engine().local_mesh().vertex_handles[std::size_t(v)];
    saved.emplace_back(vd, get(vpm, vd));
  }
  const bool keep_completed =
      choose_parameter(get_parameter(np, HL::internal_np::keep_completed_iterations), false);
  try {
    return fairing.run(std::function<bool(const HL::Fairing_report::Iteration&)>(visitor));
  } catch (...) {
    for (const auto& entry : keep_completed ? fairing.checkpoint() : saved)
      put(vpm, entry.first, entry.second);
    throw;
  }
}

} // namespace CGAL

#endif // CGAL_FAIR_WITH_HIGHLIGHT_LINES_H

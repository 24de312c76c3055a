// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_FAIRING_BUILDING_BLOCKS_H
#define CGAL_HIGHLIGHT_LINES_FAIRING_BUILDING_BLOCKS_H

#include <CGAL/fair_with_highlight_lines.h>

#include <vector>

namespace CGAL {
namespace Highlight_lines {

/// \cond SKIP_IN_MANUAL
namespace internal {
// The fairing problem of fair_with_highlight_lines() without the iteration: what the building
// blocks below report. It only reads the mesh.
template <typename TriangleMesh, typename FaceRange, typename GeomTraits, typename NamedParameters>
auto fairing_problem(const TriangleMesh& tm, const FaceRange& region,
                     const Light_setup<GeomTraits>& lights, const NamedParameters& np)
{
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type Vertex_point_map;
  const Vertex_point_map vpm = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
      get_const_property_map(CGAL::vertex_point, tm));
  Fairing_options options;
  options.neighborhood_rings = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, internal_np::neighborhood_rings), 3);
  options.window = Highlight_line_sweeper<TriangleMesh>::level_window(np);
  const auto region_set = checked_region(tm, region, get_initialized_face_index_map(tm, np));
  return Fairing_problem<TriangleMesh, Vertex_point_map, GeomTraits>(
      tm, region_set, neighborhood(tm, region_set, (std::max)(options.neighborhood_rings, 2)), vpm,
      lights, options);
}
} // namespace internal
/// \endcond

/*!
\ingroup PkgHighlightLinesRef

Writes the movable vertices of a fairing region (§3.1): the vertices that
`fair_with_highlight_lines()` may move. See there for the exact definition.

\param tm the mesh
\param region the faces of the region
\param out an output iterator accepting `vertex_descriptor`
\param np as for `fair_with_highlight_lines()` (`vertex_point_map`, `face_index_map`)
\throws Invalid_input as `fair_with_highlight_lines()`, including when there is no movable vertex.
*/
template <typename TriangleMesh, typename FaceRange, typename OutputIterator,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
OutputIterator movable_vertices(const TriangleMesh& tm, const FaceRange& region, OutputIterator out,
                                const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type Vertex_point_map;
  const Vertex_point_map vpm = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
      get_const_property_map(CGAL::vertex_point, tm));
  const int rings = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, internal_np::neighborhood_rings), 3);
  const auto region_set =
      internal::checked_region(tm, region, get_initialized_face_index_map(tm, np));
  // The local mesh of the fairing (its neighbourhood, checked as the fairing checks it) and
  // its region; no lights, no energy.
  const internal::Model_engine<TriangleMesh, Vertex_point_map, CGAL::Sequential_tag> engine(
      tm, vpm,
      parameters::face_range(internal::neighborhood(tm, region_set, (std::max)(rings, 2))));
  internal::Fairing_region fairing_region;
  internal::build_fairing_region(
      tm, engine.local_mesh(), [&region_set](auto f) { return region_set.count(f) != 0; },
      fairing_region);
  internal::require_movable_vertex(fairing_region);
  for (int v : fairing_region.movable)
    *out++ = engine.local_mesh().vertex_handles[std::size_t(v)];
  return out;
}

/*!
\ingroup PkgHighlightLinesRef

Writes the desired highlight lines of a fairing region (§3.2, the blue curves of the paper's
figure 7b): for each part of a highlight line crossing the region, the OGH curve between its
delimiting nodes, sampled at `samples` points evenly spaced in arc length, as a
`std::vector<Point_3>`.

\param tm the mesh
\param region the faces of the region
\param lights the light setup
\param out an output iterator accepting `std::vector<GeomTraits::Point_3>`
\param samples the number of points per curve (at least 2)
\param np as for `fair_with_highlight_lines()`
*/
template <typename TriangleMesh, typename FaceRange, typename GeomTraits, typename OutputIterator,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
OutputIterator
desired_highlight_lines(const TriangleMesh& tm, const FaceRange& region,
                        const Light_setup<GeomTraits>& lights, OutputIterator out,
                        std::size_t samples = 32,
                        const NamedParameters& np = CGAL::parameters::default_values())
{
  auto problem = internal::fairing_problem(tm, region, lights, np);
  Fairing_report report;
  problem.make_targets(report);
  samples = (std::max)(samples, std::size_t(2));
  for (const auto& line : problem.desired_lines()) {
    std::vector<typename GeomTraits::Point_3> polyline;
    for (std::size_t i = 0; i < samples; ++i) {
      const auto p = line.curve.point_at_arc_length_fraction(double(i) / double(samples - 1));
      polyline.emplace_back(p[0], p[1], p[2]);
    }
    *out++ = std::move(polyline);
  }
  return out;
}

} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_FAIRING_BUILDING_BLOCKS_H

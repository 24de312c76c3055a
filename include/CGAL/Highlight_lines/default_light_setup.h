// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_DEFAULT_LIGHT_SETUP_H
#define CGAL_HIGHLIGHT_LINES_DEFAULT_LIGHT_SETUP_H

#include <CGAL/Highlight_lines/Highlight_line_sweeper.h>
#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/Highlight_lines/Light_setup.h>
#include <CGAL/Highlight_lines/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Highlight_lines {

/*!
\ingroup PkgHighlightLinesRef

A light setup that shows a mesh well without any tuning, as a designer's light tunnel would:
the light plane lies above the mesh at a distance of one bounding-box diagonal, facing it;
"above" is along the axis of smallest bounding-box extent (the height of a car body), the
lights run along the axis of largest extent, and the spacing is chosen so that about
`number_of_lines` lights fall within the central 90 % of the highlight distance values of
the vertices facing the plane.

\tparam TriangleMesh a model of `FaceGraph` whose faces are triangles
\param tm the mesh
\param np an optional sequence of named parameters among `vertex_point_map`,
`Highlight_lines::parameters::face_range` (the bounding box and the distance values are
taken on these faces only), `Highlight_lines::parameters::crease_edge_map` (the distance values
of the model cut along the creases, see \ref hl_creases) and
`Highlight_lines::parameters::number_of_lines` (default 20).

\throws Invalid_input if the mesh (range) is empty or flat in a way that leaves no spread
of distance values, or for the input problems listed at `compute_highlight_lines()`.
*/
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Light_setup<typename GetGeomTraits<TriangleMesh, NamedParameters>::type>
default_light_setup(const TriangleMesh& tm,
                    const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type Kernel;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type Vertex_point_map;
  typedef typename Kernel::Point_3 Point_3;
  typedef typename Kernel::Vector_3 Vector_3;

  const double lines = double(CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, internal_np::number_of_lines), 20));
  if (!(lines >= 1))
    throw Invalid_input(Invalid_input::Problem::INVALID_PARAMETER,
                        "number_of_lines must be at least 1");

  const Highlight_line_sweeper<TriangleMesh, Vertex_point_map, Kernel> sweeper(tm, np);
  const auto& lm = sweeper.local_mesh();
  const std::size_t nv = lm.number_of_model_vertices;
  if (nv == 0)
    throw Invalid_input(Invalid_input::Problem::EMPTY_FACE_RANGE,
                        "default_light_setup(): the mesh has no face");
  std::array<double, 3> lo = {lm.xyz[0], lm.xyz[1], lm.xyz[2]}, hi = lo;
  for (std::size_t v = 0; v < nv; ++v)
    for (int k = 0; k < 3; ++k) {
      lo[k] = (std::min)(lo[k], lm.xyz[3 * v + std::size_t(k)]);
      hi[k] = (std::max)(hi[k], lm.xyz[3 * v + std::size_t(k)]);
    }
  int up = 0, along = 0;
  for (int k = 1; k < 3; ++k) {
    if (hi[k] - lo[k] < hi[up] - lo[up])
      up = k;
    if (hi[k] - lo[k] > hi[along] - lo[along])
      along = k;
  }
  if (along == up)
    along = (up + 1) % 3;
  const double diagonal =
      std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                (hi[2] - lo[2]) * (hi[2] - lo[2]));
  std::array<double, 3> a = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};
  a[std::size_t(up)] = hi[std::size_t(up)] + diagonal;
  std::array<double, 3> h = {0, 0, 0}, z = {0, 0, 0};
  h[std::size_t(along)] = 1;
  z[std::size_t(up)] = 1;

  // Distance values with a provisional unit spacing, from the vertices facing the plane.
  const Light_setup<Kernel> unit(Point_3(a[0], a[1], a[2]), Vector_3(h[0], h[1], h[2]),
                                 Vector_3(z[0], z[1], z[2]), 1);
  std::vector<double> d;
  d.reserve(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    const double* p = lm.point(int(v));
    const auto n = sweeper.vertex_normals().unit_normal(int(v));
    const double zn = n[std::size_t(up)];
    if (zn > 0.05) {
      const double w[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
      const auto x = internal::vector3::cross({w[0], w[1], w[2]}, h);
      d.push_back(internal::vector3::dot(x, n) / zn);
    }
  }
  if (d.size() < 2)
    throw Invalid_input(Invalid_input::Problem::INVALID_PARAMETER,
                        "default_light_setup(): no part of the mesh faces the light plane");
  std::sort(d.begin(), d.end());
  const double spread =
      d[std::size_t(0.95 * double(d.size() - 1))] - d[std::size_t(0.05 * double(d.size() - 1))];
  if (!(spread > 0))
    throw Invalid_input(Invalid_input::Problem::INVALID_PARAMETER,
                        "default_light_setup(): the highlight distance values do not vary (a "
                        "flat mesh parallel to the light plane); give a light setup instead");
  return Light_setup<Kernel>(unit.base_point(), unit.light_direction(), unit.plane_normal(),
                             spread / lines);
}

/*!
\ingroup PkgHighlightLinesRef

The range of light indices `[lo, hi]` whose highlight lines cover the central 90 % of the
surface facing the light plane (the 5 % and 95 % quantiles of the highlight distance values of
the vertices with `Z·N > 0`). Passed as `Highlight_lines::parameters::level_range`, it keeps
lines off the regions where the normals turn parallel to the light plane and the lines crowd,
as a light tunnel with a finite number of tubes would.

\param tm the mesh
\param lights the light setup
\param np an optional sequence of named parameters among `vertex_point_map`,
`Highlight_lines::parameters::face_range` and `Highlight_lines::parameters::crease_edge_map`.

\throws Invalid_input if no vertex faces the light plane.
*/
template <typename TriangleMesh, typename GeomTraits,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::pair<long long, long long>
default_level_range(const TriangleMesh& tm, const Light_setup<GeomTraits>& lights,
                    const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type Vertex_point_map;
  const Highlight_line_sweeper<TriangleMesh, Vertex_point_map, GeomTraits> sweeper(tm, np);
  std::vector<internal::Vertex_level> levels;
  sweeper.classify(lights, levels);
  std::vector<double> d;
  for (const internal::Vertex_level& level : levels)
    if (level.normal_side > 0 && !level.out_of_range)
      d.push_back(level.distance);
  if (d.empty())
    throw Invalid_input(Invalid_input::Problem::INVALID_PARAMETER,
                        "default_level_range(): no vertex faces the light plane");
  std::sort(d.begin(), d.end());
  const double s = lights.spacing_value();
  return {static_cast<long long>(std::floor(d[std::size_t(0.05 * double(d.size() - 1))] / s)),
          static_cast<long long>(std::ceil(d[std::size_t(0.95 * double(d.size() - 1))] / s))};
}

} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_DEFAULT_LIGHT_SETUP_H

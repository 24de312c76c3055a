// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_LIGHT_PLANES_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_LIGHT_PLANES_H

#include <CGAL/Highlight_lines/Light_setup.h>
#include <CGAL/Highlight_lines/internal/vector3.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// The detection's first step: the light planes it looks through. `lights`, then (if
// `all_sides`) the five other faces of a cube around the mesh in the lights' frame (Z, H,
// H x Z), as far from the centroid of `points` as `lights` (twice the mesh's reach if `lights`
// lies closer): every unit normal lies within 54.7 degrees of one of their normals, so every
// face is scored by the setups of at least one plane. All have the spacing of `lights`.
template <typename GeomTraits>
std::vector<Light_setup<GeomTraits>> light_planes_around(const Light_setup<GeomTraits>& lights,
                                                         const std::vector<vector3::Vec3>& points,
                                                         bool all_sides)
{
  using namespace vector3;
  const auto z0 = lights.plane_normal_array(), h0 = lights.light_direction_array();
  const auto x0 = cross(h0, z0);
  Vec3 centre{0, 0, 0};
  double reach = 0;
  for (const Vec3& p : points)
    centre = centre + (1.0 / double(points.size())) * p;
  for (const Vec3& p : points)
    reach = (std::max)(reach, norm(p - centre));
  const auto a0 = lights.base_point_array();
  double distance =
      dot(Vec3{a0[0] - centre[0], a0[1] - centre[1], a0[2] - centre[2]}, Vec3{z0[0], z0[1], z0[2]});
  if (!(distance > reach))
    distance = 2 * reach;
  std::vector<Light_setup<GeomTraits>> planes(1, lights);
  if (all_sides)
    for (int axis = 0; axis < 3; ++axis)
      for (double sign : {1.0, -1.0}) {
        if (axis == 0 && sign > 0)
          continue; // `lights` itself
        const auto& n = axis == 0 ? z0 : axis == 1 ? h0 : x0;
        const auto& h = axis == 0 ? h0 : z0;
        typedef typename GeomTraits::Point_3 Point_3;
        typedef typename GeomTraits::Vector_3 Vector_3;
        planes.emplace_back(Point_3(centre[0] + distance * sign * n[0],
                                    centre[1] + distance * sign * n[1],
                                    centre[2] + distance * sign * n[2]),
                            Vector_3(h[0], h[1], h[2]),
                            Vector_3(sign * n[0], sign * n[1], sign * n[2]), lights.spacing());
      }
  return planes;
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_LIGHT_PLANES_H

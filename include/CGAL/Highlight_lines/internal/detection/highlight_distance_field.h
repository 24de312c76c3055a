// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_HIGHLIGHT_DISTANCE_FIELD_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_HIGHLIGHT_DISTANCE_FIELD_H

#include <CGAL/Highlight_lines/Light_setup.h>
#include <CGAL/Highlight_lines/internal/vector3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// The highlight distance d (eq. 4, without the division by the spacing) at each model vertex
// of a local mesh facing the lights of one setup, and its gradient over the surface
// (area-weighted mean of those of the faces whose corners all face them). The lines are its
// level sets m s: they lie s/|grad d| apart on the surface, and a sideways shift r of a line
// is a change r.grad(d)/s of its level. Shifting the lights across changes d by a constant
// only.
struct Highlight_distance_field
{
  std::vector<double> value;           // NaN where the vertex does not face the lights
  std::vector<vector3::Vec3> gradient; // where `weight` > 0
  std::vector<double> weight;          // the area of the facing faces around the vertex

  template <typename Local_mesh, typename GeomTraits>
  void compute(const Local_mesh& local, const std::vector<vector3::Vec3>& unit_normals,
               const Light_setup<GeomTraits>& setup)
  {
    using namespace vector3;
    const std::size_t nv = unit_normals.size(), nf = local.number_of_model_faces;
    value.resize(nv);
    gradient.resize(nv);
    weight.resize(nv);
    const auto z = setup.plane_normal_array();
    const auto a = setup.base_point_array(), hd = setup.light_direction_array();
    for (std::size_t v = 0; v < nv; ++v) {
      const Vec3& n = unit_normals[v];
      const double facing = dot(n, Vec3{z[0], z[1], z[2]});
      const double* p = local.point(int(v));
      const Vec3 w{p[0] - a[0], p[1] - a[1], p[2] - a[2]};
      value[v] = facing > 0.05 ? dot(cross(w, Vec3{hd[0], hd[1], hd[2]}), n) / facing
                               : std::numeric_limits<double>::quiet_NaN();
      gradient[v] = Vec3{0, 0, 0};
      weight[v] = 0;
    }
    for (std::size_t f = 0; f < nf; ++f) {
      const auto& c = local.face_vertices[f];
      const double d0 = value[std::size_t(c[0])], d1 = value[std::size_t(c[1])],
                   d2 = value[std::size_t(c[2])];
      if (!std::isfinite(d0) || !std::isfinite(d1) || !std::isfinite(d2))
        continue;
      const double *p0 = local.point(c[0]), *p1 = local.point(c[1]), *p2 = local.point(c[2]);
      const Vec3 q0{p0[0], p0[1], p0[2]}, q1{p1[0], p1[1], p1[2]}, q2{p2[0], p2[1], p2[2]};
      const Vec3 face_normal = cross(q1 - q0, q2 - q0);
      const double twice_area = norm(face_normal);
      if (!(twice_area > 0))
        continue;
      // grad = sum d_i (n x e_i) / 2A, e_i the edge opposite corner i; times the area A.
      const Vec3 e = d0 * (q2 - q1) + d1 * (q0 - q2) + d2 * (q1 - q0);
      const Vec3 weighted = (0.5 / twice_area) * cross(face_normal, e);
      for (int v : c) {
        gradient[std::size_t(v)] = gradient[std::size_t(v)] + weighted;
        weight[std::size_t(v)] += 0.5 * twice_area;
      }
    }
    for (std::size_t v = 0; v < nv; ++v)
      if (weight[v] > 0)
        gradient[v] = (1 / weight[v]) * gradient[v];
  }
};

// Line density from the mesh: a defect is only seen where several lines of one setup cross it,
// so the lights are brought closer (never farther apart) until the lines lie at most
// `line_spacing` apart (s/|grad d|, from `field` computed for `setup`) on three quarters of the
// surface facing them within the incidence limit (`minimum_facing`, a cosine). The lines crowd
// where the surface curves (|grad d| grows with the curvature times the distance to the plane),
// so the flatter parts set the spacing, and the cost stays proportional to the facing area over
// the spacing.
template <typename GeomTraits>
Light_setup<GeomTraits> with_spacing_from_mesh(const Light_setup<GeomTraits>& setup,
                                               const Highlight_distance_field& field,
                                               const std::vector<vector3::Vec3>& unit_normals,
                                               double minimum_facing, double line_spacing)
{
  using namespace vector3;
  const auto z = setup.plane_normal_array();
  std::vector<double> rates;
  for (std::size_t v = 0; v < unit_normals.size(); ++v)
    if (field.weight[v] > 0 && dot(unit_normals[v], Vec3{z[0], z[1], z[2]}) >= minimum_facing)
      rates.push_back(norm(field.gradient[v]));
  if (rates.empty())
    return setup;
  const std::size_t q = rates.size() / 4;
  std::nth_element(rates.begin(), rates.begin() + std::ptrdiff_t(q), rates.end());
  const double spacing = line_spacing * rates[q];
  if (!(spacing > 0) || !std::isfinite(spacing) || !(spacing < setup.spacing_value()))
    return setup;
  return Light_setup<GeomTraits>(setup.base_point(), setup.light_direction(), setup.plane_normal(),
                                 spacing);
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_HIGHLIGHT_DISTANCE_FIELD_H

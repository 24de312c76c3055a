// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_SHARP_EDGE_VERTICES_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_SHARP_EDGE_VERTICES_H

#include <CGAL/Highlight_lines/internal/vector3.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// The model vertices of a local mesh (Local_mesh.h) that lie on a sharp edge: one whose two
// faces' normals are more than `sharp_edge_angle` degrees apart (the criterion of
// PMP::detect_sharp_edges()). The highlight lines kink there by design: the detection counts
// no anomaly next to them and grows no region across them.
template <typename Local_mesh>
std::vector<char> sharp_edge_vertices(const Local_mesh& local, double sharp_edge_angle)
{
  using namespace vector3;
  const std::size_t nf = local.number_of_model_faces;
  const std::size_t nv = local.number_of_model_vertices;
  const double pi = 3.14159265358979323846;
  const double cos_sharp = std::cos(sharp_edge_angle * pi / 180);
  std::vector<char> sharp(nv, 0);
  std::vector<std::array<int, 2>> edge_faces(local.edge_vertices.size(), {-1, -1});
  for (std::size_t f = 0; f < nf; ++f)
    for (int e : local.face_edges[f]) {
      auto& ef = edge_faces[std::size_t(e)];
      (ef[0] < 0 ? ef[0] : ef[1]) = int(f);
    }
  auto face_normal = [&](int f) {
    const auto& c = local.face_vertices[std::size_t(f)];
    const double *p = local.point(c[0]), *q = local.point(c[1]), *r = local.point(c[2]);
    const Vec3 n = cross(Vec3{q[0] - p[0], q[1] - p[1], q[2] - p[2]},
                         Vec3{r[0] - p[0], r[1] - p[1], r[2] - p[2]});
    const double length = norm(n);
    return length > 0 ? (1 / length) * n : n;
  };
  for (std::size_t e = 0; e < edge_faces.size(); ++e)
    if (edge_faces[e][1] >= 0 &&
        dot(face_normal(edge_faces[e][0]), face_normal(edge_faces[e][1])) < cos_sharp)
      for (int v : local.edge_vertices[e])
        if (std::size_t(v) < nv)
          sharp[std::size_t(v)] = 1;
  return sharp;
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_SHARP_EDGE_VERTICES_H

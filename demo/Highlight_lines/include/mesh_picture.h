// Conversions from a CGAL Surface_mesh and CGAL polylines to the arrays the picture writer
// (highlight_picture.h, which knows nothing of CGAL) draws. Shared by the command-line programs.
#ifndef HIGHLIGHT_LINES_DEMO_MESH_PICTURE_H
#define HIGHLIGHT_LINES_DEMO_MESH_PICTURE_H

#include <CGAL/Surface_mesh.h>

#include "highlight_picture.h"

#include <array>
#include <vector>

namespace mesh_picture {

// A CGAL point or vector as three doubles.
template <typename PointOrVector>
std::array<double, 3> to_array(const PointOrVector& p)
{
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

// The vertices and triangles of a Surface_mesh, indexed as the mesh indexes its vertices.
template <typename Point>
void mesh_arrays(const CGAL::Surface_mesh<Point>& mesh,
                 std::vector<highlight_picture::Point3>& points,
                 std::vector<std::array<std::size_t, 3>>& triangles)
{
  points.clear();
  triangles.clear();
  for (auto v : vertices(mesh))
    points.push_back(to_array(mesh.point(v)));
  for (auto f : faces(mesh)) {
    std::array<std::size_t, 3> t{};
    std::size_t j = 0;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      t[j++] = std::size_t(v);
    triangles.push_back(t);
  }
}

template <typename Point>
std::vector<std::vector<highlight_picture::Point3>>
polyline_arrays(const std::vector<std::vector<Point>>& polylines)
{
  std::vector<std::vector<highlight_picture::Point3>> result;
  for (const auto& polyline : polylines) {
    result.emplace_back();
    for (const auto& p : polyline)
      result.back().push_back(to_array(p));
  }
  return result;
}

} // namespace mesh_picture

#endif // HIGHLIGHT_LINES_DEMO_MESH_PICTURE_H

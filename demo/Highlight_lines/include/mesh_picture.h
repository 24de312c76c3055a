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

// The mesh cut along the edges e with get(creases, e): a vertex gets one point per sector of
// faces between crease edges (one for a vertex on no crease), so that smooth shading does not
// round the creases. The first num_vertices(mesh) points are the vertices, in order; the others
// are the copies of the vertices on creases.
struct Cut_corners
{
  std::vector<std::size_t> point_of_corner; // by halfedge h: the point of target(h) in face(h)
  std::vector<std::size_t> origin;          // by point: its vertex
};

template <typename Point, typename CreaseMap>
Cut_corners cut_corners(const CGAL::Surface_mesh<Point>& mesh, CreaseMap creases)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  Cut_corners cut;
  cut.point_of_corner.assign(mesh.number_of_halfedges(), 0);
  cut.origin.resize(mesh.number_of_vertices());
  for (std::size_t i = 0; i < cut.origin.size(); ++i)
    cut.origin[i] = i;
  std::vector<typename Mesh::Halfedge_index> ring;
  for (auto v : vertices(mesh)) {
    ring.clear();
    for (auto h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh))
      ring.push_back(h);
    // Start after a crease or a border, so that a sector is never split by the wrap-around.
    std::size_t start = 0;
    for (std::size_t i = 0; i < ring.size(); ++i)
      if (mesh.is_border(ring[i]) || get(creases, mesh.edge(mesh.next(ring[i])))) {
        start = (i + 1) % ring.size();
        break;
      }
    std::size_t point = std::size_t(v);
    bool used = false;
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const auto h = ring[(start + k) % ring.size()];
      if (mesh.is_border(h))
        continue;
      cut.point_of_corner[std::size_t(h)] = point;
      used = true;
      if (get(creases, mesh.edge(mesh.next(h))) && k + 1 < ring.size()) {
        cut.origin.push_back(std::size_t(v));
        point = cut.origin.size() - 1;
        used = false;
      }
    }
    if (!used && point + 1 == cut.origin.size() && point >= mesh.number_of_vertices())
      cut.origin.pop_back(); // a copy opened after the last face of the ring: no face uses it
  }
  return cut;
}

// mesh_arrays(), with the mesh cut along the edges e with get(creases, e) (cut_corners()).
template <typename Point, typename CreaseMap>
void mesh_arrays(const CGAL::Surface_mesh<Point>& mesh, CreaseMap creases,
                 std::vector<highlight_picture::Point3>& points,
                 std::vector<std::array<std::size_t, 3>>& triangles)
{
  const Cut_corners cut = cut_corners(mesh, creases);
  points.clear();
  for (std::size_t v : cut.origin)
    points.push_back(to_array(mesh.point(typename CGAL::Surface_mesh<Point>::Vertex_index(
        typename CGAL::Surface_mesh<Point>::size_type(v)))));
  triangles.clear();
  for (auto f : faces(mesh)) {
    std::array<std::size_t, 3> t{};
    std::size_t j = 0;
    for (auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
      t[j++] = cut.point_of_corner[std::size_t(mesh.prev(h))];
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

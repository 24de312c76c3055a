// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_SHARP_VERTICES_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_SHARP_VERTICES_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <cmath>
#include <cstddef>
#include <unordered_map>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// Whether a vertex lies on a sharp edge: an edge whose two faces' normals are more than
// `sharp_edge_angle` degrees apart (the criterion of PMP::detect_sharp_edges()). Face normals
// are computed when first needed and kept, so a walk over a small part of a large mesh pays for
// that part only.
template <typename TriangleMesh, typename VertexPointMap>
class Sharp_vertex_test
{
  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  typedef typename Graph_traits::face_descriptor face_descriptor;
  typedef typename Graph_traits::vertex_descriptor vertex_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  typedef typename Kernel_traits<Point>::Kernel::Vector_3 Vector;

public:
  Sharp_vertex_test(const TriangleMesh& tm, double sharp_edge_angle, VertexPointMap vpm)
      : tm_(tm), vpm_(vpm), fim_(get_initialized_face_index_map(tm)),
        cos_sharp_(std::cos(sharp_edge_angle * std::acos(-1.0) / 180))
  {
  }

  bool operator()(vertex_descriptor v)
  {
    for (auto h : halfedges_around_target(halfedge(v, tm_), tm_)) {
      const face_descriptor f = face(h, tm_), g = face(opposite(h, tm_), tm_);
      if (f != Graph_traits::null_face() && g != Graph_traits::null_face() &&
          CGAL::to_double(normal(f) * normal(g)) < cos_sharp_)
        return true;
    }
    return false;
  }

private:
  const Vector& normal(face_descriptor f)
  {
    const std::size_t index = std::size_t(get(fim_, f));
    auto it = normals_.find(index);
    if (it == normals_.end())
      it = normals_
               .emplace(index, Polygon_mesh_processing::compute_face_normal(
                                   f, tm_, CGAL::parameters::vertex_point_map(vpm_)))
               .first;
    return it->second;
  }

  const TriangleMesh& tm_;
  VertexPointMap vpm_;
  typename GetInitializedFaceIndexMap<TriangleMesh>::const_type fim_;
  double cos_sharp_;
  std::unordered_map<std::size_t, Vector> normals_; // by face index
};

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_SHARP_VERTICES_H

// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_GROWN_FACE_REGION_H
#define CGAL_HIGHLIGHT_LINES_GROWN_FACE_REGION_H

#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/Highlight_lines/internal/sharp_vertices.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <cmath>
#include <cstddef>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Highlight_lines {

/*!
\ingroup PkgHighlightLinesRef

Returns the faces of `region` and the rings of faces around it, up to `rings` rings: the faces
around its vertices, then around theirs, and so on, never past a vertex of a sharp edge (an
edge whose two faces' normals are more than `sharp_edge_angle` degrees apart, the criterion of
`Polygon_mesh_processing::detect_sharp_edges()`): such a vertex is reached, not crossed, so the
grown region crosses no sharp edge that `region` did not. The faces of `region` come first, in
their order.

`detect_and_fair_highlight_line_irregularities()` fairs each region found grown so, by
`detection_scale` rings: a region is centred where the highlight lines move most, often one
flank of a defect, and a fairing moves only the inner vertices of its region.

\tparam TriangleMesh a model of `FaceGraph`
\tparam VertexPointMap a model of `ReadablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and a point of a
        %CGAL kernel as value type

\param tm the mesh
\param region faces of `tm`, each once
\param rings the number of rings of faces to add
\param sharp_edge_angle in degrees
\param vpm the points of the vertices of `tm`

\throws Highlight_lines::Invalid_input (`INVALID_PARAMETER`) if `rings` is negative or
`sharp_edge_angle` is not in `(0, 180]`.
*/
template <typename TriangleMesh, typename VertexPointMap>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> grown_face_region(
    const TriangleMesh& tm,
    const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& region,
    int rings, double sharp_edge_angle, VertexPointMap vpm)
{
  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  typedef typename Graph_traits::face_descriptor face_descriptor;
  typedef typename Graph_traits::vertex_descriptor vertex_descriptor;

  if (rings < 0)
    throw Invalid_input(Invalid_input::Problem::INVALID_PARAMETER,
                        "grown_face_region: rings must not be negative");
  if (!(sharp_edge_angle > 0 && sharp_edge_angle <= 180))
    throw Invalid_input(Invalid_input::Problem::INVALID_PARAMETER,
                        "grown_face_region: sharp_edge_angle must be in (0, 180] degrees");
  const auto fim = get_initialized_face_index_map(tm);
  const auto vim = get_initialized_vertex_index_map(tm);
  internal::Sharp_vertex_test<TriangleMesh, VertexPointMap> on_sharp_edge(tm, sharp_edge_angle,
                                                                          vpm);

  std::vector<face_descriptor> grown = region;
  std::unordered_set<std::size_t> in_region, reached;
  std::vector<vertex_descriptor> front;
  for (face_descriptor f : region)
    in_region.insert(std::size_t(get(fim, f)));
  for (face_descriptor f : region)
    for (vertex_descriptor v : vertices_around_face(halfedge(f, tm), tm))
      if (reached.insert(std::size_t(get(vim, v))).second)
        front.push_back(v);
  for (int ring = 0; ring < rings && !front.empty(); ++ring) {
    std::vector<vertex_descriptor> next;
    for (vertex_descriptor v : front) {
      if (on_sharp_edge(v))
        continue;
      for (face_descriptor f : faces_around_target(halfedge(v, tm), tm)) {
        if (f == Graph_traits::null_face() || !in_region.insert(std::size_t(get(fim, f))).second)
          continue;
        grown.push_back(f);
        for (vertex_descriptor u : vertices_around_face(halfedge(f, tm), tm))
          if (reached.insert(std::size_t(get(vim, u))).second)
            next.push_back(u);
      }
    }
    front.swap(next);
  }
  return grown;
}

} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_GROWN_FACE_REGION_H

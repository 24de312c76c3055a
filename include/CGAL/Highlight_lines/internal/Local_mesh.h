// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_LOCAL_MESH_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_LOCAL_MESH_H

#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/Highlight_lines/internal/Compact_ids.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// A flat copy of the part of a triangle mesh on which a highlight line model is computed:
// the model faces (the user's face range), their vertices ("model vertices") and edges, and
// the one-ring closure needed for the vertex normals of eq. 3 (every face incident to a model
// vertex, with its vertices). Hot loops work on these arrays, not on handles and property maps.
//
// Vertices [0, number_of_model_vertices) are model vertices; faces [0, number_of_model_faces)
// are model faces. Face corner j is source(h_j) with h_0 = halfedge(f), h_{j+1} = next(h_j);
// face edge j joins corners j and j+1.
template <typename TriangleMesh>
struct Local_mesh
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  std::vector<vertex_descriptor> vertex_handles;
  std::vector<std::size_t> vertex_indices; // as given by the vertex index map (for messages)
  std::vector<double> xyz;                 // 3 coordinates per vertex
  std::size_t number_of_model_vertices = 0;

  std::vector<face_descriptor> face_handles;
  std::vector<std::size_t> face_indices;
  std::vector<std::array<int, 3>> face_vertices;
  std::vector<std::array<int, 3>> face_edges; // model faces only
  std::size_t number_of_model_faces = 0;

  std::vector<halfedge_descriptor> edge_halfedges; // canonical: source = edge_vertices[e][0]
  std::vector<std::array<int, 2>> edge_vertices;

  // Order in which face contributions are summed into vertex normals: by increasing face
  // index, so that a model on a face range agrees bit for bit with the whole mesh's model.
  // Empty: the local order, which is already that order for the whole mesh.
  std::vector<int> face_summation_order;

  // What the exact evaluations need to walk around a vertex in the mesh.
  const TriangleMesh* mesh = nullptr;
  Compact_ids face_ids;
  std::function<std::size_t(face_descriptor)> face_index;

  // A mesh cut along creases (crease_cut.h): the vertices with several sectors and their
  // copies, sorted, and the faces of the i-th one's sector at
  // [sector_face_begin[i], sector_face_begin[i + 1]); empty otherwise.
  std::vector<int> sector_vertices, sector_face_begin, sector_faces;

  const double* point(int v) const { return &xyz[3 * std::size_t(v)]; }

  // Calls f(local face id) for every face incident to model vertex v (rarely used: exact
  // fallbacks only); on a cut mesh, for the faces of its sector.
  template <typename F>
  void for_each_face_around(int v, F&& f) const
  {
    const auto sector = std::lower_bound(sector_vertices.begin(), sector_vertices.end(), v);
    if (sector != sector_vertices.end() && *sector == v) {
      const std::size_t i = std::size_t(sector - sector_vertices.begin());
      for (int k = sector_face_begin[i]; k < sector_face_begin[i + 1]; ++k)
        f(sector_faces[std::size_t(k)]);
      return;
    }
    for (halfedge_descriptor h :
         halfedges_around_target(halfedge(vertex_handles[std::size_t(v)], *mesh), *mesh)) {
      const face_descriptor fd = face(h, *mesh);
      if (fd != boost::graph_traits<TriangleMesh>::null_face())
        f(face_ids.find(face_index(fd)));
    }
  }
};

inline bool lexicographically_smaller(const double* p, const double* q)
{
  for (int i = 0; i < 3; ++i)
    if (p[i] != q[i])
      return p[i] < q[i];
  return false;
}

// Whether the edge from local vertex a to b runs against its canonical direction: edges run
// from the lexicographically smaller point (ties: the smaller vertex index), so that node
// positions do not depend on which face saw an edge first.
template <typename TriangleMesh>
bool against_canonical_direction(const Local_mesh<TriangleMesh>& lm, int a, int b)
{
  return lexicographically_smaller(lm.point(b), lm.point(a)) ||
         (!lexicographically_smaller(lm.point(a), lm.point(b)) &&
          lm.vertex_indices[std::size_t(b)] < lm.vertex_indices[std::size_t(a)]);
}

inline std::string describe_point(const double* p)
{
  std::ostringstream s;
  s.precision(17);
  s << '(' << p[0] << ", " << p[1] << ", " << p[2] << ')';
  return s.str();
}

template <typename TriangleMesh, typename FaceIndexMap>
[[noreturn]] void throw_non_triangle(FaceIndexMap fim,
                                     typename boost::graph_traits<TriangleMesh>::face_descriptor f)
{
  throw Invalid_input(Invalid_input::Problem::NON_TRIANGLE_FACE,
                      "face " + std::to_string(get(fim, f)) +
                          " is not a triangle: the highlight line model is defined on triangle "
                          "meshes (triangulate it first, e.g. with "
                          "CGAL::Polygon_mesh_processing::triangulate_faces())",
                      get(fim, f));
}

// The whole mesh: sequential passes over vertices, edges and faces with dense tables indexed
// by the index maps (cheaper than discovering elements from the faces).
template <typename TriangleMesh, typename VertexPointMap, typename VertexIndexMap,
          typename FaceIndexMap, typename HalfedgeIndexMap>
void build_whole_local_mesh(const TriangleMesh& tm, VertexPointMap vpm, VertexIndexMap vim,
                            FaceIndexMap fim, HalfedgeIndexMap him, Local_mesh<TriangleMesh>& lm)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  std::vector<int> vertex_id(num_vertices(tm), -1), halfedge_edge(num_halfedges(tm), -1);
  auto grow = [](std::vector<int>& table, std::size_t key) {
    if (key >= table.size())
      table.resize(key + 1, -1);
  };

  // Vertices and edges are numbered in the order the faces first reach them: neighbouring
  // elements get nearby ids, which keeps the per-sweep passes over edges and faces, with their
  // reads of per-vertex data, cache friendly.
  lm.vertex_handles.reserve(num_vertices(tm));
  lm.vertex_indices.reserve(num_vertices(tm));
  lm.xyz.reserve(3 * num_vertices(tm));
  lm.edge_halfedges.reserve(num_edges(tm));
  lm.edge_vertices.reserve(num_edges(tm));
  lm.face_handles.reserve(num_faces(tm));
  lm.face_indices.reserve(num_faces(tm));
  lm.face_vertices.reserve(num_faces(tm));
  lm.face_edges.reserve(num_faces(tm));
  lm.face_ids = Compact_ids(true, num_faces(tm));

  auto vertex = [&](typename GT::vertex_descriptor v) {
    const std::size_t key = std::size_t(get(vim, v));
    grow(vertex_id, key);
    if (vertex_id[key] >= 0)
      return vertex_id[key];
    const auto& p = get(vpm, v);
    const double c[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]))
      throw Invalid_input(Invalid_input::Problem::NON_FINITE_COORDINATE,
                          "vertex " + std::to_string(key) + " has a non-finite coordinate " +
                              describe_point(c),
                          key);
    vertex_id[key] = int(lm.vertex_handles.size());
    lm.vertex_handles.push_back(v);
    lm.vertex_indices.push_back(key);
    lm.xyz.insert(lm.xyz.end(), c, c + 3);
    return vertex_id[key];
  };
  auto edge = [&](typename GT::halfedge_descriptor h, int a, int b) {
    const std::size_t h_key = std::size_t(get(him, h));
    grow(halfedge_edge, h_key);
    if (halfedge_edge[h_key] >= 0)
      return halfedge_edge[h_key];
    const std::size_t o_key = std::size_t(get(him, opposite(h, tm)));
    if (against_canonical_direction(lm, a, b)) {
      std::swap(a, b);
      h = opposite(h, tm);
    }
    grow(halfedge_edge, o_key);
    halfedge_edge[h_key] = halfedge_edge[o_key] = int(lm.edge_halfedges.size());
    lm.edge_halfedges.push_back(h);
    lm.edge_vertices.push_back({a, b});
    return halfedge_edge[h_key];
  };

  for (typename GT::face_descriptor f : faces(tm)) {
    const typename GT::halfedge_descriptor h[3] = {halfedge(f, tm), next(halfedge(f, tm), tm),
                                                   next(next(halfedge(f, tm), tm), tm)};
    if (next(h[2], tm) != h[0])
      throw_non_triangle<TriangleMesh>(fim, f);
    bool inserted = false;
    lm.face_ids.insert(std::size_t(get(fim, f)), int(lm.face_handles.size()), inserted);
    lm.face_handles.push_back(f);
    lm.face_indices.push_back(std::size_t(get(fim, f)));
    const std::array<int, 3> corners = {vertex(source(h[0], tm)), vertex(source(h[1], tm)),
                                        vertex(source(h[2], tm))};
    lm.face_vertices.push_back(corners);
    lm.face_edges.push_back({edge(h[0], corners[0], corners[1]), edge(h[1], corners[1], corners[2]),
                             edge(h[2], corners[2], corners[0])});
  }
  lm.number_of_model_vertices = lm.vertex_handles.size();
  lm.number_of_model_faces = lm.face_handles.size();
  lm.mesh = &tm;
  lm.face_index = [fim](typename GT::face_descriptor f) { return std::size_t(get(fim, f)); };
}

// Builds the local mesh on `faces` (all faces of `tm` if `whole_mesh`). Throws Invalid_input
// for non-triangle faces, faces not in the mesh, and non-finite coordinates.
template <typename TriangleMesh, typename FaceRange, typename VertexPointMap,
          typename VertexIndexMap, typename FaceIndexMap, typename HalfedgeIndexMap>
void build_local_mesh(const TriangleMesh& tm, const FaceRange& faces, bool whole_mesh,
                      VertexPointMap vpm, VertexIndexMap vim, FaceIndexMap fim,
                      HalfedgeIndexMap him, Local_mesh<TriangleMesh>& lm)
{
  typedef Local_mesh<TriangleMesh> LM;
  typedef typename LM::halfedge_descriptor halfedge_descriptor;
  typedef typename LM::face_descriptor face_descriptor;
  typedef typename LM::vertex_descriptor vertex_descriptor;
  typedef Invalid_input::Problem Problem;
  if (whole_mesh) {
    build_whole_local_mesh(tm, vpm, vim, fim, him, lm);
    return;
  }

  Compact_ids face_ids(false, 0), vertex_ids(false, 0), edge_ids(false, 0);

  auto check_triangle = [&](face_descriptor f) {
    halfedge_descriptor h = halfedge(f, tm);
    if (h == boost::graph_traits<TriangleMesh>::null_halfedge() ||
        next(next(next(h, tm), tm), tm) != h)
      throw_non_triangle<TriangleMesh>(fim, f);
  };

  auto add_vertex = [&](vertex_descriptor v) {
    bool inserted = false;
    const std::size_t key = get(vim, v);
    const int id = vertex_ids.insert(key, int(lm.vertex_handles.size()), inserted);
    if (inserted) {
      lm.vertex_handles.push_back(v);
      lm.vertex_indices.push_back(key);
      const auto& p = get(vpm, v);
      const double c[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
      for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(c[i]))
          throw Invalid_input(Problem::NON_FINITE_COORDINATE,
                              "vertex " + std::to_string(key) + " has a non-finite coordinate " +
                                  describe_point(c),
                              key);
        lm.xyz.push_back(c[i]);
      }
    }
    return id;
  };

  auto add_face = [&](face_descriptor f) {
    bool inserted = false;
    face_ids.insert(get(fim, f), int(lm.face_handles.size()), inserted);
    if (inserted) {
      check_triangle(f);
      lm.face_handles.push_back(f);
      lm.face_indices.push_back(get(fim, f));
      halfedge_descriptor h = halfedge(f, tm);
      std::array<int, 3> corners;
      for (int j = 0; j < 3; ++j, h = next(h, tm))
        corners[j] = add_vertex(source(h, tm));
      lm.face_vertices.push_back(corners);
    }
    return inserted;
  };

  // 1. Model faces, with their vertices.
  auto add_edge = [&](halfedge_descriptor h) {
    // An edge is keyed by the smaller index of its halfedges (CGAL 5.5 has no usable edge
    // index map for a Polyhedron_3 without ids).
    const std::size_t key =
        (std::min)(std::size_t(get(him, h)), std::size_t(get(him, opposite(h, tm))));
    bool inserted = false;
    const int e = edge_ids.insert(key, int(lm.edge_halfedges.size()), inserted);
    if (inserted) {
      // Canonical direction, from the lexicographically smaller point, so that node positions
      // do not depend on which face saw an edge first.
      int a = vertex_ids.find(get(vim, source(h, tm))),
          b = vertex_ids.find(get(vim, target(h, tm)));
      if (against_canonical_direction(lm, a, b)) {
        std::swap(a, b);
        h = opposite(h, tm);
      }
      lm.edge_halfedges.push_back(h);
      lm.edge_vertices.push_back({a, b});
    }
    return e;
  };

  // A triangle mesh has about half as many vertices and 1.5 times as many edges as faces; the
  // one-ring closure adds a ring of faces.
  const std::size_t range_size = std::size_t(std::distance(std::begin(faces), std::end(faces)));
  face_ids.reserve(range_size + range_size / 4);
  vertex_ids.reserve(range_size / 2 + range_size / 8);
  edge_ids.reserve(range_size + range_size / 2);
  for (face_descriptor f : faces) {
    if (f == boost::graph_traits<TriangleMesh>::null_face())
      throw Invalid_input(Problem::FACE_NOT_IN_MESH, "the face range contains a null face");
    add_face(f);
  }
  lm.number_of_model_faces = lm.face_handles.size();
  lm.number_of_model_vertices = lm.vertex_handles.size();

  // 2. Edges of the model faces.
  lm.face_edges.resize(lm.number_of_model_faces);
  for (std::size_t f = 0; f < lm.number_of_model_faces; ++f) {
    halfedge_descriptor h = halfedge(lm.face_handles[f], tm);
    for (int j = 0; j < 3; ++j, h = next(h, tm))
      lm.face_edges[f][std::size_t(j)] = add_edge(h);
  }

  // 3. One-ring closure of the model vertices: every incident face (for eq. 3).
  {
    for (std::size_t v = 0; v < lm.number_of_model_vertices; ++v)
      for (halfedge_descriptor h :
           halfedges_around_target(halfedge(lm.vertex_handles[v], tm), tm)) {
        const face_descriptor f = face(h, tm);
        if (f != boost::graph_traits<TriangleMesh>::null_face())
          add_face(f);
      }
    lm.face_summation_order.resize(lm.face_handles.size());
    for (std::size_t f = 0; f < lm.face_handles.size(); ++f)
      lm.face_summation_order[f] = int(f);
    std::sort(lm.face_summation_order.begin(), lm.face_summation_order.end(), [&](int f, int g) {
      return lm.face_indices[std::size_t(f)] < lm.face_indices[std::size_t(g)];
    });
  }
  lm.mesh = &tm;
  lm.face_ids = std::move(face_ids);
  lm.face_index = [fim](face_descriptor f) { return std::size_t(get(fim, f)); };
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_LOCAL_MESH_H

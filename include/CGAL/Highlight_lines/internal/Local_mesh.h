// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_LOCAL_MESH_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_LOCAL_MESH_H

#include <CGAL/Highlight_lines/Invalid_input.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// Maps a sparse or dense element index (as given by an index property map) to a compact id.
// Dense storage when the whole mesh is processed, hashing when only a face range is.
class Compact_ids
{
public:
  static constexpr int none = -1;

  Compact_ids(bool dense, std::size_t bound) : dense_(dense)
  {
    if (dense_)
      table_.assign(bound, none);
  }

  int find(std::size_t key) const
  {
    if (dense_)
      return key < table_.size() ? table_[key] : none;
    auto it = map_.find(key);
    return it == map_.end() ? none : it->second;
  }

  // Returns the id of `key`, assigning `next` if it has none yet.
  int insert(std::size_t key, int next, bool& inserted)
  {
    if (dense_) {
      if (key >= table_.size())
        table_.resize(key + 1, none);
      inserted = table_[key] == none;
      if (inserted)
        table_[key] = next;
      return table_[key];
    }
    auto result = map_.emplace(key, next);
    inserted = result.second;
    return result.first->second;
  }

private:
  bool dense_;
  std::vector<int> table_;
  std::unordered_map<std::size_t, int> map_;
};

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

  // For the exact evaluations: the faces around each model vertex (CSR).
  std::vector<int> vertex_face_begin, vertex_faces;

  const double* point(int v) const { return &xyz[3 * std::size_t(v)]; }
};

inline bool lexicographically_smaller(const double* p, const double* q)
{
  for (int i = 0; i < 3; ++i)
    if (p[i] != q[i])
      return p[i] < q[i];
  return false;
}

inline std::string describe_point(const double* p)
{
  std::ostringstream s;
  s.precision(17);
  s << '(' << p[0] << ", " << p[1] << ", " << p[2] << ')';
  return s.str();
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

  Compact_ids face_ids(whole_mesh, whole_mesh ? num_faces(tm) : 0);
  Compact_ids vertex_ids(whole_mesh, whole_mesh ? num_vertices(tm) : 0);
  Compact_ids edge_ids(whole_mesh, whole_mesh ? num_halfedges(tm) : 0);

  auto check_triangle = [&](face_descriptor f) {
    halfedge_descriptor h = halfedge(f, tm);
    if (h == boost::graph_traits<TriangleMesh>::null_halfedge() ||
        next(next(next(h, tm), tm), tm) != h)
      throw Invalid_input(Problem::NON_TRIANGLE_FACE,
                          "face " + std::to_string(get(fim, f)) +
                              " is not a triangle: the highlight line model is defined on "
                              "triangle meshes (triangulate it first, e.g. with "
                              "CGAL::Polygon_mesh_processing::triangulate_faces())",
                          get(fim, f));
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
  for (face_descriptor f : faces) {
    if (f == boost::graph_traits<TriangleMesh>::null_face())
      throw Invalid_input(Problem::FACE_NOT_IN_MESH, "the face range contains a null face");
    add_face(f);
  }
  lm.number_of_model_faces = lm.face_handles.size();
  lm.number_of_model_vertices = lm.vertex_handles.size();

  // 2. Edges of the model faces; canonical direction from the lexicographically smaller point
  // so that node positions do not depend on which face saw an edge first.
  lm.face_edges.resize(lm.number_of_model_faces);
  for (std::size_t f = 0; f < lm.number_of_model_faces; ++f) {
    halfedge_descriptor h = halfedge(lm.face_handles[f], tm);
    for (int j = 0; j < 3; ++j, h = next(h, tm)) {
      bool inserted = false;
      // An edge is keyed by the smaller index of its halfedges (CGAL 5.5 has no usable edge
      // index map for a Polyhedron_3 without ids).
      const std::size_t key =
          (std::min)(std::size_t(get(him, h)), std::size_t(get(him, opposite(h, tm))));
      const int e = edge_ids.insert(key, int(lm.edge_halfedges.size()), inserted);
      if (inserted) {
        int a = lm.face_vertices[f][j], b = lm.face_vertices[f][(j + 1) % 3];
        halfedge_descriptor he = h;
        if (lexicographically_smaller(lm.point(b), lm.point(a)) ||
            (!lexicographically_smaller(lm.point(a), lm.point(b)) &&
             lm.vertex_indices[b] < lm.vertex_indices[a])) {
          std::swap(a, b);
          he = opposite(h, tm);
        }
        lm.edge_halfedges.push_back(he);
        lm.edge_vertices.push_back({a, b});
      }
      lm.face_edges[f][j] = e;
    }
  }

  // 3. One-ring closure of the model vertices: every incident face (for eq. 3).
  std::vector<int> counts(lm.number_of_model_vertices + 1, 0);
  std::vector<std::pair<int, int>> incidences; // (model vertex, face)
  incidences.reserve(3 * lm.number_of_model_faces);
  if (whole_mesh) {
    for (std::size_t f = 0; f < lm.face_handles.size(); ++f)
      for (int v : lm.face_vertices[f])
        incidences.emplace_back(v, int(f));
  } else {
    for (std::size_t v = 0; v < lm.number_of_model_vertices; ++v) {
      for (halfedge_descriptor h :
           halfedges_around_target(halfedge(lm.vertex_handles[v], tm), tm)) {
        const face_descriptor f = face(h, tm);
        if (f == boost::graph_traits<TriangleMesh>::null_face())
          continue;
        add_face(f);
        incidences.emplace_back(int(v), face_ids.find(get(fim, f)));
      }
    }
  }
  for (const auto& vf : incidences)
    ++counts[std::size_t(vf.first) + 1];
  for (std::size_t v = 0; v < lm.number_of_model_vertices; ++v)
    counts[v + 1] += counts[v];
  lm.vertex_face_begin = counts;
  lm.vertex_faces.assign(incidences.size(), 0);
  for (const auto& vf : incidences)
    lm.vertex_faces[std::size_t(counts[std::size_t(vf.first)]++)] = vf.second;
  // Normals are sums over these lists: order them by face index, as for the whole mesh, so
  // that a model on a face range agrees bit for bit with the whole mesh's model.
  if (!whole_mesh)
    for (std::size_t v = 0; v < lm.number_of_model_vertices; ++v)
      std::sort(lm.vertex_faces.begin() + lm.vertex_face_begin[v],
                lm.vertex_faces.begin() + lm.vertex_face_begin[v + 1], [&](int f, int g) {
                  return lm.face_indices[std::size_t(f)] < lm.face_indices[std::size_t(g)];
                });
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_LOCAL_MESH_H

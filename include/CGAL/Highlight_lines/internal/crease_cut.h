// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_CREASE_CUT_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_CREASE_CUT_H

// The model on a surface with creases (beyond the paper): eq. 3 averages the face normals
// around a vertex, also across a crease of a CAD tessellation, so that the normal field, and
// with it the highlight lines, bends over the faces next to every crease (on a planar face
// the lines should be straight). Cutting the local mesh along the crease edges gives each
// smooth sector of the faces around a vertex its own copy of the vertex: the normals of eq. 3
// are then summed per sector, every step of the model runs unchanged on the cut mesh, and the
// lines end at a crease (two nodes on a crease edge, one per side), as a reflection breaks
// there.

#include <CGAL/Highlight_lines/internal/Local_mesh.h>

#include <CGAL/boost/graph/iterator.h>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// Room in the arrays of `lm`, before it is built on the whole of `tm`, for what
// cut_at_creases() adds: at most two vertex copies and one edge per crease edge. Inserting them
// then moves no array of a large mesh (a fresh copy of its coordinates costs more than the cut).
template <typename TriangleMesh, typename CreaseMap>
void reserve_room_for_cut(const TriangleMesh& tm, CreaseMap creases, Local_mesh<TriangleMesh>& lm)
{
  std::size_t crease_edges = 0;
  for (auto e : edges(tm))
    crease_edges += get(creases, e) ? 1 : 0;
  const std::size_t vertices = num_vertices(tm) + 2 * crease_edges;
  lm.vertex_handles.reserve(vertices);
  lm.vertex_indices.reserve(vertices);
  lm.xyz.reserve(3 * vertices);
  lm.edge_halfedges.reserve(num_edges(tm) + crease_edges);
  lm.edge_vertices.reserve(num_edges(tm) + crease_edges);
}

// Cuts `lm` along the edges e with get(creases, e) == true: each model vertex gets one local
// vertex per sector (the faces around it between two crease edges or mesh borders), an edge
// along a crease gets one per side, and lm.sector_faces lists the faces of each vertex with
// several sectors for the exact evaluations. Without crease edges at a vertex, nothing changes
// there.
template <typename TriangleMesh, typename CreaseMap>
void cut_at_creases(const TriangleMesh& tm, CreaseMap creases, Local_mesh<TriangleMesh>& lm)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  const std::size_t model_vertices = lm.number_of_model_vertices;
  const std::size_t old_vertices = lm.vertex_handles.size();

  // Only the rings of the vertices on a crease edge are walked, and only their corners, faces
  // and edges change: a CAD part has thousands of them among millions of vertices, and arrays
  // over the whole mesh (first touched, on a large mesh) cost more than the cut itself.
  std::vector<char> on_crease(model_vertices, 0);
  for (std::size_t e = 0; e < lm.edge_halfedges.size(); ++e)
    if (get(creases, edge(lm.edge_halfedges[e], tm)))
      for (int u : lm.edge_vertices[e])
        on_crease[std::size_t(u)] = 1; // the ends of a model face's edge are model vertices
  // On a face range, a model vertex on its border also has edges of the one-ring closure only.
  for (std::size_t f = lm.number_of_model_faces; f < lm.face_handles.size(); ++f) {
    halfedge_descriptor h = halfedge(lm.face_handles[f], tm);
    for (std::size_t j = 0; j < 3; ++j, h = next(h, tm))
      if (get(creases, edge(h, tm)))
        for (int u : {lm.face_vertices[f][j], lm.face_vertices[f][(j + 1) % 3]})
          if (std::size_t(u) < model_vertices)
            on_crease[std::size_t(u)] = 1;
  }

  // 1. The sector of each face corner at a crease vertex. Around the target of h_i, the faces
  // face(h_i) and face(h_{i+1}) share the edge of next(h_i).
  struct Corner
  {
    std::size_t split; // the vertex, by position in `split`
    int face, corner, sector;
  };
  std::vector<Corner> corners;     // of the vertices with several sectors
  std::vector<int> split, sectors; // those vertices, and their numbers of sectors
  std::vector<int> ring_faces;
  std::vector<char> cut_after;
  for (std::size_t v = 0; v < model_vertices; ++v) {
    if (!on_crease[v])
      continue;
    ring_faces.clear();
    cut_after.clear();
    for (halfedge_descriptor h : halfedges_around_target(halfedge(lm.vertex_handles[v], tm), tm)) {
      const face_descriptor f = face(h, tm);
      ring_faces.push_back(f == GT::null_face() ? -1 : lm.face_ids.find(lm.face_index(f)));
      cut_after.push_back(get(creases, edge(next(h, tm), tm)));
    }
    const std::size_t n = ring_faces.size();
    auto boundary_before = [&](std::size_t i) {
      const std::size_t previous = (i + n - 1) % n;
      return cut_after[previous] || ring_faces[previous] < 0 || ring_faces[i] < 0;
    };
    std::size_t start = n;
    for (std::size_t i = 0; i < n && start == n; ++i)
      if (boundary_before(i))
        start = i;
    if (start == n)
      continue; // not reached: a crease edge is a boundary
    const std::size_t first_corner = corners.size();
    int sector = 0;
    bool sector_used = false;
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = (start + k) % n;
      if (k > 0 && boundary_before(i) && sector_used) {
        ++sector;
        sector_used = false;
      }
      const int f = ring_faces[i];
      if (f < 0)
        continue;
      sector_used = true;
      for (int c = 0; c < 3; ++c)
        if (lm.face_vertices[std::size_t(f)][std::size_t(c)] == int(v))
          corners.push_back({split.size(), f, c, sector});
    }
    // A boundary passed last (a border halfedge at the end of the ring, as OpenMesh's
    // halfedge(v) gives it) opens no sector: only sectors with faces count. A vertex where a
    // single crease edge ends keeps one sector.
    const int count = sector + (sector_used ? 1 : 0);
    if (count > 1) {
      split.push_back(int(v));
      sectors.push_back(count);
    } else
      corners.resize(first_corner);
  }
  if (split.empty())
    return;

  // 2. New vertices: sector 0 of a split vertex keeps its id, the others are new model
  // vertices after the old ones (the model is canonical: vertex and edge ids do not change
  // it); the vertices outside the model move up behind them.
  std::vector<int> first_copy(split.size() + 1, int(model_vertices));
  for (std::size_t i = 0; i < split.size(); ++i)
    first_copy[i + 1] = first_copy[i] + sectors[i] - 1;
  const int copies = first_copy.back() - int(model_vertices);
  {
    std::vector<typename Local_mesh<TriangleMesh>::vertex_descriptor> handles;
    std::vector<std::size_t> indices;
    std::vector<double> xyz;
    for (std::size_t i = 0; i < split.size(); ++i)
      for (int s = 1; s < sectors[i]; ++s) {
        const std::size_t v = std::size_t(split[i]);
        handles.push_back(lm.vertex_handles[v]);
        indices.push_back(lm.vertex_indices[v]);
        xyz.insert(xyz.end(), lm.xyz.begin() + std::ptrdiff_t(3 * v),
                   lm.xyz.begin() + std::ptrdiff_t(3 * v + 3));
      }
    const std::ptrdiff_t at = std::ptrdiff_t(model_vertices);
    lm.vertex_handles.insert(lm.vertex_handles.begin() + at, handles.begin(), handles.end());
    lm.vertex_indices.insert(lm.vertex_indices.begin() + at, indices.begin(), indices.end());
    lm.xyz.insert(lm.xyz.begin() + 3 * at, xyz.begin(), xyz.end());
  }
  if (old_vertices > model_vertices)
    for (std::array<int, 3>& face_corners : lm.face_vertices)
      for (int& u : face_corners)
        if (std::size_t(u) >= model_vertices)
          u += copies;
  lm.number_of_model_vertices = model_vertices + std::size_t(copies);
  auto vertex_of = [&](const Corner& c) {
    return c.sector == 0 ? split[c.split] : first_copy[c.split] + c.sector - 1;
  };

  // 3. The edges of the model faces whose corners changed: an edge whose two sides now join
  // different vertices (along a crease) becomes two, one per side, both with the old edge's
  // canonical halfedge and direction (the copies of a vertex keep its point and index, which
  // decide the direction).
  std::vector<int> edges_to_redo;
  for (const Corner& c : corners)
    if (c.sector > 0) {
      lm.face_vertices[std::size_t(c.face)][std::size_t(c.corner)] = vertex_of(c);
      if (std::size_t(c.face) < lm.number_of_model_faces)
        for (int e : lm.face_edges[std::size_t(c.face)])
          edges_to_redo.push_back(e);
    }
  std::sort(edges_to_redo.begin(), edges_to_redo.end());
  edges_to_redo.erase(std::unique(edges_to_redo.begin(), edges_to_redo.end()), edges_to_redo.end());
  for (int e : edges_to_redo) {
    const halfedge_descriptor h = lm.edge_halfedges[std::size_t(e)];
    const std::size_t first_index =
        lm.vertex_indices[std::size_t(lm.edge_vertices[std::size_t(e)][0])];
    bool first_side = true; // it keeps the old edge
    std::array<int, 2> first_ends{-1, -1};
    for (halfedge_descriptor side : {h, opposite(h, tm)}) {
      const face_descriptor fd = face(side, tm);
      if (fd == GT::null_face())
        continue;
      const int f = lm.face_ids.find(lm.face_index(fd));
      if (f < 0 || std::size_t(f) >= lm.number_of_model_faces)
        continue;
      for (std::size_t j = 0; j < 3; ++j) {
        if (lm.face_edges[std::size_t(f)][j] != e)
          continue;
        int a = lm.face_vertices[std::size_t(f)][j],
            b = lm.face_vertices[std::size_t(f)][(j + 1) % 3];
        if (lm.vertex_indices[std::size_t(a)] != first_index)
          std::swap(a, b);
        if (first_side) {
          first_side = false;
          first_ends = {a, b};
          lm.edge_vertices[std::size_t(e)] = first_ends;
        } else if (first_ends != std::array<int, 2>{a, b}) {
          lm.face_edges[std::size_t(f)][j] = int(lm.edge_halfedges.size());
          lm.edge_halfedges.push_back(h);
          lm.edge_vertices.push_back({a, b});
        }
      }
    }
  }

  // 4. The faces of each split vertex's sectors, for the exact evaluations.
  std::vector<std::pair<int, int>> vertex_faces; // (vertex, face)
  for (const Corner& c : corners)
    vertex_faces.push_back({vertex_of(c), c.face});
  std::sort(vertex_faces.begin(), vertex_faces.end());
  lm.sector_vertices.clear();
  lm.sector_face_begin.assign(1, 0);
  lm.sector_faces.clear();
  for (const auto& [vertex, f] : vertex_faces) {
    if (lm.sector_vertices.empty() || lm.sector_vertices.back() != vertex) {
      lm.sector_vertices.push_back(vertex);
      lm.sector_face_begin.push_back(lm.sector_face_begin.back());
    }
    lm.sector_faces.push_back(f);
    ++lm.sector_face_begin.back();
  }
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_CREASE_CUT_H

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

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// Cuts `lm` along the edges e with get(creases, e) == true: each model vertex gets one local
// vertex per sector (the faces around it between two crease edges or mesh borders), the edges
// of the model faces are renumbered, and lm.sector_faces lists each model vertex's faces for
// the exact evaluations. Without crease edges at a vertex, nothing changes there.
template <typename TriangleMesh, typename CreaseMap>
void cut_at_creases(const TriangleMesh& tm, CreaseMap creases, Local_mesh<TriangleMesh>& lm)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  const std::size_t model_vertices = lm.number_of_model_vertices;
  const std::size_t old_vertices = lm.vertex_handles.size();

  // 1. The sector of each face corner at a model vertex. Around the target of h_i, the faces
  // face(h_i) and face(h_{i+1}) share the edge of next(h_i).
  std::vector<int> corner_sector(3 * lm.face_vertices.size(), 0);
  std::vector<int> sectors(model_vertices, 1);
  std::vector<int> ring_faces;
  std::vector<char> cut_after;
  bool any_cut = false;
  for (std::size_t v = 0; v < model_vertices; ++v) {
    ring_faces.clear();
    cut_after.clear();
    bool has_crease = false;
    for (halfedge_descriptor h : halfedges_around_target(halfedge(lm.vertex_handles[v], tm), tm)) {
      const face_descriptor f = face(h, tm);
      ring_faces.push_back(f == GT::null_face() ? -1 : lm.face_ids.find(lm.face_index(f)));
      const bool crease = get(creases, edge(next(h, tm), tm));
      cut_after.push_back(crease);
      has_crease = has_crease || crease;
    }
    if (!has_crease)
      continue;
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
          corner_sector[3 * std::size_t(f) + std::size_t(c)] = sector;
    }
    // A boundary passed last (a border halfedge at the end of the ring, as OpenMesh's
    // halfedge(v) gives it) opens no sector: only sectors with faces count. A vertex where a
    // single crease edge ends keeps one sector.
    sectors[v] = sector + (sector_used ? 1 : 0);
    any_cut = any_cut || sectors[v] > 1;
  }
  if (!any_cut)
    return;

  // 2. New vertex ids: the sectors of a model vertex follow each other; model vertices stay
  // first.
  std::vector<int> first_id(model_vertices + 1, 0);
  for (std::size_t v = 0; v < model_vertices; ++v)
    first_id[v + 1] = first_id[v] + sectors[v];
  const int new_model_vertices = first_id[model_vertices];
  std::vector<typename Local_mesh<TriangleMesh>::vertex_descriptor> handles;
  std::vector<std::size_t> indices;
  std::vector<double> xyz;
  handles.reserve(std::size_t(new_model_vertices) + old_vertices - model_vertices);
  for (std::size_t v = 0; v < old_vertices; ++v)
    for (int s = 0; s < (v < model_vertices ? sectors[v] : 1); ++s) {
      handles.push_back(lm.vertex_handles[v]);
      indices.push_back(lm.vertex_indices[v]);
      xyz.insert(xyz.end(), lm.xyz.begin() + std::ptrdiff_t(3 * v),
                 lm.xyz.begin() + std::ptrdiff_t(3 * v + 3));
    }
  for (std::size_t f = 0; f < lm.face_vertices.size(); ++f)
    for (std::size_t c = 0; c < 3; ++c) {
      int& u = lm.face_vertices[f][c];
      u = std::size_t(u) < model_vertices ? first_id[std::size_t(u)] + corner_sector[3 * f + c]
                                          : new_model_vertices + (u - int(model_vertices));
    }
  lm.vertex_handles = std::move(handles);
  lm.vertex_indices = std::move(indices);
  lm.xyz = std::move(xyz);
  lm.number_of_model_vertices = std::size_t(new_model_vertices);

  // 3. The edges of the model faces, in the order the faces reach them, with the canonical
  // direction of build_local_mesh(): an edge stays one edge where the ends of its two sides
  // agree, and becomes two (one per side) along a crease. A table of two slots per old edge
  // finds them (a hash of the end pairs missed the cache on every side of a large mesh).
  std::vector<std::array<int, 2>> new_edges_of(lm.edge_halfedges.size(), {-1, -1});
  lm.edge_halfedges.clear();
  lm.edge_vertices.clear();
  for (std::size_t f = 0; f < lm.number_of_model_faces; ++f) {
    halfedge_descriptor h = halfedge(lm.face_handles[f], tm);
    for (std::size_t j = 0; j < 3; ++j, h = next(h, tm)) {
      int a = lm.face_vertices[f][j], b = lm.face_vertices[f][(j + 1) % 3];
      std::array<int, 2>& slots = new_edges_of[std::size_t(lm.face_edges[f][j])];
      int id = -1;
      for (int& slot : slots) {
        if (slot < 0) {
          slot = int(lm.edge_halfedges.size());
          halfedge_descriptor canonical = h;
          if (against_canonical_direction(lm, a, b)) {
            std::swap(a, b);
            canonical = opposite(h, tm);
          }
          lm.edge_halfedges.push_back(canonical);
          lm.edge_vertices.push_back({a, b});
        }
        const std::array<int, 2>& ends = lm.edge_vertices[std::size_t(slot)];
        if ((ends[0] == a && ends[1] == b) || (ends[0] == b && ends[1] == a)) {
          id = slot;
          break;
        }
      }
      lm.face_edges[f][j] = id; // an edge has two sides on a triangle mesh: id >= 0
    }
  }

  // 4. The faces of each model vertex's sector, for the exact evaluations.
  lm.sector_face_begin.assign(std::size_t(new_model_vertices) + 1, 0);
  for (const std::array<int, 3>& corners : lm.face_vertices)
    for (int u : corners)
      if (u < new_model_vertices)
        ++lm.sector_face_begin[std::size_t(u) + 1];
  for (std::size_t u = 0; u < std::size_t(new_model_vertices); ++u)
    lm.sector_face_begin[u + 1] += lm.sector_face_begin[u];
  lm.sector_faces.assign(std::size_t(lm.sector_face_begin.back()), 0);
  std::vector<int> next_slot(lm.sector_face_begin.begin(), lm.sector_face_begin.end() - 1);
  for (std::size_t f = 0; f < lm.face_vertices.size(); ++f)
    for (int u : lm.face_vertices[f])
      if (u < new_model_vertices)
        lm.sector_faces[std::size_t(next_slot[std::size_t(u)]++)] = int(f);
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_CREASE_CUT_H

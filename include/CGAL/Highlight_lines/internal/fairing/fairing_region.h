// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_FAIRING_REGION_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_FAIRING_REGION_H

#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/Highlight_lines/internal/Local_mesh.h>

#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// The fairing region R on the local mesh of the neighbourhood model, and what §3.1 derives
// from it.
//
// A vertex is *inside* R when it is not on a mesh border and every face around it is in R;
// every other vertex is outside R. A node is inside R when it lies inside an edge whose two
// faces are in R, or on a vertex inside R; all other nodes are outside.
//
// Movable vertices (§3.1): vertices of R that are not support vertices of any vertex or node
// outside R. The support of a vertex is itself and its one-ring (eq. 3); the support of a node
// on edge (V1, V2) is V1, V2 and their supports (eq. 4). The ends of an edge carrying a node
// outside R are themselves outside R, so this reduces to: the vertices inside R whose whole
// one-ring is inside R.
struct Fairing_region
{
  std::vector<char> face_in_region;                 // per local face
  std::vector<char> vertex_inside;                  // per model vertex
  std::vector<char> edge_inside;                    // per local edge: both faces in R
  std::vector<char> edge_touches_region;            // per local edge: a face in R
  std::vector<int> movable;                         // local vertex ids
  std::vector<int> variable;                        // per local vertex: index in `movable`, or -1
  std::vector<int> energy_vertices;                 // the vertices inside R (eq. 6 sums over them)
  std::vector<int> vertex_face_begin, vertex_faces; // local faces around each local vertex
  std::vector<int> vertex_neighbor_begin, vertex_neighbors; // one-rings, for model vertices
};

template <typename TriangleMesh, typename IsInRegion>
void build_fairing_region(const TriangleMesh& tm, const Local_mesh<TriangleMesh>& lm,
                          IsInRegion&& is_in_region, Fairing_region& out)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  const std::size_t nf = lm.face_vertices.size(), nv = lm.vertex_handles.size(),
                    nmv = lm.number_of_model_vertices;

  out.face_in_region.assign(nf, 0);
  for (std::size_t f = 0; f < nf; ++f)
    out.face_in_region[f] = is_in_region(lm.face_handles[f]) ? 1 : 0;

  // Local faces around local vertices (complete one-rings for the model vertices).
  std::vector<int> count(nv + 1, 0);
  for (const auto& corners : lm.face_vertices)
    for (int v : corners)
      ++count[std::size_t(v) + 1];
  for (std::size_t v = 0; v < nv; ++v)
    count[v + 1] += count[v];
  out.vertex_face_begin = count;
  out.vertex_faces.assign(std::size_t(count[nv]), 0);
  for (std::size_t f = 0; f < nf; ++f)
    for (int v : lm.face_vertices[f])
      out.vertex_faces[std::size_t(count[std::size_t(v)]++)] = int(f);

  // The region is asked once per face (it may be a std::set): the rest reads face_in_region.
  // Inside: no mesh border at the vertex and its whole one-ring, which the local mesh holds
  // for model vertices, in R.
  out.vertex_inside.assign(nmv, 0);
  for (std::size_t v = 0; v < nmv; ++v) {
    bool inside = true;
    for (int i = out.vertex_face_begin[v]; i < out.vertex_face_begin[v + 1] && inside; ++i)
      inside = out.face_in_region[std::size_t(out.vertex_faces[std::size_t(i)])] != 0;
    if (inside)
      for (halfedge_descriptor h : halfedges_around_target(halfedge(lm.vertex_handles[v], tm), tm))
        if (face(h, tm) == boost::graph_traits<TriangleMesh>::null_face()) {
          inside = false;
          break;
        }
    out.vertex_inside[v] = inside;
  }

  // Every edge belongs to a model face, and faces in R are model faces.
  std::vector<unsigned char> faces_in_region(lm.edge_halfedges.size(), 0);
  for (std::size_t f = 0; f < lm.number_of_model_faces; ++f)
    if (out.face_in_region[f])
      for (int e : lm.face_edges[f])
        ++faces_in_region[std::size_t(e)];
  out.edge_inside.assign(faces_in_region.size(), 0);
  out.edge_touches_region.assign(faces_in_region.size(), 0);
  for (std::size_t e = 0; e < faces_in_region.size(); ++e) {
    out.edge_inside[e] = faces_in_region[e] == 2;
    out.edge_touches_region[e] = faces_in_region[e] > 0;
  }

  // One-rings of model vertices, from the local faces.
  out.vertex_neighbor_begin.assign(nmv + 1, 0);
  out.vertex_neighbors.clear();
  for (std::size_t v = 0; v < nmv; ++v) {
    for (int i = out.vertex_face_begin[v]; i < out.vertex_face_begin[v + 1]; ++i)
      for (int w : lm.face_vertices[std::size_t(out.vertex_faces[std::size_t(i)])])
        if (w != int(v) && std::find(out.vertex_neighbors.begin() + out.vertex_neighbor_begin[v],
                                     out.vertex_neighbors.end(), w) == out.vertex_neighbors.end())
          out.vertex_neighbors.push_back(w);
    out.vertex_neighbor_begin[v + 1] = int(out.vertex_neighbors.size());
  }

  out.movable.clear();
  out.energy_vertices.clear();
  out.variable.assign(nv, -1);
  for (std::size_t v = 0; v < nmv; ++v) {
    if (!out.vertex_inside[v])
      continue;
    out.energy_vertices.push_back(int(v));
    bool ring_inside = true;
    for (int i = out.vertex_neighbor_begin[v]; i < out.vertex_neighbor_begin[v + 1]; ++i) {
      const int w = out.vertex_neighbors[std::size_t(i)];
      ring_inside = ring_inside && std::size_t(w) < nmv && out.vertex_inside[std::size_t(w)];
    }
    if (ring_inside) {
      out.variable[v] = int(out.movable.size());
      out.movable.push_back(int(v));
    }
  }
}

// Throws Invalid_input if `region` has no movable vertex (nothing to fair).
inline void require_movable_vertex(const Fairing_region& region)
{
  if (region.movable.empty())
    throw Invalid_input(Invalid_input::Problem::NO_MOVABLE_VERTEX,
                        "the fairing region has no movable vertex: a vertex can move only if "
                        "it and all its neighbours lie inside the region (not on its border nor "
                        "on a mesh border); enlarge the region by at least two rings");
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_FAIRING_REGION_H

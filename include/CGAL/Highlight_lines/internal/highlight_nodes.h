// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_HIGHLIGHT_NODES_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_HIGHLIGHT_NODES_H

#include <CGAL/Highlight_lines/internal/Local_mesh.h>
#include <CGAL/Highlight_lines/internal/level_classification.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// Options restricting the model (SPEC §3, "bounded output").
struct Level_window
{
  long long lowest = -(1LL << 50), highest = (1LL << 50); // levels m considered
  std::size_t max_levels_per_edge = 256;                  // edges over it are skipped

  bool contains(long long m) const { return lowest <= m && m <= highest; }
};

// A highlight node (§2.3): on the interior of an edge (edge >= 0) or on a vertex
// (vertex >= 0) whose d value equals m·s exactly.
struct Raw_node
{
  int edge = -1;
  int vertex = -1;
  long long level = 0;
  double parameter = 0; // along the canonical edge direction, from edge_vertices[edge][0]
  std::array<double, 3> point{};
};

// The interior nodes of one edge: levels first_level .. first_level + count - 1, ascending,
// with node ids first_node .. first_node + count - 1.
struct Edge_nodes
{
  int first_node = 0;
  int count = 0;
  long long first_level = 0;
  bool skipped = false; // more levels than allowed, or d undefined/out of range at an end

  int node_at_level(long long m) const { return first_node + int(m - first_level); }
};

struct Highlight_nodes
{
  std::vector<Raw_node> nodes;
  std::vector<Edge_nodes> edges;
  std::vector<int> vertex_node; // per model vertex: node id or -1
  std::size_t number_of_capped_edges = 0;
};

// Both ends defined, with the same side of the light plane: d is continuous on the edge.
inline bool edge_is_usable(const Vertex_level& a, const Vertex_level& b)
{
  return a.defined() && b.defined() && a.normal_side == b.normal_side;
}

// Eq. 4 (corrected): on edge (V1, V2) with d1 != d2, a node for every m with m·s strictly
// between d1 and d2, at Q = V1 + t (V2 - V1), t = (m·s - d1) / (d2 - d1). Which levels lie
// strictly between is read from the exact vertex classes, never from the rounded d values.
template <typename TriangleMesh>
void compute_highlight_nodes(const Local_mesh<TriangleMesh>& lm,
                             const std::vector<Vertex_level>& levels, double spacing,
                             const Level_window& window, Highlight_nodes& out)
{
  const std::size_t ne = lm.edge_vertices.size();
  out.nodes.clear();
  out.edges.assign(ne, Edge_nodes());
  out.number_of_capped_edges = 0;

  int next_id = 0;
  for (std::size_t e = 0; e < ne; ++e) {
    Edge_nodes& en = out.edges[e];
    const Vertex_level& a = levels[std::size_t(lm.edge_vertices[e][0])];
    const Vertex_level& b = levels[std::size_t(lm.edge_vertices[e][1])];
    if (!edge_is_usable(a, b)) {
      en.skipped = true;
      continue;
    }
    const bool a_is_lower = a.level <= b.level;
    const Vertex_level& lo = a_is_lower ? a : b;
    const Vertex_level& hi = a_is_lower ? b : a;
    // Levels strictly between: (lo.level, hi.level], minus hi.level when hi lies on it.
    long long first = lo.level + 1, last = hi.on_level ? hi.level - 1 : hi.level;
    first = (std::max)(first, window.lowest);
    last = (std::min)(last, window.highest);
    if (last < first)
      continue;
    if (std::size_t(last - first + 1) > window.max_levels_per_edge) {
      en.skipped = true;
      ++out.number_of_capped_edges;
      continue;
    }
    en.first_node = next_id;
    en.first_level = first;
    en.count = int(last - first + 1);
    next_id += en.count;
  }

  out.nodes.resize(std::size_t(next_id));
  for (std::size_t e = 0; e < ne; ++e) {
    const Edge_nodes& en = out.edges[e];
    if (en.count == 0)
      continue;
    const int va = lm.edge_vertices[e][0], vb = lm.edge_vertices[e][1];
    const double da = levels[std::size_t(va)].distance, db = levels[std::size_t(vb)].distance;
    const double* pa = lm.point(va);
    const double* pb = lm.point(vb);
    for (int i = 0; i < en.count; ++i) {
      Raw_node& node = out.nodes[std::size_t(en.first_node + i)];
      node.edge = int(e);
      node.level = en.first_level + i;
      const double t = db != da ? (double(node.level) * spacing - da) / (db - da) : 0.5;
      node.parameter = std::min(1.0, std::max(0.0, t)); // rounding must not leave the edge
      for (int k = 0; k < 3; ++k)
        node.point[std::size_t(k)] = pa[k] + node.parameter * (pb[k] - pa[k]);
    }
  }

  out.vertex_node.assign(lm.number_of_model_vertices, -1);
  for (std::size_t v = 0; v < lm.number_of_model_vertices; ++v) {
    const Vertex_level& l = levels[v];
    if (!l.defined() || !l.on_level || !window.contains(l.level))
      continue;
    Raw_node node;
    node.vertex = int(v);
    node.level = l.level;
    const double* p = lm.point(int(v));
    node.point = {p[0], p[1], p[2]};
    out.vertex_node[v] = int(out.nodes.size());
    out.nodes.push_back(node);
  }
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_HIGHLIGHT_NODES_H

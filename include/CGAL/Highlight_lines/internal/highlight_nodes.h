// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_HIGHLIGHT_NODES_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_HIGHLIGHT_NODES_H

#include <CGAL/Highlight_lines/internal/Local_mesh.h>
#include <CGAL/Highlight_lines/internal/level_classification.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <stdexcept>
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

struct Highlight_nodes
{
  static constexpr int no_node = -1; // an edge with no node inside
  static constexpr int capped = -2;  // an edge with more levels inside than allowed

  std::vector<Raw_node> nodes;
  // Per edge: the id of its node of lowest level, or no_node, or capped. The nodes of an
  // edge have consecutive ids, by increasing level from first_interior_level().
  std::vector<int> edge_first_node;
  std::vector<int> vertex_node; // per model vertex: node id or -1
  std::size_t number_of_capped_edges = 0;
};

// Both ends defined, with the same side of the light plane: d is continuous on the edge.
inline bool edge_is_usable(const Vertex_level& a, const Vertex_level& b)
{
  return a.defined() && b.defined() && a.normal_side == b.normal_side;
}

// The lowest level strictly inside the edge, within the window.
inline long long first_interior_level(const Vertex_level& a, const Vertex_level& b,
                                      const Level_window& window)
{
  return (std::max)((std::min)(a.level, b.level) + 1, window.lowest);
}

// The id of the node of level m inside edge e (which must carry one).
inline int node_on_edge(const Highlight_nodes& hn, int e, const Vertex_level& a,
                        const Vertex_level& b, const Level_window& window, long long m)
{
  return hn.edge_first_node[std::size_t(e)] + int(m - first_interior_level(a, b, window));
}

// Eq. 4 (corrected): on edge (V1, V2) with d1 != d2, a node for every m with m·s strictly
// between d1 and d2, at Q = V1 + t (V2 - V1), t = (m·s - d1) / (d2 - d1). Which levels lie
// strictly between is read from the exact vertex classes, never from the rounded d values.
// A compact sort key of a vertex class, so that the hot loops over edges and faces read 8
// bytes per vertex: 2k + 1 when k·s < d < (k+1)·s, 2k when d = k·s; an odd sentinel when d
// is undefined. Two ends with equal keys have no level strictly between them.
inline long long level_key(const Vertex_level& l)
{
  // The sentinel is odd: faces and edges with undefined ends take the quick rejections.
  return l.defined() ? 2 * l.level + (l.on_level ? 0 : 1)
                     : (std::numeric_limits<long long>::min)() + 1;
}

inline void compute_level_keys(const std::vector<Vertex_level>& levels,
                               std::vector<long long>& keys)
{
  keys.resize(levels.size());
  for (std::size_t v = 0; v < levels.size(); ++v)
    keys[v] = level_key(levels[v]);
}

template <typename TriangleMesh>
void compute_highlight_nodes(const Local_mesh<TriangleMesh>& lm,
                             const std::vector<Vertex_level>& levels,
                             const std::vector<long long>& keys, double spacing,
                             const Level_window& window, Highlight_nodes& out)
{
  const std::size_t ne = lm.edge_vertices.size();
  out.nodes.clear();
  out.edge_first_node.assign(ne, Highlight_nodes::no_node);
  out.number_of_capped_edges = 0;

  std::vector<int> carrying; // edges with nodes, in order
  int next_id = 0;
  for (std::size_t e = 0; e < ne; ++e) {
    const std::size_t va = std::size_t(lm.edge_vertices[e][0]),
                      vb = std::size_t(lm.edge_vertices[e][1]);
    if (keys[va] == keys[vb])
      continue; // the common case first: no level strictly inside
    const Vertex_level& a = levels[va];
    const Vertex_level& b = levels[vb];
    if (a.level == b.level || !edge_is_usable(a, b))
      continue;
    const Vertex_level& hi = a.level < b.level ? b : a;
    // Levels strictly inside: (lo.level, hi.level], minus hi.level when hi lies on it.
    const long long first = first_interior_level(a, b, window);
    const long long last = (std::min)(hi.on_level ? hi.level - 1 : hi.level, window.highest);
    if (last < first)
      continue;
    if (std::size_t(last - first + 1) > window.max_levels_per_edge) {
      out.edge_first_node[e] = Highlight_nodes::capped;
      ++out.number_of_capped_edges;
      continue;
    }
    if (last - first + 1 > (std::numeric_limits<int>::max)() - next_id)
      throw std::length_error("highlight line model: more than 2^31 nodes; restrict it with "
                              "the level_range or face_range named parameters, or raise the "
                              "spacing");
    out.edge_first_node[e] = next_id;
    next_id += int(last - first + 1);
    carrying.push_back(int(e));
  }

  out.nodes.resize(std::size_t(next_id));
  for (int edge : carrying) {
    const std::size_t e = std::size_t(edge);
    const int va = lm.edge_vertices[e][0], vb = lm.edge_vertices[e][1];
    const Vertex_level& a = levels[std::size_t(va)];
    const Vertex_level& b = levels[std::size_t(vb)];
    const double da = a.distance, db = b.distance;
    const double* pa = lm.point(va);
    const double* pb = lm.point(vb);
    const long long first = first_interior_level(a, b, window);
    const Vertex_level& hi = a.level < b.level ? b : a;
    const long long last = (std::min)(hi.on_level ? hi.level - 1 : hi.level, window.highest);
    for (long long m = first; m <= last; ++m) {
      Raw_node& node = out.nodes[std::size_t(out.edge_first_node[e] + int(m - first))];
      node.edge = int(e);
      node.level = m;
      const double t = db != da ? (double(m) * spacing - da) / (db - da) : 0.5;
      node.parameter = std::min(1.0, std::max(0.0, t)); // rounding must not leave the edge
      for (int k = 0; k < 3; ++k)
        node.point[std::size_t(k)] = pa[k] + node.parameter * (pb[k] - pa[k]);
    }
  }

  out.vertex_node.assign(lm.number_of_model_vertices, -1);
  for (std::size_t v = 0; v < lm.number_of_model_vertices; ++v) {
    if (keys[v] & 1)
      continue; // not on a level
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

// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_MODEL_LINE_TRACING_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_MODEL_LINE_TRACING_H

#include <CGAL/Highlight_lines/internal/model/highlight_nodes.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

struct Traced_line
{
  long long level = 0;
  bool closed = false;
  std::vector<int> nodes; // a closed line does not repeat its first node
};

struct Traced_lines
{
  std::vector<Traced_line> lines;
  std::vector<int> degree;    // per node
  std::vector<int> new_order; // node ids in canonical order (old ids)
  std::vector<int> new_id;    // its inverse: the canonical id of each node
  // Work arrays, kept so that a sweep reuses the memory of the previous one.
  std::vector<int> begin, fill, isolated;
  std::vector<std::array<int, 2>> incident; // per node: its segments and their other ends
  std::vector<char> used;
};

// Canonical order of nodes: by level, then lexicographically by position. Used to make the
// output independent of the order of faces and of the mesh data structure.
inline bool node_less(const Raw_node& a, const Raw_node& b)
{
  if (a.level != b.level)
    return a.level < b.level;
  if (a.point != b.point)
    return a.point < b.point;
  return (a.vertex >= 0) < (b.vertex >= 0);
}

// Splits the graph of segments into maximal polylines: a line runs through nodes of degree 2
// and ends at nodes of any other degree (mesh or range borders, poles, capped edges, and
// vertices lying exactly on a level at a saddle, where lines meet). What remains are closed
// lines. Then every line gets a canonical start and direction, lines are sorted, and nodes
// are renumbered in order of appearance.
inline void trace_lines(const std::vector<Raw_node>& nodes,
                        const std::vector<std::array<int, 2>>& segments, Traced_lines& out)
{
  const std::size_t n = nodes.size();
  out.lines.clear();
  out.degree.assign(n, 0);
  for (const auto& s : segments) {
    ++out.degree[std::size_t(s[0])];
    ++out.degree[std::size_t(s[1])];
  }
  std::vector<int>& begin = out.begin;
  begin.assign(n + 1, 0);
  for (std::size_t v = 0; v < n; ++v)
    begin[v + 1] = begin[v] + out.degree[v];
  // Per node, its segments with their other ends: a step of a walk reads the node's entries
  // only, not the segment.
  std::vector<std::array<int, 2>>& incident = out.incident;
  incident.resize(static_cast<std::size_t>(begin[n]));
  {
    std::vector<int>& fill = out.fill;
    fill.assign(begin.begin(), begin.end() - 1);
    for (std::size_t s = 0; s < segments.size(); ++s) {
      const int a = segments[s][0], b = segments[s][1];
      incident[std::size_t(fill[std::size_t(a)]++)] = {int(s), b};
      incident[std::size_t(fill[std::size_t(b)]++)] = {int(s), a};
    }
  }
  std::vector<char>& used = out.used;
  used.assign(segments.size(), 0);
  auto degree_of = [&](int v) { return begin[std::size_t(v) + 1] - begin[std::size_t(v)]; };
  // From node start along its entry `first`.
  auto walk = [&](int start, const std::array<int, 2>& first) {
    Traced_line line;
    line.level = nodes[std::size_t(start)].level;
    line.nodes.push_back(start);
    int s = first[0], v = first[1];
    const bool start_has_degree_2 = degree_of(start) == 2;
    for (;;) {
      used[std::size_t(s)] = 1;
      if (v == start && start_has_degree_2) {
        line.closed = true;
        break;
      }
      line.nodes.push_back(v);
      const int* range = &begin[std::size_t(v)];
      if (range[1] - range[0] != 2)
        break;
      const std::array<int, 2>* inc = &incident[std::size_t(range[0])];
      const std::array<int, 2>& next = inc[0][0] == s ? inc[1] : inc[0];
      s = next[0];
      v = next[1];
      if (used[std::size_t(s)])
        break;
    }
    out.lines.push_back(std::move(line));
  };
  for (std::size_t v = 0; v < n; ++v)
    if (out.degree[v] != 2)
      for (int i = begin[v]; i < begin[v + 1]; ++i)
        if (!used[std::size_t(incident[std::size_t(i)][0])])
          walk(int(v), incident[std::size_t(i)]);
  for (std::size_t v = 0; v < n; ++v)
    for (int i = begin[v]; i < begin[v + 1]; ++i)
      if (!used[std::size_t(incident[std::size_t(i)][0])])
        walk(int(v), incident[std::size_t(i)]);

  auto less = [&](int a, int b) { return node_less(nodes[std::size_t(a)], nodes[std::size_t(b)]); };
  for (Traced_line& line : out.lines) {
    std::vector<int>& ids = line.nodes;
    if (!line.closed) {
      if (less(ids.back(), ids.front()))
        std::reverse(ids.begin(), ids.end());
    } else {
      std::rotate(ids.begin(), std::min_element(ids.begin(), ids.end(), less), ids.end());
      if (ids.size() > 2 && less(ids.back(), ids[1]))
        std::reverse(ids.begin() + 1, ids.end());
    }
  }
  std::sort(out.lines.begin(), out.lines.end(), [&](const Traced_line& a, const Traced_line& b) {
    if (a.level != b.level)
      return a.level < b.level;
    const std::size_t common = (std::min)(a.nodes.size(), b.nodes.size());
    for (std::size_t i = 0; i < common && i < 2; ++i) {
      if (less(a.nodes[i], b.nodes[i]))
        return true;
      if (less(b.nodes[i], a.nodes[i]))
        return false;
    }
    if (a.closed != b.closed)
      return a.closed < b.closed;
    return a.nodes.size() < b.nodes.size();
  });

  std::vector<int>& new_id = out.new_id;
  new_id.assign(n, -1);
  out.new_order.clear();
  out.new_order.reserve(n);
  for (const Traced_line& line : out.lines)
    for (int v : line.nodes)
      if (new_id[std::size_t(v)] < 0) {
        new_id[std::size_t(v)] = int(out.new_order.size());
        out.new_order.push_back(v);
      }
  std::vector<int>& isolated = out.isolated;
  isolated.clear();
  for (std::size_t v = 0; v < n; ++v)
    if (new_id[v] < 0)
      isolated.push_back(int(v));
  std::sort(isolated.begin(), isolated.end(), less);
  for (int v : isolated) {
    new_id[std::size_t(v)] = int(out.new_order.size());
    out.new_order.push_back(v);
  }
  for (Traced_line& line : out.lines)
    for (int& v : line.nodes)
      v = new_id[std::size_t(v)];
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_MODEL_LINE_TRACING_H

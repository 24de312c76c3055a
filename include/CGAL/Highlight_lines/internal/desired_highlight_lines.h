// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_DESIRED_HIGHLIGHT_LINES_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_DESIRED_HIGHLIGHT_LINES_H

#include <CGAL/Highlight_lines/internal/fairing_region.h>
#include <CGAL/Highlight_lines/internal/highlight_nodes.h>
#include <CGAL/Highlight_lines/internal/line_tracing.h>
#include <CGAL/Highlight_lines/internal/node_jacobian.h>

#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// Identifies a node across recomputations of the model: nodes outside R never move.
struct Node_key
{
  int edge = -1;
  int vertex = -1;
  long long level = 0;

  static Node_key of(const Raw_node& n) { return {n.edge, n.vertex, n.level}; }
  bool operator<(const Node_key& o) const
  {
    return std::tie(edge, vertex, level) < std::tie(o.edge, o.vertex, o.level);
  }
  bool operator==(const Node_key& o) const
  {
    return edge == o.edge && vertex == o.vertex && level == o.level;
  }
};

inline bool node_is_inside(const Raw_node& n, const Fairing_region& region)
{
  return n.edge >= 0 ? region.edge_inside[std::size_t(n.edge)] != 0
                     : region.vertex_inside[std::size_t(n.vertex)] != 0;
}

// A maximal part of a highlight line inside R between two delimiting nodes outside R
// (§3.2): node ids (canonical ids of the model) from Q0 to Q1 inclusive, in travel order.
struct Line_piece
{
  std::vector<int> nodes;
  // The outside nodes before Q0 and after Q1 (up to two each, nearest first), for the
  // tangent estimates; -1 where the line ends.
  std::array<int, 2> before{{-1, -1}}, after{{-1, -1}};
};

struct Pieces_found
{
  std::vector<Line_piece> pieces;
  std::size_t lines_ending_inside = 0; // enter R and end there (border, pole, saddle): no target
  std::size_t loops_inside = 0;        // closed lines wholly inside R: no target
};

// Cuts every line of the model into its parts inside R.
template <typename Model>
Pieces_found find_line_pieces(const Model& model, const Fairing_region& region)
{
  Pieces_found found;
  for (const Traced_line& line : model.lines.lines) {
    const std::vector<int>& ids = line.nodes;
    const std::size_t n = ids.size();
    std::vector<char> inside(n);
    bool any_inside = false, any_outside = false;
    for (std::size_t i = 0; i < n; ++i) {
      inside[i] = node_is_inside(model.node(std::size_t(ids[i])), region);
      any_inside = any_inside || inside[i];
      any_outside = any_outside || !inside[i];
    }
    if (!any_inside)
      continue;
    if (!any_outside) {
      if (line.closed)
        ++found.loops_inside;
      else
        ++found.lines_ending_inside;
      continue;
    }
    // An open line that starts inside R enters R from its end and gets no target there.
    if (!line.closed && inside[0])
      ++found.lines_ending_inside;
    // Walk from an outside node; a closed line is walked around once, cyclically.
    long long first = 0;
    if (line.closed)
      while (inside[std::size_t(first)])
        ++first;
    const long long count = (long long)n;
    auto exists = [&](long long k) { return line.closed || (first + k >= 0 && first + k < count); };
    auto index = [&](long long k) { return std::size_t(((first + k) % count + count) % count); };
    auto outside_at = [&](long long k) { return exists(k) && !inside[index(k)]; };
    for (long long k = 0; k < count - first; ++k) {
      if (!outside_at(k) || !exists(k + 1) || outside_at(k + 1))
        continue;
      Line_piece piece;
      piece.nodes.push_back(ids[index(k)]);
      long long j = k + 1;
      while (exists(j) && !outside_at(j))
        piece.nodes.push_back(ids[index(j++)]);
      if (!exists(j)) {
        ++found.lines_ending_inside;
        break;
      }
      piece.nodes.push_back(ids[index(j)]);
      for (int b = 0; b < 2 && outside_at(k - 1 - b); ++b)
        piece.before[std::size_t(b)] = ids[index(k - 1 - b)];
      for (int b = 0; b < 2 && outside_at(j + 1 + b); ++b)
        piece.after[std::size_t(b)] = ids[index(j + 1 + b)];
      found.pieces.push_back(std::move(piece));
      k = j - 1;
    }
  }
  return found;
}

// Tangent at the end point p of a line coming from q1 (nearest) and q2: the derivative of the
// chord-length quadratic through q2, q1, p at p (or the last chord with one neighbour).
inline Vec3 end_tangent(const Vec3& p, const Vec3* q1, const Vec3* q2)
{
  auto sub = [](const Vec3& a, const Vec3& b) {
    return Vec3{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  };
  auto norm = [](const Vec3& a) { return std::sqrt(dot3(a, a)); };
  const Vec3 d1 = sub(p, *q1);
  const double h1 = norm(d1);
  if (q2 == nullptr || !(h1 > 0))
    return d1;
  const Vec3 d2 = sub(*q1, *q2);
  const double h2 = norm(d2);
  if (!(h2 > 0))
    return d1;
  const double w = h1 / (h1 + h2);
  Vec3 t;
  for (int k = 0; k < 3; ++k)
    t[std::size_t(k)] =
        d1[std::size_t(k)] / h1 + w * (d1[std::size_t(k)] / h1 - d2[std::size_t(k)] / h2);
  return t;
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_DESIRED_HIGHLIGHT_LINES_H

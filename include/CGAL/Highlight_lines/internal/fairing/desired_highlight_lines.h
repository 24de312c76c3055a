// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_DESIRED_HIGHLIGHT_LINES_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_DESIRED_HIGHLIGHT_LINES_H

#include <CGAL/Highlight_lines/internal/fairing/fairing_region.h>
#include <CGAL/Highlight_lines/internal/model/highlight_nodes.h>
#include <CGAL/Highlight_lines/internal/model/line_tracing.h>
#include <CGAL/Highlight_lines/internal/fairing/node_jacobian.h>

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
  // The outside nodes before Q0 and after Q1 (up to max_tangent_nodes each, nearest first),
  // for the tangent estimates.
  std::vector<int> before, after;
};

constexpr long long max_tangent_nodes = 8;

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
      for (long long b = 0; b < max_tangent_nodes && outside_at(k - 1 - b) && b + 1 < count; ++b)
        piece.before.push_back(ids[index(k - 1 - b)]);
      for (long long b = 0; b < max_tangent_nodes && outside_at(j + 1 + b) && b + 1 < count; ++b)
        piece.after.push_back(ids[index(j + 1 + b)]);
      found.pieces.push_back(std::move(piece));
      k = j - 1;
    }
  }
  return found;
}

// Tangent at the end point p of a line coming from `previous` (nearest first): the derivative
// at p of the least-squares quadratic through p and the previous points within arc length
// `reach` of p (chord-length parameter, t = 0 at p). Fitting over a fixed length, rather than
// over the one or two nearest nodes, keeps edge-scale wiggles of the line out of the tangent.
inline Vec3 fitted_end_tangent(const Vec3& p, const std::vector<Vec3>& previous, double reach)
{
  using namespace vector3;
  std::vector<std::pair<double, Vec3>> samples; // (t < 0, point - p)
  double t = 0;
  Vec3 last = p;
  for (const Vec3& q : previous) {
    const Vec3 d = q - last;
    t -= std::sqrt(vector3::dot(d, d));
    if (!samples.empty() && -t > reach)
      break;
    samples.emplace_back(t, q - p);
    last = q;
  }
  if (samples.empty())
    return {0, 0, 0};
  if (samples.size() == 1 || !(samples.front().first < 0))
    return p - previous.front();
  // Normal equations of min Σ |a t_i + b t_i² - (q_i - p)|².
  double s2 = 0, s3 = 0, s4 = 0;
  Vec3 r1{0, 0, 0}, r2{0, 0, 0};
  for (const auto& sample : samples) {
    const double ti = sample.first, t2 = ti * ti;
    s2 += t2;
    s3 += t2 * ti;
    s4 += t2 * t2;
    for (int k = 0; k < 3; ++k) {
      r1[std::size_t(k)] += ti * sample.second[std::size_t(k)];
      r2[std::size_t(k)] += t2 * sample.second[std::size_t(k)];
    }
  }
  const double det = s2 * s4 - s3 * s3;
  if (!(std::abs(det) > 1e-12 * s2 * s4))
    return p - previous.front();
  Vec3 a;
  for (int k = 0; k < 3; ++k)
    a[std::size_t(k)] = (s4 * r1[std::size_t(k)] - s3 * r2[std::size_t(k)]) / det;
  return a;
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_DESIRED_HIGHLIGHT_LINES_H

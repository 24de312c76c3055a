// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_DIFFERENCE_ENERGY_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_DIFFERENCE_ENERGY_H

// §3.5 of the paper, "Difference function": how far the highlight lines inside the region lie
// from their desired curves (eq. 10-14),
//   q_diff = Σ_lines Σ_i l_i ‖Q̄_i − Q̃_i‖²,
// Q̃_i the point of the line's OGH curve at the node's normalised chord-length parameter
// (eq. 12), l_i half the length of the two segments at the node (eq. 14), Q̄_i the node moved
// with the vertices (eq. 13). The fairing uses the Gauss–Newton form with Q̄_i = Q_i + J_i x
// (J_i from node_jacobian.h), which is convex, and divides q_diff by the cube of the region's
// length scale so that the result commutes with uniform scaling.
//
// The desired curves are fixed for the whole fairing; the line pieces they belong to are found
// again in every new model ("matched"): their delimiting nodes lie outside the region and never
// move.

#include <CGAL/Highlight_lines/internal/fairing/desired_highlight_lines.h>
#include <CGAL/Highlight_lines/internal/fairing/fairing_region.h>
#include <CGAL/Highlight_lines/internal/fairing/node_jacobian.h>
#include <CGAL/Highlight_lines/internal/fairing/ogh_curve.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// A desired highlight line (§3.2): the fixed OGH curve between two delimiting nodes.
struct Desired_line
{
  Node_key start, end;
  Ogh_target curve;
};

// One line piece of the current model matched to its desired line, with the data of q_diff.
struct Matched_piece
{
  std::vector<int> nodes;      // canonical ids, Q0 .. Q1
  std::vector<Vec3> targets;   // eq. 12, for the inner nodes
  std::vector<double> weights; // eq. 14, for the inner nodes
};

template <typename Model>
Vec3 node_position(const Model& model, int id)
{
  const auto& p = model.node(std::size_t(id)).point;
  return {p[0], p[1], p[2]};
}

// The targets (eq. 12) and weights (eq. 14) of the inner nodes of a matched piece.
template <typename Model>
void complete_matched_piece(const Model& model, const Desired_line& d, Matched_piece& piece)
{
  std::vector<Vec3> p;
  for (int id : piece.nodes)
    p.push_back(node_position(model, id));
  std::vector<double> chord(p.size(), 0.0);
  for (std::size_t i = 1; i < p.size(); ++i) {
    const Vec3 e{p[i][0] - p[i - 1][0], p[i][1] - p[i - 1][1], p[i][2] - p[i - 1][2]};
    chord[i] = chord[i - 1] + std::sqrt(vector3::dot(e, e));
  }
  const double total = chord.back() > 0 ? chord.back() : 1;
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    piece.targets.push_back(d.curve.point_at_arc_length_fraction(chord[i] / total));
    piece.weights.push_back(0.5 * (chord[i + 1] - chord[i - 1]));
  }
}

// Finds each desired line's piece in `model` (from its start node, through nodes inside the
// region, to its end node) with its targets and weights. A desired line whose piece is not
// found (the line now leaves the region elsewhere) is skipped for this model.
template <typename Model>
std::vector<Matched_piece> match_desired_lines(const Model& model, const Fairing_region& region,
                                               const std::vector<Desired_line>& desired)
{
  // key -> (line, position); a node where lines meet (degree > 2) is in several lines
  std::multimap<Node_key, std::pair<std::size_t, std::size_t>> where;
  std::set<Node_key> wanted;
  for (const Desired_line& d : desired)
    wanted.insert(d.start);
  const auto& lines = model.lines.lines;
  for (std::size_t l = 0; l < lines.size(); ++l)
    for (std::size_t i = 0; i < lines[l].nodes.size(); ++i) {
      const Node_key key = Node_key::of(model.node(std::size_t(lines[l].nodes[i])));
      if (wanted.count(key))
        where.emplace(key, std::make_pair(l, i));
    }
  auto walk = [&](const Desired_line& d, const Traced_line& line, std::size_t start, int direction,
                  Matched_piece& piece) {
    const long long n = (long long)line.nodes.size();
    piece.nodes.assign(1, line.nodes[start]);
    for (long long k = 1; k <= n; ++k) {
      long long pos = (long long)start + direction * k;
      if (line.closed)
        pos = ((pos % n) + n) % n;
      else if (pos < 0 || pos >= n)
        return false;
      const int id = line.nodes[std::size_t(pos)];
      piece.nodes.push_back(id);
      const Raw_node& node = model.node(std::size_t(id));
      if (Node_key::of(node) == d.end)
        return piece.nodes.size() > 2;
      if (!node_is_inside(node, region))
        return false;
    }
    return false;
  };
  std::vector<Matched_piece> matched;
  for (const Desired_line& d : desired) {
    const auto occurrences = where.equal_range(d.start);
    bool done = false;
    for (auto it = occurrences.first; it != occurrences.second && !done; ++it)
      for (int direction : {1, -1}) {
        Matched_piece piece;
        if (walk(d, lines[it->second.first], it->second.second, direction, piece)) {
          complete_matched_piece(model, d, piece);
          matched.push_back(std::move(piece));
          done = true;
          break;
        }
      }
  }
  return matched;
}

// q_diff of `model`: Σ l_i ‖Q_i − Q̃_i‖² / length_scale³.
template <typename Model>
double difference_energy(const Model& model, const std::vector<Matched_piece>& pieces,
                         double length_scale)
{
  double value = 0;
  for (const Matched_piece& piece : pieces)
    for (std::size_t i = 0; i < piece.targets.size(); ++i) {
      const Vec3 q = node_position(model, piece.nodes[i + 1]);
      const Vec3 e{q[0] - piece.targets[i][0], q[1] - piece.targets[i][1],
                   q[2] - piece.targets[i][2]};
      value += piece.weights[i] * vector3::dot(e, e);
    }
  return value / (length_scale * length_scale * length_scale);
}

// Hands w · Σ l_i ‖Q_i + J_i x − Q̃_i‖² (w includes the normalisation) to the sinks
// add_P(i, j, v) (i <= j, duplicates to be summed) and add_q(i, v); returns the trace of its
// matrix.
template <typename Model, typename AddP, typename AddQ>
double add_difference_quadratic(const Model& model, const std::vector<Matched_piece>& pieces,
                                const Node_jacobian& J,
                                const std::vector<std::array<int, 2>>& edge_vertices,
                                double spacing, double w, AddP&& add_P, AddQ&& add_q)
{
  double trace = 0;
  Node_jacobian::Row row;
  for (const Matched_piece& piece : pieces)
    for (std::size_t i = 0; i < piece.targets.size(); ++i) {
      const Raw_node& node = model.node(std::size_t(piece.nodes[i + 1]));
      // On an edge almost along a highlight line (its d values differ by a small fraction of
      // the spacing), eq. 13 moves the node by many edge lengths for a small change of d: its
      // linearisation means nothing there, and it would swamp the program. Such nodes still
      // shape the chord-length parameters, but get no term.
      if (node.edge >= 0) {
        const auto& ends = edge_vertices[std::size_t(node.edge)];
        const double D = model.levels[std::size_t(ends[1])].distance -
                         model.levels[std::size_t(ends[0])].distance;
        if (!(std::abs(D) >= 0.1 * spacing))
          continue;
      }
      J.node_row(node, edge_vertices, model.levels, spacing, row);
      // By variable, so that the pairs a <= b of the upper triangle are those that follow a.
      std::sort(row.begin(), row.end(),
                [](const auto& x, const auto& y) { return x.first < y.first; });
      const Vec3 q = node_position(model, piece.nodes[i + 1]);
      const Vec3 r{q[0] - piece.targets[i][0], q[1] - piece.targets[i][1],
                   q[2] - piece.targets[i][2]};
      const double factor = 2 * w * piece.weights[i];
      for (std::size_t ia = 0; ia < row.size(); ++ia) {
        const auto& a = row[ia];
        add_q(a.first, factor * vector3::dot(a.second, r));
        const double diagonal = factor * vector3::dot(a.second, a.second);
        add_P(a.first, a.first, diagonal);
        trace += diagonal;
        for (std::size_t ib = ia + 1; ib < row.size(); ++ib)
          add_P(a.first, row[ib].first, factor * vector3::dot(a.second, row[ib].second));
      }
    }
  return trace;
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_DIFFERENCE_ENERGY_H

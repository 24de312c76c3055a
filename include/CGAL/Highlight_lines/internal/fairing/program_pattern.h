// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_PROGRAM_PATTERN_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_PROGRAM_PATTERN_H

// Which entries of a fairing program's matrix can ever be nonzero: the pairs of variables at
// most three edges apart. Every term couples only such pairs: a node on the edge (a, b) moves
// with a, b and their one-rings (node_jacobian.h), the mean curvature of a vertex with its
// one-ring, so the curvature variation across an edge (i, j) with the one-rings of i and j,
// and the Willmore energy of a vertex with its one-ring.
//
// Which pairs a program actually holds changes from one iteration to the next: nodes move onto
// other edges, and an edge's clamped cotangent weight (curvature_variation_energy.h) crosses
// zero (on a grid, every diagonal's weight is a rounding error either side of it). A few
// hundred new entries among 10^6 can join parts of the mesh that the fill-reducing ordering
// had eliminated apart (the factorisation of a fairing of 2.4·10^4 variables took 3 times the
// flops with the old ordering), so the solver would compute a new ordering at nearly every
// factorisation. Handing it this pattern once, as explicit zeros, makes one analysis serve the
// whole fairing.

#include <CGAL/Highlight_lines/internal/fairing/fairing_region.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// The pairs (i, j), i <= j, of variables of `region` joined by a path of at most three edges
// (through any model vertex), diagonal included; by increasing i.
inline std::vector<std::pair<int, int>>
variable_pairs_within_three_edges(const Fairing_region& region)
{
  std::vector<std::pair<int, int>> pairs;
  const std::size_t model_vertices =
      region.vertex_neighbor_begin.empty() ? 0 : region.vertex_neighbor_begin.size() - 1;
  std::vector<int> seen_from(region.variable.size(), -1);
  std::vector<int> frontier, next;
  for (std::size_t i = 0; i < region.movable.size(); ++i) {
    const int start = region.movable[i];
    seen_from[std::size_t(start)] = int(i);
    frontier.assign(1, start);
    pairs.emplace_back(int(i), int(i));
    for (int depth = 0; depth < 3; ++depth) {
      next.clear();
      for (int v : frontier) {
        if (std::size_t(v) >= model_vertices)
          continue; // no one-ring known: not a model vertex, no term reaches past it
        for (int k = region.vertex_neighbor_begin[std::size_t(v)];
             k < region.vertex_neighbor_begin[std::size_t(v) + 1]; ++k) {
          const int w = region.vertex_neighbors[std::size_t(k)];
          if (seen_from[std::size_t(w)] == int(i))
            continue;
          seen_from[std::size_t(w)] = int(i);
          next.push_back(w);
          const int j = region.variable[std::size_t(w)];
          if (j > int(i))
            pairs.emplace_back(int(i), j);
        }
      }
      frontier.swap(next);
    }
  }
  return pairs;
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_PROGRAM_PATTERN_H

// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_CURVATURE_VARIATION_ENERGY_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_CURVATURE_VARIATION_ENERGY_H

// A third-order fairness energy (beyond the paper): the variation of the mean curvature,
//   E = ℓ² Σ_{edges ij} c_ij (H_i - H_j)²,   H_i = K_i · N_i,
// over the edges with an end inside R, K the cotangent mean curvature normal of
// willmore_energy.h, N_i the unit vertex normal, c_ij = (cot α_ij + cot β_ij) / 2 clamped to
// [0, 1], and ℓ² the area of R (E is dimensionless, as the Willmore energy is). E is the
// Dirichlet energy ∫ ‖∇H‖² of the mean curvature: zero on planes and spheres, and its minimisers
// with fixed surroundings continue the surface's curvature across R's border (curvature
// continuous, as PMP::fair with continuity 2), where the Willmore energy continues only its
// tangent planes. Real surfaces (scans, CAD parts) are predicted much closer that way.
//
// Why the normal part and the clamp: on slivers and folded triangles (scans) the tangential part
// of K and the cotangent of a tiny angle are discretisation artefacts of hundreds of times the
// curvature; an edge opposite two small angles would weigh hundreds of times its share. On
// well-shaped triangles (every angle above 45°) neither changes anything.
//
// With the weights, areas and normals frozen (at the vertices inside R and their neighbours,
// whose H the edges difference) and the vertices displaced along fixed directions, every H_i is
// affine in x: E(x) = ½ xᵀ Q x + cᵀ x + r exactly, handed to a sink as add_willmore_quadratic()
// does.

#include <CGAL/Highlight_lines/internal/willmore_energy.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// c_ij clamped to [0, 1] (see the file comment); negative values (two obtuse angles) would make
// E indefinite.
inline double clamped_edge_weight(double c)
{
  return c > 1 ? 1.0 : (c > 0 ? c : 0.0);
}

// The frozen weights over R's energy vertices and their neighbours; `inner` marks the rows of
// the energy vertices (the rows of E), `row_of_vertex` maps a vertex to its row (-1 if none).
struct Frozen_curvature_variation
{
  Frozen_willmore_weights weights;
  std::vector<char> inner;
  std::vector<int> row_of_vertex;
  double scale = 1; // ℓ²
};

// `energy_vertices`: I_R; `neighbours_of(v, out)` appends v's neighbours; every vertex of I_R and
// of their one-rings must have its full one-ring in `triangles`. `length_scale`: ℓ.
template <typename Neighbours>
Frozen_curvature_variation
freeze_curvature_variation(const std::vector<std::array<double, 3>>& positions,
                           const std::vector<std::array<int, 3>>& triangles,
                           const std::vector<int>& energy_vertices, Neighbours&& neighbours_of,
                           double length_scale)
{
  Frozen_curvature_variation frozen;
  std::vector<char> seen(positions.size(), 0), is_energy(positions.size(), 0);
  std::vector<int> rows = energy_vertices;
  for (int v : energy_vertices)
    seen[std::size_t(v)] = is_energy[std::size_t(v)] = 1;
  std::vector<int> ring;
  for (int v : energy_vertices) {
    ring.clear();
    neighbours_of(v, ring);
    for (int u : ring)
      if (!seen[std::size_t(u)]) {
        seen[std::size_t(u)] = 1;
        rows.push_back(u);
      }
  }
  frozen.weights = freeze_willmore_weights(positions, triangles, rows);
  frozen.row_of_vertex.assign(positions.size(), -1);
  frozen.inner.assign(rows.size(), 0);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    frozen.row_of_vertex[std::size_t(rows[r])] = int(r);
    frozen.inner[r] = is_energy[std::size_t(rows[r])];
  }
  frozen.scale = length_scale * length_scale;
  return frozen;
}

// The quadratic of E in x, to a sink: add_P(v, w, value) with v <= w, add_q(v, value); returns
// E(0). `normals`: the unit normal N_m of each frozen row m (same order as
// frozen.weights.energy_vertices). H_m = K_m · N_m with N_m frozen, and ∂K_m/∂x_v = s N_v with
// a scalar s (Σ_k w_mk if v = m, -w_mv if v is a neighbour), so ∂H_m/∂x_v = s (N_v · N_m) and
// the row of edge ij of the least-squares form is a_v = sqrt(ℓ² c_ij) ∂(H_i - H_j)/∂x_v.
template <typename AddP, typename AddQ>
double add_curvature_variation_quadratic(const Frozen_curvature_variation& frozen,
                                         const std::vector<std::array<double, 3>>& positions,
                                         const std::vector<std::array<double, 3>>& normals,
                                         const std::vector<int>& variable_of_vertex,
                                         const std::vector<std::array<double, 3>>& directions,
                                         AddP add_P, AddQ add_q)
{
  using namespace willmore_detail;
  const Frozen_willmore_weights& w = frozen.weights;
  const std::size_t rows = w.energy_vertices.size();
  CGAL_precondition(normals.size() == rows);
  std::vector<double> H(rows), own(rows, 0.0);
  for (std::size_t r = 0; r < rows; ++r) {
    H[r] = dot(mean_curvature_normal(w, r, positions), normals[r]);
    for (const auto& n : w.neighbours[r])
      own[r] += n.weight;
  }
  // ∂H_m/∂x scaled by `coefficient`, added to `row` (variable, value; merged below).
  std::vector<std::pair<int, double>> row, merged;
  auto add_h_row = [&](std::size_t m, double coefficient) {
    const int self = variable_of_vertex[std::size_t(w.energy_vertices[m])];
    if (self >= 0)
      row.emplace_back(self, coefficient * own[m] * dot(directions[std::size_t(self)], normals[m]));
    for (const auto& n : w.neighbours[m]) {
      const int v = variable_of_vertex[std::size_t(n.vertex)];
      if (v >= 0)
        row.emplace_back(v, -coefficient * n.weight * dot(directions[std::size_t(v)], normals[m]));
    }
  };
  double r0 = 0;
  for (std::size_t i = 0; i < rows; ++i) {
    if (!frozen.inner[i])
      continue;
    for (const auto& n : w.neighbours[i]) {
      const int j = frozen.row_of_vertex[std::size_t(n.vertex)];
      CGAL_assertion(j >= 0); // the neighbours of an energy vertex are frozen
      if (frozen.inner[std::size_t(j)] && std::size_t(j) < i)
        continue; // each edge once
      const double c = clamped_edge_weight(n.weight * w.area[i]);
      if (!(c > 0))
        continue;
      const double root = std::sqrt(frozen.scale * c);
      const double g = root * (H[i] - H[std::size_t(j)]);
      r0 += g * g;
      row.clear();
      add_h_row(i, root);
      add_h_row(std::size_t(j), -root);
      std::sort(row.begin(), row.end());
      merged.clear();
      for (const auto& s : row)
        if (!merged.empty() && merged.back().first == s.first)
          merged.back().second += s.second;
        else
          merged.push_back(s);
      for (std::size_t a = 0; a < merged.size(); ++a) {
        add_q(merged[a].first, 2 * merged[a].second * g);
        for (std::size_t b = a; b < merged.size(); ++b)
          add_P(merged[a].first, merged[b].first, 2 * merged[a].second * merged[b].second);
      }
    }
  }
  return r0;
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_CURVATURE_VARIATION_ENERGY_H

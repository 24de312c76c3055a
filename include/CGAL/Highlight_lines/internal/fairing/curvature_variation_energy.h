// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_CURVATURE_VARIATION_ENERGY_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_CURVATURE_VARIATION_ENERGY_H

// A third-order fairness energy (beyond the paper): the variation of the mean curvature,
//   E = ℓ² Σ_{edges ij} c_ij (H_i - H_j)² + μ Σ_{i in R} A_i H_i²,   H_i = K_i · N_i,
// over the edges with an end inside R, K the cotangent mean curvature normal of
// willmore_energy.h, N_i the unit vertex normal, c_ij = (cot α_ij + cot β_ij) / 2 clamped to
// [0, 1], ℓ² the area of R, A_i the vertex areas (E is dimensionless, as the Willmore energy is)
// and μ = mean_curvature_weight(). The first term is the Dirichlet energy ∫ ‖∇H‖² of the mean
// curvature: zero on planes and spheres, and its minimisers with fixed surroundings continue the
// surface's curvature across R's border (curvature continuous, as PMP::fair with continuity 2),
// where the Willmore energy continues only its tangent planes. Real surfaces (scans, CAD parts)
// are predicted much closer that way. The second, a share of the Willmore energy, keeps the
// minimiser from following a surface of constant mean curvature far off the input (see
// mean_curvature_weight()).
//
// Why the normal part and the clamp: on slivers and folded triangles (scans) the tangential part
// of K and the cotangent of a tiny angle are discretisation artefacts of hundreds of times the
// curvature; an edge opposite two small angles would weigh hundreds of times its share. On
// well-shaped triangles (every angle above 45°) neither changes anything.
//
// The pointwise mean curvature (Mean_curvature_fit_options): by default H_i = K_i · N_i, except at
// the vertices with a sliver or a folded triangle around them in the fairing's input, where H_i
// is the least-squares quadric fit of mean_curvature_fit.h over the two-ring, in the frame of the
// plane fitted to it (FIT_ON_DEGENERATE_RINGS). There the cotangent H_i measures the triangles'
// shapes, hundreds of times the curvature, and the vertex normal of a folded ring can point
// anywhere: measured on scan-like real dents (benchmark_real_dents --jitter 0.45 and 0.3, seeds
// 7, 8, 9; per case against the cotangent H, geometric means) the RMS distance to the truth
// falls to 0.50-0.75 x at jitter 0.45 and 0.78-1.02 x at 0.3, the highlight deviation to 0.40-0.67
// and 0.73-1.02 x, with a fifth fewer iterations; wherever no ring is degenerate (the 30 real dents
// without jitter, the hoods) nothing changes. The fit everywhere (QUADRIC_FIT,
// CGAL_HIGHLIGHT_LINES_CURVATURE_VARIATION_FIT) is exact for quadrics on any triangulation: the
// cotangent H_i does not converge on irregular triangulations, so E grows with their density
// (the dented hood at jitter 0.3 over 40², 80², 160² cells: 79, 191, 527; fitted: 61, 77, 83,
// curvature_variation_test.cpp). Measured, same runs (cotangent → fit): benchmark_fairing's
// hoods end at 0.0149 → 0.0009 ē from the true lines (784 movable vertices; PMP::fair 0.0052),
// 0.0172 → 0.0039 and 0.0269 → 0.0044 (9,173 and 9,174), the beetle's roof 0.046 → 0.021;
// benchmark_real_dents (30 cases): RMS to the truth 0.498 → 0.539 × PMP::fair's, highlight
// deviation 0.646 → 0.710 × (54 cases with --centres 6: 0.530 → 0.515 and 0.693 → 0.697). Hence
// not everywhere until the real meshes agree.
//
// With the weights, areas and normals frozen (at the vertices inside R and their neighbours,
// whose H the edges difference) and the vertices displaced along fixed directions, every H_i is
// affine in x: E(x) = ½ xᵀ Q x + cᵀ x + r exactly, handed to a sink as add_willmore_quadratic()
// does.

#include <CGAL/Highlight_lines/internal/fairing/mean_curvature_fit.h>
#include <CGAL/Highlight_lines/internal/fairing/willmore_energy.h>
#include <CGAL/Highlight_lines/internal/qp/bucket_sort.h>

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
  using Stencil = std::vector<Frozen_willmore_weights::Neighbour>;
  Frozen_willmore_weights weights;
  std::vector<char> inner;
  // Per row: a vertex outside R on a sharp edge (see vertices_on_sharp_edges()), whose edges to
  // R's vertices are left out of E.
  std::vector<char> on_crease;
  std::vector<int> row_of_vertex;
  double scale = 1; // ℓ²
  // μ of the term μ Σ_{i in R} A_i H_i² (see mean_curvature_weight()).
  double mean_curvature_weight = 0;
  // The mean curvature's discretisation; with a fit, the points of each row's fit, and once
  // fit_mean_curvatures() has run, each row's stencil (H_m = Σ f (P_m - P_j) · N_m).
  Mean_curvature_fit_options fit;
  std::vector<std::vector<int>> fit_points;
  std::vector<char> fitted; // FIT_ON_DEGENERATE_RINGS: per row, whether its H is fitted
  std::vector<Stencil> stencil;

  // The stencil of H_m: the fitted one, or the cotangent weights.
  const Stencil& stencil_of(std::size_t m) const
  {
    return stencil.empty() || stencil[m].empty() ? weights.neighbours[m] : stencil[m];
  }
};

// The mean curvature of the energy: the cotangent formula unless
// CGAL_HIGHLIGHT_LINES_CURVATURE_VARIATION_FIT is defined (the fit of mean_curvature_fit.h; see
// the file comment for the figures).
inline Mean_curvature_fit_options default_mean_curvature_fit_options()
{
  Mean_curvature_fit_options o;
#ifndef CGAL_HIGHLIGHT_LINES_CURVATURE_VARIATION_FIT
  o.method = Mean_curvature_fit_options::Method::FIT_ON_DEGENERATE_RINGS;
#endif
  return o;
}

// Per vertex of `positions`: whether a triangle of `triangles` around it has a corner below
// `sliver_angle` or is folded against the area-weighted normal of its ring, where the cotangent
// mean curvature is an artefact of the triangle shapes.
inline std::vector<char>
vertices_with_degenerate_rings(const std::vector<std::array<double, 3>>& positions,
                               const std::vector<std::array<int, 3>>& triangles,
                               double sliver_angle)
{
  using namespace willmore_detail;
  std::vector<std::array<double, 3>> ring_normal(positions.size(), {0, 0, 0});
  std::vector<char> degenerate(positions.size(), 0);
  const double cos_sliver = std::cos(sliver_angle);
  auto cross_of = [&](const std::array<int, 3>& t) {
    return cross(positions[std::size_t(t[1])] - positions[std::size_t(t[0])],
                 positions[std::size_t(t[2])] - positions[std::size_t(t[0])]);
  };
  for (const auto& t : triangles) {
    bool thin = false;
    for (int c = 0; c < 3; ++c) {
      const auto& p = positions[std::size_t(t[std::size_t(c)])];
      const auto u = positions[std::size_t(t[std::size_t((c + 1) % 3)])] - p;
      const auto v = positions[std::size_t(t[std::size_t((c + 2) % 3)])] - p;
      thin = thin || !(dot(u, v) < cos_sliver * std::sqrt(dot(u, u) * dot(v, v)));
    }
    const auto n = cross_of(t);
    for (int c : t) {
      degenerate[std::size_t(c)] = degenerate[std::size_t(c)] || thin;
      for (int k = 0; k < 3; ++k)
        ring_normal[std::size_t(c)][std::size_t(k)] += n[std::size_t(k)];
    }
  }
  for (const auto& t : triangles) {
    const auto n = cross_of(t);
    for (int c : t)
      if (!(dot(n, ring_normal[std::size_t(c)]) > 0))
        degenerate[std::size_t(c)] = 1;
  }
  return degenerate;
}

// The angle (radians) between two faces' normals beyond which their edge is a crease for the
// energy: 60°, the default of the detection's and PMP::detect_sharp_edges()' criterion.
inline double crease_angle()
{
  return std::acos(-1.0) / 3;
}

// μ, the weight of the term μ Σ_{i in R} A_i H_i² added to E (a share of the Willmore energy
// ∫ H²). ∫ ‖∇H‖² alone is zero on every surface of constant mean curvature, however curved: with
// a region that reaches into a narrow part of a real mesh (a camel's head, 116 movable vertices,
// 12 ē across) the fairing followed such a surface into a pocket 35 ē deep, converged and with
// every step accepted. The term makes E positive definite in H; its scale ℓ² against the area
// makes variations of H over lengths below about ℓ / √μ cost more than H itself. Measured (μ = 0,
// 3, 10, 30): the pocket's deepest vertex moves 35, 5.0 (iteration limit), 1.6, 1.0 ē (Willmore
// alone 0.67, PMP::fair 1.7); benchmark_real_dents, 30 cases, median RMS distance to the undented
// surface / depth 0.077, 0.077, 0.081, 0.089 and highlight deviation 0.156, 0.153, 0.160, 0.184
// ē; at jitter 0.45 (seeds 7, 8, 9) RMS 0.222/0.173/0.195, 0.217/0.172/0.207,
// 0.206/0.169/0.188, 0.188/0.195/0.193; benchmark_fairing's hoods and roof end closer to the
// true surface as μ grows (784 movable: 0.0149, 0.0145, 0.0137, 0.0120 ē).
inline double mean_curvature_weight()
{
  return 10.0;
}

// Per vertex of `positions`: whether it lies on a sharp edge of `triangles`, an edge whose two
// triangles' normals are more than `sharp_edge_angle` (radians) apart, the criterion of
// PMP::detect_sharp_edges(). A crease is a curvature discontinuity by design: a vertex on it
// has a mean curvature of the crease's angle over an edge length, which the energy would
// continue into R (measured on the shared fandisk, dents and bumps 0.5 and 1 ē high next to its
// creases, fairing the faces within R + 2 ē up to the sharp edges: RMS distance to the undented
// surface 1.58 of the dent's as the median, against 0.51 with the Willmore energy and 0.52 with
// PMP::fair()).
inline std::vector<char>
vertices_on_sharp_edges(const std::vector<std::array<double, 3>>& positions,
                        const std::vector<std::array<int, 3>>& triangles, double sharp_edge_angle)
{
  using namespace willmore_detail;
  std::vector<char> on_sharp_edge(positions.size(), 0);
  const double cos_sharp = std::cos(sharp_edge_angle);
  // Once per triangle: each takes part in up to three edge comparisons.
  std::vector<std::array<double, 3>> unit_normals(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const std::array<int, 3>& t = triangles[i];
    const auto n = cross(positions[std::size_t(t[1])] - positions[std::size_t(t[0])],
                         positions[std::size_t(t[2])] - positions[std::size_t(t[0])]);
    const double length = std::sqrt(dot(n, n));
    unit_normals[i] = length > 0 ? (1 / length) * n : n;
  }
  // The triangle sides grouped by their smaller vertex (a stable counting sort, in triangle
  // order: this runs on every triangle of the fairing's local mesh); within a group, each later
  // triangle of an edge is compared with its first.
  struct Side
  {
    int b = 0;
    std::size_t triangle = 0;
  };
  std::vector<int> group_start;
  std::vector<Side> sides;
  bucket_sort(
      int(positions.size()),
      [&](auto&& emit) {
        for (std::size_t i = 0; i < triangles.size(); ++i)
          for (int c = 0; c < 3; ++c) {
            const auto [a, b] =
                std::minmax(triangles[i][std::size_t(c)], triangles[i][std::size_t((c + 1) % 3)]);
            emit(a, Side{b, i});
          }
      },
      group_start, sides);
  for (std::size_t a = 0; a < positions.size(); ++a)
    for (int p = group_start[a]; p < group_start[a + 1]; ++p) {
      const Side& side = sides[std::size_t(p)];
      int first = group_start[a];
      while (sides[std::size_t(first)].b != side.b)
        ++first;
      if (first != p && dot(unit_normals[sides[std::size_t(first)].triangle],
                            unit_normals[side.triangle]) < cos_sharp)
        on_sharp_edge[a] = on_sharp_edge[std::size_t(side.b)] = 1;
    }
  return on_sharp_edge;
}

// `energy_vertices`: I_R; `neighbours_of(v, out)` appends v's neighbours; every vertex of I_R and
// of their one-rings must have its full one-ring in `triangles`. `length_scale`: ℓ.
// `degenerate` (FIT_ON_DEGENERATE_RINGS, per vertex of `positions`): the rows to fit, if not
// those of vertices_with_degenerate_rings() at `positions`. The fairing fixes them at its input:
// a row switching between the two discretisations from one iteration to the next makes the
// energy jump, and the iteration then took 10 to 60 % more steps (scan-like real dents).
// `on_sharp_edge` (per vertex of `positions`): the crease vertices, if not those of
// vertices_on_sharp_edges() at `positions` at 60°; the fairing fixes them at its input too.
template <typename Neighbours>
Frozen_curvature_variation freeze_curvature_variation(
    const std::vector<std::array<double, 3>>& positions,
    const std::vector<std::array<int, 3>>& triangles, const std::vector<int>& energy_vertices,
    Neighbours&& neighbours_of, double length_scale,
    const Mean_curvature_fit_options& fit = default_mean_curvature_fit_options(),
    const std::vector<char>* degenerate = nullptr, const std::vector<char>* on_sharp_edge = nullptr)
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
  frozen.mean_curvature_weight = mean_curvature_weight();
  {
    const bool given = on_sharp_edge && on_sharp_edge->size() == positions.size();
    const std::vector<char> computed =
        given ? std::vector<char>() : vertices_on_sharp_edges(positions, triangles, crease_angle());
    const std::vector<char>& sharp = given ? *on_sharp_edge : computed;
    frozen.on_crease.assign(rows.size(), 0);
    for (std::size_t r = 0; r < rows.size(); ++r)
      frozen.on_crease[r] = !frozen.inner[r] && sharp[std::size_t(rows[r])];
  }
  frozen.fit = fit;
  if (fit.method == Mean_curvature_fit_options::Method::FIT_ON_DEGENERATE_RINGS) {
    const bool given = degenerate && degenerate->size() == positions.size();
    const std::vector<char> computed =
        given ? std::vector<char>()
              : vertices_with_degenerate_rings(positions, triangles, fit.sliver_angle);
    const std::vector<char>& flags = given ? *degenerate : computed;
    frozen.fitted.assign(rows.size(), 0);
    for (std::size_t r = 0; r < rows.size(); ++r)
      frozen.fitted[r] = flags[std::size_t(rows[r])];
  }
  if (fit.method != Mean_curvature_fit_options::Method::COTANGENT) {
    // The points of each row's fit: its one-ring (complete, from the frozen weights), or its
    // two-ring over `triangles` when the one-ring is small; always the two-ring on a degenerate
    // ring (FIT_ON_DEGENERATE_RINGS), whose one-ring can lie nearly on a line once projected
    // (measured: with fits of the one-ring F grew a hundredfold within a few iterations).
    std::vector<std::vector<int>> adjacent;
    frozen.fit_points.resize(rows.size());
    for (std::size_t r = 0; r < rows.size(); ++r) {
      if (!frozen.fitted.empty() && !frozen.fitted[r])
        continue;
      std::vector<int>& points = frozen.fit_points[r];
      for (const auto& n : frozen.weights.neighbours[r])
        points.push_back(n.vertex);
      if (frozen.fitted.empty() && int(points.size()) >= fit.minimum_one_ring)
        continue;
      if (adjacent.empty()) {
        adjacent.resize(positions.size());
        for (const auto& t : triangles)
          for (int c = 0; c < 3; ++c)
            for (int d = 1; d < 3; ++d) {
              std::vector<int>& a = adjacent[std::size_t(t[std::size_t(c)])];
              const int other = t[std::size_t((c + d) % 3)];
              if (std::find(a.begin(), a.end(), other) == a.end())
                a.push_back(other);
            }
      }
      const std::size_t one_ring = points.size();
      for (std::size_t i = 0; i < one_ring; ++i)
        for (int u : adjacent[std::size_t(points[i])])
          if (u != rows[r] && std::find(points.begin(), points.end(), u) == points.end())
            points.push_back(u);
    }
  }
  return frozen;
}

// Freezes the fitted stencils at `positions` with the unit normals `normals` of the frozen
// rows (nothing with the cotangent discretisation). A row whose fit is singular keeps the
// cotangent stencil. With FIT_ON_DEGENERATE_RINGS, the normals of the fitted rows are replaced
// by those of the planes through their points (plane_normal()): use them for the quadratic.
inline void fit_mean_curvatures(Frozen_curvature_variation& frozen,
                                const std::vector<std::array<double, 3>>& positions,
                                std::vector<std::array<double, 3>>& normals)
{
  if (frozen.fit.method == Mean_curvature_fit_options::Method::COTANGENT)
    return;
  const bool everywhere = frozen.fit.method == Mean_curvature_fit_options::Method::QUADRIC_FIT;
  const std::size_t rows = frozen.weights.energy_vertices.size();
  CGAL_precondition(normals.size() == rows);
  frozen.stencil.assign(rows, {});
  for (std::size_t m = 0; m < rows; ++m) {
    // The vertex normal of a folded ring can point anywhere; the fit's frame and the
    // direction of H then take the normal of the plane through its points.
    if (!everywhere && frozen.fitted[m])
      normals[m] = plane_normal(frozen.weights.energy_vertices[m], frozen.fit_points[m], positions,
                                normals[m]);
    if (everywhere || frozen.fitted[m])
      quadric_fit_stencil(frozen.weights.energy_vertices[m], normals[m], frozen.fit_points[m],
                          positions, frozen.fit, frozen.stencil[m],
                          everywhere && frozen.fit.cotangent_prior ? &frozen.weights.neighbours[m]
                                                                   : nullptr);
  }
}

// H_m at `positions`, per frozen row, with the frozen stencils and `normals`: K_m · N_m with the
// cotangent weights, or the fitted stencil's Σ f (P_m - P_j) · N_m.
inline std::vector<double>
frozen_mean_curvatures(const Frozen_curvature_variation& frozen,
                       const std::vector<std::array<double, 3>>& positions,
                       const std::vector<std::array<double, 3>>& normals)
{
  const Frozen_willmore_weights& w = frozen.weights;
  CGAL_precondition(normals.size() == w.energy_vertices.size());
  std::vector<double> H(w.energy_vertices.size());
  using namespace willmore_detail;
  for (std::size_t m = 0; m < H.size(); ++m) {
    const std::array<double, 3>& vm = positions[std::size_t(w.energy_vertices[m])];
    double h = 0;
    for (const auto& n : frozen.stencil_of(m))
      h += n.weight * dot(vm - positions[std::size_t(n.vertex)], normals[m]);
    H[m] = h;
  }
  return H;
}

// Calls edge(i, j, ω) once for every edge ij with an end in R, the other not on a crease
// outside R, and a positive weight ω = ℓ² c_ij, i and j its frozen rows.
template <typename Edge>
void for_each_weighted_edge(const Frozen_curvature_variation& frozen, Edge edge)
{
  const Frozen_willmore_weights& w = frozen.weights;
  for (std::size_t i = 0; i < w.energy_vertices.size(); ++i) {
    if (!frozen.inner[i])
      continue;
    for (const auto& n : w.neighbours[i]) {
      const int j = frozen.row_of_vertex[std::size_t(n.vertex)];
      CGAL_assertion(j >= 0); // the neighbours of an energy vertex are frozen
      if (frozen.inner[std::size_t(j)] && std::size_t(j) < i)
        continue; // each edge once
      if (!frozen.on_crease.empty() && frozen.on_crease[std::size_t(j)])
        continue; // the curvature of a crease is not continued into R
      const double c = clamped_edge_weight(n.weight * w.area[i]);
      if (c > 0)
        edge(int(i), j, frozen.scale * c);
    }
  }
}

// Calls term(i, μ A_i) for every row i of R, the terms μ A_i H_i² of E.
template <typename Term>
void for_each_mean_curvature_term(const Frozen_curvature_variation& frozen, Term term)
{
  if (!(frozen.mean_curvature_weight > 0))
    return;
  for (std::size_t i = 0; i < frozen.weights.energy_vertices.size(); ++i)
    if (frozen.inner[i])
      term(int(i), frozen.mean_curvature_weight * frozen.weights.area[i]);
}

// Calls couple(a, b), a <= b, for every pair of variables (`variable[v]`, -1 for a fixed
// vertex) that the term of an edge with a fitted end can join, whatever the edge's weight now:
// the vertices of the two ends' stencils. A fitted stencil reaches two rings, so such a term
// joins vertices up to five edges apart, beyond the pattern every program declares
// (program_pattern.h), and an edge's clamped weight can turn positive in a later program.
template <typename Couple>
void for_each_fitted_coupling(const Frozen_curvature_variation& frozen,
                              const std::vector<int>& variable, Couple couple)
{
  if (frozen.fitted.empty())
    return;
  const Frozen_willmore_weights& w = frozen.weights;
  std::vector<int> joined;
  auto add_row = [&](std::size_t r) {
    const auto add_vertex = [&](int v) {
      const int x = variable[std::size_t(v)];
      if (x >= 0)
        joined.push_back(x);
    };
    add_vertex(w.energy_vertices[r]);
    for (const auto& n : frozen.stencil_of(r))
      add_vertex(n.vertex);
    if (frozen.fitted[r])
      for (int v : frozen.fit_points[r])
        add_vertex(v);
  };
  for (std::size_t i = 0; i < w.energy_vertices.size(); ++i) {
    if (!frozen.inner[i])
      continue;
    for (const auto& n : w.neighbours[i]) {
      const int j = frozen.row_of_vertex[std::size_t(n.vertex)];
      if (!frozen.fitted[i] && !frozen.fitted[std::size_t(j)])
        continue;
      joined.clear();
      add_row(i);
      add_row(std::size_t(j));
      std::sort(joined.begin(), joined.end());
      joined.erase(std::unique(joined.begin(), joined.end()), joined.end());
      for (std::size_t a = 0; a < joined.size(); ++a)
        for (std::size_t b = a; b < joined.size(); ++b)
          couple(joined[a], joined[b]);
    }
  }
}

// E at the frozen weights and normals, without its quadratic.
inline double curvature_variation_value(const Frozen_curvature_variation& frozen,
                                        const std::vector<std::array<double, 3>>& positions,
                                        const std::vector<std::array<double, 3>>& normals)
{
  const std::vector<double> H = frozen_mean_curvatures(frozen, positions, normals);
  double value = 0;
  for_each_weighted_edge(frozen, [&](int i, int j, double weight) {
    const double d = H[std::size_t(i)] - H[std::size_t(j)];
    value += weight * d * d;
  });
  for_each_mean_curvature_term(frozen, [&](int i, double weight) {
    value += weight * H[std::size_t(i)] * H[std::size_t(i)];
  });
  return value;
}

// The arrays of add_curvature_variation_quadratic(), kept by a caller that assembles one program
// per iteration: on a region of 10^5 vertices, growing and first touching fresh ones took half
// of the assembly's time.
struct Curvature_variation_workspace
{
  struct Edge
  {
    int i, j;
    double weight;
  };
  // Sparse rows: row m's (index, value) pairs at [start[m], start[m + 1]).
  struct Sparse_rows
  {
    std::vector<int> start, index;
    std::vector<double> value;
    void reset(std::size_t rows)
    {
      start.assign(rows + 1, 0);
      index.clear();
      value.clear();
    }
  };
  Sparse_rows B, LB;
  std::vector<int> l_start, next, bt_start, touched;
  std::vector<double> degree, LH, accumulated;
  std::vector<Edge> edges;
  std::vector<std::pair<int, double>> l_entries, bt_entries;
  std::vector<char> held;
};

// The quadratic of E in x, to a sink: add_P(v, w, value) with v <= w, once per entry of the
// upper triangle, add_q(v, value); returns E(0). `normals`: the unit normal N_m of each frozen
// row m (same order as frozen.weights.energy_vertices). H_m = Σ_k w_mk (P_m - P_k) · N_m with
// the frozen stencil w (the cotangent weights or the fit's) and N_m frozen, so
// H = B x + H⁰ with B_mv = s (d_v · N_m), s = Σ_k w_mk if v = m, -w_mv if v is in the stencil. With
// L = Σ_edges ℓ² c_ij (e_i - e_j)(e_i - e_j)ᵀ + Σ_{i in R} μ A_i e_i e_iᵀ, the weighted Laplacian
// of the edges plus the mean curvature term on its diagonal, E = (B x + H⁰)ᵀ
// L (B x + H⁰): the matrix is 2 Bᵀ (L B), built row by row with a dense accumulator, which costs a
// third of the flops of summing each edge's outer product and hands the sink one value per entry
// instead of about ten.
template <typename AddP, typename AddQ>
double add_curvature_variation_quadratic(const Frozen_curvature_variation& frozen,
                                         const std::vector<std::array<double, 3>>& positions,
                                         const std::vector<std::array<double, 3>>& normals,
                                         const std::vector<int>& variable_of_vertex,
                                         const std::vector<std::array<double, 3>>& directions,
                                         AddP add_P, AddQ add_q,
                                         Curvature_variation_workspace& work)
{
  using namespace willmore_detail;
  using Edge = Curvature_variation_workspace::Edge;
  const Frozen_willmore_weights& w = frozen.weights;
  const std::size_t rows = w.energy_vertices.size();
  const int variables = int(directions.size());

  // H⁰ and the rows of B (variable, value), row m at [B.start[m], B.start[m + 1]).
  const std::vector<double> H = frozen_mean_curvatures(frozen, positions, normals);
  Curvature_variation_workspace::Sparse_rows& B = work.B;
  B.reset(rows);
  for (std::size_t m = 0; m < rows; ++m) {
    double own = 0;
    for (const auto& n : frozen.stencil_of(m)) {
      own += n.weight;
      const int v = variable_of_vertex[std::size_t(n.vertex)];
      if (v >= 0) {
        B.index.push_back(v);
        B.value.push_back(-n.weight * dot(directions[std::size_t(v)], normals[m]));
      }
    }
    const int self = variable_of_vertex[std::size_t(w.energy_vertices[m])];
    if (self >= 0) {
      B.index.push_back(self);
      B.value.push_back(own * dot(directions[std::size_t(self)], normals[m]));
    }
    B.start[m + 1] = int(B.index.size());
  }

  // The edges (each once) with their weights ℓ² c_ij and the terms μ A_i of R; L's diagonal;
  // E(0).
  std::vector<Edge>& edges = work.edges;
  std::vector<double>& degree = work.degree;
  edges.clear();
  degree.assign(rows, 0.0);
  double r0 = 0;
  for_each_weighted_edge(frozen, [&](int i, int j, double weight) {
    edges.push_back({i, j, weight});
    degree[std::size_t(i)] += weight;
    degree[std::size_t(j)] += weight;
    const double d = H[std::size_t(i)] - H[std::size_t(j)];
    r0 += weight * d * d;
  });
  for_each_mean_curvature_term(frozen, [&](int i, double weight) {
    degree[std::size_t(i)] += weight;
    r0 += weight * H[std::size_t(i)] * H[std::size_t(i)];
  });
  // L's off-diagonal entries by row (-ω per edge, both ways); `degree` is its diagonal.
  std::vector<int>& l_start = work.l_start;
  l_start.assign(rows + 1, 0);
  for (const Edge& e : edges) {
    ++l_start[std::size_t(e.i) + 1];
    ++l_start[std::size_t(e.j) + 1];
  }
  for (std::size_t m = 0; m < rows; ++m)
    l_start[m + 1] += l_start[m];
  std::vector<std::pair<int, double>>& l_entries = work.l_entries;
  l_entries.resize(static_cast<std::size_t>(l_start[rows]));
  std::vector<int>& next = work.next;
  {
    next.assign(l_start.begin(), l_start.end() - 1);
    for (const Edge& e : edges) {
      l_entries[std::size_t(next[std::size_t(e.i)]++)] = {e.j, -e.weight};
      l_entries[std::size_t(next[std::size_t(e.j)]++)] = {e.i, -e.weight};
    }
  }

  // A dense accumulator over the variables, with the list of those it holds.
  std::vector<double>& accumulated = work.accumulated;
  std::vector<char>& held = work.held;
  std::vector<int>& touched = work.touched;
  accumulated.assign(std::size_t(variables), 0.0);
  held.assign(std::size_t(variables), 0);
  touched.clear();
  auto accumulate = [&](int v, double value) {
    if (!held[std::size_t(v)]) {
      held[std::size_t(v)] = 1;
      touched.push_back(v);
    }
    accumulated[std::size_t(v)] += value;
  };
  auto add_row_of_B = [&](std::size_t m, double factor) {
    for (int p = B.start[m]; p < B.start[m + 1]; ++p)
      accumulate(B.index[std::size_t(p)], factor * B.value[std::size_t(p)]);
  };

  // The rows of L B (and of L H⁰), for the rows where B or L is not empty.
  Curvature_variation_workspace::Sparse_rows& LB = work.LB;
  std::vector<double>& LH = work.LH;
  LB.reset(rows);
  LH.assign(rows, 0.0);
  for (std::size_t m = 0; m < rows; ++m) {
    if (degree[m] > 0) {
      add_row_of_B(m, degree[m]);
      LH[m] = degree[m] * H[m];
      for (int p = l_start[m]; p < l_start[m + 1]; ++p) {
        const auto& [k, value] = l_entries[std::size_t(p)];
        add_row_of_B(std::size_t(k), value);
        LH[m] += value * H[std::size_t(k)];
      }
    }
    for (int v : touched) {
      LB.index.push_back(v);
      LB.value.push_back(accumulated[std::size_t(v)]);
      accumulated[std::size_t(v)] = 0;
      held[std::size_t(v)] = 0;
    }
    touched.clear();
    LB.start[m + 1] = int(LB.index.size());
  }

  // Bᵀ by variable: the rows m with B_mv ≠ 0.
  std::vector<int>& bt_start = work.bt_start;
  bt_start.assign(std::size_t(variables) + 1, 0);
  for (int v : B.index)
    ++bt_start[std::size_t(v) + 1];
  for (int v = 0; v < variables; ++v)
    bt_start[std::size_t(v) + 1] += bt_start[std::size_t(v)];
  std::vector<std::pair<int, double>>& bt_entries = work.bt_entries;
  bt_entries.resize(B.index.size());
  {
    next.assign(bt_start.begin(), bt_start.end() - 1);
    for (std::size_t m = 0; m < rows; ++m)
      for (int p = B.start[m]; p < B.start[m + 1]; ++p)
        bt_entries[std::size_t(next[std::size_t(B.index[std::size_t(p)])]++)] = {
            int(m), B.value[std::size_t(p)]};
  }

  // Row a of the matrix, 2 Σ_m B_ma (L B)_m, upper part; and q_a = 2 Σ_m B_ma (L H⁰)_m.
  for (int a = 0; a < variables; ++a) {
    double q = 0;
    for (int p = bt_start[std::size_t(a)]; p < bt_start[std::size_t(a) + 1]; ++p) {
      const auto& [m, b] = bt_entries[std::size_t(p)];
      q += b * LH[std::size_t(m)];
      for (int t = LB.start[std::size_t(m)]; t < LB.start[std::size_t(m) + 1]; ++t) {
        const int v = LB.index[std::size_t(t)];
        if (v >= a)
          accumulate(v, 2 * b * LB.value[std::size_t(t)]);
      }
    }
    if (bt_start[std::size_t(a)] < bt_start[std::size_t(a) + 1])
      add_q(a, 2 * q);
    for (int v : touched) {
      add_P(a, v, accumulated[std::size_t(v)]);
      accumulated[std::size_t(v)] = 0;
      held[std::size_t(v)] = 0;
    }
    touched.clear();
  }
  return r0;
}

// The same with arrays of its own.
template <typename AddP, typename AddQ>
double add_curvature_variation_quadratic(const Frozen_curvature_variation& frozen,
                                         const std::vector<std::array<double, 3>>& positions,
                                         const std::vector<std::array<double, 3>>& normals,
                                         const std::vector<int>& variable_of_vertex,
                                         const std::vector<std::array<double, 3>>& directions,
                                         AddP add_P, AddQ add_q)
{
  Curvature_variation_workspace work;
  return add_curvature_variation_quadratic(frozen, positions, normals, variable_of_vertex,
                                           directions, add_P, add_q, work);
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_CURVATURE_VARIATION_ENERGY_H

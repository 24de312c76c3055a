// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_WILLMORE_ENERGY_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_WILLMORE_ENERGY_H

// §3.4 of the paper, "Fairness function": the discrete Willmore energy (eq. 6-9)
//   E = Σ_{i in I_R} A_i ‖K_i‖²,   K_i = 1/(2 A_i) Σ_j (cot α_ij + cot β_ij)(V_i - V_j),
//   A_i = 1/3 of the area of the triangles around V_i (eq. 7).
// Eq. 8 as printed lacks the factor 1/2 of the standard cotangent formula; we use the standard
// one (the user manual says so), so K_i approximates the mean curvature normal 2 H N (‖K‖ = 2 on
// the unit sphere). A·K² is dimensionless: E does not change under uniform scaling or rigid
// motions.
//
// With A_i and the cotangent weights frozen at the current positions and the movable vertices
// displaced along fixed directions, V̄_k = V_k + x_k N_k, every K_i is affine in x, so
// E(x) = ½ xᵀ Q x + cᵀ x + r exactly. Plain arrays only: no mesh, no kernel.

#include <CGAL/Highlight_lines/internal/vector3.h>
#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/assertions.h>

#include <Eigen/Sparse>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {
namespace willmore_detail {

using namespace vector3;

} // namespace willmore_detail

// The frozen part of the energy: per energy vertex i, A_i and the weights
// w_ij = (cot α_ij + cot β_ij) / (2 A_i), so that K_i = Σ_j w_ij (V_i - V_j).
//
// Boundary: the weights are accumulated triangle by triangle, so an edge with only one incident
// triangle in the given list contributes only its one cotangent (the usual convention at a
// mesh border). An energy vertex is expected to have its full one-ring in the list; otherwise
// its K and A are those of the partial ring.
struct Frozen_willmore_weights
{
  struct Neighbour
  {
    int vertex;
    double weight; // (cot α + cot β) / (2 A_i)
  };

  std::vector<int> energy_vertices; // I_R, as given
  std::vector<double> area;         // A_i, per energy vertex
  std::vector<std::vector<Neighbour>> neighbours;
};

// Freezes A_i and the cotangent weights at `positions`. `triangles` index into `positions` and
// must contain every triangle around every energy vertex. Throws Invalid_input
// (DEGENERATE_FACE, element = index into `triangles`) for a triangle around an energy vertex
// with collinear corners, where a cotangent is infinite.
inline Frozen_willmore_weights
freeze_willmore_weights(const std::vector<std::array<double, 3>>& positions,
                        const std::vector<std::array<int, 3>>& triangles,
                        const std::vector<int>& energy_vertices)
{
  using namespace willmore_detail;
  Frozen_willmore_weights frozen;
  frozen.energy_vertices = energy_vertices;
  frozen.area.assign(energy_vertices.size(), 0.0);
  frozen.neighbours.resize(energy_vertices.size());
  for (auto& ring : frozen.neighbours)
    ring.reserve(8); // a ring of up to 8 without regrowing (6 on regular meshes)

  std::vector<int> row_of_vertex(positions.size(), -1);
  for (std::size_t row = 0; row < energy_vertices.size(); ++row) {
    const int v = energy_vertices[row];
    CGAL_precondition(v >= 0 && std::size_t(v) < positions.size());
    CGAL_precondition(row_of_vertex[std::size_t(v)] == -1); // each energy vertex once
    row_of_vertex[std::size_t(v)] = int(row);
  }

  // Unnormalised weights: Σ cot and the ring area, divided by 2 A_i once the ring is complete.
  auto add_weight = [&](int row, int j, double cotangent) {
    for (auto& n : frozen.neighbours[std::size_t(row)])
      if (n.vertex == j) {
        n.weight += cotangent;
        return;
      }
    frozen.neighbours[std::size_t(row)].push_back({j, cotangent});
  };

  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const std::array<int, 3>& tri = triangles[f];
    bool touches_energy_vertex = false;
    for (int corner = 0; corner < 3; ++corner) {
      CGAL_precondition(tri[corner] >= 0 && std::size_t(tri[corner]) < positions.size());
      touches_energy_vertex |= row_of_vertex[std::size_t(tri[corner])] >= 0;
    }
    if (!touches_energy_vertex)
      continue;
    const Vec3& p0 = positions[std::size_t(tri[0])];
    const Vec3& p1 = positions[std::size_t(tri[1])];
    const Vec3& p2 = positions[std::size_t(tri[2])];
    const double double_area = norm(cross(p1 - p0, p2 - p0));
    if (!(double_area > 0) || !std::isfinite(double_area))
      throw Invalid_input(Invalid_input::Problem::DEGENERATE_FACE,
                          "Willmore energy: triangle " + std::to_string(f) +
                              " of the local mesh is degenerate (collinear corners)",
                          f);
    // cot of the angle at corner k = (u·v) / |u × v| with u, v the edges leaving k; |u × v| is
    // twice the triangle area whichever corner it is taken at.
    const Vec3* p[3] = {&p0, &p1, &p2};
    double cot[3];
    for (int k = 0; k < 3; ++k)
      cot[k] = dot(*p[(k + 1) % 3] - *p[k], *p[(k + 2) % 3] - *p[k]) / double_area;

    for (int corner = 0; corner < 3; ++corner) {
      const int row = row_of_vertex[std::size_t(tri[corner])];
      if (row < 0)
        continue;
      const int j = (corner + 1) % 3, k = (corner + 2) % 3;
      frozen.area[std::size_t(row)] += double_area / 6; // one third of the triangle area
      add_weight(row, tri[j], cot[k]);                  // edge (i, j) is opposite corner k
      add_weight(row, tri[k], cot[j]);
    }
  }

  for (std::size_t row = 0; row < energy_vertices.size(); ++row) {
    CGAL_precondition(frozen.area[row] > 0); // an energy vertex without triangles
    for (auto& n : frozen.neighbours[row])
      n.weight /= 2 * frozen.area[row];
  }
  return frozen;
}

// K_i = Σ_j w_ij (V_i - V_j) with the frozen weights, at `positions` (which may be displaced).
inline std::array<double, 3>
mean_curvature_normal(const Frozen_willmore_weights& frozen, std::size_t row,
                      const std::vector<std::array<double, 3>>& positions)
{
  using namespace willmore_detail;
  const Vec3& vi = positions[std::size_t(frozen.energy_vertices[row])];
  Vec3 k{0, 0, 0};
  for (const auto& n : frozen.neighbours[row])
    k = k + n.weight * (vi - positions[std::size_t(n.vertex)]);
  return k;
}

// E = Σ A_i ‖K_i‖² with the frozen A_i and weights, at `positions` (which may be displaced).
inline double frozen_willmore_energy(const Frozen_willmore_weights& frozen,
                                     const std::vector<std::array<double, 3>>& positions)
{
  double energy = 0;
  for (std::size_t row = 0; row < frozen.energy_vertices.size(); ++row) {
    const std::array<double, 3> k = mean_curvature_normal(frozen, row, positions);
    energy += frozen.area[row] * willmore_detail::dot(k, k);
  }
  return energy;
}

// The true discrete Willmore energy: weights and areas taken at `positions` themselves
// (for reports and benchmarks).
inline double willmore_energy(const std::vector<std::array<double, 3>>& positions,
                              const std::vector<std::array<int, 3>>& triangles,
                              const std::vector<int>& energy_vertices)
{
  return frozen_willmore_energy(freeze_willmore_weights(positions, triangles, energy_vertices),
                                positions);
}

// E(x) = ½ xᵀ Q x + cᵀ x + r = ‖J x + k‖², with J stacking sqrt(A_i) ∂K_i/∂x (three rows per
// energy vertex) and k stacking sqrt(A_i) K_i at x = 0; hence Q = 2 JᵀJ (symmetric, positive
// semidefinite by construction), c = 2 Jᵀk, r = ‖k‖².
struct Willmore_quadratic
{
  Eigen::SparseMatrix<double> Q; // full symmetric storage, exactly symmetric
  Eigen::VectorXd c;
  double r = 0;
  Eigen::SparseMatrix<double> J; // the least-squares form, for solvers that want it
  Eigen::VectorXd k;

  double value(const Eigen::VectorXd& x) const { return 0.5 * x.dot(Q * x) + c.dot(x) + r; }
  Eigen::VectorXd gradient(const Eigen::VectorXd& x) const { return Q * x + c; }
};

// The energy as a function of the displacements x of `movable_vertices` (variable number =
// position in that list) along `directions` (unit normals N_k, same order), with the weights
// frozen in `frozen` and the undisplaced `positions`. Movable vertices outside every energy
// vertex's ring get zero rows and columns.
inline Willmore_quadratic willmore_quadratic(const Frozen_willmore_weights& frozen,
                                             const std::vector<std::array<double, 3>>& positions,
                                             const std::vector<int>& movable_vertices,
                                             const std::vector<std::array<double, 3>>& directions)
{
  CGAL_precondition(movable_vertices.size() == directions.size());
  const Eigen::Index n = Eigen::Index(movable_vertices.size());
  std::vector<int> variable_of_vertex(positions.size(), -1);
  for (std::size_t v = 0; v < movable_vertices.size(); ++v) {
    const int vertex = movable_vertices[v];
    CGAL_precondition(vertex >= 0 && std::size_t(vertex) < positions.size());
    CGAL_precondition(variable_of_vertex[std::size_t(vertex)] == -1); // each vertex once
    variable_of_vertex[std::size_t(vertex)] = int(v);
  }

  const std::size_t m = frozen.energy_vertices.size();
  Willmore_quadratic quadratic;
  quadratic.k.resize(Eigen::Index(3 * m));
  std::vector<Eigen::Triplet<double>> entries;
  // ∂K_i/∂x_v = w N_v for each term w (V_i - V_j) where V_i is movable, -w N_v where V_j is.
  auto add_column = [&](std::size_t row, int vertex, double coefficient) {
    const int v = variable_of_vertex[std::size_t(vertex)];
    if (v < 0)
      return;
    for (int a = 0; a < 3; ++a)
      entries.emplace_back(Eigen::Index(3 * row) + a, v,
                           coefficient * directions[std::size_t(v)][a]);
  };
  for (std::size_t row = 0; row < m; ++row) {
    const double root_area = std::sqrt(frozen.area[row]);
    const std::array<double, 3> k = mean_curvature_normal(frozen, row, positions);
    for (int a = 0; a < 3; ++a)
      quadratic.k[Eigen::Index(3 * row) + a] = root_area * k[std::size_t(a)];
    for (const auto& neighbour : frozen.neighbours[row]) {
      add_column(row, frozen.energy_vertices[row], root_area * neighbour.weight);
      add_column(row, neighbour.vertex, -root_area * neighbour.weight);
    }
  }
  quadratic.J.resize(Eigen::Index(3 * m), n);
  quadratic.J.setFromTriplets(entries.begin(), entries.end()); // sums the duplicates

  const Eigen::SparseMatrix<double> Jt = quadratic.J.transpose();
  const Eigen::SparseMatrix<double> gram = Jt * quadratic.J;
  // Q = gram + gramᵀ (= 2 JᵀJ): the product sums (p, q) and (q, p) in different orders, and
  // adding the transpose makes Q symmetric to the last bit, which symmetric solvers may assume.
  const Eigen::SparseMatrix<double> gram_t = gram.transpose();
  quadratic.Q = gram + gram_t;
  quadratic.c = 2 * (Jt * quadratic.k);
  quadratic.r = quadratic.k.squaredNorm();
  return quadratic;
}

// The same quadratic handed straight to a sink, without the sparse products of
// willmore_quadratic(): row i of J holds a_iv = sqrt(A_i) ∂K_i/∂x_v (a 3-vector per variable v
// of the ring), so Q_vw = 2 Σ_i a_iv · a_iw and c_v = 2 Σ_i a_iv · sqrt(A_i) K_i. Calls
// add_P(v, w, value) with v <= w once per energy vertex and pair (a sink that sums the
// duplicates gets Q), add_q(v, value) likewise; returns r = E(0). `variable_of_vertex` maps
// a vertex to its variable, -1 if it does not move.
//
// With `energy_normals` (a unit normal N_i per energy vertex), K_i is replaced by its normal part
// (K_i · N_i) N_i: the energy Σ A_i (K_i · N_i)² of the mean curvature alone.
template <typename AddP, typename AddQ>
double add_willmore_quadratic(const Frozen_willmore_weights& frozen,
                              const std::vector<std::array<double, 3>>& positions,
                              const std::vector<int>& variable_of_vertex,
                              const std::vector<std::array<double, 3>>& directions, AddP add_P,
                              AddQ add_q,
                              const std::vector<std::array<double, 3>>* energy_normals = nullptr)
{
  using namespace willmore_detail;
  double r = 0;
  std::vector<std::pair<int, Vec3>> row;
  // The normal part of a vector of the row: still a 3-vector, along N_i.
  auto part = [energy_normals](std::size_t i, const Vec3& a) {
    if (energy_normals == nullptr)
      return a;
    const Vec3& n = (*energy_normals)[i];
    return dot(a, n) * n;
  };
  for (std::size_t i = 0; i < frozen.energy_vertices.size(); ++i) {
    const double root_area = std::sqrt(frozen.area[i]);
    const Vec3 k = part(i, root_area * mean_curvature_normal(frozen, i, positions));
    r += dot(k, k);
    row.clear();
    double own = 0;
    for (const auto& neighbour : frozen.neighbours[i]) {
      own += neighbour.weight;
      const int v = variable_of_vertex[std::size_t(neighbour.vertex)];
      if (v >= 0)
        row.emplace_back(v, part(i, (-root_area * neighbour.weight) * directions[std::size_t(v)]));
    }
    const int self = variable_of_vertex[std::size_t(frozen.energy_vertices[i])];
    if (self >= 0)
      row.emplace_back(self, part(i, (root_area * own) * directions[std::size_t(self)]));
    for (const auto& a : row) {
      add_q(a.first, 2 * dot(a.second, k));
      for (const auto& b : row)
        if (a.first <= b.first)
          add_P(a.first, b.first, 2 * dot(a.second, b.second));
    }
  }
  return r;
}

// Freeze and build in one call: the quadratic of the energy around `energy_vertices` at the
// current `positions`.
inline Willmore_quadratic make_willmore_quadratic(
    const std::vector<std::array<double, 3>>& positions,
    const std::vector<std::array<int, 3>>& triangles, const std::vector<int>& energy_vertices,
    const std::vector<int>& movable_vertices, const std::vector<std::array<double, 3>>& directions)
{
  return willmore_quadratic(freeze_willmore_weights(positions, triangles, energy_vertices),
                            positions, movable_vertices, directions);
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_WILLMORE_ENERGY_H

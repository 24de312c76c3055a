// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_MEAN_CURVATURE_FIT_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_MEAN_CURVATURE_FIT_H

// A pointwise mean curvature that is consistent on irregular triangulations and linear in the
// positions: at a vertex P with unit normal N and a tangent frame (T1, T2), the heights
// h_j = (P_j - P) · N of nearby vertices are fitted, in the least-squares sense, by
//   h(u, v) = a u² + b u v + c v² [+ d u + e v],   u = (P_j - P) · T1, v = (P_j - P) · T2,
// and H = -2 (a + c), the scale and sign of the cotangent formula's K · N (2/R on a sphere of
// radius R with outer normals). With the frame and the (u, v) of the points frozen, (a, c) are
// fixed linear combinations of the heights: H = Σ_j f_j (P - P_j) · N, a stencil like the
// cotangent one, so the energies built on it stay exact quadratics in the normal displacements.
//
// Exact for quadratic height functions over the frame's plane on any triangulation (the
// cotangent formula is exact for them only on symmetric rings), hence a mean curvature that
// converges under refinement of jittered meshes, where the cotangent one oscillates by O(1).

#include <CGAL/Highlight_lines/internal/vector3.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

struct Mean_curvature_fit_options
{
  enum class Method {
    COTANGENT,   // the cotangent formula's K · N (not consistent on irregular triangulations)
    QUADRIC_FIT, // the fit above
    // The cotangent formula where the one-ring is well shaped, the least-squares fit over the
    // two-ring where it holds a sliver (a corner below `sliver_angle`) or a folded triangle:
    // there the cotangent H is an artefact of the triangle shapes (so it is no prior either),
    // the fit reads only the points (curvature_variation_energy.h).
    FIT_ON_DEGENERATE_RINGS
  };
  Method method = Method::QUADRIC_FIT;
  // Points: the one-ring if it has at least `minimum_one_ring` vertices, else the two-ring.
  int minimum_one_ring = 6;
  // Fit d u + e v too: the vertex normal is not the surface's, and without them an O(h) error
  // of the normal makes an O(1) error of H (measured: the hoods of benchmark_fairing end 4.5x to
  // 500x further from the truth without them).
  bool linear_terms = true;
  // The stencil closest to the cotangent one (Σ δ_j², over the fit's points) among those exact
  // for the fitted height functions, instead of the least-squares fit's (the smallest Σ f_j²):
  // equal to the cotangent stencil where that one is exact (symmetric rings), and with its
  // response to the oscillations of one-ring size, which a least-squares fit damps.
  bool cotangent_prior = true;
  // FIT_ON_DEGENERATE_RINGS: the corner angle below which a triangle is a sliver (5°, the
  // fairing report's).
  double sliver_angle = 5 * 3.14159265358979323846 / 180;
};

namespace fit_detail {

using namespace vector3;

// Solves the symmetric positive definite M z = r (k <= 5) by Cholesky; false if M is
// numerically singular (a pivot below 1e-12 of the largest diagonal entry).
inline bool solve_spd(double M[5][5], double* r, int k)
{
  double largest = 0;
  for (int i = 0; i < k; ++i)
    largest = (std::max)(largest, M[i][i]);
  if (!(largest > 0) || !std::isfinite(largest))
    return false;
  for (int j = 0; j < k; ++j) {
    double d = M[j][j];
    for (int p = 0; p < j; ++p)
      d -= M[j][p] * M[j][p];
    if (!(d > 1e-12 * largest))
      return false;
    M[j][j] = std::sqrt(d);
    for (int i = j + 1; i < k; ++i) {
      double s = M[i][j];
      for (int p = 0; p < j; ++p)
        s -= M[i][p] * M[j][p];
      M[i][j] = s / M[j][j];
    }
  }
  for (int i = 0; i < k; ++i) { // L y = r
    for (int p = 0; p < i; ++p)
      r[i] -= M[i][p] * r[p];
    r[i] /= M[i][i];
  }
  for (int i = k - 1; i >= 0; --i) { // Lᵀ z = y
    for (int p = i + 1; p < k; ++p)
      r[i] -= M[p][i] * r[p];
    r[i] /= M[i][i];
  }
  return true;
}

} // namespace fit_detail

// The stencil (vertex, f_j) of H = Σ_j f_j (P - P_j) · N at `center` with unit normal `normal`
// over the points `points` (vertex ids into `positions`, `center` not among them). Returns
// false, leaving `stencil` empty, if the fit is singular (too few or degenerate points).
template <typename Neighbour>
bool quadric_fit_stencil(int center, const std::array<double, 3>& normal,
                         const std::vector<int>& points,
                         const std::vector<std::array<double, 3>>& positions,
                         const Mean_curvature_fit_options& options, std::vector<Neighbour>& stencil,
                         const std::vector<Neighbour>* prior = nullptr)
{
  using namespace fit_detail;
  stencil.clear();
  const int k = options.linear_terms ? 5 : 3;
  if (int(points.size()) < k)
    return false;
  // Tangent frame: T1 ⊥ N from the coordinate axis least aligned with N.
  const Vec3& n = normal;
  const double ax = std::abs(n[0]), ay = std::abs(n[1]), az = std::abs(n[2]);
  const Vec3 axis =
      (ax <= ay && ax <= az) ? Vec3{1, 0, 0} : (ay <= az ? Vec3{0, 1, 0} : Vec3{0, 0, 1});
  Vec3 t1 = cross(n, axis);
  const double t1_length = norm(t1);
  if (!(t1_length > 0))
    return false;
  t1 = (1 / t1_length) * t1;
  const Vec3 t2 = cross(n, t1);

  const Vec3& p = positions[std::size_t(center)];
  std::vector<std::array<double, 5>> rows; // (u, v), then φ in the scaled coordinates
  rows.reserve(points.size());
  double scale2 = 0;
  for (int j : points) {
    const Vec3 d = positions[std::size_t(j)] - p;
    const double u = dot(d, t1), v = dot(d, t2);
    rows.push_back({u, v, 0, 0, 0});
    scale2 += u * u + v * v;
  }
  scale2 /= double(points.size());
  if (!(scale2 > 0) || !std::isfinite(scale2))
    return false;
  const double s = std::sqrt(scale2);
  double M[5][5] = {};
  for (auto& row : rows) {
    const double u = row[0] / s, v = row[1] / s;
    row = {u * u, u * v, v * v, u, v};
    for (int a = 0; a < k; ++a)
      for (int b = 0; b <= a; ++b)
        M[a][b] += row[std::size_t(a)] * row[std::size_t(b)];
  }
  for (int a = 0; a < k; ++a)
    for (int b = a + 1; b < k; ++b)
      M[a][b] = M[b][a];
  // In the scaled coordinates, g_j = s² f_j must satisfy Σ_j g_j φ_j = t = (2, 0, 2, 0, 0)
  // (then Σ_j f_j (P - P_j) · N = -Σ_j f_j h_j = -2 (a + c) for every fitted h), M = Σ φ φᵀ.
  // The smallest g in Σ g_j² is the least-squares fit's stencil; the smallest change to the
  // prior g⁰ is g = g⁰ + Φ M⁻¹ (t - Φᵀ g⁰).
  std::vector<double> g0(points.size(), 0.0);
  if (prior)
    for (std::size_t i = 0; i < points.size(); ++i)
      for (const auto& entry : *prior)
        if (entry.vertex == points[i])
          g0[i] = entry.weight * scale2;
  double z[5] = {2, 0, 2, 0, 0};
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int a = 0; a < k; ++a)
      z[a] -= g0[i] * rows[i][std::size_t(a)];
  if (!solve_spd(M, z, k))
    return false;
  stencil.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& row = rows[i];
    double f = 0;
    for (int a = 0; a < k; ++a)
      f += z[a] * row[std::size_t(a)];
    stencil.push_back({points[i], (g0[i] + f) / scale2});
  }
  return true;
}

// The unit normal of the least-squares plane through `center` and `points` (the eigenvector of
// their covariance with the smallest eigenvalue), on the side of `orientation`; `orientation`
// itself if the points do not span a plane.
inline std::array<double, 3> plane_normal(int center, const std::vector<int>& points,
                                          const std::vector<std::array<double, 3>>& positions,
                                          const std::array<double, 3>& orientation)
{
  using namespace fit_detail;
  const Vec3& p = positions[std::size_t(center)];
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int j : points)
    mean +=
        Eigen::Vector3d(positions[std::size_t(j)][0] - p[0], positions[std::size_t(j)][1] - p[1],
                        positions[std::size_t(j)][2] - p[2]);
  mean /= double(points.size() + 1); // the centre is the origin
  Eigen::Matrix3d covariance = mean * mean.transpose();
  for (int j : points) {
    const Eigen::Vector3d d(positions[std::size_t(j)][0] - p[0],
                            positions[std::size_t(j)][1] - p[1],
                            positions[std::size_t(j)][2] - p[2]);
    covariance += (d - mean) * (d - mean).transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
  if (eigen.info() != Eigen::Success || !(eigen.eigenvalues()[1] > 0))
    return orientation;
  Eigen::Vector3d n = eigen.eigenvectors().col(0);
  if (n.dot(Eigen::Vector3d(orientation[0], orientation[1], orientation[2])) < 0)
    n = -n;
  return {n[0], n[1], n[2]};
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_MEAN_CURVATURE_FIT_H

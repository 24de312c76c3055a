// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_VECTOR3_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_VECTOR3_H

#include <array>
#include <cmath>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// Plain 3-vectors of doubles for the internals that work on flat arrays (OGH curves, energies,
// Jacobians). The operators live in their own namespace: bring them in with a using-directive.
namespace vector3 {

using Vec3 = std::array<double, 3>;

inline Vec3 operator+(const Vec3& a, const Vec3& b)
{
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vec3 operator-(const Vec3& a, const Vec3& b)
{
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Vec3 operator*(double s, const Vec3& a)
{
  return {s * a[0], s * a[1], s * a[2]};
}
inline double dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const Vec3& a)
{
  return std::sqrt(dot(a, a));
}
inline bool is_finite(const Vec3& a)
{
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}

// The eigenvalues and unit eigenvectors (unsorted, eigenvector j in column j of `vectors`) of
// the symmetric 3 x 3 matrix `c`, by Jacobi rotations.
inline void symmetric_eigen(const double (&c)[3][3], std::array<double, 3>& values,
                            double (&vectors)[3][3])
{
  double a[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      a[i][j] = c[i][j];
      vectors[i][j] = i == j ? 1 : 0;
    }
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    if (!(off > 1e-30 * (a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2])))
      break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0)
          continue;
        const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
        const double t =
            (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double cs = 1 / std::sqrt(t * t + 1), sn = t * cs;
        for (int k = 0; k < 3; ++k) { // columns
          const double kp = a[k][p], kq = a[k][q];
          a[k][p] = cs * kp - sn * kq;
          a[k][q] = sn * kp + cs * kq;
        }
        for (int k = 0; k < 3; ++k) { // rows
          const double pk = a[p][k], qk = a[q][k];
          a[p][k] = cs * pk - sn * qk;
          a[q][k] = sn * pk + cs * qk;
        }
        for (int k = 0; k < 3; ++k) {
          const double kp = vectors[k][p], kq = vectors[k][q];
          vectors[k][p] = cs * kp - sn * kq;
          vectors[k][q] = sn * kp + cs * kq;
        }
      }
  }
  values = {a[0][0], a[1][1], a[2][2]};
}

} // namespace vector3

using vector3::Vec3;
} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_VECTOR3_H

// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_SURROUNDINGS_FIT_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_SURROUNDINGS_FIT_H

#include <CGAL/Highlight_lines/internal/vector3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// The quadric height field h(x, y) = c0 + c1 x + c2 y + c3 x^2 + c4 xy + c5 y^2 over the tangent
// plane (normal `normal`) at the vertex `origin`, x and y in units of the region's radius (the
// largest distance of a vertex of `region` from `origin`), fitted (least squares) to the
// vertices of `region` farther than 60 % of that radius from `origin`: the smooth surface the
// surroundings predict. Calls `inner(h - fit)` for each vertex nearer than that; returns the
// fit at the origin, or the mean height of the outer vertices if the fit is singular (then
// `inner` is not called), or 0 if there is nothing to fit.
template <typename Local_mesh, typename Inner>
double fit_surroundings(const Local_mesh& local, int origin, const vector3::Vec3& normal,
                        const std::set<int>& region, Inner inner)
{
  using namespace vector3;
  const double* pp = local.point(origin);
  const Vec3 p{pp[0], pp[1], pp[2]};
  Vec3 t = std::abs(normal[0]) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  t = t - dot(t, normal) * normal;
  t = (1 / norm(t)) * t;
  const Vec3 u = cross(normal, t);
  double radius = 0;
  for (int v : region) {
    const double* q = local.point(v);
    radius = (std::max)(radius, norm(Vec3{q[0], q[1], q[2]} - p));
  }
  if (!(radius > 0))
    return 0;
  auto coordinates = [&](int v) {
    const double* q = local.point(v);
    const Vec3 d = Vec3{q[0], q[1], q[2]} - p;
    return std::array<double, 4>{dot(d, t) / radius, dot(d, u) / radius, dot(d, normal), norm(d)};
  };
  double m[6][7] = {};
  double mean = 0;
  std::size_t count = 0;
  for (int v : region) {
    const auto c = coordinates(v);
    if (c[3] < 0.6 * radius)
      continue;
    const double x = c[0], y = c[1], h = c[2];
    const double basis[6] = {1, x, y, x * x, x * y, y * y};
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j)
        m[i][j] += basis[i] * basis[j];
      m[i][6] += basis[i] * h;
    }
    mean += h;
    ++count;
  }
  if (count == 0)
    return 0;
  // Gauss-Jordan elimination with partial pivoting.
  for (int c = 0; c < 6; ++c) {
    int pivot = c;
    for (int r = c + 1; r < 6; ++r)
      if (std::abs(m[r][c]) > std::abs(m[pivot][c]))
        pivot = r;
    if (!(std::abs(m[pivot][c]) > 1e-12 * double(count)))
      return mean / double(count);
    for (int k = 0; k < 7; ++k)
      std::swap(m[c][k], m[pivot][k]);
    for (int r = 0; r < 6; ++r)
      if (r != c) {
        const double f = m[r][c] / m[c][c];
        for (int k = 0; k < 7; ++k)
          m[r][k] -= f * m[c][k];
      }
  }
  double coefficient[6];
  for (int i = 0; i < 6; ++i)
    coefficient[i] = m[i][6] / m[i][i];
  for (int v : region) {
    const auto c = coordinates(v);
    if (c[3] >= 0.6 * radius)
      continue;
    const double x = c[0], y = c[1];
    inner(c[2] - (coefficient[0] + coefficient[1] * x + coefficient[2] * y +
                  coefficient[3] * x * x + coefficient[4] * x * y + coefficient[5] * y * y));
  }
  return coefficient[0];
}

// Whether the vertex `peak` lies below (against `normal`) the quadric height field over its
// tangent plane fitted to the vertices of `region` farther than 60 % of the region's radius
// from it; the mean of those vertices if the fit is singular.
template <typename Local_mesh>
bool peak_lies_below_fit(const Local_mesh& local, int peak, const vector3::Vec3& normal,
                         const std::set<int>& region)
{
  return fit_surroundings(local, peak, normal, region, [](double) {}) > 0;
}

// Whether the inner part of `region` (within 60 % of its radius from `centre`) lies below
// (against `normal`) the quadric its outer part predicts: the sign of the inner vertex farthest
// from the fit. A defect's centre moves most, wherever its strongest anomaly lies (for a wide
// dent often on its flank, where the lines are displaced most, and where the surface can lie
// on either side of a fit centred on it); a sum over the inner vertices would add up the
// fit's own error over the whole neighbourhood.
template <typename Local_mesh>
bool region_lies_below_fit(const Local_mesh& local, int centre, const vector3::Vec3& normal,
                           const std::set<int>& region)
{
  double farthest = 0;
  const double at_centre = fit_surroundings(local, centre, normal, region, [&farthest](double h) {
    if (std::abs(h) > std::abs(farthest))
      farthest = h;
  });
  return farthest != 0 ? farthest < 0 : at_centre > 0;
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_SURROUNDINGS_FIT_H

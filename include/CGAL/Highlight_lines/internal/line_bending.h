// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_LINE_BENDING_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_LINE_BENDING_H

#include <CGAL/Highlight_lines/internal/vector3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// The bending measure of the irregularity detection, on one highlight line.
//
// The line is resampled at a uniform arc-length step h. With w = q h (q even), the third
// difference D = p(s + 3w/2) - 3 p(s + w/2) + 3 p(s - w/2) - p(s - 3w/2) is w^2 times the
// change of the discrete curvature vector k (second differences at step w) over one step:
// w^3 p''' + O(w^5) on a smooth curve. On an arc-length parametrised curve
// p''' = k' N + k t B - k^2 T: the last term only says that the curvature vector turns with
// the tangent (it is there on a circle), so it is projected out:
//   bending(s) = |D - (D.T) T| / w,   T the unit chord p(s + w/2) - p(s - w/2),
// that is w^2 |k' N + k t B|. The measure is dimensionless (an angle, in radians), vanishes
// on straight lines and circles, is small on any smoothly curved line, and peaks where the
// curvature changes abruptly (wiggles, kinks, dents). Its support is 3w, so an anomaly stays
// within 3w/2 of its cause. Samples closer than 3w/2 to the end of an open line are not
// evaluated.
struct Line_bending_scales
{
  double step = 0;      // h
  int fine_samples = 4; // q, even: w = q h
};

struct Line_bending
{
  // One entry per resampled point; `bending` is negative where it is not evaluated.
  std::vector<double> bending;
  // The polyline vertex nearest (in arc length) to each resampled point.
  std::vector<std::size_t> nearest_vertex;
};

// `points` is the polyline; for a closed line the last point joins the first (it is not
// repeated).
inline void compute_line_bending(const std::vector<vector3::Vec3>& input, bool closed,
                                 const Line_bending_scales& scales, Line_bending& out)
{
  using namespace vector3;
  out.bending.clear();
  out.nearest_vertex.clear();
  const std::size_t n = input.size();
  if (n < 2 || !(scales.step > 0))
    return;
  // The samples must not depend on where the line starts or which way it runs (that order
  // comes from coordinates and changes under rigid motions): open lines are sampled
  // symmetrically about their middle, closed lines from the node farthest from their centroid.
  std::size_t first_point = 0;
  if (closed) {
    Vec3 centroid{0, 0, 0};
    for (const Vec3& p : input)
      centroid = centroid + (1.0 / double(n)) * p;
    double farthest = -1;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 d = input[i] - centroid;
      if (dot(d, d) > farthest) {
        farthest = dot(d, d);
        first_point = i;
      }
    }
  }
  auto point = [&](std::size_t i) -> const Vec3& { return input[(i + first_point) % n]; };
  const std::size_t segments = closed ? n : n - 1;
  std::vector<double> arc(segments + 1, 0.0);
  for (std::size_t i = 0; i < segments; ++i)
    arc[i + 1] = arc[i] + norm(point(i + 1) - point(i));
  const double length = arc.back();
  if (!(length > 0) || !std::isfinite(length))
    return;

  // Closed lines: a step that divides the length, so the samples are periodic.
  std::size_t samples;
  double h = scales.step, start = 0;
  if (closed) {
    samples = std::size_t(std::llround(length / h));
    if (samples < 3)
      return;
    h = length / double(samples);
  } else {
    samples = std::size_t(std::floor(length / h)) + 1;
    start = 0.5 * (length - double(samples - 1) * h);
  }
  std::vector<Vec3> resampled(samples);
  out.nearest_vertex.resize(samples);
  std::size_t seg = 0;
  for (std::size_t i = 0; i < samples; ++i) {
    const double s = (std::min)(start + double(i) * h, length);
    while (seg + 1 < segments && arc[seg + 1] < s)
      ++seg;
    const double len = arc[seg + 1] - arc[seg];
    const double t = len > 0 ? (std::min)(1.0, (std::max)(0.0, (s - arc[seg]) / len)) : 0.0;
    resampled[i] = point(seg) + t * (point(seg + 1) - point(seg));
    out.nearest_vertex[i] = ((t < 0.5 ? seg : seg + 1) + first_point) % n;
  }

  out.bending.assign(samples, -1.0);
  const int half = scales.fine_samples / 2, reach = 3 * half;
  const double w = double(scales.fine_samples) * h;
  auto at = [&](std::ptrdiff_t i) -> const Vec3& {
    if (closed) {
      const std::ptrdiff_t m = std::ptrdiff_t(samples);
      return resampled[std::size_t(((i % m) + m) % m)];
    }
    return resampled[std::size_t(i)];
  };
  std::ptrdiff_t first = reach, last = std::ptrdiff_t(samples) - 1 - reach;
  if (closed) {
    if (samples <= std::size_t(2 * reach))
      return; // shorter than the stencil
    first = 0;
    last = std::ptrdiff_t(samples) - 1;
  }
  for (std::ptrdiff_t i = first; i <= last; ++i) {
    const Vec3 chord = at(i + half) - at(i - half);
    const Vec3 third = (at(i + reach) - at(i - reach)) - 3.0 * chord;
    const double chord_length = norm(chord);
    const Vec3 normal_part =
        chord_length > 0 ? third - (dot(third, chord) / (chord_length * chord_length)) * chord
                         : third;
    out.bending[std::size_t(i)] = norm(normal_part) / w;
  }
}

// Median and normalised median absolute deviation (1.4826 MAD: the standard deviation for
// normally distributed values) of the non-negative entries of `values`.
struct Robust_statistics
{
  double median = 0;
  double deviation = 0;
  std::size_t count = 0;
};

inline Robust_statistics robust_statistics(const std::vector<double>& values)
{
  std::vector<double> v;
  v.reserve(values.size());
  for (double x : values)
    if (x >= 0)
      v.push_back(x);
  Robust_statistics stats;
  stats.count = v.size();
  if (v.empty())
    return stats;
  auto median_of = [](std::vector<double>& a) {
    const std::size_t mid = a.size() / 2;
    std::nth_element(a.begin(), a.begin() + std::ptrdiff_t(mid), a.end());
    double m = a[mid];
    if (a.size() % 2 == 0)
      m = 0.5 * (m + *std::max_element(a.begin(), a.begin() + std::ptrdiff_t(mid)));
    return m;
  };
  stats.median = median_of(v);
  for (double& x : v)
    x = std::abs(x - stats.median);
  stats.deviation = 1.4826 * median_of(v);
  return stats;
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_LINE_BENDING_H

// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_LINE_BENDING_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_LINE_BENDING_H

#include <CGAL/Highlight_lines/internal/vector3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
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

// A polyline resampled at equal arc-length steps (`step`, or for a closed line the nearest
// step that divides its length), with the index of the input point nearest to each sample and,
// if `breaks` flags input points, which samples have a flagged point between them and the next
// (or at them).
struct Line_samples
{
  std::vector<vector3::Vec3> points;
  std::vector<std::size_t> nearest_vertex;
  std::vector<char> broken;
  double step = 0;
};

// The samples do not depend on where the line starts or which way it runs (that order comes
// from coordinates and changes under rigid motions): open lines are sampled symmetrically about
// their middle, closed lines from the point farthest from their centroid. `points` is the
// polyline; for a closed line the last point joins the first (it is not repeated). Returns
// false (and no samples) for lines too short or degenerate to sample.
inline bool resample_line(const std::vector<vector3::Vec3>& input, bool closed, double step,
                          Line_samples& out, const std::vector<char>& breaks = {})
{
  using namespace vector3;
  out.points.clear();
  out.nearest_vertex.clear();
  out.broken.clear();
  const std::size_t n = input.size();
  if (n < 2 || !(step > 0))
    return false;
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
    return false;
  std::size_t samples;
  double h = step, start = 0;
  if (closed) {
    samples = std::size_t(std::llround(length / h));
    if (samples < 3)
      return false;
    h = length / double(samples);
  } else {
    samples = std::size_t(std::floor(length / h)) + 1;
    start = 0.5 * (length - double(samples - 1) * h);
  }
  out.step = h;
  out.points.resize(samples);
  out.nearest_vertex.resize(samples);
  out.broken.assign(samples, 0);
  auto is_break = [&](std::size_t i) { return !breaks.empty() && breaks[(i + first_point) % n]; };
  std::size_t seg = 0;
  for (std::size_t i = 0; i < samples; ++i) {
    const double s = (std::min)(start + double(i) * h, length);
    while (seg + 1 < segments && arc[seg + 1] < s) {
      if (i > 0 && is_break(seg + 1))
        out.broken[i - 1] = 1;
      ++seg;
    }
    const double len = arc[seg + 1] - arc[seg];
    const double t = len > 0 ? (std::min)(1.0, (std::max)(0.0, (s - arc[seg]) / len)) : 0.0;
    out.points[i] = point(seg) + t * (point(seg + 1) - point(seg));
    out.nearest_vertex[i] = ((t < 0.5 ? seg : seg + 1) + first_point) % n;
    if (is_break(seg) || is_break(seg + 1))
      out.broken[i] = 1;
  }
  return true;
}

// See resample_line() for `input` and `closed`.
inline void compute_line_bending(const std::vector<vector3::Vec3>& input, bool closed,
                                 const Line_bending_scales& scales, Line_bending& out)
{
  using namespace vector3;
  out.bending.clear();
  out.nearest_vertex.clear();
  Line_samples line;
  if (!resample_line(input, closed, scales.step, line))
    return;
  const std::vector<Vec3>& resampled = line.points;
  const std::size_t samples = resampled.size();
  const double h = line.step;
  out.nearest_vertex = line.nearest_vertex;

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

// The lateral residual of the irregularity detection (with `local_residual`), on one
// highlight line: how far the line moves sideways from the smooth course its neighbourhood
// along the line predicts.
//
// The line is resampled at a uniform arc-length step h (as for the bending). At sample i, a
// quadratic in arc length (each coordinate) is fitted by least squares to the samples at
// offsets `gap <= |j - i| <= reach` on both sides, within the stretch of line between the
// nearest breaks (sharp edges) and ends, with at least `minimum_side` samples on each side:
// the line's course at a larger scale, without the part a local defect displaces. The residual
// is the mean over the samples within `centre` of i of their offset from the fit, without its
// component along the fit's tangent at i. It vanishes on straight lines and circles (up to the
// cubic error of the fit), is not bounded (a dent of height a moves the lines over it by about
// a/k, k the rate at which the highlight value changes across them), and is local: it only
// depends on samples within `reach` of i.
struct Line_residual_scales
{
  double step = 0;      // h
  int centre = 2;       // samples averaged on either side of the centre
  int gap = 6;          // the fit ignores samples closer than this
  int reach = 16;       // and farther than this
  int minimum_side = 3; // samples the fit needs on each side of the gap
};

struct Line_residual
{
  // One entry per resampled point; `valid[i]` is 0 where the residual is not evaluated.
  std::vector<vector3::Vec3> residual;
  std::vector<vector3::Vec3> tangent; // unit
  std::vector<char> valid;
  // The polyline vertex nearest (in arc length) to each resampled point.
  std::vector<std::size_t> nearest_vertex;
};

// `breaks` (optional, one flag per point of `input`): points where the line crosses a feature
// (a sharp edge) and kinks by design; no fit reaches over one.
inline void compute_line_residual(const std::vector<vector3::Vec3>& input, bool closed,
                                  const Line_residual_scales& scales, Line_residual& out,
                                  const std::vector<char>& breaks = {})
{
  using namespace vector3;
  out.residual.clear();
  out.tangent.clear();
  out.valid.clear();
  out.nearest_vertex.clear();
  Line_samples line;
  if (!resample_line(input, closed, scales.step, line, breaks))
    return;
  const std::vector<Vec3>& resampled = line.points;
  const std::vector<char>& broken = line.broken;
  const std::size_t samples = resampled.size();
  out.nearest_vertex = line.nearest_vertex;
  out.residual.assign(samples, Vec3{0, 0, 0});
  out.tangent.assign(samples, Vec3{0, 0, 0});
  out.valid.assign(samples, 0);
  const std::ptrdiff_t m = std::ptrdiff_t(samples), reach = scales.reach, gap = scales.gap,
                       centre = scales.centre, side = scales.minimum_side;
  if (closed && m <= 2 * reach)
    return; // shorter than the window
  // How far each sample can look along the line without crossing a break or an end: the
  // fit's window is [i - back[i], i + ahead[i]] (at most `reach` on each side).
  std::vector<std::ptrdiff_t> back(samples, 0), ahead(samples, 0);
  {
    const int passes = closed ? 2 : 1;
    std::ptrdiff_t run = closed ? reach : 0;
    for (int pass = 0; pass < passes; ++pass)
      for (std::ptrdiff_t i = 0; i < m; ++i) {
        back[std::size_t(i)] = run;
        run = broken[std::size_t(i)] ? 0 : (std::min)(run + 1, reach);
      }
    run = closed ? reach : 0;
    for (int pass = 0; pass < passes; ++pass)
      for (std::ptrdiff_t i = m - 1; i >= 0; --i) {
        run = broken[std::size_t(i)] ? 0 : run;
        ahead[std::size_t(i)] = run;
        run = (std::min)(run + 1, reach);
      }
    // A break at the sample itself: nothing on either side.
    for (std::ptrdiff_t i = 0; i < m; ++i)
      if (broken[std::size_t(i)])
        back[std::size_t(i)] = ahead[std::size_t(i)] = 0;
  }
  auto at = [&](std::ptrdiff_t i) -> const Vec3& {
    if (closed)
      return resampled[std::size_t(((i % m) + m) % m)];
    return resampled[std::size_t(i)];
  };
  for (std::ptrdiff_t i = 0; i < m; ++i) {
    const std::ptrdiff_t lo = back[std::size_t(i)], hi = ahead[std::size_t(i)];
    if (lo - gap + 1 < side || hi - gap + 1 < side)
      continue; // too few samples on one side of the gap to predict the centre
    // Least-squares quadratic a0 + a1 t + a2 t^2 (t in samples) on the offsets t in
    // [-lo, -gap] and [gap, hi], in coordinates relative to the sample (no cancellation far
    // from the origin).
    const Vec3& o = at(i);
    double mt[5] = {0, 0, 0, 0, 0};
    Vec3 mp[3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    for (std::ptrdiff_t t = -lo; t <= hi; ++t) {
      if (t > -gap && t < gap)
        continue;
      const double td = double(t), t2 = td * td;
      const double powers[5] = {1, td, t2, t2 * td, t2 * t2};
      for (int k = 0; k < 5; ++k)
        mt[k] += powers[k];
      const Vec3 p = at(i + t) - o;
      for (int k = 0; k < 3; ++k)
        mp[k] = mp[k] + powers[k] * p;
    }
    // Solve [m0 m1 m2; m1 m2 m3; m2 m3 m4] a = mp (Cramer's rule; well conditioned for the
    // windows allowed above).
    const double a11 = mt[0], a12 = mt[1], a13 = mt[2], a22 = mt[2], a23 = mt[3], a33 = mt[4];
    const double c11 = a22 * a33 - a23 * a23, c12 = a13 * a23 - a12 * a33,
                 c13 = a12 * a23 - a13 * a22, c22 = a11 * a33 - a13 * a13,
                 c23 = a12 * a13 - a11 * a23, c33 = a11 * a22 - a12 * a12;
    const double det = a11 * c11 + a12 * c12 + a13 * c13;
    if (!(std::abs(det) > 0))
      continue;
    const Vec3 a0 = (1 / det) * (c11 * mp[0] + c12 * mp[1] + c13 * mp[2]);
    const Vec3 a1 = (1 / det) * (c12 * mp[0] + c22 * mp[1] + c23 * mp[2]);
    const Vec3 a2 = (1 / det) * (c13 * mp[0] + c23 * mp[1] + c33 * mp[2]);
    // The centre's mean residual.
    Vec3 r{0, 0, 0};
    const std::ptrdiff_t c = (std::min)({centre, lo, hi});
    for (std::ptrdiff_t t = -c; t <= c; ++t) {
      const double td = double(t);
      r = r + (at(i + t) - o) - (a0 + td * a1 + td * td * a2);
    }
    r = (1.0 / double(2 * c + 1)) * r;
    const double speed = norm(a1);
    if (!(speed > 0))
      continue;
    const Vec3 tangent = (1 / speed) * a1;
    out.residual[std::size_t(i)] = r - dot(r, tangent) * tangent;
    out.tangent[std::size_t(i)] = tangent;
    out.valid[std::size_t(i)] = 1;
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

// Median and normalised median absolute deviation of `v` (reordered; may be empty).
inline Robust_statistics median_and_deviation(std::vector<double>& v)
{
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

inline Robust_statistics robust_statistics(const std::vector<double>& values)
{
  std::vector<double> v;
  v.reserve(values.size());
  for (double x : values)
    if (x >= 0)
      v.push_back(x);
  return median_and_deviation(v);
}

// Median and normalised median absolute deviation of the finite entries of `values` (of any
// sign).
inline Robust_statistics robust_statistics_signed(const std::vector<double>& values)
{
  std::vector<double> v;
  v.reserve(values.size());
  for (double x : values)
    if (std::isfinite(x))
      v.push_back(x);
  return median_and_deviation(v);
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_LINE_BENDING_H

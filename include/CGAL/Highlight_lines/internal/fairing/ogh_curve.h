// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_OGH_CURVE_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_OGH_CURVE_H

// §3.2 of the paper, "Desired highlight lines": the optimized geometric Hermite (OGH) curve
// of Yong & Cheng that replaces the part of a highlight line inside the fairing region, its
// normalised arc-length parameterisation (the target points of eq. 12 are read from it), and
// a two-segment fallback where a single OGH curve would not keep the tangent directions.
// Plain arrays only: no mesh, no kernel.

#include <CGAL/Highlight_lines/internal/vector3.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {
namespace ogh_detail {

using namespace vector3;

// a / |a|, or 0 for a zero vector. Divided by its largest component first, so that tiny or huge
// (finite) tangents still give their direction instead of under- or overflowing in |a|².
inline Vec3 unit(const Vec3& a)
{
  const double largest = (std::max)({std::abs(a[0]), std::abs(a[1]), std::abs(a[2])});
  if (!(largest > 0))
    return {0, 0, 0};
  const Vec3 b = {a[0] / largest, a[1] / largest, a[2] / largest}; // 1/largest may overflow
  return (1 / norm(b)) * b;
}

// 8-point Gauss–Legendre rule on [-1, 1]: exact for polynomials of degree 15.
constexpr int gauss_points = 8;
constexpr double gauss_node[gauss_points] = {
    -0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
    0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
constexpr double gauss_weight[gauss_points] = {
    0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
    0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

} // namespace ogh_detail

enum class Ogh_curve_status {
  OK,                   ///< a curve is defined (it may still fail `keeps_tangent_directions()`)
  NON_FINITE_INPUT,     ///< a NaN or infinite coordinate
  ZERO_TANGENT,         ///< T0 or T1 has no direction
  COINCIDENT_END_POINTS ///< Q0 == Q1 (up to rounding of the coordinates)
};

// H(t) = (2t+1)(t-1)² Q0 + (-2t+3)t² Q1 + (1-t)² t a0 T0 + (t-1) t² a1 T1, t in [0, 1] (eq. 5).
//
// The printed eq. 5 and its coefficients are right as they stand: the four cubics are the
// Hermite basis, so H(0) = Q0, H(1) = Q1, H'(0) = a0 T0, H'(1) = a1 T1; and a0, a1 are the
// stationary point of the strain energy ∫‖H''‖² dt, which is
//   12 D·D + 4 a0² T0·T0 + 4 a1² T1·T1 - 12 a0 D·T0 - 12 a1 D·T1 + 4 a0 a1 T0·T1,
// i.e. 2 a0 T0·T0 + a1 T0·T1 = 3 D·T0 and a0 T0·T1 + 2 a1 T1·T1 = 3 D·T1 (D = Q1 - Q0), whose
// solution by Cramer's rule is the printed pair (a1's numerator and denominator both negated).
//
// The tangents are normalised on construction, so t0(), t1() are unit vectors and a0, a1 are
// the speeds |H'| at the ends (the curve does not depend on the lengths of the given
// tangents). The denominator 4 (T0·T0)(T1·T1) - (T0·T1)² is at least 3 |T0|²|T1|² by
// Cauchy–Schwarz: parallel tangents never make it vanish; only a zero tangent does.
class Ogh_curve
{
public:
  using Vec3 = ogh_detail::Vec3;

  Ogh_curve(const Vec3& q0, const Vec3& tangent0, const Vec3& q1, const Vec3& tangent1)
      : q0_(q0), q1_(q1)
  {
    using namespace ogh_detail;
    if (!is_finite(q0) || !is_finite(q1) || !is_finite(tangent0) || !is_finite(tangent1)) {
      status_ = Ogh_curve_status::NON_FINITE_INPUT;
      return;
    }
    t0_ = unit(tangent0);
    t1_ = unit(tangent1);
    if (t0_ == Vec3{0, 0, 0} || t1_ == Vec3{0, 0, 0}) {
      status_ = Ogh_curve_status::ZERO_TANGENT;
      return;
    }
    const Vec3 d = q1 - q0;
    const double scale = (std::max)({std::abs(q0[0]), std::abs(q0[1]), std::abs(q0[2]),
                                     std::abs(q1[0]), std::abs(q1[1]), std::abs(q1[2])});
    // Below a few ulps of the coordinates the chord is rounding noise, not a direction.
    if (!(norm(d) > 8 * 2.220446049250313e-16 * scale)) {
      status_ = Ogh_curve_status::COINCIDENT_END_POINTS;
      return;
    }
    const double c = dot(t0_, t1_); // T0·T0 = T1·T1 = 1
    const double det = 4 - c * c;   // >= 3
    a0_ = (6 * dot(d, t0_) - 3 * dot(d, t1_) * c) / det;
    a1_ = (6 * dot(d, t1_) - 3 * dot(d, t0_) * c) / det;
    status_ = Ogh_curve_status::OK;
    build_arc_length_table();
  }

  Ogh_curve_status status() const { return status_; }
  const Vec3& q0() const { return q0_; }
  const Vec3& q1() const { return q1_; }
  const Vec3& t0() const { return t0_; } // unit
  const Vec3& t1() const { return t1_; } // unit
  double a0() const { return a0_; }
  double a1() const { return a1_; }

  // No loop, cusp or fold: the curve leaves Q0 along +T0 and arrives at Q1 along +T1
  // (Yong & Cheng: a0 > 0 and a1 > 0).
  bool keeps_tangent_directions() const
  {
    return status_ == Ogh_curve_status::OK && a0_ > 0 && a1_ > 0;
  }

  Vec3 point(double t) const
  {
    using namespace ogh_detail;
    const double u = 1 - t;
    return (2 * t + 1) * u * u * q0_ + (3 - 2 * t) * t * t * q1_ + (u * u * t * a0_) * t0_ -
           (u * t * t * a1_) * t1_;
  }

  Vec3 derivative(double t) const
  {
    using namespace ogh_detail;
    const double u = 1 - t;
    return (6 * t * u) * (q1_ - q0_) + (u * (1 - 3 * t) * a0_) * t0_ +
           (t * (3 * t - 2) * a1_) * t1_;
  }

  double speed(double t) const { return ogh_detail::norm(derivative(t)); }

  // Arc length of the whole curve; 0 unless status() == OK.
  double length() const { return breaks_.empty() ? 0 : cumulative_length_.back(); }

  // The t at which the arc length from Q0 is s·length(), s clamped to [0, 1].
  double parameter_at_arc_length_fraction(double s) const
  {
    if (breaks_.empty() || !(s > 0))
      return 0;
    if (s >= 1)
      return 1;
    const double target = s * length();
    // The sub-interval [breaks_[k], breaks_[k+1]] whose cumulative lengths bracket the target.
    const std::size_t k =
        std::size_t(std::upper_bound(cumulative_length_.begin(), cumulative_length_.end(), target) -
                    cumulative_length_.begin()) -
        1;
    if (k + 1 >= breaks_.size())
      return 1;
    const double begin = breaks_[k];
    const double remaining = target - cumulative_length_[k];
    // Newton on L(t) = ∫_begin^t |H'| - remaining, monotone in t; bisection keeps it in the
    // bracket where the speed is (nearly) zero.
    double lo = begin, hi = breaks_[k + 1];
    const double span = cumulative_length_[k + 1] - cumulative_length_[k];
    double t = span > 0 ? begin + (hi - begin) * (remaining / span) : begin;
    // A cubic Hermite guess of t(arc length) from the speeds at the piece's ends (dt/dL is
    // their inverse) leaves Newton one correction instead of three; where an end's speed is
    // small against the mean speed the guess is poor and the linear one is kept.
    const double width = hi - begin, mean_speed = span / width;
    const double speed0 = break_speed_[k], speed1 = break_speed_[k + 1];
    if (span > 0 && speed0 > 0.5 * mean_speed && speed1 > 0.5 * mean_speed) {
      const double u = remaining / span, u2 = u * u, u3 = u2 * u;
      const double hermite = (2 * u3 - 3 * u2 + 1) * begin + (u3 - 2 * u2 + u) * span / speed0 +
                             (-2 * u3 + 3 * u2) * hi + (u3 - u2) * span / speed1;
      if (hermite > lo && hermite < hi)
        t = hermite;
    }
    for (int iteration = 0; iteration < 100; ++iteration) {
      const double f = integrate_speed(begin, t) - remaining;
      if (std::abs(f) <= 1e-15 * length())
        break;
      (f > 0 ? hi : lo) = t;
      const double v = speed(t);
      double next = v > 0 ? t - f / v : 0.5 * (lo + hi);
      if (!(next > lo && next < hi))
        next = 0.5 * (lo + hi);
      if (next == t)
        break;
      // Newton converges quadratically: after a correction this small (in units of the
      // piece's parameter width) the next residual is at rounding level, and checking it
      // would cost another integration (a third of the inversion's time).
      const bool converged = std::abs(next - t) <= 1e-8 * width;
      t = next;
      if (converged)
        break;
    }
    return t;
  }

  // The point of the normalised arc-length parameterisation H̃(s) (eq. 12), s in [0, 1].
  Vec3 point_at_arc_length_fraction(double s) const
  {
    return point(parameter_at_arc_length_fraction(s));
  }

private:
  double integrate_speed(double a, double b) const
  {
    const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
    double sum = 0;
    for (int i = 0; i < ogh_detail::gauss_points; ++i)
      sum += ogh_detail::gauss_weight[i] * speed(mid + half * ogh_detail::gauss_node[i]);
    return half * sum;
  }

  // Break points of [0, 1] refined until Gauss–Legendre on each piece agrees with the sum over
  // its two halves to ~1e-14 of the total: |H'| is smooth but can have a sharp minimum near
  // an end (small a0 or a1), where a uniform table would lose accuracy.
  void build_arc_length_table()
  {
    const double total_estimate = integrate_speed(0, 1);
    const double tolerance = 1e-14 * total_estimate;
    breaks_.assign(1, 0.0);
    cumulative_length_.assign(1, 0.0);
    struct Piece
    {
      double a, b, length;
      int depth;
    };
    // Depth-first, left piece on top, so that the pieces come out in increasing t.
    std::vector<Piece> stack;
    constexpr int initial = 16;
    for (int i = initial - 1; i >= 0; --i) {
      const double a = double(i) / initial, b = double(i + 1) / initial;
      stack.push_back({a, b, integrate_speed(a, b), 0});
    }
    while (!stack.empty()) {
      const Piece p = stack.back();
      stack.pop_back();
      const double mid = 0.5 * (p.a + p.b);
      const double left = integrate_speed(p.a, mid), right = integrate_speed(mid, p.b);
      if (std::abs(left + right - p.length) > tolerance && p.depth < 30) {
        stack.push_back({mid, p.b, right, p.depth + 1});
        stack.push_back({p.a, mid, left, p.depth + 1});
        continue;
      }
      breaks_.push_back(p.b);
      cumulative_length_.push_back(cumulative_length_.back() + left + right);
    }
    break_speed_.clear();
    for (double t : breaks_)
      break_speed_.push_back(speed(t));
  }

  Vec3 q0_, q1_, t0_{0, 0, 0}, t1_{0, 0, 0};
  double a0_ = 0, a1_ = 0;
  Ogh_curve_status status_ = Ogh_curve_status::OK;
  std::vector<double> breaks_, cumulative_length_; // arc-length table, empty unless OK
  std::vector<double> break_speed_;                // |H'| at the breaks
};

// The target curve of one highlight line crossing the region: one OGH curve, or two joined
// with G1 continuity (same point, same tangent direction and orientation), or none.
struct Ogh_target
{
  using Vec3 = ogh_detail::Vec3;

  enum class Status {
    SINGLE_SEGMENT, ///< the OGH curve from Q0 to Q1 keeps the tangent directions
    TWO_SEGMENTS,   ///< it does not; a G1 spline of two OGH curves through a middle point does
    NONE            ///< no tangent-keeping target: the line gets none (fairness only)
  };

  Status status = Status::NONE;
  // The status of the single OGH curve: not OK when NONE comes from degenerate input; OK when
  // the input was fine (then NONE means that neither one nor two segments kept the tangent
  // directions).
  Ogh_curve_status input_status = Ogh_curve_status::OK;
  std::vector<Ogh_curve> segments; // 1, 2, or none

  double length() const
  {
    double sum = 0;
    for (const Ogh_curve& segment : segments)
      sum += segment.length();
    return sum;
  }

  // H̃(s) over the whole target, s in [0, 1] the normalised arc length (eq. 12).
  // Precondition: status != NONE.
  Vec3 point_at_arc_length_fraction(double s) const
  {
    s = std::clamp(s, 0.0, 1.0);
    const double first = segments.front().length();
    const double along = s * length();
    if (segments.size() == 1 || along <= first)
      return segments.front().point_at_arc_length_fraction(first > 0 ? along / first : 0);
    const double second = segments.back().length();
    return segments.back().point_at_arc_length_fraction(second > 0 ? (along - first) / second : 1);
  }
};

// The target for a highlight line between the delimiting nodes Q0 and Q1 with end tangents
// T0, T1 oriented along the line's direction of travel (§3.2 of the paper).
//
// Fallback when the single OGH curve fails (a0 <= 0 or a1 <= 0): split at the middle point M
// of the ordinary cubic Hermite curve whose end tangents have the chord length |D|,
//   M  = (Q0 + Q1)/2 + |D|/8 (T0 - T1),   TM = 3/2 D - |D|/4 (T0 + T1)   (unit T0, T1),
// and fit an OGH curve on each half. This TM never vanishes and always points forward along
// the chord (TM·D >= |D|²), which is what makes the halves usually succeed where the whole
// failed (e.g. S-shaped configurations). If either half fails too, there is no target.
inline Ogh_target make_ogh_target(const ogh_detail::Vec3& q0, const ogh_detail::Vec3& tangent0,
                                  const ogh_detail::Vec3& q1, const ogh_detail::Vec3& tangent1)
{
  using namespace ogh_detail;
  Ogh_target target;
  Ogh_curve whole(q0, tangent0, q1, tangent1);
  target.input_status = whole.status();
  if (whole.status() != Ogh_curve_status::OK)
    return target;
  if (whole.keeps_tangent_directions()) {
    target.status = Ogh_target::Status::SINGLE_SEGMENT;
    target.segments.push_back(std::move(whole));
    return target;
  }
  const Vec3 d = q1 - q0;
  const double chord = norm(d);
  const Vec3 m = 0.5 * (q0 + q1) + (chord / 8) * (whole.t0() - whole.t1());
  const Vec3 tm = 1.5 * d - (chord / 4) * (whole.t0() + whole.t1());
  Ogh_curve first(q0, whole.t0(), m, tm), second(m, tm, q1, whole.t1());
  if (first.keeps_tangent_directions() && second.keeps_tangent_directions()) {
    target.status = Ogh_target::Status::TWO_SEGMENTS;
    target.segments.push_back(std::move(first));
    target.segments.push_back(std::move(second));
  }
  return target;
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_OGH_CURVE_H

// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_MODEL_LEVEL_CLASSIFICATION_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_MODEL_LEVEL_CLASSIFICATION_H

#include <CGAL/Highlight_lines/Light_setup.h>
#include <CGAL/Highlight_lines/internal/Local_mesh.h>
#include <CGAL/Highlight_lines/internal/parallel.h>
#include <CGAL/Highlight_lines/internal/model/vertex_normals.h>

#include <CGAL/Interval_nt.h>
#include <CGAL/Number_types/internal/Exact_type_selector.h>
#include <CGAL/FPU.h>

#include <boost/config.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

// The common case of the classification two vertices at a time (see
// Level_classifier::classify_common_case_lanes()) where GCC's vector extensions map to SSE2;
// elsewhere one vertex at a time, with the same results.
#if defined(__GNUC__) && !defined(__clang__) && defined(__SSE2__) &&                               \
    !defined(CGAL_HIGHLIGHT_LINES_NO_TWO_LANES)
#define CGAL_HIGHLIGHT_LINES_TWO_LANES
#endif
// On x86-64, four vertices at a time in AVX2 vectors when the processor has them (decided at
// run time, see classify_four_at_a_time()), with the same results.
#if defined(CGAL_HIGHLIGHT_LINES_TWO_LANES) && defined(__x86_64__) &&                              \
    !defined(CGAL_HIGHLIGHT_LINES_NO_FOUR_LANES)
#define CGAL_HIGHLIGHT_LINES_FOUR_LANES
#endif

namespace CGAL {
namespace Highlight_lines {
namespace internal {

#ifdef CGAL_HIGHLIGHT_LINES_TWO_LANES
// The vectors of Level_classifier::classify_common_case_lanes() (GCC does not apply
// vector_size to a size that depends on a template parameter).
template <int Lanes_count>
struct Lane_vectors;
template <>
struct Lane_vectors<2>
{
  typedef double Lanes __attribute__((vector_size(16)));
  typedef long long Masks __attribute__((vector_size(16)));
};
template <>
struct Lane_vectors<4>
{
  typedef double Lanes __attribute__((vector_size(32)));
  typedef long long Masks __attribute__((vector_size(32)));
};
#endif

// Where the highlight distance value d of a vertex (eq. 1) lies among the levels m·s.
// Decided once per vertex and cached: edges and faces read these classes, so all elements
// incident to a vertex agree on it by construction.
struct Vertex_level
{
  // 16 bytes (written for every vertex in every sweep): the level and the flags share a word.
  long long level : 58;        // k with k·s <= d < (k+1)·s
  signed char normal_side : 2; // sign of Z·Ñ; 0: the normal line is parallel to S, d undefined
  bool on_level : 1;           // d == k·s exactly
  bool out_of_range : 1;       // |d/s| >= 2^50: normal almost parallel to S, levels unusable
  bool turned_away : 1;        // Z·Ñ < 0 and only the side facing the lights is wanted
  double distance;             // d in double (exactly k·s when on_level)

  Vertex_level()
      : level(0), normal_side(0), on_level(false), out_of_range(false), turned_away(false),
        distance(0)
  {
  }

  bool defined() const { return normal_side != 0 && !out_of_range && !turned_away; }

  // Sign of d - m·s, for a defined vertex.
  int compare_to_level(long long m) const
  {
    if (level > m)
      return 1;
    if (level < m)
      return -1;
    return on_level ? 0 : 1;
  }
};

// See level_key().
constexpr long long key_side_offset = 1LL << 53;
constexpr long long undefined_key = (std::numeric_limits<long long>::min)() + 1;

// Statistics of the filter, for tests and benchmarks.
struct Classification_statistics
{
  std::size_t static_filter_failures = 0;
  std::size_t interval_filter_failures = 0;
};

// The polynomial predicate of the classification. With W = P - A0 and Ñ the unnormalised
// normal (eq. 3), d - m·s has the sign of  E(m) = (W x H)·Ñ - (m·s)(Z·Ñ)  times sign(Z·Ñ).
// E is evaluated in three stages: double with a running error bound (almost always enough),
// interval arithmetic, and an exact ring type, always from the one-ring points so that the
// answer is exact for the double input coordinates.
template <typename TriangleMesh>
class Level_classifier
{
private:
  // The terms of E in double for one vertex, with bounds on their rounding errors (NaN when
  // not trusted).
  struct Terms
  {
    double num = 0, num_bound = 0, den = 0, den_bound = 0, bound_factor = 0;
  };

public:
  Level_classifier(const Local_mesh<TriangleMesh>& lm, const Vertex_normals& vn,
                   const std::array<double, 3>& a, const std::array<double, 3>& h,
                   const std::array<double, 3>& z, double s)
      : lm_(lm), vn_(vn), points_(lm.xyz.data()), normals_(vn.normal.data()),
        bounds_(vn.bound.data()), a_(a), h_(h), z_(z),
        s_(s), habs_{std::abs(h[0]), std::abs(h[1]), std::abs(h[2])},
        zabs_sum_(std::abs(z[0]) + std::abs(z[1]) + std::abs(z[2])),
        inverse_s_(1 / s), habs_pair_{std::abs(h[1]) + std::abs(h[2]),
                                      std::abs(h[0]) + std::abs(h[2]),
                                      std::abs(h[0]) + std::abs(h[1])}
  {
  }

  // With facing_side_only, a vertex whose normal points away from the light plane is only
  // marked turned_away: its level is not needed.
  Vertex_level classify(int v, Classification_statistics& stats,
                        bool facing_side_only = false) const
  {
    Common_case c;
    if (classify_common_case(v, facing_side_only, c))
      return c.level();
    return classify_in_general(v, stats, facing_side_only);
  }

  // The result of the common case (see classify_common_case()).
  struct Common_case
  {
    long long k;
    double d;
    bool facing, turned_away;

    Vertex_level level() const
    {
      Vertex_level result;
      result.normal_side = facing ? 1 : -1;
      result.turned_away = turned_away;
      result.level = turned_away ? 0 : k;
      result.distance = turned_away ? 0.0 : d;
      return result;
    }
    long long key() const // level_key(level())
    {
      return turned_away ? undefined_key : 2 * k + 1 + (facing ? 0 : key_side_offset);
    }
  };

  // The common case, without data-dependent branches (the side of the normal is random in
  // vertex order): the side certain from the static bound, and either turned away, or
  // k = floor(d/s) with both comparisons with k·s and (k+1)·s certain and d strictly between.
  // Then the answer is the one of classify_in_general(), which starts with the same
  // comparisons; otherwise returns false.
  // Inlined into the loop over vertices: without the call, its result stays in registers.
  BOOST_FORCEINLINE bool classify_common_case(int v, bool facing_side_only,
                                              Common_case& result) const
  {
    const double* n = normals_ + 3 * std::size_t(v);
    const double* p = points_ + 3 * std::size_t(v);
    const double bound_factor = bounds_[std::size_t(v)]; // NaN: not certain
    const double den = z_[0] * n[0] + z_[1] * n[1] + z_[2] * n[2];
    const double den_bound = bound_factor * zabs_sum_;
    const double w[3] = {p[0] - a_[0], p[1] - a_[1], p[2] - a_[2]};
    const double wm[3] = {std::abs(p[0]) + std::abs(a_[0]), std::abs(p[1]) + std::abs(a_[1]),
                          std::abs(p[2]) + std::abs(a_[2])};
    const double x[3] = {w[1] * h_[2] - w[2] * h_[1], w[2] * h_[0] - w[0] * h_[2],
                         w[0] * h_[1] - w[1] * h_[0]};
    // m(W x H) summed over its components, factored: (|h1| + |h2|) m(w0) + ...
    const double xm = wm[0] * habs_pair_[0] + wm[1] * habs_pair_[1] + wm[2] * habs_pair_[2];
    const double num = x[0] * n[0] + x[1] * n[1] + x[2] * n[2];
    const double num_bound = bound_factor * xm;
    const bool side_certain = (std::abs(den) > den_bound) & (den_bound > min_magnitude);
    const bool facing = den > 0;
    // Any guess of k will do (the bracket is certified); floor without a libm call.
    const double d = num / den;
    // The clamp maps NaN (den = 0) to guess_limit: the conversion below is always defined.
    const double q = (std::max)(-guess_limit, (std::min)(guess_limit, d * inverse_s_));
    long long k = static_cast<long long>(q);
    k -= q < double(k) ? 1 : 0;
    const double ms0 = double(k) * s_, ms1 = double(k + 1) * s_;
    const double e0 = num - ms0 * den, e1 = num - ms1 * den;
    const double b0 = num_bound + std::abs(ms0) * den_bound,
                 b1 = num_bound + std::abs(ms1) * den_bound;
    // Bitwise on 0/1 integers: all tests are evaluated, without branches.
    auto bit = [](bool b) { return unsigned(b); };
    const unsigned bracket = bit(std::abs(e0) > b0) & bit(std::abs(e1) > b1) &
                             bit(b0 > min_magnitude) & bit(b1 > min_magnitude) &
                             bit(b0 < infinity) & bit(b1 < infinity) & bit((e0 > 0) == facing) &
                             bit((e1 > 0) != facing) & bit(std::abs(d * inverse_s_) < guess_limit);
    const unsigned turned_away = bit(facing_side_only) & bit(!facing);
    if (!(bit(side_certain) & (turned_away | bracket)))
      return false;
    result.k = k;
    result.d = d;
    result.facing = facing;
    result.turned_away = turned_away;
    return true;
  }

#ifdef CGAL_HIGHLIGHT_LINES_TWO_LANES
  // classify_common_case() for the Lanes vertices v, v + 1, ... at once, in the lanes of
  // vectors (two: SSE2; four: AVX2, see classify_vertices()): the same operations on the same
  // doubles, hence the same results, in about 1 / Lanes of the instructions (the pass is bound
  // by them). floor(q) is taken as r - (r > q) with r = q rounded to an integer by adding and
  // subtracting 1.5 * 2^52 (exact for |q| <= 2^49, in any rounding mode r is floor(q) or
  // ceil(q)). Bit i of the result: lane i is a common case. No multiply-add is contracted: the
  // AVX2 caller does not enable FMA.
  template <int Lanes_count>
  BOOST_FORCEINLINE unsigned classify_common_case_lanes(std::size_t v, bool facing_side_only,
                                                        Common_case result[Lanes_count]) const
  {
    typedef typename Lane_vectors<Lanes_count>::Lanes Lanes;
    typedef typename Lane_vectors<Lanes_count>::Masks Masks;
    const double* n = normals_ + 3 * v;
    const double* p = points_ + 3 * v;
    // Broadcasts and loads without helper functions: a function taking or returning an AVX
    // vector is only safe where AVX is enabled.
    Lanes n0, n1, n2, p0, p1, p2, bound_factor;
    Masks magnitude_bits;
    Lanes z0, z1, z2, a0, a1, a2, aabs0, aabs1, aabs2, h0, h1, h2, hp0, hp1, hp2, zabs_sum,
        inverse_s, s, zero, one, min_mag, inf, limit, minus_limit, shift;
    for (int i = 0; i < Lanes_count; ++i) {
      n0[i] = n[3 * i];
      n1[i] = n[3 * i + 1];
      n2[i] = n[3 * i + 2];
      p0[i] = p[3 * i];
      p1[i] = p[3 * i + 1];
      p2[i] = p[3 * i + 2];
      bound_factor[i] = bounds_[v + std::size_t(i)];
      magnitude_bits[i] = 0x7fffffffffffffffLL;
      z0[i] = z_[0];
      z1[i] = z_[1];
      z2[i] = z_[2];
      a0[i] = a_[0];
      a1[i] = a_[1];
      a2[i] = a_[2];
      aabs0[i] = std::abs(a_[0]);
      aabs1[i] = std::abs(a_[1]);
      aabs2[i] = std::abs(a_[2]);
      h0[i] = h_[0];
      h1[i] = h_[1];
      h2[i] = h_[2];
      hp0[i] = habs_pair_[0];
      hp1[i] = habs_pair_[1];
      hp2[i] = habs_pair_[2];
      zabs_sum[i] = zabs_sum_;
      inverse_s[i] = inverse_s_;
      s[i] = s_;
      zero[i] = 0.0;
      one[i] = 1.0;
      min_mag[i] = min_magnitude;
      inf[i] = infinity;
      limit[i] = guess_limit;
      minus_limit[i] = -guess_limit;
      shift[i] = rounding_shift;
    }
#define CGAL_HIGHLIGHT_LINES_MAGNITUDE(x) Lanes(Masks(x) & magnitude_bits)
    const Lanes den = z0 * n0 + z1 * n1 + z2 * n2;
    const Lanes den_bound = bound_factor * zabs_sum;
    const Lanes w0 = p0 - a0, w1 = p1 - a1, w2 = p2 - a2;
    const Lanes wm0 = CGAL_HIGHLIGHT_LINES_MAGNITUDE(p0) + aabs0,
                wm1 = CGAL_HIGHLIGHT_LINES_MAGNITUDE(p1) + aabs1,
                wm2 = CGAL_HIGHLIGHT_LINES_MAGNITUDE(p2) + aabs2;
    const Lanes x0 = w1 * h2 - w2 * h1, x1 = w2 * h0 - w0 * h2, x2 = w0 * h1 - w1 * h0;
    const Lanes xm = wm0 * hp0 + wm1 * hp1 + wm2 * hp2;
    const Lanes num = x0 * n0 + x1 * n1 + x2 * n2;
    const Lanes num_bound = bound_factor * xm;
    const Masks side_certain =
        (CGAL_HIGHLIGHT_LINES_MAGNITUDE(den) > den_bound) & (den_bound > min_mag);
    const Masks facing = den > zero;
    const Lanes d = num / den;
    const Lanes scaled = d * inverse_s;
    // std::min(guess_limit, x) and std::max(-guess_limit, x), NaN to guess_limit alike.
    const Lanes below = (scaled < limit) ? scaled : limit;
    const Lanes q = (minus_limit < below) ? below : minus_limit;
    const Lanes rounded = (q + shift) - shift;
    const Lanes k = rounded - ((rounded > q) ? one : zero);
    const Lanes ms0 = k * s, ms1 = (k + one) * s;
    const Lanes e0 = num - ms0 * den, e1 = num - ms1 * den;
    const Lanes b0 = num_bound + CGAL_HIGHLIGHT_LINES_MAGNITUDE(ms0) * den_bound,
                b1 = num_bound + CGAL_HIGHLIGHT_LINES_MAGNITUDE(ms1) * den_bound;
    const Masks bracket = (CGAL_HIGHLIGHT_LINES_MAGNITUDE(e0) > b0) &
                          (CGAL_HIGHLIGHT_LINES_MAGNITUDE(e1) > b1) & (b0 > min_mag) &
                          (b1 > min_mag) & (b0 < inf) & (b1 < inf) & ~((e0 > zero) ^ facing) &
                          ((e1 > zero) ^ facing) & (CGAL_HIGHLIGHT_LINES_MAGNITUDE(scaled) < limit);
#undef CGAL_HIGHLIGHT_LINES_MAGNITUDE
    const Masks turned_away = facing_side_only ? ~facing : (facing & ~facing);
    const Masks common = side_certain & (turned_away | bracket);
    unsigned found = 0;
    for (int i = 0; i < Lanes_count; ++i) {
      result[i].k = static_cast<long long>(k[i]);
      result[i].d = d[i];
      result[i].facing = facing[i] != 0;
      result[i].turned_away = turned_away[i] != 0;
      found |= unsigned(common[i] != 0) << i;
    }
    return found;
  }
#endif

private:
  static constexpr double rounding_shift = 6755399441055744.0; // 1.5 * 2^52
  static constexpr double guess_limit = double(1LL << 49);
  static constexpr double infinity = std::numeric_limits<double>::infinity();

  // Every case: certain signs from the static bound where it suffices, intervals and exact
  // arithmetic otherwise.
  Vertex_level classify_in_general(int v, Classification_statistics& stats,
                                   bool facing_side_only) const
  {
    Vertex_level result;
    const double* n = &vn_.normal[3 * std::size_t(v)];
    // The bounds use max_k m(Ñ)_k (folded into vn_.bound with the depth) instead of the
    // components of m(Ñ): looser by at most a factor 3, one value read per vertex.
    Terms t;
    t.bound_factor = vn_.bound[std::size_t(v)]; // NaN: take the exact path
    t.den = z_[0] * n[0] + z_[1] * n[1] + z_[2] * n[2];
    t.den_bound = t.bound_factor * zabs_sum_;

    // Side of the light plane the normal points to.
    if (std::abs(t.den) > t.den_bound && t.den_bound > min_magnitude)
      result.normal_side = t.den > 0 ? 1 : -1;
    else {
      ++stats.static_filter_failures;
      result.normal_side = signed_char(exact_sign(v, nullptr, stats));
      if (result.normal_side == 0)
        return result;
    }
    if (facing_side_only && result.normal_side < 0) {
      result.turned_away = true; // the position is not even read
      return result;
    }

    const double* p = lm_.point(v);
    const double w[3] = {p[0] - a_[0], p[1] - a_[1], p[2] - a_[2]};
    const double wm[3] = {std::abs(p[0]) + std::abs(a_[0]), std::abs(p[1]) + std::abs(a_[1]),
                          std::abs(p[2]) + std::abs(a_[2])};
    const double x[3] = {w[1] * h_[2] - w[2] * h_[1], w[2] * h_[0] - w[0] * h_[2],
                         w[0] * h_[1] - w[1] * h_[0]};
    const double xm = (wm[1] * habs_[2] + wm[2] * habs_[1]) +
                      (wm[2] * habs_[0] + wm[0] * habs_[2]) + (wm[0] * habs_[1] + wm[1] * habs_[0]);
    t.num = x[0] * n[0] + x[1] * n[1] + x[2] * n[2];
    t.num_bound = t.bound_factor * xm;

    // Find k with d - k·s >= 0 > d - (k+1)·s, deciding every comparison exactly. The double
    // estimate q is almost always right (two evaluations); where it is not (the double Ñ was
    // inaccurate), a galloping search and a bisection find k from the exact signs alone.
    const double d = t.num / t.den;
    const double q = d / s_;
    const long long limit = 1LL << 50; // beyond: normal almost parallel to S, levels unusable
    auto sign_of_d_minus = [&](long long m) { // sign(d - m·s)
      return result.normal_side * sign_of_E(v, t, m, stats);
    };
    long long k = std::isfinite(q) ? static_cast<long long>(std::floor((std::max)(
                                         -double(limit), (std::min)(double(limit - 1), q))))
                                   : 0;
    long long lo, hi; // sign(d - lo·s) >= 0 > sign(d - hi·s)
    int sign_at_lo;
    const int sign_at_k = sign_of_d_minus(k);
    if (sign_at_k >= 0) {
      lo = k;
      sign_at_lo = sign_at_k;
      hi = k + 1;
      for (long long step = 2;; step *= 2) {
        const int sign_at_hi = sign_of_d_minus(hi);
        if (sign_at_hi < 0)
          break;
        if (hi >= limit) {
          result.out_of_range = true;
          return result;
        }
        lo = hi;
        sign_at_lo = sign_at_hi;
        hi = (std::min)(k + step, limit);
      }
    } else {
      hi = k;
      lo = k - 1;
      for (long long step = 2;; step *= 2) {
        sign_at_lo = sign_of_d_minus(lo);
        if (sign_at_lo >= 0)
          break;
        if (lo <= -limit) {
          result.out_of_range = true;
          return result;
        }
        hi = lo;
        lo = (std::max)(k - step, -limit);
      }
    }
    while (hi - lo > 1) {
      const long long mid = lo + (hi - lo) / 2;
      const int sign_at_mid = sign_of_d_minus(mid);
      if (sign_at_mid >= 0) {
        lo = mid;
        sign_at_lo = sign_at_mid;
      } else {
        hi = mid;
      }
    }
    k = lo;
    result.on_level = sign_at_lo == 0;
    result.level = k;
    result.distance = result.on_level ? double(k) * s_ : (std::isfinite(d) ? d : double(k) * s_);
    return result;
  }

private:
  static constexpr double min_magnitude = 1e-250; // below it, underflow voids the bounds

  // Sign of E(m) for vertex v, whose terms are t.
  int sign_of_E(int v, const Terms& t, long long m, Classification_statistics& stats) const
  {
    const double ms = double(m) * s_;
    const double e = t.num - ms * t.den;
    const double bound = t.num_bound + std::abs(ms) * t.den_bound;
    if (std::abs(e) > bound && bound > min_magnitude && std::isfinite(bound))
      return e > 0 ? 1 : -1;
    ++stats.static_filter_failures;
    return exact_sign(v, &m, stats);
  }

  // Sign of E(*m), or of Z·Ñ if m is null: interval filter, then exact.
  int exact_sign(int v, const long long* m, Classification_statistics& stats) const
  {
    {
      CGAL::Protect_FPU_rounding<true> protection;
      const CGAL::Uncertain<CGAL::Sign> sign =
          CGAL::sign(evaluate<CGAL::Interval_nt_advanced>(v, m));
      if (CGAL::is_certain(sign))
        return int(CGAL::get_certain(sign));
    }
    ++stats.interval_filter_failures;
    typedef typename CGAL::internal::Exact_ring_selector<double>::Type Exact;
    return int(CGAL::sign(evaluate<Exact>(v, m)));
  }

  template <typename NT>
  NT evaluate(int v, const long long* m) const
  {
    const std::array<NT, 3> n = unnormalized_vertex_normal<NT>(lm_, v);
    const NT den = NT(z_[0]) * n[0] + NT(z_[1]) * n[1] + NT(z_[2]) * n[2];
    if (m == nullptr)
      return den;
    const double* p = lm_.point(v);
    const NT w[3] = {NT(p[0]) - NT(a_[0]), NT(p[1]) - NT(a_[1]), NT(p[2]) - NT(a_[2])};
    const NT x[3] = {w[1] * NT(h_[2]) - w[2] * NT(h_[1]), w[2] * NT(h_[0]) - w[0] * NT(h_[2]),
                     w[0] * NT(h_[1]) - w[1] * NT(h_[0])};
    const NT num = x[0] * n[0] + x[1] * n[1] + x[2] * n[2];
    // m·s formed in NT: |m| < 2^50 converts to double exactly.
    return num - (NT(double(*m)) * NT(s_)) * den;
  }

  typedef signed char signed_char;

  const Local_mesh<TriangleMesh>& lm_;
  const Vertex_normals& vn_;
  // The arrays of the common case, read without going through the containers.
  const double *points_, *normals_, *bounds_;
  std::array<double, 3> a_, h_, z_;
  double s_;
  std::array<double, 3> habs_;
  double zabs_sum_;
  double inverse_s_;
  std::array<double, 3> habs_pair_;
};

// A compact key of a vertex class, so that the hot loops over edges and faces read 8 bytes
// per vertex and nothing else: for a defined vertex, its band
//   b = 2k + 1 when k·s < d < (k+1)·s,  b = 2k when d = k·s  (|b| <= 2^51 + 1),
// plus key_side_offset when its normal points away from the light plane (Z·Ñ < 0); an odd
// sentinel when d is undefined. Hence: equal keys have no level strictly between them; the
// parity is that of the band (odd: strictly inside a band); two ends of an edge see the light
// plane from the same side iff their keys lie on the same side of key_side_offset / 2.

inline long long level_key(const Vertex_level& l)
{
  // The sentinel is odd: faces and edges with undefined ends take the quick rejections.
  if (!l.defined())
    return undefined_key;
  return 2 * (long long)(l.level) + (l.on_level ? 0 : 1) +
         (l.normal_side < 0 ? key_side_offset : 0);
}

// The band of a defined key (see level_key()).
inline long long key_band(long long key)
{
  return key > key_side_offset / 2 ? key - key_side_offset : key;
}

// Whether d is continuous along an edge whose ends have these keys: both defined, with the
// same side of the light plane.
inline bool keys_usable(long long a, long long b)
{
  return a != undefined_key && b != undefined_key &&
         (a > key_side_offset / 2) == (b > key_side_offset / 2);
}

// The level k of a band: floor(b / 2).
inline long long band_level(long long band)
{
  return band >> 1;
}

// Sign of d - m·s for a vertex of band b.
inline int compare_band_to_level(long long band, long long m)
{
  return band > 2 * m ? 1 : (band < 2 * m ? -1 : 0);
}

#ifdef CGAL_HIGHLIGHT_LINES_TWO_LANES
// Classifies the vertices [v, e) Lanes_count at a time while at least Lanes_count remain
// (Level_classifier::classify_common_case_lanes(), store(v, common case) for its common cases,
// in_general(v) for the others); returns the first vertex left.
template <int Lanes_count, typename Classifier, typename Store, typename InGeneral>
BOOST_FORCEINLINE std::size_t classify_lanes(const Classifier& classifier, std::size_t v,
                                             std::size_t e, bool facing_side_only,
                                             const Store& store, const InGeneral& in_general)
{
  for (; v + Lanes_count <= e; v += Lanes_count) {
    typename Classifier::Common_case common[Lanes_count];
    const unsigned found =
        classifier.template classify_common_case_lanes<Lanes_count>(v, facing_side_only, common);
    if (found == (1u << Lanes_count) - 1) {
      for (int i = 0; i < Lanes_count; ++i)
        store(v + std::size_t(i), common[i]);
      continue;
    }
    for (int i = 0; i < Lanes_count; ++i) {
      if (found & (1u << i))
        store(v + std::size_t(i), common[i]);
      else
        in_general(v + std::size_t(i));
    }
  }
  return v;
}
#endif

#ifdef CGAL_HIGHLIGHT_LINES_FOUR_LANES
// Whether the processor (and the system) supports AVX2.
inline bool has_four_lanes()
{
  static const bool avx2 = __builtin_cpu_supports("avx2") != 0;
  return avx2;
}

// classify_lanes<4>() compiled for AVX2 (without FMA: no multiply-add is contracted, the
// results are those of the other paths); only where has_four_lanes().
template <typename Classifier, typename Store, typename InGeneral>
__attribute__((target("avx2"))) std::size_t
classify_four_at_a_time(const Classifier& classifier, std::size_t v, std::size_t e,
                        bool facing_side_only, const Store& store, const InGeneral& in_general)
{
  return classify_lanes<4>(classifier, v, e, facing_side_only, store, in_general);
}
#endif

// What a sweep's classification pass gathers besides the classes.
struct Classification_summary
{
  std::size_t undefined = 0;    // Z·Ñ = 0
  std::size_t out_of_range = 0; // |d/s| >= 2^50
  std::vector<int> on_level;    // defined vertices with d = k·s exactly, increasing
};

// Classifies the vertices [0, nv) in one pass: their keys, d values (the distance of
// Vertex_level) and, if `levels` is not null, their classes; concurrently over blocks of
// vertices with a parallel tag, with the same result.
template <typename ConcurrencyTag, typename TriangleMesh>
void classify_vertices(const Level_classifier<TriangleMesh>& classifier, std::size_t nv,
                       bool facing_side_only, std::vector<Vertex_level>* levels,
                       std::vector<long long>& keys, std::vector<double>& distances,
                       Classification_summary& summary, Classification_statistics& stats)
{
  if (levels != nullptr)
    levels->resize(nv);
  keys.resize(nv);
  distances.resize(nv);
  const Chunks chunks = chunks_for<ConcurrencyTag>(nv, std::size_t(1) << 14);
  struct Part
  {
    Classification_statistics stats;
    std::size_t undefined = 0, out_of_range = 0;
    std::vector<int> on_level;
  };
  std::vector<Part> parts(chunks.size());
  for_each_chunk<ConcurrencyTag>(chunks, [&](std::size_t c, std::size_t b, std::size_t e) {
    Part& part = parts[c];
    // Copies local to the pass: the stores into keys and distances cannot alias its
    // constants (the lights, the arrays and the options), which then stay in registers.
    const Level_classifier<TriangleMesh> local_classifier = classifier;
    const bool local_facing_side_only = facing_side_only;
    Vertex_level* const level_out = levels != nullptr ? levels->data() : nullptr;
    long long* const key_out = keys.data();
    double* const distance_out = distances.data();
    auto store_common_case = [&](std::size_t v,
                                 const typename Level_classifier<TriangleMesh>::Common_case& c) {
      // Strictly inside a band, or turned away: no vertex node, defined or not counted.
      if (level_out != nullptr)
        level_out[v] = c.level();
      key_out[v] = c.key();
      distance_out[v] = c.turned_away ? 0.0 : c.d;
    };
    auto classify_in_general = [&](std::size_t v) {
      const Vertex_level l = classifier.classify(int(v), part.stats, facing_side_only);
      if (level_out != nullptr)
        level_out[v] = l;
      const long long key = level_key(l);
      key_out[v] = key;
      distance_out[v] = l.distance;
      if (!(key & 1))
        part.on_level.push_back(int(v)); // even keys: defined, on a level
      part.undefined += l.normal_side == 0;
      part.out_of_range += l.out_of_range;
    };
    std::size_t v = b;
#ifdef CGAL_HIGHLIGHT_LINES_FOUR_LANES
    if (has_four_lanes())
      v = classify_four_at_a_time(local_classifier, v, e, local_facing_side_only, store_common_case,
                                  classify_in_general);
#endif
#ifdef CGAL_HIGHLIGHT_LINES_TWO_LANES
    v = classify_lanes<2>(local_classifier, v, e, local_facing_side_only, store_common_case,
                          classify_in_general);
#endif
    for (; v < e; ++v) {
      typename Level_classifier<TriangleMesh>::Common_case common;
      if (local_classifier.classify_common_case(int(v), local_facing_side_only, common))
        store_common_case(v, common);
      else
        classify_in_general(v);
    }
  });
  summary.undefined = summary.out_of_range = 0;
  summary.on_level.clear();
  for (Part& part : parts) {
    stats.static_filter_failures += part.stats.static_filter_failures;
    stats.interval_filter_failures += part.stats.interval_filter_failures;
    summary.undefined += part.undefined;
    summary.out_of_range += part.out_of_range;
    summary.on_level.insert(summary.on_level.end(), part.on_level.begin(), part.on_level.end());
  }
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_MODEL_LEVEL_CLASSIFICATION_H

// §3.2, desired highlight lines: the OGH curve, its arc-length parameterisation and the
// two-segment fallback.
#include <CGAL/Highlight_lines/internal/fairing/ogh_curve.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {
using namespace CGAL::Highlight_lines::internal;
using namespace CGAL::Highlight_lines::internal::vector3;

const double pi = std::acos(-1.0);

double distance(const Vec3& a, const Vec3& b)
{
  return norm(a - b);
}
Vec3 unit(const Vec3& a)
{
  return (1 / norm(a)) * a;
}

Vec3 random_vector(std::mt19937& rng, double range = 1)
{
  std::uniform_real_distribution<double> u(-range, range);
  return {u(rng), u(rng), u(rng)};
}

// Tangent directions within `max_angle` of the chord, in a random plane-free 3D configuration.
struct Configuration
{
  Vec3 q0, t0, q1, t1;
};

Configuration random_configuration(std::mt19937& rng, double max_angle)
{
  Configuration c;
  c.q0 = random_vector(rng, 3);
  c.q1 = c.q0 + random_vector(rng, 2);
  const Vec3 chord = unit(c.q1 - c.q0);
  auto tilted = [&](double length) {
    // chord rotated by an angle below max_angle towards a random perpendicular direction.
    Vec3 r = random_vector(rng);
    r = unit(r - dot(r, chord) * chord);
    const double angle = std::uniform_real_distribution<double>(0, max_angle)(rng);
    return length * (std::cos(angle) * chord + std::sin(angle) * r);
  };
  c.t0 = tilted(0.3);
  c.t1 = tilted(4.0);
  return c;
}

// Arc length of H over [0, t], from polylines of n and 2n chords, Richardson-extrapolated
// (chord sums converge as h²): independent of the Gauss–Legendre table of the class.
double polyline_length(const Ogh_curve& h, double t, int n)
{
  auto chords = [&](int m) {
    double sum = 0;
    Vec3 previous = h.point(0);
    for (int i = 1; i <= m; ++i) {
      const Vec3 p = h.point(t * i / m);
      sum += distance(p, previous);
      previous = p;
    }
    return sum;
  };
  const double coarse = chords(n), fine = chords(2 * n);
  return (4 * fine - coarse) / 3;
}

bool segments_cross_2d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  auto side = [](const Vec3& o, const Vec3& p, const Vec3& q) {
    return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0]);
  };
  return side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0;
}

TEST(OghCurve, InterpolatesEndPointsAndEndTangentDirections)
{
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    const Configuration c = random_configuration(rng, pi / 3);
    const Ogh_curve h(c.q0, c.t0, c.q1, c.t1);
    ASSERT_EQ(h.status(), Ogh_curve_status::OK);
    ASSERT_TRUE(h.keeps_tangent_directions());
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(h.point(0)[a], c.q0[a], 1e-14);
      EXPECT_NEAR(h.point(1)[a], c.q1[a], 1e-14);
      // H'(0) = a0 T0, H'(1) = a1 T1 with unit T0, T1 along the given tangents.
      EXPECT_NEAR(h.derivative(0)[a], h.a0() * unit(c.t0)[a], 1e-12);
      EXPECT_NEAR(h.derivative(1)[a], h.a1() * unit(c.t1)[a], 1e-12);
      EXPECT_NEAR(h.t0()[a], unit(c.t0)[a], 1e-15);
      EXPECT_NEAR(h.t1()[a], unit(c.t1)[a], 1e-15);
      // derivative() is the derivative of point(): second-order one-sided differences.
      const double e = 1e-5;
      const double d0 = (-3 * h.point(0)[a] + 4 * h.point(e)[a] - h.point(2 * e)[a]) / (2 * e);
      const double d1 =
          (3 * h.point(1)[a] - 4 * h.point(1 - e)[a] + h.point(1 - 2 * e)[a]) / (2 * e);
      EXPECT_NEAR(d0, h.derivative(0)[a], 1e-8);
      EXPECT_NEAR(d1, h.derivative(1)[a], 1e-8);
      const double dm = (h.point(0.3 + e)[a] - h.point(0.3 - e)[a]) / (2 * e);
      EXPECT_NEAR(dm, h.derivative(0.3)[a], 1e-8);
    }
  }
}

// The defining property of OGH (Yong & Cheng): a0, a1 minimise the strain energy ∫‖H''‖².
// The energy is evaluated here on the Bézier form of the cubic (control points Q0, Q0 + a0T0/3,
// Q1 - a1T1/3, Q1) with Simpson's rule (exact: ‖H''‖² is quadratic in t), and minimised by
// solving for the stationary point from central differences (exact: the energy is quadratic).
TEST(OghCurve, CoefficientsMinimiseTheStrainEnergy)
{
  std::mt19937 rng(11);
  for (int trial = 0; trial < 50; ++trial) {
    const Configuration c = random_configuration(rng, pi);
    const Ogh_curve h(c.q0, c.t0, c.q1, c.t1);
    ASSERT_EQ(h.status(), Ogh_curve_status::OK);
    const Vec3 u0 = unit(c.t0), u1 = unit(c.t1);
    auto strain_energy = [&](double a0, double a1) {
      const Vec3 p0 = c.q0, p1 = c.q0 + (a0 / 3) * u0, p2 = c.q1 - (a1 / 3) * u1, p3 = c.q1;
      const Vec3 first = p2 - 2 * p1 + p0, second = p3 - 2 * p2 + p1;
      auto squared_second_derivative = [&](double t) {
        const Vec3 b = 6 * ((1 - t) * first + t * second);
        return dot(b, b);
      };
      return (squared_second_derivative(0) + 4 * squared_second_derivative(0.5) +
              squared_second_derivative(1)) /
             6;
    };
    const double e0 = strain_energy(0, 0);
    const double g0 = (strain_energy(1, 0) - strain_energy(-1, 0)) / 2;
    const double g1 = (strain_energy(0, 1) - strain_energy(0, -1)) / 2;
    const double h00 = strain_energy(1, 0) - 2 * e0 + strain_energy(-1, 0);
    const double h11 = strain_energy(0, 1) - 2 * e0 + strain_energy(0, -1);
    const double h01 = (strain_energy(1, 1) - strain_energy(1, -1) - strain_energy(-1, 1) +
                        strain_energy(-1, -1)) /
                       4;
    const double det = h00 * h11 - h01 * h01;
    const double a0 = -(h11 * g0 - h01 * g1) / det, a1 = -(h00 * g1 - h01 * g0) / det;
    const double scale_of_a = distance(c.q0, c.q1);
    EXPECT_NEAR(h.a0(), a0, 1e-9 * scale_of_a);
    EXPECT_NEAR(h.a1(), a1, 1e-9 * scale_of_a);
    // And it is a minimum, not only stationary.
    EXPECT_GT(h00, 0);
    EXPECT_GT(det, 0);
  }
}

TEST(OghCurve, LengthsOfTheGivenTangentsDoNotMatter)
{
  std::mt19937 rng(3);
  const Configuration c = random_configuration(rng, pi / 2);
  const Ogh_curve h(c.q0, c.t0, c.q1, c.t1);
  const Ogh_curve g(c.q0, 17 * c.t0, c.q1, 1e-3 * c.t1);
  for (double t = 0; t <= 1; t += 0.125)
    EXPECT_LT(distance(h.point(t), g.point(t)), 1e-14 * (1 + norm(c.q0)));
}

TEST(OghCurve, StraightConfigurationIsTheUniformlyParameterisedSegment)
{
  const Vec3 q0{1, -2, 0.5}, q1{4, 2, -0.5};
  const Vec3 d = q1 - q0;
  const Ogh_curve h(q0, 0.1 * d, q1, 3 * d);
  ASSERT_TRUE(h.keeps_tangent_directions());
  EXPECT_NEAR(h.a0(), norm(d), 1e-14 * norm(d));
  EXPECT_NEAR(h.a1(), norm(d), 1e-14 * norm(d));
  EXPECT_NEAR(h.length(), norm(d), 1e-13 * norm(d));
  for (double s = 0; s <= 1; s += 1.0 / 64) {
    const Vec3 expected = q0 + s * d;
    EXPECT_LT(distance(h.point_at_arc_length_fraction(s), expected), 1e-12 * norm(d)) << s;
    EXPECT_LT(distance(h.point(s), expected), 1e-14 * norm(d)) << s;
  }
}

// A circular arc of angle θ with its true end tangents: the OGH curve stays close to the circle,
// closer and closer (better than third order) as the arc gets shorter, and its arc-length
// parameterisation advances uniformly in angle.
TEST(OghCurve, CircularArcConfigurationStaysCloseToTheCircle)
{
  auto deviations = [](double theta, double& radial, double& angular) {
    const Vec3 q0{1, 0, 0}, q1{std::cos(theta), std::sin(theta), 0};
    const Vec3 t0{0, 1, 0}, t1{-std::sin(theta), std::cos(theta), 0};
    const Ogh_curve h(q0, t0, q1, t1);
    EXPECT_TRUE(h.keeps_tangent_directions());
    radial = angular = 0;
    for (int i = 0; i <= 200; ++i) {
      const double s = i / 200.0;
      const Vec3 p = h.point_at_arc_length_fraction(s);
      radial = (std::max)(radial, std::abs(norm(p) - 1));
      angular = (std::max)(angular, std::abs(std::atan2(p[1], p[0]) - s * theta));
    }
    EXPECT_NEAR(h.length(), theta, 2 * radial * theta + 1e-12);
  };
  double radial60, angular60, radial30, angular30;
  deviations(pi / 3, radial60, angular60);
  deviations(pi / 6, radial30, angular30);
  // Measured: 4.1e-3 and 3.4e-4 at 60°, 2.1e-4 and 8.6e-6 at 30° (fourth and fifth order).
  EXPECT_LT(radial60, 5e-3);
  EXPECT_LT(angular60, 5e-4);
  EXPECT_LT(radial30, radial60 / 12);
  EXPECT_LT(angular30, angular60 / 12);
}

TEST(OghCurve, ArcLengthFractionIsMonotoneAndMatchesIntegratedLength)
{
  std::mt19937 rng(5);
  std::vector<Configuration> cases;
  for (int i = 0; i < 6; ++i)
    cases.push_back(random_configuration(rng, pi / 2));
  // Nearly perpendicular start: small a0, the speed has a sharp minimum near t = 0.
  cases.push_back({{0, 0, 0}, {0.2, 1, 0}, {1, 0, 0}, {1, 0.2, 0}});
  ASSERT_LT(Ogh_curve(cases.back().q0, cases.back().t0, cases.back().q1, cases.back().t1).a0(),
            0.05);
  for (const Configuration& c : cases) {
    const Ogh_curve h(c.q0, c.t0, c.q1, c.t1);
    ASSERT_EQ(h.status(), Ogh_curve_status::OK);
    const double length = polyline_length(h, 1, 20000);
    EXPECT_NEAR(h.length(), length, 1e-9 * length);
    double previous = -1;
    for (int i = 0; i <= 40; ++i) {
      const double s = i / 40.0;
      const double t = h.parameter_at_arc_length_fraction(s);
      EXPECT_GT(t, previous);
      previous = t;
      EXPECT_NEAR(polyline_length(h, t, 20000), s * h.length(), 1e-9 * h.length()) << s;
      const Vec3 p = h.point_at_arc_length_fraction(s), q = h.point(t);
      EXPECT_EQ(p, q);
    }
    EXPECT_EQ(h.parameter_at_arc_length_fraction(0), 0);
    EXPECT_EQ(h.parameter_at_arc_length_fraction(1), 1);
  }
}

// An S-shaped configuration: leaving perpendicular to the chord, arriving at 45°. The single OGH
// curve would start backwards (a0 < 0); the two-segment spline keeps all directions.
TEST(OghTarget, SShapeFallsBackToTwoSegmentsJoinedG1)
{
  const Vec3 q0{0, 0, 0}, q1{1, 0, 0}, t0{0, 1, 0}, t1{1, 1, 0};
  const Ogh_curve whole(q0, t0, q1, t1);
  ASSERT_EQ(whole.status(), Ogh_curve_status::OK);
  EXPECT_LT(whole.a0(), 0);
  EXPECT_FALSE(whole.keeps_tangent_directions());

  const Ogh_target target = make_ogh_target(q0, t0, q1, t1);
  ASSERT_EQ(target.status, Ogh_target::Status::TWO_SEGMENTS);
  ASSERT_EQ(target.segments.size(), 2u);
  const Ogh_curve& first = target.segments[0];
  const Ogh_curve& second = target.segments[1];
  EXPECT_TRUE(first.keeps_tangent_directions());
  EXPECT_TRUE(second.keeps_tangent_directions());
  EXPECT_EQ(first.q0(), q0);
  EXPECT_EQ(second.q1(), q1);
  EXPECT_EQ(first.q1(), second.q0());
  // The joint is the middle of the cubic Hermite curve with chord-length end tangents.
  const double chord = distance(q0, q1);
  const Vec3 hermite_middle = 0.5 * (q0 + q1) + (chord / 8) * (unit(t0) - unit(t1));
  EXPECT_LT(distance(first.q1(), hermite_middle), 1e-15);
  EXPECT_LT(distance(first.t0(), unit(t0)), 1e-15);
  EXPECT_LT(distance(second.t1(), unit(t1)), 1e-15);
  // G1: the same unit tangent, same orientation, on both sides of the joint.
  EXPECT_LT(distance(unit(first.derivative(1)), unit(second.derivative(0))), 1e-14);
  EXPECT_NEAR(target.length(), first.length() + second.length(), 1e-15);
  // The whole-target parameterisation runs through the joint at the right fraction.
  const double joint = first.length() / target.length();
  EXPECT_LT(distance(target.point_at_arc_length_fraction(joint), first.q1()), 1e-12);
  EXPECT_LT(distance(target.point_at_arc_length_fraction(0), q0), 1e-15);
  EXPECT_LT(distance(target.point_at_arc_length_fraction(1), q1), 1e-15);
  // Equal arc-length steps give equal chords, up to curvature: no jump at the joint.
  for (int i = 1; i <= 100; ++i) {
    const double step = distance(target.point_at_arc_length_fraction(i / 100.0),
                                 target.point_at_arc_length_fraction((i - 1) / 100.0));
    EXPECT_LE(step, target.length() / 100 * (1 + 1e-12));
    EXPECT_GT(step, 0.9 * target.length() / 100);
  }
}

TEST(OghTarget, LineTurningBackHasNoTarget)
{
  const Vec3 q0{0, 0, 0}, q1{1, 0, 0}, back{-1, 0.1, 0};
  const Ogh_target target = make_ogh_target(q0, back, q1, back);
  EXPECT_EQ(target.status, Ogh_target::Status::NONE);
  EXPECT_EQ(target.input_status, Ogh_curve_status::OK);
  EXPECT_TRUE(target.segments.empty());
}

TEST(OghTarget, GentleConfigurationIsASingleSegment)
{
  std::mt19937 rng(13);
  for (int trial = 0; trial < 20; ++trial) {
    const Configuration c = random_configuration(rng, pi / 4);
    const Ogh_target target = make_ogh_target(c.q0, c.t0, c.q1, c.t1);
    ASSERT_EQ(target.status, Ogh_target::Status::SINGLE_SEGMENT);
    const Ogh_curve h(c.q0, c.t0, c.q1, c.t1);
    for (double s = 0; s <= 1; s += 0.1)
      EXPECT_EQ(target.point_at_arc_length_fraction(s), h.point_at_arc_length_fraction(s));
  }
}

// Random planar configurations with tangents in every direction: every target that is produced
// is free of self-intersections, of zero speed and of tangent reversals (sampled), and all three
// outcomes occur.
TEST(OghTarget, TargetsNeverLoopNorReverse)
{
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> angle(-pi, pi);
  int count[3] = {0, 0, 0};
  for (int trial = 0; trial < 1500; ++trial) {
    const double a = angle(rng), b = angle(rng);
    const Vec3 q0{0, 0, 0}, q1{1, 0.3, 0};
    const Ogh_target target =
        make_ogh_target(q0, {std::cos(a), std::sin(a), 0}, q1, {std::cos(b), std::sin(b), 0});
    ++count[int(target.status)];
    if (target.status == Ogh_target::Status::NONE)
      continue;
    std::vector<Vec3> polyline;
    Vec3 previous_tangent{0, 0, 0};
    for (const Ogh_curve& segment : target.segments) {
      ASSERT_TRUE(segment.keeps_tangent_directions());
      for (int i = 0; i <= 200; ++i) {
        const double t = i / 200.0;
        polyline.push_back(segment.point(t));
        const Vec3 tangent = segment.derivative(t);
        ASSERT_GT(norm(tangent), 0) << a << " " << b;
        ASSERT_GE(dot(tangent, previous_tangent), 0) << a << " " << b;
        previous_tangent = tangent;
      }
    }
    for (std::size_t i = 0; i + 1 < polyline.size(); ++i)
      for (std::size_t j = i + 2; j + 1 < polyline.size(); ++j)
        ASSERT_FALSE(segments_cross_2d(polyline[i], polyline[i + 1], polyline[j], polyline[j + 1]))
            << a << " " << b;
  }
  EXPECT_GT(count[int(Ogh_target::Status::SINGLE_SEGMENT)], 0);
  EXPECT_GT(count[int(Ogh_target::Status::TWO_SEGMENTS)], 0);
  EXPECT_GT(count[int(Ogh_target::Status::NONE)], 0);
}

TEST(OghTarget, DegenerateInputGivesAStatusNotNaN)
{
  const Vec3 q0{1, 2, 3}, q1{2, 2, 3}, t{1, 0.5, 0}, zero{0, 0, 0};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case
  {
    Vec3 q0, t0, q1, t1;
    Ogh_curve_status expected;
  };
  const Case cases[] = {
      {q0, zero, q1, t, Ogh_curve_status::ZERO_TANGENT},
      {q0, t, q1, zero, Ogh_curve_status::ZERO_TANGENT},
      {q0, t, q0, t, Ogh_curve_status::COINCIDENT_END_POINTS},
      {q0, t, {1, 2, std::nextafter(3.0, 4.0)}, t, Ogh_curve_status::COINCIDENT_END_POINTS},
      {{nan, 0, 0}, t, q1, t, Ogh_curve_status::NON_FINITE_INPUT},
      {q0, t, q1, {0, inf, 0}, Ogh_curve_status::NON_FINITE_INPUT},
  };
  for (const Case& c : cases) {
    const Ogh_curve h(c.q0, c.t0, c.q1, c.t1);
    EXPECT_EQ(h.status(), c.expected);
    EXPECT_FALSE(h.keeps_tangent_directions());
    EXPECT_EQ(h.length(), 0);
    EXPECT_TRUE(std::isfinite(h.a0()) && std::isfinite(h.a1()));
    const Ogh_target target = make_ogh_target(c.q0, c.t0, c.q1, c.t1);
    EXPECT_EQ(target.status, Ogh_target::Status::NONE);
    EXPECT_EQ(target.input_status, c.expected);
  }
  // Tiny and huge tangents are directions like any other.
  const Ogh_curve reference(q0, t, q1, t);
  for (const double length : {1e-300, 1e-320, 1e300}) {
    const Ogh_curve h(q0, length * t, q1, length * t);
    EXPECT_EQ(h.status(), Ogh_curve_status::OK);
    EXPECT_LT(distance(h.point(0.3), reference.point(0.3)), 1e-14);
  }
  // Parallel and antiparallel tangents are not degenerate: the denominator is >= 3|T0|²|T1|².
  const Ogh_curve parallel(q0, {0, 1, 0}, q1, {0, -2, 0});
  EXPECT_EQ(parallel.status(), Ogh_curve_status::OK);
  EXPECT_TRUE(std::isfinite(parallel.a0()) && std::isfinite(parallel.a1()));
  EXPECT_TRUE(std::isfinite(parallel.point_at_arc_length_fraction(0.5)[0]));
}

} // namespace

// detect_highlight_line_irregularities() and detect_and_fair_highlight_line_irregularities():
// the bending measure, the grouping into regions, recall and precision on seeded injected
// defects, invariances, bad input, and the repair of what was found.
#include "test_meshes.h"

#include "detection_evaluation.h"

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/Highlight_lines/fairing_building_blocks.h>
#include <CGAL/Highlight_lines/grown_face_region.h>
#include <CGAL/Highlight_lines/join_touching_irregularities.h>
#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/detect_and_fair_highlight_line_irregularities.h>
#include <CGAL/detect_highlight_line_irregularities.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <iostream>
#include <limits>
#include <cmath>
#include <map>
#include <random>
#include <set>

namespace {
namespace HB = Highlight_lines_benchmark;
namespace HL = CGAL::Highlight_lines;
namespace HLI = CGAL::Highlight_lines::internal;
namespace HLP = CGAL::Highlight_lines::parameters;
using HLI::vector3::Vec3;

// A flat plate: a regular grid of 40 x 40 cells over [-1, 1]^2.
HB::Mesh flat_plate()
{
  return test::to_mesh<HB::Mesh>(
      test::grid(40, 2.0 / 40, -1, -1, [](double, double) { return 0.0; }));
}

// An irregularly triangulated car hood (jittered grid of 80 x 80 cells over [-1, 1]^2).
HB::Mesh smooth_hood(unsigned seed, int n = 80)
{
  return test::to_mesh<HB::Mesh>(test::grid(n, 2.0 / n, -1, -1, test::hood, 0.3, seed));
}

// The bending measure (`local_residual(false)`, closer to the paper), from all sides.
std::vector<HB::Irregularity> detect_bending(const HB::Mesh& mesh)
{
  std::vector<HB::Irregularity> found;
  CGAL::detect_highlight_line_irregularities(
      mesh, HL::default_light_setup(mesh, HLP::number_of_lines(30)), std::back_inserter(found),
      HLP::local_residual(false));
  return found;
}

// The hoods are height fields under the default lights: the planes on the other sides see
// nothing the top plane does not (their lines crowd where the hood turns away from them and
// are not scored), so the statistical tests on hoods sweep the top plane only, six times faster.
std::vector<HB::Irregularity> detect_bending_from_above(const HB::Mesh& mesh)
{
  std::vector<HB::Irregularity> found;
  CGAL::detect_highlight_line_irregularities(
      mesh, HL::default_light_setup(mesh, HLP::number_of_lines(30)), std::back_inserter(found),
      HLP::local_residual(HLP::all_sides(false), false));
  return found;
}

// The detection with the local residual (the default, issue 16); `all_sides` as given.
std::vector<HB::Irregularity> detect_local_residual(const HB::Mesh& mesh, bool all_sides,
                                                    int scales = 1)
{
  std::vector<HB::Irregularity> found;
  CGAL::detect_highlight_line_irregularities(
      mesh, HL::default_light_setup(mesh, HLP::number_of_lines(30)), std::back_inserter(found),
      HLP::local_residual(HLP::number_of_scales(HLP::all_sides(all_sides), scales), true));
  return found;
}

// The mirror symmetry of a Surface_mesh (its vertices in index order).
std::vector<Vec3> points_of(const HB::Mesh& mesh)
{
  std::vector<Vec3> points;
  for (auto v : vertices(mesh))
    points.push_back(Vec3{mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()});
  return points;
}

std::vector<std::array<int, 3>> faces_of(const HB::Mesh& mesh)
{
  std::vector<std::array<int, 3>> faces;
  for (auto f : CGAL::faces(mesh)) {
    std::array<int, 3> c{};
    std::size_t j = 0;
    for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      c[j++] = int(v);
    faces.push_back(c);
  }
  return faces;
}

struct Mirror_symmetry_of_mesh
{
  explicit Mirror_symmetry_of_mesh(const HB::Mesh& mesh)
      : symmetry(points_of(mesh), faces_of(mesh), test::mean_edge_length(mesh))
  {
  }
  HLI::Mirror_symmetry symmetry;
};

// Recall and precision over seeds 1..8, four defects of radius 5 ē per hood, and how many
// defects a region is located at, for `detect(mesh)`.
struct Hood_tally
{
  HB::Detection_score score;
  std::size_t located = 0;
};

template <typename Detect>
Hood_tally tally_on_hoods(double height_in_edges, Detect detect)
{
  Hood_tally total;
  for (unsigned seed = 1; seed <= 8; ++seed) {
    HB::Mesh mesh = smooth_hood(seed);
    std::vector<HB::Injected_defect> defects;
    if (height_in_edges > 0)
      defects = HB::inject_defects(mesh, 4, 5.0, height_in_edges, seed, [](auto) { return true; });
    const std::vector<HB::Irregularity> found = detect(mesh);
    const HB::Detection_score s = HB::match(mesh, defects, found);
    total.score.defects += s.defects;
    total.score.found_defects += s.found_defects;
    total.score.regions += s.regions;
    total.score.true_regions += s.true_regions;
    for (bool l : HB::located_defects(mesh, defects, found))
      total.located += l;
  }
  return total;
}

HB::Detection_score score_on_hoods(double height_in_edges)
{
  return tally_on_hoods(height_in_edges,
                        [](const HB::Mesh& m) { return detect_bending_from_above(m); })
      .score;
}

// --- The bending measure -------------------------------------------------------------------

std::vector<Vec3> sampled_curve(double length, int n, const std::function<Vec3(double)>& curve)
{
  std::vector<Vec3> points;
  for (int i = 0; i <= n; ++i)
    points.push_back(curve(length * i / n));
  return points;
}

TEST(LineBending, VanishesOnStraightLinesAndCircles)
{
  HLI::Line_bending_scales scales;
  scales.step = 0.05;
  HLI::Line_bending straight, circle;
  HLI::compute_line_bending(sampled_curve(10, 137,
                                          [](double s) {
                                            return Vec3{0.3 * s, 0.4 * s, 1.0};
                                          }),
                            false, scales, straight);
  ASSERT_GT(straight.bending.size(), 30u);
  std::size_t evaluated = 0;
  for (double b : straight.bending)
    if (b >= 0) {
      ++evaluated;
      EXPECT_LT(b, 1e-12);
    }
  EXPECT_EQ(evaluated, straight.bending.size() - 12); // 3w/2 = 6 samples at each end

  // A closed circle of radius 1, finely sampled: curvature is constant, its variation is only
  // the polygon's: far below a bump's.
  std::vector<Vec3> ring;
  for (int i = 0; i < 2000; ++i)
    ring.push_back({std::cos(2 * M_PI * i / 2000), std::sin(2 * M_PI * i / 2000), 0});
  HLI::compute_line_bending(ring, true, scales, circle);
  ASSERT_FALSE(circle.bending.empty());
  for (double b : circle.bending) {
    EXPECT_GE(b, 0);
    EXPECT_LT(b, 1e-4);
  }
}

TEST(LineBending, PeaksAtABumpAndScalesOut)
{
  // A straight line with a small sideways bump of width 0.4 around s = 5.
  auto bumped = [](double scale) {
    return sampled_curve(10 * scale, 500, [scale](double s) {
      const double t = (s / scale - 5) / 0.4;
      return Vec3{s, t * t < 1 ? scale * 0.02 * std::pow(1 - t * t, 3) : 0.0, 0};
    });
  };
  HLI::Line_bending_scales scales;
  scales.step = 0.1;
  HLI::Line_bending bending, scaled;
  HLI::compute_line_bending(bumped(1), false, scales, bending);
  scales.step = 0.1 * 7.5;
  HLI::compute_line_bending(bumped(7.5), false, scales, scaled);
  const auto peak = std::max_element(bending.bending.begin(), bending.bending.end());
  const double peak_s = 0.1 * double(peak - bending.bending.begin());
  EXPECT_NEAR(peak_s, 5.0, 0.4);
  EXPECT_GT(*peak, 0.01);
  // Away from the bump (beyond its width plus the stencil's reach), nothing.
  for (std::size_t i = 0; i < bending.bending.size(); ++i)
    if (std::abs(0.1 * double(i) - 5) > 0.4 + 0.6 + 1e-9 && bending.bending[i] >= 0) {
      EXPECT_LT(bending.bending[i], 1e-12);
    }
  // Dimensionless: scaling curve and step together gives the same values.
  ASSERT_EQ(bending.bending.size(), scaled.bending.size());
  for (std::size_t i = 0; i < bending.bending.size(); ++i)
    EXPECT_NEAR(bending.bending[i], scaled.bending[i], 1e-9);
}

TEST(LineBending, RobustStatisticsIgnoreOutliersAndUnscoredSamples)
{
  std::vector<double> values{1, 2, 3, 4, 5, 1000, -1, -1};
  const HLI::Robust_statistics stats = HLI::robust_statistics(values);
  EXPECT_EQ(stats.count, 6u);
  EXPECT_DOUBLE_EQ(stats.median, 3.5);
  EXPECT_NEAR(stats.deviation, 1.4826 * 1.5, 1e-12);
}

// The lateral residual (local_residual): zero on straight lines, tiny on a wide circle, a
// peak at a sideways bump and nothing beyond the fit's reach, no fit across a break.
TEST(LineResidual, VanishesOnSmoothLinesPeaksAtABumpAndStopsAtBreaks)
{
  HLI::Line_residual_scales scales;
  scales.step = 0.05;
  HLI::Line_residual straight, circle, bumped, kinked, kinked_unbroken;
  HLI::compute_line_residual(sampled_curve(10, 137,
                                           [](double s) {
                                             return Vec3{0.3 * s, 0.4 * s, 1.0};
                                           }),
                             false, scales, straight);
  std::size_t evaluated = 0;
  for (std::size_t i = 0; i < straight.valid.size(); ++i)
    if (straight.valid[i]) {
      ++evaluated;
      EXPECT_LT(HLI::vector3::norm(straight.residual[i]), 1e-12);
    }
  // gap + minimum_side - 1 = 8 samples at each end have too few on one side.
  EXPECT_EQ(evaluated, straight.valid.size() - 16);

  std::vector<Vec3> ring;
  for (int i = 0; i < 4000; ++i)
    ring.push_back({10 * std::cos(2 * M_PI * i / 4000), 10 * std::sin(2 * M_PI * i / 4000), 0});
  HLI::compute_line_residual(ring, true, scales, circle);
  ASSERT_FALSE(circle.valid.empty());
  for (std::size_t i = 0; i < circle.valid.size(); ++i) {
    EXPECT_TRUE(circle.valid[i]);
    EXPECT_LT(HLI::vector3::norm(circle.residual[i]), 1e-5);
  }

  // A sideways bump of height 0.02 and half-width 0.4 around s = 5.
  HLI::compute_line_residual(
      sampled_curve(10, 500,
                    [](double s) {
                      const double t = (s - 5) / 0.4;
                      return Vec3{s, t * t < 1 ? 0.02 * std::pow(1 - t * t, 3) : 0.0, 0};
                    }),
      false, scales, bumped);
  std::size_t peak = 0;
  for (std::size_t i = 0; i < bumped.valid.size(); ++i)
    if (bumped.valid[i] &&
        HLI::vector3::norm(bumped.residual[i]) > HLI::vector3::norm(bumped.residual[peak]))
      peak = i;
  EXPECT_NEAR(0.05 * double(peak), 5.0, 0.1);
  EXPECT_GT(HLI::vector3::norm(bumped.residual[peak]), 0.005);
  for (std::size_t i = 0; i < bumped.valid.size(); ++i)
    if (bumped.valid[i] && std::abs(0.05 * double(i) - 5) > 0.4 + 0.05 * scales.reach + 1e-9) {
      EXPECT_LT(HLI::vector3::norm(bumped.residual[i]), 1e-12);
    }

  // Two straight pieces meeting at a kink at s = 5, the kink's node marked as a break.
  std::vector<Vec3> kink = sampled_curve(10, 200, [](double s) {
    return s < 5 ? Vec3{s, 0, 0} : Vec3{5 + 0.8 * (s - 5), 0.6 * (s - 5), 0};
  });
  std::vector<char> breaks(kink.size(), 0);
  breaks[100] = 1;
  HLI::compute_line_residual(kink, false, scales, kinked, breaks);
  HLI::compute_line_residual(kink, false, scales, kinked_unbroken);
  double largest = 0, largest_unbroken = 0;
  for (std::size_t i = 0; i < kinked.valid.size(); ++i) {
    if (kinked.valid[i])
      largest = (std::max)(largest, HLI::vector3::norm(kinked.residual[i]));
    if (kinked_unbroken.valid[i])
      largest_unbroken =
          (std::max)(largest_unbroken, HLI::vector3::norm(kinked_unbroken.residual[i]));
  }
  EXPECT_LT(largest, 1e-9);
  EXPECT_GT(largest_unbroken, 0.05);
}

// --- Grouping ------------------------------------------------------------------------------

TEST(AnomalyRegions, JoinNearAnomaliesDropWeakOnesAndAddAMargin)
{
  // A strip of 40 x 3 vertices, triangulated.
  const int n = 40;
  std::vector<std::array<int, 3>> faces;
  auto id = [](int i, int j) { return j * n + i; };
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  auto anomaly = [&](int i, std::size_t line, std::size_t setup) {
    HLI::Anomaly a;
    a.vertex = id(i, 1);
    a.line = line;
    a.setup = setup;
    a.score = 10;
    return a;
  };
  // Cluster A (vertices 5 and 7: within 3 rings) seen in two setups; cluster B (vertex 30)
  // in one setup only.
  const std::vector<HLI::Anomaly> anomalies{anomaly(5, 0, 0), anomaly(7, 1, 1), anomaly(30, 2, 0),
                                            anomaly(30, 3, 0)};
  const auto regions = HLI::group_anomalies(faces, 3 * n, anomalies, 3, 1, 2);
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_EQ(regions[0].anomalies, (std::vector<std::size_t>{0, 1}));
  // Columns 5 - 3 - 1 = 1 to 7 + 3 + 1 = 11 are reached: faces of cells 0..11.
  std::set<int> cells;
  for (int f : regions[0].faces)
    cells.insert((f / 2) % (n - 1));
  EXPECT_EQ(*cells.begin(), 0);
  EXPECT_EQ(*cells.rbegin(), 11);

  // With one setup enough, B is a region of its own.
  EXPECT_EQ(HLI::group_anomalies(faces, 3 * n, anomalies, 3, 1, 1).size(), 2u);
}

// --- The bending measure on hoods and shared meshes (the curves are in benchmark_detection) ---

TEST(BendingMeasure, FindsEveryDefectOfAFifthOfAnEdgeLengthAndNothingElse)
{
  const HB::Detection_score s = score_on_hoods(0.05);
  EXPECT_EQ(s.defects, 32u);
  EXPECT_EQ(s.recall(), 1.0);
  EXPECT_EQ(s.precision(), 1.0);
}

TEST(BendingMeasure, FindsMostDefectsOfAFiftiethOfAnEdgeLength)
{
  const HB::Detection_score s = score_on_hoods(0.02);
  EXPECT_GE(s.recall(), 0.9);
  EXPECT_EQ(s.precision(), 1.0);
}

// The benchmark's stricter count: a region spread over the mesh holds defects, it does not
// locate them.
TEST(BendingMeasure, LocatesDefectsOnHoodsWhereARegionOverTheMeshDoesNot)
{
  HB::Mesh mesh = smooth_hood(3);
  const auto defects = HB::inject_defects(
      mesh, 2, 5.0, 0.2, 3, [](auto) { return true; }, 6);
  ASSERT_EQ(defects.size(), 2u);
  const auto found = detect_bending_from_above(mesh);
  const auto located = HB::located_defects(mesh, defects, found);
  EXPECT_EQ(HB::match(mesh, defects, found).found_defects, 2u);
  EXPECT_TRUE(located[0] && located[1]);
  HB::Irregularity everything;
  for (auto f : faces(mesh))
    everything.faces.push_back(f);
  const std::vector<HB::Irregularity> one_region{everything};
  EXPECT_EQ(HB::match(mesh, defects, one_region).found_defects, 2u);
  for (bool l : HB::located_defects(mesh, defects, one_region))
    EXPECT_FALSE(l);
}

TEST(BendingMeasure, HardlyAnyFalseAlarmOnSmoothHoods)
{
  const HB::Detection_score s = score_on_hoods(0.0);
  EXPECT_LE(s.regions, 1u); // over 8 hoods of 12,800 triangles
}

TEST(BendingMeasure, RegionsEncloseTheirDefectWithAMargin)
{
  HB::Mesh mesh = smooth_hood(3);
  const auto defects = HB::inject_defects(
      mesh, 3, 5.0, 0.3, 3, [](auto) { return true; }, 6);
  const auto found = detect_bending(mesh);
  ASSERT_EQ(found.size(), defects.size());
  for (const auto& d : defects) {
    // The region holding the centre holds every face of the defect.
    const HB::Irregularity* region = nullptr;
    for (const auto& r : found)
      for (auto f : r.faces)
        for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
          if (v == d.centre_vertex)
            region = &r;
    ASSERT_NE(region, nullptr);
    const std::set<HB::face_descriptor> faces(region->faces.begin(), region->faces.end());
    for (auto f : CGAL::faces(mesh)) {
      bool inside = true;
      for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
        inside = inside && CGAL::squared_distance(mesh.point(v), d.centre) < d.radius * d.radius;
      if (inside) {
        EXPECT_EQ(faces.count(f), 1u);
      }
    }
    EXPECT_GE(region->number_of_light_setups, 3u);
    EXPECT_GT(region->score, 5.0);
  }
}

// --- Defect versus design ------------------------------------------------------------------

// A hood folded along x = 0.1 (a crease of about 80 degrees between the normals, sharp
// enough that the defects do not blunt it below 60 degrees anywhere), on a
// regular grid whose column x = 0.1 runs along the crease.
double folded(double x, double y)
{
  return test::hood(x, y) + (x > 0.1 ? 6 * (x - 0.1) : 0.0);
}

TEST(Detection, RegionsNeverCrossASharpEdge)
{
  for (unsigned seed = 1; seed <= 3; ++seed) {
    HB::Mesh mesh = test::to_mesh<HB::Mesh>(test::grid(80, 2.0 / 80, -1, -1, folded, 0.0, seed));
    const double e = test::mean_edge_length(mesh);
    // Defects centred 1 to 3 edges from the crease: their support lies on both sides.
    const auto defects = HB::inject_defects(
        mesh, 2, 5.0, 0.3, seed,
        [&](HB::vertex_descriptor v) {
          const double d = std::abs(mesh.point(v).x() - 0.1);
          return d > e && d < 3 * e;
        },
        3);
    ASSERT_FALSE(defects.empty());
    // The vertices of the crease: a region may reach them, never the other side; with either
    // measure.
    for (const auto& r : detect_bending(mesh)) {
      bool left = false, right = false;
      for (auto f : r.faces)
        for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh)) {
          left = left || mesh.point(v).x() < 0.1 - 0.5 * e;
          right = right || mesh.point(v).x() > 0.1 + 0.5 * e;
        }
      EXPECT_FALSE(left && right) << "seed " << seed << ": " << HB::describe(r);
    }
    for (const auto& r : detect_local_residual(mesh, true)) {
      bool left = false, right = false;
      for (auto f : r.faces)
        for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh)) {
          left = left || mesh.point(v).x() < 0.1 - 0.5 * e;
          right = right || mesh.point(v).x() > 0.1 + 0.5 * e;
        }
      EXPECT_FALSE(left && right) << "local residual, seed " << seed << ": " << HB::describe(r);
    }
  }
}

// On four seeded smooth hoods with three defects 0.3 ē high, 6 radii apart: `check(defect,
// region)` for each defect and the region `detect` found holding it (which must exist).
template <typename Detect, typename Check>
void for_each_defect_region_on_hoods(Detect detect, Check check)
{
  for (unsigned seed = 1; seed <= 4; ++seed) {
    HB::Mesh mesh = smooth_hood(seed);
    const auto defects = HB::inject_defects(
        mesh, 3, 5.0, 0.3, seed, [](auto) { return true; }, 6);
    const auto found = detect(mesh);
    const auto holds = HB::regions_of_defects(mesh, defects, found);
    for (std::size_t d = 0; d < defects.size(); ++d) {
      ASSERT_NE(holds[d], std::size_t(-1));
      check(defects[d], found[holds[d]]);
    }
  }
}

TEST(BendingMeasure, ReportsDentsAndBumpsWithFullConfidenceOnSmoothHoods)
{
  std::size_t dents = 0, bumps = 0;
  for_each_defect_region_on_hoods(detect_bending_from_above, [&](const HB::Injected_defect& defect,
                                                                 const HB::Irregularity& r) {
    EXPECT_EQ(r.kind, defect.height < 0 ? HL::Irregularity_kind::DENT : HL::Irregularity_kind::BUMP)
        << HB::describe(r);
    EXPECT_GE(r.confidence, 0.8) << HB::describe(r);
    (defect.height < 0 ? dents : bumps) += 1;
  });
  EXPECT_GT(dents, 0u);
  EXPECT_GT(bumps, 0u);
}

// The same hoods with the local residual (the default), from above: each defect's region says
// DENT or BUMP as it is, with a confidence that the automatic mode fairs, but for the defects
// whose side lobes chain with a neighbour's (the defects lie 6 radii apart, the lobes reach 4w =
// 12 mean edge lengths from a defect's flanks): those look ELONGATED (measured: 11 of 12).
TEST(LocalResidual, ReportsMostDentsAndBumpsAsSuchOnSmoothHoods)
{
  std::size_t defects_seen = 0, reported_as_such = 0;
  for_each_defect_region_on_hoods(
      [](const HB::Mesh& mesh) { return detect_local_residual(mesh, false); },
      [&](const HB::Injected_defect& defect, const HB::Irregularity& r) {
        ++defects_seen;
        const bool as_such = r.kind == (defect.height < 0 ? HL::Irregularity_kind::DENT
                                                          : HL::Irregularity_kind::BUMP) &&
                             r.confidence >= 0.5;
        reported_as_such += as_such;
        if (!as_such)
          std::cout << "not reported as such: " << HB::describe(r) << "\n";
      });
  EXPECT_EQ(defects_seen, 12u);
  EXPECT_GE(reported_as_such, 11u);
}

bool holds(const HB::Mesh& mesh, const HB::Irregularity& r, HB::vertex_descriptor v)
{
  for (auto f : r.faces)
    for (auto w : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      if (w == v)
        return true;
  return false;
}

// The bending measure on the demo's mesh (60 lines, 3 x 4 light setups: with the default 2
// offsets it ranks design above the roof dent; the demo's --detect mode uses the default local
// residual, with 3 x 2 setups).
TEST(BendingMeasure, TheDemoRoofDentComesFirst)
{
  HB::vertex_descriptor centre;
  const HB::Mesh mesh = HB::demo_beetle(centre);
  std::vector<HB::Irregularity> found;
  CGAL::detect_highlight_line_irregularities(
      mesh, HL::default_light_setup(mesh, HLP::number_of_lines(60)), std::back_inserter(found),
      HLP::local_residual(HLP::number_of_offsets(4), false));
  ASSERT_FALSE(found.empty());
  EXPECT_TRUE(holds(mesh, found[0], centre)) << HB::describe(found[0]);
  EXPECT_EQ(found[0].kind, HL::Irregularity_kind::DENT);
  EXPECT_GE(found[0].confidence, 0.5);
  // Everything else found is the car's design, and says so.
  for (std::size_t i = 1; i < found.size(); ++i) {
    EXPECT_LT(found[i].confidence, 0.5) << HB::describe(found[i]);
  }
}

// Dents and bumps 0.2 ē high anywhere on two shared CAD meshes (seeded, 2 x 4 per mesh): the
// sweep from all sides finds most of them (benchmark_detection --shared: 0.625 and 0.75; with
// the plane of the default lights only, 0 and 0.625). Issue 16 asks for 0.9: not reached yet.
TEST(BendingMeasure, FindsMostSmallDefectsAnywhereOnSharedCadMeshes)
{
  for (const char* name : {"fandisk.off", "rocker-arm.off"}) {
    HB::Mesh original;
    if (!test::read_shared_mesh(name, original))
      GTEST_SKIP() << "shared mesh " << name << " not found";
    HB::Detection_score total;
    for (unsigned seed = 1; seed <= 2; ++seed) {
      HB::Mesh mesh = original;
      const auto defects = HB::inject_defects(mesh, 4, 5.0, 0.2, seed, [](auto) { return true; });
      const HB::Detection_score s = HB::match(mesh, defects, detect_bending(mesh));
      total.defects += s.defects;
      total.found_defects += s.found_defects;
    }
    EXPECT_EQ(total.defects, 8u) << name;
    EXPECT_GE(total.recall(), 0.6) << name;
  }
}

// --- The local residual (the default, issue 16) ------------------------------------------------

// On the smooth hoods (seeds 1..8, 4 defects each, from above) the local residual locates
// (HB::located_defects: the region holding the defect lies within 3R of it) 30 of 32 defects
// 0.05 ē high and 29 of 32 0.02 ē high, and next to nothing else (measured).
TEST(LocalResidual, LocatesSmallDefectsOnHoodsAndNothingElse)
{
  for (double h : {0.05, 0.02, 0.0}) {
    const Hood_tally t =
        tally_on_hoods(h, [](const HB::Mesh& m) { return detect_local_residual(m, false); });
    if (h > 0) {
      EXPECT_EQ(t.score.defects, 32u);
      EXPECT_GE(double(t.located) / double(t.score.defects), h > 0.03 ? 0.9 : 0.85) << h;
    }
    // At most one region of 30 holds no defect (measured: 33 of 33, 29 of 30, none).
    EXPECT_LE(t.score.regions - t.score.true_regions, h > 0 ? 1u : 0u) << h;
  }
}

// Regions sized to the defect: every vertex of a region within 2w + margin of its centre (and
// the other corners of its faces one edge further), the centre within 2w of the peak (w its
// scale, 3 ē, margin 2 ē: 14 ē plus an edge), on a shared scan with defects
// 0.2 ē high, where the clusters of the bending measure cover much of the mesh
// (benchmark_detection: 76 % of its vertices). With number_of_scales(2), a region of the
// coarser scale (6 ē: 26 ē plus an edge) that holds the centre of one of the finer scale takes
// its faces.
TEST(LocalResidual, RegionsAreSizedToTheDefect)
{
  HB::Mesh mesh;
  if (!test::read_shared_mesh("rocker-arm.off", mesh))
    GTEST_SKIP() << "shared mesh rocker-arm.off not found";
  const auto defects = HB::inject_defects(mesh, 4, 5.0, 0.2, 1, [](auto) { return true; });
  const double e = test::mean_edge_length(mesh);
  for (int scales : {1, 2}) {
    const auto found = detect_local_residual(mesh, true, scales);
    ASSERT_FALSE(found.empty());
    for (const auto& r : found) {
      ASSERT_TRUE(r.scale == 3 || (scales == 2 && r.scale == 6)) << r.scale;
      for (auto f : r.faces)
        for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
          ASSERT_LT(std::sqrt(CGAL::squared_distance(mesh.point(v), mesh.point(r.peak_vertex))),
                    (4 * r.scale + 4) * e)
              << HB::describe(r) << ", scale " << r.scale;
    }
    // And it locates the defects there (the bending measure: none of 8 at 0.2 ē in
    // benchmark_detection, seeds 1-2).
    std::size_t located = 0;
    for (bool l : HB::located_defects(mesh, defects, found))
      located += l;
    std::cout << "rocker-arm, seed 1, 0.2 ē, " << scales << " scale(s): located " << located
              << " of " << defects.size() << "\n";
    // Measured: 4 of 4 with 1 and 2 scales; 1 of 4 when any peak within 4w of a region twice
    // as strong was dropped as a side lobe (the defects next to the arm's fillets were lost).
    EXPECT_GE(located, 3u) << scales;
  }
}

// The mirror symmetry of a surface, the rule by which the local residual tells design from
// defects on symmetric shapes: found on the bundled Beetle (exactly symmetric: its own
// asymmetry is below the floor ē/50), where the demo's roof dent breaks it by its depth at its
// centre; not found on a smooth hood whose cross term 0.05xy no mirror keeps.
TEST(LocalResidual, FindsTheMirrorSymmetryOfDesignAndTheAsymmetryOfADefect)
{
  HB::vertex_descriptor centre;
  const HB::Mesh dented = HB::demo_beetle(centre);
  HB::Mesh beetle;
  std::ifstream in(std::string(HIGHLIGHT_LINES_DATA_DIR) + "/beetle.off");
  ASSERT_TRUE(in && CGAL::IO::read_OFF(in, beetle));
  const double e = test::mean_edge_length(beetle);
  const Mirror_symmetry_of_mesh original(beetle), with_dent(dented);
  ASSERT_TRUE(original.symmetry.is_symmetric());
  EXPECT_DOUBLE_EQ(original.symmetry.tolerance(), 0.02 * e);
  ASSERT_TRUE(with_dent.symmetry.is_symmetric()); // a dent is local
  EXPECT_LT(original.symmetry.asymmetry(int(centre)), 1e-3 * e);
  // The dent is 0.006 of the diagonal deep (0.95 ē); its mirror image lies off the dent.
  const double depth =
      std::sqrt(CGAL::squared_distance(beetle.point(centre), dented.point(centre)));
  EXPECT_GT(with_dent.symmetry.asymmetry(int(centre)), 0.9 * depth);
  EXPECT_FALSE(Mirror_symmetry_of_mesh(smooth_hood(1)).symmetry.is_symmetric());
}

// A symmetric scan is less symmetric than a design: the shared camel head's mirror images lie
// up to 0.21 ē off it (99th percentile), 7.3 times its median. A design region of hundreds of
// vertices nearly always holds a few vertices that far off, so the region's asymmetry is taken
// over a disc of the detection's scale, and measured against the scan's own asymmetry from the
// median, which defects do not lift. Measured on the undented camel head: 6 design regions (its
// eye sockets, nostrils, mouth corners, each with its mirror image among the regions) passed the
// automatic mode's level with the largest distance against the 99th percentile, none since.
TEST(LocalResidual, LeavesTheDesignOfASymmetricScanAlone)
{
  HB::Mesh camel;
  if (!test::read_shared_mesh("camelhead.off", camel))
    GTEST_SKIP() << "shared mesh camelhead.off not found";
  const double e = test::mean_edge_length(camel);
  const Mirror_symmetry_of_mesh mirror(camel);
  ASSERT_TRUE(mirror.symmetry.is_symmetric());
  EXPECT_GT(mirror.symmetry.tolerance(), 0.1 * e); // a scan: far above the floor ē/50
  EXPECT_GT(mirror.symmetry.defect_tolerance(), mirror.symmetry.tolerance());
  const auto found = detect_local_residual(camel, true);
  EXPECT_GE(found.size(), 10u); // the lines do bend over the design
  for (const auto& region : found)
    EXPECT_LT(region.confidence, 0.5) << HB::describe(region);
}

// The surface's own asymmetry against which a defect's is measured holds while defects cover
// much of a small mesh: four defects 1 ē high and 5 ē wide on the shared Spot (a symmetric
// design, its own asymmetry below the floor ē/50) cover, with their mirror images, about a
// quarter of its vertices. They lift the 99th percentile of the distances to near their height
// (measured: 0.79 ē); the defect tolerance stays below a tenth of it (0.062 ē: 8 times a median
// that they lift from 1e-15 ē).
TEST(MirrorSymmetry, DefectToleranceIsNotLiftedByTheDefects)
{
  HB::Mesh spot;
  if (!test::read_shared_mesh("spot.off", spot))
    GTEST_SKIP() << "shared mesh spot.off not found";
  const double e = test::mean_edge_length(spot);
  const auto defects = HB::inject_defects(spot, 4, 5.0, 1.0, 1, [](auto) { return true; });
  ASSERT_EQ(defects.size(), 4u);
  const Mirror_symmetry_of_mesh mirror(spot);
  ASSERT_TRUE(mirror.symmetry.is_symmetric());
  EXPECT_GT(mirror.symmetry.tolerance(), 0.5 * e);
  EXPECT_LT(mirror.symmetry.defect_tolerance(), 0.1 * e);
}

// The demo's --detect mode with the local residual (60 lines, the default 3 x 2 light setups):
// the roof dent comes first, a dent, with confidence 1; the design of the car (measured: 33
// regions, confidence at most 0.0054, all symmetric) stays far below the level at which the
// automatic mode fairs (0.5). Measured before the symmetry rule: the dent 10th, called a bump, a
// design region of confidence 0.64.
TEST(LocalResidual, TheDemoRoofDentComesFirstAndTheDesignIsLeftAlone)
{
  HB::vertex_descriptor centre;
  const HB::Mesh mesh = HB::demo_beetle(centre);
  std::vector<HB::Irregularity> found;
  CGAL::detect_highlight_line_irregularities(
      mesh, HL::default_light_setup(mesh, HLP::number_of_lines(60)), std::back_inserter(found),
      HLP::local_residual(true));
  ASSERT_FALSE(found.empty());
  EXPECT_TRUE(holds(mesh, found[0], centre)) << HB::describe(found[0]);
  EXPECT_EQ(found[0].kind, HL::Irregularity_kind::DENT);
  EXPECT_GE(found[0].confidence, 0.9);
  for (std::size_t i = 1; i < found.size(); ++i)
    EXPECT_LT(found[i].confidence, 0.01) << HB::describe(found[i]);
}

// Dents and bumps 0.2 ē high and 5 ē wide injected into `original` (seeds 1-2, up to 4 each),
// found by the local residual: how many were injected, how many lie in a region that ranks
// above every region of the undented mesh, and in how many the region passes the level at
// which the automatic mode fairs (confidence 0.5).
struct Ranking
{
  std::size_t defects = 0, above = 0, confident = 0;
};

Ranking rank_injected_defects(const HB::Mesh& original)
{
  const auto own = detect_local_residual(original, true);
  Ranking ranking;
  for (unsigned seed = 1; seed <= 2; ++seed) {
    HB::Mesh mesh = original;
    const auto injected = HB::inject_defects(mesh, 4, 5.0, 0.2, seed, [](auto) { return true; });
    const auto found = detect_local_residual(mesh, true);
    ranking.defects += injected.size();
    for (std::size_t r : HB::regions_of_defects(mesh, injected, found)) {
      if (r == std::size_t(-1))
        continue;
      bool first = true;
      for (const auto& o : own)
        first = first && HB::stronger(found[r], o);
      ranking.above += first;
      ranking.confident += found[r].confidence >= 0.5;
    }
  }
  return ranking;
}

// On the shared Beetle, dents and bumps 0.2 ē high (seeds 1-2, 2 x 4): each one found ranks
// above every region of the undented Beetle (measured: 6 of 8, the two others are not found;
// 0 of 8 before the symmetry rule, when a round design bump on the midplane had confidence 1),
// and a third of them pass the level at which the automatic mode fairs (measured: 2 of 6; none
// when the shape of a defect's anomalies was measured with those of the symmetric design next
// to it, which made them look elongated; 3 of 6 with a region's asymmetry its largest distance,
// which let the design of symmetric scans pass, see LeavesTheDesignOfASymmetricScanAlone: a
// region that holds only part of a shallow defect has fewer displaced vertices than a disc of
// the detection's scale).
TEST(LocalResidual, RanksDefectsAboveTheDesignOfASymmetricShape)
{
  HB::Mesh original;
  if (!test::read_shared_mesh("beetle.off", original))
    GTEST_SKIP() << "shared mesh beetle.off not found";
  const Ranking r = rank_injected_defects(original);
  EXPECT_EQ(r.defects, 8u);
  EXPECT_GE(r.above, 6u);
  EXPECT_GE(r.confident, 2u);
}

// On a scan without a mirror symmetry (the shared bunny, 0.2 ē, seeds 1-2, 2 x 3 defects: the
// mesh is small), a region's score is its contrast with the residuals of its surroundings, not
// with those of its lines: the defects found rank above every region of the undented bunny in
// 3 of 6 cases (measured; 1 of 6 when the score was the strongest anomaly against its line's
// noise: the ears and the neck move the lines as much around them as on them).
TEST(LocalResidual, RanksDefectsByTheirContrastWithTheSurroundings)
{
  HB::Mesh original;
  if (!test::read_shared_mesh("bunny.off", original))
    GTEST_SKIP() << "shared mesh bunny.off not found";
  const Ranking r = rank_injected_defects(original);
  EXPECT_EQ(r.defects, 6u);
  EXPECT_GE(r.above, 2u);
}

// A region must show in half of the setups that can see its centre: those that face it and
// scored a sample within w of it, not all that face it (lines are not scored near their ends
// and near sharp edges). On the shared Spot, dents and bumps 0.2 ē high (seeds 1-2, 2 x 4):
// located 7 of 8 (measured; 4 of 8 when every facing setup counted).
TEST(LocalResidual, CountsTheEvidenceAmongTheSetupsThatScoreTheSurface)
{
  HB::Mesh original;
  if (!test::read_shared_mesh("spot.off", original))
    GTEST_SKIP() << "shared mesh spot.off not found";
  std::size_t located = 0, defects = 0;
  for (unsigned seed = 1; seed <= 2; ++seed) {
    HB::Mesh mesh = original;
    const auto injected = HB::inject_defects(mesh, 4, 5.0, 0.2, seed, [](auto) { return true; });
    defects += injected.size();
    for (bool l : HB::located_defects(mesh, injected, detect_local_residual(mesh, true)))
      located += l;
  }
  EXPECT_EQ(defects, 8u);
  EXPECT_GE(located, 6u);
}

// Line density from the mesh: with lights 6 times too far apart for the defects (5 lines over
// the hood, one every ~16 ē), the local residual brings them closer and locates as many small
// defects as with 30 lines (measured: 32 of 32 at 0.05 ē, no false region; with the lights'
// own spacing, 11 of 32).
TEST(LocalResidual, TakesItsLineDensityFromTheMeshNotFromTheLights)
{
  const Hood_tally t = tally_on_hoods(0.05, [](const HB::Mesh& m) {
    std::vector<HB::Irregularity> found;
    CGAL::detect_highlight_line_irregularities(
        m, HL::default_light_setup(m, HLP::number_of_lines(5)), std::back_inserter(found),
        HLP::local_residual(HLP::all_sides(false), true));
    return found;
  });
  EXPECT_EQ(t.score.defects, 32u);
  EXPECT_GE(t.located, 29u);
  EXPECT_LE(t.score.regions - t.score.true_regions, 1u);
}

// --- Invariances --------------------------------------------------------------------------

std::set<std::array<std::size_t, 3>> face_keys(const HB::Mesh& mesh, const HB::Irregularity& r)
{
  std::set<std::array<std::size_t, 3>> keys;
  for (auto f : r.faces) {
    std::array<std::size_t, 3> k{};
    std::size_t j = 0;
    for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      k[j++] = std::size_t(v);
    std::sort(k.begin(), k.end());
    keys.insert(k);
  }
  return keys;
}

TEST(Detection, CommutesWithRigidMotionAndScaling)
{
  HB::Mesh mesh = smooth_hood(5);
  ASSERT_EQ(HB::inject_defects(
                mesh, 3, 5.0, 0.1, 5, [](auto) { return true; }, 6)
                .size(),
            3u);
  const auto lights = HL::default_light_setup(mesh, HLP::number_of_lines(30));
  const CGAL::Aff_transformation_3<HB::Kernel> motion(0.6, -0.8, 0, 1.5, 0.8, 0.6, 0, -2, 0, 0, 1,
                                                      0.25, 1.0);
  const CGAL::Aff_transformation_3<HB::Kernel> scaling(CGAL::SCALING, 1000.0);
  for (const auto& transform : {motion * scaling, scaling.inverse()}) {
    HB::Mesh moved = mesh;
    for (auto v : vertices(moved))
      moved.point(v) = transform(moved.point(v));
    std::vector<HB::Irregularity> a, b;
    CGAL::detect_highlight_line_irregularities(mesh, lights, std::back_inserter(a));
    CGAL::detect_highlight_line_irregularities(moved, lights.transformed(transform),
                                               std::back_inserter(b));
    ASSERT_EQ(a.size(), 3u);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(face_keys(mesh, a[i]), face_keys(moved, b[i]));
      EXPECT_NEAR(a[i].score, b[i].score, 1e-6 * a[i].score);
    }
  }
}

TEST(Detection, IndependentOfFaceOrderAndMeshType)
{
  test::Soup soup = test::grid(60, 2.0 / 60, -1, -1, test::hood, 0.3, 9);
  HB::Mesh mesh = test::to_mesh<HB::Mesh>(soup);
  ASSERT_EQ(HB::inject_defects(
                mesh, 2, 5.0, 0.1, 9, [](auto) { return true; }, 6)
                .size(),
            2u);
  for (auto v : vertices(mesh))
    soup.points[std::size_t(v)] = mesh.point(v);
  test::Soup shuffled = soup;
  std::shuffle(shuffled.triangles.begin(), shuffled.triangles.end(), std::mt19937(4));
  const HB::Mesh reordered = test::to_mesh<HB::Mesh>(shuffled);
  const test::Polyhedron polyhedron = test::to_mesh<test::Polyhedron>(soup);
  const auto lights = HL::default_light_setup(mesh, HLP::number_of_lines(30));

  std::vector<HB::Irregularity> a, b;
  std::vector<HL::Highlight_line_irregularity<test::Polyhedron>> c;
  CGAL::detect_highlight_line_irregularities(mesh, lights, std::back_inserter(a));
  CGAL::detect_highlight_line_irregularities(reordered, lights, std::back_inserter(b));
  CGAL::detect_highlight_line_irregularities(polyhedron, lights, std::back_inserter(c));
  ASSERT_EQ(a.size(), 2u);
  ASSERT_EQ(b.size(), a.size());
  ASSERT_EQ(c.size(), a.size());
  std::map<const void*, std::size_t> polyhedron_ids;
  std::size_t next = 0;
  for (auto v : vertices(polyhedron))
    polyhedron_ids[&*v] = next++;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(face_keys(mesh, a[i]), face_keys(reordered, b[i]));
    EXPECT_NEAR(a[i].score, b[i].score, 1e-9 * a[i].score); // normals summed in another order
    std::set<std::array<std::size_t, 3>> keys;
    for (auto f : c[i].faces) {
      std::array<std::size_t, 3> k{};
      std::size_t j = 0;
      for (auto v : CGAL::vertices_around_face(halfedge(f, polyhedron), polyhedron))
        k[j++] = polyhedron_ids[&*v];
      std::sort(k.begin(), k.end());
      keys.insert(k);
    }
    EXPECT_EQ(face_keys(mesh, a[i]), keys);
    EXPECT_NEAR(a[i].score, c[i].score, 1e-9 * a[i].score);
  }
}

TEST(Detection, ReportsProgressCanBeCancelledAndRunsInParallel)
{
  HB::Mesh mesh = smooth_hood(7, 40);
  ASSERT_EQ(HB::inject_defects(mesh, 1, 4.0, 0.5, 7, [](auto) { return true; }).size(), 1u);
  const auto lights = HL::default_light_setup(mesh, HLP::number_of_lines(30));
  std::vector<double> progress;
  std::vector<HB::Irregularity> found, cancelled, parallel;
  CGAL::detect_highlight_line_irregularities(mesh, lights, std::back_inserter(found),
                                             CGAL::parameters::callback([&](double f) {
                                               progress.push_back(f);
                                               return true;
                                             }));
  ASSERT_EQ(progress.size(), 6u * 3u * 2u); // 6 planes x 3 orientations x 2 offsets
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
  EXPECT_DOUBLE_EQ(progress.back(), 1.0);
  ASSERT_GE(found.size(), 1u);
  // The default is the local residual (the bending measure is `local_residual(false)`).
  std::vector<HB::Irregularity> residual, bending;
  CGAL::detect_highlight_line_irregularities(mesh, lights, std::back_inserter(residual),
                                             HLP::local_residual(true));
  ASSERT_EQ(residual.size(), found.size());
  for (std::size_t i = 0; i < found.size(); ++i) {
    EXPECT_EQ(face_keys(mesh, residual[i]), face_keys(mesh, found[i]));
    EXPECT_EQ(residual[i].score, found[i].score);
  }
  CGAL::detect_highlight_line_irregularities(mesh, lights, std::back_inserter(bending),
                                             HLP::local_residual(false));
  ASSERT_GE(bending.size(), 1u);
  EXPECT_FALSE(bending.size() == found.size() && bending[0].score == found[0].score);
  std::size_t calls = 0;
  CGAL::detect_highlight_line_irregularities(
      mesh, lights, std::back_inserter(cancelled),
      CGAL::parameters::callback([&](double) { return ++calls < 3; }));
  EXPECT_EQ(calls, 3u);
  EXPECT_TRUE(cancelled.empty());
#ifdef CGAL_LINKED_WITH_TBB
  CGAL::detect_highlight_line_irregularities<CGAL::Parallel_tag>(mesh, lights,
                                                                 std::back_inserter(parallel));
  ASSERT_EQ(parallel.size(), found.size());
  for (std::size_t i = 0; i < found.size(); ++i) {
    EXPECT_EQ(face_keys(mesh, parallel[i]), face_keys(mesh, found[i]));
    EXPECT_DOUBLE_EQ(parallel[i].score, found[i].score);
  }
#endif
}

// One dented hood as a Surface_mesh and as a Polyhedron_3 with the same points and faces.
struct Dented_hood_pair
{
  HB::Mesh mesh;
  test::Polyhedron polyhedron;
  std::size_t defects = 0;

  Dented_hood_pair()
  {
    test::Soup soup = test::grid(40, 2.0 / 40, -1, -1, test::hood, 0.3, 7);
    mesh = test::to_mesh<HB::Mesh>(soup);
    defects = HB::inject_defects(mesh, 1, 4.0, 0.5, 7, [](auto) { return true; }).size();
    for (auto v : vertices(mesh))
      soup.points[std::size_t(v)] = mesh.point(v);
    polyhedron = test::to_mesh<test::Polyhedron>(soup);
  }
};

// The local residual gives the same regions on a Polyhedron_3 as on a Surface_mesh, at
// one scale and at two (number_of_scales).
TEST(LocalResidual, ActsAlikeOnPolyhedronAndSurfaceMesh)
{
  const Dented_hood_pair pair;
  ASSERT_EQ(pair.defects, 1u);
  const HB::Mesh& mesh = pair.mesh;
  const test::Polyhedron& polyhedron = pair.polyhedron;
  const auto lights = HL::default_light_setup(mesh, HLP::number_of_lines(30));
  for (int scales : {1, 2}) {
    SCOPED_TRACE("number_of_scales " + std::to_string(scales));
    const auto np = HLP::local_residual(HLP::number_of_scales(scales), true);
    std::vector<HB::Irregularity> a;
    std::vector<HL::Highlight_line_irregularity<test::Polyhedron>> b;
    CGAL::detect_highlight_line_irregularities(mesh, lights, std::back_inserter(a), np);
    CGAL::detect_highlight_line_irregularities(polyhedron, lights, std::back_inserter(b), np);
    ASSERT_GE(a.size(), 1u);
    ASSERT_EQ(b.size(), a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(b[i].faces.size(), a[i].faces.size());
      EXPECT_EQ(b[i].kind, a[i].kind);
      EXPECT_NEAR(b[i].score, a[i].score, 1e-9 * a[i].score);
      EXPECT_NEAR(b[i].confidence, a[i].confidence, 1e-12);
    }
  }
}

TEST(Detection, SweepOptionsActAlikeOnPolyhedronAndSurfaceMesh)
{
  const Dented_hood_pair pair;
  ASSERT_EQ(pair.defects, 1u);
  const HB::Mesh& mesh = pair.mesh;
  const test::Polyhedron& polyhedron = pair.polyhedron;
  const auto lights = HL::default_light_setup(mesh, HLP::number_of_lines(30));
  for (bool all_sides : {false, true}) {
    std::vector<double> progress_sm, progress_ph;
    std::vector<HB::Irregularity> a;
    std::vector<HL::Highlight_line_irregularity<test::Polyhedron>> b;
    CGAL::detect_highlight_line_irregularities(
        mesh, lights, std::back_inserter(a),
        HLP::combine(HLP::all_sides(all_sides), CGAL::parameters::callback([&](double f) {
                       progress_sm.push_back(f);
                       return true;
                     })));
    CGAL::detect_highlight_line_irregularities(
        polyhedron, lights, std::back_inserter(b),
        HLP::combine(HLP::all_sides(all_sides), CGAL::parameters::callback([&](double f) {
                       progress_ph.push_back(f);
                       return true;
                     })));
    // 3 orientations x 2 offsets per plane: one plane, or the six sides of a cube.
    EXPECT_EQ(progress_sm.size(), (all_sides ? 6u : 1u) * 6u);
    EXPECT_EQ(progress_ph, progress_sm);
    ASSERT_GE(a.size(), 1u);
    ASSERT_EQ(b.size(), a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(b[i].faces.size(), a[i].faces.size());
      EXPECT_EQ(b[i].kind, a[i].kind);
      EXPECT_NEAR(b[i].score, a[i].score, 1e-9 * a[i].score);
      EXPECT_NEAR(b[i].confidence, a[i].confidence, 1e-12);
    }
    // A cancelled sweep writes nothing, whatever the mesh type.
    b.clear();
    std::size_t calls = 0;
    CGAL::detect_highlight_line_irregularities(
        polyhedron, lights, std::back_inserter(b),
        HLP::combine(HLP::all_sides(all_sides),
                     CGAL::parameters::callback([&](double) { return ++calls < 2; })));
    EXPECT_EQ(calls, 2u);
    EXPECT_TRUE(b.empty());
  }
  // minimum_confidence 0: the hood's defect is faired, on both mesh types alike (below); at the
  // default, the undented fandisk's regions (design along its fillets, of low confidence) are
  // skipped on both, and the Polyhedron_3 is left as it was.
  {
    HB::Mesh fandisk;
    if (test::read_shared_mesh("fandisk.off", fandisk)) {
      test::Polyhedron fandisk_ph, before;
      CGAL::copy_face_graph(fandisk, fandisk_ph);
      before = fandisk_ph;
      const auto fandisk_lights = HL::default_light_setup(fandisk, HLP::number_of_lines(30));
      const auto sm = CGAL::detect_and_fair_highlight_line_irregularities(fandisk, fandisk_lights);
      const auto ph =
          CGAL::detect_and_fair_highlight_line_irregularities(fandisk_ph, fandisk_lights);
      ASSERT_EQ(ph.size(), sm.size());
      std::size_t skipped = 0;
      for (std::size_t i = 0; i < ph.size(); ++i) {
        EXPECT_EQ(ph[i].skipped, sm[i].skipped);
        EXPECT_EQ(ph[i].skipped, ph[i].irregularity.confidence < 0.5);
        skipped += ph[i].skipped;
        if (ph[i].skipped) {
          EXPECT_FALSE(ph[i].repaired);
        }
      }
      EXPECT_GE(skipped, 1u);
      if (skipped == ph.size()) {
        auto p = vertices(before).begin();
        for (auto v : vertices(fandisk_ph))
          EXPECT_EQ(v->point(), (*p++)->point());
      }
    }
  }
  test::Polyhedron faired_ph = polyhedron;
  HB::Mesh faired_sm = mesh;
  const auto ph = CGAL::detect_and_fair_highlight_line_irregularities(faired_ph, lights,
                                                                      HLP::minimum_confidence(0.0));
  const auto sm = CGAL::detect_and_fair_highlight_line_irregularities(faired_sm, lights,
                                                                      HLP::minimum_confidence(0.0));
  ASSERT_EQ(ph.size(), sm.size());
  ASSERT_FALSE(ph.empty());
  EXPECT_FALSE(ph[0].skipped);
  EXPECT_TRUE(ph[0].repaired) << ph[0].failure;
  for (std::size_t i = 0; i < ph.size(); ++i) {
    EXPECT_EQ(ph[i].skipped, sm[i].skipped);
    EXPECT_EQ(ph[i].repaired, sm[i].repaired);
  }
  std::size_t i = 0;
  for (auto v : vertices(faired_ph))
    EXPECT_LT(CGAL::squared_distance(v->point(),
                                     faired_sm.point(HB::vertex_descriptor(std::uint32_t(i++)))),
              1e-20);
}

// --- Bad input ----------------------------------------------------------------------------

TEST(Detection, RejectsParametersOutOfTheirDomain)
{
  const HB::Mesh mesh = smooth_hood(1, 20);
  const auto lights = HL::default_light_setup(mesh);
  std::vector<HB::Irregularity> found;
  auto rejects = [&](const auto& np) {
    try {
      CGAL::detect_highlight_line_irregularities(mesh, lights, std::back_inserter(found), np);
    } catch (const HL::Invalid_input& e) {
      EXPECT_EQ(e.problem(), HL::Invalid_input::Problem::INVALID_PARAMETER);
      return true;
    }
    return false;
  };
  EXPECT_TRUE(rejects(HLP::number_of_orientations(0)));
  EXPECT_TRUE(rejects(HLP::number_of_offsets(-2)));
  EXPECT_TRUE(rejects(HLP::detection_scale(0.5)));
  EXPECT_TRUE(rejects(HLP::detection_scale(std::nan(""))));
  EXPECT_TRUE(rejects(HLP::detection_threshold(0.0)));
  EXPECT_TRUE(rejects(HLP::minimum_bending(-1.0)));
  EXPECT_TRUE(rejects(HLP::minimum_evidence(1.5)));
  EXPECT_TRUE(rejects(HLP::region_margin(-1)));
  EXPECT_TRUE(rejects(HLP::maximum_incidence_angle(95.0)));
  EXPECT_TRUE(rejects(HLP::number_of_scales(0)));
  EXPECT_TRUE(rejects(HLP::number_of_scales(5)));
  EXPECT_TRUE(found.empty());
}

// On a small mesh no light setup has samples enough (32) to tell its noise: the scores are then
// taken against the noise of all the samples together, not against a vanishing floor (the
// 12 x 12 hood of test/Highlight_lines/data scored 2.2e299 with explicit lights from above).
TEST(LocalResidual, ScoresStayFiniteWhereNoSetupKnowsItsNoise)
{
  const HB::Mesh dented =
      test::to_mesh<HB::Mesh>(test::grid(12, 2.0 / 12, -1, -1, [](double x, double y) {
        return test::hood(x, y) - 0.04 * std::exp(-((x + 0.3) * (x + 0.3) + y * y) / 0.05);
      }));
  std::size_t regions = 0;
  for (const HB::Mesh& mesh : {dented, smooth_hood(1, 12), smooth_hood(2, 16)}) {
    for (const auto& lights : {HL::Light_setup<HB::Kernel>(HB::Point(0, 0, 3), HB::Vector(1, 0, 0),
                                                           HB::Vector(0, 0, 1), 0.1),
                               HL::default_light_setup(mesh)}) {
      std::vector<HB::Irregularity> found;
      CGAL::detect_highlight_line_irregularities(mesh, lights, std::back_inserter(found));
      regions += found.size();
      for (const auto& region : found) {
        EXPECT_TRUE(std::isfinite(region.score));
        EXPECT_LT(region.score, 1e3);
      }
    }
  }
  std::cout << regions << " regions on the small hoods\n";
}

// Where the lines are straight to the rounding, the noise of the lines is no measure: on a
// regular 80 x 80 grid over the smooth hood (a CAD tessellation; the statistical tests use
// jittered grids), the deviations of the level residuals are ~4e-5 of the spacing, and the
// grid's own pattern and the far tails of the defects became anomalies. Measured before the
// floor of a hundredth of the spacing: 19 to 22 regions per mesh, 16 to 19 of them holding
// no defect (one of confidence 0.67); after: 2 or 3, each at a defect.
TEST(LocalResidual, FindsOnlyTheDefectsOnARegularGrid)
{
  for (unsigned seed : {1u, 2u, 3u}) {
    HB::Mesh mesh = test::to_mesh<HB::Mesh>(test::grid(80, 2.0 / 80, -1, -1, test::hood));
    const auto defects = HB::inject_defects(mesh, 2, 5.0, 0.2, seed, [](auto) { return true; });
    ASSERT_EQ(defects.size(), 2u);
    const auto found = detect_local_residual(mesh, true);
    for (bool l : HB::located_defects(mesh, defects, found))
      EXPECT_TRUE(l) << "seed " << seed;
    const auto genuine = HB::genuine_regions(mesh, defects, found);
    for (std::size_t i = 0; i < found.size(); ++i)
      EXPECT_TRUE(genuine[i]) << "seed " << seed << ": " << HB::describe(found[i]);
    EXPECT_LE(found.size(), 4u) << "seed " << seed;
  }
}

// A dent on a flat plate, a 40 x 40 regular grid: found with the confidence at which the
// automatic mode fairs it. Measured before: the principal axes of a square are a tie, which the
// dent broke by tipping one of them towards itself, so the plate was "mirror symmetric" about
// a plane through the dent and the dent was design (confidence 2e-6 to 4e-6); and a dent of
// 0.05 ē scored 3e12 against a noise of 1e-15. After: confidence 0.68 to 1.
TEST(LocalResidual, FindsADentOnAFlatPlateAsADefect)
{
  for (unsigned seed : {1u, 2u, 3u}) {
    HB::Mesh mesh = flat_plate();
    const auto defects = HB::inject_defects(mesh, 1, 4.0, 0.2, seed, [](auto) { return true; });
    ASSERT_EQ(defects.size(), 1u);
    const Mirror_symmetry_of_mesh mirror(mesh);
    if (mirror.symmetry.is_symmetric()) { // about the plate's own plane: the dent is off it
      EXPECT_GT(mirror.symmetry.asymmetry(int(defects[0].centre_vertex)),
                0.5 * std::abs(defects[0].height))
          << "seed " << seed;
    }
    const auto found = detect_local_residual(mesh, true);
    ASSERT_EQ(found.size(), 1u) << "seed " << seed;
    EXPECT_TRUE(HB::located_defects(mesh, defects, found)[0]) << "seed " << seed;
    EXPECT_GE(found[0].confidence, 0.5) << "seed " << seed << ": " << HB::describe(found[0]);
    EXPECT_LT(found[0].score, 1e3) << "seed " << seed;
  }
  HB::Mesh shallow = flat_plate();
  HB::inject_defects(shallow, 1, 4.0, 0.05, 1, [](auto) { return true; });
  for (const auto& r : detect_local_residual(shallow, true))
    EXPECT_LT(r.score, 1e3) << HB::describe(r);
}

// What is larger than a defect of the detection's scale can make is not faired by default:
// anomalies spread over more than 11w (length) or whose cluster covers more than the disc of
// that diameter (area; on a small or compact mesh a cluster wrapping around the surface spreads
// less in space than along it) are not local, and get at most half the confidence.
TEST(DefectOrDesign, WhatIsLargerThanADefectGetsLessThanHalfTheConfidence)
{
  const double w = 1;
  const double disc_area = 3.14159265358979323846 * 121 / 4; // diameter 11w
  // A defect's cluster: 8w long, covering a third of the disc.
  HLI::Anomaly_shape shape = HLI::anomaly_shape({2.0, 1.8}, w, 11 * w, disc_area / 3);
  EXPECT_EQ(shape.locality, 1);
  EXPECT_EQ(shape.slenderness, 1);
  // Just longer than 11w: no longer local, below half at once.
  shape = HLI::anomaly_shape({2.8, 2.5}, w, 11 * w, disc_area / 3);
  EXPECT_LT(shape.locality, 0.5);
  EXPECT_GT(shape.locality, 0.45);
  // 8w across, but covering twice the disc (wrapped around a compact surface).
  shape = HLI::anomaly_shape({2.0, 1.8}, w, 11 * w, 2 * disc_area);
  EXPECT_NEAR(shape.locality, 0.25, 1e-12);
  // The same area from faces that reach w beyond the anomalies: measured against the disc
  // grown by w.
  const double grown_disc_area = 3.14159265358979323846 * 6.5 * 6.5;
  shape = HLI::anomaly_shape({2.0, 1.8}, w, 11 * w, 2 * disc_area, w);
  EXPECT_NEAR(shape.locality, 0.5 * grown_disc_area / (2 * disc_area), 1e-12);
  shape = HLI::anomaly_shape({2.0, 1.8}, w, 11 * w, 0.99 * grown_disc_area, w);
  EXPECT_EQ(shape.locality, 1);
  // Elongated and long: both factors.
  shape = HLI::anomaly_shape({5.5, 0.5}, w, 11 * w);
  EXPECT_LT(shape.slenderness, 1);
  EXPECT_NEAR(shape.locality, 0.5 * std::pow(11.0 / 22.0, 2), 1e-12);
  EXPECT_EQ(HLI::kind_of_region(shape, [] { return HL::Irregularity_kind::DENT; }),
            HL::Irregularity_kind::ELONGATED);
}

// A sphere of 17 ē radius textured all over by 400 bumps and dimples (Gaussian, σ = √2 ē,
// 0.3 ē high): design over the whole surface, whose anomalies join into clusters over the whole
// sphere. At the default scale (w = 3 ē) they are longer than 11w (4 standard deviations: about
// 13w): every region is EXTENDED and stays below the automatic mode's 0.5 (measured before the
// rule: two extended regions of confidence 0.51; after: at most 0.26). At w = 4 ē they are
// shorter than 11w but cover more than a defect's disc (grown as the clusters' faces are): still
// EXTENDED by their area (measured before: 8 dents, 6 of confidence 1; after: at most 0.4).
TEST(LocalResidual, LeavesADesignTextureOverACompactSurfaceAlone)
{
  HB::Mesh mesh = test::to_mesh<HB::Mesh>(test::sphere(1.0, 5));
  const double e = test::mean_edge_length(mesh);
  std::mt19937 generator(7);
  std::normal_distribution<double> gaussian;
  std::vector<std::array<double, 4>> bumps; // unit centre, height
  for (int i = 0; i < 400; ++i) {
    const double x = gaussian(generator), y = gaussian(generator), z = gaussian(generator);
    const double length = std::sqrt(x * x + y * y + z * z);
    bumps.push_back({x / length, y / length, z / length, (i % 2 ? 0.3 : -0.3) * e});
  }
  for (auto v : vertices(mesh)) {
    const auto p = mesh.point(v);
    double height = 0;
    for (const auto& b : bumps) {
      const double d2 = (p.x() - b[0]) * (p.x() - b[0]) + (p.y() - b[1]) * (p.y() - b[1]) +
                        (p.z() - b[2]) * (p.z() - b[2]);
      height += b[3] * std::exp(-d2 / (4 * e * e));
    }
    mesh.point(v) = test::Point(p.x() * (1 + height), p.y() * (1 + height), p.z() * (1 + height));
  }
  std::size_t extended = 0;
  for (const auto& region : detect_local_residual(mesh, true))
    if (region.kind == HL::Irregularity_kind::EXTENDED) {
      ++extended;
      EXPECT_LT(region.confidence, 0.5) << HB::describe(region);
    }
  EXPECT_GE(extended, 5u); // the texture is found, and found to be wider than a defect

  std::vector<HB::Irregularity> coarser;
  CGAL::detect_highlight_line_irregularities(
      mesh, HL::default_light_setup(mesh, HLP::number_of_lines(30)), std::back_inserter(coarser),
      HLP::local_residual(HLP::detection_scale(HLP::all_sides(true), 4.0), true));
  EXPECT_GE(coarser.size(), 3u);
  for (const auto& region : coarser) {
    EXPECT_EQ(region.kind, HL::Irregularity_kind::EXTENDED) << HB::describe(region);
    EXPECT_LT(region.confidence, 0.5) << HB::describe(region);
  }
}

TEST(Detection, RejectsNonFiniteCoordinates)
{
  HB::Mesh mesh = smooth_hood(1, 20);
  const auto lights = HL::default_light_setup(mesh);
  mesh.point(*vertices(mesh).begin()) = HB::Point(std::nan(""), 0, 0);
  std::vector<HB::Irregularity> found;
  EXPECT_THROW(CGAL::detect_highlight_line_irregularities(mesh, lights, std::back_inserter(found)),
               HL::Invalid_input);
}

// --- Detect and fair ----------------------------------------------------------------------

// Detect and fair on a hood with two defects, with either measure.
void repair_every_defect_found_and_touch_nothing_else(bool local_residual)
{
  const HB::Mesh undented = smooth_hood(2, 60);
  HB::Mesh mesh = undented;
  const auto defects = HB::inject_defects(
      mesh, 2, 5.0, 0.5, 2, [](auto) { return true; }, 5);
  ASSERT_EQ(defects.size(), 2u);
  const HB::Mesh dented = mesh;
  const auto lights = HL::default_light_setup(mesh, HLP::number_of_lines(30));

  std::vector<std::size_t> iterations;
  auto visitor = [&](const HL::Fairing_report::Iteration&) {
    iterations.push_back(0);
    return true;
  };
  const auto repairs = CGAL::detect_and_fair_highlight_line_irregularities(
      mesh, lights, HLP::local_residual(HLP::fairing_visitor(visitor), local_residual));
  // One region per defect: the local residual finds one of the defects as two regions side by
  // side (its side lobes peak apart), which the fairing joins (faired apart, their common
  // border stayed fixed: 77 of the defect's 103 vertices could move, and the RMS distance to
  // the undented hood went from 0.0074 to 0.0081, worse than found).
  ASSERT_EQ(repairs.size(), 2u);
  for (const auto& repair : repairs) {
    double nearest = 1e300;
    for (const auto& d : defects)
      nearest = (std::min)(nearest, std::sqrt(CGAL::squared_distance(
                                        mesh.point(repair.irregularity.peak_vertex), d.centre)) /
                                        d.radius);
    EXPECT_LT(nearest, 3.0) << HB::describe(repair.irregularity);
  }
  std::set<HB::vertex_descriptor> movable;
  std::size_t total_iterations = 0;
  for (const auto& repair : repairs) {
    // The faces faired: the region and a margin of detection_scale = 3 rings around it.
    const std::set<HB::face_descriptor> faired(repair.faired_faces.begin(),
                                               repair.faired_faces.end());
    EXPECT_EQ(faired.size(), repair.faired_faces.size());
    for (auto f : repair.irregularity.faces)
      EXPECT_EQ(faired.count(f), 1u);
    EXPECT_GT(faired.size(), repair.irregularity.faces.size());
    EXPECT_TRUE(repair.repaired) << repair.failure;
    EXPECT_TRUE(repair.failure.empty());
    total_iterations += repair.report.iterations;
    HL::movable_vertices(mesh, repair.faired_faces, std::inserter(movable, movable.end()));
  }
  EXPECT_EQ(iterations.size(), total_iterations);

  // Each defect is mostly gone: the RMS distance to the undented surface over the defect's
  // vertices falls far below the defect's height.
  for (const auto& d : defects) {
    double before = 0, after = 0;
    std::size_t count = 0;
    for (auto v : vertices(mesh))
      if (CGAL::squared_distance(undented.point(v), d.centre) < d.radius * d.radius) {
        before += CGAL::squared_distance(dented.point(v), undented.point(v));
        after += CGAL::squared_distance(mesh.point(v), undented.point(v));
        ++count;
      }
    before = std::sqrt(before / double(count));
    after = std::sqrt(after / double(count));
    std::size_t movable_in_defect = 0;
    for (auto v : vertices(mesh))
      if (CGAL::squared_distance(undented.point(v), d.centre) < d.radius * d.radius)
        movable_in_defect += movable.count(v);
    EXPECT_EQ(movable_in_defect, count);
    EXPECT_LT(after, 0.2 * before);
  }
  // Vertices that no region could move are bit-identical.
  for (auto v : vertices(mesh))
    if (movable.count(v) == 0) {
      EXPECT_EQ(mesh.point(v), dented.point(v));
    }
}

// Regions that touch are joined into the first if both reach the confidence, on either mesh
// type; the others are left as they are.
template <typename Mesh>
void check_joining_of_touching_regions()
{
  test::Soup soup = test::grid(
      12, 1.0, 0, 0, [](double, double) { return 0.0; }, 0.0, 1);
  const Mesh mesh = test::to_mesh<Mesh>(soup);
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  // Faces by the x of their centroid: strips [0, 2), [2, 4) (touching), [8, 10) apart.
  auto strip = [&](double from, double to, double confidence, double score) {
    HL::Highlight_line_irregularity<Mesh> r;
    for (face_descriptor f : faces(mesh)) {
      double x = 0;
      for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
        x += get(CGAL::vertex_point, mesh, v).x() / 3;
      if (x >= from && x < to)
        r.faces.push_back(f);
    }
    r.confidence = confidence;
    r.score = score;
    r.number_of_anomalies = 1;
    return r;
  };
  std::vector<HL::Highlight_line_irregularity<Mesh>> regions{
      strip(0, 2, 0.9, 3), strip(8, 10, 0.8, 2), strip(2, 4, 0.7, 1), strip(4, 6, 0.1, 1)};
  const std::size_t faces_of_first = regions[0].faces.size() + regions[2].faces.size();
  HL::join_touching_irregularities(mesh, regions, 0.5);
  ASSERT_EQ(regions.size(), 3u);
  EXPECT_EQ(regions[0].faces.size(), faces_of_first);
  EXPECT_EQ(regions[0].score, 3.0);
  EXPECT_EQ(regions[0].number_of_anomalies, 2u);
  EXPECT_EQ(regions[1].score, 2.0);      // apart: left alone
  EXPECT_EQ(regions[2].confidence, 0.1); // touches the first, but below the confidence
  // A confidence out of [0, 1] is refused, the regions left as they were.
  for (double wrong : {-0.1, 1.5, std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_THROW(HL::join_touching_irregularities(mesh, regions, wrong), HL::Invalid_input);
    ASSERT_EQ(regions.size(), 3u);
    EXPECT_EQ(regions[0].faces.size(), faces_of_first);
  }
}

TEST(DetectAndFair, RepairsEveryDefectFoundAndTouchesNothingElse)
{
  for (bool local_residual : {false, true}) {
    SCOPED_TRACE(local_residual ? "local residual" : "bending");
    repair_every_defect_found_and_touch_nothing_else(local_residual);
  }
}

TEST(DetectAndFair, JoinsTouchingRegionsOnEitherMeshType)
{
  check_joining_of_touching_regions<HB::Mesh>();
  check_joining_of_touching_regions<test::Polyhedron>();
}

// The fairing margin grows a region by rings of faces, up to a sharp edge and not across it.
template <typename Mesh>
void check_that_the_fairing_margin_stops_at_sharp_edges()
{
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  const Mesh mesh = test::to_mesh<Mesh>(test::grid(80, 2.0 / 80, -1, -1, folded, 0.0, 1));
  const double e = 2.0 / 80;
  auto centroid_x = [&](face_descriptor f) {
    double x = 0;
    for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      x += get(CGAL::vertex_point, mesh, v).x() / 3;
    return x;
  };
  // A strip of faces 3 to 6 edges left of the crease at x = 0.1, 10 edges long.
  std::vector<face_descriptor> strip;
  for (face_descriptor f : faces(mesh)) {
    const double x = centroid_x(f);
    double y = 0;
    for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      y += get(CGAL::vertex_point, mesh, v).y() / 3;
    if (x > 0.1 - 6 * e && x < 0.1 - 3 * e && std::abs(y) < 5 * e)
      strip.push_back(f);
  }
  ASSERT_FALSE(strip.empty());
  const auto points = get(CGAL::vertex_point, mesh);
  // Two rings: 2 edges farther on each side, nothing else.
  const auto two = HL::grown_face_region(mesh, strip, 2, 60.0, points);
  double lowest = 1e300, highest = -1e300;
  for (auto f : two) {
    lowest = (std::min)(lowest, centroid_x(f));
    highest = (std::max)(highest, centroid_x(f));
  }
  EXPECT_GT(lowest, 0.1 - 8 * e);
  EXPECT_LT(highest, 0.1 - e);
  EXPECT_GT(two.size(), strip.size());
  // Ten rings reach the crease and stop there.
  const auto ten = HL::grown_face_region(mesh, strip, 10, 60.0, points);
  for (auto f : ten)
    for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      EXPECT_LT(get(CGAL::vertex_point, mesh, v).x(), 0.1 + 0.5 * e);
  EXPECT_GT(ten.size(), two.size());
  // Negative rings and sharp edge angles out of (0, 180] are refused.
  EXPECT_THROW(HL::grown_face_region(mesh, strip, -1, 60.0, points), HL::Invalid_input);
  for (double wrong : {0.0, -30.0, 181.0, std::numeric_limits<double>::quiet_NaN()})
    EXPECT_THROW(HL::grown_face_region(mesh, strip, 2, wrong, points), HL::Invalid_input);
}

TEST(DetectAndFair, TheFairingMarginStopsAtSharpEdges)
{
  check_that_the_fairing_margin_stops_at_sharp_edges<HB::Mesh>();
  check_that_the_fairing_margin_stops_at_sharp_edges<test::Polyhedron>();
}

// The fairing margin is the caller's: with `fairing_margin(k)` each region is faired grown by
// exactly k rings (0: the region as found), and a margin out of [0, 1000] is refused before
// anything moves, on either mesh type.
TEST(DetectAndFair, FairsWithTheCallersMargin)
{
  test::Soup soup;
  HB::Mesh mesh = HB::hood_with_one_defect(soup);
  const HB::Mesh dented = mesh;
  const auto lights = HL::default_light_setup(mesh, HLP::number_of_lines(30));
  for (int margin : {0, 1}) {
    SCOPED_TRACE(margin);
    mesh = dented;
    const auto repairs = CGAL::detect_and_fair_highlight_line_irregularities(
        mesh, lights, HLP::fairing_margin(CGAL::parameters::number_of_iterations(2), margin));
    ASSERT_FALSE(repairs.empty());
    ASSERT_TRUE(repairs[0].repaired) << repairs[0].failure;
    const auto expected = HL::grown_face_region(dented, repairs[0].irregularity.faces, margin, 60.0,
                                                get(CGAL::vertex_point, dented));
    EXPECT_EQ(repairs[0].faired_faces, expected);
    if (margin == 0) {
      EXPECT_EQ(repairs[0].faired_faces, repairs[0].irregularity.faces);
    } else {
      EXPECT_GT(repairs[0].faired_faces.size(), repairs[0].irregularity.faces.size());
    }
  }
  for (auto v : vertices(mesh))
    soup.points[std::size_t(v)] = dented.point(v);
  test::Polyhedron polyhedron = test::to_mesh<test::Polyhedron>(soup);
  const test::Polyhedron polyhedron_before = polyhedron;
  mesh = dented;
  for (int wrong : {-1, 1001}) {
    EXPECT_THROW(CGAL::detect_and_fair_highlight_line_irregularities(mesh, lights,
                                                                     HLP::fairing_margin(wrong)),
                 HL::Invalid_input);
    EXPECT_THROW(CGAL::detect_and_fair_highlight_line_irregularities(polyhedron, lights,
                                                                     HLP::fairing_margin(wrong)),
                 HL::Invalid_input);
  }
  for (auto v : vertices(mesh))
    EXPECT_EQ(mesh.point(v), dented.point(v));
  auto p = vertices(polyhedron).begin();
  for (auto q = vertices(polyhedron_before).begin(); q != vertices(polyhedron_before).end();
       ++p, ++q)
    EXPECT_EQ((*p)->point(), (*q)->point());
}

// A dent next to a crease, faired on its own disc up to the crease (the region a user would
// select, as the automatic mode's regions stop at sharp edges): the default energy leaves the
// crease's curvature outside the region, so the repair ends about as close to the undented
// surface as PMP::fair()'s (measured: 0.99 and 1.08 times its RMS distance; with the crease's
// curvature continued into the region 0.70 and 1.64 times, and on the shared fandisk's dents
// 1.58 of the dent's RMS as the median against PMP::fair()'s 0.52), and the other side of the
// crease does not move.
TEST(DetectAndFair, FairsADentNextToACreaseWithoutContinuingTheCrease)
{
  const double e = 2.0 / 80;
  const HB::Mesh undented = test::to_mesh<HB::Mesh>(test::grid(80, e, -1, -1, folded, 0.0, 1));
  for (unsigned seed : {1u, 2u}) {
    SCOPED_TRACE(seed);
    HB::Mesh mesh = undented;
    const auto defects = HB::inject_defects(mesh, 1, 5.0, 1.0, seed, [&](HB::vertex_descriptor v) {
      const HB::Point& p = undented.point(v);
      return p.x() > 0.1 - 6.5 * e && p.x() < 0.1 - 5.5 * e && std::abs(p.y()) < 0.4;
    });
    ASSERT_EQ(defects.size(), 1u);
    const HB::Mesh dented = mesh;
    const auto disc = HB::defect_disc(mesh, defects[0], defects[0].radius + 2 * e);
    CGAL::fair_with_highlight_lines(mesh, disc, HL::default_light_setup(mesh));
    HB::Mesh by_pmp = dented;
    std::vector<HB::vertex_descriptor> movable;
    HL::movable_vertices(by_pmp, disc, std::back_inserter(movable));
    CGAL::Polygon_mesh_processing::fair(by_pmp, movable);
    const auto ours = HB::repair_outcome(undented, dented, mesh, defects);
    const auto pmp = HB::repair_outcome(undented, dented, by_pmp, defects);
    std::cout << "dent next to a crease, RMS to the undented surface: " << ours.before[0] << " -> "
              << ours.after[0] << " (PMP::fair " << pmp.after[0] << ")\n";
    EXPECT_LT(ours.after[0], 1.15 * pmp.after[0]);
    for (auto v : vertices(mesh))
      if (undented.point(v).x() > 0.1 + 1e-9) {
        EXPECT_EQ(mesh.point(v), dented.point(v));
      }
  }
}

TEST(DetectAndFair, SurfaceMeshAndPolyhedronAgree)
{
  test::Soup soup;
  HB::Mesh mesh = HB::hood_with_one_defect(soup);
  test::Polyhedron polyhedron = test::to_mesh<test::Polyhedron>(soup);
  const auto lights = HL::default_light_setup(mesh, HLP::number_of_lines(30));
  const auto a = CGAL::detect_and_fair_highlight_line_irregularities(mesh, lights);
  const auto b = CGAL::detect_and_fair_highlight_line_irregularities(polyhedron, lights);
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), a.size());
  EXPECT_TRUE(a[0].repaired && b[0].repaired);
  EXPECT_EQ(a[0].report.iterations, b[0].report.iterations);
  // Polyhedron_3 enumerates vertices in insertion order, as the soup gave them.
  std::size_t i = 0;
  for (auto v : vertices(polyhedron))
    EXPECT_LT(
        CGAL::squared_distance(v->point(), mesh.point(HB::vertex_descriptor(std::uint32_t(i++)))),
        1e-20);
}

void fair_the_demo_roof_dent_and_leave_the_design_alone(bool local_residual);

TEST(DetectAndFair, FairsTheDemoRoofDentAndLeavesTheDesignAlone)
{
  for (bool local_residual : {false, true}) {
    SCOPED_TRACE(local_residual ? "local residual" : "bending");
    fair_the_demo_roof_dent_and_leave_the_design_alone(local_residual);
  }
}

// The automatic mode on a dent in a flat plate (a regular 40 x 40 grid): the dent is found as a
// defect and faired, nothing far from it moves. Measured: the RMS distance to the undented
// plate 0.0021 -> 0.0003 (3 iterations, CONVERGED) on each seed; before the tie of the plate's
// principal axes was left out of the mirror symmetry, the dent was design and skipped.
TEST(DetectAndFair, RepairsADentOnAFlatPlate)
{
  for (unsigned seed : {1u, 2u, 3u}) {
    const HB::Mesh undented = flat_plate();
    HB::Mesh mesh = undented;
    const auto defects = HB::inject_defects(mesh, 1, 4.0, 0.5, seed, [](auto) { return true; });
    ASSERT_EQ(defects.size(), 1u);
    const HB::Mesh dented = mesh;
    auto rms_to_undented = [&](const HB::Mesh& m) {
      double sum = 0;
      for (auto v : vertices(m))
        sum += CGAL::squared_distance(m.point(v), undented.point(v));
      return std::sqrt(sum / double(num_vertices(m)));
    };
    const auto repairs = CGAL::detect_and_fair_highlight_line_irregularities(
        mesh, HL::default_light_setup(mesh, HLP::number_of_lines(30)));
    std::size_t repaired = 0;
    for (const auto& r : repairs)
      repaired += r.repaired;
    EXPECT_GE(repaired, 1u) << "seed " << seed;
    EXPECT_LT(rms_to_undented(mesh), 0.3 * rms_to_undented(dented)) << "seed " << seed;
    std::size_t moved_far = 0; // vertices farther than 4R from the dent that moved
    for (auto v : vertices(mesh))
      moved_far += CGAL::squared_distance(dented.point(v), defects[0].centre) >
                       std::pow(4 * defects[0].radius, 2) &&
                   mesh.point(v) != dented.point(v);
    EXPECT_EQ(moved_far, 0u) << "seed " << seed;
  }
}

TEST(DetectAndFair, RejectsAMinimumConfidenceOutOfItsDomain)
{
  HB::vertex_descriptor centre;
  HB::Mesh mesh = HB::demo_beetle(centre);
  const HB::Mesh dented = mesh;
  EXPECT_THROW(CGAL::detect_and_fair_highlight_line_irregularities(
                   mesh, HL::default_light_setup(mesh), HLP::minimum_confidence(1.5)),
               HL::Invalid_input);
  for (auto v : vertices(mesh))
    EXPECT_EQ(mesh.point(v), dented.point(v));
}

// The demo's automatic mode (60 lines, the default 3 x 2 light setups), with either measure
// (the bending measure with 3 x 4 setups, as above).
void fair_the_demo_roof_dent_and_leave_the_design_alone(bool local_residual)
{
  HB::vertex_descriptor centre;
  HB::Mesh mesh = HB::demo_beetle(centre);
  const HB::Mesh dented = mesh;
  const auto repairs = CGAL::detect_and_fair_highlight_line_irregularities(
      mesh, HL::default_light_setup(mesh, HLP::number_of_lines(60)),
      HLP::combine(HLP::number_of_offsets(local_residual ? 2 : 4),
                   CGAL::parameters::number_of_iterations(3), HLP::local_residual(local_residual)));
  ASSERT_GE(repairs.size(), 2u);
  EXPECT_TRUE(holds(mesh, repairs[0].irregularity, centre));
  EXPECT_TRUE(repairs[0].repaired) << repairs[0].failure;
  EXPECT_FALSE(repairs[0].skipped);
  std::set<HB::vertex_descriptor> movable;
  HL::movable_vertices(mesh, repairs[0].faired_faces, std::inserter(movable, movable.end()));
  for (std::size_t i = 1; i < repairs.size(); ++i) {
    EXPECT_TRUE(repairs[i].skipped) << HB::describe(repairs[i].irregularity);
    EXPECT_FALSE(repairs[i].repaired);
    EXPECT_NE(repairs[i].failure.find("skipped"), std::string::npos);
  }
  // Nothing but the roof moved.
  for (auto v : vertices(mesh))
    if (movable.count(v) == 0) {
      EXPECT_EQ(mesh.point(v), dented.point(v));
    }
  // And the whole dent could move (the local residual's region is centred on the dent's near
  // flank, where the lines are displaced most: without the fairing margin its far flank stayed
  // out, and dented).
  HB::Mesh undented;
  std::ifstream in(std::string(HIGHLIGHT_LINES_DATA_DIR) + "/beetle.off");
  ASSERT_TRUE(in && CGAL::IO::read_OFF(in, undented));
  // (The dent's rim, pressed by less than a hundredth of its depth, may lie on the border.)
  double depth = 0;
  for (auto v : vertices(mesh))
    depth =
        (std::max)(depth, std::sqrt(CGAL::squared_distance(dented.point(v), undented.point(v))));
  std::size_t dent_vertices = 0, movable_dent_vertices = 0;
  for (auto v : vertices(mesh))
    if (CGAL::squared_distance(dented.point(v), undented.point(v)) > CGAL::square(0.01 * depth)) {
      ++dent_vertices;
      movable_dent_vertices += movable.count(v);
    }
  EXPECT_GT(dent_vertices, 50u);
  EXPECT_EQ(movable_dent_vertices, dent_vertices);
  // And the roof ends much closer to the undented roof than the dent left it (RMS distance to
  // the undented surface of the vertices within the dent's radius; measured: 0.22 of the dent's
  // with the bending measure, 0.055 with the local residual).
  HB::Injected_defect dent;
  dent.centre = undented.point(centre);
  dent.centre_vertex = centre;
  for (auto v : vertices(mesh))
    if (CGAL::squared_distance(dented.point(v), undented.point(v)) > CGAL::square(0.01 * depth))
      dent.radius = (std::max)(dent.radius,
                               std::sqrt(CGAL::squared_distance(undented.point(v), dent.centre)));
  const HB::Repair_outcome outcome = HB::repair_outcome(undented, dented, mesh, {dent});
  std::cout << "roof dent RMS to the undented surface: " << outcome.before[0] << " -> "
            << outcome.after[0] << "\n";
  EXPECT_LT(outcome.after[0], 0.4 * outcome.before[0]);
}

TEST(DetectAndFair, RecordsRegionsThatCannotBeFairedAndGoesOn)
{
  HB::Mesh mesh = smooth_hood(4, 40);
  HB::inject_defects(mesh, 1, 4.0, 0.5, 4, [](auto) { return true; });
  const HB::Mesh before = mesh;
  const auto lights = HL::default_light_setup(mesh, HLP::number_of_lines(30));
  // A margin of 0 and a tiny scale make regions too thin for some to hold a movable vertex;
  // whatever happens, nothing becomes NaN and refused regions are untouched.
  const auto repairs = CGAL::detect_and_fair_highlight_line_irregularities(
      mesh, lights,
      HLP::combine(HLP::region_margin(0), HLP::detection_scale(1.0),
                   CGAL::parameters::number_of_iterations(3)));
  for (auto v : vertices(mesh)) {
    const auto& p = mesh.point(v);
    EXPECT_TRUE(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()));
  }
  for (const auto& repair : repairs)
    if (!repair.repaired) {
      EXPECT_FALSE(repair.failure.empty());
    }
  // An invalid fairing parameter is refused before anything moves.
  mesh = before;
  EXPECT_THROW(
      CGAL::detect_and_fair_highlight_line_irregularities(mesh, lights, HLP::fairness_weight(-1.0)),
      HL::Invalid_input);
  for (auto v : vertices(mesh))
    EXPECT_EQ(mesh.point(v), before.point(v));
}

} // namespace

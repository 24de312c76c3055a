// fair_with_highlight_lines() on dents pressed into real meshes (a seeded subset of
// benchmark_real_dents: one centre per mesh of ../shared/data, both depths, both energies).
//
// Hard guarantees, on every case: a result (no exception), converged within 50 iterations, no
// flipped face against the dented input, nothing but the movable vertices moved (bit for bit),
// every coordinate finite. Quality, on the 1 ē dents: the fairing removes most of the dent; on
// both depths, Fairness_energy::CURVATURE_VARIATION ends closer to the undented surface and its
// highlight lines than PMP::fair(). The 0.3 ē dents get the hard guarantees only: the undented
// patch is not fair either, and fairing the region changes it by more than a shallow dent, so the
// faired region may end further from the undented surface than the dented input (benchmark: up
// to 2.1 times the input's RMS distance on smooth patches, 3.5 times on rough ones).
#include "fairing_quality.h"
#include "real_dent_cases.h"
#include "flipped_faces.h"
#include "forwarding_solver.h"
#include "test_meshes.h"

#include <CGAL/Highlight_lines/Fairing_report.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/Highlight_lines/fairing_building_blocks.h>
#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/fair_with_highlight_lines.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {
namespace HB = Highlight_lines_benchmark;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;
typedef HB::Dent_mesh Mesh;

// The seed of benchmark_real_dents (its default): the cases below are the first centre of each
// mesh in its table, where the thresholds were measured.
const std::uint32_t seed = 2026;

// Quality thresholds on the 1 ē dents, as ratios of the faired mesh's measure to the dented
// input's (both fair_with_highlight_lines() energies), measured with benchmark_real_dents
// --table (seed 2026, up to 3 centres per mesh: 30 cases, 15 of them at 1 ē) and set ~25 %
// above the worst value measured:
// - smooth patches (10 cases at 1 ē): RMS distance of the movable vertices to the undented
//   surface at most 0.615 times the input's (worst: rocker-arm_v6718_d1, this test's rocker-arm
//   case, with MEAN_CURVATURE; 0.598 with WILLMORE; median 0.22), and the RMS deviation of the
//   highlight nodes from the undented surface's lines at most 0.380 times the input's (same
//   case; median 0.19).
const double smooth_rms_ratio = 0.77;
const double smooth_deviation_ratio = 0.48;
// - rough patches (the smoothest patches of meshes with too few smooth ones; 5 cases at 1 ē):
//   the fairing flattens curvature that the undented surface has, and may end no closer to it
//   than the input: RMS ratio up to 1.026 (rocker-arm_v702_d1), deviation ratio up to 1.084
//   (bunny_v1271_d1, this test's bunny case; medians 0.69 and 0.32; spot_v618_d1, this test's
//   spot case: 0.34 and 0.30). Only a bound against gross degradation is asserted.
const double rough_rms_ratio = 1.3;
const double rough_deviation_ratio = 1.35;
// Fairness_energy::CURVATURE_VARIATION against PMP::fair() (continuity 1, default parameters)
// on the same case, both depths: over the 30 cases of the benchmark the RMS ratio is at most
// 1.06 (median 0.55); on this test's cases (the first centre of each mesh) at most 0.60
// (bunny_v1271_d0.3), and the highlight-line deviation ratio at most 0.69 (bunny). Thresholds
// ~25 % above.
const double cv_to_pmp_rms_ratio = 0.75;
const double cv_to_pmp_deviation_ratio = 0.87;
// Iterations: at most 17 measured (rocker-arm_v4149_d1, WILLMORE).
const std::size_t max_iterations = 50;

// The report's status and history, for failure messages.
std::string describe(const HL::Fairing_report& report)
{
  std::ostringstream out;
  out << "status " << HL::to_string(report.status) << ", " << report.iterations
      << " iterations; history (target_value, relative_max_displacement, restrained_vertices, "
         "step_scale):";
  for (const HL::Fairing_report::Iteration& it : report.history)
    out << "\n  " << it.target_value << ", " << it.relative_max_displacement << ", "
        << it.restrained_vertices << ", " << it.step_scale;
  return out.str();
}

// The lowest F of the iterates the fairing stepped from (history[i].target_value is F before
// step i).
double lowest_target_value(const HL::Fairing_report& report)
{
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < report.iterations && i < report.history.size(); ++i)
    lowest = (std::min)(lowest, report.history[i].target_value);
  return lowest;
}

bool all_finite(const Mesh& mesh)
{
  for (Mesh::Vertex_index v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      return false;
  }
  return true;
}

// Fairs a copy of the case's dented mesh into `result` with the given energy and checks the hard
// guarantees: no exception, converged within the iteration bound, every coordinate finite,
// nothing but the movable vertices moved (bit for bit), no flip by the package's definition (a
// face folded in the input may unfold). Returns false if the fairing threw.
bool fair_with_hard_guarantees(const HB::Real_dent_case& c, HL::Fairness_energy energy,
                               const std::vector<Mesh::Vertex_index>& movable, Mesh& result)
{
  result = c.input;
  HL::Fairing_report report;
  try {
    report =
        CGAL::fair_with_highlight_lines(result, c.region, c.lights, HLP::fairness_energy(energy));
  } catch (const HL::Fairing_failure& e) {
    ADD_FAILURE() << "Fairing_failure: " << e.what() << "; " << describe(e.report());
    return false;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "exception: " << e.what();
    return false;
  }
  // A stall (scan-like triangulations) is a valid end: the mesh is then the iterate of lowest F.
  EXPECT_TRUE(report.converged() || report.status == HL::Fairing_report::Status::STALLED)
      << describe(report);
  if (report.status == HL::Fairing_report::Status::STALLED) {
    EXPECT_LE(report.history.back().target_value, lowest_target_value(report) * (1 + 1e-9))
        << describe(report);
  }
  EXPECT_LE(report.iterations, max_iterations) << describe(report);
  EXPECT_TRUE(all_finite(result));
  EXPECT_EQ(HB::count_moved_vertices_outside(result, c.input, movable), 0u);
  EXPECT_TRUE(test::flipped_faces(c.input, result).empty()) << describe(report);
  return true;
}

const HL::Fairness_energy all_energies[] = {HL::Fairness_energy::WILLMORE,
                                            HL::Fairness_energy::MEAN_CURVATURE,
                                            HL::Fairness_energy::CURVATURE_VARIATION};

std::string energy_name(HL::Fairness_energy energy)
{
  switch (energy) {
  case HL::Fairness_energy::WILLMORE:
    return "WILLMORE";
  case HL::Fairness_energy::MEAN_CURVATURE:
    return "MEAN_CURVATURE";
  default:
    return "CURVATURE_VARIATION (default)";
  }
}

// One shared mesh per test; skipped if ../shared/data does not have it.
// Scan-like triangulations: the mesh jittered tangentially by up to 0.45 ē before the dent
// (benchmark_real_dents --jitter 0.45 --seed 7), one 1 ē dent.
std::vector<HB::Real_dent_case> scan_like_dent_cases(const Mesh& mesh, const std::string& stem)
{
  HB::Real_dent_options options;
  options.max_centres = 1;
  options.depths = {1.0};
  options.jitter = 0.45;
  return HB::make_real_dent_cases(mesh, stem, 7, options);
}

class RealDentTest : public ::testing::TestWithParam<const char*>
{
protected:
  void SetUp() override
  {
    stem = GetParam();
    if (!std::ifstream(test::shared_data(stem + ".off")))
      GTEST_SKIP() << test::shared_data(stem + ".off") << " not found";
    ASSERT_TRUE(test::read_shared_mesh(stem + ".off", mesh)) << test::shared_data(stem + ".off");
  }

  std::string stem;
  Mesh mesh;
};

TEST_P(RealDentTest, FairingKeepsItsGuaranteesAndRemovesDeepDents)
{
  HB::Real_dent_options options;
  options.max_centres = 1;
  const std::vector<HB::Real_dent_case> cases = HB::make_real_dent_cases(mesh, stem, seed, options);
  // Every mesh gives a case (a rough patch if it has no smooth one), at both depths.
  ASSERT_EQ(cases.size(), options.depths.size()) << stem;

  for (const HB::Real_dent_case& c : cases) {
    std::vector<Mesh::Vertex_index> movable;
    HL::movable_vertices(c.input, c.region, std::back_inserter(movable));
    ASSERT_FALSE(movable.empty()) << c.name;
    const HB::Region_info<Mesh> info(c.input, c.region);
    const bool deep = c.dent_depth >= 0.99 * c.mean_edge_length; // the 1 ē dents
    const double input_rms = HB::rms_distance_to_surface(c.input, c.truth, info);
    const double input_deviation =
        HB::deviation_from_reference(c.input, c.truth, info, c.lights).rms;

    Mesh pmp = c.input;
    ASSERT_TRUE(CGAL::Polygon_mesh_processing::fair(pmp, movable));
    const double pmp_rms = HB::rms_distance_to_surface(pmp, c.truth, info);
    const double pmp_deviation = HB::deviation_from_reference(pmp, c.truth, info, c.lights).rms;

    for (const HL::Fairness_energy energy : all_energies) {
      SCOPED_TRACE(c.name + (c.smooth ? " (smooth patch)" : " (rough patch)") + ", centre v" +
                   std::to_string(std::size_t(c.centre)) + ", " + energy_name(energy));
      Mesh result;
      if (!fair_with_hard_guarantees(c, energy, movable, result))
        continue;
      // The benchmark's own flip count (no face may turn by more than 90 degrees here: these
      // inputs have no folded triangle).
      EXPECT_EQ(HB::count_flipped_faces(result, c.input), 0u);

      const double rms = HB::rms_distance_to_surface(result, c.truth, info);
      const double deviation = HB::deviation_from_reference(result, c.truth, info, c.lights).rms;
      // The curvature-continuous energy ends closer to the undented surface than PMP::fair, at
      // both depths, positions and highlight lines.
      if (energy == HL::Fairness_energy::CURVATURE_VARIATION) {
        // fandisk: a plane; PMP::fair is exact, the iteration stops at steps below 0.001 ē.
        const double floor = 1e-4 * c.mean_edge_length;
        EXPECT_LE(rms, cv_to_pmp_rms_ratio * pmp_rms + floor)
            << "RMS distance to the undented surface / depth: faired " << rms / c.dent_depth
            << ", PMP::fair " << pmp_rms / c.dent_depth;
        EXPECT_LE(deviation, cv_to_pmp_deviation_ratio * pmp_deviation + floor)
            << "highlight line deviation / ē: faired " << deviation / c.mean_edge_length
            << ", PMP::fair " << pmp_deviation / c.mean_edge_length;
      }
      if (!deep)
        continue;
      EXPECT_LE(rms, (c.smooth ? smooth_rms_ratio : rough_rms_ratio) * input_rms)
          << "RMS distance to the undented surface / depth: faired " << rms / c.dent_depth
          << ", input " << input_rms / c.dent_depth;
      EXPECT_LE(deviation,
                (c.smooth ? smooth_deviation_ratio : rough_deviation_ratio) * input_deviation)
          << "highlight line deviation from the undented surface's / ē: faired "
          << deviation / c.mean_edge_length << ", input " << input_deviation / c.mean_edge_length;
    }
  }
}

// Scan-like triangulations: the mesh jittered tangentially by up to 0.45 ē before the dent
// (benchmark_real_dents --jitter 0.45 --seed 7: corners down to 0.12°, up to 199 folded
// triangles in a region), 1 ē dents. Only the hard guarantees (measured: at most 29 iterations
// over the 30 cases of that run). Before the local step control, a third to a half of these
// fairings ended with an exception or at the iteration bound.
TEST_P(RealDentTest, ScanLikeTriangulationsKeepTheHardGuarantees)
{
  const std::vector<HB::Real_dent_case> cases = scan_like_dent_cases(mesh, stem);
  ASSERT_EQ(cases.size(), 1u) << stem;
  const HB::Real_dent_case& c = cases.front();
  std::vector<Mesh::Vertex_index> movable;
  HL::movable_vertices(c.input, c.region, std::back_inserter(movable));
  for (const HL::Fairness_energy energy : all_energies) {
    SCOPED_TRACE(c.name + ", jitter 0.45, " + energy_name(energy));
    Mesh result;
    fair_with_hard_guarantees(c, energy, movable, result);
  }
}

// Pits as deep as they are wide (5 ē deep, radius 5 ē; benchmark_real_dents --depths 5,3, the
// first centre of each mesh), the default energy. Moving along the vertex normals alone leaves
// them where they were: the normals of a pit's walls point across it, and the flip guard holds
// the walls where they meet (RMS to the undented surface 0.26-0.30 of the depth, as the
// input's). The run then starts again from the region's uniform bi-Laplacian fill and keeps that
// second run where it lowers F fourfold without a flip (Fairing_report::restarted_from_fill).
// Measured: RMS / depth 0.0089 (camelhead), 0.0000 (fandisk, a plane), 0.0039 (spot); threshold
// 0.05. On the beetle (0.27), the bunny (0.33) and the rocker arm (0.37) the second run flips a
// face or gains less, and the first run is kept: the hard guarantees there, and that the first
// run's mesh comes back exactly.
TEST_P(RealDentTest, PitsAsDeepAsTheyAreWideAreFilled)
{
  HB::Real_dent_options options;
  options.max_centres = 1;
  options.depths = {5.0};
  const std::vector<HB::Real_dent_case> cases = HB::make_real_dent_cases(mesh, stem, seed, options);
  ASSERT_EQ(cases.size(), 1u) << stem;
  const HB::Real_dent_case& c = cases.front();
  SCOPED_TRACE(c.name);
  std::vector<Mesh::Vertex_index> movable;
  HL::movable_vertices(c.input, c.region, std::back_inserter(movable));
  Mesh result;
  if (!fair_with_hard_guarantees(c, HL::Fairness_energy::CURVATURE_VARIATION, movable, result))
    return;
  if (stem != "camelhead" && stem != "fandisk" && stem != "spot") {
    // The second run was tried and rejected (the visitor saw its iterations, the report does
    // not count them): the first run's mesh is returned exactly, the mesh a fairing bounded to
    // the first run's iterations (which then never restarts) returns.
    std::size_t visited = 0;
    Mesh rejected = c.input;
    const HL::Fairing_report report = CGAL::fair_with_highlight_lines(
        rejected, c.region, c.lights,
        HLP::fairing_visitor([&](const HL::Fairing_report::Iteration&) {
          ++visited;
          return true;
        }));
    EXPECT_FALSE(report.restarted_from_fill);
    EXPECT_GT(visited, report.iterations) << "no second run was tried";
    Mesh first_run_only = c.input;
    const HL::Fairing_report bounded = CGAL::fair_with_highlight_lines(
        first_run_only, c.region, c.lights,
        CGAL::parameters::number_of_iterations(int(report.iterations)));
    EXPECT_EQ(bounded.status, report.status);
    EXPECT_EQ(bounded.history.back().target_value, report.history.back().target_value);
    const std::size_t differing =
        std::size_t(std::count_if(movable.begin(), movable.end(), [&](Mesh::Vertex_index v) {
          return first_run_only.point(v) != rejected.point(v);
        }));
    EXPECT_EQ(differing, 0u) << "of " << movable.size() << " movable vertices";
    return;
  }
  const HB::Region_info<Mesh> info(c.input, c.region);
  EXPECT_LE(HB::rms_distance_to_surface(result, c.truth, info), 0.05 * c.dent_depth)
      << "input: " << HB::rms_distance_to_surface(c.input, c.truth, info) / c.dent_depth
      << " of the depth";
  Mesh again = c.input;
  const HL::Fairing_report report = CGAL::fair_with_highlight_lines(again, c.region, c.lights);
  EXPECT_TRUE(report.restarted_from_fill);
  EXPECT_GT(report.first_run_iterations, 0u);
  EXPECT_LT(report.first_run_iterations, report.iterations);
  // Both runs' iterations, then the energies of the mesh returned.
  EXPECT_EQ(report.history.size(), report.iterations + 1);
}

// A solver that records the pairs set_P() is called with: the first program's, and those of
// the later programs with a nonzero value.
struct Pattern_recording_solver : test::Forwarding_solver
{
  std::size_t programs = 0;
  std::set<std::pair<std::size_t, std::size_t>> declared, set_later;
  void resize(std::size_t n)
  {
    ++programs;
    inner.resize(n);
  }
  void set_P(std::size_t i, std::size_t j, double v)
  {
    if (programs == 1)
      declared.emplace(i, j);
    else if (v != 0)
      set_later.emplace(i, j);
    inner.set_P(i, j, v);
  }
};

// The first program of a fairing declares every entry that any of its programs sets, so that
// one symbolic analysis of the solver serves them all (internal/fairing/program_pattern.h): nodes
// move onto other edges and clamped cotangent weights cross zero from one iteration to the next,
// and the sliver and folded triangles of a scan-like triangulation do that most. Every energy.
TEST_P(RealDentTest, TheFirstProgramDeclaresEveryEntryOfTheLaterOnes)
{
  const std::vector<HB::Real_dent_case> cases = scan_like_dent_cases(mesh, stem);
  ASSERT_EQ(cases.size(), 1u) << stem;
  const HB::Real_dent_case& c = cases.front();
  for (const HL::Fairness_energy energy : all_energies) {
    SCOPED_TRACE(c.name + ", jitter 0.45, " + energy_name(energy));
    Mesh result = c.input;
    Pattern_recording_solver solver;
    CGAL::fair_with_highlight_lines(
        result, c.region, c.lights,
        HLP::combine(HLP::fairness_energy(energy), HLP::qp_solver(std::ref(solver))));
    EXPECT_GE(solver.programs, 2u);
    std::size_t undeclared = 0;
    for (const auto& entry : solver.set_later)
      undeclared += solver.declared.count(entry) == 0 ? 1 : 0;
    EXPECT_EQ(undeclared, 0u) << "undeclared, of " << solver.set_later.size()
                              << " entries set in the " << solver.programs - 1
                              << " programs after the first";
  }
}

INSTANTIATE_TEST_SUITE_P(RealDent, RealDentTest, ::testing::ValuesIn(HB::shared_mesh_stems()),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           std::string name = info.param;
                           for (char& ch : name)
                             if (ch == '-')
                               ch = '_';
                           return name;
                         });

// A stall on a scan-like triangulation (the Beetle's case of scan_like_dent_cases(): 191 of the
// region's 767 triangles folded). The programs, their weights frozen, predict F poorly there:
// F stops falling while the trust region halves step after step and the vertices held against
// flips creep (26 iterations before the rule, to steps below ε ē, ending at an F 10 % above the
// lowest). The fairing ends five held steps after the last iterate that lowered F by 10^-3 of
// itself, at the iterate of lowest F, with the status STALLED.
TEST(RealDentStall, AStallEndsFiveHeldStepsAfterTheLastProgressAtTheIterateOfLowestF)
{
  Mesh mesh;
  if (!std::ifstream(test::shared_data("beetle.off")))
    GTEST_SKIP() << test::shared_data("beetle.off") << " not found";
  ASSERT_TRUE(test::read_shared_mesh("beetle.off", mesh));
  const std::vector<HB::Real_dent_case> cases = scan_like_dent_cases(mesh, "beetle");
  ASSERT_EQ(cases.size(), 1u);
  const HB::Real_dent_case& c = cases.front();
  std::vector<Mesh::Vertex_index> movable;
  HL::movable_vertices(c.input, c.region, std::back_inserter(movable));
  Mesh result;
  ASSERT_TRUE(
      fair_with_hard_guarantees(c, HL::Fairness_energy::CURVATURE_VARIATION, movable, result));
  Mesh again = c.input;
  const HL::Fairing_report report = CGAL::fair_with_highlight_lines(again, c.region, c.lights);
  ASSERT_EQ(report.status, HL::Fairing_report::Status::STALLED) << describe(report);
  EXPECT_STREQ(HL::to_string(report.status), "STALLED");
  EXPECT_FALSE(report.converged());
  ASSERT_EQ(report.history.size(), report.iterations + 1) << describe(report);
  // The last iterate that made progress, by the rule's definition.
  std::size_t last_progress = 0;
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < report.iterations; ++i) {
    if (report.history[i].target_value < (1 - 1e-3) * lowest)
      last_progress = i;
    lowest = (std::min)(lowest, report.history[i].target_value);
  }
  EXPECT_EQ(report.iterations - last_progress, 5u) << describe(report);
  for (std::size_t i = report.iterations - 5; i < report.iterations; ++i)
    EXPECT_GT(report.history[i].restrained_vertices, 0u) << "step " << i;
  // The mesh returned is the iterate of lowest F (its energies are the history's last entry),
  // and it is the same mesh as the first call's, bit for bit.
  EXPECT_EQ(lowest, lowest_target_value(report));
  EXPECT_NEAR(report.history.back().target_value, lowest, 1e-9 * lowest) << describe(report);
  const std::size_t differing =
      std::size_t(std::count_if(movable.begin(), movable.end(), [&](Mesh::Vertex_index v) {
        return again.point(v) != result.point(v);
      }));
  EXPECT_EQ(differing, 0u);

  // A Polyhedron_3 copy of the same mesh stalls alike.
  typedef boost::graph_traits<test::Polyhedron> Polyhedron_traits;
  test::Polyhedron polyhedron;
  std::map<Mesh::Face_index, Polyhedron_traits::face_descriptor> face_copy;
  std::map<Mesh::Vertex_index, Polyhedron_traits::vertex_descriptor> vertex_copy;
  CGAL::copy_face_graph(
      c.input, polyhedron,
      CGAL::parameters::face_to_face_map(boost::make_assoc_property_map(face_copy))
          .vertex_to_vertex_map(boost::make_assoc_property_map(vertex_copy)));
  std::vector<Polyhedron_traits::face_descriptor> polyhedron_region;
  for (Mesh::Face_index f : c.region)
    polyhedron_region.push_back(face_copy.at(f));
  const HL::Fairing_report on_polyhedron =
      CGAL::fair_with_highlight_lines(polyhedron, polyhedron_region, c.lights);
  EXPECT_EQ(on_polyhedron.status, HL::Fairing_report::Status::STALLED) << describe(on_polyhedron);
  EXPECT_EQ(on_polyhedron.iterations, report.iterations);
  double largest_difference = 0;
  for (Mesh::Vertex_index v : movable)
    largest_difference =
        (std::max)(largest_difference,
                   std::sqrt(CGAL::squared_distance(vertex_copy.at(v)->point(), result.point(v))));
  // Alike up to the solver's tolerance: the two meshes' programs differ in the last bits (sums
  // in another order), and the cold starts after held steps let the active-set iterations take
  // other paths to the same optimum (measured 1.2e-7 e; the bound was 1e-9 e while those
  // programs were warm-started).
  EXPECT_LE(largest_difference, 1e-6 * c.mean_edge_length);
}

// The fairing also stops when all the steps still to come, estimated from the geometric tail of
// the last three, or of the last two where both were the programs' own minimisers, would
// together move no vertex by ε ē (on real dents the steps shrink by a factor of 0.002 to 0.3
// per iteration): it then ends within ε ē of where going on to steps of a ten-thousandth of
// that ends, in fewer iterations. Both depths: a 0.3 ē dent is often faired in two steps.
TEST(RealDentTail, StoppingOnTheGeometricTailEndsWithinEpsilonOfTheLimit)
{
  const double epsilon = 1e-3;
  std::size_t cases = 0, stopped_on_the_tail = 0;
  for (const std::string stem : HB::shared_mesh_stems()) {
    Mesh mesh;
    if (!test::read_shared_mesh(stem + ".off", mesh))
      continue;
    HB::Real_dent_options options;
    options.max_centres = 2;
    for (const HB::Real_dent_case& c : HB::make_real_dent_cases(mesh, stem, seed, options)) {
      SCOPED_TRACE(c.name);
      Mesh stopped = c.input, limit = c.input;
      const auto report = CGAL::fair_with_highlight_lines(stopped, c.region, c.lights,
                                                          HLP::convergence_threshold(epsilon));
      const auto on_to_the_limit = CGAL::fair_with_highlight_lines(
          limit, c.region, c.lights, HLP::convergence_threshold(1e-4 * epsilon));
      ASSERT_TRUE(report.converged()) << describe(report);
      ASSERT_TRUE(on_to_the_limit.converged()) << describe(on_to_the_limit);
      EXPECT_LT(report.iterations, on_to_the_limit.iterations);
      ++cases;
      if (report.history[report.iterations - 1].relative_max_displacement >= epsilon)
        ++stopped_on_the_tail;
      double farthest = 0;
      for (Mesh::Vertex_index v : mesh.vertices())
        farthest = (std::max)(farthest,
                              std::sqrt(CGAL::squared_distance(stopped.point(v), limit.point(v))));
      EXPECT_LE(farthest, epsilon * c.mean_edge_length) << describe(report);
    }
  }
  if (cases == 0)
    GTEST_SKIP() << "no mesh of " << HIGHLIGHT_LINES_SHARED_DATA_DIR;
  EXPECT_GE(2 * stopped_on_the_tail, cases); // measured: 16 of 22
}

// Where the steps shrink slowly (a contraction rate of 1/2 or more, as on scan-like
// triangulations and on large regions), the step is accelerated towards the limit that the last
// steps predict (Anderson acceleration, Fairing_report::Iteration::extrapolation). The fairing
// must still end where going on ends: within ε ē of a fairing run to steps of 10^-7 ē.
// Scan-like jitter of 0.45 ē (the benchmark's --jitter 0.45), the bunny and the camel head, with
// the mean curvature energy (the iteration is the same for every energy): measured, 2 of their
// 12 fairings accelerate, ending 0.11 and 0.004 ε ē away (a fairing of 2.4·10^4 movable vertices
// that accelerates takes 9 iterations instead of 16). With the default energy none of them
// accelerates any more since its mean curvature is fitted on the rings of slivers and folded
// triangles (2 of 12 did with the cotangent one).
TEST(RealDentTail, ExtrapolatingASlowTailEndsWithinEpsilonOfTheLimit)
{
  const double epsilon = 1e-3;
  std::size_t extrapolating = 0;
  bool any_mesh = false;
  for (const std::string stem : {"bunny", "camelhead"}) {
    Mesh mesh;
    if (!test::read_shared_mesh(stem + ".off", mesh))
      continue;
    any_mesh = true;
    HB::Real_dent_options options;
    options.jitter = 0.45;
    for (const HB::Real_dent_case& c : HB::make_real_dent_cases(mesh, stem, seed, options)) {
      SCOPED_TRACE(c.name);
      Mesh stopped = c.input;
      const auto report = CGAL::fair_with_highlight_lines(
          stopped, c.region, c.lights,
          HLP::combine(HLP::convergence_threshold(epsilon),
                       HLP::fairness_energy(HL::Fairness_energy::MEAN_CURVATURE)));
      const bool extrapolated =
          std::any_of(report.history.begin(), report.history.end(),
                      [](const HL::Fairing_report::Iteration& it) { return it.extrapolation > 1; });
      if (!extrapolated)
        continue;
      ++extrapolating;
      ASSERT_TRUE(report.converged()) << describe(report);
      Mesh limit = c.input;
      const auto on_to_the_limit = CGAL::fair_with_highlight_lines(
          limit, c.region, c.lights,
          HLP::combine(HLP::convergence_threshold(1e-4 * epsilon),
                       HLP::fairness_energy(HL::Fairness_energy::MEAN_CURVATURE),
                       CGAL::parameters::number_of_iterations(300)));
      ASSERT_TRUE(on_to_the_limit.converged()) << describe(on_to_the_limit);
      double farthest = 0;
      for (Mesh::Vertex_index v : mesh.vertices())
        farthest = (std::max)(farthest,
                              std::sqrt(CGAL::squared_distance(stopped.point(v), limit.point(v))));
      EXPECT_LE(farthest, epsilon * c.mean_edge_length) << describe(report);
    }
  }
  if (!any_mesh)
    GTEST_SKIP() << "no mesh of " << HIGHLIGHT_LINES_SHARED_DATA_DIR;
  EXPECT_GE(extrapolating, 1u); // the path is taken
}

// A region on a narrow part of a real mesh (the shared camel head; 369 faces, 116 movable
// vertices, 12 ē across, found while measuring region rules for the automatic mode).
// ∫ ‖∇H‖² alone is zero on any surface of constant mean curvature: the default energy then
// followed one into a pocket whose deepest vertex moved 35 ē, "converged". With the term
// μ Σ A_i H_i² (see internal::mean_curvature_weight()) it moves at most 1.6 ē, as PMP::fair()
// does (1.7 ē; Fairness_energy::WILLMORE 0.67 ē). Asserted: at most 2 ē, no flip, nothing else
// moved.
TEST(RealRegion, TheDefaultEnergyDoesNotDigAPocketIntoANarrowPart)
{
  Mesh mesh;
  if (!test::read_shared_mesh("camelhead.off", mesh))
    GTEST_SKIP() << test::shared_data("camelhead.off") << " not found";
  const std::pair<std::uint32_t, std::uint32_t> face_ranges[] = {
      {78, 79},       {81, 82},       {94, 94},       {121, 122},     {387, 389},
      {392, 392},     {406, 407},     {512, 513},     {530, 533},     {535, 535},
      {1315, 1316},   {1320, 1320},   {1324, 1325},   {1650, 1652},   {1654, 1658},
      {1692, 1693},   {1773, 1778},   {2408, 2408},   {2579, 2591},   {2597, 2597},
      {2635, 2641},   {2954, 2959},   {2975, 2975},   {3012, 3016},   {3020, 3020},
      {3023, 3024},   {5385, 5390},   {5402, 5402},   {5412, 5417},   {5904, 5909},
      {5913, 5918},   {5952, 5953},   {6033, 6038},   {6839, 6847},   {6854, 6856},
      {6896, 6901},   {7214, 7219},   {7268, 7269},   {7271, 7279},   {7283, 7285},
      {9637, 9642},   {9653, 9654},   {9664, 9669},   {10642, 10650}, {10654, 10668},
      {10768, 10769}, {11011, 11028}, {12924, 12926}, {13437, 13475}, {13491, 13493},
      {13605, 13625}, {14562, 14583}, {14586, 14588}, {14597, 14597}, {14625, 14627},
      {14736, 14750}, {14760, 14762}, {14769, 14774}, {14778, 14778}, {14787, 14787},
      {21723, 21723}, {21849, 21866}, {21899, 21902}, {21930, 21947},
  };
  std::vector<Mesh::Face_index> region;
  for (const auto& [first, last] : face_ranges)
    for (std::uint32_t f = first; f <= last; ++f)
      region.push_back(Mesh::Face_index(f));
  ASSERT_EQ(region.size(), 369u);
  std::vector<Mesh::Vertex_index> movable;
  HL::movable_vertices(mesh, region, std::back_inserter(movable));
  ASSERT_EQ(movable.size(), 116u);
  const double e = test::mean_edge_length(mesh);
  const auto lights = HL::default_light_setup(mesh, HLP::number_of_lines(30));

  Mesh faired = mesh;
  const HL::Fairing_report report = CGAL::fair_with_highlight_lines(faired, region, lights);
  EXPECT_TRUE(report.converged()) << describe(report);
  double farthest = 0;
  for (Mesh::Vertex_index v : movable)
    farthest =
        (std::max)(farthest, std::sqrt(CGAL::squared_distance(mesh.point(v), faired.point(v))));
  EXPECT_LE(farthest, 2 * e) << describe(report);
  EXPECT_EQ(HB::count_moved_vertices_outside(faired, mesh, movable), 0u);
  EXPECT_TRUE(test::flipped_faces(mesh, faired).empty());
}

// Regions of the shared meshes as they are (8 per mesh at seeded vertices, the faces within 10
// rings; rough, curved and creased parts included): the undented surface is the truth, so every
// move is a change the user did not ask for. The default fairing changes them less than
// PMP::fair() does (RMS of the movable vertices' moves; measured: median ratio 0.74 over these
// 48 regions, 0.66 over 180; ours moves more on 16 of the 48, by up to 5.0 ē on the camel head
// where PMP::fair() moves 0.73 ē), and keeps the hard guarantees on every one.
TEST(RealRegion, FairingUndentedRegionsChangesThemLessThanPMPFair)
{
  std::vector<double> ratios;
  double largest_move = 0;
  for (const std::string stem : HB::shared_mesh_stems()) {
    Mesh mesh;
    if (!test::read_shared_mesh(stem + ".off", mesh))
      continue;
    const double e = test::mean_edge_length(mesh);
    const auto lights = HL::default_light_setup(mesh, HLP::number_of_lines(30));
    for (const Mesh::Vertex_index centre : HB::seeded_vertices(mesh, 8, 5)) {
      SCOPED_TRACE(std::string(stem) + " v" + std::to_string(std::size_t(centre)));
      const std::vector<Mesh::Face_index> region = HB::faces_within_rings(mesh, centre, 10);
      std::vector<Mesh::Vertex_index> movable;
      HL::movable_vertices(mesh, region, std::back_inserter(movable));
      if (movable.empty())
        continue;
      Mesh ours = mesh, pmp = mesh;
      HL::Fairing_report report;
      ASSERT_NO_THROW(report = CGAL::fair_with_highlight_lines(ours, region, lights));
      EXPECT_LE(report.iterations, max_iterations);
      EXPECT_TRUE(all_finite(ours));
      EXPECT_EQ(HB::count_moved_vertices_outside(ours, mesh, movable), 0u);
      EXPECT_TRUE(test::flipped_faces(mesh, ours).empty());
      ASSERT_TRUE(CGAL::Polygon_mesh_processing::fair(pmp, movable));
      double ours_sum = 0, pmp_sum = 0;
      for (Mesh::Vertex_index v : movable) {
        const double moved = CGAL::squared_distance(mesh.point(v), ours.point(v));
        ours_sum += moved;
        pmp_sum += CGAL::squared_distance(mesh.point(v), pmp.point(v));
        largest_move = (std::max)(largest_move, std::sqrt(moved) / e);
      }
      ASSERT_GT(pmp_sum, 0);
      ratios.push_back(std::sqrt(ours_sum / pmp_sum));
    }
  }
  if (ratios.empty())
    GTEST_SKIP() << "no mesh of " << HIGHLIGHT_LINES_SHARED_DATA_DIR;
  std::sort(ratios.begin(), ratios.end());
  EXPECT_LT(ratios[ratios.size() / 2], 0.9);
  EXPECT_LT(largest_move, 8.0);
}

} // namespace

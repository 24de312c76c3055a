// Evaluation of detect_highlight_line_irregularities().
//
//   benchmark_detection            speed (Google Benchmark), then the recall/precision curves
//   benchmark_detection --curves   the curves only
//
// Curves: dents and bumps of radius 5 mean edge lengths (ē) and height h·ē, four per mesh,
// injected at random (seeded) into
//   - a smooth car hood, irregularly triangulated (jittered 80 x 80 grid, 12,800 triangles),
//     8 seeds: every region found is either a defect or a false alarm;
//   - the shared real meshes: these have irregularities of their own (creases, panel joints,
//     measurement noise). Regions found on the mesh before injection are its own; defects are
//     injected away from them, and a region overlapping them without holding a defect counts
//     as "own", not as a false alarm.
// Defects are placed where the lights show them (vertex normal within 45° of the light plane's
// normal). Recall: defects whose centre vertex lies in a region. Precision: regions holding a
// defect, over regions not counted as "own".
//
// Speed: the detection (3 x 2 light setups) on the bundled beetle Loop-subdivided twice
// (618,496 triangles), as a ratio to one compute_highlight_lines() on the same mesh measured
// in the same run.
#include "detection_evaluation.h"

#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/compute_highlight_lines.h>
#include <CGAL/detect_highlight_line_irregularities.h>

#include "../../test/Highlight_lines/model/test_meshes.h"

#include <benchmark/benchmark.h>

#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>

namespace {
namespace HB = Highlight_lines_benchmark;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;

const std::vector<double> heights{1.0, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01};

double hood(double x, double y)
{
  return 0.25 * (1 - 0.35 * x * x) - 0.12 * y * y + 0.05 * x * y;
}

std::vector<HB::Irregularity> detect(const HB::Mesh& mesh)
{
  std::vector<HB::Irregularity> found;
  CGAL::detect_highlight_line_irregularities(
      mesh, HL::default_light_setup(mesh, HLP::number_of_lines(30)), std::back_inserter(found));
  return found;
}

struct Curve_point
{
  std::size_t defects = 0, found = 0, regions = 0, true_regions = 0, own = 0;
};

void print_curve(const std::string& name, const std::vector<Curve_point>& points,
                 std::size_t meshes, std::size_t own_before)
{
  std::cout << "\n" << name << " (" << meshes << " meshes";
  if (own_before > 0)
    std::cout << ", " << own_before << " own regions before injection";
  std::cout << ")\n  h/ē     recall  precision  regions  own\n";
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Curve_point& p = points[i];
    const std::size_t judged = p.regions - p.own;
    std::cout << "  " << std::setw(5) << (i < heights.size() ? heights[i] : 0.0) << "  "
              << std::setw(7) << std::fixed << std::setprecision(3)
              << (p.defects ? double(p.found) / double(p.defects) : 1.0) << "  " << std::setw(9)
              << (judged ? double(p.true_regions) / double(judged) : 1.0) << "  " << std::setw(7)
              << p.regions << "  " << std::setw(3) << p.own << std::defaultfloat << "\n";
  }
}

void hood_curve()
{
  std::vector<Curve_point> curve(heights.size() + 1);
  for (unsigned seed = 1; seed <= 8; ++seed)
    for (std::size_t i = 0; i <= heights.size(); ++i) {
      HB::Mesh mesh = test::to_mesh<HB::Mesh>(test::grid(80, 2.0 / 80, -1, -1, hood, 0.3, seed));
      std::vector<HB::Injected_defect> defects;
      if (i < heights.size())
        defects = HB::inject_defects(mesh, 4, 5.0, heights[i], seed, [](auto) { return true; });
      const HB::Detection_score s = HB::match(mesh, defects, detect(mesh));
      curve[i].defects += s.defects;
      curve[i].found += s.found_defects;
      curve[i].regions += s.regions;
      curve[i].true_regions += s.true_regions;
    }
  print_curve("smooth hood; last row: no defect (false alarms)", curve, 8, 0);
}

void shared_curve(const std::string& name)
{
  HB::Mesh original;
  std::ifstream in(test::shared_data(name));
  if (!in || !CGAL::IO::read_OFF(in, original)) {
    std::cout << "\n" << name << ": not found, skipped\n";
    return;
  }
  // The mesh's own regions, and the vertices near them (no defect goes there).
  const auto own = detect(original);
  std::set<HB::vertex_descriptor> own_vertices;
  for (const auto& r : own)
    for (auto f : r.faces)
      for (auto v : CGAL::vertices_around_face(halfedge(f, original), original))
        own_vertices.insert(v);
  // Defects go where the lights can show them: on vertices facing the light plane.
  const auto lights = HL::default_light_setup(original, HLP::number_of_lines(30));
  auto normals = original.add_property_map<HB::vertex_descriptor, HB::Vector>("v:n").first;
  CGAL::Polygon_mesh_processing::compute_vertex_normals(original, normals);
  std::vector<Curve_point> curve(heights.size());
  for (unsigned seed = 1; seed <= 4; ++seed)
    for (std::size_t i = 0; i < heights.size(); ++i) {
      HB::Mesh mesh = original;
      const double radius = 5.0 * HB::mean_edge_length(mesh);
      const auto defects =
          HB::inject_defects(mesh, 4, 5.0, heights[i], seed, [&](HB::vertex_descriptor v) {
            if (normals[v] * lights.plane_normal() < 0.7)
              return false;
            for (auto w : own_vertices)
              if (CGAL::squared_distance(original.point(w), original.point(v)) <
                  4 * radius * radius)
                return false;
            return true;
          });
      const auto found = detect(mesh);
      const HB::Detection_score s = HB::match(mesh, defects, found);
      curve[i].defects += s.defects;
      curve[i].found += s.found_defects;
      curve[i].regions += s.regions;
      curve[i].true_regions += s.true_regions;
      // Regions without a defect that overlap the mesh's own ones are its own.
      for (const auto& r : found) {
        bool has_defect = false, overlaps_own = false;
        for (auto f : r.faces)
          for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh)) {
            overlaps_own = overlaps_own || own_vertices.count(v) > 0;
            for (const auto& d : defects)
              has_defect = has_defect ||
                           CGAL::squared_distance(mesh.point(v), d.centre) < d.radius * d.radius;
          }
        curve[i].own += !has_defect && overlaps_own;
      }
    }
  print_curve(name, curve, 4, own.size());
}

void curves()
{
  std::cout << "Detection recall and precision vs defect height h (radius 5 ē)\n";
  hood_curve();
  for (const char* name : {"beetle.off", "spot.off", "rocker-arm.off", "camelhead.off"})
    shared_curve(name);
}

// --- Speed --------------------------------------------------------------------------------

const HB::Mesh& refined_beetle()
{
  static std::unique_ptr<HB::Mesh> mesh;
  if (!mesh) {
    mesh = std::make_unique<HB::Mesh>();
    std::ifstream in(std::string(HIGHLIGHT_LINES_DATA_DIR) + "/beetle.off");
    if (!in || !CGAL::IO::read_OFF(in, *mesh))
      throw std::runtime_error("cannot read the bundled beetle");
    CGAL::Subdivision_method_3::Loop_subdivision(*mesh, CGAL::parameters::number_of_iterations(2));
  }
  return *mesh;
}

void BM_compute_highlight_lines(benchmark::State& state)
{
  const HB::Mesh& mesh = refined_beetle();
  const auto lights = HL::default_light_setup(mesh, HLP::number_of_lines(30));
  for (auto _ : state) {
    auto model = CGAL::compute_highlight_lines(mesh, lights, CGAL::Emptyset_iterator(),
                                               HLP::facing_side_only(true));
    benchmark::DoNotOptimize(model.nodes().data());
  }
  state.counters["faces"] = double(num_faces(mesh));
}

void BM_detect(benchmark::State& state)
{
  const HB::Mesh& mesh = refined_beetle();
  const auto lights = HL::default_light_setup(mesh, HLP::number_of_lines(30));
  std::size_t regions = 0;
  for (auto _ : state) {
    std::vector<HB::Irregularity> found;
    CGAL::detect_highlight_line_irregularities(mesh, lights, std::back_inserter(found));
    regions = found.size();
  }
  state.counters["regions"] = double(regions);
}

} // namespace

BENCHMARK(BM_compute_highlight_lines)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_detect)->Unit(benchmark::kMillisecond)->UseRealTime();

int main(int argc, char** argv)
{
  std::vector<char*> args;
  bool curves_only = false;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--curves") == 0)
      curves_only = true;
    else
      args.push_back(argv[i]);
  }
  try {
    if (!curves_only) {
      int count = int(args.size());
      benchmark::Initialize(&count, args.data());
      if (benchmark::ReportUnrecognizedArguments(count, args.data()))
        return 1;
      benchmark::RunSpecifiedBenchmarks();
      benchmark::Shutdown();
    }
    curves();
  } catch (const std::exception& e) {
    std::cerr << "benchmark_detection: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

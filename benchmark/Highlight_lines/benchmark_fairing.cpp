// Fairing a dented region: fair_with_highlight_lines() against CGAL's
// Polygon_mesh_processing::fair() and the surface diffusion flow of Xu et al. (the paper's §4),
// on the same regions, moving the same vertices.
//
//   benchmark_fairing [Google Benchmark options]   timings and counters, then the table
//   benchmark_fairing --table                       one run per case and method, the table only
//
// Cases (a dent pressed into a smooth surface; the undented surface is the ground truth):
//   hood_1e3, hood_1e4  a car-hood-like height field, irregular triangulation (grid vertices
//                       jittered by up to 0.25 of the grid step), a smooth dent; grids giving
//                       ~10³ and ~10⁴ movable vertices
//   hood_1e4_slivers    the same with the fairing test's jitter of 0.3 steps: at this size a
//                       few near-degenerate triangles appear in the region, and the discrete
//                       Willmore energy (whose cotangent weights blow up there) is dominated
//                       by them
//   beetle_roof         the bundled VW Beetle, a dent in the roof (as the example program)
//   beetle_fender       the same, a dent in the front right fender (the paper's Fig. 7)
// Methods, each on a fresh copy of the dented mesh:
//   pmp_fair  CGAL::Polygon_mesh_processing::fair(mesh, movable vertices), default
//             (bi-Laplacian, cotangent weights, G1 from the fixed rings)
//   xu_flow   surface_diffusion_flow.h: ∂V/∂t = N Δ_B H, border + one-ring held
//   ours           CGAL::fair_with_highlight_lines(mesh, region, lights), default parameters
//                  (the curvature variation energy)
//   ours_mc        the same with fairness_energy(Fairness_energy::MEAN_CURVATURE)
//   ours_willmore  the same with fairness_energy(Fairness_energy::WILLMORE), the paper's
// All of them move exactly the movable vertices of the region (fair_with_highlight_lines()'s
// definition).
//
// Counters (measures defined in fairing_quality.h): `movable`, `iterations`, `dev_ogh` and
// `dev_truth` (RMS highlight line deviation from the desired OGH lines / from the ground
// truth's lines, in units of the region's mean edge length ē), `willmore` (discrete Willmore
// energy of the region, Σ A‖K‖² as the package's q_fair), `willmore_n` (its normal part,
// Σ A (K·N)²), `jump_deg` (largest normal jump at the moved border, degrees),
// `dist_depth` (RMS distance of the movable vertices to the undented surface, in dent depths)
// and `x_pmp` (time / the time of PMP::fair on the same case in the same run).
#include "fairing_quality.h"
#include "test_meshes.h"
#include "surface_diffusion_flow.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/fair_with_highlight_lines.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Face_index face_descriptor;
typedef CGAL::Highlight_lines::Light_setup<K> Lights;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;
namespace HB = Highlight_lines_benchmark;

// ---------------------------------------------------------------------------------------------
// Cases

struct Case
{
  std::string name;
  Mesh input, truth; // dented, undented
  Lights lights{Point(0, 0, 1), Vector(1, 0, 0), Vector(0, 0, 1), 1};
  std::vector<face_descriptor> region;
  std::unique_ptr<HB::Region_info<Mesh>> info;
  std::vector<HB::Target_curve<Point>> targets;
  double dent_depth = 0;
};

// The hood of the fairing test (test::hood, a gently curved height field over [-1, 1]²), a smooth
// dent -depth (1 - (r/R)²)³ of radius 0.3 around (0.1, -0.05), and the faces within 0.45 of it.
std::unique_ptr<Case> hood_case(const std::string& name, int n, double jitter)
{
  const double depth = 0.02, radius = 0.3, cx = 0.1, cy = -0.05, region_radius = 0.45;
  const double step = 2.0 / n;
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  std::vector<Point> undented, dented;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double x = -1 + i * step, y = -1 + j * step;
      if (i > 0 && j > 0 && i < n && j < n) { // jittered interior: an irregular triangulation
        x += u(rng) * step;
        y += u(rng) * step;
      }
      const double r2 = ((x - cx) * (x - cx) + (y - cy) * (y - cy)) / (radius * radius);
      const double dent = r2 < 1 ? -depth * (1 - r2) * (1 - r2) * (1 - r2) : 0.0;
      undented.emplace_back(x, y, test::hood(x, y));
      dented.emplace_back(x, y, test::hood(x, y) + dent);
    }
  std::vector<std::array<std::size_t, 3>> triangles;
  auto id = [n](int i, int j) { return std::size_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  auto c = std::make_unique<Case>();
  c->name = name;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(dented, triangles, c->input);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(undented, triangles, c->truth);
  c->lights = Lights(Point(0, 0, 3), Vector(1, 0, 0), Vector(0, 0, 1), 0.06);
  c->dent_depth = depth;
  for (face_descriptor f : faces(c->input)) {
    bool inside = true;
    for (auto v : CGAL::vertices_around_face(halfedge(f, c->input), c->input)) {
      const Point& p = c->input.point(v);
      inside = inside && (p.x() - cx) * (p.x() - cx) + (p.y() - cy) * (p.y() - cy) <
                             region_radius * region_radius;
    }
    if (inside)
      c->region.push_back(f);
  }
  return c;
}

const Mesh& beetle()
{
  static std::unique_ptr<Mesh> mesh;
  if (!mesh) {
    mesh = std::make_unique<Mesh>();
    const std::string path = std::string(HIGHLIGHT_LINES_DATA_DIR) + "/beetle.off";
    if (!CGAL::IO::read_polygon_mesh(path, *mesh)) {
      std::cerr << "cannot read " << path << "\n";
      std::exit(1);
    }
  }
  return *mesh;
}

// A dent in the bundled beetle as the example program makes it: the region is the faces whose
// vertices lie within `radius` (× bounding-box diagonal) of the vertex nearest to `wanted`; a
// smooth dent (1 - (r/R)²)³ of depth 0.006 × diagonal and radius 0.6 × region radius is pressed
// along the vertex normals; the lights are the light tunnel of the whole car, spacing refined
// so that about 12 lights cross the region. (The car's long axis is z, up is y, front at +z;
// its right side is at x < 0.)
std::unique_ptr<Case> beetle_case(const std::string& name, const Point& wanted, double radius)
{
  auto c = std::make_unique<Case>();
  c->name = name;
  c->truth = beetle();
  c->input = c->truth;
  Mesh& mesh = c->input;
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  const double diagonal =
      std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                CGAL::square(box.zmax() - box.zmin()));
  Mesh::Vertex_index center_vertex = *vertices(mesh).begin();
  for (auto v : vertices(mesh))
    if (CGAL::squared_distance(mesh.point(v), wanted) <
        CGAL::squared_distance(mesh.point(center_vertex), wanted))
      center_vertex = v;
  const Point center = mesh.point(center_vertex);
  const double r = radius * diagonal;
  for (face_descriptor f : faces(mesh)) {
    bool inside = true;
    for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      inside = inside && CGAL::squared_distance(mesh.point(v), center) < r * r;
    if (inside)
      c->region.push_back(f);
  }
  const auto tunnel = HL::default_light_setup(mesh);
  const auto across = HL::default_level_range(mesh, tunnel, HLP::face_range(c->region));
  const double spacing = CGAL::to_double(tunnel.spacing()) *
                         double((std::max)(across.second - across.first, 1LL)) / 12.0;
  c->lights = Lights(tunnel.base_point(), tunnel.light_direction(), tunnel.plane_normal(), spacing);

  c->dent_depth = 0.006 * diagonal;
  const double dent_radius = 0.6 * r;
  std::vector<std::pair<Mesh::Vertex_index, Point>> moved;
  for (auto v : vertices(mesh)) {
    const double r2 = CGAL::squared_distance(mesh.point(v), center) / (dent_radius * dent_radius);
    if (r2 >= 1)
      continue;
    const Vector n = CGAL::Polygon_mesh_processing::compute_vertex_normal(v, mesh);
    moved.emplace_back(v, mesh.point(v) - c->dent_depth * (1 - r2) * (1 - r2) * (1 - r2) * n);
  }
  for (const auto& m : moved)
    mesh.point(m.first) = m.second;
  return c;
}

const std::vector<std::string>& case_names()
{
  static const std::vector<std::string> names = {"hood_1e3", "hood_1e4", "hood_1e4_slivers",
                                                 "beetle_roof", "beetle_fender"};
  return names;
}

Case& get_case(std::size_t index)
{
  static std::map<std::size_t, std::unique_ptr<Case>> cases;
  auto it = cases.find(index);
  if (it != cases.end())
    return *it->second;
  std::unique_ptr<Case> c;
  switch (index) {
  case 0:
    c = hood_case(case_names()[index], 80, 0.25);
    break;
  case 1:
    c = hood_case(case_names()[index], 250, 0.25);
    break;
  case 2:
    c = hood_case(case_names()[index], 250, 0.3);
    break;
  case 3: // the roof point of the example program
    c = beetle_case(case_names()[index], Point(0.04, 0.169283, -0.12), 0.07);
    break;
  default: // the top of the front right fender, clear of its crease with the front hood
    c = beetle_case(case_names()[index], Point(-0.182, -0.037, 0.338), 0.045);
    break;
  }
  c->info = std::make_unique<HB::Region_info<Mesh>>(c->input, c->region);
  c->targets = HB::leveled_desired_highlight_lines(c->input, *c->info, c->lights);
  return *(cases[index] = std::move(c));
}

// ---------------------------------------------------------------------------------------------
// Methods

enum Method { PMP_FAIR, XU_FLOW, OURS, OURS_MEAN_CURVATURE, OURS_WILLMORE, NUMBER_OF_METHODS };
const char* method_names[] = {"pmp_fair", "xu_flow", "ours", "ours_mc", "ours_willmore"};

struct Run
{
  std::size_t iterations = 0;
  bool converged = true;
  std::size_t factorizations = 0; // of the QP solver, over all iterations (ours only)
};

Run run_method(Method method, const Case& c, Mesh& mesh)
{
  Run run;
  switch (method) {
  case PMP_FAIR:
    run.iterations = 1;
    run.converged = CGAL::Polygon_mesh_processing::fair(mesh, c.info->movable);
    break;
  case XU_FLOW: {
    const HB::Surface_diffusion_flow_report r = HB::surface_diffusion_flow(mesh, c.region);
    run.iterations = r.iterations;
    run.converged = r.converged;
    break;
  }
  default: {
    const HL::Fairing_report r =
        method == OURS ? CGAL::fair_with_highlight_lines(mesh, c.region, c.lights)
                       : CGAL::fair_with_highlight_lines(
                             mesh, c.region, c.lights,
                             HLP::fairness_energy(method == OURS_MEAN_CURVATURE
                                                      ? HL::Fairness_energy::MEAN_CURVATURE
                                                      : HL::Fairness_energy::WILLMORE));
    run.iterations = r.iterations;
    run.converged = r.converged();
    for (const HL::Fairing_report::Iteration& step : r.history)
      run.factorizations += step.solver.factorizations;
    break;
  }
  }
  return run;
}

double seconds_of(const std::function<void()>& f)
{
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// PMP::fair's time on a case, the unit of the ratios: as measured by its benchmark when that
// ran (it is registered before the other methods), otherwise the best of 3 runs.
std::map<std::size_t, double>& pmp_fair_benchmark_seconds()
{
  static std::map<std::size_t, double> seconds;
  return seconds;
}

double pmp_fair_seconds(std::size_t index)
{
  auto& seconds = pmp_fair_benchmark_seconds();
  auto it = seconds.find(index);
  if (it != seconds.end())
    return it->second;
  const Case& c = get_case(index);
  double best = 1e300;
  for (int i = 0; i < 3; ++i) {
    Mesh mesh = c.input;
    best = (std::min)(best, seconds_of([&] { run_method(PMP_FAIR, c, mesh); }));
  }
  return seconds[index] = best;
}

// ---------------------------------------------------------------------------------------------
// Measures and the table

struct Measures
{
  bool timed = false;
  double seconds = 0, x_pmp = 0;
  Run run;
  HB::Line_deviation ogh, truth;
  double willmore = 0, mean_curvature = 0, jump = 0, distance = 0;
};

Measures measure(const Case& c, const Mesh& mesh)
{
  Measures m;
  m.ogh = HB::deviation_from_targets(mesh, *c.info, c.lights, c.targets);
  m.truth = HB::deviation_from_reference(mesh, c.truth, *c.info, c.lights);
  m.willmore = HB::willmore_energy_in_region(mesh, *c.info);
  m.mean_curvature = HB::mean_curvature_energy_in_region(mesh, *c.info);
  m.jump = HB::largest_normal_jump(mesh, *c.info);
  m.distance = HB::rms_distance_to_surface(mesh, c.truth, *c.info);
  return m;
}

// results[case][row]: rows "input", "truth", then the methods.
std::map<std::size_t, std::map<std::string, Measures>>& results()
{
  static std::map<std::size_t, std::map<std::string, Measures>> r;
  return r;
}

void add_references(std::size_t index)
{
  auto& rows = results()[index];
  if (rows.count("input"))
    return;
  const Case& c = get_case(index);
  rows["input"] = measure(c, c.input);
  rows["truth"] = measure(c, c.truth);
}

void print_table(std::ostream& out)
{
  char line[512];
  for (auto& [index, rows] : results()) {
    const Case& c = get_case(index);
    const double e = c.info->mean_edge_length;
    out << "\n"
        << c.name << ": " << num_vertices(c.input) << " vertices, region " << c.region.size()
        << " faces, " << c.info->movable.size() << " movable vertices, " << c.targets.size()
        << " desired lines, mean edge e = " << e << ", dent depth " << c.dent_depth << "\n";
    std::snprintf(line, sizeof line, "  %-8s %9s %7s %5s %9s %9s %9s %9s %9s %9s %8s %8s %11s\n",
                  "", "time ms", "x pmp", "iters", "ogh rms/e", "ogh max/e", "gt rms/e", "gt max/e",
                  "willmore", "willm. N", "jump deg", "dist/dep", "nodes/unm.");
    out << line;
    for (const char* row :
         {"input", "truth", "pmp_fair", "xu_flow", "ours", "ours_mc", "ours_willmore"}) {
      auto it = rows.find(row);
      if (it == rows.end())
        continue;
      const Measures& m = it->second;
      char time[64] = "", ratio[64] = "", iterations[64] = "";
      if (m.timed) {
        std::snprintf(time, sizeof time, "%.2f", 1000 * m.seconds);
        std::snprintf(ratio, sizeof ratio, "%.2f", m.x_pmp);
        std::snprintf(iterations, sizeof iterations, "%zu%s", m.run.iterations,
                      m.run.converged ? "" : "*");
      }
      char nodes[64];
      std::snprintf(nodes, sizeof nodes, "%zu/%zu", m.ogh.nodes, m.ogh.unmatched);
      std::snprintf(line, sizeof line,
                    "  %-8s %9s %7s %5s %9.4f %9.4f %9.4f %9.4f %9.4f %9.4f %8.3f %8.4f %11s\n",
                    row, time, ratio, iterations, m.ogh.rms / e, m.ogh.max / e, m.truth.rms / e,
                    m.truth.max / e, m.willmore, m.mean_curvature, m.jump,
                    m.distance / c.dent_depth, nodes);
      out << line;
    }
    // The goals of the comparison.
    for (const char* ours : {"ours", "ours_mc", "ours_willmore"}) {
      if (!(rows.count(ours) && rows.count("pmp_fair") && rows.count("xu_flow")))
        continue;
      const Measures &o = rows[ours], &p = rows["pmp_fair"], &x = rows["xu_flow"];
      const double best_willmore = (std::min)({o.willmore, p.willmore, x.willmore});
      const double best_n = (std::min)({o.mean_curvature, p.mean_curvature, x.mean_curvature});
      out << "  goals (" << ours << "): lower OGH deviation than both: "
          << (o.ogh.rms < p.ogh.rms && o.ogh.rms < x.ogh.rms ? "yes" : "NO")
          << "; lower ground-truth deviation than both: "
          << (o.truth.rms < p.truth.rms && o.truth.rms < x.truth.rms ? "yes" : "NO")
          << "; Willmore within 10 % of the best: "
          << (o.willmore <= 1.1 * best_willmore ? "yes" : "NO") << " ("
          << o.willmore / best_willmore << " x best; normal part " << o.mean_curvature / best_n
          << " x best); time <= 2 x PMP::fair: " << (o.x_pmp <= 2 ? "yes" : "NO") << " (" << o.x_pmp
          << " x; " << o.run.factorizations << " QP factorisations in " << o.run.iterations
          << " iterations)\n";
    }
  }
  out << "\n  (*: iteration bound reached before convergence. ogh: RMS / max distance of the "
         "highlight nodes inside the region to the desired OGH lines of the same light; gt: to "
         "the undented surface's lines; e: mean edge length of the region; willmore: discrete "
         "Willmore energy of the region, sum A |K|^2; willm. N: its normal part, sum A (K.N)^2; "
         "jump: largest angle between face normals across the "
         "border of the moved faces; dist/dep: RMS distance of the movable vertices to the "
         "undented surface / dent depth; nodes/unm.: highlight nodes inside the region measured "
         "against "
         "the OGH lines / left out because no desired line has their light index)\n";
}

// ---------------------------------------------------------------------------------------------
// Google Benchmark

void BM_fairing(benchmark::State& state, std::size_t index, Method method)
{
  const Case& c = get_case(index);
  Mesh mesh;
  double total = 0;
  Run run;
  for (auto _ : state) {
    state.PauseTiming();
    mesh = c.input;
    state.ResumeTiming();
    total += seconds_of([&] { run = run_method(method, c, mesh); });
  }
  Measures m = measure(c, mesh);
  m.timed = true;
  m.run = run;
  m.seconds = total / double(state.iterations());
  if (method == PMP_FAIR)
    pmp_fair_benchmark_seconds()[index] = m.seconds;
  m.x_pmp = m.seconds / pmp_fair_seconds(index);
  add_references(index);
  results()[index][method_names[method]] = m;
  const double e = c.info->mean_edge_length;
  state.counters["movable"] = double(c.info->movable.size());
  state.counters["iterations"] = double(run.iterations);
  state.counters["dev_ogh"] = m.ogh.rms / e;
  state.counters["dev_truth"] = m.truth.rms / e;
  state.counters["willmore"] = m.willmore;
  state.counters["willmore_n"] = m.mean_curvature;
  state.counters["jump_deg"] = m.jump;
  state.counters["dist_depth"] = m.distance / c.dent_depth;
  state.counters["x_pmp"] = m.x_pmp;
}

// One timed run per case and method, no Google Benchmark.
void table_only()
{
  for (std::size_t index = 0; index < case_names().size(); ++index) {
    const Case& c = get_case(index);
    add_references(index);
    for (int method = 0; method < NUMBER_OF_METHODS; ++method) {
      Mesh mesh = c.input;
      Run run;
      const double seconds = seconds_of([&] { run = run_method(Method(method), c, mesh); });
      Measures m = measure(c, mesh);
      m.timed = true;
      m.run = run;
      m.seconds = method == PMP_FAIR ? pmp_fair_seconds(index) : seconds;
      m.x_pmp = m.seconds / pmp_fair_seconds(index);
      results()[index][method_names[method]] = m;
    }
  }
}

} // namespace

int main(int argc, char** argv)
{
  bool table = false;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--table") == 0)
      table = true;
    else
      args.push_back(argv[i]);
  }
  try {
    if (table) {
      table_only();
      print_table(std::cout);
      return 0;
    }
    for (std::size_t index = 0; index < case_names().size(); ++index)
      for (int method = 0; method < NUMBER_OF_METHODS; ++method)
        benchmark::RegisterBenchmark(
            ("fairing/" + case_names()[index] + "/" + method_names[method]).c_str(), BM_fairing,
            index, Method(method))
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    int count = int(args.size());
    benchmark::Initialize(&count, args.data());
    if (benchmark::ReportUnrecognizedArguments(count, args.data()))
      return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    print_table(std::cout);
  } catch (const std::exception& e) {
    std::cerr << "benchmark_fairing: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

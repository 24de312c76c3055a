// Speed of the highlight line model on a mesh of over a million faces, as ratios to CGAL's
// Polygon_mesh_processing::compute_vertex_normals on the same mesh, measured in the same run
// (any highlight computation must at least compute normals).
//
// Counters: `x_normals` = time of the benchmark / time of compute_vertex_normals (best of 5,
// measured once per run); `nodes` = size of the output. Argument 0: the example program's
// light tunnel; 1: every level. With TBB, the model and the sweep are also measured with
// CGAL::Parallel_if_available_tag.
//
// BM_compute_highlight_lines_with_creases: the model cut along the creases (crease_edge_map).
//
// BM_sweep_segments: a sweep step as a viewer needs it, the segments of the lines without tracing
// them (Highlight_line_sweeper::compute_segments()), into the arrays of the previous step.
//
// BM_viewer_light_change: the viewer's (demo/Highlight_lines) time from a change of the lights to
// the new lines ready for drawing: the lights that fall on the surface, the segments of their
// lines through its Parallel_if_available sweeper (it draws them as GL_LINES; the polylines are
// traced only when saved), and the highlight distance field only while the zebra view is shown
// (not here). The copy to OpenGL's arrays is not included (it needs a window).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Highlight_lines/Highlight_line_sweeper.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/compute_highlight_lines.h>

#include "viewer_session.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace HL = CGAL::Highlight_lines;

// The bundled beetle, Loop-subdivided three times: 38,656 x 64 = 2,473,984 faces.
const Mesh& big_mesh()
{
  static std::unique_ptr<Mesh> mesh;
  if (!mesh) {
    mesh = std::make_unique<Mesh>();
    const std::string path = std::string(HIGHLIGHT_LINES_DATA_DIR) + "/beetle.off";
    if (!CGAL::IO::read_polygon_mesh(path, *mesh)) {
      std::cerr << "cannot read " << path << "\n";
      std::exit(1);
    }
    CGAL::Subdivision_method_3::Loop_subdivision(*mesh, CGAL::parameters::number_of_iterations(3));
  }
  return *mesh;
}

double seconds_of_compute_vertex_normals()
{
  static double seconds = 0;
  if (seconds == 0) {
    Mesh mesh = big_mesh();
    auto normals = mesh.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:bench_normal").first;
    double best = 1e300;
    for (int run = 0; run < 5; ++run) {
      const auto start = std::chrono::steady_clock::now();
      CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normals);
      best = (std::min)(
          best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    seconds = best;
  }
  return seconds;
}

void report(benchmark::State& state, double seconds_per_iteration)
{
  state.counters["faces"] = double(num_faces(big_mesh()));
  state.counters["x_normals"] = seconds_per_iteration / seconds_of_compute_vertex_normals();
}

void BM_compute_vertex_normals(benchmark::State& state)
{
  Mesh mesh = big_mesh();
  auto normals = mesh.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:n").first;
  double total = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normals);
    total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  report(state, total / double(state.iterations()));
}

// The lights of the example program (a light tunnel above the car: the levels over the
// central 90 % of the surface facing it), or every level (argument 1): near the silhouettes
// seen from the light plane lines crowd, and the output is several times larger.
std::pair<long long, long long> levels_of(const benchmark::State& state,
                                          const HL::Light_setup<K>& lights)
{
  if (state.range(0) == 1)
    return {-(1LL << 50), 1LL << 50};
  static const auto tunnel = HL::default_level_range(big_mesh(), lights);
  return tunnel;
}

// The whole model from scratch: flat copy, normals (eq. 3), classification, nodes, lines.
// Tag: CGAL::Sequential_tag or CGAL::Parallel_if_available_tag (the `_parallel` variants).
template <typename Tag>
void BM_compute_highlight_lines(benchmark::State& state)
{
  const Mesh& mesh = big_mesh();
  const auto lights = HL::default_light_setup(mesh);
  const auto np = HL::parameters::combine(HL::parameters::level_range(levels_of(state, lights)),
                                          HL::parameters::facing_side_only(state.range(0) == 0));
  double total = 0;
  std::size_t nodes = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const auto model =
        CGAL::compute_highlight_lines<Tag>(mesh, lights, CGAL::Emptyset_iterator(), np);
    total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    nodes = model.nodes().size();
  }
  state.counters["nodes"] = double(nodes);
  report(state, total / double(state.iterations()));
}

// The same model cut along the creases (crease_edge_map; here the edges sharper than 20
// degrees, found once outside the timing): the cut adds a pass over the edges and walks the
// rings of the vertices on crease edges.
void BM_compute_highlight_lines_with_creases(benchmark::State& state)
{
  static Mesh mesh = big_mesh();
  static const auto creases = [] {
    auto map = mesh.add_property_map<Mesh::Edge_index, bool>("e:bench_crease", false).first;
    CGAL::Polygon_mesh_processing::detect_sharp_edges(mesh, 20, map);
    return map;
  }();
  std::size_t crease_edges = 0;
  for (auto e : edges(mesh))
    crease_edges += creases[e] ? 1 : 0;
  const auto lights = HL::default_light_setup(mesh);
  const auto np = HL::parameters::crease_edge_map(
      HL::parameters::combine(HL::parameters::level_range(levels_of(state, lights)),
                              HL::parameters::facing_side_only(true)),
      creases);
  double total = 0;
  std::size_t nodes = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const auto model = CGAL::compute_highlight_lines(mesh, lights, CGAL::Emptyset_iterator(), np);
    total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    nodes = model.nodes().size();
  }
  state.counters["nodes"] = double(nodes);
  state.counters["crease_edges"] = double(crease_edges);
  report(state, total / double(state.iterations()));
}

// A sweep step: lights moved, everything independent of them cached in the sweeper, the model
// computed into the one of the previous step (Highlight_line_sweeper::compute(lights, model)),
// as a sweep does; with argument NewModel, into a new model object each time.
template <typename Tag, bool NewModel = false>
void BM_sweep_update(benchmark::State& state)
{
  const Mesh& mesh = big_mesh();
  const auto lights = HL::default_light_setup(mesh);
  typedef HL::Highlight_line_sweeper<Mesh, CGAL::Default, CGAL::Default, Tag> Sweeper;
  const Sweeper sweeper(mesh);
  const auto np = HL::parameters::combine(HL::parameters::level_range(levels_of(state, lights)),
                                          HL::parameters::facing_side_only(state.range(0) == 0));
  double total = 0;
  int step = 0;
  std::size_t nodes = 0;
  typename Sweeper::Model model;
  for (auto _ : state) {
    const auto moved =
        lights.translated(lights.index_direction() * (lights.spacing() * 0.1 * (++step % 10)));
    const auto start = std::chrono::steady_clock::now();
    if constexpr (NewModel) {
      const auto fresh = sweeper.compute(moved, np);
      total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      nodes = fresh.nodes().size();
      benchmark::DoNotOptimize(fresh.nodes().data());
      continue;
    }
    sweeper.compute(moved, model, np);
    total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    nodes = model.nodes().size();
    benchmark::DoNotOptimize(model.nodes().data());
  }
  state.counters["nodes"] = double(nodes);
  report(state, total / double(state.iterations()));
}

template <typename Tag>
void BM_sweep_segments(benchmark::State& state)
{
  const Mesh& mesh = big_mesh();
  const auto lights = HL::default_light_setup(mesh);
  typedef HL::Highlight_line_sweeper<Mesh, CGAL::Default, CGAL::Default, Tag> Sweeper;
  const Sweeper sweeper(mesh);
  const auto np = HL::parameters::combine(HL::parameters::level_range(levels_of(state, lights)),
                                          HL::parameters::facing_side_only(state.range(0) == 0));
  double total = 0;
  int step = 0;
  std::vector<K::Point_3> points;
  std::vector<std::array<unsigned int, 2>> segments;
  for (auto _ : state) {
    const auto moved =
        lights.translated(lights.index_direction() * (lights.spacing() * 0.1 * (++step % 10)));
    const auto start = std::chrono::steady_clock::now();
    sweeper.compute_segments(moved, points, segments, np);
    total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    benchmark::DoNotOptimize(segments.data());
  }
  state.counters["segments"] = double(segments.size());
  report(state, total / double(state.iterations()));
}

void BM_viewer_light_change(benchmark::State& state)
{
  viewer::Session session;
  std::string error;
  if (!session.set_mesh(Mesh(big_mesh()), "beetle, Loop-subdivided 3 times", error)) {
    state.SkipWithError(error.c_str());
    return;
  }
  viewer::Light_controls controls = session.light_controls();
  double total = 0;
  for (auto _ : state) {
    controls.offset += 0.1; // a tenth of the spacing across, as an arrow key moves them
    const auto start = std::chrono::steady_clock::now();
    session.set_light_controls(controls, error);
    total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    benchmark::DoNotOptimize(session.lines().data());
  }
  state.counters["lines"] = double(session.number_of_lines());
  report(state, total / double(state.iterations()));
}

BENCHMARK(BM_compute_vertex_normals)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_viewer_light_change)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_compute_highlight_lines, CGAL::Sequential_tag)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_compute_highlight_lines_with_creases)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_TEMPLATE(BM_sweep_update, CGAL::Sequential_tag)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_TEMPLATE(BM_sweep_update, CGAL::Sequential_tag, true)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_TEMPLATE(BM_sweep_segments, CGAL::Sequential_tag)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
#ifdef CGAL_LINKED_WITH_TBB
// With TBB: the same with CGAL::Parallel_if_available_tag (= Parallel_tag).
BENCHMARK_TEMPLATE(BM_compute_highlight_lines, CGAL::Parallel_if_available_tag)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_TEMPLATE(BM_sweep_update, CGAL::Parallel_if_available_tag)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_TEMPLATE(BM_sweep_segments, CGAL::Parallel_if_available_tag)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
#endif

} // namespace

BENCHMARK_MAIN();

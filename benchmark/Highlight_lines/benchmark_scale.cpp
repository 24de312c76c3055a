// Scale (issue 6): time and peak memory of the highlight line model on a mesh of several
// million faces, and of the fairing of a region with about 10^5 movable vertices.
//
//   benchmark_scale [--subdivisions k] [--grid n] [--iterations i] [--model-only]
//                   [--fairing-only]
//
// Part 1: the bundled beetle (38,656 faces), Loop-subdivided k times (default 4: 9.9M faces).
//   Reference: PMP::compute_vertex_normals on it. Then compute_highlight_lines() (the light
//   tunnel of the example program, facing side only, and every level), sequential and with
//   CGAL::Parallel_if_available_tag, and a Highlight_line_sweeper's sweep update.
// Part 2: the car-hood height field of benchmark_fairing on an n x n grid (default 800:
//   1.28M faces), jittered, a smooth dent of radius 0.3; the region is the faces within 0.45
//   of the dent (about 10^5 movable vertices for n = 800). fair_with_highlight_lines() runs
//   i iterations (default 3; 0: until it stops, at most 50); a visitor reports the time of
//   each. Reference: PMP::fair() on the same movable vertices of the same dented mesh (one
//   sparse solve), and the ratio of the two times.
//
// Memory: VmHWM of /proc/self/status, the peak resident set size. Before each phase the peak
// is reset (writing 5 to /proc/self/clear_refs), so each figure is the peak during that phase,
// including what was resident before it (given as "rss before").
#include "test_meshes.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Highlight_lines/Highlight_line_sweeper.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/Highlight_lines/fairing_building_blocks.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/compute_highlight_lines.h>
#include <CGAL/fair_with_highlight_lines.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;

double now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// A field of /proc/self/status, in MiB.
double status_mib(const char* field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::size_t n = std::strlen(field);
  while (std::getline(status, line))
    if (line.compare(0, n, field) == 0 && line.size() > n && line[n] == ':')
      return std::atof(line.c_str() + n + 1) / 1024.0;
  return -1;
}

void reset_peak()
{
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
}

// Runs a phase and prints its time and peak memory.
template <typename F>
double phase(const std::string& name, F&& f)
{
  const double rss_before = status_mib("VmRSS");
  reset_peak();
  const double start = now();
  f();
  const double seconds = now() - start;
  std::printf("%-58s %9.3f s   peak %8.1f MiB   (rss before %8.1f MiB)\n", name.c_str(), seconds,
              status_mib("VmHWM"), rss_before);
  std::fflush(stdout);
  return seconds;
}

void model_at_scale(int subdivisions)
{
  std::printf("== Part 1: highlight line model, beetle Loop-subdivided %d times\n", subdivisions);
  Mesh mesh;
  phase("read + Loop subdivision", [&] {
    const std::string path = std::string(HIGHLIGHT_LINES_DATA_DIR) + "/beetle.off";
    if (!CGAL::IO::read_polygon_mesh(path, mesh)) {
      std::cerr << "cannot read " << path << "\n";
      std::exit(1);
    }
    CGAL::Subdivision_method_3::Loop_subdivision(
        mesh, CGAL::parameters::number_of_iterations(subdivisions));
  });
  std::printf("   %zu faces, %zu vertices\n", std::size_t(num_faces(mesh)),
              std::size_t(num_vertices(mesh)));

  double normals = 1e300;
  {
    auto map = mesh.add_property_map<Mesh::Vertex_index, Vector>("v:scale_normal").first;
    for (int run = 0; run < 3; ++run)
      normals = (std::min)(normals, phase("PMP::compute_vertex_normals (reference)", [&] {
                             CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, map);
                           }));
    mesh.remove_property_map(map);
  }

  const auto lights = HL::default_light_setup(mesh);
  const auto tunnel = HLP::combine(HLP::level_range(HL::default_level_range(mesh, lights)),
                                   HLP::facing_side_only(true));
  auto report = [&](const char* what, double seconds, std::size_t nodes, std::size_t lines) {
    std::printf("   %-40s %8.3f s = %5.3f x normals; %zu nodes, %zu lines\n", what, seconds,
                seconds / normals, nodes, lines);
  };
  for (int parallel = 0; parallel < 2; ++parallel) {
    const char* tag = parallel ? "Parallel_if_available_tag" : "Sequential_tag";
    for (int all = 0; all < 2; ++all) {
      std::size_t nodes = 0, lines = 0;
      const std::string name = std::string("compute_highlight_lines, ") +
                               (all ? "every level, " : "light tunnel, ") + tag;
      const double seconds = phase(name, [&] {
        std::vector<std::vector<Point>> polylines;
        const auto model =
            parallel
                ? (all ? CGAL::compute_highlight_lines<CGAL::Parallel_if_available_tag>(
                             mesh, lights, std::back_inserter(polylines))
                       : CGAL::compute_highlight_lines<CGAL::Parallel_if_available_tag>(
                             mesh, lights, std::back_inserter(polylines), tunnel))
                : (all ? CGAL::compute_highlight_lines(mesh, lights, std::back_inserter(polylines))
                       : CGAL::compute_highlight_lines(mesh, lights, std::back_inserter(polylines),
                                                       tunnel));
        nodes = model.nodes().size();
        lines = model.lines().size();
      });
      report(all ? "model, every level" : "model, light tunnel", seconds, nodes, lines);
    }
  }

  auto sweeps = [&](auto tag) {
    typedef decltype(tag) Tag;
    typedef HL::Highlight_line_sweeper<Mesh, CGAL::Default, CGAL::Default, Tag> Sweeper;
    const char* name = std::is_same<Tag, CGAL::Sequential_tag>::value ? "Sequential_tag"
                                                                      : "Parallel_if_available_tag";
    std::unique_ptr<Sweeper> sweeper;
    phase(std::string("Highlight_line_sweeper construction, ") + name,
          [&] { sweeper = std::make_unique<Sweeper>(mesh); });
    double best = 1e300;
    std::size_t nodes = 0;
    phase(std::string("10 sweep updates (light tunnel), ") + name, [&] {
      for (int step = 1; step <= 10; ++step) {
        const auto moved =
            lights.translated(lights.index_direction() * (lights.spacing() * 0.1 * step));
        const double start = now();
        const auto model = sweeper->compute(moved, tunnel);
        best = (std::min)(best, now() - start);
        nodes = model.nodes().size();
      }
    });
    report("sweep update (best of 10)", best, nodes, 0);
  };
  sweeps(CGAL::Sequential_tag());
  sweeps(CGAL::Parallel_if_available_tag());
}

void fairing_at_scale(int n, int iterations)
{
  std::printf("== Part 2: fair_with_highlight_lines, dented hood on a %d x %d grid\n", n, n);
  const double depth = 0.02, radius = 0.3, cx = 0.1, cy = -0.05, region_radius = 0.45;
  Mesh mesh;
  std::vector<Mesh::Face_index> region;
  phase("build the dented hood", [&] {
    const double step = 2.0 / n;
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(-0.25, 0.25);
    std::vector<Point> points;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        double x = -1 + i * step, y = -1 + j * step;
        if (i > 0 && j > 0 && i < n && j < n) {
          x += u(rng) * step;
          y += u(rng) * step;
        }
        const double r2 = ((x - cx) * (x - cx) + (y - cy) * (y - cy)) / (radius * radius);
        const double dent = r2 < 1 ? -depth * (1 - r2) * (1 - r2) * (1 - r2) : 0.0;
        points.emplace_back(x, y, test::hood(x, y) + dent);
      }
    std::vector<std::array<std::size_t, 3>> triangles;
    auto id = [n](int i, int j) { return std::size_t(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, mesh);
    for (auto f : faces(mesh)) {
      bool inside = true;
      for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh)) {
        const Point& p = mesh.point(v);
        inside = inside && (p.x() - cx) * (p.x() - cx) + (p.y() - cy) * (p.y() - cy) <
                               region_radius * region_radius;
      }
      if (inside)
        region.push_back(f);
    }
  });
  std::printf("   %zu faces, region of %zu faces\n", std::size_t(num_faces(mesh)), region.size());
  const HL::Light_setup<K> lights(Point(0, 0, 3), Vector(1, 0, 0), Vector(0, 0, 1), 0.06);

  std::vector<Mesh::Vertex_index> movable;
  phase("movable vertices",
        [&] { HL::movable_vertices(mesh, region, std::back_inserter(movable)); });
  std::printf("   %zu movable vertices\n", movable.size());

  // The reference a user would otherwise call, on a copy of the same dented mesh.
  double pmp_seconds = 0;
  {
    Mesh copy = mesh;
    const double start = now();
    const bool solved = CGAL::Polygon_mesh_processing::fair(copy, movable);
    pmp_seconds = now() - start;
    std::printf("   PMP::fair: %.3f s%s\n", pmp_seconds, solved ? "" : " (solver failed)");
  }

  double last = now();
  auto visitor = [&](const HL::Fairing_report::Iteration& it) {
    const double t = now();
    std::printf("   iteration: %7.2f s, peak so far %8.1f MiB, F before it %.6g (q_fair %.6g, "
                "q_diff %.6g), "
                "max |x| / e %.3g%s, lines %zu, QP %zu active-set steps, %zu factorisations\n",
                t - last, status_mib("VmHWM"), it.target_value, it.fairness_energy,
                it.difference_energy, it.relative_max_displacement,
                it.extrapolation > 1
                    ? (" (accelerated " + std::to_string(it.extrapolation) + " x)").c_str()
                    : "",
                it.lines_targeted, it.solver.iterations, it.solver.factorizations);
    std::fflush(stdout);
    last = now();
    return true;
  };
  HL::Fairing_report report;
  const int limit = iterations > 0 ? iterations : 50;
  const double start = now();
  phase("fair_with_highlight_lines, at most " + std::to_string(limit) + " iterations", [&] {
    last = now();
    report = CGAL::fair_with_highlight_lines(
        mesh, region, lights,
        HLP::combine(CGAL::parameters::number_of_iterations(limit),
                     HLP::fairing_visitor(
                         std::function<bool(const HL::Fairing_report::Iteration&)>(visitor))));
  });
  const double seconds = now() - start;
  std::size_t factorizations = 0;
  for (const auto& it : report.history)
    factorizations += it.solver.factorizations;
  std::printf("   %zu iterations, %zu QP factorisations, %zu movable vertices, %s (%s): "
              "%.3f s = %.2f x PMP::fair\n",
              report.iterations, factorizations, report.number_of_movable_vertices,
              report.converged() ? "converged" : "not converged", HL::to_string(report.status),
              seconds, pmp_seconds > 0 ? seconds / pmp_seconds : 0.0);
}

} // namespace

int main(int argc, char** argv)
{
  int subdivisions = 4, grid = 800, iterations = 3;
  bool model = true, fairing = true;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--subdivisions" && i + 1 < argc)
      subdivisions = std::atoi(argv[++i]);
    else if (arg == "--grid" && i + 1 < argc)
      grid = std::atoi(argv[++i]);
    else if (arg == "--iterations" && i + 1 < argc)
      iterations = std::atoi(argv[++i]);
    else if (arg == "--model-only")
      fairing = false;
    else if (arg == "--fairing-only")
      model = false;
    else {
      std::cerr << "usage: " << argv[0]
                << " [--subdivisions k] [--grid n] [--iterations i] [--model-only] "
                   "[--fairing-only]\n";
      return 1;
    }
  }
#ifdef CGAL_LINKED_WITH_TBB
  std::printf("TBB: yes (Parallel_if_available_tag is Parallel_tag)\n");
#else
  std::printf("TBB: no (Parallel_if_available_tag is Sequential_tag)\n");
#endif
  if (model)
    model_at_scale(subdivisions);
  if (fairing)
    fairing_at_scale(grid, iterations);
  return 0;
}

// A program of a user of the package: it is built by a separate CMake project that finds the
// installed package with find_package(CGAL_Highlight_lines), or add_subdirectory()s the
// repository, and links CGAL::Highlight_lines (see CMakeLists.txt).
// It computes highlight lines on a generated mesh, sweeps the lights, fairs a dent, and
// exits with a non-zero status if anything is not as documented.
//
// The parts between //! [name] markers are shown in the user manual (\snippet), so the code
// of the manual is compiled and run by the test suite.

//! [includes]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/compute_highlight_lines.h>
#include <CGAL/fair_with_highlight_lines.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;
//! [includes]

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace {

int failures = 0;

void check(bool ok, const std::string& what)
{
  if (!ok) {
    std::cerr << "FAILED: " << what << "\n";
    ++failures;
  }
}

// A gently curved, car-hood-like height field over [-1, 1]^2, as a grid of n x n cells split
// into triangles, with a smooth dent of the given depth around (0.1, -0.05).
Mesh hood(int n, double dent_depth)
{
  Mesh mesh;
  std::vector<Mesh::Vertex_index> v;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = -1 + 2.0 * i / n, y = -1 + 2.0 * j / n;
      const double r2 = ((x - 0.1) * (x - 0.1) + (y + 0.05) * (y + 0.05)) / (0.3 * 0.3);
      const double dent = r2 < 1 ? -dent_depth * (1 - r2) * (1 - r2) * (1 - r2) : 0.0;
      v.push_back(mesh.add_vertex(
          K::Point_3(x, y, 0.25 * (1 - 0.35 * x * x) - 0.12 * y * y + 0.05 * x * y + dent)));
    }
  auto id = [&](int i, int j) { return v[std::size_t(j * (n + 1) + i)]; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      mesh.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      mesh.add_face(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  return mesh;
}

bool finite(const K::Point_3& p)
{
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
}

} // namespace

int main()
{
  Mesh mesh = hood(40, 0.02);
  check(is_valid_polygon_mesh(mesh) && num_faces(mesh) == 3200, "the generated mesh is valid");

  //! [lights]
  // Lights in the plane z = 3 (normal Z = +z), running along x (H), 0.06 apart.
  const HL::Light_setup<K> lights(K::Point_3(0, 0, 3), K::Vector_3(1, 0, 0), K::Vector_3(0, 0, 1),
                                  0.06);
  //! [lights]

  //! [compute]
  std::vector<std::vector<K::Point_3>> polylines;
  const auto model = CGAL::compute_highlight_lines(mesh, lights, std::back_inserter(polylines));
  std::size_t closed = 0, on_vertices = 0;
  for (const auto& line : model.lines()) // line.level: the index m of its light
    closed += line.is_closed;
  for (const auto& node : model.nodes()) // inside an edge (halfedge, parameter) or on a vertex
    on_vertices += node.is_on_vertex();
  std::cout << model.lines().size() << " highlight lines (" << closed << " closed) through "
            << model.nodes().size() << " nodes (" << on_vertices << " on vertices)\n";
  //! [compute]

  check(!model.lines().empty(), "the model has highlight lines");
  check(polylines.size() == model.lines().size(), "one polyline per line");
  check(model.number_of_skipped_edges() == 0 && model.number_of_undefined_vertices() == 0,
        "nothing is skipped on a gently curved surface");
  std::size_t points = 0;
  for (std::size_t i = 0; i < polylines.size() && i < model.lines().size(); ++i) {
    const auto& line = model.lines()[i];
    check(polylines[i].size() == line.nodes.size() + (line.is_closed ? 1 : 0),
          "a polyline has the line's nodes, a closed one repeats its first point");
    for (const auto& p : polylines[i]) {
      check(finite(p) && std::abs(p.x()) <= 1 && std::abs(p.y()) <= 1, "points on the mesh");
      ++points;
    }
  }
  check(points >= 200,
        "the lines are sampled at the mesh edges (" + std::to_string(points) + " points)");

  //! [named_parameters]
  // The package's named parameters are free functions (CGAL 5.5 cannot chain them with '.');
  // combine() joins them with CGAL's own.
  std::vector<Mesh::Face_index> upper_half; // the faces with y >= 0
  for (auto f : faces(mesh)) {
    bool upper = true;
    for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      upper = upper && mesh.point(v).y() >= 0;
    if (upper)
      upper_half.push_back(f);
  }
  const auto part = CGAL::compute_highlight_lines(
      mesh, lights, CGAL::Emptyset_iterator(),
      HLP::combine(CGAL::parameters::vertex_point_map(get(CGAL::vertex_point, mesh)),
                   HLP::face_range(upper_half), HLP::level_range(std::make_pair(-5, 5)),
                   HLP::max_levels_per_edge(64)));
  //! [named_parameters]
  check(!part.lines().empty() && part.nodes().size() < model.nodes().size(),
        "a face range and a level range restrict the model");
  for (const auto& node : part.nodes())
    check(node.level >= -5 && node.level <= 5 && node.point.y() >= -1e-12,
          "the restricted model stays in its ranges");

  //! [sweep]
  // Sweeping the lights: the normals are computed once, each light setup costs only the
  // highlight distances, the nodes and their connection.
  const HL::Highlight_line_sweeper<Mesh> sweeper(mesh);
  std::vector<std::size_t> lines_per_step;
  for (int step = 0; step < 5; ++step) {
    const auto swept = sweeper.compute(lights.translated(K::Vector_3(0, 0.01 * step, 0)));
    lines_per_step.push_back(swept.lines().size());
  }
  //! [sweep]
  for (std::size_t n : lines_per_step)
    check(n > 0, "every sweep step has lines");
  check(sweeper.compute(lights).nodes().size() == model.nodes().size(),
        "the sweeper computes the same model as compute_highlight_lines()");

  // Bad input is refused with an exception naming the problem.
  bool refused = false;
  try {
    HL::Light_setup<K> bad(K::Point_3(0, 0, 3), K::Vector_3(0, 0, 1), K::Vector_3(0, 0, 1), 0.06);
  } catch (const HL::Invalid_input& e) {
    refused = e.problem() == HL::Invalid_input::Problem::INVALID_LIGHT_SETUP;
  }
  check(refused, "a light direction not in the light plane is refused");

  //! [fair]
  // The region: the faces around the dent.
  std::vector<Mesh::Face_index> region;
  for (auto f : faces(mesh)) {
    bool inside = true;
    for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      inside = inside &&
               CGAL::squared_distance(mesh.point(v), K::Point_3(0.1, -0.05, 0.25)) < 0.45 * 0.45;
    if (inside)
      region.push_back(f);
  }
  const HL::Fairing_report report = CGAL::fair_with_highlight_lines(
      mesh, region, lights,
      HLP::combine(CGAL::parameters::number_of_iterations(20),
                   HLP::fairing_visitor([](const HL::Fairing_report::Iteration& it) {
                     std::cout << "  q_fair " << it.fairness_energy << ", q_diff "
                               << it.difference_energy << ", max |x| / mean edge "
                               << it.relative_max_displacement << "\n";
                     return true; // false would stop the fairing
                   })));
  std::cout << (report.converged() ? "converged" : "stopped") << " after " << report.iterations
            << " iterations; " << report.number_of_movable_vertices << " movable vertices, "
            << report.number_of_lines_targeted << " lines targeted\n";
  //! [fair]

  check(report.iterations >= 1 && report.number_of_movable_vertices > 0 &&
            report.number_of_lines_targeted > 0,
        "the fairing moves vertices towards desired lines");
  check(!report.history.empty() &&
            report.history.back().target_value < report.history.front().target_value,
        "the fairing decreases the target function");
  // Everything outside the movable vertices is unchanged, bit for bit.
  const Mesh original = hood(40, 0.02);
  std::size_t moved_vertices = 0;
  for (auto v : vertices(mesh)) {
    const bool same = mesh.point(v) == original.point(v);
    moved_vertices += !same;
    if (!same)
      check(CGAL::squared_distance(mesh.point(v), K::Point_3(0.1, -0.05, 0.25)) < 0.45 * 0.45,
            "only vertices of the region move");
  }
  check(moved_vertices > 0 && moved_vertices <= report.number_of_movable_vertices,
        "the movable vertices moved");

  if (failures > 0) {
    std::cerr << failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  std::cout << "consumer: all checks passed\n";
  return EXIT_SUCCESS;
}

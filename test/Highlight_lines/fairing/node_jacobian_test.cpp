// The analytic Jacobian of the node positions (eq. 13 linearised through eq. 1 and eq. 3)
// against central finite differences.
#include "test_meshes.h"

#include <CGAL/fair_with_highlight_lines.h>

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace {
using namespace test;
namespace HL = CGAL::Highlight_lines;
typedef boost::graph_traits<Surface_mesh>::face_descriptor face_descriptor;
typedef boost::property_map<Surface_mesh, CGAL::vertex_point_t>::type Vpm;
typedef HL::internal::Fairing_problem<Surface_mesh, Vpm, K> Fairing_problem;

TEST(NodeJacobian, MatchesFiniteDifferences)
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(grid(
      24, 2.0 / 24, -1, -1,
      [](double x, double y) {
        return 0.2 * std::sin(1.3 * x + 0.2) * std::cos(1.1 * y) + 0.1 * x * y;
      },
      0.3, 23));
  std::set<face_descriptor> region;
  for (auto f : faces(mesh)) {
    bool inside = true;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      inside =
          inside && CGAL::squared_distance(mesh.point(v), Point(0, 0, mesh.point(v).z())) < 0.36;
    if (inside)
      region.insert(f);
  }
  const auto neighborhood = HL::internal::neighborhood(
      mesh, HL::internal::checked_region(mesh, region, get(CGAL::face_index, mesh)), 3);
  const Lights lights(Point(0.2, 0.1, 2.5), Vector(1, 0.3, 0), Vector(0, 0, 1), 0.05);
  HL::internal::Fairing_options options;
  const Vpm vpm = get(CGAL::vertex_point, mesh);
  const Fairing_problem problem(mesh, region, neighborhood, vpm, lights, options);
  const auto& lm = problem.engine().local_mesh();
  const auto directions = problem.movable_normals();

  // Recompute the model the fairing problem sees.
  HL::internal::Model_engine<Surface_mesh, Vpm, CGAL::Sequential_tag> probe(
      mesh, vpm, HL::parameters::face_range(neighborhood));
  HL::internal::Raw_model model;
  probe.compute_raw(lights, HL::internal::Level_window(), false, model);
  const HL::internal::Node_jacobian J = problem.jacobian(directions);

  std::size_t compared = 0;
  double worst = 0, scale = 0;
  for (std::size_t id = 0; id < model.nodes.nodes.size() && compared < 400; id += 7) {
    const HL::internal::Raw_node node = model.nodes.nodes[id];
    const auto row = J.node_row(node, lm.edge_vertices, model.levels, lights.spacing_value());
    // Every movable vertex within two rings of the node's carrier: those missing from the
    // analytic row must have a zero finite difference.
    const auto& region = problem.region();
    std::set<int> near;
    std::vector<int> carriers;
    if (node.vertex >= 0)
      carriers.push_back(node.vertex);
    else
      carriers = {lm.edge_vertices[std::size_t(node.edge)][0],
                  lm.edge_vertices[std::size_t(node.edge)][1]};
    for (int c : carriers) {
      near.insert(c);
      for (int i = region.vertex_neighbor_begin[std::size_t(c)];
           i < region.vertex_neighbor_begin[std::size_t(c) + 1]; ++i) {
        const int w = region.vertex_neighbors[std::size_t(i)];
        near.insert(w);
        if (std::size_t(w) < lm.number_of_model_vertices)
          for (int j = region.vertex_neighbor_begin[std::size_t(w)];
               j < region.vertex_neighbor_begin[std::size_t(w) + 1]; ++j)
            near.insert(region.vertex_neighbors[std::size_t(j)]);
      }
    }
    std::vector<std::pair<int, std::array<double, 3>>> entries;
    for (int v : near) {
      const int var = region.variable[std::size_t(v)];
      if (var < 0)
        continue;
      std::array<double, 3> analytic{0, 0, 0};
      for (const auto& e : row)
        if (e.first == var)
          analytic = e.second;
      entries.emplace_back(var, analytic);
    }
    for (const auto& entry : entries) {
      const int var = entry.first;
      const auto vd = lm.vertex_handles[std::size_t(problem.region().movable[std::size_t(var)])];
      const Point original = mesh.point(vd);
      auto node_position = [&](double x) {
        const auto& u = directions[std::size_t(var)];
        mesh.point(vd) =
            Point(original.x() + x * u[0], original.y() + x * u[1], original.z() + x * u[2]);
        probe.update_positions();
        std::vector<HL::internal::Vertex_level> levels;
        probe.classify(lights, levels);
        mesh.point(vd) = original;
        // Eq. 13 at the same edge and level, or the vertex itself.
        if (node.vertex >= 0) {
          const double* p = probe.local_mesh().point(node.vertex);
          return std::array<double, 3>{p[0], p[1], p[2]};
        }
        const int a = lm.edge_vertices[std::size_t(node.edge)][0],
                  b = lm.edge_vertices[std::size_t(node.edge)][1];
        const double da = levels[std::size_t(a)].distance, db = levels[std::size_t(b)].distance;
        const double t = (double(node.level) * lights.spacing_value() - da) / (db - da);
        const double* pa = probe.local_mesh().point(a);
        const double* pb = probe.local_mesh().point(b);
        return std::array<double, 3>{pa[0] + t * (pb[0] - pa[0]), pa[1] + t * (pb[1] - pa[1]),
                                     pa[2] + t * (pb[2] - pa[2])};
      };
      const double h = 1e-6;
      const auto plus = node_position(h), minus = node_position(-h);
      for (int k = 0; k < 3; ++k) {
        const double fd = (plus[k] - minus[k]) / (2 * h);
        worst = std::max(worst, std::abs(fd - entry.second[std::size_t(k)]));
        scale = std::max(scale, std::abs(fd));
      }
      ++compared;
    }
  }
  probe.update_positions();
  EXPECT_GT(compared, 50u);
  EXPECT_LT(worst, 1e-5 * std::max(scale, 1.0)) << "largest derivative " << scale;
}

} // namespace

// The highlight distance as a PLY vertex property (issue 18), as the command-line programs write it
// (demo/Highlight_lines/include/mesh_io.h, highlight_lines --mesh-out FILE.ply): written,
// read back with CGAL's PLY reader, the values are the library's, they are eq. 1 evaluated
// independently, and their linear interpolation along each edge equals m·s at the model's
// nodes, so that a viewer's contour filter at m·s draws the highlight lines.
#include "test_meshes.h"

#include "mesh_io.h"

#include <CGAL/Highlight_lines/Highlight_line_sweeper.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/compute_highlight_lines.h>

#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace {

using namespace test;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;

// d of eq. 1 at vertex v, with the area-weighted normal of eq. 3, computed here.
double ply_test_eq1_distance(const Surface_mesh& mesh, Surface_mesh::Vertex_index v,
                             const Lights& lights)
{
  const Vector n = area_weighted_normal(mesh, v);
  const Vector w = mesh.point(v) - lights.base_point();
  return CGAL::to_double(CGAL::cross_product(w, lights.light_direction()) * n) /
         CGAL::to_double(lights.plane_normal() * n);
}

bool ply_test_same(double a, double b)
{
  return (std::isnan(a) && std::isnan(b)) || a == b;
}

TEST(HighlightDistancePly, WrittenReadBackAndContouredAtTheNodes)
{
  for (const std::string name : {"spot.off", "beetle.off"}) {
    Surface_mesh mesh;
    ASSERT_TRUE(CGAL::IO::read_polygon_mesh(shared_data(name), mesh)) << name;
    const Lights lights = HL::default_light_setup(mesh, HLP::number_of_lines(40));
    const std::string path = ::testing::TempDir() + "highlight_distance_" + name + ".ply";
    ASSERT_TRUE(mesh_io::write_ply_with_highlight_distances(path, mesh, lights, true)) << name;

    Surface_mesh back;
    std::ifstream in(path, std::ios::binary);
    ASSERT_TRUE(CGAL::IO::read_PLY(in, back)) << name;
    ASSERT_EQ(num_vertices(back), num_vertices(mesh)) << name;
    ASSERT_EQ(num_faces(back), num_faces(mesh)) << name;
    auto [distance, has_distance] = back.property_map<Surface_mesh::Vertex_index, double>(
        mesh_io::highlight_distance_property());
    auto [level, has_level] =
        back.property_map<Surface_mesh::Vertex_index, double>(mesh_io::highlight_level_property());
    ASSERT_TRUE(has_distance && has_level) << name;

    // The library's values, read back bit for bit; NaN exactly on the vertices turned away.
    std::vector<double> library(num_vertices(mesh), 0.0);
    const HL::Highlight_line_sweeper<Surface_mesh> sweeper(mesh);
    sweeper.highlight_distances(lights,
                                CGAL::make_property_map(library), // indexed by the vertex index
                                HLP::facing_side_only(true));
    const double s = CGAL::to_double(lights.spacing());
    std::size_t defined = 0, checked_eq1 = 0;
    for (auto v : vertices(mesh)) {
      const double d = distance[v];
      ASSERT_TRUE(ply_test_same(d, library[std::size_t(v)])) << name << ": vertex " << v;
      ASSERT_TRUE(ply_test_same(level[v], d / s)) << name << ": vertex " << v;
      ASSERT_EQ(back.point(v), mesh.point(v)) << name << ": vertex " << v;
      if (std::isnan(d))
        continue;
      ++defined;
      // Eq. 1 evaluated independently (double normals: agreement to rounding).
      const double eq1 = ply_test_eq1_distance(mesh, v, lights);
      ASSERT_NEAR(d, eq1, 1e-9 * (std::abs(eq1) + s)) << name << ": vertex " << v;
      ++checked_eq1;
    }
    EXPECT_GT(defined, num_vertices(mesh) / 4) << name;
    EXPECT_LT(defined, num_vertices(mesh)) << name << ": the vertices turned away are NaN";
    EXPECT_EQ(checked_eq1, defined) << name;

    // The contour at m·s of the values read back passes through every node of the model.
    const auto model = CGAL::compute_highlight_lines(
        mesh, lights, CGAL::Emptyset_iterator(),
        HLP::combine(HLP::facing_side_only(true),
                     HLP::level_range(HL::default_level_range(mesh, lights))));
    ASSERT_GT(model.nodes().size(), 100u) << name;
    for (const auto& node : model.nodes()) {
      const double target = double(node.level) * s;
      if (node.is_on_vertex()) {
        EXPECT_EQ(distance[node.vertex], target) << name;
        continue;
      }
      const double d1 = distance[back.source(node.halfedge)],
                   d2 = distance[back.target(node.halfedge)];
      ASSERT_FALSE(std::isnan(d1) || std::isnan(d2)) << name;
      // The contour filter's crossing: where the linear interpolant equals m·s.
      const double t = (target - d1) / (d2 - d1);
      EXPECT_NEAR(t, node.parameter, 1e-9) << name << ": level " << node.level;
      EXPECT_NEAR(d1 + node.parameter * (d2 - d1), target, 1e-9 * (std::abs(d1) + std::abs(d2)))
          << name << ": level " << node.level;
    }
    std::remove(path.c_str());
  }
}

// highlight_distances() on Polyhedron_3 (vertices as handles, a map keyed by them) gives the
// values of Surface_mesh on the same surface, vertex for vertex in input order, NaN alike.
TEST(HighlightDistances, SurfaceMeshAndPolyhedronAgree)
{
  const Soup soup = grid(
      30, 0.1, -1.5, -1.5, [](double x, double y) { return 0.4 * std::sin(x) * std::cos(y); }, 0.3,
      11);
  const Surface_mesh sm = to_mesh<Surface_mesh>(soup);
  const Polyhedron poly = to_mesh<Polyhedron>(soup);
  const Lights lights(Point(0.2, -0.1, 3), Vector(1, 0.3, 0), Vector(-0.06, 0.2, 1), 0.07);

  std::vector<double> from_sm(num_vertices(sm), 0.0);
  HL::Highlight_line_sweeper<Surface_mesh>(sm).highlight_distances(
      lights, CGAL::make_property_map(from_sm), HLP::facing_side_only(true));
  std::map<Polyhedron::Vertex_const_handle, double> by_handle;
  HL::Highlight_line_sweeper<Polyhedron>(poly).highlight_distances(
      lights, boost::make_assoc_property_map(by_handle), HLP::facing_side_only(true));

  ASSERT_EQ(by_handle.size(), from_sm.size());
  std::size_t i = 0, defined = 0;
  for (auto v = poly.vertices_begin(); v != poly.vertices_end(); ++v, ++i) {
    ASSERT_TRUE(ply_test_same(by_handle[v], from_sm[i])) << "vertex " << i;
    defined += !std::isnan(from_sm[i]);
  }
  EXPECT_GT(defined, from_sm.size() / 2);
}

} // namespace

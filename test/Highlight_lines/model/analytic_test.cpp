// Analytic cases with known highlight lines: plane, cylinder, sphere.
#include "test_meshes.h"

#include <CGAL/compute_highlight_lines.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iterator>

namespace {
using namespace test;
using CGAL::Highlight_lines::Light_setup;

auto no_output()
{
  return CGAL::Emptyset_iterator();
}

// Lights in the plane z = h, running along x: on the plane z = 0 the highlight distance is
// d = -y, so light m images on the straight line y = -m s.
TEST(AnalyticPlane, LinesAreStraightEquallySpacedAndCounted)
{
  const double s = 0.7;
  const Surface_mesh mesh = to_mesh<Surface_mesh>(grid(
      40, 0.25, 0, 0, [](double, double) { return 0.0; }, 0.3));
  const Lights lights(Point(0, 0, 5), Vector(1, 0, 0), Vector(0, 0, 1), s);
  std::vector<std::vector<Point>> polylines;
  const auto model = CGAL::compute_highlight_lines(mesh, lights, std::back_inserter(polylines));

  // y in [0, 10]: levels m = 0 (the border row y = 0) down to m = -14 (y = 9.8).
  ASSERT_EQ(model.lines().size(), 15u);
  ASSERT_EQ(polylines.size(), 15u);
  for (const auto& line : model.lines()) {
    EXPECT_FALSE(line.is_closed);
    EXPECT_LE(line.level, 0);
    EXPECT_GE(line.level, -14);
    for (std::size_t n : line.nodes)
      EXPECT_NEAR(CGAL::to_double(model.nodes()[n].point.y()), -double(line.level) * s, 1e-12);
    // Each line crosses the whole plane.
    EXPECT_NEAR(CGAL::to_double(model.nodes()[line.nodes.front()].point.x()), 0.0, 1e-12);
    EXPECT_NEAR(CGAL::to_double(model.nodes()[line.nodes.back()].point.x()), 10.0, 1e-12);
  }
  EXPECT_EQ(model.number_of_skipped_edges(), 0u);
  EXPECT_EQ(model.number_of_undefined_vertices(), 0u);
}

// On an integer grid with unit spacing every vertex lies exactly on a level: all nodes are
// vertex nodes and every horizontal grid edge is a highlight edge.
TEST(AnalyticPlane, IntegerGridGivesVertexNodesAndHighlightEdges)
{
  const Surface_mesh mesh =
      to_mesh<Surface_mesh>(grid(10, 1.0, 0, 0, [](double, double) { return 0.0; }));
  const Lights lights(Point(0, 0, 3), Vector(1, 0, 0), Vector(0, 0, 1), 1.0);
  const auto model = CGAL::compute_highlight_lines(mesh, lights, no_output());
  ASSERT_EQ(model.lines().size(), 11u);
  for (const auto& line : model.lines()) {
    EXPECT_FALSE(line.is_closed);
    ASSERT_EQ(line.nodes.size(), 11u);
    for (std::size_t i = 0; i < line.nodes.size(); ++i) {
      const auto& node = model.nodes()[line.nodes[i]];
      EXPECT_TRUE(node.is_on_vertex());
      EXPECT_EQ(CGAL::to_double(node.point.y()), -double(line.level));
      EXPECT_EQ(node.degree, (i == 0 || i + 1 == line.nodes.size()) ? 1u : 2u);
    }
  }
  EXPECT_EQ(model.nodes().size(), 121u);
}

// Cylinder x^2 + z^2 = 1 around the y axis, lights along y in the plane z = h: d = h x / z,
// so light m images on the ruling at angle atan(m s / h) from +z. The vertex normals are exact
// (symmetric one-rings) away from the border; the node error is then the error of linear
// interpolation of d along the edges and must shrink quadratically.
double cylinder_node_error(int around)
{
  const double h = 3, s = 0.3;
  const Surface_mesh mesh =
      to_mesh<Surface_mesh>(cylinder_patch(1.0, 1.0, 2.0, around, around / 2));
  const Lights lights(Point(0, 0, h), Vector(0, 1, 0), Vector(0, 0, 1), s);
  const auto model = CGAL::compute_highlight_lines(mesh, lights, no_output());
  double worst = 0;
  std::size_t checked = 0;
  for (const auto& node : model.nodes()) {
    const double x = CGAL::to_double(node.point.x()), z = CGAL::to_double(node.point.z());
    const double angle = std::atan2(x, z), expected = std::atan(double(node.level) * s / h);
    // Away from the patch border, where one-sided one-rings tilt the normals (first order).
    const double y = CGAL::to_double(node.point.y());
    if (y < 0.25 || y > 1.75 || std::abs(angle) > 0.8)
      continue;
    worst = (std::max)(worst, std::abs(angle - expected));
    ++checked;
  }
  EXPECT_GT(checked, 100u);
  return worst;
}

TEST(AnalyticCylinder, NodesConvergeQuadraticallyToRulings)
{
  const double coarse = cylinder_node_error(24), fine = cylinder_node_error(96);
  EXPECT_LT(coarse, 0.02);
  EXPECT_LT(fine, coarse / 10) << "coarse " << coarse << " fine " << fine;
}

// Sphere of radius 1, lights along x in the plane z = h: d = -h y / z, so light m images on
// the great circle in the plane y + (m s / h) z = 0. Nodes near the equator z = 0, where the
// normal turns parallel to the light plane, are left out of the comparison.
double sphere_node_error(int levels, std::size_t& undefined)
{
  const double h = 3, s = 0.25;
  const Surface_mesh mesh = to_mesh<Surface_mesh>(sphere(1.0, levels));
  const Lights lights(Point(0, 0, h), Vector(1, 0, 0), Vector(0, 0, 1), s);
  const auto model = CGAL::compute_highlight_lines(mesh, lights, no_output());
  undefined = model.number_of_undefined_vertices();
  double worst = 0;
  for (const auto& node : model.nodes()) {
    const double x = CGAL::to_double(node.point.x()), y = CGAL::to_double(node.point.y()),
                 z = CGAL::to_double(node.point.z());
    const double len = std::sqrt(x * x + y * y + z * z);
    if (std::abs(z) < 0.3 * len)
      continue;
    const double c = double(node.level) * s / h;
    worst = (std::max)(worst, std::abs(y + c * z) / (len * std::sqrt(1 + c * c)));
  }
  return worst;
}

TEST(AnalyticSphere, NodesConvergeToGreatCircles)
{
  std::size_t undefined3 = 0, undefined5 = 0;
  const double coarse = sphere_node_error(3, undefined3), fine = sphere_node_error(5, undefined5);
  EXPECT_LT(coarse, 0.05);
  EXPECT_LT(fine, coarse / 3) << "coarse " << coarse << " fine " << fine;
  // The equator vertices have normals exactly parallel to the light plane (by symmetry).
  EXPECT_EQ(undefined3, 4u * 8u);
  EXPECT_EQ(undefined5, 4u * 32u);
}

} // namespace

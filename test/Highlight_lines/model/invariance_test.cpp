// The model does not depend on the mesh data structure, on the order of the faces, on a
// rigid motion or a uniform scaling of mesh and lights together, nor on restricting it to a
// face range (up to the faces left out).
#include "test_meshes.h"

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/compute_highlight_lines.h>

#include <gtest/gtest.h>

#include <cmath>

namespace {
using namespace test;

// A comparable summary of a model: lines with their level, closedness and node points.
struct Line_summary
{
  long long level;
  bool closed;
  std::vector<std::array<double, 3>> points;
  std::vector<bool> on_vertex;
};

template <typename Model>
std::vector<Line_summary> summarize(const Model& model)
{
  std::vector<Line_summary> result;
  for (const auto& line : model.lines()) {
    Line_summary s{line.level, line.is_closed, {}, {}};
    for (std::size_t n : line.nodes) {
      const auto& p = model.nodes()[n].point;
      s.points.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
      s.on_vertex.push_back(model.nodes()[n].is_on_vertex());
    }
    result.push_back(s);
  }
  return result;
}

// Same lines, same node counts and kinds; points within `tolerance`.
void expect_same_lines(const std::vector<Line_summary>& a, const std::vector<Line_summary>& b,
                       double tolerance)
{
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].level, b[i].level) << "line " << i;
    ASSERT_EQ(a[i].closed, b[i].closed) << "line " << i;
    ASSERT_EQ(a[i].points.size(), b[i].points.size()) << "line " << i;
    EXPECT_EQ(a[i].on_vertex, b[i].on_vertex);
    for (std::size_t j = 0; j < a[i].points.size(); ++j)
      for (int k = 0; k < 3; ++k)
        ASSERT_NEAR(a[i].points[j][k], b[i].points[j][k], tolerance)
            << "line " << i << " node " << j;
  }
}

Soup wavy_surface()
{
  return grid(
      50, 0.1, -2.5, -2.5,
      [](double x, double y) { return 0.3 * std::sin(1.3 * x) * std::cos(0.9 * y) + 0.05 * x * y; },
      0.3, 5);
}
const Lights wavy_lights(Point(0.3, -0.2, 4), Vector(1, 0.5, 0), Vector(0, 0, 1), 0.15);

TEST(Invariance, SurfaceMeshAndPolyhedronAgree)
{
  const Soup soup = wavy_surface();
  const auto sm = to_mesh<Surface_mesh>(soup);
  const auto poly = to_mesh<Polyhedron>(soup);
  const auto a = CGAL::compute_highlight_lines(sm, wavy_lights, CGAL::Emptyset_iterator());
  const auto b = CGAL::compute_highlight_lines(poly, wavy_lights, CGAL::Emptyset_iterator());
  EXPECT_GT(a.lines().size(), 10u);
  expect_same_lines(summarize(a), summarize(b), 1e-12);
}

TEST(Invariance, IndependentOfFaceOrder)
{
  Soup soup = wavy_surface();
  const auto reference = CGAL::compute_highlight_lines(to_mesh<Surface_mesh>(soup), wavy_lights,
                                                       CGAL::Emptyset_iterator());
  std::mt19937 rng(3);
  std::shuffle(soup.triangles.begin(), soup.triangles.end(), rng);
  for (auto& t : soup.triangles) // also rotate the corners of each triangle
    std::rotate(t.begin(), t.begin() + (rng() % 3), t.end());
  const auto shuffled = CGAL::compute_highlight_lines(to_mesh<Surface_mesh>(soup), wavy_lights,
                                                      CGAL::Emptyset_iterator());
  expect_same_lines(summarize(reference), summarize(shuffled), 1e-12);
}

TEST(Invariance, CommutesWithRigidMotionAndScaling)
{
  const Soup soup = wavy_surface();
  const auto reference = CGAL::compute_highlight_lines(to_mesh<Surface_mesh>(soup), wavy_lights,
                                                       CGAL::Emptyset_iterator());
  // Rotation about a generic axis, then scaling by 2.5 and a translation.
  const double angle = 0.7;
  Vector axis(1, 2, 2);
  axis = axis / 3;
  const double c = std::cos(angle), s = std::sin(angle);
  const double x = CGAL::to_double(axis.x()), y = CGAL::to_double(axis.y()),
               z = CGAL::to_double(axis.z());
  const double lambda = 2.5;
  const CGAL::Aff_transformation_3<K> motion(
      lambda * (c + x * x * (1 - c)), lambda * (x * y * (1 - c) - z * s),
      lambda * (x * z * (1 - c) + y * s), 1.0, lambda * (y * x * (1 - c) + z * s),
      lambda * (c + y * y * (1 - c)), lambda * (y * z * (1 - c) - x * s), -2.0,
      lambda * (z * x * (1 - c) - y * s), lambda * (z * y * (1 - c) + x * s),
      lambda * (c + z * z * (1 - c)), 0.5);
  Soup moved = soup;
  for (Point& p : moved.points)
    p = p.transform(motion);
  const auto result = CGAL::compute_highlight_lines(
      to_mesh<Surface_mesh>(moved), wavy_lights.transformed(motion), CGAL::Emptyset_iterator());
  // Compare as sets of (level, transformed point); canonical order may differ after motion.
  std::multimap<long long, std::array<double, 3>> expected, actual;
  for (const auto& node : reference.nodes()) {
    const Point p = node.point.transform(motion);
    expected.emplace(node.level, std::array<double, 3>{p.x(), p.y(), p.z()});
  }
  for (const auto& node : result.nodes())
    actual.emplace(node.level,
                   std::array<double, 3>{node.point.x(), node.point.y(), node.point.z()});
  ASSERT_EQ(expected.size(), actual.size());
  ASSERT_EQ(reference.lines().size(), result.lines().size());
  for (auto it = expected.begin(); it != expected.end();) {
    const long long level = it->first;
    auto range_a = expected.equal_range(level);
    auto range_b = actual.equal_range(level);
    ASSERT_EQ(std::distance(range_a.first, range_a.second),
              std::distance(range_b.first, range_b.second));
    for (auto a = range_a.first; a != range_a.second; ++a) {
      double best = 1e300;
      for (auto b = range_b.first; b != range_b.second; ++b) {
        const double d = std::hypot(a->second[0] - b->second[0], a->second[1] - b->second[1],
                                    a->second[2] - b->second[2]);
        best = (std::min)(best, d);
      }
      EXPECT_LT(best, 1e-9) << "level " << level;
    }
    it = range_a.second;
  }
}

TEST(Invariance, FaceRangeGivesTheRestrictedModel)
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(wavy_surface());
  // The faces whose centroid lies in a disk.
  std::vector<Surface_mesh::Face_index> disk;
  for (auto f : faces(mesh)) {
    double cx = 0, cy = 0;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      cx += mesh.point(v).x() / 3;
      cy += mesh.point(v).y() / 3;
    }
    if (cx * cx + cy * cy < 1.0)
      disk.push_back(f);
  }
  namespace HLP = CGAL::Highlight_lines::parameters;
  const auto whole = CGAL::compute_highlight_lines(mesh, wavy_lights, CGAL::Emptyset_iterator());
  const auto part = CGAL::compute_highlight_lines(mesh, wavy_lights, CGAL::Emptyset_iterator(),
                                                  HLP::face_range(disk));
  // Every node of the restricted model is a node of the whole model, bit for bit.
  std::set<std::pair<long long, std::array<double, 3>>> whole_nodes;
  for (const auto& n : whole.nodes())
    whole_nodes.insert({n.level, {n.point.x(), n.point.y(), n.point.z()}});
  ASSERT_GT(part.nodes().size(), 50u);
  for (const auto& n : part.nodes())
    EXPECT_TRUE(whole_nodes.count({n.level, {n.point.x(), n.point.y(), n.point.z()}}));
  EXPECT_LT(part.nodes().size(), whole.nodes().size());
}

} // namespace

// The model on a surface with creases (crease_edge_map): on a box, a CAD part of planar faces,
// every line runs straight within one face and ends at its creases; without the map (eq. 3
// averages the normals across the creases) the lines bend next to them.
#include "test_meshes.h"

#include <CGAL/Highlight_lines/Highlight_line_sweeper.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/compute_highlight_lines.h>

#include <boost/property_map/property_map.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <map>
#include <random>
#include <set>
#include <unordered_map>

namespace {
using namespace test;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;
namespace PMP = CGAL::Polygon_mesh_processing;

// Lights whose plane faces three sides of the box obliquely.
Lights oblique_lights()
{
  const Vector z = Vector(1, 2, 3) / std::sqrt(14.0);
  const Vector h = Vector(2, -1, 0) / std::sqrt(5.0);
  return Lights(Point(0.5, 0.5, 4), h, z, 0.05);
}

// The largest distance of a line's nodes from the chord through its ends, and whether they
// all lie on one side of the box.
template <typename Model>
std::pair<double, bool> straightness(const Model& model, const typename Model::Line& line)
{
  const Point p = model.nodes()[line.nodes.front()].point;
  const Point q = model.nodes()[line.nodes.back()].point;
  double largest = 0;
  std::array<bool, 6> on_side;
  on_side.fill(true);
  for (std::size_t n : line.nodes) {
    const Point r = model.nodes()[n].point;
    if (p != q) {
      const Vector d = q - p;
      largest = (std::max)(
          largest, std::sqrt(CGAL::cross_product(d, r - p).squared_length() / d.squared_length()));
    }
    for (int k = 0; k < 3; ++k) {
      on_side[std::size_t(2 * k)] = on_side[std::size_t(2 * k)] && std::abs(r[k]) <= 1e-12;
      on_side[std::size_t(2 * k + 1)] =
          on_side[std::size_t(2 * k + 1)] && std::abs(r[k] - 1) <= 1e-12;
    }
  }
  return {largest, std::find(on_side.begin(), on_side.end(), true) != on_side.end()};
}

template <typename Mesh>
using Crease_map = boost::associative_property_map<
    std::map<typename boost::graph_traits<Mesh>::edge_descriptor, bool>>;

TEST(Creases, LinesRunStraightWithinEachPlanarFaceOfABox)
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(jittered_box(12, 0.2, 3));
  // As in the manual (\ref hl_creases).
  auto creases = get(CGAL::dynamic_edge_property_t<bool>(), mesh);
  PMP::detect_sharp_edges(mesh, 60, creases);
  std::size_t sharp_edges = 0;
  for (auto e : edges(mesh))
    sharp_edges += get(creases, e) ? 1 : 0;
  ASSERT_EQ(sharp_edges, 12u * 12u); // 12 box edges of 12 mesh edges each

  const auto cut = CGAL::compute_highlight_lines(mesh, oblique_lights(), CGAL::Emptyset_iterator(),
                                                 HLP::crease_edge_map(creases));
  ASSERT_GT(cut.lines().size(), 30u);
  for (const auto& line : cut.lines()) {
    const auto [deviation, on_one_side] = straightness(cut, line);
    EXPECT_LE(deviation, 1e-12);
    EXPECT_TRUE(on_one_side);
  }

  // The paper's model (eq. 3 across the creases) bends the lines next to them.
  const auto averaged =
      CGAL::compute_highlight_lines(mesh, oblique_lights(), CGAL::Emptyset_iterator());
  double most = 0;
  std::size_t crossing = 0;
  for (const auto& line : averaged.lines()) {
    const auto [deviation, on_one_side] = straightness(averaged, line);
    most = (std::max)(most, deviation);
    crossing += on_one_side ? 0 : 1;
  }
  EXPECT_GT(most, 1e-2);
  EXPECT_GT(crossing, 0u);
}

// A map without crease edges leaves the model of the paper, bit for bit.
TEST(Creases, NoCreaseEdgeGivesThePapersModel)
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(jittered_box(8, 0.2, 5));
  std::map<Surface_mesh::Edge_index, bool> none;
  const auto with_map =
      CGAL::compute_highlight_lines(mesh, oblique_lights(), CGAL::Emptyset_iterator(),
                                    HLP::crease_edge_map(Crease_map<Surface_mesh>(none)));
  const auto without =
      CGAL::compute_highlight_lines(mesh, oblique_lights(), CGAL::Emptyset_iterator());
  ASSERT_EQ(with_map.nodes().size(), without.nodes().size());
  ASSERT_EQ(with_map.lines().size(), without.lines().size());
  for (std::size_t i = 0; i < without.nodes().size(); ++i)
    EXPECT_EQ(with_map.nodes()[i].point, without.nodes()[i].point);
  for (std::size_t i = 0; i < without.lines().size(); ++i)
    EXPECT_EQ(with_map.lines()[i].nodes, without.lines()[i].nodes);
}

// Polyhedron_3 with a map keyed by its edges gives the lines of Surface_mesh; the nodes on a
// crease edge name that edge; a face range gives the lines of its faces.
TEST(Creases, PolyhedronAgreesWithSurfaceMesh)
{
  const Soup soup = jittered_box(8, 0.2, 7);
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  const Polyhedron poly = to_mesh<Polyhedron>(soup);
  std::map<Surface_mesh::Edge_index, bool> sharp_sm;
  std::map<boost::graph_traits<Polyhedron>::edge_descriptor, bool> sharp_poly;
  Crease_map<Surface_mesh> creases_sm(sharp_sm);
  Crease_map<Polyhedron> creases_poly(sharp_poly);
  PMP::detect_sharp_edges(mesh, 60, creases_sm);
  PMP::detect_sharp_edges(poly, 60, creases_poly);
  std::vector<std::vector<Point>> lines_sm, lines_poly;
  const auto model_sm = CGAL::compute_highlight_lines(
      mesh, oblique_lights(), std::back_inserter(lines_sm), HLP::crease_edge_map(creases_sm));
  CGAL::compute_highlight_lines(poly, oblique_lights(), std::back_inserter(lines_poly),
                                HLP::crease_edge_map(creases_poly));
  ASSERT_GT(lines_sm.size(), 20u);
  std::sort(lines_sm.begin(), lines_sm.end());
  std::sort(lines_poly.begin(), lines_poly.end());
  EXPECT_EQ(lines_sm, lines_poly);

  // Nodes on edges carry a halfedge of that edge: a line that ends on a crease ends on it.
  std::size_t ends_on_creases = 0;
  for (const auto& line : model_sm.lines())
    for (std::size_t n : {line.nodes.front(), line.nodes.back()}) {
      const auto& node = model_sm.nodes()[n];
      if (node.halfedge != Surface_mesh::null_halfedge() &&
          get(creases_sm, edge(node.halfedge, mesh)))
        ++ends_on_creases;
    }
  EXPECT_GT(ends_on_creases, model_sm.lines().size());
}

// On a face range, the cut model is the whole cut model restricted to the range: the lines
// of the top side alone are those of the whole box that lie on it.
TEST(Creases, FaceRangeGivesTheWholeModelRestricted)
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(jittered_box(10, 0.2, 9));
  auto creases = get(CGAL::dynamic_edge_property_t<bool>(), mesh);
  PMP::detect_sharp_edges(mesh, 60, creases);
  std::vector<Surface_mesh::Face_index> top;
  for (auto f : faces(mesh)) {
    bool on_top = true;
    for (auto v : vertices_around_face(mesh.halfedge(f), mesh))
      on_top = on_top && mesh.point(v).z() == 1;
    if (on_top)
      top.push_back(f);
  }
  ASSERT_EQ(num_faces(mesh), 1200u);
  ASSERT_EQ(top.size(), 200u);
  std::vector<std::vector<Point>> whole, range;
  const auto model = CGAL::compute_highlight_lines(
      mesh, oblique_lights(), std::back_inserter(whole), HLP::crease_edge_map(creases));
  CGAL::compute_highlight_lines(mesh, oblique_lights(), std::back_inserter(range),
                                HLP::face_range(HLP::crease_edge_map(creases), top));
  whole.erase(std::remove_if(whole.begin(), whole.end(),
                             [](const std::vector<Point>& line) {
                               for (const Point& p : line)
                                 if (p.z() != 1)
                                   return true;
                               return false;
                             }),
              whole.end());
  ASSERT_GT(range.size(), 10u);
  std::sort(whole.begin(), whole.end());
  std::sort(range.begin(), range.end());
  EXPECT_EQ(whole, range);
}

} // namespace

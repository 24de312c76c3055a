// Topological guarantees of the node connection (§2.4 of the paper): segments never cross
// inside a triangle, every node has two segments except at borders, undefined vertices and
// saddles exactly on a level, closed lines come out closed, the face order does not matter.
#include "test_meshes.h"

#include <CGAL/compute_highlight_lines.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

namespace {
using namespace test;

typedef CGAL::Highlight_lines::Highlight_line_model<Surface_mesh, K> Model;
typedef boost::graph_traits<Surface_mesh>::face_descriptor face_descriptor;
typedef boost::graph_traits<Surface_mesh>::halfedge_descriptor halfedge_descriptor;

// A smooth bump on a plane, seen by lights far above: the bump reverses the slope of d, so
// d has extrema there and some highlight lines close around them.
Surface_mesh bump(int n, double jitter)
{
  return to_mesh<Surface_mesh>(grid(
      n, 4.0 / n, -2, -2,
      [](double x, double y) { return 0.2 * std::exp(-(x * x + y * y) / 0.49); }, jitter, 11));
}
const Lights bump_lights(Point(0.1, 0.05, 5), Vector(1, 0, 0), Vector(0, 0, 1), 0.17);

// Faces around the carrier of a node.
std::vector<face_descriptor> carrier_faces(const Surface_mesh& mesh, const Model::Node& node)
{
  std::vector<face_descriptor> faces;
  if (node.is_on_vertex()) {
    for (face_descriptor f : CGAL::faces_around_target(mesh.halfedge(node.vertex), mesh))
      if (f != Surface_mesh::null_face())
        faces.push_back(f);
  } else {
    for (halfedge_descriptor h : {node.halfedge, mesh.opposite(node.halfedge)})
      if (!mesh.is_border(h))
        faces.push_back(mesh.face(h));
  }
  return faces;
}

// Position of a node on the boundary of face f, in [0, 3): corner j is at j, edge j (from
// corner j to corner j+1) covers (j, j+1).
double boundary_position(const Surface_mesh& mesh, face_descriptor f, const Model::Node& node)
{
  halfedge_descriptor h = mesh.halfedge(f);
  for (int j = 0; j < 3; ++j, h = mesh.next(h)) {
    if (node.is_on_vertex() && mesh.source(h) == node.vertex)
      return j;
    if (!node.is_on_vertex() && h == node.halfedge)
      return j + node.parameter;
    if (!node.is_on_vertex() && mesh.opposite(h) == node.halfedge)
      return j + 1 - node.parameter;
  }
  ADD_FAILURE() << "node not on face";
  return -1;
}

struct Face_segment
{
  long long level;
  double a, b; // boundary positions, a < b
};

std::map<face_descriptor, std::vector<Face_segment>> segments_by_face(const Surface_mesh& mesh,
                                                                      const Model& model)
{
  std::map<face_descriptor, std::vector<Face_segment>> result;
  for (const auto& s : segments_of(model)) {
    const auto& p = model.nodes()[s.first];
    const auto& q = model.nodes()[s.second];
    EXPECT_EQ(p.level, q.level);
    std::vector<face_descriptor> fp = carrier_faces(mesh, p), fq = carrier_faces(mesh, q);
    std::vector<face_descriptor> common;
    for (face_descriptor f : fp)
      if (std::find(fq.begin(), fq.end(), f) != fq.end())
        common.push_back(f);
    EXPECT_FALSE(common.empty()) << "a segment joins nodes that share no face";
    if (p.is_on_vertex() && q.is_on_vertex())
      continue; // a highlight edge: on the boundary of its faces
    EXPECT_EQ(common.size(), 1u);
    if (common.empty())
      continue;
    double a = boundary_position(mesh, common.front(), p),
           b = boundary_position(mesh, common.front(), q);
    if (a > b)
      std::swap(a, b);
    result[common.front()].push_back({p.level, a, b});
  }
  return result;
}

TEST(NodeConnection, NoSegmentsCrossInATriangle)
{
  const Surface_mesh mesh = bump(60, 0.35);
  const Model model = CGAL::compute_highlight_lines(mesh, bump_lights, CGAL::Emptyset_iterator());
  const auto by_face = segments_by_face(mesh, model);
  std::size_t pairs = 0;
  for (const auto& entry : by_face) {
    const auto& segs = entry.second;
    std::set<long long> levels;
    for (const auto& s : segs)
      EXPECT_TRUE(levels.insert(s.level).second) << "two segments of one level in a triangle";
    for (std::size_t i = 0; i < segs.size(); ++i)
      for (std::size_t j = i + 1; j < segs.size(); ++j) {
        ++pairs;
        // Chords of a convex boundary cross or touch iff their end points interleave.
        const auto inside = [&](double t) { return segs[i].a < t && t < segs[i].b; };
        const auto on_end = [&](double t) { return t == segs[i].a || t == segs[i].b; };
        EXPECT_FALSE(on_end(segs[j].a) || on_end(segs[j].b));
        EXPECT_EQ(inside(segs[j].a), inside(segs[j].b)) << "segments cross in a triangle";
      }
  }
  EXPECT_GT(pairs, 100u); // the test has teeth: many triangles carry several lines
}

TEST(NodeConnection, InteriorNodesHaveExactlyTwoSegments)
{
  const Surface_mesh mesh = bump(60, 0.35);
  const Model model = CGAL::compute_highlight_lines(mesh, bump_lights, CGAL::Emptyset_iterator());
  ASSERT_EQ(model.number_of_skipped_edges(), 0u);
  ASSERT_EQ(model.number_of_undefined_vertices(), 0u);
  std::size_t border_nodes = 0;
  for (const auto& node : model.nodes()) {
    const bool on_border = node.is_on_vertex() ? CGAL::is_border(node.vertex, mesh) != boost::none
                                               : CGAL::is_border(mesh.edge(node.halfedge), mesh);
    border_nodes += on_border;
    EXPECT_EQ(node.degree, on_border ? 1u : 2u);
  }
  EXPECT_GT(border_nodes, 20u);
}

TEST(NodeConnection, ClosedHighlightLinesComeOutClosed)
{
  const Surface_mesh mesh = bump(60, 0.35);
  const Model model = CGAL::compute_highlight_lines(mesh, bump_lights, CGAL::Emptyset_iterator());
  std::size_t closed = 0;
  for (const auto& line : model.lines()) {
    if (line.is_closed) {
      ++closed;
      EXPECT_GE(line.nodes.size(), 3u);
    } else {
      // An open line must end where the guarantees allow it: here only on the border.
      for (std::size_t end : {line.nodes.front(), line.nodes.back()})
        EXPECT_EQ(model.nodes()[end].degree, 1u);
    }
  }
  EXPECT_GE(closed, 2u); // around the extrema of d on both sides of the bump
}

// A grid symmetric under the half-turn about the origin: the normal at the origin is exactly
// vertical, so with the base light above the origin its d value is exactly 0. The surface
// and the lights are chosen so that d has a monkey-saddle-like critical point there: level 0
// passes through the origin vertex in six directions.
TEST(NodeConnection, SaddleVertexOnLevelSplitsLines)
{
  const double phi = 20 * M_PI / 180, c = std::cos(phi), s = std::sin(phi);
  const double h = 2;
  // Coordinates are multiples of 1/32: the half-turn maps vertices to vertices exactly.
  const Surface_mesh mesh =
      to_mesh<Surface_mesh>(grid(20, 1.0 / 32, -10.0 / 32, -10.0 / 32, [&](double x, double y) {
        const double u = c * x + s * y, v = -s * x + c * y; // surface rotated with the lights
        return 0.5 * (-u * u + v * v / h);
      }));
  const Lights lights(Point(0, 0, h), Vector(c, s, 0), Vector(0, 0, 1), 0.01);
  const Model model = CGAL::compute_highlight_lines(mesh, lights, CGAL::Emptyset_iterator());
  const Model::Node* saddle = nullptr;
  for (const auto& node : model.nodes())
    if (node.is_on_vertex() && node.point == Point(0, 0, 0))
      saddle = &node;
  ASSERT_NE(saddle, nullptr) << "the origin must lie exactly on level 0";
  EXPECT_EQ(saddle->level, 0);
  EXPECT_EQ(saddle->degree, 6u);
  std::size_t ends_at_saddle = 0;
  for (const auto& line : model.lines())
    if (!line.is_closed)
      for (std::size_t end : {line.nodes.front(), line.nodes.back()})
        ends_at_saddle += &model.nodes()[end] == saddle;
  EXPECT_EQ(ends_at_saddle, 6u);
}

// On a sphere the normals of the equator vertices are exactly parallel to a horizontal light
// plane: d is undefined there; lines must stop before, with no NaN anywhere.
TEST(NodeConnection, PolesEndLinesWithoutNaN)
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(sphere(1.0, 4));
  const Lights lights(Point(0.2, 0.1, 3), Vector(1, 0, 0), Vector(0, 0, 1), 0.2);
  const Model model = CGAL::compute_highlight_lines(mesh, lights, CGAL::Emptyset_iterator());
  EXPECT_EQ(model.number_of_undefined_vertices(), 64u);
  for (const auto& node : model.nodes()) {
    EXPECT_TRUE(std::isfinite(CGAL::to_double(node.point.x())) &&
                std::isfinite(CGAL::to_double(node.point.y())) &&
                std::isfinite(CGAL::to_double(node.point.z())));
    // No node on an edge that touches the equator.
    if (!node.is_on_vertex()) {
      EXPECT_NE(CGAL::to_double(mesh.point(mesh.source(node.halfedge)).z()), 0.0);
      EXPECT_NE(CGAL::to_double(mesh.point(mesh.target(node.halfedge)).z()), 0.0);
    }
  }
  EXPECT_GT(model.lines().size(), 10u);
}

// Bounded output: near the silhouette seen from the light plane d grows without bound; the
// per-edge cap skips such edges and counts them, and the level range restricts the model.
TEST(NodeConnection, LevelCapAndRangeBoundTheOutput)
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(sphere(1.0, 4));
  const Lights lights(Point(0.2, 0.1, 3), Vector(1, 0, 0), Vector(0, 0, 1), 0.01);
  namespace HLP = CGAL::Highlight_lines::parameters;
  const Model capped = CGAL::compute_highlight_lines(mesh, lights, CGAL::Emptyset_iterator(),
                                                     HLP::max_levels_per_edge(8));
  const Model uncapped = CGAL::compute_highlight_lines(mesh, lights, CGAL::Emptyset_iterator(),
                                                       HLP::max_levels_per_edge(1000000));
  EXPECT_GT(capped.number_of_skipped_edges(), 0u);
  EXPECT_EQ(uncapped.number_of_skipped_edges(), 0u);
  EXPECT_LT(capped.nodes().size(), uncapped.nodes().size());
  const Model ranged = CGAL::compute_highlight_lines(mesh, lights, CGAL::Emptyset_iterator(),
                                                     HLP::level_range(std::make_pair(-3, 5)));
  EXPECT_GT(ranged.nodes().size(), 0u);
  for (const auto& node : ranged.nodes()) {
    EXPECT_GE(node.level, -3);
    EXPECT_LE(node.level, 5);
  }
}

} // namespace

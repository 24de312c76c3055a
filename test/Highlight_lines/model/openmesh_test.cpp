// OpenMesh, through CGAL's graph traits, gives the same model as Surface_mesh.
#ifdef HIGHLIGHT_LINES_HAS_OPENMESH

// OpenMesh's property containers trip GCC 12's -Wmaybe-uninitialized once inlined here.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "test_meshes.h"

#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
#include <CGAL/boost/graph/properties_TriMesh_ArrayKernelT.h>
#include <CGAL/Highlight_lines/Highlight_line_sweeper.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/compute_highlight_lines.h>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <map>

#include <gtest/gtest.h>

namespace {
using namespace test;
struct Double_traits : public OpenMesh::DefaultTraits
{
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
typedef OpenMesh::TriMesh_ArrayKernelT<Double_traits> Open_mesh;

// Built with OpenMesh's own API: CGAL 5.5's point map for OpenMesh writes through float.
Open_mesh open_mesh(const Soup& soup)
{
  Open_mesh om;
  std::vector<Open_mesh::VertexHandle> handles;
  for (const Point& p : soup.points)
    handles.push_back(om.add_vertex(Open_mesh::Point(p.x(), p.y(), p.z())));
  for (const auto& t : soup.triangles)
    om.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
  return om;
}

// A soup as Surface_mesh and as OpenMesh, each with its edges sharper than 60 degrees.
struct Meshes_with_creases
{
  typedef std::map<Surface_mesh::Edge_index, bool> Sharp_sm;
  typedef std::map<boost::graph_traits<Open_mesh>::edge_descriptor, bool> Sharp_om;

  Surface_mesh sm;
  Open_mesh om;
  Sharp_sm sharp_sm;
  Sharp_om sharp_om;

  boost::associative_property_map<Sharp_sm> creases_sm()
  {
    return boost::associative_property_map<Sharp_sm>(sharp_sm);
  }
  boost::associative_property_map<Sharp_om> creases_om()
  {
    return boost::associative_property_map<Sharp_om>(sharp_om);
  }

  explicit Meshes_with_creases(const Soup& soup)
      : sm(to_mesh<Surface_mesh>(soup)), om(open_mesh(soup))
  {
    CGAL::Polygon_mesh_processing::detect_sharp_edges(sm, 60, creases_sm());
    CGAL::Polygon_mesh_processing::detect_sharp_edges(om, 60, creases_om());
  }

  // The models cut along the creases, under oblique lights that cross every side of the box.
  const Lights lights{Point(0.5, 0.5, 4), Vector(2, -1, 0), Vector(1, 2, 3), 0.05};
  auto model_sm()
  {
    return CGAL::compute_highlight_lines(
        sm, lights, CGAL::Emptyset_iterator(),
        CGAL::Highlight_lines::parameters::crease_edge_map(creases_sm()));
  }
  auto model_om()
  {
    return CGAL::compute_highlight_lines(
        om, lights, CGAL::Emptyset_iterator(),
        CGAL::Highlight_lines::parameters::crease_edge_map(creases_om()));
  }
};

TEST(Invariance, OpenMeshAndSurfaceMeshAgree)
{
  const Soup soup = grid(
      40, 0.1, -2, -2,
      [](double x, double y) {
        return 0.25 * std::sin(1.7 * x + 0.3) * std::cos(1.1 * y) + 0.04 * x * x;
      },
      0.3, 9);
  const Surface_mesh sm = to_mesh<Surface_mesh>(soup);
  const Open_mesh om = open_mesh(soup);
  const Lights lights(Point(0.3, -0.2, 4), Vector(0.6, 0.8, 0), Vector(0, 0, 1), 0.12);
  const auto a = CGAL::compute_highlight_lines(sm, lights, CGAL::Emptyset_iterator());
  const auto b = CGAL::compute_highlight_lines(om, lights, CGAL::Emptyset_iterator());
  ASSERT_GT(a.lines().size(), 10u);
  ASSERT_EQ(a.lines().size(), b.lines().size());
  ASSERT_EQ(a.nodes().size(), b.nodes().size());
  for (std::size_t i = 0; i < a.lines().size(); ++i) {
    ASSERT_EQ(a.lines()[i].level, b.lines()[i].level);
    ASSERT_EQ(a.lines()[i].is_closed, b.lines()[i].is_closed);
    ASSERT_EQ(a.lines()[i].nodes, b.lines()[i].nodes);
  }
  for (std::size_t i = 0; i < a.nodes().size(); ++i) {
    EXPECT_NEAR(a.nodes()[i].point.x(), CGAL::to_double(b.nodes()[i].point.x()), 1e-12);
    EXPECT_NEAR(a.nodes()[i].point.y(), CGAL::to_double(b.nodes()[i].point.y()), 1e-12);
    EXPECT_NEAR(a.nodes()[i].point.z(), CGAL::to_double(b.nodes()[i].point.z()), 1e-12);
    EXPECT_EQ(a.nodes()[i].degree, b.nodes()[i].degree);
  }
}

// The model cut along the creases (crease_edge_map, a map keyed by OpenMesh's edges) gives
// the lines of Surface_mesh.
TEST(Invariance, OpenMeshAndSurfaceMeshAgreeWithCreases)
{
  Meshes_with_creases meshes(jittered_box(8, 0.2, 13));
  std::vector<std::vector<Point>> a;
  meshes.model_sm().polylines(std::back_inserter(a));
  const auto b = meshes.model_om();
  ASSERT_GT(a.size(), 20u);
  ASSERT_EQ(a.size(), b.lines().size());
  std::vector<std::vector<std::array<double, 3>>> la, lb;
  for (const auto& line : a) {
    la.emplace_back();
    for (const Point& p : line)
      la.back().push_back({p.x(), p.y(), p.z()});
  }
  for (const auto& line : b.lines()) {
    lb.emplace_back();
    for (std::size_t n : line.nodes) {
      const auto& p = b.nodes()[n].point;
      lb.back().push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
    }
    if (line.is_closed)
      lb.back().push_back(lb.back().front());
  }
  std::sort(la.begin(), la.end());
  std::sort(lb.begin(), lb.end());
  ASSERT_EQ(la.size(), lb.size());
  for (std::size_t i = 0; i < la.size(); ++i) {
    ASSERT_EQ(la[i].size(), lb[i].size());
    for (std::size_t j = 0; j < la[i].size(); ++j)
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(la[i][j][std::size_t(k)], lb[i][j][std::size_t(k)], 1e-12);
  }
}

// An open box: detect_sharp_edges() marks its border edges too, and OpenMesh's halfedge(v)
// puts the border halfedge last around a border vertex. The cut gives a vertex one local copy
// per sector with faces only (no copy without faces, whose distance value would be undefined):
// the same counts and lines as Surface_mesh, whose border halfedge comes first.
TEST(Invariance, OpenMeshAndSurfaceMeshAgreeWithCreasesOnAnOpenMesh)
{
  Meshes_with_creases meshes(jittered_box(8, 0.2, 17, true));
  const auto a = meshes.model_sm();
  const auto b = meshes.model_om();
  namespace HLP = CGAL::Highlight_lines::parameters;
  // Sectors: the 4 bottom corners have 3, the 7 inner vertices of the 8 box edges left 2, the
  // 4 rim corners 2 (two walls), the other rim vertices 1.
  const std::size_t copies = num_vertices(meshes.sm) + 4 * 2 + 8 * 7 + 4 * 1;
  EXPECT_EQ(CGAL::Highlight_lines::Highlight_line_sweeper<Surface_mesh>(
                meshes.sm, HLP::crease_edge_map(meshes.creases_sm()))
                .number_of_vertices(),
            copies);
  EXPECT_EQ(CGAL::Highlight_lines::Highlight_line_sweeper<Open_mesh>(
                meshes.om, HLP::crease_edge_map(meshes.creases_om()))
                .number_of_vertices(),
            copies);
  EXPECT_EQ(a.number_of_undefined_vertices(), b.number_of_undefined_vertices());
  ASSERT_GT(a.lines().size(), 10u);
  ASSERT_EQ(a.lines().size(), b.lines().size());
  ASSERT_EQ(a.nodes().size(), b.nodes().size());
}

} // namespace

#endif

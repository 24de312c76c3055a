// OpenMesh, through CGAL's graph traits and a point map of the caller's, is faired as
// Surface_mesh is: the automatic mode (detection and fairing) and a pit whose second run starts
// from Polygon_mesh_processing::fair() on the OpenMesh mesh itself.
#ifdef HIGHLIGHT_LINES_HAS_OPENMESH

// OpenMesh's property containers trip GCC 12's -Wmaybe-uninitialized once inlined here.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "test_meshes.h"

#include "detection_evaluation.h"

#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
#include <CGAL/boost/graph/properties_TriMesh_ArrayKernelT.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/detect_and_fair_highlight_line_irregularities.h>
#include <CGAL/fair_with_highlight_lines.h>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace {
namespace HB = Highlight_lines_benchmark;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;

struct Double_traits : public OpenMesh::DefaultTraits
{
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
typedef OpenMesh::TriMesh_ArrayKernelT<Double_traits> Open_mesh;

// The points of an Open_mesh as CGAL points, read and written in double precision (CGAL 5.5's
// own point map for OpenMesh writes through float).
struct Open_mesh_point_map
{
  typedef boost::graph_traits<Open_mesh>::vertex_descriptor key_type;
  typedef test::Point value_type;
  typedef value_type reference;
  typedef boost::read_write_property_map_tag category;
  Open_mesh* mesh = nullptr;

  friend value_type get(const Open_mesh_point_map& map, key_type v)
  {
    const Open_mesh::Point& p = map.mesh->point(v);
    return value_type(p[0], p[1], p[2]);
  }
  friend void put(const Open_mesh_point_map& map, key_type v, const value_type& p)
  {
    map.mesh->set_point(v, Open_mesh::Point(p.x(), p.y(), p.z()));
  }
};

// Built with OpenMesh's own API, vertices and faces in the soup's order.
Open_mesh to_open_mesh(const test::Soup& soup)
{
  Open_mesh mesh;
  std::vector<Open_mesh::VertexHandle> handles;
  for (const test::Point& p : soup.points)
    handles.push_back(mesh.add_vertex(Open_mesh::Point(p.x(), p.y(), p.z())));
  for (const auto& t : soup.triangles)
    mesh.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
  return mesh;
}

// The largest distance between the points of the two meshes, vertex by vertex.
double largest_difference(const HB::Mesh& a, const Open_mesh& b)
{
  double largest = 0;
  for (auto v : vertices(a)) {
    const Open_mesh::Point& p = b.point(Open_mesh::VertexHandle(int(std::uint32_t(v))));
    largest = (std::max)(
        largest, std::sqrt(CGAL::squared_distance(a.point(v), test::Point(p[0], p[1], p[2]))));
  }
  return largest;
}

TEST(OpenMesh, AutomaticModeAgreesWithSurfaceMesh)
{
  test::Soup soup;
  HB::Mesh mesh = HB::hood_with_one_defect(soup);
  Open_mesh open_mesh = to_open_mesh(soup);
  const Open_mesh dented = open_mesh;
  Open_mesh_point_map points;
  points.mesh = &open_mesh;
  const auto lights = HL::default_light_setup(mesh, HLP::number_of_lines(30));
  const auto a = CGAL::detect_and_fair_highlight_line_irregularities(mesh, lights);
  const auto b = CGAL::detect_and_fair_highlight_line_irregularities(
      open_mesh, lights, CGAL::parameters::vertex_point_map(points));
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), a.size());
  EXPECT_TRUE(a[0].repaired && b[0].repaired);
  EXPECT_EQ(a[0].report.iterations, b[0].report.iterations);
  EXPECT_LT(largest_difference(mesh, open_mesh), 1e-10);
  // The fairing moved the dent (not only the points read back unchanged).
  double moved = 0;
  for (auto v : open_mesh.vertices())
    moved = (std::max)(moved, (open_mesh.point(v) - dented.point(v)).norm());
  EXPECT_GT(moved, 1e-3);
}

// A pit as deep as it is wide: its first run ends held back against flips and the second starts
// from PMP::fair()'s fill, computed through the caller's point map.
TEST(OpenMesh, PitRestartedFromAFillAgreesWithSurfaceMesh)
{
  test::Soup soup = test::grid(30, 2.0 / 30, -1, -1, test::hood, 0.3, 17);
  const double depth = 0.3, radius = 0.3, cx = 0.1, cy = -0.05;
  for (test::Point& p : soup.points) {
    const double r2 =
        ((p.x() - cx) * (p.x() - cx) + (p.y() - cy) * (p.y() - cy)) / (radius * radius);
    if (r2 < 1)
      p = test::Point(p.x(), p.y(), p.z() - depth * (1 - r2) * (1 - r2) * (1 - r2));
  }
  HB::Mesh mesh = test::to_mesh<HB::Mesh>(soup);
  Open_mesh open_mesh = to_open_mesh(soup);
  std::vector<HB::Mesh::Face_index> region;
  std::vector<Open_mesh::FaceHandle> open_region;
  for (auto f : faces(mesh)) {
    bool inside = true;
    for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh)) {
      const test::Point& p = mesh.point(v);
      inside = inside && (p.x() - cx) * (p.x() - cx) + (p.y() - cy) * (p.y() - cy) <
                             1.5 * radius * 1.5 * radius;
    }
    if (inside) {
      region.push_back(f);
      open_region.push_back(Open_mesh::FaceHandle(int(std::uint32_t(f))));
    }
  }
  Open_mesh_point_map points;
  points.mesh = &open_mesh;
  const test::Lights lights(test::Point(0, 0, 3), test::Vector(1, 0, 0), test::Vector(0, 0, 1),
                            0.06);
  const HL::Fairing_report a = CGAL::fair_with_highlight_lines(mesh, region, lights);
  const HL::Fairing_report b = CGAL::fair_with_highlight_lines(
      open_mesh, open_region, lights, CGAL::parameters::vertex_point_map(points));
  EXPECT_TRUE(a.restarted_from_fill);
  EXPECT_TRUE(b.restarted_from_fill);
  EXPECT_EQ(a.first_run_iterations, b.first_run_iterations);
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_LT(largest_difference(mesh, open_mesh), 1e-10);
}

} // namespace

#endif

// Inputs found by the fuzzer (test/fuzz), each reduced to the call that went wrong. The checks
// are the fuzzer's: an expected error leaves the mesh bit-identical; a result has only finite
// points, moves movable vertices only and flips no triangle with respect to the input.
#include "test_meshes.h"

#include <CGAL/Highlight_lines/fairing_building_blocks.h>
#include <CGAL/fair_with_highlight_lines.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <sstream>

namespace {
using namespace test;
namespace HL = CGAL::Highlight_lines;
typedef Surface_mesh::Face_index Face;
typedef Surface_mesh::Vertex_index Vertex;

Surface_mesh read_off(const std::string& text)
{
  Surface_mesh mesh;
  std::istringstream in(text);
  EXPECT_TRUE(CGAL::IO::read_OFF(in, mesh));
  return mesh;
}

// The fuzzer's fixed light setups: plane normal (1, 1, 1), one bounding-box diagonal above the
// centre of the box, spacing diagonal / divisions.
Lights diagonal_lights(const Surface_mesh& mesh, double divisions)
{
  const CGAL::Bbox_3 box = CGAL::bbox_3(mesh.points().begin(), mesh.points().end());
  const double diagonal =
      std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                CGAL::square(box.zmax() - box.zmin()));
  const Point centre((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2,
                     (box.zmin() + box.zmax()) / 2);
  return Lights(centre + Vector(1, 1, 1) * diagonal, Vector(1, -1, 0), Vector(1, 1, 1),
                diagonal / divisions);
}

// Fairs `region` and checks the fuzzer's properties.
void expect_safe_fairing(Surface_mesh& mesh, const std::vector<Face>& region, const Lights& lights,
                         int iterations)
{
  const Surface_mesh before = mesh;
  try {
    CGAL::fair_with_highlight_lines(mesh, region, lights,
                                    CGAL::parameters::number_of_iterations(iterations));
  } catch (const std::exception& e) {
    ASSERT_TRUE(dynamic_cast<const HL::Invalid_input*>(&e) ||
                dynamic_cast<const HL::Fairing_failure*>(&e))
        << e.what();
    for (Vertex v : mesh.vertices())
      EXPECT_EQ(0, std::memcmp(&mesh.point(v), &before.point(v), sizeof(Point))) << e.what();
    return;
  }
  std::vector<Vertex> movable;
  HL::movable_vertices(mesh, region, std::back_inserter(movable));
  const std::set<Vertex> may_move(movable.begin(), movable.end());
  for (Vertex v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    EXPECT_TRUE(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()));
    if (!may_move.count(v)) {
      EXPECT_EQ(p, before.point(v)) << "vertex " << v << " moved but is not movable";
    }
  }
  for (Face f : flipped_faces(before, mesh))
    ADD_FAILURE() << "face " << f << " flipped";
}

// An octahedron with a stretched vertex, faired whole for two iterations: each step kept every
// triangle's orientation relative to the previous step, but face 4 turned by more than 90
// degrees over both.
TEST(FuzzRegression, NoTriangleFlipsOverSeveralIterations)
{
  Surface_mesh mesh = read_off("OFF\n6 8 0\n"
                               "1 0 0\n-1 0.5 0\n0 10 0\n0 -1 2\n0 0 1\n0 0 -1\n"
                               "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n"
                               "3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n");
  const std::vector<Face> all(mesh.faces().begin(), mesh.faces().end());
  expect_safe_fairing(mesh, all, diagonal_lights(mesh, 4), 2);
}

} // namespace

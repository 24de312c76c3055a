// fair_with_highlight_lines() on a CGAL::Surface_mesh: a smooth dent is pressed into the mesh
// (default: the bundled Beetle), the faces around it are faired, and the results are written.
//   fair_dented_region [mesh.off] [faired.off] [dented.off]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/fair_with_highlight_lines.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace HL = CGAL::Highlight_lines;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv)
{
  const std::string input =
      argc > 1 ? argv[1] : std::string(HIGHLIGHT_LINES_DATA_DIR) + "/beetle.off";
  const std::string output = argc > 2 ? argv[2] : "fair_dented_region.off";
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(input, mesh) || is_empty(mesh)) {
    std::cerr << "cannot read " << input << "\n";
    return 1;
  }

  // The region: the faces within 7 % of the box's diagonal of the top vertex beside the middle.
  const CGAL::Bbox_3 box = PMP::bbox(mesh);
  const double diagonal =
      std::sqrt(CGAL::squared_distance(K::Point_3(box.xmin(), box.ymin(), box.zmin()),
                                       K::Point_3(box.xmax(), box.ymax(), box.zmax())));
  const double radius = 0.07 * diagonal;
  Mesh::Vertex_index top;
  for (Mesh::Vertex_index v : vertices(mesh))
    if (mesh.point(v).x() > box.xmin() + 0.55 * (box.xmax() - box.xmin()) &&
        (top == Mesh::null_vertex() || mesh.point(v).y() > mesh.point(top).y()))
      top = v;
  const K::Point_3 centre = mesh.point(top);
  auto inside = [&](Mesh::Vertex_index v) {
    return CGAL::squared_distance(mesh.point(v), centre) < radius * radius;
  };
  std::vector<Mesh::Face_index> region;
  for (Mesh::Face_index f : faces(mesh)) {
    const auto corners = vertices_around_face(halfedge(f, mesh), mesh);
    if (std::all_of(corners.begin(), corners.end(), inside))
      region.push_back(f);
  }

  // The defect: a smooth dent of depth 0.6 % of the diagonal, pressed along the normals.
  std::vector<std::pair<Mesh::Vertex_index, K::Point_3>> dented;
  for (Mesh::Vertex_index v : vertices(mesh)) {
    const double t = CGAL::squared_distance(mesh.point(v), centre) / CGAL::square(0.6 * radius);
    if (t < 1)
      dented.emplace_back(v, mesh.point(v) - 0.006 * diagonal * CGAL::square(1 - t) * (1 - t) *
                                                 PMP::compute_vertex_normal(v, mesh));
  }
  for (const auto& [v, p] : dented)
    mesh.point(v) = p;
  const auto precision = CGAL::parameters::stream_precision(17);
  if (argc > 3 && !CGAL::IO::write_polygon_mesh(argv[3], mesh, precision))
    return 1;

  // Bad input throws (the mesh unchanged); a stall returns the best result, with a status.
  try {
    const HL::Fairing_report report =
        CGAL::fair_with_highlight_lines(mesh, region, HL::default_light_setup(mesh));
    std::cout << report.number_of_movable_vertices << " movable vertices, " << report.iterations
              << " iterations: " << HL::to_string(report.status) << "\n";
  } catch (const HL::Invalid_input& error) { // e.g. no face within the radius on a coarse mesh
    std::cerr << error.what() << "\n";
    return 1;
  }
  return CGAL::IO::write_polygon_mesh(output, mesh, precision) ? 0 : 1;
}

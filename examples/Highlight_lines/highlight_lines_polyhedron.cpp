// compute_highlight_lines() on a CGAL::Polyhedron_3, with named parameters: the highlight
// lines of a face range only, for a few lights, written as CGAL polylines.
//
//   highlight_lines_polyhedron [mesh.off] [output.polylines.txt]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/compute_highlight_lines.h>

#include <fstream>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef boost::graph_traits<Polyhedron>::face_descriptor face_descriptor;
namespace HL = CGAL::Highlight_lines;

int main(int argc, char** argv)
{
  const std::string input =
      argc > 1 ? argv[1] : std::string(HIGHLIGHT_LINES_DATA_DIR) + "/beetle.off";
  const std::string output = argc > 2 ? argv[2] : "highlight_lines_polyhedron.polylines.txt";
  Polyhedron mesh;
  if (!CGAL::IO::read_polygon_mesh(input, mesh)) {
    std::cerr << "cannot read " << input << "\n";
    return 1;
  }

  // Lights placed above the mesh automatically.
  const HL::Light_setup<K> lights = HL::default_light_setup(mesh);

  // The front half of the mesh along the lights' direction: a face range.
  const K::Vector_3 along = lights.light_direction();
  std::vector<face_descriptor> front;
  for (face_descriptor f : faces(mesh))
    if ((f->halfedge()->vertex()->point() - CGAL::ORIGIN) * along > 0)
      front.push_back(f);

  // Our parameters and CGAL's in one pack.
  const auto np = HL::parameters::combine(
      CGAL::parameters::vertex_point_map(get(CGAL::vertex_point, mesh)),
      HL::parameters::face_range(front), HL::parameters::level_range(std::make_pair(-10, 10)),
      HL::parameters::facing_side_only(true));
  std::vector<std::vector<K::Point_3>> polylines;
  const auto model = CGAL::compute_highlight_lines(mesh, lights, std::back_inserter(polylines), np);

  std::size_t closed = 0;
  for (const auto& line : model.lines())
    closed += line.is_closed;
  std::cout << front.size() << " faces: " << model.lines().size() << " highlight lines (" << closed
            << " closed) through " << model.nodes().size() << " nodes\n";

  std::ofstream out(output);
  out.precision(17);
  for (const auto& polyline : polylines) {
    out << polyline.size();
    for (const auto& p : polyline)
      out << ' ' << p;
    out << '\n';
  }
  return model.lines().empty() || !out ? 1 : 0;
}

// compute_highlight_lines() on a CAD part with sharp edges: the creases found by
// PMP::detect_sharp_edges() and passed as crease_edge_map, so that the model is computed on the
// mesh cut along them (one normal per sector of faces at a crease vertex). The lights of
// README's picture pair; the lines of both models are written as CGAL polylines, and the
// program counts the lines that bend. On the bundled extruded part lit along the extrusion, a
// real reflection is a row of straight lines: with the paper's normals (eq. 3 averages the face
// normals across the creases) the lines bend and break up in a band along each crease; cut
// along the creases, they run straight from end to end.
//
//   highlight_lines_on_cad_part [mesh.off] [crease angle in degrees] [output prefix]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/compute_highlight_lines.h>

#include <CGAL/squared_distance_3.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::edge_descriptor edge_descriptor;
namespace HL = CGAL::Highlight_lines;
namespace PMP = CGAL::Polygon_mesh_processing;

typedef std::vector<std::vector<K::Point_3>> Polylines;

// The lines whose points stray from the chord between their ends by more than `fraction` of its
// length: on an extruded part lit along the extrusion, the reflections run straight.
std::size_t bent_lines(const Polylines& polylines, double fraction)
{
  std::size_t bent = 0;
  for (const auto& polyline : polylines) {
    if (polyline.empty())
      continue;
    const K::Segment_3 chord(polyline.front(), polyline.back());
    const double length2 = chord.squared_length();
    bool straight = length2 > 0;
    for (const K::Point_3& p : polyline)
      straight = straight && CGAL::squared_distance(p, chord) <= fraction * fraction * length2;
    bent += !straight;
  }
  return bent;
}

bool write_polylines(const Polylines& polylines, const std::string& file)
{
  std::ofstream out(file);
  out.precision(17);
  for (const auto& polyline : polylines) {
    out << polyline.size();
    for (const auto& p : polyline)
      out << ' ' << p;
    out << '\n';
  }
  return bool(out);
}

int main(int argc, char** argv)
{
  const std::string input =
      argc > 1 ? argv[1] : std::string(HIGHLIGHT_LINES_DATA_DIR) + "/slot_block.off";
  const double crease_angle = argc > 2 ? std::atof(argv[2]) : 45.0;
  const std::string prefix = argc > 3 ? argv[3] : "highlight_lines_on_cad_part";
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(input, mesh) || is_empty(mesh)) {
    std::cerr << "cannot read " << input << "\n";
    return 1;
  }
  if (!(crease_angle > 0 && crease_angle <= 90)) {
    std::cerr << "the crease angle must lie in (0, 90] degrees\n";
    return 1;
  }

  // The creases: edges whose two faces' normals differ by more than the angle (and borders).
  auto creases = mesh.add_property_map<edge_descriptor, bool>("e:crease", false).first;
  PMP::detect_sharp_edges(mesh, crease_angle, creases);
  std::size_t crease_edges = 0;
  for (edge_descriptor e : edges(mesh))
    crease_edges += get(creases, e);

  // README's lights: the plane above the part, lights along x every 0.3.
  const HL::Light_setup<K> lights(K::Point_3(1.5, 0.6, 3.99296), K::Vector_3(1, 0, 0),
                                  K::Vector_3(0, 0, 1), 0.3);

  Polylines papers_polylines, cut_polylines;
  const auto papers =
      CGAL::compute_highlight_lines(mesh, lights, std::back_inserter(papers_polylines));
  const auto cut = CGAL::compute_highlight_lines(mesh, lights, std::back_inserter(cut_polylines),
                                                 HL::parameters::crease_edge_map(creases));

  std::cout << crease_edges << " crease edges (normals more than " << crease_angle
            << " degrees apart)\n"
            << "the paper's normals: " << papers.lines().size() << " lines, "
            << bent_lines(papers_polylines, 0.01) << " bend by more than 1 % of their length\n"
            << "cut along the creases: " << cut.lines().size() << " lines, "
            << bent_lines(cut_polylines, 0.01) << " bend by more than 1 % of their length\n";

  if (!write_polylines(papers_polylines, prefix + ".paper.polylines.txt") ||
      !write_polylines(cut_polylines, prefix + ".creases.polylines.txt")) {
    std::cerr << "cannot write " << prefix << ".*.polylines.txt\n";
    return 1;
  }
  std::cout << "wrote " << prefix << ".paper.polylines.txt and " << prefix
            << ".creases.polylines.txt\n";
  return cut.lines().empty() ? 1 : 0;
}

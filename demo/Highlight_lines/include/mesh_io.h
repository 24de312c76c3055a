// Mesh and region files for the command-line programs: every mesh format CGAL reads, written
// back in the format it came in, and regions as face-id lists or CGAL Lab selection files.
#ifndef HIGHLIGHT_LINES_DEMO_MESH_IO_H
#define HIGHLIGHT_LINES_DEMO_MESH_IO_H

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Highlight_lines/Highlight_line_sweeper.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/PLY.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace mesh_io {

// The extension of `path`, lower case, with its dot (".off"), or "" if it has none.
inline std::string extension(const std::string& path)
{
  const std::size_t slash = path.find_last_of("/\\");
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return "";
  std::string e = path.substr(dot);
  std::transform(e.begin(), e.end(), e.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return e;
}

// Whether CGAL writes meshes in the format of this extension (".off", ".obj", ".ply", ".stl").
inline bool writable_extension(const std::string& e)
{
  return e == ".off" || e == ".obj" || e == ".ply" || e == ".stl";
}

// The extension of a format asked for on a command line ("ply", ".PLY", ...), with its dot, or
// "" if CGAL does not write that format.
inline std::string format_extension(std::string format)
{
  std::transform(format.begin(), format.end(), format.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (!format.empty() && format[0] != '.')
    format = "." + format;
  return writable_extension(format) ? format : "";
}

// The format to write a mesh read from `input` in: `asked` (an extension with its dot) if not
// empty, otherwise the input's own if CGAL writes it, otherwise OFF.
inline std::string output_extension(const std::string& input, const std::string& asked = "")
{
  if (!asked.empty())
    return asked;
  const std::string e = extension(input);
  return writable_extension(e) ? e : ".off";
}

// A Surface_mesh compacts its indices after faces were removed (the programs write face ids);
// other meshes have nothing to collect.
template <typename Point>
void compact_indices(CGAL::Surface_mesh<Point>& mesh)
{
  mesh.collect_garbage();
}
template <typename Mesh>
void compact_indices(Mesh&)
{
}

// Reads a triangle mesh from any format CGAL reads (OFF, OBJ, PLY, STL, by the extension).
// A file that is not a valid polygon mesh as it stands (a soup: triangles of an STL export
// that are not consistently oriented, duplicated or degenerate faces, non-manifold edges) is
// repaired and oriented; faces with more than three corners (quads of a CAD export) are
// triangulated; triangles whose corners are collinear (scans and CAD exports hold a few; the
// highlight line model has no normal for them and refuses them) are removed. Each of these is
// said in a note on `notes`. Returns false if no face could be read.
template <typename Mesh>
bool read_triangle_mesh(const std::string& path, Mesh& mesh, std::ostream& notes = std::cout)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  typedef typename boost::property_traits<
      typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if (!CGAL::IO::read_polygon_soup(path, points, polygons) || polygons.empty())
    return false;
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    const std::size_t read_points = points.size(), read_polygons = polygons.size();
    PMP::repair_polygon_soup(points, polygons);
    PMP::orient_polygon_soup(points, polygons);
    notes << "note: " << path << " is a polygon soup (" << read_points << " points, "
          << read_polygons << " faces), repaired and oriented into a mesh of " << points.size()
          << " vertices and " << polygons.size() << " faces; face ids refer to this mesh\n";
  }
  mesh.clear();
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if (is_empty(mesh))
    return false;
  std::size_t polygonal = 0;
  for (auto f : faces(mesh))
    polygonal += degree(f, mesh) > 3 ? 1 : 0;
  if (polygonal > 0) {
    const std::size_t before = num_faces(mesh);
    if (!PMP::triangulate_faces(mesh))
      return false;
    notes << "note: " << polygonal << " of the " << before << " faces of " << path
          << " have more than three corners: triangulated (" << num_faces(mesh)
          << " triangles; the first triangle of a face keeps its id, the others are added)\n";
  }
  std::size_t degenerate = 0;
  for (auto f : faces(mesh))
    degenerate += PMP::is_degenerate_triangle_face(f, mesh) ? 1 : 0;
  if (degenerate > 0) {
    const bool removed = PMP::remove_degenerate_faces(mesh);
    compact_indices(mesh);
    if (is_empty(mesh))
      return false;
    notes << "note: degenerate faces (collinear corners) in " << path << ": " << degenerate << ", "
          << (removed ? "removed" : "not all could be removed")
          << " with Polygon_mesh_processing::remove_degenerate_faces(), leaving "
          << num_vertices(mesh) << " vertices and " << num_faces(mesh)
          << " faces; face ids refer to this mesh\n";
  }
  return true;
}

// Reads a program's input mesh (read_triangle_mesh()) and says what it holds; false, after a
// message naming `program`, if it cannot.
template <typename Mesh>
bool read_input_mesh(const std::string& path, Mesh& mesh, const std::string& program)
{
  if (!read_triangle_mesh(path, mesh)) {
    std::cerr << program << ": cannot read a polygon mesh from " << path << "\n";
    return false;
  }
  std::cout << "mesh " << path << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh)
            << " faces\n";
  return true;
}

// Writes `mesh` to `path` (the format by the extension), with all the digits of a double.
template <typename Mesh>
bool write_mesh(const std::string& path, const Mesh& mesh)
{
  return CGAL::IO::write_polygon_mesh(path, mesh, CGAL::parameters::stream_precision(17));
}

// The names of the vertex properties write_ply_with_highlight_distances() adds.
inline const char* highlight_distance_property()
{
  return "v:highlight_distance";
}
inline const char* highlight_level_property()
{
  return "v:highlight_level";
}

// Writes a Surface_mesh as a binary PLY file with two scalar vertex properties: the highlight
// distance value d of each vertex (`highlight_distance`, as the library computes it, see
// Highlight_line_sweeper::highlight_distances()) and d/s (`highlight_level`), NaN where d is
// undefined or, with `facing_side_only`, where the normal points away from the lights. The
// highlight line of light m is the contour of highlight_distance at m·s, or of highlight_level
// at m: any viewer's contour filter (ParaView, MeshLab) draws the lines.
template <typename Point, typename Lights>
bool write_ply_with_highlight_distances(const std::string& path,
                                        const CGAL::Surface_mesh<Point>& mesh, const Lights& lights,
                                        bool facing_side_only)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  Mesh copy = mesh; // the properties are written with the mesh; the caller's mesh stays as it is
  auto distance = copy.template add_property_map<typename Mesh::Vertex_index, double>(
                          highlight_distance_property(), 0.0)
                      .first;
  auto level = copy.template add_property_map<typename Mesh::Vertex_index, double>(
                       highlight_level_property(), 0.0)
                   .first;
  const CGAL::Highlight_lines::Highlight_line_sweeper<Mesh> sweeper(copy);
  sweeper.highlight_distances(
      lights, distance, CGAL::Highlight_lines::parameters::facing_side_only(facing_side_only));
  const double s = CGAL::to_double(lights.spacing());
  for (auto v : vertices(copy))
    level[v] = distance[v] / s;
  std::ostringstream comment;
  comment.precision(17);
  comment << "highlight_distance: d of eq. 1; the highlight line of light m is its contour at "
             "m*s, s = "
          << s << "\nhighlight_level: d/s; the highlight line of light m is its contour at m";
  std::ofstream out(path, std::ios::binary);
  CGAL::IO::set_mode(out, CGAL::IO::BINARY);
  return CGAL::IO::write_PLY(out, copy, comment.str()) && bool(out);
}

// Face ids of a region file: either CGAL Lab's selection file (`*.selection.txt`: a line of
// selected vertex ids, a line of selected face ids, a line of selected edges) whose face line
// is used, or a plain list of face ids separated by white space. Ids are checked against
// `number_of_faces`; on any error `error` says what and the result is empty.
inline std::vector<std::size_t> read_region(const std::string& path, std::size_t number_of_faces,
                                            std::string& error)
{
  std::ifstream in(path);
  if (!in) {
    error = "cannot open " + path;
    return {};
  }
  const bool selection = path.size() >= 14 && extension(path) == ".txt" &&
                         path.compare(path.size() - 14, 14, ".selection.txt") == 0;
  std::string text;
  if (selection) {
    std::string vertex_line;
    if (!std::getline(in, vertex_line) || !std::getline(in, text)) {
      error = path + " is not a CGAL Lab selection file (no line of face ids)";
      return {};
    }
  } else {
    std::ostringstream all;
    all << in.rdbuf();
    text = all.str();
  }
  std::istringstream ids(text);
  std::vector<std::size_t> region;
  long long id;
  while (ids >> id) {
    if (id < 0 || id >= (long long)number_of_faces) {
      error = "face id " + std::to_string(id) + " in " + path + " is not a face of the mesh";
      return {};
    }
    region.push_back(std::size_t(id));
  }
  if (!ids.eof()) {
    error = "cannot read face ids from " + path;
    return {};
  }
  if (region.empty())
    error = path + " selects no face";
  return region;
}

// Writes a region as a CGAL Lab selection file: no vertices, the face ids, no edges.
inline bool write_selection(const std::string& path, const std::vector<std::size_t>& faces)
{
  std::ofstream out(path);
  out << "\n";
  for (std::size_t i = 0; i < faces.size(); ++i)
    out << (i ? " " : "") << faces[i];
  out << "\n\n";
  return bool(out);
}

} // namespace mesh_io

#endif

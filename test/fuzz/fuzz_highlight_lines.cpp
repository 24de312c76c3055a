// libFuzzer target: arbitrary bytes -> OFF reading (CGAL IO) -> compute_highlight_lines ->
// fair_with_highlight_lines on a small region.
//
// Input: an ASCII OFF file. An optional first line "# hl <light> <rings> <vertex> <iterations>
// <soup>" chooses the parameters (missing numbers are 0):
//   light       0: default_light_setup(); otherwise a fixed setup above the bounding box, plane
//               normal chosen by light % 4 (x, y, z, (1,1,1)), spacing diagonal / (1 + light % 64)
//   rings       the region is the faces within 1 + rings % 3 rings of a vertex
//   vertex      that vertex is vertex % number_of_vertices
//   iterations  1 + iterations % 3 fairing iterations
//   soup        odd: read a polygon soup, repair and orient it (non-manifold vertices are
//               duplicated, as CGAL's repair does) before building the mesh
//
// Expected rejections (Invalid_input, Fairing_failure, a reader failure) are fine. Bugs, which
// abort: any other exception from the package, a sanitizer report, a non-finite node or point,
// a mesh changed by a call that threw, a vertex moved that is not movable, a flipped triangle.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/OFF.h>

#include "flipped_faces.h"

#include <CGAL/Highlight_lines/Fairing_report.h>
#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/Highlight_lines/fairing_building_blocks.h>
#include <CGAL/compute_highlight_lines.h>
#include <CGAL/fair_with_highlight_lines.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Face_index Face;
typedef Mesh::Vertex_index Vertex;
namespace HL = CGAL::Highlight_lines;
namespace PMP = CGAL::Polygon_mesh_processing;

// Outcome counts, printed at exit when HL_FUZZ_STATS is set: how deep the inputs get.
struct Statistics
{
  std::map<std::string, std::size_t> counts;
  ~Statistics()
  {
    if (std::getenv("HL_FUZZ_STATS"))
      for (const auto& entry : counts)
        std::fprintf(stderr, "%-28s %zu\n", entry.first.c_str(), entry.second);
  }
} statistics;

void count(const char* outcome)
{
  ++statistics.counts[outcome];
}

[[noreturn]] void bug(const char* what)
{
  std::fprintf(stderr, "fuzz_highlight_lines: BUG: %s\n", what);
  std::abort();
}

bool finite(const Point& p)
{
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
}

// Bit-exact copy of the points (NaN-safe comparison).
std::vector<double> coordinates(const Mesh& mesh)
{
  std::vector<double> c;
  for (Vertex v : mesh.vertices())
    for (int k = 0; k < 3; ++k)
      c.push_back(mesh.point(v)[k]);
  return c;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

std::vector<std::string> tokens_of(const std::string& line)
{
  std::istringstream in(line);
  std::vector<std::string> tokens;
  for (std::string t; in >> t;)
    tokens.push_back(t);
  return tokens;
}

bool parse_integer(const std::string& t, long long lo, long long hi, long long& value)
{
  if (t.empty() || t.size() > 12 || t.find_first_not_of("0123456789") != std::string::npos)
    return false;
  value = std::stoll(t);
  return value >= lo && value <= hi;
}

bool parse_double(const std::string& t)
{
  char* end = nullptr;
  std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size();
}

// The gate in front of CGAL 5.5's OFF reader, which sizes its arrays from the header and face
// counts without checking them (a count of 10^12 allocates terabytes) and casts negative face
// sizes from double to size_t (undefined behaviour): only a strict, simple OFF layout with
// bounded counts passes. Those are reader problems, not this package's.
bool is_simple_off(const std::string& text)
{
  std::istringstream in(text);
  std::vector<std::vector<std::string>> lines;
  for (std::string line; std::getline(in, line);) {
    const auto tokens = tokens_of(line);
    if (tokens.empty())
      continue;
    if (tokens[0][0] == '#') {
      if (!lines.empty())
        return false; // comments only before the header
      continue;
    }
    if (line.find('#') != std::string::npos)
      return false;
    lines.push_back(tokens);
  }
  if (lines.empty() || lines[0][0] != "OFF")
    return false;
  std::vector<std::string> header(lines[0].begin() + 1, lines[0].end());
  std::size_t next = 1;
  if (header.empty() && lines.size() > 1)
    header = lines[next++];
  long long nv = 0, nf = 0, ne = 0;
  if (header.size() != 3 || !parse_integer(header[0], 0, 1000, nv) ||
      !parse_integer(header[1], 0, 2000, nf) || !parse_integer(header[2], 0, 1000000, ne))
    return false;
  if (lines.size() != next + std::size_t(nv + nf))
    return false;
  for (long long v = 0; v < nv; ++v) {
    const auto& t = lines[next++];
    if (t.size() != 3 || !parse_double(t[0]) || !parse_double(t[1]) || !parse_double(t[2]))
      return false;
  }
  for (long long f = 0; f < nf; ++f) {
    const auto& t = lines[next++];
    long long size = 0, index = 0;
    if (!parse_integer(t[0], 0, 64, size) || t.size() != std::size_t(size) + 1)
      return false;
    for (std::size_t j = 1; j < t.size(); ++j)
      if (!parse_integer(t[j], 0, 1000000, index))
        return false;
  }
  return true;
}

struct Parameters
{
  long long light = 0, rings = 0, vertex = 0, iterations = 0, soup = 0;
};

Parameters parameters_of(const std::string& text)
{
  Parameters p;
  if (text.compare(0, 4, "# hl") == 0) {
    std::istringstream in(text.substr(4, text.find('\n') - 4));
    long long* fields[] = {&p.light, &p.rings, &p.vertex, &p.iterations, &p.soup};
    for (long long* field : fields) {
      std::string t;
      if (!(in >> t) || !parse_integer(t, 0, 1000000000, *field))
        break;
    }
  }
  return p;
}

bool read_mesh(const std::string& text, bool as_soup, Mesh& mesh)
{
  std::istringstream in(text);
  if (!as_soup)
    return CGAL::IO::read_OFF(in, mesh) && !is_empty(mesh);
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if (!CGAL::IO::read_OFF(in, points, polygons))
    return false;
  PMP::repair_polygon_soup(points, polygons);
  PMP::orient_polygon_soup(points, polygons);
  if (polygons.empty() || !PMP::is_polygon_soup_a_polygon_mesh(polygons))
    return false;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return !is_empty(mesh);
}

HL::Light_setup<K> lights_for(const Mesh& mesh, long long choice)
{
  if (choice == 0)
    return HL::default_light_setup(mesh);
  const CGAL::Bbox_3 box = CGAL::bbox_3(mesh.points().begin(), mesh.points().end());
  const double diagonal =
      std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                CGAL::square(box.zmax() - box.zmin()));
  const Point centre((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2,
                     (box.zmin() + box.zmax()) / 2);
  const Vector normals[4] = {Vector(1, 0, 0), Vector(0, 1, 0), Vector(0, 0, 1), Vector(1, 1, 1)};
  const Vector directions[4] = {Vector(0, 0, 1), Vector(0, 0, 1), Vector(1, 0, 0),
                                Vector(1, -1, 0)};
  const Vector& z = normals[choice % 4];
  // Invalid (e.g. a zero or infinite spacing): Invalid_input from the constructor.
  return HL::Light_setup<K>(centre + z * diagonal, directions[choice % 4], z,
                            diagonal / double(1 + choice % 64));
}

// The faces within `rings` rings of faces around v.
std::vector<Face> region_around(const Mesh& mesh, Vertex v, int rings)
{
  std::set<Face> region;
  std::set<Vertex> front{v}, seen{v};
  for (int ring = 0; ring < rings; ++ring) {
    std::set<Vertex> next;
    for (Vertex w : front)
      for (Face f : CGAL::faces_around_target(mesh.halfedge(w), mesh))
        if (f != Mesh::null_face() && region.insert(f).second)
          for (Vertex u : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
            if (seen.insert(u).second)
              next.insert(u);
    front.swap(next);
  }
  return std::vector<Face>(region.begin(), region.end());
}

// What any model must hold: finite nodes and polyline points, lines made of existing nodes.
// `what` names the call in the bug report.
template <typename Model>
void check_model_output(const Model& model, const std::vector<std::vector<Point>>& polylines,
                        const std::string& what)
{
  for (const auto& node : model.nodes())
    if (!finite(node.point))
      bug(("non-finite highlight node (" + what + ")").c_str());
  for (const auto& line : model.lines())
    for (std::size_t id : line.nodes)
      if (id >= model.nodes().size())
        bug(("line refers to a node that does not exist (" + what + ")").c_str());
  for (const auto& polyline : polylines)
    for (const Point& p : polyline)
      if (!finite(p))
        bug(("non-finite polyline point (" + what + ")").c_str());
}

// Returns whether the model was computed (the mesh passed its checks).
bool check_model(const Mesh& mesh, const HL::Light_setup<K>& lights)
{
  bool computed = false;
  const std::vector<double> before = coordinates(mesh);
  std::vector<std::vector<Point>> polylines;
  try {
    const auto model = CGAL::compute_highlight_lines(mesh, lights, std::back_inserter(polylines));
    check_model_output(model, polylines, "compute_highlight_lines");
    count(model.lines().empty() ? "model: no line" : "model: lines");
    computed = true;
  } catch (const HL::Invalid_input&) {
    count("model: Invalid_input");
  }
  if (!same_bits(before, coordinates(mesh)))
    bug("compute_highlight_lines changed the mesh");
  return computed;
}

// The model cut along the creases sharper than `angle` degrees: the same guarantees.
void check_model_with_creases(const Mesh& mesh, const HL::Light_setup<K>& lights, double angle)
{
  const std::vector<double> before = coordinates(mesh);
  std::map<Mesh::Edge_index, bool> sharp;
  boost::associative_property_map<std::map<Mesh::Edge_index, bool>> creases(sharp);
  for (auto e : edges(mesh))
    put(creases, e, false);
  try {
    CGAL::Polygon_mesh_processing::detect_sharp_edges(mesh, angle, creases);
    std::vector<std::vector<Point>> polylines;
    const auto model = CGAL::compute_highlight_lines(mesh, lights, std::back_inserter(polylines),
                                                     HL::parameters::crease_edge_map(creases));
    check_model_output(model, polylines, "compute_highlight_lines with creases");
    count(model.lines().empty() ? "creases: no line" : "creases: lines");
  } catch (const HL::Invalid_input&) {
    count("creases: Invalid_input");
  }
  if (!same_bits(before, coordinates(mesh)))
    bug("compute_highlight_lines with creases changed the mesh");
}

void check_fairing(Mesh& mesh, const HL::Light_setup<K>& lights, const Parameters& p)
{
  const Vertex centre(std::uint32_t(p.vertex % (long long)mesh.number_of_vertices()));
  if (mesh.is_isolated(centre))
    return;
  const std::vector<Face> region = region_around(mesh, centre, 1 + int(p.rings % 3));
  const std::vector<double> before = coordinates(mesh);
  const Mesh input = mesh;
  try {
    CGAL::fair_with_highlight_lines(mesh, region, lights,
                                    CGAL::parameters::number_of_iterations(1 + p.iterations % 3));
  } catch (const HL::Invalid_input&) {
    count("fairing: Invalid_input");
    if (!same_bits(before, coordinates(mesh)))
      bug("Invalid_input thrown, but the mesh changed");
    return;
  } catch (const HL::Fairing_failure&) {
    count("fairing: Fairing_failure");
    if (!same_bits(before, coordinates(mesh)))
      bug("Fairing_failure thrown, but the mesh was not restored");
    return;
  }
  count(same_bits(before, coordinates(mesh)) ? "fairing: nothing moved" : "fairing: moved");
  // The movable vertices of the input, which passed the checks: the faired mesh can leave the
  // range of sizes the fairing accepts (a vertex 1e60 away makes the region's mean edge, and
  // with it the steps, that large), and movable_vertices() would then refuse it.
  std::vector<Vertex> movable;
  HL::movable_vertices(input, region, std::back_inserter(movable));
  const std::set<Vertex> may_move(movable.begin(), movable.end());
  const std::vector<double> after = coordinates(mesh);
  for (Vertex v : mesh.vertices()) {
    if (!finite(mesh.point(v)))
      bug("non-finite point written into the mesh");
    if (!may_move.count(v) &&
        std::memcmp(&before[3 * std::size_t(v)], &after[3 * std::size_t(v)], 3 * sizeof(double)))
      bug("a vertex that is not movable moved");
  }
  if (!test::flipped_faces(input, mesh).empty())
    bug("a triangle flipped");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  if (!is_simple_off(text)) {
    count("input: not simple OFF");
    return 0;
  }
  const Parameters p = parameters_of(text);
  Mesh mesh;
  try {
    if (!read_mesh(text, p.soup % 2 == 1, mesh)) {
      count("input: reader failed");
      return 0;
    }
  } catch (const std::exception&) { // CGAL's reader and repair functions, not ours
    count("input: reader threw");
    return 0;
  }

  std::optional<HL::Light_setup<K>> lights;
  try {
    lights.emplace(lights_for(mesh, p.light));
  } catch (const HL::Invalid_input&) {
    count("lights: Invalid_input");
    return 0;
  }
  // The creases only on meshes the model accepts: detect_sharp_edges() needs face normals.
  if (check_model(mesh, *lights))
    check_model_with_creases(mesh, *lights, 10.0 + double(std::llabs(p.light / 4) % 16) * 10.0);
  check_fairing(mesh, *lights, p);
  return 0;
}

// Checks what a scripted session of highlight_lines_viewer wrote (test/viewer_session.script)
// against the library called directly, without any of the viewer's code:
//   - the screenshots are PNG files that are not blank, and the two taken before and after a
//     sweep of the lights differ;
//   - the lines saved before and after the sweep are compute_highlight_lines() for the lights
//     saved with them, and differ; those saved with the model cut along the creases are
//     compute_highlight_lines() with crease_edge_map (PMP::detect_sharp_edges() at 30 degrees),
//     and differ from the paper's, also after the fairing is undone with the creases shown;
//   - the region is the face CGAL's AABB tree finds first along the viewer's picking ray, grown
//     across edges to the faces whose corners lie within the radius of the hit point;
//   - the faired mesh is fair_with_highlight_lines() of that region with the saved lights and
//     iteration bound; the before / after comparison shows both, undo gives back the mesh as
//     read, redo the faired one.
//
//   highlight_lines_viewer_check MESH DIR ITERATIONS RADIUS OX OY OZ DX DY DZ
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/compute_highlight_lines.h>
#include <CGAL/fair_with_highlight_lines.h>

#include "mesh_io.h"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Face_index Face;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;

namespace {

int failures = 0;

void expect(bool ok, const std::string& what)
{
  std::cout << (ok ? "ok:     " : "FAILED: ") << what << "\n";
  failures += ok ? 0 : 1;
}

// ---- PNG (8-bit RGB, as highlight_picture::write_png writes it) ------------------------------

struct Picture
{
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};

std::uint32_t big_endian(const std::uint8_t* p)
{
  return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

bool read_png(const std::string& path, Picture& picture)
{
  std::ifstream in(path, std::ios::binary);
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                        std::istreambuf_iterator<char>());
  const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (bytes.size() < 8 || !std::equal(signature, signature + 8, bytes.begin()))
    return false;
  std::vector<std::uint8_t> compressed;
  for (std::size_t at = 8; at + 12 <= bytes.size();) {
    const std::size_t length = big_endian(&bytes[at]);
    const std::string type(bytes.begin() + long(at) + 4, bytes.begin() + long(at) + 8);
    const std::uint8_t* data = &bytes[at + 8];
    if (at + 12 + length > bytes.size())
      return false;
    if (type == "IHDR") {
      picture.width = int(big_endian(data));
      picture.height = int(big_endian(data + 4));
      if (data[8] != 8 || data[9] != 2 || data[12] != 0)
        return false; // only 8-bit RGB, not interlaced
    } else if (type == "IDAT") {
      compressed.insert(compressed.end(), data, data + length);
    }
    at += 12 + length;
  }
  const std::size_t stride = std::size_t(picture.width) * 3;
  std::vector<std::uint8_t> raw((stride + 1) * std::size_t(picture.height));
  uLongf raw_size = uLongf(raw.size());
  if (picture.width <= 0 ||
      uncompress(raw.data(), &raw_size, compressed.data(), uLong(compressed.size())) != Z_OK ||
      raw_size != raw.size())
    return false;
  picture.rgb.assign(stride * std::size_t(picture.height), 0);
  for (std::size_t y = 0; y < std::size_t(picture.height); ++y) {
    const std::uint8_t filter = raw[y * (stride + 1)];
    const std::uint8_t* line = &raw[y * (stride + 1) + 1];
    std::uint8_t* out = &picture.rgb[y * stride];
    const std::uint8_t* above = y > 0 ? &picture.rgb[(y - 1) * stride] : nullptr;
    for (std::size_t x = 0; x < stride; ++x) {
      const int a = x >= 3 ? out[x - 3] : 0, b = above ? above[x] : 0,
                c = above && x >= 3 ? above[x - 3] : 0;
      int predictor = 0;
      switch (filter) {
      case 0:
        break;
      case 1:
        predictor = a;
        break;
      case 2:
        predictor = b;
        break;
      case 3:
        predictor = (a + b) / 2;
        break;
      case 4: {
        const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
        predictor = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
        break;
      }
      default:
        return false;
      }
      out[x] = std::uint8_t((line[x] + predictor) & 0xFF);
    }
  }
  return true;
}

// Standard deviation of the grey values: a blank (one-colour) picture has none.
double grey_deviation(const Picture& p)
{
  double sum = 0, squares = 0;
  const std::size_t n = p.rgb.size() / 3;
  for (std::size_t i = 0; i < n; ++i) {
    const double grey = (p.rgb[3 * i] + p.rgb[3 * i + 1] + p.rgb[3 * i + 2]) / 3.0;
    sum += grey;
    squares += grey * grey;
  }
  const double mean = sum / double(n);
  return std::sqrt(std::max(squares / double(n) - mean * mean, 0.0));
}

// Over the columns from `first_column` on (the panel lies to their left).
double fraction_of_pixels_changed(const Picture& a, const Picture& b, std::size_t first_column = 0)
{
  std::size_t changed = 0, compared = 0;
  const std::size_t width = std::size_t(a.width), height = std::size_t(a.height);
  for (std::size_t row = 0; row < height; ++row)
    for (std::size_t column = first_column; column < width; ++column) {
      const std::size_t i = 3 * (row * width + column);
      changed +=
          a.rgb[i] != b.rgb[i] || a.rgb[i + 1] != b.rgb[i + 1] || a.rgb[i + 2] != b.rgb[i + 2];
      ++compared;
    }
  return compared > 0 ? double(changed) / double(compared) : 0.;
}

// ---- Files written by the viewer ---------------------------------------------------------------

HL::Light_setup<K> read_lights(const std::string& path,
                               std::pair<long long, long long>* levels = nullptr)
{
  std::ifstream in(path);
  std::string word;
  double base[3] = {0, 0, 0}, direction[3] = {0, 0, 0}, normal[3] = {0, 0, 0}, spacing = 0;
  std::pair<long long, long long> levels_read(0, -1);
  while (in >> word) {
    if (word == "spacing")
      in >> spacing;
    else if (word == "levels")
      in >> levels_read.first >> levels_read.second;
    else {
      double* target = word == "base" ? base : word == "direction" ? direction : normal;
      in >> target[0] >> target[1] >> target[2];
    }
  }
  if (levels)
    *levels = levels_read;
  return HL::Light_setup<K>(K::Point_3(base[0], base[1], base[2]),
                            K::Vector_3(direction[0], direction[1], direction[2]),
                            K::Vector_3(normal[0], normal[1], normal[2]), spacing);
}

std::vector<std::vector<double>> read_polylines(const std::string& path)
{
  std::ifstream in(path);
  std::vector<std::vector<double>> result;
  std::size_t n = 0;
  while (in >> n) {
    result.emplace_back(3 * n);
    for (double& c : result.back())
      in >> c;
  }
  return result;
}

std::vector<std::vector<double>> flat(const std::vector<std::vector<K::Point_3>>& polylines)
{
  std::vector<std::vector<double>> result;
  for (const auto& polyline : polylines) {
    result.emplace_back();
    for (const auto& p : polyline)
      result.back().insert(result.back().end(), {p.x(), p.y(), p.z()});
  }
  return result;
}

std::vector<K::Point_3> positions(const Mesh& mesh)
{
  std::vector<K::Point_3> result;
  for (auto v : vertices(mesh))
    result.push_back(mesh.point(v));
  return result;
}

std::vector<K::Point_3> read_positions(const std::string& path)
{
  Mesh mesh;
  if (!mesh_io::read_triangle_mesh(path, mesh))
    return {};
  return positions(mesh);
}

} // namespace

int main(int argc, char** argv)
{
  if (argc != 11) {
    std::cerr
        << "usage: highlight_lines_viewer_check MESH DIR ITERATIONS RADIUS OX OY OZ DX DY DZ\n";
    return 2;
  }
  const std::string dir = argv[2];
  const unsigned int iterations = unsigned(std::atoi(argv[3]));
  const double radius = std::atof(argv[4]);
  const K::Point_3 ray_origin(std::atof(argv[5]), std::atof(argv[6]), std::atof(argv[7]));
  const K::Vector_3 ray_direction(std::atof(argv[8]), std::atof(argv[9]), std::atof(argv[10]));
  Mesh mesh;
  if (!mesh_io::read_triangle_mesh(argv[1], mesh)) {
    std::cerr << "cannot read " << argv[1] << "\n";
    return 2;
  }

  // Screenshots.
  Picture before_sweep, after_sweep, zebra, shaded, shaded_creases;
  const bool read = read_png(dir + "/sweep_0.png", before_sweep) &&
                    read_png(dir + "/sweep_1.png", after_sweep) &&
                    read_png(dir + "/zebra.png", zebra) && read_png(dir + "/shaded.png", shaded) &&
                    read_png(dir + "/shaded_creases.png", shaded_creases);
  expect(read, "the screenshots are PNG files of 8-bit RGB");
  if (read) {
    expect(before_sweep.width == 800 && before_sweep.height == 600,
           "a screenshot has the window's size, 800 x 600 (got " +
               std::to_string(before_sweep.width) + " x " + std::to_string(before_sweep.height) +
               ")");
    for (const auto& [name, picture] :
         {std::make_pair("sweep_0", &before_sweep), std::make_pair("sweep_1", &after_sweep),
          std::make_pair("zebra", &zebra)})
      expect(grey_deviation(*picture) > 20, std::string(name) +
                                                ".png is not blank (grey deviation " +
                                                std::to_string(grey_deviation(*picture)) + ")");
    const double changed = fraction_of_pixels_changed(before_sweep, after_sweep);
    expect(changed > 0.005, "the lines moved on screen: " + std::to_string(100 * changed) +
                                " % of the pixels changed with the sweep");
    // Without lines, only the shading can tell the two apart: cut along the creases, it turns
    // sharply there (one normal per sector of faces), elsewhere it is the same. Right of the
    // panel (which shows the crease angle).
    const double cut = fraction_of_pixels_changed(shaded, shaded_creases, 400);
    expect(cut > 0.002 && cut < 0.5,
           "the shading is cut along the creases: " + std::to_string(100 * cut) +
               " % of the pixels right of the panel changed");
  }

  // Lines before and after the sweep.
  std::vector<std::vector<double>> saved_lines[2];
  for (int i = 0; i < 2; ++i) {
    const std::string n = std::to_string(i);
    std::pair<long long, long long> levels(0, -1);
    const auto lights = read_lights(dir + "/lights_" + n + ".txt", &levels);
    std::vector<std::vector<K::Point_3>> expected;
    CGAL::compute_highlight_lines(
        mesh, lights, std::back_inserter(expected),
        HLP::combine(HLP::level_range(levels), HLP::facing_side_only(true)));
    saved_lines[i] = read_polylines(dir + "/lines_" + n + ".polylines.txt");
    expect(!expected.empty() && saved_lines[i] == flat(expected),
           "lines_" + n + " are compute_highlight_lines() for lights_" + n + " (" +
               std::to_string(saved_lines[i].size()) + " lines, expected " +
               std::to_string(expected.size()) + ")");
  }
  expect(saved_lines[0] != saved_lines[1], "the lines moved with the lights");

  // Lines cut along the creases sharper than 30 degrees: with the lights after the sweep, and
  // after an undo of the fairing (the mesh as read again, the creases found anew).
  auto creases = mesh.add_property_map<Mesh::Edge_index, bool>("e:check_crease", false).first;
  CGAL::Polygon_mesh_processing::detect_sharp_edges(mesh, 30, creases);
  std::vector<std::vector<double>> saved_cut_lines;
  for (const std::string name : {"creases", "creases_undone"}) {
    std::pair<long long, long long> levels(0, -1);
    const auto lights = read_lights(dir + "/lights_" + name + ".txt", &levels);
    std::vector<std::vector<K::Point_3>> expected;
    CGAL::compute_highlight_lines(
        mesh, lights, std::back_inserter(expected),
        HLP::crease_edge_map(HLP::combine(HLP::level_range(levels), HLP::facing_side_only(true)),
                             creases));
    const auto saved = read_polylines(dir + "/lines_" + name + ".polylines.txt");
    expect(!expected.empty() && saved == flat(expected),
           "lines_" + name + " are compute_highlight_lines() with crease_edge_map at 30 degrees (" +
               std::to_string(saved.size()) + " lines, expected " +
               std::to_string(expected.size()) + ")");
    if (saved_cut_lines.empty())
      saved_cut_lines = saved;
  }
  expect(saved_cut_lines != saved_lines[1], "the cut model's lines differ from the paper's");
  mesh.remove_property_map(creases);

  // The region.
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;
  Tree tree(faces(mesh).first, faces(mesh).second, mesh);
  const auto hit = tree.first_intersection(K::Ray_3(ray_origin, ray_direction));
  const K::Point_3* hit_point = hit ? boost::get<K::Point_3>(&hit->first) : nullptr;
  expect(hit_point != nullptr, "the picking ray hits the mesh");
  std::string error;
  const std::vector<std::size_t> saved_region =
      mesh_io::read_region(dir + "/region.txt", num_faces(mesh), error);
  if (hit_point) {
    std::vector<char> in_region(num_faces(mesh), 0), visited(num_faces(mesh), 0);
    std::vector<Face> stack{hit->second};
    visited[std::size_t(hit->second)] = 1;
    while (!stack.empty()) {
      const Face f = stack.back();
      stack.pop_back();
      bool inside = true;
      for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
        inside = inside && CGAL::squared_distance(mesh.point(v), *hit_point) <= radius * radius;
      if (!inside && f != hit->second)
        continue;
      in_region[std::size_t(f)] = 1;
      if (!inside)
        break; // the picked face alone, below the radius
      for (auto g : CGAL::faces_around_face(halfedge(f, mesh), mesh))
        if (g != Mesh::null_face() && !visited[std::size_t(g)]) {
          visited[std::size_t(g)] = 1;
          stack.push_back(g);
        }
    }
    std::vector<std::size_t> expected;
    for (std::size_t f = 0; f < in_region.size(); ++f)
      if (in_region[f])
        expected.push_back(f);
    expect(error.empty() && saved_region == expected,
           "the region is the face hit (" + std::to_string(std::size_t(hit->second)) +
               ") grown by the radius: " + std::to_string(saved_region.size()) +
               " faces, expected " + std::to_string(expected.size()));
  }

  // Fairing, undo, redo.
  const std::vector<K::Point_3> original = positions(mesh);
  std::vector<Face> region;
  for (std::size_t f : saved_region)
    region.push_back(Face(Mesh::size_type(f)));
  if (!region.empty()) {
    const auto lights = read_lights(dir + "/lights_fair.txt");
    Mesh faired = mesh;
    CGAL::fair_with_highlight_lines(faired, region, lights,
                                    CGAL::parameters::number_of_iterations(iterations));
    const std::vector<K::Point_3> expected = positions(faired);
    expect(expected != original, "the library's fairing moves the region");
    const std::vector<K::Point_3> saved = read_positions(dir + "/faired.off");
    double largest_difference = saved.size() == expected.size() ? 0 : HUGE_VAL;
    for (std::size_t i = 0; i < saved.size() && i < expected.size(); ++i)
      largest_difference =
          std::max(largest_difference, std::sqrt(CGAL::squared_distance(saved[i], expected[i])));
    std::ostringstream difference;
    difference << largest_difference;
    expect(saved == expected,
           "the viewer's faired mesh is fair_with_highlight_lines() of the region (largest "
           "difference " +
               difference.str() + ")");
  }
  expect(read_positions(dir + "/before.off") == original &&
             read_positions(dir + "/after.off") == read_positions(dir + "/faired.off"),
         "the before / after comparison shows the mesh as read and the faired one");
  expect(read_positions(dir + "/undone.off") == original, "undo gives back the mesh as read");
  expect(read_positions(dir + "/redone.off") == read_positions(dir + "/faired.off"),
         "redo gives back the faired mesh");
  std::cout << (failures == 0 ? "all checks passed\n"
                              : std::to_string(failures) + " check(s) failed\n");
  return failures == 0 ? 0 : 1;
}

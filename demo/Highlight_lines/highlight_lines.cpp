// Computes the highlight line model of a triangle mesh and writes it as CGAL polylines and as a
// picture of the shaded mesh with its highlight lines.
//
//   highlight_lines [mesh.off|.obj|.ply|.stl] [options]
//
// With no mesh, the bundled VW Beetle body (data/beetle.off) is used. Run with --help for the
// options; with no light options, a light tunnel is placed above the mesh automatically
// (CGAL::Highlight_lines::default_light_setup()).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/compute_highlight_lines.h>

#include "command_line.h"
#include "highlight_picture.h"
#include "mesh_io.h"
#include "mesh_picture.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;

namespace {

const char* usage =
    "usage: highlight_lines [MESH] [options]\n"
    "\n"
    "Computes the highlight lines of a triangle mesh (OFF, OBJ, PLY or STL; polygon soups are\n"
    "repaired, polygons triangulated, degenerate triangles removed) for a row of parallel\n"
    "tube lights, and writes PREFIX.polylines.txt (CGAL polylines) and PREFIX.png.\n"
    "MESH defaults to the bundled VW Beetle body.\n"
    "\n"
    "options:\n"
    "  --out PREFIX            output prefix (default: highlight_lines)\n"
    "  --mesh-out FILE         also write the mesh as read (triangulated, repaired), in the\n"
    "                          format of FILE's extension (.off, .obj, .ply or .stl); a .ply\n"
    "                          file (binary) carries two vertex properties: highlight_distance,\n"
    "                          the highlight distance d (NaN where the normal points away from\n"
    "                          the lights), whose contour at m*s is the line of light m, and\n"
    "                          highlight_level = d/s, whose contour at m is that line: any\n"
    "                          viewer's contour filter (ParaView, MeshLab) shows the lines\n"
    "  --lines N               with the automatic light setup: about N lights across the\n"
    "                          central part of the surface (default 40)\n"
    "  --base X Y Z            a point of the base light A0     } all four give the light\n"
    "  --direction X Y Z       the direction H of the lights    } setup explicitly; H must be\n"
    "  --normal X Y Z          the normal Z of the light plane  } perpendicular to Z\n"
    "  --spacing S             the distance between lights      }\n"
    "  --levels LO HI          only the lights with index in [LO, HI]\n"
    "  --crease-angle DEG      edges whose faces' normals differ by more than DEG degrees\n"
    "                          are creases (Polygon_mesh_processing::detect_sharp_edges()):\n"
    "                          the normals are not averaged across them, so that the lines\n"
    "                          run straight on the planar faces of a CAD part and end at its\n"
    "                          creases (default: none, the paper's model); --mesh-out's\n"
    "                          highlight_distance stays the paper's field (one value per\n"
    "                          vertex)\n"
    "  --view AZIMUTH ELEVATION  viewing direction in degrees around the light-plane normal\n"
    "                          (default 35 30)\n"
    "  --size W H              picture size in pixels (default 1600 1000)\n"
    "  --help                  this text\n";

using command_line::fail;
using command_line::number;
using command_line::word;

struct Options
{
  std::string mesh = std::string(HIGHLIGHT_LINES_DATA_DIR) + "/beetle.off";
  std::string out = "highlight_lines";
  std::string mesh_out;
  int lines = 40;
  command_line::Light_options lights;
  std::optional<std::pair<long long, long long>> levels;
  std::optional<double> crease_angle;
  double azimuth = 35, elevation = 30;
  command_line::Picture_size size{1600, 1000};
};

Options parse(int argc, char** argv)
{
  Options o;
  command_line::parse(
      argc, argv, usage,
      [&](const std::string& a, int& i) {
        if (a == "--out")
          o.out = word(i, argc, argv);
        else if (a == "--mesh-out") {
          o.mesh_out = word(i, argc, argv);
          if (!mesh_io::writable_extension(mesh_io::extension(o.mesh_out)))
            fail("--mesh-out " + o.mesh_out + ": the extension must be .off, .obj, .ply or .stl");
        } else if (a == "--lines")
          o.lines = int(number(i, argc, argv));
        else if (a == "--levels") {
          const double lo = number(i, argc, argv), hi = number(i, argc, argv);
          o.levels = std::make_pair((long long)lo, (long long)hi);
        } else if (a == "--crease-angle") {
          o.crease_angle = number(i, argc, argv);
          if (!(*o.crease_angle > 0 && *o.crease_angle < 180))
            fail("--crease-angle: the angle must lie strictly between 0 and 180 degrees");
        } else if (a == "--view") {
          o.azimuth = number(i, argc, argv);
          o.elevation = number(i, argc, argv);
        } else
          return o.lights.read(a, i, argc, argv) || o.size.read(a, i, argc, argv);
        return true;
      },
      [&](const std::string& mesh) { o.mesh = mesh; });
  o.lights.check();
  o.size.check(16, 10000);
  return o;
}

using mesh_picture::to_array;

} // namespace

int main(int argc, char** argv)
{
  command_line::program() = "highlight_lines";
  const Options options = parse(argc, argv);

  Mesh mesh;
  if (!mesh_io::read_input_mesh(options.mesh, mesh, command_line::program()))
    return 1;

  // With --crease-angle, the mesh's creases: every step below computes the model cut along
  // them (the light setup's spacing too, from the distance values of the cut model).
  auto creases = mesh.add_property_map<Mesh::Edge_index, bool>("e:highlight_crease", false).first;
  if (options.crease_angle) {
    CGAL::Polygon_mesh_processing::detect_sharp_edges(mesh, *options.crease_angle, creases);
    std::size_t number_of_creases = 0;
    for (auto e : edges(mesh))
      number_of_creases += creases[e] ? 1 : 0;
    std::cout << number_of_creases << " crease edges (normals differ by more than "
              << *options.crease_angle << " degrees)\n";
  }
  try {
    // Runs `compute` with the named parameters `np`, cut along the creases if asked for.
    auto run = [&](const auto& np, const auto& compute) {
      return options.crease_angle ? compute(HLP::crease_edge_map(np, creases)) : compute(np);
    };
    const HL::Light_setup<K> lights =
        options.lights.given() ? options.lights.setup<K>()
                               : run(HLP::number_of_lines(options.lines), [&](const auto& np) {
                                   return HL::default_light_setup(mesh, np);
                                 });
    std::cout << "lights: base " << lights.base_point() << ", direction "
              << lights.light_direction() << ", plane normal " << lights.plane_normal()
              << ", spacing " << lights.spacing() << "\n";

    // By default, the lights over the central part of the surface, imaged on the side of
    // the surface that faces them (as a light tunnel shows them).
    const std::pair<long long, long long> levels =
        options.levels
            ? *options.levels
            : run(CGAL::parameters::vertex_point_map(mesh.points()),
                  [&](const auto& np) { return HL::default_level_range(mesh, lights, np); });
    std::cout << "light indices " << levels.first << " to " << levels.second << "\n";
    std::vector<std::vector<K::Point_3>> polylines;
    const auto model = run(
        HLP::combine(HLP::level_range(levels), HLP::facing_side_only(true)), [&](const auto& np) {
          return CGAL::compute_highlight_lines(mesh, lights, std::back_inserter(polylines), np);
        });
    std::cout << model.lines().size() << " highlight lines through " << model.nodes().size()
              << " nodes";
    if (model.number_of_skipped_edges() > 0)
      std::cout << "; " << model.number_of_skipped_edges()
                << " edges crossing too many lights were skipped";
    if (model.number_of_undefined_vertices() > 0)
      std::cout << "; " << model.number_of_undefined_vertices()
                << " vertices have normals parallel to the light plane";
    std::cout << "\n";

    const std::string polylines_path = options.out + ".polylines.txt";
    std::ofstream file(polylines_path);
    file.precision(17);
    for (const auto& polyline : polylines) {
      file << polyline.size();
      for (const auto& p : polyline)
        file << ' ' << p;
      file << '\n';
    }
    if (!file) {
      std::cerr << "highlight_lines: cannot write " << polylines_path << "\n";
      return 1;
    }

    // The picture: the mesh seen from above the light plane's side, lines drawn over it.
    std::vector<highlight_picture::Point3> points;
    std::vector<std::array<std::size_t, 3>> triangles;
    if (options.crease_angle)
      mesh_picture::mesh_arrays(mesh, creases, points, triangles);
    else
      mesh_picture::mesh_arrays(mesh, points, triangles);
    // Azimuth around the light plane normal Z, measured from the light direction H.
    const auto z = to_array(lights.plane_normal()), h = to_array(lights.light_direction());
    const auto w = highlight_picture::detail::cross(z, h);
    const double a = options.azimuth * M_PI / 180, e = options.elevation * M_PI / 180;
    highlight_picture::Vector3 view;
    for (int k = 0; k < 3; ++k)
      view[k] = -(std::cos(e) * (std::cos(a) * h[k] + std::sin(a) * w[k]) + std::sin(e) * z[k]);
    const auto camera =
        highlight_picture::fit_camera(points, view, z, options.size.width, options.size.height);
    highlight_picture::Renderer renderer(options.size.width, options.size.height, camera);
    renderer.draw_mesh(points, triangles);
    renderer.draw_polylines(mesh_picture::polyline_arrays(polylines));
    const std::string picture_path = options.out + ".png";
    if (!highlight_picture::write_png(picture_path, renderer.image())) {
      std::cerr << "highlight_lines: cannot write " << picture_path << "\n";
      return 1;
    }
    std::cout << "wrote " << polylines_path << " and " << picture_path << "\n";
    if (!options.mesh_out.empty()) {
      const bool ply = mesh_io::extension(options.mesh_out) == ".ply";
      if (!(ply ? mesh_io::write_ply_with_highlight_distances(options.mesh_out, mesh, lights, true)
                : mesh_io::write_mesh(options.mesh_out, mesh))) {
        std::cerr << "highlight_lines: cannot write " << options.mesh_out << "\n";
        return 1;
      }
      std::cout << "wrote " << options.mesh_out
                << (ply ? (options.crease_angle
                               ? " (vertex properties highlight_distance and highlight_level of "
                                 "the paper's model, without the cut at the creases: one value "
                                 "per vertex)"
                               : " (vertex properties highlight_distance and highlight_level: "
                                 "the lines are their contours at m*s and m)")
                        : "")
                << "\n";
    }
  } catch (const HL::Invalid_input& e) {
    std::cerr << "highlight_lines: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

// Finds where the highlight lines of a mesh bend abnormally and marks those regions in a picture.
//
//   detect_highlight_line_irregularities [mesh.off|.obj|.ply] [options]
//
// With no mesh, the bundled VW Beetle body (data/beetle.off) is used. Run with --help.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/compute_highlight_lines.h>
#include <CGAL/detect_highlight_line_irregularities.h>

#include "command_line.h"
#include "highlight_picture.h"
#include "mesh_io.h"
#include "region_overview.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::face_descriptor face_descriptor;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;
namespace pic = highlight_picture;

namespace {

const char* usage =
    "usage: detect_highlight_line_irregularities [MESH] [options]\n"
    "\n"
    "Sweeps a light tunnel over a triangle mesh (OFF, OBJ, PLY or STL; polygon soups are\n"
    "repaired, polygons triangulated, degenerate triangles removed), finds where the\n"
    "highlight lines bend abnormally, prints the regions found and writes PREFIX.png\n"
    "(regions tinted, strongest in red),\n"
    "PREFIX.regions.txt (one line of face indices per region) and, per region,\n"
    "PREFIX.region_N.selection.txt (a CGAL Lab selection file).\n"
    "MESH defaults to the bundled VW Beetle body.\n"
    "\n"
    "options:\n"
    "  --out PREFIX        output prefix (default: irregularities)\n"
    "  --lines N           about N lights across the surface (default 30)\n"
    "  --base X Y Z        a point of the base light A0     } all four give the light\n"
    "  --direction X Y Z   the direction H of the lights    } setup explicitly (the first\n"
    "  --normal X Y Z      the normal Z of the light plane  } plane of the sweep); H must be\n"
    "  --spacing S         the distance between lights      } perpendicular to Z\n"
    "  --orientations N    light directions in the sweep (default 3)\n"
    "  --offsets N         shifts of the lights per direction (default 2)\n"
    "  --scale W           scale of the measure, in mean edge lengths (default 3)\n"
    "  --threshold Z       robust z-score of an anomaly (default 5)\n"
    "  --bending           score the lines by their bending against each line's statistics\n"
    "                      (the paper's measure; default: the sideways residual from a\n"
    "                      local fit, which locates defects on scans and CAD parts)\n"
    "  --size W H          picture size in pixels (default 1600 1000)\n"
    "  --help              this text\n";

using command_line::number;
using command_line::word;

struct Options
{
  std::string mesh = std::string(HIGHLIGHT_LINES_DATA_DIR) + "/beetle.off";
  std::string out = "irregularities";
  int lines = 30, orientations = 3, offsets = 2;
  double scale = 3, threshold = 5;
  bool local_residual = true;
  command_line::Light_options lights;
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
        else if (a == "--lines")
          o.lines = int(number(i, argc, argv));
        else if (a == "--orientations")
          o.orientations = int(number(i, argc, argv));
        else if (a == "--offsets")
          o.offsets = int(number(i, argc, argv));
        else if (a == "--scale")
          o.scale = number(i, argc, argv);
        else if (a == "--threshold")
          o.threshold = number(i, argc, argv);
        else if (a == "--bending")
          o.local_residual = false;
        else
          return o.lights.read(a, i, argc, argv) || o.size.read(a, i, argc, argv);
        return true;
      },
      [&](const std::string& mesh) { o.mesh = mesh; });
  o.lights.check();
  o.size.check(16, 10000);
  return o;
}

} // namespace

int main(int argc, char** argv)
{
  command_line::program() = "detect_highlight_line_irregularities";
  const Options o = parse(argc, argv);
  Mesh mesh;
  if (!mesh_io::read_input_mesh(o.mesh, mesh, command_line::program()))
    return 1;
  try {
    const HL::Light_setup<K> lights =
        o.lights.given() ? o.lights.setup<K>()
                         : HL::default_light_setup(mesh, HLP::number_of_lines(o.lines));
    std::vector<HL::Highlight_line_irregularity<Mesh>> found;
    CGAL::detect_highlight_line_irregularities(
        mesh, lights, std::back_inserter(found),
        HLP::combine(HLP::number_of_orientations(o.orientations), HLP::number_of_offsets(o.offsets),
                     HLP::detection_scale(o.scale), HLP::detection_threshold(o.threshold),
                     HLP::local_residual(o.local_residual)));

    std::cout << found.size()
              << " irregular region(s), the likeliest defects first (confidence below 0.5: "
                 "likely design):\n";
    std::ofstream regions_file(o.out + ".regions.txt");
    for (std::size_t i = 0; i < found.size(); ++i) {
      const auto& r = found[i];
      std::cout << "  #" << i + 1 << ": " << HL::to_string(r.kind) << ", confidence "
                << r.confidence << ", score " << r.score
                << (o.local_residual ? ", sideways offset up to " : ", bending up to ")
                << r.max_bending << (o.local_residual ? " mean edge lengths" : " rad")
                << ", seen on " << r.number_of_lines << " lines in " << r.number_of_light_setups
                << " light setups, " << r.faces.size() << " faces around "
                << mesh.point(r.peak_vertex) << "\n";
      std::vector<std::size_t> ids;
      for (std::size_t k = 0; k < r.faces.size(); ++k) {
        ids.push_back(std::size_t(r.faces[k]));
        regions_file << (k ? " " : "") << ids.back();
      }
      regions_file << "\n";
      const std::string selection = o.out + ".region_" + std::to_string(i + 1) + ".selection.txt";
      if (!mesh_io::write_selection(selection, ids)) {
        std::cerr << "detect_highlight_line_irregularities: cannot write " << selection << "\n";
        return 1;
      }
    }

    // The picture: the whole mesh from above the light plane, the regions tinted (red: the
    // strongest, orange: the others), the highlight lines of the first light setup on top.
    std::vector<std::vector<face_descriptor>> regions;
    for (const auto& r : found)
      regions.push_back(r.faces);
    const pic::Image image =
        region_overview::picture(mesh, lights, regions, o.size.width, o.size.height);
    const std::string picture = o.out + ".png";
    if (!pic::write_png(picture, image) || !regions_file) {
      std::cerr << "detect_highlight_line_irregularities: cannot write " << picture << " or "
                << o.out << ".regions.txt\n";
      return 1;
    }
    std::cout << "wrote " << picture << " and " << o.out << ".regions.txt\n";
  } catch (const HL::Invalid_input& e) {
    std::cerr << "detect_highlight_line_irregularities: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

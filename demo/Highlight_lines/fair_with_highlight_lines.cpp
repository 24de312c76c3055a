// The whole story on one mesh: highlight lines show a dent, the dent's region is faired with
// highlight lines, and the lines run smoothly again.
//
//   fair_with_highlight_lines [mesh] [options]      (see --help)
//
// With no mesh, the bundled VW Beetle body is used and a dent is pressed into its roof first
// (so that there is something to repair): the program says so, and shows it.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/Highlight_lines/fairing_building_blocks.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/compute_highlight_lines.h>
#include <CGAL/detect_highlight_line_irregularities.h>
#include <CGAL/Highlight_lines/grown_face_region.h>
#include <CGAL/Highlight_lines/join_touching_irregularities.h>
#include <CGAL/fair_with_highlight_lines.h>

#include "command_line.h"
#include "highlight_picture.h"
#include "mesh_io.h"
#include "mesh_picture.h"
#include "region_overview.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Face_index face_descriptor;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;
namespace pic = highlight_picture;

namespace {

// Below this many movable vertices the program suggests a larger region.
constexpr std::size_t few_movable_vertices = 10;

const char* usage =
    "usage: fair_with_highlight_lines [MESH] [options]\n"
    "\n"
    "Fairs a region of a triangle mesh (OFF, OBJ, PLY or STL; polygon soups are repaired,\n"
    "polygons triangulated, degenerate triangles removed) so that the surface and its\n"
    "highlight lines become smooth: writes PREFIX.png (before / after, close-up),\n"
    "PREFIX_faired.EXT and, when a dent was added,\n"
    "PREFIX_dented.EXT, in the format of MESH (EXT: its extension) or as --format asks.\n"
    "MESH defaults to the bundled VW Beetle body, into whose roof a dent is pressed first.\n"
    "\n"
    "options:\n"
    "  --out PREFIX          output prefix (default: fairing)\n"
    "  --format EXT          write the meshes as off, obj, ply or stl (default: the format of\n"
    "                        MESH, OFF if CGAL does not write it)\n"
    "  --center X Y Z        centre of the region (the nearest vertex is used); default: on the\n"
    "                        roof of the bundled beetle, or the mesh's highest point on the\n"
    "                        axis of smallest extent\n"
    "  --radius R            region radius: faces whose three vertices lie within R of the\n"
    "                        centre (default: 7 % of the bounding box diagonal)\n"
    "  --region FILE         region as a file of face indices (whitespace separated), or as a\n"
    "                        CGAL Lab selection file (*.selection.txt: its face ids), instead\n"
    "  --dent DEPTH          press a smooth dent of this depth into the region first, along the\n"
    "                        normals (default: 0.6 % of the diagonal for the bundled beetle,\n"
    "                        none for a user's mesh); 0 for none\n"
    "  --lines N             about N lights across the region (default 12)\n"
    "  --base X Y Z          a point of the base light A0     } the light setup, explicitly;\n"
    "  --direction X Y Z     the direction H of the lights    } all four together (default:\n"
    "  --normal X Y Z        the normal Z of the light plane  } a light tunnel above the mesh,\n"
    "  --spacing S           the distance between lights      } spacing from --lines)\n"
    "  --iterations N        iteration bound (default 50)\n"
    "  --curvature-variation fair with the variation of the mean curvature, the default\n"
    "                        (continues the surface's curvature across the region's border:\n"
    "                        the closest repair of scanned and CAD surfaces)\n"
    "  --willmore            fair with the Willmore energy of the paper (continues only the\n"
    "                        tangent planes)\n"
    "  --mean-curvature      fair with the mean curvature energy (the normal part of the\n"
    "                        Willmore energy; for meshes with slivers or folded triangles)\n"
    "  --detect              automatic mode: find the irregular regions of the whole mesh\n"
    "                        (CGAL::detect_and_fair_highlight_line_irregularities), fair each,\n"
    "                        and write PREFIX_regions.png (before / after, regions tinted: red\n"
    "                        the strongest) instead of the close-up; --center, --radius and\n"
    "                        --region then only place the dent\n"
    "  --max-regions N       with --detect: fair at most the N strongest regions (default: all)\n"
    "  --min-confidence C    with --detect: fair only the regions of confidence >= C (default\n"
    "                        0.5; the others, elongated along a feature or wider than a defect,\n"
    "                        are likely design and are listed as skipped); 0 fairs every one\n"
    "  --fairing-margin N    with --detect: rings of faces added around each region before it\n"
    "                        is faired, never across a sharp edge (default 3, the detection\n"
    "                        scale; fewer move less design around a region, but may leave part\n"
    "                        of a defect outside it)\n"
    "  --show-irregularities also sweep the lights over the whole mesh and write\n"
    "                        PREFIX_irregularities.png, the irregular regions tinted (done by\n"
    "                        default only for the bundled beetle without --center/--region)\n"
    "  --size W H            picture size per panel (default 800 600)\n"
    "  --help                this text\n";

using command_line::fail;
using command_line::number;
using command_line::word;

struct Options
{
  std::string mesh = std::string(HIGHLIGHT_LINES_DATA_DIR) + "/beetle.off";
  bool default_mesh = true;
  std::string out = "fairing";
  std::string format; // the output meshes' extension, with its dot; empty: the input's
  std::optional<K::Point_3> center;
  std::optional<double> radius, dent;
  command_line::Light_options lights;
  std::string region_file;
  int lines = 12, iterations = 50;
  command_line::Picture_size size{800, 600};
  bool detect = false, show_irregularities = false;
  HL::Fairness_energy energy = HL::Fairness_energy::CURVATURE_VARIATION;
  std::size_t max_regions = std::size_t(-1);
  double min_confidence = 0.5;
  int fairing_margin = 3;
};

Options parse(int argc, char** argv)
{
  Options o;
  command_line::parse(
      argc, argv, usage,
      [&](const std::string& a, int& i) {
        if (a == "--out")
          o.out = word(i, argc, argv);
        else if (a == "--region")
          o.region_file = word(i, argc, argv);
        else if (a == "--format") {
          const std::string format = word(i, argc, argv);
          o.format = mesh_io::format_extension(format);
          if (o.format.empty())
            fail("--format " + format + ": must be off, obj, ply or stl");
        } else if (a == "--center") {
          const auto c = command_line::triple(i, argc, argv);
          o.center = K::Point_3(c[0], c[1], c[2]);
        } else if (a == "--radius")
          o.radius = number(i, argc, argv);
        else if (a == "--dent")
          o.dent = number(i, argc, argv);
        else if (a == "--lines")
          o.lines = int(number(i, argc, argv));
        else if (a == "--detect")
          o.detect = true;
        else if (a == "--show-irregularities")
          o.show_irregularities = true;
        else if (a == "--mean-curvature")
          o.energy = HL::Fairness_energy::MEAN_CURVATURE;
        else if (a == "--willmore")
          o.energy = HL::Fairness_energy::WILLMORE;
        else if (a == "--curvature-variation")
          o.energy = HL::Fairness_energy::CURVATURE_VARIATION;
        else if (a == "--min-confidence") {
          o.min_confidence = number(i, argc, argv);
          if (!(o.min_confidence >= 0 && o.min_confidence <= 1))
            fail("--min-confidence must be in [0, 1]");
        } else if (a == "--fairing-margin") {
          const double n = number(i, argc, argv);
          if (!(n >= 0 && n <= 1000 && n == std::floor(n)))
            fail("--fairing-margin must be a whole number of rings in [0, 1000]");
          o.fairing_margin = int(n);
        } else if (a == "--max-regions") {
          const double n = number(i, argc, argv);
          if (!(n >= 1))
            fail("--max-regions must be at least 1");
          o.max_regions = std::size_t(n);
        } else if (a == "--iterations")
          o.iterations = int(number(i, argc, argv));
        else
          return o.lights.read(a, i, argc, argv) || o.size.read(a, i, argc, argv);
        return true;
      },
      [&](const std::string& mesh) {
        o.mesh = mesh;
        o.default_mesh = false;
      });
  o.lights.check();
  o.size.check(64, 8000);
  return o;
}

using mesh_picture::to_array;

// A close-up of the region: the mesh shaded (region tinted), its highlight lines, and
// optionally other curves (the desired lines) in colour.
pic::Image picture(const Mesh& mesh, const std::vector<face_descriptor>& region,
                   const HL::Light_setup<K>& lights, const std::pair<long long, long long>& levels,
                   const std::vector<std::vector<K::Point_3>>& extra, const Options& o)
{
  std::vector<pic::Point3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  mesh_picture::mesh_arrays(mesh, points, triangles);
  std::vector<std::optional<pic::RGB>> colors;
  std::vector<bool> in_region(num_faces(mesh), false);
  for (face_descriptor f : region)
    in_region[std::size_t(f)] = true;
  for (auto f : faces(mesh)) {
    colors.push_back(in_region[std::size_t(f)] ? std::optional<pic::RGB>(pic::mix(
                                                     pic::colors::paint, pic::colors::region, 0.45))
                                               : std::nullopt);
  }
  // Close-up: the region and a margin, seen from the light plane's side.
  std::vector<pic::Point3> focus;
  for (face_descriptor f : region)
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      focus.push_back(to_array(mesh.point(v)));
  const auto z = to_array(lights.plane_normal());
  const auto h = to_array(lights.light_direction());
  pic::Vector3 view;
  for (int k = 0; k < 3; ++k)
    view[k] = -(0.35 * h[k] + z[k]);
  pic::Camera camera = pic::fit_camera(focus, view, h, o.size.width, o.size.height, 0.0);
  camera.view_height *= 1.35;
  pic::Renderer renderer(o.size.width, o.size.height, camera);
  renderer.draw_mesh(points, triangles, pic::Surface_style{}, colors);
  std::vector<std::vector<K::Point_3>> lines;
  CGAL::compute_highlight_lines(
      mesh, lights, std::back_inserter(lines),
      HLP::combine(HLP::level_range(levels), HLP::facing_side_only(true)));
  renderer.draw_polylines(mesh_picture::polyline_arrays(lines));
  if (!extra.empty()) {
    const auto curves = mesh_picture::polyline_arrays(extra);
    pic::Line_style blue;
    blue.color = pic::colors::blue;
    blue.width = 2.2;
    renderer.draw_polylines(curves, blue);
  }
  return renderer.image();
}

// The irregular regions of the whole mesh, found by a light sweep with the detection's defaults
// (the lights' spacing refined from the mesh: a defect is only seen if several lines cross it),
// the strongest first; printed. More offsets give design regions a higher confidence: with 4
// instead of the default 2, the automatic mode faired a region of the undented fandisk (and,
// with these 60 lines, two of the bunny), moving it by 3-5 % of the bounding box diagonal.
std::vector<HL::Highlight_line_irregularity<Mesh>>
find_irregularities(const Mesh& mesh, const HL::Light_setup<K>& lights)
{
  std::cout << "looking for irregular highlight lines (3 light directions x 2 offsets)...\n";
  std::vector<HL::Highlight_line_irregularity<Mesh>> found;
  CGAL::detect_highlight_line_irregularities(mesh, lights, std::back_inserter(found));
  std::cout << found.size() << " irregular region(s), the likeliest defects first:\n";
  const std::size_t shown = (std::min)(found.size(), std::size_t(5));
  for (std::size_t i = 0; i < shown; ++i)
    std::cout << "  " << HL::to_string(found[i].kind) << ", confidence " << found[i].confidence
              << ", score " << found[i].score << ", " << found[i].faces.size() << " faces around "
              << mesh.point(found[i].peak_vertex) << ", seen in " << found[i].number_of_light_setups
              << " light setups\n";
  if (found.size() > shown)
    std::cout << "  and " << found.size() - shown << " more, of lower confidence x score\n";
  return found;
}

// Whether some face of `region` has a neighbour outside it (the mesh's own border does not
// count): a region without one holds whole parts of the mesh, which nothing outside holds.
bool has_border_inside_the_mesh(const Mesh& mesh, const std::vector<face_descriptor>& region)
{
  std::vector<char> in_region(mesh.num_faces(), 0); // indices up to the removed faces too
  for (face_descriptor f : region)
    in_region[f.idx()] = 1;
  for (face_descriptor f : region)
    for (auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const face_descriptor g = mesh.face(mesh.opposite(h));
      if (g != Mesh::null_face() && !in_region[g.idx()])
        return true;
    }
  return false;
}

// The light tunnel of the whole mesh, with the spacing refined so that about `lines` lights
// cross the region.
HL::Light_setup<K> region_light_tunnel(const Mesh& mesh, const std::vector<face_descriptor>& region,
                                       int lines)
{
  const auto tunnel = HL::default_light_setup(mesh);
  const auto across = HL::default_level_range(mesh, tunnel, HLP::face_range(region));
  const double spacing = CGAL::to_double(tunnel.spacing()) *
                         double((std::max)(across.second - across.first, 1LL)) / double(lines);
  return HL::Light_setup<K>(tunnel.base_point(), tunnel.light_direction(), tunnel.plane_normal(),
                            spacing);
}

// The lights drawn in the close-up: those over the region and as many again on each side.
// Taken from the region, not the mesh: lights that face the region need not face the rest.
std::pair<long long, long long> region_levels(const Mesh& mesh, const HL::Light_setup<K>& lights,
                                              const std::vector<face_descriptor>& region)
{
  try {
    const auto r = HL::default_level_range(mesh, lights, HLP::face_range(region));
    const long long margin = (std::max)(r.second - r.first, 2LL);
    return {r.first - margin, r.second + margin};
  } catch (const HL::Invalid_input&) { // no vertex of the region faces the light plane
    return {-1000, 1000};              // the model caps the levels per edge anyway
  }
}

HL::Light_setup<K> sweep_lights(const Mesh& mesh, const Options& o)
{
  return o.lights.given() ? o.lights.setup<K>()
                          : HL::default_light_setup(mesh, HLP::number_of_lines(60));
}

// Automatic mode: find the irregular regions of the whole mesh, fair them one at a time (the
// strongest first), and show them before and after.
int detect_and_fair(Mesh& mesh, const Options& o)
{
  const HL::Light_setup<K> lights = sweep_lights(mesh, o);
  std::vector<HL::Highlight_line_irregularity<Mesh>> found = find_irregularities(mesh, lights);
  // Only the likely defects are faired (as detect_and_fair_highlight_line_irregularities()
  // does with its minimum_confidence), those that touch as one; no region crosses a sharp edge.
  const std::size_t before_joining = found.size();
  HL::join_touching_irregularities(mesh, found, o.min_confidence);
  if (found.size() < before_joining)
    std::cout << "touching regions to fair joined: " << before_joining << " regions -> "
              << found.size() << "\n";
  std::vector<HL::Highlight_line_irregularity<Mesh>> skipped;
  {
    std::vector<HL::Highlight_line_irregularity<Mesh>> kept;
    for (auto& r : found)
      (r.confidence >= o.min_confidence ? kept : skipped).push_back(std::move(r));
    found.swap(kept);
  }
  // The strongest few skipped (the rest is design too, and weaker).
  const std::size_t shown = (std::min)(skipped.size(), std::size_t(3));
  for (std::size_t i = 0; i < shown; ++i)
    std::cout << "skipped (confidence " << skipped[i].confidence << " below " << o.min_confidence
              << ", " << HL::to_string(skipped[i].kind)
              << ": likely design): " << skipped[i].faces.size() << " faces around "
              << mesh.point(skipped[i].peak_vertex) << "\n";
  if (skipped.size() > shown)
    std::cout << "skipped " << skipped.size() - shown << " more of lower confidence\n";
  if (found.size() > o.max_regions) {
    found.resize(o.max_regions);
    std::cout << "the " << o.max_regions << " strongest are faired\n";
  }
  std::vector<std::vector<face_descriptor>> regions;
  // Each with a margin of rings (by default 3, the detection scale), as
  // detect_and_fair_highlight_line_irregularities() does: a region is centred where the lines
  // move most, often one flank of the defect, and a fairing moves only its inner vertices.
  for (const auto& r : found)
    regions.push_back(HL::grown_face_region(mesh, r.faces, o.fairing_margin, 60.0,
                                            get(CGAL::vertex_point, mesh)));
  const pic::Image before =
      region_overview::picture(mesh, lights, regions, o.size.width, o.size.height);

  std::size_t repaired = 0;
  for (std::size_t i = 0; i < found.size(); ++i) {
    std::cout << "region " << i + 1 << "/" << found.size() << ": " << std::flush;
    try {
      const HL::Fairing_report report = CGAL::fair_with_highlight_lines(
          mesh, regions[i], lights,
          HLP::fairness_energy(CGAL::parameters::number_of_iterations(o.iterations), o.energy));
      ++repaired;
      std::cout << HL::to_string(report.status) << " after " << report.iterations << " iterations, "
                << report.number_of_movable_vertices << " movable vertices\n";
    } catch (const HL::Invalid_input& e) {
      std::cout << "not faired: " << e.what() << "\n";
    } catch (const HL::Fairing_failure& e) {
      std::cout << "not faired: " << e.what() << " (left unchanged)\n";
    }
  }
  const pic::Image after =
      region_overview::picture(mesh, lights, regions, o.size.width, o.size.height);
  pic::Layout layout;
  layout.title = "Irregular regions found and faired";
  const pic::Image both =
      pic::side_by_side({before, after},
                        {"before: " + std::to_string(found.size()) + " region(s) to fair, " +
                             std::to_string(skipped.size()) + " skipped as design",
                         "after: " + std::to_string(repaired) + " faired"},
                        layout);
  if (!pic::write_png(o.out + "_regions.png", both) ||
      !mesh_io::write_mesh(o.out + "_faired" + mesh_io::output_extension(o.mesh, o.format), mesh)) {
    std::cerr << "fair_with_highlight_lines: cannot write the output files\n";
    return 1;
  }
  std::cout << "wrote " << o.out << "_regions.png and " << o.out << "_faired"
            << mesh_io::output_extension(o.mesh, o.format) << "\n";
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  command_line::program() = "fair_with_highlight_lines";
  const Options o = parse(argc, argv);
  Mesh mesh;
  if (!mesh_io::read_input_mesh(o.mesh, mesh, command_line::program()))
    return 1;
  try {
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
    const double diagonal =
        std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                  CGAL::square(box.zmax() - box.zmin()));
    // The region's centre: a vertex.
    K::Point_3 wanted = o.center ? *o.center : K::Point_3(0.04, box.ymax(), -0.12);
    if (!o.center && !o.default_mesh) { // top of the mesh along its smallest extent
      const double ext[3] = {box.xmax() - box.xmin(), box.ymax() - box.ymin(),
                             box.zmax() - box.zmin()};
      const int up = ext[0] < ext[1] ? (ext[0] < ext[2] ? 0 : 2) : (ext[1] < ext[2] ? 1 : 2);
      double c[3] = {(box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2,
                     (box.zmin() + box.zmax()) / 2};
      c[up] = up == 0 ? box.xmax() : up == 1 ? box.ymax() : box.zmax();
      wanted = K::Point_3(c[0], c[1], c[2]);
    }
    Mesh::Vertex_index center_vertex = *vertices(mesh).begin();
    for (auto v : vertices(mesh))
      if (CGAL::squared_distance(mesh.point(v), wanted) <
          CGAL::squared_distance(mesh.point(center_vertex), wanted))
        center_vertex = v;
    const K::Point_3 center = mesh.point(center_vertex);
    const double radius = o.radius ? *o.radius : 0.07 * diagonal;

    std::vector<face_descriptor> region;
    if (!o.region_file.empty()) {
      std::string error;
      for (std::size_t id : mesh_io::read_region(o.region_file, num_faces(mesh), error))
        region.push_back(face_descriptor(std::uint32_t(id)));
      if (!error.empty())
        fail(error);
    } else {
      for (auto f : faces(mesh)) {
        bool inside = true;
        for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
          inside = inside && CGAL::squared_distance(mesh.point(v), center) < radius * radius;
        if (inside)
          region.push_back(f);
      }
    }
    std::cout << "region: " << region.size() << " faces around " << center << "\n";

    if (region.empty())
      fail("the region is empty: give a larger --radius or another --center");
    // Explicit lights (--base --direction --normal --spacing) are used as given. Otherwise: the
    // light tunnel of the whole mesh, with the spacing refined so that about o.lines lights
    // cross the region (the close-up shows the lines' shape there).
    const HL::Light_setup<K> lights =
        o.lights.given() ? o.lights.setup<K>() : region_light_tunnel(mesh, region, o.lines);
    std::cout << "lights: base " << lights.base_point() << ", direction "
              << lights.light_direction() << ", plane normal " << lights.plane_normal()
              << ", spacing " << lights.spacing() << "\n";
    const auto levels = region_levels(mesh, lights, region);

    // The dent: a smooth bump (1 - (r/R)^2)^3 pressed along the normals, inside the region.
    const double dent = o.dent ? *o.dent : (o.default_mesh ? 0.006 * diagonal : 0.0);
    if (dent != 0) {
      std::vector<std::pair<Mesh::Vertex_index, K::Point_3>> moved;
      const double dent_radius = 0.6 * radius;
      for (auto v : vertices(mesh)) {
        const double r2 =
            CGAL::squared_distance(mesh.point(v), center) / (dent_radius * dent_radius);
        if (r2 >= 1)
          continue;
        const K::Vector_3 n = CGAL::Polygon_mesh_processing::compute_vertex_normal(v, mesh);
        moved.emplace_back(v, mesh.point(v) - dent * (1 - r2) * (1 - r2) * (1 - r2) * n);
      }
      for (const auto& m : moved)
        mesh.point(m.first) = m.second;
      std::cout << "pressed a dent of depth " << dent << " and radius " << dent_radius
                << " into the surface (" << moved.size() << " vertices moved)\n";
      mesh_io::write_mesh(o.out + "_dented" + mesh_io::output_extension(o.mesh, o.format), mesh);
    }

    if (o.detect)
      return detect_and_fair(mesh, o);

    // Where the highlight lines are irregular, over the whole mesh (the user's region is faired
    // below; --detect fairs these instead): in the demo on the bundled mesh, or when asked.
    if (o.show_irregularities || (o.default_mesh && o.region_file.empty() && !o.center)) {
      const HL::Light_setup<K> sweep = sweep_lights(mesh, o);
      std::vector<std::vector<face_descriptor>> regions;
      for (const auto& r : find_irregularities(mesh, sweep))
        regions.push_back(r.faces);
      if (!pic::write_png(
              o.out + "_irregularities.png",
              region_overview::picture(mesh, sweep, regions, o.size.width, o.size.height)))
        fail("cannot write " + o.out + "_irregularities.png");
      std::cout << "wrote " << o.out << "_irregularities.png (tinted: the irregular regions)\n";
    }

    std::vector<std::vector<K::Point_3>> desired;
    HL::desired_highlight_lines(mesh, region, lights, std::back_inserter(desired));
    const pic::Image before = picture(mesh, region, lights, levels, desired, o);
    // Without desired lines the highlight term is empty: the fairing then only lowers the
    // fairness energy, which on a large region takes long for a result the user did not ask
    // for. Said before the run.
    if (desired.empty()) {
      std::cout << "note: no highlight line gets a desired line here (one must cross the "
                   "region's border twice, with nodes outside it at both ends): the fairing only "
                   "smooths the region by its fairness energy; ";
      if (!has_border_inside_the_mesh(mesh, region)) {
        std::cout << "the region has no border inside the mesh (it holds all of each part of "
                     "the mesh it touches";
        if (o.region_file.empty())
          std::cout << "; --radius " << radius << ", the bounding box diagonal is " << diagonal;
        std::cout << "): give a region around the defect, with a border\n";
      } else
        std::cout << "lights closer together (--spacing, --lines) or in another direction, or a "
                     "region farther from the mesh's border, put lines across it\n";
    }

    const auto start = std::chrono::steady_clock::now();
    auto progress = [](const HL::Fairing_report::Iteration& it) {
      std::cout << "  iteration: q_fair " << it.fairness_energy << ", q_diff "
                << it.difference_energy << ", max |x| / mean edge " << it.relative_max_displacement
                << ", lines targeted " << it.lines_targeted;
      if (it.restrained_vertices > 0)
        std::cout << ", " << it.restrained_vertices << " vertices held back against flips";
      if (it.extrapolation > 1)
        std::cout << ", slow tail extrapolated (step x " << it.extrapolation << ")";
      std::cout << "\n";
      return true;
    };
    const HL::Fairing_report report = CGAL::fair_with_highlight_lines(
        mesh, region, lights,
        HLP::combine(CGAL::parameters::number_of_iterations(o.iterations),
                     HLP::fairing_visitor(progress), HLP::fairness_energy(o.energy)));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::size_t restrained = 0;
    for (const auto& it : report.history)
      restrained = (std::max)(restrained, it.restrained_vertices);
    std::cout << HL::to_string(report.status) << " after " << report.iterations << " iterations in "
              << seconds << " s; " << report.number_of_movable_vertices << " movable vertices, "
              << report.number_of_lines_targeted << " lines targeted ("
              << report.number_of_two_segment_targets << " two-segment), "
              << report.number_of_lines_without_target << " without target\n";
    if (report.number_of_folded_triangles > 0 && o.energy == HL::Fairness_energy::WILLMORE)
      std::cout << "note: " << report.number_of_folded_triangles
                << " triangles of the region are folded; their tangential curvature dominates "
                   "the Willmore energy: try --mean-curvature\n";
    else if (report.number_of_sliver_triangles > 0 && o.energy == HL::Fairness_energy::WILLMORE)
      std::cout << "note: " << report.number_of_sliver_triangles
                << " triangles of the region have a corner below 5 degrees; if the faired "
                   "surface bends away from its surroundings, try --mean-curvature\n";
    // A vertex moves only if its two-ring lies in the region: a region a few edges wide, as
    // the default radius gives on a coarse mesh, leaves the fairing almost nothing to move.
    if (report.number_of_movable_vertices < few_movable_vertices)
      std::cout << "note: only " << report.number_of_movable_vertices
                << " movable vertices (a vertex moves if its two-ring lies in the region): "
                << (o.region_file.empty() ? "a larger --radius (now " + std::to_string(radius) + ")"
                                          : std::string("a larger region"))
                << " gives the fairing room\n";
    if (restrained > 0)
      std::cout << "up to " << restrained << " vertices per step were held back where moving "
                << "them would have flipped a triangle\n";
    // A crumpled triangulation (a raw scan): moving vertices along their normals cannot
    // untangle folded triangles, so F stops falling while vertices are held back.
    if (report.status == HL::Fairing_report::Status::STALLED) {
      std::cout << "note: F stopped falling over five steps that held vertices back against flips";
      if (report.number_of_folded_triangles + report.number_of_sliver_triangles > 0)
        std::cout << "; " << report.number_of_folded_triangles
                  << " triangles of the region are folded and " << report.number_of_sliver_triangles
                  << " have a corner below 5 degrees: moving vertices along their normals "
                     "cannot untangle such a triangulation";
      std::cout << "\n";
    }
    if (report.returned_best_iterate)
      std::cout << "the mesh is the iterate of lowest F, not the last one\n";
    if (report.restarted_from_fill)
      std::cout << "the first run (" << report.first_run_iterations
                << " iterations) ended held back against flips or without lowering F; the "
                   "mesh returned is from a second run, started from the region filled by "
                   "PMP::fair (uniform bi-Laplacian)\n";
    if (!report.history.empty())
      std::cout << "target F = w1 q_fair + w2 q_diff: " << report.history.front().target_value
                << " -> " << report.history.back().target_value << "\n";

    const pic::Image after = picture(mesh, region, lights, levels, desired, o);
    pic::Layout layout;
    layout.title = "Fairing with highlight lines";
    const pic::Image both =
        pic::side_by_side({before, after},
                          {dent != 0 ? "before: a dent pressed into the surface" : "before",
                           "after " + std::to_string(report.iterations) + " iterations"},
                          layout);
    if (!pic::write_png(o.out + ".png", both) ||
        !mesh_io::write_mesh(o.out + "_faired" + mesh_io::output_extension(o.mesh, o.format),
                             mesh)) {
      std::cerr << "fair_with_highlight_lines: cannot write the output files\n";
      return 1;
    }
    std::cout << "wrote " << o.out << ".png and " << o.out << "_faired"
              << mesh_io::output_extension(o.mesh, o.format) << " (blue: the desired "
              << "highlight lines; tinted: the region)\n";
  } catch (const HL::Invalid_input& e) {
    std::cerr << "fair_with_highlight_lines: " << e.what() << "\n";
    return 1;
  } catch (const HL::Fairing_failure& e) {
    std::cerr << "fair_with_highlight_lines: " << e.what() << " (the mesh was left unchanged)\n";
    return 1;
  }
  return 0;
}

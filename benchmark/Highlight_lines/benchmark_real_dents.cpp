// Fairing dents pressed into smooth patches of real meshes: fair_with_highlight_lines() against
// CGAL::Polygon_mesh_processing::fair() and the surface diffusion flow of Xu et al., on the
// same regions, moving the same vertices.
//
//   benchmark_real_dents [--table] [--seed N] [--centres N] [--repetitions N] [--mesh STEM]
//                        [--dump DIR] [--jitter J] [--from-truth] [--far-grid N] [--anywhere N]
//                        [--depths D1,D2,...] [--mesh-file PATH]...
//
// The table mode is the only mode (`--table` is accepted and is the default): one Markdown
// table per case, then two summary tables (one row per method): over all the cases, and over
// the cases of smooth patches only. No Google Benchmark: each case is small
// and the timing is a median of `--repetitions` (3) runs of each method with
// std::chrono::steady_clock, as a ratio to PMP::fair's median on the same case in the same run.
//
// Cases (real_dent_cases.h): for every mesh of HIGHLIGHT_LINES_SHARED_DATA_DIR (beetle, bunny,
// camelhead, fandisk, rocker-arm, spot; missing files are skipped with a message), up to
// `--centres` (3) centres drawn with the fixed seed (`--seed`, 2026), each dented to depths 1 ē
// and 0.3 ē (`--depths`, a comma-separated list in ē: e.g. 5,3 for pits as deep as the dent's
// radius of 5 ē); the region is the faces within 8 ē of the centre, the lights cross it with about
// 10 lines. The centres are in smooth patches (largest dihedral <= 25°, face normals within 45°
// of the lights' normal) where the mesh has them; a mesh with fewer is filled up with its
// smoothest rough patches (face normals within 75°), so that every mesh gives cases. The case
// header says which (`patch smooth` / `patch rough`), and so does the `patches` column of the
// summaries. `--dump DIR` writes each case's dented and undented mesh
// (DIR/<case>_input.off, DIR/<case>_truth.off) and region (DIR/<case>_region.txt, face
// indices).
//
// Meshes the team does not have: `--mesh-file PATH` (repeatable) replaces the shared meshes by
// the given files, read as the command-line programs read a user's file
// (mesh_io::read_triangle_mesh(): OFF, OBJ, PLY, STL; soups repaired, polygons triangulated,
// degenerate faces removed, each said on stderr), named by their file name without its
// extension, in both modes.
//
// Large meshes: `--far-grid N` adds to each case's mesh (dented and undented) a grid of 2 N²
// triangles beyond its bounding box, far from every region: a fairing's time should not grow
// with the mesh around the region (a car body has 10^6 faces).
//
// Scan-like triangulations: `--jitter J` (default 0: no jitter, the cases above bit for bit)
// moves every vertex of each mesh tangentially, by a random vector of length up to J ē_g (ē_g
// the mesh's mean edge length) in the plane orthogonal to its vertex normal, drawn from a
// std::mt19937 seeded from `--seed` independently of the centres (jitter_tangentially() of
// real_dent_cases.h). The centres and regions are chosen on the unjittered mesh (its smooth
// patches; `patch smooth` refers to it), everything else (ē, the lights, the dent, the largest
// dihedral and normal angles shown) on the jittered mesh, which is also the truth. At J = 0.3
// to 0.45 the regions hold slivers with corners of a few degrees and folded triangles, as
// scanned meshes do. Every case header ends with the triangles of the region of the dented
// input: the smallest corner angle, the number of triangles with a corner below 5° and the
// number of folded triangles (a face whose normal has a non-positive dot product with the sum
// of its corners' unit vertex normals). A line after the summaries gives the extremes over all
// the cases.
//
// The floor: `--from-truth` runs every method on the undented mesh instead (same region, same
// lights), measured against the same truth: how far each method moves a surface that has no
// dent. A method that ends at its floor on the dented input has removed the whole dent; what
// remains is the distance between the fair surface it settles on and the real surface.
//
// The floor anywhere: `--anywhere N` replaces the table by one row per mesh: N seeded vertices
// (`--seed`), anywhere on the mesh (rough, curved and creased parts included), each the centre
// of the faces within 10 rings, faired as they are (no dent, the default light setup of the
// whole mesh with 30 lines) by ours (the default), ours_willmore and pmp_fair. Every move is a
// change nobody asked for: the row gives the medians of the RMS move of the movable vertices in
// ē (the mesh's mean edge length), the regions where ours moves more than pmp_fair, and the tail:
// the regions where ours' largest move exceeds both 2 ē and twice pmp_fair's.
//
// Methods, each on a fresh copy of the dented mesh:
//   pmp_fair     CGAL::Polygon_mesh_processing::fair(mesh, movable vertices), default
//                parameters (bi-Laplacian, cotangent weights; continuity 1)
//   pmp_fair_c2  the same with fairing_continuity(2) (tri-Laplacian: curvature-continuous)
//   xu_flow      surface_diffusion_flow.h with its default options (as benchmark_fairing.cpp)
//   ours          CGAL::fair_with_highlight_lines(mesh, region, lights), default parameters
//                 (the curvature variation energy)
//   ours_mc       the same with fairness_energy(Fairness_energy::MEAN_CURVATURE)
//   ours_willmore the same with fairness_energy(Fairness_energy::WILLMORE), the paper's
// The movable vertices are HL::movable_vertices() of the region (fair_with_highlight_lines()'s
// definition).
//
// Columns:
//   produced   whether the method produced a mesh; if not, the reason (the exception's what():
//              HL::Invalid_input, HL::Fairing_failure or another std::exception, or PMP::fair
//              returning false)
//   status     ours: HL::to_string(report.status) (CONVERGED, ITERATION_LIMIT, STEP_BLOCKED,
//              STALLED, ...), "(refilled)" where it ran again from PMP::fair's fill of the region
//              (Fairing_report::restarted_from_fill); conv: report.converged(), xu_flow: its
//              convergence flag; pmp_fair: its return value
//   iters      iterations (pmp_fair: 1); the summaries give the median and the maximum
//   fact       sparse factorisations: ours, the QP solver's summed over the iterations
//              (Box_QP_report::factorizations); pmp_fair, one LU; xu_flow, one LU per step;
//              the summaries give the median
//   rms/depth  RMS distance of the movable vertices to the undented surface / dent depth
//              (fairing_quality.h); the `input` row is the dented input (doing nothing)
//   dev/ē      RMS distance of the highlight nodes inside the region to the undented surface's
//              lines of the same light (deviation_from_reference), in ē; on the row "desired",
//              of the desired (OGH) lines of the mesh the methods start from
//              (targets_from_reference): where a fairing that met them exactly would end
//   willmore   discrete Willmore energy of the region (Σ A‖K‖², fairing_quality.h)
//   flips      faces whose normal turned by more than 90° from the dented input; "(k folded)":
//              k of them were folded in the input (unfolding one counts as a flip)
//   outside    vertices outside the movable set that moved (bit-exact comparison)
//   ms, x pmp  median time of the method and its ratio to PMP::fair's median
#include "fairing_quality.h"
#include "mesh_io.h"
#include "real_dent_cases.h"
#include "surface_diffusion_flow.h"

#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/Highlight_lines/fairing_building_blocks.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/fair_with_highlight_lines.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {
typedef Highlight_lines_benchmark::Dent_mesh Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;
namespace HB = Highlight_lines_benchmark;

enum Method {
  PMP_FAIR,
  PMP_FAIR_C2,
  XU_FLOW,
  OURS,
  OURS_MEAN_CURVATURE,
  OURS_WILLMORE,
  NUMBER_OF_METHODS
};
const char* method_names[] = {"pmp_fair", "pmp_fair_c2", "xu_flow",
                              "ours",     "ours_mc",     "ours_willmore"};

struct Options
{
  std::uint32_t seed = 2026;
  std::size_t centres = 3;
  int repetitions = 3;
  std::string only_mesh, dump_dir;
  double jitter = 0; // in ē_g
  bool from_truth = false;
  int far_grid = 0;                        // cells per side of the grid added far away
  std::size_t anywhere = 0;                // regions per mesh of the --anywhere mode (0: the table)
  std::vector<double> depths = {1.0, 0.3}; // in ē
  std::vector<std::string> mesh_files;     // --mesh-file: instead of the shared meshes
};

// The meshes to run on, as (name, path): the shared meshes, or the --mesh-file ones.
std::vector<std::pair<std::string, std::string>> mesh_sources(const Options& options)
{
  std::vector<std::pair<std::string, std::string>> sources;
  if (options.mesh_files.empty())
    for (const std::string stem : HB::shared_mesh_stems())
      sources.emplace_back(stem, test::shared_data(stem + ".off"));
  for (const std::string& path : options.mesh_files) {
    const std::size_t slash = path.find_last_of("/\\");
    std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    name = name.substr(0, name.find_last_of('.'));
    sources.emplace_back(name, path);
  }
  if (!options.only_mesh.empty())
    sources.erase(
        std::remove_if(sources.begin(), sources.end(),
                       [&](const auto& source) { return source.first != options.only_mesh; }),
        sources.end());
  return sources;
}

// Reads the mesh of a source of mesh_sources(); false if it cannot. The cases need compact
// indices (the programs' reader keeps the ids of triangulated polygons, leaving removed ones).
bool read_source(const Options& options, const std::string& name, const std::string& path,
                 Mesh& mesh)
{
  if (options.mesh_files.empty())
    return test::read_shared_mesh(name + ".off", mesh);
  if (!mesh_io::read_triangle_mesh(path, mesh, std::cerr))
    return false;
  mesh.collect_garbage();
  return true;
}

// Appends an n x n grid of triangles beyond the bounding box of `mesh` (faces and vertices get
// the next indices: the regions stay valid).
void add_far_grid(Mesh& mesh, int n)
{
  const auto box = CGAL::Polygon_mesh_processing::bbox(mesh);
  const double size = (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), 1e-3});
  std::vector<vertex_descriptor> grid;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      grid.push_back(mesh.add_vertex(Mesh::Point(box.xmax() + size * (1 + double(i) / n),
                                                 box.ymin() + size * double(j) / n, box.zmax())));
  auto at = [&](int i, int j) { return grid[std::size_t(i * (n + 1) + j)]; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
}

// One method (or the input / truth) on one case.
struct Outcome
{
  bool produced = false;
  std::string reason;
  bool converged = false;
  std::string status; // ours only
  std::size_t iterations = 0, factorizations = 0;
  double seconds = 0, x_pmp = 0; // medians; x_pmp <= 0: not available
  double rms_depth = 0, line_deviation = 0, willmore = 0;
  std::size_t flips = 0, outside_moved = 0;
  std::size_t flips_of_folded = 0; // of `flips`, faces folded in the dented input
};

struct Run
{
  bool produced = true;
  std::string reason;
  bool converged = false;
  std::string status;
  std::size_t iterations = 0, factorizations = 0;
};

Run run_method(Method method, const HB::Real_dent_case& c,
               const std::vector<vertex_descriptor>& movable, Mesh& mesh)
{
  Run run;
  switch (method) {
  case PMP_FAIR:
  case PMP_FAIR_C2:
    run.iterations = 1;
    run.factorizations = 1;
    run.converged = CGAL::Polygon_mesh_processing::fair(
        mesh, movable, CGAL::parameters::fairing_continuity(method == PMP_FAIR ? 1u : 2u));
    if (!run.converged) {
      run.produced = false;
      run.reason = "PMP::fair returned false";
    }
    break;
  case XU_FLOW: {
    const HB::Surface_diffusion_flow_report r = HB::surface_diffusion_flow(mesh, c.region);
    run.iterations = r.iterations;
    run.factorizations = r.iterations;
    run.converged = r.converged;
    break;
  }
  default: {
    const HL::Fairing_report r =
        method == OURS ? CGAL::fair_with_highlight_lines(mesh, c.region, c.lights)
                       : CGAL::fair_with_highlight_lines(
                             mesh, c.region, c.lights,
                             HLP::fairness_energy(method == OURS_MEAN_CURVATURE
                                                      ? HL::Fairness_energy::MEAN_CURVATURE
                                                      : HL::Fairness_energy::WILLMORE));
    run.iterations = r.iterations;
    for (const HL::Fairing_report::Iteration& step : r.history)
      run.factorizations += step.solver.factorizations;
    run.status =
        std::string(HL::to_string(r.status)) + (r.restarted_from_fill ? " (refilled)" : "");
    run.converged = r.converged();
    break;
  }
  }
  return run;
}

double median(std::vector<double> v)
{
  if (v.empty())
    return std::nan("");
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// `folded`: the faces of the region folded in the dented input; `start`: the mesh the method
// started from (flips and moves are counted against it).
void measure(Outcome& o, const HB::Real_dent_case& c, const HB::Region_info<Mesh>& info,
             const std::vector<vertex_descriptor>& movable,
             const std::vector<Mesh::Face_index>& folded, const Mesh& mesh, const Mesh& start)
{
  o.rms_depth = HB::rms_distance_to_surface(mesh, c.truth, info) / c.dent_depth;
  o.line_deviation =
      HB::deviation_from_reference(mesh, c.truth, info, c.lights).rms / c.mean_edge_length;
  o.willmore = HB::willmore_energy_in_region(mesh, info);
  o.flips = HB::count_flipped_faces(mesh, start);
  o.flips_of_folded = HB::count_flipped_faces(mesh, start, folded);
  o.outside_moved = HB::count_moved_vertices_outside(mesh, start, movable);
}

// Runs `method` `repetitions` times on fresh copies of the dented mesh (stopping at the first
// failure) and measures the last result.
Outcome evaluate(Method method, const HB::Real_dent_case& c, const HB::Region_info<Mesh>& info,
                 const std::vector<vertex_descriptor>& movable, const std::string& movable_error,
                 const std::vector<Mesh::Face_index>& folded, int repetitions, bool from_truth)
{
  Outcome o;
  if ((method == PMP_FAIR || method == PMP_FAIR_C2) && !movable_error.empty()) {
    o.reason = "no movable vertices: " + movable_error;
    return o;
  }
  std::vector<double> times;
  Mesh result;
  Run run;
  for (int rep = 0; rep < repetitions; ++rep) {
    Mesh mesh = from_truth ? c.truth : c.input;
    try {
      const auto start = std::chrono::steady_clock::now();
      run = run_method(method, c, movable, mesh);
      times.push_back(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    } catch (const HL::Invalid_input& e) {
      run = Run();
      run.produced = false;
      run.reason = std::string("Invalid_input: ") + e.what();
    } catch (const HL::Fairing_failure& e) {
      run = Run();
      run.produced = false;
      run.reason = "Fairing_failure (after " + std::to_string(e.report().iterations) +
                   " iterations): " + e.what();
    } catch (const std::exception& e) {
      run = Run();
      run.produced = false;
      run.reason = std::string("exception: ") + e.what();
    }
    if (!run.produced)
      break;
    result = std::move(mesh);
  }
  o.produced = run.produced;
  o.reason = run.reason;
  o.converged = run.converged;
  o.status = run.status;
  o.iterations = run.iterations;
  o.factorizations = run.factorizations;
  if (!o.produced)
    return o;
  o.seconds = median(times);
  measure(o, c, info, movable, folded, result, from_truth ? c.truth : c.input);
  return o;
}

std::string fixed(double x, int digits)
{
  if (!std::isfinite(x))
    return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, x);
  return buffer;
}

std::string general(double x)
{
  if (!std::isfinite(x))
    return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.4g", x);
  return buffer;
}

// "1, 0.3 and 5": the dent depths, for the title.
std::string depth_list(const std::vector<double>& depths)
{
  std::string list;
  for (std::size_t i = 0; i < depths.size(); ++i)
    list += (i == 0 ? "" : i + 1 == depths.size() ? " and " : ", ") + general(depths[i]);
  return list;
}

// Markdown cells must not contain '|' or new lines.
std::string cell(std::string s)
{
  for (char& ch : s)
    if (ch == '|' || ch == '\n')
      ch = ch == '|' ? '/' : ' ';
  return s;
}

// A flip count, with the flips of faces folded in the input if any.
std::string flips_text(std::size_t flips, std::size_t of_folded)
{
  return std::to_string(flips) +
         (of_folded > 0 ? " (" + std::to_string(of_folded) + " folded)" : std::string());
}

struct Summary
{
  std::size_t cases = 0, produced = 0, converged = 0, flips = 0, flips_of_folded = 0, outside = 0,
              worse_than_input = 0;
  std::vector<double> iterations, factorizations, rms_depth, line_deviation, x_pmp;
};

void print_case(std::ostream& out, const HB::Real_dent_case& c, const HB::Region_info<Mesh>& info,
                const std::vector<vertex_descriptor>& movable, const std::string& movable_error,
                const HB::Region_triangle_quality& quality, const Outcome& input,
                const Outcome& truth, double desired_deviation,
                const std::vector<Outcome>& outcomes)
{
  const double e = c.mean_edge_length;
  // Dented vertices that no method may move, and the largest of their displacements.
  std::size_t dented_not_movable = 0;
  double largest_fixed_displacement = 0;
  for (vertex_descriptor v : c.dented_vertices)
    if (std::find(movable.begin(), movable.end(), v) == movable.end()) {
      ++dented_not_movable;
      largest_fixed_displacement =
          (std::max)(largest_fixed_displacement,
                     std::sqrt(CGAL::squared_distance(c.input.point(v), c.truth.point(v))));
    }
  std::set<long long> levels;
  std::string levels_text;
  try {
    levels = HB::levels_in_region(c.truth, c.region, c.lights);
    levels_text = std::to_string(levels.size()) +
                  (levels.empty() ? std::string()
                                  : " (" + std::to_string(*levels.begin()) + " to " +
                                        std::to_string(*levels.rbegin()) + ")");
  } catch (const std::exception& ex) {
    levels_text = std::string("error: ") + ex.what();
  }
  out << "\n### " << c.name << "\n\n"
      << num_vertices(c.input) << " vertices; centre v" << std::size_t(c.centre) << "; region "
      << c.region.size() << " faces, radius " << fixed(c.region_radius / e, 2) << " ē, "
      << movable.size() << " movable vertices"
      << (movable_error.empty() ? std::string() : " (movable_vertices(): " + movable_error + ")")
      << (movable.size() == info.movable.size()
              ? std::string()
              : " (fairing_quality.h counts " + std::to_string(info.movable.size()) + ")")
      << "; " << c.dented_vertices.size() << " dented vertices, " << dented_not_movable
      << " of them not movable"
      << (dented_not_movable > 0
              ? " (displaced by at most " + fixed(largest_fixed_displacement / c.dent_depth, 4) +
                    " depth)"
              : std::string())
      << "; ē = " << general(e) << ", depth " << fixed(c.dent_depth / e, 2) << " ē; patch "
      << (c.smooth ? "smooth" : "rough")
      << (c.jitter > 0 ? std::string(" (chosen before the jitter)") : std::string())
      << ": largest dihedral " << fixed(c.max_dihedral_degrees, 1) << "°, largest normal angle "
      << fixed(c.max_normal_angle_degrees, 1) << "°; light spacing "
      << fixed(CGAL::to_double(c.lights.spacing()) / e, 2) << " ē, light levels in the region "
      << levels_text << "; region triangles (input): smallest corner "
      << fixed(quality.smallest_corner_degrees, 2) << "°, " << quality.slivers << " below 5°, "
      << quality.folded.size() << " folded"
      << "\n\n";
  out << "| method | produced | status | conv | iters | fact | rms/depth | dev/ē | willmore | "
         "flips | outside | ms | x pmp | reason |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  // `outside` is not shown for the truth: there it counts the dented vertices not movable.
  auto row = [&](const char* name, const Outcome& o, bool timed) {
    const bool truth_row = std::strcmp(name, "truth") == 0;
    out << "| " << name << " | " << (o.produced ? "yes" : "no") << " | " << o.status << " | "
        << (timed && o.produced ? (o.converged ? "yes" : "no") : "") << " | "
        << (timed && o.produced ? std::to_string(o.iterations) : "") << " | "
        << (timed && o.produced ? std::to_string(o.factorizations) : "") << " | "
        << (o.produced ? fixed(o.rms_depth, 4) : "") << " | "
        << (o.produced ? fixed(o.line_deviation, 4) : "") << " | "
        << (o.produced ? general(o.willmore) : "") << " | "
        << (o.produced ? flips_text(o.flips, o.flips_of_folded) : "") << " | "
        << (o.produced && !truth_row ? std::to_string(o.outside_moved) : "") << " | "
        << (timed && o.produced ? fixed(1000 * o.seconds, 1) : "") << " | "
        << (timed && o.produced && o.x_pmp > 0 ? fixed(o.x_pmp, 2) : "") << " | " << cell(o.reason)
        << " |\n";
  };
  row("input", input, false);
  row("truth", truth, false);
  out << "| desired | | | | | | | " << fixed(desired_deviation, 4) << " | | | | | | |\n";
  for (int m = 0; m < NUMBER_OF_METHODS; ++m)
    row(method_names[m], outcomes[std::size_t(m)], true);
}

void add_to_summary(Summary& s, const Outcome& o, const Outcome& input)
{
  ++s.cases;
  if (!o.produced)
    return;
  ++s.produced;
  s.worse_than_input += o.rms_depth > input.rms_depth ? 1 : 0;
  s.converged += o.converged ? 1 : 0;
  s.iterations.push_back(double(o.iterations));
  s.factorizations.push_back(double(o.factorizations));
  s.rms_depth.push_back(o.rms_depth);
  s.line_deviation.push_back(o.line_deviation);
  if (o.x_pmp > 0)
    s.x_pmp.push_back(o.x_pmp);
  s.flips += o.flips;
  s.flips_of_folded += o.flips_of_folded;
  s.outside += o.outside_moved;
}

// `patches`: the cases summarised ("all", "smooth", "1 ē", "0.3 ē").
void print_summary(std::ostream& out, const char* patches,
                   const std::map<std::string, Summary>& summaries)
{
  out << "\n### Summary, " << patches
      << " patches (medians over the cases where the method produced a mesh)\n\n"
      << "| method | patches | cases | produced % | converged % | median iters | max iters | "
         "median fact | median rms/depth | median dev/ē | median x pmp | total flips | any outside "
         "moved | "
         "rms > input |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const char* name : {"input", "desired", "pmp_fair", "pmp_fair_c2", "xu_flow", "ours",
                           "ours_mc", "ours_willmore"}) {
    auto it = summaries.find(name);
    if (it == summaries.end())
      continue;
    const Summary& s = it->second;
    if (std::strcmp(name, "desired") == 0) {
      out << "| desired | " << patches << " | " << s.cases << " | | | | | | | "
          << fixed(median(s.line_deviation), 4) << " | | | | |\n";
      continue;
    }
    const bool is_input = std::strcmp(name, "input") == 0;
    const double n = double((std::max)(s.cases, std::size_t(1)));
    out << "| " << name << " | " << patches << " | " << s.cases << " | "
        << fixed(100.0 * double(s.produced) / n, 0) << " | "
        << (is_input ? "" : fixed(100.0 * double(s.converged) / n, 0)) << " | "
        << (is_input ? "" : fixed(median(s.iterations), 1)) << " | "
        << (is_input || s.iterations.empty() ? ""
                                             : std::to_string(std::size_t(*std::max_element(
                                                   s.iterations.begin(), s.iterations.end()))))
        << " | " << (is_input ? "" : fixed(median(s.factorizations), 1)) << " | "
        << fixed(median(s.rms_depth), 4) << " | " << fixed(median(s.line_deviation), 4) << " | "
        << (is_input ? "" : fixed(median(s.x_pmp), 2)) << " | "
        << flips_text(s.flips, s.flips_of_folded) << " | "
        << (is_input ? "" : (s.outside > 0 ? "YES (" + std::to_string(s.outside) + ")" : "no"))
        << " | " << (is_input ? "" : std::to_string(s.worse_than_input)) << " |\n";
  }
}

void print_legend(std::ostream& out)
{
  out << "\n(patches: all the cases, or those of smooth patches only (largest dihedral <= 25°, "
         "normals within 45° of the lights' normal; the others are the smoothest rough patches "
         "of meshes with too few smooth ones); rms/depth: RMS distance of the movable vertices "
         "to the undented surface / dent depth; dev/ē: RMS distance of the highlight nodes "
         "inside the region to the undented surface's lines, in local mean edge lengths (desired: "
         "of the desired lines' points); fact: "
         "sparse factorisations (ours: the QP solver's over all iterations; pmp_fair: one LU; "
         "xu_flow: one LU per step); x pmp: "
         "median time / PMP::fair's median time on the same case; rms > input: cases where the "
         "method ended further from the undented surface than the dented input; status: "
         "HL::to_string(Fairing_report::Status), conv: converged)\n";
}

void dump_case(const std::string& dir, const HB::Real_dent_case& c)
{
  CGAL::IO::write_polygon_mesh(dir + "/" + c.name + "_input.off", c.input,
                               CGAL::parameters::stream_precision(17));
  CGAL::IO::write_polygon_mesh(dir + "/" + c.name + "_truth.off", c.truth,
                               CGAL::parameters::stream_precision(17));
  std::ofstream region(dir + "/" + c.name + "_region.txt");
  for (auto f : c.region)
    region << std::size_t(f) << "\n";
  // Base point, direction, plane normal, spacing: what the main program's --base --direction
  // --normal --spacing take.
  std::ofstream lights(dir + "/" + c.name + "_lights.txt");
  lights.precision(17);
  lights << c.lights.base_point() << " " << c.lights.light_direction() << " "
         << c.lights.plane_normal() << " " << c.lights.spacing() << "\n";
}

bool parse(int argc, char** argv, Options& options)
{
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << "benchmark_real_dents: " << a << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--table")
      continue;
    if (a == "--seed")
      options.seed = std::uint32_t(std::stoul(value()));
    else if (a == "--centres")
      options.centres = std::size_t(std::stoul(value()));
    else if (a == "--repetitions")
      options.repetitions = (std::max)(1, std::stoi(value()));
    else if (a == "--mesh")
      options.only_mesh = value();
    else if (a == "--dump")
      options.dump_dir = value();
    else if (a == "--jitter")
      options.jitter = std::stod(value());
    else if (a == "--from-truth")
      options.from_truth = true;
    else if (a == "--far-grid")
      options.far_grid = std::stoi(value());
    else if (a == "--mesh-file")
      options.mesh_files.push_back(value());
    else if (a == "--anywhere")
      options.anywhere = std::size_t(std::stoul(value()));
    else if (a == "--depths") {
      options.depths.clear();
      std::stringstream list(value());
      for (std::string depth; std::getline(list, depth, ',');)
        options.depths.push_back(std::stod(depth));
      if (options.depths.empty() || !std::all_of(options.depths.begin(), options.depths.end(),
                                                 [](double d) { return d > 0; })) {
        std::cerr << "benchmark_real_dents: --depths needs positive depths, e.g. 1,0.3\n";
        return false;
      }
    } else {
      std::cerr << "usage: benchmark_real_dents [--table] [--seed N] [--centres N] "
                   "[--repetitions N] [--mesh STEM] [--dump DIR] [--jitter J] [--from-truth] "
                   "[--far-grid N] [--anywhere N] [--depths D1,D2,...] [--mesh-file PATH]...\n";
      return false;
    }
  }
  return true;
}

// --anywhere N: the undented regions of every mesh (see the file comment).
void run_anywhere(std::ostream& out, const Options& options)
{
  out << "# Undented regions anywhere (" << options.anywhere
      << " per mesh, faces within 10 rings of a seeded vertex, seed " << options.seed
      << "): RMS move of the movable vertices / ē, medians\n\n"
      << "| mesh | regions | ours | pmp_fair | ours_willmore | ours moves more than pmp_fair | "
         "tail: ours > 2 ē and > 2 x pmp_fair | ours' largest move / ē |\n"
      << "|---|---|---|---|---|---|---|---|\n";
  for (const auto& [stem, path] : mesh_sources(options)) {
    Mesh mesh;
    if (!read_source(options, stem, path, mesh)) {
      out << "| " << stem << " | cannot read " << path << " | | | | | | |\n";
      continue;
    }
    const double e = test::mean_edge_length(mesh);
    const auto lights = HL::default_light_setup(mesh, HLP::number_of_lines(30));
    std::vector<double> ours_rms, pmp_rms, willmore_rms;
    std::size_t more = 0, tail = 0;
    double largest = 0;
    for (const vertex_descriptor centre :
         HB::seeded_vertices(mesh, options.anywhere, options.seed)) {
      const std::vector<Mesh::Face_index> region = HB::faces_within_rings(mesh, centre, 10);
      std::vector<vertex_descriptor> movable;
      HL::movable_vertices(mesh, region, std::back_inserter(movable));
      if (movable.empty())
        continue;
      Mesh ours = mesh, willmore = mesh, pmp = mesh;
      try {
        CGAL::fair_with_highlight_lines(ours, region, lights);
        CGAL::fair_with_highlight_lines(willmore, region, lights,
                                        HLP::fairness_energy(HL::Fairness_energy::WILLMORE));
      } catch (const std::exception& ex) {
        out << "| " << stem << " | v" << std::size_t(centre) << ": " << ex.what()
            << " | | | | | | |\n";
        continue;
      }
      CGAL::Polygon_mesh_processing::fair(pmp, movable);
      double sums[3] = {0, 0, 0}, largest_ours = 0, largest_pmp = 0;
      for (vertex_descriptor v : movable) {
        const double moves[3] = {CGAL::squared_distance(mesh.point(v), ours.point(v)),
                                 CGAL::squared_distance(mesh.point(v), pmp.point(v)),
                                 CGAL::squared_distance(mesh.point(v), willmore.point(v))};
        for (int m = 0; m < 3; ++m)
          sums[m] += moves[m];
        largest_ours = (std::max)(largest_ours, std::sqrt(moves[0]));
        largest_pmp = (std::max)(largest_pmp, std::sqrt(moves[1]));
      }
      const double n = double(movable.size());
      ours_rms.push_back(std::sqrt(sums[0] / n) / e);
      pmp_rms.push_back(std::sqrt(sums[1] / n) / e);
      willmore_rms.push_back(std::sqrt(sums[2] / n) / e);
      more += sums[0] > sums[1] ? 1 : 0;
      tail += largest_ours > 2 * e && largest_ours > 2 * largest_pmp ? 1 : 0;
      largest = (std::max)(largest, largest_ours / e);
    }
    out << "| " << stem << " | " << ours_rms.size() << " | " << fixed(median(ours_rms), 3) << " | "
        << fixed(median(pmp_rms), 3) << " | " << fixed(median(willmore_rms), 3) << " | " << more
        << " | " << tail << " | " << fixed(largest, 2) << " |\n";
    out.flush();
  }
}

} // namespace

int main(int argc, char** argv)
{
  Options options;
  try {
    if (!parse(argc, argv, options))
      return 2;
  } catch (const std::logic_error&) { // std::stoi / std::stod: not a number, or out of range
    std::cerr << "benchmark_real_dents: an option's value is not a number in range (see "
                 "--help)\n";
    return 2;
  }
  if (options.anywhere > 0) {
    run_anywhere(std::cout, options);
    return 0;
  }
  const auto start = std::chrono::steady_clock::now();
  std::ostream& out = std::cout;
  out << "# Dents in real meshes (seed " << options.seed << ", up to " << options.centres
      << " centres per mesh, depths " << depth_list(options.depths) << " ē, median of "
      << options.repetitions << " runs"
      << (options.jitter > 0 ? "; tangential jitter up to " + general(options.jitter) + " ē_g"
                             : std::string())
      << ")\n";
  std::map<std::string, Summary> summaries, smooth_summaries, deep_summaries, shallow_summaries;
  HB::Real_dent_options dent_options;
  dent_options.max_centres = options.centres;
  dent_options.jitter = options.jitter;
  dent_options.depths = options.depths;
  // The extremes of the region triangles over all the cases (of their dented inputs).
  double smallest_corner = 180;
  std::string smallest_corner_case;
  std::size_t cases_total = 0, cases_with_slivers = 0, cases_with_folds = 0, most_slivers = 0,
              most_folded = 0;
  std::string most_slivers_case, most_folded_case;
  for (const auto& [stem, path] : mesh_sources(options)) {
    Mesh mesh;
    if (!read_source(options, stem, path, mesh)) {
      out << "\n## " << stem << ": cannot read " << path << ", skipped\n";
      continue;
    }
    const auto making = std::chrono::steady_clock::now();
    std::vector<HB::Real_dent_case> cases =
        HB::make_real_dent_cases(mesh, stem, options.seed, dent_options);
    if (options.far_grid > 0)
      for (HB::Real_dent_case& c : cases) {
        add_far_grid(c.input, options.far_grid);
        add_far_grid(c.truth, options.far_grid);
      }
    const double making_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - making).count();
    const std::size_t smooth_cases = std::size_t(
        std::count_if(cases.begin(), cases.end(), [](const auto& c) { return c.smooth; }));
    out << "\n## " << stem << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh)
        << " faces; " << cases.size() / dent_options.depths.size() << " patches drawn ("
        << smooth_cases / dent_options.depths.size() << " smooth, "
        << (cases.size() - smooth_cases) / dent_options.depths.size() << " rough), " << cases.size()
        << " cases (made in " << fixed(1000 * making_seconds, 0) << " ms)"
        << (options.jitter > 0
                ? "; jittered tangentially by up to " + general(options.jitter) +
                      " ē_g = " + general(options.jitter * test::mean_edge_length(mesh))
                : std::string())
        << "\n";
    for (const HB::Real_dent_case& c : cases) {
      if (!options.dump_dir.empty())
        dump_case(options.dump_dir, c);
      const HB::Region_info<Mesh> info(c.input, c.region);
      std::vector<vertex_descriptor> movable;
      std::string movable_error;
      try {
        HL::movable_vertices(c.input, c.region, std::back_inserter(movable));
      } catch (const std::exception& e) {
        movable_error = e.what();
        movable = info.movable;
      }
      const HB::Region_triangle_quality quality = HB::region_triangle_quality(c.input, c.region);
      ++cases_total;
      cases_with_slivers += quality.slivers > 0 ? 1 : 0;
      cases_with_folds += quality.folded.empty() ? 0 : 1;
      if (quality.smallest_corner_degrees < smallest_corner) {
        smallest_corner = quality.smallest_corner_degrees;
        smallest_corner_case = c.name;
      }
      if (quality.slivers > most_slivers) {
        most_slivers = quality.slivers;
        most_slivers_case = c.name;
      }
      if (quality.folded.size() > most_folded) {
        most_folded = quality.folded.size();
        most_folded_case = c.name;
      }
      Outcome input, truth;
      input.produced = truth.produced = true;
      measure(input, c, info, movable, quality.folded, c.input, c.input);
      measure(truth, c, info, movable, quality.folded, c.truth, c.truth);
      std::vector<Outcome> outcomes;
      for (int m = 0; m < NUMBER_OF_METHODS; ++m)
        outcomes.push_back(evaluate(Method(m), c, info, movable, movable_error, quality.folded,
                                    options.repetitions, options.from_truth));
      const Outcome& pmp = outcomes[PMP_FAIR];
      for (Outcome& o : outcomes)
        if (o.produced && pmp.produced && pmp.seconds > 0)
          o.x_pmp = o.seconds / pmp.seconds;
      // How far the desired lines of the mesh the methods start from lie from the truth's.
      double desired_deviation = std::nan("");
      try {
        const Mesh& start = options.from_truth ? c.truth : c.input;
        desired_deviation =
            HB::targets_from_reference(c.truth, info, c.lights,
                                       HB::leveled_desired_highlight_lines(start, info, c.lights))
                .rms /
            c.mean_edge_length;
      } catch (const std::exception&) {
        // no desired lines (the fairing refuses the region): "-"
      }
      print_case(out, c, info, movable, movable_error, quality, input, truth, desired_deviation,
                 outcomes);
      out.flush();
      const bool deep = c.dent_depth >= 0.99 * c.mean_edge_length;
      for (auto* s : {&summaries, &smooth_summaries, &deep_summaries, &shallow_summaries}) {
        if ((s == &smooth_summaries && !c.smooth) || (s == &deep_summaries && !deep) ||
            (s == &shallow_summaries && deep))
          continue;
        add_to_summary((*s)["input"], input, input);
        if (std::isfinite(desired_deviation)) {
          ++(*s)["desired"].cases;
          (*s)["desired"].line_deviation.push_back(desired_deviation);
        }
        for (int m = 0; m < NUMBER_OF_METHODS; ++m)
          add_to_summary((*s)[method_names[m]], outcomes[std::size_t(m)], input);
      }
    }
  }
  print_summary(out, "all", summaries);
  print_summary(out, "smooth", smooth_summaries);
  print_summary(out, "dents of 1 ē or deeper", deep_summaries);
  print_summary(out, "dents shallower than 1 ē", shallow_summaries);
  out << "\n(region triangles of the dented inputs, over the " << cases_total
      << " cases: smallest corner " << fixed(smallest_corner, 2) << "°"
      << (smallest_corner_case.empty() ? std::string() : " (" + smallest_corner_case + ")") << "; "
      << cases_with_slivers << " cases with corners below 5° (most: " << most_slivers
      << (most_slivers_case.empty() ? std::string() : " in " + most_slivers_case) << "); "
      << cases_with_folds << " cases with folded triangles (most: " << most_folded
      << (most_folded_case.empty() ? std::string() : " in " + most_folded_case) << "))\n";
  print_legend(out);
  out << "\n(total time "
      << fixed(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1)
      << " s)\n";
  return 0;
}

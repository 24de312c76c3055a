// Evaluation of detect_highlight_line_irregularities().
//
//   benchmark_detection            speed (Google Benchmark), then the recall/precision curves
//   benchmark_detection --curves   the curves only
//
// Curves: dents and bumps of radius 5 mean edge lengths (ē) and height h·ē, four per mesh,
// injected at random (seeded):
//   - into a smooth car hood, irregularly triangulated (jittered 80 x 80 grid, 12,800
//     triangles), 8 seeds: every region found is either a defect or a false alarm; the same
//     on a regular grid (a CAD tessellation: the lines are straight to the rounding) and on a
//     flat plate (a regular grid);
//   - anywhere into every shared real mesh (see shared_table()): recall, precision counting
//     every region without a defect as false, the rank of the defects, the regions found on
//     the mesh as it is, and time and memory against one compute_highlight_lines().
//
//   benchmark_detection --shared [--seeds N]   the shared meshes only (N x 4 defects/height)
//   benchmark_detection --mesh NAME            one shared mesh
//   benchmark_detection --mesh-file PATH ...   meshes the team does not have instead (repeatable;
//                                              read as the command-line programs read them)
//   benchmark_detection --local [--mesh NAME]  the detection near each defect only
//                                              (face_range: the faces within 3R of it)
//   benchmark_detection ... --bending          the same with HLP::local_residual(false)
//   benchmark_detection ... --scales N         with HLP::number_of_scales(N) (default 1)
//   benchmark_detection ... --defect-regions    each defect's region (kind, size, confidence)
//   benchmark_detection --misses [--mesh NAME]  per defect not located, why (see misses_table())
//   benchmark_detection --repair [--mesh NAME]  what the automatic mode and PMP::fair on the same
//                                              regions do to the defects and to the rest of the
//                                              surface (see repair_table()); then what limits
//                                              the repairs (see repair_limits_table(); not
//                                              with --no-limits)
//   benchmark_detection ... --fairing-margin N  the automatic mode with HLP::fairing_margin(N)
//   benchmark_detection --demo [--bending]     the regions of the demo's --detect mode
//                                              (scripts/demo, part 3: the Beetle with a dent
//                                              in its roof; 60 lines, 3 x 2 light setups)
//
// Speed: the detection (3 x 2 light setups) on the bundled beetle Loop-subdivided twice
// (618,496 triangles), as a ratio to one compute_highlight_lines() on the same mesh measured
// in the same run.
#include "detection_evaluation.h"
#include "mesh_io.h"

#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/compute_highlight_lines.h>
#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/detect_and_fair_highlight_line_irregularities.h>
#include <CGAL/detect_highlight_line_irregularities.h>
#include <CGAL/Highlight_lines/grown_face_region.h>
#include <CGAL/Highlight_lines/join_touching_irregularities.h>

#include "test_meshes.h"

#include <benchmark/benchmark.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <malloc.h>
#include <new>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>

namespace {
namespace HB = Highlight_lines_benchmark;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;

// --- Memory: every allocation of the program counted, the peak since the last reset --------

std::atomic<std::size_t> allocated_bytes{0}, peak_bytes{0};

void* counted_allocation(std::size_t size)
{
  void* p = std::malloc(size == 0 ? 1 : size);
  if (!p)
    throw std::bad_alloc();
  const std::size_t now = allocated_bytes += malloc_usable_size(p);
  std::size_t peak = peak_bytes.load();
  while (now > peak && !peak_bytes.compare_exchange_weak(peak, now)) {
  }
  return p;
}

void counted_free(void* p) noexcept
{
  if (p) {
    allocated_bytes -= malloc_usable_size(p);
    std::free(p);
  }
}

} // namespace

void* operator new(std::size_t size)
{
  return counted_allocation(size);
}
void* operator new[](std::size_t size)
{
  return counted_allocation(size);
}
void operator delete(void* p) noexcept
{
  counted_free(p);
}
void operator delete[](void* p) noexcept
{
  counted_free(p);
}
void operator delete(void* p, std::size_t) noexcept
{
  counted_free(p);
}
void operator delete[](void* p, std::size_t) noexcept
{
  counted_free(p);
}

namespace Highlight_lines_benchmark {
// The peak of the memory allocated with operator new since construction or reset(), above
// what was allocated then.
class Peak_memory
{
public:
  Peak_memory() { reset(); }
  void reset()
  {
    base_ = allocated_bytes.load();
    peak_bytes = base_;
  }
  std::size_t peak() const { return peak_bytes.load() - base_; }

private:
  std::size_t base_ = 0;
};
} // namespace Highlight_lines_benchmark

namespace {

const std::vector<double> heights{1.0, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01};

// --bending: the detection with HLP::local_residual(false), the bending measure (the default
// is the local residual, issue 16).
bool local_residual = true;
// --scales N: the number of detection scales of the local residual (w, 2w, ...).
int scales = 1;
// --defect-regions: the shared table lists the region holding each defect.
bool list_defect_regions = false;

// The named parameters of every detection of this benchmark (the measure and the scales).
auto detection_parameters()
{
  return HLP::number_of_scales(HLP::local_residual(local_residual), scales);
}

// The detection with the default lights (30 lines) and `np`.
template <typename NamedParameters>
std::vector<HB::Irregularity> detect(const HB::Mesh& mesh, const NamedParameters& np)
{
  std::vector<HB::Irregularity> found;
  CGAL::detect_highlight_line_irregularities(
      mesh, HL::default_light_setup(mesh, HLP::number_of_lines(30)), std::back_inserter(found), np);
  return found;
}

std::vector<HB::Irregularity> detect(const HB::Mesh& mesh)
{
  return detect(mesh, detection_parameters());
}

struct Curve_point
{
  std::size_t defects = 0, found = 0, located = 0, regions = 0, true_regions = 0, own = 0;
};

void print_curve(const std::string& name, const std::vector<Curve_point>& points,
                 std::size_t meshes, std::size_t own_before)
{
  std::cout << "\n" << name << " (" << meshes << " meshes";
  if (own_before > 0)
    std::cout << ", " << own_before << " own regions before injection";
  std::cout << ")\n  h/ē     recall  precision  regions  own\n";
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Curve_point& p = points[i];
    const std::size_t judged = p.regions - p.own;
    std::cout << "  " << std::setw(5) << (i < heights.size() ? heights[i] : 0.0) << "  "
              << std::setw(7) << std::fixed << std::setprecision(3)
              << (p.defects ? double(p.found) / double(p.defects) : 1.0) << "  " << std::setw(9)
              << (judged ? double(p.true_regions) / double(judged) : 1.0) << "  " << std::setw(7)
              << p.regions << "  " << std::setw(3) << p.own << std::defaultfloat << "\n";
  }
}

// Four defects per mesh on an 80 x 80 grid over [-1, 1]^2 of `height`, jittered by `jitter`
// of a cell (0: a regular grid, as CAD tessellations often are), 8 seeds.
void grid_curve(const std::string& name, double (*height)(double, double), double jitter)
{
  std::vector<Curve_point> curve(heights.size() + 1);
  for (unsigned seed = 1; seed <= 8; ++seed)
    for (std::size_t i = 0; i <= heights.size(); ++i) {
      HB::Mesh mesh =
          test::to_mesh<HB::Mesh>(test::grid(80, 2.0 / 80, -1, -1, height, jitter, seed));
      std::vector<HB::Injected_defect> defects;
      if (i < heights.size())
        defects = HB::inject_defects(mesh, 4, 5.0, heights[i], seed, [](auto) { return true; });
      const HB::Detection_score s = HB::match(mesh, defects, detect(mesh));
      curve[i].defects += s.defects;
      curve[i].found += s.found_defects;
      curve[i].regions += s.regions;
      curve[i].true_regions += s.true_regions;
    }
  print_curve(name + "; last row: no defect (false alarms)", curve, 8, 0);
}

double flat(double, double)
{
  return 0;
}

// The table on the shared real meshes. Per mesh: the regions found on the mesh as it is (none
// is an injected defect: design, or the mesh's own irregularities), then per height
// h in {1, 0.5, 0.2, 0.1} ē, `seeds` meshes with four defects each (radius 5 ē, dent or bump
// at random, centred on any vertex at least 2R from the border and 3R from each other).
//   recall     defects whose centre vertex lies in a region (compare with the share of the
//              vertices the undented mesh's regions cover, printed above the table);
//   located    defects whose region lies within 3R of the defects it holds (a region over
//              much of the mesh holds defects without locating them);
//   precision  regions holding a defect over all regions (every region without one is false);
//   first      found defects ranked above every region of the same mesh that holds none;
//   >undented  defects whose region ranks above every region found on the undented mesh
//              (missed defects count as failures);
//   rank       mean rank (1 = strongest) of the regions of the found defects;
//   faired     defects located by a region of confidence >= 0.5, which the automatic mode
//              fairs;
//   design faired  regions of confidence >= 0.5 holding no defect (the automatic mode would
//              reshape the design there), summed over the seeds;
//   whole      faired defects that the region the automatic mode fairs can move whole
//              (HB::covered_defects() after HL::join_touching_irregularities() and the fairing
//              margin of detection_scale = 3 rings: every vertex within 0.8 R a movable vertex
//              of the region; --fairing-margin N for N rings).
// Time and memory: the detection on the undented mesh, as ratios to one
// compute_highlight_lines() with the default lights (30 lines) on the same mesh.
struct Table_row
{
  std::size_t defects = 0, found = 0, located = 0, regions = 0, true_regions = 0, first = 0,
              above_undented = 0, rank_sum = 0, faired = 0, design_faired = 0, whole = 0;
};

// Reads the shared mesh `name`, or the mesh at `name` if it is a path (--mesh-file: a mesh the
// team does not have, read as the command-line programs read a user's file); says so and
// returns false if it is missing.
bool read_shared_mesh(const std::string& name, HB::Mesh& mesh)
{
  if (name.find('/') == std::string::npos ? test::read_shared_mesh(name, mesh)
                                          : mesh_io::read_triangle_mesh(name, mesh, std::cerr))
    return true;
  std::cout << "\n" << name << ": not found, skipped\n";
  return false;
}

// What the automatic mode would fair: detect_and_fair_highlight_line_irregularities() fairs the
// regions of at least its default minimum_confidence.
constexpr double minimum_confidence = 0.5;
// The rings of faces the automatic mode adds around a region before fairing it (as
// detect_and_fair_highlight_line_irregularities() does: detection_scale, 3, rounded up).
int fairing_margin = 3;

void shared_table(const std::string& name, unsigned seeds)
{
  HB::Mesh original;
  if (!read_shared_mesh(name, original))
    return;
  const auto lights = HL::default_light_setup(original, HLP::number_of_lines(30));
  HB::Peak_memory memory;
  auto start = std::chrono::steady_clock::now();
  {
    auto model = CGAL::compute_highlight_lines(original, lights, CGAL::Emptyset_iterator(),
                                               HLP::facing_side_only(true));
    benchmark::DoNotOptimize(model.nodes().data());
  }
  const double model_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::size_t model_bytes = memory.peak();
  memory.reset();
  start = std::chrono::steady_clock::now();
  const auto own = detect(original);
  const double detect_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::size_t detect_bytes = memory.peak();

  std::cout << "\n"
            << name << " (" << num_faces(original) << " faces): detection " << std::fixed
            << std::setprecision(2) << detect_seconds << " s = " << std::setprecision(1)
            << detect_seconds / model_seconds << " x compute_highlight_lines(), peak memory "
            << double(detect_bytes) / double((std::max)(model_bytes, std::size_t(1))) << " x ("
            << double(detect_bytes) / 1e6 << " MB)\n"
            << std::defaultfloat << "  undented mesh: " << own.size() << " region(s)";
  std::size_t own_confident = 0;
  for (const auto& r : own) {
    std::cout << " [" << HB::describe(r) << "]";
    own_confident += r.confidence >= minimum_confidence;
  }
  std::cout << "\n  of confidence >= " << minimum_confidence
            << " (faired by the automatic mode): " << own_confident;
  // The recall a defect would get from these regions alone: the share of the vertices they
  // cover (a defect is centred on a vertex at random; the regions on the dented mesh are
  // about the same).
  {
    std::set<HB::vertex_descriptor> covered;
    for (const auto& vs : HB::vertices_of_regions(original, own))
      covered.insert(vs.begin(), vs.end());
    std::cout << "\n  they cover " << std::fixed << std::setprecision(2)
              << double(covered.size()) / double(num_vertices(original))
              << " of the vertices: the recall of a defect centred at random that the detection "
                 "misses"
              << std::defaultfloat;
  }
  std::cout << "\n  h/ē   defects  recall  located  precision  first  >undented  mean rank  regions"
               "  faired  design faired  whole\n";
  for (double h : {1.0, 0.5, 0.2, 0.1}) {
    Table_row row;
    for (unsigned seed = 1; seed <= seeds; ++seed) {
      HB::Mesh mesh = original;
      const auto defects = HB::inject_defects(mesh, 4, 5.0, h, seed, [](auto) { return true; });
      const auto found = detect(mesh);
      const HB::Detection_score s = HB::match(mesh, defects, found);
      row.defects += s.defects;
      row.found += s.found_defects;
      row.regions += s.regions;
      row.true_regions += s.true_regions;
      const auto holds = HB::regions_of_defects(mesh, defects, found);
      const auto genuine = HB::genuine_regions(mesh, defects, found);
      const auto located = HB::located_defects(mesh, defects, found);
      // As the automatic mode fairs them: touching regions of that confidence joined.
      std::vector<HB::Irregularity> joined = found;
      HL::join_touching_irregularities(mesh, joined, minimum_confidence);
      for (auto& r : joined)
        if (r.confidence >= minimum_confidence)
          r.faces = HL::grown_face_region(mesh, r.faces, fairing_margin, 60.0,
                                          get(CGAL::vertex_point, mesh));
      const auto covered = HB::covered_defects(mesh, defects, joined);
      for (std::size_t d = 0; d < defects.size(); ++d) {
        row.located += located[d];
        const bool faired = located[d] && found[holds[d]].confidence >= minimum_confidence;
        row.faired += faired;
        row.whole += faired && covered[d];
      }
      for (std::size_t j = 0; j < found.size(); ++j)
        row.design_faired += !genuine[j] && found[j].confidence >= minimum_confidence;
      for (std::size_t d = 0; d < defects.size(); ++d) {
        const std::size_t r = holds[d];
        if (r == std::size_t(-1))
          continue;
        row.rank_sum += r + 1;
        if (list_defect_regions)
          std::cout << "    h " << h << " seed " << seed << " defect " << d << " rank " << r + 1
                    << " [" << HB::describe(found[r]) << "]\n";
        bool first = true;
        for (std::size_t j = 0; j < found.size(); ++j)
          first = first && (genuine[j] || HB::stronger(found[r], found[j]));
        row.first += first;
        bool above = true;
        for (const auto& o : own)
          above = above && HB::stronger(found[r], o);
        row.above_undented += above;
      }
    }
    std::cout << "  " << std::setw(4) << h << "  " << std::setw(7) << row.defects << "  "
              << std::fixed << std::setprecision(3) << std::setw(6)
              << (row.defects ? double(row.found) / double(row.defects) : 1.0) << "  "
              << std::setw(7) << (row.defects ? double(row.located) / double(row.defects) : 1.0)
              << "  " << std::setw(9)
              << (row.regions ? double(row.true_regions) / double(row.regions) : 1.0) << "  "
              << std::setw(5) << (row.found ? double(row.first) / double(row.found) : 1.0) << "  "
              << std::setw(9)
              << (row.defects ? double(row.above_undented) / double(row.defects) : 1.0) << "  "
              << std::setprecision(1) << std::setw(9)
              << (row.found ? double(row.rank_sum) / double(row.found) : 0.0) << "  "
              << std::setw(7) << row.regions << "  " << std::setprecision(3) << std::setw(6)
              << (row.defects ? double(row.faired) / double(row.defects) : 1.0) << "  "
              << std::setw(13) << row.design_faired << "  " << std::setw(5)
              << (row.defects ? double(row.whole) / double(row.defects) : 1.0) << std::defaultfloat
              << "\n"
              << std::flush;
  }
}

// Whether the measure sees the defects where the rest of the mesh is left out: per defect,
// the detection restricted (face_range) to the faces within 3R of its centre, on the dented
// mesh (seen: a region holds the centre vertex) and on the same faces of the undented mesh
// (quiet: no region there), and whether the dented disc's strongest region (by score) is
// stronger than every region of the undented disc. The lights are those of the whole mesh.
void local_table(const std::string& name, unsigned seeds)
{
  HB::Mesh original;
  if (!read_shared_mesh(name, original))
    return;
  const auto lights = HL::default_light_setup(original, HLP::number_of_lines(30));
  std::cout << "\n"
            << name << ", detection within 3R of each defect\n  h/ē   defects  seen  "
            << "quiet undented disc  stronger\n";
  for (double h : {1.0, 0.5, 0.2, 0.1}) {
    std::size_t defects = 0, seen = 0, quiet = 0, stronger = 0;
    for (unsigned seed = 1; seed <= seeds; ++seed) {
      HB::Mesh mesh = original;
      for (const auto& d : HB::inject_defects(mesh, 4, 5.0, h, seed, [](auto) { return true; })) {
        std::vector<HB::face_descriptor> disc;
        for (auto f : faces(mesh)) {
          bool near = false;
          for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
            near = near ||
                   CGAL::squared_distance(original.point(v), d.centre) < std::pow(3 * d.radius, 2);
          if (near)
            disc.push_back(f);
        }
        std::vector<HB::Irregularity> dented, undented;
        CGAL::detect_highlight_line_irregularities(
            mesh, lights, std::back_inserter(dented),
            HLP::local_residual(HLP::face_range(disc), local_residual));
        CGAL::detect_highlight_line_irregularities(
            original, lights, std::back_inserter(undented),
            HLP::local_residual(HLP::face_range(disc), local_residual));
        ++defects;
        seen += HB::regions_of_defects(mesh, {d}, dented)[0] != std::size_t(-1);
        quiet += undented.empty();
        // The dented disc's strongest region beats everything of the undented disc.
        double best = 0, best_undented = 0;
        for (const auto& r : dented)
          best = (std::max)(best, r.score);
        for (const auto& r : undented)
          best_undented = (std::max)(best_undented, r.score);
        stronger += best > best_undented;
      }
    }
    std::cout << "  " << std::setw(4) << h << "  " << std::setw(7) << defects << "  " << std::fixed
              << std::setprecision(3) << std::setw(5) << double(seen) / double(defects) << "  "
              << std::setw(19) << double(quiet) / double(defects) << "  " << std::setw(8)
              << double(stronger) / double(defects) << std::defaultfloat << "\n"
              << std::flush;
  }
}

// Where a region lies against a defect, in mean edge lengths: the distance from the defect's
// centre to the region's peak vertex and to the mean of its vertices, and the farthest vertex.
std::string region_geometry(const HB::Mesh& mesh, const HB::Irregularity& region,
                            const HB::Injected_defect& defect)
{
  const double e = test::mean_edge_length(mesh);
  std::set<HB::Mesh::Vertex_index> vertices;
  for (auto f : region.faces)
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      vertices.insert(v);
  HB::Vector mean(0, 0, 0);
  double farthest = 0;
  for (auto v : vertices) {
    mean = mean + (mesh.point(v) - CGAL::ORIGIN) / double(vertices.size());
    farthest =
        (std::max)(farthest, std::sqrt(CGAL::squared_distance(mesh.point(v), defect.centre)));
  }
  std::ostringstream out;
  out << std::setprecision(3) << " (peak "
      << std::sqrt(CGAL::squared_distance(mesh.point(region.peak_vertex), defect.centre)) / e
      << " ē, mean " << std::sqrt(CGAL::squared_distance(CGAL::ORIGIN + mean, defect.centre)) / e
      << " ē, farthest " << farthest / e << " ē from the defect)";
  return out.str();
}

// Why defects are missed (--misses): per defect that no region locates, what lies around it,
// from the detection's output only. A defect is
//   mis-centred  if a region holds its centre vertex but reaches farther than 3R from it;
//   folded       if not, and it turned edges within 2R of its centre sharp (over 60°: creases
//                to the detection, which breaks the lines there and drops anomalies near them);
//   by design    if not, and a region of the undented mesh reaches within 2R of it;
//   unseen       otherwise.
// Whatever the cause, a missed defect is also counted as
//   silent       if its lines show no peak of their own: no region of a permissive detection
//                (minimum_evidence 1e-6, so that the anomalies of a single light setup make a
//                region) has its strongest anomaly within R of the defect's centre. A silent
//                defect is missed by the scoring (its offsets stay below detection_threshold
//                times the noise), whatever the grouping does; a mis-centred or by-design one
//                that is silent only lies next to a region of the design. It is an upper
//                bound: where a stronger region's disc takes a defect's anomalies whole, the
//                defect has no peak of its own either.
// Each missed defect is listed with the sharp edges near it before and after injection.
std::size_t sharp_edges_near(const HB::Mesh& mesh, const HB::Point& centre, double radius)
{
  std::size_t count = 0;
  for (auto e : edges(mesh)) {
    const auto h = halfedge(e, mesh);
    if (is_border_edge(h, mesh) ||
        CGAL::squared_distance(mesh.point(source(h, mesh)), centre) > radius * radius)
      continue;
    const auto n = CGAL::Polygon_mesh_processing::compute_face_normal(face(h, mesh), mesh);
    const auto m =
        CGAL::Polygon_mesh_processing::compute_face_normal(face(opposite(h, mesh), mesh), mesh);
    count += n * m < 0.5;
  }
  return count;
}

// Per defect, whether a permissive detection (see misses_table()) has a region whose strongest
// anomaly lies within the defect's radius of its centre.
std::vector<bool> defects_with_own_peak(const HB::Mesh& mesh,
                                        const std::vector<HB::Injected_defect>& defects)
{
  const auto found = detect(mesh, HLP::minimum_evidence(detection_parameters(), 1e-6));
  std::vector<bool> peaked(defects.size(), false);
  for (std::size_t d = 0; d < defects.size(); ++d)
    for (const auto& region : found)
      peaked[d] =
          peaked[d] || (region.peak_vertex != HB::Mesh::null_vertex() &&
                        CGAL::squared_distance(mesh.point(region.peak_vertex), defects[d].centre) <=
                            defects[d].radius * defects[d].radius);
  return peaked;
}

void misses_table(const std::string& name, unsigned seeds)
{
  HB::Mesh original;
  if (!read_shared_mesh(name, original))
    return;
  const auto own = detect(original);
  const auto own_vertices = HB::vertices_of_regions(original, own);
  std::cout << "\n" << name << ": defects not located, and why\n";
  std::cout
      << "  h/ē   defects  located  mis-centred (by design)  folded  by design  unseen  silent\n";
  std::ostringstream details;
  for (double h : {1.0, 0.5, 0.2, 0.1}) {
    std::size_t defects = 0, located = 0;
    std::array<std::size_t, 4> causes{0, 0, 0, 0}; // mis-centred, folded, by design, unseen
    std::size_t miscentred_by_design = 0;          // mis-centred next to an undented region
    std::size_t silent = 0;                        // missed, without a peak of their own
    for (unsigned seed = 1; seed <= seeds; ++seed) {
      HB::Mesh mesh = original;
      const auto injected = HB::inject_defects(mesh, 4, 5.0, h, seed, [](auto) { return true; });
      const auto found = detect(mesh);
      const auto holds = HB::regions_of_defects(mesh, injected, found);
      const auto is_located = HB::located_defects(mesh, injected, found);
      const auto own_peak = defects_with_own_peak(mesh, injected);
      for (std::size_t d = 0; d < injected.size(); ++d) {
        ++defects;
        if (is_located[d]) {
          ++located;
          continue;
        }
        const auto& defect = injected[d];
        const double near = 2 * defect.radius;
        const std::size_t before = sharp_edges_near(original, defect.centre, near),
                          after = sharp_edges_near(mesh, defect.centre, near);
        std::size_t design_region = std::size_t(-1);
        for (std::size_t r = 0; r < own.size() && design_region == std::size_t(-1); ++r)
          for (auto v : own_vertices[r])
            if (CGAL::squared_distance(original.point(v), defect.centre) <= near * near) {
              design_region = r;
              break;
            }
        const int cause = holds[d] != std::size_t(-1)        ? 0
                          : after > before                   ? 1
                          : design_region != std::size_t(-1) ? 2
                                                             : 3;
        ++causes[std::size_t(cause)];
        silent += !own_peak[d];
        miscentred_by_design += cause == 0 && design_region != std::size_t(-1);
        const char* why = cause == 0   ? "mis-centred"
                          : cause == 1 ? "folded"
                          : cause == 2 ? "by design"
                                       : "unseen";
        details << "  h " << h << ", seed " << seed << ", " << (defect.height < 0 ? "dent" : "bump")
                << " " << d << ": " << why << (own_peak[d] ? "" : ", silent")
                << "; sharp edges within 2R " << before << " -> " << after;
        if (holds[d] != std::size_t(-1))
          details << "; held by region " << holds[d] + 1 << " of " << found.size() << " ["
                  << HB::describe(found[holds[d]]) << "]"
                  << region_geometry(mesh, found[holds[d]], defect);
        if (design_region != std::size_t(-1))
          details << "; undented region " << design_region + 1 << " within 2R ["
                  << HB::describe(own[design_region]) << "]";
        details << "\n";
      }
    }
    std::cout << "  " << std::setw(4) << h << "  " << std::setw(7) << defects << "  "
              << std::setw(7) << located << "  " << std::setw(11) << causes[0] << " ("
              << std::setw(9) << miscentred_by_design << ")  " << std::setw(6) << causes[1] << "  "
              << std::setw(9) << causes[2] << "  " << std::setw(6) << causes[3] << "  "
              << std::setw(6) << silent << "\n"
              << std::flush;
  }
  std::cout << details.str() << std::flush;
}

// The demo's --detect mode on the dented Beetle: every region, its rank and whether it holds
// the roof dent; time against one compute_highlight_lines() with the same lights.
// --repair: what the automatic mode (detect_and_fair_highlight_line_irregularities(), default
// minimum_confidence) does to each shared mesh, against the undented mesh as the truth, and
// what PMP::fair() does to the same regions (the regions the automatic mode fairs: confidence
// >= 0.5, touching ones joined, grown by the fairing margin; PMP::fair on their movable
// vertices). Per height: the injected defects whose vertices the repair moved, how many of
// those end closer to the undented surface (RMS over the vertices within R), the median ratio
// after / before over them, and the surface that was right (vertices farther than R from every
// defect): how far the repair moved it, the largest distance of one of its vertices to the
// undented surface, in ē. The undented mesh first: whatever is faired there is design.
struct Repair_row
{
  std::size_t moved = 0, closer = 0;
  std::vector<double> ratios;
  double farthest = 0;
  void add(const HB::Repair_outcome& o)
  {
    for (std::size_t d = 0; d < o.moved.size(); ++d)
      if (o.moved[d]) {
        ++moved;
        closer += o.after[d] < o.before[d];
        ratios.push_back(o.after[d] / (std::max)(o.before[d], 1e-300));
      }
    farthest = (std::max)(farthest, o.collateral_largest);
  }
  double median_ratio()
  {
    if (ratios.empty())
      return 0;
    std::sort(ratios.begin(), ratios.end());
    return ratios[ratios.size() / 2];
  }
};

// PMP::fair() on the regions the automatic mode faired, one after the other.
void pmp_fair_regions(HB::Mesh& mesh, const std::vector<HL::Irregularity_repair<HB::Mesh>>& repairs)
{
  for (const auto& r : repairs) {
    if (!r.repaired)
      continue;
    std::vector<HB::vertex_descriptor> movable;
    HL::movable_vertices(mesh, r.faired_faces, std::back_inserter(movable));
    CGAL::Polygon_mesh_processing::fair(mesh, movable);
  }
}

void repair_table(const std::string& name, unsigned seeds)
{
  HB::Mesh original;
  if (!read_shared_mesh(name, original))
    return;
  const double e = test::mean_edge_length(original);
  auto repair = [](HB::Mesh& mesh, std::size_t& faired) {
    const auto repairs = CGAL::detect_and_fair_highlight_line_irregularities(
        mesh, HL::default_light_setup(mesh, HLP::number_of_lines(30)),
        HLP::fairing_margin(HLP::number_of_scales(HLP::local_residual(local_residual), scales),
                            fairing_margin));
    for (const auto& r : repairs)
      faired += r.repaired;
    return repairs;
  };
  {
    HB::Mesh mesh = original;
    std::size_t faired = 0;
    repair(mesh, faired);
    const HB::Repair_outcome o = HB::repair_outcome(original, original, mesh, {});
    std::cout << "\n"
              << name << ", undented: " << faired
              << " region(s) faired, the surface moved by up to " << std::setprecision(3)
              << o.collateral_largest / e << " ē\n";
  }
  std::cout << "  h/ē  defects  regions faired | ours: moved  closer  median after/before  "
               "right surface moved up to (ē) | PMP::fair: moved  closer  median  up to (ē)\n";
  Repair_row all_ours, all_pmp;
  for (double h : {1.0, 0.5, 0.2, 0.1}) {
    std::size_t defects = 0, faired = 0;
    Repair_row ours, pmp;
    for (unsigned seed = 1; seed <= seeds; ++seed) {
      HB::Mesh mesh = original;
      const auto injected = HB::inject_defects(mesh, 4, 5.0, h, seed, [](auto) { return true; });
      const HB::Mesh dented = mesh;
      HB::Mesh by_pmp = mesh;
      pmp_fair_regions(by_pmp, repair(mesh, faired));
      defects += injected.size();
      ours.add(HB::repair_outcome(original, dented, mesh, injected));
      pmp.add(HB::repair_outcome(original, dented, by_pmp, injected));
    }
    std::cout << std::setprecision(3) << std::setw(5) << h << std::setw(9) << defects
              << std::setw(16) << faired << std::setw(14) << ours.moved << std::setw(8)
              << ours.closer << std::setw(21) << ours.median_ratio() << std::setw(31)
              << ours.farthest / e << std::setw(18) << pmp.moved << std::setw(8) << pmp.closer
              << std::setw(8) << pmp.median_ratio() << std::setw(11) << pmp.farthest / e << "\n";
    for (Repair_row* row : {&ours, &pmp}) {
      Repair_row& all = row == &ours ? all_ours : all_pmp;
      all.moved += row->moved;
      all.closer += row->closer;
      all.ratios.insert(all.ratios.end(), row->ratios.begin(), row->ratios.end());
      all.farthest = (std::max)(all.farthest, row->farthest);
    }
  }
  std::cout << "  all heights: ours " << all_ours.closer << " of " << all_ours.moved
            << " moved closer, median " << all_ours.median_ratio() << ", right surface up to "
            << all_ours.farthest / e << " ē; PMP::fair " << all_pmp.closer << " of "
            << all_pmp.moved << ", median " << all_pmp.median_ratio() << ", up to "
            << all_pmp.farthest / e << " ē\n";
}

// How many of a set of defects a repair brought closer to the undented surface, and the median
// ratio after / before of their RMS distances to it.
struct Closer_tally
{
  std::size_t count = 0, closer = 0;
  std::vector<double> ratios;
  void add(double before, double after)
  {
    ++count;
    closer += after < before;
    ratios.push_back(after / (std::max)(before, 1e-300));
  }
  void add(const Closer_tally& other)
  {
    count += other.count;
    closer += other.closer;
    ratios.insert(ratios.end(), other.ratios.begin(), other.ratios.end());
  }
  std::string str() const
  {
    if (count == 0)
      return "-";
    std::vector<double> sorted = ratios;
    std::sort(sorted.begin(), sorted.end());
    std::ostringstream out;
    out << closer << "/" << count << " " << std::setprecision(3) << sorted[sorted.size() / 2];
    return out.str();
  }
};

// --repair, second table: what limits the repairs. Per injected defect: whether the undented
// surface under it is predictable from its surroundings (HB::surroundings_predict_the_surface:
// a quadric fitted to the undented rim R to R + 4 ē predicts the undented surface within R better
// than the dented surface lies), and what fair_with_highlight_lines() (default parameters, the
// lights of the automatic mode) and PMP::fair() do on the defect's own disc (the faces within
// R + 2 ē of its centre: the region a user who sees the defect would fair), each on its own.
// Columns: closer/count and the median ratio after / before of the RMS distance to the
// undented surface (over the vertices within R).
void repair_limits_table(const std::string& name, unsigned seeds)
{
  HB::Mesh original;
  if (!read_shared_mesh(name, original))
    return;
  const double e = test::mean_edge_length(original);
  std::cout << "  h/ē  defects  predictable | automatic mode: moved predictable | defect's "
               "disc: ours        PMP::fair   | predictable only: ours   PMP::fair\n";
  Closer_tally all_ours, all_pmp, all_predictable_ours, all_predictable_pmp;
  for (double h : {1.0, 0.5, 0.2, 0.1}) {
    std::size_t defects = 0, predictable = 0;
    Closer_tally automatic, automatic_predictable, ours, pmp, predictable_ours, predictable_pmp;
    for (unsigned seed = 1; seed <= seeds; ++seed) {
      HB::Mesh dented = original;
      const auto injected = HB::inject_defects(dented, 4, 5.0, h, seed, [](auto) { return true; });
      // The lights of the automatic mode as repair_table() sets them, from the dented mesh.
      const auto lights = HL::default_light_setup(dented, HLP::number_of_lines(30));
      HB::Mesh repaired = dented;
      CGAL::detect_and_fair_highlight_line_irregularities(
          repaired, lights,
          HLP::fairing_margin(HLP::local_residual(HLP::number_of_scales(scales), local_residual),
                              fairing_margin));
      const HB::Repair_outcome automatic_outcome =
          HB::repair_outcome(original, dented, repaired, injected);
      for (std::size_t d = 0; d < injected.size(); ++d) {
        ++defects;
        const double before = automatic_outcome.before[d];
        const bool is_predictable = HB::surroundings_predict_the_surface(
            original, injected[d],
            CGAL::Polygon_mesh_processing::compute_vertex_normal(injected[d].centre_vertex,
                                                                 original),
            4 * e, before);
        predictable += is_predictable;
        if (automatic_outcome.moved[d]) {
          automatic.add(before, automatic_outcome.after[d]);
          if (is_predictable)
            automatic_predictable.add(before, automatic_outcome.after[d]);
        }
        const auto disc = HB::defect_disc(dented, injected[d], injected[d].radius + 2 * e);
        HB::Mesh by_ours = dented, by_pmp = dented;
        // A refused or failed fairing (e.g. the centre on a sharp edge: an empty disc) leaves
        // the mesh as it was, and is measured as such.
        try {
          CGAL::fair_with_highlight_lines(by_ours, disc, lights);
        } catch (const std::exception&) {
        }
        try {
          std::vector<HB::vertex_descriptor> movable;
          HL::movable_vertices(by_pmp, disc, std::back_inserter(movable));
          CGAL::Polygon_mesh_processing::fair(by_pmp, movable);
        } catch (const std::exception&) {
        }
        const double after_ours =
            HB::repair_outcome(original, dented, by_ours, {injected[d]}).after[0];
        const double after_pmp =
            HB::repair_outcome(original, dented, by_pmp, {injected[d]}).after[0];
        ours.add(before, after_ours);
        pmp.add(before, after_pmp);
        if (is_predictable) {
          predictable_ours.add(before, after_ours);
          predictable_pmp.add(before, after_pmp);
        }
      }
    }
    std::cout << std::setw(5) << h << std::setw(9) << defects << std::setw(13) << predictable
              << std::setw(20) << automatic.str() << std::setw(13) << automatic_predictable.str()
              << std::setw(19) << ours.str() << std::setw(14) << pmp.str() << std::setw(23)
              << predictable_ours.str() << std::setw(12) << predictable_pmp.str() << "\n";
    all_ours.add(ours);
    all_pmp.add(pmp);
    all_predictable_ours.add(predictable_ours);
    all_predictable_pmp.add(predictable_pmp);
  }
  std::cout << "  all heights, the defect's own disc: ours " << all_ours.str() << ", PMP::fair "
            << all_pmp.str() << "; the predictable defects: ours " << all_predictable_ours.str()
            << ", PMP::fair " << all_predictable_pmp.str() << "\n";
}

void demo_table()
{
  HB::vertex_descriptor centre;
  const HB::Mesh mesh = HB::demo_beetle(centre);
  const auto lights = HL::default_light_setup(mesh, HLP::number_of_lines(60));
  auto start = std::chrono::steady_clock::now();
  {
    auto model = CGAL::compute_highlight_lines(mesh, lights, CGAL::Emptyset_iterator(),
                                               HLP::facing_side_only(true));
    benchmark::DoNotOptimize(model.nodes().data());
  }
  const double model_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  start = std::chrono::steady_clock::now();
  std::vector<HB::Irregularity> found;
  CGAL::detect_highlight_line_irregularities(
      mesh, lights, std::back_inserter(found),
      HLP::local_residual(HLP::number_of_scales(scales), local_residual));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "demo beetle, roof dent" << (local_residual ? "" : ", bending measure") << ": "
            << found.size() << " regions, " << std::fixed << std::setprecision(2) << seconds
            << " s = " << std::setprecision(1) << seconds / model_seconds
            << " x compute_highlight_lines()" << std::defaultfloat << "\n";
  const auto holds =
      HB::regions_of_defects(mesh, {HB::Injected_defect{mesh.point(centre), centre, 0, 0}}, found);
  for (std::size_t i = 0; i < found.size(); ++i)
    std::cout << "  " << i + 1 << (holds[0] == i ? " ROOF DENT " : " ") << HB::describe(found[i])
              << ", scale " << found[i].scale << "\n";
}

void curves(const std::vector<std::string>& meshes, unsigned seeds, bool hood)
{
  if (hood) {
    std::cout << "Detection recall and precision vs defect height h (radius 5 ē)\n";
    grid_curve("smooth hood", test::hood, 0.3);
    grid_curve("smooth hood, regular grid", test::hood, 0);
    grid_curve("flat plate, regular grid", flat, 0);
  }
  std::cout << "\nShared meshes: dents and bumps of radius 5 ē anywhere on the surface, " << seeds
            << " x 4 per height\n";
  for (const auto& name : meshes)
    shared_table(name, seeds);
}

// --- Speed --------------------------------------------------------------------------------

const HB::Mesh& refined_beetle()
{
  static std::unique_ptr<HB::Mesh> mesh;
  if (!mesh) {
    mesh = std::make_unique<HB::Mesh>();
    std::ifstream in(std::string(HIGHLIGHT_LINES_DATA_DIR) + "/beetle.off");
    if (!in || !CGAL::IO::read_OFF(in, *mesh))
      throw std::runtime_error("cannot read the bundled beetle");
    CGAL::Subdivision_method_3::Loop_subdivision(*mesh, CGAL::parameters::number_of_iterations(2));
  }
  return *mesh;
}

void BM_compute_highlight_lines(benchmark::State& state)
{
  const HB::Mesh& mesh = refined_beetle();
  const auto lights = HL::default_light_setup(mesh, HLP::number_of_lines(30));
  for (auto _ : state) {
    auto model = CGAL::compute_highlight_lines(mesh, lights, CGAL::Emptyset_iterator(),
                                               HLP::facing_side_only(true));
    benchmark::DoNotOptimize(model.nodes().data());
  }
  state.counters["faces"] = double(num_faces(mesh));
}

void BM_detect(benchmark::State& state)
{
  const HB::Mesh& mesh = refined_beetle();
  const auto lights = HL::default_light_setup(mesh, HLP::number_of_lines(30));
  std::size_t regions = 0;
  for (auto _ : state) {
    std::vector<HB::Irregularity> found;
    CGAL::detect_highlight_line_irregularities(mesh, lights, std::back_inserter(found));
    regions = found.size();
  }
  state.counters["regions"] = double(regions);
}

} // namespace

BENCHMARK(BM_compute_highlight_lines)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_detect)->Unit(benchmark::kMillisecond)->UseRealTime();

int main(int argc, char** argv)
{
  std::vector<char*> args;
  bool curves_only = false, hood = true, local = false, demo = false, misses = false,
       repair = false, limits = true, mesh_files_given = false;
  unsigned seeds = 2;
  std::vector<std::string> meshes{"beetle.off",  "bunny.off",      "camelhead.off",
                                  "fandisk.off", "rocker-arm.off", "spot.off"};
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--curves") == 0)
      curves_only = true;
    else if (std::strcmp(argv[i], "--shared") == 0) // the shared meshes only
      curves_only = true, hood = false;
    else if (std::strcmp(argv[i], "--mesh") == 0 && i + 1 < argc)
      meshes.assign(1, argv[++i]), curves_only = true, hood = false;
    else if (std::strcmp(argv[i], "--mesh-file") == 0 && i + 1 < argc) { // repeatable
      if (!mesh_files_given)
        meshes.clear();
      mesh_files_given = true;
      const std::string path = argv[++i]; // a path: read_shared_mesh() tells it by its '/'
      meshes.push_back(path.find('/') == std::string::npos ? "./" + path : path);
      curves_only = true, hood = false;
    } else if (std::strcmp(argv[i], "--local") == 0) // the detection near each defect only
      local = true, curves_only = true, hood = false;
    else if (std::strcmp(argv[i], "--misses") == 0) // why defects are not located
      misses = true, curves_only = true, hood = false;
    else if (std::strcmp(argv[i], "--repair") == 0) // what the automatic mode does
      repair = true, curves_only = true, hood = false;
    else if (std::strcmp(argv[i], "--no-limits") == 0) // --repair: the first table only
      limits = false;
    else if (std::strcmp(argv[i], "--demo") == 0)
      demo = true, curves_only = true;
    else if (std::strcmp(argv[i], "--bending") == 0) // HLP::local_residual(false)
      local_residual = false;
    else if (std::strcmp(argv[i], "--defect-regions") == 0)
      list_defect_regions = true;
    else if (std::strcmp(argv[i], "--scales") == 0 && i + 1 < argc)
      scales = std::stoi(argv[++i]);
    else if (std::strcmp(argv[i], "--fairing-margin") == 0 && i + 1 < argc)
      fairing_margin = std::atoi(argv[++i]);
    else if (std::strcmp(argv[i], "--seeds") == 0 && i + 1 < argc)
      seeds = unsigned(std::stoul(argv[++i]));
    else
      args.push_back(argv[i]);
  }
  try {
    if (!curves_only) {
      int count = int(args.size());
      benchmark::Initialize(&count, args.data());
      if (benchmark::ReportUnrecognizedArguments(count, args.data()))
        return 1;
      benchmark::RunSpecifiedBenchmarks();
      benchmark::Shutdown();
    }
    if (demo)
      demo_table();
    else if (misses)
      for (const auto& name : meshes)
        misses_table(name, seeds);
    else if (repair)
      for (const auto& name : meshes) {
        repair_table(name, seeds);
        if (limits)
          repair_limits_table(name, seeds);
      }
    else if (local)
      for (const auto& name : meshes)
        local_table(name, seeds);
    else
      curves(meshes, seeds, hood);
  } catch (const std::exception& e) {
    std::cerr << "benchmark_detection: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

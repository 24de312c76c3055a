// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Evaluation of detect_highlight_line_irregularities(): dents and bumps of known position and
// size injected (seeded) into smooth or real meshes, and the detections matched against them.
// Shared by the benchmark (recall/precision curves) and the tests (strict thresholds).
#ifndef HIGHLIGHT_LINES_BENCHMARK_DETECTION_EVALUATION_H
#define HIGHLIGHT_LINES_BENCHMARK_DETECTION_EVALUATION_H

#include "test_meshes.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Highlight_lines/fairing_building_blocks.h>
#include <CGAL/Highlight_lines/internal/sharp_vertices.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/detect_highlight_line_irregularities.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <iomanip>
#include <sstream>
#include <string>
#include <random>
#include <set>
#include <vector>

namespace Highlight_lines_benchmark {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<Mesh>::face_descriptor face_descriptor;
typedef CGAL::Highlight_lines::Highlight_line_irregularity<Mesh> Irregularity;

/// A defect put into a mesh: displacement `height · (1 - (r/R)²)³` along the vertex normals,
/// for the vertices within Euclidean distance `R` of `centre` (negative height: a dent).
struct Injected_defect
{
  Point centre;
  vertex_descriptor centre_vertex;
  double radius = 0;
  double height = 0;
};

inline bool is_border_near(const Mesh& mesh, vertex_descriptor v, double radius)
{
  for (auto w : vertices(mesh))
    if (mesh.is_border(w) &&
        CGAL::squared_distance(mesh.point(w), mesh.point(v)) <= radius * radius)
      return true;
  return false;
}

/// Injects `count` defects of radius `radius_in_edges · ē` and height `height_in_edges · ē`
/// (random sign) at random vertices at least `2R` from the border and `separation · R` from
/// each other.
/// `eligible(v)` restricts the centres (e.g. to smooth panels of a real mesh).
template <typename Eligible>
std::vector<Injected_defect> inject_defects(Mesh& mesh, int count, double radius_in_edges,
                                            double height_in_edges, unsigned seed,
                                            Eligible eligible, double separation = 3)
{
  const double e = test::mean_edge_length(mesh);
  const double radius = radius_in_edges * e, height = height_in_edges * e;
  std::vector<vertex_descriptor> candidates;
  for (auto v : vertices(mesh))
    if (eligible(v))
      candidates.push_back(v);
  std::mt19937 rng(seed);
  std::vector<Injected_defect> defects;
  for (int attempt = 0; attempt < 1000 && int(defects.size()) < count && !candidates.empty();
       ++attempt) {
    const vertex_descriptor v =
        candidates[std::uniform_int_distribution<std::size_t>(0, candidates.size() - 1)(rng)];
    const Point c = mesh.point(v);
    bool far = !is_border_near(mesh, v, 2 * radius);
    for (const auto& d : defects)
      far = far && CGAL::squared_distance(d.centre, c) > std::pow(separation * radius, 2);
    if (!far)
      continue;
    Injected_defect d;
    d.centre = c;
    d.centre_vertex = v;
    d.radius = radius;
    d.height = std::bernoulli_distribution(0.5)(rng) ? height : -height;
    defects.push_back(d);
  }
  auto normals = mesh.add_property_map<vertex_descriptor, Vector>("v:injection_normal").first;
  CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normals);
  std::vector<Point> moved(mesh.points().begin(), mesh.points().end());
  for (const auto& d : defects)
    for (auto w : vertices(mesh)) {
      const double r2 = CGAL::squared_distance(mesh.point(w), d.centre) / (d.radius * d.radius);
      if (r2 < 1) {
        const double f = (1 - r2) * (1 - r2) * (1 - r2);
        moved[w.idx()] = moved[w.idx()] + d.height * f * normals[w];
      }
    }
  for (auto w : vertices(mesh))
    mesh.point(w) = moved[w.idx()];
  mesh.remove_property_map(normals);
  return defects;
}

/// How the detections match the defects.
struct Detection_score
{
  std::size_t defects = 0, found_defects = 0;
  std::size_t regions = 0, true_regions = 0;
  double recall() const { return defects == 0 ? 1.0 : double(found_defects) / double(defects); }
  double precision() const { return regions == 0 ? 1.0 : double(true_regions) / double(regions); }
};

/// A defect is found if a region contains a face at its centre vertex; a region is true if it
/// has a vertex within the radius of some defect.
inline Detection_score match(const Mesh& mesh, const std::vector<Injected_defect>& defects,
                             const std::vector<Irregularity>& found)
{
  Detection_score score;
  score.defects = defects.size();
  score.regions = found.size();
  std::vector<std::set<vertex_descriptor>> region_vertices(found.size());
  for (std::size_t i = 0; i < found.size(); ++i)
    for (face_descriptor f : found[i].faces)
      for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
        region_vertices[i].insert(v);
  for (const auto& d : defects) {
    bool hit = false;
    for (const auto& vs : region_vertices)
      hit = hit || vs.count(d.centre_vertex) > 0;
    score.found_defects += hit;
  }
  for (const auto& vs : region_vertices) {
    bool genuine = false;
    for (vertex_descriptor v : vs)
      for (const auto& d : defects)
        genuine = genuine || CGAL::squared_distance(mesh.point(v), d.centre) < d.radius * d.radius;
    score.true_regions += genuine;
  }
  return score;
}

/// Whether region `a` is reported before region `b` (the order of the detection's output).
inline bool stronger(const Irregularity& a, const Irregularity& b)
{
  return a.confidence * a.score > b.confidence * b.score;
}

/// One line about a region: its size and strength.
inline std::string describe(const Irregularity& r)
{
  std::ostringstream s;
  s << CGAL::Highlight_lines::to_string(r.kind) << ", " << r.faces.size() << " faces, score "
    << std::setprecision(3) << r.score << ", confidence " << std::setprecision(2) << r.confidence;
  return s.str();
}

inline std::vector<std::set<vertex_descriptor>>
vertices_of_regions(const Mesh& mesh, const std::vector<Irregularity>& found)
{
  std::vector<std::set<vertex_descriptor>> region_vertices(found.size());
  for (std::size_t i = 0; i < found.size(); ++i)
    for (face_descriptor f : found[i].faces)
      for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
        region_vertices[i].insert(v);
  return region_vertices;
}

/// Per defect, the index of the region holding its centre vertex, or -1.
inline std::vector<std::size_t> regions_of_defects(const Mesh& mesh,
                                                   const std::vector<Injected_defect>& defects,
                                                   const std::vector<Irregularity>& found)
{
  const auto region_vertices = vertices_of_regions(mesh, found);
  std::vector<std::size_t> holds(defects.size(), std::size_t(-1));
  for (std::size_t d = 0; d < defects.size(); ++d)
    for (std::size_t i = 0; i < found.size() && holds[d] == std::size_t(-1); ++i)
      if (region_vertices[i].count(defects[d].centre_vertex) > 0)
        holds[d] = i;
  return holds;
}

/// Per defect, whether it is located: every vertex of the region holding its centre vertex
/// (`regions_of_defects()`) lies within `reach` radii of a defect that region holds. A region
/// spread over much of the mesh holds the defects it covers without locating them (fairing it
/// would reshape the design around them); a defect's anomalies lie within R + 3w/2 of it, and
/// its region adds a margin of a few rings.
inline std::vector<bool> located_defects(const Mesh& mesh,
                                         const std::vector<Injected_defect>& defects,
                                         const std::vector<Irregularity>& found, double reach = 3)
{
  const auto region_vertices = vertices_of_regions(mesh, found);
  const auto holds = regions_of_defects(mesh, defects, found);
  std::vector<bool> located(defects.size(), false);
  for (std::size_t d = 0; d < defects.size(); ++d) {
    if (holds[d] == std::size_t(-1))
      continue;
    bool local = true;
    for (vertex_descriptor v : region_vertices[holds[d]]) {
      bool near = false;
      for (std::size_t e = 0; e < defects.size() && !near; ++e)
        near = holds[e] == holds[d] && CGAL::squared_distance(mesh.point(v), defects[e].centre) <=
                                           std::pow(reach * defects[e].radius, 2);
      local = local && near;
    }
    located[d] = local;
  }
  return located;
}

/// Per defect, whether the region holding its centre vertex could move all of it: every vertex
/// within `inner` radii of its centre (moved by at least 5 % of the height at 0.8) is one of the
/// region's movable vertices (CGAL::Highlight_lines::movable_vertices(): what a fairing of the
/// region moves; none if the fairing refuses the region). A region centred on a defect's flank
/// holds the defect without being able to repair its far side.
inline std::vector<bool> covered_defects(const Mesh& mesh,
                                         const std::vector<Injected_defect>& defects,
                                         const std::vector<Irregularity>& found, double inner = 0.8)
{
  const auto holds = regions_of_defects(mesh, defects, found);
  std::vector<bool> covered(defects.size(), false);
  for (std::size_t d = 0; d < defects.size(); ++d) {
    if (holds[d] == std::size_t(-1))
      continue;
    std::set<vertex_descriptor> movable;
    try {
      CGAL::Highlight_lines::movable_vertices(mesh, found[holds[d]].faces,
                                              std::inserter(movable, movable.end()));
    } catch (const CGAL::Highlight_lines::Invalid_input&) {
      continue;
    }
    bool all = true;
    for (vertex_descriptor v : vertices(mesh))
      all = all && (CGAL::squared_distance(mesh.point(v), defects[d].centre) >
                        std::pow(inner * defects[d].radius, 2) ||
                    movable.count(v) == 1);
    covered[d] = all;
  }
  return covered;
}

/// Per region, whether it has a vertex within the radius of some defect.
inline std::vector<bool> genuine_regions(const Mesh& mesh,
                                         const std::vector<Injected_defect>& defects,
                                         const std::vector<Irregularity>& found)
{
  const auto region_vertices = vertices_of_regions(mesh, found);
  std::vector<bool> genuine(found.size(), false);
  for (std::size_t i = 0; i < found.size(); ++i)
    for (vertex_descriptor v : region_vertices[i])
      for (const auto& d : defects)
        if (CGAL::squared_distance(mesh.point(v), d.centre) < d.radius * d.radius)
          genuine[i] = true;
  return genuine;
}

/// The detection tests' dented hood: a 50 x 50 grid over [-1, 1]^2 (jitter 0.3, seed 6) lifted
/// by test::hood, with one defect of radius 4 ē and height 0.5 ē (seed 6). `soup` receives the
/// dented points, so that the same mesh can be built as another type.
inline Mesh hood_with_one_defect(test::Soup& soup)
{
  soup = test::grid(50, 2.0 / 50, -1, -1, test::hood, 0.3, 6);
  Mesh mesh = test::to_mesh<Mesh>(soup);
  if (inject_defects(mesh, 1, 4.0, 0.5, 6, [](auto) { return true; }).size() != 1)
    throw std::logic_error("hood_with_one_defect(): the defect found no place");
  for (auto v : vertices(mesh))
    soup.points[std::size_t(v)] = mesh.point(v);
  return mesh;
}

// The bundled demo (scripts/demo, part 3): the Beetle with the dent fair_with_highlight_lines
// presses into its roof; `centre` is the dent's centre vertex.
inline Mesh demo_beetle(vertex_descriptor& centre)
{
  Mesh mesh;
  std::ifstream in(std::string(HIGHLIGHT_LINES_DATA_DIR) + "/beetle.off");
  if (!in || !CGAL::IO::read_OFF(in, mesh))
    throw std::runtime_error("cannot read the bundled beetle");
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  const double diagonal =
      std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                CGAL::square(box.zmax() - box.zmin()));
  const Point wanted(0.04, box.ymax(), -0.12);
  centre = *vertices(mesh).begin();
  for (auto v : vertices(mesh))
    if (CGAL::squared_distance(mesh.point(v), wanted) <
        CGAL::squared_distance(mesh.point(centre), wanted))
      centre = v;
  const Point c = mesh.point(centre);
  const double radius = 0.6 * 0.07 * diagonal, depth = 0.006 * diagonal;
  std::vector<std::pair<vertex_descriptor, Point>> moved;
  for (auto v : vertices(mesh)) {
    const double r2 = CGAL::squared_distance(mesh.point(v), c) / (radius * radius);
    if (r2 < 1)
      moved.emplace_back(v, mesh.point(v) -
                                depth * (1 - r2) * (1 - r2) * (1 - r2) *
                                    CGAL::Polygon_mesh_processing::compute_vertex_normal(v, mesh));
  }
  for (const auto& m : moved)
    mesh.point(m.first) = m.second;
  return mesh;
}

/// The faces around the vertices within `radius` of the defect's centre, reached from its centre
/// vertex along edges and never past a vertex of a sharp edge (faces more than 60° apart, as
/// the automatic mode's regions): the region a user who sees the defect would fair (the defect
/// and a rim).
inline std::vector<face_descriptor> defect_disc(const Mesh& mesh, const Injected_defect& defect,
                                                double radius)
{
  CGAL::Highlight_lines::internal::Sharp_vertex_test<Mesh,
                                                     Mesh::Property_map<vertex_descriptor, Point>>
      on_sharp_edge(mesh, 60.0, mesh.points());
  std::set<vertex_descriptor> reached{defect.centre_vertex};
  std::vector<vertex_descriptor> front{defect.centre_vertex};
  std::set<face_descriptor> disc;
  while (!front.empty()) {
    const vertex_descriptor v = front.back();
    front.pop_back();
    if (on_sharp_edge(v))
      continue;
    for (face_descriptor f : faces_around_target(halfedge(v, mesh), mesh))
      if (f != boost::graph_traits<Mesh>::null_face())
        disc.insert(f);
    for (vertex_descriptor u : vertices_around_target(halfedge(v, mesh), mesh))
      if (CGAL::squared_distance(mesh.point(u), defect.centre) <= radius * radius &&
          reached.insert(u).second)
        front.push_back(u);
  }
  return std::vector<face_descriptor>(disc.begin(), disc.end());
}

/// Whether the undented surface under a defect is what its surroundings predict, to better than
/// the defect's own depth: the quadric height field over the tangent plane at the defect's
/// centre (normal `normal`), fitted to the undented vertices between R and R + `rim` from the
/// centre (reached along edges, facing the same way), predicts the undented vertices within R
/// with a smaller RMS error than the RMS distance `dented_rms` of the dented ones. No method
/// that sees only the dented mesh can be expected to bring a defect closer where it does not:
/// the design there varies at the defect's own scale.
inline bool surroundings_predict_the_surface(const Mesh& undented, const Injected_defect& defect,
                                             const Vector& normal, double rim, double dented_rms)
{
  const Vector a = std::abs(normal.x()) < 0.9 ? Vector(1, 0, 0) : Vector(0, 1, 0);
  Vector t = CGAL::cross_product(normal, a);
  t = t / std::sqrt(t.squared_length());
  const Vector u = CGAL::cross_product(normal, t);
  Injected_defect reach = defect;
  reach.radius = defect.radius + rim;
  std::vector<std::array<double, 3>> outer, inner;
  std::set<vertex_descriptor> seen;
  for (face_descriptor f : defect_disc(undented, reach, reach.radius))
    for (vertex_descriptor v : vertices_around_face(halfedge(f, undented), undented)) {
      const Vector d = undented.point(v) - defect.centre;
      if (!seen.insert(v).second || d.squared_length() > CGAL::square(reach.radius) ||
          CGAL::Polygon_mesh_processing::compute_vertex_normal(v, undented) * normal < 0.3)
        continue;
      const std::array<double, 3> c{d * t / defect.radius, d * u / defect.radius, d * normal};
      (d.squared_length() < CGAL::square(defect.radius) ? inner : outer).push_back(c);
    }
  if (outer.size() < 12 || inner.empty())
    return false;
  auto basis = [](double x, double y) {
    Eigen::Matrix<double, 1, 6> b;
    b << 1, x, y, x * x, x * y, y * y;
    return b;
  };
  Eigen::MatrixXd A(outer.size(), 6);
  Eigen::VectorXd h(outer.size());
  for (std::size_t i = 0; i < outer.size(); ++i) {
    A.row(Eigen::Index(i)) = basis(outer[i][0], outer[i][1]);
    h(Eigen::Index(i)) = outer[i][2];
  }
  const Eigen::VectorXd fit = A.colPivHouseholderQr().solve(h);
  double error = 0;
  for (const auto& c : inner)
    error += CGAL::square(basis(c[0], c[1]).dot(fit) - c[2]);
  return std::sqrt(error / double(inner.size())) < dented_rms;
}

/// What a repair did to the injected defects and to the rest of the surface, measured against
/// the undented surface (the truth): distances of vertices to it, in mesh units.
struct Repair_outcome
{
  /// Per defect: the RMS distance of the vertices within its radius to the undented surface,
  /// dented and after the repair; and whether the repair moved any of them.
  std::vector<double> before, after;
  std::vector<bool> moved;
  /// The vertices farther than a radius from every defect (surface that was right): how many
  /// the repair moved, and the largest distance of one of them to the undented surface after.
  std::size_t collateral_moved = 0;
  double collateral_largest = 0;
};

/// Compares `dented` and `repaired` (the same mesh, vertex for vertex) with `undented`.
inline Repair_outcome repair_outcome(const Mesh& undented, const Mesh& dented, const Mesh& repaired,
                                     const std::vector<Injected_defect>& defects)
{
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>> Tree;
  Tree tree(faces(undented).first, faces(undented).second, undented);
  tree.accelerate_distance_queries();
  Repair_outcome outcome;
  std::vector<double> sum_before(defects.size(), 0), sum_after(defects.size(), 0);
  std::vector<std::size_t> count(defects.size(), 0);
  outcome.moved.assign(defects.size(), false);
  for (vertex_descriptor v : vertices(undented)) {
    const bool moved = dented.point(v) != repaired.point(v);
    bool near_a_defect = false;
    for (std::size_t d = 0; d < defects.size(); ++d)
      if (CGAL::squared_distance(undented.point(v), defects[d].centre) <
          CGAL::square(defects[d].radius)) {
        near_a_defect = true;
        sum_before[d] += tree.squared_distance(dented.point(v));
        sum_after[d] += tree.squared_distance(repaired.point(v));
        ++count[d];
        if (moved)
          outcome.moved[d] = true;
      }
    if (!near_a_defect && moved) {
      ++outcome.collateral_moved;
      outcome.collateral_largest = (std::max)(outcome.collateral_largest,
                                              std::sqrt(tree.squared_distance(repaired.point(v))));
    }
  }
  for (std::size_t d = 0; d < defects.size(); ++d) {
    const double n = double((std::max)(count[d], std::size_t(1)));
    outcome.before.push_back(std::sqrt(sum_before[d] / n));
    outcome.after.push_back(std::sqrt(sum_after[d] / n));
  }
  return outcome;
}

} // namespace Highlight_lines_benchmark

#endif // HIGHLIGHT_LINES_BENCHMARK_DETECTION_EVALUATION_H

// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef HIGHLIGHT_LINES_BENCHMARK_REAL_DENT_CASES_H
#define HIGHLIGHT_LINES_BENCHMARK_REAL_DENT_CASES_H

// Seeded dent cases on real meshes: a smooth dent pressed into a patch of a mesh (smooth if the
// mesh has one, else its smoothest), with the undented mesh as the ground truth, a fairing region
// around it and lights above it. Plain functions, no printing, no benchmark library: shared by
// benchmark_real_dents.cpp and tests.
//
//   auto cases = make_real_dent_cases(mesh, "bunny", seed);  // up to 3 centres x 2 depths
//   options.jitter = 0.3;  // the same centres on a scan-like triangulation of the mesh
//
// Definitions (all distances Euclidean; ē_g is the mean edge length of the whole mesh):
// - *Vertex normal*: eq. 3 of the paper, the normalised sum of the cross products
//   (p1 - p0) x (p2 - p0) of the faces around the vertex (area-weighted), on the whole mesh.
// - *Local mean edge length* ē of a centre c: the mean length of the (distinct) edges of the
//   faces reached from c's faces across edges through faces whose three vertices lie within
//   8 ē_g of c. All the radii below are multiples of this local ē.
// - *Region* of c: the faces reached from c's faces across edges through faces whose three
//   vertices lie within `region_radius` (8) ē of c, i.e. the connected component containing c
//   of the faces inside the ball (another sheet of the surface passing through the ball is not
//   part of it). Its radius ρ is the largest distance of its vertices to c.
// - *Candidate*: c can be a centre when
//   (a) no border vertex is reachable from c along edges through vertices within
//       `border_clearance` (10) ē of c;
//   (b) the region is a topological disk (connected by construction, Euler characteristic 1)
//       containing every face around c, and no face of it is degenerate (zero cross product);
//   (e) every face normal N of the region is within `max_rough_normal_angle_degrees` (75°) of
//       the patch normal Z (below): every face faces the light plane, Z·N > cos 75° ≈ 0.26, so
//       the highlight distance (eq. 1 divides by Z·N) is defined and at most ~4 times denser
//       than under the lights anywhere in the region.
// - *Smooth patch*: a candidate that also satisfies
//   (c) every edge between two faces of the region has a dihedral angle (angle between the two
//       face normals) of at most `max_dihedral_degrees` (25°): no crease or sharp feature;
//   (d) every face normal of the region is within `max_normal_angle_degrees` (45°) of Z: at
//       45° the lines are at most √2 times denser than under the lights, so the lights sweep
//       the whole region evenly; beyond it they graze the surface. With (c) this also keeps the
//       region a height field over the plane ⟂ Z, which the dent along the normals assumes.
//   Any other candidate is a *rough patch* (coarse meshes such as bunny.off and spot.off have
//   no smooth patch at the 8 ē region scale: the 10th percentile of their largest dihedral is
//   45° / 31°).
//   None of the thresholds depends on the mesh: (c) separates smooth tessellations (a few
//   degrees between neighbouring faces at 10–20 edges per curvature radius) from features;
//   (d) and (e) are the geometry of the light setup.
// - *Smoothness score* of a candidate: its largest dihedral angle (c), then (on ties) its
//   largest normal angle to Z (d); lower is smoother.
// - *Centres*: the mesh's vertices are shuffled with a std::mt19937 seeded with `seed`
//   (portable Fisher–Yates on the raw generator output, identical on every standard library),
//   then examined in that order; a vertex is kept when it is a smooth patch and its region
//   cannot overlap an already kept one (|c_a - c_b| > ρ_a + ρ_b), until `max_centres` are kept.
//   This draws uniformly among the smooth patches, spread apart. If fewer are kept (the whole
//   mesh was examined) and `fill_with_rough` is set (the default), the mesh is filled up with
//   its smoothest rough patches: the rough candidates, ordered by smoothness score (ties in the
//   shuffled order), are examined in that order and kept under the same overlap rule, until
//   `max_centres` are kept. So the smooth patches come first, and every mesh with a candidate
//   gives cases; each case says whether its patch is smooth (`Real_dent_case::smooth`).
// - *Dent* (one case per depth in `depths`, in ē: 1 and 0.3): every vertex of the region within
//   R = `dent_radius` (5) ē of c moves by -depth (1 - (r/R)²)³ N, N its vertex normal on the
//   undented mesh, r its distance to c. The region's border lies 7–8 ē from c and the movable
//   vertices of fair_with_highlight_lines() are two rings inside it, so on a regular patch the
//   dented vertices are all movable (`dented_vertices` lets a caller check it).
// - *Lights*: Z = the region's area-weighted mean normal (normalised sum of its faces' cross
//   products); H = a unit vector ⟂ Z drawn from a std::mt19937 seeded with std::seed_seq{seed,
//   centre index} (deterministic); A0 = c + 2ρ Z (a light plane above the patch); spacing
//   s = (max d - min d) / `levels_across` (10), d = ((P - A0) x H)·N / (Z·N) the package's
//   highlight distance of every region vertex P of the undented mesh with its normal N, so that
//   about 10 lights (9 to 11 levels) cross the region.
//
// - *Jitter* (scan-like triangulations; `jitter` J in ē_g, 0 by default: no jitter, the cases
//   above bit for bit): jitter_tangentially() moves every vertex of the mesh by a random vector
//   drawn uniformly in the disk of radius J ē_g of the plane orthogonal to its vertex normal
//   (both taken on the unjittered mesh), which leaves the surface nearly where it was but
//   skews its triangles: at J = 0.3–0.45 slivers with corners of a few degrees and folded
//   triangles appear, as in scanned meshes. The generator is a std::mt19937 seeded with
//   std::seed_seq{seed, 0x6a69, 0x74746572} ("jitter"), independent of the centre draw. The
//   jittered patches are rougher, so the centres and their regions are chosen on the
//   *unjittered* mesh as above (`smooth` and the candidate criteria refer to it; the jitter
//   does not change the connectivity, so the regions remain valid); then the mesh is jittered
//   and everything else is computed on the jittered mesh as above: ē (with the jittered ē_g),
//   ρ, Z, the largest dihedral and normal angles reported, the lights, the vertex normals and
//   the dent. The jittered, undented mesh is the truth and the mesh the dent is pressed into.
//
// Helpers: count_flipped_faces() (faces whose normal turned by more than 90° from a reference
// of the same connectivity), count_moved_vertices_outside() / only_given_vertices_moved()
// (bit-exact comparison of every other vertex point), levels_in_region() (the light indices of
// the highlight lines computed on the region only), region_triangle_quality() (the smallest
// corner angle, the slivers and the folded triangles of a region).

#include "test_meshes.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Highlight_lines/Light_setup.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/compute_highlight_lines.h>
#include <CGAL/function_objects.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace Highlight_lines_benchmark {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Dent_kernel;
typedef CGAL::Surface_mesh<Dent_kernel::Point_3> Dent_mesh;
typedef CGAL::Highlight_lines::Light_setup<Dent_kernel> Dent_lights;

/// The parameters of make_real_dent_cases() (see the file comment); lengths in ē.
struct Real_dent_options
{
  std::size_t max_centres = 3;
  double region_radius = 8;
  double border_clearance = 10;
  double dent_radius = 5;
  std::vector<double> depths = {1.0, 0.3};
  double max_dihedral_degrees = 25;           // (c), smooth patches
  double max_normal_angle_degrees = 45;       // (d), smooth patches
  double max_rough_normal_angle_degrees = 75; // (e), every candidate
  bool fill_with_rough = true;                // fill up with the smoothest rough patches
  double levels_across = 10;
  double jitter = 0; // tangential jitter of the mesh, in ē_g (0: none; see the file comment)
};

/// One dent case.
struct Real_dent_case
{
  std::string name; // <mesh stem>_v<centre index>_d<depth in ē>
  Dent_mesh input;  // dented
  Dent_mesh truth;  // undented
  std::vector<Dent_mesh::Face_index> region;
  Dent_lights lights{Dent_kernel::Point_3(0, 0, 1), Dent_kernel::Vector_3(1, 0, 0),
                     Dent_kernel::Vector_3(0, 0, 1), 1};
  double mean_edge_length = 0; // local ē
  double dent_depth = 0;       // absolute (depth in ē times ē)
  Dent_mesh::Vertex_index centre;
  // For reports and checks.
  std::vector<Dent_mesh::Vertex_index> dented_vertices; // the vertices the dent moved
  double region_radius = 0;                             // ρ
  double max_dihedral_degrees = 0;                      // largest dihedral angle in the region
  double max_normal_angle_degrees = 0;                  // largest face normal angle to Z
  bool smooth = true; // a smooth patch (c, d), or else the smoothest rough patches (see above);
                      // with a jitter, of the unjittered mesh
  double jitter = 0;  // the tangential jitter of `truth` and `input`, in ē_g (0: none)
};

namespace real_dent_detail {

typedef Dent_kernel::Point_3 Point;
typedef Dent_kernel::Vector_3 Vector;
typedef Dent_mesh::Vertex_index Vertex;
typedef Dent_mesh::Face_index Face;

constexpr double pi = 3.14159265358979323846;

inline double length(const Vector& v)
{
  return std::sqrt(v.squared_length());
}

inline double angle_degrees(const Vector& a, const Vector& b)
{
  const double la = length(a), lb = length(b);
  const double c = (std::max)(-1.0, (std::min)(1.0, (a * b) / (la * lb)));
  return std::acos(c) * 180 / pi;
}

// Eq. 3: normalised sum of the face cross products around each vertex (zero if degenerate).
inline std::vector<Vector> vertex_normals(const Dent_mesh& mesh)
{
  std::vector<Vector> normal(mesh.number_of_vertices(), CGAL::NULL_VECTOR);
  for (Face f : mesh.faces()) {
    const Vector c = test::face_cross_product(mesh, f);
    for (Vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      normal[std::size_t(v)] = normal[std::size_t(v)] + c;
  }
  for (Vector& n : normal) {
    const double l = length(n);
    if (l > 0)
      n = n / l;
  }
  return normal;
}

// Marks over the indices of one kind of mesh element, cleared in O(1) between uses (the
// candidates are examined around every vertex of a mesh: no per-call set or allocation).
class Marks
{
public:
  void clear(std::size_t n)
  {
    if (mark_.size() < n)
      mark_.resize(n, 0);
    if (++stamp_ == 0) {
      std::fill(mark_.begin(), mark_.end(), 0u);
      stamp_ = 1;
    }
  }
  bool contains(std::size_t i) const { return mark_[i] == stamp_; }
  // Whether i was not marked yet (it is now).
  bool insert(std::size_t i)
  {
    if (mark_[i] == stamp_)
      return false;
    mark_[i] = stamp_;
    return true;
  }

private:
  std::vector<std::uint32_t> mark_;
  std::uint32_t stamp_ = 0;
};

// The working memory of examine(), reused from candidate to candidate.
struct Scratch
{
  bool mesh_has_border = true; // if not, no border is nearby (a) anywhere: not searched
  Marks faces, vertices, edges, evaluated;
  std::vector<char> within; // of the vertices `evaluated`: within the ball
  std::vector<Vertex> front;
  std::vector<Dent_mesh::Edge_index> edge_list;
};

// The faces reached from the faces around `c` across edges, through faces whose three vertices
// lie within `radius` of c, in breadth-first order. Empty if c is isolated. Leaves the result
// marked in `scratch.faces`.
inline std::vector<Face> ball_component(const Dent_mesh& mesh, Vertex c, double radius,
                                        Scratch& scratch)
{
  const Point& centre = mesh.point(c);
  const double r2 = radius * radius;
  scratch.evaluated.clear(mesh.number_of_vertices());
  scratch.within.resize(mesh.number_of_vertices());
  scratch.faces.clear(mesh.number_of_faces());
  auto inside = [&](Face f) {
    for (Vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      const std::size_t i = std::size_t(v);
      if (scratch.evaluated.insert(i))
        scratch.within[i] = CGAL::squared_distance(mesh.point(v), centre) <= r2;
      if (!scratch.within[i])
        return false;
    }
    return true;
  };
  std::vector<Face> result;
  if (mesh.halfedge(c) == Dent_mesh::null_halfedge())
    return result;
  for (Face f : CGAL::faces_around_target(mesh.halfedge(c), mesh))
    if (f != Dent_mesh::null_face() && !scratch.faces.contains(std::size_t(f)) && inside(f)) {
      scratch.faces.insert(std::size_t(f));
      result.push_back(f);
    }
  for (std::size_t i = 0; i < result.size(); ++i)
    for (auto h : CGAL::halfedges_around_face(mesh.halfedge(result[i]), mesh)) {
      const Face g = mesh.face(mesh.opposite(h));
      if (g != Dent_mesh::null_face() && !scratch.faces.contains(std::size_t(g)) && inside(g)) {
        scratch.faces.insert(std::size_t(g));
        result.push_back(g);
      }
    }
  return result;
}

// The mean length of the distinct edges of `faces`, summed in the order of the edge indices.
// Leaves the edges in `scratch.edge_list`.
inline double mean_edge_length_of(const Dent_mesh& mesh, const std::vector<Face>& faces,
                                  Scratch& scratch)
{
  scratch.edges.clear(mesh.number_of_edges());
  scratch.edge_list.clear();
  for (Face f : faces)
    for (auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
      if (scratch.edges.insert(std::size_t(mesh.edge(h))))
        scratch.edge_list.push_back(mesh.edge(h));
  std::sort(scratch.edge_list.begin(), scratch.edge_list.end());
  double sum = 0;
  for (auto e : scratch.edge_list) {
    const auto h = mesh.halfedge(e);
    sum +=
        std::sqrt(CGAL::squared_distance(mesh.point(mesh.source(h)), mesh.point(mesh.target(h))));
  }
  return scratch.edge_list.empty() ? 0.0 : sum / double(scratch.edge_list.size());
}

// Whether a border vertex is reachable from c along edges through vertices within `radius`.
inline bool border_nearby(const Dent_mesh& mesh, Vertex c, double radius, Scratch& scratch)
{
  const Point& centre = mesh.point(c);
  const double r2 = radius * radius;
  scratch.vertices.clear(mesh.number_of_vertices());
  scratch.front.assign(1, c);
  scratch.vertices.insert(std::size_t(c));
  while (!scratch.front.empty()) {
    const Vertex v = scratch.front.back();
    scratch.front.pop_back();
    if (mesh.is_border(v))
      return true;
    for (Vertex w : CGAL::vertices_around_target(mesh.halfedge(v), mesh))
      if (!scratch.vertices.contains(std::size_t(w)) &&
          CGAL::squared_distance(mesh.point(w), centre) <= r2) {
        scratch.vertices.insert(std::size_t(w));
        scratch.front.push_back(w);
      }
  }
  return false;
}

// A candidate (see the file comment), or `ok == false`; `smooth` if it is a smooth patch.
struct Patch
{
  bool ok = false, smooth = false;
  double mean_edge_length = 0, radius = 0, max_dihedral = 0, max_normal_angle = 0;
  std::vector<Face> region;
  Vector normal = CGAL::NULL_VECTOR; // Z
};

// The largest dihedral angle over the edges between two faces of `region` (each once), in
// degrees; `cross` holds the cross products of the faces of `region`, which are marked in
// `scratch.faces`.
inline double max_dihedral_degrees(const Dent_mesh& mesh, const std::vector<Face>& region,
                                   const std::vector<Vector>& cross, const Scratch& scratch)
{
  double largest = 0;
  for (std::size_t i = 0; i < region.size(); ++i)
    for (auto h : CGAL::halfedges_around_face(mesh.halfedge(region[i]), mesh)) {
      const Face g = mesh.face(mesh.opposite(h));
      if (g == Dent_mesh::null_face() || !scratch.faces.contains(std::size_t(g)) ||
          !(region[i] < g))
        continue;
      largest = (std::max)(largest, angle_degrees(cross[i], test::face_cross_product(mesh, g)));
    }
  return largest;
}

inline Patch examine(const Dent_mesh& mesh, Vertex c, double global_edge,
                     const Real_dent_options& options, Scratch& scratch)
{
  Patch patch;
  if (mesh.halfedge(c) == Dent_mesh::null_halfedge() || mesh.is_border(c))
    return patch;
  const double e =
      mean_edge_length_of(mesh, ball_component(mesh, c, 8 * global_edge, scratch), scratch);
  if (!(e > 0))
    return patch;
  // (a) no border nearby.
  if (scratch.mesh_has_border && border_nearby(mesh, c, options.border_clearance * e, scratch))
    return patch;
  // (b) a disk containing c's faces, no degenerate face. The region stays marked in
  // scratch.faces.
  std::vector<Face> region = ball_component(mesh, c, options.region_radius * e, scratch);
  for (Face f : CGAL::faces_around_target(mesh.halfedge(c), mesh))
    if (f == Dent_mesh::null_face() || !scratch.faces.contains(std::size_t(f)))
      return patch;
  scratch.vertices.clear(mesh.number_of_vertices());
  scratch.edges.clear(mesh.number_of_edges());
  std::size_t number_of_vertices = 0, number_of_edges = 0;
  Vector sum = CGAL::NULL_VECTOR;
  std::vector<Vector> cross;
  cross.reserve(region.size());
  for (Face f : region) {
    for (auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      if (scratch.vertices.insert(std::size_t(mesh.target(h)))) {
        ++number_of_vertices;
        patch.radius = (std::max)(patch.radius, std::sqrt(CGAL::squared_distance(
                                                    mesh.point(mesh.target(h)), mesh.point(c))));
      }
      number_of_edges += scratch.edges.insert(std::size_t(mesh.edge(h))) ? 1 : 0;
    }
    cross.push_back(test::face_cross_product(mesh, f));
    if (!(cross.back().squared_length() > 0))
      return patch;
    sum = sum + cross.back();
  }
  if (long(number_of_vertices) - long(number_of_edges) + long(region.size()) != 1)
    return patch;
  if (!(length(sum) > 0))
    return patch;
  const Vector Z = sum / length(sum);
  // (e), (d) normals near Z (first: the cheaper test, and the one coarse meshes fail).
  for (const Vector& n : cross)
    patch.max_normal_angle = (std::max)(patch.max_normal_angle, angle_degrees(n, Z));
  if (!(patch.max_normal_angle <= options.max_rough_normal_angle_degrees))
    return patch;
  // (c) dihedral angles.
  patch.max_dihedral = max_dihedral_degrees(mesh, region, cross, scratch);
  patch.ok = true;
  patch.smooth = patch.max_dihedral <= options.max_dihedral_degrees &&
                 patch.max_normal_angle <= options.max_normal_angle_degrees;
  patch.mean_edge_length = e;
  patch.region = std::move(region);
  patch.normal = Z;
  return patch;
}

// A chosen patch (`chosen`, examined on a mesh of the same connectivity) measured again on
// `mesh`, the jittered mesh: ē (`global_edge` is ē_g of `mesh`), ρ, Z, the largest dihedral and
// normal angles, as examine() does; the region and `smooth` are kept. `ok == false` if ē or Z
// vanish on `mesh`.
inline Patch remeasure(const Dent_mesh& mesh, Vertex c, const Patch& chosen, double global_edge,
                       Scratch& scratch)
{
  Patch patch;
  patch.smooth = chosen.smooth;
  patch.region = chosen.region;
  patch.mean_edge_length =
      mean_edge_length_of(mesh, ball_component(mesh, c, 8 * global_edge, scratch), scratch);
  scratch.faces.clear(mesh.number_of_faces());
  scratch.vertices.clear(mesh.number_of_vertices());
  Vector sum = CGAL::NULL_VECTOR;
  std::vector<Vector> cross;
  cross.reserve(patch.region.size());
  for (Face f : patch.region) {
    scratch.faces.insert(std::size_t(f));
    for (Vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      if (scratch.vertices.insert(std::size_t(v)))
        patch.radius = (std::max)(patch.radius,
                                  std::sqrt(CGAL::squared_distance(mesh.point(v), mesh.point(c))));
    cross.push_back(test::face_cross_product(mesh, f));
    sum = sum + cross.back();
  }
  if (!(patch.mean_edge_length > 0) || !(length(sum) > 0))
    return patch;
  const Vector Z = sum / length(sum);
  for (const Vector& n : cross)
    patch.max_normal_angle = (std::max)(patch.max_normal_angle, angle_degrees(n, Z));
  patch.max_dihedral = max_dihedral_degrees(mesh, patch.region, cross, scratch);
  patch.normal = Z;
  patch.ok = true;
  return patch;
}

// A uniform double in [-1, 1] from the raw generator output (portable).
inline double symmetric_unit(std::mt19937& rng)
{
  return double(rng()) / 2147483647.5 - 1.0;
}

inline std::string depth_label(double depth)
{
  std::string s = std::to_string(depth);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.')
    s.pop_back();
  return s;
}

} // namespace real_dent_detail

/// Moves every vertex of `mesh` tangentially, as a scanner's triangulation would place it: by a
/// random vector drawn uniformly in the disk of radius `amount` ē_g (ē_g the mean edge length of
/// `mesh`) of the plane orthogonal to the vertex's area-weighted normal (eq. 3), ē_g and the
/// normals taken on `mesh` before any move. The connectivity is unchanged. The vertices are
/// visited in index order and draw, from one std::mt19937 seeded with std::seed_seq{seed,
/// 0x6a69, 0x74746572}, a point of the square [-1, 1]² (two raw outputs, mapped as the centres'
/// light directions are: portable) until it lies in the unit disk; its coordinates are taken in
/// the basis (t, n x t) of the plane, t = n x a normalised, a the coordinate axis least aligned
/// with the normal n. A vertex without a normal (isolated, or only degenerate faces around it)
/// draws but stays. Nothing moves if `amount` is not positive or `mesh` has removed elements.
/// At `amount` 0.3 to 0.45 the triangles of a regular mesh become slivers with corners of a few
/// degrees, and some fold over their neighbours.
inline void jitter_tangentially(Dent_mesh& mesh, double amount, std::uint32_t seed)
{
  namespace D = real_dent_detail;
  if (!(amount > 0) || mesh.number_of_vertices() == 0 || mesh.has_garbage())
    return;
  const double radius = amount * test::mean_edge_length(mesh);
  const std::vector<D::Vector> normal = D::vertex_normals(mesh);
  std::seed_seq seq{seed, std::uint32_t(0x6a69), std::uint32_t(0x74746572)};
  std::mt19937 rng(seq);
  for (D::Vertex v : mesh.vertices()) {
    double x = 0, y = 0;
    do {
      x = D::symmetric_unit(rng);
      y = D::symmetric_unit(rng);
    } while (!(x * x + y * y <= 1));
    const D::Vector& n = normal[std::size_t(v)];
    if (!(n.squared_length() > 0))
      continue;
    const double ax = std::abs(n.x()), ay = std::abs(n.y()), az = std::abs(n.z());
    const D::Vector axis = ax <= ay && ax <= az ? D::Vector(1, 0, 0)
                           : ay <= az           ? D::Vector(0, 1, 0)
                                                : D::Vector(0, 0, 1);
    D::Vector t = CGAL::cross_product(n, axis);
    t = t / D::length(t);
    const D::Vector u = CGAL::cross_product(n, t);
    mesh.point(v) = mesh.point(v) + ((radius * x) * t + (radius * y) * u);
  }
}

/// The dent cases of `mesh` (see the file comment): up to `options.max_centres` centres, one
/// case per centre and depth, in the order centre by centre (the smooth patches first, then the
/// rough ones from the smoothest). `name` is the mesh's name (the file stem), the prefix of the
/// case names. With `options.jitter` > 0 the centres and regions are chosen on `mesh`, and the
/// cases are made on `mesh` jittered by jitter_tangentially(mesh, options.jitter, seed).
inline std::vector<Real_dent_case> make_real_dent_cases(const Dent_mesh& mesh,
                                                        const std::string& name, std::uint32_t seed,
                                                        const Real_dent_options& options = {})
{
  namespace D = real_dent_detail;
  std::vector<Real_dent_case> cases;
  if (mesh.number_of_vertices() == 0 || mesh.has_garbage())
    return cases;
  const double global_edge = test::mean_edge_length(mesh);
  const std::vector<D::Vector> normal = D::vertex_normals(mesh);

  // Candidate order: a portable Fisher–Yates shuffle.
  std::vector<D::Vertex> order(mesh.vertices().begin(), mesh.vertices().end());
  std::mt19937 rng(seed);
  for (std::size_t i = order.size(); i > 1; --i)
    std::swap(order[i - 1], order[std::size_t(rng() % i)]);

  struct Kept
  {
    D::Vertex centre;
    D::Patch patch;
  };
  std::vector<Kept> kept;
  D::Scratch scratch;
  scratch.mesh_has_border = false;
  for (D::Vertex v : mesh.vertices())
    if (mesh.is_border(v)) {
      scratch.mesh_has_border = true;
      break;
    }
  // Regions are within ρ of their centre: they cannot overlap if the centres are more than
  // ρ_a + ρ_b apart.
  auto apart = [&](D::Vertex c, double radius) {
    for (const Kept& k : kept)
      if (!(std::sqrt(CGAL::squared_distance(mesh.point(c), mesh.point(k.centre))) >
            radius + k.patch.radius))
        return false;
    return true;
  };
  // The rough candidates met on the way, with their score (the region is not kept: it is
  // computed again for the few chosen).
  struct Rough
  {
    D::Vertex centre;
    double max_dihedral, max_normal_angle, radius;
  };
  std::vector<Rough> rough;
  for (D::Vertex c : order) {
    if (kept.size() >= options.max_centres)
      break;
    D::Patch patch = D::examine(mesh, c, global_edge, options, scratch);
    if (!patch.ok)
      continue;
    if (!patch.smooth) {
      rough.push_back({c, patch.max_dihedral, patch.max_normal_angle, patch.radius});
      continue;
    }
    if (apart(c, patch.radius))
      kept.push_back({c, std::move(patch)});
  }
  if (options.fill_with_rough && kept.size() < options.max_centres) {
    std::stable_sort(rough.begin(), rough.end(), [](const Rough& a, const Rough& b) {
      return a.max_dihedral < b.max_dihedral ||
             (a.max_dihedral == b.max_dihedral && a.max_normal_angle < b.max_normal_angle);
    });
    for (const Rough& r : rough) {
      if (kept.size() >= options.max_centres)
        break;
      if (apart(r.centre, r.radius))
        kept.push_back({r.centre, D::examine(mesh, r.centre, global_edge, options, scratch)});
    }
  }

  // With a jitter, the chosen patches are measured again on the jittered mesh, and everything
  // below is computed on it (see the file comment).
  const bool jittering = options.jitter > 0;
  Dent_mesh jittered;
  std::vector<D::Vector> jittered_normal;
  if (jittering) {
    jittered = mesh;
    jitter_tangentially(jittered, options.jitter, seed);
    jittered_normal = D::vertex_normals(jittered);
    const double jittered_edge = test::mean_edge_length(jittered);
    for (Kept& k : kept)
      k.patch = D::remeasure(jittered, k.centre, k.patch, jittered_edge, scratch);
  }
  const Dent_mesh& geometry = jittering ? jittered : mesh;
  const std::vector<D::Vector>& vertex_normal = jittering ? jittered_normal : normal;

  for (const Kept& k : kept) {
    const D::Patch& patch = k.patch;
    if (!patch.ok)
      continue;
    const double e = patch.mean_edge_length;
    const D::Point centre = geometry.point(k.centre);
    const D::Vector& Z = patch.normal;

    // H: a random unit vector, made perpendicular to Z.
    std::seed_seq seq{seed, std::uint32_t(std::size_t(k.centre))};
    std::mt19937 h_rng(seq);
    D::Vector H = CGAL::NULL_VECTOR;
    while (!(D::length(H) > 0.1)) {
      const D::Vector v(D::symmetric_unit(h_rng), D::symmetric_unit(h_rng),
                        D::symmetric_unit(h_rng));
      if (D::length(v) > 1 || D::length(v) < 0.1)
        continue;
      H = v - (v * Z) * Z;
    }
    H = H / D::length(H);
    H = H - (H * Z) * Z; // once more, against rounding
    H = H / D::length(H);
    const D::Point A0 = centre + 2 * patch.radius * Z;

    std::set<D::Vertex> region_vertices;
    for (D::Face f : patch.region)
      for (D::Vertex v : CGAL::vertices_around_face(geometry.halfedge(f), geometry))
        region_vertices.insert(v);
    double dmin = std::numeric_limits<double>::infinity(), dmax = -dmin;
    for (D::Vertex v : region_vertices) {
      const D::Vector& N = vertex_normal[std::size_t(v)];
      const double d = (CGAL::cross_product(geometry.point(v) - A0, H) * N) / (Z * N);
      dmin = (std::min)(dmin, d);
      dmax = (std::max)(dmax, d);
    }
    const double spacing = (dmax - dmin) / options.levels_across;
    if (!(spacing > 0) || !std::isfinite(spacing))
      continue;
    const Dent_lights lights(A0, H, Z, spacing);

    const double R = options.dent_radius * e;
    for (double depth_in_e : options.depths) {
      Real_dent_case c;
      c.name =
          name + "_v" + std::to_string(std::size_t(k.centre)) + "_d" + D::depth_label(depth_in_e);
      c.truth = geometry;
      c.input = geometry;
      c.region = patch.region;
      c.lights = lights;
      c.mean_edge_length = e;
      c.dent_depth = depth_in_e * e;
      c.centre = k.centre;
      c.region_radius = patch.radius;
      c.max_dihedral_degrees = patch.max_dihedral;
      c.max_normal_angle_degrees = patch.max_normal_angle;
      c.smooth = patch.smooth;
      c.jitter = jittering ? options.jitter : 0.0;
      for (D::Vertex v : region_vertices) {
        const double u = CGAL::squared_distance(geometry.point(v), centre) / (R * R);
        if (!(u < 1))
          continue;
        const double w = (1 - u) * (1 - u) * (1 - u);
        c.input.point(v) = geometry.point(v) - (c.dent_depth * w) * vertex_normal[std::size_t(v)];
        c.dented_vertices.push_back(v);
      }
      cases.push_back(std::move(c));
    }
  }
  return cases;
}

/// The stems of the meshes of the developers' test set (../shared/data), in report order.
inline const std::array<const char*, 6>& shared_mesh_stems()
{
  static const std::array<const char*, 6> stems = {"beetle",  "bunny",      "camelhead",
                                                   "fandisk", "rocker-arm", "spot"};
  return stems;
}

/// A region of the mesh as it is, anywhere on it (no patch selection, no dent): the faces whose
/// three vertices lie within `rings` edges of `centre`.
inline std::vector<Dent_mesh::Face_index>
faces_within_rings(const Dent_mesh& mesh, Dent_mesh::Vertex_index centre, int rings)
{
  std::set<Dent_mesh::Vertex_index> within{centre};
  std::vector<Dent_mesh::Vertex_index> front{centre};
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<Dent_mesh::Vertex_index> next;
    for (Dent_mesh::Vertex_index v : front)
      for (Dent_mesh::Vertex_index u : CGAL::vertices_around_target(mesh.halfedge(v), mesh))
        if (within.insert(u).second)
          next.push_back(u);
    front.swap(next);
  }
  std::vector<Dent_mesh::Face_index> region;
  for (Dent_mesh::Face_index f : mesh.faces()) {
    bool inside = true;
    for (Dent_mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      inside = inside && within.count(v) != 0;
    if (inside)
      region.push_back(f);
  }
  return region;
}

/// `count` vertices drawn uniformly with std::mt19937(seed) (repeats possible): the centres of
/// the undented regions of benchmark_real_dents --anywhere and of the tests.
inline std::vector<Dent_mesh::Vertex_index> seeded_vertices(const Dent_mesh& mesh,
                                                            std::size_t count, std::uint32_t seed)
{
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::uint32_t> pick(0,
                                                    std::uint32_t(mesh.number_of_vertices() - 1));
  std::vector<Dent_mesh::Vertex_index> centres;
  for (std::size_t k = 0; k < count; ++k)
    centres.push_back(Dent_mesh::Vertex_index(pick(rng)));
  return centres;
}

/// Faces of `faces` (of two meshes of the same connectivity) whose normal turned by more than
/// 90° from `reference`: the dot product of the two cross products is <= 0 (a face that became
/// degenerate counts). Faces degenerate in `reference` are not counted.
template <typename FaceRange>
std::size_t count_flipped_faces(const Dent_mesh& mesh, const Dent_mesh& reference,
                                const FaceRange& faces)
{
  std::size_t flipped = 0;
  for (Dent_mesh::Face_index f : faces) {
    const Dent_kernel::Vector_3 r = test::face_cross_product(reference, f);
    if (r.squared_length() > 0 && !(test::face_cross_product(mesh, f) * r > 0))
      ++flipped;
  }
  return flipped;
}

/// The same over all the faces.
inline std::size_t count_flipped_faces(const Dent_mesh& mesh, const Dent_mesh& reference)
{
  return count_flipped_faces(mesh, reference, reference.faces());
}

/// Vertices not in `allowed` whose point in `mesh` differs from the one in `reference` (same
/// connectivity), compared bit for bit.
template <typename VertexRange>
std::size_t count_moved_vertices_outside(const Dent_mesh& mesh, const Dent_mesh& reference,
                                         const VertexRange& allowed)
{
  const std::set<Dent_mesh::Vertex_index> ok(allowed.begin(), allowed.end());
  std::size_t moved = 0;
  for (Dent_mesh::Vertex_index v : reference.vertices()) {
    if (ok.count(v))
      continue;
    const auto& p = mesh.point(v);
    const auto& q = reference.point(v);
    const double a[3] = {p.x(), p.y(), p.z()}, b[3] = {q.x(), q.y(), q.z()};
    if (std::memcmp(a, b, sizeof a) != 0)
      ++moved;
  }
  return moved;
}

/// Whether only vertices of `allowed` moved (bit-exact).
template <typename VertexRange>
bool only_given_vertices_moved(const Dent_mesh& mesh, const Dent_mesh& reference,
                               const VertexRange& allowed)
{
  return count_moved_vertices_outside(mesh, reference, allowed) == 0;
}

/// The shape of the triangles of a region (region_triangle_quality()).
struct Region_triangle_quality
{
  double smallest_corner_degrees = 180;      // the smallest corner angle of the region's triangles
  std::size_t slivers = 0;                   // triangles with a corner below the sliver angle
  std::vector<Dent_mesh::Face_index> folded; // the folded triangles, in the order of the region
};

/// The smallest corner angle (atan2(|u x w|, u·w) at each corner, in degrees) of the triangles
/// of `faces`, the number of *slivers* (a corner below `sliver_degrees`, 5° as
/// Fairing_report::number_of_sliver_triangles) and the *folded* triangles: those whose cross
/// product has a non-positive dot product with the sum of the unit vertex normals (eq. 3, on
/// the whole of `mesh`) of their three corners, as Fairing_report::number_of_folded_triangles.
template <typename FaceRange>
Region_triangle_quality region_triangle_quality(const Dent_mesh& mesh, const FaceRange& faces,
                                                double sliver_degrees = 5)
{
  namespace D = real_dent_detail;
  Region_triangle_quality quality;
  const std::vector<D::Vector> normal = D::vertex_normals(mesh);
  for (Dent_mesh::Face_index f : faces) {
    std::array<D::Vertex, 3> corner;
    std::size_t k = 0;
    for (D::Vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      if (k < 3)
        corner[k++] = v;
    double smallest = 180;
    D::Vector corner_normals = CGAL::NULL_VECTOR;
    for (std::size_t i = 0; i < 3; ++i) {
      const D::Point& p = mesh.point(corner[i]);
      const D::Vector u = mesh.point(corner[(i + 1) % 3]) - p;
      const D::Vector w = mesh.point(corner[(i + 2) % 3]) - p;
      smallest = (std::min)(smallest,
                            std::atan2(D::length(CGAL::cross_product(u, w)), u * w) * 180 / D::pi);
      corner_normals = corner_normals + normal[std::size_t(corner[i])];
    }
    quality.smallest_corner_degrees = (std::min)(quality.smallest_corner_degrees, smallest);
    quality.slivers += smallest < sliver_degrees ? 1 : 0;
    if (!(test::face_cross_product(mesh, f) * corner_normals > 0))
      quality.folded.push_back(f);
  }
  return quality;
}

/// The light indices of the highlight lines of `mesh` computed on `region` only.
template <typename FaceRange>
std::set<long long> levels_in_region(const Dent_mesh& mesh, const FaceRange& region,
                                     const Dent_lights& lights)
{
  const auto model =
      CGAL::compute_highlight_lines(mesh, lights, CGAL::Emptyset_iterator(),
                                    CGAL::Highlight_lines::parameters::face_range(region));
  std::set<long long> levels;
  for (const auto& line : model.lines())
    levels.insert(line.level);
  return levels;
}

} // namespace Highlight_lines_benchmark

#endif // HIGHLIGHT_LINES_BENCHMARK_REAL_DENT_CASES_H

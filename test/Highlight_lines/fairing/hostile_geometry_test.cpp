// Hostile geometry through the model and the fairing: every case ends either in a clear
// Invalid_input with the mesh bit-identical to before, or in a correct result (no NaN or
// infinity anywhere, only movable vertices moved, no triangle flipped, and what "correct" means
// for the case). The user manual's "Hostile Input" table lists these cases and their outcomes.
#include "test_meshes.h"

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Highlight_lines/fairing_building_blocks.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/compute_highlight_lines.h>
#include <CGAL/fair_with_highlight_lines.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <set>

namespace {
using namespace test;
namespace HL = CGAL::Highlight_lines;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef Surface_mesh::Face_index Face;
typedef Surface_mesh::Vertex_index Vertex;
typedef HL::Invalid_input::Problem Problem;

double bump(double x, double y)
{
  return 0.3 * std::exp(-3 * (x * x + y * y)) + 0.05 * x * y;
}

bool finite(const Point& p)
{
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
}

bool same_bits(const Surface_mesh& a, const Surface_mesh& b)
{
  if (a.number_of_vertices() != b.number_of_vertices())
    return false;
  for (Vertex v : a.vertices())
    if (std::memcmp(&a.point(v), &b.point(v), sizeof(Point)) != 0)
      return false;
  return true;
}

// The model's nodes and polylines are finite and every line refers to existing nodes.
template <typename Model>
void expect_sane_model(const Model& model, const std::vector<std::vector<Point>>& polylines)
{
  for (const auto& node : model.nodes())
    EXPECT_TRUE(finite(node.point)) << node.point;
  for (const auto& line : model.lines())
    for (std::size_t id : line.nodes)
      EXPECT_LT(id, model.nodes().size());
  for (const auto& polyline : polylines)
    for (const Point& p : polyline)
      EXPECT_TRUE(finite(p)) << p;
}

template <typename Model>
Model sane_model(const Surface_mesh& mesh, const Lights& lights)
{
  const Surface_mesh before = mesh;
  std::vector<std::vector<Point>> polylines;
  Model model = CGAL::compute_highlight_lines(mesh, lights, std::back_inserter(polylines));
  expect_sane_model(model, polylines);
  EXPECT_TRUE(same_bits(mesh, before));
  return model;
}

typedef HL::Highlight_line_model<Surface_mesh, K> Model;

// Fairs `region`; on success checks finiteness, that only movable vertices moved and that no
// triangle flipped with respect to the input, and returns the report.
HL::Fairing_report expect_correct_fairing(Surface_mesh& mesh, const std::vector<Face>& region,
                                          const Lights& lights, int iterations = 5)
{
  const Surface_mesh before = mesh;
  const HL::Fairing_report report = CGAL::fair_with_highlight_lines(
      mesh, region, lights, CGAL::parameters::number_of_iterations(iterations));
  std::vector<Vertex> movable;
  HL::movable_vertices(before, region, std::back_inserter(movable));
  const std::set<Vertex> may_move(movable.begin(), movable.end());
  EXPECT_EQ(report.number_of_movable_vertices, movable.size());
  for (Vertex v : mesh.vertices()) {
    EXPECT_TRUE(finite(mesh.point(v))) << "vertex " << v;
    if (!may_move.count(v)) {
      EXPECT_EQ(mesh.point(v), before.point(v)) << "vertex " << v << " is not movable";
    }
  }
  for (Face f : flipped_faces(before, mesh))
    ADD_FAILURE() << "face " << f << " flipped";
  for (const auto& step : report.history)
    EXPECT_TRUE(std::isfinite(step.fairness_energy) && std::isfinite(step.difference_energy));
  return report;
}

// The fairing refuses with `problem`, and the mesh is bit-identical.
void expect_refused(Surface_mesh& mesh, const std::vector<Face>& region, const Lights& lights,
                    Problem problem)
{
  const Surface_mesh before = mesh;
  try {
    CGAL::fair_with_highlight_lines(mesh, region, lights);
    ADD_FAILURE() << "no exception";
  } catch (const HL::Invalid_input& e) {
    EXPECT_EQ(e.problem(), problem) << e.what();
  }
  EXPECT_TRUE(same_bits(mesh, before));
}

// The faces whose vertices all lie within `radius` of (cx, cy) in the xy plane.
std::vector<Face> faces_within(const Surface_mesh& mesh, double cx, double cy, double radius)
{
  std::vector<Face> region;
  for (Face f : mesh.faces()) {
    bool inside = true;
    for (Vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      const Point& p = mesh.point(v);
      inside = inside && CGAL::square(p.x() - cx) + CGAL::square(p.y() - cy) < radius * radius;
    }
    if (inside)
      region.push_back(f);
  }
  return region;
}

std::vector<Face> all_faces(const Surface_mesh& mesh)
{
  return std::vector<Face>(mesh.faces().begin(), mesh.faces().end());
}

const Lights lights_above(Point(0, 0, 3), Vector(1, 0, 0), Vector(0, 0, 1), 0.04);

// ---------------------------------------------------------------------------------------------

// Two patches touching at one vertex. A Surface_mesh (like a Polyhedron_3) cannot hold a
// non-manifold vertex: reading the soup directly fails; CGAL's soup repair
// (orient_polygon_soup) duplicates the vertex, and each patch then has its own copy, on its
// border. The model treats the patches as two sheets; fairing one leaves the other untouched.
TEST(HostileGeometry, NonManifoldVertexSplitByTheSoupRepair)
{
  Soup a = grid(10, 0.1, -1, -1, bump), b = grid(10, 0.1, 0, 0, bump);
  // b's corner (0, 0) is a's corner (0, 0): one point shared by two patches.
  Soup soup = a;
  const std::size_t shared = 10 * 11 + 10; // a's vertex at (0, 0)
  std::vector<std::size_t> b_id(b.points.size());
  for (std::size_t i = 0; i < b.points.size(); ++i) {
    if (i == 0) {
      b_id[i] = shared;
      continue;
    }
    b_id[i] = soup.points.size();
    soup.points.push_back(b.points[i]);
  }
  for (const auto& t : b.triangles)
    soup.triangles.push_back({b_id[t[0]], b_id[t[1]], b_id[t[2]]});
  ASSERT_FALSE(PMP::is_polygon_soup_a_polygon_mesh(soup.triangles));

  std::vector<Point> points = soup.points;
  std::vector<std::vector<std::size_t>> polygons;
  for (const auto& t : soup.triangles)
    polygons.push_back({t[0], t[1], t[2]});
  PMP::orient_polygon_soup(points, polygons);
  ASSERT_EQ(points.size(), soup.points.size() + 1) << "the shared vertex is duplicated";
  Surface_mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(mesh));

  // Each copy has the normal of its own fan: the model is the union of the patches' models.
  const Model model = sane_model<Model>(mesh, lights_above);
  const Model model_a = sane_model<Model>(to_mesh<Surface_mesh>(a), lights_above);
  const Model model_b = sane_model<Model>(to_mesh<Surface_mesh>(b), lights_above);
  EXPECT_GT(model.lines().size(), 10u);
  EXPECT_EQ(model.lines().size(), model_a.lines().size() + model_b.lines().size());
  std::multiset<std::pair<long long, Point>> nodes, nodes_of_patches;
  for (const auto& node : model.nodes())
    nodes.insert({node.level, node.point});
  for (const Model* m : {&model_a, &model_b})
    for (const auto& node : m->nodes())
      nodes_of_patches.insert({node.level, node.point});
  EXPECT_EQ(nodes, nodes_of_patches);

  // Fairing the middle of patch a: patch b does not move.
  Surface_mesh faired = mesh;
  const auto report =
      expect_correct_fairing(faired, faces_within(mesh, -0.5, -0.5, 0.45), lights_above);
  EXPECT_GT(report.number_of_movable_vertices, 5u);
  for (Vertex v : mesh.vertices())
    if (mesh.point(v).x() >= 0 && mesh.point(v).y() >= 0) {
      EXPECT_EQ(faired.point(v), mesh.point(v));
    }
  // A region around the shared point: its copies are border vertices and stay where they are.
  Surface_mesh around = mesh;
  expect_correct_fairing(around, faces_within(mesh, 0, 0, 0.7), lights_above);
  for (Vertex v : mesh.vertices())
    if (mesh.point(v) == Point(0, 0, bump(0, 0))) {
      EXPECT_EQ(around.point(v), mesh.point(v));
    }
}

// An annulus and a grid with two holes: lines end on the borders; the fairing between the
// borders works and keeps the border vertices.
TEST(HostileGeometry, MultipleBorders)
{
  Soup soup;
  const int around = 64, across = 16;
  for (int j = 0; j <= across; ++j)
    for (int i = 0; i < around; ++i) {
      const double r = 1 + double(j) / across, a = 2 * CGAL_PI * i / around;
      soup.points.emplace_back(r * std::cos(a), r * std::sin(a),
                               0.2 * r * r + 0.02 * std::sin(3 * a));
    }
  auto id = [&](int i, int j) { return std::size_t(j * around + (i % around)); };
  for (int j = 0; j < across; ++j)
    for (int i = 0; i < around; ++i) {
      soup.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      soup.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  Surface_mesh annulus = to_mesh<Surface_mesh>(soup);
  std::vector<Surface_mesh::Halfedge_index> borders;
  PMP::extract_boundary_cycles(annulus, std::back_inserter(borders));
  ASSERT_EQ(borders.size(), 2u);
  const Lights lights(Point(0, 0, 4), Vector(1, 0, 0), Vector(0, 0, 1), 0.1);
  const Model model = sane_model<Model>(annulus, lights);
  std::size_t open = 0;
  for (const auto& line : model.lines()) {
    if (line.is_closed)
      continue;
    ++open;
    for (std::size_t end : {line.nodes.front(), line.nodes.back()}) {
      const auto& node = model.nodes()[end];
      if (!node.is_on_vertex()) {
        EXPECT_TRUE(CGAL::is_border_edge(node.halfedge, annulus)) << "open lines end on a border";
      }
    }
  }
  EXPECT_GT(open, 4u);
  Surface_mesh faired = annulus;
  const auto report = expect_correct_fairing(faired, faces_within(annulus, 0, -1.5, 0.45), lights);
  EXPECT_GT(report.number_of_movable_vertices, 5u);

  // A grid with two holes; the region surrounds one of them.
  Soup holes = grid(24, 1.0 / 12, -1, -1, bump);
  auto cell_centre = [&](const std::array<std::size_t, 3>& t) {
    const Point& p = holes.points[t[0]];
    const Point& q = holes.points[t[1]];
    const Point& r = holes.points[t[2]];
    return Point((p.x() + q.x() + r.x()) / 3, (p.y() + q.y() + r.y()) / 3, 0);
  };
  std::vector<std::array<std::size_t, 3>> kept;
  for (const auto& t : holes.triangles) {
    const Point c = cell_centre(t);
    if (CGAL::squared_distance(c, Point(-0.4, 0, 0)) > 0.02 &&
        CGAL::squared_distance(c, Point(0.5, 0.3, 0)) > 0.02)
      kept.push_back(t);
  }
  holes.triangles = kept;
  Surface_mesh holed = to_mesh<Surface_mesh>(holes);
  borders.clear();
  PMP::extract_boundary_cycles(holed, std::back_inserter(borders));
  ASSERT_EQ(borders.size(), 3u);
  sane_model<Model>(holed, lights_above);
  Surface_mesh faired_holed = holed;
  expect_correct_fairing(faired_holed, faces_within(holed, -0.4, 0, 0.6), lights_above);
}

// Needles (aspect ratio 1e-7) and tiny triangles (1e-12 of the others' area) inside a region.
TEST(HostileGeometry, TinyAndNeedleTriangles)
{
  Soup soup = grid(16, 0.125, -1, -1, bump);
  // A sliver: a vertex 1e-8 away from the midpoint of the diagonal (a, b) of the cell at the
  // centre splits the triangle below the diagonal into two triangles and a sliver (a, needle, b)
  // of aspect ratio about 1e-7.
  auto index = [](int i, int j) { return std::size_t(j * 17 + i); };
  const std::size_t a = index(8, 8), b = index(9, 9);
  const Point m = CGAL::midpoint(soup.points[a], soup.points[b]);
  soup.points.emplace_back(m.x() + 1e-8, m.y() - 1e-8, m.z());
  const std::size_t needle = soup.points.size() - 1;
  // A tiny triangle: a vertex 1e-6 from a corner of another cell, splitting it into three.
  const std::size_t c = index(6, 8);
  const Point& pc = soup.points[c];
  soup.points.emplace_back(pc.x() + 1e-6, pc.y() + 0.5e-6, bump(pc.x() + 1e-6, pc.y() + 0.5e-6));
  const std::size_t tiny = soup.points.size() - 1;
  std::vector<std::array<std::size_t, 3>> triangles;
  for (const auto& t : soup.triangles) {
    const std::set<std::size_t> corners(t.begin(), t.end());
    if (corners.count(a) && corners.count(b) && corners.count(index(9, 8))) {
      triangles.push_back({a, index(9, 8), needle});
      triangles.push_back({index(9, 8), b, needle});
      triangles.push_back({a, needle, b});
    } else if (t[0] == c && t[1] == index(7, 8)) { // the cell to the right of c, lower triangle
      triangles.push_back({t[0], t[1], tiny});
      triangles.push_back({t[1], t[2], tiny});
      triangles.push_back({t[2], t[0], tiny});
    } else {
      triangles.push_back(t);
    }
  }
  soup.triangles = triangles;
  Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  ASSERT_EQ(mesh.number_of_faces(), 16u * 16u * 2u + 2u + 2u);
  ASSERT_TRUE(CGAL::is_triangle_mesh(mesh));
  sane_model<Model>(mesh, lights_above);
  Surface_mesh faired = mesh;
  const auto report = expect_correct_fairing(faired, faces_within(mesh, 0, 0, 0.6), lights_above);
  EXPECT_GT(report.number_of_movable_vertices, 20u);
}

// A triangle folded in the input (a vertex pushed across the opposite edge of one of its
// triangles, whose normal then opposes its corners' vertex normals) inside a dented region, as
// strong jitter makes them: the fairing may turn it (it unfolds or stays folded, never
// degenerates) and judges flips on the others. Judging the folded one against its input normal
// stalled the steps until every one "would flip a triangle".
TEST(HostileGeometry, FoldedTriangleInTheRegion)
{
  auto dented = [](double x, double y) {
    const double r2 = (x * x + y * y) / 0.25;
    return bump(x, y) - (r2 < 1 ? 0.05 * (1 - r2) * (1 - r2) * (1 - r2) : 0.0);
  };
  Soup soup = grid(16, 0.125, -1, -1, dented);
  auto index = [](int i, int j) { return std::size_t(j * 17 + i); };
  Point& p = soup.points[index(9, 8)];
  p = Point(p.x() - 0.16, p.y() + 0.1, dented(p.x() - 0.16, p.y() + 0.1));
  Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  const auto region = faces_within(mesh, 0, 0, 0.7);
  // The fold is there, in the region: it counts as flipped if its input normal is kept.
  Surface_mesh flat = mesh;
  for (Vertex v : flat.vertices())
    flat.point(v) = Point(flat.point(v).x(), flat.point(v).y(), 0);
  std::size_t folded = 0;
  for (Face f : region)
    folded += face_cross_product(flat, f).z() < 0;
  ASSERT_GT(folded, 0u);
  sane_model<Model>(mesh, lights_above);
  const auto report = expect_correct_fairing(mesh, region, lights_above, 20);
  EXPECT_GT(report.iterations, 1u);
  // The report counts them, so that a user can switch to the mean curvature energy.
  EXPECT_EQ(report.number_of_folded_triangles, folded);
}

// Coincident points that are distinct vertices: a seam (the two sides of a cut along x = 0)
// behaves as two borders and stays closed; a face with two coincident corners is degenerate.
TEST(HostileGeometry, DuplicatedVertices)
{
  Soup soup = grid(16, 0.125, -1, -1, bump);
  auto index = [](int i, int j) { return std::size_t(j * 17 + i); };
  std::map<std::size_t, std::size_t> copy;
  for (int j = 0; j <= 16; ++j) {
    copy[index(8, j)] = soup.points.size();
    soup.points.push_back(soup.points[index(8, j)]);
  }
  for (auto& t : soup.triangles) {
    const double cx = (soup.points[t[0]].x() + soup.points[t[1]].x() + soup.points[t[2]].x()) / 3;
    if (cx > 0)
      for (std::size_t& v : t)
        if (copy.count(v))
          v = copy[v];
  }
  Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  sane_model<Model>(mesh, lights_above);
  Surface_mesh faired = mesh;
  const auto report = expect_correct_fairing(faired, faces_within(mesh, 0, 0, 0.7), lights_above);
  EXPECT_GT(report.number_of_movable_vertices, 10u);
  for (const auto& entry : copy)
    EXPECT_EQ(faired.point(Vertex(std::uint32_t(entry.first))),
              faired.point(Vertex(std::uint32_t(entry.second))))
        << "the seam stays closed";

  // Two distinct vertices at one point in a face: refused, the mesh untouched.
  Soup pinched = grid(16, 0.125, -1, -1, bump);
  pinched.points[index(9, 8)] = pinched.points[index(8, 8)];
  Surface_mesh degenerate = to_mesh<Surface_mesh>(pinched);
  expect_refused(degenerate, faces_within(degenerate, 0, 0, 0.7), lights_above,
                 Problem::DEGENERATE_FACE);
  try {
    CGAL::compute_highlight_lines(degenerate, lights_above, CGAL::Emptyset_iterator());
    ADD_FAILURE() << "no exception";
  } catch (const HL::Invalid_input& e) {
    EXPECT_EQ(e.problem(), Problem::DEGENERATE_FACE);
  }
}

// A fixed mesh scaled by 2^k, k = -20 .. 20 (about 1e-6 .. 1e6), and by 1e-6 and 1e6 exactly:
// model and fairing scale with it. Scaling by a power of two is exact in floating point, so
// the normalized results agree to rounding; 10^k scalings round the input, so nodes may only
// agree approximately and vertices exactly on a level may move off it.
TEST(HostileGeometry, HugeAndTinyCoordinates)
{
  const Soup soup = grid(20, 0.1, -1, -1, bump, 0.3, 5);
  const Surface_mesh reference_mesh = to_mesh<Surface_mesh>(soup);
  const Model reference = sane_model<Model>(reference_mesh, lights_above);
  Surface_mesh reference_faired = reference_mesh;
  const std::vector<Face> region = faces_within(reference_mesh, 0.1, 0, 0.6);
  expect_correct_fairing(reference_faired, region, lights_above);
  ASSERT_GT(reference.nodes().size(), 100u);

  for (double scale : {std::ldexp(1.0, -20), std::ldexp(1.0, -10), std::ldexp(1.0, 10),
                       std::ldexp(1.0, 20), 1e-6, 1e6}) {
    SCOPED_TRACE(scale);
    int exponent = 0;
    const bool exact = std::frexp(scale, &exponent) == 0.5;
    const CGAL::Aff_transformation_3<K> scaling(CGAL::SCALING, scale);
    Surface_mesh mesh = reference_mesh;
    for (Vertex v : mesh.vertices())
      mesh.point(v) = mesh.point(v).transform(scaling);
    const Lights lights = lights_above.transformed(scaling);
    const Model model = sane_model<Model>(mesh, lights);
    if (exact) {
      ASSERT_EQ(model.nodes().size(), reference.nodes().size());
      for (std::size_t i = 0; i < model.nodes().size(); ++i) {
        EXPECT_EQ(model.nodes()[i].level, reference.nodes()[i].level);
        EXPECT_LT(
            std::sqrt(CGAL::squared_distance(model.nodes()[i].point.transform(scaling.inverse()),
                                             reference.nodes()[i].point)),
            1e-12);
      }
    } else {
      EXPECT_NEAR(double(model.nodes().size()), double(reference.nodes().size()),
                  0.01 * double(reference.nodes().size()));
    }
    expect_correct_fairing(mesh, region, lights);
    double worst = 0;
    for (Vertex v : mesh.vertices())
      worst = (std::max)(
          worst, std::sqrt(CGAL::squared_distance(mesh.point(v).transform(scaling.inverse()),
                                                  reference_faired.point(v))));
    EXPECT_LT(worst, exact ? 1e-12 : 1e-6) << "normalized fairing result";
  }
}

// Coordinates around 2^400 and 2^-400, whose cubes over- and underflow double: the model (exact
// predicates) still works; the fairing, whose double arithmetic takes lengths to the fourth
// power, refuses the region with SCALE_OUT_OF_RANGE and leaves the mesh untouched.
TEST(HostileGeometry, ExtremeScales)
{
  const Soup soup = grid(10, 0.2, -1, -1, bump, 0.3, 5);
  const Surface_mesh unit = to_mesh<Surface_mesh>(soup);
  const Model reference = sane_model<Model>(unit, lights_above);
  for (int exponent : {-400, 400}) {
    SCOPED_TRACE(exponent);
    const CGAL::Aff_transformation_3<K> scaling(CGAL::SCALING, std::ldexp(1.0, exponent));
    Surface_mesh mesh = unit;
    for (Vertex v : mesh.vertices())
      mesh.point(v) = mesh.point(v).transform(scaling);
    const Lights lights = lights_above.transformed(scaling);
    const Model model = sane_model<Model>(mesh, lights);
    ASSERT_EQ(model.nodes().size(), reference.nodes().size());
    for (std::size_t i = 0; i < model.nodes().size(); ++i)
      EXPECT_EQ(model.nodes()[i].level, reference.nodes()[i].level);
    expect_refused(mesh, faces_within(mesh, 0, 0, 0.6 * std::ldexp(1.0, exponent)), lights,
                   Problem::SCALE_OUT_OF_RANGE);
  }
}

// Every normal parallel to the light plane (Z·N = 0): a plane z = 0 under lights whose plane
// is x = const, and a cylinder whose axis is Z. d is undefined at every vertex: no node, no
// line; the fairing has no target and fairs by q_fair alone.
TEST(HostileGeometry, AllNormalsParallelToTheLightPlane)
{
  const Lights sideways(Point(5, 0, 0), Vector(0, 1, 0), Vector(1, 0, 0), 0.05);
  Surface_mesh plane =
      to_mesh<Surface_mesh>(grid(12, 1.0 / 6, -1, -1, [](double, double) { return 0.0; }));
  const Model model = sane_model<Model>(plane, sideways);
  EXPECT_EQ(model.nodes().size(), 0u);
  EXPECT_EQ(model.lines().size(), 0u);
  EXPECT_EQ(model.number_of_undefined_vertices(), plane.number_of_vertices());
  Surface_mesh faired_plane = plane;
  const auto report =
      expect_correct_fairing(faired_plane, faces_within(plane, 0, 0, 0.7), sideways);
  EXPECT_EQ(report.number_of_lines_targeted, 0u);
  EXPECT_TRUE(report.converged()) << "a plane is already fair";
  for (Vertex v : faired_plane.vertices())
    EXPECT_LT(std::abs(faired_plane.point(v).z()), 1e-12);

  // Cylinder around the y axis, lights with Z = y.
  Surface_mesh cylinder = to_mesh<Surface_mesh>(cylinder_patch(1, 1.2, 2, 24, 16));
  const Lights along_axis(Point(0, 5, 0), Vector(1, 0, 0), Vector(0, 1, 0), 0.05);
  const Model cylinder_model = sane_model<Model>(cylinder, along_axis);
  EXPECT_EQ(cylinder_model.nodes().size(), 0u);
  std::vector<Face> region;
  for (Face f : cylinder.faces()) {
    bool inside = true;
    for (Vertex v : CGAL::vertices_around_face(cylinder.halfedge(f), cylinder))
      inside = inside && std::abs(cylinder.point(v).x()) < 0.6 &&
               std::abs(cylinder.point(v).y() - 1) < 0.6;
    if (inside)
      region.push_back(f);
  }
  Surface_mesh faired_cylinder = cylinder;
  EXPECT_EQ(expect_correct_fairing(faired_cylinder, region, along_axis).number_of_lines_targeted,
            0u);
}

// The region is the whole mesh: of an open patch (the movable vertices are those two rings
// away from the border; lines cross the border, not the region's edge, so they get no target)
// and of a closed sphere (every vertex movable, no node outside: no target).
TEST(HostileGeometry, RegionCoversTheWholeMesh)
{
  Surface_mesh patch = to_mesh<Surface_mesh>(grid(12, 1.0 / 6, -1, -1, bump));
  const auto report = expect_correct_fairing(patch, all_faces(patch), lights_above);
  EXPECT_EQ(report.number_of_movable_vertices, 9u * 9u);
  EXPECT_EQ(report.number_of_lines_targeted, 0u);

  Surface_mesh sphere_mesh = to_mesh<Surface_mesh>(sphere(1, 3));
  const Lights lights(Point(0, 0, 3), Vector(1, 0, 0), Vector(0, 0, 1), 0.2);
  const auto closed = expect_correct_fairing(sphere_mesh, all_faces(sphere_mesh), lights);
  EXPECT_EQ(closed.number_of_movable_vertices, sphere_mesh.number_of_vertices());
  EXPECT_EQ(closed.number_of_lines_targeted, 0u);
}

// Too small regions: a single face, and a ring of faces around a vertex (the vertex is inside
// the region, its neighbours are not). Refused with NO_MOVABLE_VERTEX, the mesh untouched; the
// model on a single face (face_range) works.
TEST(HostileGeometry, RegionsWithoutMovableVertex)
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(grid(12, 1.0 / 6, -1, -1, bump));
  const Face single = *mesh.faces().begin();
  expect_refused(mesh, {single}, lights_above, Problem::NO_MOVABLE_VERTEX);
  Surface_mesh closed = to_mesh<Surface_mesh>(sphere(1, 2));
  expect_refused(closed, {*closed.faces().begin()}, lights_above, Problem::NO_MOVABLE_VERTEX);

  const Vertex centre(std::uint32_t(6 * 13 + 6));
  std::vector<Face> ring;
  for (Face f : CGAL::faces_around_target(mesh.halfedge(centre), mesh))
    ring.push_back(f);
  ASSERT_EQ(ring.size(), 6u);
  expect_refused(mesh, ring, lights_above, Problem::NO_MOVABLE_VERTEX);

  const Surface_mesh before = mesh;
  std::vector<std::vector<Point>> polylines;
  const auto model =
      CGAL::compute_highlight_lines(mesh, lights_above, std::back_inserter(polylines),
                                    HL::parameters::face_range(std::vector<Face>{single}));
  expect_sane_model(model, polylines);
  for (const auto& line : model.lines())
    EXPECT_LE(line.nodes.size(), 2u) << "a segment across the face";
  EXPECT_TRUE(same_bits(mesh, before));
}

} // namespace

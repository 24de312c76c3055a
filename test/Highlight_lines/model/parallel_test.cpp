// CGAL::Parallel_tag gives bit for bit the sequential model: same nodes (positions, levels,
// carriers, parameters, degrees), same lines in the same canonical order, same counts; on
// real meshes of the shared data set, on a refined one (many chunks per pass), with vertices
// exactly on levels (vertex nodes, highlight edges), capped edges and face ranges, across
// sweeps of one sweeper, and after update_positions(). Errors name the same element. A model
// computed into an existing model object (Highlight_line_sweeper::compute(lights, model)) is
// the fresh one, whatever the object held before, and a const sweeper computes from several
// threads at once.
// The identity tests need TBB (CGAL_LINKED_WITH_TBB); without it only the fallback of
// Parallel_if_available_tag is checked.
#include "test_meshes.h"

#include <CGAL/Highlight_lines/Highlight_line_sweeper.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/compute_highlight_lines.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace test;
namespace HL = CGAL::Highlight_lines;

template <typename Model>
void expect_identical(const Model& a, const Model& b, const std::string& what)
{
  ASSERT_EQ(a.nodes().size(), b.nodes().size()) << what;
  ASSERT_EQ(a.lines().size(), b.lines().size()) << what;
  EXPECT_EQ(a.number_of_segments(), b.number_of_segments()) << what;
  EXPECT_EQ(a.number_of_skipped_edges(), b.number_of_skipped_edges()) << what;
  EXPECT_EQ(a.number_of_undefined_vertices(), b.number_of_undefined_vertices()) << what;
  EXPECT_EQ(a.number_of_out_of_range_vertices(), b.number_of_out_of_range_vertices()) << what;
  auto same_bits = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  for (std::size_t i = 0; i < a.nodes().size(); ++i) {
    const auto& p = a.nodes()[i];
    const auto& q = b.nodes()[i];
    ASSERT_TRUE(same_bits(p.point.x(), q.point.x()) && same_bits(p.point.y(), q.point.y()) &&
                same_bits(p.point.z(), q.point.z()))
        << what << ": node " << i << " at " << p.point << " vs " << q.point;
    ASSERT_EQ(p.level, q.level) << what << ": node " << i;
    ASSERT_EQ(p.halfedge, q.halfedge) << what << ": node " << i;
    ASSERT_EQ(p.vertex, q.vertex) << what << ": node " << i;
    ASSERT_TRUE(same_bits(p.parameter, q.parameter)) << what << ": node " << i;
    ASSERT_EQ(p.degree, q.degree) << what << ": node " << i;
  }
  for (std::size_t i = 0; i < a.lines().size(); ++i) {
    ASSERT_EQ(a.lines()[i].level, b.lines()[i].level) << what << ": line " << i;
    ASSERT_EQ(a.lines()[i].is_closed, b.lines()[i].is_closed) << what << ": line " << i;
    ASSERT_EQ(a.lines()[i].nodes, b.lines()[i].nodes) << what << ": line " << i;
  }
}

// compute_highlight_lines() with both tags, polylines included.
template <typename Tag, typename NamedParameters>
void expect_tag_agrees(const Surface_mesh& mesh, const Lights& lights, const NamedParameters& np,
                       const std::string& what)
{
  std::vector<std::vector<Point>> serial_lines, parallel_lines;
  const auto serial =
      CGAL::compute_highlight_lines(mesh, lights, std::back_inserter(serial_lines), np);
  const auto parallel =
      CGAL::compute_highlight_lines<Tag>(mesh, lights, std::back_inserter(parallel_lines), np);
  ASSERT_GT(serial.nodes().size(), 0u) << what;
  expect_identical(serial, parallel, what);
  EXPECT_EQ(serial_lines, parallel_lines) << what;
}

Surface_mesh shared_mesh(const std::string& name, int subdivisions = 0)
{
  Surface_mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(shared_data(name), mesh))
    ADD_FAILURE() << "cannot read " << shared_data(name);
  if (subdivisions > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(
        mesh, CGAL::parameters::number_of_iterations(subdivisions));
  return mesh;
}

// A flat grid (d = x exactly: vertices on levels, highlight edges along y) with a smooth bump
// in one corner; about 2 x 300^2 faces, so that every pass has many chunks.
Surface_mesh flat_grid_with_bump()
{
  return to_mesh<Surface_mesh>(grid(300, 0.125, -18.75, -18.75, [](double x, double y) {
    const double r2 = (x - 8) * (x - 8) + (y - 8) * (y - 8);
    return r2 < 36 ? 0.5 * std::pow(1 - r2 / 36, 3) : 0.0;
  }));
}
const Lights flat_grid_lights(Point(0, 0, 1), Vector(0, 1, 0), Vector(0, 0, 1), 0.25);

TEST(Parallel, IfAvailableTagAgreesWithSequential)
{
  // With TBB this is Parallel_tag, without it the sequential fallback: the same model.
  const Surface_mesh mesh = shared_mesh("spot.off");
  const Lights lights = HL::default_light_setup(mesh);
  expect_tag_agrees<CGAL::Parallel_if_available_tag>(mesh, lights,
                                                     CGAL::parameters::default_values(), "spot");
}

// Highlight_line_sweeper::compute(lights, model) overwrites a model object: whatever it held
// before (a larger or smaller model, of another mesh, other lights, vertex nodes or none), the
// result is the fresh compute(lights)'s, bit for bit, lights and counts included.
template <typename Sweeper, typename NamedParameters>
void expect_reused_model_is_fresh(const Sweeper& sweeper, const Lights& lights,
                                  typename Sweeper::Model& reused, const NamedParameters& np,
                                  const std::string& what)
{
  const typename Sweeper::Model fresh = sweeper.compute(lights, np);
  sweeper.compute(lights, reused, np);
  expect_identical(fresh, reused, what);
  EXPECT_EQ(fresh.number_of_trimmed_nodes(), reused.number_of_trimmed_nodes()) << what;
  EXPECT_TRUE(fresh.lights().base_point_array() == reused.lights().base_point_array() &&
              fresh.lights().plane_normal_array() == reused.lights().plane_normal_array() &&
              fresh.lights().light_direction_array() == reused.lights().light_direction_array() &&
              fresh.lights().spacing_value() == reused.lights().spacing_value())
      << what;
}

template <typename Tag>
void expect_reused_models_are_fresh(const std::string& tag)
{
  typedef HL::Highlight_line_sweeper<Surface_mesh, CGAL::Default, CGAL::Default, Tag> Sweeper;
  const Surface_mesh refined = shared_mesh("beetle.off", 1), small = shared_mesh("bunny.off"),
                     grid = flat_grid_with_bump();
  const Sweeper on_refined(refined), on_small(small), on_grid(grid);
  const Lights refined_lights = HL::default_light_setup(refined),
               small_lights = HL::default_light_setup(small);
  typename Sweeper::Model reused; // one object for the whole sequence
  EXPECT_TRUE(reused.nodes().empty() && reused.lines().empty());
  EXPECT_EQ(reused.number_of_segments(), 0u);
  const auto all = CGAL::parameters::default_values();
  // Large, then a sweep of one mesh, then smaller meshes and fewer lights, then larger again.
  expect_reused_model_is_fresh(on_refined, refined_lights, reused, all, tag + ": refined beetle");
  for (int step = 1; step < 4; ++step)
    expect_reused_model_is_fresh(on_refined,
                                 refined_lights.translated(refined_lights.index_direction() *
                                                           (refined_lights.spacing() * 0.3 * step)),
                                 reused, HL::parameters::facing_side_only(step % 2 == 0),
                                 tag + ": refined beetle, sweep step " + std::to_string(step));
  expect_reused_model_is_fresh(on_small, small_lights, reused, all, tag + ": bunny");
  expect_reused_model_is_fresh(on_small, small_lights, reused,
                               HL::parameters::level_range(std::make_pair(0, 1)),
                               tag + ": bunny, two lights");
  expect_reused_model_is_fresh(on_grid, flat_grid_lights, reused, all,
                               tag + ": grid, vertex nodes");
  expect_reused_model_is_fresh(on_small, small_lights, reused,
                               HL::parameters::level_range(std::make_pair(5, 4)),
                               tag + ": bunny, no light");
  EXPECT_TRUE(reused.nodes().empty() && reused.lines().empty());
  expect_reused_model_is_fresh(on_refined, refined_lights, reused,
                               HL::parameters::max_levels_per_edge(2),
                               tag + ": refined beetle, capped edges");
  expect_reused_model_is_fresh(on_grid, flat_grid_lights, reused,
                               HL::parameters::level_range(std::make_pair(-20, 40)),
                               tag + ": grid, level range");
}

TEST(Sweeper, ModelComputedIntoAnExistingOneEqualsTheFreshOne)
{
  expect_reused_models_are_fresh<CGAL::Sequential_tag>("sequential");
  expect_reused_models_are_fresh<CGAL::Parallel_if_available_tag>("parallel if available");
}

// The same on Polyhedron_3 (handles, not indices): a model reused across a larger and a smaller
// surface and a sweep step equals the fresh one.
TEST(Sweeper, ModelComputedIntoAnExistingOneOnAPolyhedron)
{
  auto bump = [](double x, double y) {
    const double r2 = (x - 1) * (x - 1) + (y - 1) * (y - 1);
    return r2 < 9 ? 0.5 * std::pow(1 - r2 / 9, 3) : 0.1 * x;
  };
  const Polyhedron large = to_mesh<Polyhedron>(grid(60, 0.125, -3.75, -3.75, bump, 0.2, 3)),
                   small = to_mesh<Polyhedron>(grid(20, 0.125, -1.25, -1.25, bump, 0.2, 5));
  typedef HL::Highlight_line_sweeper<Polyhedron> Sweeper;
  const Sweeper on_large(large), on_small(small);
  const Lights lights(Point(0.1, 0, 2), Vector(0, 1, 0), Vector(0.05, 0, 1), 0.1);
  const auto all = CGAL::parameters::default_values();
  Sweeper::Model reused;
  expect_reused_model_is_fresh(on_large, lights, reused, all, "polyhedron");
  expect_reused_model_is_fresh(on_small, lights, reused, all, "smaller polyhedron");
  expect_reused_model_is_fresh(on_large, lights.translated(lights.index_direction() * 0.03), reused,
                               HL::parameters::facing_side_only(true), "polyhedron, sweep step");
  EXPECT_FALSE(reused.nodes().empty());
}

// Highlight_line_sweeper::compute_segments(): the segments between consecutive nodes of the
// model's lines (closing segments included), each once, with the same points bit for bit, and
// nothing else; every index within the points; the same arrays with every tag, and whatever
// the arrays held before (they are reused across the calls).
typedef std::array<double, 6> Segment_bits; // its two points, the smaller first

Segment_bits segment_bits(const Point& p, const Point& q)
{
  const std::array<double, 3> a = {p.x(), p.y(), p.z()}, b = {q.x(), q.y(), q.z()};
  const std::array<double, 3>& first = a < b ? a : b;
  const std::array<double, 3>& second = a < b ? b : a;
  return {first[0], first[1], first[2], second[0], second[1], second[2]};
}

// The segments between consecutive nodes of a model's lines (closing ones included), sorted.
template <typename Model>
std::vector<Segment_bits> sorted_segments_of_lines(const Model& model)
{
  std::vector<Segment_bits> segments;
  for (const auto& line : model.lines()) {
    const std::size_t n = line.nodes.size();
    for (std::size_t i = 0; i + 1 < n + (line.is_closed ? 1 : 0); ++i)
      segments.push_back(segment_bits(model.nodes()[line.nodes[i]].point,
                                      model.nodes()[line.nodes[(i + 1) % n]].point));
  }
  std::sort(segments.begin(), segments.end());
  return segments;
}

template <typename Sweeper, typename NamedParameters>
void expect_segments_of_the_model(const Surface_mesh& mesh, const Sweeper& sweeper,
                                  const Lights& lights, std::vector<Point>& points,
                                  std::vector<std::array<unsigned int, 2>>& segments,
                                  const NamedParameters& np, const std::string& what)
{
  const typename Sweeper::Model model = sweeper.compute(lights, np);
  sweeper.compute_segments(lights, points, segments, np);
  const std::vector<Segment_bits> expected = sorted_segments_of_lines(model);
  std::vector<Segment_bits> got;
  for (const auto& segment : segments) {
    ASSERT_LT(segment[0], points.size()) << what;
    ASSERT_LT(segment[1], points.size()) << what;
    got.push_back(segment_bits(points[segment[0]], points[segment[1]]));
  }
  EXPECT_EQ(got.size(), model.number_of_segments()) << what;
  std::sort(got.begin(), got.end());
  auto same_bits = [](const std::vector<Segment_bits>& a, const std::vector<Segment_bits>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Segment_bits)) == 0);
  };
  EXPECT_TRUE(same_bits(expected, got))
      << what << ": " << got.size() << " segments, the model's lines have " << expected.size();
  EXPECT_TRUE(std::adjacent_find(got.begin(), got.end()) == got.end())
      << what << ": a segment twice";
  // The same arrays from fresh ones, and with the other tag.
  typedef HL::Highlight_line_sweeper<Surface_mesh, CGAL::Default, CGAL::Default,
                                     CGAL::Parallel_if_available_tag>
      Other;
  std::vector<Point> fresh_points;
  std::vector<std::array<std::size_t, 2>> fresh_segments;
  Other(mesh).compute_segments(lights, fresh_points, fresh_segments, np);
  EXPECT_TRUE(fresh_points == points) << what;
  ASSERT_EQ(fresh_segments.size(), segments.size()) << what;
  for (std::size_t i = 0; i < segments.size(); ++i)
    ASSERT_TRUE(fresh_segments[i][0] == segments[i][0] && fresh_segments[i][1] == segments[i][1])
        << what << ": segment " << i;
}

TEST(Sweeper, SegmentsAreThoseOfTheModelsLines)
{
  const Surface_mesh refined = shared_mesh("beetle.off", 1), small = shared_mesh("bunny.off"),
                     fandisk = shared_mesh("fandisk.off"), grid = flat_grid_with_bump();
  typedef HL::Highlight_line_sweeper<Surface_mesh> Sweeper;
  const Sweeper on_refined(refined), on_small(small), on_fandisk(fandisk), on_grid(grid);
  const Lights refined_lights = HL::default_light_setup(refined),
               small_lights = HL::default_light_setup(small),
               fandisk_lights = HL::default_light_setup(fandisk);
  std::vector<Point> points; // reused across all the calls
  std::vector<std::array<unsigned int, 2>> segments;
  const auto all = CGAL::parameters::default_values();
  expect_segments_of_the_model(refined, on_refined, refined_lights, points, segments, all,
                               "refined beetle");
  EXPECT_GT(segments.size(), 1000u);
  for (int step = 1; step < 4; ++step)
    expect_segments_of_the_model(
        refined, on_refined,
        refined_lights.translated(refined_lights.index_direction() *
                                  (refined_lights.spacing() * 0.3 * step)),
        points, segments,
        HL::parameters::combine(
            HL::parameters::facing_side_only(step % 2 == 0),
            HL::parameters::level_range(HL::default_level_range(refined, refined_lights))),
        "refined beetle, sweep step " + std::to_string(step));
  expect_segments_of_the_model(small, on_small, small_lights, points, segments, all, "bunny");
  expect_segments_of_the_model(fandisk, on_fandisk, fandisk_lights, points, segments,
                               HL::parameters::facing_side_only(true), "fandisk, facing side");
  expect_segments_of_the_model(grid, on_grid, flat_grid_lights, points, segments, all,
                               "grid, vertex nodes and highlight edges");
  expect_segments_of_the_model(refined, on_refined, refined_lights, points, segments,
                               HL::parameters::max_levels_per_edge(2),
                               "refined beetle, capped edges");
  expect_segments_of_the_model(small, on_small, small_lights, points, segments,
                               HL::parameters::level_range(std::make_pair(5, 4)),
                               "bunny, no light");
  EXPECT_TRUE(segments.empty());
}

// compute() and compute_segments() are const: several threads may call them on one sweeper at
// once (each call then works in its own memory or in the sweeper's, never in another's). Four
// threads sweep the lights over one sweeper together; every model and every segment list is
// the one a sweeper used by one thread gives.
TEST(Sweeper, ConstComputationsFromSeveralThreadsAtOnceGiveTheSequentialResults)
{
  const Surface_mesh refined = shared_mesh("beetle.off", 1);
  typedef HL::Highlight_line_sweeper<Surface_mesh> Sweeper;
  const Sweeper alone(refined), shared(refined);
  const Lights lights = HL::default_light_setup(refined);
  const int threads = 4, steps = 6;
  auto step_lights = [&](int t, int step) {
    return lights.translated(lights.index_direction() *
                             (lights.spacing() * 0.07 * (t * steps + step)));
  };
  std::vector<std::vector<Sweeper::Model>> models(threads);
  std::vector<std::vector<std::vector<std::array<unsigned int, 2>>>> segments(threads);
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t)
    workers.emplace_back([&, t] {
      std::vector<Point> points;
      for (int step = 0; step < steps; ++step) {
        models[std::size_t(t)].push_back(shared.compute(step_lights(t, step)));
        segments[std::size_t(t)].emplace_back();
        shared.compute_segments(step_lights(t, step), points, segments[std::size_t(t)].back());
      }
    });
  for (std::thread& worker : workers)
    worker.join();
  std::vector<Point> points;
  std::vector<std::array<unsigned int, 2>> expected;
  for (int t = 0; t < threads; ++t)
    for (int step = 0; step < steps; ++step) {
      const std::string what = "thread " + std::to_string(t) + ", step " + std::to_string(step);
      expect_identical(alone.compute(step_lights(t, step)),
                       models[std::size_t(t)][std::size_t(step)], what);
      alone.compute_segments(step_lights(t, step), points, expected);
      ASSERT_EQ(expected, segments[std::size_t(t)][std::size_t(step)]) << what;
    }
  EXPECT_GT(expected.size(), 1000u);
}

// The same on Polyhedron_3 (handles, not indices), with 32-bit indices into reused arrays.
TEST(Sweeper, SegmentsAreThoseOfTheModelsLinesOnAPolyhedron)
{
  auto bump = [](double x, double y) {
    const double r2 = (x - 1) * (x - 1) + (y - 1) * (y - 1);
    return r2 < 9 ? 0.5 * std::pow(1 - r2 / 9, 3) : 0.1 * x;
  };
  const Polyhedron polyhedron = to_mesh<Polyhedron>(grid(60, 0.125, -3.75, -3.75, bump, 0.2, 3));
  const HL::Highlight_line_sweeper<Polyhedron> sweeper(polyhedron);
  const Lights lights(Point(0.1, 0, 2), Vector(0, 1, 0), Vector(0.05, 0, 1), 0.1);
  std::vector<Point> points;
  std::vector<std::array<std::uint32_t, 2>> segments;
  for (int step = 0; step < 3; ++step) {
    SCOPED_TRACE("sweep step " + std::to_string(step));
    const Lights moved = lights.translated(lights.index_direction() * (0.03 * step));
    const auto model = sweeper.compute(moved);
    sweeper.compute_segments(moved, points, segments);
    const std::vector<Segment_bits> expected = sorted_segments_of_lines(model);
    std::vector<Segment_bits> got;
    for (const auto& segment : segments) {
      ASSERT_LT(segment[0], points.size());
      ASSERT_LT(segment[1], points.size());
      got.push_back(segment_bits(points[segment[0]], points[segment[1]]));
    }
    EXPECT_GT(got.size(), 100u);
    std::sort(got.begin(), got.end());
    EXPECT_TRUE(expected == got) << got.size() << " segments, the model's lines have "
                                 << expected.size();
  }
}

#ifdef CGAL_LINKED_WITH_TBB

TEST(Parallel, SharedMeshesAreBitIdentical)
{
  for (const std::string name : {"beetle.off", "bunny.off", "fandisk.off", "rocker-arm.off"}) {
    const Surface_mesh mesh = shared_mesh(name);
    const Lights lights = HL::default_light_setup(mesh);
    expect_tag_agrees<CGAL::Parallel_tag>(mesh, lights, CGAL::parameters::default_values(),
                                          name + " (all levels)");
    expect_tag_agrees<CGAL::Parallel_tag>(
        mesh, lights,
        HL::parameters::combine(HL::parameters::facing_side_only(true),
                                HL::parameters::level_range(HL::default_level_range(mesh, lights))),
        name + " (light tunnel)");
    expect_tag_agrees<CGAL::Parallel_tag>(mesh, lights, HL::parameters::max_levels_per_edge(2),
                                          name + " (capped edges)");
  }
}

TEST(Parallel, RefinedMeshIsBitIdentical)
{
  // The beetle Loop-subdivided twice: 38,656 x 16 faces, dozens of chunks per pass.
  const Surface_mesh mesh = shared_mesh("beetle.off", 2);
  const Lights lights = HL::default_light_setup(mesh);
  expect_tag_agrees<CGAL::Parallel_tag>(mesh, lights, CGAL::parameters::default_values(),
                                        "refined beetle");
  expect_tag_agrees<CGAL::Parallel_tag>(mesh, lights, HL::parameters::facing_side_only(true),
                                        "refined beetle, facing side");
  // A face range: every other block of faces.
  std::vector<Surface_mesh::Face_index> range;
  for (auto f : faces(mesh))
    if ((std::size_t(f) / 5000) % 2 == 0)
      range.push_back(f);
  expect_tag_agrees<CGAL::Parallel_tag>(mesh, lights, HL::parameters::face_range(range),
                                        "refined beetle, face range");
}

TEST(Parallel, VerticesOnLevelsAreBitIdentical)
{
  const Surface_mesh mesh = flat_grid_with_bump();
  const auto serial =
      CGAL::compute_highlight_lines(mesh, flat_grid_lights, CGAL::Emptyset_iterator());
  std::size_t vertex_nodes = 0;
  for (const auto& node : serial.nodes())
    vertex_nodes += node.is_on_vertex();
  ASSERT_GT(vertex_nodes, 1000u); // the flat part: highlight edges
  expect_tag_agrees<CGAL::Parallel_tag>(mesh, flat_grid_lights, CGAL::parameters::default_values(),
                                        "grid");
  expect_tag_agrees<CGAL::Parallel_tag>(mesh, flat_grid_lights,
                                        HL::parameters::level_range(std::make_pair(-20, 40)),
                                        "grid, level range");
}

TEST(Parallel, SweepsAndPositionUpdatesAreBitIdentical)
{
  Surface_mesh mesh = shared_mesh("beetle.off", 1);
  typedef HL::Highlight_line_sweeper<Surface_mesh> Serial;
  typedef HL::Highlight_line_sweeper<Surface_mesh, CGAL::Default, CGAL::Default, CGAL::Parallel_tag>
      Parallel;
  static_assert(std::is_same<Serial::Model, Parallel::Model>::value, "one model type");
  Serial serial(mesh);
  Parallel parallel(mesh);
  EXPECT_EQ(serial.vertex_normals().normal, parallel.vertex_normals().normal);
  const Lights lights = HL::default_light_setup(mesh);
  // Buffers are reused across sweeps: the lights move by fractions of the spacing.
  for (int step = 0; step < 6; ++step) {
    const Lights moved =
        lights.translated(lights.index_direction() * (lights.spacing() * 0.3 * step));
    const auto np = HL::parameters::facing_side_only(step % 2 == 0);
    expect_identical(serial.compute(moved, np), parallel.compute(moved, np),
                     "sweep " + std::to_string(step));
  }
  // Move every vertex a little along z, re-read the positions.
  for (auto v : vertices(mesh))
    mesh.point(v) = mesh.point(v) + Vector(0, 0, 0.001 * std::sin(100 * mesh.point(v).x()));
  serial.update_positions();
  parallel.update_positions();
  EXPECT_EQ(serial.vertex_normals().normal, parallel.vertex_normals().normal);
  expect_identical(serial.compute(lights), parallel.compute(lights), "after update_positions");
  expect_identical(Serial(mesh).compute(lights), parallel.compute(lights), "fresh sweeper");
}

TEST(Parallel, ErrorsNameTheSameElement)
{
  // Two degenerate faces far apart in face order: both report the first one.
  Surface_mesh mesh = shared_mesh("beetle.off", 2);
  std::vector<Surface_mesh::Face_index> all(faces(mesh).begin(), faces(mesh).end());
  for (std::size_t i : {all.size() - 1000, std::size_t(5000)}) {
    const auto h = halfedge(all[i], mesh);
    const Point a = mesh.point(source(h, mesh)), b = mesh.point(target(h, mesh));
    mesh.point(target(next(h, mesh), mesh)) = CGAL::midpoint(a, b);
  }
  auto problem_of = [&](auto compute) -> std::string {
    try {
      compute();
    } catch (const HL::Invalid_input& e) {
      return e.what();
    }
    return "no error";
  };
  const Lights lights = HL::default_light_setup(shared_mesh("beetle.off"));
  const std::string serial =
      problem_of([&] { CGAL::compute_highlight_lines(mesh, lights, CGAL::Emptyset_iterator()); });
  const std::string parallel = problem_of([&] {
    CGAL::compute_highlight_lines<CGAL::Parallel_tag>(mesh, lights, CGAL::Emptyset_iterator());
  });
  EXPECT_NE(serial.find("degenerate"), std::string::npos) << serial;
  EXPECT_EQ(serial, parallel);

  // Non-finite coordinates met by update_positions(): the first vertex is named.
  Surface_mesh moving = shared_mesh("beetle.off", 2);
  HL::Highlight_line_sweeper<Surface_mesh> s(moving);
  HL::Highlight_line_sweeper<Surface_mesh, CGAL::Default, CGAL::Default, CGAL::Parallel_tag> p(
      moving);
  std::vector<Surface_mesh::Vertex_index> vs(vertices(moving).begin(), vertices(moving).end());
  for (std::size_t i : {vs.size() - 10, std::size_t(3000)})
    moving.point(vs[i]) = Point(std::nan(""), 0, 0);
  EXPECT_EQ(problem_of([&] { s.update_positions(); }), problem_of([&] { p.update_positions(); }));
}

#endif // CGAL_LINKED_WITH_TBB

} // namespace

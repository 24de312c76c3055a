// The fairing's step control: flips are judged against the input and held back locally, a
// stall returns the best iterate with a status instead of throwing, and the trust region lets
// deep dents converge within the iteration bound.
#include "forwarding_solver.h"
#include "flipped_faces.h"
#include "test_meshes.h"

#include <CGAL/Highlight_lines/fairing_building_blocks.h>
#include <CGAL/Highlight_lines/internal/fairing/flip_guard.h>
#include <CGAL/fair_with_highlight_lines.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <type_traits>
#include <vector>

namespace {
using namespace test;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;
typedef Surface_mesh::Face_index Face;
typedef Surface_mesh::Vertex_index Vertex;

// A hood (n x n grid over [-1, 1]^2, jittered) with a smooth dent of `depth` around the origin.
Soup dented_hood_soup(int n, double depth, double jitter = 0.25)
{
  Soup soup = grid(n, 2.0 / n, -1, -1, hood, jitter, 17);
  for (Point& p : soup.points) {
    const double r2 = (p.x() * p.x() + p.y() * p.y()) / 0.09;
    if (r2 < 1)
      p = Point(p.x(), p.y(), p.z() - depth * (1 - r2) * (1 - r2) * (1 - r2));
  }
  return soup;
}

Surface_mesh dented_hood(int n, double depth, double jitter = 0.25)
{
  return to_mesh<Surface_mesh>(dented_hood_soup(n, depth, jitter));
}

std::vector<Face> faces_within(const Surface_mesh& mesh, double radius)
{
  std::vector<Face> region;
  for (Face f : mesh.faces()) {
    bool inside = true;
    for (Vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      inside =
          inside && mesh.point(v).x() * mesh.point(v).x() + mesh.point(v).y() * mesh.point(v).y() <
                        radius * radius;
    if (inside)
      region.push_back(f);
  }
  return region;
}

const Lights lights_above(Point(0, 0, 3), Vector(1, 0, 0), Vector(0, 0, 1), 0.06);

// Wraps the built-in solver and replaces some of its solutions, to provoke what the step control
// must handle.
struct Meddling_solver : test::Forwarding_solver
{
  int calls = 0;
  std::function<void(int call, std::vector<double>& x)> meddle;
  std::size_t n = 0;
  void resize(std::size_t size)
  {
    n = size;
    inner.resize(size);
  }
  template <typename OutputIterator>
  HL::Box_QP_report solve(OutputIterator out)
  {
    std::vector<double> x(n);
    HL::Box_QP_report report = inner.solve(x.begin());
    meddle(++calls, x);
    std::copy(x.begin(), x.end(), out);
    return report;
  }
};

std::size_t flips(const Surface_mesh& before, const Surface_mesh& after)
{
  return flipped_faces(before, after).size();
}

std::vector<Point> points_of(const Surface_mesh& mesh)
{
  std::vector<Point> points;
  for (Vertex v : mesh.vertices())
    points.push_back(mesh.point(v));
  return points;
}

// The flip rule itself: a face flips when its normal turns by more than 90 degrees from its
// input normal, or degenerates; a face folded in the input only must not degenerate.
TEST(FlipGuard, FlipIsATurnOfMoreThanARightAngleFromTheInput)
{
  using HL::internal::Vec3;
  const std::vector<std::array<int, 3>> faces = {{0, 1, 2}, {0, 1, 2}};
  const Vec3 up{0, 0, 1}, none{0, 0, 0};
  const HL::internal::Flip_guard guard(faces, {up, none}); // face 1: folded in the input
  auto with_apex = [](double x, double y, double z) {
    return std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {x, y, z}};
  };
  // Tilted by less than 90 degrees: not a flip; by more: a flip; degenerate: a flip.
  EXPECT_FALSE(guard.flips(0, with_apex(0, 1, 0)));
  EXPECT_FALSE(guard.flips(0, with_apex(0, 0.1, 5))); // normal (0, -5, 0.1): 88.9 degrees
  EXPECT_TRUE(guard.flips(0, with_apex(0, -0.1, 5))); // 91.1 degrees
  EXPECT_TRUE(guard.flips(0, with_apex(0, -1, 0)));   // upside down
  EXPECT_TRUE(guard.flips(0, with_apex(2, 0, 0)));    // collinear
  EXPECT_FALSE(guard.flips(1, with_apex(0, -1, 0)));  // folded: any orientation
  EXPECT_TRUE(guard.flips(1, with_apex(2, 0, 0)));    // but not degenerate
  std::vector<std::size_t> flipped;
  guard.flipped_faces(with_apex(0, -1, 0), flipped);
  EXPECT_EQ(flipped, std::vector<std::size_t>{0});
}

// One vertex whose solved displacement would flip its faces is held back alone: the others
// move, and the fairing ends as without the disturbance.
TEST(StepControl, AFlippingVertexHoldsBackOnlyItsNeighbourhood)
{
  const Surface_mesh input = dented_hood(24, 0.02);
  const auto region = faces_within(input, 0.5);
  Surface_mesh reference = input;
  const auto clean = CGAL::fair_with_highlight_lines(reference, region, lights_above);
  ASSERT_TRUE(clean.converged());

  // The first solution sends one vertex 100 region sizes along its normal: its faces flip.
  Meddling_solver solver;
  std::size_t disturbed = 0;
  solver.meddle = [&](int call, std::vector<double>& x) {
    if (call == 1) {
      disturbed = x.size() / 2;
      x[disturbed] = 100.0;
    }
  };
  Surface_mesh mesh = input;
  const auto report =
      CGAL::fair_with_highlight_lines(mesh, region, lights_above, HLP::qp_solver(std::ref(solver)));
  EXPECT_EQ(flips(input, mesh), 0u);
  EXPECT_TRUE(report.converged()) << HL::to_string(report.status);
  ASSERT_FALSE(report.history.empty());
  const auto& first = report.history.front();
  EXPECT_GE(first.resolves, 1u);
  EXPECT_GE(first.restrained_vertices, 1u);
  EXPECT_LE(first.restrained_vertices, 12u); // the vertex and a few neighbours, not everyone
  EXPECT_EQ(first.step_scale, 1.0);          // held back by a re-solve, not by scaling
  EXPECT_GT(first.max_displacement, 0);
  // The disturbance cost nothing in the end: the same surface, up to the solver's tolerance.
  const std::vector<Point> a = points_of(mesh), b = points_of(reference);
  double largest = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    largest = (std::max)(largest, std::sqrt(CGAL::squared_distance(a[i], b[i])));
  EXPECT_LT(largest, 1e-3);
}

// The faces of the two rings around the vertex nearest to the origin: its only movable vertex.
std::vector<Face> two_rings(const Surface_mesh& mesh)
{
  Vertex centre = *mesh.vertices().begin();
  for (Vertex v : mesh.vertices())
    if (CGAL::squared_distance(mesh.point(v), Point(0, 0, mesh.point(v).z())) <
        CGAL::squared_distance(mesh.point(centre), Point(0, 0, mesh.point(centre).z())))
      centre = v;
  std::set<Face> faces;
  for (Vertex w : CGAL::vertices_around_target(mesh.halfedge(centre), mesh))
    for (Face f : CGAL::faces_around_target(mesh.halfedge(w), mesh))
      faces.insert(f);
  return std::vector<Face>(faces.begin(), faces.end());
}

// The same on a Polyhedron_3: the held-back vertices are reported, and the fairing ends where the
// Surface_mesh one does.
TEST(StepControl, HoldingBackWorksOnAPolyhedron)
{
  const Soup soup = dented_hood_soup(24, 0.02);
  Surface_mesh surface_mesh = to_mesh<Surface_mesh>(soup);
  Polyhedron polyhedron = to_mesh<Polyhedron>(soup);
  auto disturb = [](int call, std::vector<double>& x) {
    if (call == 1)
      x[x.size() / 2] = 100.0;
  };
  auto fair = [&](auto& mesh) {
    typedef std::remove_reference_t<decltype(mesh)> Mesh;
    std::vector<typename boost::graph_traits<Mesh>::face_descriptor> region;
    for (auto f : faces(mesh)) {
      bool inside = true;
      for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh)) {
        const Point p = get(CGAL::vertex_point, mesh, v);
        inside = inside && p.x() * p.x() + p.y() * p.y() < 0.25;
      }
      if (inside)
        region.push_back(f);
    }
    Meddling_solver solver;
    solver.meddle = disturb;
    return CGAL::fair_with_highlight_lines(mesh, region, lights_above,
                                           HLP::qp_solver(std::ref(solver)));
  };
  const HL::Fairing_report on_polyhedron = fair(polyhedron);
  const HL::Fairing_report on_surface_mesh = fair(surface_mesh);
  EXPECT_TRUE(on_polyhedron.converged()) << HL::to_string(on_polyhedron.status);
  ASSERT_FALSE(on_polyhedron.history.empty());
  EXPECT_GE(on_polyhedron.history.front().resolves, 1u);
  EXPECT_GE(on_polyhedron.history.front().restrained_vertices, 1u);
  EXPECT_LE(on_polyhedron.history.front().restrained_vertices, 12u);
  EXPECT_NEAR(on_polyhedron.history.back().target_value,
              on_surface_mesh.history.back().target_value,
              1e-6 * on_surface_mesh.history.back().target_value);
}

// Records, per solve(), whether it starts a new program (set_P() called since the last solve)
// and whether it was warm-started.
struct Warm_start_recorder : Meddling_solver
{
  struct Call
  {
    bool new_program, warm;
  };
  std::vector<Call> record;
  bool assembled = false, warm = false;
  void set_P(std::size_t i, std::size_t j, double v)
  {
    assembled = true;
    inner.set_P(i, j, v);
  }
  void set_warm_start(const std::vector<double>& x0)
  {
    warm = true;
    inner.set_warm_start(x0);
  }
  template <typename OutputIterator>
  HL::Box_QP_report solve(OutputIterator out)
  {
    record.push_back({assembled, warm});
    assembled = warm = false;
    return Meddling_solver::solve(out);
  }
};

// After a step that held vertices back against flips, the next program starts cold (the held
// entries sit at bounds the flip guard set, not the program); after a free step that lowered F
// it starts from that step.
TEST(StepControl, AProgramAfterAHeldBackStepStartsCold)
{
  const Surface_mesh input = dented_hood(24, 0.02);
  const auto region = faces_within(input, 0.5);
  Surface_mesh mesh = input;
  Warm_start_recorder solver;
  solver.meddle = [](int call, std::vector<double>& x) {
    if (call == 1)
      x[x.size() / 2] = 100.0; // flips faces: held back and solved again
  };
  const auto report =
      CGAL::fair_with_highlight_lines(mesh, region, lights_above, HLP::qp_solver(std::ref(solver)));
  std::vector<bool> program_warm;
  for (const auto& call : solver.record)
    if (call.new_program)
      program_warm.push_back(call.warm);
  ASSERT_GE(program_warm.size(), 3u);
  ASSERT_GE(report.history.size(), program_warm.size());
  ASSERT_GE(report.history.front().restrained_vertices, 1u);
  std::size_t after_held = 0, warm_after_free = 0;
  for (std::size_t k = 1; k < program_warm.size(); ++k) {
    if (report.history[k - 1].restrained_vertices > 0) {
      ++after_held;
      EXPECT_FALSE(program_warm[k]) << "program " << k;
    } else if (report.history[k].target_value < report.history[k - 1].target_value) {
      warm_after_free += program_warm[k];
    }
  }
  EXPECT_GE(after_held, 1u);
  EXPECT_GE(warm_after_free, 1u); // the recorder tells warm starts apart
  EXPECT_EQ(flips(input, mesh), 0u);
}

// A solver whose every solution after the first iteration sends the only movable vertex a
// million region sizes along its normal (on this convex hood, that drags a face around it over,
// at every scale the step control tries): the fairing stops with STEP_BLOCKED instead of
// throwing, and keeps the first iteration's progress. (Sent the other way, the vertex would
// make a spike, whose faces turn by less than 90 degrees: no flip.)
TEST(StepControl, ABlockedStepReturnsTheBestIterate)
{
  const Surface_mesh input = dented_hood(24, 0.02);
  const auto region = two_rings(input);
  std::vector<Vertex> movable;
  HL::movable_vertices(input, region, std::back_inserter(movable));
  ASSERT_EQ(movable.size(), 1u);
  Surface_mesh after_one = input;
  const auto one = CGAL::fair_with_highlight_lines(after_one, region, lights_above,
                                                   CGAL::parameters::number_of_iterations(1));
  const bool first_step_helped = one.history.back().target_value < one.history.front().target_value;

  for (double direction : {1.0}) {
    Meddling_solver solver;
    solver.meddle = [direction](int call, std::vector<double>& x) {
      if (call > 1)
        x[0] = direction * 1e6;
    };
    Surface_mesh mesh = input;
    HL::Fairing_report report;
    // A threshold below the first step (7e-4 of the region's size), so that a second is tried.
    ASSERT_NO_THROW(
        report = CGAL::fair_with_highlight_lines(
            mesh, region, lights_above,
            HLP::combine(HLP::qp_solver(std::ref(solver)), HLP::convergence_threshold(1e-6))));
    EXPECT_EQ(report.status, HL::Fairing_report::Status::STEP_BLOCKED)
        << HL::to_string(report.status);
    EXPECT_EQ(report.iterations, 3u); // one step, then two blocked ones
    EXPECT_EQ(flips(input, mesh), 0u);
    EXPECT_EQ(points_of(mesh), points_of(first_step_helped ? after_one : input));
    for (const auto& step : report.history)
      EXPECT_LE(report.history.back().target_value, step.target_value);
  }
}

// Whatever stops the iteration short of convergence, the mesh returned is the iterate of lowest
// target value F.
TEST(StepControl, ANonConvergedFairingReturnsTheIterateOfLowestF)
{
  const Surface_mesh input = dented_hood(24, 0.05);
  const auto region = faces_within(input, 0.5);
  for (int bound = 1; bound <= 4; ++bound) {
    Surface_mesh mesh = input;
    const auto report = CGAL::fair_with_highlight_lines(
        mesh, region, lights_above, CGAL::parameters::number_of_iterations(bound));
    if (report.converged())
      continue;
    EXPECT_EQ(report.status, HL::Fairing_report::Status::ITERATION_LIMIT);
    for (const auto& step : report.history)
      EXPECT_LE(report.history.back().target_value, step.target_value) << "bound " << bound;
  }
}

// F stationary under steps the programs ask for (between ε and 10 ε ē: too large for the test
// on the last step, too small to matter) ends the fairing without solving a further program,
// and the mesh returned is the iterate of lowest F. From the third program on, every solution
// is rescaled to a given size, constant (the steps then overshoot the minimum and F alternates)
// or shrinking by a factor 0.8 per program (a slow tail: the fairing extrapolates it, and the
// step taken is then longer than 10 ε ē although its program asked for less). Three such
// steps with F within 0.3 % of where they started: converged, the next program not solved.
TEST(StepControl, AStationaryTargetEndsTheIterationBeforeAnotherProgram)
{
  const Surface_mesh input = dented_hood(24, 0.05);
  const auto region = faces_within(input, 0.5);
  double edge_sum = 0;
  std::size_t edges = 0;
  for (Face f : region)
    for (auto h : CGAL::halfedges_around_face(input.halfedge(f), input)) {
      edge_sum += std::sqrt(
          CGAL::squared_distance(input.point(input.source(h)), input.point(input.target(h))));
      ++edges;
    }
  const double mean_edge = edge_sum / double(edges);
  const double epsilon = 0.001; // the default convergence threshold
  struct Rescaling
  {
    double size, ratio; // the third solution's size in mean edge lengths, then per program
  };
  for (const Rescaling rescaling :
       {Rescaling{0.005, 1}, Rescaling{0.009, 1}, Rescaling{0.009, 0.8}}) {
    SCOPED_TRACE(testing::Message() << "size " << rescaling.size << ", ratio " << rescaling.ratio);
    Surface_mesh mesh = input;
    Meddling_solver solver;
    solver.meddle = [&](int call, std::vector<double>& x) {
      double largest = 0;
      for (double v : x)
        largest = (std::max)(largest, std::abs(v));
      const double size = rescaling.size * std::pow(rescaling.ratio, call - 3) * mean_edge;
      if (call >= 3 && largest > 0)
        for (double& v : x)
          v *= size / largest;
    };
    const auto report = CGAL::fair_with_highlight_lines(mesh, region, lights_above,
                                                        HLP::qp_solver(std::ref(solver)));
    ASSERT_EQ(report.status, HL::Fairing_report::Status::CONVERGED) << HL::to_string(report.status);
    EXPECT_EQ(std::size_t(solver.calls), report.iterations);
    ASSERT_GE(report.iterations, 3u);
    EXPECT_LE(report.iterations, 5u); // two free steps, three rescaled ones
    bool stretched_beyond = false;
    for (std::size_t i = 2; i < report.iterations; ++i) {
      const double asked = rescaling.size * std::pow(rescaling.ratio, double(i) - 2);
      EXPECT_NEAR(report.history[i].relative_solution_displacement, asked, 0.05 * asked);
      EXPECT_LT(report.history[i].relative_solution_displacement, 10 * epsilon);
      stretched_beyond =
          stretched_beyond || (report.history[i].extrapolation > 1 &&
                               report.history[i].relative_max_displacement > 10 * epsilon);
    }
    if (rescaling.ratio < 1) {
      EXPECT_TRUE(stretched_beyond) << "the slow tail was not extrapolated beyond 10 ε ē";
    }
    EXPECT_TRUE(report.returned_best_iterate);
    for (const auto& step : report.history)
      EXPECT_LE(report.history.back().target_value, step.target_value);
  }
}

// The same on a Polyhedron_3 (the slow tail, extrapolated): the stationary stop comes before
// another program at the same iteration as on the Surface_mesh, with the same mesh returned.
TEST(StepControl, AStationaryTargetEndsTheIterationOnAPolyhedronAsOnASurfaceMesh)
{
  const Soup soup = dented_hood_soup(24, 0.05);
  Surface_mesh surface_mesh = to_mesh<Surface_mesh>(soup);
  Polyhedron polyhedron = to_mesh<Polyhedron>(soup);
  struct Run
  {
    HL::Fairing_report report;
    int programs_solved;
    std::vector<Point> points; // in the soup's vertex order, which both meshes keep
  };
  auto fair = [&](auto& mesh) {
    typedef std::remove_reference_t<decltype(mesh)> Mesh;
    std::vector<typename boost::graph_traits<Mesh>::face_descriptor> region;
    double edge_sum = 0;
    std::size_t edges = 0;
    for (auto f : faces(mesh)) {
      bool inside = true;
      for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh)) {
        const Point p = get(CGAL::vertex_point, mesh, v);
        inside = inside && p.x() * p.x() + p.y() * p.y() < 0.25;
      }
      if (!inside)
        continue;
      region.push_back(f);
      for (auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
        edge_sum +=
            std::sqrt(CGAL::squared_distance(get(CGAL::vertex_point, mesh, source(h, mesh)),
                                             get(CGAL::vertex_point, mesh, target(h, mesh))));
        ++edges;
      }
    }
    const double mean_edge = edge_sum / double(edges);
    Meddling_solver solver;
    solver.meddle = [mean_edge](int call, std::vector<double>& x) {
      double largest = 0;
      for (double v : x)
        largest = (std::max)(largest, std::abs(v));
      if (call >= 3 && largest > 0)
        for (double& v : x)
          v *= 0.009 * std::pow(0.8, call - 3) * mean_edge / largest;
    };
    Run run;
    run.report = CGAL::fair_with_highlight_lines(mesh, region, lights_above,
                                                 HLP::qp_solver(std::ref(solver)));
    run.programs_solved = solver.calls;
    for (auto v : vertices(mesh))
      run.points.push_back(get(CGAL::vertex_point, mesh, v));
    return run;
  };
  const Run on_polyhedron = fair(polyhedron);
  const Run on_surface_mesh = fair(surface_mesh);
  const HL::Fairing_report& polyhedron_report = on_polyhedron.report;
  const HL::Fairing_report& surface_mesh_report = on_surface_mesh.report;
  ASSERT_EQ(polyhedron_report.status, HL::Fairing_report::Status::CONVERGED)
      << HL::to_string(polyhedron_report.status);
  EXPECT_EQ(surface_mesh_report.status, HL::Fairing_report::Status::CONVERGED);
  // Stopped before solving another program: two free steps, then three rescaled ones at most.
  EXPECT_EQ(std::size_t(on_polyhedron.programs_solved), polyhedron_report.iterations);
  EXPECT_GE(polyhedron_report.iterations, 3u);
  EXPECT_LE(polyhedron_report.iterations, 5u);
  EXPECT_EQ(polyhedron_report.iterations, surface_mesh_report.iterations);
  EXPECT_EQ(on_polyhedron.programs_solved, on_surface_mesh.programs_solved);
  EXPECT_TRUE(polyhedron_report.returned_best_iterate);
  EXPECT_EQ(polyhedron_report.returned_best_iterate, surface_mesh_report.returned_best_iterate);
  bool extrapolated = false;
  ASSERT_EQ(polyhedron_report.history.size(), surface_mesh_report.history.size());
  for (std::size_t i = 0; i < polyhedron_report.history.size(); ++i) {
    extrapolated = extrapolated || polyhedron_report.history[i].extrapolation > 1;
    EXPECT_NEAR(polyhedron_report.history[i].target_value,
                surface_mesh_report.history[i].target_value,
                1e-9 * surface_mesh_report.history[i].target_value);
    EXPECT_NEAR(polyhedron_report.history[i].relative_solution_displacement,
                surface_mesh_report.history[i].relative_solution_displacement,
                1e-9 + 1e-6 * surface_mesh_report.history[i].relative_solution_displacement);
  }
  EXPECT_TRUE(extrapolated) << "the slow tail was not extrapolated";
  for (const auto& step : polyhedron_report.history)
    EXPECT_LE(polyhedron_report.history.back().target_value, step.target_value);
  ASSERT_EQ(on_polyhedron.points.size(), on_surface_mesh.points.size());
  for (std::size_t i = 0; i < on_polyhedron.points.size(); ++i)
    EXPECT_LT(CGAL::squared_distance(on_polyhedron.points[i], on_surface_mesh.points[i]), 1e-20)
        << "vertex " << i;
}

// A dent several grid steps deep, wider than the bound of eq. 16 lets a vertex move in one
// iteration: the fairing converges within the default iteration bound, without flips.
TEST(StepControl, ADeepDentConvergesWithinTheIterationBound)
{
  const int n = 40;
  const double step = 2.0 / n;
  for (double depth : {1.0, 2.5}) {
    const Surface_mesh input = dented_hood(n, depth * step);
    const auto region = faces_within(input, 0.6);
    Surface_mesh mesh = input;
    const auto report = CGAL::fair_with_highlight_lines(mesh, region, lights_above);
    EXPECT_TRUE(report.converged())
        << HL::to_string(report.status) << " after " << report.iterations;
    EXPECT_LE(report.iterations, 25u);
    EXPECT_EQ(flips(input, mesh), 0u);
    EXPECT_LT(report.history.back().target_value, 0.2 * report.history.front().target_value);
  }
}

} // namespace

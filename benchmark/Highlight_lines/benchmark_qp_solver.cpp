// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Speed of Active_set_box_QP_solver on fairing-like problems, as a ratio to one unconstrained
// Eigen::SimplicialLDLT factorisation + solve of the same matrix measured in the same run.
//
// The problem: the cotangent bi-Laplacian  W^T M^-1 W  of the interior vertices of an
// irregular Delaunay disk patch (random points whose density varies across the disk, the
// boundary ring fixed), plus a sum of rank-one terms  j j^T  whose supports are those of the
// highlight nodes of the fairing (the two ends of an edge crossing a level line and their
// one-rings), plus bounds  |x_i| <= half the shortest edge at vertex i  -- the matrix and
// bounds of the fairing QP (eq. 16 of the paper). The linear term is built from a known solution: a
// smooth displacement field clamped to the bounds, with positive multipliers on the clamped
// variables, so that exactly the requested fraction of bounds is active at the optimum; the
// benchmark checks the solution found against it.
//
// Cases: n = 10^3, 10^4, 10^5 interior vertices; 5 % and 30 % of the bounds active;
//   start 0, cold        -- a new solver, no warm start;
//   start 1, warm        -- a new solver, warm start from the solution of a nearby problem
//                           (the field 1.5 % weaker and shifted by 0.01: 3 to 13 % of the
//                           active bounds differ);
//   start 2, warm_reused -- the same, with the solver object that solved the nearby problem,
//                           as the fairing iteration does (the symbolic analysis is kept);
//   start 3, warm_close  -- as warm_reused, from a closer problem (the field 0.2 % weaker and
//                           shifted by 0.002: about 1 % of the active bounds differ).
// Counters: ratio = QP time / baseline time (both measured in every iteration of the case),
// QP_ms and baseline_ms, active_percent, iterations, factorizations, relative KKT residual,
// the largest deviation from the known solution relative to the largest bound, and the
// percentage of active bounds that differ between the problem and the warm start's problem.

#include <CGAL/Highlight_lines/Active_set_box_QP_solver.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <Eigen/SparseCholesky>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <utility>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vertex_base = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using Delaunay =
    CGAL::Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<Vertex_base>>;
using Point = Kernel::Point_2;
using Sparse_matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Solver = CGAL::Highlight_lines::Active_set_box_QP_solver;

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The matrix and bounds of a fairing QP on a disk patch with n interior vertices.
struct Fairing_like_patch
{
  Sparse_matrix Q;
  Eigen::VectorXd bound; // |x_i| <= bound_i
  std::vector<Point> position;

  explicit Fairing_like_patch(int n)
  {
    std::mt19937 random(20260101u + static_cast<unsigned>(n));
    std::uniform_real_distribution<double> uniform(0., 1.);
    std::vector<std::pair<Point, int>> points;
    const int ring = static_cast<int>(2. * std::sqrt(M_PI * n)) + 8;
    for (int k = 0; k < ring; ++k) {
      const double angle = 2. * M_PI * k / ring;
      points.emplace_back(Point(std::cos(angle), std::sin(angle)), n + k);
    }
    for (int k = 0; k < n;) {
      const double x = 2. * uniform(random) - 1., y = 2. * uniform(random) - 1.;
      // inside the disk, away from the ring, with a density 3x higher on one side
      if (x * x + y * y > 0.97 || uniform(random) > 0.35 + 0.325 * (1. + x))
        continue;
      points.emplace_back(Point(x, y), k++);
    }
    const Delaunay dt(points.begin(), points.end());
    const int all = n + ring;
    position.resize(all);
    for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
      position[v->info()] = v->point();

    // Cotangent Laplacian, barycentric areas, shortest edges, one-rings.
    std::vector<Eigen::Triplet<double>> laplacian;
    std::vector<double> area(all, 0.), shortest(all, 1e300);
    std::vector<std::vector<int>> ring_of(all);
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      const int id[3] = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
      const double face_area =
          std::abs(CGAL::area(position[id[0]], position[id[1]], position[id[2]]));
      for (int e = 0; e < 3; ++e) {
        const int a = id[e], b = id[(e + 1) % 3], opposite = id[(e + 2) % 3];
        const auto u = position[a] - position[opposite], v = position[b] - position[opposite];
        const double cotangent = (u * v) / std::abs(u.x() * v.y() - u.y() * v.x());
        laplacian.emplace_back(a, b, -0.5 * cotangent);
        laplacian.emplace_back(b, a, -0.5 * cotangent);
        laplacian.emplace_back(a, a, 0.5 * cotangent);
        laplacian.emplace_back(b, b, 0.5 * cotangent);
        area[a] += face_area / 3.;
        const double length = std::sqrt(CGAL::squared_distance(position[a], position[b]));
        shortest[a] = std::min(shortest[a], length);
        shortest[b] = std::min(shortest[b], length);
        ring_of[a].push_back(b);
        ring_of[b].push_back(a);
      }
    }
    Sparse_matrix L(all, all);
    L.setFromTriplets(laplacian.begin(), laplacian.end());
    const Sparse_matrix W = L.topLeftCorner(n, n); // boundary ring fixed
    Eigen::VectorXd inverse_area(n);
    for (int i = 0; i < n; ++i)
      inverse_area[i] = 1. / area[i];
    const Sparse_matrix bilaplacian = Sparse_matrix(W.transpose()) * inverse_area.asDiagonal() * W;

    // Highlight nodes: edges crossing the level lines of a linear "distance" function.
    std::vector<Eigen::Triplet<double>> nodes;
    for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
      const int a = e->first->vertex((e->second + 1) % 3)->info();
      const int b = e->first->vertex((e->second + 2) % 3)->info();
      const auto level = [&](int v) {
        return std::floor(7. * position[v].x() + 3. * position[v].y());
      };
      if (level(a) == level(b))
        continue;
      std::vector<int> support{a, b};
      support.insert(support.end(), ring_of[a].begin(), ring_of[a].end());
      support.insert(support.end(), ring_of[b].begin(), ring_of[b].end());
      std::sort(support.begin(), support.end());
      support.erase(std::unique(support.begin(), support.end()), support.end());
      std::vector<std::pair<int, double>> j;
      for (int v : support)
        if (v < n)
          j.emplace_back(v, (v == a || v == b ? 1. : 0.3) * (uniform(random) - 0.3));
      for (const auto& p : j)
        for (const auto& q : j)
          nodes.emplace_back(p.first, q.first, p.second * q.second);
    }
    Sparse_matrix low_rank(n, n);
    low_rank.setFromTriplets(nodes.begin(), nodes.end());
    // The node term weighs about a third of the fairness term on the diagonal.
    const double weight =
        0.3 * bilaplacian.diagonal().mean() / std::max(low_rank.diagonal().mean(), 1e-300);
    Q = bilaplacian + weight * low_rank;
    Q.makeCompressed();
    bound.resize(n);
    for (int i = 0; i < n; ++i)
      bound[i] = 0.5 * shortest[i];
  }
};

// A linear term whose minimiser is known: the smooth field a * s clamped to the bounds,
// with a chosen so that the requested fraction of bounds is active, and multipliers on the
// active bounds proportional to how far the field pushes past them.
struct Known_solution_problem
{
  Eigen::VectorXd c, solution;
  std::size_t active = 0;

  Known_solution_problem(const Fairing_like_patch& patch, double active_fraction, double growth,
                         double shift)
  {
    const Eigen::Index n = patch.bound.size();
    Eigen::VectorXd field(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double x = patch.position[i].x() + shift, y = patch.position[i].y();
      field[i] = std::exp(-10. * ((x - 0.3) * (x - 0.3) + y * y)) -
                 0.8 * std::exp(-15. * ((x + 0.4) * (x + 0.4) + (y - 0.3) * (y - 0.3))) +
                 0.3 * std::sin(5. * x) * std::cos(4. * y);
    }
    std::vector<double> ratio(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i)
      ratio[i] = std::abs(field[i]) / patch.bound[i];
    // The threshold halfway between two ratios: no variable is degenerate (free on a bound).
    std::sort(ratio.begin(), ratio.end());
    const std::size_t first_active = std::size_t((1. - active_fraction) * n);
    const double amplitude = growth * 2. / (ratio[first_active - 1] + ratio[first_active]);
    solution = (amplitude * field).cwiseMax(-patch.bound).cwiseMin(patch.bound);
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(n); // at the solution
    const Eigen::VectorXd diagonal = patch.Q.diagonal();
    for (Eigen::Index i = 0; i < n; ++i) {
      const double excess = std::abs(amplitude * field[i]) - patch.bound[i];
      if (excess >= 0.) {
        ++active;
        const double multiplier = diagonal[i] * excess + 1e-3 * diagonal[i] * patch.bound[i];
        gradient[i] = field[i] > 0. ? -multiplier : multiplier;
      }
    }
    c = gradient - patch.Q * solution;
  }
};

void set_problem(Solver& solver, const Fairing_like_patch& patch,
                 const Known_solution_problem& problem);

// A problem to warm start from, solved once; its solver object is reused by the *_reused
// cases.
struct Warm_start
{
  Known_solution_problem problem;
  std::vector<double> solution;
  Solver solver;

  Warm_start(const Fairing_like_patch& patch, double active_fraction, double growth, double shift)
      : problem(patch, active_fraction, growth, shift)
  {
    set_problem(solver, patch, problem);
    solver.solve(std::back_inserter(solution));
  }
};

struct Case_data
{
  Fairing_like_patch patch;
  Known_solution_problem problem;
  Warm_start nearby, close;

  Case_data(int n, double active_fraction)
      : patch(n), problem(patch, active_fraction, 1.015, 0.01),
        nearby(patch, active_fraction, 1., 0.), close(patch, active_fraction, 1.015 / 1.002, 0.008)
  {
  }
};

// Building a patch of 10^5 vertices and solving the warm start problems takes seconds: share
// them between the cases.
Case_data& case_data(int n, int active_percent)
{
  static std::map<std::pair<int, int>, std::unique_ptr<Case_data>> cache;
  auto& slot = cache[{n, active_percent}];
  if (!slot)
    slot = std::make_unique<Case_data>(n, active_percent / 100.);
  return *slot;
}

void set_problem(Solver& solver, const Fairing_like_patch& patch,
                 const Known_solution_problem& problem)
{
  const std::size_t n = static_cast<std::size_t>(patch.bound.size());
  solver.resize(n);
  solver.set_P(patch.Q);
  for (std::size_t i = 0; i < n; ++i) {
    solver.set_q(i, problem.c[i]);
    solver.set_l(i, -patch.bound[i]);
    solver.set_u(i, patch.bound[i]);
  }
}

enum Start { COLD, WARM, WARM_REUSED, WARM_CLOSE };

void BM_box_QP(benchmark::State& state)
{
  const int n = static_cast<int>(state.range(0));
  const int active_percent = static_cast<int>(state.range(1));
  const Start start = static_cast<Start>(state.range(2));
  Case_data& data = case_data(n, active_percent);
  const Eigen::VectorXd rhs = -data.problem.c;

  double qp_seconds = 0., baseline_seconds = 0.;
  CGAL::Highlight_lines::Box_QP_report report;
  std::vector<double> x;
  for (auto _ : state) {
    // Baseline: one unconstrained factorisation + solve of the same matrix.
    auto begin = std::chrono::steady_clock::now();
    Eigen::SimplicialLDLT<Sparse_matrix> ldlt(data.patch.Q);
    Eigen::VectorXd unconstrained = ldlt.solve(rhs);
    benchmark::DoNotOptimize(unconstrained.data());
    baseline_seconds += seconds_since(begin);

    Solver fresh;
    Warm_start& warm_start = (start == WARM_CLOSE) ? data.close : data.nearby;
    Solver& used = (start == WARM_REUSED || start == WARM_CLOSE) ? warm_start.solver : fresh;

    begin = std::chrono::steady_clock::now();
    set_problem(used, data.patch, data.problem);
    if (start != COLD)
      used.set_warm_start(warm_start.solution);
    x.clear();
    report = used.solve(std::back_inserter(x));
    const double elapsed = seconds_since(begin);
    qp_seconds += elapsed;
    state.SetIterationTime(elapsed);
    if (!report.is_optimal())
      state.SkipWithError(report.message.c_str());
  }

  double deviation = 0.;
  for (Eigen::Index i = 0; i < data.problem.solution.size(); ++i)
    deviation = std::max(deviation, std::abs(x[i] - data.problem.solution[i]));
  const double iterations = static_cast<double>(state.iterations());
  state.counters["ratio"] = qp_seconds / baseline_seconds;
  state.counters["QP_ms"] = 1e3 * qp_seconds / iterations;
  state.counters["baseline_ms"] = 1e3 * baseline_seconds / iterations;
  state.counters["active_percent"] = 100. * double(report.active_bounds) / n;
  state.counters["iterations"] = static_cast<double>(report.iterations);
  state.counters["factorizations"] = static_cast<double>(report.factorizations);
  state.counters["rel_KKT"] = report.relative_kkt_residual;
  state.counters["deviation"] = deviation / data.patch.bound.maxCoeff();
  // How far the warm start is: bounds active in one of the two problems only, relative to the
  // number of active bounds.
  if (start != COLD) {
    const Known_solution_problem& from =
        (start == WARM_CLOSE) ? data.close.problem : data.nearby.problem;
    std::size_t differing = 0;
    for (Eigen::Index i = 0; i < data.problem.solution.size(); ++i)
      differing += (std::abs(data.problem.solution[i]) == data.patch.bound[i]) !=
                   (std::abs(from.solution[i]) == data.patch.bound[i]);
    state.counters["warm_start_differs_percent"] =
        100. * double(differing) / double(data.problem.active);
  }
}

void cases(benchmark::internal::Benchmark* benchmark)
{
  benchmark->ArgNames({"n", "active_percent", "start"});
  for (int n : {1000, 10000, 100000})
    for (int active_percent : {5, 30})
      for (int start : {COLD, WARM, WARM_REUSED, WARM_CLOSE})
        benchmark->Args({n, active_percent, start});
}

} // namespace

// Three iterations per case keep the run at a few minutes; each one also runs the baseline.
BENCHMARK(BM_box_QP)->Apply(cases)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(3);

BENCHMARK_MAIN();

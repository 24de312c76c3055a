// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Speed of Active_set_box_QP_solver on fairing-like problems, as a ratio to one unconstrained
// Eigen::SimplicialLDLT factorisation + solve of the same matrix measured in the same run
// (BM_box_QP), and as a ratio to ONE of the solver's own supernodal factorisations of the
// same matrix, on programs whose active bounds form smooth regions or are scattered as in
// Moré and Toraldo's GPCG test problems (BM_box_QP_vs_factorization, described below; run it
// alone with --benchmark_filter=vs_factorization, about 5 minutes), and one solve with the
// factorisation in single precision against one in double (BM_preconditioner_precision).
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

#include "fairing_like_programs.h"

#include <CGAL/Highlight_lines/Active_set_box_QP_solver.h>

#include <Eigen/SparseCholesky>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <utility>
#include <vector>

namespace {

using Sparse_matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Solver = CGAL::Highlight_lines::Active_set_box_QP_solver;

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The CPU time of this thread: the solver and the factorisation are serial, and on a shared
// machine their ratio in wall time varies with the load of the other cores.
double thread_seconds()
{
  timespec now;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

using Highlight_lines_benchmark::Fairing_like_patch; // the fairing-like programs

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

// ---------------------------------------------------------------------------------------------
// BM_box_QP_vs_factorization: the solve time as a ratio to ONE numeric supernodal LDL^T
// factorisation of the same matrix (the solver's own, internal::Supernodal_LDLT, on the
// whole P), both timed in every repetition of the case, in CPU time of the thread (both are
// serial); the counters are medians over the repetitions, and ratio_without_analysis leaves
// out the symbolic analysis (AMD ordering, supernodes) that a cold solve includes. Two kinds of
// program on the same fairing-like matrix, 20 % of the bounds active at the optimum:
//   kind 0, smooth    -- the active bounds form smooth regions (the clamped smooth field of
//                        Known_solution_problem);
//   kind 1, scattered -- the active bounds are scattered at random, as in the test problems
//                        of Moré and Toraldo's GPCG: a random 20 % of the variables on a
//                        random side, random multipliers, random free values inside the box.
// start 0, cold: a new solver (its time includes the symbolic analysis, reported apart as
// analysis_ms); start 1, warm: a copy of the solver that solved a nearby program (the one
// a fairing iteration reuses: symbolic analysis and last factorisation kept), warm-started
// from that program's solution (warm_start_differs_percent of the active bounds differ);
// start 2, warm_new: a new solver warm-started from the same point (no factorisation at
// hand: analysis included, as cold).

// A program whose active bounds are scattered at random. `redraw` is the fraction of
// variables whose draw is replaced by another one (a nearby program).
struct Scattered_problem
{
  Eigen::VectorXd c, solution;
  std::size_t active = 0;

  Scattered_problem(const Fairing_like_patch& patch, double active_fraction, double redraw)
  {
    const Eigen::Index n = patch.bound.size();
    std::mt19937 random(777u), other(778u), choice(779u);
    std::uniform_real_distribution<double> uniform(0., 1.);
    const Eigen::VectorXd diagonal = patch.Q.diagonal();
    solution.resize(n);
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      double draw[4];
      for (double& d : draw)
        d = uniform(random);
      double alternative[4];
      for (double& d : alternative)
        d = uniform(other);
      if (uniform(choice) < redraw)
        std::copy(alternative, alternative + 4, draw);
      const double b = patch.bound[i];
      if (draw[0] < active_fraction) {
        ++active;
        const double side = draw[1] < 0.5 ? -1. : 1.;
        solution[i] = side * b;
        const double multiplier = diagonal[i] * b * (0.01 + draw[2]);
        gradient[i] = -side * multiplier;
      } else
        solution[i] = b * (1.9 * draw[3] - 0.95);
    }
    c = gradient - patch.Q * solution;
  }
};

enum Kind { SMOOTH, SCATTERED };

struct Ratio_case_data
{
  Fairing_like_patch patch;
  Eigen::VectorXd c, solution, nearby_c, nearby_solution_exact;
  std::size_t active = 0;
  std::vector<double> nearby_solution;
  Solver nearby_solver; // solved the nearby program
  CGAL::Highlight_lines::internal::Supernodal_LDLT ldlt;
  double analysis_seconds = 0.;

  Ratio_case_data(int n, Kind kind) : patch(n)
  {
    const double fraction = 0.2;
    if (kind == SMOOTH) {
      const Known_solution_problem problem(patch, fraction, 1.015, 0.01),
          nearby(patch, fraction, 1., 0.);
      c = problem.c;
      solution = problem.solution;
      active = problem.active;
      nearby_c = nearby.c;
      nearby_solution_exact = nearby.solution;
    } else {
      const Scattered_problem problem(patch, fraction, 0.), nearby(patch, fraction, 0.05);
      c = problem.c;
      solution = problem.solution;
      active = problem.active;
      nearby_c = nearby.c;
      nearby_solution_exact = nearby.solution;
    }
    set(nearby_solver, nearby_c);
    nearby_solver.solve(std::back_inserter(nearby_solution));
    // The symbolic analysis, as the solver does it (AMD on the whole pattern).
    const double begin = thread_seconds();
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> permutation;
    Sparse_matrix pattern = patch.Q;
    Eigen::internal::minimum_degree_ordering(pattern, permutation);
    const std::vector<int> ordering(permutation.indices().data(), permutation.indices().data() + n);
    ldlt.analyze(n, patch.Q.outerIndexPtr(), patch.Q.innerIndexPtr(), ordering);
    analysis_seconds = thread_seconds() - begin;
  }

  void set(Solver& solver, const Eigen::VectorXd& linear) const
  {
    const std::size_t n = static_cast<std::size_t>(patch.bound.size());
    solver.resize(n);
    solver.set_P(patch.Q);
    for (std::size_t i = 0; i < n; ++i) {
      solver.set_q(i, linear[i]);
      solver.set_l(i, -patch.bound[i]);
      solver.set_u(i, patch.bound[i]);
    }
  }
};

Ratio_case_data& ratio_case_data(int n, Kind kind)
{
  static std::map<std::pair<int, int>, std::unique_ptr<Ratio_case_data>> cache;
  auto& slot = cache[{n, int(kind)}];
  if (!slot)
    slot = std::make_unique<Ratio_case_data>(n, kind);
  return *slot;
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 == 1 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

void BM_box_QP_vs_factorization(benchmark::State& state)
{
  const int n = static_cast<int>(state.range(0));
  const Kind kind = static_cast<Kind>(state.range(1));
  const bool warm = state.range(2) != 0, reused = state.range(2) == 1;
  Ratio_case_data& data = ratio_case_data(n, kind);

  std::vector<double> solve_times, factorization_times;
  CGAL::Highlight_lines::Box_QP_report report;
  std::vector<double> x;
  for (auto _ : state) {
    double begin = thread_seconds();
    const auto inertia = data.ldlt.factorize(data.patch.Q.valuePtr(), 1e-12);
    benchmark::DoNotOptimize(inertia);
    factorization_times.push_back(thread_seconds() - begin);

    Solver used = reused ? data.nearby_solver : Solver(); // untimed copy
    begin = thread_seconds();
    data.set(used, data.c);
    if (warm)
      used.set_warm_start(data.nearby_solution);
    x.clear();
    report = used.solve(std::back_inserter(x));
    const double elapsed = thread_seconds() - begin;
    solve_times.push_back(elapsed);
    state.SetIterationTime(elapsed);
    if (!report.is_optimal())
      state.SkipWithError(report.message.c_str());
  }
  double deviation = 0.;
  for (Eigen::Index i = 0; i < data.solution.size(); ++i)
    deviation = std::max(deviation, std::abs(x[i] - data.solution[i]));
  const double solve_median = median(solve_times),
               factorization_median = median(factorization_times);
  state.counters["ratio"] = solve_median / factorization_median;
  state.counters["solve_ms"] = 1e3 * solve_median;
  state.counters["factorization_ms"] = 1e3 * factorization_median;
  state.counters["analysis_ms"] = 1e3 * data.analysis_seconds;
  if (!reused)
    state.counters["ratio_without_analysis"] =
        (solve_median - data.analysis_seconds) / factorization_median;
  state.counters["factorizations"] = static_cast<double>(report.factorizations);
  state.counters["iterations"] = static_cast<double>(report.iterations);
  state.counters["projection_steps"] = static_cast<double>(report.projection_steps);
  state.counters["active_percent"] = 100. * double(report.active_bounds) / n;
  state.counters["rel_KKT"] = report.relative_kkt_residual;
  state.counters["deviation"] = deviation / data.patch.bound.maxCoeff();
  if (warm) {
    std::size_t differing = 0;
    for (Eigen::Index i = 0; i < data.solution.size(); ++i)
      differing += (std::abs(data.solution[i]) == data.patch.bound[i]) !=
                   (std::abs(data.nearby_solution_exact[i]) == data.patch.bound[i]);
    state.counters["warm_start_differs_percent"] = 100. * double(differing) / double(data.active);
  }
}

// BM_preconditioner_precision: one solve with the supernodal factorisation of the smooth
// case's matrix in single precision (Supernodal_LDLT::solve_in_single_precision(), what the
// solver's conjugate gradients use on factors of 2^22 entries and more) as a ratio to one
// in double precision (solve()), both timed in every iteration, in CPU time of the thread;
// the single-precision copy of the factor is made before (once per factorisation). Counters:
// ratio, single_ms, double_ms, factor_MB (in double precision), the relative difference.
void BM_preconditioner_precision(benchmark::State& state)
{
  const int n = static_cast<int>(state.range(0));
  Ratio_case_data& data = ratio_case_data(n, SMOOTH);
  data.ldlt.factorize(data.patch.Q.valuePtr(), 1e-12);
  const Eigen::VectorXd b = data.c;
  Eigen::VectorXd exact = b, single = b;
  data.ldlt.solve_in_single_precision(single); // makes the copy
  std::vector<double> double_times, single_times;
  for (auto _ : state) {
    exact = b;
    double begin = thread_seconds();
    data.ldlt.solve(exact);
    double_times.push_back(thread_seconds() - begin);
    single = b;
    begin = thread_seconds();
    data.ldlt.solve_in_single_precision(single);
    const double elapsed = thread_seconds() - begin;
    single_times.push_back(elapsed);
    state.SetIterationTime(elapsed);
  }
  state.counters["ratio"] = median(single_times) / median(double_times);
  state.counters["single_ms"] = 1e3 * median(single_times);
  state.counters["double_ms"] = 1e3 * median(double_times);
  state.counters["factor_MB"] = 8e-6 * double(data.ldlt.number_of_factor_entries());
  state.counters["relative_difference"] = (single - exact).norm() / exact.norm();
}

void ratio_cases(benchmark::internal::Benchmark* benchmark)
{
  benchmark->ArgNames({"n", "kind", "start"});
  for (int n : {10000, 100000})
    for (int kind : {SMOOTH, SCATTERED})
      for (int start : {0, 1, 2})
        benchmark->Args({n, kind, start});
}

} // namespace

// Three iterations per case keep the run at a few minutes; each one also runs the baseline.
BENCHMARK(BM_box_QP)->Apply(cases)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(3);
// Five repetitions per case (medians); run alone with --benchmark_filter=vs_factorization.
BENCHMARK(BM_box_QP_vs_factorization)
    ->Apply(ratio_cases)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5);

// Medians of 21 solves of each kind; run alone with --benchmark_filter=precision.
BENCHMARK(BM_preconditioner_precision)
    ->ArgName("n")
    ->Arg(10000)
    ->Arg(100000)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(21);

BENCHMARK_MAIN();

// Active_set_box_QP_solver on large fairing-like problems (a bi-Laplacian on a grid with
// irregular weights, bounds that vary per variable), whose solution is known by construction:
// KKT conditions, agreement with the known solution, warm starts, reuse of the solver.

#include <CGAL/Highlight_lines/Active_set_box_QP_solver.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <random>
#include <vector>

namespace {

using CGAL::Highlight_lines::Active_set_box_QP_solver;
using CGAL::Highlight_lines::Box_QP_report;
using CGAL::Highlight_lines::Box_QP_status;
using Sparse_matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// The side of a large grid: under AddressSanitizer (CI's instrumented build, several times
// slower) two thirds of it, the same code paths on a grid of 10^4 instead of 2 x 10^4 variables.
int large_side(int side)
{
#if defined(__SANITIZE_ADDRESS__)
  return 2 * side / 3;
#else
  return side;
#endif
}

// Q = W^T M^-1 W for the weighted Laplacian W of an m x m grid (with diagonals, random edge
// weights, Dirichlet boundary) and random "areas" M; bounds |x_i| <= b_i with b_i varying.
// A jitter changes each inverse area by up to that fraction (and nothing else): the matrix
// of the next iteration of a fairing, with the same pattern. Without all diagonals, every
// third cell's diagonal edge is left out (the same values otherwise): a pattern contained in
// the full one, as a fairing's programs lose a few entries from one iteration to the next.
struct Grid_problem
{
  int m = 0, n = 0;
  Sparse_matrix Q;
  Eigen::VectorXd bound;

  explicit Grid_problem(int side, unsigned seed, double jitter = 0., bool all_diagonals = true)
      : m(side), n(side * side)
  {
    std::mt19937 jitter_random(seed + 1000);
    std::uniform_real_distribution<double> change(-jitter, jitter);
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> weight(0.5, 1.5);
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd degree = Eigen::VectorXd::Zero(n);
    const auto id = [side](int i, int j) { return i * side + j; };
    for (int i = 0; i < side; ++i)
      for (int j = 0; j < side; ++j) {
        const int neighbours[3][2] = {{i + 1, j}, {i, j + 1}, {i + 1, j + 1}};
        for (const auto& nb : neighbours) {
          const double w = weight(random);
          if (!all_diagonals && nb[0] == i + 1 && nb[1] == j + 1 && (i + 2 * j) % 3 == 0)
            continue;
          degree[id(i, j)] += w;
          if (nb[0] < side && nb[1] < side) {
            degree[id(nb[0], nb[1])] += w;
            entries.emplace_back(id(i, j), id(nb[0], nb[1]), -w);
            entries.emplace_back(id(nb[0], nb[1]), id(i, j), -w);
          }
        }
      }
    for (int k = 0; k < n; ++k)
      entries.emplace_back(k, k, degree[k] + 1e-3);
    Sparse_matrix W(n, n);
    W.setFromTriplets(entries.begin(), entries.end());
    Eigen::VectorXd inverse_area(n);
    for (int k = 0; k < n; ++k)
      inverse_area[k] = weight(random) * (1. + change(jitter_random));
    Q = Sparse_matrix(W.transpose()) * inverse_area.asDiagonal() * W;
    Q.makeCompressed();
    bound.resize(n);
    for (int k = 0; k < n; ++k)
      bound[k] = 0.5 * weight(random) / side;
  }
};

// The linear term whose minimiser is the smooth field a * s clamped to the bounds, with
// positive multipliers on the clamped variables; a is chosen so that the given fraction of
// the bounds is active.
struct Known_solution
{
  Eigen::VectorXd c, x;
  std::size_t active = 0;

  Known_solution(const Grid_problem& grid, double active_fraction, double phase)
  {
    const int n = grid.n;
    Eigen::VectorXd field(n);
    for (int k = 0; k < n; ++k) {
      const double s = double(k / grid.m) / grid.m, t = double(k % grid.m) / grid.m;
      field[k] =
          std::sin(6. * s + phase) * std::cos(5. * t) + 0.5 * std::exp(-20. * (s - t) * (s - t));
    }
    std::vector<double> ratio(n);
    for (int k = 0; k < n; ++k)
      ratio[k] = std::abs(field[k]) / grid.bound[k];
    // The threshold halfway between two ratios: no variable is degenerate (free on a bound).
    std::sort(ratio.begin(), ratio.end());
    const std::size_t first_active = std::size_t((1. - active_fraction) * n);
    const double amplitude = 2. / (ratio[first_active - 1] + ratio[first_active]);
    x = (amplitude * field).cwiseMax(-grid.bound).cwiseMin(grid.bound);
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(n);
    const Eigen::VectorXd diagonal = grid.Q.diagonal();
    for (int k = 0; k < n; ++k) {
      const double excess = std::abs(amplitude * field[k]) - grid.bound[k];
      if (excess >= 0.) {
        ++active;
        const double multiplier = diagonal[k] * (excess + 1e-3 * grid.bound[k]);
        gradient[k] = field[k] > 0. ? -multiplier : multiplier;
      }
    }
    c = gradient - grid.Q * x;
  }
};

struct Result
{
  Box_QP_report report;
  std::vector<double> x;
};

Result solve(Active_set_box_QP_solver& solver, const Grid_problem& grid,
             const Known_solution& problem, const std::vector<double>* warm_start = nullptr)
{
  solver.resize(grid.n);
  solver.set_P(grid.Q);
  for (int k = 0; k < grid.n; ++k) {
    solver.set_q(k, problem.c[k]);
    solver.set_l(k, -grid.bound[k]);
    solver.set_u(k, grid.bound[k]);
  }
  if (warm_start != nullptr)
    solver.set_warm_start(*warm_start);
  Result result;
  result.report = solver.solve(std::back_inserter(result.x));
  return result;
}

// The KKT conditions, computed here independently of the solver.
double relative_kkt_residual(const Grid_problem& grid, const Known_solution& problem,
                             const std::vector<double>& x)
{
  const Eigen::Map<const Eigen::VectorXd> point(x.data(), grid.n);
  const Eigen::VectorXd gradient = grid.Q * point + problem.c;
  double residual = 0.;
  for (int k = 0; k < grid.n; ++k) {
    double projected = gradient[k];
    if (x[k] <= -grid.bound[k])
      projected = std::min(projected, 0.);
    if (x[k] >= grid.bound[k])
      projected = std::max(projected, 0.);
    residual = std::max(residual, std::abs(projected));
  }
  double Q_norm = 0.;
  for (int k = 0; k < grid.n; ++k)
    Q_norm = std::max(Q_norm, grid.Q.col(k).cwiseAbs().sum()); // symmetric: rows = columns
  return residual / (problem.c.cwiseAbs().maxCoeff() + Q_norm * point.cwiseAbs().maxCoeff());
}

void expect_known_solution(const Grid_problem& grid, const Known_solution& problem,
                           const Result& result)
{
  ASSERT_EQ(result.report.status, Box_QP_status::OPTIMAL) << result.report.message;
  ASSERT_EQ(result.x.size(), std::size_t(grid.n));
  double deviation = 0.;
  for (int k = 0; k < grid.n; ++k) {
    ASSERT_LE(std::abs(result.x[k]), grid.bound[k]) << "variable " << k;
    deviation = std::max(deviation, std::abs(result.x[k] - problem.x[k]));
  }
  EXPECT_LE(deviation, 1e-8 * grid.bound.maxCoeff());
  EXPECT_EQ(result.report.active_bounds, problem.active);
  EXPECT_LE(result.report.relative_kkt_residual, 1e-10);
  EXPECT_LE(relative_kkt_residual(grid, problem, result.x), 1e-10);
}

TEST(BoxQPLargeProblems, KKTConditionsHoldOnLargeBiLaplacianProblems)
{
  const Grid_problem grid(large_side(150), 1);
  for (double active_fraction : {0.05, 0.3}) {
    SCOPED_TRACE(active_fraction);
    const Known_solution problem(grid, active_fraction, 0.);
    Active_set_box_QP_solver solver;
    expect_known_solution(grid, problem, solve(solver, grid, problem));
  }
}

TEST(BoxQPLargeProblems, WarmStartFromANearbyProblemTakesFewerIterations)
{
  const Grid_problem grid(large_side(120), 2);
  const Known_solution nearby(grid, 0.15, 0.), problem(grid, 0.15, 0.02);
  Active_set_box_QP_solver solver;
  const Result previous = solve(solver, grid, nearby);
  expect_known_solution(grid, nearby, previous);
  const Result cold = solve(solver, grid, problem);
  const Result warm = solve(solver, grid, problem, &previous.x);
  expect_known_solution(grid, problem, cold);
  expect_known_solution(grid, problem, warm);
  EXPECT_LT(warm.report.iterations, cold.report.iterations);
  EXPECT_LT(warm.report.factorizations, cold.report.factorizations);
}

TEST(BoxQPLargeProblems, ReusedSolverGivesExactlyTheResultOfAFreshOne)
{
  const Grid_problem grid(80, 3);
  const Known_solution first(grid, 0.1, 0.), second(grid, 0.2, 1.);
  Active_set_box_QP_solver reused, fresh;
  solve(reused, grid, first);
  const Result again = solve(reused, grid, second);
  const Result once = solve(fresh, grid, second);
  EXPECT_EQ(again.x, once.x);
  EXPECT_EQ(again.report.iterations, once.report.iterations);
}

// The symbolic analysis of the last pattern serves a pattern it contains (the missing entries
// factorised as zeros), and a pattern that adds a few entries is analysed joined with the last
// one: both ways, the reused solver finds the known solution, as a fresh one does.
TEST(BoxQPLargeProblems, ProgramsWithNearbyPatternsGiveTheResultOfAFreshSolver)
{
  const Grid_problem full(60, 5), sparser(60, 5, 0., false);
  ASSERT_LT(sparser.Q.nonZeros(), full.Q.nonZeros());
  const Known_solution on_full(full, 0.1, 0.), on_sparser(sparser, 0.2, 0.7);
  for (const bool sparser_first : {false, true}) {
    SCOPED_TRACE(sparser_first);
    const Grid_problem& first = sparser_first ? sparser : full;
    const Grid_problem& second = sparser_first ? full : sparser;
    const Known_solution& second_problem = sparser_first ? on_full : on_sparser;
    Active_set_box_QP_solver reused, fresh;
    solve(reused, first, sparser_first ? on_sparser : on_full);
    const Result again = solve(reused, second, second_problem);
    const Result once = solve(fresh, second, second_problem);
    expect_known_solution(second, second_problem, again);
    ASSERT_EQ(again.x.size(), once.x.size());
    for (std::size_t k = 0; k < once.x.size(); ++k)
      ASSERT_NEAR(again.x[k], once.x[k], 1e-10 * second.bound.maxCoeff()) << "variable " << k;
  }
}

TEST(BoxQPLargeProblems, WarmStartOneBoundAwayFromTheOptimumSkipsRefactorisation)
{
  // Conjugate gradients preconditioned by the factorisation of the warm start's free set
  // solve the next system when the active set changes by a single bound.
  const Grid_problem grid(large_side(200), 4);
  const Known_solution problem(grid, 0.1, 0.5);
  std::vector<double> x0(problem.x.data(), problem.x.data() + grid.n);
  for (int k = 0; k < grid.n; ++k)
    if (std::abs(x0[k]) == grid.bound[k]) {
      x0[k] = 0.; // free one active variable
      break;
    }
  Active_set_box_QP_solver solver;
  const Result result = solve(solver, grid, problem, &x0);
  expect_known_solution(grid, problem, result);
  EXPECT_EQ(result.report.iterations, 2u);
  EXPECT_EQ(result.report.factorizations, 1u);
}

TEST(BoxQPLargeProblems, ScalingTheProblemChangesNeitherItsPathNorItsCost)
{
  // A warm start with an active bound missing and an extra one: the next free sets differ
  // from the factorised one by variables that left it and variables that joined it, and the
  // bordered systems mix entries of P with entries of P^-1. At the scale of a fairing
  // program (P of the order of 10^8) those differ by twenty orders of magnitude; solved
  // without equilibration, the refinement diverged and each such iteration refactorised.
  std::vector<Box_QP_report> reports;
  for (double scale : {1., 1e8}) {
    SCOPED_TRACE(scale);
    Grid_problem grid(large_side(100), 5);
    grid.Q *= scale;
    const Known_solution problem(grid, 0.1, 0.3); // c scales with Q
    // Free the active variable deepest inside its active region (the largest multiplier
    // relative to its diagonal) and pin the free variable farthest from its bounds.
    const Eigen::VectorXd gradient = grid.Q * problem.x + problem.c;
    const auto depth = [&](int k) {
      return std::abs(problem.x[k]) == grid.bound[k] ? std::abs(gradient[k]) / grid.Q.coeff(k, k)
                                                     : 1. - std::abs(problem.x[k]) / grid.bound[k];
    };
    int freed = -1, pinned = -1;
    for (int k = 0; k < grid.n; ++k) {
      int& chosen = std::abs(problem.x[k]) == grid.bound[k] ? freed : pinned;
      if (chosen < 0 || depth(k) > depth(chosen))
        chosen = k;
    }
    std::vector<double> x0(problem.x.data(), problem.x.data() + grid.n);
    x0[std::size_t(freed)] = 0.;
    x0[std::size_t(pinned)] = grid.bound[pinned];
    Active_set_box_QP_solver solver;
    const Result result = solve(solver, grid, problem, &x0);
    expect_known_solution(grid, problem, result);
    reports.push_back(result.report);
  }
  EXPECT_GT(reports[0].iterations, 2u); // the bordered path is taken
  EXPECT_EQ(reports[1].iterations, reports[0].iterations);
  EXPECT_EQ(reports[1].factorizations, reports[0].factorizations);
}

TEST(BoxQPLargeProblems, WarmStartWithoutActiveBoundsActivatesAsAColdStartDoes)
{
  // The next program of a fairing whose trust region grew: the last step lies inside the new
  // bounds, so its warm start knows no active bound. Activating every violated bound then
  // overshoots as from a cold start; the solver takes the cold start's careful path instead,
  // here with the same iterations and factorisations (a new solver has no factorisation to
  // precondition with).
  const Grid_problem grid(60, 9);
  const Known_solution problem(grid, 0.05, 0.2);
  std::vector<double> inside(std::size_t(grid.n));
  for (int k = 0; k < grid.n; ++k)
    inside[std::size_t(k)] = 0.; // the cold start's point, given as a warm start
  Active_set_box_QP_solver cold_solver, warm_solver;
  const Result cold = solve(cold_solver, grid, problem);
  const Result warm = solve(warm_solver, grid, problem, &inside);
  expect_known_solution(grid, problem, cold);
  expect_known_solution(grid, problem, warm);
  EXPECT_GT(cold.report.iterations, 2u);
  EXPECT_EQ(warm.report.iterations, cold.report.iterations);
  EXPECT_EQ(warm.report.factorizations, cold.report.factorizations);
}

TEST(BoxQPLargeProblems, WarmStartOnANearbyMatrixIsPreconditionedByTheLastFactorisation)
{
  // The next program of a fairing: other values of P, a shifted optimum. The factorisation
  // left by the last solve preconditions conjugate gradients, so that no new one is needed.
  const Grid_problem grid(large_side(150), 6), next_grid(large_side(150), 6, 0.02);
  const Known_solution problem(grid, 0.1, 0.), next(next_grid, 0.1, 0.);
  Active_set_box_QP_solver solver, fresh;
  const Result first = solve(solver, grid, problem);
  expect_known_solution(grid, problem, first);
  const Result warm = solve(solver, next_grid, next, &first.x);
  const Result cold = solve(fresh, next_grid, next, &first.x);
  expect_known_solution(next_grid, next, warm);
  expect_known_solution(next_grid, next, cold);
  EXPECT_EQ(warm.report.factorizations, 0u);
  EXPECT_GE(cold.report.factorizations, 1u);
}

TEST(BoxQPLargeProblems, WarmStartOnAGrownPatternIsPreconditionedByTheLastFactorisation)
{
  // As above, but the next program's matrix has entries the last one lacked (a new pattern
  // to analyse): the last factorisation, laid out for the old pattern, still preconditions
  // conjugate gradients before anything is analysed or factorised anew.
  const Grid_problem grid(large_side(150), 6, 0., false), next_grid(large_side(150), 6, 0.02);
  ASSERT_LT(grid.Q.nonZeros(), next_grid.Q.nonZeros());
  const Known_solution problem(grid, 0.1, 0.), next(next_grid, 0.1, 0.);
  Active_set_box_QP_solver solver;
  const Result first = solve(solver, grid, problem);
  expect_known_solution(grid, problem, first);
  const Result warm = solve(solver, next_grid, next, &first.x);
  expect_known_solution(next_grid, next, warm);
  EXPECT_EQ(warm.report.factorizations, 0u);
}

// The fairing solves a program again with tighter bounds where its solution would flip faces:
// the same P and q, a few variables held at half their value. The factorisation the first solve
// left is of that same matrix, so bordering solves the new free sets exactly, without a new
// factorisation (before, it counted as a stale preconditioner, and conjugate gradients over the
// changed free set often ran out of their budget: 827 -> 510 factorisations over 180 scan-like
// real-dent fairings), and the result is a fresh solver's.
TEST(BoxQPLargeProblems, SolvingAgainWithTighterBoundsReusesTheFactorisation)
{
  const Grid_problem grid(60, 7);
  const Known_solution problem(grid, 0.1, 0.4);
  Active_set_box_QP_solver solver;
  const Result first = solve(solver, grid, problem);
  expect_known_solution(grid, problem, first);
  // The 8 free variables farthest from zero, held at half their value.
  std::vector<int> free_variables;
  for (int k = 0; k < grid.n; ++k)
    if (std::abs(first.x[std::size_t(k)]) < grid.bound[k])
      free_variables.push_back(k);
  std::partial_sort(free_variables.begin(), free_variables.begin() + 8, free_variables.end(),
                    [&](int a, int b) {
                      return std::abs(first.x[std::size_t(a)]) > std::abs(first.x[std::size_t(b)]);
                    });
  free_variables.resize(8);
  Eigen::VectorXd lower = -grid.bound, upper = grid.bound;
  for (int k : free_variables) {
    const double hold = 0.5 * std::abs(first.x[std::size_t(k)]);
    ASSERT_GT(hold, 0.);
    lower[k] = -hold;
    upper[k] = hold;
    solver.set_l(std::size_t(k), -hold);
    solver.set_u(std::size_t(k), hold);
  }
  solver.set_warm_start(first.x);
  Result again;
  again.report = solver.solve(std::back_inserter(again.x));
  Active_set_box_QP_solver fresh;
  fresh.resize(std::size_t(grid.n));
  fresh.set_P(grid.Q);
  for (int k = 0; k < grid.n; ++k) {
    fresh.set_q(std::size_t(k), problem.c[k]);
    fresh.set_l(std::size_t(k), lower[k]);
    fresh.set_u(std::size_t(k), upper[k]);
  }
  Result once;
  once.report = fresh.solve(std::back_inserter(once.x));
  ASSERT_EQ(again.report.status, Box_QP_status::OPTIMAL) << again.report.message;
  ASSERT_EQ(once.report.status, Box_QP_status::OPTIMAL) << once.report.message;
  ASSERT_EQ(again.x.size(), once.x.size());
  for (std::size_t k = 0; k < once.x.size(); ++k)
    ASSERT_NEAR(again.x[k], once.x[k], 1e-10 * grid.bound.maxCoeff()) << "variable " << k;
  for (int k : free_variables)
    EXPECT_EQ(std::abs(again.x[std::size_t(k)]), upper[k]) << "variable " << k;
  EXPECT_EQ(again.report.factorizations, 0u);
  EXPECT_GE(once.report.factorizations, 1u);
}

TEST(BoxQPLargeProblems, MonotonePhaseAloneSolvesAFairingLikeProblem)
{
  const Grid_problem grid(40, 5);
  const Known_solution problem(grid, 0.1, 0.3);
  Active_set_box_QP_solver solver;
  solver.set_maximum_number_of_primal_dual_iterations(0);
  expect_known_solution(grid, problem, solve(solver, grid, problem));
}

TEST(BoxQPLargeProblems, FewBoundsHoldingBackAFarMinimiserAreFoundWithOneFactorisation)
{
  // The first program of a fairing: the free minimiser (a smooth bump of height 1) leaves
  // the generous bounds (0.4) at thousands of variables, but a few tight bounds (0.05 at 2 %
  // of the bump's core, as short edges limit a fairing's steps) hold the solution back, and
  // few other bounds are active at it. Activating several violated bounds at once pins
  // coupled variables and overshoots (two factorisations here, 166 on a fairing of 5 10^4
  // variables); the cold start's primal steps activate only the bounds that hold, with one
  // factorisation. The result is the one of the monotone phase alone, another method.
  const Grid_problem grid(large_side(60), 3);
  const int n = grid.n, m = grid.m;
  Eigen::VectorXd bump(n), l(n), u(n);
  std::size_t tight = 0, violated = 0;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> pick(0., 1.);
  for (int k = 0; k < n; ++k) {
    const int i = k / m, j = k % m;
    const double s = double(i) / (m - 1) - 0.5, t = double(j) / (m - 1) - 0.5;
    bump[k] = std::exp(-4. * (s * s + t * t));
    const bool core = std::abs(s) < 0.3 && std::abs(t) < 0.3 && pick(random) < 0.02;
    u[k] = core ? 0.05 : 0.4;
    l[k] = -u[k];
    tight += core;
    violated += bump[k] > u[k];
  }
  const Eigen::VectorXd c = -(grid.Q * bump);
  Active_set_box_QP_solver solver, monotone;
  solver.set_gradient_projection(false); // as the fairing's first programs, that it skips
  monotone.set_maximum_number_of_primal_dual_iterations(0);
  const auto run = [&](Active_set_box_QP_solver& s) {
    s.resize(std::size_t(n));
    s.set_P(grid.Q);
    for (int k = 0; k < n; ++k) {
      s.set_q(std::size_t(k), c[k]);
      s.set_l(std::size_t(k), l[k]);
      s.set_u(std::size_t(k), u[k]);
    }
    Result result;
    result.report = s.solve(std::back_inserter(result.x));
    return result;
  };
  const Result result = run(solver), reference = run(monotone);
  ASSERT_EQ(result.report.status, Box_QP_status::OPTIMAL) << result.report.message;
  ASSERT_EQ(reference.report.status, Box_QP_status::OPTIMAL) << reference.report.message;
  EXPECT_GT(violated, 10 * tight);
  EXPECT_LE(result.report.active_bounds, tight);
  EXPECT_GT(result.report.active_bounds, 0u);
  EXPECT_EQ(result.report.factorizations, 1u);
  double deviation = 0.;
  for (int k = 0; k < n; ++k) {
    ASSERT_LE(std::abs(result.x[k]), u[k]);
    deviation = std::max(deviation, std::abs(result.x[k] - reference.x[k]));
  }
  EXPECT_LE(deviation, 1e-8);
}

// ---------------------------------------------------------------------------------------------
// The gradient projection phase (problems of 2000 variables or more): its result is the one
// of the active-set path alone (set_gradient_projection(false)) and satisfies the KKT
// conditions checked here, on scattered and smooth active sets and on degenerate bounds.

// A linear term whose minimiser has a random `fraction` of the variables on a random bound
// (multipliers of random size), the others at random values inside: the active bounds are
// scattered, as in Moré and Toraldo's test problems.
struct Scattered_solution
{
  Eigen::VectorXd c, x;
  std::size_t active = 0;

  Scattered_solution(const Grid_problem& grid, double fraction, unsigned seed)
  {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> uniform(0., 1.);
    const Eigen::VectorXd diagonal = grid.Q.diagonal();
    x.resize(grid.n);
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(grid.n);
    for (int k = 0; k < grid.n; ++k) {
      const double b = grid.bound[k];
      if (uniform(random) < fraction) {
        ++active;
        const double side = uniform(random) < 0.5 ? -1. : 1.;
        x[k] = side * b;
        gradient[k] = -side * diagonal[k] * b * (0.01 + uniform(random));
      } else
        x[k] = b * (1.9 * uniform(random) - 0.95);
    }
    c = gradient - grid.Q * x;
  }
};

// Solves min 1/2 x^T Q x + c^T x on [l, u] with a new solver, gradient projection on or off.
Result solve_box(const Sparse_matrix& Q, const Eigen::VectorXd& c, const Eigen::VectorXd& l,
                 const Eigen::VectorXd& u, bool gradient_projection,
                 const std::vector<double>* warm_start = nullptr,
                 Active_set_box_QP_solver* reused = nullptr)
{
  Active_set_box_QP_solver fresh;
  Active_set_box_QP_solver& solver = reused != nullptr ? *reused : fresh;
  solver.set_gradient_projection(gradient_projection);
  const int n = static_cast<int>(c.size());
  solver.resize(std::size_t(n));
  solver.set_P(Q);
  for (int k = 0; k < n; ++k) {
    solver.set_q(std::size_t(k), c[k]);
    solver.set_l(std::size_t(k), l[k]);
    solver.set_u(std::size_t(k), u[k]);
  }
  if (warm_start != nullptr)
    solver.set_warm_start(*warm_start);
  Result result;
  result.report = solver.solve(std::back_inserter(result.x));
  return result;
}

// The relative KKT residual of x, computed here: projected gradient over the size of its terms.
double box_kkt_residual(const Sparse_matrix& Q, const Eigen::VectorXd& c, const Eigen::VectorXd& l,
                        const Eigen::VectorXd& u, const std::vector<double>& x)
{
  const Eigen::Map<const Eigen::VectorXd> point(x.data(), c.size());
  const Eigen::VectorXd gradient = Q * point + c;
  double residual = 0., Q_norm = 0.;
  for (Eigen::Index k = 0; k < c.size(); ++k) {
    double projected = gradient[k];
    if (l[k] == u[k])
      projected = 0.;
    else if (x[k] <= l[k])
      projected = std::min(projected, 0.);
    else if (x[k] >= u[k])
      projected = std::max(projected, 0.);
    residual = std::max(residual, std::abs(projected));
    Q_norm = std::max(Q_norm, Q.col(k).cwiseAbs().sum());
  }
  return residual / (c.cwiseAbs().maxCoeff() + Q_norm * point.cwiseAbs().maxCoeff());
}

// Both results optimal, within the bounds, satisfying the KKT conditions, and equal to the
// tolerance (the solution is unique: Q is positive definite).
void expect_same_optimum_both_ways(const Sparse_matrix& Q, const Eigen::VectorXd& c,
                                   const Eigen::VectorXd& l, const Eigen::VectorXd& u,
                                   const Result& with, const Result& without)
{
  for (const Result* result : {&with, &without}) {
    ASSERT_EQ(result->report.status, Box_QP_status::OPTIMAL) << result->report.message;
    ASSERT_EQ(result->x.size(), std::size_t(c.size()));
    for (Eigen::Index k = 0; k < c.size(); ++k) {
      ASSERT_GE(result->x[k], l[k]) << "variable " << k;
      ASSERT_LE(result->x[k], u[k]) << "variable " << k;
    }
    EXPECT_LE(result->report.relative_kkt_residual, 1e-10);
    EXPECT_LE(box_kkt_residual(Q, c, l, u, result->x), 1e-10);
  }
  double scale = 0., deviation = 0.;
  for (Eigen::Index k = 0; k < c.size(); ++k) {
    scale = std::max(scale, std::abs(without.x[k]));
    deviation = std::max(deviation, std::abs(with.x[k] - without.x[k]));
  }
  EXPECT_LE(deviation, 1e-8 * std::max(scale, 1e-300));
  EXPECT_EQ(with.report.active_bounds, without.report.active_bounds);
  EXPECT_NEAR(with.report.objective_value, without.report.objective_value,
              1e-9 * std::max(1., std::abs(without.report.objective_value)));
}

TEST(BoxQPGradientProjection, ScatteredActiveBoundsGiveTheKnownSolution)
{
  const Grid_problem grid(large_side(90), 11);
  const Scattered_solution problem(grid, 0.2, 12);
  const Eigen::VectorXd l = -grid.bound, u = grid.bound;
  const Result with = solve_box(grid.Q, problem.c, l, u, true);
  const Result without = solve_box(grid.Q, problem.c, l, u, false);
  expect_same_optimum_both_ways(grid.Q, problem.c, l, u, with, without);
  EXPECT_GT(with.report.projection_steps, 0u);
  EXPECT_EQ(without.report.projection_steps, 0u);
  EXPECT_EQ(with.report.active_bounds, problem.active);
  double deviation = 0.;
  for (int k = 0; k < grid.n; ++k)
    deviation = std::max(deviation, std::abs(with.x[k] - problem.x[k]));
  EXPECT_LE(deviation, 1e-8 * grid.bound.maxCoeff());
  // The face found leaves little to the active-set iterations.
  EXPECT_LE(with.report.factorizations, without.report.factorizations);
}

TEST(BoxQPGradientProjection, SmoothActiveRegionsGiveTheResultOfTheActiveSetPath)
{
  const Grid_problem grid(large_side(90), 13);
  for (double fraction : {0.05, 0.2}) {
    SCOPED_TRACE(fraction);
    const Known_solution problem(grid, fraction, 0.4);
    const Eigen::VectorXd l = -grid.bound, u = grid.bound;
    const Result with = solve_box(grid.Q, problem.c, l, u, true);
    const Result without = solve_box(grid.Q, problem.c, l, u, false);
    expect_same_optimum_both_ways(grid.Q, problem.c, l, u, with, without);
    EXPECT_GT(with.report.projection_steps, 0u);
    expect_known_solution(grid, problem, with);
  }
}

TEST(BoxQPGradientProjection, WarmStartsGiveTheResultOfTheActiveSetPath)
{
  // A good warm start (the solution of the problem itself) and a poor one (the solution of
  // another scattered problem) both end at the optimum; the good one keeps its active set.
  const Grid_problem grid(large_side(90), 14);
  const Scattered_solution problem(grid, 0.2, 15), other(grid, 0.2, 16);
  const Eigen::VectorXd l = -grid.bound, u = grid.bound;
  const std::vector<double> exact(problem.x.data(), problem.x.data() + grid.n);
  const std::vector<double> poor(other.x.data(), other.x.data() + grid.n);
  const Result good_with = solve_box(grid.Q, problem.c, l, u, true, &exact);
  const Result good_without = solve_box(grid.Q, problem.c, l, u, false, &exact);
  expect_same_optimum_both_ways(grid.Q, problem.c, l, u, good_with, good_without);
  EXPECT_EQ(good_with.report.iterations, good_without.report.iterations);
  EXPECT_EQ(good_with.report.factorizations, good_without.report.factorizations);
  const Result poor_with = solve_box(grid.Q, problem.c, l, u, true, &poor);
  const Result poor_without = solve_box(grid.Q, problem.c, l, u, false, &poor);
  expect_same_optimum_both_ways(grid.Q, problem.c, l, u, poor_with, poor_without);
  EXPECT_GT(poor_with.report.projection_steps, 0u);
  // Reusing the solver (its last factorisation preconditions) gives the same optimum.
  Active_set_box_QP_solver reused;
  solve_box(grid.Q, other.c, l, u, true, nullptr, &reused);
  const Result poor_reused = solve_box(grid.Q, problem.c, l, u, true, &poor, &reused);
  expect_same_optimum_both_ways(grid.Q, problem.c, l, u, poor_reused, poor_without);
}

TEST(BoxQPGradientProjection, ReusedSolverCorrectsAPoorWarmStartByProjection)
{
  // The next program of an iterative method, with the last factorisation at hand, but
  // warm-started far from its face (the solution of another scattered problem): the projected
  // steps find the face, as a new solver's do, instead of many active-set iterations
  // preconditioned by that factorisation.
  const Grid_problem grid(large_side(90), 19);
  const Scattered_solution problem(grid, 0.2, 20), other(grid, 0.2, 21);
  const Eigen::VectorXd l = -grid.bound, u = grid.bound;
  const std::vector<double> poor(other.x.data(), other.x.data() + grid.n);
  Active_set_box_QP_solver reused, reused_without;
  solve_box(grid.Q, other.c, l, u, true, nullptr, &reused);
  solve_box(grid.Q, other.c, l, u, false, nullptr, &reused_without);
  const Result with = solve_box(grid.Q, problem.c, l, u, true, &poor, &reused);
  const Result without = solve_box(grid.Q, problem.c, l, u, false, &poor, &reused_without);
  const Result fresh = solve_box(grid.Q, problem.c, l, u, true, &poor);
  expect_same_optimum_both_ways(grid.Q, problem.c, l, u, with, without);
  expect_same_optimum_both_ways(grid.Q, problem.c, l, u, with, fresh);
  EXPECT_GT(with.report.projection_steps, 0u);
  EXPECT_LE(with.report.factorizations, fresh.report.factorizations);
  EXPECT_LT(with.report.factorizations, without.report.factorizations);
}

TEST(BoxQPGradientProjection, DegenerateBoundsGiveTheResultOfTheActiveSetPath)
{
  const Grid_problem grid(50, 17); // 2500 variables: enough for the gradient projection
  const int n = grid.n;
  const double infinity = std::numeric_limits<double>::infinity();
  const Scattered_solution scattered(grid, 0.2, 18);
  {
    SCOPED_TRACE("all bounds active");
    Eigen::VectorXd c(n);
    for (int k = 0; k < n; ++k)
      c[k] = (k % 3 == 0 ? 1e3 : -1e3) * grid.Q.coeff(k, k) * grid.bound[k] * 50.;
    const Eigen::VectorXd l = -grid.bound, u = grid.bound;
    const Result with = solve_box(grid.Q, c, l, u, true);
    const Result without = solve_box(grid.Q, c, l, u, false);
    expect_same_optimum_both_ways(grid.Q, c, l, u, with, without);
    EXPECT_EQ(with.report.active_bounds, std::size_t(n));
  }
  {
    SCOPED_TRACE("no bound active");
    // The unconstrained minimiser lies at half the bounds.
    const Eigen::VectorXd l = -grid.bound, u = grid.bound;
    const Eigen::VectorXd c = -(grid.Q * (0.5 * scattered.x));
    const Result with = solve_box(grid.Q, c, l, u, true);
    const Result without = solve_box(grid.Q, c, l, u, false);
    expect_same_optimum_both_ways(grid.Q, c, l, u, with, without);
    EXPECT_EQ(with.report.active_bounds, 0u);
  }
  {
    SCOPED_TRACE("infinite bounds");
    Eigen::VectorXd l = -grid.bound, u = grid.bound;
    for (int k = 0; k < n; ++k) {
      if (k % 4 == 0)
        l[k] = -infinity;
      if (k % 5 == 0)
        u[k] = infinity;
    }
    const Result with = solve_box(grid.Q, scattered.c, l, u, true);
    const Result without = solve_box(grid.Q, scattered.c, l, u, false);
    expect_same_optimum_both_ways(grid.Q, scattered.c, l, u, with, without);
  }
  {
    SCOPED_TRACE("a bound equal on both sides");
    Eigen::VectorXd l = -grid.bound, u = grid.bound;
    for (int k = 0; k < n; k += 7)
      l[k] = u[k] = (k % 2 == 0 ? 0.5 : -0.25) * grid.bound[k];
    const Result with = solve_box(grid.Q, scattered.c, l, u, true);
    const Result without = solve_box(grid.Q, scattered.c, l, u, false);
    expect_same_optimum_both_ways(grid.Q, scattered.c, l, u, with, without);
    for (int k = 0; k < n; k += 7)
      EXPECT_EQ(with.x[k], l[k]) << "variable " << k;
  }
}

} // namespace

// Active_set_box_QP_solver against an independent solver: CGAL's exact QP_solver
// (CGAL::solve_quadratic_program with Gmpzf arithmetic) on many random small problems, and
// the adapter Quadratic_program_traits_box_QP_adapter wrapping a QuadraticProgramTraits model
// that is itself built on CGAL's exact solver.

#include <CGAL/Highlight_lines/Active_set_box_QP_solver.h>
#include <CGAL/Highlight_lines/Quadratic_program_traits_box_QP_adapter.h>

#include <CGAL/Gmpzf.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <random>
#include <utility>
#include <vector>

namespace {

using CGAL::Highlight_lines::Active_set_box_QP_solver;
using CGAL::Highlight_lines::Box_QP_report;
using CGAL::Highlight_lines::Box_QP_status;
using CGAL::Highlight_lines::Quadratic_program_traits_box_QP_adapter;

const double infinity = std::numeric_limits<double>::infinity();

// A box QP with a sparse P (upper triangle, i <= j).
struct Random_box_QP
{
  int n = 0;
  std::map<std::pair<int, int>, double> P;
  std::vector<double> q, l, u;
  double r = 0.;
  bool singular = false;

  double objective(const std::vector<double>& x) const
  {
    double value = r;
    for (const auto& entry : P) {
      const int i = entry.first.first, j = entry.first.second;
      value += (i == j ? 0.5 : 1.) * entry.second * x[i] * x[j];
    }
    for (int i = 0; i < n; ++i)
      value += q[i] * x[i];
    return value;
  }

  double scale(const std::vector<double>& x) const // size of the terms of the objective
  {
    double value = std::abs(r);
    for (const auto& entry : P)
      value += std::abs(entry.second * x[entry.first.first] * x[entry.first.second]);
    for (int i = 0; i < n; ++i)
      value += std::abs(q[i] * x[i]);
    return value;
  }
};

// P = B^T B + shift I with B sparse (a few random entries per row): symmetric positive
// definite, or only semidefinite when B has fewer rows than columns and shift = 0. `coupling`
// makes B's rows denser, P further from an M-matrix. Bounds: a mix of two-sided, one-sided,
// absent and fixed (l = u); all finite when P is singular so that the optimum is bounded.
Random_box_QP random_box_QP(std::mt19937& random, int n, bool singular, int coupling)
{
  std::uniform_real_distribution<double> uniform(-1., 1.);
  Random_box_QP qp;
  qp.n = n;
  qp.singular = singular;
  const int rows = singular ? std::max(1, n / 2) : n;
  for (int row = 0; row < rows; ++row) {
    std::map<int, double> b;
    const int entries = 1 + static_cast<int>(random() % (2 + coupling));
    for (int k = 0; k < entries; ++k)
      b[static_cast<int>(random() % n)] = std::round(uniform(random) * 64.) / 16.;
    for (const auto& bi : b)
      for (const auto& bj : b)
        if (bi.first <= bj.first)
          qp.P[{bi.first, bj.first}] += bi.second * bj.second;
  }
  if (!singular)
    for (int i = 0; i < n; ++i)
      qp.P[{i, i}] += 0.125 * (1 + random() % 8);
  qp.q.resize(n);
  qp.l.resize(n);
  qp.u.resize(n);
  for (int i = 0; i < n; ++i) {
    qp.q[i] = std::round(uniform(random) * 256.) / 32.;
    const double a = std::round(uniform(random) * 32.) / 16., width = (1 + random() % 32) / 16.;
    switch (singular ? random() % 2 : random() % 6) {
    case 0:
    case 1:
      qp.l[i] = a;
      qp.u[i] = a + width;
      break;
    case 2:
      qp.l[i] = a;
      qp.u[i] = infinity;
      break;
    case 3:
      qp.l[i] = -infinity;
      qp.u[i] = a;
      break;
    case 4:
      qp.l[i] = -infinity;
      qp.u[i] = infinity;
      break;
    default:
      qp.l[i] = qp.u[i] = a; // fixed
    }
  }
  qp.r = uniform(random);
  return qp;
}

template <class Solver>
Box_QP_report solve_with(Solver& solver, const Random_box_QP& qp, std::vector<double>& x,
                         const std::vector<double>* warm_start = nullptr)
{
  solver.resize(qp.n);
  // All ordered pairs: the lower triangle must be ignored.
  for (const auto& entry : qp.P) {
    solver.set_P(entry.first.first, entry.first.second, entry.second);
    if (entry.first.first != entry.first.second)
      solver.set_P(entry.first.second, entry.first.first, entry.second);
  }
  for (int i = 0; i < qp.n; ++i) {
    solver.set_q(i, qp.q[i]);
    solver.set_l(i, qp.l[i]);
    solver.set_u(i, qp.u[i]);
  }
  solver.set_r(qp.r);
  if (warm_start != nullptr)
    solver.set_warm_start(*warm_start);
  x.clear();
  return solver.solve(std::back_inserter(x));
}

// CGAL's QP_solver minimises x^T D x + c^T x + c0 and is given 2D: with 2D = P its
// objective is ours.
struct Exact_solution
{
  bool optimal = false;
  std::vector<double> x;
  double objective = 0.;
};

Exact_solution solve_exactly(const Random_box_QP& qp)
{
  CGAL::Quadratic_program<double> program(CGAL::EQUAL, false, 0., false, 0.);
  for (const auto& entry : qp.P)
    program.set_d(entry.first.second, entry.first.first, entry.second); // row >= column
  for (int i = 0; i < qp.n; ++i) {
    program.set_c(i, qp.q[i]);
    if (std::isfinite(qp.l[i]))
      program.set_l(i, true, qp.l[i]);
    if (std::isfinite(qp.u[i]))
      program.set_u(i, true, qp.u[i]);
  }
  program.set_c0(qp.r);
  const CGAL::Quadratic_program_solution<CGAL::Gmpzf> solution =
      CGAL::solve_quadratic_program(program, CGAL::Gmpzf());
  Exact_solution result;
  result.optimal = solution.is_optimal();
  if (result.optimal) {
    for (auto it = solution.variable_values_begin(); it != solution.variable_values_end(); ++it)
      result.x.push_back(CGAL::to_double(*it));
    result.objective = CGAL::to_double(solution.objective_value());
  }
  return result;
}

// Same optimum: objective values agree relative to the size of the objective's terms, and,
// when P is definite (unique minimiser), the points agree too.
void expect_same_optimum(const Random_box_QP& qp, const Box_QP_report& report,
                         const std::vector<double>& x, const Exact_solution& exact,
                         double x_tolerance)
{
  ASSERT_TRUE(exact.optimal);
  ASSERT_EQ(report.status, Box_QP_status::OPTIMAL) << report.message;
  ASSERT_EQ(x.size(), std::size_t(qp.n));
  for (int i = 0; i < qp.n; ++i) {
    EXPECT_GE(x[i], qp.l[i]) << "variable " << i;
    EXPECT_LE(x[i], qp.u[i]) << "variable " << i;
  }
  const double scale = 1. + qp.scale(exact.x);
  EXPECT_NEAR(qp.objective(x), exact.objective, 1e-9 * scale);
  EXPECT_NEAR(report.objective_value, exact.objective, 1e-9 * scale);
  if (!qp.singular) {
    double x_scale = 1.;
    for (double v : exact.x)
      x_scale = std::max(x_scale, std::abs(v));
    for (int i = 0; i < qp.n; ++i)
      EXPECT_NEAR(x[i], exact.x[i], x_tolerance * x_scale) << "variable " << i;
  }
}

int random_size(std::mt19937& random, int trial)
{
  // mostly small, some up to 200
  return trial % 10 == 0 ? 100 + static_cast<int>(random() % 101)
                         : 1 + static_cast<int>(random() % 40);
}

TEST(BoxQPExactComparison, MatchesCGALExactQPSolverOnRandomProblems)
{
  std::mt19937 random(2026);
  Active_set_box_QP_solver solver; // reused across problems of different sizes
  for (int trial = 0; trial < 300; ++trial) {
    const Random_box_QP qp = random_box_QP(random, random_size(random, trial), false, trial % 4);
    std::vector<double> x;
    const Box_QP_report report = solve_with(solver, qp, x);
    SCOPED_TRACE("trial " + std::to_string(trial) + ", n = " + std::to_string(qp.n));
    expect_same_optimum(qp, report, x, solve_exactly(qp), 1e-7);
    EXPECT_LE(report.relative_kkt_residual, 1e-10);
  }
}

TEST(BoxQPExactComparison, MatchesCGALExactQPSolverOnRandomSingularProblems)
{
  std::mt19937 random(4);
  Active_set_box_QP_solver solver;
  for (int trial = 0; trial < 150; ++trial) {
    const Random_box_QP qp = random_box_QP(random, random_size(random, trial), true, trial % 3);
    std::vector<double> x;
    const Box_QP_report report = solve_with(solver, qp, x);
    SCOPED_TRACE("trial " + std::to_string(trial) + ", n = " + std::to_string(qp.n));
    expect_same_optimum(qp, report, x, solve_exactly(qp), 0.);
  }
}

TEST(BoxQPExactComparison, MonotonePhaseAloneMatchesCGALExactQPSolver)
{
  // The projected Newton phase is the safeguard of the primal-dual phase: check it alone.
  std::mt19937 random(99);
  Active_set_box_QP_solver solver;
  solver.set_maximum_number_of_primal_dual_iterations(0);
  for (int trial = 0; trial < 100; ++trial) {
    const bool singular = trial % 3 == 0;
    const Random_box_QP qp = random_box_QP(random, random_size(random, trial), singular, 2);
    std::vector<double> x;
    const Box_QP_report report = solve_with(solver, qp, x);
    SCOPED_TRACE("trial " + std::to_string(trial) + ", n = " + std::to_string(qp.n));
    expect_same_optimum(qp, report, x, solve_exactly(qp), 1e-7);
  }
}

TEST(BoxQPExactComparison, WarmStartsFromPerturbedSolutionsMatchCGALExactQPSolver)
{
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  Active_set_box_QP_solver solver;
  for (int trial = 0; trial < 100; ++trial) {
    const Random_box_QP qp = random_box_QP(random, random_size(random, trial), false, 1);
    const Exact_solution exact = solve_exactly(qp);
    // A wrong active set: the exact solution with random entries moved to a bound.
    std::vector<double> x0 = exact.x;
    for (int i = 0; i < qp.n; ++i)
      if (random() % 4 == 0)
        x0[i] = uniform(random) > 0. ? qp.u[i] : qp.l[i];
    std::vector<double> x;
    const Box_QP_report report = solve_with(solver, qp, x, &x0);
    SCOPED_TRACE("trial " + std::to_string(trial) + ", n = " + std::to_string(qp.n));
    expect_same_optimum(qp, report, x, exact, 1e-7);
  }
}

// A model of QuadraticProgramTraits (min 1/2 x^T P x + q^T x + r, l <= A x <= u) built on
// CGAL's exact QP_solver, to test the adapter with an independent solver. Like CGAL's OSQP
// model, set_P(i, j, v) sets P_ij = P_ji = v and ignores j < i, and the solution is written
// with `*(++it) = v`.
class Exact_quadratic_program_traits
{
public:
  void resize(std::size_t n, std::size_t m)
  {
    n_ = n;
    P_.clear();
    A_.clear();
    q_.assign(n, 0.);
    l_.assign(m, -infinity);
    u_.assign(m, infinity);
    r_ = 0.;
  }
  void set_P(std::size_t i, std::size_t j, double value)
  {
    if (j >= i)
      P_[{i, j}] = value;
  }
  void set_q(std::size_t i, double value) { q_[i] = value; }
  void set_r(double value) { r_ = value; }
  void set_A(std::size_t i, std::size_t j, double value) { A_[{i, j}] = value; }
  void set_l(std::size_t i, double value) { l_[i] = value; }
  void set_u(std::size_t i, double value) { u_[i] = value; }

  template <class OutputIterator>
  bool solve(OutputIterator solution)
  {
    CGAL::Quadratic_program<double> program(CGAL::EQUAL, false, 0., false, 0.);
    for (const auto& entry : P_)
      program.set_d(static_cast<int>(entry.first.second), static_cast<int>(entry.first.first),
                    entry.second);
    for (std::size_t i = 0; i < n_; ++i)
      program.set_c(static_cast<int>(i), q_[i]);
    program.set_c0(r_);
    int row = 0;
    const auto add_row = [&](std::size_t constraint, CGAL::Comparison_result relation, double b) {
      for (const auto& entry : A_)
        if (entry.first.first == constraint)
          program.set_a(static_cast<int>(entry.first.second), row, entry.second);
      program.set_r(row, relation);
      program.set_b(row, b);
      ++row;
    };
    for (std::size_t k = 0; k < l_.size(); ++k) {
      if (l_[k] == u_[k])
        add_row(k, CGAL::EQUAL, l_[k]);
      else {
        if (std::isfinite(l_[k]))
          add_row(k, CGAL::LARGER, l_[k]);
        if (std::isfinite(u_[k]))
          add_row(k, CGAL::SMALLER, u_[k]);
      }
    }
    const CGAL::Quadratic_program_solution<CGAL::Gmpzf> result =
        CGAL::solve_quadratic_program(program, CGAL::Gmpzf());
    if (!result.is_optimal())
      return false;
    std::size_t written = 0;
    for (auto it = result.variable_values_begin(); it != result.variable_values_end();
         ++it, ++written)
      *(++solution) = CGAL::to_double(*it);
    for (; written < n_; ++written) // variables that appear nowhere
      *(++solution) = 0.;
    return true;
  }

private:
  std::size_t n_ = 0;
  std::map<std::pair<std::size_t, std::size_t>, double> P_, A_;
  std::vector<double> q_, l_, u_;
  double r_ = 0.;
};

TEST(BoxQPExactComparison, AdapterMakesAQuadraticProgramTraitsModelASolver)
{
  std::mt19937 random(17);
  Quadratic_program_traits_box_QP_adapter<Exact_quadratic_program_traits> adapter;
  Active_set_box_QP_solver solver;
  for (int trial = 0; trial < 60; ++trial) {
    const bool singular = trial % 4 == 0;
    const Random_box_QP qp = random_box_QP(random, 1 + trial % 30, singular, trial % 3);
    std::vector<double> x_adapter, x_solver;
    const Box_QP_report adapter_report = solve_with(adapter, qp, x_adapter);
    const Box_QP_report solver_report = solve_with(solver, qp, x_solver);
    SCOPED_TRACE("trial " + std::to_string(trial) + ", n = " + std::to_string(qp.n));
    const Exact_solution exact = solve_exactly(qp);
    expect_same_optimum(qp, adapter_report, x_adapter, exact, 1e-12);
    expect_same_optimum(qp, solver_report, x_solver, exact, 1e-7);
  }
}

// A QuadraticProgramTraits model that fails, or returns too few values.
struct Failing_quadratic_program_traits
{
  std::size_t values_written = 0;
  bool success = false;
  void resize(std::size_t, std::size_t) {}
  void set_P(std::size_t, std::size_t, double) {}
  void set_q(std::size_t, double) {}
  void set_r(double) {}
  void set_A(std::size_t, std::size_t, double) {}
  void set_l(std::size_t, double) {}
  void set_u(std::size_t, double) {}
  template <class OutputIterator>
  bool solve(OutputIterator solution)
  {
    for (std::size_t i = 0; i < values_written; ++i)
      *solution++ = 0.;
    return success;
  }
};

TEST(BoxQPExactComparison, AdapterReportsFailuresOfTheWrappedModel)
{
  for (const auto& behaviour :
       {std::make_pair(std::size_t(3), false), std::make_pair(std::size_t(2), true)}) {
    Failing_quadratic_program_traits traits;
    traits.values_written = behaviour.first;
    traits.success = behaviour.second;
    Quadratic_program_traits_box_QP_adapter<Failing_quadratic_program_traits> adapter(traits);
    adapter.resize(3);
    for (int i = 0; i < 3; ++i) {
      adapter.set_P(i, i, 1.);
      adapter.set_l(i, -1.);
      adapter.set_u(i, 1.);
    }
    std::vector<double> x;
    const Box_QP_report report = adapter.solve(std::back_inserter(x));
    EXPECT_EQ(report.status, Box_QP_status::NUMERICAL_FAILURE);
    EXPECT_FALSE(report.message.empty());
    EXPECT_EQ(x.size(), 3u);
  }
}

TEST(BoxQPExactComparison, AdapterChecksTheInputLikeTheBuiltInSolver)
{
  Quadratic_program_traits_box_QP_adapter<Exact_quadratic_program_traits> adapter;
  std::vector<double> x;
  adapter.resize(2);
  adapter.set_P(0, 0, 1.);
  adapter.set_l(1, 2.);
  adapter.set_u(1, 1.);
  EXPECT_EQ(adapter.solve(std::back_inserter(x)).status, Box_QP_status::INFEASIBLE_BOUNDS);
  adapter.resize(2);
  adapter.set_q(0, std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(adapter.solve(std::back_inserter(x)).status, Box_QP_status::INVALID_INPUT);
  adapter.resize(2);
  adapter.set_P(1, 1, -1.);
  EXPECT_EQ(adapter.solve(std::back_inserter(x)).status, Box_QP_status::NOT_CONVEX);
  adapter.resize(2);
  adapter.set_P(0, 0, 1.);
  adapter.set_P(1, 1, 1.);
  adapter.set_warm_start(std::vector<double>(3, 0.));
  EXPECT_EQ(adapter.solve(std::back_inserter(x)).status, Box_QP_status::INVALID_INPUT);
  EXPECT_EQ(adapter.solve(std::back_inserter(x)).status, Box_QP_status::OPTIMAL);
}

} // namespace

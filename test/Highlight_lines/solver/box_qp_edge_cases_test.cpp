// Statuses and semantics of Active_set_box_QP_solver on the edge cases of the issue: all
// bounds active, none active, l = u, infinite bounds, singular P with a bounded optimum,
// unbounded objective, l > u, NaN and infinite input, non-convexity, iteration limit; and
// the assembly semantics of the BoxConstrainedQuadraticProgramSolver concept.

#include <CGAL/Highlight_lines/Active_set_box_QP_solver.h>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using CGAL::Highlight_lines::Active_set_box_QP_solver;
using CGAL::Highlight_lines::Box_QP_report;
using CGAL::Highlight_lines::Box_QP_status;
using Sparse_matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

const double infinity = std::numeric_limits<double>::infinity();
const double nan = std::numeric_limits<double>::quiet_NaN();

// The 1D Laplacian with Dirichlet ends, squared: SPD, not an M-matrix, condition ~ n^4.
Sparse_matrix squared_path_laplacian(int n)
{
  Sparse_matrix L(n, n);
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, 2.);
    if (i + 1 < n) {
      entries.emplace_back(i, i + 1, -1.);
      entries.emplace_back(i + 1, i, -1.);
    }
  }
  L.setFromTriplets(entries.begin(), entries.end());
  return Sparse_matrix(L * L);
}

void set_matrix(Active_set_box_QP_solver& solver, const Sparse_matrix& P)
{
  for (int j = 0; j < P.outerSize(); ++j)
    for (Sparse_matrix::InnerIterator it(P, j); it; ++it)
      solver.set_P(static_cast<std::size_t>(it.row()), static_cast<std::size_t>(j), it.value());
}

struct Result
{
  Box_QP_report report;
  std::vector<double> x;
};

Result solve(Active_set_box_QP_solver& solver)
{
  Result result;
  result.report = solver.solve(std::back_inserter(result.x));
  return result;
}

bool within_bounds(const std::vector<double>& x, const std::vector<double>& l,
                   const std::vector<double>& u)
{
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!(x[i] >= l[i] && x[i] <= u[i]))
      return false;
  return true;
}

TEST(BoxQPEdgeCases, AllBoundsActiveGivesTheBounds)
{
  const int n = 60;
  const Sparse_matrix P = squared_path_laplacian(n);
  Active_set_box_QP_solver solver(n);
  set_matrix(solver, P);
  std::vector<double> l(n), u(n);
  for (int i = 0; i < n; ++i) {
    // A strong pull towards +infinity presses every variable against its upper bound.
    solver.set_q(i, -1e6);
    l[i] = -1. - 0.01 * i;
    u[i] = 0.5 + 0.001 * (i % 7);
    solver.set_l(i, l[i]);
    solver.set_u(i, u[i]);
  }
  const Result result = solve(solver);
  ASSERT_EQ(result.report.status, Box_QP_status::OPTIMAL) << result.report.message;
  EXPECT_EQ(result.report.active_bounds, std::size_t(n));
  for (int i = 0; i < n; ++i)
    EXPECT_EQ(result.x[i], u[i]);
  EXPECT_LE(result.report.relative_kkt_residual, 1e-10);
}

TEST(BoxQPEdgeCases, NoBoundsActiveGivesTheUnconstrainedMinimiser)
{
  const int n = 80;
  const Sparse_matrix P = squared_path_laplacian(n);
  Eigen::VectorXd q(n);
  for (int i = 0; i < n; ++i)
    q[i] = std::sin(0.3 * i);
  const Eigen::VectorXd unconstrained = Eigen::SimplicialLDLT<Sparse_matrix>(P).solve(-q);
  const double width = 2. * unconstrained.cwiseAbs().maxCoeff();
  Active_set_box_QP_solver solver(n);
  set_matrix(solver, P);
  for (int i = 0; i < n; ++i) {
    solver.set_q(i, q[i]);
    solver.set_l(i, -width);
    solver.set_u(i, width);
  }
  const Result result = solve(solver);
  ASSERT_EQ(result.report.status, Box_QP_status::OPTIMAL) << result.report.message;
  EXPECT_EQ(result.report.active_bounds, 0u);
  for (int i = 0; i < n; ++i)
    EXPECT_NEAR(result.x[i], unconstrained[i], 1e-8 * width);
}

TEST(BoxQPEdgeCases, FixedVariablesKeepTheirValueExactly)
{
  const int n = 50;
  const Sparse_matrix P = squared_path_laplacian(n);
  Active_set_box_QP_solver solver(n);
  set_matrix(solver, P);
  for (int i = 0; i < n; ++i) {
    solver.set_q(i, std::cos(0.2 * i));
    if (i % 5 == 0) {
      solver.set_l(i, 0.1 * i);
      solver.set_u(i, 0.1 * i);
    } else {
      solver.set_l(i, -10.);
      solver.set_u(i, 10.);
    }
  }
  const Result result = solve(solver);
  ASSERT_EQ(result.report.status, Box_QP_status::OPTIMAL) << result.report.message;
  for (int i = 0; i < n; i += 5)
    EXPECT_EQ(result.x[i], 0.1 * i);
  EXPECT_GE(result.report.active_bounds, std::size_t(n / 5));
}

TEST(BoxQPEdgeCases, InfiniteBoundsOnOneSideAreHonoured)
{
  // Known solution: x* = lower bound on the even variables with multiplier 1, free elsewhere.
  const int n = 40;
  const Sparse_matrix P = squared_path_laplacian(n);
  Eigen::VectorXd x_star(n), gradient_star = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n; ++i) {
    x_star[i] = (i % 2 == 0) ? 1. : 3. + std::sin(double(i));
    if (i % 2 == 0)
      gradient_star[i] = 1.;
  }
  const Eigen::VectorXd q = gradient_star - P * x_star;
  Active_set_box_QP_solver solver(n);
  set_matrix(solver, P);
  for (int i = 0; i < n; ++i) {
    solver.set_q(i, q[i]);
    solver.set_l(i, i % 2 == 0 ? 1. : -infinity); // upper bounds stay +infinity
  }
  const Result result = solve(solver);
  ASSERT_EQ(result.report.status, Box_QP_status::OPTIMAL) << result.report.message;
  for (int i = 0; i < n; ++i)
    EXPECT_NEAR(result.x[i], x_star[i], 1e-7);
  EXPECT_EQ(result.report.active_bounds, std::size_t(n / 2));
}

TEST(BoxQPEdgeCases, FreeVariablesWithoutAnyBoundAreSolved)
{
  const int n = 30;
  const Sparse_matrix P = squared_path_laplacian(n);
  Active_set_box_QP_solver solver(n);
  set_matrix(solver, P);
  for (int i = 0; i < n; ++i)
    solver.set_q(i, 1.);
  const Result result = solve(solver);
  ASSERT_EQ(result.report.status, Box_QP_status::OPTIMAL) << result.report.message;
  const Eigen::VectorXd expected =
      Eigen::SimplicialLDLT<Sparse_matrix>(P).solve(-Eigen::VectorXd::Ones(n));
  for (int i = 0; i < n; ++i)
    EXPECT_NEAR(result.x[i], expected[i], 1e-8 * expected.cwiseAbs().maxCoeff());
}

TEST(BoxQPEdgeCases, SingularMatrixWithBoundedOptimumIsSolved)
{
  // A path graph Laplacian without Dirichlet ends: its null space is the constants. The
  // linear term pushes along the constants, the bounds stop it.
  const int n = 25;
  Active_set_box_QP_solver solver(n);
  std::vector<double> l(n), u(n);
  for (int i = 0; i + 1 < n; ++i) {
    solver.set_P(i, i, 1.);
    solver.set_P(i + 1, i + 1, 1.);
    solver.set_P(i, i + 1, -1.);
  }
  for (int i = 0; i < n; ++i) {
    solver.set_q(i, -1. + 0.1 * std::sin(double(i)));
    l[i] = -2.;
    u[i] = 1. + 0.05 * (i % 3);
    solver.set_l(i, l[i]);
    solver.set_u(i, u[i]);
  }
  const Result result = solve(solver);
  ASSERT_EQ(result.report.status, Box_QP_status::OPTIMAL) << result.report.message;
  EXPECT_TRUE(within_bounds(result.x, l, u));
  EXPECT_LE(result.report.relative_kkt_residual, 1e-10);
  EXPECT_GT(result.report.active_bounds, 0u);
}

TEST(BoxQPEdgeCases, SingularMatrixWithLinearTermInItsRangeIsSolved)
{
  // P = diag(1, 0): the second variable does not appear in the objective at all.
  Active_set_box_QP_solver solver(2);
  solver.set_P(0, 0, 1.);
  solver.set_q(0, -3.);
  const Result result = solve(solver);
  ASSERT_EQ(result.report.status, Box_QP_status::OPTIMAL) << result.report.message;
  EXPECT_NEAR(result.x[0], 3., 1e-12);
  EXPECT_TRUE(std::isfinite(result.x[1]));
  EXPECT_NEAR(result.report.objective_value, -4.5, 1e-12);
}

TEST(BoxQPEdgeCases, LinearProgramOnABoxIsSolved)
{
  const int n = 12;
  Active_set_box_QP_solver solver(n);
  std::vector<double> l(n), u(n);
  double expected = 0.;
  for (int i = 0; i < n; ++i) {
    const double q = (i % 3 == 0) ? 0. : (i % 2 == 0 ? 1.5 : -2.);
    solver.set_q(i, q);
    l[i] = -1. - i;
    u[i] = 2. + i;
    solver.set_l(i, l[i]);
    solver.set_u(i, u[i]);
    expected += q > 0 ? q * l[i] : q * u[i];
  }
  const Result result = solve(solver);
  ASSERT_EQ(result.report.status, Box_QP_status::OPTIMAL) << result.report.message;
  EXPECT_NEAR(result.report.objective_value, expected, 1e-12);
  EXPECT_TRUE(within_bounds(result.x, l, u));
}

TEST(BoxQPEdgeCases, UnboundedObjectiveIsReported)
{
  // The constants are in the null space of P and q pushes along them; the upper bounds are
  // infinite, so nothing stops the descent.
  const int n = 10;
  Active_set_box_QP_solver solver(n);
  std::vector<double> l(n, -5.), u(n, infinity);
  for (int i = 0; i + 1 < n; ++i) {
    solver.set_P(i, i, 1.);
    solver.set_P(i + 1, i + 1, 1.);
    solver.set_P(i, i + 1, -1.);
  }
  for (int i = 0; i < n; ++i) {
    solver.set_q(i, -1.);
    solver.set_l(i, l[i]);
  }
  const Result result = solve(solver);
  EXPECT_EQ(result.report.status, Box_QP_status::UNBOUNDED) << result.report.message;
  EXPECT_TRUE(within_bounds(result.x, l, u));
  EXPECT_FALSE(result.report.message.empty());
}

TEST(BoxQPEdgeCases, LowerBoundAboveUpperBoundIsInfeasible)
{
  Active_set_box_QP_solver solver(4);
  for (int i = 0; i < 4; ++i)
    solver.set_P(i, i, 1.);
  solver.set_l(2, 1.);
  solver.set_u(2, 0.5);
  const Result result = solve(solver);
  EXPECT_EQ(result.report.status, Box_QP_status::INFEASIBLE_BOUNDS);
  EXPECT_NE(result.report.message.find("variable 2"), std::string::npos) << result.report.message;
  ASSERT_EQ(result.x.size(), 4u);
  for (double v : result.x)
    EXPECT_TRUE(std::isnan(v));
}

TEST(BoxQPEdgeCases, NonFiniteInputIsInvalid)
{
  struct Corruption
  {
    const char* what;
    void (*apply)(Active_set_box_QP_solver&);
  };
  const Corruption corruptions[] = {
      {"P(1, 2)", [](Active_set_box_QP_solver& s) { s.set_P(1, 2, nan); }},
      {"P(0, 0)", [](Active_set_box_QP_solver& s) { s.set_P(0, 0, infinity); }},
      {"q(3)", [](Active_set_box_QP_solver& s) { s.set_q(3, nan); }},
      {"q(1)", [](Active_set_box_QP_solver& s) { s.set_q(1, -infinity); }},
      {"variable 2", [](Active_set_box_QP_solver& s) { s.set_l(2, nan); }},
      {"variable 0", [](Active_set_box_QP_solver& s) { s.set_u(0, nan); }},
      {"variable 1", [](Active_set_box_QP_solver& s) { s.set_l(1, infinity); }},
      {"variable 3", [](Active_set_box_QP_solver& s) { s.set_u(3, -infinity); }},
      {"r is", [](Active_set_box_QP_solver& s) { s.set_r(nan); }},
  };
  for (const Corruption& corruption : corruptions) {
    Active_set_box_QP_solver solver(4);
    for (int i = 0; i < 4; ++i) {
      solver.set_P(i, i, 2.);
      solver.set_q(i, 1.);
    }
    corruption.apply(solver);
    const Result result = solve(solver);
    EXPECT_EQ(result.report.status, Box_QP_status::INVALID_INPUT) << corruption.what;
    EXPECT_NE(result.report.message.find(corruption.what), std::string::npos)
        << result.report.message;
    ASSERT_EQ(result.x.size(), 4u);
    EXPECT_TRUE(std::isnan(result.x[0]));
  }
}

TEST(BoxQPEdgeCases, IndefiniteMatrixIsNotConvex)
{
  const int n = 30;
  Active_set_box_QP_solver solver(n);
  std::vector<double> l(n, -1.), u(n, 1.);
  const Sparse_matrix P = squared_path_laplacian(n);
  set_matrix(solver, P);
  solver.set_P(17, 17, -100.); // makes P(17, 17) negative
  for (int i = 0; i < n; ++i) {
    solver.set_l(i, l[i]);
    solver.set_u(i, u[i]);
    solver.set_q(i, 0.1);
  }
  const Result result = solve(solver);
  EXPECT_EQ(result.report.status, Box_QP_status::NOT_CONVEX) << result.report.message;
  EXPECT_TRUE(within_bounds(result.x, l, u));
  EXPECT_NE(result.report.message.find("variable"), std::string::npos);
}

TEST(BoxQPEdgeCases, IndefiniteMatrixWithZeroDiagonalIsNotConvex)
{
  // [0 1; 1 0] has a zero first pivot whose coupling proves negative curvature.
  Active_set_box_QP_solver solver(2);
  solver.set_P(0, 1, 1.);
  const Result result = solve(solver);
  EXPECT_EQ(result.report.status, Box_QP_status::NOT_CONVEX) << result.report.message;
}

TEST(BoxQPEdgeCases, RandomIndefiniteMatricesAreNotConvex)
{
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 50; ++trial) {
    const int n = 3 + trial;
    // B^T B - s I with s above the smallest eigenvalue of B^T B is indefinite.
    Eigen::MatrixXd B(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        B(i, j) = normal(random);
    Eigen::MatrixXd P = B.transpose() * B;
    const double smallest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(P).eigenvalues()[0];
    P -= (smallest + 0.5) * Eigen::MatrixXd::Identity(n, n);
    Active_set_box_QP_solver solver(n);
    for (int i = 0; i < n; ++i)
      for (int j = i; j < n; ++j)
        solver.set_P(i, j, P(i, j));
    const Result result = solve(solver);
    EXPECT_EQ(result.report.status, Box_QP_status::NOT_CONVEX) << "n = " << n;
  }
}

TEST(BoxQPEdgeCases, IterationLimitIsReportedWithAPointWithinTheBounds)
{
  const int n = 200;
  const Sparse_matrix P = squared_path_laplacian(n);
  std::vector<double> l(n), u(n);
  Active_set_box_QP_solver solver(n);
  set_matrix(solver, P);
  for (int i = 0; i < n; ++i) {
    solver.set_q(i, -1e-3 * std::sin(0.1 * i) * i);
    l[i] = -0.01 * (1 + i % 3);
    u[i] = 0.01 * (1 + i % 4);
    solver.set_l(i, l[i]);
    solver.set_u(i, u[i]);
  }
  solver.set_maximum_number_of_iterations(1);
  const Result limited = solve(solver);
  EXPECT_EQ(limited.report.status, Box_QP_status::ITERATION_LIMIT);
  EXPECT_EQ(limited.report.iterations, 1u);
  EXPECT_TRUE(within_bounds(limited.x, l, u));

  solver.set_maximum_number_of_iterations(500);
  const Result full = solve(solver);
  ASSERT_EQ(full.report.status, Box_QP_status::OPTIMAL) << full.report.message;
  EXPECT_GT(full.report.iterations, 1u);
  EXPECT_LE(full.report.objective_value, limited.report.objective_value);
}

// set_P() adds: entries given in pieces, the lower triangle (ignored) and explicit zeros (in
// the pattern, not in the values) give the same solution as the matrix given once, both where
// the solver sums P in place (small problems) and where it collects triplets (large ones).
TEST(BoxQPEdgeCases, RepeatedEntriesAreSummedAtAnySize)
{
  for (const int n : {40, 700}) {
    const Sparse_matrix P = squared_path_laplacian(n);
    auto set_program = [&](Active_set_box_QP_solver& solver) {
      for (int i = 0; i < n; ++i) {
        solver.set_q(i, std::cos(0.3 * i));
        solver.set_l(i, -0.5 - 0.1 * (i % 3));
        solver.set_u(i, 0.4 + 0.1 * (i % 5));
      }
    };
    Active_set_box_QP_solver once(n), in_pieces(n);
    set_matrix(once, P);
    set_program(once);
    for (int j = 0; j < P.outerSize(); ++j)
      for (Sparse_matrix::InnerIterator it(P, j); it; ++it) {
        const std::size_t row = static_cast<std::size_t>(it.row()), col = std::size_t(j);
        in_pieces.set_P(row, col, 0.5 * it.value());
        in_pieces.set_P(row, col, 0.);
        in_pieces.set_P(row, col, 0.5 * it.value());
      }
    in_pieces.set_P(0, std::size_t(n - 1), 0.);
    set_program(in_pieces);
    const Result expected = solve(once), result = solve(in_pieces);
    ASSERT_EQ(expected.report.status, Box_QP_status::OPTIMAL) << expected.report.message;
    ASSERT_EQ(result.report.status, Box_QP_status::OPTIMAL) << result.report.message;
    ASSERT_EQ(result.x.size(), std::size_t(n));
    double largest = 0;
    for (double v : expected.x)
      largest = (std::max)(largest, std::abs(v));
    for (int i = 0; i < n; ++i)
      EXPECT_NEAR(result.x[std::size_t(i)], expected.x[std::size_t(i)], 1e-9 * largest)
          << "n = " << n << ", i = " << i;
  }
}

TEST(BoxQPEdgeCases, EmptyProblemIsOptimal)
{
  Active_set_box_QP_solver solver;
  solver.set_r(2.5);
  const Result result = solve(solver);
  EXPECT_EQ(result.report.status, Box_QP_status::OPTIMAL);
  EXPECT_TRUE(result.x.empty());
  EXPECT_EQ(result.report.objective_value, 2.5);
}

TEST(BoxQPEdgeCases, IndexOutOfRangeIsInvalidInput)
{
  Active_set_box_QP_solver solver(3);
  solver.set_P(0, 5, 1.);
  Result result = solve(solver);
  EXPECT_EQ(result.report.status, Box_QP_status::INVALID_INPUT);
  EXPECT_NE(result.report.message.find("set_P: index 5"), std::string::npos)
      << result.report.message;

  solver.resize(3);
  solver.set_u(3, 1.);
  result = solve(solver);
  EXPECT_EQ(result.report.status, Box_QP_status::INVALID_INPUT);
  EXPECT_NE(result.report.message.find("set_u: index 3"), std::string::npos)
      << result.report.message;

  solver.resize(3);
  solver.set_P(Sparse_matrix(4, 4));
  result = solve(solver);
  EXPECT_EQ(result.report.status, Box_QP_status::INVALID_INPUT);
}

TEST(BoxQPEdgeCases, WarmStartOfWrongSizeIsInvalidInputForOneSolve)
{
  Active_set_box_QP_solver solver(3);
  for (int i = 0; i < 3; ++i)
    solver.set_P(i, i, 1.);
  solver.set_warm_start(std::vector<double>(2, 0.));
  EXPECT_EQ(solve(solver).report.status, Box_QP_status::INVALID_INPUT);
  // The warm start applies to one solve only.
  EXPECT_EQ(solve(solver).report.status, Box_QP_status::OPTIMAL);
}

TEST(BoxQPEdgeCases, UpperTriangleIsReadAndEntriesAccumulate)
{
  // min 1/2 (2 x0^2 + 2 x0 x1 + 3 x1^2) - x0 + r, r = 1 + 2, given in pieces.
  Active_set_box_QP_solver pieces(2);
  pieces.set_P(0, 0, 1.);
  pieces.set_P(0, 0, 1.);
  pieces.set_P(0, 1, 0.25);
  pieces.set_P(0, 1, 0.75);
  pieces.set_P(1, 0, 100.); // lower triangle: ignored
  pieces.set_P(1, 1, 3.);
  pieces.set_q(0, -0.5);
  pieces.set_q(0, -0.5);
  pieces.set_r(1.);
  pieces.set_r(2.);
  const Result result = solve(pieces);
  ASSERT_EQ(result.report.status, Box_QP_status::OPTIMAL);
  // P = [2 1; 1 3], q = (-1, 0): x = P^-1 (1, 0) = (0.6, -0.2), f = -0.3 + 3.
  EXPECT_NEAR(result.x[0], 0.6, 1e-14);
  EXPECT_NEAR(result.x[1], -0.2, 1e-14);
  EXPECT_NEAR(result.report.objective_value, 2.7, 1e-14);

  Active_set_box_QP_solver bulk(2);
  Sparse_matrix P(2, 2);
  P.insert(0, 0) = 2.;
  P.insert(0, 1) = 1.;
  P.insert(1, 0) = 1.;
  P.insert(1, 1) = 3.;
  bulk.set_P(P);
  bulk.set_q(0, -1.);
  bulk.set_r(3.);
  const Result bulk_result = solve(bulk);
  EXPECT_EQ(bulk_result.x, result.x);
}

TEST(BoxQPEdgeCases, ResizeClearsTheProblemAndSolveCanBeRepeated)
{
  Active_set_box_QP_solver solver(2);
  solver.set_P(0, 0, 1.);
  solver.set_P(1, 1, 1.);
  solver.set_q(0, -1.);
  solver.set_u(0, 0.5);
  const Result first = solve(solver);
  const Result again = solve(solver);
  EXPECT_EQ(first.x, again.x);
  EXPECT_EQ(first.x[0], 0.5);

  solver.resize(2);
  solver.set_P(0, 0, 1.);
  solver.set_P(1, 1, 1.);
  solver.set_q(0, -1.);
  const Result cleared = solve(solver);
  EXPECT_NEAR(cleared.x[0], 1., 1e-14); // the old bound is gone
}

TEST(BoxQPEdgeCases, RandomMalformedProblemsGetADocumentedStatus)
{
  // Mixtures of the above, to be sure nothing crashes or hangs.
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  const double specials[] = {nan, infinity, -infinity, 0., 1e300, -1e300, 1e-300};
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 1 + trial % 17;
    Active_set_box_QP_solver solver(n);
    for (int k = 0; k < 3 * n; ++k) {
      const std::size_t i = random() % n, j = random() % n;
      solver.set_P(i, j, random() % 20 == 0 ? specials[random() % 7] : uniform(random));
    }
    for (int i = 0; i < n; ++i) {
      solver.set_P(i, i, random() % 3 == 0 ? 0. : 2.);
      solver.set_q(i, random() % 25 == 0 ? specials[random() % 7] : uniform(random));
      if (random() % 2)
        solver.set_l(i, random() % 15 == 0 ? specials[random() % 7] : uniform(random) - 1.);
      if (random() % 2)
        solver.set_u(i, random() % 15 == 0 ? specials[random() % 7] : uniform(random) + 1.);
    }
    solver.set_maximum_number_of_iterations(200);
    const Result result = solve(solver);
    ASSERT_EQ(result.x.size(), std::size_t(n));
    switch (result.report.status) {
    case Box_QP_status::INVALID_INPUT:
    case Box_QP_status::INFEASIBLE_BOUNDS:
      EXPECT_FALSE(result.report.message.empty());
      break;
    case Box_QP_status::OPTIMAL:
      EXPECT_LE(result.report.relative_kkt_residual, 1e-10);
      [[fallthrough]];
    default:
      for (double v : result.x)
        EXPECT_FALSE(std::isnan(v)) << to_string(result.report.status);
    }
  }
}

TEST(BoxQPEdgeCases, StatusNamesAreTheEnumerators)
{
  EXPECT_STREQ(to_string(Box_QP_status::OPTIMAL), "OPTIMAL");
  EXPECT_STREQ(to_string(Box_QP_status::ITERATION_LIMIT), "ITERATION_LIMIT");
  EXPECT_STREQ(to_string(Box_QP_status::INFEASIBLE_BOUNDS), "INFEASIBLE_BOUNDS");
  EXPECT_STREQ(to_string(Box_QP_status::NOT_CONVEX), "NOT_CONVEX");
  EXPECT_STREQ(to_string(Box_QP_status::UNBOUNDED), "UNBOUNDED");
  EXPECT_STREQ(to_string(Box_QP_status::INVALID_INPUT), "INVALID_INPUT");
  EXPECT_STREQ(to_string(Box_QP_status::NUMERICAL_FAILURE), "NUMERICAL_FAILURE");
}

} // namespace

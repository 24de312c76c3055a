// The assembly of P in internal::Box_QP_problem above the dense size: entries of the pattern of
// the problems before are summed in place, the others wait as triplets and are merged into the
// pattern. Whichever way an entry takes, the assembled matrix must be the one the calls
// describe: the entries set in this problem only, each summed in the order of its calls.

#include <CGAL/Highlight_lines/internal/qp/Box_QP_problem.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

using CGAL::Highlight_lines::Box_QP_status;
using CGAL::Highlight_lines::internal::Box_QP_problem;

struct Call
{
  std::size_t i, j;
  double value;
};

// Upper-triangle calls on `pairs` random entries of an n x n matrix (diagonal included),
// each entry called 1 to `repeats` times, interleaved at random.
std::vector<Call> random_calls(std::size_t n, std::size_t pairs, int repeats, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_int_distribution<std::size_t> index(0, n - 1);
  std::uniform_int_distribution<int> times(1, repeats);
  std::uniform_real_distribution<double> value(-1., 1.);
  std::vector<Call> calls;
  for (std::size_t k = 0; k < pairs; ++k) {
    std::size_t i = index(random), j = index(random);
    if (i > j)
      std::swap(i, j);
    if (k % 7 == 0)
      i = j;
    for (int t = times(random); t > 0; --t)
      calls.push_back({i, j, value(random)});
  }
  std::shuffle(calls.begin(), calls.end(), random);
  return calls;
}

void assemble(Box_QP_problem& problem, std::size_t n, const std::vector<Call>& calls)
{
  problem.resize(n);
  for (const Call& call : calls)
    problem.add_P(call.i, call.j, call.value);
  std::string message;
  ASSERT_EQ(problem.validate(message), Box_QP_status::OPTIMAL) << message;
  problem.assemble();
}

// The matrix the calls describe, computed independently: each entry summed in call order from
// zero, both triangles, every diagonal entry present; by (column, row).
void expect_matrix_of(const Box_QP_problem& problem, std::size_t n, const std::vector<Call>& calls)
{
  std::map<std::pair<std::size_t, std::size_t>, double> upper, expected;
  for (std::size_t k = 0; k < n; ++k)
    upper[{k, k}] = 0.;
  for (const Call& call : calls)
    upper[{call.i, call.j}] += call.value; // a new entry starts from zero
  for (const auto& entry : upper) {
    expected[{entry.first.second, entry.first.first}] = entry.second;
    expected[{entry.first.first, entry.first.second}] = entry.second;
  }
  const auto& P = problem.P();
  ASSERT_EQ(std::size_t(P.rows()), n);
  ASSERT_EQ(std::size_t(P.nonZeros()), expected.size());
  auto it = expected.begin();
  for (int column = 0; column < P.outerSize(); ++column)
    for (Box_QP_problem::Sparse_matrix::InnerIterator p(P, column); p; ++p, ++it) {
      ASSERT_EQ(it->first.first, std::size_t(column));
      ASSERT_EQ(it->first.second, std::size_t(p.row())) << "column " << column;
      // Bit for bit: the same sums in the same order.
      ASSERT_EQ(p.value(), it->second) << "P(" << p.row() << ", " << column << ")";
    }
}

constexpr std::size_t n = 1500; // above the dense size (512)

TEST(BoxQPProblemAssembly, ALargeProblemHoldsTheSumsOfItsCallsInCallOrder)
{
  // 40,000 calls on 3 n entries: the triplets are merged into the pattern during the calls
  // (from 8 n of them), and entries set before a merge are summed in place after it.
  const std::vector<Call> calls = random_calls(n, 3 * n, 20, 1);
  ASSERT_GT(calls.size(), 8 * n);
  Box_QP_problem problem;
  assemble(problem, n, calls);
  expect_matrix_of(problem, n, calls);
}

TEST(BoxQPProblemAssembly, TheNextProblemHoldsOnlyItsOwnEntries)
{
  // The second problem shares part of the first one's pattern, leaves the rest unset and adds
  // entries of its own: only its own entries, and zero on unset diagonals, are in its matrix.
  const std::vector<Call> first = random_calls(n, 2 * n, 4, 2);
  std::vector<Call> second = random_calls(n, n, 4, 3);
  for (std::size_t k = 0; k < first.size(); k += 3)
    second.push_back({first[k].i, first[k].j, 0.5 * first[k].value});
  Box_QP_problem problem;
  assemble(problem, n, first);
  assemble(problem, n, second);
  expect_matrix_of(problem, n, second);
  // And the first one again: the entries only the second problem set are gone.
  assemble(problem, n, first);
  expect_matrix_of(problem, n, first);
  // A problem that sets a few of the entries (the pattern keeps only those afterwards), then
  // the first one again.
  const std::vector<Call> few = random_calls(n, n / 10, 2, 10);
  assemble(problem, n, few);
  expect_matrix_of(problem, n, few);
  assemble(problem, n, first);
  expect_matrix_of(problem, n, first);
}

TEST(BoxQPProblemAssembly, AnotherNumberOfVariablesStartsAFreshPattern)
{
  Box_QP_problem problem;
  assemble(problem, n, random_calls(n, 2 * n, 3, 4));
  const std::vector<Call> smaller = random_calls(n - 100, n, 3, 5);
  assemble(problem, n - 100, smaller);
  expect_matrix_of(problem, n - 100, smaller);
  // Dense in between: the sparse pattern starts again afterwards.
  assemble(problem, 100, random_calls(100, 300, 3, 6));
  const std::vector<Call> again = random_calls(n, 2 * n, 3, 7);
  assemble(problem, n, again);
  expect_matrix_of(problem, n, again);
}

TEST(BoxQPProblemAssembly, ANonFiniteSumInThePatternIsReported)
{
  const std::vector<Call> calls = random_calls(n, 2 * n, 3, 8);
  Box_QP_problem problem;
  assemble(problem, n, calls); // every entry of `calls` is in the pattern now
  problem.resize(n);
  for (const Call& call : calls)
    problem.add_P(call.i, call.j, call.value);
  problem.add_P(calls[5].i, calls[5].j, std::numeric_limits<double>::infinity());
  std::string message;
  EXPECT_EQ(problem.validate(message), Box_QP_status::INVALID_INPUT);
  const std::string entry =
      "P(" + std::to_string(calls[5].i) + ", " + std::to_string(calls[5].j) + ") is ";
  EXPECT_EQ(message.rfind(entry, 0), 0u) << message;
}

// Finite terms whose sum overflows: rejected whether they wait as triplets (a fresh problem)
// or are summed in the pattern (the same problem again), as the dense sums are.
TEST(BoxQPProblemAssembly, AnOverflowingSumIsReportedWhereverItsTermsWait)
{
  const std::vector<Call> calls = random_calls(n, 2 * n, 3, 9);
  Box_QP_problem problem;
  for (int round = 0; round < 2; ++round) {
    SCOPED_TRACE(round == 0 ? "as triplets" : "in the pattern");
    problem.resize(n);
    for (const Call& call : calls)
      problem.add_P(call.i, call.j, call.value);
    problem.add_P(3, 7, 1e308);
    problem.add_P(3, 7, 1e308);
    std::string message;
    EXPECT_EQ(problem.validate(message), Box_QP_status::INVALID_INPUT);
    EXPECT_EQ(message, "P(3, 7) is inf");
  }
}

} // namespace

// The sparse factorisation inside Active_set_box_QP_solver: solves like Eigen's
// SimplicialLDLT on definite matrices, tells semidefinite and indefinite matrices apart, and
// finds null-space directions of semidefinite ones.

#include <CGAL/Highlight_lines/internal/qp/Supernodal_LDLT.h>
#include <CGAL/Highlight_lines/internal/qp/fill_reducing_ordering.h>
#include <CGAL/Highlight_lines/internal/qp/uninitialized_array.h>

#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <new>
#include <limits>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

namespace {

using CGAL::Highlight_lines::internal::Supernodal_LDLT;
using Sparse_matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// A symmetric sparse matrix from random edges: the weighted graph Laplacian (semidefinite,
// null space = constants on each connected component) plus `shift` on the diagonal.
Sparse_matrix random_graph_matrix(std::mt19937& random, int n, int edges, double shift,
                                  bool connected)
{
  std::uniform_real_distribution<double> weight(0.1, 2.);
  std::vector<Eigen::Triplet<double>> entries;
  const auto add_edge = [&](int a, int b) {
    const double w = weight(random);
    entries.emplace_back(a, b, -w);
    entries.emplace_back(b, a, -w);
    entries.emplace_back(a, a, w);
    entries.emplace_back(b, b, w);
  };
  if (connected)
    for (int i = 0; i + 1 < n; ++i)
      add_edge(i, i + 1);
  for (int e = 0; e < edges; ++e) {
    const int a = static_cast<int>(random() % n), b = static_cast<int>(random() % n);
    if (a != b)
      add_edge(a, b);
  }
  for (int i = 0; i < n; ++i)
    entries.emplace_back(i, i, shift);
  Sparse_matrix A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  A.makeCompressed();
  return A;
}

std::vector<int> amd_ordering(const Sparse_matrix& A)
{
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> permutation;
  Eigen::AMDOrdering<int>()(A, permutation);
  return std::vector<int>(permutation.indices().data(), permutation.indices().data() + A.rows());
}

Supernodal_LDLT::Inertia factorize(Supernodal_LDLT& ldlt, const Sparse_matrix& A,
                                   const std::vector<int>& ordering)
{
  ldlt.analyze(static_cast<int>(A.rows()), A.outerIndexPtr(), A.innerIndexPtr(), ordering);
  return ldlt.factorize(A.valuePtr(), 1e-12);
}

TEST(SupernodalLDLT, SolvesDefiniteSystemsLikeEigenSimplicialLDLT)
{
  std::mt19937 random(1);
  for (int n : {1, 2, 7, 60, 500, 3000}) {
    const Sparse_matrix A = random_graph_matrix(random, n, 3 * n, 0.05, true);
    std::vector<int> natural(n);
    std::iota(natural.begin(), natural.end(), 0);
    for (const std::vector<int>& ordering : {natural, amd_ordering(A)}) {
      Supernodal_LDLT ldlt;
      ASSERT_EQ(factorize(ldlt, A, ordering), Supernodal_LDLT::Inertia::POSITIVE_DEFINITE);
      const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
      Eigen::VectorXd x = b;
      ldlt.solve(x);
      const Eigen::VectorXd reference = Eigen::SimplicialLDLT<Sparse_matrix>(A).solve(b);
      EXPECT_LE((A * x - b).norm(), 1e-10 * b.norm()) << "n = " << n;
      EXPECT_LE((x - reference).norm(), 1e-8 * reference.norm()) << "n = " << n;
      EXPECT_EQ(ldlt.number_of_zero_pivots(), 0);
    }
  }
}

TEST(SupernodalLDLT, SolvesInSinglePrecisionToItsAccuracyAtAnyScale)
{
  // The preconditioner's solve: within float's relative accuracy (times the growth of a
  // moderately conditioned matrix) of the double solve, for matrices and right-hand sides
  // scaled far beyond float's range, and again after a refactorisation with other values
  // (the single-precision copy of the factor is made anew).
  std::mt19937 random(7);
  for (int n : {1, 60, 3000}) {
    const Sparse_matrix A = random_graph_matrix(random, n, 3 * n, 0.05, true);
    const std::vector<int> ordering = amd_ordering(A);
    for (double scale : {1., 1e-45, 1e45}) {
      SCOPED_TRACE(scale);
      const Sparse_matrix scaled = scale * A;
      Supernodal_LDLT ldlt;
      ASSERT_EQ(factorize(ldlt, scaled, ordering), Supernodal_LDLT::Inertia::POSITIVE_DEFINITE);
      for (int refactorisation = 0; refactorisation < 2; ++refactorisation) {
        if (refactorisation == 1) {
          const Sparse_matrix shifted = scaled * 2.5;
          ASSERT_EQ(ldlt.factorize(shifted.valuePtr(), 1e-12),
                    Supernodal_LDLT::Inertia::POSITIVE_DEFINITE);
        }
        for (double b_scale : {1., 1e-40, 1e40}) {
          const Eigen::VectorXd b = b_scale * Eigen::VectorXd::Random(n);
          Eigen::VectorXd exact = b, single = b;
          ldlt.solve(exact);
          ldlt.solve_in_single_precision(single);
          ASSERT_TRUE(single.allFinite()) << "n = " << n;
          EXPECT_LE((single - exact).norm(), 1e-4 * exact.norm()) << "n = " << n;
          if (n > 1) {
            EXPECT_GT((single - exact).norm(), 0.) << "n = " << n; // floats were used
          }
        }
      }
      Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
      ldlt.solve_in_single_precision(zero);
      EXPECT_EQ(zero.cwiseAbs().maxCoeff(), 0.);
    }
  }
}

// The column counts of the factor, computed from the elimination tree in almost O(nnz(A)),
// against a symbolic elimination on dense boolean columns, on random patterns (connected or
// not, sparse or dense), renumbered in a postorder of their elimination tree as the
// factorisation does.
TEST(SupernodalLDLT, ColumnCountsMatchASymbolicElimination)
{
  std::mt19937 random(7);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 1 + static_cast<int>(random() % 70);
    const Sparse_matrix A =
        random_graph_matrix(random, n, static_cast<int>(random() % (3 * n + 1)), 1., trial % 2);
    // Symbolic elimination in the natural order: the rows below the diagonal of each column.
    const auto eliminate = [n](const std::vector<std::vector<char>>& below) {
      std::vector<std::vector<char>> L = below;
      std::vector<int> parent(n, -1);
      for (int j = 0; j < n; ++j)
        for (int i = j + 1; i < n; ++i)
          if (L[j][i]) {
            if (parent[j] == -1)
              parent[j] = i;
            else
              L[parent[j]][i] = 1;
          }
      std::vector<int> count(n, 1);
      for (int j = 0; j < n; ++j)
        count[j] += static_cast<int>(std::count(L[j].begin() + j + 1, L[j].end(), 1));
      return std::make_pair(parent, count);
    };
    std::vector<std::vector<char>> below(n, std::vector<char>(n, 0));
    for (int j = 0; j < n; ++j)
      for (Sparse_matrix::InnerIterator it(A, j); it; ++it)
        if (it.row() > j)
          below[j][it.row()] = 1;
    const auto [parent, count] = eliminate(below);
    // A postorder (children in increasing order, roots in increasing order).
    std::vector<std::vector<int>> children(n);
    for (int j = 0; j < n; ++j)
      if (parent[j] != -1)
        children[parent[j]].push_back(j);
    std::vector<int> post, position(n);
    const std::function<void(int)> visit = [&](int j) {
      for (int c : children[j])
        visit(c);
      position[j] = static_cast<int>(post.size());
      post.push_back(j);
    };
    for (int j = 0; j < n; ++j)
      if (parent[j] == -1)
        visit(j);
    // The tree and the lower triangle of A (diagonal included) in the postorder.
    std::vector<int> tree(n, -1), Bp(n + 1, 0), Bi;
    for (int j = 0; j < n; ++j)
      if (parent[j] != -1)
        tree[position[j]] = position[parent[j]];
    for (int k = 0; k < n; ++k) {
      std::vector<int> rows;
      for (Sparse_matrix::InnerIterator it(A, post[k]); it; ++it)
        if (position[it.row()] >= k)
          rows.push_back(position[it.row()]);
      std::sort(rows.begin(), rows.end());
      Bi.insert(Bi.end(), rows.begin(), rows.end());
      Bp[k + 1] = static_cast<int>(Bi.size());
    }
    std::vector<int> computed;
    CGAL::Highlight_lines::internal::cholesky_column_counts(tree, Bp, Bi, computed);
    for (int j = 0; j < n; ++j)
      ASSERT_EQ(computed[position[j]], count[j]) << "trial " << trial << ", column " << j;
  }
}

TEST(SupernodalLDLT, RefactorisingNewValuesReusesTheAnalysis)
{
  std::mt19937 random(2);
  const Sparse_matrix A = random_graph_matrix(random, 400, 1200, 0.1, true);
  Supernodal_LDLT ldlt;
  factorize(ldlt, A, amd_ordering(A));
  const Sparse_matrix B = 3. * A; // same pattern, new values
  ASSERT_EQ(ldlt.factorize(B.valuePtr(), 1e-12), Supernodal_LDLT::Inertia::POSITIVE_DEFINITE);
  const Eigen::VectorXd b = Eigen::VectorXd::Random(400);
  Eigen::VectorXd x = b;
  ldlt.solve(x);
  EXPECT_LE((B * x - b).norm(), 1e-10 * b.norm());
}

// The factor's storage is reused and left uninitialised between analyses: each factorisation
// must write all of it, whatever an earlier, larger or smaller, factor left there; and a copy
// or a move must solve as the original.
TEST(SupernodalLDLT, ReanalysingOtherPatternsAndCopyingGiveTheSameSolutions)
{
  std::mt19937 random(7);
  Supernodal_LDLT ldlt;
  for (int n : {300, 3000, 40, 3000}) { // a chain with a few shortcuts: moderate fill
    const Sparse_matrix A = random_graph_matrix(random, n, n / 20, 0.1, true);
    ASSERT_EQ(factorize(ldlt, A, amd_ordering(A)), Supernodal_LDLT::Inertia::POSITIVE_DEFINITE)
        << "n = " << n;
    const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
    Eigen::VectorXd x = b;
    ldlt.solve(x);
    EXPECT_LE((A * x - b).norm(), 1e-10 * b.norm()) << "n = " << n;
    Supernodal_LDLT copy = ldlt;
    Eigen::VectorXd y = b;
    copy.solve(y);
    EXPECT_EQ(x, y) << "n = " << n;
    const Supernodal_LDLT moved = std::move(copy);
    Eigen::VectorXd z = b;
    moved.solve(z);
    EXPECT_EQ(x, z) << "n = " << n;
  }
}

TEST(SupernodalLDLT, DetectsIndefiniteMatrices)
{
  std::mt19937 random(3);
  for (int n : {2, 10, 200, 2000}) {
    // A Laplacian minus a multiple of the identity larger than its smallest eigenvalue (0).
    const Sparse_matrix A = random_graph_matrix(random, n, 2 * n, -0.01, true);
    Supernodal_LDLT ldlt;
    EXPECT_EQ(factorize(ldlt, A, amd_ordering(A)), Supernodal_LDLT::Inertia::INDEFINITE)
        << "n = " << n;
    EXPECT_GE(ldlt.negative_pivot(), 0);
    EXPECT_LT(ldlt.negative_pivot(), n);
  }
}

TEST(SupernodalLDLT, FindsTheNullSpaceOfSemidefiniteMatrices)
{
  std::mt19937 random(4);
  for (int n : {3, 50, 1000}) {
    const Sparse_matrix A = random_graph_matrix(random, n, 2 * n, 0., true);
    Supernodal_LDLT ldlt;
    ASSERT_EQ(factorize(ldlt, A, amd_ordering(A)), Supernodal_LDLT::Inertia::POSITIVE_SEMIDEFINITE);
    EXPECT_EQ(ldlt.number_of_zero_pivots(), 1); // connected: the constants only

    // b orthogonal to the constants: a true solution, no null-space part.
    Eigen::VectorXd b = Eigen::VectorXd::Random(n);
    b.array() -= b.mean();
    Eigen::VectorXd x, null_direction;
    ldlt.solve_with_null_space_part(b, x, null_direction);
    EXPECT_LE((A * x - b).norm(), 1e-9 * b.norm()) << "n = " << n;
    EXPECT_LE(null_direction.norm(), 1e-9 * x.norm()) << "n = " << n;

    // b along the constants: the null-space part is a constant vector with b^T v > 0.
    b.setOnes();
    ldlt.solve_with_null_space_part(b, x, null_direction);
    ASSERT_GT(b.dot(null_direction), 0.);
    EXPECT_LE((A * null_direction).norm(), 1e-9 * A.norm() * null_direction.norm());
    EXPECT_LE((null_direction.array() - null_direction.mean()).matrix().norm(),
              1e-9 * null_direction.norm());
  }
}

TEST(SupernodalLDLT, CountsOneZeroPivotPerConnectedComponent)
{
  std::mt19937 random(5);
  // Two disconnected paths: a 2-dimensional null space.
  std::vector<Eigen::Triplet<double>> entries;
  const int half = 40;
  for (int i = 0; i + 1 < 2 * half; ++i)
    if (i != half - 1)
      for (const auto& e :
           {Eigen::Triplet<double>(i, i + 1, -1.), Eigen::Triplet<double>(i + 1, i, -1.),
            Eigen::Triplet<double>(i, i, 1.), Eigen::Triplet<double>(i + 1, i + 1, 1.)})
        entries.push_back(e);
  Sparse_matrix A(2 * half, 2 * half);
  A.setFromTriplets(entries.begin(), entries.end());
  A.makeCompressed();
  Supernodal_LDLT ldlt;
  EXPECT_EQ(factorize(ldlt, A, amd_ordering(A)), Supernodal_LDLT::Inertia::POSITIVE_SEMIDEFINITE);
  EXPECT_EQ(ldlt.number_of_zero_pivots(), 2);
}

TEST(SupernodalLDLT, CouplingOfAZeroPivotProvesIndefiniteness)
{
  // [0 1; 1 0]: the first pivot is zero and its column is not.
  Sparse_matrix A(2, 2);
  A.insert(0, 0) = 0.;
  A.insert(1, 1) = 0.;
  A.insert(0, 1) = 1.;
  A.insert(1, 0) = 1.;
  A.makeCompressed();
  Supernodal_LDLT ldlt;
  EXPECT_EQ(factorize(ldlt, A, {0, 1}), Supernodal_LDLT::Inertia::INDEFINITE);
}

TEST(SupernodalLDLT, EmptyMatrixIsPositiveDefinite)
{
  Sparse_matrix A(0, 0);
  A.makeCompressed();
  Supernodal_LDLT ldlt;
  EXPECT_EQ(factorize(ldlt, A, {}), Supernodal_LDLT::Inertia::POSITIVE_DEFINITE);
}

// A grid's 1-ring Laplacian raised to the power `rings` (its pattern couples the vertices within
// `rings` edges) times its transpose, plus `shift` I: symmetric positive definite, the pattern of
// a fairing program of 2 `rings` rings (a fairing couples vertices within three edges).
Sparse_matrix grid_matrix(int side, int rings, double shift)
{
  const int n = side * side;
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      const int v = i * side + j;
      entries.emplace_back(v, v, 4.5);
      const int di[] = {-1, 1, 0, 0}, dj[] = {0, 0, -1, 1};
      for (int k = 0; k < 4; ++k)
        if (i + di[k] >= 0 && i + di[k] < side && j + dj[k] >= 0 && j + dj[k] < side)
          entries.emplace_back(v, (i + di[k]) * side + j + dj[k], -1.);
    }
  Sparse_matrix L(n, n);
  L.setFromTriplets(entries.begin(), entries.end());
  Sparse_matrix power = L;
  for (int r = 1; r < rings; ++r)
    power = Sparse_matrix(power * L);
  Sparse_matrix identity(n, n);
  identity.setIdentity();
  Sparse_matrix A = Sparse_matrix(power.transpose() * power) + shift * identity;
  A.makeCompressed();
  return A;
}

using CGAL::Highlight_lines::internal::fill_reducing_ordering;
using CGAL::Highlight_lines::internal::Ordering_method;

TEST(FillReducingOrdering, BothMethodsGivePermutationsThatSolve)
{
  const Sparse_matrix A = grid_matrix(40, 2, 0.01);
  const int n = static_cast<int>(A.rows());
  for (Ordering_method method :
       {Ordering_method::MINIMUM_DEGREE, Ordering_method::NESTED_DISSECTION}) {
    const std::vector<int> ordering = fill_reducing_ordering(A, method);
    std::vector<int> sorted = ordering;
    std::sort(sorted.begin(), sorted.end());
    std::vector<int> identity(n);
    std::iota(identity.begin(), identity.end(), 0);
    ASSERT_EQ(sorted, identity);
    Supernodal_LDLT ldlt;
    ASSERT_EQ(factorize(ldlt, A, ordering), Supernodal_LDLT::Inertia::POSITIVE_DEFINITE);
    const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
    Eigen::VectorXd x = b;
    ldlt.solve(x);
    EXPECT_LE((A * x - b).norm(), 1e-10 * b.norm());
  }
}

// A pattern without off-diagonal entries (a graph without edges, on which METIS_NodeND fails)
// still gets an ordering, by either method.
TEST(FillReducingOrdering, ADiagonalPatternIsOrdered)
{
  Sparse_matrix A(50, 50);
  A.setIdentity();
  A.makeCompressed();
  for (Ordering_method method :
       {Ordering_method::MINIMUM_DEGREE, Ordering_method::NESTED_DISSECTION}) {
    std::vector<int> ordering = fill_reducing_ordering(A, method);
    std::sort(ordering.begin(), ordering.end());
    std::vector<int> identity(50);
    std::iota(identity.begin(), identity.end(), 0);
    EXPECT_EQ(ordering, identity);
  }
}

// Nested dissection's separators beat minimum degree on large two-dimensional meshes
// (George 1973), which is why the solver tries it there.
TEST(FillReducingOrdering, NestedDissectionNeedsFewerFlopsOnALargeGrid)
{
  if (!CGAL::Highlight_lines::internal::has_nested_dissection())
    GTEST_SKIP() << "METIS not linked (CGAL_METIS_ENABLED undefined)";
  const Sparse_matrix A = grid_matrix(150, 1, 0.);
  const int n = static_cast<int>(A.rows());
  Supernodal_LDLT minimum_degree, nested_dissection;
  minimum_degree.analyze(n, A.outerIndexPtr(), A.innerIndexPtr(),
                         fill_reducing_ordering(A, Ordering_method::MINIMUM_DEGREE));
  nested_dissection.analyze(n, A.outerIndexPtr(), A.innerIndexPtr(),
                            fill_reducing_ordering(A, Ordering_method::NESTED_DISSECTION));
  EXPECT_LT(nested_dissection.factorization_flops(), 0.9 * minimum_degree.factorization_flops());
}

// The solver's analysis: with a threshold of 0 flops per entry nested dissection is always
// tried, and the analysis of fewer flops is kept; the returned ordering is the analysed one.
TEST(FillReducingOrdering, TheAnalysisKeepsTheOrderingOfFewerFlops)
{
  using CGAL::Highlight_lines::internal::analyze_in_fill_reducing_ordering;
  // Nested dissection wins on the large grid, minimum degree on the small wide one.
  for (const Sparse_matrix& A : {grid_matrix(150, 1, 0.01), grid_matrix(60, 3, 1.)}) {
    const int n = static_cast<int>(A.rows());
    double fewest = std::numeric_limits<double>::infinity();
    for (Ordering_method method :
         {Ordering_method::MINIMUM_DEGREE, Ordering_method::NESTED_DISSECTION}) {
      Supernodal_LDLT single;
      single.analyze(n, A.outerIndexPtr(), A.innerIndexPtr(), fill_reducing_ordering(A, method));
      fewest = std::min(fewest, single.factorization_flops());
    }
    Supernodal_LDLT ldlt, check;
    const std::vector<int> ordering = analyze_in_fill_reducing_ordering(ldlt, A, 0.);
    EXPECT_EQ(ldlt.factorization_flops(), fewest);
    check.analyze(n, A.outerIndexPtr(), A.innerIndexPtr(), ordering);
    EXPECT_EQ(check.factorization_flops(), ldlt.factorization_flops());
    ASSERT_EQ(ldlt.factorize(A.valuePtr(), 1e-12), Supernodal_LDLT::Inertia::POSITIVE_DEFINITE);
    const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
    Eigen::VectorXd x = b;
    ldlt.solve(x);
    EXPECT_LE((A * x - b).norm(), 1e-10 * b.norm());
    // The default threshold keeps minimum degree on matrices this small.
    Supernodal_LDLT by_default;
    EXPECT_EQ(analyze_in_fill_reducing_ordering(by_default, A),
              fill_reducing_ordering(A, Ordering_method::MINIMUM_DEGREE));
  }
}

// Sanitizers' allocators report an impossible allocation as an error instead of throwing.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define HIGHLIGHT_LINES_TEST_SANITIZED_ALLOCATOR
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) ||                         \
    __has_feature(memory_sanitizer) || __has_feature(hwaddress_sanitizer)
#define HIGHLIGHT_LINES_TEST_SANITIZED_ALLOCATOR
#endif
#endif

// The factor's storage: kept when large enough, values copied and moved whole, and empty (not
// a size without storage) when an allocation fails.
TEST(UninitializedArray, KeepsItsStorageAndIsEmptyAfterAFailedAllocation)
{
  using CGAL::Highlight_lines::internal::Uninitialized_array;
  Uninitialized_array<double> array;
  array.resize(100);
  std::iota(array.data(), array.data() + 100, 0.);
  const double* storage = array.data();
  array.resize(50);
  EXPECT_EQ(array.data(), storage);
  EXPECT_EQ(array.size(), 50u);
  Uninitialized_array<double> copy = array;
  EXPECT_NE(copy.data(), array.data());
  EXPECT_TRUE(std::equal(array.data(), array.data() + 50, copy.data()));
  const Uninitialized_array<double> moved = std::move(copy);
  EXPECT_EQ(moved.size(), 50u);
  EXPECT_EQ(moved.data()[49], 49.);
  EXPECT_EQ(copy.size(), 0u);
#if defined(HIGHLIGHT_LINES_TEST_SANITIZED_ALLOCATOR)
  GTEST_SKIP() << "the sanitizer's allocator aborts on an impossible allocation, not throwing";
#else
  EXPECT_THROW(array.resize(std::numeric_limits<std::size_t>::max() / 16), std::bad_alloc);
  EXPECT_EQ(array.size(), 0u);
  array.resize(10); // usable again
  array.data()[9] = 1.;
  EXPECT_EQ(array.size(), 10u);
#endif
}

} // namespace

// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_QP_FILL_REDUCING_ORDERING_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_QP_FILL_REDUCING_ORDERING_H

#include <CGAL/Highlight_lines/internal/qp/Supernodal_LDLT.h>

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>

#include <cstddef>
#include <utility>
#include <vector>

#if defined(CGAL_METIS_ENABLED)
#include <metis.h>
#endif

namespace CGAL {
namespace Highlight_lines {
namespace internal {

enum class Ordering_method {
  MINIMUM_DEGREE,   // approximate minimum degree (Eigen's port of AMD)
  NESTED_DISSECTION // METIS_NodeND; minimum degree where METIS is not linked
};

// Whether nested dissection is available (METIS linked: CGAL::METIS_support defines
// CGAL_METIS_ENABLED).
inline constexpr bool has_nested_dissection()
{
#if defined(CGAL_METIS_ENABLED)
  return true;
#else
  return false;
#endif
}

// When a minimum degree ordering's factorisation takes more flops per entry of the pattern
// than this, nested dissection is tried as well, and the ordering of fewer flops is kept.
// METIS costs 0.3-0.5 µs per entry more than minimum degree; where it wins it saves about a
// third of the flops, at ~16 GFlop/s: the 3-4 factorisations of a large fairing repay it from
// about 5000 flops per entry. Measured (December 7, 2026; benchmark_scale --fairing-only, old
// and new binaries alternated) on fairings, whose programs couple the vertices within three
// edges: at 10^5 movable vertices 8,400 flops per entry, nested dissection 42 % fewer flops
// and 20 % fewer factor entries (a factorisation 1.87 -> 1.21 s), the fairing's median 17.4 ->
// 15.0 s (six and seven runs, each 14 to 21 s); at 4.8 10^4, 5.4 / 5.2 -> 4.4 / 4.4 s; at 2.4
// 10^4 no difference (1.7 / 1.6 s both). On the
// two-ring bi-Laplacians of benchmark_factorization (1,750 to 3,900 flops per entry from 2.5
// 10^4 to 10^5 variables) METIS's ordering costs more than four factorisations save; counting
// the preconditioning solves too (nested dissection takes 0.8 times a solve at 10^5, and a
// large fairing makes ~140), the balance there is close (benchmark_factorization --table).
constexpr double nested_dissection_flops_per_entry = 5000;

// The fill-reducing ordering of the symmetric pattern `pattern` (both triangles stored, the
// diagonal may be): ordering[k] is the variable eliminated at position k. `pattern` is taken
// by value: minimum degree overwrites its argument.
template <typename Sparse_matrix>
std::vector<int> fill_reducing_ordering(Sparse_matrix pattern, Ordering_method method)
{
  const int n = static_cast<int>(pattern.cols());
#if defined(CGAL_METIS_ENABLED)
  if (method == Ordering_method::NESTED_DISSECTION && n > 1) {
    // METIS wants the adjacency graph: no diagonal entries.
    std::vector<idx_t> first(static_cast<std::size_t>(n) + 1, 0), neighbors;
    neighbors.reserve(static_cast<std::size_t>(pattern.nonZeros()));
    for (int j = 0; j < n; ++j) {
      for (typename Sparse_matrix::InnerIterator it(pattern, j); it; ++it)
        if (it.index() != j)
          neighbors.push_back(static_cast<idx_t>(it.index()));
      first[static_cast<std::size_t>(j) + 1] = static_cast<idx_t>(neighbors.size());
    }
    idx_t vertices = n, options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    std::vector<idx_t> permutation(static_cast<std::size_t>(n)),
        inverse(static_cast<std::size_t>(n));
    // METIS_NodeND's perm is the variable at each position, as ours. It fails on a graph
    // without edges (where any ordering does): minimum degree below, as on any failure.
    if (!neighbors.empty() && METIS_NodeND(&vertices, first.data(), neighbors.data(), nullptr,
                                           options, permutation.data(), inverse.data()) == METIS_OK)
      return std::vector<int>(permutation.begin(), permutation.end());
  }
#else
  (void)method;
#endif
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> permutation;
  Eigen::internal::minimum_degree_ordering(pattern, permutation);
  // AMD returns, for each elimination position, the variable eliminated there.
  return std::vector<int>(permutation.indices().data(), permutation.indices().data() + n);
}

// Analyses the symmetric pattern `pattern` (both triangles stored, compressed) into `ldlt` in a
// minimum degree ordering, and where that factorisation takes more than `flops_per_entry`
// flops per entry of the pattern and METIS is linked, in a nested dissection ordering too;
// keeps the analysis of fewer flops and returns its ordering.
template <typename Sparse_matrix>
std::vector<int>
analyze_in_fill_reducing_ordering(Supernodal_LDLT& ldlt, const Sparse_matrix& pattern,
                                  double flops_per_entry = nested_dissection_flops_per_entry)
{
  const int n = static_cast<int>(pattern.cols());
  std::vector<int> ordering = fill_reducing_ordering(pattern, Ordering_method::MINIMUM_DEGREE);
  ldlt.analyze(n, pattern.outerIndexPtr(), pattern.innerIndexPtr(), ordering);
  const double minimum_degree_flops = ldlt.factorization_flops();
  if (!has_nested_dissection() ||
      !(minimum_degree_flops > flops_per_entry * double(pattern.nonZeros())))
    return ordering;
  std::vector<int> dissection = fill_reducing_ordering(pattern, Ordering_method::NESTED_DISSECTION);
  ldlt.analyze(n, pattern.outerIndexPtr(), pattern.innerIndexPtr(), dissection);
  if (ldlt.factorization_flops() < minimum_degree_flops)
    return dissection;
  ldlt.analyze(n, pattern.outerIndexPtr(), pattern.innerIndexPtr(), ordering);
  return ordering;
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_QP_FILL_REDUCING_ORDERING_H

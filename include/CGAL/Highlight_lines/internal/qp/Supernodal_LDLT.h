// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_QP_SUPERNODAL_LDLT_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_QP_SUPERNODAL_LDLT_H

#include <CGAL/Highlight_lines/internal/qp/bucket_sort.h>
#include <CGAL/Highlight_lines/internal/qp/uninitialized_array.h>
#include <CGAL/assertions.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// The column counts of the Cholesky factor L of A (diagonal included) from the elimination
// tree of A, numbered in postorder (tree[j]: the parent of j, -1 for a root), and the lower
// triangle of A by columns (Bp, Bi), in almost O(nnz(A)) instead of O(nnz(L)): the
// skeleton-matrix method of Gilbert, Ng and Peyton (1994) as in CSparse's cs_counts. Row i
// of L is the union of the tree paths from the columns j < i of row i of A up to i; delta
// counts, per column, where such paths start (leaves of row subtrees) minus where two of
// them meet (least common ancestors of consecutive leaves), and the counts are the sums of
// delta over subtrees.
inline void cholesky_column_counts(const std::vector<int>& tree, const std::vector<int>& Bp,
                                   const std::vector<int>& Bi, std::vector<int>& count)
{
  const int n = static_cast<int>(tree.size());
  std::vector<int> first(n, -1), max_first(n, -1), previous_leaf(n, -1), ancestor(n);
  count.assign(n, 0);
  // first[j]: the first descendant of j in postorder; a leaf of the tree starts a path.
  for (int k = 0; k < n; ++k) {
    count[k] = first[k] == -1 ? 1 : 0;
    for (int j = k; j != -1 && first[j] == -1; j = tree[j])
      first[j] = k;
  }
  for (int i = 0; i < n; ++i)
    ancestor[i] = i;
  for (int j = 0; j < n; ++j) {
    if (tree[j] != -1)
      --count[tree[j]];
    for (int q = Bp[j]; q < Bp[j + 1]; ++q) {
      const int i = Bi[q];
      // Is j a leaf of the subtree of row i (no earlier column of row i below j)?
      if (i <= j || first[j] <= max_first[i])
        continue;
      max_first[i] = first[j];
      const int previous = previous_leaf[i];
      previous_leaf[i] = j;
      ++count[j];
      if (previous != -1) { // the paths from previous and j meet at their common ancestor
        int meet = previous;
        while (meet != ancestor[meet])
          meet = ancestor[meet];
        for (int v = previous; v != meet;) {
          const int up = ancestor[v];
          ancestor[v] = meet;
          v = up;
        }
        --count[meet];
      }
    }
    if (tree[j] != -1)
      ancestor[j] = tree[j];
  }
  for (int j = 0; j < n; ++j) // children precede their parent in postorder
    if (tree[j] != -1)
      count[tree[j]] += count[j];
}

// Multifrontal supernodal L D L^T factorisation of a sparse symmetric matrix, without
// pivoting, that tells positive definite, positive semidefinite and indefinite matrices apart
// while it factorises. A pivot below -tolerance times its diagonal entry proves negative
// curvature. A pivot within +-tolerance is a zero pivot of a semidefinite matrix: its column
// of L is set to zero, and its entries in the Schur complement must vanish too (a 2x2 minor
// [0 b; b c] with b != 0 is indefinite). Solves act as a pseudo-inverse on the zero pivots.
//
// The symbolic analysis (elimination tree, postorder, relaxed supernodes, where every entry
// goes) depends on the sparsity pattern and the fill-reducing ordering only, so it is done
// once per pattern; every numeric factorisation then does its work in dense blocks (Eigen's
// matrix products), which is several times faster than a simplicial factorisation.
class Supernodal_LDLT
{
public:
  enum class Inertia { POSITIVE_DEFINITE, POSITIVE_SEMIDEFINITE, INDEFINITE };

  // outer/inner: the pattern of the whole symmetric n x n matrix in compressed columns (both
  // triangles; each pair {i, j} is read once, from the entry with i >= j).
  // ordering[k]: the variable eliminated at position k.
  void analyze(int n, const int* outer, const int* inner, const std::vector<int>& ordering)
  {
    n_ = n;
    has_single_precision_factor_ = false;
    std::vector<int> position(n);
    for (int k = 0; k < n; ++k)
      position[ordering[k]] = k;

    // The lower triangle in the given ordering, by rows: row_columns of row i are the
    // columns j < i with an entry (i, j).
    std::vector<int> row_start, row_columns;
    bucket_sort(
        n,
        [&](auto&& emit) {
          for (int j = 0; j < n; ++j)
            for (int p = outer[j]; p < outer[j + 1]; ++p)
              if (inner[p] > j) {
                const int a = position[inner[p]], b = position[j];
                emit(std::max(a, b), std::min(a, b));
              }
        },
        row_start, row_columns);

    // Elimination tree (Liu's algorithm with path compression).
    std::vector<int> parent(n, -1), ancestor(n, -1);
    for (int k = 0; k < n; ++k)
      for (int p = row_start[k]; p < row_start[k + 1]; ++p)
        for (int i = row_columns[p]; i != -1 && i < k;) {
          const int next = ancestor[i];
          ancestor[i] = k;
          if (next == -1)
            parent[i] = k;
          i = next;
        }

    // Postorder, so that every subtree is a contiguous range of columns; it keeps the fill.
    std::vector<int> post;
    postorder(parent, post);
    std::vector<int> inverse_post(n);
    for (int k = 0; k < n; ++k)
      inverse_post[post[k]] = k;
    std::vector<int> tree(n, -1);
    for (int k = 0; k < n; ++k)
      if (parent[post[k]] != -1)
        tree[k] = inverse_post[parent[post[k]]];
    permutation_.resize(n);
    for (int k = 0; k < n; ++k)
      permutation_[k] = ordering[post[k]];
    for (int k = 0; k < n; ++k)
      position[permutation_[k]] = k;

    // The lower triangle in the final order, by columns; Bsource is the position of the entry
    // in the input arrays.
    std::vector<int> Bp;
    std::vector<std::pair<int, int>> row_and_source;
    bucket_sort(
        n,
        [&](auto&& emit) {
          for (int j = 0; j < n; ++j)
            for (int p = outer[j]; p < outer[j + 1]; ++p)
              if (inner[p] >= j) {
                const int a = position[inner[p]], b = position[j];
                emit(std::min(a, b), std::pair<int, int>(std::max(a, b), p));
              }
        },
        Bp, row_and_source);
    std::vector<int> Bi(row_and_source.size()), Bsource(row_and_source.size());
    for (std::size_t q = 0; q < row_and_source.size(); ++q) {
      Bi[q] = row_and_source[q].first;
      Bsource[q] = row_and_source[q].second;
    }

    std::vector<int> column_count, flag(n, -1), children(n, 0);
    for (int k = 0; k < n; ++k)
      if (tree[k] != -1)
        ++children[tree[k]];
    cholesky_column_counts(tree, Bp, Bi, column_count);

    find_supernodes(tree, column_count, children);
    const int supernodes = number_of_supernodes();

    // Rows below each supernode: those of its columns in A and those of its children.
    std::vector<int> child_start, child_list;
    bucket_sort(
        supernodes,
        [&](auto&& emit) {
          for (int s = 0; s < supernodes; ++s)
            if (super_parent_[s] != -1)
              emit(super_parent_[s], s);
        },
        child_start, child_list);
    struct_start_.assign(supernodes + 1, 0);
    struct_rows_.clear();
    max_below_ = 0;
    std::fill(flag.begin(), flag.end(), -1);
    for (int s = 0; s < supernodes; ++s) {
      const int last = super_first_[s + 1] - 1;
      const std::size_t begin = struct_rows_.size();
      for (int j = super_first_[s]; j <= last; ++j)
        for (int q = Bp[j]; q < Bp[j + 1]; ++q)
          if (Bi[q] > last && flag[Bi[q]] != s) {
            flag[Bi[q]] = s;
            struct_rows_.push_back(Bi[q]);
          }
      for (int c = child_start[s]; c < child_start[s + 1]; ++c)
        for (int t = struct_start_[child_list[c]]; t < struct_start_[child_list[c] + 1]; ++t) {
          const int i = struct_rows_[t];
          if (i > last && flag[i] != s) {
            flag[i] = s;
            struct_rows_.push_back(i);
          }
        }
      std::sort(struct_rows_.begin() + static_cast<std::ptrdiff_t>(begin), struct_rows_.end());
      struct_start_[s + 1] = static_cast<int>(struct_rows_.size());
      max_below_ = std::max(max_below_, struct_start_[s + 1] - struct_start_[s]);
    }

    // Where the entries of A and the rows of the children's update matrices go in the
    // frontal matrices (column-major, r x r for r rows), and where the panels of L are.
    std::vector<int>& local = flag;
    assembly_start_.assign(supernodes + 1, 0);
    assembly_position_.resize(Bi.size());
    assembly_source_.resize(Bi.size());
    relative_.assign(struct_rows_.size(), 0);
    panel_start_.assign(supernodes + 1, 0);
    diagonal_source_.assign(n, -1);
    factorization_flops_ = 0.;
    std::size_t entry = 0;
    for (int s = 0; s < supernodes; ++s) {
      const int first = super_first_[s], k = super_first_[s + 1] - first;
      const int r = k + struct_start_[s + 1] - struct_start_[s];
      for (int a = 0; a < k; ++a)
        local[first + a] = a;
      for (int t = struct_start_[s]; t < struct_start_[s + 1]; ++t)
        local[struct_rows_[t]] = k + (t - struct_start_[s]);
      for (int j = first; j < first + k; ++j)
        for (int q = Bp[j]; q < Bp[j + 1]; ++q, ++entry) {
          assembly_position_[entry] =
              static_cast<std::size_t>(local[Bi[q]]) + static_cast<std::size_t>(j - first) * r;
          assembly_source_[entry] = Bsource[q];
          if (Bi[q] == j)
            diagonal_source_[j] = Bsource[q];
        }
      assembly_start_[s + 1] = static_cast<int>(entry);
      for (int c = child_start[s]; c < child_start[s + 1]; ++c)
        for (int t = struct_start_[child_list[c]]; t < struct_start_[child_list[c] + 1]; ++t)
          relative_[t] = local[struct_rows_[t]];
      panel_start_[s + 1] = panel_start_[s] + static_cast<std::size_t>(r) * k;
      factorization_flops_ += double(r) * k * k + double(r - k) * (r - k) * k;
    }
    L_.resize(panel_start_[supernodes]); // factorize() writes every panel before reading it
    // The update matrices wait on a stack (children before their parent, in postorder): its
    // largest extent, in entries.
    std::size_t top = 0;
    update_stack_size_ = 0;
    for (int s = 0; s < supernodes; ++s) {
      for (int c = child_start[s]; c < child_start[s + 1]; ++c) {
        const std::size_t below =
            std::size_t(struct_start_[child_list[c] + 1] - struct_start_[child_list[c]]);
        top -= below * below;
      }
      const std::size_t below = std::size_t(struct_start_[s + 1] - struct_start_[s]);
      top += below * below;
      update_stack_size_ = std::max(update_stack_size_, top);
    }
    solve_flops_ = 4. * double(panel_start_[supernodes]) + 4. * n;
  }

  // values: aligned with the inner array given to analyze().
  Inertia factorize(const double* values, double pivot_tolerance)
  {
    const int n = n_;
    const int supernodes = number_of_supernodes();
    has_single_precision_factor_ = false;
    D_.assign(n, 0.);
    is_zero_pivot_.assign(n, 0);
    zero_pivots_ = 0;
    negative_pivot_ = -1;
    // The scale a pivot is compared with: its diagonal entry, or the largest one.
    std::vector<double> scale(n, 0.);
    double max_diagonal = 0.;
    for (int j = 0; j < n; ++j)
      if (diagonal_source_[j] >= 0)
        max_diagonal = std::max(max_diagonal, values[diagonal_source_[j]]);
    for (int j = 0; j < n; ++j) {
      const double d = diagonal_source_[j] >= 0 ? values[diagonal_source_[j]] : 0.;
      scale[j] = d > 0. ? d : (max_diagonal > 0. ? max_diagonal : 1.);
    }

    // The update matrices of the supernodes waiting for their parent, one after the other on
    // a stack kept from one factorisation to the next (in postorder the children of a
    // supernode are on top of it when it is processed); the one being formed in update_work_.
    // Fresh matrices for each supernode cost the first factorisation of a 10^5-variable
    // fairing program a third of its time in page faults (2.11 -> 1.62 s, later ones 1.50 s).
    update_stack_.resize(update_stack_size_);
    update_work_.resize(std::size_t(max_below_) * std::size_t(max_below_));
    std::vector<std::size_t> update_start;
    std::vector<int> updating_supernode;
    Eigen::MatrixXd W;
    Eigen::VectorXd weights;
    for (int s = 0; s < supernodes; ++s) {
      const int first = super_first_[s], k = super_first_[s + 1] - first;
      const int below = struct_start_[s + 1] - struct_start_[s], r = k + below;
      // The frontal matrix in two parts that need no copying afterwards: its first k columns
      // F (r x k) are factorised in place, in L, and its lower right block T (below x below)
      // becomes the update matrix. Entries of A lie in the first k columns only.
      Eigen::Map<Eigen::MatrixXd> F(L_.data() + panel_start_[s], r, k);
      F.setZero();
      Eigen::Map<Eigen::MatrixXd> T(update_work_.data(), below, below);
      T.triangularView<Eigen::Lower>().setZero();
      double* f = F.data();
      double* t = T.data();
      for (int q = assembly_start_[s]; q < assembly_start_[s + 1]; ++q)
        f[assembly_position_[q]] += values[assembly_source_[q]];
      while (!updating_supernode.empty() && super_parent_[updating_supernode.back()] == s) {
        const int child = updating_supernode.back();
        const double* U = update_stack_.data() + update_start.back();
        const int* rel = relative_.data() + struct_start_[child];
        const int size = struct_start_[child + 1] - struct_start_[child];
        for (int b = 0; b < size; ++b) {
          const double* u = U + static_cast<std::ptrdiff_t>(b) * size;
          if (rel[b] < k) {
            double* column = f + static_cast<std::ptrdiff_t>(rel[b]) * r;
            for (int a = b; a < size; ++a)
              column[rel[a]] += u[a];
          } else { // rel is increasing: the rows a >= b of a column of T lie in T too
            double* column = t + static_cast<std::ptrdiff_t>(rel[b] - k) * below;
            for (int a = b; a < size; ++a)
              column[rel[a] - k] += u[a];
          }
        }
        update_start.pop_back();
        updating_supernode.pop_back();
      }

      // Left-looking L D L^T of the panel F(:, 0:k), with the pivots checked, by blocks of
      // columns so that most of the work is a matrix product.
      const int block_width = 32;
      for (int j0 = 0; j0 < k; j0 += block_width) {
        const int width = std::min(block_width, k - j0);
        if (j0 > 0) {
          W.noalias() = F.block(j0, 0, width, j0) *
                        Eigen::Map<const Eigen::VectorXd>(D_.data() + first, j0).asDiagonal();
          F.block(j0, j0, r - j0, width).noalias() -= F.block(j0, 0, r - j0, j0) * W.transpose();
        }
        for (int j = j0; j < j0 + width; ++j) {
          if (j > j0) {
            weights = F.block(j, j0, 1, j - j0)
                          .transpose()
                          .cwiseProduct(
                              Eigen::Map<const Eigen::VectorXd>(D_.data() + first + j0, j - j0));
            F.block(j, j, r - j, 1).noalias() -= F.block(j, j0, r - j, j - j0) * weights;
          }
          const int column = first + j;
          const double d = F(j, j);
          if (d < -pivot_tolerance * scale[column]) {
            negative_pivot_ = permutation_[column];
            return Inertia::INDEFINITE;
          }
          if (d <= pivot_tolerance * scale[column]) {
            for (int a = j + 1; a < r; ++a) {
              const int row = a < k ? first + a : struct_rows_[struct_start_[s] + a - k];
              if (F(a, j) * F(a, j) > pivot_tolerance * scale[column] * scale[row]) {
                negative_pivot_ = permutation_[column];
                return Inertia::INDEFINITE;
              }
            }
            F.block(j, j, r - j, 1).setZero();
            is_zero_pivot_[column] = 1;
            ++zero_pivots_;
          } else {
            D_[column] = d;
            F.block(j + 1, j, r - j - 1, 1) /= d;
          }
          F(j, j) = 1.;
        }
      }
      if (below > 0) {
        const auto L21 = F.block(k, 0, below, k);
        W.noalias() = L21 * Eigen::Map<const Eigen::VectorXd>(D_.data() + first, k).asDiagonal();
        T.triangularView<Eigen::Lower>() -= W * L21.transpose();
        // Onto the stack where the children's updates were (they are all read).
        const std::size_t start =
            update_start.empty() ? 0
                                 : update_start.back() + update_entries(updating_supernode.back());
        CGAL_assertion(start + update_entries(s) <= update_stack_size_);
        double* to = update_stack_.data() + start;
        for (int b = 0; b < below; ++b)
          std::copy(T.data() + std::ptrdiff_t(b) * below + b,
                    T.data() + std::ptrdiff_t(b + 1) * below, to + std::ptrdiff_t(b) * below + b);
        update_start.push_back(start);
        updating_supernode.push_back(s);
      }
    }
    return zero_pivots_ == 0 ? Inertia::POSITIVE_DEFINITE : Inertia::POSITIVE_SEMIDEFINITE;
  }

  // b <- (L D L^T)^+ b, in the original numbering.
  void solve(Eigen::VectorXd& b) const
  {
    permute_in(b, work_);
    forward_substitute(L_.data(), work_);
    divide_by_pivots(work_);
    backward_substitute(L_.data(), work_);
    permute_out(work_, b);
  }

  // b <- (L D L^T)^+ b as solve() does, with the substitutions in single precision (relative
  // error ~1e-7): for a preconditioner, whose exactness does not matter. The substitutions
  // stream the factor from memory, and a copy in floats halves what they read (made at the
  // first such solve after a factorisation). The vectors are scaled to a largest entry of 1
  // before each substitution, so that any scale of the problem stays within float's range.
  void solve_in_single_precision(Eigen::VectorXd& b) const
  {
    if (!has_single_precision_factor_) {
      const std::size_t size = number_of_factor_entries();
      single_L_.resize(size);
      const double* from = L_.data();
      float* to = single_L_.data();
      for (std::size_t i = 0; i < size; ++i)
        to[i] = static_cast<float>(from[i]);
      has_single_precision_factor_ = true;
    }
    const double b_scale = b.cwiseAbs().maxCoeff();
    if (!(b_scale > 0.) || !std::isfinite(b_scale))
      return solve(b); // zero (nothing to scale) or not finite (let it propagate)
    single_work_.resize(n_);
    for (int k = 0; k < n_; ++k)
      single_work_[k] = static_cast<float>(b[permutation_[k]] / b_scale);
    forward_substitute(single_L_.data(), single_work_);
    work_.resize(n_);
    for (int j = 0; j < n_; ++j)
      work_[j] = is_zero_pivot_[j] ? 0. : double(single_work_[j]) / D_[j];
    double y_scale = work_.cwiseAbs().maxCoeff();
    if (!(y_scale > 0.) || !std::isfinite(y_scale))
      y_scale = 1.;
    for (int j = 0; j < n_; ++j)
      single_work_[j] = static_cast<float>(work_[j] / y_scale);
    backward_substitute(single_L_.data(), single_work_);
    for (int k = 0; k < n_; ++k)
      b[permutation_[k]] = double(single_work_[k]) * y_scale * b_scale;
  }

  using Right_hand_sides = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

  // B <- (L D L^T)^+ B for several right-hand sides at once (the columns of B), in the
  // original numbering: the substitutions then run as matrix products.
  void solve(Right_hand_sides& B) const
  {
    Right_hand_sides Y(n_, B.cols());
    for (int k = 0; k < n_; ++k)
      Y.row(k) = B.row(permutation_[k]);
    forward_substitute(L_.data(), Y);
    divide_by_pivots(Y);
    backward_substitute(L_.data(), Y);
    for (int k = 0; k < n_; ++k)
      B.row(permutation_[k]) = Y.row(k);
  }

  // x <- (L D L^T)^+ b, and null_direction <- L^-T P0 L^-1 b, where P0 keeps the entries of
  // the zero pivots: a vector of the null space along which b^T null_direction =
  // |P0 L^-1 b|^2, zero exactly when b is orthogonal to the null space.
  void solve_with_null_space_part(const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                  Eigen::VectorXd& null_direction) const
  {
    permute_in(b, work_);
    forward_substitute(L_.data(), work_);
    null_work_.setZero(n_);
    for (int j = 0; j < n_; ++j)
      if (is_zero_pivot_[j])
        null_work_[j] = work_[j];
    divide_by_pivots(work_);
    backward_substitute(L_.data(), work_);
    backward_substitute(L_.data(), null_work_);
    x.resize(n_);
    null_direction.resize(n_);
    permute_out(work_, x);
    permute_out(null_work_, null_direction);
  }

  int number_of_zero_pivots() const { return zero_pivots_; }
  // The variable at which negative curvature was found, or -1.
  int negative_pivot() const { return negative_pivot_; }
  double factorization_flops() const { return factorization_flops_; }
  // The entries of L stored (the panels of the supernodes, explicit zeros included).
  std::size_t number_of_factor_entries() const
  {
    return panel_start_.empty() ? 0 : panel_start_.back();
  }
  double solve_flops() const { return solve_flops_; }

private:
  int number_of_supernodes() const { return static_cast<int>(super_first_.size()) - 1; }
  // The entries of supernode s's update matrix.
  std::size_t update_entries(int s) const
  {
    const std::size_t below = std::size_t(struct_start_[s + 1] - struct_start_[s]);
    return below * below;
  }

  static void postorder(const std::vector<int>& parent, std::vector<int>& post)
  {
    const int n = static_cast<int>(parent.size());
    std::vector<int> first_child(n, -1), next_sibling(n, -1), stack;
    for (int j = n - 1; j >= 0; --j)
      if (parent[j] != -1) {
        next_sibling[j] = first_child[parent[j]];
        first_child[parent[j]] = j;
      }
    post.clear();
    post.reserve(n);
    for (int root = 0; root < n; ++root) {
      if (parent[root] != -1)
        continue;
      stack.push_back(root);
      while (!stack.empty()) {
        const int j = stack.back();
        if (first_child[j] != -1) {
          stack.push_back(first_child[j]);
          first_child[j] = next_sibling[first_child[j]];
        } else {
          stack.pop_back();
          post.push_back(j);
        }
      }
    }
  }

  // Fundamental supernodes (chains of columns with nested structures), then relaxed
  // amalgamation with the child that precedes a supernode when few explicit zeros are added
  // (the thresholds of CHOLMOD): bigger dense blocks run much faster.
  void find_supernodes(const std::vector<int>& tree, const std::vector<int>& column_count,
                       const std::vector<int>& children)
  {
    const int n = n_;
    std::vector<int> fundamental;
    for (int j = 0; j < n; ++j)
      if (j == 0 ||
          !(tree[j - 1] == j && column_count[j - 1] == column_count[j] + 1 && children[j] == 1))
        fundamental.push_back(j);
    fundamental.push_back(n);
    super_first_.clear();
    std::vector<long long> true_nonzeros;
    for (std::size_t f = 0; f + 1 < fundamental.size(); ++f) {
      int first = fundamental[f];
      const int last = fundamental[f + 1] - 1;
      long long nonzeros = 0;
      for (int j = first; j <= last; ++j)
        nonzeros += column_count[j];
      const long long rows_below = column_count[last] - 1;
      while (!super_first_.empty() && tree[first - 1] == first) {
        const long long columns = last - super_first_.back() + 1;
        const long long rows = columns + rows_below;
        const long long dense = columns * rows - columns * (columns - 1) / 2;
        const long long merged_nonzeros = nonzeros + true_nonzeros.back();
        const double zeros = double(dense - merged_nonzeros) / double(dense);
        if (!(columns <= 4 || (columns <= 16 && zeros < 0.8) || (columns <= 48 && zeros < 0.1) ||
              zeros < 0.05))
          break;
        nonzeros = merged_nonzeros;
        first = super_first_.back();
        super_first_.pop_back();
        true_nonzeros.pop_back();
      }
      super_first_.push_back(first);
      true_nonzeros.push_back(nonzeros);
    }
    const int supernodes = static_cast<int>(super_first_.size());
    super_first_.push_back(n);
    std::vector<int> column_to_super(n);
    for (int s = 0; s < supernodes; ++s)
      for (int j = super_first_[s]; j < super_first_[s + 1]; ++j)
        column_to_super[j] = s;
    super_parent_.assign(supernodes, -1);
    for (int s = 0; s < supernodes; ++s) {
      const int up = tree[super_first_[s + 1] - 1];
      if (up != -1)
        super_parent_[s] = column_to_super[up];
    }
  }

  void permute_in(const Eigen::VectorXd& b, Eigen::VectorXd& y) const
  {
    y.resize(n_);
    for (int k = 0; k < n_; ++k)
      y[k] = b[permutation_[k]];
  }

  void permute_out(const Eigen::VectorXd& y, Eigen::VectorXd& b) const
  {
    for (int k = 0; k < n_; ++k)
      b[permutation_[k]] = y[k];
  }

  // Y: a vector, or a row-major matrix whose columns are right-hand sides (so that the rows
  // gathered and scattered below are contiguous); `factor`: the panels of L, in the scalar
  // type of Y.
  template <class Rows>
  void forward_substitute(const typename Rows::Scalar* factor, Rows& Y) const
  {
    typedef Eigen::Matrix<typename Rows::Scalar, Eigen::Dynamic, Eigen::Dynamic> Panel;
    const int supernodes = number_of_supernodes();
    Rows buffer(max_below_, Y.cols()); // allocated once: most supernodes are small
    for (int s = 0; s < supernodes; ++s) {
      const int first = super_first_[s], k = super_first_[s + 1] - first;
      const int below = struct_start_[s + 1] - struct_start_[s];
      Eigen::Map<const Panel> panel(factor + panel_start_[s], k + below, k);
      auto X = Y.middleRows(first, k);
      panel.topRows(k).template triangularView<Eigen::UnitLower>().solveInPlace(X);
      if (below > 0) {
        auto t = buffer.topRows(below);
        t.noalias() = panel.bottomRows(below) * X;
        const int* rows = struct_rows_.data() + struct_start_[s];
        for (int a = 0; a < below; ++a)
          Y.row(rows[a]) -= t.row(a);
      }
    }
  }

  template <class Rows>
  void divide_by_pivots(Rows& Y) const
  {
    for (int j = 0; j < n_; ++j) {
      if (is_zero_pivot_[j])
        Y.row(j).setZero();
      else
        Y.row(j) /= D_[j];
    }
  }

  template <class Rows>
  void backward_substitute(const typename Rows::Scalar* factor, Rows& Y) const
  {
    typedef Eigen::Matrix<typename Rows::Scalar, Eigen::Dynamic, Eigen::Dynamic> Panel;
    Rows buffer(max_below_, Y.cols());
    for (int s = number_of_supernodes() - 1; s >= 0; --s) {
      const int first = super_first_[s], k = super_first_[s + 1] - first;
      const int below = struct_start_[s + 1] - struct_start_[s];
      Eigen::Map<const Panel> panel(factor + panel_start_[s], k + below, k);
      auto X = Y.middleRows(first, k);
      if (below > 0) {
        auto t = buffer.topRows(below);
        const int* rows = struct_rows_.data() + struct_start_[s];
        for (int a = 0; a < below; ++a)
          t.row(a) = Y.row(rows[a]);
        X.noalias() -= panel.bottomRows(below).transpose() * t;
      }
      panel.topRows(k).transpose().template triangularView<Eigen::UnitUpper>().solveInPlace(X);
    }
  }

  int n_ = 0;
  std::vector<int> permutation_; // the variable at each position of the factorisation
  std::vector<int> super_first_, super_parent_, struct_start_, struct_rows_, relative_;
  int max_below_ = 0; // the most rows below a supernode
  std::vector<int> assembly_start_, assembly_source_, diagonal_source_;
  std::vector<std::size_t> assembly_position_, panel_start_;
  Uninitialized_array<double> L_;
  std::size_t update_stack_size_ = 0;
  Uninitialized_array<double> update_stack_, update_work_; // see factorize()
  std::vector<double> D_;
  std::vector<char> is_zero_pivot_;
  int zero_pivots_ = 0, negative_pivot_ = -1;
  double factorization_flops_ = 0., solve_flops_ = 0.;
  mutable Eigen::VectorXd work_, null_work_;
  // A copy of L_ in single precision, for solve_in_single_precision().
  mutable Uninitialized_array<float> single_L_;
  mutable bool has_single_precision_factor_ = false;
  mutable Eigen::VectorXf single_work_;
};

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_QP_SUPERNODAL_LDLT_H

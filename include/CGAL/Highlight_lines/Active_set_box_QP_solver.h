// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_ACTIVE_SET_BOX_QP_SOLVER_H
#define CGAL_HIGHLIGHT_LINES_ACTIVE_SET_BOX_QP_SOLVER_H

#include <CGAL/Highlight_lines/Box_QP_report.h>
#include <CGAL/Highlight_lines/internal/uninitialized_array.h>

#include <Eigen/Dense>
#include <Eigen/OrderingMethods>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// The data of a bound-constrained QP  min 1/2 x^T Q x + c^T x + r,  l <= x <= u,  gathered
// through the setters of the BoxConstrainedQuadraticProgramSolver concept, with the input
// checks and the evaluation of a point (KKT residual, objective) that every model reports in
// the same way.
class Box_QP_problem
{
public:
  using Sparse_matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
  using Triplet = Eigen::Triplet<double, int>;

  void resize(std::size_t n)
  {
    n_ = n;
    upper_triplets_.clear();
    // A small problem sums P in place (a real dent's fairing, 100-300 variables, makes 3 to 7
    // set_P() calls per entry); a large one collects triplets (n² sums would not fit).
    dense_ = n <= dense_size_limit;
    dense_values_.assign(dense_ ? n * (n + 1) / 2 : 0, 0.);
    dense_present_.assign(dense_values_.size(), 0);
    c_.setZero(static_cast<Eigen::Index>(n));
    r_ = 0.;
    l_.setConstant(static_cast<Eigen::Index>(n), -std::numeric_limits<double>::infinity());
    u_.setConstant(static_cast<Eigen::Index>(n), std::numeric_limits<double>::infinity());
    setter_error_.clear();
    Q_.resize(0, 0);
  }

  std::size_t size() const { return n_; }

  // Only the upper triangle is read, so that a loop over all ordered pairs of a symmetric
  // matrix gives every entry once.
  void add_P(std::size_t i, std::size_t j, double value)
  {
    if (i > j)
      return;
    if (j >= n_) {
      note_setter_error("set_P", i, j);
      return;
    }
    if (dense_) {
      const std::size_t at = j * (j + 1) / 2 + i;
      dense_values_[at] += value;
      dense_present_[at] = 1;
    } else {
      upper_triplets_.emplace_back(static_cast<int>(i), static_cast<int>(j), value);
    }
  }

  void add_P(const Sparse_matrix& P)
  {
    if (static_cast<std::size_t>(P.rows()) != n_ || static_cast<std::size_t>(P.cols()) != n_) {
      if (setter_error_.empty()) {
        std::ostringstream os;
        os << "set_P: the matrix is " << P.rows() << " x " << P.cols() << " but the problem has "
           << n_ << " variables";
        setter_error_ = os.str();
      }
      return;
    }
    if (!dense_)
      upper_triplets_.reserve(upper_triplets_.size() + static_cast<std::size_t>(P.nonZeros()));
    for (int col = 0; col < P.outerSize(); ++col)
      for (Sparse_matrix::InnerIterator it(P, col); it; ++it)
        add_P(static_cast<std::size_t>(it.row()), static_cast<std::size_t>(col), it.value());
  }

  void add_q(std::size_t i, double value)
  {
    if (i >= n_)
      note_setter_error("set_q", i);
    else
      c_[static_cast<Eigen::Index>(i)] += value;
  }

  void add_r(double value) { r_ += value; }

  void set_l(std::size_t i, double value)
  {
    if (i >= n_)
      note_setter_error("set_l", i);
    else
      l_[static_cast<Eigen::Index>(i)] = value;
  }

  void set_u(std::size_t i, double value)
  {
    if (i >= n_)
      note_setter_error("set_u", i);
    else
      u_[static_cast<Eigen::Index>(i)] = value;
  }

  // Checks the data in the order a user would fix it: indices, then values, then bounds.
  Box_QP_status validate(std::string& message) const
  {
    std::ostringstream os;
    if (!setter_error_.empty()) {
      message = setter_error_;
      return Box_QP_status::INVALID_INPUT;
    }
    for (const Triplet& t : upper_triplets_)
      if (!std::isfinite(t.value())) {
        os << "P(" << t.row() << ", " << t.col() << ") is " << t.value();
        message = os.str();
        return Box_QP_status::INVALID_INPUT;
      }
    for (std::size_t j = 0, at = 0; j < (dense_ ? n_ : 0); ++j)
      for (std::size_t i = 0; i <= j; ++i, ++at)
        if (!std::isfinite(dense_values_[at])) { // a sum is finite if its terms are
          os << "P(" << i << ", " << j << ") is " << dense_values_[at];
          message = os.str();
          return Box_QP_status::INVALID_INPUT;
        }
    if (!std::isfinite(r_)) {
      os << "r is " << r_;
      message = os.str();
      return Box_QP_status::INVALID_INPUT;
    }
    for (Eigen::Index i = 0; i < c_.size(); ++i) {
      if (!std::isfinite(c_[i])) {
        os << "q(" << i << ") is " << c_[i];
        message = os.str();
        return Box_QP_status::INVALID_INPUT;
      }
      if (std::isnan(l_[i]) || l_[i] == std::numeric_limits<double>::infinity()) {
        os << "variable " << i << ": the lower bound is " << l_[i]
           << " (allowed: a finite value or -infinity)";
        message = os.str();
        return Box_QP_status::INVALID_INPUT;
      }
      if (std::isnan(u_[i]) || u_[i] == -std::numeric_limits<double>::infinity()) {
        os << "variable " << i << ": the upper bound is " << u_[i]
           << " (allowed: a finite value or +infinity)";
        message = os.str();
        return Box_QP_status::INVALID_INPUT;
      }
    }
    for (Eigen::Index i = 0; i < c_.size(); ++i)
      if (l_[i] > u_[i]) {
        os << "variable " << i << ": the lower bound " << l_[i] << " exceeds the upper bound "
           << u_[i];
        message = os.str();
        return Box_QP_status::INFEASIBLE_BOUNDS;
      }
    return Box_QP_status::OPTIMAL;
  }

  // Builds the full symmetric matrix (both triangles, duplicates summed, every diagonal
  // entry present even if zero: solvers replace the rows of active variables by their
  // diagonal) and the norms the tolerances are relative to. Requires validate() to have
  // succeeded. The upper triangle is gathered by columns with a counting sort and summed
  // with a marker array; two transpositions then give the lower and the upper part of every
  // column of Q in increasing rows. Linear in the number of set_P() calls, which outnumber
  // the entries several times in an assembly of local stencils.
  void assemble()
  {
    const int n = static_cast<int>(n_);
    // The upper triangle with duplicates summed, by columns, rows in no particular order;
    // the diagonal entry first.
    // The work arrays are members: at 10^5 variables they hold millions of entries, and
    // allocating them afresh for each program of a fairing faults their pages in each time.
    std::vector<int>& upper_rows = upper_rows_;
    std::vector<double>& upper_values = upper_values_;
    std::vector<int> upper_start(n_ + 1, 0);
    upper_rows.clear();
    upper_values.clear();
    if (dense_)
      gather_dense_upper(upper_start, upper_rows, upper_values);
    else
      gather_triplet_upper(upper_start, upper_rows, upper_values);
    // Column j of Q: the rows i < j (its strictly upper part), then the rows k >= j (the
    // entries (j, k) of the upper triangle).
    std::vector<int> upper_count(n_, 0), lower_count(n_, 0);
    for (int j = 0; j < n; ++j) {
      upper_count[j] = upper_start[j + 1] - upper_start[j] - 1;
      for (int p = upper_start[j]; p < upper_start[j + 1]; ++p)
        ++lower_count[upper_rows[p]];
    }
    Q_.resize(n, n);
    Q_.resizeNonZeros(static_cast<Eigen::Index>(2 * upper_rows.size() - n_));
    int* outer = Q_.outerIndexPtr();
    int* inner = Q_.innerIndexPtr();
    double* values = Q_.valuePtr();
    outer[0] = 0;
    for (int j = 0; j < n; ++j)
      outer[j + 1] = outer[j] + upper_count[j] + lower_count[j];
    // Lower parts: visiting the columns k in increasing order appends the rows k of every
    // column j <= k in increasing order.
    std::vector<int> next(n_);
    for (int j = 0; j < n; ++j)
      next[j] = outer[j] + upper_count[j];
    for (int k = 0; k < n; ++k)
      for (int p = upper_start[k]; p < upper_start[k + 1]; ++p) {
        const int j = upper_rows[p];
        inner[next[j]] = k;
        values[next[j]++] = upper_values[p];
      }
    // Upper parts: the mirror of the lower parts, visited by increasing column.
    for (int j = 0; j < n; ++j)
      next[j] = outer[j];
    for (int j = 0; j < n; ++j)
      for (int p = outer[j] + upper_count[j] + 1; p < outer[j + 1]; ++p) { // below the diagonal
        const int k = inner[p];
        inner[next[k]] = j;
        values[next[k]++] = values[p];
      }
    diagonal_ = Q_.diagonal();
    Eigen::VectorXd row_sums = Eigen::VectorXd::Zero(n);
    for (int col = 0; col < n; ++col)
      for (Sparse_matrix::InnerIterator it(Q_, col); it; ++it)
        row_sums[it.row()] += std::abs(it.value());
    Q_norm_ = n > 0 ? row_sums.maxCoeff() : 0.;
    c_norm_ = n > 0 ? c_.cwiseAbs().maxCoeff() : 0.;
  }

  const Sparse_matrix& Q() const { return Q_; }
  const Eigen::VectorXd& c() const { return c_; }
  const Eigen::VectorXd& l() const { return l_; }
  const Eigen::VectorXd& u() const { return u_; }
  const Eigen::VectorXd& diagonal() const { return diagonal_; }
  double r() const { return r_; }
  double Q_norm() const { return Q_norm_; }
  double c_norm() const { return c_norm_; }

  // The size of the terms a gradient at x is made of; KKT residuals are relative to it.
  double gradient_scale(double x_norm) const
  {
    const double scale = c_norm_ + Q_norm_ * x_norm;
    return scale > 0. ? scale : 1.;
  }

  // A change of x below this size (relative tolerance 1) changes the gradient by less than
  // the gradient scale: it is the unit in which closeness to a bound is judged.
  double x_scale(double x_norm) const { return x_norm + (Q_norm_ > 0. ? c_norm_ / Q_norm_ : 0.); }

  double objective(const Eigen::VectorXd& x, const Eigen::VectorXd& Qx) const
  {
    return 0.5 * x.dot(Qx) + c_.dot(x) + r_;
  }

  Eigen::VectorXd clamp(const Eigen::VectorXd& x) const { return x.cwiseMax(l_).cwiseMin(u_); }

  // Projected gradient (see Box_QP_report) of a point within the bounds.
  double kkt_residual(const Eigen::VectorXd& x, const Eigen::VectorXd& gradient) const
  {
    double residual = 0.;
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      double projected = gradient[i];
      if (l_[i] == u_[i])
        projected = 0.;
      else if (x[i] <= l_[i])
        projected = std::min(projected, 0.);
      else if (x[i] >= u_[i])
        projected = std::max(projected, 0.);
      residual = std::max(residual, std::abs(projected));
    }
    return residual;
  }

  // Fills everything of the report but the status, iterations, factorisations and message.
  void evaluate(const Eigen::VectorXd& x, Box_QP_report& report) const
  {
    const Eigen::VectorXd Qx = Q_ * x;
    const Eigen::VectorXd gradient = Qx + c_;
    report.kkt_residual = kkt_residual(x, gradient);
    report.relative_kkt_residual =
        report.kkt_residual / gradient_scale(x.size() > 0 ? x.cwiseAbs().maxCoeff() : 0.);
    report.objective_value = objective(x, Qx);
    report.active_bounds = 0;
    for (Eigen::Index i = 0; i < x.size(); ++i)
      if (x[i] == l_[i] || x[i] == u_[i])
        ++report.active_bounds;
  }

private:
  // The triplets' upper triangle by columns, each entry summed in the order of the set_P()
  // calls: a counting sort, then a marker array.
  void gather_triplet_upper(std::vector<int>& upper_start, std::vector<int>& upper_rows,
                            std::vector<double>& upper_values)
  {
    const int n = static_cast<int>(n_);
    std::vector<int> start(n_ + 1, 0);
    for (const Triplet& t : upper_triplets_)
      ++start[t.col() + 1];
    for (int j = 0; j < n; ++j)
      start[j + 1] += start[j];
    std::vector<std::pair<int, double>>& by_column = by_column_;
    by_column.resize(upper_triplets_.size());
    {
      std::vector<int> next(start.begin(), start.end() - 1);
      for (const Triplet& t : upper_triplets_)
        by_column[next[t.col()]++] = {t.row(), t.value()};
    }
    std::vector<int> slot(n_, -1);
    upper_rows.reserve(by_column.size() / 2 + n_);
    upper_values.reserve(upper_rows.capacity());
    for (int j = 0; j < n; ++j) {
      const int first = static_cast<int>(upper_rows.size());
      upper_rows.push_back(j);
      upper_values.push_back(0.);
      slot[j] = first;
      for (int p = start[j]; p < start[j + 1]; ++p) {
        const int i = by_column[p].first;
        if (slot[i] < first) {
          slot[i] = static_cast<int>(upper_rows.size());
          upper_rows.push_back(i);
          upper_values.push_back(0.);
        }
        upper_values[slot[i]] += by_column[p].second;
      }
      upper_start[j + 1] = static_cast<int>(upper_rows.size());
    }
  }

  // The same from the dense sums (the same values: each summed in the order of the calls).
  void gather_dense_upper(std::vector<int>& upper_start, std::vector<int>& upper_rows,
                          std::vector<double>& upper_values) const
  {
    for (std::size_t j = 0; j < n_; ++j) {
      const std::size_t column = j * (j + 1) / 2;
      upper_rows.push_back(static_cast<int>(j));
      upper_values.push_back(dense_values_[column + j]);
      for (std::size_t i = 0; i < j; ++i)
        if (dense_present_[column + i]) {
          upper_rows.push_back(static_cast<int>(i));
          upper_values.push_back(dense_values_[column + i]);
        }
      upper_start[j + 1] = static_cast<int>(upper_rows.size());
    }
  }

  void note_setter_error(const char* setter, std::size_t i, std::size_t j = 0)
  {
    if (!setter_error_.empty())
      return; // the first error is the one to fix first
    std::ostringstream os;
    os << setter << ": index " << (i >= n_ ? i : j) << " is out of range (the problem has " << n_
       << " variables)";
    setter_error_ = os.str();
  }

  std::size_t n_ = 0;
  static constexpr std::size_t dense_size_limit = 512; // 1 MiB of sums at most
  std::vector<Triplet> upper_triplets_;
  std::vector<std::pair<int, double>> by_column_; // work arrays of assemble()
  std::vector<int> upper_rows_;
  std::vector<double> upper_values_;
  bool dense_ = false;
  std::vector<double> dense_values_; // column j at j (j + 1) / 2, rows 0 to j
  std::vector<unsigned char> dense_present_;
  Eigen::VectorXd c_, l_, u_, diagonal_;
  double r_ = 0.;
  std::string setter_error_;
  Sparse_matrix Q_;
  double Q_norm_ = 0., c_norm_ = 0.;
};

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
    std::vector<int> position(n);
    for (int k = 0; k < n; ++k)
      position[ordering[k]] = k;

    // The lower triangle in the given ordering, by rows: row_columns of row i are the
    // columns j < i with an entry (i, j).
    std::vector<int> row_start(n + 1, 0);
    for (int j = 0; j < n; ++j)
      for (int p = outer[j]; p < outer[j + 1]; ++p)
        if (inner[p] > j)
          ++row_start[std::max(position[inner[p]], position[j]) + 1];
    for (int i = 0; i < n; ++i)
      row_start[i + 1] += row_start[i];
    std::vector<int> row_columns(static_cast<std::size_t>(row_start[n]));
    {
      std::vector<int> next(row_start.begin(), row_start.end() - 1);
      for (int j = 0; j < n; ++j)
        for (int p = outer[j]; p < outer[j + 1]; ++p)
          if (inner[p] > j) {
            const int a = position[inner[p]], b = position[j];
            row_columns[next[std::max(a, b)]++] = std::min(a, b);
          }
    }

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
    std::vector<int> Bp(n + 1, 0);
    for (int j = 0; j < n; ++j)
      for (int p = outer[j]; p < outer[j + 1]; ++p)
        if (inner[p] >= j)
          ++Bp[std::min(position[inner[p]], position[j]) + 1];
    for (int j = 0; j < n; ++j)
      Bp[j + 1] += Bp[j];
    std::vector<int> Bi(static_cast<std::size_t>(Bp[n])), Bsource(Bi.size());
    {
      std::vector<int> next(Bp.begin(), Bp.end() - 1);
      for (int j = 0; j < n; ++j)
        for (int p = outer[j]; p < outer[j + 1]; ++p)
          if (inner[p] >= j) {
            const int a = position[inner[p]], b = position[j];
            const int q = next[std::min(a, b)]++;
            Bi[q] = std::max(a, b);
            Bsource[q] = p;
          }
    }

    std::vector<int> column_count, flag(n, -1), children(n, 0);
    for (int k = 0; k < n; ++k)
      if (tree[k] != -1)
        ++children[tree[k]];
    cholesky_column_counts(tree, Bp, Bi, column_count);

    find_supernodes(tree, column_count, children);
    const int supernodes = number_of_supernodes();

    // Rows below each supernode: those of its columns in A and those of its children.
    std::vector<int> child_start(supernodes + 1, 0), child_list(supernodes);
    for (int s = 0; s < supernodes; ++s)
      if (super_parent_[s] != -1)
        ++child_start[super_parent_[s] + 1];
    for (int s = 0; s < supernodes; ++s)
      child_start[s + 1] += child_start[s];
    {
      std::vector<int> next(child_start.begin(), child_start.end() - 1);
      for (int s = 0; s < supernodes; ++s)
        if (super_parent_[s] != -1)
          child_list[next[super_parent_[s]]++] = s;
    }
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
    solve_flops_ = 4. * double(panel_start_[supernodes]) + 4. * n;
  }

  // values: aligned with the inner array given to analyze().
  Inertia factorize(const double* values, double pivot_tolerance)
  {
    const int n = n_;
    const int supernodes = number_of_supernodes();
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

    // Update matrices of the supernodes waiting for their parent; in postorder the children
    // of a supernode are on top of the stack when it is processed.
    std::vector<Eigen::MatrixXd> updates;
    std::vector<int> updating_supernode;
    Eigen::MatrixXd T, W;
    Eigen::VectorXd weights;
    for (int s = 0; s < supernodes; ++s) {
      const int first = super_first_[s], k = super_first_[s + 1] - first;
      const int below = struct_start_[s + 1] - struct_start_[s], r = k + below;
      // The frontal matrix in two parts that need no copying afterwards: its first k columns
      // F (r x k) are factorised in place, in L, and its lower right block T (below x below)
      // becomes the update matrix. Entries of A lie in the first k columns only.
      Eigen::Map<Eigen::MatrixXd> F(L_.data() + panel_start_[s], r, k);
      F.setZero();
      T.setZero(below, below);
      double* f = F.data();
      double* t = T.data();
      for (int q = assembly_start_[s]; q < assembly_start_[s + 1]; ++q)
        f[assembly_position_[q]] += values[assembly_source_[q]];
      while (!updating_supernode.empty() && super_parent_[updating_supernode.back()] == s) {
        const Eigen::MatrixXd& U = updates.back();
        const int* rel = relative_.data() + struct_start_[updating_supernode.back()];
        const int size = static_cast<int>(U.rows());
        for (int b = 0; b < size; ++b) {
          const double* u = U.data() + static_cast<std::ptrdiff_t>(b) * size;
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
        updates.pop_back();
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
        updates.push_back(std::move(T));
        updating_supernode.push_back(s);
      }
    }
    return zero_pivots_ == 0 ? Inertia::POSITIVE_DEFINITE : Inertia::POSITIVE_SEMIDEFINITE;
  }

  // b <- (L D L^T)^+ b, in the original numbering.
  void solve(Eigen::VectorXd& b) const
  {
    permute_in(b, work_);
    forward_substitute(work_);
    divide_by_pivots(work_);
    backward_substitute(work_);
    permute_out(work_, b);
  }

  using Right_hand_sides = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

  // B <- (L D L^T)^+ B for several right-hand sides at once (the columns of B), in the
  // original numbering: the substitutions then run as matrix products.
  void solve(Right_hand_sides& B) const
  {
    Right_hand_sides Y(n_, B.cols());
    for (int k = 0; k < n_; ++k)
      Y.row(k) = B.row(permutation_[k]);
    forward_substitute(Y);
    divide_by_pivots(Y);
    backward_substitute(Y);
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
    forward_substitute(work_);
    null_work_.setZero(n_);
    for (int j = 0; j < n_; ++j)
      if (is_zero_pivot_[j])
        null_work_[j] = work_[j];
    divide_by_pivots(work_);
    backward_substitute(work_);
    backward_substitute(null_work_);
    x.resize(n_);
    null_direction.resize(n_);
    permute_out(work_, x);
    permute_out(null_work_, null_direction);
  }

  int number_of_zero_pivots() const { return zero_pivots_; }
  // The variable at which negative curvature was found, or -1.
  int negative_pivot() const { return negative_pivot_; }
  double factorization_flops() const { return factorization_flops_; }
  double solve_flops() const { return solve_flops_; }

private:
  int number_of_supernodes() const { return static_cast<int>(super_first_.size()) - 1; }

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
  // gathered and scattered below are contiguous).
  template <class Rows>
  void forward_substitute(Rows& Y) const
  {
    const int supernodes = number_of_supernodes();
    Rows buffer(max_below_, Y.cols()); // allocated once: most supernodes are small
    for (int s = 0; s < supernodes; ++s) {
      const int first = super_first_[s], k = super_first_[s + 1] - first;
      const int below = struct_start_[s + 1] - struct_start_[s];
      Eigen::Map<const Eigen::MatrixXd> panel(L_.data() + panel_start_[s], k + below, k);
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
  void backward_substitute(Rows& Y) const
  {
    Rows buffer(max_below_, Y.cols());
    for (int s = number_of_supernodes() - 1; s >= 0; --s) {
      const int first = super_first_[s], k = super_first_[s + 1] - first;
      const int below = struct_start_[s + 1] - struct_start_[s];
      Eigen::Map<const Eigen::MatrixXd> panel(L_.data() + panel_start_[s], k + below, k);
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
  std::vector<double> D_;
  std::vector<char> is_zero_pivot_;
  int zero_pivots_ = 0, negative_pivot_ = -1;
  double factorization_flops_ = 0., solve_flops_ = 0.;
  mutable Eigen::VectorXd work_, null_work_;
};

} // namespace internal

/*!
\ingroup PkgHighlightLinesRef

The built-in solver of bound-constrained convex quadratic programs

\f[ \min_x \tfrac{1}{2} x^T P x + q^T x + r \quad \text{subject to} \quad l \le x \le u \f]

with a sparse symmetric positive (semi)definite \f$ P \f$, as they arise at every iteration
of the highlight-line fairing.

<b>Method.</b> A primal-dual active-set method (the semismooth Newton method of
Hintermüller, Ito and Kunisch for box constraints): each iteration fixes the variables of the
current active set at their bounds, minimises exactly over the free variables (one sparse
linear system \f$ P_{FF} x_F = -q_F - P_{FA} x_A \f$), frees every active variable whose
multiplier has the wrong sign and activates bounds that free variables violate. It stops
when nothing changes, which makes the KKT conditions hold. Plain PDAS activates all violated
bounds at once; with a matrix that is not an M-matrix (a bi-Laplacian couples vertices two
rings apart with the "wrong" sign) pinning coupled variables together overshoots, and on
large fairing problems plain PDAS chatters for hundreds of iterations. So violated bounds are
activated by decreasing violation as a maximal independent set of the graph of \f$ P \f$
(no two activated variables coupled), together with the violating variables all of whose
coupled variables violate or are active (the inside of a region pressed against its bounds);
every violated bound is activated once the previous activations turned out mostly right (at
most half as many releases followed), and right after a warm start only one per
neighbourhood of radius two (a bound missing from a nearly right active set shows as a bulge
of violations around it). Fairing problems of \f$ 10^3 \f$ to \f$ 10^5 \f$ variables took
10 to 20 iterations from a cold start this way; a gradient projection phase (below) now
finds most of the active set first. A cold start, or a warm start with no active bound,
first takes the steps of a primal active-set method: from a feasible point on the current
face of the box it goes towards the minimiser on that face up to the first bound crossed and
activates that bound alone, and it releases bounds only at a face minimiser inside the box,
so the objective decreases at every step. Each step is one solve bordered by the changed
variable, and the steps continue while the activations clear the violations geometrically
(15 % each: a few bounds hold the solution back) and their changes fit in the bordering budget of
one factorisation; then the primal-dual iterations continue from the point reached, activating twice
as many bounds at each iteration as long as every activation clears many other violations, and then
as above. On a deep dent whose steps a few short edges limit, the free minimiser leaves the box at
thousands of vertices while some twenty bounds are active at the solution; activating by the
violations overshoots far (with the fairing's curvature variation energy, which couples three rings
of vertices, pinned vertices pull their neighbours out of the box), and activating several of the
bounds crossed first still pinned hundreds of coupled vertices: the first programs of fairings of
\f$ 2.4 \cdot 10^4 \f$, \f$ 4.9 \cdot 10^4 \f$ and \f$ 10^5 \f$ variables took 4, 166 and 4
factorisations that way, and take one each with the primal steps (21 to 35 bordered solves).

<b>Gradient projection.</b> Problems of 2000 variables or more first look for the active
bounds by gradient projection (the method of Moré and Toraldo, GPCG): projected searches
along the gradient scaled by the diagonal of \f$ P \f$ alternate with conjugate gradients
(diagonal preconditioner) on the variables inside the box, each step one or a few products
with \f$ P \f$. It stops when a round of it moves fewer variables on or off their bounds
than the primal-dual iterations absorb cheaply, or at a budget of about one factorisation's
cost; the primal-dual iterations then start from the bounds it found, as from a warm start.
Where the active bounds are scattered (the free subsystems are then well conditioned), it
finds nearly all of them and the solve takes one factorisation instead of ten or more; where
they form large smooth regions it finds their bulk, and the primal-dual iterations correct
the rest. If its first projected gradient steps reach no bound, the active set is small and
the phase ends there (the primal-dual iterations start as without it). After a warm start
that knows an active set, one projected gradient step checks it first: if that step moves
few variables the warm start is good and the primal-dual iterations start from it
unchanged; otherwise the phase continues from it. A warm start with the factorisation of the
previous program at hand (a reused solver in an iterative method) skips the phase: the
active-set iterations preconditioned by that factorisation are cheaper there. The phase only
chooses where the active-set iterations start: the returned point meets the same KKT
conditions. `set_gradient_projection(false)` turns it off.

<b>Linear algebra.</b> \f$ P \f$ is factorised by a supernodal multifrontal
\f$ LDL^T \f$ factorisation whose dense blocks run as matrix products (several times
faster than a simplicial factorisation), in a fill-reducing ordering (AMD). The matrix
factorised for a free set \f$ F \f$ is \f$ P \f$ with the rows and columns of the other
variables replaced by their diagonal entry, so that its pattern never changes: the symbolic
analysis is done once per sparsity pattern and kept across calls of `solve()` (reuse the
solver object in an iterative method), and each iteration only refactorises numerically.
When the free set has changed little since the last factorisation, the system is solved with
that factorisation bordered by the changed variables instead (the variables that left the
free set are constrained by multipliers, those that joined it are eliminated through a small
dense Schur complement): one solve per changed variable, kept for the next iterations, as
long as that is cheaper than a new factorisation. Iterative refinement brings the residual
of every solve to the tolerance. Variables with \f$ l_i = u_i \f$ never enter a system.
After `set_warm_start()`, the factorisation left by the previous `solve()` (of another
matrix, but in an iterative method of a nearby one) preconditions conjugate gradients on
the free subsystems, for as many iterations as a new factorisation would cost (and its
symbolic analysis, if the pattern changed); only then is a new factorisation made. The
successive programs of a fairing are solved that way with a factorisation every few outer
iterations instead of several per iteration. Without a warm start every `solve()`
factorises afresh, so that a reused solver gives exactly the result of a new one.

<b>Safeguards.</b> If the active set cycles, the primal-dual iteration limit is reached, or a
free subsystem is singular (semidefinite \f$ P \f$), the solver continues with a monotone
projected Newton method (Bertsekas) from the best feasible point found: Newton steps on the
free variables with an Armijo search along the projection arc, scaled gradient steps on the
variables close to a bound, and for singular subsystems steps along directions of zero
curvature up to the nearest bound (or `UNBOUNDED` if no bound stops them). The objective
decreases at every step of that phase, so it cannot cycle; an iteration limit bounds the
work. Non-convexity is detected in every factorisation (a negative pivot, or a nonzero
coupling with a zero pivot) and in the gradient projection phase (nonpositive curvature
along a search direction ends it, and a matrix with a nonpositive diagonal entry skips it):
with a cold start without that phase (fewer than 2000 variables, or turned off) the first
factorisation is the one of the whole \f$ P \f$, so an indefinite \f$ P \f$ is always
reported as `NOT_CONVEX`; with that phase or a warm start only the free subsystems are
factorised, or solved by conjugate gradients (which hand
over to a factorisation on nonpositive curvature), and negative curvature confined to the
variables that stay active may go unnoticed (the returned point is then a KKT point whose
free subsystem is positive definite).

<b>Warm starts.</b> `set_warm_start()` passes a point whose entries lying on (or beyond)
a finite bound form the initial active set; its other entries only serve as initial guesses.
The bounds may differ from those of the problem the point came from: only on which side of
them its entries lie matters.

<b>Tolerance.</b> The solve stops with `Box_QP_status::OPTIMAL` when the relative KKT
residual (see `Box_QP_report`) of the returned point is at most `tolerance()`. Pivots
smaller than `pivot_tolerance()` times their diagonal entry are taken as zero (singular
\f$ P \f$); pivots below minus that are negative curvature.

\cgalModels `BoxConstrainedQuadraticProgramSolver`
*/
class Active_set_box_QP_solver
{
public:
  /// The sparse matrix type accepted by the bulk setter.
  using Sparse_matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  /// \name Creation
  /// @{

  /// creates a solver for a problem with no variables.
  Active_set_box_QP_solver() { resize(0); }

  /// creates a solver for a problem with `n` variables; see `resize()`.
  explicit Active_set_box_QP_solver(std::size_t n) { resize(n); }

  /// @}

  /// \name Problem
  /// @{

  /*!
  sets the number of variables to `n` and clears the problem: \f$ P = 0 \f$, \f$ q = 0 \f$,
  \f$ r = 0 \f$, \f$ l = -\infty \f$, \f$ u = +\infty \f$, no warm start. What was learnt
  about the sparsity pattern of \f$ P \f$ (ordering and symbolic factorisation) is kept and
  reused if the next problem has the same pattern; the parameters are kept too.
  */
  void resize(std::size_t n)
  {
    problem_.resize(n);
    warm_start_.clear();
    has_warm_start_ = false;
  }

  /// returns the number of variables.
  std::size_t number_of_variables() const { return problem_.size(); }

  /*!
  adds `value` to \f$ P_{ij} \f$ and to \f$ P_{ji} \f$ (once if `i == j`) when `i <= j`;
  calls with `i > j` are ignored, so that a loop over all ordered pairs of a symmetric matrix
  gives every entry exactly once. Repeated calls add up, which suits assembly.
  An index out of range makes the next `solve()` report `Box_QP_status::INVALID_INPUT`.
  */
  void set_P(std::size_t i, std::size_t j, double value) { problem_.add_P(i, j, value); }

  /*!
  adds the upper triangle (entries with row <= column) of `P`, an `n x n` matrix, to
  \f$ P \f$: the bulk equivalent of calling `set_P(i, j, P(i, j))` for all its entries.
  */
  void set_P(const Sparse_matrix& P) { problem_.add_P(P); }

  /// adds `value` to \f$ q_i \f$.
  void set_q(std::size_t i, double value) { problem_.add_q(i, value); }

  /// adds `value` to the constant term \f$ r \f$.
  void set_r(double value) { problem_.add_r(value); }

  /// sets \f$ l_i \f$ to `value` (a finite value or `-std::numeric_limits<double>::infinity()`).
  void set_l(std::size_t i, double value) { problem_.set_l(i, value); }

  /// sets \f$ u_i \f$ to `value` (a finite value or `+std::numeric_limits<double>::infinity()`).
  void set_u(std::size_t i, double value) { problem_.set_u(i, value); }

  /*!
  passes a starting point for the next call of `solve()` only; it must have
  `number_of_variables()` entries. Entries lying on or beyond a finite bound form the
  initial active set (to restart from an active set alone, put \f$ l_i \f$ or \f$ u_i \f$ in
  the entries of the active variables and anything strictly between the bounds, e.g.
  `0` or NaN, elsewhere); the other entries are initial guesses.
  */
  void set_warm_start(const std::vector<double>& x0)
  {
    warm_start_ = x0;
    has_warm_start_ = true;
  }

  /// @}

  /// \name Parameters
  /// @{

  /// sets the relative KKT residual at which a point is optimal (default `1e-10`); values are
  /// clamped to `[1e-14, 1e-2]`.
  void set_tolerance(double tolerance) { tolerance_ = std::min(std::max(tolerance, 1e-14), 1e-2); }
  /// returns the relative KKT tolerance.
  double tolerance() const { return tolerance_; }

  /// sets the limit on the total number of iterations of a solve (default `500`).
  void set_maximum_number_of_iterations(std::size_t n) { maximum_iterations_ = n; }
  /// returns the iteration limit.
  std::size_t maximum_number_of_iterations() const { return maximum_iterations_; }

  /// sets how many primal-dual active-set iterations are tried before the monotone projected
  /// Newton phase takes over (default `50`; `0` uses the monotone phase only).
  void set_maximum_number_of_primal_dual_iterations(std::size_t n) { maximum_primal_dual_ = n; }
  /// returns the primal-dual iteration limit.
  std::size_t maximum_number_of_primal_dual_iterations() const { return maximum_primal_dual_; }

  /// sets whether `solve()` may look for the active bounds by gradient projection before the
  /// active-set iterations (default `true`; see <b>Gradient projection</b> above). With
  /// `false` every solve takes the active-set path from its start.
  void set_gradient_projection(bool use) { use_gradient_projection_ = use; }
  /// returns whether the gradient projection phase may be used.
  bool gradient_projection() const { return use_gradient_projection_; }

  /// sets the relative size below which a pivot of a factorisation counts as zero
  /// (default `1e-12`).
  void set_pivot_tolerance(double tolerance) { pivot_tolerance_ = tolerance; }
  /// returns the relative pivot tolerance.
  double pivot_tolerance() const { return pivot_tolerance_; }

  /// @}

  /// \name Solving
  /// @{

  /*!
  solves the problem and writes the `number_of_variables()` values of the solution to
  `x_out`. The problem and the solver's parameters are not changed, so `solve()` can be
  called again, e.g. after `set_warm_start()`.

  The values written are a point within the bounds for the statuses `OPTIMAL`,
  `ITERATION_LIMIT`, `NOT_CONVEX`, `UNBOUNDED` and `NUMERICAL_FAILURE` (the solution, or the
  best point found), and NaN for `INFEASIBLE_BOUNDS` and `INVALID_INPUT`.

  \tparam OutputIterator an output iterator accepting `double`.
  */
  template <class OutputIterator>
  Box_QP_report solve(OutputIterator x_out)
  {
    const Box_QP_report report = solve_and_keep_solution();
    for (Eigen::Index i = 0; i < x_.size(); ++i)
      *x_out++ = x_[i];
    return report;
  }

  /// @}

private:
  using Inertia = internal::Supernodal_LDLT::Inertia;
  enum Variable_state : signed char { FREE, AT_LOWER, AT_UPPER, FIXED };

  // How the primal-dual phase ended.
  enum class Primal_dual_outcome { CONVERGED, CONTINUE_MONOTONE, NOT_CONVEX, ITERATION_LIMIT };

  Box_QP_report solve_and_keep_solution()
  {
    Box_QP_report report;
    const std::size_t n = problem_.size();
    const bool had_warm_start = has_warm_start_;
    std::vector<double> x0;
    x0.swap(warm_start_);
    has_warm_start_ = false;

    report.status = problem_.validate(report.message);
    if (report.status == Box_QP_status::OPTIMAL && had_warm_start && x0.size() != n) {
      std::ostringstream os;
      os << "the warm start has " << x0.size() << " values but the problem has " << n
         << " variables";
      report.message = os.str();
      report.status = Box_QP_status::INVALID_INPUT;
    }
    if (report.status != Box_QP_status::OPTIMAL) {
      x_.setConstant(static_cast<Eigen::Index>(n), std::numeric_limits<double>::quiet_NaN());
      return report;
    }

    problem_.assemble();
    if (n == 0) {
      x_.resize(0);
      problem_.evaluate(x_, report);
      report.status = Box_QP_status::OPTIMAL;
      return report;
    }
    // The factorisation left by the previous solve() is of another matrix. After a warm start
    // (the next program of an iterative method, alike the last one) it still preconditions
    // conjugate gradients well, which is much cheaper than a new factorisation.
    has_factorization_ = has_factorization_ && had_warm_start &&
                         inertia_ == Inertia::POSITIVE_DEFINITE && factored_free_.size() == n;
    factorization_is_stale_ = has_factorization_;
    preconditioned_iterations_ = 0;
    initialize_states(had_warm_start ? &x0 : nullptr);

    bool knows_active_set = had_warm_start && has_active_bound();
    if (use_gradient_projection() && gradient_projection_phase(report, knows_active_set))
      knows_active_set = has_active_bound();
    Primal_dual_outcome outcome = primal_dual_phase(report, knows_active_set);
    if (outcome == Primal_dual_outcome::CONVERGED) {
      problem_.evaluate(x_, report);
      if (report.relative_kkt_residual <= tolerance_) {
        report.status = Box_QP_status::OPTIMAL;
        return report;
      }
      outcome = Primal_dual_outcome::CONTINUE_MONOTONE; // polish a point that fell short
    }
    if (outcome == Primal_dual_outcome::NOT_CONVEX) {
      report.status = Box_QP_status::NOT_CONVEX;
      report.message = not_convex_message();
    } else if (outcome == Primal_dual_outcome::ITERATION_LIMIT) {
      report.status = Box_QP_status::ITERATION_LIMIT;
      report.message = "iteration limit reached in the primal-dual active-set phase";
    } else {
      report.status = projected_newton_phase(report);
    }
    problem_.evaluate(x_, report);
    return report;
  }

  // ---------------------------------------------------------------------------------------
  // Factorisations of free subsystems

  // The symbolic analysis (fill-reducing ordering, supernodes) depends on the pattern of P
  // only, and serves every P whose pattern it contains (the entries P lacks are factorised as
  // zeros). Whether it contains Q's pattern; if so, and `positions` is given, the position in
  // the analysed pattern of each entry of Q. Both patterns have increasing rows in each column.
  bool is_analyzed(const Sparse_matrix& Q, std::vector<int>* positions = nullptr) const
  {
    const int n = static_cast<int>(Q.cols());
    if (analyzed_outer_.size() != static_cast<std::size_t>(n + 1))
      return false;
    if (positions)
      positions->resize(static_cast<std::size_t>(Q.nonZeros()));
    const int* outer = Q.outerIndexPtr();
    const int* inner = Q.innerIndexPtr();
    for (int j = 0; j < n; ++j) {
      int a = analyzed_outer_[j];
      for (int p = outer[j]; p < outer[j + 1]; ++p) {
        while (a < analyzed_outer_[j + 1] && analyzed_inner_[a] < inner[p])
          ++a;
        if (a == analyzed_outer_[j + 1] || analyzed_inner_[a] != inner[p])
          return false;
        if (positions)
          (*positions)[p] = a;
      }
    }
    return true;
  }

  // Analyses a new pattern: the union of P's and the last one's if that is at most a quarter
  // larger than P's (a fairing's programs gain and lose a few entries from one iteration to
  // the next, so the union soon contains them all), else P's alone.
  void update_analysis()
  {
    const Sparse_matrix& Q = problem_.Q();
    const int n = static_cast<int>(Q.cols());
    if (is_analyzed(Q, &analyzed_position_))
      return;
    Sparse_matrix pattern = Q;
    bool grown = false;
    if (analyzed_outer_.size() == static_cast<std::size_t>(n + 1)) {
      Sparse_matrix last(n, n);
      last.resizeNonZeros(static_cast<Eigen::Index>(analyzed_inner_.size()));
      std::copy(analyzed_outer_.begin(), analyzed_outer_.end(), last.outerIndexPtr());
      std::copy(analyzed_inner_.begin(), analyzed_inner_.end(), last.innerIndexPtr());
      std::fill(last.valuePtr(), last.valuePtr() + last.nonZeros(), 1.);
      Sparse_matrix joined = Q.cwiseAbs() + last;
      if (double(joined.nonZeros()) <= 1.25 * double(Q.nonZeros())) {
        pattern = std::move(joined);
        grown = true;
      }
    }
    // The pattern is stored whole (both triangles and the diagonal), as Eigen's AMD routine
    // wants it: a copy of it saves the symmetrisation of Eigen::AMDOrdering.
    analyzed_outer_.assign(pattern.outerIndexPtr(), pattern.outerIndexPtr() + n + 1);
    analyzed_inner_.assign(pattern.innerIndexPtr(), pattern.innerIndexPtr() + pattern.nonZeros());
    // A pattern that only grew keeps its ordering if that adds little work: the ordering is
    // half of an analysis (a fairing of ~100 variables analyses at each of its first
    // iterations, as nodes move onto new edges). But new entries can join parts that the
    // ordering eliminated apart (the second factorisation of a fairing of 2.4 10^4 variables
    // took 2.5 times the flops that way): then a new ordering is computed.
    bool analyzed = false;
    if (grown && analyzed_ordering_.size() == static_cast<std::size_t>(n)) {
      const double last_flops = ldlt_.factorization_flops();
      ldlt_.analyze(n, analyzed_outer_.data(), analyzed_inner_.data(), analyzed_ordering_);
      analyzed = ldlt_.factorization_flops() <= 1.1 * last_flops;
    }
    if (!analyzed) {
      Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> permutation;
      Eigen::internal::minimum_degree_ordering(pattern, permutation);
      // AMD returns, for each elimination position, the variable eliminated there.
      analyzed_ordering_.assign(permutation.indices().data(), permutation.indices().data() + n);
      ldlt_.analyze(n, analyzed_outer_.data(), analyzed_inner_.data(), analyzed_ordering_);
    }
    is_analyzed(Q, &analyzed_position_); // contained by construction: fills the positions
    // The factor of the last matrix is laid out for the old analysis: it can precondition
    // nothing any more.
    has_factorization_ = false;
    factorization_is_stale_ = false;
  }

  // Factorises the matrix K_F that is P on the free variables F = {i : is_free[i]} and
  // diagonal elsewhere (the diagonal of P where it is positive, else 1): the pattern stays
  // the one of P, so only the numeric factorisation is redone, and K_F^-1 solves the free
  // subsystem while it keeps the other variables where the right-hand side puts them.
  internal::Supernodal_LDLT::Inertia factorize(const std::vector<char>& is_free,
                                               Box_QP_report& report)
  {
    update_analysis();
    const Sparse_matrix& Q = problem_.Q();
    const int n = static_cast<int>(Q.cols());
    masked_values_.assign(analyzed_inner_.size(), 0.);
    const int* outer = Q.outerIndexPtr();
    const int* inner = Q.innerIndexPtr();
    const double* values = Q.valuePtr();
    for (int j = 0; j < n; ++j)
      for (int p = outer[j]; p < outer[j + 1]; ++p) {
        const int i = inner[p];
        masked_values_[analyzed_position_[p]] =
            i == j ? (is_free[j] ? values[p] : (values[p] > 0. ? values[p] : 1.))
                   : ((is_free[i] && is_free[j]) ? values[p] : 0.);
      }
    ++report.factorizations;
    factored_free_ = is_free;
    bordering_column_of_.assign(static_cast<std::size_t>(n), -1);
    bordering_variables_.clear();
    bordering_columns_.resize(n, 0);
    has_factorization_ = true;
    factorization_is_stale_ = false;
    inertia_ = ldlt_.factorize(masked_values_.data(), pivot_tolerance_);
    if (inertia_ == internal::Supernodal_LDLT::Inertia::INDEFINITE)
      negative_curvature_variable_ = ldlt_.negative_pivot();
    return inertia_;
  }

  std::string not_convex_message() const
  {
    std::ostringstream os;
    os << "P is not positive semidefinite: negative curvature found at variable "
       << negative_curvature_variable_;
    return os.str();
  }

  // How many bordering columns (one solve each, computed in blocks) are worth computing
  // before a new factorisation is cheaper. Dense factorisation kernels run about ten times
  // faster per flop than the memory-bound substitutions; block solves about four times.
  // The columns are solved in blocks, whose substitutions run as matrix products at about
  // the speed per flop of the factorisation's (measured on grid bi-Laplacians of 1600 to
  // 40000 variables: a factorisation costs as much as 26 to 53 columns solved 16 at a time,
  // for a flop ratio of 17 to 58). A column, once solved, serves every later iteration until
  // the next factorisation.
  std::size_t bordering_budget() const
  {
    const double columns_per_factorization =
        ldlt_.factorization_flops() / std::max(1., ldlt_.solve_flops());
    const double memory_limit = 2.5e7 / std::max(1., double(problem_.size())); // 200 MB
    return static_cast<std::size_t>(
        std::max(0., std::min(columns_per_factorization, memory_limit)));
  }

  // Solves P_FF y_F = b_F (b and y vanish outside the free set F) with the factorisation of
  // K_F0 for an older free set F0, by bordering it with the changed variables: the variables
  // S_a that left F0 are constrained to 0 by multipliers mu, the variables S_f that joined
  // it are eliminated through the Schur complement. With K = P_F0F0, W_a = K^-1 E_Sa and
  // W_f = K^-1 P_F0,Sf (one solve per changed variable, kept until the next factorisation, so
  // that later iterations only add the variables that change again) and y0 = K^-1 b_F0:
  //   y_F0 = y0 - W_f y_Sf - W_a mu, where
  //   [ P_SfSf - P_Sf,F0 W_f   -(W_f)_Sa^T ] [ y_Sf ]   [ b_Sf - P_Sf,F0 y0 ]
  //   [ (W_f)_Sa                (W_a)_Sa    ] [ mu   ] = [ (y0)_Sa           ].
  // Returns false when more columns would be needed than are worth it.
  bool solve_by_bordering(const std::vector<char>& is_free, const Eigen::VectorXd& b,
                          Eigen::VectorXd& y)
  {
    const Sparse_matrix& Q = problem_.Q();
    const int n = static_cast<int>(b.size());
    std::vector<int> left, joined, missing; // S_a, S_f, and those without a column yet
    for (int i = 0; i < n; ++i) {
      if (factored_free_[i] && !is_free[i])
        left.push_back(i);
      else if (!factored_free_[i] && is_free[i])
        joined.push_back(i);
      else
        continue;
      if (bordering_column_of_[i] < 0)
        missing.push_back(i);
    }
    if (bordering_variables_.size() + missing.size() > bordering_budget())
      return false;
    if (!missing.empty()) {
      internal::Supernodal_LDLT::Right_hand_sides columns =
          internal::Supernodal_LDLT::Right_hand_sides::Zero(
              n, static_cast<Eigen::Index>(missing.size()));
      for (std::size_t m = 0; m < missing.size(); ++m) {
        const int i = missing[m];
        if (factored_free_[i])
          columns(i, m) = 1.;
        else
          for (Sparse_matrix::InnerIterator it(Q, i); it; ++it)
            if (factored_free_[it.row()])
              columns(it.row(), m) = it.value();
      }
      ldlt_.solve(columns);
      const Eigen::Index first = static_cast<Eigen::Index>(bordering_variables_.size());
      bordering_columns_.conservativeResize(n, first + columns.cols());
      bordering_columns_.rightCols(columns.cols()) = columns;
      for (std::size_t m = 0; m < missing.size(); ++m) {
        bordering_column_of_[missing[m]] = static_cast<int>(first) + static_cast<int>(m);
        bordering_variables_.push_back(missing[m]);
      }
    }

    Eigen::VectorXd y0 = b;
    for (int i = 0; i < n; ++i)
      if (!factored_free_[i])
        y0[i] = 0.;
    ldlt_.solve(y0);
    const Eigen::Index f = static_cast<Eigen::Index>(joined.size());
    const Eigen::Index a = static_cast<Eigen::Index>(left.size());
    if (f + a > 0) {
      const auto column = [this](int variable) {
        return bordering_columns_.col(bordering_column_of_[variable]);
      };
      // P_F0,j . v for a variable j outside F0
      const auto coupling_dot = [&](int j, const auto& v) {
        double sum = 0.;
        for (Sparse_matrix::InnerIterator it(Q, j); it; ++it)
          if (factored_free_[it.row()])
            sum += it.value() * v[it.row()];
        return sum;
      };
      Eigen::MatrixXd M(f + a, f + a);
      Eigen::VectorXd rhs(f + a);
      for (Eigen::Index p = 0; p < f; ++p) {
        const int j = joined[p];
        for (Eigen::Index p2 = 0; p2 < f; ++p2)
          M(p, p2) = Q.coeff(j, joined[p2]) - coupling_dot(j, column(joined[p2]));
        for (Eigen::Index t = 0; t < a; ++t) {
          M(p, f + t) = -column(j)[left[t]];
          M(f + t, p) = column(j)[left[t]];
        }
        rhs[p] = b[j] - coupling_dot(j, y0);
      }
      for (Eigen::Index t = 0; t < a; ++t) {
        for (Eigen::Index t2 = 0; t2 < a; ++t2)
          M(f + t, f + t2) = column(left[t2])[left[t]];
        rhs[f + t] = y0[left[t]];
      }
      // The blocks of M differ in scale by the square of P's (P against P^-1 entries):
      // equilibrated, a pivoting LU solves it to working accuracy, and the refinement of
      // correct_free_entries() converges instead of diverging.
      Eigen::VectorXd scale = Eigen::VectorXd::Ones(f + a);
      for (Eigen::Index k = 0; k < f + a; ++k)
        if (std::abs(M(k, k)) > 0.)
          scale[k] = 1. / std::sqrt(std::abs(M(k, k)));
      const Eigen::VectorXd scaled_solution =
          (scale.asDiagonal() * M * scale.asDiagonal()).fullPivLu().solve(scale.cwiseProduct(rhs));
      const Eigen::VectorXd solution = scale.cwiseProduct(scaled_solution);
      if (!solution.allFinite())
        return false;
      for (Eigen::Index p = 0; p < f; ++p)
        y0 -= solution[p] * column(joined[p]);
      for (Eigen::Index t = 0; t < a; ++t)
        y0 -= solution[f + t] * column(left[t]);
      for (Eigen::Index p = 0; p < f; ++p)
        y0[joined[p]] = solution[p];
    }
    y = y0;
    for (int i = 0; i < n; ++i)
      if (!is_free[i])
        y[i] = 0.;
    return true;
  }

  // Corrects the free entries of x until P_FF x_F = -q_F - P_FA x_A holds to the target
  // (the other entries hold their bounds), with the last factorisation and bordering.
  // Returns false if bordering is too expensive for this free set or the target is missed.
  bool correct_free_entries(const std::vector<char>& is_free, Eigen::VectorXd& x)
  {
    const Sparse_matrix& Q = problem_.Q();
    const Eigen::VectorXd& c = problem_.c();
    const Eigen::Index n = x.size();
    Eigen::VectorXd residual(n), correction;
    // A few corrections: the first solves, the others refine in floating point.
    for (int iteration = 0;; ++iteration) {
      residual.noalias() = -(Q * x + c);
      for (Eigen::Index i = 0; i < n; ++i)
        if (!is_free[i])
          residual[i] = 0.;
      const double target = 0.01 * tolerance_ * problem_.gradient_scale(x.cwiseAbs().maxCoeff());
      if (residual.cwiseAbs().maxCoeff() <= target)
        return true;
      if (iteration == 3 || !solve_by_bordering(is_free, residual, correction))
        return false;
      x += correction;
    }
  }

  // How many conjugate gradient iterations (one solve with the factorisation and one product
  // with P each) are worth doing in a solve() before a new factorisation is cheaper. The
  // dense kernels of a factorisation run about 6 times faster per flop than the
  // substitutions, which stream the factor from memory (measured on fairings of 2.4 10^4
  // and 10^5 variables: 11 to 15 against 2 to 2.6 GFlop/s); a new pattern costs a symbolic
  // analysis on top, about half a factorisation.
  std::size_t conjugate_gradient_budget() const
  {
    const double product_flops = 2. * double(problem_.Q().nonZeros());
    const double iteration_flops = ldlt_.solve_flops() + product_flops;
    const double factorization = ldlt_.factorization_flops() / 6. / iteration_flops;
    return static_cast<std::size_t>(is_analyzed(problem_.Q()) ? factorization
                                                              : 1.5 * factorization);
  }

  // Solves P_FF x_F = -q_F - P_FA x_A (the other entries of x hold their bounds) by conjugate
  // gradients preconditioned with the stale factorisation of K_F0: K_F0^-1 on the variables
  // of F n F0, the diagonal of P on those of F \ F0 (a symmetric positive definite operator on
  // F). Returns false when the budget of iterations of this solve() runs out before the
  // residual reaches the target of correct_free_entries() -- or is bound to, at the rate of
  // convergence seen so far --, or on nonpositive curvature (which a new factorisation then
  // tells apart).
  bool solve_by_preconditioned_cg(const std::vector<char>& is_free, Eigen::VectorXd& x)
  {
    const Sparse_matrix& Q = problem_.Q();
    const Eigen::VectorXd& c = problem_.c();
    const Eigen::VectorXd& diagonal = problem_.diagonal();
    const Eigen::Index n = x.size();
    const std::size_t budget = conjugate_gradient_budget();
    const auto free_part = [&](Eigen::VectorXd& v) {
      for (Eigen::Index i = 0; i < n; ++i)
        if (!is_free[i])
          v[i] = 0.;
    };
    const auto precondition = [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) {
      z = r;
      for (Eigen::Index i = 0; i < n; ++i)
        if (!factored_free_[i])
          z[i] = 0.;
      ldlt_.solve(z);
      for (Eigen::Index i = 0; i < n; ++i)
        if (!is_free[i])
          z[i] = 0.;
        else if (!factored_free_[i])
          z[i] = r[i] / (diagonal[i] > 0. ? diagonal[i] : 1.);
    };
    Eigen::VectorXd r, z, p, Qp;
    // Restarts from the true residual guard against the drift of the recurrence.
    for (int restart = 0; restart < 3; ++restart) {
      r.noalias() = -(Q * x + c);
      free_part(r);
      const double target = 0.01 * tolerance_ * problem_.gradient_scale(x.cwiseAbs().maxCoeff());
      if (r.cwiseAbs().maxCoeff() <= target)
        return true;
      precondition(r, z);
      p = z;
      double rz = r.dot(z);
      const double initial_residual = r.norm();
      const double reduction_needed = std::log(target / r.cwiseAbs().maxCoeff());
      for (int iteration = 1;; ++iteration) {
        if (preconditioned_iterations_ >= budget)
          return false;
        if (iteration > 5) {
          // A preconditioner of a matrix that differs much converges slowly: give up early
          // rather than waste the budget.
          const double rate = std::log(r.norm() / initial_residual) / (iteration - 1);
          const double still_needed = rate < 0. ? reduction_needed / rate - (iteration - 1) : 1e300;
          if (double(preconditioned_iterations_) + still_needed > double(budget))
            return false;
        }
        ++preconditioned_iterations_;
        Qp.noalias() = Q * p;
        free_part(Qp);
        const double curvature = p.dot(Qp);
        if (!(curvature > 0.) || !(rz > 0.))
          return false;
        const double alpha = rz / curvature;
        x += alpha * p;
        r -= alpha * Qp;
        if (r.cwiseAbs().maxCoeff() <= 0.5 * target)
          break;
        precondition(r, z);
        const double rz_next = r.dot(z);
        p = z + (rz_next / rz) * p;
        rz = rz_next;
      }
    }
    return false;
  }

  // Result of solving a free subsystem.
  enum class Free_solve { SOLVED, SINGULAR, INDEFINITE, FAILED };

  Free_solve solve_free_subsystem(const std::vector<char>& is_free, Eigen::VectorXd& x,
                                  Box_QP_report& report)
  {
    if (has_factorization_ && inertia_ == Inertia::POSITIVE_DEFINITE) {
      Eigen::VectorXd attempt = x;
      if (factorization_is_stale_ ? solve_by_preconditioned_cg(is_free, attempt)
                                  : correct_free_entries(is_free, attempt)) {
        x = attempt;
        return Free_solve::SOLVED;
      }
    }
    const Inertia inertia = factorize(is_free, report);
    if (inertia == Inertia::INDEFINITE)
      return Free_solve::INDEFINITE;
    if (inertia == Inertia::POSITIVE_SEMIDEFINITE)
      return Free_solve::SINGULAR;
    return correct_free_entries(is_free, x) ? Free_solve::SOLVED : Free_solve::FAILED;
  }

  // ---------------------------------------------------------------------------------------
  // Primal-dual active-set phase

  void initialize_states(const std::vector<double>* x0)
  {
    const Eigen::VectorXd& l = problem_.l();
    const Eigen::VectorXd& u = problem_.u();
    const Eigen::Index n = l.size();
    state_.assign(static_cast<std::size_t>(n), FREE);
    start_.setZero(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      if (l[i] == u[i]) {
        state_[i] = FIXED;
        continue;
      }
      if (x0 == nullptr)
        continue;
      const double xi = (*x0)[i];
      if (std::isfinite(l[i]) && xi <= l[i])
        state_[i] = AT_LOWER;
      else if (std::isfinite(u[i]) && xi >= u[i])
        state_[i] = AT_UPPER;
      else if (std::isfinite(xi))
        start_[i] = xi;
    }
    x_ = problem_.clamp(start_);
  }

  std::uint64_t hash_of_states() const
  {
    std::uint64_t hash = 1469598103934665603ull; // FNV-1a
    for (signed char s : state_) {
      hash ^= static_cast<unsigned char>(s);
      hash *= 1099511628211ull;
    }
    return hash;
  }

  // Activates bounds violated by the free variables of x and returns how many. Plain PDAS
  // activates them all; when P is not an M-matrix (a bi-Laplacian has positive entries two
  // rings apart), pinning two coupled variables at once overshoots, and PDAS then chatters
  // on large problems instead of converging. So violated bounds are activated by
  // decreasing violation (scaled by sqrt(P_ii), an energy) as a maximal independent set of
  // the graph of P -- no two activated variables are coupled -- plus every violating
  // variable whose coupled variables all violate or are active already, so that the inside
  // of a region pressed against its bounds is activated at once (INDEPENDENT). Given a
  // point `way_from` within the bounds, the order is instead the one in which the segment
  // from it to x crosses the bounds.
  enum class Activation {
    ALL,         // every violated bound
    INDEPENDENT, // an independent set of the graph of P, and the insides of violated regions
    SPARSE       // an independent set of the square of that graph
  };

  std::size_t count_violated_bounds(const Eigen::VectorXd& x, double x_tolerance) const
  {
    const Eigen::VectorXd& l = problem_.l();
    const Eigen::VectorXd& u = problem_.u();
    std::size_t count = 0;
    for (Eigen::Index i = 0; i < x.size(); ++i)
      if (state_[i] == FREE && std::max(l[i] - x[i], x[i] - u[i]) > x_tolerance)
        ++count;
    return count;
  }

  std::size_t activate_violated_bounds(const Eigen::VectorXd& x, double x_tolerance,
                                       Activation activation,
                                       const Eigen::VectorXd* way_from = nullptr,
                                       std::size_t limit = std::numeric_limits<std::size_t>::max())
  {
    const Sparse_matrix& Q = problem_.Q();
    const Eigen::VectorXd& l = problem_.l();
    const Eigen::VectorXd& u = problem_.u();
    const Eigen::VectorXd& diagonal = problem_.diagonal();
    const int n = static_cast<int>(x.size());
    violation_.setZero(n);
    violators_.clear();
    for (int i = 0; i < n; ++i) {
      if (state_[i] != FREE)
        continue;
      const double excess = std::max(l[i] - x[i], x[i] - u[i]);
      if (excess > x_tolerance) {
        if (way_from != nullptr) {
          // 1 / (the fraction of the way at which x_i leaves its box)
          const double bound = x[i] > u[i] ? u[i] : l[i];
          const double room = std::abs(bound - (*way_from)[i]);
          const double travel = std::abs(x[i] - (*way_from)[i]);
          violation_[i] = room > 0. ? travel / room : std::numeric_limits<double>::max();
        } else
          violation_[i] = diagonal[i] > 0. ? excess * std::sqrt(diagonal[i]) : excess;
        violators_.push_back(i);
      }
    }
    std::sort(violators_.begin(), violators_.end(), [this](int a, int b) {
      return violation_[a] > violation_[b] || (violation_[a] == violation_[b] && a < b);
    });
    activate_.assign(static_cast<std::size_t>(n), 0);
    std::vector<char>& coupled_to_activated = blocked_;
    coupled_to_activated.assign(static_cast<std::size_t>(n), 0);
    std::size_t chosen = 0;
    for (int i : violators_) {
      if (coupled_to_activated[i] && activation != Activation::ALL)
        continue;
      if (chosen++ >= limit)
        break;
      activate_[i] = 1;
      for (Sparse_matrix::InnerIterator it(Q, i); it; ++it) {
        coupled_to_activated[it.row()] = 1;
        if (activation == Activation::SPARSE)
          for (Sparse_matrix::InnerIterator second(Q, it.row()); second; ++second)
            coupled_to_activated[second.row()] = 1;
      }
    }
    if (activation == Activation::INDEPENDENT)
      for (int i : violators_) {
        bool inside = true;
        for (Sparse_matrix::InnerIterator it(Q, i); it && inside; ++it)
          inside = state_[it.row()] != FREE || violation_[it.row()] > 0.;
        if (inside)
          activate_[i] = 1;
      }
    std::size_t activated = 0;
    for (int i : violators_)
      if (activate_[i]) {
        state_[i] = x[i] < l[i] ? AT_LOWER : AT_UPPER;
        ++activated;
      }
    return activated;
  }

  bool has_active_bound() const
  {
    return std::any_of(state_.begin(), state_.end(),
                       [](signed char s) { return s == AT_LOWER || s == AT_UPPER; });
  }

  // ---------------------------------------------------------------------------------------
  // Gradient projection phase (Moré and Toraldo 1991, GPCG): finds the face of the box the
  // solution lies on by projected searches along the scaled gradient alternating with
  // conjugate gradients (diagonal preconditioner) on the variables inside the box, each
  // iteration one or a few products with P instead of a factorisation. Where the active bounds
  // are scattered, it finds nearly all of them in a few dozen products, and the primal-dual
  // phase then finishes from that active set with a single factorisation; where they form
  // large smooth regions the free subsystems are ill-conditioned and it stops at its budget
  // (a fraction of a factorisation's cost), having found what it could.

  // A warm start of an iterative method (a factorisation of the last program at hand) is left
  // to the active-set iterations preconditioned by that factorisation: measured on the
  // fairing (programs of 10^4 variables with some 10 to 100 active bounds), the projected
  // steps moved the bounds that matter around and took 13 factorisations per fairing
  // instead of 5.
  bool use_gradient_projection() const
  {
    return use_gradient_projection_ && problem_.size() >= gradient_projection_minimum_size_ &&
           !has_factorization_;
  }

  // Runs the phase from x_ (with start_ on the active bounds of the states); on return
  // true, state_, start_ and x_ describe the point it reached. From a warm start that knows
  // an active set, the phase first checks it: if the first projected gradient step moves
  // no more variables than the primal-dual phase absorbs cheaply, the warm start is good
  // and is left to the primal-dual phase untouched (return false).
  bool gradient_projection_phase(Box_QP_report& report, bool check_warm_start)
  {
    const Sparse_matrix& Q = problem_.Q();
    const Eigen::VectorXd& c = problem_.c();
    const Eigen::VectorXd& l = problem_.l();
    const Eigen::VectorXd& u = problem_.u();
    const Eigen::VectorXd& diagonal = problem_.diagonal();
    const Eigen::Index n = l.size();
    if (n == 0 || !(diagonal.minCoeff() > 0.))
      return false; // a zero or negative diagonal: leave it to the factorisations
    update_analysis();
    // A product with P streams the matrix from memory; the dense kernels of a factorisation
    // run about three times faster per flop.
    const double product_flops = 3. * (2. * double(Q.nonZeros()) + 10. * double(n));
    const double budget = gradient_projection_budget_ * ldlt_.factorization_flops() / product_flops;
    std::size_t products = 0;
    const Eigen::VectorXd inverse_diagonal = diagonal.cwiseInverse();

    Eigen::VectorXd x = x_;
    for (Eigen::Index i = 0; i < n; ++i)
      if (state_[i] == AT_LOWER || state_[i] == FIXED)
        x[i] = l[i];
      else if (state_[i] == AT_UPPER)
        x[i] = u[i];
    Eigen::VectorXd Qx = Q.transpose() * x; // P is symmetric: rows are gathered faster
    ++products;
    Eigen::VectorXd gradient = Qx + c;
    double objective = problem_.objective(x, Qx);
    // -1 at the lower bound, 1 at the upper bound, 0 inside.
    std::vector<signed char> face(static_cast<std::size_t>(n)), round_face;
    std::size_t at_bounds = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      face[i] = x[i] <= l[i] ? -1 : (x[i] >= u[i] ? 1 : 0);
      at_bounds += face[i] != 0;
    }
    round_face = face;
    const std::size_t fixed_variables = static_cast<std::size_t>(
        std::count(state_.begin(), state_.end(), static_cast<signed char>(FIXED)));

    Eigen::VectorXd candidate(n), Q_candidate, d, Qd;
    std::vector<int> clamped;
    // Armijo search along the projection arc P[x + a d] from a = first, with Qd = P d: the
    // product at a point of the arc is Qx + a Qd corrected by the columns of the clamped
    // variables, so a search costs no full product. Returns the number of variables whose
    // side changed, or -1 if no step was taken.
    const auto projected_search = [&](double first) -> long {
      double step = first;
      for (int trial = 0; trial < 30; ++trial, step *= 0.5) {
        clamped.clear();
        double slope = 0.;
        for (Eigen::Index i = 0; i < n; ++i) {
          const double target = x[i] + step * d[i];
          const double value = std::min(std::max(target, l[i]), u[i]);
          candidate[i] = value;
          if (value != target)
            clamped.push_back(static_cast<int>(i));
          slope += gradient[i] * (value - x[i]);
        }
        if (!(slope < 0.))
          return -1;
        Q_candidate = Qx + step * Qd;
        for (int i : clamped) {
          const double correction = candidate[i] - (x[i] + step * d[i]);
          for (Sparse_matrix::InnerIterator it(Q, i); it; ++it)
            Q_candidate[it.row()] += it.value() * correction;
        }
        const double candidate_objective = problem_.objective(candidate, Q_candidate);
        if (candidate_objective <= objective + 0.25 * slope) {
          long changed = 0;
          at_bounds = 0;
          for (Eigen::Index i = 0; i < n; ++i) {
            const signed char s = candidate[i] <= l[i] ? -1 : (candidate[i] >= u[i] ? 1 : 0);
            changed += (s != face[i]);
            face[i] = s;
            at_bounds += s != 0;
          }
          x.swap(candidate);
          Qx.swap(Q_candidate);
          gradient = Qx + c;
          objective = candidate_objective;
          ++report.projection_steps;
          return changed;
        }
      }
      return -1;
    };

    const double gradient_target = 0.01 * tolerance_ * problem_.gradient_scale(0.);
    // The face has settled when a round moves fewer variables than the primal-dual phase
    // absorbs cheaply (a few bordering columns, a small fraction of the active bounds).
    const double absorbed = 0.5 * double(bordering_budget());
    bool curvature_failure = false;
    Eigen::VectorXd r, z, p, w, Qw, Qp;
    // Conjugate gradients per visit of a face: their count grows with the diameter of the
    // mesh; fewer leave more rounds to the projected gradient steps, which find the bounds.
    const int cg_iterations =
        static_cast<int>(std::min(200., std::max(25., 0.25 * std::sqrt(double(n)))));
    for (int round = 0; double(products) < budget && !curvature_failure; ++round) {
      // Projected gradient steps, until the face settles or the decrease stalls.
      double best_decrease = 0.;
      for (int step = 0; step < 25 && double(products) < budget; ++step) {
        d = -inverse_diagonal.cwiseProduct(gradient);
        for (Eigen::Index i = 0; i < n; ++i)
          if ((face[i] < 0 && d[i] < 0.) || (face[i] > 0 && d[i] > 0.) || l[i] == u[i])
            d[i] = 0.;
        Qd.noalias() = Q.transpose() * d;
        ++products;
        const double curvature = d.dot(Qd), slope = gradient.dot(d);
        if (!(slope < 0.))
          break;
        if (!(curvature > 0.)) {
          curvature_failure = true;
          break;
        }
        const double before = objective;
        const long changed = projected_search(-slope / curvature);
        if (check_warm_start) {
          check_warm_start = false;
          if (double(changed) <= std::max(absorbed, 0.02 * double(at_bounds)))
            return false;
        }
        if (changed < 0)
          break;
        const double decrease = before - objective;
        best_decrease = std::max(best_decrease, decrease);
        if (changed == 0 || decrease <= 0.25 * best_decrease)
          break;
      }
      if (curvature_failure)
        break;
      // No bound reached from a cold start: the active set is small, and the active-set
      // iterations find it from the start as cheaply (the fairing's programs).
      if (round == 0 && at_bounds <= fixed_variables)
        return false;
      // Conjugate gradients on the variables inside the box, while the face holds; the
      // iterations stop when their decrease falls below a tenth of the best one.
      for (int cg_phase = 0; cg_phase < 5 && double(products) < budget; ++cg_phase) {
        r = -gradient;
        for (Eigen::Index i = 0; i < n; ++i)
          if (face[i] != 0 || l[i] == u[i])
            r[i] = 0.;
        if (r.cwiseAbs().maxCoeff() <= gradient_target)
          break;
        z = inverse_diagonal.cwiseProduct(r);
        p = z;
        w.setZero(n);
        Qw.setZero(n);
        double rz = r.dot(z), best = 0.;
        for (int iteration = 0; iteration < cg_iterations && double(products) < budget;
             ++iteration) {
          Qp.noalias() = Q.transpose() * p;
          ++products;
          const double curvature = p.dot(Qp); // p vanishes outside the free variables
          if (!(curvature > 0.)) {
            curvature_failure = true;
            break;
          }
          const double alpha = rz / curvature;
          w += alpha * p;
          Qw += alpha * Qp;
          for (Eigen::Index i = 0; i < n; ++i)
            if (face[i] == 0 && l[i] != u[i])
              r[i] -= alpha * Qp[i];
          const double decrease = 0.5 * alpha * rz; // of the quadratic along the face
          best = std::max(best, decrease);
          if (decrease <= 0.1 * best)
            break;
          z = inverse_diagonal.cwiseProduct(r);
          const double rz_next = r.dot(z);
          p = z + (rz_next / rz) * p;
          rz = rz_next;
        }
        if (curvature_failure)
          break;
        d.swap(w);
        Qd.swap(Qw);
        const long changed = projected_search(1.);
        if (changed != 0)
          break; // a new bound was hit (or no step): back to projected gradient steps
      }
      if (curvature_failure)
        break;
      std::size_t moved = 0;
      for (Eigen::Index i = 0; i < n; ++i)
        moved += (face[i] != round_face[i]);
      round_face = face;
      const double settled = std::max(absorbed, 0.02 * double(at_bounds));
      if (round > 0 && double(moved) <= settled)
        break;
    }
    if (curvature_failure || report.projection_steps == 0)
      return false;
    // The face found: bounds that the gradient pushes against are active, the other
    // variables free with their values as initial guesses.
    for (Eigen::Index i = 0; i < n; ++i) {
      if (state_[i] == FIXED)
        continue;
      if (face[i] < 0 && gradient[i] > 0.)
        state_[i] = AT_LOWER;
      else if (face[i] > 0 && gradient[i] < 0.)
        state_[i] = AT_UPPER;
      else
        state_[i] = FREE;
    }
    start_ = x;
    x_ = x;
    return true;
  }

  Primal_dual_outcome primal_dual_phase(Box_QP_report& report, bool warm_started)
  {
    const Sparse_matrix& Q = problem_.Q();
    const Eigen::VectorXd& c = problem_.c();
    const Eigen::VectorXd& l = problem_.l();
    const Eigen::VectorXd& u = problem_.u();
    const Eigen::Index n = l.size();

    Eigen::VectorXd x = start_; // the iterate: bounds on the active set, free values elsewhere
    double best_objective = problem_.objective(x_, Q * x_);
    std::vector<char> is_free(static_cast<std::size_t>(n));
    std::unordered_set<std::uint64_t> visited{hash_of_states()};
    std::size_t previous_activations = 0, previous_violations = 0;
    const std::size_t unlimited = std::numeric_limits<std::size_t>::max();
    // A warm start without active bounds says nothing about the active set: start as cold.
    const bool knows_active_set = warm_started && has_active_bound();
    std::size_t activation_limit = knows_active_set ? unlimited : 1;
    // Without a known active set, primal active-set steps come first: from a feasible point
    // on the current face, go towards the face's minimiser up to the first bound crossed and
    // activate that bound; release bounds only at a face minimiser inside the box. The
    // objective decreases at every step, and no activation overshoots: the fairing's first
    // programs (10^4 to 10^5 variables, the free minimiser out of the box at thousands of
    // vertices, some 20 bounds active at the solution) take one factorisation and 20 to 30
    // bordered solves this way, where activating several bounds at once pinned hundreds of
    // coupled vertices and took 4 to 166 factorisations. The steps continue as long as the
    // activations clear the violations geometrically and their changes fit in one
    // factorisation's bordering budget; then the primal-dual iterations take over from the
    // point reached (they find a large active set of independent bounds with fewer solves).
    bool primal_steps = !knows_active_set;
    std::size_t primal_changes = 0, primal_activations = 0, most_violations = 0,
                activations_at_most = 0, violations_before = 0;
    Eigen::VectorXd primal = x_; // feasible, on the face of the current active set

    for (std::size_t iteration = 0;; iteration += primal_steps ? 0 : 1) {
      if (!primal_steps && iteration >= maximum_primal_dual_)
        return Primal_dual_outcome::CONTINUE_MONOTONE;
      if (report.iterations >= maximum_iterations_)
        return Primal_dual_outcome::ITERATION_LIMIT;
      ++report.iterations;

      for (Eigen::Index i = 0; i < n; ++i) {
        is_free[i] = (state_[i] == FREE);
        if (state_[i] == AT_LOWER || state_[i] == FIXED)
          x[i] = l[i];
        else if (state_[i] == AT_UPPER)
          x[i] = u[i];
      }
      const Free_solve solved = solve_free_subsystem(is_free, x, report);
      if (solved == Free_solve::INDEFINITE)
        return Primal_dual_outcome::NOT_CONVEX;
      if (solved != Free_solve::SOLVED)
        return Primal_dual_outcome::CONTINUE_MONOTONE;

      const Eigen::VectorXd gradient = Q * x + c;
      const double x_norm = x.cwiseAbs().maxCoeff();
      const double x_tolerance = 0.1 * tolerance_ * problem_.x_scale(x_norm);
      const double gradient_tolerance = 0.1 * tolerance_ * problem_.gradient_scale(x_norm);
      // Releases every active variable whose multiplier has the wrong sign (the multiplier
      // of x_i >= l_i is g_i, the one of x_i <= u_i is -g_i).
      const auto release_bounds = [&] {
        std::size_t released = 0;
        for (Eigen::Index i = 0; i < n; ++i)
          if ((state_[i] == AT_LOWER && gradient[i] < -gradient_tolerance) ||
              (state_[i] == AT_UPPER && gradient[i] > gradient_tolerance)) {
            state_[i] = FREE;
            ++released;
          }
        return released;
      };
      if (primal_steps) {
        // Where a few bounds hold the solution back, the violations shrink geometrically with
        // the activations, after a transient of one or two (fairings of 10^4 to 10^5
        // variables: from 15128 to 7556 in 5 activations, to 203 in 11, to 0 in 31); the steps
        // continue while each activation since the peak clears 15 % of them (two activations
        // of grace). Where each clears a few, the bounds act alone, and the batches of the
        // primal-dual iterations find them with fewer solves.
        // Counted from the most violations seen (the first activations may raise them).
        const std::size_t violations = count_violated_bounds(x, x_tolerance);
        if (violations >= most_violations) {
          most_violations = violations;
          activations_at_most = primal_activations;
        }
        const double since_most = double(primal_activations - activations_at_most);
        const bool activations_pay =
            double(violations) <= double(most_violations) * std::pow(0.85, since_most - 2.);
        if (primal_activations > 0 && (!activations_pay || primal_changes >= bordering_budget())) {
          // Continue as the primal-dual iterations would after activating the last bound.
          primal_steps = false;
          iteration = 1;
          previous_violations = violations_before;
          previous_activations = 1;
        } else {
          std::size_t changes = 0;
          if (violations == 0) {
            primal = problem_.clamp(x);
            changes = release_bounds();
          } else {
            changes = activate_violated_bounds(x, x_tolerance, Activation::ALL, &primal, 1);
            ++primal_activations;
            // violation_ of the activated variable: 1 / the fraction of the way to its bound.
            double step = 1.;
            for (int i : violators_)
              if (activate_[i])
                step = 1. / violation_[i];
            primal = problem_.clamp(primal + step * (x - primal));
          }
          x_ = primal; // the objective decreased: the best feasible point so far
          best_objective = problem_.objective(x_, Q * x_);
          if (changes == 0)
            return Primal_dual_outcome::CONVERGED;
          if (!visited.insert(hash_of_states()).second)
            return Primal_dual_outcome::CONTINUE_MONOTONE;
          primal_changes += changes;
          violations_before = violations;
          continue;
        }
      }
      std::size_t changes = release_bounds();
      // After the primal steps of a cold start (or a warm start without active bounds), twice
      // as many bounds at each iteration, those crossed first on the way from the best
      // feasible point so far, as long as each activation clears at least three other
      // violations: a few active bounds then hold the solution back everywhere, and
      // activating by the violations would overshoot far.
      const std::size_t violations = count_violated_bounds(x, x_tolerance);
      const bool was_limited = activation_limit != unlimited;
      if (iteration > 0 && was_limited) {
        const bool few_hold_many =
            double(violations) + 3. * double(previous_activations) < double(previous_violations);
        // Activations that cleared at least half as many violations as their number (but not
        // three times it) act independently: plain PDAS then converges fast. Where they
        // cleared fewer (or violations elsewhere grew), the bounds are coupled and
        // activating them all would overshoot: keep the limit.
        const bool independent = 2. * double(violations) + double(previous_activations) <=
                                 2. * double(previous_violations);
        activation_limit = few_hold_many ? 2 * activation_limit
                           : independent ? unlimited
                                         : activation_limit;
      }
      previous_violations = violations;
      // Activations that the next iteration mostly keeps (and were not limited) are not
      // overshooting: then activate every violated bound, as plain PDAS does. After a warm
      // start, whose active set is meant to be nearly right, a missing active bound shows as
      // a bulge of violations around it: activate only one per bulge.
      Activation activation = Activation::INDEPENDENT;
      if (iteration == 0)
        activation = Activation::SPARSE;
      else if (activation_limit != unlimited)
        activation = Activation::ALL; // the first crossed, up to the limit
      else if (previous_activations > 0 && 2 * changes <= previous_activations && !was_limited)
        activation = Activation::ALL;
      const Eigen::VectorXd* way_from =
          activation_limit != unlimited && !knows_active_set ? &x_ : nullptr;
      previous_activations =
          activate_violated_bounds(x, x_tolerance, activation, way_from, activation_limit);
      changes += previous_activations;
      const Eigen::VectorXd feasible = problem_.clamp(x);
      if (changes == 0) {
        x_ = feasible;
        return Primal_dual_outcome::CONVERGED;
      }
      // The best feasible point is where the monotone phase starts, should it be needed.
      const double objective = problem_.objective(feasible, Q * feasible);
      if (objective < best_objective) {
        best_objective = objective;
        x_ = feasible;
      }
      if (!visited.insert(hash_of_states()).second)
        return Primal_dual_outcome::CONTINUE_MONOTONE; // the active set cycles
    }
  }

  // ---------------------------------------------------------------------------------------
  // Monotone projected Newton phase (Bertsekas 1982), from the feasible point x_.

  Box_QP_status projected_newton_phase(Box_QP_report& report)
  {
    const Sparse_matrix& Q = problem_.Q();
    const Eigen::VectorXd& c = problem_.c();
    const Eigen::VectorXd& l = problem_.l();
    const Eigen::VectorXd& u = problem_.u();
    const Eigen::VectorXd& diagonal = problem_.diagonal();
    const Eigen::Index n = l.size();
    const double max_diagonal = n > 0 ? diagonal.maxCoeff() : 0.;
    const double default_inverse_diagonal = max_diagonal > 0. ? 1. / max_diagonal : 1.;
    // Diagonal scaling of gradient steps, exact for a diagonal P.
    Eigen::VectorXd inverse_diagonal(n);
    for (Eigen::Index i = 0; i < n; ++i)
      inverse_diagonal[i] = diagonal[i] > 0. ? 1. / diagonal[i] : default_inverse_diagonal;

    std::vector<char> is_free(static_cast<std::size_t>(n));
    Eigen::VectorXd x = x_;
    Eigen::VectorXd Qx = Q * x;
    double objective = problem_.objective(x, Qx);

    // Armijo search along the projection arc x(a) = P[x + a d]; returns whether it succeeded.
    auto projected_search = [&](const Eigen::VectorXd& gradient, const Eigen::VectorXd& d) {
      double step = 1.;
      for (int trial = 0; trial < 60; ++trial, step *= 0.5) {
        const Eigen::VectorXd candidate = problem_.clamp(x + step * d);
        const Eigen::VectorXd move = candidate - x;
        const double slope = gradient.dot(move);
        if (!(slope < 0.))
          continue;
        const Eigen::VectorXd Q_candidate = Q * candidate;
        const double candidate_objective = problem_.objective(candidate, Q_candidate);
        if (candidate_objective <= objective + 1e-4 * slope) {
          x = candidate;
          Qx = Q_candidate;
          objective = candidate_objective;
          return true;
        }
      }
      return false;
    };

    for (;;) {
      const Eigen::VectorXd gradient = Qx + c;
      const double x_norm = x.cwiseAbs().maxCoeff();
      const double gradient_scale = problem_.gradient_scale(x_norm);
      const double kkt = problem_.kkt_residual(x, gradient);
      x_ = x;
      if (kkt <= tolerance_ * gradient_scale)
        return Box_QP_status::OPTIMAL;
      if (report.iterations >= maximum_iterations_) {
        report.message = "iteration limit reached";
        return Box_QP_status::ITERATION_LIMIT;
      }
      ++report.iterations;

      // Variables within epsilon of a bound that the gradient pushes against are handled by
      // scaled gradient steps; epsilon shrinks with the distance to stationarity.
      double epsilon = 0.;
      for (Eigen::Index i = 0; i < n; ++i) {
        const double projected =
            std::min(std::max(x[i] - inverse_diagonal[i] * gradient[i], l[i]), u[i]);
        epsilon = std::max(epsilon, std::abs(projected - x[i]));
      }
      for (Eigen::Index i = 0; i < n; ++i) {
        const bool binding = (l[i] == u[i]) || (x[i] <= l[i] + epsilon && gradient[i] > 0.) ||
                             (x[i] >= u[i] - epsilon && gradient[i] < 0.);
        is_free[i] = !binding;
      }
      Eigen::VectorXd newton_step, v;
      bool took_null_space_step = false;
      for (;;) {
        if (!has_factorization_ || factorization_is_stale_ || is_free != factored_free_) {
          if (factorize(is_free, report) == Inertia::INDEFINITE) {
            report.message = not_convex_message();
            return Box_QP_status::NOT_CONVEX;
          }
        } else if (inertia_ == Inertia::INDEFINITE) {
          report.message = not_convex_message();
          return Box_QP_status::NOT_CONVEX;
        }
        Eigen::VectorXd negative_free_gradient = -gradient;
        for (Eigen::Index i = 0; i < n; ++i)
          if (!is_free[i])
            negative_free_gradient[i] = 0.;
        ldlt_.solve_with_null_space_part(negative_free_gradient, newton_step, v);

        // A zero pivot means P_FF is singular; if -g_F has a component v in its null space,
        // the objective decreases linearly along v: go as far as a bound allows.
        if (ldlt_.number_of_zero_pivots() == 0)
          break;
        const double slope = gradient.dot(v);
        if (!(-slope > 0.01 * tolerance_ * gradient_scale * v.lpNorm<1>()))
          break;
        const Eigen::VectorXd Qv = Q * v;
        const double curvature = v.dot(Qv);
        double step = std::numeric_limits<double>::infinity();
        if (curvature > tolerance_ * problem_.Q_norm() * v.squaredNorm())
          step = -slope / curvature;
        const double v_norm = v.cwiseAbs().maxCoeff();
        std::size_t leaving_at_once = 0;
        for (Eigen::Index i = 0; i < n; ++i) {
          if (std::abs(v[i]) <= 1e-9 * v_norm)
            continue; // round-off of a direction that is free of bounds there
          double room = std::numeric_limits<double>::infinity();
          if (v[i] < 0. && std::isfinite(l[i]))
            room = (l[i] - x[i]) / v[i];
          else if (v[i] > 0. && std::isfinite(u[i]))
            room = (u[i] - x[i]) / v[i];
          if (room <= 0.) {
            // v leaves the box through a variable already on its bound: fix that variable and
            // look for another direction.
            is_free[i] = 0;
            ++leaving_at_once;
          }
          step = std::min(step, room);
        }
        if (leaving_at_once > 0)
          continue;
        if (!std::isfinite(step)) {
          report.message = "the objective is unbounded below along a direction of zero "
                           "curvature that no bound stops";
          return Box_QP_status::UNBOUNDED;
        }
        x = problem_.clamp(x + step * v);
        Qx = Q * x;
        objective = problem_.objective(x, Qx);
        took_null_space_step = true;
        break;
      }
      if (took_null_space_step)
        continue;

      Eigen::VectorXd d(n);
      for (Eigen::Index i = 0; i < n; ++i)
        d[i] = is_free[i] ? newton_step[i] : -inverse_diagonal[i] * gradient[i];
      if (projected_search(gradient, d))
        continue;
      const Eigen::VectorXd scaled_gradient_step = -inverse_diagonal.cwiseProduct(gradient);
      if (projected_search(gradient, scaled_gradient_step))
        continue;
      // No descent is left in floating point: accept the point if it is nearly stationary.
      if (kkt <= 100. * tolerance_ * gradient_scale)
        return Box_QP_status::OPTIMAL;
      report.message = "no further descent possible in floating point";
      return Box_QP_status::NUMERICAL_FAILURE;
    }
  }

  // ---------------------------------------------------------------------------------------

  internal::Box_QP_problem problem_;
  std::vector<double> warm_start_;
  bool has_warm_start_ = false;

  double tolerance_ = 1e-10;
  double pivot_tolerance_ = 1e-12;
  std::size_t maximum_iterations_ = 500;
  std::size_t maximum_primal_dual_ = 50;
  // The gradient projection phase: from this many variables on, and for at most this many
  // factorisations' worth of flops (counted as products with P).
  bool use_gradient_projection_ = true;
  std::size_t gradient_projection_minimum_size_ = 2000;
  double gradient_projection_budget_ = 1.;

  // The pattern the symbolic analysis of ldlt_ is for, and the position in it of each entry
  // of the current P.
  std::vector<int> analyzed_outer_, analyzed_inner_, analyzed_position_;
  std::vector<int> analyzed_ordering_; // for each elimination position, the variable there

  // The last factorisation and the free set it is for.
  internal::Supernodal_LDLT ldlt_;
  internal::Supernodal_LDLT::Inertia inertia_ =
      internal::Supernodal_LDLT::Inertia::POSITIVE_DEFINITE;
  bool has_factorization_ = false;
  // Whether that factorisation is of the previous solve()'s matrix (a preconditioner only),
  // and how many preconditioned iterations this solve() has spent.
  bool factorization_is_stale_ = false;
  std::size_t preconditioned_iterations_ = 0;
  std::vector<char> factored_free_;
  std::vector<double> masked_values_;
  // The columns of the bordering of the last factorisation, and for which variables.
  Eigen::MatrixXd bordering_columns_;
  std::vector<int> bordering_column_of_, bordering_variables_;
  int negative_curvature_variable_ = -1;

  std::vector<signed char> state_;
  Eigen::VectorXd start_, x_;
  // Work space of activate_violated_bounds().
  Eigen::VectorXd violation_;
  std::vector<int> violators_;
  std::vector<char> activate_, blocked_;
};

} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_ACTIVE_SET_BOX_QP_SOLVER_H

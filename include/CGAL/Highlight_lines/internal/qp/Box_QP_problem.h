// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_QP_BOX_QP_PROBLEM_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_QP_BOX_QP_PROBLEM_H

#include <CGAL/Highlight_lines/Box_QP_report.h>
#include <CGAL/Highlight_lines/internal/qp/bucket_sort.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// The data of a bound-constrained QP  min 1/2 x^T P x + q^T x + r,  l <= x <= u,  gathered
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
    upper_triplets_.clear();
    // A small problem sums P in place (a real dent's fairing, 100-300 variables, makes 3 to 7
    // set_P() calls per entry); a large one sums in place the entries of the pattern of the
    // problems before it with as many variables (see add_P()).
    dense_ = n <= dense_size_limit;
    dense_values_.assign(dense_ ? n * (n + 1) / 2 : 0, 0.);
    dense_present_.assign(dense_values_.size(), 0);
    if (dense_ || n != n_ || pattern_start_.size() != n + 1) {
      pattern_start_.assign(dense_ ? 0 : n + 1, 0);
      pattern_rows_.clear();
      pattern_values_.clear();
      pattern_set_.clear();
    } else {
      std::fill(pattern_values_.begin(), pattern_values_.end(), 0.);
      std::fill(pattern_set_.begin(), pattern_set_.end(), static_cast<unsigned char>(0));
    }
    n_ = n;
    q_.setZero(static_cast<Eigen::Index>(n));
    r_ = 0.;
    l_.setConstant(static_cast<Eigen::Index>(n), -std::numeric_limits<double>::infinity());
    u_.setConstant(static_cast<Eigen::Index>(n), std::numeric_limits<double>::infinity());
    setter_error_.clear();
    P_.resize(0, 0);
    assembled_ = false;
  }

  std::size_t size() const { return n_; }

  // Only the upper triangle is read, so that a loop over all ordered pairs of a symmetric
  // matrix gives every entry once.
  void add_P(std::size_t i, std::size_t j, double value)
  {
    if (i > j)
      return;
    assembled_ = false;
    if (j >= n_) {
      note_setter_error("set_P", i, j);
      return;
    }
    if (dense_) {
      const std::size_t at = j * (j + 1) / 2 + i;
      dense_values_[at] += value;
      dense_present_[at] = 1;
      return;
    }
    // An entry of the known pattern is summed in its place; another one waits as a triplet
    // until the triplets are merged into the pattern. Successive programs of an iterative
    // method share their pattern (a fairing declares it in its first program), so that after
    // the first one nearly every call is summed in place. Collecting every call as a triplet,
    // then sorting and summing them, took two more passes over all the calls of each program
    // (10^5-variable fairing: median 2.08 -> 1.91 x PMP::fair, peak memory 958 -> 930 MiB).
    const int* rows = pattern_rows_.data();
    const int* begin = rows + pattern_start_[j];
    const int* end = rows + pattern_start_[j + 1];
    const int* found = std::lower_bound(begin, end, static_cast<int>(i));
    if (found != end && *found == static_cast<int>(i)) {
      const std::size_t at = static_cast<std::size_t>(found - rows);
      pattern_values_[at] += value;
      pattern_set_[at] = 1;
      return;
    }
    upper_triplets_.emplace_back(static_cast<int>(i), static_cast<int>(j), value);
    // Merged when they outnumber the pattern's entries (and n): linear in the calls overall.
    if (upper_triplets_.size() >= pattern_rows_.size() + 8 * n_)
      merge_triplets_into_pattern();
  }

  void add_P(const Sparse_matrix& matrix)
  {
    assembled_ = false;
    if (static_cast<std::size_t>(matrix.rows()) != n_ ||
        static_cast<std::size_t>(matrix.cols()) != n_) {
      if (setter_error_.empty()) {
        std::ostringstream os;
        os << "set_P: the matrix is " << matrix.rows() << " x " << matrix.cols()
           << " but the problem has " << n_ << " variables";
        setter_error_ = os.str();
      }
      return;
    }
    for (int col = 0; col < matrix.outerSize(); ++col)
      for (Sparse_matrix::InnerIterator it(matrix, col); it; ++it)
        add_P(static_cast<std::size_t>(it.row()), static_cast<std::size_t>(col), it.value());
  }

  void add_q(std::size_t i, double value)
  {
    if (i >= n_)
      note_setter_error("set_q", i);
    else
      q_[static_cast<Eigen::Index>(i)] += value;
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

  // Checks the data in the order a user would fix it: indices, then values, then bounds. The
  // entries of P are checked as the sums assemble() will use (a non-finite term makes its sum
  // non-finite, and finite terms can overflow): the triplets are merged into the pattern first.
  Box_QP_status validate(std::string& message)
  {
    std::ostringstream os;
    if (!setter_error_.empty()) {
      message = setter_error_;
      return Box_QP_status::INVALID_INPUT;
    }
    merge_triplets_into_pattern();
    for (std::size_t j = 0; j + 1 < pattern_start_.size(); ++j)
      for (int p = pattern_start_[j]; p < pattern_start_[j + 1]; ++p)
        if (pattern_set_[p] && !std::isfinite(pattern_values_[p])) {
          os << "P(" << pattern_rows_[p] << ", " << j << ") is " << pattern_values_[p];
          message = os.str();
          return Box_QP_status::INVALID_INPUT;
        }
    for (std::size_t j = 0, at = 0; j < (dense_ ? n_ : 0); ++j)
      for (std::size_t i = 0; i <= j; ++i, ++at)
        if (!std::isfinite(dense_values_[at])) {
          os << "P(" << i << ", " << j << ") is " << dense_values_[at];
          message = os.str();
          return Box_QP_status::INVALID_INPUT;
        }
    if (!std::isfinite(r_)) {
      os << "r is " << r_;
      message = os.str();
      return Box_QP_status::INVALID_INPUT;
    }
    for (Eigen::Index i = 0; i < q_.size(); ++i) {
      if (!std::isfinite(q_[i])) {
        os << "q(" << i << ") is " << q_[i];
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
    for (Eigen::Index i = 0; i < q_.size(); ++i)
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
  // succeeded. The upper triangle is gathered by columns from the dense sums or the pattern
  // (the last triplets merged into it first); two transpositions then give the lower and the
  // upper part of every column of P in increasing rows. Linear in the number of entries and of
  // the set_P() calls since the last merge.
  void assemble()
  {
    const int n = static_cast<int>(n_);
    // The upper triangle with duplicates summed, by columns, the diagonal entry first.
    // The work arrays are members: at 10^5 variables they hold millions of entries, and
    // allocating them afresh for each program of a fairing faults their pages in each time.
    std::vector<int>& upper_rows = upper_rows_;
    std::vector<double>& upper_values = upper_values_;
    std::vector<int> upper_start(n_ + 1, 0);
    upper_rows.clear();
    upper_values.clear();
    if (dense_) {
      gather_dense_upper(upper_start, upper_rows, upper_values);
    } else {
      merge_triplets_into_pattern();
      gather_pattern_upper(upper_start, upper_rows, upper_values);
      drop_unset_entries_if_most();
    }
    // Column j of P: the rows i < j (its strictly upper part), then the rows k >= j (the
    // entries (j, k) of the upper triangle).
    std::vector<int> upper_count(n_, 0), lower_count(n_, 0);
    for (int j = 0; j < n; ++j) {
      upper_count[j] = upper_start[j + 1] - upper_start[j] - 1;
      for (int p = upper_start[j]; p < upper_start[j + 1]; ++p)
        ++lower_count[upper_rows[p]];
    }
    P_.resize(n, n);
    P_.resizeNonZeros(static_cast<Eigen::Index>(2 * upper_rows.size() - n_));
    int* outer = P_.outerIndexPtr();
    int* inner = P_.innerIndexPtr();
    double* values = P_.valuePtr();
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
    diagonal_ = P_.diagonal();
    Eigen::VectorXd row_sums = Eigen::VectorXd::Zero(n);
    for (int col = 0; col < n; ++col)
      for (Sparse_matrix::InnerIterator it(P_, col); it; ++it)
        row_sums[it.row()] += std::abs(it.value());
    P_norm_ = n > 0 ? row_sums.maxCoeff() : 0.;
    update_q_norm();
    assembled_ = true;
  }

  // Whether P is assembled and unchanged since (only q, r and the bounds may have changed, as
  // when a program is solved again with tighter bounds): assemble() would give the same matrix.
  bool is_assembled() const { return assembled_; }

  void update_q_norm() { q_norm_ = n_ > 0 ? q_.cwiseAbs().maxCoeff() : 0.; }

  const Sparse_matrix& P() const { return P_; }
  const Eigen::VectorXd& q() const { return q_; }
  const Eigen::VectorXd& l() const { return l_; }
  const Eigen::VectorXd& u() const { return u_; }
  const Eigen::VectorXd& diagonal() const { return diagonal_; }
  double r() const { return r_; }
  double P_norm() const { return P_norm_; }
  double q_norm() const { return q_norm_; }

  // The size of the terms a gradient at x is made of; KKT residuals are relative to it.
  double gradient_scale(double x_norm) const
  {
    const double scale = q_norm_ + P_norm_ * x_norm;
    return scale > 0. ? scale : 1.;
  }

  // A change of x below this size (relative tolerance 1) changes the gradient by less than
  // the gradient scale: it is the unit in which closeness to a bound is judged.
  double x_scale(double x_norm) const { return x_norm + (P_norm_ > 0. ? q_norm_ / P_norm_ : 0.); }

  double objective(const Eigen::VectorXd& x, const Eigen::VectorXd& Px) const
  {
    return 0.5 * x.dot(Px) + q_.dot(x) + r_;
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
    const Eigen::VectorXd Px = P_ * x;
    const Eigen::VectorXd gradient = Px + q_;
    report.kkt_residual = kkt_residual(x, gradient);
    report.relative_kkt_residual =
        report.kkt_residual / gradient_scale(x.size() > 0 ? x.cwiseAbs().maxCoeff() : 0.);
    report.objective_value = objective(x, Px);
    report.active_bounds = 0;
    for (Eigen::Index i = 0; i < x.size(); ++i)
      if (x[i] == l_[i] || x[i] == u_[i])
        ++report.active_bounds;
  }

private:
  // Adds the entries of the triplets to the pattern (each summed in the order of the set_P()
  // calls: a stable counting sort by column, then a marker array), keeping the rows of each
  // column increasing. A triplet's entry is never in the pattern: it would have been summed
  // there.
  void merge_triplets_into_pattern()
  {
    if (upper_triplets_.empty())
      return;
    const int n = static_cast<int>(n_);
    std::vector<int> start;
    std::vector<std::pair<int, double>>& by_column = by_column_;
    bucket_sort(
        n,
        [this](auto&& emit) {
          for (const Triplet& t : upper_triplets_)
            emit(t.col(), std::pair<int, double>(t.row(), t.value()));
        },
        start, by_column);
    std::vector<int> column_of(n_, -1), slot(n_), merged_start(n_ + 1, 0), merged_rows;
    std::vector<double> merged_values;
    std::vector<unsigned char> merged_set;
    std::size_t merged_size = pattern_rows_.size(); // the old entries and the distinct new ones
    for (int j = 0; j < n; ++j)
      for (int p = start[j]; p < start[j + 1]; ++p)
        if (column_of[by_column[p].first] != j) {
          column_of[by_column[p].first] = j;
          ++merged_size;
        }
    std::fill(column_of.begin(), column_of.end(), -1);
    merged_rows.reserve(merged_size);
    merged_values.reserve(merged_size);
    merged_set.reserve(merged_size);
    std::vector<std::pair<int, double>> added; // the new entries of one column, summed
    for (int j = 0; j < n; ++j) {
      added.clear();
      for (int p = start[j]; p < start[j + 1]; ++p) {
        const int i = by_column[p].first;
        if (column_of[i] != j) {
          column_of[i] = j;
          slot[i] = static_cast<int>(added.size());
          added.emplace_back(i, 0.);
        }
        added[static_cast<std::size_t>(slot[i])].second += by_column[p].second;
      }
      std::sort(added.begin(), added.end());
      auto next_added = added.begin();
      for (int p = pattern_start_[j]; p <= pattern_start_[j + 1]; ++p) {
        const int old_row = p < pattern_start_[j + 1] ? pattern_rows_[p] : n;
        for (; next_added != added.end() && next_added->first < old_row; ++next_added) {
          merged_rows.push_back(next_added->first);
          merged_values.push_back(next_added->second);
          merged_set.push_back(1);
        }
        if (old_row < n) {
          merged_rows.push_back(old_row);
          merged_values.push_back(pattern_values_[p]);
          merged_set.push_back(pattern_set_[p]);
        }
      }
      merged_start[j + 1] = static_cast<int>(merged_rows.size());
    }
    pattern_start_.swap(merged_start);
    pattern_rows_.swap(merged_rows);
    pattern_values_.swap(merged_values);
    pattern_set_.swap(merged_set);
    upper_triplets_.clear(); // merged: not before, so that a failed allocation loses no call
  }

  // Keeps only the entries set in this problem where the others are the majority: the pattern
  // is the union of the patterns since the number of variables last changed, which a solver
  // reused for unrelated programs would otherwise grow without bound.
  void drop_unset_entries_if_most()
  {
    const std::size_t set = static_cast<std::size_t>(
        std::count(pattern_set_.begin(), pattern_set_.end(), static_cast<unsigned char>(1)));
    if (2 * set >= pattern_set_.size())
      return;
    std::size_t kept = 0;
    for (std::size_t j = 0; j < n_; ++j) {
      const int begin = pattern_start_[j], end = pattern_start_[j + 1];
      pattern_start_[j] = static_cast<int>(kept);
      for (int p = begin; p < end; ++p)
        if (pattern_set_[p]) {
          pattern_rows_[kept] = pattern_rows_[p];
          pattern_values_[kept] = pattern_values_[p];
          pattern_set_[kept] = 1;
          ++kept;
        }
    }
    pattern_start_[n_] = static_cast<int>(kept);
    pattern_rows_.resize(kept);
    pattern_values_.resize(kept);
    pattern_set_.resize(kept);
    pattern_rows_.shrink_to_fit();
    pattern_values_.shrink_to_fit();
    pattern_set_.shrink_to_fit();
  }

  // The upper triangle by columns from the pattern: its entries set in this problem, and every
  // diagonal entry (zero if not set), first in its column.
  void gather_pattern_upper(std::vector<int>& upper_start, std::vector<int>& upper_rows,
                            std::vector<double>& upper_values) const
  {
    for (std::size_t j = 0; j < n_; ++j) {
      const int diagonal_at = static_cast<int>(upper_rows.size());
      upper_rows.push_back(static_cast<int>(j));
      upper_values.push_back(0.);
      for (int p = pattern_start_[j]; p < pattern_start_[j + 1]; ++p) {
        if (!pattern_set_[p])
          continue;
        if (pattern_rows_[p] == static_cast<int>(j)) {
          upper_values[diagonal_at] = pattern_values_[p];
        } else {
          upper_rows.push_back(pattern_rows_[p]);
          upper_values.push_back(pattern_values_[p]);
        }
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
  // The sparse case (see add_P()): the pattern of the entries set since the number of
  // variables last changed (the union of those problems' patterns), by columns with increasing
  // rows (pattern_start_, pattern_rows_),
  // this problem's sums there (pattern_values_) and whether it set each (pattern_set_); the
  // entries outside the pattern as triplets until merged.
  std::vector<int> pattern_start_, pattern_rows_;
  std::vector<double> pattern_values_;
  std::vector<unsigned char> pattern_set_;
  std::vector<Triplet> upper_triplets_;
  std::vector<std::pair<int, double>> by_column_; // work array of merge_triplets_into_pattern()
  std::vector<int> upper_rows_;
  std::vector<double> upper_values_;
  bool dense_ = false;
  bool assembled_ = false;           // see is_assembled()
  std::vector<double> dense_values_; // column j at j (j + 1) / 2, rows 0 to j
  std::vector<unsigned char> dense_present_;
  Eigen::VectorXd q_, l_, u_, diagonal_;
  double r_ = 0.;
  std::string setter_error_;
  Sparse_matrix P_;
  double P_norm_ = 0., q_norm_ = 0.;
};

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_QP_BOX_QP_PROBLEM_H

// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_ACTIVE_SET_BOX_QP_SOLVER_H
#define CGAL_HIGHLIGHT_LINES_ACTIVE_SET_BOX_QP_SOLVER_H

#include <CGAL/Highlight_lines/Box_QP_report.h>
#include <CGAL/Highlight_lines/internal/qp/Box_QP_problem.h>
#include <CGAL/Highlight_lines/internal/qp/Supernodal_LDLT.h>
#include <CGAL/Highlight_lines/internal/qp/fill_reducing_ordering.h>

#include <Eigen/Dense>
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

/*!
\ingroup PkgHighlightLinesRef

The built-in solver of bound-constrained convex quadratic programs

\f[ \min_x \tfrac{1}{2} x^T P x + q^T x + r \quad \text{subject to} \quad l \le x \le u \f]

with a sparse symmetric positive (semi)definite \f$ P \f$, as they arise at every iteration
of the highlight-line fairing.

<b>Method</b> (in detail: \ref hl_solver_method in the manual). A
primal-dual active-set method (the semismooth Newton method of Hintermüller, Ito and Kunisch
for box constraints) whose iterations each solve one sparse linear system over the free
variables. A problem of 2000 variables or more first looks for the active bounds by
gradient projection (Moré and Toraldo; a warm start is first checked by one projected step,
and kept if that moves few variables); a cold start also takes primal active-set steps that
activate the bounds in the order the step crosses them. The systems are solved with a
supernodal \f$ LDL^T \f$ factorisation in a fill-reducing ordering (approximate minimum
degree; where the program links `CGAL::METIS_support`, which defines `CGAL_METIS_ENABLED`,
also nested dissection by METIS when minimum degree leaves a factorisation of more than 5000
flops per entry of the pattern of \f$ P \f$, and the ordering of fewer flops is kept),
analysed once per sparsity pattern (reuse the solver object in an iterative method), and bordered by
the changed variables while that is cheaper than a new factorisation. After `set_warm_start()`, the
factorisation left by the previous `solve()` is reused before a new one is made: bordered if
\f$ P \f$ has not changed since (neither `resize()` nor `set_P()` was called: the same program
solved again with other bounds, \f$ q \f$ or \f$ r \f$), else as the preconditioner of
conjugate gradients on the free subsystems. Without a warm start every `solve()` factorises
afresh, so that a reused solver gives exactly the result of a new one. If the active set cycles, the
primal-dual iteration limit is reached or a free subsystem is singular, a monotone projected
Newton method (Bertsekas) continues from the best feasible point found, so that the solve
cannot cycle.

<b>Convexity.</b> Non-convexity is detected in every factorisation (a negative pivot, or a
nonzero coupling with a zero pivot) and in the gradient projection phase (nonpositive
curvature along a search direction): with a cold start without that phase (fewer than 2000
variables, or `set_gradient_projection(false)`) the first factorisation is the one of the whole
\f$ P \f$, so an indefinite \f$ P \f$ is always reported as `NOT_CONVEX`; with that phase or a
warm start only the free subsystems are factorised, and negative curvature confined to the
variables that stay active may go unnoticed (the returned point is then a KKT point whose free
subsystem is positive definite). A singular \f$ P \f$ whose free subsystem has directions of
zero curvature that no bound stops is reported as `UNBOUNDED`.

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

    // A program solved again with other bounds (as the fairing does where a step would flip a
    // face) keeps its matrix, and after a warm start the factorisation of it that the last
    // solve left.
    const bool same_matrix = problem_.is_assembled();
    if (same_matrix)
      problem_.update_q_norm();
    else
      problem_.assemble();
    if (n == 0) {
      x_.resize(0);
      problem_.evaluate(x_, report);
      report.status = Box_QP_status::OPTIMAL;
      return report;
    }
    // Unless the matrix is the same, the factorisation left by the previous solve() is of
    // another matrix. After a warm start (the next program of an iterative method, alike the
    // last one) it still preconditions conjugate gradients well, which is much cheaper than a
    // new factorisation.
    has_factorization_ = has_factorization_ && had_warm_start &&
                         inertia_ == Inertia::POSITIVE_DEFINITE && factored_free_.size() == n;
    factorization_is_stale_ = has_factorization_ && (!same_matrix || factorization_is_stale_);
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
  // zeros). Whether it contains P's pattern; if so, and `positions` is given, the position in
  // the analysed pattern of each entry of P. Both patterns have increasing rows in each column.
  bool is_analyzed(const Sparse_matrix& P, std::vector<int>* positions = nullptr) const
  {
    const int n = static_cast<int>(P.cols());
    if (analyzed_outer_.size() != static_cast<std::size_t>(n + 1))
      return false;
    if (positions)
      positions->resize(static_cast<std::size_t>(P.nonZeros()));
    const int* outer = P.outerIndexPtr();
    const int* inner = P.innerIndexPtr();
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
    const Sparse_matrix& P = problem_.P();
    const int n = static_cast<int>(P.cols());
    if (is_analyzed(P, &analyzed_position_))
      return;
    Sparse_matrix pattern = P;
    bool grown = false;
    if (analyzed_outer_.size() == static_cast<std::size_t>(n + 1)) {
      Sparse_matrix last(n, n);
      last.resizeNonZeros(static_cast<Eigen::Index>(analyzed_inner_.size()));
      std::copy(analyzed_outer_.begin(), analyzed_outer_.end(), last.outerIndexPtr());
      std::copy(analyzed_inner_.begin(), analyzed_inner_.end(), last.innerIndexPtr());
      std::fill(last.valuePtr(), last.valuePtr() + last.nonZeros(), 1.);
      Sparse_matrix joined = P.cwiseAbs() + last;
      if (double(joined.nonZeros()) <= 1.25 * double(P.nonZeros())) {
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
    if (!analyzed) // pattern's arrays are analyzed_outer_'s and analyzed_inner_'s
      analyzed_ordering_ = internal::analyze_in_fill_reducing_ordering(ldlt_, pattern);
    is_analyzed(P, &analyzed_position_); // contained by construction: fills the positions
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
    const Sparse_matrix& P = problem_.P();
    const int n = static_cast<int>(P.cols());
    masked_values_.assign(analyzed_inner_.size(), 0.);
    const int* outer = P.outerIndexPtr();
    const int* inner = P.innerIndexPtr();
    const double* values = P.valuePtr();
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
    single_precision_preconditioner_ =
        ldlt_.number_of_factor_entries() >= single_precision_factor_entries;
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
    const Sparse_matrix& P = problem_.P();
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
          for (Sparse_matrix::InnerIterator it(P, i); it; ++it)
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
        for (Sparse_matrix::InnerIterator it(P, j); it; ++it)
          if (factored_free_[it.row()])
            sum += it.value() * v[it.row()];
        return sum;
      };
      Eigen::MatrixXd M(f + a, f + a);
      Eigen::VectorXd rhs(f + a);
      for (Eigen::Index p = 0; p < f; ++p) {
        const int j = joined[p];
        for (Eigen::Index p2 = 0; p2 < f; ++p2)
          M(p, p2) = P.coeff(j, joined[p2]) - coupling_dot(j, column(joined[p2]));
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
    const Sparse_matrix& P = problem_.P();
    const Eigen::VectorXd& q = problem_.q();
    const Eigen::Index n = x.size();
    Eigen::VectorXd residual(n), correction;
    // A few corrections: the first solves, the others refine in floating point.
    for (int iteration = 0;; ++iteration) {
      residual.noalias() = -(P * x + q);
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
    const double product_flops = 2. * double(problem_.P().nonZeros());
    const double iteration_flops = ldlt_.solve_flops() + product_flops;
    const double factorization = ldlt_.factorization_flops() / 6. / iteration_flops;
    return static_cast<std::size_t>(is_analyzed(problem_.P()) ? factorization
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
    // A large factorisation in single precision first: the substitutions stream the factor
    // from memory, and floats halve what they read (a solve takes 0.59 times as long at 10^5
    // variables, benchmark_qp_solver). Where the matrix is too ill-conditioned for floats
    // (slivers), conjugate gradients stall with it; they go on from where they are with the
    // factorisation in double precision, which then preconditions every solve until the next
    // factorisation. A factor that fits in the cache gains little, and small programs keep
    // double precision.
    if (single_precision_preconditioner_) {
      if (preconditioned_cg(is_free, x))
        return true;
      single_precision_preconditioner_ = false;
    }
    return preconditioned_cg(is_free, x);
  }

  bool preconditioned_cg(const std::vector<char>& is_free, Eigen::VectorXd& x)
  {
    const Sparse_matrix& P = problem_.P();
    const Eigen::VectorXd& q = problem_.q();
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
      if (single_precision_preconditioner_)
        ldlt_.solve_in_single_precision(z);
      else
        ldlt_.solve(z);
      for (Eigen::Index i = 0; i < n; ++i)
        if (!is_free[i])
          z[i] = 0.;
        else if (!factored_free_[i])
          z[i] = r[i] / (diagonal[i] > 0. ? diagonal[i] : 1.);
    };
    Eigen::VectorXd r, z, p, Pp;
    // Restarts from the true residual guard against the drift of the recurrence.
    for (int restart = 0; restart < 3; ++restart) {
      r.noalias() = -(P * x + q);
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
        Pp.noalias() = P * p;
        free_part(Pp);
        const double curvature = p.dot(Pp);
        if (!(curvature > 0.) || !(rz > 0.))
          return false;
        const double alpha = rz / curvature;
        x += alpha * p;
        r -= alpha * Pp;
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
    const Sparse_matrix& P = problem_.P();
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
      for (Sparse_matrix::InnerIterator it(P, i); it; ++it) {
        coupled_to_activated[it.row()] = 1;
        if (activation == Activation::SPARSE)
          for (Sparse_matrix::InnerIterator second(P, it.row()); second; ++second)
            coupled_to_activated[second.row()] = 1;
      }
    }
    if (activation == Activation::INDEPENDENT)
      for (int i : violators_) {
        bool inside = true;
        for (Sparse_matrix::InnerIterator it(P, i); it && inside; ++it)
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

  // Also with the factorisation of the last program at hand (a reused solver, warm-started):
  // a warm start whose first projected step moves few variables is left to the active-set
  // iterations preconditioned by that factorisation (the fairing's programs, some 10 to 100
  // active bounds: one step of ~1 % of a factorisation each, same iterates), while a warm
  // start far from the face is corrected by the projection, as a new solver's would be
  // (fairing-like programs of 10^4 and 10^5 variables, 20 % of bounds active, warm-started
  // from a nearby program's solution: 4 to 7 factorisations before, one now).
  bool use_gradient_projection() const
  {
    return use_gradient_projection_ && problem_.size() >= gradient_projection_minimum_size_;
  }

  // Runs the phase from x_ (with start_ on the active bounds of the states); on return
  // true, state_, start_ and x_ describe the point it reached. From a warm start that knows
  // an active set, the phase first checks it: if the first projected gradient step moves
  // no more variables than the primal-dual phase absorbs cheaply, the warm start is good
  // and is left to the primal-dual phase untouched (return false).
  bool gradient_projection_phase(Box_QP_report& report, bool check_warm_start)
  {
    const Sparse_matrix& P = problem_.P();
    const Eigen::VectorXd& q = problem_.q();
    const Eigen::VectorXd& l = problem_.l();
    const Eigen::VectorXd& u = problem_.u();
    const Eigen::VectorXd& diagonal = problem_.diagonal();
    const Eigen::Index n = l.size();
    if (n == 0 || !(diagonal.minCoeff() > 0.))
      return false; // a zero or negative diagonal: leave it to the factorisations
    // The budget below needs an analysis' flop count. With the last factorisation at hand
    // (a warm start) that analysis serves, even if the pattern grew: analysing now would
    // discard the factorisation that preconditions the active-set iterations.
    if (!has_factorization_)
      update_analysis();
    // A product with P streams the matrix from memory; the dense kernels of a factorisation
    // run about three times faster per flop.
    const double product_flops = 3. * (2. * double(P.nonZeros()) + 10. * double(n));
    const double budget = gradient_projection_budget_ * ldlt_.factorization_flops() / product_flops;
    std::size_t products = 0;
    const Eigen::VectorXd inverse_diagonal = diagonal.cwiseInverse();

    Eigen::VectorXd x = x_;
    for (Eigen::Index i = 0; i < n; ++i)
      if (state_[i] == AT_LOWER || state_[i] == FIXED)
        x[i] = l[i];
      else if (state_[i] == AT_UPPER)
        x[i] = u[i];
    Eigen::VectorXd Px = P.transpose() * x; // P is symmetric: rows are gathered faster
    ++products;
    Eigen::VectorXd gradient = Px + q;
    double objective = problem_.objective(x, Px);
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

    Eigen::VectorXd candidate(n), P_candidate, d, Pd;
    std::vector<int> clamped;
    // Armijo search along the projection arc P[x + a d] from a = first, with Pd = P d: the
    // product at a point of the arc is Px + a Pd corrected by the columns of the clamped
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
        P_candidate = Px + step * Pd;
        for (int i : clamped) {
          const double correction = candidate[i] - (x[i] + step * d[i]);
          for (Sparse_matrix::InnerIterator it(P, i); it; ++it)
            P_candidate[it.row()] += it.value() * correction;
        }
        const double candidate_objective = problem_.objective(candidate, P_candidate);
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
          Px.swap(P_candidate);
          gradient = Px + q;
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
    Eigen::VectorXd r, z, p, w, Pw, Pp;
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
        Pd.noalias() = P.transpose() * d;
        ++products;
        const double curvature = d.dot(Pd), slope = gradient.dot(d);
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
        Pw.setZero(n);
        double rz = r.dot(z), best = 0.;
        for (int iteration = 0; iteration < cg_iterations && double(products) < budget;
             ++iteration) {
          Pp.noalias() = P.transpose() * p;
          ++products;
          const double curvature = p.dot(Pp); // p vanishes outside the free variables
          if (!(curvature > 0.)) {
            curvature_failure = true;
            break;
          }
          const double alpha = rz / curvature;
          w += alpha * p;
          Pw += alpha * Pp;
          for (Eigen::Index i = 0; i < n; ++i)
            if (face[i] == 0 && l[i] != u[i])
              r[i] -= alpha * Pp[i];
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
        Pd.swap(Pw);
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
    const Sparse_matrix& P = problem_.P();
    const Eigen::VectorXd& q = problem_.q();
    const Eigen::VectorXd& l = problem_.l();
    const Eigen::VectorXd& u = problem_.u();
    const Eigen::Index n = l.size();

    Eigen::VectorXd x = start_; // the iterate: bounds on the active set, free values elsewhere
    double best_objective = problem_.objective(x_, P * x_);
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

      const Eigen::VectorXd gradient = P * x + q;
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
          best_objective = problem_.objective(x_, P * x_);
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
      const double objective = problem_.objective(feasible, P * feasible);
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
    const Sparse_matrix& P = problem_.P();
    const Eigen::VectorXd& q = problem_.q();
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
    Eigen::VectorXd Px = P * x;
    double objective = problem_.objective(x, Px);

    // Armijo search along the projection arc x(a) = P[x + a d]; returns whether it succeeded.
    auto projected_search = [&](const Eigen::VectorXd& gradient, const Eigen::VectorXd& d) {
      double step = 1.;
      for (int trial = 0; trial < 60; ++trial, step *= 0.5) {
        const Eigen::VectorXd candidate = problem_.clamp(x + step * d);
        const Eigen::VectorXd move = candidate - x;
        const double slope = gradient.dot(move);
        if (!(slope < 0.))
          continue;
        const Eigen::VectorXd P_candidate = P * candidate;
        const double candidate_objective = problem_.objective(candidate, P_candidate);
        if (candidate_objective <= objective + 1e-4 * slope) {
          x = candidate;
          Px = P_candidate;
          objective = candidate_objective;
          return true;
        }
      }
      return false;
    };

    for (;;) {
      const Eigen::VectorXd gradient = Px + q;
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
        const Eigen::VectorXd Pv = P * v;
        const double curvature = v.dot(Pv);
        double step = std::numeric_limits<double>::infinity();
        if (curvature > tolerance_ * problem_.P_norm() * v.squaredNorm())
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
        Px = P * x;
        objective = problem_.objective(x, Px);
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
  // Whether conjugate gradients use the factorisation in single precision, see
  // solve_by_preconditioned_cg(): from 2^22 entries of the factor on (32 MiB in double
  // precision, beyond the last-level cache of most machines).
  bool single_precision_preconditioner_ = false;
  static constexpr std::size_t single_precision_factor_entries = std::size_t(1) << 22;
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

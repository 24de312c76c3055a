// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_QUADRATIC_PROGRAM_TRAITS_BOX_QP_ADAPTER_H
#define CGAL_HIGHLIGHT_LINES_QUADRATIC_PROGRAM_TRAITS_BOX_QP_ADAPTER_H

#include <CGAL/Highlight_lines/internal/qp/Box_QP_problem.h>
#include <CGAL/Highlight_lines/Box_QP_report.h>

#include <CGAL/number_utils.h>

#include <cstddef>
#include <iterator>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// Collects what a QuadraticProgramTraits model writes, converted to double. Models differ in
// how they advance the iterator (CGAL's OSQP model writes `*(++it) = v`), so both increments
// do nothing and every assignment appends.
class To_double_collector
{
public:
  using iterator_category = std::output_iterator_tag;
  using value_type = void;
  using difference_type = std::ptrdiff_t;
  using pointer = void;
  using reference = void;

  explicit To_double_collector(std::vector<double>& values) : values_(&values) {}

  template <class Number>
  To_double_collector& operator=(const Number& value)
  {
    values_->push_back(CGAL::to_double(value));
    return *this;
  }
  To_double_collector& operator*() { return *this; }
  To_double_collector& operator++() { return *this; }
  To_double_collector operator++(int) { return *this; }

private:
  std::vector<double>* values_;
};

} // namespace internal

/*!
\ingroup PkgHighlightLinesRef

Makes a model of CGAL's `QuadraticProgramTraits`, such as
`CGAL::OSQP_quadratic_program_traits`, a model of `BoxConstrainedQuadraticProgramSolver`.

The adapter gathers the problem with the accumulating semantics of the concept, checks it
like the built-in solver does (`INVALID_INPUT`, `INFEASIBLE_BOUNDS`, and `NOT_CONVEX` for a
negative diagonal entry of \f$ P \f$), then passes it to the wrapped model as the program
\f$ \min \frac{1}{2}x^TPx + q^Tx + r \f$ subject to \f$ l \le I x \le u \f$: `resize(n, n)`,
every entry of the upper triangle of \f$ P \f$ once, every \f$ q_i \f$, \f$ r \f$, the
identity as `A`, and the bounds, infinite ones included. The point the model returns is
clamped to the bounds (iterative solvers return points slightly outside) and evaluated:
the status is `OPTIMAL` if the model reported success and the relative KKT residual of that
point is at most `tolerance()`, `NUMERICAL_FAILURE` otherwise. `QuadraticProgramTraits` has no
warm start, so the one passed is only checked for its size.

\tparam QuadraticProgramTraits a model of `QuadraticProgramTraits` whose number type is
constructible from `double` and has `CGAL::to_double()`.

\cgalModels `BoxConstrainedQuadraticProgramSolver`
*/
template <class QuadraticProgramTraits>
class Quadratic_program_traits_box_QP_adapter
{
public:
  /// \name Creation
  /// @{

  /// wraps `traits`.
  explicit Quadratic_program_traits_box_QP_adapter(
      const QuadraticProgramTraits& traits = QuadraticProgramTraits())
      : traits_(traits)
  {
    resize(0);
  }

  /// @}

  /// \name Problem
  /// The semantics of `BoxConstrainedQuadraticProgramSolver`.
  /// @{

  /// starts a new problem with `n` variables.
  void resize(std::size_t n)
  {
    problem_.resize(n);
    warm_start_size_ = 0;
    has_warm_start_ = false;
  }
  /// adds `value` to \f$ P_{ij} \f$ and \f$ P_{ji} \f$ if `i <= j`.
  void set_P(std::size_t i, std::size_t j, double value) { problem_.add_P(i, j, value); }
  /// adds `value` to \f$ q_i \f$.
  void set_q(std::size_t i, double value) { problem_.add_q(i, value); }
  /// adds `value` to \f$ r \f$.
  void set_r(double value) { problem_.add_r(value); }
  /// sets \f$ l_i \f$.
  void set_l(std::size_t i, double value) { problem_.set_l(i, value); }
  /// sets \f$ u_i \f$.
  void set_u(std::size_t i, double value) { problem_.set_u(i, value); }
  /// checks the size of `x0` at the next `solve()`; the values are not used.
  void set_warm_start(const std::vector<double>& x0)
  {
    warm_start_size_ = x0.size();
    has_warm_start_ = true;
  }

  /// @}

  /// \name Parameters
  /// @{

  /// sets the relative KKT residual up to which a point is reported optimal (default `1e-6`,
  /// the accuracy that first-order solvers such as OSQP reach).
  void set_tolerance(double tolerance) { tolerance_ = tolerance; }
  /// returns the relative KKT tolerance.
  double tolerance() const { return tolerance_; }
  /// returns the wrapped model, e.g. to change its settings.
  QuadraticProgramTraits& traits() { return traits_; }

  /// @}

  /// \name Solving
  /// @{

  /// solves the problem with the wrapped model; see `BoxConstrainedQuadraticProgramSolver`.
  template <class OutputIterator>
  Box_QP_report solve(OutputIterator x_out)
  {
    const std::size_t n = problem_.size();
    Box_QP_report report;
    Eigen::VectorXd x = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(n),
                                                  std::numeric_limits<double>::quiet_NaN());
    const bool warm_start_size_is_wrong = has_warm_start_ && warm_start_size_ != n;
    has_warm_start_ = false;
    report.status = problem_.validate(report.message);
    if (report.status == Box_QP_status::OPTIMAL && warm_start_size_is_wrong) {
      std::ostringstream os;
      os << "the warm start has " << warm_start_size_ << " values but the problem has " << n
         << " variables";
      report.message = os.str();
      report.status = Box_QP_status::INVALID_INPUT;
    }
    if (report.status == Box_QP_status::OPTIMAL && n > 0)
      report.status = solve_with_traits(x, report);
    else if (report.status == Box_QP_status::OPTIMAL)
      problem_.evaluate(x, report);
    for (Eigen::Index i = 0; i < x.size(); ++i)
      *x_out++ = x[i];
    return report;
  }

  /// @}

private:
  Box_QP_status solve_with_traits(Eigen::VectorXd& x, Box_QP_report& report)
  {
    problem_.assemble();
    const auto& P = problem_.P();
    const auto& q = problem_.q();
    const auto& l = problem_.l();
    const auto& u = problem_.u();
    const std::size_t n = problem_.size();
    x = problem_.clamp(Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n)));
    for (std::size_t i = 0; i < n; ++i)
      if (problem_.diagonal()[static_cast<Eigen::Index>(i)] < 0.) {
        std::ostringstream os;
        os << "P is not positive semidefinite: P(" << i << ", " << i << ") is negative";
        report.message = os.str();
        problem_.evaluate(x, report);
        return Box_QP_status::NOT_CONVEX;
      }

    traits_.resize(n, n);
    for (int column = 0; column < P.outerSize(); ++column)
      for (typename std::decay_t<decltype(P)>::InnerIterator it(P, column); it; ++it)
        if (it.row() <= column)
          traits_.set_P(static_cast<std::size_t>(it.row()), static_cast<std::size_t>(column),
                        it.value());
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Index k = static_cast<Eigen::Index>(i);
      traits_.set_q(i, q[k]);
      traits_.set_A(i, i, 1.);
      traits_.set_l(i, l[k]);
      traits_.set_u(i, u[k]);
    }
    traits_.set_r(problem_.r());

    std::vector<double> values;
    values.reserve(n);
    const bool success = traits_.solve(internal::To_double_collector(values));
    if (values.size() == n)
      x = problem_.clamp(
          Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(n)));
    problem_.evaluate(x, report);
    report.iterations = 1;
    if (!success || values.size() != n) {
      std::ostringstream os;
      os << "the wrapped QuadraticProgramTraits model "
         << (success ? "returned " : "reported a failure and returned ") << values.size()
         << " values for " << n << " variables";
      report.message = os.str();
      return Box_QP_status::NUMERICAL_FAILURE;
    }
    if (!(report.relative_kkt_residual <= tolerance_)) {
      std::ostringstream os;
      os << "the point of the wrapped QuadraticProgramTraits model has a relative KKT "
            "residual of "
         << report.relative_kkt_residual << ", above the tolerance " << tolerance_;
      report.message = os.str();
      return Box_QP_status::NUMERICAL_FAILURE;
    }
    return Box_QP_status::OPTIMAL;
  }

  QuadraticProgramTraits traits_;
  internal::Box_QP_problem problem_;
  std::size_t warm_start_size_ = 0;
  bool has_warm_start_ = false;
  double tolerance_ = 1e-6;
};

} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_QUADRATIC_PROGRAM_TRAITS_BOX_QP_ADAPTER_H

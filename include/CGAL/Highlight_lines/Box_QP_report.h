// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_BOX_QP_REPORT_H
#define CGAL_HIGHLIGHT_LINES_BOX_QP_REPORT_H

#include <cstddef>
#include <limits>
#include <ostream>
#include <string>

namespace CGAL {
namespace Highlight_lines {

/*!
\ingroup PkgHighlightLinesRef

The outcome of solving a bound-constrained quadratic program
\f$ \min \frac{1}{2} x^T P x + q^T x + r \f$ subject to \f$ l \le x \le u \f$
with a model of `BoxConstrainedQuadraticProgramSolver`.
*/
enum class Box_QP_status {
  /// The returned point satisfies the bounds and the KKT conditions within the solver's
  /// tolerance: it is a minimiser.
  OPTIMAL,
  /// The iteration limit was reached first; the returned point satisfies the bounds and is the
  /// best one found.
  ITERATION_LIMIT,
  /// Some lower bound exceeds its upper bound (\f$ l_i > u_i \f$): no point satisfies the bounds.
  INFEASIBLE_BOUNDS,
  /// \f$ P \f$ was found to have negative curvature (it is not positive semidefinite), so the
  /// problem is not convex.
  NOT_CONVEX,
  /// The objective decreases without bound along a feasible direction of zero curvature
  /// (possible only when \f$ P \f$ is singular).
  UNBOUNDED,
  /// The data cannot be used: a NaN or infinite entry of \f$ P \f$ or \f$ q \f$, a NaN bound,
  /// \f$ l_i = +\infty \f$ or \f$ u_i = -\infty \f$, an index out of range, or a warm start
  /// of the wrong size. The report's message names the offending entry.
  INVALID_INPUT,
  /// The computation broke down or stagnated in floating point before the KKT conditions were
  /// met, or a wrapped solver reported a failure; the returned point satisfies the bounds.
  NUMERICAL_FAILURE
};

/*!
\ingroup PkgHighlightLinesRef
returns the name of the enumerator, such as `"OPTIMAL"`.
*/
inline const char* to_string(Box_QP_status status)
{
  switch (status) {
  case Box_QP_status::OPTIMAL:
    return "OPTIMAL";
  case Box_QP_status::ITERATION_LIMIT:
    return "ITERATION_LIMIT";
  case Box_QP_status::INFEASIBLE_BOUNDS:
    return "INFEASIBLE_BOUNDS";
  case Box_QP_status::NOT_CONVEX:
    return "NOT_CONVEX";
  case Box_QP_status::UNBOUNDED:
    return "UNBOUNDED";
  case Box_QP_status::INVALID_INPUT:
    return "INVALID_INPUT";
  case Box_QP_status::NUMERICAL_FAILURE:
    return "NUMERICAL_FAILURE";
  }
  return "UNKNOWN";
}

/// writes `to_string(status)`.
inline std::ostream& operator<<(std::ostream& os, Box_QP_status status)
{
  return os << to_string(status);
}

/*!
\ingroup PkgHighlightLinesRef

What a model of `BoxConstrainedQuadraticProgramSolver` reports about one call of `solve()`.

The KKT residual is the infinity norm of the projected gradient \f$ \pi \f$ at the returned
point \f$ x \f$, with \f$ g = Px + q \f$: \f$ \pi_i = g_i \f$ if \f$ l_i < x_i < u_i \f$,
\f$ \pi_i = \min(g_i, 0) \f$ if \f$ x_i = l_i < u_i \f$, \f$ \pi_i = \max(g_i, 0) \f$ if
\f$ x_i = u_i > l_i \f$, and \f$ \pi_i = 0 \f$ if \f$ l_i = u_i \f$. It vanishes exactly at
the minimisers of a convex problem.
*/
struct Box_QP_report
{
  /// how the solve ended.
  Box_QP_status status = Box_QP_status::INVALID_INPUT;
  /// the number of active-set iterations (each solves one linear system of the free
  /// variables).
  std::size_t iterations = 0;
  /// the number of sparse matrix factorisations computed (0 if the solver does not say).
  std::size_t factorizations = 0;
  /// the number of projected searches (steps along a projection arc onto the box) of a
  /// gradient projection phase that looks for the active bounds before the active-set
  /// iterations (0 if the solver has no such phase or skipped it).
  std::size_t projection_steps = 0;
  /// \f$ \|\pi\|_\infty \f$, see above; NaN when no point was computed.
  double kkt_residual = std::numeric_limits<double>::quiet_NaN();
  /// `kkt_residual` divided by \f$ \|q\|_\infty + \|P\|_\infty \|x\|_\infty \f$, the size of
  /// the terms the gradient is made of (1 is used when that size is zero), so that it is
  /// invariant under scaling of the problem.
  double relative_kkt_residual = std::numeric_limits<double>::quiet_NaN();
  /// the number of variables whose returned value equals one of their bounds (variables with
  /// \f$ l_i = u_i \f$ included).
  std::size_t active_bounds = 0;
  /// \f$ \frac{1}{2} x^T P x + q^T x + r \f$ at the returned point; NaN when no point was
  /// computed.
  double objective_value = std::numeric_limits<double>::quiet_NaN();
  /// a human-readable explanation when the status is not `OPTIMAL`, naming the offending
  /// variable or entry where there is one.
  std::string message;

  /// returns `status == Box_QP_status::OPTIMAL`.
  bool is_optimal() const { return status == Box_QP_status::OPTIMAL; }
};

} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_BOX_QP_REPORT_H

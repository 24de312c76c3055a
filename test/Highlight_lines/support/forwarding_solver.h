// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A model of the box-QP solver concept that forwards every call to the built-in solver: a test
// derives from it and hides the calls it watches or changes (the fairing calls them on the
// derived type).
#ifndef HIGHLIGHT_LINES_TEST_FORWARDING_SOLVER_H
#define HIGHLIGHT_LINES_TEST_FORWARDING_SOLVER_H

#include <CGAL/Highlight_lines/Active_set_box_QP_solver.h>

#include <cstddef>
#include <vector>

namespace test {

struct Forwarding_solver
{
  CGAL::Highlight_lines::Active_set_box_QP_solver inner;
  void resize(std::size_t n) { inner.resize(n); }
  void set_P(std::size_t i, std::size_t j, double v) { inner.set_P(i, j, v); }
  void set_q(std::size_t i, double v) { inner.set_q(i, v); }
  void set_r(double v) { inner.set_r(v); }
  void set_l(std::size_t i, double v) { inner.set_l(i, v); }
  void set_u(std::size_t i, double v) { inner.set_u(i, v); }
  void set_warm_start(const std::vector<double>& x0) { inner.set_warm_start(x0); }
  template <typename OutputIterator>
  CGAL::Highlight_lines::Box_QP_report solve(OutputIterator out)
  {
    return inner.solve(out);
  }
};

} // namespace test

#endif // HIGHLIGHT_LINES_TEST_FORWARDING_SOLVER_H

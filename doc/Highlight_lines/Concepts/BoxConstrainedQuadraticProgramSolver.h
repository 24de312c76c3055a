/*!
\ingroup PkgHighlightLinesConcepts
\cgalConcept

A concept for solvers of bound-constrained convex quadratic programs

<center>
\f{eqnarray*}{
& \mbox{minimize} & \frac{1}{2}\mathbf{x}^{T}P\mathbf{x} + \mathbf{q}^{T}\mathbf{x} + r \\
& \mbox{subject to} & \mathbf{l} \leq \mathbf{x} \leq \mathbf{u}
\f}
</center>

in \f$ n \f$ real variables \f$ \mathbf{x} = (x_0, \ldots, x_{n-1}) \f$, where

<UL>
<LI>\f$ P \f$ is a sparse symmetric positive (semi)definite \f$ n \times n \f$ matrix,
<LI>\f$ \mathbf{q} \f$ is an \f$ n \f$-dimensional vector and \f$ r \f$ a constant,
<LI>\f$ l_i \in \mathbb{R} \cup \{-\infty\} \f$ and \f$ u_i \in \mathbb{R} \cup \{+\infty\} \f$
are the bounds of variable \f$ i \f$; \f$ l_i = u_i \f$ fixes it.
</UL>

`CGAL::fair_with_highlight_lines()` solves one such program at every iteration (the
displacements of the movable vertices along their normals, bounded by half the shortest
incident edge) and takes the solver as a named parameter; its default is the built-in model
`CGAL::Highlight_lines::Active_set_box_QP_solver`.

<b>Use.</b> A model is default constructible and reusable: `resize()` starts a new problem
(every entry is cleared), the setters fill it, `set_warm_start()` optionally passes a starting
point, and `solve()` writes the solution and returns a `CGAL::Highlight_lines::Box_QP_report`.
A model may keep what does not depend on the values between problems of the same size and
sparsity pattern (e.g. a symbolic factorisation), which makes the repeated solves of an
iterative method cheaper.

<b>Assembly.</b> \f$ P \f$ is given by its upper triangle: `set_P(i, j, v)` with `i <= j`
adds `v` to \f$ P_{ij} \f$ and \f$ P_{ji} \f$, and calls with `i > j` are ignored, so that a
loop over all ordered pairs of a symmetric matrix (e.g. \f$ J^T J \f$ over the support of a
Jacobian row) gives every entry exactly once. `set_P()`, `set_q()` and `set_r()` <em>add</em>
to what is there, so that the objective can be assembled term by term; `set_l()` and
`set_u()` overwrite. Indices out of range and non-finite values are not preconditions: they
are reported by `solve()` as `Box_QP_status::INVALID_INPUT`, with a message that names the
entry.

<b>Relation to `QuadraticProgramTraits`.</b> CGAL's Solver_interface concept
`QuadraticProgramTraits` (model: `CGAL::OSQP_quadratic_program_traits`) describes the general
problem \f$ \min \frac{1}{2}x^TPx + q^Tx + r \f$ subject to \f$ l \le Ax \le u \f$. This
concept is the case \f$ A = I \f$ with the same member names and the same objective, and
differs as follows: `resize(n)` instead of `resize(n, m)` and no `set_A()`, since the
constraints are the bounds of the variables; `set_P()`, `set_q()` and `set_r()` accumulate
(`QuadraticProgramTraits` overwrites, and its OSQP model also ignores `set_P(i, j, v)` with
`i > j`); a warm start; and `solve()` returns a report with a status, the number of
iterations and the KKT residual instead of a `bool`. Any model of `QuadraticProgramTraits` is
made a model of this concept by
`CGAL::Highlight_lines::Quadratic_program_traits_box_QP_adapter`, which passes the bounds as
the constraints \f$ l \le I x \le u \f$.

<b>Results.</b> `solve()` writes exactly \f$ n \f$ values whatever the status. With
`Box_QP_status::OPTIMAL`, they satisfy the bounds exactly and the KKT conditions within the
model's tolerance (the report's `relative_kkt_residual`); with `ITERATION_LIMIT`,
`NOT_CONVEX`, `UNBOUNDED` or `NUMERICAL_FAILURE` they are a point within the bounds (the best
one found); with `INFEASIBLE_BOUNDS` (some \f$ l_i > u_i \f$) or `INVALID_INPUT` they are NaN.
A model never throws for bad data and never loops forever: it stops at an iteration limit.

\cgalHasModel `CGAL::Highlight_lines::Active_set_box_QP_solver`
\cgalHasModel `CGAL::Highlight_lines::Quadratic_program_traits_box_QP_adapter`

\sa `QuadraticProgramTraits`
\sa `CGAL::Highlight_lines::Box_QP_report`
*/
class BoxConstrainedQuadraticProgramSolver
{
public:
  /// \name Memory
  /// @{

  /*!
  starts a new problem with `n` variables: \f$ P = 0 \f$, \f$ q = 0 \f$, \f$ r = 0 \f$,
  \f$ l_i = -\infty \f$, \f$ u_i = +\infty \f$, and no warm start.
  */
  void resize(std::size_t n);

  /// @}

  /// \name Initialization
  /// @{

  /*!
  if `i <= j`, adds `value` to the entries \f$ P_{ij} \f$ and \f$ P_{ji} \f$ (to
  \f$ P_{ii} \f$ once if `i == j`); does nothing if `i > j`.
  */
  void set_P(std::size_t i, std::size_t j, double value);

  /*!
  adds `value` to the entry \f$ q_i \f$.
  */
  void set_q(std::size_t i, double value);

  /*!
  adds `value` to the constant \f$ r \f$.
  */
  void set_r(double value);

  /*!
  sets the lower bound \f$ l_i \f$ to `value`, a finite number or
  `-std::numeric_limits<double>::infinity()`.
  */
  void set_l(std::size_t i, double value);

  /*!
  sets the upper bound \f$ u_i \f$ to `value`, a finite number or
  `std::numeric_limits<double>::infinity()`.
  */
  void set_u(std::size_t i, double value);

  /*!
  passes a starting point with \f$ n \f$ entries to the next call of `solve()` (and to that
  call only; a warm start of the wrong size makes it report `INVALID_INPUT`). Its entries
  lying on or beyond a finite bound give the initial active set, the others are initial
  values. To restart from the active set of a previous solve alone, put \f$ l_i \f$ or
  \f$ u_i \f$ in the entries of the variables that were at their lower or upper bound, and
  any value strictly between the bounds (e.g. NaN, which counts as between) elsewhere. A
  model may ignore the warm start (the adapter does), but not its size check.
  */
  void set_warm_start(const std::vector<double>& x0);

  /// @}

  /// \name Operations
  /// @{

  /*!
  solves the problem, writes the \f$ n \f$ values of \f$ \mathbf{x} \f$ to `x_out` (see
  above for what they are, depending on the status), and returns the report. The problem is
  kept, so `solve()` may be called again.

  \tparam OutputIterator an output iterator accepting `double`.
  */
  template <class OutputIterator>
  CGAL::Highlight_lines::Box_QP_report solve(OutputIterator x_out);

  /// @}
};

// Plugging a quadratic program solver into fair_with_highlight_lines(), and watching the
// iterations: the solver is any model of the BoxConstrainedQuadraticProgramSolver concept,
// passed by reference with the qp_solver named parameter. Here, the built-in active-set solver
// with a looser tolerance wrapped in a small model that counts and times its solves; any other
// model (e.g. Quadratic_program_traits_box_QP_adapter around a CGAL QuadraticProgramTraits
// model such as OSQP's) is plugged in the same way.
//
//   fairing_with_own_solver
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Highlight_lines/Active_set_box_QP_solver.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/fair_with_highlight_lines.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;

// A model of BoxConstrainedQuadraticProgramSolver: forwards to the built-in solver, and keeps
// statistics of the solves.
class Timed_solver
{
public:
  Timed_solver() { inner_.set_tolerance(1e-8); } // enough for a fairing step

  void resize(std::size_t n) { inner_.resize(n); }
  void set_P(std::size_t i, std::size_t j, double v) { inner_.set_P(i, j, v); }
  void set_q(std::size_t i, double v) { inner_.set_q(i, v); }
  void set_r(double v) { inner_.set_r(v); }
  void set_l(std::size_t i, double v) { inner_.set_l(i, v); }
  void set_u(std::size_t i, double v) { inner_.set_u(i, v); }
  void set_warm_start(const std::vector<double>& x0) { inner_.set_warm_start(x0); }

  template <typename OutputIterator>
  HL::Box_QP_report solve(OutputIterator out)
  {
    const auto start = std::chrono::steady_clock::now();
    HL::Box_QP_report report = inner_.solve(out);
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++solves_;
    return report;
  }

  std::size_t solves() const { return solves_; }
  double seconds() const { return seconds_; }

private:
  HL::Active_set_box_QP_solver inner_;
  std::size_t solves_ = 0;
  double seconds_ = 0;
};

int main()
{
  // A gently curved panel, 60 x 60 cells, with a small bump in the middle.
  Mesh mesh;
  const int n = 60;
  std::vector<Mesh::Vertex_index> v;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = -1 + 2.0 * i / n, y = -1 + 2.0 * j / n, r2 = (x * x + y * y) / 0.09;
      const double bump = r2 < 1 ? 0.01 * (1 - r2) * (1 - r2) * (1 - r2) : 0.0;
      v.push_back(mesh.add_vertex(K::Point_3(x, y, 0.2 * (1 - 0.3 * x * x) - 0.1 * y * y + bump)));
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const auto a = v[j * (n + 1) + i], b = v[j * (n + 1) + i + 1],
                 c = v[(j + 1) * (n + 1) + i + 1], d = v[(j + 1) * (n + 1) + i];
      mesh.add_face(a, b, c);
      mesh.add_face(a, c, d);
    }
  // The region: faces within 0.45 of the centre.
  std::vector<Mesh::Face_index> region;
  for (auto f : faces(mesh)) {
    bool inside = true;
    for (auto w : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      inside = inside &&
               CGAL::squared_distance(mesh.point(w), K::Point_3(0, 0, mesh.point(w).z())) < 0.2;
    if (inside)
      region.push_back(f);
  }
  const HL::Light_setup<K> lights(K::Point_3(0, 0, 3), K::Vector_3(1, 0, 0), K::Vector_3(0, 0, 1),
                                  0.05);

  Timed_solver solver;
  auto show = [](const HL::Fairing_report::Iteration& it) {
    std::cout << "  F = " << it.target_value
              << "  max |x| / mean edge = " << it.relative_max_displacement
              << "  solver: " << HL::to_string(it.solver.status) << " in " << it.solver.iterations
              << " iterations\n";
    return true; // false would stop the fairing here
  };
  const HL::Fairing_report report = CGAL::fair_with_highlight_lines(
      mesh, region, lights,
      HLP::combine(HLP::qp_solver(std::ref(solver)), HLP::fairing_visitor(show),
                   HLP::convergence_threshold(1e-3), CGAL::parameters::number_of_iterations(30)));
  std::cout << (report.converged() ? "converged" : "did not converge") << " after "
            << report.iterations << " iterations; " << solver.solves() << " QP solves took "
            << solver.seconds() << " s\n";
  return report.converged() && solver.solves() == report.iterations ? 0 : 1;
}

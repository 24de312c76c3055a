// Plugging a quadratic program solver into fair_with_highlight_lines() (any model of the
// BoxConstrainedQuadraticProgramSolver concept, passed by reference with the qp_solver named
// parameter), and watching the iterations. Here the built-in active-set solver, with a looser
// tolerance, in a small model that counts its solves; Quadratic_program_traits_box_QP_adapter
// plugs in a CGAL QuadraticProgramTraits model (e.g. OSQP's) the same way.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Highlight_lines/Active_set_box_QP_solver.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/fair_with_highlight_lines.h>

#include <functional>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;

// A model of BoxConstrainedQuadraticProgramSolver: forwards to the built-in solver and counts.
class Counting_solver
{
public:
  Counting_solver() { inner_.set_tolerance(1e-8); } // enough for a fairing step
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
    ++solves;
    return inner_.solve(out);
  }
  std::size_t solves = 0;

private:
  HL::Active_set_box_QP_solver inner_;
};

int main()
{
  // A gently curved panel over [-1, 1]^2, 60 x 60 cells, with a small bump in the middle; the
  // region is the faces within 0.45 of the middle.
  auto panel = [](std::size_t i, std::size_t j) {
    const double x = -1 + i / 30.0, y = -1 + j / 30.0, r = 1 - (x * x + y * y) / 0.09;
    return K::Point_3(x, y, 0.2 - 0.06 * x * x - 0.1 * y * y + (r > 0 ? 0.01 * r * r * r : 0));
  };
  Mesh mesh;
  CGAL::make_grid(60, 60, mesh, panel, true);
  std::vector<Mesh::Face_index> region;
  for (auto f : faces(mesh)) {
    bool inside = true;
    for (auto w : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      inside = inside && CGAL::square(mesh.point(w).x()) + CGAL::square(mesh.point(w).y()) < 0.2;
    if (inside)
      region.push_back(f);
  }
  const HL::Light_setup<K> lights(K::Point_3(0, 0, 3), K::Vector_3(1, 0, 0), K::Vector_3(0, 0, 1),
                                  0.05);
  Counting_solver solver;
  auto show = [](const HL::Fairing_report::Iteration& it) {
    std::cout << "  F = " << it.target_value
              << ", max |x| / mean edge = " << it.relative_max_displacement << ", solver "
              << HL::to_string(it.solver.status) << " in " << it.solver.iterations
              << " iterations\n";
    return true; // false would stop the fairing here
  };
  const HL::Fairing_report report = CGAL::fair_with_highlight_lines(
      mesh, region, lights,
      HLP::combine(HLP::qp_solver(std::ref(solver)), HLP::fairing_visitor(show),
                   HLP::convergence_threshold(1e-3), CGAL::parameters::number_of_iterations(30)));
  std::cout << (report.converged() ? "converged" : "did not converge") << " after "
            << report.iterations << " iterations and " << solver.solves << " QP solves\n";
  return report.converged() && solver.solves == report.iterations ? 0 : 1;
}

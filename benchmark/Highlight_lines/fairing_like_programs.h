// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef HIGHLIGHT_LINES_BENCHMARK_FAIRING_LIKE_PROGRAMS_H
#define HIGHLIGHT_LINES_BENCHMARK_FAIRING_LIKE_PROGRAMS_H

// The matrix and bounds of fairing-like quadratic programs (eq. 16 of the paper) on a synthetic
// disk patch, for benchmarks of the QP solver and of its factorisation:
//
//   Highlight_lines_benchmark::Fairing_like_patch patch(n);  // n interior vertices = variables
//   patch.Q      // symmetric positive definite, both triangles stored, compressed columns
//   patch.bound  // |x_i| <= bound_i
//
// Q is the cotangent bi-Laplacian  W^T M^-1 W  of the interior vertices of an irregular
// Delaunay disk patch (random points whose density varies threefold across the disk, the
// boundary ring fixed), plus a sum of rank-one terms  j j^T  whose supports are those of the
// highlight nodes of the fairing (the two ends of an edge crossing a level line and their
// one-rings), weighing about a third of the bi-Laplacian on the diagonal. It couples the
// vertices within two edges.
//
//   Fairing_like_patch patch(n, Fairing_like_patch::Fairness::CURVATURE_VARIATION);
//
// replaces the bi-Laplacian by a curvature-variation-like term, the fairing's default energy:
// the squared differences across the edges of the mean curvatures H = M^-1 L x (L over all the
// vertices, the boundary ring's x fixed at 0), each weighted by its edge's length. It couples
// the vertices within three edges, as the programs of fair_with_highlight_lines() do (about
// 1.7 times the entries of the bi-Laplacian's, and several times its factorisation's flops).
//
// Used by benchmark_qp_solver and benchmark_factorization (same seeds, same matrices).

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <random>
#include <utility>
#include <vector>

namespace Highlight_lines_benchmark {

namespace fairing_like_detail {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vertex_base = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using Delaunay =
    CGAL::Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<Vertex_base>>;
} // namespace fairing_like_detail

// The matrix and bounds of a fairing QP on a disk patch with n interior vertices.
struct Fairing_like_patch
{
  using Kernel = fairing_like_detail::Kernel;
  using Delaunay = fairing_like_detail::Delaunay;
  using Point = Kernel::Point_2;
  using Sparse_matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  Sparse_matrix Q;
  Eigen::VectorXd bound; // |x_i| <= bound_i
  std::vector<Point> position;

  enum class Fairness { BI_LAPLACIAN, CURVATURE_VARIATION };

  explicit Fairing_like_patch(int n, Fairness fairness = Fairness::BI_LAPLACIAN)
  {
    std::mt19937 random(20260101u + static_cast<unsigned>(n));
    std::uniform_real_distribution<double> uniform(0., 1.);
    std::vector<std::pair<Point, int>> points;
    const int ring = static_cast<int>(2. * std::sqrt(M_PI * n)) + 8;
    for (int k = 0; k < ring; ++k) {
      const double angle = 2. * M_PI * k / ring;
      points.emplace_back(Point(std::cos(angle), std::sin(angle)), n + k);
    }
    for (int k = 0; k < n;) {
      const double x = 2. * uniform(random) - 1., y = 2. * uniform(random) - 1.;
      // inside the disk, away from the ring, with a density 3x higher on one side
      if (x * x + y * y > 0.97 || uniform(random) > 0.35 + 0.325 * (1. + x))
        continue;
      points.emplace_back(Point(x, y), k++);
    }
    const Delaunay dt(points.begin(), points.end());
    const int all = n + ring;
    position.resize(all);
    for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
      position[v->info()] = v->point();

    // Cotangent Laplacian, barycentric areas, shortest edges, one-rings.
    std::vector<Eigen::Triplet<double>> laplacian;
    std::vector<double> area(all, 0.), shortest(all, 1e300);
    std::vector<std::vector<int>> ring_of(all);
    // The triangles and edges in an order of their vertex ids, not of the triangulation's
    // storage: the insertion order of the points (a spatial sort drawing from CGAL's default
    // random generator, which earlier patches of the same process advanced) would otherwise
    // change the order of the sums below, and with it the last bits of the program and the
    // solver's path on it (a benchmark's counts depended on which patches it made first).
    std::vector<std::array<int, 3>> triangles;
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      std::array<int, 3> t = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end()); // same orientation
      triangles.push_back(t);
    }
    std::sort(triangles.begin(), triangles.end());
    std::vector<std::pair<int, int>> edges;
    for (const auto& t : triangles)
      for (int e = 0; e < 3; ++e)
        edges.emplace_back(std::min(t[e], t[(e + 1) % 3]), std::max(t[e], t[(e + 1) % 3]));
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    for (const auto& id : triangles) {
      const double face_area =
          std::abs(CGAL::area(position[id[0]], position[id[1]], position[id[2]]));
      for (int e = 0; e < 3; ++e) {
        const int a = id[e], b = id[(e + 1) % 3], opposite = id[(e + 2) % 3];
        const auto u = position[a] - position[opposite], v = position[b] - position[opposite];
        const double cotangent = (u * v) / std::abs(u.x() * v.y() - u.y() * v.x());
        laplacian.emplace_back(a, b, -0.5 * cotangent);
        laplacian.emplace_back(b, a, -0.5 * cotangent);
        laplacian.emplace_back(a, a, 0.5 * cotangent);
        laplacian.emplace_back(b, b, 0.5 * cotangent);
        area[a] += face_area / 3.;
        const double length = std::sqrt(CGAL::squared_distance(position[a], position[b]));
        shortest[a] = std::min(shortest[a], length);
        shortest[b] = std::min(shortest[b], length);
        ring_of[a].push_back(b);
        ring_of[b].push_back(a);
      }
    }
    Sparse_matrix L(all, all);
    L.setFromTriplets(laplacian.begin(), laplacian.end());
    const Sparse_matrix W = L.topLeftCorner(n, n); // boundary ring fixed
    Eigen::VectorXd inverse_area(n);
    for (int i = 0; i < n; ++i)
      inverse_area[i] = 1. / area[i];
    Sparse_matrix fairness_term = Sparse_matrix(W.transpose()) * inverse_area.asDiagonal() * W;
    if (fairness == Fairness::CURVATURE_VARIATION) {
      // Rows: the edges; (H_a - H_b) sqrt(length) with H = M^-1 L restricted to the interior
      // columns (every vertex's mean curvature, the boundary ring's too).
      std::vector<Eigen::Triplet<double>> difference;
      for (std::size_t e = 0; e < edges.size(); ++e) {
        const auto [a, b] = edges[e];
        const double weight =
            std::sqrt(std::sqrt(CGAL::squared_distance(position[a], position[b])));
        difference.emplace_back(int(e), a, weight / area[a]);
        difference.emplace_back(int(e), b, -weight / area[b]);
      }
      Sparse_matrix D(int(edges.size()), all);
      D.setFromTriplets(difference.begin(), difference.end());
      const Sparse_matrix G = D * Sparse_matrix(L.leftCols(n));
      fairness_term = Sparse_matrix(G.transpose()) * G;
    }

    // Highlight nodes: edges crossing the level lines of a linear "distance" function.
    std::vector<Eigen::Triplet<double>> nodes;
    for (const auto& [a, b] : edges) {
      const auto level = [&](int v) {
        return std::floor(7. * position[v].x() + 3. * position[v].y());
      };
      if (level(a) == level(b))
        continue;
      std::vector<int> support{a, b};
      support.insert(support.end(), ring_of[a].begin(), ring_of[a].end());
      support.insert(support.end(), ring_of[b].begin(), ring_of[b].end());
      std::sort(support.begin(), support.end());
      support.erase(std::unique(support.begin(), support.end()), support.end());
      std::vector<std::pair<int, double>> j;
      for (int v : support)
        if (v < n)
          j.emplace_back(v, (v == a || v == b ? 1. : 0.3) * (uniform(random) - 0.3));
      for (const auto& p : j)
        for (const auto& q : j)
          nodes.emplace_back(p.first, q.first, p.second * q.second);
    }
    Sparse_matrix low_rank(n, n);
    low_rank.setFromTriplets(nodes.begin(), nodes.end());
    // The node term weighs about a third of the fairness term on the diagonal.
    const double weight =
        0.3 * fairness_term.diagonal().mean() / std::max(low_rank.diagonal().mean(), 1e-300);
    Q = fairness_term + weight * low_rank;
    Q.makeCompressed();
    bound.resize(n);
    for (int i = 0; i < n; ++i)
      bound[i] = 0.5 * shortest[i];
  }
};

} // namespace Highlight_lines_benchmark

#endif // HIGHLIGHT_LINES_BENCHMARK_FAIRING_LIKE_PROGRAMS_H

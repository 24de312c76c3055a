// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef HIGHLIGHT_LINES_BENCHMARK_SURFACE_DIFFUSION_FLOW_H
#define HIGHLIGHT_LINES_BENCHMARK_SURFACE_DIFFUSION_FLOW_H

// The comparison method of the paper's §4: the surface diffusion flow of Xu, Pan and Bajaj
// ("Discrete surface modelling using partial differential equations", CAGD 23, 2006),
//
//     ∂V/∂t = N · Δ_B H,
//
// restricted to a region R with G1 boundary conditions. It is a benchmark baseline, not part
// of the package.
//
// What moves, what is held. The same vertices as in fair_with_highlight_lines(): the *movable*
// vertices of R, i.e. the vertices all of whose faces are in R (and not on a mesh border)
// whose neighbours all have this property too. Everything else is held: the region border,
// its one-ring inside R, and the whole mesh outside. Positions on the border and normals
// there (through the held one-ring) are thus prescribed, the G1 boundary condition of Xu et
// al.; Δ_B H at a movable vertex reaches two rings out, so the held vertices also supply the
// curvature around the border.
//
// Discretisation (per vertex i, with its one-ring j ∈ u(i)):
// - N_i: eq. 3 of the highlight-line paper, the normalised area-weighted sum of face normals;
// - A_i: one third of the area of the triangles around V_i (eq. 7);
// - the cotangent operator (L f)_i = 1/(2 A_i) Σ_j (cot α_ij + cot β_ij)(f_i − f_j), so that
//   K_i = (L V)_i is the mean curvature normal (≈ 2 H N, as in willmore_energy.h) and
//   Δ_B f = −L f;
// - H_i = ½ N_i · K_i (positive where the surface bends away from N, e.g. on a sphere with
//   outward normals), and (Δ_B H)_i = −(L H)_i.
// On a height field z = f(x, y) with N = +z this is f_t = −½ Δ²f: a fourth-order diffusion
// that smooths and converges to Δ_B H = 0.
//
// Time stepping: linearly implicit (semi-implicit), as Xu et al. do. At step n the normals,
// areas and cotangent weights are frozen at the current mesh; the unknowns are the normal
// displacements u_i of the movable vertices, V_i^{n+1} = V_i^n + u_i N_i^n, and
//
//     u = τ Δ_B H(V^{n+1})  ⇔  (I + τ L B) u = −τ L H^n,
//
// where H^{n+1} = H^n + B u is exact for the frozen operator (B_jk = ½ N_j · ∂K_j/∂u_k). For the
// frozen operator this is implicit Euler, stable for any τ; the nonlinearity enters only
// through re-freezing at every step. The time step is τ = time_step_factor · R⁴ with
// R = sqrt(area(R)/π) the region's radius: the slowest mode of the clamped plate of radius R
// has eigenvalue ≈ 104/R⁴ for Δ² (≈ 52/R⁴ for our ½Δ²), so with the default factor 1 it
// decays by a factor of about 50 per step whatever the mesh resolution, and the flow reaches
// its steady state Δ_B H = 0 in three or four steps. (Measured on the benchmark's cases: every
// factor from 0.001 to 10 is stable and reaches the same steady state; factors below 0.1 need
// more steps, and below 0.01 the stopping rule fires before the steady state is reached.)
//
// Stopping rule: the one of fair_with_highlight_lines() (eq. 17), max |u_i| / ē < ε with ē the
// mean edge length of R, or an iteration bound.

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <CGAL/Highlight_lines/internal/vector3.h>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace Highlight_lines_benchmark {

struct Surface_diffusion_flow_options
{
  /// τ = time_step_factor · R⁴, R = sqrt(area(region) / π).
  double time_step_factor = 1;
  /// Stop when max |u_i| / ē < convergence_threshold (ē: mean edge length in the region).
  double convergence_threshold = 0.001;
  /// Iteration bound.
  std::size_t max_iterations = 100;
};

struct Surface_diffusion_flow_report
{
  std::size_t iterations = 0;
  bool converged = false;
  std::size_t number_of_movable_vertices = 0;
  double time_step = 0;
  /// max |u_i| / ē of each step.
  std::vector<double> relative_displacements;
};

namespace sdf_detail {

using namespace CGAL::Highlight_lines::internal::vector3;

// The part of the mesh the flow reads, in flat arrays with local vertex ids.
struct Local_patch
{
  std::vector<Vec3> position;                // per local vertex
  std::vector<std::array<int, 3>> triangles; // the faces around the curvature vertices
  std::vector<int> movable;                  // local ids; the variable of movable[k] is k
  std::vector<int> variable;                 // per local vertex: index in `movable` or -1
  // Curvature vertices J: the movable vertices and their one-rings, whose H changes when a
  // movable vertex moves. Each has its complete ring of faces in `triangles`.
  std::vector<int> curvature;
  std::vector<int> row;                        // per local vertex: index in `curvature` or -1
  std::vector<std::vector<int>> faces_of;      // per curvature vertex: its triangles
  std::vector<std::vector<int>> neighbours_of; // per curvature vertex: its one-ring (local ids)
};

// Frozen operator at the current positions (see the file comment).
struct Frozen_operator
{
  std::vector<Vec3> normal;                                 // per curvature vertex
  std::vector<std::vector<std::pair<int, double>>> weights; // (local id, c_ij) per row
  std::vector<double> mean_curvature;                       // H per curvature vertex
};

inline Frozen_operator freeze(const Local_patch& patch)
{
  const std::size_t nf = patch.triangles.size();
  std::vector<Vec3> face_cross(nf);
  std::vector<std::array<double, 3>> cotangent(nf); // at each corner
  for (std::size_t f = 0; f < nf; ++f) {
    const auto& t = patch.triangles[f];
    const Vec3* p[3] = {&patch.position[std::size_t(t[0])], &patch.position[std::size_t(t[1])],
                        &patch.position[std::size_t(t[2])]};
    face_cross[f] = cross(*p[1] - *p[0], *p[2] - *p[0]);
    const double double_area = std::sqrt(dot(face_cross[f], face_cross[f]));
    if (!(double_area > 0) || !std::isfinite(double_area))
      throw std::runtime_error("surface_diffusion_flow(): a degenerate triangle");
    for (int k = 0; k < 3; ++k)
      cotangent[f][std::size_t(k)] =
          dot(*p[(k + 1) % 3] - *p[k], *p[(k + 2) % 3] - *p[k]) / double_area;
  }

  Frozen_operator op;
  const std::size_t nj = patch.curvature.size();
  op.normal.resize(nj);
  op.weights.resize(nj);
  op.mean_curvature.resize(nj);
  for (std::size_t r = 0; r < nj; ++r) {
    const int i = patch.curvature[r];
    Vec3 n{0, 0, 0};
    double area = 0;
    std::vector<std::pair<int, double>>& w = op.weights[r];
    for (int j : patch.neighbours_of[r])
      w.emplace_back(j, 0.0);
    auto add = [&w](int j, double c) {
      for (auto& entry : w)
        if (entry.first == j) {
          entry.second += c;
          return;
        }
    };
    for (int f : patch.faces_of[r]) {
      const auto& t = patch.triangles[std::size_t(f)];
      for (int k = 0; k < 3; ++k)
        n[std::size_t(k)] += face_cross[std::size_t(f)][std::size_t(k)]; // eq. 3
      area += std::sqrt(dot(face_cross[std::size_t(f)], face_cross[std::size_t(f)])) / 6;
      const int c = t[0] == i ? 0 : t[1] == i ? 1 : 2;
      const int a = (c + 1) % 3, b = (c + 2) % 3;
      add(t[std::size_t(a)], cotangent[std::size_t(f)][std::size_t(b)]); // edge (i, a) faces b
      add(t[std::size_t(b)], cotangent[std::size_t(f)][std::size_t(a)]);
    }
    const double length = std::sqrt(dot(n, n));
    for (int k = 0; k < 3; ++k)
      op.normal[r][std::size_t(k)] = n[std::size_t(k)] / length;
    Vec3 K{0, 0, 0};
    for (auto& entry : w) {
      entry.second /= 2 * area;
      const Vec3 e = patch.position[std::size_t(i)] - patch.position[std::size_t(entry.first)];
      for (int k = 0; k < 3; ++k)
        K[std::size_t(k)] += entry.second * e[std::size_t(k)];
    }
    op.mean_curvature[r] = 0.5 * dot(op.normal[r], K);
  }
  return op;
}

} // namespace sdf_detail

/// The movable vertices of `region` as fair_with_highlight_lines() defines them: not on a mesh
/// border, all faces in the region, and every neighbour likewise.
template <typename TriangleMesh, typename FaceRange>
std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>
region_movable_vertices(const TriangleMesh& tm, const FaceRange& region)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  const std::set<face_descriptor> in(region.begin(), region.end());
  std::set<vertex_descriptor> candidates;
  for (face_descriptor f : in)
    for (vertex_descriptor v : vertices_around_face(halfedge(f, tm), tm))
      candidates.insert(v);
  std::map<vertex_descriptor, bool> inside_cache;
  auto inside = [&](vertex_descriptor v) {
    auto it = inside_cache.find(v);
    if (it != inside_cache.end())
      return it->second;
    bool result = true;
    for (face_descriptor f : faces_around_target(halfedge(v, tm), tm))
      result = result && f != boost::graph_traits<TriangleMesh>::null_face() && in.count(f) > 0;
    return inside_cache[v] = result;
  };
  std::vector<vertex_descriptor> movable;
  for (vertex_descriptor v : candidates) {
    bool ok = inside(v);
    for (vertex_descriptor w : vertices_around_target(halfedge(v, tm), tm))
      ok = ok && inside(w);
    if (ok)
      movable.push_back(v);
  }
  return movable;
}

/// Runs the surface diffusion flow on `region` of `tm` (see the file comment). Only the movable
/// vertices of the region are written, through the vertex point map.
template <typename TriangleMesh, typename FaceRange>
Surface_diffusion_flow_report
surface_diffusion_flow(TriangleMesh& tm, const FaceRange& region,
                       const Surface_diffusion_flow_options& options = {})
{
  using namespace sdf_detail;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type Point;
  auto vpm = get(CGAL::vertex_point, tm);

  Surface_diffusion_flow_report report;
  const std::vector<vertex_descriptor> movable = region_movable_vertices(tm, region);
  report.number_of_movable_vertices = movable.size();
  if (movable.empty())
    return report;

  // Local patch: movable vertices, their rings (curvature vertices), the rings' faces.
  Local_patch patch;
  std::map<vertex_descriptor, int> local;
  std::vector<vertex_descriptor> handle;
  auto local_id = [&](vertex_descriptor v) {
    auto it = local.find(v);
    if (it != local.end())
      return it->second;
    const int id = int(handle.size());
    local.emplace(v, id);
    handle.push_back(v);
    const Point& p = get(vpm, v);
    patch.position.push_back(
        {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
    return id;
  };
  for (vertex_descriptor v : movable)
    patch.movable.push_back(local_id(v));
  std::vector<vertex_descriptor> curvature_handles;
  {
    std::set<vertex_descriptor> seen;
    for (vertex_descriptor v : movable) {
      if (seen.insert(v).second)
        curvature_handles.push_back(v);
      for (vertex_descriptor w : vertices_around_target(halfedge(v, tm), tm))
        if (seen.insert(w).second)
          curvature_handles.push_back(w);
    }
  }
  std::map<face_descriptor, int> face_id;
  for (vertex_descriptor v : curvature_handles) {
    patch.curvature.push_back(local_id(v));
    patch.faces_of.emplace_back();
    patch.neighbours_of.emplace_back();
    for (face_descriptor f : faces_around_target(halfedge(v, tm), tm)) {
      auto it = face_id.find(f);
      if (it == face_id.end()) {
        std::array<int, 3> t{};
        int k = 0;
        for (vertex_descriptor w : vertices_around_face(halfedge(f, tm), tm)) {
          if (k == 3)
            throw std::runtime_error("surface_diffusion_flow(): a face is not a triangle");
          t[std::size_t(k++)] = local_id(w);
        }
        it = face_id.emplace(f, int(patch.triangles.size())).first;
        patch.triangles.push_back(t);
      }
      patch.faces_of.back().push_back(it->second);
    }
    for (vertex_descriptor w : vertices_around_target(halfedge(v, tm), tm))
      patch.neighbours_of.back().push_back(local_id(w));
  }
  const std::size_t nv = patch.position.size(), n = patch.movable.size(),
                    nj = patch.curvature.size();
  patch.variable.assign(nv, -1);
  for (std::size_t k = 0; k < n; ++k)
    patch.variable[std::size_t(patch.movable[k])] = int(k);
  patch.row.assign(nv, -1);
  for (std::size_t r = 0; r < nj; ++r)
    patch.row[std::size_t(patch.curvature[r])] = int(r);

  // Region scales: area (for τ) and mean edge length ē (for the stopping rule).
  double region_area = 0, edge_sum = 0;
  std::size_t edge_count = 0;
  for (face_descriptor f : region) {
    std::array<Vec3, 3> p;
    int k = 0;
    for (vertex_descriptor v : vertices_around_face(halfedge(f, tm), tm)) {
      const Point& q = get(vpm, v);
      p[std::size_t(k++ % 3)] = {CGAL::to_double(q.x()), CGAL::to_double(q.y()),
                                 CGAL::to_double(q.z())};
    }
    const Vec3 c = cross(p[1] - p[0], p[2] - p[0]);
    region_area += 0.5 * std::sqrt(dot(c, c));
    for (int e = 0; e < 3; ++e) { // every interior edge twice, border edges once: fine for a mean
      const Vec3 d = p[std::size_t((e + 1) % 3)] - p[std::size_t(e)];
      edge_sum += std::sqrt(dot(d, d));
      ++edge_count;
    }
  }
  const double mean_edge = edge_sum / double(edge_count);
  const double radius = std::sqrt(region_area / 3.14159265358979323846);
  const double tau = options.time_step_factor * radius * radius * radius * radius;
  report.time_step = tau;

  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  bool analysed = false;
  for (std::size_t iteration = 0; iteration < options.max_iterations; ++iteration) {
    const Frozen_operator op = freeze(patch);

    // B (nj x n): H^{n+1}_j = H^n_j + Σ_k B_jk u_k, from K_j = Σ_l c_jl (V_j − V_l).
    std::vector<Eigen::Triplet<double>> b_entries;
    for (std::size_t r = 0; r < nj; ++r) {
      const int j = patch.curvature[r];
      const int vj = patch.variable[std::size_t(j)];
      for (const auto& [l, c] : op.weights[r]) {
        if (vj >= 0) // ∂K_j/∂u_j = c_jl N_j, and N_j · N_j = 1
          b_entries.emplace_back(Eigen::Index(r), vj, 0.5 * c);
        const int vl = patch.variable[std::size_t(l)];
        if (vl >= 0) // ∂K_j/∂u_l = −c_jl N_l
          b_entries.emplace_back(
              Eigen::Index(r), vl,
              -0.5 * c * dot(op.normal[r], op.normal[std::size_t(patch.row[std::size_t(l)])]));
      }
    }
    Eigen::SparseMatrix<double> B{Eigen::Index(nj), Eigen::Index(n)};
    B.setFromTriplets(b_entries.begin(), b_entries.end());

    // L restricted to the movable rows (n x nj): (L f)_i = Σ_j c_ij (f_i − f_j).
    std::vector<Eigen::Triplet<double>> l_entries;
    Eigen::VectorXd H = Eigen::VectorXd::Zero(Eigen::Index(nj));
    for (std::size_t r = 0; r < nj; ++r)
      H[Eigen::Index(r)] = op.mean_curvature[r];
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t r = std::size_t(patch.row[std::size_t(patch.movable[k])]);
      for (const auto& [l, c] : op.weights[r]) {
        l_entries.emplace_back(Eigen::Index(k), Eigen::Index(r), c);
        l_entries.emplace_back(Eigen::Index(k), Eigen::Index(patch.row[std::size_t(l)]), -c);
      }
    }
    Eigen::SparseMatrix<double> L{Eigen::Index(n), Eigen::Index(nj)};
    L.setFromTriplets(l_entries.begin(), l_entries.end());

    Eigen::SparseMatrix<double> I{Eigen::Index(n), Eigen::Index(n)};
    I.setIdentity();
    const Eigen::SparseMatrix<double> A = I + tau * (L * B);
    const Eigen::VectorXd rhs = -tau * (L * H);
    if (!analysed) {
      lu.analyzePattern(A);
      analysed = true;
    }
    lu.factorize(A);
    if (lu.info() != Eigen::Success)
      throw std::runtime_error("surface_diffusion_flow(): the linear system is singular");
    const Eigen::VectorXd u = lu.solve(rhs);

    double largest = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double uk = u[Eigen::Index(k)];
      if (!std::isfinite(uk))
        throw std::runtime_error("surface_diffusion_flow(): the step is not finite");
      const int v = patch.movable[k];
      const Vec3& normal = op.normal[std::size_t(patch.row[std::size_t(v)])];
      for (int c = 0; c < 3; ++c)
        patch.position[std::size_t(v)][std::size_t(c)] += uk * normal[std::size_t(c)];
      largest = (std::max)(largest, std::abs(uk));
    }
    report.relative_displacements.push_back(largest / mean_edge);
    report.iterations = iteration + 1;
    if (largest / mean_edge < options.convergence_threshold) {
      report.converged = true;
      break;
    }
  }

  for (std::size_t k = 0; k < n; ++k) {
    const Vec3& p = patch.position[std::size_t(patch.movable[k])];
    put(vpm, handle[std::size_t(patch.movable[k])], Point(p[0], p[1], p[2]));
  }
  return report;
}

} // namespace Highlight_lines_benchmark

#endif // HIGHLIGHT_LINES_BENCHMARK_SURFACE_DIFFUSION_FLOW_H

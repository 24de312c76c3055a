// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_NODE_JACOBIAN_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_NODE_JACOBIAN_H

#include <CGAL/Highlight_lines/internal/Local_mesh.h>
#include <CGAL/Highlight_lines/internal/fairing/fairing_region.h>
#include <CGAL/Highlight_lines/internal/model/highlight_nodes.h>
#include <CGAL/Highlight_lines/internal/model/vertex_normals.h>

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include <CGAL/Highlight_lines/internal/vector3.h>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// Derivatives of node positions with respect to the normal displacements x_k of the movable
// vertices (V_k -> V_k + x_k N_k), for the Gauss–Newton form of q_diff,
// sum_i l_i |Q_i + J_i x - Q~_i|^2, which is convex (see internal/fairing/difference_energy.h).
//
// A node on edge (V1, V2) at level m sits at Q = V1 + t (V2 - V1), t = (m s - d1)/(d2 - d1)
// (eq. 13). d of a vertex (eq. 1) depends on its position and, through Ñ (eq. 3), on its
// one-ring, so x_k moves Q when k is V1, V2 or a neighbour of either.
//
// It reads the local mesh and the normals it was made with (valid while they do not change)
// and caches the distance gradients: one object per iteration, used by one thread.
class Node_jacobian
{
public:
  typedef std::vector<std::pair<int, Vec3>> Row;            // (variable, dQ/dx_variable)
  typedef std::vector<std::pair<int, double>> Distance_row; // (variable, dd/dx_variable)

  template <typename TriangleMesh>
  Node_jacobian(const Local_mesh<TriangleMesh>& lm, const Fairing_region& region,
                const Vertex_normals& vn, const std::vector<Vec3>& directions, const Vec3& a,
                const Vec3& h, const Vec3& z)
      : region_(region), directions_(directions), a_(a), h_(h), z_(z), xyz_(lm.xyz.data()),
        normals_(vn.normal.data()), face_vertices_(lm.face_vertices.data()),
        gradients_(lm.xyz.size() / 3), has_gradient_(lm.xyz.size() / 3, 0)
  {
  }

  // d(d_v)/dx_k for every variable k that moves d_v; computed once per vertex (the nodes on
  // the edges around a vertex share it).
  const Distance_row& distance_gradient(int v) const
  {
    if (!has_gradient_[std::size_t(v)]) {
      compute_distance_gradient(v, gradients_[std::size_t(v)]);
      has_gradient_[std::size_t(v)] = 1;
    }
    return gradients_[std::size_t(v)];
  }

  // dQ/dx for a node; `levels` gives the current d values, s the spacing.
  Row node_row(const Raw_node& node, const std::vector<std::array<int, 2>>& edge_vertices,
               const std::vector<Vertex_level>& levels, double s) const
  {
    Row row;
    node_row(node, edge_vertices, levels, s, row);
    return row;
  }

  // The same into `row` (cleared first), which keeps its storage from one node to the next.
  void node_row(const Raw_node& node, const std::vector<std::array<int, 2>>& edge_vertices,
                const std::vector<Vertex_level>& levels, double s, Row& row) const
  {
    row.clear();
    auto add = [&row](int var, const Vec3& d) { add_to_row(row, var, d); };
    if (node.vertex >= 0) { // eq. 13 for a node on a vertex: the vertex's new position
      const int var = region_.variable[std::size_t(node.vertex)];
      if (var >= 0)
        add(var, directions_[std::size_t(var)]);
      return;
    }
    const int va = edge_vertices[std::size_t(node.edge)][0],
              vb = edge_vertices[std::size_t(node.edge)][1];
    const double da = levels[std::size_t(va)].distance, db = levels[std::size_t(vb)].distance;
    const double D = db - da;
    if (D == 0)
      return;
    const double t = (double(node.level) * s - da) / D;
    const Vec3 pa = point(va), pb = point(vb);
    const Vec3 edge{pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
    for (int end = 0; end < 2; ++end) {
      const int v = end == 0 ? va : vb;
      const int var = region_.variable[std::size_t(v)];
      const double weight = end == 0 ? 1 - t : t; // dQ/dV
      if (var >= 0) {
        const Vec3& u = directions_[std::size_t(var)];
        add(var, {weight * u[0], weight * u[1], weight * u[2]});
      }
      const double dt_dd = end == 0 ? (t - 1) / D : -t / D; // dt/d(d_end)
      for (const auto& g : distance_gradient(v)) {
        const double f = dt_dd * g.second;
        add(g.first, {f * edge[0], f * edge[1], f * edge[2]});
      }
    }
  }

private:
  // Adds d to the entry of variable var, appending one if there is none yet.
  static void add_to_row(Row& row, int var, const Vec3& d)
  {
    auto it = std::find_if(row.begin(), row.end(), [var](const auto& e) { return e.first == var; });
    if (it == row.end())
      row.emplace_back(var, d);
    else
      for (int k = 0; k < 3; ++k)
        it->second[std::size_t(k)] += d[std::size_t(k)];
  }

  Vec3 point(int v) const
  {
    const double* p = xyz_ + 3 * std::size_t(v);
    return {p[0], p[1], p[2]};
  }
  Vec3 normal(int v) const
  {
    const double* n = normals_ + 3 * std::size_t(v);
    return {n[0], n[1], n[2]};
  }

  void compute_distance_gradient(int v, Distance_row& result) const
  {
    // dÑ/dx_k = sum over faces around v containing k of N_k x (p_next(k) - p_prev(k)).
    Row& dn = normal_gradient_;
    dn.clear();
    for (int i = region_.vertex_face_begin[std::size_t(v)];
         i < region_.vertex_face_begin[std::size_t(v) + 1]; ++i) {
      const std::array<int, 3>& c =
          face_vertices_[std::size_t(region_.vertex_faces[std::size_t(i)])];
      for (int j = 0; j < 3; ++j) {
        const int var = region_.variable[std::size_t(c[std::size_t(j)])];
        if (var < 0)
          continue;
        const Vec3 p_next = point(c[std::size_t((j + 1) % 3)]),
                   p_prev = point(c[std::size_t((j + 2) % 3)]);
        const Vec3 d =
            vector3::cross(directions_[std::size_t(var)],
                           {p_next[0] - p_prev[0], p_next[1] - p_prev[1], p_next[2] - p_prev[2]});
        add_to_row(dn, var, d);
      }
    }
    const Vec3 p = point(v), n = normal(v);
    const Vec3 x = vector3::cross({p[0] - a_[0], p[1] - a_[1], p[2] - a_[2]}, h_);
    const double num = vector3::dot(x, n), den = vector3::dot(z_, n);
    result.clear();
    result.reserve(dn.size() + 1);
    const int own = region_.variable[std::size_t(v)];
    for (const auto& e : dn) {
      double dnum = vector3::dot(x, e.second);
      if (e.first == own)
        dnum += vector3::dot(vector3::cross(directions_[std::size_t(own)], h_), n);
      const double dden = vector3::dot(z_, e.second);
      result.emplace_back(e.first, (dnum * den - num * dden) / (den * den));
    }
    if (own >= 0 && dn.empty()) // a vertex moved without any face around: only its position
      result.emplace_back(own,
                          vector3::dot(vector3::cross(directions_[std::size_t(own)], h_), n) / den);
  }

  const Fairing_region& region_;
  std::vector<Vec3> directions_; // a copy: callers may pass a temporary
  Vec3 a_, h_, z_;
  const double* xyz_; // the local mesh's points and Ñ, 3 per vertex
  const double* normals_;
  const std::array<int, 3>* face_vertices_;
  mutable std::vector<Distance_row> gradients_;
  mutable std::vector<char> has_gradient_;
  mutable Row normal_gradient_; // compute_distance_gradient()'s work space
};

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_NODE_JACOBIAN_H

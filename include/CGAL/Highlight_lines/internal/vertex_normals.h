// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_VERTEX_NORMALS_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_VERTEX_NORMALS_H

#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/Highlight_lines/internal/Local_mesh.h>

#include <CGAL/Number_types/internal/Exact_type_selector.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// Unit round-off of double, doubled: every error bound below counts 2u per operation on the
// longest path of the expression, which also absorbs the rounding of the magnitudes.
constexpr double error_per_operation = 2.0 * 1.1102230246251565e-16;

// Eq. 3 of the paper: the vertex normal is the area-weighted sum of the unit face normals,
// i.e. the sum of the face cross products (p1-p0) x (p2-p0), normalised. The unnormalised
// sum Ñ is kept: the highlight distance d does not depend on its length, so d stays a
// rational function of the coordinates, which the exact level classification relies on.
//
// Alongside each computed quantity x we keep a magnitude m(x) (the same expression evaluated
// on absolute values) so that |x - exact(x)| <= depth * error_per_operation * m(x).
struct Vertex_normals
{
  std::vector<double> normal, normal_magnitude; // Ñ and its magnitude, 3 per model vertex
  std::vector<int> valence;                     // number of incident faces

  std::array<double, 3> unit_normal(int v) const
  {
    const double* n = &normal[3 * std::size_t(v)];
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0))
      return {0, 0, 0};
    return {n[0] / len, n[1] / len, n[2] / len};
  }
};

// The cross product of face f in the number type NT (exact or interval).
template <typename NT, typename TriangleMesh>
std::array<NT, 3> face_cross_product(const Local_mesh<TriangleMesh>& lm, std::size_t f)
{
  const double* p0 = lm.point(lm.face_vertices[f][0]);
  const double* p1 = lm.point(lm.face_vertices[f][1]);
  const double* p2 = lm.point(lm.face_vertices[f][2]);
  const NT a[3] = {NT(p1[0]) - NT(p0[0]), NT(p1[1]) - NT(p0[1]), NT(p1[2]) - NT(p0[2])};
  const NT b[3] = {NT(p2[0]) - NT(p0[0]), NT(p2[1]) - NT(p0[1]), NT(p2[2]) - NT(p0[2])};
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Ñ of model vertex v in the number type NT, from the one-ring points.
template <typename NT, typename TriangleMesh>
std::array<NT, 3> unnormalized_vertex_normal(const Local_mesh<TriangleMesh>& lm, int v)
{
  std::array<NT, 3> n = {NT(0), NT(0), NT(0)};
  lm.for_each_face_around(v, [&](int f) {
    const auto c = face_cross_product<NT>(lm, std::size_t(f));
    for (int k = 0; k < 3; ++k)
      n[std::size_t(k)] = n[std::size_t(k)] + c[std::size_t(k)];
  });
  return n;
}

template <typename TriangleMesh>
[[noreturn]] void throw_degenerate_face(const Local_mesh<TriangleMesh>& lm, std::size_t f)
{
  throw Invalid_input(Invalid_input::Problem::DEGENERATE_FACE,
                      "face " + std::to_string(lm.face_indices[f]) +
                          " is degenerate (its three vertices are collinear); remove it first, "
                          "e.g. with CGAL::Polygon_mesh_processing::remove_degenerate_faces()",
                      lm.face_indices[f]);
}

// Sums the face cross products into the model vertices, in the summation order of the local
// mesh, and checks exactly that no model face is degenerate (throws Invalid_input).
template <typename TriangleMesh>
void compute_vertex_normals(const Local_mesh<TriangleMesh>& lm, Vertex_normals& vn)
{
  typedef typename CGAL::internal::Exact_ring_selector<double>::Type Exact;
  const std::size_t nv = lm.number_of_model_vertices, nf = lm.face_vertices.size();
  vn.normal.assign(3 * nv, 0.0);
  vn.normal_magnitude.assign(3 * nv, 0.0);
  vn.valence.assign(nv, 0);
  const bool local_order = lm.face_summation_order.empty();
  for (std::size_t i = 0; i < nf; ++i) {
    const std::size_t f = local_order ? i : std::size_t(lm.face_summation_order[i]);
    const std::array<int, 3>& corners = lm.face_vertices[f];
    const double* p0 = lm.point(corners[0]);
    const double* p1 = lm.point(corners[1]);
    const double* p2 = lm.point(corners[2]);
    const double a[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
    const double b[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
    const double am[3] = {std::abs(p1[0]) + std::abs(p0[0]), std::abs(p1[1]) + std::abs(p0[1]),
                          std::abs(p1[2]) + std::abs(p0[2])};
    const double bm[3] = {std::abs(p2[0]) + std::abs(p0[0]), std::abs(p2[1]) + std::abs(p0[1]),
                          std::abs(p2[2]) + std::abs(p0[2])};
    const double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                         a[0] * b[1] - a[1] * b[0]};
    const double cm[3] = {am[1] * bm[2] + am[2] * bm[1], am[2] * bm[0] + am[0] * bm[2],
                          am[0] * bm[1] + am[1] * bm[0]};
    if (f < lm.number_of_model_faces) {
      bool certainly_non_zero = false;
      for (int k = 0; k < 3 && !certainly_non_zero; ++k)
        certainly_non_zero = std::abs(c[k]) > 4 * error_per_operation * cm[k];
      if (!certainly_non_zero) {
        const auto exact = face_cross_product<Exact>(lm, f);
        if (CGAL::is_zero(exact[0]) && CGAL::is_zero(exact[1]) && CGAL::is_zero(exact[2]))
          throw_degenerate_face(lm, f);
      }
    }
    for (int v : corners) {
      if (std::size_t(v) >= nv)
        continue;
      double* n = &vn.normal[3 * std::size_t(v)];
      double* nm = &vn.normal_magnitude[3 * std::size_t(v)];
      for (int k = 0; k < 3; ++k) {
        n[k] += c[k];
        nm[k] += cm[k];
      }
      ++vn.valence[std::size_t(v)];
    }
  }
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_VERTEX_NORMALS_H

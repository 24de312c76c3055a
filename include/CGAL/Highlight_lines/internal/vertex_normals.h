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
  std::vector<double> face_cross, face_cross_magnitude; // 3 per local face
  std::vector<double> normal, normal_magnitude;         // Ñ, 3 per model vertex
  std::vector<int> valence;                             // number of incident faces

  std::array<double, 3> unit_normal(int v) const
  {
    const double* n = &normal[3 * std::size_t(v)];
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0))
      return {0, 0, 0};
    return {n[0] / len, n[1] / len, n[2] / len};
  }
};

template <typename TriangleMesh>
void compute_face_cross_products(const Local_mesh<TriangleMesh>& lm, Vertex_normals& vn)
{
  const std::size_t nf = lm.face_vertices.size();
  vn.face_cross.resize(3 * nf);
  vn.face_cross_magnitude.resize(3 * nf);
  for (std::size_t f = 0; f < nf; ++f) {
    const double* p0 = lm.point(lm.face_vertices[f][0]);
    const double* p1 = lm.point(lm.face_vertices[f][1]);
    const double* p2 = lm.point(lm.face_vertices[f][2]);
    const double a[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
    const double b[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
    const double am[3] = {std::abs(p1[0]) + std::abs(p0[0]), std::abs(p1[1]) + std::abs(p0[1]),
                          std::abs(p1[2]) + std::abs(p0[2])};
    const double bm[3] = {std::abs(p2[0]) + std::abs(p0[0]), std::abs(p2[1]) + std::abs(p0[1]),
                          std::abs(p2[2]) + std::abs(p0[2])};
    double* c = &vn.face_cross[3 * f];
    double* cm = &vn.face_cross_magnitude[3 * f];
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
    cm[0] = am[1] * bm[2] + am[2] * bm[1];
    cm[1] = am[2] * bm[0] + am[0] * bm[2];
    cm[2] = am[0] * bm[1] + am[1] * bm[0];
  }
}

template <typename TriangleMesh>
void accumulate_vertex_normals(const Local_mesh<TriangleMesh>& lm, Vertex_normals& vn)
{
  const std::size_t nv = lm.number_of_model_vertices;
  vn.normal.assign(3 * nv, 0.0);
  vn.normal_magnitude.assign(3 * nv, 0.0);
  vn.valence.assign(nv, 0);
  for (std::size_t v = 0; v < nv; ++v) {
    double* n = &vn.normal[3 * v];
    double* nm = &vn.normal_magnitude[3 * v];
    for (int i = lm.vertex_face_begin[v]; i < lm.vertex_face_begin[v + 1]; ++i) {
      const std::size_t f = std::size_t(lm.vertex_faces[std::size_t(i)]);
      for (int k = 0; k < 3; ++k) {
        n[k] += vn.face_cross[3 * f + k];
        nm[k] += vn.face_cross_magnitude[3 * f + k];
      }
    }
    vn.valence[v] = lm.vertex_face_begin[v + 1] - lm.vertex_face_begin[v];
  }
}

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
  for (int i = lm.vertex_face_begin[std::size_t(v)]; i < lm.vertex_face_begin[std::size_t(v) + 1];
       ++i) {
    const auto c = face_cross_product<NT>(lm, std::size_t(lm.vertex_faces[std::size_t(i)]));
    for (int k = 0; k < 3; ++k)
      n[k] = n[k] + c[k];
  }
  return n;
}

// Throws Invalid_input for a model face whose three corners are collinear (decided exactly).
template <typename TriangleMesh>
void check_model_faces_not_degenerate(const Local_mesh<TriangleMesh>& lm, const Vertex_normals& vn)
{
  typedef typename CGAL::internal::Exact_ring_selector<double>::Type Exact;
  for (std::size_t f = 0; f < lm.number_of_model_faces; ++f) {
    bool certainly_non_zero = false;
    for (int k = 0; k < 3 && !certainly_non_zero; ++k)
      certainly_non_zero = std::abs(vn.face_cross[3 * f + k]) >
                           4 * error_per_operation * vn.face_cross_magnitude[3 * f + k];
    if (certainly_non_zero)
      continue;
    const auto c = face_cross_product<Exact>(lm, f);
    if (CGAL::is_zero(c[0]) && CGAL::is_zero(c[1]) && CGAL::is_zero(c[2]))
      throw Invalid_input(Invalid_input::Problem::DEGENERATE_FACE,
                          "face " + std::to_string(lm.face_indices[f]) +
                              " is degenerate (its three vertices are collinear); remove it "
                              "first, e.g. with CGAL::Polygon_mesh_processing::"
                              "remove_degenerate_faces()",
                          lm.face_indices[f]);
  }
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_VERTEX_NORMALS_H

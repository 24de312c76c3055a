// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_MODEL_VERTEX_NORMALS_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_MODEL_VERTEX_NORMALS_H

#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/Highlight_lines/internal/Local_mesh.h>
#include <CGAL/Highlight_lines/internal/parallel.h>

#include <CGAL/Number_types/internal/Exact_type_selector.h>

#include <algorithm>
#include <array>
#include <limits>
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
  // Per model vertex, the factor of the classification's error bounds (a bound on the error
  // of a dot product of Ñ with a vector w, see Level_classifier):
  //   (valence + 16) * error_per_operation * max_k m(Ñ)_k,
  // NaN where the magnitudes are so small (subnormal cross products) that the relative bound
  // does not cover the absolute errors: the classification then always takes the exact path.
  std::vector<double> bound;

  std::array<double, 3> unit_normal(int v) const
  {
    const double* n = &normal[3 * std::size_t(v)];
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0))
      return {0, 0, 0};
    return {n[0] / len, n[1] / len, n[2] / len};
  }
};

// See Vertex_normals::bound.
template <typename ConcurrencyTag = CGAL::Sequential_tag>
void compute_classification_bounds(Vertex_normals& vn)
{
  const std::size_t nv = vn.valence.size();
  vn.bound.resize(nv);
  for_each_chunk<ConcurrencyTag>(chunks_for<ConcurrencyTag>(nv, std::size_t(1) << 14),
                                 [&](std::size_t, std::size_t b, std::size_t e) {
                                   for (std::size_t v = b; v < e; ++v) {
                                     const double* nm = &vn.normal_magnitude[3 * v];
                                     vn.bound[v] = nm[0] + nm[1] + nm[2] > 1e-280
                                                       ? double(vn.valence[v] + 16) *
                                                             error_per_operation *
                                                             (std::max)({nm[0], nm[1], nm[2]})
                                                       : std::numeric_limits<double>::quiet_NaN();
                                   }
                                 });
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

// The cross product of a face in double, with its magnitude (see Vertex_normals).
struct Face_cross_product
{
  double c[3], cm[3];
};

template <typename TriangleMesh>
void double_face_cross_product(const Local_mesh<TriangleMesh>& lm, std::size_t f,
                               Face_cross_product& out)
{
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
  out.c[0] = a[1] * b[2] - a[2] * b[1];
  out.c[1] = a[2] * b[0] - a[0] * b[2];
  out.c[2] = a[0] * b[1] - a[1] * b[0];
  out.cm[0] = am[1] * bm[2] + am[2] * bm[1];
  out.cm[1] = am[2] * bm[0] + am[0] * bm[2];
  out.cm[2] = am[0] * bm[1] + am[1] * bm[0];
}

// Whether model face f is degenerate, decided exactly (filtered).
template <typename TriangleMesh>
bool is_degenerate_face(const Local_mesh<TriangleMesh>& lm, std::size_t f,
                        const Face_cross_product& x)
{
  typedef typename CGAL::internal::Exact_ring_selector<double>::Type Exact;
  for (int k = 0; k < 3; ++k)
    if (std::abs(x.c[k]) > 4 * error_per_operation * x.cm[k])
      return false;
  const auto exact = face_cross_product<Exact>(lm, f);
  return CGAL::is_zero(exact[0]) && CGAL::is_zero(exact[1]) && CGAL::is_zero(exact[2]);
}

// Sums the face cross products into the model vertices, in the summation order of the local
// mesh, and checks exactly that no model face is degenerate (throws Invalid_input for the
// first one in summation order). With a parallel tag the cross products and checks of blocks
// of faces are computed concurrently; their sums into the vertices stay sequential, in the
// same order: the normals are bit for bit those of the sequential computation.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh>
void compute_vertex_normals(const Local_mesh<TriangleMesh>& lm, Vertex_normals& vn)
{
  const std::size_t nv = lm.number_of_model_vertices, nf = lm.face_vertices.size();
  vn.normal.assign(3 * nv, 0.0);
  vn.normal_magnitude.assign(3 * nv, 0.0);
  vn.valence.assign(nv, 0);
  const bool local_order = lm.face_summation_order.empty();
  auto face_at = [&](std::size_t i) {
    return local_order ? i : std::size_t(lm.face_summation_order[i]);
  };
  auto accumulate = [&](std::size_t f, const Face_cross_product& x) {
    for (int v : lm.face_vertices[f]) {
      if (std::size_t(v) >= nv)
        continue;
      double* n = &vn.normal[3 * std::size_t(v)];
      double* nm = &vn.normal_magnitude[3 * std::size_t(v)];
      for (int k = 0; k < 3; ++k) {
        n[k] += x.c[k];
        nm[k] += x.cm[k];
      }
      ++vn.valence[std::size_t(v)];
    }
  };
  if constexpr (!Is_parallel<ConcurrencyTag>::value) {
    for (std::size_t i = 0; i < nf; ++i) {
      const std::size_t f = face_at(i);
      Face_cross_product x;
      double_face_cross_product(lm, f, x);
      if (f < lm.number_of_model_faces && is_degenerate_face(lm, f, x))
        throw_degenerate_face(lm, f);
      accumulate(f, x);
    }
  } else {
    // Blocks of faces small enough for the cache: cross products concurrently, then summed.
    const std::size_t block = std::size_t(1) << 16, grain = std::size_t(1) << 12;
    std::vector<Face_cross_product> cross((std::min)(nf, block));
    std::vector<unsigned char> degenerate(cross.size());
    for (std::size_t first = 0; first < nf; first += block) {
      const std::size_t size = (std::min)(block, nf - first);
      for_each_chunk<ConcurrencyTag>(
          Chunks(size, grain), [&](std::size_t, std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e; ++i) {
              const std::size_t f = face_at(first + i);
              double_face_cross_product(lm, f, cross[i]);
              degenerate[i] = f < lm.number_of_model_faces && is_degenerate_face(lm, f, cross[i]);
            }
          });
      for (std::size_t i = 0; i < size; ++i) {
        if (degenerate[i])
          throw_degenerate_face(lm, face_at(first + i));
        accumulate(face_at(first + i), cross[i]);
      }
    }
  }
  compute_classification_bounds<ConcurrencyTag>(vn);
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_MODEL_VERTEX_NORMALS_H

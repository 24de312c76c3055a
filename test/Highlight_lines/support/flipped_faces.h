// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What "no triangle flipped" means for the fairing, as the tests and the fuzzer check it.
#ifndef HIGHLIGHT_LINES_TEST_FLIPPED_FACES_H
#define HIGHLIGHT_LINES_TEST_FLIPPED_FACES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <map>
#include <vector>

namespace test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3 Flip_vector;
typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Flip_mesh;

// (p1 - p0) x (p2 - p0) of a triangle of a Flip_mesh.
inline Flip_vector face_cross_product(const Flip_mesh& mesh, Flip_mesh::Face_index f)
{
  const auto h = mesh.halfedge(f);
  return CGAL::cross_product(mesh.point(mesh.target(h)) - mesh.point(mesh.source(h)),
                             mesh.point(mesh.target(mesh.next(h))) - mesh.point(mesh.source(h)));
}

// The fairing's guarantee against flips, checked on `after` against `before` (same
// connectivity): a triangle whose normal agrees with its corners' vertex normals (eq. 3: unit
// sums of the face cross products) keeps its orientation (its normal turns by less than a right
// angle); a triangle folded in `before` may unfold but must not degenerate. Returns the faces
// that break it.
inline std::vector<Flip_mesh::Face_index> flipped_faces(const Flip_mesh& before,
                                                        const Flip_mesh& after)
{
  std::map<Flip_mesh::Vertex_index, Flip_vector> normal;
  for (auto f : before.faces())
    for (auto v : CGAL::vertices_around_face(before.halfedge(f), before)) {
      auto it = normal.emplace(v, CGAL::NULL_VECTOR).first;
      it->second = it->second + face_cross_product(before, f);
    }
  std::vector<Flip_mesh::Face_index> flipped;
  for (auto f : before.faces()) {
    Flip_vector corners = CGAL::NULL_VECTOR;
    for (auto v : CGAL::vertices_around_face(before.halfedge(f), before)) {
      const double length = std::sqrt(normal[v].squared_length());
      if (length > 0)
        corners = corners + normal[v] / length;
    }
    const Flip_vector n0 = face_cross_product(before, f), n1 = face_cross_product(after, f);
    const double agreement = n0 * corners;
    // Rounding decides the side of a triangle almost perpendicular to its vertex normals: there
    // only the weaker rule is checked.
    const double ambiguous = 1e-9 * std::sqrt(n0.squared_length() * corners.squared_length());
    if (n1 != n0 && (agreement > ambiguous ? !(n1 * n0 > 0) : n1 == CGAL::NULL_VECTOR))
      flipped.push_back(f);
  }
  return flipped;
}

} // namespace test

#endif // HIGHLIGHT_LINES_TEST_FLIPPED_FACES_H

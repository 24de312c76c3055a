// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_FLIP_GUARD_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_FLIP_GUARD_H

// The no-flip rule of the fairing's steps (the purpose of eq. 16's bound, enforced directly).
//
// A face *flips* when its normal turns by more than 90° from its normal in the input mesh
// (the mesh the fairing started from), or when it degenerates. Judging against the input, not
// the start of the step, keeps steps that each turn a face by less than 90° from adding up to
// a flip. A face already folded in the input (its normal opposes the sum of its corners' unit
// vertex normals, as slivers of a noisy scan can be) has no trustworthy orientation: it may
// turn freely, and must only stay non-degenerate.

#include <CGAL/Highlight_lines/internal/fairing/node_jacobian.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

class Flip_guard
{
public:
  Flip_guard() = default;

  // `faces`: the corners (local vertex ids) of the faces a step can change; `input_cross`:
  // their input cross products, or zero for a face folded in the input.
  Flip_guard(std::vector<std::array<int, 3>> faces, std::vector<Vec3> input_cross)
      : faces_(std::move(faces)), input_cross_(std::move(input_cross))
  {
  }

  bool empty() const { return faces_.empty(); }
  std::size_t size() const { return faces_.size(); }
  const std::array<int, 3>& corners(std::size_t j) const { return faces_[j]; }

  // Whether face j flips with its corners at `points` (indexed by local vertex id).
  bool flips(std::size_t j, const std::vector<Vec3>& points) const
  {
    const auto& c = faces_[j];
    const Vec3& p0 = points[std::size_t(c[0])];
    const Vec3& p1 = points[std::size_t(c[1])];
    const Vec3& p2 = points[std::size_t(c[2])];
    const Vec3 n = vector3::cross({p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]},
                                  {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]});
    const Vec3& reference = input_cross_[j];
    if (reference == Vec3{0, 0, 0})
      return !(vector3::dot(n, n) > 0);
    return !(vector3::dot(n, reference) > 0);
  }

  // The faces that flip with their corners at `points`.
  void flipped_faces(const std::vector<Vec3>& points, std::vector<std::size_t>& out) const
  {
    out.clear();
    for (std::size_t j = 0; j < faces_.size(); ++j)
      if (flips(j, points))
        out.push_back(j);
  }

private:
  std::vector<std::array<int, 3>> faces_;
  std::vector<Vec3> input_cross_;
};

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_FLIP_GUARD_H

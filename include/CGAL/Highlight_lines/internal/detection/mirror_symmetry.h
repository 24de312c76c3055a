// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_MIRROR_SYMMETRY_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_MIRROR_SYMMETRY_H

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <CGAL/Highlight_lines/internal/vector3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// The unit eigenvectors of the symmetric 3 x 3 matrix `c` (Jacobi rotations) whose eigenvalue
// is apart from the others by more than `relative_gap` of the largest: an eigenvector of a
// (nearly) repeated eigenvalue is any vector of a plane, set by whatever small asymmetry
// breaks the tie (on a square plate, by a dent: the plane through it).
inline std::vector<vector3::Vec3> separate_eigenvectors(const double (&c)[3][3],
                                                        double relative_gap)
{
  std::array<double, 3> values;
  double v[3][3];
  vector3::symmetric_eigen(c, values, v);
  const double largest =
      (std::max)({std::abs(values[0]), std::abs(values[1]), std::abs(values[2])});
  std::vector<vector3::Vec3> axes;
  for (int j = 0; j < 3; ++j) {
    bool separate = true;
    for (int k = 0; k < 3; ++k)
      separate = separate && (k == j || std::abs(values[std::size_t(j)] - values[std::size_t(k)]) >
                                            relative_gap * largest);
    if (separate)
      axes.push_back(vector3::Vec3{v[0][j], v[1][j], v[2][j]});
  }
  return axes;
}

// The mirror symmetry of a surface, if it has one. Designed shapes (car bodies, most
// characters, many machine parts) are mirror symmetric, and so is their design: a feature has
// its mirror image, or lies on the plane and is its own. A defect breaks the symmetry. The
// plane of a mirror symmetry passes through the centroid and is normal to a principal axis of
// the vertices, so only those three planes are tried (of axes whose variances are told apart); the
// surface is symmetric about one if three quarters of its vertices have their mirror image within
// `ē/10` of it (measured: a symmetric car body and character 1e-6 ē and 1e-15 ē, a scanned head
// 0.06 ē, the others 1.4 ē and more). `asymmetry(v)` is the distance of the mirror image of vertex
// `v` to the surface; `tolerance()` the surface's own asymmetry, the 99th percentile of those
// distances over its vertices, at least `ē/50` (rounding, remeshing); `defect_tolerance()` the
// same estimated from their median (see there).
class Mirror_symmetry
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef std::vector<K::Triangle_3>::const_iterator Iterator;
  typedef CGAL::AABB_triangle_primitive<K, Iterator> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;

public:
  Mirror_symmetry(const std::vector<vector3::Vec3>& points,
                  const std::vector<std::array<int, 3>>& faces, double mean_edge)
      : points_(points)
  {
    using namespace vector3;
    if (points.empty() || faces.empty() || !(mean_edge > 0))
      return;
    triangles_.reserve(faces.size());
    auto point = [&](int v) {
      const Vec3& p = points[std::size_t(v)];
      return K::Point_3(p[0], p[1], p[2]);
    };
    for (const auto& f : faces)
      triangles_.emplace_back(point(f[0]), point(f[1]), point(f[2]));
    tree_ = std::make_unique<Tree>(triangles_.begin(), triangles_.end());
    tree_->accelerate_distance_queries();
    Vec3 c{0, 0, 0};
    for (const Vec3& p : points)
      c = c + (1.0 / double(points.size())) * p;
    double m[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    for (const Vec3& p : points)
      for (int r = 0; r < 3; ++r)
        for (int q = 0; q < 3; ++q)
          m[r][q] +=
              (p[std::size_t(r)] - c[std::size_t(r)]) * (p[std::size_t(q)] - c[std::size_t(q)]);
    centre_ = c;
    std::vector<double> d(points.size());
    double best = 0.1 * mean_edge;
    for (const Vec3& axis : separate_eigenvectors(m, minimum_axis_gap)) {
      normal_ = (1 / norm(axis)) * axis;
      // The 3n/4-th smallest distance exceeds `best` as soon as more than n - 3n/4 - 1 do: stop
      // there (the far mirror images of a plane that is no symmetry are the slow queries).
      const std::size_t q75 = (3 * d.size()) / 4, allowed = d.size() - q75 - 1;
      std::size_t beyond = 0;
      for (std::size_t v = 0; v < points.size() && beyond <= allowed; ++v) {
        d[v] = asymmetry(int(v));
        beyond += !(d[v] <= best);
      }
      if (beyond > allowed)
        continue;
      std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(q75), d.end());
      if (!(d[q75] <= best))
        continue;
      best = d[q75];
      found_ = normal_;
      const std::size_t q99 = (99 * d.size()) / 100;
      std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(q99), d.end());
      tolerance_ = (std::max)(d[q99], 0.02 * mean_edge);
      const std::size_t q50 = d.size() / 2;
      std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(q50), d.end());
      defect_tolerance_ = (std::max)(median_to_tail * d[q50], 0.02 * mean_edge);
    }
    normal_ = found_;
  }

  bool is_symmetric() const { return tolerance_ > 0; }
  double tolerance() const { return tolerance_; }

  // The surface's own asymmetry against which a defect's is measured: `median_to_tail` times
  // the median distance, at least `ē/50`. The median holds while defects and their mirror
  // images cover less than half of the vertices; the 99th percentile does not (four defects 5 ē
  // wide on the shared Spot cover a quarter of its vertices that way and lifted it from ē/50 to
  // their height).
  double defect_tolerance() const { return defect_tolerance_; }

  double asymmetry(int v) const
  {
    using namespace vector3;
    const Vec3& p = points_[std::size_t(v)];
    const Vec3 r = p - (2 * dot(p - centre_, normal_)) * normal_;
    return std::sqrt(tree_->squared_distance(K::Point_3(r[0], r[1], r[2])));
  }

private:
  // Principal axes whose variances differ by less than this share of the largest are not
  // told apart (a symmetric design has its plane where its shape sets it, not where a defect
  // tips a tie).
  static constexpr double minimum_axis_gap = 0.05;
  // The tail of a scan's own asymmetry over its median: the shared camel head (a symmetric
  // scan) has its 99th percentile at 7.3 times its median (0.21 ē), a mesh the team does not
  // have (Homer) at 3.9 times; a half-normal distribution at 3.8 times.
  static constexpr double median_to_tail = 8;
  std::vector<vector3::Vec3> points_;
  std::vector<K::Triangle_3> triangles_;
  std::unique_ptr<Tree> tree_;
  vector3::Vec3 centre_{0, 0, 0}, normal_{0, 0, 0}, found_{0, 0, 0};
  double tolerance_ = 0;
  double defect_tolerance_ = 0;
};

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_MIRROR_SYMMETRY_H

// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_REGION_ASSESSMENT_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_REGION_ASSESSMENT_H

#include <CGAL/Highlight_lines/Highlight_line_irregularity.h>
#include <CGAL/Highlight_lines/internal/detection/anomaly_regions.h>
#include <CGAL/Highlight_lines/internal/detection/surroundings_fit.h>
#include <CGAL/Highlight_lines/internal/vector3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// The last step of the detection: what kind of anomaly a region holds, from the shape of its
// anomalies and the surface around it.

// How local the anomalies of a region are at the detection's scale `w`, from their spread
// along their two main axes (`axes`, standard deviations; four of them make the length and the
// width, the width at least `w`). Anomalies more than twice as long as wide follow a feature
// (slenderness < 1); longer than `longest`, the length over which a defect up to the
// detection's scale spreads its anomalies, they are shape at another scale (locality < 1). So
// are anomalies whose faces cover more than the disc of diameter `longest` grown by `margin`
// (`area`, if positive: the area of the faces of the cluster, which reach `margin` beyond its
// anomalies): on a small or compact mesh a cluster that wraps around the surface spreads less
// in space than along it. What is not local gets at most half the confidence, so that the
// default `minimum_confidence` (0.5) fairs no such region.
struct Anomaly_shape
{
  double slenderness = 1, locality = 1;
};

inline Anomaly_shape anomaly_shape(const std::array<double, 2>& axes, double w, double longest,
                                   double area = 0, double margin = 0)
{
  const double length = 4 * axes[0], width = (std::max)(4 * axes[1], w);
  Anomaly_shape shape;
  shape.slenderness = (std::min)(1.0, std::pow(2 * width / (std::max)(length, 1e-300), 2));
  shape.locality = (std::min)(1.0, std::pow(longest / (std::max)(length, 1e-300), 2));
  if (area > 0) {
    const double disc_area = 3.14159265358979323846 * std::pow(longest / 2 + margin, 2);
    shape.locality = (std::min)(shape.locality, disc_area / area);
  }
  if (shape.locality < 1)
    shape.locality /= 2;
  return shape;
}

// ELONGATED or EXTENDED by the shape of the anomalies; for a compact region, the DENT or BUMP
// `compact_kind()` tells.
template <typename CompactKind>
Irregularity_kind kind_of_region(const Anomaly_shape& shape, CompactKind compact_kind)
{
  if (shape.slenderness < 1)
    return Irregularity_kind::ELONGATED;
  if (shape.locality < 1)
    return Irregularity_kind::EXTENDED;
  return compact_kind();
}

// DENT or BUMP for the peak of a region (the bending measure): the side, against the peak's
// `normal`, of the quadric height field over its tangent plane fitted to the region's outer
// vertices (beyond 60 % of the region's radius from the peak) on which the peak lies.
template <typename LocalMesh>
Irregularity_kind
dent_or_bump_at_peak(const LocalMesh& local, const std::vector<std::array<int, 3>>& corners,
                     const std::vector<int>& faces, int peak, const vector3::Vec3& normal)
{
  std::set<int> region_vertices;
  for (int f : faces)
    for (int v : corners[std::size_t(f)])
      region_vertices.insert(v);
  return peak_lies_below_fit(local, peak, normal, region_vertices) ? Irregularity_kind::DENT
                                                                   : Irregularity_kind::BUMP;
}

// DENT or BUMP for a region grouped around `centre` (the local residual): the side of the
// quadric fitted to the vertices within twice the region's reach from the centre (reached along
// edges, not across a sharp edge) on which its inner part lies. Over twice the reach, the
// surroundings the fit reads lie beyond a defect that fills the region, which a wide dent often
// does at the finer scale.
template <typename LocalMesh>
Irregularity_kind
dent_or_bump_around_centre(const LocalMesh& local, const std::vector<vector3::Vec3>& points,
                           const std::vector<std::array<int, 3>>& corners,
                           const Vertex_adjacency& adjacency, const std::vector<char>& sharp,
                           const std::vector<int>& faces, int centre, const vector3::Vec3& normal)
{
  using namespace vector3;
  const Vec3& at = points[std::size_t(centre)];
  double reach = 0;
  for (int f : faces)
    for (int v : corners[std::size_t(f)])
      reach = (std::max)(reach, norm(points[std::size_t(v)] - at));
  std::set<int> neighbourhood{centre};
  std::vector<int> front{centre};
  while (!front.empty()) {
    const int v = front.back();
    front.pop_back();
    if (sharp[std::size_t(v)] && v != centre)
      continue;
    adjacency.for_each_neighbour(v, [&](int u) {
      if (norm(points[std::size_t(u)] - at) <= 2 * reach && neighbourhood.insert(u).second)
        front.push_back(u);
    });
  }
  return region_lies_below_fit(local, centre, normal, neighbourhood) ? Irregularity_kind::DENT
                                                                     : Irregularity_kind::BUMP;
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_REGION_ASSESSMENT_H

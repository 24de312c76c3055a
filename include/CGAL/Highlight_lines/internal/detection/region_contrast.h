// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_REGION_CONTRAST_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_REGION_CONTRAST_H

#include <CGAL/Highlight_lines/internal/detection/anomaly_regions.h>
#include <CGAL/Highlight_lines/internal/detection/line_bending.h>
#include <CGAL/Highlight_lines/internal/vector3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// A sample the local residual scored: its vertex, its light setup, and its level residual less
// the setup's median.
struct Scored_sample
{
  int vertex;
  std::size_t setup;
  float value;
};

// The contrast of a region with its surroundings: per light setup among its anomalies, the
// offset of its strongest anomaly from the median of the samples of the same setup in the
// surroundings (between `disc` and `surroundings` from the centre, reached along edges that
// cross no sharp edge), over their robust deviation; the median over the setups. A defect
// stands out of a quiet patch; the lines of a feature-rich patch (a scan's eyes and ears, a
// fillet and its neighbours) move as much around it as in it.
class Region_contrast
{
public:
  Region_contrast(const std::vector<vector3::Vec3>& points, const Vertex_adjacency& adjacency,
                  const std::vector<char>& sharp, const std::vector<Scored_sample>& samples,
                  double disc, double surroundings)
      : points_(points), adjacency_(adjacency), sharp_(sharp), disc_(disc),
        surroundings_(surroundings), sample_offsets_(points.size() + 1, 0),
        vertex_samples_(samples.size()), distance_to_centre_(points.size(), -1.0)
  {
    // The samples of each vertex, in compressed rows.
    for (const auto& sample : samples)
      ++sample_offsets_[std::size_t(sample.vertex) + 1];
    for (std::size_t v = 1; v < sample_offsets_.size(); ++v)
      sample_offsets_[v] += sample_offsets_[v - 1];
    std::vector<std::size_t> fill(sample_offsets_.begin(), sample_offsets_.end() - 1);
    for (const auto& sample : samples)
      vertex_samples_[fill[std::size_t(sample.vertex)]++] = {sample.setup, sample.value};
  }

  // The contrast of `region` (its anomalies index `anomalies`); -1 if no setup has samples
  // enough around it.
  double operator()(const Peak_region& region, const std::vector<Anomaly>& anomalies)
  {
    using namespace vector3;
    std::vector<int> reached{region.centre}, front{region.centre};
    const Vec3& at = points_[std::size_t(region.centre)];
    distance_to_centre_[std::size_t(region.centre)] = 0;
    while (!front.empty()) {
      const int v = front.back();
      front.pop_back();
      if (sharp_[std::size_t(v)] && v != region.centre)
        continue;
      adjacency_.for_each_neighbour(v, [&](int u) {
        if (distance_to_centre_[std::size_t(u)] >= 0)
          return;
        const double d = norm(points_[std::size_t(u)] - at);
        if (d > surroundings_)
          return;
        distance_to_centre_[std::size_t(u)] = d;
        reached.push_back(u);
        front.push_back(u);
      });
    }
    std::vector<std::pair<std::size_t, std::size_t>> strongest_of_setup; // (setup, anomaly)
    for (std::size_t i : region.anomalies) {
      const auto& a = anomalies[i];
      auto it = std::find_if(strongest_of_setup.begin(), strongest_of_setup.end(),
                             [&a](const auto& e) { return e.first == a.setup; });
      if (it == strongest_of_setup.end())
        strongest_of_setup.emplace_back(a.setup, i);
      else if (a.score > anomalies[it->second].score)
        it->second = i;
    }
    std::vector<std::vector<double>> values(strongest_of_setup.size());
    for (int v : reached)
      if (distance_to_centre_[std::size_t(v)] >= disc_)
        for (std::size_t k = sample_offsets_[std::size_t(v)];
             k < sample_offsets_[std::size_t(v) + 1]; ++k)
          for (std::size_t j = 0; j < strongest_of_setup.size(); ++j)
            if (strongest_of_setup[j].first == vertex_samples_[k].first)
              values[j].push_back(double(vertex_samples_[k].second));
    for (int v : reached)
      distance_to_centre_[std::size_t(v)] = -1;
    std::vector<double> contrasts;
    for (std::size_t j = 0; j < strongest_of_setup.size(); ++j) {
      if (values[j].size() < 8)
        continue;
      const auto& a = anomalies[strongest_of_setup[j].second];
      const Robust_statistics around = robust_statistics_signed(values[j]);
      // At least a quarter of the noise the anomaly's score was measured against.
      const double floor = 0.25 * std::abs(a.value) / (std::max)(a.score, 1e-300);
      contrasts.push_back(std::abs(a.value - around.median) /
                          (std::max)({around.deviation, floor, 1e-300}));
    }
    if (contrasts.empty())
      return -1.0;
    std::nth_element(contrasts.begin(),
                     contrasts.begin() + std::ptrdiff_t((contrasts.size() - 1) / 2),
                     contrasts.end());
    return contrasts[(contrasts.size() - 1) / 2];
  }

private:
  const std::vector<vector3::Vec3>& points_;
  const Vertex_adjacency& adjacency_;
  const std::vector<char>& sharp_;
  double disc_, surroundings_;
  std::vector<std::size_t> sample_offsets_;
  std::vector<std::pair<std::size_t, float>> vertex_samples_;
  std::vector<double> distance_to_centre_; // -1 outside the surroundings being read
};

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_REGION_CONTRAST_H

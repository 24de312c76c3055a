// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_LINE_SCORING_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_LINE_SCORING_H

#include <CGAL/Highlight_lines/internal/detection/anomaly_regions.h>
#include <CGAL/Highlight_lines/internal/detection/highlight_distance_field.h>
#include <CGAL/Highlight_lines/internal/detection/line_bending.h>
#include <CGAL/Highlight_lines/internal/detection/line_peaks.h>
#include <CGAL/Highlight_lines/internal/detection/region_contrast.h>
#include <CGAL/Highlight_lines/internal/vector3.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// The points of a highlight line of a model, in doubles.
template <typename Nodes, typename Line>
void line_points(const Nodes& nodes, const Line& line, std::vector<vector3::Vec3>& polyline)
{
  polyline.clear();
  for (std::size_t n : line.nodes) {
    const auto& p = nodes[n].point;
    polyline.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  }
}

// The second step of the detection, after the light setups are sampled: the lines of each setup
// are scored, and the peaks of the measure along a line become anomalies at the mesh vertex
// nearest to them. Samples where the surface turns too far away from the lights are not scored,
// and no anomaly is counted within one ring of a sharp edge (the lines kink there by design).
// Only the peaks along a line count (one per stencil width): the stencil spreads a defect's
// response over 3w/2 to either side, the peak stays on the defect.
// One object scores all the setups of one sweep; the anomalies carry their line (numbered over
// the sweep) and their setup.
class Line_scoring
{
public:
  // `normals` the unit vertex normals (eq. 3), `near_sharp` the vertices of sharp edges and
  // those one ring from them, `minimum_facing` the cosine of the largest incidence angle,
  // `mean_edge` the mean edge length, `minimum_bending` the option.
  Line_scoring(const std::vector<vector3::Vec3>& normals, const std::vector<char>& near_sharp,
               double minimum_facing, double mean_edge, double minimum_bending)
      : normals_(normals), near_sharp_(near_sharp), minimum_facing_(minimum_facing),
        mean_edge_(mean_edge), minimum_bending_(minimum_bending)
  {
  }

  // The local residual (see detect_highlight_line_irregularities()): each line's sideways
  // offset from the course its neighbourhood predicts, in levels of the lights, at the samples
  // of `scales`. The candidates are the peaks of |level residual - the setup's median| along
  // each line (one per `gap` samples to either side); they are scored by
  // divide_by_noise() once the noise of every setup is known. `plane_normal` the setup's,
  // `level_per_distance` one over its spacing, `field` its highlight distance field;
  // `nearest_vertex(node)` the compact vertex nearest to a node (-1 if none),
  // `on_sharp_edge(node)` whether the line kinks at the node by design.
  template <typename Nodes, typename Lines, typename NearestVertex, typename OnSharpEdge>
  void score_level_residuals(const Nodes& nodes, const Lines& lines,
                             const std::array<double, 3>& plane_normal, double level_per_distance,
                             const Highlight_distance_field& field,
                             const Line_residual_scales& scales, std::size_t setup,
                             NearestVertex nearest_vertex, OnSharpEdge on_sharp_edge)
  {
    using namespace vector3;
    const Vec3 z{plane_normal[0], plane_normal[1], plane_normal[2]};
    residuals_.resize(lines.size());
    level_residuals_.resize(lines.size());
    sample_vertices_.resize(lines.size());
    std::vector<double> pooled;
    for (std::size_t l = 0; l < lines.size(); ++l) {
      line_points(nodes, lines[l], polyline_);
      line_breaks_.clear();
      for (std::size_t n : lines[l].nodes)
        line_breaks_.push_back(on_sharp_edge(nodes[n]) ? 1 : 0);
      compute_line_residual(polyline_, lines[l].is_closed, scales, residuals_[l], line_breaks_);
      // Each sample's mesh vertex; samples where the surface turns too far away from the
      // lights are not scored.
      const auto& residual = residuals_[l];
      std::vector<double>& level = level_residuals_[l];
      level.assign(residual.valid.size(), std::numeric_limits<double>::quiet_NaN());
      sample_vertices_[l].assign(residual.valid.size(), -1);
      for (std::size_t i = 0; i < residual.valid.size(); ++i) {
        if (!residual.valid[i])
          continue;
        const int compact = nearest_vertex(nodes[lines[l].nodes[residual.nearest_vertex[i]]]);
        if (compact < 0 || dot(normals_[std::size_t(compact)], z) < minimum_facing_ ||
            !(field.weight[std::size_t(compact)] > 0))
          continue;
        sample_vertices_[l][i] = compact;
        level[i] =
            level_per_distance * dot(residual.residual[i], field.gradient[std::size_t(compact)]);
        if (std::isfinite(level[i]))
          pooled.push_back(level[i]);
        else
          sample_vertices_[l][i] = -1;
      }
    }
    // The noise: median and robust deviation of the level residuals of the whole setup.
    const Robust_statistics stats = robust_statistics_signed(pooled);
    setup_deviations.push_back(stats.count >= 32 ? stats.deviation : -1.0);
    // Every scored sample, for the noise of the surroundings of a region.
    for (std::size_t l = 0; l < lines.size(); ++l)
      for (std::size_t i = 0; i < level_residuals_[l].size(); ++i)
        if (sample_vertices_[l][i] >= 0)
          samples.push_back(
              {sample_vertices_[l][i], setup, float(level_residuals_[l][i] - stats.median)});

    std::vector<double> magnitude;
    for (std::size_t l = 0; l < lines.size(); ++l, ++line_) {
      const auto& level = level_residuals_[l];
      magnitude.assign(level.size(), -1.0);
      for (std::size_t i = 0; i < level.size(); ++i)
        if (sample_vertices_[l][i] >= 0)
          magnitude[i] = std::abs(level[i] - stats.median);
      // The line's own noise, if it has samples enough to tell.
      std::vector<double> own;
      for (std::size_t i = 0; i < level.size(); ++i)
        if (sample_vertices_[l][i] >= 0)
          own.push_back(level[i]);
      const Robust_statistics line_stats = robust_statistics_signed(own);
      const double line_noise = line_stats.count >= 32 ? line_stats.deviation : -1.0;
      for (std::size_t i = 0; i < level.size(); ++i) {
        if (sample_vertices_[l][i] < 0 || !(magnitude[i] > 0))
          continue;
        const double shift = norm(residuals_[l].residual[i]) / mean_edge_;
        if (!(shift > minimum_bending_) ||
            !is_peak_along_line(magnitude, i, lines[l].is_closed, std::ptrdiff_t(scales.gap)))
          continue;
        Anomaly* a = add_anomaly(sample_vertices_[l][i], setup, magnitude[i], shift);
        if (a) {
          a->noise = line_noise;
          a->value = level[i] - stats.median;
        }
      }
    }
  }

  // After score_level_residuals() on every setup: each candidate's offset over the noise of its
  // line, at least `line_noise_floor` of its setup's, itself floored at half the median over the
  // setups (a setup that only sees planes has next to none, and would make any rounding an
  // anomaly; where no setup knows its noise, at half that of all the samples); the setup's alone
  // where the line has too few samples. Those above `threshold` stay. No noise counts below
  // `minimum_noise_in_levels`: where the lines are straight to the rounding (a plane, a regular
  // grid over a smooth surface), their deviations fall to 1e-15 to 1e-5 of the spacing of the
  // lights, and the far tails of a defect or the grid's own pattern would become anomalies.
  void divide_by_noise(double threshold)
  {
    std::vector<double> known;
    for (double d : setup_deviations)
      if (d > 0)
        known.push_back(d);
    double floor = 0; // minimum_noise_in_levels bounds every noise from below
    if (!known.empty()) {
      std::nth_element(known.begin(), known.begin() + std::ptrdiff_t(known.size() / 2),
                       known.end());
      floor = (std::max)(floor, 0.5 * known[known.size() / 2]);
    } else {
      // No setup has samples enough to tell its noise (a small mesh, short lines): half that of
      // all the scored samples together; with too few of those, no sample can be told apart
      // from the noise.
      std::vector<double> values;
      for (const Scored_sample& sample : samples)
        values.push_back(sample.value);
      const Robust_statistics all = robust_statistics_signed(values);
      if (all.count < 32) {
        anomalies.clear();
        return;
      }
      floor = (std::max)(floor, 0.5 * all.deviation);
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < anomalies.size(); ++i) {
      Anomaly a = anomalies[i];
      const double setup_noise = (std::max)(setup_deviations[a.setup], floor);
      const double noise =
          a.noise >= 0 ? (std::max)(a.noise, line_noise_floor * setup_noise) : setup_noise;
      a.score /= (std::max)(noise, minimum_noise_in_levels);
      if (!(a.score > threshold))
        continue;
      anomalies[kept++] = a;
    }
    anomalies.resize(kept);
  }

  // The bending measure (closer to the paper): the change of the lines' curvature at the
  // samples of `scales`, as a robust z-score against the line's own statistics (those of the
  // whole setup for lines of fewer than 32 samples, and a quarter of the setup's deviation as a
  // floor); the peaks above `threshold` are anomalies.
  template <typename Nodes, typename Lines, typename NearestVertex>
  void score_bending(const Nodes& nodes, const Lines& lines,
                     const std::array<double, 3>& plane_normal, const Line_bending_scales& scales,
                     double threshold, std::size_t setup, NearestVertex nearest_vertex)
  {
    using namespace vector3;
    const Vec3 z{plane_normal[0], plane_normal[1], plane_normal[2]};
    bendings_.resize(lines.size());
    sample_vertices_.resize(lines.size());
    std::vector<double> pooled;
    for (std::size_t l = 0; l < lines.size(); ++l) {
      line_points(nodes, lines[l], polyline_);
      compute_line_bending(polyline_, lines[l].is_closed, scales, bendings_[l]);
      // Each sample's mesh vertex; samples where the surface turns too far away from the
      // lights are not scored.
      std::vector<double>& bending = bendings_[l].bending;
      sample_vertices_[l].assign(bending.size(), -1);
      for (std::size_t i = 0; i < bending.size(); ++i) {
        if (bending[i] < 0)
          continue;
        const int compact = nearest_vertex(nodes[lines[l].nodes[bendings_[l].nearest_vertex[i]]]);
        if (compact < 0 || dot(normals_[std::size_t(compact)], z) < minimum_facing_) {
          bending[i] = -1;
          continue;
        }
        sample_vertices_[l][i] = compact;
        pooled.push_back(bending[i]);
      }
    }
    const Robust_statistics setup_stats = robust_statistics(pooled);

    for (std::size_t l = 0; l < lines.size(); ++l, ++line_) {
      Robust_statistics stats = robust_statistics(bendings_[l].bending);
      if (stats.count < 32)
        stats = setup_stats;
      const double deviation = (std::max)(
          {stats.deviation, 0.25 * setup_stats.deviation, 1e-3 * minimum_bending_, 1e-300});
      const auto& bending = bendings_[l].bending;
      for (std::size_t i = 0; i < bending.size(); ++i) {
        if (bending[i] < 0 || !(bending[i] > minimum_bending_))
          continue;
        const double score = (bending[i] - stats.median) / deviation;
        if (!(score > threshold) ||
            !is_peak_along_line(bending, i, lines[l].is_closed, scales.fine_samples))
          continue;
        add_anomaly(sample_vertices_[l][i], setup, score, bending[i]);
      }
    }
  }

  std::vector<Anomaly> anomalies;
  // With the local residual: every scored sample, and per setup the noise of its level
  // residuals (-1 if it has too few samples to tell).
  std::vector<Scored_sample> samples;
  std::vector<double> setup_deviations;

private:
  // A peak of the current line becomes an anomaly unless it lies next to a sharp edge; the new
  // anomaly, or null.
  Anomaly* add_anomaly(int vertex, std::size_t setup, double score, double bending)
  {
    if (near_sharp_[std::size_t(vertex)])
      return nullptr;
    Anomaly a;
    a.vertex = vertex;
    a.line = line_;
    a.setup = setup;
    a.score = score;
    a.bending = bending;
    anomalies.push_back(a);
    return &anomalies.back();
  }

  static constexpr double line_noise_floor = 0.25;
  // A hundredth of the spacing of the lights: an offset of a line several times smaller than
  // that is invisible in a picture of the lines (the real meshes of the developers' set have
  // noises of 0.3 to 2.5 spacings, the smooth synthetic hoods 0.01 to 0.09).
  static constexpr double minimum_noise_in_levels = 0.01;
  const std::vector<vector3::Vec3>& normals_;
  const std::vector<char>& near_sharp_;
  double minimum_facing_, mean_edge_, minimum_bending_;
  std::size_t line_ = 0; // the current line, over all setups scored
  std::vector<vector3::Vec3> polyline_;
  std::vector<std::vector<int>> sample_vertices_;
  std::vector<Line_bending> bendings_;
  std::vector<Line_residual> residuals_;
  std::vector<char> line_breaks_;
  std::vector<std::vector<double>> level_residuals_;
};

// The setups that can see a defect at each vertex: those facing it within the incidence limit
// (at most `facing_setups` of the vertex) that scored a sample within `rings` rings of it, not
// across a sharp edge. Facing is not enough: a setup's lines are not scored near their ends,
// near a sharp edge or where its lights cross the surface at a grazing angle, and a defect
// there cannot show in it (on the shared Spot, this located 7 of 8 defects 0.2 ē high instead
// of 4).
inline std::vector<std::size_t>
setups_seeing_vertices(const std::vector<Scored_sample>& samples, std::size_t number_of_setups,
                       const Vertex_adjacency& adjacency, const std::vector<char>& sharp, int rings,
                       const std::vector<std::size_t>& facing_setups)
{
  const std::size_t nv = facing_setups.size();
  std::vector<std::size_t> seeing(nv, 0);
  const std::size_t words = (number_of_setups + 63) / 64;
  std::vector<std::uint64_t> mask(nv * words, 0), next;
  for (const auto& sample : samples)
    mask[std::size_t(sample.vertex) * words + sample.setup / 64] |= std::uint64_t(1)
                                                                    << (sample.setup % 64);
  for (int r = 0; r < rings; ++r) {
    next = mask;
    for (std::size_t v = 0; v < nv; ++v)
      if (!sharp[v])
        adjacency.for_each_neighbour(int(v), [&](int u) {
          for (std::size_t k = 0; k < words; ++k)
            next[std::size_t(u) * words + k] |= mask[v * words + k];
        });
    mask.swap(next);
  }
  for (std::size_t v = 0; v < nv; ++v) {
    std::size_t count = 0;
    for (std::size_t k = 0; k < words; ++k)
      for (std::uint64_t m = mask[v * words + k]; m != 0; m &= m - 1)
        ++count;
    seeing[v] = (std::min)(count, facing_setups[v]);
  }
  return seeing;
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_LINE_SCORING_H

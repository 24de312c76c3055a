// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_FAIRING_PROBLEM_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_FAIRING_PROBLEM_H

#include <CGAL/Highlight_lines/Fairing_report.h>
#include <CGAL/Highlight_lines/Fairness_energy.h>
#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/Highlight_lines/Light_setup.h>
#include <CGAL/Highlight_lines/internal/fairing/curvature_variation_energy.h>
#include <CGAL/Highlight_lines/internal/fairing/desired_highlight_lines.h>
#include <CGAL/Highlight_lines/internal/fairing/fairing_region.h>
#include <CGAL/Highlight_lines/internal/fairing/mean_curvature_fit.h>
#include <CGAL/Highlight_lines/internal/fairing/node_jacobian.h>
#include <CGAL/Highlight_lines/internal/fairing/ogh_curve.h>
#include <CGAL/Highlight_lines/internal/model/model_engine.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// The arc length of line, in mean edge lengths, over which end tangents are fitted.
constexpr double tangent_reach_in_edges = 3;

struct Fairing_options
{
  double fairness_weight = 1, difference_weight = 1, convergence_threshold = 0.001;
  Fairness_energy fairness_energy = Fairness_energy::CURVATURE_VARIATION;
  std::size_t max_iterations = 50;
  int neighborhood_rings = 3;
  Level_window window;
};

// What a fairing of one region solves, read from the mesh without changing it: the local mesh
// of the region's neighbourhood, the region (§3.1), the highlight line model on it and the
// desired lines (§3.2), and the scales of the energies. The iteration (fairing.h) derives from
// it; the building blocks (fairing_building_blocks.h) use it alone.
template <typename TriangleMesh, typename VertexPointMap, typename GeomTraits>
class Fairing_problem
{
protected:
  typedef Model_engine<TriangleMesh, VertexPointMap, CGAL::Sequential_tag> Engine;

public:
  template <typename FaceSet>
  Fairing_problem(
      const TriangleMesh& tm, const FaceSet& region,
      const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& neighborhood,
      VertexPointMap vpm, const Light_setup<GeomTraits>& lights, const Fairing_options& options)
      : vpm_(vpm), lights_(lights), options_(options),
        engine_(tm, vpm, Highlight_lines::parameters::face_range(neighborhood))
  {
    const Local_mesh<TriangleMesh>& lm = engine_.local_mesh();
    build_fairing_region(
        tm, lm, [&region](auto f) { return region.count(f) != 0; }, region_);
    require_movable_vertex(region_);
    // Mean edge length in R (eq. 17) and the length scale of q_diff's normalisation.
    double length_sum = 0, area = 0;
    std::size_t edges = 0;
    for (std::size_t e = 0; e < lm.edge_vertices.size(); ++e)
      if (region_.edge_touches_region[e]) {
        length_sum += distance(lm.edge_vertices[e][0], lm.edge_vertices[e][1]);
        ++edges;
      }
    for (std::size_t f = 0; f < lm.face_vertices.size(); ++f)
      if (region_.face_in_region[f]) {
        const Vec3 c = face_cross(int(f));
        area += 0.5 * std::sqrt(vector3::dot(c, c));
      }
    mean_edge_length_ = length_sum / double((std::max)(edges, std::size_t(1)));
    length_scale_ = std::sqrt(area);
    // The fairing's double arithmetic takes lengths to the fourth power (squared areas in the
    // cotangent weights, area^{3/2} in q_diff's normalisation): beyond this range they over- or
    // underflow, and a sound region would be refused as degenerate or faired with NaN weights.
    const double smallest = 1e-60, largest = 1e60;
    if (!(mean_edge_length_ >= smallest && mean_edge_length_ <= largest &&
          length_scale_ >= smallest && length_scale_ <= largest))
      throw Invalid_input(Invalid_input::Problem::SCALE_OUT_OF_RANGE,
                          "fair_with_highlight_lines(): the region's size (mean edge length " +
                              std::to_string(mean_edge_length_) +
                              ") is outside the range [1e-60, 1e60] the fairing supports; "
                              "scale the mesh and the light setup towards unit size");
  }

  // The model of the current mesh and the desired lines (§3.2), fixed for the whole fairing.
  void make_targets(Fairing_report& report)
  {
    report.number_of_movable_vertices = region_.movable.size();
    model_window_ = options_.window;
    restrict_to_region_levels(model_window_);
    compute_model();
    report.number_of_folded_triangles = 0;
    report.number_of_sliver_triangles = 0;
    for (std::size_t f = 0; f < region_.face_in_region.size(); ++f)
      if (region_.face_in_region[f]) {
        report.number_of_folded_triangles += is_folded(int(f)) ? 1 : 0;
        report.number_of_sliver_triangles +=
            smallest_angle(int(f)) < fit_options_.sliver_angle ? 1 : 0;
      }
    if (options_.fairness_energy == Fairness_energy::CURVATURE_VARIATION &&
        fit_options_.method == Mean_curvature_fit_options::Method::FIT_ON_DEGENERATE_RINGS)
      degenerate_rings_ = vertices_with_degenerate_rings(
          local_points(), engine_.local_mesh().face_vertices, fit_options_.sliver_angle);
    if (options_.fairness_energy == Fairness_energy::CURVATURE_VARIATION)
      crease_vertices_ = vertices_on_sharp_edges(local_points(), engine_.local_mesh().face_vertices,
                                                 crease_angle());
    desired_.clear();
    make_desired_lines(report);
    // From now on only the targeted lines count (q_diff), so the next models are computed for
    // their levels only: the neighbourhood's other levels (dense where it turns away from the
    // lights) can hold ten times their nodes.
    if (desired_.empty()) { // an empty window, with levels the node code can double
      model_window_.lowest = 1;
      model_window_.highest = 0;
      return;
    }
    long long lowest = desired_.front().start.level, highest = lowest;
    for (const Desired_line& line : desired_) {
      lowest = (std::min)(lowest, line.start.level);
      highest = (std::max)(highest, line.start.level);
    }
    model_window_.lowest = (std::max)(model_window_.lowest, lowest);
    model_window_.highest = (std::min)(model_window_.highest, highest);
  }

  const Fairing_region& region() const { return region_; }
  const Engine& engine() const { return engine_; }
  const std::vector<Desired_line>& desired_lines() const { return desired_; }
  const Raw_model& model() const { return model_; }

  // Public for the tests: the rows dQ/dx of the nodes of the current model.
  Node_jacobian jacobian(const std::vector<Vec3>& directions) const
  {
    const Local_mesh<TriangleMesh>& lm = engine_.local_mesh();
    return Node_jacobian(lm, region_, engine_.vertex_normals(), directions,
                         lights_.base_point_array(), lights_.light_direction_array(),
                         lights_.plane_normal_array());
  }

  std::vector<Vec3> movable_normals() const
  {
    std::vector<Vec3> directions;
    for (int v : region_.movable)
      directions.push_back(engine_.vertex_normals().unit_normal(v));
    return directions;
  }

protected:
  Vec3 position(int v) const
  {
    const double* p = engine_.local_mesh().point(v);
    return {p[0], p[1], p[2]};
  }
  double distance(int a, int b) const
  {
    const Vec3 p = position(a), q = position(b);
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                     (p[2] - q[2]) * (p[2] - q[2]));
  }
  Vec3 face_cross(int f) const
  {
    const auto& c = engine_.local_mesh().face_vertices[std::size_t(f)];
    const Vec3 p0 = position(c[0]), p1 = position(c[1]), p2 = position(c[2]);
    return vector3::cross({p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]},
                          {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]});
  }
  // Whether the normal of face f opposes (or is orthogonal to) the sum of the unit vertex
  // normals at its corners: a triangle folded over a neighbour.
  bool is_folded(int f) const
  {
    Vec3 corner_normals{0, 0, 0};
    for (int c : engine_.local_mesh().face_vertices[std::size_t(f)]) {
      const Vec3 m = engine_.vertex_normals().unit_normal(c);
      for (int k = 0; k < 3; ++k)
        corner_normals[std::size_t(k)] += m[std::size_t(k)];
    }
    return !(vector3::dot(face_cross(f), corner_normals) > 0);
  }
  // The smallest corner angle of face f, in radians.
  double smallest_angle(int f) const
  {
    const auto& c = engine_.local_mesh().face_vertices[std::size_t(f)];
    double smallest = 4;
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = position(c[std::size_t(k)]), a = position(c[std::size_t((k + 1) % 3)]),
                 b = position(c[std::size_t((k + 2) % 3)]);
      const Vec3 u{a[0] - p[0], a[1] - p[1], a[2] - p[2]}, w{b[0] - p[0], b[1] - p[1], b[2] - p[2]};
      const Vec3 n = vector3::cross(u, w);
      smallest =
          (std::min)(smallest, std::atan2(std::sqrt(vector3::dot(n, n)), vector3::dot(u, w)));
    }
    return smallest;
  }

  double shortest_edge(int v) const
  {
    double shortest = std::numeric_limits<double>::infinity();
    for (int i = region_.vertex_neighbor_begin[std::size_t(v)];
         i < region_.vertex_neighbor_begin[std::size_t(v) + 1]; ++i)
      shortest = (std::min)(shortest, distance(v, region_.vertex_neighbors[std::size_t(i)]));
    return shortest;
  }

  void compute_model() { engine_.compute_raw(lights_, model_window_, false, model_); }

  // The levels that can cross R: a node of level m lies on an edge of a face of R, between
  // ends of levels k (k s <= d < (k + 1) s), so m is in [min k, max k + 1] over R's vertices.
  // The first model needs no other level (a line is followed out of R along its own), and the
  // neighbourhood's other levels can hold several times their nodes. Unchanged where a
  // vertex of R has no level (its normal parallel to the light plane).
  void restrict_to_region_levels(Level_window& window) const
  {
    std::vector<Vertex_level> levels;
    engine_.classify(lights_, levels);
    long long lowest = 0, highest = 0;
    bool any = false;
    const Local_mesh<TriangleMesh>& lm = engine_.local_mesh();
    for (std::size_t f = 0; f < region_.face_in_region.size(); ++f) {
      if (!region_.face_in_region[f])
        continue;
      for (int v : lm.face_vertices[f]) {
        const Vertex_level& level = levels[std::size_t(v)];
        if (level.normal_side == 0 || level.out_of_range)
          return;
        lowest = any ? (std::min)(lowest, (long long)level.level) : (long long)level.level;
        highest = any ? (std::max)(highest, (long long)level.level) : (long long)level.level;
        any = true;
      }
    }
    if (!any)
      return;
    window.lowest = (std::max)(window.lowest, lowest);
    window.highest = (std::min)(window.highest, highest + 1);
  }

  Vec3 node_point(int id) const
  {
    const auto& p = model_.node(std::size_t(id)).point;
    return {p[0], p[1], p[2]};
  }

  void make_desired_lines(Fairing_report& report)
  {
    const Pieces_found found = find_line_pieces(model_, region_);
    report.number_of_lines_without_target = found.lines_ending_inside + found.loops_inside;
    for (const Line_piece& piece : found.pieces) {
      if (piece.before.empty() || piece.after.empty()) { // no tangent outside R
        ++report.number_of_lines_without_target;
        continue;
      }
      const Vec3 q0 = node_point(piece.nodes.front()), q1 = node_point(piece.nodes.back());
      std::vector<Vec3> before, after;
      for (int id : piece.before)
        before.push_back(node_point(id));
      for (int id : piece.after)
        after.push_back(node_point(id));
      // Along the line's direction of travel at both ends.
      const double reach = tangent_reach_in_edges * mean_edge_length_;
      const Vec3 t0 = fitted_end_tangent(q0, before, reach);
      Vec3 t1 = fitted_end_tangent(q1, after, reach);
      for (double& c : t1)
        c = -c;
      Desired_line line{Node_key::of(model_.node(std::size_t(piece.nodes.front()))),
                        Node_key::of(model_.node(std::size_t(piece.nodes.back()))),
                        make_ogh_target(q0, t0, q1, t1)};
      if (line.curve.status == Ogh_target::Status::NONE) {
        ++report.number_of_lines_without_target;
        continue;
      }
      if (line.curve.status == Ogh_target::Status::TWO_SEGMENTS)
        ++report.number_of_two_segment_targets;
      desired_.push_back(std::move(line));
    }
    report.number_of_lines_targeted = desired_.size();
  }

  std::vector<Vec3> local_points() const
  {
    std::vector<Vec3> points(engine_.local_mesh().vertex_handles.size());
    for (std::size_t v = 0; v < points.size(); ++v)
      points[v] = position(int(v));
    return points;
  }

  VertexPointMap vpm_;
  Light_setup<GeomTraits> lights_;
  Fairing_options options_;
  Engine engine_;
  Fairing_region region_;
  Raw_model model_;
  Level_window model_window_; // the levels of the desired lines, see make_targets()
  std::vector<Desired_line> desired_;
  // The curvature variation's mean curvature: fitted on the rings degenerate in the input (per
  // local vertex), the cotangent formula elsewhere (curvature_variation_energy.h).
  Mean_curvature_fit_options fit_options_ = default_mean_curvature_fit_options();
  std::vector<char> degenerate_rings_;
  std::vector<char> crease_vertices_; // on a sharp edge in the input, see freeze_variation()
  double mean_edge_length_ = 1, length_scale_ = 1;
};

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_FAIRING_PROBLEM_H

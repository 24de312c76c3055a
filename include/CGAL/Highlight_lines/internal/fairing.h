// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_H

#include <CGAL/Highlight_lines/Fairing_report.h>
#include <CGAL/Highlight_lines/Fairness_energy.h>
#include <CGAL/Highlight_lines/Highlight_line_sweeper.h>
#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/Highlight_lines/Light_setup.h>
#include <CGAL/Highlight_lines/internal/desired_highlight_lines.h>
#include <CGAL/Highlight_lines/internal/fairing_region.h>
#include <CGAL/Highlight_lines/internal/node_jacobian.h>
#include <CGAL/Highlight_lines/internal/ogh_curve.h>
#include <CGAL/Highlight_lines/internal/willmore_energy.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// A desired highlight line (§3.2): the fixed OGH curve between two delimiting nodes.
struct Desired_line
{
  Node_key start, end;
  Ogh_target curve;
};

// One line piece of the current model matched to its desired line, with the data of q_diff.
struct Matched_piece
{
  std::vector<int> nodes;      // canonical ids, Q0 .. Q1
  std::vector<Vec3> targets;   // eq. 12, for the inner nodes
  std::vector<double> weights; // eq. 14, for the inner nodes
};

// The arc length of line, in mean edge lengths, over which end tangents are fitted.
constexpr double tangent_reach_in_edges = 3;

struct Fairing_options
{
  double fairness_weight = 1, difference_weight = 1, convergence_threshold = 0.001;
  Fairness_energy fairness_energy = Fairness_energy::WILLMORE;
  std::size_t max_iterations = 50;
  int neighborhood_rings = 3;
  Level_window window;
};

// The iteration of §3.7 on the neighbourhood of one region.
template <typename TriangleMesh, typename VertexPointMap, typename GeomTraits, typename Solver>
class Fairing
{
  typedef Highlight_line_sweeper<TriangleMesh, VertexPointMap, GeomTraits> Sweeper;
  typedef typename Sweeper::Raw_model Raw_model;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;

public:
  template <typename FaceSet>
  Fairing(
      TriangleMesh& tm, const FaceSet& region,
      const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& neighborhood,
      VertexPointMap vpm, const Light_setup<GeomTraits>& lights, const Fairing_options& options,
      Solver& solver)
      : tm_(tm), vpm_(vpm), lights_(lights), options_(options), solver_(solver),
        sweeper_(tm, Highlight_lines::parameters::face_range(neighborhood).vertex_point_map(vpm))
  {
    const Local_mesh<TriangleMesh>& lm = sweeper_.local_mesh();
    build_fairing_region(
        tm, lm, [&region](auto f) { return region.count(f) != 0; }, region_);
    if (region_.movable.empty())
      throw Invalid_input(Invalid_input::Problem::NO_MOVABLE_VERTEX,
                          "the fairing region has no movable vertex: a vertex can move only if "
                          "it and all its neighbours lie inside the region (not on its border nor "
                          "on a mesh border); enlarge the region by at least two rings");
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
        area += 0.5 * std::sqrt(dot3(c, c));
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

  Fairing_report run(const std::function<bool(const Fairing_report::Iteration&)>& visitor)
  {
    Fairing_report report;
    make_targets(report);

    for (std::size_t iteration = 0;; ++iteration) {
      take_checkpoint();
      Fairing_report::Iteration step;
      const std::size_t n = region_.movable.size();
      solver_.resize(n);
      const std::vector<Vec3> directions = movable_normals();

      const double w1 = options_.fairness_weight;
      const double w2 =
          options_.difference_weight / (length_scale_ * length_scale_ * length_scale_);
      // q_fair: the Willmore energy with frozen weights, an exact quadratic in x.
      double trace = 0;
      step.fairness_energy = add_fairness_terms(directions, w1, trace);
      solver_.set_r(w1 * step.fairness_energy);
      // q_diff: Gauss–Newton form over the matched line pieces.
      std::vector<Matched_piece> pieces = match_desired_lines();
      step.lines_targeted = pieces.size();
      step.difference_energy = add_difference_terms(pieces, directions, w2);
      // Q is positive semidefinite in exact arithmetic but can be singular (e.g. on regular
      // grids); rounding then leaves tiny negative pivots. A relative 1e-10 on the diagonal makes
      // the program strictly convex and changes the solution negligibly.
      trace += difference_trace_;
      const double regularization = 1e-10 * trace / double((std::max)(n, std::size_t(1)));
      if (regularization > 0 && std::isfinite(regularization))
        for (std::size_t i = 0; i < n; ++i)
          solver_.set_P(i, i, regularization);
      step.target_value =
          w1 * step.fairness_energy + options_.difference_weight * step.difference_energy;
      if (iteration >= options_.max_iterations) {
        report.status = Fairing_report::Status::ITERATION_LIMIT;
        report.history.push_back(step);
        break;
      }

      // Eq. 16: |x_i| <= half the shortest edge at V_i.
      for (std::size_t i = 0; i < n; ++i) {
        const double bound = 0.5 * shortest_edge(region_.movable[i]);
        solver_.set_l(i, -bound);
        solver_.set_u(i, bound);
      }
      std::vector<double> x(n, 0.0);
      // Successive programs are alike: start from the previous solution and its active set.
      if (previous_solution_.size() == n)
        solver_.set_warm_start(previous_solution_);
      step.solver = solver_.solve(x.begin());
      // A solver that ran out of iterations still returns a feasible, improved point: use it.
      const bool usable =
          step.solver.is_optimal() ||
          (step.solver.status == Box_QP_status::ITERATION_LIMIT &&
           std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); }));
      if (!usable) {
        report.history.push_back(step);
        throw Fairing_failure("fair_with_highlight_lines(): the QP solver failed at iteration " +
                                  std::to_string(iteration + 1) + ": " + step.solver.message,
                              report);
      }
      previous_solution_ = x;
      step.step_scale = move_without_flips(x, directions, report);
      double max_x = 0;
      for (double xi : x)
        max_x = (std::max)(max_x, std::abs(xi));
      step.max_displacement = max_x; // of the QP solution; the move applied is step_scale times it
      step.relative_max_displacement = max_x / mean_edge_length_;
      report.history.push_back(step);
      sweeper_.update_positions();
      compute_model();
      const bool go_on = visitor(step);
      report.iterations = iteration + 1; // completed: the visitor returned
      if (!go_on) {
        report.status = Fairing_report::Status::STOPPED_BY_VISITOR;
        break;
      }
      // Eq. 17 on the solution itself: a step shortened against a flip is no convergence.
      if (step.step_scale == 1 && step.relative_max_displacement < options_.convergence_threshold) {
        report.status = Fairing_report::Status::CONVERGED;
        break;
      }
    }
    // The energies of the final mesh.
    if (report.status != Fairing_report::Status::ITERATION_LIMIT) {
      Fairing_report::Iteration last;
      const std::vector<Vec3> directions = movable_normals();
      last.fairness_energy = fairness_value();
      std::vector<Matched_piece> pieces = match_desired_lines();
      last.lines_targeted = pieces.size();
      last.difference_energy = difference_value(pieces);
      last.target_value = options_.fairness_weight * last.fairness_energy +
                          options_.difference_weight * last.difference_energy;
      report.history.push_back(last);
    }
    return report;
  }

  // The model of the current mesh and the desired lines (§3.2), fixed for the whole fairing.
  void make_targets(Fairing_report& report)
  {
    report.number_of_movable_vertices = region_.movable.size();
    compute_model();
    report.number_of_folded_triangles = 0;
    for (std::size_t f = 0; f < region_.face_in_region.size(); ++f)
      if (region_.face_in_region[f] && is_folded(int(f)))
        ++report.number_of_folded_triangles;
    desired_.clear();
    make_desired_lines(report);
  }

  // The movable vertices' points at the start of the current iteration.
  const std::vector<std::pair<vertex_descriptor, Point>>& checkpoint() const { return checkpoint_; }

  const Fairing_region& region() const { return region_; }
  const Sweeper& sweeper() const { return sweeper_; }
  const std::vector<Desired_line>& desired_lines() const { return desired_; }
  const Raw_model& model() const { return model_; }

  // Public for the tests: the rows dQ/dx of the nodes of the current model.
  Node_jacobian jacobian(const std::vector<Vec3>& directions) const
  {
    const Local_mesh<TriangleMesh>& lm = sweeper_.local_mesh();
    return Node_jacobian(lm, region_, sweeper_.vertex_normals(), directions,
                         lights_.base_point_array(), lights_.light_direction_array(),
                         lights_.plane_normal_array());
  }

  std::vector<Vec3> movable_normals() const
  {
    std::vector<Vec3> directions;
    for (int v : region_.movable)
      directions.push_back(sweeper_.vertex_normals().unit_normal(v));
    return directions;
  }

private:
  Vec3 position(int v) const
  {
    const double* p = sweeper_.local_mesh().point(v);
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
    const auto& c = sweeper_.local_mesh().face_vertices[std::size_t(f)];
    const Vec3 p0 = position(c[0]), p1 = position(c[1]), p2 = position(c[2]);
    return cross3({p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]},
                  {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]});
  }
  // Whether the normal of face f opposes (or is orthogonal to) the sum of the unit vertex
  // normals at its corners: a triangle folded over a neighbour.
  bool is_folded(int f) const
  {
    Vec3 corner_normals{0, 0, 0};
    for (int c : sweeper_.local_mesh().face_vertices[std::size_t(f)]) {
      const Vec3 m = sweeper_.vertex_normals().unit_normal(c);
      for (int k = 0; k < 3; ++k)
        corner_normals[std::size_t(k)] += m[std::size_t(k)];
    }
    return !(dot3(face_cross(f), corner_normals) > 0);
  }
  double shortest_edge(int v) const
  {
    double shortest = std::numeric_limits<double>::infinity();
    for (int i = region_.vertex_neighbor_begin[std::size_t(v)];
         i < region_.vertex_neighbor_begin[std::size_t(v) + 1]; ++i)
      shortest = (std::min)(shortest, distance(v, region_.vertex_neighbors[std::size_t(i)]));
    return shortest;
  }

  void compute_model() { sweeper_.compute_raw(lights_, options_.window, false, model_); }

  void take_checkpoint()
  {
    checkpoint_.clear();
    for (int v : region_.movable) {
      const vertex_descriptor vd = sweeper_.local_mesh().vertex_handles[std::size_t(v)];
      checkpoint_.emplace_back(vd, get(vpm_, vd));
    }
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

  // Finds each desired line's piece in the current model (its delimiting nodes lie outside R
  // and never move) and computes the targets of its inner nodes (eq. 12) and their weights
  // (eq. 14).
  std::vector<Matched_piece> match_desired_lines() const
  {
    // key -> (line, position); a node where lines meet (degree > 2) is in several lines
    std::multimap<Node_key, std::pair<std::size_t, std::size_t>> where;
    std::set<Node_key> wanted;
    for (const Desired_line& d : desired_)
      wanted.insert(d.start);
    const auto& lines = model_.lines.lines;
    for (std::size_t l = 0; l < lines.size(); ++l)
      for (std::size_t i = 0; i < lines[l].nodes.size(); ++i) {
        const Node_key key = Node_key::of(model_.node(std::size_t(lines[l].nodes[i])));
        if (wanted.count(key))
          where.emplace(key, std::make_pair(l, i));
      }
    // The piece from position `start` of `line` to the node d.end through nodes inside R.
    auto walk = [&](const Desired_line& d, const Traced_line& line, std::size_t start,
                    int direction, Matched_piece& piece) {
      const long long n = (long long)line.nodes.size();
      piece.nodes.assign(1, line.nodes[start]);
      for (long long k = 1; k <= n; ++k) {
        long long pos = (long long)start + direction * k;
        if (line.closed)
          pos = ((pos % n) + n) % n;
        else if (pos < 0 || pos >= n)
          return false;
        const int id = line.nodes[std::size_t(pos)];
        piece.nodes.push_back(id);
        const Raw_node& node = model_.node(std::size_t(id));
        if (Node_key::of(node) == d.end)
          return piece.nodes.size() > 2;
        if (!node_is_inside(node, region_))
          return false;
      }
      return false;
    };
    std::vector<Matched_piece> matched;
    for (const Desired_line& d : desired_) {
      const auto occurrences = where.equal_range(d.start);
      bool done = false;
      for (auto it = occurrences.first; it != occurrences.second && !done; ++it)
        for (int direction : {1, -1}) {
          Matched_piece piece;
          if (walk(d, lines[it->second.first], it->second.second, direction, piece)) {
            complete_piece(d, piece);
            matched.push_back(std::move(piece));
            done = true;
            break;
          }
        }
    }
    return matched;
  }

  void complete_piece(const Desired_line& d, Matched_piece& piece) const
  {
    std::vector<Vec3> p;
    for (int id : piece.nodes)
      p.push_back(node_point(id));
    std::vector<double> chord(p.size(), 0.0);
    for (std::size_t i = 1; i < p.size(); ++i) {
      const Vec3 e{p[i][0] - p[i - 1][0], p[i][1] - p[i - 1][1], p[i][2] - p[i - 1][2]};
      chord[i] = chord[i - 1] + std::sqrt(dot3(e, e));
    }
    const double total = chord.back() > 0 ? chord.back() : 1;
    for (std::size_t i = 1; i + 1 < p.size(); ++i) {
      piece.targets.push_back(d.curve.point_at_arc_length_fraction(chord[i] / total));
      piece.weights.push_back(0.5 * (chord[i + 1] - chord[i - 1]));
    }
  }

  double difference_value(const std::vector<Matched_piece>& pieces) const
  {
    double value = 0;
    for (const Matched_piece& piece : pieces)
      for (std::size_t i = 0; i < piece.targets.size(); ++i) {
        const Vec3 q = node_point(piece.nodes[i + 1]);
        const Vec3 e{q[0] - piece.targets[i][0], q[1] - piece.targets[i][1],
                     q[2] - piece.targets[i][2]};
        value += piece.weights[i] * dot3(e, e);
      }
    return value / (length_scale_ * length_scale_ * length_scale_);
  }

  // Adds w · Σ l_i ‖Q_i + J_i x − Q̃_i‖² to the solver; returns q_diff at x = 0.
  double add_difference_terms(const std::vector<Matched_piece>& pieces,
                              const std::vector<Vec3>& directions, double w)
  {
    const Node_jacobian J = jacobian(directions);
    const auto& lm = sweeper_.local_mesh();
    difference_trace_ = 0;
    for (const Matched_piece& piece : pieces)
      for (std::size_t i = 0; i < piece.targets.size(); ++i) {
        const Raw_node& node = model_.node(std::size_t(piece.nodes[i + 1]));
        // On an edge almost along a highlight line (its d values differ by a small fraction of
        // the spacing), eq. 13 moves the node by many edge lengths for a small change of d: its
        // linearisation means nothing there, and it would swamp the program. Such nodes still
        // shape the chord-length parameters, but get no term.
        if (node.edge >= 0) {
          const auto& ends = lm.edge_vertices[std::size_t(node.edge)];
          const double D = model_.levels[std::size_t(ends[1])].distance -
                           model_.levels[std::size_t(ends[0])].distance;
          if (!(std::abs(D) >= 0.1 * lights_.spacing_value()))
            continue;
        }
        const Node_jacobian::Row row =
            J.node_row(node, lm.edge_vertices, model_.levels, lights_.spacing_value());
        const Vec3 q = node_point(piece.nodes[i + 1]);
        const Vec3 r{q[0] - piece.targets[i][0], q[1] - piece.targets[i][1],
                     q[2] - piece.targets[i][2]};
        const double l = piece.weights[i];
        // The solver's set_P() adds: one call per pair and node, duplicates summed there.
        for (const auto& a : row) {
          solver_.set_q(std::size_t(a.first), 2 * w * l * dot3(a.second, r));
          for (const auto& b : row)
            if (a.first <= b.first) {
              const double value = 2 * w * l * dot3(a.second, b.second);
              solver_.set_P(std::size_t(a.first), std::size_t(b.first), value);
              if (a.first == b.first)
                difference_trace_ += value;
            }
        }
      }
    return difference_value(pieces);
  }

  std::vector<Vec3> local_points() const
  {
    std::vector<Vec3> points(sweeper_.local_mesh().vertex_handles.size());
    for (std::size_t v = 0; v < points.size(); ++v)
      points[v] = position(int(v));
    return points;
  }

  // The unit normals of the energy vertices, for Fairness_energy::MEAN_CURVATURE.
  const std::vector<Vec3>& energy_normals()
  {
    energy_normals_.clear();
    for (int v : region_.energy_vertices)
      energy_normals_.push_back(sweeper_.vertex_normals().unit_normal(v));
    return energy_normals_;
  }

  // q_fair of the current mesh.
  double fairness_value()
  {
    const std::vector<Vec3> points = local_points();
    return add_willmore_quadratic(
        freeze_willmore_weights(points, sweeper_.local_mesh().face_vertices,
                                region_.energy_vertices),
        points, region_.variable, movable_normals(), [](int, int, double) {}, [](int, double) {},
        options_.fairness_energy == Fairness_energy::MEAN_CURVATURE ? &energy_normals() : nullptr);
  }

  // Adds w · q_fair to the solver and the trace of its matrix to `trace`; returns q_fair at 0.
  double add_fairness_terms(const std::vector<Vec3>& directions, double w, double& trace)
  {
    const std::vector<Vec3> points = local_points();
    const Frozen_willmore_weights frozen = freeze_willmore_weights(
        points, sweeper_.local_mesh().face_vertices, region_.energy_vertices);
    return add_willmore_quadratic(
        frozen, points, region_.variable, directions,
        [&](int a, int b, double value) {
          solver_.set_P(std::size_t(a), std::size_t(b), w * value);
          if (a == b)
            trace += w * value;
        },
        [&](int a, double value) { solver_.set_q(std::size_t(a), w * value); },
        options_.fairness_energy == Fairness_energy::MEAN_CURVATURE ? &energy_normals() : nullptr);
  }

  // Moves the movable vertices by x_i N_i, halving the step while a triangle would flip or
  // degenerate. Flips are judged against the input mesh, not the start of the step: steps that
  // each turn a triangle by less than 90 degrees can add up to a flip. A triangle folded in the
  // input (its normal opposed to the sum of its corners' unit vertex normals) may unfold; it
  // must only stay non-degenerate. Returns the scale applied.
  double move_without_flips(const std::vector<double>& x, const std::vector<Vec3>& directions,
                            Fairing_report& report)
  {
    const auto& lm = sweeper_.local_mesh();
    if (step_faces_.empty()) { // the first step: the mesh and its normals are still the input's
      for (int v : region_.movable)
        for (int i = region_.vertex_face_begin[std::size_t(v)];
             i < region_.vertex_face_begin[std::size_t(v) + 1]; ++i)
          step_faces_.push_back(region_.vertex_faces[std::size_t(i)]);
      std::sort(step_faces_.begin(), step_faces_.end());
      step_faces_.erase(std::unique(step_faces_.begin(), step_faces_.end()), step_faces_.end());
      // Zero for a folded triangle: then any non-degenerate orientation is accepted.
      for (int f : step_faces_)
        input_face_cross_.push_back(is_folded(f) ? Vec3{0, 0, 0} : face_cross(f));
    }
    const std::vector<int>& faces = step_faces_;
    std::vector<Vec3> start(region_.movable.size());
    for (std::size_t i = 0; i < region_.movable.size(); ++i)
      start[i] = position(region_.movable[i]);

    double scale = 1;
    for (int attempt = 0; attempt < 12; ++attempt, scale *= 0.5) {
      std::vector<Vec3> moved(lm.vertex_handles.size());
      for (std::size_t v = 0; v < moved.size(); ++v)
        moved[v] = position(int(v));
      for (std::size_t i = 0; i < region_.movable.size(); ++i)
        for (int k = 0; k < 3; ++k)
          moved[std::size_t(region_.movable[i])][std::size_t(k)] =
              start[i][std::size_t(k)] + scale * x[i] * directions[i][std::size_t(k)];
      bool ok = true;
      for (std::size_t j = 0; j < faces.size() && ok; ++j) {
        const auto& c = lm.face_vertices[std::size_t(faces[j])];
        const Vec3& p0 = moved[std::size_t(c[0])];
        const Vec3& p1 = moved[std::size_t(c[1])];
        const Vec3& p2 = moved[std::size_t(c[2])];
        const Vec3 n = cross3({p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]},
                              {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]});
        const Vec3& reference = input_face_cross_[j];
        ok = reference == Vec3{0, 0, 0} ? dot3(n, n) > 0 : dot3(n, reference) > 0;
      }
      if (!ok)
        continue;
      for (std::size_t i = 0; i < region_.movable.size(); ++i) {
        const Vec3& p = moved[std::size_t(region_.movable[i])];
        put(vpm_, lm.vertex_handles[std::size_t(region_.movable[i])], Point(p[0], p[1], p[2]));
      }
      return scale;
    }
    throw Fairing_failure("fair_with_highlight_lines(): every step, down to 1/2048 of the "
                          "solver's, would flip a triangle",
                          report);
  }

  TriangleMesh& tm_;
  VertexPointMap vpm_;
  Light_setup<GeomTraits> lights_;
  Fairing_options options_;
  Solver& solver_;
  Sweeper sweeper_;
  Fairing_region region_;
  Raw_model model_;
  std::vector<Desired_line> desired_;
  std::vector<std::pair<vertex_descriptor, Point>> checkpoint_;
  std::vector<double> previous_solution_;
  std::vector<Vec3> energy_normals_;
  std::vector<int> step_faces_;        // the faces around movable vertices
  std::vector<Vec3> input_face_cross_; // their input cross products, zero where folded
  double difference_trace_ = 0;        // trace of the q_diff part of the last program
  double mean_edge_length_ = 1, length_scale_ = 1;
};

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_H

// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_IRREGULARITY_SWEEP_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_IRREGULARITY_SWEEP_H

#include <CGAL/Highlight_lines/Highlight_line_irregularity.h>
#include <CGAL/Highlight_lines/Light_setup.h>
#include <CGAL/Highlight_lines/internal/detection/anomaly_regions.h>
#include <CGAL/Highlight_lines/internal/detection/detection_options.h>
#include <CGAL/Highlight_lines/internal/detection/highlight_distance_field.h>
#include <CGAL/Highlight_lines/internal/detection/light_planes.h>
#include <CGAL/Highlight_lines/internal/detection/line_bending.h>
#include <CGAL/Highlight_lines/internal/detection/line_scoring.h>
#include <CGAL/Highlight_lines/internal/detection/mirror_symmetry.h>
#include <CGAL/Highlight_lines/internal/detection/region_assessment.h>
#include <CGAL/Highlight_lines/internal/detection/region_contrast.h>
#include <CGAL/Highlight_lines/internal/detection/regions_across_scales.h>
#include <CGAL/Highlight_lines/internal/detection/sharp_edge_vertices.h>
#include <CGAL/Highlight_lines/internal/vector3.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <functional>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <set>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// The detection of detect_highlight_line_irregularities() on the model mesh of a sweeper: the
// light setups are sampled (light_planes.h), their lines scored (line_scoring.h), the anomalies
// grouped into regions (anomaly_regions.h) and each region assessed (region_contrast.h,
// region_assessment.h), at one scale per sweep_at_scale(); strongest_first() then orders the
// regions of all scales (regions_across_scales.h). The mesh, the sweeper and the lights must
// outlive it.
template <typename TriangleMesh, typename GeomTraits, typename Sweeper, typename VertexIndexMap>
class Irregularity_sweep
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef vector3::Vec3 Vec3;
  static constexpr double pi = 3.14159265358979323846;

public:
  Irregularity_sweep(const TriangleMesh& tm, const Sweeper& sweeper,
                     const Light_setup<GeomTraits>& lights, const Detection_options& options,
                     VertexIndexMap vim)
      : tm_(tm), sweeper_(sweeper), local_(sweeper.local_mesh()), options_(options), vim_(vim),
        nv_(int(local_.number_of_model_vertices)),
        // The model faces in compact vertex ids (the detection works on them only).
        corners_(local_.face_vertices.begin(),
                 local_.face_vertices.begin() + std::ptrdiff_t(local_.number_of_model_faces)),
        adjacency_(corners_, nv_)
  {
    using namespace vector3;
    for (int v = 0; v < nv_; ++v) {
      const std::size_t index = get(vim_, local_.vertex_handles[std::size_t(v)]);
      if (index >= compact_of_index_.size())
        compact_of_index_.resize(index + 1, -1);
      compact_of_index_[index] = v;
    }
    double edge_sum = 0;
    std::size_t edge_count = 0;
    for (const auto& e : local_.edge_vertices) {
      const double* p = local_.point(e[0]);
      const double* q = local_.point(e[1]);
      edge_sum += std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                            (p[2] - q[2]) * (p[2] - q[2]));
      ++edge_count;
    }
    if (edge_count == 0)
      return;
    mean_edge_ = edge_sum / double(edge_count);

    // With the local residual, the mirror symmetry of the surface, if it has one (design is
    // symmetric, defects are not), and the asymmetry of each vertex, computed when needed.
    points_.resize(static_cast<std::size_t>(nv_));
    for (int v = 0; v < nv_; ++v) {
      const double* p = local_.point(v);
      points_[std::size_t(v)] = Vec3{p[0], p[1], p[2]};
    }
    if (options_.local_residual) {
      mirror_ = std::make_unique<Mirror_symmetry>(points_, corners_, mean_edge_);
      mirror_distance_.assign(static_cast<std::size_t>(nv_), -1.0);
    }

    // Unit vertex normals (eq. 3), for the incidence test of the samples.
    normals_.resize(static_cast<std::size_t>(nv_));
    for (int v = 0; v < nv_; ++v) {
      const auto n = sweeper_.vertex_normals().unit_normal(v);
      normals_[std::size_t(v)] = Vec3{n[0], n[1], n[2]};
    }
    // The vertices of sharp edges: the lines kink there by design, so anomalies within one ring
    // of them are not counted, and no region grows across one.
    sharp_ = sharp_edge_vertices(local_, options_.sharp_edge_angle);
    near_sharp_ = sharp_;
    grow_by_rings(adjacency_, 1, near_sharp_);
    minimum_facing_ = std::cos(options_.maximum_incidence_angle * pi / 180);

    // The light planes: `lights`, then (if all sides are looked at) the five other faces of a
    // cube around the mesh, so that every face is scored by the setups of at least one plane.
    planes_ = light_planes_around(lights, points_, options_.all_sides);
    // How many setups score each vertex: those of the planes it faces within the incidence
    // limit.
    scoring_setups_.assign(static_cast<std::size_t>(nv_), 0);
    for (const auto& plane : planes_) {
      const auto z = plane.plane_normal_array();
      for (int v = 0; v < nv_; ++v)
        if (dot(normals_[std::size_t(v)], Vec3{z[0], z[1], z[2]}) >= minimum_facing_)
          scoring_setups_[std::size_t(v)] += std::size_t(options_.orientations * options_.offsets);
    }
  }

  // Whether the mesh has no edge to look at (then no sweep runs).
  bool is_empty() const { return !(mean_edge_ > 0); }

  // One sweep at the scale `scale` (w, in mean edge lengths), the `pass`-th of `passes`: its
  // regions are added to those found; false if `progress(fraction done)` returned false
  // (cancelled). `model_options` are the named parameters of the model of each setup.
  template <typename ModelOptions, typename Progress>
  bool sweep_at_scale(const double scale, const std::size_t pass, const std::size_t passes,
                      const ModelOptions& model_options, Progress progress)
  {
    using namespace vector3;
    auto nearest_vertex = [this](const auto& node) { return nearest_compact_vertex(node); };
    auto on_sharp_edge = [this](const auto& node) { return is_on_sharp_edge(node); };
    const std::size_t total_setups =
        planes_.size() * std::size_t(options_.orientations * options_.offsets);
    Line_bending_scales scales;
    scales.step = scale * mean_edge_ / double(scales.fine_samples);
    // With `local_residual`, the residual's scales (Line_residual_scales): step h = w/4, the
    // fit from 3w/2 to 4w on either side, the centre's mean over w/2 on either side.
    Line_residual_scales residual_scales;
    residual_scales.step = scale * mean_edge_ / 4.0;

    // The lines of every setup, scored (line_scoring.h).
    Line_scoring scoring(normals_, near_sharp_, minimum_facing_, mean_edge_,
                         options_.minimum_bending);
    std::size_t setup_id = 0;
    Highlight_distance_field field; // with the local residual, per orientation
    for (const auto& plane : planes_)
      for (int o = 0; o < options_.orientations; ++o) {
        Light_setup<GeomTraits> turned =
            o == 0 ? plane : plane.rotated(plane.plane_normal(), pi * o / options_.orientations);
        if (options_.local_residual) {
          // Line density from the mesh: the lines at most `w` apart on most of the surface
          // facing them, so that a defect of the detection's size is crossed by about three
          // lines of every setup.
          field.compute(local_, normals_, turned);
          turned =
              with_spacing_from_mesh(turned, field, normals_, minimum_facing_, scale * mean_edge_);
        }
        const auto across = turned.index_direction();
        for (int k = 0; k < options_.offsets; ++k, ++setup_id) {
          const Light_setup<GeomTraits> shifted =
              k == 0 ? turned
                     : turned.translated(across * (turned.spacing() * k / options_.offsets));
          const auto model = sweeper_.compute(shifted, model_options);
          if (options_.local_residual)
            scoring.score_level_residuals(model.nodes(), model.lines(),
                                          shifted.plane_normal_array(), 1 / shifted.spacing_value(),
                                          field, residual_scales, setup_id, nearest_vertex,
                                          on_sharp_edge);
          else
            scoring.score_bending(model.nodes(), model.lines(), shifted.plane_normal_array(),
                                  scales, options_.threshold, setup_id, nearest_vertex);
          if (!progress((double(pass) + double(setup_id + 1) / double(total_setups)) /
                        double(passes)))
            return false; // cancelled: no region
        }
      }
    std::vector<Anomaly>& anomalies = scoring.anomalies;
    std::vector<Scored_sample>& samples = scoring.samples;

    if (options_.local_residual) {
      scoring.divide_by_noise(options_.threshold);
      const std::vector<std::size_t> seeing_setups =
          setups_seeing_vertices(samples, setup_id, adjacency_, sharp_,
                                 (std::max)(1, int(std::ceil(scale))), scoring_setups_);
      // A region must show in a share `minimum_evidence` of the setups that can see it.
      const std::vector<std::size_t> minimum_setups =
          required_setups(seeing_setups, options_.minimum_evidence);
      const double w = scale * mean_edge_;
      // A defect of radius R <= 3w/2 displaces the lines within R of its centre: its anomalies lie
      // in a disc of radius 2w. What the surroundings show is read up to three times as far.
      const double disc = 2 * w, surroundings = 3 * disc;
      const auto regions = group_anomalies_around_peaks(corners_, points_, anomalies, disc,
                                                        options_.margin * mean_edge_, surroundings,
                                                        2 * disc, minimum_setups, sharp_);
      // The clusters the anomalies form when those closer than `detection_scale` edges are joined
      // (without a margin): a defect's stay on their own, those of a fillet, a panel joint or a
      // soft crease chain along it, those of a change of shape at a larger scale over it.
      const int join_rings = (std::max)(1, int(std::ceil(scale)));
      // The cluster of each anomaly of `members` (indices into `anomalies`) among them, and the
      // shape and the area (of its faces) of each cluster.
      auto cluster = [&](const std::vector<std::size_t>& members,
                         std::vector<std::size_t>& cluster_of,
                         std::vector<std::array<double, 2>>& cluster_shape,
                         std::vector<double>& cluster_area) {
        std::vector<Anomaly> subset;
        for (std::size_t i : members)
          subset.push_back(anomalies[i]);
        const auto clusters = group_anomalies(
            corners_, nv_, subset, join_rings, 0,
            std::vector<std::size_t>(static_cast<std::size_t>(nv_), std::size_t(1)), sharp_);
        cluster_of.assign(anomalies.size(), std::size_t(-1));
        cluster_shape.assign(clusters.size(), {0, 0});
        cluster_area.assign(clusters.size(), 0);
        for (std::size_t k = 0; k < clusters.size(); ++k) {
          std::set<int> cluster_vertices;
          for (std::size_t j : clusters[k].anomalies) {
            cluster_of[members[j]] = k;
            cluster_vertices.insert(subset[j].vertex);
          }
          cluster_shape[k] = spreads_of_vertices(points_, cluster_vertices);
          for (int f : clusters[k].faces)
            cluster_area[k] += face_area(f);
        }
      };
      std::vector<std::size_t> all_anomalies(anomalies.size());
      for (std::size_t i = 0; i < anomalies.size(); ++i)
        all_anomalies[i] = i;
      std::vector<std::size_t> cluster_of;
      std::vector<std::array<double, 2>> cluster_shape;
      std::vector<double> cluster_area;
      cluster(all_anomalies, cluster_of, cluster_shape, cluster_area);
      // On a mirror symmetric surface, the anomalies of the design are explained by the
      // symmetry; a defect next to a feature would chain with the feature's anomalies and look
      // elongated. So the shape of a region that holds anomalies near asymmetric vertices (those
      // farther from their mirror image than the surface's own asymmetry, and the vertices
      // within `detection_scale` rings of them) is that of their cluster without the others.
      std::vector<char> asymmetric;
      std::vector<std::size_t> asymmetric_cluster_of;
      std::vector<std::array<double, 2>> asymmetric_shape;
      std::vector<double> asymmetric_area;
      if (mirror_ && mirror_->is_symmetric()) {
        asymmetric.assign(static_cast<std::size_t>(nv_), 0);
        for (int v = 0; v < nv_; ++v) {
          double& a = mirror_distance_[std::size_t(v)];
          if (!(a >= 0))
            a = mirror_->asymmetry(v);
          asymmetric[std::size_t(v)] = a > mirror_->tolerance();
        }
        grow_by_rings(adjacency_, join_rings, asymmetric, sharp_);
        std::vector<std::size_t> members;
        for (std::size_t i = 0; i < anomalies.size(); ++i)
          if (asymmetric[std::size_t(anomalies[i].vertex)])
            members.push_back(i);
        cluster(members, asymmetric_cluster_of, asymmetric_shape, asymmetric_area);
      }
      // The contrast of each region with its surroundings (between `disc` and `surroundings`
      // from its centre), from every scored sample.
      Region_contrast contrast_with_surroundings(points_, adjacency_, sharp_, samples, disc,
                                                 surroundings);
      samples.clear();
      samples.shrink_to_fit();
      for (const auto& region : regions) {
        if (region.anomalies.empty() || region.faces.empty())
          continue;
        const double contrast = contrast_with_surroundings(region, anomalies);
        Highlight_line_irregularity<TriangleMesh> irregularity;
        irregularity.faces.reserve(region.faces.size());
        for (int f : region.faces)
          irregularity.faces.push_back(local_.face_handles[std::size_t(f)]);
        std::set<std::size_t> lines_seen;
        int peak = region.centre;
        for (std::size_t i : region.anomalies) {
          const Anomaly& a = anomalies[i];
          lines_seen.insert(a.line);
          if (a.score > irregularity.score) {
            irregularity.score = a.score;
            peak = a.vertex;
          }
          irregularity.max_bending = (std::max)(irregularity.max_bending, a.bending);
        }
        irregularity.peak_vertex = local_.vertex_handles[std::size_t(peak)];
        irregularity.number_of_anomalies = region.anomalies.size();
        irregularity.number_of_lines = lines_seen.size();
        irregularity.number_of_light_setups = region.setups;
        // The score is the region's contrast with its surroundings, where they have samples
        // enough; else that of its strongest anomaly against the noise of its line.
        if (contrast >= 0)
          irregularity.score = contrast;

        // Local or not: the shape of the cluster of the region's strongest anomaly (its spread
        // along its two main axes, four standard deviations). The fit of a sample sees a defect
        // up to 4w away, so a defect up to the detection's scale (R <= 3w/2) spreads its
        // anomalies over a length of at most 2R + 8w = 11w; longer clusters, or clusters whose
        // faces cover more than a disc of that diameter, are shape at another scale, and those
        // more than twice as long as wide follow a feature.
        std::size_t strongest = region.anomalies.front();
        for (std::size_t i : region.anomalies)
          if (anomalies[i].score > anomalies[strongest].score)
            strongest = i;
        std::array<double, 2> axes = cluster_shape[cluster_of[strongest]];
        double area = cluster_area[cluster_of[strongest]];
        if (!asymmetric.empty()) {
          std::size_t strongest_asymmetric = std::size_t(-1);
          for (std::size_t i : region.anomalies)
            if (asymmetric[std::size_t(anomalies[i].vertex)] &&
                (strongest_asymmetric == std::size_t(-1) ||
                 anomalies[i].score > anomalies[strongest_asymmetric].score))
              strongest_asymmetric = i;
          if (strongest_asymmetric != std::size_t(-1)) {
            axes = asymmetric_shape[asymmetric_cluster_of[strongest_asymmetric]];
            area = asymmetric_area[asymmetric_cluster_of[strongest_asymmetric]];
          }
        }
        // The faces of a cluster reach `join_rings` rings beyond its anomalies, and one more.
        const Anomaly_shape shape =
            anomaly_shape(axes, w, 11 * w, area, (join_rings + 1) * mean_edge_);
        const double seeing =
            double((std::max)(std::size_t(1), scoring_setups_[std::size_t(region.centre)]));
        irregularity.confidence =
            (std::min)(1.0, double(region.setups) / seeing) * shape.slenderness * shape.locality;
        // Design is symmetric: on a mirror symmetric surface, a region whose surface has its
        // mirror image (up to the surface's own asymmetry) is design, however round and
        // isolated; a defect moves its surface by its height away from its mirror image.
        if (mirror_ && mirror_->is_symmetric())
          irregularity.confidence *=
              (std::min)(1.0, std::pow(region_asymmetry(region.faces, region.centre, w) /
                                           mirror_->defect_tolerance(),
                                       2));
        irregularity.kind = kind_of_region(shape, [&] {
          return dent_or_bump_around_centre(local_, points_, corners_, adjacency_, sharp_,
                                            region.faces, region.centre,
                                            normals_[std::size_t(region.centre)]);
        });
        irregularity.scale = scale;
        found_.push_back(std::move(irregularity));
        found_faces_.push_back(region.faces);
        found_centre_.push_back(region.centre);
      }
    } else {
      const int join_rings = (std::max)(1, int(std::ceil(scale)));
      // A region must show in a share `minimum_evidence` of the setups that face it.
      const std::vector<std::size_t> minimum_setups =
          required_setups(scoring_setups_, options_.minimum_evidence);
      const auto regions = group_anomalies(corners_, nv_, anomalies, join_rings, options_.margin,
                                           minimum_setups, sharp_);
      for (const auto& region : regions) {
        if (region.anomalies.empty())
          continue;
        Highlight_line_irregularity<TriangleMesh> irregularity;
        irregularity.faces.reserve(region.faces.size());
        for (int f : region.faces)
          irregularity.faces.push_back(local_.face_handles[std::size_t(f)]);
        std::set<std::size_t> lines_seen, setups_seen;
        for (std::size_t i : region.anomalies) {
          const Anomaly& a = anomalies[i];
          lines_seen.insert(a.line);
          setups_seen.insert(a.setup);
          if (a.score > irregularity.score) {
            irregularity.score = a.score;
            irregularity.peak_vertex = local_.vertex_handles[std::size_t(a.vertex)];
          }
          irregularity.max_bending = (std::max)(irregularity.max_bending, a.bending);
        }
        irregularity.number_of_anomalies = region.anomalies.size();
        irregularity.number_of_lines = lines_seen.size();
        irregularity.number_of_light_setups = setups_seen.size();

        // The shape of the anomalies: their spread along the two main axes (standard deviations
        // of the positions of their vertices, principal axes of the covariance).
        std::set<int> anomaly_vertices;
        for (std::size_t i : region.anomalies)
          anomaly_vertices.insert(anomalies[i].vertex);
        const auto axes = spreads_of_vertices(points_, anomaly_vertices);
        const double w = scale * mean_edge_;
        // A defect is local: the response to one of radius R spreads over R + 3w/2 from its
        // centre, so a defect up to the detection's scale (R <= 3w/2) spreads its anomalies over
        // a length of at most 6w. Larger or longer regions are shape at another scale: design.
        const Anomaly_shape shape = anomaly_shape(axes, w, 6 * w);
        std::size_t seeing = 1;
        for (std::size_t i : region.anomalies)
          seeing = (std::max)(seeing, scoring_setups_[std::size_t(anomalies[i].vertex)]);
        irregularity.confidence = (std::min)(1.0, double(setups_seen.size()) / double(seeing)) *
                                  shape.slenderness * shape.locality;
        irregularity.kind = kind_of_region(shape, [&] {
          int peak = 0; // the strongest anomaly's vertex
          double best = -1;
          for (std::size_t i : region.anomalies)
            if (anomalies[i].score > best) {
              best = anomalies[i].score;
              peak = anomalies[i].vertex;
            }
          return dent_or_bump_at_peak(local_, corners_, region.faces, peak,
                                      normals_[std::size_t(peak)]);
        });
        irregularity.scale = scale;
        found_.push_back(std::move(irregularity));
        found_faces_.push_back(region.faces);
      }
    }
    return true;
  }

  // The regions found, strongest first (by confidence times score); with the local residual, one
  // per place over the scales (select_regions_across_scales()). Moves them out.
  std::vector<Highlight_line_irregularity<TriangleMesh>> strongest_first()
  {
    std::vector<std::size_t> order(found_.size());
    for (std::size_t i = 0; i < found_.size(); ++i)
      order[i] = i;
    std::stable_sort(order.begin(), order.end(), [this](std::size_t a, std::size_t b) {
      return found_[a].confidence * found_[a].score > found_[b].confidence * found_[b].score;
    });
    if (options_.local_residual)
      order = select_regions_across_scales(found_, found_faces_, found_centre_, order, corners_,
                                           std::size_t(nv_));
    std::vector<Highlight_line_irregularity<TriangleMesh>> regions;
    for (std::size_t i : order)
      regions.push_back(std::move(found_[i]));
    return regions;
  }

private:
  // How far a region's surface lies from its mirror image: the k-th largest distance of its
  // vertices' mirror images to the surface, k the number of its vertices within `w` of its
  // centre. A defect moves a disc of about that size away from its mirror image; the largest
  // distance alone is that of the few vertices where a scan is least symmetric, which a region
  // of hundreds of vertices nearly always holds (the shared camel head: 6 design regions passed
  // the automatic mode's level on the undented scan, none since).
  double region_asymmetry(const std::vector<int>& faces, int centre, double w)
  {
    using namespace vector3;
    std::vector<int> vertices;
    for (int f : faces)
      for (int v : corners_[std::size_t(f)])
        vertices.push_back(v);
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    std::vector<double> distances;
    std::size_t near_centre = 0;
    for (int v : vertices) {
      double& a = mirror_distance_[std::size_t(v)];
      if (!(a >= 0))
        a = mirror_->asymmetry(v);
      distances.push_back(a);
      const Vec3 d = points_[std::size_t(v)] - points_[std::size_t(centre)];
      near_centre += dot(d, d) <= w * w;
    }
    if (distances.empty())
      return 0;
    const std::size_t k = (std::min)((std::max)(near_centre, std::size_t(1)), distances.size());
    std::nth_element(distances.begin(), distances.begin() + std::ptrdiff_t(k - 1), distances.end(),
                     std::greater<double>());
    return distances[k - 1];
  }

  // The compact id of a mesh vertex (-1 if it is not a model vertex).
  int compact_vertex(vertex_descriptor v) const
  {
    const std::size_t index = get(vim_, v);
    return index < compact_of_index_.size() ? compact_of_index_[index] : -1;
  }

  // The compact id of the mesh vertex nearest to a highlight node (its vertex, or the nearer end
  // of its edge).
  template <typename Node>
  int nearest_compact_vertex(const Node& node) const
  {
    vertex_descriptor v = node.vertex;
    if (!node.is_on_vertex())
      v = node.parameter < 0.5 ? source(node.halfedge, tm_) : target(node.halfedge, tm_);
    return compact_vertex(v);
  }

  double face_area(int f) const
  {
    using namespace vector3;
    const auto& c = corners_[std::size_t(f)];
    const Vec3& p = points_[std::size_t(c[0])];
    return norm(cross(points_[std::size_t(c[1])] - p, points_[std::size_t(c[2])] - p)) / 2;
  }

  // Whether a highlight node lies on a sharp edge's vertex or on an edge with one: the line
  // kinks there.
  template <typename Node>
  bool is_on_sharp_edge(const Node& node) const
  {
    auto is_sharp = [this](vertex_descriptor v) {
      const int compact = compact_vertex(v);
      return compact >= 0 && sharp_[std::size_t(compact)];
    };
    return node.is_on_vertex()
               ? is_sharp(node.vertex)
               : is_sharp(source(node.halfedge, tm_)) || is_sharp(target(node.halfedge, tm_));
  }

  const TriangleMesh& tm_;
  const Sweeper& sweeper_;
  const typename std::decay_t<decltype(std::declval<const Sweeper&>().local_mesh())>& local_;
  Detection_options options_;
  VertexIndexMap vim_;
  int nv_;
  std::vector<std::array<int, 3>> corners_;
  Vertex_adjacency adjacency_;
  std::vector<int> compact_of_index_;
  double mean_edge_ = 0;
  std::vector<Vec3> points_;
  std::unique_ptr<Mirror_symmetry> mirror_;
  std::vector<double> mirror_distance_;
  std::vector<Vec3> normals_;
  std::vector<char> sharp_, near_sharp_;
  double minimum_facing_ = 1;
  std::vector<Light_setup<GeomTraits>> planes_;
  std::vector<std::size_t> scoring_setups_;
  // The regions of the sweeps so far, with their compact faces and (with the local residual)
  // their compact centre vertex.
  std::vector<Highlight_line_irregularity<TriangleMesh>> found_;
  std::vector<std::vector<int>> found_faces_;
  std::vector<int> found_centre_;
};

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_IRREGULARITY_SWEEP_H

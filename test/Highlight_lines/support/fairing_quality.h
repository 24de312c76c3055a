// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef HIGHLIGHT_LINES_BENCHMARK_FAIRING_QUALITY_H
#define HIGHLIGHT_LINES_BENCHMARK_FAIRING_QUALITY_H

// Quality measures of a faired region, for comparing fairing methods on the same region of the
// same mesh (benchmark_fairing.cpp). Each measure is one small function. All of them take the
// region as a Region_info built once on the input mesh: the fairing methods compared move
// vertices only, so connectivity, the region and its movable vertices are the same before and
// after.
//
// Definitions (as in fair_with_highlight_lines()):
// - a vertex is *inside* the region R when it is not on a mesh border and all its faces are in
//   R; it is *movable* when it and all its neighbours are inside;
// - a highlight node is *inside* R when it lies on a vertex inside R, or inside an edge whose
//   two faces are in R. Nodes outside R never move under any of the compared methods.
//
// Measures:
// - deviation_from_targets(): the highlight line deviation from the desired (OGH) lines of the
//   input: for every node inside R of the faired mesh's model, the distance to the nearest
//   desired curve of the same light index m (curves sampled densely, distance to the
//   polyline); RMS and max over the nodes. Nodes of a level without any desired curve are
//   not measured but counted (`unmatched`).
// - deviation_from_reference(): the same, against the highlight lines of the same level on a
//   reference mesh of the same connectivity (the undented surface: the ground truth).
// - targets_from_reference(): how far the desired lines themselves lie from the reference's
//   lines of their level (their inner sample points, RMS and max): what a fairing that met its
//   targets exactly would reach.
// - willmore_energy_in_region(): the discrete Willmore energy Σ A_i ‖K_i‖² over the vertices
//   inside R (the package's q_fair: eq. 6–8 with the standard factor ½, A_i = ⅓ ring area).
//   Dimensionless. mean_curvature_energy_in_region(): its normal part Σ A_i (K_i · N_i)².
// - largest_normal_jump(): the largest angle (degrees) between the normals of two faces
//   sharing an edge, over the edges of the *moved border*: one face touches a movable vertex
//   (it can change), the other does not (it never changes). That is where the faired surface
//   meets the fixed one, and where a method without G1 boundary conditions leaves a crease.
//   (The border edges of R itself are useless for this: both faces there keep their vertices,
//   since movable vertices lie two rings inside R.) On a fine smooth mesh the value is the
//   discretisation's dihedral angle; compare with the input's and the ground truth's.
// - rms_distance_to_surface(): RMS over the movable vertices of the distance to a reference
//   surface (the undented one).

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Kernel/global_functions_3.h>
#include <CGAL/Highlight_lines/fairing_building_blocks.h>
#include <CGAL/Highlight_lines/internal/fairing/willmore_energy.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/compute_highlight_lines.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <vector>

namespace Highlight_lines_benchmark {

/// The region and what the measures derive from it, built once on the input mesh.
template <typename TriangleMesh>
struct Region_info
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;

  std::vector<face_descriptor> faces;        // R
  std::set<face_descriptor> face_set;        // R, for look-ups
  std::set<vertex_descriptor> inside;        // vertices inside R
  std::vector<vertex_descriptor> movable;    // movable vertices of R
  std::set<vertex_descriptor> movable_set;   // the same, for look-ups
  std::vector<face_descriptor> neighborhood; // R and `rings` rings of faces around it
  double mean_edge_length = 0;               // ē over the edges of R's faces

  Region_info(const TriangleMesh& tm, const std::vector<face_descriptor>& region, int rings = 4)
      : faces(region), face_set(region.begin(), region.end())
  {
    auto is_inside = [&](vertex_descriptor v) {
      for (face_descriptor f : faces_around_target(halfedge(v, tm), tm))
        if (f == boost::graph_traits<TriangleMesh>::null_face() || face_set.count(f) == 0)
          return false;
      return true;
    };
    for (face_descriptor f : faces)
      for (vertex_descriptor v : vertices_around_face(halfedge(f, tm), tm))
        if (is_inside(v))
          inside.insert(v);
    for (vertex_descriptor v : inside) {
      bool ok = true;
      for (vertex_descriptor w : vertices_around_target(halfedge(v, tm), tm))
        ok = ok && inside.count(w) > 0;
      if (ok) {
        movable.push_back(v);
        movable_set.insert(v);
      }
    }
    std::set<face_descriptor> grown(face_set);
    std::vector<face_descriptor> front(faces);
    for (int ring = 0; ring < rings; ++ring) {
      std::vector<face_descriptor> next;
      for (face_descriptor f : front)
        for (vertex_descriptor v : vertices_around_face(halfedge(f, tm), tm))
          for (face_descriptor g : faces_around_target(halfedge(v, tm), tm))
            if (g != boost::graph_traits<TriangleMesh>::null_face() && grown.insert(g).second)
              next.push_back(g);
      front.swap(next);
    }
    neighborhood.assign(grown.begin(), grown.end());
    double sum = 0;
    std::size_t count = 0;
    for (face_descriptor f : faces)
      for (auto h : halfedges_around_face(halfedge(f, tm), tm)) {
        sum += std::sqrt(
            CGAL::to_double(CGAL::squared_distance(get(CGAL::vertex_point, tm, source(h, tm)),
                                                   get(CGAL::vertex_point, tm, target(h, tm)))));
        ++count;
      }
    mean_edge_length = sum / double(count);
  }

  /// Whether a highlight node is inside R (see the file comment).
  template <typename Node>
  bool node_is_inside(const TriangleMesh& tm, const Node& node) const
  {
    if (node.is_on_vertex())
      return inside.count(node.vertex) > 0;
    const face_descriptor f = face(node.halfedge, tm), g = face(opposite(node.halfedge, tm), tm);
    return face_set.count(f) > 0 && face_set.count(g) > 0;
  }
};

/// A desired highlight line with its light index.
template <typename Point_3>
struct Target_curve
{
  long long level = 0;
  std::vector<Point_3> points;
};

/// Distance statistics of highlight nodes to reference curves.
struct Line_deviation
{
  double rms = 0, max = 0;
  std::size_t nodes = 0;     // nodes inside R that were measured
  std::size_t unmatched = 0; // nodes inside R whose level has no reference curve
};

/// The highlight line model of `tm` on the neighbourhood of the region.
template <typename TriangleMesh, typename GeomTraits>
CGAL::Highlight_lines::Highlight_line_model<TriangleMesh, GeomTraits>
model_around_region(const TriangleMesh& tm, const Region_info<TriangleMesh>& info,
                    const CGAL::Highlight_lines::Light_setup<GeomTraits>& lights)
{
  return CGAL::compute_highlight_lines(
      tm, lights, CGAL::Emptyset_iterator(),
      CGAL::Highlight_lines::parameters::face_range(info.neighborhood));
}

/// The desired highlight lines of the region on `input` (desired_highlight_lines(), sampled at
/// `samples` points), each with the light index of its delimiting nodes.
template <typename TriangleMesh, typename GeomTraits>
std::vector<Target_curve<typename GeomTraits::Point_3>>
leveled_desired_highlight_lines(const TriangleMesh& input, const Region_info<TriangleMesh>& info,
                                const CGAL::Highlight_lines::Light_setup<GeomTraits>& lights,
                                std::size_t samples = 64)
{
  typedef typename GeomTraits::Point_3 Point_3;
  std::vector<std::vector<Point_3>> curves;
  CGAL::Highlight_lines::desired_highlight_lines(input, info.faces, lights,
                                                 std::back_inserter(curves), samples);
  const auto model = model_around_region(input, info, lights);
  std::vector<Target_curve<Point_3>> result;
  for (auto& curve : curves) {
    // The curve starts and ends on its delimiting nodes Q0, Q1: find Q0's level.
    double best = std::numeric_limits<double>::infinity();
    long long level = 0;
    for (const auto& node : model.nodes()) {
      const double d = CGAL::to_double(CGAL::squared_distance(node.point, curve.front()));
      if (d < best) {
        best = d;
        level = node.level;
      }
    }
    if (!(best <= 1e-12 * info.mean_edge_length * info.mean_edge_length))
      throw std::runtime_error("a desired line does not start on a highlight node");
    result.push_back({level, std::move(curve)});
  }
  return result;
}

namespace quality_detail {

template <typename Point_3>
using Segments_by_level = std::map<long long, std::vector<std::pair<Point_3, Point_3>>>;

template <typename Point_3>
double squared_distance_to_segments(const Point_3& p,
                                    const std::vector<std::pair<Point_3, Point_3>>& segments)
{
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel K;
  double best = std::numeric_limits<double>::infinity();
  for (const auto& s : segments)
    best = (std::min)(
        best, CGAL::to_double(CGAL::squared_distance(p, typename K::Segment_3(s.first, s.second))));
  return best;
}

// The segments of the lines of `reference` around the region, by level.
template <typename TriangleMesh, typename GeomTraits>
Segments_by_level<typename GeomTraits::Point_3>
reference_segments(const TriangleMesh& reference, const Region_info<TriangleMesh>& info,
                   const CGAL::Highlight_lines::Light_setup<GeomTraits>& lights)
{
  const auto truth = model_around_region(reference, info, lights);
  Segments_by_level<typename GeomTraits::Point_3> segments;
  for (const auto& line : truth.lines()) {
    auto& s = segments[line.level];
    for (std::size_t i = 0; i + 1 < line.nodes.size(); ++i)
      s.emplace_back(truth.nodes()[line.nodes[i]].point, truth.nodes()[line.nodes[i + 1]].point);
    if (line.is_closed && line.nodes.size() > 1)
      s.emplace_back(truth.nodes()[line.nodes.back()].point,
                     truth.nodes()[line.nodes.front()].point);
  }
  return segments;
}

template <typename TriangleMesh, typename Model, typename Point_3>
Line_deviation deviation_of_nodes(const TriangleMesh& tm, const Region_info<TriangleMesh>& info,
                                  const Model& model, const Segments_by_level<Point_3>& reference)
{
  Line_deviation result;
  double sum = 0;
  for (const auto& node : model.nodes()) {
    if (!info.node_is_inside(tm, node))
      continue;
    auto it = reference.find(node.level);
    if (it == reference.end() || it->second.empty()) {
      ++result.unmatched;
      continue;
    }
    const double best = squared_distance_to_segments(node.point, it->second);
    sum += best;
    result.max = (std::max)(result.max, std::sqrt(best));
    ++result.nodes;
  }
  result.rms = result.nodes > 0 ? std::sqrt(sum / double(result.nodes)) : 0.0;
  return result;
}

} // namespace quality_detail

/// Highlight line deviation of `tm` from the desired (OGH) lines `targets`.
template <typename TriangleMesh, typename GeomTraits>
Line_deviation
deviation_from_targets(const TriangleMesh& tm, const Region_info<TriangleMesh>& info,
                       const CGAL::Highlight_lines::Light_setup<GeomTraits>& lights,
                       const std::vector<Target_curve<typename GeomTraits::Point_3>>& targets)
{
  quality_detail::Segments_by_level<typename GeomTraits::Point_3> segments;
  for (const auto& t : targets)
    for (std::size_t i = 0; i + 1 < t.points.size(); ++i)
      segments[t.level].emplace_back(t.points[i], t.points[i + 1]);
  return quality_detail::deviation_of_nodes(tm, info, model_around_region(tm, info, lights),
                                            segments);
}

/// Highlight line deviation of `tm` from the lines of `reference` (same connectivity, e.g. the
/// undented surface).
template <typename TriangleMesh, typename GeomTraits>
Line_deviation
deviation_from_reference(const TriangleMesh& tm, const TriangleMesh& reference,
                         const Region_info<TriangleMesh>& info,
                         const CGAL::Highlight_lines::Light_setup<GeomTraits>& lights)
{
  return quality_detail::deviation_of_nodes(
      tm, info, model_around_region(tm, info, lights),
      quality_detail::reference_segments(reference, info, lights));
}

/// How far the desired lines `targets` (of the input) lie from the lines of the same level on
/// `reference` (the undented surface): the RMS and the largest distance of their inner sample
/// points to the nearest reference segment of their level, in the measure of
/// deviation_from_reference() (`nodes` counts the points). A fairing that met its targets
/// exactly would end this far from the truth's lines.
template <typename TriangleMesh, typename GeomTraits>
Line_deviation
targets_from_reference(const TriangleMesh& reference, const Region_info<TriangleMesh>& info,
                       const CGAL::Highlight_lines::Light_setup<GeomTraits>& lights,
                       const std::vector<Target_curve<typename GeomTraits::Point_3>>& targets)
{
  const auto segments = quality_detail::reference_segments(reference, info, lights);
  Line_deviation result;
  double sum = 0;
  for (const auto& target : targets) {
    auto it = segments.find(target.level);
    for (std::size_t i = 1; i + 1 < target.points.size(); ++i) {
      if (it == segments.end() || it->second.empty()) {
        ++result.unmatched;
        continue;
      }
      const double d = quality_detail::squared_distance_to_segments(target.points[i], it->second);
      sum += d;
      result.max = (std::max)(result.max, std::sqrt(d));
      ++result.nodes;
    }
  }
  result.rms = result.nodes > 0 ? std::sqrt(sum / double(result.nodes)) : 0.0;
  return result;
}

namespace quality_detail {

// The region's faces in flat arrays (local vertex ids), and its inside vertices.
struct Region_arrays
{
  std::vector<std::array<double, 3>> positions;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> energy_vertices;
};

template <typename TriangleMesh>
Region_arrays region_arrays(const TriangleMesh& tm, const Region_info<TriangleMesh>& info)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  std::map<vertex_descriptor, int> local;
  Region_arrays r;
  auto id = [&](vertex_descriptor v) {
    auto it = local.find(v);
    if (it != local.end())
      return it->second;
    const auto& p = get(CGAL::vertex_point, tm, v);
    r.positions.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
    return local[v] = int(r.positions.size() - 1);
  };
  for (auto f : info.faces) {
    std::array<int, 3> t{};
    int k = 0;
    for (vertex_descriptor v : vertices_around_face(halfedge(f, tm), tm))
      t[std::size_t(k++)] = id(v);
    r.triangles.push_back(t);
  }
  for (vertex_descriptor v : info.inside)
    r.energy_vertices.push_back(id(v));
  return r;
}

} // namespace quality_detail

/// Discrete Willmore energy of the region (over the vertices inside it).
template <typename TriangleMesh>
double willmore_energy_in_region(const TriangleMesh& tm, const Region_info<TriangleMesh>& info)
{
  const quality_detail::Region_arrays r = quality_detail::region_arrays(tm, info);
  return CGAL::Highlight_lines::internal::willmore_energy(r.positions, r.triangles,
                                                          r.energy_vertices);
}

/// The normal part of the same energy, Σ A_i (K_i · N_i)² = Σ A_i (2 H_i)² with N_i the
/// area-weighted vertex normal (eq. 3): insensitive to the tangential part of K_i, which on an
/// irregular triangulation comes from the triangle shapes rather than from the surface's
/// bending (and which a method moving vertices tangentially, like PMP::fair, can change).
template <typename TriangleMesh>
double mean_curvature_energy_in_region(const TriangleMesh& tm,
                                       const Region_info<TriangleMesh>& info)
{
  namespace HLI = CGAL::Highlight_lines::internal;
  const quality_detail::Region_arrays r = quality_detail::region_arrays(tm, info);
  const auto& positions = r.positions;
  const auto& energy_vertices = r.energy_vertices;
  std::vector<std::array<double, 3>> normal(positions.size(), {0.0, 0.0, 0.0});
  for (const auto& t : r.triangles) {
    const auto& p0 = positions[std::size_t(t[0])];
    const auto& p1 = positions[std::size_t(t[1])];
    const auto& p2 = positions[std::size_t(t[2])];
    const std::array<double, 3> a{p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
    const std::array<double, 3> b{p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
    const std::array<double, 3> c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                  a[0] * b[1] - a[1] * b[0]};
    for (int corner : t)
      for (int k = 0; k < 3; ++k)
        normal[std::size_t(corner)][std::size_t(k)] += c[std::size_t(k)];
  }
  const HLI::Frozen_willmore_weights frozen =
      HLI::freeze_willmore_weights(positions, r.triangles, energy_vertices);
  double energy = 0;
  for (std::size_t row = 0; row < energy_vertices.size(); ++row) {
    const std::array<double, 3> K = HLI::mean_curvature_normal(frozen, row, positions);
    const auto& n = normal[std::size_t(energy_vertices[row])];
    const double kn = (K[0] * n[0] + K[1] * n[1] + K[2] * n[2]) /
                      std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    energy += frozen.area[row] * kn * kn;
  }
  return energy;
}

/// Largest angle (degrees) between the normals of adjacent faces across the moved border (see
/// the file comment).
template <typename TriangleMesh>
double largest_normal_jump(const TriangleMesh& tm, const Region_info<TriangleMesh>& info)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  auto moved = [&](face_descriptor f) {
    for (auto v : vertices_around_face(halfedge(f, tm), tm))
      if (info.movable_set.count(v))
        return true;
    return false;
  };
  auto normal = [&](face_descriptor f) {
    const auto h = halfedge(f, tm);
    const auto& p = get(CGAL::vertex_point, tm, source(h, tm));
    const auto& q = get(CGAL::vertex_point, tm, target(h, tm));
    const auto& r = get(CGAL::vertex_point, tm, target(next(h, tm), tm));
    const auto n = CGAL::cross_product(q - p, r - p);
    return n / std::sqrt(CGAL::to_double(n.squared_length()));
  };
  double largest = 0;
  for (face_descriptor f : info.faces) {
    if (!moved(f))
      continue;
    for (auto h : halfedges_around_face(halfedge(f, tm), tm)) {
      const face_descriptor g = face(opposite(h, tm), tm);
      if (g == boost::graph_traits<TriangleMesh>::null_face() || moved(g))
        continue;
      const double c = (std::max)(-1.0, (std::min)(1.0, CGAL::to_double(normal(f) * normal(g))));
      largest = (std::max)(largest, std::acos(c) * 180 / 3.14159265358979323846);
    }
  }
  return largest;
}

/// RMS distance of the movable vertices of `tm` to the surface of `reference` around the
/// region.
template <typename TriangleMesh>
double rms_distance_to_surface(const TriangleMesh& tm, const TriangleMesh& reference,
                               const Region_info<TriangleMesh>& info)
{
  typedef typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type
      Point_3;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel K;
  typedef typename K::Triangle_3 Triangle_3;
  typedef typename std::vector<Triangle_3>::const_iterator Iterator;
  typedef CGAL::AABB_triangle_primitive<K, Iterator> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;
  std::vector<Triangle_3> triangles;
  for (auto f : info.neighborhood) {
    const auto h = halfedge(f, reference);
    triangles.emplace_back(
        get(CGAL::vertex_point, reference, source(h, reference)),
        get(CGAL::vertex_point, reference, target(h, reference)),
        get(CGAL::vertex_point, reference, target(next(h, reference), reference)));
  }
  Tree tree(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();
  double sum = 0;
  for (auto v : info.movable)
    sum += CGAL::to_double(tree.squared_distance(get(CGAL::vertex_point, tm, v)));
  return std::sqrt(sum / double((std::max)(info.movable.size(), std::size_t(1))));
}

} // namespace Highlight_lines_benchmark

#endif // HIGHLIGHT_LINES_BENCHMARK_FAIRING_QUALITY_H

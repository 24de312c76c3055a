// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_DETECT_HIGHLIGHT_LINE_IRREGULARITIES_H
#define CGAL_DETECT_HIGHLIGHT_LINE_IRREGULARITIES_H

#include <CGAL/Highlight_lines/Highlight_line_irregularity.h>
#include <CGAL/Highlight_lines/Highlight_line_sweeper.h>
#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/Highlight_lines/Light_setup.h>
#include <CGAL/Highlight_lines/parameters.h>
#include <CGAL/Highlight_lines/internal/anomaly_regions.h>
#include <CGAL/Highlight_lines/internal/line_bending.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

struct Detection_options
{
  int orientations = 3;
  int offsets = 2;
  double scale = 3.0;     // w, in mean edge lengths
  double threshold = 5.0; // robust z-score
  double minimum_bending = 0.01;
  double minimum_evidence = 0.5; // fraction of the light setups
  int margin = 2;
  double maximum_incidence_angle = 60; // degrees

  template <typename NamedParameters>
  explicit Detection_options(const NamedParameters& np)
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    const double o = double(
        choose_parameter(get_parameter(np, internal_np::number_of_orientations), orientations));
    const double k =
        double(choose_parameter(get_parameter(np, internal_np::number_of_offsets), offsets));
    scale = double(choose_parameter(get_parameter(np, internal_np::detection_scale), scale));
    threshold =
        double(choose_parameter(get_parameter(np, internal_np::detection_threshold), threshold));
    minimum_bending =
        double(choose_parameter(get_parameter(np, internal_np::minimum_bending), minimum_bending));
    minimum_evidence = double(
        choose_parameter(get_parameter(np, internal_np::minimum_evidence), minimum_evidence));
    const double m =
        double(choose_parameter(get_parameter(np, internal_np::region_margin), margin));
    maximum_incidence_angle = double(choose_parameter(
        get_parameter(np, internal_np::maximum_incidence_angle), maximum_incidence_angle));
    auto require = [](bool ok, const char* what) {
      if (!ok)
        throw Invalid_input(Invalid_input::Problem::INVALID_PARAMETER, what);
    };
    require(o >= 1 && o <= 64, "number_of_orientations must be in [1, 64]");
    require(k >= 1 && k <= 64, "number_of_offsets must be in [1, 64]");
    require(scale >= 1 && scale <= 1000, "detection_scale must be in [1, 1000] mean edge lengths");
    require(threshold > 0 && std::isfinite(threshold), "detection_threshold must be positive");
    require(minimum_bending >= 0 && std::isfinite(minimum_bending),
            "minimum_bending must be finite and not negative");
    require(minimum_evidence > 0 && minimum_evidence <= 1, "minimum_evidence must be in (0, 1]");
    require(m >= 0 && m <= 1000, "region_margin must be in [0, 1000] rings");
    require(maximum_incidence_angle > 0 && maximum_incidence_angle <= 90,
            "maximum_incidence_angle must be in (0, 90] degrees");
    orientations = int(o);
    offsets = int(k);
    margin = int(m);
  }
};

} // namespace internal
} // namespace Highlight_lines

// One \cgalParam... command per line, as in CGAL's reference pages: not reflowed.
// clang-format off
/*!
\ingroup PkgHighlightLinesRef

Finds the places where the highlight lines of a triangle mesh bend abnormally (dents, bumps,
wiggles, kinks) and returns face regions enclosing them, ready for
`fair_with_highlight_lines()`.

<b>The sweep.</b> The light setup `lights` is rotated within its plane (`number_of_orientations`
directions, `180°/n` apart, about the plane normal through the base point) and, for each
direction, shifted across the lights (`number_of_offsets` positions, `s/k` apart), so that
every part of the surface is crossed by highlight lines of several directions. One highlight
line model is computed per setup, with the vertex normals computed once.

<b>The measure.</b> Each highlight line is resampled at a uniform arc-length step
`h = w/4`, with `w = detection_scale · ē` (`ē` the mean edge length). At a sample `p(s)`, let
`D = p(s+3w/2) - 3p(s+w/2) + 3p(s-w/2) - p(s-3w/2)` (the change of the discrete curvature
vector over one step `w`, times `w²`) and `T` the unit chord `p(s+w/2) - p(s-w/2)`. The bending
\f[ b(s) = \| D - (D \cdot T)\,T \| / w \approx w^2 \| \kappa' N + \kappa \tau B \| \f]
(an angle, in radians) drops the tangential part `-κ²T` of `p'''`, which only says that the
curvature vector turns with the tangent: `b` vanishes on straight lines and circles, is small
along smoothly curved lines, and is large where the curvature changes abruptly. Each sample is
compared with the line's own robust statistics, the median `med` and the normalised median
absolute deviation `σ = 1.4826 MAD` of `b` along that line (for lines with fewer than 32
samples, and as a floor of a quarter of them, those of all lines of the same light setup): a
sample is an anomaly if it is the largest `b` within `w` along its line, its score
`(b - med)/σ` exceeds `detection_threshold` and `b` exceeds `minimum_bending`. Samples closer
than `3w/2` to the end of an open line, and samples where the surface normal makes more than
`maximum_incidence_angle` with the light plane's normal (near the silhouette, `d` grows without
bound and lines crowd beyond what the triangulation resolves), are not scored.

<b>The regions.</b> Each anomaly is attached to the mesh vertex nearest to it. Anomalies less
than `detection_scale` edges apart form a cluster; clusters seen in fewer than a fraction
`minimum_evidence` of the light setups are discarded as noise (a defect bends the lines of
every direction; triangulation noise rarely lines up across setups). Each remaining cluster
grows by `region_margin` rings of edges, clusters that meet merge, and the region is the set
of faces with a vertex in the grown cluster. Regions are disjoint and written by decreasing
score.

A defect is only seen where several lines cross it: the lights' spacing and
`number_of_offsets` set how small a defect can be found. Design features where the lines kink
on purpose (creases, panel joints) are reported too; restrict the search with `face_range`.

The measure and the regions are invariant under rigid motions and uniform scalings of the mesh
and the lights together, and independent of the mesh's face order.

\tparam TriangleMesh a model of `FaceGraph` whose faces are triangles
\tparam GeomTraits a model of `Kernel`
\tparam OutputIterator an output iterator accepting
        `Highlight_lines::Highlight_line_irregularity<TriangleMesh>`
\tparam NamedParameters a sequence of named parameters

\param tm the mesh
\param lights the light setup the sweep starts from; its spacing sets the density of the lines
(`Highlight_lines::default_light_setup()` is a good start)
\param out receives the regions found, the strongest first
\param np an optional sequence of named parameters among:
  \cgalNamedParamsBegin
    \cgalParamNBegin{Highlight_lines::parameters::number_of_orientations}
      \cgalParamDescription{number of light directions of the sweep, in `[1, 64]`}
      \cgalParamType{`int`}
      \cgalParamDefault{`3`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::number_of_offsets}
      \cgalParamDescription{number of shifts of the lights per direction, in `[1, 64]`}
      \cgalParamType{`int`}
      \cgalParamDefault{`2`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::detection_scale}
      \cgalParamDescription{the scale `w` of the bending measure, in mean edge lengths, in `[1, 1000]`; defects much smaller than `w` are averaged out, much larger ones look like smooth bending}
      \cgalParamType{`double`}
      \cgalParamDefault{`3`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::detection_threshold}
      \cgalParamDescription{the robust z-score above which a sample is an anomaly}
      \cgalParamType{`double`}
      \cgalParamDefault{`5`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::minimum_bending}
      \cgalParamDescription{the bending (radians) below which no sample is an anomaly, whatever its score: keeps numerical noise on very regular meshes from counting}
      \cgalParamType{`double`}
      \cgalParamDefault{`0.01`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::minimum_evidence}
      \cgalParamDescription{the fraction of the light setups of the sweep in which a region must show anomalies, in `(0, 1]`}
      \cgalParamType{`double`}
      \cgalParamDefault{`0.5`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::region_margin}
      \cgalParamDescription{rings of edges added around the anomalies; the fairing needs the defect's whole support inside the region, and the region's border ring is fixed}
      \cgalParamType{`int`}
      \cgalParamDefault{`2`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::face_range}
      \cgalParamDescription{search these faces only}
      \cgalParamType{a class model of `ConstRange` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as value type}
      \cgalParamDefault{all faces of `tm`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::maximum_incidence_angle}
      \cgalParamDescription{the largest angle (degrees, in `(0, 90]`) between a vertex normal and the light plane's normal at which the lines are scored}
      \cgalParamType{`double`}
      \cgalParamDefault{`60`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::max_levels_per_edge}
      \cgalParamDescription{as for `compute_highlight_lines()`, for every light setup of the sweep (`level_range` is ignored: the setups are rotated)}
      \cgalParamType{`std::size_t`}
      \cgalParamDefault{`256`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::facing_side_only}
      \cgalParamDescription{as for `compute_highlight_lines()`, for every light setup of the sweep}
      \cgalParamType{`bool`}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{as for `compute_highlight_lines()`}
      \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `GeomTraits::Point_3` as value type}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_index_map}
      \cgalParamDescription{as for `compute_highlight_lines()`}
      \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `std::size_t` as value type}
      \cgalParamDefault{as for `compute_highlight_lines()`}
    \cgalParamNEnd
    \cgalParamNBegin{face_index_map}
      \cgalParamDescription{as for `compute_highlight_lines()`}
      \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type}
      \cgalParamDefault{as for `compute_highlight_lines()`}
    \cgalParamNEnd
    \cgalParamNBegin{halfedge_index_map}
      \cgalParamDescription{as for `compute_highlight_lines()`}
      \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type and `std::size_t` as value type}
      \cgalParamDefault{as for `compute_highlight_lines()`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

\returns `out`, past the last region written.

\throws Highlight_lines::Invalid_input for the input `compute_highlight_lines()` rejects, or
a named parameter out of its domain. The mesh is only read.

\sa `detect_and_fair_highlight_line_irregularities()` to repair every region found.
*/
// clang-format on
template <typename TriangleMesh, typename GeomTraits, typename OutputIterator,
          typename NamedParameters = parameters::Default_named_parameters>
OutputIterator detect_highlight_line_irregularities(
    const TriangleMesh& tm, const Highlight_lines::Light_setup<GeomTraits>& lights,
    OutputIterator out, const NamedParameters& np = parameters::default_values())
{
  namespace HL = Highlight_lines;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using namespace HL::internal::vector3;
  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  typedef typename Graph_traits::vertex_descriptor vertex_descriptor;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type Vertex_point_map;
  typedef HL::Highlight_line_sweeper<TriangleMesh, Vertex_point_map, GeomTraits> Sweeper;

  const HL::internal::Detection_options options(np);
  const Sweeper sweeper(tm, np); // checks the mesh
  const auto& local = sweeper.local_mesh();

  // The model faces in compact vertex ids (the detection works on them only).
  const std::size_t nf = local.number_of_model_faces;
  std::vector<std::array<int, 3>> corners(local.face_vertices.begin(),
                                          local.face_vertices.begin() + std::ptrdiff_t(nf));
  const int nv = int(local.number_of_model_vertices);
  auto vim = get_initialized_vertex_index_map(tm, np);
  std::vector<int> compact_of_index;
  for (int v = 0; v < nv; ++v) {
    const std::size_t index = get(vim, local.vertex_handles[std::size_t(v)]);
    if (index >= compact_of_index.size())
      compact_of_index.resize(index + 1, -1);
    compact_of_index[index] = v;
  }
  double edge_sum = 0;
  std::size_t edge_count = 0;
  for (const auto& e : local.edge_vertices) {
    const double* p = local.point(e[0]);
    const double* q = local.point(e[1]);
    edge_sum += std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                          (p[2] - q[2]) * (p[2] - q[2]));
    ++edge_count;
  }
  if (edge_count == 0)
    return out;
  const double mean_edge = edge_sum / double(edge_count);

  HL::internal::Line_bending_scales scales;
  scales.step = options.scale * mean_edge / double(scales.fine_samples);

  // Only the options that make sense for every setup of the sweep.
  const auto model_options = HL::parameters::facing_side_only(
      HL::parameters::max_levels_per_edge(
          choose_parameter(get_parameter(np, HL::internal_np::max_levels_per_edge), 256)),
      choose_parameter(get_parameter(np, HL::internal_np::facing_side_only), true));

  const double pi = 3.14159265358979323846;
  // Unit vertex normals (area-weighted), for the incidence test of the samples.
  std::vector<Vec3> normals(std::size_t(nv), Vec3{0, 0, 0});
  for (const auto& f : local.face_vertices) {
    const double *a = local.point(f[0]), *b = local.point(f[1]), *c = local.point(f[2]);
    const Vec3 n = cross(Vec3{b[0] - a[0], b[1] - a[1], b[2] - a[2]},
                         Vec3{c[0] - a[0], c[1] - a[1], c[2] - a[2]});
    for (int v : f)
      if (v < nv)
        normals[std::size_t(v)] = normals[std::size_t(v)] + n;
  }
  for (Vec3& n : normals) {
    const double length = norm(n);
    n = length > 0 ? (1 / length) * n : Vec3{0, 0, 0};
  }
  const double minimum_facing = std::cos(options.maximum_incidence_angle * pi / 180);

  // Only the peaks of the bending along a line count (one per stencil width w): the stencil
  // spreads a defect's response over 3w/2 to either side, the peak stays on the defect.
  const std::ptrdiff_t peak_window = scales.fine_samples;
  auto is_local_maximum = [peak_window](const std::vector<double>& bending, std::size_t i,
                                        bool closed) {
    const std::ptrdiff_t n = std::ptrdiff_t(bending.size());
    for (std::ptrdiff_t d = -peak_window; d <= peak_window; ++d) {
      std::ptrdiff_t j = std::ptrdiff_t(i) + d;
      if (closed)
        j = ((j % n) + n) % n;
      if (d == 0 || j < 0 || j >= n)
        continue;
      // Values equal up to rounding (plateaus are common: the line is piecewise linear) tie,
      // and ties go to the first sample, so a plateau yields one peak wherever rounding
      // leaves its maximum.
      const double other = bending[std::size_t(j)], tolerance = 1e-9 * bending[i];
      if (other > bending[i] + tolerance || (other >= bending[i] - tolerance && d < 0))
        return false;
    }
    return true;
  };

  std::vector<HL::internal::Anomaly> anomalies;
  std::size_t line_id = 0, setup_id = 0;
  std::vector<Vec3> polyline;
  std::vector<std::vector<int>> sample_vertices;
  std::vector<HL::internal::Line_bending> bendings;
  for (int o = 0; o < options.orientations; ++o) {
    const HL::Light_setup<GeomTraits> turned =
        o == 0 ? lights : lights.rotated(lights.plane_normal(), pi * o / options.orientations);
    const auto across = turned.index_direction();
    for (int k = 0; k < options.offsets; ++k, ++setup_id) {
      const HL::Light_setup<GeomTraits> shifted =
          k == 0 ? turned : turned.translated(across * (turned.spacing() * k / options.offsets));
      const auto model = sweeper.compute(shifted, model_options);
      const auto& nodes = model.nodes();
      const auto& lines = model.lines();

      bendings.resize(lines.size());
      sample_vertices.resize(lines.size());
      const auto z = shifted.plane_normal_array();
      std::vector<double> pooled;
      for (std::size_t l = 0; l < lines.size(); ++l) {
        polyline.clear();
        for (std::size_t n : lines[l].nodes) {
          const auto& p = nodes[n].point;
          polyline.push_back(
              {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
        }
        HL::internal::compute_line_bending(polyline, lines[l].is_closed, scales, bendings[l]);
        // Each sample's mesh vertex; samples where the surface turns too far away from the
        // lights are not scored.
        std::vector<double>& bending = bendings[l].bending;
        sample_vertices[l].assign(bending.size(), -1);
        for (std::size_t i = 0; i < bending.size(); ++i) {
          if (bending[i] < 0)
            continue;
          const auto& node = nodes[lines[l].nodes[bendings[l].nearest_vertex[i]]];
          vertex_descriptor v = node.vertex;
          if (!node.is_on_vertex())
            v = node.parameter < 0.5 ? source(node.halfedge, tm) : target(node.halfedge, tm);
          const std::size_t index = get(vim, v);
          const int compact = index < compact_of_index.size() ? compact_of_index[index] : -1;
          if (compact < 0 ||
              dot(normals[std::size_t(compact)], Vec3{z[0], z[1], z[2]}) < minimum_facing) {
            bending[i] = -1;
            continue;
          }
          sample_vertices[l][i] = compact;
          pooled.push_back(bending[i]);
        }
      }
      const HL::internal::Robust_statistics setup_stats = HL::internal::robust_statistics(pooled);

      for (std::size_t l = 0; l < lines.size(); ++l, ++line_id) {
        HL::internal::Robust_statistics stats =
            HL::internal::robust_statistics(bendings[l].bending);
        if (stats.count < 32)
          stats = setup_stats;
        const double deviation = (std::max)({stats.deviation, 0.25 * setup_stats.deviation,
                                             1e-3 * options.minimum_bending, 1e-300});
        const auto& bending = bendings[l].bending;
        for (std::size_t i = 0; i < bending.size(); ++i) {
          if (bending[i] < 0 || !(bending[i] > options.minimum_bending))
            continue;
          const double score = (bending[i] - stats.median) / deviation;
          if (!(score > options.threshold) || !is_local_maximum(bending, i, lines[l].is_closed))
            continue;
          HL::internal::Anomaly a;
          a.vertex = sample_vertices[l][i];
          a.line = line_id;
          a.setup = setup_id;
          a.score = score;
          a.bending = bending[i];
          anomalies.push_back(a);
        }
      }
    }
  }

  const int join_rings = (std::max)(1, int(std::ceil(options.scale)));
  const std::size_t setups = std::size_t(options.orientations * options.offsets);
  const std::size_t minimum_setups = (std::max)(
      std::size_t(1), std::size_t(std::ceil(options.minimum_evidence * double(setups) - 1e-9)));
  const auto regions = HL::internal::group_anomalies(corners, nv, anomalies, join_rings,
                                                     options.margin, minimum_setups);
  std::vector<HL::Highlight_line_irregularity<TriangleMesh>> found;
  for (const auto& region : regions) {
    if (region.anomalies.empty())
      continue;
    HL::Highlight_line_irregularity<TriangleMesh> irregularity;
    irregularity.faces.reserve(region.faces.size());
    for (int f : region.faces)
      irregularity.faces.push_back(local.face_handles[std::size_t(f)]);
    std::set<std::size_t> lines_seen, setups_seen;
    for (std::size_t i : region.anomalies) {
      const HL::internal::Anomaly& a = anomalies[i];
      lines_seen.insert(a.line);
      setups_seen.insert(a.setup);
      if (a.score > irregularity.score) {
        irregularity.score = a.score;
        irregularity.peak_vertex = local.vertex_handles[std::size_t(a.vertex)];
      }
      irregularity.max_bending = (std::max)(irregularity.max_bending, a.bending);
    }
    irregularity.number_of_anomalies = region.anomalies.size();
    irregularity.number_of_lines = lines_seen.size();
    irregularity.number_of_light_setups = setups_seen.size();
    found.push_back(std::move(irregularity));
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const auto& a, const auto& b) { return a.score > b.score; });
  for (auto& irregularity : found)
    *out++ = std::move(irregularity);
  return out;
}

} // namespace CGAL

#endif // CGAL_DETECT_HIGHLIGHT_LINE_IRREGULARITIES_H

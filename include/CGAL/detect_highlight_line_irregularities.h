// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_DETECT_HIGHLIGHT_LINE_IRREGULARITIES_H
#define CGAL_DETECT_HIGHLIGHT_LINE_IRREGULARITIES_H

#include <CGAL/Highlight_lines/Highlight_line_irregularity.h>
#include <CGAL/Highlight_lines/Highlight_line_sweeper.h>
#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/Highlight_lines/Light_setup.h>
#include <CGAL/Highlight_lines/parameters.h>
#include <CGAL/Highlight_lines/internal/detection/detection_options.h>
#include <CGAL/Highlight_lines/internal/detection/irregularity_sweep.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>
#include <type_traits>
#include <utility>

namespace CGAL {

// One \cgalParam... command per line, as in CGAL's reference pages: not reflowed.
// clang-format off
/*!
\ingroup PkgHighlightLinesRef

Finds the places where the highlight lines of a triangle mesh bend abnormally (dents, bumps,
wiggles, kinks) and returns face regions enclosing them, ready for
`fair_with_highlight_lines()`.

<b>The sweep.</b> The light planes are the plane of `lights` and, with `all_sides` (the
default), the five other sides of a cube around the mesh in the frame of `lights` (normals
`±Z`, `±H`, `±H×Z`, each plane as far from the centroid of the vertices as `lights`, with its
spacing `s`): every normal lies within 54.7° of one of their normals, so every face faces some
plane within the default incidence limit and is scored. Each plane's lights are rotated within
the plane (`number_of_orientations` directions, `180°/n` apart, about the plane normal through
the base point) and, for each direction, shifted across the lights (`number_of_offsets`
positions, `s/k` apart), so that every part of the surface is crossed by highlight lines of
several directions. One highlight
line model is computed per setup, with the vertex normals computed once.

<b>Two measures.</b> By default (`local_residual(true)`), each line is scored by how far it
runs sideways from the course a fit of its neighbourhood predicts, and the anomalies are
grouped around their peaks into regions sized to the defect (see "The local residual" below).
`local_residual(false)` scores each line by its bending against the line's own statistics and
groups the anomalies into clusters, the measure closest to the paper's (next paragraphs). On
the shared real meshes with injected dents and bumps, the local residual locates 0.38–0.88 of
them at 0.2 ē and the bending measure almost none (its clusters chain over design until they
cover half of the mesh); its regions are the ones `detect_and_fair_highlight_line_irregularities()`
can repair (see "Measured" below).

<b>The bending measure (`local_residual(false)`).</b> Each highlight line is resampled at a uniform arc-length step
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

<b>Sharp edges.</b> Edges whose two faces' normals make more than 60° (the criterion of
`Polygon_mesh_processing::detect_sharp_edges()`) are feature lines where the lines kink by
design: anomalies within one ring of their vertices are not counted, and no region grows
across them (a region reaches a sharp edge's vertices, never the other side).

<b>The regions (bending measure).</b> Each anomaly is attached to the mesh vertex nearest to it. Anomalies less
than `detection_scale` edges apart form a cluster; clusters seen in fewer than a fraction
`minimum_evidence` of the light setups that score their vertices (those of the planes they
face within the incidence limit) are discarded as noise (a defect bends the lines of
every direction; triangulation noise rarely lines up across setups). Each remaining cluster
grows by `region_margin` rings of edges, clusters that meet merge, and the region is the set
of faces with a vertex in the grown cluster. Regions are disjoint.

<b>Defect or design.</b> A dent or a bump is local and round: its anomalies spread over at
most `2R + 3w` (`R` its radius, up to the scale `3w/2` the measure looks for) in every
direction. A fillet, a panel joint or a soft crease bends the lines all along its length, and
a change of shape at a larger scale bends them over a wide area. Each region gets a `kind`
(`Highlight_lines::Irregularity_kind`: `DENT` or `BUMP` by the side of the smooth quadric its
surroundings predict on which the strongest anomaly lies, `ELONGATED` or `EXTENDED`) and a
`confidence` in [0, 1] (the share of the light setups that saw it, lowered for elongated
regions and below half for extended ones: see
`Highlight_lines::Highlight_line_irregularity::confidence`). Regions are
written by decreasing `confidence * score`: local defects first, design last.

<b>The local residual (the default).</b> The bending is an
angle, bounded, and each sample is judged against its whole line: on scans whose lines bend
everywhere no sample stands out, and the clusters chain over design features until they cover
half of the mesh, so that a defect is "found" without being located. With the local residual,
the lights of each setup are first brought closer (never farther apart) until its lines lie
at most `w` apart on three quarters of the surface facing them (the lines lie `s/|∇d|` apart;
`|∇d|` grows with the curvature, so the flatter parts set the spacing): a defect is only seen
where several lines of a setup cross it, and with the lights' own spacing the flat parts of a
CAD part or of a car body are crossed by a line every 12 to 35 `ē` (30 lights). Then each line is
resampled at `h = w/4` and, at each sample, a quadratic in arc length is fitted (least
squares) to the samples between `3w/2` and `4w` away on both sides, within the stretch of line
that crosses no sharp edge (at least three samples on each side; nearer to a sharp edge or an
end of the line the sample is not scored): the course the line's neighbourhood predicts,
without the part a local defect displaces. The residual is the mean sideways offset (across
the fit's tangent) of the samples within `w/2` from that prediction, converted to levels of
the lights by the gradient of the highlight distance `d/s` at the sample's vertex (a shift
`r` of a line is a change `r·∇d/s` of its level, whatever the spacing of the lines there). It
is unbounded and measures the displacement where a defect is. Each sample's score is the
offset of its level residual from the median of its light setup divided by the robust
deviation of its line (at least a quarter of its setup's, itself at least half the median
over the setups; the setup's alone for lines of fewer than 32 scored samples; never less than
a hundredth of a level: on a plane or a regular grid over a smooth surface the lines are
straight to 1e-15 to 1e-5 of a level, and the grid's own pattern and the far tails of a
defect would stand out against that); anomalies are
the peaks along each line (the largest within `3w/2`) above `detection_threshold`, farther
than one ring from a sharp edge, whose offset exceeds `minimum_bending` mean edge lengths.
They are grouped around their peaks, strongest first, instead of into clusters: the disc of
radius `2w` around an anomaly that holds anomalies of the most distinct light setups is
re-centred on their mean, and becomes a region and claims them if they show in
`minimum_evidence` of the setups that see its centre (that face it within the incidence limit
and scored a sample within `detection_scale` rings of it, not across a sharp edge: lines are
not scored near their ends and near sharp edges, and a defect there cannot show in them)
without the side lobes of earlier regions
(the fit around a defect pulls the samples `3w/2` to `4w` along the same lines the other way:
an anomaly is a lobe if an earlier region has a stronger anomaly on the same line within `4w`
of it; a defect next to a stronger feature keeps the anomalies of its lines that do not cross
the feature); the region is the faces with a vertex within the disc's reach plus
`region_margin` edge lengths of its centre, reached along edges without crossing a sharp edge
or an earlier region. So
regions are sized to the defect (about `2w + margin` in radius, not thousands of faces) and
a defect next to a feature gets its own region. A region's `score` is its contrast with its
surroundings, not with its lines: per light setup that showed it, the offset of its strongest
anomaly from the median of that setup's residuals at the vertices between `2w` and `6w` from
the region's centre (reached along edges, never across a sharp edge) over their robust
deviation (at least a quarter of the noise the anomaly was scored against), the median over
the setups. A defect stands out of a quiet patch; on a scan or a coarse mesh the lines move
about as much around a feature (an eye, an ear, a tessellated fillet) as on it. The `kind` and the `confidence` are those
above, computed on the cluster (anomalies less than `detection_scale` edges apart, chained)
of the region's strongest anomaly, with `11w` in place of `6w` (the fit sees a defect from
`4w` away); a cluster whose faces cover more than the disc of diameter `11w` (grown by the
rings the faces reach beyond the anomalies) is `EXTENDED` too
(on a small or compact mesh, a cluster that wraps around the surface spreads less in space than
along it: on a sculpture of 4,494 vertices, 70 mean edge lengths across, one cluster over most
of the surface measured `13w` in space and covered 1.2 such grown discs).

<b>Design is symmetric (local residual).</b> Designed shapes are mostly mirror
symmetric, and so is their design: a feature has its mirror image, or lies on the plane and is
its own, however round and isolated it is (the Beetle's bump on its midplane, Spot's eyes); a
defect breaks the symmetry by its height. The surface is mirror symmetric about one of the three
planes through the centroid of its vertices normal to their principal axes (a mirror plane is
one of them; an axis whose variance is within 5 % of the largest of another's is not tried: the
axes of such a tie, a square plate's, are set by whatever breaks it, a dent on the plate
included, which then lies on the plane) if three quarters of the vertices have their mirror
image within `ē/10` of the surface. Its own asymmetry is read from those distances twice, both
at least `ē/50`: `a0`, their 99th percentile, marks the asymmetric vertices; `a1`, 8 times their
median, is what a defect must exceed (defects lift the median far less than the 99th
percentile until they and their mirror images cover half of the vertices: four defects 1 `ē`
high over a quarter of the shared Spot's vertices lift `a0` to 0.79 `ē`, `a1` to 0.062 `ē`; a
scan's 99th percentile lies at 4 to 8 times its median).
A region's asymmetry `a` is the `k`-th largest distance of the mirror image of one of its
vertices to the surface, `k` the number of its vertices within `w` of its centre: a defect moves
a disc of about that size away from its mirror image, while a scan holds a few vertices far from
theirs in almost any region of hundreds of vertices. Its confidence is multiplied by
`min(1, (a/a1)²)`. And the shape of a
region that holds anomalies near asymmetric vertices (farther than `a0` from their mirror
image, or within `detection_scale` rings of one) is that of their cluster alone: the anomalies
of the symmetric design next to a defect would chain with its own and make it look elongated.
On a surface without a mirror symmetry nothing changes. A defect centred on the plane (within
about `ē` for the injected defects of radius `5ē`) is its own mirror image and is taken for
design.

<b>Several scales (local residual, `number_of_scales`).</b> The residual at scale `w`
sees defects of radius up to `3w/2`; wider ones move the lines over the fit's window too and
are partly absorbed into the prediction. With `number_of_scales(n)`, the sweep is repeated at
`2w`, ..., `2^(n-1) w` (the lines twice as far apart each time, so each sweep costs about half
the one before). The regions of all scales are taken strongest first, each one unless it shares
a face with one taken before; a region of a coarser scale that holds the centre of a region of
a finer scale takes the faces and the peak of the strongest such (the finer scale places and
sizes a defect more precisely). `Highlight_line_irregularity::scale` says at which scale a
region was strongest. The `kind` of a compact region is the side of the quadric fitted to its
surroundings (over twice its reach) on which its inner vertex farthest from the fit lies.

<b>Measured</b> with `benchmark_detection --shared --seeds 2` (radius 5 ē, 2 × 4 defects per
height per shared mesh; `--bending` for the bending measure): the located recall (the region
holding the defect lies within 3R of it) at 1 / 0.5 / 0.2 / 0.1 ē is .875/.875/.625/.625 on the
beetle, .667/.333/.5/.5 on the bunny, .375/.375/.5/.5 on the camel head, .875/.75/.375/.25 on
the fandisk, .5/.625/.75/.875 on the rocker arm and .875/.875/.875/1 on spot, where the bending
measure locates 0–0.13. The defects found rank above every region of the undented mesh at
0.2 ē in 0.75 of the cases on the beetle, 0.875 on spot, 0.5 on the bunny, 0.375 on the
fandisk, 0.125 on the camel head and 0 on the rocker arm, whose tessellated blends move the
lines more than a defect 0.2 ē high (the camel head's mirror symmetry, a scan's, is accepted
but its own asymmetry, 0.21 ē, is as large as the defects). The fandisk's missed defects lie
within 1.2–4.3 ē of a sharp edge, where the lines are not scored. Regions of confidence ≥ 0.5
(those `detect_and_fair_highlight_line_irregularities()` fairs) hold 44 of the 184 defects
(beetle 12, bunny 5, camel head 4, fandisk 12, rocker arm 0, spot 11) and 10 design regions
over the 48 dented meshes (camel head 1, rocker arm 6, spot 3); the undented meshes have 1
(rocker arm). The bending measure's regions of that confidence hold no defect,
and 11 design regions. On the bundled demo (`benchmark_detection --demo`) the roof dent is the
first region, a `DENT` of confidence 1, and the 33 design regions have confidence 0.0054 at
most. Two scales (`--scales 2`) locate no more defects there and rank fewer above the undented
fandisk, at 1.6 times the cost: one scale is the default. Its precision at 0.2 ē (every region
without a defect counted false) is lower than the bending measure's (beetle 0.185, camel head
0.26, fandisk 0.54, rocker arm 0.31, against 0.38, 0.5, 0.8 and 1: the undented meshes yield 4
to 34 regions of mostly low confidence, the bending measure's few regions are large and hold
defects by covering half of the mesh). The denser lines make it two to three times as slow as
the bending measure (2.5 s against 1.0 s on the shared Beetle, 39k faces, 36 setups; the
symmetry test takes 0.3 s of it).

A defect is only seen where several lines cross it: the lights' spacing and
`number_of_offsets` set how small a defect can be found. Design features that are not sharp
edges (fillets, panel joints) are reported too, as `ELONGATED` or `EXTENDED` regions of low
confidence after the local defects; restrict the search with `face_range`.

The measure and the regions are invariant under rigid motions and uniform scalings of the mesh
and the lights together, and independent of the mesh's face order.

\tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), or `CGAL::Parallel_tag` (needs TBB)
        or `CGAL::Parallel_if_available_tag` to compute each light setup's model in parallel
        (the regions are the same)
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
      \cgalParamDescription{the scale `w` of the measure, in mean edge lengths, in `[1, 1000]`; defects much smaller than `w` are averaged out, much larger ones look like smooth bending}
      \cgalParamType{`double`}
      \cgalParamDefault{`3`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::detection_threshold}
      \cgalParamDescription{the robust z-score above which a sample is an anomaly}
      \cgalParamType{`double`}
      \cgalParamDefault{`5`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::minimum_bending}
      \cgalParamDescription{the sideways offset (mean edge lengths; with `local_residual(false)`, the bending in radians) below which no sample is an anomaly, whatever its score: keeps numerical noise on very regular meshes from counting}
      \cgalParamType{`double`}
      \cgalParamDefault{`0.01`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::minimum_evidence}
      \cgalParamDescription{the fraction of the light setups of the sweep that can see a region (that face it) in which it must show anomalies, in `(0, 1]`}
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
    \cgalParamNBegin{Highlight_lines::parameters::all_sides}
      \cgalParamDescription{whether the sweep also uses the five other sides of a cube around the mesh in the frame of `lights` (so that every face is scored); `false`: the plane of `lights` only, about six times cheaper}
      \cgalParamType{`bool`}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::max_levels_per_edge}
      \cgalParamDescription{for every light setup of the sweep, an edge crossing more levels is left out with its faces (`level_range` is ignored: the setups are rotated; unlike `compute_highlight_lines()`, no level is kept on such an edge: the samples scored face the lights within `maximum_incidence_angle`)}
      \cgalParamType{`std::size_t`}
      \cgalParamDefault{`256`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::facing_side_only}
      \cgalParamDescription{as for `compute_highlight_lines()`, for every light setup of the sweep}
      \cgalParamType{`bool`}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::local_residual}
      \cgalParamDescription{whether the lines are scored by their sideways residual from a local fit and the anomalies grouped around their peaks (see "The local residual" above) rather than by the bending against each line's statistics and grouped into clusters; with it, the spacing of `lights` is only an upper bound (each setup's lights are brought closer until its lines lie at most `w` apart on most of the surface), `minimum_bending` is a sideways offset in mean edge lengths and `Highlight_line_irregularity::max_bending` the largest such offset}
      \cgalParamType{`bool`}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::number_of_scales}
      \cgalParamDescription{with `local_residual`: the number `n` of detection scales, in `[1, 4]`; the sweep is repeated at `w`, `2w`, ..., `2^(n-1) w` (each about half as costly as the one before) and each region keeps its best scale (see "Several scales" above); ignored without `local_residual`}
      \cgalParamType{`int`}
      \cgalParamDefault{`1`}
    \cgalParamNEnd
    \cgalParamNBegin{callback}
      \cgalParamDescription{called after each light setup of the sweep with the fraction of the setups done (in `(0, 1]`); if it returns `false`, the detection stops and writes no region}
      \cgalParamType{a callable with signature `bool(double)`}
      \cgalParamDefault{none}
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
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename GeomTraits, typename OutputIterator,
          typename NamedParameters = parameters::Default_named_parameters>
OutputIterator detect_highlight_line_irregularities(
    const TriangleMesh& tm, const Highlight_lines::Light_setup<GeomTraits>& lights,
    OutputIterator out, const NamedParameters& np = parameters::default_values())
{
  namespace HL = Highlight_lines;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type Vertex_point_map;
  typedef HL::Highlight_line_sweeper<TriangleMesh, Vertex_point_map, GeomTraits, ConcurrencyTag>
      Sweeper;

  // The detection finds creases itself (sharp edges break its lines and bound its regions),
  // and its tables are per mesh vertex: a mesh cut along creases would give a vertex several.
  static_assert(CGAL::parameters::is_default_parameter<NamedParameters,
                                                       HL::internal_np::crease_edge_map_t>::value,
                "detect_highlight_line_irregularities() does not take crease_edge_map: it "
                "treats edges sharper than 60 degrees as creases itself");
  const HL::internal::Detection_options options(np);
  const Sweeper sweeper(tm, np); // checks the mesh
  const auto vim = get_initialized_vertex_index_map(tm, np);
  HL::internal::Irregularity_sweep<TriangleMesh, GeomTraits, Sweeper, std::decay_t<decltype(vim)>>
      detection(tm, sweeper, lights, options, vim);
  if (detection.is_empty())
    return out;

  // Only the options that make sense for every setup of a sweep. An edge crossing more than
  // max_levels_per_edge levels is dropped with its faces, as before the model's facing window:
  // the scoring is tuned on it (with the facing window, the recall on the shared fandisk falls
  // from 5 to 4 of 8 defects in Detection.FindsMostSmallDefectsAnywhereOnSharedCadMeshes).
  const auto some_model_options = HL::parameters::facing_side_only(
      HL::parameters::max_levels_per_edge(
          choose_parameter(get_parameter(np, HL::internal_np::max_levels_per_edge), 256)),
      choose_parameter(get_parameter(np, HL::internal_np::facing_side_only), true));
  const CGAL::Named_function_parameters<bool, HL::internal_np::drop_faces_over_cap_t,
                                        std::decay_t<decltype(some_model_options)>>
      model_options(true, some_model_options);
  // Progress and cancellation (the `callback` named parameter).
  const auto callback =
      choose_parameter(get_parameter(np, internal_np::callback), [](double) { return true; });

  // The bending measure sweeps once. The local residual at scale w sees defects of radius up to
  // 3w/2 (wider ones move the lines over the fit's window too, and are partly absorbed into the
  // prediction), so its sweep can be repeated at 2w, 4w, ... (`number_of_scales`); the lines of
  // each are twice as far apart as those of the one before, so it costs about half as much.
  const std::size_t passes = options.local_residual ? std::size_t(options.scales) : 1;
  for (std::size_t pass = 0; pass < passes; ++pass)
    if (!detection.sweep_at_scale(options.scale * double(std::size_t(1) << pass), pass, passes,
                                  model_options, callback))
      return out; // cancelled: no region
  for (auto& region : detection.strongest_first())
    *out++ = std::move(region);
  return out;
}

} // namespace CGAL

#endif // CGAL_DETECT_HIGHLIGHT_LINE_IRREGULARITIES_H

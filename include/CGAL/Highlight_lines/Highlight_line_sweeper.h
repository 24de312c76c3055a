// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_HIGHLIGHT_LINE_SWEEPER_H
#define CGAL_HIGHLIGHT_LINES_HIGHLIGHT_LINE_SWEEPER_H

#include <CGAL/Highlight_lines/Highlight_line_model.h>
#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/Highlight_lines/Light_setup.h>
#include <CGAL/Highlight_lines/parameters.h>
#include <CGAL/Highlight_lines/internal/model/model_engine.h>
#include <CGAL/Highlight_lines/internal/parallel.h>

#include <CGAL/Default.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/tags.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <array>
#include <limits>
#include <mutex>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// The template arguments of Highlight_line_sweeper, with CGAL::Default resolved.
template <typename TriangleMesh, typename VertexPointMap>
struct Sweeper_vertex_point_map
{
  typedef typename CGAL::Default::Get<
      VertexPointMap,
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::type type;
};

template <typename TriangleMesh, typename VertexPointMap, typename GeomTraits>
struct Sweeper_geom_traits
{
  typedef typename CGAL::Default::Get<
      GeomTraits, typename CGAL::Kernel_traits<
                      typename boost::property_traits<typename Sweeper_vertex_point_map<
                          TriangleMesh, VertexPointMap>::type>::value_type>::Kernel>::type type;
};

} // namespace internal

/*!
\ingroup PkgHighlightLinesRef

Computes highlight line models of one triangle mesh for many light setups, cheaply.

Everything that does not depend on the lights is computed once, in the constructor: a flat
copy of the mesh part the model is computed on, the vertex normals of eq. 3 and the input
checks. `compute()` then only evaluates the highlight distance values, classifies the
vertices against the levels, places the nodes and connects them. This is what an interactive
sweep of the light setup over the surface needs (§3: "translating and rotating ... the array
of linear light sources"); `compute(lights, model)` computes each step into the same model
object, reusing its memory.

When the mesh moves (e.g. during fairing), call `update_positions()`.

With `ConcurrencyTag = CGAL::Parallel_tag` (or `CGAL::Parallel_if_available_tag` when TBB is
linked), the passes over vertices, edges and faces run concurrently with TBB: the face cross
products of the normals (their sums stay in the sequential order), the classification of the
vertices, the placement of the nodes and their connection per face; tracing the lines and
building the model stay sequential. The result is bit for bit the one of the sequential
computation: same nodes, same lines, in the same order.

The `compute()` functions are `const` and may be called on one sweeper from several threads at
once: a call reuses the memory of the previous one unless another call is running, and then
works in its own.

\tparam TriangleMesh a model of `FaceGraph` whose faces are triangles
\tparam VertexPointMap a model of `ReadablePropertyMap` from vertices to points, or
`CGAL::Default` (the internal point map of the mesh)
\tparam GeomTraits a model of `Kernel`, the kernel of the light setups and of the model's
points, or `CGAL::Default` (the kernel of the points)
\tparam ConcurrencyTag enables sequential versus parallel computation. Possible values are
`CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` (requires TBB: a static assertion
fails otherwise) and `CGAL::Parallel_if_available_tag`. For example
`Highlight_line_sweeper<Mesh, CGAL::Default, CGAL::Default, CGAL::Parallel_if_available_tag>`.
*/
template <typename TriangleMesh,
          typename VertexPointMap =
              typename internal::Sweeper_vertex_point_map<TriangleMesh, CGAL::Default>::type,
          typename GeomTraits = typename internal::Sweeper_geom_traits<TriangleMesh, VertexPointMap,
                                                                       CGAL::Default>::type,
          typename ConcurrencyTag = CGAL::Sequential_tag>
class Highlight_line_sweeper
{
  typedef typename internal::Sweeper_vertex_point_map<TriangleMesh, VertexPointMap>::type Vpm;
  typedef typename internal::Sweeper_geom_traits<TriangleMesh, VertexPointMap, GeomTraits>::type Gt;
  // Instantiating Is_parallel checks the tag (and that TBB is there for Parallel_tag).
  static constexpr bool is_parallel = internal::Is_parallel<ConcurrencyTag>::value;
  typedef internal::Raw_model Raw_model;

public:
  /// The type of the models computed.
  typedef Highlight_line_model<TriangleMesh, Gt> Model;
  /// The type of the light setups.
  typedef Light_setup<Gt> Lights;
  /// The concurrency tag.
  typedef ConcurrencyTag Concurrency_tag;

  /*!
  Prepares the computation on `tm`.

  \param tm the mesh; it must outlive the sweeper.
  \param np an optional sequence of named parameters among:
    - `Highlight_lines::parameters::face_range(faces)`: compute the model on these faces only
      (default: all faces). Vertex normals still use the full one-ring of each vertex, so
      the model on a range is the whole mesh's model restricted to the range.
    - `CGAL::parameters::vertex_point_map(vpm)` (default: the internal point map).
    - `CGAL::parameters::vertex_index_map`, `face_index_map`, `halfedge_index_map` (default:
      internal index maps, or dynamic ones initialised here).
    - `Highlight_lines::parameters::crease_edge_map(creases)` (default: none): the models are
      computed on the mesh cut along the edges marked `true` (see \ref hl_creases).

  \throws Invalid_input if a face involved is not a triangle or is degenerate, or a vertex has
  a non-finite coordinate.
  */
  template <typename NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Highlight_line_sweeper(const TriangleMesh& tm,
                                  const NamedParameters& np = CGAL::parameters::default_values())
      : engine_(tm,
                CGAL::parameters::choose_parameter(
                    CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                    get_const_property_map(CGAL::vertex_point, tm)),
                np)
  {
  }

  /// Re-reads the points of all vertices involved from the vertex point map and recomputes
  /// the normals. \throws Invalid_input as the constructor.
  void update_positions() { engine_.update_positions(); }

  /*!
  Computes the highlight line model for `lights`.

  \param lights the light setup.
  \param np an optional sequence of named parameters among:
    - `Highlight_lines::parameters::level_range(std::pair<long long, long long>(lo, hi))`:
      only the lights with index `m` in `[lo, hi]` (default: all).
    - `Highlight_lines::parameters::max_levels_per_edge(n)`: an edge that would carry more
      than `n` nodes (it crosses more than `n` lights: its normals turn almost parallel to
      the light plane) keeps only the nodes of the lights imaged where the surface faces the
      light plane (see `compute_highlight_lines()`); the others are trimmed and counted in
      `Model::number_of_skipped_edges()` and `Model::number_of_trimmed_nodes()`. Default: 256.
    - `Highlight_lines::parameters::facing_side_only(true)`: only the vertices whose normal
      points towards the light plane (`Z·N > 0`) get highlight lines, as a real reflection
      would show them; the paper's definition (the default, `false`) uses the whole normal
      line and also images the lights on the side turned away from them.
  */
  template <typename NamedParameters = CGAL::parameters::Default_named_parameters>
  Model compute(const Lights& lights,
                const NamedParameters& np = CGAL::parameters::default_values()) const
  {
    Model model;
    compute(lights, model, np);
    return model;
  }

  /*!
  Computes the highlight line model for `lights` into `model`, overwriting it and reusing its
  memory: the model of a previous sweep step, of any mesh and light setup, or a
  default-constructed one. The result is the one `compute(lights, np)` returns, bit for bit;
  a sweep that keeps one model object avoids allocating and touching fresh memory for the
  nodes and lines of every step (what an interactive viewer does on each light change).

  \param lights the light setup.
  \param model receives the model.
  \param np an optional sequence of named parameters, as for `compute(lights, np)`.
  */
  template <typename NamedParameters = CGAL::parameters::Default_named_parameters>
  void compute(const Lights& lights, Model& model,
               const NamedParameters& np = CGAL::parameters::default_values()) const
  {
    std::unique_lock<std::mutex> lock(raw_mutex_.mutex, std::try_to_lock);
    Raw_model own; // another thread is computing in raw_
    Raw_model& raw = lock.owns_lock() ? raw_ : own;
    raw.keep_levels = false; // the model needs only the keys and d values
    compute_raw(lights, level_window(np), facing_side_only(np), raw);
    const internal::Highlight_nodes& nodes = raw.nodes;
    const internal::Traced_lines& traced = raw.lines;

    // Nodes that no segment reaches (edges whose faces all lie across a pole or join only the
    // facing window, extrema lying exactly on a level) carry no line; they are sorted last and
    // dropped, as Model::nodes() documents.
    std::size_t kept = traced.new_order.size();
    while (kept > 0 && traced.degree[std::size_t(traced.new_order[kept - 1])] == 0)
      --kept;
    // The nodes already there are overwritten (every field: nothing of the previous content
    // remains), the others built in place (no value-initialised nodes written twice).
    std::vector<typename Model::Node>& model_nodes = model.nodes_to_overwrite();
    const std::size_t overwritten = (std::min)(model_nodes.size(), kept);
    model_nodes.resize(overwritten);
    // A reused model gets some headroom: the next sweep step's few more nodes then move nothing.
    if (model_nodes.capacity() < kept)
      model_nodes.reserve(model_nodes.capacity() == 0 ? kept : kept + kept / 8);
    // Nodes are read in line order, at random: each node and then its edge's halfedge are
    // prefetched ahead (two steps, the halfedge needs the node's edge).
    constexpr std::size_t ahead = 2 * internal::prefetch_distance;
    for (std::size_t i = 0; i < kept; ++i) {
      if (i + ahead < kept) {
        const std::size_t later = std::size_t(traced.new_order[i + ahead]);
        internal::prefetch(&nodes.nodes[later]);
        internal::prefetch(&traced.degree[later]);
        const int edge = nodes.nodes[std::size_t(traced.new_order[i + ahead / 2])].edge;
        if (edge >= 0)
          internal::prefetch(&engine_.local_mesh().edge_halfedges[std::size_t(edge)]);
      }
      const int old_id = traced.new_order[i];
      const internal::Raw_node& raw = nodes.nodes[std::size_t(old_id)];
      typename Model::Node& node = i < overwritten ? model_nodes[i] : model_nodes.emplace_back();
      node.point = typename Gt::Point_3(raw.point[0], raw.point[1], raw.point[2]);
      node.level = raw.level;
      node.degree = std::size_t(traced.degree[std::size_t(old_id)]);
      if (raw.edge >= 0) {
        node.halfedge = engine_.local_mesh().edge_halfedges[std::size_t(raw.edge)];
        node.parameter = raw.parameter;
        node.vertex = boost::graph_traits<TriangleMesh>::null_vertex();
      } else {
        node.halfedge = boost::graph_traits<TriangleMesh>::null_halfedge();
        node.parameter = 0;
        node.vertex = engine_.local_mesh().vertex_handles[std::size_t(raw.vertex)];
      }
    }
    std::vector<typename Model::Line>& model_lines = model.lines_to_overwrite();
    model_lines.resize(traced.lines.size());
    for (std::size_t i = 0; i < traced.lines.size(); ++i) {
      model_lines[i].level = traced.lines[i].level;
      model_lines[i].is_closed = traced.lines[i].closed;
      model_lines[i].nodes.assign(traced.lines[i].nodes.begin(), traced.lines[i].nodes.end());
    }
    model.set_lights_and_counts(lights, raw.segments.segments.size(), nodes.number_of_capped_edges,
                                raw.summary.undefined, raw.summary.out_of_range,
                                nodes.number_of_trimmed_nodes);
  }

  /*!
  Computes the segments of the highlight line model for `lights` without tracing them into
  lines: what a viewer draws on each light change, e.g. as `GL_LINES` through an index buffer.
  `points` receives node positions and `segments` pairs of indices into `points`; both are
  overwritten, and their memory reused.

  The segments are those of the model `compute(lights, np)` returns: each segment between two
  consecutive nodes of one of its lines (the closing segment of a closed line included) is
  in `segments` exactly once, with the same points bit for bit, and there are no others.
  Their order, their directions and the order of `points` are unspecified (but the same with
  every concurrency tag), and `points` may hold nodes that no segment joins (the model leaves
  them out). Tracing the lines into their canonical order and building the model, which this
  leaves out, take a fifth to a quarter of `compute()` on large meshes.

  \tparam Index an integer type of at least 32 bits, e.g. `unsigned int` (OpenGL's
  index buffers) or `std::size_t`
  \param lights the light setup.
  \param points receives the points of the nodes.
  \param segments receives the segments, as indices into `points`.
  \param np an optional sequence of named parameters, as for `compute(lights, np)`.
  */
  template <typename Index, typename NamedParameters = CGAL::parameters::Default_named_parameters>
  void compute_segments(const Lights& lights, std::vector<typename Gt::Point_3>& points,
                        std::vector<std::array<Index, 2>>& segments,
                        const NamedParameters& np = CGAL::parameters::default_values()) const
  {
    static_assert(std::is_integral<Index>::value && sizeof(Index) >= 4,
                  "Index must be an integer type of at least 32 bits");
    std::unique_lock<std::mutex> lock(raw_mutex_.mutex, std::try_to_lock);
    Raw_model own; // another thread is computing in raw_
    Raw_model& raw = lock.owns_lock() ? raw_ : own;
    raw.keep_levels = false;
    compute_raw(lights, level_window(np), facing_side_only(np), raw, false);
    const std::vector<internal::Raw_node>& nodes = raw.nodes.nodes;
    const std::vector<std::array<int, 2>>& raw_segments = raw.segments.segments;
    points.resize(nodes.size());
    segments.resize(raw_segments.size());
    const internal::Chunks chunks =
        internal::chunks_for<ConcurrencyTag>(nodes.size(), std::size_t(1) << 15);
    internal::for_each_chunk<ConcurrencyTag>(chunks,
                                             [&](std::size_t, std::size_t b, std::size_t e) {
                                               for (std::size_t i = b; i < e; ++i) {
                                                 const std::array<double, 3>& p = nodes[i].point;
                                                 points[i] = typename Gt::Point_3(p[0], p[1], p[2]);
                                               }
                                             });
    const internal::Chunks segment_chunks =
        internal::chunks_for<ConcurrencyTag>(raw_segments.size(), std::size_t(1) << 15);
    internal::for_each_chunk<ConcurrencyTag>(
        segment_chunks, [&](std::size_t, std::size_t b, std::size_t e) {
          for (std::size_t i = b; i < e; ++i)
            segments[i] = {Index(raw_segments[i][0]), Index(raw_segments[i][1])};
        });
  }

  /*!
  Writes the highlight distance value `d` (eq. 1) of every vertex of the faces the model is
  computed on into `distances`: the field whose level sets `d = m·s` are the highlight lines
  (a node lies where the linear interpolation of `d` along an edge equals `m·s`, eq. 4), so
  that a viewer's contour filter at the values `m·s` draws them. The values are those the
  model is computed from (a vertex exactly on a level gets exactly `m·s`). A vertex whose `d`
  is undefined (its normal is parallel to the light plane, or `|d/s| >= 2^50`) gets a quiet
  NaN, and so does, with `facing_side_only`, a vertex whose normal points away from the light
  plane.

  \tparam VertexDistanceMap a model of `WritablePropertyMap` with
  `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `double` as value
  type
  \param lights the light setup.
  \param distances receives the values.
  \param np an optional sequence of named parameters among
  `Highlight_lines::parameters::facing_side_only` (default: `false`).
  */
  template <typename VertexDistanceMap,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  void highlight_distances(const Lights& lights, VertexDistanceMap distances,
                           const NamedParameters& np = CGAL::parameters::default_values()) const
  {
    Raw_model model;
    model.keep_levels = true;
    classify(lights, model, facing_side_only(np));
    for (std::size_t v = 0; v < engine_.local_mesh().number_of_model_vertices; ++v) {
      const internal::Vertex_level& level = model.levels[v];
      put(distances, engine_.local_mesh().vertex_handles[v],
          level.defined() ? level.distance : std::numeric_limits<double>::quiet_NaN());
    }
  }

  /// Number of faces the model is computed on.
  std::size_t number_of_faces() const { return engine_.local_mesh().number_of_model_faces; }
  /// Number of vertices of those faces; with `crease_edge_map`, a vertex counts once per
  /// sector of its faces between crease edges.
  std::size_t number_of_vertices() const { return engine_.local_mesh().number_of_model_vertices; }

  /// \cond SKIP_IN_MANUAL
  const internal::Local_mesh<TriangleMesh>& local_mesh() const { return engine_.local_mesh(); }
  const internal::Vertex_normals& vertex_normals() const { return engine_.vertex_normals(); }
  internal::Classification_statistics statistics() const { return engine_.statistics(); }

  const internal::Model_engine<TriangleMesh, Vpm, ConcurrencyTag>& engine() const
  {
    return engine_;
  }

  template <typename NamedParameters>
  static internal::Level_window level_window(const NamedParameters& np)
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    internal::Level_window window;
    const auto range = choose_parameter(get_parameter(np, internal_np::level_range),
                                        std::make_pair(window.lowest, window.highest));
    window.lowest = (std::max)(window.lowest, (long long)(range.first));
    window.highest = (std::min)(window.highest, (long long)(range.second));
    const auto cap = choose_parameter(get_parameter(np, internal_np::max_levels_per_edge),
                                      window.max_levels_per_edge);
    if (!(cap >= 1))
      throw Invalid_input(Invalid_input::Problem::INVALID_PARAMETER,
                          "max_levels_per_edge must be at least 1");
    window.max_levels_per_edge = std::size_t(cap);
    window.keep_facing_levels =
        !choose_parameter(get_parameter(np, internal_np::drop_faces_over_cap), false);
    return window;
  }

  template <typename NamedParameters>
  static bool facing_side_only(const NamedParameters& np)
  {
    return CGAL::parameters::choose_parameter(
        CGAL::parameters::get_parameter(np, internal_np::facing_side_only), false);
  }

  void classify(const Lights& lights, std::vector<internal::Vertex_level>& levels,
                bool facing_side_only = false) const
  {
    engine_.classify(lights, levels, facing_side_only);
  }
  internal::Level_classifier<TriangleMesh> classifier(const Lights& lights) const
  {
    return engine_.classifier(lights);
  }
  /// \endcond

private:
  void compute_raw(const Lights& lights, const internal::Level_window& window,
                   bool facing_side_only, Raw_model& out, bool trace = true) const
  {
    engine_.compute_raw(lights, window, facing_side_only, out, trace);
  }
  void classify(const Lights& lights, Raw_model& out, bool facing_side_only) const
  {
    engine_.classify(lights, out, facing_side_only);
  }

  internal::Model_engine<TriangleMesh, Vpm, ConcurrencyTag> engine_;
  // Reused across sweeps (no reallocation, no page faults) by one call at a time.
  mutable Raw_model raw_;
  mutable internal::Copyable_mutex raw_mutex_;
};

} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_HIGHLIGHT_LINE_SWEEPER_H

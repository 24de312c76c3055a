// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_MODEL_MODEL_ENGINE_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_MODEL_MODEL_ENGINE_H

#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/Highlight_lines/internal/Local_mesh.h>
#include <CGAL/Highlight_lines/internal/crease_cut.h>
#include <CGAL/Highlight_lines/internal/model/highlight_nodes.h>
#include <CGAL/Highlight_lines/internal/model/level_classification.h>
#include <CGAL/Highlight_lines/internal/model/line_tracing.h>
#include <CGAL/Highlight_lines/internal/model/node_connection.h>
#include <CGAL/Highlight_lines/internal/model/vertex_normals.h>
#include <CGAL/Highlight_lines/internal/parallel.h>
#include <CGAL/Highlight_lines/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <cstddef>
#include <mutex>
#include <string>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// A mutex that a copy of its owner gets anew: it guards a cache of the owner, not its value.
struct Copyable_mutex
{
  std::mutex mutex;
  Copyable_mutex() = default;
  Copyable_mutex(const Copyable_mutex&) {}
  Copyable_mutex& operator=(const Copyable_mutex&) { return *this; }
};

// The model in local ids: what Model_engine::compute_raw() produces, before the public
// Highlight_line_model is built from it (the fairing works on it directly).
struct Raw_model
{
  // The classes of the vertices: filled only if keep_levels (the public model does not need
  // them).
  std::vector<Vertex_level> levels;
  bool keep_levels = true;
  std::vector<long long> keys;   // level_key() of each vertex
  std::vector<double> distances; // d of each vertex (Vertex_level::distance)
  Classification_summary summary;
  Highlight_nodes nodes;
  Highlight_segments segments;
  Traced_lines lines;  // node ids in lines are canonical ids: see node()
  Level_window window; // as used: with the facing window of the sweep
  const Raw_node& node(std::size_t canonical_id) const
  {
    return nodes.nodes[std::size_t(lines.new_order[canonical_id])];
  }
};

// The model's pipeline on a flat copy of (part of) a mesh, shared by the public
// Highlight_line_sweeper and the fairing: the local mesh and the vertex normals (eq. 3) are
// built once; compute_raw() then runs the steps of §2 for one light setup: classify the
// vertices against the levels (level_classification.h), place the nodes (highlight_nodes.h),
// connect them (node_connection.h) and trace the lines (line_tracing.h).
template <typename TriangleMesh, typename VertexPointMap, typename ConcurrencyTag>
class Model_engine
{
  static constexpr bool is_parallel = Is_parallel<ConcurrencyTag>::value;

public:
  // `np`: face_range (default: all faces), crease_edge_map (default: none) and the index maps.
  // Throws Invalid_input on a face that is not a triangle or is degenerate, or on a non-finite
  // coordinate.
  template <typename NamedParameters>
  Model_engine(const TriangleMesh& tm, VertexPointMap vpm, const NamedParameters& np) : vpm_(vpm)
  {
    using CGAL::parameters::get_parameter;
    using CGAL::parameters::get_parameter_reference;
    using CGAL::parameters::is_default_parameter;
    auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
    auto fim = CGAL::get_initialized_face_index_map(tm, np);
    auto him = CGAL::get_initialized_halfedge_index_map(tm, np);
    constexpr bool whole_mesh =
        is_default_parameter<NamedParameters, internal_np::face_range_t>::value;
    if constexpr (whole_mesh &&
                  !is_default_parameter<NamedParameters, internal_np::crease_edge_map_t>::value)
      reserve_room_for_cut(tm, get_parameter(np, internal_np::crease_edge_map), mesh_);
    if constexpr (whole_mesh)
      build_local_mesh(tm, faces(tm), true, vpm_, vim, fim, him, mesh_);
    else
      build_local_mesh(tm, get_parameter_reference(np, internal_np::face_range), false, vpm_, vim,
                       fim, him, mesh_);
    if constexpr (!is_default_parameter<NamedParameters, internal_np::crease_edge_map_t>::value)
      cut_at_creases(tm, get_parameter(np, internal_np::crease_edge_map), mesh_);
    compute_normals();
    compute_owned_edges(mesh_, owned_edges_);
  }

  // Re-reads the points from the vertex point map and recomputes the normals.
  void update_positions()
  {
    // Vertex order decides which non-finite coordinate is reported, also when parallel.
    const std::size_t nv = mesh_.vertex_handles.size();
    const Chunks chunks = chunks_for<ConcurrencyTag>(nv, std::size_t(1) << 14);
    std::vector<std::size_t> first_bad(chunks.size(), nv);
    for_each_chunk<ConcurrencyTag>(chunks, [&](std::size_t c, std::size_t b, std::size_t e) {
      for (std::size_t v = b; v < e; ++v) {
        const auto& p = get(vpm_, mesh_.vertex_handles[v]);
        const double x[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                             CGAL::to_double(p.z())};
        if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2])) {
          first_bad[c] = v;
          return;
        }
        for (int k = 0; k < 3; ++k)
          mesh_.xyz[3 * v + std::size_t(k)] = x[k];
      }
    });
    for (std::size_t bad : first_bad)
      if (bad < nv) {
        const auto& p = get(vpm_, mesh_.vertex_handles[bad]);
        const double c[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                             CGAL::to_double(p.z())};
        throw Invalid_input(Invalid_input::Problem::NON_FINITE_COORDINATE,
                            "vertex " + std::to_string(mesh_.vertex_indices[bad]) +
                                " has a non-finite coordinate " + describe_point(c),
                            mesh_.vertex_indices[bad]);
      }
    compute_normals();
  }

  const Local_mesh<TriangleMesh>& local_mesh() const { return mesh_; }
  const Vertex_normals& vertex_normals() const { return normals_; }
  Classification_statistics statistics() const
  {
    std::lock_guard<std::mutex> guard(statistics_mutex_.mutex);
    return statistics_;
  }

  // The model for `lights` within `options`' levels. Without `trace`, out.lines is left as it
  // was (the segments alone need no lines).
  template <typename Lights>
  void compute_raw(const Lights& lights, const Level_window& options, bool facing_side_only,
                   Raw_model& out, bool trace = true) const
  {
    Level_window window = options;
    Highlight_nodes& nodes = out.nodes;
    classify(lights, out, facing_side_only);
    find_active_faces<ConcurrencyTag>(mesh_, owned_edges_, out.keys, window, nodes.active_faces);
    // Active faces do not depend on the facing window (see is_active_face()).
    set_facing_window<ConcurrencyTag>(normals_, lights.plane_normal_array(), out.keys, window);
    out.window = window;
    const std::vector<int>& on_level = out.summary.on_level;
    // Sequentially, the nodes are placed and connected in one pass over the active faces.
    if (!is_parallel && !may_exceed_node_ids(window, nodes.active_faces.size(),
                                             number_of_vertex_nodes(on_level, out.keys, window))) {
      place_and_connect_nodes(mesh_, out.keys, out.distances, on_level, lights.spacing_value(),
                              window, nodes, out.segments);
    } else {
      compute_highlight_nodes<ConcurrencyTag>(mesh_, out.keys, out.distances, on_level,
                                              lights.spacing_value(), window, nodes);
      connect_highlight_nodes<ConcurrencyTag>(mesh_, nodes, window, out.segments);
    }
    if (trace)
      trace_lines(nodes.nodes, out.segments.segments, out.lines);
  }

  // The class of every vertex against the levels of `lights`.
  template <typename Lights>
  void classify(const Lights& lights, std::vector<Vertex_level>& levels,
                bool facing_side_only = false) const
  {
    Raw_model model;
    classify(lights, model, facing_side_only);
    levels = std::move(model.levels);
  }

  template <typename Lights>
  void classify(const Lights& lights, Raw_model& out, bool facing_side_only) const
  {
    Classification_statistics statistics;
    classify_vertices<ConcurrencyTag>(classifier(lights), mesh_.number_of_model_vertices,
                                      facing_side_only, out.keep_levels ? &out.levels : nullptr,
                                      out.keys, out.distances, out.summary, statistics);
    std::lock_guard<std::mutex> guard(statistics_mutex_.mutex);
    statistics_.static_filter_failures += statistics.static_filter_failures;
    statistics_.interval_filter_failures += statistics.interval_filter_failures;
  }

  template <typename Lights>
  Level_classifier<TriangleMesh> classifier(const Lights& lights) const
  {
    return Level_classifier<TriangleMesh>(mesh_, normals_, lights.base_point_array(),
                                          lights.light_direction_array(),
                                          lights.plane_normal_array(), lights.spacing_value());
  }

private:
  void compute_normals() { compute_vertex_normals<ConcurrencyTag>(mesh_, normals_); }

  VertexPointMap vpm_;
  Local_mesh<TriangleMesh> mesh_;
  Vertex_normals normals_;
  std::vector<unsigned char> owned_edges_; // per model face: compute_owned_edges()
  mutable Classification_statistics statistics_;
  mutable Copyable_mutex statistics_mutex_;
};

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_MODEL_MODEL_ENGINE_H

// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_MODEL_HIGHLIGHT_NODES_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_MODEL_HIGHLIGHT_NODES_H

#include <CGAL/Highlight_lines/internal/Local_mesh.h>
#include <CGAL/Highlight_lines/internal/model/level_classification.h>
#include <CGAL/Highlight_lines/internal/parallel.h>
#include <CGAL/Highlight_lines/internal/model/vertex_normals.h>

#include <boost/config.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// Options restricting the model: near silhouettes |d| grows without bound, so one edge can
// cross thousands of levels. The named parameter level_range restricts the levels; an edge
// crossing more than max_levels_per_edge of them keeps only those of the facing window (the
// lights imaged where the surface faces the light plane, see set_facing_window()): the levels
// beyond it are trimmed from the edge, and counted, see compute_highlight_lines().
struct Level_window
{
  long long lowest = -(1LL << 50), highest = (1LL << 50); // levels m considered
  std::size_t max_levels_per_edge = 256;           // edges over it keep only the facing window
  long long facing_lowest = 1, facing_highest = 0; // the facing window; empty by default
  // false: an edge over the cap keeps no level and its faces join none (the rule before the
  // facing window, which the detection's sweeps keep: their tuning rests on it).
  bool keep_facing_levels = true;

  bool contains(long long m) const { return lowest <= m && m <= highest; }
  // Whether an edge could cross more than max_levels_per_edge levels of the window.
  bool may_trim() const
  {
    return highest >= lowest && std::size_t(highest - lowest) >= max_levels_per_edge;
  }
};

// The cosine of the incidence limit of the facing window: vertices whose unit normal makes an
// angle of at most acos(0.05), about 87 degrees, with the normal Z of the light plane (as for
// the vertices that default_light_setup() spreads the lights over).
constexpr double facing_window_cosine = 0.05;

// A highlight node (§2.3): on the interior of an edge (edge >= 0) or on a vertex
// (vertex >= 0) whose d value equals m·s exactly.
struct Raw_node
{
  int edge = -1;
  int vertex = -1;
  long long level = 0;
  double parameter = 0; // along the canonical edge direction, from edge_vertices[edge][0]
  std::array<double, 3> point{};
};

// An active face (see Highlight_nodes::active_faces) with what the sweep passes need of it,
// so that they stream one array instead of gathering from the face arrays of the mesh.
struct Active_face
{
  std::array<int, 3> vertices; // corners; edge j joins corners j and j + 1
  std::array<int, 3> edges;
  int face;
  unsigned owned; // bit j: edge j is owned by this face; bit j + 3: its canonical direction
                  // is from corner j + 1 to corner j (see compute_owned_edges())
  std::array<long long, 3> keys; // of the corners: the later passes gather no keys
};

struct Highlight_nodes
{
  std::vector<Raw_node> nodes;
  // Model faces whose corners are not all strictly inside one level band, by increasing face:
  // the only faces that can carry segments. All edges with nodes and all highlight edges are
  // edges of these faces (the keys of their ends differ, or are even).
  std::vector<Active_face> active_faces;
  // Per edge: the id of its node of lowest level, for the edges with nodes (only those
  // entries are written; the others are stale). The nodes of an edge have consecutive ids,
  // by increasing level from first_interior_level(). Edge nodes are numbered by edge, in
  // edge order; vertex nodes follow, in vertex order.
  std::vector<int> edge_first_node;
  std::vector<int> vertex_node; // per model vertex: its node id, written for vertex nodes only
  std::size_t number_of_edge_nodes = 0;
  // Edges over max_levels_per_edge that lost levels (beyond the facing window), and the nodes
  // they would have carried there.
  std::size_t number_of_capped_edges = 0;
  std::size_t number_of_trimmed_nodes = 0;
};

// The lowest level strictly inside an edge whose ends have bands a != b, within the window.
inline long long first_interior_level(long long band_a, long long band_b,
                                      const Level_window& window)
{
  return (std::max)(band_level((std::min)(band_a, band_b)) + 1, window.lowest);
}

// Eq. 4 (corrected): on edge (V1, V2) with d1 != d2, a node for every m with m·s strictly
// between d1 and d2, at Q = V1 + t (V2 - V1), t = (m·s - d1) / (d2 - d1). Which levels lie
// strictly between is read from the exact vertex classes (their keys), never from the rounded
// d values. Returns the number of those levels the edge keeps (their lowest in `first`): all
// of them within the window; when they are more than window.max_levels_per_edge, only those
// of the facing window, and `trimmed` (if given) is set to the number of levels left out; -1
// (and all of them trimmed) when those are still more than max_levels_per_edge.
inline long long interior_levels(long long key_a, long long key_b, const Level_window& window,
                                 long long& first, long long* trimmed = nullptr)
{
  if (trimmed != nullptr)
    *trimmed = 0;
  if (key_a == key_b || !keys_usable(key_a, key_b))
    return 0; // the common case first: no level strictly inside
  const long long a = key_band(key_a), b = key_band(key_b);
  // Levels m with min(a, b) < 2m < max(a, b).
  first = first_interior_level(a, b, window);
  long long last = (std::min)(band_level((std::max)(a, b) - 1), window.highest);
  if (last < first)
    return 0;
  if (std::size_t(last - first) < window.max_levels_per_edge)
    return last - first + 1;
  const long long all = last - first + 1;
  first = (std::max)(first, window.facing_lowest);
  last = (std::min)(last, window.facing_highest);
  const long long kept = last >= first ? last - first + 1 : 0;
  // Still over the cap inside the facing window (a spacing tiny against the mesh, an edge
  // almost parallel to the light plane): the edge is skipped whole and its faces join no
  // level, as without the facing window; otherwise the model could grow without bound.
  if (std::size_t(kept) > window.max_levels_per_edge) {
    if (trimmed != nullptr)
      *trimmed = all;
    return -1;
  }
  if (trimmed != nullptr)
    *trimmed = all - kept;
  return kept;
}

// Per model face, bit j set when the face is the first, in face order, to have its edge j:
// the face that numbered it (edges are numbered in the order faces first reach them), and
// the one that creates the edge's nodes in a sweep; then bit j + 3 set when the canonical
// direction of that edge (edge_vertices) is from corner j + 1 to corner j.
template <typename TriangleMesh>
void compute_owned_edges(const Local_mesh<TriangleMesh>& lm, std::vector<unsigned char>& owned)
{
  owned.assign(lm.number_of_model_faces, 0);
  std::vector<unsigned char> seen(lm.edge_vertices.size(), 0);
  for (std::size_t f = 0; f < lm.number_of_model_faces; ++f)
    for (int j = 0; j < 3; ++j) {
      const std::size_t e = std::size_t(lm.face_edges[f][std::size_t(j)]);
      if (!seen[e]) {
        seen[e] = 1;
        const bool reversed = lm.edge_vertices[e][0] != lm.face_vertices[f][std::size_t(j)];
        owned[f] = static_cast<unsigned char>(owned[f] | (1u << j) | (reversed ? 8u << j : 0u));
      }
    }
}

// Whether the edge between corners of keys a and b can carry something of the window: a node
// strictly inside (m·s strictly between the d values of its ends, kept or trimmed), or an end
// exactly on a level m of the window (a vertex node of a segment or highlight edge); that is,
// some band 2m of the window lies within the bands of the ends.
inline bool edge_meets_window(long long key_a, long long key_b, const Level_window& window)
{
  if (!keys_usable(key_a, key_b))
    return false;
  const long long a = key_band(key_a), b = key_band(key_b);
  const long long low = (std::max)((std::min)(a, b), 2 * window.lowest),
                  high = (std::min)((std::max)(a, b), 2 * window.highest);
  return low <= high && (!(low & 1) || low < high);
}

// Asks for the cache line of `address` ahead of its use (a hint only: no effect on results).
// Forced inline here and in its callers: GCC finds a function made of prefetches free of side
// effects and drops the calls to it.
BOOST_FORCEINLINE void prefetch(const void* address)
{
#if defined(__GNUC__)
  __builtin_prefetch(address);
#else
  (void)address;
#endif
}

// Prefetches what placing the nodes of an active face reads at random: the d values and
// points of its corners, and the first node ids of its edges. The passes over active faces
// call it a few faces ahead, so that these reads do not wait for memory one after the other.
template <typename TriangleMesh>
BOOST_FORCEINLINE void prefetch_active_face(const Local_mesh<TriangleMesh>& lm,
                                            const Active_face& face, const double* distances,
                                            const int* edge_first_node)
{
  for (int j = 0; j < 3; ++j) {
    const std::size_t v = std::size_t(face.vertices[std::size_t(j)]);
    prefetch(distances + v);
    prefetch(lm.xyz.data() + 3 * v);
    prefetch(lm.xyz.data() + 3 * v + 2); // a point may straddle two cache lines
    prefetch(edge_first_node + face.edges[std::size_t(j)]);
  }
}

// Prefetches the first node ids of the edges of an active face (as the connection reads them).
BOOST_FORCEINLINE void prefetch_edge_first_nodes(const Active_face& face,
                                                 const int* edge_first_node)
{
  for (int j = 0; j < 3; ++j)
    prefetch(edge_first_node + face.edges[std::size_t(j)]);
}

// Active faces ahead of the one processed whose reads are prefetched.
constexpr std::size_t prefetch_distance = 8;

// Whether a face whose corners have these keys can carry a node, a segment or a highlight edge
// of the window. Those that cannot (their three corners strictly inside one level band, or no
// level of the window between their corners) carry none: a segment inside a face lies at a
// level m with 2m between the bands of two of its corners, a node on a face edge between those
// of its ends (and edges trimmed beyond the facing window still have levels of the window
// strictly inside).
inline bool is_active_face(const std::array<long long, 3>& corner_keys, const Level_window& window)
{
  const long long k0 = corner_keys[0];
  if (k0 == corner_keys[1] && k0 == corner_keys[2] && (k0 & 1))
    return false;
  return edge_meets_window(k0, corner_keys[1], window) ||
         edge_meets_window(corner_keys[1], corner_keys[2], window) ||
         edge_meets_window(corner_keys[2], k0, window);
}

// The faces that can carry a node, a segment or a highlight edge of the window (see
// is_active_face()), in face order.
template <typename ConcurrencyTag, typename TriangleMesh>
void find_active_faces(const Local_mesh<TriangleMesh>& lm,
                       const std::vector<unsigned char>& owned_edges,
                       const std::vector<long long>& keys, const Level_window& window,
                       std::vector<Active_face>& active)
{
  const Chunks chunks = chunks_for<ConcurrencyTag>(lm.number_of_model_faces, std::size_t(1) << 15);
  std::vector<std::vector<Active_face>> parts(chunks.size() > 1 ? chunks.size() : 0);
  active.clear();
  for_each_chunk<ConcurrencyTag>(chunks, [&](std::size_t c, std::size_t b, std::size_t e) {
    std::vector<Active_face>& out = parts.empty() ? active : parts[c];
    const std::array<int, 3>* fv = lm.face_vertices.data();
    const long long* k = keys.data();
    for (std::size_t f = b; f < e; ++f) {
      const std::array<long long, 3> corner_keys = {k[fv[f][0]], k[fv[f][1]], k[fv[f][2]]};
      if (is_active_face(corner_keys, window))
        out.push_back(Active_face{fv[f], lm.face_edges[f], int(f), owned_edges[f], corner_keys});
    }
  });
  concatenate(parts, active);
}

// Calls f(face, j, count, first, trimmed) for every edge j owned by the active faces
// [begin, end) with interior levels, with its interior_levels(); and ahead(face) for the face
// prefetch_distance ahead of the one processed.
template <typename F, typename Ahead>
void for_each_owned_edge(const std::vector<Active_face>& active, std::size_t begin, std::size_t end,
                         const Level_window& window, F&& f, Ahead&& ahead)
{
  for (std::size_t i = begin; i < end; ++i) {
    if (i + prefetch_distance < end)
      ahead(active[i + prefetch_distance]);
    const Active_face& face = active[i];
    if ((face.owned & 7u) == 0)
      continue;
    for (int j = 0; j < 3; ++j) {
      if (!(face.owned & (1u << j)))
        continue;
      long long first = 0, trimmed = 0;
      const long long count = interior_levels(
          face.keys[std::size_t(j)], face.keys[std::size_t((j + 1) % 3)], window, first, &trimmed);
      if (count != 0 || trimmed != 0)
        f(face, j, (std::max)(count, 0LL), first, trimmed); // a skipped edge has no node
    }
  }
}

// The facing window of a sweep (see Level_window): from floor(d/s) of the lowest to
// floor(d/s) + 1 of the highest d value of the vertices facing the light plane within the
// incidence limit (Z·Ñ >= facing_window_cosine |Ñ|), read from their exact classes; empty if there
// is none. Only needed, and only computed, when an edge can cross more than max_levels_per_edge
// levels.
template <typename ConcurrencyTag>
void set_facing_window(const Vertex_normals& vn, const std::array<double, 3>& z,
                       const std::vector<long long>& keys, Level_window& window)
{
  window.facing_lowest = 1;
  window.facing_highest = 0;
  if (!window.keep_facing_levels || !window.may_trim())
    return;
  const std::size_t nv = keys.size();
  const Chunks chunks = chunks_for<ConcurrencyTag>(nv, std::size_t(1) << 15);
  const long long none_low = (std::numeric_limits<long long>::max)(),
                  none_high = (std::numeric_limits<long long>::min)();
  std::vector<std::array<long long, 2>> parts(chunks.size(), {none_low, none_high});
  for_each_chunk<ConcurrencyTag>(chunks, [&](std::size_t c, std::size_t b, std::size_t e) {
    long long low = none_low, high = none_high;
    for (std::size_t v = b; v < e; ++v) {
      const long long key = keys[v];
      if (key == undefined_key || key > key_side_offset / 2)
        continue; // undefined, or the normal points away from the light plane
      const double* n = &vn.normal[3 * v];
      const double zn = z[0] * n[0] + z[1] * n[1] + z[2] * n[2];
      if (!(zn * zn >= facing_window_cosine * facing_window_cosine *
                           (n[0] * n[0] + n[1] * n[1] + n[2] * n[2])) ||
          !(zn > 0))
        continue;
      const long long level = band_level(key);
      low = (std::min)(low, level);
      high = (std::max)(high, level + 1);
    }
    parts[c] = {low, high};
  });
  long long low = none_low, high = none_high;
  for (const auto& part : parts) {
    low = (std::min)(low, part[0]);
    high = (std::max)(high, part[1]);
  }
  if (low <= high) {
    window.facing_lowest = low;
    window.facing_highest = high;
  }
}

// Node ids are ints.
constexpr std::size_t max_node_ids = std::size_t((std::numeric_limits<int>::max)());

inline void check_number_of_nodes(std::size_t nodes)
{
  if (nodes > max_node_ids)
    throw std::length_error("highlight line model: more than 2^31 nodes; restrict it with "
                            "the level_range or face_range named parameters, or raise the "
                            "spacing");
}

// The number of vertex nodes of a sweep: the vertices exactly on a level of the window.
inline std::size_t number_of_vertex_nodes(const std::vector<int>& on_level_vertices,
                                          const std::vector<long long>& keys,
                                          const Level_window& window)
{
  std::size_t vertex_nodes = 0;
  for (int v : on_level_vertices)
    vertex_nodes += window.contains(band_level(key_band(keys[std::size_t(v)])));
  return vertex_nodes;
}

// Whether the nodes of these active faces could be more than the ids (an edge keeps at most
// max_levels_per_edge of them): they must then be counted before the memory is taken.
inline bool may_exceed_node_ids(const Level_window& window, std::size_t active_faces,
                                std::size_t vertex_nodes)
{
  return double(window.max_levels_per_edge) * double(3 * active_faces) + double(vertex_nodes) >
         double(max_node_ids);
}

// Appends to `nodes` the `count` nodes of levels first, first + 1, ... of edge j of `face`,
// in the canonical direction of the edge.
template <typename TriangleMesh>
void place_edge_nodes(const Local_mesh<TriangleMesh>& lm, const Active_face& face, int j,
                      long long count, long long first, const std::vector<double>& distances,
                      double spacing, std::vector<Raw_node>& nodes)
{
  check_number_of_nodes(nodes.size() + std::size_t(count));
  const int edge = face.edges[std::size_t(j)];
  // The canonical direction, without reading edge_vertices.
  const bool reversed = (face.owned & (8u << j)) != 0;
  const int va = face.vertices[std::size_t(reversed ? (j + 1) % 3 : j)],
            vb = face.vertices[std::size_t(reversed ? j : (j + 1) % 3)];
  const double da = distances[std::size_t(va)], db = distances[std::size_t(vb)];
  const double* pa = lm.point(va);
  const double* pb = lm.point(vb);
  for (long long m = first; m < first + count; ++m) {
    Raw_node node;
    node.edge = edge;
    node.vertex = -1;
    node.level = m;
    const double t = db != da ? (double(m) * spacing - da) / (db - da) : 0.5;
    node.parameter = std::min(1.0, std::max(0.0, t)); // rounding must not leave the edge
    for (int k = 0; k < 3; ++k)
      node.point[std::size_t(k)] = pa[k] + node.parameter * (pb[k] - pa[k]);
    nodes.push_back(node);
  }
}

// Appends the vertex nodes (vertices whose d value equals m·s exactly, for m in the window)
// after the out.number_of_edge_nodes edge nodes, and numbers them in out.vertex_node.
template <typename TriangleMesh>
void place_vertex_nodes(const Local_mesh<TriangleMesh>& lm, const std::vector<long long>& keys,
                        const std::vector<int>& on_level_vertices, std::size_t vertex_nodes,
                        const Level_window& window, Highlight_nodes& out)
{
  check_number_of_nodes(out.number_of_edge_nodes + vertex_nodes);
  out.nodes.resize(out.number_of_edge_nodes + vertex_nodes);
  std::size_t id = out.number_of_edge_nodes;
  for (int v : on_level_vertices) {
    const long long level = band_level(key_band(keys[std::size_t(v)]));
    if (!window.contains(level))
      continue;
    Raw_node& node = out.nodes[id];
    node.edge = -1;
    node.vertex = v;
    node.level = level;
    node.parameter = 0;
    const double* p = lm.point(v);
    node.point = {p[0], p[1], p[2]};
    out.vertex_node[std::size_t(v)] = int(id++);
  }
}

// The nodes of a sweep on the active faces out.active_faces: the nodes of their owned edges,
// placed in one pass per chunk of active faces and numbered by edge; then the vertex nodes.
// Concurrently with a parallel tag (the chunks' nodes are then renumbered and concatenated in
// chunk order), with the same result.
template <typename ConcurrencyTag, typename TriangleMesh>
void compute_highlight_nodes(const Local_mesh<TriangleMesh>& lm, const std::vector<long long>& keys,
                             const std::vector<double>& distances,
                             const std::vector<int>& on_level_vertices, double spacing,
                             const Level_window& window, Highlight_nodes& out)
{
  // Stale entries are never read: no per-sweep initialisation.
  out.edge_first_node.resize(lm.edge_vertices.size());
  out.vertex_node.resize(lm.number_of_model_vertices);

  const std::vector<Active_face>& active = out.active_faces;
  const Chunks chunks = chunks_for<ConcurrencyTag>(active.size(), std::size_t(1) << 12);
  const std::size_t vertex_nodes = number_of_vertex_nodes(on_level_vertices, keys, window);
  // Where the nodes could add up to more than ids, they are counted first, so that the error
  // comes before the memory is taken.
  if (may_exceed_node_ids(window, active.size(), vertex_nodes)) {
    std::vector<std::size_t> chunk_nodes(chunks.size(), 0);
    for_each_chunk<ConcurrencyTag>(chunks, [&](std::size_t c, std::size_t b, std::size_t e) {
      for_each_owned_edge(
          active, b, e, window,
          [&](const Active_face&, int, long long count, long long, long long) {
            chunk_nodes[c] += std::size_t(count);
          },
          [](const Active_face&) {});
    });
    std::size_t total = vertex_nodes;
    for (std::size_t n : chunk_nodes)
      total += n;
    check_number_of_nodes(total);
  }

  // Edge nodes, per chunk; edge_first_node in ids local to the chunk. Sequentially the one
  // chunk places them in out.nodes directly, whose capacity is reused across sweeps.
  struct Part
  {
    std::vector<Raw_node> nodes;
    std::size_t capped = 0, trimmed = 0;
  };
  std::vector<Part> parts(chunks.size());
  const bool single = chunks.size() <= 1;
  if (single && !parts.empty())
    std::swap(parts[0].nodes, out.nodes);
  for_each_chunk<ConcurrencyTag>(chunks, [&](std::size_t c, std::size_t b, std::size_t e) {
    Part& part = parts[c];
    std::vector<Raw_node>& nodes = part.nodes;
    nodes.clear();
    for_each_owned_edge(
        active, b, e, window,
        [&](const Active_face& face, int j, long long count, long long first, long long trimmed) {
          part.capped += trimmed != 0;
          part.trimmed += std::size_t(trimmed);
          if (count == 0)
            return;
          out.edge_first_node[std::size_t(face.edges[std::size_t(j)])] = int(nodes.size());
          place_edge_nodes(lm, face, j, count, first, distances, spacing, nodes);
        },
        [&](const Active_face& face) {
          prefetch_active_face(lm, face, distances.data(), out.edge_first_node.data());
        });
  });

  out.number_of_capped_edges = out.number_of_trimmed_nodes = 0;
  for (const Part& part : parts) {
    out.number_of_capped_edges += part.capped;
    out.number_of_trimmed_nodes += part.trimmed;
  }
  if (single) {
    if (!parts.empty())
      std::swap(parts[0].nodes, out.nodes);
    else
      out.nodes.clear();
  } else {
    // Global ids: each chunk's edges start after the nodes of the chunks before it. An edge's
    // nodes are consecutive, and its first one starts a run of its edge id.
    std::size_t total = 0;
    for (const Part& part : parts)
      total += part.nodes.size();
    check_number_of_nodes(total + vertex_nodes);
    out.nodes.resize(total);
    std::vector<std::size_t> offsets(parts.size() + 1, 0);
    for (std::size_t c = 0; c < parts.size(); ++c)
      offsets[c + 1] = offsets[c] + parts[c].nodes.size();
    for_each_chunk<ConcurrencyTag>(
        Chunks(parts.size(), 1), [&](std::size_t c, std::size_t, std::size_t) {
          const std::vector<Raw_node>& nodes = parts[c].nodes;
          const int offset = int(offsets[c]);
          for (std::size_t i = 0; i < nodes.size(); ++i)
            if (offset != 0 && (i == 0 || nodes[i - 1].edge != nodes[i].edge))
              out.edge_first_node[std::size_t(nodes[i].edge)] += offset;
          std::copy(nodes.begin(), nodes.end(), out.nodes.begin() + std::ptrdiff_t(offset));
        });
  }
  out.number_of_edge_nodes = out.nodes.size();
  place_vertex_nodes(lm, keys, on_level_vertices, vertex_nodes, window, out);
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_MODEL_HIGHLIGHT_NODES_H

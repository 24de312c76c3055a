// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_MODEL_NODE_CONNECTION_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_MODEL_NODE_CONNECTION_H

#include <CGAL/Highlight_lines/internal/Local_mesh.h>
#include <CGAL/Highlight_lines/internal/model/highlight_nodes.h>
#include <CGAL/Highlight_lines/internal/model/level_classification.h>
#include <CGAL/Highlight_lines/internal/parallel.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

struct Highlight_segments
{
  std::vector<std::array<int, 2>> segments; // node ids
  std::size_t faces_across_poles = 0;       // active faces where d is undefined or changes side
  std::size_t faces_with_capped_edges = 0;  // faces joining only the levels of the facing window
};

typedef std::vector<std::array<int, 2>> Segment_list;

// What connecting a range of active faces gathers.
struct Connection_part
{
  Segment_list in_faces, highlight_edges;
  std::size_t faces_across_poles = 0, faces_with_capped_edges = 0;
};

// The interior levels of the three edges of an active face (interior_levels(): count, the
// first level kept, the levels trimmed); edge j joins corners j and j + 1.
struct Face_edge_levels
{
  long long count[3], first[3], trimmed[3];

  explicit Face_edge_levels(const Active_face& face, const Level_window& window)
  {
    for (int j = 0; j < 3; ++j)
      count[j] = interior_levels(face.keys[std::size_t(j)], face.keys[std::size_t((j + 1) % 3)],
                                 window, first[j], &trimmed[j]);
  }
};

// §2.4 and Fig. 2, for one active face: its highlight edges (both ends on one level, emitted by
// the face owning the edge) and the segments inside it. node_on_face_edge(j, m) is the id of
// the node of level m on face edge j; vertex_node(v) that of the node on vertex v.
template <typename TriangleMesh, typename NodeOnFaceEdge, typename VertexNode>
void connect_face(const Local_mesh<TriangleMesh>& lm, const Active_face& face,
                  const Face_edge_levels& edge_levels, const Level_window& window,
                  const NodeOnFaceEdge& node_on_face_edge, const VertexNode& vertex_node,
                  Connection_part& part)
{
  const std::array<long long, 3>& k = face.keys;

  // Highlight edges owned by this face: both ends on one level (equal, even keys).
  for (int j = 0; j < 3; ++j) {
    const long long ka = k[j];
    if (!(face.owned & (1u << j)) || ka != k[(j + 1) % 3] || (ka & 1))
      continue;
    // Equal even keys are defined, on the same side and on the same level.
    if (window.contains(band_level(key_band(ka)))) {
      // In the canonical direction of the edge, as an edge pass would emit it.
      const std::array<int, 2>& ends = lm.edge_vertices[std::size_t(face.edges[std::size_t(j)])];
      part.highlight_edges.push_back({vertex_node(ends[0]), vertex_node(ends[1])});
    }
  }

  if (!keys_usable(k[0], k[1]) || !keys_usable(k[1], k[2])) {
    ++part.faces_across_poles;
    return;
  }
  // A face with an edge whose levels beyond the facing window were trimmed joins only the
  // levels of the facing window. A face with a skipped edge (over the cap even inside the
  // facing window) joins none.
  const bool skipped_edge =
      edge_levels.count[0] < 0 || edge_levels.count[1] < 0 || edge_levels.count[2] < 0;
  const bool trimmed_face =
      (edge_levels.trimmed[0] | edge_levels.trimmed[1] | edge_levels.trimmed[2]) != 0;
  part.faces_with_capped_edges += trimmed_face;
  if (skipped_edge)
    return;
  const long long band[3] = {key_band(k[0]), key_band(k[1]), key_band(k[2])};
  long long lowest = (std::max)(band_level(std::min({band[0], band[1], band[2]})), window.lowest);
  long long highest = (std::min)(band_level(std::max({band[0], band[1], band[2]})), window.highest);
  if (trimmed_face) {
    lowest = (std::max)(lowest, window.facing_lowest);
    highest = (std::min)(highest, window.facing_highest);
  }
  for (long long m = lowest; m <= highest; ++m) {
    const int r[3] = {compare_band_to_level(band[0], m), compare_band_to_level(band[1], m),
                      compare_band_to_level(band[2], m)};
    const int on = (r[0] == 0) + (r[1] == 0) + (r[2] == 0);
    if (on == 0) {
      if (r[0] == r[1] && r[1] == r[2])
        continue;
      // The lone corner i is on one side, the other two on the other side.
      const int i = r[0] == r[1] ? 2 : (r[0] == r[2] ? 1 : 0);
      part.in_faces.push_back({node_on_face_edge((i + 2) % 3, m), node_on_face_edge(i, m)});
    } else if (on == 1) {
      const int i = r[0] == 0 ? 0 : (r[1] == 0 ? 1 : 2);
      if (r[(i + 1) % 3] * r[(i + 2) % 3] >= 0)
        continue; // the level only touches the triangle at corner i
      part.in_faces.push_back(
          {vertex_node(face.vertices[std::size_t(i)]), node_on_face_edge((i + 1) % 3, m)});
    }
    // on >= 2: highlight edges, above.
  }
}

// The segments of the parts in order: those inside faces first, by face, then the highlight
// edges, by edge. A single part's in_faces is swapped into out.segments (buffers reused).
inline void merge_connection(std::vector<Connection_part>& parts, Highlight_segments& out)
{
  out.faces_across_poles = 0;
  out.faces_with_capped_edges = 0;
  const bool single = parts.size() == 1;
  if (single)
    std::swap(parts[0].in_faces, out.segments);
  else
    out.segments.clear();
  for (std::size_t c = single ? 1 : 0; c < parts.size(); ++c)
    out.segments.insert(out.segments.end(), parts[c].in_faces.begin(), parts[c].in_faces.end());
  for (const Connection_part& part : parts) {
    out.segments.insert(out.segments.end(), part.highlight_edges.begin(),
                        part.highlight_edges.end());
    out.faces_across_poles += part.faces_across_poles;
    out.faces_with_capped_edges += part.faces_with_capped_edges;
  }
}

// §2.4 and Fig. 2: inside each triangle, nodes of the same index on different edges are
// joined; an edge whose two ends lie exactly on one level (a highlight edge) is a segment
// itself, emitted once per edge (by the face owning it). Per triangle and level this is the
// zero set of the linear interpolant of d - m·s, decided from the exact vertex classes (their
// keys) only: segments of different levels cannot cross, and a segment is found by both
// faces of its nodes' edges. Only the active faces of `hn` can carry segments. The segments
// inside faces come first, by face, then the highlight edges, by edge; with a parallel tag,
// chunks of active faces are processed concurrently and their segments merged in that order.
template <typename ConcurrencyTag, typename TriangleMesh>
void connect_highlight_nodes(const Local_mesh<TriangleMesh>& lm, const Highlight_nodes& hn,
                             const Level_window& window, Highlight_segments& out)
{
  const std::vector<Active_face>& active = hn.active_faces;
  const Chunks chunks = chunks_for<ConcurrencyTag>(active.size(), std::size_t(1) << 12);
  std::vector<Connection_part> parts(chunks.size());
  if (parts.size() == 1)
    std::swap(parts[0].in_faces, out.segments); // reuse the buffer of the previous sweep

  for_each_chunk<ConcurrencyTag>(chunks, [&](std::size_t c, std::size_t b, std::size_t e) {
    Connection_part& part = parts[c];
    part.in_faces.clear();
    auto vertex_node = [&](int v) { return hn.vertex_node[std::size_t(v)]; };
    for (std::size_t i = b; i < e; ++i) {
      if (i + prefetch_distance < e)
        prefetch_edge_first_nodes(active[i + prefetch_distance], hn.edge_first_node.data());
      const Active_face& face = active[i];
      const Face_edge_levels edge_levels(face, window);
      auto node_on_face_edge = [&](int j, long long m) {
        return hn.edge_first_node[std::size_t(face.edges[std::size_t(j)])] +
               int(m - edge_levels.first[j]);
      };
      connect_face(lm, face, edge_levels, window, node_on_face_edge, vertex_node, part);
    }
  });
  merge_connection(parts, out);
}

// compute_highlight_nodes() and connect_highlight_nodes() in one sequential pass over the
// active faces, with the same results: each face places the nodes of the edges it owns, then
// connects its nodes. The nodes of an edge it does not own were placed by the edge's owner,
// an earlier active face, moments before (they lie strictly inside the edge, so the owner's
// corners span a level of the window). Vertex nodes are numbered after all edge nodes: the
// segments carry them as provisional ids -2 - i until the edge nodes are counted.
// Not for active faces whose nodes could exceed the ids (see may_exceed_node_ids()).
template <typename TriangleMesh>
void place_and_connect_nodes(const Local_mesh<TriangleMesh>& lm, const std::vector<long long>& keys,
                             const std::vector<double>& distances,
                             const std::vector<int>& on_level_vertices, double spacing,
                             const Level_window& window, Highlight_nodes& hn,
                             Highlight_segments& out)
{
  hn.edge_first_node.resize(lm.edge_vertices.size()); // stale entries are never read
  hn.vertex_node.resize(lm.number_of_model_vertices);
  const std::size_t vertex_nodes = number_of_vertex_nodes(on_level_vertices, keys, window);
  int provisional = -2;
  for (int v : on_level_vertices)
    if (window.contains(band_level(key_band(keys[std::size_t(v)]))))
      hn.vertex_node[std::size_t(v)] = provisional--;

  std::vector<Connection_part> part(1);
  std::swap(part[0].in_faces, out.segments); // reuse the buffer of the previous sweep
  part[0].in_faces.clear();
  std::vector<Raw_node>& nodes = hn.nodes;
  nodes.clear();
  int* const edge_first_node = hn.edge_first_node.data();
  const int* const vertex_node_ids = hn.vertex_node.data();
  auto vertex_node = [&](int v) { return vertex_node_ids[std::size_t(v)]; };
  hn.number_of_capped_edges = hn.number_of_trimmed_nodes = 0;
  const std::vector<Active_face>& active = hn.active_faces;
  for (std::size_t i = 0; i < active.size(); ++i) {
    if (i + prefetch_distance < active.size())
      prefetch_active_face(lm, active[i + prefetch_distance], distances.data(), edge_first_node);
    const Active_face& face = active[i];
    const Face_edge_levels edge_levels(face, window);
    for (int j = 0; j < 3; ++j) {
      if (!(face.owned & (1u << j)))
        continue;
      const long long count = (std::max)(edge_levels.count[j], 0LL); // skipped: no node
      hn.number_of_capped_edges += edge_levels.trimmed[j] != 0;
      hn.number_of_trimmed_nodes += std::size_t(edge_levels.trimmed[j]);
      if (count == 0)
        continue;
      edge_first_node[std::size_t(face.edges[std::size_t(j)])] = int(nodes.size());
      place_edge_nodes(lm, face, j, count, edge_levels.first[j], distances, spacing, nodes);
    }
    auto node_on_face_edge = [&](int j, long long m) {
      return edge_first_node[std::size_t(face.edges[std::size_t(j)])] +
             int(m - edge_levels.first[j]);
    };
    connect_face(lm, face, edge_levels, window, node_on_face_edge, vertex_node, part[0]);
  }
  hn.number_of_edge_nodes = nodes.size();
  place_vertex_nodes(lm, keys, on_level_vertices, vertex_nodes, window, hn);
  merge_connection(part, out);
  if (vertex_nodes > 0) {
    const int first_vertex_node = int(hn.number_of_edge_nodes);
    for (std::array<int, 2>& segment : out.segments)
      for (int& id : segment)
        if (id < -1)
          id = first_vertex_node + (-2 - id);
  }
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_MODEL_NODE_CONNECTION_H

// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_NODE_CONNECTION_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_NODE_CONNECTION_H

#include <CGAL/Highlight_lines/internal/Local_mesh.h>
#include <CGAL/Highlight_lines/internal/highlight_nodes.h>
#include <CGAL/Highlight_lines/internal/level_classification.h>
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
  typedef std::vector<std::array<int, 2>> Segments;
  struct Part
  {
    Segments in_faces, highlight_edges;
    std::size_t faces_across_poles = 0, faces_with_capped_edges = 0;
  };
  const std::vector<Active_face>& active = hn.active_faces;
  const Chunks chunks = chunks_for<ConcurrencyTag>(active.size(), std::size_t(1) << 12);
  std::vector<Part> parts(chunks.size());
  const bool single = chunks.size() == 1;
  if (single)
    std::swap(parts[0].in_faces, out.segments); // reuse the buffer of the previous sweep

  for_each_chunk<ConcurrencyTag>(chunks, [&](std::size_t c, std::size_t b, std::size_t e) {
    Part& part = parts[c];
    part.in_faces.clear();
    for (std::size_t i = b; i < e; ++i) {
      const Active_face& face = active[i];
      const std::array<long long, 3>& k = face.keys;

      // Highlight edges owned by this face: both ends on one level (equal, even keys).
      for (int j = 0; j < 3; ++j) {
        const long long ka = k[j];
        if (!(face.owned & (1u << j)) || ka != k[(j + 1) % 3] || (ka & 1))
          continue;
        // Equal even keys are defined, on the same side and on the same level.
        if (window.contains(band_level(key_band(ka)))) {
          // In the canonical direction of the edge, as an edge pass would emit it.
          const std::array<int, 2>& ends =
              lm.edge_vertices[std::size_t(face.edges[std::size_t(j)])];
          part.highlight_edges.push_back(
              {hn.vertex_node[std::size_t(ends[0])], hn.vertex_node[std::size_t(ends[1])]});
        }
      }

      if (!keys_usable(k[0], k[1]) || !keys_usable(k[1], k[2])) {
        ++part.faces_across_poles;
        continue;
      }
      // The first level kept on each face edge; a face with an edge whose levels beyond the
      // facing window were trimmed joins only the levels of the facing window.
      // A face with a skipped edge (over the cap even inside the facing window) joins none.
      long long first[3] = {0, 0, 0}, trimmed[3] = {0, 0, 0};
      bool skipped_edge = false;
      for (int j = 0; j < 3; ++j)
        skipped_edge |= interior_levels(k[j], k[(j + 1) % 3], window, first[j], &trimmed[j]) < 0;
      const bool trimmed_face = (trimmed[0] | trimmed[1] | trimmed[2]) != 0;
      part.faces_with_capped_edges += trimmed_face;
      if (skipped_edge)
        continue;
      const long long band[3] = {key_band(k[0]), key_band(k[1]), key_band(k[2])};
      long long lowest =
          (std::max)(band_level(std::min({band[0], band[1], band[2]})), window.lowest);
      long long highest =
          (std::min)(band_level(std::max({band[0], band[1], band[2]})), window.highest);
      if (trimmed_face) {
        lowest = (std::max)(lowest, window.facing_lowest);
        highest = (std::min)(highest, window.facing_highest);
      }
      // Face edge j joins corners j and j + 1.
      auto node_on_face_edge = [&](int j, long long m) {
        return hn.edge_first_node[std::size_t(face.edges[std::size_t(j)])] + int(m - first[j]);
      };
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
          const int corner = face.vertices[std::size_t(i)];
          CGAL_assertion(hn.vertex_node[std::size_t(corner)] >= 0);
          part.in_faces.push_back(
              {hn.vertex_node[std::size_t(corner)], node_on_face_edge((i + 1) % 3, m)});
        }
        // on >= 2: highlight edges, above.
      }
    }
  });

  out.faces_across_poles = 0;
  out.faces_with_capped_edges = 0;
  if (single)
    std::swap(parts[0].in_faces, out.segments);
  else
    out.segments.clear();
  for (std::size_t c = single ? 1 : 0; c < parts.size(); ++c)
    out.segments.insert(out.segments.end(), parts[c].in_faces.begin(), parts[c].in_faces.end());
  for (const Part& part : parts) {
    out.segments.insert(out.segments.end(), part.highlight_edges.begin(),
                        part.highlight_edges.end());
    out.faces_across_poles += part.faces_across_poles;
    out.faces_with_capped_edges += part.faces_with_capped_edges;
  }
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_NODE_CONNECTION_H

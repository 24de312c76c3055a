// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_NODE_CONNECTION_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_NODE_CONNECTION_H

#include <CGAL/Highlight_lines/internal/Local_mesh.h>
#include <CGAL/Highlight_lines/internal/highlight_nodes.h>
#include <CGAL/Highlight_lines/internal/level_classification.h>

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
  std::size_t faces_across_poles = 0;       // faces where d is undefined or changes side
  std::size_t faces_with_capped_edges = 0;
};

// §2.4 and Fig. 2: inside each triangle, nodes of the same index on different edges are
// joined; an edge whose two ends lie exactly on one level (a highlight edge) is a segment
// itself, emitted once per edge. Per triangle and level this is the zero set of the linear
// interpolant of d - m·s, decided from the exact vertex classes only: segments of different
// levels cannot cross, and a segment is found by both faces of its nodes' edges.
template <typename TriangleMesh>
void connect_highlight_nodes(const Local_mesh<TriangleMesh>& lm,
                             const std::vector<Vertex_level>& levels,
                             const std::vector<long long>& keys, const Highlight_nodes& hn,
                             const Level_window& window, Highlight_segments& out)
{
  out.segments.clear();
  out.faces_across_poles = 0;
  out.faces_with_capped_edges = 0;

  for (std::size_t f = 0; f < lm.number_of_model_faces; ++f) {
    const std::array<int, 3>& fv = lm.face_vertices[f];
    const long long k0 = keys[std::size_t(fv[0])];
    if (k0 == keys[std::size_t(fv[1])] && k0 == keys[std::size_t(fv[2])] && (k0 & 1))
      continue; // the common case first: the three corners strictly inside one level band
    const std::array<int, 3>& fe = lm.face_edges[f];
    const Vertex_level* l[3] = {&levels[std::size_t(fv[0])], &levels[std::size_t(fv[1])],
                                &levels[std::size_t(fv[2])]};
    if (!edge_is_usable(*l[0], *l[1]) || !edge_is_usable(*l[1], *l[2])) {
      ++out.faces_across_poles;
      continue;
    }
    if (hn.edge_first_node[std::size_t(fe[0])] == Highlight_nodes::capped ||
        hn.edge_first_node[std::size_t(fe[1])] == Highlight_nodes::capped ||
        hn.edge_first_node[std::size_t(fe[2])] == Highlight_nodes::capped) {
      ++out.faces_with_capped_edges;
      continue;
    }
    const long long lowest =
        (std::max)(std::min({l[0]->level, l[1]->level, l[2]->level}), window.lowest);
    const long long highest =
        (std::min)(std::max({l[0]->level, l[1]->level, l[2]->level}), window.highest);
    // Face edge j joins corners j and j + 1.
    auto node_on_face_edge = [&](int j, long long m) {
      return node_on_edge(hn, fe[std::size_t(j)], *l[j], *l[(j + 1) % 3], window, m);
    };
    for (long long m = lowest; m <= highest; ++m) {
      const int r[3] = {l[0]->compare_to_level(m), l[1]->compare_to_level(m),
                        l[2]->compare_to_level(m)};
      const int on = (r[0] == 0) + (r[1] == 0) + (r[2] == 0);
      if (on == 0) {
        if (r[0] == r[1] && r[1] == r[2])
          continue;
        // The lone corner i is on one side, the other two on the other side.
        const int i = r[0] == r[1] ? 2 : (r[0] == r[2] ? 1 : 0);
        out.segments.push_back({node_on_face_edge((i + 2) % 3, m), node_on_face_edge(i, m)});
      } else if (on == 1) {
        const int i = r[0] == 0 ? 0 : (r[1] == 0 ? 1 : 2);
        if (r[(i + 1) % 3] * r[(i + 2) % 3] >= 0)
          continue; // the level only touches the triangle at corner i
        CGAL_assertion(hn.vertex_node[std::size_t(fv[std::size_t(i)])] >= 0);
        out.segments.push_back(
            {hn.vertex_node[std::size_t(fv[std::size_t(i)])], node_on_face_edge((i + 1) % 3, m)});
      }
      // on >= 2: highlight edges, below.
    }
  }

  for (std::size_t e = 0; e < lm.edge_vertices.size(); ++e) {
    const int a = lm.edge_vertices[e][0], b = lm.edge_vertices[e][1];
    if (keys[std::size_t(a)] != keys[std::size_t(b)] || (keys[std::size_t(a)] & 1))
      continue; // a highlight edge has both ends on one level: equal, even keys
    const Vertex_level& la = levels[std::size_t(a)];
    const Vertex_level& lb = levels[std::size_t(b)];
    if (edge_is_usable(la, lb) && la.on_level && lb.on_level && la.level == lb.level &&
        window.contains(la.level))
      out.segments.push_back({hn.vertex_node[std::size_t(a)], hn.vertex_node[std::size_t(b)]});
  }
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_NODE_CONNECTION_H

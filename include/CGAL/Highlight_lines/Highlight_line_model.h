// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_HIGHLIGHT_LINE_MODEL_H
#define CGAL_HIGHLIGHT_LINES_HIGHLIGHT_LINE_MODEL_H

#include <CGAL/Highlight_lines/Light_setup.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Highlight_lines {

/*!
\ingroup PkgHighlightLinesRef

The highlight line model of a triangle mesh for one light setup (§2 of the paper): the
highlight nodes, where highlight lines cross mesh edges or pass through vertices, and the
highlight lines as sequences of nodes.

Lines are maximal chains of segments through nodes with exactly two segments. A line ends at
a node with one segment (a mesh border or the border of the face range the model was
computed on, a vertex whose highlight distance is undefined, a face that joins only the
lights imaged where the surface faces the light plane because one of its edges crosses too
many levels) or with more than two (a vertex lying exactly on a level at a
saddle, where lines meet). Lines that close up are reported closed, without repeating their
first node.

The result is canonical: each line starts at its lexicographically smallest end point (closed
lines: at their smallest node, continuing towards its smaller neighbour), lines are sorted by
level and start, and nodes are numbered in the order the lines visit them. Hence the model
does not depend on the order of the faces in the mesh nor on the mesh data structure
(up to the last bits of node positions, which depend on the order in which face contributions
are summed into vertex normals).

\tparam TriangleMesh a model of `FaceGraph`
\tparam GeomTraits a model of `Kernel`
*/
template <typename TriangleMesh, typename GeomTraits>
class Highlight_line_model
{
public:
  /// The vertex descriptor of the mesh.
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// The halfedge descriptor of the mesh.
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  /// The point type of the kernel.
  typedef typename GeomTraits::Point_3 Point_3;

  /// A highlight node.
  struct Node
  {
    /// Position on the mesh.
    Point_3 point;
    /// Index `m` of the light source: the highlight distance value of the node is `m·s`.
    long long level = 0;
    /// For a node inside an edge `(V1, V2)`: a halfedge of that edge with `source == V1`;
    /// `null_halfedge()` for a node on a vertex.
    halfedge_descriptor halfedge = boost::graph_traits<TriangleMesh>::null_halfedge();
    /// For a node inside an edge: `t` with `point = V1 + t·(V2 - V1)`, in [0, 1].
    double parameter = 0;
    /// For a node on a vertex (the vertex's highlight distance value is exactly `m·s`):
    /// that vertex; `null_vertex()` otherwise.
    vertex_descriptor vertex = boost::graph_traits<TriangleMesh>::null_vertex();
    /// Number of highlight segments incident to the node.
    std::size_t degree = 0;

    /// Whether the node lies on a vertex rather than inside an edge.
    bool is_on_vertex() const { return vertex != boost::graph_traits<TriangleMesh>::null_vertex(); }
  };

  /// A highlight line: a polyline of nodes of one level.
  struct Line
  {
    /// Index `m` of the light source.
    long long level = 0;
    /// Whether the last node is joined back to the first one.
    bool is_closed = false;
    /// Indices into `nodes()`.
    std::vector<std::size_t> nodes;
  };

  /*!
  An empty model (no node, no line, every count zero), to be filled by
  `Highlight_line_sweeper::compute(lights, model)`; until then its `lights()` are a placeholder
  (`A0` the origin, `H` along x, `Z` along z, `s = 1`).
  */
  Highlight_line_model()
      : lights_(Point_3(0, 0, 0), typename GeomTraits::Vector_3(1, 0, 0),
                typename GeomTraits::Vector_3(0, 0, 1), 1),
        number_of_segments_(0), skipped_edges_(0), undefined_vertices_(0),
        out_of_range_vertices_(0), trimmed_nodes_(0)
  {
  }

  /// \cond SKIP_IN_MANUAL
  // What Highlight_line_sweeper writes into an existing model, reusing its memory: the nodes
  // and the lines (their node lists included) are overwritten in place.
  std::vector<Node>& nodes_to_overwrite() { return nodes_; }
  std::vector<Line>& lines_to_overwrite() { return lines_; }
  void set_lights_and_counts(const Light_setup<GeomTraits>& lights, std::size_t number_of_segments,
                             std::size_t skipped_edges, std::size_t undefined_vertices,
                             std::size_t out_of_range_vertices, std::size_t trimmed_nodes)
  {
    lights_ = lights;
    number_of_segments_ = number_of_segments;
    skipped_edges_ = skipped_edges;
    undefined_vertices_ = undefined_vertices;
    out_of_range_vertices_ = out_of_range_vertices;
    trimmed_nodes_ = trimmed_nodes;
  }

  Highlight_line_model(const Light_setup<GeomTraits>& lights, std::vector<Node> nodes,
                       std::vector<Line> lines, std::size_t number_of_segments,
                       std::size_t skipped_edges, std::size_t undefined_vertices,
                       std::size_t out_of_range_vertices, std::size_t trimmed_nodes = 0)
      : lights_(lights), nodes_(std::move(nodes)), lines_(std::move(lines)),
        number_of_segments_(number_of_segments), skipped_edges_(skipped_edges),
        undefined_vertices_(undefined_vertices), out_of_range_vertices_(out_of_range_vertices),
        trimmed_nodes_(trimmed_nodes)
  {
  }
  /// \endcond

  /// The light setup the model was computed for.
  const Light_setup<GeomTraits>& lights() const { return lights_; }
  /*!
  The highlight nodes that lie on a highlight line: exactly the nodes of `lines()`, numbered
  in the order the lines visit them. Every node is in at least one line and has `degree >= 1`;
  every node of a line is here.

  Nodes that no highlight segment reaches are left out: a vertex whose highlight distance
  equals `m·s` where that level only touches the surface (a local extremum of `d`); the nodes
  of an edge all of whose faces have a vertex whose `d` is undefined or whose normal points to
  the other side of the light plane; the nodes, beyond the lights imaged where the surface
  faces the light plane, of an edge whose faces all join only those lights (see
  `number_of_skipped_edges()`).
  */
  const std::vector<Node>& nodes() const { return nodes_; }
  /// All highlight lines.
  const std::vector<Line>& lines() const { return lines_; }
  /// Number of highlight segments (line pieces inside one triangle, or highlight edges).
  std::size_t number_of_segments() const { return number_of_segments_; }
  /*!
  Number of edges that would carry more nodes than the `max_levels_per_edge` named parameter
  allows and lost some: such an edge keeps only the nodes of the lights imaged where the
  surface faces the light plane within about 87 degrees (the levels from the lowest to the
  highest highlight distance value of the vertices whose unit normal `N` has `Z·N >= 0.05`),
  its faces join only those lights, and the lines of the other lights end there. The nodes
  left out are counted by `number_of_trimmed_nodes()`.
  */
  std::size_t number_of_skipped_edges() const { return skipped_edges_; }
  /// Number of nodes that the edges counted by `number_of_skipped_edges()` would have carried
  /// beyond the lights imaged where the surface faces the light plane.
  std::size_t number_of_trimmed_nodes() const { return trimmed_nodes_; }
  /// Number of vertices whose normal is parallel to the light plane (`Z·N = 0`): their
  /// highlight distance is undefined, no node is placed on their edges. With
  /// `Highlight_lines::parameters::crease_edge_map`, a vertex counts once per sector.
  std::size_t number_of_undefined_vertices() const { return undefined_vertices_; }
  /// Number of vertices whose normal is so close to parallel to the light plane that
  /// `|d/s| >= 2^50`; they are treated like undefined ones.
  std::size_t number_of_out_of_range_vertices() const { return out_of_range_vertices_; }

  /*!
  Writes each line as a polyline, CGAL style: a `std::vector<Point_3>` per line; a closed
  line repeats its first point at the end.
  */
  template <typename OutputIterator>
  OutputIterator polylines(OutputIterator out) const
  {
    for (const Line& line : lines_) {
      std::vector<Point_3> polyline;
      polyline.reserve(line.nodes.size() + 1);
      for (std::size_t n : line.nodes)
        polyline.push_back(nodes_[n].point);
      if (line.is_closed && !line.nodes.empty())
        polyline.push_back(nodes_[line.nodes.front()].point);
      *out++ = std::move(polyline);
    }
    return out;
  }

private:
  Light_setup<GeomTraits> lights_;
  std::vector<Node> nodes_;
  std::vector<Line> lines_;
  std::size_t number_of_segments_, skipped_edges_, undefined_vertices_, out_of_range_vertices_,
      trimmed_nodes_;
};

} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_HIGHLIGHT_LINE_MODEL_H

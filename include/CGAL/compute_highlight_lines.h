// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_COMPUTE_HIGHLIGHT_LINES_H
#define CGAL_COMPUTE_HIGHLIGHT_LINES_H

#include <CGAL/Highlight_lines/Highlight_line_model.h>
#include <CGAL/Highlight_lines/Highlight_line_sweeper.h>
#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/Highlight_lines/Light_setup.h>
#include <CGAL/Highlight_lines/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

namespace CGAL {

// One \cgalParam... command per line, as in CGAL's reference pages: not reflowed.
// clang-format off
/*!
\ingroup PkgHighlightLinesRef

Computes the highlight line model of a triangle mesh (§2 of the paper, with the corrections
of the package's specification) and writes its lines as polylines.

The steps: the vertex normals of eq. 3 (area-weighted sum of face normals, not the weighting
of `Polygon_mesh_processing::compute_vertex_normals()`); the highlight distance value `d` of
every vertex (eq. 1); a node on each edge for every light index `m` with `m·s` strictly
between the `d` values of its ends (corrected eq. 4), or on a vertex whose `d` equals `m·s`;
per triangle, nodes of the same index are joined, and an edge whose ends lie on one level is
a segment itself (Fig. 2).

Whether a vertex lies below, on or above a level is decided exactly (a filtered predicate on
the input coordinates, with an exact fallback), once per vertex: the topology of the lines is
right even for vertices exactly on a level. Where the normal of a vertex is parallel to the
light plane (`Z·N = 0`), `d` is undefined: no node is placed on the edges at that vertex, nor
on edges whose ends see the light plane from different sides; lines end there.

\tparam ConcurrencyTag enables sequential versus parallel computation. Possible values are
`CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` (requires TBB: a static assertion
fails otherwise) and `CGAL::Parallel_if_available_tag`, e.g.
`compute_highlight_lines<CGAL::Parallel_if_available_tag>(tm, lights, out)`. In parallel, the
passes over faces, vertices and edges (normals, classification, nodes, connection) run
concurrently with TBB; the result is bit for bit the sequential one (same nodes, same lines in
the same order).
\tparam TriangleMesh a model of `FaceGraph` whose faces are triangles
\tparam GeomTraits a model of `Kernel`
\tparam PolylineOutputIterator an output iterator accepting `std::vector<GeomTraits::Point_3>`
\tparam NamedParameters a sequence of named parameters

\param tm the mesh
\param lights the light setup
\param out receives one polyline per highlight line; a closed line repeats its first point
\param np an optional sequence of named parameters among:
  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `tm`}
      \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `GeomTraits::Point_3` as value type}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_index_map}
      \cgalParamDescription{a property map associating to each vertex of `tm` a unique index between `0` and `num_vertices(tm) - 1`}
      \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `std::size_t` as value type}
      \cgalParamDefault{an internal property map of `tm` if there is one, otherwise a dynamic one initialised here}
    \cgalParamNEnd
    \cgalParamNBegin{face_index_map}
      \cgalParamDescription{a property map associating to each face of `tm` a unique index between `0` and `num_faces(tm) - 1`}
      \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type}
      \cgalParamDefault{an internal property map of `tm` if there is one, otherwise a dynamic one initialised here}
    \cgalParamNEnd
    \cgalParamNBegin{halfedge_index_map}
      \cgalParamDescription{a property map associating to each halfedge of `tm` a unique index between `0` and `num_halfedges(tm) - 1`}
      \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type and `std::size_t` as value type}
      \cgalParamDefault{an internal property map of `tm` if there is one, otherwise a dynamic one initialised here}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::face_range}
      \cgalParamDescription{a range of faces of `tm`: the model is computed on them only; vertex normals still use the full one-rings, so the result is the whole model restricted to these faces. Time and memory are proportional to the range.}
      \cgalParamType{a class model of `ConstRange` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as value type}
      \cgalParamDefault{all faces of `tm`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::crease_edge_map}
      \cgalParamDescription{a property map whose value is `true` on the crease edges of `tm` (e.g. filled by `Polygon_mesh_processing::detect_sharp_edges()`): the model is computed on the mesh cut along them, with one normal per sector of faces between crease edges at a vertex, so that the lines run straight on the planar faces of a CAD part and end at its creases (see \ref hl_creases)}
      \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and `bool` as value type}
      \cgalParamDefault{no crease: the normals of eq. 3 over the whole one-ring, as in the paper}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::level_range}
      \cgalParamDescription{a pair `(lo, hi)`: only the lights with index `m` in `[lo, hi]` get highlight lines}
      \cgalParamType{`std::pair<int, int>` (or a pair of other integer types)}
      \cgalParamDefault{all lights}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::max_levels_per_edge}
      \cgalParamDescription{an edge crossing more levels keeps only the lights imaged where the surface faces the light plane (from the lowest to the highest `d` of the vertices whose unit normal has `Z·N >= 0.05`, about 87 degrees of incidence), and its faces join only those; the nodes beyond are trimmed and counted in `number_of_skipped_edges()` and `number_of_trimmed_nodes()`. This bounds the output near where the normals turn parallel to the light plane and `d` grows without bound, and keeps every line where the surface faces the lights}
      \cgalParamType{`std::size_t`, at least 1}
      \cgalParamDefault{`256`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::facing_side_only}
      \cgalParamDescription{if `true`, only the vertices whose normal points towards the light plane (`Z·N > 0`) get highlight lines, as a real reflection would show them; the paper's definition (`false`) uses the whole normal line and also images the lights on the side turned away from them}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

\returns the highlight line model: nodes (position, index, carrying edge or vertex,
parameter on the edge) and lines as node sequences.

\throws Highlight_lines::Invalid_input if a face involved is not a triangle or is
degenerate, if a vertex has a non-finite coordinate, or if a named parameter is out of its
domain. Light setups are validated when they are constructed.

\sa `Highlight_lines::Highlight_line_sweeper` to compute models for many light setups.
*/
// clang-format on
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename GeomTraits, typename PolylineOutputIterator,
          typename NamedParameters = parameters::Default_named_parameters>
Highlight_lines::Highlight_line_model<TriangleMesh, GeomTraits> compute_highlight_lines(
    const TriangleMesh& tm, const Highlight_lines::Light_setup<GeomTraits>& lights,
    PolylineOutputIterator out, const NamedParameters& np = parameters::default_values())
{
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type Vertex_point_map;
  const Highlight_lines::Highlight_line_sweeper<TriangleMesh, Vertex_point_map, GeomTraits,
                                                ConcurrencyTag>
      sweeper(tm, np);
  auto model = sweeper.compute(lights, np);
  model.polylines(out);
  return model;
}

} // namespace CGAL

#endif // CGAL_COMPUTE_HIGHLIGHT_LINES_H

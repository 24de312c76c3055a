// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_HIGHLIGHT_LINE_IRREGULARITY_H
#define CGAL_HIGHLIGHT_LINES_HIGHLIGHT_LINE_IRREGULARITY_H

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Highlight_lines {

/*!
\ingroup PkgHighlightLinesRef

A place where highlight lines bend abnormally, as found by
`detect_highlight_line_irregularities()`: a face region that encloses the anomalies with a
margin, ready to be passed to `fair_with_highlight_lines()`.

\tparam TriangleMesh a model of `FaceGraph`
*/
template <typename TriangleMesh>
struct Highlight_line_irregularity
{
  /// The face descriptor of the mesh.
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  /// The vertex descriptor of the mesh.
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;

  /// The region: the faces within the margin of the anomalies, edge-connected.
  std::vector<face_descriptor> faces;
  /// The strongest anomaly: how many robust standard deviations its bending lies above the
  /// median bending of its line (the larger, the more certain and the more visible).
  double score = 0;
  /// The largest bending measured in the region, in radians.
  double max_bending = 0;
  /// The vertex nearest to the strongest anomaly.
  vertex_descriptor peak_vertex = boost::graph_traits<TriangleMesh>::null_vertex();
  /// Number of abnormal samples found in the region, over all light setups.
  std::size_t number_of_anomalies = 0;
  /// Number of distinct highlight lines (over all light setups) with an abnormal sample in the
  /// region.
  std::size_t number_of_lines = 0;
  /// Number of light setups of the sweep in which the region showed an anomaly.
  std::size_t number_of_light_setups = 0;
};

} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_HIGHLIGHT_LINE_IRREGULARITY_H

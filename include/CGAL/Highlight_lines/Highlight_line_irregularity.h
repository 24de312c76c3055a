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

What an irregular region found by `detect_highlight_line_irregularities()` looks like.
*/
enum class Irregularity_kind {
  /// A compact region whose strongest anomaly lies below the mean of the region, along the
  /// normal: a dent.
  DENT,
  /// A compact region whose strongest anomaly lies above the mean of the region: a bump.
  BUMP,
  /// Anomalies spread along a line, more than twice as long as wide (and as the detection
  /// scale): the lines kink along a feature (a fillet, a panel joint, a crease
  /// softer than the sharp-edge angle) rather than at one place. Usually design.
  ELONGATED,
  /// Anomalies spread wider than a defect the detection looks for can spread them: along their
  /// main axis over more than `6w` (`w` the detection scale; a defect of radius `R <= 3w/2`
  /// spreads its anomalies over at most `2R + 3w`), with the local residual `11w` or a cluster
  /// of them covering more than the disc of that diameter. A change of shape at a larger scale,
  /// or, on a small or compact mesh, a cluster that wraps around the surface. Usually design;
  /// its `confidence` is below 0.5.
  EXTENDED
};

/*!
\ingroup PkgHighlightLinesRef

The name of `kind`, in lower case: "dent", "bump", "elongated" or "extended".
*/
inline const char* to_string(Irregularity_kind kind)
{
  switch (kind) {
  case Irregularity_kind::DENT:
    return "dent";
  case Irregularity_kind::BUMP:
    return "bump";
  case Irregularity_kind::ELONGATED:
    return "elongated";
  case Irregularity_kind::EXTENDED:
    return "extended";
  }
  return "unknown";
}

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
  /// The region's contrast with its surroundings (the larger, the more certain and the more
  /// visible): per light setup that showed it, how many robust standard deviations its
  /// strongest residual lies from the residuals of the same setup around it (between `2w` and
  /// `6w` from its centre, not across a sharp edge), the median over those setups (where the
  /// surroundings hold too few samples, the strongest anomaly's score against the noise of its
  /// line). With `local_residual(false)`: how many robust standard deviations the strongest
  /// anomaly's bending lies above the median bending of its line.
  double score = 0;
  /// The largest sideways offset of a line measured in the region, in mean edge lengths (with
  /// `local_residual(false)`: the largest bending, in radians).
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
  /// What the region looks like.
  Irregularity_kind kind = Irregularity_kind::DENT;
  /// How sure the detection is that the region is a local defect rather than design, in
  /// [0, 1]: the fraction of the sweep's light setups that showed an anomaly in it, times
  /// `min(1, (2 max(b, w) / l)^2)` (small for a region elongated along a feature) and a
  /// locality factor `min(1, (6w / l)^2)` (small for a region much larger than a defect),
  /// where `l` and `b` are four standard deviations of the positions of the anomalies along
  /// their two main axes and `w` the detection scale. With the local residual, the default, the
  /// locality factor is `min(1, (11w / l)^2, A0 / A)`, `A` the area of the faces the anomalies'
  /// cluster covers and `A0` that of the disc of diameter `11w` grown by the rings those faces
  /// reach beyond the anomalies; and on a mirror symmetric surface the confidence is also
  /// multiplied by `min(1, (a/a0)^2)`, `a` the region's asymmetry and `a0` the surface's own
  /// (symmetric regions are design). Where the locality factor is below 1 (the region is
  /// `EXTENDED`, or `ELONGATED` and longer than a defect can make), it is halved: such a region
  /// never reaches the 0.5 at which `detect_and_fair_highlight_line_irregularities()` fairs by
  /// default. Regions are reported by decreasing `confidence * score`.
  double confidence = 0;
  /// The detection scale `w` (in mean edge lengths) of the sweep that found the region: the
  /// scale `detection_scale`, or with several `number_of_scales` the one at which the region
  /// was strongest.
  double scale = 0;
};

} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_HIGHLIGHT_LINE_IRREGULARITY_H

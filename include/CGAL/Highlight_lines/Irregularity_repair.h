// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_IRREGULARITY_REPAIR_H
#define CGAL_HIGHLIGHT_LINES_IRREGULARITY_REPAIR_H

#include <CGAL/Highlight_lines/Fairing_report.h>
#include <CGAL/Highlight_lines/Highlight_line_irregularity.h>

#include <boost/graph/graph_traits.hpp>

#include <string>
#include <vector>

namespace CGAL {
namespace Highlight_lines {

/*!
\ingroup PkgHighlightLinesRef

What `detect_and_fair_highlight_line_irregularities()` did with one region it found.

\tparam TriangleMesh a model of `FaceGraph`
*/
template <typename TriangleMesh>
struct Irregularity_repair
{
  /// The region found, as `detect_highlight_line_irregularities()` reported it (joined with
  /// the touching regions faired with it: `Highlight_lines::join_touching_irregularities()`).
  Highlight_line_irregularity<TriangleMesh> irregularity;
  /// The faces faired: those of `irregularity` and the rings of faces around them that the
  /// fairing margin adds (see `detect_and_fair_highlight_line_irregularities()`); empty if the
  /// region was skipped.
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> faired_faces;
  /// Whether the region was faired; if not, the mesh is exactly as it was before this region
  /// was tried, and `failure` says why.
  bool repaired = false;
  /// Whether the region was not tried at all: its `confidence` is below
  /// `Highlight_lines::parameters::minimum_confidence` (most likely design, not a defect);
  /// `failure` then says so.
  bool skipped = false;
  /// The fairing's report: its iterations, or those carried out before a failure.
  Fairing_report report;
  /// The message of the exception that stopped the fairing of this region, or empty.
  std::string failure;
};

} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_IRREGULARITY_REPAIR_H

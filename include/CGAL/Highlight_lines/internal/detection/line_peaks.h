// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_LINE_PEAKS_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_LINE_PEAKS_H

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// Whether sample i of a measure along a line is its peak within `window` samples to either
// side (around the end of a closed line): only the peaks count, one per stencil width, since a
// measure spreads a defect's response over its stencil and the peak stays on the defect.
// Values equal up to rounding tie (plateaus are common: the line is piecewise linear), and
// ties go to the first sample, so a plateau yields one peak wherever rounding leaves its
// maximum.
inline bool is_peak_along_line(const std::vector<double>& values, std::size_t i, bool closed,
                               std::ptrdiff_t window)
{
  const std::ptrdiff_t n = std::ptrdiff_t(values.size());
  for (std::ptrdiff_t d = -window; d <= window; ++d) {
    std::ptrdiff_t j = std::ptrdiff_t(i) + d;
    if (closed)
      j = ((j % n) + n) % n;
    if (d == 0 || j < 0 || j >= n)
      continue;
    const double other = values[std::size_t(j)], tolerance = 1e-9 * values[i];
    if (other > values[i] + tolerance || (other >= values[i] - tolerance && d < 0))
      return false;
  }
  return true;
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_LINE_PEAKS_H

// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_REGIONS_ACROSS_SCALES_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_REGIONS_ACROSS_SCALES_H

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// The regions of the sweeps at several scales, taken strongest first (`by_strength`, indices
// into `found`), each one unless it shares a face with one taken before. A region found at a
// coarser scale takes the faces (and the peak) of the strongest region of a finer scale
// centred in it: the finer scale places a defect more precisely and its region is sized to it
// (about 2w + margin in radius), the coarser one, with less noise and a fit that reaches beyond
// wide defects, says how strong and how local it is. `faces[i]` are the compact faces of
// `found[i]` (corners in `corners`), `centres[i]` its compact centre vertex. Returns the indices
// of the regions kept, in order.
template <typename Irregularity>
std::vector<std::size_t> select_regions_across_scales(
    std::vector<Irregularity>& found, const std::vector<std::vector<int>>& faces,
    const std::vector<int>& centres, const std::vector<std::size_t>& by_strength,
    const std::vector<std::array<int, 3>>& corners, std::size_t number_of_vertices)
{
  std::vector<std::size_t> order;
  std::vector<char> taken(corners.size(), 0), used(found.size(), 0),
      in_region(number_of_vertices, 0);
  for (std::size_t i : by_strength) {
    if (used[i])
      continue;
    std::size_t faces_of = i;
    for (int f : faces[i])
      for (int v : corners[std::size_t(f)])
        in_region[std::size_t(v)] = 1;
    for (std::size_t j : by_strength)
      if (!used[j] && found[j].scale < found[i].scale && in_region[std::size_t(centres[j])]) {
        faces_of = j;
        break;
      }
    for (int f : faces[i])
      for (int v : corners[std::size_t(f)])
        in_region[std::size_t(v)] = 0;
    bool overlaps = false;
    for (int f : faces[faces_of])
      overlaps = overlaps || taken[std::size_t(f)];
    if (overlaps)
      continue;
    for (int f : faces[faces_of])
      taken[std::size_t(f)] = 1;
    used[i] = used[faces_of] = 1;
    if (faces_of != i) {
      found[i].faces = found[faces_of].faces;
      found[i].peak_vertex = found[faces_of].peak_vertex;
    }
    order.push_back(i);
  }
  return order;
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_REGIONS_ACROSS_SCALES_H

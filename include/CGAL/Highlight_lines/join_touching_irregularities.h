// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_JOIN_TOUCHING_IRREGULARITIES_H
#define CGAL_HIGHLIGHT_LINES_JOIN_TOUCHING_IRREGULARITIES_H

#include <CGAL/Highlight_lines/Highlight_line_irregularity.h>
#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Highlight_lines {

/*!
\ingroup PkgHighlightLinesRef

Joins the regions of `irregularities` whose `confidence` reaches `minimum_confidence` and that
share a vertex, directly or through other such regions, into the first of them in the list;
the others of each group are removed, and the order of the rest is kept. Regions below
`minimum_confidence` are left as they are.

Why: the local residual of `detect_highlight_line_irregularities()` sizes its regions to the
defect and keeps them disjoint, so a defect whose anomalies peak twice (a strong one: its
side lobes) may be written as two regions side by side. Faired one after the other, their
common border is fixed in both fairings (only inner vertices move) and the defect cannot be
repaired across it. `detect_and_fair_highlight_line_irregularities()` joins the regions it
fairs with this function.

The joined region has the faces of all (the regions are disjoint, as the detection writes
them), the sum of their `number_of_anomalies` and `number_of_lines`, the largest of their
`number_of_light_setups` and `max_bending`, and the `kind`, `score`, `confidence`,
`peak_vertex` and `scale` of the first.

\tparam TriangleMesh a model of `FaceGraph`

\param tm the mesh the regions were found on
\param irregularities the regions, as `detect_highlight_line_irregularities()` wrote them
\param minimum_confidence the confidence below which a region is left alone, in `[0, 1]`

\throws Highlight_lines::Invalid_input (`INVALID_PARAMETER`) if `minimum_confidence` is not in
`[0, 1]`; `irregularities` is then left as it was.
*/
template <typename TriangleMesh>
void join_touching_irregularities(
    const TriangleMesh& tm, std::vector<Highlight_line_irregularity<TriangleMesh>>& irregularities,
    double minimum_confidence)
{
  if (!(minimum_confidence >= 0 && minimum_confidence <= 1))
    throw Invalid_input(Invalid_input::Problem::INVALID_PARAMETER,
                        "join_touching_irregularities: minimum_confidence must be in [0, 1]");
  const std::size_t n = irregularities.size();
  std::vector<std::size_t> first(n); // union-find; a group's root is its first region
  std::iota(first.begin(), first.end(), std::size_t(0));
  auto root = [&first](std::size_t i) {
    while (first[i] != i)
      i = first[i] = first[first[i]];
    return i;
  };
  const auto vim = get_initialized_vertex_index_map(tm);
  std::unordered_map<std::size_t, std::size_t> region_of_vertex;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(irregularities[i].confidence >= minimum_confidence))
      continue;
    for (auto f : irregularities[i].faces)
      for (auto v : vertices_around_face(halfedge(f, tm), tm)) {
        const auto inserted = region_of_vertex.emplace(std::size_t(get(vim, v)), i);
        if (!inserted.second) {
          const std::size_t a = root(i), b = root(inserted.first->second);
          first[(std::max)(a, b)] = (std::min)(a, b);
        }
      }
  }
  std::vector<Highlight_line_irregularity<TriangleMesh>> joined;
  std::vector<std::size_t> position(n, n); // of each root in `joined`
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t r = root(i);
    if (r == i) {
      position[i] = joined.size();
      joined.push_back(std::move(irregularities[i]));
      continue;
    }
    auto& into = joined[position[r]];
    const auto& from = irregularities[i];
    into.faces.insert(into.faces.end(), from.faces.begin(), from.faces.end());
    into.number_of_anomalies += from.number_of_anomalies;
    into.number_of_lines += from.number_of_lines;
    into.number_of_light_setups =
        (std::max)(into.number_of_light_setups, from.number_of_light_setups);
    into.max_bending = (std::max)(into.max_bending, from.max_bending);
  }
  irregularities.swap(joined);
}

} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_JOIN_TOUCHING_IRREGULARITIES_H

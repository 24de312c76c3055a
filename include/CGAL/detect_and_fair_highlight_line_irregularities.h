// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_DETECT_AND_FAIR_HIGHLIGHT_LINE_IRREGULARITIES_H
#define CGAL_DETECT_AND_FAIR_HIGHLIGHT_LINE_IRREGULARITIES_H

#include <CGAL/Highlight_lines/Irregularity_repair.h>
#include <CGAL/Highlight_lines/grown_face_region.h>
#include <CGAL/Highlight_lines/join_touching_irregularities.h>
#include <CGAL/detect_highlight_line_irregularities.h>
#include <CGAL/fair_with_highlight_lines.h>

#include <cmath>
#include <iterator>
#include <string>
#include <vector>

namespace CGAL {

// One \cgalParam... command per line, as in CGAL's reference pages: not reflowed.
// clang-format off
/*!
\ingroup PkgHighlightLinesRef

Finds the irregular regions of a mesh with `detect_highlight_line_irregularities()` and fairs
each of them with `fair_with_highlight_lines()`, one at a time, the strongest first, as the
paper prescribes for several regions (the model is recomputed for each, so a region is faired
against the highlight lines left by the previous ones).

Only the regions that are most likely defects are faired: those whose `confidence` reaches
`minimum_confidence` (default 0.5: a compact region seen in at least half of the light setups;
regions elongated along a feature get a lower confidence, the more so the longer they are:
most `ELONGATED` regions fall below it, not all; regions spread wider than a defect of the
detection's scale can make, `EXTENDED`, always do. The kind is no proof: a dent on a flat plate
can be reported `ELONGATED` with confidence 0.68, and compact design regions of the camel head
with 1). The others are reported as
skipped (`Irregularity_repair::skipped`) and left untouched. Regions to be faired that touch
are joined and faired as one (`Highlight_lines::join_touching_irregularities()`): faired apart,
their common border would stay fixed in both fairings. And each is faired with a margin of `fairing_margin` rings of
faces (by default `detection_scale`, rounded up; never across a sharp edge:
`Highlight_lines::grown_face_region()`): a region is centred where the lines move most, often
one flank of a defect, and a fairing moves only the inner vertices of its region (`benchmark_detection --shared`, column "whole": of the 57
injected defects whose regions the local residual would fair, 22 could be moved whole without
the margin, 44 with it). No region found crosses a sharp edge (see
`detect_highlight_line_irregularities()`), nor does the margin, so no fairing reshapes a
feature line.

A region whose fairing is refused (e.g. it has no movable vertex because it is too thin) or
fails is left exactly as it was, recorded with the reason, and the next region is tried.

<b>Not yet a reliable repair.</b> Measured against the undented surface on the shared real
meshes with injected dents and bumps (`benchmark_detection --repair`, see the manual), 8 of
the 86 defects whose vertices this function moved ended closer to the undented surface, and
it moved the surface away from the defects by up to 1.2–4.2 mean edge lengths (with
`Polygon_mesh_processing::fair()` on the same regions, 5 of 86): the regions found are
placed and sized for seeing a defect, not for fairing it (on the beetle, the fairing of each
defect's own disc brings all 11 defects that their surroundings predict closer; this function
moves 5 of them, 4 closer). Check each repair (its `faired_faces`) before keeping it.

\tparam TriangleMesh a model of `MutableFaceGraph` whose faces are triangles
\tparam GeomTraits a model of `Kernel`

\param tm the mesh, modified in place through the vertex point map
\param lights the light setup: it starts the detection's sweep and is the one whose lines the
fairing makes run smoothly
\param np an optional sequence of named parameters: those of
`detect_highlight_line_irregularities()` and those of `fair_with_highlight_lines()`, passed to
both (a `fairing_visitor` is called for every iteration of every region), and:
  \cgalNamedParamsBegin
    \cgalParamNBegin{Highlight_lines::parameters::minimum_confidence}
      \cgalParamDescription{the `confidence` (in `[0, 1]`) below which a region found is skipped}
      \cgalParamType{`double`}
      \cgalParamDefault{`0.5`}
    \cgalParamNEnd
    \cgalParamNBegin{Highlight_lines::parameters::fairing_margin}
      \cgalParamDescription{the number of rings of faces added around each region before it is faired, never across a sharp edge}
      \cgalParamType{`int`, in `[0, 1000]`}
      \cgalParamDefault{`detection_scale` rounded up (3)}
      \cgalParamExtra{measured against the undented surface (`benchmark_detection --repair --fairing-margin N`), a smaller margin moves the design around a region less but leaves more defects partly outside their region; see the manual}
    \cgalParamNEnd
  \cgalNamedParamsEnd

\returns one entry per region found (regions joined as above counting as one), in the order
they were found (and faired), skipped ones included.

\throws Highlight_lines::Invalid_input for what the detection rejects (the mesh is untouched).
Exceptions other than `Highlight_lines::Invalid_input` and `Highlight_lines::Fairing_failure`
(e.g. from a visitor) propagate, with the region being faired restored as
`fair_with_highlight_lines()` documents; the regions faired before stay faired.
*/
// clang-format on
template <typename TriangleMesh, typename GeomTraits,
          typename NamedParameters = parameters::Default_named_parameters>
std::vector<Highlight_lines::Irregularity_repair<TriangleMesh>>
detect_and_fair_highlight_line_irregularities(
    TriangleMesh& tm, const Highlight_lines::Light_setup<GeomTraits>& lights,
    const NamedParameters& np = parameters::default_values())
{
  namespace HL = Highlight_lines;
  const double minimum_confidence = double(parameters::choose_parameter(
      parameters::get_parameter(np, HL::internal_np::minimum_confidence), 0.5));
  if (!(minimum_confidence >= 0 && minimum_confidence <= 1))
    throw HL::Invalid_input(HL::Invalid_input::Problem::INVALID_PARAMETER,
                            "minimum_confidence must be in [0, 1]");
  // The fairing margin: by default as many rings as the detection scale's mean edge lengths, up
  // to the detection's sharp edges (the options are checked here as the detection checks them).
  const HL::internal::Detection_options detection_options(np);
  const int margin_rings = int(
      parameters::choose_parameter(parameters::get_parameter(np, HL::internal_np::fairing_margin),
                                   int(std::ceil(detection_options.scale))));
  if (!(margin_rings >= 0 && margin_rings <= 1000))
    throw HL::Invalid_input(HL::Invalid_input::Problem::INVALID_PARAMETER,
                            "fairing_margin must be in [0, 1000] rings");
  const auto vpm =
      parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                   get_const_property_map(vertex_point, tm));
  std::vector<HL::Highlight_line_irregularity<TriangleMesh>> found;
  detect_highlight_line_irregularities(static_cast<const TriangleMesh&>(tm), lights,
                                       std::back_inserter(found), np);
  HL::join_touching_irregularities(static_cast<const TriangleMesh&>(tm), found, minimum_confidence);
  std::vector<HL::Irregularity_repair<TriangleMesh>> repairs;
  repairs.reserve(found.size());
  for (auto& irregularity : found) {
    HL::Irregularity_repair<TriangleMesh> repair;
    repair.irregularity = std::move(irregularity);
    if (repair.irregularity.confidence < minimum_confidence) {
      repair.skipped = true;
      repair.failure = "skipped: confidence " + std::to_string(repair.irregularity.confidence) +
                       " below minimum_confidence " + std::to_string(minimum_confidence) +
                       " (likely design, not a defect)";
      repairs.push_back(std::move(repair));
      continue;
    }
    repair.faired_faces =
        HL::grown_face_region(static_cast<const TriangleMesh&>(tm), repair.irregularity.faces,
                              margin_rings, detection_options.sharp_edge_angle, vpm);
    try {
      repair.report = fair_with_highlight_lines(tm, repair.faired_faces, lights, np);
      repair.repaired = true;
    } catch (const HL::Fairing_failure& e) {
      repair.report = e.report();
      repair.failure = e.what();
    } catch (const HL::Invalid_input& e) {
      // A parameter out of its domain is refused for the first region already, before the
      // mesh is touched: the caller's mistake, not the region's.
      if (e.problem() == HL::Invalid_input::Problem::INVALID_PARAMETER)
        throw;
      repair.failure = e.what();
    }
    repairs.push_back(std::move(repair));
  }
  return repairs;
}

} // namespace CGAL

#endif // CGAL_DETECT_AND_FAIR_HIGHLIGHT_LINE_IRREGULARITIES_H

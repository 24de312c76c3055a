// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_FAIRNESS_ENERGY_H
#define CGAL_HIGHLIGHT_LINES_FAIRNESS_ENERGY_H

namespace CGAL {
namespace Highlight_lines {

/*!
\ingroup PkgHighlightLinesRef

The fairness term \f$ q_{\mathrm{fair}} \f$ of `CGAL::fair_with_highlight_lines()`, chosen with
the named parameter `Highlight_lines::parameters::fairness_energy`. Both use the cotangent
mean curvature normal \f$ K_i = \frac{1}{2A_i} \sum_j (\cot\alpha_{ij} + \cot\beta_{ij})
(V_i - V_j) \f$ with the weights and areas frozen in each iteration.
*/
enum class Fairness_energy {
  /// \f$ \sum_i A_i \|K_i\|^2 \f$, the discrete Willmore energy of the paper (eq. 6–8). Its
  /// minimisers continue only the tangent planes of the surroundings: on dents pressed into
  /// real meshes they end further from the undented surface than `Polygon_mesh_processing::fair()`
  /// (see the manual's section on real dents).
  WILLMORE,
  /// \f$ \sum_i A_i (K_i \cdot N_i)^2 \f$, its normal part (the squared mean curvature). Equal
  /// to `WILLMORE` on well-shaped triangles; on slivers and folded triangles the tangential
  /// part of \f$ K_i \f$ (a discretisation artefact, large where cotangents are) dominates the
  /// Willmore energy, and displacements along the normals that cancel it bend the surface.
  MEAN_CURVATURE,
  /// \f$ \ell^2 \sum_{ij} c_{ij} (H_i - H_j)^2 + \mu \sum_i A_i H_i^2 \f$, the first sum
  /// over the edges with an end inside the region, the second over its vertices,
  /// \f$ H_i = K_i \cdot N_i \f$, \f$ c_{ij} = \frac{1}{2}(\cot\alpha_{ij} +
  /// \cot\beta_{ij}) \f$ clamped to [0, 1], \f$ \ell^2 \f$ the area of the region,
  /// \f$ \mu = 10 \f$ (at a vertex with a sliver or a folded triangle around it in the input,
  /// \f$ H_i \f$ is the mean curvature of a quadric fitted to its two-ring instead: the
  /// cotangent formula there measures the triangles, not the surface): the variation of the
  /// mean curvature (a third-order energy, beyond the paper) and a share of the squared mean
  /// curvature. The first term's minimisers continue the surface's curvature across the
  /// region's border, where the Willmore energy continues only its tangent planes, so that the
  /// faired surface ends closer to the surface that should be there: on dents pressed into real
  /// meshes, the RMS distance to the undented surface is half that of
  /// `Polygon_mesh_processing::fair()` and 0.4 times that of `WILLMORE` (see the manual's
  /// section on real dents). The second keeps the fairing off surfaces of constant mean
  /// curvature, on which the first is zero however far they are from the input (a region
  /// across a narrow part of a mesh was otherwise pushed 35 mean edge lengths inwards). The
  /// default.
  CURVATURE_VARIATION
};

} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_FAIRNESS_ENERGY_H

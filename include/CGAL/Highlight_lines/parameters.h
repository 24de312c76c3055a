// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_PARAMETERS_H
#define CGAL_HIGHLIGHT_LINES_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Highlight_lines {

/// \cond SKIP_IN_MANUAL
// Tags of this package's named parameters. They live in our namespace: CGAL 5.5's lookup
// works with any tag type, and CGAL's own tag list must not be patched.
namespace internal_np {
enum face_range_t { face_range };
enum level_range_t { level_range };
enum max_levels_per_edge_t { max_levels_per_edge };
enum number_of_lines_t { number_of_lines };
enum facing_side_only_t { facing_side_only };
enum fairness_weight_t { fairness_weight };
enum fairness_energy_t { fairness_energy };
enum difference_weight_t { difference_weight };
enum convergence_threshold_t { convergence_threshold };
enum qp_solver_t { qp_solver };
enum fairing_visitor_t { fairing_visitor };
enum neighborhood_rings_t { neighborhood_rings };
enum keep_completed_iterations_t { keep_completed_iterations };
enum number_of_orientations_t { number_of_orientations };
enum number_of_offsets_t { number_of_offsets };
enum detection_scale_t { detection_scale };
enum detection_threshold_t { detection_threshold };
enum minimum_bending_t { minimum_bending };
enum minimum_evidence_t { minimum_evidence };
enum region_margin_t { region_margin };
enum maximum_incidence_angle_t { maximum_incidence_angle };
enum minimum_confidence_t { minimum_confidence };
enum fairing_margin_t { fairing_margin };
enum all_sides_t { all_sides };
enum local_residual_t { local_residual };
enum number_of_scales_t { number_of_scales };
enum crease_edge_map_t { crease_edge_map };
// Internal, for the detection's sweeps: an edge over max_levels_per_edge is dropped with its
// faces (the rule before the facing window, see internal::Level_window).
enum drop_faces_over_cap_t { drop_faces_over_cap };
} // namespace internal_np
/// \endcond

/*!
\ingroup PkgHighlightLinesRef

Named parameters of this package.

CGAL 5.5 generates the member functions used to chain named parameters
(`CGAL::parameters::vertex_point_map(vpm).geom_traits(k)`) from its own list, which cannot be
extended from outside CGAL. Each parameter of this package is therefore offered as two free
functions: one that starts a pack, `Highlight_lines::parameters::face_range(faces)`, and one
that appends to an existing pack, `Highlight_lines::parameters::face_range(pack, faces)`.
A CGAL parameter can follow one of ours with the usual member syntax, and `combine()` joins
packs:

\code
namespace HLP = CGAL::Highlight_lines::parameters;
auto np1 = HLP::face_range(faces).vertex_point_map(vpm);
auto np2 = HLP::level_range(CGAL::parameters::geom_traits(k), std::make_pair(-5, 5));
auto np3 = HLP::combine(CGAL::parameters::vertex_point_map(vpm), HLP::face_range(faces),
                        HLP::max_levels_per_edge(64));
\endcode

A mixed pack can be forwarded unchanged to CGAL functions, which ignore the tags they do not
know.
*/
namespace parameters {

/// \cond SKIP_IN_MANUAL
#define CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(TAG, NAME)                                            \
  template <typename T>                                                                            \
  CGAL::Named_function_parameters<T, internal_np::TAG> NAME(const T& value)                        \
  {                                                                                                \
    return CGAL::Named_function_parameters<T, internal_np::TAG>(value);                            \
  }                                                                                                \
  template <typename NP_T, typename NP_Tag, typename NP_Base, typename T>                          \
  CGAL::Named_function_parameters<T, internal_np::TAG,                                             \
                                  CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>>          \
  NAME(const CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>& pack, const T& value)         \
  {                                                                                                \
    return CGAL::Named_function_parameters<                                                        \
        T, internal_np::TAG, CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>>(value, pack); \
  }

CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(face_range_t, face_range)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(level_range_t, level_range)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(max_levels_per_edge_t, max_levels_per_edge)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(number_of_lines_t, number_of_lines)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(facing_side_only_t, facing_side_only)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(fairness_weight_t, fairness_weight)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(fairness_energy_t, fairness_energy)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(difference_weight_t, difference_weight)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(convergence_threshold_t, convergence_threshold)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(qp_solver_t, qp_solver)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(fairing_visitor_t, fairing_visitor)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(neighborhood_rings_t, neighborhood_rings)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(keep_completed_iterations_t, keep_completed_iterations)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(number_of_orientations_t, number_of_orientations)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(number_of_offsets_t, number_of_offsets)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(detection_scale_t, detection_scale)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(detection_threshold_t, detection_threshold)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(minimum_bending_t, minimum_bending)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(minimum_evidence_t, minimum_evidence)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(region_margin_t, region_margin)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(maximum_incidence_angle_t, maximum_incidence_angle)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(minimum_confidence_t, minimum_confidence)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(fairing_margin_t, fairing_margin)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(all_sides_t, all_sides)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(local_residual_t, local_residual)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(number_of_scales_t, number_of_scales)
CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER(crease_edge_map_t, crease_edge_map)

#undef CGAL_HIGHLIGHT_LINES_NAMED_PARAMETER

namespace combine_impl {
template <typename Front, typename Back>
struct Appended;

template <typename Front, typename T, typename Tag>
struct Appended<Front, CGAL::Named_function_parameters<T, Tag, CGAL::internal_np::No_property>>
{
  typedef CGAL::Named_function_parameters<T, Tag, Front> type;
  static type
  make(const Front& front,
       const CGAL::Named_function_parameters<T, Tag, CGAL::internal_np::No_property>& back)
  {
    return type(CGAL::internal_np::get_reference(back.v), front);
  }
};

template <typename Front, typename T, typename Tag, typename Base>
struct Appended<Front, CGAL::Named_function_parameters<T, Tag, Base>>
{
  typedef CGAL::Named_function_parameters<T, Tag, Base> Back;
  typedef Appended<Front, Base> Inner;
  typedef CGAL::Named_function_parameters<T, Tag, typename Inner::type> type;
  static type make(const Front& front, const Back& back)
  {
    return type(CGAL::internal_np::get_reference(back.v),
                Inner::make(front, static_cast<const Base&>(back)));
  }
};
} // namespace combine_impl
/// \endcond

/// Joins named parameter packs into one; for a tag given twice, the later pack wins.
template <typename P>
const P& combine(const P& pack)
{
  return pack;
}

/// \cond SKIP_IN_MANUAL
template <typename P1, typename P2, typename... Rest>
auto combine(const P1& first, const P2& second, const Rest&... rest)
{
  return combine(combine_impl::Appended<P1, P2>::make(first, second), rest...);
}
/// \endcond

} // namespace parameters
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_PARAMETERS_H

// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_DETECTION_OPTIONS_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_DETECTION_OPTIONS_H

#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/Highlight_lines/parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <cmath>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// The options of detect_highlight_line_irregularities(), read from its named parameters and
// checked.
struct Detection_options
{
  int orientations = 3;
  int offsets = 2;
  double scale = 3.0;     // w, in mean edge lengths
  double threshold = 5.0; // robust z-score
  double minimum_bending = 0.01;
  double minimum_evidence = 0.5; // fraction of the light setups
  int margin = 2;
  double maximum_incidence_angle = 60; // degrees
  double sharp_edge_angle = 60;        // degrees
  bool all_sides = true;
  bool local_residual = true; // false: the bending measure (closer to the paper)
  int scales = 1;             // with local_residual: w, 2w, ...

  template <typename NamedParameters>
  explicit Detection_options(const NamedParameters& np)
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    const double o = double(
        choose_parameter(get_parameter(np, internal_np::number_of_orientations), orientations));
    const double k =
        double(choose_parameter(get_parameter(np, internal_np::number_of_offsets), offsets));
    scale = double(choose_parameter(get_parameter(np, internal_np::detection_scale), scale));
    threshold =
        double(choose_parameter(get_parameter(np, internal_np::detection_threshold), threshold));
    minimum_bending =
        double(choose_parameter(get_parameter(np, internal_np::minimum_bending), minimum_bending));
    minimum_evidence = double(
        choose_parameter(get_parameter(np, internal_np::minimum_evidence), minimum_evidence));
    const double m =
        double(choose_parameter(get_parameter(np, internal_np::region_margin), margin));
    all_sides = bool(choose_parameter(get_parameter(np, internal_np::all_sides), all_sides));
    local_residual =
        bool(choose_parameter(get_parameter(np, internal_np::local_residual), local_residual));
    const double n =
        double(choose_parameter(get_parameter(np, internal_np::number_of_scales), scales));
    maximum_incidence_angle = double(choose_parameter(
        get_parameter(np, internal_np::maximum_incidence_angle), maximum_incidence_angle));
    auto require = [](bool ok, const char* what) {
      if (!ok)
        throw Invalid_input(Invalid_input::Problem::INVALID_PARAMETER, what);
    };
    require(o >= 1 && o <= 64, "number_of_orientations must be in [1, 64]");
    require(k >= 1 && k <= 64, "number_of_offsets must be in [1, 64]");
    require(scale >= 1 && scale <= 1000, "detection_scale must be in [1, 1000] mean edge lengths");
    require(threshold > 0 && std::isfinite(threshold), "detection_threshold must be positive");
    require(minimum_bending >= 0 && std::isfinite(minimum_bending),
            "minimum_bending must be finite and not negative");
    require(minimum_evidence > 0 && minimum_evidence <= 1, "minimum_evidence must be in (0, 1]");
    require(m >= 0 && m <= 1000, "region_margin must be in [0, 1000] rings");
    require(n >= 1 && n <= 4, "number_of_scales must be in [1, 4]");
    require(maximum_incidence_angle > 0 && maximum_incidence_angle <= 90,
            "maximum_incidence_angle must be in (0, 90] degrees");
    orientations = int(o);
    offsets = int(k);
    margin = int(m);
    scales = int(n);
  }
};

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_DETECTION_OPTIONS_H

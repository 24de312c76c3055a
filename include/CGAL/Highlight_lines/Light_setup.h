// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_LIGHT_SETUP_H
#define CGAL_HIGHLIGHT_LINES_LIGHT_SETUP_H

#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/Highlight_lines/internal/vector3.h>

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <sstream>
#include <string>

namespace CGAL {
namespace Highlight_lines {

/*!
\ingroup PkgHighlightLinesRef

A family of coplanar, parallel, equally spaced linear light sources (§2.1–2.2 of the paper):
the light plane `S` with unit normal `Z`, a point `A0` of the base light source `L0` (in `S`),
the unit direction `H` of the lights (in `S`, so `H·Z = 0`) and the spacing `s > 0` between
adjacent lights.

The highlight distance value of a surface point `P` with normal `N` is (eq. 1)
`d(P) = ((P - A0) x H)·N / (Z·N)`; `P` lies on the highlight line of light number `m` when
`d(P) = m·s`. Note that `d` is the signed distance, measured along `H x Z`, from `L0` to the
point where the normal line of `P` meets `S` (the paper says "along `Z x H`", which has the
opposite sign; only the numbering direction of the lights is affected).

A light setup is validated on construction and is immutable; sweeping the highlight line
model over a surface means computing it for a sequence of setups obtained with
`translated()`, `rotated()` or `transformed()`.

\tparam GeomTraits a model of `Kernel`.
*/
template <typename GeomTraits>
class Light_setup
{
public:
  /// The kernel, `GeomTraits`.
  typedef GeomTraits Geom_traits;
  /// The number type of the kernel.
  typedef typename GeomTraits::FT FT;
  /// The point type of the kernel.
  typedef typename GeomTraits::Point_3 Point_3;
  /// The vector type of the kernel.
  typedef typename GeomTraits::Vector_3 Vector_3;

  /*!
  Builds and validates a light setup.

  \param base_point a point `A0` of the base light `L0`; it also fixes the light plane.
  \param light_direction the direction `H` of the lights; normalised here.
  \param plane_normal the normal `Z` of the light plane; normalised here.
  \param spacing the distance `s` between adjacent lights.

  \throws Invalid_input (problem `INVALID_LIGHT_SETUP`) if a value is not finite, a vector is
  zero, the spacing is not positive, or `H` is not perpendicular to `Z` (the angle between
  them may differ from 90 degrees by at most about 1e-6 radians; `H` is then projected into
  the plane so that the stored vectors are orthonormal to double precision).
  */
  Light_setup(const Point_3& base_point, const Vector_3& light_direction,
              const Vector_3& plane_normal, const FT& spacing)
  {
    auto to_array = [](const auto& v) {
      return std::array<double, 3>{CGAL::to_double(v.x()), CGAL::to_double(v.y()),
                                   CGAL::to_double(v.z())};
    };
    a_ = to_array(base_point);
    h_ = to_array(light_direction);
    z_ = to_array(plane_normal);
    s_ = CGAL::to_double(spacing);
    validate_and_normalize();
  }

  /// The point `A0` on the base light source.
  Point_3 base_point() const { return Point_3(a_[0], a_[1], a_[2]); }
  /// The unit direction `H` of the light sources.
  Vector_3 light_direction() const { return Vector_3(h_[0], h_[1], h_[2]); }
  /// The unit normal `Z` of the light plane.
  Vector_3 plane_normal() const { return Vector_3(z_[0], z_[1], z_[2]); }
  /// The unit vector `H x Z`, in the light plane, along which light indices grow.
  Vector_3 index_direction() const
  {
    const auto c = internal::vector3::cross(h_, z_);
    return Vector_3(c[0], c[1], c[2]);
  }
  /// The spacing `s` between adjacent light sources.
  FT spacing() const { return FT(s_); }

  /// The point on light number `m`, in the light plane: `A0 + m·s·(H x Z)`.
  Point_3 point_on_light(long long m) const
  {
    const auto c = internal::vector3::cross(h_, z_);
    const double t = double(m) * s_;
    return Point_3(a_[0] + t * c[0], a_[1] + t * c[1], a_[2] + t * c[2]);
  }

  /// The same lights moved by `t`.
  Light_setup translated(const Vector_3& t) const
  {
    return Light_setup(base_point() + t, light_direction(), plane_normal(), spacing());
  }

  /// The same lights rotated by `angle` (radians) around the axis through `A0` along `axis`.
  Light_setup rotated(const Vector_3& axis, double angle) const
  {
    std::array<double, 3> k{CGAL::to_double(axis.x()), CGAL::to_double(axis.y()),
                            CGAL::to_double(axis.z())};
    const double len = std::sqrt(internal::vector3::dot(k, k));
    if (!(len > 0) || !std::isfinite(len) || !std::isfinite(angle))
      throw Invalid_input(Invalid_input::Problem::INVALID_LIGHT_SETUP,
                          "Light_setup::rotated(): the rotation axis must be a finite, non-zero "
                          "vector and the angle finite");
    for (double& c : k)
      c /= len;
    auto rotate = [&](const std::array<double, 3>& v) { // Rodrigues' formula
      const double c = std::cos(angle), s = std::sin(angle), kv = internal::vector3::dot(k, v);
      const auto kxv = internal::vector3::cross(k, v);
      return std::array<double, 3>{v[0] * c + kxv[0] * s + k[0] * kv * (1 - c),
                                   v[1] * c + kxv[1] * s + k[1] * kv * (1 - c),
                                   v[2] * c + kxv[2] * s + k[2] * kv * (1 - c)};
    };
    const auto h = rotate(h_), z = rotate(z_);
    return Light_setup(base_point(), Vector_3(h[0], h[1], h[2]), Vector_3(z[0], z[1], z[2]),
                       spacing());
  }

  /*!
  The lights moved along with a mesh by the similarity `T` (a rigid motion, possibly with a
  uniform scaling `λ`): `A0`, `H` and `Z` are transformed and the spacing is multiplied by
  `λ`, so that the highlight lines of the transformed mesh are the transformed lines.

  \throws Invalid_input if `T` is not a similarity.
  */
  Light_setup transformed(const Aff_transformation_3<GeomTraits>& T) const
  {
    const Vector_3 h = light_direction().transform(T);
    const Vector_3 z = plane_normal().transform(T);
    const double lh = std::sqrt(CGAL::to_double(h.squared_length()));
    const double lz = std::sqrt(CGAL::to_double(z.squared_length()));
    if (!(std::abs(lh - lz) <= 1e-9 * (std::max)(lh, lz)))
      throw Invalid_input(Invalid_input::Problem::INVALID_LIGHT_SETUP,
                          "Light_setup::transformed(): the transformation is not a similarity");
    return Light_setup(base_point().transform(T), h, z, FT(s_ * lh));
  }

  /// \cond SKIP_IN_MANUAL
  // Flat copies used by the computations.
  const std::array<double, 3>& base_point_array() const { return a_; }
  const std::array<double, 3>& light_direction_array() const { return h_; }
  const std::array<double, 3>& plane_normal_array() const { return z_; }
  double spacing_value() const { return s_; }
  /// \endcond

private:
  void fail(const std::string& what) const
  {
    std::ostringstream message;
    message.precision(17);
    message << "invalid light setup: " << what << " (base point " << a_[0] << ' ' << a_[1] << ' '
            << a_[2] << ", direction " << h_[0] << ' ' << h_[1] << ' ' << h_[2] << ", plane normal "
            << z_[0] << ' ' << z_[1] << ' ' << z_[2] << ", spacing " << s_ << ")";
    throw Invalid_input(Invalid_input::Problem::INVALID_LIGHT_SETUP, message.str());
  }

  void validate_and_normalize()
  {
    for (int i = 0; i < 3; ++i)
      if (!std::isfinite(a_[i]) || !std::isfinite(h_[i]) || !std::isfinite(z_[i]))
        fail("non-finite coordinate");
    if (!std::isfinite(s_) || !(s_ > 0))
      fail("the spacing must be a finite positive number");
    const double lh = std::sqrt(internal::vector3::dot(h_, h_)),
                 lz = std::sqrt(internal::vector3::dot(z_, z_));
    if (!(lh > 0) || !std::isfinite(lh))
      fail("the light direction H is the zero vector or too large");
    if (!(lz > 0) || !std::isfinite(lz))
      fail("the plane normal Z is the zero vector or too large");
    for (int i = 0; i < 3; ++i) {
      h_[i] /= lh;
      z_[i] /= lz;
    }
    const double hz = internal::vector3::dot(h_, z_);
    if (std::abs(hz) > 1e-6)
      fail("the light direction H must lie in the light plane, i.e. be perpendicular to its "
           "normal Z (H·Z = " +
           std::to_string(hz) + " after normalisation)");
    for (int i = 0; i < 3; ++i)
      h_[i] -= hz * z_[i];
    const double lh2 = std::sqrt(internal::vector3::dot(h_, h_));
    for (double& c : h_)
      c /= lh2;
  }

  std::array<double, 3> a_, h_, z_;
  double s_;
};

} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_LIGHT_SETUP_H

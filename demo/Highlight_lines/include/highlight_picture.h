// Copyright (c) 2024 The Highlight_lines package authors.
//
// highlight_picture.h: a small software renderer and PNG writer for the command-line programs.
//
// Renders triangle meshes (z-buffered, Lambert + ambient + Blinn specular, smooth or flat,
// two-sided), 3D polylines and point markers drawn over them with a depth test, captions in a
// built-in bitmap font, and side-by-side compositions, then writes the result as PNG, compressed
// with zlib (Debian zlib1g-dev). Nothing else but the C++ standard library is used, so the
// programs need no image library and no display. Anti-aliasing is done by supersampling the
// whole picture.

#ifndef HIGHLIGHT_PICTURE_H
#define HIGHLIGHT_PICTURE_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <zlib.h>

namespace highlight_picture {

using Point3 = std::array<double, 3>;
using Vector3 = std::array<double, 3>;

struct RGB
{
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
};

inline bool operator==(const RGB& a, const RGB& b)
{
  return a.r == b.r && a.g == b.g && a.b == b.b;
}
inline bool operator!=(const RGB& a, const RGB& b)
{
  return !(a == b);
}

/// Linear blend: t = 0 gives `a`, t = 1 gives `b`.
inline RGB mix(const RGB& a, const RGB& b, double t)
{
  t = std::clamp(t, 0.0, 1.0);
  auto channel = [t](std::uint8_t x, std::uint8_t y) {
    return static_cast<std::uint8_t>(std::lround(x + (y - x) * t));
  };
  return {channel(a.r, b.r), channel(a.g, b.g), channel(a.b, b.b)};
}

namespace colors {
inline constexpr RGB white{255, 255, 255};
inline constexpr RGB black{0, 0, 0};
inline constexpr RGB background{255, 255, 255};
inline constexpr RGB text{40, 40, 48};
inline constexpr RGB panel_frame{215, 215, 220};
/// Neutral grey-blue, like a car's paint under a light box.
inline constexpr RGB paint{158, 170, 188};
/// Dark, slightly blue highlight lines.
inline constexpr RGB highlight_line{22, 26, 40};
/// Tint for a region of interest, e.g. the faired region.
inline constexpr RGB region{140, 190, 235};
inline constexpr RGB red{210, 45, 40};
inline constexpr RGB orange{235, 140, 30};
inline constexpr RGB green{40, 150, 70};
inline constexpr RGB blue{40, 90, 200};
} // namespace colors

/// Blue (t = 0) through white (t = 0.5) to red (t = 1): for signed quantities such as deviations.
inline RGB diverging_color(double t)
{
  constexpr RGB cold{59, 76, 192};
  constexpr RGB neutral{235, 235, 235};
  constexpr RGB warm{180, 4, 38};
  t = std::clamp(t, 0.0, 1.0);
  return t < 0.5 ? mix(cold, neutral, 2 * t) : mix(neutral, warm, 2 * t - 1);
}

namespace detail {

inline Vector3 add(const Vector3& a, const Vector3& b)
{
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vector3 sub(const Vector3& a, const Vector3& b)
{
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Vector3 scale(const Vector3& a, double s)
{
  return {a[0] * s, a[1] * s, a[2] * s};
}
inline double dot(const Vector3& a, const Vector3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vector3 cross(const Vector3& a, const Vector3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline constexpr double pi = 3.14159265358979323846;
inline double length(const Vector3& a)
{
  return std::sqrt(dot(a, a));
}
inline Vector3 normalized(const Vector3& a)
{
  const double l = length(a);
  return l > 0 ? scale(a, 1 / l) : Vector3{0, 0, 0};
}

} // namespace detail

// ------------------------------------------------------------------------------------------------
// Image
// ------------------------------------------------------------------------------------------------

/// An RGB raster, row-major from the top-left corner.
class Image
{
public:
  Image() = default;
  Image(int width, int height, RGB fill = colors::background)
      : width_(std::max(width, 0)), height_(std::max(height, 0)),
        pixels_(static_cast<std::size_t>(width_) * height_, fill)
  {
  }

  int width() const { return width_; }
  int height() const { return height_; }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
  RGB& operator()(int x, int y) { return pixels_[static_cast<std::size_t>(y) * width_ + x]; }
  const RGB& operator()(int x, int y) const
  {
    return pixels_[static_cast<std::size_t>(y) * width_ + x];
  }
  const std::vector<RGB>& pixels() const { return pixels_; }
  RGB* data() { return pixels_.data(); }
  const RGB* data() const { return pixels_.data(); }

  /// Fills the part of the rectangle that lies inside the image.
  void fill_rectangle(int x, int y, int width, int height, RGB color)
  {
    const int x0 = std::max(x, 0), x1 = std::min(x + width, width_);
    const int y0 = std::max(y, 0), y1 = std::min(y + height, height_);
    for (int yy = y0; yy < y1; ++yy)
      for (int xx = x0; xx < x1; ++xx)
        (*this)(xx, yy) = color;
  }

  /// Copies `other` with its top-left corner at (x, y), clipped to this image.
  void paste(const Image& other, int x, int y)
  {
    for (int yy = 0; yy < other.height(); ++yy)
      for (int xx = 0; xx < other.width(); ++xx)
        if (contains(x + xx, y + yy))
          (*this)(x + xx, y + yy) = other(xx, yy);
  }

  /// Box-filters factor x factor blocks into one pixel (the last partial blocks are dropped).
  Image downsampled(int factor) const
  {
    if (factor <= 1)
      return *this;
    Image result(width_ / factor, height_ / factor);
    const int samples = factor * factor;
    for (int y = 0; y < result.height(); ++y)
      for (int x = 0; x < result.width(); ++x) {
        int r = 0, g = 0, b = 0;
        for (int dy = 0; dy < factor; ++dy) {
          const RGB* row = &(*this)(x * factor, y * factor + dy);
          for (int dx = 0; dx < factor; ++dx) {
            r += row[dx].r;
            g += row[dx].g;
            b += row[dx].b;
          }
        }
        result(x, y) = {static_cast<std::uint8_t>((r + samples / 2) / samples),
                        static_cast<std::uint8_t>((g + samples / 2) / samples),
                        static_cast<std::uint8_t>((b + samples / 2) / samples)};
      }
    return result;
  }

private:
  int width_ = 0;
  int height_ = 0;
  std::vector<RGB> pixels_;
};

// ------------------------------------------------------------------------------------------------
// Camera
// ------------------------------------------------------------------------------------------------

struct Box3
{
  Point3 min{0, 0, 0};
  Point3 max{0, 0, 0};
};

inline Box3 bounding_box(const std::vector<Point3>& points)
{
  Box3 box;
  if (points.empty())
    return box;
  box.min = box.max = points.front();
  for (const Point3& p : points)
    for (int i = 0; i < 3; ++i) {
      box.min[i] = std::min(box.min[i], p[i]);
      box.max[i] = std::max(box.max[i], p[i]);
    }
  return box;
}

/// Orthographic camera. Depth is measured along `view_direction` from `center`.
struct Camera
{
  Point3 center{0, 0, 0};           ///< world point shown at the image centre
  Vector3 view_direction{0, 0, -1}; ///< from the eye into the scene
  Vector3 up{0, 1, 0};              ///< made perpendicular to view_direction
  double view_height = 2.0;         ///< world length spanned by the image height
  /// Nothing nearer than this depth is drawn: cuts away what hides a zoomed-in region.
  double near_clip = -std::numeric_limits<double>::infinity();

  Vector3 forward() const { return detail::normalized(view_direction); }
  Vector3 right() const
  {
    Vector3 r = detail::cross(forward(), up);
    if (detail::length(r) < 1e-12 * detail::length(up)) // up parallel to the view: pick any
      r = detail::cross(forward(),
                        std::abs(forward()[0]) < 0.9 ? Vector3{1, 0, 0} : Vector3{0, 1, 0});
    return detail::normalized(r);
  }
  Vector3 true_up() const { return detail::cross(right(), forward()); }
};

/// Direction from the eye into the scene for a viewer at the given azimuth (about +z, from +x)
/// and elevation (above the xy plane), in degrees; use with up = {0, 0, 1}.
inline Vector3 view_direction_from_angles(double azimuth_degrees, double elevation_degrees)
{
  const double a = azimuth_degrees * detail::pi / 180, e = elevation_degrees * detail::pi / 180;
  return {-std::cos(e) * std::cos(a), -std::cos(e) * std::sin(a), -std::sin(e)};
}

/// Camera that shows all `points` in a width x height picture, with `margin` (a fraction of
/// the picture size) left free on each side.
inline Camera fit_camera(const std::vector<Point3>& points, const Vector3& view_direction,
                         const Vector3& up, int width, int height, double margin = 0.05)
{
  Camera camera;
  camera.view_direction = view_direction;
  camera.up = up;
  if (points.empty())
    return camera;
  const Vector3 axes[3] = {camera.right(), camera.true_up(), camera.forward()};
  double lo[3], hi[3];
  for (int i = 0; i < 3; ++i)
    lo[i] = hi[i] = detail::dot(points.front(), axes[i]);
  for (const Point3& p : points)
    for (int i = 0; i < 3; ++i) {
      const double c = detail::dot(p, axes[i]);
      lo[i] = std::min(lo[i], c);
      hi[i] = std::max(hi[i], c);
    }
  camera.center = {0, 0, 0};
  for (int i = 0; i < 3; ++i)
    camera.center = detail::add(camera.center, detail::scale(axes[i], (lo[i] + hi[i]) / 2));
  const double aspect = height > 0 ? static_cast<double>(width) / height : 1.0;
  const double extent = std::max(hi[1] - lo[1], (hi[0] - lo[0]) / aspect);
  const double usable = std::max(1 - 2 * margin, 0.05);
  camera.view_height = extent > 0 ? extent / usable : 1.0;
  return camera;
}

/// Camera that shows `box` (e.g. a close-up of a region) in a width x height picture.
inline Camera fit_camera(const Box3& box, const Vector3& view_direction, const Vector3& up,
                         int width, int height, double margin = 0.05)
{
  std::vector<Point3> corners;
  for (int i = 0; i < 8; ++i)
    corners.push_back({(i & 1) ? box.max[0] : box.min[0], (i & 2) ? box.max[1] : box.min[1],
                       (i & 4) ? box.max[2] : box.min[2]});
  return fit_camera(corners, view_direction, up, width, height, margin);
}

// ------------------------------------------------------------------------------------------------
// Mesh helpers
// ------------------------------------------------------------------------------------------------

/// Area-weighted vertex normals (unit length; zero for isolated vertices).
template <class Index>
std::vector<Vector3> vertex_normals(const std::vector<Point3>& points,
                                    const std::vector<std::array<Index, 3>>& triangles)
{
  std::vector<Vector3> normals(points.size(), Vector3{0, 0, 0});
  for (const auto& t : triangles) {
    const std::size_t i = static_cast<std::size_t>(t[0]), j = static_cast<std::size_t>(t[1]),
                      k = static_cast<std::size_t>(t[2]);
    if (i >= points.size() || j >= points.size() || k >= points.size())
      continue;
    // The unnormalised cross product weighs each face by its area.
    const Vector3 n =
        detail::cross(detail::sub(points[j], points[i]), detail::sub(points[k], points[i]));
    for (std::size_t v : {i, j, k})
      normals[v] = detail::add(normals[v], n);
  }
  for (Vector3& n : normals)
    n = detail::normalized(n);
  return normals;
}

// ------------------------------------------------------------------------------------------------
// Renderer
// ------------------------------------------------------------------------------------------------

struct Surface_style
{
  RGB color = colors::paint;
  bool smooth = true;    ///< interpolate vertex normals; false: one normal per face
  bool two_sided = true; ///< back faces are lit like front faces
  double ambient = 0.12;
  double diffuse = 0.8;
  double specular = 0.3;
  double shininess = 40;
  /// Key light, in camera coordinates: x right, y up, z toward the viewer.
  Vector3 light_direction{-0.45, 0.55, 1.0};
  /// Weak second light from the other side so the shadowed side keeps its shape.
  double fill = 0.18;
  Vector3 fill_direction{0.7, -0.3, 0.6};
};

struct Line_style
{
  RGB color = colors::highlight_line;
  double width = 1.6; ///< in output pixels
  /// Lines are pulled this many output-pixel sizes toward the viewer before the depth test.
  double depth_bias = 1.5;
};

struct Marker_style
{
  RGB color = colors::orange;
  double radius = 3.5; ///< in output pixels
  RGB outline = colors::highlight_line;
  double outline_width = 1.0; ///< in output pixels; 0 for none
  double depth_bias = 1.5;    ///< as in Line_style
};

struct Render_options
{
  int supersampling = 3; ///< the picture is rendered this many times larger, then box-filtered
  RGB background = colors::background;
};

namespace detail {

/// Converts after clamping, since converting an out-of-range double to int is undefined.
inline int clamped_int(double value, int low, int high)
{
  if (!(value > low)) // also NaN
    return low;
  return value < high ? static_cast<int>(value) : high;
}

template <class Index>
bool valid_index(Index i, std::size_t size)
{
  if constexpr (std::is_signed<Index>::value)
    if (i < 0)
      return false;
  return static_cast<std::size_t>(i) < size;
}

inline double srgb_to_linear(std::uint8_t c)
{
  const double v = c / 255.0;
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

/// Lighting is computed in linear light, which gives the soft falloff of real paint; this table
/// converts back to sRGB without calling pow() per pixel.
inline std::uint8_t linear_to_srgb(double v)
{
  static constexpr int table_size = 4096;
  static const std::array<std::uint8_t, table_size + 1> table = [] {
    std::array<std::uint8_t, table_size + 1> t{};
    for (int i = 0; i <= table_size; ++i) {
      const double x = static_cast<double>(i) / table_size;
      const double s = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055;
      t[i] = static_cast<std::uint8_t>(std::lround(std::clamp(s, 0.0, 1.0) * 255));
    }
    return t;
  }();
  if (!(v > 0))
    return 0;
  return table[v >= 1 ? table_size : static_cast<int>(v * table_size + 0.5)];
}

} // namespace detail

/// Z-buffered software renderer. Meshes are rasterised immediately; polylines and markers are
/// kept and drawn over the finished surface by image(), so the call order does not matter.
class Renderer
{
public:
  /// A width x height picture (in output pixels) seen through `camera`.
  Renderer(int width, int height, const Camera& camera, const Render_options& options = {})
      : width_(std::max(width, 1)), height_(std::max(height, 1)),
        supersampling_(std::clamp(options.supersampling, 1, 8)), camera_(camera),
        right_(camera.right()), up_(camera.true_up()), forward_(camera.forward()),
        sample_size_(camera.view_height / (height_ * supersampling_)),
        samples_(width_ * supersampling_, height_ * supersampling_, options.background),
        depth_(static_cast<std::size_t>(samples_.width()) * samples_.height(),
               std::numeric_limits<float>::infinity())
  {
  }

  int width() const { return width_; }
  int height() const { return height_; }
  const Camera& camera() const { return camera_; }

  /// Output-pixel coordinates (x right, y down) and depth (larger is farther) of `p`.
  std::array<double, 3> project(const Point3& p) const
  {
    const Screen_point s = to_screen(p);
    return {s.x / supersampling_, s.y / supersampling_, s.depth};
  }

  /// World length of one output pixel.
  double pixel_size() const { return sample_size_ * supersampling_; }

  /// Rasterises a triangle mesh. `face_colors`, if not empty, has one entry per triangle and
  /// replaces style.color where set (e.g. to tint a region).
  template <class Index>
  void draw_mesh(const std::vector<Point3>& points,
                 const std::vector<std::array<Index, 3>>& triangles,
                 const Surface_style& style = {},
                 const std::vector<std::optional<RGB>>& face_colors = {})
  {
    static_assert(std::is_integral<Index>::value, "triangle indices must be integers");
    if (!face_colors.empty() && face_colors.size() != triangles.size())
      throw std::invalid_argument("highlight_picture: face_colors needs one entry per triangle");
    for (const auto& t : triangles)
      for (Index i : t)
        if (!detail::valid_index(i, points.size()))
          throw std::out_of_range("highlight_picture: triangle index out of range");

    std::vector<Screen_point> screen(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
      screen[i] = to_screen(points[i]);
    std::vector<Vector3> normals;
    if (style.smooth) {
      normals = vertex_normals(points, triangles);
      for (Vector3& n : normals)
        n = to_camera_frame(n);
    }

    const Lighting lighting(style);
    const double default_color[3] = {detail::srgb_to_linear(style.color.r),
                                     detail::srgb_to_linear(style.color.g),
                                     detail::srgb_to_linear(style.color.b)};
    for (std::size_t f = 0; f < triangles.size(); ++f) {
      const std::size_t v[3] = {static_cast<std::size_t>(triangles[f][0]),
                                static_cast<std::size_t>(triangles[f][1]),
                                static_cast<std::size_t>(triangles[f][2])};
      const Vector3 face_normal = to_camera_frame(detail::cross(
          detail::sub(points[v[1]], points[v[0]]), detail::sub(points[v[2]], points[v[0]])));
      // Two-sided lighting: a face seen from behind is lit as if its normals were flipped.
      const double flip = (style.two_sided && face_normal[2] < 0) ? -1.0 : 1.0;
      Vector3 corner_normals[3];
      for (int c = 0; c < 3; ++c)
        corner_normals[c] =
            detail::scale(style.smooth ? normals[v[c]] : detail::normalized(face_normal), flip);

      double color[3] = {default_color[0], default_color[1], default_color[2]};
      if (!face_colors.empty() && face_colors[f]) {
        const RGB& c = *face_colors[f];
        color[0] = detail::srgb_to_linear(c.r);
        color[1] = detail::srgb_to_linear(c.g);
        color[2] = detail::srgb_to_linear(c.b);
      }

      rasterize_triangle(screen[v[0]], screen[v[1]], screen[v[2]],
                         [&](std::size_t sample, const double b[3]) {
                           Vector3 n = corner_normals[0];
                           if (style.smooth)
                             n = detail::normalized(
                                 detail::add(detail::add(detail::scale(corner_normals[0], b[0]),
                                                         detail::scale(corner_normals[1], b[1])),
                                             detail::scale(corner_normals[2], b[2])));
                           samples_.data()[sample] = lighting.shade(n, color);
                         });
    }
  }

  /// Draws a 3D polyline over the surface; the parts hidden by the surface are not drawn.
  void draw_polyline(const std::vector<Point3>& polyline, const Line_style& style = {},
                     bool closed = false)
  {
    if (polyline.empty())
      return;
    const std::size_t style_index = line_styles_.size();
    line_styles_.push_back(style);
    std::vector<Screen_point> screen;
    for (const Point3& p : polyline)
      screen.push_back(to_screen(p));
    if (closed && polyline.size() > 2)
      screen.push_back(screen.front());
    if (screen.size() == 1 && screen[0].finite())
      segments_.push_back({screen[0], screen[0], style_index});
    for (std::size_t i = 0; i + 1 < screen.size(); ++i)
      if (screen[i].finite() && screen[i + 1].finite())
        segments_.push_back({screen[i], screen[i + 1], style_index});
  }

  void draw_polylines(const std::vector<std::vector<Point3>>& polylines,
                      const Line_style& style = {})
  {
    for (const auto& polyline : polylines)
      draw_polyline(polyline, style);
  }

  /// Draws a disc at each visible point (markers are drawn over the lines).
  void draw_points(const std::vector<Point3>& points, const Marker_style& style = {})
  {
    for (const Point3& p : points)
      if (const Screen_point s = to_screen(p); s.finite())
        markers_.push_back({s, style});
  }

  /// The finished picture: surface, then lines, then markers, box-filtered to the output size.
  Image image() const
  {
    Image canvas = samples_;
    for (const Segment& segment : segments_)
      draw_segment(canvas, segment);
    for (const Marker& marker : markers_)
      draw_marker(canvas, marker);
    return canvas.downsampled(supersampling_);
  }

private:
  struct Screen_point
  {
    double x = 0, y = 0; ///< in samples (supersampled pixels), y down
    double depth = 0;
    bool finite() const { return std::isfinite(x) && std::isfinite(y) && std::isfinite(depth); }
  };
  struct Segment
  {
    Screen_point a, b;
    std::size_t style;
  };
  struct Marker
  {
    Screen_point center;
    Marker_style style;
  };

  /// Surface shading for one style; lighting is done in linear light.
  class Lighting
  {
  public:
    explicit Lighting(const Surface_style& style)
        : style_(style), light_(detail::normalized(style.light_direction)),
          fill_(detail::normalized(style.fill_direction)),
          half_(detail::normalized(detail::add(light_, Vector3{0, 0, 1}))),
          // Below this n.h the highlight is under 1/1000 and pow() is skipped.
          specular_cutoff_(style.shininess > 0 ? std::pow(1e-3, 1 / style.shininess) : 0)
    {
    }

    RGB shade(const Vector3& n, const double color[3]) const
    {
      const double lambert = std::max(0.0, detail::dot(n, light_));
      const double fill = std::max(0.0, detail::dot(n, fill_));
      const double n_dot_h = detail::dot(n, half_);
      const double highlight = (style_.specular > 0 && n_dot_h > specular_cutoff_ && lambert > 0)
                                   ? style_.specular * std::pow(n_dot_h, style_.shininess)
                                   : 0.0;
      const double diffuse = style_.ambient + style_.diffuse * lambert + style_.fill * fill;
      return {detail::linear_to_srgb(color[0] * diffuse + highlight),
              detail::linear_to_srgb(color[1] * diffuse + highlight),
              detail::linear_to_srgb(color[2] * diffuse + highlight)};
    }

  private:
    Surface_style style_;
    Vector3 light_, fill_, half_;
    double specular_cutoff_;
  };

  Screen_point to_screen(const Point3& p) const
  {
    const Vector3 d = detail::sub(p, camera_.center);
    return {detail::dot(d, right_) / sample_size_ + 0.5 * samples_.width(),
            0.5 * samples_.height() - detail::dot(d, up_) / sample_size_, detail::dot(d, forward_)};
  }

  /// World vector to camera coordinates: x right, y up, z toward the viewer.
  Vector3 to_camera_frame(const Vector3& v) const
  {
    return {detail::dot(v, right_), detail::dot(v, up_), -detail::dot(v, forward_)};
  }

  /// Calls shade(sample index, barycentrics) for each sample centre inside the triangle that
  /// passes the depth test, after storing its depth.
  template <class Shade>
  void rasterize_triangle(const Screen_point& p0, const Screen_point& p1, const Screen_point& p2,
                          Shade&& shade)
  {
    const Screen_point* v[3] = {&p0, &p1, &p2};
    const double area = (p1.x - p0.x) * (p2.y - p0.y) - (p1.y - p0.y) * (p2.x - p0.x);
    if (!(std::abs(area) > 1e-12)) // degenerate on screen (or NaN)
      return;
    const double w = samples_.width(), h = samples_.height();
    const double min_x = std::max(std::min({p0.x, p1.x, p2.x}), 0.0);
    const double max_x = std::min(std::max({p0.x, p1.x, p2.x}), w);
    const double min_y = std::max(std::min({p0.y, p1.y, p2.y}), 0.0);
    const double max_y = std::min(std::max({p0.y, p1.y, p2.y}), h);
    if (min_x > max_x || min_y > max_y)
      return;
    const int x_first = static_cast<int>(std::ceil(min_x - 0.5));
    const int x_last = std::min(static_cast<int>(std::floor(max_x - 0.5)), samples_.width() - 1);
    const int y_first = static_cast<int>(std::ceil(min_y - 0.5));
    const int y_last = std::min(static_cast<int>(std::floor(max_y - 0.5)), samples_.height() - 1);
    // Shared edges are drawn by both triangles (harmless with a z-buffer): no cracks.
    constexpr double inside_tolerance = 1e-7;
    double step_x[3];
    for (int i = 0; i < 3; ++i) {
      const Screen_point &a = *v[(i + 1) % 3], &b = *v[(i + 2) % 3];
      step_x[i] = -(b.y - a.y) / area;
    }
    const float near_clip = static_cast<float>(camera_.near_clip);
    for (int y = y_first; y <= y_last; ++y) {
      const double py = y + 0.5, px0 = x_first + 0.5;
      // Barycentrics at the row start, each from its own edge (keeps rounding local).
      double row_start[3];
      double lo = x_first, hi = x_last;
      for (int i = 0; i < 3; ++i) {
        const Screen_point &a = *v[(i + 1) % 3], &b = *v[(i + 2) % 3];
        row_start[i] = ((b.x - a.x) * (py - a.y) - (b.y - a.y) * (px0 - a.x)) / area;
        // Narrow the span to where this barycentric is non-negative.
        if (step_x[i] > 0)
          lo = std::max(lo, std::ceil(x_first + (-inside_tolerance - row_start[i]) / step_x[i]));
        else if (step_x[i] < 0)
          hi = std::min(hi, std::floor(x_first + (-inside_tolerance - row_start[i]) / step_x[i]));
        else if (row_start[i] < -inside_tolerance)
          hi = lo - 1;
      }
      if (!(lo <= hi))
        continue;
      for (int x = static_cast<int>(lo); x <= static_cast<int>(hi); ++x) {
        double b[3];
        for (int i = 0; i < 3; ++i)
          b[i] = row_start[i] + (x - x_first) * step_x[i];
        if (b[0] < -inside_tolerance || b[1] < -inside_tolerance || b[2] < -inside_tolerance)
          continue;
        const float depth = static_cast<float>(b[0] * p0.depth + b[1] * p1.depth + b[2] * p2.depth);
        const std::size_t sample = static_cast<std::size_t>(y) * samples_.width() + x;
        if (depth < depth_[sample] && depth >= near_clip) {
          depth_[sample] = depth;
          shade(sample, b);
        }
      }
    }
  }

  /// True when nothing of the surface lies in front of `depth` near sample position (x, y).
  /// The farthest of the 3x3 neighbouring samples is used: a point lying on a plane is never
  /// in front of all of them, however steeply the plane is seen.
  bool visible(double x, double y, double depth) const
  {
    if (!(depth >= camera_.near_clip) || !std::isfinite(x) || !std::isfinite(y))
      return false;
    const int cx = static_cast<int>(std::floor(std::clamp(x, -2.0, samples_.width() + 2.0)));
    const int cy = static_cast<int>(std::floor(std::clamp(y, -2.0, samples_.height() + 2.0)));
    float farthest = -std::numeric_limits<float>::infinity();
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int sx = std::clamp(cx + dx, 0, samples_.width() - 1);
        const int sy = std::clamp(cy + dy, 0, samples_.height() - 1);
        farthest = std::max(farthest, depth_[static_cast<std::size_t>(sy) * samples_.width() + sx]);
      }
    return depth <= farthest;
  }

  /// A round-capped thick segment; each sample takes the visibility of the nearest point of
  /// the centre line, so a line is hidden or shown across its whole width.
  void draw_segment(Image& canvas, const Segment& segment) const
  {
    const Line_style& style = line_styles_[segment.style];
    const double radius = std::max(style.width, 0.0) * supersampling_ / 2;
    Screen_point a = segment.a, b = segment.b;
    if (!clip_to_canvas(a, b, radius + 2))
      return;
    const double bias = style.depth_bias * sample_size_ * supersampling_;
    const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
    const double y_min = std::max(std::min(a.y, b.y) - radius, 0.0);
    const double y_max = std::min(std::max(a.y, b.y) + radius, canvas.height() - 1.0);
    if (!(y_min <= y_max) || radius <= 0)
      return;
    for (int y = static_cast<int>(y_min); y <= static_cast<int>(y_max); ++y) {
      const double py = y + 0.5;
      // Part of the centre line within `radius` of this row, then the row's x extent.
      double t0 = 0, t1 = 1;
      if (std::abs(dy) > 1e-12) {
        t0 = (py - radius - a.y) / dy;
        t1 = (py + radius - a.y) / dy;
        if (t0 > t1)
          std::swap(t0, t1);
        t0 = std::max(t0, 0.0);
        t1 = std::min(t1, 1.0);
        if (t0 > t1)
          continue;
      }
      const double xa = a.x + t0 * dx, xb = a.x + t1 * dx;
      const int x_first =
          detail::clamped_int(std::floor(std::min(xa, xb) - radius), 0, canvas.width());
      const int x_last =
          detail::clamped_int(std::ceil(std::max(xa, xb) + radius), -1, canvas.width() - 1);
      for (int x = x_first; x <= x_last; ++x) {
        const double px = x + 0.5;
        const double t =
            length2 > 0 ? std::clamp(((px - a.x) * dx + (py - a.y) * dy) / length2, 0.0, 1.0) : 0.0;
        const double qx = a.x + t * dx, qy = a.y + t * dy;
        if ((px - qx) * (px - qx) + (py - qy) * (py - qy) > radius * radius)
          continue;
        if (visible(qx, qy, a.depth + t * (b.depth - a.depth) - bias))
          canvas(x, y) = style.color;
      }
    }
  }

  /// Liang-Barsky clipping of segment ab to the canvas grown by `border`, so that far-away
  /// end points cannot make the pixel loops below long.
  bool clip_to_canvas(Screen_point& a, Screen_point& b, double border) const
  {
    const double dx = b.x - a.x, dy = b.y - a.y, dz = b.depth - a.depth;
    if (!std::isfinite(dx) || !std::isfinite(dy) || !std::isfinite(dz))
      return false;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {a.x + border, samples_.width() + border - a.x, a.y + border,
                         samples_.height() + border - a.y};
    double t0 = 0, t1 = 1;
    for (int i = 0; i < 4; ++i) {
      if (p[i] == 0) {
        if (q[i] < 0)
          return false;
        continue;
      }
      const double t = q[i] / p[i];
      if (p[i] < 0)
        t0 = std::max(t0, t);
      else
        t1 = std::min(t1, t);
    }
    if (!(t0 <= t1))
      return false;
    const Screen_point start = a;
    a = {start.x + t0 * dx, start.y + t0 * dy, start.depth + t0 * dz};
    b = {start.x + t1 * dx, start.y + t1 * dy, start.depth + t1 * dz};
    return true;
  }

  void draw_marker(Image& canvas, const Marker& marker) const
  {
    const Marker_style& style = marker.style;
    const Screen_point& c = marker.center;
    const double bias = style.depth_bias * sample_size_ * supersampling_;
    if (!visible(c.x, c.y, c.depth - bias))
      return;
    const double outer = std::max(style.radius, 0.0) * supersampling_;
    const double inner = std::max(style.radius - style.outline_width, 0.0) * supersampling_;
    const int x_first = detail::clamped_int(std::floor(c.x - outer), 0, canvas.width());
    const int x_last = detail::clamped_int(std::ceil(c.x + outer), -1, canvas.width() - 1);
    const int y_first = detail::clamped_int(std::floor(c.y - outer), 0, canvas.height());
    const int y_last = detail::clamped_int(std::ceil(c.y + outer), -1, canvas.height() - 1);
    for (int y = y_first; y <= y_last; ++y)
      for (int x = x_first; x <= x_last; ++x) {
        const double ex = x + 0.5 - c.x, ey = y + 0.5 - c.y, d2 = ex * ex + ey * ey;
        if (d2 <= inner * inner)
          canvas(x, y) = style.color;
        else if (d2 <= outer * outer)
          canvas(x, y) = style.outline;
      }
  }

  int width_, height_, supersampling_;
  Camera camera_;
  Vector3 right_, up_, forward_;
  double sample_size_; ///< world length of one sample
  Image samples_;      ///< supersampled colour buffer
  std::vector<float> depth_;
  std::vector<Line_style> line_styles_;
  std::vector<Segment> segments_;
  std::vector<Marker> markers_;
};

// ------------------------------------------------------------------------------------------------
// Text
// ------------------------------------------------------------------------------------------------

namespace detail {

/// 5 x 9 bitmap font for printable ASCII (32..126): 7 rows of capitals, then 2 rows for
/// descenders. One byte per row, bit 4 is the leftmost column.
inline constexpr std::uint8_t font_5x9[95][9] = {
    {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}, // ' '
    {0x04, 0x04, 0x04, 0x04, 0x04, 0x00, 0x04, 0x00, 0x00}, // '!'
    {0x0a, 0x0a, 0x0a, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}, // '"'
    {0x0a, 0x0a, 0x1f, 0x0a, 0x1f, 0x0a, 0x0a, 0x00, 0x00}, // '#'
    {0x04, 0x0f, 0x14, 0x0e, 0x05, 0x1e, 0x04, 0x00, 0x00}, // '$'
    {0x18, 0x19, 0x02, 0x04, 0x08, 0x13, 0x03, 0x00, 0x00}, // '%'
    {0x0c, 0x12, 0x14, 0x08, 0x15, 0x12, 0x0d, 0x00, 0x00}, // '&'
    {0x04, 0x04, 0x08, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}, // '\''
    {0x02, 0x04, 0x08, 0x08, 0x08, 0x04, 0x02, 0x00, 0x00}, // '('
    {0x08, 0x04, 0x02, 0x02, 0x02, 0x04, 0x08, 0x00, 0x00}, // ')'
    {0x00, 0x04, 0x15, 0x0e, 0x15, 0x04, 0x00, 0x00, 0x00}, // '*'
    {0x00, 0x04, 0x04, 0x1f, 0x04, 0x04, 0x00, 0x00, 0x00}, // '+'
    {0x00, 0x00, 0x00, 0x00, 0x00, 0x0c, 0x0c, 0x04, 0x08}, // ','
    {0x00, 0x00, 0x00, 0x1f, 0x00, 0x00, 0x00, 0x00, 0x00}, // '-'
    {0x00, 0x00, 0x00, 0x00, 0x00, 0x0c, 0x0c, 0x00, 0x00}, // '.'
    {0x00, 0x01, 0x02, 0x04, 0x08, 0x10, 0x00, 0x00, 0x00}, // '/'
    {0x0e, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0e, 0x00, 0x00}, // '0'
    {0x04, 0x0c, 0x04, 0x04, 0x04, 0x04, 0x0e, 0x00, 0x00}, // '1'
    {0x0e, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1f, 0x00, 0x00}, // '2'
    {0x1f, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0e, 0x00, 0x00}, // '3'
    {0x02, 0x06, 0x0a, 0x12, 0x1f, 0x02, 0x02, 0x00, 0x00}, // '4'
    {0x1f, 0x10, 0x1e, 0x01, 0x01, 0x11, 0x0e, 0x00, 0x00}, // '5'
    {0x06, 0x08, 0x10, 0x1e, 0x11, 0x11, 0x0e, 0x00, 0x00}, // '6'
    {0x1f, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08, 0x00, 0x00}, // '7'
    {0x0e, 0x11, 0x11, 0x0e, 0x11, 0x11, 0x0e, 0x00, 0x00}, // '8'
    {0x0e, 0x11, 0x11, 0x0f, 0x01, 0x02, 0x0c, 0x00, 0x00}, // '9'
    {0x00, 0x0c, 0x0c, 0x00, 0x0c, 0x0c, 0x00, 0x00, 0x00}, // ':'
    {0x00, 0x0c, 0x0c, 0x00, 0x0c, 0x0c, 0x04, 0x08, 0x00}, // ';'
    {0x02, 0x04, 0x08, 0x10, 0x08, 0x04, 0x02, 0x00, 0x00}, // '<'
    {0x00, 0x00, 0x1f, 0x00, 0x1f, 0x00, 0x00, 0x00, 0x00}, // '='
    {0x08, 0x04, 0x02, 0x01, 0x02, 0x04, 0x08, 0x00, 0x00}, // '>'
    {0x0e, 0x11, 0x01, 0x02, 0x04, 0x00, 0x04, 0x00, 0x00}, // '?'
    {0x0e, 0x11, 0x01, 0x0d, 0x15, 0x15, 0x0e, 0x00, 0x00}, // '@'
    {0x0e, 0x11, 0x11, 0x11, 0x1f, 0x11, 0x11, 0x00, 0x00}, // 'A'
    {0x1e, 0x11, 0x11, 0x1e, 0x11, 0x11, 0x1e, 0x00, 0x00}, // 'B'
    {0x0e, 0x11, 0x10, 0x10, 0x10, 0x11, 0x0e, 0x00, 0x00}, // 'C'
    {0x1c, 0x12, 0x11, 0x11, 0x11, 0x12, 0x1c, 0x00, 0x00}, // 'D'
    {0x1f, 0x10, 0x10, 0x1e, 0x10, 0x10, 0x1f, 0x00, 0x00}, // 'E'
    {0x1f, 0x10, 0x10, 0x1e, 0x10, 0x10, 0x10, 0x00, 0x00}, // 'F'
    {0x0e, 0x11, 0x10, 0x17, 0x11, 0x11, 0x0f, 0x00, 0x00}, // 'G'
    {0x11, 0x11, 0x11, 0x1f, 0x11, 0x11, 0x11, 0x00, 0x00}, // 'H'
    {0x0e, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0e, 0x00, 0x00}, // 'I'
    {0x07, 0x02, 0x02, 0x02, 0x02, 0x12, 0x0c, 0x00, 0x00}, // 'J'
    {0x11, 0x12, 0x14, 0x18, 0x14, 0x12, 0x11, 0x00, 0x00}, // 'K'
    {0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1f, 0x00, 0x00}, // 'L'
    {0x11, 0x1b, 0x15, 0x15, 0x11, 0x11, 0x11, 0x00, 0x00}, // 'M'
    {0x11, 0x11, 0x19, 0x15, 0x13, 0x11, 0x11, 0x00, 0x00}, // 'N'
    {0x0e, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0e, 0x00, 0x00}, // 'O'
    {0x1e, 0x11, 0x11, 0x1e, 0x10, 0x10, 0x10, 0x00, 0x00}, // 'P'
    {0x0e, 0x11, 0x11, 0x11, 0x15, 0x12, 0x0d, 0x00, 0x00}, // 'Q'
    {0x1e, 0x11, 0x11, 0x1e, 0x14, 0x12, 0x11, 0x00, 0x00}, // 'R'
    {0x0f, 0x10, 0x10, 0x0e, 0x01, 0x01, 0x1e, 0x00, 0x00}, // 'S'
    {0x1f, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04, 0x00, 0x00}, // 'T'
    {0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0e, 0x00, 0x00}, // 'U'
    {0x11, 0x11, 0x11, 0x11, 0x11, 0x0a, 0x04, 0x00, 0x00}, // 'V'
    {0x11, 0x11, 0x11, 0x15, 0x15, 0x15, 0x0a, 0x00, 0x00}, // 'W'
    {0x11, 0x11, 0x0a, 0x04, 0x0a, 0x11, 0x11, 0x00, 0x00}, // 'X'
    {0x11, 0x11, 0x11, 0x0a, 0x04, 0x04, 0x04, 0x00, 0x00}, // 'Y'
    {0x1f, 0x01, 0x02, 0x04, 0x08, 0x10, 0x1f, 0x00, 0x00}, // 'Z'
    {0x0e, 0x08, 0x08, 0x08, 0x08, 0x08, 0x0e, 0x00, 0x00}, // '['
    {0x00, 0x10, 0x08, 0x04, 0x02, 0x01, 0x00, 0x00, 0x00}, // '\\'
    {0x0e, 0x02, 0x02, 0x02, 0x02, 0x02, 0x0e, 0x00, 0x00}, // ']'
    {0x04, 0x0a, 0x11, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}, // '^'
    {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x1f, 0x00}, // '_'
    {0x08, 0x04, 0x02, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}, // '`'
    {0x00, 0x00, 0x0e, 0x01, 0x0f, 0x11, 0x0f, 0x00, 0x00}, // 'a'
    {0x10, 0x10, 0x16, 0x19, 0x11, 0x11, 0x1e, 0x00, 0x00}, // 'b'
    {0x00, 0x00, 0x0e, 0x10, 0x10, 0x11, 0x0e, 0x00, 0x00}, // 'c'
    {0x01, 0x01, 0x0d, 0x13, 0x11, 0x11, 0x0f, 0x00, 0x00}, // 'd'
    {0x00, 0x00, 0x0e, 0x11, 0x1f, 0x10, 0x0e, 0x00, 0x00}, // 'e'
    {0x06, 0x09, 0x08, 0x1c, 0x08, 0x08, 0x08, 0x00, 0x00}, // 'f'
    {0x00, 0x00, 0x0f, 0x11, 0x11, 0x11, 0x0f, 0x01, 0x0e}, // 'g'
    {0x10, 0x10, 0x16, 0x19, 0x11, 0x11, 0x11, 0x00, 0x00}, // 'h'
    {0x04, 0x00, 0x0c, 0x04, 0x04, 0x04, 0x0e, 0x00, 0x00}, // 'i'
    {0x02, 0x00, 0x06, 0x02, 0x02, 0x02, 0x02, 0x12, 0x0c}, // 'j'
    {0x10, 0x10, 0x12, 0x14, 0x18, 0x14, 0x12, 0x00, 0x00}, // 'k'
    {0x0c, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0e, 0x00, 0x00}, // 'l'
    {0x00, 0x00, 0x1a, 0x15, 0x15, 0x15, 0x15, 0x00, 0x00}, // 'm'
    {0x00, 0x00, 0x16, 0x19, 0x11, 0x11, 0x11, 0x00, 0x00}, // 'n'
    {0x00, 0x00, 0x0e, 0x11, 0x11, 0x11, 0x0e, 0x00, 0x00}, // 'o'
    {0x00, 0x00, 0x1e, 0x11, 0x11, 0x11, 0x1e, 0x10, 0x10}, // 'p'
    {0x00, 0x00, 0x0f, 0x11, 0x11, 0x11, 0x0f, 0x01, 0x01}, // 'q'
    {0x00, 0x00, 0x16, 0x19, 0x10, 0x10, 0x10, 0x00, 0x00}, // 'r'
    {0x00, 0x00, 0x0f, 0x10, 0x0e, 0x01, 0x1e, 0x00, 0x00}, // 's'
    {0x08, 0x08, 0x1c, 0x08, 0x08, 0x09, 0x06, 0x00, 0x00}, // 't'
    {0x00, 0x00, 0x11, 0x11, 0x11, 0x13, 0x0d, 0x00, 0x00}, // 'u'
    {0x00, 0x00, 0x11, 0x11, 0x11, 0x0a, 0x04, 0x00, 0x00}, // 'v'
    {0x00, 0x00, 0x11, 0x11, 0x15, 0x15, 0x0a, 0x00, 0x00}, // 'w'
    {0x00, 0x00, 0x11, 0x0a, 0x04, 0x0a, 0x11, 0x00, 0x00}, // 'x'
    {0x00, 0x00, 0x11, 0x11, 0x11, 0x11, 0x0f, 0x01, 0x0e}, // 'y'
    {0x00, 0x00, 0x1f, 0x02, 0x04, 0x08, 0x1f, 0x00, 0x00}, // 'z'
    {0x02, 0x04, 0x04, 0x08, 0x04, 0x04, 0x02, 0x00, 0x00}, // '{'
    {0x04, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04, 0x00, 0x00}, // '|'
    {0x08, 0x04, 0x04, 0x02, 0x04, 0x04, 0x08, 0x00, 0x00}, // '}'
    {0x00, 0x00, 0x08, 0x15, 0x02, 0x00, 0x00, 0x00, 0x00}, // '~'
};

inline constexpr int glyph_width = 5;
inline constexpr int glyph_height = 9;
inline constexpr int glyph_advance = 6;
inline constexpr int line_advance = 11;

inline std::vector<std::string> split_lines(const std::string& text)
{
  std::vector<std::string> lines(1);
  for (char c : text)
    if (c == '\n')
      lines.emplace_back();
    else
      lines.back() += c;
  return lines;
}

} // namespace detail

/// Width in pixels of `text` drawn at `scale` (the longest line for multi-line text).
inline int text_width(const std::string& text, int scale = 2)
{
  std::size_t longest = 0;
  for (const std::string& line : detail::split_lines(text))
    longest = std::max(longest, line.size());
  return longest == 0 ? 0 : static_cast<int>(longest * detail::glyph_advance - 1) * scale;
}

/// Height in pixels of `text` drawn at `scale`, descenders included.
inline int text_height(const std::string& text, int scale = 2)
{
  const int lines = static_cast<int>(detail::split_lines(text).size());
  return ((lines - 1) * detail::line_advance + detail::glyph_height) * scale;
}

/// Draws `text` with its top-left corner at (x, y); each font pixel is a scale x scale block.
/// '\n' starts a new line; characters outside printable ASCII are drawn as '?'.
inline void draw_text(Image& image, int x, int y, const std::string& text, RGB color, int scale = 2)
{
  scale = std::max(scale, 1);
  int line_y = y;
  for (const std::string& line : detail::split_lines(text)) {
    int glyph_x = x;
    for (char c : line) {
      const int code = static_cast<unsigned char>(c);
      const auto& glyph = detail::font_5x9[(code >= 32 && code < 127 ? code : '?') - 32];
      for (int row = 0; row < detail::glyph_height; ++row)
        for (int column = 0; column < detail::glyph_width; ++column)
          if (glyph[row] & (0x10 >> column))
            image.fill_rectangle(glyph_x + column * scale, line_y + row * scale, scale, scale,
                                 color);
      glyph_x += detail::glyph_advance * scale;
    }
    line_y += detail::line_advance * scale;
  }
}

/// Draws `text` with each line centred on `center_x`, the first line's top at `y`.
inline void draw_text_centered(Image& image, int center_x, int y, const std::string& text,
                               RGB color, int scale = 2)
{
  int line_y = y;
  for (const std::string& line : detail::split_lines(text)) {
    draw_text(image, center_x - text_width(line, scale) / 2, line_y, line, color, scale);
    line_y += detail::line_advance * std::max(scale, 1);
  }
}

// ------------------------------------------------------------------------------------------------
// Composition
// ------------------------------------------------------------------------------------------------

struct Layout
{
  int margin = 16; ///< free border around everything
  int gap = 16;    ///< between panels
  int columns = 0; ///< panels per row; 0 puts them all in one row
  int caption_scale = 3;
  int title_scale = 3;
  std::string title; ///< drawn centred above all panels when not empty
  RGB background = colors::background;
  RGB text_color = colors::text;
  RGB frame = colors::panel_frame;
  int frame_width = 1; ///< border drawn around each panel; 0 for none
};

/// Places `panels` side by side (or in a grid, see Layout::columns), each with its caption
/// centred above it; e.g. before/after comparisons. Captions and title may have several lines.
inline Image side_by_side(const std::vector<Image>& panels,
                          const std::vector<std::string>& captions = {}, const Layout& layout = {})
{
  const int count = static_cast<int>(panels.size());
  const int columns =
      layout.columns > 0 ? std::min(layout.columns, std::max(count, 1)) : std::max(count, 1);
  const int rows = (count + columns - 1) / columns;
  const int frame = std::max(layout.frame_width, 0);
  const int caption_gap = layout.caption_scale * 4;
  auto caption = [&](int i) {
    return i < static_cast<int>(captions.size()) ? captions[i] : std::string();
  };

  std::vector<int> column_width(columns, 0), caption_height(rows, 0), panel_height(rows, 0);
  for (int i = 0; i < count; ++i) {
    const int row = i / columns, column = i % columns;
    column_width[column] = std::max({column_width[column], panels[i].width() + 2 * frame,
                                     text_width(caption(i), layout.caption_scale)});
    if (!caption(i).empty())
      caption_height[row] = std::max(caption_height[row],
                                     text_height(caption(i), layout.caption_scale) + caption_gap);
    panel_height[row] = std::max(panel_height[row], panels[i].height() + 2 * frame);
  }

  const int title_height =
      layout.title.empty() ? 0 : text_height(layout.title, layout.title_scale) + 3 * layout.gap / 2;
  int width = 2 * layout.margin + std::max(columns - 1, 0) * layout.gap;
  for (int w : column_width)
    width += w;
  width = std::max(width, 2 * layout.margin + text_width(layout.title, layout.title_scale));
  int height = 2 * layout.margin + title_height + std::max(rows - 1, 0) * layout.gap;
  for (int r = 0; r < rows; ++r)
    height += caption_height[r] + panel_height[r];

  Image result(width, height, layout.background);
  if (!layout.title.empty())
    draw_text_centered(result, width / 2, layout.margin, layout.title, layout.text_color,
                       layout.title_scale);
  int y = layout.margin + title_height;
  for (int r = 0; r < rows; ++r) {
    int x = layout.margin;
    for (int c = 0; c < columns && r * columns + c < count; ++c) {
      const int i = r * columns + c;
      const int center = x + column_width[c] / 2;
      if (!caption(i).empty()) // just above the panel, even when another caption is taller
        draw_text_centered(result, center,
                           y + caption_height[r] - caption_gap -
                               text_height(caption(i), layout.caption_scale),
                           caption(i), layout.text_color, layout.caption_scale);
      const Image& panel = panels[i];
      const int panel_x = center - panel.width() / 2, panel_y = y + caption_height[r] + frame;
      if (frame > 0)
        result.fill_rectangle(panel_x - frame, panel_y - frame, panel.width() + 2 * frame,
                              panel.height() + 2 * frame, layout.frame);
      result.paste(panel, panel_x, panel_y);
      x += column_width[c] + layout.gap;
    }
    y += caption_height[r] + panel_height[r] + layout.gap;
  }
  return result;
}

// ------------------------------------------------------------------------------------------------
// PNG writing (zlib compresses and computes the CRC-32 of the chunks)
// ------------------------------------------------------------------------------------------------

/// zlib stream (RFC 1950) of `data`, at zlib's best compression.
inline std::vector<std::uint8_t> zlib_compress(const std::uint8_t* data, std::size_t size)
{
  uLongf length = compressBound(static_cast<uLong>(size));
  std::vector<std::uint8_t> out(length);
  if (compress2(out.data(), &length, data, static_cast<uLong>(size), Z_BEST_COMPRESSION) != Z_OK)
    throw std::runtime_error("highlight_picture: zlib could not compress the image");
  out.resize(length);
  return out;
}

inline std::vector<std::uint8_t> zlib_compress(const std::vector<std::uint8_t>& data)
{
  return zlib_compress(data.data(), data.size());
}

namespace detail {

inline std::uint8_t paeth(int a, int b, int c)
{
  const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  return static_cast<std::uint8_t>(pa <= pb && pa <= pc ? a : pb <= pc ? b : c);
}

/// PNG scanlines, each led by its filter type. Per row the filter with the smallest sum of
/// absolute residuals is chosen (the PNG specification's heuristic): smooth shading then
/// becomes runs of small numbers that LZ77 compresses well.
inline std::vector<std::uint8_t> filtered_scanlines(const Image& image)
{
  const std::size_t row_bytes = static_cast<std::size_t>(image.width()) * 3;
  std::vector<std::uint8_t> out;
  out.reserve((row_bytes + 1) * image.height());
  std::vector<std::uint8_t> previous(row_bytes, 0), current(row_bytes), candidate(row_bytes),
      best(row_bytes);
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const RGB& p = image(x, y);
      current[3 * x] = p.r;
      current[3 * x + 1] = p.g;
      current[3 * x + 2] = p.b;
    }
    std::uint64_t best_cost = std::numeric_limits<std::uint64_t>::max();
    std::uint8_t best_type = 0;
    for (std::uint8_t type = 0; type < 5; ++type) {
      std::uint64_t cost = 0;
      for (std::size_t i = 0; i < row_bytes; ++i) {
        const int a = i >= 3 ? current[i - 3] : 0, b = previous[i],
                  c = i >= 3 ? previous[i - 3] : 0;
        const int predictor = type == 0   ? 0
                              : type == 1 ? a
                              : type == 2 ? b
                              : type == 3 ? (a + b) / 2
                                          : paeth(a, b, c);
        candidate[i] = static_cast<std::uint8_t>(current[i] - predictor);
        cost += static_cast<std::uint64_t>(std::abs(static_cast<std::int8_t>(candidate[i])));
      }
      if (cost < best_cost) {
        best_cost = cost;
        best_type = type;
        best.swap(candidate);
      }
    }
    out.push_back(best_type);
    out.insert(out.end(), best.begin(), best.end());
    previous.swap(current);
  }
  return out;
}

inline void append_chunk(std::vector<std::uint8_t>& png, const char type[4],
                         const std::vector<std::uint8_t>& payload)
{
  const std::uint32_t length = static_cast<std::uint32_t>(payload.size());
  for (int shift = 24; shift >= 0; shift -= 8)
    png.push_back(static_cast<std::uint8_t>(length >> shift));
  const std::size_t type_position = png.size();
  png.insert(png.end(), type, type + 4);
  png.insert(png.end(), payload.begin(), payload.end());
  const std::uint32_t crc = static_cast<std::uint32_t>(
      ::crc32(0L, png.data() + type_position, static_cast<uInt>(4 + payload.size())));
  for (int shift = 24; shift >= 0; shift -= 8)
    png.push_back(static_cast<std::uint8_t>(crc >> shift));
}

} // namespace detail

/// The bytes of a PNG file (8-bit RGB, not interlaced) holding `image`.
inline std::vector<std::uint8_t> encode_png(const Image& image)
{
  std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<std::uint8_t> header;
  for (std::uint32_t value :
       {static_cast<std::uint32_t>(image.width()), static_cast<std::uint32_t>(image.height())})
    for (int shift = 24; shift >= 0; shift -= 8)
      header.push_back(static_cast<std::uint8_t>(value >> shift));
  header.insert(header.end(), {8, 2, 0, 0, 0}); // bit depth, RGB, deflate, adaptive, no interlace
  detail::append_chunk(png, "IHDR", header);
  detail::append_chunk(png, "IDAT", zlib_compress(detail::filtered_scanlines(image)));
  detail::append_chunk(png, "IEND", {});
  return png;
}

/// Writes `image` as a PNG file; returns false if the file could not be written.
inline bool write_png(const std::string& path, const Image& image)
{
  const std::vector<std::uint8_t> png = encode_png(image);
  std::ofstream file(path, std::ios::binary);
  file.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  return static_cast<bool>(file);
}

} // namespace highlight_picture

#endif // HIGHLIGHT_PICTURE_H

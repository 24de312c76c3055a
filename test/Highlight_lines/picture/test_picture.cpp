// Tests of the example programs' picture writer: the PNG structure (chunk CRCs, the zlib stream
// decoded with zlib's inflate, the pixels after undoing the row filters), and what the renderer
// draws.

#include "highlight_picture.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace hp = highlight_picture;

namespace {

constexpr double pi = hp::detail::pi;

std::vector<std::uint8_t> bytes_of(const std::string& text)
{
  return std::vector<std::uint8_t>(text.begin(), text.end());
}

/// The data of a zlib stream, decoded with zlib's inflate; throws if the stream is invalid or
/// does not end exactly at the end of `stream` (inflate checks the Adler-32 trailer).
std::vector<std::uint8_t> zlib_inflate(const std::vector<std::uint8_t>& stream)
{
  z_stream z{};
  if (inflateInit(&z) != Z_OK)
    throw std::runtime_error("inflateInit failed");
  std::vector<std::uint8_t> out;
  std::uint8_t buffer[4096];
  z.next_in = const_cast<Bytef*>(stream.data());
  z.avail_in = static_cast<uInt>(stream.size());
  int status = Z_OK;
  while (status == Z_OK) {
    z.next_out = buffer;
    z.avail_out = sizeof(buffer);
    status = inflate(&z, Z_NO_FLUSH);
    out.insert(out.end(), buffer, buffer + (sizeof(buffer) - z.avail_out));
  }
  const bool complete = status == Z_STREAM_END && z.avail_in == 0;
  inflateEnd(&z);
  if (!complete)
    throw std::runtime_error("invalid zlib stream (status " + std::to_string(status) + ")");
  return out;
}

std::vector<std::uint8_t> random_bytes(std::size_t n, unsigned seed, int alphabet = 256)
{
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> byte(0, alphabet - 1);
  std::vector<std::uint8_t> data(n);
  for (auto& b : data)
    b = static_cast<std::uint8_t>(byte(rng));
  return data;
}

std::uint32_t read_big_endian(const std::vector<std::uint8_t>& data, std::size_t at)
{
  return (std::uint32_t(data[at]) << 24) | (std::uint32_t(data[at + 1]) << 16) |
         (std::uint32_t(data[at + 2]) << 8) | data[at + 3];
}

// ------------------------------------------------------------------------------------------------
// Scenes
// ------------------------------------------------------------------------------------------------

struct Mesh
{
  std::vector<hp::Point3> points;
  std::vector<std::array<int, 3>> triangles;
};

/// Unit sphere: an icosahedron subdivided `levels` times, vertices pushed onto the sphere.
Mesh icosphere(int levels)
{
  const double t = (1 + std::sqrt(5.0)) / 2;
  Mesh m;
  m.points = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
              {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  auto to_sphere = [](hp::Point3 p) {
    const double l = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    return hp::Point3{p[0] / l, p[1] / l, p[2] / l};
  };
  for (auto& p : m.points)
    p = to_sphere(p);
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto found = midpoints.find(key);
      if (found != midpoints.end())
        return found->second;
      const hp::Point3 &p = m.points[a], &q = m.points[b];
      m.points.push_back(to_sphere({p[0] + q[0], p[1] + q[1], p[2] + q[2]}));
      const int index = static_cast<int>(m.points.size()) - 1;
      midpoints[key] = index;
      return index;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& tri : m.triangles) {
      const int ab = midpoint(tri[0], tri[1]), bc = midpoint(tri[1], tri[2]),
                ca = midpoint(tri[2], tri[0]);
      finer.push_back({tri[0], ab, ca});
      finer.push_back({tri[1], bc, ab});
      finer.push_back({tri[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    m.triangles = finer;
  }
  return m;
}

/// Looking down -z at the origin, `pixels_per_unit` output pixels per world unit.
hp::Camera front_camera(int height, double pixels_per_unit)
{
  hp::Camera camera;
  camera.center = {0, 0, 0};
  camera.view_direction = {0, 0, -1};
  camera.up = {0, 1, 0};
  camera.view_height = height / pixels_per_unit;
  return camera;
}

int luminance(const hp::RGB& c)
{
  return (299 * c.r + 587 * c.g + 114 * c.b) / 1000;
}

constexpr hp::RGB line_red{255, 0, 0};
bool is_red(const hp::RGB& c)
{
  return c.r > 200 && c.g < 60 && c.b < 60;
}

int count_red(const hp::Image& image, int x0, int y0, int x1, int y1)
{
  int count = 0;
  for (int y = std::max(y0, 0); y < std::min(y1, image.height()); ++y)
    for (int x = std::max(x0, 0); x < std::min(x1, image.width()); ++x)
      count += is_red(image(x, y)) ? 1 : 0;
  return count;
}

/// One big triangle in the plane z = 0 covering |x|, |y| < 1 and more.
Mesh wall()
{
  return {{{-3, -3, 0}, {3, -3, 0}, {0, 4, 0}}, {{0, 1, 2}}};
}

} // namespace

// ------------------------------------------------------------------------------------------------
// zlib stream
// ------------------------------------------------------------------------------------------------

TEST(ZlibStream, RoundTripsThroughInflate)
{
  for (const std::vector<std::uint8_t>& data :
       {std::vector<std::uint8_t>{}, bytes_of("a"), bytes_of("highlight lines"),
        random_bytes(100000, 3), random_bytes(100000, 4, 3), std::vector<std::uint8_t>(70000, 0)})
    EXPECT_EQ(zlib_inflate(hp::zlib_compress(data)), data) << data.size() << " bytes";
}

TEST(ZlibStream, HasHeaderAndAdler32AndCompresses)
{
  const std::vector<std::uint8_t> data = random_bytes(50000, 5, 4);
  const std::vector<std::uint8_t> z = hp::zlib_compress(data);
  ASSERT_GT(z.size(), 6u);
  EXPECT_EQ(z[0] & 0x0F, 8) << "deflate";
  EXPECT_EQ((z[0] * 256 + z[1]) % 31, 0) << "header check bits";
  EXPECT_EQ(read_big_endian(z, z.size() - 4),
            static_cast<std::uint32_t>(adler32(1L, data.data(), static_cast<uInt>(data.size()))));
  EXPECT_LT(z.size(), data.size() / 3) << "four symbols take two bits each";
}

// ------------------------------------------------------------------------------------------------
// PNG
// ------------------------------------------------------------------------------------------------

namespace {

/// Pixels with flat areas, gradients and noise, so that every row filter gets chosen somewhere.
hp::Image test_card(int width, int height)
{
  hp::Image image(width, height);
  std::mt19937 rng(99);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      hp::RGB& p = image(x, y);
      if (y < height / 4)
        p = {200, 200, 200};
      else if (y < height / 2)
        p = {static_cast<std::uint8_t>(x * 3), static_cast<std::uint8_t>(y * 2),
             static_cast<std::uint8_t>(x + y)};
      else if (y < 3 * height / 4)
        p = {static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng()),
             static_cast<std::uint8_t>(rng())};
      else
        p = {static_cast<std::uint8_t>(x * x), static_cast<std::uint8_t>(y * x),
             static_cast<std::uint8_t>(255 - x)};
    }
  return image;
}

struct Chunk
{
  std::string type;
  std::vector<std::uint8_t> payload;
};

std::vector<Chunk> read_chunks(const std::vector<std::uint8_t>& png)
{
  std::vector<Chunk> chunks;
  std::size_t at = 8;
  while (at + 12 <= png.size()) {
    const std::uint32_t length = read_big_endian(png, at);
    if (at + 12 + length > png.size())
      throw std::runtime_error("chunk runs past the end of the file");
    Chunk chunk;
    chunk.type.assign(png.begin() + at + 4, png.begin() + at + 8);
    chunk.payload.assign(png.begin() + at + 8, png.begin() + at + 8 + length);
    const std::uint32_t stored_crc = read_big_endian(png, at + 8 + length);
    EXPECT_EQ(stored_crc, static_cast<std::uint32_t>(
                              crc32(0L, png.data() + at + 4, static_cast<uInt>(4 + length))))
        << "CRC of chunk " << chunk.type;
    chunks.push_back(chunk);
    at += 12 + length;
  }
  EXPECT_EQ(at, png.size()) << "bytes after the last chunk";
  return chunks;
}

/// Undoes the PNG row filters (all five types) of 8-bit RGB scanlines.
std::vector<std::uint8_t> unfilter(const std::vector<std::uint8_t>& data, int width, int height,
                                   std::vector<int>& filter_uses)
{
  const std::size_t row = static_cast<std::size_t>(width) * 3;
  std::vector<std::uint8_t> pixels(row * height);
  filter_uses.assign(5, 0);
  for (int y = 0; y < height; ++y) {
    const int type = data[y * (row + 1)];
    if (type > 4)
      throw std::runtime_error("invalid filter type");
    ++filter_uses[type];
    for (std::size_t i = 0; i < row; ++i) {
      const int a = i >= 3 ? pixels[y * row + i - 3] : 0;
      const int b = y > 0 ? pixels[(y - 1) * row + i] : 0;
      const int c = (i >= 3 && y > 0) ? pixels[(y - 1) * row + i - 3] : 0;
      int predictor = 0;
      if (type == 1)
        predictor = a;
      else if (type == 2)
        predictor = b;
      else if (type == 3)
        predictor = (a + b) / 2;
      else if (type == 4) {
        const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
        predictor = (pa <= pb && pa <= pc) ? a : (pb <= pc ? b : c);
      }
      pixels[y * row + i] = static_cast<std::uint8_t>(data[y * (row + 1) + 1 + i] + predictor);
    }
  }
  return pixels;
}

} // namespace

TEST(Png, FileHasSignatureChunksAndTheImagePixels)
{
  const hp::Image image = test_card(97, 64);
  const std::vector<std::uint8_t> png = hp::encode_png(image);
  const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(std::memcmp(png.data(), signature, 8), 0);

  const std::vector<Chunk> chunks = read_chunks(png);
  ASSERT_EQ(chunks.size(), 3u);
  EXPECT_EQ(chunks[0].type, "IHDR");
  EXPECT_EQ(chunks[1].type, "IDAT");
  EXPECT_EQ(chunks[2].type, "IEND");
  EXPECT_TRUE(chunks[2].payload.empty());

  const std::vector<std::uint8_t>& header = chunks[0].payload;
  ASSERT_EQ(header.size(), 13u);
  EXPECT_EQ(read_big_endian(header, 0), 97u);
  EXPECT_EQ(read_big_endian(header, 4), 64u);
  EXPECT_EQ(header[8], 8) << "bit depth";
  EXPECT_EQ(header[9], 2) << "RGB";
  EXPECT_EQ(header[10], 0);
  EXPECT_EQ(header[11], 0);
  EXPECT_EQ(header[12], 0) << "not interlaced";

  const std::vector<std::uint8_t>& idat = chunks[1].payload;
  ASSERT_GT(idat.size(), 6u);
  EXPECT_EQ((idat[0] * 256 + idat[1]) % 31, 0);
  const std::vector<std::uint8_t> scanlines = zlib_inflate(idat); // checks the Adler-32
  ASSERT_EQ(scanlines.size(), 64u * (1 + 97 * 3));

  std::vector<int> filter_uses;
  const std::vector<std::uint8_t> pixels = unfilter(scanlines, 97, 64, filter_uses);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 97; ++x) {
      const hp::RGB& p = image(x, y);
      const std::size_t at = (static_cast<std::size_t>(y) * 97 + x) * 3;
      ASSERT_TRUE(pixels[at] == p.r && pixels[at + 1] == p.g && pixels[at + 2] == p.b)
          << "pixel " << x << ", " << y;
    }
  int filters_used = 0;
  for (int uses : filter_uses)
    filters_used += uses > 0 ? 1 : 0;
  EXPECT_GE(filters_used, 3) << "adaptive filtering should pick several filter types";
}

TEST(Png, WritesAFile)
{
  const hp::Image image = test_card(20, 10);
  const std::string path = ::testing::TempDir() + "highlight_picture_test.png";
  ASSERT_TRUE(hp::write_png(path, image));
  std::ifstream file(path, std::ios::binary);
  const std::vector<std::uint8_t> written((std::istreambuf_iterator<char>(file)),
                                          std::istreambuf_iterator<char>());
  EXPECT_EQ(written, hp::encode_png(image));
  std::remove(path.c_str());
  EXPECT_FALSE(hp::write_png("/nonexistent-directory/x.png", image));
}

// ------------------------------------------------------------------------------------------------
// Image, text and composition
// ------------------------------------------------------------------------------------------------

TEST(Image, DownsamplingAveragesBlocks)
{
  hp::Image image(6, 3, hp::colors::black);
  image.fill_rectangle(0, 0, 3, 3, hp::colors::white);
  image(3, 0) = {90, 180, 9};
  const hp::Image small = image.downsampled(3);
  ASSERT_EQ(small.width(), 2);
  ASSERT_EQ(small.height(), 1);
  EXPECT_EQ(small(0, 0), hp::colors::white);
  EXPECT_EQ(small(1, 0), (hp::RGB{10, 20, 1}));
}

TEST(Text, DrawsInsideItsBoxWithDescenders)
{
  const int scale = 2;
  const std::string text = "Ag 0.12";
  hp::Image image(200, 60, hp::colors::white);
  hp::draw_text(image, 10, 10, text, hp::colors::black, scale);
  const int w = hp::text_width(text, scale), h = hp::text_height(text, scale);
  EXPECT_EQ(w, (7 * 6 - 1) * scale);
  EXPECT_EQ(h, 9 * scale);
  int inside = 0, outside = 0, descender = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      if (image(x, y) != hp::colors::black)
        continue;
      const bool in_box = x >= 10 && x < 10 + w && y >= 10 && y < 10 + h;
      (in_box ? inside : outside)++;
      descender += (in_box && y >= 10 + 7 * scale) ? 1 : 0;
    }
  EXPECT_GT(inside, 40);
  EXPECT_EQ(outside, 0);
  EXPECT_GT(descender, 0) << "'g' reaches below the baseline";

  EXPECT_EQ(hp::text_width("ab\nabcd", 1), 23);
  EXPECT_EQ(hp::text_height("ab\nabcd", 1), 20);
  EXPECT_EQ(hp::text_width("", 3), 0);
}

TEST(Text, CentredLinesShareTheirCentre)
{
  hp::Image image(100, 40, hp::colors::white);
  hp::draw_text_centered(image, 50, 2, "ab\nabcd", hp::colors::black, 1);
  for (const auto& [top, bottom] : {std::pair<int, int>{2, 11}, std::pair<int, int>{13, 22}}) {
    int min_x = image.width(), max_x = -1;
    for (int y = top; y < bottom; ++y)
      for (int x = 0; x < image.width(); ++x)
        if (image(x, y) == hp::colors::black) {
          min_x = std::min(min_x, x);
          max_x = std::max(max_x, x);
        }
    ASSERT_GE(max_x, min_x) << "line starting at row " << top;
    EXPECT_NEAR((min_x + max_x + 1) / 2.0, 50, 1.5) << "line starting at row " << top;
  }
}

TEST(Text, EveryPrintableCharacterHasAGlyphExceptSpace)
{
  for (char c = 33; c < 127; ++c) {
    hp::Image image(10, 12, hp::colors::white);
    hp::draw_text(image, 1, 1, std::string(1, c), hp::colors::black, 1);
    int ink = 0;
    for (const hp::RGB& p : image.pixels())
      ink += p == hp::colors::black ? 1 : 0;
    EXPECT_GT(ink, 0) << "character '" << c << "'";
  }
}

TEST(Composition, PlacesPanelsSideBySideWithCaptions)
{
  const hp::Image red(50, 40, hp::RGB{255, 0, 0}), blue(60, 30, hp::RGB{0, 0, 255});
  hp::Layout layout;
  layout.title = "Comparison";
  const hp::Image both = hp::side_by_side({red, blue}, {"before", "after"}, layout);
  const int caption_width = hp::text_width("before", layout.caption_scale);
  EXPECT_EQ(both.width(), 2 * layout.margin + layout.gap + std::max(52, caption_width) +
                              std::max(62, hp::text_width("after", layout.caption_scale)));
  int red_pixels = 0, blue_pixels = 0, text_pixels = 0, red_min_x = both.width(),
      blue_min_x = both.width(), red_min_y = both.height();
  for (int y = 0; y < both.height(); ++y)
    for (int x = 0; x < both.width(); ++x) {
      const hp::RGB& p = both(x, y);
      if (p == hp::RGB{255, 0, 0}) {
        ++red_pixels;
        red_min_x = std::min(red_min_x, x);
        red_min_y = std::min(red_min_y, y);
      } else if (p == hp::RGB{0, 0, 255}) {
        ++blue_pixels;
        blue_min_x = std::min(blue_min_x, x);
      } else if (p == layout.text_color) {
        ++text_pixels;
      }
    }
  EXPECT_EQ(red_pixels, 50 * 40);
  EXPECT_EQ(blue_pixels, 60 * 30);
  EXPECT_LT(red_min_x, blue_min_x) << "first panel on the left";
  EXPECT_GT(red_min_y, hp::text_height("Comparison", 3) + hp::text_height("before", 3))
      << "title and caption above the panels";
  EXPECT_GT(text_pixels, 100);

  hp::Layout grid;
  grid.columns = 1;
  const hp::Image stacked = hp::side_by_side({red, blue}, {}, grid);
  EXPECT_EQ(stacked.width(), 2 * grid.margin + 62);
  EXPECT_EQ(stacked.height(), 2 * grid.margin + grid.gap + 42 + 32);
}

// ------------------------------------------------------------------------------------------------
// Camera and renderer
// ------------------------------------------------------------------------------------------------

TEST(Camera, FitShowsEveryPointInsideTheMargin)
{
  const Mesh sphere = icosphere(2);
  std::vector<hp::Point3> points;
  for (const auto& p : sphere.points)
    points.push_back({3 * p[0] + 10, p[1] - 4, 0.5 * p[2]}); // an off-centre ellipsoid
  const int width = 300, height = 200;
  for (const hp::Vector3& view :
       {hp::Vector3{0, 0, -1}, hp::Vector3{1, 1, -1}, hp::view_direction_from_angles(30, 20)}) {
    const hp::Camera camera = hp::fit_camera(points, view, {0, 0, 1}, width, height, 0.1);
    const hp::Renderer renderer(width, height, camera, {1, hp::colors::white});
    double min_x = 1e9, max_x = -1e9, min_y = 1e9, max_y = -1e9;
    for (const auto& p : points) {
      const auto s = renderer.project(p);
      min_x = std::min(min_x, s[0]);
      max_x = std::max(max_x, s[0]);
      min_y = std::min(min_y, s[1]);
      max_y = std::max(max_y, s[1]);
    }
    EXPECT_GE(min_x, 0.1 * height - 1e-6);
    EXPECT_LE(max_x, width - 0.1 * height + 1e-6);
    EXPECT_GE(min_y, 0.1 * height - 1e-6);
    EXPECT_LE(max_y, height - 0.1 * height + 1e-6);
    // The tighter direction touches its margins, and the picture is centred.
    EXPECT_NEAR(std::max(max_y - min_y, (max_x - min_x) * height / width), 0.8 * height, 1e-6);
    EXPECT_NEAR(min_x + max_x, width, 1e-6);
    EXPECT_NEAR(min_y + max_y, height, 1e-6);
  }
}

TEST(Renderer, SphereSilhouetteCoversTheExpectedArea)
{
  const Mesh sphere = icosphere(4);
  const int width = 240, height = 200;
  const double radius_px = 70;
  const double disc_fraction = pi * radius_px * radius_px / (width * height);
  for (int supersampling : {1, 3}) {
    hp::Renderer renderer(width, height, front_camera(height, radius_px),
                          {supersampling, hp::colors::white});
    renderer.draw_mesh(sphere.points, sphere.triangles);
    const hp::Image image = renderer.image();
    int covered = 0, holes = 0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const bool background = image(x, y) == hp::colors::white;
        covered += background ? 0 : 1;
        const double dx = x + 0.5 - width / 2.0, dy = y + 0.5 - height / 2.0;
        holes += (background && std::hypot(dx, dy) < radius_px - 2) ? 1 : 0;
      }
    EXPECT_EQ(holes, 0) << "background showing through the surface";
    // Anti-aliased edge pixels are partly covered yet count fully: allow half the perimeter.
    const double edge_allowance = supersampling > 1 ? pi * radius_px / (width * height) : 0.0;
    EXPECT_NEAR(covered / double(width * height), disc_fraction,
                0.02 * disc_fraction + edge_allowance)
        << "supersampling " << supersampling;
  }
}

TEST(Renderer, SphereIsBrightestWhereTheNormalFacesTheLight)
{
  const Mesh sphere = icosphere(4);
  const int size = 200;
  const double radius_px = 80;
  hp::Surface_style style;
  style.specular = 0;
  style.fill = 0;
  hp::Renderer renderer(size, size, front_camera(size, radius_px), {1, hp::colors::white});
  renderer.draw_mesh(sphere.points, sphere.triangles, style);
  const hp::Image image = renderer.image();

  const hp::Vector3 light = hp::detail::normalized(style.light_direction);
  auto pixel_at_normal = [&](const hp::Vector3& n) {
    return image(static_cast<int>(size / 2.0 + radius_px * n[0]),
                 static_cast<int>(size / 2.0 - radius_px * n[1]));
  };
  const hp::Vector3 away = hp::detail::normalized({-0.6 * light[0], -0.6 * light[1], 0.5});
  EXPECT_GT(luminance(pixel_at_normal(light)), luminance(pixel_at_normal({0, 0, 1})) + 5);
  EXPECT_GT(luminance(pixel_at_normal({0, 0, 1})), luminance(pixel_at_normal(away)) + 20);

  // The brightest pixels cluster around the point whose normal is the light direction.
  int brightest = 0;
  for (const hp::RGB& p : image.pixels())
    if (p != hp::colors::white)
      brightest = std::max(brightest, luminance(p));
  double sum_x = 0, sum_y = 0;
  int count = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      if (image(x, y) != hp::colors::white && luminance(image(x, y)) >= brightest - 1) {
        sum_x += x + 0.5;
        sum_y += y + 0.5;
        ++count;
      }
  ASSERT_GT(count, 0);
  EXPECT_NEAR(sum_x / count, size / 2.0 + radius_px * light[0], 4.0);
  EXPECT_NEAR(sum_y / count, size / 2.0 - radius_px * light[1], 4.0);
}

TEST(Renderer, FlatShadingAndFaceColoursApply)
{
  const Mesh sphere = icosphere(2);
  hp::Surface_style flat;
  flat.smooth = false;
  flat.specular = 0;
  std::vector<std::optional<hp::RGB>> tint(sphere.triangles.size());
  std::size_t tinted_face = 0;
  for (std::size_t f = 0; f < sphere.triangles.size(); ++f) {
    double z = 0;
    for (int v : sphere.triangles[f])
      z += sphere.points[v][2];
    if (z > 2.9) { // faces around the pole facing the viewer
      tint[f] = hp::RGB{0, 200, 0};
      tinted_face = f;
    }
  }
  hp::Renderer renderer(200, 200, front_camera(200, 80), {1, hp::colors::white});
  renderer.draw_mesh(sphere.points, sphere.triangles, flat, tint);
  const hp::Image image = renderer.image();
  // The centre of the tinted face is green.
  hp::Point3 centroid{0, 0, 0};
  for (int v : sphere.triangles[tinted_face])
    for (int i = 0; i < 3; ++i)
      centroid[i] += sphere.points[v][i] / 3;
  const auto s = renderer.project(centroid);
  const hp::RGB& p = image(static_cast<int>(s[0]), static_cast<int>(s[1]));
  EXPECT_GT(p.g, 2 * p.r + 20);
  EXPECT_GT(p.g, 2 * p.b + 20);
  // Flat shading: a face has a single colour, so many pixels share exactly the same value.
  std::map<std::tuple<int, int, int>, int> histogram;
  for (const hp::RGB& q : image.pixels())
    if (q != hp::colors::white)
      ++histogram[{q.r, q.g, q.b}];
  EXPECT_LT(histogram.size(), sphere.triangles.size());

  EXPECT_THROW(renderer.draw_mesh(sphere.points, sphere.triangles, flat,
                                  std::vector<std::optional<hp::RGB>>(3)),
               std::invalid_argument);
  const std::vector<std::array<int, 3>> bad = {{0, 1, static_cast<int>(sphere.points.size())}};
  EXPECT_THROW(renderer.draw_mesh(sphere.points, bad), std::out_of_range);
  const std::vector<std::array<int, 3>> negative = {{0, 1, -1}};
  EXPECT_THROW(renderer.draw_mesh(sphere.points, negative), std::out_of_range);
}

TEST(Renderer, PolylineInFrontIsVisibleAndBehindIsHidden)
{
  const Mesh w = wall();
  const int size = 200;
  hp::Line_style style;
  style.color = line_red;
  style.width = 3;
  auto render = [&](double z) {
    hp::Renderer renderer(size, size, front_camera(size, 50), {3, hp::colors::white});
    renderer.draw_mesh(w.points, w.triangles);
    // Horizontal line at y = 0.5 from x = -3.9 to 3.9: the wall covers it only for |x| < ~1.8.
    renderer.draw_polyline({{-3.9, 0.5, z}, {0, 0.5, z}, {3.9, 0.5, z}}, style);
    return renderer.image();
  };
  const int row = static_cast<int>(size / 2.0 - 0.5 * 50);
  // Over the wall: |x| < 1.5 world units, i.e. 75 pixels from the centre.
  const int wall_x0 = size / 2 - 75, wall_x1 = size / 2 + 75;

  const hp::Image front = render(0.3);
  EXPECT_GT(count_red(front, wall_x0, row - 3, wall_x1, row + 4), 2 * 150 - 1) << "two full rows";
  const hp::Image on_surface = render(0.0);
  EXPECT_GT(count_red(on_surface, wall_x0, row - 3, wall_x1, row + 4), 2 * 150 - 1)
      << "two full rows";
  const hp::Image behind = render(-0.3);
  EXPECT_EQ(count_red(behind, wall_x0, row - 3, wall_x1, row + 4), 0);
  EXPECT_GT(count_red(behind, 0, row - 3, 5, row + 4), 0) << "visible where nothing hides it";
}

TEST(Renderer, PolylineOnASteepSurfaceStaysVisible)
{
  // A plane seen almost edge-on (depth changes 8 world units per world unit across the screen).
  const std::vector<hp::Point3> points = {{-1, -1, -8}, {1, -1, 8}, {1, 1, 8}, {-1, 1, -8}};
  const std::vector<std::array<std::size_t, 3>> triangles = {{0, 1, 2}, {0, 2, 3}};
  hp::Renderer renderer(200, 200, front_camera(200, 80), {3, hp::colors::white});
  renderer.draw_mesh(points, triangles);
  hp::Line_style style;
  style.color = line_red;
  std::vector<hp::Point3> line;
  for (int i = 0; i <= 50; ++i) {
    const double x = -0.9 + 1.8 * i / 50;
    line.push_back({x, 0.3 + 0.2 * x, 8 * x});
  }
  renderer.draw_polyline(line, style);
  const hp::Image image = renderer.image();
  int columns_with_line = 0;
  const int x0 = static_cast<int>(100 - 0.85 * 80), x1 = static_cast<int>(100 + 0.85 * 80);
  for (int x = x0; x < x1; ++x)
    columns_with_line += count_red(image, x, 0, x + 1, 200) > 0 ? 1 : 0;
  EXPECT_EQ(columns_with_line, x1 - x0);
}

TEST(Renderer, BackOfTheSphereHidesItsLines)
{
  const Mesh sphere = icosphere(4);
  const hp::Vector3 view = hp::view_direction_from_angles(0, 30);
  const hp::Camera camera = hp::fit_camera(sphere.points, view, {0, 0, 1}, 300, 300);
  hp::Renderer renderer(300, 300, camera);
  renderer.draw_mesh(sphere.points, sphere.triangles);
  hp::Line_style style;
  style.color = line_red;
  style.width = 2;
  std::vector<hp::Point3> equator;
  for (int i = 0; i < 360; ++i)
    equator.push_back({std::cos(i * pi / 180), std::sin(i * pi / 180), 0});
  renderer.draw_polyline(equator, style, true);
  const hp::Image image = renderer.image();
  const hp::Vector3 toward_viewer = hp::detail::scale(hp::detail::normalized(view), -1);
  int front_checked = 0, back_checked = 0;
  for (const hp::Point3& p : equator) {
    const double facing = hp::detail::dot(p, toward_viewer);
    if (std::abs(facing) < 0.4)
      continue; // near the silhouette
    const auto s = renderer.project(p);
    const int x = static_cast<int>(s[0]), y = static_cast<int>(s[1]);
    if (facing > 0) {
      EXPECT_TRUE(is_red(image(x, y))) << "front point at " << x << ", " << y;
      ++front_checked;
    } else {
      EXPECT_EQ(count_red(image, x - 1, y - 1, x + 2, y + 2), 0)
          << "back point at " << x << ", " << y;
      ++back_checked;
    }
  }
  EXPECT_GT(front_checked, 100);
  EXPECT_GT(back_checked, 100);
}

TEST(Renderer, MarkersAreDepthTested)
{
  const Mesh w = wall();
  hp::Renderer renderer(200, 200, front_camera(200, 50), {3, hp::colors::white});
  renderer.draw_mesh(w.points, w.triangles);
  hp::Marker_style style;
  style.color = hp::RGB{0, 220, 0};
  style.radius = 5;
  renderer.draw_points({{-1, 0, 0.0}, {1, 0, -0.5}}, style);
  const hp::Image image = renderer.image();
  const auto on_wall = renderer.project({-1, 0, 0}), behind = renderer.project({1, 0, -0.5});
  EXPECT_EQ(image(static_cast<int>(on_wall[0]), static_cast<int>(on_wall[1])),
            (hp::RGB{0, 220, 0}));
  EXPECT_NE(image(static_cast<int>(behind[0]), static_cast<int>(behind[1])), (hp::RGB{0, 220, 0}));
}

TEST(Renderer, NonFiniteAndFarAwayGeometryIsSkipped)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double huge = 1e300;
  const std::vector<hp::Point3> points = {{0, 0, 0}, {nan, 0, 0}, {huge, -huge, 0}, {1, 1, 0}};
  const std::vector<std::array<int, 3>> triangles = {{0, 1, 3}, {0, 2, 3}};
  hp::Renderer renderer(50, 50, front_camera(50, 10), {2, hp::colors::white});
  renderer.draw_mesh(points, triangles);
  renderer.draw_polyline(points);
  renderer.draw_points(points);
  const hp::Image image = renderer.image();
  EXPECT_EQ(image.width(), 50);
  EXPECT_NE(image(27, 23), hp::colors::white) << "the huge triangle still covers the centre";
}

TEST(Renderer, NearClipCutsAwayWhatIsInFront)
{
  const Mesh w = wall();
  std::vector<hp::Point3> front_wall = w.points;
  for (auto& p : front_wall)
    p[2] = 1; // a second wall nearer to the viewer
  hp::Surface_style green;
  green.color = {0, 200, 0};
  hp::Camera camera = front_camera(100, 25);
  hp::Renderer unclipped(100, 100, camera, {1, hp::colors::white});
  unclipped.draw_mesh(w.points, w.triangles);
  unclipped.draw_mesh(front_wall, w.triangles, green);
  EXPECT_GT(unclipped.image()(50, 50).g, 100);

  camera.near_clip = -0.5; // depth is -z here: keeps z < 0.5
  hp::Renderer clipped(100, 100, camera, {1, hp::colors::white});
  clipped.draw_mesh(w.points, w.triangles);
  clipped.draw_mesh(front_wall, w.triangles, green);
  const hp::RGB p = clipped.image()(50, 50);
  EXPECT_LT(p.g, p.b) << "the grey-blue back wall shows";
}

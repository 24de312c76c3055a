// Mesh generators and helpers shared by the tests and the benchmarks: synthetic meshes, the
// developers' shared meshes and their unit length ē.
#ifndef HIGHLIGHT_LINES_TEST_MESHES_H
#define HIGHLIGHT_LINES_TEST_MESHES_H

#include "flipped_faces.h"

#include <CGAL/Highlight_lines/Light_setup.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <array>
#include <map>
#include <cmath>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Surface_mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef CGAL::Highlight_lines::Light_setup<K> Lights;

struct Soup
{
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3>> triangles;
};

template <typename Mesh>
Mesh to_mesh(const Soup& soup)
{
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.triangles, mesh);
  return mesh;
}

// A grid of (n+1) x (n+1) vertices over [x0, x0 + n*step] x [y0, y0 + n*step], lifted by
// height(x, y). Every cell is split along the diagonal of the same direction, so the grid is
// symmetric under the half-turn about its centre. jitter moves interior vertices in x and y.
inline Soup grid(int n, double step, double x0, double y0,
                 const std::function<double(double, double)>& height, double jitter = 0,
                 unsigned seed = 1)
{
  Soup soup;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double x = x0 + i * step, y = y0 + j * step;
      if (jitter > 0 && i > 0 && j > 0 && i < n && j < n) {
        x += u(rng) * step;
        y += u(rng) * step;
      }
      soup.points.emplace_back(x, y, height(x, y));
    }
  auto id = [n](int i, int j) { return std::size_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      soup.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      soup.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return soup;
}

// The car hood of the fairing and detection tests (and of benchmark_fairing): a gently curved
// height field over [-1, 1]^2, for grid().
inline double hood(double x, double y)
{
  return 0.25 * (1 - 0.35 * x * x) - 0.12 * y * y + 0.05 * x * y;
}

// Cylinder x^2 + z^2 = r^2 around the y axis, angles in [-half_angle, half_angle] from +z,
// y in [0, length]; `around` x `along` cells, optionally with jittered interior vertices.
inline Soup cylinder_patch(double r, double half_angle, double length, int around, int along,
                           double jitter = 0, unsigned seed = 7)
{
  Soup soup;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  for (int j = 0; j <= along; ++j)
    for (int i = 0; i <= around; ++i) {
      double a = -half_angle + 2 * half_angle * i / around, y = length * j / along;
      if (jitter > 0 && i > 0 && j > 0 && i < around && j < along) {
        a += u(rng) * 2 * half_angle / around;
        y += u(rng) * length / along;
      }
      soup.points.emplace_back(r * std::sin(a), y, r * std::cos(a));
    }
  auto id = [around](int i, int j) { return std::size_t(j * (around + 1) + i); };
  for (int j = 0; j < along; ++j)
    for (int i = 0; i < around; ++i) {
      soup.triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j)});
      soup.triangles.push_back({id(i + 1, j), id(i, j + 1), id(i + 1, j + 1)});
    }
  return soup;
}

// The unit box, each side an n x n grid whose inner vertices are jittered within the side's
// plane by up to jitter / n (an irregular CAD tessellation; below 0.25 no triangle folds);
// sides share their border vertices. `open`: without its side z = 1 (a mesh with a border).
inline Soup jittered_box(int n, double jitter, unsigned seed, bool open = false)
{
  Soup soup;
  std::map<std::array<double, 3>, std::size_t> index_of;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter / n, jitter / n);
  auto vertex = [&](const std::array<double, 3>& p) {
    const auto found = index_of.emplace(p, soup.points.size());
    if (found.second)
      soup.points.emplace_back(p[0], p[1], p[2]);
    return found.first->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {0.0, 1.0}) {
      if (open && axis == 2 && side == 1.0)
        continue;
      const int a = (axis + 1) % 3, b = (axis + 2) % 3;
      std::vector<std::size_t> ids;
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          std::array<double, 3> p{};
          p[std::size_t(axis)] = side;
          const bool inner = i > 0 && i < n && j > 0 && j < n;
          p[std::size_t(a)] = double(i) / n + (inner ? u(rng) : 0.0);
          p[std::size_t(b)] = double(j) / n + (inner ? u(rng) : 0.0);
          ids.push_back(vertex(p));
        }
      auto id = [&](int i, int j) { return ids[std::size_t(j * (n + 1) + i)]; };
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          std::array<std::array<std::size_t, 3>, 2> triangles = {
              {{id(i, j), id(i + 1, j), id(i + 1, j + 1)},
               {id(i, j), id(i + 1, j + 1), id(i, j + 1)}}};
          for (auto t : triangles) {
            // Outward: the normal along +axis on the side 1, -axis on the side 0.
            const Vector normal = CGAL::cross_product(soup.points[t[1]] - soup.points[t[0]],
                                                      soup.points[t[2]] - soup.points[t[0]]);
            const double along = axis == 0 ? normal.x() : axis == 1 ? normal.y() : normal.z();
            if ((along > 0) != (side > 0.5))
              std::swap(t[1], t[2]);
            soup.triangles.push_back(t);
          }
        }
    }
  return soup;
}

// Unit-radius-r sphere by subdividing an octahedron `levels` times, projected.
inline Soup sphere(double r, int levels)
{
  Soup soup;
  soup.points = {Point(1, 0, 0),  Point(-1, 0, 0), Point(0, 1, 0),
                 Point(0, -1, 0), Point(0, 0, 1),  Point(0, 0, -1)};
  soup.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                    {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> mid;
    auto midpoint = [&](std::size_t a, std::size_t b) {
      auto key = std::make_pair((std::min)(a, b), (std::max)(a, b));
      auto it = mid.find(key);
      if (it != mid.end())
        return it->second;
      const Point& p = soup.points[a];
      const Point& q = soup.points[b];
      soup.points.push_back(CGAL::midpoint(p, q));
      return mid[key] = soup.points.size() - 1;
    };
    std::vector<std::array<std::size_t, 3>> next;
    for (const auto& t : soup.triangles) {
      const std::size_t a = midpoint(t[0], t[1]), b = midpoint(t[1], t[2]),
                        c = midpoint(t[2], t[0]);
      next.push_back({t[0], a, c});
      next.push_back({a, t[1], b});
      next.push_back({c, b, t[2]});
      next.push_back({a, b, c});
    }
    soup.triangles = next;
  }
  for (Point& p : soup.points) {
    const double len = std::sqrt(CGAL::to_double((p - CGAL::ORIGIN).squared_length()));
    p = Point(r * p.x() / len, r * p.y() / len, r * p.z() / len);
  }
  return soup;
}

// Consecutive nodes of every line, as pairs of node indices.
template <typename Model>
std::vector<std::pair<std::size_t, std::size_t>> segments_of(const Model& model)
{
  std::vector<std::pair<std::size_t, std::size_t>> result;
  for (const auto& line : model.lines()) {
    for (std::size_t i = 0; i + 1 < line.nodes.size(); ++i)
      result.emplace_back(line.nodes[i], line.nodes[i + 1]);
    if (line.is_closed)
      result.emplace_back(line.nodes.back(), line.nodes.front());
  }
  return result;
}

// The normal of eq. 3 at vertex v, computed here independently of the library: the sum of the
// cross products of its faces (area-weighted, not normalised).
inline Vector area_weighted_normal(const Surface_mesh& mesh, Surface_mesh::Vertex_index v)
{
  Vector n(0, 0, 0);
  for (auto f : CGAL::faces_around_target(mesh.halfedge(v), mesh)) {
    if (f == Surface_mesh::null_face())
      continue;
    const auto h = mesh.halfedge(f);
    const Point a = mesh.point(mesh.source(h)), b = mesh.point(mesh.target(h)),
                c = mesh.point(mesh.target(mesh.next(h)));
    n = n + CGAL::cross_product(b - a, c - a);
  }
  return n;
}

// The path of the shared mesh `name` (a file name, e.g. "bunny.off"), in ../shared/data.
inline std::string shared_data(const std::string& name)
{
  return std::string(HIGHLIGHT_LINES_SHARED_DATA_DIR) + "/" + name;
}

// Reads the shared mesh `name` into `mesh`; false if it is missing, unreadable or empty.
template <typename Mesh>
bool read_shared_mesh(const std::string& name, Mesh& mesh)
{
  const std::string path = shared_data(name);
  return std::ifstream(path) && CGAL::IO::read_polygon_mesh(path, mesh) && !is_empty(mesh);
}

// The mean edge length ē of a Surface_mesh (0 without edges): the unit of the injected dents
// and of the distances the tests and benchmarks report.
template <typename Mesh>
double mean_edge_length(const Mesh& mesh)
{
  double sum = 0;
  for (auto e : edges(mesh))
    sum +=
        std::sqrt(CGAL::squared_distance(mesh.point(source(e, mesh)), mesh.point(target(e, mesh))));
  return num_edges(mesh) > 0 ? sum / double(num_edges(mesh)) : 0.0;
}

} // namespace test

#endif

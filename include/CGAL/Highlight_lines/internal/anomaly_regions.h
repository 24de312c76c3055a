// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_ANOMALY_REGIONS_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_ANOMALY_REGIONS_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// An abnormal bending sample of a highlight line, attached to the mesh vertex nearest to it.
struct Anomaly
{
  int vertex = 0;
  std::size_t line = 0;  // over all light setups of the sweep
  std::size_t setup = 0; // which light setup
  double score = 0;      // robust z-score of the bending on its line
  double bending = 0;    // radians
};

struct Anomaly_region
{
  std::vector<int> faces;
  std::vector<std::size_t> anomalies; // indices into the anomaly list
};

// Vertex adjacency of a triangle soup, in compressed rows.
class Vertex_adjacency
{
public:
  Vertex_adjacency(const std::vector<std::array<int, 3>>& faces, int number_of_vertices)
      : offsets_(std::size_t(number_of_vertices) + 1, 0)
  {
    for (const auto& f : faces)
      for (int v : f)
        offsets_[std::size_t(v) + 1] += 2;
    for (std::size_t i = 1; i < offsets_.size(); ++i)
      offsets_[i] += offsets_[i - 1];
    neighbours_.resize(offsets_.back());
    std::vector<std::size_t> fill(offsets_.begin(), offsets_.end() - 1);
    for (const auto& f : faces)
      for (int j = 0; j < 3; ++j) {
        const int v = f[std::size_t(j)];
        neighbours_[fill[std::size_t(v)]++] = f[std::size_t((j + 1) % 3)];
        neighbours_[fill[std::size_t(v)]++] = f[std::size_t((j + 2) % 3)];
      }
  }

  template <typename F>
  void for_each_neighbour(int v, F&& f) const
  {
    for (std::size_t i = offsets_[std::size_t(v)]; i < offsets_[std::size_t(v) + 1]; ++i)
      f(neighbours_[i]);
  }

  int number_of_vertices() const { return int(offsets_.size()) - 1; }

private:
  std::vector<std::size_t> offsets_;
  std::vector<int> neighbours_;
};

// Marks in `inside` every vertex within `rings` edges of a marked one; paths do not pass
// through `barrier` vertices (optional flags: they are reached, not crossed).
inline void grow_by_rings(const Vertex_adjacency& adjacency, int rings, std::vector<char>& inside,
                          const std::vector<char>& barrier = {})
{
  std::vector<int> front;
  for (int v = 0; v < adjacency.number_of_vertices(); ++v)
    if (inside[std::size_t(v)])
      front.push_back(v);
  std::vector<int> next;
  for (int r = 0; r < rings && !front.empty(); ++r) {
    next.clear();
    for (int v : front)
      if (barrier.empty() || !barrier[std::size_t(v)])
        adjacency.for_each_neighbour(v, [&](int w) {
          if (!inside[std::size_t(w)]) {
            inside[std::size_t(w)] = 1;
            next.push_back(w);
          }
        });
    front.swap(next);
  }
}

// Labels the edge-connected components of the marked vertices (unmarked: -1); returns their
// number. `barrier` vertices (optional flags) are labelled but connect nothing.
inline int label_components(const Vertex_adjacency& adjacency, const std::vector<char>& inside,
                            std::vector<int>& label, const std::vector<char>& barrier = {})
{
  label.assign(inside.size(), -1);
  int components = 0;
  std::vector<int> stack;
  for (int seed = 0; seed < adjacency.number_of_vertices(); ++seed) {
    if (!inside[std::size_t(seed)] || label[std::size_t(seed)] >= 0)
      continue;
    label[std::size_t(seed)] = components;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      if (!barrier.empty() && barrier[std::size_t(v)])
        continue;
      adjacency.for_each_neighbour(v, [&](int w) {
        if (inside[std::size_t(w)] && label[std::size_t(w)] < 0) {
          label[std::size_t(w)] = components;
          stack.push_back(w);
        }
      });
    }
    ++components;
  }
  return components;
}

// Groups anomalies into disjoint face regions:
// 1. anomalies closer than `join_rings` edges belong to one cluster;
// 2. a cluster seen in fewer light setups than the largest `minimum_setups[v]` of its
//    anomalies' vertices is dropped: a defect bends the lines of every direction, while
//    triangulation noise rarely lines up across setups;
// 3. the remaining clusters grow by `margin_rings` edges, clusters that meet merge, and each
//    region is the set of faces with a vertex in the grown cluster.
// `barrier` (optional, one flag per vertex: the vertices of sharp edges): clusters and margins
// reach these vertices but never grow through them, so no region crosses a feature line; a
// face goes to the region of one of its vertices off the barrier if it has one.
inline std::vector<Anomaly_region> group_anomalies(const std::vector<std::array<int, 3>>& faces,
                                                   int number_of_vertices,
                                                   const std::vector<Anomaly>& anomalies,
                                                   int join_rings, int margin_rings,
                                                   const std::vector<std::size_t>& minimum_setups,
                                                   const std::vector<char>& barrier = {})
{
  const Vertex_adjacency adjacency(faces, number_of_vertices);
  std::vector<char> inside(std::size_t(number_of_vertices), 0);
  for (const Anomaly& a : anomalies)
    inside[std::size_t(a.vertex)] = 1;
  grow_by_rings(adjacency, join_rings, inside, barrier);
  std::vector<int> label;
  const int clusters = label_components(adjacency, inside, label, barrier);

  std::vector<std::set<std::size_t>> setups(static_cast<std::size_t>(clusters));
  std::vector<std::size_t> required(static_cast<std::size_t>(clusters), 1);
  for (const Anomaly& a : anomalies) {
    const std::size_t c = std::size_t(label[std::size_t(a.vertex)]);
    setups[c].insert(a.setup);
    required[c] = (std::max)(required[c], minimum_setups[std::size_t(a.vertex)]);
  }
  for (std::size_t v = 0; v < inside.size(); ++v)
    if (inside[v] && setups[std::size_t(label[v])].size() < required[std::size_t(label[v])])
      inside[v] = 0;
  grow_by_rings(adjacency, margin_rings, inside, barrier);
  const int components = label_components(adjacency, inside, label, barrier);

  std::vector<Anomaly_region> regions(static_cast<std::size_t>(components));
  auto on_barrier = [&](int v) { return !barrier.empty() && barrier[std::size_t(v)]; };
  for (std::size_t f = 0; f < faces.size(); ++f) {
    int chosen = -1;
    for (int pass = 0; pass < 2 && chosen < 0; ++pass)
      for (int v : faces[f])
        if (chosen < 0 && label[std::size_t(v)] >= 0 && (pass == 1 || !on_barrier(v)))
          chosen = label[std::size_t(v)];
    if (chosen >= 0)
      regions[std::size_t(chosen)].faces.push_back(int(f));
  }
  for (std::size_t i = 0; i < anomalies.size(); ++i)
    if (label[std::size_t(anomalies[i].vertex)] >= 0)
      regions[std::size_t(label[std::size_t(anomalies[i].vertex)])].anomalies.push_back(i);
  return regions;
}

inline std::vector<Anomaly_region> group_anomalies(const std::vector<std::array<int, 3>>& faces,
                                                   int number_of_vertices,
                                                   const std::vector<Anomaly>& anomalies,
                                                   int join_rings, int margin_rings,
                                                   std::size_t minimum_setups)
{
  return group_anomalies(faces, number_of_vertices, anomalies, join_rings, margin_rings,
                         std::vector<std::size_t>(std::size_t(number_of_vertices), minimum_setups));
}

// The square roots of the two largest eigenvalues of the symmetric 3 x 3 matrix `c` (a
// covariance): the standard deviations along its two main axes (Jacobi rotations).
inline std::array<double, 2> largest_spreads(const double (&c)[3][3])
{
  double a[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      a[i][j] = c[i][j];
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    if (!(off > 1e-30 * (a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2])))
      break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0)
          continue;
        const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
        const double t =
            (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double cs = 1 / std::sqrt(t * t + 1), sn = t * cs;
        for (int k = 0; k < 3; ++k) { // columns
          const double kp = a[k][p], kq = a[k][q];
          a[k][p] = cs * kp - sn * kq;
          a[k][q] = sn * kp + cs * kq;
        }
        for (int k = 0; k < 3; ++k) { // rows
          const double pk = a[p][k], qk = a[q][k];
          a[p][k] = cs * pk - sn * qk;
          a[q][k] = sn * pk + cs * qk;
        }
      }
  }
  std::array<double, 3> e{a[0][0], a[1][1], a[2][2]};
  std::sort(e.begin(), e.end(), [](double x, double y) { return x > y; });
  return {std::sqrt((std::max)(e[0], 0.0)), std::sqrt((std::max)(e[1], 0.0))};
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_ANOMALY_REGIONS_H

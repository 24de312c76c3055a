// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_ANOMALY_REGIONS_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_ANOMALY_REGIONS_H

#include <array>
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

// Marks in `inside` every vertex within `rings` edges of a marked one.
inline void grow_by_rings(const Vertex_adjacency& adjacency, int rings, std::vector<char>& inside)
{
  std::vector<int> front;
  for (int v = 0; v < adjacency.number_of_vertices(); ++v)
    if (inside[std::size_t(v)])
      front.push_back(v);
  std::vector<int> next;
  for (int r = 0; r < rings && !front.empty(); ++r) {
    next.clear();
    for (int v : front)
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
// number.
inline int label_components(const Vertex_adjacency& adjacency, const std::vector<char>& inside,
                            std::vector<int>& label)
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
// 2. a cluster seen in fewer than `minimum_setups` light setups is dropped: a defect bends
//    the lines of every direction, while triangulation noise rarely lines up across setups;
// 3. the remaining clusters grow by `margin_rings` edges, clusters that meet merge, and each
//    region is the set of faces with a vertex in the grown cluster.
inline std::vector<Anomaly_region> group_anomalies(const std::vector<std::array<int, 3>>& faces,
                                                   int number_of_vertices,
                                                   const std::vector<Anomaly>& anomalies,
                                                   int join_rings, int margin_rings,
                                                   std::size_t minimum_setups)
{
  const Vertex_adjacency adjacency(faces, number_of_vertices);
  std::vector<char> inside(std::size_t(number_of_vertices), 0);
  for (const Anomaly& a : anomalies)
    inside[std::size_t(a.vertex)] = 1;
  grow_by_rings(adjacency, join_rings, inside);
  std::vector<int> label;
  const int clusters = label_components(adjacency, inside, label);

  std::vector<std::set<std::size_t>> setups(static_cast<std::size_t>(clusters));
  for (const Anomaly& a : anomalies)
    setups[std::size_t(label[std::size_t(a.vertex)])].insert(a.setup);
  for (std::size_t v = 0; v < inside.size(); ++v)
    if (inside[v] && setups[std::size_t(label[v])].size() < minimum_setups)
      inside[v] = 0;
  grow_by_rings(adjacency, margin_rings, inside);
  const int components = label_components(adjacency, inside, label);

  std::vector<Anomaly_region> regions(static_cast<std::size_t>(components));
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int v : faces[f])
      if (label[std::size_t(v)] >= 0) {
        regions[std::size_t(label[std::size_t(v)])].faces.push_back(int(f));
        break;
      }
  for (std::size_t i = 0; i < anomalies.size(); ++i)
    if (label[std::size_t(anomalies[i].vertex)] >= 0)
      regions[std::size_t(label[std::size_t(anomalies[i].vertex)])].anomalies.push_back(i);
  return regions;
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_ANOMALY_REGIONS_H

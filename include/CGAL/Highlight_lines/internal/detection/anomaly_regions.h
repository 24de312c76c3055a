// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_ANOMALY_REGIONS_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_ANOMALY_REGIONS_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <queue>
#include <unordered_map>
#include <set>
#include <utility>
#include <vector>

#include <CGAL/Highlight_lines/internal/vector3.h>

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
  double noise = -1;     // the robust deviation of the residuals of its line, if known
  double value = 0;      // with the local residual: its level residual less its setup's median
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

// Adds each face to the region of one of its vertices (`owner`, -1 for none), of a vertex off
// the barrier if it has one: a region reaches a sharp edge's vertices, never the other side.
template <typename Region>
void add_faces_to_regions(const std::vector<std::array<int, 3>>& faces,
                          const std::vector<int>& owner, const std::vector<char>& barrier,
                          std::vector<Region>& regions)
{
  auto on_barrier = [&](int v) { return !barrier.empty() && barrier[std::size_t(v)]; };
  for (std::size_t f = 0; f < faces.size(); ++f) {
    int chosen = -1;
    for (int pass = 0; pass < 2 && chosen < 0; ++pass)
      for (int v : faces[f])
        if (chosen < 0 && owner[std::size_t(v)] >= 0 && (pass == 1 || !on_barrier(v)))
          chosen = owner[std::size_t(v)];
    if (chosen >= 0)
      regions[std::size_t(chosen)].faces.push_back(int(f));
  }
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
  add_faces_to_regions(faces, label, barrier, regions);
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

// The number of light setups a region must show in at each vertex: a share `minimum_evidence`
// of the `seeing` setups that can see it there, at least one.
inline std::vector<std::size_t> required_setups(const std::vector<std::size_t>& seeing,
                                                double minimum_evidence)
{
  std::vector<std::size_t> required(seeing.size());
  for (std::size_t v = 0; v < seeing.size(); ++v)
    required[v] = (std::max)(std::size_t(1),
                             std::size_t(std::ceil(minimum_evidence * double(seeing[v]) - 1e-9)));
  return required;
}

// A region around a peak of the anomalies (group_anomalies_around_peaks()).
struct Peak_region
{
  std::vector<int> faces;
  std::vector<std::size_t> anomalies;     // in the disc around the centre: indices into the list
  std::vector<std::size_t> neighbourhood; // all anomalies within `neighbourhood_radius`
  int centre = -1;                        // vertex
  std::size_t setups = 0;                 // distinct setups among `anomalies`
  double strength = 0; // the sum over those setups of their strongest anomaly's score
};

// Groups anomalies into disjoint regions around their peaks, strongest first (non-maximum
// suppression), so that no region grows along a feature or chains over the mesh:
// 1. the evidence of a disc of radius `radius` around an anomaly is the number of distinct
//    light setups among the unclaimed anomalies in it (ties: the sum over those setups of
//    their strongest score);
// 2. repeatedly, the disc of most evidence is re-centred on the mean of its anomalies (at the
//    vertex of one of them nearest to it); if its anomalies, without the side lobes of
//    earlier regions (anomalies on the same line as one of an earlier region, within
//    `separation` of it and weaker), show in at least
//    `minimum_setups[centre]` setups it becomes a region and claims them, else it is dropped;
// 3. a region's faces are those with a vertex within `radius + margin` (Euclidean) of the
//    centre, reached from it along edges that pass no `barrier` vertex (they are reached, not
//    crossed) nor a vertex of an earlier region.
// `neighbourhood` lists every anomaly (claimed or not) within `neighbourhood_radius` of the
// centre: what the surroundings show, to tell a local defect from a feature.
inline std::vector<Peak_region> group_anomalies_around_peaks(
    const std::vector<std::array<int, 3>>& faces, const std::vector<vector3::Vec3>& points,
    const std::vector<Anomaly>& anomalies, double radius, double margin,
    double neighbourhood_radius, double separation, const std::vector<std::size_t>& minimum_setups,
    const std::vector<char>& barrier = {})
{
  using namespace vector3;
  const int nv = int(points.size());
  std::vector<Peak_region> regions;
  if (anomalies.empty() || !(radius > 0))
    return regions;
  // A uniform grid of cells of side `radius` over the anomalies.
  const double cell = radius;
  struct Key_hash
  {
    std::size_t operator()(const std::array<long long, 3>& k) const
    {
      return std::size_t(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
    }
  };
  auto key_of = [cell](const Vec3& p) {
    return std::array<long long, 3>{(long long)std::floor(p[0] / cell),
                                    (long long)std::floor(p[1] / cell),
                                    (long long)std::floor(p[2] / cell)};
  };
  std::unordered_map<std::array<long long, 3>, std::vector<std::size_t>, Key_hash> grid;
  for (std::size_t i = 0; i < anomalies.size(); ++i)
    grid[key_of(points[std::size_t(anomalies[i].vertex)])].push_back(i);
  auto within = [&](const Vec3& c, double r, auto&& f) {
    const long long reach = (long long)std::ceil(r / cell);
    const auto k = key_of(c);
    for (long long x = -reach; x <= reach; ++x)
      for (long long y = -reach; y <= reach; ++y)
        for (long long z = -reach; z <= reach; ++z) {
          const auto it = grid.find({k[0] + x, k[1] + y, k[2] + z});
          if (it == grid.end())
            continue;
          for (std::size_t i : it->second) {
            const Vec3 d = points[std::size_t(anomalies[i].vertex)] - c;
            if (dot(d, d) <= r * r)
              f(i);
          }
        }
  };
  std::vector<char> claimed(anomalies.size(), 0);
  struct Evidence
  {
    std::size_t setups = 0;
    double strength = 0;
    bool operator<(const Evidence& o) const
    {
      return setups != o.setups ? setups < o.setups : strength < o.strength;
    }
  };
  std::vector<std::pair<std::size_t, double>> best_of_setup; // (setup, score), reused
  // The setups of best_of_setup and the sum of the best score of each (sorts it).
  auto tally_setups = [&best_of_setup]() {
    std::sort(best_of_setup.begin(), best_of_setup.end());
    Evidence e;
    for (std::size_t j = 0; j < best_of_setup.size(); ++j)
      if (j + 1 == best_of_setup.size() || best_of_setup[j + 1].first != best_of_setup[j].first) {
        ++e.setups;
        e.strength += best_of_setup[j].second;
      }
    return e;
  };
  auto evidence = [&](const Vec3& c, std::vector<std::size_t>* members) {
    best_of_setup.clear();
    if (members)
      members->clear();
    within(c, radius, [&](std::size_t i) {
      if (claimed[i])
        return;
      if (members)
        members->push_back(i);
      best_of_setup.emplace_back(anomalies[i].setup, anomalies[i].score);
    });
    return tally_setups();
  };
  // Lazy greedy: evidence only falls as anomalies are claimed.
  typedef std::pair<Evidence, std::size_t> Entry;
  auto lower = [](const Entry& a, const Entry& b) {
    return a.first < b.first || (!(b.first < a.first) && a.second > b.second);
  };
  std::priority_queue<Entry, std::vector<Entry>, decltype(lower)> queue(lower);
  for (std::size_t i = 0; i < anomalies.size(); ++i)
    queue.push({evidence(points[std::size_t(anomalies[i].vertex)], nullptr), i});
  const Vertex_adjacency adjacency(faces, nv);
  std::vector<int> owner(std::size_t(nv), -1);
  std::vector<std::size_t> members, recentred, unexplained;
  std::unordered_multimap<std::size_t, std::size_t> lobe_source; // line -> anomaly
  std::vector<int> front;
  while (!queue.empty()) {
    const Entry top = queue.top();
    queue.pop();
    if (claimed[top.second])
      continue;
    const Vec3 c = points[std::size_t(anomalies[top.second].vertex)];
    const Evidence now = evidence(c, &members);
    if (now.setups == 0)
      continue;
    if (now < top.first) {
      queue.push({now, top.second});
      continue;
    }
    // Re-centre on the mean of the disc's anomalies.
    Vec3 mean{0, 0, 0};
    for (std::size_t i : members)
      mean = mean + (1.0 / double(members.size())) * points[std::size_t(anomalies[i].vertex)];
    int centre = anomalies[top.second].vertex;
    double nearest = 1e300;
    for (std::size_t i : members) {
      const Vec3 d = points[std::size_t(anomalies[i].vertex)] - mean;
      if (dot(d, d) < nearest && owner[std::size_t(anomalies[i].vertex)] < 0) {
        nearest = dot(d, d);
        centre = anomalies[i].vertex;
      }
    }
    if (owner[std::size_t(centre)] >= 0)
      continue; // inside an earlier region: its anomalies are another region's surroundings
    const Vec3 cc = points[std::size_t(centre)];
    evidence(cc, &recentred); // the anomalies of the re-centred disc
    // Side lobes: the fit around a defect pulls the samples 3w/2 to 4w along the same lines
    // the other way, which leaves weaker peaks there. An anomaly is such a lobe if an earlier
    // region has a stronger anomaly on the same line within `separation` of it; the candidate
    // must show in enough setups without its lobes. (A defect next to a stronger feature keeps
    // the anomalies of its lines that do not cross the feature: a region more than twice as
    // strong nearby no longer suppresses it, as it did before.)
    lobe_source.clear();
    for (const Peak_region& r : regions) {
      const Vec3 d = points[std::size_t(r.centre)] - cc;
      if (dot(d, d) < std::pow(separation + 2 * radius, 2))
        for (std::size_t j : r.anomalies)
          lobe_source.emplace(anomalies[j].line, j);
    }
    unexplained.clear();
    for (std::size_t i : recentred) {
      bool lobe = false;
      const auto range = lobe_source.equal_range(anomalies[i].line);
      for (auto it = range.first; it != range.second && !lobe; ++it) {
        const Anomaly& source = anomalies[it->second];
        const Vec3 d =
            points[std::size_t(source.vertex)] - points[std::size_t(anomalies[i].vertex)];
        lobe = dot(d, d) <= separation * separation && source.score > anomalies[i].score;
      }
      if (!lobe)
        unexplained.push_back(i);
    }
    best_of_setup.clear();
    for (std::size_t i : unexplained)
      best_of_setup.emplace_back(anomalies[i].setup, anomalies[i].score);
    const Evidence own = tally_setups();
    if (own.setups < (std::max)(std::size_t(1), minimum_setups[std::size_t(centre)]))
      continue; // not enough evidence: this candidate is dropped, its anomalies stay
    Peak_region region;
    region.centre = centre;
    region.anomalies = recentred;
    region.setups = own.setups;
    region.strength = own.strength;
    for (std::size_t i : recentred)
      claimed[i] = 1;
    within(cc, neighbourhood_radius, [&](std::size_t i) { region.neighbourhood.push_back(i); });
    // The faces: a ball around the centre reaching the disc's anomalies, plus the margin.
    double reach = radius;
    for (std::size_t i : recentred)
      reach = (std::max)(reach, norm(points[std::size_t(anomalies[i].vertex)] - cc));
    reach += margin;
    const int id = int(regions.size());
    std::vector<int> inside;
    front.assign(1, centre);
    owner[std::size_t(centre)] = id;
    inside.push_back(centre);
    while (!front.empty()) {
      const int v = front.back();
      front.pop_back();
      if (!barrier.empty() && barrier[std::size_t(v)] && v != centre)
        continue;
      adjacency.for_each_neighbour(v, [&](int w) {
        if (owner[std::size_t(w)] >= 0)
          return;
        const Vec3 d = points[std::size_t(w)] - cc;
        if (dot(d, d) > reach * reach)
          return;
        owner[std::size_t(w)] = id;
        inside.push_back(w);
        front.push_back(w);
      });
    }
    regions.push_back(std::move(region));
  }
  add_faces_to_regions(faces, owner, barrier, regions);
  return regions;
}

// The square roots of the two largest eigenvalues of the symmetric 3 x 3 matrix `c` (a
// covariance): the standard deviations along its two main axes (Jacobi rotations).
inline std::array<double, 2> largest_spreads(const double (&c)[3][3])
{
  std::array<double, 3> e;
  double vectors[3][3];
  vector3::symmetric_eigen(c, e, vectors);
  std::sort(e.begin(), e.end(), [](double x, double y) { return x > y; });
  return {std::sqrt((std::max)(e[0], 0.0)), std::sqrt((std::max)(e[1], 0.0))};
}

// The spreads along the two main axes (largest_spreads()) of the points of `vertices` (indices
// into `points`, each once): the shape of a set of anomalies.
template <typename VertexRange>
std::array<double, 2> spreads_of_vertices(const std::vector<vector3::Vec3>& points,
                                          const VertexRange& vertices)
{
  using namespace vector3;
  const double size = double(vertices.size());
  Vec3 mean{0, 0, 0};
  for (int v : vertices)
    mean = mean + (1.0 / size) * points[std::size_t(v)];
  double c[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  for (int v : vertices) {
    const Vec3 d = points[std::size_t(v)] - mean;
    for (int r = 0; r < 3; ++r)
      for (int q = 0; q < 3; ++q)
        c[r][q] += d[std::size_t(r)] * d[std::size_t(q)] / size;
  }
  return largest_spreads(c);
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_DETECTION_ANOMALY_REGIONS_H

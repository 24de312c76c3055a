// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_FACE_REGION_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_FACE_REGION_H

#include <CGAL/Highlight_lines/Invalid_input.h>
#include <CGAL/Highlight_lines/internal/Compact_ids.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {

template <typename P>
class Surface_mesh;
template <typename K, typename VEF>
class SM_index_pmap;
class SM_Face_index;

namespace Highlight_lines {
namespace internal {

// The faces of a region, looked up by face index in a hash table of the region's size: a
// region has hundreds of faces, a car body 10^6, and a table over every face index of the
// mesh (cleared, then copied for the neighbourhood) cost a fairing two passes over the mesh.
template <typename TriangleMesh, typename FaceIndexMap>
class Face_region
{
public:
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename std::vector<face_descriptor>::const_iterator const_iterator;

  explicit Face_region(FaceIndexMap fim) : fim_(fim) {}

  std::size_t index(face_descriptor f) const { return std::size_t(get(fim_, f)); }

  // Requires a face of the mesh.
  bool insert(face_descriptor f)
  {
    bool inserted = false;
    ids_.insert(index(f), int(faces_.size()), inserted);
    if (inserted)
      faces_.push_back(f);
    return inserted;
  }
  // 1 for a face of the mesh in the region, else 0.
  std::size_t count(face_descriptor f) const
  {
    return ids_.find(index(f)) != Compact_ids::none ? 1 : 0;
  }
  const_iterator begin() const { return faces_.begin(); } // in the order of insertion
  const_iterator end() const { return faces_.end(); }
  std::size_t size() const { return faces_.size(); }
  bool empty() const { return faces_.empty(); }

private:
  FaceIndexMap fim_;
  Compact_ids ids_{false, 0}; // face index -> position in faces_
  std::vector<face_descriptor> faces_;
};

// One more than the largest face index of `tm`.
template <typename TriangleMesh, typename FaceIndexMap>
std::size_t face_index_bound(const TriangleMesh& tm, FaceIndexMap fim)
{
  std::size_t bound = 0;
  for (auto f : faces(tm))
    bound = (std::max)(bound, std::size_t(get(fim, f)) + 1);
  return bound;
}

// Whether the faces are a Surface_mesh's indices read with its own index map: then a face
// belongs to the mesh if its index is below the face array's size and it is not removed.
template <typename TriangleMesh, typename FaceIndexMap>
struct Has_surface_mesh_face_indices : std::false_type
{
};
template <typename P>
struct Has_surface_mesh_face_indices<Surface_mesh<P>, SM_index_pmap<P, SM_Face_index>>
    : std::true_type
{
};

// Whether the mesh is a Surface_mesh, whose vertex descriptors are indices.
template <typename TriangleMesh>
struct Is_surface_mesh : std::false_type
{
};
template <typename P>
struct Is_surface_mesh<Surface_mesh<P>> : std::true_type
{
};

// The region, after checking that it is a non-empty range of faces of `tm`. A face belongs
// to `tm` if it is the face of `tm` with its index: one linear pass over the faces (a set of
// all faces would cost O(F log F) and an allocation per face, for every region), except on a
// Surface_mesh, which answers without one (a car body has 10^6 faces, a region hundreds).
template <typename TriangleMesh, typename FaceRange, typename FaceIndexMap>
Face_region<TriangleMesh, FaceIndexMap> checked_region(const TriangleMesh& tm,
                                                       const FaceRange& faces_in, FaceIndexMap fim)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  const face_descriptor null_face = boost::graph_traits<TriangleMesh>::null_face();
  constexpr bool surface_mesh = Has_surface_mesh_face_indices<TriangleMesh, FaceIndexMap>::value;
  std::size_t index_bound = 0;
  std::vector<face_descriptor> face_with_index;
  if constexpr (surface_mesh) {
    index_bound = tm.num_faces(); // removed faces included
  } else {
    index_bound = face_index_bound(tm, fim);
    face_with_index.assign(index_bound, null_face);
    for (face_descriptor f : faces(tm))
      face_with_index[std::size_t(get(fim, f))] = f;
  }
  auto is_face_with_index = [&](face_descriptor f, std::size_t index) {
    if constexpr (surface_mesh)
      return !tm.is_removed(f);
    else
      return face_with_index[index] == f;
  };
  Face_region<TriangleMesh, FaceIndexMap> region(fim);
  for (face_descriptor f : faces_in) {
    // A foreign face's index is read from the foreign face; it is only compared below.
    const std::size_t index = f == null_face ? index_bound : std::size_t(get(fim, f));
    if (index >= index_bound || !is_face_with_index(f, index))
      throw Invalid_input(Invalid_input::Problem::FACE_NOT_IN_MESH,
                          "fair_with_highlight_lines(): the region contains a face that is not "
                          "a face of the mesh",
                          f == null_face ? Invalid_input::no_element : index);
    region.insert(f);
  }
  if (region.empty())
    throw Invalid_input(Invalid_input::Problem::EMPTY_FACE_RANGE,
                        "fair_with_highlight_lines(): the region is empty");
  return region;
}

// The region and `rings` rings of faces around it, by increasing face index: where highlight
// lines are recomputed.
template <typename TriangleMesh, typename FaceIndexMap>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>
neighborhood(const TriangleMesh& tm, const Face_region<TriangleMesh, FaceIndexMap>& region,
             int rings)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  Face_region<TriangleMesh, FaceIndexMap> result = region;
  std::vector<face_descriptor> front(result.begin(), result.end());
  // A vertex is shared by about six faces of a front. A Surface_mesh's vertices are indices:
  // each is expanded once (the repeated expansions were 5 % of a small fairing). Other graphs
  // have no index without a pass over the mesh, and expand a vertex from each of its faces.
  constexpr bool indexed_vertices = Is_surface_mesh<TriangleMesh>::value;
  Compact_ids expanded(false, 0);
  if constexpr (indexed_vertices)
    expanded.reserve(3 * front.size());
  auto first_expansion = [&expanded](vertex_descriptor v) {
    if constexpr (indexed_vertices) {
      bool inserted = false;
      expanded.insert(std::size_t(v), 0, inserted);
      return inserted;
    } else {
      (void)v;
      return true;
    }
  };
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<face_descriptor> next;
    for (face_descriptor f : front)
      for (auto v : vertices_around_face(halfedge(f, tm), tm))
        if (first_expansion(v))
          for (face_descriptor g : faces_around_target(halfedge(v, tm), tm))
            if (g != boost::graph_traits<TriangleMesh>::null_face() && result.insert(g))
              next.push_back(g);
    front.swap(next);
  }
  std::vector<face_descriptor> faces_by_index(result.begin(), result.end());
  std::sort(faces_by_index.begin(), faces_by_index.end(),
            [&result](face_descriptor a, face_descriptor b) {
              return result.index(a) < result.index(b);
            });
  return faces_by_index;
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_FAIRING_FACE_REGION_H

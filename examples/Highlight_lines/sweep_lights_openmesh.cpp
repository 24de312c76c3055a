// Sweeping the light setup over an OpenMesh mesh with Highlight_line_sweeper: the normals
// are computed once; each light position only recomputes the distance values and the lines,
// into the same model object (its memory reused), and the segments a viewer would draw
// (compute_segments(): index pairs for GL_LINES, without tracing the lines).
//
//   sweep_lights_openmesh [mesh.off]
// OpenMesh's property containers trip GCC 12's -Wmaybe-uninitialized once inlined.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Highlight_lines/Highlight_line_sweeper.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
#include <CGAL/boost/graph/properties_TriMesh_ArrayKernelT.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <array>
#include <chrono>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
struct Double_traits : public OpenMesh::DefaultTraits
{
  typedef OpenMesh::Vec3d Point; // CGAL's points are doubles
  typedef OpenMesh::Vec3d Normal;
};
typedef OpenMesh::TriMesh_ArrayKernelT<Double_traits> Mesh;
namespace HL = CGAL::Highlight_lines;

int main(int argc, char** argv)
{
  const std::string input =
      argc > 1 ? argv[1] : std::string(HIGHLIGHT_LINES_DATA_DIR) + "/beetle.off";
  Mesh mesh;
  if (!OpenMesh::IO::read_mesh(mesh, input)) { // OpenMesh's own reader keeps double precision
    std::cerr << "cannot read " << input << "\n";
    return 1;
  }
  const HL::Light_setup<K> lights = HL::default_light_setup(mesh);
  const HL::Highlight_line_sweeper<Mesh> sweeper(mesh); // normals (eq. 3) computed here, once

  // Move the lights across their own direction by one spacing in ten steps, as a designer
  // sweeping the light tunnel over the car body; the line pattern moves with them.
  const auto start = std::chrono::steady_clock::now();
  const auto levels = HL::parameters::level_range(std::make_pair(-15, 15));
  HL::Highlight_line_sweeper<Mesh>::Model model; // computed into at each step
  std::vector<K::Point_3> points;                // the segments' ends, and the segments
  std::vector<std::array<unsigned int, 2>> segments;
  std::size_t total_nodes = 0;
  for (int step = 0; step <= 10; ++step) {
    const auto moved =
        lights.translated(lights.index_direction() * (lights.spacing() * step / 10.0));
    sweeper.compute(moved, model, levels);
    sweeper.compute_segments(moved, points, segments, levels);
    total_nodes += model.nodes().size();
    std::cout << "step " << step << ": " << model.lines().size() << " lines, "
              << model.nodes().size() << " nodes, " << segments.size() << " segments to draw\n";
    if (segments.size() != model.number_of_segments())
      return 1; // the segments are those of the model's lines
  }
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::cout << "11 light positions in " << ms << " ms\n";
  return total_nodes > 0 ? 0 : 1;
}

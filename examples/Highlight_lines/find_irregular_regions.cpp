// detect_highlight_line_irregularities() on a CGAL::Surface_mesh: the regions where the
// highlight lines deviate from the course their surroundings predict, strongest first, printed
// and written as a face property (the region's rank, 0 outside every region) in a PLY file.
//
//   find_irregular_regions [mesh.off] [output.ply]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/detect_highlight_line_irregularities.h>

#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace HL = CGAL::Highlight_lines;

int main(int argc, char** argv)
{
  const std::string input =
      argc > 1 ? argv[1] : std::string(HIGHLIGHT_LINES_DATA_DIR) + "/beetle.off";
  const std::string output = argc > 2 ? argv[2] : "find_irregular_regions.ply";
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(input, mesh) || is_empty(mesh)) {
    std::cerr << "cannot read " << input << "\n";
    return 1;
  }

  // The lights are swept over every side of the mesh, in several directions and offsets.
  const HL::Light_setup<K> lights = HL::default_light_setup(mesh);
  std::vector<HL::Highlight_line_irregularity<Mesh>> regions;
  CGAL::detect_highlight_line_irregularities(mesh, lights, std::back_inserter(regions));

  // A defect is local and breaks the shape's symmetry: high confidence. Design features that
  // are not sharp edges (fillets, panel joints) come after it, with low confidence.
  std::size_t likely_defects = 0;
  for (std::size_t i = 0; i < regions.size() && i < 10; ++i) {
    const auto& r = regions[i];
    std::cout << i + 1 << ": " << HL::to_string(r.kind) << ", " << r.faces.size()
              << " faces, score " << r.score << ", confidence " << r.confidence << "\n";
  }
  for (const auto& r : regions)
    likely_defects += r.confidence >= 0.5;
  std::cout << regions.size() << " regions, " << likely_defects
            << " of confidence >= 0.5 (those detect_and_fair fairs)\n";

  auto rank = mesh.add_property_map<Mesh::Face_index, int>("f:region", 0).first;
  for (std::size_t i = regions.size(); i-- > 0;)
    for (Mesh::Face_index f : regions[i].faces)
      rank[f] = int(i + 1);
  std::ofstream out(output);
  return CGAL::IO::write_PLY(out, mesh) ? 0 : 1;
}

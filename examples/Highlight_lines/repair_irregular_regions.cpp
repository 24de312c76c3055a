// detect_and_fair_highlight_line_irregularities() on a CGAL::Polyhedron_3: the automatic
// mode. It finds the regions whose highlight lines are irregular, fairs those that are likely
// defects, says what it skipped and why, and the repaired mesh is written.
//
//   repair_irregular_regions [mesh.off] [output.off]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/detect_and_fair_highlight_line_irregularities.h>

#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Polyhedron_3<K> Polyhedron;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;

int main(int argc, char** argv)
{
  const std::string input =
      argc > 1 ? argv[1] : std::string(HIGHLIGHT_LINES_DATA_DIR) + "/beetle.off";
  const std::string output = argc > 2 ? argv[2] : "repair_irregular_regions.off";
  Polyhedron mesh;
  if (!CGAL::IO::read_polygon_mesh(input, mesh) || is_empty(mesh)) {
    std::cerr << "cannot read " << input << "\n";
    return 1;
  }

  // Regions below the confidence level are skipped (most likely design); each fairing that
  // fails leaves the mesh as it was before that region.
  const HL::Light_setup<K> lights = HL::default_light_setup(mesh);
  const std::vector<HL::Irregularity_repair<Polyhedron>> repairs =
      CGAL::detect_and_fair_highlight_line_irregularities(mesh, lights,
                                                          HLP::minimum_confidence(0.5));

  std::size_t repaired = 0, skipped = 0;
  for (const auto& r : repairs) {
    if (r.repaired) {
      ++repaired;
      std::cout << "faired a " << HL::to_string(r.irregularity.kind) << " of "
                << r.irregularity.faces.size() << " faces (confidence " << r.irregularity.confidence
                << "): " << HL::to_string(r.report.status) << " after " << r.report.iterations
                << " iterations\n";
    } else if (r.skipped)
      ++skipped;
    else
      std::cout << "not faired: " << r.failure << "\n";
  }
  std::cout << repaired << " regions faired, " << skipped
            << " skipped (confidence below 0.5: most likely design)\n";
  return CGAL::IO::write_polygon_mesh(output, mesh, CGAL::parameters::stream_precision(17)) ? 0 : 1;
}

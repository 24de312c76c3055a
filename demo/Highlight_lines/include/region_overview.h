// A picture of a whole Surface_mesh seen from the light plane's side, some face regions tinted
// (red: the first, orange: the others) and the highlight lines of a light setup drawn on top.
// Shared by the command-line programs that show detected irregularities.
#ifndef HIGHLIGHT_LINES_DEMO_REGION_OVERVIEW_H
#define HIGHLIGHT_LINES_DEMO_REGION_OVERVIEW_H

#include <CGAL/Highlight_lines/Light_setup.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/compute_highlight_lines.h>

#include "highlight_picture.h"
#include "mesh_picture.h"

#include <array>
#include <optional>
#include <vector>

namespace region_overview {

template <typename Point, typename Kernel>
highlight_picture::Image
picture(const CGAL::Surface_mesh<Point>& mesh,
        const CGAL::Highlight_lines::Light_setup<Kernel>& lights,
        const std::vector<std::vector<typename CGAL::Surface_mesh<Point>::Face_index>>& regions,
        int width, int height)
{
  namespace pic = highlight_picture;
  namespace HLP = CGAL::Highlight_lines::parameters;
  using mesh_picture::to_array;
  std::vector<pic::Point3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  mesh_picture::mesh_arrays(mesh, points, triangles);
  std::vector<std::optional<pic::RGB>> colors(num_faces(mesh));
  for (std::size_t i = regions.size(); i-- > 0;)
    for (auto f : regions[i])
      colors[std::size_t(f)] =
          pic::mix(pic::colors::paint, i == 0 ? pic::colors::red : pic::colors::orange, 0.6);
  const auto z = to_array(lights.plane_normal());
  const auto h = to_array(lights.light_direction());
  const pic::Vector3 view{-(0.5 * h[0] + z[0]), -(0.5 * h[1] + z[1]), -(0.5 * h[2] + z[2])};
  pic::Renderer renderer(width, height, pic::fit_camera(points, view, z, width, height));
  renderer.draw_mesh(points, triangles, pic::Surface_style{}, colors);
  std::vector<std::vector<Point>> lines;
  CGAL::compute_highlight_lines(
      mesh, lights, std::back_inserter(lines),
      HLP::combine(HLP::level_range(CGAL::Highlight_lines::default_level_range(mesh, lights)),
                   HLP::facing_side_only(true)));
  renderer.draw_polylines(mesh_picture::polyline_arrays(lines));
  return renderer.image();
}

} // namespace region_overview

#endif // HIGHLIGHT_LINES_DEMO_REGION_OVERVIEW_H

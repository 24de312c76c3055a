// The default level window (issue 18): a whole-mesh model without a level range keeps every
// line where the surface faces the light plane; an edge crossing more than
// max_levels_per_edge levels only loses the levels beyond the lights imaged there, and that is
// counted. And nodes() holds exactly the nodes of lines(), as documented.
#include "test_meshes.h"

#include <CGAL/Highlight_lines/Highlight_line_sweeper.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/compute_highlight_lines.h>

#include <gtest/gtest.h>

#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace {

using namespace test;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;

typedef HL::Highlight_line_model<Surface_mesh, K> Window_model;

Surface_mesh window_test_mesh(const std::string& name)
{
  Surface_mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(shared_data(name), mesh))
    ADD_FAILURE() << "cannot read " << shared_data(name);
  return mesh;
}

// Per vertex: whether its normal (eq. 3: the sum of the face cross products, computed here)
// points towards the light plane, Z·N > 0.
std::vector<bool> window_test_facing(const Surface_mesh& mesh, const Lights& lights)
{
  std::vector<bool> facing(num_vertices(mesh), false);
  const Vector z = lights.plane_normal();
  for (auto v : vertices(mesh))
    facing[std::size_t(v)] = z * area_weighted_normal(mesh, v) > 0;
  return facing;
}

// A node as the models compute it: its level and exact position.
typedef std::tuple<long long, double, double, double> Window_node_key;

Window_node_key window_node_key(const Window_model::Node& node)
{
  return Window_node_key(node.level, node.point.x(), node.point.y(), node.point.z());
}

// Whether a node lies on a face whose three vertices face the light plane.
bool window_node_on_facing_face(const Surface_mesh& mesh, const std::vector<bool>& facing,
                                const Window_model::Node& node)
{
  auto facing_face = [&](Surface_mesh::Face_index f) {
    if (f == Surface_mesh::null_face())
      return false;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      if (!facing[std::size_t(v)])
        return false;
    return true;
  };
  if (node.is_on_vertex()) {
    for (auto f : CGAL::faces_around_target(mesh.halfedge(node.vertex), mesh))
      if (facing_face(f))
        return true;
    return false;
  }
  return facing_face(mesh.face(node.halfedge)) ||
         facing_face(mesh.face(mesh.opposite(node.halfedge)));
}

// nodes() is documented as exactly the nodes of lines(), each with degree >= 1.
void expect_nodes_are_the_nodes_of_the_lines(const Window_model& model, const std::string& what)
{
  std::vector<int> visits(model.nodes().size(), 0);
  for (const auto& line : model.lines())
    for (std::size_t n : line.nodes) {
      ASSERT_LT(n, model.nodes().size()) << what;
      ++visits[n];
    }
  std::size_t unvisited = 0, isolated = 0;
  for (std::size_t i = 0; i < model.nodes().size(); ++i) {
    unvisited += visits[i] == 0;
    isolated += model.nodes()[i].degree == 0;
  }
  EXPECT_EQ(unvisited, 0u) << what << ": nodes in no line";
  EXPECT_EQ(isolated, 0u) << what << ": nodes without segment";
  // Numbered in the order the lines visit them: the first visits are 0, 1, 2, ...
  std::size_t next = 0;
  std::vector<bool> seen(model.nodes().size(), false);
  for (const auto& line : model.lines())
    for (std::size_t n : line.nodes)
      if (!seen[n]) {
        seen[n] = true;
        ASSERT_EQ(n, next++) << what << ": node numbering";
      }
}

// The proof: on every shared mesh, under a light tunnel of 40 lines placed above it, a
// whole-mesh call without a level range keeps every node with |m| <= 60 that lies on a face
// whose vertices face the light plane (the nodes of the call restricted to [-60, 60], where no
// edge crosses 256 levels). Before, every face next to an edge crossing more than 256 levels
// was dropped whole: thousands of those nodes were lost per mesh.
TEST(LevelWindow, WholeMeshKeepsTheLinesWhereTheSurfaceFacesTheLights)
{
  for (const std::string name :
       {"beetle.off", "bunny.off", "camelhead.off", "fandisk.off", "rocker-arm.off", "spot.off"}) {
    const Surface_mesh mesh = window_test_mesh(name);
    ASSERT_GT(num_faces(mesh), 0u) << name;
    const Lights lights = HL::default_light_setup(mesh, HLP::number_of_lines(40));
    const HL::Highlight_line_sweeper<Surface_mesh> sweeper(mesh);
    const Window_model reference =
        sweeper.compute(lights, HLP::level_range(std::make_pair(-60, 60)));
    const Window_model whole = sweeper.compute(lights);
    EXPECT_EQ(reference.number_of_skipped_edges(), 0u) << name;

    std::set<Window_node_key> kept;
    for (const auto& node : whole.nodes())
      kept.insert(window_node_key(node));
    const std::vector<bool> facing = window_test_facing(mesh, lights);
    std::size_t wanted = 0, missing = 0;
    for (const auto& node : reference.nodes()) {
      if (!window_node_on_facing_face(mesh, facing, node))
        continue;
      ++wanted;
      missing += kept.count(window_node_key(node)) == 0;
    }
    EXPECT_GT(wanted, 1000u) << name;
    EXPECT_EQ(missing, 0u) << name << ": " << missing << " of " << wanted
                           << " nodes with |m| <= 60 on faces facing the light plane lost";
    // The rule still acts near the silhouettes, and is counted.
    EXPECT_GT(whole.number_of_skipped_edges(), 0u) << name;
    EXPECT_GT(whole.number_of_trimmed_nodes(), 0u) << name;
    EXPECT_EQ(reference.number_of_trimmed_nodes(), 0u) << name;

    expect_nodes_are_the_nodes_of_the_lines(reference, name + " [-60, 60]");
    expect_nodes_are_the_nodes_of_the_lines(whole, name + " (all levels)");
  }
}

// The cap only trims: raising it adds nodes beyond the facing window and never removes one, and
// the trimmed nodes are counted as the difference on the edges concerned.
TEST(LevelWindow, TheCapOnlyTrimsBeyondTheFacingLights)
{
  const Surface_mesh mesh = window_test_mesh("spot.off");
  const Lights lights = HL::default_light_setup(mesh, HLP::number_of_lines(40));
  const HL::Highlight_line_sweeper<Surface_mesh> sweeper(mesh);
  const Window_model capped = sweeper.compute(lights, HLP::max_levels_per_edge(16));
  const Window_model default_cap = sweeper.compute(lights);
  ASSERT_GT(capped.number_of_skipped_edges(), default_cap.number_of_skipped_edges());
  // Same lights kept where the surface faces them: the nodes of the smaller cap are nodes of
  // the larger one, as far as the levels they share go.
  std::set<Window_node_key> larger;
  for (const auto& node : default_cap.nodes())
    larger.insert(window_node_key(node));
  std::size_t missing = 0;
  for (const auto& node : capped.nodes())
    missing += larger.count(window_node_key(node)) == 0;
  EXPECT_EQ(missing, 0u);
  EXPECT_LT(capped.nodes().size(), default_cap.nodes().size());
  expect_nodes_are_the_nodes_of_the_lines(capped, "spot, cap 16");
}

// A spacing tiny against the mesh (found by the fuzzer): edges then cross more levels than
// the cap even inside the facing window. They are skipped whole, with their faces, as without
// the facing window, instead of the model growing past 2^31 nodes (std::length_error).
TEST(LevelWindow, EdgesOverTheCapInsideTheFacingWindowAreSkipped)
{
  const Surface_mesh mesh = window_test_mesh("bunny.off");
  const Lights usual = HL::default_light_setup(mesh, HLP::number_of_lines(40));
  const Lights dense(usual.base_point(), usual.light_direction(), usual.plane_normal(),
                     usual.spacing() * 1e-9);
  const HL::Highlight_line_sweeper<Surface_mesh> sweeper(mesh);
  const std::size_t cap = 64;
  std::optional<Window_model> model;
  ASSERT_NO_THROW(model.emplace(sweeper.compute(dense, HLP::max_levels_per_edge(cap))));
  EXPECT_GT(model->number_of_skipped_edges(), num_edges(mesh) / 2);
  EXPECT_LE(model->nodes().size(), cap * num_edges(mesh));
  expect_nodes_are_the_nodes_of_the_lines(*model, "bunny, spacing 1e-9 of the usual");
}

} // namespace

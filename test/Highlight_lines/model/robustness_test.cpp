// Bad input gets a clear error and leaves the mesh untouched; real meshes go through.
#include "test_meshes.h"

#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/compute_highlight_lines.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

namespace {
using namespace test;
using CGAL::Highlight_lines::Invalid_input;
typedef Invalid_input::Problem Problem;

template <typename F>
void expect_invalid_input(F&& f, Problem problem, const std::string& message_part)
{
  try {
    f();
    ADD_FAILURE() << "no exception";
  } catch (const Invalid_input& e) {
    EXPECT_EQ(e.problem(), problem) << e.what();
    EXPECT_NE(std::string(e.what()).find(message_part), std::string::npos) << e.what();
  }
}

const Lights lights(Point(0, 0, 5), Vector(1, 0, 0), Vector(0, 0, 1), 0.1);

TEST(BadInput, InvalidLightSetupsAreRefused)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto make = [](Point a, Vector h, Vector z, double s) { return Lights(a, h, z, s); };
  expect_invalid_input([&] { make(Point(0, 0, 1), Vector(1, 0, 0.5), Vector(0, 0, 1), 1); },
                       Problem::INVALID_LIGHT_SETUP, "perpendicular");
  expect_invalid_input([&] { make(Point(0, 0, 1), Vector(0, 0, 0), Vector(0, 0, 1), 1); },
                       Problem::INVALID_LIGHT_SETUP, "zero vector");
  expect_invalid_input([&] { make(Point(0, 0, 1), Vector(1, 0, 0), Vector(0, 0, 0), 1); },
                       Problem::INVALID_LIGHT_SETUP, "zero vector");
  expect_invalid_input([&] { make(Point(0, 0, 1), Vector(1, 0, 0), Vector(0, 0, 1), 0); },
                       Problem::INVALID_LIGHT_SETUP, "spacing");
  expect_invalid_input([&] { make(Point(0, 0, 1), Vector(1, 0, 0), Vector(0, 0, 1), -2); },
                       Problem::INVALID_LIGHT_SETUP, "spacing");
  expect_invalid_input([&] { make(Point(0, 0, 1), Vector(1, 0, 0), Vector(0, 0, 1), nan); },
                       Problem::INVALID_LIGHT_SETUP, "spacing");
  expect_invalid_input([&] { make(Point(nan, 0, 1), Vector(1, 0, 0), Vector(0, 0, 1), 1); },
                       Problem::INVALID_LIGHT_SETUP, "non-finite");
  expect_invalid_input([&] { make(Point(0, 0, 1), Vector(inf, 0, 0), Vector(0, 0, 1), 1); },
                       Problem::INVALID_LIGHT_SETUP, "non-finite");
  // A direction off the plane by less than 1e-6 is accepted and projected.
  const Lights almost(Point(0, 0, 1), Vector(1, 0, 1e-9), Vector(0, 0, 2), 1);
  EXPECT_EQ(CGAL::to_double(almost.light_direction().z()), 0.0);
  EXPECT_EQ(CGAL::to_double(almost.plane_normal().z()), 1.0);
}

TEST(BadInput, NonTriangleFaceIsNamed)
{
  Surface_mesh mesh;
  auto v0 = mesh.add_vertex(Point(0, 0, 0)), v1 = mesh.add_vertex(Point(1, 0, 0)),
       v2 = mesh.add_vertex(Point(1, 1, 0)), v3 = mesh.add_vertex(Point(0, 1, 0)),
       v4 = mesh.add_vertex(Point(2, 0, 0));
  mesh.add_face(v0, v1, v2, v3);
  mesh.add_face(v1, v4, v2);
  const Surface_mesh copy = mesh;
  expect_invalid_input(
      [&] { CGAL::compute_highlight_lines(mesh, lights, CGAL::Emptyset_iterator()); },
      Problem::NON_TRIANGLE_FACE, "face 0 is not a triangle");
}

TEST(BadInput, NonFiniteCoordinateIsNamed)
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(grid(4, 1, 0, 0, [](double, double) { return 0.0; }));
  mesh.point(Surface_mesh::Vertex_index(7)) = Point(1, std::numeric_limits<double>::quiet_NaN(), 0);
  expect_invalid_input(
      [&] { CGAL::compute_highlight_lines(mesh, lights, CGAL::Emptyset_iterator()); },
      Problem::NON_FINITE_COORDINATE, "vertex 7");
}

TEST(BadInput, DegenerateFaceIsNamed)
{
  Soup soup = grid(4, 1, 0, 0, [](double, double) { return 0.0; });
  soup.points.push_back(Point(10, 0, 0));
  soup.points.push_back(Point(11, 0, 0));
  soup.points.push_back(Point(12, 0, 0)); // collinear
  soup.triangles.push_back(
      {soup.points.size() - 3, soup.points.size() - 2, soup.points.size() - 1});
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  expect_invalid_input(
      [&] { CGAL::compute_highlight_lines(mesh, lights, CGAL::Emptyset_iterator()); },
      Problem::DEGENERATE_FACE, "degenerate");
}

TEST(BadInput, InvalidParameterIsRefused)
{
  const Surface_mesh mesh =
      to_mesh<Surface_mesh>(grid(4, 1, 0, 0, [](double, double) { return 0.0; }));
  namespace HLP = CGAL::Highlight_lines::parameters;
  expect_invalid_input(
      [&] {
        CGAL::compute_highlight_lines(mesh, lights, CGAL::Emptyset_iterator(),
                                      HLP::max_levels_per_edge(0));
      },
      Problem::INVALID_PARAMETER, "max_levels_per_edge");
}

TEST(NamedParameters, OursAndCGALsCombineInAnyOrder)
{
  const Surface_mesh mesh =
      to_mesh<Surface_mesh>(grid(20, 0.5, 0, 0, [](double x, double y) { return 0.1 * x * y; }));
  namespace HLP = CGAL::Highlight_lines::parameters;
  const auto reference = CGAL::compute_highlight_lines(mesh, lights, CGAL::Emptyset_iterator(),
                                                       HLP::level_range(std::make_pair(-20, -5)));
  const auto vpm = get(CGAL::vertex_point, mesh);
  const auto a = CGAL::compute_highlight_lines(
      mesh, lights, CGAL::Emptyset_iterator(),
      HLP::level_range(std::make_pair(-20, -5)).vertex_point_map(vpm).geom_traits(K()));
  const auto b = CGAL::compute_highlight_lines(
      mesh, lights, CGAL::Emptyset_iterator(),
      HLP::level_range(CGAL::parameters::vertex_point_map(vpm), std::make_pair(-20, -5)));
  const auto c = CGAL::compute_highlight_lines(
      mesh, lights, CGAL::Emptyset_iterator(),
      HLP::combine(CGAL::parameters::vertex_point_map(vpm).geom_traits(K()),
                   HLP::max_levels_per_edge(100), HLP::level_range(std::make_pair(-20, -5))));
  ASSERT_GT(reference.nodes().size(), 0u);
  for (const auto* m : {&a, &b, &c}) {
    EXPECT_EQ(m->nodes().size(), reference.nodes().size());
    for (const auto& node : m->nodes())
      EXPECT_TRUE(node.level >= -20 && node.level <= -5);
  }
}

// The highlight distance is invariant under a change of base point along the lights and
// shifts by exactly one level when the base point moves by one spacing across the lights.
TEST(LightSetup, SweepsMoveLevelsPredictably)
{
  const Surface_mesh mesh =
      to_mesh<Surface_mesh>(grid(20, 0.5, 0, 0, [](double x, double y) { return 0.1 * x * y; }));
  CGAL::Highlight_lines::Highlight_line_sweeper<Surface_mesh> sweeper(mesh);
  const auto base = sweeper.compute(lights);
  const auto along = sweeper.compute(lights.translated(Vector(3, 0, 0)));
  const auto across =
      sweeper.compute(lights.translated(lights.index_direction() * lights.spacing()));
  ASSERT_EQ(base.nodes().size(), along.nodes().size());
  ASSERT_EQ(base.nodes().size(), across.nodes().size());
  for (std::size_t i = 0; i < base.nodes().size(); ++i) {
    EXPECT_EQ(base.nodes()[i].level, along.nodes()[i].level);
    EXPECT_EQ(base.nodes()[i].level, across.nodes()[i].level + 1);
    EXPECT_LT(CGAL::squared_distance(base.nodes()[i].point, across.nodes()[i].point), 1e-20);
  }
  // Rotated lights stay orthonormal.
  const auto turned = lights.rotated(Vector(0.3, 0.2, 1), 0.4);
  EXPECT_NEAR(CGAL::to_double(turned.light_direction() * turned.plane_normal()), 0.0, 1e-15);
  EXPECT_NEAR(CGAL::to_double(turned.light_direction().squared_length()), 1.0, 1e-15);
  EXPECT_NEAR(CGAL::to_double(turned.plane_normal().squared_length()), 1.0, 1e-15);
  EXPECT_NE(sweeper.compute(turned).nodes().size(), 0u);
}

class SharedMeshes : public ::testing::TestWithParam<std::string>
{
};

// Every real mesh of the developers' data set goes through, with a default light setup, and
// its model satisfies the invariants that hold everywhere: finite nodes, levels matching the
// lines, degrees consistent with the lines.
TEST_P(SharedMeshes, ModelIsConsistent)
{
  const std::string path = shared_data(GetParam());
  if (!std::filesystem::exists(path))
    GTEST_SKIP() << path << " not found";
  Surface_mesh mesh;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(path, mesh));
  const auto lights = CGAL::Highlight_lines::default_light_setup(mesh);
  const auto model = CGAL::compute_highlight_lines(mesh, lights, CGAL::Emptyset_iterator());
  EXPECT_GT(model.lines().size(), 5u);
  std::vector<std::size_t> degree(model.nodes().size(), 0);
  for (const auto& s : segments_of(model)) {
    ++degree[s.first];
    ++degree[s.second];
  }
  for (std::size_t i = 0; i < model.nodes().size(); ++i) {
    const auto& n = model.nodes()[i];
    EXPECT_EQ(n.degree, degree[i]);
    EXPECT_GT(n.degree, 0u);
    EXPECT_TRUE(std::isfinite(n.point.x()) && std::isfinite(n.point.y()) &&
                std::isfinite(n.point.z()));
    if (n.degree > 2) {
      EXPECT_TRUE(n.is_on_vertex()) << "only vertices on a level join more than two segments";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllSharedMeshes, SharedMeshes,
                         ::testing::Values("beetle.off", "bunny.off", "camelhead.off",
                                           "fandisk.off", "rocker-arm.off", "spot.off"),
                         [](const auto& info) {
                           std::string name = info.param.substr(0, info.param.find('.'));
                           name.erase(std::remove(name.begin(), name.end(), '-'), name.end());
                           return name;
                         });

} // namespace

#include <CGAL/Gmpq.h>

namespace {
using namespace test;

// A two-face fan built so that rounding in one face's cross product flips the double sign of
// Z·Ñ (found in review). The classification must follow the exact one-ring values: level
// floor(d/s), side sign(Z·Ñ), nothing out of range.
TEST(ExactClassification, FollowsExactValuesWhereDoubleNormalsAreWrong)
{
  Surface_mesh m;
  const double e52 = std::ldexp(1.0, -52), e51 = std::ldexp(1.0, -51), e105 = std::ldexp(1.0, -105);
  auto v0 = m.add_vertex(Point(0, 0, 0));
  auto p1 = m.add_vertex(Point(1 + e52, 1, 0));
  auto p2 = m.add_vertex(Point(1 + e51, 1 + e52, 1));
  auto p3 = m.add_vertex(Point(0, -e105, 1));
  m.add_face(p1, p2, v0);
  m.add_face(p2, p3, v0);
  const double s = 2.0 * std::ldexp(1.0, 105) / 1000.5;
  const Lights lights(Point(0, 0, 1), Vector(1, 0, 0), Vector(0, 0, 1), s);
  CGAL::Highlight_lines::Highlight_line_sweeper<Surface_mesh> sweeper(m);
  std::vector<CGAL::Highlight_lines::internal::Vertex_level> levels;
  sweeper.classify(lights, levels);
  const auto& lm = sweeper.local_mesh();
  typedef CGAL::Gmpq Q;
  for (std::size_t v = 0; v < lm.number_of_model_vertices; ++v) {
    Q n[3] = {0, 0, 0};
    for (std::size_t f = 0; f < lm.face_vertices.size(); ++f) {
      const auto& c = lm.face_vertices[f];
      if (c[0] != int(v) && c[1] != int(v) && c[2] != int(v))
        continue;
      const double *a = lm.point(c[0]), *b = lm.point(c[1]), *d = lm.point(c[2]);
      Q u[3], w[3];
      for (int k = 0; k < 3; ++k) {
        u[k] = Q(b[k]) - Q(a[k]);
        w[k] = Q(d[k]) - Q(a[k]);
      }
      n[0] += u[1] * w[2] - u[2] * w[1];
      n[1] += u[2] * w[0] - u[0] * w[2];
      n[2] += u[0] * w[1] - u[1] * w[0];
    }
    const double* p = lm.point(int(v));
    // (P - A0) x H with H = (1, 0, 0), A0 = (0, 0, 1); Z = (0, 0, 1).
    const Q W[3] = {Q(p[0]), Q(p[1]), Q(p[2]) - Q(1)};
    const Q num = W[2] * n[1] - W[1] * n[2], den = n[2];
    const auto& level = levels[v];
    ASSERT_EQ(int(level.normal_side), int(CGAL::sign(den))) << "vertex " << v;
    if (den == 0)
      continue;
    const Q ratio = num / den / Q(s);
    EXPECT_FALSE(level.out_of_range) << "vertex " << v;
    // floor(ratio) == level  <=>  level <= ratio < level + 1
    EXPECT_TRUE(Q(double(level.level)) <= ratio && ratio < Q(double(level.level + 1)))
        << "vertex " << v << ": level " << level.level << ", exact d/s " << CGAL::to_double(ratio);
    EXPECT_EQ(level.on_level, ratio == Q(double(level.level)));
  }
}

// The classification pass takes the common case several vertices at a time (two lanes, or
// four with AVX2 where the processor has them) and the other vertices one at a time; every
// class must be the one Level_classifier::classify() gives that vertex alone, to the bit.
// Lights through a vertex of an integer grid, along the axes, with a power-of-two spacing:
// many vertices lie exactly on a level, so that lanes of common and general cases mix.
TEST(ExactClassification, VectorPassesEqualOneVertexAtATime)
{
  auto wavy = [](double x, double y) { return std::floor(3 * std::sin(x) + 2 * std::cos(y)); };
  std::vector<Surface_mesh> meshes;
  meshes.push_back(to_mesh<Surface_mesh>(grid(37, 1.0, -18, -18, wavy)));
  meshes.push_back(to_mesh<Surface_mesh>(sphere(3.0, 4)));
  for (const Surface_mesh& m : meshes) {
    CGAL::Highlight_lines::Highlight_line_sweeper<Surface_mesh> sweeper(m);
    const Point corner = m.point(*vertices(m).begin());
    const std::vector<Lights> all_lights = {
        Lights(corner, Vector(1, 0, 0), Vector(0, 0, 1), 0.25),
        Lights(corner, Vector(0, 1, 0), Vector(1, 0, 1), 0.5),
        Lights(Point(0.1, 0.2, 5), Vector(1, 0.3, 0), Vector(0.3, -1, 5), 0.37)};
    for (const Lights& lights : all_lights)
      for (bool facing_side_only : {false, true}) {
        std::vector<CGAL::Highlight_lines::internal::Vertex_level> levels;
        sweeper.classify(lights, levels, facing_side_only);
        const auto classifier = sweeper.classifier(lights);
        CGAL::Highlight_lines::internal::Classification_statistics stats;
        ASSERT_EQ(levels.size(), sweeper.local_mesh().number_of_model_vertices);
        std::size_t on_level = 0;
        for (std::size_t v = 0; v < levels.size(); ++v) {
          const auto alone = classifier.classify(int(v), stats, facing_side_only);
          const auto& l = levels[v];
          on_level += l.on_level;
          ASSERT_EQ(l.level, alone.level) << "vertex " << v;
          ASSERT_EQ(l.normal_side, alone.normal_side) << "vertex " << v;
          ASSERT_EQ(l.on_level, alone.on_level) << "vertex " << v;
          ASSERT_EQ(l.out_of_range, alone.out_of_range) << "vertex " << v;
          ASSERT_EQ(l.turned_away, alone.turned_away) << "vertex " << v;
          ASSERT_EQ(std::memcmp(&l.distance, &alone.distance, sizeof(double)), 0) << "vertex " << v;
        }
        if (&lights == &all_lights[0] && &m == &meshes[0]) {
          EXPECT_GT(on_level, std::size_t(10)); // the general case is exercised
        }
      }
  }
}

} // namespace

#define BOOST_TEST_MODULE model
#include <boost/test/unit_test.hpp>

#include "model/Scene_model.h"
#include "exact/Rational_kernel.h"
#include "float/Double_kernel.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"

using namespace clash4d;
using Q = Rational;

static Scene scene_with(const std::string& shape_a, const std::string& motion_a = "rest")
{
  std::string text = R"({"format":"clash4d-scene/1","time":[0,10],"objects":[{"name":"a","shape":)" + shape_a +
                     R"(,"motion":")" + motion_a + R"("},{"name":"b","shape":{"block":{"min":[0,0,0],"max":[1,1,1]}}}]})";
  return read_scene(read_json_text(text));
}

static Csg_model<Q> model_of(const std::string& shape)
{
  Rational_kernel k;
  return Scene_model<Rational_kernel>::build(k, scene_with(shape)).objects[0].csg;
}

static void check_box(const Box<Q, 3>& b, std::array<Q, 3> lo, std::array<Q, 3> hi)
{
  for (int a = 0; a < 3; ++a) {
    BOOST_TEST_REQUIRE((b.has_lo[a] && b.has_hi[a]));
    BOOST_TEST(b.lo[a] == lo[a]);
    BOOST_TEST(b.hi[a] == hi[a]);
  }
}

// Every vertex lies on at least three planes and inside all of them.
static void check_vertices_on_planes(const Primitive<Q>& p)
{
  for (const auto& v : p.vertices) {
    int on = 0;
    for (const auto& h : p.planes) {
      Q value = h[0] * v[0] + h[1] * v[1] + h[2] * v[2] + h[3];
      BOOST_TEST(value <= Q(0));
      on += value == Q(0);
    }
    BOOST_TEST(on >= 3);
  }
}

BOOST_AUTO_TEST_CASE(block_is_six_halfspaces_with_its_box)
{
  auto m = model_of(R"({"block":{"min":[0,"0.5",-1],"max":[1,2,"1/3"]}})");
  BOOST_TEST_REQUIRE(m.primitives.size() == 1u);
  BOOST_TEST(m.primitives[0].planes.size() == 6u);
  check_box(m.primitives[0].box, {Q(0), Q(1, 2), Q(-1)}, {Q(1), Q(2), Q(1, 3)});
  check_vertices_on_planes(m.primitives[0]);
}

BOOST_AUTO_TEST_CASE(rotation_matrices_are_exactly_orthogonal)
{
  for (auto w : {std::array<int, 4>{3, 0, 0, 4}, {1, 1, 1, 1}, {1, 2, 3, 4}, {7, -1, 5, 2}, {0, 0, 0, 9}}) {
    auto R = rotation_matrix(Q(w[0]), Q(w[1]), Q(w[2]), Q(w[3]));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) BOOST_TEST(dot(R[i], R[j]) == Q(i == j ? 1 : 0));
    BOOST_TEST(determinant3(R[0], R[1], R[2]) == Q(1));
  }
}

BOOST_AUTO_TEST_CASE(rotated_block_box_is_the_box_of_its_rotated_corners)
{
  // q = (3,0,0,4): about z by the angle with cos = -7/25, sin = 24/25.
  auto m = model_of(R"({"rotate":[3,0,0,4],"solid":{"block":{"min":[-1,-1,-1],"max":[1,1,1]}}})");
  check_box(m.primitives[0].box, {Q(-31, 25), Q(-31, 25), Q(-1)}, {Q(31, 25), Q(31, 25), Q(1)});
  check_vertices_on_planes(m.primitives[0]);
}

BOOST_AUTO_TEST_CASE(translate_then_rotate_composes)
{
  // rotate by 90 degrees about z (q = (1,0,0,1)) a block translated by (2,0,0):
  // the block [2,3]x[0,1]x[0,1] goes to [-1,0]x[2,3]x[0,1].
  auto m = model_of(R"({"rotate":[1,0,0,1],"solid":{"translate":[2,0,0],"solid":{"block":{"min":[0,0,0],"max":[1,1,1]}}}})");
  check_box(m.primitives[0].box, {Q(-1), Q(2), Q(0)}, {Q(0), Q(3), Q(1)});
  check_vertices_on_planes(m.primitives[0]);
}

BOOST_AUTO_TEST_CASE(prism_hull_and_convex)
{
  auto prism = model_of(R"({"prism":{"base":[[0,0],[2,0],[1,1]],"z":[0,"0.5"]}})");
  BOOST_TEST(prism.primitives[0].planes.size() == 5u);
  check_box(prism.primitives[0].box, {Q(0), Q(0), Q(0)}, {Q(2), Q(1), Q(1, 2)});
  check_vertices_on_planes(prism.primitives[0]);

  auto cube = model_of(R"({"hull":[[0,0,0],[1,0,0],[0,1,0],[1,1,0],[0,0,1],[1,0,1],[0,1,1],[1,1,1],["1/2","1/2","1/2"]]})");
  BOOST_TEST(cube.primitives[0].planes.size() == 6u);   // one plane per facet, not per triangle
  check_box(cube.primitives[0].box, {Q(0), Q(0), Q(0)}, {Q(1), Q(1), Q(1)});
  check_vertices_on_planes(Primitive<Q>{"", cube.primitives[0].planes, {{Q(0), Q(0), Q(0)}, {Q(1), Q(1), Q(1)}}, {}, {}});

  auto octa = model_of(R"({"convex":[[1,1,1,-1],[1,1,-1,-1],[1,-1,1,-1],[1,-1,-1,-1],[-1,1,1,-1],[-1,1,-1,-1],[-1,-1,1,-1],[-1,-1,-1,-1],[1,0,0,-5]]})");
  BOOST_TEST(octa.primitives[0].vertices.size() == 6u);
  check_box(octa.primitives[0].box, {Q(-1), Q(-1), Q(-1)}, {Q(1), Q(1), Q(1)});
  check_vertices_on_planes(octa.primitives[0]);
}

// Model_builder::primitive_box (what a sweep tie asks of a one-primitive
// object, exact/Filtered_runner.h) is the box the model gives the
// primitive, for every kind under a rotation and a translation: block,
// prism and hull from their vertices alone, convex and half-spaces from
// their planes; the rotated block's by hand too (corners (+-1,+-1) turned
// by cos = -7/25, sin = 24/25 reach +-31/25).
BOOST_AUTO_TEST_CASE(primitive_box_is_the_models_box)
{
  const std::string turn = R"({"rotate":[3,0,0,4],"solid":{"translate":["1/3",-2,"0.5"],"solid":)";
  for (std::string shape : {std::string(R"({"block":{"min":[-1,-1,-1],"max":[1,1,1]}})"),
                            std::string(R"({"prism":{"base":[[0,0],[2,0],[1,1]],"z":[0,"0.5"]}})"),
                            std::string(R"({"hull":[[0,0,0],[1,0,0],[0,1,0],[0,0,1],["1/2","1/3","1/7"]]})"),
                            std::string(R"({"convex":[[1,1,1,-1],[1,1,-1,-1],[1,-1,1,-1],[1,-1,-1,-1],[-1,1,1,-1],[-1,1,-1,-1],[-1,-1,1,-1],[-1,-1,-1,-1]]})"),
                            std::string(R"({"halfspace":[-2,0,0,1]})"), std::string(R"({"halfspace":[1,1,0,-1]})")}) {
    for (const std::string& placed : {shape, turn + shape + "}}"}) {
      Scene scene = scene_with(placed);
      Box<Q, 3> quick = Model_builder<Rational_kernel>(Rational_kernel()).primitive_box(scene.objects[0].shape);
      Box<Q, 3> built = model_of(placed).primitives[0].box;
      for (int a = 0; a < 3; ++a) {
        BOOST_TEST((quick.has_lo[a] == built.has_lo[a] && quick.has_hi[a] == built.has_hi[a]), placed << " axis " << a);
        if (quick.has_lo[a] && built.has_lo[a]) BOOST_TEST(quick.lo[a] == built.lo[a], placed << " axis " << a);
        if (quick.has_hi[a] && built.has_hi[a]) BOOST_TEST(quick.hi[a] == built.hi[a], placed << " axis " << a);
      }
    }
  }
  Scene turned = scene_with(R"({"rotate":[3,0,0,4],"solid":{"block":{"min":[-1,-1,-1],"max":[1,1,1]}}})");
  check_box(Model_builder<Rational_kernel>(Rational_kernel()).primitive_box(turned.objects[0].shape),
            {Q(-31, 25), Q(-31, 25), Q(-1)}, {Q(31, 25), Q(31, 25), Q(1)});
}

// The reader makes a rotation's matrix once (Solid::constructed), and the
// rational model read from it is the one computed from q: the same planes
// and vertices, number for number.
BOOST_AUTO_TEST_CASE(rotate_reads_its_exact_matrix)
{
  Scene scene = scene_with(R"({"rotate":[7,-1,5,2],"solid":{"prism":{"base":[[0,0],[2,0],[1,1]],"z":[0,"0.5"]}}})");
  const Solid& rotate = scene.objects[0].shape;
  auto R = rotation_matrix(Q(7), Q(-1), Q(5), Q(2));
  BOOST_TEST_REQUIRE(rotate.constructed.size() == 9u);
  for (int i = 0; i < 9; ++i) BOOST_TEST(rotate.constructed[static_cast<std::size_t>(i)] == R[i / 3][i % 3]);
  Solid computed = rotate;
  computed.constructed.clear();
  Rational_kernel k;
  Csg_model<Q> read = Model_builder<Rational_kernel>(k).build(rotate), made = Model_builder<Rational_kernel>(k).build(computed);
  BOOST_TEST(read.primitives[0].planes == made.primitives[0].planes);
  BOOST_TEST(read.primitives[0].vertices == made.primitives[0].vertices);
}

BOOST_AUTO_TEST_CASE(halfspace_box_is_omega_unless_axis_aligned)
{
  auto slanted = model_of(R"({"intersection":[{"halfspace":[1,1,0,-1]},{"block":{"min":[0,0,0],"max":[1,1,1]}}]})");
  BOOST_TEST(!slanted.primitives[0].box.has_hi[0]);
  BOOST_TEST(!slanted.primitives[0].box.has_lo[0]);
  auto axis = model_of(R"({"intersection":[{"halfspace":[-2,0,0,1]},{"block":{"min":[0,0,0],"max":[1,1,1]}}]})");
  BOOST_TEST(axis.primitives[0].box.has_lo[0]);
  BOOST_TEST(axis.primitives[0].box.lo[0] == Q(1, 2));
  BOOST_TEST(!axis.primitives[0].box.has_hi[0]);
}

BOOST_AUTO_TEST_CASE(motion_displacement_is_continuous_with_zero_at_zero)
{
  Rational_kernel k;
  Motion m = parse_motion("vel 1 0 0 until -2 rest until 0 vel 0 1 2 until 5 vel -1 -1 0 until 7 rest", "motion");
  auto p = Motion_path<Q>::build(k, m);
  BOOST_TEST(p.displacement(Q(0)) == (Vector3<Q>{Q(0), Q(0), Q(0)}));
  for (std::size_t i = 0; i < p.times.size(); ++i) {
    const Q& T = p.times[i];
    for (int a = 0; a < 3; ++a)
      BOOST_TEST(p.velocity[i][a] * T + p.offset[i][a] == p.velocity[i + 1][a] * T + p.offset[i + 1][a]);
  }
  BOOST_TEST(p.displacement(Q(5)) == (Vector3<Q>{Q(0), Q(5), Q(10)}));
  BOOST_TEST(p.displacement(Q(6)) == (Vector3<Q>{Q(-1), Q(4), Q(10)}));
  BOOST_TEST(p.displacement(Q(100)) == (Vector3<Q>{Q(-2), Q(3), Q(10)}));
  BOOST_TEST(p.displacement(Q(-3)) == (Vector3<Q>{Q(-1), Q(0), Q(0)}));   // vel 1 before -2
}

BOOST_AUTO_TEST_CASE(double_model_reads_rounded_numbers)
{
  Double_kernel k;
  auto m = Scene_model<Double_kernel>::build(k, scene_with(R"({"block":{"min":["0.1",0,0],"max":["1/3",1,1]}})"));
  BOOST_TEST(m.objects[0].csg.primitives[0].box.lo[0] == 0.1);
  BOOST_TEST(m.objects[0].csg.primitives[0].box.hi[0] == 1.0 / 3.0);
}

// Corners (Primitive::corners): the points where four or more planes of a
// primitive meet, found exactly by validation. Checked against the planes:
// every listed plane is zero at the point, and no other plane is.
static void check_corner(const Primitive<Q>& p, const std::vector<int>& corner)
{
  BOOST_TEST_REQUIRE(corner.size() >= 4u);
  // The point: the first three planes' meeting point, by Cramer's rule.
  Vector3<Q> v = vertex_of(p.planes[corner[0]], p.planes[corner[1]], p.planes[corner[2]]);
  for (std::size_t i = 0; i < p.planes.size(); ++i) {
    const auto& h = p.planes[i];
    bool listed = std::find(corner.begin(), corner.end(), static_cast<int>(i)) != corner.end();
    BOOST_TEST((h[0] * v[0] + h[1] * v[1] + h[2] * v[2] + h[3] == Q(0)) == listed);
  }
}

BOOST_AUTO_TEST_CASE(square_pyramid_has_its_apex_as_a_corner)
{
  // Four side facets meet at the apex; the base corners have three planes.
  auto m = model_of(R"({"hull":[[0,0,0],[2,0,0],[2,2,0],[0,2,0],["1/3","1","5/7"]]})");
  const auto& p = m.primitives[0];
  BOOST_TEST(p.planes.size() == 5u);
  BOOST_TEST_REQUIRE(p.corners.size() == 1u);
  BOOST_TEST(p.corners[0].size() == 4u);
  check_corner(p, p.corners[0]);
}

BOOST_AUTO_TEST_CASE(octahedron_has_six_corners)
{
  std::string planes;
  for (int a : {-1, 1})
    for (int b : {-1, 1})
      for (int c : {-1, 1})
        planes += (planes.empty() ? "" : ",") + std::string("[") + std::to_string(a) + "," + std::to_string(b) + "," +
                  std::to_string(c) + ",-1]";
  auto m = model_of("{\"convex\":[" + planes + "]}");
  const auto& p = m.primitives[0];
  BOOST_TEST_REQUIRE(p.corners.size() == 6u);
  for (const auto& c : p.corners) check_corner(p, c);
  // A block has none: three planes at each of its corners.
  BOOST_TEST(model_of(R"({"hull":[[0,0,0],[1,0,0],[0,1,0],[1,1,0],[0,0,1],[1,0,1],[0,1,1],[1,1,1]]})")
                 .primitives[0].corners.empty());
}

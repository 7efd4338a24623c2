#define BOOST_TEST_MODULE model
#include <boost/test/unit_test.hpp>

#include "model/Extrusion.h"
#include "model/Point_classifier.h"
#include "model/Scene_model.h"
#include "search/S_bounds.h"
#include "exact/Interval_kernel.h"
#include "exact/Rational_kernel.h"
#include "float/Double_kernel.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"
#include <functional>

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

// A block under a translation takes its box from its corners min and max
// (Model_builder::primitive) instead of the min and max over all eight:
// the same numbers in every kernel, bit for bit, because rounding is
// monotone. Decimal sides (0.1, 0.3) make the intervals wide and the
// doubles rounded; exactly, the box is [min + d, max + d].
template <class K>
static void check_block_box_is_corners_box()
{
  using FT = typename K::FT;
  K k;
  Scene scene = scene_with(
      R"({"translate":["0.1","-0.3",2],"solid":{"block":{"min":["-0.7","0.1","0.3"],"max":["0.2","0.3","1.1"]}}})");
  CGAL::Protect_FPU_rounding<std::is_same_v<K, Interval_kernel>> protect;   // what the interval kernel needs
  Primitive<FT> p = Scene_model<K>::build(k, scene).objects[0].csg.primitives[0];
  BOOST_TEST_REQUIRE(p.vertices.size() == 8u);
  auto same = [](const FT& x, const FT& y) {
    if constexpr (std::is_same_v<FT, Interval>) return x.inf() == y.inf() && x.sup() == y.sup();
    else return x == y;
  };
  for (int a = 0; a < 3; ++a) {
    FT lo = p.vertices[0][a], hi = p.vertices[0][a];
    for (const auto& v : p.vertices) {
      lo = Number_ops<FT>::lower(lo, v[a]);
      hi = Number_ops<FT>::upper(hi, v[a]);
    }
    BOOST_TEST_REQUIRE((p.box.has_lo[a] && p.box.has_hi[a]));
    BOOST_TEST(same(p.box.lo[a], lo), "axis " << a);
    BOOST_TEST(same(p.box.hi[a], hi), "axis " << a);
  }
}

BOOST_AUTO_TEST_CASE(translated_block_box_is_its_corners_box_in_every_kernel)
{
  check_block_box_is_corners_box<Rational_kernel>();
  check_block_box_is_corners_box<Double_kernel>();
  check_block_box_is_corners_box<Interval_kernel>();
  check_box(model_of(R"({"translate":["0.1","-0.3",2],"solid":{"block":{"min":["-0.7","0.1","0.3"],)"
                     R"("max":["0.2","0.3","1.1"]}}})")
                .primitives[0]
                .box,
            {Q(-3, 5), Q(-1, 5), Q(23, 10)}, {Q(3, 10), Q(0), Q(31, 10)});
}

// is_generic_inside decides a one-primitive object by its planes' signs
// alone; the block [0, 1/2] x [-1, 1] x [1/3, 2] is strictly inside
// exactly where each coordinate is strictly between its bounds. Points on
// a grid through every face (and outside) are held against that rule and
// against Plane_sides, which every many-primitive object still takes.
BOOST_AUTO_TEST_CASE(one_primitive_membership_is_its_planes_signs)
{
  Rational_kernel k;
  Scene scene = scene_with(R"({"block":{"min":[0,-1,"1/3"],"max":["1/2",1,2]}})");
  Scene_model<Rational_kernel> model = Scene_model<Rational_kernel>::build(k, scene);
  const Csg_model<Q>& csg = model.objects[0].csg;
  BOOST_TEST_REQUIRE(csg.nodes.size() == 1u);
  const std::array<Q, 3> lo{Q(0), Q(-1), Q(1, 3)}, hi{Q(1, 2), Q(1), Q(2)};
  const std::vector<Q> steps{Q(-1), Q(0), Q(1, 4), Q(1, 3), Q(1, 2), Q(1), Q(2), Q(3)};
  int inside = 0, total = 0;
  for (const Q& x : steps)
    for (const Q& y : steps)
      for (const Q& z : steps) {
        Vector4<Q> g{x, y, z, Q(1)};
        bool want = true;
        for (int a = 0; a < 3; ++a) want = want && lo[a] < g[a] && g[a] < hi[a];
        bool got = is_generic_inside(k, model, 0, g);
        BOOST_TEST(got == want, "(" << x << ", " << y << ", " << z << ")");
        BOOST_TEST(got == Plane_sides<Q>(k, csg, {x, y, z}).generic_inside(csg));
        inside += got;
        ++total;
      }
  BOOST_TEST(inside == 16);   // x in {1/4, 1/3}, y in {0, 1/4, 1/3, 1/2}, z in {1/2, 1}
  BOOST_TEST(total == 512);
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
// by cos = -7/25, sin = 24/25 reach +-31/25). Under a turn about z and
// under one about no axis (every entry of R non-zero: a prism's box is
// made from its base and its two heights apart, Model_builder::prism_box).
BOOST_AUTO_TEST_CASE(primitive_box_is_the_models_box)
{
  const std::string turn = R"({"rotate":[3,0,0,4],"solid":{"translate":["1/3",-2,"0.5"],"solid":)";
  const std::string skew = R"({"rotate":[1,2,3,4],"solid":{"translate":["1/3",-2,"0.5"],"solid":)";
  for (std::string shape : {std::string(R"({"block":{"min":[-1,-1,-1],"max":[1,1,1]}})"),
                            std::string(R"({"prism":{"base":[[0,0],[2,0],[1,1]],"z":[0,"0.5"]}})"),
                            std::string(R"({"hull":[[0,0,0],[1,0,0],[0,1,0],[0,0,1],["1/2","1/3","1/7"]]})"),
                            std::string(R"({"convex":[[1,1,1,-1],[1,1,-1,-1],[1,-1,1,-1],[1,-1,-1,-1],[-1,1,1,-1],[-1,1,-1,-1],[-1,-1,1,-1],[-1,-1,-1,-1]]})"),
                            std::string(R"({"halfspace":[-2,0,0,1]})"), std::string(R"({"halfspace":[1,1,0,-1]})")}) {
    for (const std::string& placed : {shape, turn + shape + "}}", skew + shape + "}}"}) {
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

// build_boxes: the tree of build with each primitive's box alone, so the
// S-bounds settled on it are the model's (the rational region stage reads
// only them, exact/Exact_span.h). A union of every primitive kind, placed
// by a translation (the box moved as a whole), a rotation and neither; and
// one hand-derived box: the 3-4-5 turn of the unit cube, translated.
// A union of every primitive kind, placed by a translation, a rotation and
// neither, minus a turned and moved block: the trees below are held to
// build's on it.
const std::string every_kind = R"({"difference":[{"union":[
      {"translate":["1/3",-2,"0.5"],"solid":{"block":{"min":[-1,-1,-1],"max":[1,1,1]}}},
      {"rotate":[3,0,0,4],"solid":{"prism":{"base":[[0,0],[2,0],[1,1]],"z":[0,"0.5"]}}},
      {"intersection":[{"hull":[[0,0,0],[1,0,0],[0,1,0],[0,0,1],["1/2","1/3","1/7"]]},{"halfspace":[1,1,0,-1]}]},
      {"translate":[2,0,0],"solid":{"convex":[[1,1,1,-1],[1,1,-1,-1],[1,-1,1,-1],[1,-1,-1,-1],[-1,1,1,-1],[-1,1,-1,-1],[-1,-1,1,-1],[-1,-1,-1,-1]]}}]},
    {"translate":[5,0,0],"solid":{"rotate":[3,0,0,4],"solid":{"block":{"min":[-1,-1,-1],"max":[1,1,1]}}}}]})";

void check_same_tree(const Csg_model<Q>& part, const Csg_model<Q>& built)
{
  BOOST_TEST_REQUIRE(part.nodes.size() == built.nodes.size());
  BOOST_TEST_REQUIRE(part.primitives.size() == built.primitives.size());
  for (std::size_t i = 0; i < built.nodes.size(); ++i) {
    BOOST_TEST((part.nodes[i].op == built.nodes[i].op && part.nodes[i].primitive == built.nodes[i].primitive &&
                part.nodes[i].children == built.nodes[i].children && part.nodes[i].parent == built.nodes[i].parent));
  }
}

void check_same_box(const Box<Q, 3>& b, const Box<Q, 3>& m, std::size_t i)
{
  BOOST_TEST((b.has_lo == m.has_lo && b.has_hi == m.has_hi), "primitive " << i);
  for (int a = 0; a < 3; ++a) {
    if (b.has_lo[a] && m.has_lo[a]) BOOST_TEST(b.lo[a] == m.lo[a], "primitive " << i << " axis " << a);
    if (b.has_hi[a] && m.has_hi[a]) BOOST_TEST(b.hi[a] == m.hi[a], "primitive " << i << " axis " << a);
  }
}

BOOST_AUTO_TEST_CASE(boxes_only_tree_is_the_models)
{
  const std::string& shape = every_kind;
  Scene scene = scene_with(shape);
  Rational_kernel k;
  Csg_model<Q> built = model_of(shape), boxes = Model_builder<Rational_kernel>(k).build_boxes(scene.objects[0].shape);
  check_same_tree(boxes, built);
  for (std::size_t i = 0; i < built.primitives.size(); ++i) {
    BOOST_TEST((boxes.primitives[i].planes.empty() && boxes.primitives[i].vertices.empty()));
    check_same_box(boxes.primitives[i].box, built.primitives[i].box, i);
  }
  Check_stats ignored;
  auto settled_boxes = settled_bounds(k, boxes, ignored, true), settled_model = settled_bounds(k, built, ignored, true);
  BOOST_TEST_REQUIRE(settled_boxes.size() == settled_model.size());
  for (std::size_t i = 0; i < settled_boxes.size(); ++i) {
    BOOST_TEST(settled_boxes[i].empty == settled_model[i].empty, "node " << i);
    for (int a = 0; a < 3; ++a) {
      BOOST_TEST(settled_boxes[i].has_lo[a] == settled_model[i].has_lo[a]);
      if (settled_boxes[i].has_lo[a]) BOOST_TEST(settled_boxes[i].lo[a] == settled_model[i].lo[a]);
      BOOST_TEST(settled_boxes[i].has_hi[a] == settled_model[i].has_hi[a]);
      if (settled_boxes[i].has_hi[a]) BOOST_TEST(settled_boxes[i].hi[a] == settled_model[i].hi[a]);
    }
  }
  // The cube turned by q = (3, 0, 0, 4) reaches 31/25 = (7 + 24)/25 along
  // x and y (|R| rows: 7/25, 24/25), then moved 5 along x.
  check_box(boxes.primitives.back().box, {Q(5) - Q(31, 25), Q(-31, 25), Q(-1)}, {Q(5) + Q(31, 25), Q(31, 25), Q(1)});
}

// build_planes and build_vertices: the tree of build with each primitive's
// planes alone (what the exact run's plane tables and witnesses read,
// exact/Filtered_runner.h), and with its vertices and box alone (what
// completes that model into build's): together, build's primitives, number
// for number, and neither holds the other's part. Each kind is placed by a
// translation, a rotation, both and neither (every_kind).
BOOST_AUTO_TEST_CASE(planes_and_vertices_trees_are_the_models)
{
  Scene scene = scene_with(every_kind);
  Rational_kernel k;
  Csg_model<Q> built = model_of(every_kind), planes = Model_builder<Rational_kernel>(k).build_planes(scene.objects[0].shape),
               vertices = Model_builder<Rational_kernel>(k).build_vertices(scene.objects[0].shape);
  check_same_tree(planes, built);
  check_same_tree(vertices, built);
  for (std::size_t i = 0; i < built.primitives.size(); ++i) {
    const Primitive<Q>&p = planes.primitives[i], &v = vertices.primitives[i], &m = built.primitives[i];
    BOOST_TEST(!m.planes.empty());
    BOOST_TEST(p.planes == m.planes, "primitive " << i);
    BOOST_TEST((p.vertices.empty() && !p.box.has_lo[0] && !p.box.has_hi[0]), "primitive " << i);
    bool same_corners = p.corners && m.corners ? *p.corners == *m.corners : p.corners == m.corners;   // two readings
    BOOST_TEST((same_corners && p.path == m.path), "primitive " << i);
    BOOST_TEST(v.planes.empty(), "primitive " << i);
    BOOST_TEST(v.vertices == m.vertices, "primitive " << i);
    check_same_box(v.box, m.box, i);
  }
}

// placed_geometry (an object's convex-pair guide, search/Convex_guide.h): a
// one-primitive shape's planes and vertices, number for number build's, in
// rationals and in doubles, for each kind placed by a translation, a
// rotation, both and neither (the single primitives of every_kind, and each
// one bare).
template <class K>
void check_placed_geometry(const K& k, const Solid& shape, const std::string& where)
{
  Primitive<typename K::FT> placed = Model_builder<K>(k).placed_geometry(shape);
  Csg_model<typename K::FT> built = Model_builder<K>(k).build(shape);
  BOOST_TEST_REQUIRE(built.primitives.size() == 1u, where);
  BOOST_TEST(!placed.planes.empty(), where);
  BOOST_TEST((placed.planes == built.primitives[0].planes), where);
  BOOST_TEST((placed.vertices == built.primitives[0].vertices), where);
}

BOOST_AUTO_TEST_CASE(placed_geometry_is_the_models_primitive)
{
  Scene scene = scene_with(every_kind);
  const Solid& whole = scene.objects[0].shape;   // difference of (union of four) and one
  std::vector<const Solid*> singles{&whole.children[1]};
  for (const Solid& c : whole.children[0].children)
    if (c.kind != Solid::Kind::Intersection) singles.push_back(&c);
  for (const Solid& c : whole.children[0].children[2].children) singles.push_back(&c);   // a hull, a half-space
  std::size_t n = singles.size();
  for (std::size_t i = 0; i < n; ++i) {   // each bare too: no transform
    const Solid* s = singles[i];
    while (s->kind == Solid::Kind::Translate || s->kind == Solid::Kind::Rotate) s = &s->children[0];
    singles.push_back(s);
  }
  BOOST_TEST_REQUIRE(singles.size() == 12u);
  for (std::size_t i = 0; i < singles.size(); ++i) {
    check_placed_geometry(Rational_kernel(), *singles[i], "rational, solid " + std::to_string(i));
    check_placed_geometry(Double_kernel(0), *singles[i], "double, solid " + std::to_string(i));
  }
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

// The reader approximates every number of every solid once (numbers/
// Approximation.h), and the interval and double models read those; a
// number changed after reading (the shrinker changes scenes) is read from
// itself, never from the approximation of the number it replaced. A
// block's 1/3 changed to 2/3 after reading: the interval model must
// enclose 2/3 and the double model read it. Every solid of a tree is
// approximated, a rotation's exact matrix too. A hull's exact facet planes
// (Solid::constructed), each coefficient doubled after reading: the
// interval planes must enclose the new coefficients.
BOOST_AUTO_TEST_CASE(numbers_changed_after_reading_are_read_again)
{
  Scene scene = scene_with(R"({"block":{"min":[0,0,0],"max":["1/3",1,1]}})");
  Solid& block = scene.objects[0].shape;
  BOOST_TEST_REQUIRE(block.numbers_approximated.size() == block.numbers.size());
  BOOST_TEST(block.numbers_approximated[3].of(block.numbers[3]));
  Interval_kernel ik;
  auto hi_x = [&](const Scene& s) {
    CGAL::Protect_FPU_rounding<true> protect;
    return Scene_model<Interval_kernel>::build(ik, s).objects[0].csg.primitives[0].box.hi[0];
  };
  auto read = hi_x(scene);
  BOOST_TEST((Q(read.inf()) < Q(1, 3) && Q(1, 3) < Q(read.sup())));   // encloses 1/3, no double
  block.numbers[3] = Q(2, 3);
  auto changed = hi_x(scene);
  BOOST_TEST((Q(changed.inf()) < Q(2, 3) && Q(2, 3) < Q(changed.sup())));
  Double_kernel dk;
  BOOST_TEST(Scene_model<Double_kernel>::build(dk, scene).objects[0].csg.primitives[0].box.hi[0] == 2.0 / 3.0);

  // Every solid of the tree is approximated, the ones under others too.
  Scene tree = scene_with(R"({"union":[{"translate":["1/3",0,0],"solid":{"block":{"min":[0,0,0],"max":[1,1,1]}}},)"
                          R"({"rotate":[1,1,0,0],"solid":{"block":{"min":[0,0,0],"max":[1,1,1]}}}]})");
  std::function<void(const Solid&)> approximated = [&](const Solid& s) {
    BOOST_TEST(s.numbers_approximated.size() == s.numbers.size());
    BOOST_TEST(s.constructed_approximated.size() == s.constructed.size());
    for (std::size_t i = 0; i < s.numbers.size(); ++i) BOOST_TEST(s.numbers_approximated[i].of(s.numbers[i]));
    for (const Solid& c : s.children) approximated(c);
  };
  approximated(tree.objects[0].shape);
  BOOST_TEST(!tree.objects[0].shape.children[1].constructed.empty());   // the rotation's exact matrix

  Scene hull = scene_with(R"({"hull":[[0,0,0],[3,0,0],[0,3,0],[0,0,3]]})");
  Solid& h = hull.objects[0].shape;
  BOOST_TEST_REQUIRE(h.constructed_approximated.size() == h.constructed.size());
  for (Rational& c : h.constructed) c = c * Q(2);   // the same planes, scaled: every number another
  CGAL::Protect_FPU_rounding<true> protect;
  auto planes = Scene_model<Interval_kernel>::build(ik, hull).objects[0].csg.primitives[0].planes;
  BOOST_TEST_REQUIRE(planes.size() * 4 == h.constructed.size());
  for (std::size_t i = 0; i < h.constructed.size(); ++i) {
    const auto& x = planes[i / 4][i % 4];
    BOOST_TEST((Q(x.inf()) <= h.constructed[i] && h.constructed[i] <= Q(x.sup())), "coefficient " << i);
  }
}

// A motion's numbers are approximated by the reader as a solid's are, and
// read by the interval and double models (Motion_path::build) only for
// the numbers they were made from: a velocity and a time changed after
// reading are read from themselves, and so is a motion whose segments
// shift (its first segment dropped in code), where each index then holds
// the approximation of another number.
BOOST_AUTO_TEST_CASE(motion_numbers_changed_after_reading_are_read_again)
{
  Scene scene = scene_with(R"({"block":{"min":[0,0,0],"max":[1,1,1]}})", "vel 1/3 1/5 0 until 1/7 vel 1/9 0 1/11");
  Motion& m = scene.objects[0].motion;
  BOOST_TEST_REQUIRE(m.times_approximated.size() == 1u);
  BOOST_TEST_REQUIRE(m.velocities_approximated.size() == 6u);
  BOOST_TEST(m.times_approximated[0].of(m.times[0]));
  for (std::size_t i = 0; i < 6; ++i) BOOST_TEST(m.velocities_approximated[i].of(m.velocities[i / 3][i % 3]));
  Interval_kernel ik;
  Double_kernel dk;
  auto encloses = [](const CGAL::Interval_nt<false>& x, const Q& q) { return Q(x.inf()) < q && q < Q(x.sup()); };
  auto path = [&](const Scene& s) {
    CGAL::Protect_FPU_rounding<true> protect;
    return Scene_model<Interval_kernel>::build(ik, s).objects[0].motion;
  };
  Motion_path<CGAL::Interval_nt<false>> read = path(scene);
  BOOST_TEST(encloses(read.times[0], Q(1, 7)));
  BOOST_TEST(encloses(read.velocity[0][0], Q(1, 3)));
  BOOST_TEST(encloses(read.velocity[1][2], Q(1, 11)));

  m.velocities[0][0] = Q(2, 3);
  m.times[0] = Q(2, 7);
  Motion_path<CGAL::Interval_nt<false>> changed = path(scene);
  BOOST_TEST(encloses(changed.times[0], Q(2, 7)));
  BOOST_TEST(encloses(changed.velocity[0][0], Q(2, 3)));
  BOOST_TEST(encloses(changed.velocity[0][1], Q(1, 5)));   // unchanged, read from its approximation
  Motion_path<double> rounded = Scene_model<Double_kernel>::build(dk, scene).objects[0].motion;
  BOOST_TEST(rounded.times[0] == 2.0 / 7.0);
  BOOST_TEST(rounded.velocity[0][0] == 2.0 / 3.0);

  // The first segment dropped: velocity 0 is now (1/9, 0, 1/11), at the
  // indices of the approximations of 2/3, 1/5 and 0.
  m.times.clear();
  m.velocities.erase(m.velocities.begin());
  Motion_path<CGAL::Interval_nt<false>> shifted = path(scene);
  BOOST_TEST_REQUIRE(shifted.velocity.size() == 1u);
  BOOST_TEST(encloses(shifted.velocity[0][0], Q(1, 9)));
  BOOST_TEST(encloses(shifted.velocity[0][2], Q(1, 11)));
  BOOST_TEST(Scene_model<Double_kernel>::build(dk, scene).objects[0].motion.velocity[0][0] == 1.0 / 9.0);
}

// A path made again in place (Motion_path::rebuild, a prepared scene's
// moved object) holds what a new one holds, whatever it held before: more
// segments, fewer, negative times (offsets made outward from t = 0).
BOOST_AUTO_TEST_CASE(a_rebuilt_motion_path_is_a_new_one)
{
  const char* motions[] = {"vel 1/3 1/5 0 until -2 vel 1/9 0 1/11 until 7/2 vel 0 -1 2", "vel 3 0 -1/7", "rest",
                           "vel 1 2 3 until 5 vel -1/2 0 0"};
  Rational_kernel rk;
  Double_kernel dk;
  Motion_path<Q> exact;
  Motion_path<double> rounded;
  for (const char* text : motions) {
    Scene scene = scene_with(R"({"block":{"min":[0,0,0],"max":[1,1,1]}})", text);
    const Motion& m = scene.objects[0].motion;
    exact.rebuild(rk, m);
    rounded.rebuild(dk, m);
    Motion_path<Q> e = Motion_path<Q>::build(rk, m);
    Motion_path<double> d = Motion_path<double>::build(dk, m);
    BOOST_TEST((exact.times == e.times && exact.exact_times == e.exact_times), text);
    BOOST_TEST((exact.velocity == e.velocity && exact.offset == e.offset), text);
    BOOST_TEST((rounded.times == d.times && rounded.exact_times == d.exact_times), text);
    BOOST_TEST((rounded.velocity == d.velocity && rounded.offset == d.offset), text);
    BOOST_TEST(exact.velocity.size() == m.velocities.size(), text);
  }
}

// [tL, tH] is split at the breakpoints strictly inside it only: a motion
// whose velocity changes before tL, at tH or after it has the whole span,
// its ends the scene's own numbers; one inside splits it there, and the
// end's grid flag is its own (1/3 is no double).
BOOST_AUTO_TEST_CASE(sub_spans_split_only_at_breakpoints_inside_the_span)
{
  const std::string block = R"({"block":{"min":[0,0,0],"max":[1,1,1]}})";
  auto check_kernel = [&](const auto& k) {
    using K = std::decay_t<decltype(k)>;
    for (const char* outside : {"vel 1 0 0 until -2 vel 0 1 0 until 12 vel 0 0 1", "vel 1 0 0 until 10 vel 0 1 0",
                                "vel 1 0 0 until 0 vel 0 1 0", "rest"}) {
      Scene scene = scene_with(block, outside);
      Scene_model<K> model = Scene_model<K>::build(k, scene);
      for (const auto& spans : {model.sub_spans({0}), model.sub_spans({0, 1})}) {
        BOOST_TEST_REQUIRE(spans.size() == 1u, outside);
        BOOST_TEST((spans[0].exact_lo == &model.exact_t_lo && spans[0].exact_hi == &model.exact_t_hi), outside);
        BOOST_TEST((spans[0].lo_on_grid && spans[0].hi_on_grid), outside);
      }
    }
    Scene scene = scene_with(block, "vel 1 0 0 until -2 vel 0 1 0 until 1/3 vel 0 0 1 until 12 vel 1 1 1");
    Scene_model<K> model = Scene_model<K>::build(k, scene);
    auto spans = model.sub_spans({1, 0});
    BOOST_TEST_REQUIRE(spans.size() == 2u);
    BOOST_TEST((*spans[0].exact_lo == Q(0) && *spans[0].exact_hi == Q(1, 3)));
    BOOST_TEST((*spans[1].exact_lo == Q(1, 3) && *spans[1].exact_hi == Q(10)));
    BOOST_TEST((spans[0].lo_on_grid && !spans[0].hi_on_grid && !spans[1].lo_on_grid && spans[1].hi_on_grid));
  };
  check_kernel(Rational_kernel());
  CGAL::Protect_FPU_rounding<true> protect;
  check_kernel(Interval_kernel());
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
  BOOST_TEST_REQUIRE(p.corners);
  BOOST_TEST_REQUIRE(p.corners->size() == 1u);
  BOOST_TEST((*p.corners)[0].size() == 4u);
  check_corner(p, (*p.corners)[0]);
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
  BOOST_TEST_REQUIRE(p.corners);
  BOOST_TEST_REQUIRE(p.corners->size() == 6u);
  for (const auto& c : *p.corners) check_corner(p, c);
  // A block has none: three planes at each of its corners.
  BOOST_TEST(!model_of(R"({"hull":[[0,0,0],[1,0,0],[0,1,0],[1,1,0],[0,0,1],[1,0,1],[0,1,1],[1,1,1]]})")
                  .primitives[0]
                  .corners);
}

// A solid's corners are made once, by the reader, and every model of it
// (one per check and kernel) holds them: the same corners, not a copy,
// moved with the solid (a translated and a rotated pyramid).
BOOST_AUTO_TEST_CASE(models_share_the_solids_corners)
{
  const std::string pyramid = R"({"hull":[[0,0,0],[2,0,0],[2,2,0],[0,2,0],["1/3","1","5/7"]]})";
  Scene scene = scene_with(R"({"rotate":[1,1,0,0],"solid":{"translate":["1/3",0,0],"solid":)" + pyramid + "}}");
  const Solid& hull = scene.objects[0].shape.children[0].children[0];
  BOOST_TEST_REQUIRE(hull.corners);
  Rational_kernel rk;
  Interval_kernel ik;
  Double_kernel dk;
  Scene_model<Rational_kernel> model = Scene_model<Rational_kernel>::build(rk, scene);
  const Primitive<Q>& exact = model.objects[0].csg.primitives[0];
  BOOST_TEST(exact.corners == hull.corners);   // the same object
  check_corner(exact, (*exact.corners)[0]);     // and the moved planes still meet there
  CGAL::Protect_FPU_rounding<true> protect;
  BOOST_TEST(Scene_model<Interval_kernel>::build(ik, scene).objects[0].csg.primitives[0].corners == hull.corners);
  BOOST_TEST(Scene_model<Double_kernel>::build(dk, scene).objects[0].csg.primitives[0].corners == hull.corners);
}

// A table entry made alone (Extrusion::pair_entry, what a filter's
// rational lines read, exact/Exact_span.h) is pair_table's entry, and the
// groups made without planes (pair_groups) are pair_table's: every_kind
// moving against a block, sheared by each object's velocity in turn, in
// its own frames and in neither's.
BOOST_AUTO_TEST_CASE(table_entries_made_alone_are_the_pair_tables)
{
  Scene scene = scene_with(every_kind, "vel 1/3 -2 5/7");
  Rational_kernel k;
  Scene_model<Rational_kernel> model = Scene_model<Rational_kernel>::build(k, scene);
  const Time_span<Q> span = model.sub_spans({0, 1}).at(0);
  Moving_object<Q> A = moving_on(model, 0, span, {}), B = moving_on(model, 1, span, {});
  using E = Extrusion<Rational_kernel>;
  for (bool fitted : {false, true})
    for (std::array<bool, 3> frame : {std::array<bool, 3>{true, false, true}, std::array<bool, 3>{false, true, false}}) {
      Vector3<Q> shear = E::shear_of(A, B, frame, fitted);
      Motion_groups<Q> whole, alone;
      std::vector<Hyperplane4<Q>> table = E::pair_table(A, B, shear, frame, fitted, whole);
      E::pair_groups(A, B, shear, frame, fitted, alone);
      BOOST_TEST_REQUIRE(alone.of.size() == table.size());
      BOOST_TEST(alone.of == whole.of);
      BOOST_TEST(alone.corners == whole.corners);
      BOOST_TEST(alone.corner_count == whole.corner_count);
      BOOST_TEST(alone.corner_count > 0);   // the hull's and the convex solid's corners
      BOOST_TEST((alone.still == whole.still && alone.velocity == whole.velocity));
      for (std::size_t e = 0; e < table.size(); ++e) {
        Hyperplane4<Q> h = E::pair_entry(A, B, alone, e);
        BOOST_TEST((h.n == table[e].n && h.c == table[e].c), "entry " << e);
      }
      BOOST_CHECK_THROW(E::pair_entry(A, B, alone, table.size()), std::out_of_range);
    }
}

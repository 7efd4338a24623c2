#define BOOST_TEST_MODULE skeleton
#include <boost/test/unit_test.hpp>

#include "exact/Exact_instantiation.h"
#include "float/Double_instantiation.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"
#include <set>

using namespace clash4d;
using Point = std::array<std::string, 4>;

static Scene blocks(const std::string& b_min, const std::string& b_max, const std::string& motion)
{
  return read_scene(read_json_text(R"({"format":"clash4d-scene/1","time":[0,1],"objects":[
    {"name":"a","shape":{"block":{"min":[0,0,0],"max":[2,2,2]}}},
    {"name":"b","shape":{"block":{"min":)" + b_min + R"(,"max":)" + b_max + R"(}},"motion":")" + motion + R"("}]})"));
}

// The collision region is polygon(x, t) x square(y, z) with the square
// [0,2]^2 or [1,2]^2: a product of polygons has E1 V2 + V1 E2 edges, and its
// vertices are the products of the vertices.
static void check_product(const Skeleton_answer& a, const std::set<std::pair<std::string, std::string>>& polygon_xt,
                          const std::set<std::string>& square_side, std::size_t expected_edges)
{
  BOOST_TEST_REQUIRE(a.pairs.size() == 1u);
  BOOST_TEST(a.pairs[0].edges.size() == expected_edges);
  for (const auto& e : a.pairs[0].edges)
    for (const Point& p : e) {
      BOOST_TEST(polygon_xt.count({p[0], p[3]}) == 1u, p[0] << "," << p[3]);
      BOOST_TEST(square_side.count(p[1]) == 1u);
      BOOST_TEST(square_side.count(p[2]) == 1u);
    }
  std::set<Point> ends;
  for (const auto& e : a.pairs[0].edges) ends.insert(e.begin(), e.end());
  BOOST_TEST(ends.size() == polygon_xt.size() * 4);   // every vertex is an end
}

BOOST_AUTO_TEST_CASE(overlapping_static_blocks_give_a_tesseract)
{
  // [1,2]^3 x [0,1]: 4 * 2^3 = 32 edges, 16 vertices.
  Skeleton_answer a = skeleton_exact(blocks("[1,1,1]", "[3,3,3]", "rest"));
  check_product(a, {{"1", "0"}, {"2", "0"}, {"1", "1"}, {"2", "1"}}, {"1", "2"}, 32);
}

BOOST_AUTO_TEST_CASE(moving_block_gives_a_trapezoid_prism)
{
  // b = [1-t, 3-t] x [0,2]^2 meets a = [0,2]^3 in x in [1-t, 2]: the
  // trapezoid (1,0) (2,0) (2,1) (0,1) times the square [0,2]^2: 32 edges.
  for (bool exact : {true, false}) {
    Scene s = blocks("[1,0,0]", "[3,2,2]", "vel -1 0 0");
    Skeleton_answer a = exact ? skeleton_exact(s) : skeleton_double(s);
    check_product(a, {{"1", "0"}, {"2", "0"}, {"2", "1"}, {"0", "1"}}, {"0", "2"}, 32);
  }
}

BOOST_AUTO_TEST_CASE(velocity_change_is_a_true_vertex)
{
  // b stops at t = 1/2: the polygon is the pentagon (1,0) (2,0) (2,1)
  // (1/2,1) (1/2,1/2); 5 * 4 + 5 * 4 = 40 edges, 20 vertices.
  Skeleton_answer a = skeleton_exact(blocks("[1,0,0]", "[3,2,2]", "vel -1 0 0 until 1/2 rest"));
  check_product(a, {{"1", "0"}, {"2", "0"}, {"2", "1"}, {"1/2", "1"}, {"1/2", "1/2"}}, {"0", "2"}, 40);
}

BOOST_AUTO_TEST_CASE(touching_blocks_have_no_collision_region)
{
  BOOST_TEST(skeleton_exact(blocks("[2,0,0]", "[3,2,2]", "rest")).pairs.empty());
  BOOST_TEST(skeleton_exact(blocks("[3,0,0]", "[4,2,2]", "vel -1 0 0")).pairs.empty());   // touches at t = 1 = tH
}

#define BOOST_TEST_MODULE null_object_test
// Generate-and-test (search/Null_object_test.h, §4.2) through its public
// run(formula, region, goal), on plane tables and formulas built by hand:
// the 4D extrusions (equation (4)) of unit blocks that overlap, that only
// touch (regularised: no collision), single slabs and differences. A point
// found must be a certificate: strictly inside every half-space the formula
// needs and strictly inside the region (regularised-semantics items 1-3).
//
// CLASH4D_SEED overrides the seed of the random case, CLASH4D_STAGE_CASES the
// number of cases (a quarter of them here: each runs a whole conquer).
#include <boost/test/unit_test.hpp>

#include "search/Null_object_test.h"
#include "support/Stage_tests.h"

#include <algorithm>
#include <string>

using namespace clash4d;
using namespace clash4d::stage_tests;

namespace {

template <class FT>
using H = Hyperplane4<FT>;

// The six half-spaces of the block [lo, hi] (3D, n.x + d <= 0) moving with
// D(t) = v t, extruded by equation (4); appended to the table, indices
// returned.
template <class FT>
std::vector<std::uint32_t> add_block(std::vector<H<FT>>& table, std::array<FT, 3> lo, std::array<FT, 3> hi,
                                     Vector3<FT> v = {FT(0), FT(0), FT(0)})
{
  std::vector<std::uint32_t> out;
  Vector3<FT> o{FT(0), FT(0), FT(0)};
  for (int q = 0; q < 3; ++q) {
    Plane3<FT> below{FT(0), FT(0), FT(0), lo[q]}, above{FT(0), FT(0), FT(0), -hi[q]};
    below[q] = FT(-1);   // -x_q + lo_q <= 0
    above[q] = FT(1);    // x_q - hi_q <= 0
    for (const auto& p : {below, above}) {
      out.push_back(static_cast<std::uint32_t>(table.size()));
      table.push_back(extrude(p, v, o));
    }
  }
  return out;
}

template <class FT>
std::array<FT, 3> p3(long x, long y, long z)
{
  return {FT(x), FT(y), FT(z)};
}

template <class FT>
Box<FT, 4> region(std::array<long, 4> lo, std::array<long, 4> hi)
{
  Box<FT, 4> b;
  for (int a = 0; a < 4; ++a) b.set(a, FT(lo[a]), FT(hi[a]));
  return b;
}

// The leaves hs as one node of operator op.
void leaves(Formula::Builder& b, const std::vector<std::uint32_t>& hs, Formula::Op op)
{
  std::size_t mark = b.open();
  for (auto h : hs) b.leaf(h);
  b.close(op, mark);
}

Formula conjunction(const std::vector<std::uint32_t>& hs)
{
  Formula::Builder b;
  leaves(b, hs, Formula::Op::And);
  return b.finish();
}

template <class K>
struct Conquer {
  using FT = typename K::FT;
  K k;
  std::vector<H<FT>> table;
  Check_stats stats;
  Search_goal<FT> goal;

  bool run(const Formula& f, const Box<FT, 4>& r, bool earliest = false)
  {
    goal = Search_goal<FT>();
    goal.earliest = earliest;
    Null_object_test<K> gt(k, table, stats);
    gt.run(f, r, goal);
    return goal.found;
  }

  // The point found is a certificate: the formula holds with strict signs
  // (no leaf's plane through it) and it is strictly inside the region.
  void check_certificate(const Formula& f, const Box<FT, 4>& r, const std::string& where) const
  {
    const Vector4<FT>& p = goal.inside;
    for (const auto& t : f.code())
      if (t.op == Formula::Op::Leaf) BOOST_TEST(table[t.arg].value(p) != FT(0), where << ": on plane " << t.arg);
    Truth at_p = f.evaluate([&](std::uint32_t h) {
      FT v = table[h].value(p);
      return v < FT(0) ? Truth::True : v > FT(0) ? Truth::False : Truth::Unknown;
    });
    BOOST_TEST((at_p == Truth::True), where << ": the formula does not hold strictly at the point");
    for (int a = 0; a < 4; ++a) BOOST_TEST((r.lo[a] < p[a] && p[a] < r.hi[a]), where << ": outside the region, axis " << a);
  }
};

} // namespace

BOOST_AUTO_TEST_CASE_TEMPLATE(overlapping_moving_blocks_give_a_point_strictly_inside, K, Kernels)
{
  using FT = typename K::FT;
  Conquer<K> c;
  // A = [0,1]^3 moving with (1,0,0): by (4), -x + t <= 0 and x - t - 1 <= 0
  // (x in [t, t + 1]); B = [2,3] x [0,1]^2 at rest. Their y, z faces
  // coincide. A's x interval meets (2, 3) openly when t + 1 > 2 and t < 3:
  // the collision region is 1 < t < 3, max(2, t) < x < min(3, t + 1).
  auto a = add_block<FT>(c.table, p3<FT>(0, 0, 0), p3<FT>(1, 1, 1), {FT(1), FT(0), FT(0)});
  auto b = add_block<FT>(c.table, p3<FT>(2, 0, 0), p3<FT>(3, 1, 1));
  BOOST_TEST((c.table[a[0]].n == Vector4<FT>{FT(-1), FT(0), FT(0), FT(1)}));   // -x + t
  BOOST_TEST((c.table[a[1]].n == Vector4<FT>{FT(1), FT(0), FT(0), FT(-1)}));   // x - t - 1
  BOOST_TEST(c.table[a[1]].c == FT(-1));
  std::vector<std::uint32_t> both = a;
  both.insert(both.end(), b.begin(), b.end());
  Formula f = conjunction(both);
  Box<FT, 4> r = region<FT>({-1, -1, -1, 0}, {5, 2, 2, 4});
  BOOST_TEST_REQUIRE(c.run(f, r));
  c.check_certificate(f, r, "moving blocks");
  const auto& p = c.goal.inside;
  BOOST_TEST((FT(1) < p[3] && p[3] < FT(3)));
  BOOST_TEST((std::max(FT(2), p[3]) < p[0] && p[0] < std::min(FT(3), p[3] + FT(1))));
  BOOST_TEST(c.stats.lines > 0u);
  BOOST_TEST(c.stats.points_classified > 0u);

  // Earliest mode (§5): the region's closure starts at t = 1, where A's face
  // x = t + 1 reaches B's face x = 2; the contact point has t = 1, x = 2 and
  // y, z in [0, 1].
  BOOST_TEST_REQUIRE(c.run(f, r, true));
  c.check_certificate(f, r, "moving blocks, earliest");
  BOOST_TEST(c.goal.t_star == FT(1));
  BOOST_TEST(c.goal.contact[3] == FT(1));
  BOOST_TEST(c.goal.contact[0] == FT(2));
  for (int q : {1, 2}) BOOST_TEST((FT(0) <= c.goal.contact[q] && c.goal.contact[q] <= FT(1)));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(overlap_from_the_start_is_earliest_at_the_region_start, K, Kernels)
{
  using FT = typename K::FT;
  Conquer<K> c;
  // A = [0,2]^3 and B = [1,3]^3 at rest overlap in (1,2)^3 at every time; over
  // t in [1/2, 1] the earliest point of the closure is at t = 1/2 (the span's
  // start, a region face), with x, y, z in [1, 2].
  auto a = add_block<FT>(c.table, p3<FT>(0, 0, 0), p3<FT>(2, 2, 2));
  auto b = add_block<FT>(c.table, p3<FT>(1, 1, 1), p3<FT>(3, 3, 3));
  a.insert(a.end(), b.begin(), b.end());
  Formula f = conjunction(a);
  Box<FT, 4> r = region<FT>({-1, -1, -1, 0}, {4, 4, 4, 1});
  r.lo[3] = num<FT>(1, 2);
  BOOST_TEST_REQUIRE(c.run(f, r, true));
  c.check_certificate(f, r, "static overlap, earliest");
  BOOST_TEST(c.goal.t_star == num<FT>(1, 2));
  BOOST_TEST(c.goal.contact[3] == num<FT>(1, 2));
  for (int q = 0; q < 3; ++q) BOOST_TEST((FT(1) <= c.goal.contact[q] && c.goal.contact[q] <= FT(2)));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(blocks_touching_on_a_face_do_not_collide, K, Kernels)
{
  using FT = typename K::FT;
  Conquer<K> c;
  // A = [0,1]^3 and B = [1,2] x [0,1]^2, both at rest: they share the face
  // x = 1 at every time. Closed sets meet; the regularised intersection is
  // null (item 6): no generic point has x < 1 and x > 1.
  auto a = add_block<FT>(c.table, p3<FT>(0, 0, 0), p3<FT>(1, 1, 1));
  auto b = add_block<FT>(c.table, p3<FT>(1, 0, 0), p3<FT>(2, 1, 1));
  a.insert(a.end(), b.begin(), b.end());
  BOOST_TEST(!c.run(conjunction(a), region<FT>({-1, -1, -1, 0}, {3, 2, 2, 1})));
  BOOST_TEST(!c.run(conjunction(a), region<FT>({-1, -1, -1, 0}, {3, 2, 2, 1}), true));
  // Touching along an edge only (B = [1,2] x [1,2] x [0,1]): no point either.
  Conquer<K> e;
  auto ea = add_block<FT>(e.table, p3<FT>(0, 0, 0), p3<FT>(1, 1, 1));
  auto eb = add_block<FT>(e.table, p3<FT>(1, 1, 0), p3<FT>(2, 2, 1));
  ea.insert(ea.end(), eb.begin(), eb.end());
  BOOST_TEST(!e.run(conjunction(ea), region<FT>({-1, -1, -1, 0}, {3, 3, 2, 1})));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(blocks_touching_at_one_instant_do_not_collide, K, Kernels)
{
  using FT = typename K::FT;
  Conquer<K> c;
  // A = [0,1]^3 moving with (1,0,0), B = [2,3] x [0,1]^2 at rest: they touch
  // at t = 1 (x = 2) and overlap after. Over t in [0, 1] only the touch is in
  // the region: no point. Over t in [0, 3/2] the overlap 1 < t < 3/2 is.
  auto a = add_block<FT>(c.table, p3<FT>(0, 0, 0), p3<FT>(1, 1, 1), {FT(1), FT(0), FT(0)});
  auto b = add_block<FT>(c.table, p3<FT>(2, 0, 0), p3<FT>(3, 1, 1));
  a.insert(a.end(), b.begin(), b.end());
  Formula f = conjunction(a);
  BOOST_TEST(!c.run(f, region<FT>({-1, -1, -1, 0}, {5, 2, 2, 1})));
  Box<FT, 4> longer = region<FT>({-1, -1, -1, 0}, {5, 2, 2, 1});
  longer.hi[3] = num<FT>(3, 2);
  BOOST_TEST_REQUIRE(c.run(f, longer));
  c.check_certificate(f, longer, "after the touch");
  BOOST_TEST(FT(1) < c.goal.inside[3]);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(a_single_slab_or_halfspace_in_the_region_is_found, K, Kernels)
{
  using FT = typename K::FT;
  Conquer<K> c;
  // The slab 0 <= x <= 1 (-x <= 0, x - 1 <= 0) in [-1,2] x [0,1]^3: its
  // interior 0 < x < 1 meets the region's.
  c.table = {{{FT(-1), FT(0), FT(0), FT(0)}, FT(0)}, {{FT(1), FT(0), FT(0), FT(0)}, FT(-1)},
             {{FT(1), FT(0), FT(0), FT(0)}, num<FT>(-1, 2)},
             {{FT(-1), FT(0), FT(0), FT(0)}, FT(3)}, {{FT(1), FT(0), FT(0), FT(0)}, FT(-4)},
             {{FT(-1), FT(0), FT(0), FT(0)}, FT(2)}};
  Box<FT, 4> r = region<FT>({-1, 0, 0, 0}, {2, 1, 1, 1});
  Formula slab = conjunction({0, 1});
  BOOST_TEST_REQUIRE(c.run(slab, r));
  c.check_certificate(slab, r, "slab");
  BOOST_TEST((FT(0) < c.goal.inside[0] && c.goal.inside[0] < FT(1)));
  // One half-space, x <= 1/2: found (one plane and the region's faces).
  Formula half = conjunction({2});
  BOOST_TEST_REQUIRE(c.run(half, r));
  c.check_certificate(half, r, "half-space");
  // The slab 3 <= x <= 4 misses x <= 2: nothing.
  BOOST_TEST(!c.run(conjunction({3, 4}), r));
  // x >= 2 only touches the region's face x = 2: nothing.
  BOOST_TEST(!c.run(conjunction({5}), r));
  // x <= 4 holds on the whole region: found (no leaf plane crosses it).
  c.table.push_back({{FT(1), FT(0), FT(0), FT(0)}, FT(-4)});
  Formula all_of_it = conjunction({6});
  BOOST_TEST_REQUIRE(c.run(all_of_it, r));
  c.check_certificate(all_of_it, r, "everything");
}

BOOST_AUTO_TEST_CASE_TEMPLATE(leaf_planes_that_are_region_faces, K, Kernels)
{
  using FT = typename K::FT;
  Conquer<K> c;
  // The slab 0 <= x <= 1 over the region x in [0, 1]: both leaf planes are
  // faces of the region (the same plane, same orientation); the region's
  // interior is inside. x >= 1 over the same region is the complement of
  // its face x <= 1 (opposite orientation): only the face, nothing.
  c.table = {{{FT(-1), FT(0), FT(0), FT(0)}, FT(0)}, {{FT(1), FT(0), FT(0), FT(0)}, FT(-1)},
             {{FT(-2), FT(0), FT(0), FT(0)}, FT(2)}};
  Box<FT, 4> r = region<FT>({0, 0, 0, 0}, {1, 1, 1, 1});
  Formula slab = conjunction({0, 1});
  BOOST_TEST_REQUIRE(c.run(slab, r));
  c.check_certificate(slab, r, "slab = region");
  BOOST_TEST(!c.run(conjunction({2}), r));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(differences_are_found_only_where_they_have_interior, K, Kernels)
{
  using FT = typename K::FT;
  Conquer<K> c;
  // A = [0,2] x [0,1]^2 minus B = [0,1] x [-1,2]^2, both at rest: A and not B
  // is And(A's six leaves, Or(complements of B's six)) (Formula.h). The
  // difference is 1 < x < 2 (with 0 < y, z < 1).
  auto a = add_block<FT>(c.table, p3<FT>(0, 0, 0), p3<FT>(2, 1, 1));
  auto b = add_block<FT>(c.table, p3<FT>(0, -1, -1), p3<FT>(1, 2, 2));
  std::vector<std::uint32_t> not_b;
  for (auto h : b) {
    not_b.push_back(static_cast<std::uint32_t>(c.table.size()));
    c.table.push_back(c.table[h].complement());
  }
  Formula::Builder fb;
  std::size_t mark = fb.open();
  for (auto h : a) fb.leaf(h);
  leaves(fb, not_b, Formula::Op::Or);
  fb.close(Formula::Op::And, mark);
  Formula f = fb.finish();
  Box<FT, 4> r = region<FT>({-1, -2, -2, 0}, {3, 3, 3, 1});
  BOOST_TEST_REQUIRE(c.run(f, r));
  c.check_certificate(f, r, "A / B");
  BOOST_TEST((FT(1) < c.goal.inside[0] && c.goal.inside[0] < FT(2)));

  // A minus itself: every boundary point satisfies both non-strictly, but the
  // regularised difference is null, so nothing is found.
  Conquer<K> d;
  auto s = add_block<FT>(d.table, p3<FT>(0, 0, 0), p3<FT>(1, 1, 1));
  std::vector<std::uint32_t> not_s;
  for (auto h : s) {
    not_s.push_back(static_cast<std::uint32_t>(d.table.size()));
    d.table.push_back(d.table[h].complement());
  }
  Formula::Builder gb;
  std::size_t gm = gb.open();
  for (auto h : s) gb.leaf(h);
  leaves(gb, not_s, Formula::Op::Or);
  gb.close(Formula::Op::And, gm);
  BOOST_TEST(!d.run(gb.finish(), region<FT>({-1, -1, -1, 0}, {2, 2, 2, 1})));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(a_union_is_found_in_its_part_inside_the_region, K, Kernels)
{
  using FT = typename K::FT;
  Conquer<K> c;
  // (A or B) and C with A = [10,12] x [0,2]^2 (beyond the region's x <= 6),
  // B = [0,2]^3, C = [1,4] x [0,2]^2: only B and C overlap, in 1 < x < 2.
  auto a = add_block<FT>(c.table, p3<FT>(10, 0, 0), p3<FT>(12, 2, 2));
  auto b = add_block<FT>(c.table, p3<FT>(0, 0, 0), p3<FT>(2, 2, 2));
  auto cc = add_block<FT>(c.table, p3<FT>(1, 0, 0), p3<FT>(4, 2, 2));
  Formula::Builder fb;
  std::size_t top = fb.open();
  std::size_t either = fb.open();
  leaves(fb, a, Formula::Op::And);
  leaves(fb, b, Formula::Op::And);
  fb.close(Formula::Op::Or, either);
  for (auto h : cc) fb.leaf(h);
  fb.close(Formula::Op::And, top);
  Formula f = fb.finish();
  Box<FT, 4> r = region<FT>({-1, -1, -1, 0}, {6, 3, 3, 1});
  BOOST_TEST_REQUIRE(c.run(f, r));
  c.check_certificate(f, r, "union");
  BOOST_TEST((FT(1) < c.goal.inside[0] && c.goal.inside[0] < FT(2)));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(earliest_of_two_collisions_in_a_union, K, Kernels)
{
  using FT = typename K::FT;
  Conquer<K> c;
  // A = [0,1]^3 moving with (1,0,0) against (B or C), B = [4,5] x [0,1]^2,
  // C = [2,3] x [0,1]^2 at rest (B's leaves first). A meets C for
  // t + 1 > 2, t < 3: (1, 3); B for t + 1 > 4, t < 5: (3, 5). Over t in
  // [0, 5] the earliest is t = 1 (x = 2), whatever order the lines come in.
  auto a = add_block<FT>(c.table, p3<FT>(0, 0, 0), p3<FT>(1, 1, 1), {FT(1), FT(0), FT(0)});
  auto b = add_block<FT>(c.table, p3<FT>(4, 0, 0), p3<FT>(5, 1, 1));
  auto cc = add_block<FT>(c.table, p3<FT>(2, 0, 0), p3<FT>(3, 1, 1));
  Formula::Builder fb;
  std::size_t top = fb.open();
  for (auto h : a) fb.leaf(h);
  std::size_t either = fb.open();
  leaves(fb, b, Formula::Op::And);
  leaves(fb, cc, Formula::Op::And);
  fb.close(Formula::Op::Or, either);
  fb.close(Formula::Op::And, top);
  Formula f = fb.finish();
  Box<FT, 4> r = region<FT>({-1, -1, -1, 0}, {7, 2, 2, 5});
  BOOST_TEST_REQUIRE(c.run(f, r));
  c.check_certificate(f, r, "union, any");
  const FT& t = c.goal.inside[3];
  BOOST_TEST(((FT(1) < t && t < FT(3)) || (FT(3) < t && t < FT(5))));
  BOOST_TEST_REQUIRE(c.run(f, r, true));
  c.check_certificate(f, r, "union, earliest");
  BOOST_TEST(c.goal.t_star == FT(1));
  BOOST_TEST(c.goal.contact[0] == FT(2));
}

// Two random boxes with random velocities over [0, T]: they collide exactly
// when some t in (0, T) has, on every axis, (u - v) t strictly between
// b - alpha and beta - a (their open intervals overlap). The region holds
// both boxes for every t, so generate-and-test must agree.
BOOST_AUTO_TEST_CASE_TEMPLATE(random_moving_boxes_agree_with_interval_overlap, K, Kernels)
{
  using FT = typename K::FT;
  std::uint64_t seed = env_number("CLASH4D_SEED", 19900713ull) + 5, cases = env_number("CLASH4D_STAGE_CASES", 200) / 4 + 1;
  BOOST_TEST_MESSAGE("generate-and-test vs interval overlap, " << K::name() << ": seed " << seed << ", " << cases
                                                               << " pairs (CLASH4D_SEED, CLASH4D_STAGE_CASES / 4)");
  std::size_t collide = 0, contacts = 0;
  for (std::uint64_t i = 0; i < cases; ++i) {
    std::mt19937_64 rng(case_seed(seed, i));
    Conquer<K> c;
    std::array<FT, 3> a, al, b, be;
    Vector3<FT> u, v;
    for (int q = 0; q < 3; ++q) {
      long lo = pick(rng, 0, 3);
      a[q] = FT(lo), al[q] = FT(pick(rng, lo + 1, 4));
      lo = pick(rng, 0, 3);
      b[q] = FT(lo), be[q] = FT(pick(rng, lo + 1, 4));
      u[q] = FT(pick(rng, -1, 1));
      v[q] = FT(pick(rng, -1, 1));
    }
    FT T(pick(rng, 1, 3));
    auto ha = add_block<FT>(c.table, a, al, u);
    auto hb = add_block<FT>(c.table, b, be, v);
    ha.insert(ha.end(), hb.begin(), hb.end());
    Formula f = conjunction(ha);
    Box<FT, 4> r = region<FT>({-4, -4, -4, 0}, {8, 8, 8, 0});
    r.hi[3] = T;
    // The open times of overlap, by hand; closed: whether the closed boxes
    // meet (a contact when they meet without an open overlap).
    FT tl(0), th = T;
    bool meet = true, closed = true;
    for (int q = 0; q < 3; ++q) {
      FT w = u[q] - v[q], low = b[q] - al[q], high = be[q] - a[q];
      if (w == FT(0)) {
        meet = meet && low < FT(0) && FT(0) < high;
        closed = closed && low <= FT(0) && FT(0) <= high;
        continue;
      }
      FT t1 = low / w, t2 = high / w;
      tl = std::max(tl, std::min(t1, t2));
      th = std::min(th, std::max(t1, t2));
    }
    closed = closed && tl <= th;
    meet = meet && tl < th;
    collide += meet;
    contacts += closed && !meet;
    std::string where = "case " + std::to_string(i) + " (seed " + std::to_string(seed) + ")";
    BOOST_TEST(c.run(f, r) == meet, where);
    if (c.goal.found) {
      c.check_certificate(f, r, where);
      BOOST_TEST((tl < c.goal.inside[3] && c.goal.inside[3] < th), where);
    }
    // Earliest mode: the collision starts at tl, the inf of the open times.
    if (meet) {
      BOOST_TEST_REQUIRE(c.run(f, r, true), where << " earliest");
      c.check_certificate(f, r, where + " earliest");
      BOOST_TEST(c.goal.t_star == tl, where << " earliest");
    }
  }
  BOOST_TEST_MESSAGE(collide << " of " << cases << " pairs collide, " << contacts << " only touch");
  BOOST_TEST(collide > 0u);
  BOOST_TEST(contacts > 0u);   // the regularised boundary is exercised
}

// The exact decisions a filter asks of another kernel's conquer
// (exact/Interval_filter.h: improves, compare_cuts, zero_on_line), on
// planes whose answers follow by hand.
BOOST_AUTO_TEST_CASE_TEMPLATE(vertex_times_cut_orders_and_zeros_on_a_line, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  auto plane = [](long a, long b, long c, long d, long e) { return H<FT>{{FT(a), FT(b), FT(c), FT(d)}, FT(e)}; };
  // x = 1, y = 2, z = 3 and x + y + z + t = 10 meet at t = 4; as num / den
  // the sign of den may be either, the quotient is 4.
  std::array<FT, 2> t = meeting_time(plane(1, 0, 0, 0, -1), plane(0, 1, 0, 0, -2), plane(0, 0, 1, 0, -3),
                                     plane(1, 1, 1, 1, -10));
  BOOST_REQUIRE(k.sign(t[1]) != CGAL::ZERO);
  BOOST_TEST(k.sign(t[0] - FT(4) * t[1]) == CGAL::ZERO);
  // Four planes through one line meet in no point: den = 0.
  BOOST_TEST(k.sign(meeting_time(plane(1, 0, 0, 0, -1), plane(0, 1, 0, 0, -2), plane(0, 0, 1, 0, -3),
                                 plane(1, 1, 0, 0, -3))[1]) == CGAL::ZERO);
  // The line x = 1, y = 2, z = 3 (planes 0-2), oriented by the generalised
  // cross product of their normals: for e_x, e_y, e_z it is (0, 0, 0, M3)
  // with M3 = det(I3) = 1 (geometry/kernel_ft4.h), so time grows along it.
  // t = 4 (plane 3) and t = 5 (plane 4) cut it: t = 4 comes first. Plane 5, x + y = 3, contains it; plane 6, x = 2, is
  // parallel to it without containing it.
  std::vector<H<FT>> table{plane(1, 0, 0, 0, -1), plane(0, 1, 0, 0, -2), plane(0, 0, 1, 0, -3),
                           plane(0, 0, 0, 1, -4), plane(0, 0, 0, 2, -10), plane(1, 1, 0, 0, -3),
                           plane(1, 0, 0, 0, -2)};
  Check_stats stats;
  Null_object_test<K> g(k, table, stats);
  Plane_layout layout;
  for (long e = 0; e < 7; ++e) {
    layout.entry.push_back(e);
    layout.face.push_back(-1);
    layout.moves_along.push_back(0);
    layout.corners.emplace_back();
  }
  layout.first_face = 7;
  g.adopt(layout, region<FT>({0, 0, 0, 0}, {8, 8, 8, 8}));
  const std::array<std::size_t, 3> line{0, 1, 2};
  BOOST_TEST(g.cut_order(line, 3, 4) == CGAL::SMALLER);
  BOOST_TEST(g.cut_order(line, 4, 3) == CGAL::LARGER);
  BOOST_TEST(g.cut_order(line, 3, 3) == CGAL::EQUAL);
  BOOST_TEST(!g.zero_on_line(line, 3, true));
  BOOST_TEST(g.zero_on_line(line, 5, true));
  BOOST_TEST(g.zero_on_line(line, 5, false));
  BOOST_TEST(g.zero_on_line(line, 6, true));
  BOOST_TEST(!g.zero_on_line(line, 6, false));
}

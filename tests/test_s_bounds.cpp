#define BOOST_TEST_MODULE s_bounds
// The S-bound stage (search/S_bounds.h, §4.3): leaf boxes and Omega at
// branches, the Upward and Downward rules of figure 2 on small CSG trees,
// settle's fixpoint, and Appendix B's closed form for two moving boxes. Every
// expected value is worked out by hand beside its case.
//
// CLASH4D_SEED overrides the seed of the random cases, CLASH4D_STAGE_CASES
// their number.
#include <boost/test/unit_test.hpp>

#include "search/S_bounds.h"
#include "exact/Interval_kernel.h"
#include "support/Stage_tests.h"

#include <algorithm>
#include <string>

using namespace clash4d;
using namespace clash4d::stage_tests;

namespace {

template <class FT>
Box<FT, 3> box3(std::array<long, 3> lo, std::array<long, 3> hi)
{
  Box<FT, 3> b;
  for (int a = 0; a < 3; ++a) b.set(a, FT(lo[a]), FT(hi[a]));
  return b;
}

template <class FT>
void check_box(const Box<FT, 3>& b, std::array<long, 3> lo, std::array<long, 3> hi, const std::string& what)
{
  BOOST_TEST_REQUIRE(!b.empty, what << " is empty");
  for (int a = 0; a < 3; ++a) {
    BOOST_TEST_REQUIRE((b.has_lo[a] && b.has_hi[a]), what << " unbounded on axis " << a);
    BOOST_TEST(b.lo[a] == FT(lo[a]), what << " lo[" << a << "]");
    BOOST_TEST(b.hi[a] == FT(hi[a]), what << " hi[" << a << "]");
  }
}

// A CSG tree built by hand: parents before children, root 0.
template <class FT>
struct Tree {
  Csg_model<FT> m;
  int branch(Csg_node::Op op, int parent)
  {
    Csg_node n;
    n.op = op;
    return add(n, parent);
  }
  int leaf(const Box<FT, 3>& b, int parent)
  {
    Primitive<FT> p;
    p.box = b;
    m.primitives.push_back(p);
    Csg_node n;
    n.primitive = static_cast<int>(m.primitives.size()) - 1;
    return add(n, parent);
  }
  int add(Csg_node n, int parent)
  {
    n.parent = parent;
    m.nodes.push_back(n);
    int i = static_cast<int>(m.nodes.size()) - 1;
    if (parent >= 0) m.nodes[parent].children.push_back(i);
    return i;
  }
};

using Op = Csg_node::Op;

// One branch `op` over two leaves a and b.
template <class FT>
Tree<FT> two_leaves(Op op, const Box<FT, 3>& a, const Box<FT, 3>& b)
{
  Tree<FT> t;
  int root = t.branch(op, -1);
  t.leaf(a, root);
  t.leaf(b, root);
  return t;
}

} // namespace

// --- §4.3.1: initial bounds, Upward and Downward rules -----------------------

BOOST_AUTO_TEST_CASE_TEMPLATE(initial_puts_boxes_at_leaves_and_omega_at_branches, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  S_bounds<K> sb(k);
  Tree<FT> t;
  int u = t.branch(Op::Union, -1);
  t.leaf(box3<FT>({0, 0, 0}, {1, 1, 1}), u);
  int i = t.branch(Op::Intersection, u);
  t.leaf(box3<FT>({2, 0, 0}, {3, 1, 1}), i);
  t.leaf(Box<FT, 3>::whole(), i);   // a half-space primitive: Omega
  auto beta = sb.initial(t.m);
  BOOST_TEST_REQUIRE(beta.size() == 5u);
  // §4.3.1: "the bounds at the leaf nodes [are] supersets of the relevant
  // primitive shapes, and Omega elsewhere".
  for (int n : {0, 2, 4}) {
    BOOST_TEST(!beta[n].empty);
    for (int a = 0; a < 3; ++a) BOOST_TEST((!beta[n].has_lo[a] && !beta[n].has_hi[a]), "node " << n << " axis " << a);
  }
  check_box(beta[1], {0, 0, 0}, {1, 1, 1}, "leaf 1");
  check_box(beta[3], {2, 0, 0}, {3, 1, 1}, "leaf 3");
}

BOOST_AUTO_TEST_CASE_TEMPLATE(initial_leaf_without_interior_is_nothing, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  S_bounds<K> sb(k);
  Tree<FT> t;
  int u = t.branch(Op::Union, -1);
  t.leaf(box3<FT>({0, 0, 0}, {0, 1, 1}), u);   // flat: x in [0, 0], no interior
  t.leaf(box3<FT>({0, 0, 0}, {1, 1, 1}), u);
  auto beta = sb.initial(t.m);
  // Box.h has_no_interior: a regular set inside a flat box is empty.
  BOOST_TEST(beta[1].empty);
  BOOST_TEST(!beta[2].empty);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(union_of_two_blocks_goes_up_as_their_join, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  S_bounds<K> sb(k);
  Tree<FT> t;
  int u = t.branch(Op::Union, -1);
  t.leaf(box3<FT>({0, 0, 0}, {1, 1, 1}), u);
  t.leaf(box3<FT>({2, -1, 0}, {3, 1, 4}), u);
  auto beta = sb.initial(t.m);
  // Upward, union node: Omega meet (beta(L) join beta(R)); the join is the
  // coordinatewise min of the lows and max of the highs:
  // x [min(0,2), max(1,3)] = [0,3], y [min(0,-1), max(1,1)] = [-1,1],
  // z [min(0,0), max(1,4)] = [0,4].
  BOOST_TEST(sb.up(t.m, beta));
  check_box(beta[0], {0, -1, 0}, {3, 1, 4}, "union");
  // Downward: each leaf meets the root, which contains it: no change.
  BOOST_TEST(!sb.down(t.m, beta));
  check_box(beta[1], {0, 0, 0}, {1, 1, 1}, "leaf 1");
  check_box(beta[2], {2, -1, 0}, {3, 1, 4}, "leaf 2");
  // A second pass moves nothing: settle stops after it (2 passes).
  auto again = sb.initial(t.m);
  BOOST_TEST(sb.settle(t.m, again, 10) == 2);
  check_box(again[0], {0, -1, 0}, {3, 1, 4}, "settled union");
}

BOOST_AUTO_TEST_CASE_TEMPLATE(union_with_a_halfspace_stays_unbounded_where_it_is, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  S_bounds<K> sb(k);
  Tree<FT> t;
  int u = t.branch(Op::Union, -1);
  t.leaf(box3<FT>({0, 0, 0}, {1, 1, 1}), u);
  Box<FT, 3> below5 = Box<FT, 3>::whole();   // the half-space x <= 5
  below5.hi[0] = FT(5);
  below5.has_hi[0] = true;
  t.leaf(below5, u);
  auto beta = sb.initial(t.m);
  sb.up(t.m, beta);
  // join: a side stays bounded only when both are; x hi = max(1, 5) = 5,
  // every other side is unbounded (the half-space has no bound there).
  BOOST_TEST(beta[0].has_hi[0]);
  BOOST_TEST(beta[0].hi[0] == FT(5));
  BOOST_TEST(!beta[0].has_lo[0]);
  for (int a = 1; a < 3; ++a) BOOST_TEST((!beta[0].has_lo[a] && !beta[0].has_hi[a]));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(intersection_of_disjoint_blocks_is_empty_everywhere, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  S_bounds<K> sb(k);
  Tree<FT> t;
  int i = t.branch(Op::Intersection, -1);
  t.leaf(box3<FT>({0, 0, 0}, {1, 1, 1}), i);
  t.leaf(box3<FT>({2, 0, 0}, {3, 1, 1}), i);
  auto beta = sb.initial(t.m);
  // Upward, intersection: meet has x in [max(0,2), min(1,3)] = [2,1]: empty.
  BOOST_TEST(sb.up(t.m, beta));
  BOOST_TEST(beta[0].empty);
  // Downward: each leaf meet the empty root is empty (the whole tree is null).
  BOOST_TEST(sb.down(t.m, beta));
  BOOST_TEST(beta[1].empty);
  BOOST_TEST(beta[2].empty);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(intersection_of_blocks_touching_on_a_face_is_empty, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  S_bounds<K> sb(k);
  Tree<FT> t;
  int i = t.branch(Op::Intersection, -1);
  t.leaf(box3<FT>({0, 0, 0}, {1, 1, 1}), i);
  t.leaf(box3<FT>({1, 0, 0}, {2, 1, 1}), i);
  auto beta = sb.initial(t.m);
  // meet: x in [max(0,1), min(1,2)] = [1,1], a face without interior; the
  // regularised intersection is null (regularised-semantics item 2).
  sb.settle(t.m, beta, 10);
  BOOST_TEST(beta[0].empty);
  BOOST_TEST(beta[1].empty);
  BOOST_TEST(beta[2].empty);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(intersection_goes_up_as_meet_and_down_into_the_children, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  S_bounds<K> sb(k);
  Tree<FT> t = two_leaves(Op::Intersection, box3<FT>({0, 0, 0}, {2, 2, 2}), box3<FT>({1, -1, 1}, {3, 1, 3}));
  auto beta = sb.initial(t.m);
  // Upward: meet = x [max(0,1), min(2,3)] = [1,2], y [max(0,-1), min(2,1)] =
  // [0,1], z [max(0,1), min(2,3)] = [1,2].
  sb.up(t.m, beta);
  check_box(beta[0], {1, 0, 1}, {2, 1, 2}, "intersection");
  // Downward: child meet parent; both children shrink to the meet itself.
  BOOST_TEST(sb.down(t.m, beta));
  check_box(beta[1], {1, 0, 1}, {2, 1, 2}, "leaf 1");
  check_box(beta[2], {1, 0, 1}, {2, 1, 2}, "leaf 2");
}

// Downward, each child tightened on one side only: [0,2]^3 meet [1,3]^3 =
// [1,2]^3, so the first child moves only its lower sides and the second only
// its upper ones (a shrink must not take a bound whose one side already
// holds for the whole box, S_bounds::within).
BOOST_AUTO_TEST_CASE_TEMPLATE(children_shrink_on_one_side_only, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  S_bounds<K> sb(k);
  Tree<FT> t = two_leaves(Op::Intersection, box3<FT>({0, 0, 0}, {2, 2, 2}), box3<FT>({1, 1, 1}, {3, 3, 3}));
  auto beta = sb.initial(t.m);
  sb.up(t.m, beta);
  check_box(beta[0], {1, 1, 1}, {2, 2, 2}, "intersection");
  BOOST_TEST(sb.down(t.m, beta));
  check_box(beta[1], {1, 1, 1}, {2, 2, 2}, "leaf 1 (lower sides)");
  check_box(beta[2], {1, 1, 1}, {2, 2, 2}, "leaf 2 (upper sides)");
  BOOST_TEST(!sb.down(t.m, beta));   // settled: nothing moves again
}

BOOST_AUTO_TEST_CASE_TEMPLATE(difference_goes_up_as_its_left_bound, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  S_bounds<K> sb(k);
  Tree<FT> t = two_leaves(Op::Difference, box3<FT>({0, 0, 0}, {2, 2, 2}), box3<FT>({1, 1, 1}, {3, 3, 3}));
  auto beta = sb.initial(t.m);
  // Upward, '/' node: S = beta(L) = [0,2]^3 (the subtrahend cannot enlarge
  // it, and a box cannot express the hole).
  sb.up(t.m, beta);
  check_box(beta[0], {0, 0, 0}, {2, 2, 2}, "difference");
  // Downward: the subtrahend matters only inside the minuend's bound:
  // [1,3]^3 meet [0,2]^3 = [1,2]^3; the minuend is unchanged.
  sb.down(t.m, beta);
  check_box(beta[1], {0, 0, 0}, {2, 2, 2}, "minuend");
  check_box(beta[2], {1, 1, 1}, {2, 2, 2}, "subtrahend");
}

// Without S-bounds (--no-sbounds, §4.1's original procedure) each object is
// enclosed by its tree's box: every node the box of its children's (upward
// once), nothing narrowed downward, no S-bound pass counted. So a composite
// object of bounded primitives has a bounded root (a pair of two such
// objects needs no far bound).
BOOST_AUTO_TEST_CASE_TEMPLATE(without_s_bounds_each_node_is_its_childrens_box, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  Check_stats stats;
  // Intersection: the meet [1,2]^3 at the root, the leaves as they are
  // (S-bounds would narrow both to [1,2]^3, children_shrink_on_one_side_only).
  Tree<FT> meet = two_leaves(Op::Intersection, box3<FT>({0, 0, 0}, {2, 2, 2}), box3<FT>({1, 1, 1}, {3, 3, 3}));
  auto beta = settled_bounds(k, meet.m, stats, false);
  check_box(beta[0], {1, 1, 1}, {2, 2, 2}, "intersection");
  check_box(beta[1], {0, 0, 0}, {2, 2, 2}, "leaf 1");
  check_box(beta[2], {1, 1, 1}, {3, 3, 3}, "leaf 2");
  // Union: the join; difference: the minuend's box.
  Tree<FT> join = two_leaves(Op::Union, box3<FT>({0, 0, 0}, {1, 1, 1}), box3<FT>({2, -1, 0}, {3, 1, 4}));
  check_box(settled_bounds(k, join.m, stats, false)[0], {0, -1, 0}, {3, 1, 4}, "union");
  Tree<FT> cut = two_leaves(Op::Difference, box3<FT>({0, 0, 0}, {2, 2, 2}), box3<FT>({1, 1, 1}, {3, 3, 3}));
  auto diff = settled_bounds(k, cut.m, stats, false);
  check_box(diff[0], {0, 0, 0}, {2, 2, 2}, "difference");
  check_box(diff[2], {1, 1, 1}, {3, 3, 3}, "subtrahend, not narrowed");
  BOOST_TEST(stats.sbound_passes == 0u);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(difference_drops_a_disjoint_subtrahend_and_keeps_a_covered_minuend, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  S_bounds<K> sb(k);
  {
    Tree<FT> t;
    int d = t.branch(Op::Difference, -1);
    t.leaf(box3<FT>({0, 0, 0}, {1, 1, 1}), d);
    t.leaf(box3<FT>({5, 0, 0}, {6, 1, 1}), d);
    auto beta = sb.initial(t.m);
    sb.settle(t.m, beta, 10);
    // Subtrahend [5,6] x .. meet [0,1] x ..: x in [5,1], empty (pruned).
    check_box(beta[0], {0, 0, 0}, {1, 1, 1}, "difference");
    BOOST_TEST(beta[2].empty);
  }
  {
    Tree<FT> t;
    int d = t.branch(Op::Difference, -1);
    t.leaf(box3<FT>({0, 0, 0}, {1, 1, 1}), d);
    t.leaf(box3<FT>({-1, -1, -1}, {2, 2, 2}), d);
    auto beta = sb.initial(t.m);
    sb.settle(t.m, beta, 10);
    // The set is null ([0,1]^3 minus a cover) but S-bounds only bound: the
    // root keeps the left bound [0,1]^3 and the subtrahend shrinks to it.
    check_box(beta[0], {0, 0, 0}, {1, 1, 1}, "difference");
    check_box(beta[2], {0, 0, 0}, {1, 1, 1}, "subtrahend");
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(settle_needs_a_second_up_pass_when_down_empties_a_leaf, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  S_bounds<K> sb(k);
  Tree<FT> t;
  int root = t.branch(Op::Intersection, -1);   // 0
  int u = t.branch(Op::Union, root);           // 1
  t.leaf(box3<FT>({-1, -1, -1}, {3, 3, 3}), root);   // 2: C
  t.leaf(box3<FT>({0, 0, 0}, {2, 2, 2}), u);         // 3: A
  t.leaf(box3<FT>({6, 0, 0}, {8, 2, 2}), u);         // 4: B
  auto beta = sb.initial(t.m);
  // Pass 1. Up: U = A join B = [0,8]x[0,2]x[0,2]; root = U meet C =
  // [0,3]x[0,2]x[0,2]. Down: U = C = [0,3]x[0,2]x[0,2]; A unchanged; B meet U
  // has x in [6,3]: empty.
  // Pass 2. Up: U = A join (empty) = [0,2]^3, root = U meet C = [0,2]^3.
  // Down: C = [0,2]^3.
  // Pass 3 moves nothing, so settle returns 3.
  BOOST_TEST(sb.settle(t.m, beta, 10) == 3);
  check_box(beta[0], {0, 0, 0}, {2, 2, 2}, "root");
  check_box(beta[1], {0, 0, 0}, {2, 2, 2}, "union");
  check_box(beta[2], {0, 0, 0}, {2, 2, 2}, "C");
  check_box(beta[3], {0, 0, 0}, {2, 2, 2}, "A");
  BOOST_TEST(beta[4].empty);
  // A fixpoint: neither rule moves anything now.
  BOOST_TEST(!sb.up(t.m, beta));
  BOOST_TEST(!sb.down(t.m, beta));

  // With one pass allowed, settle stops after pass 1's state.
  auto one = sb.initial(t.m);
  BOOST_TEST(sb.settle(t.m, one, 1) == 1);
  check_box(one[0], {0, 0, 0}, {3, 2, 2}, "root after one pass");
  check_box(one[1], {0, 0, 0}, {3, 2, 2}, "union after one pass");
  BOOST_TEST(one[4].empty);
}

// --- Appendix B: the meet of two moving boxes ---------------------------------

namespace {

// Runs meet_moving on copies; A moves with D(t) = u t + oa, B with v t + ob.
template <class K>
struct Meet_case {
  using FT = typename K::FT;
  Box<FT, 3> a, b;
  Vector3<FT> u{}, v{}, oa{}, ob{};
  FT tl, th;
  bool alive = false;

  bool run(const K& k)
  {
    S_bounds<K> sb(k);
    typename S_bounds<K>::Moving_box ma{&a, &u, &oa}, mb{&b, &v, &ob};
    alive = sb.meet_moving(ma, mb, tl, th);
    return alive;
  }
};

template <class FT>
Vector3<FT> vec3(long x, long y, long z)
{
  return {FT(x), FT(y), FT(z)};
}

} // namespace

BOOST_AUTO_TEST_CASE_TEMPLATE(appendix_b_paper_example_gives_2x2x4x2, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  // §4.1's example with the sphere (radius 4, centre (5,5,5), velocity
  // (1,1,1)) replaced by its box [1,9]^3, and the cube of side 4 centred at
  // (44,54,5), velocity (0,0,1): [42,46]x[52,56]x[3,7]; span [0,64].
  Meet_case<K> c;
  c.a = box3<FT>({1, 1, 1}, {9, 9, 9});
  c.u = vec3<FT>(1, 1, 1);
  c.b = box3<FT>({42, 52, 3}, {46, 56, 7});
  c.v = vec3<FT>(0, 0, 1);
  c.tl = FT(0);
  c.th = FT(64);
  BOOST_TEST_REQUIRE(c.run(k));
  // Time: b - alpha <= (u - v) t <= beta - a per axis.
  //  x: 42 - 9 <= t <= 46 - 1, t in [33, 45];  y: 52 - 9 <= t <= 56 - 1,
  //  t in [43, 55];  z: u = v, -6 <= 0 <= 6 holds, no constraint.
  //  [0,64] meet [33,45] meet [43,55] = [43,45]: length 2 (the paper's 4th 2).
  BOOST_TEST(c.tl == FT(43));
  BOOST_TEST(c.th == FT(45));
  // Space, (v - u) t over [43, 45]: x, y: -t in [-45, -43]; z: 0.
  //  x: a' = max(1, 42 - 45) = 1, alpha' = min(9, 46 - 43) = 3;
  //     b' = max(42, 1 + 43) = 44, beta' = min(46, 9 + 45) = 46.
  //  y: a' = max(1, 52 - 45) = 7, alpha' = min(9, 56 - 43) = 9;
  //     b' = max(52, 1 + 43) = 52, beta' = min(56, 9 + 45) = 54.
  //  z: a' = max(1, 3 + 0) = 3, alpha' = min(9, 7 + 0) = 7; b' = 3, beta' = 7.
  // Widths 2 x 2 x 4 for either object: the paper's 2 x 2 x 4 x 2.
  check_box(c.a, {1, 7, 3}, {3, 9, 7}, "sphere's box");
  check_box(c.b, {44, 52, 3}, {46, 54, 7}, "cube");
}

BOOST_AUTO_TEST_CASE_TEMPLATE(appendix_b_boxes_that_never_meet_give_a_null_span, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  // A = [0,1] in x moving at 1, B = [10,11] at rest, span [0,5]:
  // 10 - 1 <= t <= 11 - 0 gives [9, 11], which misses [0, 5].
  Meet_case<K> c;
  c.a = box3<FT>({0, 0, 0}, {1, 1, 1});
  c.u = vec3<FT>(1, 0, 0);
  c.b = box3<FT>({10, 0, 0}, {11, 1, 1});
  c.v = vec3<FT>(0, 0, 0);
  c.tl = FT(0);
  c.th = FT(5);
  BOOST_TEST(!c.run(k));
  // Same but they meet only at the instant t = 9 = th: [9, 11] meet [0, 9]
  // is the point 9, no interior: touching is not a collision.
  Meet_case<K> d = c;
  d.th = FT(9);
  BOOST_TEST(!d.run(k));
  // Disjoint in y for all time (same y velocity 0): y [0,1] against [2,3].
  Meet_case<K> e = c;
  e.th = FT(20);
  e.b = box3<FT>({10, 2, 0}, {11, 3, 1});
  BOOST_TEST(!e.run(k));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(appendix_b_same_velocity_keeps_the_span_and_meets_in_3d, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  // Both move at (1, 2, 0). "If the objects have the same velocity, then the
  // temporal bound is unaffected, and the change in spatial bound is
  // equivalent to that for the three-dimensional S-bound system."
  Meet_case<K> c;
  c.a = box3<FT>({0, 0, 0}, {2, 2, 2});
  c.b = box3<FT>({1, -1, 1}, {3, 1, 3});
  c.u = c.v = vec3<FT>(1, 2, 0);
  c.tl = FT(-3);
  c.th = FT(7);
  BOOST_TEST_REQUIRE(c.run(k));
  BOOST_TEST(c.tl == FT(-3));
  BOOST_TEST(c.th == FT(7));
  // (v - u) t = 0: a' = max(a, b), alpha' = min(alpha, beta), the same for
  // b', beta': both become the 3D meet [1,2] x [0,1] x [1,2].
  check_box(c.a, {1, 0, 1}, {2, 1, 2}, "A");
  check_box(c.b, {1, 0, 1}, {2, 1, 2}, "B");
  // Same velocity, touching faces (x: alpha = 2 = b): b - alpha = 0 is not
  // < 0, so no interior at any time.
  Meet_case<K> d;
  d.a = box3<FT>({0, 0, 0}, {2, 2, 2});
  d.b = box3<FT>({2, 0, 0}, {4, 2, 2});
  d.u = d.v = vec3<FT>(1, 2, 0);
  d.tl = FT(-3);
  d.th = FT(7);
  BOOST_TEST(!d.run(k));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(appendix_b_negative_relative_velocity_with_offsets, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  // A = [10,11] in x moving at -1, given as the box [0,1] with offset 10;
  // B = [0,5] at rest, given as [-1,4] with offset 1. y, z overlap always.
  // Span [0, 7].
  Meet_case<K> c;
  c.a = box3<FT>({0, 0, 0}, {1, 1, 1});
  c.oa = vec3<FT>(10, 0, 0);
  c.u = vec3<FT>(-1, 0, 0);
  c.b = box3<FT>({-1, 0, 0}, {4, 1, 1});
  c.ob = vec3<FT>(1, 0, 0);
  c.tl = FT(0);
  c.th = FT(7);
  BOOST_TEST_REQUIRE(c.run(k));
  // x in world terms: a = 10, alpha = 11, b = 0, beta = 5, u - v = -1:
  // 0 - 11 <= -t <= 5 - 10, so 5 <= t <= 11; with [0, 7]: [5, 7].
  BOOST_TEST(c.tl == FT(5));
  BOOST_TEST(c.th == FT(7));
  // (v - u) t = t over [5, 7]: min 5, max 7.
  //  a' = max(10, 0 + 5) = 10, alpha' = min(11, 5 + 7) = 11: A unchanged.
  //  b' = max(0, 10 - 7) = 3, beta' = min(5, 11 - 5) = 5: B's x is [3, 5]
  //  (A sweeps [10 - 7, 11 - 5] = [3, 6] over [5, 7]), i.e. [2, 4] in B's
  //  own frame (offset 1).
  check_box(c.a, {0, 0, 0}, {1, 1, 1}, "A (own frame)");
  check_box(c.b, {2, 0, 0}, {4, 1, 1}, "B (own frame)");
}

BOOST_AUTO_TEST_CASE_TEMPLATE(appendix_b_bounds_an_unbounded_side, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  // A: x >= 0 only (a half-space's bound), moving at +1; B = [10,11] at rest.
  Meet_case<K> c;
  c.a = Box<FT, 3>::whole();
  c.a.lo[0] = FT(0);
  c.a.has_lo[0] = true;
  c.u = vec3<FT>(1, 0, 0);
  c.b = box3<FT>({10, 0, 0}, {11, 1, 1});
  c.tl = FT(0);
  c.th = FT(20);
  BOOST_TEST_REQUIRE(c.run(k));
  // alpha = +inf, so only (u - v) t <= beta - a: t <= 11; span [0, 11].
  BOOST_TEST(c.tl == FT(0));
  BOOST_TEST(c.th == FT(11));
  // (v - u) t = -t over [0, 11]: min -11, max 0.
  //  alpha' = beta + max = 11 + 0 = 11 (A at time t is [t, inf), and
  //  q <= 11 with t >= 0 gives q - t <= 11); a' = max(0, 10 - 11) = 0.
  //  y, z: A gains B's [0, 1] (same velocity 0 there).
  //  b' = max(10, 0 - 0) = 10; beta' stays 11 (alpha is infinite).
  check_box(c.a, {0, 0, 0}, {11, 1, 1}, "A");
  check_box(c.b, {10, 0, 0}, {11, 1, 1}, "B");

  // A: x <= 20 only, moving at -1 (negative u - v, so the inequality flips
  // on division); B = [10,11] at rest; span [0, 20].
  Meet_case<K> d;
  d.a = Box<FT, 3>::whole();
  d.a.hi[0] = FT(20);
  d.a.has_hi[0] = true;
  d.u = vec3<FT>(-1, 0, 0);
  d.b = box3<FT>({10, 0, 0}, {11, 1, 1});
  d.tl = FT(0);
  d.th = FT(20);
  BOOST_TEST_REQUIRE(d.run(k));
  // b - alpha <= (u - v) t: 10 - 20 <= -t, so t <= 10 (a = -inf: no lower
  // limit). Span [0, 10].
  BOOST_TEST(d.tl == FT(0));
  BOOST_TEST(d.th == FT(10));
  // (v - u) t = t over [0, 10]: a' = b + min = 10 + 0 = 10, alpha' =
  // min(20, 11 + 10) = 20 (B seen from A's frame is [10 + t, 11 + t]);
  // b' = 10 (a infinite), beta' = min(11, 20 - 0) = 11.
  check_box(d.a, {10, 0, 0}, {20, 1, 1}, "A moving left");
  check_box(d.b, {10, 0, 0}, {11, 1, 1}, "B");
}

// --- Random cases -----------------------------------------------------------

namespace {

// Strict membership of a point in a node (generic points only: off every
// face), with or without restricting each node to its bound.
template <class FT>
bool strictly_in(const Box<FT, 3>& b, const Vector3<FT>& p)
{
  if (b.empty) return false;
  for (int a = 0; a < 3; ++a) {
    if (b.has_lo[a] && !(b.lo[a] < p[a])) return false;
    if (b.has_hi[a] && !(p[a] < b.hi[a])) return false;
  }
  return true;
}

template <class FT>
bool member(const Csg_model<FT>& m, int n, const Vector3<FT>& p, const std::vector<Box<FT, 3>>* beta)
{
  const Csg_node& node = m.nodes[n];
  if (beta && !strictly_in((*beta)[n], p)) return false;
  switch (node.op) {
    case Op::Primitive: return strictly_in(m.primitives[node.primitive].box, p);
    case Op::Union:
      return std::any_of(node.children.begin(), node.children.end(), [&](int c) { return member(m, c, p, beta); });
    case Op::Intersection:
      return std::all_of(node.children.begin(), node.children.end(), [&](int c) { return member(m, c, p, beta); });
    case Op::Difference:
      if (!member(m, node.children[0], p, beta)) return false;
      for (std::size_t c = 1; c < node.children.size(); ++c)
        if (member(m, node.children[c], p, beta)) return false;
      return true;
  }
  return false;
}

template <class FT>
void random_tree(Tree<FT>& t, std::mt19937_64& rng, int depth, int parent)
{
  if (depth == 0 || pick(rng, 0, 3) == 0) {
    Box<FT, 3> b;
    for (int a = 0; a < 3; ++a) {
      long lo = pick(rng, 0, 7), hi = pick(rng, lo + 1, 8);
      b.set(a, FT(lo), FT(hi));
    }
    t.leaf(b, parent);
    return;
  }
  Op ops[3] = {Op::Union, Op::Intersection, Op::Difference};
  int n = t.branch(ops[pick(rng, 0, 2)], parent);
  long children = pick(rng, 2, 3);
  for (long c = 0; c < children; ++c) random_tree(t, rng, depth - 1, n);
}

} // namespace

// The S-bound property (§4.3.1): "the set given by each subtree need not be
// evaluated outside of its appropriate bound". Restricting every node to its
// settled bound must not change the root's membership at any generic point
// (half-integer points: every bound is an integer box). And bounds only shrink.
BOOST_AUTO_TEST_CASE_TEMPLATE(random_trees_keep_the_s_bound_property, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  S_bounds<K> sb(k);
  std::uint64_t seed = env_number("CLASH4D_SEED", 19900713ull), cases = env_number("CLASH4D_STAGE_CASES", 200);
  BOOST_TEST_MESSAGE("S-bound property, " << K::name() << ": seed " << seed << ", " << cases
                                          << " trees (CLASH4D_SEED, CLASH4D_STAGE_CASES)");
  std::size_t emptied = 0;
  for (std::uint64_t i = 0; i < cases; ++i) {
    std::mt19937_64 rng(case_seed(seed, i));
    Tree<FT> t;
    random_tree(t, rng, 3, -1);
    auto start = sb.initial(t.m), beta = start;
    int passes = sb.settle(t.m, beta, 100);
    BOOST_TEST(passes < 100, "case " << i << " (seed " << seed << ") did not settle");
    BOOST_TEST(!sb.up(t.m, beta));
    BOOST_TEST(!sb.down(t.m, beta));
    emptied += beta[0].empty;
    for (std::size_t n = 0; n < beta.size(); ++n) {
      // Only shrinks: the settled bound is its own meet with the initial one.
      Box<FT, 3> m = meet(beta[n], start[n]);
      BOOST_TEST(same_on_grid(k, sb.normalised(m), beta[n]), "case " << i << " node " << n << " grew");
    }
    for (int s = 0; s < 60; ++s) {
      Vector3<FT> p;
      for (int a = 0; a < 3; ++a) p[a] = num<FT>(2 * pick(rng, -1, 8) + 1, 2);
      bool plain = member<FT>(t.m, 0, p, nullptr), bounded = member<FT>(t.m, 0, p, &beta);
      BOOST_TEST(plain == bounded, "case " << i << " (seed " << seed << ") point " << p[0] << "," << p[1] << "," << p[2]);
    }
  }
  BOOST_TEST_MESSAGE(emptied << " of " << cases << " trees proved null by S-bounds alone");
}

// Appendix B's closed form against the paper's unsimplified definitions, on
// random boxes and velocities in {-1, 0, 1} (so every quotient is a half,
// exact in doubles). The span: the open t where, on every axis,
// max(ut + a, vt + b) < min(ut + alpha, vt + beta). The bounds:
// a' = min(q_l - u t_l, q_h - u t_h), alpha' = max(Q_l - u t_l, Q_h - u t_h)
// with q = max(ut + a, vt + b), Q = min(ut + alpha, vt + beta), and the same
// with v for b', beta'.
BOOST_AUTO_TEST_CASE_TEMPLATE(random_moving_boxes_match_the_unsimplified_form, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  std::uint64_t seed = env_number("CLASH4D_SEED", 19900713ull) + 1, cases = env_number("CLASH4D_STAGE_CASES", 200) * 5;
  BOOST_TEST_MESSAGE("Appendix B closed form, " << K::name() << ": seed " << seed << ", " << cases << " pairs");
  std::size_t alive = 0;
  for (std::uint64_t i = 0; i < cases; ++i) {
    std::mt19937_64 rng(case_seed(seed, i));
    Meet_case<K> c;
    std::array<FT, 3> a, al, b, be, u, v;
    for (int q = 0; q < 3; ++q) {
      long lo = pick(rng, -6, 5), hi = pick(rng, lo + 1, 6);
      a[q] = FT(lo), al[q] = FT(hi);
      lo = pick(rng, -6, 5), hi = pick(rng, lo + 1, 6);
      b[q] = FT(lo), be[q] = FT(hi);
      u[q] = FT(pick(rng, -1, 1));
      v[q] = FT(pick(rng, -1, 1));
      c.oa[q] = FT(pick(rng, -2, 2));
      c.ob[q] = FT(pick(rng, -2, 2));
      c.a.set(q, a[q] - c.oa[q], al[q] - c.oa[q]);
      c.b.set(q, b[q] - c.ob[q], be[q] - c.ob[q]);
    }
    c.u = u;
    c.v = v;
    long t0 = pick(rng, -8, 7);
    c.tl = FT(t0);
    c.th = FT(pick(rng, t0 + 1, 8));
    // The span by hand: per axis, (u - v) t > b - alpha and < beta - a.
    FT tl = c.tl, th = c.th;
    bool empty = false;
    for (int q = 0; q < 3; ++q) {
      FT w = u[q] - v[q], low = b[q] - al[q], high = be[q] - a[q];
      if (w == FT(0)) {
        empty = empty || !(low < FT(0) && FT(0) < high);
        continue;
      }
      FT t1 = low / w, t2 = high / w;
      tl = std::max(tl, std::min(t1, t2));
      th = std::min(th, std::max(t1, t2));
    }
    empty = empty || !(tl < th);
    std::string where = "case " + std::to_string(i) + " (seed " + std::to_string(seed) + ")";
    bool got = c.run(k);
    BOOST_TEST(got == !empty, where);
    if (!got || empty) continue;
    ++alive;
    BOOST_TEST(c.tl == tl, where);
    BOOST_TEST(c.th == th, where);
    for (int q = 0; q < 3; ++q) {
      FT ql = std::max(u[q] * tl + a[q], v[q] * tl + b[q]), qh = std::max(u[q] * th + a[q], v[q] * th + b[q]);
      FT Ql = std::min(u[q] * tl + al[q], v[q] * tl + be[q]), Qh = std::min(u[q] * th + al[q], v[q] * th + be[q]);
      FT a2 = std::min(ql - u[q] * tl, qh - u[q] * th), al2 = std::max(Ql - u[q] * tl, Qh - u[q] * th);
      FT b2 = std::min(ql - v[q] * tl, qh - v[q] * th), be2 = std::max(Ql - v[q] * tl, Qh - v[q] * th);
      BOOST_TEST(c.a.lo[q] + c.oa[q] == a2, where << " a' axis " << q);
      BOOST_TEST(c.a.hi[q] + c.oa[q] == al2, where << " alpha' axis " << q);
      BOOST_TEST(c.b.lo[q] + c.ob[q] == b2, where << " b' axis " << q);
      BOOST_TEST(c.b.hi[q] + c.ob[q] == be2, where << " beta' axis " << q);
    }
  }
  BOOST_TEST_MESSAGE(alive << " of " << cases << " pairs meet");
}

// --- An approximate kernel's undecided signs (keep_doubtful) -----------------
//
// Intervals enclose 1/10 and 3/10 but cannot tell 1/10 - 1/10 from a small
// number of either sign. By default such a sign throws, as every interval
// sign does (the filter then makes the stage in rationals). keep_doubtful
// keeps the box or the time range instead, which still bounds the node, and
// doubted() says so; decided signs are unaffected, and rationals decide all.

namespace {

Box<Interval_kernel::FT, 3> tenths_box(const Interval_kernel& k, long x_lo, long x_hi)
{
  Box<Interval_kernel::FT, 3> b;
  b.set(0, k.from_rational(Rational(static_cast<int>(x_lo), 10)), k.from_rational(Rational(static_cast<int>(x_hi), 10)));
  b.set(1, Interval_kernel::FT(0), Interval_kernel::FT(1));
  b.set(2, Interval_kernel::FT(0), Interval_kernel::FT(1));
  return b;
}

} // namespace

BOOST_AUTO_TEST_CASE(an_undecided_flat_box_is_kept_and_doubted)
{
  Interval_kernel ik;
  Interval_kernel::Protector protect;
  // x in [1/10, 1/10]: flat, so (regularised) a null set; intervals cannot
  // tell it from x in [1/10, 1/10 + e].
  const auto flat = tenths_box(ik, 1, 1);
  S_bounds<Interval_kernel> strict(ik), doubting(ik, false, true);
  BOOST_CHECK_THROW(strict.normalised(flat), CGAL::Uncertain_conversion_exception);
  Box<Interval_kernel::FT, 3> kept = doubting.normalised(flat);
  BOOST_TEST(!kept.empty);
  BOOST_TEST(doubting.doubted());
  // Decided signs: [1/10, 3/10] has room, [3/10, 1/10] is empty; neither doubts.
  S_bounds<Interval_kernel> decided(ik, false, true);
  BOOST_TEST(!decided.normalised(tenths_box(ik, 1, 3)).empty);
  BOOST_TEST(decided.normalised(tenths_box(ik, 3, 1)).empty);
  BOOST_TEST(!decided.doubted());
  // Closed semantics keeps a flat box anyway, but hi < lo by an undecided
  // amount is doubted the same way.
  S_bounds<Interval_kernel> closed(ik, true, true);
  BOOST_TEST(!closed.normalised(flat).empty);
  BOOST_TEST(closed.doubted());
  // Rationals decide: the flat box is nothing.
  Rational_kernel rk;
  Box<Rational, 3> exact;
  exact.set(0, Rational(1, 10), Rational(1, 10));
  exact.set(1, Rational(0), Rational(1));
  exact.set(2, Rational(0), Rational(1));
  BOOST_TEST(S_bounds<Rational_kernel>(rk, false, true).normalised(exact).empty);
}

// A moving at 1/10 along x, B at 1/10 too: the relative velocity is 0, but
// its enclosure holds both signs, so Appendix B's span cannot be narrowed
// by it. Kept: [tl, th] stays [0, 5] (still bounding the meeting times,
// which are all of it here: the boxes overlap and move together).
BOOST_AUTO_TEST_CASE(an_undecided_relative_velocity_keeps_the_span)
{
  using FT = Interval_kernel::FT;
  Interval_kernel ik;
  Interval_kernel::Protector protect;
  Box<FT, 3> a = tenths_box(ik, 0, 10), b = tenths_box(ik, 5, 15);
  Vector3<FT> u{ik.from_rational(Rational(1, 10)), FT(0), FT(0)}, v = u, o{FT(0), FT(0), FT(0)};
  FT tl(0), th(5);
  S_bounds<Interval_kernel> doubting(ik, false, true);
  typename S_bounds<Interval_kernel>::Moving_box ma{&a, &u, &o}, mb{&b, &v, &o};
  // v - u of two equal enclosures is an interval around 0, not the point 0.
  BOOST_TEST_REQUIRE(!CGAL::is_certain(ik.is_nonnegative(v[0] - u[0], true)));
  BOOST_TEST(doubting.meet_moving(ma, mb, tl, th));
  BOOST_TEST(doubting.doubted());
  BOOST_TEST((tl.inf() == 0 && tl.sup() == 0 && th.inf() == 5 && th.sup() == 5));
  // Both boxes narrowed to the overlap x in [1/2, 1], an enclosure of it.
  BOOST_TEST((a.lo[0].inf() <= 0.5 && 0.5 <= a.lo[0].sup() && a.hi[0].inf() <= 1 && 1 <= a.hi[0].sup()));
  // Without keep_doubtful the sign of v - u throws.
  Box<FT, 3> a2 = tenths_box(ik, 0, 10), b2 = tenths_box(ik, 5, 15);
  FT tl2(0), th2(5);
  typename S_bounds<Interval_kernel>::Moving_box ma2{&a2, &u, &o}, mb2{&b2, &v, &o};
  BOOST_CHECK_THROW(S_bounds<Interval_kernel>(ik).meet_moving(ma2, mb2, tl2, th2), CGAL::Uncertain_conversion_exception);
}

#define BOOST_TEST_MODULE neighbourhood
// The neighbourhood classification of Appendix A (search/Neighbourhood.h):
// around a point on a line l, the hyperplanes through it (all containing l)
// form a central arrangement in the 3D quotient by l, and find_inside must
// offer every open cell of it to the caller, each by a direction that lies
// strictly in that cell. The cases count the distinct sign vectors offered
// (the callback records them and says no) against the number of cells
// derived by hand, and check each cell's direction.
//
// Cell counts: a central arrangement of distinct planes in R^3 has
// 2 + 2 * sum over its lines L of (m_L - 1) open cells, m_L the number of
// planes through L (Zaslavsky's count; n planes in general position give
// n(n - 1) + 2, n planes through one line 2n, one plane 2).
//
// CLASH4D_SEED overrides the seed of the random case, CLASH4D_STAGE_CASES the
// number of cases.
#include <boost/test/unit_test.hpp>

#include "search/Neighbourhood.h"
#include "support/Stage_tests.h"

#include <set>
#include <string>

using namespace clash4d;
using namespace clash4d::stage_tests;

namespace {

using Signs = std::vector<int>;

template <class FT>
Vector4<FT> vec(long a, long b, long c, long d)
{
  return {FT(a), FT(b), FT(c), FT(d)};
}

std::string text(const Signs& s)
{
  std::string out;
  for (int x : s) out += x > 0 ? '+' : x < 0 ? '-' : '0';
  return out;
}

// Every sign vector find_inside offers when nothing is inside.
template <class K>
std::set<Signs> cells_offered(const Vector4<typename K::FT>& l, const std::vector<Vector4<typename K::FT>>& normals,
                              std::size_t* tested = nullptr)
{
  K k;
  Neighbourhood<K> hood(k);
  std::set<Signs> seen;
  auto d = hood.find_inside(l, normals, [&](const Signs& s) {
    seen.insert(s);
    return false;
  });
  BOOST_TEST(!d.has_value());
  if (tested) *tested = hood.cells_tested();
  return seen;
}

// Asks for the one cell `want` and checks the direction returned: n_i . d
// has sign want[i] for every i, and d is not along l.
template <class K>
void check_direction_into(const Vector4<typename K::FT>& l, const std::vector<Vector4<typename K::FT>>& normals,
                          const Signs& want, const std::string& where)
{
  using FT = typename K::FT;
  K k;
  Neighbourhood<K> hood(k);
  auto d = hood.find_inside(l, normals, [&](const Signs& s) { return s == want; });
  BOOST_TEST_REQUIRE(d.has_value(), where << ": no direction into " << text(want));
  for (std::size_t i = 0; i < normals.size(); ++i) {
    FT nd = dot(normals[i], *d);
    int s = nd > FT(0) ? 1 : nd < FT(0) ? -1 : 0;
    BOOST_TEST(s == want[i], where << ": cell " << text(want) << ", plane " << i);
  }
  bool along_l = true;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) along_l = along_l && minor2(*d, l, i, j) == FT(0);
  BOOST_TEST(!along_l, where << ": direction along l");
}

// The cells offered must be `expected` in number, each with no zero sign,
// and each reachable by a direction strictly inside it.
template <class K>
std::set<Signs> check_cells(const Vector4<typename K::FT>& l, const std::vector<Vector4<typename K::FT>>& normals,
                            std::size_t expected, const std::string& where)
{
  std::set<Signs> cells = cells_offered<K>(l, normals);
  BOOST_TEST(cells.size() == expected, where << ": " << cells.size() << " cells offered, " << expected << " exist");
  for (const Signs& s : cells) {
    BOOST_TEST(s.size() == normals.size());
    for (int x : s) BOOST_TEST((x == 1 || x == -1), where << ": sign vector " << text(s));
    check_direction_into<K>(l, normals, s, where);
  }
  return cells;
}

// All sign vectors of length n but the listed ones.
std::set<Signs> all_but(std::size_t n, std::set<std::string> missing)
{
  std::set<Signs> out;
  for (int mask = 0; mask < (1 << n); ++mask) {
    Signs s(n);
    for (std::size_t i = 0; i < n; ++i) s[i] = (mask >> i & 1) ? -1 : 1;
    if (!missing.count(text(s))) out.insert(s);
  }
  return out;
}

} // namespace

BOOST_AUTO_TEST_CASE_TEMPLATE(no_plane_through_the_point_means_the_point_is_generic, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  // Appendix A step 0: nothing to classify, the formula is asked once with
  // no signs, and the point itself is the answer (direction 0).
  Neighbourhood<K> hood(k);
  int calls = 0;
  auto d = hood.find_inside(vec<FT>(0, 0, 0, 1), {}, [&](const Signs& s) {
    ++calls;
    BOOST_TEST(s.empty());
    return true;
  });
  BOOST_TEST(calls == 1);
  BOOST_TEST_REQUIRE(d.has_value());
  for (int i = 0; i < 4; ++i) BOOST_TEST((*d)[i] == FT(0));
  Neighbourhood<K> none(k);
  BOOST_TEST(!none.find_inside(vec<FT>(0, 0, 0, 1), {}, [](const Signs&) { return false; }).has_value());
  BOOST_TEST(none.cells_tested() == 0u);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(three_coordinate_planes_give_the_8_octants, K, Kernels)
{
  using FT = typename K::FT;
  // l = t axis; x = 0, y = 0, z = 0 through the point: A.2, independent
  // normals; the quotient is xyz space and its 8 octants are every sign
  // vector.
  std::vector<Vector4<FT>> n{vec<FT>(1, 0, 0, 0), vec<FT>(0, 1, 0, 0), vec<FT>(0, 0, 1, 0)};
  std::size_t tested = 0;
  auto cells = cells_offered<K>(vec<FT>(0, 0, 0, 1), n, &tested);
  BOOST_TEST(tested == 8u);   // each octant offered once
  BOOST_TEST((cells == all_but(3, {})));
  check_cells<K>(vec<FT>(0, 0, 0, 1), n, 8, "octants");
}

BOOST_AUTO_TEST_CASE_TEMPLATE(three_independent_planes_around_a_skew_line, K, Kernels)
{
  using FT = typename K::FT;
  // l = (1,1,1,1); the normals (1,-1,0,0), (0,1,-1,0), (0,0,1,-1) are
  // orthogonal to l and a basis of the vectors with coordinate sum 0, so
  // independent with l: 8 cells, every sign vector.
  Vector4<FT> l = vec<FT>(1, 1, 1, 1);
  std::vector<Vector4<FT>> n{vec<FT>(1, -1, 0, 0), vec<FT>(0, 1, -1, 0), vec<FT>(0, 0, 1, -1)};
  auto cells = check_cells<K>(l, n, 8, "skew line");
  BOOST_TEST((cells == all_but(3, {})));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(parallel_normals_give_two_cells, K, Kernels)
{
  using FT = typename K::FT;
  Vector4<FT> l = vec<FT>(0, 0, 0, 1);
  // One plane: its two sides.
  auto one = check_cells<K>(l, {vec<FT>(0, 3, 0, 0)}, 2, "one plane");
  BOOST_TEST((one == std::set<Signs>{{1}, {-1}}));
  // x = 0 three times, once reversed (A.1: "multiple references to a
  // half-space or its complement"): still one plane, 2 cells, and the signs
  // agree with the orientations: (+,+,-) and (-,-,+).
  auto three = check_cells<K>(l, {vec<FT>(1, 0, 0, 0), vec<FT>(2, 0, 0, 0), vec<FT>(-1, 0, 0, 0)}, 2, "parallel");
  BOOST_TEST((three == std::set<Signs>{{1, 1, -1}, {-1, -1, 1}}));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(two_planes_give_four_wedges, K, Kernels)
{
  using FT = typename K::FT;
  // A.2, n = 2: x = 0 and y = 0 meet in a line of the quotient; 2(1) + 2 = 4
  // wedges, every sign vector.
  auto cells = check_cells<K>(vec<FT>(0, 0, 0, 1), {vec<FT>(1, 0, 0, 0), vec<FT>(0, 1, 0, 0)}, 4, "two planes");
  BOOST_TEST((cells == all_but(2, {})));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(three_coplanar_normals_have_two_redundant_sign_vectors, K, Kernels)
{
  using FT = typename K::FT;
  // A.3: normals x, y, x + y lie in a plane, so the three planes share the z
  // line: 2n = 6 cells, and of the 8 inputs exactly 2 are spatially
  // redundant: x > 0, y > 0 forces x + y > 0, so (+,+,-) and (-,-,+).
  auto cells = check_cells<K>(vec<FT>(0, 0, 0, 1), {vec<FT>(1, 0, 0, 0), vec<FT>(0, 1, 0, 0), vec<FT>(1, 1, 0, 0)}, 6,
                              "coplanar 3");
  BOOST_TEST((cells == all_but(3, {"++-", "--+"})));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(four_coplanar_normals_give_eight_sectors, K, Kernels)
{
  using FT = typename K::FT;
  // A.4: x, y, x + y, x - y, all containing the z line: 2n = 8 sectors.
  check_cells<K>(vec<FT>(0, 0, 0, 1),
                 {vec<FT>(1, 0, 0, 0), vec<FT>(0, 1, 0, 0), vec<FT>(1, 1, 0, 0), vec<FT>(1, -1, 0, 0)}, 8, "coplanar 4");
}

BOOST_AUTO_TEST_CASE_TEMPLATE(four_planes_in_general_position_span_3d, K, Kernels)
{
  using FT = typename K::FT;
  // A.5: x, y, z and x + y + z, no three normals dependent: n(n - 1) + 2 = 14
  // cells. The 2 missing sign vectors: x, y, z > 0 forces x + y + z > 0, and
  // the opposite.
  auto cells = check_cells<K>(
      vec<FT>(0, 0, 0, 1), {vec<FT>(1, 0, 0, 0), vec<FT>(0, 1, 0, 0), vec<FT>(0, 0, 1, 0), vec<FT>(1, 1, 1, 0)}, 14,
      "general 4");
  BOOST_TEST((cells == all_but(4, {"+++-", "---+"})));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(five_planes_in_general_position, K, Kernels)
{
  using FT = typename K::FT;
  // x, y, z, x + y + z, x - y + 2z: every triple independent (determinants
  // of the triples with (1,-1,2): 2, 1, 1, 3, -1, -2); 5 * 4 + 2 = 22 cells.
  check_cells<K>(vec<FT>(0, 0, 0, 1),
                 {vec<FT>(1, 0, 0, 0), vec<FT>(0, 1, 0, 0), vec<FT>(0, 0, 1, 0), vec<FT>(1, 1, 1, 0), vec<FT>(1, -1, 2, 0)},
                 22, "general 5");
}

BOOST_AUTO_TEST_CASE_TEMPLATE(three_planes_through_a_line_and_a_fourth_across, K, Kernels)
{
  using FT = typename K::FT;
  // x = 0, y = 0, x + y = 0 share the z line (m = 3), and z = 0 meets each
  // in a line of its own (m = 2 each): 2 + 2((3 - 1) + 1 + 1 + 1) = 12, the
  // 6 wedges around the z line cut by z = 0.
  check_cells<K>(vec<FT>(0, 0, 0, 1),
                 {vec<FT>(1, 0, 0, 0), vec<FT>(0, 1, 0, 0), vec<FT>(1, 1, 0, 0), vec<FT>(0, 0, 1, 0)}, 12, "pencil + 1");
}

BOOST_AUTO_TEST_CASE_TEMPLATE(a_repeated_plane_among_independent_ones, K, Kernels)
{
  using FT = typename K::FT;
  // x, y, z and -2x: four normals but three planes, so the octants again (8),
  // with the fourth sign always the opposite of the first.
  auto cells = check_cells<K>(
      vec<FT>(0, 0, 0, 1), {vec<FT>(1, 0, 0, 0), vec<FT>(0, 1, 0, 0), vec<FT>(0, 0, 1, 0), vec<FT>(-2, 0, 0, 0)}, 8,
      "repeated");
  for (const Signs& s : cells) BOOST_TEST(s[3] == -s[0]);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(general_position_around_a_skew_line, K, Kernels)
{
  using FT = typename K::FT;
  // l = (1,2,3,4) with four normals orthogonal to it (each dot product is
  // 2 - 2, 6 - 6, 4 - 4, 12 - 12 = 0). General position in the quotient
  // means every triple independent together with l; checked below as a
  // precondition, then n(n - 1) + 2 = 14 cells.
  K k;
  Vector4<FT> l = vec<FT>(1, 2, 3, 4);
  std::vector<Vector4<FT>> n{vec<FT>(2, -1, 0, 0), vec<FT>(0, 3, -2, 0), vec<FT>(4, 0, 0, -1), vec<FT>(0, 0, 4, -3)};
  for (const auto& x : n) BOOST_TEST_REQUIRE(dot(x, l) == FT(0));
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b)
      for (int c = b + 1; c < 4; ++c) BOOST_TEST_REQUIRE(k.orientation4(l, n[a], n[b], n[c]) != CGAL::ZERO);
  check_cells<K>(l, n, 14, "skew general 4");
}

// Random normals around random lines: the cells offered are distinct,
// sign-consistent (a direction strictly inside each) and as many as
// 2 + 2 * sum (m_L - 1), computed here from the planes' lines.
BOOST_AUTO_TEST_CASE_TEMPLATE(random_arrangements_offer_every_cell_once, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  std::uint64_t seed = env_number("CLASH4D_SEED", 19900713ull) + 4, cases = env_number("CLASH4D_STAGE_CASES", 200);
  BOOST_TEST_MESSAGE("neighbourhood cells, " << K::name() << ": seed " << seed << ", " << cases
                                             << " arrangements (CLASH4D_SEED, CLASH4D_STAGE_CASES)");
  std::size_t total_cells = 0, degenerate = 0;
  for (std::uint64_t i = 0; i < cases; ++i) {
    std::mt19937_64 rng(case_seed(seed, i));
    auto rnd = [&](long r) { return vec<FT>(pick(rng, -r, r), pick(rng, -r, r), pick(rng, -r, r), pick(rng, -r, r)); };
    Vector4<FT> l = rnd(2);
    if (k.is_zero(l)) continue;
    std::vector<Vector4<FT>> normals;
    long count = pick(rng, 1, 6);
    while (static_cast<long>(normals.size()) < count) {
      Vector4<FT> n;
      long kind = pick(rng, 0, 5);
      if (kind == 0 && !normals.empty()) {
        // a repeat of an earlier plane, maybe reversed
        const auto& m = normals[pick(rng, 0, normals.size() - 1)];
        FT s(pick(rng, 0, 1) ? 2 : -1);
        n = {m[0] * s, m[1] * s, m[2] * s, m[3] * s};
      } else if (kind == 1 && normals.size() >= 2) {
        // a plane through the line of two earlier ones (coplanar normals)
        const auto& a = normals[0];
        const auto& b = normals[1];
        FT p(pick(rng, -2, 2)), q(pick(rng, -2, 2));
        n = {a[0] * p + b[0] * q, a[1] * p + b[1] * q, a[2] * p + b[2] * q, a[3] * p + b[3] * q};
      } else {
        n = generalised_cross(l, rnd(2), rnd(2));   // orthogonal to l
      }
      if (!k.is_zero(n)) normals.push_back(n);
    }
    // Distinct planes, then the lines they meet in (directions up to sign).
    std::vector<Vector4<FT>> planes, lines;
    auto parallel = [&](const Vector4<FT>& a, const Vector4<FT>& b) {
      for (int x = 0; x < 4; ++x)
        for (int y = x + 1; y < 4; ++y)
          if (minor2(a, b, x, y) != FT(0)) return false;
      return true;
    };
    for (const auto& n : normals)
      if (std::none_of(planes.begin(), planes.end(), [&](const auto& p) { return parallel(p, n); })) planes.push_back(n);
    for (std::size_t a = 0; a < planes.size(); ++a)
      for (std::size_t b = a + 1; b < planes.size(); ++b) {
        Vector4<FT> r = generalised_cross(l, planes[a], planes[b]);
        if (std::none_of(lines.begin(), lines.end(), [&](const auto& x) { return parallel(x, r); })) lines.push_back(r);
      }
    std::size_t sum = 0;
    for (const auto& r : lines) {
      std::size_t m = 0;
      for (const auto& p : planes) m += dot(p, r) == FT(0);
      sum += m - 1;
    }
    std::size_t expected = 2 + 2 * sum;
    degenerate += planes.size() >= 3 && expected != planes.size() * (planes.size() - 1) + 2;
    std::string where = "case " + std::to_string(i) + " (seed " + std::to_string(seed) + ")";
    BOOST_TEST_CHECKPOINT(where);
    total_cells += check_cells<K>(l, normals, expected, where).size();
  }
  BOOST_TEST_MESSAGE(total_cells << " cells checked; " << degenerate << " arrangements not in general position");
  BOOST_TEST(degenerate > 0u);
}

// The memo of one line's cells (Neighbourhood::Memo, kept by generate-and-
// test for the edges of one line): a second point of the line, asked with
// another formula, gets the same first cell inside and the same direction
// as a fresh enumeration, in the same order, without constructing the
// rays again. x, y, z and x + y + z around t (14 cells, as above).
BOOST_AUTO_TEST_CASE_TEMPLATE(a_memo_of_a_lines_cells_gives_the_fresh_answer, K, Kernels)
{
  using FT = typename K::FT;
  K k;
  const Vector4<FT> l = vec<FT>(0, 0, 0, 1);
  const std::vector<Vector4<FT>> N{vec<FT>(1, 0, 0, 0), vec<FT>(0, 1, 0, 0), vec<FT>(0, 0, 1, 0), vec<FT>(1, 1, 1, 0)};
  auto wants = [](const Signs& want) { return [want](const Signs& s) { return s == want; }; };
  typename Neighbourhood<K>::Memo memo;
  // Nothing inside: every cell tested (some more than once: a cell has
  // several extreme rays), the memo complete with each test, 14 cells.
  Neighbourhood<K> first(k);
  BOOST_TEST(!first.find_inside(l, N, [](const Signs&) { return false; }, &memo).has_value());
  BOOST_TEST(memo.complete);
  const std::size_t tested = memo.cells.size();
  BOOST_TEST(tested == first.cells_tested());
  std::set<Signs> distinct;
  for (const auto& cell : memo.cells) distinct.insert(cell.second);
  BOOST_TEST(distinct.size() == 14u);
  for (const Signs& want : {Signs{-1, -1, 1, -1}, Signs{1, 1, 1, 1}, Signs{1, -1, -1, 1}}) {
    Neighbourhood<K> fresh(k), again(k);
    std::optional<Vector4<FT>> a = fresh.find_inside(l, N, wants(want));
    std::optional<Vector4<FT>> b = again.find_inside(l, N, wants(want), &memo);
    BOOST_REQUIRE(a.has_value());
    BOOST_REQUIRE(b.has_value());
    for (int q = 0; q < 4; ++q) BOOST_TEST(k.sign((*a)[q] - (*b)[q]) == CGAL::ZERO, text(want));
    BOOST_TEST(again.cells_tested() == fresh.cells_tested(), text(want));   // the same order
    BOOST_TEST(memo.cells.size() == tested);                                // nothing constructed again
  }
  // A memo left partial (the first cell asked for was found early) is
  // completed when a later point needs more of it.
  typename Neighbourhood<K>::Memo partial;
  Neighbourhood<K> early(k), late(k), fresh(k);
  BOOST_TEST(early.find_inside(l, N, [](const Signs&) { return true; }, &partial).has_value());
  BOOST_TEST(!partial.complete);
  BOOST_TEST(partial.cells.size() == 1u);
  std::optional<Vector4<FT>> b = late.find_inside(l, N, wants({1, 1, 1, 1}), &partial);
  std::optional<Vector4<FT>> a = fresh.find_inside(l, N, wants({1, 1, 1, 1}));
  BOOST_REQUIRE(a.has_value());
  BOOST_REQUIRE(b.has_value());
  for (int q = 0; q < 4; ++q) BOOST_TEST(k.sign((*a)[q] - (*b)[q]) == CGAL::ZERO);
}

// The minors whose roots are a pair's critical times (Critical_times.h,
// fact 10 of regularised-semantics.md), enumerated once for any polynomial
// ring: the exact stage's integer polynomials and the double stage's. Only
// mixed minors are made (a minor of one object's planes keeps its sign
// under a rigid motion), and a plane both objects have is one row.
#ifndef CLASH4D_ROTATION_PAIR_MINORS_H
#define CLASH4D_ROTATION_PAIR_MINORS_H

#include "rotation/Critical_times.h"
#include "run/Work_budget.h"
#include <array>
#include <initializer_list>
#include <map>
#include <vector>

namespace clash4d {

// What a filter knows of a minor on the interval before it is made:
// identically zero there, no root there, or neither.
enum class Minor_state { zero, nonzero, unsure };

namespace pair_minors_detail {

// Whether a polynomial is the zero polynomial (every coefficient 0).
template <class Poly>
bool zero_polynomial(const Poly& p)
{
  for (int i = 0; i < p.size(); ++i)
    if (p[i] != 0) return false;
  return true;
}

// Whether two rows are proportional as vectors of polynomials (every 2 x 2
// minor identically zero): the same plane up to a factor that is a
// function of t of one sign (a norm |q(t)|^2, or its negative).
template <class Poly>
bool proportional(const std::array<Poly, 4>& u, const std::array<Poly, 4>& v)
{
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b)
      if (!zero_polynomial(u[a] * v[b] - u[b] * v[a])) return false;
  return true;
}

// Which object each row is a plane of. A plane both objects have (a face
// of each on z = 0, both turning about z: rows equal up to a factor of one
// sign) is one row of both, its first copy: a minor of it with one
// object's planes keeps its sign, and a minor with another copy is a
// multiple of one with the first.
class Row_owners {
public:
  template <class Poly>
  Row_owners(const std::vector<std::array<Poly, 4>>& rows, int split) : owner_(rows.size()), first_(rows.size())
  {
    int m = static_cast<int>(rows.size());
    for (int i = 0; i < m; ++i) {
      first_[i] = true;
      owner_[i] = i < split ? 1 : 2;
      for (int j = 0; j < i && first_[i]; ++j)
        if (first_[j] && proportional(rows[j], rows[i])) {
          first_[i] = false;
          owner_[j] |= owner_[i];
        }
    }
  }

  // Whether the minor of these rows is one to solve: first copies only,
  // with a plane of the first object only and one of the second only.
  bool mixed(std::initializer_list<int> ids) const
  {
    bool a = false, b = false;
    for (int i : ids) {
      if (!first_[i]) return false;
      a = a || owner_[i] == 1;
      b = b || owner_[i] == 2;
    }
    return a && b;
  }

private:
  std::vector<int> owner_;    // 1: the first object's only, 2: the second's only, 3: both
  std::vector<bool> first_;   // the first copy of its plane
};

// The minors of the normals, made when a full minor needs them.
template <class Poly>
class Normal_minors {
public:
  explicit Normal_minors(const std::vector<std::array<Poly, 4>>& rows) : rows_(rows) {}
  const Poly& operator()(int i, int j, int k)
  {
    auto [it, added] = made_.try_emplace({i, j, k});
    if (added) it->second = normal_minor(rows_[i], rows_[j], rows_[k]);
    return it->second;
  }

private:
  const std::vector<std::array<Poly, 4>>& rows_;
  std::map<std::array<int, 3>, Poly> made_;
};

// The 4 x 4 minor of rows i, j, k, l by the last column: the offsets e
// against the minors of the normals.
template <class Poly, class Normals>
Poly full_minor(const std::vector<std::array<Poly, 4>>& r, Normals& normals, int i, int j, int k, int l)
{
  return r[j][3] * normals(i, k, l) - r[i][3] * normals(j, k, l) + r[l][3] * normals(i, j, k) - r[k][3] * normals(i, j, l);
}

// Whether a feature minor that is identically zero on the interval marks
// no event and may be left out (docs/rotation.md, Degenerate features):
//  - its four normals stay in one plane (every 3 x 3 minor of them the zero
//    polynomial): of two convex pieces' features only two edges that stay
//    parallel do (a vertex's triple is independent), and parallel lines
//    never cross at one point;
//  - it holds a plane of the first piece and one of the second that bound
//    them on the same side: proportional rows (Row_owners) whose factor's
//    sign, read as the sign of their dot product inside the interval
//    (filter.sign_inside, exact in the exact stage), times the pieces'
//    sides of them is positive. filter.may_be_proportional(a, b) is false
//    only where rows a and b are surely not proportional (a filter: the
//    rows made are then not multiplied out).
// What it finds of a triple of normals or a pair of rows is kept for the
// interval's other features: a box against a box has some eighty such
// features on each interval, over a few dozen triples and pairs.
template <class Poly, class Filter>
class Eventless_features {
public:
  Eventless_features(const std::vector<std::array<Poly, 4>>& rows, const Pair_features& features, int first_count,
                     const Filter& filter)
      : r_(rows), features_(features), first_count_(first_count), filter_(filter)
  {
  }

  bool operator()(const Minor_rows& m)
  {
    auto [i, j, k, l] = m;
    if (flat(i, j, k) && flat(i, j, l) && flat(i, k, l) && flat(j, k, l)) return true;
    for (int a : m)
      for (int b : m)
        if (a < first_count_ && b >= first_count_ && same_side(a, b)) return true;
    return false;
  }

private:
  // Whether the normals' minor of rows i, j, k is the zero polynomial:
  // exactly 0 on a piece of the interval (the filter), else made.
  bool flat(int i, int j, int k)
  {
    auto [it, added] = flat_.try_emplace({i, j, k}, false);
    if (added) {
      Minor_state s = filter_.whole_state({i, j, k, -1});
      if (s == Minor_state::unsure) s = filter_.piece_state({i, j, k, -1});
      it->second = s == Minor_state::zero || (s == Minor_state::unsure && zero_polynomial(normal_minor(r_[i], r_[j], r_[k])));
    }
    return it->second;
  }

  bool same_side(int a, int b)
  {
    auto [it, added] = same_side_.try_emplace({a, b}, false);
    if (added && filter_.may_be_proportional(a, b) && proportional(r_[a], r_[b])) {
      const auto &u = r_[a], &v = r_[b];
      it->second = filter_.sign_inside(u[0] * v[0] + u[1] * v[1] + u[2] * v[2] + u[3] * v[3]) * features_.sides[a] *
                       features_.sides[b] >
                   0;
    }
    return it->second;
  }

  const std::vector<std::array<Poly, 4>>& r_;
  const Pair_features& features_;
  int first_count_;
  const Filter& filter_;
  std::map<std::array<int, 3>, bool> flat_;
  std::map<std::pair<int, int>, bool> same_side_;
};

} // namespace pair_minors_detail

// Calls table.add(minor, rows) for each of the given 4 x 4 minors of rows
// of both objects (two convex pieces' vertex-face and edge-edge minors,
// Rotating_pair.cpp; the first first_count rows the first piece's) that
// filter.whole_state(rows) and filter.piece_state(rows) (the interval
// whole, then its pieces) do not rule out as rootless, and that mark events
// (Eventless_features leaves out those that never need to). A minor
// identically zero on the interval (the filter says zero, or
// filter.identically_zero(minor, rows) once it is made) is then a feature
// incidence that holds on the whole interval and may mark a touch: the
// features do not mark every touch, and false is returned at once, so that
// every mixed minor is taken instead (enumerate_pair_minors). Looks at the
// work budget. Filter::minors_cost_more: whether making a minor costs more
// than asking Eventless_features (exact integer polynomials) or not
// (doubles).
template <class Poly, class Filter, class Table>
bool enumerate_feature_minors(const std::vector<std::array<Poly, 4>>& r, int first_count,
                              const Pair_features& features, const Filter& filter, Table& table)
{
  // A triple's normals' minor is made once: features share their triples
  // (a vertex-face minor's four normals' minors are an edge-edge one's too).
  pair_minors_detail::Normal_minors<Poly> normals(r);
  pair_minors_detail::Eventless_features<Poly, Filter> eventless(r, features, first_count, filter);
  std::size_t made = 0;
  for (const Minor_rows& m : features.minors) {
    if (++made % 4096 == 0) Work_budget::check();
    // An eventless feature's minor is identically zero (parallel lines, or
    // two rows of one plane): asked before the pieces of the interval and
    // the minor where they cost more (Filter::minors_cost_more), else once
    // the minor is found zero.
    Minor_state state = filter.whole_state(m);
    if (state == Minor_state::unsure && Filter::minors_cost_more && eventless(m)) continue;
    if (state == Minor_state::unsure) state = filter.piece_state(m);
    if (state == Minor_state::nonzero) continue;
    auto [i, j, k, l] = m;
    if (state == Minor_state::unsure) {
      Poly d = pair_minors_detail::full_minor(r, normals, i, j, k, l);
      if (!filter.identically_zero(d, m)) {
        table.add(d, m);
        continue;
      }
    }
    if (!eventless(m)) return false;
  }
  return true;
}

// Calls table.add(minor, rows) for each mixed minor that filter.settled
// (rows) does not rule out: the 4 x 4 minors, the normals' 3 x 3 minors
// (with v_inf: parallel planes, or three meeting at infinity), and when
// neither object spans space (low_rank) the 2 x 2 and 3 x 3 minors over
// every choice of columns. Looks at the work budget (--max-seconds).
template <class Poly, class Filter, class Table>
void enumerate_pair_minors(const std::vector<std::array<Poly, 4>>& r, int first_count, bool low_rank,
                           const Filter& filter, Table& table)
{
  using namespace pair_minors_detail;
  int m = static_cast<int>(r.size());
  Row_owners owners(r, first_count);
  Normal_minors<Poly> normals(r);
  if (low_rank)
    for (int i = 0; i < m; ++i)
      for (int j = i + 1; j < m; ++j)
        if (owners.mixed({i, j}))
          for (int a = 0; a < 4; ++a)
            for (int b = a + 1; b < 4; ++b) table.add(r[i][a] * r[j][b] - r[i][b] * r[j][a], {i, j, -1, -1});
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j)
      for (int k = j + 1; k < m; ++k)
        if (owners.mixed({i, j, k})) {
          if (!filter.settled({i, j, k, -1})) table.add(normals(i, j, k), {i, j, k, -1});
          if (!low_rank) continue;
          for (int drop = 0; drop < 3; ++drop) {
            std::array<std::array<Poly, 4>, 3> rows = {r[i], r[j], r[k]};
            for (auto& row : rows) row[drop] = row[3];   // column `drop` replaced by e
            table.add(normal_minor(rows[0], rows[1], rows[2]), {i, j, k, -1});
          }
        }
  std::size_t made = 0;
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j)
      for (int k = j + 1; k < m; ++k)
        for (int l = k + 1; l < m; ++l)
          if (owners.mixed({i, j, k, l})) {
            if (!filter.settled({i, j, k, l})) table.add(full_minor(r, normals, i, j, k, l), {i, j, k, l});
            if (++made % 4096 == 0) Work_budget::check();
          }
}

} // namespace clash4d

#endif

#include "rotation/Critical_times.h"

#include "rotation/Pair_minors.h"

#include "run/Work_budget.h"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <unordered_map>

namespace clash4d {

namespace {

// The minors are computed on integer rows: each plane's row times the
// common denominator of its coefficients (a positive factor: the same
// roots, the same signs), so no fraction is reduced on the way.
using Int_poly = Integer_time_poly;
using Int_row = std::array<Int_poly, 4>;

Int_row integer_row(const Moving_plane& h)
{
  mpz_class d;
  return integer_polys(h, d);
}

using Poly_key = std::vector<mpz_class>;

// The coefficients without trailing zeros, divided by their gcd, the last
// one positive: one key per polynomial up to a non-zero factor; empty for
// the zero polynomial.
Poly_key primitive(const Int_poly& p)
{
  Poly_key c = p.coefficients();
  while (!c.empty() && c.back() == 0) c.pop_back();
  if (c.empty()) return c;
  mpz_class g = 0;
  for (const mpz_class& x : c) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), x.get_mpz_t());
  if (c.back() < 0) g = -g;
  for (mpz_class& x : c) mpz_divexact(x.get_mpz_t(), x.get_mpz_t(), g.get_mpz_t());
  return c;
}

// The minors by their primitive polynomial: each distinct one is solved once.
class Minor_table {
public:
  void add(const Int_poly& p, const Minor_rows& rows)
  {
    Poly_key k = primitive(p);
    if (k.size() < 2) return;   // a non-zero constant, or identically zero
    table_[std::move(k)].push_back(rows);
  }
  const std::map<Poly_key, std::vector<Minor_rows>>& table() const { return table_; }

private:
  std::map<Poly_key, std::vector<Minor_rows>> table_;
};

// A filter before any exact minor (one predicate: "this minor has no root
// on [lo, hi]"): the rows evaluated in intervals on [lo, hi] whole, then,
// where that is not enough, on a few closed pieces of it that cover it; a
// minor whose interval value excludes 0 there has no root, surely, and is
// not made exactly. Minors the intervals cannot settle are made and solved
// exactly as before.
class Interval_rows {
public:
  using I = CGAL::Interval_nt<false>;
  static constexpr int pieces = 32;
  static constexpr bool minors_cost_more = true;   // integer polynomials (Pair_minors.h)

  // Each coefficient is enclosed once, and each piece's ends are enclosed
  // from lo's and hi's intervals (a sure enclosure of the exact piece).
  // Only the rows `used` marks are enclosed (all when it is empty): the
  // others are never asked about. at_[0] is [lo, hi] whole, at_[1 ..
  // pieces] its pieces; a row is evaluated on the pieces only when a minor
  // that [lo, hi] whole leaves unsure asks for it (pieces_of).
  Interval_rows(const std::vector<Moving_plane>& planes, const Rational& lo, const Rational& hi,
                const std::vector<bool>& used = {})
      : middle_((lo + hi) / 2), rows_(planes.size()), on_pieces_(planes.size(), false)
  {
    CGAL::Protect_FPU_rounding<true> upward;
    auto wanted = [&](std::size_t r) { return used.empty() || used[r]; };
    for (std::size_t r = 0; r < planes.size(); ++r)
      if (wanted(r)) {
        const Moving_plane& h = planes[r];
        rows_[r] = {enclosed(h[0]), enclosed(h[1]), enclosed(h[2]), enclosed(h[3])};
      }
    I low(enclosing_interval(lo)), width = I(enclosing_interval(hi)) - low;
    for (int k = 0; k <= pieces; ++k) {
      I from = k == 0 ? low : low + width * I(k - 1) / I(pieces), to = k == 0 ? low + width : low + width * I(k) / I(pieces);
      times_[k] = I(from.inf(), to.sup());
    }
    at_.assign(pieces + 1, std::vector<std::array<I, 4>>(rows_.size(), {I(0), I(0), I(0), I(0)}));
    for (std::size_t r = 0; r < rows_.size(); ++r)
      if (wanted(r)) at_[0][r] = row_on(r, 0);
  }

  // Whether the minor of these rows (four, or three with v_inf: -1 last)
  // surely has no root on [lo, hi] that is a critical time: non-zero on
  // every piece, or exactly 0 on one (a polynomial that vanishes on an
  // interval is identically zero: a plane's structural zeros, such as the
  // z part of a vertical plane turning about z, are exact in intervals).
  bool settled(const Minor_rows& m) const
  {
    Minor_state whole = whole_state(m);
    return (whole != Minor_state::unsure ? whole : piece_state(m)) != Minor_state::unsure;
  }

  // zero: exactly 0 on the interval whole or on a piece (identically
  // zero); nonzero: excludes 0 on [lo, hi] whole, or on every piece (no
  // root on [lo, hi]); unsure otherwise. Callers ask the whole interval
  // first: it settles a minor far from 0 at one evaluation instead of one
  // per piece.
  Minor_state whole_state(const Minor_rows& m) const
  {
    CGAL::Protect_FPU_rounding<true> upward;
    return state_on(m, 0, 1);
  }
  Minor_state piece_state(const Minor_rows& m) const
  {
    CGAL::Protect_FPU_rounding<true> upward;
    if (changes_sign(m)) return Minor_state::unsure;
    return state_on(m, 1, pieces + 1);
  }

  // A minor made exactly is identically zero when it is the zero polynomial.
  bool identically_zero(const Int_poly& d, const Minor_rows&) const { return primitive(d).empty(); }

  // False when rows a and b are surely not proportional: one of their 2 x 2
  // minors a_c b_d - a_d b_c excludes 0 on [lo, hi] whole, so that minor is
  // not the zero polynomial.
  bool may_be_proportional(int a, int b) const
  {
    CGAL::Protect_FPU_rounding<true> upward;
    const std::array<I, 4> &u = at_[0][a], &v = at_[0][b];
    for (int c = 0; c < 4; ++c)
      for (int d = c + 1; d < 4; ++d) {
        I m = u[c] * v[d] - u[d] * v[c];
        if (m.inf() > 0 || m.sup() < 0) return false;
      }
    return true;
  }

  // The sign of p at the middle of [lo, hi], exactly.
  int sign_inside(const Int_poly& p) const
  {
    Rational v = 0;
    for (int i = p.size(); i-- > 0;) v = v * middle_ + Rational(CGAL::Gmpz(p[i].get_mpz_t()));
    return CGAL::sign(v);
  }

private:
  // A triple's normals' minor on [lo, hi] whole (entry 0) and, once asked
  // for, on every piece.
  struct Normals {
    std::array<I, pieces + 1> at;
    bool pieces_made = false;
  };

  // Row r's coefficients enclosed on times_[k] (under the caller's
  // rounding guard).
  std::array<I, 4> row_on(std::size_t r, int k) const
  {
    const I& t = times_[k];
    return {rows_[r][0].at(t), rows_[r][1].at(t), rows_[r][2].at(t), rows_[r][3].at(t)};
  }

  // Whether the minor is surely of opposite signs at lo and at hi: then it
  // has a root between them (a polynomial), every cover of [lo, hi] has a
  // piece whose value holds 0, and no piece's value is exactly 0 (the
  // minor is not the zero polynomial), so the pieces would say unsure: the
  // turning hits' contact minors, whose pieces were most of this filter's
  // cost. Under the caller's rounding guard.
  bool changes_sign(const Minor_rows& m) const
  {
    I a = minor_at(m, times_[1].inf()), b = minor_at(m, times_[pieces].sup());
    return (a.inf() > 0 && b.sup() < 0) || (a.sup() < 0 && b.inf() > 0);
  }

  // The minor enclosed at the time t, from the rows alone (no cache): its
  // rows at t, then full_minor's expansion (Pair_minors.h).
  I minor_at(const Minor_rows& m, double t) const
  {
    std::vector<std::array<I, 4>> r;
    for (int row : m)
      if (row >= 0) r.push_back({rows_[row][0].at(I(t)), rows_[row][1].at(I(t)), rows_[row][2].at(I(t)), rows_[row][3].at(I(t))});
    auto normals = [&](int a, int b, int c) { return normal_minor(r[a], r[b], r[c]); };
    return r.size() == 3 ? normals(0, 1, 2) : pair_minors_detail::full_minor(r, normals, 0, 1, 2, 3);
  }

  // Rows i, j, k and l (l < 0: none) evaluated on every piece, once each.
  void pieces_of(const Minor_rows& m) const
  {
    for (int r : m)
      if (r >= 0 && !on_pieces_[r]) {
        for (int k = 1; k <= pieces; ++k) at_[k][r] = row_on(r, k);
        on_pieces_[r] = true;
      }
  }

  // The minor's state on at_[from .. to): the whole interval, or its pieces.
  Minor_state state_on(const Minor_rows& m, int from, int to) const
  {
    bool apart = true, on_pieces = from > 0;
    if (on_pieces) pieces_of(m);
    auto [i, j, k, l] = m;
    if (l < 0) {
      const Normals& d = normals(i, j, k, on_pieces);
      for (int p = from; p < to; ++p)
        if (!note(d.at[p], apart)) return Minor_state::zero;
    } else {
      // By the last column: the offsets against the normals' minors.
      const Normals &a = normals(i, k, l, on_pieces), &b = normals(j, k, l, on_pieces),
                    &c = normals(i, j, k, on_pieces), &e = normals(i, j, l, on_pieces);
      for (int p = from; p < to; ++p) {
        const std::vector<std::array<I, 4>>& r = at_[p];
        if (!note(r[j][3] * a.at[p] - r[i][3] * b.at[p] + r[l][3] * c.at[p] - r[k][3] * e.at[p], apart))
          return Minor_state::zero;
      }
    }
    return apart ? Minor_state::nonzero : Minor_state::unsure;
  }

  // The normals' minor of rows i, j, k, made once: a pair's minors share
  // their triples (two boxes' 240 feature minors ask about 180 triples
  // some 960 times). Under the caller's rounding guard.
  const Normals& normals(int i, int j, int k, bool on_pieces) const
  {
    std::uint64_t key = static_cast<std::uint64_t>(i) << 42 | static_cast<std::uint64_t>(j) << 21 | static_cast<std::uint64_t>(k);
    auto [it, added] = normals_.try_emplace(key);
    Normals& n = it->second;
    if (added) n.at[0] = normal_minor(at_[0][i], at_[0][j], at_[0][k]);
    if (on_pieces && !n.pieces_made) {
      for (int p = 1; p <= pieces; ++p) n.at[p] = normal_minor(at_[p][i], at_[p][j], at_[p][k]);
      n.pieces_made = true;
    }
    return n;
  }

  // False when d is exactly 0 (the minor is identically zero); clears
  // apart when d holds 0.
  static bool note(const I& d, bool& apart)
  {
    if (d.inf() == 0 && d.sup() == 0) return false;
    apart = apart && (d.inf() > 0 || d.sup() < 0);
    return true;
  }

  Rational middle_;
  std::vector<std::array<Interval_poly, 4>> rows_;   // each row's coefficients enclosed
  std::array<I, pieces + 1> times_;                  // [lo, hi] whole, then each piece
  mutable std::vector<std::vector<std::array<I, 4>>> at_;   // [time][row]: pieces made by pieces_of
  mutable std::vector<bool> on_pieces_;                      // row r's pieces made
  mutable std::unordered_map<std::uint64_t, Normals> normals_;   // by (i, j, k), 21 bits each
};

// The filter before a distinct minor is solved (one predicate: "p has no
// root in [lo, hi]"), where the 32 pieces above were not enough: p itself
// (its primitive integer coefficients, enclosed) in intervals on [lo, hi],
// cut in two where the interval holds 0, down to 1/1024 of it. True only
// when every piece excludes 0; then there is surely no root and nothing is
// factored or isolated.
bool surely_no_root(const Poly_key& p, const Rational& lo, const Rational& hi)
{
  using I = CGAL::Interval_nt<false>;
  CGAL::Protect_FPU_rounding<true> upward;
  std::vector<I> c;
  for (const mpz_class& x : p) c.emplace_back(enclosing_interval(x));
  auto value = [&](const I& t) {
    I v(0);
    for (std::size_t i = c.size(); i-- > 0;) v = v * t + c[i];
    return v;
  };
  struct Piece {
    I t;
    int depth;
  };
  std::vector<Piece> todo = {{I(enclosing_interval(lo).first, enclosing_interval(hi).second), 0}};
  while (!todo.empty()) {
    Piece q = todo.back();
    todo.pop_back();
    I v = value(q.t);
    if (v.inf() > 0 || v.sup() < 0) continue;
    if (q.depth == 10) return false;
    double mid = q.t.inf() + (q.t.sup() - q.t.inf()) / 2;
    if (!(q.t.inf() < mid && mid < q.t.sup())) return false;
    todo.push_back({I(mid, q.t.sup()), q.depth + 1});
    todo.push_back({I(q.t.inf(), mid), q.depth + 1});
  }
  return true;
}

// The factor a turning object's rows put into the minors, which no
// critical time is a root of: n(t) = N(q(t)) a (Moving_planes.h), and the
// cofactors of N(q) are |q|^2 N(q), so a minor with two normals of one
// turning object holds |q(t)|^2 > 0. It is read off one row: n.n =
// |q|^4 |a|^2, so the primitive part of n.n is the square of |q|^2's. A
// turning box's irrational minor (t^2 + 1)(23 t^2 - 20 t + 3) is then a
// quadratic, which FLINT factors by its discriminant where the quartic
// took Zassenhaus' algorithm (a sixth of the query). None (a constant)
// for an object that does not turn.
Int_poly row_scale(const Int_row& row)
{
  Int_poly square = (row[0] * row[0] + row[1] * row[1] + row[2] * row[2]).primitive_part();
  std::optional<Int_poly> root = square.size() > 1 ? square.square_root() : std::nullopt;
  return root ? *root : Int_poly();
}

// Each object's scale (row_scale, on its first row that was made), kept
// when it surely has no root on [lo, hi].
std::vector<Int_poly> scales_of(const std::vector<Int_row>& rows, std::size_t first_count, const Rational& lo,
                                const Rational& hi)
{
  std::vector<Int_poly> scales;
  for (auto [from, to] : {std::pair{std::size_t{0}, first_count}, std::pair{first_count, rows.size()}})
    for (std::size_t r = from; r < to; ++r) {
      if (rows[r][0].size() == 0 && rows[r][1].size() == 0 && rows[r][2].size() == 0) continue;
      Int_poly scale = row_scale(rows[r]);
      if (scale.size() > 1 && surely_no_root(scale.coefficients(), lo, hi)) scales.push_back(std::move(scale));
      break;
    }
  return scales;
}

// p without every power of the scales that divides it: the same roots on
// [lo, hi].
Poly_key without_scales(const Poly_key& p, const std::vector<Int_poly>& scales)
{
  Int_poly rest(p);
  for (const Int_poly& scale : scales)
    while (std::optional<Int_poly> q = rest.divided_by(scale)) rest = std::move(*q);
  return primitive(rest);
}

} // namespace

void check_pair_minor_count(int m, int split)
{
  auto choose = [](double n, int k) {
    double c = 1;
    for (int i = 0; i < k; ++i) c = c * (n - i) / (i + 1);
    return n < k ? 0.0 : c;
  };
  double count = choose(m, 4) + choose(m, 3) - choose(split, 4) - choose(split, 3) - choose(m - split, 4) -
                 choose(m - split, 3);
  if (count > static_cast<double>(CLASH4D_MAX_PAIR_MINORS))
    throw Minor_limit("a pair with " + std::to_string(split) + " and " + std::to_string(m - split) + " planes has " +
                      std::to_string(static_cast<long long>(count)) + " minors, more than the limit of " +
                      std::to_string(CLASH4D_MAX_PAIR_MINORS) + " (the time slices take every minor of a pair's "
                      "planes; docs/rotation.md, Cost)");
}

Critical_times::Critical_times(const std::vector<Moving_plane>& planes, std::size_t first_count, const Rational& lo,
                               const Rational& hi, bool low_rank)
{
  std::vector<Int_row> rows;
  rows.reserve(planes.size());
  for (const Moving_plane& h : planes) rows.push_back(integer_row(h));
  check_pair_minor_count(static_cast<int>(rows.size()), static_cast<int>(first_count));
  Minor_table table;
  enumerate_pair_minors(rows, static_cast<int>(first_count), low_rank, Interval_rows(planes, lo, hi), table);
  solve(table.table(), rows, first_count, lo, hi);
}

void check_feature_minor_count(std::size_t features, std::size_t m, std::size_t split)
{
  if (features > CLASH4D_MAX_PAIR_MINORS)
    throw Minor_limit("a pair of convex pieces with " + std::to_string(split) + " and " + std::to_string(m - split) +
                      " planes has " + std::to_string(features) +
                      " vertex-face and edge-edge minors, more than the limit of " +
                      std::to_string(CLASH4D_MAX_PAIR_MINORS) + " (docs/rotation.md, Cost)");
}

Critical_times::Critical_times(const std::vector<Moving_plane>& planes, std::size_t first_count, const Rational& lo,
                               const Rational& hi, bool low_rank, const Pair_features& features)
{
  check_feature_minor_count(features.minors.size(), planes.size(), first_count);
  // Only the rows of the features are made (near features: a few of the
  // pair's planes); the others stay zero and are never read.
  std::vector<bool> used(planes.size(), false);
  for (const Minor_rows& m : features.minors)
    for (int r : m)
      if (r >= 0) used[r] = true;
  std::vector<Int_row> rows(planes.size());
  for (std::size_t r = 0; r < planes.size(); ++r)
    if (used[r]) rows[r] = integer_row(planes[r]);
  Minor_table table;
  if (!enumerate_feature_minors(rows, static_cast<int>(first_count), features, Interval_rows(planes, lo, hi, used),
                                table)) {
    // A feature incidence that holds on the whole interval and may mark
    // a touch: the touches are not all marked by a feature minor's root;
    // every mixed minor.
    *this = Critical_times(planes, first_count, lo, hi, low_rank);
    return;
  }
  restricted_ = true;
  solve(table.table(), rows, first_count, lo, hi);
}

// The times found so far that are roots of p too take p's minors, and p
// is returned without their minimal polynomials: its other roots are
// those of the rest, so a root two minors share is factored out once.
std::vector<mpz_class> Critical_times::without_known_roots(const std::vector<mpz_class>& p,
                                                           const std::vector<Minor_rows>& minors)
{
  std::vector<mpz_class> rest = p;
  for (Critical_time& c : times_) {
    std::optional<std::vector<mpz_class>> cofactor = c.t.root_divided_out(rest);
    if (!cofactor) continue;
    c.vanishing.insert(c.vanishing.end(), minors.begin(), minors.end());
    rest = std::move(*cofactor);
  }
  return rest;
}

void Critical_times::solve(const std::map<std::vector<mpz_class>, std::vector<Minor_rows>>& table,
                           const std::vector<std::array<Integer_time_poly, 4>>& rows, std::size_t first_count,
                           const Rational& lo, const Rational& hi)
{
  std::optional<std::vector<Int_poly>> scales;   // made when a minor is first solved
  for (const auto& [key, minors] : table) {
    Work_budget::check();
    minor_count_ += minors.size();
    if (surely_no_root(key, lo, hi)) continue;
    if (!scales) scales = scales_of(rows, first_count, lo, hi);
    Poly_key rest = without_known_roots(without_scales(key, *scales), minors);
    if (rest.size() < 2 || (rest.size() < key.size() && surely_no_root(rest, lo, hi))) continue;
    for (Algebraic& r : Algebraic::real_roots_rational_first(rest, lo, hi)) {
      if (compare(r, lo) <= 0 || compare(r, hi) >= 0) continue;
      times_.push_back({std::move(r), minors});
    }
  }
  // Distinct already: a root of two minors is found once (without_known_roots).
  std::sort(times_.begin(), times_.end(), [](const Critical_time& a, const Critical_time& b) { return a.t < b.t; });
}

} // namespace clash4d

#include "rotation/Critical_times.h"

#include "search/Work_budget.h"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <map>

namespace clash4d {

namespace {

// The minors are computed on integer rows: each plane's row times the
// common denominator of its coefficients (a positive factor: the same
// roots, the same signs), so no fraction is reduced on the way.
using Int_poly = Polynomial<mpz_class, 16>;
using Int_row = std::array<Int_poly, 4>;

Int_row integer_row(const Moving_plane& h)
{
  mpz_class d = 1;
  for (const Time_poly& p : h)
    for (int i = 0; i < p.size(); ++i) {
      mpz_class den(p[i].denominator().mpz());
      mpz_lcm(d.get_mpz_t(), d.get_mpz_t(), den.get_mpz_t());
    }
  Int_row out;
  for (int c = 0; c < 4; ++c) {
    std::vector<mpz_class> coefficients;
    for (int i = 0; i < h[c].size(); ++i)
      coefficients.push_back(mpz_class(h[c][i].numerator().mpz()) * (d / mpz_class(h[c][i].denominator().mpz())));
    out[c] = Int_poly(coefficients);
  }
  return out;
}

using Poly_key = std::vector<mpz_class>;

// Whether two rows are proportional as vectors of polynomials (every 2 x 2
// minor identically zero): the same plane up to a factor that is a
// function of t of one sign (a norm |q(t)|^2, or its negative).
bool proportional(const Int_row& u, const Int_row& v)
{
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) {
      Int_poly d = u[a] * v[b] - u[b] * v[a];
      for (int i = 0; i < d.size(); ++i)
        if (d[i] != 0) return false;
    }
  return true;
}

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

// The 4 x 4 determinant of rows i < j < k < l by the last column: the
// offsets e against the minors of the normals.
template <class Normals>
Int_poly full_minor(const std::vector<Int_row>& r, const Minor_rows& m, Normals& D)
{
  auto [i, j, k, l] = m;
  return r[j][3] * D(i, k, l) - r[i][3] * D(j, k, l) + r[l][3] * D(i, j, k) - r[k][3] * D(i, j, l);
}

// The 2 x 2 minors of rows (i, j) over each two of the four columns.
void pair_minors(const std::vector<Int_row>& r, int i, int j, Minor_table& table)
{
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) table.add(r[i][a] * r[j][b] - r[i][b] * r[j][a], {i, j, -1, -1});
}

// The 3 x 3 minors of rows (i, j, k) over each three of the four columns.
void low_rank_minors(const std::vector<Int_row>& r, int i, int j, int k, Minor_table& table)
{
  for (int drop = 0; drop < 3; ++drop) {
    std::array<Int_row, 3> rows = {r[i], r[j], r[k]};
    for (auto& row : rows) row[drop] = row[3];   // column `drop` replaced by e
    table.add(normal_minor(rows[0], rows[1], rows[2]), {i, j, k, -1});
  }
}

// A filter before any exact minor (one predicate: "this minor has no root
// on [lo, hi]"): the rows evaluated in intervals on a few closed pieces of
// [lo, hi] that cover it; a minor whose interval value excludes 0 on every
// piece has no root there, surely, and is not made exactly. Minors the
// intervals cannot settle are made and solved exactly as before.
class Interval_rows {
public:
  using I = CGAL::Interval_nt<false>;
  static constexpr int pieces = 32;

  Interval_rows(const std::vector<Moving_plane>& planes, const Rational& lo, const Rational& hi)
  {
    CGAL::Protect_FPU_rounding<true> upward;
    at_.resize(pieces);
    for (int k = 0; k < pieces; ++k) {
      I t(CGAL::to_interval(lo + (hi - lo) * Rational(k, pieces)).first,
          CGAL::to_interval(lo + (hi - lo) * Rational(k + 1, pieces)).second);
      for (const Moving_plane& h : planes) {
        std::array<I, 4> v;
        for (int c = 0; c < 4; ++c) v[c] = horner(h[c], t);
        at_[k].push_back(v);
      }
    }
  }

  // Whether the minor of these rows (four, or three with v_inf: -1 last)
  // surely has no root on [lo, hi] that is a critical time: non-zero on
  // every piece, or exactly 0 on one (a polynomial that vanishes on an
  // interval is identically zero: a plane's structural zeros, such as the
  // z part of a vertical plane turning about z, are exact in intervals).
  bool settled(const Minor_rows& m) const
  {
    CGAL::Protect_FPU_rounding<true> upward;
    bool nonzero = true;
    for (const auto& rows : at_) {
      I d = m[3] < 0 ? normal(rows, m[0], m[1], m[2]) : full(rows, m);
      if (d.inf() == 0 && d.sup() == 0) return true;
      nonzero = nonzero && (d.inf() > 0 || d.sup() < 0);
    }
    return nonzero;
  }

private:
  static I horner(const Time_poly& p, const I& t)
  {
    I v(0);
    for (int i = p.size() - 1; i >= 0; --i) v = v * t + I(CGAL::to_interval(p[i]));
    return v;
  }
  static I normal(const std::vector<std::array<I, 4>>& r, int i, int j, int k)
  {
    return normal_minor(r[i], r[j], r[k]);
  }
  static I full(const std::vector<std::array<I, 4>>& r, const Minor_rows& m)
  {
    auto [i, j, k, l] = m;
    return r[j][3] * normal(r, i, k, l) - r[i][3] * normal(r, j, k, l) + r[l][3] * normal(r, i, j, k) -
           r[k][3] * normal(r, i, j, l);
  }

  std::vector<std::vector<std::array<I, 4>>> at_;   // [piece][row]
};

// The exact minors of the normals, made when a full minor needs them.
class Normal_minors {
public:
  explicit Normal_minors(const std::vector<Int_row>& rows) : rows_(rows) {}
  const Int_poly& operator()(int i, int j, int k)
  {
    auto [it, added] = made_.try_emplace({i, j, k});
    if (added) it->second = normal_minor(rows_[i], rows_[j], rows_[k]);
    return it->second;
  }

private:
  const std::vector<Int_row>& rows_;
  std::map<std::array<int, 3>, Int_poly> made_;
};

} // namespace

namespace {

void check_minor_count(int m, int split)
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

// Which object each row is a plane of. A plane both objects have (a face
// of each on z = 0, both turning about z: rows equal up to a factor of one
// sign) is one row of both, its first copy: a minor of it with one
// object's planes keeps its sign, and a minor with another copy is a
// multiple of one with the first.
class Row_owners {
public:
  Row_owners(const std::vector<Int_row>& rows, int split) : owner_(rows.size()), first_(rows.size())
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

} // namespace

Critical_times::Critical_times(const std::vector<Moving_plane>& planes, std::size_t first_count, const Rational& lo,
                               const Rational& hi, bool low_rank)
{
  std::vector<Int_row> rows;
  rows.reserve(planes.size());
  for (const Moving_plane& h : planes) rows.push_back(integer_row(h));
  int m = static_cast<int>(rows.size());
  check_minor_count(m, static_cast<int>(first_count));
  Row_owners owners(rows, static_cast<int>(first_count));
  Interval_rows filter(planes, lo, hi);
  Normal_minors normals(rows);
  Minor_table table;
  if (low_rank)
    for (int i = 0; i < m; ++i)
      for (int j = i + 1; j < m; ++j)
        if (owners.mixed({i, j})) pair_minors(rows, i, j, table);
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j)
      for (int k = j + 1; k < m; ++k)
        if (owners.mixed({i, j, k})) {
          // with v_inf: parallel planes, or three meeting at infinity
          if (!filter.settled({i, j, k, -1})) table.add(normals(i, j, k), {i, j, k, -1});
          if (low_rank) low_rank_minors(rows, i, j, k, table);
        }
  std::size_t made = 0;
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j)
      for (int k = j + 1; k < m; ++k)
        for (int l = k + 1; l < m; ++l)
          if (owners.mixed({i, j, k, l})) {
            if (!filter.settled({i, j, k, l})) table.add(full_minor(rows, {i, j, k, l}, normals), {i, j, k, l});
            if (++made % 4096 == 0) Work_budget::check();
          }
  solve(table.table(), lo, hi);
}

void Critical_times::solve(const std::map<std::vector<mpz_class>, std::vector<Minor_rows>>& table, const Rational& lo,
                           const Rational& hi)
{
  for (const auto& [key, minors] : table) {
    Work_budget::check();
    minor_count_ += minors.size();
    for (Algebraic& r : Algebraic::real_roots(key, lo, hi)) {
      if (compare(r, lo) <= 0 || compare(r, hi) >= 0) continue;
      times_.push_back({std::move(r), minors});
    }
  }
  std::sort(times_.begin(), times_.end(), [](const Critical_time& a, const Critical_time& b) { return a.t < b.t; });
  // Equal roots of different polynomials: one critical time.
  std::vector<Critical_time> merged;
  for (Critical_time& c : times_) {
    if (!merged.empty() && merged.back().t == c.t) {
      merged.back().vanishing.insert(merged.back().vanishing.end(), c.vanishing.begin(), c.vanishing.end());
      continue;
    }
    merged.push_back(std::move(c));
  }
  times_ = std::move(merged);
}

} // namespace clash4d

#include "rotation/Critical_times.h"

#include "search/Work_budget.h"

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
Int_poly full_minor(const std::vector<Int_row>& r, const Minor_rows& m, const std::map<std::array<int, 3>, Int_poly>& normals)
{
  auto D = [&](int a, int b, int c) -> const Int_poly& { return normals.at({a, b, c}); };
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

} // namespace

Critical_times::Critical_times(const std::vector<Moving_plane>& planes, std::size_t first_count, const Rational& lo,
                               const Rational& hi, bool low_rank)
{
  std::vector<Int_row> rows;
  rows.reserve(planes.size());
  for (const Moving_plane& h : planes) rows.push_back(integer_row(h));
  int m = static_cast<int>(rows.size()), split = static_cast<int>(first_count);
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
  auto mixed = [&](std::initializer_list<int> ids) {
    bool a = false, b = false;
    for (int i : ids) (i < split ? a : b) = true;
    return a && b;
  };
  std::map<std::array<int, 3>, Int_poly> normals;
  Minor_table table;
  if (low_rank)
    for (int i = 0; i < m; ++i)
      for (int j = i + 1; j < m; ++j)
        if (mixed({i, j})) pair_minors(rows, i, j, table);
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j)
      for (int k = j + 1; k < m; ++k) {
        Int_poly d = normal_minor(rows[i], rows[j], rows[k]);
        if (mixed({i, j, k})) {
          table.add(d, {i, j, k, -1});   // with v_inf: parallel or meeting at infinity
          if (low_rank) low_rank_minors(rows, i, j, k, table);
        }
        normals.emplace(std::array<int, 3>{i, j, k}, std::move(d));
      }
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j)
      for (int k = j + 1; k < m; ++k)
        for (int l = k + 1; l < m; ++l)
          if (mixed({i, j, k, l})) {
            table.add(full_minor(rows, {i, j, k, l}, normals), {i, j, k, l});
            if (++minor_count_ % 4096 == 0) Work_budget::check();
          }
  minor_count_ = 0;
  for (const auto& [key, minors] : table.table()) {
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

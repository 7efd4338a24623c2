#include "certify/Polynomial_conflict.h"

#include "certify/Coefficients.h"
#include "certify/Positivity.h"

namespace clash4d {
namespace {

using CGAL::is_zero;   // exact on Rational
bool is_zero(const Time_poly& p) { return is_zero_polynomial(p); }

using Column = std::array<Time_poly, 4>;   // one literal's (n, e), or the slack's (0, 0, 0, -1)
using Matrix = std::vector<std::vector<Rational>>;

// A basis of the kernel of m (rows x columns), by Gauss-Jordan elimination.
std::vector<std::vector<Rational>> kernel(Matrix m, std::size_t columns)
{
  std::vector<int> pivot_of(columns, -1);
  std::size_t row = 0;
  for (std::size_t c = 0; c < columns && row < m.size(); ++c) {
    std::size_t p = row;
    while (p < m.size() && is_zero(m[p][c])) ++p;
    if (p == m.size()) continue;
    std::swap(m[p], m[row]);
    for (std::size_t r = 0; r < m.size(); ++r) {
      if (r == row || is_zero(m[r][c])) continue;
      Rational f = m[r][c] / m[row][c];
      for (std::size_t k = 0; k < columns; ++k) m[r][k] -= f * m[row][k];
    }
    pivot_of[c] = static_cast<int>(row++);
  }
  std::vector<std::vector<Rational>> basis;
  for (std::size_t free = 0; free < columns; ++free) {
    if (pivot_of[free] >= 0) continue;
    std::vector<Rational> v(columns, Rational(0));
    v[free] = 1;
    for (std::size_t c = 0; c < columns; ++c)
      if (pivot_of[c] >= 0) v[c] = -m[pivot_of[c]][free] / m[pivot_of[c]][c];
    basis.push_back(std::move(v));
  }
  return basis;
}

// Caratheodory: moves mu (> 0 on `support`, in the kernel) along other
// kernel directions until the support's kernel is one line. With
// keep_last, the last column's weight is never moved (the slack).
void reduce_support(const std::vector<Column>& cols, const Rational& s, std::vector<Rational>& mu,
                    std::vector<std::size_t>& support, bool keep_last)
{
  for (;;) {
    Matrix m(4, std::vector<Rational>(support.size()));
    for (int r = 0; r < 4; ++r)
      for (std::size_t j = 0; j < support.size(); ++j) m[r][j] = cols[support[j]][r].at(s);
    auto basis = kernel(m, support.size());
    if (basis.size() <= 1) return;
    // A kernel vector that is not mu's direction (two independent ones exist).
    std::vector<Rational> nu = basis[0];
    bool parallel = true;
    for (std::size_t j = 0; j < support.size(); ++j) parallel = parallel && nu[j] * mu[support[0]] == mu[support[j]] * nu[0];
    if (parallel) nu = basis[1];
    std::size_t last = support.size() - 1;
    if (keep_last && support.back() == cols.size() - 1) {
      Rational f = nu[last] / mu[support[last]];
      for (std::size_t j = 0; j < support.size(); ++j) nu[j] -= f * mu[support[j]];
    }
    bool any_positive = false;
    for (const Rational& x : nu) any_positive = any_positive || CGAL::sign(x) == CGAL::POSITIVE;
    if (!any_positive)
      for (Rational& x : nu) x = -x;
    std::optional<Rational> theta;
    for (std::size_t j = 0; j < support.size(); ++j)
      if (CGAL::sign(nu[j]) == CGAL::POSITIVE && (!theta || mu[support[j]] / nu[j] < *theta)) theta = mu[support[j]] / nu[j];
    std::vector<std::size_t> kept;
    for (std::size_t j = 0; j < support.size(); ++j) {
      mu[support[j]] -= *theta * nu[j];
      if (!is_zero(mu[support[j]])) kept.push_back(support[j]);
    }
    support = kept;
  }
}

// det of the square matrix of polynomials (at most 3 x 3 here).
Time_poly det(const std::vector<std::vector<Time_poly>>& m)
{
  std::size_t n = m.size();
  if (n == 0) return Time_poly(Rational(1));
  if (n == 1) return m[0][0];
  if (n == 2) return m[0][0] * m[1][1] - m[0][1] * m[1][0];
  Time_poly out(Rational(0));
  for (std::size_t j = 0; j < n; ++j) {
    std::vector<std::vector<Time_poly>> minor;
    for (std::size_t r = 1; r < n; ++r) {
      std::vector<Time_poly> row;
      for (std::size_t c = 0; c < n; ++c)
        if (c != j) row.push_back(m[r][c]);
      minor.push_back(row);
    }
    Time_poly term = m[0][j] * det(minor);
    out = j % 2 ? out - term : out + term;
  }
  return out;
}

// The cofactor dependence of the support's columns over the rows `rows`
// (one fewer than the columns), signed to agree with mu at s; none when it
// vanishes at s or disagrees with mu there.
std::optional<std::vector<Time_poly>> cofactors(const std::vector<Column>& cols, const std::vector<std::size_t>& support,
                                                const std::vector<int>& rows, const std::vector<Rational>& mu,
                                                const Rational& s)
{
  std::vector<Time_poly> lambda;
  for (std::size_t j = 0; j < support.size(); ++j) {
    std::vector<std::vector<Time_poly>> m;
    for (int r : rows) {
      std::vector<Time_poly> row;
      for (std::size_t k = 0; k < support.size(); ++k)
        if (k != j) row.push_back(cols[support[k]][r]);
      m.push_back(row);
    }
    Time_poly d = det(m);
    lambda.push_back(j % 2 ? -d : d);
  }
  Rational scale = lambda[0].at(s) / mu[support[0]];
  if (is_zero(scale)) return std::nullopt;
  for (std::size_t j = 0; j < support.size(); ++j)
    if (lambda[j].at(s) != scale * mu[support[j]]) return std::nullopt;
  if (CGAL::sign(scale) == CGAL::NEGATIVE)
    for (Time_poly& p : lambda) p = -p;
  return lambda;
}

// The row sets to try, those without e first (the identity must hold in
// x, y and z; the e row is the slack's to show).
std::vector<std::vector<int>> row_choices(std::size_t size)
{
  std::vector<std::vector<int>> out;
  for (unsigned mask = 0; mask < 16; ++mask) {
    std::vector<int> rows;
    for (int r = 0; r < 4; ++r)
      if (mask >> r & 1) rows.push_back(r);
    if (rows.size() == size) out.push_back(rows);
  }
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.back() < b.back(); });
  return out;
}

using coefficients::Poly;
using coefficients::divide;
using coefficients::gcd;
using coefficients::trimmed;

// The multipliers divided by their common factor, signed to keep their
// signs at s: cofactors can share a factor that vanishes at a piece's end
// (all of them zero there proves nothing in closed semantics).
void without_common_factor(std::vector<Time_poly>& lambda, const Rational& s)
{
  Poly g;
  for (const Time_poly& l : lambda) g = gcd(g, l.coefficients());
  if (g.size() <= 1) return;
  Rational at_s(0);
  for (std::size_t i = g.size(); i-- > 0;) at_s = at_s * s + g[i];
  for (Rational& c : g) c /= at_s;   // g(s) = 1
  for (Time_poly& l : lambda) {
    Poly a = l.coefficients();
    l = Time_poly(trimmed(divide(a, g)));
  }
}

} // namespace

Time_poly Polynomial_conflict::slack() const
{
  Time_poly out(Rational(0));
  for (std::size_t i = 0; i < literals.size(); ++i) out += lambda[i] * literals[i][3];
  return out;
}

bool Polynomial_conflict::valid_on(const Algebraic& lo, const Algebraic& hi, bool strict, bool open_end) const
{
  bool some = false;
  for (const Time_poly& l : lambda) {
    if (!nonnegative_on(l.coefficients(), lo, hi)) return false;
    some = some || !is_zero(l);
  }
  if (strict) return some && nonnegative_on(slack().coefficients(), lo, hi);
  return positive_on(slack().coefficients(), lo, hi, !open_end);
}

std::optional<Polynomial_conflict> lift_conflict(const std::vector<Moving_plane>& literals,
                                                 const std::vector<Rational>& lambda, const Rational& s, bool keep_slack)
{
  std::vector<Column> cols(literals.begin(), literals.end());
  cols.push_back({Time_poly(Rational(0)), Time_poly(Rational(0)), Time_poly(Rational(0)), Time_poly(Rational(-1))});
  std::vector<Rational> mu = lambda;
  Rational slack(0);
  for (std::size_t i = 0; i < literals.size(); ++i) slack += lambda[i] * literals[i][3].at(s);
  mu.push_back(slack);
  std::vector<std::size_t> support;
  for (std::size_t j = 0; j < mu.size(); ++j)
    if (CGAL::sign(mu[j]) == CGAL::POSITIVE) support.push_back(j);
  if (CGAL::sign(slack) == CGAL::NEGATIVE || support.empty()) return std::nullopt;
  reduce_support(cols, s, mu, support, keep_slack);
  for (const std::vector<int>& rows : row_choices(support.size() - 1)) {
    auto l = cofactors(cols, support, rows, mu, s);
    if (!l) continue;
    without_common_factor(*l, s);
    Polynomial_conflict c;
    for (std::size_t j = 0; j < support.size(); ++j) {
      if (support[j] == literals.size()) continue;   // the slack's weight is the e sum's
      c.literals.push_back(literals[support[j]]);
      c.lambda.push_back((*l)[j]);
    }
    bool identity = true;
    for (int r = 0; r < 3 && identity; ++r) {
      Time_poly sum(Rational(0));
      for (std::size_t i = 0; i < c.literals.size(); ++i) sum += c.lambda[i] * c.literals[i][r];
      identity = is_zero(sum);
    }
    if (identity && !c.literals.empty()) return c;
  }
  return std::nullopt;
}

} // namespace clash4d

#include "search/Motzkin_lp.h"

#include "numbers/Exact_lp.h"
#include "search/Double_simplex.h"
#include <CGAL/Gmpz.h>
#include <CGAL/Gmpzf.h>

namespace clash4d {
namespace {

using Lp = CGAL::Quadratic_program<CGAL::Gmpz>;

// Gmpzf is man * 2^exp.
Rational to_rational(const CGAL::Gmpzf& x)
{
  Rational m(x.man());
  long e = x.exp();
  return e >= 0 ? m * power_of_two(static_cast<int>(e)) : m / power_of_two(static_cast<int>(-e));
}

CGAL::Gmpz integer(const Rational& q) { return q.numerator(); }   // literals are integers

// sum lambda (a, b, c, e_t) = 0 and sum lambda = 1 over lambda >= 0.
Lp dual_program(const std::vector<Motzkin_row>& rows)
{
  Lp lp(CGAL::EQUAL, true, 0, false, 0);
  for (int j = 0; j < static_cast<int>(rows.size()); ++j) {
    for (int i = 0; i < 4; ++i) lp.set_a(j, i, integer((*rows[j].h)[i]));
    lp.set_a(j, 4, 1);
  }
  for (int i = 0; i < 4; ++i) lp.set_b(i, 0);
  lp.set_b(4, 1);
  return lp;
}

std::optional<std::vector<Rational>> solved(const Lp& lp, std::size_t n)
{
  CGAL::Quadratic_program_solution<CGAL::Gmpzf> s = solve_exact_lp(lp, CGAL::Gmpzf());
  if (!s.is_optimal()) return std::nullopt;
  std::vector<Rational> lambda;
  for (auto it = s.variable_values_begin(); it != s.variable_values_end(); ++it)
    lambda.push_back(to_rational(it->numerator()) / to_rational(it->denominator()));
  lambda.resize(n, Rational(0));
  return lambda;
}

// The basic solution on the support: sum lambda_j (a_j, 1) = (0, 0, 0, 0, 1)
// solved exactly by Gauss-Jordan elimination, when it has one solution.
std::optional<std::vector<Rational>> basic_solution(const std::vector<Motzkin_row>& rows, const std::vector<int>& support)
{
  const int k = static_cast<int>(support.size());
  std::vector<std::vector<Rational>> M(5, std::vector<Rational>(static_cast<std::size_t>(k + 1)));
  for (int c = 0; c < k; ++c) {
    for (int i = 0; i < 4; ++i) M[i][c] = (*rows[static_cast<std::size_t>(support[c])].h)[i];
    M[4][c] = 1;
  }
  M[4][k] = 1;
  for (int c = 0; c < k; ++c) {
    int p = c;
    while (p < 5 && CGAL::sign(M[p][c]) == CGAL::ZERO) ++p;
    if (p == 5) return std::nullopt;   // dependent columns: not one solution
    std::swap(M[p], M[c]);
    for (int i = 0; i < 5; ++i)
      if (i != c && CGAL::sign(M[i][c]) != CGAL::ZERO) {
        Rational f = M[i][c] / M[c][c];
        for (int j = c; j <= k; ++j) M[i][j] -= f * M[c][j];
      }
  }
  for (int i = k; i < 5; ++i)
    if (CGAL::sign(M[i][k]) != CGAL::ZERO) return std::nullopt;   // inconsistent
  std::vector<Rational> all(rows.size(), Rational(0));
  for (int c = 0; c < k; ++c) all[static_cast<std::size_t>(support[c])] = M[c][k] / M[c][c];
  return all;
}

} // namespace

bool proves_infeasible(const std::vector<Motzkin_row>& rows, const std::vector<Rational>& lambda)
{
  if (lambda.size() != rows.size()) return false;
  std::array<Rational, 5> sum{};
  bool any = false, strict_part = false;
  for (std::size_t j = 0; j < rows.size(); ++j) {
    if (CGAL::sign(lambda[j]) == CGAL::NEGATIVE) return false;
    if (CGAL::sign(lambda[j]) == CGAL::ZERO) continue;
    any = true;
    strict_part = strict_part || rows[j].strict;
    for (int i = 0; i < 5; ++i) sum[i] += lambda[j] * (*rows[j].h)[i];
  }
  for (int i = 0; i < 4; ++i)
    if (CGAL::sign(sum[i]) != CGAL::ZERO) return false;
  CGAL::Sign e = CGAL::sign(sum[4]);
  return any && (e == CGAL::POSITIVE || (e == CGAL::ZERO && strict_part));
}

namespace {

// A guess at the support of an optimal lambda: the dual LP in doubles, with
// the normalisation sum lambda_j big_j = 1 instead of sum lambda_j = 1 (any
// positive weights exclude lambda = 0 alike): every scaled column has
// entries of at most 1, and a 1 in the last row. Its dual,
// min pi_5 s.t. pi . (a_j / big_j, 1) >= e_j / big_j, is
// min over x = -(pi_1..pi_4) of max_j h_j(x) / big_j (Inside_guess).
std::optional<std::vector<int>> guessed_support(const std::vector<Motzkin_row>& rows, Inside_guess* inside)
{
  Double_simplex lp(5, static_cast<int>(rows.size()), {0, 0, 0, 0, 1});
  for (std::size_t j = 0; j < rows.size(); ++j) {
    const Literal_coefficients& h = *rows[j].h;
    double big = 1.0;
    for (int i = 0; i < 4; ++i) big = std::max(big, std::abs(CGAL::to_double(h[i])));
    double a[5];
    for (int i = 0; i < 4; ++i) a[i] = CGAL::to_double(h[i]) / big;
    a[4] = 1.0;
    lp.column(static_cast<int>(j), a, CGAL::to_double(h[4]) / big);
  }
  std::optional<Double_simplex::Optimum> o = lp.solve();
  if (!o) return std::nullopt;
  if (inside && o->value < 0) {
    for (int i = 0; i < 4; ++i) inside->x[i] = -o->pi[i];
    inside->found = true;
  }
  return std::vector<int>(o->basis.begin(), o->basis.end());
}

std::optional<std::vector<Rational>> on_support(const std::vector<Motzkin_row>& rows, const std::vector<int>& support)
{
  if (auto lambda = basic_solution(rows, support); lambda && proves_infeasible(rows, *lambda)) return lambda;
  std::vector<Motzkin_row> few;
  for (int j : support) few.push_back(rows[static_cast<std::size_t>(j)]);
  Lp lp = dual_program(few);
  for (int j = 0; j < static_cast<int>(few.size()); ++j) lp.set_c(j, -integer((*few[j].h)[4]));
  auto lambda = solved(lp, few.size());
  if (!lambda || !proves_infeasible(few, *lambda)) return std::nullopt;
  std::vector<Rational> all(rows.size(), Rational(0));
  for (std::size_t k = 0; k < support.size(); ++k) all[static_cast<std::size_t>(support[k])] = (*lambda)[k];
  return all;
}

} // namespace

std::optional<std::vector<Rational>> motzkin_multipliers(const std::vector<Motzkin_row>& rows, Lp_effort effort,
                                                        Inside_guess* inside)
{
  if (inside) *inside = Inside_guess();
  if (rows.empty()) return std::nullopt;
  // The exact LP over every row costs about a millisecond; the exact LP
  // over the few rows a double simplex picks, tens of microseconds.
  Inside_guess guess;
  std::optional<std::vector<int>> support = guessed_support(rows, &guess);
  auto none = [&] {
    if (inside) *inside = guess;
    return std::nullopt;
  };
  if (effort == Lp_effort::quick) {   // the guess's basic solution alone: one small exact solve
    if (!support || support->empty()) return none();
    auto lambda = basic_solution(rows, *support);
    if (lambda && proves_infeasible(rows, *lambda)) return lambda;
    return none();
  }
  if (support && !support->empty())
    if (auto lambda = on_support(rows, *support)) return lambda;
  Lp lp = dual_program(rows);
  for (int j = 0; j < static_cast<int>(rows.size()); ++j) lp.set_c(j, -integer((*rows[j].h)[4]));   // max sum lambda e
  auto lambda = solved(lp, rows.size());
  if (!lambda) return none();
  if (proves_infeasible(rows, *lambda)) return lambda;
  // Optimum 0 (or below): a proof needs weight on a strict row with sum e >= 0.
  Lp second = dual_program(rows);
  for (int j = 0; j < static_cast<int>(rows.size()); ++j) {
    second.set_a(j, 5, integer((*rows[j].h)[4]));
    if (rows[j].strict) second.set_c(j, -1);
  }
  second.set_b(5, 0);
  second.set_r(5, CGAL::LARGER);
  lambda = solved(second, rows.size());
  if (lambda && proves_infeasible(rows, *lambda)) return lambda;
  return none();
}

} // namespace clash4d

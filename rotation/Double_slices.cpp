#include "rotation/Double_slices.h"

#include "float/Double_instantiation.h"
#include "rotation/Cell_vertices.h"
#include "rotation/Rotating_pair.h"
#include "rotation/Pair_minors.h"

#include <CGAL/Interval_nt.h>
#include <unsupported/Eigen/Polynomials>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace clash4d {

namespace {

using Double_poly = Polynomial<double, 16>;
using Double_row = std::array<Double_poly, 4>;

Double_row double_row(const Moving_plane& h)
{
  Double_row out;
  for (int c = 0; c < 4; ++c) {
    std::vector<double> coefficients;
    for (int i = 0; i < h[c].size(); ++i) coefficients.push_back(CGAL::to_double(h[c][i]));
    out[c] = Double_poly(coefficients);
  }
  return out;
}

struct Every_minor {
  bool settled(const Minor_rows&) const { return false; }
};

// The filter of the feature minors in doubles: none is ruled out before it
// is made (the real roots are sought in (lo, hi) anyway), and one made is
// identically zero when no coefficient exceeds 1e-12 of the bound on its
// coefficients, the product of its rows' coefficients' sums of absolute
// values (the rounding of an exact zero is some 1e-15 of it). One taken
// for zero that is not costs the full enumeration, never a touch.
class Double_feature_filter {
public:
  Double_feature_filter(const std::vector<Double_row>& rows, double lo, double hi) : middle_(0.5 * lo + 0.5 * hi)
  {
    for (const Double_row& r : rows) {
      double s = 0;
      for (const Double_poly& p : r)
        for (int i = 0; i < p.size(); ++i) s += std::fabs(p[i]);
      size_.push_back(s);
    }
  }
  static constexpr bool minors_cost_more = false;   // doubles (Pair_minors.h)
  Minor_state whole_state(const Minor_rows&) const { return Minor_state::unsure; }
  Minor_state piece_state(const Minor_rows&) const { return Minor_state::unsure; }
  bool identically_zero(const Double_poly& d, const Minor_rows& m) const
  {
    double bound = 1e-12 * size_[m[0]] * size_[m[1]] * size_[m[2]] * size_[m[3]];
    for (int i = 0; i < d.size(); ++i)
      if (std::fabs(d[i]) > bound) return false;
    return true;
  }
  // Rows are multiplied out in doubles (no filter).
  bool may_be_proportional(int, int) const { return true; }
  // The sign of p at the middle of the interval.
  int sign_inside(const Double_poly& p) const
  {
    double v = p.at(middle_);
    return (v > 0) - (v < 0);
  }

private:
  double middle_;
  std::vector<double> size_;
};

struct Double_minors {
  std::vector<std::pair<Double_poly, Minor_rows>> minors;
  void add(const Double_poly& p, const Minor_rows& rows) { minors.emplace_back(p, rows); }
};

// Whether p keeps one sign on [lo, hi] with room to spare: in intervals
// on 8 pieces, |p| stays above 1e-9 of the sum of its terms' sizes. Such a
// p has no root there that the companion matrix would report as real (its
// complex roots are far from the real line), so the eigenvalues are not
// sought; a p that comes near 0 is solved as before.
bool far_from_zero(const std::vector<double>& c, double lo, double hi)
{
  using I = CGAL::Interval_nt<false>;
  CGAL::Protect_FPU_rounding<true> upward;
  double reach = std::max({1.0, std::fabs(lo), std::fabs(hi)}), size = 0, power = 1;
  for (double x : c) {
    size += std::fabs(x) * power;
    power *= reach;
  }
  double margin = 1e-9 * size;
  const int pieces = 8;
  for (int k = 0; k < pieces; ++k) {
    I t = I(lo) + (I(hi) - I(lo)) * I(k, k + 1) / I(pieces);
    I v(0);
    for (std::size_t i = c.size(); i-- > 0;) v = v * t + I(c[i]);
    if (!(v.inf() > margin || v.sup() < -margin)) return false;
  }
  return true;
}

// The real roots of p in (lo, hi), by the eigenvalues of its companion
// matrix; leading coefficients below 1e-14 of the largest are dropped.
std::vector<double> real_roots(const Double_poly& p, double lo, double hi)
{
  std::vector<double> c = p.coefficients();
  double big = 0;
  for (double x : c) big = std::max(big, std::fabs(x));
  while (!c.empty() && std::fabs(c.back()) <= 1e-14 * big) c.pop_back();
  std::vector<double> out;
  if (c.size() < 2 || far_from_zero(c, lo, hi)) return out;
  if (c.size() == 2) {
    out.push_back(-c[0] / c[1]);
  } else {
    Eigen::PolynomialSolver<double, Eigen::Dynamic> solver(Eigen::Map<const Eigen::VectorXd>(c.data(), c.size()));
    for (const auto& z : solver.roots())
      if (std::fabs(z.imag()) <= 1e-7 * std::max(1.0, std::abs(z))) out.push_back(z.real());
  }
  out.erase(std::remove_if(out.begin(), out.end(), [&](double r) { return !(lo < r && r < hi); }), out.end());
  return out;
}

double at(const Double_poly& p, double t)
{
  double v = 0;
  for (int i = p.size() - 1; i >= 0; --i) v = v * t + p[i];
  return v;
}

std::vector<std::array<double, 4>> rows_at(const std::vector<Moving_plane>& rows, double t)
{
  std::vector<std::array<double, 4>> out(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    Double_row r = double_row(rows[i]);
    for (int c = 0; c < 4; ++c) out[i][c] = at(r[c], t);
  }
  return out;
}

std::array<Algebraic, 3> exact_point(const std::array<double, 3>& x)
{
  return {Algebraic(Rational(x[0])), Algebraic(Rational(x[1])), Algebraic(Rational(x[2]))};
}

bool finite(const std::array<double, 3>& x)
{
  return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

} // namespace

Check_answer Double_slices::check(const Scene& s, const Check_options& o) const
{
  return check_double(s, tolerance_, o);
}

// The static double pipeline can answer with a witness that is not a
// finite double (an overflow or 0/0 in a float subject): that is no point,
// and no Rational holds it (GMP would abort); the answer is refused.
Rational Double_slices::read_answer_number(const std::string& text) const
{
  double x = std::strtod(text.c_str(), nullptr);
  if (!std::isfinite(x))
    throw Rotation_unsupported("the double pipeline answered with a witness coordinate that is not a finite number (" +
                               text + ")");
  return Rational(x);
}

std::vector<Moving_plane> Double_slices::rows(const Rotating_object& a, const Rotating_object& b,
                                              const Rational& at) const
{
  return pair_rows(a, b, at);
}

std::vector<Critical_time> Double_slices::critical_times(const std::vector<Moving_plane>& planes,
                                                         std::size_t first_count, const Rational& lo,
                                                         const Rational& hi, bool low_rank,
                                                         const Pair_features* features) const
{
  std::vector<Double_row> rows;
  for (const Moving_plane& h : planes) rows.push_back(double_row(h));
  Double_minors table;
  if (features) check_feature_minor_count(features->minors.size(), rows.size(), first_count);
  if (!features || !enumerate_feature_minors(rows, static_cast<int>(first_count), *features,
                                             Double_feature_filter(rows, CGAL::to_double(lo), CGAL::to_double(hi)),
                                             table)) {
    // Every mixed minor, as the exact stage (Critical_times.h): no features,
    // or one of them identically zero on the interval.
    table.minors.clear();
    check_pair_minor_count(static_cast<int>(rows.size()), static_cast<int>(first_count));
    enumerate_pair_minors(rows, static_cast<int>(first_count), low_rank, Every_minor(), table);
  }
  std::vector<std::pair<double, Minor_rows>> roots;
  for (const auto& [p, m] : table.minors)
    for (double r : real_roots(p, CGAL::to_double(lo), CGAL::to_double(hi))) roots.emplace_back(r, m);
  std::sort(roots.begin(), roots.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Critical_time> out;
  for (const auto& [r, m] : roots) {
    if (out.empty() || CGAL::to_double(out.back().t.rational()) != r) out.push_back({Algebraic(Rational(r)), {}});
    out.back().vanishing.push_back(m);
  }
  return out;
}

std::optional<Rational> Double_slices::sample(const Algebraic& left, const Algebraic& right) const
{
  double l = left.to_double(), r = right.to_double(), m = 0.5 * l + 0.5 * r;
  if (!(l < m && m < r)) return std::nullopt;
  return Rational(m);
}

// A vertex of the witness's cell at s, where its planes meet at t*: the
// exact stage's construction (Exact_slices.h) in doubles; the vertex at s
// when no vertex's planes meet at t* in doubles, w when the cell has none.
std::array<Algebraic, 3> Double_slices::contact_point(const std::vector<Moving_plane>& rows,
                                                      const std::array<Rational, 3>& w, const Rational& s,
                                                      const Algebraic& t_star, const std::vector<int>& near_rows) const
{
  std::vector<std::array<double, 4>> at_s = rows_at(rows, CGAL::to_double(s)), at_t = rows_at(rows, t_star.to_double());
  std::array<double, 3> wd = {CGAL::to_double(w[0]), CGAL::to_double(w[1]), CGAL::to_double(w[2])};
  std::optional<std::array<double, 3>> x, at_sample;
  cell_vertices(at_s, wd, [&](int i, int j, int k) {
    if (!at_sample) at_sample = cramer_point(at_s[i], at_s[j], at_s[k], det3(at_s[i], at_s[j], at_s[k]));
    double d = det3(at_t[i], at_t[j], at_t[k]);
    if (d != 0) x = cramer_point(at_t[i], at_t[j], at_t[k], d);
    return x && finite(*x);
  }, [](std::size_t, std::size_t, std::size_t, const std::vector<int>&) { return Cell_filter::unknown; }, near_rows);
  if (x && finite(*x)) return exact_point(*x);
  if (at_sample && finite(*at_sample)) return exact_point(*at_sample);
  return {Algebraic(w[0]), Algebraic(w[1]), Algebraic(w[2])};
}

} // namespace clash4d

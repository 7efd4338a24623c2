#include "exact/Ccd_filtered_kernel.h"

#include "numbers/Interval_isolation.h"
#include <algorithm>
#include <cmath>

namespace clash4d {

namespace {

using Interval = Ccd_filtered_kernel::Interval;
using Poly = Polynomial<Interval>;

// Bisections of an isolating enclosure before a sign or a comparison asks
// rationals instead: enough to split roots a few ulps apart.
constexpr int refinements = 40;

// The exact rational work of a fallback (GMP, FLINT, Arb, MPFR) runs with
// the FPU back in its default mode.
struct Nearest {
  CGAL::Protect_FPU_rounding<true> guard{CGAL_FE_TONEAREST};
};

bool surely_zero_poly(const Poly& g)
{
  for (int i = 0; i < g.size(); ++i)
    if (!(g[i].inf() == 0 && g[i].sup() == 0)) return false;
  return true;
}

int sure_sign(const Interval& x) { return Interval_isolation<Poly::capacity>::sure_sign(x); }

} // namespace

Ccd_filtered_kernel::Ccd_filtered_kernel(const Ccd_query& q, const Rational& separation)
  : query_(q), separation_(separation), separation_at_(CGAL::to_interval(separation)),
    p_(q.type(), q.enclosure(),
       CGAL::is_positive(separation) ? std::optional<Interval>(separation_at_ * separation_at_) : std::nullopt)
{
  if (CGAL::FPU_get_cw() != CGAL_FE_UPWARD)
    throw std::logic_error("Ccd_filtered_kernel: made without its Protector (the intervals need upward rounding)");
}

Ccd_rational_kernel& Ccd_filtered_kernel::rational()
{
  if (!rational_) {
    Nearest nearest;
    rational_.emplace(query_, separation_);
  }
  return *rational_;
}

bool Ccd_filtered_kernel::swept_boxes_apart()
{
  bool unsure = false;
  bool apart = clash4d::swept_boxes_apart(type(), query_.enclosure(), [&](const Interval& a, const Interval& b) {
    CGAL::Uncertain<bool> less = a + separation_at_ < b;
    if (CGAL::is_certain(less)) return less.make_certain();
    unsure = true;
    return false;
  });
  if (apart || !unsure) return apart;
  ++exact_questions_;
  Nearest nearest;
  return rational().swept_boxes_apart();
}

bool Ccd_filtered_kernel::boxes_surely_apart(const Ccd_query& q, const Rational& separation)
{
  double d = CGAL::is_zero(separation) ? 0.0 : CGAL::to_interval(separation).second;
  if (!std::isfinite(d)) return false;
  int first = q.type() == Ccd_type::vertex_face ? 1 : 2;
  const auto& e = q.enclosure();
  for (int axis = 0; axis < 3; ++axis) {
    double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
    for (int v = 0; v < 8; ++v) {
      int side = v % 4 < first ? 0 : 1;
      lo[side] = std::min(lo[side], e[static_cast<std::size_t>(v)][static_cast<std::size_t>(axis)].inf());
      hi[side] = std::max(hi[side], e[static_cast<std::size_t>(v)][static_cast<std::size_t>(axis)].sup());
    }
    auto up = [d](double x) { return d == 0 ? x : std::nextafter(x + d, HUGE_VAL); };
    if (up(hi[0]) < lo[1] || up(hi[1]) < lo[0]) return true;
  }
  return false;
}

const std::vector<Ccd_filtered_kernel::Root>& Ccd_filtered_kernel::roots(int name)
{
  auto& r = roots_[static_cast<std::size_t>(name)];
  if (r) return *r;
  r.emplace();
  const Poly& g = p_(name);
  if (surely_zero_poly(g)) return *r;
  std::vector<Isolated_root> found;
  if (Interval_isolation<Poly::capacity>::isolate(g, 0, 1, found)) {
    for (const Isolated_root& x : found) r->push_back(Root{x.at, x.lower_sign, std::nullopt});
    return *r;
  }
  ++exact_questions_;
  Nearest nearest;
  for (const Algebraic& x : rational().roots(name)) r->push_back(Root{x.to_interval(), 0, x});
  return *r;
}

Algebraic Ccd_filtered_kernel::exact(const Time& t)
{
  if (t.name < 0) return Algebraic(Rational(t.value));
  Root& x = root(t);
  if (!x.exact && x.at.inf() == x.at.sup()) x.exact = Algebraic(Rational(x.at.inf()));   // a root at a cut: rational
  if (!x.exact) {
    Nearest nearest;
    // The enclosure's ends are doubles, so dyadic: root_between's interval.
    x.exact = Algebraic::root_between(rational().polynomials()(t.name).coefficients(), Rational(x.at.inf()),
                                      Rational(x.at.sup()));
  }
  return *x.exact;
}

// Halves t's enclosure where a sure sign at its middle says which half
// holds it; false when it cannot be narrowed in intervals. A root that came
// from rationals is left as it is: its enclosure is already narrow
// (numbers/Algebraic.h), and a question it leaves open is one for
// rationals.
bool Ccd_filtered_kernel::refine(const Time& t)
{
  if (t.name < 0) return false;
  Root& x = root(t);
  if (x.lower_sign == 0) return false;
  double lo = x.at.inf(), hi = x.at.sup(), m = lo + (hi - lo) / 2;
  if (!(lo < m && m < hi)) return false;
  int s = sure_sign(p_(t.name).at(Interval(m)));
  if (s == 2 || s == 0) return false;
  x.at = s == x.lower_sign ? Interval(m, hi) : Interval(lo, m);
  return true;
}

int Ccd_filtered_kernel::sign_at(int name, const Time& t)
{
  if (name == t.name) return 0;   // a root of that polynomial, by construction
  const Poly& g = p_(name);
  for (int i = 0;; ++i) {
    int s = sure_sign(g.at(enclosure(t)));
    if (s != 2) return s;
    if (i == refinements || !refine(t)) break;
  }
  ++exact_questions_;
  Algebraic x = exact(t);
  Nearest nearest;
  return Ccd_rational_kernel::sign_of(rational().polynomials()(name), x);
}

int Ccd_filtered_kernel::sign_after(int name, const Time& t)
{
  if (int s = sign_at(name, t)) return s;
  // Zero at t: the first derivative not zero there, in intervals while
  // they are sure.
  Poly g = p_(name);
  for (int order = 1; order < Poly::capacity; ++order) {
    g = g.derivative();
    int s = sure_sign(g.at(enclosure(t)));
    if (s == 2) break;
    if (s != 0) return s;
    if (surely_zero_poly(g)) return 0;
  }
  ++exact_questions_;
  Algebraic x = exact(t);
  Nearest nearest;
  return rational().sign_after(name, x);
}

int Ccd_filtered_kernel::compare(const Time& a, const Time& b)
{
  if (a.name == b.name && a.name >= 0) return a.index < b.index ? -1 : (a.index > b.index ? 1 : 0);
  if (a.name < 0 && b.name < 0) return a.value < b.value ? -1 : (a.value > b.value ? 1 : 0);
  for (int i = 0;; ++i) {
    Interval ea = enclosure(a), eb = enclosure(b);
    if (ea.sup() < eb.inf()) return -1;
    if (eb.sup() < ea.inf()) return 1;
    if (i == refinements) break;
    bool moved = refine(a);
    moved = refine(b) || moved;
    if (!moved) break;
  }
  ++exact_questions_;
  Algebraic x = exact(a), y = exact(b);
  Nearest nearest;
  return clash4d::compare(x, y);
}

Ccd_filtered_kernel::Time Ccd_filtered_kernel::next_time(const Ccd_path& names, const Time& t)
{
  Time best{-1, 0, 1.0};
  for (int name : names) {
    const std::vector<Root>& r = roots(name);
    for (std::size_t i = 0; i < r.size(); ++i) {
      Time candidate{name, static_cast<int>(i), 0};
      if (compare(t, candidate) < 0) {
        if (compare(candidate, best) < 0) best = candidate;
        break;
      }
    }
  }
  return best;
}

} // namespace clash4d

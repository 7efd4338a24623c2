// Certified isolation of a polynomial's real roots in doubles: the filter in
// front of exact root isolation (Arb, numbers/Algebraic.h), as an interval
// sign is the filter in front of a rational one. g has interval
// coefficients that enclose an exact polynomial's (CGAL::Interval_nt, the
// caller holding upward rounding); every root of that polynomial in [a, b]
// is reported in an enclosure holding it and no other root, or the call
// fails (false) and nothing can be concluded.
//
// An end or a cut where g is surely zero is a root of its own (a point
// enclosure: a rational, exactly). Otherwise, on [a, b] with g's signs at
// both ends sure and not zero: g's enclosure over [a, b] excludes zero (no
// root), or g''s does (g strictly monotone: a single simple root exactly
// when the ends' signs differ), or [a, b] is cut in two at a point where
// g's sign is sure (off the dyadic middle, where rational inputs often put
// roots). A double root, roots closer than doubles can tell, or a
// polynomial zero exactly but not surely so in intervals run out of depth
// or budget and fail.
#ifndef CLASH4D_NUMBERS_INTERVAL_ISOLATION_H
#define CLASH4D_NUMBERS_INTERVAL_ISOLATION_H

#include "numbers/Polynomial.h"
#include <CGAL/Interval_nt.h>
#include <algorithm>
#include <utility>
#include <vector>

namespace clash4d {

struct Isolated_root {
  CGAL::Interval_nt<false> at;   // holds the root and no other (a point: the root is that double)
  int lower_sign = 0;            // g's sign at at.inf() (0 for a point)
};

template <int Capacity>
class Interval_isolation {
public:
  using Interval = CGAL::Interval_nt<false>;
  using Poly = Polynomial<Interval, Capacity>;

  static constexpr int depth = 40;    // cuts of one branch
  static constexpr int budget = 160;  // subintervals looked at in all

  // The roots in [a, b] (a < b doubles), ascending; false when intervals
  // cannot certify them. narrow: each enclosure is then halved while the
  // sign at its middle is sure, down to a few ulps (for exact roots made
  // once and compared often).
  static bool isolate(const Poly& g, double a, double b, std::vector<Isolated_root>& out, bool narrow = false)
  {
    Interval_isolation run(g);
    int sa = run.sure_sign_at(a), sb = run.sure_sign_at(b);
    if (sa == 2 || sb == 2) return false;
    if (sa == 0) run.found_.push_back({Interval(a), 0});
    if (!run.inside(a, b, 0)) return false;
    if (sb == 0) run.found_.push_back({Interval(b), 0});
    if (narrow)
      for (Isolated_root& r : run.found_) run.narrow(r);
    out.insert(out.end(), run.found_.begin(), run.found_.end());
    return true;
  }

  // g's sign at t: -1, 0 or 1 when sure, 2 when not.
  static int sure_sign(const Interval& v)
  {
    if (v.inf() > 0) return 1;
    if (v.sup() < 0) return -1;
    return v.inf() == 0 && v.sup() == 0 ? 0 : 2;
  }

private:
  explicit Interval_isolation(const Poly& g) : g_(g), dg_(g.derivative()), ddg_(dg_.derivative()) {}
  int sure_sign_at(double t) const { return sure_sign(g_.at(Interval(t))); }

  // f over [a, b]: Horner's enclosure, narrowed by the mean value form
  // f(m) + f'([a, b]) ([a, b] - m), whose excess shrinks with the square of
  // the width (Horner's only with the width): near a root or an extremum
  // the cuts stop far sooner.
  static Interval over(const Poly& f, const Poly& df, double a, double b)
  {
    Interval t(a, b), horner = f.at(t);
    double m = a + (b - a) / 2;
    Interval mean = f.at(Interval(m)) + df.at(t) * (t - Interval(m));
    double lo = std::max(horner.inf(), mean.inf()), hi = std::min(horner.sup(), mean.sup());
    return lo <= hi ? Interval(lo, hi) : horner;
  }

  void narrow(Isolated_root& r) const
  {
    if (r.lower_sign == 0) return;
    double lo = r.at.inf(), hi = r.at.sup();
    for (int i = 0; i < 64; ++i) {
      double m = lo + (hi - lo) / 2;
      if (!(lo < m && m < hi)) break;
      int s = sure_sign_at(m);
      if (s == 2 || s == 0) break;
      (s == r.lower_sign ? lo : hi) = m;
    }
    r.at = Interval(lo, hi);
  }

  // [a, b] with g's signs at a and b sure.
  bool inside(double a, double b, int level)
  {
    if (--left_ < 0) return false;
    Interval t(a, b);
    if (!over(g_, dg_, a, b).do_overlap(0)) return true;
    if (!over(dg_, ddg_, a, b).do_overlap(0)) {
      int sa = sure_sign_at(a), sb = sure_sign_at(b);   // an end that is a root was reported by its cut
      if (sa != 0 && sb != 0 && sa != sb) found_.push_back({t, sa});
      return true;
    }
    if (level == depth) return false;
    for (double ratio : {0.4142135623730951, 0.5857864376269049, 0.3090169943749474}) {
      double m = a + (b - a) * ratio;
      if (!(a < m && m < b)) return false;
      int sm = sure_sign_at(m);
      if (sm == 2) continue;
      if (!inside(a, m, level + 1)) return false;
      if (sm == 0) found_.push_back({Interval(m), 0});
      return inside(m, b, level + 1);
    }
    return false;
  }

  const Poly& g_;
  Poly dg_, ddg_;
  std::vector<Isolated_root> found_;
  int left_ = budget;
};

} // namespace clash4d

#endif

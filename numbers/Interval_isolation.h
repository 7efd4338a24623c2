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
  // cannot certify them.
  static bool isolate(const Poly& g, double a, double b, std::vector<Isolated_root>& out)
  {
    Interval_isolation run(g);
    int sa = run.sure_sign_at(a), sb = run.sure_sign_at(b);
    if (sa == 2 || sb == 2) return false;
    if (sa == 0) run.found_.push_back({Interval(a), 0});
    if (!run.inside(a, b, 0)) return false;
    if (sb == 0) run.found_.push_back({Interval(b), 0});
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
  explicit Interval_isolation(const Poly& g) : g_(g), dg_(g.derivative()) {}
  int sure_sign_at(double t) const { return sure_sign(g_.at(Interval(t))); }

  // [a, b] with g's signs at a and b sure.
  bool inside(double a, double b, int level)
  {
    if (--left_ < 0) return false;
    Interval t(a, b);
    if (!g_.at(t).do_overlap(0)) return true;
    if (!dg_.at(t).do_overlap(0)) {
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
  Poly dg_;
  std::vector<Isolated_root> found_;
  int left_ = budget;
};

} // namespace clash4d

#endif

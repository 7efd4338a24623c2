// The time slices' numbers in the double instantiation (`check --number
// double` on a turning scene): the float subject the comparer holds against
// the exact answer. The same stage (Rotating_pair.h) with its numbers in
// doubles: the minors made from the rows rounded to doubles, their real
// roots from Eigen's companion-matrix solver, a double midpoint as each
// sample, the static pipeline's double instantiation at each time, and the
// contact point by Cramer's rule in doubles. Every time is a double, so a
// closed question is always asked at a (rational) time, never in Q(r).
#ifndef CLASH4D_ROTATION_DOUBLE_SLICES_H
#define CLASH4D_ROTATION_DOUBLE_SLICES_H

#include "check/Check_answer.h"
#include "numbers/Algebraic.h"
#include "rotation/Contact_at_critical.h"
#include "rotation/Critical_times.h"
#include "rotation/Moving_planes.h"
#include "scene/Scene.h"
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace clash4d {

struct Rotating_object;

class Double_slices {
public:
  static constexpr bool is_exact = false;
  // tolerance: the static double pipeline's (|value| <= tolerance is 0).
  explicit Double_slices(double tolerance) : tolerance_(tolerance) {}

  Check_answer check(const Scene& s, const Check_options& o) const;
  // A number of check's answer: a double's shortest decimal, read back to
  // that double (its exact value).
  Rational read_answer_number(const std::string& text) const;
  // The pair's rows at `at` (pair_rows), read into doubles where asked.
  std::vector<Moving_plane> rows(const Rotating_object& a, const Rotating_object& b, const Rational& at) const;
  // Real roots in (lo, hi) of the mixed minors made in doubles; a root is
  // kept when its imaginary part is at most 1e-7 max(1, |z|) (a double
  // root, a touch, comes out of the eigenvalues as a pair about sqrt(eps)
  // apart). Each time is a double, as an exact Algebraic.
  // features: the only minors to solve (two convex pieces' vertex-face and
  // edge-edge minors), as in the exact stage, unless one of them is
  // identically zero on (lo, hi) (to rounding: Double_slices.cpp); null,
  // or such a zero, for every mixed minor.
  std::vector<Critical_time> critical_times(const std::vector<Moving_plane>& rows, std::size_t first_count,
                                            const Rational& lo, const Rational& hi, bool low_rank,
                                            const Pair_features* features = nullptr) const;
  // The double midpoint of left and right; none when no double lies
  // strictly between their doubles.
  std::optional<Rational> sample(const Algebraic& left, const Algebraic& right) const;
  std::array<Algebraic, 3> contact_point(const std::vector<Moving_plane>& rows, const std::array<Rational, 3>& w,
                                         const Rational& s, const Algebraic& t_star,
                                         const std::vector<int>& near_rows = {}) const;
  // Never asked: every critical time here is a double.
  Contact_at_critical closed_at_irrational(const std::vector<Moving_plane>&, const Rotating_object&,
                                           const Rotating_object&, const Critical_time&) const
  {
    return {};
  }

private:
  double tolerance_;
};

} // namespace clash4d

#endif

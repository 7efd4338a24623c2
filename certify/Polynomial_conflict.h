// A conflict whose multipliers are polynomials in t
// (docs/certificate-format.md, 8.3), made from a static conflict found at a
// rational sample time s: the static multipliers are reduced to a minimal
// positive dependence of the literals' vectors (n_i(s), e_i(s)) and the
// slack (0, 0, 0, -1), and the dependence is then written as Cramer's
// cofactors, which are polynomials in t and a dependence at every t where
// the literals keep their rank (regularised-semantics.md, fact 10: on the
// critical interval around s, and often well beyond it).
#ifndef CLASH4D_CERTIFY_POLYNOMIAL_CONFLICT_H
#define CLASH4D_CERTIFY_POLYNOMIAL_CONFLICT_H

#include "numbers/Algebraic.h"
#include "rotation/Moving_planes.h"
#include "search/Term_search.h"
#include <optional>
#include <vector>

namespace clash4d {

struct Polynomial_conflict {
  Conflict::Of of = Conflict::Of::Both;
  std::vector<Moving_plane> literals;   // as written, each < 0 (or <= 0)
  std::vector<Time_poly> lambda;

  // sum lambda_i e_i.
  Time_poly slack() const;
  // The rules of 8.3 on [lo, hi]: strict (regularised, `of` A or B), or
  // non-strict (`of` both, closed), then on [lo, hi) when open_end.
  bool valid_on(const Algebraic& lo, const Algebraic& hi, bool strict, bool open_end) const;
};

// The static conflict sum lambda_i l_i(s) over the literals (their vectors
// at s make the static conflict's identity hold), lifted to polynomial
// multipliers; keep_slack: sum lambda_i e_i must stay positive (non-strict
// literals). None when no cofactor choice gives an identity in t.
std::optional<Polynomial_conflict> lift_conflict(const std::vector<Moving_plane>& literals,
                                                 const std::vector<Rational>& lambda, const Rational& s,
                                                 bool keep_slack);

} // namespace clash4d

#endif

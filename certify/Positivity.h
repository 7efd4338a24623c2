// The signs a turning certificate claims of a polynomial in t on a piece of
// time (docs/certificate-format.md, 8.1), decided here exactly with the
// pipeline's own algebraic numbers (numbers/Algebraic.h): the writer checks
// each multiplier before it writes it, so a proof the checkers would reject
// is never written. The checkers decide the same claims with code of their
// own (Sturm sequences).
#ifndef CLASH4D_CERTIFY_POSITIVITY_H
#define CLASH4D_CERTIFY_POSITIVITY_H

#include "numbers/Algebraic.h"
#include <vector>

namespace clash4d {

// p's coefficients, constant first. a < b.
// p >= 0 on [a, b]: p = 0, or p > 0 between any two of its roots in (a, b).
bool nonnegative_on(const std::vector<Rational>& p, const Algebraic& a, const Algebraic& b);
// p > 0 on [a, b] (closed_end) or on [a, b).
bool positive_on(const std::vector<Rational>& p, const Algebraic& a, const Algebraic& b, bool closed_end);
// p > 0 on (a, b]: p(b) > 0 and no root of p in (a, b).
bool positive_after(const std::vector<Rational>& p, const Algebraic& a, const Algebraic& b);
bool is_zero_polynomial(const std::vector<Rational>& p);

} // namespace clash4d

#endif

// A rational strictly between two distinct real algebraic numbers, the one
// with the least denominator (Stern-Brocot): the sample times of critical
// intervals (regularised-semantics.md, fact 10) stay short, so witnesses
// read as a person would write them. Between algebraic numbers it is found
// by exact comparisons with the numbers themselves (a Stern-Brocot descent),
// so it does not depend on how far their isolating intervals were refined.
#ifndef CLASH4D_ROTATION_SIMPLEST_RATIONAL_H
#define CLASH4D_ROTATION_SIMPLEST_RATIONAL_H

#include "numbers/Algebraic.h"

namespace clash4d {

// The simplest rational q with lo < q < hi (lo < hi); for rational ends,
// numbers/Rational.h's simplest_between.
Rational simplest_between(const Algebraic& lo, const Algebraic& hi);

} // namespace clash4d

#endif

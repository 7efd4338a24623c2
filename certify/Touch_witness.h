// The closed touch of a pair at an irrational time r
// (docs/certificate-format.md, 8.4): the common point C of both closed
// objects, exact in Q(r) (rotation/Exact_slices.h finds it on the planes
// of a minor that vanishes at r), and for each object a generic witness
// C + delta d at the same time: d points into a cell of the object on the
// planes through C (found in doubles, then checked exactly), and delta is
// halved until no other plane lies between C and the witness.
#ifndef CLASH4D_CERTIFY_TOUCH_WITNESS_H
#define CLASH4D_CERTIFY_TOUCH_WITNESS_H

#include "rotation/Object_parts.h"
#include <nlohmann/json.hpp>

namespace clash4d {

// The `touch` object of a pair that touches at the irrational time r, with
// t_lo <= r <= t_hi (the objects, with their convex pieces). Throws
// Turning_proof_missing when no point or witness is found.
nlohmann::ordered_json touch_at_irrational(const Object_parts& a, const Object_parts& b, const Algebraic& r,
                                           const Rational& t_lo, const Rational& t_hi);

} // namespace clash4d

#endif

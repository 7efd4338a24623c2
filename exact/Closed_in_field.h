// The static closed question at an irrational critical time r of a turning
// pair (regularised-semantics.md, fact 12), asked of the static pipeline
// itself on the number-field kernel (exact/Number_field_kernel.h): each
// shape posed at r, its numbers in Q(r), then the cascade's closed check of
// the two (check/Collision_checker.h), as at a rational time. The turning
// stage (rotation/Exact_slices.cpp) asks it where its own candidate points
// cannot decide: a contact with no vertex in it (an unbounded piece's
// edge on a face), which no vertex-face or edge-edge point finds.
#ifndef CLASH4D_EXACT_CLOSED_IN_FIELD_H
#define CLASH4D_EXACT_CLOSED_IN_FIELD_H

#include "numbers/Algebraic.h"
#include "numbers/Rational.h"
#include "scene/Scene.h"
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace clash4d {

// A polynomial in r, coefficients constant term first.
using Field_poly = std::vector<Rational>;

// A shape posed at r: rotated by R(q(r)) about its origin, then moved to
// c(r) (the spec's pose), each number a polynomial in r.
struct Field_posed {
  const Solid* shape = nullptr;
  std::array<Field_poly, 4> q;   // w x y z, q(r) != 0
  std::array<Field_poly, 3> c;
};

// The static closed question's answer at r: the shapes meet, with a point
// common to both closed shapes (each coordinate a polynomial in r of degree
// below r's); they do not; or the question was not taken on (`refused`
// says why), which the caller reports as not decided, never as an answer.
struct Field_answer {
  bool meet = false;
  std::array<Field_poly, 3> point;
  std::string refused;   // empty: decided
};

// The answer for two shapes posed at the irrational r. Field computations
// are serialised (e-antic refines its numbers' enclosures in place).
Field_answer closed_point_in_field(const Algebraic& r, const Field_posed& a, const Field_posed& b);

} // namespace clash4d

#endif

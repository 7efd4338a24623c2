// The closed question at an irrational critical time (regularised-semantics
// fact 12): a common point of both closed objects there, none, or not
// decided, with the reason. A typed answer, so that the slice search
// chooses what an undecided time means for its goal (Rotating_pair.cpp):
// the first contact is then unknown, but a verdict may still be made later.
#ifndef CLASH4D_ROTATION_CONTACT_AT_CRITICAL_H
#define CLASH4D_ROTATION_CONTACT_AT_CRITICAL_H

#include "numbers/Algebraic.h"
#include <array>
#include <optional>
#include <string>

namespace clash4d {

// Point: the meeting point's form (algebraic coordinates; or quotients of
// polynomials in t, the certificate writer's, in Exact_slices.cpp).
template <class Point>
struct Closed_at_critical {
  std::optional<Point> point;   // where they meet, when they do
  std::string undecided;        // why it is not decided; empty when it is

  bool decided() const { return undecided.empty(); }
};

using Contact_at_critical = Closed_at_critical<std::array<Algebraic, 3>>;

} // namespace clash4d

#endif

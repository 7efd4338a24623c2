// An object of a turning pair and, when it is a union of several bounded
// convex pieces, each piece on its own: a pair of such objects collides
// (or touches) exactly when some pair of pieces does, and its t* is the
// least of theirs, so the minors are those of two pieces' planes, not of
// two whole meshes (docs/rotation.md, Many convex pieces). Read by the
// check (Rotating_check.cpp) and by the certificate writer
// (certify/Turning_prover.cpp).
#ifndef CLASH4D_ROTATION_OBJECT_PARTS_H
#define CLASH4D_ROTATION_OBJECT_PARTS_H

#include "rotation/Rotating_pair.h"
#include <array>
#include <vector>

namespace clash4d {

// A box holding an object over [lo, hi]: its origin's path (linear on each
// segment, so the segment's clipped ends bound it) widened by the shape's
// reach, which no rotation about the origin exceeds. Not bounded: the
// shape is unbounded.
struct Swept_box {
  bool bounded = false;
  std::array<Rational, 3> min, max;
};

Swept_box swept_box(const Rotating_object& o, const Rational& lo, const Rational& hi);
// Whether the boxes overlap (touching included); unbounded boxes may.
bool may_meet(const Swept_box& a, const Swept_box& b);

struct Object_parts {
  Rotating_object whole;
  std::vector<Solid> piece_solids;   // owned here, pointed to by pieces
  std::vector<Rotating_object> pieces;   // none: the object is one piece
  std::vector<Swept_box> piece_boxes;    // over [lo, hi]

  Object_parts(const Scene_object& o, const Rational& lo, const Rational& hi);
  // pieces point into piece_solids: a copy would point into another's.
  Object_parts(const Object_parts&) = delete;
  Object_parts& operator=(const Object_parts&) = delete;
  Object_parts(Object_parts&&) = default;
  Object_parts& operator=(Object_parts&&) = default;

  // The object's parts: its pieces, or the whole when it is one.
  std::size_t count() const { return pieces.empty() ? 1 : pieces.size(); }
  const Rotating_object& part(std::size_t i) const { return pieces.empty() ? whole : pieces[i]; }
};

// f(part of a, part of b) for each pair of parts that may meet (their
// swept boxes overlap when both objects are in pieces), until f returns
// true.
template <class F>
void for_parts_that_may_meet(const Object_parts& a, const Object_parts& b, F&& f)
{
  bool boxes = !a.pieces.empty() && !b.pieces.empty();
  for (std::size_t i = 0; i < a.count(); ++i)
    for (std::size_t j = 0; j < b.count(); ++j)
      if (!boxes || may_meet(a.piece_boxes[i], b.piece_boxes[j]))
        if (f(a.part(i), b.part(j))) return;
}

// The critical times on (lo, hi) of two parts whose rows (pair_rows) are
// given: of their feature minors when features_only and both are convex
// pieces (Critical_times says whether they are: restricted()), of every
// mixed minor otherwise.
Critical_times part_pair_times(const Rotating_object& a, const Rotating_object& b, const std::vector<Moving_plane>& rows,
                               const Rational& lo, const Rational& hi, bool features_only);

// The times on (lo, hi) where the answer about two parts may change, for
// the certificate writer's cuts: part_pair_times' critical times, but for
// two convex pieces with features_only only in the runs the apart cover
// leaves on [lo, hi] and of their near features there (Apart_cover.h;
// docs/rotation.md, Near features). rows: pair_rows at `at`, a time of
// [lo, hi]. restricted: set when they are some features' only.
std::vector<Algebraic> part_pair_events(const Rotating_object& a, const Rotating_object& b,
                                        const std::vector<Moving_plane>& rows, const Rational& at, const Rational& lo,
                                        const Rational& hi, bool features_only, bool& restricted);

} // namespace clash4d

#endif

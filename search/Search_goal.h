// What the division and generate-and-test stages look for: any point inside
// the collision region (stop at the first), or the earliest one (§5: examine
// the earliest regions first and stop only when no earlier point can have
// been missed); in the semantics asked for (search/Semantics.h).
#ifndef CLASH4D_SEARCH_SEARCH_GOAL_H
#define CLASH4D_SEARCH_SEARCH_GOAL_H

#include "geometry/kernel_ft4.h"
#include "numbers/Number_ops.h"
#include "search/Semantics.h"
#include <array>
#include <cstddef>
#include <optional>

namespace clash4d {

template <class FT>
struct Search_goal {
  bool earliest = false;
  Semantics semantics = Semantics::regularised;
  bool found = false;
  bool improved = false;        // set whenever a better point is recorded
  // A point of an open cell inside the formula: on none of the formula's
  // planes or the region's faces (the witness is made from it).
  // Closed semantics: a point of both closed objects instead (it may lie on
  // their planes), with a direction into a cell inside A around it and one
  // into a cell inside B (zero when the point lies on no plane of the
  // object's formula there).
  Vector4<FT> inside = shared_zeros<FT, 4>();
  Vector4<FT> toward_a = shared_zeros<FT, 4>(), toward_b = shared_zeros<FT, 4>();
  // Earliest mode: the least time seen so far over the closure of the
  // collision region (regularised-semantics item 5: a vertex of the
  // arrangement), and the point there.
  FT t_star = zero_value<FT>();
  Vector4<FT> contact = shared_zeros<FT, 4>();
  // Earliest mode: the four planes (the current conquer's layout) that meet
  // at the contact point, when a line of this conquer recorded it
  // (Null_object_test). An edge of the conquer ending where the same four
  // planes meet ends at that very point, whose time is t* exactly: it
  // cannot improve, and no comparison is asked (a tie, which intervals
  // could not certify). Cleared by every other record.
  std::optional<std::array<std::size_t, 4>> vertex;
  std::size_t records = 0;      // improvements so far (a caller sees whether it made one)
  // Recorded by a convex pair's linear programs (search/Convex_pair.h): the
  // region's closure on the sub-span is one convex polyhedron holding the
  // contact point, with `inside` in its interior; closed, cell_a and cell_b
  // are points strictly inside each object at the contact's time (unread
  // in regularised semantics). Every such point sees the contact in its
  // cell's closure.
  struct Convex_record {
    Vector4<FT> cell_a = shared_zeros<FT, 4>(), cell_b = shared_zeros<FT, 4>();
  };
  std::optional<Convex_record> convex;   // none: the search's own record

  // Earliest mode across pairs: a pair whose collision cannot start before
  // the best time of the pairs already examined need not be searched.
  std::optional<FT> ceiling;

  bool done() const { return found && !earliest; }
  // Could a region or edge whose times start at t_from hold a better point?
  // Signs are kernel k's.
  template <class K>
  bool can_improve(const K& k, const FT& t_from) const
  {
    // Not strict: a pair that ties the best must still be found, so that the
    // first pair in order wins ties whatever order the threads ran in.
    if (ceiling && k.less(*ceiling, t_from)) return false;
    return !found || (earliest && k.less(t_from, t_star));
  }

  bool closed() const { return semantics == Semantics::closed; }

  // Whether it improved.
  template <class K>
  bool record(const K& k, const Vector4<FT>& in, const Vector4<FT>& lowest)
  {
    if (found && !k.less(lowest[3], t_star)) return false;
    found = improved = true;
    inside = in;
    t_star = lowest[3];
    contact = lowest;
    vertex.reset();
    convex.reset();
    ++records;
    return true;
  }

  // Closed semantics: the point p is in both closed objects; a and b lead
  // into a cell of each (regularised-semantics item 5: the least time of the
  // touching set is at such a point, a vertex).
  template <class K>
  void record_touch(const K& k, const Vector4<FT>& p, const Vector4<FT>& a, const Vector4<FT>& b)
  {
    if (found && !k.less(p[3], t_star)) return;
    found = improved = true;
    inside = contact = p;
    t_star = p[3];
    vertex.reset();
    convex.reset();
    ++records;
    toward_a = a;
    toward_b = b;
  }
};

} // namespace clash4d

#endif

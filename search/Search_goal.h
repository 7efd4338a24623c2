// What the division and generate-and-test stages look for: any point inside
// the collision region (stop at the first), or the earliest one (§5: examine
// the earliest regions first and stop only when no earlier point can have
// been missed).
#ifndef CLASH4D_SEARCH_SEARCH_GOAL_H
#define CLASH4D_SEARCH_SEARCH_GOAL_H

#include "geometry/kernel_ft4.h"

namespace clash4d {

template <class FT>
struct Search_goal {
  bool earliest = false;
  bool found = false;
  bool improved = false;        // set whenever a better point is recorded
  // A point of an open cell inside the formula: on none of the formula's
  // planes or the region's faces (the witness is made from it).
  Vector4<FT> inside{};
  // Earliest mode: the least time seen so far over the closure of the
  // collision region (regularised-semantics item 5: a vertex of the
  // arrangement), and the point there.
  FT t_star{};
  Vector4<FT> contact{};

  // Earliest mode across pairs: a pair whose collision cannot start before
  // the best time of the pairs already examined need not be searched.
  bool has_ceiling = false;
  FT ceiling{};

  bool done() const { return found && !earliest; }
  // Could a region or edge whose times start at t_from hold a better point?
  // Signs are kernel k's.
  template <class K>
  bool can_improve(const K& k, const FT& t_from) const
  {
    // Not strict: a pair that ties the best must still be found, so that the
    // first pair in order wins ties whatever order the threads ran in.
    if (has_ceiling && k.less(ceiling, t_from)) return false;
    return !found || (earliest && k.less(t_from, t_star));
  }

  template <class K>
  void record(const K& k, const Vector4<FT>& in, const Vector4<FT>& lowest)
  {
    if (found && !k.less(lowest[3], t_star)) return;
    found = improved = true;
    inside = in;
    t_star = lowest[3];
    contact = lowest;
  }
};

} // namespace clash4d

#endif

// The CCD decider, written once over a time kernel K (exact/, float/): a
// sweep of t from 0 to 1 that visits only the times where the answer can
// change, and stops at the first contact, which is t*.
//
// Why it is exact. The static test (Ccd_contact.h) at a time is a path of
// sign questions on named polynomials in t. On an open interval where every
// polynomial the path asked keeps its sign, the test takes the same path and
// gives the same answer. So from a time t where there is no contact, the
// test is run once more with each sign taken just after t (the first
// non-zero derivative's sign); if it fails there too, it fails on all of
// (t, r), r the least root after t of the polynomials it asked (or 1), and
// the next time to look at is r. The contact set is closed, so its least
// element, t*, is one of the times visited: 0, 1, or a root of a polynomial
// the path asked. Each time is a rational or a real algebraic number;
// nothing is sampled or perturbed (regularised-semantics fact 10, in one
// dimension of time, and fact 12: the closed answer at a critical time).
//
// A time kernel K provides:
//   K::Time, K::is_exact         a time (0, 1, or a root of a named polynomial)
//   k.type()                     the query's type
//   k.separated()                whether the names are those of a minimum
//                                separation (ccd_name::separated)
//   k.swept_boxes_apart()        the primitives' boxes over [0, 1] do not meet
//                                (or come within the separation): a quick "no"
//                                that needs no polynomial
//   k.zero()                     t = 0
//   k.is_end(t)                  t = 1
//   k.sign_at(name, t)           the sign of a named polynomial at t
//   k.sign_after(name, t)        its sign on (t, t + e) for small e > 0
//   k.next_time(names, t)        the least root in (t, 1] of the named
//                                polynomials that are not identically zero,
//                                or 1
#ifndef CLASH4D_CCD_CCD_SWEEP_H
#define CLASH4D_CCD_CCD_SWEEP_H

#include "ccd/Ccd_contact.h"
#include <boost/container/small_vector.hpp>
#include <optional>
#include <stdexcept>

namespace clash4d {

template <class Time>
struct Ccd_sweep_result {
  bool collide = false;
  Time t;                // t*, when collide
  Ccd_contact contact;   // how the primitives meet at t*
};

using Ccd_path = boost::container::small_vector<int, 16>;

template <class K>
Ccd_sweep_result<typename K::Time> ccd_sweep(K& k)
{
  using Time = typename K::Time;
  Ccd_sweep_result<Time> result;
  if (k.swept_boxes_apart()) return result;
  Time t = k.zero();
  Ccd_path path;
  for (;;) {
    if (auto c = static_contact(k.type(), k.separated(), [&](int name) { return k.sign_at(name, t); })) {
      result = {true, t, *c};
      return result;
    }
    if (k.is_end(t)) return result;
    path.clear();
    auto after = static_contact(k.type(), k.separated(), [&](int name) {
      path.push_back(name);
      return k.sign_after(name, t);
    });
    if (after) {
      // Exactly, impossible: the contact set is closed. A tolerance can make
      // a float kernel's signs at t and just after t disagree; it answers t.
      if constexpr (K::is_exact) throw std::logic_error("ccd: a contact just after a time but not at it");
      result = {true, t, *after};
      return result;
    }
    t = k.next_time(path, t);
  }
}

} // namespace clash4d

#endif

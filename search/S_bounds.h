// S-bound preprocessing (§4.3): 3D aligned boxes per CSG node rewritten by the
// Upward and Downward rules of figure 2, and at the root of a pair the closed
// form of Appendix B for two boxes moving with constant velocities.
#ifndef CLASH4D_SEARCH_S_BOUNDS_H
#define CLASH4D_SEARCH_S_BOUNDS_H

#include "geometry/Box.h"
#include "model/Csg_model.h"
#include "model/Scene_model.h"
#include "search/Check_stats.h"
#include "search/Stage_clock.h"
#include <vector>

namespace clash4d {

template <class K>
class S_bounds {
public:
  using FT = typename K::FT;
  using Box3 = Box<FT, 3>;
  using Bounds = std::vector<Box3>;   // one per CSG node

  // Passes of the Up/Down rules at most; they converge in a linear number
  // of passes (§5, footnote 7), and stopping early only costs pruning.
  static constexpr int max_passes = 16;

  // closed: for a pair under closed semantics (search/Semantics.h), where
  // bounds that only touch still meet (a box without interior is kept).
  // An object's own bounds are settled without it: a node whose bound has
  // no interior is a null regularised set in either semantics, since both
  // take the solids as regularised sets.
  // keep_doubtful: where an approximate kernel cannot tell whether a box is
  // empty (bounds meeting exactly) or whether a time range is, it keeps the
  // box or the range, which still bounds the node (a box only ever shrinks
  // to a set it contains), and doubted() says so; otherwise such a sign
  // throws, as every sign of the kernel does.
  explicit S_bounds(const K& k, bool closed = false, bool keep_doubtful = false)
    : k_(k), closed_(closed), keep_doubtful_(keep_doubtful) {}

  // A box or a time range was kept undecided (keep_doubtful): the bounds
  // are sound, but not those an exact kernel makes.
  bool doubted() const { return doubted_; }

  // Leaves start at their primitive's box, branches at Omega (§4.3.1).
  Bounds initial(const Csg_model<FT>& m) const
  {
    Bounds beta(m.nodes.size(), Box3::whole());
    for (std::size_t i = 0; i < m.nodes.size(); ++i)
      if (m.nodes[i].op == Csg_node::Op::Primitive) beta[i] = normalised(m.primitives[m.nodes[i].primitive].box);
    return beta;
  }

  // Upward rule bottom-up (children have larger indices than parents).
  bool up(const Csg_model<FT>& m, Bounds& beta) const
  {
    bool changed = false;
    for (std::size_t i = m.nodes.size(); i-- > 0;) {
      const Csg_node& n = m.nodes[i];
      if (n.op == Csg_node::Op::Primitive) continue;
      Box3 s = beta[n.children[0]];
      for (std::size_t c = 1; c < n.children.size(); ++c) {
        if (n.op == Csg_node::Op::Intersection) s = meet(s, beta[n.children[c]]);
        else if (n.op == Csg_node::Op::Union) s = join(s, beta[n.children[c]]);
      }
      changed |= shrink(beta[i], s);
    }
    return changed;
  }

  // Downward rule top-down: a node matters only inside its parent's bound.
  bool down(const Csg_model<FT>& m, Bounds& beta) const
  {
    bool changed = false;
    for (std::size_t i = 1; i < m.nodes.size(); ++i) changed |= shrink(beta[i], beta[m.nodes[i].parent]);
    return changed;
  }

  // Up then Down until no bound moves by a grid step, or max_passes; returns
  // the passes run.
  int settle(const Csg_model<FT>& m, Bounds& beta, int max_passes) const
  {
    int passes = 0;
    while (passes < max_passes) {
      ++passes;
      bool changed = up(m, beta);
      changed |= down(m, beta);
      if (!changed) break;
    }
    return passes;
  }

  // One object's root bound, in its own frame, moving with D(t) = v t + o.
  struct Moving_box {
    Box3* box;
    const Vector3<FT>* v;
    const Vector3<FT>* o;
  };

  // Appendix B: intersect two moving boxes over the time span [tl, th],
  // narrowing the span and both boxes. Returns false when the intersection
  // has no interior (no collision in this span).
  bool meet_moving(Moving_box A, Moving_box B, FT& tl, FT& th) const
  {
    if (A.box->empty || B.box->empty) return false;
    for (int q = 0; q < 3; ++q)
      if (!narrow_time(side(A, q), side(B, q), (*A.v)[q] - (*B.v)[q], tl, th)) return false;
    for (int q = 0; q < 3; ++q) {
      Side a = side(A, q), b = side(B, q);
      FT w = (*B.v)[q] - (*A.v)[q];                 // (v - u)
      FT m1 = Number_ops<FT>::lower(w * tl, w * th), M1 = Number_ops<FT>::upper(w * tl, w * th);
      // a' = max(a, b + min((v-u)t)), alpha' = min(alpha, beta + max((v-u)t)),
      // b' = max(b, a - max((v-u)t)), beta' = min(beta, alpha - min((v-u)t)).
      Side a2 = a, b2 = b;
      if (b.has_lo) raise(a2, b.lo + m1);
      if (b.has_hi) lower(a2, b.hi + M1);
      if (a.has_lo) raise(b2, a.lo - M1);
      if (a.has_hi) lower(b2, a.hi - m1);
      store(A, q, a2);
      store(B, q, b2);
    }
    *A.box = normalised(*A.box);
    *B.box = normalised(*B.box);
    return !A.box->empty && !B.box->empty;
  }

  // A box with no interior is the empty bound (see has_no_interior); closed,
  // only an empty one.
  Box3 normalised(const Box3& b) const
  {
    if (!keep_doubtful_) return (closed_ ? is_empty_box(k_, b) : has_no_interior(k_, b)) ? Box3::nothing() : b;
    if (b.empty) return b;
    for (int q = 0; q < 3; ++q)
      if (b.has_lo[q] && b.has_hi[q] && surely_apart(b.hi[q] - b.lo[q])) return Box3::nothing();
    return b;
  }

private:
  const K& k_;
  bool closed_;
  bool keep_doubtful_;
  mutable bool doubted_ = false;

  // Whether gap (a side's hi - lo, or an overlap's length) leaves no room:
  // regularised, gap <= 0 (no interior); closed, gap < 0. Undecided under
  // keep_doubtful: room, and doubted.
  bool surely_apart(const FT& gap) const
  {
    CGAL::Uncertain<bool> room = k_.is_nonnegative(gap, !closed_);
    if (CGAL::is_certain(room)) return !CGAL::get_certain(room);
    doubted_ = true;
    return false;
  }

  struct Side {   // [lo, hi] of one axis in world coordinates at t = 0
    FT lo, hi;
    bool has_lo, has_hi;
  };

  Side side(const Moving_box& m, int q) const
  {
    const Box3& b = *m.box;
    return {b.has_lo[q] ? b.lo[q] + (*m.o)[q] : FT(0), b.has_hi[q] ? b.hi[q] + (*m.o)[q] : FT(0), b.has_lo[q], b.has_hi[q]};
  }
  void store(const Moving_box& m, int q, const Side& s) const
  {
    Box3& b = *m.box;
    if (s.has_lo) { b.lo[q] = s.lo - (*m.o)[q]; b.has_lo[q] = true; }
    if (s.has_hi) { b.hi[q] = s.hi - (*m.o)[q]; b.has_hi[q] = true; }
  }
  static void raise(Side& s, const FT& lo) { s.lo = s.has_lo ? Number_ops<FT>::upper(s.lo, lo) : lo; s.has_lo = true; }
  static void lower(Side& s, const FT& hi) { s.hi = s.has_hi ? Number_ops<FT>::lower(s.hi, hi) : hi; s.has_hi = true; }

  // Whether beta meet s is beta itself, number for number (Number_ops::
  // same), so that shrinking by s leaves beta as it is (beta, as stored,
  // is normalised already).
  static bool within(const Box3& beta, const Box3& s)
  {
    if (beta.empty || s.empty) return beta.empty;
    for (int q = 0; q < 3; ++q) {
      if (s.has_lo[q] && (!beta.has_lo[q] || !Number_ops<FT>::same(Number_ops<FT>::upper(beta.lo[q], s.lo[q]), beta.lo[q])))
        return false;
      if (s.has_hi[q] && (!beta.has_hi[q] || !Number_ops<FT>::same(Number_ops<FT>::lower(beta.hi[q], s.hi[q]), beta.hi[q])))
        return false;
    }
    return true;
  }

  // ut + a <= q <= ut + alpha and vt + b <= q <= vt + beta give
  // b - alpha <= (u - v) t <= beta - a (Appendix B, "Computing [tl, th]").
  bool narrow_time(const Side& a, const Side& b, const FT& w, FT& tl, FT& th) const
  {
    bool has_low = b.has_lo && a.has_hi, has_high = b.has_hi && a.has_lo;
    FT low = has_low ? b.lo - a.hi : FT(0), high = has_high ? b.hi - a.lo : FT(0);
    if (keep_doubtful_ && !CGAL::is_certain(k_.uncertain_sign(w))) {
      doubted_ = true;   // no narrowing: [tl, th] still bounds the meeting times
      return true;
    }
    CGAL::Sign s = k_.sign(w);
    if (s == CGAL::ZERO) {
      // Same velocity: the overlap along q is the same at every time.
      if (has_low && (keep_doubtful_ ? surely_apart(-low) : no_room(CGAL::opposite(k_.sign(low))))) return false;
      if (has_high && (keep_doubtful_ ? surely_apart(high) : no_room(k_.sign(high)))) return false;
      return !(has_low && has_high && apart(high, low));
    }
    if (s == CGAL::NEGATIVE) std::swap(low, high), std::swap(has_low, has_high);
    if (has_low) tl = Number_ops<FT>::upper(tl, low / w);
    if (has_high) th = Number_ops<FT>::lower(th, high / w);
    return !apart(th, tl);
  }

  // Whether the times or lengths hi >= lo leave no room: regularised, the
  // span must keep an interior (hi > lo); closed, a point (a touch at one
  // instant) is enough.
  bool apart(const FT& hi, const FT& lo) const
  {
    return keep_doubtful_ ? surely_apart(hi - lo) : no_room(k_.compare(hi, lo));
  }
  bool no_room(CGAL::Sign gap) const { return closed_ ? gap == CGAL::NEGATIVE : gap != CGAL::POSITIVE; }

  // beta <- beta meet s; true when it moved by a grid step (Box.h).
  bool shrink(Box3& beta, const Box3& s) const
  {
    if (within(beta, s)) return false;   // most nodes, once settled: no box made
    Box3 r = normalised(meet(beta, s));
    bool changed = !same_on_grid(k_, r, beta);
    beta = r;
    return changed;
  }
};

// The 3D S-bounds of every object on its own (§4.3.1), settled once and
// shared by every pair: §6's per-partner arrays start from these, and each
// pair narrows its own copies. Without S-bounds (--no-sbounds), §4.1's
// original procedure: the leaves' boxes as they are, and each node's the
// box of its children's (the upward rule once: join, meet, a difference's
// first child), so that an object made of bounded primitives has a bounded
// box; its root is "the object enclosed" at each velocity change.
template <class K>
typename S_bounds<K>::Bounds settled_bounds(const K& k, const Csg_model<typename K::FT>& csg, Check_stats& stats,
                                            bool use_sbounds)
{
  S_bounds<K> sb(k);
  typename S_bounds<K>::Bounds b = sb.initial(csg);
  if (use_sbounds) stats.sbound_passes += sb.settle(csg, b, S_bounds<K>::max_passes);
  else sb.up(csg, b);
  return b;
}

template <class K>
std::vector<typename S_bounds<K>::Bounds> settled_bounds_all(const K& k, const Scene_model<K>& model, Check_stats& stats,
                                                             bool use_sbounds)
{
  Stage_clock clock(stats.timed);
  std::vector<typename S_bounds<K>::Bounds> settled;
  for (const auto& o : model.objects) settled.push_back(settled_bounds(k, o.csg, stats, use_sbounds));
  stats.seconds_sbounds += clock.seconds();
  return settled;
}

} // namespace clash4d

#endif

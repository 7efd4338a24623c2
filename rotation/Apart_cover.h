// Where two turning convex pieces are surely apart, found before any minor
// is made: the paper's section 7 runs the algebra only in the regions the
// bounds leave, and this is the time slices' bound (docs/rotation.md,
// Apart pieces). On a closed time interval J, a plane of one piece's
// half-spaces that has every vertex of the other strictly outside it, in
// interval arithmetic over all of J (fact 9: the planes and the vertices
// are polynomials in t, so intervals bound them surely), separates the two
// closed pieces at every t in J. Neither a collision nor a touch happens
// there in either semantics, so no critical time in J can change an answer
// and no static question needs asking in J. Where plain interval
// arithmetic over J cannot tell, the mean value form of the vertex's
// distance polynomial is asked (outside, below).
#ifndef CLASH4D_ROTATION_APART_COVER_H
#define CLASH4D_ROTATION_APART_COVER_H

#include "rotation/Moving_planes.h"
#include "rotation/Rotating_pair.h"
#include <CGAL/Interval_nt.h>
#include <array>
#include <deque>
#include <optional>
#include <utility>
#include <vector>

namespace clash4d {

// A closed time interval the cover could not prove apart.
struct Time_piece {
  Rational lo, hi;
  // lo lies in an interval proved apart (so the closed question at lo is
  // answered: no touch there).
  bool after_apart = false;
};

class Apart_cover {
public:
  // How many times [lo, hi] is cut in two at most: pieces of about 1/64 of it.
  static constexpr int max_depth = 6;

  // a, b: two bounded, full-dimensional convex pieces (Shape_planes::
  // convex_features), under the pose segments in force at time `at`.
  Apart_cover(const Rotating_object& a, const Rotating_object& b, const Rational& at);

  // Whether the pieces are surely apart at every time of [lo, hi].
  bool apart_on(const Rational& lo, const Rational& hi) const;

  // The features of `all` (feature_minors of the same two pieces) whose
  // parts may meet the other piece at some time of [lo, hi]: a feature is
  // left out when its vertex or edge of one piece has all its vertices
  // strictly outside one plane of the other throughout (intervals, as
  // apart_on), since a touch at tau puts the feature that marks it, vertex
  // or edge, in both closed pieces at tau (docs/rotation.md, Near
  // features).
  Pair_features near_features(const Pair_features& all, const Rational& lo, const Rational& hi) const;

  // How many intervals for_each_unsure has proved apart so far.
  std::size_t proved_apart() const { return proved_apart_; }

  // Visits the parts of [lo, hi] not proved apart, in time order: [lo, hi]
  // is cut in two until a part is proved apart or max_depth is reached,
  // and the parts left are joined while they touch, in runs of 1, 2, 4, ...
  // of them (the first answer is often in the first; a long stretch
  // where the pieces come near costs few runs). Stops at the first visit
  // that returns true, and returns whether one did.
  template <class Visit>
  bool for_each_unsure(const Rational& lo, const Rational& hi, Visit&& visit) const
  {
    Runs<Visit> runs(lo, visit);
    return walk(lo, hi, 0, runs) || runs.flush();
  }

private:
  using I = CGAL::Interval_nt<false>;
  using Point = std::array<I, 3>;

  // One piece's numbers under its segment, as intervals made once: N(q(t))
  // (|q|^2 times the rotation), |q(t)|^2, the origin c(t), its vertices at
  // rest, and for each of its rows +1 or -1 (inside is orientation * row
  // <= 0).
  struct Side {
    std::array<std::array<Interval_poly, 3>, 3> rotation;
    Interval_poly norm;
    std::array<Interval_poly, 3> origin;
    std::vector<Point> vertices;
    std::vector<int> orientation;
    std::size_t first_row = 0;
    std::vector<std::vector<int>> edges;   // each edge's vertices
    // The vertices where they stay, when the pose's polynomials are all
    // constant (a resting piece): made once, the same intervals as
    // vertices_on at any time.
    std::optional<std::vector<Point>> at_rest;
  };

  // How far outside a plane of one piece a vertex of the other is, as a
  // polynomial in t with interval coefficients: orientation * (n(t) .
  // N'(t) v + (e(t) + n(t) . c'(t)) |q'(t)|^2), the plane's value at the
  // vertex times |q'(t)|^2 > 0 (the vertex's piece primed): > 0 exactly
  // where the vertex is strictly outside. With its derivative.
  struct Reach {
    Interval_poly value, slope;
  };

  // The leaves walk finds, joined into runs (for_each_unsure).
  template <class Visit>
  class Runs {
  public:
    Runs(const Rational& lo, Visit& visit) : lo_(lo), visit_(visit) {}
    bool operator()(const Rational& l, const Rational& h)
    {
      bool touches = has_last_ && last_end_ == l;
      has_last_ = true;
      last_end_ = h;
      if (pending_ && !touches) {
        if (flush()) return true;
        run_ = 1;
      }
      if (!pending_) {
        current_ = {l, h, !(l == lo_) && !touches};
        pending_ = true;
        leaves_ = 0;
      }
      current_.hi = h;
      if (++leaves_ < run_) return false;
      run_ *= 2;
      return flush();
    }
    bool flush()
    {
      if (!pending_) return false;
      pending_ = false;
      return visit_(current_);
    }

  private:
    Rational lo_, last_end_;
    Visit& visit_;
    Time_piece current_;
    bool pending_ = false, has_last_ = false;
    int leaves_ = 0, run_ = 1;
  };

  static Side side(const Rotating_object& o, const Rational& at, std::size_t first_row);
  // Appends o's planes under s to the rows (a's, then b's, as pair_rows).
  void add_rows(const Rotating_object& o, const Side& s);
  std::vector<Point> vertices_on(const Side& s, const I& t) const;
  // The vertices at t from the pose's polynomials, under the caller's
  // rounding guard.
  static std::vector<Point> vertices_at(const Side& s, const I& t);
  // The rows over the times t, under the caller's rounding guard.
  std::vector<std::array<I, 4>> rows_on(const I& t) const;
  // Whether vertex k of the other piece (at points[k] over t) is strictly
  // outside plane p of s at every time of t, under the caller's rounding
  // guard: the plane's value there in intervals, and where that holds 0,
  // the mean value form of its reach, r(mid) + r'(t) (t - mid) (mid: a
  // point of t). Near a touch that leaves out most of the overestimate,
  // which shrinks as t's width squared where the first shrinks as its
  // width, so the cover proves apart up to much nearer the touch.
  bool outside(const Side& s, std::size_t p, const std::vector<std::array<I, 4>>& rows, const std::vector<Point>& points,
               std::size_t k, const I& t, const I& mid) const;
  // The reach of vertex k of the other piece past plane p of s, made when
  // first asked.
  const Reach& reach(const Side& s, std::size_t p, std::size_t k) const;
  // Whether some row of s has every point strictly outside it.
  bool separates(const Side& s, const std::vector<std::array<I, 4>>& rows, const std::vector<Point>& points,
                 const I& t, const I& mid) const;
  // Per part of the other piece (its vertices, then its edges), whether
  // all its points are strictly outside one row of s.
  std::vector<bool> far_parts(const Side& s, const std::vector<std::array<I, 4>>& rows,
                              const std::vector<Point>& points, const std::vector<std::vector<int>>& edges, const I& t,
                              const I& mid) const;
  // [lo, hi] enclosed, and a point of it, under the caller's rounding guard.
  static std::pair<I, I> times(const Rational& lo, const Rational& hi);

  template <class Leaf>
  bool walk(const Rational& lo, const Rational& hi, int depth, Leaf& leaf) const
  {
    if (apart_on(lo, hi)) {
      ++proved_apart_;
      return false;
    }
    if (depth == max_depth) return leaf(lo, hi);
    // Cut at 31/64, not at the half: every cut is then a dyadic with an
    // odd numerator over 64^depth (exact in doubles), never a simple time
    // such as 1/2 or 1/4 where scenes put their contacts. A cut there
    // would leave the double stage a sliver between the cut and its
    // rounded critical time (the exact stage does not care).
    Rational cut = lo + (hi - lo) * Rational(31, 64);
    return walk(lo, cut, depth + 1, leaf) || walk(cut, hi, depth + 1, leaf);
  }

  std::vector<std::array<Interval_poly, 4>> rows_;
  Side a_, b_;
  // Reaches made so far (a memo, not a state): b's vertices past a's
  // planes, then a's past b's, each pair [plane * vertices + vertex] an
  // index into reach_store_ (-1: not made yet), so that only the few the
  // cover asks for are made (a deque: references to them stay valid).
  mutable std::array<std::vector<int>, 2> reach_index_;
  mutable std::deque<Reach> reach_store_;
  mutable std::size_t proved_apart_ = 0;   // a count for --stats, not a state
};

} // namespace clash4d

#endif

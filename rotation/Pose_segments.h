// An object's motion as pose segments: on each, the un-normalised
// quaternion q(t) and the origin c(t) are polynomials in t of degree at most
// one (spec: Motion with rotation (poses); regularised-semantics.md, fact 9).
// A ROBMOD string is the same with q = (1, 0, 0, 0) and c(t) = D(t), so a
// pair of any two motions is read alike.
#ifndef CLASH4D_ROTATION_POSE_SEGMENTS_H
#define CLASH4D_ROTATION_POSE_SEGMENTS_H

#include "numbers/Polynomial.h"
#include "numbers/Rational.h"
#include "scene/Scene.h"
#include <array>
#include <vector>

namespace clash4d {

// Polynomials in t with rational coefficients: products of the degree-one
// pose polynomials reach degree 9 in a minor of four planes.
using Time_poly = Polynomial<Rational, 16>;

// p = 0 as a polynomial: every coefficient is zero, so p vanishes at every
// t (not only at the times asked).
inline bool is_zero_polynomial(const Time_poly& p)
{
  for (int i = 0; i < p.size(); ++i)
    if (CGAL::sign(p[i]) != CGAL::ZERO) return false;
  return true;
}

struct Pose_segment {
  // The closed interval [lo, hi] of the segment; unbounded ends are flagged.
  Rational lo, hi;
  bool from_minus_infinity = false, to_plus_infinity = false;
  std::array<Time_poly, 4> q;   // w x y z
  std::array<Time_poly, 3> c;   // the shape's origin

  bool holds(const Rational& t) const
  {
    return (from_minus_infinity || !(t < lo)) && (to_plus_infinity || !(hi < t));
  }
};

// The segments of m in time order, covering the whole line.
std::vector<Pose_segment> pose_segments(const Motion& m);

// The segment of segments whose closed interval holds t (the first such).
const Pose_segment& segment_at(const std::vector<Pose_segment>& segments, const Rational& t);

} // namespace clash4d

#endif

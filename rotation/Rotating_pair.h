// One pair of objects of which at least one turns, decided exactly by time
// slices (regularised-semantics.md, facts 9 to 12): the critical times of
// the pair's planes cut [tL, tH] into open intervals on which every answer
// about the pair is constant; the static question is asked at one rational
// sample per interval (and, in closed semantics, at each critical time),
// and the static question is the static pipeline's (exact/), unchanged.
#ifndef CLASH4D_ROTATION_ROTATING_PAIR_H
#define CLASH4D_ROTATION_ROTATING_PAIR_H

#include "check/Check_answer.h"
#include "numbers/Algebraic.h"
#include "rotation/Critical_times.h"
#include "rotation/Pose_segments.h"
#include "rotation/Shape_planes.h"
#include "scene/Scene.h"
#include <array>
#include <optional>
#include <stdexcept>
#include <string>

namespace clash4d {

// An object, or one convex piece of it, as the rotation stage reads it.
struct Rotating_object {
  std::string name;             // the object's
  const Solid* solid = nullptr; // its shape or the piece, owned elsewhere
  Shape_planes shape;
  std::vector<Pose_segment> segments;

  static Rotating_object make(const Scene_object& o);
  // A piece of o's shape, moving as o does.
  static Rotating_object piece(const Scene_object& o, const Solid& piece);
};

// A question this release of the stage cannot decide exactly (the reason
// names it); the command reports it as unsupported input, never as an answer.
struct Rotation_unsupported : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What the time slices did (`check --stats`), summed over piece pairs.
struct Slice_counts {
  std::size_t piece_pairs = 0;       // pairs of objects or convex pieces decided
  std::size_t apart_intervals = 0;      // time intervals proved apart (Apart_cover.h)
  std::size_t sliced_intervals = 0;  // time intervals whose critical times were found
  std::size_t critical_times = 0;    // found in them
  std::size_t static_questions = 0;  // static checks at rational times
  std::size_t apart_samples = 0;     // rational times the cover proved apart instead

  Slice_counts& operator+=(const Slice_counts& o)
  {
    piece_pairs += o.piece_pairs;
    apart_intervals += o.apart_intervals;
    sliced_intervals += o.sliced_intervals;
    critical_times += o.critical_times;
    static_questions += o.static_questions;
    apart_samples += o.apart_samples;
    return *this;
  }
};

struct Rotating_answer {
  bool collide = false;
  // Regularised: a rational generic point inside both at a rational time.
  // Closed: a point of both closed objects, possibly at an irrational time.
  std::array<Algebraic, 4> witness;
  bool witness_verified = false;
  bool earliest = false;
  Algebraic t_star;                  // with --earliest
  std::array<Algebraic, 3> contact;  // a point of the closure at t*
  bool at_start = false;
  Slice_counts counts;
};

// The pair's answer on [t_lo, t_hi] by the time slices in the numbers of
// Slices: Exact_slices (exact answers) or Double_slices (the float subject).
template <class Slices>
Rotating_answer decide_rotating_pair(const Rotating_object& a, const Rotating_object& b, const Rational& t_lo,
                                     const Rational& t_hi, const Check_options& options, const Slices& slices);

// lo, the times strictly inside (lo, hi) where either motion changes its
// polynomials (pose times, velocity changes), and hi, ascending.
std::vector<Rational> piece_ends(const Rotating_object& a, const Rotating_object& b, const Rational& lo,
                                 const Rational& hi);

// The events of two bounded, full-dimensional convex pieces, as rows of the
// pair's matrix (a's planes, then b's): the vertex-face and edge-edge
// minors whose roots are the only times their answers can change (why:
// Rotating_pair.cpp); none when either shape is not one such piece.
std::optional<Pair_features> feature_minors(const Shape_planes& a, const Shape_planes& b);

// The rows of fact 10's matrix for a and b on the motion pieces that hold
// `at`: a's planes as polynomials in t, then b's.
std::vector<Moving_plane> pair_rows(const Rotating_object& a, const Rotating_object& b, const Rational& at);
// The same rows each times a positive integer (integer_moving_planes):
// the same half-spaces, for the exact time slices.
std::vector<Moving_plane> integer_pair_rows(const Rotating_object& a, const Rotating_object& b, const Rational& at);

// The scene of the two objects at rest, placed as they are at time t.
Scene posed_pair(const Rotating_object& a, const Rotating_object& b, const Rational& t);

} // namespace clash4d

#endif

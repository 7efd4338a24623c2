// The time slices' numbers in the exact instantiation (`--number exact` and
// `rational`): critical times as exact real algebraic numbers, a rational
// sample strictly inside each interval (the simplest one), the contact
// point exact in Q(t*), and the closed question at an irrational critical
// time decided exactly there (fact 12). Rotating_pair.h runs the slices.
#ifndef CLASH4D_ROTATION_EXACT_SLICES_H
#define CLASH4D_ROTATION_EXACT_SLICES_H

#include "check/Check_answer.h"
#include "exact/Closed_in_field.h"
#include "numbers/Algebraic.h"
#include "rotation/Contact_at_critical.h"
#include "rotation/Critical_times.h"
#include "rotation/Moving_planes.h"
#include "scene/Scene.h"
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace clash4d {

struct Rotating_object;

// The static question at a rational time: a static pipeline's check.
using Static_check = std::function<Check_answer(const Scene&, const Check_options&)>;

// A point as Cramer's quotients num(t) / den(t), den(r) != 0 at the time r
// it is asked at.
struct Quotient_point {
  std::array<Time_poly, 3> num;
  Time_poly den;
};

// The common point closed_at_irrational finds, as quotients in t (what a
// certificate writes in Q(r)); none when there is none.
std::optional<Quotient_point> closed_point_at(const std::vector<Moving_plane>& rows, const Rotating_object& a,
                                              const Rotating_object& b, const Critical_time& c);

// o's shape posed at the irrational r (its pose segment's q and c as
// polynomials): what the static pipeline in Q(r) reads
// (exact/Closed_in_field.h).
Field_posed posed_at(const Rotating_object& o, const Algebraic& r);

// Where the pair's normals span a plane only (rank 2 at s, so on the whole
// critical interval: the minors with v_inf keep their sign there), every
// cell is a prism along the lineality d(t) = n_i(t) x n_j(t) and has no
// vertex. The plane d(t).x + e = 0, e = 0 (or 1 where w is on d(s).x = 0,
// so that w is off it), cuts them all: its minors with three rows are |d| times
// the rows' own minors in d's orthogonal plane, and with two rows and
// v_inf (n_i x n_j).d, so they vanish only where the pair's do, and the
// cut arrangement keeps its vertices' planes on the interval as the pair's
// does. Where the normals are all parallel, as polynomials (rank 1), the
// cells are slabs, and two cuts across n make a point of each face (see
// the .cpp). The cut cell's vertices are points of w's cell's closure:
// where a contact point or a witness path starts (docs/rotation.md). None
// when the normals at s (at: the rows there) have rank 3, or are parallel
// at s only.
std::vector<Moving_plane> lineality_cuts(const std::vector<Moving_plane>& rows,
                                         const std::vector<std::array<Rational, 4>>& at, const Rational& s,
                                         const std::array<Rational, 3>& w);

class Exact_slices {
public:
  static constexpr bool is_exact = true;
  explicit Exact_slices(Static_check check) : check_(std::move(check)) {}

  Check_answer check(const Scene& s, const Check_options& o) const { return check_(s, o); }
  // A number of check's answer: its exact text "p/q".
  Rational read_answer_number(const std::string& text) const { return rational_from_string(text); }
  // The pair's rows (fact 10's matrix) at `at`, each times a positive
  // integer: integer polynomials, since every question asked of them here
  // is about signs, roots and meeting points (integer_pair_rows).
  std::vector<Moving_plane> rows(const Rotating_object& a, const Rotating_object& b, const Rational& at) const;
  // features: the only minors to solve (two convex pieces' vertex-face and
  // edge-edge minors), or null for every mixed minor.
  std::vector<Critical_time> critical_times(const std::vector<Moving_plane>& rows, std::size_t first_count,
                                            const Rational& lo, const Rational& hi, bool low_rank,
                                            const Pair_features* features = nullptr) const
  {
    if (features) return Critical_times(rows, first_count, lo, hi, low_rank, *features).times();
    return Critical_times(rows, first_count, lo, hi, low_rank).times();
  }
  // A rational strictly between left < right: the midpoint of rational
  // ends, else the simplest rational between.
  std::optional<Rational> sample(const Algebraic& left, const Algebraic& right) const;
  // A point of the closure of the collision region at t*, the left end of
  // the interval whose sample s has the generic witness w (Rotating_pair.cpp).
  std::array<Algebraic, 3> contact_point(const std::vector<Moving_plane>& rows, const std::array<Rational, 3>& w,
                                         const Rational& s, const Algebraic& t_star,
                                         const std::vector<int>& near_rows = {}) const;
  // The closed question at an irrational critical time c: a common point
  // of both closed objects, none, or not decided (two unbounded shapes
  // the static pipeline in Q(r) refuses).
  Contact_at_critical closed_at_irrational(const std::vector<Moving_plane>& rows, const Rotating_object& a,
                                           const Rotating_object& b, const Critical_time& c) const;

private:
  Static_check check_;
};

} // namespace clash4d

#endif

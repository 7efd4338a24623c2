// The `fcl` subject: the same scene decided by FCL's continuous collision
// (Flexible Collision Library, Debian's libfcl-dev), the floating-point
// library robotics users rely on, so its answers can be held against the
// exact ones like any other subject (compare/Comparer.h).
//
// FCL can express a scene when every object is a convex polyhedron (block,
// prism, hull, convex, possibly translated or rotated) or a union of such,
// and every object moves with one constant velocity over the whole span
// [tL, tH] (no velocity change strictly inside it): FCL's translation motion
// interpolates one begin and one end placement. An object that turns
// (a pose motion with one pose segment over the span) goes to FCL's screw
// motion between its placements at tL and tH. Other scenes (half-spaces,
// intersections, differences, piecewise motions) are skipped with a reason.
//
// What FCL is asked: conservative advancement (CCDC_CONSERVATIVE_ADVANCEMENT
// with CCDM_TRANS and FCL's own GJK/EPA, GST_INDEP) between every pair of
// convex pieces of two objects. FCL gets doubles: the scene's numbers are
// rounded to the nearest double first (as the double subject reads them);
// each piece is then the exact convex hull of its vertices, each vertex
// rounded to the nearest double, as an fcl::Convexd mesh. A pair
// collides when some pair of pieces does; its time of contact is the smallest
// one, mapped back to t* = tL + toc (tH - tL).
//
// FCL decides closed sets (touching is contact, hence collision) and stops
// advancing within a time tolerance, while the contract's collision is the
// regularised intersection: those disagreements are what the comparer
// classifies. FCL returns no point inside both objects, so the answer has no
// witness point (and no earliest contact point), only the pair and t*.
#ifndef CLASH4D_COMPARE_FCL_SUBJECT_H
#define CLASH4D_COMPARE_FCL_SUBJECT_H

#include "check/Check_answer.h"
#include "scene/Scene.h"
#include <memory>
#include <optional>
#include <string>

namespace clash4d {

class Fcl_subject {
public:
  // Converts the scene to FCL shapes and motions, or records why it cannot
  // ("not expressible by fcl: ...", or "fcl: not built in ..." when clash4d
  // was built without FCL). Never throws for an inexpressible scene.
  explicit Fcl_subject(const Scene& scene);
  ~Fcl_subject();
  Fcl_subject(Fcl_subject&&) noexcept;
  Fcl_subject& operator=(Fcl_subject&&) noexcept;

  // Whether clash4d was built with FCL (CMake option CLASH4D_WITH_FCL).
  static bool built_in();

  bool expressible() const { return reason_.empty(); }
  const std::string& reason() const { return reason_; }

  // Where FCL's motions are not the scene's (regularised-semantics fact
  // 13: a turn at constant angular velocity about a fixed axis matches a
  // pose only when the other object rests and this one turns about a fixed
  // point the shorter way): why, for the first such pair; "" otherwise.
  std::string motion_law() const;

  // FCL's time of contact of objects i and j in [0, 1] (0 at tL, 1 at tH),
  // or nothing when FCL finds no contact. Requires expressible().
  std::optional<double> time_of_contact(int i, int j) const;

  // The answer in the comparer's form: number "fcl"; every non-ignored pair
  // in pair order (stopping at the first colliding one unless all_pairs or
  // earliest); witness and contact points empty (FCL gives none); with
  // earliest, t* as the shortest decimal of its double. Requires expressible().
  Check_answer check(const Check_options& options) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string reason_;
};

} // namespace clash4d

#endif

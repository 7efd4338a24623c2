// The `bullet` subject (--subject bullet): the scene decided by Bullet's
// continuous convex collision (Debian's libbullet-dev, double precision), the
// physics engine of many games and robot simulators, held against the exact
// answer like any other subject (compare/Comparer.h).
//
// Bullet expresses the scenes FCL does (compare/Convex_motion.h): convex
// pieces or unions of them, each object under one translation over the span;
// others are skipped with the reason. Each pair of pieces is a
// btConvexHullShape (collision margin 0) swept by btContinuousConvexCollision
// (conservative advancement on GJK distances, btVoronoiSimplexSolver,
// btGjkEpaPenetrationDepthSolver); a pair collides when some pair of pieces
// hits, at the smallest time of impact. Bullet stops advancing within a
// distance of 1e-4 and counts contact as a hit: it answers the closed
// question with that tolerance, and gives no point.
#ifndef CLASH4D_COMPARE_BULLET_SUBJECT_H
#define CLASH4D_COMPARE_BULLET_SUBJECT_H

#include "check/Check_answer.h"
#include "scene/Scene.h"
#include <memory>
#include <optional>
#include <string>

namespace clash4d {

class Bullet_subject {
public:
  // Converts the scene, or records why not ("not expressible by bullet:
  // ...", or "bullet: not built in ..."). Never throws for such a scene.
  explicit Bullet_subject(const Scene& scene);
  ~Bullet_subject();

  // Whether clash4d was built with Bullet (CMake option CLASH4D_WITH_BULLET).
  static bool built_in();
  // Where Bullet's motions are not the scene's (as Fcl_subject::motion_law;
  // Bullet also clamps a step's turn to pi/4): why, or "".
  std::string motion_law() const;
  // The distance below which its cast reports a hit.
  static constexpr double tolerance = 1e-4;

  bool expressible() const { return reason_.empty(); }
  const std::string& reason() const { return reason_; }

  // The answer in the comparer's form (number "bullet"; no points; t* with
  // earliest). Requires expressible().
  Check_answer check(const Check_options& options) const;

private:
  std::optional<double> time_of_contact(int i, int j) const;
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string reason_;
};

} // namespace clash4d

#endif

// The comparer: runs every subject on a scene and holds it against the exact
// answer in the subject's own semantics (issue 14: a subject is wrong only
// when it is wrong in its own terms), in the spirit of CGAL's Kernel_checker
// (run two kernels side by side; on mismatch report both answers and the
// inputs). Subjects:
//   exact            the reference, regularised (rationals);
//   exact closed     the reference in closed semantics (touching counts);
//   double           the same pipeline on doubles, plain sign tests, in the
//                    semantics asked for (--semantics, default regularised);
//   double tol=EPS   the same with |value| <= EPS treated as zero;
//   exact-rounded    exact arithmetic on the scene with every number rounded
//                    to the nearest double (separates input rounding from
//                    arithmetic, regularised-semantics item 8), likewise;
//   fcl              optional (--fcl): FCL's continuous collision on the
//                    scenes it can express (compare/Fcl_subject.h), closed
//                    semantics; on the others it is skipped with the reason,
//                    which is neither an agreement nor a disagreement. It
//                    gives no witness point, so it is never an "invalid
//                    witness".
//   bullet           optional (--subject bullet): Bullet's continuous convex
//                    collision, closed, on the same scenes as fcl
//                    (compare/Bullet_subject.h).
//   NAME             each --subject NAME=COMMAND (compare/External_subject.h),
//                    in the semantics its hello line declares: "unsupported"
//                    answers are skipped; its witness point is checked against
//                    every pair; a crash, time-out or answer out of protocol
//                    is a fault with that cause.
// Every disagreement is classified by its cause:
//   input rounding   exact (in the subject's semantics) on the rounded scene
//                    already disagrees with exact on the true one; or the
//                    subject is exact-rounded, whose witness is exact for
//                    the rounded scene, and that witness does not hold in
//                    the true one (the verdicts agree);
//   contact          the scene is one of touching only: exact regularised
//                    says no collision and exact closed says the closed
//                    objects meet (regularised-semantics item 6), so the
//                    verdict hinges on what touching means;
//   motion law       a library (fcl, bullet) whose motion passes through
//                    other configurations than the scene's poses (it turns
//                    at constant angular velocity about a fixed axis:
//                    regularised-semantics fact 13), so its verdict answers
//                    another question;
//   tolerance        the subject has a tolerance and exact shows it is what
//                    made the difference: for `double tol=EPS` (EPS bounds the
//                    half-space values as written, not a distance) the same
//                    pipeline without it, `double`, gives exact's verdict;
//                    for a subject declaring a distance tolerance (bullet,
//                    an external subject's hello), exact gives the subject's
//                    verdict on the scene with one object of the pair moved
//                    by a vector no longer than it (one of 26 directions);
//   time             with earliest, the verdicts agree but |t* - exact t*|
//                    exceeds time_bound (decided exactly);
//   arithmetic       otherwise: the subject's own rounding;
//   invalid witness  verdicts agree but the subject's witness does not hold
//                    in the true scene (checked exactly: strictly inside both
//                    objects, or, closed, in both closed objects), the
//                    subject not being exact-rounded.
#ifndef CLASH4D_COMPARE_COMPARER_H
#define CLASH4D_COMPARE_COMPARER_H

#include "compare/Comparison.h"
#include "scene/Scene.h"
#include "search/Semantics.h"
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace clash4d {

class External_pool;

struct Compare_options {
  // The semantics of the toolkit's own float subjects (double, double tol,
  // exact-rounded); every subject is judged in its own.
  Semantics semantics = Semantics::regularised;
  std::vector<double> tolerances{1e-9};   // one "double tol=EPS" subject each
  bool earliest = false;                  // also compare t* (and report its error)
  // With earliest: the largest |t* - exact t*| that is no disagreement
  // (its exact value is the bound; beyond it the cause is `time`).
  double time_bound = 1e-9;
  bool rounded = true;                    // run the exact-rounded subject (--no-rounded: not)
  bool doubles = true;                    // run the double subjects (double, double tol=EPS)
  bool fcl = false;                       // run the fcl subject (skipped where FCL cannot express the scene)
  bool bullet = false;                    // run the bullet subject (likewise)
  // External subjects (--subject NAME=COMMAND): their processes, shared by
  // every copy of these options and kept for the whole run.
  std::vector<std::shared_ptr<External_pool>> externals;
  // Called with each subject's name before it runs (progress on long
  // comparisons); may be empty.
  std::function<void(const std::string& subject)> on_subject;
};

// The comparison of every subject with exact (JSON form in compare/README.md).
Comparison compare_scene(const Scene& scene, const std::string& file, const Compare_options& options);

// The scene with every number replaced by the exact value of its nearest
// double, re-validated; throws Input_error when the rounded scene is invalid
// and std::range_error when a number has no double.
Scene rounded_scene(const Scene& scene);

// The name of the double subject with tolerance tol ("double tol=1e-09").
std::string tolerance_subject(double tol);

// A row's t error |t* - exact t*| as it is shown, 3 significant digits
// ("1.25e-10"): a display, never decided on.
std::string t_error_text(const Rational& error);

// The semantics a compiled-in library decides in: FCL and Bullet the closed
// question (they count touching).
const char* builtin_semantics(const std::string& subject);

} // namespace clash4d

#endif

// The comparer: runs every subject on a scene and holds it against the exact
// answer, in the spirit of CGAL's Kernel_checker (run two kernels side by
// side; on mismatch report both answers and the inputs). Subjects:
//   exact            the reference (rationals);
//   double           the same pipeline on doubles, plain sign tests;
//   double tol=EPS   the same with |value| <= EPS treated as zero;
//   exact-rounded    exact arithmetic on the scene with every number rounded
//                    to the nearest double (separates input rounding from
//                    arithmetic, regularised-semantics item 8);
//   fcl              optional (--fcl): FCL's continuous collision on the
//                    scenes it can express (compare/Fcl_subject.h); on the
//                    others it is skipped with the reason, which is neither
//                    an agreement nor a disagreement. It gives no witness
//                    point, so it is never an "invalid witness".
//   bullet           optional (--subject bullet): Bullet's continuous convex
//                    collision, on the same scenes as fcl (compare/Bullet_subject.h).
//   NAME             each --subject NAME=COMMAND (compare/External_subject.h):
//                    "unsupported" answers are skipped; its witness point is
//                    checked against every pair; a crash, time-out or answer
//                    out of protocol is a fault with that cause.
// Every disagreement is classified by its cause:
//   input rounding   exact on the rounded scene already disagrees;
//   contact          the exact verdict flips when one of the two objects is
//                    moved by a tiny amount (2^-20 or 2^-40 of the scene's
//                    scale) along an axis or a diagonal ({-1,0,1}^3: two
//                    blocks sharing an edge need a diagonal; small objects far
//                    from the origin the smaller move): the closed objects
//                    touch or nearly do, so the case hinges on regularisation;
//   arithmetic       otherwise: the subject's own rounding or tolerance;
//   invalid witness  verdicts agree but the subject's witness is not strictly
//                    inside both objects of the true scene (checked exactly).
// Until the exact pipeline decides the closed question, a closed subject's
// touching answers are classified like anyone's (contact).
#ifndef CLASH4D_COMPARE_COMPARER_H
#define CLASH4D_COMPARE_COMPARER_H

#include "compare/Comparison.h"
#include "scene/Scene.h"
#include <memory>
#include <string>
#include <vector>

namespace clash4d {

class External_pool;

struct Compare_options {
  std::vector<double> tolerances{1e-9};   // one "double tol=EPS" subject each
  bool earliest = false;                  // also compare t* (and report its error)
  bool rounded = true;                    // run the exact-rounded subject
  bool fcl = false;                       // run the fcl subject (skipped where FCL cannot express the scene)
  bool bullet = false;                    // run the bullet subject (likewise)
  // External subjects (--subject NAME=COMMAND): their processes, shared by
  // every copy of these options and kept for the whole run.
  std::vector<std::shared_ptr<External_pool>> externals;
};

// The comparison of every subject with exact (JSON form in compare/README.md).
Comparison compare_scene(const Scene& scene, const std::string& file, const Compare_options& options);

// The scene with every number replaced by the exact value of its nearest
// double, re-validated; throws Input_error when the rounded scene is invalid
// and std::range_error when a number has no double.
Scene rounded_scene(const Scene& scene);

// The name of the double subject with tolerance tol ("double tol=1e-09").
std::string tolerance_subject(double tol);

// The semantics a built-in subject decides in: the toolkit's pipelines the
// regularised question, FCL the closed one (it counts touching).
const char* builtin_semantics(const std::string& subject);

} // namespace clash4d

#endif

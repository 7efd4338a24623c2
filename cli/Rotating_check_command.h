// `check` on a scene where some object turns (rotation/Rotating_check.h):
// the same options and the same output as for translations (spec: clash4d
// check), with t* and points printed as the spec's algebraic-number object
// where rotation makes them irrational.
#ifndef CLASH4D_CLI_ROTATING_CHECK_COMMAND_H
#define CLASH4D_CLI_ROTATING_CHECK_COMMAND_H

#include "check/Check_answer.h"
#include "scene/Scene.h"
#include "rotation/Rotating_check.h"
#include <functional>
#include <iosfwd>
#include <string>

namespace clash4d {

struct Rotating_check_request {
  std::string file, number;
  Check_options options;
  bool stats = false;
  double tolerance = 0;   // --number double: the static double pipeline's
  // Run on the answer before it is printed (the certificate): it may throw
  // an Input_error, and then no answer is printed.
  std::function<void(const Rotating_check_answer&)> before_print;
};

// The exit status: 0 no collision, 1 collision. A question this release
// does not decide for rotating scenes is an Input_error naming the turning
// object (exit 2, never a guess).
int run_rotating_check(const Scene& scene, const Rotating_check_request& r, std::ostream& out);

} // namespace clash4d

#endif

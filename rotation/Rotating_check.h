// `check` on a scene where some object turns: every pair that is not
// ignored and whose swept boxes meet is decided by the time slices of
// Rotating_pair.h. Pairs where neither object turns are decided the same
// way (a translation is a pose motion without rotation), so one scene gets
// one method.
#ifndef CLASH4D_ROTATION_ROTATING_CHECK_H
#define CLASH4D_ROTATION_ROTATING_CHECK_H

#include "rotation/Rotating_pair.h"
#include <string>
#include <vector>

namespace clash4d {

struct Rotating_pair_answer {
  std::string a, b;   // object names
  Rotating_answer answer;
};

struct Rotating_check_answer {
  std::string number;                    // "exact", "rational" or "double"
  Semantics semantics = Semantics::regularised;
  bool collide = false;
  std::vector<Rotating_pair_answer> pairs;   // colliding pairs, in pair order
  int earliest_pair = -1;                    // index of the smallest t* (--earliest)
  std::size_t pairs_examined = 0;            // pairs whose swept boxes met
  Slice_counts counts;                       // over every pair examined

  const Rotating_pair_answer* reported() const
  {
    if (pairs.empty()) return nullptr;
    return &pairs[earliest_pair >= 0 ? earliest_pair : 0];
  }
};

// Whether some object of the scene turns (Motion::rotates()).
bool scene_rotates(const Scene& scene);

// number: "exact" (the static questions in the filtered kernel),
// "rational", or "double" (the float subject, Double_slices.h, with the
// static double pipeline's tolerance). Throws Rotation_unsupported for a
// question this release cannot decide exactly.
Rotating_check_answer check_rotating(const Scene& scene, const Check_options& options, const std::string& number,
                                     double tolerance = 0);

} // namespace clash4d

#endif

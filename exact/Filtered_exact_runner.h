// The filtered exact kernel's runner, Filtered_runner<Interval_kernel,
// Rational_kernel> (exact/Filtered_runner.h), behind a class of its own, so
// that the pipeline is compiled once (exact/Exact_instantiation.cpp) for
// check_exact and for Exact_checker's kept runners alike. Compiled in both
// files, it took about four minutes of each under the sanitizers.
#ifndef CLASH4D_EXACT_FILTERED_EXACT_RUNNER_H
#define CLASH4D_EXACT_FILTERED_EXACT_RUNNER_H

#include "check/Check_answer.h"
#include "scene/Scene.h"
#include <memory>
#include <vector>

namespace clash4d {

class Filtered_exact_runner {
public:
  // As Filtered_runner's: reusable keeps what a check makes for the next
  // (Exact_checker); the scene must outlive the runner.
  Filtered_exact_runner(const Scene& scene, bool use_sbounds, bool reusable = false);
  ~Filtered_exact_runner();
  Filtered_exact_runner(const Filtered_exact_runner&) = delete;
  Filtered_exact_runner& operator=(const Filtered_exact_runner&) = delete;

  Check_answer check(const Check_options& options);
  // The objects whose motions changed in the scene (a reusable runner).
  void motions_changed(const std::vector<int>& changed);
  Skeleton_answer skeleton();

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace clash4d

#endif

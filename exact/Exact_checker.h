// A scene prepared once for many exact checks (`--number exact`, the
// filtered kernel), as a peer engine converts its shapes once and then
// queries them: the interval model, each object's S-bounds, the sweep's
// pairs (per semantics) and the convex pairs' guides are made by the first
// check and kept; the rational parts made on demand are kept too. Every
// answer is the one check_exact gives for the same options (tests/
// test_filtered.cpp, prepared_checks_are_check_exact); its stats count the
// work of that call alone.
// The same shapes may be checked under other motions, as a peer engine
// keeps its shapes and takes new transforms per query: check(motions,
// options) answers as check_exact on the scene with those motions, and
// keeps the shapes' parts (models, S-bounds, guides' planes); only what
// depends on motions is made again.
// The scene must outlive the checker and not change. One check at a time
// (a check may run its pairs in parallel itself).
#ifndef CLASH4D_EXACT_EXACT_CHECKER_H
#define CLASH4D_EXACT_EXACT_CHECKER_H

#include "check/Check_answer.h"
#include "scene/Scene.h"
#include <memory>
#include <vector>

namespace clash4d {

class Exact_checker {
public:
  explicit Exact_checker(const Scene& scene);
  ~Exact_checker();
  Exact_checker(const Exact_checker&) = delete;
  Exact_checker& operator=(const Exact_checker&) = delete;

  // check_exact(scene, options): S-bounds on or off (options.sbounds) each
  // prepared once, on first use.
  Check_answer check(const Check_options& options);
  // check_exact on the scene with object i moving by motions[i] (one per
  // object, in the scene's order). Throws std::invalid_argument, naming the
  // object, on a count or a motion the scene reader would refuse. The
  // scene's own motions are the plain check's again.
  Check_answer check(const std::vector<Motion>& motions, const Check_options& options);

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace clash4d

#endif

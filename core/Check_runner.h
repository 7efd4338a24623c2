// `check` over a whole scene with one kernel: every pair not ignored, in
// order, stopping at the first collision unless all pairs are asked for.
#ifndef CLASH4D_CORE_CHECK_RUNNER_H
#define CLASH4D_CORE_CHECK_RUNNER_H

#include "core/Check_answer.h"
#include "core/Collision_checker.h"

namespace clash4d {

template <class K>
Pair_answer pair_answer(const K& k, const Scene_model<K>& model, const Pair_result<typename K::FT>& r)
{
  Pair_answer p;
  p.a = model.objects[r.a].name;
  p.b = model.objects[r.b].name;
  for (int i = 0; i < 4; ++i) p.witness[i] = k.to_text(r.witness[i]);
  p.witness_verified = r.witness_verified;
  p.earliest = r.earliest;
  if (r.earliest) {
    p.t_star = k.to_text(r.t_star);
    for (int i = 0; i < 4; ++i) p.contact[i] = k.to_text(r.contact[i]);
    p.at_start = k.compare(r.t_star, model.t_lo) == CGAL::ZERO;
  }
  return p;
}

template <class K>
Check_answer run_check(const K& k, const Scene& scene, const Check_options& options)
{
  using FT = typename K::FT;
  Check_answer answer;
  answer.number = K::name();
  auto start = std::chrono::steady_clock::now();
  Scene_model<K> model = Scene_model<K>::build(k, scene);
  answer.stats.seconds_model = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Collision_checker<K> checker(k, model, answer.stats, options.sbounds);
  int n = static_cast<int>(model.objects.size());
  bool have_best = false;
  FT best{};
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      if (scene.ignored(a, b)) continue;
      // Without --all-pairs only the earliest pair is reported, so a pair
      // need not be searched past the best time found so far.
      const FT* ceiling = options.earliest && !options.all_pairs && have_best ? &best : nullptr;
      Pair_result<FT> r = checker.check_pair(a, b, options.earliest, ceiling);
      if (!r.collide) continue;
      answer.collide = true;
      answer.pairs.push_back(pair_answer(k, model, r));
      if (options.earliest && (!have_best || r.t_star < best)) {
        have_best = true;
        best = r.t_star;
        answer.earliest_pair = static_cast<int>(answer.pairs.size()) - 1;
      }
      if (!options.all_pairs && !options.earliest) return answer;
    }
  return answer;
}

} // namespace clash4d

#endif

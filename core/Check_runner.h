// `check` over a whole scene with one kernel: every pair not ignored, in
// order, stopping at the first collision unless all pairs are asked for.
#ifndef CLASH4D_CORE_CHECK_RUNNER_H
#define CLASH4D_CORE_CHECK_RUNNER_H

#include "core/Check_answer.h"
#include "core/Collision_checker.h"

namespace clash4d {

template <class K>
Check_answer run_check(const K& k, const Scene& scene, const Check_options& options)
{
  Check_answer answer;
  answer.number = K::name();
  auto start = std::chrono::steady_clock::now();
  Scene_model<K> model = Scene_model<K>::build(k, scene);
  answer.stats.seconds_model = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Collision_checker<K> checker(k, model, answer.stats, options.sbounds);
  int n = static_cast<int>(model.objects.size());
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      if (scene.ignored(a, b)) continue;
      Pair_result<typename K::FT> r = checker.check_pair(a, b);
      if (!r.collide) continue;
      answer.collide = true;
      Pair_answer p;
      p.a = model.objects[a].name;
      p.b = model.objects[b].name;
      for (int i = 0; i < 4; ++i) p.witness[i] = k.to_text(r.witness[i]);
      p.witness_verified = r.witness_verified;
      answer.pairs.push_back(p);
      if (!options.all_pairs) return answer;
    }
  return answer;
}

} // namespace clash4d

#endif

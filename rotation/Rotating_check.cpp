#include "rotation/Rotating_check.h"

#include "exact/Exact_instantiation.h"
#include "rotation/Double_slices.h"
#include "rotation/Exact_slices.h"
#include "rotation/Object_parts.h"

#include <algorithm>
#include <optional>

namespace clash4d {

namespace {

template <class Slices>
Rotating_answer decide_parts(const Object_parts& a, const Object_parts& b, const Rational& lo, const Rational& hi,
                             const Check_options& options, const Slices& slices)
{
  if (a.pieces.empty() && b.pieces.empty()) return decide_rotating_pair(a.whole, b.whole, lo, hi, options, slices);
  Rotating_answer best;
  Slice_counts counts;
  Rational until = hi;   // with --earliest, a piece pair first meeting after it cannot win
  for_parts_that_may_meet(a, b, [&](const Rotating_object& pa, const Rotating_object& pb) {
    Rotating_answer r = decide_rotating_pair(pa, pb, lo, until, options, slices);
    counts += r.counts;
    if (!r.collide || (best.collide && !(r.t_star < best.t_star))) return false;
    best = std::move(r);
    if (!options.earliest) return true;   // the first colliding pair answers
    // A later pair wins only with a t* below this one's, so it is asked
    // up to a rational at or above it; none is below the span's start.
    if (best.t_star.upper() < until) until = best.t_star.upper();
    return !(lo < until);
  });
  best.counts = counts;
  return best;
}

// The pairs (i < j, in pair order) whose boxes may meet: a sweep along x
// over the bounded boxes, and every pair with an unbounded one.
std::vector<std::pair<int, int>> candidate_pairs(const std::vector<Swept_box>& boxes)
{
  std::vector<int> bounded, unbounded;
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i) (boxes[i].bounded ? bounded : unbounded).push_back(i);
  std::sort(bounded.begin(), bounded.end(), [&](int a, int b) { return boxes[a].min[0] < boxes[b].min[0]; });
  std::vector<std::pair<int, int>> out;
  for (std::size_t k = 0; k < bounded.size(); ++k)
    for (std::size_t l = k + 1; l < bounded.size() && !(boxes[bounded[k]].max[0] < boxes[bounded[l]].min[0]); ++l)
      if (may_meet(boxes[bounded[k]], boxes[bounded[l]]))
        out.emplace_back(std::min(bounded[k], bounded[l]), std::max(bounded[k], bounded[l]));
  for (int u : unbounded)
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
      if (i != u) out.emplace_back(std::min(u, i), std::max(u, i));
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

} // namespace

bool scene_rotates(const Scene& scene)
{
  for (const Scene_object& o : scene.objects)
    if (o.motion.rotates()) return true;
  return false;
}

namespace {

template <class Slices>
Rotating_check_answer check_pairs(const Scene& scene, const Check_options& options, const Slices& slices)
{
  std::vector<Object_parts> objects;
  std::vector<Swept_box> boxes;
  for (const Scene_object& o : scene.objects) {
    objects.emplace_back(o, scene.t_lo, scene.t_hi);
    boxes.push_back(swept_box(objects.back().whole, scene.t_lo, scene.t_hi));
  }
  Rotating_check_answer out;
  out.semantics = options.semantics;
  bool every_pair = options.all_pairs || options.earliest;
  for (auto [i, j] : candidate_pairs(boxes)) {
    if (scene.ignored(i, j)) continue;
    ++out.pairs_examined;
    Rotating_answer a = decide_parts(objects[i], objects[j], scene.t_lo, scene.t_hi, options, slices);
    out.counts += a.counts;
    if (!a.collide) continue;
    out.collide = true;
    out.pairs.push_back({scene.objects[i].name, scene.objects[j].name, std::move(a)});
    if (options.earliest) {
      int last = static_cast<int>(out.pairs.size()) - 1;
      if (out.earliest_pair < 0 || out.pairs[last].answer.t_star < out.pairs[out.earliest_pair].answer.t_star)
        out.earliest_pair = last;
    }
    if (!every_pair) return out;
  }
  return out;
}

} // namespace

Rotating_check_answer check_rotating(const Scene& scene, const Check_options& options, const std::string& number,
                                     double tolerance)
{
  Rotating_check_answer out;
  if (number == "double") out = check_pairs(scene, options, Double_slices(tolerance));
  else out = check_pairs(scene, options, Exact_slices(number == "rational" ? &check_rational : &check_exact));
  out.number = number;
  return out;
}

} // namespace clash4d

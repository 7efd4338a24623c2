#include "rotation/Rotating_check.h"

#include "exact/Exact_instantiation.h"

#include <algorithm>
#include <optional>

namespace clash4d {

namespace {

// A box holding the object over [lo, hi]: its origin's path (linear on
// each segment, so the segment's clipped ends bound it) widened by the
// shape's reach, which no rotation about the origin exceeds. None: the
// shape is unbounded.
struct Swept_box {
  bool bounded = false;
  std::array<Rational, 3> min, max;
};

Swept_box swept_box(const Rotating_object& o, const Rational& lo, const Rational& hi)
{
  Swept_box box;
  if (!o.shape.reach) return box;
  bool has_point = false;
  for (const Pose_segment& s : o.segments) {
    Rational a = s.from_minus_infinity || s.lo < lo ? lo : s.lo;
    Rational b = s.to_plus_infinity || hi < s.hi ? hi : s.hi;
    if (b < a) continue;
    for (const Rational& t : {a, b}) {
      std::array<Rational, 3> c = {s.c[0].at(t), s.c[1].at(t), s.c[2].at(t)};
      for (int k = 0; k < 3; ++k) {
        if (!has_point || c[k] < box.min[k]) box.min[k] = c[k];
        if (!has_point || box.max[k] < c[k]) box.max[k] = c[k];
      }
      has_point = true;
    }
  }
  for (int k = 0; k < 3; ++k) {
    box.min[k] -= *o.shape.reach;
    box.max[k] += *o.shape.reach;
  }
  box.bounded = true;
  return box;
}

bool may_meet(const Swept_box& a, const Swept_box& b)
{
  if (!a.bounded || !b.bounded) return true;
  for (int k = 0; k < 3; ++k)
    if (a.max[k] < b.min[k] || b.max[k] < a.min[k]) return false;
  return true;
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

Rotating_check_answer check_rotating(const Scene& scene, const Check_options& options, const std::string& number)
{
  Static_check check = number == "rational" ? &check_rational : &check_exact;
  std::vector<Rotating_object> objects;
  std::vector<Swept_box> boxes;
  for (const Scene_object& o : scene.objects) {
    objects.push_back(Rotating_object::make(o));
    boxes.push_back(swept_box(objects.back(), scene.t_lo, scene.t_hi));
  }
  Rotating_check_answer out;
  out.number = number;
  out.semantics = options.semantics;
  bool every_pair = options.all_pairs || options.earliest;
  for (auto [i, j] : candidate_pairs(boxes)) {
    if (scene.ignored(i, j)) continue;
    ++out.pairs_examined;
    Rotating_answer a = decide_rotating_pair(objects[i], objects[j], scene.t_lo, scene.t_hi, options, check);
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

} // namespace clash4d

#include "rotation/Rotating_check.h"

#include "exact/Exact_instantiation.h"
#include "rotation/Double_slices.h"
#include "rotation/Exact_slices.h"

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

// The convex leaves of a union (meshes are unions of hulls), each under the
// transforms above it: pieces whose closed union is the closed shape.
void convex_leaves(const Solid& s, std::vector<Solid>& out)
{
  if (s.kind == Solid::Kind::Union) {
    for (const Solid& c : s.children) convex_leaves(c, out);
    return;
  }
  if (s.kind != Solid::Kind::Translate && s.kind != Solid::Kind::Rotate) {
    out.push_back(s);
    return;
  }
  std::vector<Solid> inner;
  convex_leaves(s.children.front(), inner);
  for (Solid& leaf : inner) {
    Solid wrap = s;
    wrap.children = {std::move(leaf)};
    out.push_back(std::move(wrap));
  }
}

// An object and, when it is a union of several bounded convex pieces, each
// piece on its own: a pair of such objects collides (or touches) exactly
// when some pair of pieces does, and its t* is the least of theirs, so the
// minors are those of two pieces' planes, not of two whole meshes.
struct Object_parts {
  Rotating_object whole;
  std::vector<Solid> piece_solids;   // owned here, pointed to by pieces
  std::vector<Rotating_object> pieces;
  std::vector<Swept_box> piece_boxes;

  Object_parts(const Scene_object& o, const Rational& lo, const Rational& hi) : whole(Rotating_object::make(o))
  {
    if (whole.shape.convex_pieces.size() < 2) return;
    convex_leaves(o.shape, piece_solids);
    for (const Solid& p : piece_solids) {
      pieces.push_back(Rotating_object::piece(o, p));
      piece_boxes.push_back(swept_box(pieces.back(), lo, hi));
    }
  }
};

template <class Slices>
Rotating_answer decide_parts(const Object_parts& a, const Object_parts& b, const Rational& lo, const Rational& hi,
                             const Check_options& options, const Slices& slices)
{
  if (a.pieces.empty() && b.pieces.empty()) return decide_rotating_pair(a.whole, b.whole, lo, hi, options, slices);
  auto count = [](const Object_parts& p) { return p.pieces.empty() ? std::size_t(1) : p.pieces.size(); };
  auto part = [](const Object_parts& p, std::size_t i) -> const Rotating_object& { return p.pieces.empty() ? p.whole : p.pieces[i]; };
  Rotating_answer best;
  Slice_counts counts;
  Rational until = hi;   // with --earliest, a piece pair first meeting after it cannot win
  for (std::size_t i = 0; i < count(a) && lo < until; ++i)
    for (std::size_t j = 0; j < count(b) && lo < until; ++j) {
      if (!a.pieces.empty() && !b.pieces.empty() && !may_meet(a.piece_boxes[i], b.piece_boxes[j])) continue;
      Rotating_answer r = decide_rotating_pair(part(a, i), part(b, j), lo, until, options, slices);
      counts += r.counts;
      if (!r.collide) continue;
      if (!options.earliest) {
        r.counts = counts;
        return r;
      }
      if (best.collide && !(r.t_star < best.t_star)) continue;
      best = std::move(r);
      // A later pair wins only with a t* below this one's, so it is asked
      // up to a rational at or above it; none is below the span's start.
      if (best.t_star.upper() < until) until = best.t_star.upper();
    }
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

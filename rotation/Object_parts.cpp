#include "rotation/Object_parts.h"
#include "rotation/Apart_cover.h"

namespace clash4d {

namespace {

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

} // namespace

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

Object_parts::Object_parts(const Scene_object& o, const Rational& lo, const Rational& hi) : whole(Rotating_object::make(o))
{
  if (whole.shape.convex_pieces.size() < 2) return;
  convex_leaves(o.shape, piece_solids);
  for (const Solid& p : piece_solids) {
    pieces.push_back(Rotating_object::piece(o, p));
    piece_boxes.push_back(swept_box(pieces.back(), lo, hi));
  }
}

Critical_times part_pair_times(const Rotating_object& a, const Rotating_object& b, const std::vector<Moving_plane>& rows,
                               const Rational& lo, const Rational& hi, bool features_only)
{
  bool low_rank = !a.shape.spans_space && !b.shape.spans_space;
  std::size_t split = a.shape.planes.size();
  std::optional<Pair_features> features;
  if (features_only) features = feature_minors(a.shape, b.shape);
  return features ? Critical_times(rows, split, lo, hi, low_rank, *features) : Critical_times(rows, split, lo, hi, low_rank);
}

std::vector<Algebraic> part_pair_events(const Rotating_object& a, const Rotating_object& b,
                                        const std::vector<Moving_plane>& rows, const Rational& at, const Rational& lo,
                                        const Rational& hi, bool features_only, bool& restricted)
{
  std::vector<Algebraic> out;
  auto take = [&](const Critical_times& c) {
    restricted = restricted || c.restricted();
    for (const Critical_time& t : c.times()) out.push_back(t.t);
  };
  std::optional<Pair_features> features;
  if (features_only) features = feature_minors(a.shape, b.shape);
  if (!features) {
    take(part_pair_times(a, b, rows, lo, hi, false));
    return out;
  }
  restricted = true;
  bool low_rank = !a.shape.spans_space && !b.shape.spans_space;
  Apart_cover cover(a, b, at);
  cover.for_each_unsure(lo, hi, [&](const Time_piece& p) {
    take(Critical_times(rows, a.shape.planes.size(), p.lo, p.hi, low_rank, cover.near_features(*features, p.lo, p.hi)));
    return false;
  });
  return out;
}

} // namespace clash4d

// The witness of a collision (regularised-semantics item 3): the point
// generate-and-test found inside the formula's cell, in world coordinates,
// moved off every plane of the two objects (planes of primitives the
// S-bounds pruned were not in the search) and rounded to a short dyadic
// point (snap), so that anyone can check it by evaluating half-spaces. A
// kernel that cannot tell a sign the point depends on (a filter's
// enclosures, at an overlap as thin as they are) gives no point (nullopt);
// an exact kernel always gives one.
#ifndef CLASH4D_SEARCH_WITNESS_H
#define CLASH4D_SEARCH_WITNESS_H

#include "model/Extrusion.h"
#include <algorithm>
#include <optional>
#include <vector>

namespace clash4d {

template <class K>
class Witness {
public:
  using FT = typename K::FT;
  using H = Hyperplane4<FT>;
  using V4 = Vector4<FT>;
  using Moving = Moving_object<FT>;

  explicit Witness(const K& k) : k_(k) {}

  // p, found in the frame x' = x - shear t on the sub-span [lo, hi].
  std::optional<V4> make(V4 p, const Vector3<FT>& shear, const Moving& A, const Moving& B, const FT& lo,
                         const FT& hi) const
  {
    to_world(p, shear);
    return generic_snapped(p, world_planes(A, B, lo, hi), 4);
  }

  // Earliest (regularised): a generic point strictly inside both objects
  // with the contact point c in the closure of its cell, taken on the open
  // segment from c to the point `in` found inside (the cell is convex and c
  // in its closure), within a step that crosses no plane not through c.
  std::optional<V4> near(V4 c, V4 in, const Vector3<FT>& shear, const Moving& A, const Moving& B, const FT& lo,
                         const FT& hi) const
  {
    to_world(c, shear);
    to_world(in, shear);
    std::vector<H> world = world_planes(A, B, lo, hi);
    V4 d{in[0] - c[0], in[1] - c[1], in[2] - c[2], in[3] - c[3]};
    V4 p = point_along(c, safe_step(d, world, values_at(c, world)), d);
    return generic_snapped(p, world, 4);
  }

  // Closed semantics: a point strictly inside object M, on none of its
  // planes, at p's time, with p in the closure of its cell; d leads from p
  // into a cell inside M (frame of the search). M's planes all contain its
  // motion (v, 1), so d less d_t (v, 1) leads into the same cell at p's
  // time: the point stays in the sub-span even when p is at its end.
  std::optional<V4> near_in_space(V4 p, V4 d, const Vector3<FT>& shear, const Moving& M) const
  {
    to_world(p, shear);
    to_world(d, shear);
    for (int q = 0; q < 3; ++q) d[q] -= d[3] * M.v[q];
    d[3] = FT(0);
    std::vector<H> own = object_planes(M);
    if (!k_.is_zero(d)) p = point_along(p, safe_step(d, own, values_at(p, own)), d);
    return generic_snapped(p, own, 3);
  }

private:
  const K& k_;

  static void to_world(V4& p, const Vector3<FT>& shear)
  {
    for (int q = 0; q < 3; ++q) p[q] += shear[q] * p[3];
  }

  static std::vector<H> object_planes(const Moving& m)
  {
    std::vector<H> planes;
    for (const auto& prim : m.object->csg.primitives)
      for (const H& h : Extrusion<K>::primitive_planes(prim, m.v, m.o)) planes.push_back(h);
    return planes;
  }

  static std::vector<H> world_planes(const Moving& A, const Moving& B, const FT& lo, const FT& hi)
  {
    std::vector<H> world = object_planes(A), more = object_planes(B);
    world.insert(world.end(), more.begin(), more.end());
    world.push_back(time_at_least(lo));
    world.push_back(time_at_most(hi));
    return world;
  }

  // p moved off every plane through it, then snapped; the first `dims`
  // coordinates move (3: the time stays).
  std::optional<V4> generic_snapped(V4 p, const std::vector<H>& planes, int dims) const
  {
    std::vector<FT> values = values_at(p, planes);
    CGAL::Uncertain<bool> moved = make_generic(p, planes, values, dims);
    if (!CGAL::is_certain(moved)) return std::nullopt;
    if (moved.make_certain()) values = values_at(p, planes);
    return snap(p, planes, values, dims);
  }

  static std::vector<FT> values_at(const V4& p, const std::vector<H>& planes)
  {
    std::vector<FT> values;
    values.reserve(planes.size());
    for (const H& h : planes) values.push_back(h.value(p));
    return values;
  }

  // Largest step (halved) along d from p that crosses no hyperplane not
  // already through p; values[i] is planes[i] at p.
  FT safe_step(const V4& d, const std::vector<H>& planes, const std::vector<FT>& values) const
  {
    bool any = false;
    FT best(1);
    for (std::size_t i = 0; i < planes.size(); ++i) {
      FT nd = dot(planes[i].n, d);
      if (k_.sign(values[i]) == CGAL::ZERO || k_.sign(nd) == CGAL::ZERO) continue;
      FT s = Number_ops<FT>::magnitude(values[i]) / Number_ops<FT>::magnitude(nd);
      best = any ? Number_ops<FT>::lower(best, s) : s;
      any = true;
    }
    return any ? best / FT(2) : FT(1);
  }

  // Steps p off the planes through it; true when it moved, indeterminate
  // when the kernel cannot tell whether a plane is through it.
  CGAL::Uncertain<bool> make_generic(V4& p, const std::vector<H>& planes, const std::vector<FT>& values, int dims) const
  {
    std::vector<const H*> through;
    for (std::size_t i = 0; i < planes.size(); ++i) {
      CGAL::Uncertain<CGAL::Sign> s = k_.uncertain_sign(values[i]);
      if (!CGAL::is_certain(s)) return CGAL::Uncertain<bool>::indeterminate();
      if (s.make_certain() == CGAL::ZERO) through.push_back(&planes[i]);
    }
    if (through.empty()) return false;
    // d = (1, j, j^2, j^3) is orthogonal to a given normal for at most three
    // values of j, so some j <= 3 * |through| + 1 avoids all of them (with
    // dims 3, d = (1, j, j^2, 0) and a normal whose space part is not zero,
    // as every object plane's is).
    for (int j = 1;; ++j) {
      V4 d{FT(1), FT(j), FT(j * j), dims == 4 ? FT(j * j * j) : FT(0)};
      bool ok = true;
      for (const H* h : through) ok = ok && k_.dot_sign(h->n, d) != CGAL::ZERO;
      if (ok) {
        p = point_along(p, safe_step(d, planes, values), d);
        return true;
      }
      if (j > 3 * static_cast<int>(through.size()) + 1) return false;   // only with a tolerance
    }
  }

  // p rounded to the coarsest grid 2^-bits that keeps it where it is. No
  // plane n.x + c changes sign within max-norm distance room of p, where
  // room = min |h(p)| / (4 max |n_j|) (as |h(q) - h(p)| <= |n|_1 |q - p|);
  // with 2^-bits <= room, rounding each coordinate to the nearest multiple
  // of 2^-bits moves p by at most room / 2, so every |h| keeps at least half
  // its value. The result is a function of the exact p alone: a kernel that
  // only encloses p (intervals) finds the same dyadic point or fails the
  // filter. And users read 1/2 rather than 1999999999/4000000000.
  // bits is taken for 13/16 of the room: the search makes distances that
  // are powers of two (grid faces, halved steps), and an enclosure of an
  // exact power of two could not say which side of it the room is on.
  std::optional<V4> snap(const V4& p, const std::vector<H>& planes, const std::vector<FT>& values, int dims) const
  {
    FT least = Number_ops<FT>::magnitude(values[0]), widest = Number_ops<FT>::magnitude(planes[0].n[0]);
    for (std::size_t i = 0; i < planes.size(); ++i) {
      if (i > 0) least = Number_ops<FT>::lower(least, Number_ops<FT>::magnitude(values[i]));
      for (const FT& n : planes[i].n) widest = Number_ops<FT>::upper(widest, Number_ops<FT>::magnitude(n));
    }
    FT room = FT(13) * least / (FT(64) * widest);
    CGAL::Uncertain<CGAL::Sign> positive = k_.uncertain_sign(room);
    if (!CGAL::is_certain(positive)) return std::nullopt;
    if (positive.make_certain() != CGAL::POSITIVE) return p;   // only with a tolerance: not generic
    int bits = std::max(0, k_.grid_exponent(room));
    V4 out = p;
    for (int q = 0; q < dims; ++q) out[q] = k_.round_to_grid(p[q], bits);
    return out;
  }
};

} // namespace clash4d

#endif

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
#include "search/Witness_signs.h"
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
    return make_on(p, shear, world_planes(A, B, lo, hi));
  }
  // The same on the sub-span's world planes as world_planes makes them,
  // made already (a convex pair's rows, search/Convex_pair.h). values: the
  // planes' values at p when known already (a convex pair's, evaluated at
  // its guess; its frame is the world's, shear zero), the same numbers
  // values_at gives.
  std::optional<V4> make_on(V4 p, const Vector3<FT>& shear, const std::vector<H>& world,
                            const std::vector<FT>* values = nullptr) const
  {
    to_world(p, shear);
    return generic_snapped(p, world, 4, nullptr, values);
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
    std::optional<FT> step = safe_step(d, world, values_at(c, world));
    if (!step) return std::nullopt;
    return generic_snapped(point_along(c, *step, d), world, 4);
  }

  // Closed semantics: a point strictly inside object M, on none of its
  // planes, at p's time, with p in the closure of its cell; d leads from p
  // into a cell inside M (frame of the search). M's planes all contain its
  // motion (v, 1), so d less d_t (v, 1) leads into the same cell at p's
  // time: the point stays in the sub-span even when p is at its end.
  // signs: where the kernel cannot tell whether a plane is through p or
  // parallel to a step, the exact answer (a filter's, search/Witness_signs.h);
  // the point made is then the exact kernel's, or none.
  std::optional<V4> near_in_space(V4 p, V4 d, const Vector3<FT>& shear, const Moving& M,
                                  const Witness_signs* signs = nullptr) const
  {
    in_space(p, d, shear, M.v);
    std::vector<H> own = object_planes(M);
    std::vector<FT> values = values_at(p, own);
    Zeros zeros{signs, std::vector<char>(own.size(), 0), -1, d};
    if (!decide_zeros(values, own, zeros)) return std::nullopt;
    if (!k_.is_zero(d)) {
      std::optional<FT> step = safe_step(d, own, values, &zeros, 0);
      if (!step) return std::nullopt;
      p = point_along(p, *step, d);
      zeros.direction = 0;
    }
    return generic_snapped(p, own, 3, &zeros);
  }

  // near_in_space's p and d in world space at p's time: unsheared, and d
  // less its part along M's motion (v, 1).
  static void in_space(V4& p, V4& d, const Vector3<FT>& shear, const Vector3<FT>& v)
  {
    to_world(p, shear);
    to_world(d, shear);
    for (int q = 0; q < 3; ++q) d[q] -= d[3] * v[q];
    d[3] = FT(0);
  }

  // Direction j >= 1 of make_generic's steps: (1, j, j^2, j^3), or with
  // dims 3 (1, j, j^2, 0).
  static V4 generic_direction(int j, int dims)
  {
    return {FT(1), FT(j), FT(j * j), dims == 4 ? FT(j * j * j) : FT(0)};
  }

  // Both objects' planes extruded on the sub-span [lo, hi] (A's, B's, then
  // t >= lo and t <= hi): the planes make keeps the witness off.
  static std::vector<H> world_planes(const Moving& A, const Moving& B, const FT& lo, const FT& hi)
  {
    std::vector<H> world;
    world.reserve(A.object->csg.plane_count() + B.object->csg.plane_count() + 2);
    add_object_planes(A, world);
    add_object_planes(B, world);
    world.push_back(time_at_least(lo));
    world.push_back(time_at_most(hi));
    return world;
  }

private:
  const K& k_;

  static void to_world(V4& p, const Vector3<FT>& shear)
  {
    for (int q = 0; q < 3; ++q) p[q] += shear[q] * p[3];
  }

  // m's planes extruded (equation (4)), appended to planes.
  static void add_object_planes(const Moving& m, std::vector<H>& planes)
  {
    for (const auto& prim : m.object->csg.primitives) Extrusion<K>::add_primitive_planes(prim, m.v, m.o, planes);
  }

  static std::vector<H> object_planes(const Moving& m)
  {
    std::vector<H> planes;
    planes.reserve(m.object->csg.plane_count());
    add_object_planes(m, planes);
    return planes;
  }

  // Which planes are zero at the current point, for a kernel that cannot
  // tell (signs given): at the contact, as signs says; after a step along
  // direction `direction` (safe_step moves off every plane the step is not
  // parallel to), those that were and are parallel to it. `along` is
  // direction 0.
  struct Zeros {
    const Witness_signs* signs = nullptr;
    std::vector<char> zero;
    int direction = -1;     // -1: at the contact
    V4 along;
  };

  // The values the kernel cannot sign that are zero, made exact zeros
  // (Zeros); false when one is not zero (its sign unknown) or no signs.
  bool decide_zeros(std::vector<FT>& values, const std::vector<H>& planes, Zeros& z) const
  {
    for (std::size_t i = 0; i < values.size(); ++i) {
      CGAL::Uncertain<CGAL::Sign> s = k_.uncertain_sign(values[i]);
      if (CGAL::is_certain(s)) {
        z.zero[i] = s.make_certain() == CGAL::ZERO;
        continue;
      }
      if (!z.signs) return false;
      bool zero = z.direction < 0 ? z.signs->through_contact(i)
                                  : z.zero[i] && is_parallel(dot(planes[i].n, z.along), i, &z, z.direction);
      if (!zero) return false;
      values[i] = FT(0);
      z.zero[i] = 1;
    }
    return true;
  }

  // Whether n.d = nd is zero: the kernel's sign, or where it cannot tell,
  // the exact answer for plane i and direction `direction` (z's signs);
  // indeterminate when neither can tell.
  CGAL::Uncertain<bool> parallel_sign(const FT& nd, std::size_t i, const Zeros* z, int direction) const
  {
    if (!z || !z->signs) return k_.sign(nd) == CGAL::ZERO;
    CGAL::Uncertain<CGAL::Sign> s = k_.uncertain_sign(nd);
    if (CGAL::is_certain(s)) return s.make_certain() == CGAL::ZERO;
    if (z->signs->parallel(i, direction)) return true;
    return CGAL::Uncertain<bool>::indeterminate();   // not parallel, but its slope is not bounded away from 0
  }
  bool is_parallel(const FT& nd, std::size_t i, const Zeros* z, int direction) const
  {
    CGAL::Uncertain<bool> p = parallel_sign(nd, i, z, direction);
    return CGAL::is_certain(p) && p.make_certain();
  }

  // p moved off every plane through it, then snapped; the first `dims`
  // coordinates move (3: the time stays).
  // known: the planes' values at p, when the caller has them.
  std::optional<V4> generic_snapped(V4 p, const std::vector<H>& planes, int dims, Zeros* z = nullptr,
                                    const std::vector<FT>* known = nullptr) const
  {
    std::vector<FT> own;
    const std::vector<FT>* values = known;
    if (!values || z) {   // decide_zeros writes its zeros into them: a copy of its own
      own = known ? *known : values_at(p, planes);
      values = &own;
    }
    if (z && !decide_zeros(own, planes, *z)) return std::nullopt;
    CGAL::Uncertain<bool> moved = make_generic(p, planes, *values, dims, z);
    if (!CGAL::is_certain(moved)) return std::nullopt;
    if (moved.make_certain()) {
      own = values_at(p, planes);
      values = &own;
    }
    return snap(p, planes, *values, dims);
  }

  static std::vector<FT> values_at(const V4& p, const std::vector<H>& planes)
  {
    std::vector<FT> values;
    values.reserve(planes.size());
    for (const H& h : planes) values.push_back(h.value(p));
    return values;
  }

  // Largest step (halved) along d from p that crosses no hyperplane not
  // already through p; values[i] is planes[i] at p. None when a slope's
  // sign is known only to be nonzero (z: Zeros; direction: d's number).
  std::optional<FT> safe_step(const V4& d, const std::vector<H>& planes, const std::vector<FT>& values,
                              const Zeros* z = nullptr, int direction = 0) const
  {
    bool any = false;
    FT best(1);
    for (std::size_t i = 0; i < planes.size(); ++i) {
      if (k_.sign(values[i]) == CGAL::ZERO) continue;
      FT nd = dot(planes[i].n, d);
      CGAL::Uncertain<bool> parallel = parallel_sign(nd, i, z, direction);
      if (!CGAL::is_certain(parallel)) return std::nullopt;
      if (parallel.make_certain()) continue;
      FT s = Number_ops<FT>::magnitude(values[i]) / Number_ops<FT>::magnitude(nd);
      best = any ? Number_ops<FT>::lower(best, s) : s;
      any = true;
    }
    return any ? best / FT(2) : FT(1);
  }

  // Steps p off the planes through it; true when it moved, indeterminate
  // when the kernel cannot tell whether a plane is through it (or, with
  // z, a slope it needs).
  CGAL::Uncertain<bool> make_generic(V4& p, const std::vector<H>& planes, const std::vector<FT>& values, int dims,
                                     const Zeros* z = nullptr) const
  {
    std::vector<std::size_t> through;
    for (std::size_t i = 0; i < planes.size(); ++i) {
      CGAL::Uncertain<CGAL::Sign> s = k_.uncertain_sign(values[i]);
      if (!CGAL::is_certain(s)) return CGAL::Uncertain<bool>::indeterminate();
      if (s.make_certain() == CGAL::ZERO) through.push_back(i);
    }
    if (through.empty()) return false;
    // d = (1, j, j^2, j^3) is orthogonal to a given normal for at most three
    // values of j, so some j <= 3 * |through| + 1 avoids all of them (with
    // dims 3, d = (1, j, j^2, 0) and a normal whose space part is not zero,
    // as every object plane's is).
    for (int j = 1;; ++j) {
      V4 d = generic_direction(j, dims);
      bool ok = true;
      for (std::size_t i : through) {
        if (!ok) break;
        if (!z || !z->signs) {
          ok = k_.dot_sign(planes[i].n, d) != CGAL::ZERO;
          continue;
        }
        CGAL::Uncertain<bool> parallel = parallel_sign(dot(planes[i].n, d), i, z, j);
        if (!CGAL::is_certain(parallel)) return CGAL::Uncertain<bool>::indeterminate();
        ok = !parallel.make_certain();
      }
      if (ok) {
        std::optional<FT> step = safe_step(d, planes, values, z, j);
        if (!step) return CGAL::Uncertain<bool>::indeterminate();
        p = point_along(p, *step, d);
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

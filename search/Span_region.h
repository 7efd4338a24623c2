// The region of space-time one pair is searched in on one constant-velocity
// sub-span: the 4D S-bounds of §4.3.2 (3D Up/Down passes in each object and
// Appendix B's closed form at the root, repeated until nothing shrinks),
// then Appendix B's optimal fitting of one box in a sheared frame, with its
// faces moved out to the search's dyadic grid. §4.1's original bound (no
// S-bounds) is kept for comparison (--no-sbounds). A pair unbounded along
// an axis is searched within the scene's far bound (model/Far_bound.h).
#ifndef CLASH4D_SEARCH_SPAN_REGION_H
#define CLASH4D_SEARCH_SPAN_REGION_H

#include "model/Extrusion.h"
#include "search/Check_stats.h"
#include "search/S_bounds.h"
#include <optional>
#include <stdexcept>

namespace clash4d {

// The region stage's outcome for one pair on one sub-span (Span_region::
// stage): whether the S-bounds leave the pair a chance there, the narrowed
// times, the fitted box (for statistics) and the region searched (on the
// grid; nothing when the fitted box is empty), with its frame. A run in
// another kernel may adopt it (exact/Interval_filter.h).
template <class FT>
struct Region_stage {
  bool alive = false;
  FT tl{}, th{};
  Box<FT, 4> fitted;
  std::optional<Box<FT, 4>> region;
  Vector3<FT> shear{};
  std::array<bool, 3> frame_of_a{};
  // The S-bounds kept a box or a time range an approximate kernel could not
  // decide (S_bounds' keep_doubtful): "not alive" is still a proof, but an
  // alive stage is not an exact kernel's, and is left without its region.
  bool doubtful = false;
};

template <class K>
class Span_region {
public:
  using FT = typename K::FT;
  using Box3 = Box<FT, 3>;
  using Box4 = Box<FT, 4>;
  using Moving = Moving_object<FT>;

  // far_exponent: Scene_model::far_exponent, R = 2^far_exponent
  // (model/Far_bound.h); closed: the pair under closed semantics (S_bounds'
  // closed); keep_doubtful: S_bounds' (a filter's first try).
  Span_region(const K& k, Check_stats& stats, int far_exponent, bool closed = false, bool keep_doubtful = false)
    : k_(k), sb_(k, closed, keep_doubtful), stats_(stats), far_exponent_(far_exponent), closed_(closed) {}

  // The whole stage on the sub-span [lo, hi]: the 4D S-bounds (narrowing
  // A's and B's bounds; none with use_sbounds off), then the fitted box
  // (or §4.1's original), moved out to the grid. Closed, a box without
  // interior (objects that only touch) is kept and widened too.
  Region_stage<FT> stage(Moving& A, Moving& B, const Time_span<FT>& span, bool use_sbounds)
  {
    const FT &lo = span.lo, &hi = span.hi;
    Region_stage<FT> st;
    st.tl = lo;
    st.th = hi;
    st.alive = use_sbounds ? four_d_bounds(A, B, st.tl, st.th) : true;
    st.doubtful = sb_.doubted();
    if (!st.alive || st.doubtful) return st;
    st.fitted = use_sbounds ? fitted(A, B, st.tl, st.th, st.shear, st.frame_of_a) : original(A, B, lo, hi, st.shear);
    if (closed_ ? is_empty_box(k_, st.fitted) : has_no_interior(k_, st.fitted)) return st;
    st.region = use_sbounds || closed_ ? on_grid(st.fitted, span) : st.fitted;
    return st;
  }

  // §4.3.2: narrows A's and B's bounds and [tl, th]; false when the pair
  // cannot meet on the sub-span. The passes stop when no bound moved by a
  // grid step (Kernel_base::same_on_grid), a decision every kernel
  // certifies alike.
  bool four_d_bounds(Moving& A, Moving& B, FT& tl, FT& th)
  {
    for (int pass = 0; pass < S_bounds<K>::max_passes; ++pass) {
      ++stats_.sbound_passes;
      Box3 ra = A.beta[0], rb = B.beta[0];
      FT l0 = tl, h0 = th;
      typename S_bounds<K>::Moving_box ma{&A.beta[0], &A.v, &A.o}, mb{&B.beta[0], &B.v, &B.o};
      if (!sb_.meet_moving(ma, mb, tl, th)) return false;
      sb_.settle(A.object->csg, A.beta, S_bounds<K>::max_passes);
      sb_.settle(B.object->csg, B.beta, S_bounds<K>::max_passes);
      if (A.beta[0].empty || B.beta[0].empty) return false;
      if (same_on_grid(k_, ra, A.beta[0]) && same_on_grid(k_, rb, B.beta[0]) && k_.same_on_grid(l0, tl) &&
          k_.same_on_grid(h0, th))
        break;
    }
    return true;
  }

  // Appendix B, "optimal fitting": per axis, measure q in the frame of the
  // object whose bound is narrower there (q' = q - w t with w its velocity),
  // the widths compared on the grid (Kernel_base::less_on_grid). Sets the
  // shear w per axis and whose frame it is (frame_of_a). An axis along
  // which neither is bounded on both sides gets the far bound (far_axis).
  Box4 fitted(const Moving& A, const Moving& B, const FT& tl, const FT& th, Vector3<FT>& shear,
              std::array<bool, 3>& frame_of_a) const
  {
    Box4 region;
    for (int q = 0; q < 3; ++q) {
      const Box3 &ba = A.beta[0], &bb = B.beta[0];
      bool fa = ba.has_lo[q] && ba.has_hi[q], fb = bb.has_lo[q] && bb.has_hi[q];
      if (!fa && !fb) {
        frame_of_a[q] = true;
        far_axis(A, B, q, tl, th, region, shear);
        continue;
      }
      bool use_a = fa && (!fb || !k_.less_on_grid(bb.hi[q] - bb.lo[q], ba.hi[q] - ba.lo[q]));
      frame_of_a[q] = use_a;
      const Moving& m = use_a ? A : B;
      const Box3& bm = use_a ? ba : bb;
      shear[q] = m.v[q];
      region.set(q, bm.lo[q] + m.o[q], bm.hi[q] + m.o[q]);
    }
    region.set(3, tl, th);
    return region;
  }

  // §4.1's original bound: each object's box at the span's ends (its swept
  // box under one velocity), intersected, with the span's times; no shear.
  Box4 original(const Moving& A, const Moving& B, const FT& lo, const FT& hi, Vector3<FT>& shear) const
  {
    Box3 sweep[2];
    int i = 0;
    for (const Moving* m : {&A, &B}) {
      Box3 at_lo = m->beta[0], at_hi = m->beta[0];
      for (int q = 0; q < 3; ++q) {
        FT dlo = m->v[q] * lo + m->o[q], dhi = m->v[q] * hi + m->o[q];
        at_lo.lo[q] += dlo; at_lo.hi[q] += dlo;
        at_hi.lo[q] += dhi; at_hi.hi[q] += dhi;
      }
      sweep[i++] = join(at_lo, at_hi);
    }
    Box3 both = meet(sweep[0], sweep[1]);
    Box4 region;
    for (int q = 0; q < 3; ++q) {
      // Unbounded sides: the far bound, in this world frame as everywhere
      // (model/Far_bound.h: every vertex has |x_q| < R).
      region.set(q, both.has_lo[q] ? both.lo[q] : -far(), both.has_hi[q] ? both.hi[q] : far());
      shear[q] = FT(0);
    }
    region.set(3, lo, hi);
    return region;
  }

  // Region faces moved out to the next multiples of 2^-grid_bits beyond the
  // S-bound region, which stays a bound. S-bounds are vertex coordinates, so
  // their faces pass through the objects' vertex lines: a degeneracy of the
  // bound, not of the scene, which interval arithmetic cannot certify. Grid
  // values are exact in every kernel, and so are the bisections of §4.1.
  // Regularised, time stays within the sub-span [lo, hi] (the formula has no
  // time slab). Closed, the formula holds the sub-span's closed slab
  // (Extrusion::add_time_slab), so at an end off the grid (a velocity
  // change at t = 3/10, say) the time face stays on the grid: a face there
  // would be a plane of the formula that intervals could only enclose. At
  // an end on the grid the face is the end (a region then folds or
  // simplifies against the slab, as every kernel decides alike).
  // The rounding jumps at half-grid points, not at the grid points that
  // integer and short binary bounds sit on, so an interval enclosing such a
  // bound still rounds to one grid point; the margin is at least half a step.
  Box4 on_grid(const Box4& region, const Time_span<FT>& span) const
  {
    const FT &lo = span.lo, &hi = span.hi;
    const FT step = k_.power_of_two(-K::grid_bits);
    auto below = [&](const FT& x) { return k_.grid_point(x) - step; };
    Box4 out = region;
    for (int q = 0; q < 4; ++q) out.set(q, below(region.lo[q]), -below(-region.hi[q]));
    if (!closed_ || span.lo_on_grid) out.lo[3] = Number_ops<FT>::upper(out.lo[3], lo);
    if (!closed_ || span.hi_on_grid) out.hi[3] = Number_ops<FT>::lower(out.hi[3], hi);
    return out;
  }

private:
  const K& k_;
  S_bounds<K> sb_;
  Check_stats& stats_;
  int far_exponent_;
  bool closed_;

  FT far() const
  {
    if (far_exponent_ < 0) throw std::logic_error("internal error: a pair unbounded along an axis without a far bound");
    return k_.far_power_of_two(far_exponent_);
  }

  // Neither object bounded on both sides of axis q. It is measured in A's
  // frame (x' = x - v_A t; frame_of_a, so a run in another kernel rebuilds
  // the same table, exact/Exact_span.h), within [-R, R] (R: the far
  // bound, beyond every vertex of the scene's arrangement in every such
  // frame, model/Far_bound.h), narrowed by A's sides (constant in its
  // frame) and B's swept over [tl, th] (x'_q - (v_B - v_A) t lies in B's
  // bound). Why nothing is lost: every non-empty face of the pair's
  // collision region has a vertex v of the arrangement in its closure
  // (Far_bound.h); an open cell has points as near v as wished, |v'_q| < R,
  // and they lie within the other axes' S-bounds and [tl, th] as the whole
  // region does, so the box meets the cell in an open set (on_grid moves the
  // faces outward past v). Closed semantics: v itself is a touching point in
  // the box. --earliest: t* is attained at such a vertex (the least t over a
  // pointed polyhedron), so the box's t* is the pair's.
  void far_axis(const Moving& A, const Moving& B, int q, const FT& tl, const FT& th, Box4& region,
                Vector3<FT>& shear) const
  {
    using Ops = Number_ops<FT>;
    const Box3 &ba = A.beta[0], &bb = B.beta[0];
    const FT R = far();
    FT lo = -R, hi = R;
    if (ba.has_lo[q]) lo = Ops::upper(lo, ba.lo[q] + A.o[q]);
    if (ba.has_hi[q]) hi = Ops::lower(hi, ba.hi[q] + A.o[q]);
    const FT d = B.v[q] - A.v[q], at_l = d * tl + B.o[q], at_h = d * th + B.o[q];
    if (bb.has_lo[q]) lo = Ops::upper(lo, bb.lo[q] + Ops::lower(at_l, at_h));
    if (bb.has_hi[q]) hi = Ops::lower(hi, bb.hi[q] + Ops::upper(at_l, at_h));
    shear[q] = A.v[q];
    region.set(q, lo, hi);
  }
};

} // namespace clash4d

#endif

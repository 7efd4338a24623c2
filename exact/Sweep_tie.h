// A pair the intervals' sweep kept only on a tie (Filtered_runner::
// drop_apart_ties), decided as EK's sweep decides it (Pair_sweep::meets on
// EK's root boxes, regularised semantics), with exact numbers made only
// where the intervals cannot decide. Two swept boxes meet when on every
// axis each one's upper side lies strictly past the other's lower side;
// each such comparison is tried on AK's enclosures of the two sides, and
// only one the intervals cannot certify (a tie: faces at decimal
// coordinates that touch) is made in EK, from those two sides alone.
//
// A one-primitive object with vertices (block, hull, prism, convex) has as
// root its vertices' box (Model_builder::primitive_box): a side is the
// greatest (least) coordinate over the vertices whose enclosures can reach
// the enclosure's extreme (most often one), read from the scene and placed
// by its transforms in EK (Model_builder::local_vertex). Another object's
// root is EK's own (Filtered_runner::exact_root), enclosed for AK. Either
// way each AK number encloses EK's, so a certain comparison is EK's.
#ifndef CLASH4D_EXACT_SWEEP_TIE_H
#define CLASH4D_EXACT_SWEEP_TIE_H

#include "check/Pair_sweep.h"
#include "model/Model_builder.h"
#include <CGAL/Uncertain.h>
#include <array>
#include <optional>
#include <vector>

namespace clash4d {

template <class Runner>
class Sweep_tie {
public:
  using AK = typename Runner::Approximate_kernel;
  using EK = typename Runner::Exact_kernel;
  using AFT = typename AK::FT;
  using EFT = typename EK::FT;

  explicit Sweep_tie(Runner& runner) : r_(runner), roots_(runner.scene().objects.size()) {}

  // Whether some box of i and some box of j share interior (EK's answer).
  bool meets(int i, int j)
  {
    typename AK::Protector protect;
    const Root &ri = root(i), &rj = root(j);
    if (ri.aroot.empty || rj.aroot.empty) return false;
    Pair_sweep<AK> sweep(r_.ak(), false);
    for (const auto& x : r_.interval_model().sub_spans({i}))
      for (const auto& y : r_.interval_model().sub_spans({j})) {
        Box<AFT, 4> a = sweep.swept(r_.interval_model(), i, ri.aroot, x);
        Box<AFT, 4> b = sweep.swept(r_.interval_model(), j, rj.aroot, y);
        bool all = true;
        for (int q = 0; q < 4 && all; ++q)
          all = opens_past({i, &x, &a}, {j, &y, &b}, q) && opens_past({j, &y, &b}, {i, &x, &a}, q);
        if (all) return true;
      }
    return false;
  }

private:
  // An object's root box: AK's enclosure of it, and EK's sides as asked
  // (the box itself for an object that is not one primitive with vertices).
  struct Root {
    Box<AFT, 3> aroot;
    std::optional<Box<EFT, 3>> exact;           // the whole root in EK
    Affine3<EFT> placed;                        // a one primitive's transforms, in EK
    const Solid* solid = nullptr;               // that primitive, under them
    std::array<std::optional<EFT>, 6> sides;    // [2 q + upper]: made as asked
  };
  // One object's swept box on one of its sub-spans (AK's numbers).
  struct Swept {
    int object;
    const Time_span<AFT>* span;
    const Box<AFT, 4>* box;
  };

  // Pair_sweep::opens_past (regularised): a's upper side strictly past b's
  // lower side on axis q; in EK when the intervals cannot tell.
  bool opens_past(const Swept& a, const Swept& b, int q)
  {
    if (!a.box->has_hi[q] || !b.box->has_lo[q]) return true;
    const AK& k = r_.ak();
    if (!k.possibly_positive(a.box->hi[q] - b.box->lo[q])) return false;
    if (!k.possibly_nonnegative(b.box->lo[q] - a.box->hi[q])) return true;
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    return r_.ek().compare(side(a, q, true), side(b, q, false)) == CGAL::LARGER;
  }

  // EK's side of a swept box: its root's plus the motion's displacement
  // (Pair_sweep::moved), or the sub-span's end on the time axis.
  EFT side(const Swept& s, int q, bool upper)
  {
    const EK& k = r_.ek();
    Time_span<EFT> span{k.from_rational(*s.span->exact_lo), k.from_rational(*s.span->exact_hi)};
    if (q == 3) return upper ? span.hi : span.lo;
    r_.rational().need_motion(s.object);
    // AK's certified choice of the motion's segment (Pair_sweep::swept), EK's.
    std::size_t seg = r_.interval_model().segment_on(s.object, *s.span);
    auto [dlo, dhi] = Pair_sweep<EK>(k, false).moved(r_.rational().model(), s.object, seg, span, q);
    return root_side(s.object, q, upper) + (upper ? dhi : dlo);
  }

  EFT root_side(int i, int q, bool upper)
  {
    Root& r = root(i);
    if (r.exact) return upper ? r.exact->hi[q] : r.exact->lo[q];
    std::optional<EFT>& made = r.sides[static_cast<std::size_t>(2 * q + upper)];
    if (made) return *made;
    // The vertices whose enclosure reaches past every other's near side:
    // the exact extreme is one of them (each encloses its vertex).
    const auto& vs = r_.interval_model().objects[i].csg.primitives[0].vertices;
    double reach = upper ? vs[0][q].inf() : vs[0][q].sup();
    for (const auto& v : vs) reach = upper ? std::max(reach, v[q].inf()) : std::min(reach, v[q].sup());
    Model_builder<EK> builder(r_.ek());
    std::optional<EFT> best;
    for (std::size_t k = 0; k < vs.size(); ++k) {
      if (upper ? vs[k][q].sup() < reach : vs[k][q].inf() > reach) continue;
      EFT x = r.placed.apply(builder.local_vertex(*r.solid, k), q);
      best = !best ? x : upper ? Number_ops<EFT>::upper(*best, x) : Number_ops<EFT>::lower(*best, x);
    }
    made = std::move(best);
    return *made;
  }

  Root& root(int i)
  {
    Root& r = roots_[static_cast<std::size_t>(i)];
    if (r.solid || r.exact) return r;
    const Csg_model<AFT>& csg = r_.interval_model().objects[i].csg;
    if (csg.nodes.size() == 1 && !csg.primitives[0].vertices.empty() && !r_.exact_only(i)) {
      r.aroot = csg.primitives[0].box;
      r.placed = Affine3<EFT>::identity();
      r.solid = &Model_builder<EK>(r_.ek()).peel(r_.scene().objects[static_cast<std::size_t>(i)].shape, r.placed);
    } else {
      r.exact = r_.exact_root(i);
      r.aroot = r_.enclose(*r.exact);
    }
    return r;
  }

  Runner& r_;
  std::vector<Root> roots_;
};

} // namespace clash4d

#endif

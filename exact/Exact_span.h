// The rational side of one pair's interval run (exact/Interval_filter.h):
// the plane table of the sub-span the interval run is in, made when it is
// first needed, and the decisions the intervals could not certify, made on
// the rational planes: whether two planes are one, and whether a line of a
// conquer holds a point inside (the filter at the level of one line).
#ifndef CLASH4D_EXACT_EXACT_SPAN_H
#define CLASH4D_EXACT_EXACT_SPAN_H

#include "exact/Exact_line_filter.h"
#include "model/Extrusion.h"
#include "search/Null_object_test.h"
#include "exact/Exact_stage.h"
#include <map>
#include <memory>
#include <optional>

namespace clash4d {

// Runner: exact/Filtered_runner.h, which owns the rational model.
template <class Runner>
class Exact_span {
public:
  using AK = typename Runner::Approximate_kernel;
  using EK = typename Runner::Exact_kernel;
  using AFT = typename AK::FT;
  using EFT = typename EK::FT;

  // A conquer's lines decided in rationals, on the same layout of planes.
  class Lines {
  public:
    Lines(const EK& k, const std::vector<Hyperplane4<EFT>>& table, const Motion_groups<EFT>& groups, bool exact)
      : lines_(k, table, stats_, &groups, &policy_), exact_(exact) {}
    Null_object_test<EK, Exact_line_filter>& conquer() { return lines_; }
    const Null_object_test<EK, Exact_line_filter>& conquer() const { return lines_; }
    // Whether line i, j, m holds a point inside.
    bool has_inside(const Pair_formula& f, std::size_t i, std::size_t j, std::size_t m, Semantics semantics)
    {
      CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
      return lines_.line_has_inside(f, i, j, m, semantics);
    }

    // Line i, j, m examined in rationals for the goal (earliest mode: its
    // t* the rational run's own, exact), as that run examines it; only on
    // an exact region (the rational run's own) is that run's line.
    bool exact() const { return exact_; }
    void test_line(const Pair_formula& f, std::size_t i, std::size_t j, std::size_t m, Search_goal<EFT>& goal)
    {
      CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
      lines_.test_line(f, i, j, m, goal);
    }

  private:
    Check_stats stats_;                   // the interval run counted the lines
    Exact_line_filter policy_;
    Null_object_test<EK, Exact_line_filter> lines_;
    bool exact_;
  };

  // closed: the tables carry the sub-span's time slab (Extrusion::add_time_slab).
  explicit Exact_span(Runner& runner, bool closed = false) : runner_(runner), closed_(closed) {}

  // Whether two planes are one, each a table entry or (entry -1) a face of
  // the interval run's region; a face whose value the intervals only enclose
  // cannot be compared exactly here, and the interval run fails as it would
  // have.
  int proportional(int a, int b, std::size_t s, const std::array<bool, 3>& frame, long eh, int fh, long eg, int fg,
                   const Box<AFT, 4>& region)
  {
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    enter(a, b, s, frame);
    auto plane = [&](long e, int f) {
      if (e >= 0) return entry(static_cast<std::size_t>(e));
      std::optional<Rational> v = runner_.ak().exact_value(f % 2 ? region.hi[f / 2] : region.lo[f / 2]);
      if (!v) throw CGAL::Uncertain_conversion_exception("a region face the intervals only enclose");
      Box<EFT, 4> exact;
      exact.set(f / 2, runner_.ek().from_rational(*v), runner_.ek().from_rational(*v));
      return Null_object_test<EK>::face(exact, f);
    };
    if (eh < 0 || eg < 0) {
      runner_.counted_plane_test();
      return clash4d::proportional(runner_.ek(), plane(eh, fh), plane(eg, fg));
    }
    auto [it, fresh] = answers_.try_emplace({eh, eg}, 0);
    if (fresh) {
      runner_.counted_plane_test();
      it->second = clash4d::proportional(runner_.ek(), plane(eh, fh), plane(eg, fg));
    }
    return it->second;
  }

  // The lines of one interval conquer (its layout and region) the intervals
  // cannot decide. The rational region is the interval region widened to
  // the doubles that enclose it, which contains the rational run's own
  // region: the formula, simplified over the interval region with certified
  // signs, holds over it, and over the sliver outside it may only add
  // points inside, which send the pair to the rational run anyway. When the
  // interval region is exact (grid faces: point intervals) it is the
  // rational run's own, and a line found is the one that run will find.
  // as_is: on the table's own planes (a point found is then the rational
  // run's), not in lowest terms. own: the rational run's region, when the
  // caller knows it (exact/Region_faces.h).
  std::shared_ptr<Lines> lines(int a, int b, std::size_t s, const std::array<bool, 3>& frame, const Plane_layout& layout,
                               const Box<AFT, 4>& region, bool as_is = false, const Box<EFT, 4>* own = nullptr)
  {
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    enter(a, b, s, frame);
    runner_.counted_region();
    Box<EFT, 4> outer;
    bool exact = true;
    for (int q = 0; q < 4; ++q) {
      auto lo = CGAL::to_interval(region.lo[q]), hi = CGAL::to_interval(region.hi[q]);
      exact = exact && lo.first == lo.second && hi.first == hi.second;
      outer.set(q, EFT(lo.first), EFT(hi.second));
    }
    if (own) {
      outer = *own;
      exact = true;
    }
    for (long e : layout.entry)
      if (e >= 0) entry(static_cast<std::size_t>(e));   // all the lines read (Null_object_test::adopt)
    auto conquer = std::make_shared<Lines>(runner_.ek(), as_is ? table_ : lowest_terms(layout), groups_, exact);
    conquer->conquer().adopt(layout, outer);
    return conquer;
  }

  // The region stage of sub-span s (Span_region::stage) in rationals, for
  // an interval run that could not certify it: the rational run's own
  // narrowed times, fitted box and region (grid points, exact in
  // intervals), enclosed, and its emptied S-bounds copied onto the interval
  // run's A and B (only their emptiness shapes the formula,
  // Extrusion::emit). The shear is made from A's and B's velocities by the
  // frame, as the interval run makes it (Extrusion::shear_of).
  template <class M>
  void region_stage(int a, int b, std::size_t s, M& A, M& B, Region_stage<AFT>& st)
  {
    Region_stage<EFT> e;
    Moving_object<EFT> EA, EB;
    {
      CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
      runner_.rational().need_bounds(a);   // the settled S-bounds, all the stage reads
      runner_.rational().need_bounds(b);
      const Scene_model<EK>& model = runner_.rational().model();
      const Time_span<EFT> span = model.sub_spans({a, b}).at(s);
      EA = runner_.rational().bounds_on(a, span);
      EB = runner_.rational().bounds_on(b, span);
      Check_stats scratch;
      e = Span_region<EK>(runner_.ek(), scratch, model.far_exponent, closed_)
              .stage(EA, EB, span, runner_.use_sbounds());
    }
    runner_.counted_stage();
    Exact_stage<EFT>& kept = stages_[s];
    kept.stage = e;
    for (const auto& n : EA.beta) kept.empty_a.push_back(n.empty);
    for (const auto& n : EB.beta) kept.empty_b.push_back(n.empty);
    auto to = [&](const EFT& x) { return runner_.ak().from_rational(runner_.ek().to_rational(x)); };
    auto box = [&](const Box<EFT, 4>& x) {
      Box<AFT, 4> y;
      for (int q = 0; q < 4; ++q) y.set(q, to(x.lo[q]), to(x.hi[q]));
      return y;
    };
    for (std::size_t n = 0; n < A.beta.size(); ++n) A.beta[n].empty = EA.beta[n].empty;
    for (std::size_t n = 0; n < B.beta.size(); ++n) B.beta[n].empty = EB.beta[n].empty;
    st = Region_stage<AFT>();
    st.alive = e.alive;
    st.tl = to(e.tl);
    st.th = to(e.th);
    if (!e.alive) return;
    st.fitted = box(e.fitted);
    if (e.region) st.region = box(*e.region);
    st.frame_of_a = e.frame_of_a;
    for (int q = 0; q < 3; ++q)
      st.shear[q] = !runner_.use_sbounds() ? AFT(0) : e.frame_of_a[q] ? A.v[q] : B.v[q];
  }

  // The stages region_stage made, per sub-span (for the trail's replay).
  Exact_stages<EFT>& stages() { return stages_; }

  // Per table entry of the sub-span, its rational normal scaled to coprime
  // integers (normals), and the whole plane, normal and offset, scaled to
  // coprime integers (planes), enclosed in intervals (point intervals
  // unless the integers are beyond a double's): nonzero multiples of the
  // interval run's entry, so a determinant or dot product of keys the
  // intervals certify zero is zero for those planes, exactly.
  void keys(int a, int b, std::size_t s, const std::array<bool, 3>& frame, std::vector<Vector4<AFT>>& normals,
            std::vector<Hyperplane4<AFT>>& planes)
  {
    std::vector<std::array<Rational, 4>> exact;
    std::vector<std::array<Rational, 5>> whole;
    {
      CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
      enter(a, b, s, frame);
      for (std::size_t e = 0; e < table_.size(); ++e) {
        const Hyperplane4<EFT>& h = entry(e);
        std::array<Rational, 4> x;
        std::array<Rational, 5> y;
        for (int q = 0; q < 4; ++q) y[q] = x[q] = runner_.ek().to_rational(h.n[q]);
        y[4] = runner_.ek().to_rational(h.c);
        scale_to_coprime_integers(x.data(), 4);
        scale_to_coprime_integers(y.data(), 5);
        exact.push_back(x);
        whole.push_back(y);
      }
    }
    auto to = [&](const Rational& x) { return runner_.ak().from_rational(x); };
    normals.clear();
    planes.clear();
    for (const auto& x : exact) normals.push_back({to(x[0]), to(x[1]), to(x[2]), to(x[3])});
    for (const auto& y : whole) planes.push_back({{to(y[0]), to(y[1]), to(y[2]), to(y[3])}, to(y[4])});
  }

private:
  Runner& runner_;
  bool closed_;
  std::size_t span_ = static_cast<std::size_t>(-1);
  // The sub-span's table (Extrusion::pair_table, closed with its time
  // slab), each entry made as it is first read (entry): a rational line
  // reads the planes of one conquer, a fraction of the table.
  std::vector<Hyperplane4<EFT>> table_;
  std::vector<char> made_;
  // On the sub-span, as pair_table takes them (made on entering one: a
  // filter that never asks costs no rational number).
  std::optional<Moving_object<EFT>> A_, B_;
  std::vector<Hyperplane4<EFT>> lowest_;        // table entries in lowest terms, as lines need them
  std::vector<char> lowest_made_;
  Motion_groups<EFT> groups_;
  std::map<std::pair<long, long>, int> answers_;
  Exact_stages<EFT> stages_;

  void enter(int a, int b, std::size_t s, const std::array<bool, 3>& frame)
  {
    if (s == span_) return;
    runner_.rational().need_planes(a);   // the table reads planes alone
    runner_.rational().need_planes(b);
    const Scene_model<EK>& model = runner_.rational().model();
    const Time_span<EFT> span = model.sub_spans({a, b}).at(s);
    A_ = moving_on(model, a, span, {});
    B_ = moving_on(model, b, span, {});
    groups_ = Motion_groups<EFT>();
    bool fitted = runner_.use_sbounds();
    Extrusion<EK>::pair_groups(*A_, *B_, Extrusion<EK>::shear_of(*A_, *B_, frame, fitted), frame, fitted, groups_);
    table_.assign(groups_.of.size(), unmade());
    made_.assign(table_.size(), 0);
    if (closed_) {
      Extrusion<EK>::add_time_slab(table_, span.lo, span.hi);
      made_.resize(table_.size(), 1);
    }
    lowest_.clear();
    answers_.clear();
    span_ = s;
  }

  // Table entry e, made when first read.
  const Hyperplane4<EFT>& entry(std::size_t e)
  {
    if (!made_.at(e)) {
      table_[e] = Extrusion<EK>::pair_entry(*A_, *B_, groups_, e);
      made_[e] = 1;
    }
    return table_[e];
  }

  // What an entry holds until it is made: copies of one zero plane (a
  // rational zero made per coefficient would be an allocation each).
  static const Hyperplane4<EFT>& unmade()
  {
    static const EFT zero(0);
    static const Hyperplane4<EFT> none{{zero, zero, zero, zero}, zero};
    return none;
  }

  // Lines decide signs only (a point found is made again by the rational
  // run), so they may use each plane in lowest terms: the arithmetic of a
  // line then starts from coprime integers, not products of the scene's
  // denominators.
  const std::vector<Hyperplane4<EFT>>& lowest_terms(const Plane_layout& layout)
  {
    if (lowest_.empty()) {
      lowest_ = table_;
      lowest_made_.assign(table_.size(), 0);
    }
    for (long e : layout.entry)
      if (e >= 0 && !lowest_made_[e]) {
        lowest_[e] = runner_.ek().in_lowest_terms(table_[e]);
        lowest_made_[e] = 1;
      }
    return lowest_;
  }
};

} // namespace clash4d

#endif

// `check` and `skeleton` through a filter (CGAL's Filtered_predicate pattern
// applied to a whole pair): every pair is first run by the generic stages on
// the approximate kernel AK (intervals), whose sign() throws
// CGAL::Uncertain_conversion_exception when it cannot certify a sign, with
// the search policy exact/Interval_filter.h, which decides single lines and
// plane comparisons in EK (rationals) instead. Every decision of a run that
// did not stop is certified, the heuristic ones included (S-bound passes and
// frames are chosen on grid points, Kernel_base::grid_point), so such a run
// took the path EK's run takes, on numbers enclosing EK's: its "no
// collision" is EK's.
//
// A colliding pair's witness is made by AK itself when nothing in its run
// was left uncertain (Interval_filter::witness_certified): the witness is
// snapped to a dyadic grid point (Witness::snap), which AK finds exactly
// from its enclosures. Otherwise the line that found the point is run
// again in EK, on the rational run's region, and the witness made from it
// (witness_from); where that is not the rational run's line (AK's path
// was not certified, or the point lay in the sliver between AK's region
// and EK's), the whole search runs again on EK. Earliest mode, in both
// semantics: the interval run decides in rationals the lines that improve
// the goal or tie with its t* (exact/Interval_filter.h), so its path is the
// rational run's; t*, the contact point and the witness are its own where
// they come out as points, and otherwise they are made from its last
// improvement's line in EK as above, or a rational run replays that
// improvement (exact/Earliest_replay.h); where that fails, earliest mode
// runs the whole search in rationals.
// Every witness EK makes is checked against the scene with plane sides
// that AK's model decides where it can certify them (exact/
// Certified_sides.h): the same check, most planes in intervals.
//
// EK's model is built object by object, only for objects that need it.
#ifndef CLASH4D_EXACT_FILTERED_RUNNER_H
#define CLASH4D_EXACT_FILTERED_RUNNER_H

#include "check/Check_runner.h"
#include "exact/Certified_sides.h"
#include "exact/Earliest_replay.h"
#include "exact/Exact_witness_signs.h"
#include "exact/Filtered_result.h"
#include "exact/Interval_filter.h"
#include "exact/Rational_model.h"
#include "exact/Sweep_tie.h"
#include "geometry/Box_meeting.h"
#include "search/Apart_pieces.h"
#include "search/Witness.h"
#include <CGAL/Uncertain.h>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>

namespace clash4d {

// AK::Protector, the RAII guard putting the FPU in the mode AK needs, is
// held around every AK computation, in the thread doing it; AK::
// encloses_here() says whether that mode takes effect on this machine.
template <class AK, class EK>
class Filtered_runner {
public:
  using Approximate_kernel = AK;
  using Exact_kernel = EK;
  using AFT = typename AK::FT;
  using EFT = typename EK::FT;
  using Protector = typename AK::Protector;
  using Result = Filtered_result<AFT, EFT>;

  // reusable: check may be called again (exact/Exact_checker.h).
  Filtered_runner(const Scene& scene, bool use_sbounds, bool reusable = false)
    : scene_(scene), use_sbounds_(use_sbounds), reusable_(reusable), rational_(ek_, scene, use_sbounds) {}

  // On a reusable runner, may be called again (a prepared scene: the model,
  // S-bounds, sweeps and guides are made once), one call at a time; each
  // answer is the one a fresh runner gives, its stats counting its own work.
  Check_answer check(const Check_options& options)
  {
    if (reusable_) reset_counts();   // a fresh runner's are zero
    convex_lp_ = options.convex_lp;
    Check_answer answer;
    answer.stats.timed = options.stage_seconds;
    const std::vector<std::pair<int, int>>* prepared = nullptr;
    if (!prepare(answer.stats, prepared, options.semantics)) {
      answer = run_check(ek_, scene_, options);     // AK could not even build the model
    } else {
      const std::vector<std::pair<int, int>>& pairs = *prepared;
      auto check_one = [&](std::size_t i, const EFT* ceiling, Semantics semantics, Check_stats& stats) {
        Check_options o = options;
        o.semantics = semantics;
        return check_pair(pairs[i].first, pairs[i].second, o, ceiling, stats);
      };
      // A result kept in intervals is printed from them: each number a point
      // (at_start's comparison too, kept_in_points).
      auto answer_one = [&](const Result& r, Pair_answer& p) {
        if (!r.in_points()) return pair_answer(ek_, rational_.model(), r.exact(), p);
        std::optional<Protector> protect;   // at_start's comparison (--earliest) is interval arithmetic
        if (r.points().earliest) protect.emplace();
        pair_answer(ak_, amodel_, r.points(), p);
      };
      run_pairs(ek_, pairs, options, check_one, answer_one, answer);
    }
    answer.number = EK_name;
    answer.semantics = options.semantics;
    finish(answer.stats);
    return answer;
  }

  // One pair of the scene's objects as check asks it, its answer in EK (the
  // rational run's); none when AK cannot build the model, and the caller
  // asks EK itself. For a stage that takes its pairs one at a time: the
  // piece pairs of --earliest on unions (check/Piece_pairs.h), on a runner
  // of the piece scene.
  std::optional<Pair_result<EFT>> check_one(int a, int b, const Check_options& options, const EFT* ceiling,
                                            Check_stats& stats)
  {
    convex_lp_ = options.convex_lp;
    if (!prepared_) {
      // The caller counts its own pairs and bounds: the piece scene's model
      // and sweep counts are not the query's.
      Check_stats made = stats.fresh();
      prepared_ = prepare_model(made);
    }
    if (!*prepared_) return std::nullopt;
    // check_pair writes a pair's own counts (as run_pairs gives each pair),
    // added to the caller's.
    Check_stats own = stats.fresh();
    Result r = check_pair(a, b, options, ceiling, own);
    stats.add(own);
    if (!r.in_points()) return std::move(r.make_exact());
    Pair_result<EFT> e;
    if (r.points().collide) exact_copy(r.points(), e);
    return e;
  }

  // The pairs of the scene's objects whose boxes may meet in this
  // semantics, as check's sweep finds them (its ties decided on EK's
  // boxes), the runner's own; null when AK cannot build the model. Asked
  // before check_one, whose model it makes: the piece pairs ask it first,
  // so that pieces no sweep keeps are answered before anything is made in
  // EK.
  const std::vector<std::pair<int, int>>* swept_pairs(Semantics semantics)
  {
    if (prepared_) throw std::logic_error("Filtered_runner: swept_pairs asked after check_one");
    Check_stats made;   // the piece scene's counts are not the query's (as check_one)
    const std::vector<std::pair<int, int>>* pairs = nullptr;
    prepared_ = prepare(made, pairs, semantics);
    return *prepared_ ? pairs : nullptr;
  }

  // When the boxes of objects i and j, moving, may first meet (the least
  // over sub-spans of first_box_meeting on AK's S-bounds and motions, as
  // the piece pairs ask it in EK): an interval holding that time, none
  // when the intervals are certain, on every sub-span, that they never do.
  // An object AK could not bound, or a sign the intervals cannot tell: the
  // whole span. After swept_pairs.
  std::optional<AFT> box_meeting(int i, int j) const
  {
    const AFT whole(amodel_.t_lo.inf(), amodel_.t_hi.sup());
    if (exact_only(i) || exact_only(j)) return whole;
    std::size_t ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
    const Motion_path<AFT>&a = amodel_.objects[ui].motion, &b = amodel_.objects[uj].motion;
    try {
      Protector protect;
      std::optional<AFT> first;
      for (const auto& span : amodel_.sub_spans({i, j})) {
        std::size_t sa = amodel_.segment_on(i, span), sb = amodel_.segment_on(j, span);
        std::optional<AFT> t = first_box_meeting(ak_, asettled_[ui][0], a.velocity[sa], a.offset[sa],
                                                 asettled_[uj][0], b.velocity[sb], b.offset[sb], span.lo, span.hi);
        if (t) first = first ? AFT(std::min(first->inf(), t->inf()), std::min(first->sup(), t->sup())) : *t;
      }
      return first;
    } catch (const CGAL::Uncertain_conversion_exception&) {   // this predicate's filter only
      return whole;
    }
  }

  // The runner's own counters (its work in rationals, exact/ only) into
  // stats: check does it at its end; a caller of check_one at its own
  // (the piece pairs: exact/Exact_instantiation.cpp).
  void finish(Check_stats& stats) const
  {
    stats.exact_fallbacks = fallbacks_.load();
    stats.exact_witness_runs = witness_runs_.load();
    stats.exact_regions = exact_regions_.load();
    stats.exact_plane_tests = exact_planes_.load();
    stats.exact_region_stages = exact_stages_.load();
    stats.witnesses_by_intervals = witnesses_by_intervals_.load();
    stats.earliest_by_intervals = earliest_by_intervals_.load();
    stats.apart_proofs = apart_proofs_.load();
    stats.apart_attempts = apart_attempts_.load();
    stats.replay_stages_adopted = stages_adopted_.load();
    stats.earliest_lines_rerun = lines_rerun_.load();
    stats.witness_lines_rerun = witness_lines_.load();
    stats.closed_cells_by_intervals = closed_cells_.load();
    stats.witnesses_by_terms = witnesses_by_terms_.load();
  }

  // A reusable runner's scene, whose objects in `changed` now have other
  // motions (exact/Exact_checker.h): what depends on motions is made again
  // by the next check, as a fresh runner would make it (each object's
  // motion in AK and EK, its guide's motion, the sweeps, the far exponent);
  // what depends on shapes alone is kept (the models' trees, S-bounds, EK's
  // planes, the guides' planes). Only while no check runs.
  void motions_changed(const std::vector<int>& changed)
  {
    if (!reusable_) throw std::logic_error("Filtered_runner::motions_changed: not made reusable");
    for (Prepared_sweep& sweep : sweeps_) sweep.done = false;   // made again by the next check, into the same storage
    rational_.motions_changed(changed);
    if (!model_.done || !model_.ok) {
      model_ = Prepared_model();   // made whole by the next check
      return;
    }
    try {
      Protector protect;
      for (int i : changed) amodel_.objects[i].motion.rebuild(ak_, scene_.objects[i].motion);
      amodel_.far_exponent = rational_.model().far_exponent = far_exponent(scene_);
    } catch (const CGAL::Uncertain_conversion_exception&) {
      model_ = Prepared_model();
    }
  }

  Skeleton_answer skeleton()
  {
    if (!use_sbounds_) throw std::logic_error("Filtered_runner::skeleton: made without S-bounds");
    if (reusable_) reset_counts();   // a fresh runner's are zero
    Skeleton_answer answer;
    const std::vector<std::pair<int, int>>* prepared = nullptr;
    if (!prepare(answer.stats, prepared)) {
      answer = run_skeleton(ek_, scene_);
    } else {
      const std::vector<std::pair<int, int>>& pairs = *prepared;
      auto skeleton_one = [&](std::size_t i, Check_stats& stats) {
      int a = pairs[i].first, b = pairs[i].second;
      if (!exact_only_[a] && !exact_only_[b]) {
        try {
          Protector protect;
          Check_stats astats = stats.fresh();
          if (Pair_skeleton<AK>(ak_, amodel_, asettled_, astats).edges(a, b).empty()) {
            stats = astats;
            return std::vector<typename Pair_skeleton<EK>::Segment>();
          }
          ++witness_runs_;
        } catch (const CGAL::Uncertain_conversion_exception&) {
          ++fallbacks_;
        }
      }
      rational_.need_exact(a);
      rational_.need_exact(b);
      return Pair_skeleton<EK>(ek_, rational_.model(), rational_.settled(), stats).edges(a, b);
    };
      run_skeleton_pairs(ek_, rational_.model(), pairs, skeleton_one, answer);
    }
    answer.number = EK_name;
    finish(answer.stats);
    return answer;
  }

  // What its policies (exact/Interval_filter.h, exact/Exact_span.h,
  // exact/Sweep_tie.h) read of the run, and the exact work they ask of it;
  // they reach nothing else.
  const AK& ak() const { return ak_; }
  const EK& ek() const { return ek_; }
  const Scene& scene() const { return scene_; }
  bool use_sbounds() const { return use_sbounds_; }
  const Scene_model<AK>& interval_model() const { return amodel_; }
  bool exact_only(int i) const { return exact_only_[static_cast<std::size_t>(i)] != 0; }
  Rational_model<EK>& rational() { return rational_; }
  // The witness checks' plane sides in EK's runs (certified_sides).
  const Sides_at<EFT>& certified() const { return certified_; }
  // --stats: a plane tested in rationals on a sub-span's table, a region
  // made in rationals, a region stage run in rationals (exact/Exact_span.h).
  void counted_plane_test() { ++exact_planes_; }
  void counted_region() { ++exact_regions_; }
  void counted_stage() { ++exact_stages_; }

  // A long search handed over (Interval_filter::decides_here):
  // whether conflicts close off every term of the pair's formula on the
  // scene's whole span, exact LPs on EK's model (search/Apart_pieces.h):
  // proven, that is the pair's "no collision", as its certificate proves
  // it. Not: a term the double simplex's guess does not close off (it may
  // have a point; asking again would meet it again), or past step_limit.
  // Not proven: apart_until, the end of the leading sub-spans it did prove
  // apart (Apart_pieces::proven_until; tL when none), which hold nothing.
  // inside (regularised, any point wanted): where the open term's LP guessed
  // a point inside it, the witness made from it and checked (witness_at),
  // the pair's collision (Apart::inside).
  enum class Apart { proven, not_proven, out_of_steps, inside };
  Apart proves_apart(int a, int b, Semantics semantics, std::uint64_t step_limit, Rational& apart_until,
                     Pair_result<EFT>* inside = nullptr)
  {
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    rational_.need_model(a);
    rational_.need_model(b);
    Apart_pieces<EK> pieces(rational_.model(), semantics, step_limit, Lp_effort::quick);
    pieces.prove(a, b, ek_.to_rational(rational_.model().t_hi), false);
    Apart verdict = Apart::proven;
    if (const std::optional<Term_stop>& stop = pieces.stopped()) {
      verdict = stop->why == Term_stop::Why::out_of_steps ? Apart::out_of_steps : Apart::not_proven;
      if (verdict == Apart::not_proven && inside && stop->inside.found && witness_at(a, b, stop->inside.x, *inside)) {
        verdict = Apart::inside;
        ++witnesses_by_terms_;
      }
    }
    ++(verdict == Apart::proven ? apart_proofs_ : apart_attempts_);
    apart_until = pieces.proven_until();
    return verdict;
  }

  // Whether sub-span s of pair (a, b) ends by `until` (need_motion).
  bool span_ends_by(int a, int b, std::size_t s, const Rational& until) const
  {
    return !ek_.less(ek_.from_rational(until), rational_.model().sub_spans({a, b}).at(s).hi);
  }

  // AK's number x in EK when it is a point interval: then it is the exact
  // number the rational run has there. Exchanged in (swap_numbers: no copy
  // of a rational).
  bool to_exact(const AFT& x, EFT& to) const
  {
    std::optional<Rational> v = ak_.exact_value(x);
    if (!v) return false;
    EFT e = ek_.from_rational(*v);
    swap_numbers(to, e);
    return true;
  }
  // The same for a point: every coordinate a point interval.
  bool to_exact(const Vector4<AFT>& x, Vector4<EFT>& to) const
  {
    for (int q = 0; q < 4; ++q)
      if (!to_exact(x[q], to[q])) return false;
    return true;
  }

  // Object i's root box in EK, as the sweep reads it: a one-primitive
  // object's is its primitive's box (its S-bounds have nothing to narrow),
  // made without a model (Model_builder::primitive_box); another's, its
  // settled S-bounds' root. Either holds the object (the sweep's only need).
  Box<EFT, 3> exact_root(int i)
  {
    rational_.need_motion(i);
    if (amodel_.objects[i].csg.nodes.size() != 1) {
      rational_.need_bounds(i);
      return rational_.settled()[i][0];
    }
    return Model_builder<EK>(ek_).primitive_box(scene_.objects[static_cast<std::size_t>(i)].shape);
  }

  Box<AFT, 3> enclose(const Box<EFT, 3>& e) const
  {
    Box<AFT, 3> b;
    b.empty = e.empty;
    b.has_lo = e.has_lo;
    b.has_hi = e.has_hi;
    for (int q = 0; q < 3; ++q) {
      if (e.has_lo[q]) b.lo[q] = ak_.from_rational(ek_.to_rational(e.lo[q]));
      if (e.has_hi[q]) b.hi[q] = ak_.from_rational(ek_.to_rational(e.hi[q]));
    }
    return b;
  }

private:
  static constexpr const char* EK_name = "exact";

  // A point the double simplex guessed inside a term of the pair's formula
  // (Term_stop::inside; world frame), made the pair's witness as a search's
  // point inside is made (Witness::make: moved off every plane of both
  // objects on its sub-span, snapped) and checked (is_valid_witness): a
  // regularised collision. False when it is not one after all. The guess
  // is only where to look; every sign is EK's. Asked by proves_apart alone.
  bool witness_at(int a, int b, const std::array<double, 4>& x, Pair_result<EFT>& r)
  {
    Vector4<EFT> p;
    for (int q = 0; q < 4; ++q) {
      if (!std::isfinite(x[q])) return false;
      p[q] = ek_.from_rational(exact_rational(x[q]));
    }
    const auto& spans = rational_.model().sub_spans({a, b});
    auto span = std::find_if(spans.begin(), spans.end(),
                             [&](const Time_span<EFT>& s) { return !ek_.less(p[3], s.lo) && !ek_.less(s.hi, p[3]); });
    if (span == spans.end()) return false;
    // Both models are whole: proves_apart made them (need_model).
    Moving_object<EFT> A = moving_on(rational_.model(), a, *span, {}), B = moving_on(rational_.model(), b, *span, {});
    const Vector3<EFT> no_shear{EFT(0), EFT(0), EFT(0)};
    std::optional<Vector4<EFT>> w = Witness<EK>(ek_).make(p, no_shear, A, B, span->lo, span->hi);
    if (!w || !is_valid_witness(ek_, rational_.model(), a, b, *w, &certified_)) return false;
    r = Pair_result<EFT>();
    r.a = a;
    r.b = b;
    r.collide = r.has_witness = r.witness_verified = true;
    r.witness = r.contact = *w;
    return true;
  }

  // One pair: the interval run, then, when it could not decide or could not
  // make the witness, EK along its trail or from the start. A witness the
  // interval run made of points stays in them (exact/Filtered_result.h).
  Result check_pair(int a, int b, const Check_options& options, const EFT* ceiling, Check_stats& stats)
  {
    Search_trail trail;
    Check_stats astats = stats.fresh();
    bool earliest_trail = false;
    Exact_stages<EFT> stages;   // region stages the interval run made in rationals, for the replay
    Stage_clock clock(stats.timed);
    if (!exact_only_[a] && !exact_only_[b]) {
      try {
        Protector protect;
        AFT aceiling = ceiling ? ak_.from_rational(ek_.to_rational(*ceiling)) : AFT(0);
        Interval_filter<Filtered_runner> policy(*this, trail, astats, options.semantics);
        if (options.earliest) policy.resolve_earliest(ceiling);
        if (!options.apart_proofs) policy.never_hand_over();
        Collision_checker<AK, Interval_filter<Filtered_runner>> checker(ak_, amodel_, asettled_, astats, use_sbounds_,
                                                                        &policy);
        checker.use_convex_lp(convex_lp_);
        checker.use_guides(&guide_source_);
        Pair_result<AFT> found =
            checker.check_pair(a, b, options.earliest, ceiling ? &aceiling : nullptr, options.semantics);
        using Stop = typename Interval_filter<Filtered_runner>::Stop;
        switch (policy.stop()) {
        case Stop::apart:
          stopped_in_search(astats, clock, stats);
          return Result();
        case Stop::inside:
          stopped_in_search(astats, clock, stats);
          return Pair_result<EFT>(std::move(policy.found_inside()));
        case Stop::convex_uncertain:
          ++fallbacks_;   // a sign outside the programs' own: the pair in rationals
          trail.complete = false;
          break;
        case Stop::none:
          if (std::optional<Result> r = interval_answer(policy, std::move(found), a, b, options, astats, stats))
            return std::move(*r);
          earliest_trail = options.earliest && policy.earliest_trail();
          stages = policy.take_stages();
          ++witness_runs_;
        }
      } catch (const CGAL::Uncertain_conversion_exception&) {
        ++fallbacks_;
        trail.complete = false;
      }
    }
    rational_.need_exact(a);
    rational_.need_exact(b);
    if (earliest_trail)
      if (auto r = replayed(trail, stages, a, b, options.semantics, astats, stats)) return std::move(*r);
    Collision_checker<EK> checker(ek_, rational_.model(), rational_.settled(), stats, use_sbounds_);
    checker.use_convex_lp(convex_lp_);
    checker.check_points_with(&certified_);
    checker.use_guides(&guide_source_);
    return checker.check_pair(a, b, options.earliest, ceiling, options.semantics);
  }

  // The interval run's answer when it searched to the end: none found, a
  // witness of points, a convex pair's answer, or the witness line's;
  // nothing when a rational run must make it.
  std::optional<Result> interval_answer(Interval_filter<Filtered_runner>& policy, Pair_result<AFT>&& found, int a,
                                        int b, const Check_options& options, Check_stats& astats, Check_stats& stats)
  {
    if (!found.collide) {
      stats = std::move(astats);
      return Result();
    }
    if (found.has_witness && found.witness_verified && exact_copyable(found)) {
      stats = std::move(astats);
      ++witnesses_by_intervals_;
      return kept_in_points(std::move(found));
    }
    if (std::optional<Pair_result<EFT>> r = policy.convex_answer(found)) {
      stats = std::move(astats);
      return Result(std::move(*r));
    }
    if (std::optional<Pair_result<EFT>> r = witness_line(policy, a, b, options, astats, stats))
      return Result(std::move(*r));
    return std::nullopt;
  }

  // The interval run stopped inside a span by a hand-over's answer
  // (Interval_filter::Stop apart or inside): its time, and the LPs', are the
  // search's.
  static void stopped_in_search(const Check_stats& astats, const Stage_clock& clock, Check_stats& stats)
  {
    stats = astats;
    double counted = astats.seconds_sbounds + astats.seconds_divide + astats.seconds_witness;
    stats.seconds_divide += std::max(0.0, clock.seconds() - counted);
  }

  // witness_from, timed and counted; stats: the interval run's, on success.
  std::optional<Pair_result<EFT>> witness_line(Interval_filter<Filtered_runner>& policy, int a, int b,
                                               const Check_options& options, const Check_stats& astats,
                                               Check_stats& stats)
  {
    Stage_clock made(stats.timed);
    std::optional<Pair_result<EFT>> r = witness_from(policy, a, b, options.semantics, options.earliest);
    if (!r) return r;
    stats = astats;
    stats.seconds_witness += made.seconds();
    ++witness_runs_;
    if (options.earliest) {
      ++earliest_by_intervals_;
      ++lines_rerun_;
    } else {
      ++witness_lines_;
    }
    return r;
  }

  // When the intervals found the point (earliest mode: t*) but could not
  // make the witness: the rational run's goal, made from the line that
  // found it (Interval_filter::exact_goal), and its witness made in EK as
  // the rational run makes it, instead of replaying the search to that line.
  std::optional<Pair_result<EFT>> witness_from(Interval_filter<Filtered_runner>& policy, int a, int b,
                                               Semantics semantics, bool earliest)
  {
    std::optional<typename Interval_filter<Filtered_runner>::Exact_goal> g = policy.exact_goal();
    if (!g) return std::nullopt;
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    rational_.need_planes(a);   // the witness and its check read planes alone
    rational_.need_planes(b);
    const Time_span<EFT> span = rational_.model().sub_spans({a, b}).at(g->span);
    Moving_object<EFT> A = moving_on(rational_.model(), a, span, {}), B = moving_on(rational_.model(), b, span, {});
    Pair_result<EFT> r;
    r.a = a;
    r.b = b;
    r.semantics = semantics;
    r.collide = true;
    Check_stats ignored;
    Vector3<EFT> shear = Extrusion<EK>::shear_of(A, B, g->frame, use_sbounds_);
    std::optional<std::array<Vector4<EFT>, 2>> cells;
    if (g->goal.closed() && !g->goal.convex) cells = interval_cells(*g, a, b, A, B, shear);
    Collision_checker<EK> checker(ek_, rational_.model(), rational_.settled(), ignored, use_sbounds_);
    checker.check_points_with(&certified_);
    checker.use_guides(&guide_source_);
    checker.make_witness(g->goal, shear, A, B, span, r, cells ? &*cells : nullptr);
    if (!r.witness_verified) return std::nullopt;   // not expected: the search in rationals decides
    r.earliest = earliest;
    return r;
  }

  // The sides of object i's planes at y, a point of its solid, for the
  // witness checks of EK's runs: intervals first (exact/Certified_sides.h).
  Plane_sides<EFT> certified_sides(int i, const Vector3<EFT>& y) const
  {
    std::size_t o = static_cast<std::size_t>(i);
    return clash4d::certified_sides(ak_, amodel_.objects[o].csg, ek_, rational_.model().objects[o].csg, y);
  }

  // Closed: each object's generic point near the contact (Witness::
  // near_in_space) made in AK, the signs AK cannot tell there asked of EK
  // (Exact_witness_signs): EK's own points, whose space coordinates are
  // snapped (point intervals) and whose time is the contact's; or none,
  // and EK makes them. A and B, shear: EK's, on g's sub-span.
  std::optional<std::array<Vector4<EFT>, 2>> interval_cells(const typename Interval_filter<Filtered_runner>::Exact_goal& g,
                                                            int a, int b, const Moving_object<EFT>& A,
                                                            const Moving_object<EFT>& B, const Vector3<EFT>& shear)
  {
    try {
      Protector protect;
      const Time_span<AFT> span = amodel_.sub_spans({a, b}).at(g.span);
      const Moving_object<AFT> IA = moving_on(amodel_, a, span, {}), IB = moving_on(amodel_, b, span, {});
      const Vector3<AFT> ishear = Extrusion<AK>::shear_of(IA, IB, g.frame, use_sbounds_);
      auto enclose = [&](const Vector4<EFT>& x) {
        Vector4<AFT> y;
        for (int q = 0; q < 4; ++q) y[q] = ak_.from_rational(ek_.to_rational(x[q]));
        return y;
      };
      const Moving_object<EFT>* exact[2] = {&A, &B};
      const Moving_object<AFT>* approx[2] = {&IA, &IB};
      const Vector4<EFT>* toward[2] = {&g.goal.toward_a, &g.goal.toward_b};
      std::array<Vector4<EFT>, 2> out;
      for (int o = 0; o < 2; ++o) {
        Exact_witness_signs<EK> signs(ek_, *exact[o], g.goal.contact, *toward[o], shear);
        std::size_t count = 0;
        for (const auto& prim : approx[o]->object->csg.primitives) count += prim.planes.size();
        if (count != signs.plane_count()) return std::nullopt;   // not expected: one scene, one model
        std::optional<Vector4<AFT>> p =
            Witness<AK>(ak_).near_in_space(enclose(g.goal.contact), enclose(*toward[o]), ishear, *approx[o], &signs);
        if (!p) return std::nullopt;
        for (int q = 0; q < 3; ++q) {
          std::optional<Rational> x = ak_.exact_value((*p)[q]);
          if (!x) return std::nullopt;
          out[o][q] = ek_.from_rational(*x);
        }
        out[o][3] = g.goal.contact[3];   // near_in_space keeps the time
      }
      ++closed_cells_;
      return out;
    } catch (const CGAL::Uncertain_conversion_exception&) {
      return std::nullopt;
    }
  }

  // EK along the earliest-mode interval run's trail, to its last
  // improvement; the answer when the trail held, counted.
  std::optional<Pair_result<EFT>> replayed(const Search_trail& trail, const Exact_stages<EFT>& stages, int a, int b,
                                           Semantics semantics, const Check_stats& astats, Check_stats& stats)
  {
    Check_stats rstats = stats.fresh();
    Earliest_replay<EFT> replay(trail, stages);
    Collision_checker<EK, Earliest_replay<EFT>> checker(ek_, rational_.model(), rational_.settled(), rstats,
                                                        use_sbounds_, &replay);
    checker.check_points_with(&certified_);
    checker.use_guides(&guide_source_);
    checker.use_convex_lp(convex_lp_);
    Pair_result<EFT> r = checker.check_pair(a, b, true, nullptr, semantics);
    if (!r.collide || replay.diverged()) return std::nullopt;
    ++earliest_by_intervals_;
    stages_adopted_ += replay.adopted();
    stats = astats;                     // the search, as the interval run did it
    stats.seconds_witness += rstats.seconds_witness;
    return r;
  }

  const Scene& scene_;
  const bool use_sbounds_, reusable_;
  bool convex_lp_ = true;
  std::optional<bool> prepared_;              // check_one: whether prepare_model could (none: not yet asked)
  AK ak_;
  EK ek_;
  Rational_model<EK> rational_;               // EK's model, object by object as asked
  Scene_model<AK> amodel_;
  std::vector<typename S_bounds<AK>::Bounds> asettled_;
  std::vector<char> exact_only_;              // AK could not bound the object: its pairs go to EK
  // What prepare made: AK's model and S-bounds, with the stats of their
  // making; the sweep's pairs per semantics (regularised, closed), with
  // the counts the sweep sets (all of the stats it changes: sweep_pairs),
  // so that a sweep made again per query (other motions) copies no stats.
  struct Prepared_model {
    bool done = false, ok = false;
    std::optional<Check_stats> stats;
  };
  struct Prepared_sweep {
    bool done = false;
    std::vector<std::pair<int, int>> pairs;
    std::size_t object_pairs = 0, candidate_pairs = 0, exact_sweep_ties = 0;
    void keep(const Check_stats& s)
    {
      object_pairs = s.object_pairs, candidate_pairs = s.candidate_pairs, exact_sweep_ties = s.exact_sweep_ties;
    }
    void put(Check_stats& s) const
    {
      s.object_pairs = object_pairs, s.candidate_pairs = candidate_pairs, s.exact_sweep_ties = exact_sweep_ties;
    }
  };
  Prepared_model model_;
  Prepared_sweep sweeps_[2];
  std::vector<char> sweep_certain_;           // the intervals' sweep's, per pair (drop_apart_ties)
  const Sides_at<EFT> certified_{[this](int i, const Vector3<EFT>& y) { return certified_sides(i, y); }};
  // Each object's convex-pair guide, made once (search/Convex_guide.h): all
  // pairs of a check, and every check of a prepared scene, share it.
  const Guide_source guide_source_{[this](int i) { return rational_.guide(i); }};
  std::atomic<std::size_t> fallbacks_{0}, witness_runs_{0}, exact_regions_{0}, exact_planes_{0},
      witnesses_by_intervals_{0}, earliest_by_intervals_{0}, exact_stages_{0}, apart_proofs_{0}, apart_attempts_{0},
      stages_adopted_{0}, lines_rerun_{0}, witness_lines_{0}, closed_cells_{0},
      witnesses_by_terms_{0};

  // Whether to_exact(x) takes, without making the number.
  bool exact_point(const Vector4<AFT>& x) const
  {
    return std::all_of(x.begin(), x.end(), [&](const AFT& c) { return ak_.has_exact_value(c); });
  }
  // Whether AK's witness, verified on a certified path, is EK's: each
  // number exact_copy takes a point interval. Regularised, the witness's
  // coordinates are grid points (Witness::snap), exact doubles, so AK's
  // point intervals are EK's numbers. Closed, the touching point is any
  // rational: kept only when every coordinate of it and of the generic
  // points is a point interval, whose verification (all signs certain,
  // zeros only of exact point arithmetic) holds for that point.
  // Earliest: t*, the contact point and its generic points (closed: the
  // first touch, kept above), each kept only as a point interval, the
  // rational run's number (the goal encloses that run's,
  // exact/Interval_filter.h).
  bool exact_copyable(const Pair_result<AFT>& found) const
  {
    bool closed = found.semantics == Semantics::closed;
    if (!exact_point(found.witness)) {
      if (closed) return false;
      throw std::logic_error("internal error: an interval witness is not a point");
    }
    auto cells = [&](const std::vector<Vector4<AFT>>& c) {
      return c.size() == 2 && exact_point(c[0]) && exact_point(c[1]);
    };
    if (closed && !cells(found.witness_cells)) return false;
    return !found.earliest ||
           (ak_.has_exact_value(found.t_star) && exact_point(found.contact) && cells(found.contact_cells));
  }
  // An exact_copyable answer kept in its points, with t* in EK for
  // run_pairs (one rational, where EK's copy of the whole answer made two
  // dozen). Copied into EK only when --earliest's at_start would compare a
  // point t* with a t_lo that is no point (pair_answer: in intervals, an
  // uncertain sign).
  Result kept_in_points(Pair_result<AFT>&& found) const
  {
    if (!found.earliest) return Result::of_points(std::move(found));
    if (!ak_.has_exact_value(amodel_.t_lo)) {
      Result r;
      exact_copy(found, r.make_exact());   // in place: a copy of rationals costs
      return r;
    }
    std::optional<Rational> t = ak_.exact_value(found.t_star);
    if (!t) throw std::logic_error("internal error: an --earliest answer's t* not a point");
    EFT exact_t = ek_.from_rational(*t);
    return Result::of_points(std::move(found), &exact_t);
  }
  // That witness in EK's numbers (exact_copyable), written into r, a
  // fresh result.
  void exact_copy(const Pair_result<AFT>& found, Pair_result<EFT>& r) const
  {
    auto take = [&](const auto& x, auto& to) {
      if (!to_exact(x, to)) throw std::logic_error("internal error: exact_copy of a number that is not a point");
    };
    r.a = found.a;
    r.b = found.b;
    r.semantics = found.semantics;
    r.collide = r.has_witness = r.witness_verified = true;
    take(found.witness, r.witness);
    if (found.semantics == Semantics::closed) {
      r.witness_cells.resize(2);
      for (int i = 0; i < 2; ++i) take(found.witness_cells[i], r.witness_cells[i]);
      r.contact_cells = r.witness_cells;
      r.contact = r.witness;
    }
    if (found.earliest) {
      take(found.t_star, r.t_star);
      take(found.contact, r.contact);
      r.contact_cells.resize(2);
      for (int i = 0; i < 2; ++i) take(found.contact_cells[i], r.contact_cells[i]);
      r.earliest = true;
    }
  }

  // AK's model, each object's S-bounds (EK's where AK fails), and the sweep's
  // pairs. False when AK cannot build the model, or cannot be trusted on
  // this machine at all (AK::encloses_here): the whole run goes to EK.
  // Made once (the pairs once per semantics): a prepared scene's later
  // checks reuse them, and their stats give the same counts with no time.
  bool prepare(Check_stats& stats, const std::vector<std::pair<int, int>>*& pairs,
               Semantics semantics = Semantics::regularised)
  {
    if (!prepare_model(stats)) return false;
    Prepared_sweep& sweep = sweeps_[semantics == Semantics::closed ? 1 : 0];
    if (!sweep.done) {
      sweep_pairs(stats, sweep.pairs, semantics);
      sweep.done = true;
      sweep.keep(stats);
    } else {
      sweep.put(stats);
    }
    pairs = &sweep.pairs;
    return true;
  }
  // AK's model and each object's S-bounds, made once: all a pair's check
  // reads (check_one asks no sweep: its caller chose the pair).
  bool prepare_model(Check_stats& stats)
  {
    if (!AK::encloses_here()) {   // AK's signs could be wrong on this machine (valgrind): EK alone
      ++fallbacks_;
      return false;
    }
    if (!model_.done) {
      model_.ok = build_model(stats);
      model_.done = true;
      if (reusable_) model_.stats = stats;   // (a single check's runner copies nothing)
    } else {
      reuse_model(stats);
    }
    return model_.ok;
  }
  // A reused model's counts in stats, with no time (a later check of a
  // prepared scene), copied in place.
  void reuse_model(Check_stats& stats) const
  {
    if (!model_.stats) throw std::logic_error("Filtered_runner: checked again, but not made reusable");
    bool timed = stats.timed;
    stats = *model_.stats;
    stats.clear_seconds();
    stats.timed = timed;
  }
  bool build_model(Check_stats& stats)
  {
    std::size_t n = scene_.objects.size();
    exact_only_.assign(n, 0);
    asettled_.clear();   // a check stopped here before (a work budget) left a part
    Stage_clock clock(stats.timed);
    try {
      Protector protect;
      amodel_ = Scene_model<AK>::build(ak_, scene_);
      rational_.model().far_exponent = amodel_.far_exponent;   // one exponent, from the scene: EK's runs take AK's path
    } catch (const CGAL::Uncertain_conversion_exception&) {
      ++fallbacks_;
      return false;
    }
    stats.seconds_model = clock.lap();
    for (std::size_t i = 0; i < n; ++i) asettled_.push_back(settle(static_cast<int>(i), stats));
    stats.seconds_sbounds += clock.seconds();
    return true;
  }
  void sweep_pairs(Check_stats& stats, std::vector<std::pair<int, int>>& pairs, Semantics semantics)
  {
    try {
      Protector protect;
      candidate_pairs(ak_, amodel_, asettled_, scene_, stats, semantics, pairs, &sweep_certain_);
    } catch (const CGAL::Uncertain_conversion_exception&) {
      // The sweep could not order some motion times: sweep in EK instead.
      ++fallbacks_;
      for (std::size_t i = 0; i < scene_.objects.size(); ++i) rational_.need_exact(static_cast<int>(i));
      candidate_pairs(ek_, rational_.model(), rational_.settled(), scene_, stats, semantics, pairs);
      return;
    }
    drop_apart_ties(pairs, sweep_certain_, stats, semantics);
  }

  // The pairs the intervals' sweep kept only because their boxes might
  // touch (rounding: every sign certain but a tie's), decided on EK's boxes:
  // boxes that only touch have no common interior, so such a pair cannot
  // collide in regularised semantics. The double run drops such a pair by
  // rounding's luck (a contact under a rotation); this drops it by proof,
  // before any convex program or search.
  // Closed semantics keeps its ties unexamined: touching boxes meet there,
  // so only a gap below the intervals' width would drop the pair, while the
  // usual tie is an exact contact that EK's boxes keep after making both
  // objects' motions and boxes in rationals (a fifth of a decimal contact's
  // query). A pair kept with such a gap is proven apart by its own check,
  // which decides any pair: the answer is the rational run's.
  void drop_apart_ties(std::vector<std::pair<int, int>>& pairs, const std::vector<char>& certain, Check_stats& stats,
                       Semantics semantics)
  {
    if (semantics == Semantics::closed || std::find(certain.begin(), certain.end(), 0) == certain.end()) return;
    Stage_clock clock(stats.timed);
    Sweep_tie<Filtered_runner> ties(*this);
    std::vector<std::pair<int, int>> kept;
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      auto [i, j] = pairs[p];
      if (!certain[p]) {
        ++stats.exact_sweep_ties;
        if (!tie_meets(ties, i, j)) continue;
      }
      kept.emplace_back(i, j);
    }
    stats.candidate_pairs = kept.size();
    stats.seconds_sweep += clock.seconds();
    pairs = std::move(kept);
  }

  // A tie's pair on exact sides (Sweep_tie); where the intervals cannot
  // even make the boxes, on EK's whole boxes (Pair_sweep::meets).
  bool tie_meets(Sweep_tie<Filtered_runner>& ties, int i, int j)
  {
    try {
      return ties.meets(i, j);
    } catch (const CGAL::Uncertain_conversion_exception&) {
      ++fallbacks_;
    }
    std::vector<Box<EFT, 3>> eroots(scene_.objects.size());
    eroots[static_cast<std::size_t>(i)] = exact_root(i);
    eroots[static_cast<std::size_t>(j)] = exact_root(j);
    return Pair_sweep<EK>(ek_, false).meets(rational_.model(), eroots, i, j);
  }

  typename S_bounds<AK>::Bounds settle(int i, Check_stats& stats)
  {
    try {
      Protector protect;
      return settled_bounds(ak_, amodel_.objects[i].csg, stats, use_sbounds_);
    } catch (const CGAL::Uncertain_conversion_exception&) {
      ++fallbacks_;
      exact_only_[i] = 1;
      rational_.need_exact(i);
      // Only the sweep reads it: the root box, EK's enclosed in AK's numbers.
      Protector protect;
      return typename S_bounds<AK>::Bounds(1, enclose(rational_.settled()[i][0]));
    }
  }

  void reset_counts()
  {
    for (std::atomic<std::size_t>* c :
         {&fallbacks_, &witness_runs_, &exact_regions_, &exact_planes_, &witnesses_by_intervals_,
          &earliest_by_intervals_, &exact_stages_, &apart_proofs_, &apart_attempts_, &stages_adopted_, &lines_rerun_,
          &witness_lines_, &closed_cells_, &witnesses_by_terms_})
      c->store(0, std::memory_order_relaxed);   // no check is running: nothing to order against
  }
};

} // namespace clash4d

#endif

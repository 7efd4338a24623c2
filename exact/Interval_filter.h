// The search policy of a pair's interval run, the approximate half of the
// filtered exact kernel (exact/Filtered_runner.h). The interval kernel
// throws CGAL::Uncertain_conversion_exception for a sign it cannot
// certify; this policy is where that is caught:
//  - a zero of a plane on a line (parallel, containing), the order of two
//    cuts of a line, and (earliest mode) a tie of a vertex with t* are
//    asked of the conquer's rational planes alone (zero_on_line,
//    compare_cuts, improves);
//  - a line of generate-and-test with another such sign is decided in
//    rationals alone (exact/Exact_span.h) and the run goes on;
//  - two planes the intervals cannot tell apart are compared on the
//    rational planes;
//  - a witness the intervals cannot make is left to a rational run;
//  - once a line or a box simplification of a sub-span was uncertain,
//    generate-and-test and divide-and-conquer get the
//    normals of the sub-span's rational planes in lowest terms
//    (normal_keys, Exact_span::normal_keys): small integers, on which
//    intervals are exact, so planes that are parallel after a rational
//    rotation (and lines of dependent normals) are zeros it writes.
// Anything else uncertain stops the run, and the runner redoes the pair in
// rationals. For an any-witness search it records whether its path to the
// first point inside was certified (exact/Search_trail.h), so that only the
// line that found it is run again in rationals (exact_goal).
//
// Earliest mode, in both semantics (resolve_earliest; closed: t* is the
// first touch): t* is any rational, which
// intervals only enclose, and the vertex at t* ends several edges, whose
// times tie with it. So a line with a sign the intervals cannot certify is
// examined again in rationals, on the same layout
// (Exact_span::Lines::earliest), against the goal's exact t* (kept here
// beside the goal's enclosure of it), and the goal then holds the rational
// run's own t*, enclosed. A line the intervals examined to the end made
// the rational run's decisions: if it recorded nothing, the rational run
// records nothing there either; if it improved the goal, the goal holds an
// enclosure of the rational run's t*, whose exact value is made only when
// a later line needs it (the line again in rationals, from nothing found:
// its least time, below the previous t*, is recorded either way).
// A region folded to "inside" records its own lower time, a grid point.
// The trail then ends at the last improvement (the rational run's last),
// and a rational run replays it (Earliest_replay) to make t*, the contact
// point and the witness, instead of searching the whole pair again.
#ifndef CLASH4D_EXACT_INTERVAL_FILTER_H
#define CLASH4D_EXACT_INTERVAL_FILTER_H

#include "exact/Apart_hand_over.h"
#include "exact/Exact_span.h"
#include "exact/Region_faces.h"
#include "exact/Search_trail.h"
#include <cmath>
#include <limits>
#include <type_traits>
#include <variant>

namespace clash4d {

template <class Runner>
class Interval_filter {
public:
  using AK = typename Runner::Approximate_kernel;
  using AFT = typename AK::FT;
  using EK = typename Runner::Exact_kernel;
  using EFT = typename EK::FT;

  // Why the interval run stopped the pair's search before its end. The
  // stages are told through the policy's hooks (takes_child, decides_here,
  // stops_after, convex_stage's empty verdict) and return as at the end of
  // a search; the runner then reads stop() (Filtered_runner::check_pair).
  enum class Stop {
    none,
    apart,             // the runner proved the pair apart (decides_here)
    inside,            // the runner made the pair's witness, checked, from a point the
                       // hand-over's LP found inside a term of its formula (found_inside)
    convex_uncertain   // a sign in a convex pair's linear programs the intervals could not
                       // certify outside the programs' own predicates (convex_certain asks
                       // those of the rational stage): the runner runs the pair in
                       // rationals (exact_fallbacks)
  };

  Interval_filter() = default;   // only as a stage's unused default
  // An any-witness search, whose trail and witness are wanted, unless
  // resolve_earliest makes it an earliest one, in the given semantics.
  Interval_filter(Runner& runner, Search_trail& trail, Check_stats& stats, Semantics semantics)
    : runner_(&runner), trail_(&trail), stats_(&stats), semantics_(semantics), hand_over_(semantics) {}

  // Earliest mode: lines decided against the exact t* (see above);
  // ceiling: the runner's, in rationals.
  void resolve_earliest(const EFT* ceiling)
  {
    earliest_ = true;
    ceiling_ = ceiling;
  }
  static constexpr bool keeps_doubtful_bounds() { return true; }
  // Whether the trail leads to the rational run's last improvement, made
  // on a certified path (an earliest-mode rational run can replay it).
  bool earliest_trail() const { return earliest_ && trail_->complete && !trail_->approximate && !pending_; }

  // Whether goal.can_improve(k, t) would meet a comparison the intervals
  // cannot certify: the same comparisons (the kernel's compare, the sign of
  // a - b), stopping where it stops, asked without a throw.
  template <class FT>
  static bool ties(const AK& k, const Search_goal<FT>& goal, const FT& t)
  {
    if (goal.ceiling) {
      CGAL::Uncertain<CGAL::Sign> s = k.uncertain_sign(*goal.ceiling - t);
      if (!CGAL::is_certain(s)) return true;
      if (CGAL::get_certain(s) == CGAL::NEGATIVE) return false;   // can_improve: no, at once
    }
    return goal.found && goal.earliest && !CGAL::is_certain(k.uncertain_sign(t - goal.t_star));
  }
  // goal.can_improve(k, t) in intervals; nothing at a tie the caller then
  // decides in rationals (when tie_in_rationals: it can), without the
  // throw; at a tie it cannot decide, the interval run's throw.
  template <class FT>
  static std::optional<bool> certified_improves(const AK& k, const Search_goal<FT>& goal, const FT& t,
                                                bool tie_in_rationals)
  {
    if (tie_in_rationals && ties(k, goal, t)) return std::nullopt;
    return goal.can_improve(k, t);
  }

  // Earliest mode: a sub-span starting exactly at t* (the motion changing
  // at the contact: approach and stop) ties with it, which intervals cannot
  // tell. The span's start (a scene number) is compared with the exact t*
  // (rational_goal_of), as the rational run compares them, instead of the
  // whole pair again in rationals.
  // Such a tie is the rule on those scenes (certified_improves: no throw).
  template <class FT>
  bool enters_span(const AK& k, const Search_goal<FT>& goal, const Time_span<FT>& span)
  {
    if (std::optional<bool> r = certified_improves(k, goal, span.lo, earliest_ && span.exact_lo)) return *r;
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    Search_goal<EFT> e = rational_goal_of(goal);
    ++stats_->exact_ties;
    return e.can_improve(runner_->ek(), runner_->ek().from_rational(*span.exact_lo));
  }
  // Earliest mode: a convex pair's vertex B at time t, against a t* or a
  // ceiling it ties with (two pairs touching at one instant, another
  // sub-span's vertex): B's time in rationals, compared as the rational
  // run compares it.
  template <class Stage, class FT>
  bool convex_improves(const AK& k, Stage& stage, const Search_goal<FT>& goal, const std::array<int, 4>* B,
                       const FT& t)
  {
    if (std::optional<bool> r = certified_improves(k, goal, t, earliest_ && B)) return *r;
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    Search_goal<EFT> e = rational_goal_of(goal);
    ++stats_->exact_ties;
    return e.can_improve(runner_->ek(), exact_convex(stage.a(), stage.b(), stage.span_index()).vertex(*B)[3]);
  }
  bool skips_span(std::size_t index)
  {
    const std::optional<Rational>& until = hand_over_.until();
    bool apart = until && runner_->span_ends_by(a_, b_, index, *until);
    stats_->apart_spans += apart;
    return apart;
  }
  template <class Decide>
  auto convex_stage(Decide decide) -> std::optional<decltype(decide())>
  {
    try {
      return decide();
    } catch (const CGAL::Uncertain_conversion_exception&) {
      stop_ = Stop::convex_uncertain;
      return std::nullopt;
    }
  }
  Stop stop() const { return stop_; }
  // Stop::inside: the pair's answer.
  Pair_result<EFT>& found_inside() { return *inside_; }
  // A sign of a convex pair's programs the intervals cannot certify (a
  // touch's multiplier sum, a fifth row through a vertex): the same
  // predicate of the rational run's stage on the sub-span, whose rows are
  // made only as asked.
  template <class Stage, class Predicate>
  auto convex_certain(Stage& stage, Predicate p)
  {
    try {
      auto r = p(stage);
      if (CGAL::is_certain(r)) return CGAL::get_certain(r);
    } catch (const CGAL::Uncertain_conversion_exception&) {
    }
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    ++stats_->convex_exact_signs;
    convex_guides_ = stage.guides();
    return CGAL::get_certain(p(exact_convex(stage.a(), stage.b(), stage.span_index())));
  }
  template <class Stage>
  void convex_found(const Stage& stage)
  {
    convex_found_ = stage.found();
    convex_pair_ = {stage.a(), stage.b()};
    convex_guides_ = stage.guides();
  }
  // A convex pair's answer where the intervals made its point inside (or
  // its guess point) but only enclose the vertex at t* or the closed
  // point's time: that vertex, and each object's deep point at its time,
  // made by the rational run's stage, the rest copied (points, the
  // rational run's numbers). Valid as the stage proved it (Convex_pair).
  std::optional<Pair_result<EFT>> convex_answer(const Pair_result<AFT>& found)
  {
    if (!convex_found_ || !found.collide) return std::nullopt;
    bool closed = found.semantics == Semantics::closed;
    Pair_result<EFT> r;
    r.a = found.a, r.b = found.b;
    r.semantics = found.semantics;
    r.collide = r.has_witness = r.witness_verified = true;
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    ++stats_->convex_exact_signs;
    Convex_pair<EK>& e = exact_convex(found.a, found.b, convex_found_->index);
    const Convex_found& f = *convex_found_;
    Vector4<EFT> g{EFT(f.point[0]), EFT(f.point[1]), EFT(f.point[2]), EFT(f.point[3])};
    if (!closed && !(found.has_witness && found.witness_verified && runner_->to_exact(found.witness, r.witness))) {
      // A point inside the intervals could not snap (an overlap as thin as
      // their enclosures): the witness made from it in rationals, on every
      // plane of the objects (their models' planes: all it and its check read).
      runner_->rational().need_planes(found.a);
      runner_->rational().need_planes(found.b);
      const Exact_convex& x = *exact_convex_;
      Vector3<EFT> world{EFT(0), EFT(0), EFT(0)};
      r.witness = Witness<EK>(runner_->ek())
                      .make(f.at_centre ? e.centre(f.centre_rows) : g, world, x.A, x.B, x.span.lo, x.span.hi)
                      .value();   // rationals tell every sign
      if (!is_valid_witness(runner_->ek(), runner_->rational().model(), r.a, r.b, r.witness, &runner_->certified()))
        return std::nullopt;
    }
    Vector4<EFT> p = f.at_vertex ? e.vertex(f.basis) : f.at_centre ? r.witness : g;
    if (closed) {
      r.witness = p;
      r.witness_cells = r.contact_cells = {e.cell(0, p[3]), e.cell(1, p[3])};
    } else {
      r.contact_cells = {r.witness, r.witness};
    }
    r.contact = p;
    r.t_star = p[3];
    r.earliest = found.earliest;
    return r;
  }
  // The region stage; where the intervals leave a decision open (S-bounds
  // meeting exactly: objects in contact), the stage in rationals, adopted:
  // the run goes on from the rational run's own region and pruning. Boxes
  // the intervals cannot decide are first kept (keeps_doubtful_bounds):
  // bounds all the same, so a stage that prunes the span with them proves
  // it holds no collision (and no touch, closed), as the rational run's
  // smaller bounds do. The rational run may search it instead, but finds
  // nothing there, and a later span's search does not depend on it.
  template <class M, class Stage, class Run>
  void region_stage(int a, int b, std::size_t index, M& A, M& B, Stage& st, Run run)
  {
    try {
      run();
      if (!st.doubtful) {
        if (st.region) roots_[index] = *st.region;
        return;
      }
      if (!st.alive) {
        ++stats_->doubtful_stages_pruned;
        return;
      }
    } catch (const CGAL::Uncertain_conversion_exception&) {
    }
    exact().region_stage(a, b, index, A, B, st);
    if (st.region) exact_roots_[index] = exact().stages().at(index).stage.region;
  }

  // The rational run's goal, made from the line that found it, with the
  // sub-span and frame it was found in; nothing otherwise. A witness the
  // intervals could not make (a touching point or a contact point they
  // only enclose: which planes pass through it is for exact arithmetic to
  // say) is made from it, instead of replaying the search to that line.
  // Earliest mode: on a certified path whose last improvement was a line
  // the intervals examined (exact_last). Any witness: on a certified path
  // (the trail complete, not approximate), the line that found the point,
  // in intervals or in rationals; the rational run's search stops at the
  // same line, its first with a point.
  struct Exact_goal {
    Search_goal<EFT> goal;
    std::size_t span;
    std::array<bool, 3> frame;
  };
  std::optional<Exact_goal> exact_goal()
  {
    if (earliest_) {
      const Stale* last = last_line();
      if (!last || !witness_certified()) return std::nullopt;
      std::optional<Search_goal<EFT>> e = exact_last(true);
      if (!e) return std::nullopt;
      return Exact_goal{std::move(*e), last->span, last->frame};
    }
    if (!found_line_ || !trail_->complete || trail_->approximate) return std::nullopt;
    Search_goal<EFT> start;
    start.semantics = semantics_;
    std::optional<Search_goal<EFT>> e = goal_on_line(*found_line_, std::move(start), true);
    // Nothing there: the point lay in the sliver between the interval
    // region (widened to doubles) and the rational run's, which then
    // searches on; the pair goes to it.
    if (!e || !e->found) return std::nullopt;
    return Exact_goal{std::move(*e), found_line_->span, found_line_->frame};
  }

  // The region stages made in rationals, handed on to the trail's replay.
  Exact_stages<EFT> take_stages() { return exact_ ? std::move(exact_->stages()) : Exact_stages<EFT>(); }

  void search_span(int a, int b, std::size_t index, const std::array<bool, 3>& frame_of_a)
  {
    a_ = a, b_ = b, span_ = index, frame_ = frame_of_a;
    hand_over_.new_span();
    lines_.reset();   // a new search: its conquers count from zero again
    keys_.reset();
  }
  void found_in_span(std::size_t index)
  {
    trail_->span = index;   // the earliest replay skips the sub-spans before it
  }
  bool stops_after(std::size_t) const { return stop_ != Stop::none; }
  // The point is the rational run's own when the path was certified (the
  // trail is not approximate) and the intervals found it themselves. A
  // closed witness (a touching point, any rational) is made too: the runner
  // keeps it only when every coordinate is a point interval, that is the
  // rational run's number (Filtered_runner::exact_copy).
  // Earliest mode: the goal then encloses the rational run's
  // t*, contact point and point inside (see above), unless its last
  // improvement was a line examined in rationals on keys (planes scaled to
  // lowest terms give other generic points), so the witness and contact
  // cells made from it are the rational run's where they come out as
  // points (the runner keeps them only then).
  bool witness_certified() const
  {
    bool earliest_here = earliest_ && !pending_ && !std::holds_alternative<On_keys>(last_);
    return (!earliest_ || earliest_here) && !trail_->approximate && !found_in_rationals_;
  }
  // Closed, the witness is the contact point itself, kept only as point
  // intervals (Filtered_runner::exact_copy): one whose time is not a point
  // is not made (the convex pair's rational answer, or the witness line,
  // gives it), as making it would come to nothing.
  template <class FT>
  bool witness_answers(const Search_goal<FT>& goal) const
  {
    return !goal.closed() || goal.contact[3].is_point();
  }
  template <class F>
  void attempt(F make)
  {
    try {
      make();
    } catch (const CGAL::Uncertain_conversion_exception&) {
      // No witness: the pair goes to a rational run.
    }
  }

  // The leaf was kept: the path may now differ from the rational run's.
  void uncertain_simplification() { trail_->approximate = true; }
  bool takes_child(std::size_t, int) const { return !hand_over_.span_apart() && stop_ == Stop::none; }
  // Earliest mode: a region whose lower time ties with t* (a sub-span end
  // off the grid, where the objects are already in contact) is compared
  // exactly, on the rational run's region (exact/Region_faces.h) and t*.
  template <class FT>
  bool can_enter(const AK& k, const Search_goal<FT>& goal, const Box<FT, 4>& region)
  {
    if (std::optional<bool> r = certified_improves(k, goal, region.lo[3], earliest_ && lag_ != Lag::fold)) return *r;
    std::optional<Box<EFT, 4>> exact = exact_region(span_, region);
    if (!exact) throw CGAL::Uncertain_conversion_exception("a region's time the intervals only enclose");
    return rational_goal_of(goal).can_improve(runner_->ek(), exact->lo[3]);
  }
  // Earliest mode: a point of a line (an edge's end, a segment's earliest
  // end) whose time the intervals cannot tell from t*: a tie, the vertex at
  // t* ending edges of other conquers too. Its time is that of the vertex
  // where the line's three planes and the one cutting it there meet: one
  // 4x4 solve on the rational planes of the conquer (on the rational run's
  // region, exact/Region_faces.h), compared with the exact t* as the
  // rational run compares it, instead of the whole line in rationals.
  // (Such ties are common, the contact vertex ending many edges:
  // certified_improves, without the throw.)
  template <class G, class FT, class Fourth>
  bool improves(const AK& k, const G& g, const Search_goal<FT>& goal, const FT& t,
                const std::array<std::size_t, 3>& line, Fourth fourth)
  {
    if (std::optional<bool> r = certified_improves(k, goal, t, earliest_ && goal.earliest && lag_ != Lag::fold))
      return *r;
    std::size_t p = fourth();
    if (p == npos) throw CGAL::Uncertain_conversion_exception("a tie at an unknown vertex");
    Search_goal<EFT> exact_goal = rational_goal_of(goal);
    typename Exact_span<Runner>::Lines& lines = conquer_lines(g);
    if (!lines.exact()) throw CGAL::Uncertain_conversion_exception("a tie on a widened region");
    const auto& e = lines.conquer();
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    std::array<EFT, 2> time = meeting_time(e.plane(line[0]), e.plane(line[1]), e.plane(line[2]), e.plane(p));
    CGAL::Sign den = runner_->ek().sign(time[1]);
    if (den == CGAL::ZERO) throw CGAL::Uncertain_conversion_exception("a tie where the planes meet in no point");
    ++stats_->exact_ties;
    return exact_goal.can_improve(runner_->ek(), runner_->ek().quotient(time[0], time[1], den));
  }
  // Two cuts of a line the intervals cannot order (several planes through
  // one point the intervals only enclose: the contact vertex, a decimal
  // face) are ordered on the rational planes of the conquer, when both
  // planes are known: the rational run's order, instead of the whole line
  // in rationals. A face's cut needs the rational run's region.
  template <class G, class FT>
  CGAL::Sign compare_cuts(const AK& k, const G& g, const FT& a, std::size_t pa, const FT& b, std::size_t pb,
                          const std::array<std::size_t, 3>& line)
  {
    try {
      return k.compare(a, b);
    } catch (const CGAL::Uncertain_conversion_exception&) {
      if (pa == npos || pb == npos) throw;
    }
    const auto* e = exact_planes(g, line, pa, pb);
    if (!e) throw CGAL::Uncertain_conversion_exception("cuts of a widened region's faces");
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    ++stats_->exact_cut_orders;
    return e->cut_order(line, pa, pb);
  }
  // A zero the intervals leave open (a plane parallel to a line, or
  // containing it, under decimal coefficients the keys do not hold
  // exactly: the contact face of a thin overlap) is asked of the rational
  // planes of the conquer: the rational run's zero. Not zero there, the
  // interval sign is asked later and the line goes to rationals as before.
  template <class G>
  bool zero_on_line(const AK&, const G& g, const std::array<std::size_t, 3>& line, std::size_t p, bool along)
  {
    const auto* e = exact_planes(g, line, p, p);
    if (!e) return false;
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    ++stats_->exact_zeros;
    return e->zero_on_line(line, p, along);
  }
  // A long search is handed over: when exact/Apart_hand_over.h says so
  // (search_work), the runner asks whether conflicts close off every term
  // of the pair's formula (Filtered_runner::proves_apart; one exact LP per
  // conflict, where generate-and-test examines many lines per conflict).
  // Proven, the run stops (Stop::apart), the pair's "no collision" (a
  // pair apart on the whole span has no t* either: earliest mode too, until
  // a point inside is found). A term left open in a regularised search for
  // any point inside may give the witness (Stop::inside: the pair collides,
  // wherever the search was). Otherwise it goes on where it was, and asks
  // again later (out of steps) or never (a term left open; once a point
  // inside is found: test_line).
  void never_hand_over() { hand_over_.never(); }
  // A proof that stops at a later sub-span (a term with a point there, or
  // its step bound) still proves the sub-spans before it apart: the
  // search of this one stops (takes_child, decides_here: nothing is
  // there, as the rational run would find), and later ones it covers are
  // skipped (skips_span).
  bool decides_here(std::size_t, bool conquers)
  {
    if (hand_over_.span_apart() || stop_ != Stop::none) return false;
    if (!conquers || !hand_over_.due(search_work())) return true;
    Rational until;
    Pair_result<EFT> inside;
    switch (runner_->proves_apart(a_, b_, semantics_, hand_over_.steps(), until,
                                  earliest_ || closed() ? nullptr : &inside)) {
    case Runner::Apart::proven: stop_ = Stop::apart; return false;
    case Runner::Apart::inside: stop_ = Stop::inside, inside_ = std::move(inside); return false;
    case Runner::Apart::out_of_steps: hand_over_.out_of_steps(); break;
    case Runner::Apart::not_proven: hand_over_.never(); break;
    }
    bool covered = runner_->span_ends_by(a_, b_, span_, until);
    hand_over_.proved_until(std::move(until), covered);
    stats_->apart_spans += covered;
    return !covered;
  }
  template <class FT>
  void found_at(const std::vector<int>& path, bool on_line, const Box<FT, 4>& region, const Pair_formula& f)
  {
    if (earliest_) {
      // A fold reached in earliest mode improves the goal (its lower time
      // passed the same comparison on entry); a conquer may not have.
      if (on_line && !pending_) return;
      if (!on_line) {
        last_ = std::monostate();   // a fold: its region's centre and lower face
      }
      keep_region(region, f);
      trail_->path = path;
      trail_->on_line = on_line;
      trail_->line = pending_line_;
      trail_->complete = true;
      pending_ = false;
      if (!on_line) lag_ = Lag::fold;   // (a line's own was synced when it improved: earliest_line)
      return;
    }
    trail_->complete = true;   // any witness: the found line is run again alone (exact_goal)
  }

  template <class FT>
  bool jumps_to(Box<FT, 4>&, Pair_formula&, bool&, std::vector<int>&) const { return false; }
  const std::array<std::size_t, 3>* replay_line() const { return nullptr; }
  void replayed(bool) {}

  // Earliest mode (t* is any rational) is not decided line by line: an
  // uncertain sign there stops the run.
  template <class G>
  void test_line(G& g, const Pair_formula& f, std::size_t i, std::size_t j, std::size_t m, Search_goal<AFT>& goal)
  {
    // A point inside found (by a fold before, or this line; earliest mode
    // goes on): the pair is not apart, and no hand-over is asked again.
    bool before = goal.found;
    if (before) never_hand_over();
    if (goal.earliest) {
      if (earliest_) earliest_line(g, f, i, j, m, goal);
      else g.test_line(f, i, j, m, goal);
      if (goal.found) never_hand_over();
      return;
    }
    try {
      g.test_line(f, i, j, m, goal);
    } catch (const CGAL::Uncertain_conversion_exception&) {
      decide_in_rationals(g, f, i, j, m, goal);
    }
    if (!earliest_ && !before && goal.found) {
      found_line_ = Stale{span_, frame_, g.layout(), g.region(), f, {i, j, m}};
    }
  }

  int same_plane(const AK& k, const Hyperplane4<AFT>& h, const Hyperplane4<AFT>& g, long eh, int fh, long eg, int fg,
                 const Box<AFT, 4>& region)
  {
    // Planes that are one are common (rotated copies), and undecidable in
    // intervals: asked without a throw.
    CGAL::Uncertain<int> same = proportional_or_unsure(k, h, g);
    if (CGAL::is_certain(same)) return CGAL::get_certain(same);
    return exact().proportional(a_, b_, span_, frame_, eh, fh, eg, fg, region);
  }

  // The normal keys of the sub-span's table, once it had an uncertain line.
  template <class FT>
  const std::vector<Vector4<FT>>* normal_keys() const
  {
    static_assert(std::is_same_v<FT, AFT>, "normal keys are the interval run's");
    return keys_ ? &keys_->normals : nullptr;
  }
  template <class FT>
  const std::vector<Hyperplane4<FT>>* plane_keys() const
  {
    static_assert(std::is_same_v<FT, AFT>, "plane keys are the interval run's");
    return keys_ ? &keys_->planes : nullptr;
  }
  // A box simplification the intervals leave open: the keys now (a plane
  // through a corner of a grid region is a zero on them).
  template <class FT>
  const std::vector<Hyperplane4<FT>>* plane_keys_on_doubt()
  {
    static_assert(std::is_same_v<FT, AFT>, "plane keys are the interval run's");
    make_keys();
    return &keys_->planes;
  }

  // A keyed line's neighbourhoods on the keys (Null_object_test::classify
  // and, closed, test_touch): whether some cell is inside, or nothing when
  // even the keys leave a sign open.
  template <class V, class Inside>
  std::optional<bool> verdict_first(const V& l, const std::vector<V>& keys, Inside& inside, std::size_t& tested)
  {
    return interval_verdict(runner_->ak(), tested,
                            [&](auto& hood) { return hood.find_inside(l, keys, inside).has_value(); });
  }
  template <class V, class Inside>
  std::optional<bool> verdict_around(const std::vector<V>& keys, Inside inside, std::size_t& tested)
  {
    return interval_verdict(runner_->ak(), tested,
                            [&](auto& hood) { return hood.find_inside_around(keys, inside).has_value(); });
  }

private:
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);   // no plane (Null_object_test's)
  Runner* runner_ = nullptr;
  // A convex pair's stage in rationals, for the signs the intervals leave
  // open: EK's motions of the two objects, and their planes made as the
  // stage reads them (model/Primitive_planes.h). The stage, the planes and
  // the sub-spans are the pair's, made once; start_span sets the stage on
  // the sub-span asked (before, a stage per sub-span: a closed touch asks
  // a few signs on each of ten).
  struct Exact_convex {
    int a, b;
    std::optional<std::size_t> index;   // the sub-span the stage is set on (none: not yet)
    typename Scene_model<EK>::Spans spans;
    Time_span<EFT> span;
    Moving_object<EFT> A, B;
    Convex_pair<EK> stage;
    Exact_convex(Runner& runner, int a_, int b_, Primitive_planes<EK>& pa, Primitive_planes<EK>& pb,
                 const Convex_guides& guides)
      : a(a_), b(b_), spans(runner.rational().model().sub_spans({a_, b_})),
        stage(runner.ek(), runner.rational().model(), a_, b_, nullptr, guides)
    {
      stage.use_planes(pa, pb);
    }
    void start_span(Runner& runner, std::size_t i)
    {
      index = i;
      span = spans.at(i);
      A = moving_on(runner.rational().model(), a, span, {});
      B = moving_on(runner.rational().model(), b, span, {});
      stage.start_span(i, A, B, span);
    }
  };
  std::unique_ptr<Exact_convex> exact_convex_;
  std::unique_ptr<Primitive_planes<EK>> exact_planes_[2];   // the pair's objects' (a filter is one pair's)
  Convex_guides convex_guides_;                              // the interval stage's, shared
  std::optional<Convex_found> convex_found_;
  std::array<int, 2> convex_pair_{};                         // whose stage recorded convex_found_

  Convex_pair<EK>& exact_convex(int a, int b, std::size_t index)
  {
    if (!exact_convex_ || exact_convex_->a != a || exact_convex_->b != b) {
      runner_->rational().need_motion(a);
      runner_->rational().need_motion(b);
      int ids[2] = {a, b};
      for (int o = 0; o < 2; ++o)
        if (!exact_planes_[o])
          exact_planes_[o] = std::make_unique<Primitive_planes<EK>>(
              runner_->ek(), runner_->scene().objects[static_cast<std::size_t>(ids[o])].shape);
      exact_convex_ = std::make_unique<Exact_convex>(*runner_, a, b, *exact_planes_[0], *exact_planes_[1], convex_guides_);
    }
    if (exact_convex_->index != index) exact_convex_->start_span(*runner_, index);
    return exact_convex_->stage;
  }

  // The rational side of the pair's sub-spans, made when first asked (a
  // convex pair decided in intervals asks nothing of it).
  std::unique_ptr<Exact_span<Runner>> exact_;
  Exact_span<Runner>& exact()
  {
    if (!exact_) exact_ = std::make_unique<Exact_span<Runner>>(*runner_, closed());
    return *exact_;
  }
  Search_trail* trail_ = nullptr;
  Check_stats* stats_ = nullptr;
  Semantics semantics_ = Semantics::regularised;
  bool closed() const { return semantics_ == Semantics::closed; }
  int a_ = -1, b_ = -1;
  std::size_t span_ = 0;
  // The search's work in lines: each line examined, and each cell tested
  // around a point whose neighbourhood was classified (Appendix A: its
  // rays and sectors at a vertex where many planes meet, as at touches of
  // differences and under rotation), which costs about as much as a line
  // there (0.3-0.7 us against 0.5 us: the contact fixtures' exactly
  // filled cavities and pegs, fuzz's rotated touches, the weaving late stop).
  std::size_t search_work() const { return stats_->lines + stats_->cells_tested; }
  Apart_hand_over hand_over_;
  Stop stop_ = Stop::none;
  std::optional<Pair_result<EFT>> inside_;   // Stop::inside's answer
  std::array<bool, 3> frame_{};
  std::shared_ptr<typename Exact_span<Runner>::Lines> lines_;   // this conquer's, once one is needed
  std::size_t lines_conquer_ = 0;                               // which conquer they are for
  bool found_in_rationals_ = false;                             // the point is for a rational run to make
  bool earliest_ = false;                                       // resolve_earliest
  const EFT* ceiling_ = nullptr;
  std::optional<EFT> t_star_;                                   // the goal's t*, exact, once found
  bool pending_ = false;                                        // a line improved; its conquer's path follows
  std::array<std::size_t, 3> pending_line_{};
  // The line that last improved the goal in intervals.
  struct Stale {
    std::size_t span;
    std::array<bool, 3> frame;
    Plane_layout layout;
    Box<AFT, 4> region;
    Pair_formula formula;
    std::array<std::size_t, 3> line;
  };
  // Earliest mode, the line that last improved the goal: none (nothing
  // found yet, or a fold since), one the intervals examined, or one
  // examined in rationals on keys (planes in lowest terms give other
  // generic points than the rational run's: witness_certified).
  struct On_keys {};
  std::variant<std::monostate, Stale, On_keys> last_;
  const Stale* last_line() const { return std::get_if<Stale>(&last_); }
  std::optional<Stale> found_line_;   // any witness: the line that found the point
  // How t_star_ stands to the interval goal's t*: the same number; behind
  // the line last_, which improved it in intervals (made when a comparison
  // needs it: make_exact); or behind a fold, whose t* is its region's lower
  // time, a grid point (taken at the next line: earliest_line).
  enum class Lag { none, line, fold };
  Lag lag_ = Lag::none;
  // Whether t* is at the conquer's lower time (no line of it improves),
  // for which conquer and which t* (set_t_star counts them).
  struct Floor {
    std::size_t conquer, t_star;
    bool reached;
  };
  std::optional<Floor> floor_;
  std::size_t t_stars_ = 0;

  void set_t_star(EFT t)
  {
    t_star_ = std::move(t);
    ++t_stars_;
  }

  static bool same(const AFT& x, const AFT& y) { return x.inf() == y.inf() && x.sup() == y.sup(); }
  // Whether the enclosure holds a multiple of 2^-40 (region times are).
  static bool near_grid(const AFT& x)
  {
    double s = std::ldexp(1.0, 40), lo = x.inf() * s, hi = x.sup() * s;
    return std::isfinite(lo) && std::isfinite(hi) && std::floor(hi) >= std::ceil(lo);
  }

  // The rational run's goal where the interval run's is `goal`: its t*
  // exact (a convex pair's: its programs' vertex, always one in earliest
  // mode, made in rationals; a search's: t_star_, as can_enter has it).
  template <class FT>
  Search_goal<EFT> rational_goal_of(const Search_goal<FT>& goal)
  {
    if (goal.found && goal.convex) {
      if (!convex_found_ || !convex_found_->at_vertex) throw CGAL::Uncertain_conversion_exception("t* off a vertex");
      Search_goal<EFT> e = rational_goal(false);
      e.found = true;
      e.t_star = exact_convex(convex_pair_[0], convex_pair_[1], convex_found_->index).vertex(convex_found_->basis)[3];
      return e;
    }
    if (lag_ == Lag::fold) throw CGAL::Uncertain_conversion_exception("t* of a fold not yet exact");
    if (lag_ == Lag::line) make_exact();
    if (goal.found && !t_star_) throw CGAL::Uncertain_conversion_exception("t* not yet exact");
    return rational_goal(goal.found);
  }
  // The earliest-mode goal in rationals: the pair's semantics and ceiling,
  // and, when found, the exact t* (t_star_, in step).
  Search_goal<EFT> rational_goal(bool found) const
  {
    Search_goal<EFT> e;
    e.earliest = true;
    e.semantics = semantics_;
    e.found = found;
    if (found) e.t_star = *t_star_;
    if (ceiling_) e.ceiling = *ceiling_;
    return e;
  }

  // t_star_ for the goal the stale line left (still stale when it cannot
  // be made: a caller catching the exception must not go on with the old).
  void make_exact()
  {
    if (!exact_last(false)) throw CGAL::Uncertain_conversion_exception("earliest mode on a widened region");
    lag_ = Lag::none;
  }

  // The goal the last line left, and t_star_: that line in rationals, from
  // nothing found (its least time is below the t* before it, which the
  // intervals certified), records the rational run's own t* and contact
  // point. as_is: on the table's own planes, not in lowest terms, so that
  // the point inside is the rational run's too. The conquer's own region
  // must be exact; nothing otherwise.
  std::optional<Search_goal<EFT>> exact_last(bool as_is)
  {
    std::optional<Search_goal<EFT>> e = goal_on_line(*last_line(), rational_goal(false), as_is);
    if (!e) return e;
    if (!e->found) throw std::logic_error("internal error: a line the intervals certified found nothing in rationals");
    set_t_star(e->t_star);
    return e;
  }
  // Line s examined in rationals from the goal `from`, as the rational run
  // examines it, when the conquer's region is exact (that run's own).
  std::optional<Search_goal<EFT>> goal_on_line(const Stale& s, Search_goal<EFT> from, bool as_is)
  {
    std::shared_ptr<typename Exact_span<Runner>::Lines> lines =
        lines_on(s.span, s.frame, s.layout, s.region, as_is);
    lines_.reset();   // the span's table may have been another's
    if (!lines->exact()) return std::nullopt;
    ++stats_->exact_lines;
    lines->test_line(s.formula, s.line[0], s.line[1], s.line[2], from);
    return from;
  }

  // Earliest mode: the line in intervals; in rationals when it improves the
  // goal or cannot be certified.
  template <class G>
  void earliest_line(G& g, const Pair_formula& f, std::size_t i, std::size_t j, std::size_t m, Search_goal<AFT>& goal)
  {
    if (lag_ == Lag::fold) {
      // A fold's t* is its region's lower time, a grid point.
      std::optional<Rational> t = runner_->ak().exact_value(goal.t_star);
      if (!t) throw CGAL::Uncertain_conversion_exception("a fold's time the intervals only enclose");
      set_t_star(runner_->ek().from_rational(*t));
      lag_ = Lag::none;
    }
    // Every point of the closed region is at or after its lower time: once
    // t* is there, no line of the conquer improves it (decided exactly,
    // once per conquer and t*).
    if (t_star_ && goal.found && lag_ == Lag::none) {
      if (!floor_ || floor_->conquer != g.conquers() || floor_->t_star != t_stars_) {
        std::optional<Rational> lo = runner_->ak().exact_value(g.region().lo[3]);
        floor_ = Floor{g.conquers(), t_stars_, lo && !runner_->ek().less(runner_->ek().from_rational(*lo), *t_star_)};
      }
      if (floor_->reached) return;
    }
    Search_goal<AFT> saved = goal;
    try {
      g.test_line(f, i, j, m, goal);
      if (goal.found == saved.found && (!goal.found || same(goal.t_star, saved.t_star))) return;
      // Improved, every decision certified: the exact t* is made when needed.
      last_ = Stale{span_, frame_, g.layout(), g.region(), f, {i, j, m}};
      lag_ = Lag::line;
      pending_ = true;
      pending_line_ = {i, j, m};
      if (std::optional<Rational> t = runner_->ak().exact_value(goal.t_star)) {
        set_t_star(runner_->ek().from_rational(*t));   // a point: the exact t* itself
        lag_ = Lag::none;
      } else if (near_grid(goal.t_star)) {
        // Likely a region's face (S-bounds fitted to the contact time):
        // the later comparisons with region times need the exact t*.
        make_exact();
        goal.t_star = runner_->ak().from_rational(runner_->ek().to_rational(*t_star_));
      }
      return;
    } catch (const CGAL::Uncertain_conversion_exception&) {
    }
    goal = saved;
    make_keys();
    if (lag_ == Lag::line) make_exact();
    if (!conquer_lines(g).exact()) throw CGAL::Uncertain_conversion_exception("earliest mode on a widened region");
    ++stats_->exact_lines;
    // Nothing found yet (no tie with t* possible): most such lines hold no
    // point inside at all, which the verdict alone (its neighbourhoods
    // classified in intervals first) says more cheaply.
    if (!goal.found && !lines_->has_inside(f, i, j, m, goal.semantics)) return;
    Search_goal<EFT> e = rational_goal(goal.found);
    lines_->test_line(f, i, j, m, e);
    if (!e.improved) return;
    set_t_star(e.t_star);
    last_ = On_keys();
    auto enclose = [&](const EFT& x) { return runner_->ak().from_rational(runner_->ek().to_rational(x)); };
    goal.found = goal.improved = true;
    goal.vertex.reset();   // the rational conquer's record, not this one's
    goal.t_star = enclose(e.t_star);
    for (int q = 0; q < 4; ++q) {
      goal.contact[q] = enclose(e.contact[q]);
      goal.inside[q] = enclose(e.inside[q]);
      goal.toward_a[q] = enclose(e.toward_a[q]);
      goal.toward_b[q] = enclose(e.toward_b[q]);
    }
    pending_ = true;
    pending_line_ = {i, j, m};
  }
  // The deciding region, for the replay to go to directly, when its faces
  // are points (the rational run's region).
  void keep_region(const Box<AFT, 4>& region, const Pair_formula& f)
  {
    trail_->region.reset();
    Search_trail::Known_region known;
    for (int q = 0; q < 4; ++q) {
      std::optional<Rational> lo = runner_->ak().exact_value(region.lo[q]);
      std::optional<Rational> hi = runner_->ak().exact_value(region.hi[q]);
      if (!lo || !hi) return;
      known.faces[2 * q] = std::move(*lo);
      known.faces[2 * q + 1] = std::move(*hi);
    }
    known.formula = f;
    trail_->region = std::move(known);
  }
  // The current conquer in rationals, when the line's planes and p and q
  // there are the rational run's: table planes always, region faces only
  // on the rational run's region; nothing otherwise.
  template <class G>
  const Null_object_test<EK, Exact_line_filter>* exact_planes(const G& g, const std::array<std::size_t, 3>& line,
                                                               std::size_t p, std::size_t q)
  {
    typename Exact_span<Runner>::Lines& lines = conquer_lines(g);
    std::size_t faces = g.layout().first_face;
    bool face = p >= faces || q >= faces || line[0] >= faces || line[1] >= faces || line[2] >= faces;
    return face && !lines.exact() ? nullptr : &lines.conquer();
  }
  // The current conquer's lines in rationals (lines_), made once per conquer.
  template <class G>
  typename Exact_span<Runner>::Lines& conquer_lines(const G& g)
  {
    if (!lines_ || lines_conquer_ != g.conquers()) {
      lines_ = lines_on(span_, frame_, g.layout(), g.region());
      lines_conquer_ = g.conquers();
    }
    return *lines_;
  }
  // A conquer's lines in rationals (Exact_span::lines), on the rational
  // run's own region when the intervals only enclose a face of it but it
  // follows from the sub-span's root (exact/Region_faces.h).
  std::shared_ptr<typename Exact_span<Runner>::Lines> lines_on(std::size_t s, const std::array<bool, 3>& frame,
                                                               const Plane_layout& layout, const Box<AFT, 4>& region,
                                                               bool as_is = false)
  {
    bool points = true;
    for (int q = 0; q < 4; ++q) points = points && region.lo[q].is_point() && region.hi[q].is_point();
    std::optional<Box<EFT, 4>> root = points ? std::nullopt : exact_region(s, region);
    return exact().lines(a_, b_, s, frame, layout, region, as_is, root ? &*root : nullptr);
  }

  // The rational run's region of sub-span s that the interval region
  // encloses, when it follows from the sub-span's root.
  std::optional<Box<EFT, 4>> exact_region(std::size_t s, const Box<AFT, 4>& region)
  {
    std::optional<Box<EFT, 4>> root = exact_root(s);
    if (!root) return std::nullopt;
    return Region_faces<AK, EK>(runner_->ak(), runner_->ek()).descendant(region, *root);
  }

  // Sub-span s's root region in rationals: the stage's own when it was made
  // in rationals; from the interval stage's faces (Region_faces::root) when
  // it was made with S-bounds in regularised semantics (Span_region::
  // on_grid); made once, when first needed.
  std::optional<Box<EFT, 4>> exact_root(std::size_t s)
  {
    auto known = exact_roots_.find(s);
    if (known != exact_roots_.end()) return known->second;
    std::optional<Box<EFT, 4>>& root = exact_roots_[s];
    auto it = roots_.find(s);
    if (it == roots_.end() || closed() || !runner_->use_sbounds()) return root;
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    runner_->rational().need_motion(a_);   // the sub-spans' times; the faces read no model
    runner_->rational().need_motion(b_);
    const Time_span<EFT> span = runner_->rational().model().sub_spans({a_, b_}).at(s);
    root = Region_faces<AK, EK>(runner_->ak(), runner_->ek()).root(it->second, span.lo, span.hi);
    return root;
  }
  std::map<std::size_t, Box<AFT, 4>> roots_;                         // the interval stages' regions
  std::map<std::size_t, std::optional<Box<EFT, 4>>> exact_roots_;    // exact_root's, per sub-span

  void make_keys()
  {
    if (keys_) return;
    Keys k;
    exact().keys(a_, b_, span_, frame_, k.normals, k.planes);
    keys_ = std::move(k);
  }

  // The sub-span's normal and plane keys (Exact_span::keys), made at its
  // first line the intervals could not decide.
  struct Keys {
    std::vector<Vector4<AFT>> normals;
    std::vector<Hyperplane4<AFT>> planes;
  };
  std::optional<Keys> keys_;

  // One line the intervals could not decide; the same rational conquer
  // serves the rest of this conquer's lines.
  template <class G>
  void decide_in_rationals(G& g, const Pair_formula& f, std::size_t i, std::size_t j, std::size_t m, Search_goal<AFT>& goal)
  {
    conquer_lines(g);
    make_keys();
    ++stats_->exact_lines;
    if (lines_->has_inside(f, i, j, m, goal.semantics)) {
      goal.found = goal.improved = true;
      found_in_rationals_ = true;
    }
  }
};

} // namespace clash4d

#endif

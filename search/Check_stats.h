// What each stage of the cascade did (`clash4d check --stats`).
#ifndef CLASH4D_SEARCH_CHECK_STATS_H
#define CLASH4D_SEARCH_CHECK_STATS_H

#include "numbers/Stat_number.h"
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace clash4d {

// One constant-velocity sub-span of one pair, as the S-bound stage left it.
struct Span_stats {
  std::string pair;                       // "a/b", the objects' names
  Stat_range span;
  std::optional<Stat_range> narrowed;     // none: pruned
  std::size_t primitives = 0, primitives_alive = 0, leaves = 0;
  std::vector<Stat_range> region;         // the box handed to division, per axis (none: not reached)
  std::vector<Stat_number> frame;         // per axis, the velocity it is measured against
};

struct Check_stats {
  // Many objects (§6): pairs in the scene, and those the sweep kept
  std::size_t object_pairs = 0, candidate_pairs = 0;
  // Filtered exact kernel: candidate pairs the intervals' sweep could not
  // tell from touching, decided on rational boxes (exact/Filtered_runner.h).
  std::size_t exact_sweep_ties = 0;
  double seconds_sweep = 0;
  // S-bounds (§4.3)
  std::size_t pairs = 0, sub_spans = 0, sub_spans_pruned = 0;
  std::size_t sbound_passes = 0;
  std::size_t primitives = 0, primitives_pruned = 0;
  std::optional<Stat_range> span_before;   // first examined sub-span
  std::optional<Stat_range> span_after;    // ... after the S-bounds (none: pruned)
  std::vector<Span_stats> spans;
  // Divide-and-conquer (§4.1)
  std::vector<std::size_t> regions_per_depth;
  std::size_t conquers = 0, leaves_at_conquer = 0, max_leaves_at_conquer = 0;
  std::vector<Stat_range> conquered_box;   // hull of the regions conquered (last span), per axis
  // Generate-and-test (§4.2, Appendix A)
  std::size_t lines = 0, points_classified = 0, cells_tested = 0;
  // Convex pairs (search/Convex_pair.h, beyond the paper): sub-spans the
  // linear programs decided, and those they left to the cascade; filtered
  // kernel, convex_exact_signs: signs of the programs the intervals could
  // not certify (a touch, a fifth row through a vertex), and vertices at t*
  // they only enclosed, each asked of the rational run's stage alone.
  std::size_t convex_spans = 0, convex_undecided = 0, convex_exact_signs = 0;
  // Filtered exact kernel (set once per run; 0 for other kernels):
  // exact_fallbacks: interval runs (object bounds, pairs) stopped by a sign
  // the intervals could not certify, each then redone in rationals;
  // exact_witness_runs: colliding pairs rerun in rationals to construct
  // their witness, t* and contact point exactly; exact_regions and
  // exact_lines: lines of generate-and-test with a sign the intervals could
  // not certify, each then decided in rationals alone (the run goes on), and
  // the regions they were in;
  // exact_plane_tests: pairs of planes the intervals could not tell apart
  // or identify (parallel faces), decided on the rational planes instead;
  // exact_region_stages: sub-spans whose S-bounds and region the intervals
  // could not certify (bounds that meet exactly: a contact), made in
  // rationals and adopted by the interval run, which goes on;
  // doubtful_stages_pruned: sub-spans the interval run pruned with S-bounds
  // that kept boxes it could not decide (bounds that meet exactly), bounds
  // all the same, instead of making the stage in rationals;
  // witnesses_by_intervals: colliding pairs whose witness (earliest mode:
  // and t* and the contact point) the interval run made itself, as points,
  // on a path certified to be the rational run's (no rerun);
  // earliest_by_intervals: earliest-mode colliding pairs whose search the
  // interval run made (ties with t* decided in rationals), the rational run
  // only replaying its last improvement (of exact_witness_runs);
  // earliest_lines_rerun: of those, pairs where only that
  // improvement's line was run again in rationals, and the witness made
  // from it, instead of a replay;
  // witness_lines_rerun: any-witness colliding pairs (of
  // exact_witness_runs) whose search the interval run made, with only the
  // line that found the point run again in rationals and the witness made
  // from it, instead of searching again;
  // exact_ties: points of lines whose time the intervals could not tell
  // from t* (earliest mode), compared exactly by the time of the one
  // vertex there instead of the line in rationals; and sub-spans starting
  // at a convex pair's t*, compared with its vertex in rationals;
  // exact_cut_orders: two cuts of a line the intervals could not order,
  // ordered on the rational planes instead of the line in rationals;
  // exact_zeros: planes the intervals could not call parallel to a line
  // (or containing it), asked of the rational planes;
  // apart_proofs: pairs whose long search was handed over to conflicts
  // that close off every term (search/Apart_pieces.h) and proven apart;
  // apart_attempts: such hand-overs that did not prove it (a term has a
  // point, or the step bound), the search going on;
  // witnesses_by_terms: of those attempts, regularised searches for any
  // point inside that it ended with the pair's witness, made from the
  // double simplex's point inside the term left open and checked in
  // rationals (Filtered_runner::witness_at);
  // apart_spans: sub-spans such an attempt still proved apart (those
  // before the term with a point), whose search it stopped or skipped;
  // replay_stages_adopted: sub-span region stages an earliest replay took
  // from the interval run (made there in rationals) instead of making them
  // again;
  // closed_cells_by_intervals: closed touches whose generic points inside
  // each object (search/Witness.h, near_in_space) the interval run made,
  // with the signs it could not tell (planes through the contact, steps
  // parallel to a plane) asked of the rational planes one by one, instead
  // of making them in rationals over every plane.
  std::size_t exact_fallbacks = 0, exact_witness_runs = 0, exact_regions = 0,
              exact_lines = 0, exact_plane_tests = 0, exact_region_stages = 0, witnesses_by_intervals = 0,
              earliest_by_intervals = 0, apart_proofs = 0, apart_attempts = 0, apart_spans = 0,
              replay_stages_adopted = 0, earliest_lines_rerun = 0, witness_lines_rerun = 0, exact_ties = 0,
              exact_cut_orders = 0, exact_zeros = 0, doubtful_stages_pruned = 0,
              closed_cells_by_intervals = 0, witnesses_by_terms = 0;
  // Time per stage, seconds; measured only when timed (search/Stage_clock.h:
  // Check_options::stage_seconds, which --stats sets), otherwise 0.
  double seconds_model = 0, seconds_sbounds = 0, seconds_divide = 0, seconds_witness = 0;
  bool timed = false;

  // Empty counts for a part of this run (a pair, another kernel's try),
  // timed as this run is.
  Check_stats fresh() const
  {
    Check_stats s;
    s.timed = timed;
    return s;
  }

  // The same counts with no time: a part made before and reused (a
  // prepared scene's model, exact/Filtered_runner.h).
  void clear_seconds() { seconds_sweep = seconds_model = seconds_sbounds = seconds_divide = seconds_witness = 0; }

  // Adds another run's counts (pairs checked in parallel, merged in order).
  void add(const Check_stats& o)
  {
    pairs += o.pairs; sub_spans += o.sub_spans; sub_spans_pruned += o.sub_spans_pruned;
    sbound_passes += o.sbound_passes; primitives += o.primitives; primitives_pruned += o.primitives_pruned;
    if (!span_before) { span_before = o.span_before; span_after = o.span_after; }
    spans.insert(spans.end(), o.spans.begin(), o.spans.end());
    if (regions_per_depth.size() < o.regions_per_depth.size()) regions_per_depth.resize(o.regions_per_depth.size(), 0);
    for (std::size_t d = 0; d < o.regions_per_depth.size(); ++d) regions_per_depth[d] += o.regions_per_depth[d];
    conquers += o.conquers; leaves_at_conquer += o.leaves_at_conquer;
    if (o.max_leaves_at_conquer > max_leaves_at_conquer) max_leaves_at_conquer = o.max_leaves_at_conquer;
    if (!o.conquered_box.empty()) conquered_box = o.conquered_box;
    lines += o.lines; points_classified += o.points_classified; cells_tested += o.cells_tested;
    convex_spans += o.convex_spans; convex_undecided += o.convex_undecided;
    convex_exact_signs += o.convex_exact_signs;
    exact_lines += o.exact_lines;
    exact_ties += o.exact_ties;
    exact_cut_orders += o.exact_cut_orders;
    exact_zeros += o.exact_zeros;
    doubtful_stages_pruned += o.doubtful_stages_pruned;
    apart_spans += o.apart_spans;
    seconds_sbounds += o.seconds_sbounds; seconds_divide += o.seconds_divide; seconds_witness += o.seconds_witness;
  }

  void visit(std::size_t depth)
  {
    if (regions_per_depth.size() <= depth) regions_per_depth.resize(depth + 1, 0);
    ++regions_per_depth[depth];
  }
};

} // namespace clash4d

#endif

#include "exact/Exact_instantiation.h"
#include "model/Extrusion_report.h"
#include "exact/Filtered_exact_runner.h"
#include "exact/Filtered_runner.h"
#include "exact/Interval_kernel.h"
#include "exact/Piece_prepass.h"
#include "exact/Rational_kernel.h"
#include <CGAL/FPU.h>

namespace clash4d {

// The filtered exact kernel: intervals first, rationals where they fail.
// Instantiated here only (Filtered_exact_runner.h).
using Filtered_exact = Filtered_runner<Interval_kernel, Rational_kernel>;

struct Filtered_exact_runner::Impl {
  Impl(const Scene& scene, bool use_sbounds, bool reusable) : runner(scene, use_sbounds, reusable) {}
  Filtered_exact runner;
};

Filtered_exact_runner::Filtered_exact_runner(const Scene& scene, bool use_sbounds, bool reusable)
    : impl_(std::make_unique<Impl>(scene, use_sbounds, reusable))
{
}

Filtered_exact_runner::~Filtered_exact_runner() = default;

Check_answer Filtered_exact_runner::check(const Check_options& options) { return impl_->runner.check(options); }

void Filtered_exact_runner::motions_changed(const std::vector<int>& changed) { impl_->runner.motions_changed(changed); }

Skeleton_answer Filtered_exact_runner::skeleton() { return impl_->runner.skeleton(); }

// Mostly a few linear programs per piece pair (check/Piece_pairs.h).
std::optional<Check_answer> check_exact_by_pieces(const Scene& scene, const Check_options& options,
                                                  std::shared_ptr<void>* kept)
{
  using Model = Scene_model<Rational_kernel>;
  if (!Piece_pairs<Rational_kernel>::asked(options)) return std::nullopt;
  std::optional<Piece_split> split = Piece_split::make(scene);
  if (!split) return std::nullopt;
  Rational_kernel k;
  Stage_clock clock(options.stage_seconds);
  // Each piece pair by the filtered kernel on the piece scene, whose
  // planes are the pieces' own (the answer is the rational run's).
  Filtered_exact pieces(split->scene, options.sbounds);
  std::optional<Piece_prepass<Filtered_exact>> first = Piece_prepass<Filtered_exact>::make(scene, *split, pieces, options);
  // The piece scene's model and sweep, and the pass's searches; none for a
  // prepared scene, whose model is kept (the piece scene's runner, made per
  // query, is counted nowhere on the path below either).
  double first_seconds = clock.lap();
  if (first && first->apart()) {
    Check_answer answer;
    answer.number = "exact";
    answer.semantics = options.semantics;
    answer.stats.timed = options.stage_seconds;
    answer.stats.add(first->stats());
    answer.stats.object_pairs = split->piece_pairs(scene);
    answer.stats.candidate_pairs = first->meeting().size();
    answer.stats.seconds_model = kept ? 0.0 : first_seconds;
    pieces.finish(answer.stats);
    return answer;
  }
  std::shared_ptr<Model> model = kept ? std::static_pointer_cast<Model>(*kept) : nullptr;
  double model_seconds = 0;
  if (!model) {
    model = std::make_shared<Model>(Model::build(k, scene));
    model_seconds = clock.seconds();
    if (kept) *kept = model;
  }
  auto pair_check = [&](int i, int j, const Rational* ceiling, Check_stats& stats) {
    if (first)
      if (std::optional<Pair_result<Rational>> r = first->answer(i, j, ceiling)) return r;
    return pieces.check_one(i, j, options, ceiling, stats);
  };
  std::optional<Check_answer> a = piece_pairs_check(k, scene, *model, options, *split, pair_check,
                                                    first ? &first->meeting() : nullptr);
  if (!a) return std::nullopt;
  a->number = "exact";
  if (first) a->stats.add(first->stats());   // the pass's searches, reused or not
  a->stats.seconds_model = model_seconds;
  pieces.finish(a->stats);   // the runner's work in rationals, as check reports it
  return a;
}

Check_answer check_exact(const Scene& scene, const Check_options& options)
{
  if (std::optional<Check_answer> a = check_exact_by_pieces(scene, options)) return std::move(*a);
  return Filtered_exact(scene, options.sbounds).check(options);
}

// Extrusion is all constructions (nothing to filter): rationals, labelled exact.
nlohmann::ordered_json extrude_exact(const Scene& scene)
{
  nlohmann::ordered_json j = extrude_rational(scene);
  j["number"] = "exact";
  return j;
}

Skeleton_answer skeleton_exact(const Scene& scene)
{
  return Filtered_exact(scene, true).skeleton();
}

} // namespace clash4d

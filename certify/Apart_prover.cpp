#include "certify/Apart_prover.h"

#include "certify/Split_prover.h"
#include "search/Apart_pieces.h"
#include <algorithm>

namespace clash4d {
namespace {

using json = nlohmann::ordered_json;
using K = Rational_kernel;

} // namespace

json conflict_json(const Conflict& c, const Literal_table& table, bool closed)
{
  json literals = json::array(), lambda = json::array();
  for (std::size_t i = 0; i < c.literals.size(); ++i) {
    literals.push_back(literal_json(table.form(c.literals[i])));
    lambda.push_back(to_string(c.lambda[i]));
  }
  json out{{"literals", literals}, {"lambda", lambda}};
  if (closed) out["of"] = c.of == Conflict::Of::A ? "A" : c.of == Conflict::Of::B ? "B" : "both";
  return out;
}

json literal_json(const Literal_coefficients& h)
{
  json out = json::array();
  for (const auto& x : h) out.push_back(to_string(x));
  return out;
}

Apart_prover::Apart_prover(const Scene& scene, Semantics semantics, std::uint64_t step_limit)
    : scene_(scene), semantics_(semantics), limit_(step_limit)
{
}

const Scene_model<K>& Apart_prover::model()
{
  if (!model_) model_ = Scene_model<K>::build(k_, scene_);
  return *model_;
}

json Apart_prover::prove(int a, int b, const Rational& until, bool strict_end)
{
  json list;
  Split_stats split;
  // Two unions of convex pieces (meshes): a split tree whose leaves close
  // off pieces one by one (certify/Split_prover.h); otherwise, or past its
  // limits, the conflicts of every term.
  if (auto tree = split_apart_pieces(model(), a, b, until, strict_end, semantics_, split_limits_, &split)) {
    list = std::move(*tree);
    conflicts_ += split.conflicts;
    ++split_pairs_;
  } else {
    Apart_pieces<K> pieces(model(), semantics_, limit_ - std::min(limit_, steps_));
    list = json::array();
    std::vector<Apart_piece> proven = pieces.prove(a, b, until, strict_end);
    if (const std::optional<Term_stop>& stop = pieces.stopped()) {
      if (stop->why == Term_stop::Why::out_of_steps) throw Term_limit(stop->what);
      throw Term_feasible(stop->what);
    }
    for (const Apart_piece& p : proven) {
      json conflicts = json::array();
      for (const auto& c : p.conflicts) conflicts.push_back(conflict_json(c, p.literals, semantics_ == Semantics::closed));
      list.push_back(json{{"t", json::array({to_string(p.lo), to_string(p.hi)})}, {"proof", json{{"conflicts", conflicts}}}});
    }
    steps_ += pieces.steps();
    conflicts_ += pieces.conflicts();
  }
  json out{{"until", to_string(until)}};
  if (strict_end) out["open_end"] = true;
  out["pieces"] = list;
  return out;
}

} // namespace clash4d

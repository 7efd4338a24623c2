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

// The split tree (certify/Split_prover.h) grows with the pieces times its
// leaves; the proof term by term with the terms its conflicts cannot share.
// Pieces that share planes (a bowl's floor wedges, a star's underside) let
// one conflict close off many terms, so on pairs of up to
// Split_limits::compare_pairs pairs of pieces both are made and the one
// with fewer conflicts is written; beyond, the tree alone, which the terms
// cannot match at that size (a UR5 pair: 95,398 conflicts against 3,632).
json Apart_prover::prove(int a, int b, const Rational& until, bool strict_end)
{
  Split_stats split;
  std::optional<json> tree = split_apart_pieces(model(), a, b, until, strict_end, semantics_, split_limits_, &split);
  std::size_t pairs = model().objects[static_cast<std::size_t>(a)].csg.primitives.size() *
                      model().objects[static_cast<std::size_t>(b)].csg.primitives.size();
  std::optional<Term_proof> terms;
  if (!tree || pairs <= split_limits_.compare_pairs) terms = term_proof(a, b, until, strict_end, tree.has_value());
  json out{{"until", to_string(until)}};
  if (strict_end) out["open_end"] = true;
  if (tree && (!terms || split.conflicts <= terms->conflicts)) {
    out["pieces"] = std::move(*tree);
    conflicts_ += split.conflicts;
  } else {
    out["pieces"] = std::move(terms->pieces);
    conflicts_ += terms->conflicts;
    steps_ += terms->steps;
  }
  return out;
}

// The conflicts of every term, piece by piece (search/Apart_pieces.h), or
// nothing when they pass the step limit and `optional` (a tree stands
// instead). A term with a point is an error either way: the pair is not
// apart, or the tree and the terms disagree.
std::optional<Apart_prover::Term_proof> Apart_prover::term_proof(int a, int b, const Rational& until, bool strict_end,
                                                                 bool optional)
{
  Apart_pieces<K> pieces(model(), semantics_, limit_ - std::min(limit_, steps_));
  std::vector<Apart_piece> proven = pieces.prove(a, b, until, strict_end);
  if (const std::optional<Term_stop>& stop = pieces.stopped()) {
    if (stop->why == Term_stop::Why::out_of_steps) {
      if (optional) return std::nullopt;
      throw Term_limit(stop->what);
    }
    throw Term_feasible(stop->what);
  }
  Term_proof out{json::array(), pieces.conflicts(), pieces.steps()};
  for (const Apart_piece& p : proven) {
    json conflicts = json::array();
    for (const auto& c : p.conflicts) conflicts.push_back(conflict_json(c, p.literals, semantics_ == Semantics::closed));
    out.pieces.push_back(json{{"t", json::array({to_string(p.lo), to_string(p.hi)})}, {"proof", json{{"conflicts", conflicts}}}});
  }
  return out;
}

} // namespace clash4d

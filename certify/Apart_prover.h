// The proof that a pair does not collide (or touch) before a time: the
// span [tL, until] cut at every velocity change of the pair, and on each
// piece the conflicts that close off every term of the pair's formula
// (docs/certificate-format.md, APART). The formulas are the pipeline's own
// extrusion (model/Extrusion.h) over the rational kernel, with no S-bound
// pruning: the proof must not rest on a step it does not show.
#ifndef CLASH4D_CERTIFY_APART_PROVER_H
#define CLASH4D_CERTIFY_APART_PROVER_H

#include "certify/Split_prover.h"
#include "search/Term_search.h"
#include "exact/Rational_kernel.h"
#include "model/Scene_model.h"
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

namespace clash4d {

// A pair the certificate says is apart has a term with a point: the answer
// being certified is wrong, or the pipeline and the certifier disagree
// (Term_stop::Why::open_term). An internal error, never a proof.
struct Term_feasible : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// Closing off the terms took more steps than a checker is held to
// (Term_stop::Why::out_of_steps): a resource limit.
struct Term_limit : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Apart_prover {
public:
  Apart_prover(const Scene& scene, Semantics semantics, std::uint64_t step_limit);

  // APART for objects a and b until `until`; strict_end: the closed proof of
  // an earliest time, which leaves t = until out. Throws Term_feasible,
  // Term_limit.
  nlohmann::ordered_json prove(int a, int b, const Rational& until, bool strict_end);

  std::uint64_t steps() const { return steps_; }
  std::size_t conflicts() const { return conflicts_; }
  void set_split_limits(const Split_limits& limits) { split_limits_ = limits; }

private:
  using K = Rational_kernel;
  K k_;
  const Scene& scene_;
  std::optional<Scene_model<K>> model_;   // built at the first proof: a witness needs none
  Semantics semantics_;
  std::uint64_t limit_, steps_ = 0;
  std::size_t conflicts_ = 0;
  Split_limits split_limits_;

  const Scene_model<K>& model();

  struct Term_proof {
    nlohmann::ordered_json pieces;
    std::size_t conflicts = 0;
    std::uint64_t steps = 0;
  };
  std::optional<Term_proof> term_proof(int a, int b, const Rational& until, bool strict_end, bool optional);
};

// A literal's JSON form: five integers as strings.
nlohmann::ordered_json literal_json(const Literal_coefficients& h);

// A CONFLICT of a leaf (its literals from table); closed: with its "of".
nlohmann::ordered_json conflict_json(const Conflict& c, const Literal_table& table, bool closed);

} // namespace clash4d

#endif

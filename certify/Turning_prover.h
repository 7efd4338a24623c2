// The proof that a pair of which some object turns does not collide (or
// touch) on [tL, until] (docs/certificate-format.md, 8.3): the span cut at
// the motions' breakpoints and at the pair's critical times (regularised-
// semantics.md, fact 10); on each critical interval the static apart proof
// at its sample time (certify/Apart_prover.h on the posed pair), its
// conflicts lifted to polynomial multipliers (Polynomial_conflict.h); and
// consecutive intervals merged into one piece for as long as one proof
// stays valid, so that a piece ends only where a proof's basis changes.
// Each piece's proof is checked on the piece alone (8.3), whatever cut the
// span: two convex pieces are cut at their feature minors' roots (as check
// decides them, rotation/Rotating_pair.h), two unions of convex pieces at
// those of their pairs of pieces (rotation/Object_parts.h), and an
// interval on which the proof at its sample does not hold is cut again at
// every mixed minor's (of each pair of pieces). When both objects are
// unions of convex pieces (one of them at least two), the APART is given by
// members (8.3): each pair of pieces proved apart on its own pieces of time,
// cut at its own events only, so the proof grows with the pairs of pieces
// and their own events, not with their product.
#ifndef CLASH4D_CERTIFY_TURNING_PROVER_H
#define CLASH4D_CERTIFY_TURNING_PROVER_H

#include "certify/Polynomial_conflict.h"
#include "rotation/Object_parts.h"
#include "rotation/Rotating_pair.h"
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace clash4d {

// A proof this release cannot make (the reason names where): the command
// refuses the certificate, never writes a wrong one.
struct Turning_proof_missing : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Turning_prover {
public:
  // feature_events: as Check_options::feature_events (false: every mixed
  // minor's critical times from the start).
  Turning_prover(const Scene& scene, Semantics semantics, std::uint64_t step_limit, bool feature_events = true);

  // APART for objects a and b until `until`; open_end: closed semantics
  // leaves t = until out. Throws Turning_proof_missing, Term_limit.
  nlohmann::ordered_json prove(int a, int b, const Algebraic& until, bool open_end);

  std::uint64_t steps() const { return steps_; }
  std::size_t conflicts() const { return conflicts_; }

private:
  struct Leaf {
    Algebraic lo, hi;
    std::vector<Polynomial_conflict> conflicts;
  };
  using Proof = std::vector<Polynomial_conflict>;

  std::vector<Leaf> pose_piece(const Rational& lo, const Rational& piece_hi, const Algebraic& hi, bool open_end);
  nlohmann::ordered_json pieces_until(const Algebraic& until, bool open_end);
  bool by_members() const;
  Proof proof_at(const std::vector<Moving_plane>& rows, const Rational& s);
  std::vector<Algebraic> critical_cuts(const Rational& mid, const Rational& lo, const Rational& piece_hi,
                                       const Algebraic& hi, bool features_only, bool& restricted) const;
  bool valid(const Proof& p, const Algebraic& lo, const Algebraic& hi, bool open_end) const;
  const Rotating_object& a() const { return *a_; }
  const Rotating_object& b() const { return *b_; }

  const Scene& scene_;
  Semantics semantics_;
  bool feature_events_;
  std::uint64_t limit_, steps_ = 0;
  std::size_t conflicts_ = 0;
  std::optional<Object_parts> parts_a_, parts_b_;   // the pair being proved, with its convex pieces
  // What is proved now: the whole objects (cut at every pair of their
  // pieces that may meet), or one member of each (cut at that pair's; then
  // at least one of them is a piece, not its whole object).
  const Rotating_object *a_ = nullptr, *b_ = nullptr;
  bool one_member_pair() const { return a_ != &parts_a_->whole || b_ != &parts_b_->whole; }
  std::string where_;                      // names it in a refusal
};

} // namespace clash4d

#endif

// A pair proven apart by conflicts (docs/certificate-format.md, APART): the
// span [tL, until] cut at every velocity change of the pair, and on each
// piece the conflicts of Term_search that close off every DNF term of the
// pair's formula, on the pair's own extrusion (model/Extrusion.h) with no
// shear and no S-bound pruning. One exact LP per conflict (Motzkin_lp), so
// it decides "no collision" where generate-and-test would examine many lines
// (exact/Interval_filter.h hands a long search over to it), and it is the
// proof a certificate writes (certify/Apart_prover.h). Over a kernel whose
// FT is Rational (the certificate's numbers).
#ifndef CLASH4D_SEARCH_APART_PIECES_H
#define CLASH4D_SEARCH_APART_PIECES_H

#include "model/Extrusion.h"
#include "search/Term_search.h"
#include <algorithm>
#include <optional>
#include <vector>

namespace clash4d {

// One piece of time and the conflicts closing off its terms.
struct Apart_piece {
  Rational lo, hi;
  bool strict_end = false;
  Literal_table literals;
  std::vector<Conflict> conflicts;
};

// tL, every velocity change of objects a and b strictly before until, and
// until: the ends of an APART's pieces (section 3).
template <class K>
std::vector<Rational> apart_cuts(const Scene_model<K>& model, int a, int b, const Rational& until)
{
  std::vector<Rational> cuts{model.t_lo, until};
  for (int i : {a, b})
    for (const auto& t : model.objects[i].motion.times)
      if (model.t_lo < t && t < until) cuts.push_back(t);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  return cuts;
}

template <class K>
class Apart_pieces {
public:
  using FT = typename K::FT;

  // effort: as Term_search's (quick: a proof found is a proof, none found
  // says nothing).
  Apart_pieces(const Scene_model<K>& model, Semantics semantics, std::uint64_t step_limit,
               Lp_effort effort = Lp_effort::complete)
    : model_(model), semantics_(semantics), limit_(step_limit), effort_(effort)
  {
  }

  // The pieces of objects a and b until `until`, each closed off; strict_end:
  // the closed proof of an earliest time, which leaves t = until out. The
  // leading pieces only, when a piece's search stopped (stopped(): a term
  // has a point, so the pair is not apart, or the steps ran out).
  std::vector<Apart_piece> prove(int a, int b, const Rational& until, bool strict_end)
  {
    std::vector<Rational> cuts = apart_cuts(model_, a, b, until);
    std::vector<Apart_piece> pieces;
    proven_until_ = cuts.front();
    stop_.reset();
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      Apart_piece p = piece(a, b, cuts[i], cuts[i + 1], strict_end && i + 2 == cuts.size());
      if (stop_) break;
      pieces.push_back(std::move(p));
      proven_until_ = cuts[i + 1];
    }
    return pieces;
  }
  // Why prove did not close off every piece; nothing when it did.
  const std::optional<Term_stop>& stopped() const { return stop_; }

  // The end of the leading pieces closed off so far: when prove stopped,
  // the pair is still proven apart on [tL, proven_until()] (each piece's
  // proof stands alone), a prefix of its sub-spans.
  const Rational& proven_until() const { return proven_until_; }

  std::uint64_t steps() const { return steps_; }
  std::size_t conflicts() const { return conflicts_; }

private:
  const Scene_model<K>& model_;
  Semantics semantics_;
  std::uint64_t limit_, steps_ = 0;
  Lp_effort effort_;
  std::size_t conflicts_ = 0;
  Rational proven_until_;
  std::optional<Term_stop> stop_;

  Apart_piece piece(int a, int b, const Rational& lo, const Rational& hi, bool strict_end)
  {
    const Time_span<FT> span{lo, hi};
    auto everything = [&](int i) { return std::vector<Box<FT, 3>>(model_.objects[i].csg.nodes.size()); };
    Moving_object<FT> A = moving_on(model_, a, span, everything(a)), B = moving_on(model_, b, span, everything(b));
    Motion_groups<FT> groups;
    const Vector3<FT> no_shear{FT(0), FT(0), FT(0)};
    auto table = Extrusion<K>::pair_table(A, B, no_shear, {false, false, false}, false, groups);
    Pair_formula f = Extrusion<K>::pair_formula(A, B);

    Apart_piece out{lo, hi, strict_end, {}, {}};
    std::vector<int> literal_of;
    for (const auto& h : table) literal_of.push_back(out.literals.id({h.n[0], h.n[1], h.n[2], h.n[3], h.c}));
    std::vector<int> slab{out.literals.id({FT(0), FT(0), FT(0), FT(-1), lo}),
                          out.literals.id({FT(0), FT(0), FT(0), FT(1), -hi})};
    std::vector<Term_node> nodes;
    int ra = add_formula(f.a(), 0, literal_of, nodes), rb = add_formula(f.b(), 1, literal_of, nodes);
    nodes.push_back({Term_node::Op::And, -1, 0, {ra, rb}});
    const int root = static_cast<int>(nodes.size()) - 1;
    Term_search search(out.literals, std::move(nodes), root, slab, semantics_, strict_end,
                       limit_ - std::min(limit_, steps_), effort_);
    out.conflicts = search.run();
    stop_ = search.stopped();
    steps_ += search.steps();
    conflicts_ += out.conflicts.size();
    return out;
  }

  // Formula (postfix over table entries) into term nodes over literal ids.
  static int add_formula(const Formula& f, int side, const std::vector<int>& literal_of, std::vector<Term_node>& nodes)
  {
    if (f.value() != Truth::Unknown) {
      // True: an AND of nothing (one empty term); False: an OR of nothing.
      nodes.push_back({f.value() == Truth::True ? Term_node::Op::And : Term_node::Op::Or, -1, side, {}});
      return static_cast<int>(nodes.size()) - 1;
    }
    std::vector<int> stack;
    for (const auto& t : f.code()) {
      Term_node n;
      n.side = side;
      if (t.op == Formula::Op::Leaf) {
        n.literal = literal_of[t.arg];
      } else {
        n.op = t.op == Formula::Op::And ? Term_node::Op::And : Term_node::Op::Or;
        n.children.assign(stack.end() - t.arg, stack.end());
        stack.resize(stack.size() - t.arg);
      }
      nodes.push_back(std::move(n));
      stack.push_back(static_cast<int>(nodes.size()) - 1);
    }
    return stack.back();
  }
};

} // namespace clash4d

#endif

// Learns the conflicts that close off every DNF term of a pair's formula on
// one piece of time: a depth-first walk of the terms that stops a branch as
// soon as its literals hold a known conflict, asks one exact LP for a new
// conflict at each term still open (search/Motzkin_lp.h), and jumps back to
// where that conflict was complete. The rules are the checker's
// (docs/certificate-format.md, section 4), so a term this closes off is
// closed off there.
#ifndef CLASH4D_SEARCH_TERM_SEARCH_H
#define CLASH4D_SEARCH_TERM_SEARCH_H

#include "search/Literal_table.h"
#include "search/Semantics.h"
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace clash4d {

// A formula in negation normal form over literal ids; side 0 is the pair's
// first object, 1 the second.
struct Term_node {
  enum class Op : std::uint8_t { Leaf, And, Or } op = Op::Leaf;
  int literal = -1;
  int side = 0;
  std::vector<int> children;
};

struct Conflict {
  enum class Of : std::uint8_t { Both, A, B } of = Of::Both;
  std::vector<int> literals;
  std::vector<Rational> lambda;
};

// Why a term search stopped before closing off every term: an answer of
// the search, returned, not thrown (a caller decides whether it is an
// error: certify/Apart_prover.h makes it one).
struct Term_stop {
  enum class Why : std::uint8_t {
    // A term the LP finds feasible: the answer being certified is wrong,
    // or the pipeline and the certifier disagree; never written as a
    // proof. With Lp_effort::quick, only a term the guided LP did not
    // close off (a search handing over goes on instead).
    open_term,
    // The enumeration took more steps than a checker is held to.
    out_of_steps
  };
  Why why;
  std::string what;   // the reason, in words
  // open_term, regularised: the double simplex's point inside that term's
  // literals (Inside_guess), when it found one: a caller may check it as a
  // witness.
  Inside_guess inside;
};

class Term_search {
public:
  // root: nodes[root] is A AND B. slab: the piece's literals lo - t and
  // t - hi; strict_end: t - hi is strict in closed semantics (the end of an
  // earliest proof).
  // effort: Lp_effort::quick, a term the double simplex's guess does not
  // close off stops the search too (Term_stop::Why::open_term: not proven;
  // only complete says the term has a point).
  Term_search(Literal_table& table, std::vector<Term_node> nodes, int root, std::vector<int> slab,
              Semantics semantics, bool strict_end, std::uint64_t step_limit,
              Lp_effort effort = Lp_effort::complete);

  // The conflicts learnt; every term is closed off unless stopped() says
  // why not.
  std::vector<Conflict> run();
  const std::optional<Term_stop>& stopped() const { return stop_; }
  std::uint64_t steps() const { return steps_; }

private:
  Literal_table& table_;
  std::vector<Term_node> nodes_;
  int root_;
  std::vector<int> slab_;
  bool closed_, strict_end_;
  std::uint64_t limit_, steps_ = 0;
  Lp_effort effort_;
  std::vector<Conflict> conflicts_;
  std::vector<std::vector<int>> with_;      // per literal: conflicts holding it
  std::vector<int> count_[2];               // per side and literal: times in the term
  std::vector<int> order_;                  // literal ids in the order added
  std::vector<int> position_;               // per literal: first place in order_, -1 absent
  std::vector<int> pending_;
  Inside_guess inside_;                     // the last LP's, when it learnt nothing
  std::optional<Term_stop> stop_;

  // walk's jump back when the search stops: past the root, so every level
  // returns without trying another choice.
  static constexpr int unwind = -1;
  int stop(Term_stop::Why why, std::string what, Inside_guess inside = {});

  int walk();
  int leaf(int literal, int side);
  bool closed_off(int literal) const;
  bool holds(const Conflict& c) const;
  bool available(int literal, Conflict::Of of) const;
  bool is_slab(int literal) const;
  int complete();
  bool learn(std::vector<int> literals, Conflict::Of of, const std::vector<bool>& strict);
  void grow(int literal);
};

} // namespace clash4d

#endif

// Checking a leaf: every DNF term must be closed off by a valid conflict
// (docs/certificate-format.md, section 4). The conflicts' arithmetic is
// checked before (Certificate_checker); here only which literals are there.
#ifndef CLASH4D_VERIFY_TERM_ENUMERATOR_H
#define CLASH4D_VERIFY_TERM_ENUMERATOR_H

#include "verify/Solid_formula.h"
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

namespace clash4d::verifier {

// Section 4: the steps of term enumeration one certificate may take.
constexpr long long CLASH4D_VERIFY_MAX_STEPS = 10000000;

// A step is one node of the walk or one conflict's count updated when a
// literal comes or goes: the work grows with neither more than the steps.
struct Step_limit_reached : std::runtime_error {
  Step_limit_reached() : std::runtime_error("term enumeration passed 10,000,000 steps") {}
};

// An object's formula on one piece, its literals as ids (id ^ 1 is the negation).
struct Lit_tree {
  Formula::Op op = Formula::Op::And;
  int lit = -1;
  std::vector<Lit_tree> kids;
};

// Where a literal of L comes from; a conflict's `of` says which it may use.
enum Side { Side_A, Side_B, Side_path, Side_slab };
enum Of { Of_both, Of_A, Of_B };

// lits: the conflict's literal ids, each once (sorted, duplicates dropped).
struct Leaf_conflict {
  std::vector<int> lits;
  Of of = Of_both;
};

class Term_enumerator {
public:
  explicit Term_enumerator(long long& steps) : steps_(steps) {}
  // True when every term of F_A AND F_B is closed off (regularised: also by a
  // literal and its negation; closed: by `of` as section 4 says). Otherwise
  // false, and uncovered() is the first term left open, (literal, side).
  bool all_closed(bool regularised, const Lit_tree& fa, const Lit_tree& fb, const std::vector<int>& path,
                  const std::vector<int>& slab, const std::vector<Leaf_conflict>& conflicts, std::size_t ids);
  const std::vector<std::pair<int, Side>>& uncovered() const { return uncovered_; }

private:
  bool walk(Side side);
  bool closes(int lit) const;
  bool present(int lit, unsigned sides) const;
  unsigned sides(const Leaf_conflict& c) const;
  void add(int lit, Side side, int by);
  void count_step(std::size_t n);

  long long& steps_;
  bool regularised_ = true;
  const Lit_tree* fb_ = nullptr;
  const std::vector<Leaf_conflict>* conflicts_ = nullptr;
  std::unordered_map<int, std::vector<int>> by_literal_;   // literal -> conflicts using it
  std::vector<std::size_t> missing_;                       // per conflict: its literals not yet present
  std::vector<std::array<int, 4>> count_;                  // per literal and side, zero between leaves
  std::vector<const Lit_tree*> todo_;
  std::vector<std::pair<int, Side>> term_, uncovered_;
};

} // namespace clash4d::verifier

#endif

// The formula a pair's search works on: each object's formula kept apart.
// Regularised semantics asks for one open cell inside both, the conjunction
// A and B; closed semantics asks for a point in the closure of a cell inside
// A and in the closure of a cell inside B, possibly different cells
// (scene-format.md, "Closed semantics"), so it must evaluate A and B on
// their own. Simplification and evaluation are the conjunction's, done
// object by object; a single formula is the first object's, the second being
// everything (so stages can be given one formula, as their unit tests do).
#ifndef CLASH4D_MODEL_PAIR_FORMULA_H
#define CLASH4D_MODEL_PAIR_FORMULA_H

#include "model/Formula.h"
#include <utility>

namespace clash4d {

class Pair_formula {
public:
  Pair_formula() = default;
  Pair_formula(Formula a) : a_(std::move(a)) {}   // NOLINT: implicit, B = everything
  Pair_formula(Formula a, Formula b) : a_(std::move(a)), b_(std::move(b)) {}

  const Formula& a() const { return a_; }
  const Formula& b() const { return b_; }

  // Kleene conjunction of the two values.
  Truth value() const { return both(a_.value(), b_.value()); }
  std::size_t leaf_count() const { return a_.leaf_count() + b_.leaf_count(); }

  // Each object's formula simplified; B is left alone once A is false.
  template <class Status>
  Pair_formula simplified(Status status) const
  {
    Formula a = a_.simplified(status);
    if (a.value() == Truth::False) return Pair_formula(std::move(a), Formula());
    return Pair_formula(std::move(a), b_.simplified(status));
  }

  // A and B under the leaf truths (Kleene), B only when A is not false.
  template <class Leaf_truth>
  Truth evaluate(Leaf_truth truth) const
  {
    Truth a = a_.evaluate(truth);
    return a == Truth::False ? a : both(a, b_.evaluate(truth));
  }

  // Every leaf of A, then every leaf of B (a hyperplane index each).
  template <class F>
  void for_each_leaf(F f) const
  {
    for (const Formula* g : {&a_, &b_})
      for (const auto& t : g->code())
        if (t.op == Formula::Op::Leaf) f(t.arg);
  }

private:
  Formula a_, b_;

  static Truth both(Truth a, Truth b)
  {
    if (a == Truth::False || b == Truth::False) return Truth::False;
    return a == Truth::True && b == Truth::True ? Truth::True : Truth::Unknown;
  }
};

} // namespace clash4d

#endif

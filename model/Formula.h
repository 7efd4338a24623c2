// A Boolean formula over half-space leaves in negation normal form, stored in
// postfix so the division stage can simplify a copy per region with one pass
// and memory proportional to its size (§4.1). Differences are rewritten as
// A and not B, and negation is pushed to the leaves: the regularised
// complement of h <= 0 is -h <= 0 (regularised-semantics.md, item 2).
#ifndef CLASH4D_MODEL_FORMULA_H
#define CLASH4D_MODEL_FORMULA_H

#include <cstdint>
#include <boost/container/small_vector.hpp>
#include <vector>

namespace clash4d {

enum class Truth : std::uint8_t { False, True, Unknown };

class Formula {
public:
  enum class Op : std::uint8_t { Leaf, And, Or };
  struct Token {
    Op op;
    std::uint32_t arg;       // Leaf: hyperplane index; And/Or: child count
  };

  // Constant folding builder: children are emitted, then closed by an operator.
  class Builder {
  public:
    // Marks the start of a node's children.
    std::size_t open() const { return results_.size(); }
    void leaf(std::uint32_t h) { results_.push_back({Truth::Unknown, code_.size()}); code_.push_back({Op::Leaf, h}); }
    void constant(bool v) { results_.push_back({v ? Truth::True : Truth::False, code_.size()}); }
    void close(Op op, std::size_t mark)
    {
      // And: any False child makes it False; True children vanish. Or: dual.
      Truth absorbing = op == Op::And ? Truth::False : Truth::True;
      Truth neutral = op == Op::And ? Truth::True : Truth::False;
      std::size_t start = mark < results_.size() ? results_[mark].start : code_.size();
      std::uint32_t live = 0;
      bool absorbed = false;
      for (std::size_t i = mark; i < results_.size(); ++i) {
        if (results_[i].value == absorbing) absorbed = true;
        else if (results_[i].value == Truth::Unknown) ++live;
      }
      results_.resize(mark);
      if (absorbed) { code_.resize(start); results_.push_back({absorbing, start}); return; }
      if (live == 0) { code_.resize(start); results_.push_back({neutral, start}); return; }
      if (live > 1) code_.push_back({op, live});
      results_.push_back({Truth::Unknown, start});
    }
    Formula finish()
    {
      Formula f;
      f.value_ = results_.empty() ? Truth::True : results_.back().value;
      if (f.value_ == Truth::Unknown) f.code_ = std::move(code_);
      return f;
    }

  private:
    struct Result { Truth value; std::size_t start; };
    std::vector<Token> code_;
    std::vector<Result> results_;
  };

  // True or False when the formula folded to a constant, else Unknown.
  Truth value() const { return value_; }
  const std::vector<Token>& code() const { return code_; }

  std::size_t leaf_count() const
  {
    std::size_t n = 0;
    for (const auto& t : code_) n += t.op == Op::Leaf;
    return n;
  }

  // A copy with each leaf replaced by status(h) when that is not Unknown.
  template <class Status>
  Formula simplified(Status status) const
  {
    if (value_ != Truth::Unknown) return *this;
    Builder b;
    std::vector<std::size_t> marks;   // open() positions of pending children
    for (const Token& t : code_) {
      if (t.op == Op::Leaf) {
        Truth s = status(t.arg);
        if (s == Truth::Unknown) b.leaf(t.arg); else b.constant(s == Truth::True);
        marks.push_back(b.open() - 1);
      } else {
        std::size_t mark = marks[marks.size() - t.arg];
        marks.resize(marks.size() - t.arg);
        b.close(t.op, mark);
        marks.push_back(mark);
      }
    }
    return b.finish();
  }

  // Kleene evaluation with leaf truths (Unknown propagates).
  template <class Leaf_truth>
  Truth evaluate(Leaf_truth truth) const
  {
    if (value_ != Truth::Unknown) return value_;
    // On the stack for formulas of up to 128 leaves: this runs at every
    // point generate-and-test looks at.
    boost::container::small_vector<Truth, 128> stack;
    for (const Token& t : code_) {
      if (t.op == Op::Leaf) { stack.push_back(truth(t.arg)); continue; }
      Truth absorbing = t.op == Op::And ? Truth::False : Truth::True;
      Truth r = t.op == Op::And ? Truth::True : Truth::False;
      for (std::uint32_t i = 0; i < t.arg; ++i) {
        Truth c = stack.back();
        stack.pop_back();
        if (c == absorbing) r = absorbing;
        else if (c == Truth::Unknown && r != absorbing) r = Truth::Unknown;
      }
      stack.push_back(r);
    }
    return stack.back();
  }

private:
  Truth value_ = Truth::True;
  std::vector<Token> code_;
};

} // namespace clash4d

#endif

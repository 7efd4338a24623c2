#include "search/Term_search.h"

#include "run/Work_budget.h"
#include <algorithm>
#include <climits>

namespace clash4d {

Term_search::Term_search(Literal_table& table, std::vector<Term_node> nodes, int root, std::vector<int> slab,
                         Semantics semantics, bool strict_end, std::uint64_t step_limit, Lp_effort effort)
    : table_(table), nodes_(std::move(nodes)), root_(root), slab_(std::move(slab)),
      closed_(semantics == Semantics::closed), strict_end_(strict_end), limit_(step_limit), effort_(effort)
{
  // Regularised semantics has one term over both objects: one side.
  if (!closed_)
    for (auto& n : nodes_) n.side = 0;
}

std::vector<Conflict> Term_search::run()
{
  pending_ = {root_};
  walk();
  return conflicts_;
}

int Term_search::stop(Term_stop::Why why, std::string what, Inside_guess inside)
{
  stop_ = Term_stop{why, std::move(what), inside};
  return unwind;
}

void Term_search::grow(int literal)
{
  std::size_t n = std::max(table_.size(), static_cast<std::size_t>(literal) + 1);
  if (with_.size() >= n) return;
  with_.resize(n);
  for (auto& c : count_) c.resize(n, 0);
  position_.resize(2 * n, -1);
}

// One step of the depth-first walk over the pending nodes. Returns the
// length of the term prefix that holds a conflict just learnt (INT_MAX when
// none): every choice made with at least that prefix is closed off too.
// unwind (below every prefix) when the search stopped (stop_).
int Term_search::walk()
{
  if (++steps_ > limit_)
    return stop(Term_stop::Why::out_of_steps,
                "closing off the terms took more than " + std::to_string(limit_) + " steps");
  if ((steps_ & 1023) == 0) Work_budget::check();   // --max-seconds covers the certificate too
  if (pending_.empty()) return complete();
  int n = pending_.back();
  pending_.pop_back();
  const Term_node node = nodes_[n];
  int jump = INT_MAX;
  if (node.op == Term_node::Op::Leaf) {
    jump = leaf(node.literal, node.side);
  } else if (node.op == Term_node::Op::And) {
    for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) pending_.push_back(*it);
    jump = walk();
    pending_.resize(pending_.size() - node.children.size());
  } else {
    for (int c : node.children) {
      pending_.push_back(c);
      jump = walk();
      pending_.pop_back();
      if (static_cast<int>(order_.size()) >= jump) break;
    }
  }
  pending_.push_back(n);
  return jump;
}

int Term_search::leaf(int literal, int side)
{
  grow(literal);
  if (count_[side][literal] > 0) return walk();
  ++count_[side][literal];
  int key = 2 * literal + side;
  position_[key] = static_cast<int>(order_.size());
  order_.push_back(key);
  int jump = closed_off(literal) ? INT_MAX : walk();
  order_.pop_back();
  position_[key] = -1;
  --count_[side][literal];
  return jump;
}

bool Term_search::is_slab(int literal) const
{
  return std::find(slab_.begin(), slab_.end(), literal) != slab_.end();
}

bool Term_search::available(int literal, Conflict::Of of) const
{
  if (is_slab(literal)) return true;
  if (literal >= static_cast<int>(count_[0].size())) return false;
  if (of == Conflict::Of::A) return count_[0][literal] > 0;
  if (of == Conflict::Of::B) return count_[1][literal] > 0;
  return count_[0][literal] > 0 || count_[1][literal] > 0;
}

bool Term_search::holds(const Conflict& c) const
{
  for (int l : c.literals)
    if (!available(l, c.of)) return false;
  return true;
}

// Regularised: a literal with its negation in the term or the slab (section
// 4's built-in rule); both semantics: a known conflict completed by it.
bool Term_search::closed_off(int literal) const
{
  if (!closed_) {
    int neg = table_.negation(literal);
    if (is_slab(neg) || (neg < static_cast<int>(count_[0].size()) && count_[0][neg] > 0)) return true;
  }
  for (int c : with_[literal])
    if (holds(conflicts_[c])) return true;
  return false;
}

bool Term_search::learn(std::vector<int> literals, Conflict::Of of, const std::vector<bool>& strict)
{
  std::vector<Motzkin_row> rows;
  for (std::size_t i = 0; i < literals.size(); ++i) rows.push_back({&table_.form(literals[i]), strict[i]});
  auto lambda = motzkin_multipliers(rows, effort_, &inside_);
  if (!lambda) return false;
  Conflict c;
  c.of = of;
  for (std::size_t i = 0; i < literals.size(); ++i)
    if (CGAL::sign((*lambda)[i]) == CGAL::POSITIVE) c.literals.push_back(literals[i]), c.lambda.push_back((*lambda)[i]);
  for (int l : c.literals) {
    grow(l);
    with_[l].push_back(static_cast<int>(conflicts_.size()));
  }
  conflicts_.push_back(std::move(c));
  return true;
}

// A whole term no conflict closes off: one LP for a new conflict, then the
// prefix length that holds it (where the walk jumps back to).
int Term_search::complete()
{
  std::vector<int> sides[2];
  for (int key : order_) sides[key % 2].push_back(key / 2);
  auto with_slab = [&](std::vector<int> literals, bool strict) {
    std::vector<bool> s(literals.size(), strict);
    for (std::size_t i = 0; i < slab_.size(); ++i) {
      literals.push_back(slab_[i]);
      s.push_back(strict || (i == 1 && strict_end_));
    }
    return std::make_pair(literals, s);
  };
  bool learnt = false;
  if (!closed_) {
    auto [l, s] = with_slab(sides[0], true);
    learnt = learn(l, Conflict::Of::Both, s);
  } else {
    std::vector<int> both = sides[0];
    both.insert(both.end(), sides[1].begin(), sides[1].end());
    auto [l, s] = with_slab(both, false);
    auto [la, sa] = with_slab(sides[0], true);
    auto [lb, sb] = with_slab(sides[1], true);
    learnt = learn(l, Conflict::Of::Both, s) || learn(la, Conflict::Of::A, sa) || learn(lb, Conflict::Of::B, sb);
  }
  // Regularised, the one LP was the term's: its guess is a point inside it.
  Inside_guess inside = closed_ ? Inside_guess() : inside_;
  if (!learnt && effort_ == Lp_effort::quick)
    return stop(Term_stop::Why::open_term, "a term of the pair's formula was not closed off", inside);
  if (!learnt)
    return stop(Term_stop::Why::open_term, "a term of the pair's formula has a point: the apart claim does not hold",
                inside);
  const Conflict& c = conflicts_.back();
  int level = 0;
  for (int l : c.literals) {
    if (is_slab(l)) continue;
    int at = INT_MAX;
    for (int side = 0; side < 2; ++side) {
      bool usable = c.of == Conflict::Of::Both || (side == 0) == (c.of == Conflict::Of::A);
      int p = position_[2 * l + side];
      if (usable && p >= 0) at = std::min(at, p);
    }
    level = std::max(level, at + 1);
  }
  return level;
}

} // namespace clash4d

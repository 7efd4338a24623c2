#include "verify/Term_enumerator.h"

namespace clash4d::verifier {

bool Term_enumerator::present(int lit, unsigned sides) const
{
  for (int s = 0; s < 4; ++s)
    if ((sides >> s & 1u) && count_[lit][s] > 0) return true;
  return false;
}

// Section 4: regularised conflicts range over the whole term, path and slab;
// closed "of": "A" over TA and the slab only, "B" over TB and the slab.
unsigned Term_enumerator::sides(const Leaf_conflict& c) const
{
  if (!regularised_ && c.of == Of_A) return 1u << Side_A | 1u << Side_slab;
  if (!regularised_ && c.of == Of_B) return 1u << Side_B | 1u << Side_slab;
  return 0xFu;
}

void Term_enumerator::count_step(std::size_t n)
{
  steps_ += static_cast<long long>(n);
  if (steps_ > CLASH4D_VERIFY_MAX_STEPS) throw Step_limit_reached();
}

// Only conflicts using the literal just added can have become valid; each
// keeps the count of its literals still missing, so this is one look each.
bool Term_enumerator::closes(int lit) const
{
  if (regularised_ && present(lit ^ 1, 0xFu)) return true;   // a literal and its negation
  auto it = by_literal_.find(lit);
  if (it == by_literal_.end()) return false;
  for (int c : it->second)
    if (missing_[c] == 0) return true;
  return false;
}

// The literal comes (by 1) or goes (by -1) on a side; every conflict using
// it whose sides see it appear or vanish updates its missing count.
void Term_enumerator::add(int lit, Side side, int by)
{
  auto it = by_literal_.find(lit);
  if (it != by_literal_.end()) {
    count_step(it->second.size());
    for (int c : it->second) {
      unsigned s = sides((*conflicts_)[c]);
      if (!(s >> side & 1u)) continue;
      bool before = present(lit, s);
      count_[lit][side] += by;
      if (before && !present(lit, s)) ++missing_[c];
      if (!before && present(lit, s)) --missing_[c];
      count_[lit][side] -= by;
    }
  }
  count_[lit][side] += by;
  if (by > 0) term_.emplace_back(lit, side);
  else term_.pop_back();
}

bool Term_enumerator::all_closed(bool regularised, const Lit_tree& fa, const Lit_tree& fb,
                                 const std::vector<int>& path, const std::vector<int>& slab,
                                 const std::vector<Leaf_conflict>& conflicts, std::size_t ids)
{
  regularised_ = regularised;
  fb_ = &fb;
  conflicts_ = &conflicts;
  if (count_.size() < ids) count_.resize(ids, {0, 0, 0, 0});
  by_literal_.clear();
  missing_.assign(conflicts.size(), 0);
  for (std::size_t c = 0; c < conflicts.size(); ++c) {
    count_step(conflicts[c].lits.size());
    missing_[c] = conflicts[c].lits.size();
    for (int l : conflicts[c].lits) by_literal_[l].push_back(static_cast<int>(c));
  }
  // The path and the slab are in every term; they may close off the leaf alone.
  bool closed = false;
  for (int l : path) add(l, Side_path, 1), closed = closed || closes(l);
  for (int l : slab) add(l, Side_slab, 1), closed = closed || closes(l);
  uncovered_.clear();
  todo_.assign(1, &fa);
  if (!closed) closed = walk(Side_A);
  for (int l : slab) add(l, Side_slab, -1);
  for (int l : path) add(l, Side_path, -1);
  return closed;
}

// Depth first over the DNF of the formulas on todo_: AND pushes all its
// children, OR tries each child in turn; a branch stops as soon as its
// partial term is closed off (section 4). F_B's terms follow each of F_A's.
bool Term_enumerator::walk(Side side)
{
  if (todo_.empty()) {
    if (side == Side_B) return uncovered_ = term_, false;
    todo_.push_back(fb_);
    bool ok = walk(Side_B);
    todo_.pop_back();
    return ok;
  }
  count_step(1);
  const Lit_tree* n = todo_.back();
  todo_.pop_back();
  bool ok = true;
  if (n->op == Formula::Op::Atom) {
    add(n->lit, side, 1);
    ok = closes(n->lit) || walk(side);
    add(n->lit, side, -1);
  } else if (n->op == Formula::Op::And) {
    for (auto k = n->kids.rbegin(); k != n->kids.rend(); ++k) todo_.push_back(&*k);
    ok = walk(side);
    todo_.resize(todo_.size() - n->kids.size());
  } else {
    for (std::size_t i = 0; i < n->kids.size() && ok; ++i) {
      todo_.push_back(&n->kids[i]);
      ok = walk(side);
      todo_.pop_back();
    }
  }
  todo_.push_back(n);
  return ok;
}

} // namespace clash4d::verifier

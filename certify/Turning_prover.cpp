#include "certify/Turning_prover.h"

#include "certify/Apart_prover.h"
#include "certify/Split_prover.h"
#include "rotation/Critical_times.h"
#include "rotation/Simplest_rational.h"
#include "run/Work_budget.h"
#include "scene/Number_json.h"
#include <algorithm>
#include <limits>
#include <map>

namespace clash4d {
namespace {

using json = nlohmann::ordered_json;
using Vec4 = std::array<Rational, 4>;

using CGAL::is_zero;   // exact on Rational

// v divided by its first non-zero entry's absolute value: equal keys are
// positive multiples of each other.
std::vector<std::string> direction_key(const Vec4& v)
{
  Rational scale(0);
  for (const Rational& x : v)
    if (!is_zero(x)) {
      scale = CGAL::abs(x);
      break;
    }
  std::vector<std::string> key;
  for (const Rational& x : v) key.push_back(to_string(is_zero(scale) ? x : x / scale));
  return key;
}

Vec4 at(const Moving_plane& h, const Rational& s) { return {h[0].at(s), h[1].at(s), h[2].at(s), h[3].at(s)}; }

Moving_plane negated(const Moving_plane& h) { return {-h[0], -h[1], -h[2], -h[3]}; }

json poly_json(const Time_poly& p)
{
  std::vector<Rational> c = p.coefficients();
  while (c.size() > 1 && is_zero(c.back())) c.pop_back();
  json out = json::array();
  for (const Rational& x : c) out.push_back(to_string(x));
  if (out.empty()) out.push_back("0");
  return out;
}

json conflict_json(const Polynomial_conflict& c, bool closed)
{
  json literals = json::array(), lambda = json::array();
  for (std::size_t i = 0; i < c.literals.size(); ++i) {
    json lit = json::array();
    for (const Time_poly& p : c.literals[i]) lit.push_back(poly_json(p));
    literals.push_back(lit);
    lambda.push_back(poly_json(c.lambda[i]));
  }
  json out{{"literals", literals}, {"lambda", lambda}};
  if (closed) out["of"] = c.of == Conflict::Of::A ? "A" : c.of == Conflict::Of::B ? "B" : "both";
  return out;
}

Conflict::Of of_from(const json& c)
{
  if (!c.contains("of") || c["of"] == "both") return Conflict::Of::Both;
  return c["of"] == "A" ? Conflict::Of::A : Conflict::Of::B;
}

} // namespace

Turning_prover::Turning_prover(const Scene& scene, Semantics semantics, std::uint64_t step_limit, bool feature_events)
    : scene_(scene), semantics_(semantics), feature_events_(feature_events), limit_(step_limit)
{
}

bool Turning_prover::valid(const Proof& p, const Algebraic& lo, const Algebraic& hi, bool open_end) const
{
  bool closed = semantics_ == Semantics::closed;
  for (const Polynomial_conflict& c : p)
    if (!c.valid_on(lo, hi, !closed || c.of != Conflict::Of::Both, open_end)) return false;
  return true;
}

// The static apart proof of the pair posed at s, each conflict's literals
// found among the rows (or their negations) by their direction at s, and
// lifted to polynomial multipliers.
Turning_prover::Proof Turning_prover::proof_at(const std::vector<Moving_plane>& rows, const Rational& s)
{
  std::map<std::vector<std::string>, Moving_plane> by_direction;
  for (const Moving_plane& h : rows) {
    by_direction.emplace(direction_key(at(h, s)), h);
    by_direction.emplace(direction_key(at(negated(h), s)), negated(h));
  }
  Scene posed = posed_pair(a(), b(), s);
  Apart_prover prover(posed, semantics_, limit_ - std::min(limit_, steps_));
  // Term by term: a turning APART's proof is a leaf (8.3 has no split), so
  // two unions of convex pieces are not proved by a split tree here.
  Split_limits leaf_only;
  leaf_only.min_pairs = std::numeric_limits<std::size_t>::max();
  prover.set_split_limits(leaf_only);
  json apart = prover.prove(0, 1, Rational(1), false);
  steps_ += prover.steps();
  bool closed = semantics_ == Semantics::closed;
  Proof out;
  for (const json& piece : apart["pieces"]) {
    if (!piece["proof"].contains("conflicts"))
      throw Turning_proof_missing(where_ + ": the static proof at t = " + to_string(s) + " is not a leaf of conflicts");
    for (const json& c : piece["proof"]["conflicts"]) {
      std::vector<Moving_plane> literals;
      std::vector<Rational> lambda;
      for (std::size_t i = 0; i < c["literals"].size(); ++i) {
        const json& l = c["literals"][i];
        Vec4 v = {rational_from_string(l[0]), rational_from_string(l[1]), rational_from_string(l[2]),
                  rational_from_string(l[4])};
        auto it = by_direction.find(direction_key(v));
        if (!is_zero(rational_from_string(l[3])) || it == by_direction.end())
          throw Turning_proof_missing(where_ + ": a static conflict at t = " + to_string(s) +
                                      " uses a literal that is not one of the pair's planes");
        literals.push_back(it->second);
        // The static literal is k times the row at s: its multiplier
        // applies to k row(s).
        Vec4 row = at(it->second, s);
        std::size_t nz = 0;
        while (is_zero(row[nz])) ++nz;
        lambda.push_back(rational_from_string(c["lambda"][i]) * v[nz] / row[nz]);
      }
      Conflict::Of of = of_from(c);
      auto lifted = lift_conflict(literals, lambda, s, closed && of == Conflict::Of::Both);
      if (!lifted)
        throw Turning_proof_missing(where_ + ": a conflict at t = " + to_string(s) +
                                    " has no multipliers polynomial in t");
      lifted->of = of;
      out.push_back(std::move(*lifted));
    }
  }
  return out;
}

namespace {

// The distinct real roots strictly inside (lo, hi) of a proof's multipliers
// and sums, ascending: where it may stop holding.
std::vector<Algebraic> roots_inside(const std::vector<Polynomial_conflict>& proof, const Algebraic& lo,
                                    const Algebraic& hi)
{
  std::vector<Algebraic> out;
  auto add = [&](const Time_poly& p) {
    std::vector<Rational> c = p.coefficients();
    while (!c.empty() && is_zero(c.back())) c.pop_back();
    if (c.size() < 2) return;   // a constant: no root
    for (Algebraic& r : Algebraic::real_roots(c, lo.lower(), hi.upper()))
      if (lo < r && r < hi) out.push_back(std::move(r));
  };
  for (const Polynomial_conflict& c : proof) {
    for (const Time_poly& l : c.lambda) add(l);
    add(c.slack());
  }
  std::sort(out.begin(), out.end(), [](const Algebraic& a, const Algebraic& b) { return a < b; });
  out.erase(std::unique(out.begin(), out.end(), [](const Algebraic& a, const Algebraic& b) { return a == b; }), out.end());
  return out;
}

} // namespace

// lo, the critical times of the piece [lo, piece_hi] below hi, and hi: of
// the pair's planes, or of each pair of pieces whose swept boxes meet when
// an object is a union of convex pieces (every term pair's conflicts are
// minors of its two pieces' rows, and each pair of pieces answers as one
// between its own critical times); when features_only, of two convex
// pieces' features only, and only of those near each other in the runs
// their apart cover leaves (rotation/Object_parts.h, part_pair_events: a
// cut is only where a proof may change, and each leaf's proof is checked
// on the whole leaf below). `restricted`: whether some pair's are its
// features' only (every mixed minor's may then cut further).
std::vector<Algebraic> Turning_prover::critical_cuts(const Rational& mid, const Rational& lo, const Rational& piece_hi,
                                                     const Algebraic& hi, bool features_only, bool& restricted) const
{
  std::vector<Algebraic> cuts{Algebraic(lo)};
  restricted = false;
  auto add = [&](const Rotating_object& a, const Rotating_object& b) {
    for (Algebraic& t : part_pair_events(a, b, pair_rows(a, b, mid), mid, lo, piece_hi, features_only, restricted))
      if (t < hi) cuts.push_back(std::move(t));
    return false;
  };
  if (one_member_pair()) add(a(), b());
  else for_parts_that_may_meet(*parts_a_, *parts_b_, add);
  std::sort(cuts.begin() + 1, cuts.end(), [](const Algebraic& x, const Algebraic& y) { return x < y; });
  cuts.erase(std::unique(cuts.begin() + 1, cuts.end(), [](const Algebraic& x, const Algebraic& y) { return x == y; }),
             cuts.end());
  cuts.push_back(hi);
  return cuts;
}

// The leaves of one piece between breakpoints, [lo, hi] (hi <= piece_hi,
// the breakpoint that ends the piece).
std::vector<Turning_prover::Leaf> Turning_prover::pose_piece(const Rational& lo, const Rational& piece_hi,
                                                             const Algebraic& hi, bool open_end)
{
  Rational mid = simplest_between(Algebraic(lo), hi);
  std::vector<Moving_plane> rows = pair_rows(a(), b(), mid);
  bool restricted = false;
  std::vector<Algebraic> cuts = critical_cuts(mid, lo, piece_hi, hi, feature_events_, restricted);
  std::optional<std::vector<Algebraic>> every;   // every mixed minor's cuts, made when a proof needs them
  std::vector<Leaf> leaves;
  std::size_t k = 0;   // the proof of interval k covers [cuts[k], ...]
  while (k + 1 < cuts.size()) {
    Work_budget::check();   // --max-seconds: each leaf's proof is a static proof of the posed pair
    Rational s = simplest_between(cuts[k], cuts[k + 1]);
    Leaf leaf{cuts[k], cuts[k + 1], proof_at(rows, s)};
    bool last = k + 2 == cuts.size();
    if (!valid(leaf.conflicts, leaf.lo, leaf.hi, open_end && last)) {
      // An interval (of the features) on which this proof's multipliers or
      // sum change sign: cut it where they do, or failing that at every
      // mixed minor's critical times inside it, and prove its first part
      // again. Each cut is a root of a minor of the pair's rows (Cramer's
      // cofactors), so the cutting ends.
      std::vector<Algebraic> inside = roots_inside(leaf.conflicts, leaf.lo, leaf.hi);
      if (inside.empty() && restricted) {
        bool all = false;
        if (!every) every = critical_cuts(mid, lo, piece_hi, hi, false, all);
        for (const Algebraic& t : *every)
          if (leaf.lo < t && t < leaf.hi) inside.push_back(t);
      }
      if (!inside.empty()) {
        cuts.insert(cuts.begin() + static_cast<std::ptrdiff_t>(k + 1), inside.begin(), inside.end());
        continue;
      }
      throw Turning_proof_missing(where_ + ": the proof at t = " + to_string(s) +
                                  " does not hold on its whole critical interval");
    }
    ++k;
    while (k + 1 < cuts.size() && valid(leaf.conflicts, leaf.lo, cuts[k + 1], open_end && k + 2 == cuts.size()))
      leaf.hi = cuts[++k];
    leaves.push_back(std::move(leaf));
  }
  return leaves;
}

// 8.3's members: when each object is a union of bounded convex pieces, or
// one such piece, and one has two or more. Its pieces are then the
// formula's members in order (the union's convex leaves, as the checker
// flattens the formula's top OR).
bool Turning_prover::by_members() const
{
  auto convex = [](const Object_parts& o) { return !o.pieces.empty() || o.whole.shape.convex_pieces.size() == 1; };
  return convex(*parts_a_) && convex(*parts_b_) && (!parts_a_->pieces.empty() || !parts_b_->pieces.empty());
}

// The pieces of time of a() and b() from tL until `until`, each a leaf.
json Turning_prover::pieces_until(const Algebraic& until, bool open_end)
{
  json pieces = json::array();
  Rational end = until.is_rational() ? until.rational() : until.upper();
  std::vector<Rational> ends = piece_ends(a(), b(), scene_.t_lo, end);
  for (std::size_t p = 0; p + 1 < ends.size() && Algebraic(ends[p]) < until; ++p) {
    Algebraic hi = Algebraic(ends[p + 1]) < until ? Algebraic(ends[p + 1]) : until;
    for (const Leaf& leaf : pose_piece(ends[p], ends[p + 1], hi, open_end && hi == until)) {
      json conflicts = json::array();
      for (const Polynomial_conflict& c : leaf.conflicts) conflicts.push_back(conflict_json(c, semantics_ == Semantics::closed));
      conflicts_ += leaf.conflicts.size();
      pieces.push_back(json{{"t", json::array({number_json(leaf.lo), number_json(leaf.hi)})},
                            {"proof", json{{"conflicts", conflicts}}}});
    }
  }
  return pieces;
}

json Turning_prover::prove(int a, int b, const Algebraic& until, bool open_end)
{
  parts_a_.emplace(scene_.objects[a], scene_.t_lo, scene_.t_hi);
  parts_b_.emplace(scene_.objects[b], scene_.t_lo, scene_.t_hi);
  std::string pair = "objects '" + scene_.objects[a].name + "' and '" + scene_.objects[b].name + "'";
  json out{{"until", number_json(until)}};
  if (open_end) out["open_end"] = true;
  if (!by_members()) {
    a_ = &parts_a_->whole, b_ = &parts_b_->whole;
    where_ = pair;
    out["pieces"] = pieces_until(until, open_end);
    return out;
  }
  json members = json::array();
  for (std::size_t i = 0; i < parts_a_->count(); ++i)
    for (std::size_t j = 0; j < parts_b_->count(); ++j) {
      a_ = &parts_a_->part(i), b_ = &parts_b_->part(j);
      where_ = pair + ", members " + std::to_string(i) + " and " + std::to_string(j);
      members.push_back(json{{"a", std::to_string(i)}, {"b", std::to_string(j)}, {"pieces", pieces_until(until, open_end)}});
    }
  out["members"] = members;
  return out;
}

} // namespace clash4d

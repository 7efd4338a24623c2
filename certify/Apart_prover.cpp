#include "certify/Apart_prover.h"

#include "model/Extrusion.h"
#include <algorithm>

namespace clash4d {
namespace {

using json = nlohmann::ordered_json;
using K = Rational_kernel;

// Formula (postfix over table entries) into term nodes over literal ids.
int add_formula(const Formula& f, int side, const std::vector<int>& literal_of, std::vector<Term_node>& nodes)
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

json conflict_json(const Conflict& c, const Literal_table& table, bool closed)
{
  json literals = json::array(), lambda = json::array();
  for (std::size_t i = 0; i < c.literals.size(); ++i) {
    literals.push_back(literal_json(table.form(c.literals[i])));
    lambda.push_back(to_string(c.lambda[i]));
  }
  json out{{"literals", literals}, {"lambda", lambda}};
  if (closed) out["of"] = c.of == Conflict::Of::A ? "A" : c.of == Conflict::Of::B ? "B" : "both";
  return out;
}

} // namespace

json literal_json(const Literal_coefficients& h)
{
  json out = json::array();
  for (const auto& x : h) out.push_back(to_string(x));
  return out;
}

Apart_prover::Apart_prover(const Scene& scene, Semantics semantics, std::uint64_t step_limit)
    : scene_(scene), semantics_(semantics), limit_(step_limit)
{
}

const Scene_model<K>& Apart_prover::model()
{
  if (!model_) model_ = Scene_model<K>::build(k_, scene_);
  return *model_;
}

json Apart_prover::prove(int a, int b, const Rational& until, bool strict_end)
{
  // Pieces: [tL, until] cut at the pair's velocity changes inside it.
  const Scene_model<K>& m = model();
  std::vector<Rational> cuts{m.t_lo, until};
  for (int i : {a, b})
    for (const Rational& t : m.objects[i].motion.times)
      if (m.t_lo < t && t < until) cuts.push_back(t);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  json pieces = json::array();
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
    pieces.push_back(piece(a, b, cuts[i], cuts[i + 1], strict_end && i + 2 == cuts.size()));
  json out{{"until", to_string(until)}};
  if (strict_end) out["open_end"] = true;
  out["pieces"] = pieces;
  return out;
}

// One piece: the pair's extrusion on it (no shear, no S-bounds), its
// literals, and the conflicts that close off every term.
json Apart_prover::piece(int a, int b, const Rational& lo, const Rational& hi, bool strict_end)
{
  const Time_span<Rational> span{lo, hi};
  const Scene_model<K>& m = model();
  auto everything = [&](int i) { return std::vector<Box<Rational, 3>>(m.objects[i].csg.nodes.size()); };
  Moving_object<Rational> A = moving_on(m, a, span, everything(a)), B = moving_on(m, b, span, everything(b));
  Motion_groups<Rational> groups;
  const Vector3<Rational> no_shear{Rational(0), Rational(0), Rational(0)};
  auto table = Extrusion<K>::pair_table(A, B, no_shear, {false, false, false}, false, groups);
  Pair_formula f = Extrusion<K>::pair_formula(A, B);

  Literal_table literals;
  std::vector<int> literal_of;
  for (const auto& h : table) literal_of.push_back(literals.id({h.n[0], h.n[1], h.n[2], h.n[3], h.c}));
  std::vector<int> slab{literals.id({Rational(0), Rational(0), Rational(0), Rational(-1), lo}),
                        literals.id({Rational(0), Rational(0), Rational(0), Rational(1), -hi})};
  std::vector<Term_node> nodes;
  int ra = add_formula(f.a(), 0, literal_of, nodes), rb = add_formula(f.b(), 1, literal_of, nodes);
  nodes.push_back({Term_node::Op::And, -1, 0, {ra, rb}});
  const int root = static_cast<int>(nodes.size()) - 1;
  Term_search search(literals, std::move(nodes), root, slab, semantics_, strict_end,
                     limit_ - std::min(limit_, steps_));
  std::vector<Conflict> conflicts = search.run();
  steps_ += search.steps();
  conflicts_ += conflicts.size();
  json list = json::array();
  for (const auto& c : conflicts) list.push_back(conflict_json(c, literals, semantics_ == Semantics::closed));
  return json{{"t", json::array({to_string(lo), to_string(hi)})}, {"proof", json{{"conflicts", list}}}};
}

} // namespace clash4d

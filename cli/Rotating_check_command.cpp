#include "cli/Rotating_check_command.h"

#include "rotation/Critical_times.h"
#include "rotation/Rotating_check.h"
#include "scene/Rotation_refusal.h"
#include "scene/Number_json.h"
#include "scene/Printable.h"

#include <nlohmann/json.hpp>
#include <ostream>
#include <utility>
#include <vector>

namespace clash4d {

namespace {

using json = nlohmann::ordered_json;

// The double instantiation's numbers are doubles: printed as their shortest
// decimals, as the translation pipeline's double answers are (every one is
// a double's exact value, so nothing is lost).
struct Number_format {
  bool decimal = false;
  json operator()(const Algebraic& x) const { return decimal ? json(shortest_decimal(x.to_double())) : number_json(x); }
  std::string text(const Algebraic& x) const { return decimal ? shortest_decimal(x.to_double()) : x.to_text(); }
};

json point_json(const Algebraic* x, int n, const Number_format& f)
{
  json p = json::array();
  for (int i = 0; i < n; ++i) p.push_back(f(x[i]));
  return p;
}

json contact_json(const Rotating_answer& a, const Number_format& f)
{
  std::array<Algebraic, 4> p = {a.contact[0], a.contact[1], a.contact[2], a.t_star};
  return json{{"t", f(a.t_star)}, {"point", point_json(p.data(), 4, f)}, {"at_start", a.at_start}};
}

// The counts --stats gives after its method, by name (the text and the
// JSON print the same ones).
std::vector<std::pair<const char*, std::size_t>> stat_counts(const Rotating_check_answer& a)
{
  const Slice_counts& c = a.counts;
  return {{"pairs_examined", a.pairs_examined},     {"piece_pairs", c.piece_pairs},
          {"apart_intervals", c.apart_intervals},   {"sliced_intervals", c.sliced_intervals},
          {"critical_times", c.critical_times},     {"static_questions", c.static_questions},
          {"apart_samples", c.apart_samples}};
}

json answer_json(const Rotating_check_answer& a, const Check_options& o, bool stats, double tolerance)
{
  json j = {{"collide", a.collide}, {"number", a.number}, {"semantics", semantics_name(a.semantics)}};
  Number_format f{a.number == "double"};
  if (f.decimal) j["tolerance"] = tolerance;
  auto witness_json = [&](const Rotating_pair_answer& p) {
    return json{{"objects", {p.a, p.b}}, {"point", point_json(p.answer.witness.data(), 4, f)},
                {"verified", p.answer.witness_verified}};
  };
  const Rotating_pair_answer* main = a.reported();
  if (main) j["witness"] = witness_json(*main);
  if (main && o.earliest) {
    j["earliest"] = contact_json(main->answer, f);
    j["earliest"]["objects"] = {main->a, main->b};
  }
  if (o.all_pairs) {
    j["pairs"] = json::array();
    for (const auto& p : a.pairs) {
      json e = {{"objects", {p.a, p.b}}, {"witness", witness_json(p)}};
      if (o.earliest) e["earliest"] = contact_json(p.answer, f);
      j["pairs"].push_back(e);
    }
  }
  if (stats) {
    j["stats"] = {{"method", "time slices (rotation)"}};
    for (const auto& [name, count] : stat_counts(a)) j["stats"][name] = count;
  }
  return j;
}

std::string point_text(const std::array<Algebraic, 4>& p, const Number_format& f)
{
  return "x = " + f.text(p[0]) + ", y = " + f.text(p[1]) + ", z = " + f.text(p[2]) + ", t = " + f.text(p[3]);
}

void print_text(const Rotating_check_answer& a, const Check_options& o, bool stats, std::ostream& out)
{
  Number_format f{a.number == "double"};
  bool closed = a.semantics == Semantics::closed;
  std::string how = a.number + (closed ? ", closed semantics" : "") + ", with rotation";
  const Rotating_pair_answer* main = a.reported();
  if (!a.collide) out << "no collision (" << how << (closed ? ": the closed objects do not meet" : "") << ")\n";
  for (const auto& p : a.pairs) {
    if (!o.all_pairs && &p != main) continue;
    out << (closed ? "contact or collision: " : "collision: ") << printable(p.a) << " and " << printable(p.b) << " ("
        << how << ")\n";
    out << (closed ? "  common point: " : "  witness: ") << point_text(p.answer.witness, f) << "\n";
    if (p.answer.earliest)
      out << (closed ? "  first contact: t* = " : "  earliest: t* = ") << f.text(p.answer.t_star) << " at x = "
          << f.text(p.answer.contact[0]) << ", y = " << f.text(p.answer.contact[1])
          << ", z = " << f.text(p.answer.contact[2])
          << (p.answer.at_start ? "  (already in contact at the start of the span)" : "") << "\n";
  }
  if (o.earliest && main && o.all_pairs) out << "earliest pair: " << printable(main->a) << " and " << printable(main->b) << "\n";
  if (!stats) return;
  out << "stats:\n  method: time slices (rotation)\n";
  for (const auto& [name, count] : stat_counts(a)) out << "  " << name << ": " << count << "\n";
}

} // namespace

int run_rotating_check(const Scene& scene, const Rotating_check_request& r, std::ostream& out)
{
  Rotating_check_answer answer;
  try {
    answer = check_rotating(scene, r.options, r.number, r.tolerance);
  } catch (const Rotation_unsupported& e) {
    refuse_rotation(scene, std::string("not decided: ") + e.what());
  } catch (const Minor_limit& e) {
    throw Input_error("objects", e.what(), CLASH4D_EXIT_LIMIT);
  }
  if (r.before_print) r.before_print(answer);
  if (r.options.json) out << answer_json(answer, r.options, r.stats, r.tolerance).dump(2) << "\n";
  else print_text(answer, r.options, r.stats, out);
  return answer.collide ? 1 : 0;
}

} // namespace clash4d

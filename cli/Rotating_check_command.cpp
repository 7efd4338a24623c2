#include "cli/Rotating_check_command.h"

#include "rotation/Critical_times.h"
#include "rotation/Rotating_check.h"
#include "scene/Rotation_refusal.h"
#include "scene/Number_json.h"
#include "scene/Printable.h"

#include <nlohmann/json.hpp>
#include <ostream>

namespace clash4d {

namespace {

using json = nlohmann::ordered_json;

json point_json(const Algebraic* x, int n)
{
  json p = json::array();
  for (int i = 0; i < n; ++i) p.push_back(number_json(x[i]));
  return p;
}

json contact_json(const Rotating_answer& a)
{
  std::array<Algebraic, 4> p = {a.contact[0], a.contact[1], a.contact[2], a.t_star};
  return json{{"t", number_json(a.t_star)}, {"point", point_json(p.data(), 4)}, {"at_start", a.at_start}};
}

json answer_json(const Rotating_check_answer& a, const Check_options& o, bool stats)
{
  json j = {{"collide", a.collide}, {"number", a.number}, {"semantics", semantics_name(a.semantics)}};
  auto witness_json = [](const Rotating_pair_answer& p) {
    return json{{"objects", {p.a, p.b}}, {"point", point_json(p.answer.witness.data(), 4)},
                {"verified", p.answer.witness_verified}};
  };
  const Rotating_pair_answer* main = a.reported();
  if (main) j["witness"] = witness_json(*main);
  if (main && o.earliest) {
    j["earliest"] = contact_json(main->answer);
    j["earliest"]["objects"] = {main->a, main->b};
  }
  if (o.all_pairs) {
    j["pairs"] = json::array();
    for (const auto& p : a.pairs) {
      json e = {{"objects", {p.a, p.b}}, {"witness", witness_json(p)}};
      if (o.earliest) e["earliest"] = contact_json(p.answer);
      j["pairs"].push_back(e);
    }
  }
  if (stats) j["stats"] = {{"method", "time slices (rotation)"}, {"pairs_examined", a.pairs_examined}};
  return j;
}

std::string point_text(const std::array<Algebraic, 4>& p)
{
  return "x = " + p[0].to_text() + ", y = " + p[1].to_text() + ", z = " + p[2].to_text() + ", t = " + p[3].to_text();
}

void print_text(const Rotating_check_answer& a, const Check_options& o, bool stats, std::ostream& out)
{
  bool closed = a.semantics == Semantics::closed;
  std::string how = a.number + (closed ? ", closed semantics" : "") + ", with rotation";
  const Rotating_pair_answer* main = a.reported();
  if (!a.collide) out << "no collision (" << how << (closed ? ": the closed objects do not meet" : "") << ")\n";
  for (const auto& p : a.pairs) {
    if (!o.all_pairs && &p != main) continue;
    out << (closed ? "contact or collision: " : "collision: ") << printable(p.a) << " and " << printable(p.b) << " ("
        << how << ")\n";
    out << (closed ? "  common point: " : "  witness: ") << point_text(p.answer.witness) << "\n";
    if (p.answer.earliest)
      out << (closed ? "  first contact: t* = " : "  earliest: t* = ") << p.answer.t_star.to_text() << " at x = "
          << p.answer.contact[0].to_text() << ", y = " << p.answer.contact[1].to_text()
          << ", z = " << p.answer.contact[2].to_text()
          << (p.answer.at_start ? "  (already in contact at the start of the span)" : "") << "\n";
  }
  if (o.earliest && main && o.all_pairs) out << "earliest pair: " << printable(main->a) << " and " << printable(main->b) << "\n";
  if (stats) out << "stats:\n  method: time slices (rotation)\n  pairs_examined: " << a.pairs_examined << "\n";
}

} // namespace

int run_rotating_check(const Scene& scene, const Rotating_check_request& r, std::ostream& out)
{
  if (r.number == "double")
    refuse_rotation(scene, "--number double does not decide motions with rotation yet (use exact or rational)");
  Rotating_check_answer answer;
  try {
    answer = check_rotating(scene, r.options, r.number);
  } catch (const Rotation_unsupported& e) {
    refuse_rotation(scene, std::string("not decided: ") + e.what());
  } catch (const Minor_limit& e) {
    throw Input_error("objects", e.what(), CLASH4D_EXIT_LIMIT);
  }
  if (r.options.json) out << answer_json(answer, r.options, r.stats).dump(2) << "\n";
  else print_text(answer, r.options, r.stats, out);
  return answer.collide ? 1 : 0;
}

} // namespace clash4d

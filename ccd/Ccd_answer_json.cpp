#include "ccd/Ccd_answer_json.h"

#include "scene/Number_json.h"

namespace clash4d {

nlohmann::ordered_json ccd_number_json(const Ccd_number& x)
{
  if (const Algebraic* a = std::get_if<Algebraic>(&x)) return number_json(*a);
  return shortest_decimal(std::get<double>(x));
}

nlohmann::ordered_json ccd_answer_json(std::size_t index, const Ccd_answer& a, bool earliest)
{
  nlohmann::ordered_json j{{"index", index}, {"collide", a.collide}};
  if (!earliest) return j;
  if (!a.earliest) {
    j["t"] = nullptr;
    return j;
  }
  j["t"] = ccd_number_json(a.earliest->t);
  j["uv"] = {ccd_number_json(a.earliest->u), ccd_number_json(a.earliest->v)};
  return j;
}

} // namespace clash4d

#include "scene/Number_json.h"
#include "scene/Number_text.h"

#include <charconv>
#include <cstdio>

namespace clash4d {

nlohmann::ordered_json number_json(const Algebraic& x)
{
  if (x.is_rational()) return to_string(x.rational());
  nlohmann::ordered_json poly = nlohmann::ordered_json::array();
  for (const mpz_class& c : x.polynomial()) poly.push_back(c.get_str());
  auto [lo, hi] = x.short_interval();
  return {{"poly", poly}, {"between", {to_string(lo), to_string(hi)}}, {"approx", x.approx()}};
}

std::string shortest_decimal(double x)
{
  char buffer[64];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

std::string with_decimal(const std::string& text)
{
  if (text.find('/') == std::string::npos) return text;
  Number_parse n = parse_number_text(text, true);
  if (!n.ok) return text;
  char decimal[32];
  std::snprintf(decimal, sizeof decimal, "%.6g", round_to_nearest(n.value));
  return text + " (~" + decimal + ")";
}

} // namespace clash4d

#include "scene/Number_json.h"

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

} // namespace clash4d

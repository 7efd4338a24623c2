#include "compare/Decimal_text.h"

#include "numbers/Rational.h"
#include "scene/Number_text.h"
#include <cmath>
#include <cstdio>

namespace clash4d {

std::optional<double> decimal_value(const std::string& text)
{
  std::string number = text;
  // An algebraic number's text ends with its nearest double.
  std::size_t approx = text.rfind(" ~ ");
  if (text.rfind("root of", 0) == 0 && approx != std::string::npos) number = text.substr(approx + 3);
  Number_parse p = parse_number_text(number, true);
  if (!p.ok) return std::nullopt;
  double d = round_to_nearest(p.value);
  if (!std::isfinite(d)) return std::nullopt;
  return d;
}

std::string decimal_text(const std::string& text)
{
  // An integer reads as itself, however long.
  if (!text.empty() && text.find_first_not_of("-0123456789") == std::string::npos) return "";
  std::optional<double> d = decimal_value(text);
  if (!d) return "";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g", *d);
  if (text == buffer) return "";
  return std::string("\xE2\x89\x88 ") + buffer;
}

std::string with_decimal(const std::string& text)
{
  if (text.rfind("root of", 0) == 0) return text;
  std::string d = decimal_text(text);
  return d.empty() ? text : text + " (" + d + ")";
}

} // namespace clash4d

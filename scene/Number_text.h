// Reading numbers exactly from their text (spec: "Numbers").
#ifndef CLASH4D_SCENE_NUMBER_TEXT_H
#define CLASH4D_SCENE_NUMBER_TEXT_H

#include "numbers/Rational.h"
#include <string>

namespace clash4d {

// Limits that keep absurd numbers from costing gigabytes (exit 3 when hit).
constexpr std::size_t CLASH4D_MAX_NUMBER_CHARS = 1000;
constexpr long CLASH4D_MAX_EXPONENT = 1000;

struct Number_parse {
  bool ok = false;
  bool limit = false;     // refused for size, not for form
  std::string error;      // why it is not a number, when !ok
  Rational value;
};

// Integers, decimals with an optional exponent (JSON's grammar), and when
// allow_fraction, p/q with integer p and q (q != 0). Never through a double.
Number_parse parse_number_text(const std::string& text, bool allow_fraction);

} // namespace clash4d

#endif

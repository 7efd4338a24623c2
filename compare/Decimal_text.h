// The decimal shown beside an exact number in the report (about 6
// significant digits): display only, never read back into an answer.
#ifndef CLASH4D_COMPARE_DECIMAL_TEXT_H
#define CLASH4D_COMPARE_DECIMAL_TEXT_H

#include <optional>
#include <string>

namespace clash4d {

// The nearest double to a number as the comparison writes it: an integer,
// a decimal, p/q, or an algebraic number's "root of [...] in (lo, hi) ~ d"
// (Algebraic::to_text, whose d is already its nearest double); none for
// any other text.
std::optional<double> decimal_value(const std::string& text);

// "≈ 1.18302" for text, or empty when text has no value, is an integer or
// already reads as that decimal (a short decimal).
std::string decimal_text(const std::string& text);

// The text for people, with its decimal beside it: "p/q (≈ 1.18302)"; an
// integer, a short decimal or an algebraic number's text (which carries
// its own "~ d") as it is. compare's text output and the report use it.
std::string with_decimal(const std::string& text);

} // namespace clash4d

#endif

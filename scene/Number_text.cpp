#include "scene/Number_text.h"

#include <cctype>
#include <gmp.h>

namespace clash4d {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// digits * 10^exp10 as an exact rational.
Rational scaled(const std::string& digits, long exp10, bool negative)
{
  mpz_t num, den;
  mpz_init_set_str(num, digits.c_str(), 10);
  mpz_init_set_ui(den, 1);
  mpz_t power;
  mpz_init(power);
  mpz_ui_pow_ui(power, 10, static_cast<unsigned long>(exp10 < 0 ? -exp10 : exp10));
  if (exp10 < 0) mpz_mul(den, den, power); else mpz_mul(num, num, power);
  if (negative) mpz_neg(num, num);
  Rational q;
  mpq_set_num(q.mpq(), num);
  mpq_set_den(q.mpq(), den);
  mpq_canonicalize(q.mpq());
  mpz_clear(num); mpz_clear(den); mpz_clear(power);
  return q;
}

Number_parse fail(const std::string& why)
{
  Number_parse r;
  r.error = why;
  return r;
}

// JSON number grammar: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
Number_parse parse_decimal(const std::string& s)
{
  std::size_t i = 0, n = s.size();
  bool negative = false;
  if (i < n && s[i] == '-') { negative = true; ++i; }
  std::size_t int_start = i;
  while (i < n && is_digit(s[i])) ++i;
  if (i == int_start) return fail("expected a digit");
  if (i - int_start > 1 && s[int_start] == '0') return fail("leading zero");
  std::string digits = s.substr(int_start, i - int_start);
  long frac_len = 0;
  if (i < n && s[i] == '.') {
    std::size_t frac_start = ++i;
    while (i < n && is_digit(s[i])) ++i;
    if (i == frac_start) return fail("expected a digit after '.'");
    digits += s.substr(frac_start, i - frac_start);
    frac_len = static_cast<long>(i - frac_start);
  }
  long exponent = 0;
  if (i < n && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    bool exp_negative = false;
    if (i < n && (s[i] == '+' || s[i] == '-')) exp_negative = s[i++] == '-';
    std::size_t exp_start = i;
    while (i < n && is_digit(s[i])) ++i;
    if (i == exp_start) return fail("expected a digit in the exponent");
    std::string exp_digits = s.substr(exp_start, i - exp_start);
    std::size_t nz = exp_digits.find_first_not_of('0');
    exp_digits = nz == std::string::npos ? "0" : exp_digits.substr(nz);
    if (exp_digits.size() > 6 || std::stol(exp_digits) > CLASH4D_MAX_EXPONENT) {
      Number_parse r = fail("exponent beyond the limit of +-" + std::to_string(CLASH4D_MAX_EXPONENT));
      r.limit = true;
      return r;
    }
    exponent = std::stol(exp_digits) * (exp_negative ? -1 : 1);
  }
  if (i != n) return fail("unexpected '" + s.substr(i, 1) + "'");
  Number_parse r;
  r.ok = true;
  r.value = scaled(digits, exponent - frac_len, negative);
  return r;
}

Number_parse parse_integer(const std::string& s, bool allow_sign)
{
  std::size_t i = 0;
  bool negative = false;
  if (allow_sign && i < s.size() && s[i] == '-') { negative = true; ++i; }
  std::string digits = s.substr(i);
  if (digits.empty()) return fail("expected an integer");
  for (char c : digits)
    if (!is_digit(c)) return fail("unexpected '" + std::string(1, c) + "' in a fraction");
  Number_parse r;
  r.ok = true;
  r.value = scaled(digits, 0, negative);
  return r;
}

} // namespace

Number_parse parse_number_text(const std::string& text, bool allow_fraction)
{
  if (text.size() > CLASH4D_MAX_NUMBER_CHARS) {
    Number_parse r = fail("number longer than the limit of " +
                          std::to_string(CLASH4D_MAX_NUMBER_CHARS) + " characters");
    r.limit = true;
    return r;
  }
  std::size_t slash = text.find('/');
  if (slash == std::string::npos) return parse_decimal(text);
  if (!allow_fraction) return fail("fractions must be written as strings");
  Number_parse p = parse_integer(text.substr(0, slash), true);
  if (!p.ok) return fail("'" + text + "' is not a number: " + p.error);
  Number_parse q = parse_integer(text.substr(slash + 1), false);
  if (!q.ok) return fail("'" + text + "' is not a number: " + q.error);
  if (CGAL::is_zero(q.value)) return fail("zero denominator in '" + text + "'");
  p.value /= q.value;
  return p;
}

} // namespace clash4d

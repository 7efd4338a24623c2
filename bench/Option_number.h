// A benchmark option's number, read from its whole text: "--repeat 3x",
// "--seed -1" and "--min-seconds inf" are refused with a message naming the
// option, where std::stoi alone would read 3, std::stoul a wrapped
// 2^64 - 1, and a timing loop would wait for ever.
#ifndef CLASH4D_BENCH_OPTION_NUMBER_H
#define CLASH4D_BENCH_OPTION_NUMBER_H

#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace clash4d {

// T: int, unsigned long or double (finite). Throws std::invalid_argument
// "<option> <text>: not a number in range".
template <class T>
T option_number(const std::string& option, const std::string& text)
{
  static_assert(std::is_same_v<T, int> || std::is_same_v<T, unsigned long> || std::is_same_v<T, double>,
                "option_number: int, unsigned long or double");
  std::size_t used = 0;
  try {
    T v{};
    if constexpr (std::is_same_v<T, int>) v = std::stoi(text, &used);
    else if constexpr (std::is_same_v<T, double>) v = std::stod(text, &used);
    else if (text.find('-') == std::string::npos) v = std::stoul(text, &used);   // stoul would wrap "-1"
    bool finite = true;
    if constexpr (std::is_same_v<T, double>) finite = std::isfinite(v);
    if (used == text.size() && !text.empty() && finite) return v;
  } catch (const std::logic_error&) {   // std::invalid_argument, std::out_of_range
  }
  throw std::invalid_argument(option + " " + text + ": not a number in range");
}

} // namespace clash4d

#endif

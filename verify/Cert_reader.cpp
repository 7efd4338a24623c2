#include "verify/Cert_reader.h"
#include <algorithm>
#include <cctype>

namespace clash4d::verifier {
namespace {

[[noreturn]] void unreadable(const std::string& where, const std::string& reason)
{
  throw Cert_failure(CLASH4D_VERIFY_UNREADABLE, where, reason);
}

bool digits(const std::string& s, std::size_t from, std::size_t to)
{
  return from < to && std::all_of(s.begin() + from, s.begin() + to, [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

// Section 1: an optional minus, digits, and for fractions "/" and digits.
mpq_class parse(const Json& j, const std::string& at, bool integer)
{
  if (!j.is_string()) unreadable(at, std::string("expected a number as a string, not ") + j.type_name());
  const std::string& s = j.get_ref<const std::string&>();
  std::size_t start = !s.empty() && s[0] == '-' ? 1 : 0, slash = s.find('/');
  bool ok = slash == std::string::npos ? digits(s, start, s.size())
                                       : !integer && digits(s, start, slash) && digits(s, slash + 1, s.size());
  if (!ok) unreadable(at, "'" + s + "' is not " + (integer ? "an integer" : "an integer or a fraction p/q"));
  mpq_class q;
  if (q.set_str(s, 10) != 0 || q.get_den() == 0) unreadable(at, "'" + s + "' has a zero denominator");
  q.canonicalize();
  return q;
}

} // namespace

void reject(const std::string& where, const std::string& reason)
{
  throw Cert_failure(CLASH4D_VERIFY_REJECTED, where, reason);
}

std::string key_at(const std::string& at, const std::string& key) { return at.empty() ? key : at + "." + key; }
std::string index_at(const std::string& at, std::size_t i) { return at + "[" + std::to_string(i) + "]"; }

void expect_keys(const Json& j, const std::string& at, std::initializer_list<const char*> required,
                 std::initializer_list<const char*> optional)
{
  if (!j.is_object()) unreadable(at.empty() ? "(top level)" : at, std::string("expected an object, not ") + j.type_name());
  for (const char* k : required)
    if (!j.contains(k)) unreadable(at.empty() ? "(top level)" : at, std::string("missing key '") + k + "'");
  for (auto it = j.begin(); it != j.end(); ++it) {
    auto is = [&](const char* k) { return it.key() == k; };
    if (std::none_of(required.begin(), required.end(), is) && std::none_of(optional.begin(), optional.end(), is))
      reject(key_at(at, it.key()), "unknown key '" + it.key() + "'");
  }
}

const Json& read_array(const Json& j, const std::string& at, long size)
{
  if (!j.is_array()) unreadable(at, std::string("expected an array, not ") + j.type_name());
  if (size >= 0 && j.size() != static_cast<std::size_t>(size))
    unreadable(at, "expected " + std::to_string(size) + " elements, not " + std::to_string(j.size()));
  return j;
}

bool read_bool(const Json& j, const std::string& at)
{
  if (!j.is_boolean()) unreadable(at, std::string("expected true or false, not ") + j.type_name());
  return j.get<bool>();
}

std::string read_text(const Json& j, const std::string& at)
{
  if (!j.is_string()) unreadable(at, std::string("expected a string, not ") + j.type_name());
  return j.get<std::string>();
}

mpq_class read_number(const Json& j, const std::string& at) { return parse(j, at, false); }

Point4 read_point(const Json& j, const std::string& at)
{
  Point4 p;
  for (std::size_t i = 0; i < 4; ++i) p[i] = read_number(read_array(j, at, 4)[i], index_at(at, i));
  return p;
}

std::array<mpz_class, 5> read_literal(const Json& j, const std::string& at)
{
  std::array<mpz_class, 5> l;
  for (std::size_t i = 0; i < 5; ++i) l[i] = parse(read_array(j, at, 5)[i], index_at(at, i), true).get_num();
  if (std::all_of(l.begin(), l.end(), [](const mpz_class& c) { return c == 0; })) reject(at, "a literal must not be all zero");
  return l;
}

std::string text(const mpq_class& q) { return q.get_str(); }

std::string text(const Point4& p)
{
  return "(" + text(p[0]) + ", " + text(p[1]) + ", " + text(p[2]) + ", " + text(p[3]) + ")";
}

std::string text(const Literal& l)
{
  return "[" + l[0].get_str() + "," + l[1].get_str() + "," + l[2].get_str() + "," + l[3].get_str() + "," + l[4].get_str() + "]";
}

} // namespace clash4d::verifier

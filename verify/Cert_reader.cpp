#include "verify/Cert_reader.h"
#include <algorithm>
#include <cctype>
#include <set>

namespace clash4d::verifier {
namespace {

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

std::string line_column(const std::string& text, std::size_t byte)
{
  std::size_t line = 1, col = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') line++, col = 1;
    else ++col;
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(col);
}

// nlohmann's DOM builder, with the rules it does not have: a key twice, a
// JSON number, nesting too deep. Each failure keeps its JSON path.
class Cert_sax : public nlohmann::json_sax<Json> {
public:
  explicit Cert_sax(Json& result) : dom_(result, false) {}
  int exit_code = CLASH4D_VERIFY_UNREADABLE;
  std::string where, reason;

  bool null() override { return value() && dom_.null(); }
  bool boolean(bool b) override { return value() && dom_.boolean(b); }
  bool number_integer(number_integer_t) override { return number(); }
  bool number_unsigned(number_unsigned_t) override { return number(); }
  bool number_float(number_float_t, const string_t&) override { return number(); }
  bool string(string_t& s) override { return value() && dom_.string(s); }
  bool binary(binary_t&) override { return fail(path(), "binary values are not JSON"); }
  bool start_object(std::size_t n) override { return open(false) && dom_.start_object(n); }
  bool key(string_t& k) override
  {
    Level& top = levels_.back();
    top.key = k;
    if (!top.keys.insert(k).second) return fail(path(), "the key '" + k + "' appears twice in one object");
    return dom_.key(k);
  }
  bool end_object() override { return close() && dom_.end_object(); }
  bool start_array(std::size_t n) override { return open(true) && dom_.start_array(n); }
  bool end_array() override { return close() && dom_.end_array(); }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& ex) override
  {
    std::string what = ex.what();   // a number beyond double's range is a number too
    if (what.find("number overflow") != std::string::npos) return number();
    return fail(line_column(*text_, position > 0 ? position - 1 : 0), what);
  }
  void set_text(const std::string* text) { text_ = text; }

private:
  struct Level {
    bool array;
    std::size_t index = 0;
    std::string key;
    std::set<std::string> keys;
  };
  nlohmann::detail::json_sax_dom_parser<Json> dom_;
  std::vector<Level> levels_;
  const std::string* text_ = nullptr;

  std::string path() const
  {
    std::string at;
    for (const Level& l : levels_) at = l.array ? index_at(at, l.index) : key_at(at, l.key);
    if (at.size() > 200) at = at.substr(0, 100) + " ... " + at.substr(at.size() - 80);   // deep nesting: its ends
    return at.empty() ? "(top level)" : at;
  }
  bool fail(const std::string& w, const std::string& r)
  {
    if (reason.empty()) where = w, reason = r;
    return false;
  }
  bool value()
  {
    if (!levels_.empty() && levels_.back().array) ++levels_.back().index;
    return true;
  }
  // An array level's index is the element being read (counted after it).
  bool number() { return fail(path(), "expected a number as a string, not a JSON number (section 1)"); }
  bool open(bool array)
  {
    if (levels_.size() >= CLASH4D_VERIFY_MAX_NESTING) {
      exit_code = CLASH4D_VERIFY_LIMIT;
      return fail(path(), "nesting deeper than the limit of " + std::to_string(CLASH4D_VERIFY_MAX_NESTING) + " levels");
    }
    levels_.push_back({array, 0, {}, {}});
    return true;
  }
  bool close()
  {
    levels_.pop_back();
    return value();
  }
};

} // namespace

Json parse_certificate(const std::string& text)
{
  std::size_t nul = text.find('\0');   // nlohmann would end the text there
  if (nul != std::string::npos) unreadable(line_column(text, nul), "a NUL byte (section 1)");
  Json result;
  Cert_sax sax(result);
  sax.set_text(&text);
  if (!Json::sax_parse(text, &sax, nlohmann::json::input_format_t::json, true) || !sax.reason.empty())
    throw Cert_failure(sax.exit_code, sax.where, sax.reason.empty() ? "not JSON" : sax.reason);
  return result;
}

void unreadable(const std::string& where, const std::string& reason)
{
  throw Cert_failure(CLASH4D_VERIFY_UNREADABLE, where, reason);
}

void reject(const std::string& where, const std::string& reason)
{
  throw Cert_failure(CLASH4D_VERIFY_REJECTED, where, reason);
}

void reject_past_step_limit(const std::string& where, const std::string& limit)
{
  throw Cert_failure(CLASH4D_VERIFY_REJECTED, where, limit + " (the limit for one certificate): not checked", true);
}

std::string plural(std::size_t n, const char* what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); }

std::pair<int, int> pair_key(int a, int b) { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); }

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
mpz_class read_integer(const Json& j, const std::string& at) { return parse(j, at, true).get_num(); }

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

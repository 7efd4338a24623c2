// Reading the certificate's JSON by the letter of docs/certificate-format.md:
// numbers are strings (section 1), unknown keys are errors (section 3).
#ifndef CLASH4D_VERIFY_CERT_READER_H
#define CLASH4D_VERIFY_CERT_READER_H

#include "verify/Object_model.h"
#include <nlohmann/json.hpp>
#include <initializer_list>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

namespace clash4d::verifier {

using Json = nlohmann::json;

constexpr int CLASH4D_VERIFY_REJECTED = 1;     // the certificate does not prove its claim
constexpr int CLASH4D_VERIFY_UNREADABLE = 2;   // not a certificate of this format
constexpr int CLASH4D_VERIFY_LIMIT = 3;        // beyond a limit of section 6
constexpr int CLASH4D_VERIFY_INTERNAL = 4;     // the checker failed: nothing proved
// Section 6: JSON nested deeper is refused (splits stop at 2,000 before).
constexpr std::size_t CLASH4D_VERIFY_MAX_NESTING = 5000;

// The first failure: its exit status, its JSON path, the reason.
class Cert_failure : public std::runtime_error {
public:
  Cert_failure(int exit_code, std::string where, const std::string& reason, bool past_step_limit = false)
    : std::runtime_error(reason), exit_code_(exit_code), where_(std::move(where)), past_step_limit_(past_step_limit) {}
  int exit_code() const { return exit_code_; }
  const std::string& where() const { return where_; }
  // Stopped at the step limit of section 4: nothing was refuted, the rest
  // was not checked (exit 1 all the same: a certificate must be provable
  // within it).
  bool past_step_limit() const { return past_step_limit_; }
private:
  int exit_code_;
  std::string where_;
  bool past_step_limit_;
};

// The certificate's text as JSON by section 1's reading rules: UTF-8, one
// leading byte-order mark skipped, nothing but JSON whitespace after the
// value, no NUL byte, no key twice in an object, no JSON number anywhere
// (numbers are strings), nesting at most CLASH4D_VERIFY_MAX_NESTING. Throws
// Cert_failure (2, or 3 for the nesting) with the place.
Json parse_certificate(const std::string& text);

[[noreturn]] void unreadable(const std::string& where, const std::string& reason);   // exit 2
[[noreturn]] void reject(const std::string& where, const std::string& reason);
// The term enumeration of a leaf at `where` passed its step limit (section 4).
[[noreturn]] void reject_past_step_limit(const std::string& where, const std::string& limit);

// "1 term", "2 terms".
std::string plural(std::size_t n, const char* what);
// A pair of objects in a map, the lower index first.
std::pair<int, int> pair_key(int a, int b);

// JSON paths: "pairs[2].apart" and so on.
std::string key_at(const std::string& at, const std::string& key);
std::string index_at(const std::string& at, std::size_t i);

// j must be an object holding every required key (else unreadable) and no
// key outside required and optional (else rejected: an unknown key).
void expect_keys(const Json& j, const std::string& at, std::initializer_list<const char*> required,
                 std::initializer_list<const char*> optional = {});
// An array, of exactly `size` elements when size >= 0.
const Json& read_array(const Json& j, const std::string& at, long size = -1);
bool read_bool(const Json& j, const std::string& at);
std::string read_text(const Json& j, const std::string& at);
mpq_class read_number(const Json& j, const std::string& at);   // "p/q" or "p"
mpz_class read_integer(const Json& j, const std::string& at);  // "p"
Point4 read_point(const Json& j, const std::string& at);
// A literal as written: five integer strings, not all zero.
std::array<mpz_class, 5> read_literal(const Json& j, const std::string& at);

std::string text(const mpq_class& q);                            // "p/q" or "p", lowest terms
std::string text(const Point4& p);                               // "(x, y, z, t)"
std::string text(const Literal& l);                              // "[a,b,c,e_t,e]"

} // namespace clash4d::verifier

#endif

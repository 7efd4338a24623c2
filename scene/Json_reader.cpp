#include "scene/Json_reader.h"
#include "scene/Input_error.h"
#include "scene/Number_text.h"

#include <cerrno>
#include <cstdint>
#include <fcntl.h>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <unistd.h>

namespace clash4d {

const char* kind_name(Json_value::Kind k)
{
  switch (k) {
    case Json_value::Kind::Null: return "null";
    case Json_value::Kind::Boolean: return "a boolean";
    case Json_value::Kind::Number: return "a number";
    case Json_value::Kind::String: return "a string";
    case Json_value::Kind::Array: return "an array";
    case Json_value::Kind::Object: return "an object";
  }
  return "?";
}

namespace {

std::string line_column(const std::string& text, std::size_t byte)
{
  std::size_t line = 1, col = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') { ++line; col = 1; } else ++col;
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(col);
}

// The SAX events' JSON type. Its floats are long double only so that the
// parser does not call a token such as 1e1000 an overflow: the value is never
// used (numbers are read exactly from their text), and with long double's
// range (1e+-4932) every token within CLASH4D_MAX_EXPONENT reaches the
// builder, as the same text in a string does (docs/scene-format.md, Numbers).
using Sax_json = nlohmann::basic_json<std::map, std::vector, std::string, bool, std::int64_t, std::uint64_t,
                                      long double>;

// Builds a Json_value tree; open containers live on an explicit stack.
class Builder : public nlohmann::json_sax<Sax_json> {
public:
  explicit Builder(const std::string& text) : text_(text) {}
  Json_value result;
  std::string error, place;
  int exit_code = CLASH4D_EXIT_INVALID;

  bool null() override { return add(Json_value{}); }
  bool boolean(bool b) override { Json_value v; v.kind = Json_value::Kind::Boolean; v.boolean = b; return add(std::move(v)); }
  bool number_integer(number_integer_t n) override { return number(std::to_string(n)); }
  bool number_unsigned(number_unsigned_t n) override { return number(std::to_string(n)); }
  // The text s, never the double: numbers are read exactly later.
  bool number_float(number_float_t, const string_t& s) override { return number(s); }
  bool string(string_t& s) override { Json_value v; v.kind = Json_value::Kind::String; v.text = s; return add(std::move(v)); }
  bool binary(binary_t&) override { return fail("binary values are not JSON"); }
  bool start_object(std::size_t) override { return open(Json_value::Kind::Object); }
  bool key(string_t& k) override
  {
    Json_value& obj = stack_.back();
    for (const auto& m : obj.members)
      if (m.first == k) {
        place = container_path();
        return fail("duplicate key \"" + k + "\"");
      }
    keys_.back() = k;
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(Json_value::Kind::Array); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t position, const std::string& token, const nlohmann::detail::exception& ex) override
  {
    std::string what = ex.what();
    // nlohmann says "number overflow" for JSON numbers beyond double's range;
    // they are exact rationals to us, but the reader cannot hold their text.
    if (what.find("number overflow") != std::string::npos) {
      Number_parse p = parse_number_text(token, false);
      if (p.limit) {
        exit_code = CLASH4D_EXIT_LIMIT;
        place = value_path();
        return fail("number " + token.substr(0, 40) + ": " + p.error);
      }
      return fail("number " + token + " is too large for a JSON number here; write it as a string, e.g. \"" + token + "\"", position);
    }
    std::size_t colon = what.find("syntax error");
    return fail(colon == std::string::npos ? what : what.substr(colon), position);
  }

private:
  const std::string& text_;
  std::vector<Json_value> stack_;
  std::vector<std::string> keys_;   // the pending key of each open container

  bool fail(const std::string& why, std::size_t position = std::string::npos)
  {
    if (error.empty()) {
      error = why;
      if (position != std::string::npos) place = line_column(text_, position);
    }
    return false;
  }
  // The JSON path of the innermost open container, e.g. objects[1].shape,
  // or with the value being read, of that value (e.g. objects[1].shape.block).
  std::string container_path(bool with_value = false) const
  {
    std::string path;
    for (std::size_t i = 0; i + (with_value ? 0 : 1) < stack_.size(); ++i) {
      if (stack_[i].kind == Json_value::Kind::Array) path += "[" + std::to_string(stack_[i].items.size()) + "]";
      else path += (path.empty() ? "" : ".") + keys_[i];
    }
    return path;
  }
  std::string value_path() const { return container_path(true); }
  bool number(const std::string& s)
  {
    // The number rule's limits hold for every number token, meta's included
    // (the Python verifier's reader refuses them there too); only a long
    // token or one with an exponent can exceed them.
    if (s.size() > CLASH4D_MAX_NUMBER_CHARS || s.find_first_of("eE") != std::string::npos) {
      Number_parse p = parse_number_text(s, false);
      if (p.limit) {
        exit_code = CLASH4D_EXIT_LIMIT;
        place = value_path();
        return fail("'" + s.substr(0, 40) + (s.size() > 40 ? "...' " : "' ") + "is refused: " + p.error);
      }
    }
    Json_value v;
    v.kind = Json_value::Kind::Number;
    v.text = s;
    return add(std::move(v));
  }
  bool open(Json_value::Kind k)
  {
    if (stack_.size() >= CLASH4D_MAX_JSON_DEPTH) {
      exit_code = CLASH4D_EXIT_LIMIT;
      return fail("nesting deeper than the limit of " + std::to_string(CLASH4D_MAX_JSON_DEPTH) + " levels");
    }
    Json_value v;
    v.kind = k;
    stack_.push_back(std::move(v));
    keys_.emplace_back();
    return true;
  }
  bool close()
  {
    Json_value v = std::move(stack_.back());
    stack_.pop_back();
    keys_.pop_back();
    return add(std::move(v));
  }
  bool add(Json_value v)
  {
    if (stack_.empty()) { result = std::move(v); return true; }
    Json_value& top = stack_.back();
    if (top.kind == Json_value::Kind::Array) top.items.push_back(std::move(v));
    else top.members.emplace_back(keys_.back(), std::move(v));
    return true;
  }
};

} // namespace

Json_value read_json_text(const std::string& text)
{
  // nlohmann's lexer takes a NUL byte for the end of the input, so whatever
  // follows one would pass unread; JSON text holds none (RFC 8259 section 7).
  if (std::size_t nul = text.find('\0'); nul != std::string::npos)
    throw Input_error(line_column(text, nul), "a NUL byte, which JSON text never holds");
  Builder builder(text);
  bool ok = Sax_json::sax_parse(text, &builder, Sax_json::input_format_t::json, true, false);
  if (!ok || !builder.error.empty()) {
    std::string why = builder.error.empty() ? "not valid JSON" : builder.error;
    throw Input_error(builder.place, why, builder.exit_code);
  }
  return std::move(builder.result);
}

std::string read_file_text(const std::string& path, std::size_t max_bytes, const std::string& noun)
{
  int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw Input_error("", "cannot open the " + noun);
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  std::string text;
  char chunk[1 << 16];
  for (;;) {
    ssize_t n = ::read(fd, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      ::close(fd);
      if (n < 0) throw Input_error("", "cannot read the " + noun);
      return text;
    }
    text.append(chunk, static_cast<std::size_t>(n));
    if (text.size() > max_bytes) {
      ::close(fd);
      // Whole MiB as MiB (the scene's 64 MiB, a certificate's --certificate-max-mb), else bytes: never "0 MiB".
      bool mib = max_bytes >= (1u << 20) && max_bytes % (1u << 20) == 0;
      throw Input_error("", noun + " larger than the limit of " +
                                (mib ? std::to_string(max_bytes >> 20) + " MiB" : std::to_string(max_bytes) + " bytes"),
                        CLASH4D_EXIT_LIMIT);
    }
  }
}

Json_value read_json_file(const std::string& path)
{
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw Input_error("", "is a folder, not a scene file");
  return read_json_text(read_file_text(path, CLASH4D_MAX_FILE_BYTES));
}

} // namespace clash4d

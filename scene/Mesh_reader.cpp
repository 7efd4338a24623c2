#include "scene/Mesh_reader.h"
#include "scene/Json_reader.h"
#include "scene/Input_error.h"
#include "scene/Number_text.h"

#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <gmp.h>
#include <sstream>
#include <stdexcept>

namespace clash4d {

namespace {

using Point = std::array<Rational, 3>;

// 2^e * m exactly, m an unsigned integer of at most 64 bits.
Rational dyadic(std::uint64_t m, int e, bool negative)
{
  mpq_t q;
  mpq_init(q);
  mpq_set_ui(q, static_cast<unsigned long>(m), 1);
  if (e >= 0) mpq_mul_2exp(q, q, static_cast<mp_bitcnt_t>(e));
  else mpq_div_2exp(q, q, static_cast<mp_bitcnt_t>(-e));
  if (negative) mpq_neg(q, q);
  Rational out(q);
  mpq_clear(q);
  return out;
}

std::string lower(std::string_view s)
{
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string shown(std::string_view tok)
{
  std::string s(tok.substr(0, 40));
  for (char& c : s)
    if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
  return tok.size() > 40 ? s + "..." : s;
}

// Where errors point: "FILE: line L" for text, "FILE: what N" for binary.
struct Place {
  const std::string& file;
  [[noreturn]] void fail(const std::string& where, const std::string& what, int code = CLASH4D_EXIT_INVALID) const
  {
    throw Input_error(where.empty() ? file : file + ": " + where, what, code);
  }
  [[noreturn]] void at_line(std::size_t line, const std::string& what, int code = CLASH4D_EXIT_INVALID) const
  {
    fail("line " + std::to_string(line), what, code);
  }
};

void check_count(const Place& place, const std::string& where, std::size_t count, std::size_t limit, const char* what)
{
  if (count > limit)
    place.fail(where, std::to_string(count) + " " + what + " is more than the limit of " + std::to_string(limit),
               CLASH4D_EXIT_LIMIT);
}

// A cursor over text: tokens separated by blanks, lines counted, '#'
// comments skipped where the format has them.
class Text_cursor {
public:
  Text_cursor(std::string_view s, bool hash_comments) : s_(s), hash_(hash_comments) {}
  std::size_t line() const { return line_; }
  std::size_t pos() const { return pos_; }
  // The next token on the current line, if any.
  bool on_line(std::string_view& tok)
  {
    while (pos_ < s_.size() && blank(s_[pos_])) ++pos_;
    if (hash_ && pos_ < s_.size() && s_[pos_] == '#')
      while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
    if (pos_ >= s_.size() || s_[pos_] == '\n') return false;
    std::size_t start = pos_;
    while (pos_ < s_.size() && !blank(s_[pos_]) && s_[pos_] != '\n' && !(hash_ && s_[pos_] == '#')) ++pos_;
    tok = s_.substr(start, pos_ - start);
    return true;
  }
  // Past the end of the current line; false at the end of the text.
  bool next_line()
  {
    while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
    if (pos_ >= s_.size()) return false;
    ++pos_;
    ++line_;
    return true;
  }
  // The next token on any line; tok_line is its line.
  bool next(std::string_view& tok, std::size_t& tok_line)
  {
    for (;;) {
      if (on_line(tok)) return tok_line = line_, true;
      if (!next_line()) return false;
    }
  }
  // The rest of the current line as text (a name, say).
  std::string_view rest_of_line()
  {
    std::size_t start = pos_;
    while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
    return s_.substr(start, pos_ - start);
  }

private:
  static bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
  std::string_view s_;
  bool hash_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
};

// A coordinate's text read exactly. Mesh writers use forms JSON does not
// ("+1", ".5", "5.", "5.e3", "007"); they are brought to JSON's grammar first.
Rational exact_number(std::string_view tok, const Place& place, std::size_t line)
{
  std::string t(tok);
  std::string lowered = lower(t);
  if (lowered.find("nan") != std::string::npos || lowered.find("inf") != std::string::npos)
    place.at_line(line, "'" + shown(tok) + "' is not a finite number");
  std::size_t i = 0;
  std::string sign;
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) {
    if (t[i] == '-') sign = "-";
    ++i;
  }
  std::size_t mantissa_end = t.find_first_of("eE", i);
  if (mantissa_end == std::string::npos) mantissa_end = t.size();
  std::string mantissa = t.substr(i, mantissa_end - i), exponent = t.substr(mantissa_end);
  std::size_t dot = mantissa.find('.');
  std::string whole = mantissa.substr(0, dot), fraction = dot == std::string::npos ? "" : mantissa.substr(dot + 1);
  std::size_t nz = whole.find_first_not_of('0');
  whole = nz == std::string::npos ? "0" : whole.substr(nz);
  if (dot != std::string::npos && fraction.empty() && mantissa.size() > 1) fraction = "0";
  if (mantissa.empty() || mantissa == ".") place.at_line(line, "'" + shown(tok) + "' is not a number");
  std::string json = sign + whole + (dot == std::string::npos ? "" : "." + fraction) + exponent;
  Number_parse p = parse_number_text(json, false);
  if (!p.ok) {
    if (p.limit) place.at_line(line, "'" + shown(tok) + "' is refused: " + p.error, CLASH4D_EXIT_LIMIT);
    place.at_line(line, "'" + shown(tok) + "' is not a number: " + p.error);
  }
  return p.value;
}

// A decimal integer (optional sign); false when tok is not one or out of range.
bool integer_of(std::string_view tok, long long& out)
{
  std::size_t i = 0;
  bool negative = false;
  if (i < tok.size() && (tok[i] == '-' || tok[i] == '+')) negative = tok[i++] == '-';
  if (i == tok.size()) return false;
  unsigned long long v = 0;
  for (; i < tok.size(); ++i) {
    if (tok[i] < '0' || tok[i] > '9') return false;
    if (v > (1ull << 40)) return false;   // far beyond any limit
    v = v * 10 + static_cast<unsigned>(tok[i] - '0');
  }
  out = negative ? -static_cast<long long>(v) : static_cast<long long>(v);
  return true;
}

long long integer_token(std::string_view tok, const Place& place, std::size_t line, const char* what)
{
  long long v;
  if (!integer_of(tok, v)) place.at_line(line, std::string("expected ") + what + ", found '" + shown(tok) + "'");
  return v;
}

int vertex_index(long long v, std::size_t vertex_count, const Place& place, const std::string& where)
{
  if (v < 0 || static_cast<unsigned long long>(v) >= vertex_count)
    place.fail(where, "vertex index " + std::to_string(v) + " out of range (the file has " +
                          std::to_string(vertex_count) + " vertices, indices 0 to " +
                          std::to_string(static_cast<long long>(vertex_count) - 1) + ")");
  return static_cast<int>(v);
}

// ---- OFF ----------------------------------------------------------------

Mesh read_off(std::string_view bytes, const Place& place, const Mesh_limits& limits)
{
  Text_cursor c(bytes, true);
  std::string_view tok;
  std::size_t line = 1;
  if (!c.next(tok, line)) place.fail("", "empty file: expected \"OFF\"");
  std::string head = std::string(tok);
  if (head != "OFF" && head != "COFF" && head != "NOFF" && head != "CNOFF")
    place.at_line(line, "expected \"OFF\", found '" + shown(tok) + "'");
  auto need = [&](const char* what) {
    if (!c.next(tok, line)) place.at_line(c.line(), std::string("the file ends where ") + what + " was expected");
    return tok;
  };
  long long counts[3];
  for (int k = 0; k < 3; ++k) {
    counts[k] = integer_token(need("the vertex, facet and edge counts"), place, line, "a count");
    if (counts[k] < 0) place.at_line(line, "negative count " + std::to_string(counts[k]));
  }
  check_count(place, "line " + std::to_string(line), static_cast<std::size_t>(counts[0]), limits.vertices, "vertices");
  check_count(place, "line " + std::to_string(line), static_cast<std::size_t>(counts[1]), limits.facets, "facets");
  Mesh m;
  std::size_t nv = static_cast<std::size_t>(counts[0]), nf = static_cast<std::size_t>(counts[1]);
  m.vertices.reserve(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    Point p;
    for (int k = 0; k < 3; ++k) p[k] = exact_number(need("a vertex coordinate"), place, line);
    m.vertices.push_back(p);
    if (head != "OFF") c.rest_of_line();   // COFF, NOFF: colours or normals
  }
  m.facets.reserve(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    long long k = integer_token(need("a facet"), place, line, "a facet's vertex count");
    if (k < 3) place.at_line(line, "facet " + std::to_string(f) + " has " + std::to_string(k) + " vertices (at least 3)");
    check_count(place, "line " + std::to_string(line), static_cast<std::size_t>(k), limits.facet_vertices, "vertices in one facet");
    std::vector<int> facet;
    for (long long i = 0; i < k; ++i) {
      long long v = integer_token(need("a vertex index"), place, line, "a vertex index");
      facet.push_back(vertex_index(v, nv, place, "line " + std::to_string(line)));
    }
    m.facets.push_back(std::move(facet));
    c.rest_of_line();   // colour
  }
  if (c.next(tok, line)) place.at_line(line, "unexpected '" + shown(tok) + "' after the last facet");
  return m;
}

// ---- OBJ ----------------------------------------------------------------

Mesh read_obj(std::string_view bytes, const Place& place, const Mesh_limits& limits)
{
  Text_cursor c(bytes, true);
  Mesh m;
  std::string_view tok;
  do {
    std::size_t line = c.line();
    if (!c.on_line(tok)) continue;
    if (tok == "v") {
      std::vector<std::string_view> xs;
      while (c.on_line(tok)) xs.push_back(tok);
      if (xs.size() != 3 && xs.size() != 4 && xs.size() != 6)
        place.at_line(line, "a vertex needs x y z [w] (or x y z r g b), found " + std::to_string(xs.size()) + " numbers");
      Point p;
      for (int k = 0; k < 3; ++k) p[k] = exact_number(xs[k], place, line);
      if (xs.size() == 4) {
        Rational w = exact_number(xs[3], place, line);
        if (CGAL::is_zero(w)) place.at_line(line, "vertex weight w is 0");
        for (auto& x : p) x /= w;
      }
      check_count(place, "line " + std::to_string(line), m.vertices.size() + 1, limits.vertices, "vertices");
      m.vertices.push_back(p);
    } else if (tok == "f") {
      std::vector<int> facet;
      while (c.on_line(tok)) {
        std::string_view index = tok.substr(0, tok.find('/'));
        long long v = integer_token(index, place, line, "a vertex index");
        if (v == 0) place.at_line(line, "vertex index 0 (OBJ indices start at 1, or count back from -1)");
        long long zero_based = v > 0 ? v - 1 : static_cast<long long>(m.vertices.size()) + v;
        if (zero_based < 0 || static_cast<std::size_t>(zero_based) >= m.vertices.size())
          place.at_line(line, "vertex index " + std::to_string(v) + " out of range (" +
                                  std::to_string(m.vertices.size()) + " vertices so far)");
        facet.push_back(static_cast<int>(zero_based));
        check_count(place, "line " + std::to_string(line), facet.size(), limits.facet_vertices, "vertices in one facet");
      }
      if (facet.size() < 3)
        place.at_line(line, "facet " + std::to_string(m.facets.size()) + " has " + std::to_string(facet.size()) +
                                " vertices (at least 3)");
      check_count(place, "line " + std::to_string(line), m.facets.size() + 1, limits.facets, "facets");
      m.facets.push_back(std::move(facet));
    }
    // vt, vn, g, o, s, usemtl, mtllib, l, p ...: not geometry of the solid.
  } while (c.next_line());
  if (m.facets.empty()) place.fail("", "no facets (\"f\" lines)");
  return m;
}

// ---- STL ----------------------------------------------------------------

std::uint32_t le32(const unsigned char* p)
{
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

Mesh read_stl_binary(std::string_view bytes, std::size_t n, const Place& place)
{
  const unsigned char* data = reinterpret_cast<const unsigned char*>(bytes.data());
  Mesh m;
  m.vertices.reserve(3 * n);
  m.facets.reserve(n);
  for (std::size_t f = 0; f < n; ++f) {
    const unsigned char* facet = data + 84 + 50 * f;
    for (int v = 0; v < 3; ++v) {
      Point p;
      for (int k = 0; k < 3; ++k) {
        try {
          p[k] = exact_float32(le32(facet + 12 + 12 * v + 4 * k));
        } catch (const std::domain_error& e) {
          place.fail("facet " + std::to_string(f), std::string("vertex ") + std::to_string(v) + " coordinate " +
                                                        "xyz"[k] + " is " + e.what());
        }
      }
      m.vertices.push_back(p);
    }
    int base = static_cast<int>(3 * f);
    m.facets.push_back({base, base + 1, base + 2});
  }
  return m;
}

Mesh read_stl_ascii(std::string_view bytes, const Place& place, const Mesh_limits& limits)
{
  Text_cursor c(bytes, false);
  Mesh m;
  std::string_view tok;
  std::size_t line = 1;
  auto expect = [&](const char* word) {
    if (!c.next(tok, line)) place.at_line(c.line(), std::string("the file ends where \"") + word + "\" was expected");
    if (lower(tok) != word) place.at_line(line, std::string("expected \"") + word + "\", found '" + shown(tok) + "'");
  };
  expect("solid");
  c.rest_of_line();
  for (;;) {
    if (!c.next(tok, line)) place.at_line(c.line(), "the file ends where \"facet\" or \"endsolid\" was expected");
    std::string word = lower(tok);
    if (word == "endsolid") {
      c.rest_of_line();
      if (!c.next(tok, line)) break;
      if (lower(tok) != "solid") place.at_line(line, "expected \"solid\" or the end of the file, found '" + shown(tok) + "'");
      c.rest_of_line();
      continue;
    }
    if (word != "facet") place.at_line(line, "expected \"facet\" or \"endsolid\", found '" + shown(tok) + "'");
    check_count(place, "line " + std::to_string(line), m.facets.size() + 1, limits.facets, "facets");
    expect("normal");
    for (int k = 0; k < 3; ++k) {   // the normal is not used (the orientation is the vertices' order)
      if (!c.next(tok, line)) place.at_line(c.line(), "the file ends inside a normal");
      exact_number(tok, place, line);
    }
    expect("outer");
    expect("loop");
    int base = static_cast<int>(m.vertices.size());
    for (int v = 0; v < 3; ++v) {
      expect("vertex");
      Point p;
      for (int k = 0; k < 3; ++k) {
        if (!c.next(tok, line)) place.at_line(c.line(), "the file ends inside a vertex");
        p[k] = exact_number(tok, place, line);
      }
      m.vertices.push_back(p);
    }
    expect("endloop");
    expect("endfacet");
    m.facets.push_back({base, base + 1, base + 2});
  }
  if (m.facets.empty()) place.fail("", "no facets");
  return m;
}

Mesh read_stl(std::string_view bytes, const Place& place, const Mesh_limits& limits)
{
  if (bytes.empty()) place.fail("", "empty file");
  if (bytes.size() >= 84) {
    std::size_t n = le32(reinterpret_cast<const unsigned char*>(bytes.data()) + 80);
    if (bytes.size() == 84 + 50 * n) {
      check_count(place, "", n, limits.facets, "facets");
      if (n == 0) place.fail("", "binary STL with no facets");
      return read_stl_binary(bytes, n, place);
    }
  }
  std::size_t start = 0;
  while (start < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[start]))) ++start;
  if (lower(bytes.substr(start, 5)) == "solid") return read_stl_ascii(bytes, place, limits);
  if (bytes.size() < 84) place.fail("", "not an STL file: " + std::to_string(bytes.size()) +
                                            " bytes, too short for a binary STL header (84 bytes) and not ASCII (\"solid ...\")");
  std::size_t n = le32(reinterpret_cast<const unsigned char*>(bytes.data()) + 80);
  check_count(place, "", n, limits.facets, "facets");
  place.fail("", "binary STL of " + std::to_string(n) + " facets should have 84 + 50 * " + std::to_string(n) + " = " +
                     std::to_string(84 + 50 * n) + " bytes, the file has " + std::to_string(bytes.size()) +
                     (bytes.size() < 84 + 50 * n ? " (truncated: it ends inside facet " + std::to_string((bytes.size() - 84) / 50) + ")"
                                                 : " (data after the last facet)"));
}

// ---- PLY ----------------------------------------------------------------

enum class Ply_type { Int8, Uint8, Int16, Uint16, Int32, Uint32, Float32, Float64 };

bool ply_type_of(const std::string& name, Ply_type& t)
{
  static const std::pair<const char*, Ply_type> names[] = {
      {"char", Ply_type::Int8},     {"int8", Ply_type::Int8},       {"uchar", Ply_type::Uint8},
      {"uint8", Ply_type::Uint8},   {"short", Ply_type::Int16},     {"int16", Ply_type::Int16},
      {"ushort", Ply_type::Uint16}, {"uint16", Ply_type::Uint16},   {"int", Ply_type::Int32},
      {"int32", Ply_type::Int32},   {"uint", Ply_type::Uint32},     {"uint32", Ply_type::Uint32},
      {"float", Ply_type::Float32}, {"float32", Ply_type::Float32}, {"double", Ply_type::Float64},
      {"float64", Ply_type::Float64}};
  for (const auto& n : names)
    if (name == n.first) return t = n.second, true;
  return false;
}

std::size_t ply_size(Ply_type t)
{
  switch (t) {
    case Ply_type::Int8: case Ply_type::Uint8: return 1;
    case Ply_type::Int16: case Ply_type::Uint16: return 2;
    case Ply_type::Int32: case Ply_type::Uint32: case Ply_type::Float32: return 4;
    case Ply_type::Float64: return 8;
  }
  return 0;
}

bool ply_is_float(Ply_type t) { return t == Ply_type::Float32 || t == Ply_type::Float64; }

struct Ply_property {
  std::string name;
  bool list = false;
  Ply_type count_type = Ply_type::Uint8, type = Ply_type::Float32;
};

struct Ply_element {
  std::string name;
  std::size_t count = 0;
  std::size_t line = 0;
  std::vector<Ply_property> properties;
};

// The values of a PLY body, text or binary; `where` names the item read.
class Ply_body {
public:
  Ply_body(std::string_view body, std::size_t first_line, int encoding, const Place& place)
    : body_(body), text_(body, false), encoding_(encoding), place_(place), first_line_(first_line) {}
  std::string where;

  Rational number(Ply_type t)
  {
    if (encoding_ == 0) {
      std::string_view tok = token();
      return exact_number(tok, place_, first_line_ + text_.line() - 1);
    }
    if (ply_is_float(t)) {
      try {
        return t == Ply_type::Float32 ? exact_float32(static_cast<std::uint32_t>(raw(4)))
                                      : exact_float64(raw(8));
      } catch (const std::domain_error& e) {
        place_.fail(where, std::string("a coordinate is ") + e.what());
      }
    }
    return Rational(static_cast<long>(integer(t)));
  }

  long long integer(Ply_type t)
  {
    if (encoding_ == 0) {
      std::string_view tok = token();
      long long v;
      if (!integer_of(tok, v)) place_.fail(where, "expected an integer, found '" + shown(tok) + "' (line " +
                                                      std::to_string(first_line_ + text_.line() - 1) + ")");
      return v;
    }
    if (ply_is_float(t)) place_.fail(where, "a count or index of floating-point type");
    std::uint64_t u = raw(ply_size(t));
    switch (t) {
      case Ply_type::Int8: return static_cast<std::int8_t>(u);
      case Ply_type::Int16: return static_cast<std::int16_t>(u);
      case Ply_type::Int32: return static_cast<std::int32_t>(u);
      default: return static_cast<long long>(u);
    }
  }

  void skip(Ply_type t)
  {
    if (encoding_ == 0) token();
    else raw(ply_size(t));
  }

  bool at_end()
  {
    if (encoding_ != 0) return pos_ == body_.size();
    std::string_view tok;
    std::size_t line;
    return !text_.next(tok, line);
  }

private:
  std::string_view token()
  {
    std::string_view tok;
    std::size_t line;
    if (!text_.next(tok, line)) place_.fail(where, "the file ends here (truncated)");
    return tok;
  }
  // n bytes as an unsigned integer in the body's byte order.
  std::uint64_t raw(std::size_t n)
  {
    if (body_.size() - pos_ < n) place_.fail(where, "the file ends here (truncated)");
    std::uint64_t u = 0;
    for (std::size_t i = 0; i < n; ++i) {
      std::uint64_t byte = static_cast<unsigned char>(body_[pos_ + i]);
      u |= byte << (8 * (encoding_ == 1 ? i : n - 1 - i));
    }
    pos_ += n;
    return u;
  }
  std::string_view body_;
  Text_cursor text_;
  int encoding_;   // 0 ascii, 1 little endian, 2 big endian
  const Place& place_;
  std::size_t first_line_;
  std::size_t pos_ = 0;
};

// A PLY header: the body's encoding (0 ascii, 1 little endian, 2 big
// endian), its elements, and where the body starts.
struct Ply_header {
  int encoding = -1;
  std::vector<Ply_element> elements;
  std::size_t body_line = 0, body_pos = 0;
};

// "element NAME COUNT", its count within the limits.
Ply_element ply_element(const std::vector<std::string>& words, std::size_t line, const Place& place, const Mesh_limits& limits)
{
  long long n;
  if (words.size() != 3 || !integer_of(words[2], n) || n < 0) place.at_line(line, "expected \"element NAME COUNT\"");
  std::size_t limit = words[1] == "vertex" ? limits.vertices : words[1] == "face" ? limits.facets : limits.facets + limits.vertices;
  check_count(place, "line " + std::to_string(line), static_cast<std::size_t>(n), limit,
              words[1] == "vertex" ? "vertices" : words[1] == "face" ? "facets" : "items");
  return {words[1], static_cast<std::size_t>(n), line, {}};
}

// "property TYPE NAME" or "property list TYPE TYPE NAME".
Ply_property ply_property(const std::vector<std::string>& words, std::size_t line, const Place& place)
{
  Ply_property p;
  bool ok;
  p.name = words.back();
  if (words.size() == 5 && words[1] == "list") {
    p.list = true;
    ok = ply_type_of(words[2], p.count_type) && ply_type_of(words[3], p.type);
  } else {
    ok = words.size() == 3 && ply_type_of(words[1], p.type);
  }
  if (!ok) place.at_line(line, "expected \"property TYPE NAME\" or \"property list TYPE TYPE NAME\"");
  return p;
}

int ply_encoding(const std::vector<std::string>& words, std::size_t line, const Place& place)
{
  if (words.size() != 3 || words[2] != "1.0") place.at_line(line, "expected \"format ENCODING 1.0\"");
  if (words[1] == "ascii") return 0;
  if (words[1] == "binary_little_endian") return 1;
  if (words[1] == "binary_big_endian") return 2;
  place.at_line(line, "unknown format '" + shown(words[1]) + "'");
}

Ply_header read_ply_header(std::string_view bytes, const Place& place, const Mesh_limits& limits)
{
  if (bytes.empty()) place.fail("", "empty file");
  Text_cursor header(bytes, false);
  std::string_view tok;
  if (!header.on_line(tok) || tok != "ply") place.at_line(1, "expected \"ply\"");
  Ply_header h;
  bool ended = false;
  while (!ended && header.next_line()) {
    std::size_t line = header.line();
    if (!header.on_line(tok) || tok == "comment" || tok == "obj_info") continue;
    std::vector<std::string> words{std::string(tok)};
    while (header.on_line(tok)) words.emplace_back(tok);
    if (words[0] == "end_header") {
      ended = true;
    } else if (words[0] == "format") {
      h.encoding = ply_encoding(words, line, place);
    } else if (words[0] == "element") {
      h.elements.push_back(ply_element(words, line, place, limits));
    } else if (words[0] == "property") {
      if (h.elements.empty()) place.at_line(line, "a property before any element");
      h.elements.back().properties.push_back(ply_property(words, line, place));
    } else {
      place.at_line(line, "unknown header line '" + shown(words[0]) + "'");
    }
  }
  if (!ended) place.fail("", "the header has no \"end_header\"");
  if (h.encoding < 0) place.fail("", "the header has no \"format\" line");
  h.body_line = header.line() + 1;
  header.next_line();
  h.body_pos = header.pos();
  return h;
}

// A list of n values read past, n within the facet limit.
void skip_ply_list(Ply_body& body, long long n, Ply_type type, const Place& place, const Mesh_limits& limits)
{
  if (n < 0 || static_cast<std::size_t>(n) > limits.facet_vertices)
    place.fail(body.where, "list of " + std::to_string(n) + " values");
  for (long long i = 0; i < n; ++i) body.skip(type);
}

// The vertex element: x, y and z read exactly, other properties skipped.
void read_ply_vertices(const Ply_element& e, Ply_body& body, const Place& place, const Mesh_limits& limits, Mesh& m)
{
  check_count(place, "line " + std::to_string(e.line), e.count, limits.vertices, "vertices");
  int axis_of[3] = {-1, -1, -1};   // the property index of x, y, z
  for (std::size_t k = 0; k < e.properties.size(); ++k)
    for (int a = 0; a < 3; ++a)
      if (e.properties[k].name == std::string(1, "xyz"[a])) {
        if (e.properties[k].list) place.at_line(e.line, "vertex property " + e.properties[k].name + " is a list");
        axis_of[a] = static_cast<int>(k);
      }
  for (int a = 0; a < 3; ++a)
    if (axis_of[a] < 0) place.at_line(e.line, std::string("the vertex element has no property ") + "xyz"[a]);
  m.vertices.reserve(e.count);
  for (std::size_t v = 0; v < e.count; ++v) {
    body.where = "vertex " + std::to_string(v);
    Point p;
    for (std::size_t k = 0; k < e.properties.size(); ++k) {
      const Ply_property& prop = e.properties[k];
      int a = std::find(axis_of, axis_of + 3, static_cast<int>(k)) - axis_of;
      if (a < 3) p[a] = body.number(prop.type);
      else if (prop.list) skip_ply_list(body, body.integer(prop.count_type), prop.type, place, limits);
      else body.skip(prop.type);
    }
    m.vertices.push_back(p);
  }
}

// The face element: each facet's vertex_indices, other properties skipped.
void read_ply_faces(const Ply_element& e, Ply_body& body, const Place& place, const Mesh_limits& limits, Mesh& m)
{
  check_count(place, "line " + std::to_string(e.line), e.count, limits.facets, "facets");
  int indices = -1;
  for (std::size_t k = 0; k < e.properties.size(); ++k)
    if (e.properties[k].list && (e.properties[k].name == "vertex_indices" || e.properties[k].name == "vertex_index"))
      indices = static_cast<int>(k);
  if (indices < 0) place.at_line(e.line, "the face element has no list property vertex_indices");
  m.facets.reserve(e.count);
  for (std::size_t f = 0; f < e.count; ++f) {
    body.where = "facet " + std::to_string(f);
    for (std::size_t k = 0; k < e.properties.size(); ++k) {
      const Ply_property& prop = e.properties[k];
      if (!prop.list) { body.skip(prop.type); continue; }
      long long n = body.integer(prop.count_type);
      if (static_cast<int>(k) != indices) { skip_ply_list(body, n, prop.type, place, limits); continue; }
      if (n < 3) place.fail(body.where, "has " + std::to_string(n) + " vertices (at least 3)");
      check_count(place, body.where, static_cast<std::size_t>(n), limits.facet_vertices, "vertices in one facet");
      std::vector<int> facet;
      for (long long i = 0; i < n; ++i) facet.push_back(vertex_index(body.integer(prop.type), m.vertices.size(), place, body.where));
      m.facets.push_back(std::move(facet));
    }
  }
}

// Any other element: read past.
void skip_ply_element(const Ply_element& e, Ply_body& body, const Place& place, const Mesh_limits& limits)
{
  check_count(place, "line " + std::to_string(e.line), e.count, limits.facets + limits.vertices,
              ("items of element " + e.name).c_str());
  for (std::size_t i = 0; i < e.count; ++i) {
    body.where = e.name + " " + std::to_string(i);
    for (const Ply_property& prop : e.properties)
      skip_ply_list(body, prop.list ? body.integer(prop.count_type) : 1, prop.type, place, limits);
  }
}

Mesh read_ply(std::string_view bytes, const Place& place, const Mesh_limits& limits)
{
  Ply_header h = read_ply_header(bytes, place, limits);
  Ply_body body(bytes.substr(h.body_pos), h.body_line, h.encoding, place);
  Mesh m;
  bool have_vertices = false, have_faces = false;
  for (const Ply_element& e : h.elements) {
    if (e.name == "vertex") {
      if (have_vertices) place.at_line(e.line, "a second vertex element");
      have_vertices = true;
      read_ply_vertices(e, body, place, limits, m);
    } else if (e.name == "face") {
      if (have_faces) place.at_line(e.line, "a second face element");
      if (!have_vertices) place.at_line(e.line, "the face element comes before the vertex element");
      have_faces = true;
      read_ply_faces(e, body, place, limits, m);
    } else {
      skip_ply_element(e, body, place, limits);
    }
  }
  if (!have_faces || m.facets.empty()) place.fail("", "no facets (element face)");
  body.where = "";
  if (!body.at_end()) place.fail("", "unexpected data after the last element");
  return m;
}

} // namespace

Rational exact_float32(std::uint32_t bits)
{
  bool negative = bits >> 31;
  int exponent = static_cast<int>((bits >> 23) & 0xff);
  std::uint32_t mantissa = bits & 0x7fffff;
  if (exponent == 0xff) throw std::domain_error(mantissa ? "NaN" : "infinite");
  if (exponent == 0) return dyadic(mantissa, -149, negative);   // subnormal
  return dyadic(mantissa | (1u << 23), exponent - 150, negative);
}

Rational exact_float64(std::uint64_t bits)
{
  bool negative = bits >> 63;
  int exponent = static_cast<int>((bits >> 52) & 0x7ff);
  std::uint64_t mantissa = bits & ((std::uint64_t(1) << 52) - 1);
  if (exponent == 0x7ff) throw std::domain_error(mantissa ? "NaN" : "infinite");
  if (exponent == 0) return dyadic(mantissa, -1074, negative);
  return dyadic(mantissa | (std::uint64_t(1) << 52), exponent - 1075, negative);
}

Mesh_format mesh_format_of(const std::string& file_name)
{
  std::size_t dot = file_name.rfind('.');
  std::size_t slash = file_name.find_last_of("/\\");
  std::string ext = dot == std::string::npos || (slash != std::string::npos && dot < slash) ? "" : lower(file_name.substr(dot + 1));
  if (ext == "off") return Mesh_format::Off;
  if (ext == "obj") return Mesh_format::Obj;
  if (ext == "stl") return Mesh_format::Stl;
  if (ext == "ply") return Mesh_format::Ply;
  throw Input_error(file_name, "unknown mesh format '." + ext + "' (expected .off, .obj, .stl or .ply)");
}

Mesh read_mesh(std::string_view bytes, Mesh_format format, const std::string& file_name, const Mesh_limits& limits)
{
  Place place{file_name};
  if (bytes.size() > limits.file_bytes)
    place.fail("", "file of " + std::to_string(bytes.size()) + " bytes is larger than the limit of " +
                       std::to_string(limits.file_bytes) + " bytes", CLASH4D_EXIT_LIMIT);
  switch (format) {
    case Mesh_format::Off: return read_off(bytes, place, limits);
    case Mesh_format::Obj: return read_obj(bytes, place, limits);
    case Mesh_format::Stl: return read_stl(bytes, place, limits);
    case Mesh_format::Ply: return read_ply(bytes, place, limits);
  }
  place.fail("", "unknown mesh format");
}

Mesh read_mesh_file(const std::string& path, const std::string& file_name, const Mesh_limits& limits)
{
  Mesh_format format = mesh_format_of(file_name);
  std::error_code ec;
  std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (std::filesystem::is_directory(status)) throw Input_error(file_name, "is a directory, not a mesh file");
  // A pipe or a device would block or never end: a mesh is a regular file.
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw Input_error(file_name, "is not a regular file (a pipe, a device or a socket), not a mesh file");
  std::string bytes;
  try {
    bytes = read_file_text(path, limits.file_bytes, "mesh file");   // the limit holds while reading, even if the file grows
  } catch (const Input_error& e) {
    throw Input_error(file_name, e.what(), e.exit_code());
  }
  return read_mesh(bytes, format, file_name, limits);
}

} // namespace clash4d

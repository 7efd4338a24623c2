#include "ccd/Ccd_reader.h"

#include "scene/Input_error.h"
#include "scene/Json_fields.h"
#include "scene/Json_reader.h"
#include "scene/Number_text.h"
#include <cctype>
#include <charconv>
#include <filesystem>

namespace clash4d {

namespace {

using namespace json_field;

const char* const field_names[7] = {"x numerator", "x denominator", "y numerator", "y denominator",
                                    "z numerator", "z denominator", "label"};

std::string place(std::size_t line, std::size_t column)
{
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// An integer's text: an optional '-' and decimal digits.
mpz_class parse_integer(const std::string& text, const std::string& where, const char* field)
{
  std::size_t digits = text.size() - (text[0] == '-' ? 1 : 0);
  bool ok = digits > 0;
  for (std::size_t i = text.size() - digits; i < text.size() && ok; ++i) ok = text[i] >= '0' && text[i] <= '9';
  if (!ok) {
    std::string shown = text.size() > 40 ? text.substr(0, 40) + "..." : text;
    throw Input_error(where, std::string("the ") + field + " is not an integer: '" + shown + "'");
  }
  if (digits > CLASH4D_MAX_NUMBER_CHARS)
    throw Input_error(where, std::string("the ") + field + " has more than " + std::to_string(CLASH4D_MAX_NUMBER_CHARS) +
                                 " digits",
                      CLASH4D_EXIT_LIMIT);
  long small = 0;
  if (digits <= 18 && std::from_chars(text.data(), text.data() + text.size(), small).ec == std::errc()) return small;
  return mpz_class(text, 10);
}

// One CSV row: a point's three coordinates and the row's label.
struct Csv_row {
  Ccd_query::Point point;
  bool label = false;
};

Csv_row parse_csv_row(const std::string& line, std::size_t line_no)
{
  std::array<std::string, 7> fields;
  std::array<std::size_t, 7> columns{};
  std::size_t count = 0, start = 0;
  for (;;) {
    std::size_t comma = line.find(',', start);
    std::string f = line.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    std::size_t first = f.find_first_not_of(" \t"), last = f.find_last_not_of(" \t");
    if (count < 7) {
      fields[count] = first == std::string::npos ? "" : f.substr(first, last - first + 1);
      columns[count] = start + (first == std::string::npos ? 0 : first) + 1;
    }
    ++count;
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (count != 7)
    throw Input_error("line " + std::to_string(line_no),
                      "expected 7 comma-separated integers (x, y and z as numerator, denominator; a 0/1 label), found " +
                          std::to_string(count) + " fields");
  Csv_row row;
  for (int i = 0; i < 7; ++i) {
    std::string where = place(line_no, columns[i]);
    if (fields[i].empty()) throw Input_error(where, std::string("the ") + field_names[i] + " is missing");
    if (i == 6) {
      if (fields[i] != "0" && fields[i] != "1") throw Input_error(where, "the label is not 0 or 1: '" + fields[i] + "'");
      row.label = fields[i] == "1";
      continue;
    }
    if (i % 2 == 1) continue;
    mpz_class num = parse_integer(fields[i], where, field_names[i]);
    mpz_class den = parse_integer(fields[i + 1], place(line_no, columns[i + 1]), field_names[i + 1]);
    if (den == 0) throw Input_error(place(line_no, columns[i + 1]), std::string("the ") + field_names[i + 1] + " is zero");
    row.point[static_cast<std::size_t>(i / 2)] = quotient_of_integers(num, den);
  }
  return row;
}

bool ends_with(const std::string& s, const char* suffix)
{
  std::string x(suffix);
  return s.size() >= x.size() && s.compare(s.size() - x.size(), x.size(), x) == 0;
}

} // namespace

std::optional<Ccd_type> ccd_type_from_path(const std::string& path)
{
  std::filesystem::path p(path);
  std::vector<std::string> parts;
  for (const auto& part : p) parts.push_back(part.string());
  for (auto it = parts.rbegin(); it != parts.rend(); ++it) {
    if (it->rfind("vertex-face", 0) == 0) return Ccd_type::vertex_face;
    if (it->rfind("edge-edge", 0) == 0) return Ccd_type::edge_edge;
  }
  return std::nullopt;
}

Ccd_reader::Ccd_reader(const std::string& path, std::optional<Ccd_type> type)
  : file_(std::make_unique<std::ifstream>()), in_(file_.get()), format_(Format::csv), type_(type),
    type_given_(type.has_value())
{
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw Input_error("", "is a folder, not a file of queries");
  file_->open(path, std::ios::binary);
  if (!*file_) throw Input_error("", "cannot open the file");
  if (ends_with(path, ".json") || ends_with(path, ".jsonl") || ends_with(path, ".ndjson")) format_ = Format::json_lines;
  else if (!ends_with(path, ".csv")) {
    int c;
    while ((c = file_->peek()) != EOF && std::isspace(c)) file_->get();
    if (c == '{') format_ = Format::json_lines;
  }
  if (!type_) type_ = ccd_type_from_path(path);
  if (format_ == Format::csv && !type_)
    throw Input_error("", "the query type is not known: give --type vf or --type ee, or name the file or a folder "
                          "on its path vertex-face... or edge-edge...");
}

Ccd_reader::Ccd_reader(std::istream& in, Format format, std::optional<Ccd_type> type)
  : in_(&in), format_(format), type_(type), type_given_(type.has_value())
{
  if (format_ == Format::csv && !type_) throw Input_error("", "the query type is not known (--type vf or ee)");
}

bool Ccd_reader::next_line(std::string& line)
{
  if (!std::getline(*in_, line)) return false;
  ++line_;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  if (line.size() > CLASH4D_MAX_CCD_LINE)
    throw Input_error("line " + std::to_string(line_), "longer than the limit of " +
                                                           std::to_string(CLASH4D_MAX_CCD_LINE) + " characters",
                      CLASH4D_EXIT_LIMIT);
  return true;
}

bool Ccd_reader::read_csv(Ccd_query& q)
{
  std::string line;
  Ccd_query::Rows rows;
  std::optional<bool> label;
  std::size_t first_line = 0;
  for (int r = 0; r < 8; ++r) {
    if (!next_line(line)) {
      if (r == 0) return false;
      throw Input_error("line " + std::to_string(line_ + 1), "the file ends inside a query (" + std::to_string(r) +
                                                                 " of its 8 rows): a query is 8 rows");
    }
    if (line.find_first_not_of(" \t") == std::string::npos) {
      if (r == 0 && in_->peek() == EOF) return false;   // a blank last line
      throw Input_error("line " + std::to_string(line_), "a blank line (a query is 8 rows of 7 integers)");
    }
    Csv_row row = parse_csv_row(line, line_);
    rows[static_cast<std::size_t>(r)] = row.point;
    if (r == 0) label = row.label, first_line = line_;
    else if (*label != row.label)
      throw Input_error("line " + std::to_string(line_), "the label differs from the query's first row's (the label "
                                                         "is the same on all 8 rows)");
  }
  q = Ccd_query(*type_, rows);
  q.label = label;
  q.line = first_line;
  return true;
}

bool Ccd_reader::read_json_line(Ccd_query& q)
{
  std::string line;
  do {
    if (!next_line(line)) return false;
  } while (line.find_first_not_of(" \t") == std::string::npos);
  std::string at_line = "line " + std::to_string(line_);
  Json_value v;
  try {
    v = read_json_text(line);
  } catch (const Input_error& e) {
    // The parser counts within the line: its "line 1" is this line.
    std::string p = e.place();
    if (p.rfind("line 1", 0) == 0) p = at_line + p.substr(6);
    throw Input_error(p.empty() ? at_line : p, e.what(), e.exit_code());
  }
  try {
    expect_kind(v, Kind::Object, "");
    expect_keys(v, {"type", "t0", "t1", "label", "meta"}, "");
    std::optional<Ccd_type> type = type_;
    if (const Json_value* t = v.find("type")) {
      expect_kind(*t, Kind::String, "type");
      auto named = ccd_type_from_name(t->text);
      if (!named) throw Input_error("type", "expected \"vertex-face\" or \"edge-edge\", found \"" + t->text + "\"");
      if (type_given_ && *named != *type_)
        throw Input_error("type", std::string("\"") + t->text + "\" differs from --type " + ccd_type_name(*type_));
      type = named;
    }
    if (!type) throw Input_error("", "the query type is not known: give \"type\", --type, or a vertex-face or "
                                     "edge-edge file or folder name");
    Ccd_query::Rows rows;
    for (int half = 0; half < 2; ++half) {
      const char* key = half == 0 ? "t0" : "t1";
      const Json_value& pts = required(v, key, "");
      expect_kind(pts, Kind::Array, key);
      if (pts.items.size() != 4)
        throw Input_error(key, "expected the 4 vertices, found " + std::to_string(pts.items.size()));
      for (std::size_t i = 0; i < 4; ++i) rows[i + 4 * half] = read_array<3>(pts.items[i], at(key, i));
    }
    q = Ccd_query(*type, rows);
    q.line = line_;
    if (const Json_value* l = v.find("label")) {
      if (l->kind == Kind::Boolean) q.label = l->boolean;
      else if (l->kind == Kind::Number && (l->text == "0" || l->text == "1")) q.label = l->text == "1";
      else throw Input_error("label", "expected true, false, 0 or 1");
    }
  } catch (const Input_error& e) {
    throw Input_error(e.place().empty() ? at_line : at_line + ": " + e.place(), e.what(), e.exit_code());
  }
  return true;
}

std::size_t Ccd_reader::read(std::size_t count, std::vector<Ccd_query>& out)
{
  std::size_t n = 0;
  for (; n < count; ++n) {
    Ccd_query q;
    if (!(format_ == Format::csv ? read_csv(q) : read_json_line(q))) break;
    out.push_back(std::move(q));
  }
  return n;
}

} // namespace clash4d

#include "ccd/Ccd_reader.h"

#include "scene/Input_error.h"
#include "scene/Json_fields.h"
#include "scene/Json_reader.h"
#include "scene/Number_text.h"
#include <tbb/parallel_for.h>
#include <cctype>
#include <charconv>
#include <filesystem>
#include <string_view>

namespace clash4d {

namespace {

using namespace json_field;

const char* const field_names[7] = {"x numerator", "x denominator", "y numerator", "y denominator",
                                    "z numerator", "z denominator", "label"};

std::string place(std::size_t line, std::size_t column)
{
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// One field of a CSV row: its text (spaces trimmed) and where it starts.
struct Field {
  std::string_view text;
  std::size_t column = 0;   // from 1
};

// An integer's text: an optional '-' and decimal digits. The place is made
// only for an error (a row's seven fields are read per query).
mpz_class parse_integer(const Field& f, std::size_t line, const char* name)
{
  std::string_view text = f.text;
  std::size_t digits = text.size() - (!text.empty() && text[0] == '-' ? 1 : 0);
  bool ok = digits > 0;
  for (std::size_t i = text.size() - digits; i < text.size() && ok; ++i) ok = text[i] >= '0' && text[i] <= '9';
  if (!ok) {
    std::string shown(text.substr(0, 40));
    throw Input_error(place(line, f.column), std::string("the ") + name + " is not an integer: '" + shown +
                                                 (text.size() > 40 ? "...'" : "'"));
  }
  if (digits > CLASH4D_MAX_NUMBER_CHARS)
    throw Input_error(place(line, f.column),
                      std::string("the ") + name + " has more than " + std::to_string(CLASH4D_MAX_NUMBER_CHARS) + " digits",
                      CLASH4D_EXIT_LIMIT);
  long small = 0;
  if (digits <= 18 && std::from_chars(text.data(), text.data() + text.size(), small).ec == std::errc()) return small;
  return mpz_class(std::string(text), 10);
}

// One CSV row: a point's three coordinates and the row's label.
struct Csv_row {
  Ccd_query::Point point;
  bool label = false;
};

// The row's fields, trimmed; their count (7 expected).
std::size_t split_row(std::string_view line, std::array<Field, 7>& fields)
{
  std::size_t count = 0, start = 0;
  for (;;) {
    std::size_t comma = line.find(',', start);
    std::string_view f = line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
    std::size_t first = f.find_first_not_of(" \t"), last = f.find_last_not_of(" \t");
    if (count < 7)
      fields[count] = first == std::string_view::npos ? Field{std::string_view(), start + 1}
                                                      : Field{f.substr(first, last - first + 1), start + first + 1};
    ++count;
    if (comma == std::string_view::npos) return count;
    start = comma + 1;
  }
}

Csv_row parse_csv_row(const std::string& line, std::size_t line_no)
{
  std::array<Field, 7> fields;
  std::size_t count = split_row(line, fields);
  if (count != 7)
    throw Input_error("line " + std::to_string(line_no),
                      "expected 7 comma-separated integers (x, y and z as numerator, denominator; a 0/1 label), found " +
                          std::to_string(count) + " fields");
  for (int i = 0; i < 7; ++i)
    if (fields[i].text.empty())
      throw Input_error(place(line_no, fields[i].column), std::string("the ") + field_names[i] + " is missing");
  Csv_row row;
  const Field& label = fields[6];
  if (label.text != "0" && label.text != "1")
    throw Input_error(place(line_no, label.column), "the label is not 0 or 1: '" + std::string(label.text) + "'");
  row.label = label.text == "1";
  for (int i = 0; i < 6; i += 2) {
    mpz_class num = parse_integer(fields[i], line_no, field_names[i]);
    mpz_class den = parse_integer(fields[i + 1], line_no, field_names[i + 1]);
    if (den == 0)
      throw Input_error(place(line_no, fields[i + 1].column), std::string("the ") + field_names[i + 1] + " is zero");
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
  if (line.size() > CLASH4D_MAX_CCD_LINE) {
    line.clear();
    throw Input_error("line " + std::to_string(line_), "longer than the limit of " +
                                                           std::to_string(CLASH4D_MAX_CCD_LINE) + " characters",
                      CLASH4D_EXIT_LIMIT);
  }
  return true;
}

// A query's text: its lines (8 for CSV, 1 for JSON lines) and the number of
// the first.
struct Ccd_reader::Text {
  std::vector<std::string> lines;
  std::size_t first_line = 0;
};

bool Ccd_reader::take_csv(Text& t)
{
  t.lines.assign(8, std::string());
  t.first_line = line_ + 1;
  for (int r = 0; r < 8; ++r) {
    std::string& line = t.lines[static_cast<std::size_t>(r)];
    if (!next_line(line)) {
      if (r == 0) return false;
      throw Input_error("line " + std::to_string(line_ + 1), "the file ends inside a query (" + std::to_string(r) +
                                                                 " of its 8 rows): a query is 8 rows");
    }
    if (line.find_first_not_of(" \t") == std::string::npos) {
      if (r == 0 && in_->peek() == EOF) return false;   // a blank last line
      line.clear();
      throw Input_error("line " + std::to_string(line_), "a blank line (a query is 8 rows of 7 integers)");
    }
  }
  return true;
}

bool Ccd_reader::take_json_line(Text& t)
{
  t.lines.resize(1);
  do {
    if (!next_line(t.lines[0])) return false;
  } while (t.lines[0].find_first_not_of(" \t") == std::string::npos);
  t.first_line = line_;
  return true;
}

Ccd_query Ccd_reader::parse_csv(const Text& t) const
{
  Ccd_query::Rows rows;
  std::optional<bool> label;
  for (std::size_t r = 0; r < 8; ++r) {
    std::size_t line = t.first_line + r;
    Csv_row row = parse_csv_row(t.lines[r], line);
    rows[r] = row.point;
    if (r == 0) label = row.label;
    else if (*label != row.label)
      throw Input_error("line " + std::to_string(line), "the label differs from the query's first row's (the label "
                                                        "is the same on all 8 rows)");
  }
  Ccd_query q(*type_, rows);
  q.label = label;
  q.line = t.first_line;
  return q;
}

Ccd_query Ccd_reader::parse_json_line(const Text& t) const
{
  std::string at_line = "line " + std::to_string(t.first_line);
  Json_value v;
  try {
    v = read_json_text(t.lines[0]);
  } catch (const Input_error& e) {
    // The parser counts within the line: its "line 1" is this line.
    std::string p = e.place();
    if (p.rfind("line 1", 0) == 0) p = at_line + p.substr(6);
    throw Input_error(p.empty() ? at_line : p, e.what(), e.exit_code());
  }
  try {
    return json_query(v, t.first_line);
  } catch (const Input_error& e) {
    throw Input_error(e.place().empty() ? at_line : at_line + ": " + e.place(), e.what(), e.exit_code());
  }
}

Ccd_query Ccd_reader::json_query(const Json_value& v, std::size_t line) const
{
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
    if (pts.items.size() != 4) throw Input_error(key, "expected the 4 vertices, found " + std::to_string(pts.items.size()));
    for (std::size_t i = 0; i < 4; ++i) rows[i + 4 * half] = read_array<3>(pts.items[i], at(key, i));
  }
  Ccd_query q(*type, rows);
  q.line = line;
  if (const Json_value* l = v.find("label")) {
    if (l->kind == Kind::Boolean) q.label = l->boolean;
    else if (l->kind == Kind::Number && (l->text == "0" || l->text == "1")) q.label = l->text == "1";
    else throw Input_error("label", "expected true, false, 0 or 1");
  }
  return q;
}

// The lines of up to `count` queries are taken in order (the file's
// structure: rows per query, blank lines, lengths), then parsed on all
// cores. The error is the first bad place in file order: a row before a
// break in the structure is parsed first.
std::size_t Ccd_reader::read(std::size_t count, std::vector<Ccd_query>& out)
{
  std::vector<Text> texts;
  std::optional<Input_error> broken;
  Text t;
  try {
    while (texts.size() < count && (format_ == Format::csv ? take_csv(t) : take_json_line(t))) texts.push_back(t);
  } catch (const Input_error& e) {
    broken = e;
  }
  std::size_t base = out.size();
  out.resize(base + texts.size());
  std::vector<std::optional<Input_error>> errors(texts.size());
  tbb::parallel_for(std::size_t(0), texts.size(), [&](std::size_t i) {
    try {
      out[base + i] = format_ == Format::csv ? parse_csv(texts[i]) : parse_json_line(texts[i]);
    } catch (const Input_error& e) {
      errors[i] = e;
    }
  });
  for (const auto& e : errors)
    if (e) throw *e;
  if (broken) {
    if (format_ == Format::csv)   // the rows of the query the break cut short
      for (std::size_t r = 0; r < t.lines.size() && t.first_line + r <= line_; ++r)
        if (!t.lines[r].empty()) parse_csv_row(t.lines[r], t.first_line + r);
    throw *broken;
  }
  return texts.size();
}

} // namespace clash4d

#include "compare/Ccd_query_files.h"

#include "ccd/Ccd_reader.h"
#include "scene/Input_error.h"
#include "scene/Json_reader.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace clash4d {

namespace {

using json = nlohmann::ordered_json;

bool has_extension(const std::string& path, std::initializer_list<const char*> extensions)
{
  std::string e = std::filesystem::path(path).extension().string();
  for (const char* x : extensions)
    if (e == x) return true;
  return false;
}

// The first non-blank line, at most a CCD line long (a longer one is no query).
std::string first_line(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  while (std::getline(in, line) && line.find_first_not_of(" \t\r") == std::string::npos) {}
  return line.size() > CLASH4D_MAX_CCD_LINE ? "" : line;
}

json point_json(const Ccd_query::Point& p)
{
  return {to_string(p[0]), to_string(p[1]), to_string(p[2])};
}

} // namespace

bool is_ccd_query_file(const std::string& path)
{
  if (has_extension(path, {".csv", ".jsonl", ".ndjson"})) return true;
  try {
    Json_value v = read_json_text(first_line(path));
    return v.kind == Json_value::Kind::Object && v.find("t0") != nullptr;
  } catch (const Input_error&) {
    return false;   // not one object on its first line: a scene (or nothing), which the scene reader judges
  }
}

std::vector<Ccd_query> read_ccd_queries(const std::string& path, std::optional<Ccd_type> type)
{
  Ccd_reader reader(path, type);
  std::vector<Ccd_query> out;
  while (reader.read(1 << 14, out) > 0) {}
  return out;
}

std::string ccd_query_csv(const Ccd_query& q, bool label)
{
  std::string out;
  for (const Ccd_query::Point& p : q.rows()) {
    for (const Rational& x : p)
      out += mpz_class(mpq_numref(x.mpq())).get_str() + "," + mpz_class(mpq_denref(x.mpq())).get_str() + ",";
    out += label ? "1\n" : "0\n";
  }
  return out;
}

json ccd_query_json(const Ccd_query& q)
{
  json t0 = json::array(), t1 = json::array();
  for (int i = 0; i < 4; ++i) {
    t0.push_back(point_json(q.row(i)));
    t1.push_back(point_json(q.row(i + 4)));
  }
  return {{"type", ccd_type_name(q.type())}, {"t0", t0}, {"t1", t1}};
}

Ccd_query ccd_query_from_json(const json& j)
{
  std::istringstream in(j.dump());
  Ccd_reader reader(in, Ccd_reader::Format::json_lines, std::nullopt);
  std::vector<Ccd_query> one;
  if (reader.read(1, one) != 1) throw Input_error("", "no CCD query");
  return one.front();
}

} // namespace clash4d

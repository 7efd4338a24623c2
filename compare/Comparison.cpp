#include "compare/Comparison.h"

#include <stdexcept>

namespace clash4d {
namespace {

using json = nlohmann::ordered_json;

template <class T>
json optional_json(const std::optional<T>& v)
{
  return v ? json(*v) : json();
}

json located_json(const std::optional<Located>& l, bool with_t)
{
  if (!l) return json();
  json j = {{"objects", {l->objects[0], l->objects[1]}}};
  if (with_t) j["t"] = l->t;
  j["point"] = l->point ? json(*l->point) : json();
  return j;
}

// ------------------------------------------------------------------ reading

[[noreturn]] void wrong(const std::string& where, const char* expected)
{
  throw std::runtime_error("comparison: " + where + ": expected " + expected);
}

const json* member(const json& j, const char* key)
{
  auto it = j.find(key);
  return it == j.end() || it->is_null() ? nullptr : &*it;
}

std::optional<std::string> opt_string(const json& j, const char* key, const std::string& where)
{
  const json* v = member(j, key);
  if (!v) return std::nullopt;
  if (!v->is_string()) wrong(where + "." + key, "a string");
  return v->get<std::string>();
}

std::optional<bool> opt_bool(const json& j, const char* key, const std::string& where)
{
  const json* v = member(j, key);
  if (!v) return std::nullopt;
  if (!v->is_boolean()) wrong(where + "." + key, "true or false");
  return v->get<bool>();
}

std::optional<double> opt_number(const json& j, const char* key, const std::string& where)
{
  const json* v = member(j, key);
  if (!v) return std::nullopt;
  if (!v->is_number()) wrong(where + "." + key, "a number");
  return v->get<double>();
}

template <std::size_t N>
std::array<std::string, N> strings(const json& a, const std::string& where)
{
  if (!a.is_array() || a.size() != N) wrong(where, N == 2 ? "2 strings" : "4 strings");
  std::array<std::string, N> out;
  for (std::size_t i = 0; i < N; ++i) {
    if (!a[i].is_string()) wrong(where, "strings");
    out[i] = a[i].get<std::string>();
  }
  return out;
}

std::optional<Located> opt_located(const json& j, const char* key, const std::string& where)
{
  const json* v = member(j, key);
  if (!v) return std::nullopt;
  std::string here = where + "." + key;
  if (!v->is_object()) wrong(here, "an object");
  Located l;
  if (const json* o = member(*v, "objects")) l.objects = strings<2>(*o, here + ".objects");
  if (const json* p = member(*v, "point")) l.point = strings<4>(*p, here + ".point");
  l.t = opt_string(*v, "t", here).value_or("");
  return l;
}

Subject_row row_from_json(const json& s, const std::string& where)
{
  if (!s.is_object()) wrong(where, "an object");
  Subject_row r;
  r.subject = opt_string(s, "subject", where).value_or("");
  r.semantics = opt_string(s, "semantics", where).value_or("regularised");
  r.tolerance = opt_number(s, "tolerance", where);
  r.reference = opt_bool(s, "reference", where).value_or(false);
  r.ok = opt_bool(s, "ok", where).value_or(true);
  r.error = opt_string(s, "error", where).value_or("");
  r.skipped = opt_string(s, "skipped", where);
  r.collide = opt_bool(s, "collide", where);
  r.witness = opt_located(s, "witness", where);
  r.witness_valid = opt_bool(s, "witness_valid", where);
  r.earliest = opt_located(s, "earliest", where);
  r.t_error = opt_string(s, "t_error", where);
  r.seconds = opt_number(s, "seconds", where);
  r.agrees = opt_bool(s, "agrees", where);
  r.cause = opt_string(s, "cause", where);
  return r;
}

} // namespace

Subject_row Subject_run::row(bool reference) const
{
  Subject_row s;
  s.subject = subject;
  s.semantics = semantics;
  s.tolerance = tolerance;
  s.reference = reference;
  s.ok = ok;
  s.error = error;
  s.seconds = seconds;
  if (!skipped.empty()) s.skipped = skipped;   // no answer: nothing to hold against exact
  return s;
}

const Subject_row* Comparison::reference() const { return reference_in("regularised"); }

const Subject_row* Comparison::reference_in(const std::string& semantics) const
{
  for (const auto& s : subjects)
    if (s.reference && s.semantics == semantics) return &s;
  return semantics == "regularised" ? find("exact") : nullptr;
}

const Subject_row* Comparison::find(const std::string& subject) const
{
  for (const auto& s : subjects)
    if (s.subject == subject) return &s;
  return nullptr;
}

std::vector<std::string> Comparison::disagreement_keys() const
{
  std::vector<std::string> keys;
  for (const auto& d : disagreements) keys.push_back(d.subject + ": " + d.cause);
  return keys;
}

bool Comparison::has_failure() const
{
  for (const auto& s : subjects)
    if (s.failed()) return true;
  return false;
}

Comparison Comparison::reproducible() const
{
  Comparison c = *this;
  for (auto& s : c.subjects) s.seconds.reset();
  return c;
}

json row_json(const Subject_row& s)
{
  json r = {{"subject", s.subject}, {"reference", s.reference}, {"ok", s.ok}, {"error", s.error},
            {"skipped", optional_json(s.skipped)}, {"collide", optional_json(s.collide)},
            {"witness", located_json(s.witness, false)}, {"witness_valid", optional_json(s.witness_valid)},
            {"earliest", located_json(s.earliest, true)}, {"t_error", optional_json(s.t_error)}};
  if (s.seconds) r["seconds"] = *s.seconds;
  r["agrees"] = optional_json(s.agrees);
  r["cause"] = optional_json(s.cause);
  r["semantics"] = s.semantics;
  if (s.tolerance) r["tolerance"] = *s.tolerance;
  return r;
}

json Comparison::to_json() const
{
  json rows = json::array(), list = json::array();
  for (const Subject_row& s : subjects) rows.push_back(row_json(s));
  for (const Disagreement& d : disagreements)
    list.push_back({{"subject", d.subject}, {"semantics", d.semantics}, {"cause", d.cause}, {"detail", d.detail}});
  return {{"file", file}, {"name", name}, {"closed_touch", optional_json(closed_touch)}, {"subjects", rows},
          {"disagreements", list}};
}

Comparison Comparison::from_json(const json& j)
{
  if (!j.is_object()) wrong("comparison", "an object");
  Comparison c;
  c.file = opt_string(j, "file", "comparison").value_or("");
  c.name = opt_string(j, "name", "comparison").value_or("");
  c.closed_touch = opt_bool(j, "closed_touch", "comparison");
  if (const json* rows = member(j, "subjects")) {
    if (!rows->is_array()) wrong("subjects", "a list");
    for (std::size_t i = 0; i < rows->size(); ++i)
      c.subjects.push_back(row_from_json((*rows)[i], "subjects[" + std::to_string(i) + "]"));
  }
  if (const json* list = member(j, "disagreements")) {
    if (!list->is_array()) wrong("disagreements", "a list");
    for (std::size_t i = 0; i < list->size(); ++i) {
      std::string where = "disagreements[" + std::to_string(i) + "]";
      const json& d = (*list)[i];
      if (!d.is_object()) wrong(where, "an object");
      c.disagreements.push_back({opt_string(d, "subject", where).value_or(""), opt_string(d, "cause", where).value_or(""),
                                 opt_string(d, "detail", where).value_or(""),
                                 opt_string(d, "semantics", where).value_or("regularised")});
    }
  }
  return c;
}

} // namespace clash4d

#define BOOST_TEST_MODULE report
#include <boost/test/unit_test.hpp>

#include "compare/Ccd_comparer.h"
#include "compare/Report_writer.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace clash4d;
using json = nlohmann::ordered_json;
namespace fs = std::filesystem;

namespace {

Report_case make_case(const std::string& file, const std::string& scene, const std::string& comparison)
{
  return {file, read_scene(read_json_text(scene)), Comparison::from_json(json::parse(comparison)), ""};
}

// A ram moving in -x hits a box at t = 2: every subject agrees.
Report_case colliding_case()
{
  return make_case("ram.json", R"({"format": "clash4d-scene/1", "name": "ram", "time": [0, 10], "objects": [
      {"name": "box", "shape": {"block": {"min": [0,0,0], "max": [1,1,1]}}},
      {"name": "ram", "shape": {"block": {"min": [3,0,0], "max": [4,1,1]}}, "motion": "rest until 0 vel -1 0 0 until 5 rest"}]})",
    R"({"file": "ram.json", "name": "ram", "closed_touch": null, "subjects": [
      {"subject": "exact", "reference": true, "ok": true, "error": "", "collide": true,
       "witness": {"objects": ["box","ram"], "point": ["3/4","1/2","1/2","5/2"]}, "witness_valid": true,
       "earliest": {"objects": ["box","ram"], "t": "2", "point": ["1","1/2","1/2","2"]},
       "t_error": "0", "seconds": 0.0012, "agrees": true, "cause": null},
      {"subject": "double", "reference": false, "ok": true, "error": "", "collide": true,
       "witness": {"objects": ["box","ram"], "point": ["0.75","0.5","0.5","2.5"]}, "witness_valid": true,
       "earliest": null, "t_error": null, "seconds": 0.0001, "agrees": true, "cause": null},
      {"subject": "double tol=1e-09", "reference": false, "ok": true, "error": "", "collide": true,
       "witness": {"objects": ["box","ram"], "point": ["0.75","0.5","0.5","2.5"]}, "witness_valid": true,
       "earliest": null, "t_error": null, "seconds": 0.0001, "agrees": true, "cause": null},
      {"subject": "exact-rounded", "reference": false, "ok": true, "error": "", "collide": true,
       "witness": {"objects": ["box","ram"], "point": ["3/4","1/2","1/2","5/2"]}, "witness_valid": true,
       "earliest": null, "t_error": null, "seconds": 0.001, "agrees": true, "cause": null}],
     "disagreements": []})");
}

// Two blocks touching along a face: double says collision (contact), the
// tolerance subject failed.
Report_case contact_case()
{
  return make_case("dir/<touch>.json", R"json({"format": "clash4d-scene/1", "name": "touch & go", "time": [0, 1], "objects": [
      {"name": "a<b&\"c\"", "shape": {"block": {"min": [0,0,0], "max": [1,1,1]}}},
      {"name": "d", "shape": {"block": {"min": [1,0,0], "max": [2,1,1]}}}]})json",
    R"json({"file": "dir/<touch>.json", "name": "touch & go", "closed_touch": true, "subjects": [
      {"subject": "exact", "reference": true, "ok": true, "error": "", "collide": false,
       "witness": null, "witness_valid": null, "earliest": null, "t_error": null,
       "seconds": 0.002, "agrees": true, "cause": null},
      {"subject": "double", "reference": false, "ok": true, "error": "", "collide": true,
       "witness": {"objects": ["a<b&\"c\"","d"], "point": ["1","0.5","0.5","0.5"]}, "witness_valid": false,
       "earliest": null, "t_error": null, "seconds": 0.0001, "agrees": false, "cause": "contact"},
      {"subject": "double tol=1e-09", "reference": false, "ok": false, "error": "ran out of <memory> & time",
       "collide": null, "witness": null, "witness_valid": null, "earliest": null, "t_error": null,
       "seconds": 0.0001, "agrees": false, "cause": null},
      {"subject": "exact-rounded", "reference": false, "ok": true, "error": "", "collide": false,
       "witness": null, "witness_valid": null, "earliest": null, "t_error": null,
       "seconds": 0.002, "agrees": true, "cause": null}],
     "disagreements": [{"subject": "double", "cause": "contact",
       "detail": "double says collision, exact says none: the closed objects touch"}]})json");
}

// A block sliding on an unbounded floor (clipped in the drawing).
Report_case floor_case()
{
  return make_case("floor.json", R"({"format": "clash4d-scene/1", "time": [0, 4], "objects": [
      {"name": "floor", "shape": {"halfspace": [0,0,1,0]}},
      {"name": "puck", "shape": {"block": {"min": [0,0,0], "max": [1,1,1]}}, "motion": "vel 1 0 0 until 2 vel -1 1 0"}]})",
    R"({"file": "floor.json", "name": "", "closed_touch": true, "subjects": [
      {"subject": "exact", "reference": true, "ok": true, "error": "", "collide": false, "witness": null,
       "witness_valid": null, "earliest": null, "t_error": null, "seconds": 0.003, "agrees": true, "cause": null},
      {"subject": "double", "reference": false, "ok": true, "error": "", "collide": false, "witness": null,
       "witness_valid": null, "earliest": null, "t_error": null, "seconds": 0.001, "agrees": true, "cause": null}],
     "disagreements": []})");
}

std::string slurp(const fs::path& p)
{
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

std::size_t count(const std::string& text, const std::string& what)
{
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

struct Written_report {
  fs::path dir = fs::temp_directory_path() / ("clash4d_test_report_" + std::to_string(::getpid()));
  Written_report()
  {
    fs::remove_all(dir);
    Report_case touch = contact_case();
    touch.family = "static_touch";   // as a fuzz finding of that family
    write_report({colliding_case(), touch, floor_case()}, (dir / "out").string());
  }
  ~Written_report() { fs::remove_all(dir); }
  std::string read(const char* name) const { return slurp(dir / "out" / name); }
};

} // namespace

BOOST_FIXTURE_TEST_SUITE(written, Written_report)

BOOST_AUTO_TEST_CASE(three_files_and_no_temporaries)
{
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir / "out")) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  BOOST_TEST(names == (std::vector<std::string>{"index.html", "junit.xml", "report.json"}), boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(report_json_counts)
{
  json r = json::parse(read("report.json"));
  BOOST_TEST(r["format"] == "clash4d-report/1");
  BOOST_TEST(r["cases"].size() == 3u);
  BOOST_TEST(r["cases"][1]["subjects"][1]["cause"] == "contact");
  const json& s = r["summary"];
  BOOST_TEST(s["scenes"] == 3);
  BOOST_TEST(s["scenes_agreeing"] == 2);
  BOOST_TEST(s["scenes_disagreeing"] == 1);
  BOOST_TEST(s["scenes_with_errors"] == 1);
  BOOST_TEST(s["answers"] == 7);
  BOOST_TEST(s["agreements"] == 5);
  BOOST_TEST(s["disagreements"] == 1);
  BOOST_TEST(s["errors"] == 1);
  BOOST_TEST(s["by_cause"]["contact"] == 1);
  BOOST_TEST(s["by_cause"]["arithmetic"] == 0);
  BOOST_TEST(s["by_subject"]["double"]["answers"] == 3);
  BOOST_TEST(s["by_subject"]["double"]["disagreements"] == 1);
  BOOST_TEST(s["by_subject"]["double tol=1e-09"]["errors"] == 1);
  BOOST_TEST(!s["by_subject"].contains("exact"));
  // Findings by family: double's one disagreement is in the touching case's
  // family; the tolerance subject's error has no cause, and the other cases
  // have no family.
  BOOST_TEST(s["by_subject"]["double"]["by_family"].size() == 1u);
  BOOST_TEST(s["by_subject"]["double"]["by_family"]["static_touch"] == 1);
  BOOST_TEST(s["by_subject"]["double tol=1e-09"]["by_family"].empty());
  // Per subject: its semantics and mean time per query, exact's beside them
  // (the cases' seconds: double 0.0001, 0.0001, 0.001; exact 0.0012, 0.002, 0.003).
  BOOST_TEST(s["by_subject"]["double"]["semantics"] == "regularised");
  BOOST_TEST(s["by_subject"]["double"]["seconds_per_query"].get<double>() == 0.0004, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(s["reference_seconds_per_query"].get<double>() == 0.0062 / 3, boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(junit_counts_and_escaping)
{
  std::string x = read("junit.xml");
  BOOST_TEST(count(x, "<testsuite ") == 1u);
  BOOST_TEST(count(x, "<testcase ") == 10u);
  BOOST_TEST(count(x, "<failure ") == 1u);
  BOOST_TEST(count(x, "<error ") == 1u);
  BOOST_TEST(x.find("tests=\"10\" failures=\"1\" errors=\"1\"") != std::string::npos);
  BOOST_TEST(x.find("<failure message=\"contact\" type=\"disagreement\">") != std::string::npos);
  BOOST_TEST(x.find("classname=\"dir/&lt;touch&gt;.json\"") != std::string::npos);
  BOOST_TEST(x.find("ran out of &lt;memory&gt; &amp; time") != std::string::npos);
  BOOST_TEST(x.find("<touch>") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(html_is_self_contained_and_escaped)
{
  std::string h = read("index.html");
  BOOST_TEST(count(h, "<svg") == 9u);
  BOOST_TEST(count(h, "http://") == 0u);
  BOOST_TEST(count(h, "https://") == 0u);
  BOOST_TEST(count(h, "<script") == 0u);
  BOOST_TEST(h.find("a&lt;b&amp;&quot;c&quot;") != std::string::npos);
  BOOST_TEST(h.find("a<b&\"c\"") == std::string::npos);
  BOOST_TEST(h.find("dir/&lt;touch&gt;.json") != std::string::npos);
  BOOST_TEST(h.find("<touch>") == std::string::npos);
  // The summary row: 3 scenes, 2 agreeing, 1 disagreeing, 1 with errors,
  // 7 answers, 5 agreements, 1 disagreement, 1 error.
  BOOST_TEST(h.find("<td class=\"n\">3</td><td class=\"n\">2</td><td class=\"n\">1</td><td class=\"n\">1</td>"
                    "<td class=\"n\">7</td><td class=\"n\">5</td><td class=\"n\">1</td><td class=\"n\">1</td>") != std::string::npos);
  BOOST_TEST(h.find("<p>double, findings by family: static_touch 1;</p>") != std::string::npos);
  // The disagreeing case comes first.
  BOOST_TEST(h.find("id=\"case-1\"") < h.find("id=\"case-0\""));
  BOOST_TEST(h.find("id=\"case-0\"") < h.find("id=\"case-2\""));
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_CASE(unwritable_directory_is_a_clear_error)
{
  fs::path file = fs::temp_directory_path() / ("clash4d_test_report_file_" + std::to_string(::getpid()));
  std::ofstream(file) << "x";
  BOOST_CHECK_EXCEPTION(write_report({colliding_case()}, (file / "out").string()), std::runtime_error,
                        [&](const std::runtime_error& e) { return std::string(e.what()).find(file.string()) != std::string::npos; });
  fs::remove(file);
}

// A CCD query's case (compare/Ccd_comparer.h) next to a scene's: its rows in
// every file, its vertices in place of diagrams, counted as a query.
BOOST_AUTO_TEST_CASE(ccd_queries_have_rows_beside_scenes)
{
  Ccd_query::Rows rows;   // a vertex falling through the triangle z = 0 at t = 1/2
  rows[0] = {Rational(1, 4), Rational(1, 4), Rational(1)};
  rows[4] = {Rational(1, 4), Rational(1, 4), Rational(-1)};
  for (int k : {0, 4}) {
    rows[k + 1] = {Rational(0), Rational(0), Rational(0)};
    rows[k + 2] = {Rational(1), Rational(0), Rational(0)};
    rows[k + 3] = {Rational(0), Rational(1), Rational(0)};
  }
  Ccd_query q(Ccd_type::vertex_face, rows);
  q.line = 9;
  Ccd_compare_options o;
  o.earliest = true;
  fs::path dir = fs::temp_directory_path() / ("clash4d_test_report_ccd_" + std::to_string(::getpid()));
  write_report({colliding_case(), ccd_report_case("q.jsonl", compare_query(q, "q.jsonl", 2, o), "vf-face")},
               (dir / "out").string());
  json r = json::parse(slurp(dir / "out" / "report.json"));
  BOOST_TEST(r["summary"]["scenes"] == 1);
  BOOST_TEST(r["summary"]["queries"] == 1);
  BOOST_TEST(r["summary"]["scenes_agreeing"] == 2);
  const json& c = r["cases"][1];
  BOOST_TEST(c["index"] == 2);
  BOOST_TEST(c["line"] == 9);
  BOOST_TEST(c["query"]["t1"][0][2] == "-1");
  BOOST_TEST(c["subjects"][0]["t"] == "1/2");
  BOOST_TEST(!c["subjects"][0].contains("witness"));
  std::string x = slurp(dir / "out" / "junit.xml"), h = slurp(dir / "out" / "index.html");
  BOOST_TEST(count(x, "classname=\"q.jsonl: query 2 (line 9)\"") == 4u);   // exact, double, double tol, exact-rounded
  BOOST_TEST(h.find("<td>v</td><td><span class=\"mono\">(1/4, 1/4, 1)</span></td>") != std::string::npos);
  BOOST_TEST(h.find("<dt>family</dt><dd>vf-face</dd>") != std::string::npos);
  BOOST_TEST(count(h, "<svg") == 3u);   // the scene's diagrams only
  fs::remove_all(dir);
}

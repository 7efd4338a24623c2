#define BOOST_TEST_MODULE report
#include <boost/test/unit_test.hpp>

#include "compare/Ccd_comparer.h"
#include "compare/Comparer.h"
#include "compare/Decimal_text.h"
#include "compare/Display_mesh.h"
#include "compare/Report_writer.h"
#include "compare/Scene_view.h"
#include "float/Double_kernel.h"
#include "model/Model_builder.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"
#include <filesystem>
#include <fstream>
#include <regex>
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
  std::vector<std::string> expected{"index.html", "junit.xml", "report.json"};
#ifdef CLASH4D_THREE_JS
  expected.push_back("three.min.js");   // the 3D views' library, beside the page
#endif
  BOOST_TEST(names == expected, boost::test_tools::per_element());
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
  // Three diagrams per scene, and three zoomed on the ram's contact (the one
  // t*); a time axis per scene, t* marked on the ram's.
  BOOST_TEST(count(h, "<svg class=\"qt\"") == 12u);
  BOOST_TEST(count(h, "<svg class=\"time-axis\"") == 3u);
  BOOST_TEST(count(h, "<g class=\"t-star\" data-t=\"2\" data-exact=\"2\">") == 1u);
  BOOST_TEST(count(h, "http://") == 0u);
  BOOST_TEST(count(h, "https://") == 0u);
  // One 3D view per scene; three.js from the report folder, then the views' script.
  BOOST_TEST(count(h, "<canvas") == 3u);
  BOOST_TEST(count(h, "<script src=\"three.min.js\"></script>") == 1u);
  BOOST_TEST(count(h, "<script") == 5u);
  BOOST_TEST(count(h, "</script>") == 5u);
  // In the views' JSON, names keep no markup: a<b&"c" as JSON escapes.
  BOOST_TEST(h.find("\"a\\u003cb\\u0026\\\"c\\\"\"") != std::string::npos);
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
  BOOST_TEST(h.find("<td>v</td><td><span class=\"mono\">(<code class=\"whole\">1/4</code> <span class=\"approx\">(\xE2\x89\x88 0.25)</span>, "
                    "<code class=\"whole\">1/4</code> <span class=\"approx\">(\xE2\x89\x88 0.25)</span>, <code class=\"whole\">1</code>)</span></td>") != std::string::npos);
  BOOST_TEST(h.find("<dt>family</dt><dd>vf-face</dd>") != std::string::npos);
  BOOST_TEST(count(h, "<svg class=\"qt\"") == 6u);   // the scene's diagrams only (and their zoom on its t*)
  BOOST_TEST(count(h, "<svg class=\"time-axis\"") == 1u);   // the scene's, none for the query
  fs::remove_all(dir);
}

// ---------------------------------------------------------------- 3D view

namespace {

Csg_model<double> model_of(const std::string& shape)
{
  Scene s = read_scene(read_json_text(R"({"format": "clash4d-scene/1", "time": [0, 1], "objects": [{"name": "o", "shape": )" +
                                      shape +
                                      R"(}, {"name": "far", "shape": {"block": {"min": [9,9,9], "max": [10,10,10]}}}]})"));
  Double_kernel k;
  return Model_builder<Double_kernel>(k).build(s.objects[0].shape);
}

// The mesh's extent along each axis: {min x, max x, min y, ...}.
std::array<double, 6> extent(const Display_mesh& m)
{
  std::array<double, 6> e{INFINITY, -INFINITY, INFINITY, -INFINITY, INFINITY, -INFINITY};
  for (const auto& v : m.vertices)
    for (int a = 0; a < 3; ++a) { e[2 * a] = std::min(e[2 * a], v[a]); e[2 * a + 1] = std::max(e[2 * a + 1], v[a]); }
  return e;
}

const std::array<double, 3> lo{-1, -1, -1}, hi{2, 2, 2};

} // namespace

// The unit cube: 8 corners, 6 square faces of 2 triangles each.
BOOST_AUTO_TEST_CASE(display_mesh_of_the_unit_cube)
{
  Display_mesh m = display_mesh(model_of(R"({"block": {"min": [0,0,0], "max": [1,1,1]}})"), lo, hi);
  BOOST_TEST(m.vertices.size() == 8u);
  BOOST_TEST(m.triangles.size() == 12u);
  BOOST_TEST(m.cells == 1u);
  BOOST_TEST(!m.clipped);
  BOOST_TEST(extent(m) == (std::array<double, 6>{0, 1, 0, 1, 0, 1}), boost::test_tools::per_element());
  // Each triangle faces outward: its normal points away from the centre (1/2, 1/2, 1/2).
  for (const auto& t : m.triangles) {
    const auto &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    std::array<double, 3> u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    std::array<double, 3> n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    BOOST_TEST(n[0] * (a[0] - 0.5) + n[1] * (a[1] - 0.5) + n[2] * (a[2] - 0.5) > 0);
  }
}

// The cube minus the half-space x >= 1/2 (-x + 1/2 <= 0): one cell, the box
// [0, 1/2] x [0, 1]^2, again 8 corners and 12 triangles.
BOOST_AUTO_TEST_CASE(display_mesh_of_a_difference)
{
  Display_mesh m = display_mesh(
      model_of(R"({"difference": [{"block": {"min": [0,0,0], "max": [1,1,1]}}, {"halfspace": [-1, 0, 0, 0.5]}]})"), lo, hi);
  BOOST_TEST(m.vertices.size() == 8u);
  BOOST_TEST(m.triangles.size() == 12u);
  BOOST_TEST(extent(m) == (std::array<double, 6>{0, 0.5, 0, 1, 0, 1}), boost::test_tools::per_element());
}

// The floor z <= 0, unbounded: cut by the drawing box to [-1, 2]^2 x [-1, 0].
BOOST_AUTO_TEST_CASE(display_mesh_of_a_halfspace_is_clipped)
{
  Display_mesh m = display_mesh(model_of(R"({"halfspace": [0, 0, 1, 0]})"), lo, hi);
  BOOST_TEST(m.clipped);
  BOOST_TEST(m.vertices.size() == 8u);
  BOOST_TEST(m.triangles.size() == 12u);
  BOOST_TEST(extent(m) == (std::array<double, 6>{-1, 2, -1, 2, -1, 0}), boost::test_tools::per_element());
}

// The ram case's view: two cubes of 8 corners; the ram's keys at tL = 0, its
// breakpoint 5 and tH = 10 (displacements 0, (-5, 0, 0), (-5, 0, 0)); the
// buttons at the witness time 5/2 and t* = 2; the exact points marked.
BOOST_AUTO_TEST_CASE(view_data_of_the_ram)
{
  json d = scene_view_data(colliding_case(), {0, 1});
  BOOST_TEST(d["objects"].size() == 2u);
  BOOST_TEST(d["objects"][0]["vertices"].size() == 24u);
  BOOST_TEST(d["objects"][0]["triangles"].size() == 36u);
  const json& keys = d["objects"][1]["keys"];
  BOOST_TEST(keys.size() == 3u);
  BOOST_TEST(keys[1]["t"] == 5.0);
  BOOST_TEST(keys[1]["c"] == json({-5.0, 0.0, 0.0}));
  BOOST_TEST(keys[2]["c"] == json({-5.0, 0.0, 0.0}));
  BOOST_TEST(d["times"][0]["label"] == "witness time");
  BOOST_TEST(d["times"][0]["t"] == 2.5);
  BOOST_TEST(d["times"][1]["label"] == "exact t*");
  BOOST_TEST(d["times"][1]["t"] == 2.0);
  BOOST_TEST(d["marks"][0]["label"] == "exact witness");
  BOOST_TEST(d["marks"][0]["point"] == json({0.75, 0.5, 0.5}));
  BOOST_TEST(d["marks"][1]["point"] == json({1.0, 0.5, 0.5}));
}

// ---------------------------------------------------------------- numbers, findings

BOOST_AUTO_TEST_CASE(decimals_of_exact_numbers)
{
  BOOST_TEST(*decimal_value("3/4") == 0.75);
  BOOST_TEST(*decimal_value("-2.5e3") == -2500.0);
  BOOST_TEST(*decimal_value("root of [-1, 0, 8] in (0, 1) ~ 0.3535533905932738") == 0.3535533905932738);
  BOOST_TEST(!decimal_value("hello"));
  BOOST_TEST(decimal_text("2784582518619477629369/2353783867871269486592") == "\xE2\x89\x88 1.18302");
  BOOST_TEST(decimal_text("2").empty());   // already a decimal
  BOOST_TEST(decimal_text("-123456789012").empty());   // an integer reads as itself
  BOOST_TEST(decimal_text("0.1000000000000000055511151231257827") == "\xE2\x89\x88 0.1");
}

// A minimised finding whose t* is a long fraction and a subject whose t* is
// algebraic: each shown with its decimal; report.json keeps the exact text;
// the heading links the scene it was minimised from.
BOOST_AUTO_TEST_CASE(decimals_and_the_original_in_the_page)
{
  const std::string t_star = "2784582518619477629369/2353783867871269486592";
  const std::string root = "root of [-1, 0, 8] in (0, 1) ~ 0.3535533905932738";
  Report_case c = colliding_case();
  c.comparison.subjects[0].earliest->t = t_star;
  c.comparison.subjects[1].earliest = Located{{"box", "ram"}, std::nullopt, root};
  c.original = "fuzz/found/big <1>.json";
  fs::path dir = fs::temp_directory_path() / ("clash4d_test_report_numbers_" + std::to_string(::getpid()));
  write_report({c}, (dir / "out").string());
  std::string h = slurp(dir / "out" / "index.html");
  json r = json::parse(slurp(dir / "out" / "report.json"));
  BOOST_TEST(h.find(t_star + "</code> <span class=\"approx\">(\xE2\x89\x88 1.18302)</span>") != std::string::npos);
  BOOST_TEST(h.find("0.3535533905932738</code> <span class=\"approx\">(\xE2\x89\x88 0.353553)</span>") != std::string::npos);
  BOOST_TEST(h.find("3/4</code> <span class=\"approx\">(\xE2\x89\x88 0.75)</span>") != std::string::npos);
  BOOST_TEST(r["cases"][0]["subjects"][0]["earliest"]["t"] == t_star);
  BOOST_TEST(r["cases"][0]["subjects"][1]["earliest"]["t"] == root);
  BOOST_TEST(h.find("minimised from <a href=\"fuzz/found/big &lt;1&gt;.json\">") != std::string::npos);
  // The subject's t* (no point) is a button of the 3D view.
  BOOST_TEST(h.find(">double t*</button>") != std::string::npos);
#ifdef CLASH4D_THREE_JS
  BOOST_TEST(slurp(dir / "out" / "three.min.js") == slurp(CLASH4D_THREE_JS));
#endif
  fs::remove_all(dir);
}

// Coordinates near 1.2e8: the x axis' tick labels are decimals (no
// exponent) and far enough apart for their text (11px type: at least 6px a
// character between the centres of neighbours).
BOOST_AUTO_TEST_CASE(tick_labels_are_decimals_that_do_not_overlap)
{
  Report_case c = make_case("far.json", R"({"format": "clash4d-scene/1", "time": [0, 1], "objects": [
      {"name": "a", "shape": {"block": {"min": [123456789,0,0], "max": [123456790,1,1]}}},
      {"name": "b", "shape": {"block": {"min": [123456791,0,0], "max": [123456792,1,1]}}, "motion": "vel -1 0 0"}]})",
    R"({"file": "far.json", "name": "", "closed_touch": true, "subjects": [
      {"subject": "exact", "reference": true, "ok": true, "error": "", "collide": false, "witness": null,
       "witness_valid": null, "earliest": null, "t_error": null, "seconds": 0.003, "agrees": true, "cause": null}],
     "disagreements": []})");
  fs::path dir = fs::temp_directory_path() / ("clash4d_test_report_ticks_" + std::to_string(::getpid()));
  write_report({c}, (dir / "out").string());
  std::string h = slurp(dir / "out" / "index.html");
  std::string x_svg = h.substr(h.find("<svg class=\"qt\""));
  x_svg = x_svg.substr(0, x_svg.find("</svg>"));
  std::regex label("<text x=\"([0-9.]+)\" y=\"302.00\" text-anchor=\"middle\" class=\"\">([^<]*)</text>");
  std::vector<std::pair<double, std::string>> labels;
  for (std::sregex_iterator it(x_svg.begin(), x_svg.end(), label), end; it != end; ++it)
    labels.emplace_back(std::stod((*it)[1]), (*it)[2]);
  BOOST_TEST_REQUIRE(labels.size() >= 2u);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    BOOST_TEST(labels[i].second.find('e') == std::string::npos);
    double value = std::stod(labels[i].second);   // the padded span of [123456789, 123456792]
    BOOST_TEST((123456788 <= value && value <= 123456793));
    if (i) BOOST_TEST(labels[i].first - labels[i - 1].first >= 6.0 * labels[i].second.size());
  }
  fs::remove_all(dir);
}

// ---------------------------------------------------------------- a turning scene

namespace {

// The root of the fixture's expected t* polynomial (ascending coefficients,
// degree 2) in its interval, by the quadratic formula: known apart from the
// report's own reading of the comparison.
double expected_t_star(const json& t)
{
  double c = std::stod(t["poly"][0].get<std::string>()), b = std::stod(t["poly"][1].get<std::string>()),
         a = std::stod(t["poly"][2].get<std::string>());
  double lo = decimal_value(t["between"][0].get<std::string>()).value(),
         hi = decimal_value(t["between"][1].get<std::string>()).value();
  for (double s : {-1.0, 1.0}) {
    double r = (-b + s * std::sqrt(b * b - 4 * a * c)) / (2 * a);
    if (lo < r && r < hi) return r;
  }
  return NAN;
}

std::string polygon_points(const std::string& h, const std::string& title)
{
  std::size_t at = h.rfind("<polygon points=\"", h.find("<title>" + title));
  std::size_t from = at + std::string("<polygon points=\"").size();
  return h.substr(from, h.find('"', from) - from);
}

} // namespace

// square_into_slab (q from (1,0,0,0) to (1,0,0,1) over [0, 1]): the time
// axis marks t* = (5 - sqrt 14)/11 at its double with its exact text, the
// square's extent is drawn sampled under its poses, and the table says it
// turns 90 degrees about z, its centre fixed; the 3D view places it by its poses.
BOOST_AUTO_TEST_CASE(a_turning_scene_is_plotted)
{
  const std::string fixtures = std::string(CLASH4D_FIXTURES) + "/rotation/";
  Scene scene = read_scene_file(fixtures + "square_into_slab.json");
  Compare_options o;
  o.earliest = true;   // as clash4d report asks
  Report_case c{"square_into_slab.json", scene, compare_scene(scene, "square_into_slab.json", o), ""};
  fs::path dir = fs::temp_directory_path() / ("clash4d_test_report_turning_" + std::to_string(::getpid()));
  write_report({c}, (dir / "out").string());
  std::string h = slurp(dir / "out" / "index.html");

  json expected = json::parse(slurp(fixtures + "expected.json"))["square_into_slab.json"]["regularised"]["t"];
  double t_star = expected_t_star(expected);
  BOOST_TEST(std::abs(t_star - 0.11439478302055078) < 1e-15);
  std::smatch m;
  BOOST_TEST_REQUIRE(std::regex_search(h, m, std::regex("<g class=\"t-star\" data-t=\"([^\"]+)\" data-exact=\"([^\"]+)\">")));
  BOOST_TEST(std::abs(std::stod(m[1]) - t_star) < 1e-15);
  BOOST_TEST(m[2].str().rfind("root of", 0) == 0u);   // irrational: the algebraic number's text
  BOOST_TEST(h.find("t* \xE2\x89\x88 0.114395</text>") != std::string::npos);
  BOOST_TEST(count(h, "class=\"pose-time\"") == 2u);   // the square's poses at t = 0 and 1

  // The square's band in each diagram and its zoom, sampled densely (more
  // than 64 times along each edge); the slab's as a translation's (4 points).
  const std::string turning = "square (turns: extent of its vertices under the poses, sampled)";
  BOOST_TEST(count(h, "class=\"turning\"><title>" + turning + "</title>") == 6u);
  BOOST_TEST(count(polygon_points(h, turning), ",") > 2 * 64u);
  BOOST_TEST(count(polygon_points(h, "slab"), ",") == 4u);
  BOOST_TEST(h.find("No q-t diagrams") == std::string::npos);

  // What turns where: 90 degrees about z over [0, 1], the centre fixed.
  std::string turns = h.substr(h.find("<table class=\"turns\">"));
  turns = turns.substr(0, turns.find("</table>"));
  BOOST_TEST(turns.find("<tr><td>square</td><td>[<code class=\"whole\">0</code>, <code class=\"whole\">1</code>]</td>"
                        "<td class=\"n whole\">90\xC2\xB0</td><td class=\"whole\">(0, 0, 1)</td>"
                        "<td><span class=\"mono\">(0, 0, 0), fixed</span></td></tr>") != std::string::npos);
  BOOST_TEST(turns.find("<td>slab</td>") == std::string::npos);

  // The 3D view's keys are the poses (the page evaluates their law).
  json view = scene_view_data(c, {0, 1});
  BOOST_TEST(view["objects"][0]["keys"][1]["q"] == json::parse("[1.0, 0.0, 0.0, 1.0]"));
  fs::remove_all(dir);
}

// A scene with a repaired mesh says so on its page (issue 58 item 1): the
// file, its facets, the scale, the rule and what the repair did, naming the
// file's facet (fixtures/meshes/repair/zero_area.off: facet 8 is the
// zero-area triangle; in millimetres the scale is 1/1000).
BOOST_AUTO_TEST_CASE(a_repaired_mesh_is_named_on_the_page)
{
  const std::string folder = std::string(CLASH4D_FIXTURES) + "/meshes/repair";
  json s = {{"format", "clash4d-scene/1"},
            {"time", {0, 1}},
            {"objects",
             {{{"name", "part"}, {"shape", {{"mesh", "zero_area.off"}, {"repair", {"drop-zero-area"}}, {"units", "mm"}}}},
              {{"name", "probe"}, {"shape", {{"block", {{"min", {0, 0, 0}}, {"max", {1, 1, 1}}}}}}}}}};
  Scene scene = read_scene(read_json_text(s.dump()), folder);
  Report_case c{"mesh.json", scene, compare_scene(scene, "mesh.json", Compare_options()), ""};
  fs::path dir = fs::temp_directory_path() / ("clash4d_test_report_mesh_" + std::to_string(::getpid()));
  write_report({c}, (dir / "out").string());
  std::string h = slurp(dir / "out" / "index.html");
  std::string::size_type at = h.find("<table class=\"meshes\">");
  BOOST_TEST_REQUIRE(at != std::string::npos);
  std::string table = h.substr(at, h.find("</table>", at) - at);
  BOOST_TEST(table.find("<td>zero_area.off</td><td class=\"n\">9</td><td class=\"n\">1</td><td>1/1000</td>"
                        "<td>odd shells</td>") != std::string::npos, table);
  BOOST_TEST(table.find("zero-area facet(s) dropped (facet 8)") != std::string::npos, table);
  fs::remove_all(dir);
}

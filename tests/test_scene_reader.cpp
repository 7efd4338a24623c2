#define BOOST_TEST_MODULE scene_reader
#include <boost/test/unit_test.hpp>

#include "scene/Exact_validation.h"
#include "scene/Input_error.h"
#include "scene/Json_reader.h"
#include "scene/Number_text.h"
#include "scene/Pose_motion.h"
#include "scene/Scene_builder.h"
#include "scene/Scene_reader.h"
#include "scene/Scene_writer.h"
#include <nlohmann/json.hpp>

using namespace clash4d;

static const std::string two_blocks = R"({"format":"clash4d-scene/1","name":"n","time":[0,"10"],"objects":[
  {"name":"box","shape":{"block":{"min":[0,0,0],"max":[1,1,1]}}},
  {"name":"ram","shape":{"block":{"min":[3,0,0],"max":[4,1,1]}},"motion":"rest until 0 vel -1 0 0 until 5 rest"}]})";

// Replaces the first occurrence of `from` in the valid scene.
static std::string edited(const std::string& from, const std::string& to)
{
  std::string s = two_blocks;
  std::size_t at = s.find(from);
  BOOST_TEST_REQUIRE(at != std::string::npos, from);
  return s.replace(at, from.size(), to);
}

// The error for a text: its place, message and exit code.
static Input_error error_of(const std::string& text)
{
  try {
    read_scene(read_json_text(text));
  } catch (const Input_error& e) {
    return e;
  }
  BOOST_FAIL("accepted: " << text);
  return Input_error("", "");
}

static void expect_error(const std::string& text, const std::string& place, const std::string& words, int code = 2)
{
  Input_error e = error_of(text);
  BOOST_TEST(e.place() == place, "message: " << e.format("f"));
  BOOST_TEST(std::string(e.what()).find(words) != std::string::npos, "message: " << e.format("f"));
  BOOST_TEST(e.exit_code() == code);
}

BOOST_AUTO_TEST_CASE(valid_scene_is_read_exactly)
{
  Scene s = read_scene(read_json_text(two_blocks));
  BOOST_TEST(s.objects.size() == 2u);
  BOOST_TEST(s.t_hi == Rational(10));
  BOOST_TEST(s.objects[1].motion.times.size() == 2u);
  BOOST_TEST(s.objects[1].motion.velocities[1][0] == Rational(-1));
}

BOOST_AUTO_TEST_CASE(round_trip_through_the_writer)
{
  std::string text = edited(R"("min":[0,0,0])", R"("min":["0.1","-1/3","2.5e-3"])");
  Scene a = read_scene(read_json_text(text));
  Scene b = read_scene(read_json_text(write_scene(a)));
  BOOST_TEST(write_scene(a) == write_scene(b));
  BOOST_TEST(b.objects[0].shape.numbers[0] == Rational(1, 10));
  BOOST_TEST(b.objects[0].shape.numbers[1] == Rational(-1, 3));
  BOOST_TEST(b.objects[0].shape.numbers[2] == Rational(1, 400));
}

BOOST_AUTO_TEST_CASE(json_numbers_keep_their_text)
{
  // 0.1 as a JSON number must be 1/10, not the double nearest to it.
  Scene s = read_scene(read_json_text(edited(R"("min":[0,0,0])", R"("min":[0.1,1e-20,-123456789012345678901234567890])")));
  BOOST_TEST(s.objects[0].shape.numbers[0] == Rational(1, 10));
  BOOST_TEST(s.objects[0].shape.numbers[1] * Rational(100000) == parse_number_text("1e-15", false).value);
  BOOST_TEST(-s.objects[0].shape.numbers[2] / Rational(1000000000) > Rational(1000000000) * Rational(1000000000));
}

BOOST_AUTO_TEST_CASE(errors_name_the_place)
{
  expect_error(edited(R"("min":[0,0,0])", R"("min":[0,0])"), "objects[0].shape.block.min", "expected 3 numbers");
  expect_error(edited(R"("min":[3,0,0])", R"("min":[4,0,0])"), "objects[1].shape.block", "min must be less than max");
  expect_error(edited(R"("name":"n",)", R"("name":"n","colour":1,)"), "", "unknown key \"colour\"");
  expect_error(edited(R"("max":[1,1,1]}})", R"("max":[1,1,1]},"spin":1})"), "objects[0].shape", "unknown key \"spin\"");
  expect_error(edited(R"({"block":{"min":[0,0,0])", R"({"block":{"min":[0,0,0],"mid":[0,0,0])"), "objects[0].shape.block", "unknown key \"mid\"");
  expect_error(edited(R"("format":"clash4d-scene/1")", R"("format":"clash4d-scene/2")"), "format", "clash4d-scene/1");
  expect_error(edited(R"("time":[0,"10"])", R"("time":[10,10])"), "time", "tL < tH");
  expect_error(edited(R"("time":[0,"10"])", R"("time":[0,"1/0"])"), "time[1]", "zero denominator");
  expect_error(edited(R"("time":[0,"10"])", R"("time":[0,"NaN"])"), "time[1]", "not a number");
  expect_error(edited(R"("name":"ram")", R"("name":"box")"), "objects[1].name", "duplicate object name");
  expect_error(edited(R"("name":"ram")", R"("name":"")"), "objects[1].name", "must not be empty");
  expect_error(edited(R"("name":"ram")", R"("name":7)"), "objects[1].name", "expected a string");
  expect_error(edited("until 5 rest", "until 5 fly"), "objects[1].motion", "'fly'");
  expect_error(edited("until 5 rest", "until -1 rest"), "objects[1].motion", "strictly increasing");
  expect_error(edited("vel -1 0 0", "vel -1 0"), "objects[1].motion", "expected");
  expect_error(edited("rest until 0", "rest until"), "objects[1].motion", "expected a time");
  expect_error(edited(R"("name":"n",)", R"("name":"n","ignore":[["box","rom"]],)"), "ignore[0][1]", "no object is named \"rom\"");
  expect_error(edited(R"("name":"n",)", R"("name":"n","ignore":[["box","box"]],)"), "ignore[0]", "itself");
  expect_error(edited(R"("name":"n",)", R"("name":"n","ignore":[["box"]],)"), "ignore[0]", "pair");
  expect_error(edited(R"({"block":{"min":[0,0,0],"max":[1,1,1]}})", R"({"rotate":[0,0,0,0],"solid":{"block":{"min":[0,0,0],"max":[1,1,1]}}})"),
               "objects[0].shape.rotate", "quaternion must not be zero");
  expect_error(edited(R"({"block":{"min":[0,0,0],"max":[1,1,1]}})", R"({"halfspace":[0,0,0,1]})"),
               "objects[0].shape.halfspace", "must not be all zero");
  expect_error(edited(R"({"block":{"min":[0,0,0],"max":[1,1,1]}})", R"({"union":[]})"), "objects[0].shape.union", "at least 1");
  expect_error(edited(R"({"block":{"min":[0,0,0],"max":[1,1,1]}})", R"({"difference":[{"block":{"min":[0,0,0],"max":[1,1,1]}}]})"),
               "objects[0].shape.difference", "at least 2");
}

BOOST_AUTO_TEST_CASE(degenerate_solids_are_refused)
{
  auto shape = [](const std::string& s) { return edited(R"({"block":{"min":[0,0,0],"max":[1,1,1]}})", s); };
  expect_error(shape(R"({"prism":{"base":[[0,0],[0,1],[1,0]],"z":[0,1]}})"), "objects[0].shape.prism.base", "clockwise");
  expect_error(shape(R"({"prism":{"base":[[0,0],[1,0],[2,0],[1,1]],"z":[0,1]}})"), "objects[0].shape.prism.base", "collinear");
  expect_error(shape(R"({"prism":{"base":[[0,0],[2,0],[1,1],[1,3]],"z":[0,1]}})"), "objects[0].shape.prism.base", "not strictly convex");
  expect_error(shape(R"({"prism":{"base":[[0,0],[1,0],[0,1]],"z":[1,1]}})"), "objects[0].shape.prism.z", "z0 must be less");
  expect_error(shape(R"({"hull":[[0,0,0],[1,0,0],[0,1,0],[1,1,0]]})"), "objects[0].shape.hull", "one plane");
  expect_error(shape(R"({"hull":[[0,0,0],[1,0,0],[0,1,0]]})"), "objects[0].shape.hull", "at least 4");
  expect_error(shape(R"({"convex":[[1,0,0,-1],[-1,0,0,0],[0,1,0,-1],[0,-1,0,0]]})"), "objects[0].shape.convex", "unbounded");
  expect_error(shape(R"({"convex":[[1,0,0,1],[-1,0,0,0],[0,1,0,-1],[0,-1,0,0],[0,0,1,-1],[0,0,-1,0]]})"), "objects[0].shape.convex", "empty");
  expect_error(shape(R"({"convex":[[1,0,0,0],[-1,0,0,0],[0,1,0,-1],[0,-1,0,0],[0,0,1,-1],[0,0,-1,0]]})"), "objects[0].shape.convex", "no interior");
}

BOOST_AUTO_TEST_CASE(malformed_json_is_refused_with_a_position)
{
  expect_error("{\"format\": ", "line 1, column 12", "syntax error");
  expect_error("not json", "line 1, column 3", "syntax error");
  expect_error(R"({"format":"clash4d-scene/1","format":"clash4d-scene/1"})", "", "duplicate key \"format\"");
  expect_error(edited(R"("max":[1,1,1]}})", R"("max":[1,1,1],"max":[2,2,2]}})"), "objects[0].shape.block", "duplicate key \"max\"");
  expect_error("[1,2]", "", "expected an object");
  expect_error(R"({"time": NaN})", "line 1, column 11", "syntax error");
}

// One document rule for the scene reader and both verifiers (docs/scene-format.md,
// "The file"): a leading byte-order mark is ignored; nothing but whitespace
// follows the document, and a NUL byte, which nlohmann's lexer would take
// for the end of the input, is refused where it stands.
BOOST_AUTO_TEST_CASE(one_document_rule_bom_nul_and_trailing_bytes)
{
  Scene plain = read_scene(read_json_text(two_blocks));
  Scene bom = read_scene(read_json_text("\xEF\xBB\xBF" + two_blocks));
  BOOST_TEST(bom.objects.size() == plain.objects.size());
  expect_error(two_blocks + std::string("\0garbage", 8), "line 3, column 115", "NUL byte");
  expect_error(std::string("\0", 1) + two_blocks, "line 1, column 1", "NUL byte");
  expect_error(two_blocks + " x", "line 3, column 117", "syntax error");
  BOOST_TEST(read_scene(read_json_text(two_blocks + " \r\n\t")).objects.size() == 2u);
}

// spec, Numbers: a number is read from its text whether written as a JSON
// number or as a string, under the same limits; 1e1000 is within them (the
// exponent limit is 1000), so both forms give the same exact value.
// Issue 59 item 14: a NUL or a line feed in a name is written as JSON writes
// it; it neither cuts the message short nor breaks its one line.
BOOST_AUTO_TEST_CASE(names_with_control_characters_are_printed_escaped)
{
  std::string text = edited(R"("name":"box")", R"("name":"r\u0000a\nm")");
  text = text.replace(text.find(R"("name":"ram")"), 12, R"("name":"r\u0000a\nm")");
  expect_error(text, "objects[1].name", R"(duplicate object name "r\u0000a\u000am")");
}

BOOST_AUTO_TEST_CASE(a_json_number_and_its_string_are_one_rule)
{
  for (const char* form : {R"(1e1000)", R"("1e1000")"}) {
    Scene s = read_scene(read_json_text(edited(R"("max":[4,1,1])", std::string(R"("max":[)") + form + ",1,1]")));
    BOOST_TEST(s.objects[1].shape.numbers[3] == parse_number_text("1e1000", false).value, form);
  }
  for (const char* form : {R"(1e1001)", R"("1e1001")", R"(-2e4933)", R"("-2e4933")"})
    expect_error(edited(R"("max":[4,1,1])", std::string(R"("max":[)") + form + ",1,1]"), "objects[1].shape.block.max[0]",
                 "exponent", 3);
}

BOOST_AUTO_TEST_CASE(absurd_input_hits_a_named_limit)
{
  std::string deep = R"({"format":"clash4d-scene/1","time":[0,1],"objects":[{"name":"a","shape":)";
  for (int i = 0; i < 100000; ++i) deep += R"({"union":[)";
  Input_error e = error_of(deep);
  BOOST_TEST(e.exit_code() == 3);
  BOOST_TEST(std::string(e.what()).find("256") != std::string::npos);
  expect_error(edited(R"("time":[0,"10"])", R"("time":[0,"1e1000000"])"), "time[1]", "exponent", 3);
}

// spec: `meta` is any JSON value, never read by the decision; only at the top.
BOOST_AUTO_TEST_CASE(meta_holds_any_value_and_is_ignored)
{
  Scene plain = read_scene(read_json_text(two_blocks));
  for (const char* meta : {R"({"family":"x","seed":1,"deep":{"a":[1,"2",null]}})", "[1,2,3]", "\"text\"", "-2.5e-300", "null", "true"}) {
    Scene s = read_scene(read_json_text(edited(R"("name":"n",)", std::string(R"("name":"n","meta":)") + meta + ",")));
    BOOST_TEST(write_scene(s) == write_scene(plain), meta);
  }
  expect_error(edited(R"("name":"n",)", R"("name":"n","meta":1,"meta":2,)"), "", "duplicate key \"meta\"");
  expect_error(edited(R"("name":"box",)", R"("name":"box","meta":1,)"), "objects[0]", "unknown key \"meta\"");
}

BOOST_AUTO_TEST_CASE(the_writer_puts_meta_last_and_reads_back)
{
  Scene s = read_scene(read_json_text(two_blocks));
  std::string text = write_scene(s, {{"family", "f"}, {"seed", 3}});
  BOOST_TEST(text.find("\"meta\"") > text.find("\"objects\""));
  BOOST_TEST(write_scene(read_scene(read_json_text(text))) == write_scene(s));
}

// A cone: side planes a x + b y + z <= 1 for 34 rational points (a, b) of the
// unit circle (((1 - u^2) / (1 + u^2), 2 u / (1 + u^2)) for u = -8, -15/2,
// ..., 8, and (-1, 0)), all through the apex (0, 0, 1), and the base z >= 0.
// The points are in strictly convex position around the origin, so every
// side plane is a facet and the base is a 34-gon: 35 vertices, each listed
// once, and one corner (the apex, on all 34 side planes). Every triple of
// side planes meets at the apex, the case a fuzzer found slow (each triple
// classified the same point again).
BOOST_AUTO_TEST_CASE(cone_apex_is_one_vertex)
{
  std::vector<Rational4> planes;
  for (int j = -16; j <= 16; ++j) {
    Rational u(j, 2), den = 1 + u * u;
    planes.push_back({(1 - u * u) / den, 2 * u / den, Rational(1), Rational(-1)});
  }
  planes.push_back({Rational(-1), Rational(0), Rational(1), Rational(-1)});
  planes.push_back({Rational(0), Rational(0), Rational(-1), Rational(0)});
  BOOST_TEST(convex_problem(planes).empty());
  Polytope_combinatorics c = convex_vertex_triples(planes);
  BOOST_TEST(c.triples.size() == 35u);
  BOOST_REQUIRE(c.corners.size() == 1u);
  BOOST_TEST(c.corners[0].size() == 34u);
}

// A hull's facets and volume, by hand. The box [0,2]x[0,3]x[0,1/2] given by
// its 8 corners, edge midpoints (on the hull, not vertices), an inner point
// and a repeat: 6 facet planes, 8 corners of 3 planes (none of 4 or more),
// and six times the volume 3 is 18 (the mesh cache checks pieces by it).
BOOST_AUTO_TEST_CASE(hull_facets_gives_one_triple_per_facet_and_six_times_the_volume)
{
  std::vector<Rational3> points;
  for (int i = 0; i < 8; ++i)
    points.push_back({Rational(2 * (i & 1)), Rational(3 * ((i >> 1) & 1)), Rational((i >> 2) & 1, 2)});
  points.push_back({Rational(1), Rational(0), Rational(0)});
  points.push_back({Rational(2), Rational(3, 2), Rational(1, 2)});
  points.push_back({Rational(1, 3), Rational(1), Rational(1, 4)});
  points.push_back(points[5]);
  Polytope_combinatorics c = hull_facets(points);
  BOOST_TEST(c.triples.size() == 6u);
  BOOST_TEST(c.corners.empty());
  BOOST_TEST(c.six_volume == Rational(18));
  for (const auto& t : c.triples)   // every triple is three of the box's corners
    for (int k : t) BOOST_TEST(k < 8);
}

// ---- scene/Files.h: what an atomic write replaces (issue 59 items 10, 11) ----

#include "scene/Files.h"
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <thread>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

// A fresh folder per test, removed after it.
struct Scratch {
  fs::path dir;
  Scratch()
  {
    std::string pattern = (fs::temp_directory_path() / "clash4d-files-XXXXXX").string();
    BOOST_TEST_REQUIRE(::mkdtemp(pattern.data()) != nullptr);
    dir = pattern;
  }
  ~Scratch() { std::error_code ec; fs::remove_all(dir, ec); }
  std::string text_of(const fs::path& p) const
  {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  // The folder's entries other than those named: no temporary is left behind.
  std::size_t entries() const { return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), {})); }
};

} // namespace

BOOST_AUTO_TEST_SUITE(atomic_writes)

BOOST_AUTO_TEST_CASE(new_and_replaced_regular_files_keep_permissions)
{
  Scratch s;
  fs::path out = s.dir / "out.json";
  write_file_atomically(out.string(), "one\n");
  BOOST_TEST(s.text_of(out) == "one\n");
  fs::permissions(out, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  write_file_atomically(out.string(), "two\n");
  BOOST_TEST(s.text_of(out) == "two\n");
  BOOST_TEST((fs::status(out).permissions() == (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read)));
  BOOST_TEST(s.entries() == 1u);
}

BOOST_AUTO_TEST_CASE(a_symbolic_link_is_written_through_not_replaced)
{
  Scratch s;
  fs::path real = s.dir / "real.json", link = s.dir / "link.json";
  { std::ofstream(real) << "old\n"; }
  fs::create_symlink(real, link);
  write_file_atomically(link.string(), "new\n");
  BOOST_TEST(fs::is_symlink(fs::symlink_status(link)));
  BOOST_TEST(s.text_of(real) == "new\n");
  BOOST_TEST(s.entries() == 2u);
}

BOOST_AUTO_TEST_CASE(a_dangling_link_and_a_folder_are_refused_by_name)
{
  Scratch s;
  fs::path link = s.dir / "dangling.json", folder = s.dir / "folder";
  fs::create_symlink(s.dir / "missing" / "x.json", link);
  fs::create_directory(folder);
  for (const fs::path& p : {link, folder}) {
    try {
      write_file_atomically(p.string(), "x\n");
      BOOST_FAIL("written: " << p);
    } catch (const std::runtime_error& e) {
      BOOST_TEST(std::string(e.what()).find(p.string()) == 0u, e.what());
    }
  }
  BOOST_TEST(fs::is_symlink(fs::symlink_status(link)));
  BOOST_TEST(fs::is_directory(folder));
  BOOST_TEST(s.entries() == 2u);
}

BOOST_AUTO_TEST_CASE(a_device_or_a_pipe_is_written_to_as_it_is)
{
  // `--certificate /dev/null` as root made /dev/null a regular file. The
  // test makes a null device of its own where it may (as root), never
  // touching the machine's.
  Scratch s;
  fs::path null_device = s.dir / "null";
  if (::mknod(null_device.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0) {
    write_file_atomically(null_device.string(), "discarded\n");
    BOOST_TEST(fs::is_character_file(fs::status(null_device)));
    fs::remove(null_device);
  } else {
    BOOST_TEST_MESSAGE("not root: the device case is left to the pipe");
  }
  fs::path fifo = s.dir / "fifo";
  BOOST_TEST_REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  std::string read_back;
  std::thread reader([&] { read_back = s.text_of(fifo); });
  write_file_atomically(fifo.string(), "through the pipe\n");
  reader.join();
  BOOST_TEST(read_back == "through the pipe\n");
  BOOST_TEST(fs::is_fifo(fs::status(fifo)));
}

BOOST_AUTO_TEST_CASE(a_planted_link_at_the_old_temporary_name_is_not_followed)
{
  // The old temporary name was .NAME.PID.N.tmp, opened with O_TRUNC: a link
  // planted there let the tool overwrite the file it named.
  Scratch s;
  fs::path victim = s.dir / "victim.txt", out = s.dir / "out.json";
  { std::ofstream(victim) << "keep\n"; }
  // Every counter value this process can have reached by now.
  for (int n = 0; n < 64; ++n)
    fs::create_symlink(victim, s.dir / (".out.json." + std::to_string(::getpid()) + "." + std::to_string(n) + ".tmp"));
  write_file_atomically(out.string(), "written\n");
  BOOST_TEST(s.text_of(victim) == "keep\n");
  BOOST_TEST(s.text_of(out) == "written\n");
  BOOST_TEST(s.entries() == 66u);
}

BOOST_AUTO_TEST_SUITE_END()

// ---------------------------------------------------------------- poses
// Spec: "Motion with rotation (poses)"; issue 61 item 1.

// The two-block scene with ram's motion replaced by `motion` (JSON text).
static std::string with_ram_motion(const std::string& motion)
{
  return edited(R"("rest until 0 vel -1 0 0 until 5 rest")", motion);
}

BOOST_AUTO_TEST_CASE(pose_errors_name_their_place)
{
  const std::string m = "objects[1].motion";
  expect_error(with_ram_motion(R"({"poses":[{"t":0}],"spin":1})"), m, "unknown key \"spin\"");
  expect_error(with_ram_motion(R"({})"), m, "missing key \"poses\"");
  expect_error(with_ram_motion(R"({"poses":[]})"), m + ".poses", "non-empty list");
  expect_error(with_ram_motion(R"({"poses":{"t":0}})"), m + ".poses", "non-empty list");
  expect_error(with_ram_motion(R"(7)"), m, "ROBMOD string or an object");
  expect_error(with_ram_motion(R"({"poses":[{"t":0},{"translate":[1,0,0]}]})"), m + ".poses[1]", "missing key \"t\"");
  expect_error(with_ram_motion(R"({"poses":[{"t":0,"rotation":[1,0,0,0]}]})"), m + ".poses[0]", "unknown key \"rotation\"");
  expect_error(with_ram_motion(R"({"poses":[3]})"), m + ".poses[0]", "expected an object");
  expect_error(with_ram_motion(R"({"poses":[{"t":1},{"t":"1/1"}]})"), m + ".poses[1].t", "strictly increasing");
  expect_error(with_ram_motion(R"({"poses":[{"t":1},{"t":2},{"t":0}]})"), m + ".poses[2].t", "strictly increasing");
  expect_error(with_ram_motion(R"({"poses":[{"t":0},{"t":1,"rotate":[0,0,0,"0/5"]}]})"), m + ".poses[1].rotate",
               "must not be zero");
  expect_error(with_ram_motion(R"({"poses":[{"t":0},{"t":1,"rotate":[1,0,0]}]})"), m + ".poses[1].rotate", "expected 4 numbers");
  expect_error(with_ram_motion(R"({"poses":[{"t":0},{"t":1,"translate":[1,"x",0]}]})"), m + ".poses[1].translate[1]", "is not a number");
  expect_error(with_ram_motion(R"({"poses":[{"t":"1/0"}]})"), m + ".poses[0].t", "zero denominator");
  // q_{i+1} = lambda q_i, lambda < 0: q(t) passes through 0 (exactly, with fractions).
  expect_error(with_ram_motion(R"({"poses":[{"t":0,"rotate":[1,2,0,"1/3"]},{"t":1,"rotate":["-1/2",-1,0,"-1/6"]}]})"),
               m + ".poses[1].rotate", "negative multiple");
  expect_error(with_ram_motion(R"({"poses":[{"t":0},{"t":1},{"t":2,"rotate":[-3,0,0,0]}]})"), m + ".poses[2].rotate",
               "negative multiple");
  // A positive multiple, an orthogonal or an almost-opposite quaternion is fine.
  for (const char* ok : {R"({"poses":[{"t":0,"rotate":[1,2,0,3]},{"t":1,"rotate":[2,4,0,6]}]})",
                         R"({"poses":[{"t":0,"rotate":[1,0,0,0]},{"t":1,"rotate":[0,1,0,0]}]})",
                         R"({"poses":[{"t":0,"rotate":[1,0,0,0]},{"t":1,"rotate":[-1,"1/1000",0,0]}]})"})
    BOOST_CHECK_NO_THROW(read_scene(read_json_text(with_ram_motion(ok))));
}

BOOST_AUTO_TEST_CASE(more_than_ten_thousand_poses_is_a_limit)
{
  auto poses = [](int n) {
    std::string s = R"({"poses":[)";
    for (int i = 0; i < n; ++i) s += (i ? "," : "") + std::string(R"({"t":)") + std::to_string(i) + "}";
    return s + "]}";
  };
  BOOST_CHECK_NO_THROW(read_scene(read_json_text(with_ram_motion(poses(10000)))));
  expect_error(with_ram_motion(poses(10001)), "objects[1].motion.poses", "limit of 10000 poses", 3);
}

// Rotation-free poses are the piecewise-linear translation D(t) = c(t) - c(0)
// (rest outside the poses, no breakpoint where the velocity does not change)
// with the shape put at c(0).
BOOST_AUTO_TEST_CASE(rotation_free_poses_are_a_translation)
{
  Scene s = read_scene(read_json_text(with_ram_motion(
      R"({"poses":[{"t":1,"translate":[5,0,0]},{"t":3,"translate":[3,0,0],"rotate":[2,0,0,0]},{"t":4,"translate":[2,0,0]},{"t":6,"translate":[2,"1/2",0]}]})")));
  const Scene_object& ram = s.objects[1];
  BOOST_TEST(!ram.motion.rotates());
  BOOST_TEST(ram.motion.poses.size() == 4u);
  // Velocity -1 on [1, 4] (one segment: no breakpoint at 3), (0, 1/4, 0) on [4, 6].
  BOOST_TEST(ram.motion.times == (std::vector<Rational>{Rational(1), Rational(4), Rational(6)}));
  BOOST_REQUIRE(ram.motion.velocities.size() == 4u);
  BOOST_TEST(ram.motion.velocities[0] == (std::array<Rational, 3>{Rational(0), Rational(0), Rational(0)}));
  BOOST_TEST(ram.motion.velocities[1] == (std::array<Rational, 3>{Rational(-1), Rational(0), Rational(0)}));
  BOOST_TEST(ram.motion.velocities[2] == (std::array<Rational, 3>{Rational(0), Rational(1, 4), Rational(0)}));
  BOOST_TEST(ram.motion.velocities[3] == (std::array<Rational, 3>{Rational(0), Rational(0), Rational(0)}));
  // c(0) = c(1) = (5, 0, 0): the written block translated there, approximated as read.
  BOOST_TEST((ram.shape.kind == Solid::Kind::Translate));
  BOOST_TEST(ram.shape.numbers == (std::vector<Rational>{Rational(5), Rational(0), Rational(0)}));
  BOOST_TEST(ram.shape.numbers_approximated.size() == 3u);
  BOOST_TEST((ram.shape.children.at(0).kind == Solid::Kind::Block));
  BOOST_TEST(&written_shape(ram) == &ram.shape.children[0]);
  BOOST_TEST(ram.motion.times_approximated.size() == 3u);

  // c(0) between poses: c(0) = (1, 2, 0) + 1/4 ((5, 2, 0) - (1, 2, 0)) = (2, 2, 0).
  Scene mid = read_scene(read_json_text(with_ram_motion(R"({"poses":[{"t":-1,"translate":[1,2,0]},{"t":3,"translate":[5,2,0]}]})")));
  BOOST_TEST(mid.objects[1].shape.numbers == (std::vector<Rational>{Rational(2), Rational(2), Rational(0)}));
  // c(0) after the last pose; and c(0) = 0: no wrapper.
  Scene after = read_scene(read_json_text(with_ram_motion(R"({"poses":[{"t":-3,"translate":[0,0,0]},{"t":-1,"translate":[0,0,"-1/3"]}]})")));
  BOOST_TEST(after.objects[1].shape.numbers == (std::vector<Rational>{Rational(0), Rational(0), Rational(-1, 3)}));
  Scene none = read_scene(read_json_text(with_ram_motion(R"({"poses":[{"t":0},{"t":2,"translate":[1,0,0]}]})")));
  BOOST_TEST((none.objects[1].shape.kind == Solid::Kind::Block));
  // One pose: placed, at rest.
  Scene one = read_scene(read_json_text(with_ram_motion(R"({"poses":[{"t":7,"translate":[1,0,0]}]})")));
  BOOST_TEST(one.objects[1].motion.times.empty());
  BOOST_TEST(one.objects[1].motion.velocities.size() == 1u);
  BOOST_TEST((one.objects[1].shape.kind == Solid::Kind::Translate));
}

BOOST_AUTO_TEST_CASE(rotating_poses_are_read_at_rest_for_the_pipeline)
{
  Scene s = read_scene(read_json_text(with_ram_motion(
      R"({"poses":[{"t":0,"translate":[1,0,0]},{"t":2,"translate":[1,0,0],"rotate":[1,0,0,1]}]})")));
  const Motion& m = s.objects[1].motion;
  BOOST_TEST(m.rotates());
  BOOST_TEST(m.times.empty());
  BOOST_TEST(m.velocities.size() == 1u);
  BOOST_TEST((s.objects[1].shape.kind == Solid::Kind::Block));   // no wrapper: the pipeline refuses it
}

BOOST_AUTO_TEST_CASE(pose_motions_round_trip_through_the_writer)
{
  for (const char* motion :
       {R"({"poses":[{"t":"1/3","translate":["0.5",0,0]},{"t":2,"translate":[1,0,"-2/7"],"rotate":[1,0,0,1]},{"t":3}]})",
        R"({"poses":[{"t":1,"translate":[5,0,0]},{"t":4,"translate":[2,"1e-3",0],"rotate":[3,0,0,0]}]})",
        R"({"poses":[{"t":-2}]})"}) {
    Scene a = read_scene(read_json_text(with_ram_motion(motion)));
    std::string once = write_scene(a);
    Scene b = read_scene(read_json_text(once));
    BOOST_TEST(write_scene(b) == once);
    BOOST_TEST(b.objects[1].motion.poses.size() == a.objects[1].motion.poses.size());
    BOOST_TEST(b.objects[1].motion.times == a.objects[1].motion.times);
    BOOST_TEST(b.objects[1].shape.numbers == a.objects[1].shape.numbers);
    // The written shape is the original block, not the c(0) wrapper.
    nlohmann::json j = nlohmann::json::parse(once);
    BOOST_TEST(j["objects"][1]["shape"].contains("block"), once);
    BOOST_TEST(j["objects"][1]["motion"].contains("poses"), once);
  }
  // A ROBMOD motion is still written as ROBMOD.
  BOOST_TEST(nlohmann::json::parse(write_scene(read_scene(read_json_text(two_blocks))))["objects"][1]["motion"].is_string());
}

BOOST_AUTO_TEST_CASE(scene_builder_takes_poses_checked_as_the_reader)
{
  Pose a, b;
  a.t = Rational(1);
  a.translate = {Rational(5), Rational(0), Rational(0)};
  b.t = Rational(3);
  b.translate = {Rational(3), Rational(0), Rational(0)};
  Scene_builder builder("poses", Rational(0), Rational(10));
  builder.object("box", block(vec(0, 0, 0), vec(1, 1, 1))).object("ram", block(vec(0, 0, 0), vec(1, 1, 1)));
  builder.motion_poses("ram", {a, b});
  const Scene_object& ram = builder.scene().objects[1];
  BOOST_TEST((ram.shape.kind == Solid::Kind::Translate));
  BOOST_TEST(ram.motion.times.size() == 2u);
  Scene read = read_scene(read_json_text(builder.text()));
  BOOST_TEST(read.objects[1].shape.numbers == ram.shape.numbers);
  BOOST_TEST(read.objects[1].motion.times == ram.motion.times);
  BOOST_TEST(write_scene(read) == builder.text());

  Pose opposite = b;
  opposite.rotate = {Rational(-1), Rational(0), Rational(0), Rational(0)};
  try {
    builder.motion_poses("ram", {a, opposite});
    BOOST_FAIL("a negative multiple was accepted");
  } catch (const Input_error& e) {
    BOOST_TEST(e.place() == "objects[1].motion.poses[1].rotate");
    BOOST_TEST(e.exit_code() == 2);
  }
  BOOST_CHECK_THROW(builder.motion_poses("ram", {}), Input_error);
  BOOST_CHECK_THROW(builder.motion_poses("arm", {a}), std::invalid_argument);
}

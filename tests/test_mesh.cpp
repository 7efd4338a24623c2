#define BOOST_TEST_MODULE mesh
#include <boost/test/unit_test.hpp>

#include "check/Check_runner.h"
#include "exact/Exact_instantiation.h"
#include "exact/Rational_kernel.h"
#include "float/Double_instantiation.h"
#include "scene/Input_error.h"
#include "scene/Json_reader.h"
#include "scene/Mesh_check.h"
#include "scene/Mesh_reader.h"
#include "scene/Mesh_solid.h"
#include "scene/Number_text.h"
#include "scene/Scene_reader.h"
#include "support/Cli_run.h"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <unistd.h>
#include <fstream>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

using namespace clash4d;
using json = nlohmann::json;

namespace {

const std::string meshes = std::string(CLASH4D_FIXTURES) + "/meshes";

Rational exact(const std::string& text)
{
  Number_parse p = parse_number_text(text, true);
  BOOST_REQUIRE(p.ok);
  return p.value;
}

std::string file_text(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The message of the Input_error that f throws ("" when none), with its exit code.
template <class F>
std::pair<std::string, int> refusal(F f)
{
  try {
    f();
  } catch (const Input_error& e) {
    return {e.format("scene"), e.exit_code()};
  }
  return {"", 0};
}

std::pair<std::string, int> mesh_refusal(const std::string& name, const Mesh_limits& limits = Mesh_limits())
{
  return refusal([&] { read_mesh_solid(meshes + "/" + name, name, limits); });
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// One scene: the part (L) at rest and a probe.
std::string scene_text(const json& part, const json& probe, const std::string& motion)
{
  json s = {{"format", "clash4d-scene/1"},
            {"time", {0, 10}},
            {"objects", {{{"name", "part"}, {"shape", part}}, {{"name", "probe"}, {"shape", probe}, {"motion", motion}}}}};
  return s.dump();
}

struct Answer {
  bool collide = false;
  std::string time;   // t* (regularised) or first contact (closed), when colliding
};

Answer run(const Scene& scene, Semantics semantics)
{
  Check_options opts;
  opts.semantics = semantics;
  opts.earliest = true;
  Check_answer a = check_exact(scene, opts);
  Answer out;
  out.collide = a.collide;
  if (a.collide) {
    BOOST_REQUIRE(a.earliest_pair >= 0);
    out.time = a.pairs[a.earliest_pair].t_star;
    BOOST_TEST(a.pairs[a.earliest_pair].witness_verified);
  }
  return out;
}

const std::vector<std::string> l_part_files = {"l_part.off",       "l_part.obj",    "l_part_ascii.stl", "l_part_binary.stl",
                                               "l_part_ascii.ply", "l_part_le.ply", "l_part_be.ply"};

std::vector<char> binary_stl(const std::vector<std::array<float, 9>>& triangles)
{
  std::vector<char> bytes(84, ' ');
  std::uint32_t n = static_cast<std::uint32_t>(triangles.size());
  for (int k = 0; k < 4; ++k) bytes[80 + k] = static_cast<char>((n >> (8 * k)) & 0xff);   // little endian
  for (const auto& t : triangles) {
    char facet[50] = {};
    for (int k = 0; k < 9; ++k) {
      std::uint32_t bits;
      std::memcpy(&bits, &t[k], 4);
      for (int b = 0; b < 4; ++b) facet[12 + 4 * k + b] = static_cast<char>((bits >> (8 * b)) & 0xff);
    }
    bytes.insert(bytes.end(), facet, facet + 50);
  }
  return bytes;
}

std::string_view view(const std::vector<char>& v) { return std::string_view(v.data(), v.size()); }

// OFF text of boxes [lo, hi]^3 shifted by (dx, dy, dz), each as six outward
// quadrilaterals (inward when flipped), vertices numbered box by box.
struct Box {
  int lo, hi, dx, dy, dz;
  bool inward;
};
std::string boxes_off(const std::vector<Box>& boxes)
{
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::string verts, facets;
  int base = 0;
  for (const Box& b : boxes) {
    for (int i = 0; i < 8; ++i)   // index x + 2y + 4z
      verts += std::to_string((i & 1 ? b.hi : b.lo) + b.dx) + " " + std::to_string((i & 2 ? b.hi : b.lo) + b.dy) + " " +
               std::to_string((i & 4 ? b.hi : b.lo) + b.dz) + "\n";
    for (const auto& q : quads) {
      facets += "4";
      for (int k = 0; k < 4; ++k) facets += " " + std::to_string(base + q[b.inward ? 3 - k : k]);
      facets += "\n";
    }
    base += 8;
  }
  return "OFF\n" + std::to_string(base) + " " + std::to_string(6 * boxes.size()) + " 0\n" + verts + facets;
}

Solid off_solid(const std::string& text, const std::string& name)
{
  return mesh_solid(check_mesh(read_mesh(text, Mesh_format::Off, name), name), name);
}

Rational pieces_volume(const Solid& s)
{
  // Every piece of these tests is an axis-aligned box: the volume of its points' bounding box.
  Rational total(0);
  for (const Solid& c : s.children) {
    std::array<Rational, 3> lo, hi;
    for (int k = 0; k < 3; ++k) lo[k] = hi[k] = c.numbers[k];
    for (std::size_t i = 0; i < c.numbers.size(); ++i) {
      lo[i % 3] = std::min(lo[i % 3], c.numbers[i]);
      hi[i % 3] = std::max(hi[i % 3], c.numbers[i]);
    }
    total += (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
  }
  return total;
}

} // namespace

// The L-shaped part as each mesh file and as CSG gives the hand-derived
// answers of fixtures/meshes/expected.json, and exactly the CSG's answers.
BOOST_AUTO_TEST_CASE(l_part_meshes_answer_as_the_csg_part)
{
  json expected = json::parse(file_text(meshes + "/expected.json"));
  json csg = json::parse(R"({"union": [{"block": {"min": [0, 0, 0], "max": [2, 1, 1]}},
                                         {"block": {"min": [0, 1, 0], "max": [1, 2, 1]}}]})");
  for (const auto& [name, s] : expected["scenes"].items()) {
    std::string motion = s.value("motion", "rest");
    std::string why = name + ": " + s["why"].get<std::string>();
    Scene csg_scene = read_scene(read_json_text(scene_text(csg, s["probe"], motion)));
    Answer csg_regular = run(csg_scene, Semantics::regularised), csg_closed = run(csg_scene, Semantics::closed);
    BOOST_TEST(csg_regular.collide == s["regularised"]["collide"].get<bool>(), "csg " << why);
    BOOST_TEST(csg_regular.time == s["regularised"].value("earliest", ""), "csg " << why);
    BOOST_TEST(csg_closed.collide == s["closed"]["collide"].get<bool>(), "csg closed " << why);
    BOOST_TEST(csg_closed.time == s["closed"].value("first_contact", ""), "csg closed " << why);
    for (const auto& file : l_part_files) {
      Scene scene = read_scene(read_json_text(scene_text({{"mesh", file}}, s["probe"], motion)), meshes);
      Answer regular = run(scene, Semantics::regularised), closed = run(scene, Semantics::closed);
      BOOST_TEST(regular.collide == csg_regular.collide, file << " " << why);
      BOOST_TEST(regular.time == csg_regular.time, file << " " << why);
      BOOST_TEST(closed.collide == csg_closed.collide, file << " closed " << why);
      BOOST_TEST(closed.time == csg_closed.time, file << " closed " << why);
      BOOST_TEST(regular.collide == s["regularised"]["collide"].get<bool>(), file << " " << why);
      BOOST_TEST(regular.time == s["regularised"].value("earliest", ""), file << " " << why);
      BOOST_TEST(closed.collide == s["closed"]["collide"].get<bool>(), file << " closed " << why);
      BOOST_TEST(closed.time == s["closed"].value("first_contact", ""), file << " closed " << why);
    }
  }
}

BOOST_AUTO_TEST_CASE(every_format_reads_the_same_l_part)
{
  Checked_mesh reference = check_mesh(read_mesh_file(meshes + "/l_part.off", "l_part.off"), "l_part.off");
  BOOST_TEST(reference.vertices.size() == 12u);
  BOOST_TEST(reference.volume == Rational(3));   // 2 + 1
  BOOST_TEST(!reference.convex);
  std::set<std::array<Rational, 3>> points(reference.vertices.begin(), reference.vertices.end());
  for (const auto& file : l_part_files) {
    Checked_mesh m = check_mesh(read_mesh_file(meshes + "/" + file, file), file);
    BOOST_TEST(m.volume == Rational(3), file);
    BOOST_TEST(!m.convex, file);
    BOOST_TEST((std::set<std::array<Rational, 3>>(m.vertices.begin(), m.vertices.end()) == points), file);
  }
}

BOOST_AUTO_TEST_CASE(non_convex_mesh_is_a_union_of_hulls_convex_one_a_hull)
{
  Solid l = read_mesh_solid(meshes + "/l_part.obj", "l_part.obj");
  BOOST_TEST((l.kind == Solid::Kind::Union));
  BOOST_TEST(l.children.size() >= 2u);
  for (const auto& c : l.children) {
    BOOST_TEST((c.kind == Solid::Kind::Hull));
    BOOST_TEST(!c.triples.empty());
    BOOST_TEST(c.constructed.size() == 4 * c.triples.size());
  }
  Solid cube = read_mesh_solid(meshes + "/cube.off", "cube.off");
  BOOST_TEST((cube.kind == Solid::Kind::Hull));
  BOOST_TEST(cube.numbers.size() == 24u);
  BOOST_TEST(cube.triples.size() == 6u);   // one triple per facet plane
  // The same file twice in one scene: one solid, re-pathed.
  std::string text = scene_text({{"mesh", "l_part.off"}}, {{"mesh", "./l_part.off"}}, "vel 0 0 1");
  Scene scene = read_scene(read_json_text(text), meshes);
  BOOST_TEST(scene.objects[1].shape.path == "objects[1].shape.mesh");
  BOOST_TEST(scene.objects[1].shape.children.size() == scene.objects[0].shape.children.size());
  BOOST_TEST(scene.objects[1].shape.children[0].path == "objects[1].shape.mesh[0]");
}

// Shells: separate solids, a cavity, and the shells that do not bound a solid.
BOOST_AUTO_TEST_CASE(shells_cavities_crossings_and_pinches)
{
  // Two separate unit cubes: one mesh, two pieces.
  Solid two = off_solid(boxes_off({{0, 1, 0, 0, 0, false}, {0, 1, 3, 0, 0, false}}), "two.off");
  BOOST_TEST((two.kind == Solid::Kind::Union));
  BOOST_TEST(two.children.size() == 2u);
  // [0,4]^3 with the cavity [1,3]^3 (an inner shell facing inward): 64 - 8.
  Solid hollow = off_solid(boxes_off({{0, 4, 0, 0, 0, false}, {1, 3, 0, 0, 0, true}}), "hollow.off");
  BOOST_TEST((hollow.kind == Solid::Kind::Union));
  BOOST_TEST(pieces_volume(hollow) == Rational(56));
  auto refused = [](const std::string& text, const std::string& name) {
    return refusal([&] { off_solid(text, name); });
  };
  // An inward shell that is no cavity: signed volume 8 - 1 > 0, but no solid.
  auto stray = refused(boxes_off({{0, 2, 0, 0, 0, false}, {0, 1, 3, 0, 0, true}}), "stray.off");
  BOOST_TEST(stray.second == CLASH4D_EXIT_INVALID);
  BOOST_TEST(contains(stray.first, "stray.off: the facets do not bound one solid"), stray.first);
  // Two overlapping cubes in one file: the surfaces cross.
  auto crossing = refused(boxes_off({{0, 2, 0, 0, 0, false}, {0, 2, 1, 1, 1, false}}), "crossing.off");
  BOOST_TEST(crossing.second == CLASH4D_EXIT_INVALID);
  BOOST_TEST(contains(crossing.first, "crossing.off: facet "), crossing.first);
  BOOST_TEST(contains(crossing.first, ": the surface intersects itself"), crossing.first);
  // Two shells: the union of shells is the repair to offer (one shell
  // crossing itself is fixtures/meshes/repair/spike_through.off).
  BOOST_TEST(contains(crossing.first, "\"shells\": \"union\" reads crossing shells"), crossing.first);
  // Two cubes sharing only the corner (1, 1, 1).
  auto pinched = refused(boxes_off({{0, 1, 0, 0, 0, false}, {0, 1, 1, 1, 1, false}}), "pinched.off");
  BOOST_TEST(pinched.second == CLASH4D_EXIT_INVALID);
  BOOST_TEST(contains(pinched.first, "pinched.off: vertex (1, 1, 1): the surface is pinched there: 2 separate fans"), pinched.first);
}

// Binary STL: every float32 is the dyadic rational it encodes. The expected
// values are Python's fractions.Fraction of the same float32 values.
BOOST_AUTO_TEST_CASE(binary_stl_floats_are_exact)
{
  float a = 0.1f, b = 1e-7f, c = 3.3f, d = -2.5f, e = 1e-40f, f = 16777217.0f;
  std::vector<char> bytes = binary_stl({{a, b, c, d, e, f, 0, 0, 0}});
  Mesh m = read_mesh(view(bytes), Mesh_format::Stl, "floats.stl");
  BOOST_REQUIRE(m.vertices.size() == 3u);
  BOOST_TEST(m.vertices[0][0] == exact("13421773/134217728"));
  BOOST_TEST(m.vertices[0][1] == exact("14073749/140737488355328"));
  BOOST_TEST(m.vertices[0][2] == exact("13841203/4194304"));
  BOOST_TEST(m.vertices[1][0] == exact("-5/2"));
  BOOST_TEST(m.vertices[1][1] == exact("35681/356811923176489970264571492362373784095686656"));   // subnormal
  BOOST_TEST(m.vertices[1][2] == exact("16777216"));   // 16777217 rounds to 2^24 in float32
  BOOST_TEST(CGAL::is_zero(m.vertices[2][0]));
  // Not the decimal the float was written from.
  BOOST_TEST(m.vertices[0][0] != exact("0.1"));
  // The bits themselves (sign, biased exponent, fraction), taken apart independently.
  BOOST_TEST(exact_float32(0x3f800000u) == Rational(1));
  BOOST_TEST(exact_float32(0x80000001u) == -exact("1/713623846352979940529142984724747568191373312"));   // -2^-149
  BOOST_TEST(exact_float64(0x3fb999999999999aull) == exact("3602879701896397/36028797018963968"));      // 0.1
}

BOOST_AUTO_TEST_CASE(binary_ply_doubles_are_exact)
{
  // A big-endian PLY tetrahedron with 0.1 (double) on each axis.
  std::string head = "ply\nformat binary_big_endian 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
                     "property double z\nelement face 4\nproperty list uchar uint vertex_indices\nend_header\n";
  std::string bytes = head;
  auto put64 = [&](std::uint64_t u) { for (int k = 7; k >= 0; --k) bytes += static_cast<char>((u >> (8 * k)) & 0xff); };
  auto put32 = [&](std::uint32_t u) { for (int k = 3; k >= 0; --k) bytes += static_cast<char>((u >> (8 * k)) & 0xff); };
  const std::uint64_t tenth = 0x3fb999999999999aull;
  std::uint64_t v[4][3] = {{0, 0, 0}, {tenth, 0, 0}, {0, tenth, 0}, {0, 0, tenth}};
  for (auto& p : v) for (auto x : p) put64(x);
  std::uint32_t f[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (auto& t : f) { bytes += '\3'; for (auto i : t) put32(i); }
  Mesh m = read_mesh(bytes, Mesh_format::Ply, "tenth.ply");
  BOOST_TEST(m.vertices[1][0] == exact("3602879701896397/36028797018963968"));
  Checked_mesh c = check_mesh(m, "tenth.ply");
  BOOST_TEST(c.convex);
  BOOST_TEST(c.volume == exact("3602879701896397/36028797018963968") * exact("3602879701896397/36028797018963968") *
                             exact("3602879701896397/36028797018963968") / Rational(6));
}

BOOST_AUTO_TEST_CASE(decimal_text_is_exact)
{
  for (std::string file : {"tenth.off", "tenth.obj"}) {
    Mesh m = read_mesh_file(meshes + "/" + file, file);
    BOOST_TEST(m.vertices[1][0] == exact("1/10"), file);
    BOOST_TEST(m.vertices[3][2] == exact("1/10"), file);
    Checked_mesh c = check_mesh(m, file);
    BOOST_TEST(c.convex);
    BOOST_TEST(c.volume == exact("1/6000"), file);   // (1/10)^3 / 6
  }
  // Forms mesh writers use beyond JSON's grammar.
  std::string obj = "v +1. .5 -0.25e1\nv 1E+0 007 5.e-1\nv 0 0 0\nf 1 2 3\n";
  Mesh m = read_mesh(obj, Mesh_format::Obj, "forms.obj");
  BOOST_TEST(m.vertices[0][0] == Rational(1));
  BOOST_TEST(m.vertices[0][1] == exact("1/2"));
  BOOST_TEST(m.vertices[0][2] == exact("-5/2"));
  BOOST_TEST(m.vertices[1][1] == Rational(7));
  BOOST_TEST(m.vertices[1][2] == exact("1/2"));
}

// The three refusals of the issue, then the others.
BOOST_AUTO_TEST_CASE(hole_flipped_and_non_manifold_are_refused)
{
  auto hole = mesh_refusal("hole.off");
  BOOST_TEST(hole.second == CLASH4D_EXIT_INVALID);
  BOOST_TEST(contains(hole.first, "hole.off: facet 0: edge not shared with any other facet: the mesh has a hole"), hole.first);
  auto flipped = mesh_refusal("flipped.off");
  BOOST_TEST(flipped.second == CLASH4D_EXIT_INVALID);
  BOOST_TEST(contains(flipped.first, "flipped.off: facet 3: oriented against its neighbours across 4 of its edges"), flipped.first);
  auto nonmanifold = mesh_refusal("nonmanifold.off");
  BOOST_TEST(nonmanifold.second == CLASH4D_EXIT_INVALID);
  BOOST_TEST(contains(nonmanifold.first, "nonmanifold.off: facet 3: edge shared by 4 facets (3, 5, 8, 10)"), nonmanifold.first);
}

BOOST_AUTO_TEST_CASE(other_bad_meshes_are_refused_with_their_place)
{
  struct Case {
    const char* file;
    const char* message;
  };
  for (const Case& c : std::vector<Case>{
           {"index_out_of_range.off", "index_out_of_range.off: line 15: vertex index 8 out of range (the file has 8 vertices"},
           {"bad_token.obj", "bad_token.obj: line 3: 'x' is not a number"},
           {"empty.stl", "empty.stl: empty file"},
           {"inside_out.off", "inside_out.off: the facets are oriented inward (signed volume -1 < 0)"}}) {
    auto r = mesh_refusal(c.file);
    BOOST_TEST(r.second == CLASH4D_EXIT_INVALID, c.file);
    BOOST_TEST(contains(r.first, c.message), r.first);
  }
  auto refused = [](const std::string& text, Mesh_format format, const std::string& name) {
    return refusal([&] { check_mesh(read_mesh(text, format, name), name); });
  };
  // Degenerate facets.
  auto flat = refused("OFF 4 4 0  0 0 0  1 0 0  2 0 0  0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n", Mesh_format::Off, "flat.off");
  BOOST_TEST(contains(flat.first, "flat.off: facet 0: zero area (its vertices are collinear"), flat.first);
  auto repeated = refused("OFF 4 1 0  0 0 0  1 0 0  0 1 0  1 0 0\n4 0 1 2 3\n", Mesh_format::Off, "repeated.off");
  BOOST_TEST(contains(repeated.first, "repeated.off: facet 0: vertex 3 (1, 0, 0) repeats an earlier vertex"), repeated.first);
  auto skew = refused("OFF 4 1 0  0 0 0  1 0 0  1 1 1  0 1 0\n4 0 1 2 3\n", Mesh_format::Off, "skew.off");
  BOOST_TEST(contains(skew.first, "skew.off: facet 0: not planar"), skew.first);
  auto obj_zero = refused("v 0 0 0\nf 0 1 2\n", Mesh_format::Obj, "zero.obj");
  BOOST_TEST(contains(obj_zero.first, "zero.obj: line 2: vertex index 0"), obj_zero.first);
  auto ascii = refused("solid x\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n", Mesh_format::Stl, "short.stl");
  BOOST_TEST(contains(ascii.first, "short.stl: line 6: expected \"vertex\", found 'endloop'"), ascii.first);
  BOOST_TEST(contains(refused("", Mesh_format::Off, "e.off").first, "e.off: empty file"));
  BOOST_TEST(contains(refused("ply\nformat ascii 1.0\nend_header\n", Mesh_format::Ply, "e.ply").first, "e.ply: no facets"));
  BOOST_TEST(contains(refusal([] { mesh_format_of("part.step"); }).first, "unknown mesh format '.step'"));
}

BOOST_AUTO_TEST_CASE(bad_binary_stl_is_refused)
{
  float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  std::vector<char> two = binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 0, 1, 0, nan, 0, 1}});
  auto r = refusal([&] { read_mesh(view(two), Mesh_format::Stl, "nan.stl"); });
  BOOST_TEST(r.second == CLASH4D_EXIT_INVALID);
  BOOST_TEST(contains(r.first, "nan.stl: facet 1: vertex 2 coordinate x is NaN"), r.first);
  std::vector<char> infinite = binary_stl({{0, 0, 0, 1, inf, 0, 0, 1, 0}});
  BOOST_TEST(contains(refusal([&] { read_mesh(view(infinite), Mesh_format::Stl, "inf.stl"); }).first,
                      "inf.stl: facet 0: vertex 1 coordinate y is infinite"));
  // Truncated: the header says 2 facets, one is there.
  two.resize(two.size() - 50);
  two[80] = 2;
  r = refusal([&] { read_mesh(view(two), Mesh_format::Stl, "cut.stl"); });
  BOOST_TEST(r.second == CLASH4D_EXIT_INVALID);
  BOOST_TEST(contains(r.first, "cut.stl: binary STL of 2 facets should have 84 + 50 * 2 = 184 bytes, the file has 134 (truncated: it ends inside facet 1)"), r.first);
  std::vector<char> header(60, 'x');
  BOOST_TEST(contains(refusal([&] { read_mesh(view(header), Mesh_format::Stl, "tiny.stl"); }).first, "tiny.stl: not an STL file"));
}

BOOST_AUTO_TEST_CASE(limits_give_exit_3)
{
  // A binary STL header claiming 2^31 facets, in an 84-byte file.
  std::vector<char> huge = binary_stl({});
  huge[83] = static_cast<char>(0x80);
  auto r = refusal([&] { read_mesh(view(huge), Mesh_format::Stl, "huge.stl"); });
  BOOST_TEST(r.second == CLASH4D_EXIT_LIMIT);
  BOOST_TEST(contains(r.first, "huge.stl: 2147483648 facets is more than the limit of 100000"), r.first);
  // Claimed counts in text headers are refused before anything is read.
  r = refusal([] { read_mesh("OFF\n999999999 1 0\n", Mesh_format::Off, "big.off"); });
  BOOST_TEST(r.second == CLASH4D_EXIT_LIMIT);
  BOOST_TEST(contains(r.first, "big.off: line 2: 999999999 vertices is more than the limit of 100000"), r.first);
  r = refusal([] { read_mesh("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nelement face 4000000\n"
                             "property list uchar int vertex_indices\nend_header\n", Mesh_format::Ply, "big.ply"); });
  BOOST_TEST(r.second == CLASH4D_EXIT_LIMIT);
  // Smaller limits, injected.
  Mesh_limits small;
  small.facets = 5;
  r = mesh_refusal("l_part_binary.stl", small);
  BOOST_TEST(r.second == CLASH4D_EXIT_LIMIT);
  BOOST_TEST(contains(r.first, "l_part_binary.stl: 20 facets is more than the limit of 5"), r.first);
  BOOST_TEST(mesh_refusal("l_part.obj", small).second == CLASH4D_EXIT_LIMIT);
  small = Mesh_limits();
  small.vertices = 11;
  BOOST_TEST(mesh_refusal("l_part_ascii.ply", small).second == CLASH4D_EXIT_LIMIT);
  small = Mesh_limits();
  small.file_bytes = 100;
  r = mesh_refusal("l_part_ascii.stl", small);
  BOOST_TEST(r.second == CLASH4D_EXIT_LIMIT);
  BOOST_TEST(contains(r.first, "l_part_ascii.stl: mesh file larger than the limit of 100 bytes"), r.first);
  small = Mesh_limits();
  small.pieces = 1;
  r = mesh_refusal("l_part.off", small);
  BOOST_TEST(r.second == CLASH4D_EXIT_LIMIT);
  BOOST_TEST(contains(r.first, "l_part.off: the decomposition has more than the limit of 1 convex pieces"), r.first);
  BOOST_TEST(mesh_refusal("cube.off", small).second == 0);   // convex: one hull, no decomposition
}

// Through the command line, as a user runs it.
BOOST_AUTO_TEST_CASE(cli_checks_mesh_scenes_and_reports_bad_meshes)
{
  Cli_run ok = run_clash4d({"check", meshes + "/scene_l_part.json"});
  BOOST_TEST(ok.status == 1, ok.out << ok.err);
  Cli_run earliest = run_clash4d({"check", meshes + "/scene_l_part.json", "--earliest", "--json"});
  BOOST_TEST(earliest.status == 1, earliest.err);
  BOOST_TEST(contains(earliest.out, "\"1/4\""), earliest.out);
  Cli_run bad = run_clash4d({"check", meshes + "/scene_hole.json"});
  BOOST_TEST(bad.status == 2);
  BOOST_TEST(contains(bad.err, "scene_hole.json: objects[1].shape.mesh: hole.off: facet 0: edge not shared with any other facet"), bad.err);
  Cli_run missing = run_clash4d({"validate", meshes + "/scene_missing.json"});
  BOOST_TEST(missing.status == 2);
  BOOST_TEST(contains(missing.err, "objects[0].shape.mesh: no_such_part.stl: cannot open the mesh file"), missing.err);
  Cli_run valid = run_clash4d({"validate", meshes + "/scene_l_part.json"});
  BOOST_TEST(valid.status == 0, valid.err);
}

// "max_pieces" beside "mesh" (docs/meshes.md, Limits) moves the piece
// limit for that mesh: the L part has one reflex edge, so two convex pieces
// (its upper arm and its foot). A limit of 1 refuses it with exit 3 and
// names the option; 2 reads it; a count that is not a whole number from 1
// to the allowed most is refused where it is written.
BOOST_AUTO_TEST_CASE(max_pieces_moves_the_piece_limit)
{
  auto with = [](const json& max) {
    return read_scene(read_json_text(scene_text({{"mesh", "l_part.off"}, {"max_pieces", max}},
                                                {{"block", {{"min", {5, 5, 5}}, {"max", {6, 6, 6}}}}}, "rest")),
                      meshes);
  };
  auto r = refusal([&] { with(1); });
  BOOST_TEST(r.second == CLASH4D_EXIT_LIMIT);
  BOOST_TEST(contains(r.first, "objects[0].shape.mesh: l_part.off: the decomposition has more than the limit of 1 "
                               "convex pieces (raise it with \"max_pieces\""), r.first);
  Scene two = with(2);
  BOOST_TEST((two.objects[0].shape.kind == Solid::Kind::Union));
  BOOST_TEST(two.objects[0].shape.children.size() == 2u);
  BOOST_TEST(with("1000000/1000").objects[0].shape.children.size() == 2u);   // exact: 1000
  for (const json& bad : {json(0), json(2.5), json("5/2"), json(100001), json("many"), json(-3)}) {
    auto b = refusal([&] { with(bad); });
    BOOST_TEST(b.second == CLASH4D_EXIT_INVALID, bad.dump());
    BOOST_TEST(contains(b.first, "objects[0].shape.max_pieces: "), b.first);
  }
  // The default is CLASH4D_MAX_MESH_PIECES, as without the option.
  BOOST_TEST(Mesh_options().max_pieces == CLASH4D_MAX_MESH_PIECES);
}

namespace {

// Whether x is in the closed union of the hull pieces: inside a piece when
// on no facet's outer side, (q - p) x (r - p) . (x - p) <= 0 for each of its
// outward triples p q r (decided here from the points, not from the
// pieces' stored planes).
bool in_pieces(const Solid& s, const std::array<Rational, 3>& x)
{
  auto point = [](const Solid& c, int i) {
    return std::array<Rational, 3>{c.numbers[3 * i], c.numbers[3 * i + 1], c.numbers[3 * i + 2]};
  };
  auto inside = [&](const Solid& c) {
    for (const auto& t : c.triples) {
      auto p = point(c, t[0]), q = point(c, t[1]), r = point(c, t[2]);
      Rational u[3], v[3], w[3];
      for (int k = 0; k < 3; ++k) u[k] = q[k] - p[k], v[k] = r[k] - p[k], w[k] = x[k] - p[k];
      Rational side = (u[1] * v[2] - u[2] * v[1]) * w[0] + (u[2] * v[0] - u[0] * v[2]) * w[1] +
                      (u[0] * v[1] - u[1] * v[0]) * w[2];
      if (side > 0) return false;
    }
    return true;
  };
  if (s.kind == Solid::Kind::Hull) return inside(s);
  return std::any_of(s.children.begin(), s.children.end(), inside);
}

// A star-shaped prism, sheared: the polygon of n corners at angles 2 pi k / n
// (rounded to sixteenths, radii from 1 to 4 drawn), its bottom and top fanned
// from their centres, z from 0 to 2, then x += z / 2. Non-convex, and its
// side planes are oblique.
struct Star_prism {
  std::vector<std::array<Rational, 2>> ring;
  std::string off;

  // In the closed solid: undo the shear, then z in [0, 2] and (x, y) in a
  // closed fan triangle (centre, ring[k], ring[k + 1]) (the star's union).
  bool contains(const std::array<Rational, 3>& p) const
  {
    if (p[2] < 0 || p[2] > 2) return false;
    Rational x = p[0] - p[2] / 2, y = p[1];
    auto cross = [](const std::array<Rational, 2>& a, const std::array<Rational, 2>& b, const Rational& px,
                    const Rational& py) { return (b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0]); };
    std::array<Rational, 2> o{Rational(0), Rational(0)};
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const auto &a = ring[k], &b = ring[(k + 1) % ring.size()];
      if (cross(o, a, x, y) >= 0 && cross(a, b, x, y) >= 0 && cross(b, o, x, y) >= 0) return true;
    }
    return false;
  }
};

// q, a multiple of 1/16, as the exact decimal OFF reads (1/16 = 0.0625).
std::string decimal(const Rational& q)
{
  Rational scaled = q * 10000;
  long n = std::lround(CGAL::to_double(scaled));
  BOOST_REQUIRE(Rational(n) == scaled);
  std::string digits = std::to_string(std::labs(n) % 10000);
  return (n < 0 ? "-" : "") + std::to_string(std::labs(n) / 10000) + "." + std::string(4 - digits.size(), '0') + digits;
}

Star_prism star_prism(std::mt19937& rng, int n)
{
  Star_prism s;
  for (int k = 0; k < n; ++k) {
    double angle = 2 * 3.141592653589793 * k / n;
    Rational radius(1 + static_cast<int>(rng() % 4));
    Rational c(static_cast<long>(std::lround(16 * std::cos(angle)))), d(static_cast<long>(std::lround(16 * std::sin(angle))));
    s.ring.push_back({radius * c / 16, radius * d / 16});
  }
  std::ostringstream off;
  off << "OFF\n" << 2 * n + 2 << " " << 4 * n << " 0\n";
  for (int z : {0, 2})
    for (const auto& p : s.ring) off << decimal(p[0] + Rational(z) / 2) << " " << decimal(p[1]) << " " << z << "\n";
  off << "0 0 0\n1 0 2\n";
  int cb = 2 * n, ct = 2 * n + 1;
  for (int k = 0; k < n; ++k) {
    int a = k, b = (k + 1) % n;
    off << "3 " << cb << " " << b << " " << a << "\n3 " << ct << " " << n + a << " " << n + b << "\n";
    off << "3 " << a << " " << b << " " << n + b << "\n3 " << a << " " << n + b << " " << n + a << "\n";
  }
  s.off = off.str();
  return s;
}

Solid decomposed_off(const std::string& text, Mesh_decomposition method)
{
  Checked_mesh m = check_mesh(read_mesh(text, Mesh_format::Off, "star.off"), "star.off");
  BOOST_TEST_REQUIRE(!m.convex);
  return decomposed_solid(m, "star.off", Mesh_limits(), method);
}

} // namespace

// Both decompositions give the solid the facets bound: on a grid of points
// (in sixteenths, many on facets, edges and corners) and at every vertex, a
// point is in the union of the pieces exactly when the prism's own rule
// says so. Seeded (CLASH4D_MESH_SEEDS prisms, 4 by default); the seed is
// printed.
BOOST_AUTO_TEST_CASE(both_decompositions_are_the_solid_point_by_point)
{
  const char* env = std::getenv("CLASH4D_MESH_SEEDS");
  int seeds = env ? std::atoi(env) : 4;
  for (int seed = 1; seed <= seeds; ++seed) {
    BOOST_TEST_MESSAGE("star prism: seed " << seed);
    std::mt19937 rng(static_cast<unsigned>(seed));
    Star_prism star = star_prism(rng, 7 + seed % 5);
    for (Mesh_decomposition method : {Mesh_decomposition::bsp, Mesh_decomposition::nef}) {
      Solid s = decomposed_off(star.off, method);
      std::string why = std::string(decomposition_name(method)) + " seed " + std::to_string(seed);
      int inside = 0, checked = 0;
      for (int i = -20; i <= 84; i += 4)
        for (int j = -68; j <= 68; j += 5)
          for (int k = -1; k <= 33; k += 4) {
            std::array<Rational, 3> p{Rational(i) / 16, Rational(j) / 16, Rational(k) / 16};
            bool expected = star.contains(p);
            inside += expected;
            ++checked;
            BOOST_TEST(in_pieces(s, p) == expected, why << " at " << to_string(p[0]) << " " << to_string(p[1]) << " "
                                                        << to_string(p[2]));
          }
      BOOST_TEST(inside > checked / 20, why << ": the grid reaches inside");
      for (const Solid& piece : s.children)
        for (std::size_t v = 0; v < piece.numbers.size(); v += 3)
          BOOST_TEST(star.contains({piece.numbers[v], piece.numbers[v + 1], piece.numbers[v + 2]}), why << ": a piece's corner");
    }
  }
}

// "decomposition" chooses the method; the default is the partition by
// facet planes; the record and the cache key tell them apart.
BOOST_AUTO_TEST_CASE(the_decomposition_is_an_option)
{
  auto with = [](const json& part) {
    return read_scene(read_json_text(scene_text(part, {{"block", {{"min", {5, 5, 5}}, {"max", {6, 6, 6}}}}}, "rest")),
                      meshes);
  };
  Scene by_default = with({{"mesh", "l_part.off"}});
  BOOST_TEST(by_default.meshes.at(0).decomposition == "bsp");
  Scene nef = with({{"mesh", "l_part.off"}, {"decomposition", "nef"}});
  BOOST_TEST(nef.meshes.at(0).decomposition == "nef");
  BOOST_TEST(with({{"mesh", "l_part.off"}, {"decomposition", "bsp"}}).meshes.at(0).decomposition == "bsp");
  BOOST_TEST(with({{"mesh", "cube.off"}}).meshes.at(0).decomposition == "");   // convex: one hull
  auto bad = refusal([&] { with({{"mesh", "l_part.off"}, {"decomposition", "tetrahedra"}}); });
  BOOST_TEST(bad.second == CLASH4D_EXIT_INVALID);
  BOOST_TEST(contains(bad.first, "objects[0].shape.decomposition"), bad.first);
  auto hull = refusal([&] { with({{"mesh", "l_part.off"}, {"as", "hull"}, {"decomposition", "nef"}}); });
  BOOST_TEST(hull.second == CLASH4D_EXIT_INVALID);
  BOOST_TEST(contains(hull.first, "has no effect"), hull.first);
  Mesh_options a, b;
  b.decomposition = Mesh_decomposition::nef;
  BOOST_TEST(a.key() != b.key());
}

BOOST_AUTO_TEST_CASE(mesh_key_is_strict)
{
  auto r = refusal([] { read_scene(read_json_text(scene_text({{"mesh", 3}}, {{"mesh", "x.off"}}, "rest"))); });
  BOOST_TEST(contains(r.first, "objects[0].shape.mesh: expected a string"), r.first);
  r = refusal([] { read_scene(read_json_text(scene_text({{"mesh", "cube.off"}, {"size", 2}}, {{"mesh", "x.off"}}, "rest"))); });
  BOOST_TEST(contains(r.first, "unknown key \"size\""), r.first);
  r = refusal([] { read_scene(read_json_text(scene_text({{"sphere", 1}}, {{"mesh", "x.off"}}, "rest"))); });
  BOOST_TEST(contains(r.first, "hull, mesh, union"), r.first);
}

// Issue 59 item 13 (docs/meshes.md, "Where a mesh file may be"): a scene
// reaches only mesh files under its own folder, links resolved, unless the
// user allows another folder; a link to a system file is refused unread.
BOOST_AUTO_TEST_CASE(a_scene_reaches_only_mesh_files_under_its_folder)
{
  namespace fs = std::filesystem;
  fs::path root = fs::temp_directory_path() / ("clash4d_test_mesh_paths." + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "scene" / "parts");
  fs::create_directories(root / "elsewhere");
  fs::copy_file(meshes + "/cube.off", root / "scene" / "parts" / "cube.off");
  fs::copy_file(meshes + "/cube.off", root / "elsewhere" / "cube.off");
  fs::create_symlink("/etc/passwd", root / "scene" / "passwd.off");
  fs::create_symlink(root / "elsewhere" / "cube.off", root / "scene" / "linked.off");
  auto scene_with = [&](const std::string& mesh) {
    std::string file = (root / "scene" / "s.json").string();
    std::ofstream(file) << scene_text({{"mesh", mesh}}, {{"block", {{"min", {5, 5, 5}}, {"max", {6, 6, 6}}}}}, "rest");
    return file;
  };
  const std::string elsewhere = (root / "elsewhere").string();
  for (const char* inside : {"parts/cube.off", "./parts/../parts/cube.off"})
    BOOST_TEST(run_clash4d({"check", scene_with(inside)}).status == 0, inside);
  for (const std::string& outside : std::vector<std::string>{"../elsewhere/cube.off", elsewhere + "/cube.off", "linked.off", "passwd.off"}) {
    Cli_run r = run_clash4d({"check", scene_with(outside)});
    BOOST_TEST(r.status == 2, outside << ": " << r.err);
    BOOST_TEST(contains(r.err, "objects[0].shape.mesh: the mesh file \"" + outside + "\" is outside the scene's folder"), r.err);
    BOOST_TEST(!contains(r.err, "root:"), r.err);   // nothing of /etc/passwd is read
  }
  for (const std::string& allowed : std::vector<std::string>{"../elsewhere/cube.off", elsewhere + "/cube.off", "linked.off"}) {
    Cli_run r = run_clash4d({"check", scene_with(allowed), "--allow-mesh-path", elsewhere});
    BOOST_TEST(r.status == 0, allowed << ": " << r.err);
  }
  Cli_run r = run_clash4d({"check", scene_with("passwd.off"), "--allow-mesh-path", elsewhere});
  BOOST_TEST(r.status == 2, r.err);
  // The library's reader: relative to the directory it is given.
  auto in_memory = [&](const std::string& mesh, const std::vector<std::string>& allowed) {
    return refusal([&] {
      read_scene(read_json_text(scene_text({{"mesh", mesh}}, {{"mesh", "parts/cube.off"}}, "rest")),
                 (root / "scene").string(), allowed);
    });
  };
  BOOST_TEST(in_memory("parts/cube.off", {}).second == 0);
  BOOST_TEST(in_memory("../elsewhere/cube.off", {}).second == 2);
  BOOST_TEST(in_memory("../elsewhere/cube.off", {elsewhere}).second == 0);
  fs::remove_all(root);
}

// Issue 58 item 1 and 2 (docs/meshes.md, "Repairs, scale and units"): each
// fault of fixtures/meshes/repair is refused by the strict reading, and each
// repair option, the union of shells, the hull, the scale and the units give
// the answers of its expected.json, derived by hand, in both semantics.
BOOST_AUTO_TEST_CASE(repairs_scale_and_units_give_the_hand_derived_answers)
{
  const std::string folder = meshes + "/repair";
  json expected = json::parse(file_text(folder + "/expected.json"));
  const json probe = {{"block", {{"min", {5, 5, 5}}, {"max", {6, 6, 6}}}}};
  for (const json& c : expected["refused"]) {
    std::string why = c["part"].dump() + ": " + c["why"].get<std::string>();
    auto r = refusal([&] { read_scene(read_json_text(scene_text(c["part"], probe, "rest")), folder); });
    BOOST_TEST(r.second == 2, why);
    const json& error = c["error"];   // a text, or texts the message must all hold
    for (const json& e : error.is_array() ? error : json::array({error}))
      BOOST_TEST(contains(r.first, e.get<std::string>()), why << "\n  got: " << r.first);
  }
  for (const json& c : expected["answers"]) {
    std::string why = c["part"].dump() + " against " + c["probe"].dump() + ": " + c["why"].get<std::string>();
    Scene scene = read_scene(read_json_text(scene_text(c["part"], c["probe"], "rest")), folder);
    Answer regular = run(scene, Semantics::regularised), closed = run(scene, Semantics::closed);
    BOOST_TEST(regular.collide == c["regularised"].get<bool>(), why);
    BOOST_TEST(closed.collide == c["closed"].get<bool>(), "closed " << why);
    BOOST_TEST(regular.time == (regular.collide ? "0" : ""), why);
    BOOST_TEST(closed.time == (closed.collide ? "0" : ""), "closed " << why);
  }
}

// What a repair did is recorded for --stats and the report, naming the
// file's facets; a mesh read with different options is read again.
BOOST_AUTO_TEST_CASE(repairs_are_recorded_per_mesh_and_options)
{
  const std::string folder = meshes + "/repair";
  json s = {{"format", "clash4d-scene/1"},
            {"time", {0, 1}},
            {"objects",
             {{{"name", "a"}, {"shape", {{"mesh", "zero_area.off"}, {"repair", {"drop-zero-area"}}}}},
              {{"name", "b"}, {"shape", {{"mesh", "zero_area.off"}, {"repair", {"drop-zero-area"}}}}},
              {{"name", "c"}, {"shape", {{"mesh", "zero_area.off"}, {"as", "hull"}, {"units", "mm"}}}},
              {{"name", "d"}, {"shape", {{"mesh", "offplane_fan.off"}, {"repair", {"triangulate"}}}}}}}};
  Scene scene = read_scene(read_json_text(s.dump()), folder);
  BOOST_REQUIRE(scene.meshes.size() == 3u);
  const Mesh_record &dropped = scene.meshes[0], &hull = scene.meshes[1], &cut = scene.meshes[2];
  BOOST_TEST(dropped.facets == 9);
  BOOST_TEST(dropped.solid_rule == "odd shells");
  BOOST_REQUIRE(dropped.repairs.size() == 1u);
  BOOST_TEST(contains(dropped.repairs[0], "1 zero-area facet(s) dropped (facet 8), 1 neighbour(s) cut"), dropped.repairs[0]);
  BOOST_TEST(dropped.pieces == 1);
  BOOST_TEST(hull.solid_rule == "hull of the vertices");
  BOOST_TEST(hull.scale == "1/1000");
  BOOST_TEST(hull.repairs.empty());
  BOOST_REQUIRE(cut.repairs.size() == 1u);
  BOOST_TEST(contains(cut.repairs[0], "triangulate: 4 facet(s)"), cut.repairs[0]);
  BOOST_TEST(contains(cut.repairs[0], "(the first: facet 1)"), cut.repairs[0]);
}

// "split-pinched": a pinched vertex becomes one vertex per fan, the solid is
// the same (the loop of eight unit cubes, the two boxes; their pieces are
// boxes), and the record names the point and a facet of each fan.
BOOST_AUTO_TEST_CASE(split_pinched_keeps_the_solid_and_is_recorded)
{
  const std::string folder = meshes + "/repair";
  json s = {{"format", "clash4d-scene/1"},
            {"time", {0, 1}},
            {"objects",
             {{{"name", "loop"}, {"shape", {{"mesh", "pinched_loop.off"}, {"repair", {"split-pinched"}}}}},
              {{"name", "boxes"}, {"shape", {{"mesh", "pinched.off"}, {"repair", {"split-pinched"}}}}}}}};
  Scene scene = read_scene(read_json_text(s.dump()), folder);
  BOOST_REQUIRE(scene.meshes.size() == 2u);
  const Mesh_record &loop = scene.meshes[0], &boxes = scene.meshes[1];
  BOOST_REQUIRE(loop.repairs.size() == 1u);
  BOOST_TEST(contains(loop.repairs[0], "split-pinched: 1 pinched vertex(es) split"), loop.repairs[0]);
  BOOST_TEST(contains(loop.repairs[0], "(2, 1, 1) between facets 13 and 21"), loop.repairs[0]);
  BOOST_TEST(loop.solid_rule == "odd shells");
  BOOST_TEST(pieces_volume(scene.objects[0].shape) == Rational(8));
  BOOST_REQUIRE(boxes.repairs.size() == 1u);
  BOOST_TEST(contains(boxes.repairs[0], "(1, 1, 1) between facets 1 and 6"), boxes.repairs[0]);
  BOOST_TEST(boxes.pieces == 2);
  BOOST_TEST(pieces_volume(scene.objects[1].shape) == Rational(2));
  // Nothing to split: no record line, the same solid as without the option.
  json cube = {{"format", "clash4d-scene/1"},
               {"time", {0, 1}},
               {"objects",
                {{{"name", "a"}, {"shape", {{"mesh", "cube.off"}, {"repair", {"split-pinched"}}}}},
                 {{"name", "b"}, {"shape", {{"mesh", "cube.off"}}}}}}};
  Scene plain = read_scene(read_json_text(cube.dump()), folder);
  BOOST_REQUIRE(plain.meshes.size() == 2u);
  BOOST_TEST(plain.meshes[0].repairs.empty());
  BOOST_TEST((plain.objects[0].shape.kind == Solid::Kind::Hull));
  BOOST_TEST((plain.objects[0].shape.numbers == plain.objects[1].shape.numbers));
}

// The crossing test lets the copies of a split vertex meet at their point
// and nowhere else: two tetrahedra at the apex (0,0,0), the second turned
// about it, touch there alone, or share a ray from it, or cross through it.
BOOST_AUTO_TEST_CASE(split_vertices_meet_only_at_their_point)
{
  auto tetrahedra = [](const std::string& second) {
    return "OFF\n7 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + second +
           "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 0 4 5\n3 0 6 4\n3 0 5 6\n3 4 6 5\n";
  };
  auto read = [&](const std::string& second) {
    Mesh_options o;
    o.split_pinched = true;
    Mesh_record record;
    return refusal([&] { repaired_solid(read_mesh(tetrahedra(second), Mesh_format::Off, "t.off"), "t.off", o, record); });
  };
  // The point reflection of the first: the octants (+,+,+) and (-,-,-) meet at the apex alone.
  BOOST_TEST(read("-1 0 0\n0 -1 0\n0 0 -1\n").second == 0);
  // The octant (+,-,-) from the apex: it shares the ray along (1,0,0), so
  // the facets meet along the segment from (0,0,0) to (1,0,0).
  auto ray = read("2 0 0\n0 0 -1\n0 -1 0\n");
  BOOST_TEST(ray.second == CLASH4D_EXIT_INVALID);
  BOOST_TEST(contains(ray.first, "the surface intersects itself"), ray.first);
  // The cone of (1,1,-1), (1,-1,1), (-1,1,1) holds their sum (1,1,1), inside
  // the first's octant: the surfaces cross through the apex.
  auto through = read("1 1 -1\n1 -1 1\n-1 1 1\n");
  BOOST_TEST(through.second == CLASH4D_EXIT_INVALID);
  BOOST_TEST(contains(through.first, "the surface intersects itself"), through.first);
}

// --- issue 58 item 4: --earliest by piece pairs (check/Piece_pairs.h) ---

namespace {

Vector4<Rational> point_of(const std::array<std::string, 4>& text)
{
  Vector4<Rational> p;
  for (int q = 0; q < 4; ++q) p[q] = exact(text[q]);
  return p;
}

// The earliest pair's points as printed, checked against the scene's own
// objects in rationals (model/Point_classifier.h), as the cascade's are.
bool points_hold(const Scene& scene, const Check_answer& a)
{
  Rational_kernel k;
  Scene_model<Rational_kernel> model = Scene_model<Rational_kernel>::build(k, scene);
  const Pair_answer& p = a.pairs[static_cast<std::size_t>(a.earliest_pair)];
  int ia = -1, ib = -1;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (scene.objects[i].name == p.a) ia = static_cast<int>(i);
    if (scene.objects[i].name == p.b) ib = static_cast<int>(i);
  }
  if (ia < 0 || ib < 0) return false;
  if (a.semantics == Semantics::closed)
    return is_valid_touch(k, model, ia, ib, point_of(p.witness), point_of(p.witness_cells[0]),
                          point_of(p.witness_cells[1])) &&
           is_valid_touch(k, model, ia, ib, point_of(p.contact), point_of(p.contact_cells[0]),
                          point_of(p.contact_cells[1]));
  return is_valid_witness(k, model, ia, ib, point_of(p.witness)) &&
         is_valid_contact_cell(k, model, ia, ib, point_of(p.contact), point_of(p.contact_cells[0]));
}

// The piece pairs' answer is the cascade's (Check_options::piece_pairs
// false): verdict, pair and t* exactly, every point verified and holding
// against the objects; exact and rational kernels. The double run only
// has to answer.
// Returns whether they collide.
bool same_as_cascade(const Scene& scene, Semantics semantics, const std::string& why)
{
  Check_options pieces;
  pieces.earliest = true;
  pieces.semantics = semantics;
  Check_options cascade = pieces;
  cascade.piece_pairs = false;
  {
    // The piece pairs answer it themselves (no fallback to the cascade).
    Rational_kernel k;
    Scene_model<Rational_kernel> model = Scene_model<Rational_kernel>::build(k, scene);
    std::optional<Piece_split> split = Piece_split::make(scene);
    BOOST_TEST_REQUIRE(split.has_value(), why);
    BOOST_TEST(piece_pairs_check(k, scene, model, pieces, *split).has_value(), why << ": left to the cascade");
  }
  bool collide = false;
  for (auto check : {&check_exact, &check_rational}) {
    Check_answer n = check(scene, pieces), c = check(scene, cascade);
    BOOST_TEST(n.collide == c.collide, why);
    collide = n.collide;
    if (!n.collide || !c.collide) continue;
    const Pair_answer &pn = n.pairs[static_cast<std::size_t>(n.earliest_pair)],
                      &pc = c.pairs[static_cast<std::size_t>(c.earliest_pair)];
    BOOST_TEST(pn.a + "/" + pn.b == pc.a + "/" + pc.b, why);
    BOOST_TEST(pn.t_star == pc.t_star, why);
    BOOST_TEST(pn.at_start == pc.at_start, why);
    BOOST_TEST(pn.witness_verified, why);
    BOOST_TEST(points_hold(scene, n), why);
  }
  check_double(scene, 0, pieces);
  return collide;
}

// A union of `n` blocks with corners on the grid 0..4 (often touching or
// sharing faces: the degenerate cases), some under a translate.
json random_union(std::mt19937& rng, int n)
{
  std::uniform_int_distribution<int> c(0, 4);
  json parts = json::array();
  for (int i = 0; i < n; ++i) {
    int lo[3], hi[3];
    for (int q = 0; q < 3; ++q) {
      lo[q] = c(rng);
      hi[q] = c(rng);
      if (lo[q] > hi[q]) std::swap(lo[q], hi[q]);
      if (lo[q] == hi[q]) ++hi[q];
    }
    json block = {{"block", {{"min", {lo[0], lo[1], lo[2]}}, {"max", {hi[0], hi[1], hi[2]}}}}};
    parts.push_back(c(rng) == 0 ? json{{"translate", {0.5, 0, 0}}, {"solid", block}} : block);
  }
  return {{"union", parts}};
}

} // namespace

// The L part as a mesh (two convex pieces) against each probe of
// expected.json, and seeded scenes of two unions of blocks: the same t*,
// verdict and pair as the cascade, with points that hold, in both
// semantics.
BOOST_AUTO_TEST_CASE(earliest_by_piece_pairs_is_the_cascades)
{
  json expected = json::parse(file_text(meshes + "/expected.json"));
  for (const auto& [name, s] : expected["scenes"].items()) {
    Scene scene = read_scene(read_json_text(scene_text({{"mesh", "l_part.off"}}, s["probe"], s.value("motion", "rest"))),
                             meshes);
    for (Semantics semantics : {Semantics::regularised, Semantics::closed})
      same_as_cascade(scene, semantics, "l_part " + name);
  }
  int colliding = 0;
  const char* env = std::getenv("CLASH4D_PIECE_SEEDS");
  int seeds = env ? std::atoi(env) : 12;
  std::uniform_int_distribution<int> v(-2, 2);
  for (int seed = 1; seed <= seeds; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(seed));
    json a = random_union(rng, 3), b = random_union(rng, 2);
    std::string motion = "vel";
    for (int q = 0; q < 3; ++q) motion += " " + std::to_string(v(rng));
    json text = {{"format", "clash4d-scene/1"},
                 {"time", {0, 3}},
                 {"objects", {{{"name", "a"}, {"shape", a}},
                              {{"name", "b"}, {"shape", {{"translate", {3, 1, 0}}, {"solid", b}}}, {"motion", motion}}}}};
    Scene scene = read_scene(read_json_text(text.dump()));
    BOOST_TEST_MESSAGE("piece pairs: seed " << seed);
    for (Semantics semantics : {Semantics::regularised, Semantics::closed})
      colliding += same_as_cascade(scene, semantics, "seed " + std::to_string(seed) + ": " + text.dump());
  }
  BOOST_TEST_MESSAGE("piece pairs: " << colliding << " of " << 2 * seeds << " seeded queries collide");
  BOOST_TEST(colliding > 0);
}

// --stats on the piece pairs' path counts the filtered runner's own work,
// as check does (Filtered_runner::finish): each colliding answer is made by
// the interval run (witnesses_by_intervals), a convex pair's programs
// (convex_exact_signs) or a rational run (exact_witness_runs,
// exact_fallbacks) (docs/filtered-kernel.md, "The --stats counters"); the
// L part's pieces are all made in intervals. Before, the runner's counters
// were left at 0 on this path.
BOOST_AUTO_TEST_CASE(piece_pairs_stats_count_the_filtered_runners_work)
{
  json expected = json::parse(file_text(meshes + "/expected.json"));
  int colliding = 0;
  for (const auto& [name, s] : expected["scenes"].items()) {
    Scene scene = read_scene(read_json_text(scene_text({{"mesh", "l_part.off"}}, s["probe"], s.value("motion", "rest"))),
                             meshes);
    Check_options pieces;
    pieces.earliest = true;
    BOOST_TEST_REQUIRE(Piece_split::make(scene).has_value(), name);
    Check_answer a = check_exact(scene, pieces);
    if (!a.collide) continue;
    ++colliding;
    const Check_stats& st = a.stats;
    BOOST_TEST(st.witnesses_by_intervals + st.convex_exact_signs + st.exact_witness_runs + st.exact_fallbacks > 0u,
               name << ": the colliding pair's answer is counted");
  }
  BOOST_TEST(colliding > 0);
}

// --earliest on unions whose pieces' boxes cannot meet, or whose one pair
// of pieces whose boxes may meet does not collide, is answered before
// anything is made in rationals (no S-bound pass: the rational path settles
// the pieces' S-bounds first), with expected.json's hand answer. The L's
// pieces' boxes are [0,2]x[0,1]x[0,1] and [0,1]x[1,2]x[0,1]: pocket_miss and
// clear_miss have a gap to both in x or y (both semantics); the four
// touches' probes only touch them (so regularised semantics drops those
// pairs, and closed keeps them); passing_by's moving box is never where
// they are at the same time (the sweep keeps it, the moving boxes' bound,
// asked in intervals, does not); corner_gap's box overlaps the lower arm's
// alone, and the probe does not meet that arm (both semantics). Every
// other scene has a pair of pieces whose boxes meet and which collides.
BOOST_AUTO_TEST_CASE(earliest_on_pieces_whose_boxes_cannot_meet_is_answered_first)
{
  json expected = json::parse(file_text(meshes + "/expected.json"));
  std::set<std::string> swept;
  for (const auto& [name, s] : expected["scenes"].items()) {
    Scene scene = read_scene(read_json_text(scene_text({{"mesh", "l_part.off"}}, s["probe"], s.value("motion", "rest"))),
                             meshes);
    for (Semantics semantics : {Semantics::regularised, Semantics::closed}) {
      std::string key = semantics == Semantics::closed ? "closed" : "regularised";
      Check_options o;
      o.earliest = true;
      o.semantics = semantics;
      Check_answer a = check_exact(scene, o);
      BOOST_TEST(a.collide == s[key]["collide"].get<bool>(), name << " " << key);
      if (a.stats.sbound_passes > 0) continue;
      swept.insert(name + " " + key);
      BOOST_TEST(a.stats.object_pairs == 2u, name << " " << key << ": the L's two pieces against the probe");
    }
  }
  std::set<std::string> by_hand{"pocket_miss regularised", "pocket_miss closed",   "clear_miss regularised",
                                "clear_miss closed",       "face_touch regularised", "edge_touch regularised",
                                "pocket_fill_touch regularised", "pocket_corner_touch regularised",
                                "passing_by regularised",  "passing_by closed",
                                "corner_gap regularised",  "corner_gap closed"};
  BOOST_TEST((swept == by_hand));
}

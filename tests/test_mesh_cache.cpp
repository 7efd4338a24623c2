#define BOOST_TEST_MODULE mesh_cache
#include <boost/test/unit_test.hpp>

#include "run/Work_budget.h"
#include "scene/Child_process.h"
#include "scene/Input_error.h"
#include "scene/Mesh_cache.h"
#include "scene/Mesh_options.h"
#include "scene/Mesh_solid.h"
#include "scene/Scene_reader.h"
#include "scene/Slow_step_note.h"
#include "support/Cli_run.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <openssl/evp.h>
#include <sstream>
#include <thread>
#include <unistd.h>

using namespace clash4d;
namespace fs = std::filesystem;

namespace {

const std::string meshes = std::string(CLASH4D_FIXTURES) + "/meshes";

// An environment variable set for one test and put back after it.
class Scoped_env {
public:
  Scoped_env(const char* name, const std::string& value) : name_(name)
  {
    const char* old = std::getenv(name);
    had_ = old != nullptr;
    if (had_) old_ = old;
    setenv(name, value.c_str(), 1);
  }
  ~Scoped_env()
  {
    if (had_) setenv(name_, old_.c_str(), 1);
    else unsetenv(name_);
  }

private:
  const char* name_;
  bool had_;
  std::string old_;
};

// CLASH4D_CACHE_DIR as a fresh folder (not yet made) for one test.
struct Fresh_cache {
  fs::path folder = fs::temp_directory_path() /
                    ("clash4d-test-mesh-cache-" + std::to_string(getpid()) + "-" + std::to_string(count++));
  Scoped_env env{"CLASH4D_CACHE_DIR", folder.string()};
  Fresh_cache() { fs::remove_all(folder); }
  ~Fresh_cache() { fs::remove_all(folder); }

  std::vector<fs::path> files() const
  {
    std::vector<fs::path> out;
    std::error_code ec;
    if (fs::is_directory(folder, ec))
      for (const auto& e : fs::directory_iterator(folder)) out.push_back(e.path());
    return out;
  }
  static inline int count = 0;
};

std::string file_text(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void write_text(const fs::path& path, const std::string& text)
{
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

std::string sha256_hex(const std::string& text)
{
  unsigned char d[EVP_MAX_MD_SIZE];
  unsigned int n = 0;
  EVP_Digest(text.data(), text.size(), d, &n, EVP_sha256(), nullptr);
  std::string out;
  for (unsigned int i = 0; i < n; ++i) out += {"0123456789abcdef"[d[i] >> 4], "0123456789abcdef"[d[i] & 15]};
  return out;
}

Solid read_part(const std::string& file, Mesh_record& record)
{
  return read_mesh_solid(meshes + "/" + file, file, Mesh_limits(), &record);
}

// The same solid to the last number and index: what the checks build from.
bool same_solid(const Solid& a, const Solid& b)
{
  if (a.kind != b.kind || a.numbers != b.numbers || a.triples != b.triples || a.constructed != b.constructed ||
      a.children.size() != b.children.size() || !a.corners != !b.corners || (a.corners && *a.corners != *b.corners))
    return false;
  for (std::size_t i = 0; i < a.children.size(); ++i)
    if (!same_solid(a.children[i], b.children[i])) return false;
  return true;
}

// The L-part decomposed without the cache: the answer every read must give.
Solid reference_part()
{
  return mesh_solid(check_mesh(read_mesh_file(meshes + "/l_part.off", "l_part.off"), "l_part.off"), "l_part.off");
}

} // namespace

BOOST_AUTO_TEST_CASE(second_read_is_a_hit_with_the_same_pieces)
{
  Fresh_cache cache;
  Mesh_record first, second;
  Solid a = read_part("l_part.off", first);
  BOOST_TEST(first.cache == "miss");
  BOOST_TEST(first.facets == 10);
  BOOST_TEST(first.triangles == 20);
  BOOST_TEST(first.pieces == static_cast<int>(a.children.size()));
  BOOST_TEST(first.pieces >= 2);
  BOOST_REQUIRE(cache.files().size() == 1u);
  BOOST_TEST(cache.files()[0].extension() == ".pieces");
  Solid b = read_part("l_part.off", second);
  BOOST_TEST(second.cache == "hit");
  BOOST_TEST(second.decomposition_seconds == 0);
  BOOST_TEST(second.pieces == first.pieces);
  BOOST_TEST(same_solid(a, b));
  BOOST_TEST(same_solid(a, reference_part()));
  BOOST_TEST(cache.files().size() == 1u);   // nothing left behind (temporaries)
}

BOOST_AUTO_TEST_CASE(the_key_tells_meshes_and_options_apart)
{
  Checked_mesh l = check_mesh(read_mesh_file(meshes + "/l_part.off", "l_part.off"), "l_part.off");
  std::string k = Mesh_cache::key(l, Mesh_options().key());
  BOOST_TEST(k.size() == 64u);
  BOOST_TEST(Mesh_cache::key(l, Mesh_options().key()) == k);
  Mesh_options scaled;
  scaled.scale = Rational(2);
  BOOST_TEST(Mesh_cache::key(l, scaled.key()) != k);
  Checked_mesh moved = l;
  moved.vertices[0][0] += Rational(1, 1000000);
  BOOST_TEST(Mesh_cache::key(moved, Mesh_options().key()) != k);
}

BOOST_AUTO_TEST_CASE(a_damaged_entry_is_decomposed_again_with_the_same_answer)
{
  Fresh_cache cache;
  Mesh_record record;
  Solid reference = read_part("l_part.off", record);
  BOOST_REQUIRE(cache.files().size() == 1u);
  fs::path entry = cache.files()[0];
  std::string good = file_text(entry);
  // A body whose hash is right but whose pieces do not fill the mesh: one
  // piece dropped, the count and the hash made to agree.
  std::size_t body_at = good.find('\n', good.find("\nbody ") + 1) + 1;
  std::string body = good.substr(body_at);
  std::size_t last_piece = body.rfind("piece ");
  std::string fewer = body.substr(0, last_piece);
  int n = record.pieces;
  fewer.replace(0, fewer.find('\n'), "pieces " + std::to_string(n - 1));
  std::string header = good.substr(0, good.find("\nbody ")) + "\nbody " + sha256_hex(fewer) + "\n";
  std::string flipped_body = good, flipped_key = good;
  flipped_body[body_at + body.size() / 2] ^= 1;
  flipped_key[good.find("\nkey ") + 6] ^= 1;
  std::vector<std::pair<std::string, std::string>> damages = {
      {"a byte of the body flipped", flipped_body},
      {"a byte of the key flipped", flipped_key},
      {"cut in the middle", good.substr(0, good.size() / 2)},
      {"cut by one byte", good.substr(0, good.size() - 1)},
      {"empty", ""},
      {"text appended", good + "piece 4\n"},
      {"a piece missing, hash made right", header + fewer},
  };
  for (const auto& [what, text] : damages) {
    BOOST_TEST_CONTEXT(what)
    {
      write_text(entry, text);
      Mesh_record again;
      Solid s = read_part("l_part.off", again);
      BOOST_TEST(again.cache == "miss");
      BOOST_TEST(same_solid(s, reference));
      BOOST_TEST(file_text(entry) == good);   // overwritten with the right entry
      Mesh_record then;
      read_part("l_part.off", then);
      BOOST_TEST(then.cache == "hit");
    }
  }
}

BOOST_AUTO_TEST_CASE(off_writes_nothing_and_a_folder_that_cannot_be_made_is_off)
{
  Fresh_cache cache;
  {
    Scoped_env off("CLASH4D_MESH_CACHE", "off");
    Mesh_record record;
    Solid s = read_part("l_part.off", record);
    BOOST_TEST(record.cache == "off");
    BOOST_TEST(same_solid(s, reference_part()));
    BOOST_TEST(!fs::exists(cache.folder));
  }
  // Under a regular file: no folder can be made, the cache is off, no error.
  fs::create_directories(cache.folder);
  write_text(cache.folder / "file", "x");
  Scoped_env blocked("CLASH4D_CACHE_DIR", (cache.folder / "file" / "meshes").string());
  Mesh_record record;
  Solid s = read_part("l_part.off", record);
  BOOST_TEST(record.cache == "off");
  BOOST_TEST(same_solid(s, reference_part()));
  BOOST_TEST(cache.files().size() == 1u);
}

BOOST_AUTO_TEST_CASE(a_convex_mesh_is_not_decomposed_nor_cached)
{
  Fresh_cache cache;
  Mesh_record record;
  Solid cube = read_part("cube.off", record);
  BOOST_TEST((cube.kind == Solid::Kind::Hull));
  BOOST_TEST(record.cache == "");
  BOOST_TEST(record.pieces == 1);
  BOOST_TEST(cache.files().empty());
}

BOOST_AUTO_TEST_CASE(the_scene_records_each_mesh_file_and_check_stats_shows_them)
{
  Fresh_cache cache;
  Scene scene = read_scene_file(meshes + "/scene_l_part.json");
  BOOST_REQUIRE(scene.meshes.size() == 1u);
  const Mesh_record& m = scene.meshes[0];
  BOOST_TEST(m.file == "l_part_binary.stl");
  BOOST_TEST(m.place == "objects[0].shape.mesh");
  BOOST_TEST(m.facets == 20);   // STL: triangles
  BOOST_TEST(m.triangles == 20);
  BOOST_TEST(m.cache == "miss");
  Cli_run run = run_clash4d({"check", meshes + "/scene_l_part.json", "--stats", "--json"});
  auto j = nlohmann::json::parse(run.out);
  BOOST_REQUIRE(j["stats"]["meshes"].size() == 1u);
  BOOST_TEST(j["stats"]["meshes"][0]["cache"] == "hit");
  BOOST_TEST(j["stats"]["meshes"][0]["pieces"] == m.pieces);
  BOOST_TEST(j["stats"]["meshes"][0]["place"] == "objects[0].shape.mesh");
  Cli_run text = run_clash4d({"check", meshes + "/scene_l_part.json", "--stats"});
  BOOST_TEST(text.out.find("  meshes:\n    l_part_binary.stl (objects[0].shape.mesh): 20 facets, 20 triangles, ") !=
                 std::string::npos,
             text.out);
  BOOST_TEST(text.out.find("(cache hit)") != std::string::npos, text.out);
  // Without --stats, nothing about meshes.
  BOOST_TEST(run_clash4d({"check", meshes + "/scene_l_part.json", "--json"}).out.find("meshes") == std::string::npos);
}

// --max-seconds and the API's cancel flag cover the decomposition (issue 58
// item 3): with a budget it runs in a child process (scene/Child_process.h),
// and its pieces must be the very ones made here.
BOOST_AUTO_TEST_CASE(a_budgeted_decomposition_gives_the_same_pieces_from_its_child)
{
  Fresh_cache cache;
  struct Budget {   // 5 minutes: a child that never ends fails here, not at the CI's cut
    Budget() { Work_budget::start(300); }
    ~Budget() { Work_budget::start(0); }
  } budget;
  BOOST_REQUIRE(Work_budget::limited());
  Mesh_record record;
  Solid a = read_part("l_part.off", record);
  BOOST_TEST(record.cache == "miss");
  BOOST_TEST(same_solid(a, reference_part()));
}

BOOST_AUTO_TEST_CASE(a_child_returns_its_text_its_input_error_and_its_lack_of_memory)
{
  auto never = [] {};
  std::string big(3 << 20, 'x');   // more than a pipe holds: read while the child writes
  big[12345] = '\n';
  BOOST_TEST(text_of_child([&] { return big; }, never, "here") == big);
  try {
    text_of_child([]() -> std::string { throw Input_error("facet 7", "not planar", 3); }, never, "here");
    BOOST_FAIL("no Input_error");
  } catch (const Input_error& e) {
    BOOST_TEST(e.place() == "facet 7");
    BOOST_TEST(std::string(e.what()) == "not planar");
    BOOST_TEST(e.exit_code() == 3);
  }
  BOOST_CHECK_THROW(text_of_child([]() -> std::string { throw std::bad_alloc(); }, never, "here"), std::bad_alloc);
  try {
    text_of_child([]() -> std::string { throw std::logic_error("CGAL said no"); }, never, "m.off");
    BOOST_FAIL("no Input_error");
  } catch (const Input_error& e) {
    BOOST_TEST(e.place() == "m.off");
    BOOST_TEST(e.exit_code() == 4);
    BOOST_TEST(std::string(e.what()).find("CGAL said no") != std::string::npos);
  }
}

// A poll that throws (the budget ran out, the run was cancelled) stops a
// child that would never end: killed and reaped, the exception passed on.
BOOST_AUTO_TEST_CASE(a_child_is_killed_and_reaped_when_the_poll_throws)
{
  struct Stop {};
  int fds[2];
  BOOST_REQUIRE(pipe(fds) == 0);
  int polls = 0;
  auto work = [&]() -> std::string {
    pid_t me = getpid();
    if (write(fds[1], &me, sizeof me) != sizeof me) _exit(1);
    for (;;) pause();
  };
  BOOST_CHECK_THROW(text_of_child(work, [&] { if (++polls == 4) throw Stop{}; }, "here"), Stop);
  pid_t child = 0;
  BOOST_REQUIRE(read(fds[0], &child, sizeof child) == sizeof child);
  close(fds[0]);
  close(fds[1]);
  BOOST_TEST(polls == 4);
  BOOST_TEST(child != getpid());
  BOOST_TEST((kill(child, 0) == -1 && errno == ESRCH));   // gone: not even a zombie
}

// Standard error, redirected into a file while `body` runs; its text.
template <class Body>
static std::string stderr_of(Body body)
{
  fs::path file = fs::temp_directory_path() / ("clash4d-note-" + std::to_string(getpid()) + ".txt");
  std::fflush(stderr);
  int saved = dup(STDERR_FILENO);
  FILE* sink = std::fopen(file.c_str(), "w");
  BOOST_REQUIRE(saved >= 0 && sink != nullptr);
  dup2(fileno(sink), STDERR_FILENO);
  body();
  std::fflush(stderr);
  dup2(saved, STDERR_FILENO);
  close(saved);
  std::fclose(sink);
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  fs::remove(file);
  return text.str();
}

// Issue 58: a long step shows progress in logs too. Standard error here is a
// file, not a terminal: whole lines while the step runs, then one at its end;
// nothing at all for a quick step.
BOOST_AUTO_TEST_CASE(a_slow_step_writes_lines_in_a_log_and_a_quick_one_nothing)
{
  using std::chrono::milliseconds;
  Slow_step_note::Delays short_delays{milliseconds(20), milliseconds(20), milliseconds(50)};
  std::string slow = stderr_of([&] {
    Slow_step_note note("decomposing bowl.off (8 triangles)", short_delays);
    std::this_thread::sleep_for(milliseconds(400));
  });
  BOOST_TEST_MESSAGE("the slow step's log:\n" << slow);
  std::istringstream lines(slow);
  std::string line, last;
  int so_far = 0;
  while (std::getline(lines, line)) {
    BOOST_TEST(line.rfind("clash4d: decomposing bowl.off (8 triangles): ", 0) == 0);
    so_far += line.find(" s so far") != std::string::npos;
    last = line;
  }
  BOOST_TEST(so_far >= 2);
  BOOST_TEST(last.find(": done in ") != std::string::npos);
  BOOST_TEST(stderr_of([] { Slow_step_note note("decomposing quick.off (8 triangles)"); }).empty());
}

// Two cubes [0,2]^3 and [1,3]^3 in one OFF file: each shell closed and
// outward, so every check but the crossing test passes.
static std::string overlapping_cubes_off()
{
  std::string text = "OFF\n16 12 0\n";
  for (int o : {0, 1})
    for (int i = 0; i < 8; ++i)
      text += std::to_string(o + 2 * (i & 1)) + " " + std::to_string(o + 2 * ((i >> 1) & 1)) + " " +
              std::to_string(o + 2 * ((i >> 2) & 1)) + "\n";
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (int o : {0, 8})
    for (const auto& f : faces)
      text += "4 " + std::to_string(o + f[0]) + " " + std::to_string(o + f[1]) + " " + std::to_string(o + f[2]) +
              " " + std::to_string(o + f[3]) + "\n";
  return text;
}

// A cache hit skips the crossing test (an entry stands for a mesh that
// passed it), so a mesh that fails it must never get an entry: refused on
// every read, with nothing written to the cache.
BOOST_AUTO_TEST_CASE(a_crossing_mesh_is_refused_on_every_read_and_never_cached)
{
  Fresh_cache cache;
  fs::path file = fs::temp_directory_path() / ("clash4d-crossing-" + std::to_string(getpid()) + ".off");
  write_text(file, overlapping_cubes_off());
  BOOST_REQUIRE(check_mesh_surface(read_mesh_file(file.string(), "crossing.off"), "crossing.off").volume == 16);
  for (int read = 0; read < 2; ++read) {
    Mesh_record record;
    try {
      read_mesh_solid(file.string(), "crossing.off", Mesh_limits(), &record);
      BOOST_FAIL("a crossing mesh was read as a solid");
    } catch (const Input_error& e) {
      BOOST_TEST(std::string(e.what()).find("the surface intersects itself") != std::string::npos, e.what());
    }
    BOOST_TEST(cache.files().empty());
  }
  fs::remove(file);
}

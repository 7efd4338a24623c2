#include "scene/Mesh_cache.h"
#include "scene/Hull_solid.h"
#include "scene/Mesh_solid.h"
#include "scene/Slow_step_note.h"
#include "scene/Child_process.h"
#include "run/Work_budget.h"

#include <CGAL/version.h>
#include <openssl/evp.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <fcntl.h>
#include <fstream>
#include <optional>
#include <sstream>
#include <unistd.h>

namespace clash4d {
namespace {

namespace fs = std::filesystem;

std::string sha256_hex(const std::string& text)
{
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int size = 0;
  if (EVP_Digest(text.data(), text.size(), digest, &size, EVP_sha256(), nullptr) != 1)
    throw std::runtime_error("SHA-256 failed");
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (unsigned int i = 0; i < size; ++i) out += {hex[digest[i] >> 4], hex[digest[i] & 15]};
  return out;
}

// An environment variable, "" when unset.
std::string env(const char* name)
{
  const char* v = std::getenv(name);
  return v ? v : "";
}

// The folder, made if missing; empty when it cannot be.
fs::path made_folder(const fs::path& folder)
{
  std::error_code ec;
  fs::create_directories(folder, ec);
  return !ec && fs::is_directory(folder, ec) ? folder : fs::path();
}

// The entry's body: "pieces N", then per piece "piece V" and its V points,
// "x y z" each, as exact rationals; the order of Solid::numbers, so a piece
// rebuilds as the very hull it was (same triples, same planes).
std::string body_text(const Solid& pieces)
{
  std::ostringstream out;
  out << "pieces " << pieces.children.size() << "\n";
  for (const Solid& piece : pieces.children) {
    out << "piece " << piece.numbers.size() / 3 << "\n";
    for (std::size_t i = 0; i + 2 < piece.numbers.size(); i += 3)
      out << to_string(piece.numbers[i]) << " " << to_string(piece.numbers[i + 1]) << " "
          << to_string(piece.numbers[i + 2]) << "\n";
  }
  return out.str();
}

// The next "WORD N" line's N; throws std::invalid_argument otherwise.
std::size_t count_line(std::istream& in, const std::string& word, std::size_t max)
{
  std::string w, n;
  if (!(in >> w >> n) || w != word || n.empty() || n.size() > 9 || n.find_first_not_of("0123456789") != std::string::npos)
    throw std::invalid_argument("bad count");
  std::size_t count = std::stoul(n);
  if (count > max) throw std::invalid_argument("count beyond the limit");
  return count;
}

// The pieces of a body, each rebuilt and validated as a hull, and six times
// their volume; throws std::invalid_argument for any text that is not such a
// body.
Solid parse_body(const std::string& body, std::size_t max_pieces, Rational& six_volume)
{
  std::istringstream in(body);
  Solid u;
  u.kind = Solid::Kind::Union;
  std::size_t count = count_line(in, "pieces", max_pieces);
  for (std::size_t k = 0; k < count; ++k) {
    std::size_t n = count_line(in, "piece", CLASH4D_MAX_MESH_VERTICES);
    std::vector<Rational3> points(n);
    std::string text;
    for (auto& p : points)
      for (Rational& x : p) {
        if (!(in >> text)) throw std::invalid_argument("cut short");
        x = rational_from_string(text);
      }
    u.children.emplace_back();
    six_volume += make_hull_solid(points, u.children.back());
  }
  std::string rest;
  if (in >> rest) throw std::invalid_argument("text after the pieces");
  return u;
}

std::string file_text(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Writes text to a new file at path and makes it durable; false on failure.
bool write_new_file(const fs::path& path, const std::string& text)
{
  int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) return false;
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  bool ok = left == 0 && ::fsync(fd) == 0;
  return ::close(fd) == 0 && ok;
}

// The entry: its format, its key, its body's SHA-256, its body.
std::string entry_text(const std::string& key, const std::string& body)
{
  return "clash4d-mesh-cache " + std::to_string(CLASH4D_MESH_CACHE_VERSION) + "\nkey " + key + "\nbody " +
         sha256_hex(body) + "\n" + body;
}

void write_entry(const fs::path& folder, const std::string& key, const Solid& pieces)
{
  // A name of this process alone, in the same folder so that the rename is
  // atomic: a reader sees the old entry, none, or the whole new one.
  static std::atomic<unsigned> serial{0};
  fs::path temporary = folder / ("." + key + "." + std::to_string(::getpid()) + "." + std::to_string(serial++) + ".tmp");
  std::error_code ec;
  if (write_new_file(temporary, entry_text(key, body_text(pieces))))
    fs::rename(temporary, folder / (key + ".pieces"), ec);
  else
    ec = std::make_error_code(std::errc::io_error);
  if (ec) fs::remove(temporary, ec);
}

// decomposed_solid where the work budget can stop it: in a child process
// when the run has a deadline or a cancel flag (CGAL's decomposition has no
// place to look at them), here otherwise. The child's pieces come back as
// an entry's body, exact, and are rebuilt as hulls the same way. A slow
// step says so (issue 58 item 3) under `note`'s text.
Solid decomposed_within_budget(const Checked_mesh& mesh, const std::string& file_name, const Mesh_limits& limits,
                               Mesh_decomposition method, const std::string& note)
{
  if (!Work_budget::limited()) {
    Slow_step_note slow(note);
    return decomposed_solid(mesh, file_name, limits, method);
  }
  Work_budget::check();
  // The note's thread starts at the first poll, after fork(): a thread
  // that is starting while fork() copies the process can leave the child's
  // allocator locked, and the child then never ends (seen under
  // AddressSanitizer, whose allocator has no fork handler).
  std::optional<Slow_step_note> slow;
  std::string body = text_of_child([&] { return body_text(decomposed_solid(mesh, file_name, limits, method)); },
                                   [&] {
                                     if (!slow) slow.emplace(note);
                                     Work_budget::check();
                                   },
                                   file_name);
  slow.reset();
  Rational six(0);
  Solid pieces = parse_body(body, limits.pieces, six);
  if (six != Rational(6) * mesh.volume)   // the child checked this; a pipe's text is checked again
    throw std::logic_error(file_name + ": the pieces sent back by the decomposition do not fill the solid");
  return pieces;
}

} // namespace

Mesh_cache Mesh_cache::from_environment()
{
  if (env("CLASH4D_MESH_CACHE") == "off") return Mesh_cache();
  // XDG's base directories are absolute; a relative one is ignored, as the
  // specification says.
  fs::path folder;
  if (!env("CLASH4D_CACHE_DIR").empty()) folder = env("CLASH4D_CACHE_DIR");
  else if (fs::path xdg = env("XDG_CACHE_HOME"); xdg.is_absolute()) folder = xdg / "clash4d" / "meshes";
  else if (fs::path home = env("HOME"); home.is_absolute()) folder = home / ".cache" / "clash4d" / "meshes";
  return folder.empty() ? Mesh_cache() : Mesh_cache(made_folder(folder));
}

std::string Mesh_cache::key(const Checked_mesh& mesh, const std::string& options_key)
{
  // Canonical: the checked mesh's merged vertices and outward triangles, in
  // its order, every number as its lowest-terms p/q.
  std::ostringstream text;
  text << "clash4d-mesh-cache " << CLASH4D_MESH_CACHE_VERSION << "\ncgal " << CGAL_VERSION_NR << "\noptions "
       << options_key << "\nvertices " << mesh.vertices.size() << "\n";
  for (const auto& v : mesh.vertices) text << to_string(v[0]) << " " << to_string(v[1]) << " " << to_string(v[2]) << "\n";
  text << "triangles " << mesh.triangles.size() << "\n";
  for (const auto& t : mesh.triangles) text << t[0] << " " << t[1] << " " << t[2] << "\n";
  return sha256_hex(text.str());
}

fs::path Mesh_cache::entry_path(const std::string& key) const { return folder_ / (key + ".pieces"); }

std::optional<Solid> Mesh_cache::load(const std::string& key, const Checked_mesh& mesh, std::size_t max_pieces) const
{
  if (!on()) return std::nullopt;
  try {
    // Three header lines, as entry_text writes them for this key and this
    // very body: a cut, changed or foreign entry differs.
    std::string text = file_text(entry_path(key));
    std::size_t body_line = text.find("\nbody ");
    std::size_t end = body_line == std::string::npos ? body_line : text.find('\n', body_line + 1);
    if (end == std::string::npos) return std::nullopt;
    std::string body = text.substr(end + 1);
    if (text != entry_text(key, body)) return std::nullopt;
    // The pieces fill the solid exactly once, as decomposed_solid checks.
    Rational six(0);
    Solid u = parse_body(body, max_pieces, six);
    if (u.children.empty() || six != Rational(6) * mesh.volume) return std::nullopt;
    return u;
  } catch (const std::exception&) {   // any text that is not what store writes
    return std::nullopt;
  }

}

void Mesh_cache::store(const std::string& key, const Solid& pieces) const
{
  if (!on()) return;
  try {
    write_entry(folder_, key, pieces);
  } catch (const std::exception&) {   // a cache that cannot be written is only slower
  }
}

Solid Mesh_cache::decomposed(const Checked_mesh& mesh, const std::string& file_name, const Mesh_limits& limits,
                             Mesh_decomposition method, Mesh_record& record,
                             const std::function<void()>& before_decomposing) const
{
  std::string k = on() ? key(mesh, decomposition_name(method)) : "";
  if (on())
    if (std::optional<Solid> hit = load(k, mesh, limits.pieces)) {
      record.cache = "hit";
      record.decomposition_seconds = 0;
      return *hit;
    }
  record.cache = on() ? "miss" : "off";
  before_decomposing();
  auto began = std::chrono::steady_clock::now();
  Solid pieces = decomposed_within_budget(
      mesh, file_name, limits, method,
      "decomposing " + file_name + " (" + std::to_string(mesh.triangles.size()) + " triangles)");
  record.decomposition_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  store(k, pieces);
  return pieces;
}

} // namespace clash4d

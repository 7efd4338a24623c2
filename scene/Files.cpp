#include "scene/Files.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace clash4d {
namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& why)
{
  throw std::runtime_error(path + ": " + why);
}

// Writes all of text to fd; false on an error (errno says which).
bool write_all(int fd, const std::string& text)
{
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

// Where the text goes: the path itself, or, for a symbolic link, the file it
// names (written through, as a shell's `>` would, never the link replaced).
fs::path resolved_target(const std::string& path)
{
  fs::path target(path);
  std::error_code ec;
  if (!fs::is_symlink(fs::symlink_status(target, ec))) return target;
  fs::path final_target = fs::canonical(target, ec);
  if (ec) fail(path, "is a symbolic link to a file that cannot be reached (" + ec.message() + "); nothing written");
  return final_target;
}

// A device, a pipe or a socket is written to as it is (`--certificate
// /dev/null`, a FIFO): it is never replaced by a regular file.
void write_through(const std::string& path, const std::string& text)
{
  int fd = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) fail(path, std::string("cannot write: ") + std::strerror(errno));
  bool ok = write_all(fd, text);
  int saved = errno;
  ::close(fd);
  if (!ok) fail(path, std::string("cannot write: ") + std::strerror(saved));
}

// A new hidden file beside target, created exclusively and never through a
// link (O_EXCL | O_NOFOLLOW): a name planted in a shared folder in advance
// only makes the next, random, name be tried.
int create_temporary(const fs::path& target, fs::path& temporary)
{
  static std::atomic<unsigned long> counter{0};
  static thread_local std::mt19937_64 random(std::random_device{}() ^ static_cast<unsigned long>(::getpid()));
  for (int attempt = 0; attempt < 100; ++attempt) {
    char suffix[17];
    std::snprintf(suffix, sizeof suffix, "%016llx", static_cast<unsigned long long>(random()));
    temporary = target.parent_path() / ("." + target.filename().string() + "." + std::to_string(::getpid()) + "." +
                                        std::to_string(counter++) + "." + suffix + ".tmp");
    int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  errno = EEXIST;
  return -1;
}

} // namespace

void write_file_atomically(const std::string& path, const std::string& text)
{
  fs::path target = resolved_target(path);
  std::error_code ec;
  fs::file_status status = fs::status(target, ec);
  if (fs::is_directory(status)) fail(path, "is a folder, not a file; nothing written");
  if (fs::exists(status) && !fs::is_regular_file(status)) return write_through(target.string(), text);
  fs::path temporary;
  int fd = create_temporary(target, temporary);
  if (fd < 0) fail(temporary.string(), std::string("cannot write: ") + std::strerror(errno));
  // A file replaced keeps its permissions (the temporary's are 0666 less the umask).
  if (fs::is_regular_file(status)) ::fchmod(fd, static_cast<mode_t>(status.permissions()));
  bool ok = write_all(fd, text);
  int saved = errno;
  ok = ::close(fd) == 0 && ok;
  std::error_code ignored;
  if (!ok) {
    fs::remove(temporary, ignored);
    fail(temporary.string(), std::string("cannot write (") + std::strerror(saved) + "; disk full?)");
  }
  fs::rename(temporary, target, ec);
  if (ec) {
    fs::remove(temporary, ignored);
    fail(path, "cannot rename " + temporary.string() + " to it: " + ec.message());
  }
}

nlohmann::ordered_json read_json_document(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot read");
  try {
    return nlohmann::ordered_json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + ": not valid JSON (" + e.what() + ")");
  }
}

} // namespace clash4d

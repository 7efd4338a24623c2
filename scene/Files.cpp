#include "scene/Files.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace clash4d {
namespace fs = std::filesystem;

void write_file_atomically(const std::string& path, const std::string& text)
{
  static std::atomic<unsigned long> counter{0};
  fs::path target(path);
  // Hidden and unique per process and call, so concurrent writers never share it.
  fs::path temporary = target.parent_path() / ("." + target.filename().string() + "." + std::to_string(::getpid()) +
                                               "." + std::to_string(counter++) + ".tmp");
  std::error_code ignored;
  {
    std::ofstream f(temporary, std::ios::binary | std::ios::trunc);
    if (!f) throw std::runtime_error(temporary.string() + ": cannot write: " + std::strerror(errno));
    f << text;
    f.close();
    if (!f) {
      fs::remove(temporary, ignored);
      throw std::runtime_error(temporary.string() + ": cannot write (disk full?)");
    }
  }
  std::error_code ec;
  fs::rename(temporary, target, ec);
  if (ec) {
    fs::remove(temporary, ignored);
    throw std::runtime_error(path + ": cannot rename " + temporary.string() + " to it: " + ec.message());
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

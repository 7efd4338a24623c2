#include "compare/Report_cache.h"
#include "compare/External_subject.h"
#include "scene/Files.h"
#include "scene/Number_json.h"
#include "scene/Scene_writer.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace clash4d {
namespace fs = std::filesystem;

Report_cache::Report_cache(const std::string& dir) : folder_((fs::path(dir) / "cases").string()) {}

std::string Report_cache::key(const std::string& file, const Scene& scene, const Compare_options& o)
{
  nlohmann::ordered_json tolerances = nlohmann::ordered_json::array(), externals = nlohmann::ordered_json::array();
  for (double t : o.tolerances) tolerances.push_back(shortest_decimal(t));
  for (const auto& pool : o.externals) externals.push_back({pool->spec().name, pool->spec().command});
  nlohmann::ordered_json options = {{"semantics", semantics_name(o.semantics)}, {"tolerances", tolerances},
                                    {"earliest", o.earliest}, {"time_bound", shortest_decimal(o.time_bound)},
                                    {"rounded", o.rounded}, {"doubles", o.doubles}, {"fcl", o.fcl},
                                    {"bullet", o.bullet}, {"externals", externals}};
  return nlohmann::ordered_json{{"file", file}, {"options", options}, {"scene", write_scene(scene)}}.dump();
}

std::string Report_cache::path_of(const std::string& key) const
{
  std::uint64_t h = 1469598103934665603ull;   // FNV-1a: a name only; the key itself is compared
  for (unsigned char c : key) h = (h ^ c) * 1099511628211ull;
  char name[32];
  std::snprintf(name, sizeof name, "%016llx.json", static_cast<unsigned long long>(h));
  return (fs::path(folder_) / name).string();
}

std::optional<Comparison> Report_cache::find(const std::string& key) const
{
  std::ifstream in(path_of(key));
  if (!in) return std::nullopt;
  try {
    nlohmann::ordered_json j = nlohmann::ordered_json::parse(in);
    if (j.value("key", std::string()) != key) return std::nullopt;
    return Comparison::from_json(j.at("comparison"));
  } catch (const std::exception&) {
    return std::nullopt;   // a damaged file is compared again, and overwritten
  }
}

void Report_cache::store(const std::string& key, const Comparison& comparison) const
{
  fs::create_directories(folder_);
  nlohmann::ordered_json j = {{"key", key}, {"comparison", comparison.to_json()}};
  write_file_atomically(path_of(key), j.dump() + "\n");
}

std::size_t Report_cache::size() const
{
  std::error_code ec;
  std::size_t n = 0;
  for (fs::directory_iterator it(folder_, ec), end; !ec && it != end; it.increment(ec)) n += it->path().extension() == ".json";
  return n;
}

} // namespace clash4d

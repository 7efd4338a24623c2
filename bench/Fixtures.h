// The scene files of one fixture family (fixtures/paper, fixtures/contact),
// sorted, without the family's expected.json: what the benchmarks time;
// and a scene file read as the benchmarks read one.
#ifndef CLASH4D_BENCH_FIXTURES_H
#define CLASH4D_BENCH_FIXTURES_H

#include "scene/Input_error.h"
#include "scene/Scene_reader.h"
#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace clash4d {

inline std::vector<std::filesystem::path> fixture_files(const std::string& family)
{
  std::vector<std::filesystem::path> files;
  for (const auto& f : std::filesystem::directory_iterator(std::string(CLASH4D_FIXTURES) + "/" + family))
    if (f.path().extension() == ".json" && f.path().filename() != "expected.json") files.push_back(f.path());
  std::sort(files.begin(), files.end());
  return files;
}

// A scene file, read for a benchmark: a bad one stops the run with the
// message clash4d check gives, "file: place: message".
inline Scene read_bench_scene(const std::string& path)
{
  try {
    return read_scene_file(path);
  } catch (const Input_error& e) {
    throw std::runtime_error(e.format(path));
  }
}

} // namespace clash4d

#endif

// The scene files of one fixture family (fixtures/paper, fixtures/contact),
// sorted, without the family's expected.json: what the benchmarks time.
#ifndef CLASH4D_BENCH_FIXTURES_H
#define CLASH4D_BENCH_FIXTURES_H

#include <algorithm>
#include <filesystem>
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

} // namespace clash4d

#endif

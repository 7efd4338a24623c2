#include "scene/Grid_scene.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <random>
#include <stdexcept>

namespace clash4d {

Grid_scene make_grid_scene(int n, int colliding, std::uint64_t seed)
{
  if (n < 2) throw std::invalid_argument("a grid scene needs at least 2 blocks");
  int m = 1;
  while (m * m * m < n) ++m;
  std::mt19937_64 rng(seed);
  // Candidate pairs: (i, i + 1) on the same grid row, i at an even column.
  std::vector<std::pair<int, int>> candidates;
  for (int i = 0; i + 1 < n; ++i)
    if (i % m % 2 == 0 && (i + 1) % m != 0) candidates.emplace_back(i, i + 1);
  if (colliding < 0 || colliding > static_cast<int>(candidates.size()))
    throw std::invalid_argument("at most " + std::to_string(candidates.size()) + " colliding pairs fit in " +
                                std::to_string(n) + " blocks");
  std::shuffle(candidates.begin(), candidates.end(), rng);
  Grid_scene out;
  out.colliding.assign(candidates.begin(), candidates.begin() + colliding);
  std::sort(out.colliding.begin(), out.colliding.end());
  std::vector<std::string> motion(n);
  std::uniform_int_distribution<int> wobble(-2, 2);
  for (int i = 0; i < n; ++i) {
    // Out and back within the cell: displacement at most 1 per axis.
    std::string v[3], w[3];
    for (int a = 0; a < 3; ++a) {
      int p = wobble(rng);
      v[a] = std::to_string(p) + "/10";
      w[a] = std::to_string(-p) + "/10";
    }
    motion[i] = "vel " + v[0] + " " + v[1] + " " + v[2] + " until 5 vel " + w[0] + " " + w[1] + " " + w[2] + " until 10 rest";
  }
  for (const auto& p : out.colliding) {
    motion[p.first] = "vel 3/10 0 0";
    motion[p.second] = "vel -3/10 0 0";
  }
  nlohmann::ordered_json objects = nlohmann::ordered_json::array();
  for (int i = 0; i < n; ++i) {
    int x = 4 * (i % m), y = 4 * (i / m % m), z = 4 * (i / (m * m));
    objects.push_back({{"name", "b" + std::to_string(i)},
                       {"shape", {{"block", {{"min", {x, y, z}}, {"max", {x + 1, y + 1, z + 1}}}}}},
                       {"motion", motion[i]}});
  }
  nlohmann::ordered_json scene = {{"format", "clash4d-scene/1"},
                                  {"name", "grid of " + std::to_string(n) + " blocks, " + std::to_string(colliding) +
                                               " colliding pairs, seed " + std::to_string(seed)},
                                  {"time", {0, 10}},
                                  {"objects", objects}};
  // Provenance under `meta` (spec): the file stays a scene check accepts.
  nlohmann::ordered_json pairs = nlohmann::ordered_json::array();
  for (const auto& p : out.colliding) pairs.push_back({"b" + std::to_string(p.first), "b" + std::to_string(p.second)});
  scene["meta"] = {{"tool", "clash4d generate"}, {"n", n}, {"colliding", colliding}, {"seed", seed},
                   {"colliding_pairs", pairs}, {"earliest_t", 5}};
  out.json = scene.dump(1) + "\n";
  return out;
}

} // namespace clash4d

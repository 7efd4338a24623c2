#include "scene/Grid_scene.h"
#include "scene/Random_draw.h"
#include "scene/Scene_builder.h"

#include <algorithm>
#include <stdexcept>

namespace clash4d {

Grid_scene make_grid_scene(int n, int colliding, std::uint64_t seed)
{
  if (n < 2) throw std::invalid_argument("a grid scene needs at least 2 blocks");
  int m = 1;
  while (m * m * m < n) ++m;
  Random_draw draw(seed);
  // Candidate pairs: (i, i + 1) on the same grid row, i at an even column.
  std::vector<std::pair<int, int>> candidates;
  for (int i = 0; i + 1 < n; ++i)
    if (i % m % 2 == 0 && (i + 1) % m != 0) candidates.emplace_back(i, i + 1);
  if (colliding < 0 || colliding > static_cast<int>(candidates.size()))
    throw std::invalid_argument("at most " + std::to_string(candidates.size()) + " colliding pairs fit in " +
                                std::to_string(n) + " blocks");
  draw.shuffle(candidates);
  Grid_scene out;
  out.colliding.assign(candidates.begin(), candidates.begin() + colliding);
  std::sort(out.colliding.begin(), out.colliding.end());
  std::vector<Motion> motion(n);
  for (int i = 0; i < n; ++i) {
    // Out and back within the cell: displacement at most 1 per axis.
    Vec3 v;
    for (auto& c : v) c = Rational(draw.range(-2, 2)) / 10;
    motion[i] = piecewise({v, times(-1, v), vec(0, 0, 0)}, {5, 10});
  }
  for (const auto& p : out.colliding) {
    motion[p.first] = steady(vec(Rational(3, 10), 0, 0));
    motion[p.second] = steady(vec(Rational(-3, 10), 0, 0));
  }
  Scene_builder b("grid of " + std::to_string(n) + " blocks, " + std::to_string(colliding) + " colliding pairs, seed " +
                      std::to_string(seed),
                  0, 10);
  for (int i = 0; i < n; ++i) {
    Vec3 lo = vec(4 * (i % m), 4 * (i / m % m), 4 * (i / (m * m)));
    b.object("b" + std::to_string(i), block(lo, plus(lo, vec(1, 1, 1))), motion[i]);
  }
  // Provenance under `meta` (spec): the file stays a scene check accepts.
  nlohmann::ordered_json pairs = nlohmann::ordered_json::array();
  for (const auto& p : out.colliding) pairs.push_back({"b" + std::to_string(p.first), "b" + std::to_string(p.second)});
  out.json = b.text({{"tool", "clash4d generate"}, {"n", n}, {"colliding", colliding}, {"seed", seed},
                     {"colliding_pairs", pairs}, {"earliest_t", 5}});
  return out;
}

} // namespace clash4d

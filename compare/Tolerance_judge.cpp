#include "compare/Tolerance_judge.h"
#include "check/Check_answer.h"
#include "exact/Exact_instantiation.h"
#include "rotation/Rotating_check.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"
#include "scene/Scene_writer.h"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace clash4d {

std::vector<std::array<Rational, 3>> tolerance_moves(const Rational& eps)
{
  // 0.7 sqrt(2) < 0.99 and 0.57 sqrt(3) < 0.99: every move is shorter than eps.
  const Rational edge = eps * Rational(7) / Rational(10), corner = eps * Rational(57) / Rational(100);
  std::vector<std::array<Rational, 3>> moves;
  for (int i = 0; i < 3; ++i)
    for (int s : {1, -1}) {
      std::array<Rational, 3> v{Rational(0), Rational(0), Rational(0)};
      v[i] = s * eps;
      moves.push_back(v);
    }
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      for (int s : {1, -1})
        for (int u : {1, -1}) {
          std::array<Rational, 3> v{Rational(0), Rational(0), Rational(0)};
          v[i] = s * edge;
          v[j] = u * edge;
          moves.push_back(v);
        }
  for (int s : {1, -1})
    for (int u : {1, -1})
      for (int w : {1, -1}) moves.push_back({s * corner, u * corner, w * corner});
  return moves;
}

namespace {

// The scene (as written) with object i's shape moved by v: {"translate":
// v, "solid": shape} (scene format), read back so it is validated.
Scene moved(const nlohmann::ordered_json& written, std::size_t i, const std::array<Rational, 3>& v)
{
  nlohmann::ordered_json j = written;
  nlohmann::ordered_json& shape = j["objects"][i]["shape"];
  shape = nlohmann::ordered_json{{"translate", {to_string(v[0]), to_string(v[1]), to_string(v[2])}}, {"solid", shape}};
  return read_scene(read_json_text(j.dump()));
}

bool exact_collides(const Scene& scene, Semantics semantics)
{
  Check_options o;
  o.semantics = semantics;
  return scene_rotates(scene) ? check_rotating(scene, o, "exact").collide : check_exact(scene, o).collide;
}

} // namespace

bool verdict_within_tolerance(const Scene& scene, Semantics semantics, bool collide, const Rational& eps,
                              const std::vector<std::string>& movable)
{
  if (eps <= 0) return false;
  const nlohmann::ordered_json written = nlohmann::ordered_json::parse(write_scene(scene));
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (!movable.empty() && std::find(movable.begin(), movable.end(), scene.objects[i].name) == movable.end()) continue;
    for (const auto& v : tolerance_moves(eps)) {
      try {
        if (exact_collides(moved(written, i, v), semantics) == collide) return true;
      } catch (const std::exception&) {
        // A moved scene the reader refuses: no evidence either way.
      }
    }
  }
  return false;
}

} // namespace clash4d

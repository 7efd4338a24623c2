#include "scene/Scene_writer.h"
#include "scene/Pose_motion.h"

#include <nlohmann/json.hpp>

namespace clash4d {
namespace {

using json = nlohmann::ordered_json;

json numbers(const std::vector<Rational>& xs, std::size_t from, std::size_t count)
{
  json a = json::array();
  for (std::size_t i = from; i < from + count; ++i) a.push_back(to_string(xs[i]));
  return a;
}

json solid_json(const Solid& s)
{
  const char* key = solid_key(s.kind);
  const auto& n = s.numbers;
  switch (s.kind) {
    case Solid::Kind::Halfspace: return {{key, numbers(n, 0, 4)}};
    case Solid::Kind::Block: return {{key, {{"min", numbers(n, 0, 3)}, {"max", numbers(n, 3, 3)}}}};
    case Solid::Kind::Convex: {
      json a = json::array();
      for (std::size_t i = 0; i < n.size(); i += 4) a.push_back(numbers(n, i, 4));
      return {{key, a}};
    }
    case Solid::Kind::Prism: {
      json base = json::array();
      for (std::size_t i = 0; i + 2 < n.size(); i += 2) base.push_back(numbers(n, i, 2));
      return {{key, {{"base", base}, {"z", numbers(n, n.size() - 2, 2)}}}};
    }
    case Solid::Kind::Hull: {
      json a = json::array();
      for (std::size_t i = 0; i < n.size(); i += 3) a.push_back(numbers(n, i, 3));
      return {{key, a}};
    }
    case Solid::Kind::Translate:
    case Solid::Kind::Rotate:
      return {{key, numbers(n, 0, n.size())}, {"solid", solid_json(s.children[0])}};
    default: {
      json a = json::array();
      for (const Solid& c : s.children) a.push_back(solid_json(c));
      return {{key, a}};
    }
  }
}

} // namespace

std::string motion_text(const Motion& m)
{
  std::string out;
  for (std::size_t i = 0; i < m.velocities.size(); ++i) {
    if (i > 0) out += " until " + to_string(m.times[i - 1]) + " ";
    const auto& v = m.velocities[i];
    if (CGAL::is_zero(v[0]) && CGAL::is_zero(v[1]) && CGAL::is_zero(v[2])) out += "rest";
    else out += "vel " + to_string(v[0]) + " " + to_string(v[1]) + " " + to_string(v[2]);
  }
  return out;
}

// A pose motion as written (spec: Motion with rotation (poses)), every key
// of every pose; else the ROBMOD text.
json motion_json(const Motion& m)
{
  if (m.poses.empty()) return motion_text(m);
  json poses = json::array();
  for (const Pose& p : m.poses) {
    json translate = json::array(), rotate = json::array();
    for (const Rational& x : p.translate) translate.push_back(to_string(x));
    for (const Rational& x : p.rotate) rotate.push_back(to_string(x));
    poses.push_back({{"t", to_string(p.t)}, {"translate", translate}, {"rotate", rotate}});
  }
  return {{"poses", poses}};
}

json scene_json(const Scene& scene, const json& meta)
{
  json j = {{"format", "clash4d-scene/1"}};
  if (!scene.name.empty()) j["name"] = scene.name;
  j["time"] = {to_string(scene.t_lo), to_string(scene.t_hi)};
  j["objects"] = json::array();
  for (const auto& o : scene.objects)
    j["objects"].push_back({{"name", o.name}, {"shape", solid_json(written_shape(o))}, {"motion", motion_json(o.motion)}});
  if (!scene.ignore.empty()) {
    j["ignore"] = json::array();
    for (const auto& p : scene.ignore) j["ignore"].push_back({scene.objects[p.first].name, scene.objects[p.second].name});
  }
  if (!meta.is_null()) j["meta"] = meta;
  return j;
}

std::string write_scene(const Scene& scene, const json& meta)
{
  return scene_json(scene, meta).dump(2) + "\n";
}

} // namespace clash4d

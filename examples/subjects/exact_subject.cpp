// A minimal external subject in C++ (docs/subject-protocol.md): the toolkit's
// own exact check, answering clash4d's requests on standard input. Copy it
// and replace `answer` with a call into your engine.
//
//   clash4d compare scene.json --subject mine=build/clash4d_exact_subject
//
// Numbers arrive as JSON strings (exact rationals such as "1/3") or numbers;
// scene/Json_reader keeps their text, so nothing goes through a double here.
#include "exact/Exact_instantiation.h"
#include "scene/Input_error.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"

#include <nlohmann/json.hpp>
#include <iostream>
#include <string>

using json = nlohmann::ordered_json;
using namespace clash4d;

namespace {

// The answer to one request: verdict, witness point and (when asked) t*.
json answer(const Scene& scene, bool earliest)
{
  Check_options o;
  o.earliest = earliest;
  Check_answer a = check_exact(scene, o);
  json out = {{"collide", a.collide}};
  if (const Pair_answer* p = a.reported()) {
    out["witness"] = p->witness;
    if (p->earliest) out["t"] = p->t_star;
  }
  return out;
}

json reply(const std::string& line)
{
  Json_value request = read_json_text(line);   // throws Input_error on bad JSON
  const Json_value* id = request.find("id");
  const Json_value* scene = request.find("scene");
  const Json_value* earliest = request.find("earliest");
  if (!id || id->kind != Json_value::Kind::Number) throw Input_error("", "a request needs an id");
  json out = {{"id", std::stoll(id->text)}};
  // A CCD query request ("ccd"): this subject answers scenes only.
  if (request.find("ccd")) {
    out["unsupported"] = "clash4d-exact answers scenes, not CCD queries";
    return out;
  }
  if (!scene) throw Input_error("", "a request needs a scene or a ccd query");
  try {
    json a = answer(read_scene(*scene), earliest && earliest->boolean);
    out.update(a);
  } catch (const Input_error& e) {
    out["unsupported"] = e.format("scene");
  }
  return out;
}

} // namespace

int main()
{
  std::ios::sync_with_stdio(false);
  std::cout << json{{"subject", "clash4d-exact"}, {"semantics", "regularised"}}.dump() << std::endl;
  std::string line;
  while (std::getline(std::cin, line)) {
    try {
      std::cout << reply(line).dump() << std::endl;   // one line per request, flushed
    } catch (const std::exception& e) {
      std::cerr << "exact_subject: " << e.what() << "\n";
      return 2;
    }
  }
  return 0;   // clash4d closed our input: the run is over
}

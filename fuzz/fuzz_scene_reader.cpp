// libFuzzer target: the scene reader (scene/Json_reader, scene/Scene_reader)
// on arbitrary bytes. Bad input must end in Input_error (exit 2 or 3 with a
// place); anything else escaping, a crash, a leak or a hang is a finding.
// A scene that reads must also survive the writer: written and read again it
// gives the same text (the writer's round-trip promise, scene/Scene_writer.h).
#include "fuzz/Read_or_refuse.h"
#include "scene/Input_error.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"
#include "scene/Scene_writer.h"
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>

// A fuzz run never writes the user's decomposition cache (scene/Mesh_cache.h).
extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  setenv("CLASH4D_MESH_CACHE", "off", 1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace clash4d;
  Scene scene;
  if (!read_or_refuse([&] { scene = read_scene(read_json_text(std::string(reinterpret_cast<const char*>(data), size))); }))
    return 0;
  std::string once = write_scene(scene);
  std::string twice;
  try {
    twice = write_scene(read_scene(read_json_text(once)));
  } catch (const Input_error& e) {
    std::cerr << "a written scene does not read back: " << e.format("written") << "\n";
    std::abort();
  }
  if (once != twice) {
    std::cerr << "the writer does not round-trip:\n" << once << "\n---\n" << twice << "\n";
    std::abort();
  }
  return 0;
}

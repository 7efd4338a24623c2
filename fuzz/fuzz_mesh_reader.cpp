// libFuzzer target: the mesh readers (scene/Mesh_reader: OFF, OBJ, STL ASCII
// and binary, PLY), their checks (scene/Mesh_check) and the solid made of a
// mesh (scene/Mesh_solid: a hull, or the union of a Nef decomposition).
// The first byte picks the format and the repair options, the rest is the
// file. Bad input must end
// in Input_error with exit 2 or 3; anything else escaping (exit 4 included:
// CGAL failing inside), a crash, a leak or a hang is a finding.
#include "fuzz/Read_or_refuse.h"
#include "scene/Mesh_reader.h"
#include "scene/Mesh_solid.h"
#include <cstdint>
#include <cstdlib>
#include <string_view>

// A fuzz run never writes the user's decomposition cache (scene/Mesh_cache.h).
extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  setenv("CLASH4D_MESH_CACHE", "off", 1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace clash4d;
  if (size == 0) return 0;
  static const Mesh_format formats[] = {Mesh_format::Off, Mesh_format::Obj, Mesh_format::Stl, Mesh_format::Ply};
  Mesh_format format = formats[data[0] % 4];
  std::string_view bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  // Small limits keep one input's decomposition short; the limits' own code
  // is what is fuzzed, not their size.
  Mesh_limits limits;
  limits.facets = limits.vertices = 400;
  limits.pieces = 100;
  // The first byte's other bits pick the repairs and the rule
  // (scene/Mesh_repair.h): 0 is the strict reading.
  Mesh_options options;
  options.triangulate = data[0] & 4;
  options.drop_zero_area = data[0] & 8;
  options.orient = data[0] & 64;
  static const Mesh_options::Solid_rule rules[] = {Mesh_options::Solid_rule::Odd_shells,
                                                   Mesh_options::Solid_rule::Union_of_shells,
                                                   Mesh_options::Solid_rule::Hull, Mesh_options::Solid_rule::Odd_shells};
  options.rule = rules[(data[0] >> 4) % 4];
  read_or_refuse([&] {
    Mesh_record record;
    repaired_solid(read_mesh(bytes, format, "fuzz", limits), "fuzz", options, record, limits);
  });
  return 0;
}

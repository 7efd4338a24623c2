// How a mesh file becomes a solid (docs/meshes.md, "Repairs, scale and
// units"): chosen by the user in the scene, next to "mesh". Each option
// left unset keeps the strict reading: a mesh the checks refuse is refused.
#ifndef CLASH4D_SCENE_MESH_OPTIONS_H
#define CLASH4D_SCENE_MESH_OPTIONS_H

#include "numbers/Rational.h"
#include "scene/Mesh_check.h"
#include "scene/Mesh_reader.h"
#include <cstddef>
#include <string>

namespace clash4d {

struct Mesh_options {
  enum class Solid_rule {
    Odd_shells,       // the points inside an odd number of shells; shells must not cross
    Union_of_shells,  // the union of its shells, each a solid by itself; shells may cross
    Hull              // the convex hull of the vertices the facets use
  };
  Rational scale = Rational(1);   // exact, > 0: "scale" times the unit's factor
  bool triangulate = false;       // a facet not exactly planar or not strictly convex is cut into triangles
  bool drop_zero_area = false;    // zero-area triangles dropped, their middle vertex spliced into the neighbour
  bool orient = false;            // each shell's facets turned to agree, and the shell outward
  bool split_pinched = false;     // a pinched vertex split into one vertex per fan of facets
  Solid_rule rule = Solid_rule::Odd_shells;
  Mesh_decomposition decomposition = Mesh_decomposition::bsp;   // "decomposition": "bsp" or "nef"
  // "max_pieces": the most convex pieces the solid may have (exit 3 past
  // it). It bounds the work of a run, not the solid: a mesh read within
  // it has the same pieces under any larger bound.
  std::size_t max_pieces = CLASH4D_MAX_MESH_PIECES;

  // Text that tells options apart: part of the key of a mesh read once per
  // scene, and of the decomposition cache's key.
  std::string key() const
  {
    return to_string(scale) + (triangulate ? " triangulate" : "") + (drop_zero_area ? " drop-zero-area" : "") + (orient ? " orient" : "") +
           (split_pinched ? " split-pinched" : "") +
           " rule " + std::to_string(static_cast<int>(rule)) + " max_pieces " + std::to_string(max_pieces) +
           " decomposition " + decomposition_name(decomposition);
  }
};

struct Json_value;

// The options written beside "mesh" in the solid object at path; throws
// Input_error naming the member for an unknown key, unit, repair or word,
// a scale that is not positive, or a max_pieces that is not a whole number
// from 1 to CLASH4D_MAX_MESH_PIECES_ALLOWED.
Mesh_options read_mesh_options(const Json_value& solid, const std::string& path);

} // namespace clash4d

#endif

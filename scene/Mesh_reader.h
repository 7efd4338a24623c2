// Reading mesh files (OFF, OBJ, STL ASCII and binary, PLY ASCII and binary)
// into an indexed polygon mesh of exact vertices (docs/meshes.md). Text
// coordinates are read exactly ("0.1" is 1/10, scene/Number_text.h); binary
// float32/float64 values become the dyadic rationals they encode. No double
// ever holds a coordinate. Only the file's form is checked here; whether the
// mesh bounds a solid is scene/Mesh_check.h.
#ifndef CLASH4D_SCENE_MESH_READER_H
#define CLASH4D_SCENE_MESH_READER_H

#include "numbers/Rational.h"
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace clash4d {

// Limits on what a mesh file may ask for (exit 3 when exceeded).
constexpr std::size_t CLASH4D_MAX_MESH_FILE_BYTES = 64u << 20;
constexpr std::size_t CLASH4D_MAX_MESH_FACETS = 100000;
constexpr std::size_t CLASH4D_MAX_MESH_VERTICES = 100000;
constexpr std::size_t CLASH4D_MAX_FACET_VERTICES = 100;
constexpr std::size_t CLASH4D_MAX_MESH_PIECES = 1000;           // the default; "max_pieces" raises it
constexpr std::size_t CLASH4D_MAX_MESH_PIECES_ALLOWED = 100000;  // the most "max_pieces" may ask for

// The limits above, injectable so tests can reach them with small files.
struct Mesh_limits {
  std::size_t file_bytes = CLASH4D_MAX_MESH_FILE_BYTES;
  std::size_t facets = CLASH4D_MAX_MESH_FACETS;
  std::size_t vertices = CLASH4D_MAX_MESH_VERTICES;
  std::size_t facet_vertices = CLASH4D_MAX_FACET_VERTICES;
  std::size_t pieces = CLASH4D_MAX_MESH_PIECES;   // convex pieces (scene/Mesh_solid.h)
};

enum class Mesh_format { Off, Obj, Stl, Ply };

// A mesh as the file writes it: vertices in file order (0-based), facets as
// lists of vertex indices in file order. STL facets index their own three
// vertices (3 f, 3 f + 1, 3 f + 2); equal points are merged by the check.
struct Mesh {
  std::vector<std::array<Rational, 3>> vertices;
  std::vector<std::vector<int>> facets;
};

// The format of a file name's extension (.off .obj .stl .ply, any case);
// throws Input_error (exit 2) for any other.
Mesh_format mesh_format_of(const std::string& file_name);

// Parses bytes (a whole file). For STL the content decides between binary
// (size 84 + 50 n, n from the header) and ASCII ("solid ..."). Throws
// Input_error with place "FILE_NAME: line L" (text), "FILE_NAME: facet F"
// (binary) or "FILE_NAME" and the reason; exit 3 for a limit.
Mesh read_mesh(std::string_view bytes, Mesh_format format, const std::string& file_name,
               const Mesh_limits& limits = Mesh_limits());

// Reads the file at path (size-limited first), format by extension;
// file_name is the name errors show.
Mesh read_mesh_file(const std::string& path, const std::string& file_name,
                    const Mesh_limits& limits = Mesh_limits());

// The exact value of an IEEE binary32/binary64 given by its bits; throws
// std::domain_error for NaN and infinities.
Rational exact_float32(std::uint32_t bits);
Rational exact_float64(std::uint64_t bits);

} // namespace clash4d

#endif

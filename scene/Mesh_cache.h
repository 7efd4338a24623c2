// The decomposition cache (docs/meshes.md, "The decomposition cache"): the
// convex pieces of a non-convex mesh, kept on disk so a scene read again
// does not decompose its mesh files again (seconds to minutes each). An
// entry is found by a SHA-256 of the checked mesh, the cache's version and
// the mesh options, and is verified exactly before it is used: a bad entry
// is decomposed again and overwritten, never trusted, never an error.
#ifndef CLASH4D_SCENE_MESH_CACHE_H
#define CLASH4D_SCENE_MESH_CACHE_H

#include "scene/Mesh_check.h"
#include "scene/Mesh_record.h"
#include "scene/Scene.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace clash4d {

// Changed whenever the entry's text or the way pieces are made changes, so
// old entries are simply not found.
constexpr int CLASH4D_MESH_CACHE_VERSION = 1;

class Mesh_cache {
public:
  Mesh_cache() = default;   // off: nothing read, nothing written
  explicit Mesh_cache(std::filesystem::path folder) : folder_(std::move(folder)) {}

  // $CLASH4D_CACHE_DIR, else $XDG_CACHE_HOME/clash4d/meshes, else
  // $HOME/.cache/clash4d/meshes, made if missing. Off when
  // CLASH4D_MESH_CACHE=off or when no folder can be made.
  static Mesh_cache from_environment();

  bool on() const { return !folder_.empty(); }
  const std::filesystem::path& folder() const { return folder_; }

  // The entry's name: SHA-256 (hex) of the mesh's canonical text, the
  // cache's version, CGAL's version and options_key (Mesh_options::key()).
  static std::string key(const Checked_mesh& mesh, const std::string& options_key);
  std::filesystem::path entry_path(const std::string& key) const;

  // The pieces stored under key (a Union of Hulls), when the entry is
  // whole, is for this key, rebuilds as valid hulls, holds at most
  // max_pieces pieces and fills exactly mesh.volume; otherwise none.
  std::optional<Solid> load(const std::string& key, const Checked_mesh& mesh, std::size_t max_pieces) const;

  // Writes pieces (a Union of Hulls) under key, atomically: a temporary
  // file in the folder renamed over the entry. Failures are ignored.
  void store(const std::string& key, const Solid& pieces) const;

  // decomposed_solid (scene/Mesh_solid.h) through the cache: record gets
  // cache "hit", "miss" or "off" and the decomposition's seconds. Unless
  // the pieces come from the cache, before_decomposing runs first (the
  // checks an entry stands for: mesh_solid's crossing test).
  Solid decomposed(const Checked_mesh& mesh, const std::string& file_name, const Mesh_limits& limits,
                   Mesh_decomposition method, Mesh_record& record,
                   const std::function<void()>& before_decomposing = [] {}) const;

private:
  std::filesystem::path folder_;
};

} // namespace clash4d

#endif

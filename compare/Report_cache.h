// The comparisons a `report` has finished, kept in DIR/cases/ so that an
// interrupted report resumes where it stopped (issue 60: a report of 23
// minutes that was interrupted wrote nothing), as a fuzz campaign does.
// Each comparison is stored with its key and reused only when the key
// matches exactly: the file name, the scene as read (meshes included, so an
// edited mesh is compared again) and the comparison's options. An external
// subject is keyed by its name and command; a changed engine behind the
// same command is not seen (delete DIR/cases, or --fresh).
#ifndef CLASH4D_COMPARE_REPORT_CACHE_H
#define CLASH4D_COMPARE_REPORT_CACHE_H

#include "compare/Comparer.h"
#include "compare/Comparison.h"
#include "scene/Scene.h"
#include <optional>
#include <string>

namespace clash4d {

class Report_cache {
public:
  // The cache of report folder `dir`: dir/cases, created on the first store.
  explicit Report_cache(const std::string& dir);

  static std::string key(const std::string& file, const Scene& scene, const Compare_options& options);

  // The comparison stored under `key`, or none (absent, another key, or a
  // file that does not read back: compared again).
  std::optional<Comparison> find(const std::string& key) const;
  // Written to a temporary name and renamed.
  void store(const std::string& key, const Comparison& comparison) const;
  // How many comparisons are kept.
  std::size_t size() const;

private:
  std::string folder_;
  std::string path_of(const std::string& key) const;
};

} // namespace clash4d

#endif

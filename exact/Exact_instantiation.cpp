#include "exact/Exact_instantiation.h"
#include "model/Extrusion_report.h"
#include "exact/Filtered_runner.h"
#include "exact/Interval_kernel.h"
#include "exact/Rational_kernel.h"
#include <CGAL/FPU.h>

namespace clash4d {

// The filtered exact kernel: intervals first, rationals where they fail.
using Filtered_exact = Filtered_runner<Interval_kernel, Rational_kernel>;

Check_answer check_exact(const Scene& scene, const Check_options& options)
{
  return Filtered_exact(scene, options.sbounds).check(options);
}

// Extrusion is all constructions (nothing to filter): rationals, labelled exact.
nlohmann::ordered_json extrude_exact(const Scene& scene)
{
  nlohmann::ordered_json j = extrude_rational(scene);
  j["number"] = "exact";
  return j;
}

Skeleton_answer skeleton_exact(const Scene& scene)
{
  return Filtered_exact(scene, true).skeleton();
}

} // namespace clash4d

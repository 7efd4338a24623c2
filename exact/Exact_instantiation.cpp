#include "exact/Exact_instantiation.h"
#include "core/Check_runner.h"
#include "core/Extrusion_report.h"
#include "exact/Exact_kernel.h"

namespace clash4d {

Check_answer check_exact(const Scene& scene, const Check_options& options)
{
  return run_check(Exact_kernel(), scene, options);
}

nlohmann::ordered_json extrude_exact(const Scene& scene)
{
  return Extrusion_report<Exact_kernel>(Exact_kernel()).make(scene);
}

Skeleton_answer skeleton_exact(const Scene& scene)
{
  return run_skeleton(Exact_kernel(), scene);
}

} // namespace clash4d

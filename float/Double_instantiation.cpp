#include "float/Double_instantiation.h"
#include "check/Check_runner.h"
#include "model/Extrusion_report.h"
#include "float/Double_kernel.h"

namespace clash4d {

Check_answer check_double(const Scene& scene, double tolerance, const Check_options& options)
{
  return run_check(Double_kernel(tolerance), scene, options);
}

nlohmann::ordered_json extrude_double(const Scene& scene)
{
  return Extrusion_report<Double_kernel>(Double_kernel()).make(scene);
}

Skeleton_answer skeleton_double(const Scene& scene)
{
  return run_skeleton(Double_kernel(), scene);
}

} // namespace clash4d

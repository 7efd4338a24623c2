#include "exact/Exact_instantiation.h"
#include "check/Check_runner.h"
#include "model/Extrusion_report.h"
#include "exact/Rational_kernel.h"

namespace clash4d {

Check_answer check_rational(const Scene& scene, const Check_options& options)
{
  return run_check(Rational_kernel(), scene, options);
}

nlohmann::ordered_json extrude_rational(const Scene& scene)
{
  return Extrusion_report<Rational_kernel>(Rational_kernel()).make(scene);
}

Skeleton_answer skeleton_rational(const Scene& scene)
{
  return run_skeleton(Rational_kernel(), scene);
}

} // namespace clash4d

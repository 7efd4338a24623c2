#include "exact/Exact_checker.h"
#include "exact/Filtered_runner.h"
#include "exact/Interval_kernel.h"
#include "exact/Rational_kernel.h"

namespace clash4d {

using Filtered_exact = Filtered_runner<Interval_kernel, Rational_kernel>;

// One runner per S-bounds setting, made on first use and kept.
struct Exact_checker::Impl {
  const Scene& scene;
  std::unique_ptr<Filtered_exact> runner[2];
};

Exact_checker::Exact_checker(const Scene& scene) : impl_(new Impl{scene, {}}) {}
Exact_checker::~Exact_checker() = default;

Check_answer Exact_checker::check(const Check_options& options)
{
  std::unique_ptr<Filtered_exact>& r = impl_->runner[options.sbounds ? 1 : 0];
  if (!r) r = std::make_unique<Filtered_exact>(impl_->scene, options.sbounds, true);
  return r->check(options);
}

} // namespace clash4d

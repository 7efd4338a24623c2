#include "exact/Exact_checker.h"
#include "exact/Exact_instantiation.h"
#include "exact/Filtered_exact_runner.h"
#include "scene/Scene_reader.h"
#include <stdexcept>
#include <string>

namespace clash4d {

namespace {

// A motion as the scene reader accepts one (parse_motion): a velocity per
// segment, times strictly increasing, within the segment limit.
void check_motion(const Motion& m, const std::string& object)
{
  auto refuse = [&](const std::string& why) {
    throw std::invalid_argument("Exact_checker: the motion of object \"" + object + "\": " + why);
  };
  if (m.velocities.size() != m.times.size() + 1)
    refuse(std::to_string(m.times.size()) + " times need " + std::to_string(m.times.size() + 1) + " velocities, not " +
           std::to_string(m.velocities.size()));
  for (std::size_t k = 1; k < m.times.size(); ++k)
    if (!(m.times[k - 1] < m.times[k])) refuse("times must be strictly increasing (time " + std::to_string(k + 1) + ")");
  if (m.times.size() > CLASH4D_MAX_MOTION_SEGMENTS)
    refuse("more than the limit of " + std::to_string(CLASH4D_MAX_MOTION_SEGMENTS) + " motion segments");
}

bool same_motion(const Motion& a, const Motion& b) { return a.times == b.times && a.velocities == b.velocities; }

} // namespace

// One runner per S-bounds setting, made on first use and kept. The runners
// check `moved` once a check has named motions (a copy of the scene, made
// then), otherwise the scene itself.
struct Exact_checker::Impl {
  const Scene& scene;
  std::unique_ptr<Scene> moved;
  std::unique_ptr<Filtered_exact_runner> runner[2];
  std::vector<int> changed;   // move_to's, kept: a query allocates none
  std::shared_ptr<void> piece_model;   // check_exact_by_pieces', made again when motions change

  Check_answer check(const Check_options& options)
  {
    // The same answer as check_exact where it takes the piece pairs.
    if (std::optional<Check_answer> a = check_exact_by_pieces(moved ? *moved : scene, options, &piece_model))
      return std::move(*a);
    std::unique_ptr<Filtered_exact_runner>& r = runner[options.sbounds ? 1 : 0];
    if (!r) r = std::make_unique<Filtered_exact_runner>(moved ? *moved : scene, options.sbounds, true);
    return r->check(options);
  }

  // The runners' scene with object i moving by motion(i); each runner told
  // which objects changed.
  template <class Motion_of>
  void move_to(Motion_of motion)
  {
    if (!moved) {
      moved = std::make_unique<Scene>(scene);
      for (auto& r : runner) r.reset();   // they read the scene itself
      piece_model.reset();
    }
    changed.clear();
    for (std::size_t i = 0; i < moved->objects.size(); ++i)
      if (!same_motion(moved->objects[i].motion, motion(i))) {
        // The numbers only: a query's motion is a few numbers, converted
        // (Motion_path::build) for less than a copy of their approximations
        // costs (numbers/Approximation.h).
        Motion& to = moved->objects[i].motion;
        to.times = motion(i).times;
        to.velocities = motion(i).velocities;
        to.times_approximated.clear();
        to.velocities_approximated.clear();
        changed.push_back(static_cast<int>(i));
      }
    if (changed.empty()) return;
    piece_model.reset();
    try {
      for (auto& r : runner)
        if (r) r->motions_changed(changed);
    } catch (...) {
      for (auto& r : runner) r.reset();   // half told: the next check makes them afresh
      throw;
    }
  }
};

Exact_checker::Exact_checker(const Scene& scene) : impl_(new Impl{scene, nullptr, {}, {}, nullptr}) {}
Exact_checker::~Exact_checker() = default;

Check_answer Exact_checker::check(const Check_options& options)
{
  if (impl_->moved) impl_->move_to([&](std::size_t i) -> const Motion& { return impl_->scene.objects[i].motion; });
  return impl_->check(options);
}

Check_answer Exact_checker::check(const std::vector<Motion>& motions, const Check_options& options)
{
  const std::vector<Scene_object>& objects = impl_->scene.objects;
  if (motions.size() != objects.size())
    throw std::invalid_argument("Exact_checker: " + std::to_string(motions.size()) + " motions for a scene of " +
                                std::to_string(objects.size()) + " objects");
  for (std::size_t i = 0; i < motions.size(); ++i) check_motion(motions[i], objects[i].name);
  impl_->move_to([&](std::size_t i) -> const Motion& { return motions[i]; });
  return impl_->check(options);
}

} // namespace clash4d

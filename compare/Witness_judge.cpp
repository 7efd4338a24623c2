#include "compare/Witness_judge.h"

#include "check/Closed_membership.h"
#include "model/Point_classifier.h"
#include "rotation/Rotating_check.h"

namespace clash4d {

Witness_judge::Witness_judge(const Scene& scene) : scene_(scene)
{
  if (!scene_rotates(scene)) {
    model_.emplace(Scene_model<Rational_kernel>::build(Rational_kernel(), scene));
    return;
  }
  for (const Scene_object& o : scene.objects) turning_.push_back(Rotating_object::make(o));
}

bool Witness_judge::holds(int a, int b, const Vector4<Rational>& w, bool closed) const
{
  Rational_kernel k;
  if (model_) return closed ? is_valid_contact(k, *model_, a, b, w) : is_valid_witness(k, *model_, a, b, w);
  const Rational& t = w[3];
  if (closed ? (t < scene_.t_lo || scene_.t_hi < t) : !(scene_.t_lo < t && t < scene_.t_hi)) return false;
  // The two objects at rest where they are at t, over the span [0, 1]:
  // the same point at the time 1/2 inside it.
  Scene posed = posed_pair(turning_[a], turning_[b], t);
  Scene_model<Rational_kernel> model = Scene_model<Rational_kernel>::build(k, posed);
  Vector4<Rational> at = {w[0], w[1], w[2], Rational(1, 2)};
  return closed ? is_valid_contact(k, model, 0, 1, at) : is_valid_witness(k, model, 0, 1, at);
}

std::array<std::string, 2> Witness_judge::pair_holding(const Vector4<Rational>& w, bool closed) const
{
  for (std::size_t a = 0; a < scene_.objects.size(); ++a)
    for (std::size_t b = a + 1; b < scene_.objects.size(); ++b)
      if (!scene_.ignored(int(a), int(b)) && holds(int(a), int(b), w, closed))
        return {scene_.objects[a].name, scene_.objects[b].name};
  return {"", ""};
}

} // namespace clash4d

// Every object of a scene as a CSG model with its motion, over the kernel's
// number type, and the time sub-spans of constant velocity (§4.3.2).
#ifndef CLASH4D_MODEL_SCENE_MODEL_H
#define CLASH4D_MODEL_SCENE_MODEL_H

#include "model/Far_bound.h"
#include "model/Model_builder.h"
#include "model/Motion_path.h"
#include "numbers/Number_ops.h"
#include "scene/Rotation_refusal.h"
#include "scene/Scene.h"
#include <boost/container/small_vector.hpp>
#include <algorithm>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

namespace clash4d {

template <class FT>
struct Object_model {
  std::string name;
  Csg_model<FT> csg;
  Motion_path<FT> motion;
};

template <class FT>
struct Time_span {
  FT lo, hi;
  // Whether each end is a point of the search's dyadic grid (a double),
  // decided on the scene's rationals (sub_spans): closed semantics keeps a
  // region's time face at an end only then (Span_region::on_grid).
  bool lo_on_grid = true, hi_on_grid = true;
  // The ends as the scene's own numbers (in the model that made the span):
  // for guesses that must be the same in every kernel (search/Convex_pair.h).
  const Rational* exact_lo = nullptr;
  const Rational* exact_hi = nullptr;
};

template <class K>
struct Scene_model {
  using FT = typename K::FT;
  K kernel;                              // whose signs order times
  FT t_lo = zero_value<FT>(), t_hi = zero_value<FT>();
  // The scene's own (build): sub_spans orders times on them.
  Rational exact_t_lo = shared_zero<Rational>(), exact_t_hi = shared_zero<Rational>();
  bool exact_span = false, lo_on_grid = true, hi_on_grid = true;
  std::vector<Object_model<FT>> objects;
  // R = 2^far_exponent bounds the vertices of the scene's arrangement
  // (model/Far_bound.h): the search box on an axis along which neither
  // object of a pair is bounded. One exponent from the scene's rationals,
  // the same in every kernel (path identity); -1: no pair needs it.
  int far_exponent = -1;
  // The scene the model was built from (guesses made from its own numbers,
  // the same in every kernel: search/Convex_pair.h); none: no such guesses.
  const Scene* scene = nullptr;

  static Scene_model build(const K& k, const Scene& scene)
  {
    // A rotating pose motion is not the rest its times / velocities say
    // (scene/Pose_motion.h): refused, never decided as if at rest.
    refuse_rotation(scene, "motions with rotation are not supported by this command");
    Scene_model m;
    m.kernel = k;
    m.scene = &scene;
    m.t_lo = k.from_rational(scene.t_lo);
    m.t_hi = k.from_rational(scene.t_hi);
    m.set_exact_span(scene);
    m.far_exponent = clash4d::far_exponent(scene);
    Model_builder<K> builder(k);
    m.objects.reserve(scene.objects.size());
    for (const auto& o : scene.objects)
      m.objects.push_back({o.name, builder.build(o.shape), Motion_path<FT>::build(k, o.motion)});
    return m;
  }

  void set_exact_span(const Scene& scene)
  {
    exact_t_lo = scene.t_lo;
    exact_t_hi = scene.t_hi;
    exact_span = true;
    lo_on_grid = on_grid(exact_t_lo);
    hi_on_grid = on_grid(exact_t_hi);
  }

  // [tL, tH] split at every velocity change of the given objects inside it, so
  // that each of them has one constant velocity on every sub-span (§4.3.2).
  // The times are ordered and merged on the scene's own rationals (every
  // model is built from its scene, set_exact_span): a kernel that only
  // encloses times (intervals) could not tell two objects' coinciding
  // velocity changes apart. Asked per object and per pair in every check
  // (the sweep, the pair's search): up to two spans inline, and no vector
  // made for `which`.
  using Spans = boost::container::small_vector<Time_span<FT>, 2>;
  Spans sub_spans(std::initializer_list<int> which) const { return spans_of(which.begin(), which.end()); }
  Spans sub_spans(const std::vector<int>& which) const { return spans_of(which.data(), which.data() + which.size()); }

private:
  Spans spans_of(const int* first, const int* last) const
  {
    Spans spans;   // the one object returned (no move of its inline spans)
    // No velocity change inside the span: the whole span (most pairs; a
    // moved object's breakpoints past tH too), what the general path below
    // makes of it, without sorting.
    bool still = exact_span;
    for (const int* i = first; still && i != last; ++i) still = none_inside(objects[*i].motion);
    if (still) {
      spans.push_back({t_lo, t_hi, lo_on_grid, hi_on_grid, &exact_t_lo, &exact_t_hi});
      return spans;
    }
    std::vector<std::pair<const Rational*, FT>> exact{{&exact_t_lo, t_lo}, {&exact_t_hi, t_hi}};
    bool known = exact_span;
    for (const int* i = first; i != last; ++i) {
      const Motion_path<FT>& m = objects[*i].motion;
      known = known && m.exact_times.size() == m.times.size();
      for (std::size_t k = 0; known && k < m.times.size(); ++k)
        if (exact_t_lo < m.exact_times[k] && m.exact_times[k] < exact_t_hi)
          exact.emplace_back(&m.exact_times[k], m.times[k]);
    }
    if (!known) throw std::logic_error("internal error: a model without its scene's times");
    std::sort(exact.begin(), exact.end(), [](const auto& x, const auto& y) { return *x.first < *y.first; });
    auto same = [](const auto& x, const auto& y) { return *x.first == *y.first; };
    exact.erase(std::unique(exact.begin(), exact.end(), same), exact.end());
    for (std::size_t i = 0; i + 1 < exact.size(); ++i)
      spans.push_back({exact[i].second, exact[i + 1].second, on_grid(*exact[i].first), on_grid(*exact[i + 1].first),
                       exact[i].first, exact[i + 1].first});
    return spans;
  }

  // Whether no breakpoint of m lies strictly inside (tL, tH), on the
  // scene's rationals (a path without them goes the general way, which
  // refuses it).
  bool none_inside(const Motion_path<FT>& m) const
  {
    if (m.times.empty()) return true;
    if (m.exact_times.size() != m.times.size()) return false;
    for (const Rational& t : m.exact_times)
      if (exact_t_lo < t && t < exact_t_hi) return false;
    return true;
  }

public:
  static bool on_grid(const Rational& t) { return is_exact_dyadic(t, K::grid_bits); }

  // The motion segment of object i on a sub-span (constant there).
  std::size_t segment_on(int i, const Time_span<FT>& s) const
  {
    if (objects[i].motion.times.empty()) return 0;   // one segment (most objects): no midpoint to make
    return objects[i].motion.segment_at(kernel, (s.lo + s.hi) / FT(2));
  }
};

} // namespace clash4d

#endif

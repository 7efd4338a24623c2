// Every object of a scene as a CSG model with its motion, over the kernel's
// number type, and the time sub-spans of constant velocity (§4.3.2).
#ifndef CLASH4D_MODEL_SCENE_MODEL_H
#define CLASH4D_MODEL_SCENE_MODEL_H

#include "model/Far_bound.h"
#include "model/Model_builder.h"
#include "model/Motion_path.h"
#include "scene/Scene.h"
#include <algorithm>
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
};

template <class K>
struct Scene_model {
  using FT = typename K::FT;
  K kernel;                              // whose signs order times
  FT t_lo, t_hi;
  std::vector<Object_model<FT>> objects;
  // R = 2^far_exponent bounds the vertices of the scene's arrangement
  // (model/Far_bound.h): the search box on an axis along which neither
  // object of a pair is bounded. One exponent from the scene's rationals,
  // the same in every kernel (path identity); -1: no pair needs it.
  int far_exponent = -1;

  static Scene_model build(const K& k, const Scene& scene)
  {
    Scene_model m;
    m.kernel = k;
    m.t_lo = k.from_rational(scene.t_lo);
    m.t_hi = k.from_rational(scene.t_hi);
    m.far_exponent = clash4d::far_exponent(scene);
    Model_builder<K> builder(k);
    for (const auto& o : scene.objects)
      m.objects.push_back({o.name, builder.build(o.shape), Motion_path<FT>::build(k, o.motion)});
    return m;
  }

  // [tL, tH] split at every velocity change of the given objects inside it, so
  // that each of them has one constant velocity on every sub-span (§4.3.2).
  std::vector<Time_span<FT>> sub_spans(const std::vector<int>& which) const
  {
    std::vector<FT> cuts{t_lo, t_hi};
    for (int i : which)
      for (const FT& t : objects[i].motion.times)
        if (kernel.less(t_lo, t) && kernel.less(t, t_hi)) cuts.push_back(t);
    // FT's own order sorts (a tolerance is no order); the kernel merges.
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end(),
                           [&](const FT& x, const FT& y) { return kernel.compare(x, y) == CGAL::ZERO; }),
               cuts.end());
    std::vector<Time_span<FT>> spans;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) spans.push_back({cuts[i], cuts[i + 1]});
    return spans;
  }

  // The motion segment of object i on a sub-span (constant there).
  std::size_t segment_on(int i, const Time_span<FT>& s) const
  {
    return objects[i].motion.segment_at(kernel, (s.lo + s.hi) / FT(2));
  }
};

} // namespace clash4d

#endif

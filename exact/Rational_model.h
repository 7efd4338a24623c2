// The exact kernel's model of a scene in a filtered run, made object by
// object and part by part as the run asks (docs/filtered-kernel.md: "The
// rational model is built object by object, only for objects that need
// it"): an object's motion, its planes, its whole model (vertices and
// boxes), its settled S-bounds on a boxes-only tree, and its convex-pair
// guide. Each part is made once, by whichever thread asks first
// (Lazy_once: pairs run on threads), and a prepared scene keeps the parts
// that do not depend on motions across its checks (motions_changed).
// Owned by exact/Filtered_runner.h; its policies read it through the
// runner's rational().
#ifndef CLASH4D_EXACT_RATIONAL_MODEL_H
#define CLASH4D_EXACT_RATIONAL_MODEL_H

#include "exact/Lazy_once.h"
#include "model/Model_builder.h"
#include "model/Scene_model.h"
#include "search/Convex_guide.h"
#include "search/S_bounds.h"
#include <memory>
#include <vector>

namespace clash4d {

template <class EK>
class Rational_model {
public:
  using EFT = typename EK::FT;
  using Bounds = typename S_bounds<EK>::Bounds;

  Rational_model(const EK& ek, const Scene& scene, bool use_sbounds)
    : ek_(ek), scene_(scene), use_sbounds_(use_sbounds), made_(new Parts[scene.objects.size()])
  {
    model_.t_lo = ek_.from_rational(scene.t_lo);
    model_.t_hi = ek_.from_rational(scene.t_hi);
    model_.set_exact_span(scene);
    model_.scene = &scene;
    model_.objects.resize(scene.objects.size());
    settled_.resize(scene.objects.size());
    boxes_.resize(scene.objects.size());
    for (std::size_t i = 0; i < scene.objects.size(); ++i) model_.objects[i].name = scene.objects[i].name;
  }

  // The model as made so far: an object's parts are there once asked for.
  Scene_model<EK>& model() { return model_; }
  const Scene_model<EK>& model() const { return model_; }
  // Each object's settled S-bounds (need_bounds).
  std::vector<Bounds>& settled() { return settled_; }
  const std::vector<Bounds>& settled() const { return settled_; }

  // Only the motion (a convex pair's signs in rationals read their planes
  // from the scene as asked, Interval_filter::Exact_convex).
  void need_motion(int i)
  {
    made_[i].moved.call([&] { model_.objects[i].motion = Motion_path<EFT>::build(ek_, scene_.objects[i].motion); });
  }
  // The planes of object i, in its model's tree (Model_builder::
  // build_planes): all plane tables (exact/Exact_span.h), witnesses and
  // their checks read. Its vertices and boxes are made only when
  // need_model asks.
  void need_planes(int i)
  {
    need_motion(i);
    made_[i].planed.call([&] { model_.objects[i].csg = Model_builder<EK>(ek_).build_planes(scene_.objects[i].shape); });
  }
  // The whole model of object i (what EK's runs and linear programs read:
  // Convex_pair reads vertices): made whole when no planes were asked for
  // before, otherwise the planes' model completed in place: its planes,
  // which another thread may be reading, are not touched, and no reader of
  // vertices or boxes gets here before this is done.
  void need_model(int i)
  {
    need_motion(i);
    bool whole = false;
    made_[i].planed.call([&] {
      model_.objects[i].csg = Model_builder<EK>(ek_).build(scene_.objects[i].shape);
      whole = true;
    });
    made_[i].built.call([&] {
      if (whole) return;
      Csg_model<EFT> more = Model_builder<EK>(ek_).build_vertices(scene_.objects[i].shape);
      std::vector<Primitive<EFT>>& to = model_.objects[i].csg.primitives;
      for (std::size_t k = 0; k < to.size(); ++k) {
        to[k].vertices = std::move(more.primitives[k].vertices);
        to[k].box = more.primitives[k].box;
      }
    });
  }
  // The settled S-bounds of object i, and its motion, without its model:
  // settled on the boxes-only tree (Model_builder::build_boxes), whose
  // nodes and boxes are the model's, so they are the model's bounds. All a
  // region stage in rationals reads (exact/Exact_span.h), on bounds_on.
  void need_bounds(int i)
  {
    need_motion(i);
    made_[i].settled.call([&] {
      Check_stats ignored;
      boxes_[i].csg = Model_builder<EK>(ek_).build_boxes(scene_.objects[static_cast<std::size_t>(i)].shape);
      settled_[i] = settled_bounds(ek_, boxes_[i].csg, ignored, use_sbounds_);
    });
  }
  // Everything a whole run in EK reads of object i.
  void need_exact(int i)
  {
    need_model(i);
    need_bounds(i);
  }
  // Object i on a sub-span with its settled S-bounds, for the S-bound
  // stages only (need_bounds): its tree holds boxes, not planes.
  Moving_object<EFT> bounds_on(int i, const Time_span<EFT>& span) const
  {
    Moving_object<EFT> m = moving_on(model_, i, span, settled_[i]);
    m.object = &boxes_[i];
    return m;
  }
  // Object i's convex-pair guide, made by the first pair that asks.
  std::shared_ptr<const Convex_guide> guide(int i)
  {
    made_[i].guided.call([&] { made_[i].guide = Convex_guide::make(scene_.objects[static_cast<std::size_t>(i)]); });
    return made_[i].guide;
  }

  // The objects in `changed` have other motions: theirs is made again when
  // next asked, and their guides take it (a holder's copy stays as it is).
  // Only while no check runs.
  void motions_changed(const std::vector<int>& changed)
  {
    for (int i : changed) {
      made_[i].moved.reset();
      if (!made_[i].guide) continue;
      if (made_[i].guide.use_count() > 1)   // not expected: a check's holders are gone
        made_[i].guide = std::make_shared<Convex_guide>(*made_[i].guide);
      made_[i].guide->set_motion(scene_.objects[i].motion);
    }
  }

private:
  // Whether an object's planes, its whole model, its S-bounds, its motion
  // have been made (one allocation per run: a convex pair's query is a few
  // µs); and its guide, made as lazily.
  struct Parts {
    Lazy_once planed, built, settled, moved, guided;
    std::shared_ptr<Convex_guide> guide;   // changed only by motions_changed
  };

  EK ek_;
  const Scene& scene_;
  const bool use_sbounds_;
  Scene_model<EK> model_;
  std::vector<Bounds> settled_;
  std::vector<Object_model<EFT>> boxes_;   // boxes-only trees (need_bounds)
  std::unique_ptr<Parts[]> made_;
};

} // namespace clash4d

#endif

// Candidate pairs of a many-object scene (§6) without paying for all n^2:
// each object contributes one space-time box per motion segment inside the
// span (its root S-bound moved over the segment), and CGAL's
// box_intersection_d (a streaming segment tree, O(n log^4 n + k)) reports the
// pairs of boxes that meet. It runs on double boxes rounded outward
// (CGAL::to_interval), a conservative filter only: every reported pair is
// then tested with the kernel for common interior, and pairs not kept cannot
// collide (their extrusions lie in boxes without common interior).
#ifndef CLASH4D_CHECK_PAIR_SWEEP_H
#define CLASH4D_CHECK_PAIR_SWEEP_H

#include "geometry/Box.h"
#include "model/Scene_model.h"
#include "run/Work_budget.h"
#include <CGAL/box_intersection_d.h>
#include <boost/container/small_vector.hpp>
#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

namespace clash4d {

template <class K>
class Pair_sweep {
public:
  using FT = typename K::FT;
  using Box4 = Box<FT, 4>;

  // closed: boxes that only touch are kept (closed semantics). Up to
  // few_boxes boxes (a few objects, each over a few motion segments), every
  // pair of boxes is tested, which is cheaper than the sweep's setup and
  // reports the same pairs: the sweep's filter only drops boxes apart in
  // doubles rounded outward, which the kernel finds apart too.
  explicit Pair_sweep(const K& k, bool closed = false, std::size_t few_boxes = 12)
    : k_(k), closed_(closed), few_boxes_(few_boxes)
  {}

  // roots[i]: object i's root S-bound in its own frame. Returns (i, j), i < j,
  // sorted, without ignored pairs. certain (optional): per pair returned,
  // whether some box of i and some box of j meet for certain, every
  // comparison holding for every number the kernel's may stand for (an
  // interval kernel; when not, the caller may decide the pair on exact
  // boxes with meets).
  std::vector<std::pair<int, int>> candidates(const Scene_model<K>& model, const std::vector<Box<FT, 3>>& roots,
                                              const Scene& scene, std::vector<char>* certain = nullptr) const
  {
    std::vector<std::pair<int, int>> out;
    candidates_into(model, [&](std::size_t i) -> const Box<FT, 3>& { return roots[i]; }, scene, out, certain);
    return out;
  }

  // The same, object i's root read as root_of(i), written into out (and
  // certain): a prepared scene's sweep, made again on every query with new
  // motions, keeps their storage and copies no root.
  template <class Root_of>
  void candidates_into(const Scene_model<K>& model, Root_of root_of, const Scene& scene,
                       std::vector<std::pair<int, int>>& out, std::vector<char>* certain = nullptr) const
  {
    Items items;
    items.reserve(model.objects.size());   // one box per object and motion segment: most objects have one
    for (std::size_t i = 0; i < model.objects.size(); ++i) add_boxes(model, static_cast<int>(i), root_of(i), items);
    boost::container::small_vector<std::pair<std::pair<int, int>, bool>, 4> found;   // a pair, per meeting boxes: certainly?
    std::size_t reports = 0;
    auto report = [&](const Item& x, const Item& y) {
      // Many overlapping objects report n^2 pairs: the budget bounds that too.
      if (++reports % 65536 == 0) Work_budget::check();
      if (x.object == y.object || !overlaps(x.box, y.box)) return;
      int i = std::min(x.object, y.object), j = std::max(x.object, y.object);
      if (!scene.ignored(i, j)) found.push_back({{i, j}, certain && surely_overlaps(x.box, y.box)});
    };
    if (items.size() <= few_boxes_) {
      for (std::size_t a = 0; a < items.size(); ++a)
        for (std::size_t b = a + 1; b < items.size(); ++b) report(items[a], items[b]);
    } else {
      std::vector<Filter_box> boxes;
      boxes.reserve(items.size());
      for (std::size_t i = 0; i < items.size(); ++i) boxes.push_back(filter_box(items[i].box, i));
      CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Filter_box& a, const Filter_box& b) {
        report(items[a.info()], items[b.info()]);
      });
    }
    std::sort(found.begin(), found.end());
    out.clear();
    if (certain) certain->clear();
    for (const auto& [pair, sure] : found) {   // sorted: a pair's certain report last
      if (out.empty() || out.back() != pair) {
        out.push_back(pair);
        if (certain) certain->push_back(0);
      }
      if (certain && sure) certain->back() = 1;
    }
  }

  // The sweep's test on one pair: whether some box of i meets some box of j.
  bool meets(const Scene_model<K>& model, const std::vector<Box<FT, 3>>& roots, int i, int j) const
  {
    return any_pair(model, roots, i, j, [&](const Box4& a, const Box4& b) { return overlaps(a, b); });
  }

  // Object i's displacement along axis q over a sub-span, motion segment
  // seg there: its least and greatest value, at the span's ends (the
  // motion is linear on the segment). A swept box's side is its root's
  // side plus one of them.
  std::pair<FT, FT> moved(const Scene_model<K>& model, int i, std::size_t seg, const Time_span<FT>& span, int q) const
  {
    const auto& m = model.objects[i].motion;
    const FT &v = m.velocity[seg][q], &o = m.offset[seg][q];
    // At rest along q (certainly: intervals never throw here): no product,
    // which in rationals is an allocation each.
    if (CGAL::certainly(k_.uncertain_sign(v) == CGAL::ZERO)) return {o, o};
    FT d0 = v * span.lo + o, d1 = v * span.hi + o;
    return {Number_ops<FT>::lower(d0, d1), Number_ops<FT>::upper(d0, d1)};
  }
  // Object i's box on a sub-span: its root (in its own frame) moved over
  // the motion's segment there.
  Box4 swept(const Scene_model<K>& model, int i, const Box<FT, 3>& root, const Time_span<FT>& span) const
  {
    std::size_t seg = model.segment_on(i, span);
    Box4 b;
    for (int q = 0; q < 3; ++q) {
      auto [dlo, dhi] = moved(model, i, seg, span, q);
      b.has_lo[q] = root.has_lo[q];
      b.has_hi[q] = root.has_hi[q];
      if (root.has_lo[q]) b.lo[q] = root.lo[q] + dlo;
      if (root.has_hi[q]) b.hi[q] = root.hi[q] + dhi;
    }
    b.set(3, span.lo, span.hi);
    return b;
  }

private:
  const K& k_;
  bool closed_;
  std::size_t few_boxes_;
  struct Item {
    int object;
    Box4 box;
  };
  // A few objects' boxes (the common scene: a pair) inline, without the heap.
  using Items = boost::container::small_vector<Item, 4>;
  using Filter_box = CGAL::Box_intersection_d::Box_with_info_d<double, 4, std::size_t>;

  // The double box containing b (outward rounding; unbounded sides at +-max).
  static Filter_box filter_box(const Box4& b, std::size_t index)
  {
    const double big = std::numeric_limits<double>::max();
    double lo[4], hi[4];
    for (int q = 0; q < 4; ++q) {
      lo[q] = b.has_lo[q] ? std::max(-big, CGAL::to_interval(b.lo[q]).first) : -big;
      hi[q] = b.has_hi[q] ? std::min(big, CGAL::to_interval(b.hi[q]).second) : big;
    }
    return Filter_box(lo, hi, index);
  }

  void add_boxes(const Scene_model<K>& model, int i, const Box<FT, 3>& root, Items& items) const
  {
    if (root.empty) return;
    for (const auto& span : model.sub_spans({i})) items.push_back({i, swept(model, i, root, span)});
  }

  // a's interval on axis q extends strictly past the start of b's (closed:
  // reaches it).
  bool opens_past(const Box4& a, const Box4& b, int q) const
  {
    if (!a.has_hi[q] || !b.has_lo[q]) return true;
    return closed_ ? k_.possibly_nonnegative(a.hi[q] - b.lo[q]) : k_.possibly_positive(a.hi[q] - b.lo[q]);
  }
  bool overlaps(const Box4& a, const Box4& b) const
  {
    for (int q = 0; q < 4; ++q)
      if (!opens_past(a, b, q) || !opens_past(b, a, q)) return false;
    return true;
  }

  // opens_past for certain: not possibly the opposite (b.lo - a.hi >= 0;
  // closed: > 0).
  bool surely_opens_past(const Box4& a, const Box4& b, int q) const
  {
    if (!a.has_hi[q] || !b.has_lo[q]) return true;
    return closed_ ? !k_.possibly_positive(b.lo[q] - a.hi[q]) : !k_.possibly_nonnegative(b.lo[q] - a.hi[q]);
  }
  bool surely_overlaps(const Box4& a, const Box4& b) const
  {
    for (int q = 0; q < 4; ++q)
      if (!surely_opens_past(a, b, q) || !surely_opens_past(b, a, q)) return false;
    return true;
  }

  template <class Test>
  bool any_pair(const Scene_model<K>& model, const std::vector<Box<FT, 3>>& roots, int i, int j, Test test) const
  {
    Items a, b;
    add_boxes(model, i, roots[static_cast<std::size_t>(i)], a);
    add_boxes(model, j, roots[static_cast<std::size_t>(j)], b);
    for (const Item& x : a)
      for (const Item& y : b)
        if (test(x.box, y.box)) return true;
    return false;
  }
};

} // namespace clash4d

#endif

// §5's skeleton of one pair: every edge of the boundary of the pair's
// regularised collision region, in world coordinates, collinear pieces
// merged. The full, non-terminating search. Each sub-span is searched in its
// S-bound region, but with the formula of the whole extrusions (every motion
// segment with its time slab, §3, Extrusion::whole), so that edges on a
// velocity change are classified with both segments and the span's ends tL,
// tH are real faces.
// A pair unbounded along an axis is searched within the far bound
// (model/Far_bound.h): every edge meets that box (its closure, cut by the
// coordinate hyperplanes, has a vertex inside), and an unbounded edge is
// reported clipped to it.
#ifndef CLASH4D_CHECK_PAIR_SKELETON_H
#define CLASH4D_CHECK_PAIR_SKELETON_H

#include "model/Extrusion.h"
#include "search/Divide_and_conquer.h"
#include "search/Span_region.h"
#include <algorithm>
#include <map>

namespace clash4d {

template <class K>
class Pair_skeleton {
public:
  using FT = typename K::FT;
  using H = Hyperplane4<FT>;
  using V4 = Vector4<FT>;
  using Segment = std::array<V4, 2>;
  using Bounds = typename S_bounds<K>::Bounds;

  Pair_skeleton(const K& k, const Scene_model<K>& model, const std::vector<Bounds>& settled, Check_stats& stats)
    : k_(k), model_(model), settled_(settled), stats_(stats) {}

  std::vector<Segment> edges(int a, int b)
  {
    ++stats_.pairs;
    std::vector<Segment> edges;
    Span_region<K> bounds(k_, stats_, model_.far_exponent);
    for (const auto& span : model_.sub_spans({a, b})) {
      ++stats_.sub_spans;
      Moving_object<FT> A = moving_on(model_, a, span, settled_[a]), B = moving_on(model_, b, span, settled_[b]);
      FT tl = span.lo, th = span.hi;
      if (!bounds.four_d_bounds(A, B, tl, th)) { ++stats_.sub_spans_pruned; continue; }
      Vector3<FT> shear;
      std::array<bool, 3> frame_of_a{};
      Box<FT, 4> region = bounds.fitted(A, B, tl, th, shear, frame_of_a);
      std::vector<H> table;
      Formula::Builder builder;
      std::size_t mark = builder.open();
      for (const H& h : {time_at_least(model_.t_lo), time_at_most(model_.t_hi)})
        Extrusion<K>::slab_leaf(h, table, builder);
      Extrusion<K>::whole(k_, model_, a, settled_[a], shear, table, builder);
      Extrusion<K>::whole(k_, model_, b, settled_[b], shear, table, builder);
      builder.close(Formula::Op::And, mark);
      Formula formula = builder.finish();
      std::vector<Segment> pieces;
      Divide_and_conquer<K>(k_, table, stats_).skeleton(region, formula, pieces);
      for (Segment& e : pieces)
        for (V4& p : e)
          for (int q = 0; q < 3; ++q) p[q] += shear[q] * p[3];
      edges.insert(edges.end(), pieces.begin(), pieces.end());
    }
    return merge_collinear(edges);
  }

private:
  const K& k_;
  const Scene_model<K>& model_;
  const std::vector<Bounds>& settled_;
  Check_stats& stats_;

  // Pieces found in neighbouring regions (or split at cuts) are joined when
  // they lie on one line and overlap or meet end to end.
  std::vector<Segment> merge_collinear(const std::vector<Segment>& pieces) const
  {
    // Key: the direction scaled so its first non-zero coordinate k is 1, and
    // the line's point with coordinate k = 0; a piece is then [p_k, q_k].
    std::map<std::array<FT, 8>, std::vector<std::pair<FT, FT>>> lines;
    for (const Segment& e : pieces) {
      V4 d;
      for (int q = 0; q < 4; ++q) d[q] = e[1][q] - e[0][q];
      int k = 0;
      while (k < 4 && k_.sign(d[k]) == CGAL::ZERO) ++k;
      if (k == 4) continue;
      std::array<FT, 8> key;
      for (int q = 0; q < 4; ++q) key[q] = d[q] / d[k];
      for (int q = 0; q < 4; ++q) key[4 + q] = e[0][q] - e[0][k] * key[q];
      FT s0 = e[0][k], s1 = e[1][k];
      bool ascending = k_.less(s0, s1);
      lines[key].emplace_back(ascending ? s0 : s1, ascending ? s1 : s0);
    }
    std::vector<Segment> out;
    for (auto& [key, spans] : lines) {
      std::sort(spans.begin(), spans.end());
      std::vector<std::pair<FT, FT>> merged;
      for (const auto& sp : spans) {
        if (!merged.empty() && !k_.less(merged.back().second, sp.first)) {
          if (k_.less(merged.back().second, sp.second)) merged.back().second = sp.second;
        } else merged.push_back(sp);
      }
      for (const auto& sp : merged) {
        Segment e;
        for (int q = 0; q < 4; ++q) {
          e[0][q] = key[4 + q] + sp.first * key[q];
          e[1][q] = key[4 + q] + sp.second * key[q];
        }
        out.push_back(e);
      }
    }
    return out;
  }
};

} // namespace clash4d

#endif

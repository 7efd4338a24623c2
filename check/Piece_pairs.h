// --earliest on objects that are unions of convex pieces (a mesh is read as
// one: scene/Mesh_solid.h), decided piece pair by piece pair (issue 58
// item 4) instead of by the paper's divide-and-conquer over the whole
// union formula.
//
// Why it is the same t*: with A = A_1 u ... u A_m and B = B_1 u ... u B_n
// closed regular sets, A n B = u (A_i n B_j), a finite union of closed
// sets. Regularised: the closure of the interior of a finite union of
// closed sets is the union of the closures of their interiors (what each
// adds beyond that is nowhere dense), so inf t over the collision region
// of (A, B) is min over (i, j) of inf t over that of (A_i, B_j). Closed:
// each piece is regular, so A's closed set is u A_i, and the first contact
// time is the least over (i, j) of the first contact time of (A_i, B_j).
// An object that is not such a union is one piece (itself).
//
// Each piece pair is convex (or has one non-convex object) and goes through
// Collision_checker as any pair does (the linear programs of
// search/Convex_pair.h decide convex ones at once); the pairs are taken in
// the order of a lower bound on their first time, the time from which
// their swept boxes meet, and a pair whose bound starts after the best t*
// so far is never searched (the ceiling, as across object pairs in
// check/Check_runner.h). The answer's points are then made again for the
// whole objects (a point inside a piece may lie on another piece's plane)
// and checked against the original objects as the cascade's are; a point
// that fails leaves the whole query to the cascade (nothing returned).
#ifndef CLASH4D_CHECK_PIECE_PAIRS_H
#define CLASH4D_CHECK_PIECE_PAIRS_H

#include "check/Check_answer.h"
#include "check/Collision_checker.h"
#include "geometry/Box_meeting.h"
#include "search/Convex_guide.h"
#include "search/S_bounds.h"
#include "run/Work_budget.h"
#include <algorithm>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <tuple>
#include <vector>

namespace clash4d {

// A scene's objects cut into their convex pieces: one object per piece,
// with its owner's motion, its solid the piece under the owner's
// transforms. Pieces are in the order Model_builder makes the owner's
// primitives (depth first), so piece k of an object is its primitive k.
struct Piece_split {
  Scene scene;                    // the pieces as objects (the convex pairs' guides read them)
  std::vector<int> owner;         // piece -> object of the original scene
  std::vector<std::size_t> first; // object -> its first piece; first[n] = the piece count
  std::vector<char> whole;        // object -> kept whole (not a union of convex primitives)

  // Some object is a union of two or more convex primitives; none when
  // every object is one piece (the plain path is this path then).
  static std::optional<Piece_split> make(const Scene& scene)
  {
    Piece_split s;
    s.scene.name = scene.name;
    s.scene.t_lo = scene.t_lo;
    s.scene.t_hi = scene.t_hi;
    bool cut = false;
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
      const Scene_object& obj = scene.objects[o];
      s.first.push_back(s.scene.objects.size());
      std::vector<Solid> pieces;
      bool ok = cut_into(obj.shape, {}, pieces);
      s.whole.push_back(!ok);
      if (!ok) {
        pieces.clear();
        pieces.push_back(obj.shape);
      }
      cut = cut || pieces.size() > 1;
      for (std::size_t k = 0; k < pieces.size(); ++k) {
        s.scene.objects.push_back({obj.name + "#" + std::to_string(k), std::move(pieces[k]), obj.motion});
        s.owner.push_back(static_cast<int>(o));
      }
    }
    s.first.push_back(s.scene.objects.size());
    if (!cut) return std::nullopt;
    return s;
  }

  std::size_t pieces_of(std::size_t o) const { return first[o + 1] - first[o]; }

  // The pairs of pieces of two objects of `scene` (this split's) not
  // ignored: the piece pairs a query asks about.
  std::size_t piece_pairs(const Scene& scene) const
  {
    std::size_t n = scene.objects.size(), count = 0;
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 1; b < n; ++b)
        if (!scene.ignored(static_cast<int>(a), static_cast<int>(b))) count += pieces_of(a) * pieces_of(b);
    return count;
  }

private:
  static bool primitive(Solid::Kind k)
  {
    using S = Solid::Kind;
    return k == S::Halfspace || k == S::Block || k == S::Convex || k == S::Prism || k == S::Hull;
  }

  // s's convex pieces, each under the transforms above it (outer first);
  // false when s has an intersection or difference.
  static bool cut_into(const Solid& s, std::vector<const Solid*> above, std::vector<Solid>& out)
  {
    if (primitive(s.kind)) {
      Solid piece = s;
      for (auto t = above.rbegin(); t != above.rend(); ++t) piece = wrapped(**t, std::move(piece));
      out.push_back(std::move(piece));
      return true;
    }
    if (s.kind == Solid::Kind::Translate || s.kind == Solid::Kind::Rotate) {
      above.push_back(&s);
      return cut_into(s.children[0], above, out);
    }
    if (s.kind != Solid::Kind::Union) return false;
    for (const Solid& c : s.children)
      if (!cut_into(c, above, out)) return false;
    return true;
  }

  // The transform t around `inner` (t's own fields, not its subtree).
  static Solid wrapped(const Solid& t, Solid inner)
  {
    Solid w;
    w.kind = t.kind;
    w.path = t.path;
    w.numbers = t.numbers;
    w.constructed = t.constructed;
    w.numbers_approximated = t.numbers_approximated;
    w.constructed_approximated = t.constructed_approximated;
    w.children.push_back(std::move(inner));
    return w;
  }
};

template <class K>
class Piece_pairs {
public:
  using FT = typename K::FT;
  using Bounds = typename S_bounds<K>::Bounds;

  // Whether the query is one this path answers: --earliest for the
  // earliest pair only, linear programs on (the path's speed is theirs).
  static bool asked(const Check_options& o) { return o.earliest && !o.all_pairs && o.piece_pairs && o.convex_lp; }

  // Another kernel's check of piece pair (i, j) of split.scene, its answer
  // in K's numbers and K's own (the filtered kernel: exact/
  // Exact_instantiation.cpp); none: K checks the pair.
  using Pair_check = std::function<std::optional<Pair_result<FT>>(int, int, const FT*, Check_stats&)>;

  using Pair_list = std::vector<std::pair<int, int>>;

  // model: the scene's, in K (its objects' primitives are the pieces').
  // may_meet: piece pairs (i, j) among which are all whose moving boxes
  // meet, the others' known never to (the filtered kernel's sweep and
  // intervals, exact/Piece_prepass.h); none: every piece pair is asked.
  Piece_pairs(const K& k, const Scene& scene, const Scene_model<K>& model, const Piece_split& split,
              const Check_options& options, Pair_check pair_check = {}, const Pair_list* may_meet = nullptr)
    : k_(k), scene_(scene), model_(model), split_(split), options_(options), pair_check_(std::move(pair_check)),
      may_meet_(may_meet)
  {}

  // The earliest colliding pair in the objects' indices, its points made
  // for the objects and checked (r.collide false: no pair collides); none
  // when a point failed its check or the model is not the split's: the
  // caller runs the cascade.
  std::optional<Pair_result<FT>> earliest(Check_stats& stats)
  {
    if (!make_piece_model(stats)) return std::nullopt;
    std::vector<Candidate> order = candidates(stats);
    std::optional<Best> best;
    std::size_t searched = 0;
    for (const Candidate& c : order) {
      if (best && (k_.less(best->r.t_star, c.t0) ||
                   (!k_.less(c.t0, best->r.t_star) && c.object_pair >= best->object_pair)))
        continue;   // cannot start before the best (a tie: a later object pair loses it)
      if (++searched % 64 == 0) Work_budget::check();
      Pair_result<FT> r = check_pair(c, best ? &best->r.t_star : nullptr, stats);
      if (!r.collide) continue;
      if (best && !k_.less(r.t_star, best->r.t_star) &&
          (k_.less(best->r.t_star, r.t_star) || c.object_pair >= best->object_pair))
        continue;
      best = Best{std::move(r), c.object_pair};
    }
    if (!best) return Pair_result<FT>();
    int a = split_.owner[static_cast<std::size_t>(best->r.a)], b = split_.owner[static_cast<std::size_t>(best->r.b)];
    std::optional<Pair_result<FT>> r = on_objects(best->r, a, b);
    if (r || K::is_exact) return r;
    return unverified(std::move(best->r), a, b);
  }

private:
  // A piece pair, its owners' pair's place in pair order, and the time
  // from which their swept boxes meet (no collision or contact before it).
  struct Candidate {
    int i, j;
    std::size_t object_pair;
    FT t0;
  };
  struct Best {
    Pair_result<FT> r;
    std::size_t object_pair;
  };

  const K& k_;
  const Scene& scene_;
  const Scene_model<K>& model_;
  const Piece_split& split_;
  const Check_options& options_;
  Pair_check pair_check_;
  const Pair_list* may_meet_;
  Scene_model<K> pieces_;
  std::vector<Bounds> settled_;
  std::vector<std::shared_ptr<const Convex_guide>> guides_;
  Guide_source guide_source_ = [this](int i) {
    auto& g = guides_[static_cast<std::size_t>(i)];
    if (!g) g = Convex_guide::make(split_.scene.objects[static_cast<std::size_t>(i)]);
    return g;
  };

  // The pieces as objects, each one primitive of its owner's model (the
  // same numbers: no model is built again), with the owner's motion.
  bool make_piece_model(Check_stats& stats)
  {
    pieces_.kernel = model_.kernel;
    pieces_.t_lo = model_.t_lo;
    pieces_.t_hi = model_.t_hi;
    pieces_.set_exact_span(split_.scene);
    pieces_.far_exponent = model_.far_exponent;   // the pieces' planes are the objects'
    pieces_.scene = &split_.scene;
    pieces_.objects.reserve(split_.owner.size());
    for (std::size_t o = 0; o < model_.objects.size(); ++o) {
      const Object_model<FT>& obj = model_.objects[o];
      if (split_.whole[o]) {
        pieces_.objects.push_back(obj);
        continue;
      }
      if (obj.csg.primitives.size() != split_.pieces_of(o)) return false;
      for (std::size_t p = 0; p < obj.csg.primitives.size(); ++p) {
        Object_model<FT> piece{split_.scene.objects[split_.first[o] + p].name, {}, obj.motion};
        piece.csg.nodes.emplace_back();
        piece.csg.nodes[0].primitive = 0;
        piece.csg.primitives.push_back(obj.csg.primitives[p]);
        pieces_.objects.push_back(std::move(piece));
      }
    }
    settled_ = settled_bounds_all(k_, pieces_, stats, options_.sbounds);
    guides_.assign(pieces_.objects.size(), nullptr);
    return true;
  }

  // Piece pair c searched for its earliest point before `ceiling`: by the
  // pair check when there is one and it answers, else in K.
  Pair_result<FT> check_pair(const Candidate& c, const FT* ceiling, Check_stats& stats)
  {
    if (pair_check_)
      if (std::optional<Pair_result<FT>> r = pair_check_(c.i, c.j, ceiling, stats)) return std::move(*r);
    Collision_checker<K> checker(k_, pieces_, settled_, stats, options_.sbounds);
    checker.use_guides(&guide_source_);
    return checker.check_pair(c.i, c.j, true, ceiling, options_.semantics);
  }

  // Every piece pair of two objects not ignored whose swept boxes meet, by
  // the time they start to (then pair order, then pieces). Stats: the
  // piece pairs (object_pairs), those whose boxes meet (candidate_pairs);
  // `pairs` counts those searched.
  std::vector<Candidate> candidates(Check_stats& stats)
  {
    stats.object_pairs += split_.piece_pairs(scene_);
    std::vector<Candidate> out;
    std::vector<std::size_t> place = pair_places();
    Pair_list asked = may_meet_ ? pairs_of_objects(*may_meet_, place) : every_piece_pair(place);
    std::pair<int, int> owners{-1, -1};
    typename Scene_model<K>::Spans spans;
    for (std::size_t p = 0; p < asked.size(); ++p) {
      auto [i, j] = asked[p];
      std::pair<int, int> now{owner(i), owner(j)};
      if (now != owners) spans = model_.sub_spans({now.first, now.second});
      owners = now;
      if (p % 4096 == 0) Work_budget::check();
      std::size_t object_pair = place[static_cast<std::size_t>(now.first) * scene_.objects.size() +
                                      static_cast<std::size_t>(now.second)];
      for (const auto& span : spans) add_meeting(i, j, object_pair, span, out);
    }
    std::sort(out.begin(), out.end(), [&](const Candidate& x, const Candidate& y) {
      if (k_.less(x.t0, y.t0)) return true;
      if (k_.less(y.t0, x.t0)) return false;
      return std::tie(x.object_pair, x.i, x.j) < std::tie(y.object_pair, y.i, y.j);
    });
    // One entry per piece pair (its earliest sub-span's bound): the pair
    // is searched over all its sub-spans at once.
    std::vector<Candidate> once;
    std::set<std::pair<int, int>> seen;
    for (Candidate& c : out)
      if (seen.insert({c.i, c.j}).second) once.push_back(std::move(c));
    stats.candidate_pairs = once.size();
    return once;
  }

  int owner(int piece) const { return split_.owner[static_cast<std::size_t>(piece)]; }

  // Objects (a, b), a < b, -> the place of their pair in pair order (the
  // pairs not ignored, a then b ascending) at a * n + b; npos: ignored.
  std::vector<std::size_t> pair_places() const
  {
    std::size_t n = scene_.objects.size(), next = 0;
    std::vector<std::size_t> place(n * n, npos);
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 1; b < n; ++b)
        if (!scene_.ignored(static_cast<int>(a), static_cast<int>(b))) place[a * n + b] = next++;
    return place;
  }

  // Every piece pair of two objects not ignored, in pair order.
  Pair_list every_piece_pair(const std::vector<std::size_t>& place) const
  {
    Pair_list out;
    std::size_t n = scene_.objects.size();
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 1; b < n; ++b)
        if (place[a * n + b] != npos)
          for (std::size_t i = split_.first[a]; i < split_.first[a + 1]; ++i)
            for (std::size_t j = split_.first[b]; j < split_.first[b + 1]; ++j)
              out.push_back({static_cast<int>(i), static_cast<int>(j)});
    return out;
  }

  // The pairs of `given` of two objects not ignored, the lower owner's
  // piece first, grouped by their objects' pair.
  Pair_list pairs_of_objects(const Pair_list& given, const std::vector<std::size_t>& place) const
  {
    Pair_list out;
    std::size_t n = scene_.objects.size();
    for (auto [i, j] : given) {
      if (owner(j) < owner(i)) std::swap(i, j);
      std::size_t a = static_cast<std::size_t>(owner(i)), b = static_cast<std::size_t>(owner(j));
      if (a != b && place[a * n + b] != npos) out.push_back({i, j});
    }
    std::sort(out.begin(), out.end(), [&](const std::pair<int, int>& x, const std::pair<int, int>& y) {
      return std::make_tuple(owner(x.first), owner(x.second), x) < std::make_tuple(owner(y.first), owner(y.second), y);
    });
    return out;
  }

  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  // Piece pair (i, j) as a candidate on the sub-span when their boxes
  // meet there, with the first time they do.
  void add_meeting(int i, int j, std::size_t object_pair, const Time_span<FT>& span, std::vector<Candidate>& out)
  {
    int a = owner(i), b = owner(j);
    std::size_t sa = model_.segment_on(a, span), sb = model_.segment_on(b, span);
    const auto &ma = model_.objects[static_cast<std::size_t>(a)].motion,
               &mb = model_.objects[static_cast<std::size_t>(b)].motion;
    std::size_t ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
    std::optional<FT> t0 = first_box_meeting(k_, settled_[ui][0], ma.velocity[sa], ma.offset[sa], settled_[uj][0],
                                             mb.velocity[sb], mb.offset[sb], span.lo, span.hi);
    if (t0) out.push_back({i, j, object_pair, std::move(*t0)});
  }

  // Object i of the model on a sub-span, as the witness stages read it
  // (its planes and motion; no bounds).
  Moving_object<FT> moving(int i, const Time_span<FT>& span) const { return moving_on(model_, i, span, {}); }

  // The sub-span of objects a and b whose closure holds time t (strictly
  // inside it when `inside`); none when there is none.
  std::optional<Time_span<FT>> span_at(int a, int b, const FT& t, bool inside) const
  {
    for (const auto& s : model_.sub_spans({a, b})) {
      bool in = inside ? k_.less(s.lo, t) && k_.less(t, s.hi) : !k_.less(t, s.lo) && !k_.less(s.hi, t);
      if (in) return s;
    }
    return std::nullopt;
  }

  // A float kernel's answer whose points did not hold for the objects: the
  // piece pair's, marked unverified (as the cascade's float answers may
  // be), rather than the cascade's slow search; none when it has no points.
  static std::optional<Pair_result<FT>> unverified(Pair_result<FT> r, int a, int b)
  {
    bool closed = r.semantics == Semantics::closed;
    if (!r.has_witness || (closed && r.witness_cells.size() != 2) || r.contact_cells.size() != 2) return std::nullopt;
    r.a = a;
    r.b = b;
    r.witness_verified = false;
    return r;
  }

  // The piece pair's answer r for objects a and b: its t* and contact
  // point (a point of both pieces' closures is one of both objects'), with
  // the generic points made again on all of both objects' planes and
  // checked against them. A point inside a piece stays inside it along a
  // step that crosses no plane (search/Witness.h), so each is made from
  // the piece pair's own: the witness from its witness, the contact's cell
  // point on the segment from the contact to the new witness (both in the
  // closure of the pieces' convex region), a closed cell point on the
  // segment from the contact to the piece's cell point.
  std::optional<Pair_result<FT>> on_objects(const Pair_result<FT>& r, int a, int b) const
  {
    if (!r.has_witness || !r.witness_verified) return std::nullopt;
    Pair_result<FT> out;
    out.a = a;
    out.b = b;
    out.collide = out.earliest = out.has_witness = true;
    out.semantics = r.semantics;
    out.t_star = r.t_star;
    out.contact = r.contact;
    Witness<K> w(k_);
    const Vector3<FT> still{FT(0), FT(0), FT(0)};
    if (r.semantics == Semantics::closed) {
      std::optional<Time_span<FT>> span = span_at(a, b, r.witness[3], false);
      if (!span || r.witness_cells.size() != 2) return std::nullopt;
      std::optional<Vector4<FT>> g[2];
      for (int o = 0; o < 2; ++o) {
        Vector4<FT> d = r.witness_cells[o];
        for (int q = 0; q < 4; ++q) d[q] -= r.witness[q];
        g[o] = w.near_in_space(r.witness, d, still, moving(o == 0 ? a : b, *span));
        if (!g[o]) return std::nullopt;
      }
      out.witness = r.witness;
      out.witness_cells = {*g[0], *g[1]};
      out.contact_cells = out.witness_cells;
      out.witness_verified = is_valid_touch(k_, model_, a, b, out.witness, *g[0], *g[1]);
    } else {
      std::optional<Time_span<FT>> span = span_at(a, b, r.witness[3], true);
      if (!span) return std::nullopt;
      Moving_object<FT> A = moving(a, *span), B = moving(b, *span);
      std::vector<Hyperplane4<FT>> world = Witness<K>::world_planes(A, B, span->lo, span->hi);
      std::optional<Vector4<FT>> in = w.make_on(r.witness, still, world);
      std::optional<Vector4<FT>> g = in ? w.near(r.contact, *in, still, A, B, span->lo, span->hi) : std::nullopt;
      if (!g) return std::nullopt;
      out.witness = *in;
      out.contact_cells = {*g, *g};
      out.witness_verified = is_valid_witness(k_, model_, a, b, *in) &&
                             is_valid_contact_cell(k_, model_, a, b, out.contact, *g);
    }
    if (!out.witness_verified) return std::nullopt;
    return out;
  }
};

} // namespace clash4d

#endif

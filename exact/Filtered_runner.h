// `check` and `skeleton` through a filter (CGAL's Filtered_predicate pattern
// applied to a whole pair): every pair is first run by the generic stages on
// the approximate kernel AK, whose sign() throws
// CGAL::Uncertain_conversion_exception when it cannot certify a sign. Every
// decision of a run that did not throw is certified, the heuristic ones
// included (S-bound passes and frames are chosen on grid points,
// Kernel_base::grid_point), so such a run took the path EK's run takes, on
// numbers enclosing EK's: its "no collision" is EK's.
//
// A colliding pair's witness is made by AK itself when nothing in its run
// was left uncertain (Collision_checker::as_filter): the witness is snapped
// to a dyadic grid point (Witness::snap), which AK finds exactly
// from its enclosures. Otherwise the pair is run again on EK: an
// any-witness search goes straight to the point AK found, along AK's trail
// (search/Search_trail.h), and falls back to the whole search when EK's path
// differs; earliest mode (t* is any rational) always runs the whole search.
//
// EK's model is built object by object, only for objects that need it.
#ifndef CLASH4D_EXACT_FILTERED_RUNNER_H
#define CLASH4D_EXACT_FILTERED_RUNNER_H

#include "check/Check_runner.h"
#include <CGAL/Uncertain.h>
#include <map>
#include <memory>
#include <mutex>
#include <optional>

namespace clash4d {

// Protector: RAII guard putting the FPU in the mode AK needs (for intervals,
// CGAL::Protect_FPU_rounding<true>); held around every AK computation, in the
// thread doing it.
template <class AK, class EK, class Protector>
class Filtered_runner {
public:
  using AFT = typename AK::FT;
  using EFT = typename EK::FT;

  Filtered_runner(const Scene& scene, bool use_sbounds)
    : scene_(scene), use_sbounds_(use_sbounds), built_(new std::once_flag[scene.objects.size()]),
      settled_(new std::once_flag[scene.objects.size()])
  {
    emodel_.t_lo = ek_.from_rational(scene.t_lo);
    emodel_.t_hi = ek_.from_rational(scene.t_hi);
    emodel_.objects.resize(scene.objects.size());
    esettled_.resize(scene.objects.size());
    for (std::size_t i = 0; i < scene.objects.size(); ++i) emodel_.objects[i].name = scene.objects[i].name;
  }

  Check_answer check(const Check_options& options)
  {
    Check_answer answer;
    std::vector<std::pair<int, int>> pairs;
    if (!prepare(answer.stats, pairs)) {
      answer = run_check(ek_, scene_, options);     // AK could not even build the model
    } else {
      auto check_one = [&](std::size_t i, const EFT* ceiling, Check_stats& stats) {
      int a = pairs[i].first, b = pairs[i].second;
      Search_trail trail;
      Check_stats astats;
      if (!exact_only_[a] && !exact_only_[b]) {
        try {
          Protector protect;
          AFT aceiling = ceiling ? ak_.from_rational(ek_.to_rational(*ceiling)) : AFT(0);
          Collision_checker<AK> checker(ak_, amodel_, asettled_, astats, use_sbounds_);
          Exact_span exact;
          checker.as_filter(
              [&](int a, int b, std::size_t span, const std::array<bool, 3>& frame, const Plane_layout& layout,
                  const Box<AFT, 4>& region) { return exact.lines(*this, a, b, span, frame, layout, region); },
              [&](int a, int b, std::size_t span, const std::array<bool, 3>& frame, long eh, int fh, long eg, int fg,
                  const Box<AFT, 4>& region) { return exact.proportional(*this, a, b, span, frame, eh, fh, eg, fg, region); });
          if (!options.earliest) checker.follow(&trail);
          Pair_result<AFT> found = checker.check_pair(a, b, options.earliest, ceiling ? &aceiling : nullptr);
          if (!found.collide) {
            stats = astats;
            return Pair_result<EFT>();
          }
          if (found.has_witness && found.witness_verified) {
            ++witnesses_by_intervals_;
            stats = astats;
            return exact_copy(found);
          }
          ++witness_runs_;
        } catch (const CGAL::Uncertain_conversion_exception&) {
          ++fallbacks_;
          trail.complete = false;
        }
      }
      need_exact(a);
      need_exact(b);
      if (trail.complete && !trail.approximate) {
        Check_stats rstats;
        trail.mode = Search_trail::Mode::Replay;
        Collision_checker<EK> checker(ek_, emodel_, esettled_, rstats, use_sbounds_);
        checker.follow(&trail);
        Pair_result<EFT> r = checker.check_pair(a, b);
        if (r.collide && !trail.diverged) {
          ++witness_replays_;
          stats = astats;                     // the search, as the interval run did it
          stats.seconds_witness += rstats.seconds_witness;
          return r;
        }
      }
      Collision_checker<EK> checker(ek_, emodel_, esettled_, stats, use_sbounds_);
      return checker.check_pair(a, b, options.earliest, ceiling);
    };
      run_pairs(ek_, emodel_, pairs, options, check_one, answer);
    }
    answer.number = EK_name;
    finish(answer.stats);
    return answer;
  }

  Skeleton_answer skeleton()
  {
    Skeleton_answer answer;
    use_sbounds_ = true;
    std::vector<std::pair<int, int>> pairs;
    if (!prepare(answer.stats, pairs)) {
      answer = run_skeleton(ek_, scene_);
    } else {
      auto skeleton_one = [&](std::size_t i, Check_stats& stats) {
      int a = pairs[i].first, b = pairs[i].second;
      if (!exact_only_[a] && !exact_only_[b]) {
        try {
          Protector protect;
          Check_stats astats;
          if (Pair_skeleton<AK>(ak_, amodel_, asettled_, astats).edges(a, b).empty()) {
            stats = astats;
            return std::vector<typename Pair_skeleton<EK>::Segment>();
          }
          ++witness_runs_;
        } catch (const CGAL::Uncertain_conversion_exception&) {
          ++fallbacks_;
        }
      }
      need_exact(a);
      need_exact(b);
      return Pair_skeleton<EK>(ek_, emodel_, esettled_, stats).edges(a, b);
    };
      run_skeleton_pairs(ek_, emodel_, pairs, skeleton_one, answer);
    }
    answer.number = EK_name;
    finish(answer.stats);
    return answer;
  }

private:
  static constexpr const char* EK_name = "exact";
  const Scene& scene_;
  bool use_sbounds_;
  AK ak_;
  EK ek_;
  Scene_model<AK> amodel_;
  std::vector<typename S_bounds<AK>::Bounds> asettled_;
  std::vector<char> exact_only_;              // AK could not bound the object: its pairs go to EK
  Scene_model<EK> emodel_;                    // objects built on demand
  std::vector<typename S_bounds<EK>::Bounds> esettled_;
  std::unique_ptr<std::once_flag[]> built_, settled_;   // EK's model of an object, and its S-bounds
  std::atomic<std::size_t> fallbacks_{0}, witness_runs_{0}, witness_replays_{0}, exact_regions_{0}, exact_planes_{0},
      witnesses_by_intervals_{0};

  // A witness AK made on a certified path: its coordinates are grid points
  // (Witness::snap), exact doubles, so AK's point intervals are
  // EK's numbers.
  Pair_result<EFT> exact_copy(const Pair_result<AFT>& found) const
  {
    Pair_result<EFT> r;
    r.a = found.a;
    r.b = found.b;
    r.collide = r.has_witness = r.witness_verified = true;
    for (int q = 0; q < 4; ++q) {
      std::optional<Rational> x = ak_.exact_value(found.witness[q]);
      if (!x) throw std::logic_error("internal error: an interval witness is not a point");
      r.witness[q] = ek_.from_rational(*x);
    }
    return r;
  }

  // AK's model, each object's S-bounds (EK's where AK fails), and the sweep's
  // pairs. False when AK cannot build the model: the whole run goes to EK.
  bool prepare(Check_stats& stats, std::vector<std::pair<int, int>>& pairs)
  {
    std::size_t n = scene_.objects.size();
    exact_only_.assign(n, 0);
    auto start = std::chrono::steady_clock::now();
    try {
      Protector protect;
      amodel_ = Scene_model<AK>::build(ak_, scene_);
    } catch (const CGAL::Uncertain_conversion_exception&) {
      ++fallbacks_;
      return false;
    }
    stats.seconds_model = seconds_since(start);
    start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < n; ++i) asettled_.push_back(settle(static_cast<int>(i), stats));
    stats.seconds_sbounds += seconds_since(start);
    try {
      Protector protect;
      pairs = candidate_pairs(ak_, amodel_, asettled_, scene_, stats);
    } catch (const CGAL::Uncertain_conversion_exception&) {
      // The sweep could not order some motion times: sweep in EK instead.
      ++fallbacks_;
      for (std::size_t i = 0; i < n; ++i) need_exact(static_cast<int>(i));
      pairs = candidate_pairs(ek_, emodel_, esettled_, scene_, stats);
    }
    return true;
  }

  typename S_bounds<AK>::Bounds settle(int i, Check_stats& stats)
  {
    try {
      Protector protect;
      return settled_bounds(ak_, amodel_.objects[i].csg, stats, use_sbounds_);
    } catch (const CGAL::Uncertain_conversion_exception&) {
      ++fallbacks_;
      exact_only_[i] = 1;
      need_exact(i);
      // Only the sweep reads it: the root box, EK's enclosed in AK's numbers.
      Protector protect;
      return typename S_bounds<AK>::Bounds(1, enclose(esettled_[i][0]));
    }
  }

  Box<AFT, 3> enclose(const Box<EFT, 3>& e) const
  {
    Box<AFT, 3> b;
    b.empty = e.empty;
    b.has_lo = e.has_lo;
    b.has_hi = e.has_hi;
    for (int q = 0; q < 3; ++q) {
      if (e.has_lo[q]) b.lo[q] = ak_.from_rational(ek_.to_rational(e.lo[q]));
      if (e.has_hi[q]) b.hi[q] = ak_.from_rational(ek_.to_rational(e.hi[q]));
    }
    return b;
  }

  // EK's side of one pair's AK run: the plane table of the sub-span AK is
  // in, made when AK first needs it, and the planes AK could not compare.
  struct Exact_span {
    std::size_t span = static_cast<std::size_t>(-1);
    std::vector<Hyperplane4<EFT>> table;
    std::vector<Hyperplane4<EFT>> lowest;         // table entries in lowest terms, as lines need them
    std::vector<char> lowest_made;
    Motion_groups<EFT> groups;
    std::map<std::pair<long, long>, int> answers;

    void enter(Filtered_runner& runner, int a, int b, std::size_t s, const std::array<bool, 3>& frame)
    {
      if (s == span) return;
      runner.need_model(a);
      runner.need_model(b);
      Check_stats ignored;
      groups = Motion_groups<EFT>();
      table = Collision_checker<EK>(runner.ek_, runner.emodel_, runner.esettled_, ignored, runner.use_sbounds_)
                  .span_table(a, b, s, frame, groups);
      lowest.clear();
      answers.clear();
      span = s;
    }

    // Whether two planes are one, each a table entry or (entry -1) a face of
    // AK's region; a face whose value AK only encloses cannot be compared
    // exactly here, and AK's run fails as it would have.
    int proportional(Filtered_runner& runner, int a, int b, std::size_t s, const std::array<bool, 3>& frame, long eh,
                     int fh, long eg, int fg, const Box<AFT, 4>& region)
    {
      CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
      enter(runner, a, b, s, frame);
      auto plane = [&](long e, int f) {
        if (e >= 0) return table.at(static_cast<std::size_t>(e));
        std::optional<Rational> v = runner.ak_.exact_value(f % 2 ? region.hi[f / 2] : region.lo[f / 2]);
        if (!v) throw CGAL::Uncertain_conversion_exception("a region face AK only encloses");
        Box<EFT, 4> exact;
        exact.set(f / 2, runner.ek_.from_rational(*v), runner.ek_.from_rational(*v));
        return Generate_and_test<EK>::face(exact, f);
      };
      if (eh < 0 || eg < 0) {
        ++runner.exact_planes_;
        return clash4d::proportional(runner.ek_, plane(eh, fh), plane(eg, fg));
      }
      auto [it, fresh] = answers.try_emplace({eh, eg}, 0);
      if (fresh) {
        ++runner.exact_planes_;
        it->second = clash4d::proportional(runner.ek_, plane(eh, fh), plane(eg, fg));
      }
      return it->second;
    }

    // The lines of one AK conquer that AK cannot decide, decided by EK on
    // the same layout of EK's planes (the filter at the level of one line).
    // EK's region is AK's widened to the doubles that enclose it, which
    // contains EK's own region: the formula, simplified by AK over its
    // region with certified signs, holds over EK's region, and over the
    // sliver outside it may only add points inside, which send the pair to
    // EK anyway. When AK's region is exact (grid faces: point intervals) it
    // is EK's own, and a line found is the one EK's run will find (`known`).
    typename Generate_and_test<AK>::Line_decider lines(Filtered_runner& runner, int a, int b, std::size_t s,
                                                       const std::array<bool, 3>& frame, const Plane_layout& layout,
                                                       const Box<AFT, 4>& region)
    {
      CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
      enter(runner, a, b, s, frame);
      ++runner.exact_regions_;
      Box<EFT, 4> outer;
      bool exact = true;
      for (int q = 0; q < 4; ++q) {
        auto lo = CGAL::to_interval(region.lo[q]), hi = CGAL::to_interval(region.hi[q]);
        exact = exact && lo.first == lo.second && hi.first == hi.second;
        outer.set(q, EFT(lo.first), EFT(hi.second));
      }
      struct Conquer {
        Check_stats stats;              // EK's counts stay out of the run's: AK counted the lines
        Generate_and_test<EK> lines;
        Conquer(const EK& k, const std::vector<Hyperplane4<EFT>>& t, const Motion_groups<EFT>& g)
          : lines(k, t, stats, nullptr, &g) {}
      };
      // Lines decide signs only (a point found is made again by EK's own
      // run), so they may use each plane in lowest terms: the arithmetic of
      // a line then starts from coprime integers, not products of the
      // scene's denominators.
      if (lowest.empty()) {
        lowest = table;
        lowest_made.assign(table.size(), 0);
      }
      for (long e : layout.entry)
        if (e >= 0 && !lowest_made[e]) {
          lowest[e] = runner.ek_.in_lowest_terms(table[e]);
          lowest_made[e] = 1;
        }
      auto conquer = std::make_shared<Conquer>(runner.ek_, lowest, groups);
      conquer->lines.adopt(layout, outer);
      return [conquer, exact](const Formula& f, std::size_t i, std::size_t j, std::size_t m, bool& known) {
        CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
        known = exact;
        return conquer->lines.line_has_inside(f, i, j, m);
      };
    }
  };

  // EK's model of object i (what plane tables need), and with need_exact
  // its S-bounds too (what EK's runs need).
  void need_model(int i)
  {
    std::call_once(built_[i], [&] {
      const Scene_object& o = scene_.objects[i];
      emodel_.objects[i].csg = Model_builder<EK>(ek_).build(o.shape);
      emodel_.objects[i].motion = Motion_path<EFT>::build(ek_, o.motion);
    });
  }
  void need_exact(int i)
  {
    need_model(i);
    std::call_once(settled_[i], [&] {
      Check_stats ignored;
      esettled_[i] = settled_bounds(ek_, emodel_.objects[i].csg, ignored, use_sbounds_);
    });
  }

  void finish(Check_stats& stats) const
  {
    stats.exact_fallbacks = fallbacks_.load();
    stats.exact_witness_runs = witness_runs_.load();
    stats.exact_witness_replays = witness_replays_.load();
    stats.exact_regions = exact_regions_.load();
    stats.exact_plane_tests = exact_planes_.load();
    stats.witnesses_by_intervals = witnesses_by_intervals_.load();
  }

  static double seconds_since(std::chrono::steady_clock::time_point t)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }
};

} // namespace clash4d

#endif

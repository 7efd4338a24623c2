// The displacement D(t) of a ROBMOD motion (spec: Motion; paper §3): continuous,
// piecewise linear, D(0) = 0. On segment i, D(t) = velocity[i] t + offset[i].
#ifndef CLASH4D_MODEL_MOTION_PATH_H
#define CLASH4D_MODEL_MOTION_PATH_H

#include "geometry/Kernel_concept.h"
#include "geometry/kernel_ft4.h"
#include "scene/Scene.h"
#include <CGAL/enum.h>
#include <vector>

namespace clash4d {

template <class FT>
struct Motion_path {
  std::vector<FT> times;                 // breakpoints, strictly increasing
  std::vector<Rational> exact_times;     // the same, the scene's own numbers (build)
  std::vector<Vector3<FT>> velocity;     // times.size() + 1 segments
  std::vector<Vector3<FT>> offset;

  template <class K>
  static Motion_path build(const K& k, const Motion& m)
  {
    Motion_path p;
    p.rebuild(k, m);
    return p;
  }

  // This path made again for m, in place: the same numbers as build's, in
  // the vectors' own storage (a prepared scene's moved object, made again
  // per query, allocates nothing once its segments fit). Each vector sized
  // once: growing them was a tenth of a path's making. A throw (a sign the
  // kernel cannot certify) leaves it part made: its holder makes it again
  // (Filtered_runner::motions_changed drops the model, Exact_checker the
  // runners).
  template <class K>
  void rebuild(const K& k, const Motion& m)
  {
    times.clear();
    times.reserve(m.times.size());
    // Each number from the reader's approximation of it where K reads
    // them (read_number: the same number, not converted again).
    for (std::size_t i = 0; i < m.times.size(); ++i)
      times.push_back(read_number(k, m.times[i], m.times_approximated, i));
    if (m.times.empty())
      exact_times.clear();   // most paths: one segment (no assign's work)
    else
      exact_times.assign(m.times.begin(), m.times.end());
    std::size_t n = m.velocities.size();
    velocity.clear();
    velocity.reserve(n);
    const std::vector<Approximation>& va = m.velocities_approximated;
    for (std::size_t i = 0; i < n; ++i) {
      const std::array<Rational, 3>& v = m.velocities[i];
      velocity.push_back(
          {read_number(k, v[0], va, 3 * i), read_number(k, v[1], va, 3 * i + 1), read_number(k, v[2], va, 3 * i + 2)});
    }
    offset.assign(n, Vector3<FT>{FT(0), FT(0), FT(0)});
    // The segment holding t = 0 has offset 0; continuity at each breakpoint T
    // (v_i T + c_i = v_j T + c_j) fixes the others outward from it.
    std::size_t zero = 0;
    while (zero < times.size() && k.sign(times[zero]) == CGAL::NEGATIVE) ++zero;
    for (std::size_t i = zero; i + 1 < n; ++i)
      for (int a = 0; a < 3; ++a)
        offset[i + 1][a] = offset[i][a] + (velocity[i][a] - velocity[i + 1][a]) * times[i];
    for (std::size_t i = zero; i > 0; --i)
      for (int a = 0; a < 3; ++a)
        offset[i - 1][a] = offset[i][a] + (velocity[i][a] - velocity[i - 1][a]) * times[i - 1];
  }

  // The segment whose closed interval holds t (the later one at a
  // breakpoint), with kernel k's signs.
  template <class K>
  std::size_t segment_at(const K& k, const FT& t) const
  {
    std::size_t i = 0;
    while (i < times.size() && !k.less(t, times[i])) ++i;
    return i;
  }

  template <class K>
  Vector3<FT> displacement(const K& k, const FT& t) const
  {
    std::size_t i = segment_at(k, t);
    return point_along(offset[i], t, velocity[i]);
  }

  // The same in FT's own order, for code outside the pipeline (reports,
  // adapters), which has no kernel and no tolerance.
  Vector3<FT> displacement(const FT& t) const
  {
    std::size_t i = 0;
    while (i < times.size() && !(t < times[i])) ++i;
    return point_along(offset[i], t, velocity[i]);
  }
};

} // namespace clash4d

#endif

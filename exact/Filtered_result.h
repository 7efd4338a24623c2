// A pair's result in a filtered run (exact/Filtered_runner.h): the exact
// kernel's numbers, or the approximate kernel's when the interval run made
// the answer and every number of it is a point interval (Interval_kernel::
// has_exact_value), which is then exactly the exact kernel's number. A
// convex pair decided in intervals, the common query, so makes no
// rational: its answer's text is its points' (Interval_kernel::to_text, a
// point's exact dyadic rational; tests/test_numbers.cpp holds that text
// equal to the rational's), where making, moving and dropping the
// rationals of its answer was a ninth of the query's instructions.
// An --earliest answer kept in points keeps its t* in the exact kernel's
// numbers too: run_pairs compares t* across pairs and against its ceiling
// in that kernel.
#ifndef CLASH4D_EXACT_FILTERED_RESULT_H
#define CLASH4D_EXACT_FILTERED_RESULT_H

#include "check/Check_runner.h"
#include <optional>
#include <stdexcept>
#include <variant>

namespace clash4d {

template <class AFT, class EFT>
class Filtered_result {
public:
  // Not colliding (a point result that found nothing: makes no rational).
  Filtered_result() = default;
  // The exact kernel's answer, exchanged in (CGAL's Gmpq has no move:
  // numbers/Number_ops.h, swap_numbers).
  Filtered_result(Pair_result<EFT>&& exact) { make_exact().swap(exact); }
  Filtered_result(Filtered_result&&) = default;
  Filtered_result& operator=(Filtered_result&& o)
  {
    if (o.in_points()) result_ = std::move(std::get<0>(o.result_));
    else make_exact().swap(std::get<1>(o.result_));
    t_star_.swap(o.t_star_);
    return *this;
  }

  // The interval run's answer, kept as it is: the caller has checked that
  // every number the answer prints is a point (Filtered_runner::
  // exact_copyable). An --earliest answer comes with its t* in the exact
  // kernel's numbers, the number its point t* is.
  static Filtered_result of_points(Pair_result<AFT>&& points, const EFT* t_star = nullptr)
  {
    if (points.earliest != (t_star != nullptr))
      throw std::logic_error("internal error: an answer kept in intervals without its exact t*");
    Filtered_result r;
    std::get<0>(r.result_) = std::move(points);
    if (t_star) r.t_star_.emplace(*t_star);
    return r;
  }

  // The exact kernel's answer, to be written in place: the one this holds
  // (zeros when it held none).
  Pair_result<EFT>& make_exact()
  {
    if (in_points()) result_.template emplace<1>();
    return std::get<1>(result_);
  }

  bool in_points() const { return result_.index() == 0; }
  const Pair_result<AFT>& points() const { return std::get<0>(result_); }
  const Pair_result<EFT>& exact() const { return std::get<1>(result_); }

  // The Pair_result protocol of run_pairs (check/Check_runner.h).
  friend bool collides(const Filtered_result& r)
  {
    return std::visit([](const auto& p) { return p.collide; }, r.result_);
  }
  friend const EFT& collision_time(const Filtered_result& r)
  {
    if (!r.in_points()) return r.exact().t_star;
    if (!r.points().earliest) throw std::logic_error("internal error: the time of an answer without --earliest");
    return *r.t_star_;
  }
  // A witness copied into the cells stays a point.
  friend bool close_on_witness(Filtered_result& r)
  {
    return std::visit([](auto& p) { return close_on_witness(p); }, r.result_);
  }

private:
  std::variant<Pair_result<AFT>, Pair_result<EFT>> result_;
  std::optional<EFT> t_star_;   // an --earliest answer kept in points: its t* (none: no number made)
};

} // namespace clash4d

#endif

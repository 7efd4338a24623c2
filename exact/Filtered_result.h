// A pair's result in a filtered run (exact/Filtered_runner.h): the exact
// kernel's numbers, or the approximate kernel's when the interval run made
// the answer and every number of it is a point interval (Interval_kernel::
// has_exact_value), which is then exactly the exact kernel's number. A
// convex pair decided in intervals, the common query, so makes no
// rational: its answer's text is its points' (Interval_kernel::to_text, a
// point's exact dyadic rational; tests/test_numbers.cpp holds that text
// equal to the rational's), where making, moving and dropping the
// rationals of its answer was a ninth of the query's instructions.
// Answers with --earliest are always in the exact kernel's numbers: run_pairs
// compares their t* across pairs and against its ceiling in that kernel.
#ifndef CLASH4D_EXACT_FILTERED_RESULT_H
#define CLASH4D_EXACT_FILTERED_RESULT_H

#include "check/Check_runner.h"
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
    return *this;
  }

  // The interval run's answer, kept as it is: the caller has checked that
  // every number the answer prints is a point (Filtered_runner::
  // exact_copyable), and that it is not an --earliest answer.
  static Filtered_result of_points(const Pair_result<AFT>& points)
  {
    if (points.earliest) throw std::logic_error("internal error: an --earliest answer kept in intervals");
    Filtered_result r;
    std::get<0>(r.result_) = points;
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
    if (r.in_points()) throw std::logic_error("internal error: the time of an answer kept in intervals");
    return r.exact().t_star;
  }
  // A witness copied into the cells stays a point.
  friend bool close_on_witness(Filtered_result& r)
  {
    return std::visit([](auto& p) { return close_on_witness(p); }, r.result_);
  }

private:
  std::variant<Pair_result<AFT>, Pair_result<EFT>> result_;
};

} // namespace clash4d

#endif

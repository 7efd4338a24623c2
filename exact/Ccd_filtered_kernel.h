// The filtered time kernel of the CCD sweep (ccd/Ccd_sweep.h): the exact
// kernel's answers, at interval speed where intervals are sure.
//
// Each of the sweep's questions is one predicate on named polynomials and
// times, filtered on its own (CGAL's Filtered_predicate, at the granularity
// of one sign): it is first asked of the named polynomial in intervals
// (CGAL::Interval_nt, the inputs' tightest enclosures, rounding upward: the
// caller holds the Protector), and only where the interval is not sure, of
// the same named polynomial in rationals (Ccd_rational_kernel, made on the
// first such question). Times stay implicit: 0, 1, or "root i of named
// polynomial g", kept as an enclosure that intervals certified to hold one
// simple root of g and nothing else (opposite sure signs at its ends, a
// derivative surely not zero over it); the exact algebraic number is made
// only when a sign or a comparison asks for it, or for the answer. A root
// where intervals cannot certify that (a double root, a root at 0 or 1, a
// polynomial identically zero in rationals) comes from the rational kernel
// for that one polynomial. So no stage is rerun: the sweep visits the same
// times and takes the same path as in rationals, and its answer is the
// rational kernel's by construction.
#ifndef CLASH4D_EXACT_CCD_FILTERED_KERNEL_H
#define CLASH4D_EXACT_CCD_FILTERED_KERNEL_H

#include "ccd/Ccd_polynomials.h"
#include "ccd/Ccd_sweep.h"
#include "ccd/Swept_boxes.h"
#include "exact/Ccd_rational_kernel.h"
#include "exact/Interval_kernel.h"   // Number_ops<Interval>: enclosed ends of the swept boxes
#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>
#include <optional>
#include <vector>

namespace clash4d {

class Ccd_filtered_kernel {
public:
  using Interval = CGAL::Interval_nt<false>;
  using Protector = CGAL::Protect_FPU_rounding<true>;   // what the intervals need, held by the caller (also when constructing)
  static constexpr bool is_exact = true;

  // 0 or 1 (name < 0), or root `index` of named polynomial `name`.
  struct Time {
    int name = -1, index = 0;
    double value = 0;   // the rational 0 or 1, when name < 0
  };

  // The caller holds the Protector (upward rounding) from here on.
  // separation: the minimum separation D (0: the plain question).
  Ccd_filtered_kernel(const Ccd_query& q, const Rational& separation = Rational(0));

  Ccd_type type() const { return p_.type(); }
  bool separated() const { return p_.separated(); }

  bool swept_boxes_apart();
  // The same predicate's quickest filter, before any kernel or rounding
  // mode: the enclosures' ends compared as doubles (a min or max of ends
  // is exact), the separation's end added and rounded up by one ulp. True
  // only when the boxes are surely apart.
  static bool boxes_surely_apart(const Ccd_query& q, const Rational& separation);
  Time zero() const { return Time{-1, 0, 0.0}; }
  bool is_end(const Time& t) const { return t.name < 0 && t.value == 1; }
  int sign_at(int name, const Time& t);
  int sign_after(int name, const Time& t);
  Time next_time(const Ccd_path& names, const Time& t);

  // The exact number a time is, and the rational kernel (for the answer).
  Algebraic exact(const Time& t);
  Ccd_rational_kernel& rational();
  // How many questions went to rationals (--stats).
  long exact_questions() const { return exact_questions_; }

private:
  struct Root {
    Interval at;                        // holds the root and no other of the polynomial
    int lower_sign = 0;                 // the polynomial's sign at at.inf() (interval-isolated roots)
    std::optional<Algebraic> exact;     // made when asked (given, for roots from rationals)
  };

  const std::vector<Root>& roots(int name);
  Interval enclosure(const Time& t) { return t.name < 0 ? Interval(t.value) : root(t).at; }
  Root& root(const Time& t) { return roots_[static_cast<std::size_t>(t.name)]->at(static_cast<std::size_t>(t.index)); }
  bool refine(const Time& t);
  int compare(const Time& a, const Time& b);

  const Ccd_query& query_;
  Rational separation_;
  Interval separation_at_;   // its enclosure
  Ccd_polynomials<Interval> p_;
  std::optional<Ccd_rational_kernel> rational_;
  std::array<std::optional<std::vector<Root>>, ccd_name::max_count> roots_;
  long exact_questions_ = 0;
};

} // namespace clash4d

#endif

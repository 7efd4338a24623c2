// The kernel concept: what every stage may ask of a kernel K, in one place.
// A kernel bundles a number type with its sign decision (CGAL's kernels
// bundle predicates and constructions the same way). The stages are
// templates over K and take every sign from it, never from FT's own
// comparisons, so a tolerance or a filter applies everywhere.
//
// Required of K (check with `static_assert(is_kernel_v<K>)`):
//
//   typename K::FT                  the number type: a field (+ - * /) with
//                                   FT(int); Number_ops<FT> gives min, max
//                                   and |x| as constructions
//   K::name()                       "rational", "interval", "double", ...
//   K::is_exact                     every sign is the sign of the exact value
//   K::reads_exact_constructions    the model reads the reader's exact hull
//                                   planes and vertices (from_rational)
//                                   instead of computing its own
//   K::grid_bits                    the dyadic grid heuristic choices are
//                                   made on (Kernel_base)
//   k.sign(x)                       CGAL::Sign of x; an approximate kernel
//                                   that cannot certify it throws
//                                   CGAL::Uncertain_conversion_exception
//                                   (CGAL's Uncertain<> discipline: the
//                                   conversion to a certain value fails);
//                                   only a search policy in exact/ catches
//                                   it (search/No_filter.h)
//   k.from_rational(q)              a scene number in FT (exact, rounded,
//                                   or enclosed)
//   k.floor_to_grid(x, bits)        x rounded down to a multiple of 2^-bits
//   k.power_of_two(e)               2^e in FT
//   k.grid_exponent(x)              for x > 0, the e with 2^-e <= x < 2^(1-e)
//   k.to_text(x)                    text for answers and reports
//   k.to_stat(x)                    x as a statistics number (Stat_number)
//
// Provided by Kernel_base (a kernel may refine them, as the interval kernel
// does for speed): compare, less, side, dot_sign, orientation4, is_zero,
// quotient (a / b with b's sign known), largest_component, round_to_grid,
// grid_point, same_on_grid, less_on_grid, possibly_positive and
// possibly_nonnegative (conservative filters), is_nonnegative (box simplification, CGAL::Uncertain<bool>),
// uncertain_sign (CGAL::Uncertain<CGAL::Sign>, indeterminate instead of a throw),
// far_power_of_two (2^e for the far bound of unbounded pairs; a kernel that
// cannot hold it refines it to fail), in_lowest_terms (a positive multiple
// of a hyperplane in the kernel's cheapest numbers: the rational kernel's
// coprime integers; others the plane itself), K::RT and in_ring (the same
// in a ring for division-free elimination, with k.sign on it: the rational
// kernel's GMP integers; others FT), solve_regular (a regular linear
// system's solution: elimination, fraction-free in the rational kernel).
//
// Optional:
//   k.to_rational(x)                exact kernels and double: the value as
//                                   a rational (answers are printed from it)
//   K::reads_exact_rotations        a rotate's matrix is the reader's exact
//                                   one, each entry converted, even where K
//                                   computes its other constructions: two
//                                   rotations sharing an exact column then
//                                   give their faces one plane, not a plane
//                                   and its rounded twin, nearly dependent
//                                   with it, whose lines of three planes
//                                   (search/Null_object_test.h) Cramer's
//                                   rule puts anywhere (reads_exact_rotations_v;
//                                   absent: reads_exact_constructions)
//   typename K::Protector           RAII guard the kernel's arithmetic needs
//                                   (the interval kernel's rounding mode)
//   K::encloses_here()              a filtered runner's approximate kernel:
//                                   whether the Protector's mode takes effect
//                                   on this machine (not under valgrind);
//                                   false, the run is the exact kernel's alone
//   k.from_approximation(a)         a kernel that rounds or encloses the
//                                   scene's numbers: from_rational(a.q),
//                                   the same number, read from the reader's
//                                   approximation a (numbers/Approximation.h)
//                                   instead of converted again
//                                   (read_number; reads_approximations_v)
//   k.exact_value(x), k.has_exact_value(x)
//                                   a filtered runner's approximate kernel:
//                                   the rational that x is, when it is one
//                                   exactly (a point interval); whether it is.
//                                   Its to_text of such an x is that
//                                   rational's text, the exact kernel's: a
//                                   result whose numbers all have exact
//                                   values is printed from them
//                                   (exact/Filtered_result.h)
#ifndef CLASH4D_GEOMETRY_KERNEL_CONCEPT_H
#define CLASH4D_GEOMETRY_KERNEL_CONCEPT_H

#include "numbers/Approximation.h"
#include "numbers/Rational.h"
#include "numbers/Stat_number.h"
#include "geometry/kernel_ft4.h"
#include <CGAL/Uncertain.h>
#include <CGAL/enum.h>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace clash4d {

namespace kernel_concept_detail {

template <class K> const K& k();
template <class K> const typename K::FT& x();
template <class K> const Vector4<typename K::FT>& v();

// Each member's type, or a substitution failure when it is missing (so a
// kernel without it is "not a kernel", not a compile error here).
template <class K>
using Members = std::tuple<
    decltype(k<K>().sign(x<K>())), std::decay_t<decltype(k<K>().from_rational(std::declval<const Rational&>()))>,
    std::decay_t<decltype(k<K>().floor_to_grid(x<K>(), 0))>, std::decay_t<decltype(k<K>().power_of_two(0))>,
    decltype(k<K>().grid_exponent(x<K>())), decltype(k<K>().to_text(x<K>())), decltype(k<K>().to_stat(x<K>())),
    decltype(k<K>().compare(x<K>(), x<K>())), decltype(k<K>().less(x<K>(), x<K>())),
    decltype(k<K>().is_nonnegative(x<K>(), true)), std::decay_t<decltype(k<K>().quotient(x<K>(), x<K>(), CGAL::POSITIVE))>,
    decltype(k<K>().orientation4(v<K>(), v<K>(), v<K>(), v<K>())), decltype(k<K>().largest_component(v<K>()))>;

// The types the members must have, in Members' order.
template <class FT>
using Expected = std::tuple<CGAL::Sign, FT, FT, FT, int, std::string, Stat_number, CGAL::Sign, bool,
                            CGAL::Uncertain<bool>, FT, CGAL::Sign, int>;

template <class K, class = void>
struct has_required : std::false_type {};

template <class K>
struct has_required<K, std::void_t<typename K::FT, decltype(std::declval<const char*&>() = K::name()),
                                   decltype(bool{K::is_exact}), decltype(bool{K::reads_exact_constructions}),
                                   decltype(int{K::grid_bits}), Members<K>>>
  : std::bool_constant<std::is_same_v<Members<K>, Expected<typename K::FT>>> {};

} // namespace kernel_concept_detail

// True when K provides every required member above with its signature.
template <class K>
inline constexpr bool is_kernel_v = kernel_concept_detail::has_required<K>::value;

namespace kernel_concept_detail {
template <class K, class = void>
struct reads_approximations : std::false_type {};
template <class K>
struct reads_approximations<
    K, std::void_t<decltype(std::declval<const K&>().from_approximation(std::declval<const Approximation&>()))>>
  : std::true_type {};
} // namespace kernel_concept_detail

// True when K has the optional from_approximation above.
template <class K>
inline constexpr bool reads_approximations_v = kernel_concept_detail::reads_approximations<K>::value;

namespace kernel_concept_detail {
template <class K, class = void>
struct reads_exact_rotations : std::bool_constant<K::reads_exact_constructions> {};
template <class K>
struct reads_exact_rotations<K, std::void_t<decltype(bool{K::reads_exact_rotations})>>
  : std::bool_constant<K::reads_exact_rotations> {};
} // namespace kernel_concept_detail

// K::reads_exact_rotations above, or K::reads_exact_constructions when K
// does not say.
template <class K>
inline constexpr bool reads_exact_rotations_v = kernel_concept_detail::reads_exact_rotations<K>::value;

// A scene number q in K: read from a, the reader's approximation, when K
// reads those and a was made from q itself (Approximation::of; a may be
// any other number's, or none); otherwise converted. The same number
// either way (from_approximation's contract): the models' solids and
// motions (model/Model_builder.h, model/Motion_path.h).
template <class K>
typename K::FT read_number(const K& k, const Rational& q, const Approximation* a)
{
  if constexpr (reads_approximations_v<K>)
    if (a && a->of(q)) return k.from_approximation(*a);
  return k.from_rational(q);
}
// The same with a's i-th approximation, where a holds one (a solid's or a
// motion's, made for its numbers in order).
template <class K>
typename K::FT read_number(const K& k, const Rational& q, const std::vector<Approximation>& a, std::size_t i)
{
  return read_number(k, q, i < a.size() ? &a[i] : nullptr);
}

} // namespace clash4d

#endif

// The rational kernel (`--number rational`): CGAL's rational over GMP, every
// sign decided exactly. The reference the filtered kernel is held against.
#ifndef CLASH4D_EXACT_RATIONAL_KERNEL_H
#define CLASH4D_EXACT_RATIONAL_KERNEL_H

#include "geometry/Hyperplane4.h"
#include "geometry/Kernel_base.h"
#include "geometry/Kernel_concept.h"
#include "numbers/Rational.h"
#include "numbers/Stat_number.h"
#include <string>

namespace clash4d {

class Rational_kernel : public Kernel_base<Rational_kernel, Rational> {
public:
  static constexpr const char* name() { return "rational"; }
  static constexpr bool reads_exact_constructions = true;   // the same numbers, not computed again (model/Model_builder.h)
  static constexpr bool is_exact = true;
  CGAL::Sign sign(const FT& x) const { return CGAL::sign(x); }
  // The sign of a - b by cross-multiplication (mpq_cmp), without making
  // a - b in lowest terms (an allocation and a gcd).
  CGAL::Sign compare(const FT& a, const FT& b) const { return CGAL::compare(a, b); }
  // The sign of n.p + c over unreduced fractions (sign_of_sum_of_products),
  // without making the value in lowest terms.
  template <std::size_t N>
  CGAL::Sign side(const std::array<FT, N>& n, const FT& c, const std::array<FT, N>& p) const
  {
    return CGAL::Sign(sign_of_sum_of_products(n.data(), p.data(), N, &c));
  }
  FT from_rational(const Rational& q) const { return q; }
  Rational to_rational(const FT& x) const { return x; }
  FT floor_to_grid(const FT& x, int bits) const { return clash4d::floor_to_grid(x, bits); }
  FT power_of_two(int e) const { return clash4d::power_of_two(e); }
  int grid_exponent(const FT& x) const { return clash4d::grid_exponent(x); }
  std::string to_text(const FT& x) const { return to_string(x); }
  Stat_number to_stat(const FT& x) const { return {Stat_number::Kind::Exact, x, 0, 0}; }
  // A positive multiple of h with coprime integer coefficients: the same
  // half-space in smaller numbers.
  Hyperplane4<FT> in_lowest_terms(const Hyperplane4<FT>& h) const
  {
    Rational x[5] = {h.n[0], h.n[1], h.n[2], h.n[3], h.c};
    scale_to_coprime_integers(x, 5);
    return {{x[0], x[1], x[2], x[3]}, x[4]};
  }
  // The same solution as Kernel_base's elimination, fraction-free
  // (numbers/Rational.h): a gcd per coordinate instead of per operation.
  template <std::size_t N>
  std::array<FT, N> solve_regular(const std::array<std::array<FT, N + 1>, N>& M) const
  {
    std::array<FT, N * (N + 1)> m;
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = 0; j <= N; ++j) m[i * (N + 1) + j] = M[i][j];
    std::array<FT, N> x;
    clash4d::solve_regular(m.data(), N, x.data());
    return x;
  }
  // The same integers as GMP's, whose products need no gcd (the ring of
  // division-free elimination, search/Convex_pair.h).
  using RT = mpz_class;
  // sign det(a, b, c, d) with each row scaled to coprime integers: positive
  // multiples of the rows, so the sign is the same, and the cofactor
  // expansion (kernel_ft4.h) then needs no gcd per product.
  CGAL::Sign orientation4(const Vector4<FT>& a, const Vector4<FT>& b, const Vector4<FT>& c, const Vector4<FT>& d) const
  {
    std::array<Vector4<RT>, 4> m;
    const Vector4<FT>* rows[4] = {&a, &b, &c, &d};
    for (int i = 0; i < 4; ++i) coprime_integers(rows[i]->data(), 4, m[i].data());
    return sign(RT(determinant4(m[0], m[1], m[2], m[3])));
  }
  CGAL::Sign sign(const RT& x) const { return CGAL::Sign(sgn(x)); }
  Hyperplane4<RT> in_ring(const Hyperplane4<FT>& h) const
  {
    const Rational x[5] = {h.n[0], h.n[1], h.n[2], h.n[3], h.c};
    RT y[5];
    coprime_integers(x, 5, y);
    return {{std::move(y[0]), std::move(y[1]), std::move(y[2]), std::move(y[3])}, std::move(y[4])};
  }
};

static_assert(is_kernel_v<Rational_kernel>, "Rational_kernel must model the kernel concept (geometry/Kernel_concept.h)");

} // namespace clash4d

#endif

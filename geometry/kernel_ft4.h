// Predicates and constructions written once over the number type FT, as free
// functions on coordinates (in the style of CGAL's kernel_ftC2.h). Nothing
// here divides by a norm or takes a square root: every function is a
// polynomial (or a quotient of polynomials) in its inputs, so the exact
// instantiation stays exact.
#ifndef CLASH4D_GEOMETRY_KERNEL_FT4_H
#define CLASH4D_GEOMETRY_KERNEL_FT4_H

#include "numbers/Rational.h"
#include <array>
#include <type_traits>

namespace clash4d {

template <class FT> using Vector2 = std::array<FT, 2>;
template <class FT> using Vector3 = std::array<FT, 3>;
template <class FT> using Vector4 = std::array<FT, 4>;
template <class FT> using Plane3 = std::array<FT, 4>;    // a x + b y + c z + d <= 0

// a . b; in rationals over unreduced fractions, reduced once
// (numbers/Rational.h, sum_of_products: the same number, without a gcd per
// product and sum).
template <class FT, std::size_t N>
FT dot(const std::array<FT, N>& a, const std::array<FT, N>& b)
{
  if constexpr (std::is_same_v<FT, Rational>) {
    return sum_of_products(a.data(), b.data(), N);
  } else {
    FT s = a[0] * b[0];
    for (std::size_t i = 1; i < N; ++i) s += a[i] * b[i];
    return s;
  }
}

// a . b + c, the value of an affine function: the same operations as
// dot(a, b) + c in doubles and intervals; in rationals one reduction for
// the whole sum (sum_of_products with c added).
template <class FT, std::size_t N>
FT dot_plus(const std::array<FT, N>& a, const std::array<FT, N>& b, const FT& c)
{
  if constexpr (std::is_same_v<FT, Rational>) return sum_of_products(a.data(), b.data(), N, &c);
  else return dot(a, b) + c;
}

// c - a . b: the same operations as c - dot(a, b) in doubles and
// intervals; in rationals one reduction for the whole.
template <class FT, std::size_t N>
FT dot_from(const FT& c, const std::array<FT, N>& a, const std::array<FT, N>& b)
{
  if constexpr (std::is_same_v<FT, Rational>) return difference_of_products(&c, a.data(), b.data(), N);
  else return c - dot(a, b);
}
// -(a . b), likewise.
template <class FT, std::size_t N>
FT negated_dot(const std::array<FT, N>& a, const std::array<FT, N>& b)
{
  if constexpr (std::is_same_v<FT, Rational>) return difference_of_products(nullptr, a.data(), b.data(), N);
  else return -dot(a, b);
}

// -x; in rationals a zero is returned as it is (the same number, without
// the allocation a negation makes; axis-aligned planes are mostly zeros).
template <class FT>
FT negated(const FT& x)
{
  if constexpr (std::is_same_v<FT, Rational>) return x.sign() == CGAL::ZERO ? x : -x;
  else return -x;
}

template <class FT>
Vector3<FT> cross(const Vector3<FT>& a, const Vector3<FT>& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

template <class FT>
FT determinant3(const Vector3<FT>& a, const Vector3<FT>& b, const Vector3<FT>& c)
{
  return dot(a, cross(b, c));
}

// 2x2 minors of rows a, b over columns (i, j), used by the 4D cofactors.
template <class FT>
FT minor2(const Vector4<FT>& a, const Vector4<FT>& b, int i, int j)
{
  return a[i] * b[j] - a[j] * b[i];
}

// The six 2x2 minors of rows a and b, over the column pairs (0,1) (0,2)
// (0,3) (1,2) (1,3) (2,3): all that generalised_cross(a, b, c) and the base
// point of the line of planes a, b, c (search/Null_object_test.h) take
// from a and b together, so a search that fixes a and b over many c makes
// them once. The same expressions as made per line, so the same numbers in
// every kernel. In rationals a and b are kept instead: generalised_cross
// works there on their integers, and a minor is made when asked.
template <class FT>
class Pair_minors {
public:
  Pair_minors() = default;
  Pair_minors(const Vector4<FT>& a, const Vector4<FT>& b) : s_(made(a, b)) {}

  // a_i b_j - a_j b_i, for i < j.
  FT minor(int i, int j) const
  {
    if constexpr (rational) return minor2(s_.a, s_.b, i, j);
    else return s_[static_cast<std::size_t>(i == 0 ? j - 1 : i + j)];
  }

  // The generalised cross product of a, b and c: the vector g with
  // g.x = det(a, b, c, x) for every x, hence orthogonal to a, b and c, and
  // zero exactly when they are dependent (Appendix A without Gram-Schmidt).
  // In rationals, the same numbers without a gcd per product and sum: g is
  // linear in each argument, so with a = A / da (integers over a common
  // denominator, numbers/Rational.h) and likewise b, c, g(a, b, c) =
  // g(A, B, C) / (da db dc), computed in GMP integers and reduced once.
  Vector4<FT> cross(const Vector4<FT>& c) const
  {
    if constexpr (rational) {
      Vector4<mpz_class> A, B, C;
      mpz_class da, db, dc;
      over_common_denominator(s_.a.data(), 4, A.data(), da);
      over_common_denominator(s_.b.data(), 4, B.data(), db);
      over_common_denominator(c.data(), 4, C.data(), dc);
      Pair_minors<mpz_class> AB(A, B);
      Vector4<mpz_class> G = AB.cross(C);
      mpz_class den = da * db * dc;
      return {quotient_of_integers(G[0], den), quotient_of_integers(G[1], den), quotient_of_integers(G[2], den),
              quotient_of_integers(G[3], den)};
    } else {
      // Laplace expansion along the last row x: g_k = (-1)^(k+3) * M_k, with
      // M_k the 3x3 minor of (a, b, c) without column k.
      const FT &m01 = s_[0], &m02 = s_[1], &m03 = s_[2], &m12 = s_[3], &m13 = s_[4], &m23 = s_[5];
      FT M0 = c[1] * m23 - c[2] * m13 + c[3] * m12;   // columns 1,2,3
      FT M1 = c[0] * m23 - c[2] * m03 + c[3] * m02;   // columns 0,2,3
      FT M2 = c[0] * m13 - c[1] * m03 + c[3] * m01;   // columns 0,1,3
      FT M3 = c[0] * m12 - c[1] * m02 + c[2] * m01;   // columns 0,1,2
      return {-M0, M1, -M2, M3};
    }
  }

  // cross(c) for c = +-e_a (positive: +e_a), a region face's normal
  // (search/Null_object_test.h): of each M_k only the term c_a * minor is
  // left, so the same numbers as cross(c) (a product by +-1 or 0 is exact
  // in every kernel) without the twelve products.
  Vector4<FT> cross_axis(int a, bool positive) const
  {
    auto m = [&](int i, int j) {
      FT x = minor(i, j);
      return positive ? x : negated(x);
    };
    FT z(0);
    switch (a) {
    case 0: return {z, m(2, 3), negated(m(1, 3)), m(1, 2)};
    case 1: return {negated(m(2, 3)), z, m(0, 3), negated(m(0, 2))};
    case 2: return {m(1, 3), negated(m(0, 3)), z, m(0, 1)};
    default: return {negated(m(1, 2)), m(0, 2), negated(m(0, 1)), z};
    }
  }

private:
  static constexpr bool rational = std::is_same_v<FT, Rational>;
  struct Rows {
    Vector4<FT> a, b;
  };
  // Copies of handles in rationals (no number made); the minors otherwise.
  std::conditional_t<rational, Rows, std::array<FT, 6>> s_{};

  static auto made(const Vector4<FT>& a, const Vector4<FT>& b)
  {
    if constexpr (rational) {
      return Rows{a, b};
    } else {
      return std::array<FT, 6>{minor2(a, b, 0, 1), minor2(a, b, 0, 2), minor2(a, b, 0, 3),
                               minor2(a, b, 1, 2), minor2(a, b, 1, 3), minor2(a, b, 2, 3)};
    }
  }
};

// The generalised cross product of three 4-vectors (Pair_minors::cross).
template <class FT>
Vector4<FT> generalised_cross(const Vector4<FT>& a, const Vector4<FT>& b, const Vector4<FT>& c)
{
  return Pair_minors<FT>(a, b).cross(c);
}

// In rationals, as generalised_cross: det(A, B, C, D) / (da db dc dd).
template <class FT>
FT determinant4(const Vector4<FT>& a, const Vector4<FT>& b, const Vector4<FT>& c, const Vector4<FT>& d)
{
  if constexpr (std::is_same_v<FT, Rational>) {
    std::array<Vector4<mpz_class>, 4> X;
    std::array<mpz_class, 4> den;
    const Vector4<FT>* rows[4] = {&a, &b, &c, &d};
    for (int i = 0; i < 4; ++i) over_common_denominator(rows[i]->data(), 4, X[i].data(), den[i]);
    return quotient_of_integers(determinant4(X[0], X[1], X[2], X[3]), mpz_class(den[0] * den[1] * den[2] * den[3]));
  } else {
    return dot(generalised_cross(a, b, c), d);
  }
}

// p + s * d
template <class FT, std::size_t N>
std::array<FT, N> point_along(const std::array<FT, N>& p, const FT& s, const std::array<FT, N>& d)
{
  std::array<FT, N> out;
  for (std::size_t i = 0; i < N; ++i) out[i] = p[i] + s * d[i];
  return out;
}

} // namespace clash4d

#endif

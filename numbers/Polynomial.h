// A polynomial in one variable over any number type (double, interval,
// rational), of degree below Capacity, its coefficients from the constant
// term up. The CCD queries' functions of time (ccd/) are built from the
// vertices' linear motions by sums and products, and evaluated or
// differentiated by the kernels; the kernels decide every sign.
#ifndef CLASH4D_NUMBERS_POLYNOMIAL_H
#define CLASH4D_NUMBERS_POLYNOMIAL_H

#include <algorithm>
#include <array>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace clash4d {

template <class FT, int Capacity = 7>
class Polynomial {
public:
  static constexpr int capacity = Capacity;

  Polynomial() = default;
  explicit Polynomial(const FT& c0)
  {
    size_ = 1;
    if constexpr (owns_memory) c_ = {c0};   // copies: no number made first
    else c_[0] = c0;
  }
  // c[0] + c[1] t + ...: at most Capacity coefficients.
  explicit Polynomial(const std::vector<FT>& c)
  {
    if (c.size() > static_cast<std::size_t>(Capacity))
      throw std::logic_error("Polynomial: more coefficients than the capacity");
    resize(static_cast<int>(c.size()));
    std::copy(c.begin(), c.end(), c_.begin());
  }
  // The same, taking the numbers over (GMP's: none is made again).
  explicit Polynomial(std::vector<FT>&& c)
  {
    if (c.size() > static_cast<std::size_t>(Capacity))
      throw std::logic_error("Polynomial: more coefficients than the capacity");
    size_ = static_cast<int>(c.size());
    if constexpr (owns_memory) c_ = std::move(c);
    else std::copy(c.begin(), c.end(), c_.begin());
  }
  // c0 + c1 t: a coordinate moving linearly.
  Polynomial(const FT& c0, const FT& c1)
  {
    size_ = 2;
    if constexpr (owns_memory) {
      c_ = {c0, c1};
    } else {
      c_[0] = c0;
      c_[1] = c1;
    }
  }

  // The coefficients stored; the degree is at most size() - 1 (a leading
  // coefficient may be zero: only a kernel can tell).
  int size() const { return size_; }
  const FT& operator[](int i) const { return c_[i]; }
  FT& operator[](int i) { return c_[i]; }

  friend Polynomial operator+(const Polynomial& a, const Polynomial& b) { return combine(a, b, 1); }
  friend Polynomial operator-(const Polynomial& a, const Polynomial& b) { return combine(a, b, -1); }
  friend Polynomial operator-(const Polynomial& a)
  {
    Polynomial r;
    r.resize(a.size_);
    for (int i = 0; i < a.size_; ++i) r.c_[i] = -a.c_[i];
    return r;
  }
  friend Polynomial operator*(const Polynomial& a, const Polynomial& b)
  {
    Polynomial r;
    if (a.size_ == 0 || b.size_ == 0) return r;
    if (a.size_ + b.size_ - 1 > Capacity) throw std::logic_error("Polynomial: a product beyond the capacity");
    r.resize(a.size_ + b.size_ - 1);
    for (int i = 0; i < r.size_; ++i) r.c_[i] = FT(0);
    for (int i = 0; i < a.size_; ++i)
      for (int j = 0; j < b.size_; ++j) r.c_[i + j] += a.c_[i] * b.c_[j];
    return r;
  }
  Polynomial& operator+=(const Polynomial& b) { return *this = *this + b; }
  Polynomial& operator-=(const Polynomial& b) { return *this = *this - b; }

  friend Polynomial operator*(const FT& s, const Polynomial& a)
  {
    Polynomial r = a;
    for (int i = 0; i < r.size_; ++i) r.c_[i] = s * a.c_[i];
    return r;
  }

  Polynomial derivative() const
  {
    Polynomial r;
    r.resize(std::max(size_ - 1, 0));
    for (int i = 1; i < size_; ++i) r.c_[i - 1] = FT(i) * c_[i];
    return r;
  }

  // The value at x by Horner's rule, in X (FT, or a wider type such as an
  // interval around a time).
  template <class X>
  X at(const X& x) const
  {
    if (size_ == 0) return X(0);
    X v = X(c_[size_ - 1]);
    for (int i = size_ - 2; i >= 0; --i) v = v * x + X(c_[i]);
    return v;
  }

  // The coefficients as a vector (the algebraic numbers' input).
  std::vector<FT> coefficients() const { return std::vector<FT>(c_.begin(), c_.begin() + size_); }

private:
  static Polynomial combine(const Polynomial& a, const Polynomial& b, int sign)
  {
    Polynomial r;
    r.resize(std::max(a.size_, b.size_));
    for (int i = 0; i < r.size_; ++i) {
      if (i < a.size_ && i < b.size_) r.c_[i] = sign > 0 ? FT(a.c_[i] + b.c_[i]) : FT(a.c_[i] - b.c_[i]);
      else if (i < a.size_) r.c_[i] = a.c_[i];
      else r.c_[i] = sign > 0 ? b.c_[i] : FT(-b.c_[i]);
    }
    return r;
  }

  // Numbers that own memory (GMP's) are kept in a vector of size_ of them:
  // an array would make Capacity of them for every polynomial, most unread.
  static constexpr bool owns_memory = !std::is_trivially_copyable_v<FT>;
  using Storage = std::conditional_t<owns_memory, std::vector<FT>, std::array<FT, Capacity>>;

  void resize(int n)
  {
    size_ = n;
    if constexpr (owns_memory) c_.resize(n);
  }

  Storage c_;   // c_[0 .. size_) hold the coefficients; the rest is unread
  int size_ = 0;
};

} // namespace clash4d

#endif

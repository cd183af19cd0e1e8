#pragma once
/// @file InlineVector.h
/// @brief A vector of doubles with fixed inline capacity: the coefficient store of the
/// univariate Bernstein polynomials, whose degrees are bounded (products of degree ≤ 3·20),
/// so footpoint queries do no heap allocation at all.

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <initializer_list>
#include <stdexcept>

namespace exactmat
{

template <std::size_t Capacity>
class InlineVector
{
public:
  InlineVector() = default;
  InlineVector(std::initializer_list<double> values) { assign(values.begin(), values.end()); }
  // Copies move only the coefficients in use, not the whole capacity.
  InlineVector(const InlineVector& other) { assign(other.begin(), other.end()); }
  InlineVector& operator=(const InlineVector& other)
  {
    if (this != &other)
      assign(other.begin(), other.end());
    return *this;
  }

  std::size_t size() const { return Size; }
  bool empty() const { return Size == 0; }
  void resize(std::size_t n, double value = 0.0)
  {
    check(n);
    std::fill(Data + std::min(n, Size), Data + n, value);
    Size = n;
  }
  void assign(std::size_t n, double value)
  {
    check(n);
    std::fill(Data, Data + n, value);
    Size = n;
  }
  /// n elements whose values the caller writes next (no fill).
  void resizeForOverwrite(std::size_t n)
  {
    check(n);
    Size = n;
  }
  template <typename It>
  void assign(It first, It last)
  {
    const std::size_t n = static_cast<std::size_t>(last - first);
    check(n);
    std::copy(first, last, Data);
    Size = n;
  }
  void push_back(double v)
  {
    check(Size + 1);
    Data[Size++] = v;
  }
  double& operator[](std::size_t i) { return Data[i]; }
  double operator[](std::size_t i) const { return Data[i]; }
  double front() const { return Data[0]; }
  double back() const { return Data[Size - 1]; }
  double* begin() { return Data; }
  double* end() { return Data + Size; }
  const double* begin() const { return Data; }
  const double* end() const { return Data + Size; }
  double* data() { return Data; }

private:
  static void check(std::size_t n)
  {
    if (n > Capacity)
      throw std::length_error("InlineVector: polynomial degree beyond the kernel's bound");
  }
  double Data[Capacity];
  std::size_t Size = 0;
};

} // namespace exactmat

#pragma once
/// @file Bernstein.h
/// @brief Polynomials in Bernstein form on [0,1] (univariate and tensor-product).
///
/// The closest-point solvers write the stationarity conditions of the squared distance as
/// polynomials in Bernstein form. Their coefficients bound the polynomial (convex hull
/// property), so a sub-interval whose coefficients all have one sign holds no root, and one
/// whose coefficient sequence changes sign exactly once holds exactly one (Descartes' rule
/// for the Bernstein basis). That turns "find every footpoint" into a bounded subdivision.

#include "common/InlineVector.h"

#include <array>
#include <cmath>
#include <vector>

namespace exactmat
{

namespace detail
{
/// Pascal's triangle up to the largest degree any product of polynomials here reaches,
/// built by the compiler: binomial() is in every curve evaluation and emptiness test, and
/// a call with a guarded static table cost 13% of an ellipse's trace.
constexpr int BinomialRows = 128;
struct BinomialTable
{
  double c[BinomialRows][BinomialRows] = {};
  constexpr BinomialTable()
  {
    for (int n = 0; n < BinomialRows; ++n)
    {
      c[n][0] = c[n][n] = 1.0;
      for (int k = 1; k < n; ++k)
        c[n][k] = c[n - 1][k - 1] + c[n - 1][k];
    }
  }
};
inline constexpr BinomialTable Binomials{};
} // namespace detail

/// Binomial coefficient C(n, k) as a double (n ≤ 60 is exact enough for any degree we
/// allow); 0 outside the triangle.
inline double binomial(int n, int k)
{
  return (k < 0 || k > n || n >= detail::BinomialRows) ? 0.0 : detail::Binomials.c[n][k];
}

/// Bernstein basis B_{i,p}(t), i = 0..p, and its first and second derivatives.
/// `out` must hold 3·(p+1) doubles: values, then first, then second derivatives.
void bernsteinWithDerivatives(int p, double t, double* out);

/// The two halves of Σ c_k B_{k,n}(t) at t (de Casteljau) into left and right (n + 1
/// coefficients each; n ≤ 95): the arrays' own form of BernsteinPoly::split, for tests
/// that subdivide on the stack.
void splitBernstein(const double* c, int n, double t, double* left, double* right);

/// A univariate polynomial Σ c_i B_{i,n}(t), n = c.size() − 1 (n ≤ 95).
struct BernsteinPoly
{
  InlineVector<96> c;

  int degree() const { return static_cast<int>(c.size()) - 1; }
  double operator()(double t) const;
  /// The value at t and, in `slope`, the derivative (one de Casteljau pass).
  double valueAndSlope(double t, double& slope) const;
  BernsteinPoly derivative() const;
  BernsteinPoly elevatedTo(int n) const;
  /// The same polynomial re-parameterised over [a,b] ⊂ [0,1] (de Casteljau twice).
  BernsteinPoly restrictedTo(double a, double b) const;
  void split(double t, BernsteinPoly& left, BernsteinPoly& right) const;
  /// Number of sign changes of the coefficient sequence, ignoring coefficients with
  /// |c| ≤ zero. An upper bound on the number of roots in (0,1), of the same parity.
  int signChanges(double zero) const;
  double maxAbs() const;
};

BernsteinPoly operator*(const BernsteinPoly& a, const BernsteinPoly& b);
BernsteinPoly operator+(const BernsteinPoly& a, const BernsteinPoly& b);
BernsteinPoly operator-(const BernsteinPoly& a, const BernsteinPoly& b);
BernsteinPoly operator*(double s, const BernsteinPoly& a);

/// A tensor-product polynomial Σ c_ij B_{i,nu}(u) B_{j,nv}(v); c[i*(nv+1)+j].
struct BernsteinPoly2
{
  int nu = 0, nv = 0;
  std::vector<double> c;

  BernsteinPoly2() = default;
  BernsteinPoly2(int nu_, int nv_)
    : nu(nu_)
    , nv(nv_)
    , c((nu_ + 1) * (nv_ + 1), 0.0)
  {
  }
  /// Degrees (nu_, nv_) with coefficients to be written next: the storage is kept, so a
  /// polynomial reused box after box (the subdivision searches' scratch) allocates once.
  void reshape(int nu_, int nv_)
  {
    nu = nu_;
    nv = nv_;
    c.resize((nu_ + 1) * (nv_ + 1));
  }
  double& at(int i, int j) { return c[i * (nv + 1) + j]; }
  double at(int i, int j) const { return c[i * (nv + 1) + j]; }
  double operator()(double u, double v) const;
  /// h, h_u, h_v, h_uu, h_uv, h_vv at (u, v) in one pass over the coefficients (degrees
  /// ≤ 64; no allocation): the convexity tests' Newton steps.
  std::array<double, 6> jet(double u, double v) const;
  BernsteinPoly2 derivativeU() const;
  BernsteinPoly2 derivativeV() const;
  BernsteinPoly2 elevatedTo(int mu, int mv) const;
  /// Re-parameterised over [u0,u1]×[v0,v1] ⊂ [0,1]².
  BernsteinPoly2 restrictedTo(double u0, double u1, double v0, double v1) const;
  /// The four parts at (su, sv), bit-identical to restrictedTo on each (0 … su … 1 in
  /// both): [u0 v0, u1 v0, u0 v1, u1 v1] with u0 = [0, su], u1 = [su, 1]. One split per
  /// column and two per row instead of four of each: the subdivision search's step.
  void quarter(double su, double sv, BernsteinPoly2 (&parts)[4]) const;
  /// The least and largest Bernstein coefficient of derivativeU() (alongU) or
  /// derivativeV(), bit-identical to theirs, without building it: bounds of the derivative.
  void derivativeBounds(bool alongU, double& lo, double& hi) const;
  /// The parts [0, t] and [t, 1] in u (alongU) or in v: one split per column or row.
  /// `lower` and `upper` keep their storage (neither may be *this).
  void split(double t, bool alongU, BernsteinPoly2& lower, BernsteinPoly2& upper) const;
  /// True when every coefficient is > zero or every one is < −zero: no root in the box.
  bool hasStrictSign(double zero) const;
  double maxAbs() const;
  /// Divides by the side's factor (u or 1 − u with `alongU`, else v or 1 − v; `atOne`
  /// picks the side at 1) when every coefficient on that side is within `zero`, the
  /// polynomial's rounding: its zeros in the open box stay, the side's own drop out (a
  /// query at a patch's pole makes the whole collapsed side stationary). Returns the
  /// largest factor a coefficient was multiplied by (the degree), 0 when not divided.
  int divideBySide(bool alongU, bool atOne, double zero);
};

BernsteinPoly2 operator*(const BernsteinPoly2& a, const BernsteinPoly2& b);
BernsteinPoly2 operator+(const BernsteinPoly2& a, const BernsteinPoly2& b);
BernsteinPoly2 operator-(const BernsteinPoly2& a, const BernsteinPoly2& b);
BernsteinPoly2 operator*(double s, const BernsteinPoly2& a);

} // namespace exactmat

#include "Bernstein.h"

#include <algorithm>
#include <stdexcept>

namespace exactmat
{

void bernsteinWithDerivatives(int p, double t, double* out)
{
  // Build the triangle of Bernstein values degree by degree and keep the last three rows:
  // B' and B'' of degree p are differences of the rows of degree p−1 and p−2. Every entry
  // read below is written first (row k fills 0 … k), so the rows are not cleared: this runs
  // at every curve evaluation, and clearing 1.5 KB cost more than the triangle itself.
  double rows[3][64];
  double* prev2 = rows[0];
  double* prev1 = rows[1];
  double* cur = rows[2];
  const double s = 1.0 - t;
  double* value = out;
  double* d1 = out + (p + 1);
  double* d2 = out + 2 * (p + 1);
  cur[0] = 1.0;
  for (int k = 1; k <= p; ++k)
  {
    std::swap(prev2, prev1);
    std::swap(prev1, cur);
    // The last row (degree p) goes straight to the output: no copy (a memmove call per
    // evaluation for a handful of values).
    if (k == p)
      cur = value;
    cur[0] = s * prev1[0];
    for (int i = 1; i < k; ++i)
    {
      cur[i] = s * prev1[i] + t * prev1[i - 1];
    }
    cur[k] = t * prev1[k - 1];
  }
  if (p == 0)
    value[0] = 1.0;
  for (int i = 0; i <= p; ++i)
  {
    d1[i] = 0.0;
    d2[i] = 0.0;
  }
  if (p >= 1)
  {
    for (int i = 0; i <= p; ++i)
    {
      const double a = (i >= 1) ? prev1[i - 1] : 0.0;
      const double b = (i <= p - 1) ? prev1[i] : 0.0;
      d1[i] = p * (a - b);
    }
  }
  if (p >= 2)
  {
    for (int i = 0; i <= p; ++i)
    {
      const double a = (i >= 2) ? prev2[i - 2] : 0.0;
      const double b = (i >= 1 && i - 1 <= p - 2) ? prev2[i - 1] : 0.0;
      const double c = (i <= p - 2) ? prev2[i] : 0.0;
      d2[i] = p * (p - 1) * (a - 2.0 * b + c);
    }
  }
}

// ---------------------------------------------------------------------------------------
// univariate

double BernsteinPoly::operator()(double t) const
{
  double slope;
  return valueAndSlope(t, slope);
}

double BernsteinPoly::valueAndSlope(double t, double& slope) const
{
  // de Casteljau in a stack buffer (the innermost loop of every footpoint query) down to
  // the last two points, which give the derivative and, blended, the value.
  const int n = degree();
  if (n < 1)
  {
    slope = 0.0;
    return n < 0 ? 0.0 : c[0];
  }
  double b[96];
  std::copy(c.begin(), c.end(), b);
  const double s = 1.0 - t;
  for (int r = 1; r < n; ++r)
    for (int i = 0; i <= n - r; ++i)
      b[i] = s * b[i] + t * b[i + 1];
  slope = n * (b[1] - b[0]);
  return s * b[0] + t * b[1];
}

BernsteinPoly BernsteinPoly::derivative() const
{
  const int n = degree();
  BernsteinPoly d;
  if (n <= 0)
  {
    d.c = { 0.0 };
    return d;
  }
  d.c.resize(n);
  for (int i = 0; i < n; ++i)
  {
    d.c[i] = n * (c[i + 1] - c[i]);
  }
  return d;
}

BernsteinPoly BernsteinPoly::elevatedTo(int m) const
{
  const int n = degree();
  if (m <= n)
  {
    return *this;
  }
  BernsteinPoly e;
  e.c.assign(m + 1, 0.0);
  // Elevation by (m−n) at once: e_k = Σ_i C(n,i)C(m−n,k−i)/C(m,k) c_i.
  for (int k = 0; k <= m; ++k)
  {
    double s = 0.0;
    for (int i = std::max(0, k - (m - n)); i <= std::min(n, k); ++i)
    {
      s += binomial(n, i) * binomial(m - n, k - i) * c[i];
    }
    e.c[k] = s / binomial(m, k);
  }
  return e;
}

void splitBernstein(const double* c, int n, double t, double* left, double* right)
{
  double b[96];
  std::copy(c, c + n + 1, b);
  const double s = 1.0 - t;
  left[0] = b[0];
  right[n] = b[n];
  for (int k = 1; k <= n; ++k)
  {
    for (int i = 0; i <= n - k; ++i)
      b[i] = s * b[i] + t * b[i + 1];
    left[k] = b[0];
    right[n - k] = b[n - k];
  }
}

void BernsteinPoly::split(double t, BernsteinPoly& left, BernsteinPoly& right) const
{
  // The innermost step of every subdivision search (2D footpoints split each row and
  // column of two bivariate polynomials per box): plain loops on a stack copy, no
  // library copy or fill calls for a handful of coefficients.
  const int n = degree();
  if (n < 0)
  {
    left.c.assign(0, 0.0);
    right.c.assign(0, 0.0);
    return;
  }
  left.c.resizeForOverwrite(n + 1);
  right.c.resizeForOverwrite(n + 1);
  splitBernstein(c.begin(), n, t, left.c.data(), right.c.data());
}

BernsteinPoly BernsteinPoly::restrictedTo(double a, double b) const
{
  BernsteinPoly l, r, l2, r2;
  if (b < 1.0)
  {
    split(b, l, r);
  }
  else
  {
    l = *this;
  }
  if (a <= 0.0)
  {
    return l;
  }
  l.split(a / b, l2, r2);
  return r2;
}

int BernsteinPoly::signChanges(double zero) const
{
  int changes = 0;
  int last = 0;
  for (double v : c)
  {
    const int s = (v > zero) ? 1 : ((v < -zero) ? -1 : 0);
    if (s != 0)
    {
      if (last != 0 && s != last)
      {
        ++changes;
      }
      last = s;
    }
  }
  return changes;
}

double BernsteinPoly::maxAbs() const
{
  double m = 0.0;
  for (double v : c)
  {
    m = std::max(m, std::abs(v));
  }
  return m;
}

BernsteinPoly operator*(const BernsteinPoly& a, const BernsteinPoly& b)
{
  const int m = a.degree(), n = b.degree();
  BernsteinPoly p;
  p.c.assign(m + n + 1, 0.0);
  for (int i = 0; i <= m; ++i)
  {
    for (int j = 0; j <= n; ++j)
    {
      p.c[i + j] += binomial(m, i) * binomial(n, j) * a.c[i] * b.c[j];
    }
  }
  for (int k = 0; k <= m + n; ++k)
  {
    p.c[k] /= binomial(m + n, k);
  }
  return p;
}

namespace
{
BernsteinPoly combine(const BernsteinPoly& a, const BernsteinPoly& b, double sb)
{
  const int n = std::max(a.degree(), b.degree());
  BernsteinPoly ea = a.elevatedTo(n), eb = b.elevatedTo(n);
  for (int i = 0; i <= n; ++i)
  {
    ea.c[i] += sb * eb.c[i];
  }
  return ea;
}
} // namespace

BernsteinPoly operator+(const BernsteinPoly& a, const BernsteinPoly& b)
{
  return combine(a, b, 1.0);
}

BernsteinPoly operator-(const BernsteinPoly& a, const BernsteinPoly& b)
{
  return combine(a, b, -1.0);
}

BernsteinPoly operator*(double s, const BernsteinPoly& a)
{
  BernsteinPoly r = a;
  for (double& v : r.c)
  {
    v *= s;
  }
  return r;
}

// ---------------------------------------------------------------------------------------
// tensor product

namespace
{
// Applies a univariate operation to every row (fixed i, along v) or column (fixed j, along u).
template <typename Op>
BernsteinPoly2 mapColumns(const BernsteinPoly2& a, int newNu, Op op)
{
  BernsteinPoly2 r(newNu, a.nv);
  BernsteinPoly col;
  col.c.resize(a.nu + 1);
  for (int j = 0; j <= a.nv; ++j)
  {
    for (int i = 0; i <= a.nu; ++i)
    {
      col.c[i] = a.at(i, j);
    }
    const BernsteinPoly out = op(col);
    for (int i = 0; i <= newNu; ++i)
    {
      r.at(i, j) = out.c[i];
    }
  }
  return r;
}

template <typename Op>
BernsteinPoly2 mapRows(const BernsteinPoly2& a, int newNv, Op op)
{
  BernsteinPoly2 r(a.nu, newNv);
  BernsteinPoly row;
  row.c.resize(a.nv + 1);
  for (int i = 0; i <= a.nu; ++i)
  {
    for (int j = 0; j <= a.nv; ++j)
    {
      row.c[j] = a.at(i, j);
    }
    const BernsteinPoly out = op(row);
    for (int j = 0; j <= newNv; ++j)
    {
      r.at(i, j) = out.c[j];
    }
  }
  return r;
}
} // namespace

double BernsteinPoly2::operator()(double u, double v) const
{
  BernsteinPoly col;
  col.c.resize(nu + 1);
  BernsteinPoly row;
  row.c.resize(nv + 1);
  for (int i = 0; i <= nu; ++i)
  {
    for (int j = 0; j <= nv; ++j)
    {
      row.c[j] = at(i, j);
    }
    col.c[i] = row(v);
  }
  return col(u);
}

BernsteinPoly2 BernsteinPoly2::derivativeU() const
{
  if (nu == 0)
  {
    return BernsteinPoly2(0, nv);
  }
  return mapColumns(*this, nu - 1, [](const BernsteinPoly& p) { return p.derivative(); });
}

BernsteinPoly2 BernsteinPoly2::derivativeV() const
{
  if (nv == 0)
  {
    return BernsteinPoly2(nu, 0);
  }
  return mapRows(*this, nv - 1, [](const BernsteinPoly& p) { return p.derivative(); });
}

BernsteinPoly2 BernsteinPoly2::elevatedTo(int mu, int mv) const
{
  BernsteinPoly2 r = *this;
  if (mu > nu)
  {
    r = mapColumns(r, mu, [mu](const BernsteinPoly& p) { return p.elevatedTo(mu); });
  }
  if (mv > nv)
  {
    r = mapRows(r, mv, [mv](const BernsteinPoly& p) { return p.elevatedTo(mv); });
  }
  return r;
}

BernsteinPoly2 BernsteinPoly2::restrictedTo(double u0, double u1, double v0, double v1) const
{
  BernsteinPoly2 r =
    mapColumns(*this, nu, [u0, u1](const BernsteinPoly& p) { return p.restrictedTo(u0, u1); });
  return mapRows(r, nv, [v0, v1](const BernsteinPoly& p) { return p.restrictedTo(v0, v1); });
}

void BernsteinPoly2::split(double t, bool alongU, BernsteinPoly2& lower, BernsteinPoly2& upper) const
{
  const BernsteinPoly2& a = *this;
  lower.reshape(a.nu, a.nv);
  upper.reshape(a.nu, a.nv);
  const int n = alongU ? a.nu : a.nv, lines = alongU ? a.nv + 1 : a.nu + 1;
  auto at = [&](int line, int k) { return alongU ? k * (a.nv + 1) + line : line * (a.nv + 1) + k; };
  BernsteinPoly coefficients, l, r;
  coefficients.c.resize(n + 1);
  for (int line = 0; line < lines; ++line)
  {
    for (int k = 0; k <= n; ++k)
      coefficients.c[k] = a.c[at(line, k)];
    coefficients.split(t, l, r);
    for (int k = 0; k <= n; ++k)
    {
      lower.c[at(line, k)] = l.c[k];
      upper.c[at(line, k)] = r.c[k];
    }
  }
}

void BernsteinPoly2::quarter(double su, double sv, BernsteinPoly2 (&parts)[4]) const
{
  // restrictedTo(0, s) keeps the left part of split(s) and restrictedTo(s, 1) the right
  // part of split(s / 1): one split gives both, operation for operation.
  // Per-thread halves: the search quarters a box at every level, and allocating them
  // each time was most of its cost under a sanitizer.
  thread_local BernsteinPoly2 lowerU, upperU;
  split(su, true, lowerU, upperU);
  lowerU.split(sv, false, parts[0], parts[2]);
  upperU.split(sv, false, parts[1], parts[3]);
}

void BernsteinPoly2::derivativeBounds(bool alongU, double& lo, double& hi) const
{
  const int n = alongU ? nu : nv;
  lo = hi = 0.0;
  if (n == 0)
    return;
  lo = INFINITY;
  hi = -INFINITY;
  for (int i = 0; i + (alongU ? 1 : 0) <= nu; ++i)
  {
    for (int j = 0; j + (alongU ? 0 : 1) <= nv; ++j)
    {
      const double d = n * (alongU ? at(i + 1, j) - at(i, j) : at(i, j + 1) - at(i, j));
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
  }
}

namespace
{
// The Bernstein basis of degree n ≤ 64 at t with its first and second derivatives.
void bernsteinJet(int n, double t, double* b, double* d1, double* d2)
{
  double lower2[65] = { 0.0 }, lower1[65] = { 0.0 };
  b[0] = 1.0;
  for (int k = 1; k <= n; ++k)
  {
    if (k == n - 1)
      std::copy(b, b + k, lower2);
    if (k == n)
      std::copy(b, b + k, lower1);
    b[k] = t * b[k - 1];
    for (int j = k - 1; j > 0; --j)
      b[j] = (1.0 - t) * b[j] + t * b[j - 1];
    b[0] *= 1.0 - t;
  }
  if (n == 1)
    lower2[0] = 0.0;
  for (int i = 0; i <= n; ++i)
  {
    auto at = [](const double* c, int k, int size) { return k >= 0 && k < size ? c[k] : 0.0; };
    d1[i] = n * (at(lower1, i - 1, n) - at(lower1, i, n));
    d2[i] = n * (n - 1.0) * (at(lower2, i - 2, n - 1) - 2.0 * at(lower2, i - 1, n - 1) + at(lower2, i, n - 1));
  }
}
} // namespace

std::array<double, 6> BernsteinPoly2::jet(double u, double v) const
{
  if (nu > 64 || nv > 64)
    throw std::length_error("BernsteinPoly2::jet: degree beyond 64");
  double bu[65], du[65], ddu[65], bv[65], dv[65], ddv[65];
  bernsteinJet(nu, u, bu, du, ddu);
  bernsteinJet(nv, v, bv, dv, ddv);
  std::array<double, 6> jet{};
  for (int i = 0; i <= nu; ++i)
  {
    double r0 = 0.0, r1 = 0.0, r2 = 0.0;
    for (int j = 0; j <= nv; ++j)
    {
      const double cij = at(i, j);
      r0 += cij * bv[j];
      r1 += cij * dv[j];
      r2 += cij * ddv[j];
    }
    jet[0] += bu[i] * r0;
    jet[1] += du[i] * r0;
    jet[2] += bu[i] * r1;
    jet[3] += ddu[i] * r0;
    jet[4] += du[i] * r1;
    jet[5] += bu[i] * r2;
  }
  return jet;
}

bool BernsteinPoly2::hasStrictSign(double zero) const
{
  bool allPositive = true, allNegative = true;
  for (double v : c)
  {
    allPositive = allPositive && v > zero;
    allNegative = allNegative && v < -zero;
  }
  return allPositive || allNegative;
}

int BernsteinPoly2::divideBySide(bool alongU, bool atOne, double zero)
{
  const int n = alongU ? nu : nv;
  if (n == 0)
  {
    return 0;
  }
  const int side = atOne ? n : 0;
  for (int k = 0; k <= (alongU ? nv : nu); ++k)
  {
    if (std::abs(alongU ? at(side, k) : at(k, side)) > zero)
    {
      return 0;
    }
  }
  // c_k B_k^n(t) = t · (n / k) c_k B_{k−1}^{n−1}(t) = (1 − t) · (n / (n − k)) c_k B_k^{n−1}(t).
  BernsteinPoly2 q(alongU ? nu - 1 : nu, alongU ? nv : nv - 1);
  for (int i = 0; i <= q.nu; ++i)
  {
    for (int j = 0; j <= q.nv; ++j)
    {
      const int k = alongU ? i : j;
      const int from = atOne ? k : k + 1;
      const double factor = atOne ? double(n) / (n - k) : double(n) / (k + 1);
      q.at(i, j) = factor * (alongU ? at(from, j) : at(i, from));
    }
  }
  *this = std::move(q);
  return n;
}

double BernsteinPoly2::maxAbs() const
{
  double m = 0.0;
  for (double v : c)
  {
    m = std::max(m, std::abs(v));
  }
  return m;
}

BernsteinPoly2 operator*(const BernsteinPoly2& a, const BernsteinPoly2& b)
{
  BernsteinPoly2 p(a.nu + b.nu, a.nv + b.nv);
  // In the scaled basis C(n,i)·B_i the product is a plain convolution: scale b once, so the
  // inner loop is a multiply-add (this product is the hot path of the 3D emptiness test).
  BernsteinPoly2 scaled = b;
  for (int k = 0; k <= b.nu; ++k)
    for (int l = 0; l <= b.nv; ++l)
      scaled.at(k, l) *= binomial(b.nu, k) * binomial(b.nv, l);
  for (int i = 0; i <= a.nu; ++i)
  {
    for (int j = 0; j <= a.nv; ++j)
    {
      const double ca = binomial(a.nu, i) * binomial(a.nv, j) * a.at(i, j);
      for (int k = 0; k <= b.nu; ++k)
      {
        for (int l = 0; l <= b.nv; ++l)
        {
          p.at(i + k, j + l) += ca * scaled.at(k, l);
        }
      }
    }
  }
  for (int i = 0; i <= p.nu; ++i)
  {
    for (int j = 0; j <= p.nv; ++j)
    {
      p.at(i, j) /= binomial(p.nu, i) * binomial(p.nv, j);
    }
  }
  return p;
}

namespace
{
BernsteinPoly2 combine2(const BernsteinPoly2& a, const BernsteinPoly2& b, double sb)
{
  const int mu = std::max(a.nu, b.nu), mv = std::max(a.nv, b.nv);
  BernsteinPoly2 ea = a.elevatedTo(mu, mv);
  const BernsteinPoly2 eb = b.elevatedTo(mu, mv);
  for (size_t k = 0; k < ea.c.size(); ++k)
  {
    ea.c[k] += sb * eb.c[k];
  }
  return ea;
}
} // namespace

BernsteinPoly2 operator+(const BernsteinPoly2& a, const BernsteinPoly2& b)
{
  return combine2(a, b, 1.0);
}

BernsteinPoly2 operator-(const BernsteinPoly2& a, const BernsteinPoly2& b)
{
  return combine2(a, b, -1.0);
}

BernsteinPoly2 operator*(double s, const BernsteinPoly2& a)
{
  BernsteinPoly2 r = a;
  for (double& v : r.c)
  {
    v *= s;
  }
  return r;
}

} // namespace exactmat

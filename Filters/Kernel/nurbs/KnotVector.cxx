#include "KnotVector.h"

#include "common/InputError.h"

#include <algorithm>
#include <cmath>

namespace exactmat
{

void validateKnots(const KnotVector& knots, int p, int count, const std::string& entity)
{
  if (p < 1 || p > MaxDegree)
  {
    fail(entity, ": degree ", p, " is outside 1..", MaxDegree);
  }
  if (count < p + 1)
  {
    fail(entity, ": ", count, " control points are too few for degree ", p, " (need ", p + 1,
      ")");
  }
  const size_t expected = static_cast<size_t>(count + p + 1);
  if (knots.size() != expected)
  {
    fail(entity, ": knot vector has ", knots.size(), " knots, expected ", expected,
      " (control points + degree + 1)");
  }
  for (size_t i = 0; i < knots.size(); ++i)
  {
    if (!std::isfinite(knots[i]))
    {
      fail(entity, ": knot ", i, " is not finite");
    }
    if (i > 0 && knots[i] < knots[i - 1])
    {
      fail(entity, ": knot vector is not non-decreasing (knot ", i, " = ", knots[i],
        " < knot ", i - 1, " = ", knots[i - 1], ")");
    }
  }
  if (!(knots[p] < knots[count]))
  {
    fail(entity, ": empty parameter domain [", knots[p], ", ", knots[count], "]");
  }
  // Interior knots of multiplicity > p would make the curve discontinuous.
  for (int i = p + 1; i < count; ++i)
  {
    const int m = multiplicity(knots, knots[i]);
    if (knots[i] > knots[p] && knots[i] < knots[count] && m > p)
    {
      fail(entity, ": interior knot ", knots[i], " has multiplicity ", m, " > degree ", p);
    }
  }
}

KnotVector clampedUniformKnots(int p, int count)
{
  KnotVector k(count + p + 1);
  const int spans = count - p;
  for (int i = 0; i < static_cast<int>(k.size()); ++i)
  {
    if (i <= p)
    {
      k[i] = 0.0;
    }
    else if (i >= count)
    {
      k[i] = 1.0;
    }
    else
    {
      k[i] = static_cast<double>(i - p) / spans;
    }
  }
  return k;
}

int findSpan(const KnotVector& U, int p, int count, double u)
{
  const int n = count - 1;
  if (u >= U[n + 1])
  {
    // The domain end belongs to the last non-empty span.
    int k = n;
    while (k > p && U[k] >= U[n + 1])
    {
      --k;
    }
    return k;
  }
  if (u <= U[p])
  {
    int k = p;
    while (k < n && U[k + 1] <= U[p])
    {
      ++k;
    }
    return k;
  }
  // upper_bound gives the first knot > u; the span starts just before it.
  const auto it = std::upper_bound(U.begin() + p, U.begin() + n + 1, u);
  return static_cast<int>(it - U.begin()) - 1;
}

void basisDerivatives(const KnotVector& U, int i, double u, int p, int nd, double* ders)
{
  // A2.3 with fixed-size scratch (degree ≤ MaxDegree).
  double ndu[MaxDegree + 1][MaxDegree + 1];
  double left[MaxDegree + 1], right[MaxDegree + 1];
  double a[2][MaxDegree + 1];
  ndu[0][0] = 1.0;
  for (int j = 1; j <= p; ++j)
  {
    left[j] = u - U[i + 1 - j];
    right[j] = U[i + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r)
    {
      ndu[j][r] = right[r + 1] + left[j - r];
      const double temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  for (int j = 0; j <= p; ++j)
  {
    ders[j] = ndu[j][p];
  }
  for (int r = 0; r <= p; ++r)
  {
    int s1 = 0, s2 = 1;
    a[0][0] = 1.0;
    for (int k = 1; k <= nd; ++k)
    {
      double d = 0.0;
      const int rk = r - k, pk = p - k;
      if (r >= k)
      {
        a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
        d = a[s2][0] * ndu[rk][pk];
      }
      const int j1 = (rk >= -1) ? 1 : -rk;
      const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j)
      {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
        d += a[s2][j] * ndu[rk + j][pk];
      }
      if (r <= pk)
      {
        a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
        d += a[s2][k] * ndu[r][pk];
      }
      ders[k * (p + 1) + r] = d;
      std::swap(s1, s2);
    }
  }
  int r = p;
  for (int k = 1; k <= nd; ++k)
  {
    for (int j = 0; j <= p; ++j)
    {
      ders[k * (p + 1) + j] *= r;
    }
    r *= (p - k);
  }
  // Orders above the degree vanish (the loop above leaves them at whatever r·0 made them).
  for (int k = p + 1; k <= nd; ++k)
  {
    for (int j = 0; j <= p; ++j)
    {
      ders[k * (p + 1) + j] = 0.0;
    }
  }
}

int multiplicity(const KnotVector& knots, double u)
{
  return static_cast<int>(std::count(knots.begin(), knots.end(), u));
}

void insertKnot(KnotVector& U, int p, Vec4List& P, int lines, double u)
{
  // A5.1 (Boehm) for r = 1, applied to each of the `lines` interleaved control polygons.
  const int count = static_cast<int>(P.size()) / lines;
  const int k = static_cast<int>(std::upper_bound(U.begin(), U.end(), u) - U.begin()) - 1;
  const int s = multiplicity(U, u);
  Vec4List Q(static_cast<size_t>(count + 1) * lines);
  for (int l = 0; l < lines; ++l)
  {
    auto src = [&](int i) -> const Vec4& { return P[static_cast<size_t>(i) * lines + l]; };
    auto dst = [&](int i) -> Vec4& { return Q[static_cast<size_t>(i) * lines + l]; };
    for (int i = 0; i <= k - p; ++i)
    {
      dst(i) = src(i);
    }
    for (int i = k - p + 1; i <= k - s; ++i)
    {
      const double alpha = (u - U[i]) / (U[i + p] - U[i]);
      dst(i) = alpha * src(i) + (1.0 - alpha) * src(i - 1);
    }
    for (int i = k - s + 1; i <= count; ++i)
    {
      dst(i) = src(i - 1);
    }
  }
  U.insert(U.begin() + k + 1, u);
  P.swap(Q);
}

int removeKnot(KnotVector& U, int p, Vec4List& Pw, double u, int num, double tol)
{
  // A5.8 (Tiller's knot removal), r = index of the last occurrence of u.
  const int n = static_cast<int>(Pw.size()) - 1;
  const int m = n + p + 1;
  const int s = multiplicity(U, u);
  const int r = static_cast<int>(std::upper_bound(U.begin(), U.end(), u) - U.begin()) - 1;
  if (s == 0 || r <= p || r >= n + 1)
  {
    return 0;
  }
  num = std::min(num, s);
  const int ord = p + 1;
  const int fout = (2 * r - s - p) / 2;
  int first = r - p;
  int last = r - s;
  Vec4List temp(2 * p + 1 + 2);
  int t = 0;
  for (t = 0; t < num; ++t)
  {
    const int off = first - 1;
    temp[0] = Pw[off];
    temp[last + 1 - off] = Pw[last + 1];
    int i = first, j = last, ii = 1, jj = last - off;
    while (j - i > t)
    {
      const double alfi = (u - U[i]) / (U[i + ord + t] - U[i]);
      const double alfj = (u - U[j - t]) / (U[j + ord] - U[j - t]);
      temp[ii] = (Pw[i] - (1.0 - alfi) * temp[ii - 1]) / alfi;
      temp[jj] = (Pw[j] - alfj * temp[jj + 1]) / (1.0 - alfj);
      ++i;
      ++ii;
      --j;
      --jj;
    }
    bool removable = false;
    if (j - i < t)
    {
      removable = (temp[ii - 1] - temp[jj + 1]).norm() <= tol;
    }
    else
    {
      const double alfi = (u - U[i]) / (U[i + ord + t] - U[i]);
      removable =
        (Pw[i] - (alfi * temp[ii + t + 1] + (1.0 - alfi) * temp[ii - 1])).norm() <= tol;
    }
    if (!removable)
    {
      break;
    }
    i = first;
    j = last;
    while (j - i > t)
    {
      Pw[i] = temp[i - off];
      Pw[j] = temp[j - off];
      ++i;
      --j;
    }
    --first;
    ++last;
  }
  if (t == 0)
  {
    return 0;
  }
  for (int k = r + 1; k <= m; ++k)
  {
    U[k - t] = U[k];
  }
  U.resize(U.size() - t);
  int j = fout, i = j;
  for (int k = 1; k < t; ++k)
  {
    if (k % 2 == 1)
    {
      ++i;
    }
    else
    {
      --j;
    }
  }
  for (int k = i + 1; k <= n; ++k)
  {
    Pw[j] = Pw[k];
    ++j;
  }
  Pw.resize(Pw.size() - t);
  return t;
}

} // namespace exactmat

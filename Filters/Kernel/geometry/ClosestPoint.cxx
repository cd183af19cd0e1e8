#include "ClosestPoint.h"
#include "SweptPatch.h"

#include "nurbs/Bernstein.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <deque>
#include <memory>
#include <queue>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace exactmat
{

double distanceToBox(const Box3& box, const Vec3& p)
{
  if (box.isEmpty())
  {
    return Unbounded;
  }
  const Vec3 d = (box.min() - p).cwiseMax(p - box.max()).cwiseMax(Vec3::Zero());
  return d.norm();
}

namespace
{
// Bounds of the recursions: 2^-48 of a parameter interval is far below double resolution
// of a footpoint, and a root cluster that has not separated by then is one footpoint.
constexpr int MaxCurveDepth = 48;
constexpr int MaxPatchDepth = 24;
// From this depth on, a box whose Newton limit is a degenerate minimum is not split further.
constexpr int DegenerateCheckDepth = 8;
constexpr int MaxPatchBoxes = 200000;
// Cuts across a pole's collapsed side (PatchSearch): SplitAt^48 ≈ 1e-15 of the parameter
// range, where the box is the pole to rounding.
constexpr int MaxPoleCuts = 48;
constexpr int NearPoleCuts = 30; // SplitAt^30 ≈ 4e-10
// Split a little off the middle: symmetric shapes put roots exactly at t = 1/2.
constexpr double SplitAt = 0.4871;

// The product of two Bernstein polynomials on the stack, with BernsteinPoly's own
// arithmetic (operator*), operation for operation.
int bernsteinProduct(const double* a, int m, const double* b, int n, double* out)
{
  for (int k = 0; k <= m + n; ++k)
    out[k] = 0.0;
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j)
      out[i + j] += binomial(m, i) * binomial(n, j) * a[i] * b[j];
  for (int k = 0; k <= m + n; ++k)
    out[k] /= binomial(m + n, k);
  return m + n;
}

// stationarityPoly(curvePolys(curve, q)) and the scales curveFootpoints measures it by,
// without allocating (every distance query of the verification asks for it): the same
// operations in the same order, so the coefficients are bit-identical. Returns g's degree.
struct StationarityScales
{
  double dMax = 0.0, dpMax = 0.0, wMax = 0.0;
  bool polynomial = true;
};
int stationarityOnStack(const BezierCurve& curve, const Vec3& q, double* g, StationarityScales& sc)
{
  constexpr int N = MaxDegree + 1;
  const int p = curve.degree();
  const Vec4List& hp = curve.homogeneousPoints();
  double d[3][N], w[N], dw[N], dk[N], a[3 * N], b[3 * N], diff[3 * N], term[3 * N];
  for (int i = 0; i <= p; ++i)
  {
    for (int k = 0; k < 3; ++k)
      d[k][i] = hp[i](k) - q(k) * hp[i].w();
    w[i] = hp[i].w();
    sc.polynomial = sc.polynomial && w[i] == w[0];
  }
  for (int i = 0; i < p; ++i)
    dw[i] = p * (w[i + 1] - w[i]);
  int n = 0;
  for (int k = 0; k < 3; ++k)
  {
    // A coordinate the curve and the query share everywhere (z of every 2D query) adds
    // exact zeros: skip its three products.
    if (k > 0 && std::all_of(d[k], d[k] + p + 1, [](double v) { return v == 0.0; }))
      continue;
    for (int i = 0; i < p; ++i)
      dk[i] = p * (d[k][i + 1] - d[k][i]);
    int m;
    if (sc.polynomial)
      m = bernsteinProduct(d[k], p, dk, p - 1, term);
    else
    {
      const int e = bernsteinProduct(dk, p - 1, w, p, a);
      bernsteinProduct(d[k], p, dw, p - 1, b);
      for (int i = 0; i <= e; ++i)
        diff[i] = a[i] + -1.0 * b[i];
      m = bernsteinProduct(d[k], p, diff, e, term);
    }
    for (int i = 0; i <= m; ++i)
      g[i] = k == 0 ? term[i] : g[i] + 1.0 * term[i];
    n = m;
    for (int i = 0; i <= p; ++i)
      sc.dMax = std::max(sc.dMax, std::abs(d[k][i]));
    for (int i = 0; i < p; ++i)
      sc.dpMax = std::max(sc.dpMax, std::abs(dk[i]));
  }
  for (int i = 0; i <= p; ++i)
    sc.wMax = std::max(sc.wMax, std::abs(w[i]));
  return n;
}

// Newton polish of f(t) = (C − P)·C' = 0 from t0, kept inside [lo, hi]. A step is taken
// only if it does not move away from P: at a degenerate minimum (an LMPC's centre of
// curvature: f has a triple root, f' ≈ 0) Newton would jump across the curve.
double polishCurve(const BezierCurve& c, const Vec3& q, double t, double lo, double hi)
{
  CurveDerivatives d = c.derivatives(t);
  for (int it = 0; it < 8; ++it)
  {
    const Vec3 r = d.point - q;
    const double f = r.dot(d.d1);
    const double fp = d.d1.squaredNorm() + r.dot(d.d2);
    if (!(fp > 0.0))
    {
      break;
    }
    const double next = std::min(hi, std::max(lo, t - f / fp));
    if (std::abs(next - t) < 1e-16)
    {
      break;
    }
    const CurveDerivatives dn = c.derivatives(next);
    if ((dn.point - q).squaredNorm() > r.squaredNorm())
    {
      break;
    }
    t = next;
    d = dn;
  }
  return t;
}

// Finds the sign change of g on [a,b] (g(a) < 0 < g(b) or the reverse) to ~1e-13 of the
// parameter: Newton steps kept inside the shrinking bracket, halving where a step would
// leave it or not halve the step before (a root of odd multiplicity > 1 converges only
// linearly under Newton). polishCurve's Newton steps on the distance finish the job.
double bracketRoot(const BernsteinPoly& g, double a, double b, double ga, double gb)
{
  double t = (a * gb - b * ga) / (gb - ga);
  if (!(t > a && t < b))
    t = 0.5 * (a + b);
  double dxOld = b - a, dx = dxOld;
  for (int it = 0; it < 100 && b - a > 1e-12; ++it)
  {
    double slope = 0.0;
    const double gt = g.valueAndSlope(t, slope);
    if (gt == 0.0)
      return t;
    if ((gt < 0.0) == (ga < 0.0))
    {
      a = t;
      ga = gt;
    }
    else
      b = t;
    const double newton = slope != 0.0 ? t - gt / slope : a - 1.0;
    if (!(newton > a && newton < b) || std::abs(2.0 * gt) > std::abs(dxOld * slope))
    {
      dxOld = dx;
      dx = 0.5 * (b - a);
      t = a + dx;
    }
    else
    {
      dxOld = dx;
      dx = t - newton;
      t = newton;
      if (std::abs(dx) < 1e-14)
        return t;
    }
  }
  return 0.5 * (a + b);
}

struct RootFinder
{
  const BernsteinPoly& g; // on the whole [0,1]
  double zero;
  std::vector<double> minima; // parameters where g goes from − to +

  void classifyAt(double t, double h)
  {
    const double before = g(std::max(0.0, t - h)), after = g(std::min(1.0, t + h));
    if (before <= zero && after >= -zero && !(before == 0.0 && after == 0.0))
    {
      minima.push_back(t);
    }
  }

  void search(const BernsteinPoly& local, double a, double b, int depth)
  {
    const int changes = local.signChanges(zero);
#ifdef EXACTMAT_TRACE_DEBUG
    if (std::getenv("EXACTMAT_ROOT_DEBUG"))
    {
      std::fprintf(stderr, "%*s[%.9g, %.9g] changes %d zero %.3g:", depth, "", a, b, changes, zero);
      for (double v : local.c)
        std::fprintf(stderr, " %.3g", v);
      std::fprintf(stderr, "\n");
    }
#endif
    if (changes == 0)
    {
      // Every coefficient within rounding of 0: the distance is stationary to rounding over
      // [a, b] — a degenerate minimum, such as the triple root at an LMPC's centre of
      // curvature, whose sign changes rounding has erased. Not seeing it would make the
      // distance jump to a farther minimum.
      if (local.maxAbs() <= zero)
      {
        classifyAt(0.5 * (a + b), b - a);
      }
      return;
    }
    // The end values of the restricted polynomial are its first and last coefficients.
    const double ga = local.c.front(), gb = local.c.back();
    if (changes == 1 && ga < -zero && gb > zero)
    {
      minima.push_back(bracketRoot(g, a, b, ga, gb));
      return;
    }
    if (changes == 1 && ga > zero && gb < -zero)
    {
      return; // a single maximum of the distance
    }
    if (depth >= MaxCurveDepth)
    {
      classifyAt(0.5 * (a + b), b - a);
      return;
    }
    BernsteinPoly left, right;
    local.split(SplitAt, left, right);
    const double m = a + SplitAt * (b - a);
    if (std::abs(g(m)) <= zero)
    {
      classifyAt(m, 1e-3 * (b - a));
    }
    search(left, a, m, depth + 1);
    search(right, m, b, depth + 1);
  }
};

void sortAndDedupe(std::vector<CurveFootpoint>& fps)
{
  std::sort(fps.begin(), fps.end(),
    [](const CurveFootpoint& a, const CurveFootpoint& b) { return a.t < b.t; });
  std::vector<CurveFootpoint> out;
  for (const CurveFootpoint& f : fps)
  {
    if (!out.empty() && std::abs(f.t - out.back().t) < 1e-9)
    {
      if (f.distance < out.back().distance || f.atEnd)
      {
        const bool end = out.back().atEnd || f.atEnd;
        out.back() = f;
        out.back().atEnd = end;
      }
      continue;
    }
    out.push_back(f);
  }
  std::sort(out.begin(), out.end(),
    [](const CurveFootpoint& a, const CurveFootpoint& b) { return a.distance < b.distance; });
  fps.swap(out);
}
} // namespace

std::vector<CurveFootpoint> curveFootpoints(
  const BezierCurve& curve, const Vec3& query, double maxDistance, double continuumTolerance)
{
  std::vector<CurveFootpoint> result;
  if (distanceToBox(curve.boundingBox(), query) > maxDistance)
  {
    return result;
  }
  double gs[3 * (MaxDegree + 1)];
  StationarityScales sc;
  const int gDegree = stationarityOnStack(curve, query, gs, sc);
  BernsteinPoly g;
  g.c.assign(gs, gs + gDegree + 1);
  // The scale of g: |D|·|D'|·w² bounds its coefficients; 1e-14 of it is rounding noise.
  const double dMax = sc.dMax, dpMax = sc.dpMax, wMax = sc.wMax;
  const double scale = dMax * (dpMax + dMax) * wMax * (sc.polynomial ? 1.0 : wMax);
  const double zero = 1e-14 * scale;
  auto make = [&](double t, bool atEnd) {
    CurveFootpoint f;
    f.t = t;
    f.point = curve.evaluate(t);
    f.distance = (f.point - query).norm();
    f.atEnd = atEnd;
    return f;
  };

  if (g.maxAbs() <= std::max(1e-14, continuumTolerance) * scale)
  {
    // Every point is stationary: the query is the centre of a circular arc (or the curve is
    // a point). Report one footpoint for the whole curve.
    CurveFootpoint f = make(0.5, false);
    f.continuum = true;
    if (f.distance <= maxDistance)
    {
      result.push_back(f);
    }
    return result;
  }

  if (curve.degree() == 1)
  {
    // A straight edge: (C − P)·C' has the sign of (C − P)·(B − A), increasing along the
    // edge, so there is an interior minimum exactly when g goes from − to + (the root
    // search's own criterion), at P's projection — in closed form, mapped through the
    // weights (a rational line is a re-parameterised line). Polygons are all edges: this
    // is most of their distance queries.
    const double ga = g.c.front(), gb = g.c.back();
    const Vec3 a = curve.startPoint(), ab = curve.endPoint() - a;
    const double len2 = ab.squaredNorm();
    if (ga < -zero && gb > zero && len2 > 0.0)
    {
      const double s = std::min(1.0, std::max(0.0, (query - a).dot(ab) / len2));
      const double w0 = curve.homogeneousPoints()[0].w(), w1 = curve.homogeneousPoints()[1].w();
      const double t = w0 == w1 ? s : s * w0 / (s * w0 + (1.0 - s) * w1);
      if (t > 0.0 && t < 1.0)
        result.push_back(make(t, false));
    }
  }
  else
  {
    RootFinder finder{ g, zero, {} };
    finder.search(g, 0.0, 1.0, 0);
    for (double t : finder.minima)
    {
      if (t <= 0.0 || t >= 1.0)
      {
        continue; // ends are handled below
      }
      result.push_back(make(polishCurve(curve, query, t, 0.0, 1.0), false));
    }
  }
  // An end is a one-sided minimum when the distance does not decrease into the curve.
  if (g.c.front() >= -zero)
  {
    result.push_back(make(0.0, true));
  }
  if (g.c.back() <= zero)
  {
    result.push_back(make(1.0, true));
  }
  for (CurveFootpoint& f : result)
  {
    f.atEnd = f.atEnd || f.t <= 0.0 || f.t >= 1.0;
  }
  sortAndDedupe(result);
  result.erase(std::remove_if(result.begin(), result.end(),
                 [&](const CurveFootpoint& f) { return f.distance > maxDistance; }),
    result.end());
  return result;
}

namespace
{
// The minimum of a quadratic in Bernstein form on [0, 1], in closed form: a straight edge's
// squared distance. Subdividing a nearly tangent one costs up to 40 levels, and a regular
// n-gon's centre meets n of them in every disk.
bool quadraticNegativeSomewhere(const double* h)
{
  const double c0 = h[0], c1 = h[1], c2 = h[2];
  if (c0 < 0.0 || c2 < 0.0)
    return true;
  const double a = c0 - 2.0 * c1 + c2; // h'' / 2
  if (!(a > 0.0))
    return false; // concave or linear: the minimum is at an end (both ≥ 0)
  const double t = (c0 - c1) / a;     // h'(t) = 0
  if (!(t > 0.0 && t < 1.0))
    return false;
  const double u = 1.0 - t;
  return c0 * u * u + 2.0 * c1 * t * u + c2 * t * t < 0.0;
}

// The Bernstein coefficients of |C(t)·w(t) − q·w(t)|² − r²·w(t)² (degree 2p) into h[0 … 2p],
// without allocating: the emptiness test's polynomial, asked for at every tracing step.
// With d_i = P_i·w_i − q·w_i, the product of two degree-p Bernstein sums has coefficients
// h_m = Σ_{i+j=m} C(p,i)·C(p,j)/C(2p,m) · (d_i·d_j − r²·w_i·w_j); the pairs i < j and j < i
// are one term counted twice, and the radius is subtracted inside each term (where its
// cancellation against d_i·d_j is exact to rounding) rather than from the sums.
int squaredDistanceMinusRadius(const BezierCurve& curve, const Vec3& q, double radius, double* h)
{
  const int p = curve.degree(), n = 2 * p;
  const Vec4List& hp = curve.homogeneousPoints();
  double d[MaxDegree + 1][3], w[MaxDegree + 1];
  for (int i = 0; i <= p; ++i)
  {
    w[i] = hp[i].w();
    for (int k = 0; k < 3; ++k)
      d[i][k] = hp[i](k) - q(k) * w[i];
  }
  const double r2 = radius * radius;
  auto term = [&](int i, int j) {
    return d[i][0] * d[j][0] + d[i][1] * d[j][1] + d[i][2] * d[j][2] - r2 * (w[i] * w[j]);
  };
  if (p == 2)
  {
    // The conics of most profiles, in closed form: C(2,i)·C(2,j)/C(4,m) is 1 but for
    // m = 2, where the pairs (0, 2), (2, 0) and (1, 1) weigh 1/6, 1/6 and 4/6.
    h[0] = term(0, 0);
    h[1] = term(0, 1);
    h[2] = (term(0, 2) + 2.0 * term(1, 1)) / 3.0;
    h[3] = term(1, 2);
    h[4] = term(2, 2);
    return n;
  }
  for (int m = 0; m <= n; ++m)
    h[m] = 0.0;
  for (int i = 0; i <= p; ++i)
  {
    const double bi = binomial(p, i);
    for (int j = i; j <= p; ++j)
    {
      h[i + j] += (i == j ? 1.0 : 2.0) * bi * binomial(p, j) * term(i, j);
    }
  }
  for (int m = 1; m < n; ++m)
    h[m] /= binomial(n, m);
  return n;
}

// A sufficient test that h = Σ c_k B_{k,n}(t) ≥ 0 on [0, 1] when h has a (near) double
// root at τ, the touch of a tracing step's disk: with h(τ + u) = a₀ + a₁u + u²·q(u) and
// q ≥ q_min > 0 on u ∈ [−τ, 1 − τ], h ≥ a₀ − a₁²/(4 q_min), which the disk's margin keeps
// positive. The Taylor coefficients come from the power form (n ≤ 8: well conditioned
// on [0, 1]) shifted to τ. False means "not shown": the caller subdivides.
bool staysOutsideAroundTouch(const double* c, int n, double tau)
{
  if (n < 2 || n > 8)
    return false;
  // Power form: the k-th coefficient is C(n, k)·Δᵏc₀ (forward differences).
  double a[9], d[9];
  std::copy(c, c + n + 1, d);
  for (int k = 0; k <= n; ++k)
  {
    a[k] = binomial(n, k) * d[0];
    for (int i = 0; i < n - k; ++i)
      d[i] = d[i + 1] - d[i];
  }
  for (int i = 0; i < n; ++i) // Taylor shift to τ (repeated synthetic division)
    for (int j = n - 1; j >= i; --j)
      a[j] += tau * a[j + 1];
  const double lo = -tau, hi = 1.0 - tau;
  double qMin;
  if (n == 4)
  {
    // q(u) = a₂ + a₃u + a₄u²: its least value on [lo, hi], in closed form.
    auto q = [&](double u) { return a[2] + u * (a[3] + u * a[4]); };
    qMin = std::min(q(lo), q(hi));
    if (a[4] > 0.0)
    {
      const double u = -a[3] / (2.0 * a[4]);
      if (u > lo && u < hi)
        qMin = std::min(qMin, q(u));
    }
  }
  else
  {
    const double reach = std::max(tau, 1.0 - tau);
    qMin = a[2];
    double power = 1.0;
    for (int k = 3; k <= n; ++k)
    {
      power *= reach;
      qMin -= std::abs(a[k]) * power;
    }
  }
  return qMin > 0.0 && a[0] > 0.0 && a[1] * a[1] < 4.0 * qMin * a[0];
}

// Is Σ h_k B_{k,n}(t) < 0 somewhere on [0, 1]? Halving on the stack (this is every
// emptiness test's work).
bool negativeSomewhere(const double* h, int n, int depth)
{
  if (depth == 0 && n == 2)
    return quadraticNegativeSomewhere(h);
  if (*std::min_element(h, h + n + 1) >= 0.0)
    return false; // the coefficients bound h from below
  if (h[0] < 0.0 || h[n] < 0.0)
    return true; // an end of this piece is inside
  if (depth >= 40)
    return false;
  double left[2 * MaxDegree + 1], right[2 * MaxDegree + 1];
  splitBernstein(h, n, 0.5, left, right);
  if (left[n] < 0.0)
    return true; // the midpoint is inside
  return negativeSomewhere(left, n, depth + 1) || negativeSomewhere(right, n, depth + 1);
}
} // namespace

bool curveComesWithin(const BezierCurve& curve, const Vec3& query, double radius)
{
  if (!(radius > 0.0) || distanceToBox(curve.boundingBox(), query) >= radius)
  {
    return false;
  }
  if (curve.degree() == 1)
  {
    // A straight edge (whatever its weights: they only re-parameterise it): the nearest
    // point in closed form. Polygons are all edges, and a regular n-gon's centre meets n
    // of them in every disk near it.
    const Vec3 a = curve.startPoint(), ab = curve.endPoint() - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0.0 ? std::min(1.0, std::max(0.0, (query - a).dot(ab) / len2)) : 0.0;
    return (a + t * ab - query).squaredNorm() < radius * radius;
  }
  double h[2 * MaxDegree + 1];
  const int n = squaredDistanceMinusRadius(curve, query, radius, h);
  return negativeSomewhere(h, n, 0);
}

bool curveComesWithin(const BezierCurve& curve, const Vec3& query, double radius, double touch)
{
  if (curve.degree() == 1 || !(touch > 0.0 && touch < 1.0))
    return curveComesWithin(curve, query, radius);
  // (No bounding-box test: the disk touches the curve at `touch`.)
  if (!(radius > 0.0))
    return false;
  double c[2 * MaxDegree + 1];
  const int n = squaredDistanceMinusRadius(curve, query, radius, c);
  if (*std::min_element(c, c + n + 1) >= 0.0)
    return false;
  if (staysOutsideAroundTouch(c, n, touch))
    return false;
  double left[2 * MaxDegree + 1], right[2 * MaxDegree + 1];
  splitBernstein(c, n, touch, left, right);
  return negativeSomewhere(left, n, 1) || negativeSomewhere(right, n, 1);
}

CurveFootpoint closestPoint(const BezierCurve& curve, const Vec3& query)
{
  const std::vector<CurveFootpoint> fps = curveFootpoints(curve, query);
  if (!fps.empty())
  {
    return fps.front();
  }
  // Not reachable for valid curves (an end is always a candidate); keep a defined answer.
  CurveFootpoint f;
  f.point = curve.startPoint();
  f.distance = (f.point - query).norm();
  f.atEnd = true;
  return f;
}

// ---------------------------------------------------------------------------------------
// patches

namespace
{
struct PatchPolys
{
  BernsteinPoly2 gu, gv; ///< signs of (S − P)·Su and (S − P)·Sv
  /// What rounding leaves of gu and gv: each has its own, as a patch 1e12 times longer
  /// than wide (the side of a long extrusion) has derivatives 1e12 apart.
  double zeroU = 0.0, zeroV = 0.0;
};

// What identifies a patch to the caches below (its homogeneous control points) and the
// centre the bases are expressed about.
struct PatchKey
{
  int p = 0, r = 0;
  std::vector<Vec4> points;
  Vec3 centre = Vec3::Zero();
};

// The patch's homogeneous coordinates centred on it (X − c·w) and its weights, as Bernstein
// polynomials: what the bases are built from.
struct CentredCoordinates : PatchKey
{
  BernsteinPoly2 x[3], w;
  bool polynomial = true; ///< all weights equal
};

CentredCoordinates centredCoordinates(const BezierPatch& patch)
{
  CentredCoordinates c;
  c.p = patch.degreeU();
  c.r = patch.degreeV();
  c.centre = patch.boundingBox().center();
  for (int k = 0; k < 3; ++k)
    c.x[k] = BernsteinPoly2(c.p, c.r);
  c.w = BernsteinPoly2(c.p, c.r);
  const double w00 = patch.homogeneousPoint(0, 0).w();
  for (int i = 0; i <= c.p; ++i)
    for (int j = 0; j <= c.r; ++j)
    {
      const Vec4& h = patch.homogeneousPoint(i, j);
      c.points.push_back(h);
      for (int k = 0; k < 3; ++k)
        c.x[k].at(i, j) = h(k) - c.centre(k) * h.w();
      c.w.at(i, j) = h.w();
      c.polynomial = c.polynomial && h.w() == w00;
    }
  return c;
}

// The stationarity polynomials split into what the patch alone decides and what the query
// adds. With X the homogeneous coordinates (centred on the patch: X − c·w) and d = X − q·w,
//   gu = Σ_k d_k·(d_k,u·w − d_k·w_u) = Σ_k X_k·A_k − Σ_k q_k·(w·A_k),  A_k = X_k,u·w − X_k·w_u
// (the query cancels inside A), and with w constant gu = Σ_k X_k·X_k,u − Σ_k q_k·w·X_k,u:
// the products are the patch's, a query only combines them linearly. Kept per thread for
// the patches searched last (each is searched thousands of times along a seam or a sheet).
struct StationarityBasis : PatchKey
{
  bool polynomial = true;
  BernsteinPoly2 pu, pv;       ///< Σ X_k·A_k (u and v)
  BernsteinPoly2 qu[3], qv[3]; ///< w·A_k, at pu's and pv's degrees
  double wMax = 0.0, wuMax = 0.0, wvMax = 0.0;
};

std::unique_ptr<StationarityBasis> stationarityBasis(const BezierPatch& patch)
{
  const CentredCoordinates c = centredCoordinates(patch);
  auto b = std::make_unique<StationarityBasis>();
  static_cast<PatchKey&>(*b) = c;
  b->polynomial = c.polynomial;
  const BernsteinPoly2 &w = c.w, wu = w.derivativeU(), wv = w.derivativeV();
  const double w00 = c.points.front().w();
  BernsteinPoly2 au[3], av[3];
  for (int k = 0; k < 3; ++k)
  {
    const BernsteinPoly2 xu = c.x[k].derivativeU(), xv = c.x[k].derivativeV();
    au[k] = c.polynomial ? xu : xu * w - c.x[k] * wu;
    av[k] = c.polynomial ? xv : xv * w - c.x[k] * wv;
    const BernsteinPoly2 tu = c.x[k] * au[k], tv = c.x[k] * av[k];
    b->pu = k == 0 ? tu : b->pu + tu;
    b->pv = k == 0 ? tv : b->pv + tv;
  }
  for (int k = 0; k < 3; ++k)
  {
    b->qu[k] = (c.polynomial ? w00 * au[k] : w * au[k]).elevatedTo(b->pu.nu, b->pu.nv);
    b->qv[k] = (c.polynomial ? w00 * av[k] : w * av[k]).elevatedTo(b->pv.nu, b->pv.nv);
  }
  b->wMax = w.maxAbs();
  b->wuMax = wu.maxAbs();
  b->wvMax = wv.maxAbs();
  return b;
}

// What a patch alone decides (Basis: p, r, points and a factory), kept per thread for the
// last patches asked for: compared by their control points, so a hit is always the same
// patch, whichever object holds it.
template <class Basis, size_t Slots>
const Basis& cachedBasis(const BezierPatch& patch, std::unique_ptr<Basis> (*make)(const BezierPatch&))
{
  static thread_local std::array<std::unique_ptr<Basis>, Slots> cache;
  const int p = patch.degreeU(), r = patch.degreeV();
  std::uint64_t hash = 1469598103934665603ull;
  for (int i = 0; i <= p; ++i)
    for (int j = 0; j <= r; ++j)
      for (int k = 0; k < 4; ++k)
      {
        std::uint64_t bits;
        const double v = patch.homogeneousPoint(i, j)(k);
        std::memcpy(&bits, &v, sizeof bits);
        hash = (hash ^ bits) * 1099511628211ull;
      }
  std::unique_ptr<Basis>& slot = cache[(hash ^ (hash >> 29)) % Slots];
  auto same = [&]() {
    if (!slot || slot->p != p || slot->r != r)
      return false;
    for (int i = 0, n = 0; i <= p; ++i)
      for (int j = 0; j <= r; ++j, ++n)
        if (slot->points[n] != patch.homogeneousPoint(i, j))
          return false;
    return true;
  };
  if (!same())
    slot = make(patch);
  return *slot;
}

const StationarityBasis& cachedStationarityBasis(const BezierPatch& patch)
{
  return cachedBasis<StationarityBasis, 64>(patch, stationarityBasis);
}

PatchPolys patchPolys(const BezierPatch& patch, const Vec3& q)
{
  const StationarityBasis& b = cachedStationarityBasis(patch);
  const Vec3 c = q - b.centre;
  PatchPolys pp;
  pp.gu = b.pu;
  pp.gv = b.pv;
  for (size_t n = 0; n < pp.gu.c.size(); ++n)
    pp.gu.c[n] -= c(0) * b.qu[0].c[n] + c(1) * b.qu[1].c[n] + c(2) * b.qu[2].c[n];
  for (size_t n = 0; n < pp.gv.c.size(); ++n)
    pp.gv.c[n] -= c(0) * b.qv[0].c[n] + c(1) * b.qv[1].c[n] + c(2) * b.qv[2].c[n];
  // The rounding level of the direct form Σ d·(d_u·w − d·w_u), from d's control net.
  const int p = b.p, r = b.r;
  double dMax = 0.0, duMax = 0.0, dvMax = 0.0;
  auto d = [&](int i, int j, int k) {
    const Vec4& h = b.points[i * (r + 1) + j];
    return h(k) - q(k) * h.w();
  };
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i <= p; ++i)
      for (int j = 0; j <= r; ++j)
      {
        dMax = std::max(dMax, std::abs(d(i, j, k)));
        if (i < p)
          duMax = std::max(duMax, p * std::abs(d(i + 1, j, k) - d(i, j, k)));
        if (j < r)
          dvMax = std::max(dvMax, r * std::abs(d(i, j + 1, k) - d(i, j, k)));
      }
  const double rational = b.polynomial ? 0.0 : 1.0;
  pp.zeroU = 1e-13 * dMax * (duMax * (b.polynomial ? 1.0 : b.wMax) + rational * dMax * b.wuMax);
  pp.zeroV = 1e-13 * dMax * (dvMax * (b.polynomial ? 1.0 : b.wMax) + rational * dMax * b.wvMax);
  return pp;
}

struct Interval
{
  double lo, hi;
};

// Bounds of p's derivative along u or v (its Bernstein coefficients' range).
Interval derivativeBounds(const BernsteinPoly2& p, bool alongU)
{
  Interval i;
  p.derivativeBounds(alongU, i.lo, i.hi);
  return i;
}

Interval mul(Interval a, Interval b)
{
  const double c[4] = { a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi };
  return { *std::min_element(c, c + 4), *std::max_element(c, c + 4) };
}

// Solves [a b; b c]·(du, dv) = (fu, fv) for a symmetric 2×2 matrix, dropping eigen-
// directions whose eigenvalue is negligible (least-squares step of minimum norm).
bool pseudoSolve(double a, double b, double c, double fu, double fv, double& du, double& dv)
{
  const double mean = 0.5 * (a + c), diff = 0.5 * (a - c);
  const double radius = std::hypot(diff, b);
  const double l1 = mean + radius, l2 = mean - radius;
  const double big = std::max(std::abs(l1), std::abs(l2));
  if (!(big > 0.0) || !std::isfinite(big))
  {
    return false;
  }
  // Unit eigenvector of l1: (b, l1 − a) or (l1 − c, b), whichever is better conditioned.
  Vec2 e1 = std::abs(b) + std::abs(l1 - a) >= std::abs(l1 - c) + std::abs(b) ? Vec2(b, l1 - a)
                                                                              : Vec2(l1 - c, b);
  if (e1.norm() == 0.0)
  {
    e1 = Vec2(1.0, 0.0);
  }
  e1.normalize();
  const Vec2 e2(-e1.y(), e1.x());
  const Vec2 f(fu, fv);
  Vec2 step = Vec2::Zero();
  if (std::abs(l1) > 1e-8 * big)
  {
    step += (e1.dot(f) / l1) * e1;
  }
  if (std::abs(l2) > 1e-8 * big)
  {
    step += (e2.dot(f) / l2) * e2;
  }
  du = step.x();
  dv = step.y();
  return true;
}

// Newton on (f_u, f_v) = ((S−P)·Su, (S−P)·Sv) from (u, v) kept in the box. Returns true when
// it converged to a point inside the box (slightly enlarged) that is not a maximum/saddle.
// Where the Hessian is singular (a curve of minima: a torus seen from its core circle, a
// ball osculating along a principal direction) the step uses its pseudo-inverse, which
// lands on the curve; `degenerate` then reports it.
// With `clampToBox` the iterate is kept in the box instead of giving up when it leaves:
// on a curve of minima the flat direction drifts.
bool newtonPatch(const BezierPatch& patch, const Vec3& q, double& u, double& v, double u0,
  double u1, double v0, double v1, bool* degenerate = nullptr, bool clampToBox = false)
{
  const double mu = 1e-9 + 1e-6 * (u1 - u0), mv = 1e-9 + 1e-6 * (v1 - v0);
  for (int it = 0; it < 30; ++it)
  {
    const SurfaceDerivatives s = patch.derivatives(u, v);
    const Vec3 r = s.point - q;
    const double fu = r.dot(s.su), fv = r.dot(s.sv);
    const double a = s.su.squaredNorm() + r.dot(s.suu);
    const double b = s.su.dot(s.sv) + r.dot(s.suv);
    const double c = s.sv.squaredNorm() + r.dot(s.svv);
    // Stationary to rounding: done (a degenerate minimum converges only linearly, so the
    // step test below may never pass there).
    const double scale = r.norm() + 1e-300;
    if (std::abs(fu) <= 1e-15 * scale * s.su.norm() && std::abs(fv) <= 1e-15 * scale * s.sv.norm())
    {
      break;
    }
    // In arc-length-like variables (u·|Su|, v·|Sv|): a patch 1e6 times longer than wide
    // has a Hessian whose eigenvalues are 1e12 apart in (u, v), and the pseudo-inverse
    // would drop the short direction as negligible.
    // (Only there: elsewhere the plain step settles degenerate minima sooner.)
    const double nu = s.su.norm(), nv = s.sv.norm();
    const bool elongated = nu > 16.0 * nv || nv > 16.0 * nu;
    const double ku = elongated && nu > 0.0 ? 1.0 / nu : 1.0, kv = elongated && nv > 0.0 ? 1.0 / nv : 1.0;
    double du = 0.0, dv = 0.0;
    if (!pseudoSolve(a * ku * ku, b * ku * kv, c * kv * kv, fu * ku, fv * kv, du, dv))
    {
      return false;
    }
    du *= ku;
    dv *= kv;
    u -= du;
    v -= dv;
    if (clampToBox)
    {
      u = std::min(u1, std::max(u0, u));
      v = std::min(v1, std::max(v0, v));
    }
    if (u < u0 - mu || u > u1 + mu || v < v0 - mv || v > v1 + mv)
    {
      return false;
    }
    if (std::abs(du) < 1e-15 && std::abs(dv) < 1e-15)
    {
      break;
    }
    // (r is the difference of two points and known only to their coordinates' rounding:
    // a ball 5e-8 across in a plate 1e-6 thin, 1 from the origin, has r to 2e-9 of itself.)
    const double reach = 1e-9 * scale + 1e-14 * (s.point.norm() + q.norm());
    if (it == 29 && !(std::abs(fu) <= reach * s.su.norm() && std::abs(fv) <= reach * s.sv.norm()))
    {
      return false;
    }
  }
  u = std::min(1.0, std::max(0.0, u));
  v = std::min(1.0, std::max(0.0, v));
  const SurfaceDerivatives s = patch.derivatives(u, v);
  const Vec3 r = s.point - q;
  const double a = s.su.squaredNorm() + r.dot(s.suu);
  const double b = s.su.dot(s.sv) + r.dot(s.suv);
  const double c = s.sv.squaredNorm() + r.dot(s.svv);
  // Keep minima (and degenerate, flat minima); drop saddles and maxima.
  const double tol = 1e-12 * (s.su.squaredNorm() + s.sv.squaredNorm());
  if (degenerate)
  {
    *degenerate = std::abs(a * c - b * b) <= 1e-8 * (a * a + c * c + b * b);
  }
  // (A degenerate minimum's determinant is zero up to rounding of a², b², c².)
  return a + c >= -tol && a * c - b * b >= -std::max(tol * tol, 1e-12 * (a * a + b * b + c * c));
}

// How much p's coefficients vary along u (the largest range down a column i = 0 … nu) and
// along v (along a row).
void spreads(const BernsteinPoly2& p, double& alongU, double& alongV)
{
  alongU = alongV = 0.0;
  for (int j = 0; j <= p.nv; ++j)
  {
    double lo = p.at(0, j), hi = lo;
    for (int i = 1; i <= p.nu; ++i)
    {
      lo = std::min(lo, p.at(i, j));
      hi = std::max(hi, p.at(i, j));
    }
    alongU = std::max(alongU, hi - lo);
  }
  for (int i = 0; i <= p.nu; ++i)
  {
    double lo = p.at(i, 0), hi = lo;
    for (int j = 1; j <= p.nv; ++j)
    {
      lo = std::min(lo, p.at(i, j));
      hi = std::max(hi, p.at(i, j));
    }
    alongV = std::max(alongV, hi - lo);
  }
}

// The direction to halve a box whose gu and gv both change sign (PatchSearch): of the two,
// the one nearer a strict sign (the smaller share of its coefficients' range on the
// minority side of 0) decides; 1: halve in u, −1: in v, 0: quarter (it varies about as
// much either way).
int anisotropicSplit(const BernsteinPoly2& gu, const BernsteinPoly2& gv)
{
  auto minority = [](const BernsteinPoly2& p) {
    const auto [lo, hi] = std::minmax_element(p.c.begin(), p.c.end());
    const double range = *hi - *lo;
    return range > 0.0 ? std::max(0.0, std::min(-*lo, *hi)) / range : 0.0;
  };
  const BernsteinPoly2& p = minority(gu) <= minority(gv) ? gu : gv;
  double alongU = 0.0, alongV = 0.0;
  spreads(p, alongU, alongV);
  constexpr double Skew = 4.0;
  return alongU > Skew * alongV ? 1 : alongV > Skew * alongU ? -1 : 0;
}

// Boxes searched on this thread (patchSearchWork), and the limit of one search
// (PatchSearchLimit).
thread_local std::uint64_t Work = 0;
thread_local int BoxLimit = MaxPatchBoxes;
thread_local std::uint64_t CutShort = 0; // searches stopped at their limit (patchSearchesCutShort)

// The polynomials of one recursion level of a subdivision search: a box's four quarters
// (or two halves) of each polynomial it splits.
struct ScratchLevel
{
  BernsteinPoly2 u[4], v[4], d[4];
  BernsteinPoly2 own; ///< the ball polynomial of this level's box, where it starts there
};

// Scratch levels reused by every search on this thread, so that boxes allocate nothing
// once the levels have grown (a search allocated a dozen polynomials per box; under ASan
// recording each allocation's stack was 81% of the ellipsoid rim test's 700 s). A search
// leases a set for its lifetime; a search started inside another (none today) leases the
// next set.
class ScratchLease
{
public:
  ScratchLease()
  {
    if (InUse == Sets.size())
      Sets.push_back(std::make_unique<std::deque<ScratchLevel>>());
    Set = Sets[InUse++].get();
  }
  ~ScratchLease() { --InUse; }
  ScratchLease(const ScratchLease&) = delete;
  ScratchLease& operator=(const ScratchLease&) = delete;
  /// Level `l`'s polynomials (a deque: growing it keeps the other levels in place).
  ScratchLevel& at(int l)
  {
    while (Set->size() <= static_cast<size_t>(l))
      Set->emplace_back();
    return (*Set)[l];
  }

private:
  std::deque<ScratchLevel>* Set;
  static thread_local std::vector<std::unique_ptr<std::deque<ScratchLevel>>> Sets;
  static thread_local size_t InUse;
};
thread_local std::vector<std::unique_ptr<std::deque<ScratchLevel>>> ScratchLease::Sets;
thread_local size_t ScratchLease::InUse = 0;

// |S − P|²·w² = Σ_k (X_k − P_k·w)², with X centred on the patch: Σ X_k² − 2·Σ P_k·X_k·w +
// |P|²·w², whose products are the patch's alone (as the stationarity polynomials' are).
struct BallBasis : PatchKey
{
  BernsteinPoly2 xx, xw[3], ww;
};

std::unique_ptr<BallBasis> ballBasis(const BezierPatch& patch)
{
  const CentredCoordinates c = centredCoordinates(patch);
  auto b = std::make_unique<BallBasis>();
  static_cast<PatchKey&>(*b) = c;
  b->xx = c.x[0] * c.x[0] + c.x[1] * c.x[1] + c.x[2] * c.x[2];
  for (int k = 0; k < 3; ++k)
    b->xw[k] = c.x[k] * c.w;
  b->ww = c.w * c.w;
  return b;
}

// |S − P|²·w² − R²·w² in Bernstein form (S = X / w the patch, P the query): negative
// exactly where the patch enters the ball of radius R about P. `zero` receives its
// rounding level.
BernsteinPoly2 ballPolynomial(const BezierPatch& patch, const Vec3& query, double radius, double* zero = nullptr)
{
  const BallBasis& b = cachedBasis<BallBasis, 128>(patch, ballBasis);
  const Vec3 c = query - b.centre;
  const double cc = c.squaredNorm(), rr = radius * radius;
  BernsteinPoly2 ball = b.xx;
  double squaresMax = 0.0, wwMax = 0.0;
  for (size_t n = 0; n < ball.c.size(); ++n)
  {
    const double squares =
      b.xx.c[n] - 2.0 * (c(0) * b.xw[0].c[n] + c(1) * b.xw[1].c[n] + c(2) * b.xw[2].c[n]) + cc * b.ww.c[n];
    squaresMax = std::max(squaresMax, std::abs(squares));
    wwMax = std::max(wwMax, std::abs(b.ww.c[n]));
    ball.c[n] = squares - rr * b.ww.c[n];
  }
  if (zero)
    *zero = 1e-12 * (squaresMax + rr * wwMax);
  return ball;
}

// The ball polynomial's stand-in for a box wholly inside the ball (PatchSearch::search).
const BernsteinPoly2 InsideBall;

struct PatchSearch
{
  PatchSearch(const BezierPatch& patch_, const Vec3& q_, double maxDistance_, double zeroU_, double zeroV_, int limit_)
    : patch(patch_)
    , q(q_)
    , maxDistance(maxDistance_)
    , zeroU(zeroU_)
    , zeroV(zeroV_)
    , limit(limit_)
  {
  }
  const BezierPatch& patch;
  const Vec3& q;
  double maxDistance;
  double zeroU, zeroV;
  std::vector<PatchFootpoint> found;
  int boxes = 0;
  int limit = MaxPatchBoxes;
  /// Collapsed sides (0: v = 0, 1: u = 1, 2: v = 1, 3: u = 0), each one point: a pole.
  std::array<bool, 4> collapsed{ { false, false, false, false } };
  std::array<Vec3, 4> pole;  ///< each collapsed side's point
  double size = 0.0;         ///< the patch's bounding box diagonal
  /// With a finite maxDistance: the ball polynomial of radius maxDistance on the whole
  /// patch and its rounding; a box on which it is positive lies outside the ball.
  bool byBall = false;
  BernsteinPoly2 ball; ///< built when a box first needs it
  bool ballBuilt = false;
  double zeroD = 0.0;
  ScratchLease scratch;

  void add(double u, double v)
  {
    PatchFootpoint f;
    f.u = u;
    f.v = v;
    f.point = patch.evaluate(u, v);
    f.distance = (f.point - q).norm();
    if (f.distance <= maxDistance)
    {
      found.push_back(f);
    }
  }

  void search(const BernsteinPoly2& gu, const BernsteinPoly2& gv, const BernsteinPoly2* gd, double u0,
    double u1, double v0, double v1, int depthU, int depthV, int poleCuts)
  {
    const int depth = std::max(depthU, depthV);
    // The bound on the work: a curve of stationary points that Newton cannot settle would
    // otherwise cost 2^depth boxes. Past it, boxes are dropped (the patch's border curves
    // are searched separately and carry such curves where they end).
    ++Work;
    if (++boxes > limit)
    {
      CutShort += boxes == limit + 1 ? 1 : 0;
      return;
    }
    if (gu.hasStrictSign(zeroU) || gv.hasStrictSign(zeroV))
    {
      return;
    }
    // Outside the ball of radius maxDistance: first by the ball polynomial's coefficients
    // (tight on small boxes: next to an osculating touch, where the distance grows only as
    // the fourth power across the ridge, gu and gv stay undecided along a ribbon that
    // squares would have to follow to 1e-7 for 0.4 of the patch, but the distance there is
    // past maxDistance in a few levels), then by the sub-patch's bounding box (tighter on
    // large boxes).
    // (The ball polynomial only from the depth where boxes are small enough for it to
    // decide: restricted from the patch's once there, then split with the box. Above, it
    // cost a third more per box and pruned nothing the bounding boxes do not.)
    if (byBall && !gd && depth >= DegenerateCheckDepth)
    {
      if (!ballBuilt)
      {
        ball = ballPolynomial(patch, q, maxDistance, &zeroD);
        ballBuilt = true;
      }
      BernsteinPoly2& own = scratch.at(depthU + depthV + poleCuts).own;
      own = ball.restrictedTo(u0, u1, v0, v1);
      gd = &own;
    }
    // Wholly inside the ball, so is every part of the box: the polynomial can prune
    // nothing below, and is not carried (a clean foot's neighbourhood, most deep boxes);
    // the children get InsideBall to say so.
    bool inside = gd == &InsideBall;
    if (gd && !inside)
    {
      const auto [lo, hi] = std::minmax_element(gd->c.begin(), gd->c.end());
      if (*lo > zeroD)
        return;
      inside = *hi < -zeroD;
    }
    if (inside)
      gd = nullptr;
    auto childBall = [&](BernsteinPoly2& part) -> const BernsteinPoly2* { return gd ? &part : inside ? &InsideBall : nullptr; };
    if (!inside && std::isfinite(maxDistance) &&
      distanceToBox(patch.subPatchBox(u0, u1, v0, v1), q) > maxDistance)
    {
      return;
    }
    // Within 1e-9 of a pole in the parameters (30 cuts across its side), below the
    // polynomials' rounding (a query 1e-12 from the pole): the box is stationary to
    // rounding in one direction at least, and Newton from its middle stands for it
    // (subdividing it would only follow the rounding). Not farther out: an osculating
    // ball's touch is flat to fourth order, and a point merely stationary to rounding
    // there is 1e-9 too far.
    if (poleCuts >= NearPoleCuts && (gu.maxAbs() <= 4.0 * zeroU || gv.maxAbs() <= 4.0 * zeroV))
    {
      double u = 0.5 * (u0 + u1), v = 0.5 * (v0 + v1);
      if (newtonPatch(patch, q, u, v, u0, u1, v0, v1, nullptr, true))
        add(u, v);
      return;
    }
    // Interval Jacobian of (gu, gv): if its determinant cannot vanish, the box holds at most
    // one stationary point and Newton from the centre is tried (row-wise mean value theorem).
    const Interval a = derivativeBounds(gu, true), b = derivativeBounds(gu, false);
    const Interval c = derivativeBounds(gv, true), d = derivativeBounds(gv, false);
    const Interval ad = mul(a, d), bc = mul(b, c);
    const bool unique = (ad.lo - bc.hi > 0.0) || (ad.hi - bc.lo < 0.0);
    if (unique || depth >= MaxPatchDepth || depth >= DegenerateCheckDepth)
    {
      double u = 0.5 * (u0 + u1), v = 0.5 * (v0 + v1);
      bool degenerate = false;
      const bool deep = depth >= DegenerateCheckDepth && !unique;
      if (newtonPatch(patch, q, u, v, u0, u1, v0, v1, &degenerate, deep) &&
        (unique || degenerate || depth >= MaxPatchDepth))
      {
        // A box that still holds stationary points this deep and whose Newton limit is a
        // degenerate minimum lies on a curve of minima: one point of it stands for the
        // box (subdividing along the curve would cost 2^depth boxes).
        const size_t before = found.size();
        add(u, v);
        if (degenerate && !unique && found.size() > before)
        {
          found.back().continuum = true;
        }
        return;
      }
      if (depth >= MaxPatchDepth)
      {
        return;
      }
    }
    // A box on a pole's collapsed side is split across the side only: in the pole's
    // parameters (angle × distance from it) a query beside the pole leaves both
    // polynomials small along the whole side, and quartering would multiply the boxes
    // along it at every level down to the query's distance from the pole (the box limit).
    // Cut across, each level adds one box on the side and one ring beyond it; such cuts
    // do not count as depth (a query 1e-12 from the pole needs 40 of them: the foot's
    // distance from the side in the parameters), their number is bounded on its own.
    // Only while the query is within the box's reach of the pole: farther, the pole's
    // neighbourhood is an ordinary corner of the search, which quartering prunes in a few
    // boxes (the sign of (S − P)·S_v settles once the box spans little angle), while cuts
    // across the side, never narrowing the angle, would go on to the pole.
    const double extentV = (v1 - v0) * size, extentU = (u1 - u0) * size;
    auto near = [&](int side, double extent) { return collapsed[side] && (q - pole[side]).norm() < 4.0 * extent; };
    const bool acrossV = (v0 == 0.0 && near(0, extentV)) || (v1 == 1.0 && near(2, extentV));
    const bool acrossU = (u0 == 0.0 && near(3, extentU)) || (u1 == 1.0 && near(1, extentU));
    if (poleCuts >= MaxPoleCuts)
      return; // within rounding of the pole: its side's own search has it
    // The children's polynomials live in this level's scratch: the search goes depth
    // first, so a level's parts are free again once their boxes are done.
    // (Every nested call adds to depthU + depthV + poleCuts: a level per nesting.)
    ScratchLevel& parts = scratch.at(depthU + depthV + poleCuts);
    if (acrossV != acrossU)
    {
      BernsteinPoly2 &lu = parts.u[0], &hu = parts.u[1], &lv = parts.v[0], &hv = parts.v[1];
      BernsteinPoly2 &ld = parts.d[0], &hd = parts.d[1];
      const double m = acrossU ? u0 + SplitAt * (u1 - u0) : v0 + SplitAt * (v1 - v0);
      gu.split(SplitAt, acrossU, lu, hu);
      gv.split(SplitAt, acrossU, lv, hv);
      if (gd)
        gd->split(SplitAt, acrossU, ld, hd);
      const BernsteinPoly2 *pld = childBall(ld), *phd = childBall(hd);
      if (acrossU)
      {
        search(lu, lv, pld, u0, m, v0, v1, depthU, depthV, poleCuts + 1);
        search(hu, hv, phd, m, u1, v0, v1, depthU, depthV, poleCuts + 1);
      }
      else
      {
        search(lu, lv, pld, u0, u1, v0, m, depthU, depthV, poleCuts + 1);
        search(hu, hv, phd, u0, u1, m, v1, depthU, depthV, poleCuts + 1);
      }
      return;
    }
    const double um = u0 + SplitAt * (u1 - u0), vm = v0 + SplitAt * (v1 - v0);
    // Deep and still undecided within a distance bound (counting a ball's touchpoints):
    // next to a degenerate minimum (an osculating ball's touch, flat to fourth order
    // across the ridge) gu = 0 and gv = 0 are curves tangent at the foot and close along
    // a ribbon beside it. At t from the foot a box shows its sign only when about t long
    // along the ribbon and t² across, and squares t² wide along 0.1 of a ribbon took the
    // whole box budget (200,000) before reaching the foot. Halve instead the direction in
    // which the polynomial nearer a strict sign varies most, while it varies far more
    // that way.
    if (byBall && depth >= DegenerateCheckDepth)
    {
      const int along = anisotropicSplit(gu, gv);
      if (along != 0)
      {
        const bool alongU = along > 0;
        gu.split(SplitAt, alongU, parts.u[0], parts.u[1]);
        gv.split(SplitAt, alongU, parts.v[0], parts.v[1]);
        if (gd)
          gd->split(SplitAt, alongU, parts.d[0], parts.d[1]);
        const BernsteinPoly2 *d0 = childBall(parts.d[0]), *d1 = childBall(parts.d[1]);
        if (alongU)
        {
          search(parts.u[0], parts.v[0], d0, u0, um, v0, v1, depthU + 1, depthV, poleCuts);
          search(parts.u[1], parts.v[1], d1, um, u1, v0, v1, depthU + 1, depthV, poleCuts);
        }
        else
        {
          search(parts.u[0], parts.v[0], d0, u0, u1, v0, vm, depthU, depthV + 1, poleCuts);
          search(parts.u[1], parts.v[1], d1, u0, u1, vm, v1, depthU, depthV + 1, poleCuts);
        }
        return;
      }
    }
    BernsteinPoly2(&pu)[4] = parts.u;
    BernsteinPoly2(&pv)[4] = parts.v;
    BernsteinPoly2(&pd)[4] = parts.d;
    gu.quarter(SplitAt, SplitAt, pu);
    gv.quarter(SplitAt, SplitAt, pv);
    if (gd)
      gd->quarter(SplitAt, SplitAt, pd);
    auto child = [&](int k) { return childBall(pd[k]); };
    search(pu[0], pv[0], child(0), u0, um, v0, vm, depthU + 1, depthV + 1, poleCuts);
    search(pu[1], pv[1], child(1), um, u1, v0, vm, depthU + 1, depthV + 1, poleCuts);
    search(pu[2], pv[2], child(2), u0, um, vm, v1, depthU + 1, depthV + 1, poleCuts);
    search(pu[3], pv[3], child(3), um, u1, vm, v1, depthU + 1, depthV + 1, poleCuts);
  }
};

} // namespace

namespace
{
std::vector<PatchFootpoint> withSideMinima(
  const BezierPatch& patch, const Vec3& query, double maxDistance, std::vector<PatchFootpoint> result);

std::vector<PatchFootpoint> pieceFootpoints(const BezierPatch& patch, const Vec3& query,
  double maxDistance, int* boxBudget = nullptr)
{
  std::vector<PatchFootpoint> result;
  if (distanceToBox(patch.boundingBox(), query) > maxDistance)
  {
    return result;
  }
  const PatchPolys pp = patchPolys(patch, query);
  PatchSearch search(patch, query, maxDistance, pp.zeroU, pp.zeroV,
    boxBudget ? std::max(1, std::min(*boxBudget, BoxLimit)) : BoxLimit);
  const bool flatU = pp.gu.maxAbs() <= pp.zeroU, flatV = pp.gv.maxAbs() <= pp.zeroV;
  // (Every point stationary to 1e-10 of the patch's scale: the query is within about that
  // of the centre of a sphere the patch lies on — a blend's centre found by bisection, not
  // to rounding — and every point is its foot to as much; searching would follow the
  // rounding over the whole patch, 200,000 boxes.)
  if ((flatU && flatV) || (pp.gu.maxAbs() <= 1e3 * pp.zeroU && pp.gv.maxAbs() <= 1e3 * pp.zeroV))
  {
    search.add(0.5, 0.5); // the query is a centre of the whole patch (a sphere's centre)
    for (PatchFootpoint& f : search.found)
    {
      f.continuum = true;
    }
    return search.found;
  }
  if (flatU || flatV)
  {
    // Distance constant along one parameter (a query on a surface of revolution's axis):
    // solve along the other parameter's iso-line through the middle.
    const BezierCurve iso = flatU ? patch.subPatch(0.5, 0.5, 0, 1).side(3).reversed()
                                  : patch.subPatch(0, 1, 0.5, 0.5).side(0);
    for (const CurveFootpoint& c : curveFootpoints(iso, query, maxDistance))
    {
      PatchFootpoint f;
      f.u = flatU ? 0.5 : c.t;
      f.v = flatU ? c.t : 0.5;
      f.point = c.point;
      f.distance = c.distance;
      f.onBoundary = c.atEnd;
      f.continuum = true;
      result.push_back(f);
    }
    return result;
  }
  // A swept patch (an extrusion's side, a cylinder between slanted sections): its interior
  // minima from the profile's footpoints, a 1D search (SweptPatch.h).
  if (const std::optional<SweptPatch> swept = sweptPatch(patch))
    return withSideMinima(patch, query, maxDistance, sweptInteriorFootpoints(*swept, query, maxDistance));
  BernsteinPoly2 gu = pp.gu, gv = pp.gv;
  // (The control points of a side all one point: a pole. Sides 0 … 3 are v = 0, u = 1,
  // v = 1, u = 0.)
  const double size = patch.boundingBox().diagonal().norm();
  search.size = size;
  for (int side = 0; side < 4; ++side)
  {
    const bool alongU = side % 2 == 0;
    const int fixed = side == 1 ? patch.degreeU() : side == 2 ? patch.degreeV() : 0;
    auto point = [&](int k) { return alongU ? patch.controlPoint(k, fixed) : patch.controlPoint(fixed, k); };
    const Vec3 first = point(0);
    bool one = true;
    for (int k = 1; k <= (alongU ? patch.degreeU() : patch.degreeV()) && one; ++k)
      one = (point(k) - first).norm() <= 1e-14 * size;
    search.collapsed[side] = one;
    search.pole[side] = first;
  }
  // A side along which the query's stationarity holds identically (the query at a pole:
  // the collapsed side is all at distance 0) is divided out of gu and gv, or the search
  // subdivides along it to its box limit (~1 s) for the one foot the side searches below
  // find anyway. Interior stationary points are unchanged.
  for (auto [g, zero] : { std::pair{ &gu, &search.zeroU }, std::pair{ &gv, &search.zeroV } })
  {
    for (int side = 0; side < 4; ++side)
    {
      const bool alongU = side % 2 == 1, atOne = side == 1 || side == 2;
      for (int n = 0; (n = g->divideBySide(alongU, atOne, *zero)) > 0;)
      {
        *zero *= n;
      }
    }
  }
  search.byBall = std::isfinite(maxDistance);
  search.search(gu, gv, nullptr, 0.0, 1.0, 0.0, 1.0, 0, 0, 0);
  if (boxBudget)
    *boxBudget -= search.boxes;
  return withSideMinima(patch, query, maxDistance, search.found);
}

// The interior minima `result` with the minima on the patch's sides, deduplicated, nearest
// first.
std::vector<PatchFootpoint> withSideMinima(
  const BezierPatch& patch, const Vec3& query, double maxDistance, std::vector<PatchFootpoint> result)
{
  // Minima on the boundary: minima of the side curves where moving inwards does not get
  // closer, i.e. the inward derivative of the squared distance is ≥ 0.
  for (int s = 0; s < 4; ++s)
  {
    for (const CurveFootpoint& c : curveFootpoints(patch.side(s), query, maxDistance))
    {
      PatchFootpoint f;
      const Vec2 uv = BezierPatch::sideParameter(s, c.t);
      f.u = uv.x();
      f.v = uv.y();
      const SurfaceDerivatives d = patch.derivatives(f.u, f.v);
      const Vec3 r = d.point - query;
      const double inward =
        (s == 0) ? r.dot(d.sv) : (s == 1) ? -r.dot(d.su) : (s == 2) ? -r.dot(d.sv) : r.dot(d.su);
      const double scale = 1e-10 * (r.norm() + 1.0) * (d.su.norm() + d.sv.norm());
      if (inward < -scale && !c.continuum)
      {
        continue;
      }
      f.point = c.point;
      f.distance = c.distance;
      f.onBoundary = true;
      f.continuum = c.continuum;
      result.push_back(f);
    }
  }
  // Dedupe by position (corners come from two sides; Newton from neighbouring boxes).
  std::sort(result.begin(), result.end(),
    [](const PatchFootpoint& a, const PatchFootpoint& b) { return a.distance < b.distance; });
  std::vector<PatchFootpoint> unique;
  const double diag = patch.boundingBox().diagonal().norm();
  for (const PatchFootpoint& f : result)
  {
    bool seen = false;
    for (PatchFootpoint& g : unique)
    {
      // Points of one degenerate minimum (found in neighbouring deep boxes) are one.
      const double near = f.continuum && g.continuum ? 4.0 / (1 << DegenerateCheckDepth) : 1e-9;
      if ((f.point - g.point).norm() <= 1e-9 * (1.0 + diag) ||
        (std::abs(f.u - g.u) < near && std::abs(f.v - g.v) < near))
      {
        g.onBoundary = g.onBoundary && f.onBoundary;
        seen = true;
        break;
      }
    }
    if (!seen)
    {
      unique.push_back(f);
    }
  }
  return unique;
}

// Lengths of the control net along u and along v (the longest row / column).
void netExtents(const BezierPatch& patch, double& lu, double& lv)
{
  lu = lv = 0.0;
  for (int j = 0; j <= patch.degreeV(); ++j)
  {
    double l = 0.0;
    for (int i = 0; i < patch.degreeU(); ++i)
      l += (patch.controlPoint(i + 1, j) - patch.controlPoint(i, j)).norm();
    lu = std::max(lu, l);
  }
  for (int i = 0; i <= patch.degreeU(); ++i)
  {
    double l = 0.0;
    for (int j = 0; j < patch.degreeV(); ++j)
      l += (patch.controlPoint(i, j + 1) - patch.controlPoint(i, j)).norm();
    lv = std::max(lv, l);
  }
}

constexpr double MaxPieceAspect = 512.0;
constexpr int MaxPieces = 4096;

// An elongated patch (the side of an extrusion 1e6 times longer than its profile) has
// distance polynomials whose rounding, set by the far end, drowns the short direction
// near the query: the search is run on pieces cut along the long direction until they
// are no more elongated than MaxPieceAspect, nearest first, keeping only pieces within
// reach (with `nearestOnly`, within the nearest distance found so far). Minima that a
// piece finds on a cut are kept only where the whole patch is stationary there too.
std::vector<PatchFootpoint> elongatedFootpoints(
  const BezierPatch& patch, const Vec3& query, double maxDistance, bool nearestOnly)
{
  struct Piece
  {
    double gap, u0, u1, v0, v1;
    bool operator<(const Piece& o) const { return gap > o.gap; } // nearest on top
  };
  std::priority_queue<Piece> queue;
  queue.push({ distanceToBox(patch.boundingBox(), query), 0.0, 1.0, 0.0, 1.0 });
  std::vector<PatchFootpoint> found;
  // One budget of boxes for all pieces: a search that cannot settle (a side 1e9 times
  // thinner than long) stays bounded like one patch's.
  int boxBudget = MaxPatchBoxes;
  for (int pieces = 0; !queue.empty() && pieces < MaxPieces && boxBudget > 0;)
  {
    const Piece c = queue.top();
    queue.pop();
    if (c.gap > maxDistance)
      break; // the rest are farther still
    const BezierPatch sub = patch.subPatch(c.u0, c.u1, c.v0, c.v1);
    double lu = 0.0, lv = 0.0;
    netExtents(sub, lu, lv);
    // A piece far from the query for its length is conditioned by that distance, not by
    // its far end: cutting it finer only multiplies the pieces (a query 1e-2 from a side
    // 1e-12 wide would visit 1e7 of them).
    if ((lu > MaxPieceAspect * lv || lv > MaxPieceAspect * lu) && std::max(lu, lv) > 4.0 * c.gap)
    {
      const bool alongU = lu > lv;
      const double mu = 0.5 * (c.u0 + c.u1), mv = 0.5 * (c.v0 + c.v1);
      for (const Piece& h : { alongU ? Piece{ 0, c.u0, mu, c.v0, c.v1 } : Piece{ 0, c.u0, c.u1, c.v0, mv },
             alongU ? Piece{ 0, mu, c.u1, c.v0, c.v1 } : Piece{ 0, c.u0, c.u1, mv, c.v1 } })
      {
        Piece q = h;
        q.gap = distanceToBox(patch.subPatch(q.u0, q.u1, q.v0, q.v1).boundingBox(), query);
        if (q.gap <= maxDistance)
          queue.push(q);
      }
      continue;
    }
    ++pieces;
    for (PatchFootpoint f : pieceFootpoints(sub, query, maxDistance, &boxBudget))
    {
      f.u = c.u0 + f.u * (c.u1 - c.u0);
      f.v = c.v0 + f.v * (c.v1 - c.v0);
      if (f.onBoundary)
      {
        // On a cut (not the patch's own border): a minimum of the patch only if the
        // derivative across the cut vanishes.
        const bool cutU = (f.u > 0.0 && f.u < 1.0) && (f.u == c.u0 || f.u == c.u1);
        const bool cutV = (f.v > 0.0 && f.v < 1.0) && (f.v == c.v0 || f.v == c.v1);
        if (cutU || cutV)
        {
          const SurfaceDerivatives d = patch.derivatives(f.u, f.v);
          const Vec3 r = d.point - query;
          // (r is known only to the rounding of the coordinates it is the difference of: a
          // bar 1e6 long has its foot's along-coordinate off by 1e-10, which is not small
          // against 1e-9 of a short distance across the cut.)
          const double slack = 1e-9 * r.norm() + 1e-14 * (d.point.norm() + query.norm());
          const bool stationary = (!cutU || std::abs(r.dot(d.su)) <= slack * d.su.norm()) &&
            (!cutV || std::abs(r.dot(d.sv)) <= slack * d.sv.norm());
          if (!stationary && !f.continuum)
            continue;
          const bool onBorder = f.u == 0.0 || f.u == 1.0 || f.v == 0.0 || f.v == 1.0;
          f.onBoundary = onBorder;
        }
      }
      found.push_back(f);
      if (nearestOnly)
        maxDistance = std::min(maxDistance, f.distance);
    }
  }
  // Pieces within reach left unsearched (the shared budget or the piece count spent):
  // this search was cut short too.
  if (!queue.empty() && queue.top().gap <= maxDistance && boxBudget > 0)
    ++CutShort;
  std::sort(found.begin(), found.end(),
    [](const PatchFootpoint& a, const PatchFootpoint& b) { return a.distance < b.distance; });
  std::vector<PatchFootpoint> unique;
  for (const PatchFootpoint& f : found)
  {
    // The same minimum from the pieces on both sides of a cut: one.
    const bool seen = std::any_of(unique.begin(), unique.end(), [&](const PatchFootpoint& g) {
      return (f.point - g.point).norm() <= 1e-9 * (f.distance + 1e-300) ||
        (std::abs(f.u - g.u) < 1e-12 && std::abs(f.v - g.v) < 1e-12);
    });
    if (!seen && f.distance <= maxDistance)
      unique.push_back(f);
  }
  return unique;
}

bool elongated(const BezierPatch& patch)
{
  double lu = 0.0, lv = 0.0;
  netExtents(patch, lu, lv);
  return lu > MaxPieceAspect * lv || lv > MaxPieceAspect * lu;
}
} // namespace

std::vector<PatchFootpoint> patchFootpoints(
  const BezierPatch& patch, const Vec3& query, double maxDistance)
{
  if (distanceToBox(patch.boundingBox(), query) > maxDistance)
    return {};
  return elongated(patch) ? elongatedFootpoints(patch, query, maxDistance, false)
                          : pieceFootpoints(patch, query, maxDistance);
}

namespace
{
// h = |A − P·w|² − r²·w² on a sub-box of the patch: negative somewhere? The coefficients
// bound h; corners and the centre are values of h; below the first levels, convexity
// decides (byConvexity); else split in u and v in turn until the sign is decided or the
// box is 2^-24 of the patch, where the patch lies within rounding of the sphere: that
// counts as not inside.
struct ComesWithin
{
  ScratchLease scratch;
  /// Work at which the search stops (the thread's box limit from its start): a tangency
  /// along a curve of a singular parameterisation (a cone's apex, where a centre curve's
  /// balls shrink) leaves boxes undecided down to depth 24 along the whole curve, 2^24 of
  /// them. Past it the undecided rest counts as not inside, as at depth 24.
  std::uint64_t end = 0;
  bool cutShort = false;

  // The sign of h on the box decided by convexity: where the Bernstein bounds of its
  // Hessian prove it positive definite over the (convex) box, h lies above its tangent
  // plane at any point X of it, h(Y) ≥ h(X) + ∇h(X)·(Y − X); X is the box's minimiser
  // approached by projected Newton from the box's centre, so that plane's
  // least value over the box is close to h's. 1: h ≥ 0 on the box, −1: h(X) < 0, 0: not
  // decided (not convex here: split).
  int byConvexity(const BernsteinPoly2& h, Vec2 x)
  {
    // The Hessian's bounds from second differences of the coefficients (h_uu's Bernstein
    // coefficients are nu(nu − 1)·Δ²_u c, h_uv's nu·nv·Δ_u Δ_v c), refused at the first
    // that fails: along a circle of tangency, as on a torus, h is flat in one direction
    // and never convex, and this test runs on every box there.
    const int nu = h.nu, nv = h.nv;
    double aLo = INFINITY, cLo = INFINITY, bMax = 0.0;
    if (nu >= 2)
      for (int i = 0; i + 2 <= nu; ++i)
        for (int j = 0; j <= nv; ++j)
          if (!((aLo = std::min(aLo, h.at(i + 2, j) - 2.0 * h.at(i + 1, j) + h.at(i, j))) > 0.0))
            return 0;
    if (nv >= 2)
      for (int i = 0; i <= nu; ++i)
        for (int j = 0; j + 2 <= nv; ++j)
          if (!((cLo = std::min(cLo, h.at(i, j + 2) - 2.0 * h.at(i, j + 1) + h.at(i, j))) > 0.0))
            return 0;
    if (nu < 2 || nv < 2)
      return 0;
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j)
        bMax = std::max(bMax, std::abs(h.at(i + 1, j + 1) - h.at(i + 1, j) - h.at(i, j + 1) + h.at(i, j)));
    aLo *= nu * (nu - 1.0);
    cLo *= nv * (nv - 1.0);
    bMax *= double(nu) * nv;
    if (!(aLo * cLo > bMax * bMax))
      return 0;
    if (nu > 64 || nv > 64)
      return 0;
    // Newton towards the box's minimiser, kept in the box; the bound checked at each step.
    for (int it = 0; it < 4; ++it)
    {
      const std::array<double, 6> j = h.jet(x.x(), x.y());
      if (j[0] < 0.0)
        return -1;
      const double least = j[0] + std::min(-j[1] * x.x(), j[1] * (1.0 - x.x())) + std::min(-j[2] * x.y(), j[2] * (1.0 - x.y()));
      if (least >= 0.0)
        return 1;
      const double det = j[3] * j[5] - j[4] * j[4];
      const Vec2 next = (x - Vec2(j[5] * j[1] - j[4] * j[2], j[3] * j[2] - j[4] * j[1]) / det).cwiseMax(0.0).cwiseMin(1.0);
      if (!next.allFinite() || (next - x).lpNorm<Eigen::Infinity>() <= 1e-12)
        return 0;
      x = next;
    }
    return 0;
  }

  bool negativeSomewhere(const BernsteinPoly2& h, int depthU, int depthV)
  {
    if (++Work > end)
    {
      cutShort = true;
      return false;
    }
    const auto [mn, mx] = std::minmax_element(h.c.begin(), h.c.end());
    (void)mx;
    if (*mn >= 0.0)
      return false;
    if (h.at(0, 0) < 0.0 || h.at(h.nu, 0) < 0.0 || h.at(0, h.nv) < 0.0 || h.at(h.nu, h.nv) < 0.0)
      return true;
    if (h(0.5, 0.5) < 0.0)
      return true;
    // (Not on the first levels: a box that large is rarely convex, and the Hessian's
    // bounds cost a split's work.)
    if (depthU + depthV >= 2)
    {
      if (const int sign = byConvexity(h, Vec2(0.5, 0.5)); sign != 0)
        return sign < 0;
    }
    const bool splitU = depthU <= depthV;
    if ((splitU ? depthU : depthV) >= 24)
      return false;
    // Both halves in one de Casteljau pass per row (or column), into this level's scratch.
    ScratchLevel& level = scratch.at(depthU + depthV);
    BernsteinPoly2 &a = level.u[0], &b = level.u[1];
    h.split(0.5, splitU, a, b);
    const int du = depthU + (splitU ? 1 : 0), dv = depthV + (splitU ? 0 : 1);
    return negativeSomewhere(a, du, dv) || negativeSomewhere(b, du, dv);
  }
};
} // namespace

bool patchComesWithin(const BezierPatch& patch, const Vec3& query, double radius)
{
  if (!(radius > 0.0) || distanceToBox(patch.boundingBox(), query) >= radius)
    return false;
  // A swept patch's nearest point directly (SweptPatch.h): near a slanted cylinder's axis
  // the sign test meets a tangency along a curve across both parameters, box by box.
  if (const std::optional<SweptPatch> swept = sweptPatch(patch))
  {
    const std::vector<PatchFootpoint> near =
      withSideMinima(patch, query, radius, sweptInteriorFootpoints(*swept, query, radius));
    return !near.empty() && near.front().distance < radius;
  }
  ComesWithin search;
  search.end = Work + static_cast<std::uint64_t>(BoxLimit);
  const bool within = search.negativeSomewhere(ballPolynomial(patch, query, radius), 0, 0);
  CutShort += search.cutShort ? 1 : 0;
  return within;
}

std::uint64_t patchSearchWork()
{
  return Work;
}

std::uint64_t patchSearchesCutShort()
{
  return CutShort;
}

PatchSearchLimit::PatchSearchLimit(int boxes)
  : Previous(BoxLimit)
{
  BoxLimit = std::max(1, std::min(boxes, BoxLimit));
}

PatchSearchLimit::~PatchSearchLimit()
{
  BoxLimit = Previous;
}

std::optional<PatchFootpoint> localFootpoint(const BezierPatch& patch, const Vec3& query, const Vec2& start,
  double settled)
{
  Vec2 q = start;
  for (int iteration = 0; iteration < 24; ++iteration)
  {
    const SurfaceDerivatives d = patch.derivatives(q.x(), q.y());
    PatchFootpoint f;
    f.u = q.x();
    f.v = q.y();
    f.point = d.point;
    f.distance = (d.point - query).norm();
    if (f.distance <= settled)
      return f; // on the patch (at a collapsed side too, where the parameters are not unique)
    Eigen::Matrix<double, 3, 2> J;
    J << d.su, d.sv;
    const Eigen::Matrix2d normal = J.transpose() * J;
    if (!(normal.determinant() > 1e-12 * normal.squaredNorm()))
      return std::nullopt; // a pole or a collapsed side: no unique parameters here
    const Vec2 next = (q + normal.ldlt().solve(-J.transpose() * (d.point - query))).cwiseMax(0.0).cwiseMin(1.0);
    // (Settled when the step is within the rounding on the patch too: far from the origin
    // that is more than 1e-12 of the size, and across a sliver piece 1e-4 wide a parameter
    // step that small is never reached.)
    const bool converged = (next - q).norm() <= 1e-12 || (J * (next - q)).norm() <= settled;
    q = next;
    if (!converged)
      continue;
    // Kept in the square, it may have settled on a side the foot lies beyond: then the
    // distance still falls outwards (S − P is not normal to the patch there).
    const SurfaceDerivatives e = patch.derivatives(q.x(), q.y());
    const Vec3 r = e.point - query;
    const double tangential = std::hypot(r.dot(e.su) / e.su.norm(), r.dot(e.sv) / e.sv.norm());
    if (!(tangential <= 1e-6 * r.norm() + settled))
      return std::nullopt;
    f.u = q.x();
    f.v = q.y();
    f.point = e.point;
    f.distance = r.norm();
    f.onBoundary = q.minCoeff() == 0.0 || q.maxCoeff() == 1.0;
    return f;
  }
  return std::nullopt;
}

std::optional<PatchFootpoint> closestPointWithin(const BezierPatch& patch, const Vec3& query, double bound)
{
  if (distanceToBox(patch.boundingBox(), query) > bound)
    return std::nullopt;
  const std::vector<PatchFootpoint> fps = elongated(patch) ? elongatedFootpoints(patch, query, bound, true)
                                                           : pieceFootpoints(patch, query, bound);
  if (fps.empty())
    return std::nullopt;
  return fps.front();
}

PatchFootpoint closestPoint(const BezierPatch& patch, const Vec3& query)
{
  const std::vector<PatchFootpoint> fps = elongated(patch)
    ? elongatedFootpoints(patch, query, Unbounded, true)
    : pieceFootpoints(patch, query, Unbounded);
  if (!fps.empty())
  {
    return fps.front();
  }
  PatchFootpoint f;
  f.point = patch.evaluate(0, 0);
  f.distance = (f.point - query).norm();
  f.onBoundary = true;
  return f;
}

} // namespace exactmat

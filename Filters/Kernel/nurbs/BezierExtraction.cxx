#include "BezierExtraction.h"

#include "common/InputError.h"

#include <algorithm>

namespace exactmat
{

namespace
{
// Distinct knot values inside the domain [knots[p], knots[count]].
std::vector<double> domainBreaks(const KnotVector& knots, int p, int count)
{
  std::vector<double> b;
  for (int i = p; i <= count; ++i)
  {
    if (b.empty() || knots[i] != b.back())
    {
      b.push_back(knots[i]);
    }
  }
  return b;
}

// Raises every domain break to multiplicity ≥ p on `lines` interleaved control polygons.
void raiseToBezier(KnotVector& knots, int p, Vec4List& points, int lines)
{
  const int count = static_cast<int>(points.size()) / lines;
  for (double u : domainBreaks(knots, p, count))
  {
    for (int s = multiplicity(knots, u); s < p; ++s)
    {
      insertKnot(knots, p, points, lines, u);
    }
  }
}

// Index a of each non-empty span [knots[a], knots[a+1]] inside the domain.
std::vector<int> spanStarts(const KnotVector& knots, int p, int count)
{
  std::vector<int> starts;
  for (int a = p; a < count; ++a)
  {
    if (knots[a] < knots[a + 1])
    {
      starts.push_back(a);
    }
  }
  return starts;
}

Vec4List transpose(const Vec4List& net, int rows, int cols)
{
  Vec4List t(net.size());
  for (int i = 0; i < rows; ++i)
  {
    for (int j = 0; j < cols; ++j)
    {
      t[j * rows + i] = net[i * cols + j];
    }
  }
  return t;
}
} // namespace

std::vector<BezierSpan> extractBezier(const NurbsCurve& curve)
{
  const int p = curve.degree();
  KnotVector knots = curve.knots();
  Vec4List points = curve.homogeneousPoints();
  raiseToBezier(knots, p, points, 1);
  std::vector<BezierSpan> spans;
  for (int a : spanStarts(knots, p, static_cast<int>(points.size())))
  {
    BezierSpan s;
    s.curve = BezierCurve(Vec4List(points.begin() + (a - p), points.begin() + a + 1));
    s.t0 = knots[a];
    s.t1 = knots[a + 1];
    spans.push_back(std::move(s));
  }
  return spans;
}

std::vector<BezierPatchSpan> extractBezier(const NurbsSurface& surface)
{
  const int p = surface.degreeU(), q = surface.degreeV();
  KnotVector ku = surface.knotsU(), kv = surface.knotsV();
  Vec4List net = surface.homogeneousNet();
  int nu = surface.countU(), nv = surface.countV();
  // Along u the net's rows (stride nv) are the interleaved polygons; along v, transpose.
  raiseToBezier(ku, p, net, nv);
  nu = static_cast<int>(net.size()) / nv;
  net = transpose(net, nu, nv);
  raiseToBezier(kv, q, net, nu);
  nv = static_cast<int>(net.size()) / nu;
  net = transpose(net, nv, nu);

  std::vector<BezierPatchSpan> patches;
  for (int a : spanStarts(ku, p, nu))
  {
    for (int b : spanStarts(kv, q, nv))
    {
      Vec4List piece;
      piece.reserve(static_cast<size_t>(p + 1) * (q + 1));
      for (int i = a - p; i <= a; ++i)
      {
        for (int j = b - q; j <= b; ++j)
        {
          piece.push_back(net[i * nv + j]);
        }
      }
      BezierPatchSpan s;
      s.patch = BezierPatch(p, q, std::move(piece));
      s.u0 = ku[a];
      s.u1 = ku[a + 1];
      s.v0 = kv[b];
      s.v1 = kv[b + 1];
      patches.push_back(std::move(s));
    }
  }
  return patches;
}

NurbsCurve joinBezier(
  const std::vector<BezierCurve>& pieces, const std::vector<double>& breaksIn, double tolerance)
{
  if (pieces.empty())
  {
    fail("joinBezier: no pieces to join");
  }
  const int p = pieces.front().degree();
  std::vector<double> breaks = breaksIn;
  if (breaks.empty())
  {
    for (size_t i = 0; i <= pieces.size(); ++i)
    {
      breaks.push_back(static_cast<double>(i));
    }
  }
  if (breaks.size() != pieces.size() + 1)
  {
    fail("joinBezier: ", breaks.size(), " breaks for ", pieces.size(), " pieces");
  }
  KnotVector knots(p + 1, breaks.front());
  Vec4List points = pieces.front().homogeneousPoints();
  for (size_t k = 1; k < pieces.size(); ++k)
  {
    if (pieces[k].degree() != p)
    {
      fail("joinBezier: piece ", k, " has degree ", pieces[k].degree(), ", piece 0 has ", p);
    }
    if (!(breaks[k] > breaks[k - 1]))
    {
      fail("joinBezier: breaks are not increasing at ", k);
    }
    const Vec3 end = pieces[k - 1].endPoint(), start = pieces[k].startPoint();
    if ((end - start).norm() > tolerance * (1.0 + end.norm()))
    {
      fail("joinBezier: piece ", k - 1, " ends at (", end.transpose(), ") but piece ", k,
        " starts at (", start.transpose(), ")");
    }
    // A rational curve is unchanged by scaling all its weights: match the joint weight.
    const double scale = points.back().w() / pieces[k].weight(0);
    const Vec4List& next = pieces[k].homogeneousPoints();
    for (int i = 1; i <= p; ++i)
    {
      points.push_back(scale * next[i]);
    }
    knots.insert(knots.end(), p, breaks[k]);
  }
  knots.insert(knots.end(), p + 1, breaks.back());
  // Knot removal compares homogeneous points: make its tolerance relative to their size.
  double size = 1.0;
  for (const Vec4& h : points)
  {
    size = std::max(size, h.norm());
  }
  for (size_t k = 1; k < pieces.size(); ++k)
  {
    removeKnot(knots, p, points, breaks[k], p, tolerance * size);
  }
  return NurbsCurve(p, std::move(knots), std::move(points));
}

} // namespace exactmat

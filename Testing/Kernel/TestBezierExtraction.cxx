// Bézier extraction and joining: exact to rounding.
#include "nurbs/BezierExtraction.h"
#include "shapes/Primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace exactmat;

namespace
{
constexpr double ExtractionTolerance = 1e-13; // relative to the curve's size

NurbsCurve randomCurve(std::mt19937& rng, int p, int n, bool unclamped)
{
  std::uniform_real_distribution<double> coord(-5, 5), weight(0.3, 3.0), gap(0.1, 1.0);
  Vec3List pts;
  std::vector<double> w;
  for (int i = 0; i < n; ++i)
  {
    pts.push_back(Vec3(coord(rng), coord(rng), coord(rng)));
    w.push_back(weight(rng));
  }
  KnotVector k;
  double x = 0.0;
  if (unclamped)
  {
    for (int i = 0; i < n + p + 1; ++i)
    {
      k.push_back(x);
      x += gap(rng);
    }
  }
  else
  {
    // Clamped, with one double interior knot where the degree allows it.
    k.assign(p + 1, 0.0);
    for (int i = 0; i < n - p - 1; ++i)
    {
      if (!(i == 1 && p >= 2))
        x += gap(rng);
      k.push_back(x);
    }
    x += gap(rng);
    k.insert(k.end(), p + 1, x);
  }
  return NurbsCurve(p, k, pts, w);
}
} // namespace

TEST(BezierExtraction, PiecesReproduceTheCurve)
{
  std::mt19937 rng(42);
  for (int trial = 0; trial < 12; ++trial)
  {
    const int p = 1 + trial % 5;
    const NurbsCurve c = randomCurve(rng, p, p + 4 + trial % 3, trial % 2 == 1);
    ASSERT_NO_THROW(c.validate("random curve"));
    const auto spans = extractBezier(c);
    ASSERT_FALSE(spans.empty());
    EXPECT_EQ(spans.front().t0, c.domainStart());
    EXPECT_EQ(spans.back().t1, c.domainEnd());
    double size = 0.0;
    for (int i = 0; i < c.controlPointCount(); ++i)
      size = std::max(size, c.controlPoint(i).norm());
    double worst = 0.0;
    for (int k = 0; k < 1000; ++k)
    {
      const double t = c.domainStart() + (c.domainEnd() - c.domainStart()) * k / 999.0;
      size_t s = 0;
      while (s + 1 < spans.size() && t > spans[s].t1)
        ++s;
      const double local = (t - spans[s].t0) / (spans[s].t1 - spans[s].t0);
      worst = std::max(worst, (spans[s].curve.evaluate(local) - c.evaluate(t)).norm());
    }
    EXPECT_LT(worst, ExtractionTolerance * size) << "trial " << trial << " degree " << p;
  }
}

TEST(BezierExtraction, JoiningPiecesGivesTheOriginalCurveBack)
{
  std::mt19937 rng(7);
  for (int trial = 0; trial < 8; ++trial)
  {
    const int p = 2 + trial % 3;
    // Simple interior knots: the curve is C^{p−1} there, so every joint knot comes out again.
    Vec3List pts;
    std::vector<double> w;
    std::uniform_real_distribution<double> coord(-5, 5), weight(0.5, 2.0);
    const int n = p + 5;
    for (int i = 0; i < n; ++i)
    {
      pts.push_back(Vec3(coord(rng), coord(rng), 0));
      w.push_back(weight(rng));
    }
    const NurbsCurve c(p, clampedUniformKnots(p, n), pts, w);
    std::vector<BezierCurve> pieces;
    std::vector<double> breaks;
    for (const BezierSpan& s : extractBezier(c))
    {
      pieces.push_back(s.curve);
      breaks.push_back(s.t0);
    }
    breaks.push_back(c.domainEnd());
    const NurbsCurve j = joinBezier(pieces, breaks);
    ASSERT_EQ(j.controlPointCount(), c.controlPointCount());
    ASSERT_EQ(j.knots().size(), c.knots().size());
    for (size_t k = 0; k < c.knots().size(); ++k)
      EXPECT_NEAR(j.knots()[k], c.knots()[k], 1e-15);
    for (int i = 0; i < n; ++i)
    {
      EXPECT_LT((j.controlPoint(i) - c.controlPoint(i)).norm(), 1e-11);
      EXPECT_NEAR(j.weight(i) / j.weight(0), c.weight(i) / c.weight(0), 1e-11);
    }
  }
  // A polygon's pieces meet at corners: nothing can be removed, the curve is the same.
  const std::vector<BezierCurve> corner{ BezierCurve(Vec3List{ Vec3(0, 0, 0), Vec3(1, 0, 0) }, {}),
    BezierCurve(Vec3List{ Vec3(1, 0, 0), Vec3(1, 1, 0) }, {}) };
  const NurbsCurve poly = joinBezier(corner);
  EXPECT_EQ(poly.controlPointCount(), 3);
  EXPECT_LT((poly.evaluate(1.5) - Vec3(1, 0.5, 0)).norm(), 1e-15);
  // Pieces that do not meet are an error naming the joint.
  const std::vector<BezierCurve> gap{ corner[0], BezierCurve(Vec3List{ Vec3(2, 0, 0), Vec3(2, 1, 0) }, {}) };
  EXPECT_THROW(joinBezier(gap), std::runtime_error);
}

TEST(BezierExtraction, SurfacePatchesReproduceTheSurface)
{
  const NurbsCurve profile = makeArc(Vec3(3, 0, 0), 1.0, 0.0, 2 * M_PI);
  Vec4List pts = profile.homogeneousPoints();
  for (Vec4& h : pts)
    h = Vec4(h.x(), 0.0, h.y(), h.w());
  const NurbsSurface torus = makeRevolution(NurbsCurve(2, profile.knots(), pts));
  const auto patches = extractBezier(torus);
  EXPECT_EQ(patches.size(), 16u);
  double worst = 0.0;
  for (const BezierPatchSpan& s : patches)
  {
    for (int a = 0; a <= 10; ++a)
      for (int b = 0; b <= 10; ++b)
      {
        const double u = s.u0 + (s.u1 - s.u0) * a / 10.0, v = s.v0 + (s.v1 - s.v0) * b / 10.0;
        worst = std::max(worst, (s.patch.evaluate(a / 10.0, b / 10.0) - torus.evaluate(u, v)).norm());
        // Exactness: every point is on the torus (R = 3, r = 1).
        const Vec3 p = s.patch.evaluate(a / 10.0, b / 10.0);
        const double ring = std::hypot(p.x(), p.y()) - 3.0;
        EXPECT_NEAR(std::hypot(ring, p.z()), 1.0, 1e-13);
      }
  }
  EXPECT_LT(worst, ExtractionTolerance * 4.0);
}

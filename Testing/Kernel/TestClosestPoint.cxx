// Global closest points and all footpoints, against brute force refined by Newton.
#include "geometry/ClosestPoint.h"
#include "nurbs/BezierExtraction.h"
#include "shapes/Primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace exactmat;

namespace
{
constexpr double DistanceTolerance = 1e-10; // absolute, shapes of size ~1–10
constexpr int BruteForceSamples = 20000;

// Brute force: local minima of the sampled distance, each refined by Newton (kept in [0,1]).
std::vector<double> bruteForceCurveMinima(const BezierCurve& c, const Vec3& q)
{
  std::vector<double> d(BruteForceSamples + 1);
  for (int i = 0; i <= BruteForceSamples; ++i)
    d[i] = (c.evaluate(static_cast<double>(i) / BruteForceSamples) - q).norm();
  std::vector<double> minima;
  for (int i = 0; i <= BruteForceSamples; ++i)
  {
    const bool left = i == 0 || d[i] < d[i - 1];
    const bool right = i == BruteForceSamples || d[i] <= d[i + 1];
    if (left && right)
    {
      double t = static_cast<double>(i) / BruteForceSamples;
      for (int it = 0; it < 30; ++it)
      {
        const CurveDerivatives e = c.derivatives(t);
        const Vec3 r = e.point - q;
        const double f = r.dot(e.d1), fp = e.d1.squaredNorm() + r.dot(e.d2);
        if (fp <= 0)
          break;
        t = std::min(1.0, std::max(0.0, t - f / fp));
      }
      minima.push_back((c.evaluate(t) - q).norm());
    }
  }
  std::sort(minima.begin(), minima.end());
  return minima;
}

BezierCurve inflectionCubic()
{
  return BezierCurve(Vec3List{ Vec3(0, 0, 0), Vec3(1, 3, 0), Vec3(2, -3, 0), Vec3(3, 0, 0) }, {});
}

BezierCurve rationalQuartic()
{
  return BezierCurve(Vec3List{ Vec3(0, 0, 0), Vec3(1, 2, 0), Vec3(2, 2, 1), Vec3(3, -1, 0), Vec3(4, 1, 0) },
    { 1.0, 2.5, 0.4, 1.7, 1.0 });
}
} // namespace

TEST(ClosestPoint, CurveMinimaMatchBruteForce)
{
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> x(-1, 5), y(-3, 3), z(-0.5, 1.0);
  const BezierCurve arc = extractBezier(makeArc(Vec3::Zero(), 2.0, 0.0, M_PI / 2)).front().curve;
  for (const BezierCurve& c : { inflectionCubic(), rationalQuartic(), arc })
  {
    for (int trial = 0; trial < 60; ++trial)
    {
      const Vec3 q(x(rng), y(rng), z(rng));
      const auto brute = bruteForceCurveMinima(c, q);
      const auto fps = curveFootpoints(c, q);
      ASSERT_EQ(fps.size(), brute.size()) << "query " << q.transpose();
      for (size_t k = 0; k < fps.size(); ++k)
      {
        EXPECT_NEAR(fps[k].distance, brute[k], DistanceTolerance);
        EXPECT_NEAR((c.evaluate(fps[k].t) - q).norm(), fps[k].distance, 1e-14);
      }
      EXPECT_NEAR(closestPoint(c, q).distance, brute.front(), DistanceTolerance);
    }
  }
}

TEST(ClosestPoint, PointsNearTheEvoluteHaveSeveralMinima)
{
  // Parabola y = x² on [−1, 1] (a quadratic Bézier). Its evolute cusp is the centre of
  // curvature (0, 1/2) of the vertex; a point on the axis above it has two symmetric
  // minima, one below it has one.
  const BezierCurve parabola(Vec3List{ Vec3(-1, 1, 0), Vec3(0, -1, 0), Vec3(1, 1, 0) }, {});
  const auto above = curveFootpoints(parabola, Vec3(0, 0.5 + 1e-3, 0));
  ASSERT_EQ(above.size(), 2u);
  EXPECT_NEAR(above[0].distance, above[1].distance, 1e-14);
  EXPECT_NEAR(above[0].point.x(), -above[1].point.x(), 1e-12);
  // x² = y − 1/2 at the footpoints: x = ±sqrt(1e-3).
  EXPECT_NEAR(std::abs(above[0].point.x()), std::sqrt(1e-3), 1e-10);
  const auto below = curveFootpoints(parabola, Vec3(0, 0.5 - 1e-3, 0));
  ASSERT_EQ(below.size(), 1u);
  EXPECT_NEAR(below[0].point.x(), 0.0, 1e-12);
  // Slightly off the axis above the cusp: two minima of different distance.
  const Vec3 q(1e-4, 0.6, 0);
  const auto off = curveFootpoints(parabola, q);
  ASSERT_EQ(off.size(), 2u);
  const auto brute = bruteForceCurveMinima(parabola, q);
  ASSERT_EQ(brute.size(), 2u);
  EXPECT_NEAR(off[0].distance, brute[0], DistanceTolerance);
  EXPECT_NEAR(off[1].distance, brute[1], DistanceTolerance);
}

TEST(ClosestPoint, ArcCentreIsAContinuum)
{
  const BezierCurve arc = extractBezier(makeArc(Vec3(1, 1, 0), 3.0, 0.2, 1.4)).front().curve;
  const auto fps = curveFootpoints(arc, Vec3(1, 1, 0));
  ASSERT_EQ(fps.size(), 1u);
  EXPECT_TRUE(fps[0].continuum);
  EXPECT_NEAR(fps[0].distance, 3.0, 1e-13);
}

TEST(ClosestPoint, WithinDistanceKeepsOnlyNearMinima)
{
  const BezierCurve c = inflectionCubic();
  const Vec3 q(1.0, -0.3, 0.0); // two interior minima
  const auto all = curveFootpoints(c, q);
  ASSERT_GE(all.size(), 2u);
  const double cut = 0.5 * (all[0].distance + all[1].distance);
  const auto near = curveFootpoints(c, q, cut);
  EXPECT_EQ(near.size(), 1u);
  EXPECT_NEAR(near[0].distance, all[0].distance, 1e-15);
  EXPECT_TRUE(curveFootpoints(c, Vec3(100, 100, 0), 1.0).empty());
}

namespace
{
// Brute force on a patch: interior grid minima refined by Newton (kept when they converge
// inside), plus the minima of the four boundary curves by the curve brute force above.
std::vector<double> bruteForcePatchMinima(
  const BezierPatch& p, const Vec3& q, int n = 200, bool withBoundary = true)
{
  std::vector<double> d((n + 1) * (n + 1));
  auto at = [&](int i, int j) -> double& { return d[i * (n + 1) + j]; };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      at(i, j) = (p.evaluate(double(i) / n, double(j) / n) - q).norm();
  std::vector<double> minima;
  auto addUnique = [&](double dist) {
    for (double m : minima)
      if (std::abs(m - dist) < 1e-9)
        return;
    minima.push_back(dist);
  };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
    {
      bool isMin = true;
      for (int di = -1; di <= 1; ++di)
        for (int dj = -1; dj <= 1; ++dj)
        {
          const int a = i + di, b = j + dj;
          if ((di || dj) && a >= 0 && a <= n && b >= 0 && b <= n && at(a, b) < at(i, j))
            isMin = false;
        }
      if (!isMin)
        continue;
      double u = double(i) / n, v = double(j) / n;
      bool inside = true;
      for (int it = 0; it < 50 && inside; ++it)
      {
        const SurfaceDerivatives s = p.derivatives(u, v);
        const Vec3 r = s.point - q;
        const double fu = r.dot(s.su), fv = r.dot(s.sv);
        const double a = s.su.squaredNorm() + r.dot(s.suu), b = s.su.dot(s.sv) + r.dot(s.suv),
                     c = s.sv.squaredNorm() + r.dot(s.svv);
        const double det = a * c - b * b;
        u -= (c * fu - b * fv) / det;
        v -= (a * fv - b * fu) / det;
        inside = u >= -1e-3 && u <= 1 + 1e-3 && v >= -1e-3 && v <= 1 + 1e-3;
      }
      if (inside && u >= 0 && u <= 1 && v >= 0 && v <= 1)
        addUnique((p.evaluate(u, v) - q).norm());
    }
  for (int side = 0; side < 4 && withBoundary; ++side)
    for (double m : bruteForceCurveMinima(p.side(side), q))
      addUnique(m);
  std::sort(minima.begin(), minima.end());
  return minima;
}

BezierPatch wavyPatch()
{
  Vec4List net;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      net.push_back(homogeneous(Vec3(i, j, (i == 1 || i == 2) && (j == 1 || j == 2) ? 1.5 * ((i + j) % 2 ? 1 : -1) : 0.0),
        1.0 + 0.5 * ((i * j) % 2)));
  return BezierPatch(3, 3, net);
}
} // namespace

// The emptiness test of a disk tangent to a curve, told the touch (a tracing step's disk)
// or not, against the sampled distance: disks that stay outside (radius below the
// curvature radius, and the curve not coming back) and disks the curve enters beside the
// touch (radius above it) or far from it (the cubic's other lobe).
TEST(ClosestPoint, TangentDiskEmptinessMatchesBruteForce)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> at(0.02, 0.98), radius(0.05, 3.0);
  // A quarter ellipse 2 × 1 (rational quadratic), the inflected cubic, a rational quartic.
  const BezierCurve quarterEllipse(Vec3List{ Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(0, 1, 0) },
    { 1.0, std::sqrt(0.5), 1.0 });
  int inside = 0, outside = 0;
  for (const BezierCurve& c : { quarterEllipse, inflectionCubic(), rationalQuartic() })
  {
    for (int trial = 0; trial < 200; ++trial)
    {
      const double tau = at(rng), r = radius(rng);
      const CurveDerivatives d = c.derivatives(tau);
      if (d.d2.cross(d.d1).norm() <= 1e-6 * d.d1.squaredNorm())
        continue; // an inflection: no osculating plane
      // The disk on either side of the curve, in the curve's osculating plane.
      const Vec3 side = d.d1.cross(d.d2.cross(d.d1)).normalized() * (trial % 2 ? 1.0 : -1.0);
      const Vec3 x = d.point + r * side;
      const double test = r * (1.0 - 1e-9); // the tracer's disks keep a margin of this order
      const double nearest = bruteForceCurveMinima(c, x).front();
      if (std::abs(nearest - test) <= 1e-11 * r)
        continue; // too close to call
      const bool expected = nearest < test;
      (expected ? inside : outside)++;
      EXPECT_EQ(curveComesWithin(c, x, test, tau), expected) << "tau " << tau << " r " << r;
      EXPECT_EQ(curveComesWithin(c, x, test), expected) << "tau " << tau << " r " << r;
    }
  }
  // Both kinds were drawn (the test can fail either way).
  EXPECT_GT(inside, 50);
  EXPECT_GT(outside, 50);
  // The ellipse's vertex (2, 0): radius of curvature 1/2. A disk of radius 0.45 tangent
  // there stays outside, one of 0.55 is entered beside the touch.
  const double tau0 = 1e-3;
  const CurveDerivatives v = quarterEllipse.derivatives(tau0);
  const Vec3 inward = v.d1.cross(v.d2.cross(v.d1)).normalized(); // towards the centre
  EXPECT_FALSE(curveComesWithin(quarterEllipse, v.point + 0.45 * inward, 0.45 * (1 - 1e-9), tau0));
  EXPECT_TRUE(curveComesWithin(quarterEllipse, v.point + 0.55 * inward, 0.55 * (1 - 1e-9), tau0));
}

// The same for balls tangent to patches (the 3D tracer's and the cone sheets' balls)
// against the global distance: balls below the surface's curvature radii stay outside;
// larger ones, or ones the patch comes back into, are entered. Round the touch h has a near
// double root: boxes there are decided by convexity, not subdivided towards 2^-24 — counted
// in boxes (plain subdivision took ~110 a ball here).
TEST(ClosestPoint, TangentBallEmptinessMatchesTheDistance)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> at(0.02, 0.98), radius(0.02, 3.0);
  std::vector<BezierPatch> patches{ wavyPatch() };
  for (const BezierPatchSpan& span : extractBezier(ellipsoidSurfaces(Vec3(2, 1.5, 1), 0.3, 2).front()))
    patches.push_back(span.patch);
  int inside = 0, outside = 0;
  std::uint64_t work = 0;
  for (const BezierPatch& p : patches)
  {
    for (int trial = 0; trial < 60; ++trial)
    {
      const Vec2 t(at(rng), at(rng));
      const double r = radius(rng);
      const Vec3 x = p.evaluate(t.x(), t.y()) + (trial % 2 ? r : -r) * p.normal(t.x(), t.y());
      const double test = r * (1.0 - 1e-7); // the cone sheets' balls keep a margin of this order
      const double nearest = closestPoint(p, x).distance;
      if (std::abs(nearest - test) <= 1e-11 * r)
        continue; // too close to call
      const bool expected = nearest < test;
      (expected ? inside : outside)++;
      const std::uint64_t before = patchSearchWork();
      EXPECT_EQ(patchComesWithin(p, x, test), expected) << "touch " << t.transpose() << " r " << r;
      if (!expected)
        work += patchSearchWork() - before;
    }
  }
  EXPECT_GT(inside, 20);
  EXPECT_GT(outside, 20);
  EXPECT_LE(work, 40u * outside) << "boxes for " << outside << " empty balls";
}

TEST(ClosestPoint, PatchGlobalMinimumMatchesBruteForce)
{
  const BezierPatch p = wavyPatch();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> x(-0.5, 3.5), z(-2.0, 2.0);
  for (int trial = 0; trial < 25; ++trial)
  {
    const Vec3 q(x(rng), x(rng), z(rng));
    const auto brute = bruteForcePatchMinima(p, q, 120);
    const PatchFootpoint f = closestPoint(p, q);
    EXPECT_NEAR(f.distance, brute.front(), 1e-9) << q.transpose();
    EXPECT_NEAR((p.evaluate(f.u, f.v) - q).norm(), f.distance, 1e-14);
    // No footpoint is closer than the true minimum (each is a point of the patch).
    for (const PatchFootpoint& g : patchFootpoints(p, q))
      EXPECT_GE(g.distance, brute.front() - 1e-9);
  }
}

TEST(ClosestPoint, PatchFindsEverySphereMinimum)
{
  // Inside a sphere patch (octant of radius 2), points near the centre see one minimum on
  // the patch along the ray; the centre itself is a continuum.
  const NurbsCurve quarter = makeArc(Vec3::Zero(), 2.0, 0.0, M_PI / 2);
  Vec4List pts = quarter.homogeneousPoints();
  for (Vec4& h : pts)
    h = Vec4(h.x(), 0.0, h.y(), h.w());
  const NurbsSurface revolved = makeRevolution(NurbsCurve(2, quarter.knots(), pts));
  const BezierPatch octant = extractBezier(revolved).front().patch;
  const Vec3 q(0.3, 0.4, 0.5);
  const auto fps = patchFootpoints(octant, q);
  ASSERT_GE(fps.size(), 1u);
  EXPECT_NEAR(fps.front().distance, 2.0 - q.norm(), 1e-12);
  EXPECT_LT((fps.front().point - 2.0 * q.normalized()).norm(), 1e-9);
  const auto centre = patchFootpoints(octant, Vec3::Zero());
  ASSERT_EQ(centre.size(), 1u);
  EXPECT_TRUE(centre[0].continuum);
  EXPECT_NEAR(centre[0].distance, 2.0, 1e-13);
}

// A query at a pole (a collapsed side of the patch: the whole side is one point, at
// distance 0) has the pole as its one foot; a query beside it its nearest point. The side is divided out of the stationarity
// polynomials: their search used to subdivide along it to its box limit (200 000 boxes,
// ~1 s a query) whatever the reach. Counted in boxes, not seconds.
TEST(ClosestPoint, QueriesAtAndBesideAPoleAreSettledWithoutSearchingTheCollapsedSide)
{
  int poles = 0;
  for (const NurbsSurface& s : ellipsoidSurfaces(Vec3(2, 1.5, 1), 0.3, 2))
  {
    for (const BezierPatchSpan& span : extractBezier(s))
    {
      const BezierPatch& p = span.patch;
      for (int side = 0; side < 4; ++side)
      {
        const BezierCurve c = p.side(side);
        const Vec3 pole = c.evaluate(0.0);
        if ((c.evaluate(1.0) - pole).norm() > 1e-14 || (c.evaluate(0.5) - pole).norm() > 1e-14)
          continue;
        ++poles;
        for (const double reach : { 1e-8, 1e-3, Unbounded })
        {
          const std::uint64_t before = patchSearchWork();
          const std::vector<PatchFootpoint> feet = patchFootpoints(p, pole, reach);
          EXPECT_LE(patchSearchWork() - before, 64u) << "pole " << pole.transpose() << ", reach " << reach;
          ASSERT_FALSE(feet.empty()) << "pole " << pole.transpose();
          EXPECT_LE(feet.front().distance, 1e-15);
          EXPECT_LE((p.evaluate(feet.front().u, feet.front().v) - pole).norm(), 1e-15);
        }
        EXPECT_LE(closestPoint(p, pole).distance, 1e-15);
        // Beside the pole: boxes on the collapsed side are cut across it only (quartered,
        // they multiplied along it down to the query's distance from the pole, and the
        // foot was missed: 2.8e-7 found for 1.9e-13). The reference: the nearest of a
        // polar grid of the patch round the pole, out to 4 × the query's distance.
        const bool alongV = side == 0 || side == 2;
        const double fromPole = side == 0 || side == 3 ? 0.0 : 1.0;
        const Vec2 at = alongV ? Vec2(0.5, fromPole) : Vec2(fromPole, 0.5);
        const SurfaceDerivatives d = p.derivatives(at.x(), at.y());
        const double speed = (alongV ? d.sv : d.su).norm();
        for (const double delta : { 1e-12, 1e-9, 1e-6, 1e-3 })
        {
          for (const Vec3& direction : { Vec3(0.6, 0.8, 0.0), Vec3(1, 1, 3).normalized(), Vec3(-1, 0.2, 0.1).normalized() })
          {
            const Vec3 q = pole + delta * direction;
            const std::uint64_t before = patchSearchWork();
            const PatchFootpoint f = closestPoint(p, q);
            EXPECT_LE(patchSearchWork() - before, 1000u) << "beside pole " << pole.transpose() << " by " << delta;
            const double reach = std::min(1.0, 4.0 * delta / speed);
            double nearest = Unbounded;
            for (int i = 0; i <= 200; ++i)
              for (int j = 0; j <= 200; ++j)
              {
                const double across = std::abs(fromPole - reach * j / 200.0), along = i / 200.0;
                nearest = std::min(nearest, (p.evaluate(alongV ? along : across, alongV ? across : along) - q).norm());
              }
            EXPECT_LE(f.distance, nearest * (1.0 + 1e-9) + 1e-15)
              << "beside pole " << pole.transpose() << " by " << delta << " towards " << direction.transpose();
          }
        }
      }
    }
  }
  EXPECT_EQ(poles, 8); // each of the eight patches has one pole
}

TEST(ClosestPoint, PatchFindsEveryInteriorMinimum)
{
  // The wavy patch has dips: from above, several interior local minima of the distance.
  const BezierPatch p = wavyPatch();
  for (const Vec3& q : { Vec3(1.5, 1.5, 3.0), Vec3(1.0, 2.0, -2.5), Vec3(2.2, 0.9, 1.0) })
  {
    const auto brute = bruteForcePatchMinima(p, q, 200, false);
    std::vector<double> interior;
    for (const PatchFootpoint& f : patchFootpoints(p, q))
      interior.push_back(f.distance);
    // Every brute-force minimum is found by the solver.
    for (double b : brute)
    {
      double nearest = Unbounded;
      for (double f : interior)
        nearest = std::min(nearest, std::abs(f - b));
      EXPECT_LT(nearest, 1e-9) << "missed minimum at distance " << b << " from " << q.transpose();
    }
  }
}

namespace
{
// The side of the cylinder x² + y² = 1 over the angles [a0, a1] between the sections
// z = 0.3·x (below) and z = 3 + 0.2·y (above): a ruled patch of degree (2, 1) whose
// circles are no iso-lines (a fillet cut at a miter).
BezierPatch slantedCylinderPiece(double a0, double a1)
{
  const double w = std::cos(0.5 * (a1 - a0));
  const Vec3 arc[3] = { Vec3(std::cos(a0), std::sin(a0), 0.0),
    Vec3(std::cos(0.5 * (a0 + a1)), std::sin(0.5 * (a0 + a1)), 0.0) / w, Vec3(std::cos(a1), std::sin(a1), 0.0) };
  const double weights[3] = { 1.0, w, 1.0 };
  Vec4List net;
  for (int i = 0; i < 3; ++i)
  {
    const Vec3 low(arc[i].x(), arc[i].y(), 0.3 * arc[i].x()), high(arc[i].x(), arc[i].y(), 3.0 + 0.2 * arc[i].y());
    for (const Vec3& p : { low, high })
      net.push_back(Vec4(p.x(), p.y(), p.z(), 1.0) * weights[i]);
  }
  return BezierPatch(2, 1, std::move(net));
}
} // namespace

// Near the axis of a cylinder cut off by slanted planes every point of the circle at the
// query's height is nearly a foot and that circle crosses the parameters diagonally: the
// general search ran out of boxes there (a query 1e-5 from the axis: no foot at all, the
// patch's corner returned). The swept patch's search is closed form: R − ρ at the query's
// angle and height.
TEST(ClosestPoint, SlantedCylinderPieceNearItsAxis)
{
  const BezierPatch patch = slantedCylinderPiece(0.2, 0.2 + 2.0 * M_PI / 3.0);
  for (const double rho : { 0.5, 1e-3, 1e-5, 1e-8, 1e-12, 0.0 })
  {
    SCOPED_TRACE(rho);
    const double angle = 1.1, height = 1.4;
    const Vec3 q(rho * std::cos(angle), rho * std::sin(angle), height);
    const std::uint64_t cutShort = patchSearchesCutShort();
    const PatchFootpoint f = closestPoint(patch, q);
    EXPECT_EQ(patchSearchesCutShort(), cutShort);
    EXPECT_NEAR(f.distance, 1.0 - rho, 1e-14);
    EXPECT_NEAR(f.point.z(), height, 1e-14);
    EXPECT_NEAR(std::hypot(f.point.x(), f.point.y()), 1.0, 1e-14);
    if (rho >= 1e-8)
      EXPECT_NEAR(std::atan2(f.point.y(), f.point.x()), angle, 1e-14 / rho);
    EXPECT_LE((patch.evaluate(f.u, f.v) - f.point).norm(), 1e-14);
    EXPECT_TRUE(patchComesWithin(patch, q, (1.0 - rho) * (1.0 + 1e-9)));
    EXPECT_FALSE(patchComesWithin(patch, q, (1.0 - rho) * (1.0 - 1e-9)));
  }
  // Below the lower section (z = 0.3·x): the foot is on that side, as dense sampling says.
  const Vec3 q(0.1, 0.6, -0.4);
  double best = INFINITY;
  for (int k = 0; k <= 200000; ++k)
    best = std::min(best, (patch.evaluate(k / 200000.0, 0.0) - q).norm());
  const PatchFootpoint f = closestPoint(patch, q);
  EXPECT_NEAR(f.distance, best, 1e-9);
  EXPECT_NEAR(f.v, 0.0, 1e-14);
  EXPECT_TRUE(f.onBoundary);
}

// The carrier of an elliptic arc and its distance lower bound, against the distance to
// the whole ellipse found by dense sampling and Newton.
#include "geometry/ConicCarrier.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace exactmat;

namespace
{
struct Ellipse
{
  Vec2 o, e1, e2; // centre, unit axes
  double a, b;    // semi-axes along e1, e2
  Vec2 at(double t) const { return o + a * std::cos(t) * e1 + b * std::sin(t) * e2; }
  Vec2 tangent(double t) const { return -a * std::sin(t) * e1 + b * std::cos(t) * e2; }
};

// The arc of `e` from angle t0 to t1 (less than π apart) as a rational quadratic: the unit
// circle's arc (w = cos of the half span, P₁ at 1/w along the middle direction) mapped by
// the ellipse's affinity; its homogeneous points scaled by k·(1, ρ, ρ²) — the same curve,
// not in standard form, weights scaled.
BezierCurve arcOf(const Ellipse& e, double t0, double t1, double rho, double k)
{
  const double half = 0.5 * (t1 - t0), w = std::cos(half), tm = 0.5 * (t0 + t1);
  const Vec2 p[3] = { e.at(t0), e.o + (e.at(tm) - e.o) / w, e.at(t1) };
  const double weights[3] = { 1.0, w, 1.0 };
  Vec4List h;
  for (int i = 0; i < 3; ++i)
    h.push_back(homogeneous(Vec3(p[i].x(), p[i].y(), 0.0), k * weights[i] * std::pow(rho, i)));
  return BezierCurve(h);
}

// Distance from x to the whole ellipse: 2000 samples, the best refined by Newton on
// (X(t) − x)·X'(t).
double distanceToEllipse(const Ellipse& e, const Vec2& x)
{
  double best = INFINITY, tb = 0.0;
  for (int i = 0; i < 2000; ++i)
  {
    const double t = 2.0 * M_PI * i / 2000;
    const double d = (e.at(t) - x).norm();
    if (d < best)
      best = d, tb = t;
  }
  for (int it = 0; it < 50; ++it)
  {
    const Vec2 r = e.at(tb) - x, d1 = e.tangent(tb), d2 = e.o - e.at(tb);
    const double f = r.dot(d1), fp = d1.squaredNorm() + r.dot(d2);
    if (!(fp > 0.0))
      break;
    tb -= f / fp;
  }
  return std::min(best, (e.at(tb) - x).norm());
}

Ellipse randomEllipse(std::mt19937& rng, double aspect)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Ellipse e;
  const double angle = M_PI * u(rng);
  e.e1 = Vec2(std::cos(angle), std::sin(angle));
  e.e2 = Vec2(-e.e1.y(), e.e1.x());
  e.a = std::pow(10.0, u(rng));
  e.b = e.a * aspect;
  e.o = Vec2(u(rng), u(rng)) * 10.0 * e.a;
  return e;
}
} // namespace

TEST(ConicCarrier, FindsTheEllipseOfEveryArcWhateverItsWeights)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 200; ++k)
  {
    const Ellipse e = randomEllipse(rng, std::pow(10.0, -3.0 * u(rng)));
    const double t0 = 2.0 * M_PI * u(rng), span = 0.05 + 3.0 * u(rng);
    const BezierCurve arc = arcOf(e, t0, t0 + span, std::pow(10.0, 2.0 * u(rng) - 1.0), std::pow(10.0, 40.0 * u(rng) - 20.0));
    const std::optional<ConicCarrier> c = ConicCarrier::of(arc, 20.0 * e.a);
    ASSERT_TRUE(c) << "arc " << k;
    EXPECT_NEAR(c->majorRadius(), e.a, 1e-11 * e.a) << k;
    EXPECT_NEAR(c->minorRadius(), e.b, 1e-11 * e.a) << k;
    EXPECT_LE((c->centre() - e.o).norm(), 1e-11 * (e.a + e.o.norm())) << k;
  }
}

TEST(ConicCarrier, ItsBoundNeverExceedsTheDistanceToTheWholeEllipseAndIsTightOnTheMajorAxis)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
  for (int k = 0; k < 60; ++k)
  {
    const double aspect = k % 3 == 0 ? 1.0 : std::pow(10.0, -3.0 * u(rng)); // a third circles
    const Ellipse e = randomEllipse(rng, aspect);
    const double t0 = 2.0 * M_PI * u(rng);
    const std::optional<ConicCarrier> c = ConicCarrier::of(arcOf(e, t0, t0 + 0.2 + 2.5 * u(rng), 1.0, 1.0), 20.0 * e.a);
    ASSERT_TRUE(c);
    for (int i = 0; i < 200; ++i)
    {
      // Anywhere within twice the ellipse, and (every other point) near its major axis.
      const double X = 2.0 * e.a * s(rng), Y = i % 2 ? 2.0 * e.b * s(rng) : 1e-3 * e.b * s(rng);
      const Vec2 x = e.o + X * e.e1 + Y * e.e2;
      const double truth = distanceToEllipse(e, x), bound = c->distanceLowerBound(Vec3(x.x(), x.y(), 7.0));
      ASSERT_LE(bound, truth + 1e-14 * e.a) << "ellipse " << k << " point " << i;
    }
    // On the major axis between the centres of curvature (where its MAT lies) the bound
    // is the distance, to rounding.
    const double end = (e.a - e.b) * (e.a + e.b) / e.a;
    for (int i = 0; i <= 20; ++i)
    {
      const Vec2 x = e.o + end * (i / 10.0 - 1.0) * e.e1;
      const double truth = distanceToEllipse(e, x);
      EXPECT_GE(c->distanceLowerBound(Vec3(x.x(), x.y(), 0.0)), truth - 1e-12 * e.a) << k << " " << i;
    }
  }
}

TEST(ConicCarrier, NoCarrierForOtherCurves)
{
  auto quadratic = [](double w, double z) {
    return BezierCurve({ Vec3(0, 0, 0), Vec3(1, 1, z), Vec3(2, 0, 0) }, { 1.0, w, 1.0 });
  };
  EXPECT_TRUE(ConicCarrier::of(quadratic(0.5, 0.0), 2.0));
  EXPECT_FALSE(ConicCarrier::of(quadratic(1.0, 0.0), 2.0)); // a parabola
  EXPECT_FALSE(ConicCarrier::of(quadratic(2.0, 0.0), 2.0)); // a hyperbola
  EXPECT_FALSE(ConicCarrier::of(quadratic(0.5, 0.1), 2.0)); // not in the plane z = 0
  EXPECT_FALSE(ConicCarrier::of(BezierCurve({ Vec3(0, 0, 0), Vec3(2, 0, 0) }, { 1.0, 1.0 }), 2.0));
  EXPECT_FALSE(ConicCarrier::of(
    BezierCurve({ Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(2, -1, 0), Vec3(3, 0, 0) }, { 1.0, 1.0, 1.0, 1.0 }), 3.0));
}

// NURBS curves and surfaces: derivatives, curvatures, validation.
#include "common/InputError.h"
#include "nurbs/NurbsCurve.h"
#include "nurbs/NurbsSurface.h"
#include "shapes/Primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace exactmat;

namespace
{
// A rational cubic with an inflection and uneven knots.
NurbsCurve wavyCurve()
{
  Vec3List pts{ Vec3(0, 0, 0), Vec3(1, 2, 0), Vec3(2, -1, 0.5), Vec3(3, 1, 0), Vec3(4, 0, 1),
    Vec3(5, 2, 0) };
  std::vector<double> w{ 1.0, 0.7, 1.8, 0.9, 1.3, 1.0 };
  return NurbsCurve(3, { 0, 0, 0, 0, 0.3, 0.45, 1, 1, 1, 1 }, pts, w);
}

NurbsSurface wavySurface()
{
  Vec3List net;
  std::vector<double> w;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 4; ++j)
    {
      net.push_back(Vec3(i, j, std::sin(1.3 * i) * std::cos(0.7 * j)));
      w.push_back(1.0 + 0.3 * ((i + 2 * j) % 3));
    }
  return NurbsSurface(3, 2, { 0, 0, 0, 0, 0.4, 1, 1, 1, 1 }, { 0, 0, 0, 0.6, 1, 1, 1 }, 5, 4,
    net, w);
}

// Second-order central differences: error O(h²) ≈ 1e-8 relative at h = 1e-4.
constexpr double FiniteDifferenceTolerance = 1e-6;
} // namespace

TEST(NurbsCurve, DerivativesMatchFiniteDifferences)
{
  const NurbsCurve c = wavyCurve();
  const double h = 1e-5;
  for (double t : { 0.05, 0.2, 0.31, 0.37, 0.6, 0.93 }) // off the knots 0.3, 0.45
  {
    const CurveDerivatives d = c.derivatives(t);
    const Vec3 fd1 = (c.evaluate(t + h) - c.evaluate(t - h)) / (2 * h);
    const CurveDerivatives dp = c.derivatives(t + h), dm = c.derivatives(t - h);
    const Vec3 fd2 = (dp.d1 - dm.d1) / (2 * h);
    EXPECT_LT((d.d1 - fd1).norm(), FiniteDifferenceTolerance * (1 + d.d1.norm())) << t;
    EXPECT_LT((d.d2 - fd2).norm(), FiniteDifferenceTolerance * (1 + d.d2.norm())) << t;
  }
}

TEST(NurbsCurve, RationalCircleHasCurvatureOneOverR)
{
  for (double r : { 0.25, 1.0, 7.5 })
  {
    const NurbsCurve c = makeArc(Vec3(1, 2, 0), r, 0.0, 2 * M_PI);
    for (int k = 0; k <= 100; ++k)
    {
      const double t = k / 100.0;
      const CurveDerivatives d = c.derivatives(t);
      EXPECT_NEAR((d.point - Vec3(1, 2, 0)).norm(), r, 1e-14 * (1 + r));
      EXPECT_NEAR(d.signedCurvature(), 1.0 / r, 1e-12 / r);
      EXPECT_NEAR(d.curvature(), 1.0 / r, 1e-12 / r);
      // The left normal of a counter-clockwise circle points to the centre.
      EXPECT_LT((d.point + r * d.leftNormal() - Vec3(1, 2, 0)).norm(), 1e-12 * (1 + r));
    }
  }
  const NurbsCurve cw = makeArc(Vec3::Zero(), 2.0, 2 * M_PI, 0.0);
  EXPECT_NEAR(cw.derivatives(0.3).signedCurvature(), -0.5, 1e-12);
}

TEST(NurbsSurface, DerivativesMatchFiniteDifferences)
{
  const NurbsSurface s = wavySurface();
  const double h = 1e-5;
  for (double u : { 0.1, 0.43, 0.75 }) // off the knot 0.4
    for (double v : { 0.2, 0.63, 0.9 }) // off the knot 0.6
    {
      const SurfaceDerivatives d = s.derivatives(u, v);
      const SurfaceDerivatives up = s.derivatives(u + h, v), um = s.derivatives(u - h, v);
      const SurfaceDerivatives vp = s.derivatives(u, v + h), vm = s.derivatives(u, v - h);
      auto close = [](const Vec3& a, const Vec3& b) {
        return (a - b).norm() < FiniteDifferenceTolerance * (1 + a.norm());
      };
      EXPECT_TRUE(close(d.su, (up.point - um.point) / (2 * h)));
      EXPECT_TRUE(close(d.sv, (vp.point - vm.point) / (2 * h)));
      EXPECT_TRUE(close(d.suu, (up.su - um.su) / (2 * h)));
      EXPECT_TRUE(close(d.svv, (vp.sv - vm.sv) / (2 * h)));
      EXPECT_TRUE(close(d.suv, (vp.su - vm.su) / (2 * h)));
    }
}

TEST(NurbsSurface, PrincipalCurvaturesOfSphereCylinderSaddle)
{
  const double R = 1.7;
  // Sphere: a semicircle in the xz half-plane revolved about z; Su×Sv points inward or
  // outward depending on the parameterisation, so compare |k| and the sign relative to n.
  const NurbsCurve semi = [&] {
    NurbsCurve a = makeArc(Vec3::Zero(), R, -M_PI / 2, M_PI / 2);
    Vec4List p = a.homogeneousPoints();
    for (Vec4& h : p)
      h = Vec4(h.x(), 0.0, h.y(), h.w());
    return NurbsCurve(2, a.knots(), p);
  }();
  const NurbsSurface sphere = makeRevolution(semi);
  for (double u : { 0.2, 0.5, 0.8 })
    for (double v : { 0.1, 0.45, 0.7 })
    {
      const SurfaceDerivatives d = sphere.derivatives(u, v);
      EXPECT_NEAR(d.point.norm(), R, 1e-13);
      const auto k = d.principalCurvatures();
      const double sign = d.normal().dot(d.point) > 0 ? -1.0 : 1.0; // outward normal: −1/R
      EXPECT_NEAR(k.k1, sign / R, 1e-11);
      EXPECT_NEAR(k.k2, sign / R, 1e-11);
    }
  // Cylinder of radius R: one principal curvature 0 along the rulings, the other ∓1/R.
  const NurbsSurface cyl = makeExtrusion(makeArc(Vec3::Zero(), R, 0, 2 * M_PI), Vec3::UnitZ(), 2.0);
  for (double u : { 0.1, 0.33, 0.9 })
  {
    const SurfaceDerivatives d = cyl.derivatives(u, 0.4);
    const auto k = d.principalCurvatures();
    const bool outward = d.normal().dot(Vec3(d.point.x(), d.point.y(), 0)) > 0;
    EXPECT_NEAR(outward ? k.k2 : k.k1, outward ? -1.0 / R : 1.0 / R, 1e-11);
    EXPECT_NEAR(outward ? k.k1 : k.k2, 0.0, 1e-11);
    // The zero-curvature direction is the ruling (z axis).
    const Vec3 ruling = outward ? k.d1 : k.d2;
    EXPECT_NEAR(std::abs(ruling.z()), 1.0, 1e-9);
  }
  // Saddle z = x² − y² on [−1,1]²: at the origin k = ±2, directions x and y.
  Vec3List net;
  const double a[3] = { 1, -1, 1 }, x[3] = { -1, 0, 1 };
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      net.push_back(Vec3(x[i], x[j], a[i] - a[j]));
  const NurbsSurface saddle(2, 2, { 0, 0, 0, 1, 1, 1 }, { 0, 0, 0, 1, 1, 1 }, 3, 3, net);
  const SurfaceDerivatives d = saddle.derivatives(0.5, 0.5);
  EXPECT_LT(d.point.norm(), 1e-15);
  const auto k = saddle.derivatives(0.5, 0.5).principalCurvatures();
  EXPECT_NEAR(k.k1, 2.0, 1e-12);
  EXPECT_NEAR(k.k2, -2.0, 1e-12);
  EXPECT_NEAR(std::abs(k.d1.x()), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(k.d2.y()), 1.0, 1e-12);
}

TEST(NurbsCurve, ValidationNamesTheEntityAndTheProblem)
{
  const Vec3List pts{ Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(2, 0, 0) };
  auto message = [](const NurbsCurve& c) {
    try
    {
      c.validate("curve 7");
    }
    catch (const InputError& e)
    {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(message(NurbsCurve(2, { 0, 0, 0, 1, 1, 1 }, pts)), "");
  EXPECT_NE(message(NurbsCurve(2, { 0, 0, 1, 0, 1, 1 }, pts)).find("curve 7: knot vector is not non-decreasing"), std::string::npos);
  EXPECT_NE(message(NurbsCurve(2, { 0, 0, 0, 1, 1 }, pts)).find("knot vector has 5 knots, expected 6"), std::string::npos);
  EXPECT_NE(message(NurbsCurve(2, { 0, 0, 0, 1, 1, 1 }, pts, { 1, 0, 1 })).find("control point 1 has weight 0"), std::string::npos);
  EXPECT_NE(message(NurbsCurve(2, { 0, 0, 0, 1, 1, 1 }, pts, { 1, -2, 1 })).find("weight -2"), std::string::npos);
  const Vec3List bad{ Vec3(0, 0, 0), Vec3(NAN, 1, 0), Vec3(2, 0, 0) };
  EXPECT_NE(message(NurbsCurve(2, { 0, 0, 0, 1, 1, 1 }, bad)).find("control point 1 has a NaN"), std::string::npos);
  const Vec3List inf{ Vec3(0, 0, 0), Vec3(1, INFINITY, 0), Vec3(2, 0, 0) };
  EXPECT_NE(message(NurbsCurve(2, { 0, 0, 0, 1, 1, 1 }, inf)).find("NaN or infinite"), std::string::npos);
  EXPECT_NE(message(NurbsCurve(2, { 0, 0, 0, 1, NAN, 1 }, pts)).find("knot 4 is not finite"), std::string::npos);
  EXPECT_NE(message(NurbsCurve(0, { 0, 1, 1, 1 }, pts)).find("degree 0"), std::string::npos);
  EXPECT_NE(message(NurbsCurve(2, { 1, 1, 1, 1, 1, 1 }, pts)).find("empty parameter domain"), std::string::npos);
}

TEST(NurbsSurface, ValidationNamesTheEntityAndTheProblem)
{
  NurbsSurface s = wavySurface();
  EXPECT_NO_THROW(s.validate("surface 0"));
  Vec4List net = s.homogeneousNet();
  net[6].w() = -1.0;
  NurbsSurface bad(3, 2, s.knotsU(), s.knotsV(), 5, 4, net);
  try
  {
    bad.validate("surface 2");
    FAIL() << "no error";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("surface 2: control point (1, 2) has weight -1"), std::string::npos) << e.what();
  }
  KnotVector ku = s.knotsU();
  ku[4] = 2.0;
  EXPECT_THROW(NurbsSurface(3, 2, ku, s.knotsV(), 5, 4, s.homogeneousNet()).validate("s"), InputError);
}

// Generators' sweep of disks along a straight bisector (firstContact): against the
// distance to every edge sampled densely along the sweep.
#include "mat2d/Generators.h"
#include "shapes/Catalogue.h"
#include "shapes/RandomShapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace exactmat;

namespace
{
// The boundary's bounding box (of its pieces' control points).
Box3 boxOf(const Boundary2D& b)
{
  Box3 box;
  for (const auto& e : b.edges())
    box.extend(e.curve.boundingBox());
  return box;
}

// The generators that are edges.
std::vector<int> edgeGenerators(const Generators& g)
{
  std::vector<int> out;
  for (int i = 0; i < g.size(); ++i)
    if (g[i].kind == GeneratorKind::Edge)
      out.push_back(i);
  return out;
}

// Distance from x to the segment [p, q].
double toSegment(const Vec2& x, const Vec2& p, const Vec2& q)
{
  const Vec2 d = q - p;
  const double t = std::clamp((x - p).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (p + t * d - x).norm();
}
} // namespace

TEST(Generators2D, SweepFindsTheFirstContactOfStraightEdges)
{
  RandomEngine rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int contacts = 0, clear = 0;
  for (int shape = 0; shape < 6; ++shape)
  {
    const RandomShape s = randomStarPolygon(rng, 12 + 10 * shape);
    const Boundary2D b = Boundary2D::build(curvePieces(s.curves));
    const Generators g(b);
    const double size = b.diagonal();
    std::vector<std::pair<Vec2, Vec2>> edges;
    for (const auto& e : b.edges())
      edges.push_back({ e.curve.startPoint().head<2>(), e.curve.endPoint().head<2>() });
    const Vec3 lo = boxOf(b).min(), hi = boxOf(b).max();
    const std::vector<int> edgeIds = edgeGenerators(g);
    for (int k = 0; k < 200; ++k)
    {
      // A sweep anywhere: centres moving up to half the size, the radius changing
      // slower than the centre moves (as along any bisector), two edges left out.
      const Vec2 x0(lo.x() + u(rng) * (hi.x() - lo.x()), lo.y() + u(rng) * (hi.y() - lo.y()));
      const Vec2 x1 = x0 + 0.5 * size * Vec2(u(rng) - 0.5, u(rng) - 0.5);
      const double r0 = 0.2 * size * u(rng), r1 = std::max(0.0, r0 + 0.9 * (x1 - x0).norm() * (2 * u(rng) - 1));
      const int skipA = edgeIds[static_cast<size_t>(u(rng) * edgeIds.size()) % edgeIds.size()],
                skipB = edgeIds[static_cast<size_t>(u(rng) * edgeIds.size()) % edgeIds.size()];
      auto gap = [&](double t) { // least distance − radius over the edges swept
        const Vec2 x = x0 + t * (x1 - x0);
        double d = INFINITY;
        for (size_t e = 0; e < edges.size(); ++e)
          if (static_cast<int>(e) != g[skipA].edge && static_cast<int>(e) != g[skipB].edge)
            d = std::min(d, toSegment(x, edges[e].first, edges[e].second));
        return d - (r0 + t * (r1 - r0));
      };
      double t = 0.0;
      const SweepContact c = g.firstContact(x0, r0, x1, r1, skipA, skipB, t);
      ASSERT_NE(c, SweepContact::Undecided) << "a polygon has only straight edges";
      constexpr int Samples = 4000;
      const double slack = 1e-9 * size;
      if (c == SweepContact::Clear)
      {
        ++clear;
        for (int i = 0; i <= Samples; ++i)
          ASSERT_GT(gap(static_cast<double>(i) / Samples), -slack) << "shape " << shape << " sweep " << k;
        continue;
      }
      ++contacts;
      ASSERT_GE(t, 0.0);
      ASSERT_LE(t, 1.0);
      EXPECT_LE(gap(t), slack) << "shape " << shape << " sweep " << k << ": no contact at t " << t;
      for (int i = 0; i < Samples && i < t * Samples; ++i)
        ASSERT_GT(gap(static_cast<double>(i) / Samples), -slack) << "shape " << shape << " sweep " << k << ": contact before " << t;
    }
  }
  // Both answers are exercised.
  EXPECT_GT(contacts, 100);
  EXPECT_GT(clear, 100);
}

TEST(Generators2D, SweepIsUndecidedOnlyNearCurvedEdges)
{
  // The rounded rectangle's straight sides and quarter circles: a sweep along the middle
  // of its long axis stays away from the corners' arcs; one into a corner does not.
  const Boundary2D b = Boundary2D::build(curvePieces(makeShape("rounded-rectangle").curves));
  const Generators g(b);
  std::vector<int> straight;
  for (int i : edgeGenerators(g))
    if (g.straight(i))
      straight.push_back(i);
  ASSERT_GE(straight.size(), 2u);
  const int straightA = straight[0], straightB = straight[1];
  const Vec3 lo = boxOf(b).min(), hi = boxOf(b).max();
  const Vec2 c = 0.5 * (lo + hi).head<2>();
  const double w = hi.x() - lo.x(), h = hi.y() - lo.y();
  double t = 0.0;
  EXPECT_NE(g.firstContact(c - Vec2(0.05 * w, 0), 0.1 * h, c + Vec2(0.05 * w, 0), 0.1 * h, straightA, straightB, t),
    SweepContact::Undecided);
  EXPECT_EQ(g.firstContact(c, 0.1 * h, hi.head<2>() - Vec2(0.05 * h, 0.05 * h), 0.04 * h, straightA, straightB, t),
    SweepContact::Undecided);
}

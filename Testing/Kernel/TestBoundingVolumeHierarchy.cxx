// BVH queries against brute force.
#include "geometry/BoundingVolumeHierarchy.h"
#include "shapes/Catalogue.h"

#include <gtest/gtest.h>

#include <random>

using namespace exactmat;

TEST(BoundingVolumeHierarchy, QueriesMatchBruteForceOnBoxes)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> c(-10, 10), s(0.01, 1.5);
  std::vector<Box3> boxes;
  for (int i = 0; i < 500; ++i)
  {
    const Vec3 lo(c(rng), c(rng), c(rng));
    boxes.emplace_back(lo, lo + Vec3(s(rng), s(rng), s(rng)));
  }
  BoundingVolumeHierarchy bvh;
  bvh.build(boxes);
  // Treat each box's centre as the "exact" item; the box is then a valid bound.
  for (int trial = 0; trial < 300; ++trial)
  {
    const Vec3 q(c(rng), c(rng), c(rng));
    auto exact = [&](int i) { return (boxes[i].center() - q).norm(); };
    double best = Unbounded;
    int bestItem = -1;
    for (int i = 0; i < 500; ++i)
      if (exact(i) < best)
      {
        best = exact(i);
        bestItem = i;
      }
    double d = 0.0;
    EXPECT_EQ(bvh.nearest(q, exact, &d), bestItem);
    EXPECT_EQ(d, best);
    const double radius = s(rng) * 3;
    std::vector<int> brute;
    for (int i = 0; i < 500; ++i)
      if (distanceToBox(boxes[i], q) <= radius)
        brute.push_back(i);
    EXPECT_EQ(bvh.candidatesWithin(q, radius), brute);
  }
}

TEST(BoundingVolumeHierarchy, NearestBoundaryPieceMatchesBruteForce)
{
  const Shape plate = makeShape("plate-with-holes");
  const auto pieces = curvePieces(plate.curves);
  std::vector<Box3> boxes;
  for (const CurvePiece& p : pieces)
    boxes.push_back(p.curve.boundingBox());
  BoundingVolumeHierarchy bvh;
  bvh.build(boxes);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> x(-2.2, 2.2), y(-1.2, 1.2);
  for (int trial = 0; trial < 200; ++trial)
  {
    const Vec3 q(x(rng), y(rng), 0);
    auto exact = [&](int i) { return closestPoint(pieces[i].curve, q).distance; };
    double best = Unbounded;
    for (size_t i = 0; i < pieces.size(); ++i)
      best = std::min(best, exact(static_cast<int>(i)));
    double d = 0.0;
    bvh.nearest(q, exact, &d);
    EXPECT_NEAR(d, best, 1e-15);
    // Every piece within 1.2 × the nearest distance is among the candidates.
    const auto cand = bvh.candidatesWithin(q, 1.2 * best);
    for (size_t i = 0; i < pieces.size(); ++i)
    {
      if (exact(static_cast<int>(i)) <= 1.2 * best)
      {
        EXPECT_TRUE(std::binary_search(cand.begin(), cand.end(), static_cast<int>(i)));
      }
    }
  }
  EXPECT_EQ(BoundingVolumeHierarchy().candidatesWithin(Vec3::Zero(), 1.0).size(), 0u);
}

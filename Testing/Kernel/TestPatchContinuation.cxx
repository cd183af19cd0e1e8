// Pieces of one rational Bézier surface (geometry/PatchContinuation): a sub-patch is found
// with the affine map of its parameters, whatever its orientation or the scale of its
// weights; a patch that only comes close is not.
#include "geometry/PatchContinuation.h"
#include "shapes/Catalogue.h"

#include <gtest/gtest.h>

#include <random>

using namespace exactmat;

namespace
{
// A pillow face with random weights in [0.5, 2]: a rational bicubic patch.
BezierPatch rationalBicubic()
{
  const BezierPatch bicubic = patchPieces(makeShape("pillow").surfaces).front().patch;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> weight(0.5, 2.0);
  Vec4List net = bicubic.homogeneousNet();
  for (Vec4& h : net)
    h *= weight(rng) / h.w();
  return BezierPatch(bicubic.degreeU(), bicubic.degreeV(), net);
}

// The same patch with its u direction reversed.
BezierPatch reversedU(const BezierPatch& patch)
{
  Vec4List net;
  for (int i = patch.degreeU(); i >= 0; --i)
    for (int j = 0; j <= patch.degreeV(); ++j)
      net.push_back(patch.homogeneousPoint(i, j));
  return BezierPatch(patch.degreeU(), patch.degreeV(), net);
}
} // namespace

TEST(PatchContinuation, SubPatchesMapAffinely)
{
  const BezierPatch surface = rationalBicubic();
  const double tolerance = 1e-10 * 4.0;
  ParameterMap map;
  ASSERT_TRUE(pieceOfSurface(surface, surface.subPatch(0.2, 0.5, 0.6, 0.9), tolerance, map));
  EXPECT_LT((map.origin - Vec2(0.2, 0.6)).norm(), 1e-9);
  EXPECT_LT((map.axes - Eigen::Matrix2d(Eigen::Vector2d(0.3, 0.3).asDiagonal())).norm(), 1e-9);
  EXPECT_LT((map.inverse(Vec2(0.35, 0.75)) - Vec2(0.5, 0.5)).norm(), 1e-9);
  // The surface is a piece of its piece too: beyond the piece's own square.
  ASSERT_TRUE(pieceOfSurface(surface.subPatch(0.2, 0.5, 0.6, 0.9), surface, tolerance, map));
  EXPECT_LT((map(Vec2(0.2, 0.6)) - Vec2(0.0, 0.0)).norm(), 1e-9);
  // Reversed, and with every weight scaled (the same surface).
  ASSERT_TRUE(pieceOfSurface(surface, reversedU(surface.subPatch(0.0, 0.25, 0.0, 1.0)), tolerance, map));
  EXPECT_LT((map(Vec2(0.0, 0.0)) - Vec2(0.25, 0.0)).norm(), 1e-9);
  Vec4List scaled = surface.subPatch(0.7, 1.0, 0.1, 0.2).homogeneousNet();
  for (Vec4& h : scaled)
    h *= 7.0;
  EXPECT_TRUE(pieceOfSurface(surface, BezierPatch(3, 3, scaled), tolerance, map));
}

TEST(PatchContinuation, PatchesThatOnlyComeCloseAreNot)
{
  const BezierPatch surface = rationalBicubic();
  const double tolerance = 1e-10 * 4.0;
  ParameterMap map;
  // An inner control point moved by 1e-6: corners and sides still on the surface.
  Vec4List net = surface.subPatch(0.2, 0.5, 0.6, 0.9).homogeneousNet();
  net[5] += Vec4(1e-6, 0.0, 0.0, 0.0) * net[5].w();
  EXPECT_FALSE(pieceOfSurface(surface, BezierPatch(3, 3, net), tolerance, map));
  // Another face of the pillow (it meets this one at an edge).
  EXPECT_FALSE(pieceOfSurface(surface, patchPieces(makeShape("pillow").surfaces)[1].patch, tolerance, map));
}

// Neighbouring pieces far from the origin, one a sliver: matched larger on smaller whichever
// way they are asked (the sliver's extension evaluated fifty widths away multiplies the
// rounding of coordinates near 1e5 by thousands), the maps inverted and composed exactly.
TEST(PatchContinuation, NeighbourPiecesMatchWhicheverWayAsked)
{
  Vec4List net = rationalBicubic().homogeneousNet();
  for (Vec4& h : net)
    h.head<3>() += Vec3(1e5, -7e4, 4e4) * h.w();
  const BezierPatch surface(3, 3, net);
  const BezierPatch sliver = surface.subPatch(0.5, 0.51, 0.0, 1.0), wide = surface.subPatch(0.51, 1.0, 0.0, 1.0);
  const double tolerance = 64.0 * std::numeric_limits<double>::epsilon() * 1.3e5;
  ParameterMap wideInSliver, sliverInWide;
  ASSERT_TRUE(piecesOfOneSurface(sliver, wide, tolerance, wideInSliver));
  ASSERT_TRUE(piecesOfOneSurface(wide, sliver, tolerance, sliverInWide));
  EXPECT_LT((wideInSliver(Vec2(0.0, 0.0)) - Vec2(1.0, 0.0)).norm(), 1e-6);
  EXPECT_LT((wideInSliver(Vec2(1.0, 1.0)) - Vec2(50.0, 1.0)).norm(), 1e-6);
  // One map is the other's inverse; composed, they are the identity.
  const ParameterMap round = wideInSliver.after(sliverInWide);
  EXPECT_LT((round(Vec2(0.3, 0.7)) - Vec2(0.3, 0.7)).norm(), 1e-6);
  EXPECT_LT((wideInSliver.inverted()(Vec2(25.5, 0.5)) - sliverInWide(Vec2(25.5, 0.5))).norm(), 1e-6);
}

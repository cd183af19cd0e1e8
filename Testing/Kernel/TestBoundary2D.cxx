// The planar B-rep: loops, orientation, classification and bad input.
#include "brep/Boundary2D.h"
#include "geometry/CurveCrossings.h"
#include "common/InputError.h"
#include "shapes/Catalogue.h"
#include "shapes/Primitives.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace exactmat;

namespace
{
Boundary2D buildShape(const std::string& name)
{
  return Boundary2D::build(curvePieces(makeShape(name).curves));
}

std::string errorOf(const std::vector<CurvePiece>& pieces)
{
  try
  {
    Boundary2D::build(pieces);
  }
  catch (const InputError& e)
  {
    return e.what();
  }
  return "";
}

std::vector<CurvePiece> piecesOf(const std::vector<NurbsCurve>& curves)
{
  return curvePieces(curves);
}
} // namespace

struct Expected2D
{
  const char* name;
  int loops, holes, convex, reflex, smooth;
};

class CatalogueShape2D : public ::testing::TestWithParam<Expected2D>
{
};

TEST_P(CatalogueShape2D, LoopsOrientationAndVertexKinds)
{
  const Expected2D e = GetParam();
  const Boundary2D b = buildShape(e.name);
  EXPECT_EQ(static_cast<int>(b.loops().size()), e.loops);
  EXPECT_EQ(b.holeCount(), e.holes);
  EXPECT_EQ(b.countVertices(VertexKind::Convex), e.convex);
  EXPECT_EQ(b.countVertices(VertexKind::Reflex), e.reflex);
  EXPECT_EQ(b.countVertices(VertexKind::Smooth), e.smooth);
  for (const Loop2D& loop : b.loops())
  {
    // Material on the left: outer loops counter-clockwise, holes clockwise.
    EXPECT_EQ(loop.signedArea > 0.0, loop.outer);
    // Closed: each edge ends where the next starts.
    for (size_t k = 0; k < loop.edges.size(); ++k)
    {
      const Edge2D& a = b.edges()[loop.edges[k]];
      const Edge2D& c = b.edges()[loop.edges[(k + 1) % loop.edges.size()]];
      EXPECT_LT((a.curve.endPoint() - c.curve.startPoint()).norm(), 1e-9 * b.diagonal());
      EXPECT_EQ(a.endVertex, c.startVertex);
    }
  }
  // Every left normal points into the material: a point a little along it is inside.
  // (Checked through the area sign above; here: the edges' z is exactly 0.)
  for (const Edge2D& edge : b.edges())
    for (int i = 0; i <= edge.curve.degree(); ++i)
      EXPECT_EQ(edge.curve.controlPoint(i).z(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Catalogue, CatalogueShape2D,
  ::testing::Values(Expected2D{ "rectangle", 1, 0, 4, 0, 0 },
    Expected2D{ "rounded-rectangle", 1, 0, 0, 0, 8 },
    Expected2D{ "circle", 1, 0, 0, 0, 4 }, Expected2D{ "ellipse", 1, 0, 0, 0, 4 },
    Expected2D{ "annulus", 2, 1, 0, 0, 8 }, Expected2D{ "l-shape", 1, 0, 5, 1, 0 },
    Expected2D{ "star", 1, 0, 5, 5, 0 }, Expected2D{ "blob", 1, 0, 0, 0, 20 },
    Expected2D{ "spiral", 1, 0, 4, 0, 90 }, Expected2D{ "plate-with-holes", 4, 3, 4, 0, 4 + 4 + 12 },
    Expected2D{ "narrow-passage", 1, 0, 0, 4, 6 }),
  [](const auto& info) {
    std::string n = info.param.name;
    std::replace(n.begin(), n.end(), '-', '_');
    return n;
  });

TEST(Boundary2D, AreasAreExact)
{
  EXPECT_NEAR(buildShape("rectangle").loops()[0].signedArea, 8.0, 1e-13);
  EXPECT_NEAR(buildShape("circle").loops()[0].signedArea, M_PI, 1e-12);
  const Boundary2D annulus = buildShape("annulus");
  EXPECT_NEAR(annulus.loops()[0].signedArea + annulus.loops()[1].signedArea, M_PI * 0.75, 1e-12);
  const Boundary2D ellipse = buildShape("ellipse");
  EXPECT_NEAR(ellipse.loops()[0].signedArea, M_PI * 2.0 * 1.0, 1e-12);
}

TEST(Boundary2D, FixesOrientationAndEdgeDirection)
{
  // A clockwise square whose edges also point every which way: the loop comes out
  // counter-clockwise, with the reversed pieces marked.
  std::vector<NurbsCurve> curves{ makeSegment(Vec3(0, 0, 0), Vec3(0, 1, 0)),
    makeSegment(Vec3(1, 1, 0), Vec3(0, 1, 0)), makeSegment(Vec3(1, 1, 0), Vec3(1, 0, 0)),
    makeSegment(Vec3(0, 0, 0), Vec3(1, 0, 0)) };
  const Boundary2D b = Boundary2D::build(piecesOf(curves));
  ASSERT_EQ(b.loops().size(), 1u);
  EXPECT_NEAR(b.loops()[0].signedArea, 1.0, 1e-15);
  EXPECT_EQ(b.countVertices(VertexKind::Convex), 4);
  int reversed = 0;
  for (const Edge2D& e : b.edges())
    reversed += e.reversed;
  EXPECT_EQ(reversed, 2);
  // A counter-clockwise hole is turned clockwise.
  std::vector<NurbsCurve> ring{ makeArc(Vec3::Zero(), 2, 0, 2 * M_PI), makeArc(Vec3::Zero(), 1, 0, 2 * M_PI) };
  const Boundary2D r = Boundary2D::build(piecesOf(ring));
  EXPECT_EQ(r.holeCount(), 1);
  for (const Loop2D& l : r.loops())
    EXPECT_EQ(l.outer, l.signedArea > 0);
}

TEST(Boundary2D, FindsThePlaneOfATiltedDomain)
{
  // The L-shape rotated out of z = 0 and shifted: same classification, planar frame found.
  Shape l = makeShape("l-shape");
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(0.7, Vec3(1, 2, 0.5).normalized())).toRotationMatrix();
  for (NurbsCurve& c : l.curves)
  {
    Vec4List p = c.homogeneousPoints();
    for (Vec4& h : p)
      h.head<3>() = R * h.head<3>() + h.w() * Vec3(3, -1, 2);
    c = NurbsCurve(c.degree(), c.knots(), p);
  }
  const Boundary2D b = Boundary2D::build(curvePieces(l.curves));
  EXPECT_EQ(b.countVertices(VertexKind::Reflex), 1);
  EXPECT_EQ(b.countVertices(VertexKind::Convex), 5);
  EXPECT_NEAR(std::abs(b.plane().normal.dot(R * Vec3::UnitZ())), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(b.loops()[0].signedArea), 4 + 2 - 1, 1e-11);
  // Round trip of a vertex through the frame.
  const Vec3 w = b.plane().toWorld(b.vertices()[0].point);
  EXPECT_NEAR(b.plane().toLocal(w).z(), 0.0, 1e-12);
}

TEST(Boundary2D, BadInputGivesClearErrors)
{
  EXPECT_NE(errorOf({}).find("empty input"), std::string::npos);
  // Open loop: a square missing an edge.
  std::vector<NurbsCurve> open = makePolygon({ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0) });
  open.pop_back();
  const std::string o = errorOf(piecesOf(open));
  EXPECT_NE(o.find("open loop: edge 0 starts at (0, 0, 0)"), std::string::npos) << o;
  // Self-intersecting: a bow tie.
  const std::string s = errorOf(piecesOf(makePolygon({ Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(1, 0, 0), Vec3(0, 1, 0) })));
  EXPECT_NE(s.find("self-intersecting loop 0: edge 0 crosses edge 2"), std::string::npos) << s;
  // Two loops that cross.
  std::vector<NurbsCurve> two{ makeArc(Vec3::Zero(), 1, 0, 2 * M_PI), makeArc(Vec3(1, 0, 0), 1, 0, 2 * M_PI) };
  const std::string t = errorOf(piecesOf(two));
  EXPECT_NE(t.find("loops 0 and 1 intersect"), std::string::npos) << t;
  // Non-planar.
  const std::string np = errorOf(piecesOf(makePolygon({ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0.2), Vec3(0, 1, 0) })));
  EXPECT_NE(np.find("non-planar boundary"), std::string::npos) << np;
  // NaN coordinates and bad weights are named with the edge.
  std::vector<CurvePiece> nan = piecesOf(makePolygon({ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0) }));
  nan[1].curve = BezierCurve(Vec3List{ Vec3(1, 0, 0), Vec3(NAN, 1, 0) }, {});
  EXPECT_NE(errorOf(nan).find("edge 1: control point 1 has a NaN"), std::string::npos) << errorOf(nan);
  std::vector<CurvePiece> weight = piecesOf(makePolygon({ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0) }));
  weight[2].curve = BezierCurve(Vec3List{ Vec3(0, 1, 0), Vec3(0.1, 0.5, 0), Vec3(0, 0, 0) }, { 1, 0, 1 });
  weight[2].entity = 9;
  EXPECT_NE(errorOf(weight).find("edge 2 (entity 9): control point 1 has weight 0"), std::string::npos) << errorOf(weight);
  // Three edges at one vertex.
  std::vector<NurbsCurve> fig8 = makePolygon({ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0) });
  const auto more = makePolygon({ Vec3(0, 0, 0), Vec3(-1, 0, 0), Vec3(-1, -1, 0) });
  fig8.insert(fig8.end(), more.begin(), more.end());
  EXPECT_NE(errorOf(piecesOf(fig8)).find("non-manifold vertex"), std::string::npos) << errorOf(piecesOf(fig8));
  // A zero-length edge.
  std::vector<CurvePiece> zero = piecesOf(makePolygon({ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0) }));
  zero.push_back(CurvePiece{ BezierCurve(Vec3List{ Vec3(5, 5, 0), Vec3(5, 5, 0) }, {}), -1, -1, -1 });
  EXPECT_NE(errorOf(zero).find("degenerate"), std::string::npos) << errorOf(zero);
}

TEST(Boundary2D, ConnectsByPointIdsWhenGiven)
{
  // Coordinates of the shared ends differ by far more than the tolerance; ids join them.
  std::vector<CurvePiece> p = piecesOf(makePolygon({ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0) }));
  for (size_t i = 0; i < p.size(); ++i)
  {
    p[i].startId = static_cast<long long>(i);
    p[i].endId = static_cast<long long>((i + 1) % p.size());
  }
  EXPECT_EQ(Boundary2D::build(p).loops().size(), 1u);
}

// The crossing check halves curves only where parts come close; a curve that loops onto
// itself inside one half of its piece must still be found, and the verdict must be the
// one the full flattening gives.
TEST(Boundary2D, CrossingsFoundWhereverTheyAre)
{
  // A cubic with a loop, extrapolated to twice its parameter range: the loop lies in the
  // first half of the piece. Closed by a straight edge.
  const BezierCurve loopCubic(Vec3List{ Vec3(0, 0, 0), Vec3(3, 2, 0), Vec3(-1, 2, 0), Vec3(2, 0, 0) }, {});
  BezierCurve extended, beyond;
  loopCubic.split(2.0, extended, beyond);
  const BezierCurve closing(Vec3List{ extended.endPoint(), extended.startPoint() }, {});
  const CurveCrossing x = findCrossing({ { &extended, &closing } }, 1e-6);
  EXPECT_TRUE(x.found);
  EXPECT_EQ(x.curveA, 0);
  EXPECT_EQ(x.curveB, 0);
  std::vector<CurvePiece> pieces(2);
  pieces[0].curve = extended;
  pieces[1].curve = closing;
  const std::string e = errorOf(pieces);
  EXPECT_NE(e.find("edge 0 crosses itself"), std::string::npos) << e;
  // Valid shapes, curved and straight, close to themselves (the narrow passage) or not.
  for (const char* name : { "ellipse", "spiral", "narrow-passage", "plate-with-holes", "blob", "annulus" })
  {
    const Shape s = makeShape(name);
    EXPECT_NO_THROW(Boundary2D::build(curvePieces(s.curves))) << name;
  }
  // Two circles 1e-3 apart do not cross; two that overlap by 1e-4 do.
  std::vector<NurbsCurve> apart{ makeArc(Vec3::Zero(), 1, 0, 2 * M_PI), makeArc(Vec3(2.001, 0, 0), 1, 0, 2 * M_PI) };
  EXPECT_NO_THROW(Boundary2D::build(piecesOf(apart)));
  std::vector<NurbsCurve> overlap{ makeArc(Vec3::Zero(), 1, 0, 2 * M_PI), makeArc(Vec3(1.9999, 0, 0), 1, 0, 2 * M_PI) };
  EXPECT_NE(errorOf(piecesOf(overlap)).find("loops 0 and 1 intersect"), std::string::npos);
}

// Consecutive curves are passed as one when their control polygons advance along one
// direction (smooth and mild corners); those that fold back at their joint are still
// searched: a curve that turns back across the one before it is a crossing.
TEST(Boundary2D, ConsecutiveCurvesThatFoldBackCross)
{
  // a → b straight, then a quadratic from b that turns back across the first edge.
  const BezierCurve first(Vec3List{ Vec3(0, 0, 0), Vec3(2, 0, 0) }, {});
  const BezierCurve back(Vec3List{ Vec3(2, 0, 0), Vec3(0, 2, 0), Vec3(1, -1, 0) }, {});
  const BezierCurve closing(Vec3List{ Vec3(1, -1, 0), Vec3(0, 0, 0) }, {});
  const CurveCrossing x = findCrossing({ { &first, &back, &closing } }, 1e-6);
  EXPECT_TRUE(x.found);
  // The same corner without the fold: no crossing.
  const BezierCurve up(Vec3List{ Vec3(2, 0, 0), Vec3(3, 2, 0), Vec3(1, 3, 0) }, {});
  const BezierCurve home(Vec3List{ Vec3(1, 3, 0), Vec3(0, 0, 0) }, {});
  EXPECT_FALSE(findCrossing({ { &first, &up, &home } }, 1e-6).found);
  // A polygon with a spike one ulp-scale wide at a joint: the two edges of the spike
  // nearly coincide but do not cross.
  const BezierCurve in(Vec3List{ Vec3(1, 1e-9, 0), Vec3(3, 1, 0) }, {});
  const BezierCurve out(Vec3List{ Vec3(3, 1, 0), Vec3(1, 2e-9, 0) }, {});
  const BezierCurve base0(Vec3List{ Vec3(0, 0, 0), Vec3(1, 1e-9, 0) }, {});
  const BezierCurve base1(Vec3List{ Vec3(1, 2e-9, 0), Vec3(0, 3, 0) }, {});
  const BezierCurve base2(Vec3List{ Vec3(0, 3, 0), Vec3(0, 0, 0) }, {});
  EXPECT_FALSE(findCrossing({ { &base0, &in, &out, &base1, &base2 } }, 1e-6).found);
}

// Nesting is decided on coarse polygons where the probe is far from a loop and on fine
// ones where it is close: a hole 1e-4 inside the outer loop, and an island in the hole.
TEST(Boundary2D, NestingOfCloseLoops)
{
  std::vector<NurbsCurve> loops{ makeArc(Vec3::Zero(), 1, 0, 2 * M_PI),
    makeArc(Vec3::Zero(), 0.9999, 0, 2 * M_PI), makeArc(Vec3(0.2, 0, 0), 0.5, 0, 2 * M_PI) };
  const Boundary2D b = Boundary2D::build(piecesOf(loops));
  ASSERT_EQ(b.loops().size(), 3u);
  EXPECT_EQ(b.holeCount(), 1);
  int outer = 0;
  for (const Loop2D& l : b.loops())
    outer += l.outer ? 1 : 0;
  EXPECT_EQ(outer, 2);
  // The island's parent is the hole, the hole's the outer loop.
  for (const Loop2D& l : b.loops())
    if (!l.outer)
      EXPECT_NEAR(std::abs(l.signedArea), M_PI * 0.9999 * 0.9999, 1e-9);
}

// The MAT of extruded and revolved solids (thesis ch. 5) against closed forms and the
// exact swept boundary.
#include "common/InputError.h"
#include "mat25d/MAT25D.h"
#include "mat25d/SweptBoundary.h"
#include "medial/Verification.h"
#include "mat2d/Tracer.h"
#include "shapes/Catalogue.h"
#include "shapes/Primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace exactmat;

namespace
{
// Global distance = Radius to this fraction of the solid's size (the bound).
constexpr double VerifiedDistanceTolerance = 1e-9;

struct SweptMAT
{
  std::unique_ptr<Boundary2D> profile;
  std::unique_ptr<Generators> generators;
  MedialGraph graph;
  std::unique_ptr<SweepMap> sweep;
  MedialComplex mat;
  std::unique_ptr<SweptBoundary> boundary;
};

std::unique_ptr<SweptMAT> run(
  const std::vector<NurbsCurve>& curves, const Sweep& sweep, const MAT25DOptions& options = {})
{
  auto r = std::make_unique<SweptMAT>();
  r->profile = std::make_unique<Boundary2D>(Boundary2D::build(curvePieces(curves)));
  r->generators = std::make_unique<Generators>(*r->profile);
  r->graph = computeMAT2D(*r->generators);
  r->sweep = std::make_unique<SweepMap>(*r->profile, sweep);
  r->mat = computeMAT25D(*r->generators, r->graph, *r->sweep, options);
  r->boundary = std::make_unique<SweptBoundary>(*r->profile, *r->sweep);
  return r;
}

Sweep extrusion(double length)
{
  return Sweep::extrusion(length);
}

Sweep revolution(double degrees, const Vec3& axisPoint = Vec3::Zero(),
  const Vec3& axisDirection = Vec3::UnitY())
{
  return Sweep::revolution(degrees, axisPoint, axisDirection);
}

void expectVerified(const SweptMAT& r, const std::string& what, int stride = 1)
{
  const MedialVerification v = verifyMedialComplex(*r.boundary, r.mat, stride);
  EXPECT_LE(v.maxDistanceError, VerifiedDistanceTolerance)
    << what << ": worst point " << v.worstPoint << " ("
    << (v.worstPoint >= 0 ? toString(r.mat.points[v.worstPoint].type) : "") << ")";
  EXPECT_EQ(v.contactMismatches, 0)
    << what << ": first point " << v.firstMismatch << " ("
    << (v.firstMismatch >= 0 ? toString(r.mat.points[v.firstMismatch].type) : "") << ", expected "
    << (v.firstMismatch >= 0 ? r.mat.points[v.firstMismatch].contacts : 0) << " touchpoints, has "
    << v.firstMismatchCount << ") of " << v.contactsChecked;
}

std::vector<Vec3> junctions(const MedialComplex& mat)
{
  std::vector<Vec3> out;
  for (const MedialElement& e : mat.elements)
    if (e.type == MedialElementType::Junction)
      out.push_back(mat.points[e.points.front()].x);
  return out;
}

bool contains(const std::vector<Vec3>& points, const Vec3& p, double tol)
{
  for (const Vec3& q : points)
    if ((q - p).norm() <= tol)
      return true;
  return false;
}
} // namespace

// The box: a 4×2 rectangle extruded by 3. Profile MAT: branch points (±1, 0), r = 1.
TEST(MAT25D, BoxJunctionsAndSeams)
{
  const auto r = run(makeShape("rectangle").curves, extrusion(3.0));
  const std::vector<Vec3> j = junctions(r->mat);
  ASSERT_EQ(j.size(), 4u);
  for (const Vec3& p : { Vec3(-1, 0, 1), Vec3(1, 0, 1), Vec3(-1, 0, 2), Vec3(1, 0, 2) })
    EXPECT_TRUE(contains(j, p, 1e-12)) << p.transpose();
  // 5 profile segments → 10 face seams, + 2 fourth seams (rulings x = ±1, z ∈ [1, 2]).
  EXPECT_EQ(r->mat.count(MedialElementType::Seam), 12);
  EXPECT_EQ(r->mat.count(MedialElementType::SweptSheet), 5);
  EXPECT_EQ(r->mat.count(MedialElementType::ProfileSheet), 20);
  EXPECT_EQ(r->mat.count(MedialElementType::SkeletalEdge), 0);
  EXPECT_NEAR(r->mat.maximumRadius(), 1.0, 1e-12);
  // The middle sheet is y = 0, |x| ≤ 1, z ∈ [1, 2], radius 1; the ball touches y = ±1.
  for (const MedialPoint3D& p : r->mat.points)
  {
    if (p.type == MedialPoint3DType::Sheet && std::abs(p.x.y()) < 1e-12 && std::abs(p.x.x()) < 1 - 1e-9)
    {
      EXPECT_NEAR(p.radius, 1.0, 1e-12);
    }
  }
  expectVerified(*r, "box");
  EXPECT_GT(verifyMedialComplex(*r->boundary, r->mat, 7).contactsChecked, 10);
}

// Sheets built strip by strip share their border vertices after the weld: no two output
// points coincide, and every triangle edge of the profile sheets over one side's strip
// interior is shared by two triangles of the complex.
TEST(MAT25D, OutputPointsAreDistinct)
{
  for (const auto& r : { run(makeShape("rectangle").curves, extrusion(3.0)),
         run(makeShape("plate-with-holes").curves, extrusion(0.6), MAT25DOptions{ 0.05, {} }),
         run(makeShape("l-shape").curves, revolution(360.0, Vec3(-1, 0, 0))) })
  {
    const std::vector<MedialPoint3D>& p = r->mat.points;
    const double tol = 1e-10 * r->boundary->size();
    std::vector<int> order(p.size());
    for (size_t i = 0; i < p.size(); ++i)
      order[i] = static_cast<int>(i);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return p[a].x.x() < p[b].x.x(); });
    int duplicates = 0;
    for (size_t i = 0; i < order.size(); ++i)
      for (size_t j = i + 1; j < order.size() && p[order[j]].x.x() - p[order[i]].x.x() <= tol; ++j)
        duplicates += (p[order[i]].x - p[order[j]].x).norm() <= tol;
    EXPECT_EQ(duplicates, 0) << r->sweep->describe();
  }
}

namespace
{
// Brute-force junction search on the exact swept solid, independent of the 2D MAT: a grid
// of points inside the solid; where four distinct touchpoints lie within the grid's
// reach of the nearest one, Newton on the equidistance system |x − F_i(x)| = r for the
// four faces (F_i: the nearest point of that face next to the previous one) finds the
// point with four equidistant touchpoints. Returns the distinct junctions found.
std::vector<Vec3> bruteForceJunctions(const SweptMAT& r, double spacing)
{
  const SweptBoundary& b = *r.boundary;
  Box3 box;
  for (const PatchPiece& p : b.sides())
    box.extend(p.patch.boundingBox());
  const double size = b.size();
  auto contactOn = [&](int source, const Vec3& x, const Vec3& near) {
    SolidBoundary::Contact c;
    c.source = source;
    if (source < 0)
    {
      c.distance = b.faceDistance(source == SweptBoundary::ProfileFace0 ? 0 : 1, x, &c.point);
      return c;
    }
    double best = Unbounded;
    for (const PatchFootpoint& f : patchFootpoints(b.sides()[source].patch, x))
    {
      if ((f.point - near).norm() < best)
      {
        best = (f.point - near).norm();
        c.point = f.point;
        c.distance = f.distance;
      }
    }
    return c;
  };
  std::vector<Vec3> found;
  const Vec3 lo = box.min(), hi = box.max();
  for (double x = lo.x() + spacing / 2; x < hi.x(); x += spacing)
  {
    for (double y = lo.y() + spacing / 2; y < hi.y(); y += spacing)
    {
      for (double z = lo.z() + spacing / 2; z < hi.z(); z += spacing)
      {
        const Vec3 q(x, y, z);
        const double d = b.distance(q);
        if (!(d > 0.0) || !std::isfinite(d))
          continue;
        // Inside the solid: the ball about q of radius d is inside the swept region.
        Vec2 foot;
        double h = 0.0;
        if (!r.sweep->closed())
        {
          if (!r.sweep->projectOnProfileFace(0, q, foot, h) || !b.insideProfile(foot))
            continue;
        }
        std::vector<SolidBoundary::Contact> c = b.touchpoints(q, d + 2.0 * spacing);
        if (c.size() < 4)
          continue;
        c.resize(4);
        // Newton on (x, r).
        Vec3 p = q;
        double radius = d;
        bool converged = false;
        for (int it = 0; it < 30 && !converged; ++it)
        {
          Eigen::Matrix4d J;
          Eigen::Vector4d F;
          for (int i = 0; i < 4; ++i)
          {
            c[i] = contactOn(c[i].source, p, c[i].point);
            if (!std::isfinite(c[i].distance) || c[i].distance <= 0.0)
              break;
            const Vec3 u = (p - c[i].point) / c[i].distance;
            J.row(i) << u.x(), u.y(), u.z(), -1.0;
            F(i) = c[i].distance - radius;
          }
          const Eigen::Vector4d step = J.fullPivLu().solve(-F);
          if (!step.allFinite() || step.head<3>().norm() > spacing * 4)
            break;
          p += step.head<3>();
          radius += step(3);
          converged = F.cwiseAbs().maxCoeff() < 1e-13 * size && step.norm() < 1e-12 * size;
        }
        if (!converged || std::abs(b.distance(p) - radius) > 1e-10 * size)
          continue;
        // Four distinct touchpoints (two faces ending on one reflex edge touch there once).
        bool distinct = true;
        for (int i = 0; i < 4; ++i)
          for (int k = i + 1; k < 4; ++k)
            distinct = distinct && (c[i].point - c[k].point).norm() > 1e-6 * size;
        if (!distinct)
          continue;
        if (!contains(found, p, 1e-7 * size))
          found.push_back(p);
      }
    }
  }
  return found;
}
} // namespace

TEST(MAT25D, BruteForceFindsTheSameJunctions)
{
  for (const auto& [name, sweep] :
    { std::pair<std::string, Sweep>{ "rectangle", extrusion(3.0) },
      std::pair<std::string, Sweep>{ "l-shape", extrusion(2.5) },
      std::pair<std::string, Sweep>{ "rectangle", revolution(90.0, Vec3(-3, 0, 0)) } })
  {
    const auto r = run(makeShape(name).curves, sweep);
    const std::vector<Vec3> reported = junctions(r->mat);
    const std::vector<Vec3> brute = bruteForceJunctions(*r, 0.2);
    const std::string what = name + " " + r->sweep->describe();
    EXPECT_EQ(brute.size(), reported.size()) << what;
    for (const Vec3& p : brute)
      EXPECT_TRUE(contains(reported, p, 1e-9)) << what << ": " << p.transpose();
  }
}

// The extruded L: legs 1 thick; profile branch points at the leg ends (3.5, 0.5),
// (0.5, 1.5) with r = 0.5, and at the corner on y = x with r = 2 − √2 (equidistant from
// x = 0, y = 0 and the reflex corner (1, 1)).
TEST(MAT25D, ExtrudedLShape)
{
  const double L = 2.5, c = 2.0 - std::sqrt(2.0);
  const auto r = run(makeShape("l-shape").curves, extrusion(L));
  const std::vector<Vec3> j = junctions(r->mat);
  ASSERT_EQ(j.size(), 6u);
  for (const Vec3& p : { Vec3(3.5, 0.5, 0.5), Vec3(0.5, 1.5, 0.5), Vec3(c, c, c),
         Vec3(3.5, 0.5, L - 0.5), Vec3(0.5, 1.5, L - 0.5), Vec3(c, c, L - c) })
    EXPECT_TRUE(contains(j, p, 1e-12)) << p.transpose();
  // The reflex edge governs sheets: the profile sheets over the corner's wedge are
  // equidistant from a profile face and the edge x = y = 1.
  int reflexSheets = 0;
  const int reflexEdge = static_cast<int>(r->profile->edges().size()) + 2;
  for (const MedialElement& e : r->mat.elements)
    for (int g : e.governors)
      reflexSheets += g >= reflexEdge && e.type == MedialElementType::ProfileSheet;
  EXPECT_GE(reflexSheets, 2);
  expectVerified(*r, "extruded L");
}

// The revolved rectangle, a hollow cylinder segment: the 4×2 profile, 1 to 5 from the axis
// x = −3 (along y), turned by 90°. A branch point at distance ρ from the axis becomes the
// junctions at angles asin(1/ρ) and 90° − asin(1/ρ) on the circle of radius ρ (y = 0).
TEST(MAT25D, RevolvedRectangleIsAHollowCylinderSegment)
{
  const auto r = run(makeShape("rectangle").curves, revolution(90.0, Vec3(-3, 0, 0)));
  const std::vector<Vec3> j = junctions(r->mat);
  ASSERT_EQ(j.size(), 4u);
  for (const double rho : { 2.0, 4.0 })
  {
    for (const double angle : { std::asin(1.0 / rho), Pi / 2 - std::asin(1.0 / rho) })
    {
      // Right-handed about +y: the profile direction +x turns towards −z.
      const Vec3 expected(-3.0 + rho * std::cos(angle), 0.0, -rho * std::sin(angle));
      EXPECT_TRUE(contains(j, expected, 1e-12)) << expected.transpose();
    }
  }
  // Every junction ball touches the start or end face at distance 1.
  for (const MedialElement& e : r->mat.elements)
  {
    if (e.type == MedialElementType::Junction)
    {
      EXPECT_NEAR(r->mat.points[e.points[0]].radius, 1.0, 1e-12);
    }
  }
  expectVerified(*r, "revolved rectangle");
}

// The 360° revolved disk off the axis is a torus: its MAT is the core circle.
TEST(MAT25D, TorusIsItsCoreCircle)
{
  const auto r = run(makeShape("circle").curves, revolution(360.0, Vec3(-3, 0, 0)));
  EXPECT_EQ(r->mat.count(MedialElementType::CentreCurve), 1);
  EXPECT_EQ(r->mat.count(MedialElementType::Junction), 0);
  EXPECT_EQ(r->mat.count(MedialElementType::Seam), 0);
  EXPECT_EQ(r->mat.count(MedialElementType::ProfileSheet), 0);
  EXPECT_EQ(r->mat.count(MedialElementType::SweptSheet), 0);
  ASSERT_FALSE(r->mat.points.empty());
  for (const MedialPoint3D& p : r->mat.points)
  {
    EXPECT_NEAR(std::hypot(p.x.x() + 3.0, p.x.z()), 3.0, 1e-12);
    EXPECT_NEAR(p.x.y(), 0.0, 1e-12);
    EXPECT_NEAR(p.radius, 1.0, 1e-12);
  }
  const MedialElement& core = r->mat.elements.front();
  EXPECT_EQ(core.points.front(), core.points.back()); // closed
  expectVerified(*r, "torus", 1);
}

// A 360° revolution keeps no seams from faces: the profile MAT turned into sheets, its
// branch points into seam circles, its convex vertices into the solid's convex edges.
TEST(MAT25D, FullRevolutionOfARectangle)
{
  const auto r = run(makeShape("rectangle").curves, revolution(360.0, Vec3(-3, 0, 0)));
  EXPECT_EQ(r->mat.count(MedialElementType::Junction), 0);
  EXPECT_EQ(r->mat.count(MedialElementType::Seam), 2); // the branch points' circles
  EXPECT_EQ(r->mat.count(MedialElementType::SweptSheet), 5);
  EXPECT_EQ(r->mat.count(MedialElementType::ProfileSheet), 0);
  expectVerified(*r, "full revolution");
}

// The extruded ellipse (a = 2, b = 1): its profile MAT ends at the centres of curvature
// (±1.5, 0) of the vertices (r = b²/a = 0.5): skeletal edges along z from 0.5 to L − 0.5.
TEST(MAT25D, ExtrudedEllipseHasSkeletalEdges)
{
  const double L = 3.0;
  const auto r = run(makeShape("ellipse").curves, extrusion(L));
  EXPECT_EQ(r->mat.count(MedialElementType::SkeletalEdge), 2);
  for (const MedialElement& e : r->mat.elements)
  {
    if (e.type != MedialElementType::SkeletalEdge)
      continue;
    const Vec3 a = r->mat.points[e.points.front()].x, b = r->mat.points[e.points.back()].x;
    EXPECT_NEAR(std::abs(a.x()), 1.5, 1e-9);
    EXPECT_NEAR(a.y(), 0.0, 1e-9);
    EXPECT_NEAR(std::min(a.z(), b.z()), 0.5, 1e-9);
    EXPECT_NEAR(std::max(a.z(), b.z()), L - 0.5, 1e-9);
    EXPECT_NEAR((a - b).head<2>().norm(), 0.0, 1e-12);
  }
  EXPECT_EQ(r->mat.count(MedialElementType::Junction), 0);
  expectVerified(*r, "extruded ellipse");
}

// Span exactly 2·Rmax: both seams of the middle segment meet (degenerate seam, four
// touchpoints) and each junction touches both profile faces (five).
TEST(MAT25D, DegenerateJunctionsAtSpanTwiceRmax)
{
  const auto r = run(makeShape("rectangle").curves, extrusion(2.0));
  const std::vector<Vec3> j = junctions(r->mat);
  ASSERT_EQ(j.size(), 2u);
  EXPECT_TRUE(contains(j, Vec3(-1, 0, 1), 1e-12));
  EXPECT_TRUE(contains(j, Vec3(1, 0, 1), 1e-12));
  for (const MedialElement& e : r->mat.elements)
  {
    if (e.type == MedialElementType::Junction)
    {
      EXPECT_EQ(r->mat.points[e.points[0]].contacts, 5);
    }
  }
  expectVerified(*r, "box of length 2·Rmax");
}

// Spans shorter than 2·Rmax (outside chapter 5's method): the 4×2×1.5 box. The ball
// meets both end faces (z = 0, 1.5) before its 2D radius wherever the profile's medial
// radius exceeds h = 0.75: a mid-sheet z = 0.75 over the offset rectangle |x| ≤ 1.25,
// |y| ≤ 0.25, whose corners (±1.25, ±0.25, 0.75) are the junctions (both faces and two
// sides); the branch points (±1, 0) (r = 1 > h) give none.
TEST(MAT25D, ShortExtrusionHasAMidSheet)
{
  const auto r = run(makeShape("rectangle").curves, extrusion(1.5));
  const std::vector<Vec3> j = junctions(r->mat);
  ASSERT_EQ(j.size(), 4u);
  for (const Vec3& p : { Vec3(1.25, 0.25, 0.75), Vec3(-1.25, 0.25, 0.75), Vec3(1.25, -0.25, 0.75),
         Vec3(-1.25, -0.25, 0.75) })
    EXPECT_TRUE(contains(j, p, 1e-12)) << p.transpose();
  EXPECT_GT(r->mat.count(MedialElementType::MidSheet), 0);
  EXPECT_NEAR(r->mat.maximumRadius(), 0.75, 1e-12);
  for (const MedialElement& e : r->mat.elements)
  {
    if (e.type != MedialElementType::MidSheet)
      continue;
    for (const auto& t : e.triangles)
      for (int id : t)
      {
        EXPECT_NEAR(r->mat.points[id].x.z(), 0.75, 1e-12);
        EXPECT_NEAR(r->mat.points[id].radius, 0.75, 1e-12);
        EXPECT_LE(std::abs(r->mat.points[id].x.x()), 1.25 + 1e-12);
        EXPECT_LE(std::abs(r->mat.points[id].x.y()), 0.25 + 1e-12);
      }
  }
  expectVerified(*r, "short box");
}

// Bars 1e6 times longer than wide and plates 1e6 times thinner (issue 9): the side
// patches are that elongated, and the exact boundary's closest points must still be found
// (they were not: the Newton step dropped the short direction, the sign tests took the
// long direction's rounding for both; 1e3 and 1e-6 gave touchpoint mismatches, 1e-6 a
// distance error of 6e-8).
TEST(MAT25D, ElongatedExtrusionsAreVerified)
{
  for (const double length : { 1e6, 1e3, 1e-3, 1e-6 })
  {
    const auto r = run(makeShape("plate-with-holes").curves, extrusion(length), MAT25DOptions{ 0.05, {} });
    expectVerified(*r, "plate with holes extruded by " + std::to_string(length));
  }
}

// The verification's touchpoint search on sides far longer or shorter than the ball (found
// when the 2D MAT's samples moved, 2026-11-25/26): a ball 0.22 across 0.22 from the end of a
// side 1e6 long (Newton in a piece 244 long, 1e6 from the origin, stopped 1e-10 short: the rounding of its coordinates),
// and a ball 5.6e-8 across in a plate 1e-6 thin, 1 from the origin (Newton's end test asked
// for 1e-9 of the ball's size, below its coordinates' rounding). Both balls touch three /
// two faces by construction (a seam point of the long bar; a sheet point between the
// bottom cap and the side of the thin plate).
TEST(MAT25D, TouchpointsOnSidesFarLongerOrShorterThanTheBall)
{
  const auto profile = Boundary2D::build(curvePieces(makeShape("plate-with-holes").curves));
  const SweepMap long1e6(profile, extrusion(1e6)), thin1e6(profile, extrusion(1e-6));
  const SweptBoundary bar(profile, long1e6);
  const Vec3 seam(1.264928133635761, 0.77748919089680724, 999999.77748919092);
  const double seamRadius = 0.22251080910319279;
  EXPECT_EQ(bar.touchpoints(seam, seamRadius * (1.0 + 2e-9) + 1e-15 * bar.size()).size(), 3u);
  const SweptBoundary plate(profile, thin1e6);
  const Vec3 sheet(-1.0031243469493012, 0.39998785344131138, 5.5555555555555555e-08);
  const double sheetRadius = 5.5555555555555555e-08;
  EXPECT_EQ(plate.touchpoints(sheet, sheetRadius * (1.0 + 2e-9) + 1e-15 * plate.size()).size(), 2u);
  // A sheet point of the same plate whose ball meets the side at a smooth junction of the
  // profile: feet 4e-12 apart either side of it, one contact (the valley between them lies
  // outside the ball by 1e-16, the rounding of the distances).
  const Vec3 junction(0.86403803132848922, -0.4999999999959599, 5.5555555555555552e-07);
  const double junctionRadius = 4.4444444444444444e-07;
  EXPECT_EQ(plate.touchpoints(junction, junctionRadius * (1.0 + 2e-9) + 1e-15 * plate.size()).size(), 2u);
  // Every point of both, at the CLI's sheet resolution.
  for (const double length : { 1e6, 1e-6 })
  {
    const auto r = run(makeShape("plate-with-holes").curves, extrusion(length), MAT25DOptions{ 0.02, {} });
    expectVerified(*r, "plate with holes extruded by " + std::to_string(length) + " at resolution 0.02");
  }
}

// Short spans on free-form profiles, extruded and revolved (2·asin(r/x) > angle), against
// the exact solid, and the brute-force junction search.
TEST(MAT25D, ShortSpansAreVerified)
{
  for (const char* name : { "l-shape", "ellipse", "plate-with-holes", "circle", "blob" })
  {
    const auto r = run(makeShape(name).curves, extrusion(0.6), MAT25DOptions{ 0.05, {} });
    EXPECT_GT(r->mat.count(MedialElementType::MidSheet), 0) << name;
    expectVerified(*r, std::string(name) + " extruded by 0.6", 3);
  }
  const auto rev = run(makeShape("rectangle").curves, revolution(40.0, Vec3(-3, 0, 0)));
  EXPECT_GT(rev->mat.count(MedialElementType::MidSheet), 0);
  expectVerified(*rev, "rectangle revolved by 40°");
  for (const auto& r : { run(makeShape("rectangle").curves, extrusion(1.5)),
         run(makeShape("l-shape").curves, extrusion(0.8)),
         run(makeShape("rectangle").curves, revolution(40.0, Vec3(-3, 0, 0))) })
  {
    const std::vector<Vec3> reported = junctions(r->mat);
    const std::vector<Vec3> brute = bruteForceJunctions(*r, 0.1);
    EXPECT_EQ(brute.size(), reported.size()) << r->sweep->describe();
    for (const Vec3& p : brute)
      EXPECT_TRUE(contains(reported, p, 1e-9)) << r->sweep->describe() << ": " << p.transpose();
  }
}

TEST(MAT25D, BadSweepsAreClearErrors)
{
  const std::vector<NurbsCurve> rect = makeShape("rectangle").curves;
  auto message = [&](const Sweep& s) {
    try
    {
      run(rect, s);
    }
    catch (const InputError& e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(revolution(90.0)).find("crosses the profile"), std::string::npos);
  EXPECT_NE(message(revolution(90.0, Vec3(-2, 0, 0))).find("touches"), std::string::npos);
  EXPECT_NE(message(revolution(90.0, Vec3(-3, 0, 0), Vec3(0, 1, 1))).find("not in the profile"),
    std::string::npos);
  EXPECT_NE(message(revolution(400.0, Vec3(-3, 0, 0))).find("(0°, 360°]"), std::string::npos);
  EXPECT_NE(message(extrusion(-1.0)).find("positive"), std::string::npos);
  EXPECT_NE(message(extrusion(NAN)).find("positive"), std::string::npos);
}

// Every 2D catalogue shape, extruded and revolved, verified against the exact solid.
class EveryProfile : public ::testing::TestWithParam<const char*>
{
};

TEST_P(EveryProfile, ExtrudedAndRevolvedAreVerified)
{
  const Shape shape = makeShape(GetParam());
  const Boundary2D profile = Boundary2D::build(curvePieces(shape.curves));
  Box3 box;
  for (const Edge2D& e : profile.edges())
    box.extend(e.curve.boundingBox());
  const Generators g(profile);
  const MedialGraph graph = computeMAT2D(g);
  const Sweep sweeps[] = { extrusion(2.5 * graph.maximumRadius()),
    revolution(120.0, Vec3(box.min().x() - 1.0, 0, 0)),
    revolution(360.0, Vec3(box.min().x() - 0.5, 0, 0), Vec3(0, -1, 0)) };
  for (const Sweep& sweep : sweeps)
  {
    const auto r = run(shape.curves, sweep, MAT25DOptions{ 0.05, {} });
    expectVerified(*r, std::string(GetParam()) + " " + r->sweep->describe(), 3);
  }
}

INSTANTIATE_TEST_SUITE_P(MAT25D, EveryProfile,
  ::testing::Values("rectangle", "rounded-rectangle", "circle", "ellipse", "annulus", "l-shape",
    "star", "blob", "spiral", "plate-with-holes", "narrow-passage"),
  [](const ::testing::TestParamInfo<const char*>& info) {
    std::string n = info.param;
    std::replace(n.begin(), n.end(), '-', '_');
    return n;
  });

#include "mat25d/SweptSolid.h"

// The swept solid's faces: exact sides, profile faces tiled by the medial strips. Closed,
// conforming (Boundary3D accepts it: every edge shared by two faces), volume = area × L
// (extrusion) or, by Pappus, angle × area × centroid distance (revolution).
TEST(MAT25D, SweptSolidIsClosedWithTheRightVolume)
{
  for (const char* name : { "rectangle", "l-shape", "ellipse", "annulus", "plate-with-holes",
         "blob", "rounded-rectangle", "star" })
  {
    const Boundary2D profile = Boundary2D::build(curvePieces(makeShape(name).curves));
    double area = 0.0;
    for (const Loop2D& l : profile.loops())
      area += l.signedArea;
    const Generators g(profile);
    const MedialGraph graph = computeMAT2D(g);
    const SweepMap extruded(profile, extrusion(2.5 * 2.0));
    const Boundary3D solid = Boundary3D::build(sweptSolidFaces(g, graph, extruded));
    EXPECT_NEAR(solid.volume(), area * 5.0, 1e-9 * area * 5.0) << name;
  }
  // The 4×2 rectangle 1..5 from the axis (centroid at 3): 90° and 360°.
  const Boundary2D rect = Boundary2D::build(curvePieces(makeShape("rectangle").curves));
  const Generators g(rect);
  const MedialGraph graph = computeMAT2D(g);
  for (const double degrees : { 90.0, 360.0 })
  {
    const SweepMap turned(rect, revolution(degrees, Vec3(-3, 0, 0)));
    const Boundary3D solid = Boundary3D::build(sweptSolidFaces(g, graph, turned));
    EXPECT_NEAR(solid.volume(), degrees * Pi / 180.0 * 8.0 * 3.0, 1e-9 * 100.0) << degrees;
  }
}

// A profile in a tilted plane, extruded along that plane's normal and revolved about an
// axis in it: the MAT is the box's / hollow cylinder's, moved rigidly.
TEST(MAT25D, TiltedProfile)
{
  Shape rect = makeShape("rectangle");
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 0.5).normalized()).toRotationMatrix();
  const Vec3 shift(3, -1, 2);
  for (NurbsCurve& c : rect.curves)
  {
    Vec4List p = c.homogeneousPoints();
    for (Vec4& h : p)
      h.head<3>() = R * h.head<3>() + h.w() * shift;
    c = NurbsCurve(c.degree(), c.knots(), p);
  }
  const auto box = run(rect.curves, extrusion(3.0));
  const Vec3 n = box->profile->plane().normal; // the extrusion direction, ±R·z
  ASSERT_NEAR(std::abs(n.dot(R * Vec3::UnitZ())), 1.0, 1e-12);
  const std::vector<Vec3> j = junctions(box->mat);
  ASSERT_EQ(j.size(), 4u);
  for (const double x : { -1.0, 1.0 })
    for (const double z : { 1.0, 2.0 })
      EXPECT_TRUE(contains(j, R * Vec3(x, 0, 0) + shift + z * n, 1e-12)) << x << " " << z;
  expectVerified(*box, "tilted box", 3);

  // Revolved about the (moved) line x = −3 of the profile plane by 90°.
  const auto ring = run(rect.curves, revolution(90.0, R * Vec3(-3, 0, 0) + shift, R * Vec3::UnitY()));
  EXPECT_EQ(junctions(ring->mat).size(), 4u);
  for (const Vec3& p : junctions(ring->mat))
  {
    // Distance to the axis is 2 or 4 (the branch points), and the ball radius is 1.
    const Vec3 rel = p - (R * Vec3(-3, 0, 0) + shift);
    const double axial = rel.dot(R * Vec3::UnitY());
    const double rho = (rel - axial * (R * Vec3::UnitY())).norm();
    EXPECT_TRUE(std::abs(rho - 2.0) < 1e-12 || std::abs(rho - 4.0) < 1e-12) << rho;
    EXPECT_NEAR(axial, 0.0, 1e-12);
  }
  expectVerified(*ring, "tilted ring", 3);
}

// The MAT of extruded and revolved solids (thesis ch. 5) against closed forms and the
// exact swept boundary.
#include "common/InputError.h"
#include "mat25d/MAT25D.h"
#include "mat25d/Verification.h"
#include "mat2d/Tracer.h"
#include "shapes/Catalogue.h"
#include "shapes/Primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace exactmat;

namespace
{
constexpr double Pi = 3.14159265358979323846;
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
  Sweep s;
  s.kind = SweepKind::Extrusion;
  s.length = length;
  return s;
}

Sweep revolution(double degrees, const Vec3& axisPoint = Vec3::Zero(),
  const Vec3& axisDirection = Vec3::UnitY())
{
  Sweep s;
  s.kind = SweepKind::Revolution;
  s.angle = degrees * Pi / 180.0;
  s.axisPoint = axisPoint;
  s.axisDirection = axisDirection;
  return s;
}

void expectVerified(const SweptMAT& r, const std::string& what, int stride = 1)
{
  const MAT25DVerification v = verifyMAT25D(*r.boundary, r.mat, stride);
  EXPECT_LE(v.maxDistanceError, VerifiedDistanceTolerance)
    << what << ": worst point " << v.worstPoint << " ("
    << (v.worstPoint >= 0 ? toString(r.mat.points[v.worstPoint].type) : "") << ")";
  EXPECT_EQ(v.contactMismatches, 0)
    << what << ": first point " << v.firstMismatch << " ("
    << (v.firstMismatch >= 0 ? toString(r.mat.points[v.firstMismatch].type) : "") << ", expected "
    << (v.firstMismatch >= 0 ? r.mat.points[v.firstMismatch].contacts : 0) << " touchpoints, has "
    << v.firstMismatchCount << ") of " << v.contactsChecked;
  EXPECT_GT(v.contactsChecked, 0) << what;
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
}

// The sheets' B-spline fits (sheets/SheetFit) against the exact sheets: the fit's own error
// at the vertices and at the exact balls between them it never saw, an independent check
// that the fitted balls are medial (distance to the exact boundary = fitted radius), and
// the Bézier patches against the B-spline they were extracted from.
#include "brep/NormalisePieces.h"
#include "common/InputError.h"
#include "mat3d/MAT3D.h"
#include "mat3d/PatchBoundary.h"
#include "shapes/Catalogue.h"
#include "shapes/Moved.h"
#include "shapes/Polyhedra.h"
#include "sheets/SheetFit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

using namespace exactmat;

namespace
{

struct Fitted
{
  std::unique_ptr<Boundary3D> boundary;
  std::vector<MedialSheetMesh> meshes;
  std::vector<SheetFit> fits;
};

Fitted fitted(const std::vector<PatchPiece>& pieces, const SheetFitOptions& options = {})
{
  Fitted f;
  f.boundary = std::make_unique<Boundary3D>(buildNormalised(pieces));
  std::vector<std::pair<int, std::string>> failures;
  f.meshes = interpolateSheets(*f.boundary, computeMAT3D(*f.boundary), {}, failures);
  EXPECT_TRUE(failures.empty());
  for (const MedialSheetMesh& mesh : f.meshes)
    if (!mesh.triangles.empty())
      f.fits.push_back(fitSheet(mesh, f.boundary->diagonal(), options));
  return f;
}

// The radius's Bézier coefficients as a patch's first coordinate.
double patchRadius(const SheetFitPatch& patch, double u, double v)
{
  Vec4List net;
  for (double r : patch.radius)
    net.emplace_back(r, 0.0, 0.0, 1.0);
  return BezierPatch(patch.centre.degreeU(), patch.centre.degreeV(), net).evaluate(u, v).x();
}

// Every fit within the tolerance at its vertices and check points; the fitted ball at every
// `stride`-th check point medial to twice the tolerance (distance is 1-Lipschitz); every
// patch equal to the B-spline on its span.
void expectFitsWithin(const Fitted& f, double tolerance, const std::string& what, int stride = 1)
{
  ASSERT_FALSE(f.fits.empty()) << what;
  const PatchBoundary exact(*f.boundary);
  const double size = f.boundary->diagonal();
  size_t m = 0, checked = 0;
  for (const SheetFit& fit : f.fits)
  {
    while (f.meshes[m].triangles.empty())
      ++m;
    const MedialSheetMesh& mesh = f.meshes[m++];
    EXPECT_TRUE(fit.withinTolerance) << what << ": error " << fit.maxError() << " with " << fit.countS << " x "
                                     << fit.countT << " control points";
    EXPECT_LE(fit.maxError(), tolerance) << what;
    EXPECT_GT(fit.checkedPoints, 0) << what;
    for (size_t i = 0; i < mesh.checkPoints.size(); i += stride, ++checked)
    {
      Vec3 x;
      double r;
      fit.evaluate(fit.parameterOf(mesh.checkPoints[i].domain), x, r);
      EXPECT_NEAR(exact.distance(x), r, 2.0 * tolerance * size) << what;
    }
    // The trimming loops: the border vertices, in order, at the fitted surface; every
    // triangle of the sheet inside them (even-odd over the loops: outer loop and holes).
    ASSERT_EQ(static_cast<int>(fit.trimLoops.size()), mesh.loops) << what;
    size_t first = 0;
    std::vector<Vec2> edgesFrom, edgesTo;
    for (const std::vector<Vec2>& loop : fit.trimLoops)
    {
      for (size_t k = 0; k < loop.size(); ++k)
      {
        EXPECT_TRUE(loop[k].minCoeff() >= -1e-12 && loop[k].maxCoeff() <= 1.0 + 1e-12) << what;
        Vec3 x;
        double r;
        fit.evaluate(loop[k], x, r);
        EXPECT_LE((x - mesh.vertices[first + k].x).norm(), (fit.vertexError + 1e-14) * size) << what;
        edgesFrom.push_back(loop[k]);
        edgesTo.push_back(loop[(k + 1) % loop.size()]);
      }
      first += loop.size();
    }
    int outside = 0;
    for (const auto& tri : mesh.triangles)
    {
      const Vec2 c = fit.parameterOf(
        (mesh.vertices[tri[0]].domain + mesh.vertices[tri[1]].domain + mesh.vertices[tri[2]].domain) / 3.0);
      bool inside = false;
      for (size_t e = 0; e < edgesFrom.size(); ++e)
      {
        const Vec2 a = edgesFrom[e], b = edgesTo[e];
        if ((a.y() > c.y()) != (b.y() > c.y()) &&
          c.x() < a.x() + (c.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
          inside = !inside;
      }
      outside += inside ? 0 : 1;
    }
    EXPECT_EQ(outside, 0) << what << ": triangles outside the trimming loops";
    ASSERT_FALSE(fit.patches.empty()) << what;
    for (const SheetFitPatch& patch : fit.patches)
      for (double u : { 0.0, 0.3, 1.0 })
        for (double v : { 0.0, 0.7, 1.0 })
        {
          Vec3 x;
          double r;
          fit.evaluate(Vec2(patch.s0 + u * (patch.s1 - patch.s0), patch.t0 + v * (patch.t1 - patch.t0)), x, r);
          EXPECT_LE((patch.centre.evaluate(u, v) - x).norm(), 1e-12 * size) << what;
          EXPECT_NEAR(patchRadius(patch, u, v), r, 1e-12 * size) << what;
        }
  }
  EXPECT_GT(checked, 0u) << what;
}

} // namespace

TEST(SheetFit, PlanarSheetsWithLinearRadiusAreFittedExactly)
{
  // A box's sheets are planes (bisectors of two faces) with the distance to a plane as
  // radius: linear in a face's parameters, so one cubic span holds them exactly.
  const Fitted f = fitted(boxPolyhedron(2.0, 1.5, 1.0));
  ASSERT_EQ(f.fits.size(), 13u);
  for (const SheetFit& fit : f.fits)
  {
    EXPECT_LE(fit.maxError(), 1e-12);
    EXPECT_EQ(fit.rounds, 1);
    EXPECT_EQ(fit.patches.size(), 1u);
  }
  expectFitsWithin(f, 1e-12, "box");
}

TEST(SheetFit, SheetsOfReflexEdgesAndCornersAreQuadraticOrCones)
{
  // A face and a reflex edge parallel to it: a parabolic cylinder; a face and a reflex
  // corner: a paraboloid — quadratic in the face's parameters (centre and radius), held
  // by one span to the rounding. A face the reflex edge ends on (the L prism's two end
  // faces; the notched cube's three faces at its reflex corner) has a cone for its sheet,
  // r = the distance to the edge's foot: no polynomial holds the apex, so the spans are
  // refined there until the tolerance is met.
  for (const auto& [name, pieces, cones] :
    { std::tuple<std::string, std::vector<PatchPiece>, size_t>{ "L prism", lPrism(1.0, 2.5), 2 },
      { "notched cube", patchPieces(makeShape("notched-cube").surfaces), 3 } })
  {
    const Fitted f = fitted(pieces);
    expectFitsWithin(f, 1e-4, name);
    size_t exact = 0;
    for (const SheetFit& fit : f.fits)
      exact += fit.maxError() <= 1e-10 && fit.patches.size() == 1 ? 1 : 0;
    EXPECT_EQ(exact, f.fits.size() - cones) << name;
  }
}

TEST(SheetFit, CurvedSheetsMeetTheTolerance)
{
  // Bicubic faces: sheets with no polynomial form, refined until every vertex and every
  // exact ball between the vertices is within the tolerance; tighter tolerances take more
  // spans.
  const std::vector<PatchPiece> pillow = patchPieces(makeShape("pillow").surfaces);
  const Fitted coarse = fitted(pillow);
  expectFitsWithin(coarse, 1e-4, "pillow", 8);
  SheetFitOptions fine;
  fine.tolerance = 1e-6;
  const Fitted tight = fitted(pillow, fine);
  expectFitsWithin(tight, 1e-6, "pillow at 1e-6", 8);
  int coarseControls = 0, tightControls = 0;
  for (const SheetFit& fit : coarse.fits)
    coarseControls += fit.countS * fit.countT;
  for (const SheetFit& fit : tight.fits)
    tightControls += fit.countS * fit.countT;
  EXPECT_GT(tightControls, coarseControls);
  expectFitsWithin(fitted(boxWithFreeFormTop(2.0, 1.5, 1.0, 0.3, 0.5)), 1e-4, "free-form top", 4);
}

TEST(SheetFit, MovedAndScaledSolidsFitAlike)
{
  // The fit works in the unit frame: a solid far from the origin, turned and scaled, gets
  // fits within the same tolerance, exact on the same (planar) sheets.
  const std::vector<PatchPiece> solid = boxWithFreeFormTop(2.0, 1.5, 1.0, 0.3, 0.5);
  const Fitted here = fitted(solid);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.47, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  const Fitted there = fitted(movedPieces(solid, turn, 1e-3, Vec3(1e2, -1e2, 1e2), 1e50));
  ASSERT_EQ(here.fits.size(), there.fits.size());
  expectFitsWithin(there, 1e-4, "free-form top, moved", 4);
  // (The triangulations differ with the turn, so the fits are not the same numbers: both
  // within the tolerance, both exact on the planar sheets.)
  size_t exactHere = 0, exactThere = 0;
  for (size_t k = 0; k < here.fits.size(); ++k)
  {
    exactHere += here.fits[k].maxError() <= 1e-9 ? 1 : 0;
    exactThere += there.fits[k].maxError() <= 1e-9 ? 1 : 0;
  }
  EXPECT_GT(exactHere, 0u);
  EXPECT_EQ(exactThere, exactHere);
}

TEST(SheetFit, DegenerateInputIsRefused)
{
  MedialSheetMesh empty;
  EXPECT_THROW(fitSheet(empty, 1.0), InputError);
  MedialSheetMesh line;
  line.vertices.resize(3);
  for (int k = 0; k < 3; ++k)
    line.vertices[k].domain = Vec2(k, 0.0);
  line.triangles.push_back({ { 0, 1, 2 } });
  EXPECT_THROW(fitSheet(line, 1.0), InputError);
}

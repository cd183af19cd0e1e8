// The medial sheets of traced solids (sheets/SheetInterpolation) against the exact
// boundary: every vertex's ball touches the boundary at its radius, inside a sheet at
// exactly two points; the sheets' touchpoints cover every face once (each boundary point
// has one maximal ball); closed forms for the box.
#include "brep/NormalisePieces.h"
#include "common/InputError.h"
#include "geometry/DomainTriangulation.h"
#include "mat25d/MAT25D.h"
#include "mat25d/SweptSolid.h"
#include "mat2d/Tracer.h"
#include "mat3d/MAT3D.h"
#include "mat3d/PatchBoundary.h"
#include "medial/Verification.h"
#include "shapes/Catalogue.h"
#include "shapes/Moved.h"
#include "shapes/Polyhedra.h"
#include "shapes/Primitives.h"
#include "EllipsoidMAT.h"
#include "shapes/RandomShapes.h"
#include "sheets/CentreCurveFootprint.h"
#include "sheets/SheetCoverage.h"
#include "sheets/SheetInterpolation.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <sstream>
#include <tuple>

using namespace exactmat;

namespace
{

struct Sheets
{
  std::unique_ptr<Boundary3D> boundary;
  MAT3D mat;
  std::vector<MedialSheetMesh> meshes;
  std::vector<std::pair<int, std::string>> failures;
};

// viaUserFrame: the seams' balls taken to the user's frame and back first, as they reach
// vtkSheetInterpolator through vtkMAT3DFilter's output (rounded to the input's position).
Sheets sheetsOf(const std::vector<PatchPiece>& pieces, const SheetOptions& options = {}, bool viaUserFrame = false)
{
  Sheets s;
  s.boundary = std::make_unique<Boundary3D>(buildNormalised(pieces));
  s.mat = computeMAT3D(*s.boundary);
  const Normalisation& frame = s.boundary->userFrame();
  if (viaUserFrame)
    for (MAT3DSeam& seam : s.mat.seams)
      for (MedialBall3D& ball : seam.balls)
      {
        ball.x = frame.toUnit(frame.toUser(ball.x));
        ball.r = frame.lengthToUnit(frame.lengthToUser(ball.r));
      }
  s.meshes = interpolateSheets(*s.boundary, s.mat, options, s.failures);
  return s;
}

// Every vertex against the exact boundary; the touchpoint footprints of the sheets on each
// face add up to the face's area within `coverage` (relative).
void expectExactSheets(const Sheets& s, const std::string& what, double coverage, int stride = 1)
{
  EXPECT_TRUE(s.failures.empty()) << what << ": " << (s.failures.empty() ? "" : s.failures.front().second);
  const PatchBoundary exact(*s.boundary);
  const double size = s.boundary->diagonal();
  int vertices = 0;
  for (const MedialSheetMesh& mesh : s.meshes)
  {
    for (const SheetVertex& v : mesh.vertices)
    {
      if (vertices++ % stride != 0)
        continue;
      EXPECT_NEAR(exact.distance(v.x), v.r, 1e-9 * size) << what << " at " << v.x.transpose();
      if (!v.border)
      {
        const double rounding = std::max(1e-15, 64.0 * s.boundary->userFrame().inputRounding());
        EXPECT_EQ(exact.touchpoints(v.x, v.r * (1.0 + 2e-9) + rounding * size).size(), 2u)
          << what << " at " << v.x.transpose();
      }
    }
    EXPECT_LE(mesh.maxDeviation, 1e-4) << what;
  }
  EXPECT_GT(vertices, 0) << what;
  const std::vector<double> footprints =
    centreCurveFootprints(*s.boundary, medialGenerators(*s.boundary), centreCurveTouches(s.mat));
  for (const FaceCoverage& c : sheetCoverage(*s.boundary, s.meshes, footprints))
    EXPECT_LE(c.shortfall(), coverage) << what << ": face " << c.face << " covered " << c.covered << " of " << c.area;
}

// The generalised winding number of the closed, outward-oriented faces at p (each face a
// fan of n × n parameter cells, two triangles each): 1 inside, 0 outside, robust away from
// the boundary.
double windingNumber(const Boundary3D& b, const Vec3& p, int n = 8)
{
  double sum = 0.0;
  for (const Face3D& face : b.faces())
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
      {
        const Vec3 c00 = face.patch.evaluate(double(i) / n, double(j) / n) - p;
        const Vec3 c10 = face.patch.evaluate(double(i + 1) / n, double(j) / n) - p;
        const Vec3 c11 = face.patch.evaluate(double(i + 1) / n, double(j + 1) / n) - p;
        const Vec3 c01 = face.patch.evaluate(double(i) / n, double(j + 1) / n) - p;
        for (const auto& [a, bb, c] : { std::tuple<Vec3, Vec3, Vec3>{ c00, c10, c11 }, { c00, c11, c01 } })
        {
          const double la = a.norm(), lb = bb.norm(), lc = c.norm();
          sum += 2.0 * std::atan2(a.dot(bb.cross(c)), la * lb * lc + a.dot(bb) * lc + a.dot(c) * lb + bb.dot(c) * la);
        }
      }
  return sum / (4.0 * M_PI);
}

// Completeness of the whole MAT as a union of balls (the check, independent of the
// face coverage): the fraction of a grid of points inside the solid (farther than 1e-3 of
// the size from its boundary) that lie in a ball of the MAT — a seam's ball, or a ball
// interpolated (centre and radius) over a sheet triangle, sampled at barycentric steps of 1/6.
double ballCoverage(const Sheets& s, int grid)
{
  const Boundary3D& b = *s.boundary;
  const PatchBoundary exact(b);
  const double size = b.diagonal();
  // (The box of points on the faces: a rational patch's control net reaches far past it —
  // an ellipsoid's arcs of 120° have their middle control point at twice the radius.)
  Box3 box;
  for (const Face3D& f : b.faces())
    for (int i = 0; i <= 8; ++i)
      for (int j = 0; j <= 8; ++j)
        box.extend(f.patch.evaluate(i / 8.0, j / 8.0));
  struct Piece
  {
    std::array<Vec3, 3> x;
    std::array<double, 3> r;
    Vec3 centre;
    double reach;
  };
  std::vector<Piece> pieces;
  auto add = [&pieces](const std::array<Vec3, 3>& x, const std::array<double, 3>& r) {
    Piece piece{ x, r, (x[0] + x[1] + x[2]) / 3.0, 0.0 };
    for (int k = 0; k < 3; ++k)
      piece.reach = std::max(piece.reach, (x[k] - piece.centre).norm() + r[k]);
    pieces.push_back(piece);
  };
  for (const MedialSheetMesh& m : s.meshes)
    for (const auto& t : m.triangles)
      add({ { m.vertices[t[0]].x, m.vertices[t[1]].x, m.vertices[t[2]].x } },
        { { m.vertices[t[0]].r, m.vertices[t[1]].r, m.vertices[t[2]].r } });
  for (const MAT3DSeam& seam : s.mat.seams)
    for (const MedialBall3D& ball : seam.balls)
      add({ { ball.x, ball.x, ball.x } }, { { ball.r, ball.r, ball.r } });
  int inside = 0, covered = 0;
  for (int i = 0; i < grid; ++i)
    for (int j = 0; j < grid; ++j)
      for (int k = 0; k < grid; ++k)
      {
        // (Offsets off the grid's symmetry: no sample exactly on a sheet of a symmetric solid.)
        const Vec3 f((i + 0.5 + 0.0137 * k) / grid, (j + 0.5 + 0.0291 * i) / grid, (k + 0.5 + 0.0173 * j) / grid);
        const Vec3 p = box.min() + f.cwiseProduct(box.max() - box.min());
        if (exact.distance(p) <= 1e-3 * size || windingNumber(b, p) < 0.5)
          continue;
        ++inside;
        bool in = false;
        for (size_t q = 0; q < pieces.size() && !in; ++q)
        {
          const Piece& piece = pieces[q];
          if ((p - piece.centre).norm() > piece.reach)
            continue;
          for (int a = 0; a <= 6 && !in; ++a)
            for (int c = 0; a + c <= 6 && !in; ++c)
            {
              const double la = a / 6.0, lc = c / 6.0, lb = 1.0 - la - lc;
              const Vec3 x = la * piece.x[0] + lb * piece.x[1] + lc * piece.x[2];
              in = (p - x).norm() <= la * piece.r[0] + lb * piece.r[1] + lc * piece.r[2];
            }
        }
        covered += in ? 1 : 0;
      }
  EXPECT_GT(inside, grid * grid * grid / 10);
  return static_cast<double>(covered) / std::max(inside, 1);
}

} // namespace

TEST(Sheets, TheBallsFillTheSolid)
{
  // Every interior point lies in a maximal ball, so the MAT's balls — the seams' and the
  // sheets', interpolated over the triangles — fill the solid (the interpolation is within
  // the tolerance of the exact balls, hence the 99.9 %).
  for (const auto& [name, pieces] :
    { std::pair<std::string, std::vector<PatchPiece>>{ "box", boxPolyhedron(2.0, 1.5, 1.0) },
      { "L prism", lPrism(1.0, 2.5) }, { "notched cube", patchPieces(makeShape("notched-cube").surfaces) },
      { "pillow", patchPieces(makeShape("pillow").surfaces) } })
  {
    const Sheets s = sheetsOf(pieces);
    EXPECT_GE(ballCoverage(s, 16), 0.999) << name;
  }
}

// The ellipsoid with semi-axes a > b > c (any order of the axes): one sheet, bounded by the
// rim alone — the region of the plane of the shortest axis inside the ellipse with
// semi-axes (a² − c²)/a, (b² − c²)/b, with r = c·√(1 − x²/(a² − c²) − y²/(b² − c²)) —
// whatever the patch layout (poles on the shortest axis, meridians cut off or on the
// equator; poles on the rim — checked by the closed form only, as MAT3D's test says), flat,
// and moved 1.5e7 × its size; its balls fill the solid.
TEST(Sheets, EllipsoidSheetIsTheClosedForm)
{
  struct Case
  {
    Vec3 semiAxes;
    double cut;
    bool moved;
    int polar = -1; ///< the poles' axis (−1: the shortest)
  };
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 offset(3e4, -6e4, 1.5e4);
  const double scale = 1e-3;
  for (const Case& c : { Case{ Vec3(2, 1.5, 1), M_PI / 6, false }, Case{ Vec3(1, 2, 1.5), 0.0, false },
         Case{ Vec3(5, 4.5, 0.5), 0.0, false }, Case{ Vec3(2, 1.5, 1), -0.3, true }, Case{ Vec3(1, 1.5, 2), 0.0, false, 2 },
         Case{ Vec3(1, 1.5, 2), 0.3, false, 1 } })
  {
    int shortest = 0;
    const double cc = c.semiAxes.minCoeff(&shortest);
    std::vector<PatchPiece> pieces = patchPieces(ellipsoidSurfaces(c.semiAxes, c.cut, c.polar < 0 ? shortest : c.polar));
    if (c.moved)
      pieces = movedPieces(pieces, turn, scale, offset, 1e20);
    std::ostringstream what;
    what << "semi-axes " << c.semiAxes.transpose() << ", cut " << c.cut << ", poles on axis "
         << (c.polar < 0 ? shortest : c.polar) << (c.moved ? ", moved" : "");
    const Sheets s = sheetsOf(pieces);
    ASSERT_EQ(s.meshes.size(), 1u) << what.str();
    const MedialSheetMesh& mesh = s.meshes.front();
    const Normalisation& frame = s.boundary->userFrame();
    const double rounding = 64.0 * frame.inputRounding();
    double worst = 0.0, area = 0.0;
    for (const SheetVertex& v : mesh.vertices)
    {
      Vec3 x = frame.toUser(v.x);
      double r = frame.lengthToUser(v.r);
      if (c.moved)
      {
        x = turn.transpose() * (x - offset) / scale;
        r /= scale;
      }
      const EllipsoidMedialOffsets off = ellipsoidMedialOffsets(c.semiAxes, x, r);
      EXPECT_LE(off.rimLevel, 1.0 + 1e-9 + rounding) << what.str() << " at " << x.transpose();
      worst = std::max({ worst, off.offPlane, off.radiusError });
    }
    EXPECT_LE(worst / c.semiAxes.maxCoeff(), 1e-9 + rounding) << what.str();
    for (const auto& t : mesh.triangles)
      area += 0.5 * (mesh.vertices[t[1]].x - mesh.vertices[t[0]].x).cross(mesh.vertices[t[2]].x - mesh.vertices[t[0]].x).norm();
    double exact = M_PI / std::pow(frame.lengthToUser(1.0) / (c.moved ? scale : 1.0), 2);
    for (int k = 0; k < 3; ++k)
      if (k != shortest)
        exact *= (c.semiAxes(k) * c.semiAxes(k) - cc * cc) / c.semiAxes(k);
    EXPECT_NEAR(area / exact, 1.0, 1e-3) << what.str();
    if (c.polar >= 0 && c.polar != shortest)
      continue;
    expectExactSheets(s, what.str(), 2e-4, 17);
    if (!c.moved && c.semiAxes.maxCoeff() < 4.0 * cc) // (a flat one leaves too few grid points inside)
    {
      EXPECT_GE(ballCoverage(s, 12), 0.999) << what.str();
    }
  }
}

// A cylinder of radius R and length 2h > 2R: two cone sheets between each cap and the
// side, r = R − ρ = h − |z| (ρ the distance from the axis), from the caps' edges (radius 0)
// to the apexes where the axis ends; the side's middle band is touched by the axis' circles
// (counted by the coverage with the centre curve's footprint). A torus has no sheet: its
// faces are covered by the core's circles alone. Moved, turned, scaled and reweighted too.
TEST(Sheets, CylinderConesAreTheClosedFormAndTheAxisCoversTheSide)
{
  const Placement far = farFromTheOrigin();
  for (const auto& [moved, length] : { std::make_pair(false, 3.0), std::make_pair(true, 5.0) })
    {
      ShapeParameters p;
      p.length = length;
      std::vector<PatchPiece> pieces = patchPieces(makeShape("cylinder", p).surfaces);
      if (moved)
        pieces = movedPieces(pieces, far);
      const std::string what = "cylinder of length " + std::to_string(length) + (moved ? ", moved" : "");
      const Sheets s = sheetsOf(pieces);
      ASSERT_EQ(s.meshes.size(), 2u) << what;
      // (Every fifth vertex against the exact boundary: the cones have 5000; all of them
      // are held to the closed form below. The caps' area is exact, π R², and the cones'
      // footprints along each cap's circle follow it, not their chords — which left 1e-4.)
      expectExactSheets(s, what, 1e-4, 5);
      const Normalisation& frame = s.boundary->userFrame();
      double worst = 0.0;
      for (const MedialSheetMesh& mesh : s.meshes)
      {
        EXPECT_GE(mesh.apex, 0) << what;
        for (const SheetVertex& v : mesh.vertices)
        {
          Vec3 x = frame.toUser(v.x);
          double r = frame.lengthToUser(v.r);
          if (moved)
          {
            x = unplaced(far, x);
            r /= far.scale;
          }
          const double rho = std::hypot(x.x(), x.y());
          worst = std::max({ worst, std::abs(r - (p.radius - rho)), std::abs(r - (0.5 * length - std::abs(x.z()))) });
        }
      }
      EXPECT_LE(worst / length, 1e-9 + 64.0 * frame.inputRounding()) << what;
    }
  const Sheets torus = sheetsOf(patchPieces(makeShape("torus").surfaces));
  EXPECT_TRUE(torus.meshes.empty());
  EXPECT_TRUE(torus.failures.empty());
  const std::vector<double> footprints =
    centreCurveFootprints(*torus.boundary, medialGenerators(*torus.boundary), centreCurveTouches(torus.mat));
  const std::vector<FaceCoverage> coverage = sheetCoverage(*torus.boundary, torus.meshes, footprints);
  EXPECT_EQ(coverage.size(), 16u);
  for (const FaceCoverage& c : coverage)
    EXPECT_LE(c.shortfall(), 1e-4) << "torus face " << c.face << " covered " << c.covered << " of " << c.area;
}

TEST(Sheets, BoxSheetsAreTheClosedForm)
{
  // Half-extents a > b > c: 13 planar sheets; the one between top and bottom is the
  // rectangle |x| ≤ a − c, |y| ≤ b − c in z = 0 with r = c.
  const double a = 2.0, b = 1.5, c = 1.0;
  const Sheets s = sheetsOf(boxPolyhedron(a, b, c));
  ASSERT_EQ(s.meshes.size(), 13u);
  expectExactSheets(s, "box", 1e-9);
  const Normalisation& frame = s.boundary->userFrame();
  int middles = 0;
  for (const MedialSheetMesh& mesh : s.meshes)
  {
    bool middle = true;
    for (const SheetVertex& v : mesh.vertices)
      middle = middle && std::abs(frame.toUser(v.x).z()) < 1e-12 && std::abs(frame.lengthToUser(v.r) - c) < 1e-12;
    if (!middle)
      continue;
    ++middles;
    EXPECT_NEAR(frame.lengthToUser(frame.lengthToUser(mesh.area())), 4.0 * (a - c) * (b - c), 1e-12);
    EXPECT_EQ(mesh.gapVertices, 0);
    EXPECT_EQ(mesh.loops, 1);
  }
  EXPECT_EQ(middles, 1);
}

TEST(Sheets, CubeAndTetrahedronCoverTheirFaces)
{
  expectExactSheets(sheetsOf(boxPolyhedron(1.0, 1.0, 1.0)), "cube", 1e-9);
  const double h = std::sqrt(2.0 / 3.0);
  const Vec3List v{ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, std::sqrt(3.0) / 2, 0),
    Vec3(0.5, std::sqrt(3.0) / 6, h) };
  expectExactSheets(sheetsOf(polyhedron(v, { { 0, 2, 1 }, { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 } })),
    "tetrahedron", 1e-9);
}

TEST(Sheets, RandomFrustumsCoverTheirFaces)
{
  std::mt19937 rng(7);
  for (int n : { 5, 8, 12 })
    expectExactSheets(sheetsOf(randomFrustum(rng, n)), "frustum " + std::to_string(n), 1e-9);
}

TEST(Sheets, PillowSheetsAreCurvedAndExact)
{
  // Bicubic faces: curved sheets between them, refined to the tolerance.
  // Every 4th vertex against the exact boundary (13,000 bicubic closest-point queries
  // take seconds; the benchmark checks them all).
  expectExactSheets(sheetsOf(patchPieces(makeShape("pillow").surfaces)), "pillow", 2e-5, 4);
}

TEST(Sheets, PatchSplitSurfacesMeetAlongThePatchBorders)
{
  // The pillow with every face cut into 3 x 3 sub-patches (the same solid, smooth edges
  // between the patches): the nine pieces of a face are one side to the sheets (each an
  // affine part of the others' polynomial extension), so the sheets are the whole pillow's,
  // covering every face.
  std::vector<PatchPiece> pieces;
  for (const PatchPiece& p : patchPieces(makeShape("pillow").surfaces))
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
      {
        PatchPiece q;
        q.patch = p.patch.subPatch(i / 3.0, (i + 1) / 3.0, j / 3.0, (j + 1) / 3.0);
        q.entity = p.entity;
        pieces.push_back(std::move(q));
      }
  const Sheets split = sheetsOf(pieces);
  expectExactSheets(split, "pillow, 3 x 3 patches a face", 2e-5, 10);
  const Sheets whole = sheetsOf(patchPieces(makeShape("pillow").surfaces));
  EXPECT_EQ(split.meshes.size(), whole.meshes.size());
  double splitArea = 0.0, wholeArea = 0.0;
  for (const MedialSheetMesh& m : split.meshes)
    splitArea += m.area();
  for (const MedialSheetMesh& m : whole.meshes)
    wholeArea += m.area();
  EXPECT_NEAR(splitArea, wholeArea, 1e-3 * wholeArea);
}

TEST(Sheets, BoxWithAFreeFormTop)
{
  expectExactSheets(sheetsOf(boxWithFreeFormTop(2.0, 1.5, 1.0, 0.3, 0.5)), "free-form top", 2e-5);
}

TEST(Sheets, ReflexEdgesAndCornersHaveCurvedSheets)
{
  // Sheets between a face and a reflex edge (parabolic cylinders); the floor's sheet with
  // the reflex edge reaches radius 0 at the edge's foot.
  expectExactSheets(sheetsOf(lPrism(1.0, 2.5)), "L prism", 1e-3);
  // The catalogue's notched cube (one eighth cut away): sheets with the reflex corner too,
  // whose borders turn where the corner's normal cone meets a face's side.
  expectExactSheets(sheetsOf(patchPieces(makeShape("notched-cube").surfaces)), "notched cube", 1e-3);
  // The stepped block: sheets between two reflex edges closing on rims at their corners
  // (a plane for their domain), and borders turning twice around the block's foot.
  expectExactSheets(sheetsOf(patchPieces(makeShape("stepped-block").surfaces)), "stepped block", 1e-3);
}

// The same sheets wherever the solid sits, however large, turned or weighted. Each case
// failed before its fix: the L prism turned (a border closed from a radius-0 corner,
// whose reflex-edge angle means nothing, guessed the wrong root), the stepped block turned
// (a seam's end ball whose reflex-edge angle sat 1e-8 past its limit was dropped, cutting
// a sliver off a face; a reflex edge paired with the plane it borders), moved 4e5 × its
// size (seam points known only to the input's rounding, 2e-11, made spikes in the domain),
// scaled by 1e-6 (two faces of one plane paired).
TEST(Sheets, MovedTurnedScaledAndReweightedSolidsHaveTheSameSheets)
{
  struct Case
  {
    std::string name;
    std::vector<PatchPiece> pieces;
    double angle, axisY, scale, offset, weights;
  };
  const std::vector<PatchPiece> lShape = lPrism(1.0, 2.5);
  const std::vector<PatchPiece> notched = patchPieces(makeShape("notched-cube").surfaces);
  const std::vector<PatchPiece> stepped = patchPieces(makeShape("stepped-block").surfaces);
  const std::vector<Case> cases{
    { "L prism turned", lShape, 0.15, 2.1, 1.0, 0.0, 1.0 },
    { "L prism moved 1e7 x its size", lShape, 0.47, 2.0, 1.0, 1e7, 1.0 },
    { "notched cube moved 4e5 x its size", notched, 27.0 * M_PI / 180.0, 2.0, 1.0, 4e5, 1.0 },
    { "notched cube moved 1e7 x its size", notched, 0.47, 2.0, 1.0, 1e7, 1.0 },
    { "stepped block turned (a)", stepped, 2.35, 4.3, 1.0, 0.0, 1.0 },
    { "stepped block turned (b)", stepped, 0.15, 2.1, 1.0, 0.0, 1.0 },
    { "stepped block moved 4e5 x its size", stepped, 27.0 * M_PI / 180.0, 2.0, 1.0, 4e5, 1.0 },
    { "stepped block scaled by 1e-6", stepped, 27.0 * M_PI / 180.0, 2.0, 1e-6, 0.0, 1.0 },
    { "stepped block, weights x 1e100", stepped, 0.47, 2.0, 1.0, 0.0, 1e100 },
  };
  for (const Case& c : cases)
  {
    const Eigen::Matrix3d rotation = Eigen::AngleAxisd(c.angle, Vec3(1.0, c.axisY, 3.0).normalized()).toRotationMatrix();
    const Vec3 offset = c.scale * c.offset * Vec3(1.0, -1.0, 1.0);
    const Sheets s = sheetsOf(movedPieces(c.pieces, rotation, c.scale, offset, c.weights), {}, true);
    expectExactSheets(s, c.name, 1e-6, 3);
  }
}

// A seam where more than three generators touch (a square tube's axis; a tower standing
// on a slab, whose seam from the base's corner junction touches two faces and two reflex
// edges) bounds only the sheets of touches next to each other around it: the sheet of a
// face and the reflex edge opposite it has no area (they are equidistant only on the seam),
// and the sheets of the touches the seam's triplet leaves out (the tower's wall) need it
// as their border.
TEST(Sheets, DegenerateSeamsAndGridStaircasesAreComplete)
{
  // Columns of unit cells, heights[i][j] high.
  auto columns = [](std::vector<std::vector<int>> heights) {
    const int n = static_cast<int>(heights.size()), top = heights[0][0];
    return voxelSolid([heights](int i, int j, int k) { return k < heights[i][j]; }, n, n, top);
  };
  const std::vector<std::pair<std::string, std::vector<PatchPiece>>> solids{
    { "tower on a slab", columns({ { 2, 1 }, { 1, 1 } }) },
    { "square prism of 2 x 2 x 5 cells", voxelSolid([](int, int, int) { return true; }, 2, 2, 5) },
    { "cube of 2 x 2 x 2 cells", voxelSolid([](int, int, int) { return true; }, 2, 2, 2) },
    // Staircases whose borders turn along sides of several coplanar cells: a tower on
    // steps (a seam where two reflex edges meet two faces), an L-shaped tower beside a
    // lower cell (a mid-plane sheet whose border turns at another cell's side), an L of
    // three cells on a 4 x 4 slab (the slab's mid-sheet turns three times around it).
    { "tower on steps", columns({ { 3, 2 }, { 2, 1 } }) },
    { "L-shaped tower beside a low cell", columns({ { 3, 3 }, { 3, 1 } }) },
    { "L of three cells on a 4 x 4 slab",
      columns({ { 2, 2, 1, 1 }, { 2, 1, 1, 1 }, { 1, 1, 1, 1 }, { 1, 1, 1, 1 } }) },
    // A 3 x 3 slab two cells thick with a tower of two cells and one low corner cell: at
    // the junctions beside the low cell the straight seam along the slab's wall and the arc
    // around the low cell's reflex corner (both between floor and ceiling) leave in one
    // direction, tangent to each other; both must be traced, and the arc bounds the sheet
    // of the floor and that corner (not of the vertical reflex edge it also touches).
    { "tower on a slab with a low corner cell", columns({ { 3, 3, 2 }, { 2, 2, 2 }, { 2, 2, 1 } }) },
  };
  for (const auto& [name, pieces] : solids)
  {
    const Sheets s = sheetsOf(pieces);
    expectExactSheets(s, name, 1e-9);
  }
}

// Random staircases (grid solids whose exact coincidences put several sides and corners at
// one point): the first fourteen are complete and exact; the sixty-second is a known gap
// (three sheets whose domains have coinciding border vertices), and must be flagged by one
// of the three checks the filter runs: a failed sheet, a vertex off the MAT, a face not
// covered.
TEST(Sheets, RandomStaircasesAreCompleteOrFlagged)
{
  std::mt19937 rng(11);
  for (int k = 0; k < 62; ++k)
  {
    const std::vector<PatchPiece> pieces = randomStaircase(rng, 2 + k % 5, 2 + k % 2);
    if (k >= 14 && k != 61)
      continue;
    const Sheets s = sheetsOf(pieces);
    const PatchBoundary exact(*s.boundary);
    int offMAT = 0;
    for (const MedialSheetMesh& mesh : s.meshes)
      for (const SheetVertex& v : mesh.vertices)
        offMAT += std::abs(exact.distance(v.x) - v.r) > 1e-9 * s.boundary->diagonal() ? 1 : 0;
    double worst = 0.0;
    for (const FaceCoverage& c : sheetCoverage(*s.boundary, s.meshes))
      worst = std::max(worst, c.shortfall());
    const bool complete = s.failures.empty() && offMAT == 0 && worst <= 1e-3;
    if (k < 14)
    {
      EXPECT_TRUE(complete) << "staircase " << k;
      expectExactSheets(s, "staircase " + std::to_string(k), 1e-3);
    }
    else
      EXPECT_FALSE(complete) << "staircase 61 is complete now: make it an exactness case";
  }
}

// A box with a cubic cavity, centred and off its centre (the seams verify: TestMAT3D).
// The sheet of an outer face and a cavity edge perpendicular to it closes around the fan of
// normals at the edge's end (a circle in the face's parameters; its chord cut into the
// corner's sheet: 8 sheets failed). The sheet of a cavity face and the outer face across
// the gap is bounded only where its touch reaches the cavity's edges: no seam draws it and
// the tracer lists no such pair; it is found on the borders of the edges' sheets, and the
// corners' sheets take their neighbours' border runs too (4 cavity faces were not covered,
// the outer faces 10% short).
TEST(Sheets, ACavitysSheetsAreComplete)
{
  for (const auto& [half, offset] : { std::pair<double, double>{ 0.2, 0.0 }, { 0.4, 0.3 } })
  {
    std::vector<PatchPiece> pieces = boxPolyhedron(2.0, 1.5, 1.0);
    for (const PatchPiece& p : movedPieces(boxPolyhedron(half, half, half), Eigen::Matrix3d::Identity(), 1.0, Vec3(offset, 0, 0)))
      pieces.push_back(p);
    expectExactSheets(sheetsOf(pieces), "cavity " + std::to_string(half) + " at x = " + std::to_string(offset), 1e-9);
  }
  // The catalogue's: its ±y walls are touched by no seam at all (the tracer lets a wall of
  // reflex edges pass), their sheets found two rounds away from the traced ones.
  expectExactSheets(sheetsOf(patchPieces(makeShape("box-with-cavity").surfaces)), "catalogue box-with-cavity", 1e-9);
}

// The catalogue's cavity turned and moved: the same 58 sheets. (1) The tracer lists pairs of
// an outer face and a cavity wall perpendicular to it whose balls all touch one line of the
// face (a sheet with no area); unturned their border lies exactly on that line and gave no
// triangles, turned the rounding made its two sides cross ("boundary loops cross": 3 sheets
// failed; far from the origin the faces were 8% short). (2) A cavity corner's sheet found
// beyond its neighbours' borders whose first run starts a rounding's width before the arc
// it follows (its loop turned straight back there and crossed itself) was left out for
// good; it is now tried again with the runs later rounds bring, and such a step is dropped.
// (3) Newton on the touch of a cavity edge from a far guess settled on θ = 0 a billion
// turns round the edge (off its arc), so the corner where the border turns from the edge's
// end onto its normal arc's end was not found and the sheet closed on itself with no area
// (a cavity wall not covered at all). The bench's transformations 0, 3, 7 and 10 (turned
// 0.05–1.05 rad, moved up to 1e6 × the size, scaled 1e±6, weights × 1e±100) failed so.
TEST(Sheets, ACavitysSheetsDoNotDependOnWhereItSits)
{
  const std::vector<PatchPiece> pieces = patchPieces(makeShape("box-with-cavity").surfaces);
  const Sheets plain = sheetsOf(pieces);
  std::vector<std::pair<Placement, std::string>> placements;
  Placement turned;
  turned.rotation = Eigen::AngleAxisd(0.7, Vec3(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  placements.emplace_back(turned, "turned");
  placements.emplace_back(farFromTheOrigin(), "far from the origin");
  const double offsets[] = { 0.0, 1e3, 1e5, 1e6 }, scales[] = { 1.0, 1e-6, 1e6 }, weights[] = { 1.0, 1e-100, 1e100 };
  for (int k : { 0, 3, 7, 10 })
  {
    Placement placed;
    placed.rotation = Eigen::AngleAxisd(0.1 * k + 0.05, Vec3(1.0, 2.0 + 0.1 * k, 3.0).normalized()).toRotationMatrix();
    placed.scale = scales[k % 3];
    placed.offset = placed.scale * offsets[k % 4] * Vec3(1.0, -1.0, 1.0);
    placed.weightFactor = weights[(k / 3) % 3];
    placements.emplace_back(placed, "the bench's transformation " + std::to_string(k));
  }
  for (const auto& [placed, name] : placements)
  {
    const Sheets s = sheetsOf(movedPieces(pieces, placed), {}, true);
    expectExactSheets(s, "box-with-cavity " + name, 1e-6);
    EXPECT_EQ(s.meshes.size(), plain.meshes.size()) << name;
  }
}

// Random boxes with a box-shaped cavity (the bench's family: its first eight and solids 13,
// 15, 32): complete and exact. Solid 7 (a small cavity ringed by a seam loop nothing leads
// to) was refused until the tracer learnt to restart from a face no seam touches.
// Solid 1's sheet of the bottom face and a cavity edge closed each of its two seams on
// itself (two slivers, the face 5% short) until a loop about to close on itself across
// the sheet learnt to reach the other seam along the edge's sides; solid 5's sheet of an
// outer wall and a cavity edge found no side of the edge's ends (the far end of each lies
// where no ball touching the wall reaches: the edge's face normal there is the wall's) and
// had no area (the wall 0.7% short). Solid 15 has a small sheet of an outer face and a
// cavity edge found only where a cavity corner's sheet reaches that edge's normal arc (5e-7
// of a face short without it). Solids 13 and 32: a seam crossing from a cavity corner onto
// the edge ending there one step before a junction gave that stretch no sheet of the edge
// (13: an open end that could not be closed, a face 0.4% short; 32: a border that closed on
// a line, "encloses no area").
// Seed 3, solid 3: another ringed cavity (refused before the restart). Seed 3, solid 30: a
// seam of two outer walls and a cavity wall whose ball, shrinking towards the walls' convex
// edge, left the cavity wall within one step: the step reached radius 0 first and the seam
// was refused ("reaches radius 0 … not a convex vertex"); now the touch's crossing is taken
// first. Seed 4, solid 11: a cavity wall no seam touched (its shell reached), half covered,
// now found by the restart. Seed 1, solid 17, and seed 4, solid 24: a junction touching a
// cavity edge 6e-4 rad short of its wall's normal started the seam leaving it on the wall
// (the trial step crossed), its first ball off the wall: the sheet of that wall and an
// outer one had no side there and closed on a diagonal (the wall 30 % short; an outer wall
// 4 % short). Now the seam runs on the edge and crosses where it does.
TEST(Sheets, RandomBoxCavitiesAreComplete)
{
  const std::vector<std::pair<unsigned, std::vector<int>>> draws{ { 1, { 0, 1, 2, 3, 4, 5, 6, 7, 13, 15, 17, 32 } },
    { 3, { 3, 30 } }, { 4, { 11, 24 } } };
  for (const auto& [seed, solids] : draws)
  {
    std::mt19937 rng(seed);
    for (int k = 0; k <= solids.back(); ++k)
    {
      const std::vector<PatchPiece> pieces = randomBoxWithCavity(rng);
      if (std::find(solids.begin(), solids.end(), k) != solids.end())
        expectExactSheets(
          sheetsOf(pieces), "random cavity " + std::to_string(k) + " of seed " + std::to_string(seed), 1e-9);
    }
  }
}

// A small cavity inside a plate's mid-sheet: the seams around it form a ring nothing leads
// to from the convex vertices. Refused ("no seam touches face 6") until the tracer learnt to
// restart from a face no seam touches: balls grown from the cavity's faces, walked to a
// face's border and round the edge there until the entity across changes (or a ball already
// touches two: a wall's middle equidistant from the plate's faces), find a seam of the ring.
// Now the seams, the ring (a closed seam, its restart point no junction) and every sheet,
// the cavity's faces covered: the cavity above the mid-plane, on it, centred (every mirror
// symmetry kept), turned about z, tilted, a tetrahedral one, two cavities.
TEST(Sheets, ASmallCavityInsideAPlatesMidSheetIsFoundByARestart)
{
  const std::vector<PatchPiece> box = boxPolyhedron(0.13, 0.16, 0.08);
  const std::vector<PatchPiece> tetrahedron = polyhedron({ Vec3(0.1, 0.1, 0.1), Vec3(0.1, -0.1, -0.1),
                                                            Vec3(-0.1, 0.1, -0.1), Vec3(-0.1, -0.1, 0.1) },
    { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } });
  auto with = [](std::vector<PatchPiece> solid, const std::vector<PatchPiece>& cavity, const Eigen::Matrix3d& turn,
                const Vec3& at) {
    int next = 0;
    for (const PatchPiece& p : solid)
      next = std::max(next, p.entity + 1);
    for (PatchPiece p : movedPieces(cavity, turn, 1.0, at))
    {
      p.entity += next;
      solid.push_back(std::move(p));
    }
    return solid;
  };
  const std::vector<PatchPiece> plate = boxPolyhedron(2.0, 1.8, 0.55);
  const Eigen::Matrix3d same = Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d aboutZ = Eigen::AngleAxisd(0.4, Vec3::UnitZ()).toRotationMatrix();
  const Eigen::Matrix3d tilted = Eigen::AngleAxisd(0.3, Vec3(1, 1, 0).normalized()).toRotationMatrix();
  const std::vector<std::pair<std::string, std::vector<PatchPiece>>> solids{
    { "above the mid-plane", with(plate, box, same, Vec3(-0.16, 0.11, 0.28)) },
    { "on the mid-plane", with(plate, box, same, Vec3(0.3, -0.2, 0.0)) },
    { "centred", with(plate, box, same, Vec3::Zero()) },
    { "turned about z", with(plate, box, aboutZ, Vec3(-0.16, 0.11, 0.05)) },
    { "tilted", with(plate, box, tilted, Vec3(0.2, 0.1, 0.05)) },
    { "a tetrahedron", with(plate, tetrahedron, same, Vec3(0.1, 0.2, 0.0)) },
    { "two", with(with(plate, box, same, Vec3(-0.9, 0.11, 0.05)), box, same, Vec3(0.8, -0.5, -0.03)) },
  };
  for (const auto& [name, pieces] : solids)
  {
    const Sheets s = sheetsOf(pieces);
    const std::vector<std::string> problems = s.mat.topologyProblems([](const Vec3& x) { return x; });
    EXPECT_TRUE(problems.empty()) << name << ": " << problems.front();
    const PatchBoundary exact(*s.boundary);
    const MedialVerification v = verifyMedialComplex(exact, s.mat.complex(), 1, 1e-15);
    EXPECT_LE(v.maxDistanceError, 1e-9) << name;
    EXPECT_EQ(v.contactMismatches, 0) << name;
    expectExactSheets(s, "a small cavity inside a plate's mid-sheet, " + name, 1e-9);
  }
}

// The same swept solid through the 2.5D construction (exact swept sheets) and through the
// 3D tracer plus the sheets: the same total sheet area and the same largest radius, and
// every face covered.
// The swept solid's sheets through the 3D path (placed: moved, turned, scaled, reweighted)
// against the 2.5D MAT's: every vertex exact, the faces covered, the same area and largest
// radius (placed alike).
void expectSweptSheetsAgree(const std::string& profileName, const Sweep& how, const Placement& placed = {})
{
  const std::string name = profileName + (how.kind == SweepKind::Extrusion ? " extruded" : " revolved") +
    (placed.offset.norm() > 0.0 ? " and moved" : "");
  const Boundary2D profile = Boundary2D::build(curvePieces(makeShape(profileName).curves));
  const Generators generators(profile);
  const MedialGraph graph = computeMAT2D(generators);
  const SweepMap sweep(profile, how);
  // (The 2.5D sheets of revolution are fans of columns `sheetResolution` apart, chords of
  // their arcs: at the default 0.02 the revolved L's area is 1.2e-3 short of the 3D path's
  // and of its own at 0.005, which agree to 1.3e-5.)
  MAT25DOptions resolution;
  resolution.sheetResolution = how.kind == SweepKind::Extrusion ? 0.02 : 0.005;
  const MedialComplex swept = computeMAT25D(generators, graph, sweep, resolution);
  double sweptArea = 0.0;
  for (const MedialElement& e : swept.elements)
    for (const auto& t : e.triangles)
      sweptArea += 0.5 * (swept.points[t[1]].x - swept.points[t[0]].x)
                           .cross(swept.points[t[2]].x - swept.points[t[0]].x)
                           .norm();
  const Sheets s = sheetsOf(movedPieces(sweptSolidFaces(generators, graph, sweep), placed));
  // (Faces covered to 1e-4: a planar face's footprints along a reflex arc of its border
  // follow the arc — their chords reached into the hole it bounds, 1.6e-4 over on the L
  // revolved 270 degrees.)
  expectExactSheets(s, name, 1e-4, 10);
  const Normalisation& frame = s.boundary->userFrame();
  double area = 0.0, largest = 0.0;
  for (const MedialSheetMesh& mesh : s.meshes)
  {
    area += frame.lengthToUser(frame.lengthToUser(mesh.area()));
    for (const SheetVertex& v : mesh.vertices)
      largest = std::max(largest, frame.lengthToUser(v.r));
  }
  const double scale = placed.scale;
  EXPECT_NEAR(area, scale * scale * sweptArea, 1e-3 * scale * scale * sweptArea) << name;
  EXPECT_NEAR(largest, scale * swept.maximumRadius(), 1e-9 * largest) << name;
}

TEST(Sheets, SweptPolygonsAgreeWithTheSweptSolidMAT)
{
  // The revolved rectangle's curved sides are cut into 14 and 23 sliver pieces where the
  // profile's MAT samples touch; pieces of one surface are one side to the sheets (until
  // 2026-11-27 each pair of pieces was a sheet of its own whose borders along the pieces'
  // sides could not be closed: 22 of 91 failed), parameterised by the surface's own
  // extension, scaled to its speeds (else the domain is stretched 20-fold and its triangles
  // are needles: 30,000 of them in one sheet, its area 0.5% too large).
  expectSweptSheetsAgree("rectangle", Sweep::extrusion(3.0));
  expectSweptSheetsAgree("l-shape", Sweep::extrusion(2.5));
  expectSweptSheetsAgree("rectangle", Sweep::revolution(90.0, Vec3(-3.0, 0.0, 0.0), Vec3::UnitY()));
}

// Revolved solids far from the origin (3e4 times their size, turned, scaled by 1e-3,
// weights by 1e20): until 2026-11-27 16 of 32 sheets of the rectangle failed ("… is not a
// piece of the surface of …": each piece was found on the first piece's extension, evaluated
// twenty sliver widths away, where the input's rounding is multiplied by hundreds). Pieces
// are now matched with their neighbours, larger on smaller, the maps composed, and a side is
// evaluated on the piece whose square holds the point.
TEST(Sheets, MovedRevolvedSolidsHaveTheSameSheets)
{
  const Placement far = farFromTheOrigin();
  expectSweptSheetsAgree("rectangle", Sweep::revolution(90.0, Vec3(-3.0, 0.0, 0.0), Vec3::UnitY()), far);
}

// A sheet's sides do not depend on where the solid is: the same faces planar, the same
// faces one side (in the L revolved 270 degrees moved far, a sliver of the fillet's cap
// piece, 1e-4 wide, was not planar: its normal from its own derivatives is tilted by the
// rounding over its width; planes now come from a wide triangle of the control net).
TEST(Sheets, MovedSweptSolidsHaveTheSameSides)
{
  const Placement far = farFromTheOrigin();
  Placement large;
  large.rotation = Eigen::AngleAxisd(2.1, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  large.scale = 1e6;
  large.offset = 1e6 * large.scale * Vec3(-0.3, 1.0, 0.8);
  large.weightFactor = 1e-50;
  for (const auto& [shape, angle] : { std::pair<std::string, double>{ "rectangle", 90.0 }, { "l-shape", 270.0 } })
  {
    const Boundary2D profile = Boundary2D::build(curvePieces(makeShape(shape).curves));
    const Generators generators(profile);
    const MedialGraph graph = computeMAT2D(generators);
    const SweepMap sweep(profile, Sweep::revolution(angle, Vec3(-3.0, 0.0, 0.0), Vec3::UnitY()));
    const std::vector<PatchPiece> faces = sweptSolidFaces(generators, graph, sweep);
    const Boundary3D home = buildNormalised(faces);
    const std::vector<Generator3D> homeGenerators = medialGenerators(home);
    for (const Placement& placed : { far, large })
    {
      const Boundary3D moved = buildNormalised(movedPieces(faces, placed));
      const std::vector<Generator3D> movedGenerators = medialGenerators(moved);
      ASSERT_EQ(movedGenerators.size(), homeGenerators.size()) << shape;
      for (int f = 0; f < static_cast<int>(home.faces().size()); ++f)
      {
        EXPECT_EQ(movedGenerators[f].planar(), homeGenerators[f].planar()) << shape << ": face " << f;
        EXPECT_EQ(sheetSide(moved, movedGenerators, f), sheetSide(home, homeGenerators, f)) << shape << ": face " << f;
      }
    }
  }
}

// Random star polygons revolved: their reflex corners become arcs. The sheet of two such
// arcs is not planar, so the plane fitted to its border (which parameterises a sheet between
// straight reflex edges) cannot carry it: it is parameterised by one arc's (t, θ), else the
// other's, else the plane (until 2026-11-27: "an open end that cannot be closed" on the
// 10-point star); and the sheet of a cap and an arc closes its border along the arc's normal
// arc end θ = α down to the vertex where the arc ends on the cap, radius 0, where every θ
// meets (the 8-point star: 3 sheets failed).
TEST(Sheets, RevolvedStarsFillTheirSheetsBetweenReflexArcs)
{
  for (const auto& [seed, points, angle] : { std::tuple<int, int, double>{ 5, 8, 45.0 }, { 6, 10, 60.0 } })
  {
    RandomEngine rng(seed);
    const RandomShape star = randomStarPolygon(rng, points);
    const Boundary2D profile = Boundary2D::build(curvePieces(star.curves));
    const Generators generators(profile);
    const MedialGraph graph = computeMAT2D(generators);
    const SweepMap sweep(profile, Sweep::revolution(angle, Vec3(-2.0, 0.0, 0.0), Vec3::UnitY()));
    const Sheets s = sheetsOf(sweptSolidFaces(generators, graph, sweep));
    expectExactSheets(s, std::to_string(points) + "-point star revolved", 2e-4, 10);
  }
}

TEST(Sheets, RevolvedLFollowsItsReflexArcs)
{
  // The revolved L's sheet of its two parallel annuli reaches the reflex edge, an arc: its
  // border follows that arc (closed by a straight line in the annulus' parameters, the
  // sheet was refused), sampled until its chords are within the tolerance; at 270° the arc
  // is three, one per quarter turn, and the border follows them one after the other; the
  // sheet of an annulus and the middle arc turns round the arc's parameter domain the way
  // that stays on the MAT (the chords of the two ways in the annulus' parameters chose the
  // wrong one). 4 of 43 sheets failed before (37 of 186 before the pieces of a surface
  // were one side).
  expectSweptSheetsAgree("l-shape", Sweep::revolution(270.0, Vec3(-3.0, 0.0, 0.0), Vec3::UnitY()));
}

// A sheet's domain whose vertices all lie on one line (two sheets meeting along a curve
// with nothing between them, offered as a sheet of its own) has no triangles; CGAL's
// one-dimensional triangulation crashed the walk over its faces before.
TEST(DomainTriangulation, ABorderOnOneLineHasNoTriangles)
{
  EXPECT_TRUE(DomainTriangulation({ { Vec2(0, 0), Vec2(1, 1), Vec2(2, 2), Vec2(3, 3) } }).triangles().empty());
  EXPECT_EQ(DomainTriangulation({ { Vec2(0, 0), Vec2(1, 0), Vec2(0, 1) } }).triangles().size(), 1u);
}

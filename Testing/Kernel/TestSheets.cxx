// The medial sheets of traced solids (sheets/SheetInterpolation) against the exact
// boundary: every vertex's ball touches the boundary at its radius, inside a sheet at
// exactly two points; the sheets' touchpoints cover every face once (each boundary point
// has one maximal ball); closed forms for the box.
#include "brep/NormalisePieces.h"
#include "mat3d/MAT3D.h"
#include "mat3d/PatchBoundary.h"
#include "shapes/Catalogue.h"
#include "shapes/Polyhedra.h"
#include "sheets/SheetInterpolation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

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

Sheets sheetsOf(const std::vector<PatchPiece>& pieces, const SheetOptions& options = {})
{
  Sheets s;
  s.boundary = std::make_unique<Boundary3D>(buildNormalised(pieces));
  s.mat = computeMAT3D(*s.boundary);
  s.meshes = interpolateSheets(*s.boundary, s.mat, options, s.failures);
  return s;
}

// A face's area from a fine grid of its patch (exact for planar faces with straight sides,
// whose grid cells are planar quadrilaterals).
double faceArea(const BezierPatch& patch, int n = 200)
{
  double sum = 0.0;
  auto at = [&](int i, int j) { return patch.evaluate(static_cast<double>(i) / n, static_cast<double>(j) / n); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
    {
      const Vec3 a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      sum += 0.5 * ((b - a).cross(c - a).norm() + (c - a).cross(d - a).norm());
    }
  return sum;
}

// Every vertex against the exact boundary; the touchpoint footprints of the sheets on each
// face add up to the face's area within `coverage` (relative).
void expectExactSheets(const Sheets& s, const std::string& what, double coverage)
{
  EXPECT_TRUE(s.failures.empty()) << what << ": " << (s.failures.empty() ? "" : s.failures.front().second);
  const PatchBoundary exact(*s.boundary);
  const double size = s.boundary->diagonal();
  std::vector<double> covered(s.boundary->faces().size(), 0.0), area(covered.size(), 0.0);
  std::vector<int> group(covered.size());
  for (size_t f = 0; f < group.size(); ++f)
    group[f] = static_cast<int>(f);
  int vertices = 0;
  for (const MedialSheetMesh& mesh : s.meshes)
  {
    ASSERT_FALSE(mesh.triangles.empty()) << what;
    for (const SheetVertex& v : mesh.vertices)
    {
      ++vertices;
      EXPECT_NEAR(exact.distance(v.x), v.r, 1e-9 * size) << what << " at " << v.x.transpose();
      if (!v.border)
      {
        EXPECT_EQ(exact.touchpoints(v.x, v.r * (1.0 + 2e-9) + 1e-15 * size).size(), 2u) << what << " at " << v.x.transpose();
      }
    }
    EXPECT_LE(mesh.maxDeviation, 1e-4) << what;
    // A side's footprint counts for all its faces (coplanar faces across smooth edges
    // are one side): compared with their summed area below, on the side's first face.
    for (int k = 0; k < 2; ++k)
    {
      const int g = mesh.generators[k];
      if (g >= static_cast<int>(covered.size()))
        continue; // a reflex edge or corner: no area
      for (int f : mesh.members[k])
        group[f] = g;
      for (const auto& t : mesh.triangles)
      {
        const Vec3& a = mesh.vertices[t[0]].touch[k];
        const Vec3& b = mesh.vertices[t[1]].touch[k];
        const Vec3& c = mesh.vertices[t[2]].touch[k];
        covered[g] += 0.5 * (b - a).cross(c - a).norm();
      }
    }
  }
  EXPECT_GT(vertices, 0) << what;
  for (size_t f = 0; f < covered.size(); ++f)
    area[group[f]] += faceArea(s.boundary->faces()[f].patch);
  for (size_t f = 0; f < covered.size(); ++f)
  {
    if (area[f] > 0.0)
    {
      EXPECT_NEAR(covered[f], area[f], coverage * area[f]) << what << ": face " << f;
    }
  }
}

} // namespace

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
  expectExactSheets(sheetsOf(patchPieces(makeShape("pillow").surfaces)), "pillow", 1e-3);
}

TEST(Sheets, BoxWithAFreeFormTop)
{
  expectExactSheets(sheetsOf(boxWithFreeFormTop(2.0, 1.5, 1.0, 0.3, 0.5)), "free-form top", 1e-3);
}

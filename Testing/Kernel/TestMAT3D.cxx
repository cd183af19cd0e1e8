// The seams and junctions of solids bounded by free-form faces (thesis ch. 6) against closed
// forms, an independent brute-force junction search, and the exact boundary.
#include "brep/NormalisePieces.h"
#include "geometry/ClosestPoint.h"
#include "common/InputError.h"
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
#include "sheets/SheetCoverage.h"
#include "sheets/CentreCurveFootprint.h"

#include <gtest/gtest.h>

#include <set>

#include <cmath>
#include <map>
#include <random>
#include <sstream>

using namespace exactmat;

namespace
{
constexpr double VerifiedDistanceTolerance = 1e-9;

// The MAT in the normalised frame (as the filter computes it) and the map to the user's.
struct Traced
{
  std::unique_ptr<Boundary3D> boundary;
  MAT3D mat;

  struct Ball
  {
    Vec3 x;
    double r;
    int touchpoints;
  };
  // The junctions in the user's frame.
  std::vector<Ball> junctions() const
  {
    std::vector<Ball> out;
    const Normalisation& n = boundary->userFrame();
    for (const MAT3DNode& node : mat.nodes)
      if (node.vertex < 0 && !node.seamEnd)
        out.push_back({ n.toUser(node.ball.x), n.lengthToUser(node.ball.r), node.touchpoints });
    return out;
  }
};

Traced trace(const std::vector<PatchPiece>& pieces, const MAT3DOptions& options = {})
{
  Traced t;
  t.boundary = std::make_unique<Boundary3D>(buildNormalised(pieces));
  t.mat = computeMAT3D(*t.boundary, options);
  return t;
}

void expectClosedSheets(const Traced& t, const std::string& what);
std::vector<std::string> topologyProblems(const Traced& t);

// Every point checked against the exact boundary (distance = radius, touchpoint count);
// every seam joins two nodes; one connected graph.
void expectPointsVerified(const Traced& t, const std::string& what, bool closedSheets = true)
{
  const PatchBoundary boundary(*t.boundary);
  const MedialComplex c = t.mat.complex();
  const MedialVerification v =
    verifyMedialComplex(boundary, c, 1, std::max(1e-15, 64.0 * t.boundary->userFrame().inputRounding()));
  EXPECT_LE(v.maxDistanceError, VerifiedDistanceTolerance) << what;
  EXPECT_EQ(v.contactMismatches, 0) << what << ": "
                                    << v.problems(VerifiedDistanceTolerance, c, [](const Vec3& x) { return x; });
  EXPECT_GT(v.contactsChecked, 0) << what;
  EXPECT_EQ(v.osculationMismatches, 0) << what;
  std::vector<int> parent(t.mat.nodes.size());
  for (size_t i = 0; i < parent.size(); ++i)
    parent[i] = static_cast<int>(i);
  std::function<int(int)> root = [&](int i) { return parent[i] == i ? i : parent[i] = root(parent[i]); };
  for (const MAT3DSeam& s : t.mat.seams)
  {
    ASSERT_GE(s.startNode, 0) << what;
    ASSERT_GE(s.endNode, 0) << what;
    parent[root(s.startNode)] = root(s.endNode);
  }
  for (const MAT3DSkeletalEdge& s : t.mat.skeletalEdges)
    parent[root(s.startNode)] = root(s.endNode);
  int components = 0;
  for (size_t i = 0; i < parent.size(); ++i)
    components += root(static_cast<int>(i)) == static_cast<int>(i);
  EXPECT_EQ(components, 1) << what;
  if (closedSheets)
    expectClosedSheets(t, what);
}

// The seam graph's own check: every junction of four touchpoints meets four seams, every
// seam end on a rim one seam and one rim.
std::vector<std::string> topologyProblems(const Traced& t)
{
  return t.mat.topologyProblems([&t](const Vec3& x) { return t.boundary->userFrame().toUser(x); });
}

// The points verified and the seam graph consistent.
void expectVerified(const Traced& t, const std::string& what, bool closedSheets = true)
{
  expectPointsVerified(t, what, closedSheets);
  const std::vector<std::string> problems = topologyProblems(t);
  EXPECT_TRUE(problems.empty()) << what << ": " << (problems.empty() ? "" : problems.front());
}

// Every sheet's border (its seams and convex edges) is closed: each node on it is met an even
// number of times. Holds where no smooth edge splits a sheet between faces.
void expectClosedSheets(const Traced& t, const std::string& what)
{
  if (t.boundary->countEdges(VertexKind::Smooth) > 0)
    return;
  ASSERT_FALSE(t.mat.sheets.empty()) << what;
  std::vector<int> nodeOfVertex(t.boundary->vertices().size(), -1);
  for (size_t n = 0; n < t.mat.nodes.size(); ++n)
    if (t.mat.nodes[n].vertex >= 0)
      nodeOfVertex[t.mat.nodes[n].vertex] = static_cast<int>(n);
  std::vector<int> sheetsOfSeam(t.mat.seams.size(), 0);
  for (const MAT3DSheet& sheet : t.mat.sheets)
  {
    std::map<int, int> degree;
    for (int s : sheet.seams)
    {
      ++degree[t.mat.seams[s].startNode];
      ++degree[t.mat.seams[s].endNode];
      ++sheetsOfSeam[s];
    }
    for (int e : sheet.convexEdges)
    {
      ++degree[nodeOfVertex[t.boundary->edges()[e].startVertex]];
      ++degree[nodeOfVertex[t.boundary->edges()[e].endVertex]];
    }
    for (const auto& [node, d] : degree)
      EXPECT_EQ(d % 2, 0) << what << ": sheet of faces " << sheet.generatorA << ", " << sheet.generatorB << " at node " << node;
  }
  for (size_t s = 0; s < sheetsOfSeam.size(); ++s)
    EXPECT_EQ(sheetsOfSeam[s], 3) << what << ": seam " << s; // one sheet per pair of its triplet
}

std::vector<int> degrees(const MAT3D& m)
{
  std::vector<int> d(m.nodes.size(), 0);
  for (const MAT3DSeam& s : m.seams)
  {
    ++d[s.startNode];
    ++d[s.endNode];
  }
  return d;
}

// Brute force, independent of the tracer: every four faces of a convex polyhedron give a
// linear system n_i·X − r = n_i·P_i (inward unit normals); a solution with r > 0 whose
// ball is empty (no face plane cuts it, and global distance = r) is a junction.
Vec3List bruteForceJunctions(const Boundary3D& b, std::vector<double>* radii)
{
  const PatchBoundary boundary(b);
  const int n = static_cast<int>(b.faces().size());
  std::vector<Vec3> normal(n), point(n);
  for (int f = 0; f < n; ++f)
  {
    normal[f] = -b.faces()[f].patch.normal(0.5, 0.5);
    point[f] = b.faces()[f].patch.evaluate(0.5, 0.5);
  }
  Vec3List found;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k)
        for (int l = k + 1; l < n; ++l)
        {
          Eigen::Matrix4d a;
          Eigen::Vector4d rhs;
          const int f[4] = { i, j, k, l };
          for (int m = 0; m < 4; ++m)
          {
            a.row(m) << normal[f[m]].transpose(), -1.0;
            rhs(m) = normal[f[m]].dot(point[f[m]]);
          }
          // Faces of one plane (a cap split into triangles) give no junction together.
          Eigen::FullPivLU<Eigen::Matrix4d> lu(a);
          lu.setThreshold(1e-9);
          if (lu.rank() < 4)
            continue;
          const Eigen::Vector4d s = lu.solve(rhs);
          const Vec3 x = s.head<3>();
          const double r = s(3);
          if (!(r > 1e-9 * b.diagonal()))
            continue;
          // Convex solid: the ball is empty only if no face plane cuts it (cheap, first).
          bool clear = true;
          for (int m = 0; m < n && clear; ++m)
            clear = normal[m].dot(x - point[m]) >= r - 1e-9 * b.diagonal();
          if (!clear || std::abs(boundary.distance(x) - r) > 1e-9 * b.diagonal())
            continue;
          // Every one of the four faces must really touch (its foot inside the face).
          bool ok = true;
          for (int m = 0; m < 4; ++m)
            ok = ok && std::abs((closestPoint(b.faces()[f[m]].patch, x).distance) - r) <= 1e-9 * b.diagonal();
          bool known = false;
          for (const Vec3& y : found)
            known = known || (y - x).norm() < 1e-7 * b.diagonal();
          if (ok && !known)
          {
            found.push_back(x);
            if (radii)
              radii->push_back(r);
          }
        }
  return found;
}

void expectJunctionsMatchBruteForce(const Traced& t, const std::string& what)
{
  const Vec3List expected = bruteForceJunctions(*t.boundary, nullptr);
  EXPECT_EQ(t.mat.junctionCount(), static_cast<int>(expected.size())) << what;
  for (const Vec3& x : expected)
  {
    double nearest = INFINITY;
    for (const MAT3DNode& n : t.mat.nodes)
      if (n.vertex < 0)
        nearest = std::min(nearest, (n.ball.x - x).norm()); // both in the unit frame
    EXPECT_LE(nearest, 1e-9 * t.boundary->diagonal()) << what << ": junction at " << x.transpose();
  }
}
} // namespace

TEST(MAT3D, BoxJunctionsAndSeamsAreTheClosedForm)
{
  // Half-extents a > b > c: junctions (±(a−c), ±(b−c), 0) with r = c, four faces each;
  // 8 seams from the corners and 4 between the junctions.
  const double a = 2.0, b = 1.5, c = 1.0;
  const Traced t = trace(boxPolyhedron(a, b, c));
  EXPECT_EQ(t.mat.junctionCount(), 4);
  EXPECT_EQ(t.mat.seams.size(), 12u);
  const std::vector<int> d = degrees(t.mat);
  for (size_t i = 0; i < t.mat.nodes.size(); ++i)
    EXPECT_EQ(d[i], t.mat.nodes[i].vertex >= 0 ? 1 : 4);
  for (const Traced::Ball& j : t.junctions())
  {
    EXPECT_NEAR(std::abs(j.x.x()), a - c, 1e-12);
    EXPECT_NEAR(std::abs(j.x.y()), b - c, 1e-12);
    EXPECT_NEAR(j.x.z(), 0.0, 1e-12);
    EXPECT_NEAR(j.r, c, 1e-12);
    EXPECT_EQ(j.touchpoints, 4);
  }
  expectVerified(t, "box");
  expectJunctionsMatchBruteForce(t, "box");
  // 13 sheets: one per pair of adjacent faces, bounded by their convex edge and two seams
  // through a junction (the 4 vertical edges) or three (the 8 others: two corner seams and
  // one between junctions), and the middle one between top and bottom (the four seams
  // between the junctions, no edge).
  ASSERT_EQ(t.mat.sheets.size(), 13u);
  std::map<std::pair<size_t, size_t>, int> kinds; // (seams, convex edges) → sheets
  for (const MAT3DSheet& sheet : t.mat.sheets)
    ++kinds[{ sheet.seams.size(), sheet.convexEdges.size() }];
  auto count = [&kinds](size_t seams, size_t edges) { return kinds[{ seams, edges }]; };
  EXPECT_EQ(count(2, 1), 4);
  EXPECT_EQ(count(3, 1), 8);
  EXPECT_EQ(count(4, 0), 1);
}

TEST(MAT3D, CatalogueBoxAgrees)
{
  const Traced t = trace(patchPieces(makeShape("box").surfaces));
  EXPECT_EQ(t.mat.junctionCount(), 4);
  EXPECT_EQ(t.mat.seams.size(), 12u);
  expectVerified(t, "catalogue box");
}

TEST(MAT3D, CubeHasOneDegenerateJunction)
{
  // All six faces touch the ball at the centre: one junction, eight seams into it.
  const Traced t = trace(boxPolyhedron(1.0, 1.0, 1.0));
  ASSERT_EQ(t.mat.junctionCount(), 1);
  EXPECT_EQ(t.mat.seams.size(), 8u);
  const Traced::Ball j = t.junctions()[0];
  EXPECT_LE(j.x.norm(), 1e-12);
  EXPECT_NEAR(j.r, 1.0, 1e-12);
  EXPECT_EQ(j.touchpoints, 6);
  expectVerified(t, "cube");
}

TEST(MAT3D, RegularTetrahedronMeetsAtTheIncentre)
{
  const Vec3List v{ Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1) };
  const Traced t = trace(polyhedron(v, { { 0, 1, 2 }, { 0, 3, 1 }, { 0, 2, 3 }, { 1, 3, 2 } }));
  ASSERT_EQ(t.mat.junctionCount(), 1);
  EXPECT_EQ(t.mat.seams.size(), 4u);
  const double edge = (v[0] - v[1]).norm();
  const Traced::Ball j = t.junctions()[0];
  EXPECT_LE(j.x.norm(), 1e-12);
  EXPECT_NEAR(j.r, edge / (2.0 * std::sqrt(6.0)), 1e-12);
  EXPECT_EQ(j.touchpoints, 4);
  expectVerified(t, "tetrahedron");
}

TEST(MAT3D, RandomFrustumsAgreeWithBruteForce)
{
  // Truncated pyramids over random convex polygons (the caps split into coplanar fans: seams
  // cross their flat edges): the junctions of a brute-force search over every four faces,
  // every point verified, one connected graph, junctions of degree 4 (or more when
  // degenerate), corners of degree 1.
  std::mt19937 rng(7);
  for (int k = 0; k < 12; ++k)
  {
    const int n = 3 + k % 6;
    const std::vector<PatchPiece> pieces = randomFrustum(rng, n);
    const std::string what = "frustum " + std::to_string(k) + " (" + std::to_string(n) + " sides)";
    Traced t;
    try
    {
      t = trace(pieces);
    }
    catch (const InputError& e)
    {
      ADD_FAILURE() << what << ": " << e.what();
      continue;
    }
    expectVerified(t, what);
    expectJunctionsMatchBruteForce(t, what);
    const std::vector<int> d = degrees(t.mat);
    for (size_t i = 0; i < t.mat.nodes.size(); ++i)
      EXPECT_EQ(d[i], t.mat.nodes[i].vertex >= 0 ? 1 : 4) << what << ", node " << i;
  }
}

TEST(MAT3D, PillowHasCurvedSeamsIntoTheCentre)
{
  // A cube with bicubic faces bulging outwards: by symmetry the eight seams from the corners
  // meet at the centre, where all six faces touch.
  const Traced t = trace(patchPieces(makeShape("pillow").surfaces));
  ASSERT_EQ(t.mat.junctionCount(), 1);
  EXPECT_EQ(t.mat.seams.size(), 8u);
  expectVerified(t, "pillow");
}

TEST(MAT3D, BoxWithAFreeFormTop)
{
  // A 4 × 3 × 2 box whose top is a tilted bicubic bulge (outwards, then inwards): curved
  // seams, four junctions that are no longer symmetric, every point verified.
  for (const double bulge : { 0.3, -1.2 })
  {
    const Traced t = trace(boxWithFreeFormTop(2.0, 1.5, 1.0, bulge, 0.5));
    const std::string what = "bulge " + std::to_string(bulge);
    EXPECT_EQ(t.mat.junctionCount(), 4) << what;
    EXPECT_EQ(t.mat.seams.size(), 12u) << what;
    for (const Traced::Ball& j : t.junctions())
      EXPECT_EQ(j.touchpoints, 4) << what;
    expectVerified(t, what);
  }
  // A bulge so tilted that the top's ridge is a rim of the MAT, which meets a seam (a fin
  // point, where the top touches one ball twice): not traced yet, and said so.
  try
  {
    trace(boxWithFreeFormTop(2.0, 1.5, 1.0, 1.5, 0.9));
    ADD_FAILURE() << "no error";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("Rims that meet seams are not traced yet"), std::string::npos) << e.what();
  }
}

TEST(MAT3D, UnsupportedSolidsAreRefusedByName)
{
  auto message = [](const std::vector<PatchPiece>& pieces) {
    try
    {
      trace(pieces);
    }
    catch (const InputError& e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // A hollow ball (a spherical cavity inside a sphere, every point an umbilic: its MAT is
  // the sphere midway, one sheet, no seam): no rim, no vertex, no circle of contact, and
  // not a ball (ABallsMATIsItsCentre).
  std::vector<PatchPiece> hollow = patchPieces(ellipsoidSurfaces(Vec3(2, 2, 2), M_PI / 6, 2));
  for (const PatchPiece& p : patchPieces(ellipsoidSurfaces(Vec3(1, 1, 1), 0.3, 1)))
    hollow.push_back(p);
  EXPECT_NE(message(hollow).find("no convex vertex, no rim and no circle of contact"), std::string::npos)
    << message(hollow);
}

// A cylinder of radius R shorter than its diameter (length 2h < 2R): its MAT is the disk
// |ρ| ≤ R − h of its mid-plane (balls touching both caps) bounded by a circular seam of
// balls of radius h touching both caps and the side, which no vertex leads to — a restart
// from a face no seam touches finds it. Unmoved and far from the origin (turned, scaled,
// reweighted): one closed seam, ρ = R − h, z = 0, r = h, every point verified.
TEST(MAT3D, ShortCylinderIsADiskBoundedByACircularSeam)
{
  const Placement far = farFromTheOrigin();
  for (const double length : { 1.5, 0.4 })
    for (const bool moved : { false, true })
    {
      ShapeParameters p;
      p.length = length;
      std::vector<PatchPiece> pieces = patchPieces(makeShape("cylinder", p).surfaces);
      if (moved)
        pieces = movedPieces(pieces, far);
      const std::string what = "cylinder of length " + std::to_string(length) + (moved ? ", moved" : "");
      const Traced t = trace(pieces);
      ASSERT_EQ(t.mat.seams.size(), 1u) << what;
      EXPECT_EQ(t.mat.junctionCount(), 0) << what;
      const MAT3DSeam& seam = t.mat.seams.front();
      EXPECT_EQ(seam.startNode, seam.endNode) << what << ": a closed seam";
      const Normalisation& frame = t.boundary->userFrame();
      const double h = 0.5 * length, tolerance = (1e-9 + 64.0 * frame.inputRounding()) * p.radius;
      double worst = 0.0, turned = 0.0;
      Vec3 previous = Vec3::Zero();
      for (size_t i = 0; i < seam.balls.size(); ++i)
      {
        Vec3 x = frame.toUser(seam.balls[i].x);
        double r = frame.lengthToUser(seam.balls[i].r);
        if (moved)
        {
          x = unplaced(far, x);
          r /= far.scale;
        }
        worst = std::max({ worst, std::abs(std::hypot(x.x(), x.y()) - (p.radius - h)), std::abs(x.z()),
          std::abs(r - h) });
        if (i > 0)
          turned += std::atan2(previous.x() * x.y() - previous.y() * x.x(), previous.x() * x.x() + previous.y() * x.y());
        previous = x;
      }
      EXPECT_LE(worst, tolerance) << what;
      EXPECT_NEAR(std::abs(turned), 2.0 * M_PI, 1e-9) << what << ": once round";
      expectPointsVerified(t, what);
    }
}

// The ellipsoid with semi-axes a > b > c (any order of the axes): no seam, one closed rim,
// the ellipse in the plane of the shortest axis with semi-axes (a² − c²)/a and (b² − c²)/b,
// r = c·√(1 − x²/(a² − c²) − y²/(b² − c²)) (issue 10's closed form); every rim ball touches
// once and osculates. Patch layouts: poles on the shortest axis with the meridians cut off
// the equator, below it, or on it (the rim's touch then runs along the patches' common
// side); poles on the longest or middle axis (the rim passes through them: stepped over;
// next to a pole an osculating ball's touch can stop the verification's footpoint search
// at its box limit, and the ball is verified by witness: its recorded touch on the
// boundary at the radius, the ball shrunk by the tolerance empty); x, y or z shortest;
// flat ones; moved, turned, scaled and reweighted.
TEST(MAT3D, EllipsoidIsOneRimInClosedForm)
{
  struct Case
  {
    Vec3 semiAxes;
    double cut;
    int polar;
    bool moved;
  };
  const std::vector<Case> cases{ { Vec3(2, 1.5, 1), M_PI / 6, 2, false }, { Vec3(2, 1.5, 1), 0.0, 2, false },
    { Vec3(2, 1.5, 1), -0.35, 2, false }, { Vec3(1, 2, 1.5), M_PI / 6, 0, false }, { Vec3(1.5, 1, 2), 0.2, 1, false },
    { Vec3(5, 4.5, 0.5), 0.0, 2, false }, { Vec3(1, 1.5, 2), 0.0, 2, false }, { Vec3(1, 1.5, 2), 0.3, 1, false },
    { Vec3(2, 1.5, 1), 0.5, 0, false }, { Vec3(1, 2, 1.5), 0.0, 0, true } };
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 offset(3e4, -6e4, 1.5e4);
  const double scale = 1e-3;
  for (const Case& c : cases)
  {
    std::vector<PatchPiece> pieces = patchPieces(ellipsoidSurfaces(c.semiAxes, c.cut, c.polar));
    if (c.moved)
      pieces = movedPieces(pieces, turn, scale, offset, 1e20);
    std::ostringstream what;
    what << "semi-axes " << c.semiAxes.transpose() << ", cut " << c.cut << ", poles on axis " << c.polar
         << (c.moved ? ", moved" : "");
    const Traced t = trace(pieces);
    ASSERT_EQ(t.mat.seams.size(), 0u) << what.str();
    ASSERT_EQ(t.mat.skeletalEdges.size(), 1u) << what.str();
    EXPECT_EQ(t.mat.junctionCount(), 0) << what.str();
    const MAT3DSkeletalEdge& rim = t.mat.skeletalEdges.front();
    EXPECT_EQ(rim.startNode, rim.endNode) << what.str();
    int shortest = 0;
    c.semiAxes.minCoeff(&shortest);
    const Normalisation& frame = t.boundary->userFrame();
    double worst = 0.0, longest = 0.0;
    for (size_t i = 0; i < rim.balls.size(); ++i)
    {
      Vec3 x = frame.toUser(rim.balls[i].x);
      double r = frame.lengthToUser(rim.balls[i].r);
      if (c.moved)
      {
        x = turn.transpose() * (x - offset) / scale;
        r /= scale;
      }
      const EllipsoidMedialOffsets off = ellipsoidMedialOffsets(c.semiAxes, x, r);
      worst = std::max({ worst, off.offPlane, std::abs(std::sqrt(off.rimLevel) - 1.0) * c.semiAxes.maxCoeff(),
        off.radiusError });
      if (i > 0)
        longest = std::max(longest, (rim.balls[i].x - rim.balls[i - 1].x).norm() / t.boundary->diagonal());
    }
    // (Moved 1.5e7 × its size away, the input itself is rounded at 1.5e-9 of the size.)
    EXPECT_LE(worst / c.semiAxes.maxCoeff(), 1e-9 + 64.0 * frame.inputRounding()) << what.str();
    EXPECT_LE(longest, MAT3DOptions().maxStep * (1 + 1e-9)) << what.str();
    // (Verified once here: a ball osculating a face takes the footpoint search milliseconds.)
    EXPECT_TRUE(topologyProblems(t).empty()) << what.str();
    const PatchBoundary boundary(*t.boundary);
    const MedialVerification v =
      verifyMedialComplex(boundary, t.mat.complex(), 1, std::max(1e-15, 64.0 * frame.inputRounding()));
    EXPECT_LE(v.maxDistanceError, VerifiedDistanceTolerance) << what.str();
    EXPECT_EQ(v.contactMismatches, 0) << what.str();
    EXPECT_EQ(v.contactsChecked, static_cast<int>(rim.balls.size()) - 1) << what.str();
    EXPECT_EQ(v.osculationsChecked, static_cast<int>(rim.balls.size()) - 1) << what.str();
    EXPECT_EQ(v.osculationMismatches, 0) << what.str();
    // (Next to a pole the contact is known less well across the ridge than the bound the
    // verification allows for rounding says: 1.05e-6 there. Elsewhere it is at rounding.)
    if (!c.moved && c.polar == shortest)
    {
      EXPECT_LE(v.maxOsculationError, MedialVerification::OsculationTolerance) << what.str();
    }
  }
}

// A ball: no convex vertex, no rim (every point is umbilic), no circle of contact — its MAT
// is its centre alone, radius R, one ball touching every face. Found however the sphere is
// cut into patches and wherever it sits (turned, scaled 1e-3 … 1e4, moved far, weights
// × 1e-50 … 1e20); the centre's distance verified, its ball covering every face. Not a ball
// when one control point moves by 1e-7 of the size (nor an oblate spheroid 1e-3 off).
TEST(MAT3D, ABallsMATIsItsCentre)
{
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  struct Case
  {
    double cut;
    int polar;
    Placement placed;
  };
  std::vector<Case> cases{ { M_PI / 6, 2, {} }, { 0.0, 0, {} }, { -0.35, 1, {} } };
  cases.push_back({ 0.2, 2, farFromTheOrigin() });
  cases.push_back({ 0.0, 1, { turn, 1e4, Vec3(-3e8, 1e8, 2e7), 1e-50 } });
  for (const Case& c : cases)
  {
    std::ostringstream what;
    what << "cut " << c.cut << ", poles on axis " << c.polar << ", scale " << c.placed.scale;
    const Traced t = trace(movedPieces(patchPieces(ellipsoidSurfaces(Vec3(1.5, 1.5, 1.5), c.cut, c.polar)), c.placed));
    ASSERT_EQ(t.mat.nodes.size(), 1u) << what.str();
    EXPECT_TRUE(t.mat.nodes.front().sphereCentre) << what.str();
    EXPECT_TRUE(t.mat.seams.empty() && t.mat.skeletalEdges.empty() && t.mat.centreCurves.empty()) << what.str();
    EXPECT_EQ(t.mat.junctionCount(), 0) << what.str();
    const Normalisation& frame = t.boundary->userFrame();
    const Vec3 centre = unplaced(c.placed, frame.toUser(t.mat.nodes.front().ball.x));
    const double radius = frame.lengthToUser(t.mat.nodes.front().ball.r) / c.placed.scale;
    EXPECT_LE(centre.norm(), 1e-12 * 3.0 + 64.0 * frame.inputRounding() * 3.0) << what.str();
    EXPECT_NEAR(radius, 1.5, 1e-12 + 64.0 * frame.inputRounding() * 3.0) << what.str();
    const MedialComplex complex = t.mat.complex();
    // (Its ball touches a continuum: the distance is checked, no count of touchpoints.)
    const MedialVerification v = verifyMedialComplex(PatchBoundary(*t.boundary), complex, 1,
      std::max(1e-15, 64.0 * frame.inputRounding()));
    EXPECT_EQ(v.points, 1) << what.str();
    EXPECT_LE(v.maxDistanceError, VerifiedDistanceTolerance) << what.str();
    EXPECT_TRUE(v.ok(VerifiedDistanceTolerance)) << what.str();
    EXPECT_TRUE(topologyProblems(t).empty()) << what.str();
    ASSERT_EQ(complex.points.size(), 1u);
    EXPECT_EQ(complex.points.front().type, MedialPoint3DType::SphereCentre);
    ASSERT_EQ(complex.elements.size(), 1u);
    EXPECT_EQ(complex.elements.front().type, MedialElementType::SphereCentre);
    EXPECT_EQ(complex.elements.front().governors.size(), t.boundary->faces().size());
    // The coverage check's own test: the centre's ball covers every face, wholly.
    const std::vector<double> covered = sphericalFaceFootprints(*t.boundary, complex, 1e-9 * t.boundary->diagonal());
    for (const FaceCoverage& f : sheetCoverage(*t.boundary, {}, covered))
      EXPECT_LE(f.shortfall(), 1e-12) << what.str() << ": face " << f.face;
    // …and not a ball that is smaller, or off centre.
    MedialComplex off = complex;
    off.points.front().radius *= 1.0 + 1e-8;
    for (double a : sphericalFaceFootprints(*t.boundary, off, 1e-9 * t.boundary->diagonal()))
      EXPECT_EQ(a, 0.0) << what.str();
  }
  // One inner control point of one patch moved outwards by 1e-7 of the size: not a ball.
  std::vector<PatchPiece> dented = patchPieces(ellipsoidSurfaces(Vec3(1.5, 1.5, 1.5), 0.0, 2));
  {
    Vec4List net = dented.front().patch.homogeneousNet();
    Vec4& p = net[1 * (dented.front().patch.degreeV() + 1) + 1];
    p.head<3>() += 1e-7 * 5.2 * p.w() * p.head<3>().normalized();
    dented.front().patch = BezierPatch(dented.front().patch.degreeU(), dented.front().patch.degreeV(), net);
  }
  for (const std::vector<PatchPiece>& notABall :
    { dented, patchPieces(ellipsoidSurfaces(Vec3(1.5, 1.5, 1.4985), 0.0, 2)) })
  {
    try
    {
      const Traced t = trace(notABall);
      for (const MAT3DNode& n : t.mat.nodes)
        EXPECT_FALSE(n.sphereCentre);
    }
    catch (const InputError&)
    {
    }
  }
}

// A capsule (a cylinder of radius 1 and length L capped by two hemispheres, the profile
// revolved): its MAT is the axis segment between the hemispheres' centres, radius 1, a
// centre curve whose end balls touch a whole hemisphere each. The ends are those centres
// exactly (they were 7e-8 of the size past them: the touch crossed onto the hemisphere was
// bisected to within 1e-8 of the side, on the cylinder's extension), and the coverage
// counts each hemisphere as the end ball's (sphericalFaceFootprints). Unmoved and far from
// the origin.
TEST(MAT3D, ACapsulesAxisEndsAtItsHemispheresCentres)
{
  const double L = 4.0, s = std::sqrt(0.5);
  std::vector<NurbsSurface> capsule;
  capsule.push_back(makeRevolution(NurbsCurve(2, { 0, 0, 0, 1, 1, 1 },
    Vec4List{ Vec4(0, 0, -1, 1), Vec4(s, 0, -s, s), Vec4(1, 0, 0, 1) })));
  capsule.push_back(makeRevolution(NurbsCurve(1, { 0, 0, 1, 1 }, Vec4List{ Vec4(1, 0, 0, 1), Vec4(1, 0, L, 1) })));
  capsule.push_back(makeRevolution(NurbsCurve(2, { 0, 0, 0, 1, 1, 1 },
    Vec4List{ Vec4(1, 0, L, 1), Vec4(s, 0, (L + 1) * s, s), Vec4(0, 0, L + 1, 1) })));
  for (const Placement& placed : { Placement{}, farFromTheOrigin() })
  {
    const std::string what = "scale " + std::to_string(placed.scale);
    const Traced t = trace(movedPieces(patchPieces(capsule), placed));
    ASSERT_EQ(t.mat.centreCurves.size(), 1u) << what;
    EXPECT_TRUE(t.mat.seams.empty() && t.mat.skeletalEdges.empty()) << what;
    const Normalisation& frame = t.boundary->userFrame();
    const double slack = 1e-12 * (L + 2.0) + 64.0 * frame.inputRounding() * (L + 2.0);
    std::vector<double> ends;
    for (int n : { t.mat.centreCurves.front().startNode, t.mat.centreCurves.front().endNode })
    {
      const Vec3 x = unplaced(placed, frame.toUser(t.mat.nodes[n].ball.x));
      EXPECT_LE(std::hypot(x.x(), x.y()), slack) << what;
      EXPECT_NEAR(frame.lengthToUser(t.mat.nodes[n].ball.r) / placed.scale, 1.0, slack) << what;
      ends.push_back(x.z());
    }
    std::sort(ends.begin(), ends.end());
    EXPECT_NEAR(ends.front(), 0.0, slack) << what;
    EXPECT_NEAR(ends.back(), L, slack) << what;
    const MedialComplex complex = t.mat.complex();
    const MedialVerification v = verifyMedialComplex(PatchBoundary(*t.boundary), complex, 1,
      std::max(1e-15, 64.0 * frame.inputRounding()));
    EXPECT_LE(v.maxDistanceError, VerifiedDistanceTolerance) << what;
    EXPECT_TRUE(topologyProblems(t).empty()) << what;
    std::vector<double> covered =
      centreCurveFootprints(*t.boundary, medialGenerators(*t.boundary), centreCurveTouches(t.mat));
    const std::vector<double> caps = sphericalFaceFootprints(*t.boundary, complex, 1e-9 * t.boundary->diagonal());
    int capFaces = 0;
    for (size_t f = 0; f < caps.size(); ++f)
    {
      covered[f] += caps[f];
      capFaces += caps[f] > 0.0;
    }
    EXPECT_EQ(capFaces, 8) << what; // two hemispheres of four patches each
    for (const FaceCoverage& c : sheetCoverage(*t.boundary, {}, covered))
      EXPECT_LE(c.shortfall(), 1e-5) << what << ": face " << c.face << " covered " << c.covered << " of " << c.area;
  }
}

// An ellipsoid whose rim passes through its poles, turned, moved and reweighted (a layout
// the random ellipsoids of bench/ drew): next to a pole a rim ball's touch is a degenerate
// minimum of the distance, and the footpoint search's boxes beside it, quartered, spent
// 200,000 each without reaching it — the touch dropped, the ball "off" by 4e-8 with two
// touch counts wrong (1.6 M boxes in all). Halved across the ribbon beside the touch, every
// ball verifies exactly (0.14 M boxes).
TEST(MAT3D, RimBallsBesideAPoleAreVerifiedExactly)
{
  const Eigen::Matrix3d turn =
    Eigen::AngleAxisd(3.4586918188642475, Vec3(0.34734403204084119, 0.22051791735143733, -0.29853333180487129).normalized())
      .toRotationMatrix();
  const double offset = 687.21463707333874;
  const std::vector<PatchPiece> pieces =
    movedPieces(patchPieces(ellipsoidSurfaces(Vec3(0.72850766504190645, 1.0998950097477629, 0.7469782911206807),
                  0.94191324519252295, 1)),
      turn, 2.5782516649537839, Vec3(offset, -offset, 0.3 * offset), 1.0254585889731784e16);
  const Traced t = trace(pieces);
  ASSERT_EQ(t.mat.skeletalEdges.size(), 1u);
  const PatchBoundary boundary(*t.boundary);
  const std::uint64_t before = patchSearchWork();
  const MedialVerification v = verifyMedialComplex(
    boundary, t.mat.complex(), 1, std::max(1e-15, 64.0 * t.boundary->userFrame().inputRounding()));
  EXPECT_LE(v.maxDistanceError, VerifiedDistanceTolerance);
  EXPECT_EQ(v.contactMismatches, 0);
  EXPECT_GE(v.contactsChecked, 30);
  EXPECT_LE(patchSearchWork() - before, 400000u);
}

// The witness that stands in for a touchpoint search stopped at its box limit (next to a
// pole, an osculating ball's touch can exhaust it) must vouch only for right balls. With
// the searches held to 40 boxes, most rim balls of an ellipsoid are checked by witness:
// the exact ones pass, and rim balls made 1e-6 of the size too large or too small are
// flagged.
TEST(MAT3D, AWitnessedRimBallThatIsWrongIsFlagged)
{
  const Traced t = trace(patchPieces(ellipsoidSurfaces(Vec3(2, 1.5, 1), M_PI / 6, 2)));
  const PatchBoundary boundary(*t.boundary);
  const MedialComplex exact = t.mat.complex();
  const PatchSearchLimit limit(40);
  const MedialVerification v = verifyMedialComplex(boundary, exact);
  EXPECT_LE(v.maxDistanceError, VerifiedDistanceTolerance);
  EXPECT_EQ(v.contactMismatches, 0);
  EXPECT_EQ(v.osculationMismatches, 0);
  EXPECT_GE(v.witnessed, v.contactsChecked / 2) << "the witness is not exercised";
  for (const double change : { 1e-6, -1e-6 })
  {
    MedialComplex wrong = exact;
    for (MedialPoint3D& p : wrong.points)
      if (p.type == MedialPoint3DType::SkeletalEdge)
        p.radius += change * boundary.size();
    const MedialVerification w = verifyMedialComplex(boundary, wrong);
    EXPECT_GE(w.maxDistanceError, 0.5e-6) << change;
    EXPECT_FALSE(w.ok(VerifiedDistanceTolerance)) << change;
  }
  // The emptiness decision the witness rests on: each rim ball shrunk by 1e-9 of the size
  // is empty, grown by 1e-6 it is not, and moved off the MAT with its radius still reaching
  // its touch it is not either.
  int rimBalls = 0;
  for (const MedialPoint3D& p : exact.points)
  {
    if (p.type != MedialPoint3DType::SkeletalEdge || p.touches.size() != 1 || rimBalls++ % 5 != 0)
      continue;
    const double size = boundary.size();
    EXPECT_FALSE(boundary.comesWithin(p.x, p.radius - 1e-9 * size));
    EXPECT_TRUE(boundary.comesWithin(p.x, p.radius + 1e-6 * size));
    const Vec3 off = p.x + 0.01 * size * Vec3(1, 1, 1).normalized();
    EXPECT_TRUE(boundary.comesWithin(off, (p.touches.front() - off).norm() - 1e-9 * size));
  }
  EXPECT_GE(rimBalls, 20);
}

// Circles of contact (CentreCurve.h). A cylinder of radius R and length 2h > 2R: its axis
// |z| ≤ h − R, every ball of radius R touching a whole circle of the side, from end to end
// where the ball also touches a cap's centre (the cone sheets' apexes). A torus: its core
// circle, closed, every ball of the tube's radius. A prolate spheroid: its axis segment.
// Moved, turned, scaled and reweighted;
// every point verified (distance = radius; a circle's touchpoints are not counted).
TEST(MAT3D, CylinderAxisAndTorusCoreAreCentreCurvesInClosedForm)
{
  const Placement far = farFromTheOrigin();
  auto back = [&](bool moved, const Normalisation& frame, const MedialBall3D& ball) {
    Vec3 x = frame.toUser(ball.x);
    double r = frame.lengthToUser(ball.r);
    if (moved)
    {
      x = unplaced(far, x);
      r /= far.scale;
    }
    return std::make_pair(x, r);
  };
  // The points verified: every `stride`-th and the ends (a ball touching a whole circle
  // costs the global distance search milliseconds — the circle is a continuum of minima —
  // and far from the origin, where the rounded input makes it a ring of near-minima, half
  // a second).
  // (Next to a spheroid's osculating ends the distance is flat to fourth order and its
  // search takes tens of seconds a point: there only the middle three fifths are verified,
  // the ends being held to the closed form.)
  auto verified = [](const Traced& t, const std::string& what, int stride, bool ends = true) {
    const Normalisation& frame = t.boundary->userFrame();
    const PatchBoundary boundary(*t.boundary);
    MedialComplex c = t.mat.complex();
    EXPECT_TRUE(topologyProblems(t).empty()) << what;
    ASSERT_EQ(c.elements.size(), 1u) << what;
    EXPECT_EQ(c.elements.front().type, MedialElementType::CentreCurve) << what;
    for (const MedialPoint3D& p : c.points)
      EXPECT_EQ(p.type, MedialPoint3DType::CircleCentre) << what;
    MedialComplex chosen;
    const size_t nodes = t.mat.nodes.size(), inner = c.points.size() - nodes;
    for (size_t i = 0; i < c.points.size(); ++i)
    {
      const bool middle = i >= nodes && 5 * (i - nodes) >= inner && 5 * (i - nodes) <= 4 * inner;
      if (i < nodes ? ends : (i - nodes) % stride == 0 && (ends || middle))
        chosen.points.push_back(c.points[i]);
    }
    const MedialVerification v =
      verifyMedialComplex(boundary, chosen, 1, std::max(1e-15, 64.0 * frame.inputRounding()));
    EXPECT_LE(v.maxDistanceError, VerifiedDistanceTolerance) << what;
    EXPECT_EQ(v.points, static_cast<int>(chosen.points.size())) << what;
  };
  // (Under the sanitizers the solids far from the origin are left to the plain build: their
  // circle balls' distance searches alone take minutes there.)
#ifdef __SANITIZE_ADDRESS__
  for (const bool moved : { false })
#else
  for (const bool moved : { false, true })
#endif
  {
    for (const double length : { 2.5, 3.0, 8.0 })
    {
      ShapeParameters p;
      p.length = length;
      std::vector<PatchPiece> pieces = patchPieces(makeShape("cylinder", p).surfaces);
      if (moved)
        pieces = movedPieces(pieces, far);
      const std::string what = "cylinder of length " + std::to_string(length) + (moved ? ", moved" : "");
      const Traced t = trace(pieces);
      EXPECT_EQ(t.mat.seams.size(), 0u) << what;
      EXPECT_EQ(t.mat.skeletalEdges.size(), 0u) << what;
      EXPECT_EQ(t.mat.junctionCount(), 0) << what;
      ASSERT_EQ(t.mat.centreCurves.size(), 1u) << what;
      const MAT3DCentreCurve& axis = t.mat.centreCurves.front();
      EXPECT_EQ(axis.faces, (std::vector<int>{ 0, 1, 2, 3 })) << what;
      const Normalisation& frame = t.boundary->userFrame();
      const double h = 0.5 * length, tolerance = (1e-9 + 64.0 * frame.inputRounding()) * length;
      double worst = 0.0;
      for (const MedialBall3D& ball : axis.balls)
      {
        const auto [x, r] = back(moved, frame, ball);
        worst = std::max({ worst, std::hypot(x.x(), x.y()), std::abs(r - p.radius),
          std::max(0.0, std::abs(x.z()) - (h - p.radius)) });
      }
      EXPECT_LE(worst, tolerance) << what;
      std::vector<double> ends;
      for (int n : { axis.startNode, axis.endNode })
      {
        const MAT3DNode& node = t.mat.nodes[n];
        EXPECT_TRUE(node.circleEnd) << what;
        EXPECT_EQ(node.ball.size(), 2) << what; // the side and a cap
        const auto [x, r] = back(moved, frame, node.ball);
        ends.push_back(x.z());
        EXPECT_NEAR(std::abs(x.z()), h - p.radius, tolerance) << what;
        EXPECT_NEAR(r, p.radius, tolerance) << what;
      }
      EXPECT_LT(ends[0] * ends[1], 0.0) << what; // one end at each cap
      verified(t, what, moved ? 8 : 1);
    }
    for (const auto& [core, tube] : { std::make_pair(2.0, 0.5), std::make_pair(3.0, 2.5) })
    {
      std::vector<PatchPiece> pieces = patchPieces({ torusSurface(core, tube) });
      if (moved)
        pieces = movedPieces(pieces, far);
      const std::string what = "torus " + std::to_string(core) + ", " + std::to_string(tube) + (moved ? ", moved" : "");
      const Traced t = trace(pieces);
      ASSERT_EQ(t.mat.centreCurves.size(), 1u) << what;
      const MAT3DCentreCurve& ring = t.mat.centreCurves.front();
      EXPECT_EQ(ring.startNode, ring.endNode) << what;
      EXPECT_EQ(ring.faces.size(), 16u) << what;
      const Normalisation& frame = t.boundary->userFrame();
      double worst = 0.0;
      for (const MedialBall3D& ball : ring.balls)
      {
        const auto [x, r] = back(moved, frame, ball);
        worst = std::max({ worst, std::abs(std::hypot(x.x(), x.y()) - core), std::abs(x.z()), std::abs(r - tube) });
      }
      EXPECT_LE(worst, (1e-9 + 64.0 * frame.inputRounding()) * core) << what;
      verified(t, what, moved ? 64 : 8);
    }
    // A prolate spheroid x²/a² + (y² + z²)/b² = 1 (a = 2, b = 1): the axis segment
    // |x| ≤ (a² − b²)/a, r = b·√(1 − x²/(a² − b²)), its ends osculating the poles (r = b²/a).
    // Patch layouts: poles on the axis of revolution (the circles are the patches' own
    // lines, the ends at the collapsed sides) or across it (the circles cross the patches;
    // the ends where the centres turn back, located by golden section).
    for (int polar : { 0, 1, 2 })
    {
      std::vector<PatchPiece> pieces = patchPieces(ellipsoidSurfaces(Vec3(2, 1, 1), M_PI / 6, polar));
      if (moved)
        pieces = movedPieces(pieces, far);
      const std::string what = "prolate spheroid, poles on axis " + std::to_string(polar) + (moved ? ", moved" : "");
      const Traced t = trace(pieces);
      ASSERT_EQ(t.mat.centreCurves.size(), 1u) << what;
      const MAT3DCentreCurve& axis = t.mat.centreCurves.front();
      const Normalisation& frame = t.boundary->userFrame();
      double worst = 0.0;
      for (const MedialBall3D& ball : axis.balls)
      {
        const auto [x, r] = back(moved, frame, ball);
        worst = std::max({ worst, std::hypot(x.y(), x.z()), std::max(0.0, std::abs(x.x()) - 1.5),
          std::abs(r - std::sqrt(std::max(0.0, 1.0 - x.x() * x.x() / 3.0))) });
      }
      EXPECT_LE(worst, 1e-9 + 64.0 * frame.inputRounding()) << what;
      // (The ends: where the circle test still holds next to the poles, umbilics whose
      // principal directions the input's rounding turns: within 1e-3 of the osculating
      // ends, 5e-3 far from the origin; the balls there are exact, what is missing is the
      // last piece of the segment.)
      for (int n : { axis.startNode, axis.endNode })
        EXPECT_NEAR(std::abs(back(moved, frame, t.mat.nodes[n].ball).first.x()), 1.5, moved ? 5e-3 : 1e-3) << what;
      verified(t, what, moved ? 16 : 4, false);
    }
  }
}

// The osculation check is what tells a rim from a ball that merely touches once: each rim
// ball shrunk about its touch (still inside the solid, distance = radius, one touchpoint)
// fails it, and only it.
TEST(MAT3D, ARimBallThatDoesNotOsculateFailsTheVerification)
{
  const Traced t = trace(patchPieces(makeShape("ellipsoid").surfaces));
  MedialComplex c = t.mat.complex();
  const PatchBoundary boundary(*t.boundary);
  EXPECT_TRUE(verifyMedialComplex(boundary, c).ok(VerifiedDistanceTolerance));
  for (MedialPoint3D& p : c.points)
    if (p.type == MedialPoint3DType::SkeletalEdge)
    {
      const Vec3 touch = p.touches.front();
      p.x = touch + 0.99 * (p.x - touch);
      p.radius *= 0.99;
    }
  const MedialVerification v = verifyMedialComplex(boundary, c);
  EXPECT_LE(v.maxDistanceError, VerifiedDistanceTolerance);
  EXPECT_EQ(v.contactMismatches, 0);
  EXPECT_NEAR(v.maxOsculationError, 0.01, 1e-6);
  EXPECT_GT(v.osculationMismatches, 0);
  EXPECT_FALSE(v.ok(VerifiedDistanceTolerance));
  EXPECT_NE(v.problems(VerifiedDistanceTolerance, c, [](const Vec3& x) { return x; }).find("does not osculate"),
    std::string::npos);
}

namespace
{
// How many seams of the MAT touch a generator of this kind somewhere.
int seamsTouching(const MAT3D& mat, GeneratorKind3D kind)
{
  int n = 0;
  for (const MAT3DSeam& s : mat.seams)
  {
    bool touches = false;
    for (const MedialBall3D& b : s.balls)
      for (int g : b.generators)
        touches = touches || mat.generators[g].kind == kind;
    n += touches;
  }
  return n;
}

bool hasJunction(const Traced& t, const Vec3& x, double r, int touchpoints, double tolerance = 1e-10)
{
  for (const Traced::Ball& j : t.junctions())
    if ((j.x - x).norm() <= tolerance && std::abs(j.r - r) <= tolerance && j.touchpoints == touchpoints)
      return true;
  return false;
}
} // namespace

// A box with a cubic cavity (a second shell inside the first: its edges are reflex, its
// corners reflex corners of three reflex edges). Centred, the MAT keeps the solid's three
// mirror symmetries (every junction's mirror images are junctions, with the same radius);
// off centre, every point is verified. (Their sheets are not all closed by seams: the sheet
// of a cavity face and the outer face across the gap ends where its touch reaches the
// cavity's edges and the sheet of that face and the edge goes on — a border no seam draws.)
TEST(MAT3D, BoxWithACubicCavity)
{
  auto withCavity = [](double half, const Vec3& centre) {
    std::vector<PatchPiece> pieces = boxPolyhedron(2.0, 1.5, 1.0);
    for (const PatchPiece& p : movedPieces(boxPolyhedron(half, half, half), Eigen::Matrix3d::Identity(), 1.0, centre))
      pieces.push_back(p);
    return pieces;
  };
  const Traced centred = trace(withCavity(0.2, Vec3::Zero()));
  expectVerified(centred, "centred cavity", false);
  // Seams reach every corner of the cavity (balls touching it and outer faces).
  auto cavityCornersTouched = [](const MAT3D& mat) {
    std::set<int> corners;
    for (const MAT3DSeam& s : mat.seams)
      for (const MedialBall3D& b : s.balls)
        for (int g : b.generators)
          if (mat.generators[g].kind == GeneratorKind3D::ReflexCorner)
            corners.insert(mat.generators[g].entity);
    return corners.size();
  };
  EXPECT_EQ(cavityCornersTouched(centred.mat), 8u);
  const std::vector<Traced::Ball> junctions = centred.junctions();
  EXPECT_GE(junctions.size(), 8u);
  for (const Traced::Ball& j : junctions)
    for (const Vec3& mirror : { Vec3(-1, 1, 1), Vec3(1, -1, 1), Vec3(1, 1, -1) })
      EXPECT_TRUE(hasJunction(centred, j.x.cwiseProduct(mirror), j.r, j.touchpoints, 1e-9)) << j.x.transpose();
  const Traced offCentre = trace(withCavity(0.4, Vec3(0.3, 0.0, 0.0)));
  expectVerified(offCentre, "cavity off centre", false);
  EXPECT_EQ(cavityCornersTouched(offCentre.mat), 8u);
}

// The L prism, 2.5 high: a reflex edge (x = y = 1) between the inner faces. Its profile's
// MAT has branch points where the legs end, (1.5, 0.5) and (0.5, 1.5) with r = 0.5, and on
// y = x at (c, c), c = 2 − √2, equidistant from x = 0, y = 0 and the reflex corner (1, 1):
// the 3D junctions are those balls where a cap touches too (as vtkMAT25DFilter finds them).
TEST(MAT3D, LPrismHasSeamsAlongItsReflexEdge)
{
  const double h = 2.5, c = 2.0 - std::sqrt(2.0);
  const Traced t = trace(lPrism(1.0, h));
  auto found = [&](const Vec3& x, double r) { return hasJunction(t, x, r, 4); };
  EXPECT_EQ(t.junctions().size(), 6u);
  for (double z : { 0.5, h - 0.5 })
  {
    EXPECT_TRUE(found(Vec3(1.5, 0.5, z), 0.5)) << z;
    EXPECT_TRUE(found(Vec3(0.5, 1.5, z), 0.5)) << z;
  }
  EXPECT_TRUE(found(Vec3(c, c, c), c));
  EXPECT_TRUE(found(Vec3(c, c, h - c), c));
  EXPECT_EQ(t.mat.generators.size(), t.boundary->faces().size() + 1) << "one reflex edge generator";
  EXPECT_GE(seamsTouching(t.mat, GeneratorKind3D::ReflexEdge), 2);
  expectVerified(t, "L prism");
}

// The cube [0, 2]³ with the corner cube [1, 2]³ cut away. The seam of the three faces at the
// origin runs up the diagonal until the reflex corner (1, 1, 1) touches: at (k, k, k) with
// k = √3 − √3·k, k = √3 / (1 + √3). Each reflex edge (say x = z = 1) meets the faces x = 0,
// z = 0 and y = 2 at (c, 2 − c, c), c = 2 − √2; each notch face and the three outer faces
// across it at (1.5, 1.5, 0.5) and its images, r = 1/2.
TEST(MAT3D, NotchedCubeTouchesItsReflexCorner)
{
  const Traced t = trace(notchedCube(2.0, 1.0));
  const double k = std::sqrt(3.0) / (1.0 + std::sqrt(3.0)), c = 2.0 - std::sqrt(2.0);
  EXPECT_EQ(t.junctions().size(), 7u);
  EXPECT_TRUE(hasJunction(t, Vec3(k, k, k), k, 4));
  for (const Vec3& x : { Vec3(c, 2 - c, c), Vec3(2 - c, c, c), Vec3(c, c, 2 - c) })
    EXPECT_TRUE(hasJunction(t, x, c, 4)) << x.transpose();
  for (const Vec3& x : { Vec3(1.5, 1.5, 0.5), Vec3(1.5, 0.5, 1.5), Vec3(0.5, 1.5, 1.5) })
    EXPECT_TRUE(hasJunction(t, x, 0.5, 4)) << x.transpose();
  EXPECT_GE(seamsTouching(t.mat, GeneratorKind3D::ReflexCorner), 3);
  EXPECT_GE(seamsTouching(t.mat, GeneratorKind3D::ReflexEdge), 6);
  expectVerified(t, "notched cube");
  // The catalogue's notched cube (edge 4, centred, squares of a 2 × 2 × 2 grid: smooth edges
  // everywhere) is the same solid scaled by 2 and moved by (−2, −2, −2).
  const Traced catalogue = trace(patchPieces(makeShape("notched-cube").surfaces));
  EXPECT_EQ(catalogue.junctions().size(), t.junctions().size());
  for (const Traced::Ball& j : t.junctions())
    EXPECT_TRUE(hasJunction(catalogue, 2.0 * j.x - Vec3(2, 2, 2), 2.0 * j.r, j.touchpoints)) << j.x.transpose();
  expectVerified(catalogue, "catalogue notched cube");
}

// The catalogue's stepped block (a 4 × 2 × 1.5 base, a 2 × 1 × 1.5 block centred on it):
// four reflex edges around the block's foot meet its convex vertical edges at four corners.
// There the sheet of the two reflex edges closes along a rim: a straight segment from the
// corner into the base whose balls touch the corner only (radius = distance to it), ending
// where the seam of those edges and the base's bottom meets it.
TEST(MAT3D, SteppedBlockHasRimsAtItsInnerCorners)
{
  const Traced t = trace(patchPieces(makeShape("stepped-block").surfaces));
  expectVerified(t, "stepped block");
  ASSERT_EQ(t.mat.skeletalEdges.size(), 4u);
  const Normalisation& n = t.boundary->userFrame();
  for (const MAT3DSkeletalEdge& rim : t.mat.skeletalEdges)
  {
    const Vec3 corner = n.toUser(t.boundary->vertices()[rim.vertex].point);
    EXPECT_NEAR(std::abs(corner.x()), 1.0, 1e-12);
    EXPECT_NEAR(std::abs(corner.y()), 0.5, 1e-12);
    EXPECT_NEAR(corner.z(), 0.0, 1e-12);
    EXPECT_TRUE(t.mat.nodes[rim.startNode].seamEnd);
    EXPECT_EQ(t.mat.nodes[rim.endNode].vertex, rim.vertex);
    for (const MedialBall3D& b : rim.balls)
      EXPECT_NEAR((n.toUser(b.x) - corner).norm(), n.lengthToUser(b.r), 1e-12);
  }
  // Symmetric under x → −x and y → −y: 12 junctions.
  EXPECT_EQ(t.junctions().size(), 12u);
}

// Random staircases (columns of unit cells whose heights never increase along x or y, every
// face a grid square): reflex edges, reflex corners, corners where convex and reflex edges
// meet (seams ending on the rim at such a corner), degenerate seams (square tubes' axes)
// and junctions where a crossing and a fourth contact coincide. Every point verified, one
// connected graph. (A longer run: the driver in bench/, 200 staircases up to 7 × 7.)
constexpr int MinimumCleanStaircases = 23; // of 24 (measured; see the comment below)

TEST(MAT3D, RandomStaircasesAreVerified)
{
  std::mt19937 rng(1);
  int rims = 0, clean = 0;
  for (int k = 0; k < 24; ++k)
  {
    const int n = 2 + k % 4, height = 2 + (k / 4) % 2;
    const std::string what = "staircase " + std::to_string(k) + " (" + std::to_string(n) + " x " +
      std::to_string(n) + ", " + std::to_string(height) + " high)";
    Traced t;
    try
    {
      t = trace(randomStaircase(rng, n, height));
    }
    catch (const InputError& e)
    {
      ADD_FAILURE() << what << ": " << e.what();
      continue;
    }
    EXPECT_GT(t.boundary->countEdges(VertexKind::Reflex), 0) << what;
    rims += static_cast<int>(t.mat.skeletalEdges.size());
    expectPointsVerified(t, what);
    clean += topologyProblems(t).empty();
  }
  EXPECT_GT(rims, 0) << "some staircase has a seam ending on a rim";
  // Known limit (README): at some of the grid's exact coincidences a seam is missed or
  // doubled; the graph check flags those solids (the filter's verification fails). The
  // rest must stay right.
  EXPECT_GE(clean, MinimumCleanStaircases) << "staircases with a consistent seam graph";
}

// The same kind of staircases turned about random axes, scaled by 1e-3 … 1e3 and moved by
// up to 1e4 × their size: the grid's coincidences are now only as exact as the rounding of
// the moved input. Every point that comes out is verified; a solid the tracer cannot do is
// refused by name (a corner where convex and reflex edges meet, a crossing at a grid vertex
// it cannot settle), never traced wrongly. (A driver over 96: 92 consistent, 2 flagged by the
// graph check, 2 refused.)
constexpr int MinimumMovedStaircasesTraced = 22; // of 24 (measured: 24)

// Staircase k (of 24 per seed) of random seed `seed`, turned, scaled and moved by the
// motion drawn for it: one motion stream runs over seeds 1, 2, … in turn (the driver's
// family of 96).
std::vector<PatchPiece> movedStaircase(int seed, int k)
{
  std::mt19937 motion(77);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int s = 1; s <= seed; ++s)
  {
    std::mt19937 rng(s);
    for (int i = 0; i < 24; ++i)
    {
      const int n = 2 + i % 4, height = 2 + (i / 4) % 2;
      const std::vector<PatchPiece> base = randomStaircase(rng, n, height);
      const Vec3 axis = Vec3(u(motion) - 0.5, u(motion) - 0.5, u(motion) - 0.5).normalized();
      const Eigen::Matrix3d rotation = Eigen::AngleAxisd(6.28 * u(motion), axis).toRotationMatrix();
      const double scale = std::pow(10.0, -3.0 + 6.0 * u(motion));
      const Vec3 offset = scale * std::pow(10.0, 4.0 * u(motion)) * Vec3(1.0, -0.7, 0.4);
      if (s == seed && i == k)
        return movedPieces(base, rotation, scale, offset, 1.0);
    }
  }
  return {};
}

TEST(MAT3D, MovedStaircasesAreVerifiedOrRefused)
{
  int traced = 0;
  for (int k = 0; k < 24; ++k)
  {
    const std::string what = "moved staircase " + std::to_string(k);
    Traced t;
    try
    {
      t = trace(movedStaircase(1, k));
    }
    catch (const InputError& e)
    {
      EXPECT_FALSE(std::string(e.what()).empty()) << what;
      continue;
    }
    ++traced;
    expectPointsVerified(t, what);
  }
  EXPECT_GE(traced, MinimumMovedStaircasesTraced);
}

// A junction of four generators of a moved staircase (a reflex edge's touch where a wall
// meets a floor, 350 and 120 × the size from the origin) solves only to the moved input's
// rounding: polished to that, not to 1e-13 of the size ("could not be polished" before).
TEST(MAT3D, MovedStaircaseJunctionsArePolishedToTheInputsRounding)
{
  for (const auto& [seed, k] : { std::pair<int, int>{ 3, 21 }, { 4, 23 } })
  {
    const std::string what = "moved staircase " + std::to_string(k) + " of seed " + std::to_string(seed);
    Traced t;
    try
    {
      t = trace(movedStaircase(seed, k));
    }
    catch (const InputError& e)
    {
      ADD_FAILURE() << what << ": " << e.what();
      continue;
    }
    EXPECT_FALSE(t.junctions().empty()) << what;
    expectPointsVerified(t, what);
    EXPECT_TRUE(topologyProblems(t).empty()) << what;
  }
}

// The profile swept, given as the swept solid's faces (placed) and traced as a general
// solid: the 2.5D MAT's junctions (placed alike) one for one, to `tolerance` of the scale,
// every point verified, the graph consistent.
void expectAgreesWithTheSweptSolidMAT(const std::vector<NurbsCurve>& curves, const Sweep& how, const std::string& what,
  double tolerance = 1e-10, const Placement& placed = {})
{
  const Boundary2D profile = Boundary2D::build(curvePieces(curves));
  const Generators generators(profile);
  const MedialGraph graph = computeMAT2D(generators);
  const SweepMap sweep(profile, how);
  const MedialComplex swept = computeMAT25D(generators, graph, sweep, {});
  Traced t;
  try
  {
    t = trace(movedPieces(sweptSolidFaces(generators, graph, sweep), placed));
  }
  catch (const InputError& e)
  {
    ADD_FAILURE() << what << ": " << e.what();
    return;
  }
  int expected = 0;
  for (const MedialElement& e : swept.elements)
    if (e.type == MedialElementType::Junction)
    {
      ++expected;
      const MedialPoint3D& p = swept.points[e.points.front()];
      EXPECT_TRUE(hasJunction(t, placed.scale * (placed.rotation * p.x) + placed.offset, placed.scale * p.radius,
        p.contacts, tolerance * placed.scale))
        << what << ": " << p.x.transpose();
    }
  EXPECT_EQ(static_cast<int>(t.junctions().size()), expected) << what;
  expectVerified(t, what);
  EXPECT_TRUE(topologyProblems(t).empty()) << what;
}

// Cross-check with the 2.5D construction: a polygonal profile extruded, its faces as the
// swept solid builds them (caps tiled by the profile MAT's chords: hundreds of coplanar
// pieces), traced as a general solid. The junctions must be the 2.5D MAT's, one for one.
TEST(MAT3D, ExtrudedPolygonsAgreeWithTheSweptSolidMAT)
{
  for (const auto& [name, length] : { std::pair<std::string, double>{ "l-shape", 2.5 }, { "star", 2.0 }, { "rectangle", 3.0 } })
    expectAgreesWithTheSweptSolidMAT(makeShape(name).curves, Sweep::extrusion(length), name + " extruded");
}

// Random profile k of seed `seed` for the extrusion cross-check: a star polygon (even k) or
// a regular polygon jittered by 0.05 (odd k), 3–14 edges, and a length in [0.5, 4).
RandomShape randomExtrusionProfile(int seed, int k, double& length)
{
  RandomEngine rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0;; ++i)
  {
    const int edges = 3 + static_cast<int>(u(rng) * 12);
    length = 0.5 + 3.5 * u(rng);
    RandomShape shape = i % 2 == 0 ? randomStarPolygon(rng, edges) : perturbedRegularPolygon(rng, edges, 0.05);
    if (i == k)
      return shape;
  }
}

// The same cross-check on random star polygons and jittered regular polygons extruded
// (reflex corners at random angles; near the centre of a jittered polygon, branch points
// 1e-5 of the size apart). Regressions kept: profiles whose footpoint steps from an edge's
// end over a reflex corner onto the next edge between two samples (the cap tiling gave
// that corner a patch of no area: "non-manifold edge"); seed 2's profile 137, whose
// vertical seam's touches run along the smooth edges where the sides are split (the
// neighbour piece across was taken for a face inside the ball, 2e-13 of the size in: the
// seam was missed); its profile 235, whose cap seam between two branch points 2.6e-5 of
// the size apart is shorter than the trial step (missed). A driver over 300 (seed 2): 295
// agree one for one and are consistent, 5 are refused ("keeps crossing edges"), none wrong.
TEST(MAT3D, RandomExtrudedPolygonsAgreeWithTheSweptSolidMAT)
{
  std::vector<std::pair<int, int>> cases;
  for (int k = 0; k < 12; ++k)
    cases.emplace_back(1, k);
  cases.emplace_back(2, 137);
  cases.emplace_back(2, 235);
  for (const auto& [seed, k] : cases)
  {
    double length = 1.0;
    const RandomShape shape = randomExtrusionProfile(seed, k, length);
    expectAgreesWithTheSweptSolidMAT(shape.curves, Sweep::extrusion(length),
      "extruded random polygon " + std::to_string(k) + " of seed " + std::to_string(seed), 1e-8);
  }
}

// Profiles revolved by part of a turn (faces of revolution: cylinders, cones, planes and
// tori of lines, each surface cut into pieces where the profile's MAT samples touch) traced
// as general solids: the 2.5D MAT's junctions one for one, every point verified, the graph
// consistent. The random profile 15 (seed 1; 2 and others too) was refused ("keeps crossing edges
// without moving") while a touch outside a curved piece was judged by 1e-12 of its
// parameter range: on the sliver pieces a touch running along a side crossed back and
// forth. (A driver over 60 random profiles: 58 agree, 2 refused by name; 29 before.)
TEST(MAT3D, RevolvedPolygonsAgreeWithTheSweptSolidMAT)
{
  struct Case
  {
    std::string what;
    std::vector<NurbsCurve> profile;
    double angle, axis;
  };
  std::vector<Case> cases{ { "rectangle revolved 90 degrees", makeShape("rectangle").curves, 90.0, 3.0 },
    { "L revolved 270 degrees", makeShape("l-shape").curves, 270.0, 3.0 } };
  RandomEngine rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k <= 15; ++k)
  {
    const int edges = 3 + static_cast<int>(u(rng) * 12);
    const double angle = 5.0 + 350.0 * u(rng), axis = 1.6 + 4.0 * u(rng);
    const RandomShape shape = k % 2 == 0 ? randomStarPolygon(rng, edges) : perturbedRegularPolygon(rng, edges, 0.05);
    if (k == 15)
      cases.push_back({ "random profile " + std::to_string(k) + " revolved", shape.curves, angle, axis });
  }
  for (const Case& c : cases)
    expectAgreesWithTheSweptSolidMAT(
      c.profile, Sweep::revolution(c.angle, Vec3(-c.axis, 0.0, 0.0), Vec3::UnitY()), c.what, 1e-8);
}

// Swept solids turned, scaled by 1e-3, reweighted by 1e20 and moved 1e5 (about 3e4 × their
// size) from the origin. The revolved rectangle's junction of eight faces at the middle of
// each end is reached by a seam its fourth face meets tangentially (the gap closes as the
// square of the step), which bisection brackets only to about the square root of the moved
// input's rounding; that face was not taken to touch and the run was refused ("met a face
// that does not touch where it was located"), the revolved L too. The extruded L traced,
// but the verification counted 4 touchpoints at a seam point touching two cap pieces near
// their common edge, each tilted by the rounding (the boundary between the two feet
// "outside" the ball by 1e-13): the valley test now allows for the input's rounding.
TEST(MAT3D, MovedSweptSolidsAgreeWithTheSweptSolidMAT)
{
  const Placement far = farFromTheOrigin();
  for (const std::string name : { "rectangle", "l-shape" })
  {
    expectAgreesWithTheSweptSolidMAT(makeShape(name).curves, Sweep::revolution(90.0, Vec3(-3.0, 0.0, 0.0), Vec3::UnitY()),
      name + " revolved 90 degrees, moved", 1e-9, far);
    expectAgreesWithTheSweptSolidMAT(
      makeShape(name).curves, Sweep::extrusion(2.5), name + " extruded, moved", 1e-9, far);
  }
}

// The thesis' fixed-step mode (constant step 1e-3 of the size, emptiness checked every 1e-2):
// the same junctions as the adaptive mode, every point verified, steps of the given length.
TEST(MAT3D, FixedStepModeFindsTheSameJunctions)
{
  MAT3DOptions fixed;
  fixed.fixedStep = true;
  fixed.step = 1e-3;
  fixed.junctionCheckStep = 1e-2;
  std::mt19937 rng(4);
  const std::vector<std::pair<std::string, std::vector<PatchPiece>>> solids{ { "box", boxPolyhedron(2.0, 1.5, 1.0) },
    { "notched cube", notchedCube(2.0, 1.0) }, { "frustum", randomFrustum(rng, 7) },
    { "box with a free-form top", boxWithFreeFormTop(2.0, 1.5, 1.0, 0.3, 0.5) } };
  for (const auto& [name, pieces] : solids)
  {
    const Traced adaptive = trace(pieces);
    const Traced stepped = trace(pieces, fixed);
    EXPECT_EQ(stepped.junctions().size(), adaptive.junctions().size()) << name;
    for (const Traced::Ball& j : adaptive.junctions())
      EXPECT_TRUE(hasJunction(stepped, j.x, j.r, j.touchpoints, 1e-9)) << name << ": " << j.x.transpose();
    EXPECT_EQ(stepped.mat.seams.size(), adaptive.mat.seams.size()) << name;
    // Steps of the fixed length (crossings and the ends aside): many more points.
    size_t points = 0;
    for (const MAT3DSeam& seam : stepped.mat.seams)
      points += seam.balls.size();
    size_t adaptivePoints = 0;
    for (const MAT3DSeam& seam : adaptive.mat.seams)
      adaptivePoints += seam.balls.size();
    EXPECT_GT(points, 3 * adaptivePoints) << name;
    expectVerified(stepped, name + " (fixed steps)");
  }
}

TEST(MAT3D, InvariantUnderMotionScaleAndPosition)
{
  // The same junctions (moved with the solid) and every point verified, for a box, random
  // frustums and solids with reflex edges and corners (the notched cube, a staircase and the
  // stepped block with rims) rotated, scaled by 1e-6 … 1e6 and moved up to 2e6 × their size:
  // the grid solids' exact coincidences (two reflex edges' touches reaching their corner
  // together) become rounding-level near-coincidences there.
  std::mt19937 rng(11);
  const std::vector<std::vector<PatchPiece>> solids{ boxPolyhedron(2.0, 1.5, 1.0), randomFrustum(rng, 5),
    randomFrustum(rng, 9), notchedCube(2.0, 1.0), randomStaircase(rng, 3, 2),
    patchPieces(makeShape("stepped-block").surfaces) };
  const struct
  {
    double scale, offset;
  } placements[] = { { 1.0, 0.0 }, { 1e-6, 3e-6 }, { 1e6, 0.0 }, { 1.0, 1e4 }, { 3.0, 2e6 }, { 0.01, 1e3 } };
  for (size_t s = 0; s < solids.size(); ++s)
  {
    const Traced reference = trace(solids[s]);
    const std::vector<Traced::Ball> expected = reference.junctions();
    for (const auto& p : placements)
    {
      const Eigen::Matrix3d rotation =
        Eigen::AngleAxisd(0.3 + s, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
      const Vec3 offset = p.offset * Vec3(0.6, -0.8, 0.5);
      const std::string what = "solid " + std::to_string(s) + " scaled by " + std::to_string(p.scale) +
        ", moved by " + std::to_string(p.offset);
      const Traced t = trace(movedPieces(solids[s], rotation, p.scale, offset));
      expectVerified(t, what);
      ASSERT_EQ(t.mat.junctionCount(), static_cast<int>(expected.size())) << what;
      EXPECT_EQ(t.mat.seams.size(), reference.mat.seams.size()) << what;
      EXPECT_EQ(t.mat.skeletalEdges.size(), reference.mat.skeletalEdges.size()) << what;
      for (const Traced::Ball& e : expected)
      {
        const Vec3 x = p.scale * (rotation * e.x) + offset;
        double nearest = INFINITY;
        for (const Traced::Ball& j : t.junctions())
          if (j.touchpoints == e.touchpoints && std::abs(j.r - p.scale * e.r) <= 1e-9 * p.scale * 4.0)
            nearest = std::min(nearest, (j.x - x).norm());
        EXPECT_LE(nearest, 1e-9 * p.scale * 4.0) << what;
      }
    }
  }
}

// Planar faces (linear triangles, bilinear quadrilaterals whose corners lie in one plane,
// quadrilaterals with a collapsed side — the swept L's profile tiles — as triangles) take
// the closed-form nearest point; it must agree with the general patch search, inside and
// outside the solid.
TEST(PatchBoundary, PlanarFacesAgreeWithThePatchSearch)
{
  const Boundary2D profile = Boundary2D::build(curvePieces(makeShape("l-shape").curves));
  const Generators generators(profile);
  const MedialGraph graph = computeMAT2D(generators);
  const SweepMap sweep(profile, Sweep::extrusion(2.5));
  std::vector<std::vector<PatchPiece>> solids{ sweptSolidFaces(generators, graph, sweep),
    boxPolyhedron(2.0, 1.5, 1.0), patchPieces(makeShape("notched-cube").surfaces) };
  // A wedge whose quadrilaterals are skewed (not parallelograms).
  solids.push_back(polyhedron({ Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(0, 1.5, 0), Vec3(0, 0, 1), Vec3(2, 0, 0.5) },
    { { 0, 3, 2, 1 }, { 0, 1, 5, 4 }, { 1, 2, 5 }, { 3, 0, 4 }, { 4, 5, 2, 3 } }));
  std::mt19937 rng(3);
  for (size_t s = 0; s < solids.size(); ++s)
  {
    const Boundary3D b = buildNormalised(solids[s]);
    const PatchBoundary boundary(b);
    std::uniform_real_distribution<double> coordinate(-1.2, 1.2);
    for (int k = 0; k < 200; ++k)
    {
      const Vec3 x(coordinate(rng), coordinate(rng), coordinate(rng));
      double searched = Unbounded;
      for (const Face3D& f : b.faces())
        searched = std::min(searched, closestPoint(f.patch, x).distance);
      EXPECT_NEAR(boundary.distance(x), searched, 1e-12) << "solid " << s << " at " << x.transpose();
    }
  }
}

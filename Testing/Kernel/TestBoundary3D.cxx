// The solid B-rep: face adjacency, orientation, edge and vertex classification.
#include "brep/Boundary3D.h"
#include "common/InputError.h"
#include "brep/WindingNumber.h"
#include "shapes/Catalogue.h"
#include "shapes/Moved.h"
#include "shapes/Polyhedra.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace exactmat;

namespace
{
Boundary3D buildShape(const std::string& name)
{
  return Boundary3D::build(patchPieces(makeShape(name).surfaces));
}

std::vector<PatchPiece> joined(std::vector<PatchPiece> a, const std::vector<PatchPiece>& b)
{
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// The same faces, each with u and v exchanged: the whole shell turned inside out.
std::vector<PatchPiece> insideOut(std::vector<PatchPiece> pieces)
{
  for (PatchPiece& piece : pieces)
  {
    const BezierPatch& p = piece.patch;
    Vec4List net;
    for (int j = 0; j <= p.degreeV(); ++j)
      for (int i = 0; i <= p.degreeU(); ++i)
        net.push_back(p.homogeneousPoint(i, j));
    piece.patch = BezierPatch(p.degreeV(), p.degreeU(), net);
  }
  return pieces;
}

std::vector<PatchPiece> cylinderScaled(double scale, const Vec3& offset)
{
  return movedPieces(patchPieces(makeShape("cylinder").surfaces), Eigen::Matrix3d::Identity(), scale, offset);
}
} // namespace

TEST(Boundary3D, BoxHasTwelveConvexEdgesAndEightConvexVertices)
{
  const Boundary3D b = buildShape("box");
  EXPECT_EQ(b.faces().size(), 6u);
  EXPECT_EQ(b.edges().size(), 12u);
  EXPECT_EQ(b.countEdges(VertexKind::Convex), 12);
  EXPECT_EQ(b.vertices().size(), 8u);
  EXPECT_EQ(b.countVertices(VertexKind::Convex), 8);
  EXPECT_NEAR(b.volume(), 4.0 * 2.0 * 3.0, 1e-12);
  for (const Edge3D& e : b.edges())
    EXPECT_NEAR(e.dihedralAngle, M_PI / 2, 1e-12);
}

TEST(Boundary3D, CylinderSeamsAreSmoothAndRimsConvex)
{
  const Boundary3D b = buildShape("cylinder");
  // 4 side patches + 2 disks; 4 vertical seams (smooth), 8 rim arcs (convex).
  EXPECT_EQ(b.faces().size(), 6u);
  EXPECT_EQ(b.countEdges(VertexKind::Smooth), 4);
  EXPECT_EQ(b.countEdges(VertexKind::Convex), 8);
  EXPECT_NEAR(b.volume(), M_PI * 1.0 * 3.0, 1e-6); // 8x8 Gauss points on rational patches
  // Every outward normal points away from the axis or along ±z on the caps.
  for (const Face3D& f : b.faces())
  {
    const Vec3 p = f.patch.evaluate(0.5, 0.5), n = f.patch.normal(0.5, 0.5);
    const Vec3 out = std::abs(p.z()) > 1.5 - 1e-9 ? Vec3(0, 0, p.z()) : Vec3(p.x(), p.y(), 0);
    EXPECT_GT(n.dot(out), 0.0) << f.name();
  }
}

TEST(Boundary3D, PillowExtrusionRevolution)
{
  const Boundary3D pillow = buildShape("pillow");
  EXPECT_EQ(pillow.countEdges(VertexKind::Convex), 12);
  EXPECT_GT(pillow.volume(), 8.0); // bulged beyond the unit cube [−1,1]³
  const Boundary3D ext = buildShape("extrusion");
  // Side seams between Bézier pieces of the C² profile are smooth; rims convex; the cap
  // fans are flat (smooth spokes).
  EXPECT_EQ(ext.countEdges(VertexKind::Reflex), 0);
  EXPECT_EQ(ext.countEdges(VertexKind::Convex), 2 * 12);
  EXPECT_GT(ext.volume(), 0.0);
  const Boundary3D rev = buildShape("revolution");
  EXPECT_EQ(rev.countEdges(VertexKind::Convex), 0);
  EXPECT_EQ(rev.countEdges(VertexKind::Reflex), 0);
  // Pappus: volume = 2π·x̄·A of the profile; x̄ = 2.5 for the blob centred there.
  const Boundary2D profile = Boundary2D::build(curvePieces(makeShape("blob", [] {
    ShapeParameters s;
    s.count = 3;
    return s;
  }()).curves));
  (void)profile;
  EXPECT_GT(rev.volume(), 0.0);
}

TEST(Boundary3D, ReorientsAFlippedFace)
{
  std::vector<PatchPiece> pieces = patchPieces(makeShape("box").surfaces);
  // Reverse one face's parameterisation (u ⇄ v).
  const BezierPatch& p = pieces[2].patch;
  Vec4List net{ p.homogeneousPoint(0, 0), p.homogeneousPoint(1, 0), p.homogeneousPoint(0, 1),
    p.homogeneousPoint(1, 1) };
  pieces[2].patch = BezierPatch(1, 1, net);
  const Boundary3D b = Boundary3D::build(pieces);
  EXPECT_TRUE(b.faces()[2].flipped);
  EXPECT_NEAR(b.volume(), 24.0, 1e-12);
  EXPECT_EQ(b.countEdges(VertexKind::Convex), 12);
}

TEST(Boundary3D, TrianglesAreFacesToo)
{
  // A tetrahedron of four linear triangles.
  const Vec3 v[4] = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1) };
  const int tri[4][3] = { { 0, 2, 1 }, { 0, 1, 3 }, { 1, 2, 3 }, { 0, 3, 2 } };
  std::vector<PatchPiece> pieces;
  for (auto& t : tri)
  {
    TriangleNet net;
    net.degree = 1;
    net.points.resize(3);
    // index(i, j): (0,0) = V0 (k = n), (1,0) = V1, (0,1) = V2.
    net.points[TriangleNet::index(1, 0, 0)] = homogeneous(v[t[0]], 1);
    net.points[TriangleNet::index(1, 1, 0)] = homogeneous(v[t[1]], 1);
    net.points[TriangleNet::index(1, 0, 1)] = homogeneous(v[t[2]], 1);
    PatchPiece piece;
    piece.triangle = net;
    piece.patch = BezierPatch::fromTriangle(net);
    pieces.push_back(piece);
  }
  const Boundary3D b = Boundary3D::build(pieces);
  EXPECT_EQ(b.edges().size(), 6u);
  EXPECT_EQ(b.countEdges(VertexKind::Convex), 6);
  EXPECT_NEAR(b.volume(), 1.0 / 6.0, 1e-14);
}

TEST(Boundary3D, BadInputGivesClearErrors)
{
  auto errorOf = [](const std::vector<PatchPiece>& p) {
    try
    {
      Boundary3D::build(p);
    }
    catch (const InputError& e)
    {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(errorOf({}).find("empty input"), std::string::npos);
  std::vector<PatchPiece> open = patchPieces(makeShape("box").surfaces);
  open.pop_back();
  EXPECT_NE(errorOf(open).find("open surface"), std::string::npos) << errorOf(open);
  std::vector<PatchPiece> nan = patchPieces(makeShape("box").surfaces);
  Vec4List net = nan[3].patch.homogeneousNet();
  net[1].x() = NAN;
  nan[3].patch = BezierPatch(1, 1, net);
  EXPECT_NE(errorOf(nan).find("face 3: control point (0, 1) has a NaN"), std::string::npos)
    << errorOf(nan);
}

TEST(Boundary3D, WindingNumberIsOneInsideAndZeroOutsideEvenCloseToTheSurface)
{
  const Boundary3D cylinder = buildShape("cylinder"); // radius 1, |z| ≤ 1.5
  std::vector<BezierPatch> shell;
  for (const Face3D& f : cylinder.faces())
    shell.push_back(f.patch);
  for (double d : { 0.5, 1e-3, 1e-8, 1e-11 })
  {
    EXPECT_NEAR(windingNumber(shell, Vec3(1.0 - d, 0.0, 0.3)), 1.0, 1e-5) << d;
    EXPECT_NEAR(windingNumber(shell, Vec3(1.0 + d, 0.0, 0.3)), 0.0, 1e-5) << d;
    EXPECT_NEAR(windingNumber(shell, Vec3(0.2, 0.1, 1.5 - d)), 1.0, 1e-5) << d;
    EXPECT_NEAR(windingNumber(shell, Vec3(0.2, 0.1, -1.5 - d)), 0.0, 1e-5) << d;
  }
  EXPECT_TRUE(std::isnan(windingNumber(shell, Vec3(1.0, 0.0, 0.3))));
}

TEST(Boundary3D, CavitiesFaceTheirNormalsIntoTheCavity)
{
  // The box [−2, 2] × [−1.5, 1.5] × [−1, 1] with a cylindrical cavity (radius 0.3, |z| ≤
  // 0.45) off its centre, and a small box floating in the cavity: its normals point out
  // again (the material lies outside it). Each shell given either way round.
  const Vec3 c(0.4, -0.2, 0.1);
  const std::vector<PatchPiece> outer = boxPolyhedron(2.0, 1.5, 1.0);
  const std::vector<PatchPiece> cavity = cylinderScaled(0.3, c);
  const std::vector<PatchPiece> island = movedPieces(boxPolyhedron(0.1, 0.1, 0.1), Eigen::Matrix3d::Identity(), 1.0, c);
  const double cavityVolume = M_PI * 0.09 * 0.9, islandVolume = 0.008;
  for (int flips = 0; flips < 8; ++flips)
  {
    const Boundary3D b = Boundary3D::build(joined(joined(flips & 1 ? insideOut(outer) : outer,
      flips & 2 ? insideOut(cavity) : cavity), flips & 4 ? insideOut(island) : island));
    EXPECT_NEAR(b.volume(), 24.0 - cavityVolume + islandVolume, 1e-5) << flips;
    // The outer box's and the island's edges are convex, the cavity's rims reflex.
    EXPECT_EQ(b.countEdges(VertexKind::Convex), 12 + 12) << flips;
    EXPECT_EQ(b.countEdges(VertexKind::Reflex), 8) << flips;
    for (const Face3D& f : b.faces())
    {
      if (f.piece < 6 || f.piece >= 12)
        continue;
      const Vec3 p = f.patch.evaluate(0.5, 0.5), n = f.patch.normal(0.5, 0.5);
      const Vec3 away = std::abs(p.z() - c.z()) > 0.45 - 1e-9 ? Vec3(0, 0, p.z() - c.z()) : Vec3(p.x() - c.x(), p.y() - c.y(), 0);
      EXPECT_LT(n.dot(away), 0.0) << f.name() << " of the cavity must face into it (" << flips << ")";
    }
  }
  // Two separate solids both keep outward normals.
  const Boundary3D two = Boundary3D::build(joined(outer, cylinderScaled(0.3, Vec3(5, 0, 0))));
  EXPECT_NEAR(two.volume(), 24.0 + cavityVolume, 1e-5);
  EXPECT_EQ(two.countEdges(VertexKind::Reflex), 0);
}

TEST(Boundary3D, ShellsThatCrossAreRefused)
{
  const std::vector<PatchPiece> crossing = joined(boxPolyhedron(2.0, 1.5, 1.0), cylinderScaled(0.3, Vec3(1.9, 0.0, 0.0)));
  try
  {
    Boundary3D::build(crossing);
    FAIL() << "crossing shells were accepted";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("shell touches or crosses the shell of face"), std::string::npos) << e.what();
  }
}

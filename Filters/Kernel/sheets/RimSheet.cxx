#include "RimSheet.h"

#include "common/Format.h"
#include "common/InputError.h"
#include "geometry/DomainTriangulation.h"
#include "sheets/CentroidRefinement.h"
#include "mat3d/PatchBoundary.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace exactmat
{

namespace
{

// A ball of the sheet over domain point w: touching face a at qa (the side the plane's
// normal points to) and face b at qb, its centre at height h on the normal through w.
struct SheetBall
{
  int a = -1, b = -1;
  Vec2 qa = Vec2::Zero(), qb = Vec2::Zero();
  double h = 0.0, r = 0.0;
  Vec3 x = Vec3::Zero(), ta = Vec3::Zero(), tb = Vec3::Zero();
  Vec2 w = Vec2::Zero(); ///< the domain point
};

class RimSheetBuilder
{
public:
  RimSheetBuilder(const Boundary3D& boundary, const std::vector<Generator3D>& generators, const SheetBorderCurve& rim,
    const SheetOptions& options)
    : B(boundary)
    , G(generators)
    , Rim(rim)
    , Options(options)
    , Size(boundary.diagonal())
  {
    for (const Edge3D& e : B.edges())
      if (e.kind == VertexKind::Smooth)
      {
        Across[{ e.faceA, e.sideA }] = e.faceB;
        Across[{ e.faceB, e.sideB }] = e.faceA;
      }
    if (!Options.exact)
    {
      Own = std::make_unique<PatchBoundary>(B);
      Options.exact = Own.get();
    }
  }

  MedialSheetMesh run();

private:
  Vec3 lineAt(const Vec2& w, double h) const { return Origin + w.x() * E1 + w.y() * E2 + h * Normal; }
  Vec2 parameters(int f, const SolidBoundary::Contact& c) const
  {
    return !G[f].planar() && std::isfinite(c.parameters.x()) ? c.parameters : G[f].parameterOf(c.point);
  }
  double depth(const Vec3& x) const;
  bool newton(const Vec2& w, SheetBall& s) const;
  bool fresh(const Vec2& w, double centre, double reach, SheetBall& s) const;
  bool solve(const Vec2& w, const SheetBall* guess, double centre, double reach, SheetBall& s) const;
  std::string where() const
  {
    return "the sheet inside the rim through " + format(B.userPoint(Rim.centres.front()));
  }

  const Boundary3D& B;
  const std::vector<Generator3D>& G;
  const SheetBorderCurve& Rim;
  SheetOptions Options;
  double Size;
  std::unique_ptr<PatchBoundary> Own;
  std::map<std::pair<int, int>, int> Across; // (face, side) → the face beyond a smooth edge
  Vec3 Origin = Vec3::Zero(), Normal = Vec3::UnitZ(), E1 = Vec3::UnitX(), E2 = Vec3::UnitY();
};

// The distance from x to the boundary, negative outside the solid (the side of the nearest
// point's inward normal).
double RimSheetBuilder::depth(const Vec3& x) const
{
  const double d = Options.exact->distance(x);
  const auto contacts = Options.exact->touchpoints(x, d * (1.0 + 1e-9) + 1e-15 * Size);
  if (contacts.empty() || contacts.front().source < 0)
    return -d;
  const SolidBoundary::Contact& c = contacts.front();
  const Vec3 inward = G[c.source].evaluate(parameters(c.source, c)).normal;
  return (x - c.point).dot(inward) >= 0.0 ? d : -d;
}

// Newton on both touches, the height and the radius: S_a + r·N_a = S_b + r·N_b = x(w, h).
// A touch that leaves its face across a smooth edge goes on on the face beyond.
bool RimSheetBuilder::newton(const Vec2& w, SheetBall& s) const
{
  for (int it = 0, switches = 0; it < 40; ++it)
  {
    const Touch3D ta = G[s.a].evaluate(s.qa), tb = G[s.b].evaluate(s.qb);
    const Vec3 x = lineAt(w, s.h);
    Eigen::Matrix<double, 6, 1> residual;
    residual << ta.point + s.r * ta.normal - x, tb.point + s.r * tb.normal - x;
    Eigen::Matrix<double, 6, 6> j = Eigen::Matrix<double, 6, 6>::Zero();
    j.block<3, 2>(0, 0) = ta.dPoint + s.r * ta.dNormal;
    j.block<3, 2>(3, 2) = tb.dPoint + s.r * tb.dNormal;
    j.block<3, 1>(0, 4) = -Normal;
    j.block<3, 1>(3, 4) = -Normal;
    j.block<3, 1>(0, 5) = ta.normal;
    j.block<3, 1>(3, 5) = tb.normal;
    if (residual.norm() <= 1e-13 * Size)
    {
      s.x = x;
      s.ta = ta.point;
      s.tb = tb.point;
      return s.r > 0.0 && (ta.point - tb.point).norm() > 1e-9 * Size;
    }
    Eigen::Matrix<double, 6, 1> delta = j.colPivHouseholderQr().solve(-residual);
    if (!delta.allFinite())
      return false;
    // (Steps longer than a tenth of the radius leave Newton's reach.)
    const double longest = std::max({ (ta.dPoint * delta.segment<2>(0)).norm(), (tb.dPoint * delta.segment<2>(2)).norm(),
      std::abs(delta(4)), std::abs(delta(5)) });
    if (longest > 0.1 * s.r)
      delta *= 0.1 * s.r / longest;
    s.qa += delta.segment<2>(0);
    s.qb += delta.segment<2>(2);
    s.h += delta(4);
    s.r += delta(5);
    for (auto [face, q] : { std::pair<int*, Vec2*>{ &s.a, &s.qa }, std::pair<int*, Vec2*>{ &s.b, &s.qb } })
    {
      const int side = G[*face].exitSide(*q, 1e-9 * Size);
      if (side < 0)
        continue;
      const auto beyond = Across.find({ *face, side });
      if (beyond == Across.end() || ++switches > 8)
        return false;
      const Vec3 p = G[*face].evaluate(*q).point;
      *face = beyond->second;
      *q = G[*face].parameterOf(p);
    }
  }
  return false;
}

// The deepest point of the normal through w within `reach` of height `centre` (the signed
// distance is concave across a sheet: largest on it), its two contacts, then Newton. The
// deepest point alone is a sheet ball to the search's 1e-12 where Newton cannot polish it
// (a touch at a pole, where the face's parameters are singular).
bool RimSheetBuilder::fresh(const Vec2& w, double centre, double reach, SheetBall& s) const
{
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = centre - reach, hi = centre + reach;
  double m1 = hi - golden * (hi - lo), m2 = lo + golden * (hi - lo);
  double d1 = depth(lineAt(w, m1)), d2 = depth(lineAt(w, m2));
  for (int k = 0; k < 120 && hi - lo > 1e-13 * Size; ++k)
    if (d1 >= d2)
    {
      hi = m2;
      m2 = m1;
      d2 = d1;
      m1 = hi - golden * (hi - lo);
      d1 = depth(lineAt(w, m1));
    }
    else
    {
      lo = m1;
      m1 = m2;
      d1 = d2;
      m2 = lo + golden * (hi - lo);
      d2 = depth(lineAt(w, m2));
    }
  const double h = 0.5 * (lo + hi);
  const Vec3 x = lineAt(w, h);
  const double d = depth(x);
  if (!(d > 0.0))
    return false;
  const auto contacts = Options.exact->touchpoints(x, d * (1.0 + 1e-7));
  if (contacts.size() < 2)
    return false;
  // The contacts farthest to either side of the sheet.
  const SolidBoundary::Contact* up = &contacts.front();
  const SolidBoundary::Contact* down = &contacts.front();
  for (const SolidBoundary::Contact& c : contacts)
  {
    if ((c.point - x).dot(Normal) > (up->point - x).dot(Normal))
      up = &c;
    if ((c.point - x).dot(Normal) < (down->point - x).dot(Normal))
      down = &c;
  }
  if (up == down || up->source < 0 || down->source < 0)
    return false;
  s.a = up->source;
  s.b = down->source;
  s.qa = parameters(s.a, *up);
  s.qb = parameters(s.b, *down);
  s.h = h;
  s.r = d;
  SheetBall polished = s;
  if (newton(w, polished) && std::abs(polished.h - h) <= 1e-6 * Size)
  {
    s = polished;
    return true;
  }
  s.x = x;
  s.ta = up->point;
  s.tb = down->point;
  return true;
}

// From the nearest solved ball, by Newton; where that does not land, along the straight
// way to w in 2, 4, … 32 steps (continuation: a flat sheet's triangles are many radii
// across, farther than Newton reaches); else afresh.
bool RimSheetBuilder::solve(const Vec2& w, const SheetBall* guess, double centre, double reach, SheetBall& s) const
{
  auto step = [&](const Vec2& to, SheetBall& ball) {
    return newton(to, ball) && (ball.ta - ball.x).dot(Normal) >= 0.0 && (ball.tb - ball.x).dot(Normal) <= 0.0;
  };
  if (guess)
    for (int pieces = 1; pieces <= 32; pieces *= 2)
    {
      s = *guess;
      bool ok = true;
      for (int i = 1; i <= pieces && ok; ++i)
        ok = step(guess->w + (w - guess->w) * (static_cast<double>(i) / pieces), s);
      if (ok)
      {
        s.w = w;
        return true;
      }
    }
  if (!fresh(w, centre, reach, s))
    return false;
  s.w = w;
  return true;
}

MedialSheetMesh RimSheetBuilder::run()
{
  // The rim's balls, once round (a closed curve may repeat its first point at the end).
  std::vector<int> rim;
  for (size_t i = 0; i < Rim.centres.size(); ++i)
    if (i + 1 < Rim.centres.size() || (Rim.centres[i] - Rim.centres.front()).norm() > 1e-12 * Size)
      rim.push_back(static_cast<int>(i));
  if (rim.size() < 3 || Rim.touches.size() != Rim.centres.size())
    fail("3D MAT sheets: ", where(), " has fewer than three points or no touches");
  // The plane fitted to the rim's centres (least squares): its normal is the covariance's
  // smallest eigenvector.
  Origin = Vec3::Zero();
  for (int i : rim)
    Origin += Rim.centres[i];
  Origin /= static_cast<double>(rim.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (int i : rim)
    covariance += (Rim.centres[i] - Origin) * (Rim.centres[i] - Origin).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
  Normal = eigen.eigenvectors().col(0);
  E1 = eigen.eigenvectors().col(2);
  E2 = Normal.cross(E1);
  std::vector<Vec2> border;
  double reach = 0.0;
  for (int i : rim)
  {
    border.push_back(Vec2((Rim.centres[i] - Origin).dot(E1), (Rim.centres[i] - Origin).dot(E2)));
    reach = std::max(reach, 2.0 * Rim.radii[i] + std::abs((Rim.centres[i] - Origin).dot(Normal)));
  }
  std::unique_ptr<DomainTriangulation> domain;
  try
  {
    domain = std::make_unique<DomainTriangulation>(std::vector<std::vector<Vec2>>{ border });
  }
  catch (const InputError& e)
  {
    fail("3D MAT sheets: ", where(), " is not a graph over the plane fitted to it (", e.what(), ")");
  }
  MedialSheetMesh mesh;
  std::vector<SheetBall> balls(rim.size()); // per domain vertex (the rim's: its own ball)
  std::vector<bool> solved(rim.size(), false);
  for (size_t k = 0; k < rim.size(); ++k)
  {
    SheetVertex v;
    v.x = Rim.centres[rim[k]];
    v.r = Rim.radii[rim[k]];
    v.touch = { { Rim.touches[rim[k]], Rim.touches[rim[k]] } };
    v.domain = border[k];
    v.source = Rim.ids[rim[k]];
    v.border = true;
    mesh.vertices.push_back(v);
  }
  mesh.loops = 1;
  mesh.loopSizes = { static_cast<int>(rim.size()) };
  auto nearestSolved = [&](const Vec2& w) -> const SheetBall* {
    const SheetBall* best = nullptr;
    double bestDistance = INFINITY;
    for (size_t k = 0; k < balls.size(); ++k)
      if (solved[k] && (mesh.vertices[k].domain - w).norm() < bestDistance)
      {
        bestDistance = (mesh.vertices[k].domain - w).norm();
        best = &balls[k];
      }
    return best;
  };
  SheetBall last; // the ball of the vertex just solved (kept when it is added)
  auto ball = [&](const Vec2& w, const std::array<int, 3>& t) {
    const SheetVertex &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const Vec3 linear = (a.x + b.x + c.x) / 3.0;
    if (!solve(w, nearestSolved(w), (linear - Origin).dot(Normal), reach, last))
      fail("3D MAT sheets: ", where(), ": no ball touches the solid on both sides of it over ",
        format(B.userPoint(linear)));
    SheetVertex v;
    v.x = last.x;
    v.r = last.r;
    v.q = { { last.qa, last.qb } };
    v.touch = { { last.ta, last.tb } };
    return v;
  };
  refineByCentroids(*domain, mesh, Options, Size, ball,
    [&]() {
      balls.push_back(last);
      solved.push_back(true);
    },
    where());
  // The pair: the faces touched on either side (every face, for the ellipsoid); the
  // coverage check counts both sides' footprints on their union.
  std::set<int> faces;
  for (const SheetBall& s : balls)
    if (s.a >= 0)
    {
      faces.insert(s.a);
      faces.insert(s.b);
    }
  const std::vector<int> all(faces.begin(), faces.end());
  mesh.members = { { all, all } };
  mesh.generators = { { all.empty() ? -1 : all.front(), all.empty() ? -1 : all.back() } };
  return mesh;
}

} // namespace

MedialSheetMesh interpolateRimSheet(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
  const SheetBorderCurve& rim, const SheetOptions& options)
{
  return RimSheetBuilder(boundary, generators, rim, options).run();
}

std::vector<SheetBorderCurve> seamlessRims(const MAT3D& mat)
{
  std::vector<SheetBorderCurve> out;
  if (!mat.seams.empty())
    return out;
  for (const MAT3DSkeletalEdge& rim : mat.skeletalEdges)
  {
    if (rim.startNode != rim.endNode || rim.vertex >= 0)
      return {};
    SheetBorderCurve curve;
    for (size_t i = 0; i < rim.balls.size(); ++i)
    {
      curve.centres.push_back(rim.balls[i].x);
      curve.radii.push_back(rim.balls[i].r);
      curve.ids.push_back(static_cast<int>(i));
      curve.touches.push_back(rim.balls[i].touches.empty() ? Vec3(Vec3::Constant(NAN)) : rim.balls[i].touches.front());
    }
    out.push_back(std::move(curve));
  }
  return out;
}

std::vector<SheetBorderCurve> seamlessRims(const MedialComplex& mat)
{
  std::vector<SheetBorderCurve> out;
  for (const MedialElement& e : mat.elements)
  {
    if (e.type == MedialElementType::Seam)
      return {};
    if (e.type != MedialElementType::SkeletalEdge)
      continue;
    if (e.points.size() < 4 || e.points.front() != e.points.back())
      return {};
    SheetBorderCurve curve;
    for (int id : e.points)
    {
      const MedialPoint3D& p = mat.points[id];
      if (p.touches.size() != 1)
        return {}; // a rim at a vertex, or one whose touches were not given
      curve.centres.push_back(p.x);
      curve.radii.push_back(p.radius);
      curve.ids.push_back(id);
      curve.touches.push_back(p.touches.front());
    }
    out.push_back(std::move(curve));
  }
  return out;
}

} // namespace exactmat

#include "CapSheet.h"

#include "common/Format.h"
#include "common/InputError.h"
#include "geometry/ClosestPoint.h"
#include "geometry/DomainTriangulation.h"
#include "sheets/CentroidRefinement.h"
#include "mat3d/CentreCurve.h"
#include "mat3d/PatchBoundary.h"

#include <algorithm>
#include <functional>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <set>

namespace exactmat
{

namespace
{

// A ball of the sheet: touching the cap at `w` (plane coordinates) and the canal face at
// `foot` (on face `face`, parameters `qFoot`).
struct CapBall
{
  Vec2 w = Vec2::Zero();
  Vec3 x = Vec3::Zero(), touch = Vec3::Zero(), foot = Vec3::Zero();
  Vec2 qFoot = Vec2::Zero();
  double r = 0.0;
  int face = -1;
};

// Where a ball touches the canal face: the face, its parameters there, the point.
struct CanalFoot
{
  int face = -1;
  Vec2 q = Vec2::Zero();
  Vec3 point = Vec3::Zero();
};

class CapSheetBuilder
{
public:
  CapSheetBuilder(const Boundary3D& boundary, const std::vector<Generator3D>& generators, const CapEnd& end,
    const SheetOptions& options)
    : B(boundary)
    , G(generators)
    , End(end)
    , Options(options)
    , Size(boundary.diagonal())
    , Settled(std::max(1e-13, 64.0 * boundary.userFrame().inputRounding()) * boundary.diagonal())
  {
    for (const auto& face : B.faces())
      FaceBoxes.push_back(face.patch.boundingBox());
    if (!Options.exact)
    {
      Own = std::make_unique<PatchBoundary>(B);
      Options.exact = Own.get();
    }
  }

  MedialSheetMesh run();

private:
  std::string where() const
  {
    return "the cone sheet at the end " + format(B.userPoint(End.centre)) + " of a centre curve" +
      (Cap >= 0 ? " (cap " + G[Cap].name() + ")" : "");
  }
  int faceThrough(const Vec3& p, bool planar) const;
  double canalDistance(const Vec3& x, CanalFoot& foot, bool local) const;
  bool emptyBall(const Vec3& x, double radius) const;
  bool solve(const Vec2& w, double guess, const CanalFoot* seed, CapBall& ball) const;
  std::vector<SheetVertex> border();
  std::vector<double> samples(const std::function<Vec3(double)>& curve, double t1) const;
  std::vector<SheetVertex> smoothEdgeBorder(const Vec3& from);

  const Boundary3D& B;
  const std::vector<Generator3D>& G;
  const CapEnd& End;
  SheetOptions Options;
  double Size;
  std::unique_ptr<PatchBoundary> Own;
  double Settled; ///< a Newton step on a face this short has converged (the input's rounding)
  int Cap = -1;
  std::vector<int> CapSide;  // the cap's faces (coplanar pieces)
  std::vector<int> Canal;    // the faces the end's circle lies on
  std::vector<Box3> CanalBoxes;
  std::vector<Box3> FaceBoxes; // every face's
};

// The face (planar or curved, as asked) a boundary point lies on, nearest first; −1 if none.
int CapSheetBuilder::faceThrough(const Vec3& p, bool planar) const
{
  int best = -1;
  double nearest = 1e-7 * Size;
  for (int f = 0; f < static_cast<int>(B.faces().size()); ++f)
    if (G[f].planar() == planar)
      if (const double d = G[f].distance(p); d <= nearest)
      {
        nearest = d;
        best = f;
      }
  return best;
}

// The distance from x to the canal face (the nearest of its pieces) and where. `local`:
// from `foot` as it is (a neighbour's foot, or the last step's), Newton on its face when it
// settles inside that face's square (a foot on its border may have a nearer one across it);
// else the global search on every piece.
double CapSheetBuilder::canalDistance(const Vec3& x, CanalFoot& foot, bool local) const
{
  if (local && foot.face >= 0 && !G[foot.face].planar())
    if (const std::optional<PatchFootpoint> f = localFootpoint(B.faces()[foot.face].patch, x, foot.q, Settled);
        f && !f->onBoundary)
    {
      foot.q = Vec2(f->u, f->v);
      foot.point = f->point;
      return f->distance;
    }
  double best = INFINITY;
  for (size_t k = 0; k < Canal.size(); ++k)
  {
    const int f = Canal[k];
    if (distanceToBox(CanalBoxes[k], x) >= best)
      continue;
    CanalFoot here;
    here.face = f;
    if (G[f].planar())
    {
      here.point = G[f].nearestPoint(x);
      here.q = G[f].parameterOf(here.point);
    }
    else
    {
      const PatchFootpoint p = closestPoint(B.faces()[G[f].entity()].patch, x);
      here.point = p.point;
      here.q = Vec2(p.u, p.v);
    }
    if (const double d = (here.point - x).norm(); d < best)
    {
      best = d;
      foot = here;
    }
  }
  return best;
}

// Whether no face comes within `radius` of x: a decision, each face's box first, curved
// faces by the signs of their Bernstein coefficients (patchComesWithin) — cheaper than the
// distance, whose search near the axis meets a circle of minima on the canal face.
bool CapSheetBuilder::emptyBall(const Vec3& x, double radius) const
{
  for (int f = 0; f < static_cast<int>(B.faces().size()); ++f)
  {
    if (distanceToBox(FaceBoxes[f], x) >= radius)
      continue;
    if (G[f].planar() ? G[f].distance(x) < radius : patchComesWithin(B.faces()[f].patch, x, radius))
      return false;
  }
  return true;
}

// The ball touching the cap at w whose distance from the canal face is its radius: the
// root of d(S + r·N) − r, which does not increase with r (d is 1-Lipschitz): bracketed
// from 0, then Newton kept inside the bracket. With a `seed` (a neighbour's foot) the
// canal's distance is followed locally (canalDistance); the caller checks the ball empty,
// which a foot that is not the nearest fails.
bool CapSheetBuilder::solve(const Vec2& w, double guess, const CanalFoot* seed, CapBall& ball) const
{
  const Touch3D t = G[Cap].evaluate(w);
  ball.w = w;
  ball.touch = t.point;
  CanalFoot foot;
  if (seed)
    foot = *seed;
  auto value = [&](double r) { return canalDistance(t.point + r * t.normal, foot, seed != nullptr) - r; };
  // Newton from the guess (the neighbours' radius: two or three steps), kept inside the
  // bracket found on the way; doubling while no upper end is known.
  double lo = 0.0, hi = INFINITY;
  double r = guess > 0.0 ? guess : 1e-6 * Size;
  for (int it = 0; it < 200; ++it)
  {
    const double f = value(r);
    if (!std::isfinite(f))
      return false;
    if (std::abs(f) <= 1e-15 * Size)
      break;
    (f > 0.0 ? lo : hi) = r;
    if (hi - lo <= 1e-15 * Size)
      break;
    const double slope = (t.point + r * t.normal - foot.point).normalized().dot(t.normal) - 1.0;
    double next = slope < -1e-12 ? r - f / slope : NAN;
    if (!(next > lo && next < hi))
      next = std::isinf(hi) ? 2.0 * r : 0.5 * (lo + hi);
    r = next;
  }
  ball.r = r;
  ball.x = t.point + r * t.normal;
  ball.face = foot.face;
  ball.foot = foot.point;
  ball.qFoot = foot.q;
  return std::isfinite(r) && foot.face >= 0;
}

// Parameters along `curve` from 0 to t1 (both included) whose chords are within a quarter
// of the tolerance and no longer than maxEdge.
std::vector<double> CapSheetBuilder::samples(const std::function<Vec3(double)>& curve, double t1) const
{
  const double chord = 0.25 * Options.tolerance * Size, longest = Options.maxEdge * Size;
  std::vector<double> out{ 0.0 };
  std::function<void(double, double, int)> split = [&](double t0, double t2, int depth) {
    const Vec3 a = curve(t0), b = curve(t2), m = curve(0.5 * (t0 + t2));
    const Vec3 e = b - a;
    const double u = std::clamp((m - a).dot(e) / std::max(e.squaredNorm(), 1e-300), 0.0, 1.0);
    if (depth < 16 && ((a + u * e - m).norm() > chord || e.norm() > longest || depth < 2))
    {
      split(t0, 0.5 * (t0 + t2), depth + 1);
      split(0.5 * (t0 + t2), t2, depth + 1);
    }
    else
      out.push_back(t2);
  };
  split(0.0, t1, 0);
  return out;
}

// The border beside a fillet: where the cap's convex edges with the canal face end at
// `from`, the canal face goes on tangentially as another face (a fillet's arc ends where
// the fillet meets the faces it rounds), and the sheet goes on as that face's sheet with
// the cap. Its border there is the curve of balls touching the cap and that smooth edge:
// at the edge's point e with the canal's normal n (the ball side), the ball touching the
// cap plane (point p, normal m into the solid) has r = (e − p)·m / (1 − n·m) — from 0 at
// `from` up to the apex, where e is on the end's circle of contact (bisected on the edge).
// The border vertices from `from` (excluded) to the apex (included), the apex's ball the
// end's.
std::vector<SheetVertex> CapSheetBuilder::smoothEdgeBorder(const Vec3& from)
{
  const double join = 1e-7 * Size;
  const Touch3D plane = G[Cap].evaluate(G[Cap].parameterOf(End.capTouch));
  for (const Edge3D& edge : B.edges())
  {
    if (edge.kind != VertexKind::Smooth)
      continue;
    const bool aCanal = std::count(Canal.begin(), Canal.end(), edge.faceA) > 0;
    const bool bCanal = std::count(Canal.begin(), Canal.end(), edge.faceB) > 0;
    if (aCanal == bCanal)
      continue;
    const int canal = aCanal ? edge.faceA : edge.faceB;
    const BezierCurve side = B.faces()[edge.faceA].patch.side(edge.sideA);
    const bool forward = (side.startPoint() - from).norm() <= join;
    if (!forward && (side.endPoint() - from).norm() > join)
      continue;
    // The ball over the edge's point at t (0 at `from`): centre, radius, the point.
    struct EdgeBall
    {
      Vec3 x, e;
      double r;
    };
    auto at = [&](double t) {
      EdgeBall b;
      b.e = side.evaluate(forward ? t : 1.0 - t);
      const Vec3 n = G[canal].evaluate(G[canal].parameterOf(b.e)).normal;
      const double across = 1.0 - n.dot(plane.normal);
      b.r = across > 1e-12 ? (b.e - plane.point).dot(plane.normal) / across : INFINITY;
      b.x = b.e + b.r * n;
      return b;
    };
    if (!(at(1.0).r >= End.radius))
      fail("3D MAT sheets: ", where(), ": the smooth edge of ", G[canal].name(), " from ", format(B.userPoint(from)),
        " ends before its balls reach the centre curve's end");
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < 60; ++it)
    {
      const double mid = 0.5 * (lo + hi);
      (at(mid).r < End.radius ? lo : hi) = mid;
    }
    const double top = 0.5 * (lo + hi);
    if ((at(top).x - End.centre).norm() > 1e-6 * Size)
      fail("3D MAT sheets: ", where(), ": the balls along the smooth edge of ", G[canal].name(), " from ",
        format(B.userPoint(from)), " reach radius ", End.radius, " at ", format(B.userPoint(at(top).x)),
        ", not at the centre curve's end");
    // (Sampled by the balls' centres: the border's shape in the sheet.)
    const std::vector<double> ts = samples([&](double t) { return at(t).x; }, top);
    std::vector<SheetVertex> out;
    for (size_t k = 1; k + 1 < ts.size(); ++k)
    {
      const EdgeBall b = at(ts[k]);
      if (!emptyBall(b.x, b.r * (1.0 - 1e-7) - 1e-12 * Size))
        fail("3D MAT sheets: ", where(), ": its ball at ", format(B.userPoint(b.x)),
          " beside the smooth edge of ", G[canal].name(), " reaches another face (not supported yet)");
      SheetVertex v;
      v.x = b.x;
      v.r = b.r;
      const Vec3 capFoot = b.x - b.r * plane.normal;
      v.touch = { { capFoot, b.e } };
      v.q = { { G[Cap].parameterOf(capFoot), G[canal].parameterOf(b.e) } };
      v.domain = v.q[0];
      v.border = true;
      out.push_back(v);
    }
    SheetVertex apex;
    apex.x = End.centre;
    apex.r = End.radius;
    apex.touch = { { End.capTouch, End.circleTouch } };
    apex.q = { { G[Cap].parameterOf(End.capTouch), Vec2::Zero() } };
    apex.domain = apex.q[0];
    apex.source = End.id;
    apex.border = true; // (where the sheet meets the centre curve: its ball touches a circle)
    out.push_back(apex);
    return out;
  }
  fail("3D MAT sheets: ", where(), ": its cap's convex edges with the canal face end at ", format(B.userPoint(from)),
    ", where the canal face meets no other face smoothly: the sheet reaches more than the canal face there (not "
    "supported yet)");
}

// The cap's border loop: the sides of its faces that are convex edges with the canal face
// (radius 0), sampled within the tolerance and chained end to end — a closed loop around
// the apex (a shaft's flat end), or an open chain whose ends are closed through the apex
// along the smooth edges where the canal face ends (a fillet's: smoothEdgeBorder).
std::vector<SheetVertex> CapSheetBuilder::border()
{
  std::map<std::pair<int, int>, int> edgeAt; // (face, side) → edge
  for (int e = 0; e < static_cast<int>(B.edges().size()); ++e)
  {
    edgeAt[{ B.edges()[e].faceA, B.edges()[e].sideA }] = e;
    edgeAt[{ B.edges()[e].faceB, B.edges()[e].sideB }] = e;
  }
  std::vector<Vec3List> pieces;
  for (int f : CapSide)
    for (int s = 0; s < 4; ++s)
    {
      const BezierCurve side = B.faces()[f].patch.side(s);
      if ((side.startPoint() - side.endPoint()).norm() <= 1e-12 * Size &&
        (side.evaluate(0.5) - side.startPoint()).norm() <= 1e-12 * Size)
        continue; // a collapsed side (a triangle's)
      const auto it = edgeAt.find({ f, s });
      if (it == edgeAt.end())
        fail("3D MAT sheets: ", where(), ": side ", s, " of ", G[f].name(), " has no neighbour");
      const Edge3D& edge = B.edges()[it->second];
      const int other = edge.faceA == f ? edge.faceB : edge.faceA;
      // (The cap's other sides are beyond the sheet: a fillet's cap is the whole face.)
      if (edge.kind != VertexKind::Convex || !std::count(Canal.begin(), Canal.end(), other))
        continue;
      Vec3List points;
      for (double t : samples([&side](double t) { return side.evaluate(t); }, 1.0))
        points.push_back(side.evaluate(t));
      pieces.push_back(std::move(points));
    }
  if (pieces.empty())
    fail("3D MAT sheets: ", where(), ": the cap has no convex edge with the canal face");
  // Chained: each piece's end is the next one's start (either way round).
  Vec3List chain = pieces.front();
  std::vector<bool> used(pieces.size(), false);
  used[0] = true;
  const double join = 1e-7 * Size;
  for (size_t n = 1; n < pieces.size(); ++n)
  {
    bool found = false;
    for (int end = 0; end < 2 && !found; ++end)
    {
      for (size_t k = 0; k < pieces.size() && !found; ++k)
      {
        if (used[k])
          continue;
        Vec3List piece = pieces[k];
        if ((piece.back() - chain.back()).norm() <= join)
          std::reverse(piece.begin(), piece.end());
        if ((piece.front() - chain.back()).norm() > join)
          continue;
        chain.insert(chain.end(), piece.begin() + 1, piece.end());
        used[k] = found = true;
      }
      if (!found)
        std::reverse(chain.begin(), chain.end()); // (then try the chain's other end)
    }
    if (!found)
      fail("3D MAT sheets: ", where(), ": the cap's convex edges with the canal face do not form one chain (a cap "
        "with holes is not supported)");
  }
  std::vector<SheetVertex> loop;
  const bool closed = (chain.back() - chain.front()).norm() <= join;
  if (closed)
    chain.pop_back();
  for (const Vec3& p : chain)
  {
    SheetVertex v;
    v.x = p;
    v.r = 0.0;
    v.touch = { { p, p } };
    v.q = { { G[Cap].parameterOf(p), Vec2::Zero() } };
    v.domain = v.q[0];
    v.border = v.convexEdge = true;
    loop.push_back(v);
  }
  if (closed)
    return loop;
  // Open: on from its end up to the apex, and down from the apex to its start.
  std::vector<SheetVertex> up = smoothEdgeBorder(chain.back());
  std::vector<SheetVertex> down = smoothEdgeBorder(chain.front());
  down.pop_back(); // (the apex, once)
  std::reverse(down.begin(), down.end());
  loop.insert(loop.end(), up.begin(), up.end());
  loop.insert(loop.end(), down.begin(), down.end());
  return loop;
}

MedialSheetMesh CapSheetBuilder::run()
{
  Cap = faceThrough(End.capTouch, true);
  if (Cap < 0)
    fail("3D MAT sheets: ", where(), ": its ball touches no planar face besides its circle (curved caps are not "
      "supported yet)");
  CapSide = sheetSide(B, G, Cap);
  const int circleFace = faceThrough(End.circleTouch, false);
  if (circleFace < 0)
    fail("3D MAT sheets: ", where(), ": its circle of contact is on no curved face");
  std::set<int> canal{ circleFace };
  const Vec3List circle =
    contactCircle(G[circleFace], G[circleFace].parameterOf(End.circleTouch), End.centre, 64);
  for (const Vec3& p : circle)
    for (int f = 0; f < static_cast<int>(B.faces().size()); ++f)
      if (!G[f].planar() && !canal.count(f) && G[f].distance(p) <= 1e-7 * Size)
        canal.insert(f);
  Canal.assign(canal.begin(), canal.end());
  for (int f : Canal)
    CanalBoxes.push_back(B.faces()[f].patch.boundingBox());
  const std::vector<SheetVertex> loop = border();
  std::vector<Vec2> domainLoop;
  for (const SheetVertex& v : loop)
    domainLoop.push_back(v.domain);
  std::unique_ptr<DomainTriangulation> domain;
  try
  {
    domain = std::make_unique<DomainTriangulation>(std::vector<std::vector<Vec2>>{ domainLoop });
  }
  catch (const InputError& e)
  {
    fail("3D MAT sheets: ", where(), ": the cap's border cannot be triangulated (", e.what(), ")");
  }
  MedialSheetMesh mesh;
  mesh.vertices = loop;
  mesh.loops = 1;
  mesh.loopSizes = { static_cast<int>(loop.size()) };
  // The apex: the centre curve's end, a vertex of the sheet — on its border beside a
  // fillet, else inside the loop of convex edges.
  for (size_t k = 0; k < loop.size(); ++k)
    if (loop[k].source == End.id)
      mesh.apex = static_cast<int>(k);
  if (mesh.apex < 0)
  {
    const Vec2 apex = G[Cap].parameterOf(End.capTouch);
    if (domain->insert(apex) != static_cast<int>(mesh.vertices.size()))
      fail("3D MAT sheets: ", where(), ": its apex is not inside the cap's border");
    SheetVertex v;
    v.x = End.centre;
    v.r = End.radius;
    v.touch = { { End.capTouch, End.circleTouch } };
    v.q = { { apex, Vec2::Zero() } };
    v.domain = apex;
    v.source = End.id;
    v.border = true; // (where the sheet meets the centre curve: its ball touches a circle)
    mesh.apex = static_cast<int>(mesh.vertices.size());
    mesh.vertices.push_back(v);
  }
  Vec3 middle = Vec3::Zero();
  for (const Vec3& p : circle)
    middle += p;
  middle /= static_cast<double>(circle.size());
  mesh.apexCircleCentre = middle;
  mesh.apexCircleAxis = (circle[16] - circle[0]).cross(circle[32] - circle[0]).normalized();
  mesh.apexCircleRadius = (circle[0] - middle).norm();
  // (Within a longest edge of the apex — a quarter of its radius at most: farther out the
  // footprint-edge test resolves the touches' angles round the circle.)
  mesh.apexReach = std::max(Options.tolerance * Size, std::min(Options.maxEdge * Size, 0.25 * End.radius));
  // Each vertex's canal foot (the border's and the apex's: none), to start its
  // neighbours' from.
  std::vector<CanalFoot> feet(mesh.vertices.size());
  CanalFoot last;
  auto ball = [&](const Vec2& w, const std::array<int, 3>& t) {
    const SheetVertex &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const Vec3 linear = (a.x + b.x + c.x) / 3.0;
    const CanalFoot* seed = nullptr;
    for (int k : t)
      if (!seed && feet[k].face >= 0)
        seed = &feet[k];
    // Empty of the whole boundary (the canal face and the cap touch it by construction):
    // anything nearer is a part of the MAT this sheet does not model — or, solved from a
    // neighbour's foot, a nearer foot of the canal face itself: then solved again from the
    // global search.
    auto empty = [&](const CapBall& s) { return emptyBall(s.x, s.r * (1.0 - 1e-7) - 1e-12 * Size); };
    CapBall s;
    bool solved = solve(w, (a.r + b.r + c.r) / 3.0, seed, s);
    if (seed && !(solved && empty(s)))
      solved = solve(w, (a.r + b.r + c.r) / 3.0, nullptr, s);
    if (!solved)
      fail("3D MAT sheets: ", where(), ": no ball touches the cap and the canal face over ",
        format(B.userPoint(linear)));
    if (!empty(s))
      fail("3D MAT sheets: ", where(), ": its ball at ", format(B.userPoint(s.x)),
        " reaches another face (a seam crosses the cap's sheet: not supported yet)");
    SheetVertex v;
    v.x = s.x;
    v.r = s.r;
    v.q = { { w, s.qFoot } };
    v.touch = { { s.touch, s.foot } };
    last = { s.face, s.qFoot, s.foot };
    return v;
  };
  refineByCentroids(*domain, mesh, Options, Size, ball, [&]() { feet.push_back(last); }, where());
  mesh.members = { { CapSide, Canal } };
  mesh.generators = { { CapSide.front(), Canal.front() } };
  mesh.parameterisedBy = 0;
  return mesh;
}

} // namespace

namespace
{
// The distinct points of `touches` (within 1e-9 of the radius: a cap tiled into pieces
// that meet at the apex — a CAD cap cut by the 2D MAT's chords — has each piece touched
// there, at one point up to rounding).
Vec3List distinctTouches(const Vec3List& touches, double radius)
{
  Vec3List out;
  for (const Vec3& t : touches)
    if (std::none_of(out.begin(), out.end(), [&](const Vec3& o) { return (o - t).norm() <= 1e-9 * radius; }))
      out.push_back(t);
  return out;
}
} // namespace

namespace
{
// The cap end of a centre curve whose end ball (centre x, radius r) touches `touches`, the
// circle of contact's first, the curve running along `along` there: the touches off the
// circle — off the plane across the curve through its first touch; a fillet's spine end
// touches the faces beside the fillet too, at the ends of its arc — must be one point, on a
// planar face (the cap). Faces the ball's record leaves out (a complex read back keeps
// three touches) are asked: every planar face at the ball's radius.
// The direction of a polyline at its start, from the first of `points` away from it (an end
// may be recorded twice).
Vec3 directionAtStart(const Vec3List& points)
{
  for (size_t k = 1; k < points.size(); ++k)
    if (const Vec3 d = points[k] - points[0]; d.norm() > 1e-12 * std::max(1.0, points[0].norm()))
      return d;
  return Vec3::Zero();
}

std::optional<CapEnd> capEndOf(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
  const Vec3& x, double r, const Vec3& along, Vec3List touches, int id)
{
  const Vec3 axis = along.normalized();
  if (touches.empty() || !(axis.norm() > 0.5) || !(r > 0.0))
    return std::nullopt;
  const double size = boundary.diagonal();
  for (int f = 0; f < static_cast<int>(boundary.faces().size()); ++f)
    if (generators[f].planar())
      if (const Vec3 p = generators[f].nearestPoint(x); std::abs((p - x).norm() - r) <= 1e-6 * r)
        touches.push_back(p);
  const double level = (touches.front() - x).dot(axis);
  Vec3List off;
  for (const Vec3& t : touches)
    if (std::abs((t - x).dot(axis) - level) > 1e-6 * r)
      off.push_back(t);
  off = distinctTouches(off, r);
  // (Inside the cap, off every curved face: at a rounded box's corner the ball touches
  // the faces the blend joins at the corners of the blend's octant, which is no cap.)
  const auto faces = generators.begin() + static_cast<long>(boundary.faces().size());
  if (off.size() != 1 ||
    std::none_of(generators.begin(), faces,
      [&](const Generator3D& g) { return g.planar() && g.distance(off.front()) <= 1e-7 * size; }) ||
    std::any_of(generators.begin(), faces,
      [&](const Generator3D& g) { return !g.planar() && g.distance(off.front()) <= 1e-7 * size; }))
    return std::nullopt;
  return CapEnd{ x, r, touches.front(), off.front(), id };
}
} // namespace

std::vector<CapEnd> capEnds(const MAT3D& mat, const Boundary3D& boundary, const std::vector<Generator3D>& generators)
{
  std::vector<CapEnd> out;
  for (const MAT3DCentreCurve& curve : mat.centreCurves)
  {
    const size_t n = curve.balls.size();
    if (n < 2)
      continue;
    for (int end = 0; end < 2; ++end)
    {
      const int node = end == 0 ? curve.startNode : curve.endNode;
      const MAT3DNode& at = mat.nodes[node];
      if (!at.circleEnd || at.loopPoint ||
        std::any_of(out.begin(), out.end(), [node](const CapEnd& e) { return e.id == node; }))
        continue;
      Vec3List centres;
      for (size_t k = 0; k < n; ++k)
        centres.push_back(curve.balls[end == 0 ? k : n - 1 - k].x);
      const Vec3 along = directionAtStart(centres);
      if (const auto cap = capEndOf(boundary, generators, at.ball.x, at.ball.r, along, at.ball.touches, node))
        out.push_back(*cap);
    }
  }
  return out;
}

std::vector<CapEnd> capEnds(const MedialComplex& mat, const Boundary3D& boundary, const std::vector<Generator3D>& generators)
{
  std::vector<CapEnd> out;
  for (const MedialElement& e : mat.elements)
  {
    const size_t n = e.points.size();
    if (e.type != MedialElementType::CentreCurve || n < 2 || e.points.front() == e.points.back())
      continue;
    for (int end = 0; end < 2; ++end)
    {
      const int id = end == 0 ? e.points.front() : e.points.back();
      const MedialPoint3D& p = mat.points[id];
      if (p.type != MedialPoint3DType::CircleCentre ||
        std::any_of(out.begin(), out.end(), [id](const CapEnd& c) { return c.id == id; }))
        continue;
      Vec3List centres;
      for (size_t k = 0; k < n; ++k)
        centres.push_back(mat.points[e.points[end == 0 ? k : n - 1 - k]].x);
      const Vec3 along = directionAtStart(centres);
      if (const auto cap = capEndOf(boundary, generators, p.x, p.radius, along, p.touches, id))
        out.push_back(*cap);
    }
  }
  return out;
}

void dropCapGroups(std::vector<SheetGroup>& groups, const std::vector<MedialSheetMesh>& capSheets)
{
  auto within = [](const std::vector<int>& side, const std::vector<int>& members) {
    return std::all_of(side.begin(), side.end(),
      [&](int g) { return std::find(members.begin(), members.end(), g) != members.end(); });
  };
  groups.erase(std::remove_if(groups.begin(), groups.end(),
                 [&](const SheetGroup& g) {
                   return g.traced.empty() &&
                     std::any_of(capSheets.begin(), capSheets.end(), [&](const MedialSheetMesh& m) {
                       return !m.triangles.empty() &&
                         ((within(g.a, m.members[0]) && within(g.b, m.members[1])) ||
                           (within(g.b, m.members[0]) && within(g.a, m.members[1])));
                     });
                 }),
    groups.end());
}

MedialSheetMesh interpolateCapSheet(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
  const CapEnd& end, const SheetOptions& options)
{
  return CapSheetBuilder(boundary, generators, end, options).run();
}

} // namespace exactmat

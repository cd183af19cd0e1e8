#include "sheets/SheetCoverage.h"

#include "common/InputError.h"
#include "geometry/ClosestPoint.h"
#include "sheets/SheetSide.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>

namespace exactmat
{

namespace
{

// The sub-triangles a curved footprint is cut into along each side (their corners are
// projected onto the faces): the measured area converges like (h·κ / n)², and n = 4 keeps a
// random ellipsoid's rim sheet within 3e-4 of its faces' area (n = 1, the flat triangles:
// 5e-3 short).
constexpr int FootprintCuts = 4;

// A planar bilinear (or linear) patch: its flat triangles are exact.
bool flatPatch(const BezierPatch& patch, double diagonal)
{
  const Vec3 c00 = patch.evaluate(0, 0), c10 = patch.evaluate(1, 0), c01 = patch.evaluate(0, 1);
  return patch.degreeU() <= 1 && patch.degreeV() <= 1 &&
    std::abs((c10 - c00).cross(c01 - c00).normalized().dot(patch.evaluate(1, 1) - c00)) <= 1e-14 * diagonal;
}

// |S_u × S_v| integrated over n × n cells of the patch's parameter square, Gauss–Legendre
// with 3 × 3 points on each.
double patchArea(const BezierPatch& patch, int n)
{
  const double g[3] = { 0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6) };
  const double w[3] = { 5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0 };
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
        {
          const SurfaceDerivatives d = patch.derivatives((i + g[a]) / n, (j + g[b]) / n);
          sum += w[a] * w[b] * d.su.cross(d.sv).norm();
        }
  return sum / (static_cast<double>(n) * n);
}


// A point of a face: the face and its parameters there.
struct OnFace
{
  int face = -1;
  Vec2 q = Vec2::Zero();
};

// Projects points near the faces of one side of a sheet onto them: Newton from a nearby
// known point of a face (a footprint's corner), the global footpoint search only where that
// does not settle inside the face (across a patch border, at a pole).
class SideProjector
{
public:
  SideProjector(const Boundary3D& boundary, const std::vector<int>& faces)
    : B(boundary)
    , Faces(faces)
    , Near(1e-8 * boundary.diagonal())
    , Settled(std::max(1e-13, 64.0 * boundary.userFrame().inputRounding()) * boundary.diagonal())
  {
    for (int f : faces)
      Boxes.push_back(boundary.faces()[f].patch.boundingBox());
    Last.assign(faces.size(), Vec2(0.5, 0.5));
  }

  Vec3 evaluate(int face, const Vec2& q) const { return B.faces()[face].patch.evaluate(q.x(), q.y()); }

  // Where touch x lies: the face and parameters, from the sheet's own parameters `hint`
  // when a face takes x there (most sheets are parameterised by the face they touch).
  // Else Newton on each face whose box holds x, from the hint (clamped to the face), the
  // last touch located on that face (the sheet's vertices come in runs) and the face's
  // middle; the footpoint search only when none lands on x.
  OnFace locate(const Vec3& x, const Vec2& hint)
  {
    if (hint.allFinite() && hint.minCoeff() >= 0.0 && hint.maxCoeff() <= 1.0)
      for (int f : Faces)
        if ((B.faces()[f].patch.evaluate(hint.x(), hint.y()) - x).norm() <= Near)
          return remember({ f, hint });
    const Vec2 clamped = hint.allFinite() ? Vec2(hint.cwiseMax(0.0).cwiseMin(1.0)) : Vec2(0.5, 0.5);
    for (size_t k = 0; k < Faces.size(); ++k)
    {
      if (distanceToBox(Boxes[k], x) > Near)
        continue;
      for (const Vec2& seed : { clamped, Last[k], Vec2(0.5, 0.5) })
        if (const std::optional<Vec3> foot = newton(x, { Faces[k], seed }, &Found);
            foot && (*foot - x).norm() <= Near)
          return remember({ Faces[k], Found }, k);
    }
    return remember(nearest(x, Near).value_or(OnFace()));
  }

  // The point of the side's faces nearest y (a point of a flat footprint triangle, within
  // `reach` of them), Newton started from each of `starts` in turn, then on the other faces
  // within reach (a footprint whose corners are on one patch of a tiled surface reaching into
  // the next); the footpoint search when none settles inside a face; y itself when nothing
  // is found that near.
  Vec3 project(const Vec3& y, const std::array<OnFace, 3>& starts, double reach) const
  {
    for (const OnFace& s : starts)
      if (s.face >= 0)
        if (const std::optional<Vec3> p = newton(y, s))
          return *p;
    for (size_t k = 0; k < Faces.size(); ++k)
      if (Faces[k] != starts[0].face && Faces[k] != starts[1].face && Faces[k] != starts[2].face &&
        distanceToBox(Boxes[k], y) <= reach)
        if (const std::optional<Vec3> p = newton(y, { Faces[k], Last[k] }))
          return *p;
    const std::optional<OnFace> found = nearest(y, reach);
    return found ? B.faces()[found->face].patch.evaluate(found->q.x(), found->q.y()) : y;
  }

private:
  // The foot of y on one face by Newton from `start` (localFootpoint), or nothing.
  std::optional<Vec3> newton(const Vec3& y, const OnFace& start, Vec2* at = nullptr) const
  {
    const std::optional<PatchFootpoint> f = localFootpoint(B.faces()[start.face].patch, y, start.q, Settled);
    if (!f)
      return std::nullopt;
    if (at)
      *at = Vec2(f->u, f->v);
    return f->point;
  }

  std::optional<OnFace> nearest(const Vec3& y, double reach) const
  {
    std::optional<OnFace> best;
    double nearest = reach;
    for (size_t k = 0; k < Faces.size(); ++k)
    {
      if (distanceToBox(Boxes[k], y) > nearest)
        continue;
      const std::vector<PatchFootpoint> feet = patchFootpoints(B.faces()[Faces[k]].patch, y, nearest);
      if (!feet.empty() && feet.front().distance <= nearest)
      {
        nearest = feet.front().distance;
        best = OnFace{ Faces[k], Vec2(feet.front().u, feet.front().v) };
      }
    }
    return best;
  }

  OnFace remember(const OnFace& found, size_t k = static_cast<size_t>(-1))
  {
    if (k == static_cast<size_t>(-1))
      k = static_cast<size_t>(std::find(Faces.begin(), Faces.end(), found.face) - Faces.begin());
    if (k < Last.size())
      Last[k] = found.q;
    return found;
  }

  const Boundary3D& B;
  const std::vector<int>& Faces;
  double Near;
  double Settled; ///< a step of Newton's on a face this short (a length) has converged
  std::vector<Box3> Boxes;
  std::vector<Vec2> Last; ///< per face: the parameters of the touch last located on it
  Vec2 Found = Vec2::Zero();
};

// The parameter planes of a solid's sheet sides, each built once (a side of sliver pieces
// of a surface of revolution matches every piece with its neighbours: dozens of closest-point
// searches). Only curved sides have one — a planar side's q are its plane's coordinates,
// straight where its face's border may be an arc — and only for sheets interpolated between
// two sides: a sheet whose sides share faces (a rim's, whose pair is every face it touches)
// carries each vertex's own face's parameters.
class SideParameterPlanes
{
public:
  SideParameterPlanes(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
    const std::vector<bool>& flat)
    : B(boundary)
    , G(generators)
    , Flat(flat)
  {
  }

  // Side k of the mesh as a parameter plane, or null.
  const SheetSide* of(const MedialSheetMesh& mesh, int k)
  {
    const std::vector<int>& members = mesh.members[k];
    const std::vector<int>& other = mesh.members[1 - k];
    const int faces = static_cast<int>(Flat.size());
    if (members.empty() || members.front() >= faces ||
      std::all_of(members.begin(), members.end(), [this](int f) { return Flat[f]; }) ||
      std::any_of(members.begin(), members.end(),
        [&other](int f) { return std::find(other.begin(), other.end(), f) != other.end(); }))
      return nullptr;
    auto [at, added] = Planes.try_emplace(members);
    if (added)
      try
      {
        at->second = std::make_unique<SheetSide>(B, G, members);
        if (!at->second->curvedFace())
          at->second.reset();
      }
      catch (const InputError&)
      {
      }
    return at->second.get();
  }

private:
  const Boundary3D& B;
  const std::vector<Generator3D>& G;
  const std::vector<bool>& Flat;
  std::map<std::vector<int>, std::unique_ptr<SheetSide>> Planes;
};

// A side's plane and, per vertex, whether its q there is valid (the surface takes the
// vertex's touch at it).
struct SideParameters
{
  SideParameters(const SheetSide* plane, const MedialSheetMesh& mesh, int k, double near)
    : side(plane)
  {
    if (!side)
      return;
    Valid.resize(mesh.vertices.size());
    for (size_t v = 0; v < Valid.size(); ++v)
      Valid[v] = (side->point(mesh.vertices[v].q[k]) - mesh.vertices[v].touch[k]).norm() <= near;
  }
  bool valid(int v) const { return side && Valid[v]; }

  const SheetSide* side;

private:
  std::vector<char> Valid;
};

// A footprint's corners on one side of its sheet: where they touch (x), their parameters
// on the side (q: SheetSide's, from the sheet) where those are valid — the side's surface
// takes the corner there — and, found only when some point is projected, the face and
// parameters that a projection starts from.
struct FootprintCorners
{
  std::array<Vec3, 3> x;
  std::array<Vec2, 3> q;
  std::array<bool, 3> valid{ { false, false, false } };
  std::array<bool, 3> onEdge{ { false, false, false } }; ///< radius 0: on a convex edge
  std::array<bool, 3> border{ { false, false, false } }; ///< on the sheet's border (or a convex edge)
  bool planar = false; ///< the side is planar: a point off its border is its own foot
  double near = 0.0;   ///< a length the rounding stays within
  bool otherPlanar = false; ///< the other side is planar too: the edge between them is straight
  std::function<OnFace(int)> located; ///< corner → where it lies (computed once per vertex)
};

// The area of the faces under the flat footprint (a, b, c): its n × n sub-triangles with
// their corners on the faces. Where a point's corners (two for a point of a side, three
// inside) have valid side parameters, it is the side's surface at their interpolation —
// footprints are then the sheet's triangles in the side's parameter plane, which tile the
// face exactly (one evaluation per point, no search). On a planar side a point is its own
// foot, except along an arc of the face's border (two corners of the sheet's border on one
// side of a patch: a convex edge, or a reflex arc the sheet turns at): that arc, from the
// corners' patch parameters (chords of a reflex arc reach into the hole it bounds). Else it
// is the flat point projected onto the faces (Newton from the corners' faces). Footprints
// that share corners share the points of their common side (each depends only on that
// side's corners), so they tile the face as the flat triangles tile the polyhedron of
// touches.
double footprintArea(const SheetSide* side, const SideProjector& projector, const FootprintCorners& c, int n)
{
  std::array<std::optional<OnFace>, 3> where;
  auto corner = [&](int a) -> const OnFace& {
    if (!where[a])
      where[a] = c.located(a);
    return *where[a];
  };
  // Two corners on one side of one face's square (a sheet's border along a convex edge,
  // where its radius is 0): the footprint's side is that curve, not the chord.
  auto alongSide = [&](int a, int b) {
    const OnFace &p = corner(a), &q = corner(b);
    if (p.face < 0 || p.face != q.face)
      return false;
    for (int k = 0; k < 2; ++k)
      for (double border : { 0.0, 1.0 })
        if (std::abs(p.q(k) - border) <= 1e-9 && std::abs(q.q(k) - border) <= 1e-9)
          return true;
    return false;
  };
  auto projected = [&](const Vec3& y, const double (&w)[3]) {
    // (The faces come within the nearest corner's distance: the corners are on them.)
    const double reach = std::min({ (y - c.x[0]).norm(), (y - c.x[1]).norm(), (y - c.x[2]).norm() }) +
      1e-12 * (c.x[1] - c.x[0]).norm();
    // Newton from the nearest corner first.
    std::array<int, 3> order{ { 0, 1, 2 } };
    std::sort(order.begin(), order.end(), [&w](int a, int b) { return w[a] > w[b]; });
    return projector.project(y, { { corner(order[0]), corner(order[1]), corner(order[2]) } }, reach);
  };
  std::vector<Vec3> p;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j)
    {
      // (Weights from whole numbers: a side's point has an exact 0.)
      const double w[3] = { static_cast<double>(n - i - j) / n, static_cast<double>(i) / n,
        static_cast<double>(j) / n };
      if (w[0] == 1.0 || w[1] == 1.0 || w[2] == 1.0)
      {
        p.push_back(w[0] == 1.0 ? c.x[0] : w[1] == 1.0 ? c.x[1] : c.x[2]);
        continue;
      }
      // The corners this point depends on: the two of its side, or all three.
      bool valid = true;
      for (int k = 0; k < 3; ++k)
        valid = valid && (w[k] == 0.0 || c.valid[k]);
      if (valid && side)
      {
        p.push_back(side->point(w[0] * c.q[0] + w[1] * c.q[1] + w[2] * c.q[2]));
        continue;
      }
      const int a = w[0] == 0.0 ? 1 : 0, b = w[2] == 0.0 ? 1 : 2; // a side's corners
      const bool onSide = w[0] == 0.0 || w[1] == 0.0 || w[2] == 0.0;
      if (onSide && c.border[a] && c.border[b] && !(c.otherPlanar && c.onEdge[a] && c.onEdge[b]) && alongSide(a, b))
      {
        const OnFace& from = corner(a);
        p.push_back(projector.evaluate(from.face, from.q + w[b] / (w[a] + w[b]) * (corner(b).q - from.q)));
        continue;
      }
      const Vec3 flat = w[0] * c.x[0] + w[1] * c.x[1] + w[2] * c.x[2];
      p.push_back(c.planar ? flat : projected(flat, w));
    }
  // Row i starts at index i(2n + 3 − i)/2.
  auto at = [n, &p](int i, int j) -> const Vec3& { return p[i * (2 * n + 3 - i) / 2 + j]; };
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j)
    {
      sum += 0.5 * (at(i + 1, j) - at(i, j)).cross(at(i, j + 1) - at(i, j)).norm();
      if (i + j + 1 < n)
        sum += 0.5 * (at(i + 1, j) - at(i + 1, j + 1)).cross(at(i, j + 1) - at(i + 1, j + 1)).norm();
    }
  return sum;
}

} // namespace

// (The error of the 3-point rule falls like the cell's size to the sixth: a rational
// quadratic settles at 4 × 4 cells; at most 64 × 64.)
double patchArea(const BezierPatch& patch)
{
  double coarse = patchArea(patch, 1);
  for (int n = 2; n <= 64; n *= 2)
  {
    const double fine = patchArea(patch, n);
    if (std::abs(fine - coarse) <= 1e-12 * fine)
      return fine;
    coarse = fine;
  }
  return coarse;
}

std::vector<FaceCoverage> sheetCoverage(const Boundary3D& boundary, const std::vector<MedialSheetMesh>& meshes,
  const std::vector<double>& footprints)
{
  const int faces = static_cast<int>(boundary.faces().size());
  const std::vector<Generator3D> generators = medialGenerators(boundary);
  const double near = 1e-8 * boundary.diagonal();
  std::vector<int> group(faces);
  for (int f = 0; f < faces; ++f)
    group[f] = f;
  std::vector<bool> flat(faces);
  std::vector<double> faceArea(faces);
  for (int f = 0; f < faces; ++f)
  {
    const BezierPatch& patch = boundary.faces()[f].patch;
    flat[f] = flatPatch(patch, boundary.diagonal());
    faceArea[f] = flat[f] ? patchArea(patch, 1) : patchArea(patch);
  }
  SideParameterPlanes planes(boundary, generators, flat);
  std::vector<double> covered(faces, 0.0);
  for (const MedialSheetMesh& mesh : meshes)
  {
    const std::array<SideParameters, 2> parameters{ { SideParameters(planes.of(mesh, 0), mesh, 0, near),
      SideParameters(planes.of(mesh, 1), mesh, 1, near) } };
    for (int k = 0; k < 2; ++k)
    {
      const std::vector<int>& members = mesh.members[k];
      if (members.empty() || members.front() >= faces)
        continue; // a reflex edge or corner: no area
      for (int f : members)
        group[f] = members.front();
      // Flat faces (planar, bilinear) take the flat footprints as they are; planar faces
      // bounded by arcs only along those arcs; curved ones everywhere.
      const bool curved = std::any_of(members.begin(), members.end(), [&flat](int f) { return !flat[f]; });
      const bool planar = std::all_of(members.begin(), members.end(), [&](int f) { return generators[f].planar(); });
      SideProjector projector(boundary, members);
      const SideParameters& here = parameters[k];
      std::vector<std::optional<OnFace>> located(curved ? mesh.vertices.size() : 0);
      auto locate = [&](int v) -> OnFace {
        if (!located[v])
          located[v] = projector.locate(mesh.vertices[v].touch[k], mesh.vertices[v].q[k]);
        return *located[v];
      };
      for (const auto& t : mesh.triangles)
      {
        int at = 3, atApex = 0;
        for (int a = 0; a < 3 && k == 1; ++a)
          if (mesh.nearApex(t[a]))
          {
            at = a;
            ++atApex;
          }
        if (atApex >= 2)
          continue; // (its touches lie on the circle: no area)
        if (at < 3)
        {
          // The apex touches a whole circle: the triangle covers the strip between the
          // circle and its other two corners' touches (b, c), from the circle's points
          // nearest them.
          const Vec3& b = mesh.vertices[t[(at + 1) % 3]].touch[1];
          const Vec3& c = mesh.vertices[t[(at + 2) % 3]].touch[1];
          auto onCircle = [&](const Vec3& p) {
            Vec3 d = p - mesh.apexCircleCentre;
            d -= mesh.apexCircleAxis * mesh.apexCircleAxis.dot(d);
            return Vec3(mesh.apexCircleCentre + mesh.apexCircleRadius * d.normalized());
          };
          const Vec3 pb = onCircle(b), pc = onCircle(c);
          covered[members.front()] += 0.5 * ((b - pb).cross(c - pb).norm() + (c - pb).cross(pc - pb).norm());
          continue;
        }
        FootprintCorners c;
        for (int a = 0; a < 3; ++a)
        {
          c.x[a] = mesh.vertices[t[a]].touch[k];
          c.q[a] = mesh.vertices[t[a]].q[k];
          c.valid[a] = here.valid(t[a]);
          c.onEdge[a] = mesh.vertices[t[a]].convexEdge || mesh.vertices[t[a]].r <= near;
          c.border[a] = c.onEdge[a] || mesh.vertices[t[a]].border;
        }
        c.planar = planar;
        c.otherPlanar = planar && std::all_of(mesh.members[1 - k].begin(), mesh.members[1 - k].end(),
          [&](int g) { return g < faces && generators[g].planar(); });
        c.near = near;
        const bool arcs = c.border[0] + c.border[1] + c.border[2] >= 2;
        if (!curved || (planar && !arcs))
        {
          covered[members.front()] += 0.5 * (c.x[1] - c.x[0]).cross(c.x[2] - c.x[0]).norm();
          continue;
        }
        c.located = [&locate, &t](int a) { return locate(t[a]); };
        covered[members.front()] += footprintArea(here.side, projector, c, FootprintCuts);
      }
    }
  }
  for (int f = 0; f < faces && f < static_cast<int>(footprints.size()); ++f)
    covered[group[f]] += footprints[f];
  std::vector<double> area(faces, 0.0);
  for (int f = 0; f < faces; ++f)
    area[group[f]] += faceArea[f];
  std::vector<FaceCoverage> out;
  for (int f = 0; f < faces; ++f)
    if (group[f] == f)
      out.push_back({ f, area[f], covered[f] });
  return out;
}

} // namespace exactmat

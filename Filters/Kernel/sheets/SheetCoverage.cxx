#include "sheets/SheetCoverage.h"

#include "geometry/ClosestPoint.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
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

// The patch's area: Gauss–Legendre (3 × 3 points) on n × n cells of its parameter square,
// |S_u × S_v| integrated.
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
  {
    for (int f : faces)
      Boxes.push_back(boundary.faces()[f].patch.boundingBox());
    Last.assign(faces.size(), Vec2(0.5, 0.5));
  }

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
  // Newton (Gauss–Newton on S(u, v) − y ⊥ S_u, S_v, kept in the face's square) on one face
  // from `start`: the foot when it settles on the face with S − y normal to it, else
  // nothing.
  std::optional<Vec3> newton(const Vec3& y, const OnFace& start, Vec2* at = nullptr) const
  {
    const BezierPatch& patch = B.faces()[start.face].patch;
    Vec2 q = start.q;
    for (int iteration = 0; iteration < 24; ++iteration)
    {
      const SurfaceDerivatives d = patch.derivatives(q.x(), q.y());
      Eigen::Matrix<double, 3, 2> J;
      J << d.su, d.sv;
      const Eigen::Matrix2d normal = J.transpose() * J;
      if (!(normal.determinant() > 1e-12 * normal.squaredNorm()))
        return std::nullopt; // a pole or a collapsed side: no unique parameters here
      const Vec2 next = (q + normal.ldlt().solve(-J.transpose() * (d.point - y))).cwiseMax(0.0).cwiseMin(1.0);
      const bool settled = (next - q).norm() <= 1e-12;
      q = next;
      if (!settled)
        continue;
      // Kept in the square, it may have settled on a side the foot lies beyond: then the
      // distance still falls outwards (S − y is not normal to the face there).
      const SurfaceDerivatives e = patch.derivatives(q.x(), q.y());
      const Vec3 r = e.point - y;
      const double tangential = std::hypot(r.dot(e.su) / e.su.norm(), r.dot(e.sv) / e.sv.norm());
      if (!(tangential <= 1e-6 * r.norm() + 1e-12 * B.diagonal()))
        return std::nullopt;
      if (at)
        *at = q;
      return e.point;
    }
    return std::nullopt;
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
  std::vector<Box3> Boxes;
  std::vector<Vec2> Last; ///< per face: the parameters of the touch last located on it
  Vec2 Found = Vec2::Zero();
};

// The area of the faces under the flat footprint (a, b, c) whose corners lie at `corners`:
// its n × n sub-triangles with their corners projected onto the faces. Footprints that
// share corners share the projected points along their common side, so they tile the face
// as the flat triangles tile the polyhedron of touches.
double footprintArea(const SideProjector& projector, const std::array<Vec3, 3>& x,
  const std::array<OnFace, 3>& corners, int n)
{
  std::vector<Vec3> p;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j)
    {
      const double s = static_cast<double>(i) / n, t = static_cast<double>(j) / n;
      const Vec3 y = x[0] + (x[1] - x[0]) * s + (x[2] - x[0]) * t;
      // (The faces come within the nearest corner's distance: the corners are on them.)
      const double reach = std::min({ (y - x[0]).norm(), (y - x[1]).norm(), (y - x[2]).norm() }) +
        1e-12 * (x[1] - x[0]).norm();
      // Newton from the nearest corner first.
      const double w[3] = { 1.0 - s - t, s, t };
      std::array<int, 3> order{ { 0, 1, 2 } };
      std::sort(order.begin(), order.end(), [&w](int a, int b) { return w[a] > w[b]; });
      p.push_back(projector.project(y, { { corners[order[0]], corners[order[1]], corners[order[2]] } }, reach));
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

std::vector<FaceCoverage> sheetCoverage(const Boundary3D& boundary, const std::vector<MedialSheetMesh>& meshes,
  const std::vector<double>& footprints)
{
  const int faces = static_cast<int>(boundary.faces().size());
  std::vector<int> group(faces);
  for (int f = 0; f < faces; ++f)
    group[f] = f;
  std::vector<bool> flat(faces);
  std::vector<double> faceArea(faces);
  for (int f = 0; f < faces; ++f)
  {
    const BezierPatch& patch = boundary.faces()[f].patch;
    flat[f] = flatPatch(patch, boundary.diagonal());
    faceArea[f] = patchArea(patch, flat[f] ? 1 : 16);
  }
  std::vector<double> covered(faces, 0.0);
  for (const MedialSheetMesh& mesh : meshes)
    for (int k = 0; k < 2; ++k)
    {
      const std::vector<int>& members = mesh.members[k];
      if (members.empty() || members.front() >= faces)
        continue; // a reflex edge or corner: no area
      for (int f : members)
        group[f] = members.front();
      const bool curved = std::any_of(members.begin(), members.end(), [&flat](int f) { return !flat[f]; });
      SideProjector projector(boundary, members);
      std::vector<OnFace> corner(curved ? mesh.vertices.size() : 0);
      for (size_t v = 0; v < corner.size(); ++v)
        corner[v] = projector.locate(mesh.vertices[v].touch[k], mesh.vertices[v].q[k]);
      for (const auto& t : mesh.triangles)
      {
        const int at = k == 1 && mesh.apex >= 0 ? static_cast<int>(std::find(t.begin(), t.end(), mesh.apex) - t.begin()) : 3;
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
        const std::array<Vec3, 3> x{ { mesh.vertices[t[0]].touch[k], mesh.vertices[t[1]].touch[k],
          mesh.vertices[t[2]].touch[k] } };
        covered[members.front()] += curved
          ? footprintArea(projector, x, { { corner[t[0]], corner[t[1]], corner[t[2]] } }, FootprintCuts)
          : 0.5 * (x[1] - x[0]).cross(x[2] - x[0]).norm();
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

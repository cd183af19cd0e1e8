#include "geometry/PatchContinuation.h"

#include "geometry/ClosestPoint.h"

#include <Eigen/Dense>

namespace exactmat
{

namespace
{
// The parameters where the surface's extension passes through x: Gauss–Newton from the
// guess, unclamped (a piece lies beyond the surface's own unit square).
bool inverse(const BezierPatch& surface, const Vec3& x, Vec2& q, double tolerance)
{
  // Gauss–Newton until the step stalls, then the residual decides: a piece of a surface
  // known only to the input's rounding meets the extension to that, not to any fraction
  // of the tolerance.
  for (int it = 0; it < 50; ++it)
  {
    const SurfaceDerivatives d = surface.derivatives(q.x(), q.y());
    const Vec3 f = d.point - x;
    Eigen::Matrix<double, 3, 2> j;
    j.col(0) = d.su;
    j.col(1) = d.sv;
    const Vec2 step = j.colPivHouseholderQr().solve(-f);
    if (!step.allFinite())
      return false;
    q += step;
    if (!q.allFinite() || q.cwiseAbs().maxCoeff() > 1e6)
      return false;
    if (step.norm() <= 1e-14 * (1.0 + q.norm()))
      break;
  }
  return (surface.evaluate(q.x(), q.y()) - x).norm() <= tolerance;
}
} // namespace

bool pieceOfSurface(const BezierPatch& surface, const BezierPatch& piece, double tolerance, ParameterMap& map)
{
  // Three corners fix the affine map; guesses from the nearest point of the surface's own
  // square (exact for corners the two share, a start on the right border for the others).
  Vec2 q[3];
  const Vec2 corners[3] = { Vec2(0, 0), Vec2(1, 0), Vec2(0, 1) };
  for (int k = 0; k < 3; ++k)
  {
    const Vec3 x = piece.evaluate(corners[k].x(), corners[k].y());
    const PatchFootpoint f = closestPoint(surface, x);
    q[k] = Vec2(f.u, f.v);
    if (!inverse(surface, x, q[k], tolerance))
      return false;
  }
  map.origin = q[0];
  map.axes.col(0) = q[1] - q[0];
  map.axes.col(1) = q[2] - q[0];
  if (!(std::abs(map.axes.determinant()) > 1e-12))
    return false;
  // The rest of the piece must follow: the far corner, the centre, the side midpoints.
  for (const Vec2& c : { Vec2(1, 1), Vec2(0.5, 0.5), Vec2(0.5, 0), Vec2(0.5, 1), Vec2(0, 0.5), Vec2(1, 0.5),
         Vec2(0.25, 0.75) })
  {
    const Vec2 s = map(c);
    if ((surface.evaluate(s.x(), s.y()) - piece.evaluate(c.x(), c.y())).norm() > tolerance)
      return false;
  }
  return true;
}

bool piecesOfOneSurface(const BezierPatch& a, const BezierPatch& b, double tolerance, ParameterMap& bInA)
{
  if (b.boundingBox().diagonal().norm() <= a.boundingBox().diagonal().norm())
    return pieceOfSurface(a, b, tolerance, bInA);
  ParameterMap aInB;
  if (!pieceOfSurface(b, a, tolerance, aInB))
    return false;
  bInA = aInB.inverted();
  return true;
}

} // namespace exactmat

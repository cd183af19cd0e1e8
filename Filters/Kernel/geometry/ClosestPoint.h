#pragma once
/// @file ClosestPoint.h
/// @brief Global closest points and all footpoints from a point to rational Bézier curves
/// and patches.
///
/// The squared distance |C(t) − P|² is stationary where f(t) = (C − P)·C' vanishes. With
/// C = A/w and D = A − P·w, f has the sign of the polynomial g = D·(D'w − Dw'), which is
/// written in Bernstein form and its roots isolated by subdivision (a sub-interval whose
/// coefficients keep one sign is discarded, one with a single sign change holds exactly
/// one root). So every local minimum is found, not just the one a Newton iteration from a
/// guess happens to reach. Patches use the same idea on the pair g_u, g_v with an interval
/// Jacobian test for uniqueness, plus the boundary curves of the patch.

#include "nurbs/BezierCurve.h"
#include "nurbs/BezierPatch.h"

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace exactmat
{

/// A local minimum of the distance from a query point to a curve.
struct CurveFootpoint
{
  double t = 0.0;        ///< curve parameter in [0,1]
  Vec3 point = Vec3::Zero();
  double distance = 0.0;
  bool atEnd = false;    ///< t is 0 or 1 and the minimum is one-sided
  bool continuum = false; ///< the whole curve is at this distance (query at an arc centre)
};

/// A local minimum of the distance from a query point to a patch.
struct PatchFootpoint
{
  double u = 0.0, v = 0.0;
  Vec3 point = Vec3::Zero();
  double distance = 0.0;
  bool onBoundary = false; ///< the minimum lies on the patch's boundary (one-sided)
  bool continuum = false;  ///< a curve or region of the patch is at this distance
};

constexpr double Unbounded = std::numeric_limits<double>::infinity();

/// Every local minimum of |C(t) − P| on t ∈ [0,1] with distance ≤ maxDistance, including
/// one-sided minima at the ends; sorted by distance. For a query at the centre of a
/// circular arc (all points equidistant) a single footpoint with `continuum` is returned;
/// "equidistant" means the stationarity polynomial vanishes to `continuumTolerance` of its
/// scale (1e-14: rounding; more for input known only to fewer digits).
std::vector<CurveFootpoint> curveFootpoints(const BezierCurve& curve, const Vec3& query,
  double maxDistance = Unbounded, double continuumTolerance = 1e-14);

/// The global closest point of the curve (the first of curveFootpoints).
CurveFootpoint closestPoint(const BezierCurve& curve, const Vec3& query);

/// True when some point of the curve lies strictly closer than `radius` to the query:
/// decided by the sign of h(t) = |A(t) − P·w(t)|² − radius²·w(t)² (degree 2p), whose
/// Bernstein coefficients bound it, with subdivision where they do not decide. Much cheaper
/// than curveFootpoints when only emptiness of a disk matters. Subdivision stops at 2^-40,
/// where the curve is within rounding of the circle: that counts as not closer.
bool curveComesWithin(const BezierCurve& curve, const Vec3& query, double radius);
/// The same test, told where the disk touches the curve (parameter `touch`, a footpoint of
/// the query): the squared distance, which has a (near) double root there, is first
/// deflated by it (outside when the quotient's least value proves it, up to degree 8), else
/// split there, so the proof that it stays above radius² near a tangency is not a 40-level
/// subdivision around a double root. The answer is the same; only the work differs.
bool curveComesWithin(const BezierCurve& curve, const Vec3& query, double radius, double touch);

/// Every local minimum of |S(u,v) − P| on [0,1]² with distance ≤ maxDistance, interior
/// and boundary, sorted by distance.
std::vector<PatchFootpoint> patchFootpoints(
  const BezierPatch& patch, const Vec3& query, double maxDistance = Unbounded);

/// The global closest point of the patch.
PatchFootpoint closestPoint(const BezierPatch& patch, const Vec3& query);

/// The closest point of the patch when it lies within `bound`; nothing when the patch
/// stays farther. Bounded, the search drops boxes outside the ball and follows the ribbon
/// beside an osculating touch in few boxes, where the unbounded one can run to its limit.
std::optional<PatchFootpoint> closestPointWithin(const BezierPatch& patch, const Vec3& query, double bound);

/// A foot of the query on the patch found locally: Gauss–Newton on S(u, v) − P ⊥ S_u, S_v
/// from `start`, kept in the square (at most 24 steps). The foot when it settles (a step
/// within `settled`, a length — the input's rounding — or the query on the patch within it)
/// with S − P normal to the patch (a minimum on a side of the square the distance still
/// falls beyond is none); nothing at a pole or where it does not settle. A neighbour's foot
/// as the start makes it a few steps; the global search (closestPoint) stays the judge.
std::optional<PatchFootpoint> localFootpoint(const BezierPatch& patch, const Vec3& query, const Vec2& start,
  double settled);

/// True when some point of the patch lies strictly closer than `radius` to the query: the
/// sign of h(u,v) = |A − P·w|² − radius²·w² (degree 2p × 2q) decided by its Bernstein
/// coefficients, with subdivision where they do not decide (to 2^-24 of the patch: closer
/// than that the patch is within rounding of the sphere, which counts as not closer).
/// Round a tangency (a ball touching the patch: h has a near double root there, and no
/// box's coefficients are all ≥ 0 however small) a box is decided by convexity instead:
/// where the Bernstein bounds of h's Hessian prove it positive definite, h lies above its
/// tangent plane at the box's minimiser. The ball-emptiness test of the 3D tracer and the
/// cone sheets. Bounded: at most the thread's box limit (PatchSearchLimit) boxes, past
/// which the undecided rest counts as not inside (as boxes at depth 24 do: there the patch
/// lies within rounding of the sphere) and the search counts as cut short
/// (patchSearchesCutShort).
bool patchComesWithin(const BezierPatch& patch, const Vec3& query, double radius);

/// Euclidean distance from a point to an axis-aligned box (0 inside): a lower bound for
/// the distance to anything inside the box.
double distanceToBox(const Box3& box, const Vec3& p);

/// The boxes the patch searches (closest points, patchComesWithin) of this thread have
/// examined so far: a deterministic measure of their work, for budgets.
std::uint64_t patchSearchWork();

/// How many patch footpoint searches of this thread have stopped at their box limit so
/// far (their answers may lack a footpoint): callers that must not be silently wrong read
/// it before and after a query.
std::uint64_t patchSearchesCutShort();

/// While it lives, each patch search of this thread examines at most `boxes` boxes (the
/// default is generous: a curve of degenerate minima is followed far before boxes are
/// dropped). For speculative work that is undone when it goes wrong, such as the 3D
/// tracer's restarts.
class PatchSearchLimit
{
public:
  explicit PatchSearchLimit(int boxes);
  ~PatchSearchLimit();
  PatchSearchLimit(const PatchSearchLimit&) = delete;
  PatchSearchLimit& operator=(const PatchSearchLimit&) = delete;

private:
  int Previous;
};

} // namespace exactmat

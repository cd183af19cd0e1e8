#pragma once
/// @file SweptPatch.h
/// @brief Footpoints on a patch swept along one direction: degree 1 in one parameter,
/// every such line parallel to one direction D and of one weight at both ends — the
/// side of an extrusion or of a cylinder cut off by slanted planes (CAD's mitered fillets
/// and pipes: the ruled patch between two planar sections of the same profile).
///
/// There S(u, t) = (1 − t)·B(u) + t·T(u) with B and T the same planar profile C moved
/// along D, so |S − P|² = |C(u) − P⊥|² + (h(u, t) − P·D)² with h the height along D. At an
/// interior stationary point the second term's t-derivative 2(h − P·D)·(T − B)·D vanishes,
/// so h = P·D and then u is a footpoint of P⊥ on the profile: the interior minima are the
/// profile's footpoints (a 1D search) lifted to the height of P where that height lies
/// between the two sections. The general patch search instead follows, near the axis of a
/// slanted cylinder, a curve of near-minima that crosses its parameters diagonally, box
/// by box, and ran out of boxes (a query 1e-5 from the axis: 200,000 boxes, no answer).

#include "geometry/ClosestPoint.h"

#include <optional>

namespace exactmat
{

struct SweptPatch
{
  bool alongV = true;            ///< the straight lines run along v (else along u)
  Vec3 direction = Vec3::UnitZ(); ///< D, unit
  BezierCurve profile;           ///< C: the side at the lines' start, projected along D (parameter: the other one)
  BezierCurve low, high;         ///< the patch's sides at the lines' start and end
};

/// The patch as a swept patch, or nothing when it is not one to rounding.
std::optional<SweptPatch> sweptPatch(const BezierPatch& patch);

/// The interior local minima of the distance from `query` (see the file comment), within
/// maxDistance; the caller adds the minima on the patch's sides.
std::vector<PatchFootpoint> sweptInteriorFootpoints(const SweptPatch& swept, const Vec3& query, double maxDistance);

} // namespace exactmat

#pragma once
/// @file Normalisation.h
/// @brief The normalised frame every MAT computation runs in (DESIGN.md §3, Numerics):
/// the boundary moved to the origin and scaled to unit size (brep/NormalisePieces.h makes
/// it). Results and messages go back to the user's frame through the same map.
///
/// Why: double precision is relative, but a MAT is computed from differences of
/// coordinates. A part at (5e5, 4e6) loses six digits to its position before the first
/// subtraction, and a rectangle at 1e300 overflows |x|². In the normalised frame every
/// tolerance of the kernel (fractions of the size) means the same on every input, so the
/// answer does not depend on where the shape sits or how large it is. The scale is a
/// power of two: scaling is exact, only the shift rounds.

#include "common/Types.h"

#include <limits>

namespace exactmat
{

/// The similarity x ↦ (x − centre) / scale from the user's frame to the unit frame.
struct Normalisation
{
  Vec3 centre = Vec3::Zero(); ///< centre of the control points' bounding box (user frame)
  double scale = 1.0;         ///< a power of two; the box's largest half-extent / scale ∈ [0.5, 1)

  Vec3 toUnit(const Vec3& x) const { return (x - centre) / scale; }
  Vec3 toUser(const Vec3& u) const { return u * scale + centre; }
  double lengthToUnit(double l) const { return l / scale; }
  double lengthToUser(double l) const { return l * scale; }
  /// How far the user's coordinates are known, in unit-frame lengths: a coordinate of
  /// magnitude |c| carries a rounding of ε·|c|, which is ε·|c|/scale here. Far from the
  /// origin (a part at 1e7 × its size) that is far more than the unit frame's ε.
  double inputRounding() const
  {
    return std::numeric_limits<double>::epsilon() * (1.0 + centre.cwiseAbs().maxCoeff() / scale);
  }
};

} // namespace exactmat

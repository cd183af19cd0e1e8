#pragma once
/// @file Verification.h
/// @brief Checks the MAT of a solid (swept or free-form) against its exact boundary
/// (DESIGN.md §4), independently of the construction: global distance = radius at every
/// point, and the number of distinct touchpoints of every ball that has a finite number
/// of them.

#include "common/ParallelFor.h"
#include "medial/MedialComplex.h"
#include "medial/SolidBoundary.h"

#include <functional>
#include <string>

namespace exactmat
{

struct MedialVerification
{
  int points = 0;                ///< points checked
  double maxDistanceError = 0.0; ///< max |distance(X, boundary) − r| / solid size
  int worstPoint = -1;           ///< where that maximum is
  int contactsChecked = 0;       ///< points whose touchpoints were counted
  int contactMismatches = 0;     ///< of those, how many have another count
  int firstMismatch = -1;        ///< the first such point
  int firstMismatchCount = 0;    ///< and how many touchpoints it has
  /// Points whose touchpoint search stopped at its work limit short of a touch (an
  /// osculating ball next to a patch's pole: the distance is flat to fourth order there)
  /// and that were verified instead by witness: each recorded touch on the boundary at
  /// the radius, and the ball shrunk by the tolerance empty (SolidBoundary::comesWithin).
  int witnessed = 0;
  /// Skeletal edge points whose one touch lies inside a curved face: the ball must osculate
  /// the face there, radius = 1/κ1 (κ1 its largest principal curvature).
  int osculationsChecked = 0;
  double maxOsculationError = 0.0; ///< largest |radius·κ1 − 1| of those
  int worstOsculation = -1;        ///< where that maximum is
  int osculationMismatches = 0;    ///< of those, how many exceed their bound
  /// The bound on |radius·κ1 − 1| is OsculationTolerance + √(δ/r), δ what the boundary is
  /// known to (inputRounding × size): the closest point of an osculating ball is fixed
  /// across the ridge only to s ≈ (δ·r³)^¼ (a contact of fourth order), and κ1, stationary
  /// there, moves by about (s/r)² ≈ √(δ/r) relative. Unmoved solids: about 1e-8.
  static constexpr double OsculationTolerance = 1e-6;
  /// The solid's longest extent over its shortest; past MaxVerifiedAspect nothing is
  /// checked (the patch closest-point search cannot resolve sides that elongated in
  /// bounded time: minutes per solid) and the verification fails, saying so.
  double aspect = 1.0;
  static constexpr double MaxVerifiedAspect = 1e8;
  bool contactsCounted() const { return aspect <= MaxVerifiedAspect; }

  bool ok(double distanceTolerance) const
  {
    return maxDistanceError <= distanceTolerance && contactMismatches == 0 && contactsCounted() &&
      osculationMismatches == 0;
  }
  /// What is wrong and where, in one line ("" when ok); `toUser` maps the complex's
  /// points to the frame the user sees.
  std::string problems(double distanceTolerance, const MedialComplex& mat,
    const std::function<Vec3(const Vec3&)>& toUser) const;
};

/// Checks every point of the curves (junctions, seams, seam ends, skeletal edges, centre
/// curves) and every `sheetStride`-th sheet point (1 = all; radius-0 points on the
/// solid's edges count as sheet points). Touchpoints count within
/// r·(1 + 2e-9) + inputRounding·size: relative to the ball, so balls far smaller or larger
/// than the solid (a 1e-12 thin sheet, a 1e12 long bar) are counted at their own scale,
/// plus what the input is known to (a part far from the origin: its coordinates' rounding,
/// Normalisation::inputRounding, against which a tiny ball's touchpoints cannot be told).
/// A skeletal edge point touching a curved face inside (or across a smooth edge) is also
/// checked to osculate it: radius·κ1 = 1 (SolidBoundary::osculation). A centre of a ball
/// touching a whole circle is checked by distance; its recorded touch, when on the
/// boundary, bounds that distance from above (the search over a ring of minima may stop
/// at a near-minimum). A point whose touchpoint search stops at its work limit short of
/// its touches is checked by witness (MedialVerification::witnessed).
/// `parallel` runs the per-point queries; the figures are the same whichever runner is given.
MedialVerification verifyMedialComplex(
  const SolidBoundary& boundary, const MedialComplex& mat, int sheetStride = 1,
  double inputRounding = 1e-15, const ParallelFor& parallel = sequentialFor);

} // namespace exactmat

#pragma once
/// @file Verification.h
/// @brief Checks a 2D MAT against the exact boundary, independently of the tracer's own
/// solves (DESIGN.md §4): global distance = radius, footpoint counts, coverage of the
/// boundary by the footpoints, cycles = holes.

#include "mat2d/MedialGraph.h"

namespace exactmat
{

struct MAT2DVerification
{
  int points = 0;                ///< MAT points checked (every sample of every segment)
  double maxDistanceError = 0.0; ///< max |distance(X, boundary) − r| / domain size
  int footpointShortfalls = 0;   ///< normal points with < 2 footpoints, branches with < 3
  double uncovered = 0.0;        ///< boundary parameter measure no footpoint swept
  double coveredTwice = 0.0;     ///< parameter measure swept more than once
  int cycles = 0, holes = 0;

  bool ok(double distanceTolerance) const
  {
    return maxDistanceError <= distanceTolerance && footpointShortfalls == 0 &&
      uncovered <= 1e-6 && coveredTwice <= 1e-6 && cycles == holes;
  }
};

MAT2DVerification verifyMAT2D(const Generators& generators, const MedialGraph& graph);

} // namespace exactmat

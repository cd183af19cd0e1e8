#pragma once
/// @file Verification.h
/// @brief Checks a 2D MAT against the exact boundary, independently of the tracer's own
/// solves (DESIGN.md §4): global distance = radius, footpoint counts, coverage of the
/// boundary by the footpoints, cycles = holes.

#include "common/ParallelFor.h"
#include "mat2d/MedialGraph.h"

#include <string>

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
  int components = 0; ///< connected components of the graph
  int domains = 0;    ///< connected components of the domain (outer loops)
  Vec2 worstPoint = Vec2::Zero(); ///< where maxDistanceError is (domain frame)
  double worstRadius = 0.0;       ///< and its Radius

  /// Boundary parameter measure that may stay uncovered or be covered twice: the slop of
  /// footpoints found to 1e-12 of the size, summed over a few thousand pieces.
  static constexpr double CoverageSlack = 1e-6;

  bool ok(double distanceTolerance) const
  {
    return maxDistanceError <= distanceTolerance && footpointShortfalls == 0 &&
      uncovered <= CoverageSlack && coveredTwice <= CoverageSlack && cycles == holes &&
      components == domains;
  }
  /// What is wrong, in one line ("" when ok(distanceTolerance)).
  std::string problems(double distanceTolerance) const;
};

/// `parallel` runs the per-point checks (distance, footpoints); the figures are the same
/// whichever runner is given.
MAT2DVerification verifyMAT2D(const Generators& generators, const MedialGraph& graph,
  const ParallelFor& parallel = sequentialFor);

} // namespace exactmat

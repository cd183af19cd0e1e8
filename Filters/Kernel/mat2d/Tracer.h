#pragma once
/// @file Tracer.h
/// @brief The 2D MAT by boundary tracing (thesis ch. 4), past the thesis where it stops:
/// domains without convex vertices, adaptive error-controlled steps, exact emptiness
/// checks through the BVH, and coverage bookkeeping so nothing is traced twice or missed.
///
/// Every simplified segment is traced as a pair of fronts on the boundary — footpoint a
/// moving forward, footpoint b moving backward — solving the equidistance system of
/// Bisector.h by predictor–corrector continuation. A step is accepted when the disk at the
/// new MAT point is empty (global distance to the exact boundary ≥ radius, which also
/// catches curvature-criterion failures, §4.3.3) and both footpoints satisfy the curvature
/// criterion. A failed step is bisected back to the branch point (§4.3.2), whose footpoints
/// (all local minima within the radius) give the new segments: one per pair of angularly
/// consecutive footpoints not yet covered (Prop. 4.1). Segments end at convex vertices,
/// at centres of curvature of LMPC points (§4.3.3, §4.3.5), at branch points, or where
/// they reach boundary already traced (cycles of multiply-connected domains).

#include "mat2d/MedialGraph.h"

#include <functional>

namespace exactmat
{

struct MAT2DOptions
{
  /// Adaptive mode: the largest distance allowed between the traced polyline (and its
  /// linearly interpolated radius) and the true MAT, as a fraction of the domain size
  /// (bounding-box diagonal).
  double tolerance = 1e-4;
  /// Fixed-step mode (reproduces the thesis): constant step and branch-check step, as
  /// fractions of the domain size.
  bool fixedStep = false;
  double step = 1e-3;
  double branchCheckStep = 1e-2;
  /// Bounds that turn a runaway into an error instead of a hang.
  int maxSamplesPerSegment = 2000000;
  int maxSegments = 100000;
  /// Called with the fraction of the boundary covered so far (0..1).
  std::function<void(double)> progress;
};

/// Computes the MAT of the domain. Throws InputError when tracing cannot proceed (naming
/// the generators and the place), never loops without bound.
MedialGraph computeMAT2D(const Generators& generators, const MAT2DOptions& options = {});

} // namespace exactmat

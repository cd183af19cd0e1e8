#pragma once
/// @file CurveCrossings.h
/// @brief Do closed chains of Bézier curves cross? The boundary's validity check, at the
/// resolution of flatten(): two chains (or one chain with itself) cross when chords of
/// their flattened parts that are not consecutive along a chain meet.
///
/// Why not flatten everything and sweep the chords: a conic flattened to 1e-6 of the
/// size is thousands of chords, most of them far from any other curve. Here the curves are
/// halved only where control-point boxes of parts that are not neighbours overlap, so the
/// cost follows how close the curves come, not how finely they are resolved; the chords
/// finally compared are exactly flatten()'s, so the verdict is the same.

#include "nurbs/BezierCurve.h"

#include <vector>

namespace exactmat
{

struct CurveCrossing
{
  bool found = false;
  int chainA = -1, curveA = -1; ///< the chain and its curve (index along the chain)
  int chainB = -1, curveB = -1;
  Vec3 near = Vec3::Zero(); ///< a point of the crossing chord of A
};

/// `chains[c]`: the curves of closed chain c in order, each ending where the next starts
/// (the last where the first starts). `tolerance`: flatten()'s.
CurveCrossing findCrossing(
  const std::vector<std::vector<const BezierCurve*>>& chains, double tolerance);

} // namespace exactmat

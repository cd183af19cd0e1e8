#pragma once
/// @file Flatten.h
/// @brief Polyline approximations of Bézier curves, used only for topological checks
/// (self-intersection, loop nesting) — never for the MAT itself.

#include "nurbs/BezierCurve.h"

namespace exactmat
{

/// Points of `curve` (exactly on it) at parameters chosen by recursive halving until the
/// control polygon of each part deviates from its chord by ≤ tolerance (at most 2^12
/// parts). Includes both ends.
Vec3List flatten(const BezierCurve& curve, double tolerance);

/// The parts flatten() ends with, in order (their ends are its points).
std::vector<BezierCurve> flattenParts(const BezierCurve& curve, double tolerance);

/// How far the control polygon of `curve` strays from the line of its chord: flatten()
/// stops halving a part when this is ≤ its tolerance, or at MaxFlattenDepth halvings.
double chordDeviation(const BezierCurve& curve);
constexpr int MaxFlattenDepth = 12;

} // namespace exactmat

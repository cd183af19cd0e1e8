#pragma once
/// @file BezierExtraction.h
/// @brief NURBS ⇄ rational Bézier pieces, exactly.
///
/// Extraction raises every distinct knot of the parameter domain to multiplicity p by knot
/// insertion (A5.1): on each knot span the p+1 active control points are then the Bézier
/// control points. Joining concatenates pieces with knots of multiplicity p at the joints
/// and then removes each joint knot as often as the continuity there allows (A5.8), which
/// gives back the original curve when the pieces came from one.

#include "nurbs/BezierCurve.h"
#include "nurbs/BezierPatch.h"
#include "nurbs/NurbsCurve.h"
#include "nurbs/NurbsSurface.h"

#include <vector>

namespace exactmat
{

/// A Bézier piece of a NURBS curve and the knot span [t0, t1] it covers.
struct BezierSpan
{
  BezierCurve curve;
  double t0 = 0.0, t1 = 1.0;
};

/// A Bézier patch of a NURBS surface and the knot spans it covers.
struct BezierPatchSpan
{
  BezierPatch patch;
  double u0 = 0.0, u1 = 1.0, v0 = 0.0, v1 = 1.0;
};

/// Every non-empty knot span of `curve` as a rational Bézier piece, in parameter order.
std::vector<BezierSpan> extractBezier(const NurbsCurve& curve);

/// Every non-empty knot-span rectangle of `surface`; u-major order (all v for the first u).
std::vector<BezierPatchSpan> extractBezier(const NurbsSurface& surface);

/// Joins consecutive pieces of one degree into one NURBS curve. `breaks` (pieces + 1
/// increasing values; empty = 0, 1, 2, …) become the knots of the joints. Consecutive
/// pieces must meet (end = start within `tolerance`, else InputError naming the joint).
/// Rational pieces are rescaled so their weights agree at each joint, then every joint
/// knot is removed as often as the curve allows within `tolerance`.
NurbsCurve joinBezier(const std::vector<BezierCurve>& pieces,
  const std::vector<double>& breaks = {}, double tolerance = 1e-12);

} // namespace exactmat

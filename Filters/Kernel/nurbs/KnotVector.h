#pragma once
/// @file KnotVector.h
/// @brief Knot vectors: validation, span search, B-spline basis with derivatives, knot insertion.
///
/// Algorithms follow Piegl & Tiller, *The NURBS Book* (A2.1 span, A2.3 basis derivatives,
/// A5.1 knot insertion, A5.8 knot removal). Control points are homogeneous (see Types.h).

#include "common/Types.h"

#include <string>
#include <vector>

namespace exactmat
{

/// Highest polynomial degree the kernel accepts (CAD data rarely exceeds 9).
constexpr int MaxDegree = 20;

using KnotVector = std::vector<double>;

/// Throws InputError naming `entity` unless `knots` is a valid knot vector for `count`
/// control points of degree `degree`: finite, non-decreasing, of length count+degree+1,
/// interior multiplicity ≤ degree, and a non-empty parameter domain.
void validateKnots(const KnotVector& knots, int degree, int count, const std::string& entity);

/// Clamped, uniform knot vector for `count` control points of degree `degree` on [0,1].
KnotVector clampedUniformKnots(int degree, int count);

/// Index k with knots[k] ≤ u < knots[k+1] inside the domain [knots[p], knots[n+1]]
/// (n = count−1); u is clamped to the domain, and the domain end maps to the last span.
int findSpan(const KnotVector& knots, int degree, int count, double u);

/// Basis functions N_{span−p+j, p}(u) and their derivatives up to order nd (≤ 2):
/// ders[k*(p+1)+j]. `ders` must hold (nd+1)(p+1) doubles.
void basisDerivatives(
  const KnotVector& knots, int span, double u, int degree, int nd, double* ders);

/// Inserts u once into (knots, points) of degree p, where `points` are the control points
/// along the direction of the knot vector taken `stride` apart, in `lines` interleaved
/// lines (a surface's columns). Exact in homogeneous coordinates.
void insertKnot(KnotVector& knots, int degree, Vec4List& points, int lines, double u);

/// Multiplicity of knot value u in `knots` (exact comparison).
int multiplicity(const KnotVector& knots, double u);

/// Tries to remove interior knot u up to `times` times while moving no homogeneous control
/// point by more than `tolerance` (A5.8). Returns the number of removals made.
int removeKnot(KnotVector& knots, int degree, Vec4List& points, double u, int times,
  double tolerance);

} // namespace exactmat

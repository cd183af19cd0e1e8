#pragma once
/// @file PatchContinuation.h
/// @brief Whether one rational Bézier patch is a piece of another's surface: the same
/// rational function over a sub-rectangle of the other's (extended) parameter plane, as
/// subdivision makes it (the pieces of a surface of revolution cut along its profile, the
/// pieces of a face split where MAT samples touch). Such pieces share one parameterisation,
/// so a medial sheet spanning them needs no border where they meet.

#include "nurbs/BezierPatch.h"

namespace exactmat
{

/// q ↦ origin + axes · q: a piece's parameters in the whole surface's.
struct ParameterMap
{
  Vec2 origin = Vec2::Zero();
  Eigen::Matrix2d axes = Eigen::Matrix2d::Identity();

  Vec2 operator()(const Vec2& q) const { return origin + axes * q; }
  Vec2 inverse(const Vec2& q) const { return axes.inverse() * (q - origin); }
  /// The map back: the surface's parameters to the piece's.
  ParameterMap inverted() const
  {
    ParameterMap m;
    m.axes = axes.inverse();
    m.origin = -(m.axes * origin);
    return m;
  }
  /// This map after `inner` (q ↦ this(inner(q))): a piece of a piece.
  ParameterMap after(const ParameterMap& inner) const
  {
    ParameterMap m;
    m.origin = (*this)(inner.origin);
    m.axes = axes * inner.axes;
    return m;
  }
};

/// The map taking `piece`'s parameters to `surface`'s when `piece` is that surface
/// evaluated over an affine image of the unit square (its corners, centre and side
/// midpoints all within `tolerance` of the surface there, the surface's parameters found by
/// Newton on its polynomial extension, no clamping); false otherwise (a neighbour that only
/// meets it smoothly, such as the next span of a B-spline).
bool pieceOfSurface(const BezierPatch& surface, const BezierPatch& piece, double tolerance, ParameterMap& map);

/// Whether two patches are pieces of one surface, with the map taking b's parameters to
/// a's. Symmetric: the larger patch is asked to contain the other first (its extension is
/// evaluated near its own square, where the input's rounding is not amplified: a sliver's
/// extension evaluated twenty widths away multiplies it by hundreds), then the other way.
bool piecesOfOneSurface(const BezierPatch& a, const BezierPatch& b, double tolerance, ParameterMap& bInA);

} // namespace exactmat

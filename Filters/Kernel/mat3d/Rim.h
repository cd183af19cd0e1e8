#pragma once
/// @file Rim.h
/// @brief Skeletal edges (rims) of curved faces: where a medial sheet ends inside the solid
/// because its ball osculates the boundary (thesis §3.4 and the curvature criterion of
/// §6.2; an A3 contact). The ball touches one point P of a face, its radius is 1/κ1 (κ1 the
/// largest principal curvature there, positive where the face is convex) and its centre
/// P + N/κ1; P lies on a ridge: κ1 is a maximum along its own line of curvature,
/// dκ1/de1 = 0 (Porteous: there the focal surface has its cuspidal edge, which the sheet
/// ends on). A rim is traced as that ridge curve in the face's parameters — Newton on the
/// ridge function, continuation along it, onto the neighbour across a smooth edge — and
/// every ball is tested for emptiness against the whole boundary.
///
/// The ridge function needs κ1's derivative (third derivatives of the surface): it is a
/// fourth-order central difference of exactly evaluated curvatures over 1e-3 of the
/// curvature radius, whose bias (about 1e-12 of the radius) is below the ridge's own
/// rounding; the centre and the radius move only to second order with the ridge's place
/// (κ1 is stationary across a ridge).

#include "mat3d/FaceCurveSearch.h"

#include <functional>
#include <vector>

namespace exactmat
{

/// The largest principal curvature at a face's touch (positive where the face bends
/// towards the material's side away from its normal, i.e. convex: a ball of radius 1/k1
/// osculates it there), the other one, and k1's direction in the face's parameters, scaled
/// so that it moves the touch by unit length.
struct FaceCurvature
{
  double k1 = 0.0, k2 = 0.0;
  Vec2 d1 = Vec2::Zero();
};
FaceCurvature faceCurvature(const Touch3D& touch);

/// The ridge function at q of a curved face: dκ1/ds along κ1's own direction, turned along
/// `reference` (a direction in the face's parameters; the function's sign depends on that
/// orientation, which κ1's direction has none of). A fourth-order central difference over
/// min(1e-4·size, 1e-3/κ1); NaN where κ1 ≤ 0.
double ridgeFunction(const Generator3D& face, const Vec2& q, const Vec2& reference, double size);

struct RimBall
{
  int face = -1;
  Vec2 q = Vec2::Zero(); ///< the touch's parameters on the face
  Vec3 touch = Vec3::Zero();
  Vec3 x = Vec3::Zero(); ///< the centre
  double r = 0.0;
};

struct Rim
{
  std::vector<RimBall> balls; ///< in order; a closed rim repeats its first ball at the end
  bool closed = false;
  /// An open rim ended here (its last ball): where its ball stops being empty (a seam
  /// meets it: a fin point), or its touch reaches a sharp edge. Empty when closed.
  std::string end;
};

struct RimSearch : FaceCurveSearch
{
  /// Whether the ball (centre, radius) is empty of the whole boundary; it osculates one face
  /// at its touch, so the test is meant against a ball smaller by a relative 1e-6.
  std::function<bool(const Vec3&, double)> empty;
};

/// Every rim of the solid's curved faces: ridge points found where the ridge function
/// changes sign between samples of a grid on each face, kept when κ1 is a maximum there
/// and the osculating ball is empty, each traced both ways until it closes or ends.
/// Throws InputError when a trace runs away.
std::vector<Rim> traceRims(const RimSearch& search);

} // namespace exactmat

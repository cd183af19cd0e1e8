#pragma once
/// @file Primitives.h
/// @brief Exact NURBS building blocks: segments, circular arcs, circles, polygons.

#include "nurbs/NurbsCurve.h"
#include "nurbs/NurbsSurface.h"

#include <vector>

namespace exactmat
{

/// The straight segment a→b as a degree-1 curve.
NurbsCurve makeSegment(const Vec3& a, const Vec3& b);

/// The circular arc in the xy-plane (z = centre.z) from angle a0 to a1 (radians,
/// counter-clockwise when a1 > a0, clockwise otherwise): rational quadratic, one span per
/// ≤ 90° (Piegl & Tiller A7.1), so it is exact.
NurbsCurve makeArc(const Vec3& centre, double radius, double a0, double a1);

/// The closed polygon through `corners` (counter-clockwise for material inside) as
/// segments.
std::vector<NurbsCurve> makePolygon(const Vec3List& corners);

/// The tensor-product surface of a curve (u) and a straight extrusion along `direction`
/// of length `length` (v, degree 1).
NurbsSurface makeExtrusion(const NurbsCurve& profile, const Vec3& direction, double length);

/// The surface swept by `profile` (in the xz half-plane x > 0) revolving 360° about z: u
/// follows the profile, v the full circle (rational quadratic, 4 spans).
NurbsSurface makeRevolution(const NurbsCurve& profile);

/// The torus about z with core radius `core` and tube radius `tube` (0 < tube < core): the
/// tube's circle in the xz half-plane revolved (4 × 4 rational biquadratic patches). Its
/// MAT is the core circle, every ball touching a whole circle of the tube.
NurbsSurface torusSurface(double core, double tube);

/// The ellipsoid with these semi-axes about the origin as eight rational biquadratic
/// patches of the sphere's form of revolution, scaled: four quarter arcs about the polar
/// axis (0 = x, 1 = y, 2 = z; 45°→135°, …) times two meridian arcs, −90° → `cutLatitude`
/// and `cutLatitude` → 90° (radians, in (−90°, 90°)). The poles are collapsed sides; the
/// normals point outwards.
std::vector<NurbsSurface> ellipsoidSurfaces(const Vec3& semiAxes, double cutLatitude, int polarAxis);

/// Scaling families (benchmarks and tests): boundaries with local features whose entity
/// count grows with n.
/// A strip whose top and bottom are saw-tooth polylines with about n corners in all.
std::vector<NurbsCurve> makeSawToothStrip(int corners);
/// One closed cubic B-spline with `spans` Bézier spans outlining a wavy strip.
NurbsCurve makeWavyStrip(int spans);

} // namespace exactmat

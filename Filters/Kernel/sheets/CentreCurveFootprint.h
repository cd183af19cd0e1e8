#pragma once
/// @file CentreCurveFootprint.h
/// @brief What the circles of contact of centre curves cover of each face (CentreCurve.h),
/// for the sheets' coverage check (sheetCoverage): every point of a face has one maximal
/// ball, and along a cylinder's axis or a torus' core that ball is a centre curve's, not a
/// sheet's. Between two consecutive balls the circles sweep a band; it is summed strip by
/// strip (32 per turn: arc length times the way between the circles, by Simpson's rule
/// across the strip), each strip given to the face it lies on — cut where the circle
/// crosses from one face to the next, and along where the band does (both found by
/// bisection) — strips off every face (beyond a fillet's arc) left out.

#include "mat3d/Generator3D.h"
#include "mat3d/MAT3D.h"
#include "medial/MedialComplex.h"

#include <vector>

namespace exactmat
{

/// A centre curve as its balls' centres and one touch each (the tracked one), in order.
struct CentreCurveTouches
{
  Vec3List centres;
  Vec3List touches;
};

std::vector<CentreCurveTouches> centreCurveTouches(const MAT3D& mat);
/// The CentreCurve elements of a complex (their points' first touches).
std::vector<CentreCurveTouches> centreCurveTouches(const MedialComplex& mat);

/// The area of each face (Boundary3D order) the curves' circles of contact sweep.
std::vector<double> centreCurveFootprints(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
  const std::vector<CentreCurveTouches>& curves);

/// What balls that touch a whole face cover: a face lying on the sphere of a SphereCentre
/// point (the MAT of a ball: its centre) or of a CircleCentre point (a centre curve's end at
/// a spherical cap: a capsule's hemispheres) is covered wholly, once — checked here from
/// the point's centre and radius alone (mat3d/BoundarySphere.h's grid test within
/// `tolerance`, a length). Per face (Boundary3D order): the face's area or 0.
std::vector<double> sphericalFaceFootprints(const Boundary3D& boundary, const MedialComplex& mat, double tolerance);

} // namespace exactmat

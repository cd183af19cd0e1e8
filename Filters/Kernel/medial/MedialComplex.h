#pragma once
/// @file MedialComplex.h
/// @brief The MAT of a solid (swept or free-form) as a cell complex (thesis §3.4): junction points, seams,
/// skeletal edges (curves) and medial sheets (triangulated surfaces), every point with its
/// radius and classification.

#include "common/Types.h"

#include <array>
#include <vector>

namespace exactmat
{

/// How a medial point of a solid touches the boundary (thesis §3.4).
enum class MedialPoint3DType
{
  Sheet = 0,        ///< two touchpoints: inside a sheet
  Seam = 1,         ///< three: where three sheets meet
  Junction = 2,     ///< four or more: where seams meet
  SeamEnd = 3,      ///< where a seam ends: at a convex vertex of the solid (radius 0) or
                    ///< on a skeletal edge
  SkeletalEdge = 4, ///< one touchpoint of higher order: a centre of curvature of a point
                    ///< of maximal curvature (the ball osculates the boundary)
  ConvexEdge = 5,   ///< radius 0: a sheet's border on a convex edge of the solid
  CircleCentre = 6, ///< the ball touches a whole circle (axis of a cylinder, torus core)
  SphereCentre = 7  ///< the ball touches the whole boundary: the MAT of a ball is its centre
};

const char* toString(MedialPoint3DType type);

enum class MedialElementType
{
  Junction = 0,      ///< a vertex
  Seam = 1,          ///< a polyline
  SkeletalEdge = 2,  ///< a polyline
  CentreCurve = 3,   ///< a polyline of CircleCentre points
  SweptSheet = 4,    ///< triangles: a profile MAT segment swept between its seams
  ProfileSheet = 5,  ///< triangles: between a profile face and one side (or reflex edge)
  MidSheet = 6,      ///< triangles: between the two profile faces (spans < 2·Rmax)
  Sheet = 7,         ///< triangles: a free-form solid's sheet between a generator pair (sheets/)
  SphereCentre = 8   ///< a vertex: the whole MAT of a ball (its centre; governors: every face)
};

const char* toString(MedialElementType type);

struct MedialPoint3D
{
  Vec3 x = Vec3::Zero();
  double radius = 0.0;
  MedialPoint3DType type = MedialPoint3DType::Sheet;
  /// How many distinct touchpoints the ball has, by construction; 0 = not a finite count
  /// (radius 0, or a whole curve of contact).
  int contacts = 0;
  /// The points where the ball touches, where its producer records them (the 3D tracer:
  /// its generators' touches, three for a seam point, one per generator at a junction).
  Vec3List touches;
};

struct MedialElement
{
  MedialElementType type = MedialElementType::Seam;
  std::vector<int> points;                  ///< vertex / polyline point ids
  std::vector<std::array<int, 3>> triangles; ///< sheets
  /// The boundary entities the element is equidistant to (numbered by its producer: MAT25D.h
  /// for swept solids, face indices for MAT3D.h).
  std::vector<int> governors;
  int profileSegment = -1; ///< the profile MAT segment (or node, for junctions) it comes from
};

struct MedialComplex
{
  std::vector<MedialPoint3D> points;
  std::vector<MedialElement> elements;

  /// Makes points that coincide (within `tolerance`) one, keeping the most special type
  /// (sphere centre > junction > seam end > seam > skeletal edge > circle centre > convex edge > sheet):
  /// neighbouring sheets built apart then share their border vertices. Drops triangles
  /// and repeated polyline points that collapse. Returns how many points were merged.
  int weld(double tolerance);

  /// A conforming complex: a sheet triangle whose border edge (a, b) joins two points of a
  /// polyline (a seam, a skeletal edge) that are not neighbours on it — the sheet sampled
  /// more coarsely than the curve — becomes a fan from its third vertex through the curve's
  /// points between a and b, so every curve segment is a sheet edge (no T-junction).
  /// Returns how many triangles were fanned.
  int fanSheetsToCurves();

  int count(MedialElementType type) const;
  int countPoints(MedialPoint3DType type) const;
  int triangleCount() const;
  double maximumRadius() const;
};

} // namespace exactmat

#pragma once
/// @file Plane.h
/// @brief The plane of a planar domain and its local frame.

#include "common/Types.h"

namespace exactmat
{

/// An orthonormal frame (origin, e1, e2, normal) of a plane. Local coordinates (x, y, 0)
/// map to origin + x·e1 + y·e2. For a domain in z = 0 the frame is the world frame
/// exactly (origin 0, e1 = x, e2 = y), so coordinates pass through unchanged.
struct Plane
{
  Vec3 origin = Vec3::Zero();
  Vec3 e1 = Vec3::UnitX(), e2 = Vec3::UnitY(), normal = Vec3::UnitZ();

  Vec3 toLocal(const Vec3& p) const
  {
    const Vec3 d = p - origin;
    return Vec3(d.dot(e1), d.dot(e2), d.dot(normal));
  }
  Vec3 toWorld(const Vec3& l) const { return origin + l.x() * e1 + l.y() * e2 + l.z() * normal; }
  /// A homogeneous control point moved to local coordinates (exact for the world frame).
  Vec4 toLocalHomogeneous(const Vec4& h) const
  {
    const Vec3 d = h.head<3>() - h.w() * origin;
    return Vec4(d.dot(e1), d.dot(e2), d.dot(normal), h.w());
  }
  Vec4 toWorldHomogeneous(const Vec4& h) const
  {
    const Vec3 p = h.w() * origin + h.x() * e1 + h.y() * e2 + h.z() * normal;
    return Vec4(p.x(), p.y(), p.z(), h.w());
  }

  /// Least-squares plane of `points`: normal = direction of least variance, oriented
  /// towards +z (or the first non-zero axis); origin = the plane's point nearest to 0.
  static Plane fit(const Vec3List& points);
};

} // namespace exactmat

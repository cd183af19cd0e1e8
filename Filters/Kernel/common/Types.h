#pragma once
/// @file Types.h
/// @brief Vector types shared by the whole kernel.
///
/// Points are always 3-vectors (a planar domain lives in its own z = 0 frame, see
/// brep/Boundary2D.h). Rational control points are stored homogeneously as
/// (w·x, w·y, w·z, w): every algorithm that subdivides, inserts knots or elevates degree
/// then works on plain polynomial data, which keeps them exact for rational entities.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace exactmat
{

constexpr double Pi = 3.14159265358979323846;

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Vec4 = Eigen::Vector4d; ///< homogeneous control point (w·x, w·y, w·z, w)

using Vec3List = std::vector<Vec3, Eigen::aligned_allocator<Vec3>>;
using Vec4List = std::vector<Vec4, Eigen::aligned_allocator<Vec4>>;

/// Homogeneous form of a Euclidean point with weight w.
inline Vec4 homogeneous(const Vec3& p, double w)
{
  return Vec4(w * p.x(), w * p.y(), w * p.z(), w);
}

/// Euclidean point of a homogeneous control point (w must be non-zero).
inline Vec3 euclidean(const Vec4& h)
{
  return h.head<3>() / h.w();
}

} // namespace exactmat

#include "Plane.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace exactmat
{

Plane Plane::fit(const Vec3List& points)
{
  Plane plane;
  if (points.empty())
  {
    return plane;
  }
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& p : points)
  {
    centroid += p;
  }
  centroid /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points)
  {
    cov += (p - centroid) * (p - centroid).transpose();
  }
  // Input already in z = 0 (the common case) keeps the exact world frame.
  bool inXY = true;
  for (const Vec3& p : points)
  {
    inXY = inXY && p.z() == points.front().z();
  }
  Vec3 n;
  if (inXY)
  {
    n = Vec3::UnitZ();
  }
  else
  {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov);
    n = solver.eigenvectors().col(0).normalized();
    int axis = 2;
    if (std::abs(n.z()) < 1e-12)
    {
      axis = std::abs(n.y()) >= 1e-12 ? 1 : 0;
    }
    if (n(axis) < 0.0)
    {
      n = -n;
    }
  }
  plane.normal = n;
  plane.origin = centroid.dot(n) * n;
  Vec3 e1 = Vec3::UnitX() - Vec3::UnitX().dot(n) * n;
  if (e1.norm() < 1e-6)
  {
    e1 = Vec3::UnitY() - Vec3::UnitY().dot(n) * n;
  }
  plane.e1 = e1.normalized();
  plane.e2 = n.cross(plane.e1);
  if (inXY)
  {
    plane.e1 = Vec3::UnitX();
    plane.e2 = Vec3::UnitY();
  }
  return plane;
}

} // namespace exactmat

#include "shapes/Moved.h"

#include <Eigen/Geometry>

namespace exactmat
{

std::vector<PatchPiece> movedPieces(std::vector<PatchPiece> pieces, const Eigen::Matrix3d& rotation,
  double scale, const Vec3& offset, double weightFactor)
{
  auto map = [&](Vec4List& net) {
    for (Vec4& h : net)
      h = homogeneous(scale * (rotation * euclidean(h)) + offset, weightFactor * h.w());
  };
  for (PatchPiece& p : pieces)
  {
    Vec4List net = p.patch.homogeneousNet();
    map(net);
    p.patch = BezierPatch(p.patch.degreeU(), p.patch.degreeV(), std::move(net));
    if (p.triangle)
      map(p.triangle->points);
  }
  return pieces;
}

Placement farFromTheOrigin()
{
  Placement far;
  far.rotation = Eigen::AngleAxisd(0.7, Vec3(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  far.scale = 1e-3;
  far.offset = 1e5 * far.scale * Vec3(1.0, -0.7, 0.4);
  far.weightFactor = 1e20;
  return far;
}

} // namespace exactmat

#include "shapes/Moved.h"

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

} // namespace exactmat

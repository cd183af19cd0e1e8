#include "Verification.h"

#include <algorithm>
#include <cmath>

namespace exactmat
{

MAT25DVerification verifyMAT25D(
  const SweptBoundary& boundary, const MedialComplex& mat, int sheetStride)
{
  MAT25DVerification v;
  const double size = boundary.size();
  const int n = static_cast<int>(mat.points.size());
  int sheetPoints = 0;
  for (int i = 0; i < n; ++i)
  {
    const MedialPoint3D& p = mat.points[i];
    const bool sheet =
      p.type == MedialPoint3DType::Sheet || p.type == MedialPoint3DType::ConvexEdge;
    if (sheet && sheetPoints++ % std::max(1, sheetStride) != 0)
      continue;
    ++v.points;
    const double error = std::abs(boundary.distance(p.x) - p.radius) / size;
    if (!(error <= v.maxDistanceError))
    {
      v.maxDistanceError = std::isnan(error) ? INFINITY : error;
      v.worstPoint = i;
    }
    if (p.contacts <= 0)
      continue;
    ++v.contactsChecked;
    const int count = static_cast<int>(
      boundary.touchpoints(p.x, p.radius * (1.0 + 1e-9) + 1e-9 * size).size());
    if (count != p.contacts)
    {
      if (v.contactMismatches++ == 0)
      {
        v.firstMismatch = i;
        v.firstMismatchCount = count;
      }
    }
  }
  return v;
}

} // namespace exactmat

#include "Verification.h"

#include "common/Format.h"

#include <algorithm>
#include <cmath>

namespace exactmat
{

MedialVerification verifyMedialComplex(
  const SolidBoundary& boundary, const MedialComplex& mat, int sheetStride, double inputRounding)
{
  MedialVerification v;
  const double size = boundary.size();
  const int n = static_cast<int>(mat.points.size());
  int sheetPoints = 0;
  v.aspect = boundary.aspect();
  if (!v.contactsCounted())
    return v;
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
      boundary.touchpoints(p.x, p.radius * (1.0 + 2e-9) + inputRounding * size).size());
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

std::string MedialVerification::problems(double distanceTolerance, const MedialComplex& mat,
  const std::function<Vec3(const Vec3&)>& toUser) const
{
  std::string out;
  if (!(maxDistanceError <= distanceTolerance) && worstPoint >= 0)
  {
    out += "largest |distance to boundary - radius| / size " + format(maxDistanceError) +
      " > tolerance " + format(distanceTolerance) + " at " + format(toUser(mat.points[worstPoint].x));
  }
  if (!contactsCounted())
  {
    out += std::string(out.empty() ? "" : "; ") + "not verified: the solid is " + format(aspect) +
      " times longer than thick (verified up to " + format(MaxVerifiedAspect) + ")";
  }
  if (contactMismatches > 0)
  {
    const MedialPoint3D& p = mat.points[firstMismatch];
    out += std::string(out.empty() ? "" : "; ") + std::to_string(contactMismatches) + " of " +
      std::to_string(contactsChecked) + " points touch the boundary at another number of " +
      "points than constructed (first: " + toString(p.type) + " point at " + format(toUser(p.x)) +
      " touches " + std::to_string(firstMismatchCount) + ", expected " +
      std::to_string(p.contacts) + ")";
  }
  return out;
}

} // namespace exactmat

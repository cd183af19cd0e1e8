#include "Verification.h"

#include "common/Format.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace exactmat
{

MedialVerification verifyMedialComplex(const SolidBoundary& boundary, const MedialComplex& mat,
  int sheetStride, double inputRounding, const ParallelFor& parallel)
{
  MedialVerification v;
  const double size = boundary.size();
  const int n = static_cast<int>(mat.points.size());
  v.aspect = boundary.aspect();
  if (!v.contactsCounted())
    return v;
  // The points to check, chosen in order; checked independently (possibly on several
  // threads), then reduced in this order so the figures do not depend on the threads.
  std::vector<int> chosen;
  int sheetPoints = 0;
  for (int i = 0; i < n; ++i)
  {
    const MedialPoint3D& p = mat.points[i];
    const bool sheet =
      p.type == MedialPoint3DType::Sheet || p.type == MedialPoint3DType::ConvexEdge;
    if (sheet && sheetPoints++ % std::max(1, sheetStride) != 0)
      continue;
    chosen.push_back(i);
  }
  std::vector<double> error(chosen.size(), 0.0);
  std::vector<int> count(chosen.size(), -1);
  std::vector<double> osculation(chosen.size(), NAN);
  std::vector<char> witnessed(chosen.size(), 0);
  parallel(chosen.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
    {
      const MedialPoint3D& p = mat.points[chosen[k]];
      // A point whose touchpoints are counted: the nearest of them is the global distance
      // whenever that is within their reach (the same exact search, asked once).
      double distance = INFINITY;
      double bound = 0.0; // what a witness leaves open of |distance − radius|
      if (p.contacts > 0)
      {
        boundary.searchesCutShort(); // (resets it)
        const auto contacts = boundary.touchpoints(p.x, p.radius * (1.0 + 2e-9) + inputRounding * size);
        count[k] = static_cast<int>(contacts.size());
        for (const SolidBoundary::Contact& c : contacts)
          distance = std::min(distance, c.distance);
        if (p.type == MedialPoint3DType::SkeletalEdge && contacts.size() == 1)
          osculation[k] = boundary.osculation(contacts.front(), p.x, p.radius);
        // Fewer touches than constructed, and a search stopped at its limit: the
        // construction's own touches stand witness where each lies on the boundary at the
        // radius (so the distance is at most that) and the ball shrunk by the tolerance is
        // empty (so it is at least that): exact decisions, not a search for minima.
        if (count[k] < p.contacts && boundary.searchesCutShort() && !p.touches.empty())
        {
          const double slack = 1e-12 * size + inputRounding * size;
          double farthest = 0.0;
          int unmatched = 0;
          bool onBoundary = true;
          SolidBoundary::Contact at;
          for (const Vec3& touch : p.touches)
          {
            at = boundary.nearestContact(touch);
            onBoundary = onBoundary && at.distance <= slack;
            farthest = std::max(farthest, (touch - p.x).norm());
            unmatched += std::none_of(contacts.begin(), contacts.end(),
              [&](const SolidBoundary::Contact& c) { return (c.point - touch).norm() <= 1e-9 * size; });
          }
          if (onBoundary && !boundary.comesWithin(p.x, p.radius - slack))
          {
            distance = std::min(distance, farthest);
            bound = slack;
            count[k] += unmatched;
            if (p.type == MedialPoint3DType::SkeletalEdge && p.touches.size() == 1)
              osculation[k] = boundary.osculation(at, p.x, p.radius);
            witnessed[k] = 1;
          }
        }
      }
      if (!(distance < INFINITY))
      {
        distance = boundary.distance(p.x);
        // A ball touching a continuum (a circle of a canal face) is where the closest-point
        // search can stop at a near-minimum of the ring it explores (far from the origin,
        // where the rounded face is a ring of them): its recorded touch, when it lies on the
        // boundary, is a witness that the distance is at most its own. (A nearer point the
        // search finds stays found: a ball that reaches out is still caught.)
        if (p.type == MedialPoint3DType::CircleCentre && !p.touches.empty())
        {
          const Vec3& touch = p.touches.front();
          if (boundary.distance(touch) <= inputRounding * size + 1e-15 * size)
            distance = std::min(distance, (touch - p.x).norm());
        }
      }
      error[k] = std::max(std::abs(distance - p.radius), bound) / size;
    }
  });
  for (std::size_t k = 0; k < chosen.size(); ++k)
  {
    const int i = chosen[k];
    ++v.points;
    v.witnessed += witnessed[k];
    if (!(error[k] <= v.maxDistanceError))
    {
      v.maxDistanceError = std::isnan(error[k]) ? INFINITY : error[k];
      v.worstPoint = i;
    }
    if (!std::isnan(osculation[k]))
    {
      ++v.osculationsChecked;
      const double bound =
        MedialVerification::OsculationTolerance + std::sqrt(inputRounding * size / mat.points[i].radius);
      v.osculationMismatches += !(osculation[k] <= bound);
      if (!(osculation[k] <= v.maxOsculationError))
      {
        v.maxOsculationError = osculation[k];
        v.worstOsculation = i;
      }
    }
    if (mat.points[i].contacts <= 0)
      continue;
    ++v.contactsChecked;
    if (count[k] != mat.points[i].contacts && v.contactMismatches++ == 0)
    {
      v.firstMismatch = i;
      v.firstMismatchCount = count[k];
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
  if (osculationMismatches > 0 && worstOsculation >= 0)
  {
    out += std::string(out.empty() ? "" : "; ") + "a skeletal edge's ball does not osculate the face it touches: |radius x " +
      "largest curvature - 1| = " + format(maxOsculationError) + " at " + format(toUser(mat.points[worstOsculation].x));
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

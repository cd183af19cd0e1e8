#include "geometry/SweptPatch.h"

#include <algorithm>
#include <cmath>

namespace exactmat
{

std::optional<SweptPatch> sweptPatch(const BezierPatch& patch)
{
  SweptPatch s;
  s.alongV = patch.degreeV() == 1;
  if (!s.alongV && patch.degreeU() != 1)
    return std::nullopt;
  const int n = s.alongV ? patch.degreeU() : patch.degreeV();
  auto at = [&](int i, int end) -> const Vec4& {
    return s.alongV ? patch.homogeneousPoint(i, end) : patch.homogeneousPoint(end, i);
  };
  const double scale = patch.boundingBox().diagonal().norm();
  if (!(scale > 0.0))
    return std::nullopt;
  // The lines' common direction: the longest of them.
  Vec3 longest = Vec3::Zero();
  for (int i = 0; i <= n; ++i)
  {
    const Vec3 d = euclidean(at(i, 1)) - euclidean(at(i, 0));
    if (d.norm() > longest.norm())
      longest = d;
  }
  if (longest.norm() <= 1e-9 * scale)
    return std::nullopt;
  s.direction = longest.normalized();
  Vec4List profile, low, high;
  for (int i = 0; i <= n; ++i)
  {
    const Vec4 &a = at(i, 0), &b = at(i, 1);
    if (!(a.w() > 0.0) || std::abs(a.w() - b.w()) > 1e-14 * a.w())
      return std::nullopt;
    const Vec3 pa = euclidean(a), d = euclidean(b) - pa;
    if (d.cross(s.direction).norm() > 1e-13 * scale)
      return std::nullopt;
    const Vec3 flat = pa - pa.dot(s.direction) * s.direction;
    profile.push_back(Vec4(flat.x() * a.w(), flat.y() * a.w(), flat.z() * a.w(), a.w()));
    low.push_back(a);
    high.push_back(b);
  }
  s.profile = BezierCurve(std::move(profile));
  s.low = BezierCurve(std::move(low));
  s.high = BezierCurve(std::move(high));
  return s;
}

std::vector<PatchFootpoint> sweptInteriorFootpoints(const SweptPatch& swept, const Vec3& query, double maxDistance)
{
  const Vec3& D = swept.direction;
  const double height = query.dot(D);
  const Vec3 flat = query - height * D;
  std::vector<PatchFootpoint> found;
  // The height of the query between the sections at profile parameter u, as the line's
  // parameter t (inside when 0 < t < 1).
  auto lift = [&](double u, double& t) {
    const Vec3 b = swept.low.evaluate(u), h = swept.high.evaluate(u);
    const double span = (h - b).dot(D);
    if (!(std::abs(span) > 0.0))
      return false;
    t = (height - b.dot(D)) / span;
    return t > 0.0 && t < 1.0;
  };
  auto add = [&](double u, double t, bool continuum) {
    PatchFootpoint f;
    f.u = swept.alongV ? u : t;
    f.v = swept.alongV ? t : u;
    f.point = (1.0 - t) * swept.low.evaluate(u) + t * swept.high.evaluate(u);
    f.distance = (f.point - query).norm();
    f.continuum = continuum;
    f.onBoundary = false;
    if (f.distance <= maxDistance)
      found.push_back(f);
  };
  for (const CurveFootpoint& c : curveFootpoints(swept.profile, flat, maxDistance))
  {
    if (c.atEnd)
      continue; // (one-sided: a minimum of the patch's side, which the sides' search finds)
    double t = 0.0;
    if (!c.continuum)
    {
      if (lift(c.t, t))
        add(c.t, t, false);
      continue;
    }
    // The query on the profile's centre (a cylinder's axis): every u is a foot of the
    // profile; the patch's minimum is wherever the query's height lies between the
    // sections — the u where it lies deepest inside of a fine sampling stands for them.
    double best = 0.0, bestU = -1.0, bestT = 0.0;
    for (int k = 0; k <= 64; ++k)
    {
      const double u = k / 64.0;
      if (lift(u, t) && std::min(t, 1.0 - t) > best)
      {
        best = std::min(t, 1.0 - t);
        bestU = u;
        bestT = t;
      }
    }
    if (bestU >= 0.0)
      add(bestU, bestT, true);
  }
  return found;
}

} // namespace exactmat

#include "Flatten.h"

namespace exactmat
{

double chordDeviation(const BezierCurve& c)
{
  const Vec3 a = c.startPoint(), b = c.endPoint();
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  double dev = 0.0;
  for (int i = 1; i < c.degree(); ++i)
  {
    const Vec3 p = c.controlPoint(i) - a;
    const double t = len2 > 0.0 ? p.dot(ab) / len2 : 0.0;
    dev = std::max(dev, (p - t * ab).norm());
  }
  return dev;
}

namespace
{
template <typename Emit>
void recurse(const BezierCurve& c, double tol, int depth, Emit& emit)
{
  if (depth >= MaxFlattenDepth || chordDeviation(c) <= tol)
  {
    emit(c);
    return;
  }
  BezierCurve l, r;
  c.split(0.5, l, r);
  recurse(l, tol, depth + 1, emit);
  recurse(r, tol, depth + 1, emit);
}

template <typename Emit>
void halves(const BezierCurve& curve, double tolerance, Emit& emit)
{
  // Always split once: a closed single curve would otherwise be one degenerate chord.
  BezierCurve l, r;
  curve.split(0.5, l, r);
  recurse(l, tolerance, 1, emit);
  recurse(r, tolerance, 1, emit);
}
} // namespace

Vec3List flatten(const BezierCurve& curve, double tolerance)
{
  Vec3List out{ curve.startPoint() };
  auto emit = [&out](const BezierCurve& part) { out.push_back(part.endPoint()); };
  halves(curve, tolerance, emit);
  return out;
}

std::vector<BezierCurve> flattenParts(const BezierCurve& curve, double tolerance)
{
  std::vector<BezierCurve> out;
  auto emit = [&out](const BezierCurve& part) { out.push_back(part); };
  halves(curve, tolerance, emit);
  return out;
}

} // namespace exactmat

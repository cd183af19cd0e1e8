#include "RandomShapes.h"

#include "common/Format.h"
#include "shapes/Primitives.h"

#include <cmath>

namespace exactmat
{

namespace
{
constexpr double TwoPi = 6.283185307179586;

double uniform(RandomEngine& rng, double lo, double hi)
{
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

int uniformInt(RandomEngine& rng, int lo, int hi)
{
  return std::uniform_int_distribution<int>(lo, hi)(rng);
}

NurbsCurve circle(const Vec3& centre, double r, bool clockwise)
{
  return clockwise ? makeArc(centre, r, TwoPi, 0.0) : makeArc(centre, r, 0.0, TwoPi);
}
} // namespace

RandomShape randomStarPolygon(RandomEngine& rng, int edges)
{
  Vec3List corners;
  for (int k = 0; k < edges; ++k)
  {
    const double t = (k + uniform(rng, -0.25, 0.25)) * TwoPi / edges;
    const double r = uniform(rng, 0.5, 1.5);
    corners.push_back(Vec3(r * std::cos(t), r * std::sin(t), 0.0));
  }
  return { "star polygon, " + std::to_string(edges) + " edges", makePolygon(corners), 0 };
}

RandomShape perturbedRegularPolygon(RandomEngine& rng, int edges, double jitter)
{
  Vec3List corners;
  for (int k = 0; k < edges; ++k)
  {
    const double t = TwoPi * k / edges;
    const double a = uniform(rng, 0.0, TwoPi), d = jitter * std::sqrt(uniform(rng, 0.0, 1.0));
    corners.push_back(Vec3(std::cos(t) + d * std::cos(a), std::sin(t) + d * std::sin(a), 0.0));
  }
  return { "regular " + std::to_string(edges) + "-gon jittered by " + format(jitter),
    makePolygon(corners), 0 };
}

RandomShape randomBlob(RandomEngine& rng, int maxHoles)
{
  const int p = 3, count = uniformInt(rng, 12, 24);
  Vec3List pts;
  std::vector<double> weights;
  for (int i = 0; i < count; ++i)
  {
    const double t = TwoPi * i / count, r = uniform(rng, 0.6, 1.0);
    pts.push_back(Vec3(r * std::cos(t), r * std::sin(t), 0.0));
    weights.push_back(uniform(rng, 0.5, 2.0));
  }
  // Uniform unclamped knots with the first p points repeated: a closed C² curve. Its
  // points stay within the hull of 4 consecutive control points: outside radius 0.42.
  for (int i = 0; i < p; ++i)
  {
    pts.push_back(pts[i]);
    weights.push_back(weights[i]);
  }
  const int n = static_cast<int>(pts.size());
  KnotVector knots(n + p + 1);
  for (int i = 0; i < n + p + 1; ++i)
    knots[i] = static_cast<double>(i - p) / count;
  RandomShape shape{ "", { NurbsCurve(p, knots, pts, weights) }, 0 };
  std::vector<std::pair<Vec3, double>> holes;
  const int wanted = uniformInt(rng, 0, maxHoles);
  for (int attempt = 0; attempt < 50 && static_cast<int>(holes.size()) < wanted; ++attempt)
  {
    const double r = uniform(rng, 0.03, 0.08), d = uniform(rng, 0.0, 0.38 - r),
                 a = uniform(rng, 0.0, TwoPi);
    const Vec3 c(d * std::cos(a), d * std::sin(a), 0.0);
    bool free = true;
    for (const auto& [o, s] : holes)
      free = free && (o - c).norm() > r + s + 0.02;
    if (free)
      holes.push_back({ c, r });
  }
  for (const auto& [c, r] : holes)
    shape.curves.push_back(circle(c, r, uniform(rng, 0.0, 1.0) < 0.5));
  shape.holes = static_cast<int>(holes.size());
  shape.description = "rational cubic blob, " + std::to_string(count) + " control points, " +
    std::to_string(shape.holes) + " holes";
  return shape;
}

RandomShape randomDomain(RandomEngine& rng, int maxEdges)
{
  switch (uniformInt(rng, 0, 3))
  {
    case 0:
      return randomStarPolygon(rng, uniformInt(rng, 10, std::max(10, maxEdges)));
    case 1:
      return perturbedRegularPolygon(rng, uniformInt(rng, 3, 12), std::pow(10.0, uniform(rng, -9, -3)));
    case 2:
    {
      const int corners = 2 * uniformInt(rng, 2, std::max(2, maxEdges / 4));
      return { "saw-tooth strip, " + std::to_string(corners) + " corners", makeSawToothStrip(corners), 0 };
    }
    default:
      return randomBlob(rng, 3);
  }
}

Vec3 ShapeMotion::apply(const Vec3& p) const
{
  const double c = std::cos(angle), s = std::sin(angle);
  return Vec3(c * p.x() - s * p.y(), s * p.x() + c * p.y(), p.z()) * scale + offset;
}

NurbsCurve ShapeMotion::apply(const NurbsCurve& curve) const
{
  Vec3List points;
  std::vector<double> weights;
  for (int i = 0; i < curve.controlPointCount(); ++i)
  {
    points.push_back(apply(curve.controlPoint(i)));
    weights.push_back(curve.weight(i) * weightScale);
  }
  return NurbsCurve(curve.degree(), curve.knots(), points, weights);
}

std::vector<NurbsCurve> ShapeMotion::apply(const std::vector<NurbsCurve>& curves) const
{
  std::vector<NurbsCurve> out;
  for (const NurbsCurve& c : curves)
    out.push_back(apply(c));
  return out;
}

std::string ShapeMotion::describe() const
{
  return "rotated by " + format(angle) + " rad, scaled by " + format(scale) + ", moved by " +
    format(offset) + ", weights x " + format(weightScale);
}

ShapeMotion randomMotion(RandomEngine& rng)
{
  ShapeMotion m;
  m.angle = uniform(rng, 0.0, TwoPi);
  m.scale = std::pow(10.0, uniform(rng, -6.0, 6.0));
  const double a = uniform(rng, 0.0, TwoPi), d = m.scale * std::pow(10.0, uniform(rng, -1.0, 7.0));
  m.offset = Vec3(d * std::cos(a), d * std::sin(a), 0.0);
  m.weightScale = std::pow(10.0, uniform(rng, -100.0, 100.0));
  return m;
}

} // namespace exactmat

#include "Primitives.h"

#include <array>
#include <cmath>

namespace exactmat
{

NurbsCurve makeSegment(const Vec3& a, const Vec3& b)
{
  return NurbsCurve(1, { 0.0, 0.0, 1.0, 1.0 }, Vec3List{ a, b });
}

NurbsCurve makeArc(const Vec3& centre, double radius, double a0, double a1)
{
  const double sweep = a1 - a0;
  const int spans = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / (M_PI / 2) - 1e-9)));
  const double step = sweep / spans;
  const double w1 = std::cos(step / 2.0);
  Vec3List points;
  std::vector<double> weights;
  auto on = [&](double a) {
    return Vec3(centre.x() + radius * std::cos(a), centre.y() + radius * std::sin(a), centre.z());
  };
  KnotVector knots{ 0.0, 0.0, 0.0 };
  points.push_back(on(a0));
  weights.push_back(1.0);
  for (int k = 0; k < spans; ++k)
  {
    const double mid = a0 + (k + 0.5) * step;
    // The middle control point lies on the bisector at distance r / cos(step/2).
    points.push_back(Vec3(centre.x() + radius / w1 * std::cos(mid),
      centre.y() + radius / w1 * std::sin(mid), centre.z()));
    weights.push_back(w1);
    points.push_back(on(a0 + (k + 1) * step));
    weights.push_back(1.0);
    if (k + 1 < spans)
    {
      knots.push_back(static_cast<double>(k + 1) / spans);
      knots.push_back(static_cast<double>(k + 1) / spans);
    }
  }
  knots.insert(knots.end(), { 1.0, 1.0, 1.0 });
  // Snap the end exactly onto the requested angle for full circles (closing the loop).
  if (std::abs(std::abs(sweep) - 2 * M_PI) < 1e-12)
  {
    points.back() = points.front();
  }
  return NurbsCurve(2, knots, points, weights);
}

std::vector<NurbsCurve> makePolygon(const Vec3List& corners)
{
  std::vector<NurbsCurve> edges;
  for (size_t i = 0; i < corners.size(); ++i)
  {
    edges.push_back(makeSegment(corners[i], corners[(i + 1) % corners.size()]));
  }
  return edges;
}

NurbsSurface makeExtrusion(const NurbsCurve& profile, const Vec3& direction, double length)
{
  const int n = profile.controlPointCount();
  Vec4List net;
  for (int i = 0; i < n; ++i)
  {
    const Vec4& h = profile.homogeneousPoints()[i];
    net.push_back(h);
    Vec4 top = h;
    top.head<3>() += h.w() * length * direction.normalized();
    net.push_back(top);
  }
  return NurbsSurface(
    profile.degree(), 1, profile.knots(), { 0.0, 0.0, 1.0, 1.0 }, n, 2, std::move(net));
}

NurbsSurface makeRevolution(const NurbsCurve& profile)
{
  const NurbsCurve circle = makeArc(Vec3::Zero(), 1.0, 0.0, 2.0 * M_PI);
  const int n = profile.controlPointCount(), m = circle.controlPointCount();
  Vec4List net;
  for (int i = 0; i < n; ++i)
  {
    const Vec3 p = profile.controlPoint(i);
    const double w = profile.weight(i);
    for (int j = 0; j < m; ++j)
    {
      const Vec3 c = circle.controlPoint(j);
      net.push_back(homogeneous(Vec3(p.x() * c.x(), p.x() * c.y(), p.z()), w * circle.weight(j)));
    }
  }
  return NurbsSurface(profile.degree(), 2, profile.knots(), circle.knots(), n, m, std::move(net));
}

NurbsSurface torusSurface(double core, double tube)
{
  const NurbsCurve circle = makeArc(Vec3::Zero(), tube, 0.0, 2.0 * M_PI);
  Vec4List points = circle.homogeneousPoints();
  for (Vec4& p : points)
    p = Vec4(p.x() + core * p.w(), 0.0, p.y(), p.w()); // (x, y) of the circle → (core + x, 0, y)
  return makeRevolution(NurbsCurve(circle.degree(), circle.knots(), points));
}

std::vector<NurbsCurve> makeSawToothStrip(int corners)
{
  const int teeth = std::max(2, corners / 2);
  Vec3List c;
  for (int k = 0; k < teeth; ++k)
    c.push_back(Vec3(0.5 * k, (k % 2) ? -0.15 : 0.0, 0));
  for (int k = teeth - 1; k >= 0; --k)
    c.push_back(Vec3(0.5 * k, (k % 2) ? 1.15 : 1.0, 0));
  return makePolygon(c);
}

NurbsCurve makeWavyStrip(int spans)
{
  // The control polygon runs along the top, then back along the bottom; the first three
  // points repeated with uniform knots close it with C² continuity.
  const int p = 3, half = std::max(4, spans / 2);
  Vec3List pts;
  for (int i = 0; i < half; ++i)
    pts.push_back(Vec3(0.5 * i, 0.12 * std::sin(1.3 * i), 0));
  for (int i = half - 1; i >= 0; --i)
    pts.push_back(Vec3(0.5 * i, 1.0 + 0.12 * std::sin(1.7 * i + 0.5), 0));
  for (int i = 0; i < p; ++i)
    pts.push_back(pts[i]);
  KnotVector k(pts.size() + p + 1);
  for (size_t i = 0; i < k.size(); ++i)
    k[i] = static_cast<double>(i);
  return NurbsCurve(p, k, pts);
}

std::vector<NurbsSurface> ellipsoidSurfaces(const Vec3& semiAxes, double cutLatitude, int polarAxis)
{
  // A rational quadratic arc of the unit circle from angle α to β: points and weights.
  auto arc = [](double alpha, double beta, std::array<Vec3, 3>& p, std::array<double, 3>& w) {
    const double half = 0.5 * (beta - alpha), middle = 0.5 * (alpha + beta);
    p = { Vec3(std::cos(alpha), std::sin(alpha), 0.0), Vec3(std::cos(middle), std::sin(middle), 0.0) / std::cos(half),
      Vec3(std::cos(beta), std::sin(beta), 0.0) };
    w = { 1.0, std::cos(half), 1.0 };
    for (Vec3& point : p) // the poles' ρ exactly 0 (cos(−π/2) is 6e-17): collapsed sides
      for (int i = 0; i < 2; ++i)
        point(i) = std::abs(point(i)) < 1e-15 ? 0.0 : point(i);
  };
  const double cuts[3] = { -M_PI / 2, cutLatitude, M_PI / 2 };
  std::vector<NurbsSurface> faces;
  for (int band = 0; band < 2; ++band)
  {
    std::array<Vec3, 3> m; // (ρ, z) of the meridian arc in x, y
    std::array<double, 3> mw;
    arc(cuts[band], cuts[band + 1], m, mw);
    for (int k = 0; k < 4; ++k)
    {
      std::array<Vec3, 3> e; // the azimuth arc
      std::array<double, 3> ew;
      arc(M_PI / 4 + k * M_PI / 2, 3 * M_PI / 4 + k * M_PI / 2, e, ew);
      Vec3List net(9);
      std::vector<double> w(9);
      // u along the azimuth, v along the meridian (south to north): Su × Sv points out. The
      // polar axis is turned onto x or y by a cyclic exchange of the axes (a rotation).
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
        {
          const Vec3 unit(m[j].x() * e[i].x(), m[j].x() * e[i].y(), m[j].y());
          const Vec3 turned = polarAxis == 2 ? unit
            : polarAxis == 0                 ? Vec3(unit.z(), unit.x(), unit.y())
                                             : Vec3(unit.y(), unit.z(), unit.x());
          net[i * 3 + j] = turned.cwiseProduct(semiAxes);
          w[i * 3 + j] = ew[i] * mw[j];
        }
      faces.emplace_back(2, 2, KnotVector{ 0, 0, 0, 1, 1, 1 }, KnotVector{ 0, 0, 0, 1, 1, 1 }, 3, 3, net, w);
    }
  }
  return faces;
}

} // namespace exactmat

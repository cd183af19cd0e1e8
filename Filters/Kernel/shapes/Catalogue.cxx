#include "Catalogue.h"

#include "common/InputError.h"
#include "nurbs/BezierExtraction.h"
#include "shapes/Primitives.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

namespace exactmat
{

namespace
{
void requirePositive(double v, const char* parameter, const std::string& shape)
{
  if (!(v > 0.0) || !std::isfinite(v))
  {
    fail("shape '", shape, "': parameter ", parameter, " = ", v, " must be positive");
  }
}

NurbsCurve reversedCurve(const NurbsCurve& c)
{
  KnotVector k = c.knots();
  const double a = k.front(), b = k.back();
  KnotVector r(k.size());
  for (size_t i = 0; i < k.size(); ++i)
  {
    r[i] = a + b - k[k.size() - 1 - i];
  }
  Vec4List p(c.homogeneousPoints().rbegin(), c.homogeneousPoints().rend());
  return NurbsCurve(c.degree(), r, p);
}

// Closed periodic cubic B-spline through no point in particular: control points on
// r(θ) = radius·(1 + amp·cos(lobes·θ)) around `centre`; uniform unclamped knots with the
// first three control points repeated, so the curve closes with C² continuity.
NurbsCurve periodicBlob(const Vec3& centre, double radius, double amp, int lobes, int count,
  double phase = 0.0)
{
  const int p = 3;
  Vec3List pts;
  for (int i = 0; i < count; ++i)
  {
    const double t = 2.0 * M_PI * i / count;
    const double r = radius * (1.0 + amp * std::cos(lobes * t + phase));
    pts.push_back(centre + Vec3(r * std::cos(t), r * std::sin(t), 0.0));
  }
  for (int i = 0; i < p; ++i)
  {
    pts.push_back(pts[i]);
  }
  const int n = static_cast<int>(pts.size());
  KnotVector knots(n + p + 1);
  for (int i = 0; i < n + p + 1; ++i)
  {
    knots[i] = static_cast<double>(i - p) / count;
  }
  return NurbsCurve(p, knots, pts);
}

// More points or lobes than a boundary of a million pieces is a typo, not a shape: an
// error instead of an allocation that fails.
constexpr int MaximumCount = 250000;

NurbsCurve circleCurve(const Vec3& centre, double r, bool clockwise = false)
{
  return clockwise ? makeArc(centre, r, 2.0 * M_PI, 0.0) : makeArc(centre, r, 0.0, 2.0 * M_PI);
}

NurbsCurve scaled(const NurbsCurve& c, double sx, double sy)
{
  Vec4List p = c.homogeneousPoints();
  for (Vec4& h : p)
  {
    h.x() *= sx;
    h.y() *= sy;
  }
  return NurbsCurve(c.degree(), c.knots(), p);
}

NurbsCurve translated(const NurbsCurve& c, const Vec3& d)
{
  Vec4List p = c.homogeneousPoints();
  for (Vec4& h : p)
  {
    h.head<3>() += h.w() * d;
  }
  return NurbsCurve(c.degree(), c.knots(), p);
}

// A clamped cubic B-spline with the given control points.
NurbsCurve cubicThrough(const Vec3List& pts)
{
  return NurbsCurve(3, clampedUniformKnots(3, static_cast<int>(pts.size())), pts);
}

// Bilinear/bicubic helpers for the 3D shapes ------------------------------------------

NurbsSurface bezierSurface(int p, int q, const Vec3List& net, const std::vector<double>& w = {})
{
  KnotVector ku(2 * (p + 1), 0.0), kv(2 * (q + 1), 0.0);
  std::fill(ku.begin() + p + 1, ku.end(), 1.0);
  std::fill(kv.begin() + q + 1, kv.end(), 1.0);
  return NurbsSurface(p, q, ku, kv, p + 1, q + 1, net, w);
}

// Quad (a, b, c, d counter-clockwise seen from outside) as a bilinear patch with outward
// normal: u along a→b, v along a→d.
NurbsSurface quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  return bezierSurface(1, 1, Vec3List{ a, d, b, c });
}

// The box's faces counter-clockwise seen from outside (normals out), or clockwise (normals
// in: the box as a cavity, its faces pointing away from the material around it).
std::vector<NurbsSurface> boxFaces(double w, double h, double l, const Vec3& centre = Vec3::Zero(), bool inward = false)
{
  const double x = w / 2, y = h / 2, z = l / 2;
  auto P = [&](int i, int j, int k) -> Vec3 { return centre + Vec3(i ? x : -x, j ? y : -y, k ? z : -z); };
  const std::array<std::array<Vec3, 4>, 6> corners{ {
    { { P(0, 0, 0), P(0, 1, 0), P(1, 1, 0), P(1, 0, 0) } }, // z = −z, normal −z
    { { P(0, 0, 1), P(1, 0, 1), P(1, 1, 1), P(0, 1, 1) } }, // z = +z
    { { P(0, 0, 0), P(1, 0, 0), P(1, 0, 1), P(0, 0, 1) } }, // y = −y
    { { P(0, 1, 0), P(0, 1, 1), P(1, 1, 1), P(1, 1, 0) } }, // y = +y
    { { P(0, 0, 0), P(0, 0, 1), P(0, 1, 1), P(0, 1, 0) } }, // x = −x
    { { P(1, 0, 0), P(1, 1, 0), P(1, 1, 1), P(1, 0, 1) } }, // x = +x
  } };
  std::vector<NurbsSurface> faces;
  for (const auto& c : corners)
    faces.push_back(inward ? quad(c[0], c[3], c[2], c[1]) : quad(c[0], c[1], c[2], c[3]));
  return faces;
}

// The boundary of the filled cells of a grid with cell walls at xs × ys × zs: one bilinear
// square per exposed cell side, counter-clockwise seen from outside (coplanar squares meet
// at smooth edges, so every face conforms).
std::vector<NurbsSurface> gridSolidFaces(const std::array<std::vector<double>, 3>& walls,
  const std::function<bool(int, int, int)>& filled)
{
  const int n[3] = { static_cast<int>(walls[0].size()) - 1, static_cast<int>(walls[1].size()) - 1,
    static_cast<int>(walls[2].size()) - 1 };
  auto inside = [&](const std::array<int, 3>& c) {
    return c[0] >= 0 && c[0] < n[0] && c[1] >= 0 && c[1] < n[1] && c[2] >= 0 && c[2] < n[2] && filled(c[0], c[1], c[2]);
  };
  std::vector<NurbsSurface> faces;
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j)
      for (int k = 0; k < n[2]; ++k)
      {
        const std::array<int, 3> cell{ { i, j, k } };
        if (!inside(cell))
          continue;
        for (int a = 0; a < 3; ++a)
          for (int side : { -1, 1 })
          {
            std::array<int, 3> next = cell;
            next[a] += side;
            if (inside(next))
              continue;
            // Corners (u, v) along the two other axes b, c with e_b × e_c = e_a:
            // counter-clockwise seen from outside on the + side, reversed on the − side.
            const int b = (a + 1) % 3, c = (a + 2) % 3;
            auto corner = [&](int u, int v) {
              Vec3 p;
              p[a] = walls[a][cell[a] + (side > 0 ? 1 : 0)];
              p[b] = walls[b][cell[b] + u];
              p[c] = walls[c][cell[c] + v];
              return p;
            };
            if (side > 0)
              faces.push_back(quad(corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)));
            else
              faces.push_back(quad(corner(0, 0), corner(0, 1), corner(1, 1), corner(1, 0)));
          }
      }
  return faces;
}

// The cube of edge w centred at the origin with the corner cube of edge w/2 at (+, +, +) cut
// away: three reflex edges meet at the reflex corner at the origin.
std::vector<NurbsSurface> notchedCubeFaces(double w)
{
  const std::vector<double> walls{ -w / 2, 0.0, w / 2 };
  return gridSolidFaces({ walls, walls, walls }, [](int i, int j, int k) { return !(i == 1 && j == 1 && k == 1); });
}

// Two unioned boxes: a w × h × l/2 base (centred on the z axis, from z = −l/2 to 0) and a
// w/2 × h/2 × l/2 block centred on top of it — four reflex edges around the block's foot,
// corners where they meet its convex vertical edges.
std::vector<NurbsSurface> steppedBlockFaces(double w, double h, double l)
{
  const std::vector<double> xs{ -w / 2, -w / 4, w / 4, w / 2 }, ys{ -h / 2, -h / 4, h / 4, h / 2 },
    zs{ -l / 2, 0.0, l / 2 };
  return gridSolidFaces({ xs, ys, zs }, [](int i, int j, int k) { return k == 0 || (i == 1 && j == 1); });
}

// A disk of radius r at height z as one rational biquadratic patch whose four sides are the
// quarter arcs 225°→315°, 315°→45°, 45°→135°, 135°→225°, i.e. the same arcs as the sides
// of the cylinder. The centre weight 1/2 is the tensor product of the arc weights.
NurbsSurface diskPatch(double r, double z, bool up)
{
  const double s = std::sqrt(0.5), c = r * s, m = r / s;
  Vec3List net(9);
  std::vector<double> w(9);
  auto set = [&](int i, int j, const Vec3& p, double wt) {
    net[i * 3 + j] = p;
    w[i * 3 + j] = wt;
  };
  set(0, 0, Vec3(-c, -c, z), 1.0);
  set(1, 0, Vec3(0, -m, z), s);
  set(2, 0, Vec3(c, -c, z), 1.0);
  set(0, 1, Vec3(-m, 0, z), s);
  set(1, 1, Vec3(0, 0, z), 0.5);
  set(2, 1, Vec3(m, 0, z), s);
  set(0, 2, Vec3(-c, c, z), 1.0);
  set(1, 2, Vec3(0, m, z), s);
  set(2, 2, Vec3(c, c, z), 1.0);
  NurbsSurface disk = bezierSurface(2, 2, net, w);
  if (!up)
  {
    // Exchange u and v to turn the normal downwards.
    Vec3List t(9);
    std::vector<double> tw(9);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
      {
        t[j * 3 + i] = net[i * 3 + j];
        tw[j * 3 + i] = w[i * 3 + j];
      }
    disk = bezierSurface(2, 2, t, tw);
  }
  return disk;
}

std::vector<NurbsSurface> cylinderFaces(double r, double l)
{
  std::vector<NurbsSurface> faces;
  for (int k = 0; k < 4; ++k)
  {
    const double a0 = M_PI / 4 + k * M_PI / 2;
    const NurbsCurve arc = makeArc(Vec3(0, 0, -l / 2), r, a0, a0 + M_PI / 2);
    faces.push_back(makeExtrusion(arc, Vec3::UnitZ(), l));
  }
  faces.push_back(diskPatch(r, l / 2, true));
  faces.push_back(diskPatch(r, -l / 2, false));
  return faces;
}

// A cube [−a, a]³ whose six faces are bicubic patches bulging outwards by `bulge`.
std::vector<NurbsSurface> pillowFaces(double a, double bulge)
{
  std::vector<NurbsSurface> faces;
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int side = -1; side <= 1; side += 2)
    {
      // Face frame: normal n = side·e_axis; (e1, e2) with e1×e2 = n.
      Vec3 n = Vec3::Zero();
      n(axis) = side;
      Vec3 e1 = Vec3::Zero();
      e1((axis + 1) % 3) = 1.0;
      const Vec3 e2 = n.cross(e1);
      Vec3List net(16);
      for (int i = 0; i < 4; ++i)
      {
        for (int j = 0; j < 4; ++j)
        {
          const double s = -a + 2.0 * a * i / 3.0, t = -a + 2.0 * a * j / 3.0;
          const bool interior = (i == 1 || i == 2) && (j == 1 || j == 2);
          net[i * 4 + j] = a * n + s * e1 + t * e2 + (interior ? Vec3(bulge * n) : Vec3(Vec3::Zero()));
        }
      }
      faces.push_back(bezierSurface(3, 3, net));
    }
  }
  return faces;
}

// The extrusion of a star-shaped closed profile: side surfaces, and each cap as a fan of
// ruled patches from the profile's Bézier pieces to `centre` (planar, exact).
std::vector<NurbsSurface> extrusionFaces(const NurbsCurve& profile, const Vec3& centre, double l)
{
  std::vector<NurbsSurface> faces{ makeExtrusion(profile, Vec3::UnitZ(), l) };
  for (const BezierSpan& span : extractBezier(profile))
  {
    const BezierCurve& c = span.curve;
    for (int top = 0; top <= 1; ++top)
    {
      const double z = top ? l : 0.0;
      Vec4List net;
      // u from the rim to the centre; v along the piece (reversed on the top cap so that
      // the normal points out: +z on top, −z below).
      const int p = c.degree();
      for (int i = 0; i <= 1; ++i)
      {
        for (int j = 0; j <= p; ++j)
        {
          const int k = top ? j : p - j;
          const Vec4& h = c.homogeneousPoints()[k];
          Vec3 pt = (i == 0) ? euclidean(h) : centre;
          pt.z() = z;
          net.push_back(homogeneous(pt, h.w()));
        }
      }
      KnotVector kv(2 * (p + 1), 0.0);
      std::fill(kv.begin() + p + 1, kv.end(), 1.0);
      faces.emplace_back(1, p, KnotVector{ 0, 0, 1, 1 }, kv, 2, p + 1, std::move(net));
    }
  }
  return faces;
}

NurbsCurve profileBlob(const ShapeParameters& s, const Vec3& centre)
{
  return periodicBlob(centre, s.radius, 0.25, 3, 12);
}
} // namespace

const std::vector<std::string>& catalogueNames()
{
  static const std::vector<std::string> names{ "rectangle", "rounded-rectangle", "circle",
    "ellipse", "annulus", "l-shape", "star", "blob", "spiral", "plate-with-holes",
    "narrow-passage", "box", "cylinder", "pillow", "extrusion", "revolution", "notched-cube", "stepped-block",
    "box-with-cavity", "ellipsoid", "torus" };
  return names;
}

Shape makeShape(const std::string& name, const ShapeParameters& s)
{
  Shape shape;
  shape.name = name;
  const double w = s.width, h = s.height;
  if (name == "rectangle")
  {
    requirePositive(w, "width", name);
    requirePositive(h, "height", name);
    shape.curves = makePolygon(
      { Vec3(-w / 2, -h / 2, 0), Vec3(w / 2, -h / 2, 0), Vec3(w / 2, h / 2, 0), Vec3(-w / 2, h / 2, 0) });
  }
  else if (name == "rounded-rectangle")
  {
    requirePositive(w, "width", name);
    requirePositive(h, "height", name);
    requirePositive(s.cornerRadius, "cornerRadius", name);
    const double r = s.cornerRadius;
    if (!(2 * r < std::min(w, h)))
    {
      fail("shape '", name, "': cornerRadius ", r, " must be less than half of min(width, height)");
    }
    const double x = w / 2 - r, y = h / 2 - r;
    shape.curves = {
      makeSegment(Vec3(-x, -h / 2, 0), Vec3(x, -h / 2, 0)),
      makeArc(Vec3(x, -y, 0), r, -M_PI / 2, 0.0),
      makeSegment(Vec3(w / 2, -y, 0), Vec3(w / 2, y, 0)),
      makeArc(Vec3(x, y, 0), r, 0.0, M_PI / 2),
      makeSegment(Vec3(x, h / 2, 0), Vec3(-x, h / 2, 0)),
      makeArc(Vec3(-x, y, 0), r, M_PI / 2, M_PI),
      makeSegment(Vec3(-w / 2, y, 0), Vec3(-w / 2, -y, 0)),
      makeArc(Vec3(-x, -y, 0), r, M_PI, 1.5 * M_PI),
    };
  }
  else if (name == "circle")
  {
    requirePositive(s.radius, "radius", name);
    shape.curves = { circleCurve(Vec3::Zero(), s.radius) };
  }
  else if (name == "ellipse")
  {
    requirePositive(w, "width", name);
    requirePositive(h, "height", name);
    shape.curves = { scaled(circleCurve(Vec3::Zero(), 1.0), w / 2, h / 2) };
  }
  else if (name == "annulus")
  {
    requirePositive(s.radius, "radius", name);
    requirePositive(s.innerRadius, "innerRadius", name);
    if (!(s.innerRadius < s.radius))
    {
      fail("shape '", name, "': innerRadius ", s.innerRadius, " must be less than radius ", s.radius);
    }
    shape.curves = { circleCurve(Vec3::Zero(), s.radius),
      circleCurve(Vec3::Zero(), s.innerRadius, true) };
  }
  else if (name == "l-shape")
  {
    requirePositive(w, "width", name);
    requirePositive(h, "height", name);
    const double t = s.thickness;
    if (!(t > 0 && t < std::min(w, h)))
    {
      fail("shape '", name, "': thickness ", t, " must be in (0, min(width, height))");
    }
    shape.curves = makePolygon({ Vec3(0, 0, 0), Vec3(w, 0, 0), Vec3(w, t, 0), Vec3(t, t, 0),
      Vec3(t, h, 0), Vec3(0, h, 0) });
  }
  else if (name == "star")
  {
    requirePositive(s.radius, "radius", name);
    requirePositive(s.innerRadius, "innerRadius", name);
    if (s.count < 3 || s.count > MaximumCount || !(s.innerRadius < s.radius))
    {
      fail("shape '", name, "': needs count from 3 to ", MaximumCount, " and innerRadius < radius (got count ",
        s.count, ")");
    }
    Vec3List corners;
    for (int k = 0; k < 2 * s.count; ++k)
    {
      const double a = M_PI / 2 + M_PI * k / s.count;
      const double r = (k % 2 == 0) ? s.radius : s.innerRadius;
      corners.push_back(Vec3(r * std::cos(a), r * std::sin(a), 0));
    }
    shape.curves = makePolygon(corners);
  }
  else if (name == "blob")
  {
    requirePositive(s.radius, "radius", name);
    if (s.count < 2 || s.count > MaximumCount)
    {
      fail("shape '", name, "': count (lobes) must be from 2 to ", MaximumCount, " (got ", s.count, ")");
    }
    shape.curves = { periodicBlob(Vec3::Zero(), s.radius, 0.3, s.count, 4 * s.count) };
  }
  else if (name == "spiral")
  {
    requirePositive(s.radius, "radius", name);
    // A strip of width 0.3·pitch around r(θ) = radius·(0.5 + θ/2π), 2.25 turns; sides are
    // clamped cubic B-splines, ends straight caps.
    const double pitch = s.radius, width = 0.3 * pitch;
    Vec3List outer, inner;
    const int samples = 48;
    const double turns = 2.25;
    for (int i = 0; i <= samples; ++i)
    {
      const double th = 2.0 * M_PI * turns * i / samples;
      const double r = s.radius * 0.5 + pitch * th / (2.0 * M_PI);
      outer.push_back(Vec3((r + width / 2) * std::cos(th), (r + width / 2) * std::sin(th), 0));
      inner.push_back(Vec3((r - width / 2) * std::cos(th), (r - width / 2) * std::sin(th), 0));
    }
    const NurbsCurve out = cubicThrough(outer);
    const NurbsCurve in = reversedCurve(cubicThrough(inner));
    shape.curves = { out, makeSegment(outer.back(), inner.back()), in,
      makeSegment(inner.front(), outer.front()) };
  }
  else if (name == "plate-with-holes")
  {
    requirePositive(w, "width", name);
    requirePositive(h, "height", name);
    shape.curves = makePolygon(
      { Vec3(-w / 2, -h / 2, 0), Vec3(w / 2, -h / 2, 0), Vec3(w / 2, h / 2, 0), Vec3(-w / 2, h / 2, 0) });
    const double u = std::min(w / 4, h / 2);
    shape.curves.push_back(circleCurve(Vec3(-w / 4, 0, 0), 0.4 * u, true));
    shape.curves.push_back(reversedCurve(
      translated(scaled(circleCurve(Vec3::Zero(), 1.0), 0.35 * u, 0.2 * u), Vec3(w / 4, h / 5, 0))));
    shape.curves.push_back(
      reversedCurve(periodicBlob(Vec3(w / 4, -h / 4, 0), 0.18 * u, 0.3, 3, 12)));
  }
  else if (name == "narrow-passage")
  {
    requirePositive(s.radius, "radius", name);
    const double R = s.radius, half = 0.15 * R, c = 1.8 * R;
    const double a = std::asin(half / R), x = R * std::cos(a);
    shape.curves = {
      makeArc(Vec3(c, 0, 0), R, -M_PI + a, M_PI - a),
      makeSegment(Vec3(c - x, half, 0), Vec3(-c + x, half, 0)),
      makeArc(Vec3(-c, 0, 0), R, a, 2.0 * M_PI - a),
      makeSegment(Vec3(-c + x, -half, 0), Vec3(c - x, -half, 0)),
    };
    // Close the loop exactly: the arcs' computed ends and the segment ends must coincide.
  }
  else if (name == "box")
  {
    requirePositive(w, "width", name);
    requirePositive(h, "height", name);
    requirePositive(s.length, "length", name);
    shape.dimension = 3;
    shape.surfaces = boxFaces(w, h, s.length);
  }
  else if (name == "box-with-cavity")
  {
    requirePositive(w, "width", name);
    requirePositive(h, "height", name);
    requirePositive(s.length, "length", name);
    requirePositive(s.thickness, "thickness", name);
    // The cube moved along x by an eighth of the room left beside it: off centre, so the
    // MAT has no symmetry to lean on.
    const Vec3 centre((w - s.thickness) / 8.0, 0.0, 0.0);
    if (!(s.thickness < std::min(h, s.length)))
      fail("shape '", name, "': thickness ", s.thickness, " (the cavity's edge) must be less than min(height, length)");
    shape.dimension = 3;
    shape.surfaces = boxFaces(w, h, s.length);
    // The cavity's faces, turned to face into it (away from the material).
    for (NurbsSurface& f : boxFaces(s.thickness, s.thickness, s.thickness, centre, true))
      shape.surfaces.push_back(std::move(f));
  }
  else if (name == "notched-cube")
  {
    requirePositive(w, "width", name);
    shape.dimension = 3;
    shape.surfaces = notchedCubeFaces(w);
  }
  else if (name == "stepped-block")
  {
    requirePositive(w, "width", name);
    requirePositive(h, "height", name);
    requirePositive(s.length, "length", name);
    shape.dimension = 3;
    shape.surfaces = steppedBlockFaces(w, h, s.length);
  }
  else if (name == "cylinder")
  {
    requirePositive(s.radius, "radius", name);
    requirePositive(s.length, "length", name);
    shape.dimension = 3;
    shape.surfaces = cylinderFaces(s.radius, s.length);
  }
  else if (name == "ellipsoid")
  {
    requirePositive(w, "width", name);
    requirePositive(h, "height", name);
    requirePositive(s.length, "length", name);
    shape.dimension = 3;
    // Poles on the shortest axis, the meridians cut at 30°: the rim's touchpoints run along
    // the equator about that axis, inside the patches, through no pole.
    const Vec3 semiAxes(w / 2, h / 2, s.length / 2);
    int polar = 0;
    semiAxes.minCoeff(&polar);
    shape.surfaces = ellipsoidSurfaces(semiAxes, M_PI / 6, polar);
  }
  else if (name == "pillow")
  {
    requirePositive(s.radius, "radius", name);
    shape.dimension = 3;
    shape.surfaces = pillowFaces(s.radius, 0.3 * s.radius);
  }
  else if (name == "extrusion")
  {
    requirePositive(s.radius, "radius", name);
    requirePositive(s.length, "length", name);
    shape.dimension = 3;
    shape.surfaces = extrusionFaces(profileBlob(s, Vec3::Zero()), Vec3::Zero(), s.length);
  }
  else if (name == "revolution")
  {
    requirePositive(s.radius, "radius", name);
    shape.dimension = 3;
    // The blob profile in the xz-plane, centred at x = 2.5·radius (clear of the axis).
    NurbsCurve profile = profileBlob(s, Vec3::Zero());
    Vec4List pts = profile.homogeneousPoints();
    for (Vec4& p : pts)
    {
      const double x = p.x(), y = p.y();
      p = Vec4(x + 2.5 * s.radius * p.w(), 0.0, y, p.w());
    }
    shape.surfaces = { makeRevolution(NurbsCurve(profile.degree(), profile.knots(), pts)) };
  }
  else if (name == "torus")
  {
    requirePositive(w, "width", name);
    requirePositive(s.thickness, "thickness", name);
    if (!(s.thickness < w))
      fail("torus: the thickness (the tube's diameter, ", s.thickness, ") must be less than the width (the core's, ",
        w, ")");
    shape.dimension = 3;
    shape.surfaces = { torusSurface(0.5 * w, 0.5 * s.thickness) };
  }
  else
  {
    std::string known;
    for (const std::string& n : catalogueNames())
    {
      known += (known.empty() ? "" : ", ") + n;
    }
    fail("unknown shape '", name, "' (known: ", known, ")");
  }
  return shape;
}

std::vector<CurvePiece> curvePieces(const std::vector<NurbsCurve>& curves)
{
  std::vector<CurvePiece> pieces;
  for (size_t i = 0; i < curves.size(); ++i)
  {
    curves[i].validate("curve " + std::to_string(i));
    for (const BezierSpan& s : extractBezier(curves[i]))
    {
      CurvePiece p;
      p.curve = s.curve;
      p.entity = static_cast<int>(i);
      pieces.push_back(std::move(p));
    }
  }
  return pieces;
}

std::vector<PatchPiece> patchPieces(const std::vector<NurbsSurface>& surfaces)
{
  std::vector<PatchPiece> pieces;
  for (size_t i = 0; i < surfaces.size(); ++i)
  {
    surfaces[i].validate("surface " + std::to_string(i));
    for (const BezierPatchSpan& s : extractBezier(surfaces[i]))
    {
      PatchPiece p;
      p.patch = s.patch;
      p.entity = static_cast<int>(i);
      pieces.push_back(std::move(p));
    }
  }
  return pieces;
}

} // namespace exactmat

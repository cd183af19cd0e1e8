#include "CentreCurveFootprint.h"

#include "geometry/ClosestPoint.h"
#include "mat3d/BoundarySphere.h"
#include "mat3d/CentreCurve.h"
#include "sheets/SheetCoverage.h"

#include <algorithm>
#include <map>
#include <cmath>

namespace exactmat
{

std::vector<CentreCurveTouches> centreCurveTouches(const MAT3D& mat)
{
  std::vector<CentreCurveTouches> out;
  for (const MAT3DCentreCurve& curve : mat.centreCurves)
  {
    CentreCurveTouches c;
    for (const MedialBall3D& ball : curve.balls)
      if (!ball.touches.empty())
      {
        c.centres.push_back(ball.x);
        c.touches.push_back(ball.touches.front());
      }
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<CentreCurveTouches> centreCurveTouches(const MedialComplex& mat)
{
  std::vector<CentreCurveTouches> out;
  std::map<int, int> ends; // point → the centre curves ending there
  for (const MedialElement& e : mat.elements)
    if (e.type == MedialElementType::CentreCurve && !e.points.empty() && e.points.front() != e.points.back())
    {
      ++ends[e.points.front()];
      ++ends[e.points.back()];
    }
  for (const MedialElement& e : mat.elements)
  {
    if (e.type != MedialElementType::CentreCurve)
      continue;
    // Each point's touch on this curve's circle: its first, but where curves share an end
    // (a rounded box's three spines meet at the centre of its corner's blend) the end's
    // first touch is on one of them only — there the touch nearest to the neighbour's,
    // moved with the centre (circles of contact along a spine are translates), or, when
    // the end does not record one near it, that moved touch itself.
    std::vector<int> ids;
    for (int id : e.points)
      if (!mat.points[id].touches.empty())
        ids.push_back(id);
    CentreCurveTouches c;
    for (size_t k = 0; k < ids.size(); ++k)
    {
      const MedialPoint3D& p = mat.points[ids[k]];
      Vec3 touch = p.touches.front();
      if (ids.size() >= 2 && (k == 0 || k + 1 == ids.size()) && ends[ids[k]] > 1)
      {
        const MedialPoint3D& n = mat.points[ids[k == 0 ? 1 : k - 1]];
        const Vec3 neighbour = k == 0 || c.touches.empty() ? n.touches.front() : c.touches.back();
        const Vec3 moved = neighbour + (p.x - n.x);
        double nearest = INFINITY;
        for (const Vec3& t : p.touches)
          if ((t - moved).norm() < nearest)
          {
            nearest = (t - moved).norm();
            touch = t;
          }
        if (!(nearest <= 1e-6 * p.radius))
          touch = moved;
      }
      c.centres.push_back(p.x);
      c.touches.push_back(touch);
    }
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<double> sphericalFaceFootprints(const Boundary3D& boundary, const MedialComplex& mat, double tolerance)
{
  std::vector<double> covered(boundary.faces().size(), 0.0);
  for (const MedialPoint3D& p : mat.points)
    if (p.type == MedialPoint3DType::SphereCentre || p.type == MedialPoint3DType::CircleCentre)
      for (size_t f = 0; f < covered.size(); ++f)
      {
        const BezierPatch& face = boundary.faces()[f].patch;
        // (The face's middle first: most faces are nowhere near the ball's sphere.)
        if (covered[f] > 0.0 || std::abs((face.evaluate(0.5, 0.5) - p.x).norm() - p.radius) > tolerance ||
          !onSphere(face, { p.x, p.radius }, tolerance))
          continue;
        covered[f] = patchArea(face);
      }
  return covered;
}

namespace
{

// A circle of contact: centre, unit axis (along the curve), radius, and the unit
// directions to the tracked touch (angle 0) and a quarter turn on.
struct Circle
{
  Vec3 centre = Vec3::Zero(), axis = Vec3::UnitZ(), u = Vec3::UnitX(), w = Vec3::UnitY();
  double radius = 0.0;
  Vec3 at(double angle) const { return centre + radius * (std::cos(angle) * u + std::sin(angle) * w); }
};

} // namespace

std::vector<double> centreCurveFootprints(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
  const std::vector<CentreCurveTouches>& curves)
{
  const int faces = static_cast<int>(boundary.faces().size());
  std::vector<double> area(faces, 0.0);
  const double on = 1e-7 * boundary.diagonal();
  std::vector<Box3> boxes;
  for (int f = 0; f < faces; ++f)
    boxes.push_back(boundary.faces()[f].patch.boundingBox());
  // The curved face a point of a circle lies on, −1 off every face; or, with a looser
  // `within`, the nearest curved face (a point of a chord between two circles).
  auto faceAt = [&](const Vec3& p, double within) {
    int best = -1;
    double nearest = within;
    for (int f = 0; f < faces; ++f)
      if (!generators[f].planar() && distanceToBox(boxes[f], p) <= nearest)
        if (const double d = generators[f].distance(p); d <= nearest)
        {
          nearest = d;
          best = f;
          if (d <= on)
            break;
        }
    return best;
  };
  const double chordReach = 1e-2 * boundary.diagonal();
  const int m = 32;
  const double turn = 2.0 * M_PI / m;
  for (const CentreCurveTouches& curve : curves)
  {
    const size_t n = curve.centres.size();
    std::vector<Circle> circles;
    std::vector<std::vector<int>> facesOn;
    for (size_t i = 0; i < n; ++i)
    {
      // (A ball whose touch is on no curved face, or whose circle is a point — an end
      // osculating a pole — adds no band of its own: the band runs to the next circle.)
      // (A touch on an edge lies on both faces; the circle is taken from one where it is
      // defined: at a capsule's end the other is its hemisphere, umbilic, where the focal
      // point stands still every way and the circle's plane is undefined.)
      Vec3List four;
      for (int f = 0; f < faces; ++f)
        if (!generators[f].planar() && distanceToBox(boxes[f], curve.touches[i]) <= on &&
          generators[f].distance(curve.touches[i]) <= on)
        {
          four = contactCircle(generators[f], generators[f].parameterOf(curve.touches[i]), curve.centres[i], 4);
          if (std::all_of(four.begin(), four.end(), [](const Vec3& x) { return x.allFinite(); }))
            break;
          four.clear();
        }
      if (four.size() != 4)
        continue;
      Circle c;
      c.centre = 0.25 * (four[0] + four[1] + four[2] + four[3]);
      c.axis = (four[1] - four[0]).cross(four[2] - four[0]).normalized();
      // (Along the curve, so the angles of consecutive circles correspond.)
      const Vec3 along = i + 1 < n ? Vec3(curve.centres[i + 1] - curve.centres[i])
                                   : Vec3(curve.centres[i] - curve.centres[i > 0 ? i - 1 : 0]);
      if (along.dot(c.axis) < 0.0)
        c.axis = -c.axis;
      c.radius = (curve.touches[i] - c.centre).norm();
      c.u = (curve.touches[i] - c.centre) / c.radius;
      c.w = c.axis.cross(c.u);
      if (!(c.radius > on) || !c.u.allFinite() || !c.axis.allFinite())
        continue;
      std::vector<int> at(2 * m); // at every half step of the angle
      for (int k = 0; k < 2 * m; ++k)
        at[k] = faceAt(c.at(0.5 * k * turn), on);
      circles.push_back(c);
      facesOn.push_back(std::move(at));
    }
    for (size_t i = 0; i + 1 < circles.size(); ++i)
    {
      const Circle &a = circles[i], &b = circles[i + 1];
      for (int k = 0; k < m; ++k)
      {
        // The strip from angle k to k + 1, cut where either circle crosses from one face to
        // the next (by bisection on the angle): each piece's area from its own middle (the
        // area element changes with the angle: a torus' outer half is wider than its inner).
        // A border crossing the strip aslant runs from one cut to the other: the piece
        // between them is split along at its middle, which halves it as the border does.
        std::vector<double> cuts{ k * turn, (k + 1) * turn };
        for (size_t side = 0; side < 2; ++side)
        {
          const Circle& circle = side == 0 ? a : b;
          const std::vector<int>& at = facesOn[i + side];
          const int f0 = at[2 * k], f1 = at[(2 * k + 2) % (2 * m)];
          if (f0 == f1)
            continue;
          double lo = k * turn, hi = (k + 1) * turn;
          for (int it = 0; it < 30; ++it)
          {
            const double mid = 0.5 * (lo + hi);
            (faceAt(circle.at(mid), on) == f0 ? lo : hi) = mid;
          }
          cuts.push_back(0.5 * (lo + hi));
        }
        std::sort(cuts.begin(), cuts.end());
        for (size_t c = 0; c + 1 < cuts.size(); ++c)
        {
          const double middle = 0.5 * (cuts[c] + cuts[c + 1]);
          // (Simpson's rule across the piece: the way between the circles changes with the
          // angle like a cosine.)
          auto way = [&](double angle) { return (b.at(angle) - a.at(angle)).norm(); };
          const double strip = 0.5 * (a.radius + b.radius) * (cuts[c + 1] - cuts[c]) *
            (way(cuts[c]) + 4.0 * way(middle) + way(cuts[c + 1])) / 6.0;
          const int fa = cuts.size() == 2 ? facesOn[i][2 * k + 1] : faceAt(a.at(middle), on);
          const int fb = cuts.size() == 2 ? facesOn[i + 1][2 * k + 1] : faceAt(b.at(middle), on);
          // Along the strip: where the chord between the circles crosses to circle i + 1's
          // face (a torus' quarters), by bisection.
          double along = 1.0;
          if (fa != fb)
          {
            double lo = 0.0, hi = 1.0;
            for (int it = 0; it < 30; ++it)
            {
              const double mid = 0.5 * (lo + hi);
              (faceAt((1.0 - mid) * a.at(middle) + mid * b.at(middle), chordReach) == fa ? lo : hi) = mid;
            }
            along = 0.5 * (lo + hi);
          }
          if (fa >= 0)
            area[fa] += along * strip;
          if (fb >= 0)
            area[fb] += (1.0 - along) * strip;
        }
      }
    }
  }
  return area;
}

} // namespace exactmat

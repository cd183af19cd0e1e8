#include "CentreCurve.h"

#include "common/Format.h"
#include "common/InputError.h"
#include "mat3d/Rim.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace exactmat
{

namespace
{

// The ball osculating the face at q along κ1's direction: centre P + N/κ1, radius 1/κ1.
// False where the face is not convex that way, or at an umbilic (a sphere's points: its
// focal set is one point, no curve).
bool focalBall(const Generator3D& face, const Vec2& q, Vec3& centre, double& radius, Vec2* d1 = nullptr)
{
  const Touch3D t = face.evaluate(q);
  const FaceCurvature c = faceCurvature(t);
  if (!(c.k1 > 0.0) || !(c.k1 - c.k2 > 1e-6 * c.k1))
    return false;
  radius = 1.0 / c.k1;
  centre = t.point + radius * t.normal;
  if (d1)
    *d1 = c.d1;
  return std::isfinite(radius) && centre.allFinite();
}

} // namespace

bool onCircleOfContact(const Generator3D& face, const Vec2& q, double size, Vec3& centre, double& radius)
{
  Vec2 d1;
  if (face.kind() != GeneratorKind3D::Face || face.planar() || !focalBall(face, q, centre, radius, &d1))
    return false;
  // The ridge function vanishes (to its rounding, 1e-10·κ1²) here and a tenth of the
  // radius either way along κ1's direction; at a generic ridge point, which crosses the
  // lines of curvature, it is about κ1²·(h/r) there (still 100 times the noise at
  // h = 1e-6·r). The step stays within a quarter of the patch's square past its sides
  // (next to a pole, where a circle is small and its parameters crowd, it is shorter).
  const double k1 = 1.0 / radius, noise = 1e-8 * k1 * k1;
  double h = 0.1 * radius;
  for (int i = 0; i < 2; ++i)
    if (std::abs(d1(i)) > 0.0)
      h = std::min(h, 0.25 / std::abs(d1(i)));
  if (!(h > 1e-6 * radius))
    return false;
  for (double s : { 0.0, h, -h })
  {
    const Vec2 p = q + s * d1;
    if (p.minCoeff() < -0.25 || p.maxCoeff() > 1.25 || !(std::abs(ridgeFunction(face, p, d1, size)) < noise))
      return false;
  }
  return true;
}

Vec3List contactCircle(const Generator3D& face, const Vec2& q, const Vec3& centre, int samples)
{
  // The circle lies on the ball's sphere in the plane normal to the centre curve (a small
  // circle of the sphere where the normal is not square to the curve: a cone, a spheroid).
  // The curve's tangent: the centres a 1e-4 of the radius either way across the circles.
  const Touch3D t = face.evaluate(q);
  const Vec3 touch = t.point;
  const FaceCurvature c = faceCurvature(t);
  const Eigen::Matrix2d metric = t.dPoint.transpose() * t.dPoint;
  Vec2 d2 = metric.ldlt().solve(t.dPoint.transpose() * t.normal.cross(t.dPoint * c.d1));
  d2 /= (t.dPoint * d2).norm();
  const double h = 1e-4 * (touch - centre).norm();
  Vec3 ahead, behind;
  double r;
  Vec3 tangent = Vec3::Constant(NAN);
  if (focalBall(face, q + h * d2, ahead, r) && focalBall(face, q - h * d2, behind, r))
    tangent = (ahead - behind).normalized();
  const Vec3 middle = centre + tangent * tangent.dot(touch - centre);
  const Vec3 a = touch - middle;
  const Vec3 b = tangent.cross(a);
  Vec3List points;
  for (int k = 0; k < samples; ++k)
  {
    const double angle = 2.0 * M_PI * k / samples;
    points.push_back(middle + std::cos(angle) * a + std::sin(angle) * b);
  }
  return points;
}

namespace
{

class CentreTracer
{
public:
  explicit CentreTracer(const CentreCurveSearch& search)
    : S(search)
    , Gen(*search.generators)
    , Size(search.size)
  {
  }

  std::vector<CentreCurve> run();

private:
  struct Half
  {
    std::vector<CircleBall> balls;
    std::string end;
    bool blocked = false;
    bool closed = false;
  };
  bool ball(int f, const Vec2& q, CircleBall& b) const;
  Vec2 across(int f, const Vec2& q, const Vec3& heading) const;
  Half traceFrom(const CircleBall& start, Vec3 heading) const;
  CircleBall lastEmpty(int f, const Vec2& q, const Vec2& d, double hi, const CircleBall& from, int blocker) const;
  bool onTraced(const Vec3& x, const std::vector<CentreCurve>& curves) const;
  std::string where(const Vec3& x) const { return format(S.toUser ? S.toUser(x) : x); }

  const CentreCurveSearch& S;
  const std::vector<Generator3D>& Gen;
  double Size;
  double OnFace = 1e-8 * Size;
};

bool CentreTracer::ball(int f, const Vec2& q, CircleBall& b) const
{
  b.face = f;
  b.q = q;
  b.touch = Gen[f].evaluate(q).point;
  return onCircleOfContact(Gen[f], q, Size, b.x, b.r);
}

// The direction across the circles at q (e2 = N × e1, in the face's parameters, moving the
// touch by unit length), turned along `heading` (a direction in space).
Vec2 CentreTracer::across(int f, const Vec2& q, const Vec3& heading) const
{
  const Touch3D t = Gen[f].evaluate(q);
  const FaceCurvature c = faceCurvature(t);
  const Vec3 e2 = t.normal.cross(t.dPoint * c.d1);
  const Eigen::Matrix2d metric = t.dPoint.transpose() * t.dPoint;
  Vec2 d = metric.ldlt().solve(t.dPoint.transpose() * e2);
  d /= (t.dPoint * d).norm();
  return (t.dPoint * d).dot(heading) < 0.0 ? Vec2(-d) : d;
}

// The last empty ball between `from` (at q, empty) and q + hi·d, which `blocker` enters:
// where the ball starts to touch another face, the root of that face's distance from the
// centre minus the radius (exact), by bisection. A face that enters before it (the
// emptiness test at that root fails) is taken instead, nearer; at most one per face.
CircleBall CentreTracer::lastEmpty(int f, const Vec2& q, const Vec2& d, double hi, const CircleBall& from,
  int blocker) const
{
  CircleBall last = from;
  const int faces = static_cast<int>(S.boundary->faces().size());
  for (int tries = 0; tries <= faces && blocker >= 0; ++tries)
  {
    // (The blocking face is clear of the ball at `from`: the curve came from there.)
    double a = 0.0, b = hi;
    last = from;
    for (int k = 0; k < 100 && b - a > 1e-15 * Size; ++k)
    {
      const double mid = 0.5 * (a + b);
      CircleBall m;
      if (ball(f, q + mid * d, m) && Gen[blocker].distance(m.x) >= m.r)
      {
        a = mid;
        last = m;
      }
      else
        b = mid;
    }
    hi = b;
    blocker = S.entering(last.x, last.r);
  }
  return last;
}

CentreTracer::Half CentreTracer::traceFrom(const CircleBall& start, Vec3 heading) const
{
  Half half;
  half.balls.push_back(start);
  int f = start.face;
  Vec2 q = start.q;
  const double longest = S.maxStep * Size, chord = S.tolerance * Size;
  double s = std::min(longest, 0.1 * start.r);
  double length = 0.0;
  int crossings = 0; // in a row, without a step between
  for (int n = 0; n < S.maxSteps; ++n)
  {
    const CircleBall here = half.balls.back();
    const Vec2 d = across(f, q, heading);
    if (!d.allFinite())
      fail("3D MAT: the centre curve through ", where(here.x), " (touching ", Gen[f].name(),
        ") makes no progress");
    const Vec2 next = q + s * d;
    const int side = Gen[f].exitSide(next, OnFace);
    if (side >= 0)
    {
      // The step is cut where the touch crosses the side; the curve goes on from there on
      // the face beyond (a smooth edge), or ends (a sharp one).
      if (++crossings > 8)
        fail("3D MAT: the centre curve through ", where(here.x), " keeps crossing sides of ", Gen[f].name(),
          " without moving");
      // (Bisected to the side itself, not to within OnFace of it: where the curve ends at
      // a smooth edge — a capsule's axis at its hemispheres, whose centres are the ends — a
      // touch up to OnFace past the side is on the face's extension, and its ball's centre
      // that far past the true end, 7e-8 of the size.)
      double lo = 0.0, hi = s;
      for (int k = 0; k < 60 && hi - lo > 1e-13 * Size; ++k)
      {
        const double mid = 0.5 * (lo + hi);
        (Gen[f].exitSide(q + mid * d, 0.0) < 0 ? lo : hi) = mid;
      }
      CircleBall border;
      if (!ball(f, q + lo * d, border))
      {
        // (No circle at the side: a pole, where the circles shrink to a point and the
        // parameters crowd. Approached in shorter steps: the curve ends as near as they go.)
        s *= 0.5;
        --crossings;
        if (s < 1e-10 * Size)
        {
          half.end = "the circles of contact end at a side of " + Gen[f].name();
          return half;
        }
        continue;
      }
      if (const int blocker = S.entering(border.x, border.r); blocker >= 0)
      {
        half.balls.push_back(lastEmpty(f, q, d, lo, here, blocker));
        half.end = "its ball stops being empty";
        half.blocked = true;
        return half;
      }
      if ((border.x - here.x).norm() > 1e-9 * Size)
      {
        length += (border.x - here.x).norm();
        half.balls.push_back(border);
      }
      const int beyond = S.smoothNeighbour(f, side);
      CircleBall there;
      if (beyond < 0 || !ball(beyond, Gen[beyond].parameterOf(border.touch), there))
      {
        half.end = beyond < 0 ? "its touch reaches a sharp edge of " + Gen[f].name()
                              : "the circles of contact end where " + Gen[f].name() + " meets " + Gen[beyond].name();
        return half;
      }
      heading = Gen[f].evaluate(q + lo * d).dPoint * d;
      f = beyond;
      q = there.q;
      continue;
    }
    CircleBall ahead, middle;
    bool ok = ball(f, next, ahead) && ball(f, q + 0.5 * s * d, middle);
#ifdef EXACTMAT_CENTRE_DEBUG
    std::fprintf(stderr, "face %d q (%g %g) s %g next (%g %g) ahead %d middle %d\n", f, q.x(), q.y(), s, next.x(), next.y(),
      ball(f, next, ahead), ball(f, q + 0.5 * s * d, middle));
#endif
    // Chord control on the centres and on the touches too: along a straight axis any step
    // passes the first, while the circles' band between two balls bends with the face (a
    // spheroid's meridian), which the coverage sums as a chord.
    auto withinChord = [chord](const Vec3& a, const Vec3& m, const Vec3& b) {
      const Vec3 e = b - a;
      const double t = std::clamp((m - a).dot(e) / std::max(e.squaredNorm(), 1e-300), 0.0, 1.0);
      return (a + t * e - m).norm() <= chord;
    };
    if (ok)
      ok = withinChord(here.x, middle.x, ahead.x) && withinChord(here.touch, middle.touch, ahead.touch) &&
        (ahead.x - here.x).norm() <= longest && std::abs(ahead.r - here.r) <= longest;
    if (!ok)
    {
      s *= 0.5;
      if (s < 1e-10 * Size)
      {
        half.end = "the circles of contact end on " + Gen[f].name();
        return half;
      }
      continue;
    }
    // The centres turn back: the touch has passed the point where the circles shrink to
    // nothing (an umbilic, the pole of a spheroid's circles: an osculating end, A3). The
    // end is the centre farthest along, by golden section over the step.
    if (half.balls.size() >= 2 && (ahead.x - here.x).dot(here.x - half.balls[half.balls.size() - 2].x) < 0.0)
    {
      const Vec3 way = (here.x - half.balls[half.balls.size() - 2].x).normalized();
      auto along = [&](double t, CircleBall& b) { return ball(f, q + t * d, b) ? (b.x - here.x).dot(way) : -INFINITY; };
      const double g = 0.5 * (std::sqrt(5.0) - 1.0);
      double a = 0.0, c = s;
      CircleBall best = here, m1, m2;
      for (int it = 0; it < 80 && c - a > 1e-14 * Size; ++it)
      {
        const double t1 = c - g * (c - a), t2 = a + g * (c - a);
        if (along(t1, m1) >= along(t2, m2))
        {
          c = t2;
          best = m1;
        }
        else
        {
          a = t1;
          best = m2;
        }
      }
      if (S.entering(best.x, best.r) < 0 && (best.x - here.x).dot(way) > 0.0)
        half.balls.push_back(best);
      half.end = "its circles shrink to a point of " + Gen[f].name() + " (an osculating end)";
      return half;
    }
    if (const int blocker = S.entering(ahead.x, ahead.r); blocker >= 0)
    {
      half.balls.push_back(lastEmpty(f, q, d, s, here, blocker));
      half.end = "its ball stops being empty";
      half.blocked = true;
      return half;
    }
    // Closed (a torus' core): the step passes the start's centre.
    const Vec3 e = ahead.x - here.x;
    const double t = (start.x - here.x).dot(e) / std::max(e.squaredNorm(), 1e-300);
    if (half.balls.size() >= 3 && length > 2.0 * e.norm() && t > 0.0 && t <= 1.0 &&
      (here.x + t * e - start.x).norm() <= 0.25 * e.norm())
    {
      half.balls.push_back(start);
      half.closed = true;
      return half;
    }
    length += e.norm();
    crossings = 0;
    half.balls.push_back(ahead);
    heading = Gen[f].evaluate(next).dPoint * d;
    q = next;
    s = std::min(1.5 * s, longest);
  }
  fail("3D MAT: the centre curve from ", where(start.x), " on ", Gen[start.face].name(), " takes more than ",
    S.maxSteps, " steps");
}

bool CentreTracer::onTraced(const Vec3& x, const std::vector<CentreCurve>& curves) const
{
  const double near = 2.0 * S.tolerance * Size + 1e-9 * Size;
  for (const CentreCurve& curve : curves)
    for (size_t i = 0; i + 1 < curve.balls.size(); ++i)
    {
      const Vec3 a = curve.balls[i].x, e = curve.balls[i + 1].x - a;
      const double t = std::clamp((x - a).dot(e) / std::max(e.squaredNorm(), 1e-300), 0.0, 1.0);
      if ((a + t * e - x).norm() <= near)
        return true;
    }
  return false;
}

std::vector<CentreCurve> CentreTracer::run()
{
  std::vector<CentreCurve> curves;
  const int faces = static_cast<int>(S.boundary->faces().size());
  const int n = 8; // samples per parameter direction
  for (int f = 0; f < faces; ++f)
  {
    if (Gen[f].planar())
      continue;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
      {
        CircleBall start;
        if (!ball(f, Vec2((i + 0.5) / n, (j + 0.5) / n), start) || onTraced(start.x, curves) ||
          S.entering(start.x, start.r) >= 0)
          continue;
        const Vec3 heading = Gen[f].evaluate(start.q).dPoint * across(f, start.q, Vec3::UnitX());
        Half ahead = traceFrom(start, heading);
        CentreCurve curve;
        if (ahead.closed)
        {
          curve.balls = std::move(ahead.balls);
          curve.closed = true;
        }
        else
        {
          Half back = traceFrom(start, -heading);
          curve.balls.assign(back.balls.rbegin(), back.balls.rend());
          curve.balls.insert(curve.balls.end(), ahead.balls.begin() + 1, ahead.balls.end());
          curve.frontEnd = back.end;
          curve.frontBlocked = back.blocked;
          curve.backEnd = ahead.end;
          curve.backBlocked = ahead.blocked;
        }
        curves.push_back(std::move(curve));
      }
  }
  // A curve every ball of which lies on another, longer one is a piece of it, traced from a
  // start where it stalled (next to a patch's pole, where the parameters crowd): dropped.
  std::vector<double> length(curves.size(), 0.0);
  for (size_t i = 0; i < curves.size(); ++i)
    for (size_t k = 1; k < curves[i].balls.size(); ++k)
      length[i] += (curves[i].balls[k].x - curves[i].balls[k - 1].x).norm();
  std::vector<CentreCurve> kept;
  for (size_t i = 0; i < curves.size(); ++i)
  {
    bool piece = false;
    for (size_t j = 0; j < curves.size() && !piece; ++j)
    {
      if (j == i || length[j] < length[i] || (length[j] == length[i] && j > i))
        continue;
      const std::vector<CentreCurve> other{ curves[j] };
      piece = std::all_of(curves[i].balls.begin(), curves[i].balls.end(),
        [&](const CircleBall& b) { return onTraced(b.x, other); });
    }
    if (!piece)
      kept.push_back(std::move(curves[i]));
  }
  return kept;
}

} // namespace

std::vector<CentreCurve> traceCentreCurves(const CentreCurveSearch& search)
{
  return CentreTracer(search).run();
}

} // namespace exactmat

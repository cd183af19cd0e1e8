#include "Rim.h"

#include "common/Format.h"
#include "common/InputError.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace exactmat
{

FaceCurvature faceCurvature(const Touch3D& touch)
{
  // The shape operator in the face's parameters: II v = k I v, with I = dPᵀdP and
  // II = −dPᵀdN (N into the material, so a convex face has k > 0).
  const Eigen::Matrix2d first = touch.dPoint.transpose() * touch.dPoint;
  Eigen::Matrix2d second = -touch.dPoint.transpose() * touch.dNormal;
  second = (0.5 * (second + second.transpose())).eval();
  FaceCurvature c;
  const double det = first.determinant();
  if (!(det > 0.0))
    return c;
  const double mean =
    (first(0, 0) * second(1, 1) + first(1, 1) * second(0, 0) - 2.0 * first(0, 1) * second(0, 1)) / (2.0 * det);
  const double gauss = second.determinant() / det;
  const double root = std::sqrt(std::max(0.0, mean * mean - gauss));
  c.k1 = mean + root;
  c.k2 = mean - root;
  // k1's direction: the null vector of II − k1·I, orthogonal to its larger row.
  const Eigen::Matrix2d a = second - c.k1 * first;
  const Vec2 row = a.row(0).norm() >= a.row(1).norm() ? Vec2(a.row(0).transpose()) : Vec2(a.row(1).transpose());
  const Vec2 d = row.norm() > 0.0 ? Vec2(-row.y(), row.x()) : Vec2(1.0, 0.0);
  c.d1 = d / (touch.dPoint * d).norm();
  return c;
}

namespace
{
// The difference step of the ridge function, a length: 1e-3 of the curvature radius.
double ridgeDifferenceStep(double k1, double size)
{
  return std::min(1e-4 * size, 1e-3 / k1);
}
} // namespace

// The references are directions in the face's parameters: across a sharply curved face (a
// flat ellipsoid's rim) k1's direction turns by more than a right angle between two
// samples in space, while in the parameters it keeps its way.
double ridgeFunction(const Generator3D& face, const Vec2& q, const Vec2& reference, double size)
{
  const Touch3D t = face.evaluate(q);
  const FaceCurvature c = faceCurvature(t);
  if (!(c.k1 > 0.0))
    return NAN;
  const Vec2 v = (t.dPoint * c.d1).dot(t.dPoint * reference) < 0.0 ? Vec2(-c.d1) : c.d1;
  auto k1At = [&](const Vec2& p) { return faceCurvature(face.evaluate(p)).k1; };
  // Richardson's fourth-order central difference: its bias (h⁴) keeps the ridge within
  // rounding of the side it runs along (an ellipsoid cut at its equator); the second-order
  // one moved it 1e-7 of the radius off, outside both faces.
  const double h = ridgeDifferenceStep(c.k1, size);
  return (8.0 * (k1At(q + h * v) - k1At(q - h * v)) - (k1At(q + 2.0 * h * v) - k1At(q - 2.0 * h * v))) / (12.0 * h);
}

namespace
{

class RimTracer
{
public:
  explicit RimTracer(const RimSearch& search)
    : S(search)
    , Gen(*search.generators)
    , Size(search.size)
  {
  }

  std::vector<Rim> run();

private:
  double differenceStep(double k1) const { return ridgeDifferenceStep(k1, Size); }
  double k1At(int f, const Vec2& q) const { return faceCurvature(Gen[f].evaluate(q)).k1; }
  double ridge(int f, const Vec2& q, const Vec2& reference) const
  {
    return ridgeFunction(Gen[f], q, reference, Size);
  }
  Vec2 ridgeGradient(int f, const Vec2& q, const Vec2& reference, const Touch3D& t, double k1) const
  {
    const double h = 10.0 * differenceStep(k1);
    Vec2 g;
    for (int i = 0; i < 2; ++i)
    {
      Vec2 d = Vec2::Zero();
      d(i) = h / t.dPoint.col(i).norm();
      g(i) = (ridge(f, q + d, reference) - ridge(f, q - d, reference)) / (2.0 * d(i));
    }
    return g;
  }
  // k1's direction at the touch (parameters, unit length on the face), turned along
  // `reference`.
  static Vec2 direction(const Touch3D& t, const FaceCurvature& c, const Vec2& reference)
  {
    return (t.dPoint * c.d1).dot(t.dPoint * reference) < 0.0 ? Vec2(-c.d1) : c.d1;
  }
  bool toRidge(int f, Vec2& q, Vec2& reference) const;
  bool isMaximum(int f, const Vec2& q) const;
  RimBall ball(int f, const Vec2& q) const;
  Vec3 ridgeTangent(int f, const Vec2& q, const Vec2& reference, const Vec3& previous) const;
  bool advance(int f, Vec2& q, Vec2& reference, const Vec3& tangent, double s) const;
  Rim traceFrom(const RimBall& start, Vec2 reference, Vec3 tangent) const;
  bool nearPole(int f, const Vec3& p, double near, Vec3& pole) const;
  bool acrossPole(const Rim& rim, int& f, Vec2& q, Vec2& reference) const;
  bool onTracedRim(const Vec3& touch, const std::vector<Rim>& rims) const;
  std::string where(const Vec3& x) const { return format(S.toUser ? S.toUser(x) : x); }

  const RimSearch& S;
  const std::vector<Generator3D>& Gen;
  double Size;
  // A touch this close outside its face is on it: a ridge along a face side is placed only
  // to about 1e-9 of the size near a pole, where the side's parameters crowd.
  double OnFace = 1e-8 * Size;
};

// Newton onto the ridge from q, along the ridge function's gradient (the step of least
// length on the face). True when q is within 1e-10 of the size of it.
bool RimTracer::toRidge(int f, Vec2& q, Vec2& reference) const
{
  for (int it = 0; it < 40; ++it)
  {
    const Touch3D t = Gen[f].evaluate(q);
    const FaceCurvature c = faceCurvature(t);
    if (!(c.k1 > 0.0))
      return false;
    reference = direction(t, c, reference);
    const double value = ridge(f, q, reference);
    const Vec2 g = ridgeGradient(f, q, reference, t, c.k1);
    const Eigen::Matrix2d metric = t.dPoint.transpose() * t.dPoint;
    const Vec2 w = metric.ldlt().solve(g);
    const double gw = g.dot(w);
    if (!(gw > 0.0) || !std::isfinite(value))
      return false;
    const double distance = std::abs(value) / std::sqrt(gw); // to the ridge, on the face
    double scale = 1.0;
    if (distance > 0.2 / c.k1)
      scale = 0.2 / c.k1 / distance;
    q -= scale * value / gw * w;
    if (distance <= 1e-10 * Size)
      return true;
  }
  return false;
}

bool RimTracer::isMaximum(int f, const Vec2& q) const
{
  const Touch3D t = Gen[f].evaluate(q);
  const FaceCurvature c = faceCurvature(t);
  const double h = 10.0 * differenceStep(c.k1);
  return c.k1 > 0.0 && k1At(f, q + h * c.d1) + k1At(f, q - h * c.d1) - 2.0 * c.k1 < 0.0;
}

RimBall RimTracer::ball(int f, const Vec2& q) const
{
  const Touch3D t = Gen[f].evaluate(q);
  RimBall b;
  b.face = f;
  b.q = q;
  b.touch = t.point;
  b.r = 1.0 / faceCurvature(t).k1;
  b.x = t.point + b.r * t.normal;
  return b;
}

// The ridge's direction on the face at q (unit, 3D), turned along `previous`.
Vec3 RimTracer::ridgeTangent(int f, const Vec2& q, const Vec2& reference, const Vec3& previous) const
{
  const Touch3D t = Gen[f].evaluate(q);
  const FaceCurvature c = faceCurvature(t);
  const Vec2 g = ridgeGradient(f, q, reference, t, c.k1);
  const Eigen::Matrix2d metric = t.dPoint.transpose() * t.dPoint;
  const Vec3 across = t.dPoint * metric.ldlt().solve(g);
  const Vec3 along = t.normal.cross(across).normalized();
  return along.dot(previous) < 0.0 ? Vec3(-along) : along;
}

// Predictor s along the tangent (s a length on the face), corrector back onto the ridge.
bool RimTracer::advance(int f, Vec2& q, Vec2& reference, const Vec3& tangent, double s) const
{
  const Touch3D t = Gen[f].evaluate(q);
  const Eigen::Matrix2d metric = t.dPoint.transpose() * t.dPoint;
  const Vec3 from = t.point;
  q += metric.ldlt().solve(t.dPoint.transpose() * (s * tangent));
  return toRidge(f, q, reference) && (Gen[f].evaluate(q).point - from).dot(tangent) > 0.0;
}

bool RimTracer::onTracedRim(const Vec3& touch, const std::vector<Rim>& rims) const
{
  for (const Rim& rim : rims)
    for (size_t i = 0; i + 1 < rim.balls.size(); ++i)
    {
      const Vec3 a = rim.balls[i].touch, e = rim.balls[i + 1].touch - a;
      const double t = std::clamp((touch - a).dot(e) / std::max(e.squaredNorm(), 1e-300), 0.0, 1.0);
      if ((a + t * e - touch).norm() <= std::min(1e-2 * Size, 0.5 * e.norm() + 1e-6 * Size))
        return true;
    }
  return false;
}

// A side of face f collapsed to a point (a pole of a surface of revolution) within `near`
// of p.
bool RimTracer::nearPole(int f, const Vec3& p, double near, Vec3& pole) const
{
  const BezierPatch& patch = S.boundary->faces()[f].patch;
  const Vec2 ends[4][2] = { { Vec2(0, 0), Vec2(1, 0) }, { Vec2(1, 0), Vec2(1, 1) }, { Vec2(0, 1), Vec2(1, 1) },
    { Vec2(0, 0), Vec2(0, 1) } };
  for (const auto& side : ends)
  {
    const Vec3 a = patch.evaluate(side[0].x(), side[0].y()), b = patch.evaluate(side[1].x(), side[1].y()),
               m = patch.evaluate(0.5 * (side[0].x() + side[1].x()), 0.5 * (side[0].y() + side[1].y()));
    if ((a - b).norm() <= 1e-12 * Size && (a - m).norm() <= 1e-12 * Size && (a - p).norm() <= near)
    {
      pole = a;
      return true;
    }
  }
  return false;
}

// A rim through a pole: the faces' parameters are singular there, so the ridge cannot be
// followed onto it. It is stepped over: from the ball just before the pole to the ridge
// point as far beyond it on one of the faces that meet there, the one whose ridge goes on
// ahead (the pole's own ball is left out: the step, twice the way left to the pole, has
// a chord within the tolerance, √(2·tolerance·r) for a centre curve bending by 1/r).
bool RimTracer::acrossPole(const Rim& rim, int& f, Vec2& q, Vec2& reference) const
{
  // The way the touches came (the ridge's own tangent is lost near the pole, where the
  // ridge function's gradient is taken in crowded parameters).
  if (rim.balls.size() < 2)
    return false;
  const RimBall& here = rim.balls.back();
  Vec3 pole;
  const double near = std::sqrt(2.0 * S.tolerance * Size * here.r);
  if (!nearPole(f, here.touch, near, pole))
    return false;
  const Touch3D t = Gen[f].evaluate(q);
  const Vec3 across = t.dPoint * reference; // k1's direction, in space
  const double gap = (pole - here.touch).norm();
  // Over a baseline of several gaps (the last balls before a pole are close together and
  // their touches placed only to the crowded parameters' precision), in the tangent plane.
  size_t back = rim.balls.size() - 2;
  while (back > 0 && (here.touch - rim.balls[back].touch).norm() < 4.0 * gap)
    --back;
  const Vec3 normal = (here.x - here.touch).normalized();
  Vec3 tangent = here.touch - rim.balls[back].touch;
  tangent = (tangent - normal * normal.dot(tangent)).normalized();
#ifdef EXACTMAT_RIM_DEBUG
  std::fprintf(stderr, "pole %s from %s gap %g tangent %s\n", format(pole).c_str(), format(here.touch).c_str(), gap,
    format(tangent).c_str());
#endif
  for (double beyond : { near, 4.0 * gap, 2.0 * gap, gap }) // (far enough for plain steps to go on)
  {
    const Vec3 target = pole + beyond * tangent;
    for (int g = 0; g < static_cast<int>(S.boundary->faces().size()); ++g)
    {
      Vec3 other;
      if (Gen[g].planar() || !nearPole(g, pole, 1e-12 * Size, other))
        continue;
      Vec2 there = Gen[g].parameterOf(target);
      if (Gen[g].exitSide(there, OnFace) >= 0)
        continue;
      const Eigen::Matrix<double, 3, 2> d = Gen[g].evaluate(there).dPoint;
      Vec2 ref = (d.transpose() * d).ldlt().solve(d.transpose() * across);
      if (!toRidge(g, there, ref) || Gen[g].exitSide(there, OnFace) >= 0)
        continue;
      const RimBall next = ball(g, there);
#ifdef EXACTMAT_RIM_DEBUG
      std::fprintf(stderr, "pole: face %d beyond %g: touch %s ahead %g far %g\n", g, beyond, format(next.touch).c_str(),
        (next.touch - pole).dot(tangent), (next.touch - pole).norm());
#endif
      // (Beyond the pole by about the way asked, not on it: the pole's own parameters are
      // singular, its ridge direction undefined.)
      if (!((next.touch - pole).dot(tangent) >= 0.5 * beyond) || (next.touch - pole).norm() > 2.0 * beyond + gap ||
        !isMaximum(g, there) || !S.empty(next.x, next.r))
        continue;
      f = g;
      q = there;
      reference = ref;
      return true;
    }
  }
  return false;
}

Rim RimTracer::traceFrom(const RimBall& start, Vec2 reference, Vec3 tangent) const
{
  Rim rim;
  rim.balls.push_back(start);
  int f = start.face;
  Vec2 q = start.q;
  const double longest = S.maxStep * Size, chord = S.tolerance * Size;
  double s = std::min(longest, 0.1 * start.r);
  double length = 0.0;
  int crossings = 0; // in a row, without a step between
  size_t lastCount = 0;
  int stalled = 0; // iterations without a new ball
  // A step over a pole (acrossPole), going on the way it jumped.
  auto overPole = [&]() {
    const RimBall here = rim.balls.back();
    if (!acrossPole(rim, f, q, reference))
      return false;
    const RimBall beyond = ball(f, q);
    length += (beyond.x - here.x).norm();
    rim.balls.push_back(beyond);
    tangent = ridgeTangent(f, q, reference, beyond.touch - here.touch);
    s = std::min(longest, 0.1 * beyond.r);
    crossings = 0;
    return true;
  };
  for (int n = 0; n < S.maxSteps; ++n)
  {
    const RimBall here = rim.balls.back();
    stalled = rim.balls.size() == lastCount ? stalled + 1 : 0;
    lastCount = rim.balls.size();
    if (stalled > 200 || !tangent.allFinite() || !here.x.allFinite() || !std::isfinite(here.r))
      fail("3D MAT: the rim through ", where(here.x), " (touching ", Gen[f].name(), ") makes no progress");
    // Heading into a pole within a chord's reach: stepped over at once (steps onto it only
    // crowd and zigzag in the singular parameters).
    if (Vec3 pole; rim.balls.size() >= 2 && nearPole(f, here.touch, std::sqrt(2.0 * S.tolerance * Size * here.r), pole) &&
      (pole - here.touch).dot(here.touch - rim.balls[rim.balls.size() - 2].touch) > 0.0 &&
      overPole())
      continue;
    Vec2 next = q, middle = q;
    Vec2 refNext = reference, refMiddle = reference;
    bool ok = advance(f, next, refNext, tangent, s) && advance(f, middle, refMiddle, tangent, 0.5 * s);
    RimBall ahead, half;
    if (ok)
    {
      ahead = ball(f, next);
      half = ball(f, middle);
      const Vec3 e = ahead.x - here.x;
      const double t = std::clamp((half.x - here.x).dot(e) / std::max(e.squaredNorm(), 1e-300), 0.0, 1.0);
      ok = (here.x + t * e - half.x).norm() <= chord && e.norm() <= longest &&
        std::abs(ahead.r - here.r) <= longest;
    }
    if (!ok)
    {
      s *= 0.5;
      if (s < 1e-10 * Size && overPole())
        continue;
      if (s < 1e-10 * Size)
        fail("3D MAT: the rim through ", where(here.x), " (radius ", here.r, ", touching ", Gen[f].name(),
          ") cannot be followed: its ridge ends or turns sharply there");
      continue;
    }
    // The touch leaves the face: the step is cut where it crosses the side, and the rim goes
    // on from there on the face beyond (a smooth edge), or ends (a sharp one).
    // (A rim running along a face's side — an ellipsoid cut at its equator — is on it to
    // the ridge's own precision, 1e-10 of the size: it must not cross back and forth.)
    const int side = Gen[f].exitSide(next, OnFace);
    if (side >= 0)
    {
      if (crossings >= 8 && overPole())
        continue;
      if (++crossings > 8)
        fail("3D MAT: the rim through ", where(here.x), " keeps crossing sides of ", Gen[f].name(),
          " without moving");
      double lo = 0.0, hi = s;
      Vec2 inside = q;
      Vec2 refInside = reference;
      for (int k = 0; k < 60 && hi - lo > 1e-13 * Size; ++k)
      {
        const double mid = 0.5 * (lo + hi);
        Vec2 m = q;
        Vec2 rm = reference;
        if (advance(f, m, rm, tangent, mid) && Gen[f].exitSide(m, OnFace) < 0)
        {
          lo = mid;
          inside = m;
          refInside = rm;
        }
        else
          hi = mid;
      }
      const RimBall border = ball(f, inside);
      const int beyond = S.smoothNeighbour(f, side);
#ifdef EXACTMAT_RIM_DEBUG
      std::fprintf(stderr, "cross face %d side %d at q (%g %g) lo %g of %g -> face %d, touch %s\n", f, side, inside.x(),
        inside.y(), lo, s, beyond, format(border.touch).c_str());
#endif
      if (beyond < 0)
      {
        rim.balls.push_back(border);
        rim.end = "its touch reaches a sharp edge of " + Gen[f].name();
        return rim;
      }
      // (The reference direction carried over in space, at the one point both faces share.)
      Vec2 there = Gen[beyond].parameterOf(border.touch);
      const Eigen::Matrix<double, 3, 2> dThere = Gen[beyond].evaluate(there).dPoint;
      Vec2 refThere = (dThere.transpose() * dThere).ldlt().solve(
        dThere.transpose() * (Gen[f].evaluate(inside).dPoint * refInside));
      if (!toRidge(beyond, there, refThere))
        fail("3D MAT: the rim through ", where(border.x), " could not cross from ", Gen[f].name(), " onto ",
          Gen[beyond].name());
      if ((border.touch - here.touch).dot(tangent) > 1e-9 * Size) // (no ball that goes back, or nowhere)
      {
        length += (border.x - here.x).norm();
        rim.balls.push_back(border);
      }
      f = beyond;
      q = there;
      reference = refThere;
      tangent = ridgeTangent(f, q, reference, tangent);
      continue;
    }
    if (!S.empty(ahead.x, ahead.r))
    {
      rim.end = "its ball stops being empty (a seam meets it there)";
      return rim;
    }
    // Closed: the step passes the start's touch.
    const Vec3 e = ahead.touch - here.touch;
    const double t = (start.touch - here.touch).dot(e) / std::max(e.squaredNorm(), 1e-300);
    if (rim.balls.size() >= 3 && length > 2.0 * e.norm() && t > 0.0 && t <= 1.0 &&
      (here.touch + t * e - start.touch).norm() <= 0.25 * e.norm())
    {
      rim.balls.push_back(start);
      rim.closed = true;
      return rim;
    }
    length += (ahead.x - here.x).norm();
    crossings = 0;
    rim.balls.push_back(ahead);
    q = next;
    reference = refNext;
    tangent = ridgeTangent(f, q, reference, tangent);
    s = std::min(1.5 * s, longest);
  }
  fail("3D MAT: the rim from ", where(start.x), " on ", Gen[start.face].name(), " takes more than ", S.maxSteps,
    " steps");
}

std::vector<Rim> RimTracer::run()
{
  std::vector<Rim> rims;
  const int faces = static_cast<int>(S.boundary->faces().size());
  const int n = 8; // samples per parameter direction
  for (int f = 0; f < faces; ++f)
  {
    if (Gen[f].planar())
      continue;
    // Samples reach half a spacing past the face's sides (its polynomial continues the
    // surface there, as its smooth neighbour does): a ridge along a side (an ellipsoid cut at
    // its equator) lies between two of them.
    auto sample = [&](int i, int j) { return Vec2((i + 0.5) / n, (j + 0.5) / n); };
    for (int i = -1; i <= n; ++i)
      for (int j = -1; j <= n; ++j)
        for (int d = 0; d < 2; ++d)
        {
          if ((d == 0 && i == n) || (d == 1 && j == n))
            continue;
          const Vec2 a = sample(i, j), b = d == 0 ? sample(i + 1, j) : sample(i, j + 1);
          const Touch3D ta = Gen[f].evaluate(a);
          const FaceCurvature ca = faceCurvature(ta);
          if (!(ca.k1 > 0.0))
            continue;
          Vec2 reference = ca.d1;
          const double ga = ridge(f, a, reference), gb = ridge(f, b, reference);
          // (A face of constant k1 along its lines of curvature — a cylinder, a fillet — has
          // a ridge function of rounding noise only: no sign change counts below 1e-8·k1².)
          const double noise = 1e-8 * ca.k1 * ca.k1;
          if (!(ga * gb < 0.0) || std::abs(ga) < noise || std::abs(gb) < noise)
            continue;
          // Bisection between the samples first (near a sharp rim the ridge function is
          // far from linear: Newton from a sample would overshoot), then Newton.
          double lo = 0.0, hi = 1.0;
          for (int k = 0; k < 60; ++k)
          {
            const double mid = 0.5 * (lo + hi);
            const double g = ridge(f, a + mid * (b - a), reference);
            if (!std::isfinite(g))
              break;
            (g * ga > 0.0 ? lo : hi) = mid;
          }
          Vec2 q = a + 0.5 * (lo + hi) * (b - a);
          const bool onRidge = toRidge(f, q, reference);
#ifdef EXACTMAT_RIM_DEBUG
          std::fprintf(stderr, "face %d candidate (%g %g)-(%g %g) G %g %g: ridge %d at (%g %g) max %d\n", f, a.x(), a.y(),
            b.x(), b.y(), ga, gb, onRidge, q.x(), q.y(), onRidge ? isMaximum(f, q) : -1);
#endif
          if (!onRidge || Gen[f].exitSide(q, OnFace) >= 0 || !isMaximum(f, q))
            continue;
          const FaceCurvature c = faceCurvature(Gen[f].evaluate(q));
          if (c.k1 - c.k2 <= 1e-6 * c.k1) // an umbilic: no direction to follow
            continue;
          const RimBall start = ball(f, q);
#ifdef EXACTMAT_RIM_DEBUG
          std::fprintf(stderr, "  exit %d traced %d empty %d\n", Gen[f].exitSide(q, OnFace), onTracedRim(start.touch, rims),
            S.empty(start.x, start.r));
#endif
          if (onTracedRim(start.touch, rims) || !S.empty(start.x, start.r))
            continue;
          const Touch3D at = Gen[f].evaluate(q);
          const Vec3 tangent = ridgeTangent(f, q, reference, (at.dPoint * reference).cross(at.normal));
          Rim rim = traceFrom(start, reference, tangent);
          if (!rim.closed)
          {
            Rim back = traceFrom(start, reference, -tangent);
            std::reverse(back.balls.begin(), back.balls.end());
            back.balls.insert(back.balls.end(), rim.balls.begin() + 1, rim.balls.end());
            back.end = back.end + (back.end.empty() || rim.end.empty() ? "" : "; ") + rim.end;
            rim = std::move(back);
          }
          rims.push_back(std::move(rim));
        }
  }
  return rims;
}

} // namespace

std::vector<Rim> traceRims(const RimSearch& search)
{
  return RimTracer(search).run();
}

} // namespace exactmat

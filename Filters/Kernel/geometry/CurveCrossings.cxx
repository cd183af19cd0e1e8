#include "CurveCrossings.h"

#include "geometry/Flatten.h"

#include <algorithm>

namespace exactmat
{

namespace
{
double orient2d(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

bool onSegment(const Vec3& a, const Vec3& b, const Vec3& p)
{
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
    std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
}

bool segmentsIntersect(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  const double d1 = orient2d(c, d, a), d2 = orient2d(c, d, b);
  const double d3 = orient2d(a, b, c), d4 = orient2d(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  return (d1 == 0 && onSegment(c, d, a)) || (d2 == 0 && onSegment(c, d, b)) ||
    (d3 == 0 && onSegment(a, b, c)) || (d4 == 0 && onSegment(a, b, d));
}

// A part [t0, t1] of curve k of a chain, as flatten() halves it.
struct Part
{
  BezierCurve curve;
  Box3 box; ///< of the control points: holds the part and its chord
  int chain = 0, k = 0, depth = 0;
  double t0 = 0.0, t1 = 1.0;
  bool finest = false; ///< flatten() would not halve it further: compare its chord

  Part(BezierCurve c, int chain_, int k_, double a, double b, int depth_, double tolerance)
    : curve(std::move(c))
    , box(curve.boundingBox())
    , chain(chain_)
    , k(k_)
    , depth(depth_)
    , t0(a)
    , t1(b)
    , finest(depth_ >= MaxFlattenDepth || chordDeviation(curve) <= tolerance)
  {
  }
};

struct Search
{
  const std::vector<std::vector<const BezierCurve*>>& chains;
  double tolerance;
  CurveCrossing result;

  // Consecutive chords along a chain share an end: not a crossing.
  bool neighbours(const Part& p, const Part& q) const
  {
    if (p.chain != q.chain)
      return false;
    const int n = static_cast<int>(chains[p.chain].size());
    auto follows = [n](const Part& a, const Part& b) { // b starts where a ends
      if (a.k == b.k && a.t1 == b.t0)
        return true;
      return b.k == (a.k + 1) % n && a.t1 == 1.0 && b.t0 == 0.0;
    };
    return follows(p, q) || follows(q, p);
  }

  void halve(const Part& p, Part*& left, Part*& right, std::vector<Part>& store) const
  {
    BezierCurve l, r;
    p.curve.split(0.5, l, r);
    const double m = 0.5 * (p.t0 + p.t1);
    store.emplace_back(std::move(l), p.chain, p.k, p.t0, m, p.depth + 1, tolerance);
    store.emplace_back(std::move(r), p.chain, p.k, m, p.t1, p.depth + 1, tolerance);
    left = &store[store.size() - 2];
    right = &store.back();
  }

  // A part whose control polygon advances along one direction u (every leg has u·leg > 0)
  // is monotone along u, rational or not (its derivative is a positive combination of the
  // legs), and so is any polyline through its points in order: chords that are not
  // consecutive cover disjoint ranges of u, so none of them cross.
  static bool monotone(const BezierCurve& c) { return monotone(c, nullptr); }

  // The same for two parts one after the other (`next` starts where c ends): their control
  // polygons joined advance along one direction, so no chord of one crosses a chord of the
  // other but the two that meet at the joint (consecutive, sharing only it). Neighbouring
  // parts always have touching boxes, and would be halved down to the finest chords at
  // every junction of the boundary otherwise.
  static bool monotone(const BezierCurve& c, const BezierCurve* next)
  {
    Vec3 points[2 * (MaxDegree + 1)];
    int n = 0;
    for (int i = 0; i <= c.degree(); ++i)
      points[n++] = c.controlPoint(i);
    if (next)
      for (int i = 1; i <= next->degree(); ++i)
        points[n++] = next->controlPoint(i);
    Vec3 sum = Vec3::Zero();
    for (int i = 0; i + 1 < n; ++i)
    {
      const Vec3 leg = points[i + 1] - points[i];
      const double len = leg.norm();
      if (len > 0.0)
        sum += leg / len;
    }
    for (const Vec3& u : { Vec3(points[n - 1] - points[0]), sum })
    {
      bool all = true;
      for (int i = 0; i + 1 < n && all; ++i)
        all = (points[i + 1] - points[i]).dot(u) > 0.0;
      if (all)
        return true;
    }
    return false;
  }

  // q starts where p ends (the next part along the same chain).
  bool follows(const Part& p, const Part& q) const
  {
    if (p.chain != q.chain)
      return false;
    const int n = static_cast<int>(chains[p.chain].size());
    if (p.k == q.k)
      return p.t1 == q.t0;
    return q.k == (p.k + 1) % n && p.t1 == 1.0 && q.t0 == 0.0;
  }

  // Whether the part's own chords cross (a curve that loops onto itself).
  bool self(const Part& p)
  {
    if (p.finest || monotone(p.curve))
      return false;
    std::vector<Part> store;
    store.reserve(2);
    Part *a = nullptr, *b = nullptr;
    halve(p, a, b, store);
    return self(*a) || self(*b) || pair(*a, *b);
  }

  // Refines the pair until its boxes part or both are finest; true when they cross.
  bool pair(const Part& p, const Part& q)
  {
    if (!p.box.intersects(q.box))
      return false;
    if ((follows(p, q) && monotone(p.curve, &q.curve)) || (follows(q, p) && monotone(q.curve, &p.curve)))
      return false;
    if (p.finest && q.finest)
    {
      if (neighbours(p, q) ||
        !segmentsIntersect(p.curve.startPoint(), p.curve.endPoint(), q.curve.startPoint(), q.curve.endPoint()))
        return false;
      result = { true, p.chain, p.k, q.chain, q.k, 0.5 * (p.curve.startPoint() + p.curve.endPoint()) };
      return true;
    }
    // Halve the coarser part (both ends of the recursion are flatten()'s own halvings).
    const bool splitP = !p.finest && (q.finest || p.depth <= q.depth);
    std::vector<Part> store;
    store.reserve(2);
    Part *a = nullptr, *b = nullptr;
    halve(splitP ? p : q, a, b, store);
    return splitP ? (pair(*a, q) || pair(*b, q)) : (pair(p, *a) || pair(p, *b));
  }
};
} // namespace

CurveCrossing findCrossing(
  const std::vector<std::vector<const BezierCurve*>>& chains, double tolerance)
{
  Search search{ chains, tolerance, {} };
  // flatten() always halves a curve once (a closed single curve would be one chord).
  std::vector<Part> parts;
  for (size_t c = 0; c < chains.size(); ++c)
    for (size_t k = 0; k < chains[c].size(); ++k)
    {
      BezierCurve l, r;
      chains[c][k]->split(0.5, l, r);
      parts.emplace_back(std::move(l), static_cast<int>(c), static_cast<int>(k), 0.0, 0.5, 1, tolerance);
      parts.emplace_back(std::move(r), static_cast<int>(c), static_cast<int>(k), 0.5, 1.0, 1, tolerance);
    }
  for (const Part& p : parts)
    if (search.self(p))
      return search.result;
  // Sweep along x: only parts whose boxes overlap in x are paired.
  std::vector<int> order(parts.size());
  for (size_t i = 0; i < order.size(); ++i)
    order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(),
    [&parts](int a, int b) { return parts[a].box.min().x() < parts[b].box.min().x(); });
  for (size_t i = 0; i < order.size(); ++i)
  {
    const Part& p = parts[order[i]];
    for (size_t j = i + 1; j < order.size() && parts[order[j]].box.min().x() <= p.box.max().x(); ++j)
      if (search.pair(p, parts[order[j]]))
        return search.result;
  }
  return search.result;
}

} // namespace exactmat

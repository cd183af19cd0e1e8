#include "Generators.h"

#include "common/Format.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace exactmat
{

namespace
{
Vec2 xy(const Vec3& v)
{
  return Vec2(v.x(), v.y());
}

Vec2 perp(const Vec2& v)
{
  return Vec2(-v.y(), v.x());
}

double angleOf(const Vec2& v)
{
  return std::atan2(v.y(), v.x());
}
} // namespace

Generators::Generators(const Boundary2D& boundary)
  : Boundary(&boundary)
{
  const auto& edges = boundary.edges();
  const auto& vertices = boundary.vertices();
  CornerOfVertex.assign(vertices.size(), -1);
  GeneratorOfEdge.assign(edges.size(), -1);
  for (size_t l = 0; l < boundary.loops().size(); ++l)
  {
    const Loop2D& loop = boundary.loops()[l];
    const int first = static_cast<int>(List.size());
    for (int e : loop.edges)
    {
      Generator g;
      g.kind = GeneratorKind::Edge;
      g.edge = e;
      g.loop = static_cast<int>(l);
      g.entity = edges[e].entity;
      const BezierCurve& c = edges[e].curve;
      g.straight = c.degree() == 1 && c.homogeneousPoints()[0].w() == c.homogeneousPoints()[1].w();
      GeneratorOfEdge[e] = static_cast<int>(List.size());
      List.push_back(g);
      const int v = edges[e].endVertex;
      if (vertices[v].kind == VertexKind::Reflex)
      {
        Generator c;
        c.kind = GeneratorKind::ReflexCorner;
        c.vertex = v;
        c.loop = static_cast<int>(l);
        const Vec2 nIn = xy(edges[e].curve.endTangent(true));
        c.angle0 = angleOf(perp(nIn));
        c.sweep = vertices[v].turningAngle; // < 0: the normal turns clockwise
        CornerOfVertex[v] = static_cast<int>(List.size());
        List.push_back(c);
      }
    }
    const int count = static_cast<int>(List.size()) - first;
    for (int k = 0; k < count; ++k)
    {
      Generator& g = List[first + k];
      g.next = first + (k + 1) % count;
      g.prev = first + (k + count - 1) % count;
    }
    // Junctions: between an edge and a corner generator the front moves on (Reflex);
    // between two edges, the vertex's own kind.
    for (int k = 0; k < count; ++k)
    {
      Generator& g = List[first + k];
      const Generator& n = List[g.next];
      if (g.kind == GeneratorKind::ReflexCorner || n.kind == GeneratorKind::ReflexCorner)
      {
        g.endJunction = VertexKind::Reflex;
      }
      else
      {
        g.endJunction = vertices[edges[g.edge].endVertex].kind;
      }
      List[g.next].startJunction = g.endJunction;
    }
  }
  // The tree's items: an edge's box, or for a slanted straight edge the boxes of pieces
  // of it (a radial spike's one box holds a triangle of empty space that a disk near the
  // star's centre reaches: hundreds of false candidates a query). Each piece's box is
  // padded by a few ulps, so it holds the edge's own evaluation of that stretch.
  std::vector<Box3> boxes;
  for (int e = 0; e < static_cast<int>(edges.size()); ++e)
  {
    const BezierCurve& c = edges[e].curve;
    const Box3 whole = c.boundingBox();
    const Vec3 extent = whole.sizes();
    const double thin = std::min(extent.x(), extent.y()), thick = std::max(extent.x(), extent.y());
    const bool line = c.degree() == 1 && c.homogeneousPoints()[0].w() == c.homogeneousPoints()[1].w();
    // The empty space a straight edge's box holds reaches thin·thick/length from the edge;
    // pieces keep that under Reach of the boundary's size (at most 32 of them). Short
    // edges (saw teeth, a dense polygon's sides) stay one item, and so does every edge of
    // a boundary of few: a query cannot have more false candidates than there are edges,
    // and where every disk touches every edge (a regular polygon's centre) pieces only
    // multiply the boxes to visit.
    constexpr double Reach = 1e-2;
    const double looseness = thick > 0.0 ? thin * thick / std::hypot(thin, thick) : 0.0;
    const int pieces = line && edges.size() > 64
      ? std::min(32, 1 + static_cast<int>(looseness / (Reach * size2D())))
      : 1;
    if (pieces == 1)
    {
      boxes.push_back(whole);
      ItemEdge.push_back(e);
      continue;
    }
    const Vec3 a = euclidean(c.homogeneousPoints()[0]), b = euclidean(c.homogeneousPoints()[1]);
    const double pad = 8.0 * std::numeric_limits<double>::epsilon() * (a.cwiseAbs().maxCoeff() + b.cwiseAbs().maxCoeff());
    for (int k = 0; k < pieces; ++k)
    {
      const double t0 = static_cast<double>(k) / pieces, t1 = static_cast<double>(k + 1) / pieces;
      Box3 piece;
      piece.extend(a + t0 * (b - a));
      piece.extend(a + t1 * (b - a));
      piece.min().array() -= pad;
      piece.max().array() += pad;
      boxes.push_back(piece.intersection(whole));
      ItemEdge.push_back(e);
    }
  }
  Tree.build(boxes);
  Carriers.resize(edges.size());
  for (size_t e = 0; e < edges.size(); ++e)
    Carriers[e] = ConicCarrier::of(edges[e].curve, size2D());
}

std::string Generators::describe(const Vec2& x) const
{
  return format(Boundary->userPoint(x));
}

namespace
{
// A rational quadratic (the conics of most profiles, at every Newton iteration of the
// tracer): de Casteljau on x, y, w only, one reciprocal of the weight and of the speed
// instead of nine and three divisions. The same point and derivatives as the general
// path to rounding.
GeneratorPoint evaluateConic(const BezierCurve& curve, double t)
{
  const Vec4List& q = curve.homogeneousPoints();
  const double s = 1.0 - t;
  const Eigen::Vector3d q0(q[0].x(), q[0].y(), q[0].w()), q1(q[1].x(), q[1].y(), q[1].w()),
    q2(q[2].x(), q[2].y(), q[2].w());
  const Eigen::Vector3d r0 = s * q0 + t * q1, r1 = s * q1 + t * q2;
  const Eigen::Vector3d a0 = s * r0 + t * r1, a1 = 2.0 * (r1 - r0), a2 = 2.0 * (q2 - 2.0 * q1 + q0);
  const double iw = 1.0 / a0.z();
  GeneratorPoint out;
  out.p = a0.head<2>() * iw;
  const Vec2 d1 = (a1.head<2>() - a1.z() * out.p) * iw;
  const Vec2 d2 = (a2.head<2>() - 2.0 * a1.z() * d1 - a2.z() * out.p) * iw;
  const double invSpeed = 1.0 / d1.norm();
  out.n = perp(d1 * invSpeed);
  out.dp = d1;
  out.curvature = (d1.x() * d2.y() - d1.y() * d2.x()) * (invSpeed * invSpeed * invSpeed);
  out.dn = -out.curvature * d1; // N' = −κ·C' for the left normal
  return out;
}
} // namespace

GeneratorPoint Generators::evaluate(int gi, double s) const
{
  const Generator& g = List[gi];
  GeneratorPoint out;
  if (g.kind == GeneratorKind::ReflexCorner)
  {
    const double a = g.angle0 + s * g.sweep;
    out.p = xy(Boundary->vertices()[g.vertex].point);
    out.n = Vec2(std::cos(a), std::sin(a));
    out.dp = Vec2::Zero();
    out.dn = g.sweep * perp(out.n);
    out.curvature = std::numeric_limits<double>::infinity();
    return out;
  }
  const BezierCurve& curve = Boundary->edges()[g.edge].curve;
  if (curve.degree() == 2)
    return evaluateConic(curve, s);
  const CurveDerivatives d = curve.derivatives(s);
  const Vec2 d1 = xy(d.d1), d2 = xy(d.d2);
  const double speed = d1.norm();
  const Vec2 t = d1 / speed;
  out.p = xy(d.point);
  out.n = perp(t);
  out.dp = d1;
  // A straight edge has no curvature: exactly 0, not the rounding of C'' (which would make
  // it a curve with a centre of curvature 1e16 away to look for). Its point and tangent
  // stay the generic evaluation's: a closed form A + s (B − A) differs by an ulp, which a
  // 1e-6-thin extruded plate's sheet verification has been seen to notice.
  out.curvature = straight(gi) ? 0.0 : (d1.x() * d2.y() - d1.y() * d2.x()) / (speed * speed * speed);
  out.dn = -out.curvature * d1; // N' = −κ·C' for the left normal
  return out;
}

bool Generators::straight(int gi) const
{
  return List[gi].straight;
}

double Generators::distance(const Vec2& x, Vec2* nearest) const
{
  const Vec3 q(x.x(), x.y(), 0.0);
  const auto& edges = Boundary->edges();
  double d = 0.0;
  // An edge in pieces is asked once for each piece the search reaches: remember the last.
  int last = -1;
  CurveFootpoint lastFoot, best;
  best.distance = INFINITY;
  Tree.nearest(
    q,
    [&](int item) {
      const int e = ItemEdge[item];
      if (e != last)
      {
        last = e;
        lastFoot = closestPoint(edges[e].curve, q);
        if (lastFoot.distance < best.distance)
          best = lastFoot;
      }
      return lastFoot.distance;
    },
    &d);
  if (nearest)
    *nearest = xy(best.point);
  return d;
}

bool Generators::anyCloserThan(const Vec2& x, double radius) const
{
  const Vec3 q(x.x(), x.y(), 0.0);
  const auto& edges = Boundary->edges();
  int last = -1; // an edge's pieces, met one after another, are one question
  return Tree.anyWithin(q, radius, [&](int item) {
    const int e = ItemEdge[item];
    if (e == last)
      return false;
    last = e;
    return !staysOutside(e, q, radius) && curveComesWithin(edges[e].curve, q, radius);
  });
}

bool Generators::anyCloserThan(
  const Vec2& x, double radius, int touchA, double sa, int touchB, double sb) const
{
  const Vec3 q(x.x(), x.y(), 0.0);
  const auto& edges = Boundary->edges();
  const int ea = List[touchA].kind == GeneratorKind::Edge ? List[touchA].edge : -1;
  const int eb = List[touchB].kind == GeneratorKind::Edge ? List[touchB].edge : -1;
  int last = -1;
  return Tree.anyWithin(q, radius, [&](int item) {
    const int e = ItemEdge[item];
    if (e == last)
      return false;
    last = e;
    if (staysOutside(e, q, radius))
      return false;
    if (e == ea)
      return curveComesWithin(edges[e].curve, q, radius, sa);
    if (e == eb)
      return curveComesWithin(edges[e].curve, q, radius, sb);
    return curveComesWithin(edges[e].curve, q, radius);
  });
}

namespace
{
// The least t ∈ [0, 1] at which the disk (x0 + t b, r0 + t k) reaches the segment [e0, e1]
// (its distance ≤ the radius, the radius positive), or +∞. The distance to a segment is
// that to its line where the foot falls inside it, else that to an end point: the first
// contact is the earlier of the end points' and of the line's while its foot is inside.
double firstSegmentContact(const Vec2& x0, const Vec2& b, double r0, double k, const Vec2& e0, const Vec2& e1)
{
  const Vec2 edge = e1 - e0;
  const double length2 = edge.squaredNorm();
  // The segment is no nearer than its line: when the centres stay on one side of it and
  // farther than the radius at both ends (|d| − r is linear there), no disk reaches it —
  // most edges a sweep's boxes bring, settled without a square root.
  // (d0, dd: the signed distance of x0 from the line and its change along b, times |edge|.)
  const Vec2 normal(-edge.y(), edge.x());
  const double d0 = normal.dot(x0 - e0), dd = normal.dot(b), d1 = d0 + dd;
  if ((d0 > 0.0) == (d1 > 0.0) && d0 * d0 > r0 * std::abs(r0) * length2 &&
    d1 * d1 > (r0 + k) * std::abs(r0 + k) * length2)
    return INFINITY;
  double first = INFINITY;
  const double A = b.squaredNorm() - k * k;
  for (const Vec2& e : { e0, e1 })
  {
    // |a + t b|² = (r0 + t k)²: A t² + 2 B t + C = 0, the smaller root with r > 0.
    const Vec2 a = x0 - e;
    const double B = a.dot(b) - r0 * k, C = a.squaredNorm() - r0 * r0;
    if (C <= 0.0 && r0 > 0.0)
      return 0.0;
    const double D = B * B - A * C;
    if (!(D >= 0.0))
      continue;
    const double q = -(B + std::copysign(std::sqrt(D), B));
    for (const double t : { q / A, q != 0.0 ? C / q : INFINITY })
      if (t >= 0.0 && t <= 1.0 && r0 + t * k > 0.0)
        first = std::min(first, t);
  }
  // The line: |d0 + t dd| ≤ r0 + t k, i.e. (dd − k) t ≤ r0 − d0 and (dd + k) t ≥ −r0 − d0,
  // with the foot's parameter u0 + t du in [0, 1].
  if (length2 > 0.0)
  {
    const double length = std::sqrt(length2);
    const double u0 = (x0 - e0).dot(edge) / length2, du = b.dot(edge) / length2;
    double lo = 0.0, hi = 1.0;
    auto atMost = [&](double slope, double bound) { // slope · t ≤ bound
      if (slope > 0.0)
        hi = std::min(hi, bound / slope);
      else if (slope < 0.0)
        lo = std::max(lo, bound / slope);
      else if (bound < 0.0)
        hi = -1.0;
    };
    atMost(dd / length - k, r0 - d0 / length);
    atMost(-(dd / length + k), r0 + d0 / length);
    atMost(du, 1.0 - u0);
    atMost(-du, u0);
    if (lo <= hi && r0 + lo * k > 0.0)
      first = std::min(first, lo);
  }
  return first;
}

} // namespace

SweepContact Generators::firstContact(const Vec2& x0, double r0, const Vec2& x1, double r1, int touchA,
  int touchB, double& t, double endsEmpty) const
{
  const Vec2 b = x1 - x0;
  const double k = r1 - r0;
  t = INFINITY;
  if (!(std::abs(k) < b.norm()) && b.squaredNorm() > 0.0)
    return SweepContact::Undecided;
  const auto& edges = Boundary->edges();
  const int ea = List[touchA].kind == GeneratorKind::Edge ? List[touchA].edge : -1;
  const int eb = List[touchB].kind == GeneratorKind::Edge ? List[touchB].edge : -1;
  // Every disk of the sweep lies in the disk about its middle that reaches its ends'.
  const Vec2 middle = 0.5 * (x0 + x1);
  const Vec3 q(middle.x(), middle.y(), 0.0);
  const double reach = 0.5 * b.norm() + std::max(r0, r1);
  // With both end disks empty, what is left of the sweep (the convex hull of the two end
  // disks) are the two slivers between them and their common tangent beside each touched
  // line: each lies in the triangle of the tangent's touch points and the end circles'
  // crossing nearer to it (the arcs bound it from inside those chords). The tangent runs
  // inside the line by the disks' margin: the triangle is taken from the feet of x0 and
  // x1 on the line itself, padded by twice that margin.
  Box3 slivers[2];
  Vec2 corners[2][3]; // each sliver's triangle (counter-clockwise)
  bool local = endsEmpty >= 0.0 && ea >= 0 && eb >= 0 && List[touchA].straight && List[touchB].straight;
  const double d = b.norm();
  if (local)
  {
    // The circles' crossings: a along b, ±h across it.
    const double along = (r0 * r0 - r1 * r1 + d * d) / (2.0 * d), h2 = r0 * r0 - along * along;
    local = d > 0.0 && h2 > 0.0;
    if (local)
    {
      const Vec2 u = b / d, across(-u.y(), u.x());
      const Vec2 crossing[2] = { x0 + along * u + std::sqrt(h2) * across, x0 + along * u - std::sqrt(h2) * across };
      const int lines[2] = { ea, eb };
      const double pad = 2.0 * endsEmpty + 1e-12 * (size2D() + reach);
      for (int side = 0; side < 2; ++side)
      {
        const Vec2 e0 = edges[lines[side]].curve.startPoint().head<2>(), e1 = edges[lines[side]].curve.endPoint().head<2>();
        const Vec2 dir = (e1 - e0).normalized();
        auto foot = [&](const Vec2& x) { return Vec2(e0 + (x - e0).dot(dir) * dir); };
        auto fromLine = [&](const Vec2& x) { return std::abs(dir.x() * (x - e0).y() - dir.y() * (x - e0).x()); };
        const Vec2& apex = fromLine(crossing[0]) <= fromLine(crossing[1]) ? crossing[0] : crossing[1];
        Vec2* tri = corners[side];
        tri[0] = foot(x0);
        tri[1] = foot(x1);
        tri[2] = apex;
        const Vec2 u1 = tri[1] - tri[0], u2 = tri[2] - tri[0];
        if (u1.x() * u2.y() - u1.y() * u2.x() < 0.0)
          std::swap(tri[1], tri[2]);
        for (int k = 0; k < 3; ++k)
          slivers[side].extend(Vec3(tri[k].x(), tri[k].y(), 0.0));
        slivers[side].min().array() -= pad;
        slivers[side].max().array() += pad;
      }
    }
  }
  // A box meets a (padded) triangle unless one of the triangle's sides, or its bounding
  // box, separates them: a long sliver lies along a line any way it turns, its bounding
  // box does not.
  const double pad = 2.0 * std::max(endsEmpty, 0.0) + 1e-12 * (size2D() + reach);
  auto meets = [&](const Box3& box, int side) {
    if (!box.intersects(slivers[side]))
      return false;
    const Vec2 c = 0.5 * (box.min() + box.max()).head<2>(), half = 0.5 * (box.max() - box.min()).head<2>();
    const Vec2* tri = corners[side];
    for (int k = 0; k < 3; ++k)
    {
      const Vec2 e = tri[(k + 1) % 3] - tri[k];
      const Vec2 n(e.y(), -e.x()); // outward for a counter-clockwise triangle
      const double length = n.norm();
      if (length > 0.0 && n.dot(c - tri[k]) - std::abs(n.x()) * half.x() - std::abs(n.y()) * half.y() > pad * length)
        return false;
    }
    return true;
  };
  auto reaches = [&](const Box3& box) {
    if (local)
      return meets(box, 0) || meets(box, 1);
    const Vec3 nearest = q.cwiseMax(box.min()).cwiseMin(box.max());
    return (nearest - q).squaredNorm() <= reach * reach;
  };
  bool undecided = false;
  int last = -1;
  Tree.anyWhere(reaches, [&](int item) {
    const int e = ItemEdge[item];
    if (e == last || e == ea || e == eb)
      return false;
    last = e;
    const BezierCurve& c = edges[e].curve;
    if (!List[GeneratorOfEdge[e]].straight)
    {
      // No closed form: the sweep is undecided unless the curve stays out of its reach.
      undecided = !staysOutside(e, q, reach) && curveComesWithin(c, q, reach);
      return undecided;
    }
    const Vec3 e0 = c.startPoint(), e1 = c.endPoint();
    t = std::min(t, firstSegmentContact(x0, b, r0, k, Vec2(e0.x(), e0.y()), Vec2(e1.x(), e1.y())));
    return t == 0.0;
  });
  if (undecided)
    return SweepContact::Undecided;
  return t <= 1.0 ? SweepContact::Contact : SweepContact::Clear;
}

std::vector<BoundaryLocation> Generators::footpointsWithin(const Vec2& x, double radius) const
{
  const Vec3 q(x.x(), x.y(), 0.0);
  const auto& edges = Boundary->edges();
  const double merge = 1e-9 * size2D();
  std::vector<BoundaryLocation> out;
  auto addUnique = [&](const BoundaryLocation& b) { out.push_back(b); };
  // A corner within the radius is an end of an edge within it: the tree's candidates
  // name every corner to look at (not all of them: a star polygon of n edges has n/2).
  std::vector<int> candidates = Tree.candidatesWithin(q, radius);
  for (int& item : candidates)
    item = ItemEdge[item];
  // Items come in increasing order and an edge's pieces are consecutive items.
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  std::vector<int> corners;
  for (int e : candidates)
    for (int c : { List[GeneratorOfEdge[e]].prev, List[GeneratorOfEdge[e]].next })
      if (List[c].kind == GeneratorKind::ReflexCorner)
        corners.push_back(c);
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  for (int c : corners)
  {
    const Generator& g = List[c];
    const Vec2 v = xy(Boundary->vertices()[g.vertex].point);
    const Vec2 d = x - v;
    if (d.norm() > radius || d.norm() == 0.0)
    {
      continue;
    }
    // Is the direction to x inside the corner's normal cone?
    double a = angleOf(d) - g.angle0;
    a = std::remainder(a, 2.0 * M_PI);
    const double s = a / g.sweep;
    if (s >= -1e-9 && s <= 1.0 + 1e-9)
    {
      addUnique({ c, std::min(1.0, std::max(0.0, s)), v, d.normalized(), false });
    }
  }
  for (int e : candidates)
  {
    for (const CurveFootpoint& f :
      curveFootpoints(edges[e].curve, q, radius, 16.0 * Boundary->userFrame().inputRounding()))
    {
      const int g = GeneratorOfEdge[e];
      const GeneratorPoint gp = evaluate(g, f.t);
      if (f.atEnd && !f.continuum)
      {
        // A one-sided minimum at a smooth junction is no footpoint when the neighbouring
        // edge gets closer still beyond the junction.
        const bool atStart = f.t <= 0.5;
        const Generator& gen = List[g];
        if ((atStart ? gen.startJunction : gen.endJunction) == VertexKind::Smooth)
        {
          const int n = atStart ? gen.prev : gen.next;
          const GeneratorPoint np = evaluate(n, atStart ? 1.0 : 0.0);
          // d|C − x|²/2 along the neighbour, relative: a minimum exactly at the junction
          // has slope 0 up to rounding and stays.
          const double slope = (np.p - x).dot(np.dp) / ((np.p - x).norm() * np.dp.norm() + 1e-300);
          if (atStart ? slope > 1e-8 : slope < -1e-8)
            continue;
        }
      }
      addUnique({ g, f.t, gp.p, gp.n, f.continuum });
    }
  }
  // Merge footpoints that coincide (a minimum at an edge's end belongs to the corner or
  // vertex there; a corner generator describes it best, carrying the normal towards x).
  // Coinciding points have the same direction from x: sorted by angle they are
  // neighbours, so merging is O(k log k) — a regular n-gon's centre has n footpoints.
  auto angle = [&](const BoundaryLocation& b) {
    const Vec2 d = b.point - x;
    return d.norm() > 0.0 ? std::atan2(d.y(), d.x()) : std::atan2(-b.normal.y(), -b.normal.x());
  };
  std::vector<std::pair<double, BoundaryLocation>> sorted;
  sorted.reserve(out.size());
  for (const BoundaryLocation& b : out)
    sorted.push_back({ angle(b), b });
  std::sort(sorted.begin(), sorted.end(),
    [](const auto& u, const auto& v) { return u.first < v.first; });
  std::vector<BoundaryLocation> merged;
  for (const auto& [a, b] : sorted)
  {
    if (!merged.empty() && (merged.back().point - b.point).norm() <= merge)
    {
      if (List[b.g].kind == GeneratorKind::ReflexCorner)
        merged.back() = b;
      continue;
    }
    merged.push_back(b);
  }
  // The angle wraps around: the last may coincide with the first.
  if (merged.size() > 1 && (merged.back().point - merged.front().point).norm() <= merge)
  {
    if (List[merged.back().g].kind == GeneratorKind::ReflexCorner)
      merged.front() = merged.back();
    merged.pop_back();
  }
  return merged;
}

} // namespace exactmat

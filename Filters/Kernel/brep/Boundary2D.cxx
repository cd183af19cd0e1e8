#include "Boundary2D.h"

#include "common/Format.h"
#include "common/InputError.h"
#include "common/UnionFind.h"
#include "geometry/CurveCrossings.h"
#include "geometry/Flatten.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace exactmat
{

const char* toString(VertexKind kind)
{
  switch (kind)
  {
    case VertexKind::Convex:
      return "convex";
    case VertexKind::Reflex:
      return "reflex";
    default:
      return "smooth";
  }
}

std::string Edge2D::name() const
{
  std::string s = "edge " + std::to_string(piece);
  if (entity >= 0 && entity != piece)
  {
    s += " (entity " + std::to_string(entity) + ")";
  }
  return s;
}

namespace
{
std::string pieceName(const std::vector<CurvePiece>& pieces, size_t i)
{
  Edge2D e;
  e.piece = static_cast<int>(i);
  e.entity = pieces[i].entity;
  return e.name();
}



// 16-point Gauss–Legendre on [0,1].
const double GaussX[8] = { 0.0950125098376374, 0.2816035507792589, 0.4580167776572274,
  0.6178762444026438, 0.7554044083550030, 0.8656312023878318, 0.9445750230732326,
  0.9894009349916499 };
const double GaussW[8] = { 0.1894506104550685, 0.1826034150449236, 0.1691565193950025,
  0.1495959888165767, 0.1246289712555339, 0.0951585116824928, 0.0622535239386479,
  0.0271524594117541 };

// ½∮(x dy − y dx) over one curve: exact in closed form for a straight edge; for a
// polynomial curve the integrand is a polynomial of degree 2p − 1, which 16 Gauss points
// integrate exactly up to p = 16; a rational one on 4 sub-intervals of 16 points each.
double areaContribution(const BezierCurve& c)
{
  const Vec4List& h4 = c.homogeneousPoints();
  const bool polynomial = std::all_of(
    h4.begin(), h4.end(), [&h4](const Vec4& h) { return h.w() == h4.front().w(); });
  if (polynomial && c.degree() == 1)
  {
    const Vec3 a = c.startPoint(), b = c.endPoint();
    return 0.5 * (a.x() * b.y() - a.y() * b.x());
  }
  // Gauss–Legendre with 16 points is exact for polynomials up to degree 31; a rational
  // piece whose weights stay within a factor 4 has its poles far from [0, 1] (a conic arc
  // up to a half circle), so one part reaches rounding too. Wilder weights: four parts.
  double wMin = h4.front().w(), wMax = wMin;
  for (const Vec4& h : h4)
  {
    wMin = std::min(wMin, h.w());
    wMax = std::max(wMax, h.w());
  }
  const int parts = (polynomial && c.degree() <= 16) || (c.degree() <= 3 && wMax <= 4.0 * wMin) ? 1 : 4;
  double sum = 0.0;
  for (int part = 0; part < parts; ++part)
  {
    const double h = 1.0 / parts, a = h * part;
    for (int k = 0; k < 8; ++k)
    {
      for (int sgn = -1; sgn <= 1; sgn += 2)
      {
        const double t = a + 0.5 * h * (1.0 + sgn * GaussX[k]);
        const CurveDerivatives d = c.derivatives(t);
        sum += 0.5 * h * GaussW[k] * 0.5 * (d.point.x() * d.d1.y() - d.point.y() * d.d1.x());
      }
    }
  }
  return sum;
}

// Crossing-number test of p against a closed polyline.
bool insidePolyline(const Vec3List& poly, const Vec3& p)
{
  bool inside = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
  {
    const Vec3& a = poly[i];
    const Vec3& b = poly[j];
    if ((a.y() > p.y()) != (b.y() > p.y()))
    {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x)
      {
        inside = !inside;
      }
    }
  }
  return inside;
}
} // namespace

Boundary2D Boundary2D::build(const std::vector<CurvePiece>& pieces, const Options& options)
{
  if (pieces.empty())
  {
    fail("empty input: the boundary has no curves");
  }
  Boundary2D b;
  b.UserFrame = options.userFrame;
  for (size_t i = 0; i < pieces.size(); ++i)
  {
    pieces[i].curve.toNurbs().validate(pieceName(pieces, i));
  }
  b.findPlane(pieces, options);
  b.findLoops(pieces, options);
  b.orientLoops();
  b.checkIntersections();
  b.classifyVertices(options);
  return b;
}

void Boundary2D::findPlane(const std::vector<CurvePiece>& pieces, const Options& options)
{
  Vec3List points;
  Box3 box;
  for (const CurvePiece& p : pieces)
  {
    for (int i = 0; i <= p.curve.degree(); ++i)
    {
      points.push_back(p.curve.controlPoint(i));
      box.extend(points.back());
    }
  }
  Diagonal = box.diagonal().norm();
  if (!(Diagonal > 0.0))
  {
    fail("degenerate input: all ", points.size(), " control points coincide at ",
      format(UserFrame.toUser(points.front())));
  }
  ThePlane = Plane::fit(points);
  const double tol = options.planarityTolerance * Diagonal;
  for (size_t i = 0; i < pieces.size(); ++i)
  {
    for (int k = 0; k <= pieces[i].curve.degree(); ++k)
    {
      const double off = ThePlane.toLocal(pieces[i].curve.controlPoint(k)).z();
      if (std::abs(off) > tol)
      {
        fail("non-planar boundary: control point ", k, " of ", pieceName(pieces, i), " lies ",
          UserFrame.lengthToUser(off), " off the plane through the boundary (tolerance ", UserFrame.lengthToUser(tol), ")");
      }
    }
  }
}

void Boundary2D::findLoops(const std::vector<CurvePiece>& pieces, const Options& options)
{
  const int n = static_cast<int>(pieces.size());
  const double tol = options.pointTolerance * Diagonal;
  // Local-frame curves with z set to exactly 0 (planarity was checked).
  std::vector<BezierCurve> local(n);
  for (int i = 0; i < n; ++i)
  {
    Vec4List h = pieces[i].curve.homogeneousPoints();
    for (Vec4& p : h)
    {
      p = ThePlane.toLocalHomogeneous(p);
      p.z() = 0.0;
    }
    local[i] = BezierCurve(std::move(h));
    const Box3 box = local[i].boundingBox();
    if (!(box.diagonal().norm() > tol))
    {
      fail(pieceName(pieces, i), " is degenerate: all its control points coincide at ",
        format(UserFrame.toUser(pieces[i].curve.startPoint())));
    }
  }
  // Ends 2i (start) and 2i+1 (end) of piece i, merged by shared ids, then by coordinates.
  auto endPoint = [&](int e) {
    return (e % 2 == 0) ? local[e / 2].startPoint() : local[e / 2].endPoint();
  };
  UnionFind uf(2 * n);
  std::map<long long, int> byId;
  for (int e = 0; e < 2 * n; ++e)
  {
    const long long id = (e % 2 == 0) ? pieces[e / 2].startId : pieces[e / 2].endId;
    if (id >= 0)
    {
      auto [it, inserted] = byId.emplace(id, e);
      if (!inserted)
      {
        uf.unite(e, it->second);
      }
    }
  }
  std::vector<int> order(2 * n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
    [&](int a, int b) { return endPoint(a).x() < endPoint(b).x(); });
  for (int a = 0; a < 2 * n; ++a)
  {
    const Vec3 pa = endPoint(order[a]);
    for (int c = a + 1; c < 2 * n && endPoint(order[c]).x() - pa.x() <= tol; ++c)
    {
      if ((endPoint(order[c]) - pa).norm() <= tol)
      {
        uf.unite(order[a], order[c]);
      }
    }
  }
  std::map<int, std::vector<int>> groups;
  for (int e = 0; e < 2 * n; ++e)
  {
    groups[uf.find(e)].push_back(e);
  }
  std::vector<int> partner(2 * n, -1);
  for (const auto& [root, ends] : groups)
  {
    if (ends.size() == 1)
    {
      const int e = ends.front();
      fail("open loop: ", pieceName(pieces, e / 2), (e % 2 == 0 ? " starts" : " ends"), " at ",
        format(UserFrame.toUser(pieces[e / 2].curve.evaluate(e % 2 == 0 ? 0.0 : 1.0))),
        " where no other edge starts or ends");
    }
    if (ends.size() > 2)
    {
      std::string names;
      for (int e : ends)
      {
        names += (names.empty() ? "" : ", ") + pieceName(pieces, e / 2);
      }
      fail("non-manifold vertex at ",
        format(UserFrame.toUser(pieces[ends[0] / 2].curve.evaluate(ends[0] % 2))),
        ": ", ends.size(), " edge ends meet there (", names,
        "); each vertex must join exactly two edges");
    }
    partner[ends[0]] = ends[1];
    partner[ends[1]] = ends[0];
  }
  // Walk the loops; an edge met against its direction is reversed.
  std::vector<bool> used(n, false);
  Edges.resize(n);
  for (int start = 0; start < n; ++start)
  {
    if (used[start])
    {
      continue;
    }
    Loop2D loop;
    int edge = start;
    bool reversed = false;
    for (int guard = 0; guard <= n && !used[edge]; ++guard)
    {
      used[edge] = true;
      Edge2D& e = Edges[edge];
      e.piece = edge;
      e.entity = pieces[edge].entity;
      e.reversed = reversed;
      e.curve = reversed ? local[edge].reversed() : local[edge];
      e.loop = static_cast<int>(Loops.size());
      loop.edges.push_back(edge);
      const int exitEnd = 2 * edge + (reversed ? 0 : 1);
      const int enterEnd = partner[exitEnd];
      edge = enterEnd / 2;
      reversed = (enterEnd % 2 == 1);
    }
    Loops.push_back(std::move(loop));
  }
}

void Boundary2D::orientLoops()
{
  // Nesting needs polygons only when there is more than one loop (most parts have one).
  // A coarse polygon answers "is the probe inside?" as the curves would wherever the probe
  // lies outside every part's control-point box: the region between a part and its chord
  // lies in that box, so a ray from outside crosses both equally often. Otherwise the
  // loop's fine polygon (1e-6 of the size) answers.
  const bool nested = Loops.size() > 1;
  std::vector<Vec3List> polys(Loops.size()), finePolys(Loops.size());
  std::vector<std::vector<Box3>> partBoxes(Loops.size());
  for (size_t l = 0; l < Loops.size(); ++l)
  {
    double area = 0.0;
    for (int e : Loops[l].edges)
    {
      area += areaContribution(Edges[e].curve);
      if (!nested)
        continue;
      for (const BezierCurve& part : flattenParts(Edges[e].curve, 1e-3 * Diagonal))
      {
        polys[l].push_back(part.startPoint());
        partBoxes[l].push_back(part.boundingBox());
      }
    }
    Loops[l].signedArea = area;
  }
  auto inside = [&](size_t m, const Vec3& probe) {
    const bool close = std::any_of(partBoxes[m].begin(), partBoxes[m].end(), [&](const Box3& b) {
      return b.min().x() <= probe.x() && probe.x() <= b.max().x() && b.min().y() <= probe.y() &&
        probe.y() <= b.max().y();
    });
    if (!close)
      return insidePolyline(polys[m], probe);
    if (finePolys[m].empty())
      for (int e : Loops[m].edges)
      {
        const Vec3List pts = flatten(Edges[e].curve, 1e-6 * Diagonal);
        finePolys[m].insert(finePolys[m].end(), pts.begin(), pts.end() - 1);
      }
    return insidePolyline(finePolys[m], probe);
  };
  for (size_t l = 0; l < Loops.size(); ++l)
  {
    const Vec3 probe = Edges[Loops[l].edges.front()].curve.startPoint();
    int depth = 0;
    double parentArea = std::numeric_limits<double>::infinity();
    for (size_t m = 0; m < Loops.size(); ++m)
    {
      if (m != l && inside(m, probe))
      {
        ++depth;
        if (std::abs(Loops[m].signedArea) < parentArea)
        {
          parentArea = std::abs(Loops[m].signedArea);
          Loops[l].parent = static_cast<int>(m);
        }
      }
    }
    Loop2D& loop = Loops[l];
    loop.outer = (depth % 2 == 0);
    if ((loop.outer && loop.signedArea < 0.0) || (!loop.outer && loop.signedArea > 0.0))
    {
      std::reverse(loop.edges.begin(), loop.edges.end());
      for (int e : loop.edges)
      {
        Edges[e].curve = Edges[e].curve.reversed();
        Edges[e].reversed = !Edges[e].reversed;
      }
      loop.signedArea = -loop.signedArea;
      loop.flipped = true;
    }
  }
}

void Boundary2D::checkIntersections() const
{
  std::vector<std::vector<const BezierCurve*>> chains(Loops.size());
  for (size_t l = 0; l < Loops.size(); ++l)
    for (int e : Loops[l].edges)
      chains[l].push_back(&Edges[e].curve);
  const CurveCrossing x = findCrossing(chains, 1e-6 * Diagonal);
  if (!x.found)
    return;
  const Edge2D& a = Edges[Loops[x.chainA].edges[x.curveA]];
  const Edge2D& b = Edges[Loops[x.chainB].edges[x.curveB]];
  const Vec3 at = userPoint(x.near);
  if (x.chainA == x.chainB)
  {
    fail("self-intersecting loop ", x.chainA, ": ", a.name(),
      (&a == &b ? " crosses itself" : " crosses " + b.name()), " near ", format(at));
  }
  fail("loops ", x.chainA, " and ", x.chainB, " intersect: ", a.name(), " crosses ", b.name(),
    " near ", format(at));
}

void Boundary2D::classifyVertices(const Options& options)
{
  for (const Loop2D& loop : Loops)
  {
    const size_t n = loop.edges.size();
    for (size_t k = 0; k < n; ++k)
    {
      Edge2D& in = Edges[loop.edges[k]];
      Edge2D& out = Edges[loop.edges[(k + 1) % n]];
      Vertex2D v;
      v.point = in.curve.endPoint();
      v.incoming = loop.edges[k];
      v.outgoing = loop.edges[(k + 1) % n];
      const Vec3 a = in.curve.endTangent(true), b = out.curve.endTangent(false);
      v.turningAngle = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
      if (std::abs(v.turningAngle) > M_PI - options.angularTolerance)
      {
        fail("cusp where ", in.name(), " meets ", out.name(), " at ",
          format(userPoint(v.point)),
          ": the tangents are opposite (interior angle 0 or 360 degrees)");
      }
      if (std::abs(v.turningAngle) <= options.angularTolerance)
      {
        v.kind = VertexKind::Smooth;
      }
      else
      {
        v.kind = v.turningAngle > 0.0 ? VertexKind::Convex : VertexKind::Reflex;
      }
      const int id = static_cast<int>(Vertices.size());
      in.endVertex = id;
      out.startVertex = id;
      Vertices.push_back(v);
    }
  }
}

int Boundary2D::holeCount() const
{
  return static_cast<int>(
    std::count_if(Loops.begin(), Loops.end(), [](const Loop2D& l) { return !l.outer; }));
}

int Boundary2D::countVertices(VertexKind kind) const
{
  return static_cast<int>(std::count_if(
    Vertices.begin(), Vertices.end(), [kind](const Vertex2D& v) { return v.kind == kind; }));
}

} // namespace exactmat

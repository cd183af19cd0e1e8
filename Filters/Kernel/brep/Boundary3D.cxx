#include "Boundary3D.h"

#include "brep/WindingNumber.h"
#include "common/Format.h"
#include "common/GaussLegendre.h"
#include "common/InputError.h"
#include "common/UnionFind.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <queue>

namespace exactmat
{

std::string Face3D::name() const
{
  std::string s = "face " + std::to_string(piece);
  if (entity >= 0 && entity != piece)
  {
    s += " (entity " + std::to_string(entity) + ")";
  }
  return s;
}

namespace
{

// Gauss–Legendre, 8 points on [0,1].
const double* const GX = GaussLegendre8X;
const double* const GW = GaussLegendre8W;

// The same surface with u and v exchanged: its normal Su×Sv is reversed.
BezierPatch transposed(const BezierPatch& p)
{
  const int P = p.degreeU(), Q = p.degreeV();
  Vec4List net(static_cast<size_t>(P + 1) * (Q + 1));
  for (int i = 0; i <= P; ++i)
  {
    for (int j = 0; j <= Q; ++j)
    {
      net[j * (P + 1) + i] = p.homogeneousPoint(i, j);
    }
  }
  return BezierPatch(Q, P, std::move(net));
}

// The same triangle with vertices V1 and V2 exchanged (reverses its orientation).
TriangleNet mirrored(const TriangleNet& t)
{
  TriangleNet m = t;
  for (int i = 0; i <= t.degree; ++i)
  {
    for (int j = 0; i + j <= t.degree; ++j)
    {
      m.points[TriangleNet::index(t.degree, j, i)] = t.at(i, j);
    }
  }
  return m;
}


// Merges points closer than tol; returns a representative id per point.
std::vector<int> mergePoints(const Vec3List& pts, double tol)
{
  const int n = static_cast<int>(pts.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return pts[a].x() < pts[b].x(); });
  UnionFind uf(n);
  for (int a = 0; a < n; ++a)
  {
    for (int c = a + 1; c < n && pts[order[c]].x() - pts[order[a]].x() <= tol; ++c)
    {
      if ((pts[order[c]] - pts[order[a]]).norm() <= tol)
      {
        uf.unite(order[a], order[c]);
      }
    }
  }
  std::vector<int> id(n);
  for (int i = 0; i < n; ++i)
  {
    id[i] = uf.find(i);
  }
  return id;
}
} // namespace

double enclosedVolume(const std::vector<BezierPatch>& patches)
{
  double v = 0.0;
  for (const BezierPatch& p : patches)
  {
    for (int a = 0; a < 8; ++a)
    {
      for (int b = 0; b < 8; ++b)
      {
        const SurfaceDerivatives d = p.derivatives(GX[a], GX[b]);
        v += GW[a] * GW[b] * d.point.dot(d.su.cross(d.sv)) / 3.0;
      }
    }
  }
  return v;
}

Boundary3D Boundary3D::build(const std::vector<PatchPiece>& pieces, const Options& options)
{
  if (pieces.empty())
  {
    fail("empty input: the boundary has no faces");
  }
  Boundary3D b;
  b.UserFrame = options.userFrame;
  Box3 all;
  for (size_t i = 0; i < pieces.size(); ++i)
  {
    Face3D f;
    f.piece = static_cast<int>(i);
    f.entity = pieces[i].entity;
    f.patch = pieces[i].patch;
    f.triangle = pieces[i].triangle;
    f.patch.toNurbs().validate(f.name());
    all.extend(f.patch.boundingBox());
    b.Faces.push_back(std::move(f));
  }
  b.Diagonal = all.diagonal().norm();
  for (const Face3D& f : b.Faces)
  {
    if (!(f.patch.boundingBox().diagonal().norm() > options.pointTolerance * b.Diagonal))
    {
      fail(f.name(), " is degenerate: all its control points coincide at ",
        format(f.patch.controlPoint(0, 0)));
    }
  }
  b.matchSides(options);
  b.orientFaces();
  b.matchSides(options); // side indices changed where faces were re-parameterised
  b.classify(options);
  return b;
}

void Boundary3D::matchSides(const Options& options)
{
  Edges.clear();
  const double tol = options.pointTolerance * Diagonal;
  struct Side
  {
    int face, side;
    BezierCurve curve;
  };
  std::vector<Side> sides;
  Vec3List ends;
  for (size_t f = 0; f < Faces.size(); ++f)
  {
    for (int s = 0; s < 4; ++s)
    {
      BezierCurve c = Faces[f].patch.side(s);
      if (c.boundingBox().diagonal().norm() <= tol)
      {
        continue; // collapsed side (triangle apex, pole of a revolved surface)
      }
      ends.push_back(c.startPoint());
      ends.push_back(c.endPoint());
      sides.push_back({ static_cast<int>(f), s, std::move(c) });
    }
  }
  const std::vector<int> vid = mergePoints(ends, tol);
  std::map<std::pair<int, int>, std::vector<int>> byEnds;
  for (size_t k = 0; k < sides.size(); ++k)
  {
    const int a = vid[2 * k], c = vid[2 * k + 1];
    byEnds[{ std::min(a, c), std::max(a, c) }].push_back(static_cast<int>(k));
  }
  auto describe = [&](const Side& s) {
    return "side " + std::to_string(s.side) + " of " + Faces[s.face].name() + " (from " +
      format(s.curve.startPoint()) + " to " + format(s.curve.endPoint()) + ")";
  };
  // Sides with the same end vertices are the same edge when they agree at inner points.
  const double samples[3] = { 0.25, 0.5, 0.75 };
  auto agree = [&](const Side& a, const Side& b, bool reversed) {
    for (double t : samples)
    {
      if ((a.curve.evaluate(t) - b.curve.evaluate(reversed ? 1.0 - t : t)).norm() > 100.0 * tol)
      {
        return false;
      }
    }
    return true;
  };
  std::vector<int> partner(sides.size(), -1);
  for (const auto& [key, group] : byEnds)
  {
    for (int k : group)
    {
      std::vector<int> matches;
      for (int m : group)
      {
        if (m != k && (agree(sides[k], sides[m], true) || agree(sides[k], sides[m], false)))
        {
          matches.push_back(m);
        }
      }
      if (matches.empty())
      {
        fail("open surface: ", describe(sides[k]), " has no neighbouring face");
      }
      if (matches.size() > 1)
      {
        fail("non-manifold edge: ", describe(sides[k]), " is shared by ", matches.size() + 1,
          " faces");
      }
      partner[k] = matches.front();
    }
  }
  for (size_t k = 0; k < sides.size(); ++k)
  {
    if (partner[k] < static_cast<int>(k))
    {
      continue;
    }
    const Side& a = sides[k];
    const Side& b = sides[partner[k]];
    Edge3D e;
    e.faceA = a.face;
    e.sideA = a.side;
    e.faceB = b.face;
    e.sideB = b.side;
    e.startVertex = vid[2 * k];
    e.endVertex = vid[2 * k + 1];
    Edges.push_back(e);
  }
  // Vertices: the merged end points actually used by edges, renumbered densely.
  std::map<int, int> dense;
  Vertices.clear();
  for (size_t e = 0; e < Edges.size(); ++e)
  {
    for (int* v : { &Edges[e].startVertex, &Edges[e].endVertex })
    {
      auto [it, inserted] = dense.emplace(*v, static_cast<int>(Vertices.size()));
      if (inserted)
      {
        Vertex3D vx;
        vx.point = ends[*v];
        Vertices.push_back(vx);
      }
      *v = it->second;
      Vertices[it->second].edges.push_back(static_cast<int>(e));
    }
  }
}

void Boundary3D::orientFaces()
{
  const int n = static_cast<int>(Faces.size());
  // Two faces agree when they run along their shared edge in opposite directions.
  struct Link
  {
    int other;
    bool sameDirection;
  };
  std::vector<std::vector<Link>> links(n);
  for (const Edge3D& e : Edges)
  {
    const BezierCurve a = Faces[e.faceA].patch.side(e.sideA);
    const BezierCurve b = Faces[e.faceB].patch.side(e.sideB);
    const bool same = (a.startPoint() - b.startPoint()).norm() <
      (a.startPoint() - b.endPoint()).norm();
    links[e.faceA].push_back({ e.faceB, same });
    links[e.faceB].push_back({ e.faceA, same });
  }
  std::vector<int> sign(n, 0);
  std::vector<std::vector<int>> shells;
  for (int seed = 0; seed < n; ++seed)
  {
    if (sign[seed] != 0)
    {
      continue;
    }
    std::vector<int> component;
    std::queue<int> queue;
    sign[seed] = 1;
    queue.push(seed);
    while (!queue.empty())
    {
      const int f = queue.front();
      queue.pop();
      component.push_back(f);
      for (const Link& l : links[f])
      {
        const int want = l.sameDirection ? -sign[f] : sign[f];
        if (sign[l.other] == 0)
        {
          sign[l.other] = want;
          queue.push(l.other);
        }
        else if (sign[l.other] != want)
        {
          fail(Faces[f].name(), " and ", Faces[l.other].name(),
            " cannot be oriented consistently across their shared edge (the surface is not "
            "orientable)");
        }
      }
    }
    // Outward normals enclose a positive volume; otherwise flip the whole shell.
    std::vector<BezierPatch> oriented;
    for (int f : component)
    {
      oriented.push_back(sign[f] > 0 ? Faces[f].patch : transposed(Faces[f].patch));
    }
    if (enclosedVolume(oriented) < 0.0)
    {
      for (int f : component)
      {
        sign[f] = -sign[f];
      }
    }
    shells.push_back(std::move(component));
  }
  turnCavitiesInwards(shells, sign);
  std::vector<BezierPatch> all;
  for (int f = 0; f < n; ++f)
  {
    Face3D& face = Faces[f];
    if (sign[f] < 0)
    {
      face.flipped = true;
      if (face.triangle)
      {
        face.triangle = mirrored(*face.triangle);
        face.patch = BezierPatch::fromTriangle(*face.triangle);
      }
      else
      {
        face.patch = transposed(face.patch);
      }
    }
    all.push_back(face.patch);
  }
  Volume = enclosedVolume(all);
}

void Boundary3D::turnCavitiesInwards(const std::vector<std::vector<int>>& shells, std::vector<int>& sign) const
{
  if (shells.size() < 2)
  {
    return;
  }
  // Every shell now has outward normals. A shell inside an odd number of others bounds a
  // cavity (or an island in a cavity's cavity is even again): the material lies outside it,
  // so its normals must point into it.
  std::vector<std::vector<BezierPatch>> outward(shells.size());
  std::vector<Box3> boxes(shells.size());
  for (size_t s = 0; s < shells.size(); ++s)
  {
    boxes[s].setEmpty();
    for (int f : shells[s])
    {
      outward[s].push_back(sign[f] > 0 ? Faces[f].patch : transposed(Faces[f].patch));
      boxes[s].extend(Faces[f].patch.boundingBox());
    }
  }
  for (size_t a = 0; a < shells.size(); ++a)
  {
    // Where shell a lies, asked at the middles of up to eight of its faces spread over it:
    // disjoint shells give every sample the same answer, and a shell inside another lies in
    // its box. (A crossing that no sample sees goes unnoticed: the data contract's shells
    // are disjoint; this catches the usual mistakes, not every one.)
    const size_t step = std::max<size_t>(1, shells[a].size() / 8);
    const Face3D& face = Faces[shells[a].front()];
    int depth = 0;
    for (size_t b = 0; b < shells.size(); ++b)
    {
      if (b == a || !boxes[b].intersects(boxes[a]))
      {
        continue;
      }
      const std::string crossing = face.name() + "'s shell touches or crosses the shell of " +
        Faces[shells[b].front()].name() + " (the shells of a solid must be disjoint)";
      int inside = -1;
      for (size_t k = 0; k < shells[a].size(); k += step)
      {
        const Vec3 p = Faces[shells[a][k]].patch.evaluate(0.5, 0.5);
        const double w = boxes[b].contains(p) ? windingNumber(outward[b], p) : 0.0;
        const int here = static_cast<int>(std::round(w));
        if (!(std::abs(w - here) < 0.25) || here < 0 || here > 1 || (inside >= 0 && here != inside))
        {
          fail(crossing);
        }
        inside = here;
      }
      if (inside == 1 && !boxes[b].contains(boxes[a]))
      {
        fail(crossing);
      }
      depth += inside;
    }
    if (depth % 2 == 1)
    {
      for (int f : shells[a])
      {
        sign[f] = -sign[f];
      }
    }
  }
}

void Boundary3D::classify(const Options& options)
{
  for (Edge3D& e : Edges)
  {
    const BezierPatch& a = Faces[e.faceA].patch;
    const BezierPatch& b = Faces[e.faceB].patch;
    const double t = 0.5;
    const Vec2 pa = BezierPatch::sideParameter(e.sideA, t);
    const Vec2 pb = BezierPatch::sideParameter(e.sideB, 1.0 - t);
    const Vec3 na = a.normal(pa.x(), pa.y());
    const Vec3 nb = b.normal(pb.x(), pb.y());
    const Vec3 tangent = a.side(e.sideA).derivatives(t).tangent();
    // Into face B, perpendicular to the edge: B runs along the edge backwards, and its
    // interior lies to the left of its boundary seen from outside: n × (−T).
    const Vec3 intoB = nb.cross(-tangent);
    e.dihedralAngle = std::acos(std::max(-1.0, std::min(1.0, na.dot(nb))));
    if (e.dihedralAngle <= options.angularTolerance)
    {
      e.kind = VertexKind::Smooth;
    }
    else
    {
      e.kind = na.dot(intoB) < 0.0 ? VertexKind::Convex : VertexKind::Reflex;
    }
  }
  for (Vertex3D& v : Vertices)
  {
    bool reflex = false, convex = false;
    for (int e : v.edges)
    {
      reflex = reflex || Edges[e].kind == VertexKind::Reflex;
      convex = convex || Edges[e].kind == VertexKind::Convex;
    }
    v.kind = reflex ? VertexKind::Reflex : (convex ? VertexKind::Convex : VertexKind::Smooth);
  }
}

int Boundary3D::countEdges(VertexKind kind) const
{
  return static_cast<int>(
    std::count_if(Edges.begin(), Edges.end(), [kind](const Edge3D& e) { return e.kind == kind; }));
}

int Boundary3D::countVertices(VertexKind kind) const
{
  return static_cast<int>(std::count_if(
    Vertices.begin(), Vertices.end(), [kind](const Vertex3D& v) { return v.kind == kind; }));
}

} // namespace exactmat

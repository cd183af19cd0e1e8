#include "MAT3D.h"

#include "common/Format.h"
#include "common/InputError.h"
#include "geometry/BoundingVolumeHierarchy.h"
#include "geometry/ClosestPoint.h"
#include "mat3d/BoundarySphere.h"
#include "mat3d/CentreCurve.h"
#include "mat3d/Rim.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <limits>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace exactmat
{

namespace
{
// The work (boxes searched) a restart on a solid with curved faces may spend: a short
// cylinder's and a plate's successful restarts need 20 000 - 40 000; one that cannot
// succeed (an extruded blob, whose seams start at fin points) overshoots this by up to
// twice while the step that crossed it finishes. (1 000 000 until 2026-11-28: 9 s of
// failing restarts on the extruded blob, 160 s under the sanitizers.)
constexpr std::uint64_t RestartWorkBudget = 250000;
constexpr int MaxRestartSearchBoxes = 20000;

using Triplet = std::array<int, 3>;

Triplet sorted(Triplet t)
{
  std::sort(t.begin(), t.end());
  return t;
}

class Tracer
{
public:
  Tracer(const Boundary3D& boundary, const MAT3DOptions& options)
    : B(boundary)
    , Options(options)
    , Size(boundary.diagonal())
    , System(Generators)
  {
    Generators = medialGenerators(B);
    EdgeGenerator.assign(B.edges().size(), -1);
    CornerGenerator.assign(B.vertices().size(), -1);
    for (int g = 0; g < static_cast<int>(Generators.size()); ++g)
      if (Generators[g].kind() == GeneratorKind3D::ReflexEdge)
        EdgeGenerator[Generators[g].entity()] = g;
      else if (Generators[g].kind() == GeneratorKind3D::ReflexCorner)
        CornerGenerator[Generators[g].entity()] = g;
    FaceReflexEntities.resize(B.faces().size());
    for (int g = static_cast<int>(B.faces().size()); g < static_cast<int>(Generators.size()); ++g)
      for (int f : Generators[g].faces())
        FaceReflexEntities[f].push_back(g);
    std::vector<Box3> boxes;
    for (const Face3D& f : B.faces())
      boxes.push_back(f.patch.boundingBox());
    Tree.build(boxes);
    for (int e = 0; e < static_cast<int>(B.edges().size()); ++e)
    {
      const Edge3D& edge = B.edges()[e];
      SideEdge[{ edge.faceA, edge.sideA }] = e;
      SideEdge[{ edge.faceB, edge.sideB }] = e;
    }
    Solve = 1e-13 * Size;
    // Five or more faces touch one ball only as far as the input is exact (a cube moved far
    // from the origin is a cluster of junctions 1e-10 apart): their least-squares ball is
    // accepted to the input's rounding.
    Degenerate = std::max(1e-13, 64.0 * boundary.userFrame().inputRounding()) * Size;
    Margin = 1e-10 * Size;
    // A touch this close outside its entity is on it: the input's rounding (a grid of squares
    // far from the origin has a seam's touch running along a smooth edge; it must not cross
    // back and forth).
    OnEntity = std::max(Solve, Degenerate);
    NodeMerge = 1e-8 * Size;
  }

  MAT3D run();

private:
  bool hasEdgeOfKind(int vertex, VertexKind kind) const
  {
    for (int e : B.vertices()[vertex].edges)
      if (B.edges()[e].kind == kind)
        return true;
    return false;
  }
  bool attached(const MedialBall3D& ball, int face) const;
  int reflexEntityAt(int face, const Vec3& foot) const;
  std::vector<int> reflexEntitiesAt(int face, const Vec3& point, double near) const;
  int beyondVertex(int edge, int vertex) const;
  void crossOver(MedialBall3D& ball, int i, int side, const Vec3* motion = nullptr) const;
  bool merging(const MedialBall3D& ball, int& a, int& b) const;
  bool sameContact(const MedialBall3D& ball, const Vec3& a, const Vec3& b) const;
  int contactCount(const MedialBall3D& ball) const;
  std::vector<std::pair<Vec3, std::vector<int>>> contactGenerators(const MedialBall3D& ball) const;
  std::set<std::pair<int, int>> sheetPairs(const MAT3DSeam& seam, size_t b) const;
  std::set<std::pair<int, int>> stretchPairs(const MAT3DSeam& seam, size_t b) const;
  int sheetGenerator(const MedialBall3D& ball, const Vec3& point, int g, const Vec3& w) const;
  int cornerOrEdge(const MedialBall3D& ball, int i, const Vec3& w) const;
  bool onAnotherTouchFace(const MedialBall3D& ball, int i, int g) const;
  int seamEndAtVertex(const MedialBall3D& ball, int a, int b);
  // Distance from x to generator f (global closest point on its entity).
  double faceDistance(int f, const Vec3& x) const { return Generators[f].distance(x); }
  std::vector<int> facesOutside(const MedialBall3D& ball, double radius) const;
  bool empty(const MedialBall3D& ball) const;
  int reentering(const MedialBall3D& ball) const;
  int addNode(const MedialBall3D& ball, int vertex, double merge = 0.0);
  int findNode(const Vec3& x, double merge = 0.0) const;
  void startFrom(int node);
  void addRims();
  void addCentreCurves();
  bool addSphereCentre();
  void prepare(FaceCurveSearch& search) const;
  bool emptyOfAll(const Vec3& x, double r) const { return enteringFace(x, r) < 0; }
  int enteringFace(const Vec3& x, double r) const;
  int smoothNeighbour(int face, int side) const;
  MedialBall3D grownBall(int g, const Vec3& point, const Vec3& normal) const;
  std::vector<int> othersTouching(const MedialBall3D& ball) const;
  static double distanceToSeam(const MAT3DSeam& seam, const Vec3& x);
  bool onTracedSeam(const MedialBall3D& ball) const;
  bool restartFrom(int face);
  bool outgoing(int index, const Triplet& t, MedialBall3D& ball, Eigen::VectorXd& tangent, int& touchpoints) const;
  void trace(int startNode, MedialBall3D ball, Eigen::VectorXd tangent, int touchpoints);
  bool step(const MedialBall3D& from, const Eigen::VectorXd& t, double h, MedialBall3D& to) const;
  MedialBall3D junction(const MedialBall3D& before, const Eigen::VectorXd& t, double h, bool& tangential) const;
  void polishJunction(MedialBall3D& j, double reach = 0.0) const;
  void appendTouching(MedialBall3D& j, double tangency = 1e-8) const;
  bool kiss(const MedialBall3D& from, const Eigen::VectorXd& t, double h, const MedialBall3D& to, MedialBall3D& at) const;
  std::string describe(const MedialBall3D& ball) const;
  void reportProgress();
  void collectSheets();
  /// A seam leaving or reaching a node: its direction away from the node and the points
  /// where its triplet touches at the node (empty for a degenerate seam, which any triplet
  /// leaving in its direction belongs to).
  struct Departure
  {
    Vec3 direction = Vec3::Zero();
    Vec3List contacts;
  };
  void depart(int node, const Vec3& direction, const MedialBall3D& triplet, int touchpoints);
  bool departed(int node, const Vec3& direction, const MedialBall3D& triplet, int touchpoints) const;

  const Boundary3D& B;
  MAT3DOptions Options;
  double Size;
  std::vector<Generator3D> Generators;
  BallSystem System;
  BoundingVolumeHierarchy Tree;
  std::map<std::pair<int, int>, int> SideEdge;
  std::vector<int> EdgeGenerator, CornerGenerator; // by edge / vertex, −1 where none
  std::vector<std::vector<int>> FaceReflexEntities; // by face: its reflex edges and corners, ascending
  double Solve = 0.0, Degenerate = 0.0, Margin = 0.0, NodeMerge = 0.0, OnEntity = 0.0;

  MAT3D Result;
  std::set<std::pair<int, Triplet>> Traced;
  std::map<int, std::vector<Departure>> Departures; // by node
  std::vector<bool> Reached; // faces some seam has touched (for progress)
  int ReachedCount = 0;
  std::vector<int> Queue;
  int RestartNode = -1;     // the seam point a restart traces from (not a node of the MAT)
  std::uint64_t RestartWorkLimit = 0; // patchSearchWork() at which a restart gives up (0: none)
  std::set<int> Spliced;    // restart points whose two seams became one
};

std::string Tracer::describe(const MedialBall3D& ball) const
{
  // "the ball at (x, y, z) of radius r touching face 0, face 2 and face 4"
  std::ostringstream s;
  s << "the ball at " << format(B.userPoint(ball.x)) << " of radius " << B.userFrame().lengthToUser(ball.r) << " touching ";
  for (int i = 0; i < ball.size(); ++i)
    s << (i == 0 ? "" : i + 1 == ball.size() ? " and " : ", ") << Generators[ball.generators[i]].name();
  return s.str();
}

// A face the ball touches through one of its generators (the generator itself, a face at
// a reflex edge or corner it touches): it passes through a touchpoint, outside the ball.
bool Tracer::attached(const MedialBall3D& ball, int face) const
{
  for (int g : ball.generators)
  {
    const std::vector<int>& faces = Generators[g].faces();
    if (std::find(faces.begin(), faces.end(), face) != faces.end())
      return true;
  }
  return false;
}

std::vector<int> Tracer::facesOutside(const MedialBall3D& ball, double radius) const
{
  std::vector<int> out;
  for (int f : Tree.candidatesWithin(ball.x, radius))
    if (!attached(ball, f))
      out.push_back(f);
  return out;
}

// The reflex edges and corners of `face` within `near` of `point` (a point on the face's
// border), in generator order.
std::vector<int> Tracer::reflexEntitiesAt(int face, const Vec3& point, double near) const
{
  std::vector<int> out;
  for (int g : FaceReflexEntities[face])
    if (Generators[g].distance(point) <= near)
      out.push_back(g);
  return out;
}

// The reflex corner or edge generator at `foot`, a point on the border of `face`, or −1.
int Tracer::reflexEntityAt(int face, const Vec3& foot) const
{
  const std::vector<int> at = reflexEntitiesAt(face, foot, 1e-9 * Size);
  for (int g : at)
    if (Generators[g].kind() == GeneratorKind3D::ReflexCorner)
      return g; // a corner before the edges that end at it
  return at.empty() ? -1 : at.back();
}

// The generator after reflex edge `edge` past its end `vertex`: the corner there, or the
// reflex edge continuing it (a curved edge split between patches), or −1.
int Tracer::beyondVertex(int edge, int vertex) const
{
  if (CornerGenerator[vertex] >= 0)
    return CornerGenerator[vertex];
  const Generator3D& from = Generators[EdgeGenerator[edge]];
  const Vec3 here = from.evaluate(Vec2(B.edges()[edge].startVertex == vertex ? 0.0 : 1.0, 0.0)).point;
  for (int e : B.vertices()[vertex].edges)
  {
    if (e == edge || EdgeGenerator[e] < 0)
      continue;
    // Continuing: the two edges' directions at the vertex are opposite.
    const Generator3D& to = Generators[EdgeGenerator[e]];
    const double t = B.edges()[e].startVertex == vertex ? 0.0 : 1.0;
    const Vec3 a = from.evaluate(Vec2(B.edges()[edge].startVertex == vertex ? 0.0 : 1.0, 0.0)).dPoint.col(0);
    const Vec3 b = to.evaluate(Vec2(t, 0.0)).dPoint.col(0);
    if ((to.evaluate(Vec2(t, 0.0)).point - here).norm() <= 1e-9 * Size && std::abs(a.normalized().dot(b.normalized())) > 1.0 - 1e-9)
      return EdgeGenerator[e];
  }
  return -1;
}

// Whether the ball touches the boundary at a and b in one contact: they coincide, or the
// boundary between them stays on the sphere (the valley between them does not leave the
// ball: a coplanar neighbour's foot a hair from a touchpoint), as the verification decides.
bool Tracer::sameContact(const MedialBall3D& ball, const Vec3& a, const Vec3& b) const
{
  const double gap = (a - b).norm();
  if (gap <= 1e-7 * ball.r)
    return true;
  if (gap > 0.2 * ball.r)
    return false;
  const Vec3 m = 0.5 * (a + b);
  Vec3 foot = a;
  double best = Unbounded;
  for (int f : Tree.candidatesWithin(m, 0.5 * gap))
  {
    const Vec3 p = Generators[f].nearestPoint(m);
    if ((p - m).norm() < best)
    {
      best = (p - m).norm();
      foot = p;
    }
  }
  return (foot - ball.x).norm() <= ball.r + Degenerate;
}

// The distinct points where the ball touches the boundary: its generators' touches and the
// feet of every face at distance r (to Degenerate).
int Tracer::contactCount(const MedialBall3D& ball) const
{
  Vec3List points;
  for (int i = 0; i < ball.size(); ++i)
    points.push_back(Generators[ball.generators[i]].evaluate(ball.q[i]).point);
  for (int f : Tree.candidatesWithin(ball.x, ball.r + Degenerate))
  {
    // (A generator's own touch is counted; a curved face is searched only when the cheap
    // Bernstein test says it comes that close.)
    if (std::find(ball.generators.begin(), ball.generators.end(), f) != ball.generators.end())
      continue;
    if (!Generators[f].polygon() && !patchComesWithin(B.faces()[f].patch, ball.x, ball.r + Degenerate))
      continue;
    const Vec3 foot = Generators[f].nearestPoint(ball.x);
    if ((foot - ball.x).norm() > ball.r + Degenerate)
      continue;
    bool seen = false;
    for (const Vec3& p : points)
      seen = seen || sameContact(ball, p, foot);
    if (!seen)
    {
#ifdef EXACTMAT_TRACE3D_DEBUG
      std::fprintf(stderr, "   contact of face %d at (%.9g %.9g %.9g), d-r %.3g\n", f, foot.x(), foot.y(), foot.z(), (foot - ball.x).norm() - ball.r);
#endif
      points.push_back(foot);
    }
  }
  return static_cast<int>(points.size());
}

// Two of the ball's touchpoints at one point (a and b: their indices in the ball): to the
// input's rounding (a solid far from the origin has its two reflex edges' touches reach their
// common corner a rounding apart), and a small fraction of the radius.
bool Tracer::merging(const MedialBall3D& ball, int& a, int& b) const
{
  const double same = std::min(std::max(1e-9 * Size, 1e3 * Degenerate), 1e-3 * ball.r);
  for (int i = 0; i < ball.size(); ++i)
    for (int j = i + 1; j < ball.size(); ++j)
      if ((Generators[ball.generators[i]].evaluate(ball.q[i]).point -
            Generators[ball.generators[j]].evaluate(ball.q[j]).point)
            .norm() <= same)
      {
        a = i;
        b = j;
        return true;
      }
  return false;
}

// The seam through `ball` ends where touches a and b merged. At a vertex of the solid the
// sheet between them closes along a straight rim, the balls touching the vertex only
// (centre = vertex + s·normal, radius s): added from the new seam end down to the vertex.
int Tracer::seamEndAtVertex(const MedialBall3D& ball, int a, int b)
{
  const Vec3 p = Generators[ball.generators[a]].evaluate(ball.q[a]).point;
  // The nearest vertex, if near: two touches meeting tangentially are located only to about
  // the square root of the rounding (1e-8 of the size), so the margin is a hundred times that.
  int vertex = -1;
  double nearest = 1e-6 * Size;
  for (int v = 0; v < static_cast<int>(B.vertices().size()); ++v)
    if ((B.vertices()[v].point - p).norm() <= nearest)
    {
      nearest = (B.vertices()[v].point - p).norm();
      vertex = v;
    }
#ifdef EXACTMAT_TRACE3D_DEBUG
  for (int v = 0; v < static_cast<int>(B.vertices().size()); ++v)
    if ((B.vertices()[v].point - p).norm() <= 1e-3 * Size)
      std::fprintf(stderr, "   merge %d/%d: vertex %d at %.3g of the size\n", a, b, v, (B.vertices()[v].point - p).norm() / Size);
#endif
  if (vertex < 0)
    fail("3D MAT: two touchpoints of ", describe(ball), " merge at ", format(B.userPoint(p)),
      ", not at a vertex: skeletal edges of curved faces are not supported yet");
  const int existing = findNode(ball.x);
  const int node = addNode(ball, -1);
  if (existing >= 0)
    return node; // its rim is there already (or a junction is)
  Result.nodes[node].seamEnd = true;
  // The vertex's node (radius 0, every face there).
  MedialBall3D corner;
  for (int e : B.vertices()[vertex].edges)
    for (int f : { B.edges()[e].faceA, B.edges()[e].faceB })
      if (std::find(corner.generators.begin(), corner.generators.end(), f) == corner.generators.end())
      {
        corner.generators.push_back(f);
        corner.q.push_back(Generators[f].parameterOf(B.vertices()[vertex].point));
      }
  corner.x = B.vertices()[vertex].point;
  const int end = addNode(corner, vertex);
  MAT3DSkeletalEdge rim;
  rim.startNode = node;
  rim.endNode = end;
  rim.vertex = vertex;
  rim.generators = { ball.generators[a], ball.generators[b] };
  const Vec3 normal = (ball.x - p) / ball.r;
  const int pieces = std::max(1, static_cast<int>(std::ceil(ball.r / (Options.maxStep * Size))));
  for (int k = 0; k <= pieces; ++k)
  {
    MedialBall3D m;
    m.r = ball.r * (1.0 - static_cast<double>(k) / pieces);
    m.x = k == pieces ? corner.x : Vec3(p + m.r * normal);
    if (k > 0 && k < pieces)
      for (int f : facesOutside(m, m.r))
        if (faceDistance(f, m.x) < m.r - 1e-9 * Size)
          fail("3D MAT: the rim from ", describe(ball), " to the vertex at ", format(B.userPoint(p)), " enters ",
            Generators[f].name(), ": not medial");
    rim.balls.push_back(m);
  }
  Result.skeletalEdges.push_back(std::move(rim));
  return node;
}

// Whether entity g lies on a face that a touch of the ball other than touch i lies on: that
// touch is there already, so g cannot take over touch i (a crossing's candidate).
bool Tracer::onAnotherTouchFace(const MedialBall3D& ball, int i, int g) const
{
  for (int k = 0; k < ball.size(); ++k)
    if (k != i)
      for (int f : Generators[g].faces())
      {
        const std::vector<int>& faces = Generators[ball.generators[k]].faces();
        if (std::find(faces.begin(), faces.end(), f) != faces.end())
          return true;
      }
  return false;
}

// Touch i of the ball has left its entity through `side` (Generator3D::exitSide): it goes
// on to the entity beyond — the neighbour face across a smooth edge, the reflex edge at a
// face's side, the face at either end of a reflex edge's normal arc, the corner (or the
// continuing edge) at its end, the edge whose arc bounds a corner's cone.
void Tracer::crossOver(MedialBall3D& ball, int i, int side, const Vec3* motion) const
{
  const int g = ball.generators[i];
  const Generator3D& from = Generators[g];
  const Vec3 p = from.evaluate(ball.q[i]).point;
  int next = -1;
  if (from.kind() == GeneratorKind3D::Face)
  {
    const auto e = SideEdge.find({ g, side });
    if (e == SideEdge.end())
      fail("3D MAT: the seam through ", describe(ball), " left ", from.name(), " through side ", side,
        ", which no edge was matched to");
    const Edge3D& edge = B.edges()[e->second];
    if (edge.kind == VertexKind::Convex)
      fail("3D MAT: the seam through ", describe(ball), " reached the convex edge between ",
        B.faces()[edge.faceA].name(), " and ", B.faces()[edge.faceB].name(), " with a ball of radius > 0");
    next = edge.kind == VertexKind::Smooth ? (edge.faceA == g ? edge.faceB : edge.faceA) : EdgeGenerator[e->second];
  }
  else if (from.kind() == GeneratorKind3D::ReflexEdge)
  {
    const Edge3D& edge = B.edges()[from.entity()];
    if (side < 2)
      next = side == 0 ? edge.faceA : edge.faceB;
    else
    {
      const int vertex = side == 2 ? edge.startVertex : edge.endVertex;
      next = beyondVertex(from.entity(), vertex);
      // Reaching the vertex with the normal at an end of the arc (a corner where convex
      // edges meet the reflex one: the ball lies under one face): continue on that face,
      // at its corner.
      const double theta = ball.q[i].y(), alpha = from.edgeAngle(ball.q[i].x());
#ifdef EXACTMAT_TRACE3D_DEBUG
      std::fprintf(stderr, "edge end: theta %.9g alpha %.9g t %.9g\n", theta, alpha, ball.q[i].x());
#endif
      if (next < 0 && std::min(std::abs(theta), std::abs(theta - alpha)) <= 1e-5)
        next = std::abs(theta) <= std::abs(theta - alpha) ? edge.faceA : edge.faceB;
      // Else, knowing where the seam goes: the entity at the vertex nearest the ball moved
      // on that touches it along its normal (another reflex edge turning the corner, a face
      // beside it), unless it lies on a face another touch of the ball is on.
      if (next < 0 && motion)
      {
        const int nearest = sheetGenerator(ball, p, g, *motion);
        if (nearest != g && !onAnotherTouchFace(ball, i, nearest))
          next = nearest;
      }
      if (next < 0)
        fail("3D MAT: the seam through ", describe(ball), " reached the end of ", from.name(), " at ",
          format(B.userPoint(B.vertices()[vertex].point)),
          ", a corner with convex and reflex edges (or reflex ones without a normal cone): not supported yet");
    }
  }
  else
  {
    next = EdgeGenerator[from.cornerEdges()[side]];
  }
  ball.generators[i] = next;
  ball.q[i] = Generators[next].touchParameter(p, ball.x);
}

// The ball is empty of every face outside its generators (those touch it by construction;
// a planar or convex generator cannot also enter it — the curvature criterion for curved
// faces that fold back is not applied yet).
bool Tracer::empty(const MedialBall3D& ball) const
{
  const double radius = ball.r - Margin;
  if (radius <= 0.0)
    return true;
  Vec3List touches; // (evaluated when a curved face needs them)
  for (int f : facesOutside(ball, radius))
  {
    if (Generators[f].polygon())
    {
      if (Generators[f].distance(ball.x) < radius)
        return false;
      continue;
    }
    // A curved piece near a touchpoint (a surface split into pieces along the seam: the
    // sides of a revolved profile, cut where its MAT samples touch) is tangent, or nearly,
    // to the ball there: against the full radius its Bernstein test subdivides down to the
    // margin around that point. Decided against a ball smaller by 1e-6 of the radius, as the
    // touched faces themselves are (reentering): a face entering less deeply is caught at a
    // later step if it goes on, by the verification if it leaves again.
    if (touches.empty())
      for (int i = 0; i < ball.size(); ++i)
        touches.push_back(Generators[ball.generators[i]].evaluate(ball.q[i]).point);
    bool nearTouch = false;
    const Box3 box = B.faces()[f].patch.boundingBox();
    for (const Vec3& p : touches)
      nearTouch = nearTouch || distanceToBox(box, p) <= 0.05 * ball.r;
    if (patchComesWithin(B.faces()[f].patch, ball.x, nearTouch ? ball.r * (1.0 - 1e-6) - Margin : radius))
      return false;
  }
  return true;
}

// A curved face of the triplet that enters the ball (it touches the ball a second time, or
// curves into it: the thesis' curvature criterion). Planar faces cannot. The test ball is
// smaller by 1e-4·r so the tangency at the face's own touchpoint is decided quickly.
int Tracer::reentering(const MedialBall3D& ball) const
{
  const double radius = ball.r * (1.0 - 1e-4) - Margin;
  if (radius <= 0.0)
    return -1;
  for (int g : ball.generators)
    for (int f : Generators[g].faces())
      if (!Generators[f].planar() && patchComesWithin(B.faces()[f].patch, ball.x, radius))
        return f;
  return -1;
}

int Tracer::findNode(const Vec3& x, double merge) const
{
  // The nearest node within the merge distance (NodeMerge unless a caller knows its ball is
  // located less precisely).
  const double within = std::max(merge, NodeMerge);
  int best = -1;
  double nearest = Unbounded;
  for (size_t n = 0; n < Result.nodes.size(); ++n)
  {
    if (static_cast<int>(n) == RestartNode || Spliced.count(static_cast<int>(n)))
      continue;
    const double d = (Result.nodes[n].ball.x - x).norm();
    if (d <= (Result.nodes[n].imprecise ? std::max(within, 1e-5 * Size) : within) && d < nearest)
    {
      nearest = d;
      best = static_cast<int>(n);
    }
  }
  return best;
}

int Tracer::addNode(const MedialBall3D& ball, int vertex, double merge)
{
  const int found = findNode(ball.x, merge);
  if (found >= 0)
  {
    // The same junction reached again: keep every face either arrival saw (and, where the
    // node was located imprecisely, the precisely polished ball of this arrival).
    MAT3DNode& node = Result.nodes[found];
    MedialBall3D& b = node.ball;
    if (node.imprecise && merge <= 0.0 && vertex < 0)
    {
      MedialBall3D precise = ball;
      for (int i = 0; i < b.size(); ++i)
        if (std::find(precise.generators.begin(), precise.generators.end(), b.generators[i]) == precise.generators.end())
        {
          precise.generators.push_back(b.generators[i]);
          precise.q.push_back(Generators[b.generators[i]].parameterOf(Generators[b.generators[i]].nearestPoint(ball.x)));
        }
      b = precise;
      node.imprecise = false;
      return found;
    }
    for (int i = 0; i < ball.size(); ++i)
      if (std::find(b.generators.begin(), b.generators.end(), ball.generators[i]) == b.generators.end())
      {
        b.generators.push_back(ball.generators[i]);
        b.q.push_back(ball.q[i]);
      }
    return found;
  }
  MAT3DNode node;
  node.ball = ball;
  node.vertex = vertex;
  Result.nodes.push_back(std::move(node));
  Queue.push_back(static_cast<int>(Result.nodes.size()) - 1);
  return static_cast<int>(Result.nodes.size()) - 1;
}

bool Tracer::step(const MedialBall3D& from, const Eigen::VectorXd& t, double h, MedialBall3D& to) const
{
  to = from;
  const Eigen::VectorXd anchor = from.pack() + h * t;
  to.unpack(anchor);
  return System.correct(to, Solve, &t, &anchor);
}

// The seam of triplet t leaves the node along ±(null vector) when every other face of the
// node recedes from the ball (first order: N_g·dX − dr > 0) and a short trial step keeps
// the touchpoints on their faces and the ball clear of the node's other faces.
bool Tracer::outgoing(int index, const Triplet& t, MedialBall3D& ball, Eigen::VectorXd& tangent, int& touchpoints) const
{
  const MAT3DNode& node = Result.nodes[index];
  const MedialBall3D& nb = node.ball;
  ball = MedialBall3D();
  for (int g : t)
  {
    const auto it = std::find(nb.generators.begin(), nb.generators.end(), g);
    ball.generators.push_back(g);
    ball.q.push_back(nb.q[it - nb.generators.begin()]);
  }
  ball.x = nb.x;
  ball.r = nb.r;
  // First order, before the null vector: every touch's normal N_i satisfies N_i·dX = dr
  // along the seam, so the centre moves along ±(N_a − N_b) × (N_a − N_c); a triplet whose
  // both directions bring another generator of the node into the ball leaves nothing (most
  // triplets of a junction with many generators). Looser than the test below. A direction
  // already traced with the same touches (another piece of a coplanar face or an edge
  // touching where this triplet does) needs no null vector either.
  {
    Vec3 n[3];
    for (int i = 0; i < 3; ++i)
      n[i] = Generators[ball.generators[i]].evaluate(ball.q[i]).normal;
    const Vec3 d = (n[0] - n[1]).cross(n[0] - n[2]);
    if (d.norm() > 1e-6)
    {
      bool either = false;
      for (int sign = 1; sign >= -1 && !either; sign -= 2)
      {
        const Vec3 dx = sign * d.normalized();
        const double dr = n[0].dot(dx);
        if (node.vertex >= 0 && !(dr > 1e-9))
          continue;
        double worst = 1.0;
        for (int i = 0; i < nb.size(); ++i)
          if (std::find(t.begin(), t.end(), nb.generators[i]) == t.end())
            worst = std::min(worst, Generators[nb.generators[i]].evaluate(nb.q[i]).normal.dot(dx) - dr);
        either = worst >= -1e-6 && !departed(index, dx, ball, 3);
      }
      if (!either)
        return false;
    }
  }
  double separation = 1.0;
  const Eigen::VectorXd t0 = System.tangent(ball, &separation);
#ifdef EXACTMAT_TRACE3D_DEBUG
  std::fprintf(stderr, "outgoing? node r %.3g triplet %d %d %d separation %.3g\n", nb.r, t[0], t[1], t[2], separation);
#endif
  if (separation > 1e-6)
    return false; // no single seam of this triplet through the node
  const double trial = std::min(1e-4, 0.01 * Options.maxStep) * Size;
  for (int sign = 1; sign >= -1; sign -= 2)
  {
    const Eigen::VectorXd d = sign * t0;
    const Vec3 dx = d.segment<3>(6);
    const double dr = d(9);
    if (node.vertex >= 0 && !(dr > 1e-9))
      continue;
    double worst = 1.0;
    for (int i = 0; i < nb.size(); ++i)
    {
      const int g = nb.generators[i];
      if (std::find(t.begin(), t.end(), g) != t.end())
        continue;
      const Touch3D touch = Generators[g].evaluate(nb.q[i]);
      worst = std::min(worst, touch.normal.dot(dx) - dr);
    }
#ifdef EXACTMAT_TRACE3D_DEBUG
    std::fprintf(stderr, "   sign %d worst %.3g\n", sign, worst);
#endif
    if (worst < -1e-7)
      continue;
    // The trial step. A touch at the node on the border of its entity (a smooth edge
    // between coplanar pieces, a reflex edge's side or end) may leave it: the seam starts on
    // the entity beyond.
    MedialBall3D start = ball, next;
    Eigen::VectorXd direction = d;
    bool inside = false;
    // A seam shorter than the trial step (between two branch points of an extruded
    // profile's MAT 1e-5 of the size apart, its touches on side pieces as narrow) is crossed
    // past its end, its touches running over piece after piece of one surface: shorter
    // trials. (Only then: a triplet that does not leave a staircase's junction crosses grid
    // squares, each a face of its own, and a shorter trial there is only slower.)
    bool overPieces = true;
    for (int shorter = 0; shorter < 3 && !inside && overPieces; ++shorter)
    {
      start = ball;
      direction = d;
      overPieces = false;
      const double length = trial / std::pow(16.0, shorter);
      for (int attempt = 0; attempt < 4 && !inside; ++attempt)
      {
        if (!step(start, direction, length, next) || next.r < 0.0)
          break;
        int leaving = -1, side = -1;
        for (int i = 0; i < 3 && leaving < 0; ++i)
          if ((side = Generators[next.generators[i]].exitSide(next.q[i], OnEntity)) >= 0)
            leaving = i;
        inside = leaving < 0;
        if (inside)
          break;
        // A touch inside its entity at the node that leaves it within the trial step (a
        // cavity edge touched 6e-4 rad short of its wall's normal) runs on it first: the
        // seam starts on the node's triplet and is crossed, at the exact crossing, as it is
        // traced (swapped at the node, the wall's touch began off the wall and the sheet of
        // the two walls lost its side there). Only a touch on its entity's border at the
        // node starts on the entity beyond — and at a vertex, or within 1e-6 of the size of
        // the node (a moved solid's junctions are placed only to about the square root of
        // its rounding), the touch is taken to be on the border.
        if (attempt == 0 && node.vertex < 0)
        {
          double lo = 0.0, hi = length;
          MedialBall3D before = start;
          for (int k = 0; k < 60 && hi - lo > 1e-12 * Size; ++k)
          {
            const double mid = 0.5 * (lo + hi);
            MedialBall3D m;
            bool out = !step(start, direction, mid, m) || m.r < 0.0;
            for (int i = 0; i < 3 && !out; ++i)
              out = Generators[m.generators[i]].exitSide(m.q[i], OnEntity) >= 0;
            if (out)
              hi = mid;
            else
            {
              lo = mid;
              before = m;
            }
          }
          if (lo > 1e-6 * Size)
          {
            next = before;
            inside = true;
            break;
          }
        }
        MedialBall3D swapped = start;
        try
        {
          crossOver(swapped, leaving, side);
        }
        catch (const InputError&)
        {
          break; // nothing beyond (a convex edge): this triplet does not leave here
        }
        if (std::count(swapped.generators.begin(), swapped.generators.end(), swapped.generators[leaving]) > 1)
          break;
        const int from = start.generators[leaving], to = swapped.generators[leaving];
        overPieces = attempt == 3 && from < static_cast<int>(B.faces().size()) &&
          to < static_cast<int>(B.faces().size()) && B.faces()[from].entity >= 0 &&
          B.faces()[from].entity == B.faces()[to].entity;
        start = swapped;
        const Eigen::VectorXd n = System.tangent(start);
        direction = n.segment<4>(6).dot(d.segment<4>(6)) < 0.0 ? Eigen::VectorXd(-n) : n;
      }
    }
#ifdef EXACTMAT_TRACE3D_DEBUG
    std::fprintf(stderr, "   inside %d\n", (int)inside);
#endif
    if (!inside)
      continue;
    // Three distinct touchpoints: two coplanar faces touching at their common (smooth)
    // edge are one touchpoint, and such a triplet's solutions are a sheet's points.
    Vec3 touch[3];
    for (int i = 0; i < 3; ++i)
      touch[i] = Generators[next.generators[i]].evaluate(next.q[i]).point;
    const double same = 1e-6 * next.r;
    if ((touch[0] - touch[1]).norm() <= same || (touch[0] - touch[2]).norm() <= same ||
      (touch[1] - touch[2]).norm() <= same)
      continue;
    // The node's other generators stay outside the ball — but for those touching where a
    // triplet's touch is (the neighbour across the smooth edge a touch runs along: an
    // extruded profile's sides are split where its MAT's branch points touch), whose
    // distance is the ball's radius only to the solve's rounding.
    bool clear = true;
    for (int g : nb.generators)
    {
      if (std::find(t.begin(), t.end(), g) != t.end())
        continue;
      const Vec3 foot = Generators[g].nearestPoint(next.x);
      const bool atTouch = (foot - touch[0]).norm() <= same || (foot - touch[1]).norm() <= same ||
        (foot - touch[2]).norm() <= same;
      clear = clear && (atTouch || (foot - next.x).norm() >= next.r - Degenerate);
    }
    if (!clear)
      continue;
    // Generators that keep touching along the seam — where the triplet does (coplanar
    // faces), or elsewhere along a degenerate seam (the axis of an extruded star, touching
    // five reflex edges) — count as its touchpoints: the distinct feet of every face that
    // touches the trial ball.
    touchpoints = contactCount(next);
    ball = start;
    tangent = direction;
    return true;
  }
  return false;
}

// A junction between `before` (empty) and the step h along t (not empty): bisection on the
// step for the point where the nearest other face touches, then Newton on every face that
// touches there. `tangential`: the fourth face came in tangentially (see below), and the
// junction is located only to about the square root of the rounding.
MedialBall3D Tracer::junction(const MedialBall3D& before, const Eigen::VectorXd& t, double h, bool& tangential) const
{
  tangential = false;
  MedialBall3D end;
  step(before, t, h, end);
  // Faces touching both `before` (empty) and `end` keep touching along a degenerate seam
  // (the extruded star's axis, five reflex edges): they bracket nothing. (A face touching
  // `before` and inside `end` is a junction right at `before`.)
  std::vector<int> others;
  for (int f : facesOutside(end, end.r + Margin))
    if (faceDistance(f, before.x) > before.r + Degenerate || faceDistance(f, end.x) < end.r - 1e-9 * Size)
      others.push_back(f);
  // A face touching where a generator does (a coplanar neighbour across a smooth edge the
  // touchpoint runs along) is no fourth touchpoint.
  auto gap = [&](const MedialBall3D& b) {
    Vec3List touches;
    for (int i = 0; i < b.size(); ++i)
      touches.push_back(Generators[b.generators[i]].evaluate(b.q[i]).point);
    double d = Unbounded;
    for (int f : others)
    {
      // A face in a generator's plane touches where the generator does, if at all.
      bool inPlane = false;
      for (int g : b.generators)
        inPlane = inPlane || Generators[g].coplanar(Generators[f], Degenerate);
      if (inPlane)
        continue;
      const Vec3 foot = Generators[f].nearestPoint(b.x);
      bool distinct = true;
      for (const Vec3& p : touches)
        distinct = distinct && (foot - p).norm() > 1e-9 * Size;
      if (distinct)
        d = std::min(d, (foot - b.x).norm());
    }
    return d - b.r;
  };
  double lo = 0.0, hi = h;
  MedialBall3D at = before;
  for (int k = 0; k < 80 && hi - lo > 1e-15 * Size; ++k)
  {
    const double mid = 0.5 * (lo + hi);
    MedialBall3D m;
    if (!step(before, t, mid, m))
      fail("3D MAT: the seam through ", describe(before), " could not be continued while locating a junction");
    if (gap(m) > 0.0)
    {
      lo = mid;
      at = m;
    }
    else
      hi = mid;
  }
  MedialBall3D j = at;
  polishJunction(j);
  // A face whose distance to the seam's balls has a double root at the junction (it meets
  // the ball tangentially along the seam: a symmetric junction of eight faces on a revolved
  // rectangle far from the origin) is bracketed by the bisection only to about the square
  // root of the rounding of its gap, and its four-face system is singular there, so Newton
  // does not sharpen it: such a face joins from within 1e-6 of the size, and the junction
  // is known as loosely as a degenerate seam's end is.
  if (j.size() < 4)
  {
    j = at;
    polishJunction(j, 1e-6 * Size);
    tangential = j.size() >= 4 && (j.x - at.x).norm() <= 1e-5 * Size;
    if (!tangential)
      j = at;
  }
#ifdef EXACTMAT_TRACE3D_DEBUG
  std::fprintf(stderr, "junction from %s: %s (bisected at lo %.3g of h %.3g)\n", describe(before).c_str(), describe(j).c_str(), lo, h);
  for (int i = 0; i < j.size(); ++i)
    std::fprintf(stderr, "   gen %d: d-r %.3g\n", j.generators[i], faceDistance(j.generators[i], j.x) - j.r);
#endif
  if (j.size() < 4)
    fail("3D MAT: the seam through ", describe(before), " met a face that does not touch where it was located");
  return j;
}

// Every face within reach of j joins it (or the reflex edge or corner where it is touched);
// Newton on the k-generator system, repeated while another face turns out to touch the
// polished ball.
void Tracer::polishJunction(MedialBall3D& j, double reach) const
{
  // (Faces within `reach` of the ball join; by default those touching it to 1e-10 of the size.)
  reach = std::max(reach, 1e-10 * Size);
  for (int round = 0; round < 6; ++round)
  {
    bool added = false;
    for (int f : facesOutside(j, j.r + 1e-6 * Size))
    {
      const Vec3 foot = Generators[f].nearestPoint(j.x);
      const double footDistance = (foot - j.x).norm();
      // A touchpoint is a point, not a face: a face touching where a generator already
      // does (coplanar faces meeting there, a smooth edge) adds no equation.
      bool distinct = true;
      for (int i = 0; i < j.size(); ++i)
        distinct = distinct && (Generators[j.generators[i]].evaluate(j.q[i]).point - foot).norm() > 1e-7 * Size;
      // And the ball touches the face there (the centre lies on its normal), not just
      // comes near its border: a coplanar neighbour's edge a hair from a touchpoint.
      const Vec3 normal = Generators[f].evaluate(Generators[f].parameterOf(foot)).normal;
      const bool tangent = (j.x - foot).cross(normal).norm() <= 1e-8 * footDistance;
#ifdef EXACTMAT_TRACE3D_DEBUG
      std::fprintf(stderr, "   candidate face %d foot (%.9g %.9g %.9g) d-r %.3g distinct %d tangent %d\n", f, foot.x(), foot.y(), foot.z(), footDistance - j.r, (int)distinct, (int)tangent);
#endif
      if (!distinct || footDistance > j.r + reach)
        continue;
      // Touching at a reflex edge or corner of the face: that entity joins instead.
      const int g = tangent ? f : reflexEntityAt(f, foot);
      // (A reflex entity touches only with its normal in its arc or cone: else the touch
      // there belongs to a neighbour.)
      if (g >= 0 && std::find(j.generators.begin(), j.generators.end(), g) == j.generators.end() &&
        (tangent || Generators[g].exitSide(Generators[g].touchParameter(foot, j.x), 1e-9 * Size) < 0))
      {
        // A corner touching replaces the reflex edges ending there that joined before
        // (their touches were a hair short of it, or past it).
        if (Generators[g].kind() == GeneratorKind3D::ReflexCorner)
          for (int i = j.size() - 1; i >= 0; --i)
          {
            const Generator3D& other = Generators[j.generators[i]];
            if (other.kind() == GeneratorKind3D::ReflexEdge &&
              (B.edges()[other.entity()].startVertex == Generators[g].entity() ||
                B.edges()[other.entity()].endVertex == Generators[g].entity()))
            {
              j.generators.erase(j.generators.begin() + i);
              j.q.erase(j.q.begin() + i);
            }
          }
        j.generators.push_back(g);
        j.q.push_back(Generators[g].touchParameter(foot, j.x));
        added = true;
      }
    }
    if (!added)
      break;
    MedialBall3D polished = j;
#ifdef EXACTMAT_TRACE3D_DEBUG
    for (int i = 0; i < j.size(); ++i)
    {
      const Vec3 p = Generators[j.generators[i]].evaluate(j.q[i]).point;
      std::fprintf(stderr, "  polish round %d gen %d kind %d entity %d q (%.6g %.6g) point (%.6g %.6g %.6g) exit %d\n", round, j.generators[i],
        (int)Generators[j.generators[i]].kind(), Generators[j.generators[i]].entity(), j.q[i].x(), j.q[i].y(), p.x(), p.y(), p.z(),
        Generators[j.generators[i]].exitSide(j.q[i], Solve));
    }
#endif
    // (A solid far from the origin is known only to its rounding: four generators meeting
    // at a crossing of its edges solve only to that, like five or more anywhere.)
    if (!System.correct(polished, polished.size() > 4 ? Degenerate : std::max(Solve, Degenerate)))
      fail("3D MAT: the junction near ", describe(j), " could not be polished");
    j = polished;
  }
  appendTouching(j);
}

// Every entity touching the ball (to 1e-10 of the size) joins its generators, also where
// another touches at the same point and so adds no equation: a wall touched at its foot on
// a reflex edge and that edge (the ball's normal at the end of the edge's arc) start
// different seams (up the wall; along the edge's sheet below it), and so do the collinear
// pieces of an edge meeting there. Appended after a junction's solve (a repeated point is
// a repeated equation); the seams leaving solve their own triplets.
void Tracer::appendTouching(MedialBall3D& j, double tangency) const
{
  for (int f : Tree.candidatesWithin(j.x, j.r + 1e-6 * Size))
  {
    const Vec3 foot = Generators[f].nearestPoint(j.x);
    const double footDistance = (foot - j.x).norm();
    if (footDistance > j.r + 1e-10 * Size || footDistance <= Degenerate)
      continue;
    const Vec3 normal = Generators[f].evaluate(Generators[f].parameterOf(foot)).normal;
    std::vector<int> touching;
    if ((j.x - foot).cross(normal).norm() <= tangency * footDistance)
      touching.push_back(f);
    for (int g : reflexEntitiesAt(f, foot, 1e-9 * Size))
      if (Generators[g].exitSide(Generators[g].touchParameter(foot, j.x), 1e-9 * Size) < 0)
        touching.push_back(g);
    for (int g : touching)
      if (std::find(j.generators.begin(), j.generators.end(), g) == j.generators.end())
      {
        j.generators.push_back(g);
        j.q.push_back(g == f ? Generators[g].parameterOf(foot) : Generators[g].touchParameter(foot, j.x));
      }
  }
}

// A face the seam's ball touches in passing within the step from `from` by h along t (to
// `to`): a kiss. The ball comes to the face tangentially and leaves it again without
// entering, so the emptiness test sees nothing — yet the ball touches four entities there
// and other seams pass through (a symmetric part: the seam round a hole touches the one
// along the outer wall where the hole is as far from the wall as the plate is thick). The
// gap d − r of a face outside the generators changes by at most |Δx| + |Δr| over the step,
// so only faces that near both ends can be kissed; a parabola through their gaps at the
// ends and the middle that dips towards zero inside the step is followed by a golden-section
// search on the true seam balls. True with `at` the seam ball where the gap vanishes (to
// 1e-10 of the size), the kissing entities added to its generators.
bool Tracer::kiss(const MedialBall3D& from, const Eigen::VectorXd& t, double h, const MedialBall3D& to, MedialBall3D& at) const
{
  const double reach = 1.5 * ((to.x - from.x).norm() + std::abs(to.r - from.r));
  const double touching = std::max(Margin, Degenerate);
  // The gap to a surface, not to its pieces: a piece's own gap has a kink where the nearest
  // point leaves it (a hole's cylinder cut into quarters right where the seam kisses it).
  std::map<int, std::vector<int>> surfaces;
  for (int f : facesOutside(from, from.r + reach))
    if (Generators[f].polygon() || patchComesWithin(B.faces()[f].patch, from.x, from.r + reach))
      surfaces[B.faces()[f].entity >= 0 ? B.faces()[f].entity : -1 - f].push_back(f);
  auto gap = [&](const std::vector<int>& faces, const MedialBall3D& b, int* nearest = nullptr) {
    double best = Unbounded;
    for (int f : faces)
      if (const double d = Generators[f].distance(b.x) - b.r; d < best)
      {
        best = d;
        if (nearest)
          *nearest = f;
      }
    return best;
  };
  MedialBall3D middle;
  bool haveMiddle = false;
  for (const auto& entry : surfaces)
  {
    const std::vector<int>& faces = entry.second; // (a name of its own: lambdas below capture it)
    // (A surface touching at the start is the start node's, not a kiss.)
    // (The gap changes by at most `reach` over the step: a surface that cannot come down to
    // zero between both ends is skipped before the middle ball is solved.)
    const double g0 = gap(faces, from), g1 = gap(faces, to);
    if (g0 > reach || g1 > reach || g0 <= touching || (g1 > touching && g0 + g1 - reach > 2.0 * touching))
      continue;
    if (!haveMiddle && !(haveMiddle = step(from, t, 0.5 * h, middle)))
      return false; // (the step itself solved: Newton from half way fails only in pathology)
    const double gm = gap(faces, middle);
#ifdef EXACTMAT_TRACE3D_DEBUG
    std::fprintf(stderr, "   kiss? surface %d gaps %.3g %.3g %.3g\n", entry.first, g0, gm, g1);
#endif
    // The parabola through (0, g0), (½, gm), (1, g1): a minimum inside, near zero.
    const double a = 2.0 * (g0 - 2.0 * gm + g1), b = -3.0 * g0 + 4.0 * gm - g1;
    double lo = 0.0, hi = 1.0;
    if (g1 < -touching)
      continue; // it enters the ball: a junction, which the emptiness test finds
    if (g1 <= touching)
    {
      // The end ball touches already. Where it kisses the surface there (the gap's least
      // value, a double root) the junction is the step's end. But a surface the ball runs
      // along at its radius — an L prism's square leg, past the reflex edge where its wall
      // begins: the seam turns degenerate — touches over the step's rest, and the junction
      // is where the contact began: told apart by the gap 1e-3 of the size before the end
      // (a kiss's is about 1e-6 of its curvature there), then bisected. On a planar
      // surface, on where the centre's projection enters one of its pieces that touches
      // (exact: the wall's start); else on the gap (to the square root of the rounding, as
      // any tangential contact). Merged loosely either way.
      lo = hi = 1.0;
      const double before = std::max(0.5, 1.0 - 1e-3 * Size / h);
      if (MedialBall3D m; step(from, t, before * h, m) && gap(faces, m) <= touching)
      {
        const bool planar = std::all_of(faces.begin(), faces.end(), [&](int f) { return Generators[f].planar(); });
        auto touches = [&](const MedialBall3D& b) {
          if (!planar)
            return gap(faces, b) <= touching;
          for (int f : faces)
            if (Generators[f].holds(Generators[f].parameterOf(b.x), 0.0) &&
              std::abs(Generators[f].distance(b.x) - b.r) <= touching)
              return true;
          return false;
        };
        // (Where a planar piece does not hold the centre's projection at `before`, its gap
        // there is to the piece's side: a kiss at the end after all.)
        double a0 = 0.0, a1 = touches(m) ? before : 1.0;
        for (int k = 0; k < 60 && a1 < 1.0 && (a1 - a0) * h > 1e-13 * Size; ++k)
        {
          const double mid = 0.5 * (a0 + a1);
          (step(from, t, mid * h, m) && touches(m) ? a1 : a0) = mid;
        }
        if (a1 < 1.0)
          lo = hi = a1;
      }
    }
    else
    {
      if (a <= 0.0)
        continue;
      const double s = -b / (2.0 * a), dip = g0 - b * b / (4.0 * a);
      if (s <= 0.0 || s >= 1.0 || dip > 0.25 * std::min({ g0, gm, g1 }))
        continue;
      // Golden section on the true gap, about the parabola's minimum.
      const double invPhi = 0.5 * (std::sqrt(5.0) - 1.0);
      lo = std::max(0.0, s - 0.25);
      hi = std::min(1.0, s + 0.25);
      bool solved = true;
      auto gapAt = [&](double u) {
        MedialBall3D m;
        solved = solved && step(from, t, u * h, m);
        return solved ? gap(faces, m) : Unbounded;
      };
      double c = hi - invPhi * (hi - lo), d = lo + invPhi * (hi - lo);
      double gc = gapAt(c), gd = gapAt(d);
      for (int k = 0; k < 60 && solved && (hi - lo) * h > 1e-12 * Size; ++k)
        if (gc < gd)
        {
          hi = d;
          d = c;
          gd = gc;
          c = hi - invPhi * (hi - lo);
          gc = gapAt(c);
        }
        else
        {
          lo = c;
          c = d;
          gc = gd;
          d = lo + invPhi * (hi - lo);
          gd = gapAt(d);
        }
#ifdef EXACTMAT_TRACE3D_DEBUG
      std::fprintf(stderr, "   kiss golden section: solved %d gap %.3g at %.9g (touching %.3g)\n", (int)solved, std::min(gc, gd), gc < gd ? c : d, touching);
#endif
      if (!solved || std::abs(std::min(gc, gd)) > touching)
        continue;
      lo = hi = gc < gd ? c : d;
    }
    MedialBall3D m;
    int f = -1;
    if (!step(from, t, lo * h, m))
      continue;
    gap(faces, m, &f);
    // A contact of its own, not a neighbour of a touched face meeting it at its touch (a
    // coplanar piece whose side the touch is crossing).
    const Vec3 foot = Generators[f].nearestPoint(m.x);
    bool distinct = true;
    for (int i = 0; i < m.size() && distinct; ++i)
      distinct = !sameContact(m, Generators[m.generators[i]].evaluate(m.q[i]).point, foot);
#ifdef EXACTMAT_TRACE3D_DEBUG
    std::fprintf(stderr, "   kiss at %s: face %d distinct %d\n", describe(m).c_str(), f, (int)distinct);
#endif
    if (!distinct)
      continue;
    // (Where the gap is least the seam is located only to about the square root of the
    // rounding: the centre is off the kissing face's normal by about 1e-8 of the radius.)
    appendTouching(m, 1e-6);
    // A fourth contact point, not another entity touching at one of the three (the reflex
    // edges ending at a corner the seam's ball rolls round).
    bool fourth = false;
    for (int i = 3; i < m.size() && !fourth; ++i)
    {
      const Vec3 p = Generators[m.generators[i]].evaluate(m.q[i]).point;
      fourth = true;
      for (int k = 0; k < 3 && fourth; ++k)
        fourth = !sameContact(m, Generators[m.generators[k]].evaluate(m.q[k]).point, p);
    }
    if (fourth)
    {
#ifdef EXACTMAT_TRACE3D_DEBUG
      std::fprintf(stderr, "KISS %s\n", describe(m).c_str());
#endif
      at = m;
      return true;
    }
  }
  return false;
}

void Tracer::trace(int startNode, MedialBall3D ball, Eigen::VectorXd tangent, int touchpoints)
{
  MAT3DSeam seam;
  seam.touchpoints = touchpoints;
  seam.faces = { ball.generators[0], ball.generators[1], ball.generators[2] };
  seam.startNode = startNode;
  seam.balls.push_back(ball); // the node's ball restricted to the triplet
  const double tol = Options.tolerance * Size, hMax = Options.maxStep * Size;
  const bool fixed = Options.fixedStep;
  const double hFixed = Options.step * Size, checkSpacing = Options.junctionCheckStep * Size;
  double h = fixed ? hFixed : std::min(hMax, 1e-3 * Size);
  double sinceCheck = 0.0;          // fixed mode: arc length since the last emptiness check
  size_t lastChecked = 0;           // fixed mode: the last seam ball known empty
  // A ball found not empty: the junction lies in the step before the first seam ball since
  // the last check that is not empty (fixed mode), else in the step from `before` by h.
  // The balls past it are dropped. `tangential` as for junction().
  bool tangential = false;
  auto junctionSinceCheck = [&](const MedialBall3D& before, const Eigen::VectorXd& t, double h) {
    size_t first = seam.balls.size();
    for (size_t i = std::max<size_t>(lastChecked + 1, 1); i < seam.balls.size() && first == seam.balls.size(); ++i)
      if (!empty(seam.balls[i]))
        first = i;
    if (first == seam.balls.size())
      return junction(before, t, h, tangential);
    const MedialBall3D from = seam.balls[first - 1];
    Eigen::VectorXd direction = System.tangent(from);
    const Vec3 ahead = seam.balls[first].x - from.x;
    if (direction.segment<3>(6).dot(ahead) < 0.0)
      direction = -direction;
    seam.balls.resize(first);
    return junction(from, direction, ahead.norm(), tangential);
  };
  Eigen::VectorXd previous = tangent;
  int endNode = -1;
  // The seam ends at junction j. One located loosely — along a degenerate seam, where a
  // contact comes or leaves tangentially, or a kiss: to about the square root of the
  // rounding — is the junction reached from elsewhere within 1e-5 of the size, and marked.
  auto endAt = [&](const MedialBall3D& j, bool loose) {
    const size_t known = Result.nodes.size();
    endNode = addNode(j, -1, loose ? 1e-5 * Size : 0.0);
    if (loose && Result.nodes.size() > known)
      Result.nodes[endNode].imprecise = true;
    seam.balls.push_back(j);
  };
  int stalled = 0; // crossings in a row that made no progress along the seam
  Vec3 lastCrossing = Vec3::Constant(Unbounded);
  // A seam traced from a restart point (no node) that comes round to it is a closed loop:
  // the chord of a step (or of the step to a crossing: the restart point may lie on a face
  // side) passes the point.
  auto comesRound = [&](const Vec3& a, const Vec3& b) {
    if (startNode != RestartNode || seam.balls.size() <= 2)
      return false;
    const Vec3 chord = b - a, start = Result.nodes[startNode].ball.x;
    const double s = chord.squaredNorm() > 0.0 ? std::clamp((start - a).dot(chord) / chord.squaredNorm(), 0.0, 1.0) : 0.0;
    return (a + s * chord - start).norm() <= 2.0 * tol + NodeMerge;
  };
  for (int n = 0; n < Options.maxStepsPerSeam && endNode < 0; ++n)
  {
    if (n + 1 == Options.maxStepsPerSeam)
      fail("3D MAT: the seam through ", describe(ball), " did not end within ", Options.maxStepsPerSeam, " steps");
    if (RestartWorkLimit > 0 && patchSearchWork() > RestartWorkLimit)
      fail("3D MAT: the restart tracing the seam through ", describe(ball), " ran out of its budget");
    Eigen::VectorXd t = n == 0 ? tangent : System.tangent(ball);
    // Oriented by the centre and radius: the touch parameters change meaning across edges.
    if (t.segment<4>(6).dot(previous.segment<4>(6)) < 0.0)
      t = -t;
    MedialBall3D next;
    if (!step(ball, t, h, next))
    {
      h *= 0.5;
      if (h < 1e-13 * Size)
        fail("3D MAT: the seam through ", describe(ball), " cannot be continued (Newton does not converge)");
      continue;
    }
    const Eigen::VectorXd predicted = ball.pack() + h * t;
    const double error = (next.x - predicted.segment<3>(6)).norm() + std::abs(next.r - predicted(9));
    if (!fixed && error > tol && h > 1e-9 * Size)
    {
      h *= std::max(0.2, 0.8 * std::sqrt(tol / error));
      continue;
    }
    // At a degenerate node the triplet's solutions may branch: a first step that Newton
    // pulls off the computed direction has joined another seam (traced from its own
    // triplet), not this one.
    if (seam.balls.size() == 1 &&
      (next.x - ball.x).normalized().dot(t.segment<3>(6).normalized()) < 0.9)
      return;
    // The radius vanishes: the seam ends at a convex vertex.
    if (next.r < 0.0)
    {
      MedialBall3D v = ball;
      if (!System.correct(v, Solve, nullptr, nullptr, 0.0))
        fail("3D MAT: the seam through ", describe(ball), " could not be ended at radius 0");
      const int node = findNode(v.x);
      if (node < 0 || Result.nodes[node].vertex < 0)
      {
        // A touch that leaves its entity on the way (a cavity wall's touch crossing the
        // wall's edge while the ball shrinks towards an outer convex edge) is crossed
        // first: the seam goes on with the entity beyond, at a shorter step.
        bool leaves = false;
        for (int i = 0; i < 3 && !leaves; ++i)
          leaves = Generators[v.generators[i]].exitSide(v.q[i], OnEntity) >= 0;
        if (leaves && h > 1e-9 * Size)
        {
          h *= 0.5;
          continue;
        }
        fail("3D MAT: the seam through ", describe(ball), " reaches radius 0 at ", format(B.userPoint(v.x)),
          ", which is not a convex vertex");
      }
      seam.balls.push_back(v);
      endNode = node;
      break;
    }
    // A touchpoint leaving its face: bisect for the crossing, then continue on the
    // neighbour across a smooth edge.
    int leaving = -1, side = -1;
    for (int i = 0; i < 3 && leaving < 0; ++i)
    {
      side = Generators[next.generators[i]].exitSide(next.q[i], OnEntity);
      if (side >= 0)
        leaving = i;
    }
    if (leaving >= 0)
    {
      // The first crossing of any of the three (another touchpoint may leave its face
      // before the one seen leaving at the end of the step).
      double lo = 0.0, hi = h;
      MedialBall3D at = ball;
      for (int k = 0; k < 80 && hi - lo > 1e-14 * Size; ++k)
      {
        const double mid = 0.5 * (lo + hi);
        MedialBall3D m;
        const bool solved = step(ball, t, mid, m);
        int out = -1, crossed = -1;
        for (int i = 0; i < 3 && solved && out < 0; ++i)
        {
          crossed = Generators[m.generators[i]].exitSide(m.q[i], OnEntity);
          if (crossed >= 0)
            out = i;
        }
        if (solved && out < 0)
        {
          lo = mid;
          at = m;
        }
        else
        {
          hi = mid;
          if (out >= 0)
          {
            leaving = out;
            side = crossed; // the side crossed nearest the crossing
          }
        }
      }
      // A fourth face may touch before the touchpoint reaches the edge (always so at a
      // convex edge), or just as it does (a grid of squares: the face beyond an edge
      // touches the ball from there on): then the seam ends at that junction.
      MedialBall3D touching = at;
      if (empty(at) && contactCount(at) != seam.touchpoints)
        polishJunction(touching);
      else if (seam.touchpoints == 3 && empty(at) && kiss(ball, t, lo, at, touching))
        tangential = true;
      if (!empty(at) || touching.size() > 3)
      {
        const MedialBall3D j = touching.size() > 3 ? touching : junctionSinceCheck(ball, t, lo);
        // Along a degenerate seam the ball's place is not pinned by its own equations: the
        // junction is known only as well as the contact count locates it.
        endAt(j, seam.touchpoints > 3 || tangential);
        break;
      }
      // Two touchpoints meeting at a vertex as the touch leaves (the seam reaches a rim).
      if (int a = -1, b = -1; merging(at, a, b))
      {
        seam.balls.push_back(at);
        endNode = seamEndAtVertex(at, a, b);
        break;
      }
      if (comesRound(ball.x, at.x))
      {
        seam.balls.push_back(seam.balls.front());
        endNode = startNode;
        break;
      }
      const int face = at.generators[leaving];
      const MedialBall3D crossing = at;
      // Crossings that make no progress meet at a point where several entities end (a
      // staircase's vertex where a step's reflex edge ends at a taller column's corner): the
      // neighbour across the side crossed may be no nearer than the entity left, and the
      // touch goes back and forth. There the touch goes on with the entity nearest the ball
      // moved on along the seam (the rule the sheets use across a seam).
      const int nearest = stalled >= 3 ? sheetGenerator(at, Generators[face].evaluate(at.q[leaving]).point, face,
                                           t.segment<3>(6))
                                       : face;
      if (nearest != face && !onAnotherTouchFace(at, leaving, nearest))
      {
        const Generator3D& to = Generators[nearest];
        const Vec3 foot = to.nearestPoint(at.x);
        at.generators[leaving] = nearest;
        at.q[leaving] = to.kind() == GeneratorKind3D::Face ? to.parameterOf(foot) : to.touchParameter(foot, at.x);
      }
      else
      {
        const Vec3 motion = t.segment<3>(6);
        crossOver(at, leaving, side, &motion);
      }
      // (The ball on the new generator is the same ball: Newton only polishes it.)
      if (!System.correct(at, Solve) || (at.x - crossing.x).norm() > 1e-6 * Size)
        fail("3D MAT: the seam through ", describe(crossing), " could not cross from ", Generators[face].name(), " onto ",
          Generators[at.generators[leaving]].name());
#ifdef EXACTMAT_TRACE3D_DEBUG
      std::fprintf(stderr, "  crossed from %d to %s\n", face, describe(at).c_str());
#endif
      // (No progress: the step to the crossing was nil, or the crossings go back and forth
      // around one point.)
      stalled = lo > 1e-9 * Size && (at.x - lastCrossing).norm() > 1e-6 * Size ? 0 : stalled + 1;
      lastCrossing = at.x;
      if (stalled > 8)
        fail("3D MAT: the seam through ", describe(at), " keeps crossing edges without moving (",
          Generators[face].name(), " and its neighbours)");
      // Two touchpoints merged at a vertex (a reflex edge's touch reached its end where
      // another reflex edge ends): the seam ends on the rim of their sheet.
      if (int a = -1, b = -1; merging(at, a, b))
      {
        seam.balls.push_back(at);
        endNode = seamEndAtVertex(at, a, b);
        break;
      }
      seam.balls.push_back(at);
      ball = at;
      previous = t;
      lastChecked = seam.balls.size() - 1; // emptiness was checked at the crossing
      sinceCheck = 0.0;
      continue;
    }
    // Fixed mode checks emptiness only every junctionCheckStep (as the thesis does).
    sinceCheck += h;
    const bool check = !fixed || sinceCheck >= checkSpacing;
    if (check)
    {
      sinceCheck = 0.0;
      if (const int face = empty(next) ? reentering(next) : -1; face >= 0)
        fail("3D MAT: the seam through ", describe(ball), " reaches a ball that ", Generators[face].name(),
          " touches twice or curves into (a junction of one face with itself, or a skeletal edge): "
          "not supported yet");
    }
    if (check && !empty(next))
    {
      const MedialBall3D j = junctionSinceCheck(ball, t, h);
      // (As at a crossing: a degenerate seam's junction is located loosely.)
      endAt(j, seam.touchpoints > 3 || tangential);
      break;
    }
    if (MedialBall3D j; seam.touchpoints == 3 && kiss(ball, t, h, next, j))
    {
      endAt(j, true); // (located by the gap's minimum)
      break;
    }
    if (check)
      lastChecked = seam.balls.size(); // `next`, pushed below
    // A degenerate seam (more touchpoints than its triplet: a square tube's axis) ends
    // where one of its extra contacts leaves: located by bisection on the contact count.
    if (seam.touchpoints > 3 && contactCount(next) != seam.touchpoints)
    {
      double lo = 0.0, hi = h;
      MedialBall3D last = ball;
      for (int k = 0; k < 60 && hi - lo > 1e-14 * Size; ++k)
      {
        const double mid = 0.5 * (lo + hi);
        MedialBall3D m;
        if (step(ball, t, mid, m) && contactCount(m) == seam.touchpoints)
        {
          lo = mid;
          last = m;
        }
        else
          hi = mid;
      }
      polishJunction(last);
      if (last.size() < 4)
        fail("3D MAT: the degenerate seam through ", describe(ball), " loses a touchpoint where no junction is found");
      // (A contact that leaves tangentially: the degenerate system does not sharpen it.)
      endAt(last, true);
      break;
    }
    if (comesRound(ball.x, next.x))
    {
      seam.balls.push_back(seam.balls.front());
      endNode = startNode;
      break;
    }
#ifdef EXACTMAT_TRACE3D_DEBUG
    std::fprintf(stderr, "  step h %.3g to %s; exits", h, describe(next).c_str());
    for (int i = 0; i < 3; ++i)
      std::fprintf(stderr, " %d", Generators[next.generators[i]].exitSide(next.q[i], Solve));
    std::fprintf(stderr, "\n");
#endif
    seam.balls.push_back(next);
    ball = next;
    previous = t;
    h = fixed ? hFixed : std::min(hMax, h * 1.5);
  }
  seam.endNode = endNode;
  // A ball pushed at a crossing a hair before the end node is the node itself.
  while (seam.balls.size() > 2 && (seam.balls[seam.balls.size() - 2].x - seam.balls.back().x).norm() <= NodeMerge)
    seam.balls.erase(seam.balls.end() - 2);
  // The seam's direction at its end node, away from it (the end ball's first three
  // generators are the arriving triplet).
  MedialBall3D end = seam.balls.back();
  end.generators.resize(3);
  end.q.resize(3);
  const Vec3 arrival = System.tangent(end).segment<3>(6);
  const Vec3 back = seam.balls[seam.balls.size() - 2].x - end.x;
  if (arrival.norm() > 0.0)
    depart(endNode, arrival.dot(back) >= 0.0 ? arrival.normalized() : Vec3(-arrival.normalized()), end, seam.touchpoints);
  // The triplet at the end (it may have changed across smooth edges) is traced from there.
  Traced.insert({ endNode, sorted({ ball.generators[0], ball.generators[1], ball.generators[2] }) });
  // Node balls as the seam's ends, so the polyline shares the node's point.
  seam.balls.back().x = Result.nodes[endNode].ball.x;
  seam.balls.back().r = Result.nodes[endNode].ball.r;
  // A triplet leaving a degenerate node (many generators, merged touches) in a direction of
  // no seam of its own is pulled by Newton onto a seam already traced between the same
  // nodes: the same curve twice, kept once.
  const MedialBall3D& middle = seam.balls[seam.balls.size() / 2];
  for (const MAT3DSeam& other : Result.seams)
    if (std::minmax(other.startNode, other.endNode) == std::minmax(seam.startNode, seam.endNode) &&
      distanceToSeam(other, middle.x) <= 10.0 * Options.tolerance * Size)
      return;
  Result.seams.push_back(std::move(seam));
  if (static_cast<int>(Result.seams.size()) > Options.maxSeams)
    fail("3D MAT: more than ", Options.maxSeams, " seams");
}

// The distinct points where the ball touches the boundary, each with the generators that
// touch it there, the most particular kind only: a reflex corner rather than the edges
// and faces that end at it, a reflex edge rather than its two faces (whose feet are on
// their sides there); coplanar faces meeting at a smooth edge both.
std::vector<std::pair<Vec3, std::vector<int>>> Tracer::contactGenerators(const MedialBall3D& ball) const
{
  const double reach = ball.r + Degenerate;
  std::vector<int> candidates;
  for (int f : Tree.candidatesWithin(ball.x, reach))
  {
    if (!Generators[f].polygon() && !patchComesWithin(B.faces()[f].patch, ball.x, reach))
      continue;
    candidates.push_back(f);
    for (int side = 0; side < 4; ++side)
    {
      const auto it = SideEdge.find({ f, side });
      if (it == SideEdge.end())
        continue;
      candidates.push_back(EdgeGenerator[it->second]);
      const Edge3D& edge = B.edges()[it->second];
      for (int v : { edge.startVertex, edge.endVertex })
        candidates.push_back(v >= 0 ? CornerGenerator[v] : -1);
    }
  }
  for (int g : ball.generators)
    candidates.push_back(g);
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  auto rank = [this](int g) {
    const GeneratorKind3D k = Generators[g].kind();
    return k == GeneratorKind3D::ReflexCorner ? 2 : (k == GeneratorKind3D::ReflexEdge ? 1 : 0);
  };
  std::vector<std::pair<Vec3, std::vector<int>>> groups;
  for (int g : candidates)
  {
    if (g < 0)
      continue;
    const Vec3 foot = Generators[g].nearestPoint(ball.x);
    if ((foot - ball.x).norm() > reach)
      continue;
    auto group = std::find_if(groups.begin(), groups.end(),
      [&](const std::pair<Vec3, std::vector<int>>& c) { return sameContact(ball, c.first, foot); });
    if (group == groups.end())
      groups.push_back({ foot, { g } });
    else if (rank(g) > rank(group->second.front()))
      group->second = { g };
    else if (rank(g) == rank(group->second.front()))
      group->second.push_back(g);
  }
  return groups;
}

// The pairs of ball b's triplet that bound a sheet along the seam there: all three on a
// seam of three touchpoints. Along a degenerate seam (more touchpoints than its triplet)
// the sheets meeting at the seam are those between touchpoints next to each other around
// it: the touch directions, seen along the seam's tangent, in angular order, and a pair
// with a touch on either arc between its own two has no sheet there (a staircase's seam
// where two faces and two reflex edges touch: the face and the edge opposite it are
// equidistant only on the seam itself).
std::set<std::pair<int, int>> Tracer::sheetPairs(const MAT3DSeam& seam, size_t b) const
{
  const MedialBall3D& ball = seam.balls[b];
  std::set<std::pair<int, int>> pairs;
  if (seam.touchpoints <= 3 || seam.balls.size() < 3 || ball.r <= Degenerate)
  {
    // The sheet of touches i and j leaves the seam in the direction w (across the seam's
    // tangent) in which the third generator k recedes: N_i·w = N_j·w < N_k·w. A touch on
    // the border of its entity's domain belongs to the entity that direction enters.
    const size_t before = b > 0 ? b - 1 : b, after = b + 1 < seam.balls.size() ? b + 1 : b;
    const Vec3 tangent = seam.balls[after].x - seam.balls[before].x;
    Vec3 normal[3];
    for (int i = 0; i < 3; ++i)
      normal[i] = Generators[ball.generators[i]].evaluate(ball.q[i]).normal;
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j)
      {
        const int k = 3 - i - j;
        Vec3 w = tangent.cross(normal[i] - normal[j]);
        if (w.dot(normal[k] - normal[i]) < 0.0)
          w = -w;
        const bool across = ball.r > Degenerate && w.norm() > 1e-9 * tangent.norm();
        pairs.insert(std::minmax(across ? cornerOrEdge(ball, i, w) : ball.generators[i],
          across ? cornerOrEdge(ball, j, w) : ball.generators[j]));
      }
    return pairs;
  }
  // The end balls are nodes, touched by every generator there: their order is the node's.
  if (b == 0 || b + 1 == seam.balls.size())
    return {};
  // The tangent: the chord between the nearest balls either side that are elsewhere (a
  // seam that changes triplets lands several balls on the point where it does).
  size_t before = b - 1, after = b + 1;
  while (before > 0 && (seam.balls[before].x - ball.x).norm() <= Degenerate)
    --before;
  while (after + 1 < seam.balls.size() && (seam.balls[after].x - ball.x).norm() <= Degenerate)
    ++after;
  const Vec3 chord = seam.balls[after].x - seam.balls[before].x;
  if (!(chord.norm() > Degenerate))
    return {};
  const std::vector<std::pair<Vec3, std::vector<int>>> touches = contactGenerators(ball);
  if (touches.size() <= 3)
    return pairs;
  // The touches in angular order about the seam's tangent; consecutive ones bound a sheet.
  const Vec3 tangent = chord.normalized();
  const Vec3 u = tangent.unitOrthogonal(), v = tangent.cross(u);
  std::vector<std::pair<double, size_t>> order;
  for (size_t k = 0; k < touches.size(); ++k)
  {
    const Vec3 d = touches[k].first - ball.x;
    order.emplace_back(std::atan2(d.dot(v), d.dot(u)), k);
  }
  std::sort(order.begin(), order.end());
  std::set<std::pair<int, int>> adjacent;
  for (size_t k = 0; k < order.size(); ++k)
  {
    const auto& [p, gs] = touches[order[k].second];
    const auto& [o, hs] = touches[order[(k + 1) % order.size()].second];
    for (int g : gs)
      for (int h : hs)
        if (g != h)
          adjacent.insert(std::minmax(g, h));
    // And the entities the two touches move onto as the ball leaves the seam between them
    // (a touch on the border of a wall at a reflex edge: the wall's sheet needs the seam).
    Vec3 w = (p - ball.x).normalized() + (o - ball.x).normalized();
    w -= w.dot(tangent) * tangent;
    if (w.norm() > 1e-6)
    {
      const int g = sheetGenerator(ball, p, gs.front(), w), h = sheetGenerator(ball, o, hs.front(), w);
      if (g != h)
        adjacent.insert(std::minmax(g, h));
    }
  }
  return adjacent;
}

// The pairs bordering the stretch from ball b to ball b + 1 of a three-touch seam inside
// it, where each touch that moves has left its entity's border: a seam that crosses from a
// reflex corner onto the edge ending there, one step before a junction, has no ball inside
// that stretch, and at its first ball (the touch at the edge's end) the sheet beside it
// can lean onto the corner (random cavity 32: the sheet of an outer wall and a cavity edge
// lost that stretch, and its border closed on a line). A touch that stays at the vertex
// (an arc about a reflex corner) keeps the pairing of its balls.
std::set<std::pair<int, int>> Tracer::stretchPairs(const MAT3DSeam& seam, size_t b) const
{
  std::set<std::pair<int, int>> pairs;
  if (seam.touchpoints > 3 || b + 1 >= seam.balls.size())
    return pairs;
  const MedialBall3D& ball = seam.balls[b];
  const MedialBall3D& next = seam.balls[b + 1];
  const double same = std::max(1e-9 * Size, 1e3 * Degenerate);
  bool moved[3];
  for (int i = 0; i < 3; ++i)
  {
    const auto at = std::find(next.generators.begin(), next.generators.end(), ball.generators[i]);
    if (at == next.generators.end())
      return pairs; // the triplet changes: the stretch is the next ball's
    const Generator3D& gen = Generators[ball.generators[i]];
    moved[i] = (gen.evaluate(ball.q[i]).point - gen.evaluate(next.q[at - next.generators.begin()]).point).norm() > same;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (moved[i] && moved[j])
        pairs.insert(std::minmax(ball.generators[i], ball.generators[j]));
  return pairs;
}

// A three-touch seam's touch i on a reflex edge at its end where a reflex corner is (the
// normal, normal to the edge, on the border of the corner's cone), or on the corner with its
// normal on that border: the seam (an arc around a staircase's low corner cell, between
// floor and ceiling) solves with either, but moving the ball by w onto the sheet beside it
// turns the normal by w's component along the edge: into the corner's cone when that points
// away from the edge, else onto the edge.
int Tracer::cornerOrEdge(const MedialBall3D& ball, int i, const Vec3& w) const
{
  const int g = ball.generators[i];
  const Generator3D& gen = Generators[g];
  const Touch3D touch = gen.evaluate(ball.q[i]);
  const double same = std::max(1e-9 * Size, 1e3 * Degenerate);
  if (gen.kind() == GeneratorKind3D::ReflexEdge)
  {
    const Edge3D& edge = B.edges()[gen.entity()];
    for (int v : { edge.startVertex, edge.endVertex })
    {
      if (v < 0 || CornerGenerator[v] < 0 || (B.vertices()[v].point - touch.point).norm() > same)
        continue;
      const Generator3D& corner = Generators[CornerGenerator[v]];
      if (corner.exitSide(corner.touchParameter(touch.point, ball.x), OnEntity) >= 0)
        continue;
      const Vec3 along = (v == edge.startVertex ? 1.0 : -1.0) * touch.dPoint.col(0).normalized();
      // (A sheet across the seam whose w has no component along the edge stays with it.)
      return w.dot(along) < -1e-6 * w.norm() ? CornerGenerator[v] : g;
    }
  }
  else if (gen.kind() == GeneratorKind3D::ReflexCorner)
  {
    const double slack = std::max(1e-9, OnEntity / std::max(ball.r, OnEntity));
    for (size_t e = 0; e < gen.cornerEdges().size(); ++e)
    {
      const Vec3& along = gen.cornerTangents()[e];
      const int edge = gen.cornerEdges()[e];
      if (EdgeGenerator[edge] >= 0 && std::abs(touch.normal.dot(along)) <= slack && w.dot(along) > 1e-6 * w.norm())
        return EdgeGenerator[edge];
    }
  }
  return g;
}

// The generator of a ball's touch at `point` (by generator g) for the sheet beside the
// seam in direction w. A touch on the border of its entity's domain is also a touch of the
// entity beyond: a wall touched at its foot on a reflex edge and that edge, a reflex edge
// touched at its end and the reflex corner there. Each solves the seam's ball, and a seam
// can run along such a border (a staircase's mid-line touching a step's wall at its foot;
// an arc around a reflex corner between a floor and a ceiling), but the sheet beside it
// has the entity the touch moves onto when the ball moves by w: the nearest of them from
// the moved centre whose normal there passes through it.
int Tracer::sheetGenerator(const MedialBall3D& ball, const Vec3& point, int g, const Vec3& w) const
{
  const double same = std::max(1e-9 * Size, 1e3 * Degenerate);
  std::vector<int> candidates{ g };
  for (int f : Tree.candidatesWithin(point, same))
  {
    if (Generators[f].distance(point) > same)
      continue;
    candidates.push_back(f);
    for (int e : reflexEntitiesAt(f, point, same))
      candidates.push_back(e);
  }
  if (candidates.size() == 1 || ball.r <= 1e3 * same)
    return g;
  const double delta = 1e-4 * ball.r;
  const Vec3 moved = ball.x + delta * w.normalized();
  int best = g;
  double nearest = Unbounded;
  for (int c : candidates)
  {
    const Generator3D& gen = Generators[c];
    const Vec3 foot = gen.nearestPoint(moved);
    const double d = (foot - moved).norm();
    const Vec2 q = gen.kind() == GeneratorKind3D::Face ? gen.parameterOf(foot) : gen.touchParameter(foot, moved);
    const Touch3D t = gen.evaluate(q);
    if ((t.point + d * t.normal - moved).norm() > 1e-3 * delta || gen.exitSide(q, same) >= 0)
      continue; // the moved ball does not touch c along c's normal
    if (d < nearest - 1e-3 * delta * delta / ball.r)
    {
      nearest = d;
      best = c;
    }
  }
  return best;
}

// Every pair of faces in a seam's triplet (at any of its balls: a triplet changes across
// smooth edges) whose touches are next to each other around the seam bounds a sheet with
// that seam; convex edges between the pair close it.
void Tracer::collectSheets()
{
  std::map<std::pair<int, int>, MAT3DSheet> sheets;
  for (int s = 0; s < static_cast<int>(Result.seams.size()); ++s)
  {
    std::set<std::pair<int, int>> pairs;
    const MAT3DSeam& seam = Result.seams[s];
    for (size_t b = 0; b < seam.balls.size(); ++b)
      if (seam.balls[b].size() == 3)
      {
        for (const auto& pair : sheetPairs(seam, b))
          pairs.insert(pair);
        for (const auto& pair : stretchPairs(seam, b))
          pairs.insert(pair);
      }
    for (const auto& p : pairs)
    {
      MAT3DSheet& sheet = sheets[p];
      sheet.generatorA = p.first;
      sheet.generatorB = p.second;
      sheet.seams.push_back(s);
    }
  }
  for (int e = 0; e < static_cast<int>(B.edges().size()); ++e)
  {
    const Edge3D& edge = B.edges()[e];
    if (edge.kind != VertexKind::Convex)
      continue;
    const auto it = sheets.find(std::minmax(edge.faceA, edge.faceB));
    if (it != sheets.end())
      it->second.convexEdges.push_back(e);
  }
  for (auto& [pair, sheet] : sheets)
    Result.sheets.push_back(std::move(sheet));
}

void Tracer::reportProgress()
{
  if (!Options.progress || Result.seams.empty()) // (a trace may add no seam)
    return;
  Reached.resize(B.faces().size(), false);
  for (const MedialBall3D& ball : Result.seams.back().balls)
    for (int g : ball.generators)
      for (int f : Generators[g].faces())
        if (!Reached[f])
        {
          Reached[f] = true;
          ++ReachedCount;
        }
  Options.progress(static_cast<double>(ReachedCount) / static_cast<double>(B.faces().size()));
}

void Tracer::startFrom(int node)
{
  // A seam's end on a rim starts nothing: its rim is traced with it, and its triplet's two
  // merged touches make no seam.
  if (Result.nodes[node].seamEnd)
    return;
  const MedialBall3D& nb = Result.nodes[node].ball;
  const std::vector<int> faces = nb.generators;
  const int k = static_cast<int>(faces.size());

  // At a junction a seam's three touches are distinct points: generators touching at one
  // point (coplanar pieces, a wall and the reflex edge at its foot) are never in one
  // triplet. (At a vertex every generator touches the vertex.)
  Vec3List at(k);
  for (int i = 0; i < k; ++i)
    at[i] = Generators[faces[i]].evaluate(nb.q[i]).point;
  const double same = nb.r > 1e3 * Degenerate ? 1e-6 * nb.r : -1.0;
  auto apart = [&](int i, int j) { return (at[i] - at[j]).norm() > same; };
  for (int a = 0; a < k; ++a)
    for (int b = a + 1; b < k; ++b)
      for (int c = b + 1; c < k; ++c)
      {
        if (!apart(a, b) || !apart(a, c) || !apart(b, c))
          continue;
        const Triplet t = sorted({ faces[a], faces[b], faces[c] });
        if (Traced.count({ node, t }))
          continue;
        MedialBall3D ball;
        Eigen::VectorXd tangent;
        int touchpoints = 3;
        if (!outgoing(node, t, ball, tangent, touchpoints))
          continue;
#ifdef EXACTMAT_TRACE3D_DEBUG
        std::fprintf(stderr, "node %d: triplet %d %d %d leaves with %d touchpoints\n", node, t[0], t[1], t[2], touchpoints);
#endif
        Traced.insert({ node, t });
        const Vec3 d = tangent.segment<3>(6).normalized();
        if (departed(node, d, ball, touchpoints))
          continue;
        depart(node, d, ball, touchpoints);
        trace(node, ball, tangent, touchpoints);
        reportProgress();
      }
}

void Tracer::depart(int node, const Vec3& direction, const MedialBall3D& triplet, int touchpoints)
{
  Departure d{ direction, {} };
  if (touchpoints <= 3)
    for (int i = 0; i < 3; ++i)
      d.contacts.push_back(Generators[triplet.generators[i]].evaluate(triplet.q[i]).point);
  Departures[node].push_back(std::move(d));
  Result.nodes[node].directions.push_back(direction);
}

// Whether the seam of `triplet` (its touches at the node) leaving in `direction` is one
// already traced from or to the node. Two triplets with one seam: coplanar faces (a planar
// face split into triangles or squares) both touch the ball leaving along their common
// edge, at one point; a degenerate seam is every triplet of its touches. Two seams can
// also leave in one direction with different touches, tangent to each other at a
// degenerate junction (a staircase's straight seam along a wall and the arc around a
// reflex corner beside it, both between the same floor and ceiling): both are traced —
// when both have three touchpoints (a degenerate seam keeps its direction).
bool Tracer::departed(int node, const Vec3& direction, const MedialBall3D& triplet, int touchpoints) const
{
  const auto it = Departures.find(node);
  if (it == Departures.end())
    return false;
  const double same = std::max(1e-6 * Result.nodes[node].ball.r, 1e3 * Degenerate);
  for (const Departure& d : it->second)
  {
#ifdef EXACTMAT_TRACE3D_DEBUG
    std::fprintf(stderr, "   direction (%.9f %.9f %.9f) vs known (%.9f %.9f %.9f)\n", direction.x(), direction.y(),
      direction.z(), d.direction.x(), d.direction.y(), d.direction.z());
#endif
    if ((d.direction - direction).norm() >= 1e-6)
      continue;
    bool shared = true;
    for (int i = 0; i < 3 && shared && !d.contacts.empty() && touchpoints <= 3; ++i)
    {
      const Vec3 p = Generators[triplet.generators[i]].evaluate(triplet.q[i]).point;
#ifdef EXACTMAT_TRACE3D_DEBUG
      std::fprintf(stderr, "     touch of %d at (%.9g %.9g %.9g)\n", triplet.generators[i], p.x(), p.y(), p.z());
      for (const Vec3& c : d.contacts)
        std::fprintf(stderr, "       known (%.9g %.9g %.9g)\n", c.x(), c.y(), c.z());
#endif
      bool found = false;
      for (const Vec3& c : d.contacts)
        found = found || (c - p).norm() <= same;
      shared = found;
    }
    if (shared)
      return true;
  }
  return false;
}

// The largest empty ball touching generator g at `point`, its centre along `normal` (into
// the material): the shrinking ball, by bisection on the exact emptiness test.
MedialBall3D Tracer::grownBall(int g, const Vec3& point, const Vec3& normal) const
{
  const Generator3D& gen = Generators[g];
  MedialBall3D ball;
  ball.generators = { g };
  ball.q = { gen.kind() == GeneratorKind3D::Face ? gen.parameterOf(point) : gen.touchParameter(point, point + normal) };
  // The shrinking ball (Ma, Bae, Choi & Park 2012): the nearest point q of the boundary
  // inside a ball too big gives the ball touching the point and q, smaller; repeated until
  // nothing is nearer than the radius (the radii decrease to the largest empty one: every
  // ball touching the point and a boundary point is at least that big). One closest-point
  // query per face near the centre a round — the bisection on the exact emptiness test it
  // replaces subdivided for a second a ball against faces touching it tangentially (a
  // restart on an extruded blob: 160 s of walks).
  double r = Size;
  for (int k = 0; k < 200 && !(RestartWorkLimit > 0 && patchSearchWork() > RestartWorkLimit); ++k)
  {
    ball.r = r;
    ball.x = point + r * normal;
    double nearest = r * (1.0 - 1e-12);
    Vec3 q = point;
    for (int f : facesOutside(ball, r))
    {
      const Vec3 foot = Generators[f].nearestPoint(ball.x);
      if (const double d = (foot - ball.x).norm(); d < nearest)
      {
        nearest = d;
        q = foot;
      }
    }
    const Vec3 e = q - point;
    const double along = normal.dot(e);
    if (along <= 0.0) // nothing inside (or only the rounding of the point itself)
      break;
    const double smaller = e.squaredNorm() / (2.0 * along);
    if (!(smaller < r))
      break;
    r = smaller;
  }
  return ball;
}

// The generators touching a grown ball besides its own (sorted; one per contact).
std::vector<int> Tracer::othersTouching(const MedialBall3D& ball) const
{
  const Vec3 own = Generators[ball.generators[0]].evaluate(ball.q[0]).point;
  std::vector<int> others;
  for (const auto& [point, generators] : contactGenerators(ball))
    if (!sameContact(ball, point, own) && (point - own).norm() > 1e-7 * Size)
      others.push_back(generators.front());
  std::sort(others.begin(), others.end());
  return others;
}

// The distance from x to a seam's polyline.
double Tracer::distanceToSeam(const MAT3DSeam& seam, const Vec3& x)
{
  double nearest = Unbounded;
  for (size_t i = 0; i + 1 < seam.balls.size(); ++i)
  {
    const Vec3 a = seam.balls[i].x, e = seam.balls[i + 1].x - a;
    const double s = e.squaredNorm() > 0.0 ? std::clamp((x - a).dot(e) / e.squaredNorm(), 0.0, 1.0) : 0.0;
    nearest = std::min(nearest, (a + s * e - x).norm());
  }
  return nearest;
}

// A ball on a seam already traced (within the seams' own chord tolerance: the test a seam
// traced twice is kept once by).
bool Tracer::onTracedSeam(const MedialBall3D& ball) const
{
  for (const MAT3DSeam& seam : Result.seams)
    if (distanceToSeam(seam, ball.x) <= 10.0 * Options.tolerance * Size)
      return true;
  return false;
}

// Seams no convex vertex leads to (a ring of seams about a small cavity inside a sheet,
// thesis §6.5.1's restart): balls grown from points of a face no seam touches, walked from
// its middle to its border and on round a reflex edge there (the normal turning from this
// face's to the next one's), touch one other entity each until, between two of them, the
// entity changes; there a ball touches three, which Newton puts on their seam. The seam is
// traced both ways from that point and the two halves joined into one; the junctions it
// reaches start the rest as usual. False when no walk finds a seam not traced yet.
bool Tracer::restartFrom(int face)
{
  // A budget for curved solids: their walks and seams cost closest-point searches that
  // balls touching free-form faces tangentially make slow (an extruded blob, whose sheets
  // end in fin points the tracer does not know yet: minutes of walks and seams that fail
  // anyway). Counted in boxes searched, so that it gives up at the same point on every
  // machine. (A plate's restarts need 40 000 boxes each, a short cylinder's 20 000.)
  struct Budget
  {
    std::uint64_t& limit;
    ~Budget() { limit = 0; }
  } budget{ RestartWorkLimit };
  const bool polyhedron = std::all_of(Generators.begin(), Generators.begin() + B.faces().size(),
    [](const Generator3D& g) { return g.polygon(); });
  RestartWorkLimit = polyhedron ? 0 : patchSearchWork() + RestartWorkBudget;
  // (And no one closest-point search may spend a large part of it: those next to the
  // collapsed corner of a triangular piece follow a near-continuum of minima.)
  const PatchSearchLimit perSearch(polyhedron ? std::numeric_limits<int>::max() : MaxRestartSearchBoxes);
  auto exhausted = [&]() { return RestartWorkLimit > 0 && patchSearchWork() > RestartWorkLimit; };

  const int samples = 16;
  const Generator3D& own = Generators[face];
  const BezierPatch& patch = B.faces()[face].patch;
  // Walks: the four directions to the middles of the sides, then the four diagonals.
  const std::array<std::array<double, 2>, 8> directions{ { { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 }, { 1, 1 },
    { -1, -1 }, { 1, -1 }, { -1, 1 } } };
  const std::array<int, 4> sideOf{ { 1, 3, 2, 0 } }; // the side each of the first four reaches
  for (size_t w = 0; w < directions.size(); ++w)
  {
    const auto& d = directions[w];
    const double reach = 0.5 * (1.0 - 1e-9);
    auto onFace = [&](double s) {
      const Vec3 p = patch.evaluate(0.5 + d[0] * reach * s, 0.5 + d[1] * reach * s);
      return grownBall(face, p, own.evaluate(own.parameterOf(p)).normal);
    };
    std::vector<std::function<MedialBall3D(double)>> legs{ onFace };
    // Round the reflex edge at the side reached: the normal from this face's to the next's.
    const auto side = w < 4 ? SideEdge.find({ face, sideOf[w] }) : SideEdge.end();
    if (side != SideEdge.end() && EdgeGenerator[side->second] >= 0)
    {
      const Edge3D& edge = B.edges()[side->second];
      const int next = edge.faceA == face ? edge.faceB : edge.faceA;
      const Vec3 p = patch.evaluate(0.5 + d[0] * 0.5, 0.5 + d[1] * 0.5);
      const Vec3 from = own.evaluate(own.parameterOf(p)).normal;
      const Vec3 to = Generators[next].evaluate(Generators[next].parameterOf(p)).normal;
      const int g = EdgeGenerator[side->second];
      legs.push_back([this, g, p, from, to](double s) {
        const double t = 1e-6 + (1.0 - 2e-6) * s;
        return grownBall(g, p, ((1.0 - t) * from + t * to).normalized());
      });
    }
    // A ball of three touches found on a walk, put on its seam and traced unless known.
    auto attempt = [&](const MedialBall3D& at, int g, int h) {
      MedialBall3D seamBall;
      seamBall.generators = { at.generators[0], g, h };
      seamBall.q = { at.q[0] };
      for (int other : { g, h })
      {
        const Generator3D& gen = Generators[other];
        const Vec3 foot = gen.nearestPoint(at.x);
        seamBall.q.push_back(gen.kind() == GeneratorKind3D::Face ? gen.parameterOf(foot) : gen.touchParameter(foot, at.x));
      }
      seamBall.x = at.x;
      seamBall.r = at.r;
      bool inside = System.correct(seamBall, Solve) && (seamBall.x - at.x).norm() <= 1e-4 * Size && empty(seamBall);
      for (int i = 0; i < 3 && inside; ++i)
        inside = Generators[seamBall.generators[i]].exitSide(seamBall.q[i], OnEntity) < 0;
#ifdef EXACTMAT_TRACE3D_DEBUG
      std::fprintf(stderr, "restart seam ball %s inside %d contacts %d traced %d\n", describe(seamBall).c_str(), (int)inside,
        contactCount(seamBall), (int)onTracedSeam(seamBall));
#endif
      if (!inside || contactCount(seamBall) != 3 || onTracedSeam(seamBall))
        return false; // a seam known (or none)
      double separation = 1.0;
      const Eigen::VectorXd t = System.tangent(seamBall, &separation);
      if (separation > 1e-6)
        return false;
      // A restart that fails leaves the trace as it was (the check after the restarts then
      // reports the face, or its sheets' coverage does).
      const MAT3D saved = Result;
      const std::vector<int> savedQueue = Queue;
      const auto savedTraced = Traced;
      const auto savedDepartures = Departures;
      auto restore = [&]() {
        Result = saved;
        Queue = savedQueue;
        Traced = savedTraced;
        Departures = savedDepartures;
        RestartNode = -1;
      };
      MAT3DNode point;
      point.ball = seamBall;
      Result.nodes.push_back(point);
      RestartNode = static_cast<int>(Result.nodes.size()) - 1;
      const size_t first = Result.seams.size();
      bool loop = false;
      try
      {
        trace(RestartNode, seamBall, t, 3);
        loop = Result.seams.size() > first && Result.seams.back().endNode == RestartNode;
        if (!loop)
          trace(RestartNode, seamBall, -t, 3);
      }
      catch (const InputError&)
      {
        restore();
        return false;
      }
      const int restart = RestartNode;
      RestartNode = -1;
      if (loop)
      {
        Result.nodes[restart].loopPoint = true; // a closed seam through the restart point
        return true;
      }
      std::vector<int> halves;
      for (size_t i = first; i < Result.seams.size(); ++i)
        if (Result.seams[i].startNode == restart)
          halves.push_back(static_cast<int>(i));
      if (halves.size() != 2)
      {
        restore();
        return false;
      }
      // One seam from the far end of the first half to the far end of the second.
      const MAT3DSeam& a = Result.seams[halves[0]];
      const MAT3DSeam& b = Result.seams[halves[1]];
      MAT3DSeam joined;
      joined.touchpoints = 3;
      joined.balls.assign(a.balls.rbegin(), a.balls.rend());
      joined.balls.insert(joined.balls.end(), b.balls.begin() + 1, b.balls.end());
      joined.balls.front().generators.resize(3); // the arriving triplet, as a seam's start
      joined.balls.front().q.resize(3);
      joined.faces = { joined.balls.front().generators[0], joined.balls.front().generators[1],
        joined.balls.front().generators[2] };
      joined.startNode = a.endNode;
      joined.endNode = b.endNode;
      Result.seams[halves[0]] = std::move(joined);
      Result.seams.erase(Result.seams.begin() + halves[1]);
      Spliced.insert(restart);
      return true;
    };
    for (const auto& leg : legs)
    {
      double s0 = 0.0;
      std::vector<int> seen;
      for (int k = 0; k <= samples; ++k)
      {
        if (exhausted())
          return false;
        const double s1 = static_cast<double>(k) / samples;
        const MedialBall3D after = leg(s1);
        const std::vector<int> now = othersTouching(after);
#ifdef EXACTMAT_TRACE3D_DEBUG
        std::fprintf(stderr, "restart face %d walk %zu s %g: %s; others", face, w, s1, describe(after).c_str());
        for (int o : now)
          std::fprintf(stderr, " %d", o);
        std::fprintf(stderr, "\n");
#endif
        // A sample touching two others is on a seam already (a wall's middle equidistant
        // from a plate's faces); else bisect where the one other entity changes.
        if (now.size() == 2 && attempt(after, now[0], now[1]))
          return true;
        if (k > 0 && seen.size() == 1 && now.size() == 1 && seen != now)
        {
          double lo = s0, hi = s1;
          MedialBall3D at = after;
          for (int b = 0; b < 50 && !exhausted(); ++b)
          {
            const double mid = 0.5 * (lo + hi);
            const MedialBall3D m = leg(mid);
            if (othersTouching(m) == seen)
              lo = mid;
            else
            {
              hi = mid;
              at = m;
            }
          }
          if (attempt(at, seen.front(), now.front()))
            return true;
        }
        s0 = s1;
        seen = now;
      }
    }
  }
  return false;
}

// A face entering a ball that touches the boundary tangentially (osculating a face at a
// point, or along a circle), or −1 when it is empty: tested against the ball smaller by
// 1e-6 of its radius, the tangency itself left out.
int Tracer::enteringFace(const Vec3& x, double r) const
{
  const double radius = r * (1.0 - 1e-6) - Margin;
  for (int f : Tree.candidatesWithin(x, radius))
    if (Generators[f].polygon() ? Generators[f].distance(x) < radius : patchComesWithin(B.faces()[f].patch, x, radius))
      return f;
  return -1;
}

int Tracer::smoothNeighbour(int face, int side) const
{
  const auto it = SideEdge.find({ face, side });
  if (it == SideEdge.end() || B.edges()[it->second].kind != VertexKind::Smooth)
    return -1;
  const Edge3D& e = B.edges()[it->second];
  return e.faceA == face ? e.faceB : e.faceA;
}

// The centre curves of the canal faces (CentreCurve.h). Each end is a node of its own: a
// ball touching a whole circle, and — where the curve stopped because the ball reached
// another entity — that entity too (a cylinder's cap at the apex of its cone sheet). A
// closed curve (a torus' core) starts and ends at a loop point.
// The boundary, the scale and the step controls, for the rim and centre curve searches.
void Tracer::prepare(FaceCurveSearch& search) const
{
  search.boundary = &B;
  search.generators = &Generators;
  search.size = Size;
  search.tolerance = Options.tolerance;
  search.maxStep = Options.maxStep;
  search.maxSteps = Options.maxStepsPerSeam;
  search.smoothNeighbour = [this](int face, int side) { return smoothNeighbour(face, side); };
  search.toUser = [this](const Vec3& x) { return B.userPoint(x); };
}

void Tracer::addCentreCurves()
{
  CentreCurveSearch search;
  prepare(search);
  search.entering = [this](const Vec3& x, double r) { return enteringFace(x, r); };
  const double onFace = 1e-7 * Size;
  for (const CentreCurve& curve : traceCentreCurves(search))
  {
    MAT3DCentreCurve out;
    const size_t n = curve.balls.size();
    std::set<int> faces;
    for (size_t i = 0; i < n; ++i)
    {
      const CircleBall& c = curve.balls[i];
      MedialBall3D ball;
      ball.generators = { c.face };
      ball.q = { c.q };
      ball.x = c.x;
      ball.r = c.r;
      out.balls.push_back(ball);
      // The faces the circle lies on (those not known yet asked for their exact distance).
      for (const Vec3& p : contactCircle(Generators[c.face], c.q, c.x, 16))
        for (int f : Tree.candidatesWithin(p, onFace))
          if (!faces.count(f) && Generators[f].distance(p) <= onFace)
            faces.insert(f);
    }
    faces.insert(curve.balls.front().face);
    out.faces.assign(faces.begin(), faces.end());
    auto endNode = [&](const CircleBall& c, bool blocked) {
      MAT3DNode node;
      node.ball.generators = { c.face };
      node.ball.q = { c.q };
      node.ball.x = c.x;
      node.ball.r = c.r;
      node.circleEnd = true;
      // The other entities at the ball's surface (within 1e-6 of its radius: the end is
      // bisected to 1e-13 of the size, the faces' closest points are exact) — the faces
      // its circle lies on too, where they touch it off the circle.
      MedialBall3D touching = node.ball;
      int planar = 0;
      for (int f : Tree.candidatesWithin(c.x, c.r * (1.0 + 1e-6)))
        if (f != c.face && (blocked ? !faces.count(f) : true) && Generators[f].distance(c.x) <= c.r * (1.0 + 1e-6))
        {
          touching.generators.push_back(f);
          touching.q.push_back(Generators[f].parameterOf(Generators[f].nearestPoint(c.x)));
          planar += Generators[f].planar() ? 1 : 0;
        }
      // (An end touching three planar faces may start seams: a rounded box has no convex
      // vertex; its seams start where the spines of its fillets meet, at the centres of the
      // spheres that blend its corners, touching the faces the blends join at the corners
      // of their octants. Elsewhere an end that stopped where its face does touches only
      // its circle.)
      // Such an end is one node with the other curves ending there (a corner's three).
      if (planar >= 3)
      {
        const int at = addNode(touching, -1);
        Result.nodes[at].circleEnd = true;
        return at;
      }
      if (blocked)
        node.ball = touching;
      Result.nodes.push_back(node);
      return static_cast<int>(Result.nodes.size()) - 1;
    };
    if (curve.closed)
    {
      out.startNode = out.endNode = endNode(curve.balls.front(), false);
      Result.nodes.back().loopPoint = true;
    }
    else
    {
      out.startNode = endNode(curve.balls.front(), curve.frontBlocked);
      out.endNode = endNode(curve.balls.back(), curve.backBlocked);
    }
    Result.centreCurves.push_back(std::move(out));
  }
}

// A ball (every face on one sphere: BoundarySphere.h) has no seam, rim or centre curve:
// its MAT is its centre, one node whose ball touches every face (recorded at each face's
// middle). The faces are held to the sphere within what the input is known to.
bool Tracer::addSphereCentre()
{
  const std::optional<BoundarySphere> sphere = boundarySphere(B, std::max(Solve, Degenerate));
  if (!sphere)
    return false;
  MAT3DNode node;
  node.sphereCentre = true;
  node.ball.x = sphere->centre;
  node.ball.r = sphere->radius;
  for (int f = 0; f < static_cast<int>(B.faces().size()); ++f)
  {
    node.ball.generators.push_back(f);
    node.ball.q.push_back(Vec2(0.5, 0.5));
    node.ball.touches.push_back(Generators[f].evaluate(Vec2(0.5, 0.5)).point);
  }
  Result.nodes.push_back(std::move(node));
  for (const Generator3D& g : Generators)
    Result.generators.push_back({ g.kind(), g.entity(), g.faces() });
  if (Options.progress)
    Options.progress(1.0);
  return true;
}

// The rims of the curved faces (Rim.h). A closed rim is a skeletal edge from and to a
// point of its own (a loop point, as a closed seam has); a rim that ends — on a seam, at a
// fin point, or at a sharp edge — is refused: rims meeting seams are not traced yet.
void Tracer::addRims()
{
  RimSearch search;
  prepare(search);
  search.empty = [this](const Vec3& x, double r) { return emptyOfAll(x, r); };
  for (const Rim& rim : traceRims(search))
  {
    const RimBall& start = rim.balls.front();
    if (!rim.closed)
      fail("3D MAT: the rim (skeletal edge) through ", format(B.userPoint(start.x)), " on ", Generators[start.face].name(),
        " ends: ", rim.end, ". Rims that meet seams are not traced yet");
    MAT3DSkeletalEdge edge;
    edge.generators = { start.face, start.face };
    for (const RimBall& r : rim.balls)
    {
      MedialBall3D ball;
      ball.generators = { r.face };
      ball.q = { r.q };
      ball.x = r.x;
      ball.r = r.r;
      edge.balls.push_back(ball);
    }
    MAT3DNode node;
    node.ball = edge.balls.front();
    node.loopPoint = true;
    Result.nodes.push_back(node);
    edge.startNode = edge.endNode = static_cast<int>(Result.nodes.size()) - 1;
    Result.skeletalEdges.push_back(std::move(edge));
  }
}

MAT3D Tracer::run()
{
  for (int v = 0; v < static_cast<int>(B.vertices().size()); ++v)
  {
    // Seams start where a convex edge does: at convex vertices and at corners where convex
    // and reflex edges meet (outgoing() keeps the triplets whose seam enters the solid).
    const Vertex3D& vertex = B.vertices()[v];
    if (!hasEdgeOfKind(v, VertexKind::Convex))
      continue;
    MedialBall3D ball;
    for (int e : vertex.edges)
      for (int f : { B.edges()[e].faceA, B.edges()[e].faceB })
        if (std::find(ball.generators.begin(), ball.generators.end(), f) == ball.generators.end())
        {
          ball.generators.push_back(f);
          ball.q.push_back(Generators[f].parameterOf(vertex.point));
        }
    ball.x = vertex.point;
    ball.r = 0.0;
    addNode(ball, v);
  }
  // (A ball before its rims and circles: every point of a sphere is umbilic, where the
  // principal directions those searches follow are undefined.)
  if (Result.nodes.empty() && addSphereCentre())
    return std::move(Result);
  addRims();
  addCentreCurves();
  if (Result.nodes.empty())
    fail("3D MAT: the solid has no convex vertex, no rim and no circle of contact: starting elsewhere (a seam "
         "no vertex leads to, on a solid with curved faces) is not supported yet");
  size_t started = 0;
  for (; started < Queue.size(); ++started)
    startFrom(Queue[started]);
  // Every face bounds some sheet, and (for the solids traced here) every sheet has a seam
  // on its border: a face no seam touches means a part of the MAT this tracer cannot
  // reach yet (sheets bounded only by circles of contact, rims or skeletal edges: the
  // cylinder's disks). Say so rather than return a partial MAT.
  // Faces meeting at smooth edges count as one (a planar face split into triangles: a
  // triangle in its middle may be touched only by sheet points).
  const int faces = static_cast<int>(B.faces().size());
  std::vector<int> group(faces);
  for (int f = 0; f < faces; ++f)
    group[f] = f;
  std::function<int(int)> root = [&](int f) { return group[f] == f ? f : group[f] = root(group[f]); };
  for (const Edge3D& e : B.edges())
    if (e.kind == VertexKind::Smooth)
      group[root(e.faceA)] = root(e.faceB);
  std::vector<bool> touched(faces, false);
  auto markTouched = [&]() {
    for (const MAT3DSeam& seam : Result.seams)
      for (const MedialBall3D& ball : seam.balls)
        for (int g : ball.generators)
          for (int f : Generators[g].faces())
            touched[root(f)] = true;
    for (const MAT3DSkeletalEdge& rim : Result.skeletalEdges)
      for (const MedialBall3D& ball : rim.balls)
        for (int g : ball.generators)
          touched[root(g)] = true;
    for (const MAT3DCentreCurve& curve : Result.centreCurves)
    {
      for (int f : curve.faces)
        touched[root(f)] = true;
      for (int n : { curve.startNode, curve.endNode })
        for (int g : Result.nodes[n].ball.generators)
          for (int f : Generators[g].faces())
            touched[root(f)] = true;
    }
  };
  markTouched();
  // A face no seam touches yet is tried once as a restart (each finds one seam; the
  // junctions on it lead to the others): a short cylinder's circular seam, a plate's seams
  // along its walls and round its holes, which no convex vertex leads to.
  for (int f = 0; f < faces; ++f)
    if (!touched[root(f)] && root(f) == f && restartFrom(f))
    {
      for (; started < Queue.size(); ++started)
        startFrom(Queue[started]);
      markTouched();
    }
  // A planar face bounded by reflex edges only (a cavity's or pocket's wall) is exempt when
  // seams reach its shell: its sheets are bounded where their touch reaches those edges and
  // go on as the edges' sheets, which the sheet interpolator finds from the traced ones
  // (transitionSheets); what it cannot find, its face coverage check reports. A shell no
  // seam reaches at all (a small cavity inside a sheet, ringed by a loop of seams that
  // nothing leads to from the convex vertices) is still refused.
  std::vector<int> shell(faces);
  for (int f = 0; f < faces; ++f)
    shell[f] = f;
  std::function<int(int)> shellOf = [&](int f) { return shell[f] == f ? f : shell[f] = shellOf(shell[f]); };
  for (const Edge3D& e : B.edges())
    shell[shellOf(e.faceA)] = shellOf(e.faceB);
  std::vector<bool> shellTouched(faces, false);
  for (int f = 0; f < faces; ++f)
    if (touched[root(f)])
      shellTouched[shellOf(f)] = true;
  std::vector<bool> walled(faces, true);
  for (int f = 0; f < faces; ++f)
    walled[f] = Generators[f].planar();
  for (const Edge3D& e : B.edges())
    if (e.kind != VertexKind::Reflex && root(e.faceA) != root(e.faceB))
      walled[e.faceA] = walled[e.faceB] = false;
  for (int f = 0; f < faces; ++f)
    if (!walled[f])
      walled[root(f)] = false;
  for (int f = 0; f < faces; ++f)
    if (!touched[root(f)] && !(walled[root(f)] && shellTouched[shellOf(f)]))
      fail("3D MAT: no seam touches ", B.faces()[f].name(),
        ": its sheets are bounded only by edges, circles of contact or skeletal edges, which are not traced yet");
  // Corners where convex and reflex edges meet are tried as starts; those no seam leaves
  // are no node (a sheet reaches them, no seam does).
  std::vector<int> seamsAt(Result.nodes.size(), 0), renumber(Result.nodes.size(), -1);
  for (const MAT3DSeam& seam : Result.seams)
  {
    ++seamsAt[seam.startNode];
    ++seamsAt[seam.endNode];
  }
  for (const MAT3DSkeletalEdge& rim : Result.skeletalEdges)
  {
    ++seamsAt[rim.startNode];
    ++seamsAt[rim.endNode];
  }
  for (const MAT3DCentreCurve& curve : Result.centreCurves)
  {
    ++seamsAt[curve.startNode];
    ++seamsAt[curve.endNode];
  }
  std::vector<MAT3DNode> kept;
  for (size_t n = 0; n < Result.nodes.size(); ++n)
    if (seamsAt[n] > 0 || (Result.nodes[n].vertex < 0 && !Spliced.count(static_cast<int>(n))))
    {
      renumber[n] = static_cast<int>(kept.size());
      kept.push_back(std::move(Result.nodes[n]));
    }
  Result.nodes = std::move(kept);
  for (MAT3DSeam& seam : Result.seams)
  {
    seam.startNode = renumber[seam.startNode];
    seam.endNode = renumber[seam.endNode];
  }
  for (MAT3DSkeletalEdge& rim : Result.skeletalEdges)
  {
    rim.startNode = renumber[rim.startNode];
    rim.endNode = renumber[rim.endNode];
  }
  for (MAT3DCentreCurve& curve : Result.centreCurves)
  {
    curve.startNode = renumber[curve.startNode];
    curve.endNode = renumber[curve.endNode];
  }
  // A junction's touchpoints: its generators' touches, those at one point counted once
  // (coplanar faces meeting at a smooth edge under the ball, a face at a reflex edge).
  for (MAT3DNode& node : Result.nodes)
  {
    Vec3List points;
    for (int i = 0; i < node.ball.size(); ++i)
    {
      const Vec3 p = Generators[node.ball.generators[i]].evaluate(node.ball.q[i]).point;
      bool seen = false;
      for (const Vec3& other : points)
        seen = seen || (other - p).norm() <= 1e-7 * Size;
      if (!seen)
        points.push_back(p);
    }
    node.touchpoints = static_cast<int>(points.size());
  }
  // Every ball's touch points, for the output.
  auto record = [this](MedialBall3D& ball) {
    ball.touches.clear();
    for (int i = 0; i < ball.size(); ++i)
      ball.touches.push_back(Generators[ball.generators[i]].evaluate(ball.q[i]).point);
  };
  for (MAT3DNode& node : Result.nodes)
    record(node.ball);
  for (MAT3DSeam& seam : Result.seams)
    for (MedialBall3D& ball : seam.balls)
      record(ball);
  for (MAT3DSkeletalEdge& rim : Result.skeletalEdges)
    for (MedialBall3D& ball : rim.balls)
      if (rim.vertex >= 0)
        ball.touches = { B.vertices()[rim.vertex].point };
      else
        record(ball);
  for (MAT3DCentreCurve& curve : Result.centreCurves)
    for (MedialBall3D& ball : curve.balls)
      record(ball);
  collectSheets();
  for (const Generator3D& g : Generators)
    Result.generators.push_back({ g.kind(), g.entity(), g.faces() });
  return std::move(Result);
}
} // namespace

std::vector<std::string> MAT3D::topologyProblems(const std::function<Vec3(const Vec3&)>& toUser) const
{
  std::vector<int> degree(nodes.size(), 0);
  std::vector<bool> degenerate(nodes.size(), false); // a degenerate seam (> 3 touches) ends here
  for (const MAT3DSeam& s : seams)
  {
    ++degree[s.startNode];
    ++degree[s.endNode];
    if (s.touchpoints > 3)
      degenerate[s.startNode] = degenerate[s.endNode] = true;
  }
  for (const MAT3DSkeletalEdge& r : skeletalEdges)
  {
    ++degree[r.startNode];
    ++degree[r.endNode];
  }
  for (const MAT3DCentreCurve& c : centreCurves)
  {
    ++degree[c.startNode];
    ++degree[c.endNode];
  }
  std::vector<std::string> problems;
  for (size_t n = 0; n < nodes.size(); ++n)
  {
    const MAT3DNode& node = nodes[n];
    // A junction of four touchpoints is where the four seams of its triplets meet (unless a
    // degenerate seam, along which all four keep touching, stands for several of them: then
    // at least two); a seam's end on a rim joins one seam and one rim; a vertex starts at
    // least one.
    // (A centre curve's end: at least that curve.)
    if (node.sphereCentre)
    {
      if (degree[n] != 0 || nodes.size() != 1)
        problems.push_back("the ball's centre at " + format(toUser(node.ball.x)) + " is not the whole MAT");
      continue;
    }
    if (node.circleEnd)
    {
      if (degree[n] < 1)
        problems.push_back("the centre curve's end at " + format(toUser(node.ball.x)) + " meets no curve");
      continue;
    }
    const int expected = node.vertex >= 0 || degenerate[n] ? -1
      : node.seamEnd || node.loopPoint                    ? 2
      : node.touchpoints == 4                             ? 4
                                                          : -1;
    const bool wrong = node.vertex >= 0 ? degree[n] < 1
      : expected > 0                    ? degree[n] != expected
                                        : degree[n] < (degenerate[n] ? 2 : 4);
    if (wrong)
      problems.push_back(std::string(node.vertex >= 0 ? "the vertex"
            : node.seamEnd                             ? "the seam end"
            : node.loopPoint                           ? "the closed seam's point"
                                                       : "the junction") +
        " at " + format(toUser(node.ball.x)) + " meets " + std::to_string(degree[n]) + " seams or rims" +
        (expected > 0 ? ", " + std::to_string(expected) + " expected" : ""));
  }
  return problems;
}

int MAT3D::junctionCount() const
{
  return static_cast<int>(
    std::count_if(nodes.begin(), nodes.end(), [](const MAT3DNode& n) {
      return n.vertex < 0 && !n.seamEnd && !n.loopPoint && !n.circleEnd && !n.sphereCentre;
    }));
}

MedialComplex MAT3D::complex() const
{
  MedialComplex c;
  for (const MAT3DNode& n : nodes)
  {
    MedialPoint3D p;
    p.x = n.ball.x;
    p.radius = n.ball.r;
    p.type = n.sphereCentre             ? MedialPoint3DType::SphereCentre
      : n.circleEnd                ? MedialPoint3DType::CircleCentre
      : n.loopPoint                ? (n.touchpoints == 1 ? MedialPoint3DType::SkeletalEdge : MedialPoint3DType::Seam)
      : n.vertex >= 0 || n.seamEnd ? MedialPoint3DType::SeamEnd
                                   : MedialPoint3DType::Junction;
    // (A ball touching a whole circle has no count of touchpoints: its distance is checked.)
    p.contacts = n.vertex >= 0 || n.circleEnd || n.sphereCentre ? 0 : n.touchpoints;
    p.touches = n.ball.touches;
    c.points.push_back(p);
    if (n.sphereCentre)
    {
      MedialElement e;
      e.type = MedialElementType::SphereCentre;
      e.points = { static_cast<int>(c.points.size()) - 1 };
      e.governors = n.ball.generators;
      c.elements.push_back(e);
      continue;
    }
    if (n.vertex < 0 && !n.seamEnd && !n.loopPoint && !n.circleEnd)
    {
      MedialElement e;
      e.type = MedialElementType::Junction;
      e.points = { static_cast<int>(c.points.size()) - 1 };
      e.governors = n.ball.generators;
      c.elements.push_back(e);
    }
  }
  // A polyline element from node to node through its inner balls' points.
  auto addCurve = [&c](MedialElementType type, std::vector<int> governors, int startNode, int endNode,
                    const std::vector<MedialBall3D>& balls, MedialPoint3DType pointType, int contacts) {
    MedialElement e;
    e.type = type;
    e.governors = std::move(governors);
    e.points.push_back(startNode);
    for (size_t i = 1; i + 1 < balls.size(); ++i)
    {
      MedialPoint3D p;
      p.x = balls[i].x;
      p.radius = balls[i].r;
      p.type = pointType;
      p.contacts = contacts;
      p.touches = balls[i].touches;
      c.points.push_back(p);
      e.points.push_back(static_cast<int>(c.points.size()) - 1);
    }
    e.points.push_back(endNode);
    c.elements.push_back(e);
  };
  for (const MAT3DSeam& s : seams)
    addCurve(MedialElementType::Seam, { s.faces[0], s.faces[1], s.faces[2] }, s.startNode, s.endNode, s.balls,
      MedialPoint3DType::Seam, s.touchpoints);
  for (const MAT3DSkeletalEdge& rim : skeletalEdges)
    addCurve(MedialElementType::SkeletalEdge, { rim.generators[0], rim.generators[1] }, rim.startNode, rim.endNode,
      rim.balls, MedialPoint3DType::SkeletalEdge, 1);
  // (A ball touching a whole circle has no count of touchpoints: its distance is checked.)
  for (const MAT3DCentreCurve& curve : centreCurves)
    addCurve(MedialElementType::CentreCurve, curve.faces, curve.startNode, curve.endNode, curve.balls,
      MedialPoint3DType::CircleCentre, 0);
  return c;
}

MAT3D computeMAT3D(const Boundary3D& boundary, const MAT3DOptions& options)
{
  return Tracer(boundary, options).run();
}

} // namespace exactmat

#pragma once
/// @file Generators.h
/// @brief The boundary of a planar domain as MAT generators (thesis ch. 4): edges, and
/// reflex corners as zero-radius circular arcs parameterised by the normal angle
/// (§4.3.4), in loop order, with exact distance and footpoint queries.
///
/// A boundary location is (generator, s) with s ∈ [0,1]. For an edge, s is the Bézier
/// parameter; for a reflex corner, the inward normal turns from the incoming edge's end
/// normal to the outgoing edge's start normal as s goes 0 → 1. Moving forward (increasing
/// s, then on to the next generator) keeps the material on the left.

#include "brep/Boundary2D.h"
#include "geometry/BoundingVolumeHierarchy.h"
#include "geometry/ConicCarrier.h"

#include <optional>

#include <string>
#include <vector>

namespace exactmat
{

enum class GeneratorKind
{
  Edge,
  ReflexCorner
};

/// Position, inward unit normal and their derivatives with respect to s.
struct GeneratorPoint
{
  Vec2 p = Vec2::Zero(), n = Vec2::Zero();
  Vec2 dp = Vec2::Zero(), dn = Vec2::Zero();
  double curvature = 0.0; ///< signed curvature (> 0 turning left); +∞ for a corner
};

/// What a straight stretch of disks meets (Generators::firstContact).
enum class SweepContact
{
  Clear,     ///< no boundary point enters any of its disks
  Contact,   ///< the boundary enters first at the parameter returned
  Undecided  ///< a curved edge is near: no closed form (test disks one by one instead)
};

struct Generator
{
  GeneratorKind kind = GeneratorKind::Edge;
  int edge = -1;   ///< Boundary2D edge (Edge)
  int vertex = -1; ///< Boundary2D vertex (ReflexCorner)
  int loop = -1;
  int next = -1, prev = -1; ///< neighbouring generators along the loop
  /// What lies at s = 1 between this generator and `next` (and at s = 0 with `prev`):
  /// Convex stops a front; Smooth and Reflex (a corner generator follows) let it go on.
  VertexKind endJunction = VertexKind::Smooth, startJunction = VertexKind::Smooth;
  double angle0 = 0.0, sweep = 0.0; ///< ReflexCorner: normal angle at s = 0 and its change
  int entity = -1; ///< the user entity (edges), or −1
  bool straight = false; ///< Edge of degree 1 with uniform weights (a polygon's edge)
};

/// A place on the boundary: generator g, parameter s, and the point.
struct BoundaryLocation
{
  int g = -1;
  double s = 0.0;
  Vec2 point = Vec2::Zero();
  Vec2 normal = Vec2::Zero(); ///< inward normal there (for corners: towards the query)
  bool continuum = false; ///< the whole edge is at this distance (query at an arc centre)
};

class Generators
{
public:
  explicit Generators(const Boundary2D& boundary);

  const Boundary2D& boundary() const { return *Boundary; }
  int size() const { return static_cast<int>(List.size()); }
  const Generator& operator[](int g) const { return List[g]; }
  double size2D() const { return Boundary->diagonal(); }
  /// "(x, y, z)": a point of the domain's frame where the user sees it, for messages.
  std::string describe(const Vec2& x) const;

  GeneratorPoint evaluate(int g, double s) const;

  /// Distance from x to the whole boundary (exact, global); `nearest`, if given, receives
  /// a boundary point at that distance.
  double distance(const Vec2& x, Vec2* nearest = nullptr) const;
  /// Generator g is a straight edge (degree 1, uniform weights).
  bool straight(int g) const;

  /// True when some boundary point lies strictly inside the disk of `radius` about x:
  /// the emptiness test of a maximal disk, exact and cheaper than distance().
  bool anyCloserThan(const Vec2& x, double radius) const;
  /// The same, told where the disk touches generators `touchA` and `touchB` (parameters
  /// `sa`, `sb`; a tracing step's two footpoints): the same answer, found faster on curved
  /// generators (see curveComesWithin).
  bool anyCloserThan(const Vec2& x, double radius, int touchA, double sa, int touchB, double sb) const;

  /// Every footpoint of x within `radius` (local minima of the distance on the edges, and
  /// reflex corners whose normal cone contains the direction to x), merged where they
  /// coincide (a minimum at an edge's end belongs to the corner or vertex there).
  std::vector<BoundaryLocation> footpointsWithin(const Vec2& x, double radius) const;

  /// Disks whose centres run straight from x0 to x1 while their radii change linearly from
  /// r0 to r1 (the bisector of two straight edges: touching them all along, so generators
  /// `touchA` and `touchB` are left out): the least t ∈ [0, 1] at which the disk of centre
  /// x0 + t (x1 − x0) and radius r0 + t (r1 − r0) has a boundary point strictly inside, in
  /// closed form for straight edges (a line: linear in t; an end point: a quadratic) — so
  /// a whole segment between two lines is checked by one sweep, with nothing between two
  /// samples left unseen. Undecided when a curved edge comes within the sweep's reach, or
  /// when the radius changes as fast as the centre moves (no MAT segment does).
  ///
  /// `endsEmpty` ≥ 0 says both end disks (of the radii given) are known to be empty and
  /// stay this much inside the touched lines (the margin taken off their radii): then only
  /// what the sweep covers beyond them is searched — two
  /// slivers along the touched lines, each within the triangle of the lines' feet of x0
  /// and x1 and the end circles' crossing next to that line — so a step onto a node found
  /// before (a regular polygon's centre, reached from every side) costs the edges near its
  /// two lines, not every edge the node's disk reaches.
  SweepContact firstContact(const Vec2& x0, double r0, const Vec2& x1, double r1, int touchA, int touchB,
    double& t, double endsEmpty = -1.0) const;

  /// The reflex-corner generator at Boundary2D vertex v, or −1.
  int cornerAtVertex(int v) const { return CornerOfVertex[v]; }
  /// The generator of Boundary2D edge e.
  int generatorOfEdge(int e) const { return GeneratorOfEdge[e]; }

private:
  const Boundary2D* Boundary;
  std::vector<Generator> List;
  std::vector<int> CornerOfVertex, GeneratorOfEdge;
  BoundingVolumeHierarchy Tree;
  std::vector<int> ItemEdge; ///< the edge of each of the tree's items (an edge or a piece of one)
  /// The ellipse or circle each elliptic arc lies on: a disk it proves every point of the
  /// conic to stay outside needs no Bernstein test of the arc.
  std::vector<std::optional<ConicCarrier>> Carriers;
  bool staysOutside(int e, const Vec3& q, double radius) const
  {
    return Carriers[e] && Carriers[e]->distanceLowerBound(q) >= radius;
  }
};

} // namespace exactmat

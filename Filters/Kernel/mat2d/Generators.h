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
};

} // namespace exactmat

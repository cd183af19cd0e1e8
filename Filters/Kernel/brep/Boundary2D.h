#pragma once
/// @file Boundary2D.h
/// @brief The B-rep of a planar domain: edges (rational Bézier curves), loops, vertices.
///
/// Built from unordered Bézier pieces (the cells of a vtkUnstructuredGrid, or the pieces of
/// the user's NURBS curves). The builder finds the plane, the loops (from shared point ids
/// or coincident end points), orients every loop so the material is on its left (outer
/// loops counter-clockwise, holes clockwise, decided by nesting), classifies the vertices
/// (thesis §3.2) and rejects bad input with an InputError that names the edge.

#include "brep/Plane.h"
#include "common/Normalisation.h"
#include "nurbs/BezierCurve.h"

#include <string>
#include <vector>

namespace exactmat
{

/// One input piece: a rational Bézier curve in world coordinates, the user entity it came
/// from (EdgeId; −1 = none) and optional ids of its end points (−1 = use coordinates).
struct CurvePiece
{
  BezierCurve curve;
  int entity = -1;
  long long startId = -1, endId = -1;
};

enum class VertexKind
{
  Convex, ///< interior angle < 180°: a MAT segment ends here (thesis §3.2)
  Reflex, ///< interior angle > 180°: a generator of its own (a zero-radius arc)
  Smooth  ///< tangent-continuous: tracing continues onto the next edge
};

const char* toString(VertexKind kind);

struct Edge2D
{
  BezierCurve curve; ///< local frame (z = 0), oriented with the material on its left
  int piece = -1;    ///< index of the input piece
  int entity = -1;   ///< the input piece's entity id
  bool reversed = false; ///< traversed against the input piece's direction
  int loop = -1;
  int startVertex = -1, endVertex = -1;
  /// "edge 3 (entity 1)": how errors and reports name it.
  std::string name() const;
};

struct Vertex2D
{
  Vec3 point = Vec3::Zero(); ///< local frame
  int incoming = -1, outgoing = -1; ///< edges meeting here, in loop order
  VertexKind kind = VertexKind::Smooth;
  /// Signed turning angle from the incoming to the outgoing tangent, radians in (−π, π):
  /// > 0 turns left (convex), < 0 turns right (reflex). Interior angle = π − angle.
  double turningAngle = 0.0;
};

struct Loop2D
{
  std::vector<int> edges; ///< in traversal order
  double signedArea = 0.0; ///< > 0 for outer loops, < 0 for holes (after orientation)
  bool outer = true;
  int parent = -1; ///< innermost loop containing this one (−1: none)
  bool flipped = false; ///< the loop was reversed to put the material on its left
};

class Boundary2D
{
public:
  struct Options
  {
    /// End points closer than this fraction of the bounding-box diagonal are one vertex.
    double pointTolerance = 1e-9;
    /// Vertices whose tangents turn by less than this (radians) are smooth.
    double angularTolerance = 1e-6;
    /// Control points farther than this fraction of the diagonal from the fitted plane
    /// make the input non-planar.
    double planarityTolerance = 1e-9;
    /// The map from the pieces' frame back to the user's (brep/NormalisePieces.h): error
    /// messages and userPoint() report places where the user sees them.
    Normalisation userFrame;
  };

  /// Builds the B-rep; throws InputError for an empty input, invalid pieces (NaN, weights
  /// ≤ 0, zero length), a non-planar boundary, open loops, vertices shared by more than two
  /// edges, cusps, and loops that cross themselves or each other.
  static Boundary2D build(const std::vector<CurvePiece>& pieces, const Options& options);
  static Boundary2D build(const std::vector<CurvePiece>& pieces)
  {
    return build(pieces, Options());
  }

  const Plane& plane() const { return ThePlane; }
  const std::vector<Edge2D>& edges() const { return Edges; }
  const std::vector<Vertex2D>& vertices() const { return Vertices; }
  const std::vector<Loop2D>& loops() const { return Loops; }
  double diagonal() const { return Diagonal; }
  /// A point of the local (plane) frame in the user's frame, and a length likewise.
  Vec3 userPoint(const Vec3& local) const { return UserFrame.toUser(ThePlane.toWorld(local)); }
  Vec3 userPoint(const Vec2& local) const { return userPoint(Vec3(local.x(), local.y(), 0.0)); }
  double userLength(double l) const { return UserFrame.lengthToUser(l); }
  const Normalisation& userFrame() const { return UserFrame; }
  int holeCount() const;
  int countVertices(VertexKind kind) const;

private:
  void findPlane(const std::vector<CurvePiece>& pieces, const Options& options);
  void findLoops(const std::vector<CurvePiece>& pieces, const Options& options);
  void checkIntersections() const;
  void orientLoops();
  void classifyVertices(const Options& options);

  Plane ThePlane;
  Normalisation UserFrame;
  double Diagonal = 0.0;
  std::vector<Edge2D> Edges;
  std::vector<Vertex2D> Vertices;
  std::vector<Loop2D> Loops;
};

} // namespace exactmat

#pragma once
/// @file Boundary3D.h
/// @brief The B-rep of a solid bounded by rational Bézier patches: faces, the edges where
/// they meet, vertices, and their convex / reflex / smooth classification (thesis §3.2).
///
/// Faces are matched along shared boundary curves (conforming input: the two sides agree
/// geometrically, compared at several parameters). Faces are oriented consistently across
/// every shared edge and so that the normals Su×Sv point away from the material: outwards on
/// an outer shell, into the cavity on a shell that lies inside another (a cavity); a face
/// met the other way round is re-parameterised, not rejected.

#include "brep/Boundary2D.h"
#include "nurbs/BezierPatch.h"

#include <optional>
#include <string>
#include <vector>

namespace exactmat
{

/// One input face: a rational Bézier patch (world coordinates) or a triangular one, and the
/// user entity it came from (FaceId; −1 = none).
struct PatchPiece
{
  BezierPatch patch;                 ///< for triangles: BezierPatch::fromTriangle(*triangle)
  std::optional<TriangleNet> triangle;
  int entity = -1;
};

struct Face3D
{
  BezierPatch patch;    ///< oriented: Su×Sv points out of the material
  std::optional<TriangleNet> triangle; ///< oriented the same way when the face is triangular
  int piece = -1, entity = -1;
  bool flipped = false; ///< re-parameterised (u ⇄ v) to point its normal outwards
  std::string name() const;
};

struct Edge3D
{
  int faceA = -1, sideA = -1; ///< side index in BezierPatch's counter-clockwise order
  int faceB = -1, sideB = -1;
  int startVertex = -1, endVertex = -1; ///< along faceA's side direction
  VertexKind kind = VertexKind::Smooth;
  double dihedralAngle = 0.0; ///< angle between the outward normals at the mid-point, radians
};

struct Vertex3D
{
  Vec3 point = Vec3::Zero();
  std::vector<int> edges;
  VertexKind kind = VertexKind::Smooth; ///< reflex if any edge is, else convex if any is
};

class Boundary3D
{
public:
  struct Options
  {
    double pointTolerance = 1e-9;   ///< fraction of the bounding-box diagonal
    double angularTolerance = 1e-6; ///< radians; edges with normals closer are smooth
    /// The map from the user's frame to the frame the pieces are given in (identity when
    /// they are the user's): messages and userPoint() report places where the user sees them.
    Normalisation userFrame;
  };

  /// Throws InputError for an empty input, invalid patches (NaN, weights ≤ 0, collapsed to a
  /// point), open surfaces (a side with no neighbour), edges shared by more than two faces,
  /// and faces that cannot be oriented consistently.
  static Boundary3D build(const std::vector<PatchPiece>& pieces, const Options& options);
  static Boundary3D build(const std::vector<PatchPiece>& pieces)
  {
    return build(pieces, Options());
  }

  const std::vector<Face3D>& faces() const { return Faces; }
  const std::vector<Edge3D>& edges() const { return Edges; }
  const std::vector<Vertex3D>& vertices() const { return Vertices; }
  double diagonal() const { return Diagonal; }
  const Normalisation& userFrame() const { return UserFrame; }
  Vec3 userPoint(const Vec3& p) const { return UserFrame.toUser(p); }
  double volume() const { return Volume; }
  int countEdges(VertexKind kind) const;
  int countVertices(VertexKind kind) const;

private:
  void matchSides(const Options& options);
  void orientFaces();
  void turnCavitiesInwards(const std::vector<std::vector<int>>& shells, std::vector<int>& sign) const;
  void classify(const Options& options);

  std::vector<Face3D> Faces;
  std::vector<Edge3D> Edges;
  std::vector<Vertex3D> Vertices;
  double Diagonal = 0.0;
  double Volume = 0.0;
  Normalisation UserFrame;
};

/// Volume enclosed by oriented faces: (1/3)∮ S·n dA by Gauss quadrature (8×8 per patch).
double enclosedVolume(const std::vector<BezierPatch>& patches);

} // namespace exactmat

#pragma once
/// @file Generator3D.h
/// @brief A boundary entity a medial ball of a solid touches (thesis §6.2 and app. C.1–C.3):
/// a face, a reflex edge or a reflex corner, seen through two parameters q: the touchpoint
/// S(q), the unit normal N(q) pointing into the material, and their derivatives. A ball of
/// radius r touching the entity at q has its centre at S(q) + r·N(q); a seam is where three
/// such centres coincide (BallSystem, with every touchpoint parameter unknown).
///
/// * A face: q are its patch parameters. A planar face is parameterised by orthonormal
///   coordinates in its plane instead: a triangle stored as a patch with a collapsed side
///   still has a regular touchpoint map at its corners (where seams start).
/// * A reflex edge is a zero-radius cylinder: q = (t, θ), the touchpoint C(t) on the edge
///   (face A's side) and the normal N = cos θ·N_A(t) + sin θ·W(t) turning, on the short
///   arc, from face A's normal (θ = 0) to face B's (θ = α(t)), W ⟂ N_A towards N_B. Every
///   ball touching the edge from the material has its normal in that arc.
/// * A reflex corner (every non-smooth edge at the vertex reflex) is a zero-radius sphere:
///   the touchpoint is the vertex and q the gnomonic coordinates of N about an axis inside
///   its normal cone, the directions d with d·τ ≤ 0 for every edge direction τ leaving it.
///
/// So a seam of any three entities is one code path on exact geometry (DESIGN.md §3).

#include "brep/Boundary3D.h"

#include <Eigen/Core>
#include <string>
#include <vector>

namespace exactmat
{

/// A touchpoint and the first derivatives of the touchpoint map.
struct Touch3D
{
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::Zero(); ///< unit, into the material
  Eigen::Matrix<double, 3, 2> dPoint = Eigen::Matrix<double, 3, 2>::Zero();
  Eigen::Matrix<double, 3, 2> dNormal = Eigen::Matrix<double, 3, 2>::Zero();
};

enum class GeneratorKind3D
{
  Face,
  ReflexEdge,
  ReflexCorner
};

class Generator3D
{
public:
  /// Face `face` of `boundary` (which must outlive the generator).
  Generator3D(const Boundary3D& boundary, int face);
  /// Reflex edge `edge` (Boundary3D::edges()).
  static Generator3D reflexEdge(const Boundary3D& boundary, int edge);
  /// The corner at vertex `vertex`, whose non-smooth edges are all reflex.
  static Generator3D reflexCorner(const Boundary3D& boundary, int vertex);

  GeneratorKind3D kind() const { return Kind; }
  /// The face, edge or vertex index, by kind.
  int entity() const { return Entity; }
  /// The faces the entity lies on (the face; the edge's two; every face at the corner):
  /// they pass through the touchpoint without entering the ball.
  const std::vector<int>& faces() const { return Faces; }
  /// A planar face.
  bool planar() const { return Planar; }
  /// A convex planar face with straight sides (distances and inside tests in closed form).
  bool polygon() const { return !Polygon.empty(); }
  Touch3D evaluate(const Vec2& q) const;

  /// Faces: the parameters of the face's point nearest to x (planar: x projected on the
  /// plane). Edges and corners: those of the touchpoint nearest x, the ball's centre taken
  /// as x + (direction of the normal): see touchParameter.
  Vec2 parameterOf(const Vec3& x) const;
  /// The parameters of the touch at `foot` (a point of the entity) of a ball centred at
  /// `centre`: faces ignore the centre; edges and corners take the normal's angle from it.
  Vec2 touchParameter(const Vec3& foot, const Vec3& centre) const;

  /// −1 when the touch at q lies on the entity (within `tolerance`, a length), else the
  /// side crossed. Faces: the patch side (BezierPatch's numbering). Reflex edges: 0 past
  /// face A's normal (θ < 0), 1 past face B's (θ > α), 2 past the start vertex, 3 past the
  /// end vertex. Reflex corners: the index in cornerEdges() of the edge whose normal arc
  /// the normal has crossed.
  int exitSide(const Vec2& q, double tolerance) const;
  /// exitSide(q, tolerance) < 0, without asking which side: a planar face bounded by
  /// curves searches only within the tolerance of the point, not the whole patch.
  bool holds(const Vec2& q, double tolerance) const;

  /// Global distance from x to the entity (closed form for straight-sided planar faces,
  /// straight edges and corners).
  double distance(const Vec3& x) const;
  /// The distance from x when it is below `bound`, else infinity: a curved face is searched
  /// only where it comes within the bound (the nearest of many pieces, one after another).
  double distanceWithin(const Vec3& x, double bound) const;
  /// The entity's point nearest x.
  Vec3 nearestPoint(const Vec3& x) const;

  /// Two planar faces in one plane (normals the same way, the narrower one's control points
  /// within `tolerance` of the wider one's plane): a ball touches their union at one point
  /// at most.
  bool coplanar(const Generator3D& other, double tolerance) const;

  /// Reflex corners: the edges (Boundary3D indices) bounding the normal cone.
  const std::vector<int>& cornerEdges() const { return CornerEdges; }
  /// Reflex corners: the unit directions of those edges leaving the vertex (same order).
  const Vec3List& cornerTangents() const { return CornerTangents; }
  /// Reflex corners: whether the normal cone has an interior (at least three reflex edges,
  /// its axis strictly inside); two collinear reflex edges meeting make none.
  bool cornerHasCone() const;
  /// Reflex edges: the angle α(t) between the faces' normals.
  double edgeAngle(double t) const;

  std::string name() const;

private:
  Generator3D(const Boundary3D& boundary, GeneratorKind3D kind, int entity);
  void setPolygon(const BezierPatch& patch, double size);
  Touch3D evaluateFace(const Vec2& q) const;
  Touch3D evaluateEdge(const Vec2& q) const;
  Touch3D evaluateCorner(const Vec2& q) const;
  /// A face's inward normal and its derivative along the edge's parameter t.
  void edgeNormal(int which, double t, Vec3& normal, Vec3& derivative) const;

  const Boundary3D* Boundary;
  GeneratorKind3D Kind = GeneratorKind3D::Face;
  int Entity = -1;
  std::vector<int> Faces;
  bool Planar = false;
  bool Collapsed[4] = { false, false, false, false }; ///< sides that are a point (triangles)
  /// A convex planar face with straight sides: its corners in plane coordinates, counter-
  /// clockwise, and the patch side of each polygon side (from corner i to i + 1), for
  /// closed-form inside tests and distances. Empty otherwise.
  std::vector<Vec2> Polygon;
  std::vector<int> PolygonSide;
  Vec3 Origin = Vec3::Zero(), Axis0 = Vec3::Zero(), Axis1 = Vec3::Zero(), Inward = Vec3::Zero();
  /// A planar face's plane normal from a wide triangle of its control net (its derivatives'
  /// normal, Inward, is tilted by the rounding over a sliver's width): what planarity and
  /// coplanarity are judged by.
  Vec3 NetNormal = Vec3::Zero();
  double NetWidth = 0.0; ///< the height of the net's triangle that fixes NetNormal

  // Reflex edges: the curve (face A's side, t from the start vertex), and per face (0: A,
  // 1: B) its side, whether it is planar and then its constant normal.
  BezierCurve EdgeCurve;
  bool Straight = false;
  int EdgeSide[2] = { -1, -1 };
  bool EdgePlanar[2] = { false, false };
  Vec3 EdgeFaceNormal[2] = { Vec3::Zero(), Vec3::Zero() };

  // Reflex corners: the vertex (Origin), the cone's axis (Inward) and frame (Axis0, Axis1),
  // and the unit directions of the reflex edges leaving the vertex.
  std::vector<int> CornerEdges;
  Vec3List CornerTangents;
};

/// Every entity a medial ball of the solid can touch, in the numbering the 3D MAT and its
/// sheets share: the faces (generator f = face f), then the reflex edges (in edge order),
/// then the reflex corners (vertices with reflex edges and no convex one) whose normal
/// cone has an interior.
std::vector<Generator3D> medialGenerators(const Boundary3D& boundary);

} // namespace exactmat

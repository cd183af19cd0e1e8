#pragma once
/// @file MAT3D.h
/// @brief The seams and junctions of the MAT of a solid bounded by rational Bézier faces
/// (thesis ch. 6), traced from the convex vertices.
///
/// The generators a ball touches are faces, reflex edges (zero-radius cylinders) and
/// reflex corners (zero-radius spheres), all through Generator3D. Nodes are the balls where
/// seams start and end: convex vertices and corners where convex edges meet reflex ones
/// (radius 0; every face at the vertex touches) and junctions (four or more generators
/// touch). From a node every triplet of its generators whose seam leaves the node into the
/// solid is traced, once: the seam's
/// direction is the null vector of the triplet's ball equations (BallSystem), valid when
/// every other face of the node recedes from the ball along it. A seam is followed by
/// pseudo-arclength continuation with steps controlled by the chord error; after every step
/// the ball is tested for emptiness against the faces outside the triplet (exact Bernstein
/// sign test through the BVH); a ball that is not empty brackets a junction, found by
/// bisection and polished by Newton on the four-(or more-)face system. A seam ends at a
/// junction or at a vertex (r = 0). A touchpoint leaving its entity continues on the one
/// beyond: the neighbour face across a smooth edge, the reflex edge at a face's side (and
/// back onto the other face at the end of its normal arc), the reflex corner at an edge's
/// end (thesis app. C.2–C.3 as one code path).
///
/// Supported today: solids with at least one convex edge ending at a vertex (polyhedra,
/// stepped and notched blocks, free-form solids such as the pillow), closed rims of curved
/// faces (Rim.h: the ellipsoid) and centre curves of canal faces (CentreCurve.h: a
/// cylinder's axis, a torus' core), and a ball (the sphere's centre). Rims that meet seams (fin points), a face touching one
/// ball twice, seams reaching the end of a reflex edge at a corner that also has convex
/// edges, and seams no vertex leads to on curved solids are reported as InputError naming
/// what is missing, never traced wrongly.

#include "mat3d/BallSystem.h"
#include "medial/MedialComplex.h"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace exactmat
{

struct MAT3DOptions
{
  double tolerance = 1e-4; ///< chord deviation of a seam's polyline, fraction of the size
  double maxStep = 0.05;   ///< longest step along a seam (junction-check spacing), fraction
  /// Fixed-step mode (reproduces the thesis): a constant tracing step along the seams and
  /// the spacing of the emptiness (junction) checks, fractions of the size; a junction
  /// found at a check is located back to the step where the ball stopped being empty.
  bool fixedStep = false;
  double step = 1e-3;
  double junctionCheckStep = 1e-2;
  int maxSeams = 100000;
  int maxStepsPerSeam = 200000;
  /// Called after every seam with the fraction of faces reached so far (0 … 1).
  std::function<void(double)> progress;
};

struct MAT3DNode
{
  MedialBall3D ball;     ///< every face touching (r = 0 at a convex vertex)
  int vertex = -1;       ///< the vertex, or −1 for a junction or seam end
  /// A seam's end where two of its touchpoints merge at a vertex of the solid: the seam
  /// meets the skeletal edge (rim) of the sheet between those two generators there.
  bool seamEnd = false;
  /// Where a closed seam that meets no junction starts and ends (a ring of seams about a
  /// small cavity inside a sheet, found by a restart): a point of that seam, not a junction.
  bool loopPoint = false;
  /// Located only to about the square root of the rounding (where a degenerate seam loses a
  /// contact tangentially): a junction reached later within 1e-5 of the size is this one.
  bool imprecise = false;
  /// Where a centre curve ends (its ball touches a whole circle of a face and, where the
  /// curve was stopped by it, another entity: a cone sheet's apex), or a point of a closed
  /// centre curve (loopPoint too).
  bool circleEnd = false;
  /// The centre of a ball that is the whole solid (every face on one sphere: BoundarySphere.h):
  /// the MAT is this one point, its ball touching every face everywhere (generators: every
  /// face, each at its middle).
  bool sphereCentre = false;
  int touchpoints = 0;   ///< distinct points the ball touches (a point touched by two faces once)
  Vec3List directions;   ///< unit directions of the seams leaving / arriving, away from it
};

struct MAT3DSeam
{
  std::array<int, 3> faces{ { -1, -1, -1 } }; ///< the triplet at the seam's start
  int startNode = -1, endNode = -1;
  /// Distinct points each ball touches: 3, more along a degenerate seam (a symmetric solid's
  /// axis, where more generators than the triplet keep touching).
  int touchpoints = 3;
  std::vector<MedialBall3D> balls; ///< from start node to end node, both included
};

/// A skeletal edge (rim) at a vertex: where the sheet between two reflex edges ending at a
/// vertex (a staircase's inner corner) closes, its balls touch the solid at the vertex
/// only, their centres on a straight segment along the normal there, from a seam end
/// (startNode) to the vertex (endNode, radius 0).
struct MAT3DSkeletalEdge
{
  int startNode = -1, endNode = -1;
  int vertex = -1;
  std::array<int, 2> generators{ { -1, -1 } }; ///< the pair whose touchpoints merged
  std::vector<MedialBall3D> balls;             ///< centre and radius only, start to end
};

/// A curve of centres of balls touching a face along a circle (CentreCurve.h): a cylinder's
/// or cone's axis, a torus' core, a fillet's spine; from node to node (the same loop point
/// when closed).
struct MAT3DCentreCurve
{
  int startNode = -1, endNode = -1;
  std::vector<int> faces;          ///< the faces its circles of contact lie on
  std::vector<MedialBall3D> balls; ///< start to end; generators {the tracked touch's face}
};

/// A medial sheet's topology (for vtkSheetInterpolator): its generator pair and the
/// elements bounding it — the seams whose triplet holds both faces, and the convex edges
/// between them (where the sheet reaches the boundary with radius 0).
struct MAT3DSheet
{
  int generatorA = -1, generatorB = -1; ///< indices into MAT3D::generators, A < B
  std::vector<int> seams;      ///< indices into MAT3D::seams
  std::vector<int> convexEdges; ///< indices into Boundary3D::edges()
};

/// A boundary entity medial balls touch. Generator indices (in balls, seams, sheets and
/// the complex's governors) number the faces first (generator f = face f), then the reflex
/// edges, then the reflex corners.
struct MAT3DGenerator
{
  GeneratorKind3D kind = GeneratorKind3D::Face;
  int entity = -1;        ///< face, edge or vertex index in the Boundary3D
  std::vector<int> faces; ///< the faces it lies on (one, the edge's two, the corner's)
};

struct MAT3D
{
  std::vector<MAT3DGenerator> generators;
  std::vector<MAT3DNode> nodes;
  std::vector<MAT3DSeam> seams;
  std::vector<MAT3DSkeletalEdge> skeletalEdges;
  std::vector<MAT3DCentreCurve> centreCurves;
  std::vector<MAT3DSheet> sheets;

  int junctionCount() const;
  /// The graph's own check, independent of the points' verification: a junction of four
  /// touchpoints meets exactly four seams, a seam end on a rim one seam and one rim, a
  /// degenerate junction at least four, a vertex at least one. One sentence per node that
  /// does not (positions through `toUser`); empty when all do.
  std::vector<std::string> topologyProblems(const std::function<Vec3(const Vec3&)>& toUser) const;
  /// Points and elements: a Junction element per junction, a Seam polyline per seam
  /// (sharing the node points), governors = the seam's start triplet of generators; a
  /// SkeletalEdge polyline per skeletal edge (governors: the merged pair); a CentreCurve
  /// polyline of CircleCentre points per centre curve (governors: the faces it touches); a
  /// SphereCentre element of one SphereCentre point for a ball's centre (governors: every face).
  MedialComplex complex() const;
};

/// Throws InputError for what is not supported (see the file comment), naming the entity.
MAT3D computeMAT3D(const Boundary3D& boundary, const MAT3DOptions& options = {});

} // namespace exactmat

#pragma once
/// @file MedialGraph.h
/// @brief The 2D MAT as a graph: nodes (branch points, ends) and simplified segments
/// (polylines of traced MAT points), every point with its radius and footpoints.

#include "mat2d/Generators.h"

#include <vector>

namespace exactmat
{

enum class MedialPointType
{
  Normal = 0,          ///< two footpoints
  Branch = 1,          ///< three or more footpoints
  ConvexVertexEnd = 2, ///< a segment's end at a convex vertex (radius 0)
  CurvatureCentreEnd = 3, ///< a segment's end at the centre of curvature of an LMPC point
  CycleJoint = 4,      ///< a normal point where a cycle of the graph was closed
  CircleCentre = 5     ///< the whole MAT is one point (a circular domain)
};

const char* toString(MedialPointType type);

/// One MAT point: its position (in the domain's plane frame), radius and footpoints.
struct MedialSample
{
  Vec2 x = Vec2::Zero();
  double radius = 0.0;
  BoundaryLocation foot[2]; ///< the two footpoints (the same for ends with one)
};

struct MedialNode
{
  MedialSample sample;
  MedialPointType type = MedialPointType::Normal;
  std::vector<BoundaryLocation> footpoints; ///< all of them (branch points: ≥ 3)
  std::vector<int> segments;                ///< incident segments
};

struct MedialSegment
{
  int startNode = -1, endNode = -1;
  int generators[2] = { -1, -1 }; ///< generators of the first sample (front a, front b)
  std::vector<MedialSample> samples; ///< from start node to end node, both included
};

struct MedialGraph
{
  std::vector<MedialNode> nodes;
  std::vector<MedialSegment> segments;

  /// Joins the two segments at every degree-2 CycleJoint node (where tracing started from
  /// a normal point) so each simplified segment is one polyline; a joint that closes a
  /// cycle on its own segment stays.
  void mergeJoints();

  int count(MedialPointType type) const;
  /// The largest radius over nodes and samples (Rmax).
  double maximumRadius() const;
  /// Independent cycles: segments − nodes + connected components.
  int cycleCount() const;
  /// Connected components (a connected domain has one).
  int componentCount() const;
  int pointCount() const;
};

} // namespace exactmat

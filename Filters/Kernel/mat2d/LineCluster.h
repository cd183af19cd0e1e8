#pragma once
/// @file LineCluster.h
/// @brief The medial tree of straight edges nearly equidistant from one point.
///
/// A regular polygon's centre is one node of degree n. Jitter its vertices, or move it far
/// from the origin so that its coordinates are rounded, and the centre splits into a tree
/// of n − 2 branch points a few 1e-9 of the size apart, joined by segments shorter still —
/// more than a tracer that finds branch points one disk test at a time can resolve.
///
/// Near such a point the distance to each edge's line is affine, r_j(x) = a_j·x + c_j (a_j
/// the inward unit normal), and the MAT is where the least of them is attained twice: the
/// creases of the lower envelope min_j r_j. Its nodes (three lines tie, the others farther)
/// are the faces of the lower convex hull of the lifted normals (a_j, c_j), its edges the
/// hull's inner edges, and its unbounded edges the hull's border. The normals lie on the
/// unit circle, so that hull is the regular triangulation of the points a_j with weights
/// |a_j|² − c_j, which CGAL builds with exact predicates: the tree's combinatorics are the
/// given lines', however close to a tie, and it is a tree by construction.

#include "common/Types.h"

#include <array>
#include <vector>

namespace exactmat
{

/// r(x) = normal · x + offset: a line's distance, positive on its inner side.
struct ClusterLine
{
  Vec2 normal = Vec2::Zero(); ///< unit
  double offset = 0.0;
};

/// Where three lines tie and no other is nearer: a branch point of the tree.
struct ClusterNode
{
  Vec2 x = Vec2::Zero();
  double r = 0.0;                   ///< the three lines' common distance
  std::array<int, 3> lines{ -1, -1, -1 };
};

/// A crease between lines `lineA` and `lineB` from node0 to node1, or from node0 out to
/// infinity (node1 = −1: the lines are neighbours in angle).
struct ClusterEdge
{
  int lineA = -1, lineB = -1;
  int node0 = -1, node1 = -1;
};

struct ClusterTree
{
  std::vector<ClusterNode> nodes;
  std::vector<ClusterEdge> edges;
};

/// The creases of min_j r_j over the whole plane. Lines whose r_j is never the least (a
/// parallel line behind another) take no part. Empty when fewer than three lines with
/// distinct normals are given.
ClusterTree lineClusterTree(const std::vector<ClusterLine>& lines);

} // namespace exactmat

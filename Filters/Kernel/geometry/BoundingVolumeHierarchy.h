#pragma once
/// @file BoundingVolumeHierarchy.h
/// @brief An axis-aligned bounding-box tree over boundary pieces.
///
/// The thesis checks a candidate MAT point against every boundary entity (O(n) a step);
/// this tree answers the two queries the tracer needs in O(log n) for well-spread input:
/// the nearest piece, and every piece that may lie within a distance d of a point.

#include "geometry/ClosestPoint.h"

#include <functional>
#include <vector>

namespace exactmat
{

class BoundingVolumeHierarchy
{
public:
  /// Builds the tree over `boxes` (item i has box i). Median split on the longest axis.
  void build(const std::vector<Box3>& boxes);

  int itemCount() const { return static_cast<int>(Boxes.size()); }

  /// Item whose exact distance to p (given by `exactDistance(i)`) is smallest, and that
  /// distance. Boxes are visited nearest first and pruned by the best distance so far.
  /// Returns −1 for an empty tree.
  int nearest(
    const Vec3& p, const std::function<double(int)>& exactDistance, double* distance) const;

  /// Every item whose box lies within distance d of p (a superset of the items within d;
  /// the caller checks them exactly), in increasing index order.
  std::vector<int> candidatesWithin(const Vec3& p, double d) const;

private:
  struct Node
  {
    Box3 box;
    int first = 0, count = 0; ///< leaf: items Order[first .. first+count)
    int left = -1, right = -1;
  };
  int buildNode(int first, int count, int depth);

  std::vector<Box3> Boxes;
  std::vector<int> Order;
  std::vector<Node> Nodes;
};

} // namespace exactmat

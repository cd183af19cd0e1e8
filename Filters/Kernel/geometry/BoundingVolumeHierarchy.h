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

  /// Calls visit(item) for items whose box lies within distance d of p, in no particular
  /// order, until one returns true; returns whether one did. No allocation: the emptiness
  /// test of every tracing step (is any piece closer than r?) stops at its first hit.
  template <typename Visit>
  bool anyWithin(const Vec3& p, double d, Visit&& visit) const
  {
    if (!(d >= 0.0))
      return false;
    const double d2 = d * d;
    return anyWhere([&](const Box3& box) { return squaredDistanceToBox(box, p) <= d2; }, visit);
  }

  /// The walk of anyWithin for any region: `reaches(box)` is true for every box that meets
  /// it (and may be for others); items' boxes are asked too.
  template <typename Reaches, typename Visit>
  bool anyWhere(Reaches&& reaches, Visit&& visit) const
  {
    if (Nodes.empty())
      return false;
    int stack[2 * MaxTreeDepth + 8];
    int top = 0;
    stack[top++] = 0;
    while (top > 0)
    {
      const Node& node = Nodes[stack[--top]];
      if (node.box.isEmpty() || !reaches(node.box))
        continue;
      if (node.left < 0)
      {
        for (int k = node.first; k < node.first + node.count; ++k)
          if (!Boxes[Order[k]].isEmpty() && reaches(Boxes[Order[k]]) && visit(Order[k]))
            return true;
        continue;
      }
      stack[top++] = node.right;
      stack[top++] = node.left;
    }
    return false;
  }

  /// The tree's depth bound (median splits stop there, whatever the boxes).
  static constexpr int MaxTreeDepth = 64;

private:
  static double squaredDistanceToBox(const Box3& box, const Vec3& p)
  {
    if (box.isEmpty())
      return Unbounded;
    return (box.min() - p).cwiseMax(p - box.max()).cwiseMax(Vec3::Zero()).squaredNorm();
  }

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

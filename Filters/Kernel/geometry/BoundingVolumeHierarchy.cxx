#include "BoundingVolumeHierarchy.h"

#include <algorithm>
#include <queue>

namespace exactmat
{

namespace
{
constexpr int LeafSize = 2;
constexpr int MaxDepth = BoundingVolumeHierarchy::MaxTreeDepth; // bounds the recursion even for many coincident boxes
} // namespace

void BoundingVolumeHierarchy::build(const std::vector<Box3>& boxes)
{
  Boxes = boxes;
  Order.resize(boxes.size());
  for (size_t i = 0; i < boxes.size(); ++i)
  {
    Order[i] = static_cast<int>(i);
  }
  Nodes.clear();
  if (!boxes.empty())
  {
    Nodes.reserve(2 * boxes.size());
    buildNode(0, static_cast<int>(boxes.size()), 0);
  }
}

int BoundingVolumeHierarchy::buildNode(int first, int count, int depth)
{
  const int index = static_cast<int>(Nodes.size());
  Nodes.emplace_back();
  Box3 box, centres;
  for (int k = first; k < first + count; ++k)
  {
    box.extend(Boxes[Order[k]]);
    centres.extend(Boxes[Order[k]].center());
  }
  Nodes[index].box = box;
  if (count <= LeafSize || depth >= MaxDepth)
  {
    Nodes[index].first = first;
    Nodes[index].count = count;
    return index;
  }
  int axis = 0;
  centres.diagonal().maxCoeff(&axis);
  const int half = count / 2;
  std::nth_element(Order.begin() + first, Order.begin() + first + half,
    Order.begin() + first + count, [&](int a, int b) {
      return Boxes[a].center()(axis) < Boxes[b].center()(axis);
    });
  const int left = buildNode(first, half, depth + 1);
  const int right = buildNode(first + half, count - half, depth + 1);
  Nodes[index].left = left;
  Nodes[index].right = right;
  return index;
}

int BoundingVolumeHierarchy::nearest(
  const Vec3& p, const std::function<double(int)>& exactDistance, double* distance) const
{
  int best = -1;
  double bestDistance = Unbounded;
  if (Nodes.empty())
  {
    if (distance)
      *distance = bestDistance;
    return best;
  }
  using Entry = std::pair<double, int>; // (lower bound, node)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  queue.emplace(distanceToBox(Nodes[0].box, p), 0);
  while (!queue.empty())
  {
    const auto [bound, n] = queue.top();
    queue.pop();
    if (bound >= bestDistance)
    {
      break; // every remaining node is at least this far
    }
    const Node& node = Nodes[n];
    if (node.left < 0)
    {
      for (int k = node.first; k < node.first + node.count; ++k)
      {
        const int item = Order[k];
        if (distanceToBox(Boxes[item], p) >= bestDistance)
        {
          continue;
        }
        const double d = exactDistance(item);
        if (d < bestDistance || (d == bestDistance && item < best))
        {
          bestDistance = d;
          best = item;
        }
      }
      continue;
    }
    queue.emplace(distanceToBox(Nodes[node.left].box, p), node.left);
    queue.emplace(distanceToBox(Nodes[node.right].box, p), node.right);
  }
  if (distance)
  {
    *distance = bestDistance;
  }
  return best;
}

std::vector<int> BoundingVolumeHierarchy::candidatesWithin(const Vec3& p, double d) const
{
  std::vector<int> out;
  if (Nodes.empty())
  {
    return out;
  }
  std::vector<int> stack{ 0 };
  while (!stack.empty())
  {
    const Node& node = Nodes[stack.back()];
    stack.pop_back();
    if (distanceToBox(node.box, p) > d)
    {
      continue;
    }
    if (node.left < 0)
    {
      for (int k = node.first; k < node.first + node.count; ++k)
      {
        if (distanceToBox(Boxes[Order[k]], p) <= d)
        {
          out.push_back(Order[k]);
        }
      }
      continue;
    }
    stack.push_back(node.left);
    stack.push_back(node.right);
  }
  std::sort(out.begin(), out.end());
  return out;
}

} // namespace exactmat

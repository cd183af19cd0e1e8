#include "MedialGraph.h"

#include <algorithm>
#include <numeric>

namespace exactmat
{

const char* toString(MedialPointType type)
{
  switch (type)
  {
    case MedialPointType::Normal:
      return "normal";
    case MedialPointType::Branch:
      return "branch";
    case MedialPointType::ConvexVertexEnd:
      return "convex-vertex end";
    case MedialPointType::CurvatureCentreEnd:
      return "centre-of-curvature end";
    case MedialPointType::CycleJoint:
      return "cycle joint";
    default:
      return "circle centre";
  }
}

int MedialGraph::count(MedialPointType type) const
{
  return static_cast<int>(std::count_if(
    nodes.begin(), nodes.end(), [type](const MedialNode& n) { return n.type == type; }));
}

int MedialGraph::cycleCount() const
{
  std::vector<int> parent(nodes.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int a) {
    while (parent[a] != a)
      a = parent[a] = parent[parent[a]];
    return a;
  };
  int components = static_cast<int>(nodes.size());
  for (const MedialSegment& s : segments)
  {
    const int a = find(s.startNode), b = find(s.endNode);
    if (a != b)
    {
      parent[a] = b;
      --components;
    }
  }
  return static_cast<int>(segments.size()) - static_cast<int>(nodes.size()) + components;
}

int MedialGraph::pointCount() const
{
  int n = static_cast<int>(nodes.size());
  for (const MedialSegment& s : segments)
  {
    n += std::max(0, static_cast<int>(s.samples.size()) - 2);
  }
  return n;
}

} // namespace exactmat

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

void MedialGraph::mergeJoints()
{
  std::vector<bool> deadNode(nodes.size(), false), deadSegment(segments.size(), false);
  // Reversing a polyline turns the forward-moving front (foot[0]) into the backward one.
  auto reverse = [](MedialSegment& s) {
    std::reverse(s.samples.begin(), s.samples.end());
    for (MedialSample& m : s.samples)
      std::swap(m.foot[0], m.foot[1]);
    std::swap(s.startNode, s.endNode);
    std::swap(s.generators[0], s.generators[1]);
  };
  for (size_t j = 0; j < nodes.size(); ++j)
  {
    MedialNode& n = nodes[j];
    if (n.type != MedialPointType::CycleJoint || n.segments.size() != 2 ||
      n.segments[0] == n.segments[1])
      continue;
    const int s1 = n.segments[0], s2 = n.segments[1];
    MedialSegment a = std::move(segments[s1]), b = std::move(segments[s2]); // s2 dies
    if (a.endNode != static_cast<int>(j))
      reverse(a);
    if (b.startNode != static_cast<int>(j))
      reverse(b);
    a.samples.insert(a.samples.end(), b.samples.begin() + 1, b.samples.end());
    a.endNode = b.endNode;
    segments[s1] = std::move(a);
    deadSegment[s2] = true;
    deadNode[j] = true;
    // The far end of s2 now belongs to s1.
    for (int& s : nodes[segments[s1].endNode].segments)
      if (s == s2)
        s = s1;
    n.segments.clear();
  }
  // Compact, renumbering nodes and segments.
  std::vector<int> nodeIndex(nodes.size(), -1), segmentIndex(segments.size(), -1);
  std::vector<MedialNode> keptNodes;
  std::vector<MedialSegment> keptSegments;
  for (size_t i = 0; i < nodes.size(); ++i)
    if (!deadNode[i])
    {
      nodeIndex[i] = static_cast<int>(keptNodes.size());
      keptNodes.push_back(std::move(nodes[i]));
    }
  for (size_t i = 0; i < segments.size(); ++i)
    if (!deadSegment[i])
    {
      segmentIndex[i] = static_cast<int>(keptSegments.size());
      keptSegments.push_back(std::move(segments[i]));
    }
  for (MedialSegment& s : keptSegments)
  {
    s.startNode = nodeIndex[s.startNode];
    s.endNode = nodeIndex[s.endNode];
  }
  for (MedialNode& n : keptNodes)
  {
    std::vector<int> incident;
    for (int s : n.segments)
      if (s >= 0 && segmentIndex[s] >= 0)
        incident.push_back(segmentIndex[s]);
    n.segments = incident;
  }
  nodes = std::move(keptNodes);
  segments = std::move(keptSegments);
}

int MedialGraph::count(MedialPointType type) const
{
  return static_cast<int>(std::count_if(
    nodes.begin(), nodes.end(), [type](const MedialNode& n) { return n.type == type; }));
}

int MedialGraph::cycleCount() const
{
  return static_cast<int>(segments.size()) - static_cast<int>(nodes.size()) + componentCount();
}

int MedialGraph::componentCount() const
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
  return components;
}

double MedialGraph::maximumRadius() const
{
  double r = 0.0;
  for (const MedialNode& n : nodes)
    r = std::max(r, n.sample.radius);
  for (const MedialSegment& s : segments)
    for (const MedialSample& m : s.samples)
      r = std::max(r, m.radius);
  return r;
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

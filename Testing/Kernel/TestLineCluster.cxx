// The medial tree of nearly concurrent lines (mat2d/LineCluster): closed forms, an exact
// tie, and random near-regular polygons checked against the lines themselves.
#include "mat2d/LineCluster.h"

#include "shapes/RandomShapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>

using namespace exactmat;

namespace
{
double distanceOf(const ClusterLine& l, const Vec2& x)
{
  return l.normal.dot(x) + l.offset;
}

// Every node ties its three lines and no line is nearer; the tree has one node per
// triangle (lines − 2), every neighbouring pair of lines in angle an unbounded edge, and
// it is connected.
void expectMedialTree(const std::vector<ClusterLine>& lines, const ClusterTree& tree, double tolerance)
{
  const int n = static_cast<int>(lines.size());
  ASSERT_EQ(static_cast<int>(tree.nodes.size()), n - 2);
  int unbounded = 0, inner = 0;
  std::vector<int> parent(tree.nodes.size());
  for (size_t i = 0; i < parent.size(); ++i)
    parent[i] = static_cast<int>(i);
  auto find = [&](int a) {
    while (parent[a] != a)
      a = parent[a] = parent[parent[a]];
    return a;
  };
  for (const ClusterNode& node : tree.nodes)
  {
    double nearest = std::numeric_limits<double>::infinity();
    for (const ClusterLine& l : lines)
      nearest = std::min(nearest, distanceOf(l, node.x));
    for (const int l : node.lines)
      EXPECT_NEAR(distanceOf(lines[l], node.x), node.r, tolerance);
    EXPECT_NEAR(nearest, node.r, tolerance);
  }
  for (const ClusterEdge& e : tree.edges)
  {
    if (e.node1 < 0)
      ++unbounded;
    else
    {
      ++inner;
      parent[find(e.node0)] = find(e.node1);
    }
    // Both lines of an edge tie at both its ends.
    for (const int node : { e.node0, e.node1 })
    {
      if (node >= 0)
      {
        EXPECT_NEAR(distanceOf(lines[e.lineA], tree.nodes[node].x), distanceOf(lines[e.lineB], tree.nodes[node].x), tolerance);
      }
    }
  }
  EXPECT_EQ(unbounded, n);
  EXPECT_EQ(inner, n - 3);
  std::set<int> roots;
  for (size_t i = 0; i < parent.size(); ++i)
    roots.insert(find(static_cast<int>(i)));
  EXPECT_EQ(roots.size(), 1u);
}
} // namespace

// A 2a × 2b rectangle (a > b): the creases meet at (±(a − b), 0) with radius b, joined
// along the mid-line by the long sides' edge.
TEST(LineCluster, RectangleInClosedForm)
{
  const double a = 2.0, b = 0.5;
  const std::vector<ClusterLine> lines{ { Vec2(0, 1), b }, { Vec2(-1, 0), a }, { Vec2(0, -1), b }, { Vec2(1, 0), a } };
  const ClusterTree tree = lineClusterTree(lines);
  expectMedialTree(lines, tree, 1e-15);
  ASSERT_EQ(tree.nodes.size(), 2u);
  std::vector<double> xs;
  for (const ClusterNode& node : tree.nodes)
  {
    xs.push_back(node.x.x());
    EXPECT_NEAR(node.x.y(), 0.0, 1e-15);
    EXPECT_NEAR(node.r, b, 1e-15);
  }
  std::sort(xs.begin(), xs.end());
  EXPECT_NEAR(xs[0], -(a - b), 1e-15);
  EXPECT_NEAR(xs[1], a - b, 1e-15);
  const auto inner = std::find_if(tree.edges.begin(), tree.edges.end(), [](const ClusterEdge& e) { return e.node1 >= 0; });
  ASSERT_NE(inner, tree.edges.end());
  EXPECT_EQ(std::set<int>({ inner->lineA, inner->lineB }), std::set<int>({ 0, 2 }));
}

// A square's four sides tie exactly at its centre: two nodes there (any triangulation of
// an exact tie), no line nearer.
TEST(LineCluster, SquareIsAnExactTie)
{
  const std::vector<ClusterLine> lines{ { Vec2(0, 1), 1 }, { Vec2(-1, 0), 1 }, { Vec2(0, -1), 1 }, { Vec2(1, 0), 1 } };
  const ClusterTree tree = lineClusterTree(lines);
  expectMedialTree(lines, tree, 1e-15);
  for (const ClusterNode& node : tree.nodes)
  {
    EXPECT_LE(node.x.norm(), 1e-15);
    EXPECT_NEAR(node.r, 1.0, 1e-15);
  }
}

// Near-regular polygons (offsets jittered by 1e-12 … 1e-4, normals by as much): the tree
// of up to 2,000 lines is exact to the lines' own rounding, however close to a tie.
TEST(LineCluster, JitteredRegularPolygonsAgainstTheirLines)
{
  RandomEngine rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const int n : { 5, 12, 100, 2000 })
  {
    for (const double jitter : { 1e-12, 1e-8, 1e-4 })
    {
      SCOPED_TRACE(std::to_string(n) + " lines, jitter " + std::to_string(jitter));
      std::vector<ClusterLine> lines;
      for (int k = 0; k < n; ++k)
      {
        const double angle = 2 * M_PI * k / n + jitter * unit(rng);
        lines.push_back({ Vec2(std::cos(angle), std::sin(angle)), 1.0 + jitter * unit(rng) });
      }
      expectMedialTree(lines, lineClusterTree(lines), 1e-12);
    }
  }
}

// A line behind a parallel one is never the nearest: it takes no part.
TEST(LineCluster, AHiddenLineTakesNoPart)
{
  const std::vector<ClusterLine> lines{ { Vec2(0, 1), 1 }, { Vec2(-1, 0), 2 }, { Vec2(0, -1), 1 }, { Vec2(1, 0), 2 },
    { Vec2(0, 1), 1.5 } };
  const ClusterTree tree = lineClusterTree(lines);
  EXPECT_EQ(tree.nodes.size(), 2u);
  for (const ClusterEdge& e : tree.edges)
    EXPECT_TRUE(e.lineA != 4 && e.lineB != 4);
}

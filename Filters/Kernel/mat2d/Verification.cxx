#include "Verification.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/Format.h"

namespace exactmat
{

namespace
{
// Adds the boundary swept by a front going from `from` to `to` in direction dir.
void sweep(const Generators& G, std::vector<std::vector<std::pair<double, double>>>& swept,
  const BoundaryLocation& from, const BoundaryLocation& to, int dir)
{
  int g = from.g;
  double s = from.s;
  for (int k = 0; k < G.size() + 1; ++k)
  {
    if (g == to.g && (dir > 0 ? to.s >= s - 1e-9 : to.s <= s + 1e-9))
    {
      swept[g].push_back({ std::min(s, to.s), std::max(s, to.s) });
      return;
    }
    swept[g].push_back(dir > 0 ? std::make_pair(s, 1.0) : std::make_pair(0.0, s));
    g = dir > 0 ? G[g].next : G[g].prev;
    s = dir > 0 ? 0.0 : 1.0;
  }
}
} // namespace

MAT2DVerification verifyMAT2D(
  const Generators& G, const MedialGraph& graph, const ParallelFor& parallel)
{
  MAT2DVerification v;
  const double L = G.size2D();
  // The points to check, in output order; checked independently (possibly on several
  // threads), then reduced in this order so the figures do not depend on the threads.
  struct Check
  {
    Vec2 x;
    double r;
    int minFootpoints;
    double error = 0.0;
    bool shortfall = false;
  };
  std::vector<Check> checks;
  std::vector<std::vector<std::pair<double, double>>> swept(G.size());
  for (const MedialNode& n : graph.nodes)
  {
    checks.push_back({ n.sample.x, n.sample.radius, n.type == MedialPointType::Branch ? 3 : 0 });
    for (const BoundaryLocation& f : n.footpoints)
      if (f.continuum || n.type == MedialPointType::CircleCentre)
        swept[f.g].push_back({ 0.0, 1.0 });
  }
  for (const MedialSegment& s : graph.segments)
  {
    for (size_t i = 1; i + 1 < s.samples.size(); ++i)
      checks.push_back({ s.samples[i].x, s.samples[i].radius, 2 });
    for (size_t i = 0; i + 1 < s.samples.size(); ++i)
    {
      sweep(G, swept, s.samples[i].foot[0], s.samples[i + 1].foot[0], +1);
      sweep(G, swept, s.samples[i].foot[1], s.samples[i + 1].foot[1], -1);
    }
  }
  parallel(checks.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
    {
      Check& c = checks[i];
      double distance = std::numeric_limits<double>::infinity();
      if (c.minFootpoints > 0 && c.r > 1e-6 * L)
      {
        // Every footpoint within a hair more than the radius: the nearest of them is the
        // global distance whenever that is within reach (the same exact search the
        // distance query makes, asked once instead of twice).
        const auto f = G.footpointsWithin(c.x, c.r * (1.0 + 1e-6) + 1e-9 * L);
        const bool continuum = std::any_of(
          f.begin(), f.end(), [](const BoundaryLocation& b) { return b.continuum; });
        c.shortfall = !continuum && static_cast<int>(f.size()) < c.minFootpoints;
        for (const BoundaryLocation& b : f)
          distance = std::min(distance, (b.point - c.x).norm());
      }
      if (!(distance < std::numeric_limits<double>::infinity()))
        distance = G.distance(c.x);
      c.error = std::abs(distance - c.r) / L;
    }
  });
  for (const Check& c : checks)
  {
    ++v.points;
    if (!(c.error <= v.maxDistanceError)) // NaN counts as the worst
    {
      v.maxDistanceError = std::isnan(c.error) ? std::numeric_limits<double>::infinity() : c.error;
      v.worstPoint = c.x;
      v.worstRadius = c.r;
    }
    v.footpointShortfalls += c.shortfall ? 1 : 0;
  }
  for (int g = 0; g < G.size(); ++g)
  {
    if (G[g].kind != GeneratorKind::Edge)
      continue; // corners are swept in angle; their coverage follows from their edges'
    auto& list = swept[g];
    std::sort(list.begin(), list.end());
    double end = 0.0, total = 0.0, unionLength = 0.0;
    for (const auto& [lo, hi] : list)
    {
      if (lo > end)
        v.uncovered += lo - end;
      unionLength += std::max(0.0, hi - std::max(lo, end));
      total += hi - lo;
      end = std::max(end, hi);
    }
    v.uncovered += std::max(0.0, 1.0 - end);
    v.coveredTwice += std::max(0.0, total - unionLength);
  }
  v.cycles = graph.cycleCount();
  v.holes = G.boundary().holeCount();
  v.components = graph.componentCount();
  v.domains = static_cast<int>(G.boundary().loops().size()) - v.holes;
  return v;
}

std::string MAT2DVerification::problems(double distanceTolerance) const
{
  std::string out;
  auto add = [&](const std::string& s) { out += (out.empty() ? "" : "; ") + s; };
  if (!(maxDistanceError <= distanceTolerance))
    add("largest |distance to boundary - radius| / size " + format(maxDistanceError) +
      " > tolerance " + format(distanceTolerance));
  if (footpointShortfalls > 0)
    add(std::to_string(footpointShortfalls) + " points with too few footpoints");
  if (uncovered > CoverageSlack)
    add("boundary parameter " + format(uncovered) + " not swept by footpoints");
  if (coveredTwice > CoverageSlack)
    add("boundary parameter " + format(coveredTwice) + " swept twice");
  if (cycles != holes)
    add(std::to_string(cycles) + " cycles for " + std::to_string(holes) + " holes");
  if (components != domains)
    add(std::to_string(components) + " connected components for " + std::to_string(domains) +
      " connected domain" + (domains == 1 ? "" : "s"));
  return out;
}

} // namespace exactmat

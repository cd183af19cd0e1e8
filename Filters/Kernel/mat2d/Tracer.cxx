#include "Tracer.h"

#include "common/InputError.h"
#include "mat2d/Bisector.h"
#include "mat2d/LineCluster.h"
#include "common/UnionFind.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <cmath>
#include <deque>
#include <unordered_map>
#include <limits>
#include <numeric>

namespace exactmat
{

namespace
{
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
constexpr double ParamEps = 1e-12;
/// Boundary parameter a front may stand inside coverage it did not sweep (where a branch
/// point's footpoints were polished, to rounding): further than that slop, closer than a
/// cluster of branch points split by a 1e-8 perturbation, whose short segments must be
/// traced, not skipped as covered.
constexpr double CoverageSlop = 1e-11;

/// How far the medial curve strays from the chord between two of its samples, as the
/// step control needs it: positions and radii are the points (x, y, r) of the MAT
/// transform, `mid` the curve's point between them at the middle of the *held parameter*.
/// That point need not be the chord's middle: into a centre-of-curvature end the MAT point
/// moves like the square of the footpoint parameter, so the distance to the chord's
/// midpoint measures the parameterisation, not the curve's deviation (the ellipse's ends
/// took 91 samples so). The deviation is measured across the chord, at the fraction τ of
/// the way the middle point projects to, and scaled to the chord's largest by 1/(4τ(1−τ)),
/// exact for an arc of a parabola, i.e. for any smooth arc short against its curvature.
/// (Position and radius deviations are added, as the chord error always was.)
double chordDeviation(const Vec2& x0, double r0, const Vec2& xm, double rm, const Vec2& x1, double r1)
{
  const Eigen::Vector3d p0(x0.x(), x0.y(), r0), pm(xm.x(), xm.y(), rm), p1(x1.x(), x1.y(), r1);
  const Eigen::Vector3d chord = p1 - p0;
  const double length2 = chord.squaredNorm();
  if (!(length2 > 0.0))
    return (pm - p0).head<2>().norm() + std::abs(pm(2) - p0(2));
  const double tau = std::clamp((pm - p0).dot(chord) / length2, 0.05, 0.95);
  const Eigen::Vector3d across = pm - p0 - tau * chord;
  return (across.head<2>().norm() + std::abs(across(2))) / (4.0 * tau * (1.0 - tau));
}

struct Pending
{
  int node;
  BoundaryLocation a, b; ///< a moves forward, b backward
};

/// Parameter intervals of each generator already swept by a front, with an undo log for
/// the fixed-step mode's backtracking.
class Coverage
{
public:
  /// `undoable`: keep the log undo() needs (the fixed-step mode's backtracking).
  Coverage(int generators, bool undoable)
    : Intervals(generators)
    , Undoable(undoable)
  {
  }

  /// Extends interval `id` of generator g (or starts one when id < 0) to include [lo, hi];
  /// returns the interval's index.
  int cover(int g, double lo, double hi, int id)
  {
    if (hi < lo)
      std::swap(lo, hi);
    auto& list = Intervals[g];
    if (id >= 0 && id < static_cast<int>(list.size()))
    {
      if (Undoable)
        Log.push_back({ g, id, list[id].first, list[id].second, false });
      list[id].first = std::min(list[id].first, lo);
      list[id].second = std::max(list[id].second, hi);
      return id;
    }
    list.emplace_back(lo, hi);
    if (Undoable)
      Log.push_back({ g, static_cast<int>(list.size()) - 1, lo, hi, true });
    return static_cast<int>(list.size()) - 1;
  }

  /// Takes interval `id` of generator g back to end at s (its upper end for a front moving
  /// forward, dir > 0; its lower end otherwise): a front that went past where its segment
  /// ends.
  void retreat(int g, int id, double s, int dir)
  {
    auto& list = Intervals[g];
    if (id < 0 || id >= static_cast<int>(list.size()))
      return;
    if (Undoable)
      Log.push_back({ g, id, list[id].first, list[id].second, false });
    if (dir > 0)
      list[id].second = std::max(list[id].first, std::min(list[id].second, s));
    else
      list[id].first = std::min(list[id].second, std::max(list[id].first, s));
  }

  size_t mark() const { return Log.size(); }
#ifdef EXACTMAT_TRACE_DEBUG
  void dump(int g) const
  {
    std::fprintf(stderr, "  coverage of g%d:", g);
    for (const auto& [lo, hi] : Intervals[g])
      std::fprintf(stderr, " [%.12g, %.12g]", lo, hi);
    std::fprintf(stderr, "\n");
  }
#endif
  void undo(size_t to)
  {
    while (Log.size() > to)
    {
      const Entry e = Log.back();
      Log.pop_back();
      if (e.added)
        Intervals[e.g].pop_back();
      else
        Intervals[e.g][e.id] = { e.lo, e.hi };
    }
  }

  bool covers(int g, double s, int skip = -1) const
  {
    const auto& list = Intervals[g];
    for (int i = 0; i < static_cast<int>(list.size()); ++i)
    {
      if (i != skip && list[i].first <= s && s <= list[i].second)
        return true;
    }
    return false;
  }

  /// First covered parameter met moving from s (exclusive) to target in direction dir,
  /// ignoring interval `skip`; NaN when none.
  double firstAhead(int g, double s, double target, int dir, int skip) const
  {
    double best = NaN;
    const auto& list = Intervals[g];
    for (int i = 0; i < static_cast<int>(list.size()); ++i)
    {
      if (i == skip)
        continue;
      const double edge = dir > 0 ? list[i].first : list[i].second;
      const bool inside = list[i].first < s && s < list[i].second;
      const double hit = inside ? s : edge;
      const bool ahead = dir > 0 ? (hit >= s - ParamEps && hit <= target)
                                 : (hit <= s + ParamEps && hit >= target);
      if (ahead && (std::isnan(best) || (dir > 0 ? hit < best : hit > best)))
        best = hit;
    }
    return best;
  }

  double coveredMeasure() const
  {
    double total = 0.0;
    for (const auto& list : Intervals)
    {
      std::vector<std::pair<double, double>> v = list;
      std::sort(v.begin(), v.end());
      double end = -1.0;
      for (const auto& [lo, hi] : v)
      {
        total += std::max(0.0, hi - std::max(lo, end));
        end = std::max(end, hi);
      }
    }
    return total;
  }

  /// The largest stretch of generator g no front has swept (longer than 1e-6 of its
  /// parameter): true and its ends, or false.
  bool uncovered(int g, double& from, double& to) const
  {
    std::vector<std::pair<double, double>> v = Intervals[g];
    std::sort(v.begin(), v.end());
    double end = 0.0, bestLen = 1e-6;
    bool found = false;
    for (const auto& [lo, hi] : v)
    {
      if (lo - end > bestLen)
      {
        bestLen = lo - end;
        from = end;
        to = lo;
        found = true;
      }
      end = std::max(end, hi);
    }
    if (1.0 - end > bestLen)
    {
      from = end;
      to = 1.0;
      found = true;
    }
    return found;
  }

private:
  struct Entry
  {
    int g, id;
    double lo, hi;
    bool added;
  };
  std::vector<std::vector<std::pair<double, double>>> Intervals;
  bool Undoable = false;
  std::vector<Entry> Log;
};

class Tracer
{
public:
  Tracer(const Generators& g, const MAT2DOptions& o)
    : G(g)
    , O(o)
    , L(g.size2D())
    , InputRounding(64.0 * g.boundary().userFrame().inputRounding())
    , Cover(g.size(), o.fixedStep)
    , NodesByGenerator(g.size())
  {
  }

  MedialGraph run();

private:
  struct Front
  {
    int g;
    double s;
    int interval = -1; // coverage interval this front is growing
  };

  int addNode(const Vec2& x, double r, MedialPointType type, std::vector<BoundaryLocation> fps);
  int findNode(const Vec2& x, double tol) const;
  /// The node nearest x within `reach` that `accept(node)` takes, or −1.
  template <typename Accept>
  int nearestNode(const Vec2& x, double reach, Accept&& accept) const
  {
    // The cells around x that a disk of radius `reach` meets (3 × 3 for reach ≤ a cell).
    const double cell = NodeCell * L;
    int best = -1;
    double bestDistance = reach;
    const double span = std::ceil(reach / cell);
    if (!(span <= 64.0))
    {
      // A reach of many cells (or none a number can say): every node, once.
      for (int n = 0; n < static_cast<int>(Graph.nodes.size()); ++n)
      {
        const double d = (Graph.nodes[n].sample.x - x).norm();
        if (d <= bestDistance && accept(n))
        {
          bestDistance = d;
          best = n;
        }
      }
      return best;
    }
    const long long k = std::max(1LL, static_cast<long long>(span));
    const long long ci = cellIndex(x.x()), cj = cellIndex(x.y());
    for (long long i = ci - k; i <= ci + k; ++i)
    {
      for (long long j = cj - k; j <= cj + k; ++j)
      {
        const auto it = NodeGrid.find(cellKey(i, j));
        if (it == NodeGrid.end())
          continue;
        for (int n : it->second)
        {
          const double d = (Graph.nodes[n].sample.x - x).norm();
          if (d <= bestDistance && accept(n))
          {
            bestDistance = d;
            best = n;
          }
        }
      }
    }
    return best;
  }
  /// The node within `reach` of x (other than `exclude`) that touches the boundary where
  /// one of the fronts does (fa or fb, to 1e-9 of the size). Where a segment meets its end
  /// node at a grazing angle (next to an almost flat convex vertex) its fronts reach the
  /// node's feet, which bound the boundary covered before, while its point is still 1e-6
  /// short: the feet fix the point poorly there. Two maximal disks touching one boundary
  /// point from one side are nested, so they are one: the node is this segment's end.
  int nodeWithFeet(const Vec2& x, double reach, int exclude, const Vec2& fa, const Vec2& fb) const;
  void spawnWedges(int node);
  /// The node's wedges: pairs of angularly consecutive footpoints (front a, front b).
  std::vector<std::pair<BoundaryLocation, BoundaryLocation>> wedgesOf(int node) const;
  /// Whether a pending segment is still a wedge of its node (footpoints merged into a
  /// node later can split a wedge in two).
  bool isWedgeOf(const Pending& p);
  struct CachedWedges
  {
    bool valid = false;
    std::vector<std::pair<BoundaryLocation, BoundaryLocation>> wedges;
  };
  std::vector<CachedWedges> WedgeCache;
  void mergeIntoNode(int node, const std::vector<BoundaryLocation>& footpoints);
  /// Near a branch point where four or more straight edges come within ClusterSpread of
  /// its radius (a near-regular polygon's centre, split by jitter or rounding: see
  /// LineCluster.h), the medial tree of their lines, as far as it is the MAT.
  struct ClusterPlan
  {
    struct Node
    {
      Vec2 x;
      double r;
      std::vector<BoundaryLocation> feet;
    };
    std::vector<Node> nodes;
    struct Segment
    {
      int from, to;        ///< nodes
      BoundaryLocation a0, b0, a1, b1; ///< feet at both ends: a moves forward, b backward
    };
    std::vector<Segment> segments;
    int incoming = -1; ///< the node the segment that found the cluster ends on; −1: no plan
  };
  /// The plan around branch point (xb, r) found by the segment of straight edges ga, gb:
  /// the tree's nodes within ClusterSpread / 2 of it (where no other boundary point can
  /// reach their disks and every line's foot stays on its edge) that are not in the graph
  /// yet, and the tree's segments between them. No plan when the point is no such
  /// cluster or the tree does not have the segment of ga and gb end near it.
  ClusterPlan planLineCluster(const Vec2& xb, double r, int ga, int gb) const;
  /// Adds the plan's nodes and segments (the boundary they sweep covered); their ids.
  std::vector<int> commitLineCluster(const ClusterPlan& plan);
  void trace(const Pending& p);
  bool emptyDisk(const Vec2& x, double r) const;
  /// The same for a point of the bisector of generators ga, gb touching them at sa, sb.
  bool emptyDisk(const Vec2& x, double r, int ga, double sa, int gb, double sb) const
  {
    return !G.anyCloserThan(x, r - diskMargin(r), ga, sa, gb, sb);
  }
  /// How far inside a disk of radius r the boundary may reach and the disk still count
  /// as empty: rounding, and no less than the input's own.
  double diskMargin(double r) const;
  bool curvatureOk(int g, double s, double r) const;
  bool curvatureOk(int g, const GeneratorPoint& at, double r) const; ///< g evaluated already
  /// A node at the maximal disk touching the boundary at (g, s), its wedges queued; false
  /// when that disk touches there only (the osculating disk at a curvature extremum).
  bool startAt(int g, double s);
  BoundaryLocation location(int g, double s) const;
  // The LMPC between the fronts when they close in on each other along one smooth run.
  using Stretch = std::vector<std::pair<int, std::pair<double, double>>>;
  bool lmpcBetween(const Front& a, const Front& b, BoundaryLocation& at, double& kappa,
    Stretch& stretch) const;
  /// Continuum footpoints (an arc seen from its centre) are touched all along: cover
  /// their generators and make the node an end at a centre of curvature.
  void absorbContinuum(int node);
  void reportProgress();
  /// Joins components of the graph closer than ClusterReach (see the definition).
  void joinClusters();
  /// Collapses two pieces of one cluster joined twice (a cycle around no hole).
  void collapseClusterCycles();
  /// Node `gone` merged into node `keep` (segments, footpoints, type); gone is left empty.
  void absorbNode(int keep, int gone);
  /// The boundary location `distance` (in parameter) ahead of (g, s) in direction dir,
  /// crossing smooth and reflex junctions; false when a convex vertex is in the way.
  bool stepAlong(int& g, double& s, int dir, double distance) const;
  bool coveredAhead(int g, double s, int dir) const;
  /// A front at the end of its generator continues on the neighbour (not past a convex
  /// vertex), so equal places on the boundary have one description.
  BoundaryLocation normalised(const BoundaryLocation& f, int dir) const;

  const Generators& G;
  const MAT2DOptions& O;
  const double L;
  const double InputRounding; ///< how far the input's coordinates are known, / size
  Coverage Cover;
  MedialGraph Graph;
  /// Nodes by grid cell (cells of NodeCell·L), so finding a node near a point is O(1).
  std::unordered_map<long long, std::vector<int>> NodeGrid;
  /// The nodes with a footpoint on each generator: a segment between two straight edges
  /// that runs into a node found before (a regular polygon's centre, reached from every
  /// side) lands on it instead of sweeping past it.
  std::vector<std::vector<std::pair<int, double>>> NodesByGenerator; ///< (node, footpoint parameter)
  /// The node on the bisector of the fronts' generators (straight edges) between states y
  /// and y1 — footpoints on both, ahead of both fronts, at the interpolated state — the
  /// first one along; −1 when none. `at` receives its state.
  int nodeAhead(int ga, int gb, const BisectorState& y, const BisectorState& y1, const Vec2& x0, const Vec2& x1,
    BisectorState& at) const;
  static constexpr double NodeCell = 1e-5;
  /// Branch points closer than this fraction of the size are one node (a node of degree
  /// k ≥ 4): merging them moves a point by less than the verification's 1e-9.
  static constexpr double NodeMerge = 5e-10;
  /// Branch points of a cluster (a node of degree k ≥ 4 split by the input's rounding)
  /// lie up to ~1e-8 of the size apart; segments joining one another there end at the
  /// node they reach within 1e-6, so a cluster can come out in pieces. Pieces closer than
  /// this are one node of degree k (the issue allows either form).
  static constexpr double ClusterReach = 1e-7;
  /// Straight edges within this fraction of a branch point's radius make it a cluster
  /// resolved by their lines' medial tree (planLineCluster).
  static constexpr double ClusterSpread = 0.05;
  /// A branch point is looked at as a cluster when four boundary contacts lie within this
  /// fraction of its radius.
  static constexpr double ClusterTrigger = 1e-6;
  /// Branch points of a cluster's tree closer than this fraction of the size are one node.
  static constexpr double TieMerge = 1e-12;
  long long cellKey(long long i, long long j) const { return i * 73856093LL ^ j * 19349663LL; }
  /// The node grid's cell of coordinate v. Points beyond 1e9 cells (a trace gone wild on
  /// hostile input, or NaN) share the border cells: the distances decide, and neither the
  /// cast nor the key overflows.
  long long cellIndex(double v) const
  {
    const double c = std::floor(v / (NodeCell * L));
    return c >= -1e9 && c <= 1e9 ? static_cast<long long>(c) : (c > 0.0 ? 1000000000LL : -1000000000LL);
  }
  int SegmentsSinceProgress = 0;
  std::deque<Pending> Queue;
  double TotalMeasure = 1.0;
};

BoundaryLocation Tracer::location(int g, double s) const
{
  const GeneratorPoint p = G.evaluate(g, s);
  return { g, s, p.p, p.n, false };
}

bool Tracer::emptyDisk(const Vec2& x, double r) const
{
  // Tight: a cluster of branch points 1e-9 apart must not be stepped through; the
  // fronts' own footpoints are solved to 1e-13 of the size, well inside this. Input far
  // from the origin is known to fewer digits (pieces meet only to its rounding): no
  // margin below that.
  return !G.anyCloserThan(x, r - diskMargin(r));
}

double Tracer::diskMargin(double r) const
{
  return (1e-11 + InputRounding) * L + 1e-11 * r;
}

bool Tracer::curvatureOk(int g, double s, double r) const
{
  if (G[g].kind != GeneratorKind::Edge)
    return true;
  return curvatureOk(g, G.evaluate(g, s), r);
}

bool Tracer::curvatureOk(int g, const GeneratorPoint& at, double r) const
{
  if (G[g].kind != GeneratorKind::Edge)
    return true;
  const double k = at.curvature;
  return !(k > 0.0) || r * k <= 1.0 + 1e-9;
}

int Tracer::findNode(const Vec2& x, double tol) const
{
  return nearestNode(x, tol, [](int) { return true; });
}

int Tracer::nodeWithFeet(const Vec2& x, double reach, int exclude, const Vec2& fa, const Vec2& fb) const
{
  return nearestNode(x, reach, [&](int n) {
    const auto& feet = Graph.nodes[n].footpoints;
    return n != exclude && std::any_of(feet.begin(), feet.end(), [&](const BoundaryLocation& f) {
      return (f.point - fa).norm() <= 1e-9 * L || (f.point - fb).norm() <= 1e-9 * L;
    });
  });
}

int Tracer::addNode(const Vec2& x, double r, MedialPointType type, std::vector<BoundaryLocation> fps)
{
  MedialNode n;
  n.sample.x = x;
  n.sample.radius = r;
  if (!fps.empty())
  {
    n.sample.foot[0] = fps.front();
    n.sample.foot[1] = fps.size() > 1 ? fps[1] : fps.front();
  }
  n.type = type;
  n.footpoints = std::move(fps);
  Graph.nodes.push_back(std::move(n));
  const int id = static_cast<int>(Graph.nodes.size()) - 1;
  NodeGrid[cellKey(cellIndex(x.x()), cellIndex(x.y()))].push_back(id);
  for (const BoundaryLocation& f : Graph.nodes[id].footpoints)
    NodesByGenerator[f.g].push_back({ id, f.s });
  return id;
}

int Tracer::nodeAhead(int ga, int gb, const BisectorState& y, const BisectorState& y1, const Vec2& x0,
  const Vec2& x1, BisectorState& at) const
{
  const Vec2 step = x1 - x0;
  const double length2 = step.squaredNorm();
  if (!(length2 > 0.0))
    return -1;
  int best = -1;
  double first = INFINITY;
  // (A step that joins boundary traced before lands on its start to rounding. A node
  // standing for branch points within NodeMerge of one another, a regular polygon's
  // centre, is off this pair's bisector by as much: its feet may lie that far past, and
  // where the lines are almost parallel the step clipped at them ends short of it by that
  // over the angle — within the 1e-7 of the size the node may be off the step anyway.)
  auto slack = [&](int g) { return 1e-9 + 2.0 * NodeMerge * L / std::max(1e-300, G.evaluate(g, 0.5).dp.norm()); };
  const double slackA = slack(ga), slackB = slack(gb);
  for (const auto& [id, sa] : NodesByGenerator[ga])
  {
    if (!(sa > y.sa && sa <= y1.sa + slackA))
      continue;
    double sb = NaN;
    for (const auto& [other, s] : NodesByGenerator[gb])
      if (other == id && s < y.sb && s >= y1.sb - slackB)
        sb = s;
    if (std::isnan(sb))
      continue;
    const MedialNode& n = Graph.nodes[id];
    // Touching both lines, the node is on their bisector (to its own precision): where
    // along this step, and is its radius the step's there?
    const double tau = (n.sample.x - x0).dot(step) / length2;
    const Vec2 x = x0 + tau * step;
#ifdef EXACTMAT_TRACE_DEBUG
    std::fprintf(stderr, "  nodeAhead candidate %d tau %.17g off %.3g dr %.3g\n", id, tau, (x - n.sample.x).norm(), y.r + tau * (y1.r - y.r) - n.sample.radius);
#endif
    if (tau > 0.0 && tau <= 1.0 + 1e-9 + 1e-7 * L / std::sqrt(length2) && tau < first && (x - n.sample.x).norm() <= 1e-7 * L &&
      std::abs(y.r + tau * (y1.r - y.r) - n.sample.radius) <= 1e-7 * L)
    {
      first = tau;
      best = id;
      at = BisectorState{ sa, sb, n.sample.radius };
    }
  }
  return best;
}

bool Tracer::stepAlong(int& g, double& s, int dir, double distance) const
{
  s += dir * distance;
  if (s > 1.0)
  {
    if (G[g].endJunction == VertexKind::Convex)
      return false;
    s -= 1.0;
    g = G[g].next;
  }
  else if (s < 0.0)
  {
    if (G[g].startJunction == VertexKind::Convex)
      return false;
    s += 1.0;
    g = G[g].prev;
  }
  return true;
}

bool Tracer::coveredAhead(int g, double s, int dir) const
{
  // Further than the slop of a bisection, closer than any real feature.
  return stepAlong(g, s, dir, CoverageSlop) && Cover.covers(g, s);
}

BoundaryLocation Tracer::normalised(const BoundaryLocation& f, int dir) const
{
  if (dir > 0 && f.s >= 1.0 - ParamEps && G[f.g].endJunction != VertexKind::Convex)
    return location(G[f.g].next, 0.0);
  if (dir < 0 && f.s <= ParamEps && G[f.g].startJunction != VertexKind::Convex)
    return location(G[f.g].prev, 1.0);
  return f;
}

void Tracer::absorbContinuum(int node)
{
  MedialNode& n = Graph.nodes[node];
  bool any = false;
  for (const BoundaryLocation& f : n.footpoints)
  {
    if (f.continuum)
    {
      Cover.cover(f.g, 0.0, 1.0, -1);
      any = true;
    }
  }
  if (any && n.type != MedialPointType::CircleCentre)
    n.type = MedialPointType::CurvatureCentreEnd;
}

std::vector<std::pair<BoundaryLocation, BoundaryLocation>> Tracer::wedgesOf(int node) const
{
  // One segment per pair of angularly consecutive footpoints (counter-clockwise around
  // the MAT point: moving forward along the boundary turns the contact point that way).
  const MedialNode& n = Graph.nodes[node];
  std::vector<BoundaryLocation> f = n.footpoints;
  const Vec2 x = n.sample.x;
  std::sort(f.begin(), f.end(), [&](const BoundaryLocation& a, const BoundaryLocation& b) {
    const Vec2 da = a.point - x, db = b.point - x;
    const double aa = (da.norm() > 0 ? std::atan2(da.y(), da.x()) : std::atan2(-a.normal.y(), -a.normal.x()));
    const double ab = (db.norm() > 0 ? std::atan2(db.y(), db.x()) : std::atan2(-b.normal.y(), -b.normal.x()));
    return aa < ab;
  });
  // Footpoints on either side of a reflex corner, close together and with the corner
  // inside the shell the footpoints were collected in (an edge's foot 1e-7 from its own
  // reflex corner, a nearly flat corner between two feet), are one contact: the wedge
  // between them holds no segment, and the wedges on either side start from the member
  // the disk really touches (the nearest; tracing moves it across the corner as it
  // must). Feet either side of a smooth junction stay apart: near a centre of curvature
  // the whole stretch between two distinct contacts is inside the shell.
  const double r = n.sample.radius;
  auto oneContact = [&](const BoundaryLocation& a, const BoundaryLocation& b) {
    if (r <= 0.0 || (a.point - b.point).norm() > 1e-3 * r)
      return false;
    // From a forward to b: at most an edge's end, a reflex corner, the next edge's start.
    for (int g = a.g, hops = 0; hops < 2; g = G[g].next, ++hops)
    {
      if (G[g].endJunction != VertexKind::Reflex ||
        (location(g, 1.0).point - x).norm() > r * (1.0 + 1e-7) + 1e-9 * L)
        return false;
      if (G[g].next == b.g)
        return true;
    }
    return false;
  };
  const size_t k = f.size();
  // Members' angles differ by rounding only: order them along the boundary.
  for (size_t i = 0; i + 1 < k; ++i)
    if (oneContact(f[i + 1], f[i]))
      std::swap(f[i], f[i + 1]);
  std::vector<BoundaryLocation> contacts;
  if (k > 2)
  {
    size_t first = 0; // a footpoint that starts a contact
    while (first < k && oneContact(f[(first + k - 1) % k], f[first]))
      ++first;
    std::rotate(f.begin(), f.begin() + static_cast<long>(first % k), f.end());
    for (size_t i = 0; i < k; ++i)
    {
      if (i > 0 && oneContact(f[i - 1], f[i]))
      {
        if ((f[i].point - x).norm() < (contacts.back().point - x).norm())
          contacts.back() = f[i];
      }
      else
        contacts.push_back(f[i]);
    }
  }
  if (contacts.size() < 2)
    contacts = f;
  std::vector<std::pair<BoundaryLocation, BoundaryLocation>> wedges;
  for (size_t i = 0; i < contacts.size(); ++i)
    wedges.push_back({ normalised(contacts[i], +1), normalised(contacts[(i + 1) % contacts.size()], -1) });
  return wedges;
}

bool Tracer::isWedgeOf(const Pending& p)
{
  auto same = [](const BoundaryLocation& u, const BoundaryLocation& v) {
    return u.g == v.g && std::abs(u.s - v.s) <= ParamEps;
  };
  // A node's wedges change only when footpoints merge into it: cache them.
  if (WedgeCache.size() < Graph.nodes.size())
    WedgeCache.resize(Graph.nodes.size());
  auto& cached = WedgeCache[p.node];
  if (!cached.valid)
  {
    cached.wedges = wedgesOf(p.node);
    cached.valid = true;
  }
  for (const auto& [a, b] : cached.wedges)
    if (same(a, p.a) && same(b, p.b))
      return true;
  return false;
}

void Tracer::spawnWedges(int node)
{
  absorbContinuum(node);
  for (const auto& [a, b] : wedgesOf(node))
  {
    const bool aCovered = coveredAhead(a.g, a.s, +1);
    const bool bCovered = coveredAhead(b.g, b.s, -1);
    if (aCovered || bCovered)
      continue;
    Queue.push_back({ node, a, b });
  }
}

void Tracer::mergeIntoNode(int node, const std::vector<BoundaryLocation>& footpoints)
{
  // A branch point found within NodeMerge of a node is that node: its footpoints join the
  // node's (a node of degree k), and the wedges between them are traced.
  MedialNode& n = Graph.nodes[node];
  // Known: a footpoint on the same generator, or at the same place on a neighbour (an
  // edge's end and the corner or edge beyond it). O(k) per call: a regular n-gon's centre
  // is reached by n segments with n footpoints each.
  std::unordered_map<int, Vec2> known;
  for (const BoundaryLocation& o : n.footpoints)
    known.emplace(o.g, o.point);
  bool added = false;
  for (const BoundaryLocation& f : footpoints)
  {
    bool isKnown = known.count(f.g) > 0;
    for (int neighbour : { G[f.g].prev, G[f.g].next })
    {
      const auto it = known.find(neighbour);
      isKnown = isKnown || (it != known.end() && (it->second - f.point).norm() <= 1e-9 * L);
    }
    if (!isKnown)
    {
      n.footpoints.push_back(f);
      NodesByGenerator[f.g].push_back({ node, f.s });
      known.emplace(f.g, f.point);
      added = true;
    }
  }
  if (!added)
    return;
  if (node < static_cast<int>(WedgeCache.size()))
    WedgeCache[node].valid = false;
  if (n.footpoints.size() >= 3 && n.type == MedialPointType::Normal)
    n.type = MedialPointType::Branch;
  spawnWedges(node);
}

Tracer::ClusterPlan Tracer::planLineCluster(const Vec2& xb, double r, int ga, int gb) const
{
  ClusterPlan plan;
  if (!G.straight(ga) || !G.straight(gb) || !(r > 0.0))
    return plan;
  // The members: feet on the open middle of straight edges within r + spread of xb, where
  // spread stops short of anything else (a corner, a curved edge, an edge's end: the gaps'
  // reflex corners of a gear). Then within reach = spread / 2 of xb no disk of the lines'
  // tree (radius ≤ r + reach) meets anything but members (the others are farther than
  // r + spread − reach), and the tree is the MAT there.
  auto isLine = [&](const BoundaryLocation& f) {
    return G[f.g].kind == GeneratorKind::Edge && G.straight(f.g) && f.s > 0.0 && f.s < 1.0;
  };
  // A cluster of lines at all: four or more contacts within ClusterTrigger of the radius,
  // every one on a line (a cheap search — its disk reaches few pieces — before the wide
  // ones). The cluster's own scale is its radius, not the domain's (a saw-tooth's teeth).
  const std::vector<BoundaryLocation> close = G.footpointsWithin(xb, r * (1.0 + ClusterTrigger));
  if (close.size() < 4 || !std::all_of(close.begin(), close.end(), isLine))
    return plan;
  // An exact tie of a few lines (a saw-tooth's symmetric nodes, a square's centre) is one
  // node of degree k the ordinary way, without the wide searches below.
  const bool exactTie = std::all_of(close.begin(), close.end(),
    [&](const BoundaryLocation& f) { return (f.point - xb).norm() <= r * (1.0 + 1e-10) + 1e-11 * L; });
  if (exactTie && close.size() <= 8)
    return plan;
  // Widening in two steps: most clusters have something else close (a saw-tooth's corners).
  std::vector<BoundaryLocation> near;
  double spread = 0.0;
  for (const double reachOut : { 1e-4 * r, ClusterSpread * r })
  {
    near = G.footpointsWithin(xb, r + reachOut);
    spread = reachOut;
    for (const BoundaryLocation& f : near)
      if (!isLine(f))
        spread = std::min(spread, (f.point - xb).norm() - r);
    if (spread < reachOut)
      break;
  }
  if (!(spread >= 1e-9 * L))
    return plan;
  const double reach = 0.5 * spread;
  std::vector<int> gen;
  std::vector<ClusterLine> lines;
  std::vector<Vec2> origin, along;
  for (const BoundaryLocation& f : near)
  {
    if (!isLine(f) || !((f.point - xb).norm() < r + spread))
      continue;
    if (std::find(gen.begin(), gen.end(), f.g) != gen.end())
      return plan;
    const GeneratorPoint p0 = G.evaluate(f.g, 0.0), p1 = G.evaluate(f.g, 1.0);
    gen.push_back(f.g);
    origin.push_back(p0.p);
    along.push_back(p1.p - p0.p);
    // Relative to xb and r: the offsets are the small differences that decide the tree.
    lines.push_back({ p0.n, p0.n.dot(xb - p0.p) - r });
  }
  const auto ia = std::find(gen.begin(), gen.end(), ga), ib = std::find(gen.begin(), gen.end(), gb);
  if (gen.size() < 4 || ia == gen.end() || ib == gen.end())
    return plan;
  const int la = static_cast<int>(ia - gen.begin()), lb = static_cast<int>(ib - gen.begin());
  const ClusterTree tree = lineClusterTree(lines);
  const int nodes = static_cast<int>(tree.nodes.size());
  if (nodes == 0)
    return plan;
  // The tree's node where the segment of ga and gb ends: nearest xb on an edge of that pair.
  int inNode = -1;
  for (const ClusterEdge& e : tree.edges)
  {
    if (!((e.lineA == la && e.lineB == lb) || (e.lineA == lb && e.lineB == la)))
      continue;
    for (const int n : { e.node0, e.node1 })
      if (n >= 0 && (inNode < 0 || tree.nodes[n].x.norm() < tree.nodes[inNode].x.norm()))
        inNode = n;
  }
  if (inNode < 0)
    return plan;
  // A tree within NodeMerge of that node is one node of degree k (a regular polygon's
  // centre, split by the rounding of its vertices only): the verification cannot tell
  // it from one. Otherwise only branch points that coincide to rounding are one node (an
  // exact tie of four or more lines): a segment between two nodes must run the way its
  // lines' feet move, which a node standing for a group wider than it would not bear out.
  UnionFind merged(nodes);
  const bool oneNode = std::all_of(tree.nodes.begin(), tree.nodes.end(),
    [&](const ClusterNode& n) { return (n.x - tree.nodes[inNode].x).norm() <= NodeMerge * L; });
  for (const ClusterEdge& e : tree.edges)
    if (e.node1 >= 0 && (oneNode || (tree.nodes[e.node0].x - tree.nodes[e.node1].x).norm() <= TieMerge * L))
      merged.unite(e.node0, e.node1);
  std::vector<int> group(nodes, -1), representative;
  std::vector<std::vector<int>> groupLines;
  for (int n = 0; n < nodes; ++n)
  {
    const int root = merged.find(n);
    if (group[root] < 0)
    {
      group[root] = static_cast<int>(representative.size());
      representative.push_back(root);
      groupLines.emplace_back();
    }
    group[n] = group[root];
    for (const int l : tree.nodes[n].lines)
      if (std::find(groupLines[group[n]].begin(), groupLines[group[n]].end(), l) == groupLines[group[n]].end())
        groupLines[group[n]].push_back(l);
  }
  const int groups = static_cast<int>(representative.size());
  const int in = group[inNode];
  representative[in] = inNode;
  // Each group's tree edges to other groups (the BFS below walks them once).
  std::vector<std::vector<int>> edgesOf(groups);
  for (size_t e = 0; e < tree.edges.size(); ++e)
  {
    const ClusterEdge& c = tree.edges[e];
    if (c.node1 >= 0 && group[c.node0] != group[c.node1])
    {
      edgesOf[group[c.node0]].push_back(static_cast<int>(e));
      edgesOf[group[c.node1]].push_back(static_cast<int>(e));
    }
  }
  // Each group as a node: where it is, its radius, its feet (none off its edge).
  std::vector<int> planned(groups, -2); // −2 not looked at, −1 refused, else plan index
  auto place = [&](int k) {
    if (planned[k] != -2)
      return planned[k];
    planned[k] = -1;
    const Vec2 y = tree.nodes[representative[k]].x;
    const Vec2 x = xb + y;
    if (!(y.norm() <= reach) || findNode(x, NodeMerge * L) >= 0)
      return -1;
    double radius = INFINITY;
    std::vector<BoundaryLocation> feet;
    for (const int l : groupLines[k])
    {
      radius = std::min(radius, lines[l].normal.dot(y) + lines[l].offset);
      const double s = (x - origin[l]).dot(along[l]) / along[l].squaredNorm();
      if (!(s > 0.0 && s < 1.0))
        return -1;
      feet.push_back({ gen[l], s, origin[l] + s * along[l], lines[l].normal, false });
    }
    planned[k] = static_cast<int>(plan.nodes.size());
    plan.nodes.push_back({ x, r + radius, std::move(feet) });
    return planned[k];
  };
  if (place(in) < 0)
    return plan;
  // Out from there: the tree's segments between two nodes of the plan.
  std::vector<int> stack{ in };
  std::vector<bool> edgeDone(tree.edges.size(), false);
  while (!stack.empty())
  {
    const int k = stack.back();
    stack.pop_back();
    for (const int e : edgesOf[k])
    {
      const ClusterEdge& c = tree.edges[e];
      if (edgeDone[e])
        continue;
      const int other = group[c.node0] == k ? group[c.node1] : group[c.node0];
      const bool known = planned[other] >= 0;
      if (place(other) < 0)
        continue;
      edgeDone[e] = true;
      const ClusterPlan::Node &u = plan.nodes[planned[k]], &v = plan.nodes[planned[other]];
      auto footOn = [&](const ClusterPlan::Node& n, int l) {
        for (const BoundaryLocation& f : n.feet)
          if (f.g == gen[l])
            return f;
        return BoundaryLocation{};
      };
      BoundaryLocation a0 = footOn(u, c.lineA), a1 = footOn(v, c.lineA);
      BoundaryLocation b0 = footOn(u, c.lineB), b1 = footOn(v, c.lineB);
      // Front a moves forward along the boundary, b backward.
      if (a1.s - a0.s < b1.s - b0.s)
      {
        std::swap(a0, b0);
        std::swap(a1, b1);
      }
      // (A segment as short as the contraction of near-ties (TieMerge) runs up to that far
      // off its bisector: both feet may then move the same way, by a hair — a 2,000-gon
      // jittered by 1e-12 had a front step back 1.1e-9 of its edge over 3e-12, and the
      // verification count the loop swept again. Fronts do not step back; a step back
      // beyond the rounding of such segments stays, for the verification to report.)
      constexpr double Hair = 1e-7;
      if (a1.s < a0.s && a0.s - a1.s <= Hair)
        a1.s = a0.s;
      if (b1.s > b0.s && b1.s - b0.s <= Hair)
        b1.s = b0.s;
      plan.segments.push_back({ planned[k], planned[other], a0, b0, a1, b1 });
      if (!known)
        stack.push_back(other);
    }
  }
  plan.incoming = planned[in];
  return plan;
}

std::vector<int> Tracer::commitLineCluster(const ClusterPlan& plan)
{
  std::vector<int> ids;
  for (const ClusterPlan::Node& n : plan.nodes)
    ids.push_back(addNode(n.x, n.r, n.feet.size() >= 3 ? MedialPointType::Branch : MedialPointType::Normal, n.feet));
  for (const ClusterPlan::Segment& s : plan.segments)
  {
    MedialSegment seg;
    seg.startNode = ids[s.from];
    seg.endNode = ids[s.to];
    seg.generators[0] = s.a0.g;
    seg.generators[1] = s.b0.g;
    for (const auto& [node, a, b] : { std::make_tuple(s.from, s.a0, s.b0), std::make_tuple(s.to, s.a1, s.b1) })
    {
      MedialSample m;
      m.x = plan.nodes[node].x;
      m.radius = plan.nodes[node].r;
      m.foot[0] = a;
      m.foot[1] = b;
      seg.samples.push_back(m);
    }
    Cover.cover(s.a0.g, s.a0.s, s.a1.s, -1);
    Cover.cover(s.b0.g, s.b0.s, s.b1.s, -1);
    Graph.segments.push_back(std::move(seg));
    const int sid = static_cast<int>(Graph.segments.size()) - 1;
    Graph.nodes[ids[s.from]].segments.push_back(sid);
    Graph.nodes[ids[s.to]].segments.push_back(sid);
  }
  return ids;
}

bool Tracer::lmpcBetween(
  const Front& a, const Front& b, BoundaryLocation& at, double& kappa, Stretch& stretch) const
{
  // The stretch of boundary between the fronts: [a.s, b.s] on one edge, or a run of
  // edges joined smoothly. Long runs are only searched when the MAT point already sits at
  // both footpoints' centres of curvature (a circular arc seen from its centre).
  stretch.clear();
  if (a.g == b.g && a.s <= b.s + ParamEps)
    stretch.push_back({ a.g, { a.s, b.s } });
  else
  {
    bool concentric = false;
    if (G[a.g].kind == GeneratorKind::Edge && G[b.g].kind == GeneratorKind::Edge)
    {
      const GeneratorPoint pa = G.evaluate(a.g, a.s), pb = G.evaluate(b.g, b.s);
      if (pa.curvature > 0.0 && pb.curvature > 0.0)
      {
        const Vec2 ca = pa.p + pa.n / pa.curvature, cb = pb.p + pb.n / pb.curvature;
        concentric = (ca - cb).norm() <= 1e-9 * L;
      }
    }
    if (G[a.g].next != b.g && !concentric)
      return false;
    int g = a.g;
    stretch.push_back({ g, { a.s, 1.0 } });
    for (int k = 0; k < 256 && g != b.g; ++k)
    {
      if (G[g].endJunction != VertexKind::Smooth)
        return false;
      g = G[g].next;
      stretch.push_back({ g, { 0.0, g == b.g ? b.s : 1.0 } });
    }
    if (g != b.g)
      return false;
  }
  kappa = -1.0;
  for (const auto& [g, range] : stretch)
  {
    if (G[g].kind != GeneratorKind::Edge)
      return false;
    const double lo = range.first, hi = std::max(range.first, range.second);
    // Sample, then refine the best sample by golden-section search. A conic arc (degree
    // ≤ 2: less than half an ellipse, or a parabola's or hyperbola's arc) has at most one
    // vertex of maximal curvature inside, so a few samples bracket it; other curves may
    // wiggle and get more.
    const int n = G.boundary().edges()[G[g].edge].curve.degree() <= 2 ? 8 : 32;
    double bestS = lo, bestK = -1e300;
    for (int k = 0; k <= n; ++k)
    {
      const double s = lo + (hi - lo) * k / n;
      const double c = G.evaluate(g, s).curvature;
      if (c > bestK)
      {
        bestK = c;
        bestS = s;
      }
    }
    // One new evaluation per round (the other inner point is kept), down to 1e-10 of the
    // parameter: the centre of curvature is stationary at the maximum, so it moves by the
    // square of that (and the curvature's rounding hides the peak below ~1e-8 anyway).
    double l = std::max(lo, bestS - (hi - lo) / n), h = std::min(hi, bestS + (hi - lo) / n);
    // The best sample at an end of the range that is no lower than its neighbour 1e-10
    // inside is the maximum to that precision (the search is unimodal in [l, h]): an
    // ellipse's vertex where two of its arcs meet, without forty golden sections. It is
    // that end exactly, so a front can land on it (a maximum 1e-11 short of a
    // generator's end would reject every step onto the end as passing it).
    const double probe = 1e-10;
    if (bestS == lo && h - l > probe && G.evaluate(g, lo + probe).curvature <= bestK)
      h = lo;
    else if (bestS == hi && h - l > probe && G.evaluate(g, hi - probe).curvature <= bestK)
      l = hi;
    const double phi = 0.5 * (std::sqrt(5.0) - 1.0);
    double m1 = h - phi * (h - l), m2 = l + phi * (h - l);
    double k1 = 0.0, k2 = 0.0;
    if (h - l > probe)
    {
      k1 = G.evaluate(g, m1).curvature;
      k2 = G.evaluate(g, m2).curvature;
    }
    for (int it = 0; it < 60 && h - l > probe; ++it)
    {
      if (k1 < k2)
      {
        l = m1;
        m1 = m2;
        k1 = k2;
        m2 = l + phi * (h - l);
        k2 = G.evaluate(g, m2).curvature;
      }
      else
      {
        h = m2;
        m2 = m1;
        k2 = k1;
        m1 = h - phi * (h - l);
        k1 = G.evaluate(g, m1).curvature;
      }
    }
    const double s = 0.5 * (l + h);
    const double c = G.evaluate(g, s).curvature;
    if (c > kappa)
    {
      kappa = c;
      at = location(g, s);
    }
  }
  return kappa > 0.0;
}

void Tracer::trace(const Pending& p)
{
  MedialSegment seg;
  seg.startNode = p.node;
  seg.generators[0] = p.a.g;
  seg.generators[1] = p.b.g;
  const MedialNode& start = Graph.nodes[p.node];
  Front a{ p.a.g, p.a.s }, b{ p.b.g, p.b.s };
  BisectorState y{ a.s, b.s, start.sample.radius };
#ifdef EXACTMAT_TRACE_DEBUG
  std::fprintf(stderr, "trace from node %d (%.12g %.12g r %.12g): a g%d s%.12g  b g%d s%.12g\n", p.node,
    start.sample.x.x(), start.sample.x.y(), start.sample.radius, a.g, a.s, b.g, b.s);
#endif
  // Both generators where the last accepted step's corrector left them: the sample's
  // footpoints and the next step's point, tangent and weights are there (four
  // evaluations per sample saved; the same values, bit for bit).
  struct
  {
    int ga = -1, gb = -1;
    double sa = 0.0, sb = 0.0;
    GeneratorPoint pa, pb;
  } last;
  auto evaluateA = [&](double s) { return a.g == last.ga && s == last.sa ? last.pa : G.evaluate(a.g, s); };
  auto evaluateB = [&](double s) { return b.g == last.gb && s == last.sb ? last.pb : G.evaluate(b.g, s); };
  auto sampleOf = [&](const Vec2& x, double r) {
    MedialSample s;
    s.x = x;
    s.radius = r;
    const GeneratorPoint pa = evaluateA(a.s), pb = evaluateB(b.s);
    s.foot[0] = { a.g, a.s, pa.p, pa.n, false };
    s.foot[1] = { b.g, b.s, pb.p, pb.n, false };
    return s;
  };
  seg.samples.push_back(sampleOf(start.sample.x, y.r));

  const double tolerance = O.tolerance * L;
  // A chord is accepted when the estimated deviation is below this fraction of the
  // tolerance: the estimate is a parabola's through three points, and the curve's
  // third-order part can put its true largest deviation off the middle and above it.
  constexpr double Accept = 0.95;
  // The first step is the longest: a step too long is rejected on its measured chord error,
  // which also sizes the next try (down to a fifth), while growing to the right step from a
  // short one costs a sample (two disk tests) per doubling. Between two straight edges the
  // MAT is a straight line and its radius linear: no step has a chord error at all.
  double h = O.fixedStep ? O.step * L : 0.05 * L;
  const double stepsPerCheck = std::round(O.branchCheckStep / O.step);
  const int checkEvery = O.fixedStep && stepsPerCheck > 1.0 ? static_cast<int>(std::min(stepsPerCheck, 1e6)) : 1;
  int sinceCheck = 0;
  bool checkEveryStep = !O.fixedStep;
  // Checkpoint for the fixed-step mode's backtracking to the last checked point.
  struct Checkpoint
  {
    Front a, b;
    BisectorState y;
    size_t samples, coverage;
  } good{ a, b, y, seg.samples.size(), Cover.mark() };

  // Whether each front has moved off its starting place (see the sliver rule below).
  bool aLeftStart = false, bLeftStart = false;
  // The generator pair whose sweep was undecided (a curved edge within its reach): its
  // steps are tested disk by disk, at most 0.05 of the size apart.
  int noSweepA = -1, noSweepB = -1;
  // The last disk known to be empty (to the tracer's margin): the start node's, then each
  // accepted step's end. A sweep from it onto another such disk searches only its slivers.
  Vec2 emptyX = start.sample.x;
  double emptyR = start.sample.radius;
  struct
  {
    bool valid = false, closing = false;
    int ag = -1, bg = -1;
    BoundaryLocation lmpc;
    double kappa = 0.0;
    Stretch stretch;
  } cache;
  // Fixed-step mode overshot a branch point somewhere since the last check: go back to
  // the checkpoint and check every step from there.
  auto backtrack = [&]() {
    a = good.a;
    b = good.b;
    y = good.y;
    seg.samples.resize(good.samples);
    Cover.undo(good.coverage);
    checkEveryStep = true;
  };
  int endNode = -1;
  auto finish = [&](int node) {
    endNode = node;
  };

  // A smooth junction is smooth to the angular tolerance only (a circle moved to 1e7 × its
  // size has corners of 1e-9 rad between its arcs): the state of a front just moved onto
  // the next generator is on the new bisector to that angle only. Solve it again with that
  // front held at its start; where that would send the other front back (a junction
  // convex by a hair) hold the other front instead. What the jump skips is covered.
  // Moves both fronts to state t, covering the boundary they sweep on the way.
  auto advanceTo = [&](const BisectorState& t) {
    a.interval = Cover.cover(a.g, a.s, t.sa, a.interval);
    b.interval = Cover.cover(b.g, t.sb, b.s, b.interval);
    a.s = t.sa;
    b.s = t.sb;
    y = t;
  };
  auto resync = [&](int switched, bool anyDirection = false) {
    const Bisector Bs(G, a.g, b.g);
    const Vec2 before = Bs.point(y);
    for (const int held : { switched, 1 - switched })
    {
      BisectorState t = y;
      const bool solved = Bs.correct(t, held, 1e-13 * L);
#ifdef EXACTMAT_TRACE_DEBUG
      std::fprintf(stderr, "  resync held %d: a g%d s%.15g b g%d s%.15g -> solved %d sa %.15g sb %.15g moved %.3g\n", held, a.g, a.s, b.g, b.s, (int)solved, t.sa, t.sb, (Bs.point(t) - before).norm());
#endif
      if (!solved || (Bs.point(t) - before).norm() > 1e-6 * L)
        continue;
      // A front that would pass its own generator's end stops there (and moves on next).
      t.sa = std::min(t.sa, 1.0);
      t.sb = std::max(t.sb, 0.0);
      if (!anyDirection && !(t.sa >= a.s && t.sb <= b.s))
        continue;
      if (anyDirection && !(t.sa >= 0.0 && t.sb <= 1.0))
        continue;
      advanceTo(t);
      return;
    }
  };
  // A segment of two straight edges ending inside a cluster of branch points (see
  // planLineCluster) ends where the lines' medial tree has it end — to rounding, or where
  // the disk tests, blind within their margin, let it run past — and the tree's nodes and
  // segments around it join the graph. False when there is no such cluster.
  auto endInCluster = [&](const Vec2& xb, double r) {
    const ClusterPlan plan = planLineCluster(xb, r, a.g, b.g);
    if (plan.incoming < 0)
      return false;
    // The segment ends where the lines' tree has it end (to rounding, where the disk
    // tests saw the cluster): its fronts and samples go there.
    const ClusterPlan::Node& at = plan.nodes[plan.incoming];
    double sa = a.s, sb = b.s;
    for (const BoundaryLocation& f : at.feet)
    {
      sa = f.g == a.g ? f.s : sa;
      sb = f.g == b.g ? f.s : sb;
    }
    // Not behind the segment's start (the disk tests may have run past the tree's node by
    // as far as they are blind: their margin over the rate at which the third line comes in).
    const BoundaryLocation &a0 = seg.samples.front().foot[0], &b0 = seg.samples.front().foot[1];
    if ((a0.g == a.g && sa < a0.s) || (b0.g == b.g && sb > b0.s))
      return false;
    if (sa < a.s)
      Cover.retreat(a.g, a.interval, sa, +1);
    else
      a.interval = Cover.cover(a.g, a.s, sa, a.interval);
    if (sb > b.s)
      Cover.retreat(b.g, b.interval, sb, -1);
    else
      b.interval = Cover.cover(b.g, sb, b.s, b.interval);
    a.s = sa;
    b.s = sb;
    if (seg.samples.size() > 1)
      seg.samples.pop_back();
    while (seg.samples.size() > 1 &&
      ((seg.samples.back().foot[0].g == a.g && seg.samples.back().foot[0].s > sa) ||
        (seg.samples.back().foot[1].g == b.g && seg.samples.back().foot[1].s < sb)))
      seg.samples.pop_back();
    seg.samples.push_back(sampleOf(at.x, at.r));
    const std::vector<int> ids = commitLineCluster(plan);
    finish(ids[plan.incoming]);
    // The wedges the tree's own segments fill are not traced again (a segment of
    // 1e-12 sweeps less than the coverage can tell).
    for (const int n : ids)
    {
      absorbContinuum(n);
      for (const auto& wedge : wedgesOf(n))
      {
        const BoundaryLocation &fa = wedge.first, &fb = wedge.second;
        const bool filled = std::any_of(Graph.nodes[n].segments.begin(), Graph.nodes[n].segments.end(), [&](int sid) {
          const MedialSegment& t = Graph.segments[sid];
          return (t.generators[0] == fa.g && t.generators[1] == fb.g) || (t.generators[0] == fb.g && t.generators[1] == fa.g);
        });
        if (!filled && !coveredAhead(fa.g, fa.s, +1) && !coveredAhead(fb.g, fb.s, -1))
          Queue.push_back({ n, fa, fb });
      }
    }
    return true;
  };
  // The segment ends at the branch point (xb, r), its last sample: a new node with the
  // footpoints found there (and its wedges to trace), or the node already there, exactly
  // where it is. Distinct branch points of a cluster may lie 1e-8 apart: only points
  // closer than the verification's tolerance are the same node.
  auto endAtBranchPoint = [&](const Vec2& xb, double r) {
    std::vector<BoundaryLocation> fps = G.footpointsWithin(xb, r * (1.0 + 1e-10) + 1e-11 * L);
    // The point is on this pair's bisector: it touches both fronts' generators where the
    // fronts are, whether or not the search, to its tight tolerance, says so. Far from the
    // origin a foot beside a curvature peak at a smooth junction can fall out (the branch
    // point then looked like a plain point, and the wedge towards the peak was never
    // traced: a random blob moved 9e5 × its size).
    for (const Front& f : { a, b })
    {
      const BoundaryLocation at = location(f.g, f.s);
      const bool present = std::any_of(fps.begin(), fps.end(),
        [&](const BoundaryLocation& o) { return (o.point - at.point).norm() <= 1e-9 * L; });
      if (!present && std::abs((at.point - xb).norm() - r) <= 1e-9 * L)
        fps.push_back(at);
    }
    const int id = findNode(xb, NodeMerge * L);
#ifdef EXACTMAT_TRACE_DEBUG
    std::fprintf(stderr, "  branch point (%.12g %.12g) r %.12g, existing node %d, feet:", xb.x(), xb.y(), r, id);
    for (const BoundaryLocation& f : fps)
      std::fprintf(stderr, " g%d@%.12g", f.g, f.s);
    std::fprintf(stderr, "\n");
#endif
    if (id < 0 && endInCluster(xb, r))
      return;
    if (id < 0)
    {
      finish(addNode(xb, r, fps.size() >= 3 ? MedialPointType::Branch : MedialPointType::Normal, fps));
      spawnWedges(endNode);
      return;
    }
    seg.samples.back().x = Graph.nodes[id].sample.x;
    seg.samples.back().radius = Graph.nodes[id].sample.radius;
    finish(id);
    mergeIntoNode(id, fps);
  };
  // A front at a convex vertex that the other front does not share, with a disk of
  // radius > 0: the vertex is almost flat, and the edge after it meets this pair at a
  // branch point the steps' disk tests (empty to a margin) did not tell from the vertex's
  // normal. Polish that branch point and end there; false when it is not one.
  auto branchAtConvexVertex = [&](bool frontA) {
    if (y.r <= 1e-9 * L)
      return false;
    int ga = a.g, gb = b.g, gc = frontA ? G[a.g].next : G[b.g].prev;
    if (gc < 0 || gc == a.g || gc == b.g)
      return false;
    BisectorState t = y;
    double sc = frontA ? 0.0 : 1.0;
    if (!polishBranchPoint(G, ga, gb, gc, t.sa, t.sb, sc, t.r, 1e-14 * L) || ga != a.g || gb != b.g)
      return false;
    // It lies between the last two samples (the step that reached the vertex passed it
    // at a grazing angle): no farther back than the one before.
    const Bisector Bv(G, a.g, b.g);
    const Vec2 xb = Bv.point(t), xv = Bv.point(y);
    const double back = seg.samples.size() > 1 ? (seg.samples[seg.samples.size() - 2].x - xv).norm() : 0.0;
    if ((xb - xv).norm() > std::max(1e-6 * L, 1.01 * back) || !emptyDisk(xb, t.r))
      return false;
    // The front went up to the vertex; the segment ends short of it.
    const double aWas = a.s, bWas = b.s;
    advanceTo(t);
    if (t.sa < aWas)
      Cover.retreat(a.g, a.interval, t.sa, +1);
    if (t.sb > bWas)
      Cover.retreat(b.g, b.interval, t.sb, -1);
    // So are the samples: a footpoint sequence that went back would sweep the loop.
    while (seg.samples.size() > 1 &&
      ((seg.samples.back().foot[0].g == a.g && seg.samples.back().foot[0].s > t.sa) ||
        (seg.samples.back().foot[1].g == b.g && seg.samples.back().foot[1].s < t.sb)))
      seg.samples.pop_back();
    seg.samples.push_back(sampleOf(xb, t.r));
#ifdef EXACTMAT_TRACE_DEBUG
    std::fprintf(stderr, "  branch at the convex vertex after g%d: (%.12g %.12g) r %.12g\n",
      frontA ? a.g : b.g, xb.x(), xb.y(), t.r);
#endif
    endAtBranchPoint(xb, t.r);
    return true;
  };
  // The node's footpoints are polished with the generators that meet there, which at a
  // junction of pieces may be the neighbours of this wedge's (to rounding): start on
  // this pair's own bisector, either front held.
  resync(0, true);
  for (int iteration = 0; endNode < 0; ++iteration)
  {
    if (iteration > O.maxSamplesPerSegment)
    {
      fail("2D MAT: tracing the segment of generators ", a.g, " and ", b.g,
        " did not end within ", O.maxSamplesPerSegment, " steps (near ",
        G.describe(seg.samples.back().x), ")");
    }
    // Fronts at the end of their generator move on, or stop at a convex vertex.
    if (a.s >= 1.0 - ParamEps)
    {
      if (G[a.g].endJunction == VertexKind::Convex && G[a.g].next != b.g && branchAtConvexVertex(true))
        break;
      if (G[a.g].endJunction == VertexKind::Convex)
      {
        const Vec2 v = G.evaluate(a.g, 1.0).p;
        const int id = findNode(v, 1e-9 * L);
        finish(id >= 0 ? id : addNode(v, 0.0, MedialPointType::ConvexVertexEnd, { location(a.g, 1.0) }));
        seg.samples.push_back(sampleOf(v, 0.0));
        Cover.cover(b.g, 0.0, b.s, b.interval);
        break;
      }
      a = Front{ G[a.g].next, 0.0 };
      y.sa = 0.0;
      resync(0);
    }
    if (b.s <= ParamEps)
    {
      if (G[b.g].startJunction == VertexKind::Convex && G[b.g].prev != a.g && branchAtConvexVertex(false))
        break;
      if (G[b.g].startJunction == VertexKind::Convex)
      {
        const Vec2 v = G.evaluate(b.g, 0.0).p;
        const int id = findNode(v, 1e-9 * L);
        finish(id >= 0 ? id : addNode(v, 0.0, MedialPointType::ConvexVertexEnd, { location(b.g, 0.0) }));
        seg.samples.push_back(sampleOf(v, 0.0));
        Cover.cover(a.g, a.s, 1.0, a.interval);
        break;
      }
      b = Front{ G[b.g].prev, 1.0 };
      y.sb = 1.0;
      resync(1);
      // Both fronts at junctions at once (a symmetric lobe): the resync may have put
      // front a on its end.
      if (a.s >= 1.0 - ParamEps)
        continue;
    }
    const Bisector B(G, a.g, b.g);
    // Both generators at y, once: the point, the tangent, the motion and the step's
    // weights all start from them (each used to evaluate them again).
    const GeneratorPoint ga0 = evaluateA(y.sa), gb0 = evaluateB(y.sb);
    const Vec2 x0 = ga0.p + y.r * ga0.n;

    // Closing in on a point of locally maximal positive curvature: end at its centre.
    // The LMPC of the stretch between the fronts does not move while the stretch shrinks
    // around it: search again only when the stretch changes generators or loses it.
    bool closing = false;
    if (cache.valid && a.g == cache.ag && b.g == cache.bg &&
      (cache.lmpc.g != a.g || cache.lmpc.s >= a.s) && (cache.lmpc.g != b.g || cache.lmpc.s <= b.s))
    {
      closing = cache.closing;
    }
    else
    {
      cache.closing = lmpcBetween(a, b, cache.lmpc, cache.kappa, cache.stretch);
      cache.valid = true;
      cache.ag = a.g;
      cache.bg = b.g;
      closing = cache.closing;
    }
    const BoundaryLocation lmpc = cache.lmpc;
    const double kappa = cache.kappa;
    Stretch stretch = cache.stretch;
    if (closing)
    {
      // The cached stretch starts where the fronts were then; clip it to where they are.
      for (auto& [g, range] : stretch)
      {
        if (g == a.g)
          range.first = std::max(range.first, a.s);
        if (g == b.g)
          range.second = std::min(range.second, b.s);
      }
    }
    const Vec2 centre = closing ? Vec2(lmpc.point + lmpc.normal / kappa) : Vec2::Zero();
    auto endAtCentre = [&]() {
      const int id = findNode(centre, 1e-9 * L);
#ifdef EXACTMAT_TRACE_DEBUG
      std::fprintf(stderr, "  end at centre (%.12g %.12g) 1/kappa %.12g lmpc g%d s%.15g existing %d, fronts a g%d s%.12g b g%d s%.12g r %.12g\n",
        centre.x(), centre.y(), 1.0 / kappa, lmpc.g, lmpc.s, id, a.g, a.s, b.g, b.s, y.r);
#endif
      finish(id >= 0 ? id
                     : addNode(centre, 1.0 / kappa, MedialPointType::CurvatureCentreEnd, { lmpc }));
      MedialSample s = sampleOf(centre, 1.0 / kappa);
      s.foot[0] = s.foot[1] = lmpc;
      seg.samples.push_back(s);
      for (const auto& [g, range] : stretch)
        Cover.cover(g, range.first, range.second, g == a.g ? a.interval : (g == b.g ? b.interval : -1));
    };
    if (closing && (x0 - centre).norm() <= std::max(h, 1e-9 * L))
    {
      // The radius grows like a square root into such an end: accept the last chord only
      // if its midpoint is within the tolerance too (or the steps cannot shrink further).
      bool chordOk = O.fixedStep || h < 1e-9 * L || (x0 - centre).norm() <= 1e-9 * L;
      if (!chordOk)
      {
        BisectorState ym{ 0.5 * (y.sa + (lmpc.g == a.g ? lmpc.s : y.sa)),
          0.5 * (y.sb + (lmpc.g == b.g ? lmpc.s : y.sb)), 0.5 * (y.r + 1.0 / kappa) };
        const int hold = (lmpc.g == a.g) ? 0 : 1;
        chordOk = B.correct(ym, hold, 1e-13 * L) &&
          chordDeviation(x0, y.r, B.point(ym), ym.r, centre, 1.0 / kappa) <= O.tolerance * L;
      }
      if (chordOk && !checkEveryStep && sinceCheck > 0 && !emptyDisk(x0, y.r))
      {
        backtrack(); // fixed-step mode: a branch point was passed since the last check
        continue;
      }
      if (chordOk)
      {
        endAtCentre();
        break;
      }
      h *= 0.5;
    }

    const Eigen::Vector3d t = B.tangent(ga0, gb0, y.r, +1, -1);
    const double m = B.motion(ga0, gb0, y.r, t);
    if (!(m > 0.0) || t.isZero())
    {
      if (closing)
      {
        endAtCentre();
        break;
      }
      fail("2D MAT: the bisector of generators ", a.g, " and ", b.g, " is singular at ",
        G.describe(x0));
    }

    // Between two straight edges the MAT is a straight line and its radius linear: one
    // step may go all the way to where a third entity comes in, found by one sweep of
    // the disks in closed form (Generators::firstContact), not by disk tests along it.
    bool sweep = !O.fixedStep && G.straight(a.g) && G.straight(b.g) && !(a.g == noSweepA && b.g == noSweepB);
    // Its length: as far as the disks' reach stays local (a sweep costs the edges within
    // it), no less than the usual step.
    if (sweep)
      h = std::max(0.05 * L, 64.0 * y.r);
    bool accepted = false;
    for (int attempt = 0; attempt < 60 && !accepted; ++attempt)
    {
      Eigen::Vector3d dy = t * (h / m);
      // Land exactly on a generator's end, or on boundary another front already swept.
      double lambda = 1.0;
      int fixed = -1;
      double fixedValue = 0.0;
      if (dy(0) > 0.0 && a.s + dy(0) > 1.0)
      {
        lambda = (1.0 - a.s) / dy(0);
        fixed = 0;
        fixedValue = 1.0;
      }
      if (dy(1) < 0.0 && b.s + dy(1) < 0.0 && -b.s / dy(1) < lambda)
      {
        lambda = -b.s / dy(1);
        fixed = 1;
        fixedValue = 0.0;
      }
      double hitA = Cover.firstAhead(a.g, a.s, a.s + lambda * dy(0), +1, a.interval);
      double hitB = Cover.firstAhead(b.g, b.s, b.s + lambda * dy(1), -1, b.interval);
      // Slivers left by the bisection that found this segment's start node are not
      // boundary traced before.
      if (!aLeftStart && a.g == p.a.g && std::abs(hitA - p.a.s) < CoverageSlop)
        hitA = NaN;
      if (!bLeftStart && b.g == p.b.g && std::abs(hitB - p.b.s) < CoverageSlop)
        hitB = NaN;
      bool joining = false;
      if (!std::isnan(hitA) && dy(0) > 0.0)
      {
        lambda = std::max(0.0, (hitA - a.s) / dy(0));
        fixed = 0;
        fixedValue = hitA;
        joining = true;
      }
      if (!std::isnan(hitB) && dy(1) < 0.0 && (hitB - b.s) / dy(1) <= lambda)
      {
        lambda = std::max(0.0, (hitB - b.s) / dy(1));
        fixed = 1;
        fixedValue = hitB;
        joining = true;
      }
      BisectorState y1{ y.sa + lambda * dy(0), y.sb + lambda * dy(1), y.r + lambda * dy(2) };
      if (fixed < 0)
      {
        // Hold the unknown that moves most, measured by its effect on the geometry.
        const GeneratorPoint &ga = ga0, &gb = gb0;
        const double w[3] = { std::abs(t(0)) * (ga.dp.norm() + y.r * ga.dn.norm()),
          std::abs(t(1)) * (gb.dp.norm() + y.r * gb.dn.norm()), std::abs(t(2)) };
        fixed = static_cast<int>(std::max_element(w, w + 3) - w);
      }
      else
      {
        (fixed == 0 ? y1.sa : y1.sb) = fixedValue;
      }
      const double solveTol = 1e-13 * L;
      // The MAT point halfway (in the held unknown) between two states of this pair, and
      // how far the chord between them strays from the curve (the step control's measure).
      struct Halfway
      {
        BisectorState y;
        GeneratorPoint ga, gb;
        Vec2 x;
        double deviation;
      };
      auto halfway = [&](const BisectorState& y0, const Vec2& p0, const BisectorState& y2,
                       const Vec2& p2, Halfway& m) {
        m.y = BisectorState{ 0.5 * (y0.sa + y2.sa), 0.5 * (y0.sb + y2.sb), 0.5 * (y0.r + y2.r) };
        if (!B.correct(m.y, fixed, solveTol, &m.ga, &m.gb))
          return false;
        m.x = m.ga.p + m.y.r * m.ga.n;
        m.deviation = chordDeviation(p0, y0.r, m.x, m.y.r, p2, y2.r);
        return true;
      };
      GeneratorPoint ga1, gb1; // both generators at y1, from the corrector's last check
      bool ok = B.correct(y1, fixed, solveTol, &ga1, &gb1);
      // The corrector may carry a front past its generator's end (onto the extrapolated
      // curve): solve again with that front held at the end.
      if (ok && fixed != 0 && y1.sa > 1.0 + ParamEps)
      {
        y1.sa = 1.0;
        fixed = 0;
        ok = B.correct(y1, fixed, solveTol, &ga1, &gb1);
      }
      if (ok && fixed != 1 && y1.sb < -ParamEps)
      {
        y1.sb = 0.0;
        fixed = 1;
        ok = B.correct(y1, fixed, solveTol, &ga1, &gb1);
      }
      ok = ok && y1.sa >= a.s - 1e-9 && y1.sb <= b.s + 1e-9 && y1.sa <= 1.0 + ParamEps &&
        y1.sb >= -ParamEps && y1.r >= 0.0;
      // When a front had to be held at its generator's end instead, the step lands there,
      // short of the boundary traced before: it is no join (the fronts move on).
      if (joining)
        joining = (!std::isnan(hitA) && y1.sa >= hitA - ParamEps) ||
          (!std::isnan(hitB) && y1.sb <= hitB + ParamEps);
      if (ok && closing)
      {
        // Do not step onto or past the LMPC: the segment ends at its centre, reached by
        // the closing test above (the MAT point within a step of it) before the fronts
        // get there (they move like the square root of the point's distance to it). A
        // front that lands on the LMPC alone has a disk larger than the osculating one
        // there, which fails the curvature criterion; both landing on it at once leave the
        // radius undetermined (one point, one normal). An LMPC at a smooth junction is
        // also the end of the generator before it (a blob whose curvature peaks where two
        // pieces meet).
        const bool pastA = lmpc.g == a.g && y1.sa > lmpc.s + 1e-12;
        const bool pastB = lmpc.g == b.g && y1.sb < lmpc.s - 1e-12;
        const bool aAt = (lmpc.g == a.g && y1.sa >= lmpc.s - ParamEps) ||
          (lmpc.g == G[a.g].next && lmpc.s <= ParamEps && G[a.g].endJunction == VertexKind::Smooth &&
            y1.sa >= 1.0 - ParamEps);
        const bool bAt = (lmpc.g == b.g && y1.sb <= lmpc.s + ParamEps) ||
          (lmpc.g == G[b.g].prev && lmpc.s >= 1.0 - ParamEps && G[b.g].startJunction == VertexKind::Smooth &&
            y1.sb <= ParamEps);
        if (pastA || pastB || aAt || bAt)
          ok = false;
      }
      Vec2 x1 = ok ? Vec2(ga1.p + y1.r * ga1.n) : Vec2::Zero();
      // A straight step that passes a node found before, or joins boundary traced before
      // at one, ends on it exactly (its disk is the node's: found empty).
      int ontoNode = -1;
      if (ok && sweep)
      {
        BisectorState at;
        ontoNode = nodeAhead(a.g, b.g, y, y1, x0, x1, at);
        if (ontoNode >= 0)
        {
          y1 = at;
          ga1 = G.evaluate(a.g, y1.sa);
          gb1 = G.evaluate(b.g, y1.sb);
          x1 = Graph.nodes[ontoNode].sample.x;
          joining = false;
        }
      }
      // Next step from the measured chord error (∝ h²), kept within [×0.2, ×2].
      double resize = 0.5;
      // Where the sweep of a straight step meets the boundary first (> 1: nowhere).
      double contactAt = INFINITY;
      bool swept = false;
      if (ok && sweep)
      {
        double t = INFINITY;
        // Both end disks empty — the start's within the last one found so (a front moved
        // onto the next generator moves the point by rounding: its disk is taken smaller
        // by as much), the end's as a node's (every node's disk was found empty, to at
        // most this margin, when it was made) or by its own test, which stops at the first
        // piece inside when it is not — leave only the slivers beside the touched lines.
        const double moved = (x0 - emptyX).norm() + std::abs(y.r - emptyR);
        const bool startEmpty = moved <= 0.1 * diskMargin(y.r);
        const double r0 = y.r - diskMargin(y.r) - (startEmpty ? moved : 0.0);
        // The step's state at τ (the bisector is straight and its state linear along it).
        auto xAt = [&](double tau) { return Vec2(x0 + tau * (x1 - x0)); };
        auto rAt = [&](double tau) { return y.r + tau * (y1.r - y.r); };
        auto emptyAt = [&](double tau) {
          return emptyDisk(xAt(tau), rAt(tau), a.g, y.sa + tau * (y1.sa - y.sa), b.g, y.sb + tau * (y1.sb - y.sb));
        };
        SweepContact c = SweepContact::Clear;
        if (!startEmpty)
          c = G.firstContact(x0, r0, x1, y1.r - diskMargin(y1.r), a.g, b.g, t);
        else if (ontoNode >= 0 || emptyAt(1.0))
          c = G.firstContact(x0, r0, x1, y1.r - diskMargin(y1.r), a.g, b.g, t, diskMargin(std::max(y.r, y1.r)) + moved);
        else
        {
          // The end disk holds a piece: a third entity comes in on the way. Halve the
          // stretch where it does by disk tests (from the empty start, to the end), sweep
          // what lies before as slivers between empty disks and the rest in full — a full
          // sweep reaches every edge within half its length of its middle, a disk only
          // those within its radius.
          double lo = 0.0, hi = 1.0;
          for (int halving = 0; halving < 4 && (hi - lo) * (x1 - x0).norm() > 4.0 * y1.r; ++halving)
            (emptyAt(0.5 * (lo + hi)) ? lo : hi) = 0.5 * (lo + hi);
          if (lo > 0.0)
            c = G.firstContact(x0, r0, xAt(lo), rAt(lo) - diskMargin(rAt(lo)), a.g, b.g, t,
              diskMargin(std::max(y.r, rAt(lo))) + moved);
          if (c == SweepContact::Contact)
            t *= lo;
          // Then from lo to hi, or (should the margins disagree) on to the step's end.
          for (const double end : { hi, 1.0 })
            if (c == SweepContact::Clear)
            {
              c = G.firstContact(xAt(lo), rAt(lo) - diskMargin(rAt(lo)), xAt(end), rAt(end) - diskMargin(rAt(end)), a.g,
                b.g, t);
              t = lo + t * (end - lo);
            }
        }
        if (c == SweepContact::Undecided)
        {
          noSweepA = a.g;
          noSweepB = b.g;
          sweep = false;
          ok = false;
          h = std::min(h, 0.1 * L);
        }
        else
        {
          swept = true;
          resize = 2.0;
          if (c == SweepContact::Contact)
            contactAt = t;
        }
      }
      else if (ok && !O.fixedStep)
      {
        Halfway m;
        if (halfway(y, x0, y1, x1, m))
        {
          const double err = m.deviation;
          resize = err > 0.0 ? std::min(2.0, std::max(0.2, 0.9 * std::sqrt(tolerance / err))) : 2.0;
          // A step that joins boundary traced before is measured too (it lands where it
          // must, but may be too long to get there in one chord: a segment between two
          // branch points can be this one chord).
          if (err > Accept * tolerance)
            ok = false;
          // A boundary feature whose MAT interrupts this pair's only between the two ends
          // of the step would go unseen by checks at the ends: check halfway too, and
          // take a shorter step when that disk is not empty.
          else if (!joining && !emptyDisk(m.x, m.y.r, a.g, m.y.sa, b.g, m.y.sb))
          {
            ok = false;
            resize = 0.5;
          }
        }
        else
          ok = false;
      }
      if (!ok)
      {
#ifdef EXACTMAT_TRACE_DEBUG
        std::fprintf(stderr, "   reject h %.3g resize %.3g fixed %d y1 %.15g %.15g %.15g closing %d joining %d\n", h, resize, fixed, y1.sa, y1.sb, y1.r, (int)closing, (int)joining);
#endif
        h *= std::min(resize, 0.5);
        if (h < 1e-14 * L)
        {
          if (closing)
          {
            endAtCentre();
            accepted = true;
            break;
          }
          fail("2D MAT: cannot continue the segment of generators ", a.g, " and ", b.g,
            " at ", G.describe(x0), ", radius ", G.boundary().userLength(y.r));
        }
        continue;
      }
      // The step is geometrically sound; is the point on the MAT?
      ++sinceCheck;
      // Steps that land on a generator's end may end the segment there (a convex
      // vertex): they are always checked, as are joins.
      const bool landsOnEnd = (fixed == 0 && y1.sa >= 1.0 - ParamEps) || (fixed == 1 && y1.sb <= ParamEps);
      // Prop. 4.2: fronts closing in on the convex vertex their generators share meet no
      // other branch point on the way (the curvature criterion is still checked).
      const bool sharedConvexVertex = G[a.g].next == b.g && G[a.g].endJunction == VertexKind::Convex;
      const bool check = !sharedConvexVertex &&
        (checkEveryStep || sinceCheck >= checkEvery || joining || landsOnEnd);
      const bool valid = curvatureOk(a.g, ga1, y1.r) && curvatureOk(b.g, gb1, y1.r) &&
        (!check || (swept ? !(contactAt <= 1.0) : emptyDisk(x1, y1.r, a.g, y1.sa, b.g, y1.sb)));
      if (!valid)
      {
        if (!checkEveryStep)
        {
          backtrack();
          accepted = true; // restart the outer loop from the checkpoint
          break;
        }
        // Bisection between the last valid point (y) and this one for the branch point:
        // coarse first, then polished exactly with the third generator; only if that
        // fails is the bisection carried on to full precision.
        double lo = 0.0, hi = 1.0;
        BisectorState yb = y;
        auto bisect = [&](double precision) {
          for (int it = 0; it < 60 && (hi - lo) * (x1 - x0).norm() >= precision; ++it)
          {
            const double mid = 0.5 * (lo + hi);
            BisectorState ym{ y.sa + mid * (y1.sa - y.sa), y.sb + mid * (y1.sb - y.sb), y.r + mid * (y1.r - y.r) };
            if (!B.correct(ym, fixed, solveTol))
            {
              hi = mid;
              continue;
            }
            const Vec2 xm = B.point(ym);
            if (curvatureOk(a.g, ym.sa, ym.r) && curvatureOk(b.g, ym.sb, ym.r) &&
              emptyDisk(xm, ym.r, a.g, ym.sa, b.g, ym.sb))
            {
              lo = mid;
              yb = ym;
            }
            else
              hi = mid;
          }
        };
        // Polish with every candidate third generator and keep the branch point met
        // first along the segment whose disk is empty: in a cluster of branch points
        // closer than the bisection's precision (a regular polygon with a vertex moved by
        // 1e-6) several candidates converge, each to its own branch point, and only the
        // first one reached is on this segment's MAT.
        // A node already found there that this pair's bisector passes through (it has
        // footpoints on both generators, ahead of both fronts) is where the segment ends:
        // no polish, no footpoint search — a regular n-gon's centre is reached n times.
        int knownNode = -1;
        auto reuseNode = [&]() {
          const int id = findNode(B.point(yb), 1e-7 * L);
          if (id < 0 || id == p.node)
            return false;
          const MedialNode& n = Graph.nodes[id];
          const BoundaryLocation *fa = nullptr, *fb = nullptr;
          for (const BoundaryLocation& f : n.footpoints)
          {
            if (f.g == a.g && f.s >= y.sa - 1e-9)
              fa = &f;
            if (f.g == b.g && f.s <= y.sb + 1e-9)
              fb = &f;
          }
          if (!fa || !fb || fa == fb)
            return false;
          yb = BisectorState{ fa->s, fb->s, n.sample.radius };
          knownNode = id;
          return true;
        };
        // The polished branch point's fronts may have moved on to the next generators
        // (footpoints at junctions of pieces land on either side under rounding).
        int branchA = a.g, branchB = b.g;
        auto branchPoint = [&](const BisectorState& t, int ga, int gb) -> Vec2 {
          return ga == a.g && gb == b.g ? B.point(t) : Bisector(G, ga, gb).point(t);
        };
        const double strict = 1e-12 * L + 1e-12 * yb.r;
        auto polish = [&](double window, double margin) {
          const Vec2 xg = B.point(yb);
          const auto near = G.footpointsWithin(xg, yb.r * (1.0 + 1e-6) + (window > 1e-6 * L ? window : 1e-7 * L));
          const GeneratorPoint fa = G.evaluate(a.g, yb.sa), fb = G.evaluate(b.g, yb.sb);
          bool found = false;
          BisectorState best = yb;
          int bestA = a.g, bestB = b.g;
          double bestDistance = INFINITY;
          // A candidate at a front's own contact is none; across a convex vertex two feet
          // however close are two contacts (an almost flat vertex next to the branch point).
          auto atFront = [&](const BoundaryLocation& c, int g, const Vec2& p) {
            if ((c.point - p).norm() >= 1e-7 * L)
              return false;
            return !((c.g == G[g].next && G[g].endJunction == VertexKind::Convex) ||
              (c.g == G[g].prev && G[g].startJunction == VertexKind::Convex));
          };
          for (const BoundaryLocation& c : near)
          {
            if (atFront(c, a.g, fa.p) || atFront(c, b.g, fb.p) || c.continuum)
              continue;
            BisectorState yp = yb;
            double sc = c.s;
            int ga = a.g, gb = b.g, gc = c.g;
            if (!polishBranchPoint(G, ga, gb, gc, yp.sa, yp.sb, sc, yp.r, 1e-14 * L))
            {
#ifdef EXACTMAT_TRACE_DEBUG
              std::fprintf(stderr, "  polish with g%d@%.15g failed (fronts g%d@%.15g g%d@%.15g)\n", c.g, c.s, a.g, yb.sa, b.g, yb.sb);
#endif
              continue;
            }
            // A junction is the end of one generator and the start of the next: name it
            // as the fronts do (which moved on within rounding of it).
            if (ga == G[a.g].prev && yp.sa >= 1.0 - 1e-9)
            {
              ga = a.g;
              yp.sa = 0.0;
            }
            if (gb == G[b.g].next && yp.sb <= 1e-9)
            {
              gb = b.g;
              yp.sb = 1.0;
            }
            // Ahead of both fronts: on their generators, or on the ones they move on to.
            // Where the disks are empty only to the input's rounding, the fronts may have
            // passed the branch point by as much: a point just behind them is taken too.
            const bool aheadA = ga == a.g ? yp.sa >= y.sa - 1e-9 : ga == G[a.g].next;
            const bool aheadB = gb == b.g ? yp.sb <= y.sb + 1e-9 : gb == G[b.g].prev;
            const bool neighbours = (ga == a.g || ga == G[a.g].next || ga == G[a.g].prev) &&
              (gb == b.g || gb == G[b.g].next || gb == G[b.g].prev);
            const bool justBehind = margin > strict && neighbours &&
              (branchPoint(yp, ga, gb) - x0).norm() <= 1e-6 * L;
            if (!(aheadA && aheadB) && !justBehind)
            {
#ifdef EXACTMAT_TRACE_DEBUG
              std::fprintf(stderr, "  polish with g%d: g%d@%.15g g%d@%.15g behind the fronts g%d@%.15g g%d@%.15g\n", gc, ga, yp.sa, gb, yp.sb, a.g, y.sa, b.g, y.sb);
#endif
              continue;
            }
            const Vec2 xp = branchPoint(yp, ga, gb);
            if (found && (xp - branchPoint(best, bestA, bestB)).norm() <= 1e-12 * L)
              continue; // the same branch point again (a node of degree k: k candidates)
            const double fromStart = (xp - x0).norm();
#ifdef EXACTMAT_TRACE_DEBUG
            std::fprintf(stderr, "  polish with g%d: g%d g%d (%.15g %.15g) r %.15g fromStart %.3g fromXg %.3g empty %d\n", gc, ga, gb,
              xp.x(), xp.y(), yp.r, fromStart, (xp - xg).norm(),
              (int)!G.anyCloserThan(xp, yp.r - margin));
#endif
            // (Not the node this segment starts from: it cannot end there.)
            const bool atStartNode = (xp - Graph.nodes[p.node].sample.x).norm() <= 1e-13 * L;
            if ((xp - xg).norm() < window && fromStart < bestDistance && !atStartNode &&
              !G.anyCloserThan(xp, yp.r - margin))
            {
              best = yp;
              bestA = ga;
              bestB = gb;
              bestDistance = fromStart;
              found = true;
            }
          }
          if (found)
          {
            yb = best;
            branchA = bestA;
            branchB = bestB;
          }
          return found;
        };
        // Coarse, then polished; the coarse precision follows the step, so a segment
        // shorter than 1e-8 (inside a cluster of branch points) is bisected too.
        // The bisection's disk test has a margin (no less than the input's rounding):
        // where the third generator meets the segment at a grazing angle θ (next to an
        // almost flat convex vertex) it places the branch point up to margin / θ past the
        // true one, anywhere back to the last valid point: polish near first, then there.
        // The disk of the right candidate is empty to rounding; where the input is known to
        // fewer digits than that (far from the origin, pieces meet with kinks of its
        // rounding), to the input's rounding, as the bisection's disk test has it.
        auto locate = [&]() {
          const double wide = 1.01 * (B.point(yb) - x0).norm();
          const double loose = diskMargin(yb.r);
          return reuseNode() || polish(1e-6 * L, strict) || (wide > 1e-6 * L && polish(wide, strict)) ||
            (loose > 2 * strict && polish(1e-6 * L, loose));
        };
        bool located = false;
        if (contactAt <= 1.0)
        {
          // The sweep says where the third entity comes in: polish from there (a regular
          // polygon's n segments into its centre: no n disk tests of n edges each).
          BisectorState yc{ y.sa + contactAt * (y1.sa - y.sa), y.sb + contactAt * (y1.sb - y.sb),
            y.r + contactAt * (y1.r - y.r) };
          if (B.correct(yc, fixed, solveTol))
          {
            yb = yc;
            located = locate();
          }
          if (!located)
            yb = y;
        }
        if (!located)
        {
          bisect(std::min(1e-8 * L, 1e-3 * (x1 - x0).norm()));
          if (!locate())
            bisect(1e-13 * L);
        }
        const Vec2 xb = branchPoint(yb, branchA, branchB);
        // The chord to the branch point is a part of the step whose deviation was
        // measured, not the step: measure it, and put samples in where it strays (a
        // segment between two branch points can be this one chord).
        std::vector<MedialSample> onTheWay;
        if (!O.fixedStep && branchA == a.g && branchB == b.g)
        {
          auto refine = [&](auto&& self, const BisectorState& y0, const Vec2& p0,
                          const BisectorState& y2, const Vec2& p2, int depth) -> void {
            Halfway m;
            if (depth >= 8 || !halfway(y0, p0, y2, p2, m) || m.deviation <= Accept * tolerance)
              return;
            self(self, y0, p0, m.y, m.x, depth + 1);
            MedialSample sample;
            sample.x = m.x;
            sample.radius = m.y.r;
            sample.foot[0] = { a.g, m.y.sa, m.ga.p, m.ga.n, false };
            sample.foot[1] = { b.g, m.y.sb, m.gb.p, m.gb.n, false };
            onTheWay.push_back(sample);
            self(self, m.y, m.x, y2, p2, depth + 1);
          };
          refine(refine, y, x0, yb, xb, 0);
        }
        // Fronts move on to the generators of the polished footpoints (or back, by
        // rounding, to the one just left).
        if (branchA != a.g)
        {
          const bool on = branchA == G[a.g].next;
          if (on)
            Cover.cover(a.g, y.sa, 1.0, a.interval);
          a = Front{ branchA, on ? 0.0 : 1.0 };
          y.sa = a.s;
        }
        if (branchB != b.g)
        {
          const bool on = branchB == G[b.g].prev;
          if (on)
            Cover.cover(b.g, 0.0, y.sb, b.interval);
          b = Front{ branchB, on ? 1.0 : 0.0 };
          y.sb = b.s;
        }
        a.s = yb.sa;
        b.s = yb.sb;
        a.interval = Cover.cover(a.g, y.sa, yb.sa, a.interval);
        b.interval = Cover.cover(b.g, yb.sb, y.sb, b.interval);
        y = yb;
        seg.samples.insert(seg.samples.end(), onTheWay.begin(), onTheWay.end());
        seg.samples.push_back(sampleOf(xb, yb.r));
        // The node is exact to rounding: footpoints farther than that belong to another
        // branch point of a cluster (reached along one of this node's own segments).
        if (knownNode >= 0)
        {
          seg.samples.back().x = Graph.nodes[knownNode].sample.x;
          seg.samples.back().radius = Graph.nodes[knownNode].sample.radius;
          finish(knownNode);
          accepted = true;
          break;
        }
        endAtBranchPoint(xb, yb.r);
        accepted = true;
        break;
      }
      // Accept the step.
      if (swept || check)
      {
        emptyX = x1;
        emptyR = y1.r;
      }
      advanceTo(y1);
      last = { a.g, b.g, y1.sa, y1.sb, ga1, gb1 };
      aLeftStart = aLeftStart || a.g != p.a.g || std::abs(a.s - p.a.s) > 10 * CoverageSlop;
      bLeftStart = bLeftStart || b.g != p.b.g || std::abs(b.s - p.b.s) > 10 * CoverageSlop;
      seg.samples.push_back(sampleOf(x1, y1.r));
      if (check)
      {
        sinceCheck = 0;
        good = Checkpoint{ a, b, y, seg.samples.size(), Cover.mark() };
      }
      if (ontoNode >= 0)
      {
        seg.samples.back().x = Graph.nodes[ontoNode].sample.x;
        seg.samples.back().radius = Graph.nodes[ontoNode].sample.radius;
        finish(ontoNode);
      }
      if (joining)
      {
        // Reached boundary traced before: this point is a node of the graph already — or,
        // in a cluster of branch points that the disk tests did not resolve, the tree's
        // node of this pair, short of it.
        int id = findNode(x1, 1e-6 * L);
        auto touches = [&](int n, int g) {
          return std::any_of(Graph.nodes[n].footpoints.begin(), Graph.nodes[n].footpoints.end(),
            [&](const BoundaryLocation& f) { return f.g == g; });
        };
        if (!(id >= 0 && touches(id, a.g) && touches(id, b.g)) && endInCluster(x1, y1.r))
        {
          accepted = true;
          break;
        }
        if (id < 0)
          id = nodeWithFeet(x1, 1e-4 * L, p.node, ga1.p, gb1.p);
#ifdef EXACTMAT_TRACE_DEBUG
        std::fprintf(stderr, "  join at (%.12g %.12g) r %.12g fixed %d a g%d s%.12g b g%d s%.12g -> node %d\n",
          x1.x(), x1.y(), y1.r, fixed, a.g, y1.sa, b.g, y1.sb, id);
        if (id < 0)
          Cover.dump(a.g), Cover.dump(b.g);
#endif
        if (id < 0)
        {
          fail("2D MAT: the segment of generators ", a.g, " and ", b.g, " reached traced boundary at ",
            G.describe(x1), " where no MAT node is");
        }
        // The node is exact; the step only came within 1e-6 of it (at a grazing angle, or
        // landing on a generator's end): its feet are the node's too, so the footpoints
        // sweep the boundary once.
        MedialSample& last = seg.samples.back();
        last.x = Graph.nodes[id].sample.x;
        last.radius = Graph.nodes[id].sample.radius;
        for (BoundaryLocation& foot : last.foot)
        {
          const Vec2 stepped = foot.point;
          double nearest = INFINITY;
          for (const BoundaryLocation& f : Graph.nodes[id].footpoints)
          {
            if (f.g == foot.g && (f.point - stepped).norm() < nearest)
            {
              nearest = (f.point - stepped).norm();
              foot = f;
            }
          }
        }
        finish(id);
      }
      accepted = true;
      if (!O.fixedStep)
        h = std::min(0.05 * L, h * (joining ? 1.0 : resize));
    }
    if (!accepted)
    {
      fail("2D MAT: no step could be taken on the segment of generators ", a.g, " and ", b.g,
        " at ", G.describe(x0));
    }
  }
  seg.endNode = endNode;
#ifdef EXACTMAT_TRACE_DEBUG
  std::fprintf(stderr, "  ended at node %d (%.12g %.12g) type %d, %zu samples\n", endNode,
    Graph.nodes[endNode].sample.x.x(), Graph.nodes[endNode].sample.x.y(),
    static_cast<int>(Graph.nodes[endNode].type), seg.samples.size());
#endif
  if (endNode == seg.startNode)
  {
    // A sliver that leaves a node of degree k ≥ 4 and comes straight back (its branch
    // points, split by rounding, are closer than NodeMerge): the node stands for it.
    double extent = 0.0;
    for (const MedialSample& m : seg.samples)
      extent = std::max(extent, (m.x - Graph.nodes[endNode].sample.x).norm());
    if (extent <= 1e-8 * L)
    {
      reportProgress();
      return;
    }
  }
  Graph.segments.push_back(std::move(seg));
  const int sid = static_cast<int>(Graph.segments.size()) - 1;
  Graph.nodes[Graph.segments.back().startNode].segments.push_back(sid);
  Graph.nodes[endNode].segments.push_back(sid);
  if (static_cast<int>(Graph.segments.size()) > O.maxSegments)
  {
    fail("2D MAT: more than ", O.maxSegments, " segments; giving up");
  }
  reportProgress();
}

bool Tracer::startAt(int g, double s)
{
  // Shrinking ball (Ma, Bae & Choi): the maximal disk touching the boundary at p. Every
  // footpoint q inside the disk bounds the maximal radius by that of the disk through q
  // tangent at p, |q − p|² / (2 (q − p)·n); the smallest of them is the next radius (one
  // query per round: the first, of the domain's size, asks for the nearest feet only).
  const GeneratorPoint p = G.evaluate(g, s);
  // Disks touching at p are nested, so emptiness is monotone in r.
  auto emptyAt = [&](double rr) {
    return !G.anyCloserThan(p.p + rr * p.n, rr * (1.0 - 1e-12) - 1e-13 * L);
  };
  // The radius of the disk tangent at p through q (∞ when q is p, or behind p's tangent).
  auto tangentRadius = [&](const Vec2& q) {
    const Vec2 d = q - p.p;
    const double denominator = 2.0 * d.dot(p.n);
    return d.norm() > 1e-9 * L && denominator > 0.0 ? d.squaredNorm() / denominator : INFINITY;
  };
  double r = L;
  Vec2 x = p.p + r * p.n;
  bool empty = false;
  for (int it = 0; it < 200; ++it)
  {
    x = p.p + r * p.n;
    double next = r;
    if (it == 0)
    {
      // The first disk, of the domain's size, needs only the nearest boundary point.
      Vec2 q;
      G.distance(x, &q);
      next = std::min(next, tangentRadius(q));
#ifdef EXACTMAT_TRACE_DEBUG
      std::fprintf(stderr, "  shrinking ball round 0: r %.15g, nearest (%.15g %.15g), next %.15g\n", r, q.x(), q.y(), next);
#endif
      if (!(next < r))
        break;
      r = next;
      continue;
    }
    const double reach = r;
    const BoundaryLocation* nearest = nullptr;
    const std::vector<BoundaryLocation> feet = G.footpointsWithin(x, reach * (1.0 + 1e-12) + 1e-12 * L);
    for (const BoundaryLocation& f : feet)
    {
      const double through = tangentRadius(f.point);
      if (through < next)
      {
        next = through;
        nearest = &f;
      }
    }
#ifdef EXACTMAT_TRACE_DEBUG
    std::fprintf(stderr, "  shrinking ball round %d: r %.15g, %zu feet within %.15g, next %.15g\n", it, r, feet.size(), reach, next);
#endif
    if (!(next < r))
      break; // only p, or feet on the circle itself: the disk is maximal
    const bool settled = r - next <= 1e-15 * L;
    r = next;
    if (settled)
      break;
    // The rounds converge only linearly at first: solve for the disk tangent at p and at
    // the nearest foot's generator (Newton, p held), and stop if that disk is empty — it
    // touches two points, so it is the maximal one.
    if (nearest && !nearest->continuum)
    {
      BisectorState y{ s, nearest->s, r };
      const bool solved = Bisector(G, g, nearest->g).correct(y, 0, 1e-14 * L) && y.sb >= 0.0 &&
        y.sb <= 1.0 && y.r > 0.0 && y.r <= r * (1.0 + 1e-12) &&
        (G.evaluate(nearest->g, y.sb).p - p.p).norm() > 1e-9 * L;
      if (solved && emptyAt(y.r))
      {
        r = y.r;
        empty = true;
        break;
      }
    }
  }
  // The iteration may stop short (no second footpoint found where rounding hides it, a
  // near-circle): make sure the disk is empty; bisection finds the maximal one.
  if (!empty && !emptyAt(r))
  {
    double lo = 0.0, hi = r;
    for (int it = 0; it < 200 && hi - lo > 1e-15 * L; ++it)
    {
      const double mid = 0.5 * (lo + hi);
      (emptyAt(mid) ? lo : hi) = mid;
    }
    r = lo;
  }
  x = p.p + r * p.n;
  std::vector<BoundaryLocation> fps = G.footpointsWithin(x, r * (1.0 + 1e-7) + 1e-9 * L);
#ifdef EXACTMAT_TRACE_DEBUG
  std::fprintf(stderr, "start at g%d s%.15g p (%.15g %.15g) r %.15g fps %zu:", g, s, p.p.x(), p.p.y(), r, fps.size());
  for (const auto& f : fps)
    std::fprintf(stderr, " g%d@%.12g%s", f.g, f.s, f.continuum ? "c" : "");
  std::fprintf(stderr, "\n");
#endif
  if (fps.size() < 2 && !(fps.size() == 1 && fps.front().continuum))
    return false; // the osculating disk: p is a curvature extremum (the caller moves on)
  const bool circle = std::all_of(fps.begin(), fps.end(), [](const BoundaryLocation& f) { return f.continuum; });
  if (circle && !fps.empty())
  {
    // A circular domain: its MAT is the centre.
    const int id = addNode(x, r, MedialPointType::CircleCentre, fps);
    (void)id;
    for (const BoundaryLocation& f : fps)
      Cover.cover(f.g, 0.0, 1.0, -1);
    return true;
  }
  const int id = addNode(x, r, fps.size() >= 3 ? MedialPointType::Branch : MedialPointType::CycleJoint, fps);
  spawnWedges(id);
  return true;
}

void Tracer::reportProgress()
{
  // Measuring the coverage costs O(boundary): do it about a hundred times per run.
  if (!O.progress || ++SegmentsSinceProgress < std::max(1, G.size() / 100))
    return;
  SegmentsSinceProgress = 0;
  O.progress(std::min(1.0, Cover.coveredMeasure() / TotalMeasure));
}

void Tracer::joinClusters()
{
  const int domains = static_cast<int>(G.boundary().loops().size()) - G.boundary().holeCount();
  const int n = static_cast<int>(Graph.nodes.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int k) {
    while (parent[k] != k)
      k = parent[k] = parent[parent[k]];
    return k;
  };
  int components = n;
  auto unite = [&](int i, int j) {
    i = find(i);
    j = find(j);
    if (i != j)
    {
      parent[i] = j;
      --components;
    }
  };
  for (const MedialSegment& s : Graph.segments)
    unite(s.startNode, s.endNode);
  if (components <= domains)
    return;
  // Pairs of nodes (with radius: not ends at convex vertices) within reach, nearest first.
  std::vector<int> order;
  for (int k = 0; k < n; ++k)
    if (Graph.nodes[k].sample.radius > 0.0)
      order.push_back(k);
  std::sort(order.begin(), order.end(),
    [&](int i, int j) { return Graph.nodes[i].sample.x.x() < Graph.nodes[j].sample.x.x(); });
  const double reach = ClusterReach * L;
  std::vector<std::tuple<double, int, int>> pairs;
  for (size_t u = 0; u < order.size(); ++u)
  {
    const Vec2& xu = Graph.nodes[order[u]].sample.x;
    for (size_t w = u + 1; w < order.size() && Graph.nodes[order[w]].sample.x.x() - xu.x() <= reach; ++w)
    {
      const double d = (Graph.nodes[order[w]].sample.x - xu).norm();
      if (d <= reach && find(order[u]) != find(order[w]))
        pairs.emplace_back(d, order[u], order[w]);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<int> into(n);
  std::iota(into.begin(), into.end(), 0);
  for (const auto& [d, i, j] : pairs)
  {
    if (components <= domains)
      break;
    if (find(i) == find(j) || into[i] != i || into[j] != j)
      continue;
    absorbNode(i, j);
    into[j] = i;
    unite(i, j);
  }
  // Remove the nodes merged away and renumber.
  std::vector<int> renumber(n, -1);
  std::vector<MedialNode> kept;
  for (int k = 0; k < n; ++k)
  {
    if (into[k] != k)
      continue;
    renumber[k] = static_cast<int>(kept.size());
    kept.push_back(std::move(Graph.nodes[k]));
  }
  if (kept.size() == Graph.nodes.size())
    return;
  Graph.nodes = std::move(kept);
  for (MedialSegment& s : Graph.segments)
  {
    s.startNode = renumber[s.startNode];
    s.endNode = renumber[s.endNode];
  }
}

void Tracer::absorbNode(int keep, int gone)
{
  // `gone` becomes `keep`: its segments end at keep exactly, its footpoints join keep's.
  MedialNode& k = Graph.nodes[keep];
  for (const int sid : Graph.nodes[gone].segments)
  {
    MedialSegment& s = Graph.segments[sid];
    for (const bool atStart : { true, false })
    {
      if ((atStart ? s.startNode : s.endNode) != gone)
        continue;
      (atStart ? s.startNode : s.endNode) = keep;
      MedialSample& end = atStart ? s.samples.front() : s.samples.back();
      end.x = k.sample.x;
      end.radius = k.sample.radius;
    }
    if (std::find(k.segments.begin(), k.segments.end(), sid) == k.segments.end())
      k.segments.push_back(sid);
  }
  for (const BoundaryLocation& f : Graph.nodes[gone].footpoints)
    if (std::none_of(k.footpoints.begin(), k.footpoints.end(), [&](const BoundaryLocation& o) { return o.g == f.g; }))
      k.footpoints.push_back(f);
  if (k.footpoints.size() >= 3)
    k.type = MedialPointType::Branch;
  Graph.nodes[gone].segments.clear();
}

void Tracer::collapseClusterCycles()
{
  // A cluster of branch points can also come out as two of its pieces joined by two
  // segments of a few 1e-9 of the size (a 12-gon with its vertices jittered by 2e-9):
  // a cycle that encloses no hole — its disks are far larger than it — and that the
  // verification would count as one. The two pieces are one node; the segments between
  // them, loops of no length, go.
  const double reach = ClusterReach * L;
  auto tiny = [&](const MedialSegment& s) {
    double length = 0.0, smallest = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < s.samples.size(); ++k)
    {
      if (k > 0)
        length += (s.samples[k].x - s.samples[k - 1].x).norm();
      smallest = std::min(smallest, s.samples[k].radius);
    }
    return length <= reach && smallest > 1e3 * reach;
  };
  const int n = static_cast<int>(Graph.nodes.size());
  std::vector<bool> dropSegment(Graph.segments.size(), false), dropNode(n, false);
  bool changed = false;
  for (int round = 0; round < n; ++round)
  {
    // The first pair of nodes joined by two tiny segments.
    int keep = -1, gone = -1;
    for (int i = 0; i < n && keep < 0; ++i)
    {
      if (dropNode[i])
        continue;
      std::map<int, int> tinyTo;
      for (const int sid : Graph.nodes[i].segments)
      {
        const MedialSegment& s = Graph.segments[sid];
        if (dropSegment[sid] || s.startNode == s.endNode || !tiny(s))
          continue;
        const int other = s.startNode == i ? s.endNode : s.startNode;
        if (++tinyTo[other] == 2)
        {
          keep = i;
          gone = other;
          break;
        }
      }
    }
    if (keep < 0)
      break;
    changed = true;
    // The segments between the two go (loops of no length once they are one node).
    for (const int node : { keep, gone })
    {
      std::vector<int>& ids = Graph.nodes[node].segments;
      ids.erase(std::remove_if(ids.begin(), ids.end(),
                  [&](int sid) {
                    const MedialSegment& s = Graph.segments[sid];
                    const bool between = (s.startNode == keep && s.endNode == gone) ||
                      (s.startNode == gone && s.endNode == keep);
                    if (between)
                      dropSegment[sid] = true;
                    return between;
                  }),
        ids.end());
    }
    absorbNode(keep, gone);
    dropNode[gone] = true;
  }
  if (!changed)
    return;
  // Remove the segments and nodes collapsed away, and renumber.
  std::vector<int> segmentNumber(Graph.segments.size(), -1), nodeNumber(n, -1);
  std::vector<MedialSegment> segments;
  for (size_t sid = 0; sid < Graph.segments.size(); ++sid)
    if (!dropSegment[sid])
    {
      segmentNumber[sid] = static_cast<int>(segments.size());
      segments.push_back(std::move(Graph.segments[sid]));
    }
  std::vector<MedialNode> nodes;
  for (int i = 0; i < n; ++i)
    if (!dropNode[i])
    {
      nodeNumber[i] = static_cast<int>(nodes.size());
      nodes.push_back(std::move(Graph.nodes[i]));
    }
  for (MedialNode& node : nodes)
  {
    std::vector<int> ids;
    for (const int sid : node.segments)
      if (segmentNumber[sid] >= 0)
        ids.push_back(segmentNumber[sid]);
    node.segments = ids;
  }
  for (MedialSegment& s : segments)
  {
    s.startNode = nodeNumber[s.startNode];
    s.endNode = nodeNumber[s.endNode];
  }
  Graph.nodes = std::move(nodes);
  Graph.segments = std::move(segments);
}

MedialGraph Tracer::run()
{
  TotalMeasure = std::max(1.0, static_cast<double>(G.size()));
  // Convex vertices: both footpoints known (the vertex itself), radius 0 (§4.3.1).
  for (int g = 0; g < G.size(); ++g)
  {
    if (G[g].kind == GeneratorKind::Edge && G[g].endJunction == VertexKind::Convex)
    {
      const int next = G[g].next;
      const Vec2 v = G.evaluate(g, 1.0).p;
      const int id = addNode(v, 0.0, MedialPointType::ConvexVertexEnd, { location(next, 0.0), location(g, 1.0) });
      Queue.push_back({ id, location(next, 0.0), location(g, 1.0) });
    }
  }
  // Trace until every generator is covered; without convex vertices (circle, annulus,
  // smooth blobs) start from the maximal disk at an uncovered boundary point.
  for (int round = 0; round < G.size() + 1; ++round)
  {
    while (!Queue.empty())
    {
      const Pending p = Queue.front();
      Queue.pop_front();
      if (coveredAhead(p.a.g, p.a.s, +1) || coveredAhead(p.b.g, p.b.s, -1) || !isWedgeOf(p))
        continue;
      trace(p);
    }
    int g = -1;
    double from = NaN, to = NaN;
    for (int k = 0; k < G.size() && g < 0; ++k)
      if (G[k].kind == GeneratorKind::Edge && Cover.uncovered(k, from, to))
        g = k;
    if (g < 0)
      break;
    // The middle of the stretch first. A symmetric arc's middle is its curvature's
    // extremum, where the maximal disk may be the osculating one, touching there only (a
    // centre-of-curvature end, no start): then places off the middle.
    bool started = false;
    for (const double f : { 0.5, 0.382, 0.618, 0.25, 0.75 })
      if ((started = startAt(g, from + f * (to - from))))
        break;
    if (!started)
    {
      const double s = from + 0.5 * (to - from);
      fail("2D MAT: the maximal disks touching edge ", g, " at ", G.describe(G.evaluate(g, s).p),
        " and at four other places of its untraced stretch touch the boundary only there; no segment can start from them");
    }
    if (Queue.empty() && Graph.nodes.back().type != MedialPointType::CircleCentre)
    {
      fail("2D MAT: no segment could be started from boundary generator ", g);
    }
  }
  if (O.progress)
    O.progress(std::min(1.0, Cover.coveredMeasure() / TotalMeasure));
  joinClusters();
  collapseClusterCycles();
  Graph.mergeJoints();
  return std::move(Graph);
}
} // namespace

MedialGraph computeMAT2D(const Generators& generators, const MAT2DOptions& options)
{
  Tracer t(generators, options);
  return t.run();
}

} // namespace exactmat

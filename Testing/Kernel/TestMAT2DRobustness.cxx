// The 2D MAT on the inputs users bring (issue 9): moved, scaled, rotated and reweighted
// shapes give the same verified MAT; near-degenerate nodes (perturbed regular polygons)
// and dense boundaries (random star polygons) come out connected and exact; hundreds of
// random domains, seeded, are verified independently of the tracer.
#include "brep/NormalisePieces.h"
#include "common/InputError.h"
#include "geometry/ClosestPoint.h"
#include "mat2d/Tracer.h"
#include "mat2d/Verification.h"
#include "shapes/Catalogue.h"
#include "shapes/Primitives.h"
#include "shapes/RandomShapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>

using namespace exactmat;

namespace
{
// Every MAT point's global distance to the exact boundary equals its radius to this
// fraction of the domain size.
constexpr double VerifiedDistanceTolerance = 1e-9;
// Nodes of the moved shape land on the moved nodes of the original to this fraction of the
// size, plus what moving the input by `offset` rounds its coordinates by (8 ulp of the
// offset): the nodes are solved to rounding in the unit frame, whatever the motion.
double nodeAgreement(double offset, double size)
{
  return 1e-9 + 8 * std::numeric_limits<double>::epsilon() * offset / size;
}

struct Result
{
  Boundary2D boundary;
  std::unique_ptr<Generators> generators;
  MedialGraph graph;
  MAT2DVerification verification;
};

Result compute(const std::vector<NurbsCurve>& curves, const MAT2DOptions& options = {})
{
  Result r{ buildNormalised(curvePieces(curves)), nullptr, {}, {} };
  r.generators = std::make_unique<Generators>(r.boundary);
  r.graph = computeMAT2D(*r.generators, options);
  r.verification = verifyMAT2D(*r.generators, r.graph);
  return r;
}

// The verification with its problems in the failure message.
::testing::AssertionResult verified(const Result& r)
{
  if (r.verification.ok(VerifiedDistanceTolerance))
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << r.verification.problems(VerifiedDistanceTolerance);
}

::testing::AssertionResult verifiedOrRefused(const std::vector<NurbsCurve>& curves)
{
  try
  {
    return verified(compute(curves));
  }
  catch (const InputError& e)
  {
    return ::testing::AssertionFailure() << "InputError: " << e.what();
  }
}

// The graph's nodes (not the step-dependent samples) in the user's frame.
struct UserNode
{
  Vec3 x;
  double radius;
  MedialPointType type;
};

std::vector<UserNode> userNodes(const Result& r)
{
  std::vector<UserNode> out;
  for (const MedialNode& n : r.graph.nodes)
    out.push_back({ r.boundary.userPoint(n.sample.x), r.boundary.userLength(n.sample.radius), n.type });
  return out;
}
} // namespace

// The motions a shape is tested under: CAD- and map-like coordinates, scales 1e-6…1e6
// and 1e±300, rotations, weights scaled by 1e-100…1e100, and random ones; offsets up to
// `maxOffset` × the (scaled) size.
std::vector<ShapeMotion> motionsUpTo(double maxOffset, double size)
{
  RandomEngine rng(2026);
  std::vector<ShapeMotion> motions;
  auto add = [&](const ShapeMotion& m) {
    if (m.offset.norm() <= maxOffset * m.scale * size)
      motions.push_back(m);
  };
  add({ 0.0, 1.0, Vec3(1e5, 1e5, 0.0), 1.0 });        // CAD-like coordinates
  add({ 0.0, 1.0, Vec3(5e5, 4e6, 0.0), 1.0 });        // map-like coordinates
  add({ 0.3, 1e-6, Vec3(1e7 * 1e-6 * size, 0, 0), 1e100 });
  add({ 1.0, 1e-6, Vec3(1e3 * 1e-6 * size, 0, 0), 1e-100 });
  add({ 0.0, 1e6, Vec3::Zero(), 1e-100 });
  add({ 2.0, 1e6, Vec3(-1e9, 3e8, 0.0), 1e50 });
  // Coordinates near 1e300 and 1e-300 (weights scaled apart: w·x must stay a double).
  add({ 0.0, 1e300, Vec3::Zero(), 1e-5 });
  add({ 0.0, 1e-300, Vec3::Zero(), 1e300 });
  for (int k = 0; k < 4; ++k)
  {
    ShapeMotion m = randomMotion(rng);
    m.offset *= std::min(1.0, maxOffset * m.scale * size / m.offset.norm());
    add(m);
  }
  return motions;
}

struct InvarianceCase
{
  const char* shape;
  double maxOffset; ///< × size
};

class InvariantShape2D : public ::testing::TestWithParam<InvarianceCase>
{
};

// Moved, scaled, rotated, reweighted: the same MAT, moved, verified to 1e-9 of the size.
TEST_P(InvariantShape2D, SameMATWhereverAndHoweverLargeTheShapeIs)
{
  const char* name = GetParam().shape;
  const std::vector<NurbsCurve> curves = makeShape(name).curves;
  const Result base = compute(curves);
  ASSERT_TRUE(verified(base));
  const std::vector<UserNode> baseNodes = userNodes(base);
  const double baseSize = base.boundary.userLength(base.boundary.diagonal());
  for (const ShapeMotion& m : motionsUpTo(GetParam().maxOffset, baseSize))
  {
    SCOPED_TRACE(std::string(name) + " " + m.describe());
    const Result moved = compute(m.apply(curves));
    EXPECT_TRUE(verified(moved));
    ASSERT_EQ(moved.graph.segments.size(), base.graph.segments.size());
    const std::vector<UserNode> nodes = userNodes(moved);
    ASSERT_EQ(nodes.size(), baseNodes.size());
    const double size = m.scale * baseSize;
    for (const UserNode& b : baseNodes)
    {
      const Vec3 expected = m.apply(b.x);
      double nearest = INFINITY;
      const UserNode* match = nullptr;
      for (const UserNode& n : nodes)
      {
        const double d = ((n.x - expected) / size).norm(); // relative: |x| may be 1e300
        if (d < nearest && n.type == b.type)
        {
          nearest = d;
          match = &n;
        }
      }
      ASSERT_NE(match, nullptr);
      const double agreement = nodeAgreement(m.offset.norm(), size);
      EXPECT_LE(nearest, agreement);
      EXPECT_NEAR(match->radius / size, b.radius * m.scale / size, agreement);
    }
  }
}

// Shapes whose MAT has a node where k ≥ 4 generators meet by symmetry at the junctions
// of their pieces (the blob's centre of degree 5, the plate's and the passage's symmetric
// nodes) are tested to offsets of 1e6 × size: at 1e7 the input's own rounding (1e-9 of
// the size there) splits such a node into a cluster of branch points that the tracer
// places only to a few 1e-8 (README, limits). The annulus' arcs meet at corners of
// 1e-9 rad there.
INSTANTIATE_TEST_SUITE_P(Catalogue, InvariantShape2D,
  ::testing::Values(InvarianceCase{ "rectangle", 1e7 }, InvarianceCase{ "rounded-rectangle", 1e7 },
    InvarianceCase{ "circle", 1e7 }, InvarianceCase{ "ellipse", 1e7 }, InvarianceCase{ "l-shape", 1e7 },
    InvarianceCase{ "spiral", 1e7 }, InvarianceCase{ "annulus", 1e7 }, InvarianceCase{ "star", 1e7 },
    InvarianceCase{ "blob", 1e6 }, InvarianceCase{ "plate-with-holes", 1e6 },
    InvarianceCase{ "narrow-passage", 1e6 }),
  [](const auto& info) {
    std::string n = info.param.shape;
    std::replace(n.begin(), n.end(), '-', '_');
    return n;
  });

TEST(MAT2DRobustness, ScalingFamiliesMovedAndScaled)
{
  RandomEngine rng(11);
  for (const auto& curves : { makeSawToothStrip(40), std::vector<NurbsCurve>{ makeWavyStrip(12) } })
  {
    for (int k = 0; k < 3; ++k)
    {
      const ShapeMotion m = randomMotion(rng);
      SCOPED_TRACE(m.describe());
      EXPECT_TRUE(verifiedOrRefused(m.apply(curves)));
    }
  }
}

// A regular polygon's centre is one node of degree n; moving one vertex by 1e-6 splits it
// into a cluster of branch points closer than any step (the reproducers: the
// pentagon at +2e-6, +1e-6, −1e-6, the hexagon at 1e-6). Either way the graph is
// connected, every node has its footpoints and every point is exact.
TEST(MAT2DRobustness, NearDegenerateCentresOfRegularPolygons)
{
  auto polygon = [](int n, int moved, const Vec3& by) {
    Vec3List c;
    for (int k = 0; k < n; ++k)
      c.push_back(Vec3(std::cos(2 * M_PI * k / n), std::sin(2 * M_PI * k / n), 0.0) + (k == moved ? by : Vec3::Zero()));
    return makePolygon(c);
  };
  for (int n : { 4, 5, 6, 7, 8 })
  {
    for (double d : { 0.0, 1e-12, 1e-9, 1e-7, 1e-6, 2e-6, -1e-6, 1e-4 })
    {
      SCOPED_TRACE(std::to_string(n) + "-gon, vertex 0 moved by " + std::to_string(d));
      const Result r = compute(polygon(n, 0, Vec3(d, 0, 0)));
      EXPECT_TRUE(verified(r));
      EXPECT_EQ(r.graph.componentCount(), 1);
    }
  }
}

// Regular polygons of many edges whose centres the rounding of coordinates far from the
// origin (or a jitter of the vertices) splits into a tree of n − 2 branch points spread
// over up to 1e-2 of the size, joined by segments far shorter than the disk tests can
// resolve: the lines' medial tree (mat2d/LineCluster) places them. Until 2026-11-29 a
// 69-gon moved 5e6 × its size swept its boundary twice, a 500-gon and a gear of 1,000
// edges so moved stopped with "no segment could be started", and jittered polygons of
// 100 … 1,000 edges (jitter 1e-11 … 1e-8) failed the same ways.
TEST(MAT2DRobustness, ClustersOfManyNearlyEquidistantEdges)
{
  auto polygon = [](int n, double inner) {
    Vec3List c;
    for (int k = 0; k < n; ++k)
    {
      const double r = (k / 2) % 2 ? inner : 1.0; // inner < 1: a gear
      c.push_back(Vec3(r * std::cos(2 * M_PI * k / n), r * std::sin(2 * M_PI * k / n), 0.0));
    }
    return makePolygon(c);
  };
  struct Case
  {
    int n;
    double inner, offset;
  };
  for (const Case& c : { Case{ 69, 1.0, 5e6 }, Case{ 80, 1.0, 5e6 }, Case{ 500, 1.0, 5e6 }, Case{ 999, 1.0, 1e7 },
         Case{ 1000, 0.85, 5e6 }, Case{ 2000, 1.0, 1e6 } })
  {
    ShapeMotion m;
    m.angle = 0.4;
    m.offset = Vec3(c.offset, -0.7 * c.offset, 0.0);
    SCOPED_TRACE(std::to_string(c.n) + "-gon (inner radius " + std::to_string(c.inner) + ") " + m.describe());
    const Result r = compute(m.apply(polygon(c.n, c.inner)));
    EXPECT_TRUE(verified(r));
    EXPECT_EQ(r.graph.componentCount(), 1);
  }
  RandomEngine rng(29);
  for (const auto& [n, jitter] : { std::pair{ 100, 1e-11 }, std::pair{ 300, 1e-10 }, std::pair{ 1000, 1e-9 },
         std::pair{ 4000, 1e-8 } })
  {
    const RandomShape shape = perturbedRegularPolygon(rng, n, jitter);
    SCOPED_TRACE(shape.description);
    const Result r = compute(shape.curves);
    EXPECT_TRUE(verified(r));
    EXPECT_EQ(r.graph.componentCount(), 1);
  }
  // Jittered by 1e-12, the tree's contraction of near-ties (1e-12 of the size) leaves
  // segments of a few 1e-12 that run that far off their bisectors: a front stepped back
  // 1e-9 of its edge, and the verification counted the loop swept twice more (found by
  // exactmat_bench_random --clusters; its jitter for 1,000 edges drawn from seed 14).
  {
    const int n = 1000;
    RandomEngine jitterRng(1000 * n + 14);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Vec3List corners;
    for (int k = 0; k < n; ++k)
    {
      const double dx = 1e-12 * u(jitterRng), dy = 1e-12 * u(jitterRng);
      corners.push_back(Vec3(std::cos(2.0 * M_PI * k / n) + dx, std::sin(2.0 * M_PI * k / n) + dy, 0.0));
    }
    SCOPED_TRACE("1,000-gon jittered by 1e-12");
    const Result r = compute(makePolygon(corners));
    EXPECT_TRUE(verified(r));
    EXPECT_EQ(r.graph.componentCount(), 1);
  }
  // Unmoved, a regular polygon's centre is still one node of degree n (its tree, split
  // by the rounding of cos and sin only, lies within the node merge distance).
  const Result regular = compute(polygon(1000, 1.0));
  EXPECT_TRUE(verified(regular));
  const auto centre = std::max_element(regular.graph.nodes.begin(), regular.graph.nodes.end(),
    [](const MedialNode& a, const MedialNode& b) { return a.footpoints.size() < b.footpoints.size(); });
  EXPECT_EQ(centre->footpoints.size(), 1000u);
}

// Found by FuzzNURBSJson: a full circle of four rational quadratic arcs whose weights are
// off by up to 0.5%. The shrinking ball stopped short of its maximal disk (a disk that was
// not empty, one footpoint) and the graph came out in pieces with an error of 0.11 of the
// size; the start now finds the maximal disk by bisection on its emptiness.
TEST(MAT2DRobustness, NearCircleOfPerturbedRationalArcs)
{
  const std::vector<double> knots{ 0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1 };
  const Vec3List points{ Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(-1, 1, 0), Vec3(-1, 0, 0),
    Vec3(-1, -1, 0), Vec3(0, -1, 0), Vec3(1, -1, 0), Vec3(1, 0, 0) };
  const std::vector<double> weights{ 1, 0.7081607711865476, 1, 0.7071067811815476, 1,
    0.7035533905932738, 1, 0.70712067811865476, 1 };
  KnotVector kv(knots.size());
  for (size_t i = 0; i < knots.size(); ++i)
    kv[i] = knots[i];
  const Result r = compute({ NurbsCurve(2, kv, points, weights) });
  EXPECT_TRUE(verified(r));
  EXPECT_EQ(r.graph.componentCount(), 1);
}

TEST(MAT2DRobustness, SawToothStripWithCloseTeeth)
{
  EXPECT_TRUE(verifiedOrRefused(makeSawToothStrip(200)));
}

// A tiny square hole close to a long side of a 4 × 1 rectangle, at 40 places along it:
// the disks between the long sides reach it only over a short stretch, which the stepping
// saw or not depending on where its samples fell (disk tests at a step's end and middle
// only): 129 of 200 places stopped with "no segment could be started". One sweep of the
// disks between two straight edges finds where any entity first comes in.
TEST(MAT2DRobustness, ATinyHoleBetweenTheSamplesOfAStraightSegmentIsFound)
{
  for (int k = 0; k < 40; ++k)
  {
    const double xh = 0.5 + 3.0 * k / 40.0, yh = 0.0015, s = 1e-4;
    std::vector<NurbsCurve> curves = makePolygon({ Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(4, 1, 0), Vec3(0, 1, 0) });
    for (const NurbsCurve& c :
      makePolygon({ Vec3(xh - s, yh - s, 0), Vec3(xh + s, yh - s, 0), Vec3(xh + s, yh + s, 0), Vec3(xh - s, yh + s, 0) }))
      curves.push_back(c);
    const Result r = compute(curves);
    EXPECT_TRUE(verified(r)) << "hole at x = " << xh;
    EXPECT_EQ(r.verification.cycles, 1) << "hole at x = " << xh;
  }
}

// Seeded random domains (star polygons, jittered regular polygons, saw-tooth strips,
// rational blobs with holes), each randomly moved, scaled and reweighted: every one of the
// first 300 of this seed is verified. Over thousands about 1 % are still refused or flagged
// (never silently wrong); exactmat_bench_random measures the rates, and
// EXACTMAT_RANDOM_SHAPES=N runs more here (listing, not failing on, the ones not verified).
TEST(MAT2DRobustness, RandomDomains)
{
  const char* env = std::getenv("EXACTMAT_RANDOM_SHAPES");
  const int count = env ? std::atoi(env) : 300;
  RandomEngine rng(20261122);
  int failures = 0;
  for (int i = 0; i < count; ++i)
  {
    const RandomShape s = randomDomain(rng, 300);
    const ShapeMotion m = randomMotion(rng);
    const ::testing::AssertionResult r = verifiedOrRefused(m.apply(s.curves));
    if (!r)
    {
      ++failures;
      std::printf("random shape %d: %s, %s: %s\n", i, s.description.c_str(), m.describe().c_str(), r.message());
    }
  }
  std::printf("%d of %d random domains not verified\n", failures, count);
  if (!env)
  {
    EXPECT_EQ(failures, 0);
  }
}

// Findings of exactmat_bench_random (seed 1), kept: a star polygon of 293 edges moved to
// 5e11 (a branch point met at a grazing angle next to an almost flat convex vertex, placed
// 5e-6 of the size off by the disk test's margin), a regular 7-gon jittered by 4.4e-9
// (a cluster of branch points that came out in two pieces), and a 6-gon and an 11-gon
// jittered by 8e-9 and 2.7e-8.
TEST(MAT2DRobustness, RandomFindingsStayFixed)
{
  // 33, 256, 376, 382, 796: star polygons with an almost flat convex vertex whose branch
  // point with the next edge the disk tests could not tell from the vertex's normal.
  // 523, 678: rational blobs whose curvature peaks exactly where two pieces meet; a step
  // put one front on that LMPC (the end of its piece) with the other short of it, or both
  // on it at once with the radius left undetermined, and the segment came out as a false
  // branch point with two bisectors of a piece with itself (an extra cycle), or ran into
  // traced boundary. Each is checked as drawn, turned, scaled, reweighted and moved too.
  const std::vector<int> findings = { 27, 33, 71, 235, 256, 376, 382, 446, 523, 678, 796 };
  const std::vector<int> everyMotion = { 523, 678 };
  RandomEngine rng(1);
  for (int i = 0; i <= findings.back(); ++i)
  {
    const RandomShape s = randomDomain(rng, 300);
    const ShapeMotion m = randomMotion(rng);
    if (std::find(findings.begin(), findings.end(), i) == findings.end())
      continue;
    SCOPED_TRACE("shape " + std::to_string(i) + ": " + s.description + ", " + m.describe());
    EXPECT_TRUE(verifiedOrRefused(m.apply(s.curves)));
    if (std::find(everyMotion.begin(), everyMotion.end(), i) == everyMotion.end())
      continue;
    ShapeMotion turned, scaled, reweighted, moved = m;
    turned.angle = m.angle;
    scaled.scale = m.scale;
    reweighted.weightScale = m.weightScale;
    moved.weightScale = 1.0;
    for (const ShapeMotion& part : { ShapeMotion{}, turned, scaled, reweighted, moved })
    {
      SCOPED_TRACE(part.describe());
      EXPECT_TRUE(verifiedOrRefused(part.apply(s.curves)));
    }
  }
}

// A finding of `exactmat_bench_random --max-edges 2000` (seed 1, shape 1262): a regular
// 12-gon with its vertices jittered by 2.2e-9, whose centre is a cluster of branch points
// that came out as two pieces joined by two segments of 1e-9 (one cycle for no hole). The
// two pieces are one node now, in every motion.
TEST(MAT2DRobustness, ClusterJoinedTwiceIsOneNode)
{
  RandomEngine rng(1);
  RandomShape s;
  ShapeMotion m;
  for (int i = 0; i <= 1262; ++i)
  {
    s = randomDomain(rng, 2000);
    m = randomMotion(rng);
  }
  ASSERT_NE(s.description.find("12-gon"), std::string::npos) << s.description;
  ShapeMotion turned, scaled, reweighted;
  turned.angle = m.angle;
  scaled.scale = m.scale;
  reweighted.weightScale = m.weightScale;
  for (const ShapeMotion& part : { ShapeMotion{}, turned, scaled, reweighted, m })
  {
    SCOPED_TRACE(s.description + ", " + part.describe());
    const Result r = compute(part.apply(s.curves));
    EXPECT_TRUE(verified(r));
    // A tree: nodes = segments + 1.
    EXPECT_EQ(r.graph.nodes.size(), r.graph.segments.size() + 1);
  }
}

// Findings of `exactmat_bench_random --max-edges 2000` (seed 1), each as drawn and moved:
// 872 and 1054, star polygons whose branch point touches an edge 1e-7 of the size from a
// reflex corner of almost no sweep, so the footpoints on both sides of the corner are one
// contact (they gave a wedge of zero width that could not be traced, or traced the wedge
// beyond from the wrong side of the corner); 1699, a star polygon whose branch point next
// to an almost flat convex vertex touches the edge beyond it 4e-8 of the size from the
// front's own foot (taken for the front's contact, so no branch point was found there);
// 294, a blob whose first disk osculates across a smooth junction (two contacts either
// side of it that are not one, though the junction is inside the disk's shell); 1201
// (moved), a star polygon whose segment ends at a node next to an almost flat convex
// vertex with its last step landing on the vertex, 1e-6 from the node: the sample took
// the node's place but kept the step's feet, and the boundary between was swept twice;
// 517 (moved), a blob whose curvature peaks where two pieces meet: a curvature maximum
// found 1e-11 short of its piece's end made every step onto that end "pass" it, and the
// segment ended in a false branch point (2026-11-26: the maximum is now that end).
TEST(MAT2DRobustness, ContactsEitherSideOfACornerStayFixed)
{
  const std::vector<int> findings = { 294, 517, 872, 1054, 1201, 1699 };
  RandomEngine rng(1);
  for (int i = 0; i <= findings.back(); ++i)
  {
    const RandomShape s = randomDomain(rng, 2000);
    const ShapeMotion m = randomMotion(rng);
    if (std::find(findings.begin(), findings.end(), i) == findings.end())
      continue;
    for (const ShapeMotion& part : { ShapeMotion{}, m })
    {
      SCOPED_TRACE("shape " + std::to_string(i) + ": " + s.description + ", " + part.describe());
      EXPECT_TRUE(verified(compute(part.apply(s.curves))));
    }
  }
}

// Dense random stars (1,000 edges), moved, scaled and reweighted at random: seed 9 is
// moved to 2e5 × its size and has an almost flat convex vertex whose branch point with
// the next edge is within the input's rounding of that vertex's normal.
TEST(MAT2DRobustness, DenseStarsMovedFar)
{
  for (const int seed : { 1, 2, 9 })
  {
    RandomEngine rng(seed);
    const RandomShape s = randomStarPolygon(rng, 1000);
    const ShapeMotion m = randomMotion(rng);
    SCOPED_TRACE("seed " + std::to_string(seed) + ": " + s.description + ", " + m.describe());
    EXPECT_TRUE(verifiedOrRefused(m.apply(s.curves)));
  }
}

// Random stars of 10,000 edges (issue 9: they stopped with "reached traced boundary …
// where no MAT node is"). Seed 10 has a branch point next to an almost flat convex vertex
// that the vertex's own segment meets at a grazing angle: its fronts reach the node's
// feet (the end of the boundary covered before) 2e-6 of the size short of the node.
TEST(MAT2DRobustness, TenThousandEdgeStar)
{
  RandomEngine rng(10);
  const RandomShape s = randomStarPolygon(rng, 10000);
  SCOPED_TRACE(s.description);
  EXPECT_TRUE(verified(compute(s.curves)));
}

// The box tree holds a slanted straight edge of a large boundary as pieces: its answers
// must be those of every edge asked exactly. A turned 2,000-edge star, probed at points
// all over its box: the nearest distance equals the minimum over all edges, a disk just
// larger than it reaches the boundary and one just smaller does not, and the footpoints
// of that disk include the nearest edge.
TEST(MAT2DRobustness, PiecedBoxTreeAnswersAsEveryEdge)
{
  RandomEngine rng(4);
  ShapeMotion turned;
  turned.angle = 0.7;
  const Boundary2D b = buildNormalised(curvePieces(turned.apply(randomStarPolygon(rng, 2000).curves)));
  const Generators g(b);
  const auto& edges = b.edges();
  Box3 box;
  for (const Edge2D& e : edges)
    box.extend(e.curve.boundingBox());
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double size = g.size2D();
  int failures = 0;
  for (int i = 0; i < 400; ++i)
  {
    const Vec2 x(box.min().x() + unit(rng) * box.sizes().x(), box.min().y() + unit(rng) * box.sizes().y());
    const Vec3 q(x.x(), x.y(), 0.0);
    double exact = std::numeric_limits<double>::infinity();
    Vec2 foot = Vec2::Zero();
    for (const Edge2D& e : edges)
    {
      const CurveFootpoint c = closestPoint(e.curve, q);
      if (c.distance < exact)
      {
        exact = c.distance;
        foot = Vec2(c.point.x(), c.point.y());
      }
    }
    const double d = g.distance(x);
    const bool within = g.anyCloserThan(x, exact * (1.0 + 1e-9) + 1e-15);
    const bool beyond = !g.anyCloserThan(x, exact * (1.0 - 1e-9));
    bool footOnNearest = false; // (a corner may stand for an edge's end)
    for (const BoundaryLocation& f : g.footpointsWithin(x, exact * (1.0 + 1e-9) + 1e-15))
      footOnNearest = footOnNearest || (f.point - foot).norm() <= 1e-9 * size;
    if (d != exact || !within || !beyond || !footOnNearest)
    {
      ++failures;
      ADD_FAILURE() << "probe " << i << " at (" << x.x() << ", " << x.y() << "): tree " << d << ", every edge "
                    << exact << ", within " << within << ", beyond " << beyond;
      if (failures > 5)
        break;
    }
  }
}

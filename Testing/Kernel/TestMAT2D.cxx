// The 2D MAT kernel against closed forms and the exact boundary.
#include "common/InputError.h"
#include "mat2d/Tracer.h"
#include "mat2d/Verification.h"
#include "shapes/Catalogue.h"
#include "shapes/Primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>

using namespace exactmat;

namespace
{
// Every MAT point's global distance to the exact boundary equals its radius to this
// fraction of the domain size.
constexpr double VerifiedDistanceTolerance = 1e-9;

struct TracedMAT
{
  Boundary2D boundary;
  std::unique_ptr<Generators> generators;
  MedialGraph graph;
};

TracedMAT run(const std::vector<NurbsCurve>& curves, const MAT2DOptions& options = {})
{
  TracedMAT r{ Boundary2D::build(curvePieces(curves)), nullptr, {} };
  r.generators = std::make_unique<Generators>(r.boundary);
  r.graph = computeMAT2D(*r.generators, options);
  return r;
}

TracedMAT runShape(const std::string& name, const MAT2DOptions& options = {})
{
  return run(makeShape(name).curves, options);
}

void expectVerified(const TracedMAT& r, const std::string& what)
{
  const MAT2DVerification v = verifyMAT2D(*r.generators, r.graph);
  EXPECT_LE(v.maxDistanceError, VerifiedDistanceTolerance) << what;
  EXPECT_EQ(v.footpointShortfalls, 0) << what;
  EXPECT_LE(v.uncovered, 1e-6) << what;
  EXPECT_LE(v.coveredTwice, 1e-6) << what;
  EXPECT_EQ(v.cycles, v.holes) << what;
  EXPECT_GE(v.points, 1) << what;
}

template <typename F>
void forEachSample(const MedialGraph& g, F f)
{
  for (const MedialSegment& s : g.segments)
    for (const MedialSample& m : s.samples)
      f(m, s);
}
} // namespace

class EveryShape2D : public ::testing::TestWithParam<const char*>
{
};

TEST_P(EveryShape2D, VerifiedAgainstTheExactBoundaryForSeveralSteps)
{
  for (double tolerance : { 1e-3, 1e-6 })
  {
    MAT2DOptions o;
    o.tolerance = tolerance;
    expectVerified(runShape(GetParam(), o), std::string(GetParam()) + " adaptive " + std::to_string(tolerance));
  }
  for (double step : { 1e-2, 1e-3 })
  {
    MAT2DOptions o;
    o.fixedStep = true;
    o.step = step;
    o.branchCheckStep = 10 * step;
    expectVerified(runShape(GetParam(), o), std::string(GetParam()) + " fixed " + std::to_string(step));
  }
}

INSTANTIATE_TEST_SUITE_P(Catalogue, EveryShape2D,
  ::testing::Values("rectangle", "rounded-rectangle", "circle", "ellipse", "annulus", "l-shape",
    "star", "blob", "spiral", "plate-with-holes", "narrow-passage"),
  [](const auto& info) {
    std::string n = info.param;
    std::replace(n.begin(), n.end(), '-', '_');
    return n;
  });

TEST(MAT2D, RectangleHasFiveSegmentsAndTwoBranchPoints)
{
  // 4 × 2: branch points at (±1, 0), r = 1; the middle segment y = 0 with r = 1; the corner
  // segments on the diagonals |x| − 1 = |y| − ... with r = 1 − |y|.
  const TracedMAT r = runShape("rectangle");
  EXPECT_EQ(r.graph.segments.size(), 5u);
  EXPECT_EQ(r.graph.count(MedialPointType::Branch), 2);
  EXPECT_EQ(r.graph.count(MedialPointType::ConvexVertexEnd), 4);
  for (const MedialNode& n : r.graph.nodes)
  {
    if (n.type != MedialPointType::Branch)
      continue;
    EXPECT_NEAR(std::abs(n.sample.x.x()), 1.0, 1e-9);
    EXPECT_NEAR(n.sample.x.y(), 0.0, 1e-9);
    EXPECT_NEAR(n.sample.radius, 1.0, 1e-9);
    EXPECT_EQ(n.footpoints.size(), 3u);
  }
  forEachSample(r.graph, [](const MedialSample& m, const MedialSegment&) {
    const double x = std::abs(m.x.x()), y = std::abs(m.x.y());
    if (x <= 1.0 + 1e-9)
    {
      EXPECT_NEAR(y, 0.0, 1e-9);
      EXPECT_NEAR(m.radius, 1.0, 1e-9);
    }
    else
    {
      EXPECT_NEAR(x - 1.0, y, 1e-9); // on the corner's bisector
      EXPECT_NEAR(m.radius, 1.0 - y, 1e-9);
    }
  });
}

TEST(MAT2D, EllipseMatchesTheClosedForm)
{
  // a = 2, b = 1: the segment |x| ≤ (a² − b²)/a = 1.5 on y = 0, r = b·sqrt(1 − x²/(a² − b²)).
  const double a = 2.0, b = 1.0, c2 = a * a - b * b;
  const TracedMAT r = runShape("ellipse");
  EXPECT_EQ(r.graph.segments.size(), 1u);
  EXPECT_EQ(r.graph.count(MedialPointType::CurvatureCentreEnd), 2);
  double maxX = 0.0;
  forEachSample(r.graph, [&](const MedialSample& m, const MedialSegment&) {
    EXPECT_NEAR(m.x.y(), 0.0, 1e-12);
    EXPECT_NEAR(m.radius, b * std::sqrt(std::max(0.0, 1.0 - m.x.x() * m.x.x() / c2)), 1e-10);
    maxX = std::max(maxX, std::abs(m.x.x()));
  });
  EXPECT_NEAR(maxX, c2 / a, 1e-10);
}

TEST(MAT2D, AnnulusIsOneCycle)
{
  const TracedMAT r = runShape("annulus"); // R1 = 1, R2 = 0.5
  EXPECT_EQ(r.graph.segments.size(), 1u);
  EXPECT_EQ(r.graph.cycleCount(), 1);
  EXPECT_EQ(r.graph.count(MedialPointType::Branch), 0);
  forEachSample(r.graph, [](const MedialSample& m, const MedialSegment&) {
    EXPECT_NEAR(m.x.norm(), 0.75, 1e-12);
    EXPECT_NEAR(m.radius, 0.25, 1e-12);
  });
}

TEST(MAT2D, RegularPolygonHasSpokesToTheCentre)
{
  for (int n : { 3, 5, 6, 8 })
  {
    Vec3List corners;
    for (int k = 0; k < n; ++k)
      corners.push_back(Vec3(std::cos(2 * M_PI * k / n), std::sin(2 * M_PI * k / n), 0));
    const TracedMAT r = run(makePolygon(corners));
    EXPECT_EQ(static_cast<int>(r.graph.segments.size()), n) << n;
    ASSERT_EQ(r.graph.count(MedialPointType::Branch), 1) << n;
    for (const MedialNode& node : r.graph.nodes)
    {
      if (node.type == MedialPointType::Branch)
      {
        EXPECT_LT(node.sample.x.norm(), 1e-9);
        EXPECT_NEAR(node.sample.radius, std::cos(M_PI / n), 1e-9); // the apothem
        EXPECT_EQ(static_cast<int>(node.footpoints.size()), n);
      }
    }
    // Every point lies on a spoke from the centre to a corner.
    forEachSample(r.graph, [&](const MedialSample& m, const MedialSegment&) {
      const double angle = std::atan2(m.x.y(), m.x.x()) * n / (2 * M_PI);
      if (m.x.norm() > 1e-9)
      {
        EXPECT_NEAR(angle, std::round(angle), 1e-9);
      }
      EXPECT_NEAR(m.radius, m.x.norm() > 1e-12 ? (1.0 - m.x.norm()) * std::cos(M_PI / n) : std::cos(M_PI / n), 1e-9);
    });
    expectVerified(r, "polygon " + std::to_string(n));
  }
}

TEST(MAT2D, LShapeHasTheParabolicArcOfItsReflexCorner)
{
  // L: (0,0) (4,0) (4,1) (1,1) (1,2) (0,2); reflex corner (1,1). Where the footpoints are
  // the corner and the edge y = 0, the MAT is the parabola (x−1)² + (y−1)² = y².
  const TracedMAT r = runShape("l-shape");
  EXPECT_EQ(r.graph.count(MedialPointType::Branch), 3);
  int onParabola = 0;
  forEachSample(r.graph, [&](const MedialSample& m, const MedialSegment&) {
    const Generators& G = *r.generators;
    for (int k = 0; k < 2; ++k)
    {
      const BoundaryLocation& c = m.foot[k];
      const BoundaryLocation& e = m.foot[1 - k];
      if (G[c.g].kind == GeneratorKind::ReflexCorner && G[e.g].kind == GeneratorKind::Edge &&
        std::abs(e.point.y()) < 1e-12 && m.radius > 1e-9)
      {
        const double x = m.x.x(), y = m.x.y();
        EXPECT_NEAR((x - 1) * (x - 1) + (y - 1) * (y - 1), y * y, 1e-9);
        EXPECT_NEAR(m.radius, y, 1e-9);
        ++onParabola;
      }
    }
  });
  EXPECT_GT(onParabola, 3);
}

TEST(MAT2D, LongWavyNURBSStrip)
{
  // Found by the benchmark: a closed cubic B-spline of many spans, where the corrector could
  // carry a front past the end of its Bézier piece and a piece's end was taken for a
  // footpoint. Every span count must give a verified MAT with the boundary covered once.
  for (int spans : { 60, 80, 300 })
  {
    expectVerified(run({ makeWavyStrip(spans) }), "wavy strip " + std::to_string(spans));
  }
}

TEST(MAT2D, CircleIsItsCentre)
{
  const TracedMAT r = runShape("circle");
  ASSERT_EQ(r.graph.nodes.size(), 1u);
  EXPECT_EQ(r.graph.nodes[0].type, MedialPointType::CircleCentre);
  EXPECT_LT(r.graph.nodes[0].sample.x.norm(), 1e-12);
  EXPECT_NEAR(r.graph.nodes[0].sample.radius, 1.0, 1e-12);
}

TEST(MAT2D, AdaptiveStepBoundsTheChordError)
{
  // On the ellipse, the polyline between samples stays within the tolerance of the true
  // MAT (the segment y = 0) and the radius interpolates within it too.
  for (double tol : { 1e-3, 1e-5 })
  {
    MAT2DOptions o;
    o.tolerance = tol;
    const TracedMAT r = runShape("ellipse", o);
    const double L = r.boundary.diagonal();
    for (const MedialSegment& s : r.graph.segments)
      for (size_t i = 0; i + 1 < s.samples.size(); ++i)
      {
        const MedialSample &p = s.samples[i], &q = s.samples[i + 1];
        const Vec2 mid = 0.5 * (p.x + q.x);
        const double rTrue = std::sqrt(std::max(0.0, 1.0 - mid.x() * mid.x() / 3.0));
        EXPECT_LE(std::abs(0.5 * (p.radius + q.radius) - rTrue), 1.01 * tol * L);
      }
  }
}

// The tolerance is a bound on the polyline of (x, y, r) against the true medial curve
// (position and radius deviations added), on every shape: each sample of a trace 100 times
// finer lies within it of the coarse polyline (2% for the finer trace's own chords). And
// the square-root ends of centre-of-curvature segments take no more samples than the
// curve needs: the ellipse took 91 when the step control measured the distance to the
// chord's midpoint (the footpoint parameter's pace, not the curve's deviation).
TEST(MAT2D, PolylineIsWithinTheToleranceOfTheMedialCurve)
{
  for (const char* name : { "ellipse", "blob", "star", "plate-with-holes", "narrow-passage", "annulus", "spiral" })
  {
    const double tol = 1e-4;
    MAT2DOptions coarse, fine;
    coarse.tolerance = tol;
    fine.tolerance = tol / 100.0;
    const TracedMAT c = runShape(name, coarse), f = runShape(name, fine);
    const double L = c.boundary.diagonal();
    struct Chord
    {
      Eigen::Vector3d a, b;
    };
    std::vector<Chord> chords;
    auto point = [](const MedialSample& s) { return Eigen::Vector3d(s.x.x(), s.x.y(), s.radius); };
    for (const MedialSegment& s : c.graph.segments)
      for (size_t i = 0; i + 1 < s.samples.size(); ++i)
        chords.push_back({ point(s.samples[i]), point(s.samples[i + 1]) });
    double worst = 0.0;
    for (const MedialSegment& s : f.graph.segments)
      for (const MedialSample& m : s.samples)
      {
        const Eigen::Vector3d q = point(m);
        double nearest = Unbounded;
        for (const Chord& k : chords)
        {
          const Eigen::Vector3d d = k.b - k.a;
          const double t = d.squaredNorm() > 0.0 ? std::clamp((q - k.a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
          const Eigen::Vector3d e = k.a + t * d - q;
          nearest = std::min(nearest, e.head<2>().norm() + std::abs(e(2)));
        }
        worst = std::max(worst, nearest);
      }
    EXPECT_LE(worst, 1.02 * tol * L) << name;
    if (std::string(name) == "ellipse")
    {
      size_t points = 0;
      for (const MedialSegment& s : c.graph.segments)
        points += s.samples.size();
      EXPECT_LE(points, 64u);
    }
  }
}

// The verification measures the true error of a wrong point, whichever way it is wrong: a
// radius too large (the nearest footpoint is inside the point's reach: its distance is
// taken), too small (no footpoint within reach: the global distance query answers), or a
// centre moved off the axis. It takes the distance from the footpoints it counts when it
// can, so this pins that it is still the global distance.
TEST(MAT2DVerification, MeasuresTheErrorOfAWrongPoint)
{
  for (const double wrong : { 1e-3, -1e-3, 1e-7, -1e-7 })
  {
    TracedMAT r = runShape("blob");
    const double L = r.boundary.diagonal();
    MedialSample& s = r.graph.segments[0].samples[r.graph.segments[0].samples.size() / 2];
    s.radius += wrong * L;
    const MAT2DVerification v = verifyMAT2D(*r.generators, r.graph);
    EXPECT_NEAR(v.maxDistanceError, std::abs(wrong), 1e-12) << wrong;
  }
  TracedMAT r = runShape("ellipse");
  const double L = r.boundary.diagonal();
  MedialSample& s = r.graph.segments[0].samples[10];
  const double before = r.generators->distance(s.x);
  s.x.y() += 1e-4 * L; // off the major axis: nearer one side
  const double truth = std::abs(r.generators->distance(s.x) - s.radius) / L;
  EXPECT_GT(truth, 1e-6);
  EXPECT_NEAR(before, s.radius, 1e-14 * L);
  EXPECT_NEAR(verifyMAT2D(*r.generators, r.graph).maxDistanceError, truth, 1e-15);
}

TEST(MAT2D, RunawayTracingIsAnErrorNotAHang)
{
  MAT2DOptions o;
  o.maxSamplesPerSegment = 3;
  EXPECT_THROW(runShape("ellipse", o), InputError);
}

TEST(MAT2D, ProgressReachesOne)
{
  MAT2DOptions o;
  std::vector<double> seen;
  o.progress = [&](double f) { seen.push_back(f); };
  runShape("plate-with-holes", o);
  ASSERT_FALSE(seen.empty());
  EXPECT_NEAR(seen.back(), 1.0, 1e-6);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
}

// The verification's figures do not depend on how its points are shared among threads:
// a runner that gives out small ranges, last first, on threads of its own.
TEST(MAT2DVerification, AnyParallelRunnerGivesTheSequentialFigures)
{
  const ParallelFor scrambled = [](std::size_t n,
                                  const std::function<void(std::size_t, std::size_t)>& body) {
    std::vector<std::thread> threads;
    for (std::size_t end = n; end > 0;)
    {
      const std::size_t begin = end > 7 ? end - 7 : 0;
      threads.emplace_back([&body, begin, end]() { body(begin, end); });
      end = begin;
    }
    for (std::thread& t : threads)
      t.join();
  };
  for (const char* name : { "plate-with-holes", "star", "ellipse" })
  {
    const TracedMAT r = runShape(name);
    const MAT2DVerification a = verifyMAT2D(*r.generators, r.graph);
    const MAT2DVerification b = verifyMAT2D(*r.generators, r.graph, scrambled);
    EXPECT_EQ(a.points, b.points) << name;
    EXPECT_EQ(a.maxDistanceError, b.maxDistanceError) << name;
    EXPECT_EQ(a.worstPoint, b.worstPoint) << name;
    EXPECT_EQ(a.footpointShortfalls, b.footpointShortfalls) << name;
    EXPECT_EQ(a.uncovered, b.uncovered) << name;
    EXPECT_GT(a.points, 20) << name;
  }
}

// Issue 14: in the thesis' fixed-step mode the segments of a conic or a blob end exactly at
// the centres of curvature (their last step lands on the end node): the ellipse 2 x 1 at
// (±1.5, 0) with radius 0.5, the blob's five ends at radius 1/κ of their footpoint.
TEST(MAT2D, FixedStepSegmentsLandOnCurvatureCentres)
{
  MAT2DOptions fixed;
  fixed.fixedStep = true;
  for (const char* name : { "ellipse", "blob", "rounded-rectangle" })
  {
    const TracedMAT r = runShape(name, fixed);
    int ends = 0;
    for (const MedialNode& n : r.graph.nodes)
    {
      if (n.type != MedialPointType::CurvatureCentreEnd)
        continue;
      ++ends;
      const BoundaryLocation& f = n.footpoints.front();
      const GeneratorPoint gp = r.generators->evaluate(f.g, f.s);
      EXPECT_NEAR(n.sample.radius, 1.0 / gp.curvature, 1e-12) << name;
      EXPECT_NEAR((n.sample.x - (gp.p + gp.n / gp.curvature)).norm(), 0.0, 1e-12) << name;
    }
    EXPECT_GT(ends, 0) << name;
    for (const MedialSegment& s : r.graph.segments)
    {
      EXPECT_EQ((s.samples.back().x - r.graph.nodes[s.endNode].sample.x).norm(), 0.0) << name;
      EXPECT_EQ((s.samples.front().x - r.graph.nodes[s.startNode].sample.x).norm(), 0.0) << name;
    }
    expectVerified(r, name);
  }
  const TracedMAT e = runShape("ellipse", fixed);
  for (const MedialNode& n : e.graph.nodes)
    if (n.type == MedialPointType::CurvatureCentreEnd)
    {
      EXPECT_NEAR(std::abs(n.sample.x.x()), 1.5, 1e-12);
      EXPECT_NEAR(n.sample.x.y(), 0.0, 1e-12);
      EXPECT_NEAR(n.sample.radius, 0.5, 1e-12);
    }
}

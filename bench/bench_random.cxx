// exactmat_bench_random — the fuzz benchmark of the 2D MAT: thousands of seeded random
// domains (star polygons, jittered regular polygons, saw-tooth strips, rational blobs with
// holes), each randomly moved, scaled and reweighted, each verified independently
// (global distance = Radius to 1e-9 of the size, footpoints, coverage, one component per
// domain, cycles = holes). Prints per class how many were verified, refused with an
// InputError, or flagged by the verification, and the time; with -v every failure with
// the seed that reproduces it.
//
//   exactmat_bench_random [--count N] [--seed S] [--max-edges M] [-v]
//   exactmat_bench_random --star-scaling   (random stars of 1,000 … 30,000 edges, 3 seeds each)
//   exactmat_bench_random --clusters       (near-regular polygons: jittered, and moved far)
#include "brep/NormalisePieces.h"
#include "common/InputError.h"
#include "mat2d/Tracer.h"
#include "mat2d/Verification.h"
#include "shapes/Catalogue.h"
#include "shapes/Primitives.h"
#include "shapes/RandomShapes.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <random>
#include <string>
#include <vector>

using namespace exactmat;

namespace
{
struct Tally
{
  int total = 0, verified = 0, refused = 0, flagged = 0;
  double seconds = 0.0, worstError = 0.0;
};

std::string shapeClass(const std::string& description)
{
  const size_t comma = description.find(',');
  std::string c = description.substr(0, comma);
  if (c.rfind("regular", 0) == 0)
    return "jittered regular polygon";
  return c;
}
// Random star polygons of growing size as drawn (3 seeds each): tracing and verification
// time apart, and the exponent of the tracing time in the number of edges.
int starScaling()
{
  std::printf("| edges | stars | verified | segments (mean) | tracing (s, mean) | verification (s, mean) | exponent (tracing) |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|\n");
  double previousEdges = 0.0, previousTrace = 0.0;
  for (const int edges : { 1000, 3000, 10000, 30000 })
  {
    int verified = 0;
    double segments = 0.0, trace = 0.0, verify = 0.0;
    const int seeds = 3;
    for (int seed = 1; seed <= seeds; ++seed)
    {
      RandomEngine rng(static_cast<unsigned long long>(seed));
      const RandomShape s = randomStarPolygon(rng, edges);
      try
      {
        const auto t0 = std::chrono::steady_clock::now();
        const Boundary2D b = buildNormalised(curvePieces(s.curves));
        const Generators g(b);
        const MedialGraph graph = computeMAT2D(g);
        const auto t1 = std::chrono::steady_clock::now();
        const MAT2DVerification v = verifyMAT2D(g, graph);
        const auto t2 = std::chrono::steady_clock::now();
        verified += v.ok(1e-9) ? 1 : 0;
        segments += static_cast<double>(graph.segments.size()) / seeds;
        trace += std::chrono::duration<double>(t1 - t0).count() / seeds;
        verify += std::chrono::duration<double>(t2 - t1).count() / seeds;
      }
      catch (const InputError& e)
      {
        std::printf("(%d edges, seed %d: %s)\n", edges, seed, e.what());
      }
    }
    std::printf("| %d | %d | %d | %.0f | %.2f | %.2f |", edges, seeds, verified, segments, trace, verify);
    if (previousEdges > 0.0)
      std::printf(" %.2f", std::log(trace / previousTrace) / std::log(edges / previousEdges));
    std::printf(" |\n");
    std::fflush(stdout);
    previousEdges = edges;
    previousTrace = trace;
  }
  return 0;
}
// What went wrong, printed after the tables.
std::vector<std::string> Failures;

// One polygon through the MAT and its verification: 'v' verified, 'r' refused, 'f' flagged
// (the reason kept in Failures under `name`).
char verifiedPolygon(const std::string& name, const Vec3List& corners, const ShapeMotion& motion, double& seconds)
{
  const auto t0 = std::chrono::steady_clock::now();
  char result = 'f';
  try
  {
    const Boundary2D b = buildNormalised(curvePieces(motion.apply(makePolygon(corners))));
    const Generators g(b);
    const MedialGraph graph = computeMAT2D(g);
    const MAT2DVerification v = verifyMAT2D(g, graph);
    result = v.ok(1e-9) ? 'v' : 'f';
    if (result == 'f')
      Failures.push_back(name + ": flagged: " + v.problems(1e-9));
  }
  catch (const InputError& e)
  {
    result = 'r';
    Failures.push_back(name + ": refused: " + e.what());
  }
  seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

// Issue 9's near-regular polygons, whose centres split into clusters of branch points
// closer than the disk tests resolve (mat2d/LineCluster): regular n-gons with every vertex
// jittered by up to ε (3 seeds each), and regular n-gons and gears (every other pair of
// vertices at 0.85 of the radius) turned by 0.3 rad and moved by up to 1e7 × their size,
// where the input's rounding does the jittering. Each cell: verified / drawn (r refused,
// f flagged by the verification), then the mean time per polygon.
int clusterTable()
{
  const std::vector<int> sizes{ 100, 500, 1000, 2000, 4000, 7000 };
  auto cell = [](int verified, int drawn, int refused, int flagged) {
    std::printf(" %d / %d%s |", verified, drawn,
      refused + flagged == 0 ? "" : (" (" + std::to_string(refused) + " r, " + std::to_string(flagged) + " f)").c_str());
  };
  const std::vector<double> jitters{ 0.0, 1e-12, 1e-10, 1e-8, 1e-6, 1e-4 };
  std::printf("Jittered regular n-gons (unit circumradius; 3 seeds per cell)\n\n| edges |");
  for (double e : jitters)
    std::printf(" jitter %.0e |", e);
  std::printf(" ms per polygon |\n|---:|");
  for (size_t k = 0; k <= jitters.size(); ++k)
    std::printf("---:|");
  std::printf("\n");
  for (int n : sizes)
  {
    std::printf("| %d |", n);
    double seconds = 0.0;
    int runs = 0;
    for (double jitter : jitters)
    {
      int verified = 0, refused = 0, flagged = 0;
      const int seeds = jitter == 0.0 ? 1 : 3;
      for (int seed = 1; seed <= seeds; ++seed)
      {
        RandomEngine rng(static_cast<unsigned long long>(1000 * n + seed));
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        Vec3List corners;
        for (int i = 0; i < n; ++i)
        {
          const double dx = jitter * u(rng), dy = jitter * u(rng);
          corners.push_back(Vec3(std::cos(2.0 * M_PI * i / n) + dx, std::sin(2.0 * M_PI * i / n) + dy, 0.0));
        }
        char name[96];
        std::snprintf(name, sizeof name, "%d-gon jittered by %.0e (seed %d)", n, jitter, seed);
        const char r = verifiedPolygon(name, corners, ShapeMotion(), seconds);
        ++runs;
        (r == 'v' ? verified : r == 'r' ? refused : flagged) += 1;
      }
      cell(verified, seeds, refused, flagged);
    }
    std::printf(" %.0f |\n", 1e3 * seconds / runs);
    std::fflush(stdout);
  }
  const std::vector<double> offsets{ 0.0, 1e5, 1e6, 5e6, 1e7 };
  for (const bool gear : { false, true })
  {
    std::printf("\n%s turned by 0.3 rad and moved by (d, -0.7 d), d = offset x the diameter\n\n| edges |",
      gear ? "Gears (every other pair of vertices at 0.85)" : "Regular n-gons");
    for (double o : offsets)
      std::printf(" offset %.0e |", o);
    std::printf(" ms per polygon |\n|---:|");
    for (size_t k = 0; k <= offsets.size(); ++k)
      std::printf("---:|");
    std::printf("\n");
    for (int n : { 100, 500, 1000, 2000 })
    {
      std::printf("| %d |", n);
      Vec3List corners;
      for (int i = 0; i < n; ++i)
      {
        const double rr = gear && (i / 2) % 2 ? 0.85 : 1.0;
        corners.push_back(Vec3(rr * std::cos(2.0 * M_PI * i / n), rr * std::sin(2.0 * M_PI * i / n), 0.0));
      }
      double seconds = 0.0;
      for (double offset : offsets)
      {
        ShapeMotion m;
        m.angle = 0.3;
        m.offset = Vec3(2.0 * offset, -1.4 * offset, 0.0);
        char name[96];
        std::snprintf(name, sizeof name, "%s of %d edges moved by %.0e", gear ? "gear" : "n-gon", n, offset);
        const char r = verifiedPolygon(name, corners, m, seconds);
        cell(r == 'v', 1, r == 'r', r == 'f');
      }
      std::printf(" %.0f |\n", 1e3 * seconds / offsets.size());
      std::fflush(stdout);
    }
  }
  std::printf("\n");
  for (const std::string& f : Failures)
    std::printf("%s\n", f.substr(0, 300).c_str());
  return 0;
}
} // namespace

int main(int argc, char* argv[])
{
  int count = 2000, maxEdges = 2000;
  unsigned long long seed = 1;
  bool verbose = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--count" && i + 1 < argc)
      count = std::atoi(argv[++i]);
    else if (a == "--seed" && i + 1 < argc)
      seed = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--max-edges" && i + 1 < argc)
      maxEdges = std::atoi(argv[++i]);
    else if (a == "-v")
      verbose = true;
    else if (a == "--star-scaling")
      return starScaling();
    else if (a == "--clusters")
      return clusterTable();
    else
    {
      std::fprintf(stderr, "usage: exactmat_bench_random [--count N] [--seed S] [--max-edges M] [-v] | --star-scaling | --clusters\n");
      return 2;
    }
  }
  std::map<std::string, Tally> tallies;
  RandomEngine rng(seed);
  for (int i = 0; i < count; ++i)
  {
    const RandomShape s = randomDomain(rng, maxEdges);
    const ShapeMotion m = randomMotion(rng);
    Tally& t = tallies[shapeClass(s.description)];
    ++t.total;
    const auto start = std::chrono::steady_clock::now();
    std::string problem;
    try
    {
      const Boundary2D b = buildNormalised(curvePieces(m.apply(s.curves)));
      const Generators g(b);
      const MedialGraph graph = computeMAT2D(g);
      const MAT2DVerification v = verifyMAT2D(g, graph);
      if (v.ok(1e-9))
      {
        ++t.verified;
        t.worstError = std::max(t.worstError, v.maxDistanceError);
      }
      else
      {
        ++t.flagged;
        problem = "verification: " + v.problems(1e-9);
      }
    }
    catch (const InputError& e)
    {
      ++t.refused;
      problem = std::string("InputError: ") + e.what();
    }
    t.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (verbose && !problem.empty())
      std::printf("shape %d (seed %llu): %s, %s: %s\n", i, seed, s.description.c_str(),
        m.describe().c_str(), problem.c_str());
  }
  std::printf("| class | shapes | verified | refused (InputError) | flagged by verification | worst verified error | ms per shape |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
  Tally all;
  for (const auto& [name, t] : tallies)
  {
    std::printf("| %s | %d | %d | %d | %d | %.1e | %.2f |\n", name.c_str(), t.total, t.verified,
      t.refused, t.flagged, t.worstError, 1e3 * t.seconds / std::max(1, t.total));
    all.total += t.total;
    all.verified += t.verified;
    all.refused += t.refused;
    all.flagged += t.flagged;
    all.seconds += t.seconds;
  }
  std::printf("| all | %d | %d | %d | %d | | %.2f |\n", all.total, all.verified, all.refused,
    all.flagged, 1e3 * all.seconds / std::max(1, all.total));
  return 0;
}

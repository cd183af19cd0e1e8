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
#include "brep/NormalisePieces.h"
#include "common/InputError.h"
#include "mat2d/Tracer.h"
#include "mat2d/Verification.h"
#include "shapes/Catalogue.h"
#include "shapes/RandomShapes.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>

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
    else
    {
      std::fprintf(stderr, "usage: exactmat_bench_random [--count N] [--seed S] [--max-edges M] [-v] | --star-scaling\n");
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

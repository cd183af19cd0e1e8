// Benchmark of the 2D MAT (not a test): time, points, segments, branch points and the
// verified error per catalogue shape and step setting, then scaling with the number of
// boundary entities (polygons and multi-span NURBS).
//
//   exactmat_bench_mat2d [--quick]
#include "mat2d/Tracer.h"
#include "mat2d/Verification.h"
#include "shapes/Catalogue.h"
#include "shapes/Primitives.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace exactmat;

namespace
{
struct Result
{
  double ms = 0.0;      ///< tracing (computeMAT2D)
  double setupMs = 0.0; ///< the boundary (loops, orientation, crossing check) and generators
  double verifyMs = 0.0;
  int points = 0, segments = 0, branches = 0;
  double error = 0.0;
  bool topology = false; ///< boundary covered once by the footpoints and cycles = holes
};

Result measure(const std::vector<NurbsCurve>& curves, const MAT2DOptions& options, int repeats)
{
  const std::vector<CurvePiece> pieces = curvePieces(curves);
  Result r;
  r.ms = r.setupMs = r.verifyMs = 1e300;
  for (int k = 0; k < repeats; ++k)
  {
    const auto t0 = std::chrono::steady_clock::now();
    const Boundary2D bb = Boundary2D::build(pieces);
    const Generators gg(bb);
    r.setupMs = std::min(r.setupMs, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  const Boundary2D b = Boundary2D::build(pieces);
  const Generators g(b);
  MedialGraph graph;
  for (int k = 0; k < repeats; ++k)
  {
    const auto t0 = std::chrono::steady_clock::now();
    graph = computeMAT2D(g, options);
    r.ms = std::min(r.ms, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  r.points = graph.pointCount();
  r.segments = static_cast<int>(graph.segments.size());
  r.branches = graph.count(MedialPointType::Branch);
  MAT2DVerification v;
  for (int k = 0; k < repeats; ++k)
  {
    const auto t0 = std::chrono::steady_clock::now();
    v = verifyMAT2D(g, graph);
    r.verifyMs = std::min(r.verifyMs, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  r.error = v.maxDistanceError;
  r.topology = v.uncovered <= 1e-6 && v.coveredTwice <= 1e-6 && v.cycles == v.holes &&
    v.footpointShortfalls == 0;
  return r;
}

} // namespace

int main(int argc, char* argv[])
{
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int repeats = quick ? 1 : 5;
  struct Mode
  {
    const char* name;
    MAT2DOptions options;
  };
  std::vector<Mode> modes(3);
  modes[0].name = "adaptive 1e-4";
  modes[1].name = "adaptive 1e-6";
  modes[1].options.tolerance = 1e-6;
  modes[2].name = "fixed 1e-3/1e-2";
  modes[2].options.fixedStep = true;

  std::printf("## 2D MAT per catalogue shape (best of %d runs, one core)\n\n", repeats);
  std::printf("| shape | mode | set-up (ms) | tracing (ms) | verification (ms) | points | segments | branch points | verified error | coverage, cycles |\n");
  std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---|\n");
  for (const std::string& name : catalogueNames())
  {
    const Shape s = makeShape(name);
    if (s.dimension != 2)
      continue;
    for (const Mode& m : modes)
    {
      const Result r = measure(s.curves, m.options, repeats);
      std::printf("| %s | %s | %.3f | %.3f | %.3f | %d | %d | %d | %.1e | %s |\n", name.c_str(), m.name,
        r.setupMs, r.ms, r.verifyMs, r.points,
        r.segments, r.branches, r.error, r.topology ? "ok" : "WRONG");
    }
  }

  std::printf("\n## Scaling with the number of boundary entities (adaptive 1e-4)\n\n");
  std::printf("| boundary | entities | time (ms) | points | segments | ms per segment | exponent | verified error | coverage, cycles |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---|\n");
  const std::vector<int> sizes = quick ? std::vector<int>{ 10, 100, 1000 }
                                       : std::vector<int>{ 10, 30, 100, 300, 1000, 3000, 10000 };
  for (int family = 0; family < 2; ++family)
  {
    double lastMs = 0.0, lastN = 0.0;
    for (int n : sizes)
    {
      const auto curves = family == 0 ? makeSawToothStrip(n) : std::vector<NurbsCurve>{ makeWavyStrip(n) };
      const Result r = measure(curves, MAT2DOptions(), n >= 3000 ? 1 : repeats);
      const double exponent = lastMs > 0 ? std::log(r.ms / lastMs) / std::log(n / lastN) : 0.0;
      std::printf("| %s | %d | %.1f | %d | %d | %.3f | %s | %.1e | %s |\n",
        family == 0 ? "saw-tooth strip (polygon)" : "wavy strip (cubic NURBS spans)", n, r.ms, r.points,
        r.segments, r.ms / std::max(1, r.segments),
        lastMs > 0 ? std::to_string(exponent).substr(0, 4).c_str() : "", r.error, r.topology ? "ok" : "WRONG");
      std::fflush(stdout);
      lastMs = r.ms;
      lastN = n;
    }
  }
  return 0;
}

// Benchmark of the 2.5D MAT (not a test): per extruded/revolved object, the time of the
// profile's 2D MAT and of the 3D construction apart, the junctions, output size and the
// verified error; then scaling of the construction with the number of profile entities.
//
//   exactmat_bench_mat25d [--quick]
#include "mat25d/MAT25D.h"
#include "mat25d/SweptBoundary.h"
#include "medial/Verification.h"
#include "mat2d/Tracer.h"
#include "shapes/Catalogue.h"
#include "shapes/Primitives.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

using namespace exactmat;

namespace
{

double msSince(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

struct Result
{
  double profileMs = 1e300, constructionMs = 1e300;
  int junctions = 0, seams = 0, sheets = 0, points = 0, triangles = 0;
  double error = 0.0;
  int mismatches = 0, verified = 0;
};

struct Object
{
  std::string name;
  std::vector<NurbsCurve> curves;
  bool revolve = false;
  double span = 0.0; ///< length, or degrees
};

// The sweep for an object: extrusions by `span` (0: 2.5·Rmax), revolutions about the line
// parallel to y one unit left of the profile.
Sweep sweepFor(const Object& o, const Boundary2D& b, const MedialGraph& g)
{
  if (!o.revolve)
    return Sweep::extrusion(o.span > 0 ? o.span : 2.5 * g.maximumRadius());
  double xmin = 1e300;
  for (const Edge2D& e : b.edges())
    xmin = std::min(xmin, e.curve.boundingBox().min().x());
  return Sweep::revolution(o.span, Vec3(xmin - 1.0, 0, 0));
}

Result measure(const Object& o, const MAT2DOptions& options, int repeats, bool verify)
{
  const Boundary2D b = Boundary2D::build(curvePieces(o.curves));
  const Generators g(b);
  Result r;
  MedialGraph graph;
  for (int k = 0; k < repeats; ++k)
  {
    const auto t0 = std::chrono::steady_clock::now();
    graph = computeMAT2D(g, options);
    r.profileMs = std::min(r.profileMs, msSince(t0));
  }
  const SweepMap map(b, sweepFor(o, b, graph));
  MedialComplex mat;
  for (int k = 0; k < repeats; ++k)
  {
    const auto t0 = std::chrono::steady_clock::now();
    mat = computeMAT25D(g, graph, map);
    r.constructionMs = std::min(r.constructionMs, msSince(t0));
  }
  r.junctions = mat.count(MedialElementType::Junction);
  r.seams = mat.count(MedialElementType::Seam);
  r.sheets = mat.count(MedialElementType::SweptSheet) + mat.count(MedialElementType::ProfileSheet);
  r.points = static_cast<int>(mat.points.size());
  r.triangles = mat.triangleCount();
  if (verify)
  {
    const SweptBoundary boundary(b, map);
    const int sheetPoints =
      mat.countPoints(MedialPoint3DType::Sheet) + mat.countPoints(MedialPoint3DType::ConvexEdge);
    const MedialVerification v = verifyMedialComplex(boundary, mat, std::max(1, sheetPoints / 300));
    r.error = v.maxDistanceError;
    r.mismatches = v.contactMismatches;
    r.verified = v.points;
  }
  return r;
}

// A profile with many branch points: the saw-tooth strip with about n corners.
Object sawTooth(int corners, double length)
{
  return { "saw-tooth strip, " + std::to_string(corners) + " corners", makeSawToothStrip(corners), false, length };
}
} // namespace

int main(int argc, char* argv[])
{
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int repeats = quick ? 1 : 5;
  MAT2DOptions thesisStep;
  thesisStep.fixedStep = true; // step 1e-3, branch check 1e-2 of the profile size
  MAT2DOptions adaptive;

  std::vector<Object> objects;
  for (const char* name : { "rectangle", "l-shape", "ellipse", "annulus", "star", "blob", "spiral",
         "plate-with-holes", "narrow-passage" })
    objects.push_back({ name, makeShape(name).curves, false, 0.0 });
  // Shorter than 2·Rmax: mid-sheets (beyond chapter 5).
  objects.push_back({ "rectangle", makeShape("rectangle").curves, false, 1.5 });
  objects.push_back({ "plate-with-holes", makeShape("plate-with-holes").curves, false, 0.6 });
  objects.push_back({ "rectangle", makeShape("rectangle").curves, true, 90.0 });
  objects.push_back({ "rectangle", makeShape("rectangle").curves, true, 40.0 });
  objects.push_back({ "plate-with-holes", makeShape("plate-with-holes").curves, true, 120.0 });
  objects.push_back({ "circle (torus)", makeShape("circle").curves, true, 360.0 });
  objects.push_back({ "plate-with-holes", makeShape("plate-with-holes").curves, true, 360.0 });
  // A 32-junction object, as the thesis' largest (Fig. 5.12, 32 junctions, 6 s).
  for (int n = 8; n < 200; ++n)
  {
    const Boundary2D b = Boundary2D::build(curvePieces(makeSawToothStrip(n)));
    const Generators g(b);
    if (computeMAT2D(g).count(MedialPointType::Branch) == 16)
    {
      objects.push_back(sawTooth(n, 0.0));
      break;
    }
  }

  std::printf("## 2.5D MAT per object (best of %d runs, one core; sheet resolution 0.02)\n\n", repeats);
  std::printf("| profile | sweep | profile MAT mode | junctions | seams | sheets | points | triangles "
              "| profile MAT (ms) | 3D construction (ms) | total (ms) | verified error | touchpoint mismatches |\n");
  std::printf("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const Object& o : objects)
  {
    for (int mode = 0; mode < 2; ++mode)
    {
      const Result r = measure(o, mode == 0 ? thesisStep : adaptive, repeats, true);
      char sweep[64];
      if (o.revolve)
        std::snprintf(sweep, sizeof sweep, "revolved %g°", o.span);
      else
      {
        char length[32];
        std::snprintf(length, sizeof length, "%g", o.span);
        std::snprintf(sweep, sizeof sweep, "extruded %s", o.span > 0 ? length : "2.5·Rmax");
      }
      std::printf("| %s | %s | %s | %d | %d | %d | %d | %d | %.2f | %.2f | %.2f | %.1e | %d of %d |\n",
        o.name.c_str(), sweep, mode == 0 ? "fixed 1e-3" : "adaptive 1e-4", r.junctions, r.seams,
        r.sheets, r.points, r.triangles, r.profileMs, r.constructionMs, r.profileMs + r.constructionMs,
        r.error, r.mismatches, r.verified);
      std::fflush(stdout);
    }
  }

  std::printf("\n## Scaling with the number of profile entities (extruded saw-tooth strips, adaptive 1e-4)\n\n");
  std::printf("| profile entities | junctions | points | profile MAT (ms) | 3D construction (ms) | points per ms (3D) | exponent (3D) |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|\n");
  const std::vector<int> sizes = quick ? std::vector<int>{ 10, 100, 1000 }
                                       : std::vector<int>{ 10, 30, 100, 300, 1000, 3000 };
  double lastMs = 0.0, lastN = 0.0;
  for (int n : sizes)
  {
    const Result r = measure(sawTooth(n, 0.0), adaptive, n >= 1000 ? 1 : repeats, false);
    const double exponent = lastMs > 0 ? std::log(r.constructionMs / lastMs) / std::log(n / lastN) : 0.0;
    std::printf("| %d | %d | %d | %.1f | %.1f | %.0f | %s |\n", n, r.junctions, r.points, r.profileMs,
      r.constructionMs, r.points / r.constructionMs,
      lastMs > 0 ? std::to_string(exponent).substr(0, 4).c_str() : "");
    std::fflush(stdout);
    lastMs = r.constructionMs;
    lastN = n;
  }
  return 0;
}

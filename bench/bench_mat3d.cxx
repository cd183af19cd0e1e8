// Benchmark of the 3D MAT (not a test): seams and junctions per solid, tracing and
// verification time apart, the verified error; then scaling with the number of faces on
// truncated pyramids over n-gons (n side faces, caps as fans of n triangles: 3n faces);
// then random staircases (reflex edges and corners): how many are verified, refused, wrong;
// then random polygons extruded and revolved, against the 2.5D MAT's junctions;
// then the medial sheets (sheets/SheetInterpolation) per solid: filling and verification
// time, every vertex checked against the exact boundary, the faces' coverage; then random
// boxes with a box-shaped cavity (seams and sheets: complete, flagged, refused).
//
//   exactmat_bench_mat3d [--quick]
#include "brep/NormalisePieces.h"
#include "common/InputError.h"
#include "mat25d/MAT25D.h"
#include "mat25d/SweptSolid.h"
#include "mat2d/Tracer.h"
#include "mat3d/MAT3D.h"
#include "mat3d/PatchBoundary.h"
#include "medial/Verification.h"
#include "shapes/Catalogue.h"
#include "shapes/Moved.h"
#include "shapes/Polyhedra.h"
#include "shapes/Primitives.h"
#include "shapes/RandomShapes.h"
#include "sheets/SheetFit.h"
#include "sheets/CentreCurveFootprint.h"
#include "sheets/SheetCoverage.h"
#include "sheets/SheetInterpolation.h"

#include <Eigen/Geometry>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

using namespace exactmat;

namespace
{
// Every patch cut into k × k sub-patches (exact: the same solid, k² times the faces, smooth
// edges between them): free-form scaling with the number of faces.
std::vector<PatchPiece> subdivided(const std::vector<PatchPiece>& pieces, int k)
{
  std::vector<PatchPiece> out;
  for (const PatchPiece& p : pieces)
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j)
      {
        PatchPiece q;
        q.patch = p.patch.subPatch(double(i) / k, double(i + 1) / k, double(j) / k, double(j + 1) / k);
        q.entity = p.entity;
        out.push_back(std::move(q));
      }
  return out;
}

double msSince(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void row(const std::string& name, const std::vector<PatchPiece>& pieces, int repeats)
{
  const Boundary3D b = buildNormalised(pieces);
  MAT3D mat;
  double best = 1e300;
  for (int k = 0; k < repeats; ++k)
  {
    const auto t0 = std::chrono::steady_clock::now();
    mat = computeMAT3D(b);
    best = std::min(best, msSince(t0));
  }
  const MedialComplex c = mat.complex();
  const auto t0 = std::chrono::steady_clock::now();
  const PatchBoundary exact(b);
  const MedialVerification v = verifyMedialComplex(exact, c, 1, std::max(1e-15, 64.0 * b.userFrame().inputRounding()));
  const double verifyMs = msSince(t0);
  std::printf("| %s | %zu | %zu | %d | %zu | %.2f | %.0f | %.1e | %d |\n", name.c_str(), b.faces().size(),
    mat.seams.size(), mat.junctionCount(), c.points.size(), best, verifyMs, v.maxDistanceError,
    v.contactMismatches);
  std::fflush(stdout);
}
// The sheets of one solid: filled from its traced MAT (best of `repeats`), every vertex
// verified (distance = radius; two touchpoints inside a sheet), the coverage of the faces.
void sheetRow(const std::string& name, const std::vector<PatchPiece>& pieces, int repeats)
{
  const Boundary3D b = buildNormalised(pieces);
  const MAT3D mat = computeMAT3D(b);
  std::vector<MedialSheetMesh> meshes;
  std::vector<std::pair<int, std::string>> failures;
  double best = 1e300;
  for (int k = 0; k < repeats; ++k)
  {
    failures.clear();
    const auto t0 = std::chrono::steady_clock::now();
    meshes = interpolateSheets(b, mat, SheetOptions{}, failures);
    best = std::min(best, msSince(t0));
  }
  const auto t0 = std::chrono::steady_clock::now();
  const PatchBoundary exact(b);
  double error = 0.0, deviation = 0.0;
  int mismatches = 0, vertices = 0, triangles = 0, filled = 0;
  for (const MedialSheetMesh& m : meshes)
  {
    filled += m.triangles.empty() ? 0 : 1;
    triangles += static_cast<int>(m.triangles.size());
    deviation = std::max(deviation, m.maxDeviation);
    for (const SheetVertex& v : m.vertices)
    {
      ++vertices;
      error = std::max(error, std::abs(exact.distance(v.x) - v.r) / b.diagonal());
      if (!v.border && exact.touchpoints(v.x, v.r * (1.0 + 2e-9) + 1e-15 * b.diagonal()).size() != 2)
        ++mismatches;
    }
  }
  const double verifyMs = msSince(t0);
  double shortfall = 0.0;
  // (What the centre curves' circles cover counts too: a cylinder's side, a torus.)
  const std::vector<double> footprints = centreCurveFootprints(b, medialGenerators(b), centreCurveTouches(mat));
  for (const FaceCoverage& c : sheetCoverage(b, meshes, footprints))
    shortfall = std::max(shortfall, c.shortfall());
  std::printf("| %s | %zu | %d | %zu | %d | %d | %.2f | %.0f | %.1e | %d | %.1e | %.1e |\n", name.c_str(),
    b.faces().size(), filled, failures.size(), triangles, vertices, best, verifyMs, error, mismatches, shortfall,
    deviation);
  std::fflush(stdout);
}

// The sheets' B-spline fits (sheets/SheetFit) at a fit tolerance: time (best of
// `repeats`), size, the fit's own errors (at the vertices it was fitted to, at the exact
// centroid balls it never saw), and an independent check at those held-out places: the
// fitted ball's |distance to the exact boundary − fitted radius| (≤ 2 × the error).
void fitRow(const std::string& name, const std::vector<PatchPiece>& pieces, double tolerance, int repeats)
{
  const Boundary3D b = buildNormalised(pieces);
  std::vector<std::pair<int, std::string>> failures;
  const std::vector<MedialSheetMesh> meshes = interpolateSheets(b, computeMAT3D(b), SheetOptions{}, failures);
  SheetFitOptions options;
  options.tolerance = tolerance;
  std::vector<SheetFit> fits;
  double best = 1e300;
  for (int k = 0; k < repeats; ++k)
  {
    fits.clear();
    const auto t0 = std::chrono::steady_clock::now();
    for (const MedialSheetMesh& m : meshes)
      if (!m.triangles.empty())
        fits.push_back(fitSheet(m, b.diagonal(), options));
    best = std::min(best, msSince(t0));
  }
  const PatchBoundary exact(b);
  int patches = 0, controls = 0, above = 0, checked = 0;
  double vertexError = 0.0, checkError = 0.0, medial = 0.0;
  size_t m = 0;
  for (const SheetFit& fit : fits)
  {
    while (meshes[m].triangles.empty())
      ++m;
    const MedialSheetMesh& mesh = meshes[m++];
    patches += static_cast<int>(fit.patches.size());
    controls += fit.countS * fit.countT;
    above += fit.withinTolerance ? 0 : 1;
    vertexError = std::max(vertexError, fit.vertexError);
    checkError = std::max(checkError, fit.checkError);
    for (const SheetVertex& v : mesh.checkPoints)
    {
      Vec3 x;
      double r;
      fit.evaluate(fit.parameterOf(v.domain), x, r);
      medial = std::max(medial, std::abs(exact.distance(x) - r) / b.diagonal());
      ++checked;
    }
  }
  std::printf("| %s | %.0e | %zu | %d | %d | %.1f | %.1e | %.1e | %d | %.1e | %d |\n", name.c_str(), tolerance,
    fits.size(), patches, controls, best, vertexError, checkError, checked, medial, above);
  std::fflush(stdout);
}

std::string scientific(double x)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.1e", x);
  return text;
}

// The same solid turned (a different axis and angle each time), moved up to 1e6 x its
// size, scaled by 1e-6 … 1e6 and its weights scaled by 1e-100 … 1e100, the seams' balls
// passed through the user's frame as the VTK filters pass them: how many give complete
// sheets (no failed sheet, every vertex on the MAT, faces covered to 1e-3), the worst error
// and coverage shortfall over them, and how many the 3D tracer refuses.
void sheetInvarianceRow(const std::string& name, const std::vector<PatchPiece>& pieces, int count)
{
  const double offsets[] = { 0.0, 1e3, 1e5, 1e6 }, scales[] = { 1.0, 1e-6, 1e6 }, weights[] = { 1.0, 1e-100, 1e100 };
  int complete = 0, refused = 0;
  double error = 0.0, shortfall = 0.0;
  std::string first;
  for (int k = 0; k < count; ++k)
  {
    const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.1 * k + 0.05, Vec3(1.0, 2.0 + 0.1 * k, 3.0).normalized()).toRotationMatrix();
    const double scale = scales[k % 3];
    try
    {
      const Boundary3D b = buildNormalised(
        movedPieces(pieces, rotation, scale, scale * offsets[k % 4] * Vec3(1.0, -1.0, 1.0), weights[(k / 3) % 3]));
      MAT3D mat = computeMAT3D(b);
      const Normalisation& frame = b.userFrame();
      for (MAT3DSeam& seam : mat.seams)
        for (MedialBall3D& ball : seam.balls)
          ball.x = frame.toUnit(frame.toUser(ball.x));
      std::vector<std::pair<int, std::string>> failures;
      const std::vector<MedialSheetMesh> meshes = interpolateSheets(b, mat, SheetOptions{}, failures);
      const PatchBoundary exact(b);
      double worst = 0.0, uncovered = 0.0;
      int n = 0;
      for (const MedialSheetMesh& m : meshes)
        for (const SheetVertex& v : m.vertices)
          if (n++ % 5 == 0 || v.border) // every border vertex, every fifth inside
            worst = std::max(worst, std::abs(exact.distance(v.x) - v.r) / b.diagonal());
      for (const FaceCoverage& c : sheetCoverage(b, meshes))
        uncovered = std::max(uncovered, c.shortfall());
      const bool ok = failures.empty() && worst <= 1e-9 && uncovered <= 1e-3;
      complete += ok ? 1 : 0;
      if (ok)
      {
        error = std::max(error, worst);
        shortfall = std::max(shortfall, uncovered);
      }
      else if (first.empty())
        first = "turn " + std::to_string(k) + ": " +
          (!failures.empty() ? failures.front().second
                             : worst > 1e-9 ? "a vertex off the MAT by " + scientific(worst) + " of the size"
                                            : "a face not covered (shortfall " + scientific(uncovered) + ")");
    }
    catch (const InputError&)
    {
      ++refused;
    }
  }
  std::printf("| %s | %d | %d | %d | %.1e | %.1e | %s |\n", name.c_str(), count, complete, refused, error, shortfall,
    first.substr(0, 160).c_str());
  std::fflush(stdout);
}
// A catalogue profile swept as vtkNURBSSource sweeps it (sides cut where its MAT's samples
// touch, caps tiled by the MAT's chords).
std::vector<PatchPiece> sweptCatalogueSolid(const std::string& name, const Sweep& how)
{
  const Boundary2D profile = Boundary2D::build(curvePieces(makeShape(name).curves));
  const Generators generators(profile);
  return sweptSolidFaces(generators, computeMAT2D(generators), SweepMap(profile, how));
}

// The 3D tracer against the 2.5D MAT: random star polygons and jittered regular polygons
// (3–14 edges) extruded (length 0.5–4) or revolved (5–355°, axis 1.6–5.6 from the centre),
// given as the swept solid's faces (caps tiled by the profile MAT's chords, sides cut where
// its samples touch) and traced as general solids. "Agree": the same junctions, one for one
// (to 1e-7), every point verified, the graph consistent.
void crossCheckRow(bool revolve, int count, unsigned seed)
{
  RandomEngine rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int agree = 0, differ = 0, flagged = 0, refused = 0, wrong = 0, faces = 0;
  double tracingMs = 0.0;
  std::string firstRefusal;
  for (int k = 0; k < count; ++k)
  {
    const int edges = 3 + static_cast<int>(u(rng) * 12);
    const double a = u(rng), b = revolve ? u(rng) : 0.0;
    const RandomShape shape = k % 2 == 0 ? randomStarPolygon(rng, edges) : perturbedRegularPolygon(rng, edges, 0.05);
    try
    {
      const Boundary2D profile = Boundary2D::build(curvePieces(shape.curves));
      const Generators generators(profile);
      const MedialGraph graph = computeMAT2D(generators);
      const SweepMap sweep(profile, revolve ? Sweep::revolution(5.0 + 350.0 * a, Vec3(-1.6 - 4.0 * b, 0.0, 0.0), Vec3::UnitY())
                                            : Sweep::extrusion(0.5 + 3.5 * a));
      const MedialComplex swept = computeMAT25D(generators, graph, sweep, {});
      const std::vector<PatchPiece> pieces = sweptSolidFaces(generators, graph, sweep);
      faces += static_cast<int>(pieces.size());
      const auto t0 = std::chrono::steady_clock::now();
      const Boundary3D boundary = buildNormalised(pieces);
      const MAT3D mat = computeMAT3D(boundary);
      tracingMs += msSince(t0);
      const MedialComplex c = mat.complex();
      const PatchBoundary exact(boundary);
      const MedialVerification v = verifyMedialComplex(exact, c, 1, 1e-15);
      const Normalisation& n = boundary.userFrame();
      int expected = 0, matched = 0, junctions = 0;
      for (const MAT3DNode& node : mat.nodes)
        junctions += node.vertex < 0 && !node.seamEnd;
      for (const MedialElement& e : swept.elements)
      {
        if (e.type != MedialElementType::Junction)
          continue;
        ++expected;
        for (const MAT3DNode& node : mat.nodes)
          if (node.vertex < 0 && !node.seamEnd && (n.toUser(node.ball.x) - swept.points[e.points.front()].x).norm() < 1e-7)
          {
            ++matched;
            break;
          }
      }
      if (v.maxDistanceError > 1e-9 || v.contactMismatches > 0)
        ++wrong;
      else if (!mat.topologyProblems([](const Vec3& x) { return x; }).empty())
        ++flagged;
      else if (matched != expected || junctions != expected)
        ++differ;
      else
        ++agree;
    }
    catch (const InputError& e)
    {
      ++refused;
      if (firstRefusal.empty())
        firstRefusal = e.what();
    }
  }
  std::printf("| %s | %d | %.0f | %d | %d | %d | %d | %d | %.0f |\n", revolve ? "revolved" : "extruded", count,
    static_cast<double>(faces) / count, agree, differ, flagged, refused, wrong, tracingMs);
  if (!firstRefusal.empty())
    std::printf("\nFirst refusal (%s): %s\n\n", revolve ? "revolved" : "extruded", firstRefusal.c_str());
}
// One solid's seams and sheets judged as the filters' own verification would: refused by
// name (an InputError), wrong (a seam or sheet point off the MAT by more than 1e-9 of the
// size, or a seam point touching the wrong number of times: must never happen), flagged (a
// failed sheet, a face whose sheets' footprints miss it by more than 1e-3, or a seam graph
// whose junctions do not meet the seams their touchpoints make: the CLI's exit 3), or
// complete.
struct SheetVerdict
{
  bool refused = false, wrong = false, failedSheet = false, uncovered = false, badTopology = false;
  double error = 0.0, ms = 0.0;
  std::string why; // the refusal, the first failure, or the shortfall
  bool complete() const { return !refused && !wrong && !failedSheet && !uncovered && !badTopology; }
  bool flagged() const { return !refused && !wrong && !complete(); }
};

SheetVerdict judgeSheets(const std::vector<PatchPiece>& pieces)
{
  SheetVerdict v;
  try
  {
    const auto t0 = std::chrono::steady_clock::now();
    const Boundary3D b = buildNormalised(pieces);
    const MAT3D mat = computeMAT3D(b);
    std::vector<std::pair<int, std::string>> failures;
    const std::vector<MedialSheetMesh> meshes = interpolateSheets(b, mat, SheetOptions{}, failures);
    v.ms = msSince(t0);
    const PatchBoundary exact(b);
    const MedialVerification seams = verifyMedialComplex(exact, mat.complex(), 1, 1e-15);
    v.error = seams.maxDistanceError;
    for (const MedialSheetMesh& m : meshes)
      for (const SheetVertex& sv : m.vertices)
        v.error = std::max(v.error, std::abs(exact.distance(sv.x) - sv.r) / b.diagonal());
    double shortfall = 0.0;
    for (const FaceCoverage& c : sheetCoverage(b, meshes))
      shortfall = std::max(shortfall, c.shortfall());
    const std::vector<std::string> problems = mat.topologyProblems([](const Vec3& x) { return x; });
    v.wrong = v.error > 1e-9 || seams.contactMismatches > 0;
    v.failedSheet = !failures.empty();
    v.uncovered = shortfall > 1e-3;
    v.badTopology = !problems.empty();
    v.why = !failures.empty() ? failures.front().second
      : !problems.empty()     ? problems.front()
                              : "a face covered " + scientific(shortfall) + " short";
  }
  catch (const InputError& e)
  {
    v.refused = true;
    v.why = e.what();
  }
  return v;
}

// Random boxes with a box-shaped cavity anywhere inside (shapes/Polyhedra's
// randomBoxWithCavity), judged by judgeSheets.
void cavityRow(int count, unsigned seed)
{
  std::mt19937 rng(seed);
  int complete = 0, flagged = 0, refused = 0, wrong = 0;
  double ms = 0.0, error = 0.0;
  std::string firstFlag, firstRefusal;
  for (int k = 0; k < count; ++k)
  {
    const SheetVerdict v = judgeSheets(randomBoxWithCavity(rng));
    ms += v.ms;
    complete += v.complete() ? 1 : 0;
    flagged += v.flagged() ? 1 : 0;
    refused += v.refused ? 1 : 0;
    wrong += v.wrong ? 1 : 0;
    if (v.complete())
      error = std::max(error, v.error);
    std::string& first = v.refused ? firstRefusal : firstFlag;
    if (!v.complete() && first.empty())
      first = "solid " + std::to_string(k) + ": " + v.why;
  }
  std::printf("| %u | %d | %d | %d | %d | %d | %.1e | %.0f |\n", seed, count, complete, flagged, refused, wrong, error,
    ms / count);
  if (!firstFlag.empty())
    std::fprintf(stderr, "seed %u, first flagged or wrong: %s\n", seed, firstFlag.substr(0, 240).c_str());
  if (!firstRefusal.empty())
    std::fprintf(stderr, "seed %u, first refusal: %s\n", seed, firstRefusal.substr(0, 240).c_str());
}
// Random triaxial ellipsoids (semi-axes 0.5–3.5, patch layouts with the meridians cut
// anywhere in ±69° and the poles on the shortest axis or, one time in three or so, on a
// random one — then on the rim), turned, scaled by 1e-3 … 1e3, moved up to 1e4 × the
// scale, weights scaled by 1e±20: the rim and its sheet, every rim point and every 37th
// sheet vertex checked against the exact boundary, the faces' coverage measured.
void randomEllipsoidRow(int count, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int complete = 0, uncovered = 0, offPoints = 0, offAtPoles = 0, failedSheet = 0, refused = 0, witnessed = 0;
  double worstOff = 0.0, worstShortfall = 0.0, ms = 0.0;
  std::string firstUncovered, firstFailure;
  for (int k = 0; k < count; ++k)
  {
    const Vec3 axes(0.5 + 3.0 * u(rng), 0.5 + 3.0 * u(rng), 0.5 + 3.0 * u(rng));
    int shortest = 0;
    axes.minCoeff(&shortest);
    const double cut = -1.2 + 2.4 * u(rng);
    const int polar = u(rng) < 0.7 ? shortest : static_cast<int>(3.0 * u(rng)) % 3;
    const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(6.0 * u(rng), Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5).normalized()).toRotationMatrix();
    const double scale = std::pow(10.0, -3.0 + 6.0 * u(rng)), offset = std::pow(10.0, 4.0 * u(rng)) * scale;
    const std::vector<PatchPiece> pieces = movedPieces(patchPieces(ellipsoidSurfaces(axes, cut, polar)), turn, scale,
      Vec3(offset, -offset, 0.3 * offset), std::pow(10.0, -20.0 + 40.0 * u(rng)));
    const std::string name = "axes " + std::to_string(axes.x()) + " " + std::to_string(axes.y()) + " " +
      std::to_string(axes.z()) + ", poles on " + std::to_string(polar);
    const auto t0 = std::chrono::steady_clock::now();
    try
    {
      const Boundary3D b = buildNormalised(pieces);
      const MAT3D mat = computeMAT3D(b);
      std::vector<std::pair<int, std::string>> failures;
      const std::vector<MedialSheetMesh> meshes = interpolateSheets(b, mat, SheetOptions(), failures);
      ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      const double rounding = std::max(1e-15, 64.0 * b.userFrame().inputRounding());
      const PatchBoundary exact(b);
      const MedialVerification verified = verifyMedialComplex(exact, mat.complex(), 1, rounding);
      double worst = verified.maxDistanceError;
      witnessed += verified.witnessed;
      for (const MedialSheetMesh& mesh : meshes)
        for (size_t i = 0; i < mesh.vertices.size(); i += 37)
          worst = std::max(worst, std::abs(exact.distance(mesh.vertices[i].x) - mesh.vertices[i].r) / b.diagonal());
      double shortfall = 0.0;
      for (const FaceCoverage& c : sheetCoverage(b, meshes))
        shortfall = std::max(shortfall, c.shortfall());
      if (!failures.empty())
      {
        ++failedSheet;
        if (firstFailure.empty())
          firstFailure = name + ": " + failures.front().second;
      }
      else if (worst > 1e-9 + rounding)
      {
        ++(polar == shortest ? offPoints : offAtPoles);
        worstOff = std::max(worstOff, worst);
      }
      else if (shortfall > 1e-3)
      {
        ++uncovered;
        worstShortfall = std::max(worstShortfall, shortfall);
        if (firstUncovered.empty())
          firstUncovered = name + ": shortfall " + std::to_string(shortfall);
      }
      else
        ++complete;
    }
    catch (const InputError& e)
    {
      ++refused;
      if (firstFailure.empty())
        firstFailure = name + ": " + e.what();
    }
  }
  std::printf("| %d | %d | %d | %.1e | %d | %d (%.1e) | %d | %d | %d | %.0f |\n", count, complete, uncovered,
    worstShortfall, offPoints, offAtPoles, worstOff, witnessed, failedSheet, refused, ms);
  if (!firstUncovered.empty())
    std::fprintf(stderr, "random ellipsoids, first not covered: %s\n", firstUncovered.c_str());
  if (!firstFailure.empty())
    std::fprintf(stderr, "random ellipsoids, first failure: %s\n", firstFailure.substr(0, 240).c_str());
}

// Random canal solids — cylinders (radius 0.3–2, length 2.2–10 radii), tori (tube 0.1–0.9
// of the core) and prolate spheroids (2 × 1 × 1 to 4 × 1 × 1, any patch layout) — turned,
// scaled by 1e-3 … 1e3, moved up to 1e3 × the scale, weights scaled by 1e±20: one centre
// curve each, against its closed form (the cylinder's axis |z| ≤ h − R with r = R, the
// torus' core, the spheroid's segment r = b·√(1 − x²/(a² − b²)); its ends away from the
// poles), its ends and a few points verified; the cylinders' cone sheets filled and the
// faces' coverage measured with the axis' circles.
void randomCanalRow(const std::string& kind, int count, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int traced = 0, refused = 0, covered = 0;
  double worstForm = 0.0, worstVerified = 0.0, worstShortfall = 0.0, ms = 0.0;
  std::string firstFailure;
  for (int k = 0; k < count; ++k)
  {
    Placement placed;
    placed.rotation =
      Eigen::AngleAxisd(6.0 * u(rng), Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5).normalized()).toRotationMatrix();
    placed.scale = std::pow(10.0, -3.0 + 6.0 * u(rng));
    const double offset = std::pow(10.0, 3.0 * u(rng)) * placed.scale;
    placed.offset = Vec3(offset, -0.6 * offset, 0.3 * offset);
    placed.weightFactor = std::pow(10.0, -20.0 + 40.0 * u(rng));
    std::vector<PatchPiece> pieces;
    // The closed form's offset of a centre (x, r) in the original frame, and the extent.
    std::function<double(const Vec3&, double)> offForm;
    double extent = 1.0;
    if (kind == "cylinder")
    {
      ShapeParameters p;
      p.radius = 0.3 + 1.7 * u(rng);
      p.length = p.radius * (2.2 + 7.8 * u(rng));
      pieces = patchPieces(makeShape("cylinder", p).surfaces);
      extent = p.length;
      offForm = [p](const Vec3& x, double r) {
        return std::max({ std::hypot(x.x(), x.y()), std::abs(r - p.radius),
          std::max(0.0, std::abs(x.z()) - (0.5 * p.length - p.radius)) });
      };
    }
    else if (kind == "torus")
    {
      const double core = 1.0 + 2.0 * u(rng), tube = core * (0.1 + 0.8 * u(rng));
      pieces = patchPieces({ torusSurface(core, tube) });
      extent = 2.0 * (core + tube);
      offForm = [core, tube](const Vec3& x, double r) {
        return std::max({ std::abs(std::hypot(x.x(), x.y()) - core), std::abs(x.z()), std::abs(r - tube) });
      };
    }
    else
    {
      const double a = 1.0 + u(rng), b = 1.0 / (1.0 + u(rng));
      const int polar = static_cast<int>(3.0 * u(rng)) % 3;
      pieces = patchPieces(ellipsoidSurfaces(Vec3(a, b, b), M_PI / 6, polar));
      extent = 2.0 * a;
      offForm = [a, b](const Vec3& x, double r) {
        const double c2 = a * a - b * b;
        return std::max({ std::hypot(x.y(), x.z()), std::max(0.0, std::abs(x.x()) - c2 / a),
          std::abs(r - b * std::sqrt(std::max(0.0, 1.0 - x.x() * x.x() / c2))) });
      };
    }
    pieces = movedPieces(pieces, placed);
    try
    {
      const auto t0 = std::chrono::steady_clock::now();
      const Boundary3D b = buildNormalised(pieces);
      const MAT3D mat = computeMAT3D(b);
      std::vector<MedialSheetMesh> meshes;
      std::vector<std::pair<int, std::string>> failures;
      if (kind == "cylinder")
        meshes = interpolateSheets(b, mat, SheetOptions(), failures);
      ms += msSince(t0);
      if (mat.centreCurves.size() != 1 || !failures.empty())
      {
        ++refused;
        if (firstFailure.empty())
          firstFailure = kind + ": " + std::to_string(mat.centreCurves.size()) + " centre curves" +
            (failures.empty() ? "" : ", " + failures.front().second);
        continue;
      }
      ++traced;
      const Normalisation& frame = b.userFrame();
      for (const MedialBall3D& ball : mat.centreCurves.front().balls)
        worstForm = std::max(worstForm,
          offForm(unplaced(placed, frame.toUser(ball.x)), frame.lengthToUser(ball.r) / placed.scale) / extent);
      // The ends and three more points (a circle's distance search is slow: the continuum).
      MedialComplex c = mat.complex(), chosen;
      const size_t n = c.points.size();
      for (size_t i : { size_t(0), size_t(1), n / 3, n / 2, n - 1 })
        if (i < n)
          chosen.points.push_back(c.points[i]);
      const PatchBoundary exact(b);
      worstVerified = std::max(worstVerified,
        verifyMedialComplex(exact, chosen, 1, std::max(1e-15, 64.0 * frame.inputRounding())).maxDistanceError);
      double shortfall = 0.0;
      for (const FaceCoverage& f :
        sheetCoverage(b, meshes, centreCurveFootprints(b, medialGenerators(b), centreCurveTouches(mat))))
        shortfall = std::max(shortfall, f.shortfall());
      worstShortfall = std::max(worstShortfall, shortfall);
      covered += shortfall <= 1e-3 ? 1 : 0;
    }
    catch (const InputError& e)
    {
      ++refused;
      if (firstFailure.empty())
        firstFailure = kind + ": " + e.what();
    }
  }
  std::printf("| %s | %d | %d | %.1e | %.1e | %d (%.1e) | %d | %.0f |\n", kind.c_str(), count, traced, worstForm,
    worstVerified, covered, worstShortfall, refused, ms / count);
  std::fflush(stdout);
  if (!firstFailure.empty())
    std::fprintf(stderr, "random %s, first failure: %s\n", kind.c_str(), firstFailure.substr(0, 240).c_str());
}

void randomCanalTable(int count)
{
  std::printf("\n## Random canal solids: centre curves (random sizes, patch layouts, turned, moved, scaled, "
              "reweighted)\n\n");
  std::printf("| solids | count | one centre curve | largest closed-form offset / size | verified error (5 points "
              "each) | faces covered to 1e-3 (largest shortfall) | refused or wrong | MAT (and sheets) per solid (ms) |\n"
              "|---|---:|---:|---:|---:|---:|---:|---:|\n");
  randomCanalRow("cylinder", count, 7);
  randomCanalRow("torus", count, 8);
  randomCanalRow("prolate spheroid", count, 9);
}

ShapeParameters ellipsoidAxes(double width, double height, double length)
{
  ShapeParameters p;
  p.width = width;
  p.height = height;
  p.length = length;
  return p;
}
} // namespace


void randomEllipsoidTable(int count)
{
  std::printf("\n## Random ellipsoids: rim and sheet (random axes, patch layouts, turned, moved, scaled, reweighted)\n\n");
  std::printf("| solids | complete | faces not covered (> 1e-3) | largest shortfall | points off, poles off the rim | "
              "points off, poles on the rim (largest) | rim points verified by witness | sheet failed | refused | "
              "rim and sheet, total (ms) |\n"
              "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  randomEllipsoidRow(count, 1);
}

int main(int argc, char** argv)
{
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  if (argc > 1 && std::strcmp(argv[1], "--canal") == 0) // (that table alone)
  {
    randomCanalTable(20);
    return 0;
  }
  if (argc > 1 && std::strcmp(argv[1], "--ellipsoids") == 0) // (the random ellipsoids alone)
  {
    randomEllipsoidTable(argc > 2 ? std::atoi(argv[2]) : 60);
    return 0;
  }
  const int repeats = quick ? 1 : 5;
  std::printf("## 3D MAT: seams and junctions (adaptive, tolerance 1e-4; best of %d)\n\n", repeats);
  std::printf("| solid | faces | seams | junctions | points | tracing (ms) | verification (ms) | "
              "verified error | touchpoint mismatches |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  row("box 4 x 3 x 2", boxPolyhedron(2.0, 1.5, 1.0), repeats);
  row("cube (6-face junction)", boxPolyhedron(1.0, 1.0, 1.0), repeats);
  row("regular tetrahedron",
    polyhedron({ Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1) },
      { { 0, 1, 2 }, { 0, 3, 1 }, { 0, 2, 3 }, { 1, 3, 2 } }),
    repeats);
  row("pillow (bicubic faces)", patchPieces(makeShape("pillow").surfaces), repeats);
  row("box with a free-form top", boxWithFreeFormTop(2.0, 1.5, 1.0, 0.3, 0.5), repeats);
  row("ellipsoid 4 x 3 x 2 (a rim, no seam)", patchPieces(makeShape("ellipsoid", ellipsoidAxes(4, 3, 2)).surfaces), repeats);
  row("ellipsoid 10 x 9 x 1 (a rim, no seam)", patchPieces(makeShape("ellipsoid", ellipsoidAxes(10, 9, 1)).surfaces), repeats);
  row("cylinder r 1, length 3 (its axis: a centre curve)", patchPieces(makeShape("cylinder").surfaces), repeats);
  row("torus 2, 0.5 (its core: a closed centre curve)", patchPieces(makeShape("torus").surfaces), repeats);
  row("prolate spheroid 4 x 2 x 2 (its axis)", patchPieces(ellipsoidSurfaces(Vec3(2, 1, 1), M_PI / 6, 2)), repeats);
  std::mt19937 rng(3);
  for (int n : { 6, 12 })
    row("random frustum, " + std::to_string(n) + "-gon", randomFrustum(rng, n), repeats);
  row("L prism (a reflex edge)", lPrism(1.0, 2.5), repeats);
  row("notched cube (reflex corner)", patchPieces(makeShape("notched-cube").surfaces), repeats);
  std::mt19937 stairs(9);
  row("random staircase 6 x 6 x 3", randomStaircase(stairs, 6, 3), repeats);
  row("L profile revolved 270 degrees (faces of revolution)",
    sweptCatalogueSolid("l-shape", Sweep::revolution(270.0, Vec3(-3.0, 0.0, 0.0))), repeats);

  std::printf("\n## Scaling: the pillow with every face cut into k x k patches (free-form, 6k^2 faces)\n\n");
  std::printf("| solid | faces | seams | junctions | points | tracing (ms) | verification (ms) | "
              "verified error | touchpoint mismatches |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int k : { 1, 2, 4, 8 })
  {
    if (quick && k > 2)
      break;
    row("pillow, " + std::to_string(k) + " x " + std::to_string(k) + " patches a face",
      subdivided(patchPieces(makeShape("pillow").surfaces), k), k >= 4 ? 1 : repeats);
  }

  std::printf("\n## Scaling: random frustums over n-gons (3n faces)\n\n");
  std::printf("| solid | faces | seams | junctions | points | tracing (ms) | verification (ms) | "
              "verified error | touchpoint mismatches |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::mt19937 scaling(5);
  for (int n : { 10, 30, 100, 300 })
  {
    if (quick && n > 100)
      break;
    row("frustum, " + std::to_string(n) + "-gon", randomFrustum(scaling, n), n >= 300 ? 1 : repeats);
  }

  // Robustness on random staircases (grid squares: every degenerate coincidence a grid
  // brings): verified to 1e-9 with the right touchpoint counts and one connected graph,
  // refused by name, or wrong (verified error or mismatches or split graph: must be 0).
  const int count = quick ? 30 : 300;
  std::printf("\n## Random staircases (n x n columns, n = 2 … 7, 2 or 3 high; %d solids, seeds 1 … 3)\n\n", count);
  int verified = 0, refused = 0, wrong = 0, flagged = 0;
  double totalMs = 0.0;
  std::string firstRefusal;
  for (int seed = 1; seed <= 3; ++seed)
  {
    std::mt19937 r(seed);
    for (int k = 0; k < count / 3; ++k)
    {
      const int n = 2 + k % 6, height = 2 + (k / 6) % 2;
      const std::vector<PatchPiece> pieces = randomStaircase(r, n, height);
      try
      {
        const auto t0 = std::chrono::steady_clock::now();
        const Boundary3D b = buildNormalised(pieces);
        const MAT3D mat = computeMAT3D(b);
        totalMs += msSince(t0);
        const MedialComplex c = mat.complex();
        const PatchBoundary exact(b);
        const MedialVerification v = verifyMedialComplex(exact, c, 1, std::max(1e-15, 64.0 * b.userFrame().inputRounding()));
        std::vector<int> parent(mat.nodes.size());
        for (size_t i = 0; i < parent.size(); ++i)
          parent[i] = static_cast<int>(i);
        std::function<int(int)> root = [&](int i) { return parent[i] == i ? i : parent[i] = root(parent[i]); };
        for (const MAT3DSeam& seam : mat.seams)
          parent[root(seam.startNode)] = root(seam.endNode);
        for (const MAT3DSkeletalEdge& rim : mat.skeletalEdges)
          parent[root(rim.startNode)] = root(rim.endNode);
        int components = 0;
        for (size_t i = 0; i < parent.size(); ++i)
          components += root(static_cast<int>(i)) == static_cast<int>(i);
        const bool graph = mat.topologyProblems([](const Vec3& x) { return x; }).empty();
        if (v.maxDistanceError <= 1e-9 && v.contactMismatches == 0 && components == 1 && graph)
          ++verified;
        else if (!graph)
          ++flagged; // the filter's verification reports it (seams per junction)
        else
          ++wrong;
      }
      catch (const InputError& e)
      {
        ++refused;
        if (firstRefusal.empty())
          firstRefusal = e.what();
      }
    }
  }
  std::printf("| solids | verified, graph consistent | graph flagged (a seam missed or doubled) | refused by name | "
              "wrong, unflagged | tracing, total (ms) |\n|---:|---:|---:|---:|---:|---:|\n");
  std::printf("| %d | %d | %d | %d | %d | %.0f |\n", verified + flagged + refused + wrong, verified, flagged, refused,
    wrong, totalMs);
  if (!firstRefusal.empty())
    std::printf("\nFirst refusal: %s\n", firstRefusal.c_str());

  std::printf("\n## Against the 2.5D MAT: random polygons extruded and revolved, traced as general solids\n\n");
  std::printf("| sweep | solids | faces (mean) | agree (junctions one for one, verified, consistent) | junctions differ | "
              "graph flagged | refused by name | wrong, unflagged | tracing, total (ms) |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  crossCheckRow(false, quick ? 20 : 100, 2);
  crossCheckRow(true, quick ? 4 : 20, 1);

  std::printf("\n## Sheets (tolerance 1e-4, longest edge 0.05 of the size; best of %d)\n\n", repeats);
  std::printf("| solid | faces | sheets filled | failed | triangles | vertices | filling (ms) | verification (ms) | "
              "verified error | touchpoint mismatches | coverage shortfall | deviation |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  sheetRow("box 4 x 3 x 2", boxPolyhedron(2.0, 1.5, 1.0), repeats);
  sheetRow("cube", boxPolyhedron(1.0, 1.0, 1.0), repeats);
  sheetRow("pillow (bicubic faces)", patchPieces(makeShape("pillow").surfaces), repeats);
  sheetRow("box with a free-form top", boxWithFreeFormTop(2.0, 1.5, 1.0, 0.3, 0.5), repeats);
  sheetRow("L prism (a reflex edge)", lPrism(1.0, 2.5), repeats);
  sheetRow("notched cube (reflex corner)", patchPieces(makeShape("notched-cube").surfaces), repeats);
  sheetRow("stepped block (rims)", patchPieces(makeShape("stepped-block").surfaces), repeats);
  sheetRow("box with a cubic cavity (catalogue)", patchPieces(makeShape("box-with-cavity").surfaces), repeats);
  sheetRow("ellipsoid 4 x 3 x 2 (inside its rim)", patchPieces(makeShape("ellipsoid", ellipsoidAxes(4, 3, 2)).surfaces), repeats);
  sheetRow("ellipsoid 10 x 9 x 1 (inside its rim)", patchPieces(makeShape("ellipsoid", ellipsoidAxes(10, 9, 1)).surfaces), repeats);
  sheetRow("cylinder r 1, length 3 (two cones)", patchPieces(makeShape("cylinder").surfaces), repeats);
  sheetRow("torus 2, 0.5 (no sheet: the core covers it)", patchPieces(makeShape("torus").surfaces), repeats);
  // Revolved solids through the 3D tracer: curved sides cut into sliver pieces (one side of
  // a sheet per surface), arcs of reflex edges.
  for (const auto& [profile, degrees] : { std::pair<std::string, double>{ "rectangle", 90.0 }, { "l-shape", 90.0 },
         { "l-shape", 270.0 } })
    sheetRow(profile + " revolved " + std::to_string(static_cast<int>(degrees)) + " degrees",
      sweptCatalogueSolid(profile, Sweep::revolution(degrees, Vec3(-3.0, 0.0, 0.0), Vec3::UnitY())), quick ? 1 : 3);
  std::mt19937 sheetRng(5);
  for (int n : { 10, 30, 100 })
    sheetRow("random frustum, " + std::to_string(n) + "-gon", randomFrustum(sheetRng, n), quick ? 1 : 3);

  std::printf("\n## Sheet fits: cubic B-splines of centre and radius (sheets/SheetFit; best of %d)\n\n", repeats);
  std::printf("| solid | fit tolerance | sheets | Bezier patches | control points | fitting (ms) | error at vertices | "
              "error at held-out exact balls | held-out balls | their \\|distance - radius\\| | above tolerance |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (double tolerance : { 1e-4, 1e-6 })
  {
    fitRow("box 4 x 3 x 2", boxPolyhedron(2.0, 1.5, 1.0), tolerance, repeats);
    fitRow("pillow (bicubic faces)", patchPieces(makeShape("pillow").surfaces), tolerance, repeats);
    fitRow("box with a free-form top", boxWithFreeFormTop(2.0, 1.5, 1.0, 0.3, 0.5), tolerance, repeats);
    fitRow("L prism (a reflex edge)", lPrism(1.0, 2.5), tolerance, repeats);
    fitRow("notched cube (reflex corner)", patchPieces(makeShape("notched-cube").surfaces), tolerance, repeats);
    fitRow("stepped block (rims)", patchPieces(makeShape("stepped-block").surfaces), tolerance, repeats);
    fitRow("ellipsoid 4 x 3 x 2", patchPieces(makeShape("ellipsoid", ellipsoidAxes(4, 3, 2)).surfaces), tolerance, repeats);
  }

  randomEllipsoidTable(quick ? 10 : 60);
  randomCanalTable(quick ? 4 : 20);

  const int turns = quick ? 6 : 30;
  std::printf("\n## Sheets of moved, turned, scaled and reweighted solids (%d transformations each)\n\n", turns);
  std::printf("| solid | solids | complete | MAT refused | verified error | coverage shortfall | first failure |\n"
              "|---|---:|---:|---:|---:|---:|---|\n");
  sheetInvarianceRow("box 4 x 3 x 2", boxPolyhedron(2.0, 1.5, 1.0), turns);
  sheetInvarianceRow("pillow (bicubic faces)", patchPieces(makeShape("pillow").surfaces), turns);
  sheetInvarianceRow("box with a free-form top", boxWithFreeFormTop(2.0, 1.5, 1.0, 0.3, 0.5), turns);
  sheetInvarianceRow("L prism (a reflex edge)", lPrism(1.0, 2.5), turns);
  sheetInvarianceRow("notched cube (reflex corner)", patchPieces(makeShape("notched-cube").surfaces), turns);
  sheetInvarianceRow("stepped block (rims)", patchPieces(makeShape("stepped-block").surfaces), turns);
  sheetInvarianceRow("box with a cubic cavity (catalogue)", patchPieces(makeShape("box-with-cavity").surfaces), turns);
  sheetInvarianceRow("ellipsoid 4 x 3 x 2", patchPieces(makeShape("ellipsoid", ellipsoidAxes(4, 3, 2)).surfaces), turns);
  std::mt19937 turnRng(5);
  sheetInvarianceRow("random frustum, 10-gon", randomFrustum(turnRng, 10), turns);

  // Random staircases' sheets: how many are complete and exact, and how the others are
  // flagged (a failed sheet, a vertex off the MAT, a face not covered, a seam graph whose
  // junctions miss seams) — never silently.
  std::mt19937 stairRng(11);
  const int stairCount = quick ? 20 : 100;
  int complete = 0, failedSheets = 0, offMAT = 0, uncovered = 0, badTopology = 0, refusedMAT = 0;
  for (int k = 0; k < stairCount; ++k)
  {
    const SheetVerdict v = judgeSheets(randomStaircase(stairRng, 2 + k % 5, 2 + k % 2));
    complete += v.complete() ? 1 : 0;
    failedSheets += v.failedSheet ? 1 : 0;
    offMAT += v.wrong ? 1 : 0;
    uncovered += v.uncovered ? 1 : 0;
    badTopology += v.badTopology ? 1 : 0;
    refusedMAT += v.refused ? 1 : 0;
  }
  std::printf("\n## Sheets of random staircases (n x n columns, n = 2 … 6, 2 or 3 high; seed 11)\n\n");
  std::printf("| solids | complete and exact | with a failed sheet | with points off the MAT | with a face not "
              "covered | with junctions missing seams | MAT refused |\n|---:|---:|---:|---:|---:|---:|---:|\n");
  std::printf("| %d | %d | %d | %d | %d | %d | %d |\n", stairCount, complete, failedSheets, offMAT, uncovered, badTopology,
    refusedMAT);

  const int cavities = quick ? 10 : 40;
  std::printf("\n## Random boxes with a box cavity: seams and sheets (%d solids per seed)\n\n", cavities);
  std::printf("| seed | solids | complete and exact | flagged (a failed sheet, a face not covered, junctions missing "
              "seams) | refused by name | wrong, unflagged | verified error (complete ones) | tracing + sheets (ms "
              "per solid) |\n|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (unsigned seed = 1; seed <= (quick ? 1u : 8u); ++seed)
    cavityRow(cavities, seed);
  return 0;
}

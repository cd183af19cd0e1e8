#include "sheets/SheetFit.h"

#include "common/InputError.h"
#include "geometry/ClosestPoint.h"
#include "nurbs/BezierExtraction.h"
#include "nurbs/NurbsSurface.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

namespace exactmat
{

namespace
{

// Basis values N_{span−p..span}(u) of one knot vector.
struct Basis
{
  int first = 0; ///< index of the first non-zero function
  std::array<double, MaxDegree + 1> value{};
};

Basis basisAt(const KnotVector& knots, int degree, int count, double u)
{
  Basis b;
  const int span = findSpan(knots, degree, count, u);
  basisDerivatives(knots, span, u, degree, 0, b.value.data());
  b.first = span - degree;
  return b;
}

// Clamped knots on [0,1] with the given interior knots.
KnotVector clamped(int degree, const std::set<double>& interior)
{
  KnotVector k(degree + 1, 0.0);
  k.insert(k.end(), interior.begin(), interior.end());
  k.insert(k.end(), degree + 1, 1.0);
  return k;
}

// The span [a, b) of `interior` ∪ {0, 1} holding u.
std::pair<double, double> spanOf(const std::set<double>& interior, double u)
{
  double a = 0.0, b = 1.0;
  for (double k : interior)
  {
    if (k <= u)
      a = k;
    else
    {
      b = k;
      break;
    }
  }
  return { a, b };
}

// Greville abscissae: the knot averages where the control points of a linear function lie.
std::vector<double> greville(const KnotVector& knots, int degree, int count)
{
  std::vector<double> g(count, 0.0);
  for (int i = 0; i < count; ++i)
  {
    for (int k = 1; k <= degree; ++k)
      g[i] += knots[i + k];
    g[i] /= degree;
  }
  return g;
}

struct Sample
{
  Vec2 st;
  Vec3 x;
  double r;
};

} // namespace

Vec2 SheetFit::parameterOf(const Vec2& domain) const
{
  return (domain - domainOrigin).cwiseQuotient(domainExtent);
}

void SheetFit::evaluate(const Vec2& st, Vec3& x, double& r) const
{
  const Basis bs = basisAt(knotsS, degree, countS, std::clamp(st.x(), 0.0, 1.0));
  const Basis bt = basisAt(knotsT, degree, countT, std::clamp(st.y(), 0.0, 1.0));
  x = Vec3::Zero();
  r = 0.0;
  for (int i = 0; i <= degree; ++i)
    for (int j = 0; j <= degree; ++j)
    {
      const double w = bs.value[i] * bt.value[j];
      const int k = (bs.first + i) * countT + bt.first + j;
      x += w * centres[k];
      r += w * radii[k];
    }
}

SheetFit fitSheet(const MedialSheetMesh& mesh, double size, const SheetFitOptions& options)
{
  if (mesh.triangles.empty())
    fail("sheet fit: the sheet has no triangles");
  if (options.degree < 1 || options.degree > 5)
    fail("sheet fit: degree ", options.degree, " is outside 1 … 5");
  SheetFit fit;
  fit.degree = options.degree;
  const int p = fit.degree;
  // The domain's box, scaled to [0,1]² (the vertices' domain coordinates: the check points
  // lie inside the triangles).
  Vec2 lo = Vec2::Constant(Unbounded), hi = Vec2::Constant(-Unbounded);
  for (const SheetVertex& v : mesh.vertices)
  {
    lo = lo.cwiseMin(v.domain);
    hi = hi.cwiseMax(v.domain);
  }
  const Vec2 extent = hi - lo;
  if (!(extent.minCoeff() > 1e-12 * std::max(1.0, extent.maxCoeff())))
    fail("sheet fit: the sheet's parameter domain has no extent (", extent.x(), " × ", extent.y(), ")");
  fit.domainOrigin = lo;
  fit.domainExtent = extent;
  auto sample = [&](const SheetVertex& v) { return Sample{ fit.parameterOf(v.domain), v.x, v.r }; };
  std::vector<Sample> data, checks;
  for (const SheetVertex& v : mesh.vertices)
    data.push_back(sample(v));
  for (const SheetVertex& v : mesh.checkPoints)
    checks.push_back(sample(v));
  fit.fittedPoints = static_cast<int>(data.size());
  fit.checkedPoints = static_cast<int>(checks.size());

  std::set<double> interiorS, interiorT;
  const double tolerance = options.tolerance * size;
  SheetFit best = fit;
  best.vertexError = best.checkError = Unbounded;
  std::set<double> bestS, bestT;
  for (int round = 0; round < 24; ++round)
  {
    fit.rounds = round + 1;
    fit.knotsS = clamped(p, interiorS);
    fit.knotsT = clamped(p, interiorT);
    fit.countS = static_cast<int>(interiorS.size()) + p + 1;
    fit.countT = static_cast<int>(interiorT.size()) + p + 1;
    const int nS = fit.countS, nT = fit.countT, K = nS * nT;
    // Normal equations of the least-squares fit plus λ·(second differences of the net)².
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(data.size() * (p + 1) * (p + 1) * (p + 1) * (p + 1) + 27 * static_cast<size_t>(K));
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(K, 4);
    std::vector<int> index((p + 1) * (p + 1));
    std::vector<double> weight((p + 1) * (p + 1));
    for (const Sample& d : data)
    {
      const Basis bs = basisAt(fit.knotsS, p, nS, d.st.x());
      const Basis bt = basisAt(fit.knotsT, p, nT, d.st.y());
      for (int i = 0, n = 0; i <= p; ++i)
        for (int j = 0; j <= p; ++j, ++n)
        {
          index[n] = (bs.first + i) * nT + bt.first + j;
          weight[n] = bs.value[i] * bt.value[j];
        }
      for (size_t a = 0; a < index.size(); ++a)
      {
        for (size_t b = 0; b < index.size(); ++b)
          entries.emplace_back(index[a], index[b], weight[a] * weight[b]);
        rhs.row(index[a]) += weight[a] * Eigen::RowVector4d(d.x.x(), d.x.y(), d.x.z(), d.r);
      }
    }
    // The penalty: the thin-plate energy ∫ |S_ss|² + 2|S_st|² + |S_tt|² of the net, by
    // divided differences at the Greville abscissae (where a B-spline's control points of a
    // linear function lie, so linear data costs nothing on any knots), each weighted by
    // the area it stands for. Thin spans near a refined corner then cost what their
    // curvature does, and spans the data hardly reaches follow their neighbours.
    const std::vector<double> gs = greville(fit.knotsS, p, nS), gt = greville(fit.knotsT, p, nT);
    const double lambda = options.smoothing * static_cast<double>(data.size());
    auto penalise = [&](double area, const std::vector<std::pair<int, double>>& stencil) {
      for (const auto& [a, ca] : stencil)
        for (const auto& [b, cb] : stencil)
          entries.emplace_back(a, b, lambda * area * ca * cb);
    };
    auto secondDifference = [&](const std::vector<double>& g, int i, int k, int stride, double across) {
      const double h0 = g[i] - g[i - 1], h1 = g[i + 1] - g[i], h = 0.5 * (h0 + h1);
      penalise(h * across, { { k - stride, 1.0 / (h0 * h) }, { k, -(1.0 / h0 + 1.0 / h1) / h }, { k + stride, 1.0 / (h1 * h) } });
    };
    auto width = [](const std::vector<double>& g, int i) {
      return 0.5 * (g[std::min(i + 1, static_cast<int>(g.size()) - 1)] - g[std::max(i - 1, 0)]);
    };
    for (int i = 0; i < nS; ++i)
      for (int j = 0; j < nT; ++j)
      {
        const int k = i * nT + j;
        if (i > 0 && i + 1 < nS)
          secondDifference(gs, i, k, nT, width(gt, j));
        if (j > 0 && j + 1 < nT)
          secondDifference(gt, j, k, 1, width(gs, i));
        if (i + 1 < nS && j + 1 < nT)
        {
          const double hs = gs[i + 1] - gs[i], ht = gt[j + 1] - gt[j], c = 1.0 / (hs * ht);
          penalise(2.0 * hs * ht, { { k, c }, { k + 1, -c }, { k + nT, -c }, { k + nT + 1, c } });
        }
      }
    Eigen::SparseMatrix<double> normal(K, K);
    normal.setFromTriplets(entries.begin(), entries.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
    if (solver.info() != Eigen::Success)
      fail("sheet fit: the least-squares system of ", nS, " × ", nT, " control points is singular");
    const Eigen::MatrixXd net = solver.solve(rhs);
    fit.centres.resize(K);
    fit.radii.resize(K);
    for (int k = 0; k < K; ++k)
    {
      fit.centres[k] = net.row(k).head<3>().transpose();
      fit.radii[k] = net(k, 3);
    }
    // Errors, and the cells (span pairs) of the points off by more than the tolerance.
    using Span = std::pair<double, double>;
    std::set<std::pair<Span, Span>> bad;
    auto measure = [&](const std::vector<Sample>& samples) {
      double worst = 0.0;
      for (const Sample& d : samples)
      {
        Vec3 x;
        double r;
        fit.evaluate(d.st, x, r);
        const double e = std::max((x - d.x).norm(), std::abs(r - d.r));
        worst = std::max(worst, e);
        if (e > tolerance)
          bad.insert({ spanOf(interiorS, d.st.x()), spanOf(interiorT, d.st.y()) });
      }
      return worst / size;
    };
    fit.vertexError = measure(data);
    fit.checkError = measure(checks);
    fit.withinTolerance = fit.maxError() <= options.tolerance;
    // More spans than the sheet's vertices can fix only fit the vertices better and the
    // surface between them worse: the best round is kept.
    if (fit.maxError() < best.maxError())
    {
      best = fit;
      bestS = interiorS;
      bestT = interiorT;
    }
    if (fit.withinTolerance)
      break;
    // Halve the offending spans (each direction up to maxSpans spans) where a cell holds
    // enough vertices to fix the control points a split adds.
    std::map<std::pair<Span, Span>, int> count;
    for (const Sample& d : data)
    {
      const auto cell = std::make_pair(spanOf(interiorS, d.st.x()), spanOf(interiorT, d.st.y()));
      if (bad.count(cell))
        ++count[cell];
    }
    bool refined = false;
    for (const auto& [cell, n] : count)
    {
      if (n < 4 * (p + 1))
        continue;
      if (static_cast<int>(interiorS.size()) + 1 < options.maxSpans)
        refined = interiorS.insert(0.5 * (cell.first.first + cell.first.second)).second || refined;
      if (static_cast<int>(interiorT.size()) + 1 < options.maxSpans)
        refined = interiorT.insert(0.5 * (cell.second.first + cell.second.second)).second || refined;
    }
    if (!refined)
      break;
  }
  const int rounds = fit.rounds;
  fit = std::move(best);
  fit.rounds = rounds;
  interiorS = std::move(bestS);
  interiorT = std::move(bestT);

  // The trimming loops: the border loops' vertices, in the fit's parameters.
  size_t first = 0;
  for (int n : mesh.loopSizes)
  {
    std::vector<Vec2> loop;
    for (size_t v = first; v < first + n && v < mesh.vertices.size(); ++v)
      loop.push_back(fit.parameterOf(mesh.vertices[v].domain));
    first += n;
    fit.trimLoops.push_back(std::move(loop));
  }

  // The span rectangles the triangles reach, as Bézier patches.
  const int spansS = static_cast<int>(interiorS.size()) + 1, spansT = static_cast<int>(interiorT.size()) + 1;
  std::vector<double> breaksS{ 0.0 }, breaksT{ 0.0 };
  breaksS.insert(breaksS.end(), interiorS.begin(), interiorS.end());
  breaksT.insert(breaksT.end(), interiorT.begin(), interiorT.end());
  breaksS.push_back(1.0);
  breaksT.push_back(1.0);
  auto spanIndex = [](const std::vector<double>& breaks, double u) {
    const auto it = std::upper_bound(breaks.begin(), breaks.end() - 1, u);
    return std::clamp(static_cast<int>(it - breaks.begin()) - 1, 0, static_cast<int>(breaks.size()) - 2);
  };
  std::vector<bool> reached(static_cast<size_t>(spansS) * spansT, false);
  for (const auto& tri : mesh.triangles)
  {
    Vec2 a = Vec2::Constant(Unbounded), b = Vec2::Constant(-Unbounded);
    for (int v : tri)
    {
      const Vec2 st = fit.parameterOf(mesh.vertices[v].domain);
      a = a.cwiseMin(st);
      b = b.cwiseMax(st);
    }
    // (A triangle touching a knot line only along it does not reach the span beyond.)
    const double eps = 1e-12;
    for (int i = spanIndex(breaksS, a.x() + eps); i <= spanIndex(breaksS, b.x() - eps); ++i)
      for (int j = spanIndex(breaksT, a.y() + eps); j <= spanIndex(breaksT, b.y() - eps); ++j)
        reached[static_cast<size_t>(i) * spansT + j] = true;
  }
  Vec4List centreNet, radiusNet;
  for (int k = 0; k < fit.countS * fit.countT; ++k)
  {
    centreNet.emplace_back(fit.centres[k].x(), fit.centres[k].y(), fit.centres[k].z(), 1.0);
    radiusNet.emplace_back(fit.radii[k], 0.0, 0.0, 1.0);
  }
  const std::vector<BezierPatchSpan> centrePatches =
    extractBezier(NurbsSurface(p, p, fit.knotsS, fit.knotsT, fit.countS, fit.countT, centreNet));
  const std::vector<BezierPatchSpan> radiusPatches =
    extractBezier(NurbsSurface(p, p, fit.knotsS, fit.knotsT, fit.countS, fit.countT, radiusNet));
  for (size_t n = 0; n < centrePatches.size(); ++n)
  {
    if (!reached[n])
      continue;
    SheetFitPatch patch;
    patch.centre = centrePatches[n].patch;
    for (const Vec4& h : radiusPatches[n].patch.homogeneousNet())
      patch.radius.push_back(h.x());
    patch.s0 = centrePatches[n].u0;
    patch.s1 = centrePatches[n].u1;
    patch.t0 = centrePatches[n].v0;
    patch.t1 = centrePatches[n].v1;
    fit.patches.push_back(std::move(patch));
  }
  return fit;
}

} // namespace exactmat

#include "NormalisePieces.h"

#include "common/Format.h"
#include "common/InputError.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace exactmat
{

namespace
{
// The frame of a bounding box: its centre, and a power of two of its largest half-extent.
Normalisation frameOf(const Vec3& lo, const Vec3& hi)
{
  Normalisation n;
  // Halves first: hi − lo may overflow where hi/2 − lo/2 does not.
  n.centre = 0.5 * lo + 0.5 * hi;
  const double halfExtent = (0.5 * hi - 0.5 * lo).maxCoeff();
  if (halfExtent > 0.0 && std::isfinite(halfExtent))
    n.scale = std::ldexp(1.0, std::ilogb(halfExtent) + 1);
  return n;
}

std::string pieceName(const std::vector<CurvePiece>& pieces, size_t i)
{
  Edge2D e;
  e.piece = static_cast<int>(i);
  e.entity = pieces[i].entity;
  return e.name();
}
} // namespace

void normaliseWeights(std::vector<CurvePiece>& pieces)
{
  for (size_t i = 0; i < pieces.size(); ++i)
  {
    Vec4List h = pieces[i].curve.homogeneousPoints();
    double largest = 0.0;
    for (size_t k = 0; k < h.size(); ++k)
    {
      const double w = h[k].w();
      if (!(w > 0.0) || !std::isfinite(w))
        fail(pieceName(pieces, i), ": control point ", k, " has weight ", w,
          " (weights must be positive and finite)");
      largest = std::max(largest, w);
    }
    if (largest == 1.0)
      continue;
    for (Vec4& p : h)
      p /= largest;
    pieces[i].curve = BezierCurve(std::move(h));
  }
}

Normalisation normalisationOf(const std::vector<CurvePiece>& pieces)
{
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (size_t i = 0; i < pieces.size(); ++i)
  {
    for (int k = 0; k <= pieces[i].curve.degree(); ++k)
    {
      const Vec3 p = pieces[i].curve.controlPoint(k);
      if (!p.allFinite())
        fail(pieceName(pieces, i), ": control point ", k, " is not finite (", format(p), ")");
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  return pieces.empty() ? Normalisation() : frameOf(lo, hi);
}

Normalisation normalise(std::vector<CurvePiece>& pieces)
{
  normaliseWeights(pieces);
  const Normalisation n = normalisationOf(pieces);
  for (CurvePiece& piece : pieces)
  {
    Vec4List h = piece.curve.homogeneousPoints();
    for (Vec4& p : h)
    {
      // Through the Euclidean point: w·(x − c) loses nothing that w·x − w·c would keep.
      const double w = p.w();
      p = homogeneous(n.toUnit(euclidean(p)), w);
    }
    piece.curve = BezierCurve(std::move(h));
  }
  return n;
}

Boundary2D buildNormalised(std::vector<CurvePiece> pieces, Boundary2D::Options options)
{
  options.userFrame = normalise(pieces);
  // End points and planarity are known only to the input's rounding (a part far from the
  // origin was rounded before it reached us): no tolerance below a few ulp of it.
  const double rounding = 64.0 * options.userFrame.inputRounding();
  options.pointTolerance = std::max(options.pointTolerance, rounding);
  options.planarityTolerance = std::max(options.planarityTolerance, rounding);
  return Boundary2D::build(pieces, options);
}

namespace
{
std::string faceName(const std::vector<PatchPiece>& pieces, size_t i)
{
  Face3D f;
  f.piece = static_cast<int>(i);
  f.entity = pieces[i].entity;
  return f.name();
}

// Every homogeneous point of a piece (patch net, and the triangle's when it has one).
template <typename F>
void forEachNet(PatchPiece& piece, F f)
{
  Vec4List net = piece.patch.homogeneousNet();
  f(net);
  piece.patch = BezierPatch(piece.patch.degreeU(), piece.patch.degreeV(), std::move(net));
  if (piece.triangle)
    f(piece.triangle->points);
}
} // namespace

void normaliseWeights(std::vector<PatchPiece>& pieces)
{
  for (size_t i = 0; i < pieces.size(); ++i)
  {
    double largest = 0.0;
    const Vec4List& net = pieces[i].patch.homogeneousNet();
    for (size_t k = 0; k < net.size(); ++k)
    {
      const double w = net[k].w();
      if (!(w > 0.0) || !std::isfinite(w))
        fail(faceName(pieces, i), ": control point ", k, " has weight ", w,
          " (weights must be positive and finite)");
      largest = std::max(largest, w);
    }
    if (largest == 1.0)
      continue;
    // The triangle's weights are scaled too: its patch is the same surface.
    forEachNet(pieces[i], [largest](Vec4List& h) {
      for (Vec4& p : h)
        p /= largest;
    });
  }
}

Normalisation normalisationOf(const std::vector<PatchPiece>& pieces)
{
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (size_t i = 0; i < pieces.size(); ++i)
  {
    const Vec4List& net = pieces[i].patch.homogeneousNet();
    for (size_t k = 0; k < net.size(); ++k)
    {
      const Vec3 p = euclidean(net[k]);
      if (!p.allFinite())
        fail(faceName(pieces, i), ": control point ", k, " is not finite (", format(p), ")");
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  return pieces.empty() ? Normalisation() : frameOf(lo, hi);
}

Normalisation normalise(std::vector<PatchPiece>& pieces)
{
  normaliseWeights(pieces);
  const Normalisation n = normalisationOf(pieces);
  for (PatchPiece& piece : pieces)
    forEachNet(piece, [&n](Vec4List& h) {
      for (Vec4& p : h)
        p = homogeneous(n.toUnit(euclidean(p)), p.w());
    });
  return n;
}

Boundary3D buildNormalised(std::vector<PatchPiece> pieces, Boundary3D::Options options)
{
  options.userFrame = normalise(pieces);
  const double rounding = 64.0 * options.userFrame.inputRounding();
  options.pointTolerance = std::max(options.pointTolerance, rounding);
  return Boundary3D::build(pieces, options);
}

} // namespace exactmat

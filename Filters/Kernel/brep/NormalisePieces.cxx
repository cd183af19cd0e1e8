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
  Normalisation n;
  if (pieces.empty())
    return n;
  // Halves first: hi − lo may overflow where hi/2 − lo/2 does not.
  n.centre = 0.5 * lo + 0.5 * hi;
  const double halfExtent = (0.5 * hi - 0.5 * lo).maxCoeff();
  if (halfExtent > 0.0 && std::isfinite(halfExtent))
    n.scale = std::ldexp(1.0, std::ilogb(halfExtent) + 1);
  return n;
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

} // namespace exactmat

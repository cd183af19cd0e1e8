#include "MedialComplex.h"

#include <algorithm>

namespace exactmat
{

const char* toString(MedialPoint3DType type)
{
  switch (type)
  {
    case MedialPoint3DType::Sheet:
      return "sheet";
    case MedialPoint3DType::Seam:
      return "seam";
    case MedialPoint3DType::Junction:
      return "junction";
    case MedialPoint3DType::SeamEnd:
      return "seam-end";
    case MedialPoint3DType::SkeletalEdge:
      return "skeletal-edge";
    case MedialPoint3DType::ConvexEdge:
      return "convex-edge";
    case MedialPoint3DType::CircleCentre:
      return "circle-centre";
  }
  return "?";
}

const char* toString(MedialElementType type)
{
  switch (type)
  {
    case MedialElementType::Junction:
      return "junction";
    case MedialElementType::Seam:
      return "seam";
    case MedialElementType::SkeletalEdge:
      return "skeletal-edge";
    case MedialElementType::CentreCurve:
      return "centre-curve";
    case MedialElementType::SweptSheet:
      return "swept-sheet";
    case MedialElementType::ProfileSheet:
      return "profile-sheet";
    case MedialElementType::MidSheet:
      return "mid-sheet";
  }
  return "?";
}

int MedialComplex::count(MedialElementType type) const
{
  return static_cast<int>(std::count_if(elements.begin(), elements.end(),
    [type](const MedialElement& e) { return e.type == type; }));
}

int MedialComplex::countPoints(MedialPoint3DType type) const
{
  return static_cast<int>(std::count_if(
    points.begin(), points.end(), [type](const MedialPoint3D& p) { return p.type == type; }));
}

int MedialComplex::triangleCount() const
{
  int n = 0;
  for (const MedialElement& e : elements)
    n += static_cast<int>(e.triangles.size());
  return n;
}

double MedialComplex::maximumRadius() const
{
  double r = 0.0;
  for (const MedialPoint3D& p : points)
    r = std::max(r, p.radius);
  return r;
}

} // namespace exactmat

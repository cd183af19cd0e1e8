#include "MedialComplex.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

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
    case MedialPoint3DType::SphereCentre:
      return "sphere-centre";
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
    case MedialElementType::Sheet:
      return "sheet";
    case MedialElementType::SphereCentre:
      return "sphere-centre";
  }
  return "?";
}

namespace
{
int priority(MedialPoint3DType t)
{
  switch (t)
  {
    case MedialPoint3DType::SphereCentre:
      return 7;
    case MedialPoint3DType::Junction:
      return 6;
    case MedialPoint3DType::SeamEnd:
      return 5;
    case MedialPoint3DType::Seam:
      return 4;
    case MedialPoint3DType::SkeletalEdge:
      return 3;
    case MedialPoint3DType::CircleCentre:
      return 2;
    case MedialPoint3DType::ConvexEdge:
      return 1;
    case MedialPoint3DType::Sheet:
      return 0;
  }
  return 0;
}
} // namespace

int MedialComplex::fanSheetsToCurves()
{
  // Where each point lies on the curves: (element, index along it).
  std::vector<std::vector<std::pair<int, int>>> onCurve(points.size());
  bool curves = false;
  for (int e = 0; e < static_cast<int>(elements.size()); ++e)
    if (elements[e].type == MedialElementType::Seam || elements[e].type == MedialElementType::SkeletalEdge)
      for (int i = 0; i < static_cast<int>(elements[e].points.size()); ++i)
      {
        onCurve[elements[e].points[i]].push_back({ e, i });
        curves = true;
      }
  if (!curves)
    return 0;
  // The curve points strictly between a and b, from a to b (the shortest such run), or none.
  auto between = [&](int a, int b) {
    std::vector<int> run;
    if (onCurve[a].empty() || onCurve[b].empty())
      return run;
    for (const auto& [ea, i] : onCurve[a])
      for (const auto& [eb, j] : onCurve[b])
      {
        if (ea != eb || std::abs(i - j) < 2 || (!run.empty() && std::abs(i - j) - 1 >= static_cast<int>(run.size())))
          continue;
        const std::vector<int>& curve = elements[ea].points;
        run.clear();
        for (int k = i + (j > i ? 1 : -1); k != j; k += j > i ? 1 : -1)
          run.push_back(curve[k]);
      }
    return run;
  };
  int fanned = 0;
  for (MedialElement& e : elements)
  {
    if (e.triangles.empty())
      continue;
    // The element's border edges (in one of its triangles only) that join two curve points.
    std::unordered_map<std::uint64_t, int> uses;
    auto key = [](int a, int b) {
      return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
    };
    for (const auto& t : e.triangles)
      for (int k = 0; k < 3; ++k)
        if (!onCurve[t[k]].empty() && !onCurve[t[(k + 1) % 3]].empty())
          ++uses[key(t[k], t[(k + 1) % 3])];
    std::vector<std::array<int, 3>> out, work(e.triangles.rbegin(), e.triangles.rend());
    // (Each fan's triangles are checked again: a corner triangle may have two such edges.)
    for (size_t guard = 0; !work.empty() && guard < 100 * e.triangles.size() + 1000; ++guard)
    {
      const std::array<int, 3> t = work.back();
      work.pop_back();
      bool split = false;
      for (int k = 0; k < 3 && !split; ++k)
      {
        const int a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
        const auto use = uses.find(key(a, b));
        if (use == uses.end() || use->second != 1)
          continue;
        const std::vector<int> run = between(a, b);
        if (run.empty())
          continue;
        // Only a curve that runs along the edge (its points near the chord), not one that
        // merely passes through both ends elsewhere.
        const Vec3 pa = points[a].x, ab = points[b].x - pa;
        bool along = ab.squaredNorm() > 0.0;
        for (int m : run)
        {
          const double s = std::clamp((points[m].x - pa).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
          along = along && (points[m].x - pa - s * ab).norm() <= 0.25 * ab.norm();
        }
        if (!along)
          continue;
        split = true;
        ++fanned;
        int from = a;
        for (int m : run)
        {
          work.push_back({ { from, m, c } });
          from = m;
        }
        work.push_back({ { from, b, c } });
      }
      if (!split)
        out.push_back(t);
    }
    e.triangles = std::move(out);
  }
  return fanned;
}

int MedialComplex::weld(double tolerance)
{
  // Twins come out of the same formulas and differ by rounding: hash the points on a grid
  // a million times coarser than the tolerance and compare within their cell, and within
  // the neighbouring cell along an axis where a point lies within the tolerance of the
  // border (points at coordinate 0 do, on every profile face).
  const double cell = 1e6 * tolerance;
  using Key = std::array<long long, 3>;
  struct KeyHash
  {
    size_t operator()(const Key& k) const
    {
      // (Unsigned: the products wrap instead of overflowing.)
      return static_cast<size_t>(static_cast<unsigned long long>(k[0]) * 73856093ULL ^
        static_cast<unsigned long long>(k[1]) * 19349663ULL ^ static_cast<unsigned long long>(k[2]) * 83492791ULL);
    }
  };
  std::unordered_map<Key, int, KeyHash> first; // cell → first kept point in it
  first.reserve(points.size());
  std::vector<int> next; // kept point → the next kept point in its cell
  std::vector<int> target(points.size());
  std::vector<MedialPoint3D> kept;
  kept.reserve(points.size());
  int merged = 0;
  for (size_t i = 0; i < points.size(); ++i)
  {
    const MedialPoint3D& p = points[i];
    Key k;
    int options[3][2];
    int count[3];
    for (int a = 0; a < 3; ++a)
    {
      const double u = p.x[a] / cell, f = std::floor(u);
      // Clamped: a tolerance 1e-24 (a plate 1e-12 thin) puts coordinates of 1e6 at cell
      // 1e24, past long long; points that far out share a cell, compared within tolerance.
      k[a] = static_cast<long long>(std::clamp(f, -4e18, 4e18));
      count[a] = 1;
      options[a][0] = 0;
      if (u - f < 1e-5)
        options[a][count[a]++] = -1;
      else if (u - f > 1.0 - 1e-5)
        options[a][count[a]++] = 1;
    }
    int twin = -1;
    for (int a = 0; a < count[0] && twin < 0; ++a)
      for (int b = 0; b < count[1] && twin < 0; ++b)
        for (int c = 0; c < count[2] && twin < 0; ++c)
        {
          auto it = first.find({ k[0] + options[0][a], k[1] + options[1][b], k[2] + options[2][c] });
          for (int j = it == first.end() ? -1 : it->second; j >= 0 && twin < 0; j = next[j])
            if ((kept[j].x - p.x).norm() <= tolerance && std::abs(kept[j].radius - p.radius) <= tolerance)
              twin = j;
        }
    if (twin < 0)
    {
      const int id = static_cast<int>(kept.size());
      auto [it, inserted] = first.try_emplace(k, id);
      if (!inserted)
      {
        int last = it->second;
        while (next[last] >= 0)
          last = next[last];
        next[last] = id;
      }
      target[i] = id;
      kept.push_back(p);
      next.push_back(-1);
      continue;
    }
    target[i] = twin;
    ++merged;
    if (priority(p.type) > priority(kept[twin].type))
    {
      kept[twin].type = p.type;
      kept[twin].contacts = p.contacts;
    }
  }
  if (merged == 0)
    return 0;
  points = std::move(kept);
  for (MedialElement& e : elements)
  {
    for (int& id : e.points)
      id = target[id];
    const bool closed = e.points.size() > 2 && e.points.front() == e.points.back();
    e.points.erase(std::unique(e.points.begin(), e.points.end()), e.points.end());
    if (closed && e.points.size() > 1 && e.points.front() != e.points.back())
      e.points.push_back(e.points.front());
    size_t out = 0;
    for (std::array<int, 3> t : e.triangles)
    {
      for (int& id : t)
        id = target[id];
      if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
        e.triangles[out++] = t;
    }
    e.triangles.resize(out);
  }
  return merged;
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

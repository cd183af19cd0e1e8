#include "TransitionSheets.h"

#include "common/InputError.h"
#include "geometry/ClosestPoint.h"

#include <algorithm>
#include <limits>
#include <map>
#include <set>

namespace exactmat
{

namespace
{

using Pair = std::pair<int, int>;

Pair ordered(int a, int b)
{
  return { std::min(a, b), std::max(a, b) };
}

// Which generators a border vertex's sheet goes on with, on side k of the mesh's pair.
class Beyond
{
public:
  Beyond(const Boundary3D& boundary, const std::vector<Generator3D>& generators)
    : B(boundary)
    , G(generators)
    , Near(1e-7 * boundary.diagonal())
  {
    for (int e = 0; e < static_cast<int>(boundary.edges().size()); ++e)
    {
      const Edge3D& edge = boundary.edges()[e];
      EdgeAt[{ edge.faceA, edge.sideA }] = e;
      EdgeAt[{ edge.faceB, edge.sideB }] = e;
    }
    for (int g = 0; g < static_cast<int>(generators.size()); ++g)
      if (generators[g].kind() == GeneratorKind3D::ReflexEdge)
        EdgeGenerator[generators[g].entity()] = g;
      else if (generators[g].kind() == GeneratorKind3D::ReflexCorner)
        CornerGenerator[generators[g].entity()] = g;
  }

  std::vector<int> of(const SheetVertex& v, const std::vector<int>& members, int k) const
  {
    std::vector<int> out;
    if (members.empty())
      return out;
    const Generator3D& first = G[members.front()];
    if (first.kind() == GeneratorKind3D::ReflexEdge && members.size() == 1)
    {
      // Parameters (t, θ): θ = 0 is face A's normal, θ = α face B's (Generator3D).
      const Edge3D& edge = B.edges()[first.entity()];
      const Vec2& q = v.q[k];
      if (std::abs(q.y()) <= ParameterNear)
        out.push_back(edge.faceA);
      if (std::abs(q.y() - first.edgeAngle(std::clamp(q.x(), 0.0, 1.0))) <= ParameterNear)
        out.push_back(edge.faceB);
      for (int vertex : { edge.startVertex, edge.endVertex })
      {
        auto corner = CornerGenerator.find(vertex);
        if (corner != CornerGenerator.end() && (B.vertices()[vertex].point - v.touch[k]).norm() <= Near)
          out.push_back(corner->second);
      }
      return out;
    }
    if (first.kind() == GeneratorKind3D::ReflexCorner && members.size() == 1)
    {
      // The normal cone's border towards edge e is e's normal arc at its end (the normals
      // perpendicular to e): a ball whose normal is there goes on as the edge's sheet.
      if (v.r <= Near)
        return out;
      const Vec3 normal = (v.x - v.touch[k]) / v.r;
      for (size_t i = 0; i < first.cornerEdges().size(); ++i)
        if (auto edge = EdgeGenerator.find(first.cornerEdges()[i]);
            edge != EdgeGenerator.end() && std::abs(normal.dot(first.cornerTangents()[i])) <= ParameterNear)
          out.push_back(edge->second);
      return out;
    }
    if (first.kind() != GeneratorKind3D::Face)
      return out;
    const std::set<int> side(members.begin(), members.end());
    for (int f : members)
      for (int s = 0; s < 4; ++s)
      {
        auto at = EdgeAt.find({ f, s });
        if (at == EdgeAt.end() || B.edges()[at->second].kind != VertexKind::Reflex)
          continue;
        auto edge = EdgeGenerator.find(at->second);
        if (edge == EdgeGenerator.end())
          continue;
        const BezierCurve curve = B.faces()[f].patch.side(s);
        if (curve.boundingBox().exteriorDistance(v.touch[k]) <= Near && closestPoint(curve, v.touch[k]).distance <= Near)
          out.push_back(edge->second);
      }
    return out;
  }

private:
  static constexpr double ParameterNear = 1e-7;
  const Boundary3D& B;
  const std::vector<Generator3D>& G;
  double Near;
  std::map<Pair, int> EdgeAt;
  std::map<int, int> EdgeGenerator, CornerGenerator;
};

// Whether every point of generator g lies in the plane of planar face f (within 1e-9 of the
// size): a ball touching both touches them at one point — the pair has no sheet (a reflex
// edge or corner of a staircase in the plane of a step's face, coplanar faces).
bool inPlaneOf(const Boundary3D& boundary, const std::vector<Generator3D>& generators, int f, int g)
{
  if (generators[f].kind() != GeneratorKind3D::Face || !generators[f].planar())
    return false;
  const BezierPatch& patch = boundary.faces()[f].patch;
  const Vec3 origin = patch.evaluate(0.5, 0.5), normal = patch.normal(0.5, 0.5).normalized();
  const double near = 1e-9 * boundary.diagonal();
  Vec3List points;
  const Generator3D& other = generators[g];
  if (other.kind() == GeneratorKind3D::ReflexCorner)
    points.push_back(boundary.vertices()[other.entity()].point);
  else if (other.kind() == GeneratorKind3D::ReflexEdge)
  {
    const Edge3D& edge = boundary.edges()[other.entity()];
    const BezierCurve curve = boundary.faces()[edge.faceA].patch.side(edge.sideA);
    for (int i = 0; i <= curve.degree(); ++i)
      points.push_back(curve.controlPoint(i));
  }
  else if (other.planar())
  {
    const BezierPatch& q = boundary.faces()[other.entity()].patch;
    for (int i = 0; i <= q.degreeU(); ++i)
      for (int j = 0; j <= q.degreeV(); ++j)
        points.push_back(q.controlPoint(i, j));
  }
  if (points.empty())
    return false;
  for (const Vec3& x : points)
    if (std::abs((x - origin).dot(normal)) > near)
      return false;
  return true;
}

} // namespace

std::vector<TransitionSheet> transitionSheets(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
  const std::vector<SheetGroup>& groups, const std::vector<bool>& open, const std::vector<MedialSheetMesh>& meshes)
{
  std::set<Pair> known;
  std::map<std::pair<std::vector<int>, std::vector<int>>, int> knownSides;
  for (size_t k = 0; k < groups.size(); ++k)
  {
    const SheetGroup& group = groups[k];
    knownSides[{ group.a, group.b }] = static_cast<int>(k);
    if (k < open.size() && open[k])
      continue;
    for (int x : group.a)
      for (int y : group.b)
        known.insert(ordered(x, y));
  }
  const Beyond beyond(boundary, generators);
  std::map<Pair, std::vector<SheetBorderCurve>> runs;
  for (const MedialSheetMesh& mesh : meshes)
  {
    if (mesh.triangles.empty())
      continue;
    size_t first = 0;
    for (int size : mesh.loopSizes)
    {
      const size_t n = static_cast<size_t>(size);
      // Each border vertex's pairs beyond it (not yet known).
      std::vector<std::vector<Pair>> labels(n);
      for (size_t i = 0; i < n; ++i)
        for (int k : { 0, 1 })
          for (int g : beyond.of(mesh.vertices[first + i], mesh.members[k], k))
          {
            const int other = mesh.members[1 - k].front();
            const Pair p = ordered(other, g);
            if (p.first != p.second && !known.count(p) && !inPlaneOf(boundary, generators, other, g) &&
              !inPlaneOf(boundary, generators, g, other))
              labels[i].push_back(p);
          }
      auto has = [&labels, n](size_t i, const Pair& p) {
        const auto& l = labels[i % n];
        return std::find(l.begin(), l.end(), p) != l.end();
      };
      std::set<Pair> seen;
      for (size_t i = 0; i < n; ++i)
        for (const Pair& p : labels[i])
          seen.insert(p);
      for (const Pair& p : seen)
      {
        // Maximal runs of consecutive vertices (the loop is closed) that go on with p.
        size_t start = 0;
        while (start < n && has(start, p))
          ++start;
        const bool whole = start == n;
        if (whole)
          start = 0;
        for (size_t i = 0; i < n;)
        {
          const size_t at = (start + i) % n;
          if (!has(at, p))
          {
            ++i;
            continue;
          }
          SheetBorderCurve curve;
          while (i < n && has(start + i, p))
          {
            const SheetVertex& v = mesh.vertices[first + (start + i) % n];
            curve.centres.push_back(v.x);
            curve.radii.push_back(v.r);
            curve.ids.push_back(-1);
            ++i;
          }
          if (whole && !curve.centres.empty())
          {
            curve.centres.push_back(curve.centres.front());
            curve.radii.push_back(curve.radii.front());
            curve.ids.push_back(-1);
          }
          if (curve.centres.size() >= 2)
            runs[p].push_back(std::move(curve));
        }
      }
      first += n;
    }
  }
  // Two sheets whose runs coincide meet along that curve directly (a staircase's sheet of
  // two faces reaching a reflex edge just where the sheet of two reflex edges reaches a
  // face's normal): the pair they name has no area between them. Such runs are dropped.
  const double near = 1e-7 * boundary.diagonal();
  auto within = [near](const SheetBorderCurve& a, const SheetBorderCurve& b) {
    for (const Vec3& x : a.centres)
    {
      double d = std::numeric_limits<double>::infinity();
      for (size_t i = 0; i + 1 < b.centres.size() && d > near; ++i)
      {
        const Vec3 s = b.centres[i + 1] - b.centres[i];
        const double t = s.squaredNorm() > 0.0 ? std::clamp((x - b.centres[i]).dot(s) / s.squaredNorm(), 0.0, 1.0) : 0.0;
        d = (b.centres[i] + t * s - x).norm();
      }
      if (d > near)
        return false;
    }
    return true;
  };
  for (auto& [p, curves] : runs)
  {
    std::vector<bool> dropped(curves.size(), false);
    for (size_t i = 0; i < curves.size(); ++i)
      for (size_t j = i + 1; j < curves.size(); ++j)
        if (within(curves[i], curves[j]) && within(curves[j], curves[i]))
          dropped[i] = dropped[j] = true;
    std::vector<SheetBorderCurve> kept;
    for (size_t i = 0; i < curves.size(); ++i)
      if (!dropped[i])
        kept.push_back(std::move(curves[i]));
    curves = std::move(kept);
  }
  std::vector<std::array<int, 2>> pairs;
  std::vector<const std::vector<SheetBorderCurve>*> curvesOf;
  for (const auto& [p, curves] : runs)
  {
    if (curves.empty())
      continue;
    pairs.push_back({ { p.first, p.second } });
    curvesOf.push_back(&curves);
  }
  std::vector<TransitionSheet> out;
  for (const SheetGroup& group : groupSheets(boundary, generators, pairs))
  {
    if (group.traced.empty())
      continue;
    TransitionSheet sheet;
    sheet.group = { group.a, group.b, {} };
    if (auto built = knownSides.find({ group.a, group.b }); built != knownSides.end())
    {
      sheet.group = groups[built->second];
      sheet.extends = built->second;
    }
    for (int s : group.traced)
      sheet.curves.insert(sheet.curves.end(), curvesOf[s]->begin(), curvesOf[s]->end());
    out.push_back(std::move(sheet));
  }
  return out;
}

void addTransitionSheets(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
  std::vector<SheetGroup>& groups, std::vector<std::vector<SheetBorderCurve>>& borders,
  std::vector<MedialSheetMesh>& meshes, std::vector<std::string>& errors, const SheetOptions& options)
{
  constexpr int MaximumRounds = 8; // the cavities' sheets need two
  // Open: a reflex corner on one side, or found this way (then its border is only runs,
  // collected anew each round: borders[k] is empty).
  std::vector<bool> open(groups.size());
  std::vector<size_t> runsUsed(groups.size(), 0);
  for (size_t k = 0; k < groups.size(); ++k)
    open[k] = generators[groups[k].a.front()].kind() == GeneratorKind3D::ReflexCorner ||
      generators[groups[k].b.front()].kind() == GeneratorKind3D::ReflexCorner;
  // Sides found and not built: the number of runs they were tried with.
  std::map<std::pair<std::vector<int>, std::vector<int>>, size_t> refused;
  for (int round = 0; round < MaximumRounds; ++round)
  {
    bool grown = false;
    for (const TransitionSheet& sheet : transitionSheets(boundary, generators, groups, open, meshes))
      if (sheet.extends < 0)
      {
        const auto sides = std::make_pair(sheet.group.a, sheet.group.b);
        if (auto tried = refused.find(sides); tried != refused.end() && tried->second >= sheet.curves.size())
          continue;
        MedialSheetMesh mesh;
        try
        {
          mesh = interpolateSheet(boundary, generators, sheet.group, sheet.curves, options);
        }
        catch (const InputError&)
        {
        }
        if (mesh.triangles.empty()) // failed, or runs that enclose nothing
        {
          refused[sides] = sheet.curves.size();
          continue;
        }
        meshes.push_back(std::move(mesh));
        groups.push_back(sheet.group);
        borders.emplace_back();
        errors.emplace_back();
        open.push_back(true);
        runsUsed.push_back(sheet.curves.size());
        grown = true;
      }
      else if (sheet.curves.size() > runsUsed[sheet.extends])
      {
        const int k = sheet.extends;
        std::vector<SheetBorderCurve> curves = borders[k];
        curves.insert(curves.end(), sheet.curves.begin(), sheet.curves.end());
        runsUsed[k] = sheet.curves.size();
        grown = true;
        try
        {
          meshes[k] = interpolateSheet(boundary, generators, groups[k], curves, options);
          errors[k].clear();
        }
        catch (const InputError&)
        {
        }
      }
    if (!grown)
      break;
  }
}

} // namespace exactmat

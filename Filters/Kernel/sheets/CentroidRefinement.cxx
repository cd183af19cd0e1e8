#include "CentroidRefinement.h"

#include "common/InputError.h"

#include <algorithm>
#include <map>

namespace exactmat
{

void refineByCentroids(DomainTriangulation& domain, MedialSheetMesh& mesh, const SheetOptions& options, double size,
  const CentroidBall& ball, const std::function<void()>& added, const std::string& what)
{
  const double tolerance = options.tolerance * size, longest = options.maxEdge * size;
  // Triangles already found within the tolerance (by their vertices): their deviation and
  // the exact ball at their centroid.
  std::map<std::array<int, 3>, std::pair<double, SheetVertex>> accepted;
  for (int round = 0;; ++round)
  {
    if (round > 200)
      fail("3D MAT sheets: ", what, " is not refined within 200 rounds");
    int inserted = 0;
    mesh.maxDeviation = 0.0;
    mesh.checkPoints.clear();
    for (const std::array<int, 3>& t : domain.triangles())
    {
      std::array<int, 3> key = t;
      std::sort(key.begin(), key.end());
      if (const auto known = accepted.find(key); known != accepted.end())
      {
        mesh.maxDeviation = std::max(mesh.maxDeviation, known->second.first);
        mesh.checkPoints.push_back(known->second.second);
        continue;
      }
      const SheetVertex &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
      const Vec2 w = (a.domain + b.domain + c.domain) / 3.0;
      const Vec3 linear = (a.x + b.x + c.x) / 3.0;
      const double linearRadius = (a.r + b.r + c.r) / 3.0;
      // The longest edge of the triangle and of its footprints, the triangles of its
      // corners' touches: next to a rim the touches leave the osculating point like the
      // square root of the distance to it, and across a thin sheet they swing round the
      // solid, so a small triangle may touch a large, curved piece of a face — which its
      // corners' touches then do not describe (the coverage check measures the footprints).
      // (Not from an apex, nor from a ball within apexReach of it: their touches are points
      // of a whole circle, anywhere round it however close the balls come — a cap cut at a
      // slant put 200,000 vertices within 1e-12 of its apex — and the circle is the centre
      // curve's footprint.)
      double edge = std::max({ (a.x - b.x).norm(), (b.x - c.x).norm(), (c.x - a.x).norm() });
      for (int k = 0; k < 2; ++k)
        for (int i = 0; i < 3; ++i)
          if (!mesh.nearApex(t[i]) && !mesh.nearApex(t[(i + 1) % 3]))
            edge = std::max(edge, (mesh.vertices[t[i]].touch[k] - mesh.vertices[t[(i + 1) % 3]].touch[k]).norm());
      SheetVertex v = ball(w, t);
      v.domain = w;
      const double deviation = std::max((v.x - linear).norm(), std::abs(v.r - linearRadius));
      if (deviation <= tolerance && edge <= longest)
      {
        mesh.maxDeviation = std::max(mesh.maxDeviation, deviation / size);
        mesh.checkPoints.push_back(v);
        accepted[key] = { deviation / size, v };
        continue;
      }
      const int index = domain.insert(w);
      if (index < 0)
        continue;
      if (index != static_cast<int>(mesh.vertices.size()))
        fail("3D MAT sheets: ", what, ": the triangulation numbered a new point out of order");
      if (static_cast<int>(mesh.vertices.size()) >= options.maxVertices)
        fail("3D MAT sheets: ", what, " needs more than ", options.maxVertices, " vertices");
      mesh.vertices.push_back(v);
      added();
      ++inserted;
    }
    if (inserted == 0)
      break;
  }
  mesh.triangles = domain.triangles();
}

} // namespace exactmat

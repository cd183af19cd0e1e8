#include "Polyhedra.h"

#include "common/InputError.h"
#include "shapes/Moved.h"

#include <cmath>
#include <algorithm>
#include <array>
#include <map>

namespace exactmat
{

std::vector<PatchPiece> polyhedron(const Vec3List& v, const std::vector<std::vector<int>>& faces)
{
  std::vector<PatchPiece> pieces;
  auto triangle = [&](const Vec3& a, const Vec3& b, const Vec3& c, int entity) {
    TriangleNet net;
    net.degree = 1;
    net.points.resize(3);
    net.points[TriangleNet::index(1, 0, 0)] = homogeneous(a, 1);
    net.points[TriangleNet::index(1, 1, 0)] = homogeneous(b, 1);
    net.points[TriangleNet::index(1, 0, 1)] = homogeneous(c, 1);
    PatchPiece piece;
    piece.triangle = net;
    piece.patch = BezierPatch::fromTriangle(net);
    piece.entity = entity;
    pieces.push_back(piece);
  };
  for (size_t f = 0; f < faces.size(); ++f)
  {
    const std::vector<int>& l = faces[f];
    const int entity = static_cast<int>(f);
    if (l.size() == 3)
      triangle(v[l[0]], v[l[1]], v[l[2]], entity);
    else if (l.size() == 4)
    {
      PatchPiece piece;
      piece.patch = BezierPatch(1, 1,
        Vec4List{ homogeneous(v[l[0]], 1), homogeneous(v[l[3]], 1), homogeneous(v[l[1]], 1),
          homogeneous(v[l[2]], 1) });
      piece.entity = entity;
      pieces.push_back(piece);
    }
    else
    {
      Vec3 c = Vec3::Zero();
      for (int i : l)
        c += v[i];
      c /= static_cast<double>(l.size());
      for (size_t i = 0; i < l.size(); ++i)
        triangle(c, v[l[i]], v[l[(i + 1) % l.size()]], entity);
    }
  }
  return pieces;
}

std::vector<PatchPiece> boxPolyhedron(double a, double b, double c)
{
  Vec3List v;
  for (int i = 0; i < 8; ++i)
    v.push_back(Vec3((i & 1) ? a : -a, (i & 2) ? b : -b, (i & 4) ? c : -c));
  return polyhedron(v, { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 },
                          { 1, 3, 7, 5 } });
}

std::vector<PatchPiece> notchedCube(double b, double a)
{
  if (!(a > 0.0 && a < b))
    fail("notched cube: the notch corner ", a, " must lie inside the cube (0, ", b, ")");
  Vec3List v;
  auto at = [&v](double x, double y, double z) {
    const Vec3 p(x, y, z);
    for (size_t i = 0; i < v.size(); ++i)
      if (v[i] == p)
        return static_cast<int>(i);
    v.push_back(p);
    return static_cast<int>(v.size()) - 1;
  };
  // Every vertex on a face's border is in its loop, so the faces conform.
  const std::vector<std::vector<int>> faces{
    { at(0, 0, 0), at(0, b, 0), at(b, b, 0), at(b, 0, 0) },                                  // z = 0
    { at(0, 0, 0), at(0, b, 0), at(0, b, a), at(0, b, b), at(0, 0, b) },                     // x = 0
    { at(0, 0, 0), at(b, 0, 0), at(b, 0, a), at(b, 0, b), at(a, 0, b), at(0, 0, b) },        // y = 0
    { at(0, 0, b), at(a, 0, b), at(a, a, b), at(a, b, b), at(0, b, b) },                     // z = b
    { at(a, 0, b), at(b, 0, b), at(b, a, b), at(a, a, b) },
    { at(b, 0, 0), at(b, b, 0), at(b, b, a), at(b, a, a), at(b, 0, a) },                     // x = b
    { at(b, 0, a), at(b, a, a), at(b, a, b), at(b, 0, b) },
    { at(0, b, 0), at(0, b, a), at(a, b, a), at(b, b, a), at(b, b, 0) },                     // y = b
    { at(0, b, a), at(0, b, b), at(a, b, b), at(a, b, a) },
    { at(a, a, a), at(a, a, b), at(a, b, b), at(a, b, a) },                                  // the notch
    { at(a, a, a), at(b, a, a), at(b, a, b), at(a, a, b) },
    { at(a, a, a), at(a, b, a), at(b, b, a), at(b, a, a) },
  };
  return polyhedron(v, faces);
}

std::vector<PatchPiece> lPrism(double b, double h)
{
  const double c = 2.0 * b;
  const Vec3List v{ Vec3(0, 0, 0), Vec3(c, 0, 0), Vec3(c, b, 0), Vec3(b, b, 0), Vec3(b, c, 0), Vec3(0, c, 0),
    Vec3(0, 0, h), Vec3(c, 0, h), Vec3(c, b, h), Vec3(b, b, h), Vec3(b, c, h), Vec3(0, c, h) };
  std::vector<std::vector<int>> faces{ { 3, 2, 1, 0 }, { 5, 4, 3, 0 }, { 6, 7, 8, 9 }, { 6, 9, 10, 11 } };
  for (int i = 0; i < 6; ++i)
    faces.push_back({ i, (i + 1) % 6, 6 + (i + 1) % 6, 6 + i });
  return polyhedron(v, faces);
}

std::vector<PatchPiece> voxelSolid(const std::function<bool(int, int, int)>& filled, int nx, int ny, int nz, double cell)
{
  auto inside = [&](int i, int j, int k) {
    return i >= 0 && i < nx && j >= 0 && j < ny && k >= 0 && k < nz && filled(i, j, k);
  };
  Vec3List v;
  std::map<std::array<int, 3>, int> index;
  auto at = [&](const std::array<int, 3>& p) {
    const auto it = index.find(p);
    if (it != index.end())
      return it->second;
    v.push_back(cell * Vec3(p[0], p[1], p[2]));
    index[p] = static_cast<int>(v.size()) - 1;
    return static_cast<int>(v.size()) - 1;
  };
  std::vector<std::vector<int>> faces;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k)
      {
        if (!inside(i, j, k))
          continue;
        const std::array<int, 3> c{ { i, j, k } };
        for (int a = 0; a < 3; ++a)
          for (int side : { 0, 1 })
          {
            std::array<int, 3> next = c;
            next[a] += side ? 1 : -1;
            if (inside(next[0], next[1], next[2]))
              continue;
            const int b = (a + 1) % 3, d = (a + 2) % 3;
            auto corner = [&](int u, int w) {
              std::array<int, 3> p = c;
              p[a] += side;
              p[b] += u;
              p[d] += w;
              return at(p);
            };
            faces.push_back({ corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1) });
          }
      }
  return polyhedron(v, faces);
}

std::vector<PatchPiece> randomStaircase(std::mt19937& rng, int n, int maxHeight)
{
  std::uniform_int_distribution<int> drop(0, 1);
  std::vector<std::vector<int>> height(n, std::vector<int>(n, maxHeight));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
    {
      const int limit = std::min(i > 0 ? height[i - 1][j] : maxHeight, j > 0 ? height[i][j - 1] : maxHeight);
      height[i][j] = std::max(1, limit - drop(rng));
    }
  // At least one step: the first column full height, the last one cell.
  height[0][0] = maxHeight;
  if (n > 1)
    height[n - 1][n - 1] = 1;
  return voxelSolid([&height](int i, int j, int k) { return k < height[i][j]; }, n, n, maxHeight);
}

std::vector<PatchPiece> randomFrustum(std::mt19937& rng, int n)
{
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> angle(n);
  for (int i = 0; i < n; ++i)
    angle[i] = 2.0 * M_PI * (i + 0.15 + 0.7 * U(rng)) / n;
  const double ax = 1.0 + U(rng), ay = 0.6 + U(rng), lambda = 0.3 + 0.6 * U(rng), h = 0.5 + 1.5 * U(rng);
  const Vec3 shift(0.3 * (U(rng) - 0.5), 0.3 * (U(rng) - 0.5), h);
  Vec3List v;
  for (int i = 0; i < n; ++i)
    v.push_back(Vec3(ax * std::cos(angle[i]), ay * std::sin(angle[i]), 0.0));
  for (int i = 0; i < n; ++i)
    v.push_back(shift + lambda * v[i]);
  std::vector<std::vector<int>> faces;
  std::vector<int> bottom, top;
  for (int i = 0; i < n; ++i)
  {
    bottom.push_back(n - 1 - i);
    top.push_back(n + i);
    faces.push_back({ i, (i + 1) % n, n + (i + 1) % n, n + i });
  }
  faces.push_back(bottom);
  faces.push_back(top);
  return polyhedron(v, faces);
}

std::vector<PatchPiece> randomBoxWithCavity(std::mt19937& rng)
{
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int attempt = 0;; ++attempt)
  {
    const double a = 1.0 + 2.0 * U(rng), b = 0.7 + 1.5 * U(rng), c = 0.5 + 1.0 * U(rng);
    const double ha = (0.15 + 0.6 * U(rng)) * std::min({ a, b, c });
    const double hb = ha * (0.6 + 0.8 * U(rng)), hc = ha * (0.6 + 0.8 * U(rng));
    Vec3 o((a - ha) * (U(rng) - 0.5) * 1.6, (b - hb) * (U(rng) - 0.5) * 1.6, (c - hc) * (U(rng) - 0.5) * 1.6);
    const bool inside =
      std::abs(o.x()) + ha < 0.95 * a && std::abs(o.y()) + hb < 0.95 * b && std::abs(o.z()) + hc < 0.95 * c;
    // A draw that pokes out is drawn again (about one in four); after 64 the cavity is
    // centred, which always fits.
    if (!inside && attempt < 64)
      continue;
    if (!inside)
      o = Vec3::Zero();
    std::vector<PatchPiece> pieces = boxPolyhedron(a, b, c);
    for (PatchPiece& p : movedPieces(boxPolyhedron(ha, hb, hc), Eigen::Matrix3d::Identity(), 1.0, o))
    {
      p.entity += 6;
      pieces.push_back(std::move(p));
    }
    return pieces;
  }
}

std::vector<PatchPiece> boxWithFreeFormTop(double a, double b, double c, double bulge, double tilt)
{
  std::vector<PatchPiece> pieces = boxPolyhedron(a, b, c);
  Vec4List net;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
    {
      const bool inner = (i == 1 || i == 2) && (j == 1 || j == 2);
      const double z = c + (inner ? bulge * (1.0 + tilt * (i - 1.5)) : 0.0);
      net.push_back(homogeneous(Vec3(-a + 2.0 * a * i / 3.0, -b + 2.0 * b * j / 3.0, z), 1.0));
    }
  pieces[1].patch = BezierPatch(3, 3, std::move(net)); // face 1 of boxPolyhedron is z = c
  return pieces;
}

} // namespace exactmat

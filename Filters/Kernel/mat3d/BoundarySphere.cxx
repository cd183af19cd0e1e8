#include "mat3d/BoundarySphere.h"

#include <Eigen/Dense>

#include <cmath>

namespace exactmat
{

namespace
{
// The grid that decides a face: (2p + 3) × (2q + 3) parameters, sides included (the
// squared distance has degrees (2p, 2q); two more each way than it needs).
template <typename F>
void forGrid(const BezierPatch& patch, F&& f)
{
  const int nu = 2 * patch.degreeU() + 3, nv = 2 * patch.degreeV() + 3;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
      f(static_cast<double>(i) / (nu - 1), static_cast<double>(j) / (nv - 1));
}
} // namespace

bool onSphere(const BezierPatch& face, const BoundarySphere& sphere, double tolerance)
{
  bool on = true;
  forGrid(face, [&](double u, double v) {
    on = on && std::abs((face.evaluate(u, v) - sphere.centre).norm() - sphere.radius) <= tolerance;
  });
  return on;
}

std::optional<BoundarySphere> boundarySphere(const Boundary3D& boundary, double tolerance)
{
  const std::vector<Face3D>& faces = boundary.faces();
  if (faces.empty())
    return std::nullopt;
  // A face of degree 1 either way is ruled (straight lines through each point): it lies on
  // no sphere (the quickest no, for polyhedra).
  for (const Face3D& face : faces)
    if (face.patch.degreeU() < 2 || face.patch.degreeV() < 2)
      return std::nullopt;
  // |x|² = 2·c·x + (R² − |c|²): linear in (c, R² − |c|²); normal equations over every
  // grid point (the normalised frame keeps them well conditioned).
  Eigen::Matrix4d normal = Eigen::Matrix4d::Zero();
  Eigen::Vector4d rhs = Eigen::Vector4d::Zero();
  for (const Face3D& face : faces)
    forGrid(face.patch, [&](double u, double v) {
      const Vec3 x = face.patch.evaluate(u, v);
      const Eigen::Vector4d row(2.0 * x.x(), 2.0 * x.y(), 2.0 * x.z(), 1.0);
      normal += row * row.transpose();
      rhs += row * x.squaredNorm();
    });
  const Eigen::Vector4d s = normal.ldlt().solve(rhs);
  if (!s.allFinite())
    return std::nullopt;
  BoundarySphere sphere;
  sphere.centre = s.head<3>();
  const double r2 = s(3) + sphere.centre.squaredNorm();
  if (!(r2 > 0.0))
    return std::nullopt;
  sphere.radius = std::sqrt(r2);
  for (const Face3D& face : faces)
  {
    // (Normals away from the centre: the ball is the solid, not a spherical cavity.)
    const Vec3 middle = face.patch.evaluate(0.5, 0.5);
    if (!onSphere(face.patch, sphere, tolerance) || !(face.patch.normal(0.5, 0.5).dot(middle - sphere.centre) > 0.0))
      return std::nullopt;
  }
  return sphere;
}

} // namespace exactmat

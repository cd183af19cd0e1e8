#include "BallSystem.h"

#include <cmath>

namespace exactmat
{

Eigen::VectorXd MedialBall3D::pack() const
{
  const int k = size();
  Eigen::VectorXd z(2 * k + 4);
  for (int i = 0; i < k; ++i)
    z.segment<2>(2 * i) = q[i];
  z.segment<3>(2 * k) = x;
  z(2 * k + 3) = r;
  return z;
}

void MedialBall3D::unpack(const Eigen::VectorXd& z)
{
  const int k = size();
  for (int i = 0; i < k; ++i)
    q[i] = z.segment<2>(2 * i);
  x = z.segment<3>(2 * k);
  r = z(2 * k + 3);
}

Eigen::VectorXd BallSystem::residual(const MedialBall3D& ball) const
{
  const int k = ball.size();
  Eigen::VectorXd f(3 * k);
  for (int i = 0; i < k; ++i)
  {
    const Touch3D t = Generators[ball.generators[i]].evaluate(ball.q[i]);
    f.segment<3>(3 * i) = t.point + ball.r * t.normal - ball.x;
  }
  return f;
}

Eigen::MatrixXd BallSystem::jacobian(const MedialBall3D& ball) const
{
  const int k = ball.size();
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(3 * k, 2 * k + 4);
  for (int i = 0; i < k; ++i)
  {
    const Touch3D t = Generators[ball.generators[i]].evaluate(ball.q[i]);
    j.block<3, 2>(3 * i, 2 * i) = t.dPoint + ball.r * t.dNormal;
    j.block<3, 3>(3 * i, 2 * k) = -Eigen::Matrix3d::Identity();
    j.block<3, 1>(3 * i, 2 * k + 3) = t.normal;
  }
  return j;
}

Eigen::VectorXd BallSystem::tangent(const MedialBall3D& ball, double* separation) const
{
  const Eigen::MatrixXd j = jacobian(ball);
  // Square it up with a zero row: the SVD of a 10 × 10 gives the full right basis.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(j.cols(), j.cols());
  a.topRows(j.rows()) = j;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeFullV);
  const Eigen::VectorXd s = svd.singularValues();
  const int n = static_cast<int>(s.size());
  if (separation)
    *separation = s(n - 2) > 0.0 ? s(n - 1) / s(n - 2) : 1.0;
  Eigen::VectorXd t = svd.matrixV().col(n - 1);
  const int k = ball.size();
  const double dx = t.segment<3>(2 * k).norm();
  return dx > 0.0 ? Eigen::VectorXd(t / dx) : t;
}

bool BallSystem::correct(MedialBall3D& ball, double tolerance, const Eigen::VectorXd* tangent,
  const Eigen::VectorXd* anchor, double fixRadius) const
{
  const int k = ball.size();
  const int unknowns = 2 * k + 4;
  const bool constrained = tangent != nullptr || fixRadius >= 0.0;
  Eigen::VectorXd z = ball.pack();
  for (int iteration = 0; iteration < 12; ++iteration)
  {
    const Eigen::VectorXd f = residual(ball);
    const double norm = f.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(norm))
      return false;
    Eigen::MatrixXd j = jacobian(ball);
    Eigen::VectorXd rhs = -f;
    if (constrained)
    {
      j.conservativeResize(j.rows() + 1, Eigen::NoChange);
      rhs.conservativeResize(rhs.size() + 1);
      if (fixRadius >= 0.0)
      {
        j.row(j.rows() - 1).setZero();
        j(j.rows() - 1, unknowns - 1) = 1.0;
        rhs(rhs.size() - 1) = fixRadius - z(unknowns - 1);
      }
      else
      {
        j.row(j.rows() - 1) = tangent->transpose();
        rhs(rhs.size() - 1) = -tangent->dot(z - *anchor);
      }
    }
    const double constraint = constrained ? std::abs(rhs(rhs.size() - 1)) : 0.0;
    if (norm <= tolerance && constraint <= tolerance)
      return true;
    const Eigen::VectorXd dz = j.completeOrthogonalDecomposition().solve(rhs);
    if (!dz.allFinite())
      return false;
    z += dz;
    ball.unpack(z);
  }
  const Eigen::VectorXd f = residual(ball);
  return f.lpNorm<Eigen::Infinity>() <= tolerance;
}

} // namespace exactmat

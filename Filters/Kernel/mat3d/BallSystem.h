#pragma once
/// @file BallSystem.h
/// @brief The equations of a medial ball touching k generators (thesis app. C, in the form
/// DESIGN.md §3 asks for): unknowns z = (q_1 … q_k, X, r), equations
///     S_i(q_i) + r·N_i(q_i) − X = 0,   i = 1 … k          (3k equations, 2k + 4 unknowns).
/// k = 3 (a seam): 9 equations in 10 unknowns, a curve of solutions, traced by
/// pseudo-arclength continuation: the tangent is the Jacobian's null vector, so a seam
/// leaving a junction along an iso-parameter line, or with every parameter moving, is no
/// special case. k = 4: a junction, a square system. k ≥ 5 (a degenerate junction, the
/// centre of a cube): over-determined but consistent, solved in the least-squares sense.

#include "mat3d/Generator3D.h"

#include <Eigen/Dense>
#include <vector>

namespace exactmat
{

/// A ball touching generators `generators[i]` at parameters q[i].
struct MedialBall3D
{
  std::vector<int> generators; ///< indices into the tracer's generator list (faces)
  std::vector<Vec2> q;
  Vec3 x = Vec3::Zero();
  double r = 0.0;
  /// The touch points, recorded for the output when tracing ends (not an unknown).
  Vec3List touches;

  int size() const { return static_cast<int>(generators.size()); }
  Eigen::VectorXd pack() const;
  void unpack(const Eigen::VectorXd& z);
};

class BallSystem
{
public:
  explicit BallSystem(const std::vector<Generator3D>& generators)
    : Generators(generators)
  {
  }

  Eigen::VectorXd residual(const MedialBall3D& ball) const;
  Eigen::MatrixXd jacobian(const MedialBall3D& ball) const;

  /// The unit null vector of a seam's 9 × 10 Jacobian, scaled so its centre part has unit
  /// length (steps are lengths along the seam). `separation` receives the smallest
  /// singular value over the next one: near 1 where the null space is not one-dimensional
  /// (the triplet has no seam through this ball).
  Eigen::VectorXd tangent(const MedialBall3D& ball, double* separation = nullptr) const;

  /// Newton from `ball` onto the solution set. With `tangent` (a seam), the step is kept in
  /// the hyperplane through `anchor` normal to it (pseudo-arclength); `fixRadius` ≥ 0
  /// instead fixes r (a seam ending at a convex vertex, r = 0). Without either, the
  /// least-squares solution nearest the start (junctions). True when the residual reaches
  /// `tolerance` (a length) within a few iterations.
  bool correct(MedialBall3D& ball, double tolerance, const Eigen::VectorXd* tangent = nullptr,
    const Eigen::VectorXd* anchor = nullptr, double fixRadius = -1.0) const;

private:
  const std::vector<Generator3D>& Generators;
};

} // namespace exactmat

#pragma once
/// @file Bisector.h
/// @brief The equidistance system of a generator pair (thesis §4.3.1, app. A), written
/// with unit inward normals: P_a(s_a) + r·N_a(s_a) = P_b(s_b) + r·N_b(s_b).
///
/// Unknowns y = (s_a, s_b, r). Two equations, three unknowns: the MAT segment of the pair
/// is the solution curve. Unlike eq. A.4 this stays regular where the two normals are
/// parallel; it is singular only at a centre of curvature (r·κ = 1) and at r = 0.

#include "mat2d/Generators.h"

namespace exactmat
{

struct BisectorState
{
  double sa = 0.0, sb = 0.0, r = 0.0;
};

class Bisector
{
public:
  Bisector(const Generators& generators, int ga, int gb)
    : G(&generators)
    , A(ga)
    , B(gb)
  {
  }
  int generatorA() const { return A; }
  int generatorB() const { return B; }

  /// The MAT point P_a + r·N_a.
  Vec2 point(const BisectorState& y) const;
  /// Residual E(y) = P_a + r N_a − P_b − r N_b.
  Vec2 residual(const BisectorState& y) const;
  /// Unit tangent of the solution curve at y (the null vector of the 2×3 Jacobian), with
  /// its sign chosen so that the fronts advance (s_a along `dirA`, s_b along `dirB`).
  Eigen::Vector3d tangent(const BisectorState& y, int dirA, int dirB) const;
  /// The same from both generators already evaluated at y (a tracing step needs them for
  /// the point, the tangent, the motion and the step's weights: evaluated once).
  Eigen::Vector3d tangent(const GeneratorPoint& a, const GeneratorPoint& b, double r, int dirA, int dirB) const;
  /// How far the MAT point, the footpoints and the contact directions move per unit of
  /// y along `t`: the norm used to size steps.
  double motion(const BisectorState& y, const Eigen::Vector3d& t) const;
  double motion(const GeneratorPoint& a, const GeneratorPoint& b, double r, const Eigen::Vector3d& t) const;

  /// Newton on E = 0 with unknown `fixed` (0: s_a, 1: s_b, 2: r) held at its value in y.
  /// Converges to |E| ≤ tolerance in ≤ 30 iterations, else returns false. Parameters
  /// must stay in [0,1] and r ≥ 0.
  /// When given, atA and atB receive both generators evaluated at the solution (the
  /// convergence check's own evaluation: the caller's point and curvatures come free).
  bool correct(BisectorState& y, int fixed, double tolerance, GeneratorPoint* atA = nullptr,
    GeneratorPoint* atB = nullptr) const;

private:
  const Generators* G;
  int A, B;
};

/// Polishes a branch point (thesis §4.3.2) by Newton on the three-generator system
/// P_a + r N_a = P_b + r N_b = P_c + r N_c (unknowns s_a, s_b, s_c, r), so that it is
/// exact to rounding rather than to the bisection's tolerance. A footpoint that Newton
/// carries past its generator's end across a smooth or reflex junction moves on to the
/// neighbouring generator (the generator ids are updated): at a node whose footpoints lie
/// at junctions of pieces (a symmetric blob's troughs) rounding puts each on either side.
/// Returns false (leaving the inputs) when it does not converge within 30 iterations or
/// leaves the parameter ranges at a convex vertex.
bool polishBranchPoint(const Generators& G, int& ga, int& gb, int& gc, double& sa, double& sb,
  double& sc, double& r, double tolerance);

} // namespace exactmat

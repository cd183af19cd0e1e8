#pragma once
/// @file GaussLegendre.h
/// @brief The 8-point Gauss–Legendre rule on [0, 1] (exact for polynomials of degree 15):
/// the surface integrals over patches (enclosed volume, winding number).

namespace exactmat
{

inline constexpr double GaussLegendre8X[8] = { 0.0198550717512319, 0.1016667612931866, 0.2372337950418355,
  0.4082826787521751, 0.5917173212478249, 0.7627662049581645, 0.8983332387068134, 0.9801449282487681 };
inline constexpr double GaussLegendre8W[8] = { 0.0506142681451881, 0.1111905172266872, 0.1568533229389436,
  0.1813418916891810, 0.1813418916891810, 0.1568533229389436, 0.1111905172266872, 0.0506142681451881 };

} // namespace exactmat

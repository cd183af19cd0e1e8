#pragma once
/// @file WindingNumber.h
/// @brief How many times a closed, oriented surface of rational Bézier patches winds around
/// a point: 1 inside a shell whose normals point outwards, 0 outside. Decides which shell
/// of a solid is a cavity of which (Boundary3D turns a cavity's normals into it).

#include "nurbs/BezierPatch.h"

#include <vector>

namespace exactmat
{

/// (1/4π) Σ ∬ (S − p)·(Su × Sv) / |S − p|³ du dv over the patches: the solid angle they
/// subtend at p in units of the whole sphere. Each patch is cut into quarters until every
/// piece is at least twice its own size away from p (its control box), then integrated by
/// 8 × 8 Gauss points: within about 1e-6 of the true value however close p is (enough to
/// round to the whole number it is for a closed surface). Returns NaN
/// when p lies on the surface, or closer to it than 2⁻⁴⁰ of a patch's size.
double windingNumber(const std::vector<BezierPatch>& shell, const Vec3& p);

} // namespace exactmat

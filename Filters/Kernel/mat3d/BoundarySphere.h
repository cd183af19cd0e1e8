#pragma once
/// @file BoundarySphere.h
/// @brief Whether a solid is a ball: every face lies on one sphere, its normals pointing
/// away from the centre. The MAT of a ball is its centre alone — one medial ball that
/// touches the whole boundary — which no seam, rim or circle of contact leads to.
///
/// On a face S = X/w of degrees (p, q), the squared distance from a centre c less R², in
/// homogeneous form |X − c·w|² − R²·w², is a polynomial of degrees (2p, 2q): it vanishes
/// identically when it vanishes on a grid of (2p + 1) × (2q + 1) parameters. So the test
/// on such a grid (denser by two each way) is exact up to its tolerance, not a sampling.

#include "brep/Boundary3D.h"

#include <optional>

namespace exactmat
{

struct BoundarySphere
{
  Vec3 centre = Vec3::Zero();
  double radius = 0.0;
};

/// Whether the face lies on the sphere: every point of its grid at the radius from the
/// centre within `tolerance` (a length).
bool onSphere(const BezierPatch& face, const BoundarySphere& sphere, double tolerance);

/// The sphere every face lies on within `tolerance` (a length), or none: the centre and
/// radius fitted by least squares to the faces' grid points, then every grid point held to
/// |distance − radius| ≤ tolerance and every face's normal checked to point away from it.
std::optional<BoundarySphere> boundarySphere(const Boundary3D& boundary, double tolerance);

} // namespace exactmat

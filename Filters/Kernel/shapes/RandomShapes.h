#pragma once
/// @file RandomShapes.h
/// @brief Random valid planar domains for the robustness tests and the fuzz benchmark
/// (issue: "thousands of random shapes"), reproducible from a seed, and the rigid motions,
/// scalings and weight scalings under which a MAT must not change.
///
/// Every generator returns a valid domain by construction (star-shaped loops about the
/// origin, holes well inside), so a failure of the MAT on one of them is a bug of the MAT.

#include "nurbs/NurbsCurve.h"

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace exactmat
{

using RandomEngine = std::mt19937_64;

struct RandomShape
{
  std::string description; ///< "star polygon, 300 edges (seed 7)": reproduces the shape
  std::vector<NurbsCurve> curves;
  int holes = 0;
};

/// A star polygon of n edges: vertex k at angle 2πk/n (jittered by up to a quarter of
/// the spacing) and radius uniform in [0.5, 1.5].
RandomShape randomStarPolygon(RandomEngine& rng, int edges);
/// A regular n-gon inscribed in the unit circle with every vertex moved by up to
/// `jitter` (near-degenerate: its centre is a node of degree n when jitter = 0).
RandomShape perturbedRegularPolygon(RandomEngine& rng, int edges, double jitter);
/// A closed rational cubic B-spline blob (12–24 control points at radii in [0.6, 1], random
/// weights in [0.5, 2]) with up to `maxHoles` disjoint circular holes inside radius 0.38.
RandomShape randomBlob(RandomEngine& rng, int maxHoles);
/// One of the above, or a saw-tooth strip, chosen at random, with at most `maxEdges`
/// polygon edges.
RandomShape randomDomain(RandomEngine& rng, int maxEdges);

/// A similarity of the plane plus a factor per curve on its weights.
struct ShapeMotion
{
  double angle = 0.0;                 ///< rotation about the origin, radians
  double scale = 1.0;                 ///< then scaling
  Vec3 offset = Vec3::Zero();         ///< then translation
  double weightScale = 1.0;           ///< every curve's weights multiplied by this

  Vec3 apply(const Vec3& p) const;
  NurbsCurve apply(const NurbsCurve& c) const;
  std::vector<NurbsCurve> apply(const std::vector<NurbsCurve>& curves) const;
  std::string describe() const;
};

/// A random motion: rotation uniform, scale 10^U(−6, 6), offset up to 1e7 × the scaled
/// size in a random direction, weights scaled by 10^U(−100, 100).
ShapeMotion randomMotion(RandomEngine& rng);

} // namespace exactmat

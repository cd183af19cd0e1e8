#pragma once
/// @file MAT25D.h
/// @brief The MAT of an extruded or revolved solid from its profile's 2D MAT (thesis
/// ch. 5): no tracing in 3D, every entity is a transformed 2D one.
///
/// For a profile point p with 2D medial radius r, the ball of radius r about T_τ(p) touches
/// the sides where the disk touched the profile (the normals sweep with the profile,
/// Theorem B.1) and the start face when τ = capSpan(p, r) (§5.5.1). Hence, with S the span:
/// * junctions: branch points at τ = capSpan and S − capSpan (four or more touchpoints;
///   Prop. 5.1: there are no others);
/// * seams: normal points at the same spans (three touchpoints), and the "fourth seam" at
///   each branch point: its ruling/parallel between the two junctions (Prop. 5.2);
/// * skeletal edges: the ruling/parallel of each centre of curvature of an LMPC point;
/// * seam ends at convex vertices (radius 0) and on skeletal edges;
/// * swept sheets: each profile MAT segment swept between its two seams;
/// * profile sheets, between a profile face and one side: over the segment from a
///   footpoint F to its MAT point x, the point F + t(x − F) has distance t·r to the
///   boundary, so the sheet point is T_τ(F + t(x − F)) with τ = capSpan(·, t·r).
/// A 360° revolution has no profile faces: the revolved 2D MAT, with no seams from faces.
///
/// Spans shorter than the thesis needs (2·capSpan > span somewhere: an extrusion shorter
/// than 2·Rmax) are handled too, which chapter 5 leaves out: where a profile MAT point's
/// ball would reach both profile faces first, the MAT has a **mid-sheet** on the bisector
/// of the two faces (τ = span/2; radius span/2, or x·sin(span/2) for revolutions). It
/// covers the strips' upper parts, from the point where t·r reaches that radius (a seam
/// touching both faces and one side, on the trimmed offset of the profile) to the MAT
/// point; where a profile MAT segment crosses it, a junction touching both faces and two
/// sides, solved on the pair's bisector. Span = 2·capSpan exactly gives degenerate
/// junctions and seams from the same code (points where both seams meet carry one more
/// touchpoint).
///
/// Governor ids (MedialElement::governors): e ∈ [0, E) the side swept by profile edge e
/// (Boundary2D edge index), E the start profile face, E + 1 the end one, E + 2 + v the
/// reflex edge swept by profile vertex v.

#include "medial/MedialComplex.h"
#include "mat25d/Sweep.h"
#include "mat2d/MedialGraph.h"

#include <functional>

namespace exactmat
{

struct MAT25DOptions
{
  /// Target spacing of sheet vertices across the sweep and from boundary to seam, as a
  /// fraction of the solid's size. Every vertex is an exact MAT point whatever the spacing.
  double sheetResolution = 0.02;
  /// Called with the fraction done (0..1).
  std::function<void(double)> progress;
};

/// Builds the 3D MAT of the profile swept by `sweep` from the profile's 2D MAT. Throws
/// InputError when the 2D MAT is empty.
MedialComplex computeMAT25D(const Generators& profile, const MedialGraph& profileMAT,
  const SweepMap& sweep, const MAT25DOptions& options = {});

/// Governor id of a profile generator (its side face, or the reflex edge of a corner).
int governorOfGenerator(const Generators& profile, int g);

} // namespace exactmat

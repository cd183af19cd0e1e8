#pragma once
/// @file SweptSolid.h
/// @brief The closed boundary of an extruded or revolved solid as rational Bézier patches,
/// conforming along every shared edge: what vtkNURBSSource outputs for display, and what a
/// 3D method can take as input.
///
/// The sides are exact (SweepMap::sideFaces). A profile face is a planar region bounded by
/// free-form loops, possibly with holes, which no single untrimmed patch covers; it is
/// tiled by the profile's medial strips: between consecutive MAT samples x_i, x_{i+1} of a
/// segment and their footpoints F_i, F_{i+1} on one side, the patch ruled between the
/// boundary piece F_i..F_{i+1} (cut from the exact curve, in standard form) and the chord
/// x_i x_{i+1}. The strips partition the face (each boundary point belongs to one), the
/// pieces' borders are exact, and neighbours share chords and rulings, so the tiling is
/// exact and conforming; the sides are cut at the same footpoint parameters to conform.

#include "mat25d/Sweep.h"
#include "mat2d/MedialGraph.h"

#include <vector>

namespace exactmat
{

/// The faces of the swept solid. Sides carry the profile edge's entity; the start and end
/// profile faces the entities maxEntity + 1 and maxEntity + 2 (maxEntity: the largest
/// edge entity, at least −1).
std::vector<PatchPiece> sweptSolidFaces(
  const Generators& profile, const MedialGraph& profileMAT, const SweepMap& sweep);

} // namespace exactmat

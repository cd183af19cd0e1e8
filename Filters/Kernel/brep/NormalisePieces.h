#pragma once
/// @file NormalisePieces.h
/// @brief Takes boundary pieces to the normalised frame (common/Normalisation.h): each
/// piece's weights scaled so the largest is 1, the control points centred and scaled to
/// unit size.

#include "brep/Boundary2D.h"
#include "brep/Boundary3D.h"
#include "common/Normalisation.h"

#include <vector>

namespace exactmat
{

/// Scales each piece's homogeneous control points so its largest weight is 1 (the curve
/// is unchanged: a rational curve does not see a common factor of its weights). Throws
/// InputError naming the piece when a weight is not positive and finite.
void normaliseWeights(std::vector<CurvePiece>& pieces);

/// The normalisation that takes the control points of `pieces` (all of them, every
/// piece's weights already normalised) to a box centred at the origin whose largest
/// half-extent lies in [0.5, 1). Throws InputError naming the piece and control point
/// when a coordinate is not finite. A box of zero size keeps scale 1 (Boundary2D then
/// reports the degenerate input).
Normalisation normalisationOf(const std::vector<CurvePiece>& pieces);

/// normaliseWeights, then every control point mapped by normalisationOf(pieces): the
/// pieces in the unit frame, ready for Boundary2D::build. Returns the map back.
Normalisation normalise(std::vector<CurvePiece>& pieces);

/// The B-rep of `pieces` built in the normalised frame, with that frame as its user frame
/// (Boundary2D::userPoint): how every MAT filter takes its input.
Boundary2D buildNormalised(std::vector<CurvePiece> pieces, Boundary2D::Options options = {});

/// The same for the faces of a solid: weights, then the control points of every patch (and
/// triangle) taken to the unit frame.
void normaliseWeights(std::vector<PatchPiece>& pieces);
Normalisation normalisationOf(const std::vector<PatchPiece>& pieces);
Normalisation normalise(std::vector<PatchPiece>& pieces);
Boundary3D buildNormalised(std::vector<PatchPiece> pieces, Boundary3D::Options options = {});

} // namespace exactmat

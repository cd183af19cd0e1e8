#pragma once
/// @file TransitionSheets.h
/// @brief Sheets no seam borders, found on the borders of the sheets built beside them.
///
/// The 3D tracer lists a sheet's pair only when some seam's triplet holds it. A sheet whose
/// border lies wholly where its touch reaches an edge — the sheet of a cavity face and the
/// outer face across a gap narrower than any other, bounded where its touch on the cavity
/// face reaches the cavity's edges and the sheet of the outer face and that edge goes on —
/// is in no triplet. Its border is drawn by its neighbours: a run of border vertices of a
/// built sheet whose touch on a reflex edge reaches an end of its normal arc (θ = 0, α: the
/// sheet goes on with the edge's face) or an end of the edge at a reflex corner (goes on
/// with the corner), or whose touch on a face reaches a side where a reflex edge bounds it
/// (goes on with the edge), names the pair beyond it.

#include "sheets/SheetInterpolation.h"

#include <string>
#include <vector>

namespace exactmat
{

struct TransitionSheet
{
  SheetGroup group;                      ///< its sides (sheetSide); traced is empty if new
  std::vector<SheetBorderCurve> curves;  ///< the runs of its neighbours' borders it meets (ids −1)
  int extends = -1; ///< its index in `groups` when it is one of the open ones, else −1 (new)
};

/// The sheets beyond the borders of `meshes` (built for `groups`, index for index): those
/// whose sides are not among `groups`, and those among them marked `open` (sheets that take
/// their neighbours' runs: found this way before, or with a reflex corner on one side, whose
/// border where it goes on as an edge's sheet is a curve its own gap closing does not
/// follow), each with every border run that names it.
std::vector<TransitionSheet> transitionSheets(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
  const std::vector<SheetGroup>& groups, const std::vector<bool>& open, const std::vector<MedialSheetMesh>& meshes);

/// The sheets of `groups`, built from `borders` (index for index: `meshes`, and `errors`
/// empty or the reason it failed), completed: rounds of transitionSheets add the sheets
/// found beyond their borders (interpolateSheet with `options`) and build the open ones
/// again with their neighbours' runs, until a round adds nothing (at most eight). A sheet
/// found this way that does not close is left out, not failed — the tracer listed no such
/// pair, and the runs that name it may be where two sheets meet along a curve with nothing
/// between them (a staircase's exact coincidences); a real sheet left out leaves the faces
/// it covers short, which the coverage check reports. A sheet left out is tried again when
/// a later round brings it more runs (its first run alone may not close it: a turned
/// solid's rounding made the loops of a cavity corner's sheet cross). An open sheet built
/// again is kept as it was when that does not close.
void addTransitionSheets(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
  std::vector<SheetGroup>& groups, std::vector<std::vector<SheetBorderCurve>>& borders,
  std::vector<MedialSheetMesh>& meshes, std::vector<std::string>& errors, const SheetOptions& options);

} // namespace exactmat

"""Wall thickness of a solid part from its medial sheets: the thickness at a point of the
part's mid-surface is the diameter (2 x Radius) of the largest ball that fits there.

    PYTHONPATH=build/<python site dir> /usr/bin/python3 wall_thickness.py [PART] [--thin T] [-o OUT.vtp]

PART: a STEP/IGES solid, a .vtu of Bezier faces or an ExactMAT .json (default: the bundled
stepped block). Prints the thickest wall, the thickness distribution over the sheets' area
and the share of the mid-surface thinner than T (default: a tenth of the part's size);
writes the mid-surface with point data WallThickness (default: wall-thickness.vtp).
"""
import argparse
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter, vtkXMLUnstructuredGridReader

import exactmat
from exactmat import vtkMAT3DFilter, vtkNURBSSource

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("part", nargs="?", help="STEP/IGES, .vtu or .json solid")
parser.add_argument("--shape", default="stepped-block", help="bundled shape when no PART is given")
parser.add_argument("--thin", type=float, help="report the mid-surface thinner than this")
parser.add_argument("-o", "--output", default="wall-thickness.vtp")
args = parser.parse_args()

if args.part is None:
    source = vtkNURBSSource()
    source.SetShapeName(args.shape)
elif args.part.lower().endswith((".step", ".stp", ".iges", ".igs")):
    source = exactmat.vtkCADBoundaryReader()
    source.SetFileName(args.part)
elif args.part.lower().endswith(".json"):
    source = exactmat.vtkNURBSReader()
    source.SetFileName(args.part)
else:
    source = vtkXMLUnstructuredGridReader()
    source.SetFileName(args.part)

# The seams and junctions, then the sheets between them: the whole MAT, verified against
# the exact faces (every point's distance to the boundary equals its radius).
mat = vtkMAT3DFilter()
mat.SetInputConnection(source.GetOutputPort())
sheets = exactmat.vtkSheetInterpolator()
sheets.SetInputConnection(mat.GetOutputPort())
sheets.SetSourceConnection(source.GetOutputPort())
sheets.SetFitSheets(False)  # the triangles are all this needs
errors = exactmat.ErrorObserver()
errors.watch(source, mat, sheets)
sheets.Update()
errors.check()
if not sheets.GetVerificationPassed():
    sys.exit("the MAT did not verify: thicknesses would not be trustworthy")

out = sheets.GetOutput()
points = vtk_to_numpy(out.GetPoints().GetData())
radius = vtk_to_numpy(out.GetPointData().GetArray("Radius"))
element = vtk_to_numpy(out.GetCellData().GetArray("ElementType"))
thickness = 2.0 * radius
array = numpy_to_vtk(thickness, deep=True)
array.SetName("WallThickness")
out.GetPointData().AddArray(array)

# Area-weighted over the sheet triangles (ElementType 7): each triangle carries the mean
# thickness of its corners.
triangles = [c for c in range(out.GetNumberOfCells()) if element[c] == 7]
corners = np.array([[out.GetCell(c).GetPointId(k) for k in range(3)] for c in triangles])
a, b, c = points[corners[:, 0]], points[corners[:, 1]], points[corners[:, 2]]
area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
mean = thickness[corners].mean(axis=1)
size = np.linalg.norm(np.ptp(points, axis=0))
thin = args.thin if args.thin is not None else 0.1 * size

print(f"{sheets.GetNumberOfInterpolatedSheets()} sheets, {len(triangles)} triangles, "
      f"mid-surface area {area.sum():.6g}")
print(f"thickest wall        {thickness.max():.6g} (the largest ball: radius {radius.max():.6g})")
print(f"mean wall thickness  {np.average(mean, weights=area):.6g} (area-weighted over the mid-surface)")
print(f"thinner than {thin:.4g}   {100.0 * area[mean < thin].sum() / area.sum():.2f} % of the mid-surface")
for lo, hi in zip(np.linspace(0.0, thickness.max(), 6)[:-1], np.linspace(0.0, thickness.max(), 6)[1:]):
    share = area[(mean >= lo) & (mean < hi)].sum() / area.sum()
    print(f"  {lo:8.4g} .. {hi:<8.4g} {'#' * int(round(50 * share)):<50} {100 * share:5.1f} %")

writer = vtkXMLPolyDataWriter()
writer.SetInputData(out)
writer.SetFileName(args.output)
assert writer.Write() == 1
print("wrote", args.output)

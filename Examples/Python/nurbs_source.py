"""Make an exact boundary, look at it through numpy, and save it as ExactMAT JSON.

    PYTHONPATH=build/<python site dir> /usr/bin/python3 nurbs_source.py annulus.json
"""
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

from exactmat import vtkNURBSSource, vtkNURBSWriter

out = sys.argv[1] if len(sys.argv) > 1 else "annulus.json"

source = vtkNURBSSource()
source.SetShapeName("annulus")
source.SetRadius(2.0)
source.SetInnerRadius(0.75)
source.Update()
grid = source.GetOutput()

points = vtk_to_numpy(grid.GetPoints().GetData())
weights = vtk_to_numpy(grid.GetPointData().GetArray("RationalWeights"))
edges = vtk_to_numpy(grid.GetCellData().GetArray("EdgeId"))
print(f"{grid.GetNumberOfCells()} rational Bezier cells on {len(set(edges))} NURBS curves")
# The curve points (weight 1) lie exactly on the two circles.
on_curve = points[weights == 1.0]
radii = np.sort(np.unique(np.round(np.linalg.norm(on_curve, axis=1), 12)))
print("radii of the end points:", radii)
assert np.allclose(radii, [0.75, 2.0], atol=1e-12)

writer = vtkNURBSWriter()
writer.SetInputConnection(source.GetOutputPort())
writer.SetFileName(out)
assert writer.Write() == 1
print("wrote", out)

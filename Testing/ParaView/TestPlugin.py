"""Loads the built ExactMAT plugin in pvpython or pvbatch, builds a pipeline by the proxies'
names, fetches the output and checks it numerically; with a PNG path, renders off-screen
and saves a screenshot (run under xvfb-run).

    pvbatch TestPlugin.py <plugin.so> [screenshot.png]
"""
import math
import os
import sys

from paraview import servermanager
from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetColorTransferFunction, GetScalarBar, LoadPlugin, OpenDataFile, Render,
                             ResetCamera, SaveScreenshot, Show)

plugin = sys.argv[1]
png = sys.argv[2] if len(sys.argv) > 2 else None

LoadPlugin(plugin, remote=False, ns=globals())

source = NURBSSource(registrationName="annulus")  # noqa: F821 (defined by LoadPlugin)
source.Shape = "annulus"
source.Radius = 2.0
source.InnerRadius = 0.75
source.UpdatePipeline()

data = servermanager.Fetch(source)
assert data.GetNumberOfCells() == 8, data.GetNumberOfCells()
weights = data.GetPointData().GetArray("RationalWeights")
assert weights is not None
# End points of the cells (weight 1, on the curves) lie exactly on the two circles.
radii = set()
for i in range(data.GetNumberOfPoints()):
    if weights.GetValue(i) == 1.0:
        x, y, z = data.GetPoint(i)
        radii.add(round(math.hypot(x, y), 12))
assert radii == {0.75, 2.0}, radii

# The MAT filter by its proxy name: the annulus' MAT is the circle of radius 1.375 with
# radius function 0.625 everywhere.
mat = MAT2DFilter(Input=source)  # noqa: F821
mat.UpdatePipeline()
medial = servermanager.Fetch(mat)
assert medial.GetNumberOfPoints() > 20
r = medial.GetPointData().GetArray("Radius")
for i in range(medial.GetNumberOfPoints()):
    x, y, z = medial.GetPoint(i)
    assert abs(math.hypot(x, y) - 1.375) < 1e-12 and abs(r.GetValue(i) - 0.625) < 1e-12

# The 2.5D filter: the 4 x 2 rectangle extruded by 3 has junctions (+-1, 0, 1), (+-1, 0, 2).
profile = NURBSSource(registrationName="profile")  # noqa: F821
profile.Shape = "rectangle"
mat25 = MAT25DFilter(Input=profile)  # noqa: F821
mat25.Length = 3.0
mat25.UpdatePipeline()
solidMAT = servermanager.Fetch(mat25)
assert solidMAT.GetNumberOfVerts() == 4, solidMAT.GetNumberOfVerts()
kind = solidMAT.GetPointData().GetArray("PointType")
r25 = solidMAT.GetPointData().GetArray("Radius")
junctions = [solidMAT.GetPoint(i) for i in range(solidMAT.GetNumberOfPoints()) if kind.GetValue(i) == 2]
assert len(junctions) == 4 and all(abs(abs(p[0]) - 1) < 1e-12 and abs(p[1]) < 1e-12 for p in junctions), junctions
assert abs(r25.GetRange()[1] - 1.0) < 1e-12
profile.Sweep = "Extrusion"
profile.UpdatePipeline()
assert servermanager.Fetch(profile).GetCellType(0) == 77  # the swept solid: Bezier quadrilaterals

# The catalogue is selectable by name; a 3D shape gives Bezier quadrilaterals.
source.Shape = "pillow"
source.UpdatePipeline()
pillow = servermanager.Fetch(source)
assert pillow.GetNumberOfCells() == 6 and pillow.GetCellType(0) == 77, pillow.GetCellType(0)

# The 3D filter on the pillow: eight seams into one junction at the centre.
mat3 = MAT3DFilter(Input=source)  # noqa: F821
mat3.UpdatePipeline()
seams = servermanager.Fetch(mat3)
assert seams.GetNumberOfVerts() == 1 and seams.GetNumberOfLines() == 8, (seams.GetNumberOfVerts(), seams.GetNumberOfLines())

# Its sheets: the complete MAT, twelve curved sheets sharing the seams' points, verified.
sheets = SheetInterpolator(Input=mat3, Source=source)  # noqa: F821
sheets.Tolerance = 1e-3
sheets.MaximumSheetPointsVerified = 300
sheets.UpdatePipeline()
full = servermanager.Fetch(sheets)
assert full.GetNumberOfLines() == 8 and full.GetNumberOfPolys() > 100, (full.GetNumberOfLines(), full.GetNumberOfPolys())
assert full.GetFieldData().GetArray("VerificationStatus").GetValue(0) == 1

# ParaView opens an IGES part with the plugin's reader: exact planar faces, the 3D MAT.
part = OpenDataFile(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Data", "cad", "l-prism.igs"))
assert part is not None and part.GetXMLName() == "CADBoundaryReader", part
partMAT = MAT3DFilter(Input=part)  # noqa: F821
partMAT.UpdatePipeline()
assert servermanager.Fetch(partMAT).GetNumberOfVerts() == 5

# A collection of parts (Group Datasets) through the 2D filter: each part's MAT in its place,
# a summary row per part.
from paraview.simple import GroupDatasets  # noqa: E402
ring = NURBSSource(registrationName="ring")  # noqa: F821
ring.Shape = "annulus"
square = NURBSSource(registrationName="square")  # noqa: F821
square.Shape = "rectangle"
group = GroupDatasets(Input=[ring, square])
groupMAT = MAT2DFilter(Input=group)  # noqa: F821
groupMAT.NumberOfThreads = 2
groupMAT.UpdatePipeline()
collection = servermanager.Fetch(groupMAT)
assert collection.IsA("vtkCompositeDataSet"), collection.GetClassName()
status = collection.GetFieldData().GetArray("PartStatus")
assert status is not None and status.GetNumberOfTuples() == 2, status
assert [status.GetValue(i) for i in range(2)] == [0, 0]
segments = collection.GetFieldData().GetArray("NumberOfSegments")
assert sorted(segments.GetValue(i) for i in range(2)) == [1, 5]

source.Shape = "plate-with-holes"
source.UpdatePipeline()

if png:
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [900, 500]
    view.OrientationAxesVisibility = 0
    view.Background = [1.0, 1.0, 1.0]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    display = Show(source, view)
    display.NonlinearSubdivisionLevel = 4
    display.LineWidth = 3.0
    display.AmbientColor = [0.1, 0.1, 0.1]
    display.DiffuseColor = [0.1, 0.1, 0.1]
    mat.UpdatePipeline()
    medialDisplay = Show(mat, view)
    medialDisplay.LineWidth = 4.0
    ColorBy(medialDisplay, ("POINTS", "Radius"))
    medialDisplay.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(GetColorTransferFunction("Radius"), view)
    bar.TitleColor = [0.1, 0.1, 0.1]
    bar.LabelColor = [0.1, 0.1, 0.1]
    ResetCamera(view)
    Render(view)
    SaveScreenshot(png, view, ImageResolution=[900, 500])

    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    scalars = reader.GetOutput().GetPointData().GetScalars()
    dark = sum(1 for i in range(0, scalars.GetNumberOfTuples(), 7) if scalars.GetComponent(i, 0) < 128)
    assert dark > 100, "the screenshot shows no boundary (%d dark samples)" % dark
print("ExactMAT plugin OK")

"""Run by the ParaView GUI (paraview --script=… --exit under Xvfb): load the plugin, build a
pipeline, render it, and write what came out to $EXACTMAT_MARKER for the test to check."""
import os

from paraview import servermanager
from paraview.simple import LoadPlugin, Render, Show

LoadPlugin(os.environ["EXACTMAT_PLUGIN"], remote=False, ns=globals())
source = NURBSSource()  # noqa: F821 (defined by LoadPlugin)
source.Shape = "star"
source.UpdatePipeline()
data = servermanager.Fetch(source)
Show(source)
Render()
with open(os.environ["EXACTMAT_MARKER"], "w") as marker:
    marker.write("cells %d\n" % data.GetNumberOfCells())

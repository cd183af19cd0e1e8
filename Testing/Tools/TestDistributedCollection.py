"""A collection spread over MPI ranks as ParaView spreads it (run under
`mpiexec -n 2 pvbatch --mpi --symmetric`): each rank holds some parts (the others' places
are empty grids, as distributed readers leave them) and asks the MAT filter for its piece.
Every rank computes only its own parts, each equal bit for bit to that part's own run,
and every rank's output carries the whole collection's summary: the bad part and a part
no rank holds are named, the filter's counts are the collection's. Solids' seams and
sheets alike. A single boundary from a source (given to piece 0) is computed once, on
rank 0, without errors elsewhere.
"""
import json
import os
import sys
import tempfile

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIntArray
from vtkmodules.vtkCommonDataModel import (vtkCompositeDataSet, vtkPartitionedDataSetCollection,
                                           vtkUnstructuredGrid)
from vtkmodules.vtkParallelCore import vtkCommunicator, vtkMultiProcessController

import exactmat
import exactmat.batch

controller = vtkMultiProcessController.GetGlobalController()
rank, ranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
failures = []


def check(condition, what):
    if not condition:
        failures.append(f"rank {rank}: {what}")


def shape(name):
    source = exactmat.vtkNURBSSource()
    source.SetShapeName(name)
    source.Update()
    grid = vtkUnstructuredGrid()
    grid.DeepCopy(source.GetOutput())
    return grid


def open_curve():
    path = os.path.join(tempfile.gettempdir(), f"exactmat-open-curve-{os.getpid()}.json")
    with open(path, "w") as f:
        json.dump({"format": "exactmat-nurbs", "version": 1, "curves": [
            {"id": 0, "degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 0]]}]}, f)
    reader = exactmat.vtkNURBSReader()
    reader.SetFileName(path)
    reader.Update()
    os.remove(path)
    grid = vtkUnstructuredGrid()
    grid.DeepCopy(reader.GetOutput())
    return grid


check(ranks == 2, f"run with 2 ranks, not {ranks}")
names = ["rectangle", "l-shape", "star", "open-sketch", "circle", "nowhere", "plate-with-holes"]
collection = vtkPartitionedDataSetCollection()
for i, name in enumerate(names):
    mine = i % ranks == rank and name != "nowhere"
    grid = (open_curve() if name == "open-sketch" else shape(name)) if mine else vtkUnstructuredGrid()
    collection.SetPartition(i, 0, grid)
    collection.GetMetaData(i).Set(vtkCompositeDataSet.NAME(), name)

mat = exactmat.vtkMAT2DFilter()
mat.SetInputDataObject(collection)
mat.SetNumberOfThreads(1)
mat.GlobalWarningDisplayOff()
mat.UpdatePiece(rank, ranks, 0)
out = mat.GetOutputDataObject(0)
fd = out.GetFieldData()
summary_names = [fd.GetAbstractArray("PartName").GetValue(k) for k in range(len(names))]
check(fd.GetAbstractArray("PartName").GetNumberOfValues() == len(names), "a row per part, all ranks'")
check(summary_names == names, f"summary rows in collection order: {summary_names}")
status = {n: fd.GetArray("PartStatus").GetValue(k) for k, n in enumerate(summary_names)}
message = {n: fd.GetAbstractArray("PartMessage").GetValue(k) for k, n in enumerate(summary_names)}
for n in names:
    if n in ("open-sketch", "nowhere"):
        check(status[n] == 3, f"{n} failed")
    else:
        check(status[n] == 0, f"{n} verified ({message[n]})")
check("open loop" in message["open-sketch"], f"the bad part's reason: {message['open-sketch']}")
check(message["nowhere"] == "no boundary cells on any rank", f"the missing part: {message['nowhere']}")
check(mat.GetNumberOfParts() == len(names), f"NumberOfParts {mat.GetNumberOfParts()}")
check(mat.GetNumberOfFailedParts() == 2, f"NumberOfFailedParts {mat.GetNumberOfFailedParts()}")
check(not mat.GetVerificationPassed(), "a failed part fails the collection")
segments = fd.GetArray("NumberOfSegments")
check(segments is not None and segments.GetValue(names.index("plate-with-holes")) == 20,
      "the plate's 20 segments reach every rank")

for i, name in enumerate(names):
    part = out.GetPartitionAsDataObject(i, 0)
    if i % ranks != rank or name in ("open-sketch", "nowhere"):
        check(part is None or part.GetNumberOfPoints() == 0, f"{name}: not computed here")
        continue
    alone = exactmat.vtkMAT2DFilter()
    alone.SetInputData(shape(name))
    alone.SetNumberOfThreads(1)
    alone.Update()
    ref = alone.GetOutput()
    check(part is not None and part.GetNumberOfPoints() == ref.GetNumberOfPoints() > 0,
          f"{name}: its own MAT here")
    if part is not None and part.GetNumberOfPoints() == ref.GetNumberOfPoints():
        check(numpy.array_equal(vtk_to_numpy(part.GetPoints().GetData()), vtk_to_numpy(ref.GetPoints().GetData()))
              and numpy.array_equal(vtk_to_numpy(part.GetPointData().GetArray("Radius")),
                                    vtk_to_numpy(ref.GetPointData().GetArray("Radius"))),
              f"{name}: the same MAT as its own run, bit for bit")

# Solids: seams and sheets of a collection spread over the ranks, each rank filling its own.
solid_names = ["box", "notched-cube", "stepped-block"]
solids = vtkPartitionedDataSetCollection()
for i, name in enumerate(solid_names):
    solids.SetPartition(i, 0, shape(name) if i % ranks == rank else vtkUnstructuredGrid())
    solids.GetMetaData(i).Set(vtkCompositeDataSet.NAME(), name)
seams = exactmat.vtkMAT3DFilter()
seams.SetInputDataObject(solids)
seams.SetNumberOfThreads(1)
sheets = exactmat.vtkSheetInterpolator()
sheets.SetInputConnection(seams.GetOutputPort())
sheets.SetSourceData(solids)
sheets.SetNumberOfThreads(1)
sheets.UpdatePiece(rank, ranks, 0)
complete = sheets.GetOutputDataObject(0)
fd = complete.GetFieldData()
check([fd.GetAbstractArray("PartName").GetValue(k) for k in range(fd.GetAbstractArray("PartName").GetNumberOfValues())]
      == solid_names, "the sheets' summary names every solid on every rank")
check(sheets.GetNumberOfParts() == 3 and sheets.GetNumberOfFailedParts() == 0,
      f"sheets: {sheets.GetNumberOfParts()} parts, {sheets.GetNumberOfFailedParts()} failed")
for i, name in enumerate(solid_names):
    part = complete.GetPartitionAsDataObject(i, 0)
    if i % ranks != rank:
        check(part is None or part.GetNumberOfPoints() == 0, f"{name}: its sheets not filled here")
        continue
    source = exactmat.vtkNURBSSource()
    source.SetShapeName(name)
    one = exactmat.vtkMAT3DFilter()
    one.SetInputConnection(source.GetOutputPort())
    alone = exactmat.vtkSheetInterpolator()
    alone.SetInputConnection(one.GetOutputPort())
    alone.SetSourceConnection(source.GetOutputPort())
    alone.SetNumberOfThreads(1)
    alone.Update()
    ref = alone.GetOutput()
    check(part is not None and part.GetNumberOfPoints() == ref.GetNumberOfPoints() > 0
          and numpy.array_equal(vtk_to_numpy(part.GetPointData().GetArray("Radius")),
                                vtk_to_numpy(ref.GetPointData().GetArray("Radius"))),
          f"{name}: the same sheets as its own run")

# One boundary from a source: piece 0 has it, the other rank outputs nothing, no error.
source = exactmat.vtkNURBSSource()
source.SetShapeName("l-shape")
single = exactmat.vtkMAT2DFilter()
single.SetInputConnection(source.GetOutputPort())
errors = exactmat.ErrorObserver()
errors.watch(single)
single.UpdatePiece(rank, ranks, 0)
points = single.GetOutput().GetNumberOfPoints()
check(not errors.messages, f"no error on any rank: {errors.messages}")
check((points > 0) == (rank == 0), f"the single boundary's MAT on rank 0 only ({points} points)")

# The same through ParaView's own proxies: the plugin's MAT 2D Filter on a .vtpc read by
# ParaView's distributed reader (which decides who holds what): every rank's output carries
# the whole summary, each part's MAT is on exactly one rank.
from paraview import simple
path = os.path.abspath("exactmat-distributed.vtpc")  # the ranks share the working directory
if rank == 0:
    from vtkmodules.vtkIOParallelXML import vtkXMLPartitionedDataSetCollectionWriter
    parts = vtkPartitionedDataSetCollection()
    for i, name in enumerate(["rectangle", "l-shape", "star", "circle"]):
        parts.SetPartition(i, 0, shape(name))
        parts.GetMetaData(i).Set(vtkCompositeDataSet.NAME(), name)
    writer = vtkXMLPartitionedDataSetCollectionWriter()
    writer.SetInputData(parts)
    writer.SetController(None)  # rank 0 alone writes the whole collection
    writer.SetFileName(path)
    check(writer.Write() == 1, "the .vtpc is written")
controller.Barrier()
simple.LoadPlugin(sys.argv[1], remote=False, ns=globals())
reader = simple.XMLPartitionedDatasetCollectionReader(FileName=[path])
proxy = globals()["MAT2DFilter"](Input=reader)
proxy.UpdatePipeline()
local = proxy.GetClientSideObject().GetOutputDataObject(0)
fd = local.GetFieldData()
check([fd.GetAbstractArray("PartName").GetValue(k) for k in range(fd.GetAbstractArray("PartName").GetNumberOfValues())]
      == ["rectangle", "l-shape", "star", "circle"], "ParaView: the whole summary on every rank")
check(all(fd.GetArray("PartStatus").GetValue(k) == 0 for k in range(4)), "ParaView: every part verified")
held = vtkIntArray()
for i in range(4):
    part = local.GetPartitionAsDataObject(i, 0) if i < local.GetNumberOfPartitionedDataSets() else None
    held.InsertNextValue(1 if part is not None and part.GetNumberOfPoints() > 0 else 0)
held_total = vtkIntArray()
controller.AllReduce(held, held_total, vtkCommunicator.SUM_OP)
check([held_total.GetValue(i) for i in range(4)] == [1, 1, 1, 1], "ParaView: each part's MAT on exactly one rank")
controller.Barrier()
if rank == 0:
    for f in [path] + [os.path.join(os.path.splitext(path)[0], x) for x in os.listdir(os.path.splitext(path)[0])]:
        os.remove(f)
    os.rmdir(os.path.splitext(path)[0])

count = vtkIntArray()
count.InsertNextValue(len(failures))
total = vtkIntArray()
controller.AllReduce(count, total, vtkCommunicator.SUM_OP)
for f in failures:
    print("FAIL", f, flush=True)
if rank == 0:
    print(f"distributed collection: {total.GetValue(0)} failure(s) over {ranks} ranks", flush=True)
exactmat.batch.leave(1 if total.GetValue(0) else 0)

"""Many parts through one ExactMAT filter, shared among MPI ranks: the cluster form of
``exactmat batch``, with the same outputs (one NAME.vtp per part, index.pvd, summary.csv).

On a cluster (or this machine), through ParaView's MPI-enabled pvbatch::

    mpiexec -n 4 pvbatch --mpi --symmetric /path/to/exactmat/batch.py parts/ -o results/

Without MPI (one rank, threads only): ``python3 -m exactmat.batch parts/ -o results/``.

Rank r of N takes parts r, r + N, r + 2N, ... (in sorted file order), computes its share
as one vtkPartitionedDataSetCollection through the filter (its threads: ``-j``), and
writes each part's MAT; rank 0 then gathers every rank's rows (MPI GatherV) into
summary.csv and index.pvd. A part that cannot be read or computed is reported by name in
the summary; the others are computed. The exit status, on every rank and so mpiexec's, is
that of ``exactmat batch``: 0 all verified, 1 some part failed, 3 some part's
verification failed (mpiexec then also prints that a process "returned a non-zero exit
code").
"""
import argparse
import csv
import json
import os
import sys

PART_EXTENSIONS = (".vtu", ".json", ".step", ".stp", ".iges", ".igs")
STATUS = {0: "verified", 1: "not verified", 2: "verification failed", 3: "failed"}
COLUMNS = ["part", "file", "mode", "status", "segments_or_seams",
           "branch_points_or_junctions", "points", "seconds", "verified_error", "message"]


def part_files(inputs):
    files = []
    for path in inputs:
        if os.path.isdir(path):
            found = sorted(os.path.join(path, f) for f in os.listdir(path)
                           if f.lower().endswith(PART_EXTENSIONS)
                           and os.path.isfile(os.path.join(path, f)))
            if not found:
                raise SystemExit(f"exactmat batch: folder '{path}' holds no part file")
            files.extend(found)
        else:
            files.append(path)
    return files


def part_names(files):
    """File stems, made unique and safe as file names (as `exactmat batch` names them)."""
    names, used = [], set()
    for f in files:
        stem = os.path.splitext(os.path.basename(f))[0]
        stem = "".join(c if (c.isascii() and c.isalnum()) or c in "-_." else "_" for c in stem)
        name, k = stem or "part", 2
        while name in used:
            name, k = f"{stem}-{k}", k + 1
        used.add(name)
        names.append(name)
    return names


def controller():
    """The controller ParaView's pvbatch/pvpython set up (MPI under pvbatch --mpi), or None
    (a plain Python process)."""
    try:
        from vtkmodules.vtkParallelCore import vtkMultiProcessController
    except ImportError:
        return None
    return vtkMultiProcessController.GetGlobalController()


def read_part(path, mode):
    """The part's boundary grid, or (None, why)."""
    import exactmat
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    errors = exactmat.ErrorObserver()
    lower = path.lower()
    if not os.path.isfile(path):
        return None, f"cannot read '{path}': no such file"
    if lower.endswith(".json"):
        reader = exactmat.vtkNURBSReader()
    elif lower.endswith(".vtu"):
        reader = vtkXMLUnstructuredGridReader()
    elif exactmat.vtkCADBoundaryReader.CanReadFile(path):
        reader = exactmat.vtkCADBoundaryReader()
        reader.SetDimension({"3d": 3, "auto": 0}.get(mode, 2))
    else:
        return None, f"'{path}' is none of .vtu, .json, .step/.stp, .iges/.igs"
    reader.SetFileName(path)
    errors.watch(reader)
    # The executive's "returned failure" follow-up is not news: the reader's error says it.
    reader.GetExecutive().AddObserver("ErrorEvent", lambda *unused: None)
    reader.Update()
    grid = reader.GetOutputDataObject(0)
    if errors.messages or grid is None or grid.GetNumberOfCells() == 0:
        why = errors.messages[0].split("): ")[-1].strip() if errors.messages else "no boundary cells"
        return None, why
    return grid, ""


def has_surface_cells(grid):
    """Faces (a solid: 3d) rather than curves (a planar domain: 2d), as `exactmat` decides."""
    from vtkmodules.vtkCommonDataModel import (VTK_BEZIER_QUADRILATERAL, VTK_BEZIER_TRIANGLE,
                                               VTK_QUAD, VTK_TRIANGLE)
    types = grid.GetDistinctCellTypesArray()
    faces = (VTK_BEZIER_QUADRILATERAL, VTK_BEZIER_TRIANGLE, VTK_QUAD, VTK_TRIANGLE)
    return any(types.GetValue(i) in faces for i in range(types.GetNumberOfValues()))


def make_filter(mode, args):
    import exactmat
    if mode == "3d":
        f = exactmat.vtkMAT3DFilter()
        f.SetMaximumStep(args.max_step)
    elif mode in ("extrude", "revolve"):
        f = exactmat.vtkMAT25DFilter()
        if mode == "revolve":
            f.SetSweepTypeToRevolution()
            f.SetAngle(args.angle)
            f.SetAxisOrigin(*args.axis[:3])
            f.SetAxisDirection(*args.axis[3:])
        else:
            f.SetLength(args.length)
        f.SetSheetResolution(args.sheet_resolution)
    else:
        f = exactmat.vtkMAT2DFilter()
    f.SetTolerance(args.tolerance)
    f.SetVerificationTolerance(args.verify_tolerance)
    f.SetNumberOfThreads(args.threads)
    return f


def fill_sheets(mats, solids, args):
    """The solids' medial sheets (vtkSheetInterpolator on the whole collection) after their
    seams, as ``exactmat batch`` fills them: the collection of complete MATs, and per part
    (status, message) — status 3 when the sheets cannot be filled, 2 when their
    verification fails, else 0."""
    import exactmat
    sheets = exactmat.vtkSheetInterpolator()
    sheets.SetInputDataObject(mats)
    sheets.SetSourceData(solids)
    sheets.SetTolerance(args.tolerance)
    sheets.SetNumberOfThreads(args.threads)
    sheets.SetFitSheets(False)
    sheets.GlobalWarningDisplayOff()  # failed parts are in the summary
    sheets.Update()
    out = sheets.GetOutputDataObject(0)
    fd = out.GetFieldData()
    outcome = []
    for k in range(fd.GetArray("PartStatus").GetNumberOfValues()):
        status = fd.GetArray("PartStatus").GetValue(k)
        message = fd.GetAbstractArray("PartMessage").GetValue(k)
        if status == 2:
            shortfall = fd.GetArray("MaximumCoverageShortfall").GetValue(k)
            failed = fd.GetArray("NumberOfFailedSheets").GetValue(k)
            message = f"verification failed ({failed} sheet(s) not filled, faces covered to {shortfall:g}): {message}"
        outcome.append((status if status in (2, 3) else 0, "sheets: " + message if status in (2, 3) else ""))
    return out, outcome


def progress_printer(rank):
    """A progress observer factory: a line on stderr per 10 % of a group of parts."""
    def make(mode, parts):
        state = {"decile": -1}

        def observe(algorithm, event):
            decile = int(10 * algorithm.GetProgress())
            if decile > state["decile"]:
                state["decile"] = decile
                print(f"exactmat batch: rank {rank}: {mode}: {10 * decile}% of {parts} parts",
                      file=sys.stderr, flush=True)
        return observe
    return make


def run_share(files, names, indices, args, progress=None):
    """Computes parts `indices` (this rank's share); returns their summary rows.
    `progress(mode, parts)` makes a ProgressEvent observer for each group's filter."""
    from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet, vtkPartitionedDataSetCollection
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    import time
    rows, groups = {}, {}
    for i in indices:
        t0 = time.perf_counter()
        grid, why = read_part(files[i], args.mode)
        row = dict(part=names[i], file=files[i], mode=args.mode, status=STATUS[3],
                   segments_or_seams=0, branch_points_or_junctions=0, points=0,
                   seconds=time.perf_counter() - t0, verified_error=0.0, message=why)
        rows[i] = row
        if grid is None:
            continue
        if row["mode"] == "auto":
            row["mode"] = "3d" if has_surface_cells(grid) else "2d"
        groups.setdefault(row["mode"], []).append((i, grid))
    for mode, parts in groups.items():
        collection = vtkPartitionedDataSetCollection()
        for k, (i, grid) in enumerate(parts):
            collection.SetPartition(k, 0, grid)
            collection.GetMetaData(k).Set(vtkCompositeDataSet.NAME(), names[i])
        mat = make_filter(mode, args)
        mat.SetInputDataObject(collection)
        mat.GlobalWarningDisplayOff()  # failed parts are in the summary
        if progress:
            mat.AddObserver("ProgressEvent", progress(mode, len(parts)))
        mat.Update()
        out = mat.GetOutputDataObject(0)
        fd = out.GetFieldData()
        planar = mode == "2d"
        statuses = [fd.GetArray("PartStatus").GetValue(k) for k in range(len(parts))]
        sheets = None
        if mode == "3d" and not args.no_sheets:
            t0 = time.perf_counter()
            solids = vtkPartitionedDataSetCollection()
            for k, (i, grid) in enumerate(parts):
                solids.SetPartition(k, 0, grid)
            complete, sheets = fill_sheets(out, solids, args)
        for k, (i, _) in enumerate(parts):
            row = rows[i]
            status = statuses[k]
            row["status"] = STATUS[status]
            row["message"] = fd.GetAbstractArray("PartMessage").GetValue(k)
            row["seconds"] += fd.GetArray("PartSeconds").GetValue(k)
            row["verified_error"] = fd.GetArray("MaximumVerifiedError").GetValue(k)
            for column, figure in (("segments_or_seams", "NumberOfSegments" if planar else "NumberOfSeams"),
                                   ("branch_points_or_junctions",
                                    "NumberOfBranchPoints" if planar else "NumberOfJunctions")):
                array = fd.GetArray(figure)
                row[column] = int(array.GetValue(k)) if array is not None else 0
            polydata = out.GetPartitionAsDataObject(k, 0)
            row["points"] = polydata.GetNumberOfPoints() if polydata else 0
            if status == 3 or polydata is None:
                continue
            if sheets is not None:
                sheet_status, why = sheets[k]
                row["seconds"] += complete.GetFieldData().GetArray("PartSeconds").GetValue(k)
                if sheet_status == 3:
                    row["status"], row["message"] = STATUS[3], why
                    continue
                if sheet_status == 2 and status == 0:
                    row["status"], row["message"] = STATUS[2], why
                polydata = complete.GetPartitionAsDataObject(k, 0)
                row["points"] = polydata.GetNumberOfPoints()
            writer = vtkXMLPolyDataWriter()
            writer.SetInputData(polydata)
            writer.SetFileName(os.path.join(args.output, names[i] + ".vtp"))
            writer.SetDataModeToBinary()
            if writer.Write() != 1:
                row["status"], row["message"] = STATUS[3], f"cannot write {names[i]}.vtp"
    return rows


def write_summary(rows, output):
    """summary.csv and index.pvd, in part order; returns the exit status."""
    with open(os.path.join(output, "summary.csv"), "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(COLUMNS)
        for r in rows:
            w.writerow([r["part"], r["file"], r["mode"], r["status"], r["segments_or_seams"],
                        r["branch_points_or_junctions"], r["points"], "%.6g" % r["seconds"],
                        "%.3g" % r["verified_error"], r["message"].replace("\n", " ")])
    from xml.sax.saxutils import quoteattr
    with open(os.path.join(output, "index.pvd"), "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n  <Collection>\n')
        k = 0
        for r in rows:
            if r["status"] != STATUS[3]:
                f.write(f'    <DataSet part="{k}" name={quoteattr(r["part"])} '
                        f'file={quoteattr(r["part"] + ".vtp")}/>\n')
                k += 1
        f.write("  </Collection>\n</VTKFile>\n")
    failed = sum(r["status"] == STATUS[3] for r in rows)
    unverified = sum(r["status"] == STATUS[2] for r in rows)
    return 1 if failed else 3 if unverified else 0


def gather_rows(mpi, rows):
    """Every rank's summary rows on rank 0 (MPI GatherV of their JSON; the other ranks get
    their own rows back)."""
    from vtkmodules.vtkCommonCore import vtkIdTypeArray, vtkUnsignedCharArray
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    import numpy
    payload = numpy.frombuffer(json.dumps({str(i): r for i, r in rows.items()}).encode(), dtype=numpy.uint8)
    send = numpy_to_vtk(payload.copy(), deep=1, array_type=vtkUnsignedCharArray().GetDataType())
    received, lengths, offsets = vtkUnsignedCharArray(), vtkIdTypeArray(), vtkIdTypeArray()
    if not mpi.GatherV(send, received, lengths, offsets, 0):
        raise RuntimeError("exactmat batch: gathering the ranks' summaries failed")
    if mpi.GetLocalProcessId() != 0:
        return rows
    data = vtk_to_numpy(received).tobytes()
    gathered = {}
    for r in range(mpi.GetNumberOfProcesses()):
        start, length = offsets.GetValue(r), lengths.GetValue(r)
        gathered.update({int(i): row for i, row in json.loads(data[start:start + length]).items()})
    return gathered


def broadcast_status(mpi, status):
    """Rank 0's exit status on every rank, so that each leaves mpiexec with it."""
    from vtkmodules.vtkCommonCore import vtkIntArray
    value = vtkIntArray()
    value.InsertNextValue(status)
    mpi.Broadcast(value, 0)
    return value.GetValue(0)


def leave(code):
    """Exits with `code`. Under pvbatch the MPI world is finalised first and the process
    leaves at once (ParaView's own finalisation would finalise MPI a second time), so
    mpiexec returns the status; a plain Python process just exits."""
    mpi = controller()
    if mpi is None:
        sys.exit(code)
    sys.stdout.flush()
    sys.stderr.flush()
    if mpi.GetNumberOfProcesses() > 1:
        mpi.Barrier()
    mpi.Finalize()
    os._exit(code)


def main(argv=None):
    p = argparse.ArgumentParser(prog="exactmat batch (MPI)", description=__doc__.split("\n\n")[0])
    p.add_argument("inputs", nargs="+", help="part files or folders of them")
    p.add_argument("-o", "--output", default="exactmat-batch")
    p.add_argument("-j", "--threads", type=int, default=0, help="threads per rank (0: every core)")
    p.add_argument("--mode", default="auto", choices=["auto", "2d", "3d", "extrude", "revolve"])
    p.add_argument("--length", type=float, default=0.0)
    p.add_argument("--angle", type=float, default=360.0)
    p.add_argument("--axis", type=lambda s: [float(x) for x in s.split(",")], default=None)
    p.add_argument("--tolerance", type=float, default=1e-4)
    p.add_argument("--verify-tolerance", type=float, default=1e-9)
    p.add_argument("--sheet-resolution", type=float, default=0.02)
    p.add_argument("--max-step", type=float, default=0.05)
    p.add_argument("--no-sheets", action="store_true", help="solids: the seams only, no medial sheets")
    p.add_argument("--quiet", action="store_true", help="no progress lines (rank 0 prints them)")
    args = p.parse_args(argv)
    if args.mode == "extrude" and args.length <= 0:
        p.error("--mode extrude needs --length L")
    if args.mode == "revolve" and (not args.axis or len(args.axis) != 6):
        p.error("--mode revolve needs --axis PX,PY,PZ,DX,DY,DZ")

    mpi = controller()
    rank = mpi.GetLocalProcessId() if mpi else 0
    size = mpi.GetNumberOfProcesses() if mpi else 1
    files = part_files(args.inputs)
    names = part_names(files)
    os.makedirs(args.output, exist_ok=True)
    rows = run_share(files, names, range(rank, len(files), size), args,
                     progress_printer(rank) if rank == 0 and not args.quiet else None)
    gathered = gather_rows(mpi, rows) if size > 1 else rows
    status = 0
    if rank == 0:
        status = write_summary([gathered[i] for i in range(len(files))], args.output)
        print(f"ExactMAT batch: {len(files)} parts on {size} rank(s): "
              + ", ".join(f"{sum(r['status'] == s for r in gathered.values())} {s}"
                          for s in STATUS.values()))
        for i in range(len(files)):
            if gathered[i]["status"] in (STATUS[2], STATUS[3]):
                print(f"  {gathered[i]['part']} ({gathered[i]['file']}): {gathered[i]['status']}: "
                      f"{gathered[i]['message']}")
    if size > 1:
        status = broadcast_status(mpi, status)
    return status


if __name__ == "__main__":
    leave(main())

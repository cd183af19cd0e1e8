"""Parts per second with threads and MPI ranks, and the threaded verification's speed-up.

    PYTHONPATH=build/lib/python3.11/site-packages /usr/bin/python3 bench/bench_batch.py \
        build/bin/exactmat [--parts-per-shape 8] [--repeat 3]

1. A folder of parts (every 2D catalogue shape at several sizes, and the 3D catalogue solids
   the 3D filter computes) through `exactmat batch -j 1` and `-j 2`, and through
   exactmat/batch.py in `mpiexec -n 1|2 pvbatch --mpi --symmetric` (one thread per rank):
   wall time of the whole run (process start, reading, MAT, verification, writing), parts
   per second, and a check that every run's summary (but its timings) is the same.
2. The verification of single large parts on 1 and 2 threads (best of --repeat).
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import time

import exactmat
import exactmat.batch

PLANAR = ["rectangle", "rounded-rectangle", "circle", "ellipse", "annulus", "l-shape", "star",
          "blob", "spiral", "plate-with-holes", "narrow-passage"]
SOLIDS = ["box", "pillow", "notched-cube", "stepped-block"]
MPI_ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")


def make_parts(folder, per_shape):
    for names, sizes in ((PLANAR, per_shape), (SOLIDS, max(1, per_shape // 2))):
        for name in names:
            for k in range(sizes):
                source = exactmat.vtkNURBSSource()
                source.SetShapeName(name)
                source.SetWidth(4.0 + 0.25 * k)
                writer = exactmat.vtkNURBSWriter()
                writer.SetInputConnection(source.GetOutputPort())
                writer.SetFileName(os.path.join(folder, f"{name}-{k}.json"))
                writer.Write()
    return len(os.listdir(folder))


def timed(cmd, env=None):
    t0 = time.perf_counter()
    r = subprocess.run(cmd, capture_output=True, text=True, env=env)
    return time.perf_counter() - t0, r


def rows_without_time(folder):
    with open(os.path.join(folder, "summary.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        del r["seconds"]
    return rows


def verification_seconds(make, threads, repeat):
    best = float("inf")
    for _ in range(repeat):
        f = make()
        f.SetNumberOfThreads(threads)
        f.Update()
        best = min(best, f.GetVerificationSeconds())
    return best, f


def main():
    p = argparse.ArgumentParser()
    p.add_argument("exactmat")
    p.add_argument("--parts-per-shape", type=int, default=8)
    p.add_argument("--repeat", type=int, default=3)
    args = p.parse_args()
    tmp = tempfile.mkdtemp(prefix="exactmat-bench-batch-")
    try:
        parts_dir = os.path.join(tmp, "parts")
        os.makedirs(parts_dir)
        n = make_parts(parts_dir, args.parts_per_shape)
        print(f"## Parts per second ({n} parts: {len(PLANAR)} planar shapes x {args.parts_per_shape} "
              f"sizes, {len(SOLIDS)} solids x {max(1, args.parts_per_shape // 2)}; "
              f"wall time of the whole run, best of {args.repeat})\n")
        print("| run | wall time (s) | parts/s | speed-up |")
        print("|---|---:|---:|---:|")
        runs = [
            ("exactmat batch -j 1", lambda out: [args.exactmat, "batch", parts_dir, "-o", out, "-j", "1"], None),
            ("exactmat batch -j 2", lambda out: [args.exactmat, "batch", parts_dir, "-o", out, "-j", "2"], None),
            ("mpiexec -n 1 pvbatch batch.py -j 1", lambda out: ["mpiexec", "-n", "1", "pvbatch", "--mpi", "--symmetric",
                                                              exactmat.batch.__file__, parts_dir, "-o", out, "-j", "1"], MPI_ENV),
            ("mpiexec -n 2 pvbatch batch.py -j 1", lambda out: ["mpiexec", "-n", "2", "pvbatch", "--mpi", "--symmetric",
                                                              exactmat.batch.__file__, parts_dir, "-o", out, "-j", "1"], MPI_ENV),
        ]
        reference, base = None, None
        for k, (label, command, env) in enumerate(runs):
            best = float("inf")
            for _ in range(args.repeat):
                out = os.path.join(tmp, f"out{k}")
                shutil.rmtree(out, ignore_errors=True)
                seconds, r = timed(command(out), env)
                if r.returncode not in (0, 1, 3):
                    sys.exit(f"{label} failed ({r.returncode}):\n{r.stdout}\n{r.stderr}")
                best = min(best, seconds)
            rows = rows_without_time(out)
            if reference is None:
                reference = rows
            elif rows != reference:
                sys.exit(f"{label}: the summary differs from the first run's")
            base = base or best
            print(f"| {label} | {best:.2f} | {n / best:.1f} | {base / best:.2f} |")
        failed = sum(r["status"] != "verified" for r in reference)
        print(f"\nEvery run's summary identical (timings aside); {n - failed} of {n} parts verified.\n")

        print(f"## Threaded verification (best of {args.repeat})\n")
        print("| part | points checked | 1 thread (ms) | 2 threads (ms) | speed-up | same figures |")
        print("|---|---:|---:|---:|---:|---|")

        def planar(name, **settings):
            def make():
                s = exactmat.vtkNURBSSource()
                s.SetShapeName(name)
                for key, value in settings.items():
                    getattr(s, "Set" + key)(value)
                f = exactmat.vtkMAT2DFilter()
                f.SetInputConnection(s.GetOutputPort())
                f.SetTolerance(1e-6)
                return f
            return make

        def solid(name):
            def make():
                s = exactmat.vtkNURBSSource()
                s.SetShapeName(name)
                f = exactmat.vtkMAT3DFilter()
                f.SetInputConnection(s.GetOutputPort())
                return f
            return make

        cases = [("plate-with-holes (2D, tolerance 1e-6)", planar("plate-with-holes")),
                 ("spiral (2D, tolerance 1e-6)", planar("spiral")),
                 ("star, 400 spikes (2D, tolerance 1e-6)", planar("star", Count=400)),
                 ("pillow (3D)", solid("pillow")),
                 ("stepped-block (3D)", solid("stepped-block"))]
        for label, make in cases:
            one, f1 = verification_seconds(make, 1, args.repeat)
            two, f2 = verification_seconds(make, 2, args.repeat)
            same = f1.GetMaximumVerifiedError() == f2.GetMaximumVerifiedError()
            points = f1.GetOutput().GetNumberOfPoints()
            print(f"| {label} | {points} | {1e3 * one:.1f} | {1e3 * two:.1f} | {one / two:.2f} | "
                  f"{'yes' if same else 'NO'} |")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()

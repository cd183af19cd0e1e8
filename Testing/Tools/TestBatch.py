"""Many parts at once: `exactmat batch -j 2` on this machine, and the same folder through
`mpiexec -n 2 pvbatch --mpi --symmetric exactmat/batch.py`. Every part's MAT must be the
one its own run gives, bit for bit; bad parts are reported by name and the others complete.
"""
import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

import exactmat
import exactmat.batch

EXACTMAT = sys.argv.pop(1)
PVBATCH = sys.argv.pop(1)
MPIEXEC = sys.argv.pop(1)

PLANAR = ["rectangle", "rounded-rectangle", "circle", "ellipse", "annulus", "l-shape", "star",
          "blob", "spiral", "plate-with-holes", "narrow-passage"]


def run(*args, cwd=None, env=None):
    return subprocess.run([*args], capture_output=True, text=True, cwd=cwd, timeout=600, env=env)


def write_shape(path, name, width):
    source = exactmat.vtkNURBSSource()
    source.SetShapeName(name)
    source.SetWidth(width)
    writer = exactmat.vtkNURBSWriter()
    writer.SetInputConnection(source.GetOutputPort())
    writer.SetFileName(path)
    assert writer.Write() == 1, path


def write_open_curve(path):
    """Valid JSON, not a domain: one straight curve, an open loop."""
    with open(path, "w") as f:
        json.dump({"format": "exactmat-nurbs", "version": 1, "curves": [
            {"id": 0, "degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 0]]}]}, f)


def read_vtp(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def summary(folder):
    with open(os.path.join(folder, "summary.csv"), newline="") as f:
        return list(csv.DictReader(f))


class Batch(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="exactmat-batch-")
        cls.planar = os.path.join(cls.tmp, "planar")
        os.makedirs(cls.planar)
        for name in PLANAR:
            for width in (4.0, 5.5):
                write_shape(os.path.join(cls.planar, f"{name}-{width}.json"), name, width)
        with open(os.path.join(cls.planar, "garbage.json"), "w") as f:
            f.write("{ not json")
        write_open_curve(os.path.join(cls.planar, "open-sketch.json"))
        cls.parts = len(PLANAR) * 2 + 2

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def expect_same_mat(self, a, b, what):
        ma, mb = read_vtp(a), read_vtp(b)
        self.assertEqual(ma.GetNumberOfPoints(), mb.GetNumberOfPoints(), what)
        self.assertGreater(ma.GetNumberOfPoints(), 0, what)
        self.assertEqual(ma.GetNumberOfCells(), mb.GetNumberOfCells(), what)
        self.assertTrue(numpy.array_equal(vtk_to_numpy(ma.GetPoints().GetData()),
                                          vtk_to_numpy(mb.GetPoints().GetData())), what)
        for k in range(ma.GetPointData().GetNumberOfArrays()):
            name = ma.GetPointData().GetArrayName(k)
            self.assertTrue(numpy.array_equal(vtk_to_numpy(ma.GetPointData().GetArray(name)),
                                              vtk_to_numpy(mb.GetPointData().GetArray(name))),
                            f"{what}: {name}")

    def expect_planar_summary(self, rows, folder):
        self.assertEqual(len(rows), self.parts)
        by_part = {r["part"]: r for r in rows}
        bad = by_part["garbage"]
        self.assertEqual(bad["status"], "failed")
        self.assertIn("garbage.json", bad["message"])
        self.assertIn("JSON", bad["message"])
        open_sketch = by_part["open-sketch"]
        self.assertEqual(open_sketch["status"], "failed")
        self.assertIn("open loop", open_sketch["message"])
        for r in rows:
            if r["part"] in ("garbage", "open-sketch"):
                self.assertFalse(os.path.exists(os.path.join(folder, r["part"] + ".vtp")))
                continue
            self.assertEqual(r["status"], "verified", r)
            self.assertEqual(r["mode"], "2d", r)
            self.assertLessEqual(float(r["verified_error"]), 1e-9, r)
        self.assertEqual(by_part["plate-with-holes-4.0"]["segments_or_seams"], "20")
        self.assertEqual(by_part["plate-with-holes-4.0"]["branch_points_or_junctions"], "11")
        with open(os.path.join(folder, "index.pvd")) as f:
            index = f.read()
        self.assertEqual(index.count("<DataSet "), self.parts - 2)

    def test_batch_on_two_threads_gives_every_parts_own_mat(self):
        out = os.path.join(self.tmp, "threads")
        r = run(EXACTMAT, "batch", self.planar, "-o", out, "-j", "2")
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)  # two parts failed
        self.assertIn("garbage", r.stdout)
        self.assertIn("open-sketch", r.stdout)
        rows = summary(out)
        self.expect_planar_summary(rows, out)
        # Each good part alone, on one thread: the same MAT, bit for bit.
        for row in rows:
            if row["status"] != "verified":
                continue
            single = os.path.join(self.tmp, "single-" + row["part"] + ".vtp")
            one = run(EXACTMAT, "2d", row["file"], "-o", single, "-j", "1")
            self.assertEqual(one.returncode, 0, one.stderr)
            self.expect_same_mat(single, os.path.join(out, row["part"] + ".vtp"), row["part"])
        # ParaView's .pvd reader takes the index: every good part as one collection.
        from paraview.modules.vtkPVVTKExtensionsIOCore import vtkPVDReader
        reader = vtkPVDReader()
        reader.SetFileName(os.path.join(out, "index.pvd"))
        reader.Update()
        self.assertEqual(reader.GetOutputDataObject(0).GetNumberOfBlocks(), self.parts - 2)

    def test_mpi_ranks_in_pvbatch_give_the_same_results(self):
        reference = os.path.join(self.tmp, "reference")
        r = run(EXACTMAT, "batch", self.planar, "-o", reference, "-j", "1")
        self.assertEqual(r.returncode, 1, r.stderr)
        out = os.path.join(self.tmp, "mpi")
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMPI_MCA_rmaps_base_oversubscribe="1")
        r = run(MPIEXEC, "-n", "2", PVBATCH, "--mpi", "--symmetric", exactmat.batch.__file__,
                self.planar, "-o", out, "-j", "1", env=env)
        # Two parts fail: every rank, and so mpiexec, exits with exactmat batch's status 1.
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("on 2 rank(s)", r.stdout)
        rows = summary(out)
        self.expect_planar_summary(rows, out)
        ref = summary(reference)
        for a, b in zip(rows, ref):
            del a["seconds"], b["seconds"]
            self.assertEqual(a, b)
            if a["status"] == "verified":
                self.expect_same_mat(os.path.join(out, a["part"] + ".vtp"),
                                     os.path.join(reference, a["part"] + ".vtp"), a["part"])
        self.assertEqual([f for f in os.listdir(out) if f.startswith(".summary")], [])

    def test_mpi_batch_of_good_parts_exits_0_with_an_idle_rank(self):
        # One part on two ranks: rank 1 has no share, sends an empty summary and still
        # leaves with rank 0's status.
        folder = os.path.join(self.tmp, "one-part")
        os.makedirs(folder)
        shutil.copy(os.path.join(self.planar, "l-shape-4.0.json"), folder)
        out = os.path.join(self.tmp, "mpi-one")
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMPI_MCA_rmaps_base_oversubscribe="1")
        r = run(MPIEXEC, "-n", "2", PVBATCH, "--mpi", "--symmetric", exactmat.batch.__file__,
                folder, "-o", out, "-j", "1", "--quiet", env=env)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("1 parts on 2 rank(s): 1 verified", r.stdout)
        rows = summary(out)
        self.assertEqual([(row["part"], row["status"]) for row in rows], [("l-shape-4.0", "verified")])

    def test_extruded_parts(self):
        folder = os.path.join(self.tmp, "profiles")
        os.makedirs(folder)
        for name in ("rectangle", "l-shape", "star", "plate-with-holes"):
            write_shape(os.path.join(folder, name + ".json"), name, 4.0)
        write_open_curve(os.path.join(folder, "open.json"))
        out = os.path.join(self.tmp, "extruded")
        r = run(EXACTMAT, "batch", folder, "--mode", "extrude", "--length", "2", "-o", out, "-j", "2")
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        rows = {row["part"]: row for row in summary(out)}
        self.assertEqual(rows["open"]["status"], "failed")
        for name in ("rectangle", "l-shape", "star", "plate-with-holes"):
            self.assertEqual(rows[name]["status"], "verified", rows[name])
            self.assertEqual(rows[name]["mode"], "extrude")
            single = os.path.join(self.tmp, "extruded-" + name + ".vtp")
            one = run(EXACTMAT, "extrude", os.path.join(folder, name + ".json"), "--length", "2",
                      "-o", single, "-j", "1")
            self.assertEqual(one.returncode, 0, one.stderr)
            self.expect_same_mat(single, os.path.join(out, name + ".vtp"), name)
        self.assertEqual(rows["rectangle"]["branch_points_or_junctions"], "2")

    def test_cad_parts_and_solids(self):
        """STEP and IGES files among the parts, in auto mode: solids go to 3d."""
        folder = os.path.join(self.tmp, "cad")
        os.makedirs(folder)
        data = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Data", "cad")
        shutil.copy(os.path.join(data, "l-prism.igs"), folder)
        shutil.copy(os.path.join(data, "bracket.step"), folder)
        write_shape(os.path.join(folder, "box.json"), "box", 4.0)
        out = os.path.join(self.tmp, "cad-out")
        r = run(EXACTMAT, "batch", folder, "-o", out, "-j", "2")
        rows = {row["part"]: row for row in summary(out)}
        self.assertEqual(set(rows), {"l-prism", "bracket", "box"})
        for name in ("l-prism", "box", "bracket"):
            self.assertEqual(rows[name]["mode"], "3d", rows[name])
            self.assertEqual(rows[name]["status"], "verified", rows[name])
        self.assertEqual(rows["l-prism"]["branch_points_or_junctions"], "5")
        self.assertEqual(rows["box"]["branch_points_or_junctions"], "4")
        self.assertEqual(rows["bracket"]["branch_points_or_junctions"], "1")
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        # Solids get their sheets, as `exactmat 3d` gives them: the same output, bit for bit.
        one = run(EXACTMAT, "3d", os.path.join(folder, "l-prism.igs"), "-o",
                  os.path.join(self.tmp, "l-prism.vtp"), "-j", "1")
        self.assertEqual(one.returncode, 0, one.stderr)
        self.expect_same_mat(os.path.join(self.tmp, "l-prism.vtp"), os.path.join(out, "l-prism.vtp"),
                             "l-prism")
        self.assertGreater(read_vtp(os.path.join(out, "l-prism.vtp")).GetNumberOfPolys(), 100)
        # The Python (MPI) batch fills them the same way.
        py_out = os.path.join(self.tmp, "cad-py")
        env = dict(os.environ)
        r = run(sys.executable, "-m", "exactmat.batch", folder, "-o", py_out, "-j", "1", "--quiet", env=env)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.expect_same_mat(os.path.join(out, "l-prism.vtp"), os.path.join(py_out, "l-prism.vtp"), "l-prism (batch.py)")

    def test_usage_errors(self):
        r = run(EXACTMAT, "batch")
        self.assertEqual(r.returncode, 2)
        r = run(EXACTMAT, "batch", self.planar, "--mode", "revolve")
        self.assertEqual(r.returncode, 2)
        self.assertIn("--axis", r.stderr)
        empty = os.path.join(self.tmp, "empty")
        os.makedirs(empty)
        r = run(EXACTMAT, "batch", empty, "-o", os.path.join(self.tmp, "none"))
        self.assertEqual(r.returncode, 1)
        self.assertIn("holds no", r.stderr)


if __name__ == "__main__":
    unittest.main()

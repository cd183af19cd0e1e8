"""The `exactmat` program as a user runs it: the main job on the bundled shape and on
files, its summary, the .vtp it writes (checked numerically), the PNG, and bad input."""
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import unittest

from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

EXACTMAT = sys.argv.pop(1)
DATA = sys.argv.pop(1)


def run(*args, cwd=None):
    return subprocess.run([EXACTMAT, *args], capture_output=True, text=True, cwd=cwd, timeout=300)


def summary_value(text, key):
    m = re.search(r"^\s+" + re.escape(key) + r"\s+([-+0-9.eE]+)", text, re.M)
    assert m, f"no '{key}' in:\n{text}"
    return float(m.group(1))


class ExactmatCLI(unittest.TestCase):
    def test_default_shape_summary_and_output(self):
        with tempfile.TemporaryDirectory() as tmp:
            r = run("2d", "-o", "mat.vtp", cwd=tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("plate-with-holes", r.stdout)
            self.assertEqual(summary_value(r.stdout, "segments"), 20)
            self.assertEqual(summary_value(r.stdout, "branch points"), 11)
            self.assertEqual(summary_value(r.stdout, "cycles"), 3)
            self.assertLessEqual(summary_value(r.stdout, "largest verified error"), 1e-9)
            reader = vtkXMLPolyDataReader()
            reader.SetFileName(os.path.join(tmp, "mat.vtp"))
            reader.Update()
            mat = reader.GetOutput()
            self.assertEqual(mat.GetNumberOfPoints(), summary_value(r.stdout, "points"))
            radius = mat.GetPointData().GetArray("Radius")
            self.assertIsNotNone(radius)
            lo, hi = radius.GetRange()
            self.assertGreaterEqual(lo, 0.0)
            self.assertLess(hi, 1.0)  # the plate is 4 x 2
            self.assertEqual(mat.GetNumberOfLines(), 20)

    def test_json_input_fixed_step_and_png(self):
        with tempfile.TemporaryDirectory() as tmp:
            png = os.path.join(tmp, "mat.png")
            r = run("2d", os.path.join(DATA, "two-loops.json"), "-o", os.path.join(tmp, "m.vtp"),
                    "--step", "2e-3", "--png", png)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("fixed step", r.stdout)
            self.assertEqual(summary_value(r.stdout, "cycles"), 1)  # one hole
            self.assertLessEqual(summary_value(r.stdout, "largest verified error"), 1e-9)
            image = vtkPNGReader()
            image.SetFileName(png)
            image.Update()
            dims = image.GetOutput().GetDimensions()
            self.assertEqual(dims[:2], (1200, 800))
            scalars = image.GetOutput().GetPointData().GetScalars()
            coloured = sum(1 for i in range(0, scalars.GetNumberOfTuples(), 11)
                           if len({scalars.GetComponent(i, c) for c in range(3)}) > 1)
            self.assertGreater(coloured, 200, "the MAT (coloured by radius) is not in the picture")

    def test_bad_input_is_a_clear_error(self):
        with tempfile.TemporaryDirectory() as tmp:
            bad = os.path.join(tmp, "open.json")
            with open(bad, "w") as f:
                f.write('{"curves": [{"degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 0]]},'
                        ' {"degree": 1, "knots": [0, 0, 1, 1], "points": [[1, 0], [1, 1]]}]}')
            r = run("2d", bad, "-o", os.path.join(tmp, "m.vtp"))
            self.assertEqual(r.returncode, 1)
            self.assertRegex(r.stderr, r"exactmat: error: open loop: edge 0 starts at \(0, 0, 0\)")
            self.assertNotIn("vtkExecutive", r.stderr)
            r = run("2d", os.path.join(tmp, "missing.json"))
            self.assertEqual(r.returncode, 1)
            self.assertIn("cannot open", r.stderr)
            r = run("2d", "--tolerance", "abc")
            self.assertEqual(r.returncode, 2)
            self.assertIn("usage:", r.stderr)

    def test_extrude_default_shape(self):
        with tempfile.TemporaryDirectory() as tmp:
            r = run("extrude", "--length", "3", cwd=tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("extruded by 3", r.stdout)
            # 11 profile branch points, each a junction near both profile faces.
            self.assertEqual(summary_value(r.stdout, "junctions"), 22)
            self.assertIn("touchpoint mismatches 0", r.stdout)
            m = re.search(r"size ([-+0-9.eE]+), touchpoint", r.stdout)
            self.assertLessEqual(float(m.group(1)), 1e-9)
            reader = vtkXMLPolyDataReader()
            reader.SetFileName(os.path.join(tmp, "exactmat-extrude.vtp"))
            reader.Update()
            mat = reader.GetOutput()
            self.assertEqual(mat.GetNumberOfVerts(), 22)
            self.assertGreater(mat.GetNumberOfPolys(), 1000)
            for name in ("Radius", "PointType", "Touchpoints"):
                self.assertIsNotNone(mat.GetPointData().GetArray(name), name)
            for name in ("ElementType", "ElementId", "SegmentId", "Governors"):
                self.assertIsNotNone(mat.GetCellData().GetAbstractArray(name), name)
            lo, hi = mat.GetPointData().GetArray("Radius").GetRange()
            self.assertAlmostEqual(lo, 0.0)
            self.assertLess(hi, 1.0)

    def test_revolve_with_axis_and_png(self):
        with tempfile.TemporaryDirectory() as tmp:
            png = os.path.join(tmp, "rev.png")
            r = run("revolve", "--shape", "rectangle", "--angle", "90", "--axis", "-3,0,0,0,1,0",
                    "-o", os.path.join(tmp, "rev.vtp"), "--png", png)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(summary_value(r.stdout, "junctions"), 4)
            self.assertIn("touchpoint mismatches 0", r.stdout)
            image = vtkPNGReader()
            image.SetFileName(png)
            image.Update()
            self.assertEqual(image.GetOutput().GetDimensions()[:2], (1200, 900))
            # A torus: no junctions, one core circle.
            r = run("revolve", "--shape", "circle", "--axis", "-3,0,0", "-o", os.path.join(tmp, "t.vtp"))
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(summary_value(r.stdout, "junctions"), 0)

    def test_3d_default_solid_box_and_png(self):
        with tempfile.TemporaryDirectory() as tmp:
            r = run("3d", "--png", "pillow.png", cwd=tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("pillow", r.stdout)
            self.assertEqual(summary_value(r.stdout, "junctions"), 1)
            self.assertEqual(summary_value(r.stdout, "seams"), 8)
            self.assertIn("verification        passed", r.stdout)
            png = vtkPNGReader()
            png.SetFileName(os.path.join(tmp, "pillow.png"))
            png.Update()
            self.assertGreater(png.GetOutput().GetDimensions()[0], 100)
            r = run("3d", "--shape", "box", "-o", "box.vtp", cwd=tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            reader = vtkXMLPolyDataReader()
            reader.SetFileName(os.path.join(tmp, "box.vtp"))
            reader.Update()
            out = reader.GetOutput()
            self.assertEqual(out.GetNumberOfVerts(), 4)
            self.assertEqual(out.GetNumberOfLines(), 12)
            radius = out.GetPointData().GetArray("Radius")
            kinds = out.GetPointData().GetArray("PointType")
            # The catalogue box is 4 x 2 x 3: junctions at (+-1, 0, +-0.5)... with radius 1.
            junction_radii = [radius.GetValue(i) for i in range(out.GetNumberOfPoints()) if kinds.GetValue(i) == 2]
            self.assertEqual(len(junction_radii), 4)
            for value in junction_radii:
                self.assertAlmostEqual(value, 1.0, places=12)
            # Reflex edges and a reflex corner: the notched cube (edge 4, centred, the
            # (+, +, +) eighth cut away). The seam up the diagonal from (-2, -2, -2) meets
            # the reflex corner at the origin where sqrt(3) (2 - r) = r: radius
            # k = 2 sqrt(3) / (1 + sqrt(3)), centre (-2 + k) (1, 1, 1).
            r = run("3d", "--shape", "notched-cube", "--no-sheets", "-o", "notch.vtp", cwd=tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("3 reflex", r.stdout)
            self.assertEqual(summary_value(r.stdout, "junctions"), 7)
            self.assertIn("verification        passed", r.stdout)
            reader.SetFileName(os.path.join(tmp, "notch.vtp"))
            reader.Update()
            out = reader.GetOutput()
            radius = out.GetPointData().GetArray("Radius")
            kinds = out.GetPointData().GetArray("PointType")
            k = 2.0 * math.sqrt(3.0) / (1.0 + math.sqrt(3.0))
            diagonal = [i for i in range(out.GetNumberOfPoints()) if kinds.GetValue(i) == 2
                        and abs(radius.GetValue(i) - k) < 1e-9]
            self.assertEqual(len(diagonal), 1)
            x = out.GetPoint(diagonal[0])
            for c in x:
                self.assertAlmostEqual(c, -2.0 + k, places=9)
            # The thesis' fixed steps: the same junctions, many more points.
            r2 = run("3d", "--shape", "notched-cube", "--no-sheets", "--step", "2e-3", "-o", "notch-fixed.vtp", cwd=tmp)
            self.assertEqual(r2.returncode, 0, r2.stderr)
            self.assertEqual(summary_value(r2.stdout, "junctions"), 7)
            self.assertGreater(summary_value(r2.stdout, "points"), 2 * summary_value(r.stdout, "points"))
            # A solid the 3D tracer cannot do yet (the extruded blob: its seams are reached
            # only from rims that meet them) is refused with exit 1 and the reason.
            r = run("3d", "--shape", "extrusion", "-o", "c.vtp", cwd=tmp)
            self.assertEqual(r.returncode, 1)
            self.assertIn("no seam touches", r.stderr)
            # The cylinder: its axis (a centre curve) and two cone sheets, verified.
            r = run("3d", "--shape", "cylinder", "-o", "cyl.vtp", cwd=tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(summary_value(r.stdout, "centre curves"), 1)
            self.assertEqual(summary_value(r.stdout, "seams"), 0)
            self.assertIn("verification        passed", r.stdout)
            r = run("3d", "--shape", "rectangle", "-o", "r.vtp", cwd=tmp)
            self.assertEqual(r.returncode, 1)
            self.assertIn("no surface cells", r.stderr)

    def test_3d_sheets(self):
        # The catalogue box 4 x 2 x 3 with its sheets: 13 planar sheets sharing the seams'
        # points, every point verified, the faces covered; the middle sheet (between the
        # faces 2 apart) is the rectangle |x| <= 1, |z| <= 0.5 at radius 1.
        with tempfile.TemporaryDirectory() as tmp:
            r = run("3d", "--shape", "box", "--sheets", "-o", "box.vtp", "--png", "box.png", cwd=tmp)
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
            self.assertIn("13 filled (0 failed)", r.stdout)
            self.assertIn("verification        passed", r.stdout)
            reader = vtkXMLPolyDataReader()
            reader.SetFileName(os.path.join(tmp, "box.vtp"))
            reader.Update()
            out = reader.GetOutput()
            self.assertEqual(out.GetNumberOfLines(), 12)
            self.assertGreater(out.GetNumberOfPolys(), 13)
            kinds = out.GetCellData().GetArray("ElementType")
            sheet_ids = out.GetCellData().GetArray("SheetId")
            radius = out.GetPointData().GetArray("Radius")
            middle = 0
            for c in range(out.GetNumberOfCells()):
                if kinds.GetValue(c) != 7:
                    self.assertEqual(sheet_ids.GetValue(c), -1)
                    continue
                ids = out.GetCell(c).GetPointIds()
                if all(abs(radius.GetValue(ids.GetId(k)) - 1.0) < 1e-12 for k in range(3)):
                    middle += 1
                    for k in range(3):
                        x = out.GetPoint(ids.GetId(k))
                        self.assertLessEqual(abs(x[0]), 1.0 + 1e-12)
                        self.assertLessEqual(abs(x[2]), 0.5 + 1e-12)
                        self.assertAlmostEqual(x[1], 0.0, places=12)
            self.assertGreater(middle, 0)
            self.assertTrue(os.path.exists(os.path.join(tmp, "box.png")))
            # Reflex edges, a reflex corner and rims: complete and verified too; with
            # --sheet-fit, every sheet's B-spline fit within the tolerance, as Bezier cells.
            from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
            for shape in ("notched-cube", "stepped-block"):
                r = run("3d", "--shape", shape, "--sheets", "--sheet-fit", shape + "-fit.vtu",
                        "-o", shape + ".vtp", cwd=tmp)
                self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
                self.assertIn("(0 failed)", r.stdout)
                self.assertIn("(0 sheet(s) above the tolerance)", r.stdout)
                m = re.search(r"sheet fits\s+(\d+) Bezier patches.*largest error / size ([-+0-9.eE]+)", r.stdout)
                self.assertTrue(m, r.stdout)
                self.assertLessEqual(float(m.group(2)), 1e-4)
                fit = vtkXMLUnstructuredGridReader()
                fit.SetFileName(os.path.join(tmp, shape + "-fit.vtu"))
                fit.Update()
                self.assertEqual(fit.GetOutput().GetNumberOfCells(), int(m.group(1)))
                self.assertIsNotNone(fit.GetOutput().GetPointData().GetArray("Radius"))
                self.assertIsNotNone(fit.GetOutput().GetCellData().GetArray("SheetFitError"))
            r = run("3d", "--shape", "box", "--no-sheets", "--sheet-fit", "fit.vtu", cwd=tmp)
            self.assertEqual(r.returncode, 2)
            self.assertIn("--sheet-fit needs the sheets", r.stderr)
            # The sheets are the default; --no-sheets leaves the seam graph alone.
            r = run("3d", "--shape", "box", "-o", "default.vtp", cwd=tmp)
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
            self.assertIn("13 filled (0 failed)", r.stdout)
            r = run("3d", "--shape", "box", "--no-sheets", "-o", "seams.vtp", cwd=tmp)
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
            self.assertIn("not filled: --no-sheets", r.stdout)
            reader.SetFileName(os.path.join(tmp, "seams.vtp"))
            reader.Update()
            self.assertEqual(reader.GetOutput().GetNumberOfPolys(), 0)

    def test_input_alone_picks_2d_or_3d(self):
        # `exactmat INPUT`: faces make it the 3D MAT, curves the 2D MAT. The solid: the box
        # 4 x 3 x 2 as six planar VTK_QUAD faces (plain VTK, no ExactMAT module needed).
        from vtkmodules.vtkCommonCore import vtkPoints
        from vtkmodules.vtkCommonDataModel import VTK_QUAD, vtkUnstructuredGrid
        from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
        with tempfile.TemporaryDirectory() as tmp:
            points = vtkPoints()
            for i in range(8):
                points.InsertNextPoint(2.0 if i & 1 else -2.0, 1.5 if i & 2 else -1.5, 1.0 if i & 4 else -1.0)
            grid = vtkUnstructuredGrid()
            grid.SetPoints(points)
            for quad in ((0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)):
                grid.InsertNextCell(VTK_QUAD, 4, quad)
            writer = vtkXMLUnstructuredGridWriter()
            writer.SetInputData(grid)
            writer.SetFileName(os.path.join(tmp, "box.vtu"))
            self.assertEqual(writer.Write(), 1)
            r = run("box.vtu", cwd=tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("3D medial axis", r.stdout)
            self.assertEqual(summary_value(r.stdout, "junctions"), 4)
            self.assertEqual(summary_value(r.stdout, "seams"), 12)
            self.assertTrue(os.path.exists(os.path.join(tmp, "exactmat-3d.vtp")))
            r = run(os.path.join(DATA, "two-loops.json"), cwd=tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("2D medial axis", r.stdout)
            self.assertTrue(os.path.exists(os.path.join(tmp, "exactmat-2d.vtp")))
            r = run("nothing.vtu", cwd=tmp)
            self.assertEqual(r.returncode, 1)

    def test_step_and_iges_parts(self):
        # CAD parts written by OpenCASCADE, read exactly: a solid (IGES) through the 3D MAT,
        # a planar face of a solid (STEP, --face) through the 2D MAT, and files that are not.
        with tempfile.TemporaryDirectory() as tmp:
            r = run(os.path.join(DATA, "cad", "l-prism.igs"), cwd=tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("3D medial axis", r.stdout)
            self.assertIn("unit MM", r.stdout)
            self.assertEqual(summary_value(r.stdout, "junctions"), 5)
            self.assertIn("verification        passed", r.stdout)
            # A sphere (radius 1.5 about (0.5, 0, 0)): its MAT is its centre alone.
            r = run(os.path.join(DATA, "cad", "sphere.step"), "-o", "s.vtp", cwd=tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(summary_value(r.stdout, "sphere centre"), 1)
            self.assertEqual(summary_value(r.stdout, "seams"), 0)
            self.assertEqual(summary_value(r.stdout, "points"), 1)
            self.assertIn("verification        passed", r.stdout)
            reader = vtkXMLPolyDataReader()
            reader.SetFileName(os.path.join(tmp, "s.vtp"))
            reader.Update()
            mat = reader.GetOutput()
            self.assertEqual(mat.GetNumberOfVerts(), 1)
            centre = mat.GetPoint(0)
            for got, want in zip(centre, (0.5, 0.0, 0.0)):
                self.assertAlmostEqual(got, want, delta=1e-12)
            self.assertAlmostEqual(mat.GetPointData().GetArray("Radius").GetTuple1(0), 1.5, delta=1e-12)
            self.assertEqual(mat.GetPointData().GetArray("PointType").GetTuple1(0), 7)
            bracket = os.path.join(DATA, "cad", "bracket.step")
            r = run("2d", bracket, "--face", "1", "-o", "b.vtp", cwd=tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(summary_value(r.stdout, "branch points"), 6)
            r = run("2d", bracket, "--face", "2", "-o", "b.vtp", cwd=tmp)
            self.assertEqual(r.returncode, 1)
            self.assertIn("face 2 is a cylinder, not planar", r.stderr)
            r = run("2d", bracket, "--face", "40", "-o", "b.vtp", cwd=tmp)
            self.assertEqual(r.returncode, 1)
            self.assertIn("face 40 asked for, but the file has 12 face(s)", r.stderr)
            r = run("2d", bracket, "--face", "x")
            self.assertEqual(r.returncode, 2)
            # The solid (a plate with rounded corners and two round holes, one as far from the
            # wall as the plate is thick): seams along the wall and round each hole, found by
            # restarts (no convex vertex leads to them); the first hole's seam kisses the
            # wall's at one junction. Its sheets, cones between the flat faces and the round
            # ones (each a file face tiled into several patches), fill it: every face covered.
            r = run("3d", bracket, "-o", "b.vtp", "--no-sheets", cwd=tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(summary_value(r.stdout, "junctions"), 1)
            self.assertEqual(summary_value(r.stdout, "seams"), 3)
            r = run("3d", bracket, "-o", "b.vtp", cwd=tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("(0 failed)", r.stdout)
            self.assertIn("verification        passed", r.stdout)
            self.assertNotIn("not covered", r.stderr)
            with open(os.path.join(tmp, "probe.stp"), "w") as f:
                f.write("probe begin { printf(\"a SystemTap script, not STEP\") }\n")
            r = run(os.path.join(tmp, "probe.stp"), cwd=tmp)
            self.assertEqual(r.returncode, 1)
            self.assertIn("not a readable STEP file", r.stderr)

    def test_sweep_errors(self):
        r = run("extrude")
        self.assertEqual(r.returncode, 2)
        self.assertIn("needs --length", r.stderr)
        r = run("extrude", "--shape", "rectangle", "--length", "1.5", "-o", "/dev/null")
        self.assertEqual(r.returncode, 0, r.stderr)  # shorter than 2 Rmax: a mid-sheet
        self.assertEqual(summary_value(r.stdout, "junctions"), 4)
        r = run("revolve", "--shape", "rectangle", "--axis", "0,0,0", "-o", "/dev/null")
        self.assertEqual(r.returncode, 1)
        self.assertIn("crosses the profile", r.stderr)
        r = run("revolve", "--axis", "1,2")
        self.assertEqual(r.returncode, 2)

    def test_help_is_not_an_unknown_command(self):
        for flag in ("--help", "-h", "help"):
            r = run(flag)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("exit codes", r.stdout)

    def test_failed_verification_exits_3_and_names_the_worst_point(self):
        with tempfile.TemporaryDirectory() as tmp:
            r = run("2d", "--shape", "ellipse", "--verify-tolerance", "1e-300", "-o",
                    os.path.join(tmp, "m.vtp"))
            self.assertEqual(r.returncode, 3, r.stdout + r.stderr)
            self.assertIn("verification failed", r.stderr)
            self.assertIn("largest error at (", r.stderr)
            self.assertIn("FAILED", r.stdout)
            self.assertTrue(os.path.exists(os.path.join(tmp, "m.vtp")))  # still written
            r = run("extrude", "--shape", "rectangle", "--length", "3", "--verify-tolerance",
                    "1e-300", "-o", os.path.join(tmp, "e.vtp"))
            self.assertEqual(r.returncode, 3, r.stdout + r.stderr)

    def test_extreme_sweeps_are_verified_or_refused_quickly(self):
        """Bars 1e6 longer and plates 1e6 thinner than wide are verified; at 1e12 the run
        says it could not verify (exit 3) instead of searching for minutes."""
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "e.vtp")
            for length in ("1e6", "1e-6"):
                r = run("extrude", "--length", length, "-o", out)
                self.assertEqual(r.returncode, 0, length + r.stdout + r.stderr)
            for args in (("extrude", "--length", "1e-12"), ("extrude", "--length", "1e12"),
                         ("revolve", "--angle", "1e-9")):
                r = run(*args, "-o", out)
                self.assertEqual(r.returncode, 3, " ".join(args) + r.stdout + r.stderr)
                self.assertIn("not verified: the solid is", r.stderr)

    def test_coordinates_and_weights_of_any_scale(self):
        """The issue's reproducers: a 4 x 1.5 rectangle at (1e5, 1e5), near 1e300, with
        weights x 1e300; a pentagon with a vertex moved by 2e-6 (a cluster of branch points)."""
        def polygon(points, weight=None):
            curves = []
            for i, a in enumerate(points):
                b = points[(i + 1) % len(points)]
                c = {"degree": 1, "knots": [0, 0, 1, 1], "points": [list(a), list(b)]}
                if weight:
                    c["weights"] = [weight, weight]
                curves.append(c)
            return json.dumps({"format": "exactmat-nurbs", "version": 1, "curves": curves})

        def rectangle(cx, cy, s=1.0):
            return [(cx - 2 * s, cy - 0.75 * s), (cx + 2 * s, cy - 0.75 * s),
                    (cx + 2 * s, cy + 0.75 * s), (cx - 2 * s, cy + 0.75 * s)]

        pentagon = [(math.cos(2 * math.pi * k / 5), math.sin(2 * math.pi * k / 5)) for k in range(5)]
        pentagon[0] = (1 + 2e-6, 0.0)
        cases = {
            "far.json": (polygon(rectangle(1e5, 1e5)), 2, 0.75),
            "huge.json": (polygon(rectangle(0, 0, 1e300)), 2, 0.75e300),
            "tiny.json": (polygon(rectangle(0, 0, 1e-300)), 2, 0.75e-300),
            "heavy.json": (polygon(rectangle(0, 0), 1e300), 2, 0.75),
            "light.json": (polygon(rectangle(0, 0), 1e-300), 2, 0.75),
            "pentagon.json": (polygon(pentagon), None, None),
        }
        with tempfile.TemporaryDirectory() as tmp:
            for name, (text, branch_points, radius) in cases.items():
                path = os.path.join(tmp, name)
                with open(path, "w") as f:
                    f.write(text)
                r = run("2d", path, "-o", os.path.join(tmp, "m.vtp"))
                self.assertEqual(r.returncode, 0, name + ": " + r.stdout + r.stderr)
                self.assertIn("verification        passed", r.stdout, name)
                self.assertLessEqual(summary_value(r.stdout, "largest verified error"), 1e-9, name)
                if branch_points is not None:
                    self.assertEqual(summary_value(r.stdout, "branch points"), branch_points, name)
                    reader = vtkXMLPolyDataReader()
                    reader.SetFileName(os.path.join(tmp, "m.vtp"))
                    reader.Update()
                    hi = reader.GetOutput().GetPointData().GetArray("Radius").GetRange()[1]
                    self.assertAlmostEqual(hi / radius, 1.0, delta=1e-12, msg=name)

    def test_hostile_files_get_errors_that_name_them(self):
        with tempfile.TemporaryDirectory() as tmp:
            def write(name, text):
                path = os.path.join(tmp, name)
                with open(path, "w") as f:
                    f.write(text)
                return path
            os.mkdir(os.path.join(tmp, "dir.vtu"))
            cases = [
                (os.path.join(tmp, "dir.vtu"), "is a directory"),
                (write("empty.vtu", ""), "is empty"),
                (write("legacy.vtu", "# vtk DataFile Version 3.0\nx\nASCII\n"), "legacy VTK file"),
                (write("garbage.vtu", "\x01\x02 not xml at all"), "not a VTK XML file"),
                (write("poly.vtu", '<?xml version="1.0"?>\n<VTKFile type="PolyData" version="1.0">'),
                 "not an UnstructuredGrid"),
                (write("truncated.vtu", '<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" '
                       'version="1.0"><UnstructuredGrid><Piece NumberOfPoints="4"'), "truncated or corrupt"),
                (write("overflow.json", '{"curves": [{"degree": 1, "knots": [0,0,1,1], '
                       '"points": [[0,0],[1e999,0]]}]}'), "not valid JSON"),
                (write("degree.json", '{"curves": [{"degree": 4294967297, "knots": [0,0,1,1], '
                       '"points": [[0,0],[1,0]]}]}'), "degree must be an integer from 1 to 32"),
            ]
            for path, message in cases:
                r = run("2d", path, "-o", os.path.join(tmp, "m.vtp"))
                self.assertEqual(r.returncode, 1, path + ": " + r.stderr)
                self.assertIn(message, r.stderr, path)
                self.assertNotIn("ReadXMLInformation", r.stderr, path)

    def test_a_full_disk_is_not_success(self):
        if not os.path.exists("/dev/full"):
            self.skipTest("no /dev/full")
        r = run("2d", "--shape", "rectangle", "-o", "/dev/full")
        self.assertEqual(r.returncode, 4, r.stdout + r.stderr)
        self.assertIn("cannot write", r.stderr)

    def test_shapes_lists_the_catalogue(self):
        r = run("shapes")
        self.assertEqual(r.returncode, 0)
        self.assertIn("narrow-passage", r.stdout.split())


if __name__ == "__main__":
    unittest.main(verbosity=2)

"""The Python package through Debian's /usr/bin/python3: pipelines with vtkmodules, numpy
checks of the exact geometry, errors as exceptions, defaults equal to the ParaView XML."""
import os
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import reference
from vtkmodules.vtkCommonDataModel import vtkGenericCell
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter

import exactmat
from exactmat import (vtkCADBoundaryReader, vtkMAT25DFilter, vtkMAT2DFilter, vtkMAT3DFilter, vtkNURBSReader,
                      vtkNURBSSource, vtkNURBSWriter)

SOURCE_DIR = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GEOMETRY_TOLERANCE = 1e-12


def cell_points(grid, samples=(0.0, 0.25, 0.5, 0.8, 1.0)):
    """Points of every cell at the given parameters, evaluated by VTK (rational weights)."""
    cell = vtkGenericCell()
    out = []
    for c in range(grid.GetNumberOfCells()):
        grid.GetCell(c, cell)
        weights = [0.0] * cell.GetNumberOfPoints()
        for t in samples:
            x = [0.0, 0.0, 0.0]
            cell.EvaluateLocation(reference(0), [t, 0.0, 0.0], x, weights)
            out.append(x)
    return np.array(out)


class PythonPackage(unittest.TestCase):
    def test_circle_is_exact_through_vtk_evaluation(self):
        source = vtkNURBSSource()
        self.assertTrue(source.SetShapeName("circle"))
        source.SetRadius(2.0)
        source.Update()
        grid = source.GetOutput()
        self.assertEqual(grid.GetNumberOfCells(), 4)
        radii = np.linalg.norm(cell_points(grid), axis=1)
        np.testing.assert_allclose(radii, 2.0, atol=GEOMETRY_TOLERANCE)

    def test_arrays_reach_numpy(self):
        source = vtkNURBSSource()
        source.SetShapeName("plate-with-holes")
        source.Update()
        grid = source.GetOutput()
        weights = vtk_to_numpy(grid.GetPointData().GetArray("RationalWeights"))
        self.assertTrue(np.all(weights > 0))
        edges = vtk_to_numpy(grid.GetCellData().GetArray("EdgeId"))
        # 4 sides + 3 holes = 7 NURBS curves.
        self.assertEqual(len(np.unique(edges)), 7)
        ranges = vtk_to_numpy(grid.GetCellData().GetArray("ParameterRange"))
        self.assertTrue(np.all(ranges[:, 1] > ranges[:, 0]))

    def test_composes_with_vtk_xml_io(self):
        with tempfile.TemporaryDirectory() as tmp:
            source = vtkNURBSSource()
            source.SetShapeName("cylinder")
            writer = vtkXMLUnstructuredGridWriter()
            writer.SetInputConnection(source.GetOutputPort())
            writer.SetFileName(os.path.join(tmp, "cyl.vtu"))
            self.assertEqual(writer.Write(), 1)
            reader = vtkXMLUnstructuredGridReader()
            reader.SetFileName(os.path.join(tmp, "cyl.vtu"))
            reader.Update()
            a = vtk_to_numpy(source.GetOutput().GetPoints().GetData())
            b = vtk_to_numpy(reader.GetOutput().GetPoints().GetData())
            np.testing.assert_array_equal(a, b)

    def test_json_round_trip(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "blob.json")
            source = vtkNURBSSource()
            source.SetShapeName("blob")
            writer = vtkNURBSWriter()
            writer.SetInputConnection(source.GetOutputPort())
            writer.SetFileName(path)
            self.assertEqual(writer.Write(), 1)
            reader = vtkNURBSReader()
            reader.SetFileName(path)
            reader.Update()
            np.testing.assert_allclose(cell_points(reader.GetOutput()),
                                       cell_points(source.GetOutput()), atol=1e-13)

    def test_errors_reach_python(self):
        source = vtkNURBSSource()
        errors = exactmat.ErrorObserver().watch(source)
        source.SetShapeName("annulus")
        source.SetInnerRadius(3.0)
        source.Update()
        with self.assertRaisesRegex(exactmat.ExactMATError, "innerRadius 3 must be less than radius 1"):
            errors.check()
        self.assertEqual(source.GetOutput().GetNumberOfCells(), 0)
        with tempfile.TemporaryDirectory() as tmp:
            bad = os.path.join(tmp, "bad.json")
            with open(bad, "w") as f:
                f.write('{"curves": [{"degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 0]], "weights": [1, -1]}]}')
            reader = vtkNURBSReader()
            errors.watch(reader)
            reader.SetFileName(bad)
            reader.Update()
            with self.assertRaisesRegex(exactmat.ExactMATError, r"curves\[0\]: control point 1 has weight -1"):
                errors.check()

    def test_mat2d_filter_radius_through_numpy(self):
        source = vtkNURBSSource()
        source.SetShapeName("annulus")  # R = 1, r = 0.5: the MAT is the circle 0.75, radius 0.25
        mat = vtkMAT2DFilter()
        mat.SetInputConnection(source.GetOutputPort())
        mat.Update()
        out = mat.GetOutput()
        points = vtk_to_numpy(out.GetPoints().GetData())
        radius = vtk_to_numpy(out.GetPointData().GetArray("Radius"))
        np.testing.assert_allclose(np.linalg.norm(points, axis=1), 0.75, atol=1e-12)
        np.testing.assert_allclose(radius, 0.25, atol=1e-12)
        self.assertEqual(mat.GetNumberOfSegments(), 1)
        self.assertLessEqual(mat.GetMaximumVerifiedError(), 1e-12)
        foot = vtk_to_numpy(out.GetPointData().GetArray("Footpoint0"))
        np.testing.assert_allclose(np.linalg.norm(foot - points, axis=1), radius, atol=1e-12)

    def test_mat2d_filter_errors_reach_python(self):
        source = vtkNURBSSource()
        source.SetShapeName("box")
        mat = vtkMAT2DFilter()
        mat.SetInputConnection(source.GetOutputPort())
        errors = exactmat.ErrorObserver().watch(mat)
        mat.Update()
        with self.assertRaisesRegex(exactmat.ExactMATError, "surface cells"):
            errors.check()

    def test_verification_is_on_the_output(self):
        source = vtkNURBSSource()
        source.SetShapeName("ellipse")
        mat = vtkMAT2DFilter()
        mat.SetInputConnection(source.GetOutputPort())
        mat.Update()
        fd = mat.GetOutput().GetFieldData()
        self.assertEqual(fd.GetArray("VerificationStatus").GetValue(0), 1)
        self.assertLessEqual(fd.GetArray("MaximumVerifiedError").GetValue(0), 1e-9)
        self.assertTrue(mat.GetVerificationPassed())
        # A bound no floating-point result meets: the filter warns and says so on the output.
        mat.SetVerificationTolerance(1e-300)
        warnings = exactmat.ErrorObserver()
        from vtkmodules.vtkCommonCore import vtkCommand
        seen = []
        mat.AddObserver(vtkCommand.WarningEvent, lambda obj, ev: seen.append(ev))
        mat.Update()
        self.assertEqual(mat.GetOutput().GetFieldData().GetArray("VerificationStatus").GetValue(0), 0)
        self.assertIn("largest error at", mat.GetOutput().GetFieldData().GetAbstractArray("VerificationReport").GetValue(0))
        self.assertFalse(mat.GetVerificationPassed())
        self.assertTrue(seen)

    def test_hostile_parameters_are_errors_not_crashes(self):
        source = vtkNURBSSource()
        source.SetShape(55)  # clamped to a value that is no shape
        errors = exactmat.ErrorObserver().watch(source)
        source.Update()
        with self.assertRaisesRegex(exactmat.ExactMATError, "neither a catalogue shape"):
            errors.check()
        for name, count in (("star", 10**9), ("blob", 2**29)):
            source = vtkNURBSSource()
            source.SetShapeName(name)
            source.SetCount(count)
            errors = exactmat.ErrorObserver().watch(source)
            source.Update()
            with self.assertRaisesRegex(exactmat.ExactMATError, "count"):
                errors.check()
        for setter in ("SetTolerance", "SetStep"):
            source = vtkNURBSSource()
            source.SetShapeName("rectangle")
            mat = vtkMAT2DFilter()
            mat.SetInputConnection(source.GetOutputPort())
            getattr(mat, setter)(float("nan"))
            errors = exactmat.ErrorObserver().watch(mat)
            mat.Update()
            with self.assertRaisesRegex(exactmat.ExactMATError, setter[3:] + " is nan"):
                errors.check()

    def test_hostile_grids_name_the_cell_and_the_array(self):
        from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
        from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid, VTK_LINE
        def grid(points, cells, weights=None):
            g = vtkUnstructuredGrid()
            if points is not None:
                p = vtkPoints()
                for x in points:
                    p.InsertNextPoint(*x)
                g.SetPoints(p)
            for c in cells:
                g.InsertNextCell(VTK_LINE, len(c), c)
            if weights is not None:
                w = vtkDoubleArray()
                w.SetName("RationalWeights")
                for v in weights:
                    w.InsertNextValue(v)
                g.GetPointData().AddArray(w)
            return g
        square = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
        cases = [
            (grid(square, [(0, 1), (1, 2), (2, 7), (3, 0)]), "point id 7"),
            (grid(square, [(0, 1), (1, 2), (2, -1), (3, 0)]), "point id -1"),
            (grid(None, [(0, 1), (1, 2)]), "no points"),
            (grid(square, [(0, 1), (1, 2), (2, 3), (3, 0)], weights=[1, 1]), "RationalWeights has 2 values for 4 points"),
        ]
        for g, message in cases:
            mat = vtkMAT2DFilter()
            mat.SetInputData(g)
            errors = exactmat.ErrorObserver().watch(mat)
            mat.Update()
            with self.assertRaisesRegex(exactmat.ExactMATError, message):
                errors.check()

    def check_xml_defaults(self, xml_name, proxy_name, instance, expected_count):
        """Every numeric property's default in the ParaView XML equals the C++ getter's."""
        xml = os.path.join(SOURCE_DIR, "Wrapping", "ParaView", "ExactMAT", xml_name)
        proxy = ET.parse(xml).getroot().find(f".//SourceProxy[@name='{proxy_name}']")
        checked = 0
        for prop in proxy:
            if prop.tag in ("DoubleVectorProperty", "IntVectorProperty"):
                name = prop.get("name")
                value = getattr(instance, "Get" + name)()
                values = value if isinstance(value, tuple) else (value,)
                defaults = tuple(float(v) for v in prop.get("default_values").split())
                self.assertEqual(tuple(float(v) for v in values), defaults, name)
                checked += 1
        self.assertEqual(checked, expected_count)
        return proxy

    def test_a_collection_of_parts_through_the_2d_filter(self):
        """A vtkPartitionedDataSetCollection in: the same structure out, a summary per part."""
        from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet, vtkPartitionedDataSetCollection
        collection = vtkPartitionedDataSetCollection()
        for i, name in enumerate(["rectangle", "annulus", "star"]):
            source = vtkNURBSSource()
            source.SetShapeName(name)
            source.Update()
            collection.SetPartition(i, 0, source.GetOutput())
            collection.GetMetaData(i).Set(vtkCompositeDataSet.NAME(), name)
        mat = vtkMAT2DFilter()
        mat.SetInputDataObject(collection)
        mat.SetNumberOfThreads(2)
        mat.Update()
        out = mat.GetOutputDataObject(0)
        self.assertEqual(out.GetClassName(), "vtkPartitionedDataSetCollection")
        self.assertEqual(mat.GetNumberOfParts(), 3)
        self.assertEqual(mat.GetNumberOfFailedParts(), 0)
        names = out.GetFieldData().GetAbstractArray("PartName")
        status = out.GetFieldData().GetArray("PartStatus")
        segments = out.GetFieldData().GetArray("NumberOfSegments")
        self.assertEqual([names.GetValue(i) for i in range(3)], ["rectangle", "annulus", "star"])
        self.assertEqual([status.GetValue(i) for i in range(3)], [0, 0, 0])
        self.assertEqual([segments.GetValue(i) for i in range(3)], [5, 1, 5])
        self.assertEqual(mat.GetNumberOfSegments(), 11)
        self.assertGreater(out.GetPartition(1, 0).GetNumberOfPoints(), 0)

    def test_mat2d_defaults_equal_the_paraview_xml(self):
        self.check_xml_defaults("MAT2DFilter.xml", "MAT2DFilter", vtkMAT2DFilter(), 7)

    def test_mat25d_filter_box_through_numpy(self):
        # The 4 x 2 rectangle extruded by 3: junctions (+-1, 0, 1) and (+-1, 0, 2), radius 1.
        source = vtkNURBSSource()
        source.SetShapeName("rectangle")
        mat = vtkMAT25DFilter()
        mat.SetInputConnection(source.GetOutputPort())
        mat.SetLength(3.0)
        mat.Update()
        out = mat.GetOutput()
        self.assertEqual(mat.GetNumberOfJunctions(), 4)
        self.assertEqual(out.GetNumberOfVerts(), 4)
        points = vtk_to_numpy(out.GetPoints().GetData())
        radius = vtk_to_numpy(out.GetPointData().GetArray("Radius"))
        kind = vtk_to_numpy(out.GetPointData().GetArray("PointType"))
        junctions = points[kind == 2]
        np.testing.assert_allclose(np.sort(np.abs(junctions[:, 0])), 1.0, atol=1e-12)
        np.testing.assert_allclose(np.sort(junctions[:, 2]), [1, 1, 2, 2], atol=1e-12)
        np.testing.assert_allclose(radius[kind == 2], 1.0, atol=1e-12)
        # Every profile-face sheet point lies at its radius from a profile face (z = r or 3 - r).
        self.assertLessEqual(mat.GetMaximumVerifiedError(), 1e-12)
        self.assertEqual(mat.GetNumberOfTouchpointMismatches(), 0)

    def test_mat25d_filter_errors_reach_python(self):
        source = vtkNURBSSource()
        source.SetShapeName("rectangle")
        mat = vtkMAT25DFilter()
        mat.SetInputConnection(source.GetOutputPort())
        mat.SetSweepTypeToRevolution()  # about the y axis, which crosses the rectangle
        errors = exactmat.ErrorObserver().watch(mat)
        mat.Update()
        with self.assertRaisesRegex(exactmat.ExactMATError, r"touches or crosses the profile at edge"):
            errors.check()

    def test_mat25d_short_extrusion_has_a_mid_sheet(self):
        # The 4 x 2 x 1.5 box (shorter than 2 Rmax = 2): junctions (+-1.25, +-0.25, 0.75).
        source = vtkNURBSSource()
        source.SetShapeName("rectangle")
        mat = vtkMAT25DFilter()
        mat.SetInputConnection(source.GetOutputPort())
        mat.SetLength(1.5)
        mat.Update()
        out = mat.GetOutput()
        points = vtk_to_numpy(out.GetPoints().GetData())
        kind = vtk_to_numpy(out.GetPointData().GetArray("PointType"))
        junctions = points[kind == 2]
        self.assertEqual(len(junctions), 4)
        np.testing.assert_allclose(np.abs(junctions), [[1.25, 0.25, 0.75]] * 4, atol=1e-12)
        self.assertIn(6, vtk_to_numpy(out.GetCellData().GetArray("ElementType")))  # mid-sheet
        self.assertLessEqual(mat.GetMaximumVerifiedError(), 1e-12)

    def test_swept_solid_from_the_source(self):
        source = vtkNURBSSource()
        source.SetShapeName("l-shape")
        source.SetSweep(vtkNURBSSource.SweepRevolution)
        source.SetSweepAngle(90.0)
        source.SetSweepAxisOrigin(-1.0, 0.0, 0.0)
        source.Update()
        solid = source.GetOutput()
        self.assertGreater(solid.GetNumberOfCells(), 6)
        self.assertEqual(solid.GetCellType(0), 77)  # VTK_BEZIER_QUADRILATERAL

    def test_mat25d_defaults_equal_the_paraview_xml(self):
        self.check_xml_defaults("MAT25DFilter.xml", "MAT25DFilter", vtkMAT25DFilter(), 14)

    def test_mat3d_filter_pillow_and_cube_through_numpy(self):
        # The pillow (a cube with bulging bicubic faces): eight seams from the corners into one
        # junction at the centre that all six faces touch.
        source = vtkNURBSSource()
        source.SetShapeName("pillow")
        mat = vtkMAT3DFilter()
        mat.SetInputConnection(source.GetOutputPort())
        mat.Update()
        out = mat.GetOutput()
        self.assertEqual((mat.GetNumberOfJunctions(), mat.GetNumberOfSeams()), (1, 8))
        points = vtk_to_numpy(out.GetPoints().GetData())
        kind = vtk_to_numpy(out.GetPointData().GetArray("PointType"))
        touch = vtk_to_numpy(out.GetPointData().GetArray("Touchpoints"))
        np.testing.assert_allclose(points[kind == 2], [[0, 0, 0]], atol=1e-12)
        self.assertEqual(touch[kind == 2].tolist(), [6])
        self.assertTrue(mat.GetVerificationPassed())
        self.assertLessEqual(mat.GetMaximumVerifiedError(), 1e-9)
        # The notched cube: reflex edges and a reflex corner (governors joined by "/").
        source.SetShapeName("notched-cube")
        mat.Update()
        out = mat.GetOutput()
        self.assertEqual(mat.GetNumberOfJunctions(), 7)
        self.assertTrue(mat.GetVerificationPassed())
        governors = out.GetCellData().GetAbstractArray("Governors")
        tokens = [t for i in range(governors.GetNumberOfTuples()) for t in governors.GetValue(i).split(",")]
        self.assertTrue(any(t.count("/") == 2 for t in tokens))  # the reflex corner
        # An extruded blob's seams are reached only from its rims (fin points, not traced
        # yet): refused, and the reason reaches Python.
        source.SetShapeName("extrusion")
        errors = exactmat.ErrorObserver().watch(mat)
        mat.Update()
        with self.assertRaisesRegex(exactmat.ExactMATError, r"no seam touches"):
            errors.check()

    def test_mat3d_defaults_equal_the_paraview_xml(self):
        self.check_xml_defaults("MAT3DFilter.xml", "MAT3DFilter", vtkMAT3DFilter(), 8)

    def test_sheets_of_the_box_through_numpy(self):
        # The catalogue box 4 x 2 x 3: the complete MAT, 13 planar sheets; every sheet
        # vertex at radius 1 lies in the middle sheet y = 0, |x| <= 1, |z| <= 0.5.
        source = vtkNURBSSource()
        source.SetShapeName("box")
        mat = vtkMAT3DFilter()
        mat.SetInputConnection(source.GetOutputPort())
        sheets = exactmat.vtkSheetInterpolator()
        sheets.SetInputConnection(mat.GetOutputPort())
        sheets.SetSourceConnection(source.GetOutputPort())
        sheets.SetNumberOfThreads(2)
        sheets.Update()
        self.assertEqual(sheets.GetNumberOfInterpolatedSheets(), 13)
        self.assertTrue(sheets.GetVerificationPassed())
        self.assertLessEqual(sheets.GetMaximumCoverageShortfall(), 1e-9)
        out = sheets.GetOutput()
        points = vtk_to_numpy(out.GetPoints().GetData())
        radius = vtk_to_numpy(out.GetPointData().GetArray("Radius"))
        middle = points[np.abs(radius - 1.0) < 1e-12]
        self.assertGreater(len(middle), 4)
        np.testing.assert_allclose(middle[:, 1], 0.0, atol=1e-12)
        self.assertLessEqual(np.abs(middle[:, 0]).max(), 1.0 + 1e-12)
        self.assertLessEqual(np.abs(middle[:, 2]).max(), 0.5 + 1e-12)
        self.assertEqual(vtk_to_numpy(out.GetFieldData().GetArray("SheetStatus")).tolist(), [1] * 13)
        # The B-spline fits (port 1): planar sheets with linear radius, held exactly; the
        # middle sheet's cells at radius 1 in y = 0.
        fits = sheets.GetOutputDataObject(1)
        self.assertEqual(fits.GetNumberOfCells(), sheets.GetNumberOfFitPatches())
        self.assertGreaterEqual(fits.GetNumberOfCells(), 13)
        self.assertLessEqual(sheets.GetMaximumFitError(), 1e-10)
        control = vtk_to_numpy(fits.GetPoints().GetData())
        control_radius = vtk_to_numpy(fits.GetPointData().GetArray("Radius"))
        middle = []
        for c in range(fits.GetNumberOfCells()):
            ids = [fits.GetCell(c).GetPointId(k) for k in range(16)]
            if np.all(np.abs(control_radius[ids] - 1.0) < 1e-9):
                middle.extend(ids)
        self.assertGreaterEqual(len(middle), 16)
        np.testing.assert_allclose(control[middle, 1], 0.0, atol=1e-9)

    def test_sheets_defaults_equal_the_paraview_xml(self):
        self.check_xml_defaults("SheetInterpolator.xml", "SheetInterpolator", exactmat.vtkSheetInterpolator(), 8)

    def test_step_solid_through_the_3d_filter(self):
        # The L prism written by OpenCASCADE as IGES: exact planar faces, the 3D MAT verified.
        reader = vtkCADBoundaryReader()
        reader.SetFileName(os.path.join(SOURCE_DIR, "Testing", "Data", "cad", "l-prism.igs"))
        mat = vtkMAT3DFilter()
        mat.SetInputConnection(reader.GetOutputPort())
        errors = exactmat.ErrorObserver()
        errors.watch(reader, mat)
        mat.Update()
        errors.check()
        self.assertEqual(reader.GetLengthUnit(), "MM")
        self.assertTrue(mat.GetVerificationPassed())
        self.assertEqual(mat.GetNumberOfJunctions(), 5)
        face_ids = vtk_to_numpy(reader.GetOutput().GetCellData().GetArray("FaceId"))
        self.assertEqual(len(np.unique(face_ids)), 8)  # the prism's 8 faces, as in the file
        # A missing file is an exception that names it.
        bad = vtkCADBoundaryReader()
        bad.SetFileName("no-such-part.step")
        errors = exactmat.ErrorObserver()
        errors.watch(bad)
        bad.Update()
        with self.assertRaisesRegex(exactmat.ExactMATError, r"no-such-part.step: cannot open"):
            errors.check()

    def test_cad_reader_defaults_equal_the_paraview_xml(self):
        self.check_xml_defaults("CADBoundaryReader.xml", "CADBoundaryReader", vtkCADBoundaryReader(), 2)

    def test_defaults_equal_the_paraview_xml(self):
        proxy = self.check_xml_defaults("NURBSSource.xml", "NURBSSource", vtkNURBSSource(), 13)
        entries = proxy.find("IntVectorProperty[@name='Shape']").findall(".//EnumerationDomain/Entry")
        self.assertEqual(len(entries), vtkNURBSSource.GetNumberOfCatalogueShapes())
        for entry in entries:
            self.assertEqual(vtkNURBSSource.GetCatalogueShapeName(int(entry.get("value"))), entry.get("text"))


if __name__ == "__main__":
    unittest.main(verbosity=2)

// JSON reader and writer: round trips and errors.
#include "vtkExactMATArrayNames.h"
#include "vtkMATBoundaryConversion.h"
#include "vtkNURBSReader.h"
#include "vtkNURBSSource.h"
#include "vtkNURBSWriter.h"

#include "TestHelpers.h"

#include <vtkCellData.h>
#include <vtkUnstructuredGrid.h>

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

using namespace exactmat;

namespace
{
std::string slurp(const std::string& file)
{
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string output(const std::string& name)
{
  return std::string(EXACTMAT_TEST_OUTPUT) + "/" + name;
}

vtkSmartPointer<vtkUnstructuredGrid> readJson(const std::string& file, std::string* errors = nullptr)
{
  vtkNew<vtkNURBSReader> reader;
  reader->SetFileName(file.c_str());
  auto rec = ErrorRecorder::watch(reader);
  reader->Update();
  if (errors)
    *errors = rec->Messages;
  return reader->GetOutput();
}

void writeJson(vtkUnstructuredGrid* grid, const std::string& file)
{
  vtkNew<vtkNURBSWriter> writer;
  writer->SetInputData(grid);
  writer->SetFileName(file.c_str());
  ASSERT_EQ(writer->Write(), 1);
}

void expectSameGrids(vtkUnstructuredGrid* a, vtkUnstructuredGrid* b, double tolerance)
{
  ASSERT_EQ(a->GetNumberOfCells(), b->GetNumberOfCells());
  if (gridHasSurfaceCells(a))
  {
    const auto pa = patchPiecesFromGrid(a), pb = patchPiecesFromGrid(b);
    for (size_t k = 0; k < pa.size(); ++k)
      for (double u : { 0.0, 0.4, 1.0 })
        for (double v : { 0.0, 0.7, 1.0 })
          EXPECT_LT((pa[k].patch.evaluate(u, v) - pb[k].patch.evaluate(u, v)).norm(), tolerance);
  }
  else
  {
    const auto pa = curvePiecesFromGrid(a), pb = curvePiecesFromGrid(b);
    for (size_t k = 0; k < pa.size(); ++k)
    {
      EXPECT_EQ(pa[k].entity, pb[k].entity);
      ASSERT_EQ(pa[k].curve.degree(), pb[k].curve.degree());
      for (int i = 0; i <= pa[k].curve.degree(); ++i)
      {
        EXPECT_LT((pa[k].curve.controlPoint(i) - pb[k].curve.controlPoint(i)).norm(), tolerance);
        EXPECT_NEAR(pa[k].curve.weight(i), pb[k].curve.weight(i), tolerance);
      }
    }
  }
}
} // namespace

TEST(NURBSIO, GridToJsonToGridIsExact)
{
  for (const char* name : { "blob", "plate-with-holes", "narrow-passage", "spiral", "cylinder", "revolution" })
  {
    vtkNew<vtkNURBSSource> source;
    source->SetShapeName(name);
    source->Update();
    const std::string file = output(std::string("roundtrip-") + name + ".json");
    writeJson(source->GetOutput(), file);
    const auto back = readJson(file);
    // Joining pieces by knot removal and extracting them again costs a few roundings.
    expectSameGrids(source->GetOutput(), back, 1e-13);
    // And the file written from the read grid is the same file.
    const std::string again = output(std::string("roundtrip-") + name + "-2.json");
    writeJson(back, again);
    const auto back2 = readJson(again);
    expectSameGrids(back, back2, 1e-13);
  }
}

TEST(NURBSIO, CurvesComeBackAsTheOriginalNURBS)
{
  // The bundled example: a closed periodic cubic and a rational circle hole.
  const std::string file = std::string(EXACTMAT_TEST_DATA) + "/two-loops.json";
  const auto grid = readJson(file);
  ASSERT_GT(grid->GetNumberOfCells(), 2);
  writeJson(grid, output("two-loops-out.json"));
  const std::string text = slurp(output("two-loops-out.json"));
  // Two curves, not one per Bézier piece, with their original knots.
  size_t count = 0;
  for (size_t at = text.find("\"degree\""); at != std::string::npos; at = text.find("\"degree\"", at + 1))
    ++count;
  EXPECT_EQ(count, 2u) << text;
  const Boundary2D b = Boundary2D::build(curvePiecesFromGrid(grid));
  EXPECT_EQ(b.loops().size(), 2u);
  EXPECT_EQ(b.holeCount(), 1);
}

TEST(NURBSIO, BadFilesGiveClearErrors)
{
  auto errorFor = [](const std::string& name, const std::string& text) {
    const std::string file = output(name);
    std::ofstream(file) << text;
    std::string errors;
    readJson(file, &errors);
    return errors;
  };
  EXPECT_NE(errorFor("bad1.json", "{ not json").find("not valid JSON"), std::string::npos);
  EXPECT_NE(errorFor("bad2.json", "{\"curves\": []}").find("empty input"), std::string::npos);
  const std::string knots = errorFor("bad3.json",
    "{\"curves\": [{\"degree\": 1, \"knots\": [0, 1, 0.5, 1], \"points\": [[0,0],[1,0]]}]}");
  EXPECT_NE(knots.find("curves[0]: knot vector is not non-decreasing"), std::string::npos) << knots;
  const std::string length = errorFor("bad4.json",
    "{\"curves\": [{\"degree\": 2, \"knots\": [0, 0, 1, 1], \"points\": [[0,0],[1,0],[1,1]]}]}");
  EXPECT_NE(length.find("knot vector has 4 knots, expected 6"), std::string::npos) << length;
  const std::string weight = errorFor("bad5.json",
    "{\"curves\": [{\"degree\": 1, \"knots\": [0, 0, 1, 1], \"points\": [[0,0],[1,0]], \"weights\": [1, 0]}]}");
  EXPECT_NE(weight.find("control point 1 has weight 0"), std::string::npos) << weight;
  const std::string missing = errorFor("bad6.json", "{\"curves\": [{\"degree\": 1, \"points\": [[0,0],[1,0]]}]}");
  EXPECT_NE(missing.find("curves[0]: missing \"knots\""), std::string::npos) << missing;
  std::string none;
  readJson(output("does-not-exist.json"), &none);
  EXPECT_NE(none.find("cannot open"), std::string::npos);
}

#include "vtkMATPartSummary.h"

#include "vtkExactMATArrayNames.h"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkLongLongArray.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>

#include <algorithm>
#include <map>

namespace exactmat
{
namespace
{
constexpr const char* KeyColumn = "PartKey";

// Every figure any row has, in the order the rows first name them.
std::vector<PartFigure> figureColumns(const std::vector<PartRow>& rows)
{
  std::vector<PartFigure> columns;
  for (const PartRow& r : rows)
    for (const PartFigure& f : r.figures)
      if (std::none_of(columns.begin(), columns.end(), [&f](const PartFigure& c) { return c.name == f.name; }))
        columns.push_back(f);
  return columns;
}

double figureOf(const PartRow& row, const std::string& name)
{
  for (const PartFigure& f : row.figures)
    if (f.name == name)
      return f.value;
  return 0.0;
}

// The rows as a table (what travels between ranks): the summary's arrays plus the keys.
vtkSmartPointer<vtkTable> toTable(const std::vector<PartRow>& rows)
{
  vtkNew<vtkFieldData> fd;
  attachPartSummary(fd, rows);
  vtkNew<vtkLongLongArray> keys;
  keys->SetName(KeyColumn);
  for (const PartRow& r : rows)
    keys->InsertNextValue(r.key);
  auto table = vtkSmartPointer<vtkTable>::New();
  table->AddColumn(keys);
  for (int i = 0; i < fd->GetNumberOfArrays(); ++i)
    table->AddColumn(fd->GetAbstractArray(i));
  return table;
}

std::vector<PartRow> fromTable(vtkTable* table)
{
  std::vector<PartRow> rows;
  auto* keys = vtkLongLongArray::SafeDownCast(table->GetColumnByName(KeyColumn));
  auto* names = vtkStringArray::SafeDownCast(table->GetColumnByName(arrays::PartName));
  auto* status = vtkIntArray::SafeDownCast(table->GetColumnByName(arrays::PartStatus));
  auto* messages = vtkStringArray::SafeDownCast(table->GetColumnByName(arrays::PartMessage));
  auto* seconds = vtkDoubleArray::SafeDownCast(table->GetColumnByName(arrays::PartSeconds));
  auto* errors = vtkDoubleArray::SafeDownCast(table->GetColumnByName(arrays::MaximumVerifiedError));
  if (!keys || !names || !status || !messages || !seconds || !errors)
    return rows;
  const char* fixed[] = { KeyColumn, arrays::PartName, arrays::PartStatus, arrays::PartMessage,
    arrays::PartSeconds, arrays::MaximumVerifiedError };
  for (vtkIdType i = 0; i < keys->GetNumberOfValues(); ++i)
  {
    PartRow r;
    r.key = keys->GetValue(i);
    r.name = names->GetValue(i);
    r.status = status->GetValue(i);
    r.message = messages->GetValue(i);
    r.seconds = seconds->GetValue(i);
    r.maximumError = errors->GetValue(i);
    for (vtkIdType c = 0; c < table->GetNumberOfColumns(); ++c)
    {
      const std::string name = table->GetColumnName(c) ? table->GetColumnName(c) : "";
      if (std::find(std::begin(fixed), std::end(fixed), name) != std::end(fixed))
        continue;
      auto* column = vtkDataArray::SafeDownCast(table->GetColumn(c));
      if (column && i < column->GetNumberOfTuples() && r.status >= 0)
        r.figures.push_back({ name, column->GetTuple1(i), vtkIntArray::SafeDownCast(column) != nullptr });
    }
    rows.push_back(std::move(r));
  }
  return rows;
}

// Rows by key: a computed row wins over an absent one, the first computed one over later.
std::vector<PartRow> merge(const std::vector<std::vector<PartRow>>& perRank)
{
  std::map<long long, PartRow> byKey;
  for (const auto& rows : perRank)
    for (const PartRow& r : rows)
    {
      auto it = byKey.find(r.key);
      if (it == byKey.end() || (it->second.status < 0 && r.status >= 0))
        byKey[r.key] = r;
    }
  std::vector<PartRow> merged;
  for (auto& [key, r] : byKey)
  {
    if (r.status < 0)
    {
      r.status = 3;
      r.message = "no boundary cells on any rank";
      r.figures.clear();
    }
    merged.push_back(std::move(r));
  }
  return merged;
}
} // namespace

std::vector<PartRow> gatherPartRows(vtkMultiProcessController* controller, const std::vector<PartRow>& local)
{
  if (!controller || controller->GetNumberOfProcesses() < 2)
    return merge({ local });
  std::vector<vtkSmartPointer<vtkDataObject>> received;
  vtkSmartPointer<vtkTable> mine = toTable(local);
  std::vector<std::vector<PartRow>> perRank;
  if (controller->AllGather(mine, received) && static_cast<int>(received.size()) == controller->GetNumberOfProcesses())
  {
    for (auto& object : received)
      if (auto* table = vtkTable::SafeDownCast(object))
        perRank.push_back(fromTable(table));
  }
  else
    perRank.push_back(local); // the exchange failed: this rank's own rows, still in order
  return merge(perRank);
}

vtkSmartPointer<vtkDataArray> newFigureArray(const PartFigure& figure)
{
  vtkSmartPointer<vtkDataArray> a;
  if (figure.integer)
    a = vtkSmartPointer<vtkIntArray>::New();
  else
    a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(figure.name.c_str());
  return a;
}

void attachPartSummary(vtkFieldData* fd, const std::vector<PartRow>& rows)
{
  vtkNew<vtkStringArray> names, messages;
  vtkNew<vtkIntArray> status;
  vtkNew<vtkDoubleArray> seconds, errors;
  names->SetName(arrays::PartName);
  messages->SetName(arrays::PartMessage);
  status->SetName(arrays::PartStatus);
  seconds->SetName(arrays::PartSeconds);
  errors->SetName(arrays::MaximumVerifiedError);
  const std::vector<PartFigure> columns = figureColumns(rows);
  std::vector<vtkSmartPointer<vtkDataArray>> figureArrays;
  for (const PartFigure& c : columns)
    figureArrays.push_back(newFigureArray(c));
  for (const PartRow& r : rows)
  {
    names->InsertNextValue(r.name);
    status->InsertNextValue(r.status);
    messages->InsertNextValue(r.message);
    seconds->InsertNextValue(r.seconds);
    errors->InsertNextValue(r.maximumError);
    for (size_t c = 0; c < columns.size(); ++c)
      figureArrays[c]->InsertNextTuple1(figureOf(r, columns[c].name));
  }
  fd->AddArray(names);
  fd->AddArray(status);
  fd->AddArray(messages);
  fd->AddArray(seconds);
  fd->AddArray(errors);
  for (auto& a : figureArrays)
    fd->AddArray(a);
}

} // namespace exactmat

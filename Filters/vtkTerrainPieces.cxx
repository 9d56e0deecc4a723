#include "vtkTerrainPieces.h"

#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStructuredGrid.h"
#include "vtkUnsignedCharArray.h"

#include "geo_transform.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace
{
// The georeference of a piece, when it has one.
bool transformOf(vtkDataSet* data, terralux::GeoTransform& transform)
{
  vtkDataArray* coefficients = data->GetFieldData()->GetArray("GeoTransform");
  if (!coefficients || coefficients->GetNumberOfValues() != 6)
    return false;
  for (int k = 0; k < 6; ++k)
    transform.coefficients[k] = coefficients->GetComponent(k, 0);
  return true;
}

// What a piece sends: its extent, point arrays and numeric field data, no points
// (the legacy format the controller sends data sets in does not keep strings with
// spaces, as the CRS's WKT; the root takes those from its own piece).
vtkSmartPointer<vtkImageData> packetOf(vtkDataSet* piece)
{
  auto packet = vtkSmartPointer<vtkImageData>::New();
  auto* grid = vtkStructuredGrid::SafeDownCast(piece);
  terralux::GeoTransform unused;
  if (!grid || grid->GetNumberOfPoints() == 0 || !transformOf(grid, unused))
    return packet; // empty
  packet->SetExtent(grid->GetExtent());
  packet->GetPointData()->ShallowCopy(grid->GetPointData());
  vtkFieldData* fieldData = grid->GetFieldData();
  for (int k = 0; k < fieldData->GetNumberOfArrays(); ++k)
    if (vtkDataArray* array = fieldData->GetArray(k))
      packet->GetFieldData()->AddArray(array);
  return packet;
}
} // namespace

vtkSmartPointer<vtkImageData> vtkTerrainPieces::GatherToRoot(
  vtkMultiProcessController* controller, vtkDataSet* piece, int root)
{
  std::vector<vtkSmartPointer<vtkDataObject>> received;
  controller->Gather(packetOf(piece), received, root);
  if (controller->GetLocalProcessId() != root)
    return nullptr;

  std::vector<vtkImageData*> pieces;
  for (const auto& object : received)
    if (auto* image = vtkImageData::SafeDownCast(object); image && image->GetNumberOfPoints() > 0)
      pieces.push_back(image);
  if (pieces.empty())
    return nullptr;
  int whole[6] = { VTK_INT_MAX, VTK_INT_MIN, VTK_INT_MAX, VTK_INT_MIN, 0, 0 };
  for (vtkImageData* p : pieces)
  {
    const int* e = p->GetExtent();
    for (int axis = 0; axis < 2; ++axis)
    {
      whole[2 * axis] = std::min(whole[2 * axis], e[2 * axis]);
      whole[2 * axis + 1] = std::max(whole[2 * axis + 1], e[2 * axis + 1]);
    }
  }
  const int nx = whole[1] - whole[0] + 1;
  const int ny = whole[3] - whole[2] + 1;
  const vtkIdType count = static_cast<vtkIdType>(nx) * ny;

  auto result = vtkSmartPointer<vtkImageData>::New();
  result->SetExtent(whole);
  result->GetFieldData()->DeepCopy(piece && piece->GetNumberOfPoints() > 0 ? piece->GetFieldData() : pieces[0]->GetFieldData());
  // Posts no piece holds stay blanked; a piece's duplicate (ghost) marks are dropped.
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  ghosts->SetNumberOfTuples(count);
  ghosts->Fill(vtkDataSetAttributes::HIDDENPOINT);
  vtkPointData* first = pieces[0]->GetPointData();
  for (int a = 0; a < first->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* model = first->GetArray(a);
    if (!model || !model->GetName() || model == first->GetArray(vtkDataSetAttributes::GhostArrayName()))
      continue;
    vtkSmartPointer<vtkDataArray> array;
    array.TakeReference(model->NewInstance());
    array->SetName(model->GetName());
    array->SetNumberOfComponents(model->GetNumberOfComponents());
    array->SetNumberOfTuples(count);
    array->Fill(std::numeric_limits<double>::quiet_NaN());
    if (vtkInformation* info = model->HasInformation() ? model->GetInformation() : nullptr)
      array->GetInformation()->Copy(info);
    result->GetPointData()->AddArray(array);
  }
  for (vtkImageData* p : pieces)
  {
    const int* e = p->GetExtent();
    vtkUnsignedCharArray* pieceGhosts = p->GetPointGhostArray();
    for (int j = e[2]; j <= e[3]; ++j)
      for (int i = e[0]; i <= e[1]; ++i)
      {
        const vtkIdType from = (i - e[0]) + static_cast<vtkIdType>(j - e[2]) * (e[1] - e[0] + 1);
        const vtkIdType to = (i - whole[0]) + static_cast<vtkIdType>(j - whole[2]) * nx;
        ghosts->SetValue(to, pieceGhosts ? pieceGhosts->GetValue(from) & vtkDataSetAttributes::HIDDENPOINT : 0);
        for (int a = 0; a < result->GetPointData()->GetNumberOfArrays(); ++a)
        {
          vtkDataArray* target = result->GetPointData()->GetArray(a);
          if (vtkDataArray* source = p->GetPointData()->GetArray(target->GetName()))
            target->SetTuple(to, from, source);
        }
      }
  }
  result->GetPointData()->AddArray(ghosts);

  // The whole grid's georeference, from any piece's.
  terralux::GeoTransform pieceTransform;
  transformOf(pieces[0], pieceTransform);
  const int* e = pieces[0]->GetExtent();
  const int row0 = pieceTransform.firstRasterRow(e[2] - whole[2], e[3] - whole[2], ny);
  const terralux::GeoTransform wholeTransform = pieceTransform.window(-(e[0] - whole[0]), -row0, 1);
  vtkNew<vtkDoubleArray> transform;
  transform->SetName("GeoTransform");
  for (double c : wholeTransform.coefficients)
    transform->InsertNextValue(c);
  result->GetFieldData()->AddArray(transform);
  vtkNew<vtkIntArray> rasterSize;
  rasterSize->SetName("RasterSize");
  rasterSize->InsertNextValue(nx);
  rasterSize->InsertNextValue(ny);
  result->GetFieldData()->AddArray(rasterSize);
  return result;
}

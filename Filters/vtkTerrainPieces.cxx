#include "vtkTerrainPieces.h"

#include "vtkRadiosityOutputs.h"

#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkMPICommunicator.h"
#include "vtkMPIController.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStructuredGrid.h"
#include "vtkTable.h"
#include "vtkTerraLuxFieldData.h"
#include "vtkUnsignedCharArray.h"

#include "geo_transform.h"
#include "work_split.h"

#include <algorithm>
#include <climits>
#include <cstring>
#include <deque>
#include <limits>
#include <utility>
#include <vector>

namespace
{
// The georeference of a grid or a piece, when its field data has one.
bool transformOf(vtkFieldData* fieldData, terralux::GeoTransform& transform)
{
  vtkDataArray* coefficients = fieldData->GetArray(vtkTerraLuxFieldData::GeoTransformName());
  if (!coefficients || coefficients->GetNumberOfValues() != 6)
    return false;
  for (int k = 0; k < 6; ++k)
    transform.coefficients[k] = coefficients->GetComponent(k, 0);
  return true;
}

// Replaces the georeference field data: an nx x ny raster on `transform`.
void setGeoreference(vtkFieldData* fieldData, const terralux::GeoTransform& transform, int nx, int ny)
{
  vtkNew<vtkDoubleArray> coefficients;
  coefficients->SetName(vtkTerraLuxFieldData::GeoTransformName());
  for (double c : transform.coefficients)
    coefficients->InsertNextValue(c);
  fieldData->AddArray(coefficients);
  vtkNew<vtkIntArray> rasterSize;
  rasterSize->SetName(vtkTerraLuxFieldData::RasterSizeName());
  rasterSize->InsertNextValue(nx);
  rasterSize->InsertNextValue(ny);
  fieldData->AddArray(rasterSize);
}

// What a piece tells the root first: a table of one-row columns named and typed as its
// point arrays, with its numeric field data and its extent (`PieceExtent`), no points;
// the arrays' values follow one array at a time (sent as they are, no copy). A table,
// because the legacy format the controller sends data objects in keeps neither an
// image's extent in ParaView (its images are uniform grids, which it cannot write) nor
// strings with spaces (the CRS's WKT: the root takes that from its own piece). Empty
// where the piece has no georeferenced posts.
vtkSmartPointer<vtkTable> packetOf(vtkDataSet* piece, std::vector<vtkDataArray*>& arrays)
{
  auto packet = vtkSmartPointer<vtkTable>::New();
  auto* grid = vtkStructuredGrid::SafeDownCast(piece);
  terralux::GeoTransform unused;
  if (!grid || grid->GetNumberOfPoints() == 0 || !transformOf(grid->GetFieldData(), unused))
    return packet;
  vtkPointData* pointData = grid->GetPointData();
  for (int k = 0; k < pointData->GetNumberOfArrays(); ++k)
    if (vtkDataArray* array = pointData->GetArray(k); array && array->GetName())
    {
      vtkSmartPointer<vtkDataArray> column;
      column.TakeReference(array->NewInstance());
      column->SetName(array->GetName());
      column->SetNumberOfComponents(array->GetNumberOfComponents());
      column->SetNumberOfTuples(1); // the legacy format drops a table without rows
      column->Fill(0.0);
      packet->AddColumn(column);
      arrays.push_back(array);
    }
  vtkFieldData* fieldData = grid->GetFieldData();
  for (int k = 0; k < fieldData->GetNumberOfArrays(); ++k)
    if (vtkDataArray* array = fieldData->GetArray(k))
      packet->GetFieldData()->AddArray(array);
  vtkNew<vtkIntArray> extent;
  extent->SetName("PieceExtent");
  for (int k = 0; k < 6; ++k)
    extent->InsertNextValue(grid->GetExtent()[k]);
  packet->GetFieldData()->AddArray(extent);
  return packet;
}

// A piece the root assembles: its extent, its arrays' names and types (the packet's
// columns) and the rank that sends their values.
struct Piece
{
  int extent[6];
  vtkTable* table;
  int rank;
};
} // namespace

vtkSmartPointer<vtkImageData> vtkTerrainPieces::GatherToRoot(
  vtkMultiProcessController* controller, vtkDataSet* piece, int root)
{
  // First the small packets, then each piece's arrays, one rank and one array at a
  // time: the root holds the whole grid and one array in flight, the others nothing
  // more than their piece.
  std::vector<vtkDataArray*> ownArrays;
  const vtkSmartPointer<vtkTable> packet = packetOf(piece, ownArrays);
  std::vector<vtkSmartPointer<vtkDataObject>> received;
  controller->Gather(packet, received, root);
  constexpr int valuesTag = 47113;
  if (controller->GetLocalProcessId() != root)
  {
    for (vtkDataArray* array : ownArrays)
      controller->Send(array, root, valuesTag);
    return nullptr;
  }

  std::vector<Piece> pieces;
  for (int rank = 0; rank < static_cast<int>(received.size()); ++rank)
  {
    auto* table = vtkTable::SafeDownCast(received[rank]);
    vtkDataArray* extent = table ? table->GetFieldData()->GetArray("PieceExtent") : nullptr;
    if (!extent || extent->GetNumberOfValues() != 6)
      continue;
    Piece piece{ {}, table, rank };
    for (int k = 0; k < 6; ++k)
      piece.extent[k] = static_cast<int>(extent->GetComponent(k, 0));
    pieces.push_back(piece);
  }
  if (pieces.empty())
    return nullptr;
  int whole[6] = { VTK_INT_MAX, VTK_INT_MIN, VTK_INT_MAX, VTK_INT_MIN, 0, 0 };
  for (const Piece& p : pieces)
  {
    const int* e = p.extent;
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
  result->GetFieldData()->DeepCopy(
    piece && piece->GetNumberOfPoints() > 0 ? piece->GetFieldData() : pieces[0].table->GetFieldData());
  result->GetFieldData()->RemoveArray("PieceExtent");
  // Posts no piece holds stay blanked; a piece's duplicate (ghost) marks are dropped.
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  ghosts->SetNumberOfTuples(count);
  ghosts->Fill(vtkDataSetAttributes::HIDDENPOINT);
  vtkTable* first = pieces[0].table;
  for (vtkIdType a = 0; a < first->GetNumberOfColumns(); ++a)
  {
    vtkDataArray* model = vtkDataArray::SafeDownCast(first->GetColumn(a));
    if (!model || !model->GetName() || std::strcmp(model->GetName(), vtkDataSetAttributes::GhostArrayName()) == 0)
      continue;
    vtkSmartPointer<vtkDataArray> array;
    array.TakeReference(model->NewInstance());
    array->SetName(model->GetName());
    array->SetNumberOfComponents(model->GetNumberOfComponents());
    array->SetNumberOfTuples(count);
    vtkRadiosityOutputs::FillWithNaN(array);
    if (vtkInformation* info = model->HasInformation() ? model->GetInformation() : nullptr)
      array->GetInformation()->Copy(info);
    result->GetPointData()->AddArray(array);
  }
  for (const Piece& p : pieces)
  {
    const int* e = p.extent;
    const int width = e[1] - e[0] + 1;
    // The piece's arrays, in its packet's order: the root's own as they are, the others'
    // as they arrive. Each row of a piece is a run of posts in the whole grid too.
    for (vtkIdType a = 0; a < p.table->GetNumberOfColumns(); ++a)
    {
      auto* model = vtkDataArray::SafeDownCast(p.table->GetColumn(a));
      vtkSmartPointer<vtkDataArray> values = p.rank == root ? ownArrays[static_cast<std::size_t>(a)] : nullptr;
      if (!values)
      {
        values.TakeReference(model->NewInstance());
        controller->Receive(values, p.rank, valuesTag);
      }
      const bool ghost = std::strcmp(model->GetName(), vtkDataSetAttributes::GhostArrayName()) == 0;
      vtkDataArray* target = ghost ? nullptr : result->GetPointData()->GetArray(model->GetName());
      for (int j = e[2]; j <= e[3]; ++j)
      {
        const vtkIdType from = static_cast<vtkIdType>(j - e[2]) * width;
        const vtkIdType to = (e[0] - whole[0]) + static_cast<vtkIdType>(j - whole[2]) * nx;
        if (target && target->GetNumberOfComponents() == values->GetNumberOfComponents())
          target->InsertTuples(to, width, from, values);
        if (ghost)
          for (int i = 0; i < width; ++i)
            ghosts->SetValue(
              to + i, static_cast<unsigned char>(values->GetComponent(from + i, 0)) & vtkDataSetAttributes::HIDDENPOINT);
      }
    }
    // Posts of a piece without a ghost array are all shown.
    if (!p.table->GetColumnByName(vtkDataSetAttributes::GhostArrayName()))
      for (int j = e[2]; j <= e[3]; ++j)
        std::fill_n(ghosts->GetPointer((e[0] - whole[0]) + static_cast<vtkIdType>(j - whole[2]) * nx), width, 0);
  }
  result->GetPointData()->AddArray(ghosts);

  // The whole grid's georeference, from any piece's.
  terralux::GeoTransform pieceTransform;
  transformOf(pieces[0].table->GetFieldData(), pieceTransform); // packetOf sent only georeferenced pieces
  const int* e = pieces[0].extent;
  const int row0 = pieceTransform.firstRasterRow(e[2] - whole[2], e[3] - whole[2], ny);
  setGeoreference(result->GetFieldData(), pieceTransform.window(-(e[0] - whole[0]), -row0, 1), nx, ny);
  return result;
}

void vtkTerrainPieces::CropToPiece(vtkStructuredGrid* terrain, const int extent[6])
{
  int whole[6];
  terrain->GetExtent(whole);
  if (std::equal(extent, extent + 6, whole))
    return;
  terrain->Crop(extent);
  terralux::GeoTransform wholeTransform;
  if (!transformOf(terrain->GetFieldData(), wholeTransform))
    return;
  setGeoreference(terrain->GetFieldData(),
    wholeTransform.pieceOf(extent[0] - whole[0], extent[2] - whole[2], extent[3] - whole[2], whole[3] - whole[2] + 1),
    extent[1] - extent[0] + 1, extent[3] - extent[2] + 1);
}

namespace
{
class RankSplit : public terralux::WorkSplit
{
public:
  // Collective: every rank gives its piece's extent.
  RankSplit(vtkMultiProcessController* controller, const int extent[6])
    : Controller(controller)
  {
    const int own[4] = { extent[0], extent[1], extent[2], extent[3] };
    std::vector<int> all(4 * static_cast<std::size_t>(controller->GetNumberOfProcesses()));
    controller->AllGather(own, all.data(), 4);
    for (std::size_t k = 0; k < all.size(); k += 4)
      this->Windows.push_back({ all[k], all[k + 1], all[k + 2], all[k + 3] });
  }
  int part() const override { return this->Controller->GetLocalProcessId(); }
  int parts() const override { return this->Controller->GetNumberOfProcesses(); }
  void share(void* data, std::size_t size, int owner) const override
  {
    // MPI counts are ints: 1 GiB at a time.
    constexpr std::size_t chunk = std::size_t{ 1 } << 30;
    char* bytes = static_cast<char*>(data);
    for (std::size_t offset = 0; offset < size; offset += chunk)
      this->Controller->Broadcast(bytes + offset, static_cast<vtkIdType>(std::min(chunk, size - offset)), owner);
  }
  Window window(int part) const override { return this->Windows[static_cast<std::size_t>(part)]; }
  bool allSucceeded(bool succeeded) const override
  {
    int mine = succeeded ? 1 : 0, all = 0;
    this->Controller->AllReduce(&mine, &all, 1, vtkCommunicator::MIN_OP);
    return all == 1;
  }
  // Point to point through MPI: sends that do not wait (a process that waits for a
  // neighbour's hulls on one azimuth must not hold up what it sends on another).
  bool sendsPointToPoint() const override { return this->Mpi != nullptr; }
  void send(std::vector<char> bytes, int to, int tag) const override
  {
    if (bytes.size() > static_cast<std::size_t>(INT_MAX))
      throw terralux::Error("a message between MPI ranks outgrew 2 GiB");
    Outgoing& out = this->Pending.emplace_back();
    out.Size = static_cast<int>(bytes.size());
    out.Bytes = std::move(bytes);
    this->Mpi->NoBlockSend(&out.Size, 1, to, TagBase + tag, out.SizeSent);
    if (out.Size > 0)
      this->Mpi->NoBlockSend(out.Bytes.data(), out.Size, to, TagBase + tag, out.BytesSent);
  }
  std::vector<char> receive(int from, int tag) const override
  {
    int size = 0;
    this->Mpi->Receive(&size, 1, from, TagBase + tag);
    std::vector<char> bytes(static_cast<std::size_t>(std::max(0, size)));
    if (size > 0)
      this->Mpi->Receive(bytes.data(), size, from, TagBase + tag);
    return bytes;
  }
  void finishSends() const override
  {
    for (Outgoing& out : this->Pending)
    {
      out.SizeSent.Wait();
      if (out.Size > 0)
        out.BytesSent.Wait();
    }
    this->Pending.clear();
  }

private:
  static constexpr int TagBase = 7700; // apart from VTK's own tags
  struct Outgoing
  {
    int Size = 0;
    std::vector<char> Bytes;
    vtkMPICommunicator::Request SizeSent, BytesSent;
  };
  vtkMultiProcessController* Controller;
  vtkMPIController* Mpi = vtkMPIController::SafeDownCast(this->Controller);
  std::vector<Window> Windows;
  mutable std::deque<Outgoing> Pending; // kept until sent
};
} // namespace

std::unique_ptr<terralux::WorkSplit> vtkTerrainPieces::SplitAmongRanks(int piece, int pieces, const int extent[6])
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!controller || pieces < 2 || controller->GetNumberOfProcesses() != pieces ||
    controller->GetLocalProcessId() != piece)
    return nullptr;
  return std::make_unique<RankSplit>(controller, extent);
}

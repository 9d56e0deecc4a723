#include "vtkTerrainPieces.h"

#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkExtentTranslator.h"
#include "vtkFieldData.h"
#include "vtkAlgorithm.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerRequestKey.h"
#include "vtkIntArray.h"
#include "vtkMPICommunicator.h"
#include "vtkMPIController.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStructuredGrid.h"
#include "vtkTable.h"
#include "vtkTerraLuxFieldData.h"

#include "geodesy/geo_transform.h"
#include "parallel/work_split.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cstring>
#include <deque>
#include <exception>
#include <limits>
#include <utility>
#include <vector>

namespace
{
/// The field-data key of a piece's extent in the table it sends the root.
constexpr const char* pieceExtentName = "PieceExtent";
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
  // The ghosts first: the root reads the others' values with them.
  std::vector<vtkDataArray*> ordered;
  if (vtkDataArray* ghosts = grid->GetPointGhostArray())
    ordered.push_back(ghosts);
  for (int k = 0; k < pointData->GetNumberOfArrays(); ++k)
    if (vtkDataArray* array = pointData->GetArray(k);
        array && array->GetName() && array != static_cast<vtkDataArray*>(grid->GetPointGhostArray()))
      ordered.push_back(array);
  for (vtkDataArray* array : ordered)
  {
    vtkSmartPointer<vtkDataArray> column;
    column.TakeReference(array->NewInstance());
    column->SetName(array->GetName());
    column->SetNumberOfComponents(array->GetNumberOfComponents());
    column->SetNumberOfTuples(1); // the legacy format drops a table without rows
    column->Fill(0.0);
    if (array->HasInformation()) // units (vtkDataArray::UNITS_LABEL)
      column->GetInformation()->Copy(array->GetInformation());
    packet->AddColumn(column);
    arrays.push_back(array);
  }
  vtkFieldData* fieldData = grid->GetFieldData();
  for (int k = 0; k < fieldData->GetNumberOfArrays(); ++k)
    if (vtkDataArray* array = fieldData->GetArray(k))
      packet->GetFieldData()->AddArray(array);
  vtkNew<vtkIntArray> extent;
  extent->SetName(pieceExtentName);
  for (int k = 0; k < 6; ++k)
    extent->InsertNextValue(grid->GetExtent()[k]);
  packet->GetFieldData()->AddArray(extent);
  return packet;
}

// Whether the rectangles (i0, i1, j0, j1, inclusive) cover the whole extent's posts.
bool coversWhole(const std::vector<std::array<int, 4>>& rectangles, const int whole[6])
{
  // On the grid of the rectangles' edges, each elementary cell is covered or not.
  std::vector<int> xs{ whole[0], whole[1] + 1 }, ys{ whole[2], whole[3] + 1 };
  for (const auto& r : rectangles)
  {
    xs.push_back(r[0]), xs.push_back(r[1] + 1), ys.push_back(r[2]), ys.push_back(r[3] + 1);
  }
  for (auto* edges : { &xs, &ys })
  {
    std::sort(edges->begin(), edges->end());
    edges->erase(std::unique(edges->begin(), edges->end()), edges->end());
  }
  for (std::size_t b = 0; b + 1 < ys.size(); ++b)
    for (std::size_t a = 0; a + 1 < xs.size(); ++a)
    {
      if (xs[a] < whole[0] || xs[a] > whole[1] || ys[b] < whole[2] || ys[b] > whole[3])
        continue;
      const bool covered = std::any_of(rectangles.begin(), rectangles.end(), [&](const std::array<int, 4>& r) {
        return r[0] <= xs[a] && xs[a + 1] - 1 <= r[1] && r[2] <= ys[b] && ys[b + 1] - 1 <= r[3];
      });
      if (!covered)
        return false;
    }
  return true;
}

// A piece the root writes: its extent, its arrays' names and types (the packet's
// columns) and the rank that sends their values.
struct Piece
{
  int extent[6];
  vtkTable* table;
  int rank;
};
} // namespace

bool vtkTerrainPieces::SendToRoot(vtkMultiProcessController* controller, vtkDataSet* piece, int root,
  const std::function<void(const Layout&)>& begin, const std::function<void(const PieceArray&)>& each)
{
  // First the small packets, then each piece's arrays, one rank and one array at a
  // time (its ghosts first): the root holds its own piece and one array in flight, the
  // others nothing more than their piece.
  std::vector<vtkDataArray*> ownArrays;
  const vtkSmartPointer<vtkTable> packet = packetOf(piece, ownArrays);
  std::vector<vtkSmartPointer<vtkDataObject>> received;
  controller->Gather(packet, received, root);
  constexpr int valuesTag = 47113;
  if (controller->GetLocalProcessId() != root)
  {
    for (vtkDataArray* array : ownArrays)
      controller->Send(array, root, valuesTag);
    return false;
  }

  std::vector<Piece> pieces;
  for (int rank = 0; rank < static_cast<int>(received.size()); ++rank)
  {
    auto* table = vtkTable::SafeDownCast(received[rank]);
    vtkDataArray* extent = table ? table->GetFieldData()->GetArray(pieceExtentName) : nullptr;
    if (!extent || extent->GetNumberOfValues() != 6)
      continue;
    Piece p{ {}, table, rank };
    for (int k = 0; k < 6; ++k)
      p.extent[k] = static_cast<int>(extent->GetComponent(k, 0));
    pieces.push_back(p);
  }
  if (pieces.empty())
    return false;
  Layout layout;
  std::fill_n(layout.whole, 6, 0);
  layout.whole[0] = layout.whole[2] = VTK_INT_MAX;
  layout.whole[1] = layout.whole[3] = VTK_INT_MIN;
  std::vector<std::array<int, 4>> rectangles;
  for (const Piece& p : pieces)
  {
    const int* e = p.extent;
    for (int axis = 0; axis < 2; ++axis)
    {
      layout.whole[2 * axis] = std::min(layout.whole[2 * axis], e[2 * axis]);
      layout.whole[2 * axis + 1] = std::max(layout.whole[2 * axis + 1], e[2 * axis + 1]);
    }
    rectangles.push_back({ e[0], e[1], e[2], e[3] });
  }
  layout.covered = coversWhole(rectangles, layout.whole);
  const int* w = layout.whole;
  const int ny = w[3] - w[2] + 1;
  // The field data of the root's own piece where it has one (the CRS's WKT travels in
  // no packet), and the whole grid's georeference, from any piece's.
  layout.fieldData = vtkSmartPointer<vtkFieldData>::New();
  layout.fieldData->DeepCopy(
    piece && piece->GetNumberOfPoints() > 0 ? piece->GetFieldData() : pieces[0].table->GetFieldData());
  layout.fieldData->RemoveArray(pieceExtentName);
  terralux::GeoTransform pieceTransform;
  transformOf(pieces[0].table->GetFieldData(), pieceTransform); // packetOf sent only georeferenced pieces
  const int* e0 = pieces[0].extent;
  const int row0 = pieceTransform.firstRasterRow(e0[2] - w[2], e0[3] - w[2], ny);
  setGeoreference(layout.fieldData, pieceTransform.window(-(e0[0] - w[0]), -row0, 1), w[1] - w[0] + 1, ny);
  vtkTable* first = pieces[0].table;
  for (vtkIdType a = 0; a < first->GetNumberOfColumns(); ++a)
    if (auto* model = vtkDataArray::SafeDownCast(first->GetColumn(a)))
      if (std::strcmp(model->GetName(), vtkDataSetAttributes::GhostArrayName()) != 0)
        layout.arrays.push_back(model);
  // A writer's error (a missing array, a full disk) must not leave the other ranks
  // waiting to send: the root takes every array still, and throws at the end.
  std::exception_ptr failure;
  auto guarded = [&failure](const auto& call) {
    if (failure)
      return;
    try
    {
      call();
    }
    catch (...)
    {
      failure = std::current_exception();
    }
  };
  guarded([&]() { begin(layout); });

  for (const Piece& p : pieces)
  {
    // The piece's arrays, in its packet's order (ghosts first): the root's own as they
    // are, the others' as they arrive.
    PieceArray current;
    std::copy_n(p.extent, 6, current.extent);
    vtkSmartPointer<vtkDataArray> ghosts;
    for (vtkIdType a = 0; a < p.table->GetNumberOfColumns(); ++a)
    {
      auto* model = vtkDataArray::SafeDownCast(p.table->GetColumn(a));
      vtkSmartPointer<vtkDataArray> values = p.rank == root ? ownArrays[static_cast<std::size_t>(a)] : nullptr;
      if (!values)
      {
        values.TakeReference(model->NewInstance());
        controller->Receive(values, p.rank, valuesTag);
      }
      values->SetName(model->GetName());
      if (std::strcmp(model->GetName(), vtkDataSetAttributes::GhostArrayName()) == 0)
      {
        ghosts = values;
        continue;
      }
      current.ghosts = ghosts;
      current.values = values;
      guarded([&]() { each(current); });
    }
  }
  if (failure)
    std::rethrow_exception(failure);
  return true;
}

void vtkTerrainPieces::RequestedPiece(vtkInformation* info, int extent[6])
{
  info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
  const int pieces = info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    ? info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    : 1;
  if (pieces <= 1 || !info->Has(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT()))
    return;
  vtkInformationIntegerKey* splitKey = static_cast<vtkInformationIntegerKey*>(vtkExtentTranslator::UPDATE_SPLIT_MODE());
  const int splitMode = info->Has(splitKey)
    ? info->Get(splitKey)
    : vtkExtentTranslator::BLOCK_MODE;
  int whole[6];
  std::copy(extent, extent + 6, whole);
  vtkNew<vtkExtentTranslator> translator;
  translator->PieceToExtentThreadSafe(info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()), pieces,
    info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS()), whole, extent, splitMode, 0);
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

// A terrain split into pieces (one per MPI rank, VTK extents of one whole grid): a
// piece cut from the whole, and the pieces assembled on one rank for writers that
// write one file (private to TerraLux::Filters).
#ifndef vtkTerrainPieces_h
#define vtkTerrainPieces_h

#include "vtkSmartPointer.h"

#include <memory>

namespace terralux
{
class WorkSplit;
}
class vtkDataSet;
class vtkImageData;
class vtkMultiProcessController;
class vtkStructuredGrid;

struct vtkTerrainPieces
{
  /// Collective over `controller`: every rank gives its piece (a vtkStructuredGrid with
  /// vtkTerrainSource's georeference field data, or nullptr where it has none). On
  /// `root` returns the whole grid, a vtkImageData over the union of the pieces'
  /// extents with their point arrays (posts no piece has: NaN, and blanked), their
  /// field data and the whole grid's GeoTransform and RasterSize; nullptr elsewhere,
  /// and on root when no rank had a georeferenced piece.
  static vtkSmartPointer<vtkImageData> GatherToRoot(vtkMultiProcessController* controller, vtkDataSet* piece, int root);
  /// Crops a terrain to the piece `extent` (grid indices) and makes its georeference
  /// field data (GeoTransform, RasterSize) describe the piece.
  static void CropToPiece(vtkStructuredGrid* terrain, const int extent[6]);
  /// The global controller's ranks as a terralux::WorkSplit (broadcasts from each
  /// share's rank; each rank's window its piece's posts, `extent`), where the `pieces`
  /// pieces asked for are one per rank and this rank asks for its own, `piece`; null
  /// otherwise (one process, or pieces streamed by one). Collective where it splits.
  static std::unique_ptr<terralux::WorkSplit> SplitAmongRanks(int piece, int pieces, const int extent[6]);
};

#endif

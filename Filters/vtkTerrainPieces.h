// A terrain split into pieces (one per MPI rank, VTK extents of one whole grid): a
// piece cut from the whole, and the pieces sent to one rank for writers that
// write one file (private to TerraLux::Filters).
#ifndef vtkTerrainPieces_h
#define vtkTerrainPieces_h

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkSmartPointer.h"

#include <functional>
#include <memory>
#include <vector>

namespace terralux
{
class WorkSplit;
}
class vtkDataSet;
class vtkInformation;
class vtkMultiProcessController;
class vtkStructuredGrid;

struct vtkTerrainPieces
{
  /// What the root learns of the pieces before their values.
  struct Layout
  {
    int whole[6];                          ///< the union of the pieces' extents
    bool covered = true;                   ///< whether the pieces cover every post of it
    vtkSmartPointer<vtkFieldData> fieldData; ///< a piece's, with the whole's GeoTransform and RasterSize
    std::vector<vtkDataArray*> arrays; ///< the point arrays' names, types and information, no values
  };
  /// One point array of one piece, with the piece's ghosts (null where it has none).
  struct PieceArray
  {
    int extent[6];
    vtkDataArray* ghosts = nullptr;
    vtkDataArray* values = nullptr;
  };
  /// Collective over `controller`: every rank gives its piece (a vtkStructuredGrid with
  /// vtkTerrainSource's georeference field data, or nullptr where it has none). On
  /// `root`, calls `begin` with the layout, then `each` for every point array of every
  /// piece as it arrives (one at a time: the root never holds the whole grid), and
  /// returns true; false elsewhere, and on root when no rank had a georeferenced piece.
  /// What `begin` or `each` throws, the root throws once every piece has arrived.
  static bool SendToRoot(vtkMultiProcessController* controller, vtkDataSet* piece, int root,
    const std::function<void(const Layout&)>& begin, const std::function<void(const PieceArray&)>& each);
  /// Crops a terrain to the piece `extent` (grid indices) and makes its georeference
  /// field data (GeoTransform, RasterSize) describe the piece.
  static void CropToPiece(vtkStructuredGrid* terrain, const int extent[6]);
  /// The extent output `info` will be asked for once its piece is cut from its update
  /// extent (as the streaming pipeline cuts a sub-extent producer's before RequestData):
  /// for a filter's RequestUpdateExtent, which runs before that cut.
  static void RequestedPiece(vtkInformation* info, int extent[6]);
  /// The global controller's ranks as a terralux::WorkSplit (broadcasts from each
  /// share's rank; each rank's window its piece's posts, `extent`), where the `pieces`
  /// pieces asked for are one per rank and this rank asks for its own, `piece`; null
  /// otherwise (one process, or pieces streamed by one). Collective where it splits.
  static std::unique_ptr<terralux::WorkSplit> SplitAmongRanks(int piece, int pieces, const int extent[6]);
};

#endif

/**
 * @class   vtkTerrainSource
 * @brief   Georeferenced terrain from a DEM raster, in local east-north-up metres.
 *
 * vtkTerrainSource reads a digital elevation model with GDAL (GeoTIFF, SRTM .hgt,
 * ESRI ASCII grid, USGS DEM, anything GDAL opens) and places every post in a local
 * east-north-up (ENU) Cartesian frame in metres around a geographic origin: the
 * raster's CRS is brought to WGS84 with GDAL/OSR, then geodetic coordinates go to
 * ECEF and ENU with GeographicLib, so Earth curvature is kept (50 km from the
 * origin, ground at constant ellipsoidal height lies about 196 m below the tangent
 * plane). Rotated geotransforms are honoured. A raster without a CRS is taken as
 * local metres (with a warning): x, y are map coordinates and z the height, all
 * relative to the grid centre.
 *
 * Instead of a file, a vtkImageData height field (one scalar component, spacing in
 * metres, no georeference) may be connected to the optional input port 0, e.g. the
 * output of vtkDEMReader; its points keep the image's x, y and take the scalar as z.
 *
 * The output is a vtkStructuredGrid of dimensions (nx, ny, 1). Grid point (i, j)
 * is raster post (i, ny - 1 - j): i runs along raster columns and j against raster
 * rows, so for a north-up raster j grows northward and cell normals point up. A raster
 * whose geotransform keeps orientation (negative pixel width, south-up rows) keeps its
 * row order instead (grid point (i, j) is post (i, j)), so its cells face up too:
 * any valid geotransform, rotated ones included, gives an upward-facing terrain.
 *
 * Heights beyond [-12000, 10000] m, which no DEM holds, are taken as no data with a
 * warning that counts them. Refused with an error naming the fix, output empty:
 * missing or unreadable files, a band out of range, all posts no data, an empty
 * window, a GeoBounds box that is not one (south >= north, west >= east, NaN, beyond
 * the poles), both a window and a box, a CRS GDAL cannot bring to WGS84, posts that
 * map beyond latitude 90, a NaN origin, a height-field image with NaN or zero spacing.
 * Point data:
 * - `Elevation`: the raster's values (float, or double for Float64/Int32 rasters),
 *   NaN at no-data posts.
 * - vtkGhostType: no-data posts are blanked (HIDDENPOINT), which hides every cell
 *   that touches them; their points sit at the lowest valid height, never at the
 *   file's no-data value.
 *
 * Field data, enough to write results back on the same raster grid:
 * - `GeoOrigin` (latitude, longitude in degrees, height in metres above the WGS84
 *   ellipsoid; one tuple of three components) of the ENU frame (absent for rasters
 *   without a CRS);
 * - `CRS` (WKT of the raster's CRS, empty if none);
 * - `GeoTransform` (6 values, GDAL convention, raster row order) of the output grid:
 *   its pixel (i, row) is centred on grid point (i, ny - 1 - row) (or (i, row) for a
 *   transform that keeps orientation, see above), window and stride included;
 * - `RasterSize` (nx, ny);
 * - `NoDataValue` (the band's no-data value, when it has one);
 * - `LocalOrigin` (map x, y and height of the frame origin, rasters without a CRS).
 *
 * Subsetting is done by GDAL without reading the whole raster: a pixel window, a
 * geographic box, and a stride that keeps every k-th post.
 *
 * Pieces (MPI ranks, streaming): the source produces sub-extents, so a piece request
 * (UPDATE_PIECE_NUMBER, UPDATE_NUMBER_OF_PIECES, ghost levels) reads only that block of
 * the raster. A piece's posts are bit for bit the whole grid's (the frame origin is the
 * whole grid's centre); its ghost posts are marked DUPLICATEPOINT in vtkGhostType; its
 * GeoTransform and RasterSize describe the piece; its no-data posts sit at the lowest
 * valid height of the piece.
 *
 * Output port 1, the far terrain: every FarTerrainStride-th post of output 0's whole
 * grid (the whole window, whatever piece output 0 gives), in output 0's frame, with
 * its own georeference and field data `FarTerrainStride`. vtkHierarchicalRadiosity
 * (SetFarTerrainConnection) sees it beyond its DetailDistance, so that an MPI rank
 * holds output 0's piece at full resolution, with a halo, and not the whole DEM.
 * Read only when something asks for it. Output 0's information carries POST_SPACING(),
 * the least distance between neighbouring posts, for the halo a piece asks for.
 *
 * @warning DEM heights are taken as heights above the WGS84 ellipsoid; geoid
 * undulation (SRTM heights are above EGM96) shifts the whole scene by tens of metres
 * at most, and its variation across a DEM is small.
 *
 * @warning Single-precision points (the default) are good to about 2 mm at 50 km
 * from the origin; use SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION) for
 * exact coordinates over large extents.
 *
 * @sa vtkGeodeticFrame vtkDEMReader vtkStructuredGrid
 */

#ifndef vtkTerrainSource_h
#define vtkTerrainSource_h

#include "TerraLuxSourcesModule.h" // For export macro
#include "vtkSmartPointer.h"            // For ReadElevation
#include "vtkStructuredGridAlgorithm.h"

#include <memory> // For PlaceGrid

class vtkDataArray;
class vtkFieldData;
class vtkInformationDoubleKey;
class vtkImageData;
class vtkStructuredGrid;

namespace terralux
{
struct GeoTransform;
struct GridCentre;
struct GridGeoreference;
struct PixelWindow;
struct RasterInfo;
class TerrainPlacement;
}

class TERRALUXSOURCES_EXPORT vtkTerrainSource : public vtkStructuredGridAlgorithm
{
public:
  static vtkTerrainSource* New();
  vtkTypeMacro(vtkTerrainSource, vtkStructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Set/Get the DEM file: any raster GDAL reads. Ignored when a vtkImageData is
   * connected to input port 0. Default is nullptr.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * Set/Get the raster band holding the heights, numbered from 1. Default is 1.
   */
  vtkSetClampMacro(Band, int, 1, VTK_INT_MAX);
  vtkGetMacro(Band, int);
  ///@}

  ///@{
  /**
   * Set/Get a pixel window of the raster (first column, first row, width, height).
   * A width or height of 0 or less selects the whole raster; a window partly outside
   * the raster is clipped to it (with a warning). Default is (0, 0, 0, 0).
   */
  vtkSetVector4Macro(PixelWindow, int);
  vtkGetVector4Macro(PixelWindow, int);
  ///@}

  ///@{
  /**
   * Set/Get a geographic box (south, north, west, east) in WGS84 degrees; setting it
   * turns UseGeoBounds on. The output covers the raster's pixels that overlap it; it
   * must be a box (south < north in [-90, 90], west < east) that overlaps the raster,
   * else RequestData fails, and it cannot be combined with a PixelWindow. A box may
   * cross the antimeridian (west 179.9, east 180.2) where the raster's longitudes hold
   * it. NaN in it is refused even with UseGeoBounds off. Default is (0, 0, 0, 0).
   */
  virtual void SetGeoBounds(double south, double north, double west, double east);
  virtual void SetGeoBounds(const double bounds[4]);
  vtkGetVector4Macro(GeoBounds, double);
  ///@}

  ///@{
  /**
   * Set/Get whether GeoBounds selects the posts; off reads the whole raster (or the
   * PixelWindow), with a warning if GeoBounds was set to something else than its
   * default. Default is off.
   */
  vtkSetMacro(UseGeoBounds, vtkTypeBool);
  vtkGetMacro(UseGeoBounds, vtkTypeBool);
  vtkBooleanMacro(UseGeoBounds, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Set/Get the stride: every Stride-th post of the window is kept, starting with
   * its first. Default is 1.
   */
  vtkSetClampMacro(Stride, int, 1, VTK_INT_MAX);
  vtkGetMacro(Stride, int);
  ///@}

  ///@{
  /**
   * Set/Get the stride of the far terrain (output port 1) in output 0's posts: it
   * keeps every FarTerrainStride-th post of output 0, starting with its first.
   * Default is 4.
   */
  vtkSetClampMacro(FarTerrainStride, int, 2, VTK_INT_MAX);
  vtkGetMacro(FarTerrainStride, int);
  ///@}

  /**
   * On output 0's information, after RequestInformation (from a raster): the least
   * horizontal distance between neighbouring posts, metres (a lower bound, found at
   * the grid's corners and centre). A filter that needs posts within a distance of
   * its piece grows its request by it.
   */
  static vtkInformationDoubleKey* POST_SPACING();

  ///@{
  /**
   * Set/Get the geographic origin of the ENU frame: latitude, longitude (degrees)
   * and height above the WGS84 ellipsoid (metres). Setting it turns UseGeoOrigin on.
   * Default is (0, 0, 0), unused: the origin is the grid centre at its ground height.
   */
  virtual void SetGeoOrigin(double latitude, double longitude, double height);
  virtual void SetGeoOrigin(const double origin[3]);
  vtkGetVector3Macro(GeoOrigin, double);
  ///@}

  ///@{
  /**
   * Set/Get whether GeoOrigin is the frame origin (on) or the grid centre at its
   * ground height is (off). For a vtkImageData input, turning it on records
   * GeoOrigin as the georeference of the image's local frame. Default is off.
   */
  vtkSetMacro(UseGeoOrigin, vtkTypeBool);
  vtkGetMacro(UseGeoOrigin, vtkTypeBool);
  vtkBooleanMacro(UseGeoOrigin, vtkTypeBool);
  ///@}

  /**
   * Use the grid centre at its ground height as the frame origin (UseGeoOrigin off).
   */
  void SetGeoOriginToGridCenter() { this->SetUseGeoOrigin(0); }

  ///@{
  /**
   * Set/Get the precision of the output points: vtkAlgorithm::SINGLE_PRECISION or
   * vtkAlgorithm::DOUBLE_PRECISION. Default is SINGLE_PRECISION.
   */
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DOUBLE_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

protected:
  vtkTerrainSource();
  ~vtkTerrainSource() override;

  vtkTypeBool ProcessRequest(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName;
  int Band;
  int PixelWindow[4];
  double GeoBounds[4];
  vtkTypeBool UseGeoBounds;
  int Stride;
  int FarTerrainStride;
  double GeoOrigin[3];
  vtkTypeBool UseGeoOrigin;
  int OutputPointsPrecision;

private:
  vtkTerrainSource(const vtkTerrainSource&) = delete;
  void operator=(const vtkTerrainSource&) = delete;

  struct RasterRequest;
  void ResolveRasterRequest(RasterRequest& request); // throws terralux::Error
  double LeastPostSpacing(const RasterRequest& request); // POST_SPACING
  // Reads the posts of `extent` (grid indices within the whole extent; a piece, ghost
  // posts included) with the ghost posts outside `pieceExtent` marked duplicate.
  // `farStride` > 1: output 0's every farStride-th post (the far terrain), still in
  // output 0's frame.
  bool ReadRaster(const int extent[6], const int pieceExtent[6], vtkStructuredGrid* output, int farStride = 1);
  // The heights of `piece`, implausible ones made no data (with a warning); `valid`
  // counts the rest. Null, with an error, when none is valid.
  vtkSmartPointer<vtkDataArray> ReadElevation(const RasterRequest& request, const terralux::PixelWindow& piece,
    int stride, vtkIdType count, std::size_t& valid);
  // Where the grid's posts go (the frame at the whole grid's centre, or GeoOrigin), its
  // origin recorded in field data.
  // `centreTransform`: the transform of the grid whose pixels `centre` counts in.
  std::unique_ptr<terralux::TerrainPlacement> PlaceGrid(const terralux::GridGeoreference& grid,
    const terralux::RasterInfo& info, const terralux::GeoTransform& centreTransform,
    const terralux::GridCentre& centre, vtkFieldData* fieldData);
  bool ConvertHeightField(vtkImageData* input, vtkStructuredGrid* output);
  // Whether the image is a height field that makes finite points (an error if not).
  bool CheckHeightField(vtkImageData* input);
};

#endif

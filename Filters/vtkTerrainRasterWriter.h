/**
 * @class   vtkTerrainRasterWriter
 * @brief   Writes point arrays of a terrain as a multi-band GeoTIFF on the DEM's own grid.
 *
 * vtkTerrainRasterWriter takes a vtkStructuredGrid that carries vtkTerrainSource's
 * georeference (field data `GeoTransform`, `RasterSize`, `CRS`, optional `NoDataValue`),
 * e.g. vtkHierarchicalRadiosity's output 0 for a terrain, and writes chosen point arrays
 * as Float32 bands of a GeoTIFF with exactly that grid, geotransform and CRS, so the
 * result overlays the input DEM in any GIS (gdalinfo, GRASS r.in.gdal, QGIS). Each
 * component of an array is a band; band descriptions are the array names and units are
 * set (W/m^2 for irradiance and radiosity, m for Elevation). Blanked (no-data) posts and
 * NaN values are written as the no-data value.
 *
 * Under MPI (a vtkMultiProcessController with more than one process as the global
 * controller), Write() is collective: each rank asks its input for its own piece (piece
 * = rank), the pieces go to rank 0, which writes the one GeoTIFF of the whole grid. A
 * piece written alone (one process) is a GeoTIFF of that piece.
 *
 * @sa vtkTerrainSource vtkHierarchicalRadiosity
 */

#ifndef vtkTerrainRasterWriter_h
#define vtkTerrainRasterWriter_h

#include "TerraLuxFiltersModule.h" // For export macro
#include "vtkWriter.h"

class vtkDataSet;
class vtkMultiProcessController;
class vtkStructuredGrid;

#include <string> // For std::string
#include <vector> // For std::vector

class TERRALUXFILTERS_EXPORT vtkTerrainRasterWriter : public vtkWriter
{
public:
  static vtkTerrainRasterWriter* New();
  vtkTypeMacro(vtkTerrainRasterWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Set/Get the GeoTIFF file to write. Default is nullptr.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * Choose the point arrays to write, in band order. With none chosen (the default),
   * the radiosity arrays present are written (Irradiance, SunIrradiance, SkyIrradiance,
   * ReflectedIrradiance, Radiosity; vtkSolarIrradiation's GlobalIrradiation,
   * BeamIrradiation, SkyIrradiation, ReflectedIrradiation, OutgoingIrradiation,
   * SunshineDuration; SkyViewFactor), else every numeric point array.
   */
  void AddArrayName(const char* name);
  void RemoveAllArrayNames();
  int GetNumberOfArrayNames() { return static_cast<int>(this->ArrayNames.size()); }
  ///@}

  ///@{
  /**
   * Set/Get whether each piece is written on its own (on): under MPI each rank writes
   * its piece as `<FileName without extension>_<rank>.tif` and rank 0 a GDAL VRT mosaic
   * of them at FileName (give it a .vrt extension), so no rank holds the whole grid and
   * nothing travels but the file names; one process writes its one piece the same way.
   * Off (default): one GeoTIFF at FileName, written by rank 0 under MPI, each rank's
   * piece into its window as it arrives (rank 0 holds one piece's array at a time).
   */
  vtkSetMacro(WritePieces, vtkTypeBool);
  vtkGetMacro(WritePieces, vtkTypeBool);
  vtkBooleanMacro(WritePieces, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Set/Get the no-data value for blanked posts when the input has no `NoDataValue`
   * field data. Default is -9999.
   */
  vtkSetMacro(NoDataValue, double);
  vtkGetMacro(NoDataValue, double);
  ///@}

protected:
  vtkTerrainRasterWriter();
  ~vtkTerrainRasterWriter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  vtkTypeBool ProcessRequest(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  void WriteData() override;
  // Writes a terrain grid as the GeoTIFF `fileName`; throws terralux::Error.
  void WriteGrid(vtkStructuredGrid* grid, const std::string& fileName);
  // WritePieces: each rank's piece as a GeoTIFF, rank 0 the VRT over them (collective).
  void WritePiecesAndMosaic(vtkMultiProcessController* controller);

  char* FileName;
  double NoDataValue;
  vtkTypeBool WritePieces;
  std::vector<std::string> ArrayNames;

private:
  vtkTerrainRasterWriter(const vtkTerrainRasterWriter&) = delete;
  void operator=(const vtkTerrainRasterWriter&) = delete;

  bool Succeeded = false;
};

#endif

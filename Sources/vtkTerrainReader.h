/**
 * @class   vtkTerrainReader
 * @brief   Reads a DEM file as georeferenced terrain: vtkTerrainSource without an input.
 *
 * vtkTerrainReader is vtkTerrainSource's file path alone: the same properties, output
 * and field data (see vtkTerrainSource), with no input port, as a reader is for
 * ParaView's reader factory and for code that expects one (CanReadFile). Use
 * vtkTerrainSource to turn a vtkImageData height field into terrain instead.
 *
 * @sa vtkTerrainSource
 */

#ifndef vtkTerrainReader_h
#define vtkTerrainReader_h

#include "TerraLuxSourcesModule.h" // For export macro
#include "vtkTerrainSource.h"

class TERRALUXSOURCES_EXPORT vtkTerrainReader : public vtkTerrainSource
{
public:
  static vtkTerrainReader* New();
  vtkTypeMacro(vtkTerrainReader, vtkTerrainSource);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * 1 if GDAL opens `fileName` as a raster with at least one band, else 0.
   */
  int CanReadFile(const char* fileName);

protected:
  vtkTerrainReader();
  ~vtkTerrainReader() override = default;

private:
  vtkTerrainReader(const vtkTerrainReader&) = delete;
  void operator=(const vtkTerrainReader&) = delete;
};

#endif

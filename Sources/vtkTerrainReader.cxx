#include "vtkTerrainReader.h"

#include "vtkObjectFactory.h"

#include "raster/dem_raster.h"
#include "base/error.h"

vtkStandardNewMacro(vtkTerrainReader);

//------------------------------------------------------------------------------
vtkTerrainReader::vtkTerrainReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
int vtkTerrainReader::CanReadFile(const char* fileName)
{
  try
  {
    terralux::DemRaster raster(fileName ? fileName : "", 1);
    return 1;
  }
  catch (const terralux::Error&)
  {
    return 0;
  }
}

//------------------------------------------------------------------------------
void vtkTerrainReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

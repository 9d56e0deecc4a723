/**
 * @class   vtkGeodeticFrame
 * @brief   Converts between local east-north-up metres and WGS84 geodetic coordinates.
 *
 * vtkGeodeticFrame is the local Cartesian frame in which TerraLux places a scene:
 * east, north, up in metres, tangent to the WGS84 ellipsoid at a geographic origin
 * (the `GeoOrigin` field data of vtkTerrainSource's output). Conversions go through
 * ECEF (GeographicLib), so they are exact at any distance from the origin, Earth
 * curvature included.
 *
 * @code{.py}
 * frame = vtkGeodeticFrame()
 * frame.SetOriginFromFieldData(terrain.GetOutput())
 * lat, lon, h = frame.LocalToGeodetic(1000.0, 0.0, 0.0)
 * @endcode
 *
 * @sa vtkTerrainSource
 */

#ifndef vtkGeodeticFrame_h
#define vtkGeodeticFrame_h

#include "TerraLuxSourcesModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For std::unique_ptr

class vtkDataObject;

class TERRALUXSOURCES_EXPORT vtkGeodeticFrame : public vtkObject
{
public:
  static vtkGeodeticFrame* New();
  vtkTypeMacro(vtkGeodeticFrame, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Set/Get the origin: latitude, longitude in degrees (WGS84) and height above the
   * ellipsoid in metres. Default is (0, 0, 0).
   */
  vtkSetVector3Macro(Origin, double);
  vtkGetVector3Macro(Origin, double);
  ///@}

  /**
   * Take the origin from a data object's `GeoOrigin` field data (as written by
   * vtkTerrainSource). Returns false, with an error, when it has none.
   */
  bool SetOriginFromFieldData(vtkDataObject* data);

  ///@{
  /**
   * Local (east, north, up) metres to (latitude, longitude, height). The array form
   * returns false, with an error and NaN output, when the origin is invalid.
   */
  bool LocalToGeodetic(const double local[3], double geodetic[3]);
  double* LocalToGeodetic(double east, double north, double up) VTK_SIZEHINT(3);
  ///@}

  ///@{
  /**
   * (latitude, longitude, height) to local (east, north, up) metres.
   */
  bool GeodeticToLocal(const double geodetic[3], double local[3]);
  double* GeodeticToLocal(double latitude, double longitude, double height) VTK_SIZEHINT(3);
  ///@}

protected:
  vtkGeodeticFrame();
  ~vtkGeodeticFrame() override;

  double Origin[3];

private:
  vtkGeodeticFrame(const vtkGeodeticFrame&) = delete;
  void operator=(const vtkGeodeticFrame&) = delete;

  struct Internals;
  bool UpdateFrame();
  std::unique_ptr<Internals> Internal;
  double Result[3];
};

#endif

// The field-data contract of the TerraLux adapters (not wrapped): each key that one
// class writes and another reads, named once (as vtkDataSetAttributes::GhostArrayName()
// names the ghost array), and typed readers and writers of small double arrays.
#ifndef vtkTerraLuxFieldData_h
#define vtkTerraLuxFieldData_h

class vtkDataObject;
class vtkFieldData;
class vtkInformationVector;

struct vtkTerraLuxFieldData
{
  ///@{
  /// vtkTerrainSource's georeference: GeoOrigin (latitude and longitude in degrees, height
  /// in m: one tuple of 3), GeoTransform (GDAL's 6 coefficients of the piece's posts),
  /// RasterSize (columns and rows of the whole raster), CRS (WKT, a string array),
  /// NoDataValue (the raster's, where it has one).
  static const char* GeoOriginName() { return "GeoOrigin"; }
  static const char* GeoTransformName() { return "GeoTransform"; }
  static const char* RasterSizeName() { return "RasterSize"; }
  static const char* CRSName() { return "CRS"; }
  static const char* NoDataValueName() { return "NoDataValue"; }
  ///@}
  /// vtkTerrainSource's far terrain (output 1): how many of output 0's posts apart its
  /// posts are (one value).
  static const char* FarTerrainStrideName() { return "FarTerrainStride"; }
  /// vtkSkySource's radiance map: the cell array of each cell's mean radiance (W/m^2/sr).
  static const char* RadianceName() { return "Radiance"; }
  ///@{
  /// vtkSunSource's sun (also on vtkSolarIrradiation's output, one value a step):
  /// SunDirection (unit vector toward the sun in the local frame: one tuple of 3),
  /// SunZenith and SunAzimuth (degrees, azimuth clockwise from north), and the
  /// irradiances in W/m^2.
  static const char* SunDirectionName() { return "SunDirection"; }
  static const char* SunZenithName() { return "SunZenith"; }
  static const char* SunAzimuthName() { return "SunAzimuth"; }
  static const char* SunNormalIrradianceName() { return "SunNormalIrradiance"; }
  static const char* DiffuseHorizontalIrradianceName() { return "DiffuseHorizontalIrradiance"; }
  static const char* ExtraterrestrialIrradianceName() { return "ExtraterrestrialIrradiance"; }
  ///@}

  /// The GeoOrigin of `data` (latitude, longitude, height); false if it has none.
  static bool GetGeoOrigin(vtkDataObject* data, double place[3])
  {
    return GetVector(data, GeoOriginName(), place, 3);
  }

  /// Adds (or replaces) a double array of `count` values (one component each).
  static void AddVector(vtkFieldData* fieldData, const char* name, const double* values, int count);
  /// Adds (or replaces) a double array of one tuple of `components` values: a point
  /// or a direction (GeoOrigin, SunDirection), so that GetTuple3(0) reads it.
  static void AddTuple(vtkFieldData* fieldData, const char* name, const double* values, int components);
  static void AddValue(vtkFieldData* fieldData, const char* name, double value)
  {
    AddVector(fieldData, name, &value, 1);
  }
  /// Reads exactly `count` finite values of a numeric field array, in either layout
  /// (count tuples, or one tuple of count components); false if absent, of another
  /// size, or not finite.
  static bool GetVector(vtkDataObject* data, const char* name, double* values, int count);

  /// Asks every input for all of it (piece 0 of 1, no ghost levels, a structured
  /// input's whole extent): for algorithms whose outputs' pieces and extents say nothing
  /// about what they need from their inputs.
  static void RequestWholeInputs(vtkInformationVector** inputVector, int ports);
};

#endif

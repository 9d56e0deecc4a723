// Field-data helpers shared by the TerraLux adapters (not wrapped): small named
// double arrays such as `GeoOrigin` or `SunZenith`.
#ifndef vtkTerraLuxFieldData_h
#define vtkTerraLuxFieldData_h

class vtkDataObject;
class vtkFieldData;
class vtkInformationVector;

struct vtkTerraLuxFieldData
{
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

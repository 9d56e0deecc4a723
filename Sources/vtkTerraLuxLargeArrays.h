// Large data arrays on huge pages (not wrapped): the terrain's posts and elevations, the
// radiosity outputs. Their pages are faulted in where first written; at 2 MiB a page
// instead of 4 KiB, a few hundred faults instead of tens of thousands a 1025^2 grid
// (base/large_arrays.h).
#ifndef vtkTerraLuxLargeArrays_h
#define vtkTerraLuxLargeArrays_h

#include "vtkType.h"

class vtkDataArray;

struct vtkTerraLuxLargeArrays
{
  /// Sizes `array` (its components set) to `tuples` tuples, their values unset: as
  /// SetNumberOfTuples, in memory advised as huge pages where it is large.
  static void Allocate(vtkDataArray* array, vtkIdType tuples);
};

#endif

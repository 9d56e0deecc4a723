#include "vtkTerraLuxLargeArrays.h"

#include "vtkDataArray.h"

#include "base/large_arrays.h"

void vtkTerraLuxLargeArrays::Allocate(vtkDataArray* array, vtkIdType tuples)
{
  const vtkIdType values = tuples * array->GetNumberOfComponents();
  const std::size_t bytes = static_cast<std::size_t>(values) * array->GetDataTypeSize();
  if (bytes < terralux::large_arrays::threshold)
  {
    array->SetNumberOfTuples(tuples);
    return;
  }
  // The array frees it (free(): posix_memalign's memory).
  array->SetVoidArray(terralux::large_arrays::allocate(bytes), values, 0, vtkAbstractArray::VTK_DATA_ARRAY_FREE);
}

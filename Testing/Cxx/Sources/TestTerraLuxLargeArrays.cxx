// VTK data arrays on huge pages (vtkTerraLuxLargeArrays): sized as SetNumberOfTuples
// sizes them, aligned to a huge page when large, and still growable and freed by VTK.
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkTerraLuxLargeArrays.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>

TEST(TerraLuxLargeArrays, ALargeArrayIsSizedAlignedAndGrowable)
{
  vtkNew<vtkFloatArray> points;
  points->SetNumberOfComponents(3);
  const vtkIdType tuples = 1 << 20; // 12 MiB
  vtkTerraLuxLargeArrays::Allocate(points, tuples);
  ASSERT_EQ(points->GetNumberOfTuples(), tuples);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(points->GetPointer(0)) % (2u << 20), 0u);
  for (vtkIdType k = 0; k < tuples; ++k)
    points->SetTypedTuple(k, std::array<float, 3>{ float(k), 1.0f, 2.0f }.data());
  const float extra[3] = { -1.0f, -2.0f, -3.0f };
  points->InsertNextTypedTuple(extra); // VTK reallocates the memory it was given
  EXPECT_EQ(points->GetNumberOfTuples(), tuples + 1);
  EXPECT_EQ(points->GetComponent(tuples - 1, 0), float(tuples - 1));
  EXPECT_EQ(points->GetComponent(tuples, 2), -3.0f);
  vtkNew<vtkFloatArray> copy;
  copy->DeepCopy(points);
  EXPECT_EQ(copy->GetComponent(12345, 0), 12345.0f);
}

TEST(TerraLuxLargeArrays, ASmallArrayIsSizedAsUsual)
{
  vtkNew<vtkDoubleArray> values;
  values->SetNumberOfComponents(2);
  vtkTerraLuxLargeArrays::Allocate(values, 10);
  EXPECT_EQ(values->GetNumberOfTuples(), 10);
  values->SetComponent(9, 1, 4.5);
  EXPECT_EQ(values->GetComponent(9, 1), 4.5);
}

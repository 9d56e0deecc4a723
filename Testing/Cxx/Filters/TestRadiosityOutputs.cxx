// vtkRadiosityOutputs: the point arrays users read, on closed boxes and planes.
#include "vtk_test_support.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkHierarchicalRadiosity.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRadiosityOutputs.h"
#include "vtkSOADataArrayTemplate.h"
#include "vtkSkySource.h"
#include "vtkSunSource.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using terralux_test::fieldValue;
using terralux_test::MessageCatcher;
using terralux_test::runPipeline;

TEST(RadiosityOutputs, FillWithNaNReachesEveryValueOfEveryRealArray)
{
  // Output arrays and the GeoTIFF writer's whole-grid bands start as "not computed".
  vtkNew<vtkDoubleArray> doubles;
  vtkNew<vtkFloatArray> floats;
  vtkNew<vtkSOADataArrayTemplate<float>> structOfArrays; // not VTK's usual layout
  for (vtkDataArray* array : std::initializer_list<vtkDataArray*>{ doubles, floats, structOfArrays })
  {
    array->SetNumberOfComponents(3);
    array->SetNumberOfTuples(100003);
    array->Fill(1.0);
    vtkRadiosityOutputs::FillWithNaN(array);
    vtkIdType notNaN = 0;
    for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
      for (int c = 0; c < 3; ++c)
        notNaN += !std::isnan(array->GetComponent(t, c));
    EXPECT_EQ(notNaN, 0) << array->GetClassName();
  }
  vtkRadiosityOutputs::FillWithNaN(nullptr); // nothing to fill
}

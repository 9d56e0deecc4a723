// Uses both installed layers: the VTK source and the VTK-free engine.
#include <terralux/engine/geodesy/local_frame.h>
#include <terralux/vtkHierarchicalRadiosity.h>
#include <terralux/vtkTerrainSource.h>

#include <vtkNew.h>
#include <vtkStructuredGrid.h>

#include <cmath>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: terralux_consumer DEM\n";
    return 2;
  }
  vtkNew<vtkTerrainSource> terrain;
  terrain->SetFileName(argv[1]);
  terrain->Update();
  int dims[3];
  terrain->GetOutput()->GetDimensions(dims);
  vtkNew<vtkHierarchicalRadiosity> radiosity; // the filters module links too
  radiosity->SetInputConnection(terrain->GetOutputPort());
  const terralux::LocalFrame frame({ 45.0, 7.0, 0.0 });
  const terralux::LocalPoint up = frame.toLocal({ 45.0, 7.0, 10.0 });
  std::cout << "dimensions " << dims[0] << " " << dims[1] << " " << dims[2] << " up " << up[2] << "\n";
  return (dims[0] > 0 && std::abs(up[2] - 10.0) < 1e-9) ? 0 : 1;
}

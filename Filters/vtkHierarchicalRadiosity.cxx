#include "vtkHierarchicalRadiosity.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkRadiosityScene.h"

vtkStandardNewMacro(vtkHierarchicalRadiosity);

//------------------------------------------------------------------------------
vtkHierarchicalRadiosity::vtkHierarchicalRadiosity()
  : vtkRadiosityFilter(3, FAR_TERRAIN_PORT)
{
}

//------------------------------------------------------------------------------
vtkHierarchicalRadiosity::~vtkHierarchicalRadiosity() = default;

//------------------------------------------------------------------------------
int vtkHierarchicalRadiosity::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port != LIGHTS_PORT)
    return this->Superclass::FillInputPortInformation(port, info);
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkHierarchicalRadiosity::AddLights(vtkInformationVector** inputVector, vtkRadiosityScene& scene)
{
  vtkInformationVector* lights = inputVector[LIGHTS_PORT];
  for (int k = 0; k < lights->GetNumberOfInformationObjects(); ++k)
    scene.AddLight(lights->GetInformationObject(k)->Get(vtkDataObject::DATA_OBJECT()));
  return scene.Sky || !scene.Suns.empty();
}

//------------------------------------------------------------------------------
void vtkHierarchicalRadiosity::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Lights: " << this->GetNumberOfInputConnections(LIGHTS_PORT) << " connection(s)\n";
}

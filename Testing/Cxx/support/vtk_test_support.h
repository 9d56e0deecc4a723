#pragma once
// Test support for the VTK adapters: run a pipeline and catch what it reports.

#include "vtkAlgorithm.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkReverseSense.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleFilter.h"

#include <cmath>
#include <string>

namespace terralux_test
{
/// Records error and warning messages of an algorithm and its executive.
class MessageCatcher : public vtkCommand
{
public:
  static MessageCatcher* New() { return new MessageCatcher; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const std::string text = data ? static_cast<const char*>(data) : "";
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings) += text + "\n";
  }
  std::string Errors;
  std::string Warnings;
};

/// Runs the algorithm; returns the executive's status (0 when RequestData failed).
/// Error and warning messages land in `messages` instead of the terminal.
/// Value k of field array `name` of `data`, whether the array holds tuples of one value
/// or one tuple of several (GeoOrigin); NaN if there is no such array.
inline double fieldValue(vtkDataObject* data, const char* name, int k = 0)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array ? array->GetComponent(k / array->GetNumberOfComponents(), k % array->GetNumberOfComponents()) : NAN;
}

inline int runPipeline(vtkAlgorithm* algorithm, MessageCatcher* messages)
{
  const unsigned long a = algorithm->AddObserver(vtkCommand::ErrorEvent, messages);
  const unsigned long b = algorithm->AddObserver(vtkCommand::WarningEvent, messages);
  const unsigned long c = algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, messages);
  const int status = algorithm->GetExecutive()->Update();
  algorithm->RemoveObserver(a);
  algorithm->RemoveObserver(b);
  algorithm->GetExecutive()->RemoveObserver(c);
  return status;
}
/// A closed box of inward faces from the outward faces of `source` (vtkCubeSource,
/// vtkTessellatedBoxSource), triangulated, with cell array Emission: under reflectance
/// rho its radiosity is emission / (1 - rho) everywhere.
inline vtkSmartPointer<vtkPolyData> inwardBox(vtkAlgorithm* source, double emission)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkReverseSense> inward;
  inward->SetInputConnection(triangles->GetOutputPort());
  inward->ReverseCellsOn();
  inward->ReverseNormalsOn();
  inward->Update();
  auto box = vtkSmartPointer<vtkPolyData>::New();
  box->DeepCopy(inward->GetOutput());
  vtkNew<vtkDoubleArray> array;
  array->SetName("Emission");
  array->SetNumberOfTuples(box->GetNumberOfCells());
  array->Fill(emission);
  box->GetCellData()->AddArray(array);
  return box;
}
} // namespace terralux_test

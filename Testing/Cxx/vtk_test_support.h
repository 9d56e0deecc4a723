#pragma once
// Test support for the VTK adapters: run a pipeline and catch what it reports.

#include "vtkAlgorithm.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkSmartPointer.h"

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
} // namespace terralux_test

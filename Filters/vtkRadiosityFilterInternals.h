// vtkRadiosityFilter's private pieces shared by its two source files
// (vtkRadiosityFilter.cxx: parameters and pipeline passes; vtkRadiosityFilterSolve.cxx:
// the solve, the kept solver and the outputs).
#ifndef vtkRadiosityFilterInternals_h
#define vtkRadiosityFilterInternals_h

#include "vtkRadiosityFilter.h"
#include "vtkRadiosityScene.h"

#include "solver/solver.h"

#include <memory>

struct vtkRadiosityFilter::KeptSolver
{
  std::unique_ptr<vtkRadiosityScene> GeometryScene; // the grids its rays were built on
  std::unique_ptr<vtkRadiosityScene> SolverScene;   // its elements', when not the same
  // Declared last: freed before the grids it shares.
  std::unique_ptr<terralux::HierarchicalRadiosity> Solver;
};


#endif

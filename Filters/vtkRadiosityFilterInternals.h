// vtkRadiosityFilter's private pieces shared by its two source files
// (vtkRadiosityFilter.cxx: parameters and pipeline passes; vtkRadiosityFilterSolve.cxx:
// the solve, the kept solver and the outputs).
#ifndef vtkRadiosityFilterInternals_h
#define vtkRadiosityFilterInternals_h

#include "vtkRadiosityFilter.h"
#include "vtkRadiosityScene.h"

#include "solver/solver.h"

#include <memory>

// A solver kept between updates (ReuseGeometry) with the scenes whose grids its
// elements and geometry point into; it alone owns them, and frees the solver first.
struct vtkRadiosityFilter::KeptSolver
{
  /// `geometryScene`: the grids the geometry's rays were built on; `solverScene`: the
  /// elements' grids when not the same (null otherwise).
  KeptSolver(std::unique_ptr<terralux::HierarchicalRadiosity> solver,
    std::unique_ptr<vtkRadiosityScene> geometryScene, std::unique_ptr<vtkRadiosityScene> solverScene)
    : GeometryScene(std::move(geometryScene))
    , SolverScene(std::move(solverScene))
    , Solver(std::move(solver))
  {
  }
  ~KeptSolver() { this->Solver.reset(); }
  KeptSolver(const KeptSolver&) = delete;
  KeptSolver& operator=(const KeptSolver&) = delete;

  std::unique_ptr<vtkRadiosityScene> GeometryScene;
  std::unique_ptr<vtkRadiosityScene> SolverScene;
  std::unique_ptr<terralux::HierarchicalRadiosity> Solver;
};


#endif

// vtkRadiosityFilter's solve: the kept solver (ReuseGeometry), the hierarchy every
// rank solves alike, the engine's evaluation, and the outputs.
#include "vtkRadiosityFilter.h"
#include "vtkRadiosityFilterInternals.h"

#include "vtkCompositeDataSet.h"
#include "vtkCompositeDataIterator.h"
#include "vtkDataObjectTree.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkRadiosityOutputs.h"
#include "vtkRadiosityScene.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStructuredGrid.h"
#include "vtkTerraLuxFieldData.h"
#include "vtkTerrainPieces.h"
#include "vtkTerrainSource.h"

#include "base/error.h"
#include "base/finite_parameters.h"
#include "visibility/scene_geometry.h"
#include "evaluation/point_evaluator.h"
#include "solver/solver.h"
#include "solver/tuning.h"
#include "visibility/visibility.h"
#include "parallel/terrain_window.h"
#include "parallel/work_split.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <string>
#include <vector>

namespace
{
class FilterProgress : public terralux::RadiosityProgress
{
public:
  explicit FilterProgress(vtkRadiosityFilter* filter)
    : Filter(filter)
  {
  }
  bool report(double fraction) override
  {
    this->Filter->UpdateProgress(0.1 + 0.8 * fraction);
    return !this->Filter->GetAbortExecute();
  }

private:
  vtkRadiosityFilter* Filter;
};
// Output 0: the inputs, same points and cells and the same composite structure (several
// connections: a multiblock of them), with the point arrays; a terrain piece's posts
// only when `pieceExtent` is given.
void addPointArrays(vtkInformationVector* geometry, const terralux::PointEvaluator& evaluator,
  const vtkRadiosityScene& scene, vtkRadiosityOutputs::PointOptions pointOptions, const int* pieceExtent,
  vtkDataObject* output)
{
  int index = 0;
  auto withResults = [&](vtkDataSet* input) {
    vtkSmartPointer<vtkDataSet> copy;
    copy.TakeReference(input->NewInstance());
    copy->ShallowCopy(input);
    vtkRadiosityOutputs::AddPointArrays(evaluator, scene, index++, pointOptions, copy);
    return copy;
  };
  auto copyComposite = [&](vtkCompositeDataSet* input) {
    vtkSmartPointer<vtkCompositeDataSet> copy;
    copy.TakeReference(input->NewInstance());
    copy->CopyStructure(input);
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(input->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
      if (auto* dataSet = vtkDataSet::SafeDownCast(it->GetCurrentDataObject()))
        copy->SetDataSet(it, withResults(dataSet));
    return copy;
  };
  const int connections = geometry->GetNumberOfInformationObjects();
  auto inputAt = [&](int k) { return geometry->GetInformationObject(k)->Get(vtkDataObject::DATA_OBJECT()); };
  if (connections == 1 && vtkCompositeDataSet::SafeDownCast(inputAt(0)))
  {
    output->ShallowCopy(copyComposite(vtkCompositeDataSet::SafeDownCast(inputAt(0))));
  }
  else if (auto* multiblock = vtkMultiBlockDataSet::SafeDownCast(output))
  {
    multiblock->SetNumberOfBlocks(static_cast<unsigned int>(connections));
    for (int k = 0; k < connections; ++k)
    {
      vtkDataObject* input = inputAt(k);
      if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
        multiblock->SetBlock(static_cast<unsigned int>(k), copyComposite(composite));
      else if (auto* dataSet = vtkDataSet::SafeDownCast(input))
        multiblock->SetBlock(static_cast<unsigned int>(k), withResults(dataSet));
    }
  }
  else
  {
    auto* dataSet = vtkDataSet::SafeDownCast(output);
    dataSet->ShallowCopy(scene.Inputs[0].data);
    // Only the piece's posts; a terrain's piece cropped first, so that its arrays take
    // the piece's memory (each rank's share of the whole grid's).
    const bool cropFirst = pieceExtent && scene.Inputs[0].terrain >= 0;
    if (pieceExtent)
    {
      // The piece's posts in the input's grid (a window of the whole, with a far terrain).
      int extent[6] = { 0, 0, 0, 0, 0, 0 };
      if (auto* grid = vtkStructuredGrid::SafeDownCast(scene.Inputs[0].data))
        grid->GetExtent(extent);
      for (int k = 0; k < 4; ++k)
        pointOptions.posts[k] = pieceExtent[k] - extent[k - k % 2];
    }
    if (cropFirst)
      vtkTerrainPieces::CropToPiece(vtkStructuredGrid::SafeDownCast(dataSet), pieceExtent);
    pointOptions.croppedToPosts = cropFirst;
    vtkRadiosityOutputs::AddPointArrays(evaluator, scene, 0, pointOptions, dataSet);
    if (pieceExtent && !cropFirst)
      vtkTerrainPieces::CropToPiece(vtkStructuredGrid::SafeDownCast(dataSet), pieceExtent);
  }
}

// Field data: sizes, rays and seconds per phase, so a user sees where the time went.
void addStatistics(const terralux::HierarchicalRadiosity& solver, const vtkRadiosityScene& scene,
  const terralux::EvaluationStatistics& evaluation, double pointsSeconds, vtkFieldData* fieldData)
{
  const terralux::RadiosityStatistics& stats = solver.statistics();
  auto addValue = [&](const char* name, double value) { vtkRadiosityOutputs::AddFieldValue(fieldData, name, value); };
  addValue("Elements", static_cast<double>(stats.elements));
  addValue("Links", static_cast<double>(stats.links));
  addValue("Rays", static_cast<double>(solver.raysCast())); // the solve's and the points'
  addValue("Iterations", stats.iterations);
  addValue("Residual", stats.residual);
  addValue("DegeneratePolygons", static_cast<double>(solver.degeneratePolygons()));
  addValue("SkippedCells", static_cast<double>(scene.SkippedCells)); // vertices, lines: no area
  addValue("SecondsHierarchyBuild", stats.secondsHierarchyBuild);
  addValue("SecondsVisibilityBuild", stats.secondsVisibilityBuild);
  addValue("SecondsRefine", stats.secondsRefine);
  addValue("SecondsGather", stats.secondsGather);
  addValue("SecondsPushPull", stats.secondsPushPull);
  addValue("SecondsHorizons", evaluation.horizonsSeconds);
  addValue("HorizonAzimuths", evaluation.horizonAzimuths);
  addValue("HorizonRefinedPosts", static_cast<double>(evaluation.horizonRefinedPosts));
  addValue("SecondsPoints", pointsSeconds); // the lattice's gathers included
  addValue("SecondsLattice", evaluation.latticeSeconds);
  addValue("RaysRefine", static_cast<double>(stats.raysRefine));
  addValue("RaysPushPull", static_cast<double>(stats.raysPushPull));
  const double pointsRays = static_cast<double>(solver.raysCast() - stats.rays);
  addValue("RaysPoints", pointsRays);
  addValue("RaysLattice", static_cast<double>(evaluation.latticeRays));
  // Where the work went, per point the outputs read (a terrain's posts).
  const double points = static_cast<double>(std::max<std::size_t>(1, solver.pointCount()));
  addValue("RaysPerPoint", pointsRays / points);
  addValue("ElementsPerPoint", static_cast<double>(stats.elements) / points);
}

} // namespace

//------------------------------------------------------------------------------
terralux::HierarchicalRadiosity& vtkRadiosityFilter::PrepareSolver(std::unique_ptr<vtkRadiosityScene>& scene)
{
  terralux::RadiosityOptions options;
  options.errorTolerance =
    terralux::Tuning::hierarchyTolerance(this->ErrorTolerance, this->TargetError, this->EvaluateAtPoints != 0);
  options.minimumElementArea = this->MinimumElementArea;
  options.visibilitySamples = this->VisibilitySamples;
  options.gatherSamples = this->MaximumGatherRays;
  options.targetError = this->TargetError;
  options.targetErrorFloor = this->GetEffectiveTargetErrorFloor();
  options.randomSeed = static_cast<std::uint64_t>(this->RandomSeed);
  options.gatherDetailDistance = this->DetailDistance;
  options.farTerrainStride = this->FarTerrainStride;
  options.skyFromHorizons = this->SkyFromHorizons != 0;
  options.maximumIterations = this->MaximumIterations;
  options.convergenceTolerance = this->ConvergenceTolerance;
  options.maximumElements = static_cast<std::size_t>(this->MaximumNumberOfElements);
  std::unique_ptr<KeptSolver>& kept = this->Kept;
  if (!this->ReuseGeometry)
    kept.reset(); // turned off since the last update
  if (kept && kept->Solver->serves(scene->Scene, options))
  {
    // The same scene as the last update's: only the lights are new. The solver's grids
    // stay the kept scene's, equal to this one's.
    kept->Solver->clearSources();
    return *kept->Solver;
  }
  // A new hierarchy, over the kept rays and horizons if the shape is the same.
  std::shared_ptr<terralux::SceneGeometry> geometry;
  std::unique_ptr<vtkRadiosityScene> geometryScene;
  if (kept && kept->Solver->geometry()->sameShape(scene->Scene, options.farSight()))
  {
    geometry = kept->Solver->geometry();
    geometryScene = std::move(kept->GeometryScene);
  }
  kept.reset(); // the old solver, and a geometry of another shape, freed first
  auto solver = std::make_unique<terralux::HierarchicalRadiosity>(scene->Scene, options, geometry);
  // The scenes it shares grids with move here; the caller's references stay valid.
  if (geometryScene)
    kept = std::make_unique<KeptSolver>(std::move(solver), std::move(geometryScene), std::move(scene));
  else
    kept = std::make_unique<KeptSolver>(std::move(solver), std::move(scene), nullptr);
  return *kept->Solver;
}

//------------------------------------------------------------------------------
void vtkRadiosityFilter::ReleaseSolution()
{
  if (this->Kept && this->ReuseGeometry)
    this->Kept->Solver->clearSources(); // its sky belongs to a scene that ends with the update
  else
    this->Kept.reset();
}

//------------------------------------------------------------------------------
bool vtkRadiosityFilter::SolveHierarchy(vtkInformationVector** inputVector, Hierarchy& hierarchy)
{
  hierarchy.OwnScene = this->BuildScene(inputVector);
  hierarchy.Scene = hierarchy.OwnScene.get();
  if (this->GetAbortExecute()) // asked while the lights were made (vtkSolarIrradiation's steps)
    return false;
  terralux::HierarchicalRadiosity& solver = *(hierarchy.Solver = &this->PrepareSolver(hierarchy.OwnScene));
  if (solver.degeneratePolygons() > 0)
  {
    vtkWarningMacro("Skipped " << solver.degeneratePolygons() << " degenerate polygon(s) with zero area.");
  }
  if (this->FarTerrainStride > 1 && !solver.seesFarTerrain() &&
    !hierarchy.Scene->Scene.farTerrain.grid)
  {
    vtkWarningMacro("FarTerrainStride " << this->FarTerrainStride << " is ignored: it needs a DetailDistance > 0 "
      "and a scene of one terrain alone (this one has " << hierarchy.Scene->Scene.terrains.size()
      << " terrain(s) and " << hierarchy.Scene->Scene.polygons.size()
      << " polygon(s)); rays see the full resolution everywhere.");
  }
  for (const vtkRadiosityScene::SunLight& sun : hierarchy.Scene->Suns)
  {
    solver.addSun(sun.direction, sun.irradiance, sun.hours);
  }
  solver.setSky(hierarchy.Scene->Sky.get());
  this->UpdateProgress(0.1);
  FilterProgress progress(this);
  return solver.solve(&progress);
}

//------------------------------------------------------------------------------
int vtkRadiosityFilter::Solve(vtkInformationVector** inputVector, const PieceRequest& piece,
  vtkDataObject* output, vtkPolyData* leafMesh, vtkPolyData* links)
{
  Hierarchy hierarchy; // its scene outlives the kept solver's hold on its lights
  // However the update ends, the kept solver lets go of its lights and solution.
  struct Release
  {
    vtkRadiosityFilter* Filter;
    ~Release() { this->Filter->ReleaseSolution(); }
  } release{ this };
  // Ranks that each evaluate their piece of one terrain split what all of them need at
  // every post (horizons, posts' skies, the lattice), each computing its share.
  // A terrain window with its far terrain computes all it needs itself: no split.
  const bool window = this->UsesFarTerrainInput(inputVector);
  const std::unique_ptr<terralux::WorkSplit> split = piece.extent && !window
    ? vtkTerrainPieces::SplitAmongRanks(piece.piece, piece.pieces, piece.extent)
    : nullptr;
  bool solved = false;
  std::exception_ptr failure;
  try
  {
    solved = this->SolveHierarchy(inputVector, hierarchy);
  }
  catch (...)
  {
    failure = std::current_exception();
  }
  // Until here each rank worked alone. One that stopped (an error, an abort, out of
  // memory) must not leave the others waiting in the shared steps' broadcasts: all
  // learn it and stop alike.
  const bool everyRankSolved = !split || split->allSucceeded(solved && !failure);
  if (failure)
    std::rethrow_exception(failure);
  if (!solved)
  {
    vtkWarningMacro("Aborted.");
    return 1;
  }
  if (!everyRankSolved)
  {
    vtkErrorMacro("Another MPI rank stopped before the ranks' shared steps (its error or warning says why): "
                  "this rank stops too, with empty outputs.");
    return 0;
  }
  vtkRadiosityScene& scene = *hierarchy.Scene;
  terralux::HierarchicalRadiosity* solver = hierarchy.Solver;
  if (window && piece.extent)
    this->CheckWindowHalo(scene, inputVector[0], piece.extent);
  const terralux::RadiosityStatistics& stats = solver->statistics();
  if (stats.elementBudgetReached)
  {
    vtkWarningMacro("Refinement stopped at MaximumNumberOfElements ("
      << this->MaximumNumberOfElements << " elements, or four times as many links): the solution is coarser "
      << "than ErrorTolerance "
      << this->ErrorTolerance << " asks. Raise ErrorTolerance or MaximumNumberOfElements.");
  }
  if (!stats.converged)
  {
    vtkWarningMacro("Radiosity did not converge in MaximumIterations (" << this->MaximumIterations
      << "): the estimated remaining change of radiosity is " << stats.residual
      << " of the largest, above ConvergenceTolerance " << this->ConvergenceTolerance
      << ". Raise MaximumIterations.");
  }

  const bool hornNormals = this->PostNormals == HORN_NORMALS;
  terralux::EvaluationPlan plan;
  plan.atPoints = this->EvaluateAtPoints != 0;
  plan.hornNormals = hornNormals;
  plan.split = split.get();
  const terralux::PointEvaluator evaluator(*solver, plan);
  const terralux::EvaluationStatistics& prepared = evaluator.statistics();
  // Output 0: the inputs, same points and cells and the same composite structure,
  // with the point arrays.
  const auto pointsStart = std::chrono::steady_clock::now();
  vtkRadiosityOutputs::PointOptions pointOptions;
  pointOptions.bands = this->NumberOfBands;
  pointOptions.evaluateAtPoints = this->EvaluateAtPoints != 0;
  pointOptions.hornNormals = hornNormals;
  pointOptions.sunshine = scene.SunshineDuration;
  addPointArrays(inputVector[0], evaluator, scene, pointOptions, piece.extent, output);
  const double pointsSeconds =
    prepared.latticeSeconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - pointsStart).count();
  addStatistics(*solver, scene, prepared, pointsSeconds, output->GetFieldData());

  if (piece.withMeshAndLinks)
  {
    vtkRadiosityOutputs::BuildLeafMesh(*solver, scene, this->NumberOfBands, scene.Sky != nullptr, leafMesh);
    vtkRadiosityOutputs::BuildLinks(*solver, links);
  }
  this->FinishOutputs(output, leafMesh);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkRadiosityFilter::CheckWindowHalo(
  const vtkRadiosityScene& scene, vtkInformationVector* geometry, const int* pieceExtent)
{
  // What the piece's posts need, on the posts as they are.
  if (scene.Scene.terrains.size() != 1)
    return;
  vtkInformation* info = geometry->GetInformationObject(0);
  int extent[6], whole[6];
  vtkStructuredGrid::SafeDownCast(info->Get(vtkDataObject::DATA_OBJECT()))->GetExtent(extent);
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  terralux::TerrainWindow::checkHeld(*scene.Scene.terrains.front(), this->DetailDistance,
    { whole[0], whole[1], whole[2], whole[3] }, { extent[0], extent[1], extent[2], extent[3] },
    { pieceExtent[0], pieceExtent[1], pieceExtent[2], pieceExtent[3] });
}

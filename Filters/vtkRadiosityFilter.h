/**
 * @class   vtkRadiosityFilter
 * @brief   Base of TerraLux's radiosity filters: their parameters, geometry and
 * far-terrain inputs, the solve and the outputs.
 *
 * vtkRadiosityFilter turns its geometry input (port 0) into an engine scene, solves it
 * with terralux::HierarchicalRadiosity (hierarchical radiosity with clustering,
 * Daubert et al. 1997) under the lights a subclass gives (AddLights) and writes the
 * outputs: port 0 the input geometry with the point arrays, port 1 the adaptive leaf
 * mesh, port 2 the links. Its parameters are documented here; the ports, arrays and
 * field data in the subclasses, which add the lights: vtkHierarchicalRadiosity (light
 * sources on an input port) and vtkSolarIrradiation (the suns and skies of a time
 * range). Each subclass names its input ports (GEOMETRY_PORT, FAR_TERRAIN_PORT, ...).
 *
 * @sa vtkHierarchicalRadiosity vtkSolarIrradiation
 */

#ifndef vtkRadiosityFilter_h
#define vtkRadiosityFilter_h

#include "TerraLuxFiltersModule.h" // For export macro
#include "vtkDataObjectAlgorithm.h"

#include <memory> // For std::unique_ptr

class vtkPolyData;
class vtkStructuredGrid;
class vtkRadiosityScene;
namespace terralux
{
class HierarchicalRadiosity;
}

class TERRALUXFILTERS_EXPORT vtkRadiosityFilter : public vtkDataObjectAlgorithm
{
public:
  vtkAbstractTypeMacro(vtkRadiosityFilter, vtkDataObjectAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Set/Get the refinement tolerance: a link is refined when the power it carries
   * exceeds this fraction of the power the scene receives, or when its far-field
   * estimate (a cluster, a coarse terrain quad) may leave out more than 5 times this
   * fraction of the scene's mean irradiance at its receiver (the bound each receiver
   * sees). The points' values (EvaluateAtPoints) gather over the leaves at full
   * resolution, so a coarse hierarchy serves them: TargetError sets their accuracy;
   * from TargetError 0.03 up (the knob's coarse end) the hierarchy refines to three
   * times this. Default is 1e-2.
   */
  vtkSetClampMacro(ErrorTolerance, double, 1e-9, 1.0);
  vtkGetMacro(ErrorTolerance, double);
  ///@}

  ///@{
  /**
   * Set/Get the smallest element area in m^2 (0: a millionth of the scene's area).
   * Default is 0.
   */
  vtkSetClampMacro(MinimumElementArea, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MinimumElementArea, double);
  ///@}

  ///@{
  /**
   * Set/Get the visibility rays per link. Default is 4.
   */
  vtkSetClampMacro(VisibilitySamples, int, 1, 1024);
  vtkGetMacro(VisibilitySamples, int);
  ///@}

  ///@{
  /**
   * Set/Get the most rays per point of the final gather that gives, with
   * EvaluateAtPoints on, the sky and the light from surfaces at each point: as many
   * as bring its error within the point's target (TargetError), up to this
   * (docs/tuning.md says how the count is chosen). 0 re-evaluates the
   * hierarchy's links at each point instead (faster, less accurate in rough terrain).
   * Default is 4096.
   */
  vtkSetClampMacro(MaximumGatherRays, int, 0, 1 << 20);
  vtkGetMacro(MaximumGatherRays, int);
  ///@}

  ///@{
  /**
   * Set/Get the error each point's value aims at, with EvaluateAtPoints on: its
   * IrradianceError (an estimate that holds the true error at about 95 % of points)
   * within TargetError x the point's global irradiance, or a floor in W/m^2 where
   * that is more: TargetErrorFloor, or where it is negative (the default, -1)
   * FloorPerTargetError x TargetError, so that TargetError alone moves both (2 W/m^2 at
   * the default, 10 at 0.04). Gather rays, and reads between the posts a terrain gathers
   * first, go where a point's estimate is not yet within it. The speed-accuracy knob:
   * 0.008 (the default) gives 0.2-0.7 % global RMS on the validation's scenes, 0.04
   * (the command's --fast) 2-3 times faster at most 2 % (docs/validation.md). From
   * 0.03 up, a terrain's horizons are found toward 16 azimuths instead of 32 (see
   * SkyFromHorizons): half their time, the sky between azimuths less exact; and the
   * hierarchy refines to three times ErrorTolerance.
   * Defaults are 0.008 and -1 (the floor follows TargetError).
   */
  vtkSetClampMacro(TargetError, double, 1e-6, 1.0);
  vtkGetMacro(TargetError, double);
  vtkSetClampMacro(TargetErrorFloor, double, -1.0, 1e6);
  vtkGetMacro(TargetErrorFloor, double);
  /// The floor a point's aim takes (W/m^2): TargetErrorFloor, or where that is
  /// negative FloorPerTargetError x TargetError.
  double GetEffectiveTargetErrorFloor();
  /// W/m^2 of floor per unit of TargetError where the floor follows it: shaded posts
  /// (a global of about 100 W/m^2 under a low sun) aim at the same 2 % of what they
  /// receive at TargetError 0.008 and at 10 % at 0.04, so that the knob's coarse end
  /// saves their rays too (docs/tuning.md).
  static constexpr double FloorPerTargetError = 250.0;
  ///@}

  ///@{
  /**
   * Set/Get the seed of the Monte-Carlo samples that the points' values draw (their
   * final gathers, with EvaluateAtPoints on): 0, the default, or any other value for
   * another draw of the same estimate. Each seed's values are reproducible, on any
   * number of processes; rerunning with a few seeds shows the sampling noise in a
   * scene's values (IrradianceError bounds it per point).
   */
  vtkSetClampMacro(RandomSeed, int, 0, VTK_INT_MAX);
  vtkGetMacro(RandomSeed, int);
  ///@}

  ///@{
  /**
   * Set/Get the distance (m, horizontally) within which a gather ray's hit on the
   * scene's one terrain reads what its posts found (their skies by their horizons, the
   * suns they prove seen or hidden, the lattice's light from surfaces); a hit farther
   * from the gathering point sends its leaf's light, as a hit on other surfaces does.
   * Under MPI each rank then holds and receives those values only for the posts within
   * this distance of its piece, not the whole grid's: memory and traffic follow the
   * piece. Results do not depend on the number of ranks. 0 (the default): every hit
   * reads its posts, and every rank holds every post's.
   */
  vtkSetClampMacro(DetailDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(DetailDistance, double);
  ///@}

  ///@{
  /**
   * Set/Get the stride of the far terrain: with a DetailDistance, in a scene of one
   * terrain alone, a ray that goes farther than DetailDistance (horizontally) from
   * where it starts sees, beyond it, the terrain's every FarTerrainStride-th post (its
   * last row and column kept), as horizon tools trace far terrain at a coarser
   * resolution: near every point the full resolution decides shadows and what it sees,
   * far away a coarse copy of 1/FarTerrainStride^2 the posts. Horizons stay the full
   * grid's. 1 (the default): the full resolution everywhere.
   */
  vtkSetClampMacro(FarTerrainStride, int, 1, VTK_INT_MAX);
  vtkGetMacro(FarTerrainStride, int);
  ///@}

  ///@{
  /**
   * Set/Get the most gather / push-pull iterations. Default is 30.
   */
  vtkSetClampMacro(MaximumIterations, int, 1, 100000);
  vtkGetMacro(MaximumIterations, int);
  ///@}

  ///@{
  /**
   * Set/Get the most elements refinement may create; links are held to four times
   * as many. A solve that reaches either stops refining, warns, and returns the
   * solution at that size (coarser than ErrorTolerance asks): a guard against
   * tolerances that would outgrow memory (a plane with a box at tolerance 1e-9 stops
   * at 0.5 M elements and 4 M links after 17 s and 1.2 GB). Default is 1,000,000.
   */
  vtkSetClampMacro(MaximumNumberOfElements, vtkIdType, 1000, VTK_ID_MAX);
  vtkGetMacro(MaximumNumberOfElements, vtkIdType);
  ///@}

  ///@{
  /**
   * Set/Get the convergence tolerance: iterations stop when the estimated remaining
   * change of radiosity (the last change over one minus its ratio to the change
   * before, since gathering converges geometrically) falls below this fraction of the
   * largest radiosity. Where that ratio is high and steady (bright, closed scenes),
   * radiosity jumps ahead by the geometric sum. Iterations that stop at
   * MaximumIterations before converging warn with that estimate. Default is 1e-3.
   */
  vtkSetClampMacro(ConvergenceTolerance, double, 0.0, 1.0);
  vtkGetMacro(ConvergenceTolerance, double);
  ///@}

  ///@{
  /**
   * Set/Get the reflectance of cells without a reflectance array, in [0, 1).
   * Default is 0.2.
   */
  vtkSetClampMacro(DefaultReflectance, double, 0.0, 0.999);
  vtkGetMacro(DefaultReflectance, double);
  ///@}

  ///@{
  /**
   * Set/Get the names of the cell arrays holding reflectance (values in [0, 1)) and
   * emitted radiosity (W/m^2, >= 0), 1 or 3 components: input arrays to process 0 and
   * 1 (SetInputArrayToProcess with FIELD_ASSOCIATION_CELLS), named. Default is
   * nullptr: none (DefaultReflectance, no emission); nullptr, "" or "None" (the entry
   * for none in ParaView's array lists) clears it.
   */
  void SetReflectanceArrayName(const char* name) { this->SetCellArrayToProcess(ReflectanceArray, name); }
  const char* GetReflectanceArrayName() { return this->CellArrayToProcess(ReflectanceArray); }
  void SetEmissionArrayName(const char* name) { this->SetCellArrayToProcess(EmissionArray, name); }
  const char* GetEmissionArrayName() { return this->CellArrayToProcess(EmissionArray); }
  ///@}

  ///@{
  /**
   * Set/Get whether output 0's point values are evaluated at each point (a final
   * gather from the point, see MaximumGatherRays; accurate to TargetError) or
   * averaged over the leaf elements around it (smears values over elements, not
   * held to any accuracy target and without IrradianceError: 1.4-2.2 % RMS on steep
   * terrain, reflected light half missing; on terrain patches interpolated from the
   * continuous leaf mesh, direct sun still taken at each post with one ray). For
   * speed, raise TargetError instead. Default is on.
   */
  vtkSetMacro(EvaluateAtPoints, vtkTypeBool);
  vtkGetMacro(EvaluateAtPoints, vtkTypeBool);
  vtkBooleanMacro(EvaluateAtPoints, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Set/Get whether 2-D structured grids (terrains from vtkTerrainSource) enter the
   * hierarchy as terrain patches (paper section 4): parameter ranges of the grid that
   * split into finer posts only where links need it, with visibility against the
   * full-resolution surface through Embree's grid geometry, so time and memory follow
   * the solution's detail rather than the number of posts. Off: two triangles per cell
   * in clusters (the plain path, for comparison). With it on and EvaluateAtPoints off,
   * post values are interpolated from the continuous leaf mesh. Default is on.
   */
  vtkSetMacro(UseTerrainHierarchy, vtkTypeBool);
  vtkGetMacro(UseTerrainHierarchy, vtkTypeBool);
  vtkBooleanMacro(UseTerrainHierarchy, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Set/Get whether, in a scene that is a height field (terrains whose cells all face
   * up, no polygons), the sky each point does not see comes from its horizon toward 32
   * azimuths (16 where TargetError is 0.03 or more), interpolated between them, the sky
   * below it integrated exactly over the sky's cells (as r.horizon and HORAYZON work). With one terrain, the horizons of all
   * its posts are found at once by sweeping lines of posts (exact on its triangles);
   * elsewhere each is bisected with occlusion rays to 0.2 % of its sector's sky.
   * The gather's rays then gather only the light of surfaces, and the sky has no
   * sampling noise (docs/validation.md).
   * Off, or in scenes with buildings or vegetation (where a lower direction can be
   * open under a higher blocked one), occlusion rays drawn by the sky's radiance find
   * the hidden sky.
   * Only with EvaluateAtPoints on. Default is on.
   */
  vtkSetMacro(SkyFromHorizons, vtkTypeBool);
  vtkGetMacro(SkyFromHorizons, vtkTypeBool);
  vtkBooleanMacro(SkyFromHorizons, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Set/Get whether the scene's rays (the Embree scene), its terrain's horizons and the
   * element hierarchy are kept after an update and reused by the next: the rays and
   * horizons while the geometry keeps its shape (when only the lights, materials or
   * solver parameters change: a moving sun, a time step scrubbed in ParaView), the
   * hierarchy also while materials and parameters stay. They are not built again, and
   * the values are the same as those of a fresh filter. Their memory (about 100 bytes a
   * terrain post) stays held between updates; off frees it after each. Default is on.
   */
  vtkSetMacro(ReuseGeometry, vtkTypeBool);
  vtkGetMacro(ReuseGeometry, vtkTypeBool);
  vtkBooleanMacro(ReuseGeometry, vtkTypeBool);
  ///@}

  enum PostNormalType
  {
    AREA_WEIGHTED_NORMALS = 0,
    HORN_NORMALS = 1
  };

  ///@{
  /**
   * Set/Get the normal a terrain post is evaluated with: AREA_WEIGHTED_NORMALS (the
   * area-weighted normal of the six triangles around it, as a mesh's vertex normal) or
   * HORN_NORMALS (Horn's 3 x 3 normal, the convention of GRASS r.slope.aspect and
   * gdaldem slope/aspect, so results line up with slope and aspect maps from GIS
   * tools; posts on the border or next to no data keep the area-weighted one).
   * Default is AREA_WEIGHTED_NORMALS.
   */
  vtkSetClampMacro(PostNormals, int, AREA_WEIGHTED_NORMALS, HORN_NORMALS);
  vtkGetMacro(PostNormals, int);
  void SetPostNormalsToAreaWeighted() { this->SetPostNormals(AREA_WEIGHTED_NORMALS); }
  void SetPostNormalsToHorn() { this->SetPostNormals(HORN_NORMALS); }
  ///@}

  ///@{
  /**
   * Set/Get the number of bands, 1 (broadband) or 3 (RGB). Default is 1.
   */
  vtkSetClampMacro(NumberOfBands, int, 1, 3);
  vtkGetMacro(NumberOfBands, int);
  ///@}

  ///@{
  /**
   * Set or add geometry on input port 0 without a pipeline.
   */
  void SetInputData(vtkDataObject* data) { this->SetInputDataObject(0, data); }
  void AddInputData(vtkDataObject* data) { this->AddInputDataObject(0, data); }
  ///@}

  /**
   * Remove every connection of the geometry port (0), the other ports kept;
   * ParaView's repeatable inputs reset a port with this.
   */
  void RemoveAllGeometryConnections() { this->RemoveAllInputConnections(0); }

  ///@{
  /**
   * Connect the far terrain of a terrain on port 0: vtkTerrainSource's output port 1
   * (its every FarTerrainStride-th post, whole), on the subclass's FAR_TERRAIN_PORT. With a DetailDistance, rays see it beyond DetailDistance and
   * the hierarchy is solved on it (FarTerrainStride is then the source's), and a piece
   * asks port 0 for its posts and a halo only (three DetailDistances and a few posts,
   * from the source's POST_SPACING): memory per rank follows the piece, and results
   * do not depend on the number of ranks. Without a DetailDistance it is ignored.
   */
  void SetFarTerrainConnection(vtkAlgorithmOutput* output);
  void SetFarTerrainData(vtkStructuredGrid* far);
  ///@}

  ///@{
  /**
   * Output 0 (GetOutput()) is the input geometry with the point arrays (its type, or a
   * multiblock); the adaptive leaf mesh is port 1 and the links port 2 (GetOutput(port)
   * as vtkDataObjectAlgorithm gives any of them, or these typed getters).
   */
  vtkPolyData* GetLeafMeshOutput();
  vtkPolyData* GetLinksOutput();
  ///@}

protected:
  // The input arrays to process: reflectance and emission.
  enum
  {
    ReflectanceArray = 0,
    EmissionArray = 1
  };
  void SetCellArrayToProcess(int index, const char* name);
  // The named array to process `index` (nullptr if none: no name, or NoArrayName).
  static constexpr const char* NoArrayName = "None";
  const char* CellArrayToProcess(int index);
  // Throws terralux::Error naming the fix when an array to process is not a cell array.
  void CheckCellArraysToProcess();

  // `inputPorts` in all; the far terrain on `farTerrainPort`.
  vtkRadiosityFilter(int inputPorts, int farTerrainPort);
  ~vtkRadiosityFilter() override;
  const int FarTerrainPort;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  // What of the outputs a piece holds: a terrain's sub-extent (grid indices; nullptr:
  // the whole input), and whether the leaf mesh and the links (piece 0's).
  // The last update's solver (ReuseGeometry): its hierarchy, rays and horizons, with the
  // scenes whose terrain grids they share.
  struct KeptSolver;
  std::unique_ptr<KeptSolver> Kept;
  vtkTypeBool ReuseGeometry;

  struct PieceRequest
  {
    const int* extent;
    bool withMeshAndLinks;
    int piece, pieces; // of output 0 (one per MPI rank: the ranks split the shared work)
  };
  // The engine's scene of the geometry inputs and the lights; throws terralux::Error on
  // bad input.
  std::unique_ptr<vtkRadiosityScene> BuildScene(vtkInformationVector** inputVector);
  // A solver of the scene with this filter's options: the last update's where it serves
  // this scene (same shape, materials and options; ReuseGeometry), else a new one over
  // the kept rays and horizons where the shape is the same, else all new. A new solver
  // is kept, with `scene`, which the filter then owns.
  terralux::HierarchicalRadiosity& PrepareSolver(std::unique_ptr<vtkRadiosityScene>& scene);
  // After an update: the kept solver drops its lights and solution (without
  // ReuseGeometry, the solver itself).
  void ReleaseSolution();
  // The scene, its solver and the hierarchy's solution, which every rank computes alike
  // and alone.
  struct Hierarchy
  {
    std::unique_ptr<vtkRadiosityScene> OwnScene; // where the kept solver did not take it
    vtkRadiosityScene* Scene = nullptr;
    terralux::HierarchicalRadiosity* Solver = nullptr;
  };
  // False where aborted. Throws terralux::Error on bad input.
  bool SolveHierarchy(vtkInformationVector** inputVector, Hierarchy& hierarchy);
  // RequestData's work; throws terralux::Error on bad input.
  int Solve(vtkInformationVector** inputVector, const PieceRequest& piece, vtkDataObject* output,
    vtkPolyData* leafMesh, vtkPolyData* links);
  // The solve's light sources: those on an input port (vtkHierarchicalRadiosity), or a
  // time range's suns and cumulative sky (vtkSolarIrradiation). Throws terralux::Error
  // on bad input; returns false where there is no light at all.
  virtual bool AddLights(vtkInformationVector** inputVector, vtkRadiosityScene& scene) = 0;
  // Last touches to the filled outputs (array names, field data).
  virtual void FinishOutputs(vtkDataObject* output, vtkPolyData* leafMesh);
  // Whether a far terrain is connected and used (a DetailDistance).
  bool UsesFarTerrainInput(vtkInformationVector** inputVector);
  // Throws terralux::Error where the window port 0 gave holds fewer posts around the
  // piece than its values need.
  void CheckWindowHalo(const vtkRadiosityScene& scene, vtkInformationVector* geometry, const int* pieceExtent);

  double ErrorTolerance;
  double MinimumElementArea;
  int VisibilitySamples;
  int MaximumGatherRays;
  double TargetError;
  double TargetErrorFloor;
  int RandomSeed;
  double DetailDistance;
  int FarTerrainStride;
  int MaximumIterations;
  double ConvergenceTolerance;
  vtkIdType MaximumNumberOfElements;
  double DefaultReflectance;
  vtkTypeBool UseTerrainHierarchy;
  vtkTypeBool SkyFromHorizons;
  vtkTypeBool EvaluateAtPoints;
  int NumberOfBands;
  int PostNormals;

private:
  vtkRadiosityFilter(const vtkRadiosityFilter&) = delete;
  void operator=(const vtkRadiosityFilter&) = delete;
};

#endif

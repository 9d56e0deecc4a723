/**
 * @class   vtkHierarchicalRadiosity
 * @brief   Outdoor lighting by hierarchical radiosity with clustering under sun and sky.
 *
 * vtkHierarchicalRadiosity solves the light exchange of a scene lit by the sun and
 * the sky following Daubert, Schirmacher, Sillion & Drettakis (EGWR 1997): a cluster
 * hierarchy over every input surface, the root's self-link plus one link from each
 * external source, BF refinement relative to the scene's incident power, and
 * gather / push-pull iterations until radiosity converges. Visibility is ray cast
 * with Embree against the full-resolution scene.
 *
 * Input port 0 (repeatable): vtkPolyData (triangles, quads, polygons, strips),
 * 2-D vtkStructuredGrid (e.g. vtkTerrainSource output; a terrain: terrain patches of
 * paper section 4 over its visible cells, or with UseTerrainHierarchy off two
 * triangles per cell) or a composite data set of them. Reflectance per cell from the cell
 * array to process 0 (1 or 3 components) or DefaultReflectance; optional emission
 * (radiosity, W/m^2) from the cell array to process 1: SetInputArrayToProcess(0 or 1,
 * 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, name), which ParaView's array lists
 * set, or SetReflectanceArrayName / SetEmissionArrayName, which do the same.
 * Input port 1 (LIGHTS_PORT, optional, repeatable): the light sources, vtkSkySource
 * output 0 (its radiance map) and vtkSunSource output (AddLightConnection). Every
 * source connected counts: several suns add their light, several skies are summed
 * into one sky.
 * Input port 2 (FAR_TERRAIN_PORT, optional): vtkTerrainSource's far terrain
 * (SetFarTerrainConnection).
 *
 * Polygons of more than four points, and concave quads, are ear-clipped into
 * triangles (a fan would cover a notch); self-intersecting ones are refused.
 *
 * Output port 0: the input geometry (same points and cells; one input gives its own type,
 * a composite input a composite of the same structure, null and empty blocks kept;
 * several inputs a vtkMultiBlockDataSet with one block per input) with point data `Irradiance` (global),
 * `SunIrradiance`, `SkyIrradiance`, `ReflectedIrradiance` and `Radiosity` in W/m^2
 * (NumberOfBands components), evaluated at each point (direct sun by one ray from the
 * point, sky and light from surfaces by a final gather from the point over the solved
 * hierarchy, see MaximumGatherRays), so values are not smeared over the elements
 * around it; for a terrain lit
 * by a sky also `SkyViewFactor`, the cosine-weighted fraction of the sky each post sees
 * (1 on open flat ground), as SAGA and GRASS r.skyview report it (NaN at points on no
 * polygon, e.g. blanked no-data posts); with EvaluateAtPoints also `IrradianceError`,
 * each point's estimated error of `Irradiance` (W/m^2, largest band): twice the final
 * gather's standard error plus the light from surfaces its hits read times the
 * hierarchy's relative error, measured by gathering over it (docs/validation.md checks
 * it against the reference); the work goes where it misses TargetError; field
 * data `Elements`, `Links`, `Rays`, `Iterations`, `DegeneratePolygons`, `SkippedCells`
 * (vertex and line cells, and polygons of fewer than 3 points: no area, no light), seconds per
 * phase (`SecondsVisibilityBuild`, `SecondsHorizons` for the horizons of every post,
 * toward `HorizonAzimuths` azimuths: 16 at the knob's coarse end and, below it, where
 * the sky they give errs within every post's target (gentle terrain) or misses it at
 * a few posts, whose horizons toward the other 16 of 32 are then found alone
 * (`HorizonRefinedPosts` of them: rough terrain), else 32, or 64 for a year's suns;
 * `SecondsRefine`, `SecondsGather`, `SecondsPushPull`, `SecondsPoints` for output 0's
 * point values, of which `SecondsLattice` for the lattice of posts gathered first) and
 * rays per phase (`RaysRefine`, `RaysPushPull` for gather and push-pull, `RaysPoints`,
 * of which `RaysLattice`), and where the work went per point of output 0 (a terrain's
 * posts): `RaysPerPoint` (of `RaysPoints`) and `ElementsPerPoint`.
 * Output port 1: the adaptive leaf mesh, one cell per leaf element with cell data
 * `Level`, `InputIndex` and `InputCell` (the leaf's input data set, in connection and
 * composite order, and its cell there: results map back to the input's blocks), and
 * the same point arrays (SkyViewFactor: the leaves' own, under a sky),
 * continuous across elements (values at T-vertices interpolated along the coarser
 * edge; a terrain leaf's polygon holds the T-vertices of its edges, so the mesh has no
 * cracks).
 * Output port 2: the links as lines from receiver to sender (sun and sky links drawn
 * toward the sky) with cell data `Level` (the receiver's), transported `Power` (W),
 * `Sender` (0 a surface or cluster, 1 a sky patch, 2 the sun) and `SenderLevel`, as in
 * the paper's Fig. 9.
 *
 * Pieces (MPI ranks through VTK's parallel pipeline, streaming): every piece solves the
 * whole scene (its inputs are asked for whole; the solve is deterministic, so every
 * rank holds the same hierarchy) and evaluates output 0's point values only at its own
 * posts: a terrain's piece is the sub-extent asked of output 0, bit for bit that part of
 * the one-piece result, with GeoTransform and RasterSize of the piece. Other geometry is
 * not split: piece 0 carries it; the leaf mesh and links are piece 0's. With a far
 * terrain (SetFarTerrainConnection) and a DetailDistance, a terrain's piece asks its
 * input for the piece and a halo only, so that memory follows the piece.
 *
 * Refused with an error naming the fix, outputs empty: NaN or infinite parameters;
 * cells whose point ids are out of range; structured grids whose dimensions do not
 * match their points; ghost arrays of the wrong size; NaN coordinates in used cells;
 * reflectance outside [0, 1), negative emission; no light; running out of memory.
 *
 * The parameters are vtkRadiosityFilter's.
 *
 * @sa vtkRadiosityFilter vtkSolarIrradiation vtkTerrainSource vtkSunSource vtkSkySource
 */

#ifndef vtkHierarchicalRadiosity_h
#define vtkHierarchicalRadiosity_h

#include "TerraLuxFiltersModule.h" // For export macro
#include "vtkRadiosityFilter.h"

class TERRALUXFILTERS_EXPORT vtkHierarchicalRadiosity : public vtkRadiosityFilter
{
public:
  static vtkHierarchicalRadiosity* New();
  vtkTypeMacro(vtkHierarchicalRadiosity, vtkRadiosityFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The input ports.
  enum InputPorts
  {
    GEOMETRY_PORT = 0,
    LIGHTS_PORT = 1,
    FAR_TERRAIN_PORT = 2
  };

  /**
   * Connect a light source (vtkSkySource output 0 or vtkSunSource output) to LIGHTS_PORT.
   */
  void AddLightConnection(vtkAlgorithmOutput* output) { this->AddInputConnection(LIGHTS_PORT, output); }

  /**
   * Remove every connection of LIGHTS_PORT, the other ports kept; ParaView's repeatable
   * inputs reset a port with this.
   */
  void RemoveAllLightConnections() { this->RemoveAllInputConnections(LIGHTS_PORT); }

protected:
  vtkHierarchicalRadiosity();
  ~vtkHierarchicalRadiosity() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  // Every source on LIGHTS_PORT.
  bool AddLights(vtkInformationVector** inputVector, vtkRadiosityScene& scene) override;

private:
  vtkHierarchicalRadiosity(const vtkHierarchicalRadiosity&) = delete;
  void operator=(const vtkHierarchicalRadiosity&) = delete;
};

#endif

/**
 * @class   vtkSolarIrradiation
 * @brief   Irradiation over a day, a month or a year (Wh/m^2), and hours of direct sun.
 *
 * vtkSolarIrradiation sums the light of a time range on a scene, as GRASS r.sun's
 * daily mode, SAGA's Potential Incoming Solar Radiation or ArcGIS's Area Solar
 * Radiation do, with vtkHierarchicalRadiosity's physics: exact shadows, the
 * anisotropic CIE sky and interreflection, per-point values.
 *
 * The range StartTime .. EndTime (ISO 8601 with a UTC offset, as vtkSunSource) is cut
 * into steps of TimeStep minutes. Each step is the sun where NREL SPA puts it in the
 * middle of the step's lit part (a step through sunrise or sunset stands for the
 * minutes the sun is up, so the day's length is not rounded to whole steps), its
 * clear-sky irradiance (ESRA with the Linke turbidity, as r.sun, one value or twelve
 * monthly ones; or Ineichen-Perez) and the CIE standard general sky of SkyType around
 * it, scaled to the model's diffuse horizontal irradiance.
 *
 * Light transport is linear in the sources, so the sum of the solves of the steps is
 * one solve under all of them: every step's sun (its irradiance x its hours) and the
 * cumulative sky (each sky cell's radiance summed over the steps, Robinson & Stone
 * 2004). The hierarchy, its visibility and the final gather at each point are built
 * once for the whole range; each step costs one shadow ray per point at most: at the
 * posts of a DEM without missing cells, none where the post's horizons prove the sun
 * open or hidden (HorizonMap::View::clearlyAbove, clearlyBelow; the values are those
 * of the rays, but where a ray, starting a little above the post, passes over a crest a
 * cell away or under the foot of a wall steeper than about 75 deg that the proof, at
 * the post itself, rightly finds in the way).
 *
 * Input port 0: the scene, as vtkHierarchicalRadiosity's (terrains, objects,
 * composites; reflectance and emission arrays). The place is the first input's
 * GeoOrigin field data (vtkTerrainSource of a georeferenced DEM) or, without one or with
 * UseGeoOrigin off, Latitude, Longitude and Height.
 * Input port 1 (FAR_TERRAIN_PORT, optional): vtkTerrainSource's far terrain
 * (SetFarTerrainConnection). There is no light input: the filter makes the suns and
 * skies of its time range.
 *
 * Output port 0, with IntegrateOverTime on (default): the input geometry with point
 * arrays GlobalIrradiation, BeamIrradiation, SkyIrradiation, ReflectedIrradiation and
 * OutgoingIrradiation (the light leaving the surface, radiosity summed) in Wh/m^2
 * (NumberOfBands components), SunshineDuration (hours the sun reaches the point: above
 * its horizon, unshadowed, in front of the surface), on a terrain SkyViewFactor, and with
 * EvaluateAtPoints IrradiationError (Wh/m^2, vtkHierarchicalRadiosity's IrradianceError
 * of the summed solve);
 * field data `Steps`, per step `StepTime` (UTC), `StepHours`, `SunZenith`,
 * `SunAzimuth` (degrees), `SunNormalIrradiance` and `DiffuseHorizontalIrradiance`
 * (W/m^2), and vtkHierarchicalRadiosity's counts and seconds per phase, with
 * `SecondsSteps` for the suns and skies of the steps. Ports 1 and 2: the leaf mesh
 * and the links, as vtkHierarchicalRadiosity's.
 *
 * The filter advertises TIME_STEPS (hours since StartTime, one per step boundary).
 * With IntegrateOverTime off it gives the irradiance (W/m^2, vtkHierarchicalRadiosity's
 * arrays) of the instant the pipeline asks for (UPDATE_TIME_STEP; StartTime when none
 * is asked), so a ParaView user can scrub through the day.
 *
 * With a WeatherFileName (EPW or TMY3) the steps are the file's hours and the sky the
 * Perez all-weather sky of each hour's direct and diffuse irradiance (field data
 * `WeatherHours`, and `UnlitDirectIrradiation`: the file's direct Wh/m^2 in hours SPA
 * has the sun below the horizon, left out).
 *
 * Where the sun never rises in the range (polar night) the sums are zero and
 * SunshineDuration is 0; that is not an error. Refused with an error naming the fix,
 * outputs empty: a time that does not parse, an end not after the start, a step not
 * in (0, 1440] minutes, a range over ten years, a place SPA refuses, a weather file
 * with missing or garbled fields or the wrong number of rows, and everything
 * vtkHierarchicalRadiosity refuses.
 *
 * The radiosity parameters are vtkRadiosityFilter's.
 *
 * @sa vtkRadiosityFilter vtkHierarchicalRadiosity vtkSunSource vtkSkySource
 */

#ifndef vtkSolarIrradiation_h
#define vtkSolarIrradiation_h

#include "TerraLuxFiltersModule.h" // For export macro
#include "vtkRadiosityFilter.h"

class TERRALUXFILTERS_EXPORT vtkSolarIrradiation : public vtkRadiosityFilter
{
public:
  static vtkSolarIrradiation* New();
  vtkTypeMacro(vtkSolarIrradiation, vtkRadiosityFilter);

  /// The input ports: it makes its own lights.
  enum InputPorts
  {
    GEOMETRY_PORT = 0,
    FAR_TERRAIN_PORT = 1
  };
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Set/Get the first and last instant, ISO 8601 with a UTC offset
   * ("2024-06-21T00:00:00+02:00"). Default is 2000-01-01T00:00:00Z to
   * 2000-01-02T00:00:00Z.
   */
  vtkSetStringMacro(StartTime);
  vtkGetStringMacro(StartTime);
  vtkSetStringMacro(EndTime);
  vtkGetStringMacro(EndTime);
  ///@}

  ///@{
  /**
   * Set/Get the time step in minutes, in (0, 1440]. Default is 30.
   */
  vtkSetMacro(TimeStep, double);
  vtkGetMacro(TimeStep, double);
  ///@}

  ///@{
  /**
   * Set/Get whether output 0 holds the sums over the range (on) or the irradiance of
   * the requested time step (off). Default is on.
   */
  vtkSetMacro(IntegrateOverTime, vtkTypeBool);
  vtkGetMacro(IntegrateOverTime, vtkTypeBool);
  vtkBooleanMacro(IntegrateOverTime, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Set/Get whether the place comes from the input's GeoOrigin field data when it has
   * one. Default is on.
   */
  vtkSetMacro(UseGeoOrigin, vtkTypeBool);
  vtkGetMacro(UseGeoOrigin, vtkTypeBool);
  vtkBooleanMacro(UseGeoOrigin, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Set/Get the place without a GeoOrigin: degrees north, degrees east, metres above
   * the ellipsoid. Default is 0, 0, 0.
   */
  vtkSetMacro(Latitude, double);
  vtkGetMacro(Latitude, double);
  vtkSetMacro(Longitude, double);
  vtkGetMacro(Longitude, double);
  vtkSetMacro(Height, double);
  vtkGetMacro(Height, double);
  ///@}

  enum IrradianceModels
  {
    ESRA = 0,
    INEICHEN_PEREZ = 1
  };

  ///@{
  /**
   * Set/Get the clear-sky model: ESRA (r.sun's) or INEICHEN_PEREZ. Default is ESRA.
   */
  vtkSetClampMacro(IrradianceModel, int, ESRA, INEICHEN_PEREZ);
  vtkGetMacro(IrradianceModel, int);
  void SetIrradianceModelToESRA() { this->SetIrradianceModel(ESRA); }
  void SetIrradianceModelToIneichenPerez() { this->SetIrradianceModel(INEICHEN_PEREZ); }
  ///@}

  ///@{
  /**
   * Set the Linke turbidity (air mass 2) of every month, or of each month (January
   * first, as r.sun's monthly maps); Get the monthly values. Default is 3.0.
   */
  void SetLinkeTurbidity(double value);
  vtkSetVectorMacro(MonthlyLinkeTurbidity, double, 12);
  vtkGetVectorMacro(MonthlyLinkeTurbidity, double, 12);
  ///@}

  ///@{
  /**
   * Set/Get the CIE standard general sky type, 1..15, that spreads each step's
   * diffuse light over the sky. Default is 12 (CIE standard clear sky).
   */
  vtkSetClampMacro(SkyType, int, 1, 15);
  vtkGetMacro(SkyType, int);
  ///@}

  ///@{
  /**
   * Set/Get the finest level of the sky pyramid (2^Levels x 2^Levels cells), as
   * vtkSkySource's. Default is 7.
   */
  vtkSetClampMacro(SkyLevels, int, 1, 10);
  vtkGetMacro(SkyLevels, int);
  ///@}

  ///@{
  /**
   * Set/Get a weather file: an EnergyPlus EPW or a TMY3 CSV, whose hourly direct normal
   * and diffuse horizontal irradiance drive the Perez all-weather sky instead of the
   * clear sky (TimeStep, IrradianceModel, the Linke turbidity and SkyType are then
   * unused). Each hour of the file (its own local standard time; its month, day and
   * hour placed in each year StartTime .. EndTime spans) is a step, its lit part
   * evaluated at its middle with the hour's energy kept. A file more than 50 km from
   * the place warns. Default is nullptr: clear skies.
   */
  vtkSetStringMacro(WeatherFileName);
  vtkGetStringMacro(WeatherFileName);
  ///@}

  ///@{
  /**
   * Set/Get TT - UT in seconds for SPA. Default is 69.
   */
  vtkSetMacro(DeltaT, double);
  vtkGetMacro(DeltaT, double);
  ///@}

protected:
  vtkSolarIrradiation();
  ~vtkSolarIrradiation() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  bool AddLights(vtkInformationVector** inputVector, vtkRadiosityScene& scene) override;
  void FinishOutputs(vtkDataObject* output, vtkPolyData* leafMesh) override;
  bool UsesWeatherFile() const { return this->WeatherFileName && *this->WeatherFileName; }

  char* StartTime;
  char* EndTime;
  double TimeStep;
  vtkTypeBool IntegrateOverTime;
  vtkTypeBool UseGeoOrigin;
  double Latitude;
  double Longitude;
  double Height;
  int IrradianceModel;
  double MonthlyLinkeTurbidity[12];
  int SkyType;
  int SkyLevels;
  char* WeatherFileName;
  double DeltaT;

private:
  vtkSolarIrradiation(const vtkSolarIrradiation&) = delete;
  void operator=(const vtkSolarIrradiation&) = delete;

  struct Internals;
  Internals* Internal;
};

#endif

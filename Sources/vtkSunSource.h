/**
 * @class   vtkSunSource
 * @brief   The sun for a place and an instant: NREL SPA position and clear-sky irradiance.
 *
 * vtkSunSource computes the topocentric position of the sun with the NREL Solar
 * Position Algorithm (Reda & Andreas 2004; +-0.0003 deg), with atmospheric refraction
 * from Pressure and Temperature, and the sun's normal irradiance: from the ESRA
 * clear-sky model with a Linke turbidity (as GRASS r.sun uses), from the
 * Ineichen-Perez model, or as given by the user. The matching diffuse horizontal
 * irradiance is reported for vtkSkySource. Below the horizon both irradiances are 0
 * and the position is still reported.
 *
 * The place comes from Latitude, Longitude and Height, or from the `GeoOrigin` field
 * data of an optional input (e.g. vtkTerrainSource's output), so terrain -> sun
 * composes in a pipeline; the sun direction is then expressed in that terrain's
 * local east-north-up frame. The irradiances are that one place's, at its height (a
 * terrain's GeoOrigin: by default its centre post's ground): every post of the terrain
 * receives them, where the clear sky's air mass would give higher posts more beam
 * (ESRA: about 3 % a kilometre at a low sun; GRASS r.sun takes each cell's height).
 *
 * Output: vtkPolyData with one vertex DisplayDistance metres along the sun direction
 * (for display), and field data `SunDirection` (unit vector toward the sun, ENU),
 * `SunZenith`, `SunAzimuth` (compass bearing, clockwise from north), `SunAltitude`
 * (degrees), `SunNormalIrradiance`, `DiffuseHorizontalIrradiance`,
 * `GlobalHorizontalIrradiance`, `ExtraterrestrialIrradiance` (W/m^2),
 * `EarthSunDistance` (AU), `GeoOrigin` (the place used) and `DateTime` (UTC).
 *
 * @sa vtkSkySource vtkTerrainSource
 */

#ifndef vtkSunSource_h
#define vtkSunSource_h

#include "TerraLuxSourcesModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class TERRALUXSOURCES_EXPORT vtkSunSource : public vtkPolyDataAlgorithm
{
public:
  static vtkSunSource* New();
  vtkTypeMacro(vtkSunSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// How the sun's normal irradiance is obtained.
  enum IrradianceModels
  {
    ESRA = 0,           ///< ESRA clear sky with Linke turbidity (GRASS r.sun)
    INEICHEN_PEREZ = 1, ///< Ineichen-Perez clear sky with Linke turbidity
    USER = 2            ///< NormalIrradiance and DiffuseHorizontalIrradiance as given
  };

  ///@{
  /**
   * Set/Get the instant as ISO 8601 with a UTC offset or Z, e.g.
   * "2003-10-17T12:30:30-07:00". Default is "2000-01-01T12:00:00Z".
   */
  vtkSetStringMacro(DateTime);
  vtkGetStringMacro(DateTime);
  ///@}

  ///@{
  /**
   * Set/Get the place: latitude and longitude in degrees (WGS84, east positive) and
   * height above the ellipsoid in metres. Ignored when an input with `GeoOrigin`
   * is connected. Defaults are 0, 0, 0.
   */
  vtkSetClampMacro(Latitude, double, -90.0, 90.0);
  vtkGetMacro(Latitude, double);
  vtkSetMacro(Longitude, double);
  vtkGetMacro(Longitude, double);
  vtkSetMacro(Height, double);
  vtkGetMacro(Height, double);
  ///@}

  ///@{
  /**
   * Set/Get the air pressure in hPa and temperature in degC used for refraction.
   * Defaults are 1013.25 hPa and 12 degC.
   */
  vtkSetClampMacro(Pressure, double, 0.0, 2000.0);
  vtkGetMacro(Pressure, double);
  vtkSetClampMacro(Temperature, double, -100.0, 100.0);
  vtkGetMacro(Temperature, double);
  ///@}

  ///@{
  /**
   * Set/Get whether atmospheric refraction is applied (off: geometric position).
   * Default is on.
   */
  vtkSetMacro(AtmosphericRefraction, vtkTypeBool);
  vtkGetMacro(AtmosphericRefraction, vtkTypeBool);
  vtkBooleanMacro(AtmosphericRefraction, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Set/Get Delta T = TT - UT in seconds. Default is 69 s (about its 2020s value).
   */
  vtkSetClampMacro(DeltaT, double, -8000.0, 8000.0);
  vtkGetMacro(DeltaT, double);
  ///@}

  ///@{
  /**
   * Set/Get the irradiance model: ESRA, INEICHEN_PEREZ or USER. Default is ESRA.
   */
  vtkSetClampMacro(IrradianceModel, int, ESRA, USER);
  vtkGetMacro(IrradianceModel, int);
  void SetIrradianceModelToESRA() { this->SetIrradianceModel(ESRA); }
  void SetIrradianceModelToIneichenPerez() { this->SetIrradianceModel(INEICHEN_PEREZ); }
  void SetIrradianceModelToUser() { this->SetIrradianceModel(USER); }
  ///@}

  ///@{
  /**
   * Set/Get the Linke turbidity factor (air mass 2) of the clear-sky models. Default is 3.
   */
  vtkSetClampMacro(LinkeTurbidity, double, 0.5, 10.0);
  vtkGetMacro(LinkeTurbidity, double);
  ///@}

  ///@{
  /**
   * Set/Get the solar constant in W/m^2. Default is 1367 (ESRA, r.sun).
   */
  vtkSetClampMacro(SolarConstant, double, 0.0, 2000.0);
  vtkGetMacro(SolarConstant, double);
  ///@}

  ///@{
  /**
   * Set/Get the user's normal (beam) irradiance and diffuse horizontal irradiance in
   * W/m^2, used with the USER model. Defaults are 800 and 100.
   */
  vtkSetClampMacro(UserNormalIrradiance, double, 0.0, 2000.0);
  vtkGetMacro(UserNormalIrradiance, double);
  vtkSetClampMacro(UserDiffuseHorizontalIrradiance, double, 0.0, 2000.0);
  vtkGetMacro(UserDiffuseHorizontalIrradiance, double);
  ///@}

  ///@{
  /**
   * Set/Get how far along the sun direction the output vertex lies, in metres.
   * Default is 10000.
   */
  vtkSetClampMacro(DisplayDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(DisplayDistance, double);
  ///@}

  ///@{
  /**
   * Results of the last update: zenith and compass azimuth (degrees), altitude
   * (degrees), unit direction toward the sun (ENU), normal and diffuse horizontal
   * irradiance (W/m^2), extraterrestrial normal irradiance (W/m^2), Earth-Sun
   * distance (AU).
   */
  vtkGetMacro(Zenith, double);
  vtkGetMacro(Azimuth, double);
  double GetAltitude() { return 90.0 - this->Zenith; }
  vtkGetVector3Macro(Direction, double);
  vtkGetMacro(NormalIrradiance, double);
  vtkGetMacro(DiffuseHorizontalIrradiance, double);
  vtkGetMacro(ExtraterrestrialIrradiance, double);
  vtkGetMacro(EarthSunDistance, double);
  ///@}

protected:
  vtkSunSource();
  ~vtkSunSource() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* DateTime;
  double Latitude;
  double Longitude;
  double Height;
  double Pressure;
  double Temperature;
  vtkTypeBool AtmosphericRefraction;
  double DeltaT;
  int IrradianceModel;
  double LinkeTurbidity;
  double SolarConstant;
  double UserNormalIrradiance;
  double UserDiffuseHorizontalIrradiance;
  double DisplayDistance;

  double Zenith;
  double Azimuth;
  double Direction[3];
  double NormalIrradiance;
  double DiffuseHorizontalIrradiance;
  double ExtraterrestrialIrradiance;
  double EarthSunDistance;

private:
  vtkSunSource(const vtkSunSource&) = delete;
  void operator=(const vtkSunSource&) = delete;
};

#endif

/**
 * @class   vtkSkySource
 * @brief   Sky radiance distribution: CIE standard skies, Perez all-weather, uniform.
 *
 * vtkSkySource builds the diffuse sky of paper section 5.1: a radiance distribution
 * over the hemisphere, scaled so that a horizontal plane under the (untextured) sky
 * receives DiffuseHorizontalIrradiance, optionally multiplied by a texture (clouds,
 * colour). Models: the 15 CIE standard general skies (ISO 15469, SetSkyType(1..15)),
 * the traditional CIE overcast sky (1 + 2 cos Z)/3, the Perez all-weather sky (from
 * direct normal and diffuse horizontal irradiance) and the uniform sky.
 *
 * The sun position and irradiances come from the parameters, or from a connected
 * vtkSunSource on the optional input port 0 (when UseSunSource is on). A texture may
 * be connected to the optional input port 1: a vtkImageData with 1 or 3 point-scalar
 * components whose x index spans compass azimuth 0..360 deg and y index altitude
 * 0..90 deg; the radiance becomes 1 or 3 bands.
 *
 * Output port 0: the radiance map, a vtkImageData over (compass azimuth, altitude) in
 * degrees with 2^Levels x 2^Levels cells (the finest level of the sky pyramid). Cell
 * data `Radiance` (W/m^2/sr per band) holds cell averages integrated with Gauss
 * quadrature, so the hemisphere integral is right even with a circumsolar peak;
 * `SolidAngle` (sr) holds (v1 - v0)(sin u1 - sin u0). Field data:
 * `DiffuseHorizontalIrradiance`, `HorizontalIrradiance` (per band, from the map),
 * `RadianceScale`, `SunZenith`, `SunAzimuth`, `SkyModel`, and for Perez
 * `SkyClearness` and `SkyBrightness`.
 * Output port 1: a dome of radius DomeRadius (metres) with the same cells and
 * `Radiance`, for display.
 *
 * Radiance here is radiometric (W/m^2/sr). For a sky given in photometric units,
 * divide luminance (cd/m^2) by a luminous efficacy: about 120 lm/W for a clear sky's
 * diffuse light and 110-125 lm/W for overcast skies (Perez et al. 1990); e.g. a
 * diffuse horizontal illuminance of 20 klux is about 20000 / 120 = 167 W/m^2.
 *
 * @sa vtkSunSource
 */

#ifndef vtkSkySource_h
#define vtkSkySource_h

#include "TerraLuxSourcesModule.h" // For export macro
#include "vtkDataObjectAlgorithm.h"

#include <memory> // For std::unique_ptr

class vtkDataArray;
class vtkImageData;
class vtkPolyData;

namespace terralux
{
class PerezSky;
class SkyHierarchy;
class SkyModel;
}

class TERRALUXSOURCES_EXPORT vtkSkySource : public vtkDataObjectAlgorithm
{
public:
  static vtkSkySource* New();
  vtkTypeMacro(vtkSkySource, vtkDataObjectAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum SkyModels
  {
    CIE_GENERAL = 0,  ///< CIE standard general sky, type SkyType
    CIE_OVERCAST = 1, ///< traditional CIE overcast sky (Moon & Spencer)
    PEREZ = 2,        ///< Perez all-weather sky
    UNIFORM = 3       ///< constant radiance
  };

  ///@{
  /**
   * Set/Get the sky model. Default is CIE_GENERAL.
   */
  vtkSetClampMacro(SkyModel, int, CIE_GENERAL, UNIFORM);
  vtkGetMacro(SkyModel, int);
  void SetSkyModelToCIEGeneral() { this->SetSkyModel(CIE_GENERAL); }
  void SetSkyModelToCIEOvercast() { this->SetSkyModel(CIE_OVERCAST); }
  void SetSkyModelToPerez() { this->SetSkyModel(PEREZ); }
  void SetSkyModelToUniform() { this->SetSkyModel(UNIFORM); }
  ///@}

  ///@{
  /**
   * Set/Get the CIE standard general sky type, 1..15 (1-5 overcast, 6-10
   * intermediate, 11-15 clear; 12 is the CIE standard clear sky). Default is 12.
   */
  vtkSetClampMacro(SkyType, int, 1, 15);
  vtkGetMacro(SkyType, int);
  ///@}

  ///@{
  /**
   * Set/Get the sun's zenith angle and compass azimuth (clockwise from north) in
   * degrees, used without a sun source. Defaults are 45 and 180.
   */
  vtkSetClampMacro(SunZenith, double, 0.0, 180.0);
  vtkGetMacro(SunZenith, double);
  vtkSetMacro(SunAzimuth, double);
  vtkGetMacro(SunAzimuth, double);
  ///@}

  ///@{
  /**
   * Set/Get the diffuse horizontal irradiance (W/m^2) that sets the sky's absolute
   * scale, used without a sun source. Default is 100.
   */
  vtkSetClampMacro(DiffuseHorizontalIrradiance, double, 0.0, 2000.0);
  vtkGetMacro(DiffuseHorizontalIrradiance, double);
  ///@}

  ///@{
  /**
   * Set/Get the direct normal irradiance (W/m^2) and extraterrestrial normal
   * irradiance (W/m^2) that give the Perez sky its clearness and brightness, used
   * without a sun source. Defaults are 700 and 1367.
   */
  vtkSetClampMacro(DirectNormalIrradiance, double, 0.0, 2000.0);
  vtkGetMacro(DirectNormalIrradiance, double);
  vtkSetClampMacro(ExtraterrestrialIrradiance, double, 1.0, 2000.0);
  vtkGetMacro(ExtraterrestrialIrradiance, double);
  ///@}

  ///@{
  /**
   * Set/Get whether a connected vtkSunSource (input port 0) supplies the sun
   * position and irradiances. Default is on.
   */
  vtkSetMacro(UseSunSource, vtkTypeBool);
  vtkGetMacro(UseSunSource, vtkTypeBool);
  vtkBooleanMacro(UseSunSource, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Set/Get the finest level of the sky pyramid: the map has 2^Levels x 2^Levels
   * cells. Default is 7 (128 x 128: 2.8 deg of azimuth by 0.7 deg of altitude).
   */
  vtkSetClampMacro(Levels, int, 1, 10);
  vtkGetMacro(Levels, int);
  ///@}

  ///@{
  /**
   * Set/Get the radius of the display dome in metres. Default is 10000.
   */
  vtkSetClampMacro(DomeRadius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(DomeRadius, double);
  ///@}

  /**
   * Connect a vtkSunSource (port 0) or a texture (port 1).
   */
  void SetSunConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(0, output); }
  void SetTextureConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  ///@{
  /**
   * The radiance map (port 0) and the display dome (port 1), typed; GetOutput(port) of
   * vtkDataObjectAlgorithm gives either too.
   */
  vtkImageData* GetRadianceOutput();
  vtkPolyData* GetDomeOutput();
  ///@}

protected:
  vtkSkySource();
  ~vtkSkySource() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // RequestData's steps; they throw terralux::Error on bad input.
  struct SkyConditions
  {
    double sunZenith, sunAzimuth, diffuse, direct, extraterrestrial; // degrees, W/m^2
  };
  // The sun and irradiances: the connected vtkSunSource's, or the properties.
  SkyConditions Conditions(vtkDataObject* sun) const;
  std::unique_ptr<terralux::SkyModel> Model(const SkyConditions& conditions) const;
  void FillRadianceMap(const terralux::SkyHierarchy& sky, const SkyConditions& conditions,
    const terralux::PerezSky* perez, vtkImageData* map) const;
  void FillDome(vtkDataArray* radiance, vtkPolyData* dome) const;

  int SkyModel;
  int SkyType;
  double SunZenith;
  double SunAzimuth;
  double DiffuseHorizontalIrradiance;
  double DirectNormalIrradiance;
  double ExtraterrestrialIrradiance;
  vtkTypeBool UseSunSource;
  int Levels;
  double DomeRadius;

private:
  vtkSkySource(const vtkSkySource&) = delete;
  void operator=(const vtkSkySource&) = delete;
};

#endif

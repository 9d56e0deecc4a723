#pragma once
// Clear-sky irradiance of the sun and sky: the ESRA model (Rigollier, Bauer &
// Wald 2000), the one GRASS r.sun uses, and the Ineichen-Perez model (Ineichen &
// Perez 2002). Both take the Linke turbidity factor for air mass 2.

namespace terralux
{
/// Broadband solar constant used by ESRA and r.sun, W/m^2.
constexpr double solarConstantWm2 = 1367.0;

struct ClearSkyIrradiance
{
  double directNormalWm2 = 0.0;
  double diffuseHorizontalWm2 = 0.0;
  double globalHorizontalWm2 = 0.0;
};

/// Relative optical air mass of Kasten & Young (1989), zenith angle in degrees
/// (apparent); at sea level. Finite up to 96 degrees; infinity beyond.
double kastenYoungAirMass(double zenithDeg);

/// ESRA (r.sun): geometricAltitudeDeg is the sun's altitude without refraction (ESRA
/// corrects for refraction itself), heightM the site's height, linkeTurbidity for air mass 2,
/// extraterrestrialWm2 the normal irradiance at the top of the atmosphere (solar constant
/// over the squared Earth-Sun distance). Zero when the sun is below the horizon.
ClearSkyIrradiance esraClearSky(
  double geometricAltitudeDeg, double heightM, double linkeTurbidity, double extraterrestrialWm2);

/// Ineichen-Perez: apparentZenithDeg with refraction. Zero when the sun is below the horizon.
ClearSkyIrradiance ineichenPerezClearSky(
  double apparentZenithDeg, double heightM, double linkeTurbidity, double extraterrestrialWm2);

enum class ClearSkyModel
{
  Esra,
  IneichenPerez
};

/// Either model for a solar position given by its apparent (refracted) and geometric
/// zenith angles; zero while the apparent sun is below the horizon.
ClearSkyIrradiance clearSkyIrradiance(ClearSkyModel model, double apparentZenithDeg, double geometricZenithDeg,
  double heightM, double linkeTurbidity, double extraterrestrialWm2);

/// Given (measured or chosen) direct normal and diffuse horizontal irradiance with the
/// global horizontal they make at the apparent zenith angle; zero while the apparent
/// sun is below the horizon.
ClearSkyIrradiance givenIrradiance(double apparentZenithDeg, double directNormalWm2, double diffuseHorizontalWm2);
} // namespace terralux

#include "sun/solar_position.h"

#include "base/angles.h"
#include "base/error.h"
#include "sun/solar_position_terms.h"

#include <cmath>

namespace terralux
{
namespace
{

double wrapDegrees(double angle)
{
  angle = std::fmod(angle, 360.0);
  return angle < 0.0 ? angle + 360.0 : angle;
}

double evaluateSeries(const spa_terms::Series& series, double jme)
{
  double sum = 0.0;
  for (int k = 0; k < series.count; ++k)
  {
    const auto& term = series.terms[k];
    sum += term.amplitude * std::cos(term.phase + term.frequency * jme);
  }
  return sum;
}

// Sum_i S_i JME^i / 1e8 over the series of one coordinate (eq. 9-11).
template <int N>
double evaluatePolynomial(const spa_terms::Series (&series)[N], double jme)
{
  double sum = 0.0, power = 1.0;
  for (int i = 0; i < N; ++i, power *= jme)
  {
    sum += evaluateSeries(series[i], jme) * power;
  }
  return sum / 1.0e8;
}

double polynomial(double x, double c0, double c1, double c2, double c3Divisor)
{
  return c0 + x * (c1 + x * c2) + x * x * x / c3Divisor;
}
} // namespace

SolarPosition computeSolarPosition(const SolarPositionInput& in)
{
  if (!std::isfinite(in.julianDayUT) || !std::isfinite(in.deltaT) || !std::isfinite(in.latitudeDeg) ||
    !std::isfinite(in.longitudeDeg) || !std::isfinite(in.heightM) || !std::isfinite(in.pressureHPa) ||
    !std::isfinite(in.temperatureC))
  {
    throw Error("solar position inputs must be finite numbers");
  }
  if (std::abs(in.latitudeDeg) > 90.0)
  {
    throw Error("latitude must lie in [-90, 90] degrees");
  }
  if (in.pressureHPa < 0.0 || in.temperatureC <= -273.0)
  {
    throw Error("pressure must be >= 0 hPa and temperature above -273 degC");
  }

  // Time scales (eq. 5-8).
  const double jd = in.julianDayUT;
  const double jde = jd + in.deltaT / 86400.0;
  const double jc = (jd - 2451545.0) / 36525.0;
  const double jce = (jde - 2451545.0) / 36525.0;
  const double jme = jce / 10.0;

  // Earth heliocentric longitude, latitude, radius (eq. 9-12); geocentric (eq. 13-14).
  const double L = wrapDegrees(evaluatePolynomial(spa_terms::earthLongitude, jme) / degree);
  const double B = evaluatePolynomial(spa_terms::earthLatitude, jme) / degree;
  const double R = evaluatePolynomial(spa_terms::earthRadius, jme);
  const double theta = wrapDegrees(L + 180.0);
  const double beta = -B;

  // Nutation in longitude and obliquity (eq. 15-23).
  const double x[5] = {
    polynomial(jce, 297.85036, 445267.111480, -0.0019142, 189474.0),
    polynomial(jce, 357.52772, 35999.050340, -0.0001603, -300000.0),
    polynomial(jce, 134.96298, 477198.867398, 0.0086972, 56250.0),
    polynomial(jce, 93.27191, 483202.017538, -0.0036825, 327270.0),
    polynomial(jce, 125.04452, -1934.136261, 0.0020708, 450000.0),
  };
  double deltaPsi = 0.0, deltaEpsilon = 0.0;
  for (const auto& term : spa_terms::nutation)
  {
    double argument = 0.0;
    for (int j = 0; j < 5; ++j)
    {
      argument += x[j] * term.multipliers[j];
    }
    argument *= degree;
    deltaPsi += (term.a + term.b * jce) * std::sin(argument);
    deltaEpsilon += (term.c + term.d * jce) * std::cos(argument);
  }
  deltaPsi /= 36000000.0;
  deltaEpsilon /= 36000000.0;

  // True obliquity of the ecliptic (eq. 24-25).
  const double u = jme / 10.0;
  static const double epsilonTerms[11] = { 84381.448, -4680.93, -1.55, 1999.25, -51.38, -249.67,
    -39.05, 7.12, 27.87, 5.79, 2.45 };
  double epsilon0 = 0.0;
  for (int k = 10; k >= 0; --k)
  {
    epsilon0 = epsilon0 * u + epsilonTerms[k];
  }
  const double epsilon = epsilon0 / 3600.0 + deltaEpsilon;

  // Apparent sun longitude (eq. 26-27), sidereal time (eq. 28-29).
  const double deltaTau = -20.4898 / (3600.0 * R);
  const double lambda = theta + deltaPsi + deltaTau;
  const double nu0 = wrapDegrees(280.46061837 + 360.98564736629 * (jd - 2451545.0) +
    jc * jc * (0.000387933 - jc / 38710000.0));
  const double nu = nu0 + deltaPsi * std::cos(epsilon * degree);

  // Geocentric right ascension and declination (eq. 30-31).
  const double lambdaRad = lambda * degree, epsilonRad = epsilon * degree, betaRad = beta * degree;
  const double alpha = wrapDegrees(std::atan2(std::sin(lambdaRad) * std::cos(epsilonRad) -
                                     std::tan(betaRad) * std::sin(epsilonRad),
                                   std::cos(lambdaRad)) /
    degree);
  const double delta = std::asin(std::sin(betaRad) * std::cos(epsilonRad) +
                         std::cos(betaRad) * std::sin(epsilonRad) * std::sin(lambdaRad)) /
    degree;

  // Local hour angle (eq. 32) and topocentric parallax (eq. 33-38).
  const double H = wrapDegrees(nu + in.longitudeDeg - alpha);
  const double xi = 8.794 / (3600.0 * R) * degree;
  const double phi = in.latitudeDeg * degree;
  const double uTerm = std::atan(0.99664719 * std::tan(phi));
  const double xTerm = std::cos(uTerm) + in.heightM / 6378140.0 * std::cos(phi);
  const double yTerm = 0.99664719 * std::sin(uTerm) + in.heightM / 6378140.0 * std::sin(phi);
  const double Hrad = H * degree, deltaRad = delta * degree;
  const double deltaAlpha = std::atan2(-xTerm * std::sin(xi) * std::sin(Hrad),
    std::cos(deltaRad) - xTerm * std::sin(xi) * std::cos(Hrad));
  const double deltaPrime = std::atan2((std::sin(deltaRad) - yTerm * std::sin(xi)) * std::cos(deltaAlpha),
    std::cos(deltaRad) - xTerm * std::sin(xi) * std::cos(Hrad));
  const double Hprime = Hrad - deltaAlpha;

  // Topocentric elevation, refraction, zenith and azimuth (eq. 39-46).
  const double e0 =
    std::asin(std::sin(phi) * std::sin(deltaPrime) + std::cos(phi) * std::cos(deltaPrime) * std::cos(Hprime)) /
    degree;
  constexpr double sunRadius = 0.26667, refractionAtHorizon = 0.5667;
  double deltaE = 0.0;
  if (in.refraction && e0 >= -(sunRadius + refractionAtHorizon))
  {
    deltaE = (in.pressureHPa / 1010.0) * (283.0 / (273.0 + in.temperatureC)) * 1.02 /
      (60.0 * std::tan((e0 + 10.3 / (e0 + 5.11)) * degree));
  }
  const double e = e0 + deltaE;
  const double gamma = std::atan2(std::sin(Hprime),
                         std::cos(Hprime) * std::sin(phi) - std::tan(deltaPrime) * std::cos(phi)) /
    degree;

  SolarPosition result;
  result.zenithDeg = 90.0 - e;
  result.geometricZenithDeg = 90.0 - e0;
  result.azimuthDeg = wrapDegrees(gamma + 180.0);
  result.earthSunDistanceAU = R;
  result.declinationDeg = deltaPrime / degree;
  result.hourAngleDeg = Hprime / degree;

  // Equation of time (SPA appendix A.1): sun's mean longitude against its right ascension.
  const double m = polynomial(jme, 280.4664567, 360007.6982779, 0.03032028, 49931.0) -
    jme * jme * jme * jme / 15300.0 - jme * jme * jme * jme * jme / 2000000.0;
  double eot = wrapDegrees(m - 0.0057183 - alpha + deltaPsi * std::cos(epsilonRad));
  if (eot > 180.0)
  {
    eot -= 360.0;
  }
  result.equationOfTimeMinutes = 4.0 * eot;
  return result;
}
} // namespace terralux

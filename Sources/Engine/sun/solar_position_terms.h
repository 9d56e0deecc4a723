#pragma once
// Periodic terms of the NREL Solar Position Algorithm (Reda & Andreas 2004,
// Tables A4.2 and A4.3): the truncated VSOP87 series of the Earth's heliocentric
// longitude (L0..L5), latitude (B0, B1) and radius vector (R0..R4), and the
// IAU 1980 nutation series. Published data, transcribed in our own layout.

namespace terralux
{
namespace spa_terms
{
/// One term A cos(B + C * JME) of a VSOP87 series.
struct PeriodicTerm
{
  double amplitude;
  double phase;
  double frequency;
};

/// A series and its number of terms.
struct Series
{
  const PeriodicTerm* terms;
  int count;
};

extern const Series earthLongitude[6];
extern const Series earthLatitude[2];
extern const Series earthRadius[5];

/// Nutation term: multipliers of the five fundamental arguments X0..X4, and the
/// coefficients of the longitude (a + b JCE) sin and obliquity (c + d JCE) cos parts,
/// in units of 0.0001 arcsec.
struct NutationTerm
{
  int multipliers[5];
  double a, b, c, d;
};

extern const NutationTerm nutation[63];
} // namespace spa_terms
} // namespace terralux

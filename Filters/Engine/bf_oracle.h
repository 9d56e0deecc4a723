#pragma once
// The BF refinement oracle (Hanrahan, Salzman & Aupperle 1991): a link is refined
// when the power it carries, sender emittance x kernel x visibility x receiver area
// (x 1/4 for cluster receivers), exceeds a tolerance relative to the scene's total
// incident power; partially visible links are refined further. The side to split is
// the larger one, in area (surfaces, clusters) or in solid angle (sky patches).

#include "helement.h"

namespace terralux
{
enum class Refinement
{
  Keep,
  SplitReceiver,
  SplitSender
};

struct OracleSettings
{
  double powerThreshold = 0.0;        ///< W: tolerance x reference power
  double partialVisibilityFactor = 0.1; ///< partially visible links refine down to this fraction of it
  double sceneArea = 1.0;             ///< total surface area, to compare areas with solid angles
  double meanIrradiance = 0.0;        ///< W/m^2: reference power / scene area
};

/// Power carried by the link (largest band), W.
double linkPower(const HElement& receiver, const Link& link);

Refinement decideRefinement(HElement& receiver, const Link& link, const OracleSettings& settings);

/// Whether a surface lights itself enough for its self-link to be split into links
/// between its parts. A surface of area A whose area vector has length |N| sends at
/// most B (A - |N|) onto itself (all of it in a cavity, nothing on a flat or convex
/// surface: planar polygons never); B is its radiosity or, before the first gather,
/// its reflectance times the scene's mean irradiance. False for non-surfaces.
bool lightsItself(const HElement& element, const OracleSettings& settings);
} // namespace terralux

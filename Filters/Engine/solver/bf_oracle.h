#pragma once
// The BF refinement oracle (Hanrahan, Salzman & Aupperle 1991): a link is refined
// when the power it carries, sender emittance x kernel x visibility x receiver area
// (x 1/4 for cluster receivers), exceeds a tolerance relative to the scene's total
// incident power; partially visible links are refined further. The side to split is
// the larger one, in area (surfaces, clusters) or in solid angle (sky patches).

#include "hierarchy/helement.h"

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
  /// Irradiance (W/m^2) a link with a far-field estimate (a cluster at either end) may
  /// leave out at its receiver: the receiver-relative bound that the scene-relative
  /// powerThreshold cannot give (a 1 m^2 wall beside a 100 km^2 ground carries no
  /// power on the scene's scale, yet a tenth of its light).
  double irradianceThreshold = 0.0;
};

/// Power carried by the link (largest band), W.
double linkPower(const HElement& receiver, const Link& link);

/// Whether a link with a cluster at either end and a receiver (or a surface in it) under a
/// hundredth of the sender's area may leave out more irradiance at its receiver than
/// settings.irradianceThreshold: the cluster's kernel bound (its area seen from the
/// closest distance between the two boxes; 0 where a side facing one way has the other
/// behind its plane) against the link's estimate, for what the sender sends or could
/// send once lit at the scene's mean irradiance.
bool clusterMayCarryMore(const HElement& receiver, const Link& link, const OracleSettings& settings);

/// Whether a link's far-field kernel misses more irradiance at its receiver than
/// settings.irradianceThreshold: its sampled true-surface kernel (Link::sampledKernel)
/// against it, for what the sender sends or could send at the scene's mean irradiance.
/// This bounds the error each receiver sees in concave terrain, where each of the many
/// local exchanges is far below the scene-relative power threshold.
bool modelMissesExchange(const HElement& receiver, const Link& link, const OracleSettings& settings);

Refinement decideRefinement(HElement& receiver, const Link& link, const OracleSettings& settings);

/// Whether a surface lights itself enough for its self-link to be split into links
/// between its parts. A surface of area A whose area vector has length |N| sends at
/// most B (A - |N|) onto itself (all of it in a cavity, nothing on a flat or convex
/// surface: planar polygons never); B is its radiosity or, before the first gather,
/// its reflectance times the scene's mean irradiance. True when that exceeds the power
/// threshold, or, for surfaces whose children follow finer geometry (terrain patches of
/// several cells), when B (A - |N|) / A exceeds the irradiance threshold. False for
/// non-surfaces.
bool lightsItself(const HElement& element, const OracleSettings& settings);
} // namespace terralux

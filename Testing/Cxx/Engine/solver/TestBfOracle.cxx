// The BF refinement oracle (bf_oracle.h) on its own: a link's power, which links are
// kept or split at the threshold, which side splits, partial visibility refined
// further, sources that cannot split, and self-lighting surfaces.
#include "solver/bf_oracle.h"
#include "hierarchy/polygon_element.h"
#include "emitters/sun_element.h"

#include <gtest/gtest.h>

using namespace terralux;

namespace
{
struct Squares
{
  ElementStore store;
  PolygonElement* small = nullptr; // 1 m^2, receiver
  PolygonElement* large = nullptr; // 16 m^2, sender of radiosity 10
  Squares()
  {
    this->store.MinimumArea = 0.01;
    const Vec3 a[4] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } };
    const Vec3 b[4] = { { 0, 0, 5 }, { 0, 4, 5 }, { 4, 4, 5 }, { 4, 0, 5 } };
    this->small = this->store.make<PolygonElement>(0, &this->store, a, 4, uniformSpectrum(0.5), Spectrum{}, 0);
    this->large = this->store.make<PolygonElement>(0, &this->store, b, 4, uniformSpectrum(0.5), Spectrum{}, 1);
    this->large->Radiosity = uniformSpectrum(10.0);
  }
  Link link(double kernel, double visibility) const
  {
    Link l;
    l.sender = this->large;
    l.kernel = kernel;
    l.visibility = visibility;
    return l;
  }
};

OracleSettings settingsWithThreshold(double watts)
{
  OracleSettings settings;
  settings.powerThreshold = watts;
  settings.sceneArea = 17.0;
  return settings;
}
} // namespace

TEST(BfOracle, LinkPowerIsEmittanceKernelVisibilityArea)
{
  Squares squares;
  const Link link = squares.link(0.2, 0.5);
  EXPECT_DOUBLE_EQ(linkPower(*squares.small, link), 10.0 * 0.2 * 0.5 * 1.0);
  // A sun of 800 W/m^2 at cosine 0.6 on 1 m^2.
  SunElement sun(9, 0, Vec3(0, 0.8, 0.6), uniformSpectrum(800.0));
  Link sunLink;
  sunLink.sender = &sun;
  sunLink.kernel = 0.6;
  EXPECT_DOUBLE_EQ(linkPower(*squares.small, sunLink), 480.0);
}

TEST(BfOracle, LinksAboveTheThresholdSplitTheLargerSide)
{
  Squares squares;
  const Link link = squares.link(0.2, 1.0); // 2 W
  EXPECT_EQ(decideRefinement(*squares.small, link, settingsWithThreshold(2.5)), Refinement::Keep);
  // Above: the sender (16 m^2) is the larger side.
  EXPECT_EQ(decideRefinement(*squares.small, link, settingsWithThreshold(1.5)), Refinement::SplitSender);
  // Seen from the large square, the small one is the smaller side: the receiver splits.
  Link back = link;
  back.sender = squares.small;
  squares.small->Radiosity = uniformSpectrum(10.0);
  EXPECT_EQ(decideRefinement(*squares.large, back, settingsWithThreshold(1.5)), Refinement::SplitReceiver);
}

TEST(BfOracle, PartialVisibilityRefinesTenTimesFurther)
{
  Squares squares;
  const OracleSettings settings = settingsWithThreshold(5.0);
  // 1 W fully visible: kept; 1 W through a partly blocked link: above 0.1 x 5 W, split.
  EXPECT_EQ(decideRefinement(*squares.small, squares.link(0.1, 1.0), settings), Refinement::Keep);
  EXPECT_NE(decideRefinement(*squares.small, squares.link(0.2, 0.5), settings), Refinement::Keep);
  // Fully hidden: nothing to refine.
  EXPECT_EQ(decideRefinement(*squares.small, squares.link(0.2, 0.0), settings), Refinement::Keep);
}

TEST(BfOracle, SourcesThatCannotSplitLeaveItToTheReceiver)
{
  Squares squares;
  SunElement sun(9, 0, Vec3(0, 0, 1), uniformSpectrum(800.0));
  Link sunLink;
  sunLink.sender = &sun;
  sunLink.kernel = 1.0;
  EXPECT_EQ(decideRefinement(*squares.small, sunLink, settingsWithThreshold(100.0)), Refinement::SplitReceiver);
  // A receiver at its smallest area cannot split either: kept whatever it carries.
  squares.store.MinimumArea = 1.0;
  EXPECT_EQ(decideRefinement(*squares.small, sunLink, settingsWithThreshold(100.0)), Refinement::Keep);
}

TEST(BfOracle, PlanarSurfacesNeverLightThemselves)
{
  Squares squares;
  squares.small->Radiosity = uniformSpectrum(1e6);
  EXPECT_EQ(squares.small->unalignedArea(), 0.0);
  EXPECT_FALSE(lightsItself(*squares.small, settingsWithThreshold(1e-9)));
  SunElement sun(9, 0, Vec3(0, 0, 1), uniformSpectrum(800.0));
  EXPECT_FALSE(lightsItself(sun, settingsWithThreshold(1e-9)));
}

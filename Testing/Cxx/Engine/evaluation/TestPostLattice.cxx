// The lattice of posts gathered first (post_lattice.h): what posts between lattice
// posts read, and which cells are refined.

#include "sky/cie_sky.h"
#include "base/angles.h"
#include "horizons/horizon_map.h"
#include "horizons/horizon_sky.h"
#include "evaluation/open_sky.h"
#include "evaluation/post_lattice.h"
#include "horizons/post_sky.h"
#include "visibility/sampling.h"
#include "sky/sky_hierarchy.h"
#include "sky/sky_model.h"
#include "terrain/terrain_directions.h"
#include "terrain_grids.h"
#include "visibility/visibility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace terralux;
using namespace terralux_test;

// Two passes: every second lattice post first; the others only in the coarse cells
// whose corners disagree (relative to what each receives) or lack data, and at the far
// edges; a post reads between the corners of the finest cell gathered around it.
TEST(PostLattice, RefinesOnlyTheCellsWhoseCornersDisagree)
{
  // 21 x 17 posts, every 4th: lattice posts 0..5 x 0..4, coarse cells of 8 x 8 posts:
  // (0, 0), (1, 0) complete; the column at i = 16..20 lacks its far corners.
  PostLattice lattice(21, 17, 4);
  EXPECT_TRUE(lattice.gatheredInPass(8, 8, true));
  EXPECT_FALSE(lattice.gatheredInPass(4, 0, true));
  EXPECT_FALSE(lattice.gatheredInPass(8, 8, false));
  auto gathered = [](double reflected, double received) {
    PostLattice::Gathered g;
    g.reflected = uniformSpectrum(reflected);
    g.variance = 1.0;
    g.terrainSeen = 0.5;
    g.terrainByPart[0] = 0.5; // its rays met all its horizons show
    g.received = received;
    return g;
  };
  // Cell (0, 0): its corners find 10 and 10.2 W/m^2 per half of terrain seen, a spread
  // of 0.2 per 1 terrain seen, 0.1 at theirs: within 0.001 x their 200 W/m^2. Cell
  // (1, 0): 10 and 14.
  for (int j : { 0, 8, 16 })
    for (int i : { 0, 8, 16 })
      lattice.set(i, j, gathered(i == 16 ? 14.0 : (j == 8 ? 10.1 : 10.0), 200.0));
  lattice.refine(0.001);
  EXPECT_FALSE(lattice.gatheredInPass(4, 0, false));  // inside cell (0, 0) alone
  EXPECT_TRUE(lattice.gatheredInPass(12, 0, false));  // inside cell (1, 0)
  EXPECT_TRUE(lattice.gatheredInPass(8, 4, false));   // on their common side
  EXPECT_TRUE(lattice.gatheredInPass(20, 12, false)); // the edge column: always
  EXPECT_FALSE(lattice.gatheredInPass(4, 12, false)); // cell (0, 1) agrees too
  // Cell (0, 0) reads between its coarse corners: at (4, 4), the mean of 20, 20, 20.2,
  // 20.2 per terrain seen.
  Spectrum per;
  ASSERT_TRUE(lattice.perTerrainSeenAt(4.0, 4.0, per));
  EXPECT_DOUBLE_EQ(per[0], 0.5 * (20.0 + 20.2));
  EXPECT_DOUBLE_EQ(lattice.around(5, 5).largestPerTerrainSeen, 20.2);
  EXPECT_DOUBLE_EQ(lattice.around(5, 5).leastPerTerrainSeen, 20.0);
  // Cell (1, 0) reads between its lattice posts once the second pass has them.
  lattice.set(12, 0, gathered(12.0, 200.0));
  lattice.set(12, 4, gathered(12.0, 200.0));
  lattice.set(8, 4, gathered(10.0, 200.0));
  lattice.set(16, 4, gathered(14.0, 200.0));
  EXPECT_DOUBLE_EQ(lattice.around(13, 1).largestPerTerrainSeen, 28.0); // (16, 0), (16, 4)
  EXPECT_DOUBLE_EQ(lattice.around(13, 1).leastPerTerrainSeen, 24.0);  // (12, 0), (12, 4)
  Spectrum read;
  ASSERT_TRUE(lattice.reflectedAt(12.0, 2.0, read));
  EXPECT_DOUBLE_EQ(read[0], 12.0);
  // Refined too where a corner has no data.
  PostLattice holes(17, 17, 4);
  for (int j : { 0, 8, 16 })
    for (int i : { 0, 8, 16 })
      if (!(i == 16 && j == 16))
        holes.set(i, j, gathered(10.0, 200.0));
  holes.refine(0.001);
  EXPECT_FALSE(holes.gatheredInPass(4, 4, false));
  EXPECT_TRUE(holes.gatheredInPass(12, 12, false));
}

TEST(PostLattice, ReadsBetweenItsPostsAndTellsTheLargestSpreadAround)
{
  // 10 x 7 posts, every 4th: lattice posts at i = 0, 4, 8 and j = 0, 4.
  PostLattice lattice(10, 7, 4);
  EXPECT_TRUE(lattice.onLattice(8, 4));
  EXPECT_FALSE(lattice.onLattice(2, 4));
  EXPECT_EQ(lattice.varianceAround(5, 1), -1.0); // nothing gathered yet
  Spectrum read;
  EXPECT_FALSE(lattice.reflectedAt(5.0, 1.0, read));
  auto gathered = [](double reflected, double variance, double terrainSeen) {
    PostLattice::Gathered g;
    g.reflected = uniformSpectrum(reflected);
    g.variance = variance;
    g.terrainSeen = g.terrainByPart[0] = terrainSeen;
    return g;
  };
  lattice.set(4, 0, gathered(10.0, 2.0, 0.1));
  lattice.set(8, 0, gathered(19.0, 5.0, 0.1));
  lattice.set(4, 4, gathered(30.0, 1.0, 0.2));
  // (8, 4) has no data: the others share its weight.
  EXPECT_EQ(lattice.varianceAround(5, 1), 5.0);
  EXPECT_EQ(lattice.varianceAround(9, 6), 5.0); // beyond the last lattice post: its cell
  ASSERT_TRUE(lattice.reflectedAt(4.0, 0.0, read));
  EXPECT_DOUBLE_EQ(read[0], 10.0);
  ASSERT_TRUE(lattice.reflectedAt(6.0, 0.0, read));
  EXPECT_DOUBLE_EQ(read[0], 14.5);
  ASSERT_TRUE(lattice.reflectedAt(4.0, 2.0, read));
  EXPECT_DOUBLE_EQ(read[0], 20.0);
  // Near the post without data: from the others alone; at it, nothing.
  ASSERT_TRUE(lattice.reflectedAt(7.0, 3.0, read));
  EXPECT_GT(read[0], 10.0);
  EXPECT_LT(read[0], 30.0);
  EXPECT_FALSE(lattice.reflectedAt(8.0, 4.0, read));

  // Per terrain seen: (4, 0) found 10 / 0.1 = 100, (8, 0) 19 / 0.1 = 190, (4, 4)
  // 30 / 0.2 = 150: the spread around is 100 to 190.
  const PostLattice::Around around = lattice.around(5, 1);
  EXPECT_DOUBLE_EQ(around.largestPerTerrainSeen, 190.0);
  EXPECT_DOUBLE_EQ(around.leastPerTerrainSeen, 100.0);
  Spectrum per;
  ASSERT_TRUE(lattice.perTerrainSeenAt(6.0, 0.0, per));
  EXPECT_DOUBLE_EQ(per[0], 0.5 * (100.0 + 190.0));
  EXPECT_FALSE(lattice.perTerrainSeenAt(8.0, 4.0, per));
}

// What terrain sends, read between lattice posts, is the ratio of what the corners
// found to the terrain they see: a corner on an open ridge, which sees next to no
// terrain, tells nothing of it and must not read as 0; corners weigh by the terrain
// they see.
TEST(PostLattice, ReadsPerTerrainSeenByTheTerrainEachCornerSees)
{
  PostLattice lattice(9, 5, 4); // lattice posts at i = 0, 4, 8 and j = 0, 4
  auto gathered = [](double reflected, double terrainSeen) {
    PostLattice::Gathered g;
    g.reflected = uniformSpectrum(reflected);
    g.variance = 1.0;
    g.terrainSeen = g.terrainByPart[0] = terrainSeen;
    return g;
  };
  lattice.set(0, 0, gathered(0.0, 0.0)); // an open ridge: no terrain seen
  lattice.set(4, 0, gathered(3.0, 0.1));  // 30 per terrain seen
  lattice.set(0, 4, gathered(0.0, 0.0));
  lattice.set(4, 4, gathered(12.0, 0.3)); // 40
  Spectrum per;
  // Half way between the ridge and (4, 0): what (4, 0) found, not half of it.
  ASSERT_TRUE(lattice.perTerrainSeenAt(2.0, 0.0, per));
  EXPECT_DOUBLE_EQ(per[0], 30.0);
  // Between (4, 0) and (4, 4): (3 + 12) / (0.1 + 0.3), not the mean of 30 and 40.
  ASSERT_TRUE(lattice.perTerrainSeenAt(4.0, 2.0, per));
  EXPECT_DOUBLE_EQ(per[0], 37.5);
  // The spread around is that of the corners that see terrain.
  const PostLattice::Around around = lattice.around(1, 1);
  EXPECT_DOUBLE_EQ(around.largestPerTerrainSeen, 40.0);
  EXPECT_DOUBLE_EQ(around.leastPerTerrainSeen, 30.0);
  // Where no corner sees terrain there is nothing to read, and no spread.
  PostLattice open(5, 5, 4);
  for (int j : { 0, 4 })
    for (int i : { 0, 4 })
      open.set(i, j, gathered(0.0, 0.0));
  EXPECT_FALSE(open.perTerrainSeenAt(2.0, 2.0, per));
  EXPECT_DOUBLE_EQ(open.around(1, 1).largestPerTerrainSeen, 0.0);
  EXPECT_DOUBLE_EQ(open.around(1, 1).leastPerTerrainSeen, 0.0);
  EXPECT_EQ(open.around(1, 1).variance, 1.0);
}

// A corner on the terrain's edge (the grid's border, or beside missing data) sees
// terrain on one side only: the cells it is a corner of say so, whether it was gathered
// in the first pass or the second; a corner without data does not count.
TEST(PostLattice, TellsWhetherACornerLiesOnTheTerrainsEdge)
{
  PostLattice lattice(25, 25, 4); // lattice posts every 4th, coarse cells of 8 posts
  auto gathered = [](bool edge) {
    PostLattice::Gathered g;
    g.reflected = uniformSpectrum(1.0);
    g.variance = 1.0;
    g.terrainSeen = g.terrainByPart[0] = 0.1;
    g.received = 100.0;
    g.edge = edge;
    return g;
  };
  for (int j : { 0, 8, 16, 24 })
    for (int i : { 0, 8, 16, 24 })
      if (!(i == 24 && j == 24)) // no data there
        lattice.set(i, j, gathered(i == 0 || j == 0 || ((i == 24 || j == 24) && j != 8)));
  lattice.refine(0.01);
  EXPECT_TRUE(lattice.around(3, 3).edgeCorner);   // cell (0, 0): its corners at i = 0, j = 0
  EXPECT_TRUE(lattice.around(12, 3).edgeCorner);  // cell (1, 0): corners at j = 0
  EXPECT_FALSE(lattice.around(12, 12).edgeCorner); // cell (1, 1): all inside
  EXPECT_TRUE(lattice.around(20, 12).edgeCorner); // cell (2, 1): (24, 16) on the edge
  // Cell (2, 2) lacks its (24, 24) corner and is refined: the second pass's corners.
  EXPECT_TRUE(lattice.gatheredInPass(20, 20, false));
  lattice.set(20, 20, gathered(false));
  lattice.set(16, 20, gathered(false));
  lattice.set(20, 16, gathered(false));
  EXPECT_FALSE(lattice.around(17, 17).edgeCorner); // (16, 16), (20, 16), (16, 20), (20, 20)
  lattice.set(24, 20, gathered(true));
  EXPECT_TRUE(lattice.around(21, 17).edgeCorner);  // (24, 16) and (24, 20) on the edge
  EXPECT_TRUE(lattice.around(21, 21).edgeCorner);  // (24, 20); (24, 24) has no data
  PostLattice inside(25, 25, 4);
  for (int j : { 0, 8, 16, 24 })
    for (int i : { 0, 8, 16, 24 })
      inside.set(i, j, gathered(false));
  inside.refine(0.01);
  EXPECT_FALSE(inside.around(3, 3).edgeCorner);
}

// A post reads each part's light per terrain seen, weighed by the share of its own
// terrain seen there: a post on a ridge that sees only the dim side reads the dim
// side's light, not the mean of the lattice posts that see both sides.
TEST(PostLattice, ReadsEachPartByTheShareOfTerrainThePostSeesThere)
{
  PostLattice lattice(9, 9, 4);
  const int brightSector = sectorOf(1.0, 0.1), dimSector = sectorOf(-1.0, 0.1);
  const int bright = viewPartOf(brightSector, false), dim = viewPartOf(dimSector, true);
  const int unseen = viewPartOf(sectorOf(0.1, -1.0), false);
  ASSERT_NE(brightSector, dimSector);
  ASSERT_NE(unseen / 2, brightSector);
  ASSERT_NE(unseen / 2, dimSector);
  // A corner that finds 10 W/m^2 from 0.1 of terrain near it on the bright side,
  // `dimLight` from 0.1 beyond on the dim side.
  auto twoSided = [&](double dimLight) {
    PostLattice::Gathered g;
    g.variance = 1.0;
    g.terrainSeen = 0.2;
    g.received = 100.0;
    g.reflectedByPart[bright] = uniformSpectrum(10.0);
    g.reflectedByPart[dim] = uniformSpectrum(dimLight);
    g.reflected = uniformSpectrum(10.0 + dimLight);
    g.terrainByPart[bright] = g.terrainByPart[dim] = 0.1;
    return g;
  };
  for (int j : { 0, 4, 8 })
    for (int i : { 0, 4, 8 })
      lattice.set(i, j, twoSided(1.0));
  Spectrum whole;
  ASSERT_TRUE(lattice.perTerrainSeenAt(2.0, 3.0, whole));
  EXPECT_DOUBLE_EQ(whole[0], 55.0);
  PostLattice::PartRead read;
  PerViewPart<double> shares{};
  shares[dim] = 1.0;
  ASSERT_TRUE(lattice.readByPart(2.0, 3.0, shares, true, read));
  EXPECT_NEAR(read.perTerrainSeen[0], 10.0, 1e-12);
  EXPECT_EQ(read.whole, whole);
  EXPECT_EQ(read.spread, 0.0); // every corner found the same
  // The two reads differ by at most the terrain seen times the corners' width across
  // their parts.
  EXPECT_DOUBLE_EQ(lattice.around(2, 3).partWidth, 90.0);
  shares[dim] = 0.25, shares[bright] = 0.75;
  ASSERT_TRUE(lattice.readByPart(2.0, 3.0, shares, true, read));
  EXPECT_NEAR(read.perTerrainSeen[0], 0.75 * 100.0 + 0.25 * 10.0, 1e-12);
  // A part where no lattice post met terrain takes its sector's other part's light per
  // terrain seen, and in a sector where none met terrain, the whole's.
  shares = PerViewPart<double>{};
  shares[unseen] = 0.5, shares[viewPartOf(brightSector, true)] = 0.5;
  ASSERT_TRUE(lattice.readByPart(2.0, 3.0, shares, true, read));
  EXPECT_NEAR(read.perTerrainSeen[0], 0.5 * 55.0 + 0.5 * 100.0, 1e-12);
  // The spread is each part's between the corners, by the post's shares: one corner
  // finding twice the dim side's light per terrain seen spreads it by 10.
  lattice.set(4, 4, twoSided(2.0));
  shares = PerViewPart<double>{};
  shares[dim] = 0.5, shares[bright] = 0.5;
  ASSERT_TRUE(lattice.readByPart(2.0, 3.0, shares, true, read));
  EXPECT_NEAR(read.spread, 0.5 * 10.0, 1e-12);
}

// Near and far in one sector: a post that sees only the far terrain reads the far
// part's light; by sector alone, the sector's (both parts together), and the two
// differ by at most the corners' distance width.
TEST(PostLattice, ReadsTheNearAndFarPartsOfASectorApart)
{
  PostLattice lattice(9, 9, 4);
  const int q = sectorOf(1.0, 0.1), near = viewPartOf(q, false), far = viewPartOf(q, true);
  for (int j : { 0, 4, 8 })
    for (int i : { 0, 4, 8 })
    {
      PostLattice::Gathered g;
      g.variance = 1.0;
      g.terrainSeen = 0.4;
      g.received = 100.0;
      g.reflectedByPart[near] = uniformSpectrum(30.0); // 100 per terrain seen from 0.3
      g.reflectedByPart[far] = uniformSpectrum(2.0);   // 20 from 0.1
      g.reflected = uniformSpectrum(32.0);
      g.terrainByPart[near] = 0.3, g.terrainByPart[far] = 0.1;
      lattice.set(i, j, g);
    }
  EXPECT_DOUBLE_EQ(lattice.around(2, 3).distanceWidth, 80.0);
  EXPECT_DOUBLE_EQ(lattice.around(2, 3).sectorWidth, 0.0); // one sector only
  PostLattice::PartRead read;
  PerViewPart<double> shares{};
  shares[far] = 1.0;
  ASSERT_TRUE(lattice.readByPart(2.0, 3.0, shares, true, read));
  EXPECT_NEAR(read.perTerrainSeen[0], 20.0, 1e-12);
  shares = PerViewPart<double>{};
  shares[near] = 1.0; // the sector's whole share, as terrainByPart gives it without the distance
  ASSERT_TRUE(lattice.readByPart(2.0, 3.0, shares, false, read));
  EXPECT_NEAR(read.perTerrainSeen[0], 32.0 / 0.4, 1e-12);
  EXPECT_LE(std::abs(read.perTerrainSeen[0] - 20.0), lattice.around(2, 3).distanceWidth);
}

// The lattice's light per terrain seen is per terrain its rays met; where its horizons
// show more (between azimuths, below the horizontal), a post that reads takes that
// excess off its own terrain seen, in proportion to its terrain seen and void as the
// lattice's posts around found it in theirs (the void weighing excessVoidWeight).
TEST(PostLattice, TellsHowMuchMoreTerrainTheMapShowsThanTheRaysMet)
{
  PostLattice lattice(9, 9, 4);
  Spectrum per;
  double excess = -1.0;
  EXPECT_FALSE(lattice.mapExcessAt(2.0, 3.0, 0.05, 0.01, excess)); // nothing gathered yet
  auto gathered = [](double terrainSeen, double voidSeen, double met) {
    PostLattice::Gathered g;
    g.variance = 1.0;
    g.terrainSeen = terrainSeen;
    g.voidSeen = voidSeen;
    g.terrainByPart[0] = met;
    g.reflected = uniformSpectrum(100.0 * met); // 100 W/m^2 per terrain its rays met
    g.received = 100.0;
    return g;
  };
  // Every lattice post: 0.05 of terrain and 0.01 of void by its horizons, 0.045 met by
  // its rays: an excess of 0.005 per 0.05 + 4 x 0.01 = 0.09.
  for (int j : { 0, 4, 8 })
    for (int i : { 0, 4, 8 })
      lattice.set(i, j, gathered(0.05, 0.01, 0.045));
  ASSERT_TRUE(lattice.perTerrainSeenAt(2.0, 3.0, per));
  EXPECT_DOUBLE_EQ(per[0], 100.0);
  const double perBasis = 0.005 / (0.05 + PostLattice::excessVoidWeight * 0.01);
  ASSERT_TRUE(lattice.mapExcessAt(2.0, 3.0, 0.05, 0.01, excess));
  EXPECT_NEAR(excess, 0.005, 1e-15);
  // A post that sees less terrain but more void (a ridge's) loses more of its terrain.
  ASSERT_TRUE(lattice.mapExcessAt(2.0, 3.0, 0.01, 0.02, excess));
  EXPECT_NEAR(excess, perBasis * (0.01 + PostLattice::excessVoidWeight * 0.02), 1e-15);
  ASSERT_TRUE(lattice.mapExcessAt(2.0, 3.0, 0.0, 0.0, excess));
  EXPECT_EQ(excess, 0.0);
  // A lattice post whose rays met more than its horizons show has a negative excess.
  // The 3 x 3 lattice posts around (4, 4) weigh 1 there, 1/2 beside, 1/4 diagonally
  // (their tent weights: 3 in all beside it), each by its own terrain seen and void (a
  // ratio of sums).
  lattice.set(4, 4, gathered(0.05, 0.0, 0.06));
  ASSERT_TRUE(lattice.mapExcessAt(4.0, 4.0, 0.05, 0.0, excess));
  EXPECT_NEAR(excess, 0.05 * (-0.01 + 3.0 * 0.005) / (0.05 + 3.0 * 0.09), 1e-15);
}

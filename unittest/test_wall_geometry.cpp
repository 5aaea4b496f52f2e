// Wall boundary conditions as pure functions (wall_geometry.h): bounce-back on a cylinder,
// near-wall layer membership, the wall's Maxwellian.
#include "wall_geometry.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {
double radial(const double p[3], int axis)
{
  const int b = (axis + 1) % 3, c = (axis + 2) % 3;
  return std::sqrt(p[b] * p[b] + p[c] * p[c]);
}
}    // namespace

TEST(CylinderBounce, RadialCrossingReturnsAlongThePathWithReversedVelocity)
{
  // axis z, R = 1: from x = 0.99 at vx = 3 over dt = 0.01 the atom meets the wall a third of
  // the way and travels the remaining two thirds back
  const double rel[3] = {1.02, 0.0, 0.0}, v[3] = {3.0, 0.0, 1.0};
  const etd::CylinderBounce b = etd::cylinder_bounce(rel, v, 0.01, 2, 1.0, true);
  EXPECT_TRUE(b.crossed);
  EXPECT_FALSE(b.projected);
  EXPECT_NEAR(b.x[0], 0.98, 1e-14);
  EXPECT_NEAR(b.x[1], 0.0, 1e-14);
  EXPECT_NEAR(b.x[2], -2.0 * (2.0 / 3.0) * 0.01, 1e-14);
  EXPECT_EQ(b.v[0], -3.0);
  EXPECT_EQ(b.v[1], -0.0);
  EXPECT_EQ(b.v[2], -1.0);
}

TEST(CylinderBounce, ObliqueCrossingHitsTheSurfaceAndEndsInside)
{
  // axis x: cross-section (y, z)
  const double v[3] = {0.7, 2.0, 1.5}, dt = 0.02;
  const double start[3] = {0.3, 1.95, 0.4};    // |(1.95, 0.4)| = 1.9906 < R = 2
  const double rel[3] = {start[0] + dt * v[0], start[1] + dt * v[1], start[2] + dt * v[2]};
  const etd::CylinderBounce b = etd::cylinder_bounce(rel, v, dt, 0, 2.0, true);
  ASSERT_TRUE(b.crossed);
  EXPECT_FALSE(b.projected);
  for (int k = 0; k < 3; k++) EXPECT_EQ(b.v[k], -v[k]);
  // the end point lies on the incoming line, and the turning point midway between the
  // unbounced and bounced end points is on the surface
  double turn[3];
  for (int k = 0; k < 3; k++) turn[k] = 0.5 * (rel[k] + b.x[k]);
  EXPECT_NEAR(radial(turn, 0), 2.0, 1e-12);
  EXPECT_LT(radial(b.x, 0), 2.0);
  const double s = (b.x[1] - start[1]) / (dt * v[1]);
  for (int k = 0; k < 3; k++) EXPECT_NEAR(b.x[k], start[k] + s * dt * v[k], 1e-14);
}

TEST(CylinderBounce, ObstacleSendsEnteringAtomsBackOut)
{
  // fluid outside a cylinder of radius 1 (axis y: cross-section (z, x))
  const double v[3] = {-4.0, 0.5, -1.0}, dt = 0.01;
  const double start[3] = {1.02, 0.0, 0.1};
  const double rel[3] = {start[0] + dt * v[0], start[1] + dt * v[1], start[2] + dt * v[2]};
  ASSERT_LT(radial(rel, 1), 1.0);
  const etd::CylinderBounce b = etd::cylinder_bounce(rel, v, dt, 1, 1.0, false);
  ASSERT_TRUE(b.crossed);
  EXPECT_FALSE(b.projected);
  EXPECT_GT(radial(b.x, 1), 1.0);
  double turn[3];
  for (int k = 0; k < 3; k++) turn[k] = 0.5 * (rel[k] + b.x[k]);
  EXPECT_NEAR(radial(turn, 1), 1.0, 1e-12);
  for (int k = 0; k < 3; k++) EXPECT_EQ(b.v[k], -v[k]);
}

TEST(CylinderBounce, AtomsOnTheFluidSideAreLeftAlone)
{
  const double rel[3] = {0.5, 0.5, 3.0}, v[3] = {10.0, 10.0, 10.0};
  for (bool inside : {true, false}) {
    const double radius = inside ? 1.0 : 0.5;
    const etd::CylinderBounce b = etd::cylinder_bounce(rel, v, 0.01, 2, radius, inside);
    EXPECT_FALSE(b.crossed);
    for (int k = 0; k < 3; k++) {
      EXPECT_EQ(b.x[k], rel[k]);
      EXPECT_EQ(b.v[k], v[k]);
    }
  }
}

TEST(CylinderBounce, FallsBackToTheRadiusWhenThePathCannotBeRetraced)
{
  // grazing path on a short chord: retracing it would leave the cylinder on the other side
  const double v[3] = {1.0, 50.0, 0.0}, dt = 0.01;    // D = (0.01, 0.5)
  const double rel[3] = {0.999 + 0.01, 0.5, 0.0};
  etd::CylinderBounce b = etd::cylinder_bounce(rel, v, dt, 2, 1.0, true);
  EXPECT_TRUE(b.crossed);
  EXPECT_TRUE(b.projected);
  EXPECT_LT(radial(b.x, 2), 1.0);
  EXPECT_NEAR(radial(b.x, 2), 1.0, 1e-8);
  EXPECT_EQ(b.v[1], -50.0);
  // an atom that was already outside (placed there) goes onto the surface along its radius
  const double outside[3] = {0.0, 1.5, 2.0}, still[3] = {0.0, 0.0, 0.0};
  b = etd::cylinder_bounce(outside, still, dt, 2, 1.0, true);
  EXPECT_TRUE(b.projected);
  EXPECT_NEAR(b.x[0], 0.0, 1e-15);
  EXPECT_NEAR(b.x[1], 1.0, 1e-8);
  EXPECT_LT(b.x[1], 1.0);
  EXPECT_EQ(b.x[2], 2.0);
}

TEST(WallLayer, MembershipIncludesThePlaneAndExcludesTheFarEdge)
{
  EXPECT_TRUE(etd::in_wall_layer(-15.0, -15.0, 0.5, true));
  EXPECT_TRUE(etd::in_wall_layer(-14.6, -15.0, 0.5, true));
  EXPECT_FALSE(etd::in_wall_layer(-14.5, -15.0, 0.5, true));
  EXPECT_FALSE(etd::in_wall_layer(-15.1, -15.0, 0.5, true));
  EXPECT_TRUE(etd::in_wall_layer(15.0, 15.0, 0.5, false));
  EXPECT_TRUE(etd::in_wall_layer(14.6, 15.0, 0.5, false));
  EXPECT_FALSE(etd::in_wall_layer(14.5, 15.0, 0.5, false));
  EXPECT_FALSE(etd::in_wall_layer(15.1, 15.0, 0.5, false));
}

TEST(WallLayer, MaxwellianHasTheWallVelocityAndThermalSpread)
{
  EXPECT_DOUBLE_EQ(etd::wall_maxwellian(7.5, 1.0, 0.01, 0.0), 7.5);
  EXPECT_DOUBLE_EQ(etd::wall_maxwellian(7.5, 1.0, 0.01, 1.0), 17.5);
  EXPECT_DOUBLE_EQ(etd::wall_maxwellian(0.0, 0.25, 1.0, -2.0), -1.0);
}

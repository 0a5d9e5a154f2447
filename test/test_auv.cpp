//! Tests of the simulated AUV (vpSSLAuvSimulator): dynamics, autopilot, current, sensors and collision.
#include <cmath>

#include <gtest/gtest.h>

#include <visp3/core/vpException.h>
#include <visp3/core/vpMath.h>
#include <visp3/core/vpRzyxVector.h>
#include <visp3/ssl/vpSSLFinite.h>
#include <visp3/ssl_sim/vpSSLAuvSimulator.h>
#include <visp3/ssl_sim/vpSSLScenario.h>

#include "ssl_test_utils.h"

namespace {
// Vehicle level, heading north, at depth 2.5 m, \e north metres north of the world origin.
vpHomogeneousMatrix vehicleAt(double north, double yawDeg = 0., double rollDeg = 0.)
{
  return vpHomogeneousMatrix(vpTranslationVector(north, 0., 2.5),
                             vpRotationMatrix(vpRzyxVector(vpMath::rad(yawDeg), 0., vpMath::rad(rollDeg))));
}

vpColVector twist(double u, double v, double w, double p, double q, double r)
{
  vpColVector c(6);
  c[0] = u;
  c[1] = v;
  c[2] = w;
  c[3] = p;
  c[4] = q;
  c[5] = r;
  return c;
}

// Simulator with the target at home (origin, 2.5 m deep, facing south) and the vehicle \e range metres south of it.
vpSSLAuvSimulator atRange(double range, long seed = 1)
{
  vpSSLAuvSimulator auv;
  auv.setTimeStep(0.1);
  auv.setTargetPose(vpSSLScenario("approach").getTargetHome());
  auv.reset(vehicleAt(-range), seed);
  return auv;
}
} // namespace

TEST(AuvSimulator, ReachesTheStarbugTopSpeedUnderFullSurge)
{
  vpSSLAuvSimulator auv = atRange(100.);
  EXPECT_NEAR(auv.getTopSpeed(0), 1.5, 1e-3);
  for (int i = 0; i < 300; ++i) {
    auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist(3., 0., 0., 0., 0., 0.));
  }
  EXPECT_NEAR(auv.getBodyVelocity()[0], 1.5, 0.02);
  EXPECT_NEAR(auv.getThrust()[0], auv.getParameters().thrustLimit[0], 1e-9);
  EXPECT_GE(auv.getNbSaturatedAxes(), 1u);
  // It went straight: no sway, no heave, no turn.
  EXPECT_NEAR(auv.get_wMv()[1][3], 0., 1e-6);
  EXPECT_NEAR(auv.get_wMv()[2][3], 2.5, 1e-6);
}

TEST(AuvSimulator, SwayIsMarginal)
{
  vpSSLAuvSimulator auv = atRange(100.);
  for (int i = 0; i < 300; ++i) {
    auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist(0., 1., 0., 0., 0., 0.));
  }
  EXPECT_LT(auv.getBodyVelocity()[1], 0.15);
  EXPECT_NEAR(auv.getBodyVelocity()[1], auv.getTopSpeed(1), 0.01);
}

TEST(AuvSimulator, TracksAReachableDemandWithLag)
{
  vpSSLAuvSimulator auv = atRange(100.);
  auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist(0.5, 0., 0.1, 0., 0., 0.3));
  // After 0.1 s the vehicle has not reached the demand yet (inertia)...
  EXPECT_LT(auv.getBodyVelocity()[0], 0.4);
  EXPECT_LT(auv.getBodyVelocity()[5], 0.25);
  for (int i = 0; i < 100; ++i) {
    auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist(0.5, 0., 0.1, 0., 0., 0.3));
  }
  // ...after 10 s it has (the integrator removes the error left by the Coriolis terms of the turn).
  EXPECT_NEAR(auv.getBodyVelocity()[0], 0.5, 0.02);
  EXPECT_NEAR(auv.getBodyVelocity()[2], 0.1, 0.02);
  EXPECT_NEAR(auv.getBodyVelocity()[5], 0.3, 0.02);
}

TEST(AuvSimulator, DragStopsTheVehicle)
{
  vpSSLAuvSimulator auv = atRange(100.);
  for (int i = 0; i < 100; ++i) {
    auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist(1.5, 0., 0., 0., 0., 0.3));
  }
  // Without any thrust the drag alone brings it to rest.
  vpSSLAuvSimulator::vpSSLAuvParameters p = auv.getParameters();
  for (double &g : p.velocityGain) {
    g = 1e-9;
  }
  for (double &g : p.velocityIntegralGain) {
    g = 0.;
  }
  auv.setParameters(p);
  auv.init(); // autopilot integrators zeroed, vehicle at rest... so give it its speed back:
  for (int i = 0; i < 100; ++i) {
    auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist(1.5, 0., 0., 0., 0., 0.)); // feed-forward alone: 1.5 m/s
  }
  EXPECT_GT(auv.getBodyVelocity()[0], 1.4);
  for (int i = 0; i < 600; ++i) {
    auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist(0., 0., 0., 0., 0., 0.));
  }
  EXPECT_LT(vpColVector(auv.getBodyVelocity()).frobeniusNorm(), 0.01);
}

TEST(AuvSimulator, ThrustNeverExceedsTheLimits)
{
  vpSSLAuvSimulator auv = atRange(100.);
  const vpSSLAuvSimulator::vpSSLAuvParameters &p = auv.getParameters();
  for (int i = 0; i < 200; ++i) {
    const double s = (i / 20) % 2 ? 1. : -1.;
    auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist(5. * s, -3. * s, 2. * s, 1. * s, -2. * s, 4. * s));
    for (unsigned int k = 0; k < 6; ++k) {
      ASSERT_LE(std::fabs(auv.getThrust()[k]), p.thrustLimit[k] * (1. + 1e-12)) << "axis " << k;
    }
    ASSERT_TRUE(vpSSLFinite::isFinite(auv.get_wMv()));
  }
}

TEST(AuvSimulator, CurrentDriftsAVehicleHoldingStill)
{
  vpSSLAuvSimulator auv = atRange(100.);
  auv.setCurrent(vpTranslationVector(0., 0.2, 0.)); // 0.2 m/s towards the east
  for (int i = 0; i < 200; ++i) {
    auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist(0., 0., 0., 0., 0., 0.));
  }
  // The autopilot holds zero speed through the water: the vehicle drifts with the water, 4 m in 20 s.
  EXPECT_GT(auv.get_wMv()[1][3], 3.5);
  EXPECT_NEAR(auv.get_wMv()[0][3], -100., 0.1);
  // A sinusoidal sway averages out over its period.
  vpSSLAuvSimulator sway = atRange(100.);
  sway.setCurrent(vpTranslationVector(0., 0., 0.), 0.3, 10.);
  EXPECT_NEAR(sway.getCurrent(2.5)[1], 0.3, 1e-9);
  EXPECT_NEAR(sway.getCurrent(7.5)[1], -0.3, 1e-9);
  for (int i = 0; i < 200; ++i) {
    sway.setVelocity(vpRobot::ARTICULAR_FRAME, twist(0., 0., 0., 0., 0., 0.));
  }
  EXPECT_LT(std::fabs(sway.get_wMv()[1][3]), 0.5);
}

TEST(AuvSimulator, RightsItselfInRoll)
{
  vpSSLAuvSimulator auv;
  auv.setTimeStep(0.1);
  auv.reset(vehicleAt(0., 0., 20.), 1);
  for (int i = 0; i < 200; ++i) {
    auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist(0., 0., 0., 0., 0., 0.));
  }
  const vpRzyxVector rzyx(auv.get_wMv().getRotationMatrix());
  EXPECT_LT(std::fabs(vpMath::deg(rzyx[2])), 1.);
}

TEST(AuvSimulator, CameraTwistIsMappedThroughTheMount)
{
  vpSSLAuvSimulator a = atRange(100.), b = atRange(100.);
  for (int i = 0; i < 50; ++i) {
    a.setVelocity(vpRobot::CAMERA_FRAME, twist(0., 0., 0.5, 0., 0., 0.)); // along the optical axis
    b.setVelocity(vpRobot::ARTICULAR_FRAME, twist(0.5, 0., 0., 0., 0., 0.));
  }
  for (unsigned int i = 0; i < 4; ++i) {
    for (unsigned int j = 0; j < 4; ++j) {
      EXPECT_NEAR(a.get_wMv()[i][j], b.get_wMv()[i][j], 1e-9);
    }
  }
  // A camera pan (about its y axis, the vehicle's z) is a yaw, with the sway of a camera 0.5 m ahead.
  vpSSLAuvSimulator c = atRange(100.);
  c.setVelocity(vpRobot::CAMERA_FRAME, twist(0., 0., 0., 0., 0.2, 0.));
  EXPECT_NEAR(c.getDemand()[5], 0.2, 1e-12);
  EXPECT_NEAR(c.getDemand()[1], -0.1, 1e-12);
}

TEST(AuvSimulator, RejectsNonFiniteCommandsAndKeepsItsState)
{
  vpSSLAuvSimulator auv = atRange(10.);
  auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist(0.3, 0., 0., 0., 0., 0.));
  const vpHomogeneousMatrix before = auv.get_wMv();
  const double t = auv.getTime();
  EXPECT_THROW(auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist(NAN, 0., 0., 0., 0., 0.)), vpException);
  EXPECT_THROW(auv.setVelocity(vpRobot::CAMERA_FRAME, twist(0., 0., 0., 0., 0., INFINITY)), vpException);
  EXPECT_THROW(auv.setVelocity(vpRobot::ARTICULAR_FRAME, vpColVector(5, 0.)), vpException);
  EXPECT_THROW(auv.setVelocity(vpRobot::MIXT_FRAME, twist(0., 0., 0., 0., 0., 0.)), vpException);
  EXPECT_EQ(auv.getTime(), t);
  EXPECT_EQ(auv.get_wMv(), before);
  EXPECT_NEAR(auv.getDemand()[0], 0.3, 0.);
  EXPECT_THROW(auv.setTimeStep(0.), vpException);
  EXPECT_THROW(auv.setTimeStep(NAN), vpException);
  EXPECT_THROW(auv.step(-1.), vpException);
  EXPECT_THROW(auv.setCurrent(vpTranslationVector(NAN, 0., 0.)), vpException);
}

TEST(AuvSimulator, DeterministicForASeed)
{
  vpSSLAuvSimulator a = atRange(3., 7), b = atRange(3., 7), c = atRange(3., 8);
  a.setCurrent(vpTranslationVector(0.05, 0.1, 0.), 0.1, 8.);
  b.setCurrent(vpTranslationVector(0.05, 0.1, 0.), 0.1, 8.);
  c.setCurrent(vpTranslationVector(0.05, 0.1, 0.), 0.1, 8.);
  double ra = 0., rb = 0., rc = 0.;
  for (int i = 0; i < 20; ++i) {
    const vpColVector v = twist(0.2, 0., 0.05, 0., 0.02, 0.02 * std::sin(0.3 * i));
    a.setVelocity(vpRobot::ARTICULAR_FRAME, v);
    b.setVelocity(vpRobot::ARTICULAR_FRAME, v);
    c.setVelocity(vpRobot::ARTICULAR_FRAME, v);
    ra += a.getDepthMeasurement() + a.getFrontRange();
    rb += b.getDepthMeasurement() + b.getFrontRange();
    rc += c.getDepthMeasurement() + c.getFrontRange();
    ASSERT_TRUE(std::isfinite(ra)) << "the board is in range";
  }
  EXPECT_EQ(a.get_wMv(), b.get_wMv());
  EXPECT_EQ(a.getOdometry(), b.getOdometry());
  EXPECT_EQ(ra, rb);
  // The seed changes the sensors, not the physics.
  EXPECT_EQ(a.get_wMv(), c.get_wMv());
  EXPECT_NE(a.getOdometry(), c.getOdometry());
  EXPECT_NE(ra, rc);
}

TEST(AuvSimulator, DepthSensorIsUnbiasedWithCentimetreNoise)
{
  vpSSLAuvSimulator auv = atRange(10.);
  double sum = 0., sum2 = 0.;
  const int n = 2000;
  for (int i = 0; i < n; ++i) {
    const double e = auv.getDepthMeasurement() - auv.getDepth();
    sum += e;
    sum2 += e * e;
  }
  EXPECT_NEAR(sum / n, 0., 0.003);
  EXPECT_NEAR(std::sqrt(sum2 / n), 0.02, 0.003);
}

TEST(AuvSimulator, OdometryFollowsTheVehicleWithDrift)
{
  vpSSLAuvSimulator auv = atRange(30.);
  for (int i = 0; i < 100; ++i) {
    auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist(1., 0., 0., 0., 0., 0.));
  }
  // About 9.5 m travelled north (0.5 s of acceleration): the odometry says so within its 5 % scale error budget.
  const double travelled = auv.get_wMv()[0][3] + 30.;
  EXPECT_GT(travelled, 9.);
  EXPECT_NEAR(auv.getOdometry()[0][3], travelled, 0.2 * travelled);
  EXPECT_NE(auv.getOdometry()[0][3], travelled);
}

TEST(AuvSimulator, FrontRangeSeesTheBoardOnlyWhenInFront)
{
  vpSSLAuvSimulator auv = atRange(2.);
  // Vehicle origin 2 m from the board, nose 0.6 m ahead.
  EXPECT_NEAR(auv.getTrueFrontRange(), 1.4, 1e-9);
  EXPECT_NEAR(auv.getFrontRange(), 1.4, 0.05);
  auv.reset(vehicleAt(-2., 30.), 1); // turned 30 deg: the axis misses the 0.6 m board
  EXPECT_TRUE(std::isnan(auv.getTrueFrontRange()));
  auv.reset(vehicleAt(-2., 180.), 1); // facing away
  EXPECT_TRUE(std::isnan(auv.getFrontRange()));
  auv.reset(vehicleAt(-2.), 1);
  auv.setTargetInWater(false); // out of the water
  EXPECT_TRUE(std::isnan(auv.getFrontRange()));
  auv.setTargetInWater(true);
  auv.setRangeSensor(1., 0.01); // beyond its range
  EXPECT_TRUE(std::isnan(auv.getFrontRange()));
}

TEST(AuvSimulator, CollisionFlagTripsAndTheBoardStopsTheNose)
{
  vpSSLAuvSimulator auv = atRange(2.);
  EXPECT_FALSE(auv.getCollision());
  for (int i = 0; i < 100 && !auv.getCollision(); ++i) {
    auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist(0.4, 0., 0., 0., 0., 0.));
  }
  ASSERT_TRUE(auv.getCollision());
  // 1.4 m at up to 0.4 m/s, after a short acceleration.
  EXPECT_GT(auv.getFirstCollisionTime(), 3.4);
  EXPECT_LT(auv.getFirstCollisionTime(), 5.);
  // Pushing on: the nose stays on the board, the flag stays up.
  for (int i = 0; i < 50; ++i) {
    auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist(1., 0., 0., 0., 0., 0.));
  }
  EXPECT_TRUE(auv.getCollision());
  EXPECT_NEAR(auv.get_wMv()[0][3], -0.6, 0.01);
  EXPECT_NEAR(auv.getTrueFrontRange(), 0., 0.01);
  // Backing off clears it.
  for (int i = 0; i < 30; ++i) {
    auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist(-0.3, 0., 0., 0., 0., 0.));
  }
  EXPECT_FALSE(auv.getCollision());
  // A vehicle passing beside the board never collides.
  auv.reset(vpHomogeneousMatrix(vpTranslationVector(-2., 1., 2.5), vpRotationMatrix()), 1);
  for (int i = 0; i < 100; ++i) {
    auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist(0.5, 0., 0., 0., 0., 0.));
    ASSERT_FALSE(auv.getCollision());
  }
}

TEST(AuvSimulator, VpRobotInterface)
{
  vpSSLAuvSimulator auv = atRange(5.);
  vpRobot &robot = auv;
  vpColVector q;
  robot.getPosition(vpRobot::REFERENCE_FRAME, q);
  EXPECT_NEAR(q[0], -5., 1e-12);
  robot.setVelocity(vpRobot::ARTICULAR_FRAME, twist(0.5, 0., 0., 0., 0., 0.));
  robot.getDisplacement(vpRobot::ARTICULAR_FRAME, q);
  EXPECT_GT(q[0], 0.);
  robot.getPosition(vpRobot::CAMERA_FRAME, q);
  EXPECT_NEAR(q[0], auv.get_wMc()[0][3], 1e-12);
  vpMatrix J;
  robot.get_eJe(J);
  EXPECT_EQ(J.getRows(), 6u);
  robot.setPosition(vpRobot::REFERENCE_FRAME, vpPoseVector(vehicleAt(-3.)));
  EXPECT_NEAR(auv.get_wMv()[0][3], -3., 1e-12);
  EXPECT_NEAR(auv.getBodyVelocity().frobeniusNorm(), 0., 0.);
  // cMo of the target straight ahead: on the optical axis, 3 - 0.5 m away, facing the camera.
  const vpHomogeneousMatrix cMo = auv.get_cMo();
  EXPECT_NEAR(cMo[0][3], 0., 1e-9);
  EXPECT_NEAR(cMo[1][3], 0., 1e-9);
  EXPECT_NEAR(cMo[2][3], 2.5, 1e-9);
  EXPECT_NEAR(cMo[2][2], 1., 1e-9);
}

//! Closed loop of the homing behaviour (servo/) on the simulated AUV, with a perfect target sensor (no rendering).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include <gtest/gtest.h>

#include <visp3/core/vpPoint.h>
#include <visp3/core/vpRxyzVector.h>
#include <visp3/ssl/vpSSLAuvSimulator.h>
#include <visp3/ssl/vpSSLHomingBehaviour.h>
#include <visp3/ssl/vpSSLScenario.h>
#include <visp3/ssl/vpSSLServoInput.h>

TEST(AuvClosedLoop, HomingReachesTheStandOffWithAPerfectSensor)
{
  vpSSLAuvSimulator auv;
  auv.setTimeStep(0.1); // 10 Hz control, 5 ms dynamics sub-steps
  auv.setTargetPose(vpSSLScenario("approach").getTargetHome());
  // 4.5 m south of the target, 0.3 m off its axis, heading 10 degrees off.
  auv.reset(vpHomogeneousMatrix(vpTranslationVector(-4.5, 0.3, 2.7), vpRotationMatrix(vpRxyzVector(0., 0., 0.17))), 3);
  const std::vector<vpPoint> points = {vpPoint(-0.15, -0.1, 0.), vpPoint(0.15, -0.1, 0.), vpPoint(0.15, 0.1, 0.),
                                       vpPoint(-0.15, 0.1, 0.)};
  vpSSLHomingBehaviour homing;
  homing.getServoLaw().setCameraToVehicle(auv.getCameraToVehicle());
  homing.setStandOff(2.0);
  double range = NAN;
  for (int i = 0; i < 600; ++i) {
    const vpHomogeneousMatrix cMo = auv.get_cMo();
    const vpSSLServoInput input = cMo[2][3] > 0. ? vpSSLServoInput::fromPose(points, cMo) : vpSSLServoInput::none();
    homing.update(auv.getTime(), input, auv.getDepthMeasurement(), auv.getCollision());
    homing.apply(auv);
    range = auv.get_cMo()[2][3];
    ASSERT_FALSE(auv.getCollision());
  }
  EXPECT_EQ(homing.getState(), SSL_HOMING_HOME);
  EXPECT_NEAR(range, 2.0, 0.15);
  EXPECT_NEAR(auv.get_cMo()[0][3], 0., 0.2);
}

TEST(AuvClosedLoop, DockingHitsTheBoardAtTheTargetDepth)
{
  // fig9 with a perfect sensor: hold the 2 m stand-off, then dock. Before the servo law dropped its near-singular
  // heave-pitch direction the vehicle dived 1.3 m in DOCK and passed under the board without a collision.
  vpSSLAuvSimulator auv;
  auv.setTimeStep(0.2); // the scenarios' 5 Hz vision
  const vpHomogeneousMatrix wMo = vpSSLScenario("approach").getTargetHome();
  auv.setTargetPose(wMo);
  const vpTranslationVector t = wMo.getTranslationVector();
  auv.reset(vpHomogeneousMatrix(vpTranslationVector(t[0] - 4.5, t[1] + 0.3, t[2] + 0.2),
                                vpRotationMatrix(vpRxyzVector(0., 0., 0.17))),
            1);
  const std::vector<vpPoint> points = {vpPoint(-0.15, -0.1, 0.), vpPoint(0.15, -0.1, 0.), vpPoint(0.15, 0.1, 0.),
                                       vpPoint(-0.15, 0.1, 0.)};
  vpSSLHomingBehaviour homing;
  homing.getServoLaw().setCameraToVehicle(auv.getCameraToVehicle());
  homing.setStandOff(2.0);
  homing.setAutoDock(10.);
  homing.setBlindDock(1.3, 0.15);
  double worstDepthError = 0., dockTime = NAN;
  for (int i = 0; i < 450 && homing.getState() != SSL_HOMING_DOCKED; ++i) {
    const vpHomogeneousMatrix cMo = auv.get_cMo();
    const bool inView =
        cMo[2][3] > 0.05 && std::fabs(cMo[0][3] / cMo[2][3]) < 0.6 && std::fabs(cMo[1][3] / cMo[2][3]) < 0.45;
    const vpSSLServoInput input = inView ? vpSSLServoInput::fromPose(points, cMo) : vpSSLServoInput::none();
    homing.update(auv.getTime(), input, auv.getDepthMeasurement(), auv.getCollision());
    if (homing.getState() == SSL_HOMING_DOCK) {
      worstDepthError = std::max(worstDepthError, std::fabs(auv.getDepth() - t[2]));
    }
    if (homing.getState() == SSL_HOMING_DOCKED) {
      dockTime = auv.getTime();
    }
    homing.apply(auv);
  }
  ASSERT_EQ(homing.getState(), SSL_HOMING_DOCKED);
  EXPECT_LT(worstDepthError, 0.15); // the board is 0.45 m high
  std::cout << "[figures] docked at " << dockTime << " s, worst depth error in DOCK " << worstDepthError << " m"
            << std::endl;
}

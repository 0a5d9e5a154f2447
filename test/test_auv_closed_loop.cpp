//! Closed loop of the homing behaviour (servo/) on the simulated AUV, with a perfect target sensor (no rendering).
#include <cmath>
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

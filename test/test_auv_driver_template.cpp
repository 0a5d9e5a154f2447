/*
  The AUV driver skeleton users copy (modules/bench/include/visp3/ssl_harness/vpSSLRobotAuvTemplate.h): each control
  frame of vpRobot::setVelocity() reaches the vehicle as the body twist it means, within the limits and with its
  direction kept, and what is not a velocity command is refused.
*/
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include <visp3/core/vpExponentialMap.h>
#include <visp3/core/vpMath.h>
#include <visp3/ssl_servo/vpSSLServoLaw.h>

#include <visp3/ssl_harness/vpSSLRobotAuvTemplate.h>

namespace {
// A camera that gives a black image: the tests read the navigation only.
class BlackCamera : public vpFrameGrabber
{
public:
  void open(vpImage<unsigned char> &I) override { I.resize(2, 2, 0); }
  void open(vpImage<vpRGBa> &I) override { I.resize(2, 2); }
  void acquire(vpImage<unsigned char> &I) override { I.resize(2, 2, 0); }
  void acquire(vpImage<vpRGBa> &I) override { I.resize(2, 2); }
  void close() override {}
};

struct Fixture
{
  BlackCamera camera;
  vpSSLRobotAuvTemplate auv;
  vpImage<unsigned char> I;
  vpHomogeneousMatrix oMv;
  double depth = 0.;
  bool collision = true;
  Fixture()
  {
    auv.setCamera(camera, vpSSLServoLaw::forwardCameraMount(0.5));
    auv.setTimeStep(0.5);
    auv.init();
    auv.setRobotState(vpRobot::STATE_VELOCITY_CONTROL);
  }
  void step() { auv.acquire(I, oMv, depth, collision); }
};

// (surge, sway, heave, roll, pitch, yaw rates) or any 6-vector.
vpColVector twist(const std::vector<double> &v)
{
  return vpColVector(v);
}
} // namespace

TEST(AuvDriverTemplate, BodyTwistMovesTheOdometryAlongTheExponentialMap)
{
  Fixture f;
  const vpColVector v = twist({0.4, 0., 0.1, 0., 0., 0.2});
  f.auv.setVelocity(vpRobot::ARTICULAR_FRAME, v);
  f.step();
  const vpHomogeneousMatrix expected = vpExponentialMap::direct(v, 0.5);
  for (unsigned int i = 0; i < 3; ++i) {
    for (unsigned int j = 0; j < 4; ++j) {
      EXPECT_NEAR(f.oMv[i][j], expected[i][j], 1e-12);
    }
  }
  EXPECT_DOUBLE_EQ(f.auv.getTime(), 0.5);
  EXPECT_TRUE(std::isnan(f.depth)); // no pressure sensor in the stand-in
  EXPECT_FALSE(f.collision);
}

TEST(AuvDriverTemplate, ReferenceFrameTwistIsTurnedIntoTheBodyFrame)
{
  Fixture f;
  // Turn the vehicle 90 deg to starboard (yaw), then ask to move north in the odometry frame: that is to port.
  f.auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist({0., 0., 0., 0., 0., M_PI / 4.}));
  for (int i = 0; i < 4; ++i) { // 4 steps of 0.5 s
    f.step();
  }
  ASSERT_NEAR(f.oMv[1][0], 1., 1e-9); // vehicle x along the odometry y (east)
  f.auv.setVelocity(vpRobot::REFERENCE_FRAME, twist({0.3, 0., 0., 0., 0., 0.}));
  const vpColVector v = f.auv.getVelocity();
  EXPECT_NEAR(v[0], 0., 1e-9);
  EXPECT_NEAR(v[1], -0.3, 1e-9);
  EXPECT_NEAR(v[5], 0., 1e-9);
}

TEST(AuvDriverTemplate, CameraTwistOfAForwardCameraIsSurge)
{
  Fixture f;
  f.auv.setVelocity(vpRobot::CAMERA_FRAME, twist({0., 0., 0.25, 0., 0., 0.})); // along the optical axis
  const vpColVector v = f.auv.getVelocity();
  EXPECT_NEAR(v[0], 0.25, 1e-12);
  EXPECT_NEAR(v[1], 0., 1e-12);
  EXPECT_NEAR(v[2], 0., 1e-12);
}

TEST(AuvDriverTemplate, LimitsScaleTheWholeTwist)
{
  Fixture f;
  f.auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist({3., 0., 1.5, 0., 0., 0.5})); // surge 3x the 1 m/s limit
  const vpColVector v = f.auv.getVelocity();
  EXPECT_NEAR(v[0], 1., 1e-12);
  EXPECT_NEAR(v[2], 0.5, 1e-12);
  EXPECT_NEAR(v[5], 0.5 / 3., 1e-12);
}

TEST(AuvDriverTemplate, RefusesWhatIsNotAVelocityCommand)
{
  Fixture f;
  const vpColVector before = f.auv.getVelocity();
  EXPECT_THROW(f.auv.setVelocity(vpRobot::ARTICULAR_FRAME, vpColVector(5, 0.)), vpException);
  EXPECT_THROW(f.auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist({NAN, 0., 0., 0., 0., 0.})), vpException);
  EXPECT_THROW(f.auv.setVelocity(vpRobot::MIXT_FRAME, twist({0.1, 0., 0., 0., 0., 0.})), vpRobotException);
  EXPECT_THROW(f.auv.setPosition(vpRobot::REFERENCE_FRAME, vpColVector(6, 0.)), vpRobotException);
  EXPECT_EQ(f.auv.getVelocity(), before);
  f.auv.setRobotState(vpRobot::STATE_STOP);
  EXPECT_THROW(f.auv.setVelocity(vpRobot::ARTICULAR_FRAME, twist({0.1, 0., 0., 0., 0., 0.})), vpRobotException);
  vpSSLRobotAuvTemplate noCamera;
  vpImage<unsigned char> I;
  vpHomogeneousMatrix oMv;
  double depth = 0.;
  bool collision = false;
  EXPECT_THROW(noCamera.acquire(I, oMv, depth, collision), vpException);
}

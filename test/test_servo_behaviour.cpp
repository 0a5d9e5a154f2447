/*
  vpSSLHomingBehaviour (paper Sec. 5.2): search -> align -> home -> dock -> docked on a closed loop through
  ViSP's vpSimulatorCamera carried by a simulated vehicle, loss of the target back to search and re-acquisition,
  every transition on synthetic inputs, and garbage that never gives a NaN or an unbounded command.
*/
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

#include <visp3/core/vpMath.h>
#include <visp3/core/vpUniRand.h>
#include <visp3/robot/vpSimulatorCamera.h>
#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/ssl_servo/vpSSLHomingBehaviour.h>

namespace {
const double kDt = 0.04;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

bool finite(const vpColVector &v)
{
  for (unsigned int i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i])) {
      return false;
    }
  }
  return true;
}

void expectBounded(const vpSSLHomingBehaviour &b, const vpColVector &v)
{
  ASSERT_EQ(v.size(), 6u);
  ASSERT_TRUE(finite(v));
  ASSERT_TRUE(finite(b.getCameraVelocity()));
  for (unsigned int i = 0; i < 6; ++i) {
    EXPECT_LE(std::fabs(v[i]), b.getServoLaw().getVelocityLimits()[i] * (1. + 1e-12)) << "axis " << i;
  }
}

// The ssl3-a3 target seen at cMo through a 640x480 camera of 600 px focal length, as an ideal detector would
// report it: only the landmark centres inside the image count.
vpSSLServoInput observe(const vpHomogeneousMatrix &cMo)
{
  vpSSLServoInput in = vpSSLServoInput::fromPose(vpSSLTarget::ssl3a3().getPoints(), cMo);
  std::vector<vpSSLServoPoint> visible;
  for (const vpSSLServoPoint &p : in.points) {
    if (p.Z > 0.05 && std::fabs(p.x) < 320. / 600. && std::fabs(p.y) < 240. / 600.) {
      visible.push_back(p);
    }
  }
  if (visible.empty()) {
    return vpSSLServoInput::none();
  }
  in.points = visible;
  in.nbPoints = static_cast<unsigned int>(visible.size());
  return in;
}

/*
  A vehicle carrying a forward-looking camera, simulated by moving the camera with vpSimulatorCamera (the camera
  twist of a vehicle command is the motion of a camera rigidly mounted on it). World frame North-East-Down, the
  target at 6 m north, 2 m deep, facing south (towards the start).
*/
class VehicleWorld
{
public:
  explicit VehicleWorld(double startYawDeg)
      : m_vMc(vpSSLServoLaw::forwardCameraMount(0.5)),
        m_wMo(vpTranslationVector(6., 0., 2.), vpSSLServoLaw::forwardCameraMount(0.).getRotationMatrix())
  {
    m_robot.setSamplingTime(kDt);
    const vpHomogeneousMatrix wMv(vpTranslationVector(0., 0., 1.),
                                  vpRotationMatrix(vpRzyxVector(vpMath::rad(startYawDeg), 0., 0.)));
    m_robot.setPosition(wMv * m_vMc);
  }
  const vpHomogeneousMatrix &getCameraToVehicle() const { return m_vMc; }
  vpHomogeneousMatrix cMo() const { return m_robot.getPosition().inverse() * m_wMo; }
  double depth() const { return (m_robot.getPosition() * m_vMc.inverse())[2][3]; }
  // The nose (the camera) touches the sheet: the sheet's centre is just ahead of it.
  bool collision() const
  {
    const vpHomogeneousMatrix M = cMo();
    return M[2][3] > -0.05 && M[2][3] < 0.08 && std::fabs(M[0][3]) < 0.2 && std::fabs(M[1][3]) < 0.15;
  }
  vpSimulatorCamera &robot() { return m_robot; }

private:
  vpHomogeneousMatrix m_vMc;
  vpHomogeneousMatrix m_wMo;
  vpSimulatorCamera m_robot;
};

vpSSLHomingBehaviour makeBehaviour(const vpHomogeneousMatrix &vMc)
{
  vpSSLHomingBehaviour b;
  b.getServoLaw().setCameraToVehicle(vMc);
  b.setStandOff(2.);
  return b;
}

// Facing the target at 2 m, centred; or off to the side by angleDeg.
vpSSLServoInput facing(double range, double angleDeg = 0.)
{
  const vpHomogeneousMatrix cMo(vpTranslationVector(range * std::tan(vpMath::rad(angleDeg)), 0., range),
                                vpRotationMatrix());
  return vpSSLServoInput::fromPose(vpSSLTarget::ssl3a3().getPoints(), cMo);
}
} // namespace

TEST(HomingBehaviour, SearchAlignHomeDockDockedInClosedLoop)
{
  VehicleWorld world(100.); // facing away from the target
  vpSSLHomingBehaviour b = makeBehaviour(world.getCameraToVehicle());
  b.setAutoDock(5., 0.05);
  std::vector<vpSSLHomingState> states{b.getState()};
  std::vector<double> times{0.};
  double homeRangeError = kNaN;
  double t = 0.;
  for (int k = 0; k < 5000 && b.getState() != SSL_HOMING_DOCKED; ++k, t += kDt) {
    const vpColVector v = b.update(t, observe(world.cMo()), world.depth(), world.collision());
    expectBounded(b, v);
    if (b.getState() != states.back()) {
      states.push_back(b.getState());
      times.push_back(t);
    }
    if (b.getState() == SSL_HOMING_HOME) {
      homeRangeError = std::fabs(b.getRange() - 2.);
    }
    b.apply(world.robot(), vpRobot::CAMERA_FRAME);
  }
  const std::vector<vpSSLHomingState> expected{SSL_HOMING_SEARCH, SSL_HOMING_ALIGN, SSL_HOMING_HOME, SSL_HOMING_DOCK,
                                               SSL_HOMING_DOCKED};
  ASSERT_EQ(states.size(), expected.size());
  for (size_t i = 0; i < states.size(); ++i) {
    EXPECT_EQ(states[i], expected[i]) << "transition " << i << ": " << vpSSLHomingBehaviour::getStateName(states[i]);
  }
  // Auto dock needs the stand-off held within 5 cm.
  EXPECT_LT(homeRangeError, 0.05);
  EXPECT_EQ(b.getCollision(), 1u);
  // Docked: the command stays zero.
  const vpColVector v = b.update(t, observe(world.cMo()), world.depth(), world.collision());
  EXPECT_EQ(v.frobeniusNorm(), 0.);
  std::cout << "[figures] closed loop:";
  for (size_t i = 0; i < states.size(); ++i) {
    std::cout << " " << vpSSLHomingBehaviour::getStateName(states[i]) << "@" << times[i] << "s";
  }
  std::cout << std::endl;
}

TEST(HomingBehaviour, LossBeyondTheTimeoutReturnsToSearchAndTheTargetIsReacquired)
{
  VehicleWorld world(0.); // the target is ahead
  vpSSLHomingBehaviour b = makeBehaviour(world.getCameraToVehicle());
  b.setLostTimeout(3.);
  double t = 0.;
  auto step = [&](bool hidden) {
    const vpSSLServoInput in = hidden ? vpSSLServoInput::none() : observe(world.cMo());
    const vpColVector v = b.update(t, in, world.depth(), world.collision());
    expectBounded(b, v);
    b.apply(world.robot(), vpRobot::CAMERA_FRAME);
    t += kDt;
    return v;
  };
  for (int k = 0; k < 1500; ++k) {
    step(false);
  }
  ASSERT_EQ(b.getState(), SSL_HOMING_HOME);
  EXPECT_NEAR(b.getRange(), 2., 0.05);

  // A short loss (1 s < 3 s): the state stays and the vehicle hovers (zero command, no pose to servo on).
  for (int k = 0; k < 25; ++k) {
    const vpColVector v = step(true);
    EXPECT_EQ(b.getState(), SSL_HOMING_HOME);
    EXPECT_EQ(v.frobeniusNorm(), 0.);
  }
  EXPECT_FALSE(b.getTargetSeen());
  step(false);
  EXPECT_EQ(b.getState(), SSL_HOMING_HOME);

  // A long loss: back to SEARCH after the timeout, spinning.
  std::vector<vpSSLHomingState> states{b.getState()};
  for (int k = 0; k < 100; ++k) {
    step(true);
    if (b.getState() != states.back()) {
      states.push_back(b.getState());
      EXPECT_NEAR(b.getTimeSinceSeen(), 3., 0.05);
    }
  }
  ASSERT_EQ(states.size(), 2u);
  EXPECT_EQ(states[1], SSL_HOMING_SEARCH);
  EXPECT_NE(b.getVelocity()[SSL_AXIS_YAW], 0.);

  // The target is back: found again (the search keeps turning until it is in view), aligned, homed.
  for (int k = 0; k < 5000 && b.getState() != SSL_HOMING_HOME; ++k) {
    step(false);
    if (b.getState() != states.back()) {
      states.push_back(b.getState());
    }
  }
  ASSERT_EQ(states.size(), 4u);
  EXPECT_EQ(states[2], SSL_HOMING_ALIGN);
  EXPECT_EQ(states[3], SSL_HOMING_HOME);
}

TEST(HomingBehaviour, TransitionsOnSyntheticInputs)
{
  vpSSLHomingBehaviour b = makeBehaviour(vpSSLServoLaw::forwardCameraMount(0.5));
  b.setLostTimeout(2.);
  EXPECT_EQ(b.getState(), SSL_HOMING_SEARCH);

  // Nothing seen: search.
  vpColVector v = b.update(0., vpSSLServoInput::none(), 1.5, false);
  EXPECT_EQ(b.getState(), SSL_HOMING_SEARCH);
  EXPECT_DOUBLE_EQ(v[SSL_AXIS_YAW], 0.2);

  // Seen off-centre by 20 deg at the same depth: align, by turning, without surge (the range is kept).
  v = b.update(0.1, facing(2., 20.), 1.5, false);
  EXPECT_EQ(b.getState(), SSL_HOMING_ALIGN);
  EXPECT_EQ(v[SSL_AXIS_SURGE], 0.);
  EXPECT_EQ(v[SSL_AXIS_SWAY], 0.);
  EXPECT_EQ(v[SSL_AXIS_HEAVE], 0.);
  EXPECT_EQ(v[SSL_AXIS_ROLL], 0.);
  // Target to starboard (camera x > 0): turn to starboard, positive yaw rate in the z-down vehicle frame.
  EXPECT_GT(v[SSL_AXIS_YAW], 0.);

  // Centred (within 5 deg): home, servoing toward the stand-off (target at 3 m: forward).
  v = b.update(0.2, facing(3., 2.), 1.5, false);
  EXPECT_EQ(b.getState(), SSL_HOMING_HOME);
  EXPECT_GT(v[SSL_AXIS_SURGE], 0.);
  // Too close: back off.
  v = b.update(0.3, facing(1., 0.), 1.5, false);
  EXPECT_LT(v[SSL_AXIS_SURGE], 0.);

  // Docking requested: dock, moving forward even at the stand-off.
  b.startDocking();
  v = b.update(0.4, facing(2., 0.), 1.5, false);
  EXPECT_EQ(b.getState(), SSL_HOMING_DOCK);
  EXPECT_GT(v[SSL_AXIS_SURGE], 0.);
  // Cancelled: home again.
  b.stopDocking();
  b.update(0.5, facing(2., 0.), 1.5, false);
  EXPECT_EQ(b.getState(), SSL_HOMING_HOME);
  b.startDocking();
  b.update(0.6, facing(0.4, 0.), 1.5, false);
  ASSERT_EQ(b.getState(), SSL_HOMING_DOCK);

  // Lost at 0.4 m (within the blind range 0.6 m): the surge is held; at 2 m it would be zero.
  v = b.update(0.7, vpSSLServoInput::none(), 1.5, false);
  EXPECT_EQ(b.getState(), SSL_HOMING_DOCK);
  EXPECT_GE(v[SSL_AXIS_SURGE], 0.1);
  EXPECT_EQ(v[SSL_AXIS_YAW], 0.);

  // Collision: docked, zero command whatever is seen, until reset().
  v = b.update(0.8, facing(0.1, 0.), 1.5, true);
  EXPECT_EQ(b.getState(), SSL_HOMING_DOCKED);
  EXPECT_EQ(v.frobeniusNorm(), 0.);
  v = b.update(0.9, facing(2., 10.), 1.5, false);
  EXPECT_EQ(b.getState(), SSL_HOMING_DOCKED);
  EXPECT_EQ(v.frobeniusNorm(), 0.);
  b.reset();
  EXPECT_EQ(b.getState(), SSL_HOMING_SEARCH);
  EXPECT_FALSE(b.getDockingRequested());

  // Lost far while docking: zero command, then search after the timeout; the request survives the search.
  b.update(10., facing(2., 0.), 1.5, false);
  ASSERT_EQ(b.getState(), SSL_HOMING_HOME);
  b.startDocking();
  b.update(10.1, facing(2., 0.), 1.5, false);
  ASSERT_EQ(b.getState(), SSL_HOMING_DOCK);
  v = b.update(11., vpSSLServoInput::none(), 1.5, false);
  EXPECT_EQ(b.getState(), SSL_HOMING_DOCK);
  EXPECT_EQ(v.frobeniusNorm(), 0.);
  b.update(12.2, vpSSLServoInput::none(), 1.5, false);
  EXPECT_EQ(b.getState(), SSL_HOMING_SEARCH);
  EXPECT_TRUE(b.getDockingRequested());
  b.update(12.3, facing(2., 0.), 1.5, false);
  EXPECT_EQ(b.getState(), SSL_HOMING_DOCK); // SEARCH -> ALIGN -> DOCK in one step: centred, docking requested
}

TEST(HomingBehaviour, MinPointsDecidesWhenTheTargetIsSeen)
{
  vpSSLHomingBehaviour b = makeBehaviour(vpSSLServoLaw::forwardCameraMount(0.5));
  b.setMinPoints(3);
  vpSSLServoInput in = facing(2., 0.);
  in.nbPoints = 2; // a tracker predicting the third landmark
  b.update(0., in, 1.5, false);
  EXPECT_EQ(b.getState(), SSL_HOMING_SEARCH);
  in.nbPoints = 3;
  b.update(0.1, in, 1.5, false);
  EXPECT_EQ(b.getState(), SSL_HOMING_HOME);
  // Not seen (nbPoints 0) but valid, e.g. vpSSLTracker LOST: the law keeps servoing on the prediction.
  in = facing(3., 0.);
  in.nbPoints = 0;
  const vpColVector v = b.update(0.2, in, 1.5, false);
  EXPECT_EQ(b.getState(), SSL_HOMING_HOME);
  EXPECT_FALSE(b.getTargetSeen());
  EXPECT_GT(v[SSL_AXIS_SURGE], 0.);
}

TEST(HomingBehaviour, SearchSweepsYawAndDepthBetweenItsLimits)
{
  vpSSLHomingBehaviour b = makeBehaviour(vpSSLServoLaw::forwardCameraMount(0.5));
  b.setSearchPattern(-0.3, 1., 4., 20., 1.);
  double depth = 2.5;
  double minRef = 1e9, maxRef = -1e9, minDepth = 1e9, maxDepth = -1e9;
  for (int k = 0; k < 1500; ++k) {
    const vpColVector v = b.update(k * kDt, vpSSLServoInput::none(), depth, false);
    expectBounded(b, v);
    EXPECT_DOUBLE_EQ(v[SSL_AXIS_YAW], -0.3);
    minRef = std::min(minRef, b.getSearchDepth());
    maxRef = std::max(maxRef, b.getSearchDepth());
    depth += v[SSL_AXIS_HEAVE] * kDt; // heave is the depth rate (z down)
    if (k > 500) {
      minDepth = std::min(minDepth, depth);
      maxDepth = std::max(maxDepth, depth);
    }
  }
  EXPECT_NEAR(minRef, 1., 0.01);
  EXPECT_NEAR(maxRef, 4., 0.01);
  // The vehicle follows the pattern (heave limited to 0.3 m/s: 3 m in 10 s is exactly feasible, it lags a bit).
  EXPECT_LT(minDepth, 1.5);
  EXPECT_GT(maxDepth, 3.5);
  // Unknown depth: no heave, still spinning.
  const vpColVector v = b.update(100., vpSSLServoInput::none(), kNaN, false);
  EXPECT_EQ(v[SSL_AXIS_HEAVE], 0.);
  EXPECT_DOUBLE_EQ(v[SSL_AXIS_YAW], -0.3);
}

TEST(HomingBehaviour, GarbageNeverGivesANaNOrAnUnboundedCommand)
{
  vpUniRand rng(11);
  const double specials[] = {
      kNaN,  std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), 0., -1., 1e300, -1e300,
      1e-300};
  auto value = [&](double scale) {
    return rng.uniform(0., 1.) < 0.1 ? specials[static_cast<unsigned int>(rng.uniform(0, 8)) % 8u]
                                     : rng.uniform(-scale, scale);
  };
  vpSSLHomingBehaviour b = makeBehaviour(vpSSLServoLaw::forwardCameraMount(0.5));
  b.setAutoDock(0.5);
  double t = 0.;
  std::vector<unsigned int> visits(5, 0);
  for (int k = 0; k < 4000; ++k) {
    vpSSLServoInput in;
    const double r = rng.uniform(0., 1.);
    if (r < 0.5) {
      // Mostly plausible: the target somewhere ahead, with noise.
      in = facing(rng.uniform(0.05, 5.), rng.uniform(-30., 30.));
      for (vpSSLServoPoint &p : in.points) {
        p.x += rng.uniform(-0.01, 0.01);
      }
    } else if (r < 0.9) {
      in.valid = rng.uniform(0., 1.) < 0.8;
      const int n = rng.uniform(0, 6);
      for (int i = 0; i < n; ++i) {
        vpSSLServoPoint p;
        p.oX = value(0.3);
        p.oY = value(0.3);
        p.x = value(1.);
        p.y = value(1.);
        p.Z = value(5.);
        in.points.push_back(p);
      }
      in.nbPoints = static_cast<unsigned int>(rng.uniform(0, 5));
      in.hasPose = rng.uniform(0., 1.) < 0.5;
      in.cMo[0][3] = value(2.);
      in.cMo[2][3] = value(5.);
    }
    if (k % 7 == 0 && rng.uniform(0., 1.) < 0.5) {
      b.startDocking();
    }
    t += rng.uniform(0., 1.) < 0.05 ? value(1.) : kDt; // sometimes NaN, infinite or backwards
    const double depth = rng.uniform(0., 1.) < 0.1 ? value(10.) : rng.uniform(0., 5.);
    const bool collision = rng.uniform(0., 1.) < 0.01;
    const vpColVector v = b.update(t, in, depth, collision);
    expectBounded(b, v);
    ++visits[b.getState()];
    if (b.getState() == SSL_HOMING_DOCKED) {
      b.reset();
    }
  }
  // The fuzz visits every state but DOCKED (reset at once), so the checks cover every command.
  EXPECT_GT(visits[SSL_HOMING_SEARCH], 0u);
  EXPECT_GT(visits[SSL_HOMING_ALIGN], 0u);
  EXPECT_GT(visits[SSL_HOMING_HOME], 0u);
  EXPECT_GT(visits[SSL_HOMING_DOCK], 0u);
}

TEST(HomingBehaviour, ApplyDrivesAVpRobotInTheChosenFrame)
{
  vpSSLHomingBehaviour b = makeBehaviour(vpSSLServoLaw::forwardCameraMount(0.5));
  b.update(0., vpSSLServoInput::none(), 1.5, false); // search: yaw 0.2 rad/s about the vehicle's z (down)
  vpSimulatorCamera robot;
  const vpHomogeneousMatrix wMc0 = robot.getPosition();
  b.apply(robot, vpRobot::CAMERA_FRAME);
  const vpHomogeneousMatrix cMc1 = wMc0.inverse() * robot.getPosition();
  // The vehicle's z is the camera's y: the camera turns about its own y by 0.2 rad/s * 0.04 s...
  const vpThetaUVector tu(cMc1.getRotationMatrix());
  EXPECT_NEAR(tu[1], 0.2 * robot.getSamplingTime(), 1e-9);
  // ... and its centre, 0.5 m ahead of the vehicle origin, swings sideways (camera x) as well.
  EXPECT_GT(cMc1[0][3], 0.);
  EXPECT_THROW(b.apply(robot, vpRobot::REFERENCE_FRAME), vpException);
  EXPECT_NO_THROW(b.apply(robot, vpRobot::ARTICULAR_FRAME));
}

TEST(HomingBehaviour, AlignTimeoutHandsTheCentringToTheFullLaw)
{
  // A cross current holds the target 12 deg off-centre: ALIGN cannot finish; after its timeout HOME takes over
  // (with surge), which it would never do with an infinite timeout.
  for (double timeout : {5., std::numeric_limits<double>::infinity()}) {
    vpSSLHomingBehaviour b = makeBehaviour(vpSSLServoLaw::forwardCameraMount(0.5));
    b.setAlignTimeout(timeout);
    vpColVector v;
    double t = 0.;
    for (; t < 4.9; t += 0.1) {
      v = b.update(t, facing(3., 12.), 1.5, false);
      ASSERT_EQ(b.getState(), SSL_HOMING_ALIGN) << "t " << t;
      EXPECT_EQ(v[SSL_AXIS_SURGE], 0.);
    }
    for (; t < 10.; t += 0.1) {
      v = b.update(t, facing(3., 12.), 1.5, false);
    }
    if (std::isfinite(timeout)) {
      EXPECT_EQ(b.getState(), SSL_HOMING_HOME);
      EXPECT_GT(v[SSL_AXIS_SURGE], 0.); // 3 m: towards the 2 m stand-off
    } else {
      EXPECT_EQ(b.getState(), SSL_HOMING_ALIGN);
    }
  }
}

TEST(HomingBehaviour, AutoDockCentringToleranceIsItsOwn)
{
  // At the stand-off but 10 deg off-centre (a current): the default 5 deg hold never docks, a 15 deg one does.
  for (double deg : {5., 15.}) {
    vpSSLHomingBehaviour b = makeBehaviour(vpSSLServoLaw::forwardCameraMount(0.5));
    b.setAlignTimeout(0.);
    b.setAutoDock(2., 0.5, vpMath::rad(deg));
    for (double t = 0.; t < 4.; t += 0.1) {
      b.update(t, facing(2.1, 10.), 1.5, false);
    }
    EXPECT_EQ(b.getState(), deg > 10. ? SSL_HOMING_DOCK : SSL_HOMING_HOME) << deg << " deg";
  }
}

TEST(HomingBehaviour, SettersRejectBadValues)
{
  vpSSLHomingBehaviour b;
  EXPECT_THROW(b.setStandOff(0.), vpException);
  EXPECT_THROW(b.setStandOff(kNaN), vpException);
  EXPECT_THROW(b.setSearchPattern(0.2, 3., 1., 40.), vpException);
  EXPECT_THROW(b.setSearchPattern(0.2, 1., 3., 0.), vpException);
  EXPECT_THROW(b.setAlignTolerance(0.), vpException);
  EXPECT_THROW(b.setLostTimeout(-1.), vpException);
  EXPECT_THROW(b.setMinPoints(0), vpException);
  EXPECT_THROW(b.setBlindDock(-1., 0.1), vpException);
  EXPECT_THROW(b.setAutoDock(1., 0.), vpException);
  EXPECT_THROW(b.setAutoDock(1., 0.1, 0.), vpException);
  EXPECT_THROW(b.setAlignTimeout(-1.), vpException);
  EXPECT_THROW(b.setAlignTimeout(kNaN), vpException);
  EXPECT_THROW(b.setSearchHold(-0.5, 0.3), vpException);
  EXPECT_THROW(b.setSearchHold(0.5, kNaN), vpException);
  EXPECT_THROW(b.setRangeIntegralGain(-0.1), vpException);
  EXPECT_THROW(b.setRangeIntegralGain(kNaN), vpException);
  EXPECT_EQ(vpSSLHomingBehaviour::getStateName(SSL_HOMING_DOCKED), "docked");
}

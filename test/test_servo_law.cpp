/*
  vpSSLServoLaw and vpSSLServoInput: the law brings ViSP's vpSimulatorCamera to the stand-off from several start
  poses (ssl3-a3 points projected analytically, no rendering), fully actuated and as an under-actuated vehicle,
  from SSL and AprilTag inputs; it never outputs a NaN or an unbounded command.
*/
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

#include <visp3/core/vpGaussRand.h>
#include <visp3/core/vpMath.h>
#include <visp3/core/vpMeterPixelConversion.h>
#include <visp3/core/vpUniRand.h>
#include <visp3/robot/vpSimulatorCamera.h>
#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/ssl/vpSSLTracker.h>
#include <visp3/ssl_servo/vpSSLServoLaw.h>

namespace {
const double kDt = 0.04; // vpSimulatorCamera's sampling time

struct StartPose
{
  double tx, ty, tz; // target origin in the camera frame (m)
  double rx, ry, rz; // target rotation about the camera axes (deg)
};

// Start poses: 2.5 to 5 m, off-centre up to 0.8 m, turned up to 25 deg; the target is in a 640x480 view.
const StartPose kStarts[] = {{0.0, 0.0, 4.0, 0., 0., 0.},      {0.6, 0.2, 4.0, 0., 15., 0.},
                             {-0.8, -0.3, 5.0, 10., -20., 5.}, {0.3, 0.4, 3.0, -15., 10., 20.},
                             {-0.4, 0.1, 2.5, 5., 25., -10.},  {0.5, -0.5, 4.5, -10., -10., 15.}};

vpHomogeneousMatrix startPose(const StartPose &s)
{
  return vpHomogeneousMatrix(vpTranslationVector(s.tx, s.ty, s.tz),
                             vpRotationMatrix(vpRxyzVector(vpMath::rad(s.rx), vpMath::rad(s.ry), vpMath::rad(s.rz))));
}

bool finite(const vpColVector &v)
{
  for (unsigned int i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i])) {
      return false;
    }
  }
  return true;
}

void expectBounded(const vpSSLServoLaw &law, const vpColVector &v)
{
  ASSERT_EQ(v.size(), 6u);
  ASSERT_TRUE(finite(v));
  ASSERT_TRUE(finite(law.getCameraVelocity()));
  for (unsigned int i = 0; i < 6; ++i) {
    EXPECT_LE(std::fabs(v[i]), law.getVelocityLimits()[i] * (1. + 1e-12)) << "axis " << i;
  }
}

// The four AprilTag corners of a tag of side s, in vpDetectorAprilTag's tag frame (Y up, Z out of the tag).
std::vector<vpPoint> tagCorners(double s)
{
  const double h = s / 2.;
  return {vpPoint(-h, -h, 0.), vpPoint(h, -h, 0.), vpPoint(h, h, 0.), vpPoint(-h, h, 0.)};
}

// Sheet frame (X right, Y down, Z into the sheet) to tag frame: 180 deg about X.
vpHomogeneousMatrix sheetToTag()
{
  return vpHomogeneousMatrix(0., 0., 0., M_PI, 0., 0.);
}

vpCameraParameters camera()
{
  return vpCameraParameters(600., 600., 320., 240.);
}

// Input of a detected AprilTag at sheet pose cMs: pixel corners (in a shuffled order) and tag-frame pose.
vpSSLServoInput aprilTagInput(const vpHomogeneousMatrix &cMs, double tagSize, unsigned int rotate)
{
  const vpHomogeneousMatrix cMt = cMs * sheetToTag().inverse();
  std::vector<vpImagePoint> corners;
  for (vpPoint P : tagCorners(tagSize)) {
    P.track(cMt);
    vpImagePoint ip;
    vpMeterPixelConversion::convertPoint(camera(), P.get_x(), P.get_y(), ip);
    corners.push_back(ip);
  }
  std::rotate(corners.begin(), corners.begin() + (rotate % 4), corners.end());
  return vpSSLServoInput::fromAprilTag(corners, cMt, tagSize, camera());
}

struct RunResult
{
  vpHomogeneousMatrix cMo; // final pose
  double rangeError;       // |centre depth - Z*| at the end (m)
  double centreAngle;      // angle of the centre off the optical axis at the end (deg)
  double convergenceTime;  // first time range error < 2 cm and centre < 1 deg (s; inf if never)
  double maxSway;          // largest |sway| command (m/s)
  bool alwaysOk;           // every step had status OK
};

enum InputKind
{
  INPUT_SSL,
  INPUT_APRILTAG
};

/*
  Runs the law on vpSimulatorCamera for \e seconds. The camera twist of the vehicle command moves the camera, which
  is exactly the motion of a camera rigidly mounted on the vehicle.
*/
RunResult run(vpSSLServoLaw &law, const vpHomogeneousMatrix &cMoStart, double seconds, InputKind kind)
{
  const std::vector<vpPoint> points = vpSSLTarget::ssl3a3().getPoints();
  vpSimulatorCamera robot;
  robot.setSamplingTime(kDt);
  const vpHomogeneousMatrix wMo; // target frame = world frame
  robot.setPosition(wMo * cMoStart.inverse());
  RunResult r;
  r.convergenceTime = std::numeric_limits<double>::infinity();
  r.maxSway = 0.;
  r.alwaysOk = true;
  const unsigned int steps = static_cast<unsigned int>(seconds / kDt);
  for (unsigned int k = 0; k < steps; ++k) {
    const vpHomogeneousMatrix cMo = robot.getPosition().inverse() * wMo;
    const vpSSLServoInput in =
        kind == INPUT_SSL ? vpSSLServoInput::fromPose(points, cMo) : aprilTagInput(cMo, 0.2376, k);
    const vpColVector v = law.computeControlLaw(in);
    r.alwaysOk = r.alwaysOk && law.getStatus() == SSL_SERVO_OK;
    r.maxSway = std::max(r.maxSway, std::fabs(v[SSL_AXIS_SWAY]));
    double x, y;
    law.getCentre(x, y);
    const double rangeError = std::fabs(law.getCentreDepth() - law.getStandOff());
    const double angle = vpMath::deg(std::atan(std::sqrt(x * x + y * y)));
    if (rangeError < 0.02 && angle < 1. && !std::isfinite(r.convergenceTime)) {
      r.convergenceTime = k * kDt;
    }
    r.rangeError = rangeError;
    r.centreAngle = angle;
    robot.setVelocity(vpRobot::CAMERA_FRAME, law.getCameraVelocity());
  }
  r.cMo = robot.getPosition().inverse() * wMo;
  return r;
}

vpColVector limits(double t, double r)
{
  vpColVector v(6);
  for (unsigned int i = 0; i < 3; ++i) {
    v[i] = t;
    v[i + 3] = r;
  }
  return v;
}
} // namespace

TEST(ServoLaw, FullyActuatedCameraReachesTheDesiredPoseFromEveryStart)
{
  for (size_t i = 0; i < sizeof(kStarts) / sizeof(kStarts[0]); ++i) {
    vpSSLServoLaw law;
    law.setCameraRobot();
    law.setVelocityLimits(limits(0.5, 0.5));
    law.setStandOff(1.5);
    const RunResult r = run(law, startPose(kStarts[i]), 40., INPUT_SSL);
    EXPECT_TRUE(r.alwaysOk) << "start " << i;
    // The desired pose: target centre on the optical axis at 1.5 m, facing (identity rotation).
    const vpTranslationVector t = r.cMo.getTranslationVector();
    const vpThetaUVector tu(r.cMo.getRotationMatrix());
    const double rotErr = vpMath::deg(std::sqrt(tu.sumSquare()));
    EXPECT_NEAR(t[0], 0., 0.005) << "start " << i;
    EXPECT_NEAR(t[1], 0., 0.005) << "start " << i;
    EXPECT_NEAR(t[2], 1.5, 0.005) << "start " << i;
    EXPECT_LT(rotErr, 0.5) << "start " << i;
    std::cout << "[figures] 6-dof start " << i << ": range error " << r.rangeError * 1000. << " mm, rotation " << rotErr
              << " deg, converged (2 cm, 1 deg) at " << r.convergenceTime << " s" << std::endl;
  }
}

TEST(ServoLaw, UnderActuatedVehicleReachesTheStandOffWithoutSway)
{
  const vpHomogeneousMatrix vMc = vpSSLServoLaw::forwardCameraMount(0.5);
  for (size_t i = 0; i < sizeof(kStarts) / sizeof(kStarts[0]); ++i) {
    vpSSLServoLaw law; // Starbug axes: sway disabled
    law.setCameraToVehicle(vMc);
    law.setStandOff(2.);
    ASSERT_FALSE(law.getAxisEnabled(SSL_AXIS_SWAY));
    const RunResult r = run(law, startPose(kStarts[i]), 60., INPUT_SSL);
    EXPECT_TRUE(r.alwaysOk) << "start " << i;
    EXPECT_EQ(r.maxSway, 0.) << "start " << i;
    EXPECT_LT(r.rangeError, 0.02) << "start " << i;
    EXPECT_LT(r.centreAngle, 1.) << "start " << i;
    std::cout << "[figures] starbug start " << i << ": range error " << r.rangeError * 1000. << " mm, centre "
              << r.centreAngle << " deg, converged (2 cm, 1 deg) at " << r.convergenceTime << " s" << std::endl;
  }
}

TEST(ServoLaw, SwayIsUsedOnlyWhenEnabledAndLessWhenWeightedDown)
{
  // Target to the side and turned: a lateral correction is needed.
  const std::vector<vpPoint> points = vpSSLTarget::ssl3a3().getPoints();
  const vpSSLServoInput in = vpSSLServoInput::fromPose(points, startPose({0.3, 0., 2.2, 0., 10., 0.}));
  vpSSLServoLaw law;
  law.setCameraToVehicle(vpSSLServoLaw::forwardCameraMount(0.5));
  law.setStandOff(2.);
  law.setVelocityLimits(limits(100., 100.)); // no saturation
  vpColVector v = law.computeControlLaw(in);
  ASSERT_EQ(law.getStatus(), SSL_SERVO_OK);
  EXPECT_EQ(v[SSL_AXIS_SWAY], 0.);
  const vpMatrix eJe = law.getVehicleJacobian();
  ASSERT_EQ(eJe.getCols(), 5u);
  EXPECT_EQ(eJe[SSL_AXIS_PITCH][3], 0.3); // columns: surge, heave, roll, pitch, yaw
  EXPECT_EQ(eJe[SSL_AXIS_HEAVE][1], 1.);

  law.setAxisEnabled(SSL_AXIS_SWAY, true);
  const vpColVector full = law.computeControlLaw(in);
  EXPECT_GT(std::fabs(full[SSL_AXIS_SWAY]), 1e-3);
  law.setAxisWeight(SSL_AXIS_SWAY, 0.25);
  v = law.computeControlLaw(in);
  EXPECT_GT(std::fabs(v[SSL_AXIS_SWAY]), 1e-5);
  EXPECT_LT(std::fabs(v[SSL_AXIS_SWAY]), 0.5 * std::fabs(full[SSL_AXIS_SWAY]));

  // Disabling yaw and pitch as well: those axes stay exactly zero.
  law.setAxisEnabled(SSL_AXIS_YAW, false);
  law.setAxisEnabled(SSL_AXIS_PITCH, false);
  v = law.computeControlLaw(in);
  EXPECT_EQ(v[SSL_AXIS_YAW], 0.);
  EXPECT_EQ(v[SSL_AXIS_PITCH], 0.);
}

TEST(ServoLaw, CentringPrefersHeavyAxesAndKeepsTheImageVelocity)
{
  // Target 0.5 m below the optical axis at 2 m: the centring has one point and more axes than it needs, so the
  // weights decide which axes do the work, not where the image point goes. (Its speed differs a little: vpServo
  // evaluates the adaptive gain on the axis command J^+ e, which the weights change.)
  const std::vector<vpPoint> points = vpSSLTarget::ssl3a3().getPoints();
  const vpSSLServoInput in = vpSSLServoInput::fromPose(points, startPose({0.05, 0.5, 2.0, 0., 0., 0.}));
  const vpHomogeneousMatrix vMc = vpSSLServoLaw::forwardCameraMount(0.5);
  auto centreVelocity = [&](vpSSLServoLaw &law, const vpColVector &v) {
    double x, y, Z;
    EXPECT_TRUE(vpSSLServoLaw::getTargetCentre(in, x, y, Z));
    vpFeaturePoint p;
    p.buildFrom(x, y, Z);
    return vpColVector(p.interaction() * law.toCameraVelocity(v));
  };
  vpSSLServoLaw weighted; // defaults: pitch 0.3
  weighted.setCameraToVehicle(vMc);
  weighted.setVelocityLimits(limits(100., 100.));
  const vpColVector vw = weighted.computeCentringLaw(in);
  ASSERT_EQ(weighted.getStatus(), SSL_SERVO_OK);
  vpSSLServoLaw even;
  even.setCameraToVehicle(vMc);
  even.setVelocityLimits(limits(100., 100.));
  even.setAxisWeight(SSL_AXIS_PITCH, 1.);
  even.setAxisWeight(SSL_AXIS_ROLL, 1.);
  const vpColVector ve = even.computeCentringLaw(in);
  ASSERT_EQ(even.getStatus(), SSL_SERVO_OK);

  EXPECT_EQ(vw[SSL_AXIS_SURGE], 0.); // centring keeps the range
  EXPECT_EQ(vw[SSL_AXIS_ROLL], 0.);  // the roll of a forward camera cannot centre
  EXPECT_GT(vw[SSL_AXIS_HEAVE], 0.); // down, towards the target
  EXPECT_GT(std::fabs(vw[SSL_AXIS_HEAVE]), 2. * std::fabs(ve[SSL_AXIS_HEAVE]) * 0.9);
  EXPECT_LT(std::fabs(vw[SSL_AXIS_PITCH]), std::fabs(ve[SSL_AXIS_PITCH]));
  const vpColVector dw = centreVelocity(weighted, vw), de = centreVelocity(even, ve);
  // Both move the centre straight towards the image centre (the error is (x, y) = (0.025, 0.25)).
  EXPECT_NEAR(dw[0] / dw[1], 0.1, 1e-6);
  EXPECT_NEAR(de[0] / de[1], 0.1, 1e-6);
  EXPECT_LT(dw[1], 0.);
  EXPECT_NEAR(dw[1] / de[1], 1., 0.1);
  std::cout << "[figures] centring 0.5 m below at 2 m: heave " << vw[SSL_AXIS_HEAVE] << " m/s, pitch "
            << vw[SSL_AXIS_PITCH] << " rad/s (even weights: " << ve[SSL_AXIS_HEAVE] << ", " << ve[SSL_AXIS_PITCH] << ")"
            << std::endl;
}

TEST(ServoLaw, DockingStartGivesSurgeNotAHeavePitchBurst)
{
  // The start of fig9's DOCK: target centred at the 2 m stand-off, stand-off set to 0. The consistent command is
  // forward; without the pseudo-inverse threshold the near-singular heave-pitch direction takes the saturated
  // command (heave 0.3 m/s, surge 0.015 m/s) and the vehicle dives under the board.
  const std::vector<vpPoint> points = vpSSLTarget::ssl3a3().getPoints();
  for (double dy : {-0.003, 0., 0.004}) {
    const vpSSLServoInput in = vpSSLServoInput::fromPose(points, startPose({0.001, dy, 2.0, 0.3, -0.2, 0.}));
    vpSSLServoLaw law;
    law.setCameraToVehicle(vpSSLServoLaw::forwardCameraMount(0.5));
    law.setStandOff(0.);
    const vpColVector v = law.computeControlLaw(in);
    ASSERT_EQ(law.getStatus(), SSL_SERVO_OK);
    EXPECT_GT(v[SSL_AXIS_SURGE], 0.4) << "dy " << dy;
    EXPECT_LT(std::fabs(v[SSL_AXIS_HEAVE]), 0.1 * v[SSL_AXIS_SURGE]) << "dy " << dy;
    EXPECT_LT(std::fabs(v[SSL_AXIS_PITCH]), 0.05) << "dy " << dy;
  }
}

TEST(ServoLaw, NoisyMeasurementsStillHoldTheStandOff)
{
  // 1 px of image noise (600 px focal length) and 5 % of depth noise, as a tracker would give at 2 m.
  const std::vector<vpPoint> points = vpSSLTarget::ssl3a3().getPoints();
  vpGaussRand noise(1., 0., 3);
  vpSSLServoLaw law;
  law.setCameraToVehicle(vpSSLServoLaw::forwardCameraMount(0.5));
  law.setStandOff(2.);
  vpSimulatorCamera robot;
  robot.setSamplingTime(kDt);
  robot.setPosition(startPose(kStarts[2]).inverse());
  double worst = 0.;
  for (unsigned int k = 0; k < 1500; ++k) {
    const vpHomogeneousMatrix cMo = robot.getPosition().inverse();
    vpSSLServoInput in = vpSSLServoInput::fromPose(points, cMo);
    for (vpSSLServoPoint &p : in.points) {
      p.x += noise() / 600.;
      p.y += noise() / 600.;
      p.Z *= 1. + 0.05 * noise();
    }
    in.hasPose = false; // centre depth from the noisy points
    const vpColVector v = law.computeControlLaw(in);
    ASSERT_EQ(law.getStatus(), SSL_SERVO_OK);
    expectBounded(law, v);
    robot.setVelocity(vpRobot::CAMERA_FRAME, law.getCameraVelocity());
    if (k * kDt > 40.) {
      worst = std::max(worst, std::fabs(cMo[2][3] - 2.));
    }
  }
  EXPECT_LT(worst, 0.1);
  std::cout << "[figures] noisy (1 px, 5 % depth): worst range error after 40 s " << worst * 1000. << " mm"
            << std::endl;
}

TEST(ServoLaw, AprilTagInputAlsoConverges)
{
  for (size_t i = 0; i < 3; ++i) {
    vpSSLServoLaw law;
    law.setCameraToVehicle(vpSSLServoLaw::forwardCameraMount(0.5));
    law.setStandOff(1.5);
    const RunResult r = run(law, startPose(kStarts[i]), 60., INPUT_APRILTAG);
    EXPECT_TRUE(r.alwaysOk) << "start " << i;
    EXPECT_LT(r.rangeError, 0.02) << "start " << i;
    EXPECT_LT(r.centreAngle, 1.) << "start " << i;
    std::cout << "[figures] apriltag starbug start " << i << ": range error " << r.rangeError * 1000. << " mm, centre "
              << r.centreAngle << " deg, converged at " << r.convergenceTime << " s" << std::endl;
  }
}

TEST(ServoInput, AprilTagAdapterPairsCornersWhateverTheirOrder)
{
  const vpHomogeneousMatrix cMs = startPose({0.2, -0.1, 2., 10., -15., 30.});
  const vpSSLServoInput ref = aprilTagInput(cMs, 0.2, 0);
  ASSERT_TRUE(ref.valid);
  ASSERT_EQ(ref.size(), 4u);
  EXPECT_EQ(ref.nbPoints, 4u);
  for (unsigned int rot = 0; rot < 4; ++rot) {
    const vpSSLServoInput in = aprilTagInput(cMs, 0.2, rot);
    ASSERT_TRUE(in.valid);
    for (const vpSSLServoPoint &p : in.points) {
      // Each point's image coordinates are its object corner's projection in the sheet frame.
      vpPoint P(p.oX, p.oY, p.oZ);
      P.track(cMs);
      EXPECT_NEAR(p.x, P.get_x(), 1e-9);
      EXPECT_NEAR(p.y, P.get_y(), 1e-9);
      EXPECT_NEAR(p.Z, P.cP[2], 1e-9);
    }
    // The pose is turned into the sheet frame: facing the sheet is the identity rotation.
    for (unsigned int r = 0; r < 4; ++r) {
      for (unsigned int c = 0; c < 4; ++c) {
        EXPECT_NEAR(in.cMo[r][c], cMs[r][c], 1e-9);
      }
    }
  }
  // With setZAlignedWithCameraAxis(true) the detector's pose is already the sheet's.
  std::vector<vpImagePoint> corners;
  for (const vpSSLServoPoint &p : ref.points) {
    vpImagePoint ip;
    vpMeterPixelConversion::convertPoint(camera(), p.x, p.y, ip);
    corners.push_back(ip);
  }
  const vpSSLServoInput aligned = vpSSLServoInput::fromAprilTag(corners, cMs, 0.2, camera(), true);
  ASSERT_TRUE(aligned.valid);
  EXPECT_NEAR(aligned.cMo[2][3], cMs[2][3], 1e-12);

  // Rejected: wrong corner count, bad size, NaN pose.
  corners.pop_back();
  EXPECT_FALSE(vpSSLServoInput::fromAprilTag(corners, cMs, 0.2, camera()).valid);
  corners.push_back(vpImagePoint(1., 1.));
  EXPECT_FALSE(vpSSLServoInput::fromAprilTag(corners, cMs, 0., camera()).valid);
  vpHomogeneousMatrix bad = cMs;
  bad[0][3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(vpSSLServoInput::fromAprilTag(corners, bad, 0.2, camera()).valid);
}

TEST(ServoInput, TrackerAdapterWithoutPoseIsNotValid)
{
  vpSSLTracker tracker(vpSSLTarget::ssl3a3(), camera());
  const vpSSLServoInput in = vpSSLServoInput::fromTracker(tracker);
  EXPECT_FALSE(in.valid);
  EXPECT_TRUE(in.points.empty());
  vpSSLServoLaw law;
  const vpColVector v = law.computeControlLaw(in);
  EXPECT_EQ(law.getStatus(), SSL_SERVO_NO_TARGET);
  EXPECT_EQ(v.frobeniusNorm(), 0.);
}

TEST(ServoLaw, DockingWithStandOffZeroClosesTheRange)
{
  vpSSLServoLaw law;
  law.setCameraToVehicle(vpSSLServoLaw::forwardCameraMount(0.5));
  law.setStandOff(0.);
  const RunResult r = run(law, startPose(kStarts[1]), 60., INPUT_SSL);
  EXPECT_TRUE(r.alwaysOk);
  // The law aims at the depth floor (0.05 m) and slows down exponentially near it.
  EXPECT_LT(r.cMo[2][3], 0.1);
  EXPECT_GT(r.cMo[2][3], 0.);
  // Lateral offset of the target centre from the optical axis at the end: millimetres.
  const double lateral = std::sqrt(r.cMo[0][3] * r.cMo[0][3] + r.cMo[1][3] * r.cMo[1][3]);
  EXPECT_LT(lateral, 0.01);
  std::cout << "[figures] docking: final range " << r.cMo[2][3] << " m, lateral offset " << lateral * 1000. << " mm"
            << std::endl;
}

TEST(ServoLaw, HeavePitchIsTheOnlyDirectionBelowThePseudoInverseThreshold)
{
  // doc/servo.md, "Conditioning": the target centred and facing the camera, Starbug axes, forward camera. The
  // singular values of L cVe eJe over the largest (yaw), each told by the axis its right singular vector turns:
  // heave with pitch 2.6e-4 at 2 m and 5.4e-5 at 4 m (below the threshold 0.005: dropped); roll, the weakest
  // direction kept, 0.012 and 0.0069; the range (surge) 0.23 and 0.13.
  struct Expected
  {
    double Z, heavePitch, roll, surge;
  };
  const std::vector<vpPoint> points = vpSSLTarget::ssl3a3().getPoints();
  for (const Expected &e : {Expected{2., 2.6e-4, 0.012, 0.23}, Expected{4., 5.4e-5, 0.0069, 0.13}}) {
    vpSSLServoLaw law;
    law.setCameraToVehicle(vpSSLServoLaw::forwardCameraMount(0.5));
    law.setStandOff(2.);
    law.computeControlLaw(vpSSLServoInput::fromPose(points, startPose({0., 0., e.Z, 0., 0., 0.})));
    ASSERT_EQ(law.getStatus(), SSL_SERVO_OK);
    vpMatrix J = law.getTaskJacobian(), V;
    ASSERT_EQ(J.getCols(), 5u); // surge, heave, roll, pitch, yaw
    vpColVector sv;
    J.svd(sv, V);
    const double largest = sv.getMaxValue();
    // Each singular value under the axis with the largest share of its right singular vector (heave and pitch
    // share the smallest one).
    double byAxis[5] = {0., 0., 0., 0., 0.};
    for (unsigned int k = 0; k < sv.size(); ++k) {
      unsigned int axis = 0;
      for (unsigned int a = 1; a < 5; ++a) {
        axis = std::fabs(V[a][k]) > std::fabs(V[axis][k]) ? a : axis;
      }
      byAxis[axis] = std::max(byAxis[axis], sv[k] / largest);
    }
    const double heavePitch = sv.getMinValue() / largest, roll = byAxis[2], surge = byAxis[0];
    std::cout << "[figures] L cVe eJe at " << e.Z << " m, singular value / largest: heave-pitch " << heavePitch
              << ", roll " << roll << ", surge " << surge << ", yaw " << byAxis[4] << std::endl;
    EXPECT_NEAR(heavePitch, e.heavePitch, 0.05 * e.heavePitch);
    EXPECT_NEAR(roll, e.roll, 0.05 * e.roll);
    EXPECT_NEAR(surge, e.surge, 0.05 * e.surge);
    EXPECT_DOUBLE_EQ(byAxis[4], 1.);
    EXPECT_LT(heavePitch, law.getPseudoInverseThreshold());
    EXPECT_GT(roll, law.getPseudoInverseThreshold());
  }
}

TEST(ServoLaw, SaturationScalesTheWholeCommandAndKeepsItsDirection)
{
  const std::vector<vpPoint> points = vpSSLTarget::ssl3a3().getPoints();
  const vpSSLServoInput in = vpSSLServoInput::fromPose(points, startPose({0.8, 0.3, 8., 10., 20., 30.}));
  vpSSLServoLaw free;
  free.setCameraToVehicle(vpSSLServoLaw::forwardCameraMount(0.5));
  free.setVelocityLimits(limits(1e3, 1e3));
  const vpColVector vf = free.computeControlLaw(in);
  EXPECT_FALSE(free.isSaturated());

  vpSSLServoLaw law;
  law.setCameraToVehicle(vpSSLServoLaw::forwardCameraMount(0.5));
  const vpColVector v = law.computeControlLaw(in);
  ASSERT_EQ(law.getStatus(), SSL_SERVO_OK);
  EXPECT_TRUE(law.isSaturated());
  expectBounded(law, v);
  // Same direction: v = vf / scale.
  const double scale = vf.frobeniusNorm() / v.frobeniusNorm();
  EXPECT_GT(scale, 1.);
  for (unsigned int i = 0; i < 6; ++i) {
    EXPECT_NEAR(v[i] * scale, vf[i], 1e-9 * (1. + std::fabs(vf[i])));
  }
  // At least one axis sits on its limit.
  bool onLimit = false;
  for (unsigned int i = 0; i < 6; ++i) {
    onLimit = onLimit || std::fabs(std::fabs(v[i]) - law.getVelocityLimits()[i]) < 1e-12;
  }
  EXPECT_TRUE(onLimit);
}

TEST(ServoLaw, GarbageInputsGiveAZeroCommandAndAStatus)
{
  const std::vector<vpPoint> points = vpSSLTarget::ssl3a3().getPoints();
  const vpSSLServoInput good = vpSSLServoInput::fromPose(points, startPose({0., 0., 3., 0., 0., 0.}));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  vpSSLServoLaw law;
  law.setCameraToVehicle(vpSSLServoLaw::forwardCameraMount(0.5));

  struct Case
  {
    const char *what;
    vpSSLServoInput in;
    vpSSLServoStatus expected;
  };
  std::vector<Case> cases;
  cases.push_back({"none", vpSSLServoInput::none(), SSL_SERVO_NO_TARGET});
  vpSSLServoInput in = good;
  in.points.clear();
  cases.push_back({"valid but empty", in, SSL_SERVO_NO_TARGET});
  in = good;
  in.valid = false;
  cases.push_back({"not valid", in, SSL_SERVO_NO_TARGET});
  in = good;
  in.points[1].x = nan;
  cases.push_back({"NaN x", in, SSL_SERVO_INVALID_INPUT});
  in = good;
  in.points[0].Z = inf;
  cases.push_back({"infinite Z", in, SSL_SERVO_INVALID_INPUT});
  in = good;
  in.points[2].oY = -inf;
  cases.push_back({"infinite object point", in, SSL_SERVO_INVALID_INPUT});
  in = good;
  in.points[2].y = 1e200;
  cases.push_back({"huge y", in, SSL_SERVO_INVALID_INPUT});
  in = good;
  in.points[0].Z = 0.;
  cases.push_back({"zero depth", in, SSL_SERVO_BEHIND_CAMERA});
  in = good;
  in.points[1].Z = -2.;
  cases.push_back({"negative depth", in, SSL_SERVO_BEHIND_CAMERA});
  cases.push_back({"behind the camera", vpSSLServoInput::fromPose(points, startPose({0., 0., -3., 0., 0., 0.})),
                   SSL_SERVO_BEHIND_CAMERA});
  for (const Case &c : cases) {
    const vpColVector v = law.computeControlLaw(c.in);
    EXPECT_EQ(law.getStatus(), c.expected) << c.what;
    EXPECT_EQ(v.frobeniusNorm(), 0.) << c.what;
    EXPECT_EQ(law.getCameraVelocity().frobeniusNorm(), 0.) << c.what;
    law.computeCentringLaw(c.in);
    EXPECT_EQ(law.getStatus(), c.expected) << c.what;
    EXPECT_EQ(law.getVelocity().frobeniusNorm(), 0.) << c.what;
  }

  // Usable oddities: a NaN pose is ignored (centre from the points), a tiny depth is floored.
  in = good;
  in.cMo[0][0] = nan;
  vpColVector v = law.computeControlLaw(in);
  EXPECT_EQ(law.getStatus(), SSL_SERVO_OK);
  expectBounded(law, v);
  in = good;
  for (vpSSLServoPoint &p : in.points) {
    p.Z = 1e-300;
  }
  in.hasPose = false;
  v = law.computeControlLaw(in);
  EXPECT_EQ(law.getStatus(), SSL_SERVO_OK);
  expectBounded(law, v);
}

TEST(ServoLaw, RandomFuzzNeverGivesANaNOrAnUnboundedCommand)
{
  vpUniRand rng(7);
  const double specials[] = {std::numeric_limits<double>::quiet_NaN(),
                             std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity(),
                             0.,
                             -0.,
                             1e-300,
                             -1e-300,
                             1e300,
                             -1e300,
                             std::numeric_limits<double>::denorm_min(),
                             std::numeric_limits<double>::max(),
                             1e3,
                             -1.};
  const unsigned int nSpecials = sizeof(specials) / sizeof(specials[0]);
  auto value = [&](double scale) {
    return rng.uniform(0., 1.) < 0.15
               ? specials[static_cast<unsigned int>(rng.uniform(0, static_cast<int>(nSpecials))) % nSpecials]
               : rng.uniform(-scale, scale);
  };
  vpSSLServoLaw law;
  law.setCameraToVehicle(vpSSLServoLaw::forwardCameraMount(0.5));
  unsigned int nbOk = 0;
  for (int k = 0; k < 3000; ++k) {
    vpSSLServoInput in;
    in.valid = rng.uniform(0., 1.) < 0.9;
    const int n = rng.uniform(0, 8);
    for (int i = 0; i < n; ++i) {
      vpSSLServoPoint p;
      p.oX = value(0.3);
      p.oY = value(0.3);
      p.oZ = rng.uniform(0., 1.) < 0.5 ? 0. : value(0.1);
      p.x = value(1.);
      p.y = value(1.);
      p.Z = rng.uniform(0., 1.) < 0.2 ? value(5.) : std::fabs(value(5.));
      in.points.push_back(p);
    }
    in.hasPose = rng.uniform(0., 1.) < 0.5;
    for (unsigned int r = 0; r < 3; ++r) {
      for (unsigned int c = 0; c < 4; ++c) {
        in.cMo[r][c] = value(3.);
      }
    }
    in.nbPoints = static_cast<unsigned int>(n);
    law.setStandOff(rng.uniform(0., 1.) < 0.2 ? 0. : rng.uniform(0.1, 4.));
    const vpColVector v = k % 2 ? law.computeControlLaw(in) : law.computeCentringLaw(in);
    expectBounded(law, v);
    if (law.getStatus() == SSL_SERVO_OK) {
      ++nbOk;
    } else {
      EXPECT_EQ(v.frobeniusNorm(), 0.);
    }
  }
  // The fuzz must also exercise the law itself, not only the input checks.
  EXPECT_GT(nbOk, 300u);
}

TEST(ServoLaw, SettersRejectBadValues)
{
  vpSSLServoLaw law;
  EXPECT_THROW(law.setStandOff(-1.), vpException);
  EXPECT_THROW(law.setStandOff(std::numeric_limits<double>::quiet_NaN()), vpException);
  EXPECT_THROW(law.setMinDepth(0.), vpException);
  EXPECT_THROW(law.setGain(0.), vpException);
  EXPECT_THROW(law.setGain(0.2, 0.8, 10.), vpException);
  EXPECT_THROW(law.setVelocityLimits(vpColVector(5, 1.)), vpException);
  EXPECT_THROW(law.setVelocityLimits(vpColVector(6, 0.)), vpException);
  EXPECT_THROW(law.setAxisWeight(SSL_AXIS_SWAY, 0.), vpException);
  EXPECT_THROW(law.setAxisWeight(SSL_AXIS_SWAY, 1.5), vpException);
  EXPECT_THROW(law.setPseudoInverseThreshold(-0.1), vpException);
  EXPECT_THROW(law.setPseudoInverseThreshold(1.), vpException);
  vpHomogeneousMatrix bad;
  bad[0][3] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(law.setCameraToVehicle(bad), vpException);
  EXPECT_NO_THROW(law.setStandOff(0.));
}

/*
  The simulator writes the ground truth of every benchmark and closed-loop test: its poses must agree with its
  images (to a tenth of a pixel, and as an independent detector sees them), its scenarios must do what their
  names say, it must be deterministic for a seed, and its AprilTag sheet must give vpDetectorAprilTag's pose.
*/
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include <visp3/core/vpMath.h>
#include <visp3/core/vpMeterPixelConversion.h>
#include <visp3/core/vpRzyxVector.h>
#include <visp3/detection/vpDetectorAprilTag.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl/vpSSLPattern.h>
#include <visp3/ssl_sim/vpSSLAprilTagSheet.h>
#include <visp3/ssl_sim/vpSSLBackground.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>
#include <visp3/ssl_sim/vpSSLScenario.h>
#include <visp3/ssl_sim/vpSSLWaterModel.h>

#include "ssl_test_utils.h"

namespace {
// The simulator's default camera (data/camera/camera-640x480.xml): 60 deg horizontal field of view.
const vpCameraParameters kCam(554.3, 554.3, 320., 240.);
const unsigned int kWidth = 640, kHeight = 480;

std::vector<vpSSLScenarioFrame> frames(const std::string &name, unsigned int n, long seed = 0)
{
  vpSSLScenario scenario(name);
  scenario.setFrames(n, 10.);
  scenario.setSeed(seed);
  return scenario.generate();
}

// Darkness centroid of landmark l in a clean render, over the pixels whose ray meets the sheet within
// maskRadius of its centre (white paper, or the white background, around it). Only the window around the
// landmark is rendered, 8 x 8 samples per pixel.
vpImagePoint renderedCentroid(const vpHomogeneousMatrix &cMo, const vpSSLTargetLandmark &l, double maskRadius)
{
  double umin = 1e9, umax = -1e9, vmin = 1e9, vmax = -1e9;
  for (int k = 0; k < 64; ++k) {
    const double a = 2. * M_PI * k / 64.;
    const vpImagePoint p =
        sslt::projectPoint(kCam, cMo, l.x + maskRadius * std::cos(a), l.y + maskRadius * std::sin(a));
    umin = std::min(umin, p.get_u());
    umax = std::max(umax, p.get_u());
    vmin = std::min(vmin, p.get_v());
    vmax = std::max(vmax, p.get_v());
  }
  const int u0 = static_cast<int>(std::floor(umin)) - 2, v0 = static_cast<int>(std::floor(vmin)) - 2;
  const unsigned int w = static_cast<unsigned int>(umax - u0) + 3, h = static_cast<unsigned int>(vmax - v0) + 3;
  vpSSLRenderer renderer(vpCameraParameters(kCam.get_px(), kCam.get_py(), kCam.get_u0() - u0, kCam.get_v0() - v0), w,
                         h);
  renderer.setSupersampling(8);
  renderer.setReflectances(0., 1., 1.);
  vpImage<float> reflectance, range;
  renderer.render(cMo, reflectance, range);
  const vpHomogeneousMatrix oMc = cMo.inverse();
  double su = 0., sv = 0., sw = 0.;
  for (unsigned int v = 0; v < h; ++v) {
    for (unsigned int u = 0; u < w; ++u) {
      const double x = (u + u0 - kCam.get_u0()) / kCam.get_px(), y = (v + v0 - kCam.get_v0()) / kCam.get_py();
      const double dx = oMc[0][0] * x + oMc[0][1] * y + oMc[0][2], dy = oMc[1][0] * x + oMc[1][1] * y + oMc[1][2];
      const double dz = oMc[2][0] * x + oMc[2][1] * y + oMc[2][2];
      const double t = -oMc[2][3] / dz;
      const double X = oMc[0][3] + t * dx, Y = oMc[1][3] + t * dy;
      if (std::hypot(X - l.x, Y - l.y) <= maskRadius) {
        const double darkness = 1. - reflectance[v][u];
        su += darkness * (u + u0);
        sv += darkness * (v + v0);
        sw += darkness;
      }
    }
  }
  return vpImagePoint(sv / sw, su / sw);
}

double angleBetween(const vpHomogeneousMatrix &a, const vpHomogeneousMatrix &b)
{
  return vpMath::deg(vpThetaUVector((a.inverse() * b).getRotationMatrix()).getTheta());
}

// Signed area of the triangle of the three image points: its sign is the handedness of B, S1, S2.
double orientation(const vpImagePoint &a, const vpImagePoint &b, const vpImagePoint &c)
{
  return (b.get_u() - a.get_u()) * (c.get_v() - a.get_v()) - (b.get_v() - a.get_v()) * (c.get_u() - a.get_u());
}
} // namespace

TEST(Simulator, GroundTruthAgreesWithTheImagesToATenthOfAPixel)
{
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  std::vector<vpSSLScenarioFrame> views;
  for (const auto &name : {"approach", "orbit", "spiral"}) {
    for (const vpSSLScenarioFrame &f : frames(name, 9)) {
      if (f.range <= 3.1) {
        views.push_back(f);
      }
    }
  }
  ASSERT_GE(views.size(), 12u);
  vpSSLRenderer renderer(kCam, kWidth, kHeight);
  size_t checked = 0;
  double worst = 0.;
  for (const vpSSLScenarioFrame &f : views) {
    // What the tutorial writes in gt_<landmark>_u/v.
    const std::vector<vpImagePoint> truth = renderer.projectLandmarks(f.cMo);
    for (size_t k = 0; k < target.size(); ++k) {
      const vpSSLTargetLandmark &l = target.getLandmark(k);
      const double apparent = sslt::apparentRadius(kCam, f.cMo, l.x, l.y, l.radius);
      if (apparent < 8.) {
        continue;
      }
      // Perspective moves the ring's centroid off the projected centre by a known amount (forward model).
      const vpImagePoint bias = sslt::forwardDarknessCentroid(kCam, f.cMo, l) - truth[k];
      const vpImagePoint seen = renderedCentroid(f.cMo, l, l.radius + 2.5 * f.range / kCam.get_px());
      const double error = vpImagePoint::distance(seen - bias, truth[k]);
      worst = std::max(worst, error);
      EXPECT_LT(error, 0.1) << "t = " << f.t << " s, range " << f.range << " m, landmark " << l.name
                            << ", bias of the centroid " << bias;
      checked++;
    }
  }
  EXPECT_GE(checked, 25u);
  std::cout << "ground truth vs rendered ring centres: " << checked << " landmarks, worst " << worst << " px"
            << std::endl;
}

TEST(Simulator, DetectorFindsTheLandmarksWhereTheGroundTruthPutsThem)
{
  vpSSLRenderer renderer(kCam, kWidth, kHeight);
  vpSSLDetector detector;
  detector.setSmallLandmarkMode(true);
  vpImage<unsigned char> I;
  size_t checked = 0;
  double worst = 0.;
  for (const vpSSLScenarioFrame &f : frames("approach", 12)) {
    if (f.range > 5. || f.range < 1.) {
      continue;
    }
    renderer.render(f.cMo, I);
    ASSERT_TRUE(detector.detect(I)) << "range " << f.range;
    ASSERT_TRUE(detector.getTargetMatch().found) << "range " << f.range;
    const std::vector<vpImagePoint> truth = renderer.projectLandmarks(f.cMo);
    for (size_t k = 0; k < truth.size(); ++k) {
      const vpSSLLandmark *l = detector.getMatchedLandmark(k);
      if (l == nullptr) {
        continue;
      }
      const double error = vpImagePoint::distance(l->getCenter(), truth[k]);
      worst = std::max(worst, error);
      EXPECT_LT(error, 0.5) << "range " << f.range << " m, landmark " << k;
      checked++;
    }
  }
  EXPECT_GE(checked, 8u);
  std::cout << "vpSSLDetector centres vs ground truth: " << checked << " landmarks, worst " << worst << " px"
            << std::endl;
}

TEST(Simulator, SameSeedSameSequenceOtherSeedOtherNoise)
{
  const std::vector<vpSSLScenarioFrame> a = frames("left-right", 20, 7), b = frames("left-right", 20, 7);
  const std::vector<vpSSLScenarioFrame> c = frames("left-right", 20, 8);
  for (size_t k = 0; k < a.size(); ++k) {
    for (unsigned int i = 0; i < 4; ++i) {
      for (unsigned int j = 0; j < 4; ++j) {
        ASSERT_EQ(a[k].cMo[i][j], b[k].cMo[i][j]);
        ASSERT_EQ(a[k].oMv[i][j], b[k].oMv[i][j]);
        ASSERT_EQ(a[k].cMo[i][j], c[k].cMo[i][j]); // the trajectory does not depend on the seed
      }
    }
  }
  EXPECT_NE(a.back().oMv[0][3], c.back().oMv[0][3]); // the odometry noise does

  vpSSLRenderer renderer(kCam, 160, 120);
  const vpSSLBackground seabed = vpSSLBackground::fromName("seabed", 3);
  seabed.apply(renderer);
  renderer.setBackdropPose(a[5].wMo.inverse() * seabed.getWorldPose(vpSSLScenario("left-right")));
  const vpSSLWaterModel water = vpSSLWaterModel::preset("coastal");
  vpImage<float> reflectance, range;
  vpImage<unsigned char> I1, I2, I3;
  renderer.render(a[5].cMo, reflectance, range);
  water.apply(reflectance, range, kCam, a[5].t, 11, I1);
  renderer.render(b[5].cMo, reflectance, range);
  water.apply(reflectance, range, kCam, b[5].t, 11, I2);
  water.apply(reflectance, range, kCam, b[5].t, 12, I3);
  EXPECT_TRUE(I1 == I2);
  EXPECT_FALSE(I1 == I3);
  EXPECT_TRUE(vpSSLBackground::seabedTexture(64, 5) == vpSSLBackground::seabedTexture(64, 5));
  EXPECT_FALSE(vpSSLBackground::seabedTexture(64, 5) == vpSSLBackground::seabedTexture(64, 6));
}

TEST(Simulator, ApproachGoesFrom10mToTheEndRangeWithTheTargetInView)
{
  const std::vector<vpSSLScenarioFrame> f = frames("approach", 40);
  EXPECT_NEAR(f.front().range, 10., 1e-9);
  EXPECT_NEAR(f.back().range, 0.5, 1e-9);
  vpSSLRenderer renderer(kCam, kWidth, kHeight);
  for (size_t k = 0; k < f.size(); ++k) {
    EXPECT_TRUE(renderer.isTargetInView(f[k].cMo)) << "frame " << k;
    if (k > 0) {
      EXPECT_LT(f[k].range, f[k - 1].range);
    }
    // The camera keeps the target near the image centre, as a homing vehicle does.
    const vpImagePoint B = renderer.projectLandmarks(f[k].cMo)[0];
    EXPECT_LT(std::fabs(B.get_u() - 320.), 100.) << "frame " << k;
  }
  vpSSLScenario shorter("approach");
  shorter.setRanges(12., 2.);
  shorter.setFrames(5, 10.);
  EXPECT_NEAR(shorter.generate().back().range, 2., 1e-9);
  EXPECT_THROW(shorter.setRanges(0.1, 2.), vpException);
  EXPECT_THROW(vpSSLScenario("dive"), vpException);
}

TEST(Simulator, OrbitKeepsItsRangeWhileTheViewSweeps120Degrees)
{
  const std::vector<vpSSLScenarioFrame> f = frames("orbit", 25);
  double minAngle = 1e9, maxAngle = -1e9;
  for (const vpSSLScenarioFrame &frame : f) {
    EXPECT_NEAR(frame.range, 3., 1e-9);
    // Azimuth of the camera around the target's vertical axis, from its normal.
    const vpTranslationVector oc = frame.cMo.inverse().getTranslationVector();
    const double azimuth = vpMath::deg(std::atan2(oc[0], -oc[2]));
    minAngle = std::min(minAngle, azimuth);
    maxAngle = std::max(maxAngle, azimuth);
  }
  EXPECT_NEAR(minAngle, -60., 1.);
  EXPECT_NEAR(maxAngle, 60., 1.);
}

TEST(Simulator, SpiralDescendsAndClosesWhileCirclingTheAxis)
{
  const std::vector<vpSSLScenarioFrame> f = frames("spiral", 61);
  EXPECT_NEAR(f.front().range, 8., 1e-9);
  EXPECT_NEAR(f.back().range, 1.5, 1e-9);
  EXPECT_LT(f.front().wMc[2][3], f.back().wMc[2][3] - 1.); // deeper at the end (NED: z down)
  EXPECT_GT(f.front().wMc[2][3], 0.2);                     // never out of the water
  int signChanges = 0;
  for (size_t k = 1; k < f.size(); ++k) {
    const double e0 = f[k - 1].wMc[1][3], e1 = f[k].wMc[1][3];
    signChanges += (e0 > 0.) != (e1 > 0.);
    EXPECT_GT(f[k].wMc[2][3], 0.2);
  }
  EXPECT_GE(signChanges, 3); // 1.5 turns cross the axis three times
}

TEST(Simulator, TargetLeavesTheViewAndComesBack)
{
  const std::vector<vpSSLScenarioFrame> f = frames("leave-return", 40);
  vpCameraParameters wide;
  wide.initPersProjWithDistortion(360., 360., 320., 240., -0.03, 0.032348);
  for (const vpCameraParameters &cam : {kCam, wide}) {
    vpSSLRenderer renderer(cam, kWidth, kHeight);
    renderer.setSupersampling(1);
    renderer.setReflectances(0., 1., 0.5);
    std::vector<bool> seen;
    for (const vpSSLScenarioFrame &frame : f) {
      seen.push_back(renderer.isTargetInView(frame.cMo));
      // The images agree: no sheet pixel when out of view.
      vpImage<unsigned char> I;
      renderer.render(frame.cMo, I);
      size_t sheet = 0;
      for (unsigned int p = 0; p < I.getSize(); ++p) {
        sheet += I.bitmap[p] != 128;
      }
      EXPECT_EQ(sheet > 0, seen.back()) << "t = " << frame.t;
    }
    // In view, then out for a while, then in view again.
    const auto firstOut = std::find(seen.begin(), seen.end(), false);
    ASSERT_NE(firstOut, seen.end());
    EXPECT_GT(firstOut - seen.begin(), 4);
    const auto back = std::find(firstOut, seen.end(), true);
    ASSERT_NE(back, seen.end());
    EXPECT_GT(back - firstOut, 4);
    EXPECT_TRUE(std::all_of(back, seen.end(), [](bool b) { return b; }));
  }
}

TEST(Simulator, LeftRightMovesTheTargetBothWaysAndTheVehicleYawsToFollow)
{
  const std::vector<vpSSLScenarioFrame> f = frames("left-right", 50);
  const vpSSLScenario scenario("left-right");
  const double home = scenario.getTargetHome()[1][3];
  double left = 0., right = 0., yawMin = 0., yawMax = 0.;
  vpSSLRenderer renderer(kCam, kWidth, kHeight);
  for (const vpSSLScenarioFrame &frame : f) {
    left = std::min(left, frame.wMo[1][3] - home);
    right = std::max(right, frame.wMo[1][3] - home);
    const double yaw = vpMath::deg(vpRzyxVector(frame.wMv.getRotationMatrix())[0]);
    yawMin = std::min(yawMin, yaw);
    yawMax = std::max(yawMax, yaw);
    EXPECT_TRUE(renderer.isTargetInView(frame.cMo)) << "t = " << frame.t;
  }
  EXPECT_LT(left, -0.75); // west first: left in the camera looking north
  EXPECT_GT(right, 0.75);
  EXPECT_LT(yawMin, -10.);
  EXPECT_GT(yawMax, 10.);
  EXPECT_NEAR(f.front().wMo[1][3], home, 1e-12);
  EXPECT_NEAR(f.back().wMo[1][3], home, 1e-12);
}

TEST(Simulator, SurfaceReflectionIsAMirrorImageOfOppositeHandedness)
{
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const vpSSLScenarioFrame f = frames("reflection", 11)[6];
  vpSSLRenderer renderer(kCam, kWidth, kHeight);
  renderer.setWaterSurface(vpSSLScenario::surfaceInTarget(f.wMo));
  // The mirror image of each landmark centre: its reflection through the surface plane, projected.
  const vpPlane s = vpSSLScenario::surfaceInTarget(f.wMo);
  const double n = std::sqrt(s.getA() * s.getA() + s.getB() * s.getB() + s.getC() * s.getC());
  std::vector<vpImagePoint> real = renderer.projectLandmarks(f.cMo), mirror;
  for (const vpSSLTargetLandmark &l : target.getLandmarks()) {
    const double d = (s.getA() * l.x + s.getB() * l.y + s.getC() * l.z + s.getD()) / n;
    mirror.push_back(sslt::projectPoint(kCam, f.cMo, l.x - 2. * d * s.getA() / n, l.y - 2. * d * s.getB() / n,
                                        l.z - 2. * d * s.getC() / n));
  }
  ASSERT_GT(mirror[0].get_v(), 20.) << "the mirror image is out of view";
  EXPECT_LT(mirror[0].get_v(), real[0].get_v() - 50.); // above the target
  EXPECT_LT(orientation(real[0], real[1], real[2]) * orientation(mirror[0], mirror[1], mirror[2]), 0.);

  // The detector sees both images and identifies only the real target.
  vpImage<unsigned char> I;
  renderer.render(f.cMo, I);
  vpSSLDetector detector;
  detector.setSmallLandmarkMode(true);
  ASSERT_TRUE(detector.detect(I));
  ASSERT_TRUE(detector.getTargetMatch().found);
  const vpSSLLandmark *B = detector.getMatchedLandmark(0);
  ASSERT_NE(B, nullptr);
  EXPECT_LT(vpImagePoint::distance(B->getCenter(), real[0]), 1.);
  size_t mirrored = 0;
  for (const vpSSLLandmark &l : detector.getLandmarks()) {
    for (const vpImagePoint &m : mirror) {
      mirrored += vpImagePoint::distance(l.getCenter(), m) < 1.;
    }
  }
  EXPECT_GE(mirrored, 2u) << "the mirror image's landmarks are where the reflection puts them";

  // Without the surface there is no mirror image: open water (the background grey) where it was.
  renderer.clearWaterSurface();
  vpImage<unsigned char> J;
  renderer.render(f.cMo, J);
  int withSurface = 0, withoutSurface = 0;
  for (int dv = -8; dv <= 8; ++dv) {
    for (int du = -8; du <= 8; ++du) {
      const unsigned int v = static_cast<unsigned int>(mirror[0].get_v() + dv);
      const unsigned int u = static_cast<unsigned int>(mirror[0].get_u() + du);
      withSurface += std::abs(I[v][u] - 128);
      withoutSurface += std::abs(J[v][u] - 128);
    }
  }
  EXPECT_GT(withSurface, 17 * 17 * 30);
  EXPECT_EQ(withoutSurface, 0);
}

TEST(Simulator, OdometryDriftsWithDistanceTravelledButDepthAndAttitudeDoNot)
{
  const std::vector<vpSSLScenarioFrame> f = frames("approach", 100, 3);
  auto horizontalError = [](const vpSSLScenarioFrame &frame) {
    return std::hypot(frame.oMv[0][3] - frame.oMvTrue[0][3], frame.oMv[1][3] - frame.oMvTrue[1][3]);
  };
  EXPECT_NEAR(f.front().oMvTrue[0][3], 0., 1e-12); // the odometry frame starts at the vehicle
  EXPECT_LT(horizontalError(f.front()), 1e-12);
  const double drift = horizontalError(f.back());
  EXPECT_GT(drift, 0.02);
  EXPECT_LT(drift, 1.5); // 9.5 m travelled: a few percent
  for (const vpSSLScenarioFrame &frame : f) {
    EXPECT_LT(std::fabs(frame.oMv[2][3] - frame.oMvTrue[2][3]), 0.1);
    EXPECT_LT(angleBetween(frame.oMv, frame.oMvTrue), 10.);
  }
  // The vehicle frame is x forward: the odometry sees it move north, the camera's forward axis.
  EXPECT_GT(f.back().oMv[0][3], 8.);
}

TEST(Simulator, AprilTagPoseAgreesWithVpDetectorAprilTag)
{
  const vpSSLAprilTagSheet sheet = vpSSLAprilTagSheet::a3(0);
  EXPECT_NEAR(sheet.getTagSize(), 0.2376, 1e-12);
  EXPECT_EQ(vpSSLAprilTagSheet::fromName(sheet.getName()).getTagSize(), sheet.getTagSize());
  EXPECT_EQ(vpSSLAprilTagSheet::fromName("apriltag36h11-a3-id42").getId(), 42);
  EXPECT_THROW(vpSSLAprilTagSheet(587, 0.1, 0.2, 0.2), vpException);
  EXPECT_THROW(vpSSLAprilTagSheet(0, 0.25, 0.42, 0.297), vpException); // no room for the quiet border

  vpSSLRenderer renderer(kCam, kWidth, kHeight);
  renderer.setAprilTagSheet(sheet);
  // ViSP's tag frame at a few poses, and the approach scenario's views (the sheet frame turned to the tag's).
  std::vector<vpHomogeneousMatrix> poses = {sslt::lookAt(1.5) * vpSSLAprilTagSheet::getSheetToTag(),
                                            sslt::lookAt(2., 35., 20., 40.) * vpSSLAprilTagSheet::getSheetToTag(),
                                            sslt::lookAt(1., 50., 100., -70.) * vpSSLAprilTagSheet::getSheetToTag()};
  for (const vpSSLScenarioFrame &f : frames("approach", 9)) {
    if (f.range < 7.) {
      poses.push_back(f.cMo * vpSSLAprilTagSheet::getSheetToTag());
    }
  }
  vpDetectorAprilTag detector(vpDetectorAprilTag::TAG_36h11);
  vpDetectorAprilTag zAligned(vpDetectorAprilTag::TAG_36h11);
  zAligned.setZAlignedWithCameraAxis(true);
  vpImage<unsigned char> I;
  vpImagePoint offset(0., 0.);
  unsigned int nbCorners = 0;
  for (const vpHomogeneousMatrix &cMo : poses) {
    renderer.render(cMo, I);
    ASSERT_TRUE(detector.detect(I));
    ASSERT_EQ(detector.getNbObjects(), 1u);
    EXPECT_EQ(detector.getMessage(0), sheet.getMessage());
    vpHomogeneousMatrix cMoEst;
    ASSERT_TRUE(detector.getPose(0, sheet.getTagSize(), kCam, cMoEst));
    const double range = cMo.getTranslationVector().frobeniusNorm();
    EXPECT_LT((cMoEst.getTranslationVector() - cMo.getTranslationVector()).frobeniusNorm(), 0.01 * range)
        << "true " << vpPoseVector(cMo).t() << "estimated " << vpPoseVector(cMoEst).t();
    // A wrong frame convention would be off by 90 or 180 degrees. Near fronto-parallel views leave AprilTag's
    // rotation ill-conditioned (a quarter-pixel on the corners tilts the plane by several degrees); oblique
    // views pin it down.
    const double tilt = vpMath::deg(std::acos(std::fabs(cMo[2][2])));
    EXPECT_LT(angleBetween(cMoEst, cMo), tilt > 30. ? 1. : 10.) << "true " << vpPoseVector(cMo).t();
    // Corners in vpDetectorAprilTag's order, as the renderer projects them for the gt_c*_u/v columns. The
    // AprilTag library puts pixel centres at +0.5 (ViSP: at integers): its corners are half a pixel down-right.
    const std::vector<vpImagePoint> corners = renderer.projectLandmarks(cMo), found = detector.getPolygon(0);
    ASSERT_EQ(found.size(), 4u);
    for (size_t k = 0; k < 4; ++k) {
      EXPECT_LT(vpImagePoint::distance(corners[k] + vpImagePoint(0.5, 0.5), found[k]), 0.5) << "corner " << k;
      offset += found[k] - corners[k];
      nbCorners++;
    }
    // With a Z-aligned detector the pose is that of the sheet frame, X right, Y down, Z into the sheet.
    ASSERT_TRUE(zAligned.detect(I));
    ASSERT_TRUE(zAligned.getPose(0, sheet.getTagSize(), kCam, cMoEst));
    EXPECT_LT(angleBetween(cMoEst, cMo * vpSSLAprilTagSheet::getSheetToTag()), tilt > 30. ? 1. : 10.);
  }
  offset = offset / nbCorners;
  EXPECT_NEAR(offset.get_u(), 0.5, 0.1);
  EXPECT_NEAR(offset.get_v(), 0.5, 0.1);
  // Another id is another code.
  renderer.setAprilTagSheet(vpSSLAprilTagSheet::a3(42));
  renderer.render(poses[0], I);
  ASSERT_TRUE(detector.detect(I));
  ASSERT_EQ(detector.getNbObjects(), 1u);
  EXPECT_EQ(detector.getMessage(0), "36h11 id: 42");
}

TEST(Simulator, BackdropsAreSeenAtTheirDistance)
{
  const vpSSLScenario scenario("approach");
  const vpSSLScenarioFrame f = frames("approach", 9)[6];
  vpSSLRenderer renderer(kCam, kWidth, kHeight);
  vpImage<float> reflectance, range;

  // Open water: nothing but the sheet has a range.
  renderer.render(f.cMo, reflectance, range);
  EXPECT_TRUE(std::isinf(range[kHeight - 1][0]));

  // The seabed, 1.5 m below the target, is seen at the bottom of the image at its distance along the ray.
  const vpSSLBackground seabed = vpSSLBackground::fromName("seabed", 1);
  seabed.apply(renderer);
  renderer.setBackdropPose(f.wMo.inverse() * seabed.getWorldPose(scenario));
  renderer.render(f.cMo, reflectance, range);
  const double below = scenario.getSeabedDepth() - f.wMc[2][3];
  ASSERT_TRUE(std::isfinite(range[kHeight - 1][320]));
  // Ray of the bottom row: depth grows by sin(angle below the horizon) per metre.
  const vpHomogeneousMatrix wMc = f.wMc;
  const double y = (kHeight - 1 - kCam.get_v0()) / kCam.get_py();
  const double dz = wMc[2][1] * y + wMc[2][2];
  const double norm = std::sqrt(y * y + 1.);
  EXPECT_NEAR(range[kHeight - 1][320], below * norm / dz, 1e-3);
  EXPECT_TRUE(std::isinf(range[0][320])); // open water above

  // A photograph on a wall 2 m behind the target.
  const vpSSLBackground klimt = vpSSLBackground::fromName("klimt");
  ASSERT_EQ(klimt.getType(), vpSSLBackground::BACKGROUND_WALL);
  klimt.apply(renderer);
  renderer.setBackdropPose(f.wMo.inverse() * klimt.getWorldPose(scenario));
  renderer.render(f.cMo, reflectance, range);
  // The wall is the plane Z = 2 of the target frame: along the ray through pixel (5, 5) in the camera frame.
  const vpColVector normal = f.cMo.getRotationMatrix().getCol(2);
  const vpColVector onWall = vpColVector(f.cMo * vpTranslationVector(0., 0., 2.));
  const vpColVector ray(
      std::vector<double>{(5. - kCam.get_u0()) / kCam.get_px(), (5. - kCam.get_v0()) / kCam.get_py(), 1.});
  EXPECT_NEAR(range[5][5],
              vpColVector::dotProd(normal, onWall) / vpColVector::dotProd(normal, ray) * ray.frobeniusNorm(), 1e-3);
  EXPECT_THROW(vpSSLBackground::fromName("no-such-image.png"), vpException);
}

TEST(Simulator, ReportsFrameTime)
{
  const vpSSLScenario scenario("approach");
  const vpSSLScenarioFrame f = frames("approach", 9)[5];
  vpSSLRenderer renderer(kCam, kWidth, kHeight);
  const vpSSLWaterModel water = vpSSLWaterModel::preset("clear");
  renderer.setMaxRange(std::log(1e5) / 0.33); // as the tutorial does: beyond, the clear water leaves no signal
  vpImage<float> reflectance, range;
  vpImage<unsigned char> I;
  for (const char *name : {"water", "seabed", "klimt"}) {
    const vpSSLBackground background = vpSSLBackground::fromName(name, 1);
    background.apply(renderer);
    renderer.setBackdropPose(f.wMo.inverse() * background.getWorldPose(scenario));
    renderer.setWaterSurface(vpSSLScenario::surfaceInTarget(f.wMo));
    const auto t0 = std::chrono::steady_clock::now();
    renderer.render(f.cMo, reflectance, range);
    const auto t1 = std::chrono::steady_clock::now();
    water.apply(reflectance, range, kCam, f.t, 1, I);
    const auto t2 = std::chrono::steady_clock::now();
    std::cout << "640x480 " << name << ": render " << std::chrono::duration<double, std::milli>(t1 - t0).count()
              << " ms, water " << std::chrono::duration<double, std::milli>(t2 - t1).count() << " ms" << std::endl;
    const auto [lo, hi] = std::minmax_element(I.bitmap, I.bitmap + I.getSize());
    EXPECT_GT(*hi - *lo, 40) << name << ": the target must show";
  }
}

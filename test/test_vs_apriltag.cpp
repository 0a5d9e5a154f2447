// Tests of the SSL vs AprilTag benchmark: the AprilTag baseline's pose error on ViSP's own AprilTag
// benchmark images, and the arithmetic of the report (range bands, rates, range90, percentiles, pose errors).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <visp3/core/vpIoTools.h>
#include <visp3/ssl_harness/vpSSLAprilTagBaseline.h>
#include <visp3/ssl_harness/vpSSLBenchMath.h>
#include <visp3/ssl_harness/vpSSLDetectionStats.h>
#include <visp3/ssl_sim/vpSSLAprilTagSheet.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>
#include <visp3/ssl_sim/vpSSLWaterModel.h>

namespace {
const std::string kVispBenchmark = std::string(VISP_SSL_IMAGES_DIR) + "/AprilTag/benchmark/640x480";

vpSSLFrameResult frame(double range, bool detected)
{
  vpSSLFrameResult f;
  f.truthKnown = true;
  f.hasTarget = true;
  f.range = range;
  f.detected = detected;
  f.timeMs = 1.;
  return f;
}
} // namespace

// The baseline is a fair one: on ViSP's rendered benchmark image (the setup of ViSP's testAprilTag) it finds the
// five tags and its poses are within a few millimetres and a third of a degree of the truth, well inside the
// bounds ViSP's own test allows (RMS translation 0.025-0.13 m, RMS theta-u 0.04-0.18 rad).
TEST(AprilTagBaseline, PoseErrorOnVispBenchmarkImages)
{
  if (!vpIoTools::checkFilename(kVispBenchmark + "/tag36_11_640x480.png"))
    GTEST_SKIP() << "visp-images-data not installed: " << kVispBenchmark;
  const std::vector<vpSSLAprilTagBaseline::BenchmarkResult> res =
      vpSSLAprilTagBaseline::runOnVispBenchmark(kVispBenchmark);
  ASSERT_EQ(res.size(), 5u);
  for (size_t i = 0; i < res.size(); ++i) {
    SCOPED_TRACE("tag " + std::to_string(i));
    ASSERT_EQ(res[i].id, static_cast<int>(i)) << "not detected";
    // Measured 1.5 / 2.4 / 19.8 / 6.0 / 6.8 mm and 0.11-0.30 deg (tag 2 is seen at a grazing angle).
    EXPECT_LT(res[i].positionError, 0.03);
    EXPECT_LT(res[i].angleError, 0.5);
    EXPECT_LT(res[i].rmsTranslation, 0.025); // the tightest of ViSP's bounds
    EXPECT_LT(res[i].rmsThetaU, 0.04);
  }
}

// The baseline recovers the rendered A3 sheet's pose in the tag frame the sequences use as ground truth.
TEST(AprilTagBaseline, FindsRenderedA3SheetPose)
{
  vpCameraParameters cam(554., 554., 320., 240.);
  const vpSSLAprilTagSheet sheet = vpSSLAprilTagSheet::a3(0);
  vpSSLRenderer renderer(cam, 640, 480);
  renderer.setAprilTagSheet(sheet);
  const vpHomogeneousMatrix cMo(0.1, -0.05, 2., vpMath::rad(170.), vpMath::rad(10.), vpMath::rad(5.));
  vpImage<unsigned char> I;
  renderer.render(cMo, I);
  vpSSLAprilTagBaseline baseline(sheet, cam);
  ASSERT_TRUE(baseline.detect(I));
  EXPECT_EQ(baseline.getNbOthers(), 0u);
  EXPECT_LT(vpSSLBenchMath::positionError(baseline.getPose(), cMo), 0.02);
  EXPECT_LT(vpSSLBenchMath::angleError(baseline.getPose(), cMo), 2.);
  // Another id on the same sheet is not the target: no detection of it, one "other" tag.
  vpSSLAprilTagBaseline other(vpSSLAprilTagSheet::a3(1), cam);
  EXPECT_FALSE(other.detect(I));
  EXPECT_EQ(other.getNbOthers(), 1u);
}

// Reading a window around the tag (the Monte Carlo's fused AprilTag method) finds the tag the whole
// image finds, with the same corners to within a fifth of a pixel (AprilTag's quad fit takes near-tied choices that
// the coordinates' rounding can flip), and reads the whole image when the window misses the tag or cuts it.
TEST(AprilTagBaseline, WindowGivesTheWholeImageDetection)
{
  const vpCameraParameters cam(554., 554., 320., 240.);
  const vpSSLAprilTagSheet sheet = vpSSLAprilTagSheet::a3(0);
  vpSSLRenderer renderer(cam, 640, 480);
  renderer.setAprilTagSheet(sheet);
  const vpSSLWaterModel water = vpSSLWaterModel::preset("coastal");
  const double poses[][6] = {{0.1, -0.05, 2., 170., 10., 5.},   {-0.4, 0.2, 3., 180., -30., 0.},
                             {0.5, 0.3, 1.5, 160., 20., -20.},  {0., 0., 1., 180., 0., 40.},
                             {-0.8, -0.5, 3.5, 175., 35., 10.}, {0.2, 0.1, 2.5, 190., -15., 80.}};
  vpImage<float> reflectance, range;
  vpImage<unsigned char> I;
  int nbWindowed = 0;
  for (size_t k = 0; k < sizeof(poses) / sizeof(poses[0]); ++k) {
    SCOPED_TRACE("pose " + std::to_string(k));
    const double *q = poses[k];
    const vpHomogeneousMatrix cMo(q[0], q[1], q[2], vpMath::rad(q[3]), vpMath::rad(q[4]), vpMath::rad(q[5]));
    renderer.render(cMo, reflectance, range);
    water.apply(reflectance, range, cam, 0., static_cast<long>(k), I);
    vpSSLAprilTagBaseline whole(sheet, cam), windowed(sheet, cam);
    ASSERT_TRUE(whole.detect(I));
    const std::vector<vpImagePoint> corners = renderer.projectLandmarks(cMo);
    double uMin = 1e9, uMax = -1e9, vMin = 1e9, vMax = -1e9;
    for (const vpImagePoint &c : corners) {
      uMin = std::min(uMin, c.get_u());
      uMax = std::max(uMax, c.get_u());
      vMin = std::min(vMin, c.get_v());
      vMax = std::max(vMax, c.get_v());
    }
    // Around the tag: read in the window when it does not cover the image.
    const double m = 40.;
    ASSERT_TRUE(windowed.detect(I, vpRect(vpImagePoint(vMin - m, uMin - m), vpImagePoint(vMax + m, uMax + m))));
    nbWindowed += windowed.usedWindow() ? 1 : 0;
    ASSERT_EQ(windowed.getPolygon().size(), 4u);
    for (size_t i = 0; i < 4; ++i) {
      EXPECT_LT(vpImagePoint::distance(windowed.getPolygon()[i], whole.getPolygon()[i]), 0.2) << "corner " << i;
    }
    EXPECT_LT(vpSSLBenchMath::positionError(windowed.getPose(), whole.getPose()), 0.01);
    EXPECT_LT(vpSSLBenchMath::angleError(windowed.getPose(), whole.getPose()), 1.);
    // A window that cuts the tag, and one beside it: the whole image is read.
    const double uMid = 0.5 * (uMin + uMax);
    for (const vpRect &r : {vpRect(vpImagePoint(vMin - m, uMin - m), vpImagePoint(vMax + m, uMid)),
                            vpRect(vpImagePoint(vMin - m, uMax + 30.), vpImagePoint(vMax + m, uMax + 130.))}) {
      ASSERT_TRUE(windowed.detect(I, r));
      EXPECT_FALSE(windowed.usedWindow());
      for (size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(windowed.getPolygon()[i], whole.getPolygon()[i]);
      }
    }
  }
  EXPECT_GE(nbWindowed, 4); // the near views' windows cover the image
}

TEST(BenchmarkArithmetic, BandsCoverZeroToTwelveMetres)
{
  EXPECT_EQ(vpSSLBenchMath::bandIndex(0.), 0);
  EXPECT_EQ(vpSSLBenchMath::bandIndex(0.999), 0);
  EXPECT_EQ(vpSSLBenchMath::bandIndex(1.), 1);
  EXPECT_EQ(vpSSLBenchMath::bandIndex(3.9), 2);
  EXPECT_EQ(vpSSLBenchMath::bandIndex(4.), 3);
  EXPECT_EQ(vpSSLBenchMath::bandIndex(8.), 4);
  EXPECT_EQ(vpSSLBenchMath::bandIndex(12.), 4);
  EXPECT_EQ(vpSSLBenchMath::bandIndex(12.01), -1);
  EXPECT_EQ(vpSSLBenchMath::bandIndex(-0.1), -1);
  EXPECT_EQ(vpSSLBenchMath::bandIndex(vpSSLBenchMath::nan()), -1);
  EXPECT_EQ(vpSSLBenchMath::bandLabel(0), "0-1");
  EXPECT_EQ(vpSSLBenchMath::bandLabel(4), "8-12");
}

TEST(BenchmarkArithmetic, RatesPerBandAndFalseDetections)
{
  vpSSLDetectionStats s;
  s.add(frame(0.5, true));
  s.add(frame(1.5, true));
  s.add(frame(1.6, false));
  s.add(frame(5., true));
  s.add(frame(5.2, true));
  s.add(frame(5.4, false));
  s.add(frame(20., false)); // beyond the bands: counted in the overall rate only
  vpSSLFrameResult none;
  none.truthKnown = true;
  none.hasTarget = false;
  none.detected = true;
  none.falseDetection = true;
  s.add(none);
  EXPECT_EQ(s.nbFrames, 8u);
  EXPECT_EQ(s.nbWithTarget, 7u);
  EXPECT_EQ(s.nbDetected, 4u);
  EXPECT_EQ(s.nbNoTarget, 1u);
  EXPECT_EQ(s.nbFalse, 1u);
  EXPECT_DOUBLE_EQ(s.rate(), 4. / 7.);
  EXPECT_DOUBLE_EQ(s.bandRate(0), 1.);
  EXPECT_DOUBLE_EQ(s.bandRate(1), 0.5);
  EXPECT_TRUE(std::isnan(s.bandRate(2)));
  EXPECT_DOUBLE_EQ(s.bandRate(3), 2. / 3.);
  EXPECT_TRUE(std::isnan(s.bandRate(4)));
}

// A position-only pose (the SSL tracker on one landmark) has a placeholder rotation: its angle error would be
// whatever that placeholder is. Such frames count as detected and in the position error, apart in
// nbPositionOnly, and never in the angle statistics, even when the caller filled angleError.
TEST(BenchmarkArithmetic, PositionOnlyFramesAreLeftOutOfTheAngleStatistics)
{
  vpSSLDetectionStats s, t;
  const double angles[3] = {1., 2., 3.};
  for (double a : angles) {
    vpSSLFrameResult f = frame(2., true);
    f.positionError = 0.01;
    f.angleError = a;
    s.add(f);
  }
  for (int i = 0; i < 4; ++i) {
    vpSSLFrameResult f = frame(6., true);
    f.orientationKnown = false;
    f.positionError = 0.05;
    f.angleError = 90.; // what a placeholder rotation gives: must not reach the median
    s.add(f);
  }
  vpSSLFrameResult missed = frame(7., false);
  missed.orientationKnown = false; // not detected: not a position-only pose either
  s.add(missed);
  EXPECT_EQ(s.nbDetected, 7u);
  EXPECT_EQ(s.nbPositionOnly, 4u);
  EXPECT_DOUBLE_EQ(vpSSLBenchMath::percentile(s.angle, 50.), 2.);
  EXPECT_DOUBLE_EQ(vpSSLBenchMath::percentile(s.angle, 100.), 3.);
  EXPECT_DOUBLE_EQ(vpSSLBenchMath::percentile(s.position, 50.), 0.05); // positions of all 7 detected frames count
  t.merge(s);
  t.merge(s);
  EXPECT_EQ(t.nbPositionOnly, 8u);
  EXPECT_DOUBLE_EQ(vpSSLBenchMath::percentile(t.angle, 100.), 3.);
}

TEST(BenchmarkArithmetic, Range90IsTheFarthestBinDetectedNineTimesInTen)
{
  vpSSLDetectionStats s;
  for (int i = 0; i < 10; ++i)
    s.add(frame(2.1, true)); // bin [2, 2.5): 10/10
  for (int i = 0; i < 10; ++i)
    s.add(frame(4.2, i != 0)); // bin [4, 4.5): 9/10, still >= 90 %
  for (int i = 0; i < 10; ++i)
    s.add(frame(6.3, i > 1)); // bin [6, 6.5): 8/10
  EXPECT_DOUBLE_EQ(s.range90(0.5, 0.9), 4.5);
  EXPECT_DOUBLE_EQ(s.range90(0.5, 0.8), 6.5);
  EXPECT_DOUBLE_EQ(s.range90(1., 0.9), 5.);
  vpSSLDetectionStats empty;
  EXPECT_TRUE(std::isnan(empty.range90()));
}

TEST(BenchmarkArithmetic, RecordingWithoutTruthGivesTheRateOfFramesWithADetection)
{
  vpSSLDetectionStats s;
  for (int i = 0; i < 4; ++i) {
    vpSSLFrameResult f;
    f.detected = (i < 3);
    f.timeMs = i + 1.;
    s.add(f);
  }
  EXPECT_EQ(s.nbWithTarget, 0u);
  EXPECT_DOUBLE_EQ(s.rate(), 0.75);
  EXPECT_TRUE(std::isnan(s.range90()));
  EXPECT_DOUBLE_EQ(vpSSLBenchMath::percentile(s.time, 50.), 2.5);
}

TEST(BenchmarkArithmetic, PercentilesInterpolateAndSkipNaN)
{
  EXPECT_DOUBLE_EQ(vpSSLBenchMath::percentile({3., 1., 2.}, 50.), 2.);
  EXPECT_DOUBLE_EQ(vpSSLBenchMath::percentile({1., 2., 3., 4.}, 50.), 2.5);
  EXPECT_NEAR(vpSSLBenchMath::percentile({0., 10., 20., 30., 40., 50., 60., 70., 80., 90., 100.}, 95.), 95., 1e-12);
  EXPECT_DOUBLE_EQ(vpSSLBenchMath::percentile({vpSSLBenchMath::nan(), 5.}, 50.), 5.);
  EXPECT_TRUE(std::isnan(vpSSLBenchMath::percentile({}, 50.)));
}

TEST(BenchmarkArithmetic, PoseErrors)
{
  const vpHomogeneousMatrix truth(0.1, 0.2, 3., 0.1, -0.2, 0.3);
  const vpHomogeneousMatrix turned = truth * vpHomogeneousMatrix(0., 0., 0., 0., 0., vpMath::rad(7.));
  EXPECT_NEAR(vpSSLBenchMath::angleError(turned, truth), 7., 1e-9);
  EXPECT_NEAR(vpSSLBenchMath::positionError(turned, truth), 0., 1e-12);
  const vpHomogeneousMatrix moved(0.1, 0.2 + 0.03, 3. + 0.04, 0.1, -0.2, 0.3);
  EXPECT_NEAR(vpSSLBenchMath::positionError(moved, truth), 0.05, 1e-12);
  EXPECT_NEAR(vpSSLBenchMath::angleError(moved, truth), 0., 1e-4); // acos near 1
}

// Target identification (paper Sec. 3.2): the three landmarks of ssl3-a3 are labelled B, S1, S2 from the
// model alone; a mirrored target (a reflection in the water surface) is not; a lone landmark, or two that cannot
// be told apart from B, fall back to the big one; S1 and S2 without B keep their size.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include <visp3/io/vpImageIo.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl/vpSSLPoseEstimator.h>
#include <visp3/ssl_io/vpSSLCameraFile.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>

#include "ssl_test_utils.h"

namespace {
const vpCameraParameters kCam(800., 800., 319.6, 240.3);

struct Scene
{
  vpImage<unsigned char> I;
  std::vector<vpImagePoint> truth; // B, S1, S2
};

Scene render(const vpHomogeneousMatrix &cMo)
{
  vpSSLRenderer renderer(kCam, 640, 480);
  renderer.setTarget(vpSSLTarget::ssl3a3());
  renderer.setReflectances(0., 1., 0.35);
  Scene s;
  renderer.render(cMo, s.I);
  s.truth = renderer.projectLandmarks(cMo);
  return s;
}

std::string describe(double d, double tilt, double axis, double roll)
{
  return "d=" + std::to_string(d) + " tilt=" + std::to_string(tilt) + " axis=" + std::to_string(axis) +
         " roll=" + std::to_string(roll);
}
} // namespace

TEST(Identification, LabelsBS1S2InRenderedViews)
{
  vpSSLDetector detector;
  const char *names[3] = {"B", "S1", "S2"};
  for (double d : {0.9, 1.2}) {
    for (double tilt : {0., 20., 35.}) {
      for (double roll : {0., 70., 160., 250., 320.}) {
        const double axis = roll * 0.7;
        const Scene s = render(sslt::lookAt(d, tilt, axis, roll));
        detector.detect(s.I);
        const vpSSLTargetMatch &m = detector.getTargetMatch();
        ASSERT_TRUE(m.found) << describe(d, tilt, axis, roll);
        EXPECT_EQ(m.nbMatched, 3u) << describe(d, tilt, axis, roll);
        for (size_t k = 0; k < 3; ++k) {
          const vpSSLLandmark *l = detector.getMatchedLandmark(k);
          ASSERT_NE(l, nullptr) << names[k] << " " << describe(d, tilt, axis, roll);
          EXPECT_LT(std::hypot(l->u - s.truth[k].get_u(), l->v - s.truth[k].get_v()), 1.0)
              << names[k] << " " << describe(d, tilt, axis, roll);
        }
      }
    }
  }
}

TEST(Identification, FarTargetInSmallLandmarkMode)
{
  // At 3.5 m the small landmarks measure 11 px: found in small-landmark mode, and still labelled.
  vpSSLDetector detector;
  detector.setSmallLandmarkMode(true);
  const Scene s = render(sslt::lookAt(3.5, 20., 10., 40.));
  detector.detect(s.I);
  ASSERT_TRUE(detector.getTargetMatch().found);
  EXPECT_EQ(detector.getTargetMatch().nbMatched, 3u);
  for (size_t k = 0; k < 3; ++k) {
    const vpSSLLandmark *l = detector.getMatchedLandmark(k);
    ASSERT_NE(l, nullptr) << k;
    EXPECT_LT(std::hypot(l->u - s.truth[k].get_u(), l->v - s.truth[k].get_v()), 1.0) << k;
  }
}

TEST(Identification, MirrorImageIsNotGivenThePhysicalLabels)
{
  // A reflection in the water surface flips the triangle's handedness. ssl3-a3 is symmetric about the
  // axis through B, so its mirror image is an ssl3-a3 with S1 and S2 exchanged: the labels follow the
  // handedness, and the landmark labelled S1 is the image of the physical S2. (No single image can tell
  // a reflection of this target from the target itself; the tracker can, from its motion.)
  vpSSLDetector detector;
  for (double roll : {0., 90., 200.}) {
    Scene s = render(sslt::lookAt(1.2, 10., 0., roll));
    sslt::mirrorHorizontal(s.I);
    detector.detect(s.I);
    EXPECT_EQ(detector.getLandmarks().size(), 3u) << roll;
    ASSERT_EQ(detector.getTargetMatch().nbMatched, 3u) << "roll=" << roll;
    const double W = s.I.getWidth() - 1.;
    for (size_t k = 0; k < 3; ++k) {
      const size_t physical = (k == 0) ? 0 : 3 - k; // S1 <-> S2
      const vpSSLLandmark *l = detector.getMatchedLandmark(k);
      ASSERT_NE(l, nullptr);
      EXPECT_LT(std::hypot(l->u - (W - s.truth[physical].get_u()), l->v - s.truth[physical].get_v()), 1.0)
          << "label " << k << " roll=" << roll;
      if (k > 0) {
        EXPECT_GT(std::hypot(l->u - (W - s.truth[k].get_u()), l->v - s.truth[k].get_v()), 10.)
            << "a mirrored view must not get the physical label " << k;
      }
    }
  }
}

TEST(Identification, OneOrTwoVisibleLandmarksMeanTheBigOne)
{
  vpSSLDetector detector;
  // Case 1: the small landmarks hidden: B alone.
  Scene far = render(sslt::lookAt(2.6, 0., 0., 30.));
  for (size_t k = 1; k < 3; ++k) {
    sslt::occlude(far.I, vpRect(far.truth[k].get_u() - 25., far.truth[k].get_v() - 25., 50., 50.), 255);
  }
  detector.detect(far.I);
  EXPECT_EQ(detector.getLandmarks().size(), 1u);
  ASSERT_TRUE(detector.getTargetMatch().found);
  EXPECT_EQ(detector.getTargetMatch().nbMatched, 1u);
  const vpSSLLandmark *b = detector.getMatchedLandmark(0);
  ASSERT_NE(b, nullptr);
  EXPECT_LT(std::hypot(b->u - far.truth[0].get_u(), b->v - far.truth[0].get_v()), 1.0);

  // Case 2: S2 hidden: B and one small landmark cannot say which small one it is; B is still B.
  Scene two = render(sslt::lookAt(1.2, 0., 0., 0.));
  const vpImagePoint s2 = two.truth[2];
  sslt::occlude(two.I, vpRect(s2.get_u() - 45., s2.get_v() - 45., 90., 90.), 255);
  detector.detect(two.I);
  ASSERT_TRUE(detector.getTargetMatch().found);
  EXPECT_EQ(detector.getLandmarks().size(), 2u);
  EXPECT_EQ(detector.getTargetMatch().nbMatched, 1u);
  b = detector.getMatchedLandmark(0);
  ASSERT_NE(b, nullptr);
  EXPECT_LT(std::hypot(b->u - two.truth[0].get_u(), b->v - two.truth[0].get_v()), 1.0);
}

TEST(Identification, FeaturePointsFollowTheTargetOrder)
{
  vpSSLDetector detector;
  const vpHomogeneousMatrix cMo = sslt::lookAt(1.2, 0., 0., 15.);
  const Scene s = render(cMo);
  detector.detect(s.I);
  const std::vector<vpFeaturePoint> features = detector.getFeaturePoints(kCam);
  ASSERT_EQ(features.size(), 3u);
  const std::vector<vpPoint> P = vpSSLTarget::ssl3a3().getPoints();
  for (size_t k = 0; k < 3; ++k) {
    vpPoint p = P[k];
    p.track(cMo);
    EXPECT_NEAR(features[k].get_x(), p.get_x(), 1e-3) << k;
    EXPECT_NEAR(features[k].get_y(), p.get_y(), 1e-3) << k;
    EXPECT_NEAR(features[k].get_Z(), p.get_Z(), 0.05 * p.get_Z()) << k; // Eq. 6
  }
}

TEST(Identification, IdentifierAloneOnHandMadeLandmarks)
{
  // Three circles where the model puts them, seen fronto-parallel at 1000 px/m, and their mirror image.
  vpSSLTargetIdentifier identifier;
  const vpSSLTarget &t = identifier.getTarget();
  std::vector<vpSSLLandmark> landmarks;
  for (int k : {2, 0, 1}) { // any detection order
    vpSSLLandmark l;
    l.u = 320. + 1000. * t.getLandmark(k).x;
    l.v = 240. + 1000. * t.getLandmark(k).y;
    l.radius = l.minorRadius = 1000. * t.getLandmark(k).radius;
    landmarks.push_back(l);
  }
  vpSSLTargetMatch m = identifier.identify(landmarks);
  ASSERT_TRUE(m.found);
  EXPECT_EQ(m.nbMatched, 3u);
  EXPECT_EQ(m.detection[0], 1);
  EXPECT_EQ(m.detection[1], 2);
  EXPECT_EQ(m.detection[2], 0);
  for (vpSSLLandmark &l : landmarks) {
    l.u = 640. - l.u;
  }
  m = identifier.identify(landmarks);
  EXPECT_EQ(m.nbMatched, 3u);
  EXPECT_EQ(m.detection[0], 1);
  EXPECT_EQ(m.detection[1], 0); // handedness: the mirror image of S2 is labelled S1
  EXPECT_EQ(m.detection[2], 2);
  // Wrong size ratio: three equal circles are not the target's triangle.
  for (vpSSLLandmark &l : landmarks) {
    l.radius = l.minorRadius = 50.;
  }
  m = identifier.identify(landmarks);
  EXPECT_LE(m.nbMatched, 1u);
  EXPECT_TRUE(identifier.identify({}).detection == std::vector<int>(3, -1));
  EXPECT_FALSE(identifier.identify({}).found);
}

TEST(Identification, SmallPairWithoutTheBigLandmarkKeepsItsSize)
{
  // S1 and S2 alone (B out of the image or missed), fronto-parallel at 1000 px/m: they must not be taken for B,
  // whose radius would put them at twice their range. Upright, S1 is above S2; turned by a half turn the two swap,
  // and the identifier, which cannot tell, still labels the upper one S1.
  vpSSLTargetIdentifier identifier;
  const vpSSLTarget &t = identifier.getTarget();
  for (double turn : {0., M_PI}) {
    std::vector<vpSSLLandmark> landmarks;
    for (int k : {2, 1}) {
      const double x = t.getLandmark(k).x, y = t.getLandmark(k).y;
      vpSSLLandmark l;
      l.u = 320. + 1000. * (std::cos(turn) * x - std::sin(turn) * y);
      l.v = 240. + 1000. * (std::sin(turn) * x + std::cos(turn) * y);
      l.radius = l.minorRadius = 1000. * t.getLandmark(k).radius;
      landmarks.push_back(l);
    }
    const vpSSLTargetMatch m = identifier.identify(landmarks);
    ASSERT_TRUE(m.found) << turn;
    EXPECT_EQ(m.nbMatched, 2u) << turn;
    EXPECT_EQ(m.detection[0], -1) << turn;
    ASSERT_GE(m.detection[1], 0) << turn;
    ASSERT_GE(m.detection[2], 0) << turn;
    EXPECT_LT(landmarks[static_cast<size_t>(m.detection[1])].v, landmarks[static_cast<size_t>(m.detection[2])].v)
        << turn;
    // The pose estimator then reads the range from a small landmark's radius (Eq. 6): 1 m at 1000 px/m.
    const std::vector<vpSSLPoseHypothesis> h =
        vpSSLPoseEstimator(t).estimate(landmarks, m, vpCameraParameters(1000., 1000., 320., 240.));
    ASSERT_FALSE(h.empty());
    EXPECT_NEAR(h.front().cMo[2][3], 1., 1e-6) << turn;
  }
  // A detection of another size where B belongs (B read at its inner copy, the size of S1) leaves the reading to
  // the single-landmark case: the biggest detection is B.
  std::vector<vpSSLLandmark> landmarks;
  for (int k : {0, 1, 2}) {
    vpSSLLandmark l;
    l.u = 320. + 1000. * t.getLandmark(k).x;
    l.v = 240. + 1000. * t.getLandmark(k).y;
    l.radius = l.minorRadius = 1000. * t.getLandmark(k).radius * (k == 0 ? 0.5 : 1.);
    landmarks.push_back(l);
  }
  const vpSSLTargetMatch m = identifier.identify(landmarks);
  EXPECT_EQ(m.nbMatched, 1u);
  EXPECT_GE(m.detection[0], 0);
  EXPECT_EQ(m.detection[1], -1);
  EXPECT_EQ(m.detection[2], -1);
}

TEST(Identification, BigLandmarkInClearWaterAgainstDarkWater)
{
  // data/sequences/approach-clear frame 10 (simulated clear water, 1.36 m): the water beyond the sheet is
  // nearly as dark as the ink, so half of B's rays read one more ring; B must still be read at its size.
  const std::string dir = std::string(VISP_SSL_DATA_DIR) + "/sequences/approach-clear";
  vpImage<unsigned char> I;
  vpImageIo::read(I, dir + "/images/000010.png");
  const vpCameraParameters cam = vpSSLCameraFile::load(dir + "/camera.xml");
  vpSSLDetector detector;
  detector.detect(I);
  const vpSSLLandmark *b = detector.getMatchedLandmark(0);
  ASSERT_NE(b, nullptr);
  // Ground truth (frames.csv): the target origin at (0.047, 0.033, 1.362) m; B is 0.104 m from it.
  const double range = vpSSLDetector::range(*b, 0.1, cam);
  EXPECT_NEAR(range, 1.36, 0.12) << "B read at " << b->radius << " px";
}

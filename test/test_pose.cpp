// Pose from one frame (paper Sec. 3.2): case 1 gives the range from the apparent radius (Eq. 6), case 3
// gives every P3P pose in front of the camera, and the landmarks' ellipses single out the true one.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <visp3/core/vpThetaUVector.h>
#include <visp3/core/vpUniRand.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl/vpSSLPoseEstimator.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>
#include <visp3/ssl_sim/vpSSLWaterModel.h>

#include "ssl_test_utils.h"

namespace {
// 640x480 camera of 800 px focal length: the small landmarks (0.05 m) stay above 16 px of radius up to
// 2.5 m, inside what the detector's small-landmark mode reads.
vpCameraParameters camera()
{
  return vpCameraParameters(800., 800., 319.6, 240.3);
}

// The scene of the rendered-view tests: a target (ssl3-a3 unless told) rendered through camera() at 640x480, and a
// detector of it with its defaults. A test names its parts with a structured binding.
struct Scene
{
  explicit Scene(const vpSSLTarget &t = vpSSLTarget::ssl3a3()) : target(t), renderer(cam, 640, 480), detector(t)
  {
    renderer.setTarget(target);
  }
  const vpSSLTarget target;
  const vpCameraParameters cam = camera();
  vpSSLRenderer renderer;
  vpSSLDetector detector;
};

double angleDeg(const vpHomogeneousMatrix &A, const vpHomogeneousMatrix &B)
{
  return vpMath::deg(vpThetaUVector((A.inverse() * B).getRotationMatrix()).getTheta());
}

double rangeError(const vpHomogeneousMatrix &est, const vpHomogeneousMatrix &gt)
{
  const double r = gt.getTranslationVector().frobeniusNorm();
  return std::fabs(est.getTranslationVector().frobeniusNorm() - r) / r;
}

// The paper's "true pose" for this test: within 5 deg and 5 % of the range.
bool isTrue(const vpHomogeneousMatrix &est, const vpHomogeneousMatrix &gt)
{
  return angleDeg(est, gt) < 5. && rangeError(est, gt) < 0.05;
}

struct Detection
{
  vpImage<unsigned char> I;
  bool ok = false;
  std::vector<vpSSLLandmark> landmarks;
  vpSSLTargetMatch match;
};

Detection renderAndDetect(vpSSLRenderer &renderer, vpSSLDetector &detector, const vpHomogeneousMatrix &cMo)
{
  Detection d;
  renderer.render(cMo, d.I);
  detector.detect(d.I);
  d.landmarks = detector.getLandmarks();
  d.match = detector.getTargetMatch();
  d.ok = d.match.found;
  return d;
}

// Exact centres and ellipses of the target's landmarks at cMo (no detector): what a perfect detector reads.
Detection perfectDetection(const vpSSLTarget &target, const vpCameraParameters &cam, const vpHomogeneousMatrix &cMo)
{
  Detection d;
  for (size_t k = 0; k < target.size(); ++k) {
    const vpSSLTargetLandmark &t = target.getLandmark(k);
    vpSSLLandmark l;
    const vpImagePoint c = sslt::projectPoint(cam, cMo, t.x, t.y, t.z);
    l.u = c.get_u();
    l.v = c.get_v();
    vpSSLPoseEstimator::projectCircle(cam, cMo, t.x, t.y, t.z, t.radius, l.radius, l.minorRadius, l.theta);
    d.landmarks.push_back(l);
    d.match.detection.push_back(static_cast<int>(k));
  }
  d.match.found = true;
  d.match.nbMatched = static_cast<unsigned int>(target.size());
  d.ok = true;
  return d;
}

// Every hypothesis must put every landmark disc in front of the camera.
void expectInFront(const std::vector<vpSSLPoseHypothesis> &hs, const vpSSLTarget &target, const std::string &what)
{
  for (const vpSSLPoseHypothesis &h : hs) {
    for (const vpSSLTargetLandmark &t : target.getLandmarks()) {
      const double z = h.cMo[2][0] * t.x + h.cMo[2][1] * t.y + h.cMo[2][2] * t.z + h.cMo[2][3];
      EXPECT_GT(z, 0.) << what << " landmark " << t.name;
    }
  }
}
} // namespace

TEST(Pose, ProjectedCircleIsTheExactEllipse)
{
  const vpCameraParameters cam = camera();
  for (double tilt : {0., 25., 50., 65.}) {
    for (double roll : {0., 40., 110.}) {
      const vpHomogeneousMatrix cMo = sslt::lookAt(1.3, tilt, roll + 15., roll);
      double a, b, theta;
      ASSERT_TRUE(vpSSLPoseEstimator::projectCircle(cam, cMo, 0.1, -0.05, 0., 0.1, a, b, theta));
      // Reference: the widest extent of 360 projected circle points.
      EXPECT_NEAR(a, sslt::apparentRadius(cam, cMo, 0.1, -0.05, 0.1), 1e-3 * a) << tilt << " " << roll;
      EXPECT_LE(b, a);
      // The minor axis shrinks like cos(tilt) (weak perspective).
      EXPECT_NEAR(b / a, std::cos(vpMath::rad(tilt)), 0.03) << tilt;
    }
  }
  double a, b, theta;
  EXPECT_FALSE(vpSSLPoseEstimator::projectCircle(cam, sslt::lookAt(0.05, 80.), 0., 0., 0., 0.1, a, b, theta));
}

TEST(Pose, P3PHypothesesAreInFrontOfTheCameraAndContainTheTruth)
{
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const vpCameraParameters cam = camera();
  vpSSLPoseEstimator estimator(target);
  vpUniRand rng(7);
  int nbRankedFirst = 0, n = 0;
  for (int i = 0; i < 200; ++i, ++n) {
    const vpHomogeneousMatrix gt =
        sslt::lookAt(rng.uniform(0.6, 4.), rng.uniform(0., 60.), rng.uniform(0., 360.), rng.uniform(0., 360.)) *
        vpHomogeneousMatrix(rng.uniform(-0.1, 0.1), rng.uniform(-0.1, 0.1), 0, 0, 0, 0);
    const Detection d = perfectDetection(target, cam, gt);
    const std::vector<vpSSLPoseHypothesis> hs = estimator.estimate(d.landmarks, d.match, cam);
    ASSERT_FALSE(hs.empty());
    ASSERT_LE(hs.size(), 4u);
    expectInFront(hs, target, "pose " + std::to_string(i));
    bool found = false;
    for (const vpSSLPoseHypothesis &h : hs) {
      EXPECT_FALSE(h.positionOnly);
      EXPECT_EQ(h.nbLandmarks, 3u);
      EXPECT_LT(h.reprojectionError, 0.05);
      found = found || (angleDeg(h.cMo, gt) < 0.1 && rangeError(h.cMo, gt) < 1e-4);
    }
    EXPECT_TRUE(found) << "pose " << i << ": the true pose is not among the " << hs.size() << " hypotheses";
    nbRankedFirst += isTrue(hs.front().cMo, gt) ? 1 : 0;
  }
  // With exact ellipses the agreement ranking must always put the truth first.
  EXPECT_EQ(nbRankedFirst, n);
}

TEST(Pose, ThreeLandmarkPoseOnRenderedViews)
{
  Scene scene;
  auto &[target, cam, renderer, detector] = scene;
  detector.setSmallLandmarkMode(true);
  vpSSLPoseEstimator estimator(target);
  const struct
  {
    double range, tilt, axis, roll;
  } views[] = {{1.0, 0., 0., 0.}, {1.2, 30., 20., 70.}, {1.6, 20., 100., 200.}, {2.0, 40., 250., 310.}};
  for (const auto &v : views) {
    const vpHomogeneousMatrix gt = sslt::lookAt(v.range, v.tilt, v.axis, v.roll);
    const std::string what = "range " + std::to_string(v.range) + " tilt " + std::to_string(v.tilt);
    const Detection d = renderAndDetect(renderer, detector, gt);
    ASSERT_TRUE(d.ok && d.match.nbMatched == 3) << what;
    const std::vector<vpSSLPoseHypothesis> hs = estimator.estimate(d.landmarks, d.match, cam);
    expectInFront(hs, target, what);
    const vpSSLPoseHypothesis &best = hs.front();
    EXPECT_FALSE(best.positionOnly);
    EXPECT_TRUE(best.refined);
    EXPECT_LT(best.reprojectionError, 0.5) << what;
    // Stated tolerances: 3 deg and 2 % of the range (three sub-pixel centres, a ~0.2 m baseline).
    EXPECT_LT(angleDeg(best.cMo, gt), 3.) << what;
    EXPECT_LT(rangeError(best.cMo, gt), 0.02) << what;
    EXPECT_LT(best.ellipseError, 0.15) << what;

    // The same image through vpSSLDetector::detect(I, cam, cMo_vec), shaped as vpDetectorAprilTag's: the pose
    // within the same tolerances, its position within 2 % of the range, and nothing reported as position-only.
    std::vector<vpHomogeneousMatrix> cMo_vec, cMo_vec2;
    std::vector<double> errors, errors2;
    std::vector<vpTranslationVector> positions(1); // filled on purpose: detect() clears it
    ASSERT_TRUE(detector.detect(d.I, cam, cMo_vec, &cMo_vec2, &errors, &errors2, &positions)) << what;
    ASSERT_EQ(cMo_vec.size(), 1u) << what;
    ASSERT_EQ(errors.size(), 1u) << what;
    EXPECT_EQ(cMo_vec2.size(), errors2.size()) << what;
    EXPECT_TRUE(positions.empty()) << what;
    EXPECT_LT(angleDeg(cMo_vec[0], gt), 3.) << what;
    EXPECT_LT((cMo_vec[0].getTranslationVector() - gt.getTranslationVector()).frobeniusNorm(), 0.02 * v.range) << what;
    EXPECT_LT(errors[0], 0.5) << what;
  }
}

TEST(Pose, OneLandmarkRangeFromApparentRadius)
{
  // Paper case 1, Eq. 6: one landmark read in a rendered image; its centre's position comes back.
  const double R = 0.1;
  Scene scene(sslt::singleLandmarkTarget(R));
  auto &[target, cam, renderer, detector] = scene;
  vpSSLPoseEstimator estimator(target);
  for (double range : {1.5, 3., 5.}) {
    const vpHomogeneousMatrix gt = sslt::lookAt(range, 5., 30., 10.) * vpHomogeneousMatrix(0.08, -0.05, 0, 0, 0, 0);
    const Detection d = renderAndDetect(renderer, detector, gt);
    ASSERT_TRUE(d.ok) << range;
    const std::vector<vpSSLPoseHypothesis> hs = estimator.estimate(d.landmarks, d.match, cam);
    ASSERT_EQ(hs.size(), 1u);
    const vpSSLPoseHypothesis &h = hs.front();
    EXPECT_TRUE(h.positionOnly);
    EXPECT_FALSE(h.orientationKnown);
    EXPECT_EQ(h.landmark, 0);
    const double trueRange = gt.getTranslationVector().frobeniusNorm();
    EXPECT_NEAR(h.cMo.getTranslationVector().frobeniusNorm(), trueRange, 0.03 * trueRange) << range;
    EXPECT_NEAR(h.cMo[0][3], gt[0][3], 0.03 * trueRange) << range;
    EXPECT_NEAR(h.cMo[1][3], gt[1][3], 0.03 * trueRange) << range;

    // Through vpSSLDetector::detect(I, cam, cMo_vec): no full pose (its identity rotation is an assumption), the
    // position apart.
    std::vector<vpHomogeneousMatrix> cMo_vec(1), cMo_vec2(1); // filled on purpose: detect() clears them
    std::vector<vpTranslationVector> positions;
    EXPECT_FALSE(detector.detect(d.I, cam, cMo_vec, &cMo_vec2, nullptr, nullptr, &positions)) << range;
    EXPECT_TRUE(cMo_vec.empty()) << range;
    EXPECT_TRUE(cMo_vec2.empty()) << range;
    ASSERT_EQ(positions.size(), 1u) << range;
    EXPECT_LT((positions[0] - h.cMo.getTranslationVector()).frobeniusNorm(), 1e-9) << range;
  }
}

TEST(Pose, TwoLandmarksAreTreatedAsTheBigOne)
{
  // Paper case 2: two landmarks give the big one's position from its radius, nothing more.
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const vpCameraParameters cam = camera();
  const vpHomogeneousMatrix gt = sslt::lookAt(2., 10., 0., 30.);
  Detection d = perfectDetection(target, cam, gt);
  const int B = target.findLandmark("B");
  d.match.detection[B == 1 ? 2 : 1] = -1;
  d.match.nbMatched = 2;
  const std::vector<vpSSLPoseHypothesis> hs = vpSSLPoseEstimator(target).estimate(d.landmarks, d.match, cam);
  ASSERT_EQ(hs.size(), 1u);
  EXPECT_TRUE(hs.front().positionOnly);
  EXPECT_EQ(hs.front().landmark, B);
  const vpSSLTargetLandmark &b = target.getLandmark(static_cast<size_t>(B));
  vpColVector oB(4, 1.);
  oB[0] = b.x;
  oB[1] = b.y;
  oB[2] = b.z;
  const vpColVector cB = gt * oB;
  for (unsigned int i = 0; i < 3; ++i) {
    EXPECT_NEAR(hs.front().cMo[i][3], cB[i], 0.02 * cB[2]) << i;
  }
}

TEST(Pose, BadInputThrows)
{
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  vpSSLPoseEstimator estimator(target);
  const Detection d = perfectDetection(target, camera(), sslt::lookAt(1.5));
  EXPECT_THROW(estimator.estimate(d.landmarks, d.match, vpCameraParameters(0., 0., 320., 240.)), vpException);
  vpSSLTargetMatch none;
  none.detection.assign(target.size(), -1);
  EXPECT_THROW(estimator.estimate(d.landmarks, none, camera()), vpException);
  EXPECT_THROW(estimator.estimate({}, vpSSLTargetMatch(), camera()), vpException);
  vpSSLTargetMatch outOfRange = d.match;
  outOfRange.detection[1] = 7;
  EXPECT_THROW(estimator.estimate(d.landmarks, outOfRange, camera()), vpException);
  try {
    estimator.estimate(d.landmarks, d.match, vpCameraParameters(0., 0., 320., 240.));
  } catch (const vpException &e) {
    EXPECT_NE(e.getStringMessage().find("px"), std::string::npos) << e.getStringMessage();
  }
}

// The figure of doc/pose.md: how often the first-frame best hypothesis is the true one, ranked by
// reprojection error only (the paper) and by agreement with the ellipses and radii. SSL_POSE_GRID=full
// runs the whole grid (ranges 1-2.5 m every 0.5 m, tilts 0-50 deg every 10 deg, 12 in-plane rotations).
TEST(Pose, EllipseAgreementPicksTheTruePoseOnTheFirstFrame)
{
  const bool full = std::getenv("SSL_POSE_GRID") != nullptr && std::string(std::getenv("SSL_POSE_GRID")) == "full";
  Scene scene;
  auto &[target, cam, renderer, detector] = scene;
  detector.setSmallLandmarkMode(true);
  vpSSLPoseEstimator ranked(target), paper(target);
  paper.setImageAgreement(false);
  const std::vector<double> ranges = full ? std::vector<double>{1., 1.5, 2., 2.5} : std::vector<double>{1., 1.75, 2.5};
  const std::vector<double> tilts =
      full ? std::vector<double>{0., 10., 20., 30., 40., 50.} : std::vector<double>{0., 25., 50.};
  const int nbRolls = full ? 12 : 4;
  int views = 0, three = 0, truthAmong = 0, firstRanked = 0, firstPaper = 0, nbHyp = 0;
  std::vector<double> angles, ranges_;
  std::printf("range tilt  n3  truth_in  ranked_ok  paper_ok\n");
  for (double range : ranges) {
    for (double tilt : tilts) {
      int t3 = 0, tIn = 0, tR = 0, tP = 0;
      for (int i = 0; i < nbRolls; ++i) {
        const double roll = 360. * i / nbRolls + 7.;
        const double axis = std::fmod(roll * 2.3 + 40., 360.);
        const vpHomogeneousMatrix gt = sslt::lookAt(range, tilt, axis, roll);
        ++views;
        const Detection d = renderAndDetect(renderer, detector, gt);
        if (!d.ok || d.match.nbMatched != 3) {
          continue;
        }
        ++t3;
        const std::vector<vpSSLPoseHypothesis> hr = ranked.estimate(d.landmarks, d.match, cam);
        const std::vector<vpSSLPoseHypothesis> hp = paper.estimate(d.landmarks, d.match, cam);
        nbHyp += static_cast<int>(hr.size());
        bool in = false;
        for (const vpSSLPoseHypothesis &h : hr) {
          in = in || isTrue(h.cMo, gt);
        }
        tIn += in ? 1 : 0;
        tR += isTrue(hr.front().cMo, gt) ? 1 : 0;
        angles.push_back(angleDeg(hr.front().cMo, gt));
        ranges_.push_back(100. * rangeError(hr.front().cMo, gt));
        tP += isTrue(hp.front().cMo, gt) ? 1 : 0;
      }
      std::printf("%5.1f %4.0f %3d %9d %10d %9d\n", range, tilt, t3, tIn, tR, tP);
      three += t3;
      truthAmong += tIn;
      firstRanked += tR;
      firstPaper += tP;
    }
  }
  std::printf("views %d, 3 landmarks %d, hypotheses/view %.2f, truth among them %d, best is true: ranked %d "
              "(%.1f %%), reprojection only %d (%.1f %%)\n",
              views, three, three ? double(nbHyp) / three : 0., truthAmong, firstRanked,
              three ? 100. * firstRanked / three : 0., firstPaper, three ? 100. * firstPaper / three : 0.);
  auto quantile = [](std::vector<double> v, double q) {
    if (v.empty()) {
      return 0.;
    }
    std::sort(v.begin(), v.end());
    return v[static_cast<size_t>(q * (v.size() - 1))];
  };
  std::printf("best (ranked) hypothesis: rotation error median %.2f deg, 90 %% %.2f deg, max %.2f deg; range error "
              "median %.2f %%, 90 %% %.2f %%, max %.2f %%\n",
              quantile(angles, 0.5), quantile(angles, 0.9), quantile(angles, 1.), quantile(ranges_, 0.5),
              quantile(ranges_, 0.9), quantile(ranges_, 1.));
  ASSERT_GT(three, views / 2);
  EXPECT_GE(firstRanked, firstPaper);
  EXPECT_GE(firstRanked, (9 * truthAmong) / 10);
}

// The ranking on what the detector reads under water, not on exact ellipses: the views are rendered through the
// clear and coastal water models (attenuation, backscatter, forward-scatter blur, sensor noise), each with its own
// noise seed, and detected in small-landmark mode. doc/pose.md states the claim tested: whenever the true pose is
// among the P3P hypotheses the ranking puts it first, and it is never worse than reprojection alone.
TEST(Pose, RankingPicksTheTruePoseOnNoisyUnderwaterDetections)
{
  Scene scene;
  auto &[target, cam, renderer, detector] = scene;
  detector.setSmallLandmarkMode(true);
  vpSSLPoseEstimator ranked(target), paper(target);
  paper.setImageAgreement(false);
  int views = 0, three = 0, truthAmong = 0, firstRanked = 0, firstPaper = 0, missedWithTruthAmong = 0;
  long seed = 1;
  for (const std::string &waterName : {"clear", "coastal"}) {
    const vpSSLWaterModel water = vpSSLWaterModel::preset(waterName);
    for (double range : {1., 1.75, 2.5}) {
      for (double tilt : {10., 30., 50.}) {
        for (int i = 0; i < 2; ++i) {
          const double roll = 180. * i + 7. + 40. * tilt / 50.;
          const double axis = std::fmod(roll * 2.3 + 40., 360.);
          const vpHomogeneousMatrix gt = sslt::lookAt(range, tilt, axis, roll);
          ++views;
          vpImage<float> reflectance, depth;
          vpImage<unsigned char> I;
          renderer.render(gt, reflectance, depth);
          water.apply(reflectance, depth, cam, 0., seed++, I);
          detector.detect(I);
          const vpSSLTargetMatch &match = detector.getTargetMatch();
          if (!match.found || match.nbMatched != 3) {
            continue;
          }
          ++three;
          const std::vector<vpSSLPoseHypothesis> hr = ranked.estimate(detector.getLandmarks(), match, cam);
          const std::vector<vpSSLPoseHypothesis> hp = paper.estimate(detector.getLandmarks(), match, cam);
          bool in = false;
          for (const vpSSLPoseHypothesis &h : hr) {
            in = in || isTrue(h.cMo, gt);
          }
          const bool ok = isTrue(hr.front().cMo, gt);
          truthAmong += in ? 1 : 0;
          firstRanked += ok ? 1 : 0;
          firstPaper += isTrue(hp.front().cMo, gt) ? 1 : 0;
          if (in && !ok) {
            ++missedWithTruthAmong;
            ADD_FAILURE() << waterName << " range " << range << " tilt " << tilt << " roll " << roll
                          << ": the truth is among " << hr.size() << " hypotheses but the best is "
                          << angleDeg(hr.front().cMo, gt) << " deg, " << 100. * rangeError(hr.front().cMo, gt)
                          << " % off";
          }
        }
      }
    }
  }
  std::printf("under water: views %d, 3 landmarks %d, truth among the hypotheses %d, best is true: ranked %d, "
              "reprojection only %d\n",
              views, three, truthAmong, firstRanked, firstPaper);
  ASSERT_GE(three, views / 2) << "the detector lost the target in too many views to test the ranking";
  EXPECT_GE(truthAmong, (9 * three) / 10);
  EXPECT_EQ(missedWithTruthAmong, 0);
  EXPECT_GE(firstRanked, firstPaper);
}

// vpSSLDetector::detect(I, cam, cMo_vec) (its full poses are checked in ThreeLandmarkPoseOnRenderedViews and
// OneLandmarkRangeFromApparentRadius): never a position-only result among the full poses, nothing without a target.
TEST(DetectorPose, TargetSeenByItsBigLandmarkOnlyGivesNoFullPose)
{
  // ssl3-a3 at 3 m through an 800 px camera: the small landmarks (13 px of radius) give w = 40 no peak, so with the
  // short window off only B is read, and the pose is not given.
  Scene scene;
  auto &[target, cam, renderer, detector] = scene;
  detector.setShortWindow(0);
  const vpHomogeneousMatrix gt = sslt::lookAt(3., 10., 0., 0.);
  vpImage<unsigned char> I;
  renderer.render(gt, I);
  std::vector<vpHomogeneousMatrix> cMo_vec;
  std::vector<vpTranslationVector> positions;
  EXPECT_FALSE(detector.detect(I, cam, cMo_vec, nullptr, nullptr, nullptr, &positions));
  ASSERT_TRUE(detector.getTargetMatch().found);
  ASSERT_LT(detector.getTargetMatch().nbMatched, 3u);
  EXPECT_TRUE(cMo_vec.empty());
  ASSERT_EQ(positions.size(), 1u);
  // The position is B's centre.
  const vpSSLTargetLandmark &B = target.getLandmark(static_cast<size_t>(target.findLandmark("B")));
  const vpTranslationVector cB = gt * vpTranslationVector(B.x, B.y, B.z);
  EXPECT_LT((positions[0] - cB).frobeniusNorm(), 0.03 * 3.);
}

TEST(DetectorPose, NoTargetNoPose)
{
  vpImage<unsigned char> I(480, 640, 128);
  vpSSLDetector detector;
  std::vector<vpHomogeneousMatrix> cMo_vec(1);
  std::vector<vpTranslationVector> positions(1);
  EXPECT_FALSE(detector.detect(I, camera(), cMo_vec, nullptr, nullptr, nullptr, &positions));
  EXPECT_TRUE(cMo_vec.empty());
  EXPECT_TRUE(positions.empty());
}

/*
  Decimated matching pass and tracked re-reading: matching on the image decimated twice with a smaller
  window, then reading the rings at full resolution, finds the same landmarks as the full-resolution pass; and in
  tracking mode a landmark re-read around its previous ellipse keeps its full-resolution accuracy.
*/
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <visp3/core/vpMath.h>
#include <visp3/core/vpRect.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>

#include "allocation_counter.h"
#include "ssl_test_utils.h"

namespace {
struct Scene
{
  vpImage<unsigned char> I;
  std::vector<vpImagePoint> centres; // projected landmark centres, target order
};

// ssl3-a3 at distance d, turned by (rx, ry, rz) degrees, through a 56-degree 640x480 camera.
Scene render(double d, double rx, double ry, double rz, double du = 0.)
{
  const vpHomogeneousMatrix cMo(0.02 + du, -0.01, d, vpMath::rad(rx), vpMath::rad(ry), vpMath::rad(rz));
  vpSSLRenderer renderer(vpCameraParameters(600., 600., 319.5, 239.5), 640, 480);
  renderer.setTarget(vpSSLTarget::ssl3a3());
  Scene s;
  renderer.render(cMo, s.I);
  s.centres = renderer.projectLandmarks(cMo);
  return s;
}

const vpSSLLandmark *nearest(const vpSSLDetector &detector, const vpImagePoint &c)
{
  const vpSSLLandmark *best = nullptr;
  for (const vpSSLLandmark &l : detector.getLandmarks()) {
    if (best == nullptr ||
        std::hypot(l.u - c.get_u(), l.v - c.get_v()) < std::hypot(best->u - c.get_u(), best->v - c.get_v())) {
      best = &l;
    }
  }
  return best;
}
} // namespace

TEST(DetectorDecimation, SettingIsCheckedAndDefaultsToFullResolution)
{
  vpSSLDetector detector;
  EXPECT_EQ(detector.getDecimation(), 1u);
  EXPECT_THROW(detector.setDecimation(0), vpException);
  EXPECT_THROW(detector.setDecimation(3), vpException);
  detector.setDecimation(2);
  EXPECT_EQ(detector.getDecimation(), 2u);
}

TEST(DetectorDecimation, SameLandmarksAsTheFullResolutionPass)
{
  // The rings are read at full resolution from the full-resolution maximum near each decimated peak: the
  // landmarks are those of the full-resolution pass, to a small fraction of a pixel.
  const double views[][4] = {{1.0, 10., -8., 5.}, {0.8, 0., 30., 40.}, {1.5, 25., 10., -60.}, {1.6, -20., 0., 120.}};
  for (const auto &view : views) {
    const Scene s = render(view[0], view[1], view[2], view[3]);
    const std::string what = "d=" + std::to_string(view[0]) + " rz=" + std::to_string(view[3]);
    vpSSLDetector full, decimated;
    full.setDecimation(1);
    decimated.setDecimation(2);
    full.setNbThreads(1);
    decimated.setNbThreads(1);
    ASSERT_TRUE(full.detect(s.I)) << what;
    ASSERT_TRUE(decimated.detect(s.I)) << what;
    ASSERT_TRUE(full.getTargetMatch().found) << what;
    ASSERT_TRUE(decimated.getTargetMatch().found) << what;
    EXPECT_EQ(decimated.getLandmarks().size(), full.getLandmarks().size()) << what;
    for (size_t k = 0; k < s.centres.size(); ++k) {
      const vpSSLLandmark *a = full.getMatchedLandmark(k), *b = decimated.getMatchedLandmark(k);
      ASSERT_NE(a, nullptr) << what << " landmark " << k;
      ASSERT_NE(b, nullptr) << what << " landmark " << k;
      EXPECT_LT(std::hypot(a->u - b->u, a->v - b->v), 0.1) << what << " landmark " << k;
      EXPECT_NEAR(b->radius / a->radius, 1., 0.01) << what << " landmark " << k;
      EXPECT_LT(std::hypot(b->u - s.centres[k].get_u(), b->v - s.centres[k].get_v()), 0.5) << what << " landmark " << k;
    }
  }
}

TEST(DetectorDecimation, TrackedReReadingKeepsTheAccuracy)
{
  // A target sliding sideways, regions of interest around the last landmarks, no full search: every frame
  // after the first re-reads the landmarks around their previous ellipses.
  for (unsigned int decimation : {1u, 2u}) {
    vpSSLDetector detector;
    detector.setDecimation(decimation);
    detector.setNbThreads(1);
    for (int frame = 0; frame < 8; ++frame) {
      const Scene s = render(1.0 + 0.02 * frame, 10., -8., 5. + frame, 0.004 * frame);
      ASSERT_TRUE(detector.detect(s.I)) << "frame " << frame;
      EXPECT_EQ(detector.getLastSearchWasFull(), frame == 0) << "frame " << frame;
      ASSERT_TRUE(detector.getTargetMatch().found) << "frame " << frame;
      ASSERT_EQ(detector.getLandmarks().size(), 3u) << "frame " << frame;
      std::vector<vpRect> rois;
      for (size_t k = 0; k < s.centres.size(); ++k) {
        const vpSSLLandmark *l = nearest(detector, s.centres[k]);
        ASSERT_NE(l, nullptr);
        EXPECT_LT(std::hypot(l->u - s.centres[k].get_u(), l->v - s.centres[k].get_v()), 0.5)
            << "frame " << frame << " landmark " << k;
        rois.push_back(vpRect(l->u - 50., l->v - 50., 100., 100.));
      }
      // The same reading from scratch (a fresh detector, whole image) on this frame: radii agree within 2 %.
      vpSSLDetector scratch;
      scratch.setDecimation(decimation);
      scratch.setNbThreads(1);
      ASSERT_TRUE(scratch.detect(s.I));
      for (const vpSSLLandmark &a : scratch.getLandmarks()) {
        const vpSSLLandmark *b = nearest(detector, vpImagePoint(a.v, a.u));
        ASSERT_NE(b, nullptr);
        EXPECT_NEAR(b->radius / a.radius, 1., 0.02) << "frame " << frame;
        EXPECT_LT(std::hypot(a.u - b->u, a.v - b->v), 0.3) << "frame " << frame;
      }
      detector.setRegionsOfInterest(rois);
    }
  }
}

TEST(DetectorDecimation, NoHeapAllocationInSteadyState)
{
  const Scene s = render(1.0, 10., -8., 5.);
  std::vector<vpRect> rois;
  for (const vpImagePoint &c : s.centres) {
    rois.push_back(vpRect(c.get_u() - 50., c.get_v() - 50., 100., 100.));
  }
  for (int mode = 0; mode < 2; ++mode) {
    vpSSLDetector detector;
    detector.setDecimation(2);
    detector.setNbThreads(1);
    // In ROI mode, every third call searches the whole image, as a tracker with a full-search period of 3 asks.
    int call = 0;
    const std::vector<vpRect> none;
    auto nextRegions = [&]() {
      ++call;
      if (mode == 1) {
        detector.setRegionsOfInterest(call % 3 == 0 ? none : rois);
      }
    };
    for (int k = 0; k < 4; ++k) {
      nextRegions();
      ASSERT_TRUE(detector.detect(s.I));
    }
    for (int k = 0; k < 3; ++k) {
      nextRegions();
      long n = 0;
      {
        const sslt::AllocationCounter counter;
        detector.detect(s.I);
        n = counter.count();
      }
      EXPECT_EQ(detector.getLandmarks().size(), 3u) << "mode " << mode;
      EXPECT_EQ(n, 0) << "mode " << mode << ", call " << k;
    }
  }
}

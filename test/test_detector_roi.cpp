/*
  Tracking mode of the detector (paper Sec. 4.1): matching only in regions of interest around the
  predicted landmarks gives the same landmarks as the full frame, the whole image is searched exactly when no
  region is given (vpSSLTracker decides which frames), a copy tracks as the original, and detect() itself
  allocates nothing on the heap once its buffers have grown (only the target identifier's result, counted
  separately, does).
*/

#include <cstdlib>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <visp3/core/vpMath.h>
#include <visp3/core/vpRect.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl/vpSSLTargetIdentifier.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>

#include "allocation_counter.h"
#include "vpSSLDetectorTestAccess.h"

namespace {
// ssl3-a3 1 m away, turned by a few degrees (the view of bench-detector), through a 56-degree 640x480 camera.
struct View
{
  vpImage<unsigned char> I;
  std::vector<vpImagePoint> centres; // projected landmark centres, target order
};

const View &view()
{
  static View v;
  if (v.I.getSize() == 0) {
    const vpHomogeneousMatrix cMo(0.02, -0.01, 1.0, vpMath::rad(10.), vpMath::rad(-8.), vpMath::rad(5.));
    vpSSLRenderer renderer(vpCameraParameters(600., 600., 319.5, 239.5), 640, 480);
    renderer.setTarget(vpSSLTarget::ssl3a3());
    renderer.render(cMo, v.I);
    v.centres = renderer.projectLandmarks(cMo);
  }
  return v;
}

vpRect roiAround(const vpImagePoint &c)
{
  return vpRect(c.get_u() - 50., c.get_v() - 50., 100., 100.);
}

bool inside(const vpSSLLandmark &l, const std::vector<vpRect> &rois)
{
  for (const vpRect &r : rois) {
    if (r.isInside(vpImagePoint(l.v, l.u))) {
      return true;
    }
  }
  return false;
}

// Number of landmarks of \e detector within 2 px of a projected centre.
unsigned int nbFound(const vpSSLDetector &detector, const std::vector<vpImagePoint> &centres)
{
  unsigned int n = 0;
  for (const vpImagePoint &c : centres) {
    for (const vpSSLLandmark &l : detector.getLandmarks()) {
      if (std::hypot(l.u - c.get_u(), l.v - c.get_v()) < 2.) {
        ++n;
        break;
      }
    }
  }
  return n;
}
} // namespace

TEST(DetectorRoi, RoisGiveTheFullFrameLandmarksInsideThem)
{
  const View &v = view();
  ASSERT_EQ(v.centres.size(), 3u);
  vpSSLDetector full;
  full.setNbThreads(1);
  ASSERT_TRUE(full.detect(v.I));
  ASSERT_EQ(nbFound(full, v.centres), 3u);

  std::vector<vpRect> rois;
  for (const vpImagePoint &c : v.centres) {
    rois.push_back(roiAround(c));
  }
  vpSSLDetector tracked;
  tracked.setNbThreads(1);
  tracked.setRegionsOfInterest(rois);
  ASSERT_TRUE(tracked.detect(v.I));
  EXPECT_FALSE(tracked.getLastSearchWasFull());
  EXPECT_TRUE(tracked.getTargetMatch().found);

  // The same landmarks, field by field: the rings are read on the same image from the same peaks.
  unsigned int compared = 0;
  for (const vpSSLLandmark &a : full.getLandmarks()) {
    if (!inside(a, rois)) {
      continue;
    }
    const vpSSLLandmark *match = nullptr;
    for (const vpSSLLandmark &b : tracked.getLandmarks()) {
      if (std::hypot(a.u - b.u, a.v - b.v) < 1.) {
        match = &b;
      }
    }
    ASSERT_NE(match, nullptr) << "landmark at " << a.u << ", " << a.v << " lost in ROI mode";
    EXPECT_DOUBLE_EQ(match->u, a.u);
    EXPECT_DOUBLE_EQ(match->v, a.v);
    EXPECT_DOUBLE_EQ(match->radius, a.radius);
    EXPECT_DOUBLE_EQ(match->minorRadius, a.minorRadius);
    EXPECT_DOUBLE_EQ(match->theta, a.theta);
    EXPECT_DOUBLE_EQ(match->score, a.score);
    EXPECT_EQ(match->nbDirections, a.nbDirections);
    ++compared;
  }
  EXPECT_EQ(compared, 3u);
  EXPECT_EQ(tracked.getLandmarks().size(), compared);
  for (size_t k = 0; k < 3; ++k) {
    ASSERT_NE(tracked.getMatchedLandmark(k), nullptr);
    ASSERT_NE(full.getMatchedLandmark(k), nullptr);
    EXPECT_DOUBLE_EQ(tracked.getMatchedLandmark(k)->u, full.getMatchedLandmark(k)->u);
  }
}

TEST(DetectorRoi, SearchesTheWholeImageOnlyWithoutRegions)
{
  const View &v = view();
  vpSSLDetector detector;
  detector.setNbThreads(1);
  ASSERT_TRUE(detector.detect(v.I));
  EXPECT_TRUE(detector.getLastSearchWasFull()); // no regions: always the whole image
  EXPECT_EQ(nbFound(detector, v.centres), 3u);

  // One region, around the first landmark only: the two others are outside it, at every call (the tracker, not the
  // detector, decides which frames search the whole image).
  detector.setRegionsOfInterest({roiAround(v.centres[0])});
  for (int call = 0; call < 12; ++call) {
    ASSERT_TRUE(detector.detect(v.I)) << "call " << call;
    EXPECT_FALSE(detector.getLastSearchWasFull()) << "call " << call;
    EXPECT_EQ(nbFound(detector, v.centres), 1u) << "call " << call;
    EXPECT_EQ(detector.getLandmarks().size(), 1u) << "call " << call;
  }
  detector.setRegionsOfInterest({});
  detector.detect(v.I);
  EXPECT_TRUE(detector.getLastSearchWasFull());
  EXPECT_EQ(nbFound(detector, v.centres), 3u);
}

TEST(DetectorRoi, CopyKeepsTheSettingsAndTheTrackingState)
{
  const View &v = view();
  std::vector<vpRect> rois;
  for (const vpImagePoint &c : v.centres) {
    rois.push_back(roiAround(c));
  }
  vpSSLDetector original;
  original.setNbThreads(1);
  original.setThreshold(0.2);
  ASSERT_TRUE(original.detect(v.I));
  original.setRegionsOfInterest(rois);
  vpSSLDetector copy(original);
  vpSSLDetector assigned;
  assigned = original;
  for (const vpSSLDetector *d : {&copy, &assigned}) {
    EXPECT_EQ(d->getThreshold(), 0.2);
    EXPECT_EQ(d->getLandmarks().size(), original.getLandmarks().size());
    EXPECT_EQ(d->getNbObjects(), original.getNbObjects());
  }
  // The copies re-read the original's previous landmarks from the regions, as the original does; a copy detects on
  // its own (the original's next results do not change it).
  ASSERT_TRUE(original.detect(v.I));
  ASSERT_TRUE(copy.detect(v.I));
  ASSERT_TRUE(assigned.detect(v.I));
  EXPECT_TRUE(vpSSLDetectorTestAccess::getMatchedRegions(copy).empty()) << "a landmark was not re-read";
  for (const vpSSLDetector *d : {&copy, &assigned}) {
    EXPECT_FALSE(d->getLastSearchWasFull());
    ASSERT_EQ(d->getLandmarks().size(), original.getLandmarks().size());
    for (size_t k = 0; k < original.getLandmarks().size(); ++k) {
      EXPECT_EQ(d->getLandmarks()[k].u, original.getLandmarks()[k].u);
      EXPECT_EQ(d->getLandmarks()[k].radius, original.getLandmarks()[k].radius);
    }
  }
  original.setRegionsOfInterest({});
  original.setThreshold(0.5);
  EXPECT_EQ(copy.getThreshold(), 0.2);
  vpSSLDetector moved(std::move(copy));
  EXPECT_FALSE(moved.getLastSearchWasFull());
  EXPECT_EQ(moved.getLandmarks().size(), original.getLandmarks().size());
}

TEST(DetectorRoi, NoHeapAllocationInSteadyState)
{
  const View &v = view();
  // Regions centred on the landmarks (re-read from there) and 20 px off them (matched, on the decimated image for
  // the large ones).
  std::vector<vpRect> rois, offRois;
  for (const vpImagePoint &c : v.centres) {
    rois.push_back(roiAround(c));
    offRois.push_back(roiAround(vpImagePoint(c.get_i(), c.get_j() + 20.)));
  }
  const vpSSLTargetIdentifier identifier(vpSSLTarget::ssl3a3());
  for (int mode = 0; mode < 4; ++mode) {
    vpSSLDetector detector;
    detector.setNbThreads(1);
    detector.setSmallLandmarkMode(mode == 2);
    // In ROI mode, every third call searches the whole image, as a tracker with a full-search period of 3 asks.
    int call = 0;
    const std::vector<vpRect> none;
    auto nextRegions = [&]() {
      ++call;
      if (mode == 1 || mode == 3) {
        detector.setRegionsOfInterest(call % 3 == 0 ? none : (mode == 1 ? rois : offRois));
      }
    };
    // Buffers grow during the first calls (a full-search frame included in ROI mode).
    for (int k = 0; k < 4; ++k) {
      nextRegions();
      ASSERT_TRUE(detector.detect(v.I));
    }
    for (int k = 0; k < 3; ++k) {
      nextRegions();
      long detectNew = 0;
      {
        const sslt::AllocationCounter counter;
        detector.detect(v.I);
        detectNew = counter.count();
      }
      ASSERT_EQ(nbFound(detector, v.centres), 3u) << "mode " << mode;
      EXPECT_EQ(detectNew, 0) << "mode " << mode << ", call " << k;
      if (mode == 3 && !detector.getLastSearchWasFull()) {
        EXPECT_LT(vpSSLDetectorTestAccess::getMapRegions(detector).size(),
                  vpSSLDetectorTestAccess::getMatchedRegions(detector).size())
            << "no decimated region";
      }
    }
  }
}

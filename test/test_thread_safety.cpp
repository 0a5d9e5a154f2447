// The library's thread rule (README, API reference): const methods are safe to call from several threads on one
// object. Two threads call the const methods of one vpSSLTargetIdentifier and one vpSSLMatchingFunction on
// different inputs, over and over; every result must equal the one a single thread gets. scripts/tsan.sh runs
// this test under ThreadSanitizer, which also reports a race that happens to leave the results right.
#include <atomic>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl/vpSSLMatchingFunction.h>
#include <visp3/ssl/vpSSLTargetIdentifier.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>

#include "ssl_test_utils.h"

namespace {
const vpCameraParameters kCam(800., 800., 319.6, 240.3);
const int kRounds = 40;

// Views whose detections differ in number and layout, so that the identifier's buffers change size between
// calls, as do the matching maps' regions.
std::vector<vpImage<unsigned char>> renderViews()
{
  vpSSLRenderer renderer(kCam, 640, 480);
  renderer.setTarget(vpSSLTarget::ssl3a3());
  renderer.setReflectances(0., 1., 0.35);
  std::vector<vpImage<unsigned char>> views;
  for (const vpHomogeneousMatrix &cMo :
       {sslt::lookAt(0.9, 0., 0., 0.), sslt::lookAt(1.2, 35., 20., 160.), sslt::lookAt(1.5, 20., 70., 250.)}) {
    vpImage<unsigned char> I;
    renderer.render(cMo, I);
    views.push_back(I);
  }
  vpImage<unsigned char> mirrored = views[1];
  sslt::mirrorHorizontal(mirrored);
  views.push_back(mirrored);
  return views;
}

// Runs job(i) for every input i in two threads at once, each starting at a different input, kRounds times.
void runInTwoThreads(size_t nbInputs, const std::function<void(size_t)> &job)
{
  auto worker = [&](size_t first) {
    for (int r = 0; r < kRounds; ++r) {
      for (size_t k = 0; k < nbInputs; ++k) {
        job((first + k) % nbInputs);
      }
    }
  };
  std::thread a(worker, 0), b(worker, nbInputs / 2);
  a.join();
  b.join();
}

bool sameMatch(const vpSSLTargetMatch &a, const vpSSLTargetMatch &b)
{
  return a.found == b.found && a.nbMatched == b.nbMatched && a.detection == b.detection && a.residual == b.residual;
}
} // namespace

TEST(ThreadSafety, TargetIdentifierIdentifyFromTwoThreads)
{
  const std::vector<vpImage<unsigned char>> views = renderViews();
  std::vector<std::vector<vpSSLLandmark>> inputs;
  vpSSLDetector detector;
  for (const vpImage<unsigned char> &I : views) {
    detector.detect(I);
    inputs.push_back(detector.getLandmarks());
    // Fewer detections: the identifier's buffers shrink and grow from one call to the next.
    inputs.push_back(
        std::vector<vpSSLLandmark>(inputs.back().begin(), inputs.back().begin() + inputs.back().size() / 2));
  }
  const vpSSLTargetIdentifier identifier(vpSSLTarget::ssl3a3());
  std::vector<vpSSLTargetMatch> expected;
  for (const std::vector<vpSSLLandmark> &l : inputs) {
    expected.push_back(identifier.identify(l));
  }
  ASSERT_TRUE(expected[0].found);
  ASSERT_EQ(expected[0].nbMatched, 3u);

  std::atomic<int> mismatches(0);
  runInTwoThreads(inputs.size(), [&](size_t i) {
    const vpSSLTargetMatch m = identifier.identify(inputs[i]);
    if (!sameMatch(m, expected[i])) {
      ++mismatches;
    }
  });
  EXPECT_EQ(mismatches.load(), 0);
}

TEST(ThreadSafety, MatchingFunctionComputeFromTwoThreads)
{
  const std::vector<vpImage<unsigned char>> views = renderViews();
  vpSSLMatchingFunction match(40, 0.5);
  match.setNbThreads(1); // the two threads are the test's own
  std::vector<vpImage<int>> expected(views.size());
  for (size_t i = 0; i < views.size(); ++i) {
    match.compute(views[i], expected[i]);
  }
  const std::vector<vpRect> rois = {vpRect(100, 80, 200, 150), vpRect(350, 200, 180, 200)};
  std::vector<vpImage<int>> expectedRois(views.size());
  for (size_t i = 0; i < views.size(); ++i) {
    match.compute(views[i], rois, expectedRois[i]);
  }

  std::atomic<int> mismatches(0);
  runInTwoThreads(views.size(), [&](size_t i) {
    vpImage<int> M, Mr;
    match.compute(views[i], M);
    match.compute(views[i], rois, Mr);
    if (!(M == expected[i]) || !(Mr == expectedRois[i])) {
      ++mismatches;
    }
  });
  EXPECT_EQ(mismatches.load(), 0);
}

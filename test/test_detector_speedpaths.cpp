/*
  The fast paths of vpSSLDetector give the readings of the plain ones:
  - the symmetry centring's SIMD kernel (vpSSLSymmetryKernel: every centre of the search in one pass) gives the
    same landmarks, bit for bit, on every SIMD target compiled in, for the full-resolution, decimated and
    small-landmark modes, full frames and tracking frames;
  - a tracking frame without decimation normalises only the pixels its regions read (and the Eq. 7 sweep its
    row): the landmarks, radiusEq7 included, are those of the whole-image normalisation;
  - the normalisation table is applied in SIMD (byte shuffles): the default matching map is the reference map of
    the image through the normaliser's table (from a histogram of one pixel in 16), on every SIMD target, inside
    the candidate regions where a full search computes it (0 elsewhere);
  - those candidate regions (around the maxima of w / 2 on the half image) hold every landmark centre where the
    whole image's map is over the threshold;
  - the small-landmark mode's twice upsampling (SIMD) gives the plain bilinear image: its matching map is the
    reference map of that image, normalised, on every SIMD target;
  - a tracking frame re-reads each predicted landmark from its region's centre without matching, and matches the
    regions whose landmark moved too far for that;
  - a tracked landmark with decimation is re-read from the decimated peak (no climb to the full-resolution
    maximum): its score is the full-resolution map at its centre, close to the full search's.
*/

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <visp3/core/vpMath.h>
#include <visp3/core/vpRect.h>
#include <visp3/core/vpUniRand.h>
#include <visp3/ssl/vpSSLBrightnessNormalizer.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>

#include "vpSSLDetectorTestAccess.h"

namespace {
struct View
{
  vpImage<unsigned char> I;
  std::vector<vpImagePoint> centres; // projected landmark centres, target order
};

// ssl3-a3 at `distance` m, turned by a few degrees, through a 56-degree 640x480 camera; moved by `shift` px along u.
View render(double distance, double shift = 0.)
{
  View v;
  const vpHomogeneousMatrix cMo(0.02 + shift * distance / 600., -0.01, distance, vpMath::rad(10.), vpMath::rad(-8.),
                                vpMath::rad(5.));
  vpSSLRenderer renderer(vpCameraParameters(600., 600., 319.5, 239.5), 640, 480);
  renderer.setTarget(vpSSLTarget::ssl3a3());
  renderer.render(cMo, v.I);
  v.centres = renderer.projectLandmarks(cMo);
  return v;
}

std::vector<vpRect> roisAround(const std::vector<vpImagePoint> &centres)
{
  std::vector<vpRect> rois;
  for (const vpImagePoint &c : centres) {
    rois.push_back(vpRect(c.get_u() - 50., c.get_v() - 50., 100., 100.));
  }
  return rois;
}

// Every field of every landmark of a run of frames.
std::vector<vpSSLLandmark> run(vpSSLDetector &detector, const vpImage<unsigned char> &I, int frames)
{
  std::vector<vpSSLLandmark> all;
  // The fast paths must give the sweep of the plain ones too.
  detector.setRadiusSweep(true);
  for (int k = 0; k < frames; ++k) {
    detector.detect(I);
    all.insert(all.end(), detector.getLandmarks().begin(), detector.getLandmarks().end());
  }
  return all;
}

void expectSame(const vpSSLLandmark &a, const vpSSLLandmark &b, const char *what)
{
  EXPECT_EQ(a.u, b.u) << what;
  EXPECT_EQ(a.v, b.v) << what;
  EXPECT_EQ(a.radius, b.radius) << what;
  EXPECT_EQ(a.minorRadius, b.minorRadius) << what;
  EXPECT_EQ(a.theta, b.theta) << what;
  EXPECT_EQ(a.score, b.score) << what;
  EXPECT_EQ(a.radiusEq7, b.radiusEq7) << what;
  EXPECT_EQ(a.nbDirections, b.nbDirections) << what;
  for (int d = 0; d < 8; ++d) {
    EXPECT_EQ(a.directionalRadius[d], b.directionalRadius[d]) << what << ", direction " << d;
  }
}

// Modes: 0 full resolution, 1 decimation 2, 2 small-landmark mode (symmetry disc of radius 16 on the upsampled
// image), each on full frames then on tracking frames (regions around the landmarks, no full search).
std::vector<vpSSLLandmark> allModes(const View &near, const View &far)
{
  std::vector<vpSSLLandmark> all;
  for (int mode = 0; mode < 3; ++mode) {
    const View &v = mode == 2 ? far : near;
    vpSSLDetector detector;
    detector.setNbThreads(1);
    detector.setDecimation(mode == 1 ? 2 : 1);
    detector.setSmallLandmarkMode(mode == 2);
    std::vector<vpSSLLandmark> l = run(detector, v.I, 1);
    all.insert(all.end(), l.begin(), l.end());
    detector.setRegionsOfInterest(roisAround(v.centres));
    l = run(detector, v.I, 2);
    all.insert(all.end(), l.begin(), l.end());
  }
  return all;
}
// Pixels of an image of width W and height H inside the rectangles (vpRect: right = left + width - 1).
std::vector<char> insideMask(const std::vector<vpRect> &rects, unsigned int W, unsigned int H)
{
  std::vector<char> inside(static_cast<size_t>(W) * H, 0);
  for (const vpRect &r : rects) {
    for (unsigned int v = 0; v < H; ++v) {
      for (unsigned int u = 0; u < W; ++u) {
        if (u >= r.getLeft() && u <= r.getRight() && v >= r.getTop() && v <= r.getBottom()) {
          inside[static_cast<size_t>(v) * W + u] = 1;
        }
      }
    }
  }
  return inside;
}

// The default detector's matching map of I (full frame, one thread) is ref on every SIMD target compiled in: the
// whole map in the small-landmark mode; otherwise ref inside the candidate regions of the half image, which must
// cover at least minCovered of the image, and 0 outside them.
void expectMapOnEveryTarget(const vpImage<unsigned char> &I, bool smallLandmarkMode, const vpImage<int> &ref,
                            double minCovered = 1.)
{
  for (int64_t t : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(t);
    vpSSLDetector detector;
    detector.setNbThreads(1);
    detector.setSmallLandmarkMode(smallLandmarkMode);
    detector.detect(I);
    const vpImage<int> &M = detector.getMatchingMap();
    ASSERT_EQ(M.getSize(), ref.getSize());
    const std::vector<vpRect> &regions = vpSSLDetectorTestAccess::getCandidateRegions(detector);
    const std::vector<char> inside =
        smallLandmarkMode ? std::vector<char>(M.getSize(), 1) : insideMask(regions, M.getWidth(), M.getHeight());
    size_t different = 0, covered = 0;
    for (unsigned int i = 0; i < M.getSize(); ++i) {
      covered += inside[i] ? 1 : 0;
      different += M.bitmap[i] != (inside[i] ? ref.bitmap[i] : 0) ? 1 : 0;
    }
    const std::string what = std::string(hwy::TargetName(t)) + ", " + std::to_string(I.getWidth()) + "x" +
                             std::to_string(I.getHeight()) + (smallLandmarkMode ? ", small-landmark mode" : "");
    EXPECT_EQ(different, 0u) << what;
    EXPECT_GE(static_cast<double>(covered), minCovered * M.getSize()) << what;
    std::printf("%s: map computed on %.1f %% of the image\n", what.c_str(), 100. * covered / M.getSize());
  }
  hwy::SetSupportedTargetsForTest(0);
}
} // namespace

TEST(DetectorSpeedPaths, EverySimdTargetGivesTheSameLandmarks)
{
  const View near = render(1.0), far = render(3.0);
  const std::vector<vpSSLLandmark> best = allModes(near, far);
  ASSERT_GE(best.size(), 3u * 3u);
  const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
  ASSERT_FALSE(targets.empty());
  for (int64_t t : targets) {
    hwy::SetSupportedTargetsForTest(t);
    const std::vector<vpSSLLandmark> l = allModes(near, far);
    ASSERT_EQ(l.size(), best.size()) << hwy::TargetName(t);
    for (size_t k = 0; k < l.size(); ++k) {
      expectSame(l[k], best[k], hwy::TargetName(t));
    }
  }
  hwy::SetSupportedTargetsForTest(0);
}

TEST(DetectorSpeedPaths, NormalisedMapIsTheReferenceOnEverySimdTarget)
{
  // Every grey level, odd widths (vector tails), and a table that is not the identity: uniform noise over a
  // narrow band, so that the 1 % and 99 % percentiles stretch it.
  vpUniRand rng(7);
  const unsigned int sizes[][2] = {{640, 480}, {161, 97}, {3, 200}};
  for (const auto &sz : sizes) {
    vpImage<unsigned char> I(sz[1], sz[0]);
    for (unsigned int i = 0; i < I.getSize(); ++i) {
      I.bitmap[i] = static_cast<unsigned char>(i % 7 == 0 ? rng.uniform(0, 256) : rng.uniform(60, 190));
    }
    unsigned char lut[256];
    vpSSLBrightnessNormalizer().computeLut(I, lut, 4);
    bool stretched = false;
    for (int g = 0; g < 256; ++g) {
      stretched = stretched || lut[g] != g;
    }
    ASSERT_TRUE(stretched);
    vpImage<unsigned char> N(I.getHeight(), I.getWidth());
    for (unsigned int i = 0; i < I.getSize(); ++i) {
      N.bitmap[i] = lut[I.bitmap[i]];
    }
    vpImage<int> ref;
    vpSSLMatchingFunction(40, 0.5).computeReference(N, ref);
    // Noise has candidates nearly everywhere: all the map is compared but for most of the 3 px wide image.
    expectMapOnEveryTarget(I, false, ref, sz[0] == 3 ? 0.2 : 0.95);
  }
}

TEST(DetectorSpeedPaths, CandidateRegionsHoldEveryLandmarkPeakOfTheFullMap)
{
  // Where the whole image's map (w = 40, normalised) is over the threshold within 2 px of a landmark's projected
  // centre, that centre lies in a candidate region: computing w only there loses no landmark of these views.
  int checked = 0;
  for (double distance : {0.8, 1.5, 2.5, 4.}) {
    for (double shift : {0., 0.5}) {
      const View view = render(distance, shift);
      vpSSLDetector detector;
      detector.setNbThreads(1);
      detector.detect(view.I);
      const std::vector<vpRect> &regions = vpSSLDetectorTestAccess::getCandidateRegions(detector);
      unsigned char lut[256];
      vpSSLBrightnessNormalizer().computeLut(view.I, lut, 4);
      vpImage<unsigned char> N(view.I.getHeight(), view.I.getWidth());
      for (unsigned int i = 0; i < view.I.getSize(); ++i) {
        N.bitmap[i] = lut[view.I.bitmap[i]];
      }
      vpImage<int> ref;
      detector.getMatchingFunction().computeReference(N, ref);
      const double threshold = detector.getThreshold() * detector.getMatchingFunction().getMaxValue();
      const std::vector<char> inside = insideMask(regions, N.getWidth(), N.getHeight());
      for (const vpImagePoint &c : view.centres) {
        const int cu = static_cast<int>(std::lround(c.get_u())), cv = static_cast<int>(std::lround(c.get_v()));
        int best = 0;
        for (int v = std::max(0, cv - 2); v <= std::min(static_cast<int>(N.getHeight()) - 1, cv + 2); ++v) {
          for (int u = std::max(0, cu - 2); u <= std::min(static_cast<int>(N.getWidth()) - 1, cu + 2); ++u) {
            best = std::max(best, ref[v][u]);
          }
        }
        if (best < threshold || cu < 0 || cv < 0 || cu >= static_cast<int>(N.getWidth()) ||
            cv >= static_cast<int>(N.getHeight())) {
          continue;
        }
        ++checked;
        EXPECT_TRUE(inside[static_cast<size_t>(cv) * N.getWidth() + cu])
            << "landmark at (" << c.get_u() << ", " << c.get_v() << "), " << distance << " m, shift " << shift;
      }
    }
  }
  std::printf("%d landmark peaks checked\n", checked);
  EXPECT_GE(checked, 20);
}

TEST(DetectorSpeedPaths, UpsampledMapIsTheReferenceOnEverySimdTarget)
{
  // The plain loop the SIMD rows replace: output (u, v) samples input ((u + 0.5) / 2 - 0.5, ...), edges repeated.
  auto upsample = [](const vpImage<unsigned char> &I) {
    const int W = static_cast<int>(I.getWidth()), H = static_cast<int>(I.getHeight());
    vpImage<unsigned char> O(static_cast<unsigned int>(2 * H), static_cast<unsigned int>(2 * W));
    for (int v = 0; v < 2 * H; ++v) {
      const int v0 = std::max(0, (v - 1) >> 1), v1 = std::min(H - 1, ((v - 1) >> 1) + 1), wv = (v & 1) ? 3 : 1;
      for (int u = 0; u < 2 * W; ++u) {
        const int u0 = std::max(0, (u - 1) >> 1), u1 = std::min(W - 1, ((u - 1) >> 1) + 1), wu = (u & 1) ? 3 : 1;
        const int t = wu * I[v0][u0] + (4 - wu) * I[v0][u1], b = wu * I[v1][u0] + (4 - wu) * I[v1][u1];
        O[v][u] = static_cast<unsigned char>((wv * t + (4 - wv) * b + 8) >> 4);
      }
    }
    return O;
  };
  vpUniRand rng(11);
  const unsigned int sizes[][2] = {{161, 97}, {1, 30}, {2, 25}, {67, 1}};
  for (const auto &sz : sizes) {
    vpImage<unsigned char> I(sz[1], sz[0]);
    for (unsigned int i = 0; i < I.getSize(); ++i) {
      I.bitmap[i] = static_cast<unsigned char>(rng.uniform(0, 256));
    }
    const vpImage<unsigned char> U = upsample(I);
    unsigned char lut[256];
    vpSSLBrightnessNormalizer().computeLut(U, lut, 4);
    vpImage<unsigned char> N(U.getHeight(), U.getWidth());
    for (unsigned int i = 0; i < U.getSize(); ++i) {
      N.bitmap[i] = lut[U.bitmap[i]];
    }
    vpSSLDetector probe;
    probe.setSmallLandmarkMode(true);
    vpImage<int> ref;
    vpSSLMatchingFunction(probe.getMatchingFunction().getWindow(), 0.5).computeReference(N, ref);
    expectMapOnEveryTarget(I, true, ref);
  }
}

TEST(DetectorSpeedPaths, RoiNormalisationGivesTheWholeImageReading)
{
  for (int mode = 0; mode < 2; ++mode) {
    const View v = render(mode == 0 ? 1.0 : 3.0);
    vpSSLDetector full;
    full.setNbThreads(1);
    full.setSmallLandmarkMode(mode == 1);
    ASSERT_TRUE(full.detect(v.I));
    vpSSLDetector tracked;
    tracked.setNbThreads(1);
    tracked.setSmallLandmarkMode(mode == 1);
    tracked.setRegionsOfInterest(roisAround(v.centres));
    // The first tracking frame has no previous landmark: every landmark is read from scratch, as in the full
    // search, but on an image of which only the regions (grown by the window) are normalised.
    ASSERT_TRUE(tracked.detect(v.I));
    EXPECT_FALSE(tracked.getLastSearchWasFull());
    ASSERT_EQ(tracked.getLandmarks().size(), 3u) << "mode " << mode;
    for (const vpSSLLandmark &b : tracked.getLandmarks()) {
      const vpSSLLandmark *a = nullptr;
      for (const vpSSLLandmark &l : full.getLandmarks()) {
        if (std::hypot(l.u - b.u, l.v - b.v) < 1.) {
          a = &l;
        }
      }
      ASSERT_NE(a, nullptr) << "mode " << mode << ": landmark at " << b.u << ", " << b.v << " not in the full search";
      expectSame(b, *a, mode == 0 ? "full resolution" : "small-landmark mode");
    }
  }
}

TEST(DetectorSpeedPaths, TrackedDecimatedScoreIsTheMapAtTheCentre)
{
  const View v = render(1.0);
  vpSSLDetector full;
  full.setNbThreads(1);
  full.setDecimation(2);
  ASSERT_TRUE(full.detect(v.I));
  vpSSLDetector tracked;
  tracked.setNbThreads(1);
  tracked.setDecimation(2);
  tracked.setRegionsOfInterest(roisAround(v.centres));
  ASSERT_TRUE(tracked.detect(v.I)); // read from scratch
  ASSERT_TRUE(tracked.detect(v.I)); // re-read around the previous ellipses
  ASSERT_EQ(tracked.getLandmarks().size(), 3u);
  for (const vpSSLLandmark &b : tracked.getLandmarks()) {
    const vpSSLLandmark *a = nullptr;
    for (const vpSSLLandmark &l : full.getLandmarks()) {
      if (std::hypot(l.u - b.u, l.v - b.v) < 1.) {
        a = &l;
      }
    }
    ASSERT_NE(a, nullptr);
    EXPECT_NEAR(b.u, a->u, 0.05);
    EXPECT_NEAR(b.v, a->v, 0.05);
    EXPECT_NEAR(b.radius / a->radius, 1., 0.01);
    // The full search's score is the climbed maximum of the map near the centre, the tracked one the map at the
    // centre: a little lower at most, and over the detection threshold.
    EXPECT_GE(b.score, full.getThreshold());
    EXPECT_LE(b.score, 1.);
    EXPECT_NEAR(b.score, a->score, 0.1);
  }
}

TEST(DetectorSpeedPaths, MatchingMapIsZeroOutsideTheRegionsFromFrameToFrame)
{
  // Tracking frames clear only the regions the previous one wrote: after regions that move, a full search and
  // regions again, the map is the one a fresh detector computes with the same regions (zero elsewhere).
  const View v = render(1.0);
  const std::vector<vpRect> a = roisAround(v.centres);
  std::vector<vpRect> b;
  for (const vpRect &r : a) {
    b.push_back(vpRect(r.getLeft() + 37., r.getTop() - 23., 80., 120.));
  }
  b.push_back(vpRect(-30., 400., 100., 200.)); // partly outside the image
  for (unsigned int decimation : {1u, 2u}) {
    vpSSLDetector detector;
    detector.setNbThreads(1);
    detector.setDecimation(decimation);
    // The 4th call searches the whole image, as a tracker with a full-search period of 4 asks.
    const std::vector<vpRect> none;
    const std::vector<vpRect> *sequence[] = {&a, &b, &a, &none, &b, &a};
    for (size_t k = 0; k < 6; ++k) {
      detector.setRegionsOfInterest(*sequence[k]);
      detector.detect(v.I);
      EXPECT_EQ(detector.getLastSearchWasFull(), k == 3);
      vpSSLDetector fresh;
      fresh.setNbThreads(1);
      fresh.setDecimation(decimation);
      // The regions whose landmark was re-read from their centre are not matched, nor those of a large landmark
      // matched on the decimated image (getMapRegions()): a fresh detector, which has no previous landmark, matches
      // all of its regions at its own resolution.
      const std::vector<vpRect> matched = vpSSLDetectorTestAccess::getMapRegions(detector);
      if (k != 3) {
        fresh.setRegionsOfInterest(matched);
      }
      if (k == 3 || !matched.empty()) {
        fresh.detect(v.I);
      }
      const vpImage<int> &M = detector.getMatchingMap(), &F = fresh.getMatchingMap();
      size_t different = 0;
      if (k == 3 || !matched.empty()) {
        ASSERT_EQ(M.getSize(), F.getSize());
        for (unsigned int i = 0; i < M.getSize(); ++i) {
          different += M.bitmap[i] != F.bitmap[i] ? 1 : 0;
        }
      } else {
        for (unsigned int i = 0; i < M.getSize(); ++i) {
          different += M.bitmap[i] != 0 ? 1 : 0;
        }
      }
      EXPECT_EQ(different, 0u) << "decimation " << decimation << ", call " << k;
    }
  }
}

TEST(DetectorSpeedPaths, PredictedLandmarksAreReReadWithoutMatching)
{
  const View v = render(1.0);
  for (unsigned int decimation : {1u, 2u}) {
    vpSSLDetector detector;
    detector.setNbThreads(1);
    detector.setDecimation(decimation);
    ASSERT_TRUE(detector.detect(v.I));
    const std::vector<vpSSLLandmark> full = detector.getLandmarks();
    ASSERT_EQ(full.size(), 3u);
    detector.setRegionsOfInterest(roisAround(v.centres));
    detector.detect(v.I);
    EXPECT_TRUE(vpSSLDetectorTestAccess::getMatchedRegions(detector).empty()) << "decimation " << decimation;
    const vpImage<int> &M = detector.getMatchingMap();
    size_t nonZero = 0;
    for (unsigned int i = 0; i < M.getSize(); ++i) {
      nonZero += M.bitmap[i] != 0 ? 1 : 0;
    }
    EXPECT_EQ(nonZero, 0u) << "nothing is matched when every landmark is re-read";
    ASSERT_EQ(detector.getLandmarks().size(), full.size());
    for (const vpSSLLandmark &l : full) {
      bool same = false;
      for (const vpSSLLandmark &k : detector.getLandmarks()) {
        same = same || (std::hypot(k.u - l.u, k.v - l.v) < 0.01 && std::fabs(k.radius - l.radius) < 0.01 &&
                        std::fabs(k.minorRadius - l.minorRadius) < 0.01 && std::fabs(k.score - l.score) < 0.05);
      }
      EXPECT_TRUE(same) << "landmark at " << l.u << ", " << l.v << " not re-read as the full search read it";
    }
    EXPECT_TRUE(detector.getTargetMatch().found);
  }
}

TEST(DetectorSpeedPaths, LandmarksThatMovedFarFromThePredictionAreMatched)
{
  // The regions stay on the previous frame's landmarks while the target moves by 14 px: the re-reading from the
  // regions' centres cannot reach them (+-3 px per symmetry step, and the rays must stay near the start), so the
  // regions are matched and the landmarks found at their new places.
  const View before = render(1.0), after = render(1.0, 14.);
  for (unsigned int decimation : {1u, 2u}) {
    vpSSLDetector detector;
    detector.setNbThreads(1);
    detector.setDecimation(decimation);
    ASSERT_TRUE(detector.detect(before.I));
    detector.setRegionsOfInterest(roisAround(before.centres));
    detector.detect(after.I);
    EXPECT_FALSE(vpSSLDetectorTestAccess::getMatchedRegions(detector).empty()) << "decimation " << decimation;
    ASSERT_TRUE(detector.getTargetMatch().found) << "decimation " << decimation;
    for (size_t k = 0; k < after.centres.size(); ++k) {
      const vpSSLLandmark *l = detector.getMatchedLandmark(k);
      ASSERT_NE(l, nullptr);
      EXPECT_LT(std::hypot(l->u - after.centres[k].get_u(), l->v - after.centres[k].get_v()), 0.5)
          << "decimation " << decimation << ", landmark " << k;
    }
  }
}

TEST(DetectorSpeedPaths, LargePredictedLandmarksAreMatchedOnTheDecimatedImage)
{
  // At full resolution, a region whose predicted landmark has a smaller semi-axis of 25 px or more is matched on the
  // decimated image; the landmarks are those a full search reads. The target moved by 14 px, too far for the
  // re-reading from the regions' centres.
  const View before = render(1.0), after = render(1.0, 14.);
  vpSSLDetector reference;
  reference.setNbThreads(1);
  ASSERT_TRUE(reference.detect(after.I));
  ASSERT_EQ(reference.getLandmarks().size(), 3u);
  vpSSLDetector detector;
  detector.setNbThreads(1);
  ASSERT_TRUE(detector.detect(before.I));
  for (const vpSSLLandmark &l : detector.getLandmarks()) {
    ASSERT_GE(l.minorRadius, 25.) << "the test needs large landmarks";
  }
  detector.setRegionsOfInterest(roisAround(before.centres));
  detector.detect(after.I);
  EXPECT_EQ(vpSSLDetectorTestAccess::getMatchedRegions(detector).size(), 3u);
  EXPECT_TRUE(vpSSLDetectorTestAccess::getMapRegions(detector).empty())
      << "every region was matched on the decimated image";
  size_t nonZero = 0;
  const vpImage<int> &M = detector.getMatchingMap();
  for (unsigned int i = 0; i < M.getSize(); ++i) {
    nonZero += M.bitmap[i] != 0 ? 1 : 0;
  }
  EXPECT_EQ(nonZero, 0u) << "the full-resolution map has no region";
  ASSERT_EQ(detector.getLandmarks().size(), 3u);
  for (const vpSSLLandmark &l : reference.getLandmarks()) {
    bool same = false;
    for (const vpSSLLandmark &k : detector.getLandmarks()) {
      same = same || (std::hypot(k.u - l.u, k.v - l.v) < 0.05 && std::fabs(k.radius / l.radius - 1.) < 0.01 &&
                      std::fabs(k.minorRadius / l.minorRadius - 1.) < 0.01);
    }
    EXPECT_TRUE(same) << "landmark at " << l.u << ", " << l.v << " not read as the full search read it";
  }
  EXPECT_TRUE(detector.getTargetMatch().found);
}

TEST(DetectorSpeedPaths, RegionsTheDecimatedPassMissesAreMatchedAtFullResolution)
{
  // The target went from 1 m to 3.5 m between two frames: its landmarks (60 and 30 px, then 17 and 9 px) are
  // predicted large, some are missed on the decimated image, and those regions are matched again at full
  // resolution, which reads what a fresh detector matching the same regions at full resolution reads.
  const View before = render(1.0), after = render(3.5);
  vpSSLDetector detector;
  detector.setNbThreads(1);
  ASSERT_TRUE(detector.detect(before.I));
  const std::vector<vpRect> rois = roisAround(after.centres);
  detector.setRegionsOfInterest(rois);
  detector.detect(after.I);
  EXPECT_EQ(vpSSLDetectorTestAccess::getMatchedRegions(detector).size(), 3u);
  EXPECT_FALSE(vpSSLDetectorTestAccess::getMapRegions(detector).empty())
      << "no region was matched again at full resolution";
  vpSSLDetector fresh;
  fresh.setNbThreads(1);
  fresh.setRegionsOfInterest(rois);
  fresh.detect(after.I);
  EXPECT_EQ(vpSSLDetectorTestAccess::getMapRegions(fresh).size(), 3u) << "a fresh detector has no prediction";
  EXPECT_GE(fresh.getLandmarks().size(), 2u);
  EXPECT_EQ(detector.getLandmarks().size(), fresh.getLandmarks().size());
  for (const vpSSLLandmark &l : fresh.getLandmarks()) {
    bool same = false;
    for (const vpSSLLandmark &k : detector.getLandmarks()) {
      same = same || (std::hypot(k.u - l.u, k.v - l.v) < 0.05 && std::fabs(k.radius / l.radius - 1.) < 0.01);
    }
    EXPECT_TRUE(same) << "landmark at " << l.u << ", " << l.v << " (radius " << l.radius << ") not read";
  }
}

/*
  The fast matching function (SIMD with run-time dispatch, threads, regions of interest) gives exactly
  the map of computeReference() (paper Eq. 3 and 5): on noise, sparse binary and ring images, at every window
  length, at the borders and odd widths, for any thread count, on every SIMD target compiled in, and inside
  the regions of interest (0 outside them).
*/

#include <atomic>
#include <cmath>
#include <cstdlib>

#include <random>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <visp3/core/vpException.h>
#include <visp3/core/vpUniRand.h>
#include <visp3/ssl/vpSSLMatchingFunction.h>

#include "allocation_counter.h"

namespace {
enum class Kind
{
  Noise,  // i.i.d. uniform grey levels
  Sparse, // mostly 0 with a few 255 pixels: exercises equal samples and ties between directions
  Rings   // concentric rings of radii in ratio p (the printed pattern, Eq. 1), slightly noisy
};

vpImage<unsigned char> makeImage(Kind kind, unsigned int w, unsigned int h, double p, long seed)
{
  vpImage<unsigned char> I(h, w);
  vpUniRand rng(seed);
  const double cu = rng.uniform(0., w), cv = rng.uniform(0., h), r0 = rng.uniform(20., 200.);
  for (unsigned int v = 0; v < h; ++v) {
    for (unsigned int u = 0; u < w; ++u) {
      switch (kind) {
      case Kind::Noise:
        I[v][u] = static_cast<unsigned char>(rng.uniform(0, 256));
        break;
      case Kind::Sparse:
        I[v][u] = rng.uniform(0., 1.) < 0.1 ? 255 : 0;
        break;
      case Kind::Rings: {
        const double r = std::hypot(u - cu, v - cv) + 0.5;
        const int ring = static_cast<int>(std::floor(std::log(r / r0) / std::log(p)));
        I[v][u] = static_cast<unsigned char>((ring % 2 == 0 ? 220 : 30) + rng.uniform(-20, 21));
        break;
      }
      }
    }
  }
  return I;
}

// Number of pixels where the two maps differ (and the first one, for the failure message).
::testing::AssertionResult sameMap(const vpImage<int> &expected, const vpImage<int> &actual)
{
  if (expected.getWidth() != actual.getWidth() || expected.getHeight() != actual.getHeight()) {
    return ::testing::AssertionFailure() << "size " << actual.getWidth() << "x" << actual.getHeight() << " instead of "
                                         << expected.getWidth() << "x" << expected.getHeight();
  }
  long diffs = 0;
  std::string first;
  for (unsigned int v = 0; v < expected.getHeight(); ++v) {
    for (unsigned int u = 0; u < expected.getWidth(); ++u) {
      if (expected[v][u] != actual[v][u] && diffs++ == 0) {
        first = "(u " + std::to_string(u) + ", v " + std::to_string(v) + "): " + std::to_string(actual[v][u]) +
                " instead of " + std::to_string(expected[v][u]);
      }
    }
  }
  if (diffs == 0) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << diffs << " pixels differ, first at " << first;
}

::testing::AssertionResult fastEqualsReference(const vpSSLMatchingFunction &f, const vpImage<unsigned char> &I)
{
  vpImage<int> ref, fast;
  f.computeReference(I, ref);
  f.compute(I, fast);
  ::testing::AssertionResult r = sameMap(ref, fast);
  if (!r) {
    r << " (" << I.getWidth() << "x" << I.getHeight() << ", w " << f.getWindow() << ", p " << f.getP() << ", target "
      << vpSSLMatchingFunction::getSimdTarget() << ")";
  }
  return r;
}

const Kind kKinds[] = {Kind::Noise, Kind::Sparse, Kind::Rings};

// Tiny, odd, not a multiple of any vector length, and the widths around 2w where the +x and -x zones meet.
void checkSizesAndPatterns(unsigned int window, double p)
{
  const unsigned int w2 = 2 * window;
  const unsigned int sizes[][2] = {{1, 1},       {5, 3},   {3, 5},      {w2, 7},      {w2 + 1, 9},
                                   {w2 + 2, 11}, {7, w2},  {9, w2 + 1}, {11, w2 + 2}, {w2 + 1, w2},
                                   {97, 61},     {33, 65}, {130, 47},   {47, 130},    {w2 + 63, w2 + 3}};
  long seed = 1;
  vpSSLMatchingFunction f(window, p);
  for (const auto &s : sizes) {
    for (Kind kind : kKinds) {
      EXPECT_TRUE(fastEqualsReference(f, makeImage(kind, s[0], s[1], p, seed++)));
    }
  }
}
} // namespace

TEST(MatchingFast, equalsReferenceOnNoiseSparseAndRingImages)
{
  for (double p : {0.5, 0.3, 0.7}) {
    for (unsigned int window : {2u, 5u, 40u}) {
      checkSizesAndPatterns(window, p);
    }
  }
}

TEST(MatchingFast, equalsReferenceForEveryWindowLength)
{
  // Per window: a wide image (only the horizontal directions, both borders and the middle where they meet) and
  // a tall one (only the vertical ones); sizes grow with w so that each has valid pixels, and the reference stays
  // cheap. A few windows also get an image where all four directions overlap.
  vpSSLMatchingFunction f(2, 0.5);
  for (unsigned int w = 2; w <= 128; ++w) {
    f.setWindow(w);
    const unsigned int a = 2 * w + 1 + w % 3, b = 5 + w % 4;
    EXPECT_TRUE(fastEqualsReference(f, makeImage(Kind::Noise, a, b, 0.5, w)));
    EXPECT_TRUE(fastEqualsReference(f, makeImage(Kind::Rings, b, a, 0.5, w + 1000)));
  }
  for (unsigned int w : {2u, 3u, 16u, 33u, 64u, 128u}) {
    f.setWindow(w);
    EXPECT_TRUE(fastEqualsReference(f, makeImage(Kind::Sparse, 2 * w + 3, w < 64 ? 2 * w + 5 : w + 9, 0.5, w)));
  }
  for (double p : {0.3, 0.7}) {
    f.setP(p);
    for (unsigned int w : {3u, 17u, 64u, 127u, 128u}) {
      f.setWindow(w);
      EXPECT_TRUE(fastEqualsReference(f, makeImage(Kind::Noise, 2 * w + 3, 7, p, w)));
      EXPECT_TRUE(fastEqualsReference(f, makeImage(Kind::Sparse, 6, 2 * w + 2, p, w)));
    }
  }
}

TEST(MatchingFast, everySimdTargetCompiledInGivesTheSameMap)
{
  // The reference maps once, then every target the CPU supports (the scalar fallback included) against them.
  struct Case
  {
    vpSSLMatchingFunction f;
    vpImage<unsigned char> I;
    vpImage<int> ref;
  };
  std::vector<Case> cases;
  long seed = 100;
  for (unsigned int window : {2u, 9u, 40u}) {
    const unsigned int sizes[][2] = {{1, 1}, {5, 3}, {2 * window, 9}, {2 * window + 1, 2 * window + 2}, {161, 97}};
    for (const auto &sz : sizes) {
      for (Kind kind : kKinds) {
        Case c{vpSSLMatchingFunction(window, 0.5), makeImage(kind, sz[0], sz[1], 0.5, seed++), vpImage<int>()};
        c.f.computeReference(c.I, c.ref);
        cases.push_back(c);
      }
    }
  }
  const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
  ASSERT_FALSE(targets.empty());
  bool scalarSeen = false;
  for (int64_t t : targets) {
    hwy::SetSupportedTargetsForTest(t);
    EXPECT_EQ(vpSSLMatchingFunction::getSimdTarget(), hwy::TargetName(t));
    scalarSeen = scalarSeen || t == HWY_SCALAR || t == HWY_EMU128;
    for (const Case &c : cases) {
      vpImage<int> M;
      c.f.compute(c.I, M);
      EXPECT_TRUE(sameMap(c.ref, M)) << hwy::TargetName(t) << ", " << c.I.getWidth() << "x" << c.I.getHeight() << ", w "
                                     << c.f.getWindow();
    }
  }
  hwy::SetSupportedTargetsForTest(0);
  EXPECT_TRUE(scalarSeen) << "the plain fallback target was not compiled in";
}

TEST(MatchingFast, anyThreadCountGivesTheSameMap)
{
  for (unsigned int window : {8u, 40u}) {
    vpSSLMatchingFunction f(window, 0.5);
    // Large enough for the work to be split (small images run on the calling thread only).
    const vpImage<unsigned char> I = makeImage(Kind::Rings, 323, 241, 0.5, 3);
    vpImage<int> ref;
    f.computeReference(I, ref);
    for (unsigned int n : {0u, 1u, 2u, 3u, 8u}) {
      f.setNbThreads(n);
      vpImage<int> M;
      f.compute(I, M);
      EXPECT_TRUE(sameMap(ref, M)) << n << " threads, w " << window;
    }
  }
}

TEST(MatchingFast, concurrentCallersGetTheSameMap)
{
  // Two threads share one matching function (its methods are const): each must get its own scratch buffers, and
  // the one that finds the worker pool busy runs alone.
  vpSSLMatchingFunction f(40, 0.5);
  f.setNbThreads(2);
  const vpImage<unsigned char> I1 = makeImage(Kind::Noise, 300, 200, 0.5, 21),
                               I2 = makeImage(Kind::Rings, 250, 260, 0.5, 22);
  vpImage<int> ref1, ref2;
  f.computeReference(I1, ref1);
  f.computeReference(I2, ref2);
  std::atomic<int> wrong{0};
  auto worker = [&](const vpImage<unsigned char> &I, const vpImage<int> &ref) {
    vpImage<int> M;
    for (int k = 0; k < 20; ++k) {
      f.compute(I, M);
      wrong += !sameMap(ref, M);
    }
  };
  std::thread t1(worker, std::cref(I1), std::cref(ref1)), t2(worker, std::cref(I2), std::cref(ref2));
  t1.join();
  t2.join();
  EXPECT_EQ(wrong.load(), 0);
}

TEST(MatchingFast, reusedBuffersFollowSizeAndWindowChanges)
{
  // The widened image and the output are reused from call to call: shrinking and growing must not leak stale data.
  vpSSLMatchingFunction f(40, 0.5);
  vpImage<int> M;
  const unsigned int sizes[][3] = {{300, 200, 40}, {90, 85, 40}, {300, 200, 12}, {31, 300, 60}, {300, 200, 40}};
  long seed = 11;
  for (const auto &s : sizes) {
    f.setWindow(s[2]);
    const vpImage<unsigned char> I = makeImage(Kind::Noise, s[0], s[1], 0.5, seed++);
    vpImage<int> ref;
    f.computeReference(I, ref);
    f.compute(I, M);
    EXPECT_TRUE(sameMap(ref, M)) << s[0] << "x" << s[1] << " w " << s[2];
  }
}

TEST(MatchingFast, regionsOfInterestMatchTheReferenceInsideAndAreZeroOutside)
{
  vpSSLMatchingFunction f(20, 0.5);
  const vpImage<unsigned char> I = makeImage(Kind::Rings, 211, 143, 0.5, 5);
  vpImage<int> ref;
  f.computeReference(I, ref);
  std::vector<std::vector<vpRect>> cases = {
      {},                                                                           // nothing: all zero
      {vpRect(30, 20, 50, 40)},                                                     // one box inside
      {vpRect(-15, -10, 40, 30), vpRect(190, 120, 50, 50)},                         // partly outside (corners)
      {vpRect(10, 10, 80, 60), vpRect(50, 40, 80, 60), vpRect(60, 45, 5, 5)},       // overlapping, one inside another
      {vpRect(100, 50, 0, 30), vpRect(300, 300, 10, 10), vpRect(-50, -50, 20, 20)}, // empty and fully outside
      {vpRect(12.5, 7.2, 30.3, 20.9), vpRect(0, 0, 1, 1), vpRect(210, 142, 1, 1)},  // fractional, single pixels
      {vpRect(-1000, -1000, 5000, 5000)}};                                          // the whole image and more
  // Many boxes that start and end on different rows, in no order, overlapping or not (a full search's candidate
  // tiles are a few hundred such boxes).
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> position(-20, 220), side(1, 40);
  cases.emplace_back();
  for (int k = 0; k < 60; ++k) {
    cases.back().push_back(vpRect(position(rng), position(rng), side(rng), side(rng)));
  }
  for (std::size_t c = 0; c < cases.size(); ++c) {
    for (unsigned int n : {1u, 2u, 3u}) {
      f.setNbThreads(n);
      vpImage<int> M(I.getHeight(), I.getWidth(), 12345); // stale content must be cleared
      f.compute(I, cases[c], M);
      long inside = 0, wrong = 0;
      for (unsigned int v = 0; v < I.getHeight(); ++v) {
        for (unsigned int u = 0; u < I.getWidth(); ++u) {
          bool in = false;
          for (const vpRect &r : cases[c]) {
            in = in || (u >= std::ceil(r.getLeft()) && u <= std::floor(r.getRight()) && v >= std::ceil(r.getTop()) &&
                        v <= std::floor(r.getBottom()));
          }
          inside += in;
          wrong += M[v][u] != (in ? ref[v][u] : 0);
        }
      }
      EXPECT_EQ(wrong, 0) << "case " << c << ", " << n << " threads, " << inside << " pixels inside";
    }
  }
}

TEST(MatchingFast, nonFiniteRegionOfInterestIsRejected)
{
  vpSSLMatchingFunction f(20, 0.5);
  const vpImage<unsigned char> I = makeImage(Kind::Noise, 64, 48, 0.5, 1);
  vpImage<int> M;
  EXPECT_THROW(f.compute(I, {vpRect(10, 10, 10, 10), vpRect(NAN, 0, 10, 10)}, M), vpException);
}

TEST(MatchingFast, steadyStateCallsDoNotAllocate)
{
  vpSSLMatchingFunction f(40, 0.5);
  f.setNbThreads(2);
  const vpImage<unsigned char> I = makeImage(Kind::Rings, 320, 240, 0.5, 9);
  const std::vector<vpRect> rois = {vpRect(20, 20, 100, 100), vpRect(150, 100, 100, 100)};
  vpImage<int> M, Mroi;
  for (int warmup = 0; warmup < 2; ++warmup) {
    f.compute(I, M);
    f.compute(I, rois, Mroi);
  }
  long allocations = 0;
  {
    const sslt::AllocationCounter counter;
    f.compute(I, M);
    f.compute(I, rois, Mroi);
    allocations = counter.count();
  }
  EXPECT_EQ(allocations, 0);
}

TEST(MatchingFast, reportsTheTargetThatRuns)
{
  const std::string target = vpSSLMatchingFunction::getSimdTarget();
  EXPECT_EQ(target, hwy::TargetName(hwy::SupportedAndGeneratedTargets().front()));
}

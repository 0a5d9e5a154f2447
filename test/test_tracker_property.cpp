/*
  Property test of vpSSLTracker: no sequence of inputs (images of the target in any order, shifted so that it
  jumps, blank, noisy, empty or wrapped-size frames; odometry that is missing, NaN, infinite, a spike of
  kilometres, not a rigid motion) yields a NaN pose, an exception other than vpException, or a state change
  outside the state machine documented in vpSSLTracker.h. Random sequences from fixed seeds (reproducible).
*/
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <visp3/core/vpException.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpPoseVector.h>
#include <visp3/ssl/vpSSLFinite.h>
#include <visp3/ssl/vpSSLTracker.h>
#include <visp3/ssl_io/vpSSLSequenceReader.h>

#include "ssl_test_utils.h"

namespace {
struct Pool
{
  vpCameraParameters cam;
  vpHomogeneousMatrix vMc;
  std::vector<vpImage<unsigned char>> images;
};

// Every image of two recorded sequences: the target from 10 m to 0.5 m, and leaving the view and coming back.
const Pool &pool()
{
  static Pool p;
  if (p.images.empty()) {
    for (const char *name : {"approach-clear", "leave-return-clear"}) {
      vpSSLSequenceReader reader;
      reader.open(std::string(VISP_SSL_DATA_DIR) + "/sequences/" + name);
      p.cam = reader.getCameraParameters();
      p.vMc = vpHomogeneousMatrix(reader.getInfo().vMc);
      vpSSLSequenceFrame f;
      vpImage<unsigned char> I;
      while (reader.next(f, I)) {
        p.images.push_back(I);
      }
    }
  }
  return p;
}

// The transitions vpSSLTracker.h documents (a state may also stay as it is).
bool allowed(vpSSLTrackerState from, vpSSLTrackerState to)
{
  if (from == to) {
    return true;
  }
  switch (from) {
  case SSL_TRACKER_SEARCHING:
    return to == SSL_TRACKER_ACQUIRED;
  case SSL_TRACKER_ACQUIRED:
    return to == SSL_TRACKER_TRACKING || to == SSL_TRACKER_LOST;
  case SSL_TRACKER_TRACKING:
    return to == SSL_TRACKER_ACQUIRED || to == SSL_TRACKER_LOST;
  case SSL_TRACKER_LOST:
    return to == SSL_TRACKER_ACQUIRED || to == SSL_TRACKER_SEARCHING;
  }
  return false;
}

bool known(vpSSLTrackerState s)
{
  return s == SSL_TRACKER_SEARCHING || s == SSL_TRACKER_ACQUIRED || s == SSL_TRACKER_TRACKING || s == SSL_TRACKER_LOST;
}

// The image of step kind k: a pool image shifted by (du, dv) (white where it comes from outside), a blank or noisy
// frame, an empty one or one whose vpImage size wrapped.
vpImage<unsigned char> frame(std::mt19937 &rng, int &kind)
{
  const Pool &p = pool();
  std::uniform_int_distribution<int> pick(0, 99);
  const int r = pick(rng);
  vpImage<unsigned char> I;
  if (r < 70) {
    kind = 0;
    const vpImage<unsigned char> &src = p.images[rng() % p.images.size()];
    const int du = static_cast<int>(rng() % 161) - 80, dv = static_cast<int>(rng() % 121) - 60;
    const int W = static_cast<int>(src.getWidth()), H = static_cast<int>(src.getHeight());
    I.resize(src.getHeight(), src.getWidth(), 255);
    for (int v = 0; v < H; ++v) {
      for (int u = 0; u < W; ++u) {
        if (v - dv >= 0 && v - dv < H && u - du >= 0 && u - du < W) {
          I[v][u] = src[v - dv][u - du];
        }
      }
    }
  } else if (r < 78) {
    kind = 1;
    I.resize(480, 640, static_cast<unsigned char>(rng() % 256));
  } else if (r < 86) {
    kind = 1;
    I.resize(480, 640);
    for (unsigned int i = 0; i < I.getSize(); ++i) {
      I.bitmap[i] = static_cast<unsigned char>(rng() % 256);
    }
  } else if (r < 93) {
    kind = 2; // empty: track() throws and nothing changes
  } else {
    kind = 3;
    I.resize(1 + rng() % 8, 1 + rng() % 8, 128); // tiny
  }
  return I;
}

// Odometry of a step: a small motion from the previous one, or a spike, a NaN, an infinity, a non-rigid matrix.
vpHomogeneousMatrix odometry(std::mt19937 &rng, const vpHomogeneousMatrix &previous)
{
  std::uniform_real_distribution<double> small(-0.05, 0.05);
  const int r = static_cast<int>(rng() % 10);
  vpHomogeneousMatrix M;
  if (r < 5) {
    M = previous * vpHomogeneousMatrix(small(rng), small(rng), small(rng), small(rng), small(rng), small(rng));
  } else if (r == 5) {
    M = previous * vpHomogeneousMatrix(1e4, -3e3, 50., 3., -2., 1.); // a spike
  } else if (r == 6) {
    M = previous;
    M[0][3] = std::numeric_limits<double>::quiet_NaN();
  } else if (r == 7) {
    M = previous;
    M[2][3] = std::numeric_limits<double>::infinity();
  } else if (r == 8) {
    M = previous;
    M[0][0] = 1e300; // not a rotation
  } else {
    M = previous;
    M[1][1] = -std::numeric_limits<double>::infinity();
  }
  return M;
}
} // namespace

TEST(TrackerProperty, NoInputSequenceGivesANaNPoseOrAnUndocumentedTransition)
{
  const Pool &p = pool();
  ASSERT_FALSE(p.images.empty());
  unsigned int seen[4] = {0, 0, 0, 0}, transitions = 0;
  for (unsigned int seed = 1; seed <= 40; ++seed) {
    std::mt19937 rng(seed);
    vpSSLTracker tracker(vpSSLTarget::ssl3a3(), p.cam, p.vMc);
    tracker.getFilter().setNbParticles(300);
    tracker.setSeed(static_cast<long>(seed));
    vpHomogeneousMatrix oMv;
    for (int step = 0; step < 14; ++step) {
      const vpSSLTrackerState before = tracker.getState();
      int kind = 0;
      const vpImage<unsigned char> I = frame(rng, kind);
      const bool withOdometry = rng() % 3 != 0;
      if (withOdometry) {
        oMv = odometry(rng, oMv);
      }
      bool threw = false;
      try {
        if (withOdometry) {
          tracker.track(I, oMv);
        } else {
          tracker.track(I);
        }
      } catch (const vpException &) {
        threw = true;
      } catch (...) {
        FAIL() << "seed " << seed << " step " << step << ": an exception other than vpException";
      }
      const vpSSLTrackerState after = tracker.getState();
      ASSERT_TRUE(known(after)) << "seed " << seed << " step " << step;
      EXPECT_TRUE(allowed(before, after)) << "seed " << seed << " step " << step << ": " << before << " -> " << after;
      if (kind == 2) {
        EXPECT_TRUE(threw) << "an empty image must be refused";
        EXPECT_EQ(before, after) << "a refused image must not change the state";
      }
      if (after == SSL_TRACKER_SEARCHING) {
        EXPECT_FALSE(tracker.hasPose()) << "seed " << seed << " step " << step;
      }
      if (tracker.hasPose()) {
        ASSERT_TRUE(vpSSLFinite::isFinite(tracker.getPose())) << "seed " << seed << " step " << step << "\n"
                                                              << tracker.getPose();
      }
      EXPECT_LE(tracker.getNbLandmarks(), 3u);
      for (const vpRect &r : tracker.getRegionsOfInterest()) {
        EXPECT_TRUE(std::isfinite(r.getLeft()) && std::isfinite(r.getTop()) && std::isfinite(r.getWidth()) &&
                    std::isfinite(r.getHeight()));
      }
      ++seen[after];
      transitions += before != after ? 1 : 0;
    }
    tracker.reset();
    EXPECT_EQ(tracker.getState(), SSL_TRACKER_SEARCHING);
    EXPECT_FALSE(tracker.hasPose());
  }
  // The sequences drive the tracker through its states, not only SEARCHING.
  EXPECT_GT(seen[SSL_TRACKER_ACQUIRED], 0u);
  EXPECT_GT(seen[SSL_TRACKER_TRACKING] + seen[SSL_TRACKER_LOST], 0u);
  EXPECT_GT(transitions, 10u);
}

TEST(TrackerProperty, WrappedImageSizeIsRefusedWithoutChangingTheState)
{
  const Pool &p = pool();
  vpSSLTracker tracker(vpSSLTarget::ssl3a3(), p.cam, p.vMc);
  tracker.track(p.images[6]);
  const vpSSLTrackerState before = tracker.getState();
  const vpImage<unsigned char> wrapped(65536, 65537, 128);
  EXPECT_THROW(tracker.track(wrapped), vpException);
  EXPECT_EQ(tracker.getState(), before);
}

// libFuzzer target: the tracker fed arbitrary detections and odometry. Each step of the input (up to 8) picks an
// image (one of the sample photographs of ssl3-a3 halved to 320x240, shifted by up to +-64 px so that the target
// jumps; a blank or a noise image; or an empty one) and an odometry pose (none, a small motion, a spike, or eight
// raw bytes per element: NaN, infinities, 1e300). After every step the state is one of the four, a pose when there
// is one is finite, and the only exceptions are vpExceptions. The rest of the input drives vpSSLParticleFilter
// directly with arbitrary observations (labels, centres, radii) and hypotheses.
#include <algorithm>
#include <cmath>
#include <vector>

#include <visp3/core/vpException.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpPoseVector.h>
#include <visp3/ssl/vpSSLParticleFilter.h>
#include <visp3/ssl/vpSSLTracker.h>
#include <visp3/ssl_io/vpSSLImageIo.h>

#include "fuzz_common.h"

namespace {
const std::vector<vpImage<unsigned char>> &images()
{
  static const std::vector<vpImage<unsigned char>> set = [] {
    std::vector<vpImage<unsigned char>> v;
    for (int i = 0; i < 4; ++i) {
      vpImage<unsigned char> I, half(240, 320);
      vpSSLImageIo::read(I, std::string(VISP_SSL_DATA_DIR) + "/images/ssl3-a3-0" + std::to_string(i) + ".png");
      for (unsigned int r = 0; r < 240; ++r) {
        for (unsigned int c = 0; c < 320; ++c) {
          half[r][c] = static_cast<unsigned char>(
              (I[2 * r][2 * c] + I[2 * r][2 * c + 1] + I[2 * r + 1][2 * c] + I[2 * r + 1][2 * c + 1] + 2) / 4);
        }
      }
      v.push_back(half);
    }
    return v;
  }();
  return set;
}

vpCameraParameters camera()
{
  vpCameraParameters cam;
  cam.initPersProjWithoutDistortion(277.15, 277.15, 160., 120.);
  return cam;
}

bool finite(const vpHomogeneousMatrix &M)
{
  for (unsigned int i = 0; i < 16; ++i) {
    if (!std::isfinite(M.data[i])) {
      return false;
    }
  }
  return true;
}

vpHomogeneousMatrix pose(sslfuzz::Input &in, uint8_t kind)
{
  vpPoseVector p;
  for (unsigned int i = 0; i < 6; ++i) {
    p[i] = kind == 1 ? in.range(-0.2, 0.2) : kind == 2 ? in.range(-1e4, 1e4) : in.anyDouble();
  }
  vpHomogeneousMatrix M;
  if (kind == 3) {
    // Raw elements: not even a rotation.
    for (unsigned int i = 0; i < 12; ++i) {
      M.data[i] = in.anyDouble();
    }
    return M;
  }
  for (unsigned int i = 0; i < 6; ++i) {
    if (!std::isfinite(p[i])) {
      M.data[i] = p[i];
      return M;
    }
  }
  M.buildFrom(p);
  return M;
}

void fuzzTracker(sslfuzz::Input &in)
{
  vpSSLTracker tracker(vpSSLTarget::ssl3a3(), camera());
  // One thread: the fuzzer runs one process per core, and fuzz_detector covers the matching on two threads.
  tracker.getDetector().setNbThreads(1);
  tracker.getFilter().setNbParticles(50 + in.byte());
  tracker.setSeed(in.byte());
  vpHomogeneousMatrix odometry;
  const int steps = 1 + in.byte() % 8;
  for (int s = 0; s < steps; ++s) {
    const uint8_t what = in.byte();
    vpImage<unsigned char> I;
    if (what % 8 < 4) {
      const vpImage<unsigned char> &src = images()[what % 4];
      const int du = static_cast<int8_t>(in.byte()) / 2, dv = static_cast<int8_t>(in.byte()) / 2;
      // The photograph moved by (du, dv), white where it leaves the frame, copied a row at a time.
      I.resize(240, 320, 255);
      const int c0 = std::max(0, du), c1 = std::min(320, 320 + du);
      for (int r = std::max(0, dv); r < std::min(240, 240 + dv); ++r) {
        std::copy(src[r - dv] + (c0 - du), src[r - dv] + (c1 - du), I[r] + c0);
      }
    } else if (what % 8 == 4) {
      I.resize(240, 320, in.byte());
    } else if (what % 8 == 5) {
      I.resize(1 + in.byte() % 64, 1 + in.byte() % 64);
      for (unsigned int i = 0; i < I.getSize(); ++i) {
        I.bitmap[i] = in.byte();
      }
    } // else: empty
    const uint8_t odo = (what >> 3) % 5;
    try {
      if (odo == 0) {
        tracker.track(I);
      } else {
        odometry = odo == 1 ? odometry * pose(in, 1) : pose(in, odo);
        tracker.track(I, odometry);
      }
    } catch (const vpException &) {
    }
    const vpSSLTrackerState st = tracker.getState();
    if (st != SSL_TRACKER_SEARCHING && st != SSL_TRACKER_ACQUIRED && st != SSL_TRACKER_TRACKING &&
        st != SSL_TRACKER_LOST) {
      std::abort();
    }
    if (tracker.hasPose() && !finite(tracker.getPose())) {
      std::abort();
    }
  }
}

void fuzzFilter(sslfuzz::Input &in)
{
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  vpSSLParticleFilter filter(target, camera());
  filter.setNbParticles(20 + in.byte() % 64);
  std::vector<vpSSLPoseHypothesis> hypotheses(1 + in.byte() % 3);
  for (vpSSLPoseHypothesis &h : hypotheses) {
    h.cMo = pose(in, in.byte() % 4);
    h.weight = in.byte() & 1 ? in.anyDouble() : 1.;
    h.positionOnly = in.byte() & 1;
    h.landmark = static_cast<int8_t>(in.byte()) % 4;
  }
  try {
    filter.init(hypotheses);
  } catch (const vpException &) {
    return;
  }
  const int steps = in.byte() % 8;
  for (int s = 0; s < steps && in.left() > 0; ++s) {
    std::vector<vpSSLObservation> obs(in.byte() % 5);
    for (vpSSLObservation &o : obs) {
      o.label = static_cast<int8_t>(in.byte()) % 5;
      const bool raw = in.byte() & 1;
      o.u = raw ? in.anyDouble() : in.range(-100., 400.);
      o.v = raw ? in.anyDouble() : in.range(-100., 300.);
      o.radius = raw ? in.anyDouble() : in.range(-1., 100.);
    }
    try {
      if (in.byte() & 1) {
        filter.predict(pose(in, in.byte() % 4));
      } else {
        filter.predict();
      }
      filter.update(obs, hypotheses);
    } catch (const vpException &) {
    }
    if (!finite(filter.getMeanPose())) {
      std::abort();
    }
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  sslfuzz::Input in(data, size);
  if (in.byte() & 1) {
    fuzzFilter(in);
  } else {
    fuzzTracker(in);
  }
  return 0;
}

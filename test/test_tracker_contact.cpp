/*
  Tracker at contact range: the ssl3-a3 pattern is self-similar all the way in, so once B's outer rings leave the
  image the detector reads an inner ring copy of B (scale p^k) as the landmark. The tracker's prediction tells the
  copy from the landmark and scales its range back.
*/
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/ssl/vpSSLTracker.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>
#include <visp3/ssl_sim/vpSSLScenario.h>

namespace {
// A straight final approach along the target's axis, rendered without water at 10 fps: camera from 2 m to 0.12 m
// (the nose touches the board at about 0.15 m), 5 cm/frame then 2 cm/frame below 0.6 m, slightly off-centre.
struct Frame
{
  vpHomogeneousMatrix cMo, oMv;
  vpImage<unsigned char> I;
};

const std::vector<Frame> &finalApproach()
{
  static std::vector<Frame> frames;
  if (frames.empty()) {
    const vpHomogeneousMatrix wMo = vpSSLScenario("approach").getTargetHome();
    const vpHomogeneousMatrix cMv = vpSSLScenario::getDefaultCameraToVehicle().inverse();
    vpSSLRenderer renderer(vpCameraParameters(554.3, 554.3, 320., 240.), 640, 480);
    for (double range = 2.; range > 0.119; range -= range > 0.6 ? 0.05 : 0.02) {
      Frame f;
      f.cMo = vpHomogeneousMatrix(vpTranslationVector(0.01, -0.015, range), vpRotationMatrix());
      f.oMv = wMo * f.cMo.inverse() * cMv; // exact odometry: the vehicle pose in the world
      renderer.render(f.cMo, f.I);
      frames.push_back(f);
    }
  }
  return frames;
}
} // namespace

TEST(TrackerContact, RangeOfAnInnerRingCopyIsScaledBack)
{
  const std::vector<Frame> &frames = finalApproach();
  vpSSLTracker tracker(vpSSLTarget::ssl3a3(), vpCameraParameters(554.3, 554.3, 320., 240.),
                       vpSSLScenario::getDefaultCameraToVehicle());
  tracker.setSeed(1);
  int nbClose = 0;
  for (const Frame &f : frames) {
    tracker.track(f.I, f.oMv);
    const double truth = f.cMo[2][3];
    if (truth < 0.9 && tracker.hasPose()) {
      ++nbClose;
      const double range = tracker.getPose()[2][3];
      EXPECT_LT(std::fabs(range - truth), 0.05 + 0.15 * truth) << "true range " << truth << " m, tracked " << range;
    }
  }
  EXPECT_GT(nbClose, 10);
}

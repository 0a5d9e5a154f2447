//! \example tutorial-ssl-auv-driver.cpp
//! The homing loop of doc/servo.md on a vehicle driver: vpSSLRobotAuvTemplate
//! (modules/bench/include/visp3/ssl_harness/vpSSLRobotAuvTemplate.h), the skeleton of a ViSP robot driver to copy for a
//! real AUV, driven by vpSSLHomingBehaviour through vpRobot::setVelocity(). Its camera here is a vpFrameGrabber that
//! renders the ssl3-a3 target at the vehicle's pose; on a vehicle it is the camera's grabber (vpV4l2Grabber, ...), and
//! the loop below stays the same.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include <visp3/core/vpFrameGrabber.h>
#include <visp3/core/vpImageConvert.h>
#include <visp3/core/vpMath.h>
#include <visp3/ssl/vpSSLTracker.h>
#include <visp3/ssl_servo/vpSSLHomingBehaviour.h>
#include <visp3/ssl_servo/vpSSLServoInput.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>

#include "ssl_tutorial_common.h"
#include "ssl_tutorial_option_loop.h"
#include <visp3/ssl_harness/vpSSLRobotAuvTemplate.h>

namespace {
const char *kProgram = "tutorial-ssl-auv-driver";

const char *kUsage = R"(Usage: tutorial-ssl-auv-driver [options]
Runs the homing loop of doc/servo.md on vpSSLRobotAuvTemplate, the skeleton of a ViSP robot driver for an AUV
(modules/bench/include/visp3/ssl_harness/vpSSLRobotAuvTemplate.h: copy it and fill in your vehicle's autopilot and
navigation). As shipped its navigation is a perfect vehicle and its camera renders the ssl3-a3 target at the
vehicle's pose (320x240, the target 4 m ahead, off the axis and turned). Each step: acquire (image, odometry, depth,
collision), track, vpSSLHomingBehaviour::update(), apply() (setVelocity(ARTICULAR_FRAME, surge sway heave p q r)).
Prints every change of state and a final line. (No docking: the stand-in vehicle has no collision switch.)
Options:
  --steps N            Control steps of 0.2 s (1 to 100000; default 300).
  --stand-off Z        Stand-off held in HOME (m, 1 to 3; default 2).
  --help               This help.

Exit status: 0 on success, 2 on a bad option, 1 on a runtime failure; every error is one line on stderr.
Final line: state, steps, simulated time, range measured by the tracker and true range (m).
)";

struct Options
{
  long steps = 300;
  double standOff = 2.;
};

// The command line into \e o; false after --help, the usage printed.
bool parse(int argc, char **argv, Options &o)
{
  // One option: false for an option this tutorial does not know.
  const auto option = [&](const std::string &a, const auto &value) {
    if (a == "--steps") {
      o.steps = static_cast<long>(ssltut::parseInteger(a, value(), 1, 100000));
    } else if (a == "--stand-off") {
      o.standOff = ssltut::parseNumber(a, value(), 1., 3.);
    } else {
      return false;
    }
    return true;
  };
  return ssltut::readOptions(argc, argv, kUsage, ssltut::OptionStyle::ReadAll, option);
}

/*
  The stand-in camera: a vpFrameGrabber, as a real camera's driver is, rendering the target at the pose the
  vehicle's navigation gives (the stand-in navigation is exact, so this is the true view).
*/
class RenderedCamera : public vpFrameGrabber
{
public:
  RenderedCamera(const vpSSLRenderer &renderer, const vpSSLRobotAuvTemplate &auv, const vpHomogeneousMatrix &oMt)
      : m_renderer(renderer), m_auv(auv), m_oMt(oMt)
  {
    width = renderer.getWidth();
    height = renderer.getHeight();
  }
  void open(vpImage<unsigned char> &I) override
  {
    I.resize(height, width);
    init = true;
  }
  void open(vpImage<vpRGBa> &I) override
  {
    I.resize(height, width);
    init = true;
  }
  void acquire(vpImage<unsigned char> &I) override { m_renderer.render(cMt(), I); }
  void acquire(vpImage<vpRGBa> &I) override
  {
    vpImage<unsigned char> grey;
    m_renderer.render(cMt(), grey);
    vpImageConvert::convert(grey, I);
  }
  void close() override { init = false; }
  //! The target's pose in the camera frame at the vehicle's current pose.
  vpHomogeneousMatrix cMt() const { return (m_auv.getOdometry() * m_auv.getCameraToVehicle()).inverse() * m_oMt; }

private:
  const vpSSLRenderer &m_renderer;
  const vpSSLRobotAuvTemplate &m_auv;
  vpHomogeneousMatrix m_oMt;
};
} // namespace

int main(int argc, char **argv)
{
  return ssltut::guardedMain(kProgram, [&]() -> int {
    Options o;
    if (!parse(argc, argv, o)) {
      return 0; // --help
    }

    // The camera, 320x240 (the project's 640x480 camera scaled by half), forward-looking 0.5 m ahead.
    unsigned int width = 0, height = 0;
    const vpCameraParameters cam = ssltut::defaultCamera(width, height, true);
    const vpHomogeneousMatrix vMc = vpSSLServoLaw::forwardCameraMount(0.5);

    // The vehicle driver, its navigation starting at the odometry origin; the target 4 m ahead of the camera.
    vpSSLRobotAuvTemplate auv;
    auv.setTimeStep(0.2);
    const vpHomogeneousMatrix cMtStart(0.3, 0.15, 4., 0., vpMath::rad(15.), 0.);
    vpSSLRenderer renderer(cam, width, height);
    renderer.setTarget(vpSSLTarget::ssl3a3());
    renderer.setSupersampling(1);
    RenderedCamera camera(renderer, auv, vMc * cMtStart);
    vpImage<unsigned char> I;
    camera.open(I);
    auv.setCamera(camera, vMc);
    auv.init();

    // The loop of doc/servo.md.
    vpSSLTracker tracker(vpSSLTarget::ssl3a3(), cam, auv.getCameraToVehicle());
    vpSSLHomingBehaviour homing;
    homing.getServoLaw().setCameraToVehicle(auv.getCameraToVehicle());
    homing.setStandOff(o.standOff);
    vpHomogeneousMatrix oMv;
    double depth = 0.;
    bool collision = false;
    vpSSLHomingState last = homing.getState();
    std::cout << "t 0.0 s state " << vpSSLHomingBehaviour::getStateName(last) << std::endl;
    long step = 0;
    for (; step < o.steps && homing.getState() != SSL_HOMING_DOCKED; ++step) {
      auv.acquire(I, oMv, depth, collision);
      tracker.track(I, oMv);
      homing.update(auv.getTime(), vpSSLServoInput::fromTracker(tracker), depth, collision);
      homing.apply(auv); // setVelocity(vpRobot::ARTICULAR_FRAME, (u v w p q r))
      if (homing.getState() != last) {
        last = homing.getState();
        std::printf("t %.1f s state %s range %.3f m\n", auv.getTime(), vpSSLHomingBehaviour::getStateName(last).c_str(),
                    homing.getRange());
      }
    }
    double x = 0., y = 0., trueRange = 0.;
    vpSSLServoLaw::getTargetCentre(vpSSLServoInput::fromPose(vpSSLTarget::ssl3a3().getPoints(), camera.cMt()), x, y,
                                   trueRange);
    std::printf(
        "final: state %s after %ld steps (%.1f s): measured range %.3f m, true range %.3f m, stand-off %.2f m\n",
        vpSSLHomingBehaviour::getStateName(homing.getState()).c_str(), step, auv.getTime(), homing.getRange(),
        trueRange, o.standOff);
    return 0;
  });
}

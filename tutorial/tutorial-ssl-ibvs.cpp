//! \example tutorial-ssl-ibvs.cpp
//! Image-based visual servo of ViSP's free-flying camera (vpSimulatorCamera) on the ssl3-a3 target, as ViSP's
//! tutorial-ibvs-4pts-image-tracking.cpp does with four dots: at each iteration the camera image is rendered at
//! the simulated camera pose (vpSSLRenderer), the target is tracked (vpSSLTracker) and vpSSLServoLaw, set for a
//! camera robot, gives the camera twist sent to the robot, until the camera faces the target at the stand-off.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <visp3/core/vpFont.h>
#include <visp3/core/vpImageConvert.h>
#include <visp3/core/vpImageDraw.h>
#include <visp3/core/vpIoTools.h>
#include <visp3/core/vpMath.h>
#include <visp3/core/vpThetaUVector.h>
#include <visp3/io/vpImageIo.h>
#include <visp3/robot/vpSimulatorCamera.h>
#include <visp3/ssl/vpSSLTracker.h>
#include <visp3/ssl_servo/vpSSLServoInput.h>
#include <visp3/ssl_servo/vpSSLServoLaw.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>

#include "ssl_tutorial_common.h"
#include "ssl_tutorial_option_loop.h"

namespace {
const char *kProgram = "tutorial-ssl-ibvs";

const char *kUsage = R"(Usage: tutorial-ssl-ibvs [options]
Image-based visual servo of ViSP's free-flying camera (vpSimulatorCamera, 0.04 s per iteration) onto the
ssl3-a3 target: each iteration renders the camera image at the simulated pose, tracks the target
(vpSSLTracker) and sends the camera twist of vpSSLServoLaw (camera robot: six axes) to the robot. Stops when
the task error |s - s*| falls below --error; prints a line every 25 iterations and the final error.
Options:
  --stand-off Z        Desired distance from the camera to the target centre, facing it (m, 0.5 to 2; default 1).
  --start X,Y,Z,RX,RY,RZ
                       Initial pose of the target in the camera frame, cMo (m and deg, rotations about x, y, z;
                       default 0.15,-0.1,2,10,-10,30: 2 m away, off-centre, turned).
  --iterations N       Largest number of iterations (1 to 100000; default 500).
  --error E            Task error norm at which the servo has converged (normalised units, > 0; default 0.005).
  --small              320 x 240 camera (data/camera/camera-640x480.xml scaled by half) instead of 640 x 480.
  --seed N             Seed of the tracker's particle filter (0 to 100000; default 1).
  --display            Show the tracked image in a window; without an X display, write it as PNGs instead.
  --output-dir DIR     Write the annotated image every --save-every iterations and the last one into DIR
                       (created if needed; default with --display and no X display: ssl-ibvs).
  --save-every N       Period of the written images (1 to 100000 iterations; default 25).
  --help               This help.

Exit status: 0 when the servo converged, 1 when it did not within --iterations or on a runtime failure
(an image that cannot be written), 2 on a bad option; every error is one line on stderr.
Final line: iterations, simulated time, task error, and the true errors of the reached pose against the
desired one (camera facing the target centre at the stand-off): range, lateral (mm), rotation (deg).
)";

struct Options
{
  double standOff = 1.;
  vpHomogeneousMatrix cMo = vpHomogeneousMatrix(0.15, -0.1, 2., vpMath::rad(10.), vpMath::rad(-10.), vpMath::rad(30.));
  long iterations = 500;
  double error = 0.005;
  bool small = false;
  long seed = 1;
  bool display = false;
  std::string outputDir;
  long saveEvery = 25;
};

// "X,Y,Z,RX,RY,RZ" (m, deg) as a pose.
vpHomogeneousMatrix parsePose(const std::string &name, const std::string &text)
{
  std::vector<double> v;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    v.push_back(ssltut::parseNumber(name, item, -1e3, 1e3));
  }
  if (v.size() != 6 || (!text.empty() && text.back() == ',')) {
    throw ssltut::UsageError(name + ": expected X,Y,Z,RX,RY,RZ (six numbers), got \"" + text + "\"");
  }
  if (v[2] <= 0.) {
    throw ssltut::UsageError(name + ": the target must be in front of the camera (Z > 0), got \"" + text + "\"");
  }
  return vpHomogeneousMatrix(v[0], v[1], v[2], vpMath::rad(v[3]), vpMath::rad(v[4]), vpMath::rad(v[5]));
}

// The command line into \e o; false after --help, the usage printed.
bool parse(int argc, char **argv, Options &o)
{
  // One option: false for an option this tutorial does not know.
  const auto option = [&](const std::string &a, const auto &value) {
    if (a == "--stand-off") {
      o.standOff = ssltut::parseNumber(a, value(), 0.5, 2.);
    } else if (a == "--start") {
      o.cMo = parsePose(a, value());
    } else if (a == "--iterations") {
      o.iterations = static_cast<long>(ssltut::parseInteger(a, value(), 1, 100000));
    } else if (a == "--error") {
      o.error = ssltut::parseNumber(a, value(), 0., 1e3);
      if (o.error <= 0.) {
        throw ssltut::UsageError("--error: expected a number > 0");
      }
    } else if (a == "--small") {
      o.small = true;
    } else if (a == "--seed") {
      o.seed = static_cast<long>(ssltut::parseInteger(a, value(), 0, 100000));
    } else if (a == "--display") {
      o.display = true;
    } else if (a == "--output-dir") {
      o.outputDir = value();
      if (o.outputDir.empty()) {
        throw ssltut::UsageError("--output-dir: empty folder name");
      }
    } else if (a == "--save-every") {
      o.saveEvery = static_cast<long>(ssltut::parseInteger(a, value(), 1, 100000));
    } else {
      return false;
    }
    return true;
  };
  return ssltut::readOptions(argc, argv, kUsage, ssltut::OptionStyle::ReadAll, option);
}

// The image, the tracked landmarks, the target frame and the state, for the window or the PNGs.
void annotate(const vpImage<unsigned char> &I, vpSSLTracker &tracker, const vpCameraParameters &cam, long iter,
              double error, vpImage<vpRGBa> &out)
{
  vpImageConvert::convert(I, out);
  for (const vpSSLLandmark &l : tracker.getDetector().getLandmarks()) {
    vpImageDraw::drawCross(out, l.getCenter(), 12, vpColor::green, 2);
  }
  if (tracker.hasPose()) {
    vpImageDraw::drawFrame(out, tracker.getPose(), cam, 0.1, vpColor::none, 2);
  }
  char text[96];
  std::snprintf(text, sizeof(text), "iteration %ld  task error %.4f", iter, error);
  const vpFont font(16, vpFont::GENERIC_MONOSPACE);
  font.drawText(out, text, vpImagePoint(8, 8), vpColor::yellow, vpColor::black);
}
} // namespace

int main(int argc, char **argv)
{
  return ssltut::guardedMain(kProgram, [&]() -> int {
    Options o;
    if (!parse(argc, argv, o)) {
      return 0; // --help
    }

    // The camera: the project's default 640x480 camera, or the same field of view at 320x240.
    unsigned int width = 0, height = 0;
    const vpCameraParameters cam = ssltut::defaultCamera(width, height, o.small);

    vpImage<unsigned char> I(height, width);
    vpImage<vpRGBa> annotated(height, width);
    std::unique_ptr<vpDisplay> window;
    if (o.display) {
      window = ssltut::openDisplay(annotated, kProgram, kProgram,
                                   "writing annotated images instead (--output-dir, default ssl-ibvs)");
      if (window == nullptr && o.outputDir.empty()) {
        o.outputDir = "ssl-ibvs";
      }
    }
    if (!o.outputDir.empty() && !vpIoTools::checkDirectory(o.outputDir)) {
      vpIoTools::makeDirectory(o.outputDir);
    }

    // The scene: the printed target, rendered at the simulated camera pose.
    const vpSSLTarget target = vpSSLTarget::ssl3a3();
    vpSSLRenderer renderer(cam, width, height);
    renderer.setTarget(target);
    renderer.setSupersampling(1);

    // ViSP's free-flying camera; the world frame is the camera's start, so the target stays at wMo.
    vpSimulatorCamera robot;
    robot.setSamplingTime(0.04);
    vpHomogeneousMatrix wMc;
    robot.getPosition(wMc);
    const vpHomogeneousMatrix wMo = wMc * o.cMo;

    // The tracker takes the robot's pose as odometry (camera = vehicle: identity mounting).
    vpSSLTracker tracker(target, cam);
    tracker.setSeed(o.seed);

    // The law, set for a robot that moves the camera itself: the command is the camera twist.
    vpSSLServoLaw law;
    law.setCameraRobot();
    law.setStandOff(o.standOff);
    vpColVector vmax(6, 0.5); // m/s and rad/s, within vpSimulatorCamera's own caps
    law.setVelocityLimits(vmax);
    law.setGain(2., 0.5, 30.); // a camera that follows every twist at once takes more gain than a vehicle

    double error = HUGE_VAL;
    long iter = 0;
    bool converged = false;
    for (; iter < o.iterations && !converged; ++iter) {
      robot.getPosition(wMc);
      const vpHomogeneousMatrix cMo = wMc.inverse() * wMo;
      renderer.render(cMo, I);
      tracker.track(I, wMc);

      const vpSSLServoInput input = vpSSLServoInput::fromTracker(tracker);
      law.computeControlLaw(input);
      vpColVector v(6, 0.);
      if (law.getStatus() == SSL_SERVO_OK) {
        v = law.getCameraVelocity();
        error = std::sqrt(law.getError().sumSquare());
        converged = error < o.error;
      }
      robot.setVelocity(vpRobot::CAMERA_FRAME, v);

      const bool save = !o.outputDir.empty() && (iter % o.saveEvery == 0 || converged || iter + 1 == o.iterations);
      if (window != nullptr || save) {
        annotate(I, tracker, cam, iter, error, annotated);
      }
      if (window != nullptr) {
        vpDisplay::display(annotated);
        vpDisplay::displayText(annotated, 30, 8, "click to stop", vpColor::red);
        vpDisplay::flush(annotated);
        if (vpDisplay::getClick(annotated, false)) {
          ++iter;
          break;
        }
      }
      if (save) {
        char name[32];
        std::snprintf(name, sizeof(name), "/%06ld.png", iter);
        vpImageIo::write(annotated, o.outputDir + name);
      }
      if (iter % 25 == 0) {
        std::cout << "iteration " << iter << " t " << iter * 0.04 << " s landmarks " << tracker.getNbLandmarks()
                  << " servo " << vpSSLServoLaw::getStatusName(law.getStatus()) << " task error " << error << std::endl;
      }
    }

    // The true errors of the pose reached (the simulation knows it): camera facing the target centre at Z*.
    robot.getPosition(wMc);
    const vpHomogeneousMatrix cMo = wMc.inverse() * wMo;
    double x = 0., y = 0., Z = 0.;
    vpSSLServoLaw::getTargetCentre(vpSSLServoInput::fromPose(target.getPoints(), cMo), x, y, Z);
    const vpThetaUVector tu(cMo.getRotationMatrix());
    std::printf("final: %s after %ld iterations (%.2f s): task error %.5f; range error %.1f mm, lateral error "
                "%.1f mm, rotation error %.2f deg\n",
                converged ? "converged" : "not converged", iter, iter * 0.04, error, 1000. * (Z - o.standOff),
                1000. * Z * std::hypot(x, y), vpMath::deg(std::sqrt(tu.sumSquare())));
    if (!converged) {
      std::cerr << kProgram << ": the task error did not fall below " << o.error << " within " << iter << " iterations"
                << std::endl;
      return 1;
    }
    return 0;
  });
}

//! \example tutorial-ssl-detector-live.cpp
//! ViSP's tutorial-apriltag-detector-live.cpp with the SSL target: frames from a camera (vpV4l2Grabber, or
//! cv::VideoCapture for any other device) or a video file, tracked with vpSSLTracker, the pose drawn with
//! vpDisplay::displayFrame, range and tracker state on screen, click to quit.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include <visp3/core/vpConfig.h>
#include <visp3/core/vpIoTools.h>
#include <visp3/core/vpTime.h>
#include <visp3/ssl/vpSSLTracker.h>
#ifdef VISP_HAVE_V4L2
#include <visp3/sensor/vpV4l2Grabber.h>
#endif

#include "ssl_tutorial_camera_options.h"
#include "ssl_tutorial_canvas.h"
#include "ssl_tutorial_common.h"
#include "ssl_tutorial_input.h"
#include "ssl_tutorial_option_loop.h"

namespace {
const char *kProgram = "tutorial-ssl-detector-live";

const char *kUsage = R"(Usage: tutorial-ssl-detector-live [options]

Tracks the target live, as ViSP's tutorial-apriltag-detector-live: each frame goes through
vpSSLTracker (detection in regions of interest, particle filter, paper Sec. 3.3); the window shows
the target's frame (vpDisplay::displayFrame) when its orientation is known, the detected
landmarks, the range and the tracker state. Click in the window to quit.

Options:
  --input SOURCE        /dev/videoN: a V4L2 camera through vpV4l2Grabber; N (a number): camera N
                        through cv::VideoCapture (OpenCV's V4L2 backend, which also decodes MJPG
                        cameras); anything else: a video file (.avi, .mp4, ... whatever OpenCV's
                        FFmpeg decodes) read to its end.
                        Default: /dev/video0.
  --intrinsic FILE      Camera parameters, ViSP XML (default: DATA/camera/camera-640x480.xml; use
                        your camera's calibration, ranges scale with its focal length).
  --camera-name NAME    Camera name inside the XML file (default: Camera).
  --target NAME|FILE    Built-in target name or target file (default: ssl3-a3).
  --max-frames N        Stop after N frames, 1 to 1000000000 (default: a camera until the click,
                        a video to its end).
  --output DIR          Without an X display, every annotated frame goes to DIR/%06d.png
                        (default: ssl-detector-live; DIR must not be an existing file).
  --help, -h            This help.

DATA is $VISP_SSL_DATA_DIR if set, else share/visp_ssl of the installed tree the program runs
from, else the source tree's data/.

Prints one line per frame (frame, state, range in m, landmarks) and a summary on stderr.

Exit status: 0 when every frame was read to the end of the video, the frame limit or the click,
1 when the camera or the video cannot be opened, a video ends before the frame count its header
announces or a frame cannot be decoded (the frames before it are processed), an annotated frame
cannot be written, or any other runtime failure; 2 on a bad option, camera file or target. Every
error is one line on stderr.
)";

int run(int argc, char **argv)
{
  const std::string data = ssltut::dataDir();
  std::string opt_input = "/dev/video0";
  ssltut::CameraTargetOptions camera(data + "/camera/camera-640x480.xml", "--intrinsic", "--camera-name");
  std::string output_dir = "ssl-detector-live";
  long max_frames = -1;

  // One option: false for an option this tutorial does not know.
  const auto option = [&](const std::string &a, const auto &value) {
    if (a == "--input") {
      opt_input = value();
    } else if (camera.parseCameraOption(a, value)) {
    } else if (a == "--max-frames") {
      max_frames = static_cast<long>(ssltut::parseInteger(a, value(), 1, 1000000000));
    } else if (a == "--output") {
      output_dir = value();
    } else {
      return false;
    }
    return true;
  };
  if (!ssltut::readOptions(argc, argv, kUsage, ssltut::OptionStyle::HelpFirst, option)) {
    return 0; // --help
  }

  vpCameraParameters cam;
  vpSSLTarget target;
  ssltut::loadCameraAndTarget(camera.cameraFile, camera.cameraName, camera.targetName, cam, target);

  // The grabber: ViSP's V4L2 grabber for /dev/video*, OpenCV for the rest (other cameras, video files).
  vpImage<unsigned char> I;
  const bool v4l2 = opt_input.rfind("/dev/video", 0) == 0;
#ifdef VISP_HAVE_V4L2
  vpV4l2Grabber g;
#endif
  ssltut::VideoInput video;
  if (v4l2) {
#ifdef VISP_HAVE_V4L2
    // vpV4l2Grabber keeps the device name in a fixed buffer.
    if (opt_input.size() > 255) {
      throw ssltut::UsageError("--input: device name longer than 255 bytes");
    }
    // vpV4l2Grabber prints its own line on a missing device before it throws.
    if (!std::filesystem::exists(opt_input)) {
      std::cerr << kProgram << ": " << opt_input << ": cannot open the camera: no such device" << std::endl;
      return EXIT_FAILURE;
    }
    std::cout << "Use Video 4 Linux grabber on device " << opt_input << std::endl;
    g.setDevice(opt_input);
    g.setScale(1);
    try {
      g.open(I);
      g.acquire(I);
    } catch (const vpException &e) {
      std::cerr << kProgram << ": " << opt_input << ": cannot open the camera: " << e.getStringMessage() << std::endl;
      return EXIT_FAILURE;
    }
#else
    throw ssltut::UsageError("--input: " + opt_input + ": this ViSP has no V4L2 grabber; give the camera's number");
#endif
  } else {
    try {
      video.open(opt_input);
      if (!video.read(I)) {
        throw vpException(vpException::ioError, "%s: no frame", opt_input.c_str());
      }
    } catch (const vpException &e) {
      std::cerr << kProgram << ": " << e.getStringMessage() << std::endl;
      return EXIT_FAILURE;
    }
    std::cout << "Use OpenCV grabber on " << (video.isCamera() ? "camera " : "video ") << opt_input << std::endl;
  }

  std::cout << cam << std::endl;
  std::cout << "Target: " << target.getName() << " (" << target.size() << " landmarks)" << std::endl;

  ssltut::Canvas d(kProgram, output_dir); // without an X display, the drawings go to output_dir

  vpSSLTracker tracker(target, cam);
  const double axis = target.getMaxRadius();

  int status = EXIT_SUCCESS;
  long frame = 0, nbWithPose = 0;
  double totalMs = 0.;
  bool quit = false;
  while (!quit) {
    const double t = vpTime::measureTimeMs();
    const vpSSLTrackerState state = tracker.track(I);
    const double dt = vpTime::measureTimeMs() - t;
    totalMs += dt;

    d.display(I);
    vpSSLDetector &detector = tracker.getDetector();
    for (size_t i = 0; i < detector.getNbObjects(); ++i) {
      d.polygon(detector.getPolygon(i), vpColor::cyan, 1);
    }
    std::ostringstream ss;
    ss << "Frame " << frame << ": " << vpSSLTrackerStateName(state);
    if (tracker.hasPose()) {
      const vpHomogeneousMatrix cMo = tracker.getPose();
      ss << ", range " << vpMath::round(cMo.getTranslationVector().frobeniusNorm() * 100.) / 100. << " m";
      if (tracker.getOrientationKnown()) {
        d.frame(cMo, cam, axis, vpColor::none, 3);
        ++nbWithPose;
      } else {
        ss << " (position only)";
      }
    }
    ss << ", " << tracker.getNbLandmarks() << " landmark(s), " << vpMath::round(dt) << " ms";
    d.text(vpImagePoint(20, 20), ss.str(), vpColor::red);
    d.text(vpImagePoint(40, 20), "Click to quit.", vpColor::red);
    std::cout << ss.str() << std::endl;
    try {
      quit = d.show(ssltut::expandPattern("%06d.png", frame), false) && d.hasWindow();
    } catch (const vpException &e) {
      std::cerr << kProgram << ": " << e.getStringMessage() << std::endl;
      status = EXIT_FAILURE;
      break;
    }
    ++frame;
    if (max_frames >= 0 && frame >= max_frames) {
      break;
    }
    try {
#ifdef VISP_HAVE_V4L2
      if (v4l2) {
        g.acquire(I);
        continue;
      }
#endif
      if (!video.read(I)) {
        break;
      }
    } catch (const vpException &e) {
      std::cerr << kProgram << ": " << e.getStringMessage() << std::endl;
      status = EXIT_FAILURE;
      break;
    }
  }
  std::cerr << kProgram << ": " << frame << " frame(s), full pose in " << nbWithPose << ", "
            << (frame > 0 ? totalMs / frame : 0.) << " ms per frame"
            << (d.hasWindow() ? std::string() : ", annotated frames in " + output_dir + "/") << std::endl;
  return status;
}
} // namespace

int main(int argc, char **argv)
{
  return ssltut::guardedMain(kProgram, [&] { return run(argc, argv); });
}

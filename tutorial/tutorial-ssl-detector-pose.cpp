//! \example tutorial-ssl-detector-pose.cpp
//! ViSP's tutorial-apriltag-detector.cpp with vpSSLDetector in place of vpDetectorAprilTag: the same steps in the
//! same order (options, camera, read, detect with the pose, draw the objects, click, draw the pose, click).
#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <visp3/core/vpImageConvert.h>
#include <visp3/core/vpIoTools.h>
#include <visp3/core/vpTime.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl_io/vpSSLImageIo.h>

#include "ssl_tutorial_camera_options.h"
#include "ssl_tutorial_canvas.h"
#include "ssl_tutorial_common.h"
#include "ssl_tutorial_input.h"
#include "ssl_tutorial_option_loop.h"

namespace {
const char *kProgram = "tutorial-ssl-detector-pose";

const char *kUsage = R"(Usage: tutorial-ssl-detector-pose [options]

ViSP's tutorial-apriltag-detector with vpSSLDetector: detects the target in one image, draws each
landmark's box and label, then, after a click, the target's frame from
vpSSLDetector::detect(I, cam, cMo_vec). The options keep the names of ViSP's tutorial; the landmark
sizes come from the target, so there is no --tag_size.

Options:
  --input FILE          Image (default: DATA/images/ssl3-a3-00.png).
  --intrinsic FILE      Camera parameters, ViSP XML (default: DATA/camera/camera-640x480.xml, the
                        camera the sample images were rendered with).
  --camera_name NAME    Camera name inside the XML file (default: Camera).
  --target NAME|FILE    Built-in target name or target file, in place of --tag_family
                        (default: ssl3-a3).
  --window W            Window length of the matching function, an integer in [2, 128], in place
                        of --quad_decimate (default 40).
  --small_landmarks     Small-landmark mode (landmarks down to ~8 px of radius).
  --nthreads N          Worker threads of the matching function, 0 to 256 (0: all cores; default 0).
  --display_tag         Also draw each landmark's outline (vpDetectorBase::getPolygon()).
  --color N             Colour of the outlines, vpColor::getColor(N), 0 to 17 (default: red).
  --thickness N         Line thickness, 1 to 20 (default 2).
  --output DIR          Without an X display, the two drawings go to DIR/detections.png and
                        DIR/pose.png (default: ssl-detector-pose; DIR must not be an existing file).
  --help, -h            This help.

DATA is $VISP_SSL_DATA_DIR if set, else share/visp_ssl of the installed tree the program runs
from, else the source tree's data/.

Exit status: 0 when the image was read (whether or not the target was found), 1 when it cannot be
read or a drawing cannot be written, 2 on a bad option, camera file or target. Every error is one
line on stderr.
)";

int run(int argc, char **argv)
{
  const std::string data = ssltut::dataDir();
  std::string input_filename = data + "/images/ssl3-a3-00.png";
  unsigned int window = 40;
  bool small_landmarks = false;
  unsigned int nThreads = 0;
  ssltut::CameraTargetOptions camera(data + "/camera/camera-640x480.xml", "--intrinsic", "--camera_name");
  bool display_tag = false;
  int color_id = -1;
  unsigned int thickness = 2;
  std::string output_dir = "ssl-detector-pose";

  // One option: false for an option this tutorial does not know.
  const auto option = [&](const std::string &a, const auto &value) {
    if (a == "--input") {
      input_filename = value();
    } else if (camera.parseCameraOption(a, value)) {
    } else if (a == "--window") {
      window = static_cast<unsigned int>(ssltut::parseInteger(a, value(), 2, 128));
    } else if (a == "--small_landmarks") {
      small_landmarks = true;
    } else if (a == "--nthreads") {
      nThreads = ssltut::parseThreads(a, value(), true, 256);
    } else if (a == "--display_tag") {
      display_tag = true;
    } else if (a == "--color") {
      color_id = static_cast<int>(ssltut::parseInteger(a, value(), 0, vpColor::nbColors - 1));
    } else if (a == "--thickness") {
      thickness = static_cast<unsigned int>(ssltut::parseInteger(a, value(), 1, 20));
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

  std::cout << "Input: " << input_filename << std::endl;
  std::cout << cam << std::endl;
  std::cout << "target: " << target.getName() << std::endl;
  std::cout << "window: " << window << std::endl;
  std::cout << "nThreads : " << nThreads << std::endl;

  vpImage<unsigned char> I;
  vpSSLImageIo::read(I, input_filename);

  ssltut::Canvas d(kProgram, output_dir); // without an X display, the drawings go to output_dir

  vpSSLDetector detector(target);

  detector.setWindow(window);
  detector.setSmallLandmarkMode(small_landmarks);
  detector.setNbThreads(nThreads);
  const vpColor color = color_id < 0 ? vpColor::red : vpColor::getColor(static_cast<unsigned int>(color_id));

  d.display(I);

  double t = vpTime::measureTimeMs();
  std::vector<vpHomogeneousMatrix> cMo_vec;
  std::vector<vpTranslationVector> positions; // a range without an orientation (one or two landmarks seen)
  detector.detect(I, cam, cMo_vec, nullptr, nullptr, nullptr, &positions);
  t = vpTime::measureTimeMs() - t;

  std::stringstream ss;
  ss << "Detection time: " << t << " ms for " << detector.getNbObjects() << " landmarks";
  d.text(vpImagePoint(40, 20), ss.str(), vpColor::red);

  for (size_t i = 0; i < detector.getNbObjects(); i++) {
    std::vector<vpImagePoint> p = detector.getPolygon(i);
    vpRect bbox = detector.getBBox(i);
    d.rectangle(bbox, vpColor::green);
    if (display_tag) {
      d.polygon(p, color, thickness);
    }
    std::string message = detector.getMessage(i);
    d.text(vpImagePoint(bbox.getTop() - 10, bbox.getLeft()), message, vpColor::red);
    d.cross(detector.getCog(i), 14, vpColor::red, 3);
  }

  d.text(vpImagePoint(20, 20), "Click to display the target pose", vpColor::red);
  d.show("detections.png", true);

  d.display(I);

  // The frame's axes are as long as the biggest landmark's radius, as ViSP's are half the tag.
  const double axis = target.getMaxRadius();
  for (size_t i = 0; i < cMo_vec.size(); i++) {
    d.frame(cMo_vec[i], cam, axis, vpColor::none, 3);
    std::cout << "cMo:\n" << cMo_vec[i] << std::endl;
  }
  for (const vpTranslationVector &c : positions) {
    std::cout << "position only (landmark centre, m): " << c.t() << std::endl;
  }
  if (cMo_vec.empty()) {
    d.text(vpImagePoint(40, 20), positions.empty() ? "No target" : "Position only: too few landmarks for a pose",
           vpColor::red);
  }

  d.text(vpImagePoint(20, 20), "Click to quit.", vpColor::red);
  d.show("pose.png", true);
  if (!d.hasWindow()) {
    std::cerr << kProgram << ": " << (cMo_vec.empty() ? "no pose" : "pose") << ", drawings in " << output_dir << "/"
              << std::endl;
  }
  return EXIT_SUCCESS;
}
} // namespace

int main(int argc, char **argv)
{
  return ssltut::guardedMain(kProgram, [&] { return run(argc, argv); });
}

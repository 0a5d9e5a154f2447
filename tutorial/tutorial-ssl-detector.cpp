//! \example tutorial-ssl-detector.cpp
//! Detects circular self-similar landmarks and the ssl3-a3 target in an image or an image sequence.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include <visp3/core/vpImageConvert.h>
#include <visp3/core/vpImageDraw.h>
#include <visp3/core/vpIoTools.h>
#include <visp3/core/vpPixelMeterConversion.h>
#include <visp3/io/vpImageIo.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl/vpSSLInputLimits.h>
#include <visp3/ssl/vpSSLPoseEstimator.h>
#include <visp3/ssl_io/vpSSLCameraFile.h>
#include <visp3/ssl_io/vpSSLImageIo.h>

#include "ssl_tutorial_camera_options.h"
#include "ssl_tutorial_common.h"
#include "ssl_tutorial_input.h"
#include "ssl_tutorial_option_loop.h"

namespace {
const char *kUsage = R"(Usage: tutorial-ssl-detector --input IMAGE_OR_PATTERN_OR_VIDEO [options]

Detects circular self-similar landmarks (SSL) and identifies the target in each image.

Options:
  --input PATH        An image file (PNG, JPEG, PGM/PPM, BMP; at most 16384 px a side and
                      2^26 pixels, doc/input-limits.md), or a numbered sequence as a pattern
                      with one %d (e.g. images/%06d.png): from the first number found in
                      0..100000 to the first missing one, or a video file (.avi, .mp4, .mkv,
                      .mov, .m4v, .mpg, .mpeg, .webm; whatever OpenCV's FFmpeg decodes), read
                      to its end; its frames are named <video name>-<frame, 6 digits>. Required.
  --camera FILE       Camera parameters (ViSP XML, vpXmlParserCamera). Enables cMo (the best
                      P3P pose hypothesis when the target's three landmarks are seen, paper
                      Sec. 3.2) and range_m (|t| of that pose, else Eq. 6 from the radii).
  --camera-name NAME  Camera name inside the XML file (default: Camera).
  --target NAME|FILE  Built-in target name or target file (default: ssl3-a3).
  --json              Print one JSON object per image on standard output (JSON Lines,
                      doc/detection-json.md); everything else goes to stderr.
  --output DIR        Write annotated images DIR/<image name>.png (default when no window
                      is shown: ssl-detections; DIR must not be an existing file, the
                      input images' folder or inside a recorded sequence).
                      Outlines: B green, S1 cyan, S2 purple, landmarks outside the target
                      orange; red crosses at the centres.
  --display           Show the detections in a window (needs an X display; without one, a
                      one-line notice and the annotated images are written instead).
  --window W          Window length of the matching function, an integer in [2, 128]
                      (default 40).
  --small-landmarks   Small-landmark mode: matches on the image upsampled 2x with w = 20 (about
                      1.5 times the matching work of the default, whose short window already
                      reads from about 8 px of radius; doc/detector.md). Use it for targets at
                      the edge of the range.
  --no-equal-rings    Keep landmarks whose rings are better explained by rings of one width
                      (vpSSLDetector::setEqualRingCheck(false); on by default, doc/detector.md).
  --no-blur-model     Do not read faint blurred landmarks from their ring profile's blurred
                      model (vpSSLDetector::setBlurredRingModel(false); doc/detector.md).
  --no-target-completion
                      Do not read the target's missing landmarks where its big one puts them
                      (vpSSLDetector::setTargetCompletion(false); doc/detector.md).
  --all-around-budget N
                      Candidates per frame read all around where the rays give up, 0 to
                      100000 (default 24; vpSSLDetector::setAllAroundBudget(); more find a few
                      more faint small landmarks on noisy water, for more time per frame and
                      more false readings; doc/detector.md).
  --decimation D      1 (default) or 2: with 2, the matching function runs on the image
                      decimated twice (the fast mode, for landmarks of about 25 px and more),
                      the rings are still read at full resolution.
  --threshold T       Score threshold in [0, 1] on the matching value at a peak (default 0.07).
  --no-normalize      Switch brightness normalisation off (on by default, paper Fig. 13).
  --threads N         Worker threads for the matching function, 0 to 256 (default 0: all
                      cores).
  --max-frames N      Stop after N frames of a sequence, 0 to 1000000000 (default: all).
  --help              This help.

Exit status: 0 when every image was read and every annotated image written, 1 when an
image could not be read or an annotated image not written (the others are still
processed), when a video cannot be opened, has no frame, or ends before the frame count its
header announces (a truncated file, a frame that cannot be decoded: the frames before it are
processed), or on any other runtime failure, 2 on a bad option, camera file, target file or
output folder. Every error is one line on stderr.
)";

const char *kProgram = "tutorial-ssl-detector";

// A JSON string literal; bytes that are not UTF-8 (a file name in another encoding) become U+FFFD, so that every
// line stays valid JSON.
std::string jsonString(const std::string &s)
{
  return nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string num(double x, int digits)
{
  if (!std::isfinite(x)) {
    return "null";
  }
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", digits, x);
  return buf;
}

// The doc/detection-json.md record of one image.
std::string toJson(const std::string &name, const vpImage<unsigned char> &I, const vpSSLDetector &detector,
                   const vpSSLPoseEstimator &estimator, const vpCameraParameters *cam)
{
  std::ostringstream os;
  os << "{\"image\": " << jsonString(name) << ", \"width\": " << I.getWidth() << ", \"height\": " << I.getHeight()
     << ", \"time_ms\": " << num(detector.getTimes().total, 3) << ", \"landmarks\": [";
  const std::vector<vpSSLLandmark> &landmarks = detector.getLandmarks();
  for (size_t i = 0; i < landmarks.size(); ++i) {
    const vpSSLLandmark &l = landmarks[i];
    os << (i ? ", " : "") << "{\"u\": " << num(l.u, 2) << ", \"v\": " << num(l.v, 2)
       << ", \"radius_px\": " << num(l.radius, 2) << ", \"score\": " << num(l.score, 3) << "}";
  }
  os << "], \"target\": ";
  const vpSSLTargetMatch &match = detector.getTargetMatch();
  if (!match.found) {
    os << "{\"found\": false, \"n_landmarks\": 0}}";
    return os.str();
  }
  const vpSSLTarget &target = detector.getTarget();
  os << "{\"found\": true, \"n_landmarks\": " << match.nbMatched << ", \"landmarks\": {";
  bool first = true;
  double sx = 0., sy = 0., sz = 0.;
  for (size_t k = 0; k < target.size(); ++k) {
    const vpSSLLandmark *l = detector.getMatchedLandmark(k);
    if (l == nullptr) {
      continue;
    }
    os << (first ? "" : ", ") << jsonString(target.getLandmark(k).name) << ": [" << num(l->u, 2) << ", " << num(l->v, 2)
       << "]";
    first = false;
    if (cam != nullptr) {
      // Eq. 6 gives each landmark's depth; with the bearing of its centre, its position.
      double x, y;
      vpPixelMeterConversion::convertPoint(*cam, l->u, l->v, x, y);
      const double Z = vpSSLDetector::range(*l, target.getLandmark(k).radius, *cam);
      sx += x * Z;
      sy += y * Z;
      sz += Z;
    }
  }
  // Case 3 of the paper: a full pose, the hypothesis that best explains the landmarks' ellipses.
  bool havePose = false;
  vpHomogeneousMatrix cMo;
  if (cam != nullptr && match.nbMatched >= 3) {
    try {
      const std::vector<vpSSLPoseHypothesis> hypotheses = estimator.estimate(detector, *cam);
      havePose = !hypotheses.front().positionOnly;
      cMo = hypotheses.front().cMo;
    } catch (const vpException &e) {
      std::cerr << "tutorial-ssl-detector: " << name << ": no pose: " << e.getStringMessage() << std::endl;
    }
  }
  os << "}, \"cMo\": ";
  if (havePose) {
    os << "[";
    for (unsigned int i = 0; i < 16; ++i) {
      os << (i ? ", " : "") << num(cMo[i / 4][i % 4], 6);
    }
    os << "]";
  } else {
    os << "null";
  }
  os << ", \"range_m\": ";
  if (havePose) {
    os << num(cMo.getTranslationVector().frobeniusNorm(), 3);
  } else if (cam != nullptr) {
    // No pose (fewer than three landmarks): Eq. 6 distance to the centroid of the matched landmarks.
    const double n = match.nbMatched;
    os << num(std::sqrt(sx * sx + sy * sy + sz * sz) / n, 3);
  } else {
    os << "null";
  }
  os << "}}";
  return os.str();
}

void annotate(const vpImage<unsigned char> &I, vpSSLDetector &detector, vpImage<vpRGBa> &out)
{
  vpImageConvert::convert(I, out);
  // Unmatched landmarks in orange; the target's in one colour per label (B, S1, S2, ... in target order).
  const vpColor labelColors[] = {vpColor::green, vpColor::cyan, vpColor::purple, vpColor::yellow, vpColor::blue};
  for (size_t i = 0; i < detector.getNbObjects(); ++i) {
    vpColor color = vpColor::orange;
    for (size_t k = 0; k < detector.getTarget().size(); ++k) {
      if (detector.getMatchedLandmark(k) == &detector.getLandmarks()[i]) {
        color = labelColors[k % 5];
      }
    }
    vpImageDraw::drawPolygon(out, detector.getPolygon(i), color, 2, true);
    vpImageDraw::drawCross(out, detector.getLandmarks()[i].getCenter(), 10, vpColor::red, 1);
  }
}

[[noreturn]] void fail(const std::string &msg, int code)
{
  std::cerr << "tutorial-ssl-detector: " << msg << std::endl;
  std::exit(code);
}

// The first frame number of a numbered pattern (ViSP's vpVideoReader looks as far), or -1.
long firstFrame(const std::string &pattern)
{
  for (long i = 0; i <= 100000; ++i) {
    if (vpIoTools::checkFilename(ssltut::expandPattern(pattern, i))) {
      return i;
    }
  }
  return -1;
}

int run(int argc, char **argv)
{
  std::string input, outputDir;
  ssltut::CameraTargetOptions camera;
  bool json = false, display = false, normalize = true, smallLandmarks = false, equalRings = true, blurModel = true,
       completion = true;
  unsigned int window = 40, threads = 0, decimation = 1;
  double threshold = 0.07;
  long maxFrames = -1, allAroundBudget = -1; // -1: the detector's default
  // One option: false for an option this tutorial does not know.
  const auto option = [&](const std::string &a, const auto &value) {
    auto number = [&](const std::string &v) { return ssltut::parseNumber("option " + a, v); };
    auto integer = [&](const std::string &v, long long lo, long long hi) {
      return ssltut::parseInteger("option " + a, v, lo, hi);
    };
    if (camera.parseCameraOption(a, value)) {
    } else if (a == "--input") {
      input = value();
    } else if (a == "--json") {
      json = true;
    } else if (a == "--output") {
      outputDir = value();
    } else if (a == "--display") {
      display = true;
    } else if (a == "--window") {
      window = static_cast<unsigned int>(integer(value(), 2, 128));
    } else if (a == "--threshold") {
      threshold = number(value());
    } else if (a == "--small-landmarks") {
      smallLandmarks = true;
    } else if (a == "--no-equal-rings") {
      equalRings = false;
    } else if (a == "--no-blur-model") {
      blurModel = false;
    } else if (a == "--no-target-completion") {
      completion = false;
    } else if (a == "--all-around-budget") {
      allAroundBudget = static_cast<long>(integer(value(), 0, 100000));
    } else if (a == "--decimation") {
      decimation = static_cast<unsigned int>(integer(value(), 1, 2));
    } else if (a == "--no-normalize") {
      normalize = false;
    } else if (a == "--threads") {
      threads = ssltut::parseThreads("option " + a, value(), true, 256);
    } else if (a == "--max-frames") {
      maxFrames = static_cast<long>(integer(value(), 0, 1000000000));
    } else {
      return false;
    }
    return true;
  };
  if (!ssltut::readOptions(argc, argv, kUsage, ssltut::OptionStyle::HelpFirst, option)) {
    return 0; // --help
  }
  if (input.empty()) {
    fail("--input is required (see --help)", 2);
  }
  const bool isSequence = input.find('%') != std::string::npos;
  if (isSequence) {
    ssltut::checkPattern("--input", input);
  }
  const bool isVideo = !isSequence && ssltut::isVideoFile(input);
  vpImage<vpRGBa> annotated;
  std::unique_ptr<vpDisplay> window_;
  if (display) {
    // The window is opened on a placeholder first, so that a missing X server is told before any work.
    annotated.resize(480, 640, vpRGBa(0));
    window_ = ssltut::openDisplay(annotated, kProgram, kProgram,
                                  "writing annotated images instead (--output, default ssl-detections)");
    display = window_ != nullptr;
  }
  if (!display && outputDir.empty()) {
    outputDir = "ssl-detections";
  }
  // Nothing a user gave is overwritten: an existing file is not turned into a folder, nor written into.
  if (!outputDir.empty()) {
    // Annotated images are named after the input images: in the inputs' own folder they would replace them.
    ssltut::checkOutsideSequences("--output", outputDir);
    std::error_code ec;
    const std::filesystem::path inputFolder = std::filesystem::path(input).parent_path();
    if (!isVideo && std::filesystem::equivalent(outputDir, inputFolder.empty() ? "." : inputFolder, ec)) {
      fail("--output: " + outputDir + " is the folder of the input images: the annotated images would replace them", 2);
    }
    if (vpIoTools::checkFilename(outputDir) && !vpIoTools::checkDirectory(outputDir)) {
      fail("--output: " + outputDir + ": exists and is not a folder", 2);
    }
    try {
      vpIoTools::makeDirectory(outputDir);
    } catch (const vpException &e) {
      fail("--output: " + outputDir + ": cannot create the folder: " + e.getStringMessage(), 2);
    }
    if (!vpIoTools::checkDirectory(outputDir)) {
      fail("--output: " + outputDir + ": cannot create the folder", 2);
    }
  }

  // Everything the user gave is checked before the detector exists, so that an error exits cleanly.
  vpCameraParameters cam;
  bool haveCamera = false;
  vpSSLTarget target;
  try {
    target = vpSSLTarget::fromName(camera.targetName);
    vpSSLDetector check(target); // the settings' own checks, with their messages
    check.setWindow(window);
    check.setThreshold(threshold);
    check.setDecimation(decimation);
    if (!camera.cameraFile.empty()) {
      cam = vpSSLCameraFile::load(camera.cameraFile, camera.cameraName);
      haveCamera = true;
    }
  } catch (const vpException &e) {
    fail(e.getStringMessage(), 2);
  }
  vpSSLDetector detector(target);
  const vpSSLPoseEstimator estimator(target);
  detector.setWindow(window);
  detector.setThreshold(threshold);
  detector.setSmallLandmarkMode(smallLandmarks);
  detector.setEqualRingCheck(equalRings);
  detector.setBlurredRingModel(blurModel);
  detector.setTargetCompletion(completion);
  if (allAroundBudget >= 0) {
    detector.setAllAroundBudget(static_cast<unsigned int>(allAroundBudget));
  }
  detector.setDecimation(decimation);
  detector.setBrightnessNormalization(normalize);
  detector.setNbThreads(threads);

  vpImage<unsigned char> I;
  int status = 0;
  long frame = 0, nbFound = 0, nbWritten = 0;
  long index = 0;
  if (isSequence) {
    index = firstFrame(input);
    if (index < 0) {
      std::cerr << "tutorial-ssl-detector: " << input << ": cannot open sequence: no file for any number in 0..100000"
                << std::endl;
      return 1;
    }
  }
  ssltut::VideoInput video;
  if (isVideo) {
    try {
      video.open(input);
    } catch (const vpException &e) {
      std::cerr << "tutorial-ssl-detector: " << e.getStringMessage() << std::endl;
      return 1;
    }
  }
  for (bool done = false; !done; ++frame) {
    std::string name, path = input;
    if (isVideo) {
      if (maxFrames >= 0 && frame >= maxFrames) {
        break;
      }
      // A frame that cannot be decoded ends the video: there is no next frame to go on with.
      try {
        if (!video.read(I)) {
          break;
        }
      } catch (const vpException &e) {
        std::cerr << "tutorial-ssl-detector: " << e.getStringMessage() << std::endl;
        status = 1;
        break;
      }
      name = vpIoTools::getNameWE(input) + ssltut::expandPattern("-%06d", frame);
    } else if (isSequence) {
      path = ssltut::expandPattern(input, index++);
      if (!vpIoTools::checkFilename(path) || (maxFrames >= 0 && frame >= maxFrames)) {
        break;
      }
    } else {
      done = true;
    }
    // vpSSLImageIo checks the header's size before decoding and says why an image cannot be read (ViSP's PNG
    // reader trusts the header and leaks on a corrupt file).
    try {
      if (!isVideo) {
        name = vpIoTools::getName(path);
        vpSSLImageIo::read(I, path);
      }
      vpSSLInputLimits::checkImage(I, name.c_str());
    } catch (const vpException &e) {
      std::cerr << "tutorial-ssl-detector: " << e.getStringMessage() << std::endl;
      if (json) {
        std::cout << "{\"image\": " << jsonString(name) << ", \"error\": " << jsonString(e.getStringMessage()) << "}"
                  << std::endl;
      }
      status = 1;
      continue;
    }
    try {
      detector.detect(I);
    } catch (const vpException &e) {
      std::cerr << "tutorial-ssl-detector: " << name << ": " << e.getStringMessage() << std::endl;
      if (json) {
        std::cout << "{\"image\": " << jsonString(name) << ", \"error\": " << jsonString(e.getStringMessage()) << "}"
                  << std::endl;
      }
      status = 1;
      continue;
    }
    nbFound += detector.getTargetMatch().found ? 1 : 0;
    if (json) {
      std::cout << toJson(name, I, detector, estimator, haveCamera ? &cam : nullptr) << std::endl;
    }
    annotate(I, detector, annotated);
    if (display) {
      // The window was opened on a placeholder: it follows the image's size.
      if (window_->getWidth() != annotated.getWidth() || window_->getHeight() != annotated.getHeight()) {
        window_.reset(new vpDisplayX(annotated, vpDisplay::SCALE_AUTO));
        vpDisplay::setTitle(annotated, kProgram);
      }
      vpDisplay::display(annotated);
      vpDisplay::flush(annotated);
    }
    if (!outputDir.empty()) {
      const std::string base = isVideo ? name : name.substr(0, name.find_last_of('.'));
      const std::string out = outputDir + "/" + base + ".png";
      try {
        if (vpIoTools::checkDirectory(out)) {
          throw vpException(vpException::ioError, "is a folder");
        }
        vpImageIo::write(annotated, out);
        ++nbWritten;
      } catch (const vpException &e) {
        std::cerr << "tutorial-ssl-detector: " << out << ": cannot write the annotated image: " << e.getStringMessage()
                  << std::endl;
        status = 1;
      }
    }
    if (!json) {
      std::cerr << name << ": " << detector.getLandmarks().size() << " landmark(s), target "
                << (detector.getTargetMatch().found
                        ? "found (" + std::to_string(detector.getTargetMatch().nbMatched) + " landmarks)"
                        : std::string("not found"))
                << ", " << num(detector.getTimes().total, 2) << " ms" << std::endl;
    }
  }
  std::cerr << "tutorial-ssl-detector: " << frame << " image(s), target found in " << nbFound
            << (outputDir.empty() ? "" : ", " + std::to_string(nbWritten) + " annotated image(s) in " + outputDir + "/")
            << std::endl;
  std::cout.flush();
  if (!std::cout) {
    std::cerr << "tutorial-ssl-detector: standard output: write error" << std::endl;
    status = 1;
  }
  return status;
}
} // namespace

int main(int argc, char **argv)
{
  return ssltut::guardedMain(kProgram, [&] { return run(argc, argv); });
}

//! \example tutorial-ssl-record.cpp
//! Records a sequence (doc/sequence-format.md) from a video file, a numbered image pattern or a camera, with the
//! camera's intrinsics and the vehicle's odometry interpolated to the image times (doc/recordings.md).
#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include <opencv2/core/utils/logger.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include <visp3/core/vpImageConvert.h>
#include <visp3/ssl/vpSSLInputLimits.h>
#include <visp3/ssl_io/vpSSLCameraFile.h>
#include <visp3/ssl_io/vpSSLImageIo.h>
#include <visp3/ssl_io/vpSSLOdometryTrack.h>
#include <visp3/ssl_io/vpSSLSequenceWriter.h>

#include "ssl_recording_common.h"
#include "ssl_tutorial_common.h"
#include "ssl_tutorial_option_loop.h"

namespace {
const char *kUsage = R"(Usage: tutorial-ssl-record --input VIDEO|PATTERN|DEVICE --camera XML --output DIR [options]

Records a sequence (doc/sequence-format.md) that tutorial-ssl-tracker and tutorial-ssl-vs-apriltag
read as they read a simulated one: the images of a video file, of a numbered image pattern or of a
camera, the camera's intrinsics and, with --odometry, the vehicle's poses interpolated to each
image's time. Without ground truth those report detection rates, ranges, tracker states and times.
See doc/recordings.md.

Options:
  --input SRC           What to record. Required. One of:
                          a video file OpenCV reads (.avi, .mp4, ...);
                          a numbered image pattern with one %d (frames/%06d.png), read from
                          --first on until a number is missing;
                          a camera: /dev/videoN, or its number N.
  --camera XML          ViSP camera file (vpXmlParserCamera) of the camera that took the images.
                        Required. When it states an image size, the images must have it.
  --camera-name NAME    Camera in XML (default Camera).
  --output DIR          Sequence folder written. Required. It must not exist or be empty: nothing
                        is overwritten.
  --odometry CSV        Vehicle poses oMv at their own times (doc/recordings.md): a header
                        t,tx,ty,tz,tux,tuy,tuz (theta-u) or t,tx,ty,tz,qx,qy,qz,qw (quaternion),
                        then one row per pose, times increasing. They must cover the time of
                        every image (no extrapolation). Needs --camera-to-vehicle.
  --camera-to-vehicle "TX TY TZ TUX TUY TUZ"
                        vMc, the camera's pose in the vehicle frame (m, theta-u rad), for
                        sequence.json. Required with --odometry; without, 0 0 0 0 0 0 is written
                        (the tracker uses it only with odometry).
  --target NAME         Target of sequence.json (default ssl3-a3; an AprilTag sheet name or a
                        target file, doc/sequence-format.md).
  --rate HZ             Frames per second of a video or a pattern: image i is at time
                        --start-time + i / HZ. A video's default is the rate its file states;
                        a pattern needs it. A camera's images are at the clock's time (seconds
                        since 1970), as the odometry of the same vehicle should be.
  --start-time T        Time of the first image of a video or pattern, in the odometry's clock
                        (s, default 0).
  --first N             First number of a pattern (default 0).
  --frames N            Record N frames, 1 to 100000000; a video or pattern that ends before is
                        an error. Default: every frame (a camera: until Ctrl-C).
  --help                This help.

Exit status: 0 on success (also after Ctrl-C: the frames written are a valid sequence); 1 when an
input cannot be read: a missing file, a camera that cannot be opened, a video that ends before
--frames or before the frame count it states, odometry that is malformed, out of order or does not
cover an image, a camera XML for another image size, an output folder that is not empty, a write
error. The frames written before such an error are a valid sequence. 2 on a bad option. Every
error is one line on stderr.
)";

const char *kProgram = "tutorial-ssl-record";

std::atomic<bool> g_interrupted(false);
void onInterrupt(int)
{
  g_interrupted = true;
}

bool isDevice(const std::string &input)
{
  return input.rfind("/dev/", 0) == 0 || (!input.empty() && input.find_first_not_of("0123456789") == std::string::npos);
}

int run(int argc, char **argv)
{
  std::string input, cameraXml, cameraName = "Camera", odometryCsv;
  ssltut::RecordingOptions recording;
  double rate = 0., startTime = 0.;
  long long first = 0, frames = -1;
  // One option: false for an option this tutorial does not know.
  const auto option = [&](const std::string &a, const auto &value) {
    if (recording.parse(a, value)) {
    } else if (a == "--input") {
      input = value();
    } else if (a == "--camera") {
      cameraXml = value();
    } else if (a == "--camera-name") {
      cameraName = value();
    } else if (a == "--odometry") {
      odometryCsv = value();
    } else if (a == "--rate") {
      rate = ssltut::parseNumber("option " + a, value(), 1e-3, 1e6);
    } else if (a == "--start-time") {
      startTime = ssltut::parseNumber("option " + a, value(), 0., 1e10);
    } else if (a == "--first") {
      first = ssltut::parseInteger("option " + a, value(), 0, 1000000000);
    } else if (a == "--frames") {
      frames = ssltut::parseInteger("option " + a, value(), 1, 100000000);
    } else {
      return false;
    }
    return true;
  };
  if (!ssltut::readOptions(argc, argv, kUsage, ssltut::OptionStyle::HelpFirst, option)) {
    return 0; // --help
  }
  if (input.empty() || cameraXml.empty() || recording.output.empty()) {
    throw ssltut::UsageError("--input, --camera and --output are required (see --help)");
  }
  recording.checkMount(!odometryCsv.empty(), "--odometry");
  const bool device = isDevice(input), pattern = !device && input.find('%') != std::string::npos;
  if (pattern) {
    ssltut::checkPattern("option --input", input);
    if (rate <= 0.) {
      throw ssltut::UsageError("--rate is required with an image pattern (its images carry no time)");
    }
  }

  // Everything the user gave is checked before the first image is written.
  ssltut::checkNewOutput(recording.output);
  unsigned int xmlWidth = 0, xmlHeight = 0;
  const vpCameraParameters cam = vpSSLCameraFile::load(cameraXml, cameraName, &xmlWidth, &xmlHeight);
  vpSSLOdometryTrack odometry;
  if (!odometryCsv.empty()) {
    odometry = vpSSLOdometryTrack::load(odometryCsv);
  }

  cv::VideoCapture capture;
  long long expected = -1; // frames a video states it has
  if (device) {
    // OpenCV's own warning about a camera it cannot open would be a second line on stderr.
    cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
    const bool opened =
        input.rfind("/dev/", 0) == 0
            ? capture.open(input, cv::CAP_V4L2)
            : capture.open(static_cast<int>(ssltut::parseInteger("option --input", input, 0, 1000)), cv::CAP_V4L2);
    if (!opened) {
      throw vpException(vpException::ioError, "%s: cannot open the camera", input.c_str());
    }
  } else if (!pattern) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(input, ec)) {
      throw vpException(vpException::ioError, "%s: no such video file", input.c_str());
    }
    if (!capture.open(input, cv::CAP_ANY)) {
      throw vpException(vpException::ioError, "%s: cannot open as a video (format or codec unknown to OpenCV)",
                        input.c_str());
    }
    expected = static_cast<long long>(capture.get(cv::CAP_PROP_FRAME_COUNT));
    if (rate <= 0.) {
      rate = capture.get(cv::CAP_PROP_FPS);
      if (!(rate > 0.) || !std::isfinite(rate)) {
        throw vpException(vpException::ioError, "%s: the video states no frame rate: give --rate", input.c_str());
      }
    }
  }

  std::signal(SIGINT, onInterrupt);
  vpSSLSequenceWriter writer;
  const std::chrono::system_clock::time_point epoch;
  cv::Mat image;
  double firstTime = 0.;
  long long n = 0;
  while ((frames < 0 || n < frames) && !g_interrupted) {
    // The next image, or the end of the input.
    bool got;
    if (pattern) {
      const std::string path = ssltut::expandPattern(input, static_cast<long>(first + n));
      std::error_code ec;
      got = std::filesystem::is_regular_file(path, ec);
      if (got) {
        // The file's header, size and data are checked as every reader of the plugin checks them (vpSSLImageIo)
        // before OpenCV decodes it, in colour when it is: the size first, before the file is read into memory.
        uint64_t headerWidth = 0, headerHeight = 0;
        const std::string format = vpSSLImageIo::readHeader(path, headerWidth, headerHeight);
        vpSSLInputLimits::checkImageSize(headerWidth, headerHeight, path + ": " + format + " header");
        std::ifstream in(path, std::ios::binary);
        const std::vector<unsigned char> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (!in.eof() && in.fail()) {
          throw vpException(vpException::ioError, "%s: cannot read the file", path.c_str());
        }
        vpSSLImageIo::checkData(data, path);
        image = cv::imdecode(data, cv::IMREAD_ANYCOLOR);
        if (image.empty()) {
          throw vpException(vpException::ioError, "%s: cannot decode the image", path.c_str());
        }
      }
    } else {
      got = capture.read(image) && !image.empty();
    }
    const double t = device ? std::chrono::duration<double>(std::chrono::system_clock::now() - epoch).count()
                            : startTime + static_cast<double>(n) / rate;
    if (!got) {
      if (device && n == 0) {
        throw vpException(vpException::ioError, "%s: the camera gives no image", input.c_str());
      }
      if (frames > 0) {
        throw vpException(vpException::ioError, "%s: ended after %lld of the %lld frames asked (--frames)",
                          input.c_str(), n, frames);
      }
      if (expected > 0 && n < expected) {
        throw vpException(vpException::ioError, "%s: ended after %lld of the %lld frames it states (truncated?)",
                          input.c_str(), n, expected);
      }
      if (n == 0) {
        throw vpException(vpException::ioError, "%s: no image", input.c_str());
      }
      break;
    }
    const unsigned int width = static_cast<unsigned int>(image.cols), height = static_cast<unsigned int>(image.rows);
    if (xmlWidth > 0 && (width != xmlWidth || height != xmlHeight)) {
      throw vpException(vpException::badValue, "%s: camera \"%s\" is for %ux%u images, %s gives %ux%u",
                        cameraXml.c_str(), cameraName.c_str(), xmlWidth, xmlHeight, input.c_str(), width, height);
    }

    if (odometry.size() > 0 && !odometry.covers(t)) {
      throw vpException(vpException::badValue, "%s: image %lld at t = %.6f s is outside the odometry's [%.6f, %.6f]",
                        odometryCsv.c_str(), n, t, odometry.getStartTime(), odometry.getEndTime());
    }
    vpSSLSequenceFrame frame;
    frame.index = static_cast<unsigned int>(n);
    if (n == 0) {
      firstTime = t;
    }
    odometry.stampFrame(t, firstTime, frame);
    if (!writer.isOpen()) {
      writer.open(recording.output, cam, recording.info(), {vpSSLOdometryTrack::stampColumn()});
    }
    if (image.channels() == 1) {
      vpImage<unsigned char> I;
      vpImageConvert::convert(image, I);
      writer.write(frame, I);
    } else {
      vpImage<vpRGBa> I;
      vpImageConvert::convert(image, I);
      writer.write(frame, I);
    }
    ++n;
  }
  if (writer.isOpen()) {
    writer.close();
  }
  std::cout << kProgram << ": " << n << " frames written to " << recording.output
            << (odometry.size() > 0 ? " with odometry" : " without odometry") << (g_interrupted ? " (interrupted)" : "")
            << std::endl;
  return 0;
}
} // namespace

int main(int argc, char **argv)
{
  return ssltut::guardedMain(kProgram, [&] { return run(argc, argv); });
}

//! \example tutorial-ssl-tracker.cpp
//! Tracks the ssl3-a3 target over a recorded sequence with vpSSLTracker and writes the estimate beside the
//! ground truth.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include <visp3/core/vpFont.h>
#include <visp3/core/vpImageConvert.h>
#include <visp3/core/vpImageDraw.h>
#include <visp3/core/vpIoTools.h>
#include <visp3/core/vpMeterPixelConversion.h>
#include <visp3/core/vpThetaUVector.h>
#include <visp3/io/vpImageIo.h>
#include <visp3/ssl/vpSSLTracker.h>
#include <visp3/ssl_io/vpSSLSequenceReader.h>

#include "ssl_tutorial_camera_options.h"
#include "ssl_tutorial_common.h"
#include "ssl_tutorial_input.h"
#include "ssl_tutorial_option_loop.h"

namespace {
const char *kUsage = R"(Usage: tutorial-ssl-tracker --sequence DIR [options]
       tutorial-ssl-tracker --video FILE --camera XML [options]

Tracks the target of a recorded sequence (doc/sequence-format.md) with vpSSLTracker:
detector in regions of interest, single-frame pose hypotheses and a particle filter driven by the
vehicle odometry (paper Sec. 3.3). Uses the sequence's camera.xml, its camera_to_vehicle and, when
present, its odometry columns. Prints one line per frame and writes a CSV of the estimate beside
the ground truth (when the sequence has it).

Options:
  --sequence DIR        Recorded sequence folder. Required unless --video.
  --video FILE          A video file instead (.avi, .mp4, ...; whatever OpenCV's FFmpeg decodes),
                        read to its end: no odometry, no ground truth, t = frame / the video's
                        frame rate (1 fps when it announces none). Needs --camera.
  --camera XML          With --video: the camera's parameters, ViSP XML (vpXmlParserCamera).
  --camera-name NAME    With --video: the camera's name inside the XML file (default: Camera).
  --target NAME|FILE    With --video: built-in target name or target file (default: ssl3-a3).
  --csv FILE            CSV written ("-": standard output, the per-frame lines then go to stderr;
                        default: DIR/ssl-tracker.csv with --output-dir DIR, else no CSV). Columns: frame, t, state, nb_points, full_search,
                        small_mode, orientation_known, tx ty tz tux tuy tuz (estimated cMo,
                        theta-u), gt_* (ground truth), range (m), position_error (m, of the target
                        origin; without a known orientation, of the landmark centre the filter
                        holds, and no angle), angle_error_deg, single_* (the best
                        single-frame hypothesis of the same image: its kind full|position, its
                        position and angle errors; for a position-only hypothesis the position
                        error is that of the landmark centre it holds, and it has no angle).
                        Empty cells where a value does not exist. Never inside a recorded
                        sequence, never the video, camera or target file (exit status 2).
  --output-dir DIR      Write an annotated image DIR/<frame>.png per frame: projected landmark
                        circles from the estimated pose (green tracking, yellow acquired, red lost),
                        the target frame axes, detected centres (cyan crosses), regions of
                        interest (blue), the state. Never inside a recorded sequence.
  --display             Show the annotated images in a window (needs an X display; without one,
                        a one-line notice and the annotated images go to DIR of --output-dir,
                        default ssl-tracker).
  --no-odometry         Ignore the odometry columns (random-walk prediction).
  --small-landmarks M   Detector scale: auto (default, vpSSLTracker's switch from the predicted
                        radii), on (always the small-landmark mode) or off (never).
  --particles N         Particles of the filter, 1 to 1000000 (default 1000).
  --seed S              Seed of the particle filter, 0 to 2147483647 (default 1).
  --full-search N       Full-image search at least every N frames while tracking, 0 to 1000000
                        (default 10).
  --max-frames N        Stop after N frames, 0 to 1000000000 (default: all).
  --quiet               No per-frame lines.
  --summary             After the run, print a Markdown table per range band (0-1, 1-2, 2-4, 4-8,
                        8+ m, from the ground truth): frames, then for the single-frame pose and
                        for the tracker (frames in the tracking state) the frames with an estimate
                        and the median and 90th percentile of the position and angle errors, as
                        in the CSV (doc/benchmarks.md).
  --help                This help.

Exit status: 0 on success, 1 when the sequence cannot be read or is out of the limits of
doc/input-limits.md, or the video cannot be opened, has no frame or ends before the frame
count its header announces (an error in the middle of it stops the run; the frames before it
are in the CSV), when the CSV or an annotated image cannot be written whole (a full device) or on any
other runtime failure, 2 on a bad option. Every error is one line on stderr.
)";

const char *kProgram = "tutorial-ssl-tracker";

[[noreturn]] void fail(const std::string &msg, int code)
{
  std::cerr << "tutorial-ssl-tracker: " << msg << std::endl;
  std::exit(code);
}

std::string cell(double x, int digits)
{
  if (!std::isfinite(x)) {
    return "";
  }
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", digits, x);
  return buf;
}

std::string poseCells(const vpHomogeneousMatrix &M, bool valid)
{
  const vpPoseVector p(M);
  std::string out;
  for (unsigned int i = 0; i < 6; ++i) {
    out += (i ? "," : "") + (valid ? cell(p[i], i < 3 ? 6 : 7) : std::string());
  }
  return out;
}

// Angle of the rotation between two poses (degrees).
double angleError(const vpHomogeneousMatrix &a, const vpHomogeneousMatrix &b)
{
  const vpThetaUVector tu(a.getRotationMatrix().t() * b.getRotationMatrix());
  return vpMath::deg(std::sqrt(tu[0] * tu[0] + tu[1] * tu[1] + tu[2] * tu[2]));
}

// Distance between the point X of the target frame placed by two poses (m).
double positionError(const vpHomogeneousMatrix &a, const vpHomogeneousMatrix &b, const vpColVector &X)
{
  const vpColVector d = a * X - b * X;
  return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

// Errors of one estimator in one range band.
struct BandErrors
{
  std::vector<double> position, angle;
};

double percentile(std::vector<double> v, double q)
{
  if (v.empty()) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(std::min<double>(v.size() - 1, std::floor(q * (v.size() - 1) + 0.5)))];
}

std::string stat(const std::vector<double> &v, double scale, int digits)
{
  if (v.empty()) {
    return "-";
  }
  return cell(scale * percentile(v, 0.5), digits) + " / " + cell(scale * percentile(v, 0.9), digits);
}

// The outer circle of each landmark, projected with cMo.
void drawTarget(vpImage<vpRGBa> &out, const vpSSLTarget &target, const vpHomogeneousMatrix &cMo,
                const vpCameraParameters &cam, const vpColor &color)
{
  const unsigned int n = 48;
  for (const vpSSLTargetLandmark &l : target.getLandmarks()) {
    std::vector<vpImagePoint> polygon;
    for (unsigned int k = 0; k < n; ++k) {
      const double a = 2. * M_PI * k / n;
      const vpColVector X({l.x + l.radius * std::cos(a), l.y + l.radius * std::sin(a), l.z, 1.});
      const vpColVector c = cMo * X;
      if (!(c[2] > 0.)) {
        polygon.clear();
        break;
      }
      double u = 0., v = 0.;
      vpMeterPixelConversion::convertPoint(cam, c[0] / c[2], c[1] / c[2], u, v);
      polygon.push_back(vpImagePoint(v, u));
    }
    if (!polygon.empty()) {
      vpImageDraw::drawPolygon(out, polygon, color, 2, true);
    }
  }
}
int run(int argc, char **argv)
{
  bool csvSet = false;
  std::string sequence, csvPath, outputDir, smallMode = "auto";
  std::string videoPath;
  ssltut::CameraTargetOptions camera;
  bool display = false, useOdometry = true, quiet = false, summary = false;
  unsigned int particles = 1000, fullSearch = 10;
  long seed = 1, maxFrames = -1;
  // One option: false for an option this tutorial does not know.
  const auto option = [&](const std::string &a, const auto &value) {
    auto count = [&](const std::string &v, long long maximum) {
      return static_cast<long>(ssltut::parseInteger("option " + a, v, 0, maximum));
    };
    if (a == "--sequence") {
      sequence = value();
    } else if (a == "--video") {
      videoPath = value();
    } else if (camera.parseCameraOption(a, value)) {
    } else if (a == "--csv") {
      csvPath = value();
      csvSet = true;
    } else if (a == "--output-dir") {
      outputDir = value();
    } else if (a == "--display") {
      display = true;
    } else if (a == "--no-odometry") {
      useOdometry = false;
    } else if (a == "--small-landmarks") {
      smallMode = value();
      if (smallMode != "auto" && smallMode != "on" && smallMode != "off") {
        fail("option --small-landmarks: expected auto, on or off, got \"" + smallMode + "\"", 2);
      }
    } else if (a == "--particles") {
      const long n = count(value(), 1000000);
      if (n < 1) {
        fail("option --particles: expected 1 to 1000000 particles, got " + std::to_string(n), 2);
      }
      particles = static_cast<unsigned int>(n);
    } else if (a == "--seed") {
      seed = count(value(), 2147483647);
    } else if (a == "--full-search") {
      fullSearch = static_cast<unsigned int>(count(value(), 1000000));
    } else if (a == "--max-frames") {
      maxFrames = count(value(), 1000000000);
    } else if (a == "--quiet") {
      quiet = true;
    } else if (a == "--summary") {
      summary = true;
    } else {
      return false;
    }
    return true;
  };
  if (!ssltut::readOptions(argc, argv, kUsage, ssltut::OptionStyle::HelpFirst, option)) {
    return 0; // --help
  }
  const bool isVideo = !videoPath.empty();
  if (sequence.empty() && !isVideo) {
    fail("--sequence is required, or --video (see --help)", 2);
  }
  if (!sequence.empty() && isVideo) {
    fail("--sequence and --video: give one of them (see --help)", 2);
  }
  if (isVideo && camera.cameraFile.empty()) {
    fail("--video needs --camera (see --help)", 2);
  }
  if (csvSet && csvPath.empty()) {
    fail("option --csv: empty file name", 2);
  }
  vpImage<vpRGBa> annotated;
  std::unique_ptr<vpDisplay> window;
  if (display) {
    // Opened on a placeholder first, so that a missing X server is told before any work.
    annotated.resize(480, 640, vpRGBa(0));
    window = ssltut::openDisplay(annotated, kProgram, kProgram,
                                 "writing annotated images instead (--output-dir, default ssl-tracker)");
    display = window != nullptr;
    if (!display && outputDir.empty()) {
      outputDir = "ssl-tracker";
    }
  }
  if (!csvSet && !outputDir.empty()) {
    csvPath = outputDir + "/ssl-tracker.csv"; // beside the annotated images, never over a file in the current folder
  }
  // Nothing the tracker reads is written over: not a recorded sequence, not the video or the camera file.
  if (!csvPath.empty() && csvPath != "-") {
    const std::string csvOption = csvSet ? "--csv" : "--output-dir";
    ssltut::checkOutsideSequences(csvOption, csvPath);
    ssltut::checkNotAnInput(csvOption, csvPath, {videoPath, camera.cameraFile, camera.targetName});
  }
  if (!outputDir.empty()) {
    ssltut::checkOutsideSequences("--output-dir", outputDir);
  }

  vpSSLSequenceReader reader;
  ssltut::VideoInput video;
  vpSSLTarget target;
  vpCameraParameters cam;
  std::unique_ptr<vpSSLTracker> trackerPtr;
  if (isVideo) {
    ssltut::loadCameraAndTarget(camera.cameraFile, camera.cameraName, camera.targetName, cam, target);
    try {
      video.open(videoPath);
    } catch (const vpException &e) {
      fail(e.getStringMessage(), 1);
    }
    trackerPtr.reset(new vpSSLTracker(target, cam));
  } else {
    try {
      reader.open(sequence);
      // A relative target path is the sequence folder's, as in every tool (vpSSLSequenceReader::getTargetPath()).
      target = vpSSLTarget::fromName(reader.getTargetPath());
      cam = reader.getCameraParameters();
      trackerPtr.reset(new vpSSLTracker(target, cam, vpHomogeneousMatrix(reader.getInfo().vMc)));
    } catch (const vpException &e) {
      fail(sequence + ": " + e.getStringMessage(), 1);
    }
  }
  const double fps = isVideo && video.fps() > 0. ? video.fps() : 1.;
  vpSSLTracker &tracker = *trackerPtr;
  try {
    tracker.getFilter().setNbParticles(particles);
    tracker.setSeed(seed);
    tracker.setFullSearchPeriod(fullSearch);
  } catch (const vpException &e) {
    fail(e.getStringMessage(), 2);
  }
  if (smallMode != "auto") {
    tracker.setAutomaticSmallLandmarkMode(false);
    tracker.getDetector().setSmallLandmarkMode(smallMode == "on");
  }

  std::ofstream csvFile;
  const bool csvToStdout = csvPath == "-";
  std::ostream noCsv(nullptr); // no buffer: without a CSV the rows are dropped
  if (!csvToStdout && !csvPath.empty()) {
    if (!outputDir.empty() && !csvSet) {
      try {
        vpIoTools::makeDirectory(outputDir);
      } catch (const vpException &) {
        fail(outputDir + ": cannot create the folder", 1);
      }
    }
    csvFile.open(csvPath);
    if (!csvFile) {
      fail(csvPath + ": cannot write the CSV", 1);
    }
  }
  std::ostream &csv = csvToStdout ? std::cout : csvPath.empty() ? static_cast<std::ostream &>(noCsv) : csvFile;
  std::ostream &log = csvToStdout ? std::cerr : std::cout;
  if (!outputDir.empty()) {
    try {
      vpIoTools::makeDirectory(outputDir);
    } catch (const vpException &e) {
      fail(outputDir + ": cannot create the folder: " + e.getStringMessage(), 2);
    }
  }
  csv << "frame,t,state,nb_points,full_search,small_mode,orientation_known,tx,ty,tz,tux,tuy,tuz,gt_tx,gt_ty,gt_tz,gt_"
         "tux,gt_tuy,gt_"
         "tuz,range,position_error,angle_error_deg,single_kind,single_position_error,single_angle_error_deg\n";

  vpSSLSequenceFrame frame;
  vpImage<unsigned char> I;
  const vpFont font(16, vpFont::GENERIC_MONOSPACE);
  const vpColVector origin({0., 0., 0., 1.});
  long nbFrames = 0, nbTracking = 0;
  const double bandEdges[] = {0., 1., 2., 4., 8., std::numeric_limits<double>::infinity()};
  const unsigned int nbBands = 5;
  std::vector<BandErrors> singleBands(nbBands), trackerBands(nbBands);
  std::vector<long> bandFrames(nbBands, 0);
  int status = 0;
  while (maxFrames < 0 || nbFrames < maxFrames) {
    try {
      if (isVideo) {
        // A video has neither odometry nor ground truth: only the frame and its time.
        frame = vpSSLSequenceFrame();
        frame.index = static_cast<unsigned int>(video.frameIndex());
        frame.t = video.frameIndex() / fps;
        if (!video.read(I)) {
          break;
        }
      } else if (!reader.next(frame, I)) {
        break;
      }
    } catch (const vpException &e) {
      std::cerr << "tutorial-ssl-tracker: " << e.getStringMessage() << std::endl;
      status = 1;
      break;
    }
    ++nbFrames;
    vpSSLTrackerState state = SSL_TRACKER_SEARCHING;
    try {
      state = (useOdometry && frame.hasOdometry) ? tracker.track(I, vpHomogeneousMatrix(frame.oMv)) : tracker.track(I);
    } catch (const vpException &e) {
      // The rows before it stay in the CSV, which is closed below.
      std::cerr << "tutorial-ssl-tracker: " << (isVideo ? videoPath : reader.getImagePath()) << ": "
                << e.getStringMessage() << std::endl;
      status = 1;
      break;
    }
    nbTracking += state == SSL_TRACKER_TRACKING ? 1 : 0;
    const bool hasPose = tracker.hasPose();
    const vpHomogeneousMatrix cMo = tracker.getPose();
    const vpHomogeneousMatrix cMoTrue(frame.cMo);
    const bool truth = frame.hasGroundTruth;

    // Without a known orientation (one or two landmarks since the acquisition) only the landmark the filter
    // was placed on is meaningful: its centre is compared, as for a position-only single-frame hypothesis.
    const bool oriented = hasPose && tracker.getOrientationKnown();
    double error = std::numeric_limits<double>::quiet_NaN(), angle = error;
    if (hasPose && truth && oriented) {
      error = positionError(cMo, cMoTrue, origin);
      angle = angleError(cMo, cMoTrue);
    } else if (hasPose && truth) {
      size_t k = 0;
      if (!tracker.getHypotheses().empty() && tracker.getHypotheses().front().positionOnly) {
        k = static_cast<size_t>(tracker.getHypotheses().front().landmark);
      }
      const vpSSLTargetLandmark &l = target.getLandmark(k);
      error = positionError(cMo, cMoTrue, vpColVector({l.x, l.y, l.z, 1.}));
    }
    // The best single-frame hypothesis of the same detection: a full pose, or the position of one landmark.
    std::string singleKind;
    double singleError = std::numeric_limits<double>::quiet_NaN(), singleAngle = singleError;
    if (!tracker.getHypotheses().empty()) {
      const vpSSLPoseHypothesis &h = tracker.getHypotheses().front();
      singleKind = h.positionOnly ? "position" : "full";
      if (truth && h.positionOnly) {
        const vpSSLTargetLandmark &l = target.getLandmark(static_cast<size_t>(h.landmark));
        const vpColVector X({l.x, l.y, l.z, 1.});
        const vpColVector d = cMoTrue * X;
        const vpTranslationVector t = h.cMo.getTranslationVector();
        singleError = std::sqrt(vpMath::sqr(t[0] - d[0]) + vpMath::sqr(t[1] - d[1]) + vpMath::sqr(t[2] - d[2]));
      } else if (truth) {
        singleError = positionError(h.cMo, cMoTrue, origin);
        singleAngle = angleError(h.cMo, cMoTrue);
      }
    }
    const double range =
        truth ? cMoTrue.getTranslationVector().frobeniusNorm() : std::numeric_limits<double>::quiet_NaN();
    for (unsigned int b = 0; truth && b < nbBands; ++b) {
      if (range >= bandEdges[b] && range < bandEdges[b + 1]) {
        ++bandFrames[b];
        if (std::isfinite(singleError)) {
          singleBands[b].position.push_back(singleError);
        }
        if (std::isfinite(singleAngle)) {
          singleBands[b].angle.push_back(singleAngle);
        }
        if (state == SSL_TRACKER_TRACKING && std::isfinite(error)) {
          trackerBands[b].position.push_back(error);
        }
        if (state == SSL_TRACKER_TRACKING && std::isfinite(angle)) {
          trackerBands[b].angle.push_back(angle);
        }
      }
    }
    csv << frame.index << "," << cell(frame.t, 6) << "," << vpSSLTrackerStateName(state) << ","
        << tracker.getNbLandmarks() << "," << (tracker.getLastSearchWasFull() ? 1 : 0) << ","
        << (tracker.getLastSmallLandmarkMode() ? 1 : 0) << "," << (oriented ? 1 : 0) << "," << poseCells(cMo, hasPose)
        << "," << poseCells(cMoTrue, truth) << "," << cell(range, 4) << "," << cell(error, 5) << "," << cell(angle, 3)
        << "," << singleKind << "," << cell(singleError, 5) << "," << cell(singleAngle, 3) << "\n";
    if (!quiet) {
      char line[256];
      std::snprintf(line, sizeof(line), "frame %5u t %8.3f %-9s nbPoints %u%s", frame.index, frame.t,
                    vpSSLTrackerStateName(state), tracker.getNbLandmarks(),
                    tracker.getLastSmallLandmarkMode() ? " small" : "");
      log << line;
      if (hasPose) {
        const vpTranslationVector t = cMo.getTranslationVector();
        std::snprintf(line, sizeof(line), " t [%.3f %.3f %.3f] m", t[0], t[1], t[2]);
        log << line;
      }
      if (std::isfinite(error)) {
        std::snprintf(line, sizeof(line), " error %.3f m %.1f deg", error, angle);
        log << line;
      }
      log << "\n";
    }

    if (!outputDir.empty() || display) {
      vpImageConvert::convert(I, annotated);
      for (const vpRect &r : tracker.getRegionsOfInterest()) {
        vpImageDraw::drawRectangle(annotated, r, vpColor::blue, false, 1);
      }
      for (const vpSSLLandmark &l : tracker.getDetector().getLandmarks()) {
        vpImageDraw::drawCross(annotated, l.getCenter(), 10, vpColor::cyan, 1);
      }
      if (hasPose) {
        const vpColor color = state == SSL_TRACKER_TRACKING
                                  ? vpColor::green
                                  : (state == SSL_TRACKER_ACQUIRED ? vpColor::yellow : vpColor::red);
        drawTarget(annotated, target, cMo, cam, color);
        vpImageDraw::drawFrame(annotated, cMo, cam, 0.1, vpColor::none, 2);
      }
      font.drawText(annotated,
                    "frame " + std::to_string(frame.index) + " " + vpSSLTrackerStateName(state) + " nbPoints " +
                        std::to_string(tracker.getNbLandmarks()),
                    vpImagePoint(8, 8), vpColor::yellow, vpColor::black);
      if (!outputDir.empty()) {
        char name[32];
        std::snprintf(name, sizeof(name), "/%06u.png", frame.index);
        try {
          if (vpIoTools::checkDirectory(outputDir + name)) {
            throw vpException(vpException::ioError, "is a folder");
          }
          vpImageIo::write(annotated, outputDir + name);
        } catch (const vpException &e) {
          // Stops the run, but the CSV rows so far are kept (closed below).
          std::cerr << "tutorial-ssl-tracker: " << outputDir + name << ": cannot write: " << e.getStringMessage()
                    << std::endl;
          status = 1;
          break;
        }
      }
      if (display) {
        if (window->getWidth() != annotated.getWidth() || window->getHeight() != annotated.getHeight()) {
          window.reset(new vpDisplayX(annotated, vpDisplay::SCALE_AUTO));
          vpDisplay::setTitle(annotated, kProgram);
        }
        vpDisplay::display(annotated);
        vpDisplay::flush(annotated);
      }
    }
  }
  // A CSV that could not be written whole (a full device) is an error, not a success with rows missing.
  try {
    if (!csvPath.empty()) {
      ssltut::finishStream(csv, csvToStdout ? std::string("standard output") : csvPath);
    }
  } catch (const vpException &e) {
    // One line: no summary that would name the CSV as written.
    std::cerr << "tutorial-ssl-tracker: " << e.getStringMessage() << std::endl;
    return 1;
  }
  std::cerr << "tutorial-ssl-tracker: " << nbFrames << " frame(s), tracking in " << nbTracking
            << (csvToStdout || csvPath.empty() ? std::string() : ", CSV in " + csvPath)
            << (outputDir.empty() ? std::string() : ", annotated images in " + outputDir + "/") << std::endl;
  if (summary) {
    log << "\n| range (m) | frames | single-frame: frames (full) | position error (mm) median / p90 | angle error "
           "(deg) median / p90 | tracker (tracking): frames | position error (mm) median / p90 | angle error (deg) "
           "median / "
           "p90 |\n|---|---|---|---|---|---|---|---|\n";
    for (unsigned int b = 0; b < nbBands; ++b) {
      const std::string band =
          b + 1 < nbBands ? cell(bandEdges[b], 0) + "-" + cell(bandEdges[b + 1], 0) : cell(bandEdges[b], 0) + "+";
      log << "| " << band << " | " << bandFrames[b] << " | " << singleBands[b].position.size() << " ("
          << singleBands[b].angle.size() << ") | " << stat(singleBands[b].position, 1000., 1) << " | "
          << stat(singleBands[b].angle, 1., 2) << " | " << trackerBands[b].position.size() << " | "
          << stat(trackerBands[b].position, 1000., 1) << " | " << stat(trackerBands[b].angle, 1., 2) << " |\n";
    }
  }
  log.flush();
  if (!log) {
    std::cerr << "tutorial-ssl-tracker: standard output: write error" << std::endl;
    status = 1;
  }
  return status;
}
} // namespace

int main(int argc, char **argv)
{
  return ssltut::guardedMain(kProgram, [&] { return run(argc, argv); });
}

//! \example tutorial-ssl-vs-apriltag.cpp
//! Benchmarks the SSL tracker against the AprilTag baseline on recorded sequences.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <visp3/core/vpIoTools.h>
#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/ssl/vpSSLTracker.h>
#include <visp3/ssl_harness/vpSSLAprilTagBaseline.h>
#include <visp3/ssl_harness/vpSSLBenchMath.h>
#include <visp3/ssl_harness/vpSSLDetectionStats.h>
#include <visp3/ssl_io/vpSSLSequenceReader.h>
#include <visp3/ssl_sim/vpSSLAprilTagSheet.h>
#include <visp3/ssl_sim/vpSSLPlot.h>

#include "ssl_tutorial_common.h"

namespace {
const char *kUsage = R"(Usage: tutorial-ssl-vs-apriltag [options] SEQUENCE_DIR [SEQUENCE_DIR ...]

Runs, frame by frame, the SSL tracker (vpSSLTracker) on the sequences that show an SSL target and
the AprilTag baseline (vpDetectorAprilTag 36h11, quad decimate 1, pose HOMOGRAPHY_VIRTUAL_VS with
the sequence's camera and the sheet's tag size) on those that show an AprilTag sheet: the
sequence.json "target" says which (apriltag36h11-... names, vpSSLAprilTagSheet). Sequences are in
the recorded-sequence format (camera.xml, sequence.json, frames.csv, images/).

Reports per sequence, per method and per water preset: detection rate, overall and per range band
(0-1, 1-2, 2-4, 4-8, 8-12 m); range90, the far edge of the farthest 0.5 m range bin in which
>= 90 % of the frames are detected; median centre error (px) and pose error (position m, angle
deg) against the ground truth, the angle over frames with an estimated orientation only:
frames where the SSL tracker has a position-only pose (one landmark seen) are counted apart,
"position-only"; false detections on frames without the target (simulated
sequences: no ground truth means out of view; an AprilTag of another id also counts); time per
frame (median, 95th percentile, one thread). Two sequences whose sequence.json differ only by the
target (same views, noise, water) are also reported side by side.
A recording without ground truth gives the rate of frames with a detection and the timing only.

Output: the Markdown report on stdout and in DIR/report.md, DIR/summary.csv (one row per
sequence and per method), DIR/frames.csv (one row per frame and method), DIR/rate_vs_range.png
and DIR/pose_error_vs_range.png (one line per method and water preset).

Options:
  --output-dir DIR      Where to write the files (default: ssl-vs-apriltag; never inside a
                        recorded sequence).
  --max-frames N        Use at most the first N frames of each sequence, 1 to 1000000000
                        (default: all).
  --bin W               Range bin of the plots and of range90 (m, 0.01 to 100, default 0.5).
  --apriltag-decimate D AprilTag quad decimate, 1 to 16 (default 1; 2 is ViSP's default, faster,
                        shorter range; the AprilTag library crashes from 240 on).
  --progress            Always show the progress bar on stderr (default: only on a terminal).
  --quiet               Never show it.
  --check-visp-benchmark DIR
                        Instead, run the AprilTag baseline on ViSP's benchmark image
                        DIR/tag36_11_640x480.png (visp-images-data AprilTag/benchmark/640x480,
                        truth cMo_<id>.txt) and print its pose error per tag.
  --help                This help.

Ranges (the frames.csv range column, else |t| of the ground truth) beyond 1000 m are an
input error: the bins of range90 and of the plots stop there.

Exit status: 0 on success, 2 on a bad option or input (one line on stderr), 1 when a run
fails or an output file cannot be written whole (a full device), or on any other runtime
failure.
)";

const char *kProgram = "tutorial-ssl-vs-apriltag";
//! Farthest range (m) a frame may have: the benchmark's bins stop there.
const double kMaxRange = 1000.;

[[noreturn]] void fail(const std::string &msg, int code)
{
  std::cerr << "tutorial-ssl-vs-apriltag: " << msg << std::endl;
  std::exit(code);
}

double parseNumber(const std::string &opt, const std::string &v, double min, double max)
{
  char *end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || !std::isfinite(x) || x < min || x > max ||
      (v.size() > 1 && (v[0] == '+' || v[0] == '-') && (v[1] == '+' || v[1] == '-'))) {
    std::ostringstream os;
    os << opt << ": expected a number in [" << min << ", " << max << "], got \"" << v << "\"";
    fail(os.str(), 2);
  }
  return x;
}

std::string csvNum(double x)
{
  if (!std::isfinite(x))
    return "";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.6g", x);
  return buf;
}

//! A CSV cell: quoted when it holds a comma, a quote or a line break (RFC 4180).
std::string csvField(const std::string &s)
{
  if (s.find_first_of(",\"\n\r") == std::string::npos)
    return s;
  std::string out = "\"";
  for (char c : s)
    out += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string rateCell(size_t d, size_t n)
{
  if (n == 0)
    return "-";
  return vpSSLBenchMath::fmt(static_cast<double>(d) / static_cast<double>(n), 2) + " (" + std::to_string(d) + "/" +
         std::to_string(n) + ")";
}

std::string readText(const std::string &path)
{
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

//! sequence.json without its "target" member and without white space: equal for the two sheets of a pair.
std::string pairKey(const std::string &folder)
{
  std::string s = readText(folder + "/sequence.json");
  s = std::regex_replace(s, std::regex("\"target\"\\s*:\\s*\"[^\"]*\"\\s*,?"), "");
  std::string out;
  for (char c : s)
    if (!std::isspace(static_cast<unsigned char>(c)))
      out += c;
  return out;
}

size_t countFrames(const std::string &folder)
{
  std::ifstream f(folder + "/frames.csv");
  size_t n = 0;
  std::string line;
  while (std::getline(f, line))
    if (!line.empty())
      ++n;
  return n > 0 ? n - 1 : 0;
}

double extraNumber(const vpSSLSequenceFrame &f, const std::string &col)
{
  auto it = f.extras.find(col);
  if (it == f.extras.end() || it->second.empty())
    return vpSSLBenchMath::nan();
  char *end = nullptr;
  const double x = std::strtod(it->second.c_str(), &end);
  return (*end == '\0') ? x : vpSSLBenchMath::nan();
}

//! The water preset named in sequence.json's "water" object, "" when none.
std::string waterName(const vpSSLSequenceInfo &info)
{
  std::smatch m;
  if (std::regex_search(info.water, m, std::regex("\"name\"\\s*:\\s*\"([^\"]*)\"")))
    return m[1];
  return "";
}

struct SequenceResult
{
  std::string folder, name, method, water, key;
  vpSSLDetectionStats stats;
  std::map<std::string, vpSSLDetectionStats> byWater;
};

class Progress
{
public:
  Progress(size_t total, bool show) : m_total(total), m_done(0), m_show(show), m_last(-1) {}
  void step(const std::string &what)
  {
    ++m_done;
    if (!m_show || m_total == 0)
      return;
    const int pct = static_cast<int>(100 * m_done / m_total);
    if (pct == m_last && m_done != m_total)
      return;
    m_last = pct;
    const int width = 30, filled = width * pct / 100;
    std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, ' ') << "] " << pct << "% " << m_done
              << "/" << m_total << " " << what << "   " << std::flush;
    if (m_done == m_total)
      std::cerr << std::endl;
  }

  bool shown() const { return m_show && m_done > 0; }

private:
  size_t m_total, m_done;
  bool m_show;
  int m_last;
};

struct Options
{
  std::vector<std::string> sequences;
  std::string outputDir = "ssl-vs-apriltag";
  size_t maxFrames = 0;
  double bin = 0.5;
  float decimate = 1.f;
  int progress = -1; // -1: on a terminal only
};

//! Runs one method over one sequence; every per-frame row goes to \e framesCsv.
SequenceResult runSequence(const std::string &folder, const Options &opt, Progress &progress, std::ostream &framesCsv)
{
  SequenceResult res;
  res.folder = folder;
  res.name = vpIoTools::getName(folder);
  if (res.name.empty())
    res.name = folder;
  res.key = pairKey(folder);

  vpSSLSequenceReader reader;
  reader.open(folder);
  const vpSSLSequenceInfo &info = reader.getInfo();
  const bool simulated = (info.source == "simulated");
  const std::string water = waterName(info);
  const vpCameraParameters &cam = reader.getCameraParameters();

  const bool isTag = vpSSLAprilTagSheet::isName(info.target);
  std::unique_ptr<vpSSLAprilTagBaseline> baseline;
  std::unique_ptr<vpSSLTracker> tracker;
  vpSSLTarget target;
  if (isTag) {
    res.method = "AprilTag";
    baseline.reset(new vpSSLAprilTagBaseline(vpSSLAprilTagSheet::fromName(info.target), cam));
    baseline->setQuadDecimate(opt.decimate);
  } else {
    res.method = "SSL";
    // A relative target path is the sequence folder's, as in every tool (vpSSLSequenceReader::getTargetPath()).
    target = vpSSLTarget::fromName(reader.getTargetPath());
    tracker.reset(new vpSSLTracker(target, cam, vpHomogeneousMatrix(info.vMc)));
    tracker->setSeed(1);
  }

  vpSSLSequenceFrame f;
  vpImage<unsigned char> I;
  size_t n = 0;
  std::map<std::string, bool> waters;
  while ((opt.maxFrames == 0 || n < opt.maxFrames) && reader.next(f, I)) {
    ++n;
    vpSSLFrameResult r;
    r.truthKnown = simulated || f.hasGroundTruth;
    r.hasTarget = f.hasGroundTruth;
    r.range = extraNumber(f, "range");
    if (!std::isfinite(r.range) && f.hasGroundTruth)
      r.range = vpHomogeneousMatrix(f.cMo).getTranslationVector().frobeniusNorm();
    if (std::isfinite(r.range) && std::fabs(r.range) > kMaxRange) {
      std::ostringstream os;
      os << folder << "/frames.csv: frame " << f.index << ": range: " << r.range << " m, beyond the " << kMaxRange
         << " m the benchmark bins";
      throw vpException(vpException::badValue, os.str());
    }
    auto w = f.extras.find("water");
    r.water = (w != f.extras.end() && !w->second.empty()) ? w->second : water;
    const vpHomogeneousMatrix truth(f.cMo);

    const auto t0 = std::chrono::steady_clock::now();
    vpHomogeneousMatrix cMo;
    if (isTag) {
      r.detected = baseline->detect(I);
      cMo = baseline->getPose();
    } else {
      if (f.hasOdometry)
        tracker->track(I, vpHomogeneousMatrix(f.oMv));
      else
        tracker->track(I);
      const vpSSLTrackerState s = tracker->getState();
      r.detected = (s == SSL_TRACKER_ACQUIRED || s == SSL_TRACKER_TRACKING); // seen in this image
      cMo = tracker->getPose();
    }
    r.timeMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

    if (r.truthKnown && !r.hasTarget)
      r.falseDetection = r.detected;
    if (isTag && baseline->getNbOthers() > 0)
      r.falseDetection = true;

    // One landmark alone gives the tracker a position and no orientation: its rotation means nothing.
    r.orientationKnown = isTag || tracker->getOrientationKnown();
    if (r.detected && f.hasGroundTruth) {
      r.positionError = vpSSLBenchMath::positionError(cMo, truth);
      if (r.orientationKnown)
        r.angleError = vpSSLBenchMath::angleError(cMo, truth);
      if (isTag) {
        double u = 0., v = 0.;
        bool ok = true;
        for (int c = 0; c < 4; ++c) {
          const double cu = extraNumber(f, "gt_c" + std::to_string(c) + "_u");
          const double cv = extraNumber(f, "gt_c" + std::to_string(c) + "_v");
          ok = ok && std::isfinite(cu) && std::isfinite(cv);
          u += cu / 4.;
          v += cv / 4.;
        }
        // The AprilTag library puts pixel centres at +0.5 (data/sequences/README.md): that convention is
        // taken out so that the centre error measures the detector, not the convention. The pose is
        // left as vpDetectorAprilTag gives it, as a user gets it.
        if (ok)
          r.centreError = std::hypot(baseline->getCentre().get_u() - 0.5 - u, baseline->getCentre().get_v() - 0.5 - v);
      } else {
        const vpSSLTargetMatch &m = tracker->getDetector().getTargetMatch();
        const std::vector<vpSSLLandmark> &lm = tracker->getDetector().getLandmarks();
        double sum = 0.;
        int cnt = 0;
        for (size_t k = 0; k < m.detection.size() && k < target.size(); ++k) {
          const int idx = m.detection[k];
          if (idx < 0 || static_cast<size_t>(idx) >= lm.size())
            continue;
          const double gu = extraNumber(f, "gt_" + target.getLandmark(k).name + "_u");
          const double gv = extraNumber(f, "gt_" + target.getLandmark(k).name + "_v");
          if (!std::isfinite(gu) || !std::isfinite(gv))
            continue;
          sum += std::hypot(lm[idx].u - gu, lm[idx].v - gv);
          ++cnt;
        }
        if (cnt > 0)
          r.centreError = sum / cnt;
      }
    }
    res.stats.add(r);
    res.byWater[r.water.empty() ? "unknown" : r.water].add(r);
    waters[r.water.empty() ? "unknown" : r.water] = true;

    framesCsv << csvField(res.name) << "," << res.method << "," << f.index << "," << csvNum(r.range) << ","
              << csvField(r.water) << "," << (r.truthKnown ? (r.hasTarget ? "1" : "0") : "") << ","
              << (r.detected ? 1 : 0) << "," << (r.falseDetection ? 1 : 0) << "," << csvNum(r.centreError) << ","
              << csvNum(r.positionError) << "," << csvNum(r.angleError) << "," << csvNum(r.timeMs) << ","
              << (r.orientationKnown ? 1 : 0) << "\n";
    progress.step(res.name);
  }
  for (const auto &kv : waters)
    res.water += (res.water.empty() ? "" : "+") + kv.first;
  return res;
}

const char *kMainHeader =
    "| sequence | method | water | frames | rate | 0-1 m | 1-2 m | 2-4 m | 4-8 m | 8-12 m | range90 (m) "
    "| centre err (px) | position err (m) | angle err (deg) | position-only | false det. / frames w/o target "
    "| ms median | ms p95 |\n"
    "|---|---|---|---:|---|---|---|---|---|---|---:|---:|---:|---:|---:|---|---:|---:|\n";

std::string mainRow(const std::string &name, const std::string &method, const std::string &water,
                    const vpSSLDetectionStats &s)
{
  std::ostringstream os;
  const bool anyTruth = s.nbWithTarget > 0;
  os << "| " << name << " | " << method << " | " << water << " | " << s.nbFrames << " | "
     << (anyTruth ? rateCell(s.nbDetected, s.nbWithTarget) : rateCell(s.nbUnknownDetected, s.nbUnknown) + " no truth")
     << " |";
  for (size_t b = 0; b < s.bandFrames.size(); ++b)
    os << " " << rateCell(s.bandDetected[b], s.bandFrames[b]) << " |";
  os << " " << vpSSLBenchMath::fmt(s.range90(), 1) << " | "
     << vpSSLBenchMath::fmt(vpSSLBenchMath::percentile(s.centre, 50.), 2) << " | "
     << vpSSLBenchMath::fmt(vpSSLBenchMath::percentile(s.position, 50.), 3) << " | "
     << vpSSLBenchMath::fmt(vpSSLBenchMath::percentile(s.angle, 50.), 2) << " | " << s.nbPositionOnly << " | "
     << (s.nbNoTarget > 0 || s.nbFalse > 0 ? std::to_string(s.nbFalse) + " / " + std::to_string(s.nbNoTarget) : "-")
     << " | " << vpSSLBenchMath::fmt(vpSSLBenchMath::percentile(s.time, 50.), 2) << " | "
     << vpSSLBenchMath::fmt(vpSSLBenchMath::percentile(s.time, 95.), 2) << " |\n";
  return os.str();
}

void summaryCsvRow(std::ostream &os, const std::string &scope, const std::string &method, const std::string &water,
                   const vpSSLDetectionStats &s)
{
  os << csvField(scope) << "," << method << "," << csvField(water) << "," << s.nbFrames << "," << s.nbWithTarget << ","
     << s.nbDetected << "," << csvNum(s.rate());
  for (size_t b = 0; b < s.bandFrames.size(); ++b)
    os << "," << s.bandFrames[b] << "," << csvNum(s.bandRate(b));
  os << "," << csvNum(s.range90()) << "," << csvNum(vpSSLBenchMath::percentile(s.centre, 50.)) << ","
     << csvNum(vpSSLBenchMath::percentile(s.position, 50.)) << "," << csvNum(vpSSLBenchMath::percentile(s.angle, 50.))
     << "," << s.nbNoTarget << "," << s.nbFalse << "," << csvNum(vpSSLBenchMath::percentile(s.time, 50.)) << ","
     << csvNum(vpSSLBenchMath::percentile(s.time, 95.)) << "," << s.nbPositionOnly << "\n";
}

int checkVispBenchmark(const std::string &dir)
{
  std::vector<vpSSLAprilTagBaseline::BenchmarkResult> res = vpSSLAprilTagBaseline::runOnVispBenchmark(dir);
  std::cout << "AprilTag baseline on " << dir << "/tag36_11_640x480.png (ViSP testAprilTag's setup)\n\n"
            << "| tag id | tag size (m) | position err (mm) | angle err (deg) | ViSP RMS t (m) | ViSP RMS tu (rad) |\n"
            << "|---:|---:|---:|---:|---:|---:|\n";
  int missing = 0;
  for (size_t i = 0; i < res.size(); ++i) {
    if (res[i].id < 0)
      ++missing;
    std::cout << "| " << i << " | " << (i < 3 ? "0.200" : "0.100") << " | "
              << vpSSLBenchMath::fmt(1000. * res[i].positionError, 2) << " | "
              << vpSSLBenchMath::fmt(res[i].angleError, 3) << " | " << vpSSLBenchMath::fmt(res[i].rmsTranslation, 4)
              << " | " << vpSSLBenchMath::fmt(res[i].rmsThetaU, 4) << " |\n";
  }
  if (missing > 0) {
    std::cerr << "tutorial-ssl-vs-apriltag: " << missing << " of 5 tags not detected" << std::endl;
    return 1;
  }
  return 0;
}

void addPlots(const std::map<std::string, vpSSLDetectionStats> &byMethodWater, double bin, const std::string &dir)
{
  double maxRange = 1.;
  for (const auto &kv : byMethodWater)
    for (double r : kv.second.detectedRange)
      if (std::isfinite(r))
        maxRange = std::max(maxRange, std::min(r, kMaxRange));
  maxRange = std::ceil(maxRange / bin) * bin;
  vpSSLPlot rate("Detection rate vs range", "range (m)", "detection rate");
  vpSSLPlot pos("Position error vs range (median of detected frames)", "range (m)", "position error (m)");
  vpSSLPlot ang("Angle error vs range (median of detected frames)", "range (m)", "angle error (deg)");
  for (const auto &kv : byMethodWater) {
    std::vector<double> x, y;
    kv.second.binnedRate(bin, maxRange, x, y);
    rate.addSeries(kv.first, x, y, vpColor::none, vpSSLPlot::STYLE_LINE_MARKERS);
    kv.second.binnedMedian(kv.second.position, bin, maxRange, x, y);
    pos.addSeries(kv.first, x, y, vpColor::none, vpSSLPlot::STYLE_LINE_MARKERS);
    kv.second.binnedMedian(kv.second.angle, bin, maxRange, x, y);
    ang.addSeries(kv.first, x, y, vpColor::none, vpSSLPlot::STYLE_LINE_MARKERS);
  }
  rate.setYRange(0., 1.05);
  rate.setXRange(0., maxRange);
  pos.setXRange(0., maxRange);
  ang.setXRange(0., maxRange);
  rate.save(dir + "/rate_vs_range.png", 640, 360);
  vpSSLPlot::saveStacked({pos, ang}, dir + "/pose_error_vs_range.png", 640, 240);
}
int run(int argc, char **argv)
{
  Options opt;
  std::string vispDir;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&] { return ssltut::optionValue(argc, argv, i, ssltut::MissingValue::Colon); };
    if (arg == "--help" || arg == "-h") {
      std::cout << kUsage;
      return 0;
    } else if (arg == "--output-dir") {
      opt.outputDir = value();
    } else if (arg == "--max-frames") {
      opt.maxFrames = static_cast<size_t>(ssltut::parseInteger(arg, value(), 1, 1000000000));
    } else if (arg == "--bin") {
      opt.bin = parseNumber(arg, value(), 0.01, 100.);
    } else if (arg == "--apriltag-decimate") {
      // AprilTag's decimation crashes (SEGV) from 240 on; 16 is already coarser than any use.
      opt.decimate = static_cast<float>(parseNumber(arg, value(), 1., 16.));
    } else if (arg == "--progress") {
      opt.progress = 1;
    } else if (arg == "--quiet") {
      opt.progress = 0;
    } else if (arg == "--check-visp-benchmark") {
      vispDir = value();
    } else if (arg.size() > 1 && arg[0] == '-') {
      fail("unknown option " + arg + " (see --help)", 2);
    } else {
      opt.sequences.push_back(arg);
    }
  }
  if (!vispDir.empty()) {
    try {
      return checkVispBenchmark(vispDir);
    } catch (const vpException &e) {
      fail(e.getStringMessage(), 2);
    }
  }
  if (opt.sequences.empty())
    fail("no sequence folder given (see --help)", 2);
  size_t total = 0;
  for (const std::string &s : opt.sequences) {
    if (!vpIoTools::checkDirectory(s))
      fail(s + ": not a folder", 2);
    if (!vpIoTools::checkFilename(s + "/frames.csv"))
      fail(s + "/frames.csv: missing (not a sequence folder?)", 2);
    const size_t n = countFrames(s);
    total += (opt.maxFrames > 0 && n > opt.maxFrames) ? opt.maxFrames : n;
  }
  // The files it writes (frames.csv among them) never go into a recorded sequence, the inputs included.
  ssltut::checkOutsideSequences("--output-dir", opt.outputDir);
  try {
    vpIoTools::makeDirectory(opt.outputDir);
  } catch (const vpException &e) {
    fail(opt.outputDir + ": cannot create the output folder", 1);
  }
  std::ofstream framesCsv(opt.outputDir + "/frames.csv");
  if (!framesCsv)
    fail(opt.outputDir + "/frames.csv: cannot write", 1);
  framesCsv << "sequence,method,frame,range_m,water,target_in_view,detected,false_detection,centre_err_px,"
               "position_err_m,angle_err_deg,time_ms,orientation_known\n";

  Progress progress(total, opt.progress == 1 || (opt.progress == -1 && isatty(STDERR_FILENO)));
  std::vector<SequenceResult> results;
  for (const std::string &s : opt.sequences) {
    try {
      results.push_back(runSequence(s, opt, progress, framesCsv));
    } catch (const vpException &e) {
      if (progress.shown())
        std::cerr << std::endl; // end the progress bar's line
      // The rows of the sequences before are kept.
      framesCsv.close();
      const std::string msg = e.getStringMessage();
      fail(msg.find(s) == std::string::npos ? s + ": " + msg : msg, 2);
    }
  }

  // Aggregates: per method, per method and water preset.
  std::map<std::string, vpSSLDetectionStats> byMethod;
  std::map<std::string, vpSSLDetectionStats> byMethodWater;
  for (const SequenceResult &r : results) {
    byMethod[r.method].merge(r.stats);
    for (const auto &kv : r.byWater)
      byMethodWater[r.method + " " + kv.first].merge(kv.second);
  }

  std::ostringstream md;
  md << "## SSL vs AprilTag\n\nPer sequence, then per method over all sequences. Rates: detected / frames with the "
        "target in view (n/N); range90: far edge of the farthest "
     << opt.bin
     << " m bin with >= 90 % detected; errors: medians over detected frames with ground truth; times: one "
        "thread, per frame.\n\n"
     << kMainHeader;
  for (const SequenceResult &r : results)
    md << mainRow(r.name, r.method, r.water, r.stats);
  for (const auto &kv : byMethod)
    md << mainRow("**all**", kv.first, "all", kv.second);

  md << "\n### Per water preset\n\n" << kMainHeader;
  for (const auto &kv : byMethodWater) {
    const std::string method = kv.first.substr(0, kv.first.find(' '));
    md << mainRow("all", method, kv.first.substr(kv.first.find(' ') + 1), kv.second);
  }

  // Pairs: same sequence.json but for the target, one SSL and one AprilTag.
  std::ostringstream pairs;
  for (size_t i = 0; i < results.size(); ++i)
    for (size_t j = 0; j < results.size(); ++j)
      if (results[i].method == "SSL" && results[j].method == "AprilTag" && results[i].key == results[j].key &&
          results[i].stats.nbFrames == results[j].stats.nbFrames)
        pairs << mainRow(results[i].name, "SSL", results[i].water, results[i].stats)
              << mainRow(results[j].name, "AprilTag", results[j].water, results[j].stats);
  if (!pairs.str().empty())
    md << "\n### Same views, SSL sheet vs AprilTag sheet\n\nPairs of sequences identical but for the printed "
          "sheet.\n\n"
       << kMainHeader << pairs.str();

  std::cout << md.str();
  std::ofstream report(opt.outputDir + "/report.md");
  report << md.str();
  std::ofstream summary(opt.outputDir + "/summary.csv");
  summary << "scope,method,water,frames,frames_with_target,detected,rate";
  for (size_t b = 0; b + 1 < vpSSLBenchMath::bandEdges().size(); ++b)
    summary << ",frames_" << vpSSLBenchMath::bandLabel(b) << "m,rate_" << vpSSLBenchMath::bandLabel(b) << "m";
  summary << ",range90_m,centre_err_px,position_err_m,angle_err_deg,frames_without_target,false_detections,"
             "time_median_ms,time_p95_ms,position_only_frames\n";
  for (const SequenceResult &r : results)
    summaryCsvRow(summary, r.name, r.method, r.water, r.stats);
  for (const auto &kv : byMethod)
    summaryCsvRow(summary, "all", kv.first, "all", kv.second);
  for (const auto &kv : byMethodWater)
    summaryCsvRow(summary, "all", kv.first.substr(0, kv.first.find(' ')), kv.first.substr(kv.first.find(' ') + 1),
                  kv.second);
  // Checked after flushing and closing: a full device fails there, not at the first write.
  try {
    ssltut::finishStream(report, opt.outputDir + "/report.md");
    ssltut::finishStream(summary, opt.outputDir + "/summary.csv");
    ssltut::finishStream(framesCsv, opt.outputDir + "/frames.csv");
    ssltut::finishStream(std::cout, "standard output");
  } catch (const vpException &e) {
    fail(e.getStringMessage(), 1);
  }
  try {
    addPlots(byMethodWater, opt.bin, opt.outputDir);
  } catch (const vpException &e) {
    fail(e.getStringMessage(), 1);
  }
  return 0;
}
} // namespace

int main(int argc, char **argv)
{
  return ssltut::guardedMain(kProgram, [&] { return run(argc, argv); });
}

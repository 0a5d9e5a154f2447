/*
  The whole detector (paper Sec. 3, Table 1) against ViSP's AprilTag detector and OpenCV's ArUco detector, on
  the same frames: one rendered view holding both the ssl3-a3 sheet and an A3 AprilTag 36h11 sheet
  (vpSSLAprilTagSheet) side by side, 1 m away and slightly turned, through a camera of the same field of view at
  320x240, 640x480, 1280x720 and 1920x1080; the same 640x480 view under water (vpSSLWaterModel "clear", the
  sensor's noise); and ViSP's real 640x480 AprilTag photograph (no landmark: the clutter case). Each detector sees
  the other's sheet as clutter.

  Timed, on every frame: vpSSLDetector::detect() full frame (full-resolution matching, and setDecimation(2)) and
  vpDetectorAprilTag 36h11 (quad decimate 2, its default, and 1), each on one thread and on all the cores
  (the same count for both); cv::aruco::detectMarkers (DICT_APRILTAG_36h11, one thread); the reference matching
  function alone at 640x480 (the scalar loops the SIMD kernel replaces). At 640x480, three 100x100 regions of
  interest around the landmarks, in three modes:
  - tracker fast path, regions centred on the previous landmarks: each is re-read from its centre, no matching;
  - tracker fast path, regions 20 px off: what vpSSLDetector does there (re-read, matched on the image decimated
    twice, or matched at full resolution) is counted and printed beside the row;
  - the paper's ROI mode: no previous landmark (forgotten before each timed frame, untimed), so every region is
    matched and searched for peaks, at the detector's resolution.
  Every timed frame of these rows is searched in its regions: the periodic full search of vpSSLTracker is the
  full-frame row.

    ./bench-detector --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

  After Google Benchmark's own report, a table of medians (over every timed iteration), frames per second, and
  the ratio of each time to AprilTag's on the same frame with the same thread count, quad decimate 2 and 1, from
  this run only (empty when that AprilTag row was not run), beside the paper's Table 1.
  Reading: doc/benchmarks.md.
*/
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <benchmark/benchmark.h>
#include <opencv2/aruco.hpp>
#include <opencv2/core.hpp>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpImageConvert.h>
#include <visp3/core/vpMath.h>
#include <visp3/core/vpRect.h>
#include <visp3/detection/vpDetectorAprilTag.h>
#include <visp3/io/vpImageIo.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl_sim/vpSSLAprilTagSheet.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>
#include <visp3/ssl_sim/vpSSLWaterModel.h>

#include "vpSSLDetectorTestAccess.h"

namespace {
// The board 1 m in front of the camera, turned by a few degrees about each axis, and on it the ssl3-a3 target to
// the right and the tag sheet to the left: both whole sheets in view at every size.
vpHomogeneousMatrix boardPose()
{
  return vpHomogeneousMatrix(0.02, -0.01, 1.0, vpMath::rad(5.), vpMath::rad(-4.), vpMath::rad(3.));
}
vpHomogeneousMatrix sslPose()
{
  return boardPose() * vpHomogeneousMatrix(0.30, 0., 0., 0., 0., 0.);
}
// The pose of the tag frame (vpSSLAprilTagSheet), its sheet centred 0.24 m left of the board's origin.
vpHomogeneousMatrix tagPose()
{
  return boardPose() * vpHomogeneousMatrix(-0.24, 0., 0., 0., 0., 0.) * vpSSLAprilTagSheet::getSheetToTag();
}

// The same horizontal field of view (56 degrees) at every size.
vpCameraParameters camera(unsigned int width, unsigned int height)
{
  const double f = 600. * width / 640.;
  return vpCameraParameters(f, f, 0.5 * width - 0.5, 0.5 * height - 0.5);
}

// Thread count of the "all cores" rows, the same for both detectors.
unsigned int allThreads()
{
  return std::max(1u, std::thread::hardware_concurrency());
}

struct Frame
{
  vpImage<unsigned char> I;     // both sheets
  std::vector<vpRect> rois;     // 100x100 around each landmark of the target
  std::vector<vpRect> off;      // the same, 20 px to the right
  vpImage<unsigned char> blank; // uniform grey of the same size (forgets the previous landmarks)
};

// Both sheets in one view: each rendered as reflectance and range, the nearer kept at each pixel; then the
// 8-bit image, or with \e water the underwater image.
void renderBoth(const vpCameraParameters &cam, unsigned int width, unsigned int height, const vpSSLWaterModel *water,
                vpImage<unsigned char> &I)
{
  vpSSLRenderer renderer(cam, width, height);
  vpImage<float> reflectance, range, tagReflectance, tagRange;
  renderer.setTarget(vpSSLTarget::ssl3a3());
  renderer.render(sslPose(), reflectance, range);
  renderer.setAprilTagSheet(vpSSLAprilTagSheet::a3(0));
  renderer.render(tagPose(), tagReflectance, tagRange);
  for (unsigned int i = 0; i < reflectance.getSize(); ++i) {
    if (tagRange.bitmap[i] < range.bitmap[i]) {
      reflectance.bitmap[i] = tagReflectance.bitmap[i];
      range.bitmap[i] = tagRange.bitmap[i];
    }
  }
  if (water != nullptr) {
    water->apply(reflectance, range, cam, 0., 1, I);
    return;
  }
  I.resize(height, width);
  for (unsigned int i = 0; i < reflectance.getSize(); ++i) {
    I.bitmap[i] = static_cast<unsigned char>(std::lround(255. * std::min(1.f, std::max(0.f, reflectance.bitmap[i]))));
  }
}

// The frames by name: "WxH" (in air), "640x480 underwater", "640x480 AprilTag.pgm" (ViSP's photograph).
const Frame &frame(const std::string &name)
{
  static std::map<std::string, Frame> cache;
  auto it = cache.find(name);
  if (it != cache.end()) {
    return it->second;
  }
  Frame &f = cache[name];
  if (name == "640x480 AprilTag.pgm") {
    vpImageIo::read(f.I, std::string(VISP_SSL_IMAGES_DIR) + "/AprilTag/AprilTag.pgm");
  } else {
    unsigned int width = 0, height = 0;
    std::sscanf(name.c_str(), "%ux%u", &width, &height);
    const vpCameraParameters cam = camera(width, height);
    const bool underwater = name.find("underwater") != std::string::npos;
    const vpSSLWaterModel water = vpSSLWaterModel::preset("clear");
    renderBoth(cam, width, height, underwater ? &water : nullptr, f.I);
    vpSSLRenderer renderer(cam, width, height);
    for (const vpImagePoint &c : renderer.projectLandmarks(sslPose())) {
      f.rois.push_back(vpRect(c.get_u() - 50., c.get_v() - 50., 100., 100.));
      f.off.push_back(vpRect(c.get_u() - 30., c.get_v() - 50., 100., 100.));
    }
  }
  f.blank.resize(f.I.getHeight(), f.I.getWidth(), 128);
  return f;
}

// Every timed iteration, by table row, for medians; the frame and thread count of each row, for the ratios.
std::map<std::string, std::vector<double>> &samples()
{
  static std::map<std::string, std::vector<double>> s;
  return s;
}
struct RowInfo
{
  std::string frame;
  unsigned int threads = 1;
  std::string note; // what the row's regions of interest did
};
std::map<std::string, RowInfo> &rows()
{
  static std::map<std::string, RowInfo> r;
  return r;
}
std::map<std::string, vpSSLDetectorTimes> &stageTimes()
{
  static std::map<std::string, vpSSLDetectorTimes> s;
  return s;
}

std::string threadsName(unsigned int threads)
{
  return threads == 1 ? "1 thread" : std::to_string(threads) + " threads";
}
// The name of the row "DETECTOR | FRAME | N threads".
std::string rowName(const std::string &detector, const std::string &frameName, unsigned int threads)
{
  return detector + " | " + frameName + " | " + threadsName(threads);
}
// The same, recorded with its frame and thread count.
std::string row(const std::string &detector, const std::string &frameName, unsigned int threads)
{
  const std::string name = rowName(detector, frameName, threads);
  rows()[name].frame = frameName;
  rows()[name].threads = threads;
  return name;
}

// Times run() per iteration; \e forget, when given, runs before each one with the timers paused.
template <typename F>
void timeLoop(benchmark::State &state, const std::string &name, F &&run, const std::function<void()> &forget = nullptr)
{
  std::vector<double> &s = samples()[name];
  for (auto _ : state) {
    if (forget) {
      state.PauseTiming();
      forget();
      state.ResumeTiming();
    }
    const auto t0 = std::chrono::steady_clock::now();
    run();
    s.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  state.counters["fps"] = benchmark::Counter(1., benchmark::Counter::kIsIterationInvariantRate);
}

const std::vector<std::string> kFrames = {
    "320x240", "640x480", "1280x720", "1920x1080", "640x480 underwater", "640x480 AprilTag.pgm"};

enum RoiMode
{
  FULL_FRAME = 0,   // no region of interest
  FAST_CENTRED = 1, // tracker fast path, regions centred on the previous landmarks
  FAST_OFF = 2,     // tracker fast path, regions 20 px off
  PAPER_ROI = 3     // the paper's ROI mode: every region matched, no previous landmark
};

/*
  range: frame (index in kFrames), threads (0: all cores), RoiMode, decimation of the matching pass (1/2).
*/
void BM_SSL(benchmark::State &state)
{
  const std::string frameName = kFrames[static_cast<size_t>(state.range(0))];
  const unsigned int threads = state.range(1) == 0 ? allThreads() : 1u;
  const RoiMode mode = static_cast<RoiMode>(state.range(2));
  const unsigned int decimation = static_cast<unsigned int>(state.range(3));
  const Frame &f = frame(frameName);
  const bool photo = frameName.find("AprilTag.pgm") != std::string::npos;
  vpSSLDetector detector;
  detector.setNbThreads(threads);
  detector.setDecimation(decimation);
  detector.detect(f.I); // a full search first: the previous landmarks of the fast path
  if (!photo && !detector.getTargetMatch().found) {
    state.SkipWithError("ssl3-a3 not identified in the rendered frame");
    return;
  }
  std::string detectorName = "SSL full frame", note;
  if (mode != FULL_FRAME) {
    detector.setRegionsOfInterest(mode == FAST_OFF ? f.off : f.rois);
    if (mode == PAPER_ROI) {
      detector.detect(f.blank);
    }
    detector.detect(f.I);
    const size_t matched = vpSSLDetectorTestAccess::getMatchedRegions(detector).size();
    const size_t map = vpSSLDetectorTestAccess::getMapRegions(detector).size();
    const size_t reread = f.rois.size() - matched;
    const size_t decimated = decimation == 2 ? matched : matched - map, full = decimation == 2 ? 0 : map;
    if (!detector.getTargetMatch().found || (mode == PAPER_ROI && matched != f.rois.size())) {
      state.SkipWithError("ssl3-a3 not identified from the regions of interest");
      return;
    }
    detectorName = mode == FAST_CENTRED ? "SSL tracker fast path, 3 ROIs 100x100 centred"
                   : mode == FAST_OFF   ? "SSL tracker fast path, 3 ROIs 100x100 20 px off"
                                        : "SSL paper ROI mode, 3 ROIs 100x100 matched";
    note = std::to_string(reread) + " re-read, " + std::to_string(decimated) + " matched decimated, " +
           std::to_string(full) + " matched at full resolution";
  }
  const std::string name = row(detectorName + (decimation == 2 ? ", decimation 2" : ""), frameName, threads);
  rows()[name].note = note;
  vpSSLDetectorTimes sum;
  long n = 0;
  auto run = [&] {
    detector.detect(f.I);
    const vpSSLDetectorTimes &t = detector.getTimes();
    sum.normalization += t.normalization;
    sum.matching += t.matching;
    sum.peaks += t.peaks;
    sum.radius += t.radius;
    sum.identification += t.identification;
    sum.total += t.total;
    ++n;
  };
  timeLoop(state, name, run, mode == PAPER_ROI ? std::function<void()>([&] { detector.detect(f.blank); }) : nullptr);
  vpSSLDetectorTimes &mean = stageTimes()[name];
  const double k = n > 0 ? 1. / n : 0.;
  mean.normalization = sum.normalization * k;
  mean.matching = sum.matching * k;
  mean.peaks = sum.peaks * k;
  mean.radius = sum.radius * k;
  mean.identification = sum.identification * k;
  mean.total = sum.total * k;
  state.counters["norm_ms"] = mean.normalization;
  state.counters["match_ms"] = mean.matching;
  state.counters["peaks_ms"] = mean.peaks;
  state.counters["radius_ms"] = mean.radius;
  state.counters["ident_ms"] = mean.identification;
}

void BM_ReferenceMatching(benchmark::State &state)
{
  const Frame &f = frame("640x480");
  const vpSSLMatchingFunction match(40, 0.5);
  vpImage<int> M;
  timeLoop(state, row("Reference matching only", "640x480", 1), [&] {
    match.computeReference(f.I, M);
    benchmark::DoNotOptimize(M.bitmap);
  });
}

// range: frame (index in kFrames), threads (0: all cores), quad decimate.
void BM_AprilTag(benchmark::State &state)
{
  const std::string frameName = kFrames[static_cast<size_t>(state.range(0))];
  const unsigned int threads = state.range(1) == 0 ? allThreads() : 1u;
  vpDetectorAprilTag detector(vpDetectorAprilTag::TAG_36h11);
  detector.setAprilTagNbThreads(static_cast<int>(threads));
  detector.setAprilTagQuadDecimate(static_cast<float>(state.range(2)));
  vpImage<unsigned char> I = frame(frameName).I; // detect() takes a non-const image
  if (!detector.detect(I)) {
    state.SkipWithError("AprilTag not detected in the frame");
    return;
  }
  timeLoop(state, row("AprilTag 36h11 decimate " + std::to_string(state.range(2)), frameName, threads),
           [&] { benchmark::DoNotOptimize(detector.detect(I)); });
}

// range: frame (index in kFrames).
void BM_ArUco(benchmark::State &state)
{
  const std::string frameName = kFrames[static_cast<size_t>(state.range(0))];
  cv::Mat image;
  vpImageConvert::convert(frame(frameName).I, image);
  const cv::Ptr<cv::aruco::Dictionary> dictionary = cv::aruco::getPredefinedDictionary(cv::aruco::DICT_APRILTAG_36h11);
  const cv::Ptr<cv::aruco::DetectorParameters> parameters = cv::aruco::DetectorParameters::create();
  std::vector<std::vector<cv::Point2f>> corners;
  std::vector<int> ids;
  const int threads = cv::getNumThreads();
  cv::setNumThreads(1);
  cv::aruco::detectMarkers(image, dictionary, corners, ids, parameters);
  if (ids.size() != 1) {
    cv::setNumThreads(threads);
    state.SkipWithError("ArUco did not detect the tag in the rendered frame");
    return;
  }
  timeLoop(state, row("cv::aruco APRILTAG_36h11", frameName, 1),
           [&] { cv::aruco::detectMarkers(image, dictionary, corners, ids, parameters); });
  cv::setNumThreads(threads);
}

void sslArgs(benchmark::internal::Benchmark *b)
{
  for (int64_t i = 0; i < static_cast<int64_t>(kFrames.size()); ++i) {
    for (int threads : {1, 0}) {
      b->Args({i, threads, FULL_FRAME, 1});
      if (kFrames[static_cast<size_t>(i)] != "320x240") { // 15 px landmarks: below the decimated pass's envelope
        b->Args({i, threads, FULL_FRAME, 2});
      }
    }
  }
  for (int64_t mode : {FAST_CENTRED, FAST_OFF, PAPER_ROI}) {
    for (int64_t decimation : {1, 2}) {
      b->Args({1, 1, mode, decimation});
    }
  }
}
void aprilTagArgs(benchmark::internal::Benchmark *b)
{
  for (int64_t i = 0; i < static_cast<int64_t>(kFrames.size()); ++i) {
    for (int threads : {1, 0}) {
      for (int decimate : {2, 1}) {
        b->Args({i, threads, decimate});
      }
    }
  }
}

BENCHMARK(BM_SSL)->Apply(sslArgs)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ReferenceMatching)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_AprilTag)->Apply(aprilTagArgs)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ArUco)->DenseRange(0, 4)->Unit(benchmark::kMillisecond)->UseRealTime();

double median(std::vector<double> v)
{
  if (v.empty()) {
    return 0.;
  }
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// The paper's Table 1 (frames per second), where it has the same case.
std::string paperFps(const std::string &name, const RowInfo &info)
{
  if (info.threads != 1 || name.find("decimation 2") != std::string::npos) {
    return "";
  }
  if (name.rfind("SSL full frame |", 0) == 0 && info.frame == "640x480") {
    return "2.1 (P-M) / 2.8 (P-IV)";
  }
  if (name.rfind("SSL full frame |", 0) == 0 && info.frame == "320x240") {
    return "8.9 (P-M) / 11.1 (P-IV)";
  }
  if (name.rfind("SSL paper ROI mode", 0) == 0 && info.frame == "640x480") {
    return "6.8 (P-M, 640x480)";
  }
  return "";
}

// t / AprilTag's median on the same frame with the same thread count and quad decimate \e decimate, this run.
std::string ratio(double ms, const RowInfo &info, int decimate)
{
  const auto at =
      samples().find(rowName("AprilTag 36h11 decimate " + std::to_string(decimate), info.frame, info.threads));
  if (at == samples().end() || at->second.empty() || ms <= 0.) {
    return "";
  }
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.2f", ms / median(at->second));
  return buf;
}

void printTable()
{
  std::printf("\nSIMD target: %s; all cores: %u threads\n\n", vpSSLMatchingFunction::getSimdTarget().c_str(),
              allThreads());
  std::printf("| %-58s | %-20s | %-10s | %9s | %8s | %9s | %9s | %-22s |\n", "detector", "frame", "threads",
              "median ms", "fps", "t / AT d2", "t / AT d1", "paper Table 1 fps");
  std::printf("|%s|%s|%s|%s|%s|%s|%s|%s|\n", std::string(60, '-').c_str(), std::string(22, '-').c_str(),
              std::string(12, '-').c_str(), std::string(11, '-').c_str(), std::string(10, '-').c_str(),
              std::string(11, '-').c_str(), std::string(11, '-').c_str(), std::string(24, '-').c_str());
  for (const auto &entry : samples()) {
    const RowInfo &info = rows()[entry.first];
    const double ms = median(entry.second);
    const std::string detector = entry.first.substr(0, entry.first.find(" | "));
    const bool aprilTag = detector.rfind("AprilTag", 0) == 0;
    std::printf("| %-58s | %-20s | %-10s | %9.3f | %8.1f | %9s | %9s | %-22s |\n", detector.c_str(), info.frame.c_str(),
                threadsName(info.threads).c_str(), ms, ms > 0. ? 1000. / ms : 0.,
                aprilTag ? "" : ratio(ms, info, 2).c_str(), aprilTag ? "" : ratio(ms, info, 1).c_str(),
                paperFps(entry.first, info).c_str());
  }

  std::printf("\nRegions of interest (640x480, 1 thread): what the detector did in them, and the speed-up over the "
              "full frame at the same decimation\n");
  for (const auto &entry : rows()) {
    if (entry.second.note.empty() || samples()[entry.first].empty()) {
      continue;
    }
    const bool decimated = entry.first.find("decimation 2") != std::string::npos;
    const auto full = samples().find(rowName(std::string("SSL full frame") + (decimated ? ", decimation 2" : ""),
                                             entry.second.frame, entry.second.threads));
    const double roi = median(samples()[entry.first]);
    std::printf("| %-58s | %-52s | %5.1fx |\n", entry.first.substr(0, entry.first.find(" | ")).c_str(),
                entry.second.note.c_str(), full != samples().end() && roi > 0. ? median(full->second) / roi : 0.);
  }

  std::printf("\nSSL stages (mean ms): normalisation, matching, peaks, radius (ring reading), identification\n");
  for (const auto &entry : stageTimes()) {
    const vpSSLDetectorTimes &t = entry.second;
    std::printf("| %-90s | %6.3f | %6.3f | %6.3f | %6.3f | %6.3f | total %6.3f |\n", entry.first.c_str(),
                t.normalization, t.matching, t.peaks, t.radius, t.identification, t.total);
  }
}
} // namespace

int main(int argc, char **argv)
{
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
    return 1;
  }
  benchmark::AddCustomContext("simd_target", vpSSLMatchingFunction::getSimdTarget());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  printTable();
  return 0;
}

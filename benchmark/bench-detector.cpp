/*
  The whole detector (paper Sec. 3, Table 1) against ViSP's AprilTag detector and OpenCV's ArUco detector, on
  the same rendered views: ssl3-a3 and an A3 AprilTag 36h11 sheet (vpSSLAprilTagSheet) at 1 m, slightly turned,
  through a camera of the same field of view at 320x240, 640x480, 1280x720 and 1920x1080.

  Timed: vpSSLDetector::detect() full frame on one thread and on all of them (decimated matching pass, the
  full-resolution default, and at 640x480 also the decimated pass, setDecimation(2)); the same with three 100x100
  regions of interest around the landmarks at 640x480 (the paper's tracking mode); the reference matching
  function alone at 640x480 (the scalar loops the SIMD kernel replaces); vpDetectorAprilTag 36h11 on one
  thread with quad decimate 1 and 2; cv::aruco::detectMarkers with DICT_APRILTAG_36h11 on one thread; and
  SSL and AprilTag on ViSP's real 640x480 AprilTag photograph (no landmark: the clutter case); and SSL and
  AprilTag on the same 640x480 views under water (vpSSLWaterModel "clear", open water behind the sheet, the
  sensor's noise), the frames the detectors meet on a vehicle.

    ./bench-detector --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

  After Google Benchmark's own report, a table of medians (over every timed iteration), frames per second and
  the ratio of each time to AprilTag's with decimate 2 on the frame of the same size, beside the paper's Table 1.
  Reading: doc/benchmarks.md.
*/
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <string>
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
#include <visp3/ssl/vpSSLAprilTagSheet.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl/vpSSLRenderer.h>
#include <visp3/ssl/vpSSLWaterModel.h>

namespace {
// 1 m in front of the camera, turned by a few degrees about each axis: the whole A3 sheet in view.
vpHomogeneousMatrix viewPose()
{
  return vpHomogeneousMatrix(0.02, -0.01, 1.0, vpMath::rad(10.), vpMath::rad(-8.), vpMath::rad(5.));
}

// The same horizontal field of view (56 degrees) at every size.
vpCameraParameters camera(unsigned int width, unsigned int height)
{
  const double f = 600. * width / 640.;
  return vpCameraParameters(f, f, 0.5 * width - 0.5, 0.5 * height - 0.5);
}

struct Frames
{
  vpImage<unsigned char> ssl, tag;
  std::vector<vpRect> rois; // 100x100 around each landmark of the target
};

const Frames &frames(unsigned int width, unsigned int height)
{
  static std::map<std::pair<unsigned int, unsigned int>, Frames> cache;
  auto it = cache.find({width, height});
  if (it != cache.end()) {
    return it->second;
  }
  Frames &f = cache[{width, height}];
  vpSSLRenderer renderer(camera(width, height), width, height);
  renderer.setTarget(vpSSLTarget::ssl3a3());
  renderer.render(viewPose(), f.ssl);
  for (const vpImagePoint &c : renderer.projectLandmarks(viewPose())) {
    f.rois.push_back(vpRect(c.get_u() - 50., c.get_v() - 50., 100., 100.));
  }
  // The tag sheet is rendered at the pose of its tag frame (vpSSLAprilTagSheet).
  renderer.setAprilTagSheet(vpSSLAprilTagSheet::a3(0));
  renderer.render(viewPose() * vpSSLAprilTagSheet::getSheetToTag(), f.tag);
  return f;
}

// The 640x480 views of frames() through clear water (attenuation, backscatter, blur, sensor noise).
const Frames &underwaterFrames()
{
  static Frames f;
  if (f.ssl.getSize() > 0) {
    return f;
  }
  const unsigned int width = 640, height = 480;
  const vpCameraParameters cam = camera(width, height);
  vpSSLRenderer renderer(cam, width, height);
  const vpSSLWaterModel water = vpSSLWaterModel::preset("clear");
  vpImage<float> reflectance, range;
  renderer.setTarget(vpSSLTarget::ssl3a3());
  renderer.render(viewPose(), reflectance, range);
  water.apply(reflectance, range, cam, 0., 1, f.ssl);
  renderer.setAprilTagSheet(vpSSLAprilTagSheet::a3(0));
  renderer.render(viewPose() * vpSSLAprilTagSheet::getSheetToTag(), reflectance, range);
  water.apply(reflectance, range, cam, 0., 1, f.tag);
  return f;
}

// Every timed iteration, by table row, for medians.
std::map<std::string, std::vector<double>> &samples()
{
  static std::map<std::string, std::vector<double>> s;
  return s;
}
std::map<std::string, vpSSLDetectorTimes> &stageTimes()
{
  static std::map<std::string, vpSSLDetectorTimes> s;
  return s;
}

std::string sizeName(int width, int height)
{
  return std::to_string(width) + "x" + std::to_string(height);
}

template <typename F> void timeLoop(benchmark::State &state, const std::string &row, F &&run)
{
  std::vector<double> &s = samples()[row];
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    run();
    s.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  state.counters["fps"] = benchmark::Counter(1., benchmark::Counter::kIsIterationInvariantRate);
}

/*
  range: width, height, threads (0: all cores), regions of interest (0: none; 1: centred on the landmarks, which
  are re-read from there without matching; 2: 20 px off them, too far for that, so the regions are matched as in
  the paper), decimation of the matching pass (1/2).
*/
void BM_SSL(benchmark::State &state)
{
  const int width = static_cast<int>(state.range(0)), height = static_cast<int>(state.range(1));
  const unsigned int threads = static_cast<unsigned int>(state.range(2));
  const bool roi = state.range(3) != 0, off = state.range(3) == 2;
  const unsigned int decimation = static_cast<unsigned int>(state.range(4));
  const Frames &f = frames(width, height);
  vpSSLDetector detector;
  detector.setNbThreads(threads);
  detector.setDecimation(decimation);
  if (roi) {
    std::vector<vpRect> rois;
    for (const vpRect &r : f.rois) {
      rois.push_back(vpRect(r.getLeft() + (off ? 20. : 0.), r.getTop(), r.getWidth(), r.getHeight()));
    }
    detector.setRegionsOfInterest(rois);
  }
  if (!detector.detect(f.ssl) || !detector.getTargetMatch().found) {
    state.SkipWithError("ssl3-a3 not identified in the rendered frame");
    return;
  }
  const std::string row = std::string("SSL ") +
                          (roi ? (off ? "3 ROIs 100x100 off by 20 px " : "3 ROIs 100x100 ") : "full frame ") +
                          sizeName(width, height) + (threads == 1 ? " 1 thread" : " all threads") +
                          (decimation == 2 ? ", decimation 2" : "");
  vpSSLDetectorTimes sum;
  long n = 0;
  timeLoop(state, row, [&] {
    detector.detect(f.ssl);
    const vpSSLDetectorTimes &t = detector.getTimes();
    sum.normalization += t.normalization;
    sum.matching += t.matching;
    sum.peaks += t.peaks;
    sum.radius += t.radius;
    sum.identification += t.identification;
    sum.total += t.total;
    ++n;
  });
  vpSSLDetectorTimes &mean = stageTimes()[row];
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
  const int width = static_cast<int>(state.range(0)), height = static_cast<int>(state.range(1));
  const Frames &f = frames(width, height);
  const vpSSLMatchingFunction match(40, 0.5);
  vpImage<int> M;
  timeLoop(state, "Reference matching only " + sizeName(width, height), [&] {
    match.computeReference(f.ssl, M);
    benchmark::DoNotOptimize(M.bitmap);
  });
}

// range: width, height, quad decimate.
void BM_AprilTag(benchmark::State &state)
{
  const int width = static_cast<int>(state.range(0)), height = static_cast<int>(state.range(1));
  const Frames &f = frames(width, height);
  vpDetectorAprilTag detector(vpDetectorAprilTag::TAG_36h11);
  detector.setAprilTagNbThreads(1);
  detector.setAprilTagQuadDecimate(static_cast<float>(state.range(2)));
  vpImage<unsigned char> I = f.tag; // detect() takes a non-const image
  if (!detector.detect(I) || detector.getNbObjects() != 1) {
    state.SkipWithError("AprilTag not detected in the rendered frame");
    return;
  }
  timeLoop(state, "AprilTag 36h11 decimate " + std::to_string(state.range(2)) + " " + sizeName(width, height),
           [&] { benchmark::DoNotOptimize(detector.detect(I)); });
}

// ViSP's own 640x480 AprilTag photograph (real camera, several tags, clutter): AprilTag and SSL (no landmark).
void BM_AprilTagImage(benchmark::State &state)
{
  vpImage<unsigned char> I;
  vpImageIo::read(I, std::string(VISP_SSL_IMAGES_DIR) + "/AprilTag/AprilTag.pgm");
  const std::string size = sizeName(static_cast<int>(I.getWidth()), static_cast<int>(I.getHeight()));
  if (state.range(0) <= 0) {
    vpSSLDetector detector;
    detector.setNbThreads(1);
    detector.setDecimation(state.range(0) == 0 ? 1 : 2);
    timeLoop(state,
             "SSL full frame " + size + " 1 thread, AprilTag.pgm" + (state.range(0) == 0 ? "" : ", decimation 2"),
             [&] { detector.detect(I); });
    return;
  }
  vpDetectorAprilTag detector(vpDetectorAprilTag::TAG_36h11);
  detector.setAprilTagNbThreads(1);
  detector.setAprilTagQuadDecimate(static_cast<float>(state.range(0)));
  timeLoop(state, "AprilTag 36h11 decimate " + std::to_string(state.range(0)) + " " + size + ", AprilTag.pgm",
           [&] { benchmark::DoNotOptimize(detector.detect(I)); });
}

// range: 0 SSL, 1 SSL with decimation 2, 2 AprilTag decimate 2, 3 AprilTag decimate 1; on the underwater views.
void BM_Underwater(benchmark::State &state)
{
  const Frames &f = underwaterFrames();
  const int which = static_cast<int>(state.range(0));
  if (which < 2) {
    vpSSLDetector detector;
    detector.setNbThreads(1);
    detector.setDecimation(which == 0 ? 1 : 2);
    if (!detector.detect(f.ssl) || !detector.getTargetMatch().found) {
      state.SkipWithError("ssl3-a3 not identified in the underwater frame");
      return;
    }
    timeLoop(state,
             std::string("SSL full frame 640x480 1 thread") + (which == 0 ? "" : ", decimation 2") + ", underwater",
             [&] { detector.detect(f.ssl); });
    return;
  }
  vpDetectorAprilTag detector(vpDetectorAprilTag::TAG_36h11);
  detector.setAprilTagNbThreads(1);
  detector.setAprilTagQuadDecimate(which == 2 ? 2.f : 1.f);
  vpImage<unsigned char> I = f.tag;
  if (!detector.detect(I)) {
    state.SkipWithError("AprilTag not detected in the underwater frame");
    return;
  }
  timeLoop(state, std::string("AprilTag 36h11 decimate ") + (which == 2 ? "2" : "1") + " 640x480, underwater",
           [&] { benchmark::DoNotOptimize(detector.detect(I)); });
}

void BM_ArUco(benchmark::State &state)
{
  const int width = static_cast<int>(state.range(0)), height = static_cast<int>(state.range(1));
  const Frames &f = frames(width, height);
  cv::Mat image;
  vpImageConvert::convert(f.tag, image);
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
  timeLoop(state, "cv::aruco APRILTAG_36h11 " + sizeName(width, height),
           [&] { cv::aruco::detectMarkers(image, dictionary, corners, ids, parameters); });
  cv::setNumThreads(threads);
}

const std::vector<std::vector<int64_t>> kSizes = {{320, 240}, {640, 480}, {1280, 720}, {1920, 1080}};

void sslArgs(benchmark::internal::Benchmark *b)
{
  for (const auto &s : kSizes) {
    for (int threads : {1, 0}) {
      b->Args({s[0], s[1], threads, 0, 1});
    }
  }
  b->Args({640, 480, 1, 1, 1});
  b->Args({640, 480, 1, 2, 1});
  b->Args({640, 480, 0, 1, 1});
  // The decimated matching pass (setDecimation(2)), like AprilTag's quad decimate.
  b->Args({640, 480, 1, 0, 2});
  b->Args({640, 480, 0, 0, 2});
  b->Args({640, 480, 1, 1, 2});
  b->Args({640, 480, 1, 2, 2});
}
void aprilTagArgs(benchmark::internal::Benchmark *b)
{
  for (const auto &s : kSizes) {
    for (int decimate : {1, 2}) {
      b->Args({s[0], s[1], decimate});
    }
  }
}
void sizeArgs(benchmark::internal::Benchmark *b)
{
  for (const auto &s : kSizes) {
    b->Args({s[0], s[1]});
  }
}

BENCHMARK(BM_SSL)->Apply(sslArgs)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ReferenceMatching)->Args({640, 480})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_AprilTag)->Apply(aprilTagArgs)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_AprilTagImage)->Arg(-1)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Underwater)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ArUco)->Apply(sizeArgs)->Unit(benchmark::kMillisecond)->UseRealTime();

double median(std::vector<double> v)
{
  if (v.empty()) {
    return 0.;
  }
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// The paper's Table 1 (frames per second), where it has the same case.
std::string paperFps(const std::string &row)
{
  if (row.rfind("SSL full frame 640x480 1 thread", 0) == 0 && row.find("AprilTag.pgm") == std::string::npos &&
      row.find("underwater") == std::string::npos) {
    return "2.1 (P-M) / 2.8 (P-IV)";
  }
  if (row.rfind("SSL full frame 320x240 1 thread", 0) == 0) {
    return "8.9 (P-M) / 11.1 (P-IV)";
  }
  if (row.rfind("SSL 3 ROIs 100x100 640x480", 0) == 0 || row.rfind("SSL 3 ROIs 100x100 off by 20 px 640x480", 0) == 0) {
    return "6.8 (P-M, 640x480)";
  }
  return "";
}

void printTable()
{
  std::printf("\nSIMD target: %s\n\n", vpSSLMatchingFunction::getSimdTarget().c_str());
  std::printf("| %-44s | %9s | %8s | %12s | %-24s |\n", "case", "median ms", "fps", "t / AT dec 2",
              "paper Table 1 fps");
  std::printf("|%s|%s|%s|%s|%s|\n", std::string(46, '-').c_str(), std::string(11, '-').c_str(),
              std::string(10, '-').c_str(), std::string(14, '-').c_str(), std::string(26, '-').c_str());
  for (const auto &entry : samples()) {
    const double ms = median(entry.second);
    std::string ratio;
    for (const auto &s : kSizes) {
      const std::string size = sizeName(static_cast<int>(s[0]), static_cast<int>(s[1]));
      if (entry.first.find(size) == std::string::npos) {
        continue;
      }
      const std::string suffix = entry.first.find("AprilTag.pgm") != std::string::npos ? ", AprilTag.pgm"
                                 : entry.first.find("underwater") != std::string::npos ? ", underwater"
                                                                                       : "";
      auto at = samples().find("AprilTag 36h11 decimate 2 " + size + suffix);
      if (at != samples().end() && ms > 0.) {
        char buf[32];
        std::snprintf(buf, sizeof(buf), "%.2f", ms / median(at->second));
        ratio = buf;
      }
    }
    std::printf("| %-44s | %9.3f | %8.1f | %12s | %-24s |\n", entry.first.c_str(), ms, ms > 0. ? 1000. / ms : 0.,
                ratio.c_str(), paperFps(entry.first).c_str());
  }
  const auto full = samples().find("SSL full frame 640x480 1 thread");
  const auto roi = samples().find("SSL 3 ROIs 100x100 640x480 1 thread");
  if (full != samples().end() && roi != samples().end() && median(roi->second) > 0.) {
    std::printf("\nTracking mode (3 ROIs) speed-up over the full frame, 640x480, 1 thread: %.1fx\n",
                median(full->second) / median(roi->second));
  }
  const auto off = samples().find("SSL 3 ROIs 100x100 off by 20 px 640x480 1 thread");
  if (full != samples().end() && off != samples().end() && median(off->second) > 0.) {
    std::printf("The same with the regions 20 px off the landmarks (matched, as in the paper): %.1fx\n",
                median(full->second) / median(off->second));
  }
  const auto full2 = samples().find("SSL full frame 640x480 1 thread, decimation 2");
  const auto roi2 = samples().find("SSL 3 ROIs 100x100 640x480 1 thread, decimation 2");
  if (full2 != samples().end() && roi2 != samples().end() && median(roi2->second) > 0.) {
    std::printf("The same with decimation 2: %.1fx\n", median(full2->second) / median(roi2->second));
  }
  std::printf("\nSSL stages (mean ms): normalisation, matching, peaks, radius (ring reading), identification\n");
  for (const auto &entry : stageTimes()) {
    const vpSSLDetectorTimes &t = entry.second;
    std::printf("| %-44s | %6.3f | %6.3f | %6.3f | %6.3f | %6.3f | total %6.3f |\n", entry.first.c_str(),
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

//! \example tutorial-ssl-detector-recall.cpp
//! Measures vpSSLDetector on the independent evaluation corpus (visp_ssl_bench): random underwater views of the
//! ssl3-a3 sheet, made by an image path that shares no code with the simulator, and negatives; prints the recall
//! tables in Markdown and writes one CSV row per view and landmark.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <visp3/core/vpImageConvert.h>
#include <visp3/core/vpImageDraw.h>
#include <visp3/core/vpIoTools.h>
#include <visp3/detection/vpDetectorAprilTag.h>
#include <visp3/io/vpImageIo.h>
#include <visp3/ssl/vpSSLConcentricReader.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl_bench/vpSSLCorpusEvaluator.h>
#include <visp3/ssl_bench/vpSSLCorpusPhotos.h>
#include <visp3/ssl_bench/vpSSLCorpusSheet.h>
#include <visp3/ssl_bench/vpSSLCorpusView.h>

#include "ssl_tutorial_common.h"
#include "ssl_tutorial_options.h"

namespace {
const char *kUsage = R"(Usage: tutorial-ssl-detector-recall [options]

Renders random underwater views of the ssl3-a3 sheet (the independent corpus of visp_ssl_bench:
its own sheet raster, camera, water and sensor, nothing shared with vpSSLRenderer) and negatives
without it, runs vpSSLDetector on each and prints the recall of B, S1 and S2 by view angle,
radius, range / visibility, blur, minor semi-axis over blur (all views, and within 60 degrees of
the normal), contrast over noise, water, surroundings, occlusion and JPEG quality (Markdown),
the centre and radius errors, false landmarks and false targets.

Options:
  --views N          Views with the target (default 200).
  --negatives N      Views without it (default 50).
  --seed S           Corpus seed (default 1): the same seed gives the same views.
  --threads T        Views rendered and detected in parallel (default 1); each detector runs
                     on one thread, so the figures do not depend on T.
  --output-dir DIR   Where the CSV (corpus.csv, one row per view x landmark) and the saved
                     images go (default corpus-out).
  --save-images K    Write the first K target views (and the first K negatives) as PNG:
                     view-NNNNN.png (the grey image the detector reads) and
                     view-NNNNN-annotated.png (truth green, detections red), with
                     images-truth.csv (default 0); with --apriltag, also the tag rendering
                     view-NNNNN-apriltag.png.
  --save-misses K    Write the first K views whose eligible B was missed, the same way, as
                     miss-NNNNN*.png (default 0).
  --explain-misses   For every eligible landmark the detector missed, read its rings with
                     vpSSLConcentricReader from its true centre and print where that reading
                     stops (read there: the candidates missed it; the ring fit; the phase; the
                     outer ring), with misses.csv (one row per missed landmark).
  --decimation D     vpSSLDetector::setDecimation (1 or 2, default 1).
  --small-landmarks  vpSSLDetector::setSmallLandmarkMode(true).
  --no-equal-rings   vpSSLDetector::setEqualRingCheck(false) (on by default).
  --no-blur-model    vpSSLDetector::setBlurredRingModel(false) (on by default).
  --no-target-completion
                     vpSSLDetector::setTargetCompletion(false) (on by default).
  --all-around-budget N
                     vpSSLDetector::setAllAroundBudget(N), 0 to 100000 (default 24).
  --apriltag         Also render every view with an AprilTag 36h11 (id 0, 0.2376 m side,
                     centred where the SSL sheet is) instead of the SSL sheet, and run
                     vpDetectorAprilTag (36h11, quad decimate 2, one thread) on it: the tables
                     gain the target and AprilTag columns, on B's bins.
  --help             This help.

Exit status: 0 on success, 2 on a bad option or value, 1 on an error while running (one
line on stderr: out of memory, an image that cannot be written).
)";

// Largest count of views, of negatives and of saved images: a run's results are held in memory.
const long long kMaxViews = 100000;

struct Options
{
  unsigned int views = 200, negatives = 50, threads = 1, saveImages = 0, saveMisses = 0, decimation = 1;
  unsigned long long seed = 1;
  std::string outputDir = "corpus-out";
  bool small = false, equalRings = true, blurModel = true, completion = true, apriltag = false, explainMisses = false;
  long long allAroundBudget = -1; // -1: the detector's default
};

// Reads the command line into \e o. \exception ssltut::UsageError on a bad option or value (exit status 2).
void parse(int argc, char **argv, Options &o)
{
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    // An option's value, and a numeric one in [lo, hi]; else a UsageError naming the option (exit status 2).
    auto value = [&]() { return ssltut::optionValue(argc, argv, i, ssltut::MissingValue::SeeHelp); };
    auto integer = [&](long long lo, long long hi) { return ssltut::parseInteger("option " + a, value(), lo, hi); };
    if (a == "--help" || a == "-h") {
      std::cout << kUsage;
      std::exit(0);
    } else if (a == "--views") {
      o.views = static_cast<unsigned int>(integer(0, kMaxViews));
    } else if (a == "--negatives") {
      o.negatives = static_cast<unsigned int>(integer(0, kMaxViews));
    } else if (a == "--seed") {
      o.seed = static_cast<unsigned long long>(integer(0, std::numeric_limits<long long>::max()));
    } else if (a == "--threads") {
      o.threads = ssltut::parseThreads(a, value(), false, 256);
    } else if (a == "--save-images") {
      o.saveImages = static_cast<unsigned int>(integer(0, kMaxViews));
    } else if (a == "--save-misses") {
      o.saveMisses = static_cast<unsigned int>(integer(0, kMaxViews));
    } else if (a == "--decimation") {
      o.decimation = static_cast<unsigned int>(integer(1, 2));
    } else if (a == "--output-dir") {
      o.outputDir = value();
    } else if (a == "--small-landmarks") {
      o.small = true;
    } else if (a == "--no-equal-rings") {
      o.equalRings = false;
    } else if (a == "--no-blur-model") {
      o.blurModel = false;
    } else if (a == "--no-target-completion") {
      o.completion = false;
    } else if (a == "--all-around-budget") {
      o.allAroundBudget = integer(0, 100000);
    } else if (a == "--explain-misses") {
      o.explainMisses = true;
    } else if (a == "--apriltag") {
      o.apriltag = true;
    } else {
      throw ssltut::UsageError("bad option or value: " + a + " (see --help)");
    }
  }
}

// The true tag corners (px) of a view: the sheet's square through the view's homography.
std::vector<vpImagePoint> tagCorners(const vpSSLCorpusViewParams &p, const vpSSLCorpusSheet &tag)
{
  const cv::Matx33d H = vpSSLCorpusView::homography(p);
  const double h = 0.5 * tag.getTagSize();
  const double x[4] = {-h, h, h, -h}, y[4] = {-h, -h, h, h};
  std::vector<vpImagePoint> c;
  for (int i = 0; i < 4; ++i) {
    const cv::Vec3d q = H * cv::Vec3d(tag.getTagX() + x[i], tag.getTagY() + y[i], 1.);
    if (q[2] <= 0.)
      return std::vector<vpImagePoint>();
    c.push_back(vpImagePoint(q[1] / q[2], q[0] / q[2]));
  }
  return c;
}

std::vector<vpImagePoint> ellipse(double u, double v, double a, double b, double theta)
{
  std::vector<vpImagePoint> pts;
  for (int k = 0; k < 64; ++k) {
    const double t = 2. * M_PI * k / 64.;
    const double x = a * std::cos(t), y = b * std::sin(t);
    pts.push_back(
        vpImagePoint(v + x * std::sin(theta) + y * std::cos(theta), u + x * std::cos(theta) - y * std::sin(theta)));
  }
  return pts;
}

// The grey image and a colour copy with the truth (green: outer ellipse and centre) and the detections (red).
void save(const std::string &stem, const vpImage<unsigned char> &I, const vpSSLCorpusViewResult &r,
          const vpSSLDetector &detector)
{
  vpImageIo::write(I, stem + ".png");
  vpImage<vpRGBa> C;
  vpImageConvert::convert(I, C);
  for (const vpSSLCorpusLandmarkTruth &t : r.truth) {
    if (!t.isEllipse)
      continue;
    vpImageDraw::drawPolygon(C, ellipse(t.ellipseU, t.ellipseV, t.a, t.b, t.theta), vpColor::green, 1, true);
    vpImageDraw::drawCross(C, vpImagePoint(t.v, t.u), 7, vpColor::green, 1);
  }
  for (const vpSSLLandmark &l : detector.getLandmarks()) {
    vpImageDraw::drawPolygon(C, ellipse(l.u, l.v, l.radius, l.minorRadius, l.theta), vpColor::red, 1, true);
    vpImageDraw::drawCross(C, vpImagePoint(l.v, l.u), 5, vpColor::red, 1);
  }
  vpImageIo::write(C, stem + "-annotated.png");
}

// Where the rings of each eligible landmark the detector missed stop being read, from the landmark's true centre:
// a miss read there is the candidates' (no matching-map peak near it, the symmetric centre off, the all-around
// budget spent) or the checks' after the reading; the others fail in the reader's own stages. One row per missed
// landmark in misses.csv, and a Markdown table.
void explainMisses(const std::vector<vpSSLCorpusViewResult> &results, const vpSSLTarget &target,
                   const vpSSLCorpusSheet &sheet, const vpSSLCorpusPhotos &photos, const Options &o)
{
  vpSSLConcentricReader reader;
  reader.setP(target.getP());
  reader.setBlurredRingModel(o.blurModel);
  vpSSLCorpusView view(target);
  std::ofstream csv(o.outputDir + "/misses.csv");
  csv << "view,landmark,a_px,b_px,blur_sigma_px,contrast_over_noise,view_angle_deg,stage,read,read_radius_px\n";
  // Per landmark name: missed, read (of which within 10 % of the radius), stopped at stage 1, 2, 3, 4.
  std::vector<std::string> names;
  for (const vpSSLTargetLandmark &m : target.getLandmarks())
    names.push_back(m.name);
  std::vector<std::vector<unsigned int>> counts(names.size(), std::vector<unsigned int>(7, 0));
  for (const vpSSLCorpusViewResult &r : results) {
    bool rendered = false;
    for (size_t k = 0; k < r.truth.size() && k < r.results.size(); ++k) {
      const vpSSLCorpusLandmarkTruth &t = r.truth[k];
      if (!t.eligible() || r.results[k].found)
        continue;
      if (!rendered) {
        view.render(r.params, &sheet, photos);
        rendered = true;
      }
      vpSSLLandmark l;
      l.u = t.u;
      l.v = t.v;
      const bool read = reader.read(view.getImage(), l);
      const int stage = reader.getStage();
      const bool radiusOk = read && std::fabs(l.radius / t.a - 1.) <= 0.1;
      size_t n = 0;
      while (n < names.size() && names[n] != t.name)
        ++n;
      if (n == names.size())
        continue; // not a landmark of the target
      std::vector<unsigned int> &c = counts[n];
      ++c[0];
      c[1] += read ? 1 : 0;
      c[2] += radiusOk ? 1 : 0;
      if (!read)
        ++c[2 + std::min(4, std::max(1, stage))];
      char row[256];
      std::snprintf(row, sizeof(row), "%u,%s,%.4f,%.4f,%.3f,%.3f,%.2f,%d,%d,%.4f\n", r.index, t.name.c_str(), t.a, t.b,
                    t.blurSigma, t.contrastOverNoise, t.viewAngle, stage, read ? 1 : 0, read ? l.radius : 0.);
      csv << row;
    }
  }
  std::cout
      << "\n#### Eligible landmarks missed, read with vpSSLConcentricReader from their true centre\n\n"
      << "| landmark | missed | read there | of which radius within 10 % | ring fit does not lock | under a period "
         "of rings | no outer ring | outside the radius range |\n|---|---|---|---|---|---|---|---|\n";
  for (size_t n = 0; n < names.size(); ++n) {
    const std::vector<unsigned int> &c = counts[n];
    std::cout << "| " << names[n] << " | " << c[0] << " | " << c[1] << " | " << c[2] << " | " << c[3] << " | " << c[4]
              << " | " << c[5] << " | " << c[6] << " |\n";
  }
}

void configure(vpSSLDetector &d, const Options &o)
{
  d.setNbThreads(1);
  d.setDecimation(o.decimation);
  d.setSmallLandmarkMode(o.small);
  d.setEqualRingCheck(o.equalRings);
  d.setBlurredRingModel(o.blurModel);
  d.setTargetCompletion(o.completion);
  if (o.allAroundBudget >= 0)
    d.setAllAroundBudget(static_cast<unsigned int>(o.allAroundBudget));
}
} // namespace

int run(int argc, char **argv)
{
  Options o;
  parse(argc, argv, o);
  const auto t0 = std::chrono::steady_clock::now();
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  vpSSLCorpusPhotos photos;
  if (photos.load() == 0)
    std::cerr << "tutorial-ssl-detector-recall: " << photos.getMessage() << std::endl;
  const vpSSLCorpusSheet sheet = vpSSLCorpusSheet::sslTarget(target);
  vpSSLCorpusSheet tagSheet;
  if (o.apriltag)
    tagSheet = vpSSLCorpusSheet::aprilTag(0, 0.2376, target.getSheetCenterX(), target.getSheetCenterY(),
                                          target.getSheetWidth(), target.getSheetHeight(), target.getSheetCenterX(),
                                          target.getSheetCenterY());
  vpIoTools::makeDirectory(o.outputDir);

  const unsigned int total = o.views + o.negatives;
  std::vector<vpSSLCorpusViewResult> results(total);
  std::atomic<unsigned int> next(0);
  std::mutex ioMutex;
  auto worker = [&]() {
    vpSSLDetector detector(target);
    configure(detector, o);
    vpDetectorAprilTag tags(vpDetectorAprilTag::TAG_36h11);
    tags.setAprilTagQuadDecimate(2.f);
    tags.setAprilTagNbThreads(1);
    vpSSLCorpusView view(target), tagView(target);
    for (unsigned int j = next++; j < total; j = next++) {
      const bool positive = j < o.views;
      const unsigned int index = positive ? j : j - o.views;
      vpSSLCorpusViewResult &r = results[j];
      r.index = index;
      r.params = vpSSLCorpusView::draw(target, photos, o.seed, index, positive);
      view.render(r.params, &sheet, photos);
      r.truth = view.getTruth();
      const auto a = std::chrono::steady_clock::now();
      detector.detect(view.getImage());
      r.detectMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - a).count();
      vpSSLCorpusEvaluator::match(detector, r);
      if (index < o.saveImages) {
        char stem[64];
        std::snprintf(stem, sizeof(stem), "/%s-%05u", positive ? "view" : "negative", index);
        std::lock_guard<std::mutex> lock(ioMutex);
        save(o.outputDir + stem, view.getImage(), r, detector);
      }
      if (o.apriltag) {
        tagView.render(r.params, &tagSheet, photos);
        const auto b = std::chrono::steady_clock::now();
        tags.detect(tagView.getImage());
        r.tagMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - b).count();
        std::vector<std::vector<vpImagePoint>> polygons = tags.getPolygon();
        const std::vector<vpImagePoint> corners =
            positive ? tagCorners(r.params, tagSheet) : std::vector<vpImagePoint>();
        vpSSLCorpusEvaluator::matchTag(polygons, tags.getTagsId(), corners, tagSheet.getTagId(), r.params.camera.width,
                                       r.params.camera.height, r);
        if (index < o.saveImages) {
          char stem[64];
          std::snprintf(stem, sizeof(stem), "/%s-%05u-apriltag.png", positive ? "view" : "negative", index);
          std::lock_guard<std::mutex> lock(ioMutex);
          vpImageIo::write(tagView.getImage(), o.outputDir + stem);
        }
        if (!positive)
          r.tagWholeInFrame = false;
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned int t = 0; t < o.threads; ++t)
    pool.emplace_back(worker);
  for (std::thread &t : pool)
    t.join();

  vpSSLCorpusEvaluator evaluator;
  for (const vpSSLCorpusViewResult &r : results)
    evaluator.add(r);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  std::cout << "## Detector recall on the independent corpus\n\n"
            << "Views " << o.views << ", negatives " << o.negatives << ", seed " << o.seed << ", detector: decimation "
            << o.decimation << (o.small ? ", small-landmark mode" : "") << (o.equalRings ? "" : ", no equal-ring check")
            << (o.blurModel ? "" : ", no blurred-ring model") << (o.completion ? "" : ", no target completion") << ", "
            << photos.size() << " photos; wall time " << seconds << " s on " << o.threads << " thread(s).\n\n";
  evaluator.printTables(std::cout);

  const std::string csv = o.outputDir + "/corpus.csv";
  std::ofstream f(csv);
  evaluator.writeCsv(f);
  if (o.saveImages > 0) {
    vpSSLCorpusEvaluator saved;
    for (const vpSSLCorpusViewResult &r : results)
      if (r.index < o.saveImages)
        saved.add(r);
    std::ofstream g(o.outputDir + "/images-truth.csv");
    saved.writeCsv(g);
  }
  // Misses are re-rendered from their parameters (a view depends on its seed and index only).
  unsigned int misses = 0;
  vpSSLDetector detector(target);
  configure(detector, o);
  vpSSLCorpusView view(target);
  for (const vpSSLCorpusViewResult &r : results) {
    if (misses >= o.saveMisses)
      break;
    if (!r.params.hasTarget || r.truth.empty() || !r.truth[0].eligible() || r.results[0].found)
      continue;
    view.render(r.params, &sheet, photos);
    detector.detect(view.getImage());
    char stem[64];
    std::snprintf(stem, sizeof(stem), "/miss-%05u", r.index);
    save(o.outputDir + stem, view.getImage(), r, detector);
    ++misses;
  }
  if (o.explainMisses)
    explainMisses(results, target, sheet, photos, o);
  std::cerr << "tutorial-ssl-detector-recall: " << csv << " written" << std::endl;
  return 0;
}

int main(int argc, char **argv)
{
  return ssltut::guardedMain("tutorial-ssl-detector-recall", [&] { return run(argc, argv); });
}

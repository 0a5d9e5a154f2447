//! \example tutorial-ssl-paper-figures.cpp
//! Regenerates the paper's Fig. 2, Fig. 4, Fig. 5 and Table 1 as PNG plots and Markdown.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <visp3/core/vpIoTools.h>
#include <visp3/core/vpMath.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl/vpSSLMatchingFunction.h>
#include <visp3/ssl/vpSSLPattern.h>
#include <visp3/ssl/vpSSLRadiusEstimator.h>
#include <visp3/ssl_harness/vpSSLAprilTagBaseline.h>
#include <visp3/ssl_harness/vpSSLBenchMath.h>
#include <visp3/ssl_io/vpSSLSequenceReader.h>
#include <visp3/ssl_sim/vpSSLAprilTagSheet.h>
#include <visp3/ssl_sim/vpSSLPlot.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>

// Which regions of interest a frame matched (Table 1): the library's test access, as in bench-detector.
#include "vpSSLDetectorTestAccess.h"

#include "ssl_tutorial_common.h"
#include "ssl_tutorial_input.h"

namespace {
const char *kUsage = R"(Usage: tutorial-ssl-paper-figures [options]

Regenerates the figures of Negre, Pradalier and Dunbabin (JFR 2008) with their axes:
  fig2-rotation.png, fig2-tilt.png, fig2-blur-0.png, fig2-blur-45.png, fig2-contrast.png
      Fig. 2: matching response (Eq. 5 at the landmark centre / (255 w), w = 40, no brightness
      normalisation) of the linear landmark of Briggs et al. (+x direction only and the four
      directions) and of the circular landmark, under in-plane rotation, perspective tilt,
      directional Gaussian blur (horizontal and 45 deg) and contrast change; plus the detection
      rate of an AprilTag 36h11 of the same printed size under the same transformations
      (vpDetectorAprilTag, quad decimate 1, 8 noise draws of sigma 4 grey levels per point).
      Landmarks of 50 px radius, 240 x 240 views rendered exactly (4 x 4 samples per pixel).
  fig4-window.png
      Fig. 4: matching value (+x, Eq. 3 sum / 255) at the centre of circular landmarks of 20,
      40 and 60 px radius against the window size w (the Eq. 7 sweep).
  fig5-size.png
      Fig. 5: estimated against true apparent radius of landmark B over a sequence: the
      detector's ring reading and the Eq. 7 sweep peak, true radius f R / Z from ground truth.
  Table 1 (in figures.md): frames per second of vpSSLDetector (one thread) on a rendered ssl3-a3 view at
      640x480 and 320x240, beside the paper's figures: the whole image; the paper's ROI mode (three
      100x100 regions of interest, each matched and searched for peaks); and, apart, the tracker's
      fast path (the same regions, the previous landmarks re-read from their centre, no matching).
The tables behind the plots go to figures.md and stdout (Markdown).

Options:
  --output-dir DIR   Where to write (default: ssl-paper-figures).
  --sequence DIR     Sequence for Fig. 5 (default: the sample data/sequences/approach-clear; data/ is
                     $VISP_SSL_DATA_DIR if set, else share/visp_ssl of an installed tree, else the
                     source tree's).
  --quick            Fewer points, 2 x 2 samples per pixel and fewer timing runs (for tests).
  --help             This help.

Exit status: 0 on success, 2 on a bad option or input (one line on stderr), 1 when a run
fails or an output file cannot be written whole, or on any other runtime failure (one line
on stderr).
)";

[[noreturn]] void fail(const std::string &msg, int code)
{
  std::cerr << "tutorial-ssl-paper-figures: " << msg << std::endl;
  std::exit(code);
}

const unsigned int kSize = 240;      // view side (px)
const double kFocal = 400.;          // px
const double kRadius = 50. / kFocal; // landmark radius (m at 1 m): 50 px seen frontally
const unsigned int kWindow = 40;     // the paper's w
const double kP = 0.5;

enum Pattern
{
  PATTERN_LINEAR,
  PATTERN_CIRCULAR,
  PATTERN_APRILTAG
};

struct View
{
  double rotationDeg = 0.; // in-plane rotation
  double tiltDeg = 0.;     // angle between the optical axis and the plane normal (about the vertical axis)
  double blurSigma = 0.;   // directional Gaussian blur (px)
  double blurAngleDeg = 0.;
  double contrast = 1.;
};

//! Printed value (0 black, 1 white) at plane point (x, y) (m) of the pattern; the sheet around is white.
int printed(Pattern pattern, double x, double y, const vpSSLAprilTagSheet &tag)
{
  if (pattern == PATTERN_CIRCULAR) {
    const int s = vpSSLPattern::circular(x, y, kRadius, kP);
    return s < 0 ? 1 : s;
  }
  if (pattern == PATTERN_LINEAR) {
    // Briggs et al.'s bar pattern: self-similar along x from its origin (the matched point), a bar 2R long
    // (the circular landmark's diameter) and R high.
    if (std::fabs(y) > kRadius / 2.)
      return 1;
    const int s = vpSSLPattern::linear(x, 2. * kRadius, kP);
    return s < 0 ? 1 : s;
  }
  // AprilTag: black square of side 2R (8 cells) centred at the origin.
  const double cell = 2. * kRadius / 8.;
  const double cx = x / cell + 4., cy = y / cell + 4.;
  if (cx < 0. || cy < 0. || cx >= 8. || cy >= 8.)
    return 1;
  return tag.isBlackCell(static_cast<unsigned int>(cy), static_cast<unsigned int>(cx)) ? 0 : 1;
}

//! Exact rendering of a plane 1 m in front of the camera, tilted and turned, then blurred and contrast-changed.
unsigned int g_supersampling = 4; // 2 with --quick

void render(Pattern pattern, const View &view, const vpSSLAprilTagSheet &tag, vpImage<unsigned char> &I)
{
  const double phi = vpMath::rad(view.tiltDeg), theta = vpMath::rad(view.rotationDeg);
  const double ex[3] = {std::cos(phi), 0., std::sin(phi)}; // plane X axis
  const double n[3] = {-std::sin(phi), 0., std::cos(phi)}; // plane normal; the plane holds C = (0, 0, 1)
  const unsigned int ss = g_supersampling;
  const double c = kSize / 2.;
  vpImage<double> F(kSize, kSize, 0.);
  for (unsigned int v = 0; v < kSize; ++v)
    for (unsigned int u = 0; u < kSize; ++u) {
      double acc = 0.;
      for (unsigned int a = 0; a < ss; ++a)
        for (unsigned int b = 0; b < ss; ++b) {
          const double dx = (u - c + (b + 0.5) / ss - 0.5) / kFocal, dy = (v - c + (a + 0.5) / ss - 0.5) / kFocal;
          const double den = n[0] * dx + n[2];
          if (den <= 1e-9) {
            acc += 1.;
            continue;
          }
          const double t = n[2] / den; // n . C = n[2]
          const double px = t * dx, py = t * dy, pz = t - 1.;
          const double X = px * ex[0] + pz * ex[2], Y = py;
          const double x = std::cos(theta) * X + std::sin(theta) * Y;
          const double y = -std::sin(theta) * X + std::cos(theta) * Y;
          acc += printed(pattern, x, y, tag);
        }
      F[v][u] = 20. + 215. * acc / (ss * ss); // print black 20, paper white 235
    }
  if (view.blurSigma > 0.) {
    const double step = 0.5, s = view.blurSigma, ang = vpMath::rad(view.blurAngleDeg);
    const int K = static_cast<int>(std::ceil(3. * s / step));
    std::vector<double> w(2 * K + 1);
    double sum = 0.;
    for (int k = -K; k <= K; ++k)
      sum += (w[k + K] = std::exp(-0.5 * (k * step) * (k * step) / (s * s)));
    vpImage<double> G(kSize, kSize, 0.);
    for (unsigned int v = 0; v < kSize; ++v)
      for (unsigned int u = 0; u < kSize; ++u) {
        double acc = 0.;
        for (int k = -K; k <= K; ++k) {
          double x = u + k * step * std::cos(ang), y = v + k * step * std::sin(ang);
          x = std::max(0., std::min(kSize - 1.001, x));
          y = std::max(0., std::min(kSize - 1.001, y));
          const unsigned int x0 = static_cast<unsigned int>(x), y0 = static_cast<unsigned int>(y);
          const double fx = x - x0, fy = y - y0;
          acc += w[k + K] * ((1 - fy) * ((1 - fx) * F[y0][x0] + fx * F[y0][x0 + 1]) +
                             fy * ((1 - fx) * F[y0 + 1][x0] + fx * F[y0 + 1][x0 + 1]));
        }
        G[v][u] = acc / sum;
      }
    F = G;
  }
  I.resize(kSize, kSize);
  for (unsigned int k = 0; k < I.getSize(); ++k)
    I.bitmap[k] = static_cast<unsigned char>(
        std::max(0., std::min(255., std::round(127.5 + view.contrast * (F.bitmap[k] - 127.5)))));
}

//! Best Eq. 5 value (four directions, or +x only) within 4 px of the centre, / (255 w).
double response(const vpImage<unsigned char> &I, bool plusXOnly)
{
  const vpSSLMatchingFunction match(kWindow, kP);
  int best = -255 * static_cast<int>(kWindow);
  const int c = kSize / 2;
  for (int v = c - 4; v <= c + 4; ++v)
    for (int u = c - 4; u <= c + 4; ++u)
      for (int d = 0; d < (plusXOnly ? 1 : 4); ++d) {
        int value = 0;
        if (match.evaluate(I, u, v, static_cast<vpSSLDirection>(d), kWindow, value))
          best = std::max(best, value);
      }
  return best / (255. * kWindow);
}

double aprilTagRate(const View &view, const vpSSLAprilTagSheet &tag, unsigned int draws)
{
  vpImage<unsigned char> I0, I;
  render(PATTERN_APRILTAG, view, tag, I0);
  vpCameraParameters cam(kFocal, kFocal, kSize / 2., kSize / 2.);
  vpSSLAprilTagBaseline baseline(vpSSLAprilTagSheet(tag.getId(), 2. * kRadius, 1., 1.), cam);
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0., 4.);
  unsigned int found = 0;
  for (unsigned int k = 0; k < draws; ++k) {
    I = I0;
    for (unsigned int i = 0; i < I.getSize(); ++i)
      I.bitmap[i] = static_cast<unsigned char>(std::max(0., std::min(255., I0.bitmap[i] + noise(rng))));
    found += baseline.detect(I) ? 1 : 0;
  }
  return static_cast<double>(found) / draws;
}

void figure2(const std::string &dir, bool quick, std::ostream &md)
{
  const vpSSLAprilTagSheet tag = vpSSLAprilTagSheet::a3(0);
  struct Sweep
  {
    std::string file, title, xLabel;
    double from, to, step;
    std::function<void(View &, double)> set;
  };
  const double q = quick ? 4. : 1.;
  const std::vector<Sweep> sweeps = {
      {"fig2-rotation.png", "Fig. 2 row 1: in-plane rotation", "rotation (deg)", 0., 180., 5. * q,
       [](View &v, double x) { v.rotationDeg = x; }},
      {"fig2-tilt.png", "Fig. 2 row 2: perspective tilt", "angle between optical axis and landmark normal (deg)", 0.,
       85., 5. * q, [](View &v, double x) { v.tiltDeg = x; }},
      {"fig2-blur-0.png", "Fig. 2 row 3: horizontal blur", "directional Gaussian blur sigma (px)", 0., 16., 1. * q,
       [](View &v, double x) { v.blurSigma = x; }},
      {"fig2-blur-45.png", "Fig. 2 row 3: 45 deg blur", "directional Gaussian blur sigma (px)", 0., 16., 1. * q,
       [](View &v, double x) {
         v.blurSigma = x;
         v.blurAngleDeg = 45.;
       }},
      {"fig2-contrast.png", "Fig. 2 row 4: contrast change", "contrast (fraction of the printed one)", 0., 1., 0.05 * q,
       [](View &v, double x) { v.contrast = x; }},
  };
  md << "## Fig. 2\n\n| transformation | value | linear +x | linear 4 dir. | circular 4 dir. | AprilTag rate |\n"
     << "|---|---:|---:|---:|---:|---:|\n";
  for (const Sweep &s : sweeps) {
    std::vector<double> x, lin1, lin4, circ, at;
    for (double t = s.from; t <= s.to + 1e-9; t += s.step) {
      View view;
      s.set(view, t);
      vpImage<unsigned char> I;
      render(PATTERN_LINEAR, view, tag, I);
      x.push_back(t);
      lin1.push_back(response(I, true));
      lin4.push_back(response(I, false));
      render(PATTERN_CIRCULAR, view, tag, I);
      circ.push_back(response(I, false));
      at.push_back(aprilTagRate(view, tag, quick ? 2 : 8));
    }
    vpSSLPlot plot(s.title, s.xLabel, "matching response / detection rate");
    plot.addSeries("linear SSL, +x only", x, lin1, vpColor::none, vpSSLPlot::STYLE_LINE_MARKERS);
    plot.addSeries("linear SSL, 4 directions", x, lin4, vpColor::none, vpSSLPlot::STYLE_LINE_MARKERS);
    plot.addSeries("circular SSL, 4 directions", x, circ, vpColor::none, vpSSLPlot::STYLE_LINE_MARKERS);
    plot.addSeries("AprilTag 36h11 detection rate", x, at, vpColor::none, vpSSLPlot::STYLE_LINE_MARKERS);
    plot.setYRange(-0.2, 1.05);
    plot.save(dir + "/" + s.file, 640, 320);
    // Every sample, so that each value the plots show can be read in the Markdown as well.
    for (size_t i = 0; i < x.size(); ++i)
      md << "| " << s.file.substr(5, s.file.size() - 9) << " | " << vpSSLBenchMath::fmt(x[i], 2) << " | "
         << vpSSLBenchMath::fmt(lin1[i], 3) << " | " << vpSSLBenchMath::fmt(lin4[i], 3) << " | "
         << vpSSLBenchMath::fmt(circ[i], 3) << " | " << vpSSLBenchMath::fmt(at[i], 2) << " |\n";
  }
  md << "\n";
}

void figure4(const std::string &dir, std::ostream &md)
{
  const vpSSLMatchingFunction match(kWindow, kP);
  vpSSLPlot plot("Fig. 4: matching value vs window size", "window size w (px)", "matching value (Eq. 3 sum / 255)");
  md << "## Fig. 4\n\n| landmark radius (px) | Eq. 7 peak w (px) | peak / radius |\n|---:|---:|---:|\n";
  for (double radius : {20., 40., 60.}) {
    // Frontal view, rendered in pixel units (4 x 4 samples per pixel).
    vpImage<unsigned char> I(kSize, kSize, 235);
    const double c = kSize / 2.;
    for (unsigned int v = 0; v < kSize; ++v)
      for (unsigned int u = 0; u < kSize; ++u) {
        double acc = 0.;
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b) {
            const int s =
                vpSSLPattern::circular(u - c + (b + 0.5) / 4. - 0.5, v - c + (a + 0.5) / 4. - 0.5, radius, kP);
            acc += (s < 0 ? 1 : s);
          }
        I[v][u] = static_cast<unsigned char>(std::round(20. + 215. * acc / 16.));
      }
    std::vector<int> S;
    const unsigned int peak = vpSSLRadiusEstimator::sweep(I, match, kSize / 2, kSize / 2, 110, S);
    std::vector<double> x, y;
    for (size_t w = 1; w < S.size(); ++w) {
      x.push_back(static_cast<double>(w));
      y.push_back(S[w] / 255.);
    }
    char name[64];
    std::snprintf(name, sizeof(name), "R = %.0f px", radius);
    plot.addSeries(name, x, y);
    plot.addVerticalLine(radius, name);
    md << "| " << vpSSLBenchMath::fmt(radius, 0) << " | " << peak << " | " << vpSSLBenchMath::fmt(peak / radius, 2)
       << " |\n";
  }
  plot.save(dir + "/fig4-window.png", 640, 320);
  md << "\n";
}

void figure5(const std::string &dir, const std::string &sequence, std::ostream &md)
{
  vpSSLSequenceReader reader;
  reader.open(sequence);
  const vpCameraParameters &cam = reader.getCameraParameters();
  const vpSSLTarget target = vpSSLTarget::fromName(reader.getInfo().target);
  const int b = target.findLandmark("B");
  if (b < 0)
    throw vpException(vpException::badValue, "%s: target %s has no landmark B", sequence.c_str(),
                      reader.getInfo().target.c_str());
  const vpSSLTargetLandmark &B = target.getLandmark(static_cast<size_t>(b));
  vpSSLDetector detector(target);
  detector.setNbThreads(1);
  detector.setSmallLandmarkMode(true);
  const vpSSLMatchingFunction match(kWindow, target.getP());
  std::vector<double> truth, ring, eq7;
  vpSSLSequenceFrame f;
  vpImage<unsigned char> I;
  while (reader.next(f, I)) {
    if (!f.hasGroundTruth || !detector.detect(I))
      continue;
    const vpSSLLandmark *l = detector.getMatchedLandmark(static_cast<size_t>(b));
    if (l == nullptr)
      continue;
    const vpHomogeneousMatrix cMo(f.cMo);
    const vpColVector P = cMo * vpColVector({B.x, B.y, B.z, 1.});
    truth.push_back(0.5 * (cam.get_px() + cam.get_py()) * B.radius / P[2]);
    ring.push_back(l->radius);
    std::vector<int> S;
    eq7.push_back(vpSSLRadiusEstimator::sweep(I, match, vpMath::round(l->u), vpMath::round(l->v), 300, S));
  }
  vpSSLPlot plot("Fig. 5: apparent radius of landmark B", "true apparent radius (px)", "estimated radius (px)");
  plot.addSeries("ring reading (detector)", truth, ring, vpColor::none, vpSSLPlot::STYLE_MARKERS);
  plot.addSeries("Eq. 7 sweep peak", truth, eq7, vpColor::none, vpSSLPlot::STYLE_MARKERS);
  double maxR = 1.;
  for (double t : truth)
    maxR = std::max(maxR, t);
  plot.addSeries("estimated = true", {0., maxR}, {0., maxR}, vpColor::darkGray);
  plot.save(dir + "/fig5-size.png", 640, 320);
  std::vector<double> relRing, relEq7;
  for (size_t i = 0; i < truth.size(); ++i) {
    relRing.push_back(ring[i] / truth[i] - 1.);
    relEq7.push_back(eq7[i] / truth[i] - 1.);
  }
  md << "## Fig. 5\n\n"
     << truth.size() << " frames of " << sequence << " with B detected. Relative error (estimated "
     << "/ true - 1): ring reading median " << vpSSLBenchMath::fmt(100. * vpSSLBenchMath::percentile(relRing, 50.), 1)
     << " % (p5 " << vpSSLBenchMath::fmt(100. * vpSSLBenchMath::percentile(relRing, 5.), 1) << ", p95 "
     << vpSSLBenchMath::fmt(100. * vpSSLBenchMath::percentile(relRing, 95.), 1) << "); Eq. 7 sweep median "
     << vpSSLBenchMath::fmt(100. * vpSSLBenchMath::percentile(relEq7, 50.), 1) << " % (p5 "
     << vpSSLBenchMath::fmt(100. * vpSSLBenchMath::percentile(relEq7, 5.), 1) << ", p95 "
     << vpSSLBenchMath::fmt(100. * vpSSLBenchMath::percentile(relEq7, 95.), 1) << ").\n\n";
}

// Median frames per second of \e runs timed detect() calls on \e I; \e untimed runs before each one, \e check after
// each one, both outside the timer.
double medianFps(vpSSLDetector &detector, const vpImage<unsigned char> &I, unsigned int runs,
                 const std::function<void()> &untimed, const std::function<void()> &check)
{
  std::vector<double> ms;
  for (unsigned int k = 0; k < runs; ++k) {
    untimed();
    const auto t0 = std::chrono::steady_clock::now();
    detector.detect(I);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    check();
  }
  return 1000. / vpSSLBenchMath::percentile(ms, 50.);
}

// What the regions of interest of one Table 1 mode did on its last timed frame.
struct RegionUse
{
  size_t matched = 0; // matched and searched for peaks
  size_t reread = 0;  // re-read from the previous landmark's centre, no matching
};

void table1(bool quick, std::ostream &md)
{
  const unsigned int runs = quick ? 5 : 60;
  double fullFps[2], paperFps[2], fastFps[2];
  RegionUse paperUse[2], fastUse[2];
  const unsigned int widths[2] = {640, 320};
  for (int s = 0; s < 2; ++s) {
    const unsigned int w = widths[s], h = w * 3 / 4;
    const double f = 554.3 * w / 640.; // data/camera/camera-640x480.xml, scaled
    const vpCameraParameters cam(f, f, w / 2., h / 2.);
    vpSSLRenderer renderer(cam, w, h);
    renderer.setTarget(vpSSLTarget::ssl3a3());
    vpImage<unsigned char> I;
    // As bench-detector: about 1 m at 640x480 (the small landmarks above the default 26 px radius).
    const vpHomogeneousMatrix cMo(0.05, 0.02, s == 0 ? 1.0 : 0.45, 0., vpMath::rad(10.), 0.);
    renderer.render(cMo, I);
    const vpImage<unsigned char> blank(h, w, 128); // no landmark: detecting it forgets the previous ones
    vpSSLDetector detector;
    detector.setNbThreads(1);
    if (!detector.detect(I) || !detector.getTargetMatch().found)
      throw vpException(vpException::fatalError, "Table 1: the rendered %ux%u view is not detected", w, h);
    const auto nothing = [] {};
    fullFps[s] = medianFps(detector, I, runs, nothing, nothing);
    std::vector<vpRect> rois;
    for (size_t k = 0; k < 3; ++k) {
      const vpSSLLandmark *l = detector.getMatchedLandmark(k);
      if (l != nullptr)
        rois.push_back(vpRect(l->u - 50., l->v - 50., 100., 100.));
    }
    if (rois.size() != 3)
      throw vpException(vpException::fatalError, "Table 1: %u of the 3 landmarks found in the %ux%u view",
                        static_cast<unsigned int>(rois.size()), w, h);
    // Every timed frame of both region modes is searched in its regions only: the periodic whole-image search of
    // tracking (every 10th frame in the paper) is the whole-image column.
    detector.setRegionsOfInterest(rois);
    // The regions of the last frame, read through the library's test access (as bench-detector does): the public
    // interface does not say which regions were matched and which re-read.
    auto use = [&](RegionUse &u, const char *mode) {
      return [&u, &detector, mode, w, h] {
        u.matched = vpSSLDetectorTestAccess::getMatchedRegions(detector).size();
        u.reread = 3 - u.matched;
        if (!detector.getTargetMatch().found || detector.getTargetMatch().nbMatched != 3)
          throw vpException(vpException::fatalError, "Table 1: the %ux%u view is not detected in its regions (%s)", w,
                            h, mode);
      };
    };
    // The paper's ROI mode: the previous landmarks forgotten before each timed frame, so every region is matched
    // and searched for peaks.
    paperFps[s] = medianFps(
        detector, I, runs, [&] { detector.detect(blank); }, use(paperUse[s], "paper ROI mode"));
    if (paperUse[s].matched != 3)
      throw vpException(vpException::fatalError, "Table 1: %u of the 3 regions matched in the %ux%u paper ROI mode",
                        static_cast<unsigned int>(paperUse[s].matched), w, h);
    // The tracker's fast path: the landmarks of the previous frame are re-read from their centre.
    detector.detect(I);
    fastFps[s] = medianFps(detector, I, runs, nothing, use(fastUse[s], "tracker fast path"));
  }
  md << "## Table 1\n\nvpSSLDetector, one thread, rendered ssl3-a3 view, median of " << runs
     << " runs. Paper ROI mode: three 100x100 regions around the landmarks, each matched and searched for peaks "
        "(the previous landmarks forgotten before each frame, untimed). Tracker fast path: the same regions, the "
        "landmarks of the previous frame re-read from their centre without matching (vpSSLTracker's frames between "
        "whole-image searches; not in the paper).\n\n"
     << "| image size | FPS whole image (ours) | FPS paper ROI mode 100x100 (ours) | FPS tracker fast path 100x100 "
        "(ours) | paper: Pentium IV 3 GHz whole / ROI | paper: Pentium M 1.4 GHz whole / ROI |\n"
     << "|---|---:|---:|---:|---|---|\n"
     << "| 640x480 | " << vpSSLBenchMath::fmt(fullFps[0], 0) << " | " << vpSSLBenchMath::fmt(paperFps[0], 0) << " | "
     << vpSSLBenchMath::fmt(fastFps[0], 0) << " | 2.8 / - | 2.1 / 6.8 |\n"
     << "| 320x240 | " << vpSSLBenchMath::fmt(fullFps[1], 0) << " | " << vpSSLBenchMath::fmt(paperFps[1], 0) << " | "
     << vpSSLBenchMath::fmt(fastFps[1], 0) << " | 11.1 / 18.7 | 8.9 / 15.4 |\n\n"
     << "What the three regions did on the last timed frame of each mode:\n\n"
     << "| image size | mode | regions matched | regions re-read |\n|---|---|---:|---:|\n";
  for (int s = 0; s < 2; ++s) {
    const std::string size = s == 0 ? "640x480" : "320x240";
    md << "| " << size << " | paper ROI mode | " << paperUse[s].matched << " | " << paperUse[s].reread << " |\n"
       << "| " << size << " | tracker fast path | " << fastUse[s].matched << " | " << fastUse[s].reread << " |\n";
  }
  md << "\n";
}
} // namespace

static int run(int argc, char **argv)
{
  std::string dir = "ssl-paper-figures";
  std::string sequence = ssltut::dataDir() + "/sequences/approach-clear";
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&] { return ssltut::optionValue(argc, argv, i, ssltut::MissingValue::Colon); };
    if (arg == "--help" || arg == "-h") {
      std::cout << kUsage;
      return 0;
    } else if (arg == "--output-dir") {
      dir = value();
    } else if (arg == "--sequence") {
      sequence = value();
    } else if (arg == "--quick") {
      quick = true;
      g_supersampling = 2;
    } else {
      fail("unknown argument " + arg + " (see --help)", 2);
    }
  }
  if (!vpIoTools::checkFilename(sequence + "/frames.csv"))
    fail("--sequence: " + sequence + "/frames.csv: missing (not a sequence folder?)", 2);
  try {
    vpIoTools::makeDirectory(dir);
  } catch (const vpException &) {
    fail(dir + ": cannot create the output folder", 1);
  }
  std::ostringstream md;
  try {
    figure2(dir, quick, md);
    figure4(dir, md);
    figure5(dir, sequence, md);
    table1(quick, md);
  } catch (const vpException &e) {
    fail(e.getStringMessage(), 2);
  }
  std::cout << md.str();
  std::ofstream out(dir + "/figures.md");
  out << md.str();
  try {
    ssltut::finishStream(out, dir + "/figures.md");
    ssltut::finishStream(std::cout, "standard output");
  } catch (const vpException &e) {
    fail(e.getStringMessage(), 1);
  }
  return 0;
}

int main(int argc, char **argv)
{
  // No exception reaches main's caller: one line on stderr and status 1 (2 for a bad option).
  return ssltut::guardedMain("tutorial-ssl-paper-figures", [&] { return run(argc, argv); });
}

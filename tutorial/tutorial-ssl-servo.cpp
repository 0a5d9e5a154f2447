//! \example tutorial-ssl-servo.cpp
//! Closed-loop homing and docking of the simulated AUV through real rendering and detection (paper Sec. 5):
//! each control step renders the camera image at the true pose, finds the target (SSL tracker or AprilTag
//! baseline) and lets vpSSLHomingBehaviour drive vpSSLAuvSimulator. Writes a CSV and the figure's PNG.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include <visp3/core/vpIoTools.h>
#include <visp3/ssl_harness/vpSSLBenchMath.h>
#include <visp3/ssl_harness/vpSSLClosedLoop.h>
#include <visp3/ssl_servo/vpSSLHomingBehaviour.h>
#include <visp3/ssl_sim/vpSSLPlot.h>

#include "ssl_tutorial_closed_loop_options.h"
#include "ssl_tutorial_common.h"
#include "ssl_tutorial_option_loop.h"

namespace {
using ssltut::parseInteger;
using ssltut::parseNumber;
using ssltut::UsageError;

const char *kUsage = R"(Usage: tutorial-ssl-servo [options]
Closes the homing loop of the paper's Sec. 5 on the simulated AUV: at each control step (5 Hz) the camera
image is rendered at the true pose, the target is found (SSL tracker or AprilTag baseline) and the homing
behaviour drives the vehicle. Writes DIR/servo-<scenario>-<method>.csv and .png, prints a one-line summary.
Options:
  --scenario NAME      fig7 (target removed then put back), fig8 (target moved left then right),
                       fig9 (docking), field (coastal water, swaying target). Default fig7.
  --method NAME        ssl (vpSSLTracker on the ssl3-a3 sheet), apriltag (36h11 sheet, its corners and pose
                       fused with the odometry by the tracker's particle filter), truth (perfect sensor: the
                       ssl3-a3 landmarks projected at the true pose when in view), ssl-raw or apriltag-raw (the
                       single-frame pose of each image, no fusion, nothing when the target is not seen).
                       Default ssl.
  --duration S         Simulated seconds (default: fig7 300, fig8 200, fig9 90, field 120).
  --seed N             Seed of the sensors and the image noise (default 1).
  --output-dir DIR     Where the CSV and PNG go (default servo-out, created if needed).
  --width W            Image width (camera of data/camera/camera-640x480.xml scaled; default 640).
  --height H           Image height (default 480).
  --small              320 x 240 camera and 1 sample per pixel (fast).
  --supersampling N    Renderer sub-pixels per axis (default 1).
  --quiet              No progress on stderr.
  --help               This help.

Exit status: 0 on success, 2 on a bad option (one line on stderr), 1 when a run fails or an
output file cannot be written whole, or on any other runtime failure (one line on stderr).
CSV columns: t, state, nb_points, est_range, true_range, yaw_rate_demand, yaw_rate, heading_deg, depth,
lateral (vehicle y minus target y, world, m), target_y, collision, y_rel_est and y_rel_true (target centre's
starboard position in the vehicle frame, measured and true, m; empty when the target is not measured).
)";

struct Options : ssltut::ClosedLoopOutputOptions
{
  Options() { outputDir = "servo-out"; }
  std::string scenario = "fig7";
  std::string method = "ssl";
  double duration = -1.;
  long seed = 1;
  int supersampling = -1;
};

// The command line into \e o; false after --help, the usage printed.
bool parse(int argc, char **argv, Options &o)
{
  // One option: false for an option this tutorial does not know.
  const auto option = [&](const std::string &a, const auto &value) {
    if (a == "--scenario") {
      o.scenario = value();
      if (o.scenario != "fig7" && o.scenario != "fig8" && o.scenario != "fig9" && o.scenario != "field") {
        throw UsageError{"--scenario: unknown \"" + o.scenario + "\" (fig7, fig8, fig9, field)"};
      }
    } else if (a == "--method") {
      o.method = value();
      vpSSLClosedLoop::Method m;
      if (!vpSSLClosedLoop::parseMethod(o.method, m)) {
        throw UsageError{"--method: unknown \"" + o.method + "\" (ssl, apriltag, truth, ssl-raw, apriltag-raw)"};
      }
    } else if (a == "--duration") {
      o.duration = parseNumber(a, value());
      if (o.duration <= 0. || o.duration > 3600.) {
        throw UsageError{"--duration: expected a value in (0, 3600] s"};
      }
    } else if (a == "--seed") {
      o.seed = parseInteger(a, value(), 0, 100000);
    } else if (o.parseOutputOption(a, value, 100000)) {
    } else if (a == "--supersampling") {
      o.supersampling = static_cast<int>(parseInteger(a, value(), 1, 100000));
      if (o.supersampling > 8) {
        throw UsageError{"--supersampling: expected 1 to 8"};
      }
    } else {
      return false;
    }
    return true;
  };
  const bool go = ssltut::readOptions(argc, argv, kUsage, ssltut::OptionStyle::ReadAll, option);
  o.applySmall();
  if (o.supersampling < 0) {
    o.supersampling = 1; // one ray per pixel keeps a 300 s fig7 run at 640x480 within a couple of minutes
  }
  if (o.duration < 0.) {
    o.duration = o.scenario == "fig7" ? 300. : o.scenario == "fig8" ? 200. : o.scenario == "fig9" ? 90. : 120.;
  }
  return go;
}

} // namespace

using Row = vpSSLClosedLoop::Row;

static int run(int argc, char **argv)
{
  // A bad option throws UsageError: guardedMain() prints it on one line and returns 2.
  Options opt;
  if (!parse(argc, argv, opt)) {
    return EXIT_SUCCESS; // --help
  }
  vpSSLClosedLoop::Method method = vpSSLClosedLoop::Method::Ssl;
  vpSSLClosedLoop::parseMethod(opt.method, method); // checked by parse()
  const std::string base = opt.outputDir + "/servo-" + opt.scenario + "-" + opt.method;

  if (!vpIoTools::checkDirectory(opt.outputDir)) {
    vpIoTools::makeDirectory(opt.outputDir);
  }
  // The camera of the paper's vehicle, scaled to the requested image size (same field of view).
  const vpCameraParameters cam = vpSSLClosedLoop::scaledCamera(opt.width, opt.height);
  // Scenario figures (paper Sec. 5).
  const double D = opt.duration;
  const bool field = opt.scenario == "field";
  const vpSSLClosedLoop::Scene scene = vpSSLClosedLoop::paperScene(opt.scenario, D);
  const double standOff = scene.standOff;
  vpSSLClosedLoop loop(scene, method, cam, opt.width, opt.height, static_cast<unsigned int>(opt.supersampling),
                       opt.seed);
  vpSSLAuvSimulator &auv = loop.getAuv();
  const vpSSLHomingBehaviour &homing = loop.getHoming();

  std::vector<Row> rows;
  const auto start = std::chrono::steady_clock::now();
  const int nbSteps = static_cast<int>(std::lround(D / auv.getTimeStep()));
  double dockTime = NAN;
  int lastPercent = -1;
  for (int k = 0; k <= nbSteps; ++k) {
    const Row r = loop.step(k);
    if (homing.getState() == SSL_HOMING_DOCKED && !std::isfinite(dockTime)) {
      dockTime = r.t;
    }
    rows.push_back(r);
    if (std::isfinite(dockTime) && r.t > dockTime + 2.) {
      break; // docked: a little more to show it stays
    }
    loop.apply();

    const int percent = static_cast<int>(100. * k / std::max(1, nbSteps));
    if (!opt.quiet && percent / 10 != lastPercent / 10) {
      lastPercent = percent;
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(stderr, "t %.0f s (%d %%), state %s, %.0f ms/step\n", r.t, percent,
                   vpSSLHomingBehaviour::getStateName(homing.getState()).c_str(), 1000. * elapsed / (k + 1));
    }
  }
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  vpSSLClosedLoop::writeRows(base + ".csv", rows);

  // Figure.
  auto column = [&](double Row::*field) {
    std::vector<double> v;
    for (const Row &r : rows) {
      v.push_back(r.*field);
    }
    return v;
  };
  std::vector<double> ts = column(&Row::t), stateIndex;
  for (const Row &r : rows) {
    stateIndex.push_back(static_cast<double>(r.state));
  }
  const double tEnd = ts.empty() ? 1. : std::max(1., ts.back());
  auto panel = [&](const std::string &title, const std::string &y) {
    vpSSLPlot p(title, "t (s)", y);
    p.setXRange(0., tEnd);
    return p;
  };
  // The panels the scenarios share.
  auto yawPanel = [&](const std::string &title) {
    vpSSLPlot p = panel(title, "rad/s");
    p.addSeries("demanded", ts, column(&Row::yawDemand));
    p.addSeries("actual", ts, column(&Row::yawRate), vpColor::red);
    return p;
  };
  auto rangePanel = [&](const std::string &title) {
    vpSSLPlot p = panel(title, "m");
    p.addSeries("estimated", ts, column(&Row::estRange));
    p.addSeries("true", ts, column(&Row::trueRange), vpColor::red);
    return p;
  };
  auto nbPanel = [&]() {
    vpSSLPlot p = panel("nbPoints", "points");
    p.addSeries("nbPoints", ts, column(&Row::nbPoints));
    return p;
  };
  auto statePanel = [&]() {
    vpSSLPlot p = panel("State (0 search, 1 align, 2 home, 3 dock, 4 docked)", "state");
    p.addSeries("state", ts, stateIndex);
    p.setYRange(-0.5, 4.5);
    return p;
  };
  std::vector<vpSSLPlot> panels;
  const std::string what = opt.scenario + ", " + opt.method;
  if (opt.scenario == "fig7" || field) {
    vpSSLPlot depth = panel("Depth", "m");
    depth.addSeries("depth", ts, column(&Row::depth));
    vpSSLPlot rng = rangePanel("Range");
    rng.addHorizontalLine(standOff, "stand-off");
    panels = {yawPanel("Yaw rate (" + what + ")"), depth, statePanel(), nbPanel(), rng};
  } else if (opt.scenario == "fig8") {
    // As the paper's Fig. 8: the target's lateral position in the vehicle frame, which the yaw brings back to 0.
    vpSSLPlot lat = panel("Target lateral position in the vehicle frame (" + what + ")", "y_rel (m)");
    lat.addSeries("measured", ts, column(&Row::yRelEst));
    lat.addSeries("true", ts, column(&Row::yRelTrue), vpColor::red);
    lat.addSeries("target moved (world)", ts, column(&Row::targetY), vpColor::darkGreen);
    vpSSLPlot heading = panel("Heading", "deg");
    heading.addSeries("heading", ts, column(&Row::heading));
    panels = {lat, heading, yawPanel("Yaw rate")};
  } else {
    vpSSLPlot col = panel("Collision", "flag");
    col.addSeries("collision", ts, column(&Row::collision));
    col.setYRange(-0.1, 1.1);
    panels = {rangePanel("Range (" + what + ")"), nbPanel(), col, statePanel()};
  }
  vpSSLPlot::saveStacked(panels, base + ".png");

  // Summary: stand-off RMS error over the settled HOME steps (vpSSLClosedLoop::standOffRms()).
  size_t n = 0;
  const double rms = vpSSLClosedLoop::standOffRms(rows, standOff, n);
  std::printf("scenario %s, method %s, %.0f s simulated in %.1f s (%.0f ms/step, %ux%u, %d spp): final state %s, "
              "stand-off RMS %s m over %zu settled HOME steps, time to dock %s s -> %s.csv/.png\n",
              opt.scenario.c_str(), opt.method.c_str(), rows.empty() ? 0. : rows.back().t, elapsed,
              1000. * elapsed / std::max<size_t>(1, rows.size()), opt.width, opt.height,
              opt.supersampling * opt.supersampling, vpSSLHomingBehaviour::getStateName(homing.getState()).c_str(),
              n ? vpSSLBenchMath::csvNumber(rms, 3).c_str() : "n/a", n,
              std::isfinite(dockTime) ? vpSSLBenchMath::csvNumber(dockTime, 1).c_str() : "n/a", base.c_str());
  return EXIT_SUCCESS;
}

int main(int argc, char **argv)
{
  // No exception reaches main's caller: one line on stderr and status 1 (2 for a bad option).
  return ssltut::guardedMain("tutorial-ssl-servo", [&] { return run(argc, argv); });
}

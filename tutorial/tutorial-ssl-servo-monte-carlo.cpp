//! \example tutorial-ssl-servo-monte-carlo.cpp
//! Monte Carlo docking benchmark: the whole mission of tutorial-ssl-servo's closed loop (search, align, home,
//! dock) from random starts with the target out of view, in random currents and waters, the same draws for every
//! method; docking success, the reason of each failure, stand-off error and time to dock per method, water and start
//! range as runs.csv, a Markdown summary and a PNG of the outcomes.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <mutex>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <visp3/core/vpIoTools.h>
#include <visp3/core/vpMeterPixelConversion.h>
#include <visp3/core/vpRxyzVector.h>
#include <visp3/ssl_harness/vpSSLBenchMath.h>
#include <visp3/ssl_harness/vpSSLClosedLoop.h>
#include <visp3/ssl_servo/vpSSLHomingBehaviour.h>
#include <visp3/ssl_sim/vpSSLPlot.h>
#include <visp3/ssl_sim/vpSSLScenario.h>

#include "ssl_tutorial_closed_loop_options.h"
#include "ssl_tutorial_common.h"
#include "ssl_tutorial_option_loop.h"

namespace {
using ssltut::parseInteger;
using ssltut::parseNumber;
using ssltut::UsageError;

const char *kUsage = R"(Usage: tutorial-ssl-servo-monte-carlo [options]
Monte Carlo docking benchmark: N runs of the whole mission in the closed loop of tutorial-ssl-servo (simulated AUV,
rendered images, detection, homing behaviour: search, align, home, auto-dock) from random starts, the same draws
for every method. Per run: water clear or coastal (--water); camera at a range uniform in --start-range from the
target centre (capped at the water's visibility, 4 m in coastal water), on a bearing within +-30 deg of the target's
axis, depth offset +-1 m; heading uniform within +-DEG (--start-heading) of the direction of the target, drawn
again until the target is out of the camera's field of view (start_in_view says when 100 draws did not get it
out); current 0 to --max-current m/s in a random horizontal direction. Stand-off 2 m (coastal 1.5 m), docking
after holding the stand-off for 10 s within 0.5 m and 15 deg (--dock-hold: a cross current the vehicle cannot
counter without sway makes a tight hold impossible, see doc/servo-simulation.md); docked when the nose touches the
board in DOCK (the collision sensor). Writes DIR/runs.csv (one row per run and method, draws included),
DIR/summary.md (also on stdout: docking success, failures by reason, stand-off RMS, time to dock per method and
water, and per start range) and DIR/outcomes.png (success by start range and by current, per method).
Methods: ssl (vpSSLTracker: detector, single-frame pose, particle filter with the odometry), apriltag (the 36h11
sheet, its corners and pose fed to the same particle filter with the same odometry), truth (perfect sensor),
ssl-raw and apriltag-raw (the single-frame pose of each image, nothing when the target is not seen).
Failure reasons (column failure; empty when docked): never-found (the target was never seen), lost (seen, then
lost and not found again: SEARCH at the end), hold-not-reached (ALIGN or HOME at the end, DOCK never requested),
missed-board (in DOCK the camera came within 0.3 m of the target's plane or passed it without the nose touching
the board), collision (the nose hit the board outside DOCK and the run did not dock), time-out (still in DOCK).
Options:
  --runs N             Runs per method (default 20).
  --seed S             Seed of the draws and of the sensors (default 1); run i uses the same draws for all methods.
  --methods LIST       Comma-separated among ssl, apriltag, truth, ssl-raw, apriltag-raw
                       (default ssl,apriltag,truth).
  --time-limit S       Simulated seconds per run (default 240).
  --rate HZ            Control and camera rate (default 5 Hz, in [1, 20]): one image, one detection and one
                       command per period; the vehicle's dynamics are sub-stepped whatever the rate.
  --start-range MIN,MAX  Camera to target centre at the start (m, default 2,8; 0.5 <= MIN <= MAX <= 30).
  --start-heading DEG  Heading uniform within +-DEG of the direction of the target (default 180, in [0, 180]).
  --water NAME         clear, coastal or mixed (each run draws one of the two, default mixed).
  --max-current V      Largest current drawn (m/s, default 0.1; 0: still water).
  --dock-hold S,M,DEG  Auto-dock after S seconds in HOME within M metres of the stand-off and DEG degrees of
                       the optical axis (default 10,0.5,15; fig9 of tutorial-ssl-servo uses 10,0.1,5).
  --station-keeping    On by default. The behaviour gets the odometry: SEARCH holds its ground in front of where
                       the target was last seen (vpSSLHomingBehaviour::setSearchHold()), and HOME integrates the
                       range error (setRangeIntegralGain(0.05)), so that a current neither carries the vehicle off
                       while it searches nor holds it short of the stand-off.
  --no-station-keeping Without it: the behaviour of tutorial-ssl-servo's scenarios (no odometry).
  --dock-in-transit    On by default. The behaviour gets the odometry, estimates the current from it and, when the
                       current across the line of sight reaches 0.1 m/s, docks without holding the stand-off,
                       crabbing into the current (vpSSLHomingBehaviour::setDockInTransit()).
  --no-dock-in-transit Without it: the stand-off is always held before docking.
  --threads T          Runs in parallel (default 2); the results do not depend on it.
  --traces             Also write each run's steps as DIR/run-<i>-<method>.csv (tutorial-ssl-servo's columns).
  --output-dir DIR     Where runs.csv and summary.md go (default monte-carlo-out, created if needed).
  --width W            Image width (camera of data/camera/camera-640x480.xml scaled; default 640).
  --height H           Image height (default 480).
  --small              320 x 240 camera (fast, but ssl3-a3 is then too small to be detected beyond about 3 m).
  --quiet              No progress on stderr.
  --help               This help.

Exit status: 0 on success, 2 on a bad option (one line on stderr), 1 when a run fails or an
output file cannot be written whole, or on any other runtime failure (one line on stderr).
runs.csv columns: run, method, water, seed, start_distance, lateral, heading_deg, depth_offset, current_speed,
current_dir_deg, stand_off, start_range, docked, time_to_dock, standoff_rms, settled_steps, first_detection,
collisions_outside_dock, lost_events, final_state, sim_time, start_in_view, failure.
)";

struct Options : ssltut::ClosedLoopOutputOptions
{
  Options() { outputDir = "monte-carlo-out"; }
  long runs = 20;
  long seed = 1;
  std::vector<vpSSLClosedLoop::Method> methods = {vpSSLClosedLoop::Method::Ssl, vpSSLClosedLoop::Method::AprilTag,
                                                  vpSSLClosedLoop::Method::Truth};
  double timeLimit = 240.;
  double rate = 5.;
  double startRangeMin = 2., startRangeMax = 8.;
  double startHeading = 180.;
  std::string water = "mixed";
  double maxCurrent = 0.1;
  double dockHold = 10., dockRange = 0.5, dockAngle = 15.;
  bool stationKeeping = true;
  bool dockInTransit = true;
  long threads = 2;
  bool traces = false;
};

std::vector<vpSSLClosedLoop::Method> parseMethods(const std::string &text)
{
  std::vector<vpSSLClosedLoop::Method> methods;
  std::stringstream ss(text);
  std::string name;
  while (std::getline(ss, name, ',')) {
    vpSSLClosedLoop::Method m;
    if (!vpSSLClosedLoop::parseMethod(name, m)) {
      throw UsageError{"--methods: unknown \"" + name + "\" (ssl, apriltag, truth, ssl-raw, apriltag-raw)"};
    }
    if (std::find(methods.begin(), methods.end(), m) != methods.end()) {
      throw UsageError{"--methods: \"" + name + "\" given twice"};
    }
    methods.push_back(m);
  }
  if (methods.empty() || text.back() == ',') {
    throw UsageError{"--methods: expected a comma-separated list of methods (see --help), got \"" + text + "\""};
  }
  return methods;
}

// The command line into \e o; false after --help, the usage printed.
bool parse(int argc, char **argv, Options &o)
{
  // One option: false for an option this tutorial does not know.
  const auto option = [&](const std::string &a, const auto &value) {
    if (a == "--runs") {
      o.runs = parseInteger(a, value(), 1, 10000);
    } else if (a == "--seed") {
      o.seed = parseInteger(a, value(), 0, 1000000);
    } else if (a == "--methods") {
      o.methods = parseMethods(value());
    } else if (a == "--time-limit") {
      o.timeLimit = parseNumber(a, value());
      if (o.timeLimit <= 0. || o.timeLimit > 3600.) {
        throw UsageError{"--time-limit: expected a value in (0, 3600] s"};
      }
    } else if (a == "--rate") {
      o.rate = parseNumber(a, value());
      if (!(o.rate >= 1.) || o.rate > 20.) {
        throw UsageError{"--rate: expected a value in [1, 20] Hz"};
      }
    } else if (a == "--start-range") {
      const std::string v = value();
      double lo = 0., hi = 0.;
      char tail = 0;
      if (std::sscanf(v.c_str(), "%lf,%lf%c", &lo, &hi, &tail) != 2 || !(lo >= 0.5) || !(hi >= lo) || !(hi <= 30.)) {
        throw UsageError{"--start-range: expected MIN,MAX with 0.5 <= MIN <= MAX <= 30 m, got \"" + v + "\""};
      }
      o.startRangeMin = lo;
      o.startRangeMax = hi;
    } else if (a == "--start-heading") {
      o.startHeading = parseNumber(a, value());
      if (o.startHeading < 0. || o.startHeading > 180.) {
        throw UsageError{"--start-heading: expected a value in [0, 180] deg"};
      }
    } else if (a == "--water") {
      o.water = value();
      if (o.water != "clear" && o.water != "coastal" && o.water != "mixed") {
        throw UsageError{"--water: expected clear, coastal or mixed, got \"" + o.water + "\""};
      }
    } else if (a == "--max-current") {
      o.maxCurrent = parseNumber(a, value());
      if (o.maxCurrent < 0. || o.maxCurrent > 2.) {
        throw UsageError{"--max-current: expected a value in [0, 2] m/s"};
      }
    } else if (a == "--dock-hold") {
      const std::string v = value();
      double h = 0., m = 0., d = 0.;
      char tail = 0;
      if (std::sscanf(v.c_str(), "%lf,%lf,%lf%c", &h, &m, &d, &tail) != 3 || !(h >= 0.) || !(m > 0.) || !(d > 0.) ||
          !(h < 1e4) || !(m < 100.) || !(d < 90.)) {
        throw UsageError{"--dock-hold: expected S,M,DEG with S >= 0, M > 0, 0 < DEG < 90, got \"" + v + "\""};
      }
      o.dockHold = h;
      o.dockRange = m;
      o.dockAngle = d;
    } else if (a == "--traces") {
      o.traces = true;
    } else if (a == "--station-keeping") {
      o.stationKeeping = true;
    } else if (a == "--no-station-keeping") {
      o.stationKeeping = false;
    } else if (a == "--dock-in-transit") {
      o.dockInTransit = true;
    } else if (a == "--no-dock-in-transit") {
      o.dockInTransit = false;
    } else if (a == "--threads") {
      o.threads = ssltut::parseThreads(a, value(), false, 64);
    } else if (o.parseOutputOption(a, value, 10000)) {
    } else {
      return false;
    }
    return true;
  };
  const bool go = ssltut::readOptions(argc, argv, kUsage, ssltut::OptionStyle::ReadAll, option);
  o.applySmall();
  return go;
}

// The random conditions of one run, shared by every method.
struct Draw
{
  int run;
  long seed;           // sensors and image noise
  bool coastal;        // water preset: coastal (4 m visibility) or clear
  double distance;     // camera to target centre along the target's axis (m)
  double lateral;      // camera offset across the target's axis (m, east)
  double heading;      // vehicle heading, from north towards east (rad)
  double depthOffset;  // camera depth minus target centre depth (m)
  double currentSpeed; // m/s
  double currentDir;   // rad from north towards east
  bool inView;         // the target was still in the field of view after the last heading drawn
};

// Uniform in [a, b) from 53 bits of the generator: std::uniform_real_distribution is implementation-defined, this
// gives the same draws with every standard library.
double uniform(std::mt19937_64 &g, double a, double b)
{
  return a + (b - a) * static_cast<double>(g() >> 11) * 0x1.0p-53;
}

vpSSLClosedLoop::Scene makeScene(const Draw &d, const Options &opt);

// Whether a corner of the target's sheet projects into the image from the start of \e d.
bool sheetInView(const Draw &d, const Options &opt, const vpCameraParameters &cam)
{
  const vpSSLClosedLoop::Scene scene = makeScene(d, opt);
  const vpHomogeneousMatrix cMo =
      (scene.wMvStart * vpSSLScenario::getDefaultCameraToVehicle()).inverse() * scene.wMoHome;
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const double w = target.getSheetWidth() / 2., h = target.getSheetHeight() / 2.;
  for (const double cx : {-w, w}) {
    for (const double cy : {-h, h}) {
      const vpTranslationVector c = cMo * vpTranslationVector(cx, cy, 0.);
      double u = 0., v = 0.;
      if (c[2] > 0.) {
        vpMeterPixelConversion::convertPoint(cam, c[0] / c[2], c[1] / c[2], u, v);
        if (u >= 0. && v >= 0. && u < opt.width && v < opt.height) {
          return true;
        }
      }
    }
  }
  return false;
}

Draw makeDraw(long seed, int run, const Options &opt, const vpCameraParameters &cam, double coastalVisibility)
{
  std::mt19937_64 g(static_cast<std::uint64_t>(seed) * 1000003ULL + static_cast<std::uint64_t>(run));
  Draw d;
  d.run = run;
  d.seed = seed * 100003L + run + 1;
  const double w = uniform(g, 0., 1.);
  d.coastal = opt.water == "coastal" || (opt.water == "mixed" && w < 0.5);
  // Beyond its visibility the target cannot be seen: the run would only measure the search.
  const double hi = d.coastal ? std::min(opt.startRangeMax, coastalVisibility) : opt.startRangeMax;
  const double range = uniform(g, std::min(opt.startRangeMin, hi), hi);
  const double bearing = vpMath::rad(uniform(g, -30., 30.));
  d.distance = range * std::cos(bearing);
  d.lateral = range * std::sin(bearing);
  d.depthOffset = uniform(g, -1., 1.);
  d.currentSpeed = uniform(g, 0., opt.maxCurrent);
  d.currentDir = uniform(g, 0., 2. * M_PI);
  // Heading off the direction of the target (north, then the bearing back to the target centre).
  const double towards = std::atan2(-d.lateral, d.distance);
  for (int attempt = 0; attempt < 100; ++attempt) {
    d.heading = towards + vpMath::rad(uniform(g, -opt.startHeading, opt.startHeading));
    d.inView = sheetInView(d, opt, cam);
    if (!d.inView) {
      break;
    }
  }
  return d;
}

vpSSLClosedLoop::Scene makeScene(const Draw &d, const Options &opt)
{
  vpSSLClosedLoop::Scene s;
  s.timeStep = 1. / opt.rate;
  s.water = d.coastal ? "coastal" : "clear";
  s.standOff = d.coastal ? 1.5 : 2.0;
  s.autoDockHold = opt.dockHold;
  s.autoDockRange = opt.dockRange;
  s.autoDockAngle = opt.dockAngle;
  s.stationKeeping = opt.stationKeeping;
  s.rangeIntegralGain = opt.stationKeeping ? 0.05 : 0.;
  s.dockInTransit = opt.dockInTransit;
  s.wMoHome = vpSSLScenario("approach").getTargetHome();
  // The camera d.distance south of the target centre (the target faces south), then the vehicle origin behind it.
  const vpTranslationVector tHome = s.wMoHome.getTranslationVector();
  const vpTranslationVector wtc(tHome[0] - d.distance, tHome[1] + d.lateral, tHome[2] + d.depthOffset);
  const vpRotationMatrix wRv(vpRxyzVector(0., 0., d.heading));
  const vpTranslationVector vtc = vpSSLScenario::getDefaultCameraToVehicle().getTranslationVector();
  s.wMvStart = vpHomogeneousMatrix(wtc - wRv * vtc, wRv);
  s.current = vpTranslationVector(d.currentSpeed * std::cos(d.currentDir), d.currentSpeed * std::sin(d.currentDir), 0.);
  return s;
}

// What one run gave.
struct Result
{
  double startRange = NAN;
  bool docked = false;
  double timeToDock = NAN;
  double standOffRms = NAN;
  size_t settledSteps = 0;
  double firstDetection = NAN;
  int collisionsOutsideDock = 0;
  int lostEvents = 0;
  vpSSLHomingState finalState = SSL_HOMING_SEARCH;
  double simTime = 0.;
  std::string failure;       // empty when docked
  double minDockRange = NAN; // smallest true camera to target range in DOCK (m)
  double wallTime = 0.;      // not written: it depends on the load and the thread count
};

Result runOne(const Draw &d, vpSSLClosedLoop::Method method, const vpCameraParameters &cam, const Options &opt)
{
  const auto start = std::chrono::steady_clock::now();
  const vpSSLClosedLoop::Scene scene = makeScene(d, opt);
  vpSSLClosedLoop loop(scene, method, cam, opt.width, opt.height, 1, d.seed);
  Result res;
  res.startRange = loop.getAuv().get_cMo().getTranslationVector().frobeniusNorm();
  std::vector<vpSSLClosedLoop::Row> rows;
  const int nbSteps = static_cast<int>(std::lround(opt.timeLimit / scene.timeStep));
  vpSSLHomingState previous = SSL_HOMING_SEARCH;
  bool previousCollision = false;
  for (int k = 0; k <= nbSteps; ++k) {
    const vpSSLClosedLoop::Row r = loop.step(k);
    rows.push_back(r);
    if (r.seen && !std::isfinite(res.firstDetection)) {
      res.firstDetection = r.t;
    }
    // A collision that starts while docking is the goal; any other one is a bump into the board.
    const bool collision = r.collision > 0.5;
    if (collision && !previousCollision && previous != SSL_HOMING_DOCK && previous != SSL_HOMING_DOCKED) {
      ++res.collisionsOutsideDock;
    }
    // The behaviour falls back to SEARCH only after losing the target for its lost timeout.
    if (r.state == SSL_HOMING_SEARCH && previous != SSL_HOMING_SEARCH) {
      ++res.lostEvents;
    }
    previous = r.state;
    previousCollision = collision;
    res.simTime = r.t;
    if (r.state == SSL_HOMING_DOCK) {
      // Behind the target's plane the range is negative (or unknown when the target is out of the water).
      res.minDockRange = std::isfinite(res.minDockRange) ? std::min(res.minDockRange, r.trueRange) : r.trueRange;
    }
    if (r.state == SSL_HOMING_DOCKED) {
      res.docked = true;
      res.timeToDock = r.t;
      break;
    }
    loop.apply();
  }
  res.finalState = previous;
  if (res.docked) {
    res.failure.clear();
  } else if (!std::isfinite(res.firstDetection)) {
    res.failure = "never-found";
  } else if (res.minDockRange < 0.3) {
    res.failure = "missed-board";
  } else if (res.collisionsOutsideDock > 0) {
    res.failure = "collision";
  } else if (res.finalState == SSL_HOMING_SEARCH) {
    res.failure = "lost";
  } else if (res.finalState == SSL_HOMING_DOCK) {
    res.failure = "time-out";
  } else {
    res.failure = "hold-not-reached";
  }
  res.standOffRms = vpSSLClosedLoop::standOffRms(rows, scene.standOff, res.settledSteps);
  if (opt.traces) {
    vpSSLClosedLoop::writeRows(
        opt.outputDir + "/run-" + std::to_string(d.run) + "-" + vpSSLClosedLoop::methodName(method) + ".csv", rows);
  }
  res.wallTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return res;
}

// The failure reasons, in the order of the summary's columns.
const std::vector<std::string> &failureReasons()
{
  static const std::vector<std::string> reasons = {"never-found",  "lost",      "hold-not-reached",
                                                   "missed-board", "collision", "time-out"};
  return reasons;
}

// Runs whose \e key lies in [lo, hi) with their docked fraction, for the outcome plot and the per-range table.
struct Bin
{
  size_t n = 0, docked = 0;
  std::vector<double> timeToDock;
};

// One line of the summary table: the runs of one method, in one water or in all ("all").
std::string summaryLine(const std::string &method, const std::string &water, const std::vector<const Result *> &runs)
{
  std::vector<double> rms, ttd, detection;
  size_t docked = 0;
  int collisions = 0, lost = 0;
  for (const Result *r : runs) {
    docked += r->docked ? 1 : 0;
    rms.push_back(r->standOffRms);
    ttd.push_back(r->timeToDock);
    detection.push_back(r->firstDetection);
    collisions += r->collisionsOutsideDock;
    lost += r->lostEvents;
  }
  const size_t nbRms =
      static_cast<size_t>(std::count_if(rms.begin(), rms.end(), [](double x) { return std::isfinite(x); }));
  const size_t nbDetected =
      static_cast<size_t>(std::count_if(detection.begin(), detection.end(), [](double x) { return std::isfinite(x); }));
  std::ostringstream os;
  os << "| " << method << " | " << water << " | " << docked << "/" << runs.size() << " | "
     << vpSSLBenchMath::fmt(runs.empty() ? NAN : 100. * docked / runs.size(), 0) << " % | "
     << vpSSLBenchMath::fmt(vpSSLBenchMath::percentile(rms, 50.), 3) << " | "
     << vpSSLBenchMath::fmt(vpSSLBenchMath::percentile(rms, 90.), 3) << " | " << nbRms << " | "
     << vpSSLBenchMath::fmt(vpSSLBenchMath::percentile(ttd, 50.), 1) << " | "
     << vpSSLBenchMath::fmt(vpSSLBenchMath::percentile(ttd, 90.), 1) << " | "
     << vpSSLBenchMath::fmt(vpSSLBenchMath::percentile(detection, 50.), 1) << " | " << nbDetected << "/" << runs.size()
     << " | " << collisions << " | " << lost << " |";
  for (const std::string &reason : failureReasons()) {
    os << " " << std::count_if(runs.begin(), runs.end(), [&](const Result *r) { return r->failure == reason; }) << " |";
  }
  os << "\n";
  return os.str();
}
} // namespace

static int run(int argc, char **argv)
{
  // A bad option throws UsageError: guardedMain() prints it on one line and returns 2.
  Options opt;
  if (!parse(argc, argv, opt)) {
    return EXIT_SUCCESS; // --help
  }

  if (!vpIoTools::checkDirectory(opt.outputDir)) {
    vpIoTools::makeDirectory(opt.outputDir);
  }
  const vpCameraParameters cam = vpSSLClosedLoop::scaledCamera(opt.width, opt.height);
  const double coastalVisibility = vpSSLWaterModel::preset("coastal").getVisibility();

  // Jobs: run-major, so that with several threads the methods of one run progress together.
  std::vector<Draw> draws;
  for (int i = 0; i < opt.runs; ++i) {
    draws.push_back(makeDraw(opt.seed, i, opt, cam, coastalVisibility));
  }
  const size_t nbMethods = opt.methods.size();
  const size_t nbJobs = draws.size() * nbMethods;
  std::vector<Result> results(nbJobs);
  std::vector<std::string> errors(nbJobs);
  std::atomic<size_t> next(0), done(0);
  std::mutex printMutex;
  const auto start = std::chrono::steady_clock::now();
  auto worker = [&](bool alone) {
#ifdef _OPENMP
    // The renderer and the water model are OpenMP loops: with several runs in parallel, one OpenMP thread per
    // run keeps the cores busy without oversubscribing them.
    if (!alone) {
      omp_set_num_threads(1);
    }
#else
    (void)alone;
#endif
    for (size_t j = next++; j < nbJobs; j = next++) {
      const Draw &d = draws[j / nbMethods];
      const vpSSLClosedLoop::Method m = opt.methods[j % nbMethods];
      try {
        results[j] = runOne(d, m, cam, opt);
      } catch (const vpException &e) {
        errors[j] = e.getStringMessage();
      } catch (const std::exception &e) {
        errors[j] = e.what();
      }
      const size_t n = ++done;
      if (!opt.quiet) {
        std::lock_guard<std::mutex> lock(printMutex);
        const Result &r = results[j];
        std::fprintf(stderr, "%zu/%zu run %d %s %s: %s, %.1f s wall\n", n, nbJobs, d.run,
                     vpSSLClosedLoop::methodName(m).c_str(), d.coastal ? "coastal" : "clear",
                     !errors[j].empty() ? "error"
                     : r.docked         ? ("docked at " + vpSSLBenchMath::csvNumber(r.timeToDock, 1) + " s").c_str()
                                        : ("not docked, " + vpSSLHomingBehaviour::getStateName(r.finalState)).c_str(),
                     r.wallTime);
      }
    }
  };
  const size_t nbThreads = std::min<size_t>(static_cast<size_t>(opt.threads), nbJobs);
  if (nbThreads <= 1) {
    worker(true);
  } else {
    std::vector<std::thread> pool;
    for (size_t i = 0; i < nbThreads; ++i) {
      pool.emplace_back(worker, false);
    }
    for (std::thread &t : pool) {
      t.join();
    }
  }
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (size_t j = 0; j < nbJobs; ++j) {
    if (!errors[j].empty()) {
      throw vpException(vpException::fatalError, "run %d, method %s: %s", draws[j / nbMethods].run,
                        vpSSLClosedLoop::methodName(opt.methods[j % nbMethods]).c_str(), errors[j].c_str());
    }
  }

  // runs.csv
  const std::string csvPath = opt.outputDir + "/runs.csv";
  std::ofstream csv(csvPath);
  if (!csv) {
    throw vpException(vpException::ioError, "%s: cannot write", csvPath.c_str());
  }
  csv << "run,method,water,seed,start_distance,lateral,heading_deg,depth_offset,current_speed,current_dir_deg,"
         "stand_off,start_range,docked,time_to_dock,standoff_rms,settled_steps,first_detection,"
         "collisions_outside_dock,lost_events,final_state,sim_time,start_in_view,failure\n";
  for (size_t j = 0; j < nbJobs; ++j) {
    const Draw &d = draws[j / nbMethods];
    const Result &r = results[j];
    csv << d.run << ',' << vpSSLClosedLoop::methodName(opt.methods[j % nbMethods]) << ','
        << (d.coastal ? "coastal" : "clear") << ',' << d.seed << ',' << vpSSLBenchMath::csvNumber(d.distance, 3) << ','
        << vpSSLBenchMath::csvNumber(d.lateral, 3) << ',' << vpSSLBenchMath::csvNumber(vpMath::deg(d.heading), 2) << ','
        << vpSSLBenchMath::csvNumber(d.depthOffset, 3) << ',' << vpSSLBenchMath::csvNumber(d.currentSpeed, 3) << ','
        << vpSSLBenchMath::csvNumber(vpMath::deg(d.currentDir), 1) << ','
        << vpSSLBenchMath::csvNumber(d.coastal ? 1.5 : 2.0, 1) << ',' << vpSSLBenchMath::csvNumber(r.startRange, 3)
        << ',' << (r.docked ? 1 : 0) << ',' << vpSSLBenchMath::csvNumber(r.timeToDock, 1) << ','
        << vpSSLBenchMath::csvNumber(r.standOffRms, 4) << ',' << r.settledSteps << ','
        << vpSSLBenchMath::csvNumber(r.firstDetection, 1) << ',' << r.collisionsOutsideDock << ',' << r.lostEvents
        << ',' << vpSSLHomingBehaviour::getStateName(r.finalState) << ',' << vpSSLBenchMath::csvNumber(r.simTime, 1)
        << ',' << (d.inView ? 1 : 0) << ',' << r.failure << '\n';
  }
  csv.close();
  if (!csv) {
    throw vpException(vpException::ioError, "%s: write failed", csvPath.c_str());
  }

  // summary.md
  std::ostringstream md;
  md << "Monte Carlo docking: " << opt.runs << " runs per method, seed " << opt.seed << ", " << opt.width << "x"
     << opt.height << ", " << opt.water << " water, start range " << vpSSLBenchMath::csvNumber(opt.startRangeMin, 1)
     << "-" << vpSSLBenchMath::csvNumber(opt.startRangeMax, 1) << " m"
     << (opt.water == "clear" || opt.startRangeMax <= coastalVisibility
             ? std::string()
             : " (coastal starts capped at the visibility, " + vpSSLBenchMath::csvNumber(coastalVisibility, 1) + " m)")
     << ", heading +-" << vpSSLBenchMath::csvNumber(opt.startHeading, 0) << " deg, time limit "
     << vpSSLBenchMath::csvNumber(opt.timeLimit, 0) << " s, " << vpSSLBenchMath::csvNumber(opt.rate, 2)
     << " Hz, current up to " << vpSSLBenchMath::csvNumber(opt.maxCurrent, 2) << " m/s, auto-dock after "
     << vpSSLBenchMath::csvNumber(opt.dockHold, 1) << " s within " << vpSSLBenchMath::csvNumber(opt.dockRange, 2)
     << " m of the stand-off and " << vpSSLBenchMath::csvNumber(opt.dockAngle, 0) << " deg of the optical axis"
     << (opt.stationKeeping ? ", station keeping on the odometry" : ", no station keeping")
     << (opt.dockInTransit ? ", docking in transit across a current" : ", no docking in transit") << "\n\n";
  md << "| method | water | docked | success | stand-off RMS median (m) | p90 (m) | runs settled | time to dock "
        "median (s) | p90 (s) | first detection median (s) | runs detecting | collisions outside DOCK | "
        "lost-target events |";
  for (const std::string &reason : failureReasons()) {
    md << " " << reason << " |";
  }
  md << "\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (size_t m = 0; m < nbMethods; ++m) {
    for (const char *water : {"all", "clear", "coastal"}) {
      std::vector<const Result *> runs;
      for (size_t i = 0; i < draws.size(); ++i) {
        if (std::string(water) == "all" || (draws[i].coastal == (std::string(water) == "coastal"))) {
          runs.push_back(&results[i * nbMethods + m]);
        }
      }
      md << summaryLine(vpSSLClosedLoop::methodName(opt.methods[m]), water, runs);
    }
  }

  // Success and time to dock by start range (1 m bins) and success by current (0.05 m/s bins), per method.
  const double rangeBin = 1., currentBin = 0.05;
  const size_t nbRangeBins = static_cast<size_t>(std::ceil(opt.startRangeMax / rangeBin));
  const size_t nbCurrentBins = std::max<size_t>(1, static_cast<size_t>(std::ceil(opt.maxCurrent / currentBin)));
  vpSSLPlot byRange("Docked by start range", "start range (m)", "docked fraction");
  vpSSLPlot byCurrent("Docked by current", "current (m/s)", "docked fraction");
  md << "\nBy start range (camera to target centre at the start): docked / runs, time to dock median (s)\n\n"
     << "| method |";
  for (size_t b = 0; b < nbRangeBins; ++b) {
    md << " " << vpSSLBenchMath::csvNumber(b * rangeBin, 0) << "-" << vpSSLBenchMath::csvNumber((b + 1) * rangeBin, 0)
       << " m |";
  }
  md << "\n|---|";
  for (size_t b = 0; b < nbRangeBins; ++b) {
    md << "---|";
  }
  md << "\n";
  for (size_t m = 0; m < nbMethods; ++m) {
    std::vector<Bin> ranges(nbRangeBins), currents(nbCurrentBins);
    for (size_t i = 0; i < draws.size(); ++i) {
      const Result &r = results[i * nbMethods + m];
      const size_t rb = std::min(nbRangeBins - 1, static_cast<size_t>(std::max(0., r.startRange) / rangeBin));
      const size_t cb = std::min(nbCurrentBins - 1, static_cast<size_t>(draws[i].currentSpeed / currentBin));
      for (Bin *b : {&ranges[rb], &currents[cb]}) {
        ++b->n;
        b->docked += r.docked ? 1 : 0;
        b->timeToDock.push_back(r.timeToDock);
      }
    }
    auto curve = [](const std::vector<Bin> &bins, double width, std::vector<double> &x, std::vector<double> &y) {
      for (size_t b = 0; b < bins.size(); ++b) {
        x.push_back((b + 0.5) * width);
        y.push_back(bins[b].n ? static_cast<double>(bins[b].docked) / bins[b].n : NAN);
      }
    };
    std::vector<double> xr, yr, xc, yc;
    curve(ranges, rangeBin, xr, yr);
    curve(currents, currentBin, xc, yc);
    const std::string name = vpSSLClosedLoop::methodName(opt.methods[m]);
    byRange.addSeries(name, xr, yr, vpColor::none, vpSSLPlot::STYLE_LINE_MARKERS);
    byCurrent.addSeries(name, xc, yc, vpColor::none, vpSSLPlot::STYLE_LINE_MARKERS);
    md << "| " << name << " |";
    for (const Bin &b : ranges) {
      md << " " << b.docked << "/" << b.n << ", "
         << vpSSLBenchMath::fmt(vpSSLBenchMath::percentile(b.timeToDock, 50.), 1) << " |";
    }
    md << "\n";
  }
  byRange.setYRange(0., 1.05);
  byCurrent.setYRange(0., 1.05);
  byRange.setXRange(0., nbRangeBins * rangeBin);
  byCurrent.setXRange(0., nbCurrentBins * currentBin);
  vpSSLPlot::saveStacked({byRange, byCurrent}, opt.outputDir + "/outcomes.png", 800, 300);

  const std::string mdPath = opt.outputDir + "/summary.md";
  std::ofstream mdFile(mdPath);
  mdFile << md.str();
  mdFile.close();
  if (!mdFile) {
    throw vpException(vpException::ioError, "%s: cannot write", mdPath.c_str());
  }
  std::cout << md.str();
  double wall = 0.;
  for (const Result &r : results) {
    wall += r.wallTime;
  }
  std::printf("\n%zu runs in %.1f s with %zu thread(s): %.1f s per run on average -> %s, %s\n", nbJobs, elapsed,
              std::max<size_t>(1, nbThreads), wall / std::max<size_t>(1, nbJobs), csvPath.c_str(), mdPath.c_str());
  return EXIT_SUCCESS;
}

int main(int argc, char **argv)
{
  // No exception reaches main's caller: one line on stderr and status 1 (2 for a bad option).
  return ssltut::guardedMain("tutorial-ssl-servo-monte-carlo", [&] { return run(argc, argv); });
}

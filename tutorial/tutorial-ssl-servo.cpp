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
#include <visp3/core/vpRxyzVector.h>
#include <visp3/ssl/vpSSLAprilTagSheet.h>
#include <visp3/ssl/vpSSLAuvSimulator.h>
#include <visp3/ssl/vpSSLCameraFile.h>
#include <visp3/ssl/vpSSLHomingBehaviour.h>
#include <visp3/ssl/vpSSLPlot.h>
#include <visp3/ssl/vpSSLRenderer.h>
#include <visp3/ssl/vpSSLScenario.h>
#include <visp3/ssl/vpSSLServoInput.h>
#include <visp3/ssl/vpSSLTracker.h>
#include <visp3/ssl/vpSSLWaterModel.h>

#include "ssl_apriltag_baseline.h"

namespace {
const char *kUsage = R"(Usage: tutorial-ssl-servo [options]
Closes the homing loop of the paper's Sec. 5 on the simulated AUV: at each control step (5 Hz) the camera
image is rendered at the true pose, the target is found (SSL tracker or AprilTag baseline) and the homing
behaviour drives the vehicle. Writes DIR/servo-<scenario>-<method>.csv and .png, prints a one-line summary.
Options:
  --scenario NAME      fig7 (target removed then put back), fig8 (target moved left then right),
                       fig9 (docking), field (coastal water, swaying target). Default fig7.
  --method NAME        ssl (vpSSLTracker on the ssl3-a3 sheet), apriltag (36h11 sheet) or truth (perfect
                       sensor: the ssl3-a3 landmarks projected at the true pose when in view). Default ssl.
  --duration S         Simulated seconds (default: fig7 300, fig8 200, fig9 90, field 120).
  --seed N             Seed of the sensors and the image noise (default 1).
  --output-dir DIR     Where the CSV and PNG go (default ".", created if needed).
  --width W            Image width (camera of data/camera/camera-640x480.xml scaled; default 640).
  --height H           Image height (default 480).
  --small              320 x 240 camera and 1 sample per pixel (fast).
  --supersampling N    Renderer sub-pixels per axis (default 1).
  --quiet              No progress on stderr.
  --help               This help.
CSV columns: t, state, nb_points, est_range, true_range, yaw_rate_demand, yaw_rate, heading_deg, depth,
lateral (vehicle y minus target y, m), target_y, collision.
)";

struct Options
{
  std::string scenario = "fig7";
  std::string method = "ssl";
  double duration = -1.;
  long seed = 1;
  std::string outputDir = ".";
  unsigned int width = 640, height = 480;
  bool small = false;
  int supersampling = -1;
  bool quiet = false;
};

// Thrown for a bad command line: exit code 2.
struct UsageError
{
  std::string message;
};

double parseDouble(const std::string &name, const std::string &text)
{
  char *end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v)) {
    throw UsageError{name + ": not a number: \"" + text + "\""};
  }
  return v;
}

long parsePositive(const std::string &name, const std::string &text, long minimum)
{
  char *end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || v < minimum || v > 100000) {
    throw UsageError{name + ": expected an integer >= " + std::to_string(minimum) + ", got \"" + text + "\""};
  }
  return v;
}

Options parse(int argc, char **argv, bool &help)
{
  Options o;
  help = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        throw UsageError{a + " needs a value"};
      }
      return argv[++i];
    };
    if (a == "--help" || a == "-h") {
      help = true;
    } else if (a == "--scenario") {
      o.scenario = value();
      if (o.scenario != "fig7" && o.scenario != "fig8" && o.scenario != "fig9" && o.scenario != "field") {
        throw UsageError{"--scenario: unknown \"" + o.scenario + "\" (fig7, fig8, fig9, field)"};
      }
    } else if (a == "--method") {
      o.method = value();
      if (o.method != "ssl" && o.method != "apriltag" && o.method != "truth") {
        throw UsageError{"--method: unknown \"" + o.method + "\" (ssl, apriltag, truth)"};
      }
    } else if (a == "--duration") {
      o.duration = parseDouble(a, value());
      if (o.duration <= 0. || o.duration > 3600.) {
        throw UsageError{"--duration: expected a value in (0, 3600] s"};
      }
    } else if (a == "--seed") {
      o.seed = parsePositive(a, value(), 0);
    } else if (a == "--output-dir") {
      o.outputDir = value();
    } else if (a == "--width") {
      o.width = static_cast<unsigned int>(parsePositive(a, value(), 64));
    } else if (a == "--height") {
      o.height = static_cast<unsigned int>(parsePositive(a, value(), 48));
    } else if (a == "--small") {
      o.small = true;
    } else if (a == "--supersampling") {
      o.supersampling = static_cast<int>(parsePositive(a, value(), 1));
      if (o.supersampling > 8) {
        throw UsageError{"--supersampling: expected 1 to 8"};
      }
    } else if (a == "--quiet") {
      o.quiet = true;
    } else {
      throw UsageError{"unknown option " + a + " (see --help)"};
    }
  }
  if (o.small) {
    o.width = 320;
    o.height = 240;
  }
  if (o.supersampling < 0) {
    o.supersampling = 1; // one ray per pixel keeps a 300 s fig7 run at 640x480 within a couple of minutes
  }
  if (o.duration < 0.) {
    o.duration = o.scenario == "fig7" ? 300. : o.scenario == "fig8" ? 200. : o.scenario == "fig9" ? 90. : 120.;
  }
  return o;
}

// One logged control step.
struct Row
{
  double t, nbPoints, estRange, trueRange, yawDemand, yawRate, heading, depth, lateral, targetY, collision;
  vpSSLHomingState state;
};

std::string num(double x, int digits)
{
  if (!std::isfinite(x)) {
    return "";
  }
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", digits, x);
  return buf;
}
} // namespace

int main(int argc, char **argv)
{
  Options opt;
  try {
    bool help = false;
    opt = parse(argc, argv, help);
    if (help) {
      std::cout << kUsage;
      return EXIT_SUCCESS;
    }
  } catch (const UsageError &e) {
    std::cerr << "tutorial-ssl-servo: " << e.message << std::endl;
    return 2;
  }
  const bool aprilTag = opt.method == "apriltag";
  const std::string base = opt.outputDir + "/servo-" + opt.scenario + "-" + opt.method;

  try {
    if (!vpIoTools::checkDirectory(opt.outputDir)) {
      vpIoTools::makeDirectory(opt.outputDir);
    }
    // The camera of the paper's vehicle, scaled to the requested image size (same field of view).
    unsigned int w0 = 0, h0 = 0;
    const vpCameraParameters cam0 =
        vpSSLCameraFile::load(std::string(VISP_SSL_DATA_DIR) + "/camera/camera-640x480.xml", "Camera", &w0, &h0);
    const double sx = static_cast<double>(opt.width) / w0, sy = static_cast<double>(opt.height) / h0;
    vpCameraParameters cam;
    cam.initPersProjWithoutDistortion(cam0.get_px() * sx, cam0.get_py() * sy, cam0.get_u0() * sx, cam0.get_v0() * sy);

    // Scenario figures (paper Sec. 5).
    const double D = opt.duration;
    const bool field = opt.scenario == "field";
    const vpSSLWaterModel water = vpSSLWaterModel::preset(field ? "coastal" : "clear");
    const double standOff = field ? 1.5 : 2.0;
    const vpHomogeneousMatrix wMoHome = vpSSLScenario("approach").getTargetHome();

    vpSSLAuvSimulator auv;
    auv.setTimeStep(0.2); // vision at 5 Hz, dynamics sub-stepped inside
    auv.setTargetPose(wMoHome);
    // 4.5 m south of the target (camera 3.9 m from it), 0.3 m off its axis, 10 degrees off its heading, 0.2 m below
    // it; in coastal water (4 m visibility) 3 m south (camera 2.4 m away), where the target can be seen.
    const vpTranslationVector tHome = wMoHome.getTranslationVector();
    const double back = field ? 3.0 : 4.5;
    auv.reset(vpHomogeneousMatrix(vpTranslationVector(tHome[0] - back, tHome[1] + 0.3, tHome[2] + 0.2),
                                  vpRotationMatrix(vpRxyzVector(0., 0., 0.17))),
              opt.seed);

    vpSSLHomingBehaviour homing;
    homing.getServoLaw().setCameraToVehicle(auv.getCameraToVehicle());
    homing.setStandOff(standOff);
    if (opt.scenario == "fig9") {
      homing.setAutoDock(std::min(10., 0.1 * D)); // dock after holding the stand-off
    }
    // The 0.3 m ssl3-a3 pattern overflows the image within about 1.2 m (0.6 m for the behaviour's default): from
    // there the approach is blind, holding the last surge.
    homing.setBlindDock(1.3, 0.15);

    vpSSLRenderer renderer(cam, opt.width, opt.height);
    renderer.setSupersampling(static_cast<unsigned int>(opt.supersampling));
    const vpSSLAprilTagSheet sheet = vpSSLAprilTagSheet::a3(0);
    if (aprilTag) {
      renderer.setAprilTagSheet(sheet);
    } else {
      renderer.setTarget(vpSSLTarget::ssl3a3());
    }
    // Nothing is left of the direct signal beyond a 1e5 attenuation: stop the rays there (as
    // tutorial-ssl-simulate-sequence).
    const std::array<double, 3> &betaD = water.getAttenuation();
    const double clearest = std::min({betaD[0], betaD[1], betaD[2]});
    if (clearest > 0.) {
      renderer.setMaxRange(std::log(1e5) / clearest);
    }
    // The renderer takes the pose of the tag frame for an AprilTag sheet; the simulator the sheet frame.
    const vpHomogeneousMatrix sMo = aprilTag ? vpSSLAprilTagSheet::getSheetToTag() : vpHomogeneousMatrix();

    const vpSSLTarget target = vpSSLTarget::ssl3a3();
    vpSSLTracker tracker(target, cam, auv.getCameraToVehicle());
    tracker.setSeed(opt.seed);
    sslbench::AprilTagBaseline tagFinder(sheet, cam);

    std::vector<vpPoint> truthPoints;
    for (const vpSSLTargetLandmark &l : target.getLandmarks()) {
      truthPoints.emplace_back(l.x, l.y, l.z);
    }
    std::vector<Row> rows;
    vpImage<float> reflectance, range;
    vpImage<unsigned char> I;
    const auto start = std::chrono::steady_clock::now();
    const int nbSteps = static_cast<int>(std::lround(D / auv.getTimeStep()));
    double dockTime = NAN;
    int lastPercent = -1;
    for (int k = 0; k <= nbSteps; ++k) {
      const double t = auv.getTime();
      // Scenario events: the target taken out and put back, moved, swaying.
      if (opt.scenario == "fig7") {
        auv.setTargetInWater(!(t >= 0.47 * D && t < 0.75 * D));
      } else if (opt.scenario == "fig8") {
        // Moved 0.6 m to port (west, -y) at 0.3 D, then 0.6 m to starboard of home at 0.6 D.
        const double dy = t < 0.3 * D ? 0. : t < 0.6 * D ? -0.6 : 0.6;
        vpHomogeneousMatrix wMo = wMoHome;
        wMo[1][3] += dy;
        auv.setTargetPose(wMo);
      } else if (field) {
        // Swaying on its line: 0.25 m, 12 s period, with a little yaw.
        const double s = std::sin(2. * M_PI * t / 12.);
        vpHomogeneousMatrix wMo = wMoHome * vpHomogeneousMatrix(vpTranslationVector(0.25 * s, 0., 0.),
                                                                vpRotationMatrix(vpRxyzVector(0., 0.1 * s, 0.)));
        auv.setTargetPose(wMo);
      }

      // The camera image at the true pose (open water when the target is out).
      const vpHomogeneousMatrix cMo = auv.get_cMo();
      const vpHomogeneousMatrix wMo = auv.getTargetPose();
      if (opt.method == "truth") {
        // no image needed
      } else if (auv.isTargetInWater()) {
        renderer.setWaterSurface(vpSSLScenario::surfaceInTarget(wMo * sMo));
        renderer.render(cMo * sMo, reflectance, range);
      } else {
        reflectance.resize(opt.height, opt.width, 0.f);
        range.resize(opt.height, opt.width, std::numeric_limits<float>::infinity());
      }
      if (opt.method != "truth") {
        water.apply(reflectance, range, cam, t, opt.seed * 1000003L + k, I);
      }

      vpSSLServoInput input = vpSSLServoInput::none();
      if (opt.method == "truth") {
        if (auv.isTargetInWater() && renderer.isTargetInView(cMo)) {
          input = vpSSLServoInput::fromPose(truthPoints, cMo);
        }
      } else if (aprilTag) {
        if (tagFinder.detect(I)) {
          vpDetectorAprilTag &det = tagFinder.getDetector();
          const std::vector<int> ids = det.getTagsId();
          for (size_t i = 0; i < ids.size(); ++i) {
            if (ids[i] == sheet.getId()) {
              input = vpSSLServoInput::fromAprilTag(det.getPolygon(i), tagFinder.getPose(), sheet.getTagSize(), cam);
              break;
            }
          }
        }
      } else {
        tracker.track(I, auv.getOdometry());
        input = vpSSLServoInput::fromTracker(tracker);
      }

      const vpColVector command = homing.update(t, input, auv.getDepthMeasurement(), auv.getCollision());
      if (homing.getState() == SSL_HOMING_DOCKED && !std::isfinite(dockTime)) {
        dockTime = t;
      }
      Row r;
      r.t = t;
      r.state = homing.getState();
      r.nbPoints = input.valid ? input.nbPoints : 0.;
      r.estRange = homing.getRange();
      r.trueRange = auv.isTargetInWater() ? cMo[2][3] : NAN;
      r.yawDemand = command[5];
      r.yawRate = auv.getBodyVelocity()[5];
      r.heading = vpMath::deg(vpRxyzVector(auv.get_wMv().getRotationMatrix())[2]);
      r.depth = auv.getDepth();
      r.lateral = auv.get_wMv()[1][3] - wMo[1][3];
      r.targetY = wMo[1][3] - wMoHome[1][3];
      r.collision = auv.getCollision() ? 1. : 0.;
      rows.push_back(r);
      if (std::isfinite(dockTime) && t > dockTime + 2.) {
        break; // docked: a little more to show it stays
      }
      homing.apply(auv);

      const int percent = static_cast<int>(100. * k / std::max(1, nbSteps));
      if (!opt.quiet && percent / 10 != lastPercent / 10) {
        lastPercent = percent;
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "t %.0f s (%d %%), state %s, %.0f ms/step\n", t, percent,
                     vpSSLHomingBehaviour::getStateName(homing.getState()).c_str(), 1000. * elapsed / (k + 1));
      }
    }
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    // CSV.
    std::ofstream csv(base + ".csv");
    if (!csv) {
      throw vpException(vpException::ioError, "%s.csv: cannot write", base.c_str());
    }
    csv << "t,state,nb_points,est_range,true_range,yaw_rate_demand,yaw_rate,heading_deg,depth,lateral,target_y,"
           "collision\n";
    for (const Row &r : rows) {
      csv << num(r.t, 2) << ',' << vpSSLHomingBehaviour::getStateName(r.state) << ',' << num(r.nbPoints, 0) << ','
          << num(r.estRange, 4) << ',' << num(r.trueRange, 4) << ',' << num(r.yawDemand, 4) << ',' << num(r.yawRate, 4)
          << ',' << num(r.heading, 2) << ',' << num(r.depth, 4) << ',' << num(r.lateral, 4) << ',' << num(r.targetY, 4)
          << ',' << num(r.collision, 0) << '\n';
    }
    csv.close();

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
    std::vector<vpSSLPlot> panels;
    const std::string what = opt.scenario + ", " + opt.method;
    if (opt.scenario == "fig7" || field) {
      vpSSLPlot yaw = panel("Yaw rate (" + what + ")", "rad/s");
      yaw.addSeries("demanded", ts, column(&Row::yawDemand));
      yaw.addSeries("actual", ts, column(&Row::yawRate), vpColor::red);
      vpSSLPlot depth = panel("Depth", "m");
      depth.addSeries("depth", ts, column(&Row::depth));
      vpSSLPlot state = panel("State (0 search, 1 align, 2 home, 3 dock, 4 docked)", "state");
      state.addSeries("state", ts, stateIndex);
      state.setYRange(-0.5, 4.5);
      vpSSLPlot nb = panel("nbPoints", "points");
      nb.addSeries("nbPoints", ts, column(&Row::nbPoints));
      vpSSLPlot rng = panel("Range", "m");
      rng.addSeries("estimated", ts, column(&Row::estRange));
      rng.addSeries("true", ts, column(&Row::trueRange), vpColor::red);
      rng.addHorizontalLine(standOff, "stand-off");
      panels = {yaw, depth, state, nb, rng};
    } else if (opt.scenario == "fig8") {
      vpSSLPlot lat = panel("Lateral position (" + what + ")", "y (m)");
      lat.addSeries("vehicle - target", ts, column(&Row::lateral));
      lat.addSeries("target moved", ts, column(&Row::targetY), vpColor::red);
      vpSSLPlot heading = panel("Heading", "deg");
      heading.addSeries("heading", ts, column(&Row::heading));
      vpSSLPlot yaw = panel("Yaw rate", "rad/s");
      yaw.addSeries("demanded", ts, column(&Row::yawDemand));
      yaw.addSeries("actual", ts, column(&Row::yawRate), vpColor::red);
      panels = {lat, heading, yaw};
    } else {
      vpSSLPlot rng = panel("Range (" + what + ")", "m");
      rng.addSeries("estimated", ts, column(&Row::estRange));
      rng.addSeries("true", ts, column(&Row::trueRange), vpColor::red);
      vpSSLPlot nb = panel("nbPoints", "points");
      nb.addSeries("nbPoints", ts, column(&Row::nbPoints));
      vpSSLPlot col = panel("Collision", "flag");
      col.addSeries("collision", ts, column(&Row::collision));
      col.setYRange(-0.1, 1.1);
      vpSSLPlot state = panel("State (0 search, 1 align, 2 home, 3 dock, 4 docked)", "state");
      state.addSeries("state", ts, stateIndex);
      state.setYRange(-0.5, 4.5);
      panels = {rng, nb, col, state};
    }
    vpSSLPlot::saveStacked(panels, base + ".png");

    // Summary: stand-off RMS error over the HOME steps (true range) once settled, i.e. after the range first
    // came within 0.1 m of the stand-off (the approach from the start is not an error).
    double sum = 0.;
    size_t n = 0;
    bool settled = false;
    for (const Row &r : rows) {
      settled = settled || (r.state == SSL_HOMING_HOME && std::fabs(r.trueRange - standOff) < 0.1);
      if (settled && r.state == SSL_HOMING_HOME && std::isfinite(r.trueRange)) {
        sum += (r.trueRange - standOff) * (r.trueRange - standOff);
        ++n;
      }
    }
    std::printf("scenario %s, method %s, %.0f s simulated in %.1f s (%.0f ms/step, %ux%u, %d spp): final state %s, "
                "stand-off RMS %s m over %zu settled HOME steps, time to dock %s s -> %s.csv/.png\n",
                opt.scenario.c_str(), opt.method.c_str(), rows.empty() ? 0. : rows.back().t, elapsed,
                1000. * elapsed / std::max<size_t>(1, rows.size()), opt.width, opt.height,
                opt.supersampling * opt.supersampling, vpSSLHomingBehaviour::getStateName(homing.getState()).c_str(),
                n ? num(std::sqrt(sum / n), 3).c_str() : "n/a", n,
                std::isfinite(dockTime) ? num(dockTime, 1).c_str() : "n/a", base.c_str());
  } catch (const vpException &e) {
    std::cerr << "tutorial-ssl-servo: " << e.getStringMessage() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}

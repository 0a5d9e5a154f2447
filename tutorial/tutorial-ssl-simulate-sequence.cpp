//! \example tutorial-ssl-simulate-sequence.cpp
//! Writes a simulated underwater sequence (images, ground truth, odometry) in the recorded-sequence format.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <visp3/core/vpException.h>
#include <visp3/core/vpPoseVector.h>
#include <visp3/ssl_io/vpSSLCameraFile.h>
#include <visp3/ssl_io/vpSSLSequenceInfo.h>
#include <visp3/ssl_io/vpSSLSequenceWriter.h>
#include <visp3/ssl_sim/vpSSLAprilTagSheet.h>
#include <visp3/ssl_sim/vpSSLBackground.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>
#include <visp3/ssl_sim/vpSSLScenario.h>
#include <visp3/ssl_sim/vpSSLWaterModel.h>

#include "ssl_tutorial_common.h"

namespace {
const char *kUsage = R"(Usage: tutorial-ssl-simulate-sequence --output DIR [options]

Renders a scenario (vehicle and target trajectories) through a water model and writes it as a
recorded sequence (camera.xml, sequence.json, frames.csv, images/%%06d.png): ground truth cMo
(empty when the target is out of view), vehicle odometry oMv with drift and noise, and extra
columns: gt_<landmark>_u/v (projected landmark centres, or AprilTag corners gt_c0_u ... gt_c3_v),
range (m), water (preset), true_odom_* (the true vehicle pose the odometry estimates).
The same options and seed always give byte-identical files.

Options:
  --output DIR          Sequence folder to write. Required.
  --overwrite           Replace the sequence files in a folder that is not empty.
  --scenario NAME       Trajectory (default approach), one of:
%s  --water PRESET        Water (default clear), one of:
%s  --camera CAM          "default" (640x480, about 60 deg horizontal field of view in water, like
                        the paper's Point Grey behind a flat port), "wide" (640x480, about 85 deg,
                        barrel distortion), or a ViSP XML camera file with a camera named
                        "Camera" and its image size (data/camera/ has both built-in ones).
  --target NAME|FILE    SSL target: built-in name or target file (default ssl3-a3).
  --apriltag [ID]       An AprilTag 36h11 (id ID, default 0) as large as fits on an A3 sheet,
                        instead of the SSL target; ground truth is vpDetectorAprilTag's tag frame.
  --frames N            Number of frames (default 100); the path is the same, only sampled.
  --fps F               Frames per second (default 10).
  --ranges A,B          Camera-to-target range at the first and last frames (m), replacing the
                        scenario's.
  --seed S              Seed of the sensor noise, odometry and seabed, an integer in
                        [-2147483647, 2147483647] (default 1).
  --background B        What is behind the target (default water): water (open water), seabed
                        (procedural sea floor), klimt or solvay (a photograph from
                        visp-images-data on a wall behind the target), or an image file.
  --supersampling N     Sub-pixels per axis of the renderer, 1 to 16 (default 4: 16 rays per
                        pixel).
  --colour              Write colour images (default grey, as the detector reads them).
  --help                This help.

Inputs are bounded (doc/input-limits.md): camera image at most 16384 px a side and 2^26
pixels, target files as in doc/target-file.md.

Progress goes to stderr; a summary line to stdout. Exit status: 0 on success, 2 on a bad
option or input (one line on stderr, nothing written), 1 when rendering or writing fails
(a full device included) or on any other runtime failure.
)";

std::string listing(const std::vector<std::string> &names, bool scenarios)
{
  std::ostringstream os;
  for (const std::string &n : names) {
    char buf[256];
    if (scenarios) {
      std::snprintf(buf, sizeof(buf), "                          %-13s %s\n", n.c_str(),
                    vpSSLScenario::getDescription(n).c_str());
    } else {
      std::snprintf(buf, sizeof(buf), "                          %-13s %.0f m visibility\n", n.c_str(),
                    vpSSLWaterModel::preset(n).getVisibility());
    }
    os << buf;
  }
  return os.str();
}

// A number for frames.csv: fixed decimals, so that the same run writes the same bytes.
std::string cell(double x, int digits)
{
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", digits, x);
  return buf;
}

double toNumber(const std::string &option, const std::string &text)
{
  char *end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v)) {
    throw vpException(vpException::badValue, "%s: not a number: \"%s\"", option.c_str(), text.c_str());
  }
  return v;
}

unsigned int toCount(const std::string &option, const std::string &text)
{
  const double v = toNumber(option, text);
  if (v < 1. || v > 1e7 || v != std::floor(v)) {
    throw vpException(vpException::badValue, "%s: expected a whole number >= 1, got \"%s\"", option.c_str(),
                      text.c_str());
  }
  return static_cast<unsigned int>(v);
}

// The camera of --camera, and its image size.
vpCameraParameters readCamera(const std::string &what, unsigned int &width, unsigned int &height)
{
  width = 640;
  height = 480;
  vpCameraParameters cam;
  if (what == "default") {
    cam.initPersProjWithoutDistortion(554.3, 554.3, 320., 240.);
    return cam;
  }
  if (what == "wide") {
    // kdu: least-squares inverse of kud over the image (data/camera/camera-640x480-wide.xml).
    cam.initPersProjWithDistortion(360., 360., 320., 240., -0.03, 0.032348);
    return cam;
  }
  std::ifstream probe(what);
  if (!probe) {
    throw vpException(vpException::ioError, "--camera: cannot read \"%s\" (use default, wide or a ViSP XML file)",
                      what.c_str());
  }
  cam = vpSSLCameraFile::load(what, "Camera", &width, &height);
  if (width == 0 || height == 0) {
    throw vpException(vpException::badValue, "%s: camera \"Camera\": image_width and image_height are needed",
                      what.c_str());
  }
  return cam;
}
} // namespace

static int run(int argc, char **argv)
{
  std::string output, scenarioName = "approach", waterName = "clear", cameraName = "default", targetName = "ssl3-a3";
  std::string backgroundName = "water";
  bool overwrite = false, colour = false, aprilTag = false, ranges = false;
  int tagId = 0;
  unsigned int nbFrames = 100, supersampling = 4;
  double fps = 10., startRange = 0., endRange = 0.;
  long seed = 1;
  vpSSLScenario scenario;
  vpSSLWaterModel water;
  vpSSLBackground background;
  vpCameraParameters cam;
  unsigned int width = 0, height = 0;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) {
          throw vpException(vpException::badValue, "%s: missing value", arg.c_str());
        }
        return argv[++i];
      };
      if (arg == "--help" || arg == "-h") {
        std::printf(kUsage, listing(vpSSLScenario::getNames(), true).c_str(),
                    listing(vpSSLWaterModel::getPresetNames(), false).c_str());
        return EXIT_SUCCESS;
      } else if (arg == "--output") {
        output = value();
      } else if (arg == "--overwrite") {
        overwrite = true;
      } else if (arg == "--scenario") {
        scenarioName = value();
      } else if (arg == "--water") {
        waterName = value();
      } else if (arg == "--camera") {
        cameraName = value();
      } else if (arg == "--target") {
        targetName = value();
      } else if (arg == "--apriltag") {
        aprilTag = true;
        if (i + 1 < argc && argv[i + 1][0] != '-') {
          const double id = toNumber(arg, argv[++i]);
          if (id != std::floor(id) || id < 0. || id > 586.) {
            throw vpException(vpException::badValue, "--apriltag: id must be a whole number in [0, 586]");
          }
          tagId = static_cast<int>(id);
        }
      } else if (arg == "--frames") {
        nbFrames = toCount(arg, value());
      } else if (arg == "--fps") {
        fps = toNumber(arg, value());
      } else if (arg == "--ranges") {
        const std::string v = value();
        const size_t comma = v.find(',');
        if (comma == std::string::npos) {
          throw vpException(vpException::badValue, "--ranges: expected START,END in metres, got \"%s\"", v.c_str());
        }
        startRange = toNumber(arg, v.substr(0, comma));
        endRange = toNumber(arg, v.substr(comma + 1));
        ranges = true;
      } else if (arg == "--seed") {
        // The frames' seeds are seed * 1000003 + index: a seed within 32 bits keeps them inside a long.
        seed = static_cast<long>(ssltut::parseInteger(arg, value(), -2147483647LL, 2147483647LL));
      } else if (arg == "--background") {
        backgroundName = value();
      } else if (arg == "--supersampling") {
        supersampling = static_cast<unsigned int>(ssltut::parseInteger(arg, value(), 1, 16));
      } else if (arg == "--colour" || arg == "--color") {
        colour = true;
      } else {
        throw vpException(vpException::badValue, "unknown option \"%s\" (see --help)", arg.c_str());
      }
    }
    if (output.empty()) {
      throw vpException(vpException::badValue, "--output DIR is required (see --help)");
    }

    scenario = vpSSLScenario(scenarioName);
    scenario.setFrames(nbFrames, fps);
    scenario.setSeed(seed);
    if (ranges) {
      scenario.setRanges(startRange, endRange);
    }
    water = vpSSLWaterModel::preset(waterName);
    cam = readCamera(cameraName, width, height);
    background = vpSSLBackground::fromName(backgroundName, seed);
  } catch (const vpException &e) {
    std::cerr << "tutorial-ssl-simulate-sequence: " << e.getStringMessage() << std::endl;
    return 2;
  } catch (const ssltut::UsageError &e) {
    std::cerr << "tutorial-ssl-simulate-sequence: " << e.what() << std::endl;
    return 2;
  }
  std::error_code ec;
  if (!overwrite && std::filesystem::is_directory(output, ec) && !std::filesystem::is_empty(output, ec)) {
    std::cerr << "tutorial-ssl-simulate-sequence: " << output
              << ": folder is not empty (use --overwrite to replace the sequence in it)" << std::endl;
    return 2;
  }

  // The scene: target sheet, backdrop, water surface.
  vpSSLRenderer renderer(cam, width, height);
  std::vector<std::string> landmarkNames;
  vpSSLSequenceInfo info;
  try {
    renderer.setSupersampling(supersampling);
    if (aprilTag) {
      const vpSSLAprilTagSheet sheet = vpSSLAprilTagSheet::a3(tagId);
      renderer.setAprilTagSheet(sheet);
      info.target = sheet.getName();
      landmarkNames = {"c0", "c1", "c2", "c3"};
    } else {
      const vpSSLTarget target = vpSSLTarget::fromName(targetName);
      renderer.setTarget(target);
      info.target = targetName;
      for (const vpSSLTargetLandmark &l : target.getLandmarks()) {
        landmarkNames.push_back(l.name);
      }
    }
  } catch (const vpException &e) {
    std::cerr << "tutorial-ssl-simulate-sequence: " << e.getStringMessage() << std::endl;
    return 2;
  }
  background.apply(renderer);
  // Beyond the range where the clearest channel's direct signal has fallen by 1e5, nothing is left of it, even
  // at the auto exposure's largest gain (255 x 64 x 1e-5 < half a grey level): the renderer stops the rays there.
  const std::array<double, 3> &betaD = water.getAttenuation();
  const double clearest = std::min({betaD[0], betaD[1], betaD[2]});
  if (clearest > 0.) {
    renderer.setMaxRange(std::log(1e5) / clearest);
  }
  const vpHomogeneousMatrix wMb = background.getWorldPose(scenario);
  // Ground truth is the pose of the target frame: for an AprilTag, vpDetectorAprilTag's tag frame.
  const vpHomogeneousMatrix sMo = aprilTag ? vpSSLAprilTagSheet::getSheetToTag() : vpHomogeneousMatrix();

  info.vMc = vpPoseVector(scenario.getCameraToVehicle());
  info.source = "simulated";
  info.water = water.toJson();
  std::vector<std::string> columns;
  for (const std::string &n : landmarkNames) {
    columns.push_back("gt_" + n + "_u");
    columns.push_back("gt_" + n + "_v");
  }
  columns.push_back("range");
  columns.push_back("water");
  for (const char *c : {"tx", "ty", "tz", "tux", "tuy", "tuz"}) {
    columns.push_back(std::string("true_odom_") + c);
  }

  vpSSLSequenceWriter writer;
  writer.setOverwrite(overwrite);
  const auto start = std::chrono::steady_clock::now();
  unsigned int nbWithTruth = 0;
  try {
    writer.open(output, cam, info, columns);
    // What produced the sequence, beside the members of doc/sequence-format.md (readers ignore the others).
    std::string json = info.toJson();
    std::ostringstream sim;
    sim << ",\n  \"simulation\": {\"scenario\": \"" << scenario.getName() << "\", \"frames\": " << nbFrames
        << ", \"fps\": " << fps << ", \"start_range_m\": " << scenario.getStartRange()
        << ", \"end_range_m\": " << scenario.getEndRange() << ", \"seed\": " << seed << ", \"camera\": \""
        << (cameraName == "default" || cameraName == "wide" ? cameraName : "file") << "\", \"background\": \""
        << (background.getType() == vpSSLBackground::BACKGROUND_WALL && backgroundName != "klimt" &&
                    backgroundName != "solvay"
                ? "image"
                : backgroundName)
        << "\", \"supersampling\": " << supersampling << "}";
    const size_t close = json.rfind('}');
    json = json.substr(0, json.find_last_not_of(" \n", close - 1) + 1) + sim.str() + "\n}\n";
    vpSSLSequenceInfo::fromJson(json); // still a valid sequence.json
    std::ofstream jsonFile(output + "/sequence.json");
    jsonFile << json;
    ssltut::finishStream(jsonFile, output + "/sequence.json");

    const std::vector<vpSSLScenarioFrame> frames = scenario.generate();
    const unsigned int step = nbFrames >= 20 ? nbFrames / 10 : nbFrames + 1;
    vpImage<float> reflectance, range;
    vpImage<unsigned char> grey;
    vpImage<vpRGBa> rgb;
    for (const vpSSLScenarioFrame &f : frames) {
      const vpHomogeneousMatrix cMo = f.cMo * sMo, wMo = f.wMo * sMo;
      const vpHomogeneousMatrix oMw = wMo.inverse();
      renderer.setBackdropPose(oMw * wMb);
      renderer.setWaterSurface(vpSSLScenario::surfaceInTarget(wMo));
      renderer.render(cMo, reflectance, range);
      const long frameSeed = seed * 1000003L + f.index;

      vpSSLSequenceFrame row;
      row.index = f.index;
      row.t = f.t;
      row.hasOdometry = true;
      row.oMv = vpPoseVector(f.oMv);
      row.hasGroundTruth = renderer.isTargetInView(cMo);
      row.cMo = vpPoseVector(cMo);
      row.extras["water"] = water.getName();
      const vpPoseVector truth(f.oMvTrue);
      const char *axes[] = {"tx", "ty", "tz", "tux", "tuy", "tuz"};
      for (unsigned int k = 0; k < 6; ++k) {
        row.extras[std::string("true_odom_") + axes[k]] = cell(truth[k], 9);
      }
      if (row.hasGroundTruth) {
        nbWithTruth++;
        row.extras["range"] = cell(f.range, 6);
        const std::vector<vpImagePoint> points = renderer.projectLandmarks(cMo);
        for (size_t k = 0; k < points.size(); ++k) {
          if (std::isfinite(points[k].get_u()) && std::isfinite(points[k].get_v())) {
            row.extras["gt_" + landmarkNames[k] + "_u"] = cell(points[k].get_u(), 4);
            row.extras["gt_" + landmarkNames[k] + "_v"] = cell(points[k].get_v(), 4);
          }
        }
      }
      if (colour) {
        water.apply(reflectance, range, cam, f.t, frameSeed, rgb);
        writer.write(row, rgb);
      } else {
        water.apply(reflectance, range, cam, f.t, frameSeed, grey);
        writer.write(row, grey);
      }
      if ((f.index + 1) % step == 0) {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "frame %u/%u (%.0f %%), %.0f ms/frame\n", f.index + 1, nbFrames,
                     100. * (f.index + 1) / nbFrames, 1000. * elapsed / (f.index + 1));
      }
    }
    writer.close();
  } catch (const vpException &e) {
    std::cerr << "tutorial-ssl-simulate-sequence: " << e.getStringMessage() << std::endl;
    return EXIT_FAILURE;
  }
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("wrote %u frames (%u with the target in view) of scenario %s, %s water, to %s in %.1f s (%.0f "
              "ms/frame)\n",
              nbFrames, nbWithTruth, scenario.getName().c_str(), water.getName().c_str(), output.c_str(), elapsed,
              1000. * elapsed / nbFrames);
  std::fflush(stdout);
  if (std::ferror(stdout)) {
    std::cerr << "tutorial-ssl-simulate-sequence: standard output: write error" << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}

int main(int argc, char **argv)
{
  return ssltut::guardedMain("tutorial-ssl-simulate-sequence", [&] { return run(argc, argv); });
}

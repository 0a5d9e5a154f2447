/*
  The underwater image formation model: the contrast of a landmark falls with range and with
  turbidity, the presets mean the visibility they are named by, and an image is reproducible.
*/
#include <cmath>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include <visp3/ssl_sim/vpSSLRenderer.h>
#include <visp3/ssl_sim/vpSSLWaterModel.h>

#include "ssl_test_utils.h"

namespace {
const vpCameraParameters kCam(600., 600., 320., 240.);

// Michelson contrast between B's outer black ring and the white ring inside it, in ssl3-a3 rendered
// fronto-parallel at range z (reflectance, range) and seen through \e water.
double bigLandmarkContrast(const vpSSLWaterModel &water, const vpImage<float> &reflectance, const vpImage<float> &range,
                           const vpImagePoint &centre, double z)
{
  vpImage<unsigned char> I;
  water.apply(reflectance, range, kCam, 0., 1, I);
  const double a = 600. * 0.1 / z;
  double black = 0., white = 0.;
  int nb = 0, nw = 0;
  for (unsigned int v = 0; v < I.getHeight(); ++v) {
    for (unsigned int u = 0; u < I.getWidth(); ++u) {
      const double r = std::hypot(u - centre.get_u(), v - centre.get_v()) / a;
      if (r > 0.78 && r < 0.93) { // ring 0: (0.707, 1], black
        black += I[v][u];
        ++nb;
      } else if (r > 0.55 && r < 0.67) { // ring 1: (0.5, 0.707], white
        white += I[v][u];
        ++nw;
      }
    }
  }
  black /= nb;
  white /= nw;
  return (white - black) / (white + black);
}

vpSSLWaterModel noiseFree(const std::string &preset)
{
  vpSSLWaterModel water = vpSSLWaterModel::preset(preset);
  water.setSensorNoise(0., 0.);
  return water;
}
} // namespace

TEST(WaterModel, LandmarkContrastFallsWithRangeAndTurbidity)
{
  const std::vector<double> ranges = {1., 2., 3., 5., 8.};
  const std::vector<std::string> presets = vpSSLWaterModel::getPresetNames(); // clear, coastal, turbid
  std::vector<std::vector<double>> contrast(presets.size());
  vpSSLRenderer renderer(kCam, 640, 480);
  vpImage<float> reflectance, range;
  for (double z : ranges) {
    const vpHomogeneousMatrix cMo = sslt::lookAt(z);
    renderer.render(cMo, reflectance, range);
    for (size_t p = 0; p < presets.size(); ++p) {
      // Noise-free, auto exposure (the default) as a camera would adapt.
      contrast[p].push_back(
          bigLandmarkContrast(noiseFree(presets[p]), reflectance, range, renderer.projectLandmarks(cMo)[0], z));
    }
  }
  // A contrast below 1 % is lost in the 8-bit quantisation: only require it not to rise again.
  for (size_t p = 0; p < contrast.size(); ++p) {
    for (size_t i = 0; i + 1 < ranges.size(); ++i) {
      if (contrast[p][i] > 0.01) {
        EXPECT_LT(contrast[p][i + 1], contrast[p][i]) << "preset " << p << " from " << ranges[i] << " m";
      } else {
        EXPECT_LE(contrast[p][i + 1], 0.01) << "preset " << p << " from " << ranges[i] << " m";
      }
    }
  }
  for (size_t i = 0; i < ranges.size(); ++i) {
    ASSERT_EQ(presets[0] + presets[1] + presets[2], "clearcoastalturbid");
    EXPECT_GT(contrast[0][i], contrast[1][i]) << "clear vs coastal at " << ranges[i] << " m";
    if (contrast[1][i] > 0.01) {
      EXPECT_GT(contrast[1][i], contrast[2][i]) << "coastal vs turbid at " << ranges[i] << " m";
    }
  }
  EXPECT_GT(contrast[0][0], 0.7);  // clear water at 1 m: close to the print's contrast
  EXPECT_GT(contrast[0][4], 0.03); // clear water at 8 m: still there, as in the paper's tank
  EXPECT_GT(contrast[1][2], 0.05); // coastal at 3 m: still there, as off Peel Island
}

TEST(WaterModel, VisibilityIsWhereABlackTargetKeeps2PercentContrast)
{
  for (const std::string &name : vpSSLWaterModel::getPresetNames()) {
    vpSSLWaterModel water = noiseFree(name);
    const double V = water.getVisibility();
    // Left half: a black target at range V; right half: open water.
    vpImage<float> reflectance(8, 16, 0.f), range(8, 16, std::numeric_limits<float>::infinity());
    for (unsigned int v = 0; v < 8; ++v) {
      for (unsigned int u = 0; u < 8; ++u) {
        range[v][u] = static_cast<float>(V);
      }
    }
    vpImage<vpRGBa> I;
    water.setExposure(1.);
    water.apply(reflectance, range, kCam, 0., 1, I);
    // Scale so that open water reads ~250 in green, for resolution, then measure the green contrast.
    water.setExposure(250. / I[4][12].G);
    water.apply(reflectance, range, kCam, 0., 1, I);
    const double contrast = (I[4][12].G - I[4][3].G) / static_cast<double>(I[4][12].G);
    EXPECT_NEAR(contrast, 0.02, 0.004) << name;
  }
  EXPECT_NEAR(vpSSLWaterModel::preset("clear").getVisibility(), 10., 1e-9);
  EXPECT_NEAR(vpSSLWaterModel::preset("coastal").getVisibility(), 4., 1e-9);
  EXPECT_NEAR(vpSSLWaterModel::preset("turbid").getVisibility(), 2., 1e-9);
}

TEST(WaterModel, SameSeedSameImage)
{
  vpSSLRenderer renderer(kCam, 160, 120);
  renderer.setSupersampling(2);
  vpImage<float> reflectance, range;
  renderer.render(sslt::lookAt(1.), reflectance, range);
  vpSSLWaterModel water = vpSSLWaterModel::preset("coastal");
  water.setCaustics(0.5);
  vpImage<vpRGBa> A, B, C;
  water.apply(reflectance, range, kCam, 0.3, 7, A);
  water.apply(reflectance, range, kCam, 0.3, 7, B);
  water.apply(reflectance, range, kCam, 0.3, 8, C);
  EXPECT_TRUE(A == B);
  EXPECT_FALSE(A == C);
}

TEST(WaterModel, ImageDoesNotDependOnThePreviousFrames)
{
  // apply() keeps its planes from one call to the next in each thread: a frame after others of other sizes, with
  // more or fewer pixels of open water, is the frame a thread that never rendered gives.
  struct Frame
  {
    unsigned int width, height;
    double distance;
  };
  // Clear water blurs little (the lowest blur levels are in use), turbid water much.
  const std::vector<Frame> frames = {{160, 120, 1.}, {160, 120, 8.}, {80, 60, 2.}, {160, 120, 1.}, {160, 120, 30.}};
  for (size_t i = 0; i < 2 * frames.size(); ++i) {
    const vpSSLWaterModel water = vpSSLWaterModel::preset(i < frames.size() ? "clear" : "turbid");
    const Frame &f = frames[i % frames.size()];
    const vpCameraParameters cam(2. * f.width, 2. * f.width, 0.5 * f.width, 0.5 * f.height);
    vpSSLRenderer renderer(cam, f.width, f.height);
    renderer.setSupersampling(2);
    vpImage<float> reflectance, range;
    renderer.render(sslt::lookAt(f.distance), reflectance, range);
    vpImage<vpRGBa> colour, freshColour;
    vpImage<unsigned char> grey, freshGrey;
    water.apply(reflectance, range, cam, 0.1 * i, static_cast<long>(i), colour);
    water.apply(reflectance, range, cam, 0.1 * i, static_cast<long>(i), grey);
    std::thread fresh([&]() {
      water.apply(reflectance, range, cam, 0.1 * i, static_cast<long>(i), freshColour);
      water.apply(reflectance, range, cam, 0.1 * i, static_cast<long>(i), freshGrey);
    });
    fresh.join();
    EXPECT_TRUE(colour == freshColour) << "frame " << i;
    EXPECT_TRUE(grey == freshGrey) << "frame " << i;
  }
}

TEST(WaterModel, RedIsAbsorbedFirst)
{
  // Clear water: white paper at 5 m looks blue-green, and open water is blue.
  vpImage<float> reflectance(4, 8, 1.f), range(4, 8, 5.f);
  for (unsigned int v = 0; v < 4; ++v) {
    for (unsigned int u = 4; u < 8; ++u) {
      range[v][u] = std::numeric_limits<float>::infinity();
    }
  }
  vpImage<vpRGBa> I;
  noiseFree("clear").apply(reflectance, range, kCam, 0., 1, I);
  EXPECT_LT(I[2][1].R, I[2][1].G);
  EXPECT_LT(I[2][1].R, I[2][1].B);
  EXPECT_LT(I[2][6].G, I[2][6].B);
}

TEST(WaterModel, LampFallsOffWithSquaredRange)
{
  vpSSLWaterModel water = noiseFree("clear");
  water.setAttenuation({0., 0., 0.});
  water.setBackscatter({0., 0., 0.}, {0., 0., 0.});
  water.setForwardScatter(0.);
  water.setArtificialLight(0.8);
  water.setExposure(1.);
  vpImage<float> reflectance(2, 2, 1.f), range(2, 2, 1.f);
  range[0][1] = range[1][1] = 2.f;
  vpImage<unsigned char> I;
  water.apply(reflectance, range, kCam, 0., 1, I);
  EXPECT_NEAR(I[0][0], 204., 1.);      // 0.8 * 255
  EXPECT_NEAR(I[0][1], 204. / 4., 1.); // 1 / z^2
}

TEST(WaterModel, ForwardScatterBlurGrowsWithRange)
{
  // A vertical step edge at two ranges, no attenuation: count the pixels of intermediate grey.
  vpSSLWaterModel water = noiseFree("turbid");
  water.setAttenuation({0., 0., 0.});
  water.setBackscatter({0., 0., 0.}, {0., 0., 0.});
  water.setExposure(1.);
  auto edgeWidth = [&](float z) {
    vpImage<float> reflectance(9, 120, 0.f), range(9, 120, z);
    for (unsigned int v = 0; v < 9; ++v) {
      for (unsigned int u = 60; u < 120; ++u) {
        reflectance[v][u] = 1.f;
      }
    }
    vpImage<unsigned char> I;
    water.apply(reflectance, range, kCam, 0., 1, I);
    const double lo = 0.1 * I[4][119], hi = 0.9 * I[4][119];
    int n = 0;
    for (unsigned int u = 0; u < 120; ++u) {
      n += I[4][u] > lo && I[4][u] < hi;
    }
    return n;
  };
  const int near = edgeWidth(0.5f), mid = edgeWidth(2.f), far = edgeWidth(6.f);
  EXPECT_LT(near, mid);
  EXPECT_LT(mid, far);
}

TEST(WaterModel, CausticsFlickerOverTime)
{
  vpImage<float> reflectance(32, 32, 1.f), range(32, 32, 2.f);
  vpSSLWaterModel water = noiseFree("clear");
  water.setSunLight(1., {0.4, 0.08, 0.05});
  water.setExposure(0.8);
  vpImage<unsigned char> A, B;
  water.apply(reflectance, range, kCam, 0., 1, A);
  water.apply(reflectance, range, kCam, 0.7, 1, B);
  EXPECT_TRUE(A == B); // no caustics: time does not matter
  water.setCaustics(0.6);
  water.apply(reflectance, range, kCam, 0., 1, A);
  water.apply(reflectance, range, kCam, 0.7, 1, B);
  EXPECT_FALSE(A == B);
}

TEST(WaterModel, BadParametersAreRejected)
{
  EXPECT_THROW(vpSSLWaterModel::preset("muddy"), vpException);
  vpSSLWaterModel water;
  EXPECT_THROW(water.setAttenuation({-1., 0., 0.}), vpException);
  EXPECT_THROW(water.setExposure(0.), vpException);
  vpImage<float> a(2, 2), b(3, 2);
  vpImage<unsigned char> I;
  EXPECT_THROW(water.apply(a, b, kCam, 0., 1, I), vpException);
  EXPECT_NE(vpSSLWaterModel::preset("coastal").toJson().find("\"visibility_m\": 4"), std::string::npos);
}

/*!
  \file vpSSLWaterModel.cpp
  \brief Revised underwater image formation model (Akkaynak and Treibitz 2018) with forward scatter,
  sunlight or lamp, caustics and Poisson-Gaussian sensor noise.
*/
#include <visp3/ssl_sim/vpSSLWaterModel.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include <visp3/core/vpException.h>
#include <visp3/core/vpImageConvert.h>

#include "vpSSLBlur.h"
#include "vpSSLGaussRand.h"
#include "vpSSLNoiseKernel.h"

namespace {
// ln(1 / 0.02): the 2 % contrast threshold of the human (and Secchi-disc) visibility definition.
const double kLn50 = std::log(50.);
// Blur levels (px) of the forward-scatter stack; a pixel's blur interpolates linearly between two of
// them. Beyond 16 px the image is washed out by backscatter anyway, and the blur cost grows with sigma.
const double kBlurLevels[] = {0., 0.5, 1., 2., 4., 8., 16.};
const size_t kNbBlurLevels = sizeof(kBlurLevels) / sizeof(kBlurLevels[0]);
// The lamp's 1 / z^2 is capped at this range so that a target touching the port does not go infinite.
const double kLampMinRange = 0.1;
// Rec. 601 luminance, the weights vpImageConvert uses for RGBa -> grey.
const double kLuma[3] = {0.299, 0.587, 0.114};

// beta^B_G giving a visibility of V metres (2 % contrast of a black target against open water).
double ln50Over(double visibility)
{
  return kLn50 / visibility;
}

void checkNonNegative(const std::array<double, 3> &v, const char *what)
{
  for (double x : v) {
    if (!(x >= 0. && std::isfinite(x))) {
      std::ostringstream os;
      os << "vpSSLWaterModel: " << what << " must be finite and >= 0, got (" << v[0] << ", " << v[1] << ", " << v[2]
         << ")";
      throw vpException(vpException::badValue, os.str());
    }
  }
}

void checkNonNegative(double x, const char *what)
{
  if (!(x >= 0. && std::isfinite(x))) {
    std::ostringstream os;
    os << "vpSSLWaterModel: " << what << " must be finite and >= 0, got " << x;
    throw vpException(vpException::badValue, os.str());
  }
}

// The per-frame planes of apply() and radiance(), kept from one frame to the next by each thread that renders: the
// simulators call apply() every step with the same image size, and allocating and zeroing some 10 MB per frame would
// cost page faults and memset every frame. One per thread keeps apply() safe to call concurrently on the same model;
// every plane is fully written before it is read.
struct Workspace
{
  std::vector<float> rgb;            // radiance, planar: channel, pixel
  std::vector<float> direct;         // direct signal before the forward-scatter blur, planar
  std::vector<float> wHigh;          // weight of the pixel's upper blur level
  std::vector<unsigned char> level;  // the pixel's lower blur level
  std::vector<float> plane, scratch; // one channel's direct signal at one blur level, and the blur's scratch
  std::vector<float> weight;         // the pixels' weights at one blur level
  vpImage<vpRGBa> colour;            // the colour image the grey one is converted from
};

Workspace &workspace()
{
  thread_local Workspace w;
  return w;
}

std::string jsonArray(const std::array<double, 3> &v)
{
  std::ostringstream os;
  os << std::setprecision(6) << "[" << v[0] << ", " << v[1] << ", " << v[2] << "]";
  return os.str();
}
} // namespace

vpSSLWaterModel::vpSSLWaterModel()
    : m_name("clear"), m_betaD(), m_betaB(), m_veiling(), m_forwardScatter(0.), m_light(LIGHT_SUN), m_depth(3.),
      m_diffuseAttenuation(), m_surfaceIrradiance(1.), m_lampPower(1.), m_causticAmplitude(0.), m_causticDecayDepth(2.),
      m_causticWavelength(0.3), m_causticPeriod(1.5), m_noiseA(1. / 4000.), m_noiseB(1. / (255. * 255.)),
      m_exposure(1.), m_autoExposure(true), m_autoExposureMean(0.45),
      m_backgroundRange(std::numeric_limits<double>::infinity())
{
  // Clear water, 10 m visibility (the paper's test tank, where the target was seen from 8 m): red is
  // absorbed most and blue least, as in clear oceanic water (Jerlov type I-II); blue veiling light.
  m_betaD = {0.65, 0.39, 0.33};
  m_betaB = {0.55, ln50Over(10.), 0.35};
  m_veiling = {0.04, 0.22, 0.35};
  m_diffuseAttenuation = {0.40, 0.08, 0.05};
  // Forward-scatter blur grows with the scattering optical depth; the presets keep it proportional to
  // beta (0.25 mrad per unit of optical depth): 0.15 px at 5 m with a 600 px focal length here, 1.5 px
  // at 5 m in turbid water. Illustrative values, not fitted to measured point-spread functions.
  m_forwardScatter = 0.1e-3;
}

vpSSLWaterModel vpSSLWaterModel::preset(const std::string &name)
{
  vpSSLWaterModel m;
  if (name == "clear") {
    return m;
  }
  if (name == "coastal") {
    // 4 m visibility, the Secchi reading at Peel Island (Moreton Bay) during the paper's field trials, in
    // about 3 m of water: green is the clearest window, dissolved organic matter absorbs blue.
    m.m_betaD = {1.25, 0.98, 1.05};
    m.m_betaB = {1.10, ln50Over(4.), 1.02};
    m.m_veiling = {0.06, 0.30, 0.25};
    m.m_diffuseAttenuation = {0.60, 0.25, 0.35};
    m.m_forwardScatter = 0.25e-3;
  } else if (name == "turbid") {
    // 2 m visibility: harbour or river-mouth water after rain, green-brown veiling light.
    m.m_betaD = {2.30, 1.96, 2.30};
    m.m_betaB = {2.10, ln50Over(2.), 2.20};
    m.m_veiling = {0.12, 0.35, 0.25};
    m.m_diffuseAttenuation = {0.90, 0.60, 0.90};
    m.m_forwardScatter = 0.5e-3;
  } else {
    std::ostringstream os;
    os << "vpSSLWaterModel: unknown water preset \"" << name << "\"; use one of:";
    for (const std::string &n : getPresetNames()) {
      os << " " << n;
    }
    throw vpException(vpException::badValue, os.str());
  }
  m.m_name = name;
  return m;
}

std::vector<std::string> vpSSLWaterModel::getPresetNames()
{
  return {"clear", "coastal", "turbid"};
}

void vpSSLWaterModel::setAttenuation(const std::array<double, 3> &betaD)
{
  checkNonNegative(betaD, "direct-signal attenuation beta_D");
  m_betaD = betaD;
  m_name = "custom";
}

void vpSSLWaterModel::setBackscatter(const std::array<double, 3> &betaB, const std::array<double, 3> &veilingLight)
{
  checkNonNegative(betaB, "backscatter coefficient beta_B");
  checkNonNegative(veilingLight, "veiling light B_inf");
  m_betaB = betaB;
  m_veiling = veilingLight;
  m_name = "custom";
}

void vpSSLWaterModel::setForwardScatter(double radPerMetre)
{
  checkNonNegative(radPerMetre, "forward scatter");
  m_forwardScatter = radPerMetre;
  m_name = "custom";
}

void vpSSLWaterModel::setSunLight(double depth, const std::array<double, 3> &diffuseAttenuation,
                                  double surfaceIrradiance)
{
  checkNonNegative(depth, "depth");
  checkNonNegative(diffuseAttenuation, "diffuse attenuation K");
  checkNonNegative(surfaceIrradiance, "surface irradiance");
  m_light = LIGHT_SUN;
  m_depth = depth;
  m_diffuseAttenuation = diffuseAttenuation;
  m_surfaceIrradiance = surfaceIrradiance;
  m_name = "custom";
}

void vpSSLWaterModel::setArtificialLight(double power)
{
  checkNonNegative(power, "lamp power");
  m_light = LIGHT_ARTIFICIAL;
  m_lampPower = power;
  m_name = "custom";
}

void vpSSLWaterModel::setCaustics(double amplitude, double decayDepth, double wavelength, double period)
{
  checkNonNegative(amplitude, "caustic amplitude");
  if (!(decayDepth > 0. && wavelength > 0. && period > 0.)) {
    throw vpException(vpException::badValue,
                      "vpSSLWaterModel: caustic decay depth %g, wavelength %g and period %g must be > 0", decayDepth,
                      wavelength, period);
  }
  m_causticAmplitude = amplitude;
  m_causticDecayDepth = decayDepth;
  m_causticWavelength = wavelength;
  m_causticPeriod = period;
  m_name = "custom";
}

void vpSSLWaterModel::setSensorNoise(double a, double b)
{
  checkNonNegative(a, "noise coefficient a");
  checkNonNegative(b, "noise coefficient b");
  m_noiseA = a;
  m_noiseB = b;
  m_name = "custom";
}

void vpSSLWaterModel::setExposure(double exposure)
{
  if (!(exposure > 0. && std::isfinite(exposure))) {
    throw vpException(vpException::badValue, "vpSSLWaterModel: exposure %g must be > 0", exposure);
  }
  m_exposure = exposure;
  m_autoExposure = false;
}

void vpSSLWaterModel::setAutoExposure(bool enable, double targetMean)
{
  if (!(targetMean > 0. && targetMean < 1.)) {
    throw vpException(vpException::badValue, "vpSSLWaterModel: auto-exposure mean %g not in (0, 1)", targetMean);
  }
  m_autoExposure = enable;
  m_autoExposureMean = targetMean;
}

void vpSSLWaterModel::setBackgroundRange(double range)
{
  if (!(range > 0.)) {
    throw vpException(vpException::badValue, "vpSSLWaterModel: background range %g m must be > 0", range);
  }
  m_backgroundRange = range;
}

double vpSSLWaterModel::getVisibility() const
{
  return m_betaB[1] > 0. ? kLn50 / m_betaB[1] : std::numeric_limits<double>::infinity();
}

void vpSSLWaterModel::radiance(const vpImage<float> &reflectance, const vpImage<float> &range,
                               const vpCameraParameters &cam, double t, std::vector<float> &rgb) const
{
  const unsigned int w = reflectance.getWidth(), h = reflectance.getHeight();
  const size_t n = static_cast<size_t>(w) * h;
  const double focal = 0.5 * (cam.get_px() + cam.get_py());
  std::array<double, 3> ambient; // light on the target before the path back to the camera
  for (int c = 0; c < 3; ++c) {
    ambient[c] =
        m_light == LIGHT_SUN ? m_surfaceIrradiance * std::exp(-m_diffuseAttenuation[c] * m_depth) : m_lampPower;
  }
  const double causticAmplitude =
      m_light == LIGHT_SUN ? m_causticAmplitude * std::exp(-m_depth / m_causticDecayDepth) : 0.;
  const double k = 2. * M_PI / m_causticWavelength, omega = 2. * M_PI / m_causticPeriod;

  // Backscatter goes straight into rgb (planar: channel, pixel); the direct signal is kept apart with,
  // per pixel, its forward-scatter blur as a position on the blur stack (level and weight of level + 1).
  Workspace &ws = workspace();
  std::vector<float> &direct = ws.direct, &wHigh = ws.wHigh;
  std::vector<unsigned char> &level = ws.level;
  direct.resize(3 * n);
  wHigh.resize(n);
  level.resize(n);
  bool used[kNbBlurLevels] = {};
  rgb.resize(3 * n);
  for (unsigned int v = 0; v < h; ++v) {
    for (unsigned int u = 0; u < w; ++u) {
      const size_t p = static_cast<size_t>(v) * w + u;
      double z = range.bitmap[p];
      if (!std::isfinite(z)) {
        z = m_backgroundRange;
      }
      if (!std::isfinite(z)) {
        // Pure veiling light: no direct signal, at blur level 0 with no weight above it.
        level[p] = 0;
        wHigh[p] = 0.f;
        for (int c = 0; c < 3; ++c) {
          direct[c * n + p] = 0.f;
          rgb[c * n + p] = static_cast<float>(m_veiling[c] * ambient[c]);
        }
        continue;
      }
      // Forward scatter: an angular spread growing with range.
      const double sigma = std::min(m_forwardScatter * z * focal, kBlurLevels[kNbBlurLevels - 1]);
      size_t l = 0;
      while (l + 2 < kNbBlurLevels && sigma > kBlurLevels[l + 1]) {
        ++l;
      }
      level[p] = static_cast<unsigned char>(l);
      wHigh[p] = static_cast<float>(std::min(1., (sigma - kBlurLevels[l]) / (kBlurLevels[l + 1] - kBlurLevels[l])));
      used[l] = true;
      used[l + 1] = used[l + 1] || wHigh[p] > 0.f;
      double caustic = 1.;
      if (causticAmplitude > 0.) {
        // Fronto-parallel approximation of the point on the target: pixel offset x range / focal.
        const double X = (u - cam.get_u0()) * z / cam.get_px(), Y = (v - cam.get_v0()) * z / cam.get_py();
        const double s = (std::sin(k * X + omega * t) + std::sin(k * (-0.5 * X + 0.866 * Y) + 1.13 * omega * t + 1.3) +
                          std::sin(k * (-0.5 * X - 0.866 * Y) - 0.87 * omega * t + 2.1)) /
                         3.;
        caustic = std::max(0., 1. + causticAmplitude * s);
      }
      for (int c = 0; c < 3; ++c) {
        double light = ambient[c] * caustic;
        if (m_light == LIGHT_ARTIFICIAL) {
          // The lamp's light reaches the target through the same water as the direct signal comes back.
          const double zl = std::max(z, kLampMinRange);
          light = m_lampPower * std::exp(-m_betaD[c] * z) / (zl * zl);
        }
        // Akkaynak and Treibitz 2018, Eq. 2: direct signal and backscatter with their own coefficients.
        direct[c * n + p] = static_cast<float>(reflectance.bitmap[p] * light * std::exp(-m_betaD[c] * z));
        rgb[c * n + p] = static_cast<float>(m_veiling[c] * ambient[c] * (1. - std::exp(-m_betaB[c] * z)));
      }
    }
  }
  // Each pixel's direct signal is spread with the blur of its own range (scattering happens along its
  // own path), by linear interpolation between the two nearest levels of the stack.
  // A pixel's weight at a level is the same for the three channels: computed once per level.
  std::vector<float> &plane = ws.plane, &scratch = ws.scratch, &weight = ws.weight;
  plane.resize(n);
  weight.resize(n);
  for (size_t l = 0; l < kNbBlurLevels; ++l) {
    if (!used[l]) {
      continue;
    }
    for (size_t p = 0; p < n; ++p) {
      weight[p] = level[p] == l ? 1.f - wHigh[p] : (level[p] + 1u == l ? wHigh[p] : 0.f);
    }
    for (int c = 0; c < 3; ++c) {
      const float *dc = &direct[c * n];
      for (size_t p = 0; p < n; ++p) {
        plane[p] = weight[p] * dc[p];
      }
      vpSSLBlur::addBlurred(plane, w, h, kBlurLevels[l], scratch, &rgb[c * n]);
    }
  }
}

void vpSSLWaterModel::apply(const vpImage<float> &reflectance, const vpImage<float> &range,
                            const vpCameraParameters &cam, double t, long seed, vpImage<vpRGBa> &I) const
{
  if (reflectance.getSize() == 0 || reflectance.getWidth() != range.getWidth() ||
      reflectance.getHeight() != range.getHeight()) {
    throw vpException(vpException::dimensionError,
                      "vpSSLWaterModel: reflectance (%ux%u) and range (%ux%u) images must be non-empty and the same "
                      "size",
                      reflectance.getWidth(), reflectance.getHeight(), range.getWidth(), range.getHeight());
  }
  std::vector<float> &rgb = workspace().rgb;
  radiance(reflectance, range, cam, t, rgb);
  const size_t n = reflectance.getSize();
  double gain = m_exposure;
  if (m_autoExposure) {
    double mean = 0.;
    for (size_t p = 0; p < n; ++p) {
      mean += kLuma[0] * rgb[p] + kLuma[1] * rgb[n + p] + kLuma[2] * rgb[2 * n + p];
    }
    mean /= n;
    // Bounded like a real camera's exposure range: a black frame is not amplified without limit.
    gain = mean > 0. ? std::min(std::max(m_autoExposureMean / mean, 1. / 64.), 64.) : 64.;
  }
  I.resize(reflectance.getHeight(), reflectance.getWidth());
  // vpGaussRand(1, 0, seed)'s draws, inline (vpSSLGaussRand.h).
  vpSSLGaussRand noise(1., 0., seed);
  // A block's deviates are drawn first (pixel after pixel, R, G, B: the order of the draws is the image's), then
  // used by the vectorised pixel arithmetic (vpSSLNoiseKernel), which writes vpRGBa's R, G, B, A bytes.
  const size_t kBlock = 1024;
  double deviates[3 * kBlock];
  unsigned char *rgba = reinterpret_cast<unsigned char *>(I.bitmap);
  for (size_t p0 = 0; p0 < n; p0 += kBlock) {
    const size_t nb = std::min(kBlock, n - p0);
    noise.draw(deviates, 3 * nb);
    vpSSLNoiseKernel::exposeQuantise(&rgb[p0], &rgb[n + p0], &rgb[2 * n + p0], deviates, nb, gain, m_noiseA, m_noiseB,
                                     rgba + 4 * p0);
  }
}

void vpSSLWaterModel::apply(const vpImage<float> &reflectance, const vpImage<float> &range,
                            const vpCameraParameters &cam, double t, long seed, vpImage<unsigned char> &I) const
{
  vpImage<vpRGBa> &colour = workspace().colour;
  apply(reflectance, range, cam, t, seed, colour);
  vpImageConvert::convert(colour, I);
}

std::string vpSSLWaterModel::toJson() const
{
  std::ostringstream os;
  os << std::setprecision(6) << "{\"name\": \"" << m_name << "\", \"visibility_m\": " << getVisibility()
     << ", \"beta_d\": " << jsonArray(m_betaD) << ", \"beta_b\": " << jsonArray(m_betaB)
     << ", \"veiling_light\": " << jsonArray(m_veiling) << ", \"forward_scatter_rad_per_m\": " << m_forwardScatter
     << ", \"light\": \"" << (m_light == LIGHT_SUN ? "sun" : "artificial") << "\", \"depth_m\": " << m_depth
     << ", \"diffuse_attenuation\": " << jsonArray(m_diffuseAttenuation)
     << ", \"surface_irradiance\": " << m_surfaceIrradiance << ", \"lamp_power\": " << m_lampPower
     << ", \"caustics\": {\"amplitude\": " << m_causticAmplitude << ", \"decay_depth_m\": " << m_causticDecayDepth
     << ", \"wavelength_m\": " << m_causticWavelength << ", \"period_s\": " << m_causticPeriod << "}"
     << ", \"noise_a\": " << m_noiseA << ", \"noise_b\": " << m_noiseB << ", \"exposure\": " << m_exposure
     << ", \"auto_exposure\": " << (m_autoExposure ? "true" : "false")
     << ", \"auto_exposure_mean\": " << m_autoExposureMean << ", \"background_range_m\": ";
  if (std::isfinite(m_backgroundRange)) {
    os << m_backgroundRange;
  } else {
    os << "null";
  }
  os << "}";
  return os.str();
}

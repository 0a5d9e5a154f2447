/*!
  \file vpSSLBackground.cpp
  \brief Backdrops of the simulator: procedural seabed and real photographs.
*/
#include <visp3/ssl_sim/vpSSLBackground.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include <visp3/core/vpException.h>
#include <visp3/core/vpIoTools.h>
#include <visp3/core/vpUniRand.h>
#include <visp3/ssl_io/vpSSLImageIo.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>
#include <visp3/ssl_sim/vpSSLScenario.h>

namespace {
const char *kDebianImages = "/usr/share/visp-images-data/ViSP-images";
// Wall 2 m behind the target, the photograph 6 m wide: at the ranges of the scenarios it fills the view
// behind the sheet with detail of a few pixels to tens of pixels, like a cluttered dock or reef.
const double kWallDistance = 2.;
const double kWallWidth = 6.;
// Seabed texture: 1 cm per texel over 10.24 m, mirrored beyond.
const double kSeabedTexel = 0.01;
const unsigned int kSeabedSize = 1024;

// Periodic value noise: a g x g lattice of uniform values, smoothly interpolated; \e size is a multiple of g.
std::vector<float> valueNoise(unsigned int size, unsigned int g, vpUniRand &rng)
{
  std::vector<float> lattice(static_cast<size_t>(g) * g);
  for (float &v : lattice) {
    v = static_cast<float>(rng.uniform(0., 1.));
  }
  std::vector<float> out(static_cast<size_t>(size) * size);
  const double step = static_cast<double>(g) / size;
  for (unsigned int y = 0; y < size; ++y) {
    const double fy = y * step;
    const unsigned int y0 = static_cast<unsigned int>(fy) % g, y1 = (y0 + 1) % g;
    double ay = fy - std::floor(fy);
    ay = ay * ay * (3. - 2. * ay);
    for (unsigned int x = 0; x < size; ++x) {
      const double fx = x * step;
      const unsigned int x0 = static_cast<unsigned int>(fx) % g, x1 = (x0 + 1) % g;
      double ax = fx - std::floor(fx);
      ax = ax * ax * (3. - 2. * ax);
      const double top = (1. - ax) * lattice[y0 * g + x0] + ax * lattice[y0 * g + x1];
      const double bottom = (1. - ax) * lattice[y1 * g + x0] + ax * lattice[y1 * g + x1];
      out[static_cast<size_t>(y) * size + x] = static_cast<float>((1. - ay) * top + ay * bottom);
    }
  }
  return out;
}

// Paints a disc of \e radius texels at (cx, cy) with reflectance \e value, soft-edged over one texel, shaded
// by \e shade (0: flat; > 0: lit from one side, as a rounded stone).
void stone(std::vector<float> &r, unsigned int size, double cx, double cy, double radius, double value, double shade)
{
  const int x0 = std::max(0, static_cast<int>(cx - radius - 1)), x1 = std::min<int>(size - 1, cx + radius + 1);
  const int y0 = std::max(0, static_cast<int>(cy - radius - 1)), y1 = std::min<int>(size - 1, cy + radius + 1);
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const double dx = x - cx, dy = y - cy, d = std::hypot(dx, dy);
      const double w = std::min(1., std::max(0., radius - d + 0.5));
      if (w > 0.) {
        const double lit = value * (1. + shade * (-dx - dy) / (1.41 * radius));
        float &p = r[static_cast<size_t>(y) * size + x];
        p = static_cast<float>((1. - w) * p + w * lit);
      }
    }
  }
}

std::string photoPath(const std::string &name)
{
  std::string root = vpIoTools::getViSPImagesDataPath();
  if (root.empty()) {
    root = kDebianImages;
  }
  if (name == "klimt") {
    return root + "/Klimt/Klimt.pgm";
  }
  return root + "/Solvay/Solvay_conference_1927_Version2_1024x705.png";
}
} // namespace

vpSSLBackground::vpSSLBackground() : m_name("water"), m_type(BACKGROUND_WATER), m_texture(), m_texelSize(1.) {}

std::vector<std::string> vpSSLBackground::getNames()
{
  return {"water", "seabed", "klimt", "solvay"};
}

vpSSLBackground vpSSLBackground::fromName(const std::string &nameOrImage, long seed)
{
  vpSSLBackground b;
  b.m_name = nameOrImage;
  if (nameOrImage == "water") {
    return b;
  }
  if (nameOrImage == "seabed") {
    b.m_type = BACKGROUND_SEABED;
    b.m_texture = seabedTexture(kSeabedSize, seed);
    b.m_texelSize = kSeabedTexel;
    return b;
  }
  const bool builtIn = nameOrImage == "klimt" || nameOrImage == "solvay";
  const std::string path = builtIn ? photoPath(nameOrImage) : nameOrImage;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    std::string msg = "vpSSLBackground: ";
    if (builtIn) {
      msg +=
          "\"" + nameOrImage + "\" needs " + path + " (install Debian's visp-images-data or set VISP_INPUT_IMAGE_PATH)";
    } else {
      msg += "\"" + nameOrImage + "\" is neither water, seabed, klimt, solvay nor an image file";
    }
    throw vpException(vpException::ioError, msg);
  }
  // vpSSLImageIo checks the header's size before decoding (ViSP's PNG reader trusts it and leaks on a corrupt
  // file): a user's --background image is as hostile as any input.
  try {
    vpSSLImageIo::read(b.m_texture, path);
  } catch (const vpException &e) {
    throw vpException(vpException::ioError, "vpSSLBackground: cannot read image %s: %s", path.c_str(), e.what());
  }
  if (b.m_texture.getSize() == 0) {
    throw vpException(vpException::ioError, "vpSSLBackground: image %s is empty", path.c_str());
  }
  b.m_type = BACKGROUND_WALL;
  b.m_texelSize = kWallWidth / b.m_texture.getWidth();
  return b;
}

vpImage<unsigned char> vpSSLBackground::seabedTexture(unsigned int size, long seed)
{
  if (size < 16) {
    throw vpException(vpException::badValue, "vpSSLBackground: seabed texture size %u must be >= 16", size);
  }
  vpUniRand rng(seed);
  // Large-scale patches (sand against darker detritus), then finer grain: fractal value noise.
  std::vector<float> r(static_cast<size_t>(size) * size, 0.f);
  double amplitude = 0.5, total = 0.;
  for (unsigned int g = 4; g <= size / 4 && g <= 256; g *= 2, amplitude *= 0.6) {
    const std::vector<float> octave = valueNoise(size, g, rng);
    for (size_t p = 0; p < r.size(); ++p) {
      r[p] += static_cast<float>(amplitude * octave[p]);
    }
    total += amplitude;
  }
  // Sand ripples about 8 cm apart, their crests bent by the patches; the light falls along the ripples.
  const double angle = rng.uniform(0., M_PI), wavelength = 8.;
  const double ca = std::cos(angle), sa = std::sin(angle);
  const std::vector<float> warp = valueNoise(size, std::min(8u, size / 2), rng);
  for (unsigned int y = 0; y < size; ++y) {
    for (unsigned int x = 0; x < size; ++x) {
      const size_t p = static_cast<size_t>(y) * size + x;
      const double patch = r[p] / total; // about [0, 1], mean 0.5
      const double ripple = std::sin(2. * M_PI * (ca * x + sa * y) / wavelength + 12. * warp[p]);
      r[p] = static_cast<float>(0.30 + 0.22 * (patch - 0.5) + 0.05 * ripple);
    }
  }
  // Pebbles and shells (1 to 3 cm), then a few rocks (15 to 45 cm): density per square metre of texture.
  const double area = (size * kSeabedTexel) * (size * kSeabedTexel);
  const unsigned int nbPebbles = static_cast<unsigned int>(30. * area), nbRocks = static_cast<unsigned int>(0.3 * area);
  for (unsigned int i = 0; i < nbPebbles; ++i) {
    const double cx = rng.uniform(0., size), cy = rng.uniform(0., size), radius = rng.uniform(1., 3.);
    stone(r, size, cx, cy, radius, rng.uniform(0.08, 0.6), 0.3);
  }
  for (unsigned int i = 0; i < nbRocks; ++i) {
    const double cx = rng.uniform(0., size), cy = rng.uniform(0., size), radius = rng.uniform(15., 45.);
    stone(r, size, cx, cy, radius, rng.uniform(0.08, 0.2), 0.5);
  }
  vpImage<unsigned char> I(size, size);
  for (size_t p = 0; p < r.size(); ++p) {
    I.bitmap[p] = static_cast<unsigned char>(std::lround(255. * std::min(1.f, std::max(0.f, r[p]))));
  }
  return I;
}

void vpSSLBackground::apply(vpSSLRenderer &renderer) const
{
  if (m_type == BACKGROUND_WATER) {
    renderer.setBackdrop(vpImage<unsigned char>(), 1.);
  } else {
    renderer.setBackdrop(m_texture, m_texelSize);
  }
}

vpHomogeneousMatrix vpSSLBackground::getWorldPose(const vpSSLScenario &scenario) const
{
  if (m_type == BACKGROUND_SEABED) {
    // The floor plane, texture columns north and rows east, Z down into the ground.
    return vpHomogeneousMatrix(0., 0., scenario.getSeabedDepth(), 0., 0., 0.);
  }
  // A wall parallel to the target at home, behind it; the photograph upright (its rows go down).
  return scenario.getTargetHome() * vpHomogeneousMatrix(0., 0., kWallDistance, 0., 0., 0.);
}

// libFuzzer target: the detector on arbitrary image bytes and sizes. The first byte picks the mode:
// - even: the rest is an image file (PNG, JPEG, PNM, BMP or anything), read by vpSSLImageIo (headers that
//   declare huge sizes, truncated and corrupt data), then detected;
// - odd: the next four bytes give a width and a height (1 to 512 each: 1x1, 1xN, Nx1 included) and the rest the
//   pixels, repeated to fill the image, with the detector's settings (small-landmark mode, window, decimation,
//   normalisation) from the following bytes.
// Every path ends in landmarks within the image or a vpException.
#include <cmath>

#include <visp3/core/vpException.h>
#include <visp3/core/vpImage.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl/vpSSLInputLimits.h>
#include <visp3/ssl_io/vpSSLImageIo.h>

#include "fuzz_common.h"

namespace {
void detect(vpSSLDetector &detector, const vpImage<unsigned char> &I)
{
  // vpSSLDetector::detect() checks its image with vpSSLInputLimits::checkImage() (a wrapped vpImage size is refused
  // there).
  vpSSLInputLimits::checkImage(I, "fuzz");
  detector.detect(I);
  for (const vpSSLLandmark &l : detector.getLandmarks()) {
    if (!std::isfinite(l.u) || !std::isfinite(l.v) || !std::isfinite(l.radius) || l.u < -1. || l.v < -1. ||
        l.u > I.getWidth() || l.v > I.getHeight()) {
      std::abort();
    }
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  static vpSSLDetector detector;
  sslfuzz::Input in(data, size);
  const uint8_t mode = in.byte();
  vpImage<unsigned char> I;
  try {
    if ((mode & 1) == 0) {
      const std::filesystem::path path = sslfuzz::scratch() / "image";
      sslfuzz::writeFile(path, in.rest(), in.left());
      vpSSLImageIo::read(I, path.string());
      detector.setSmallLandmarkMode(false);
      detector.setWindow(40);
      detector.setShortWindow(10);
      detect(detector, I);
      return 0;
    }
    const unsigned int w = 1 + in.u16() % 512, h = 1 + in.u16() % 512;
    const uint8_t settings = in.byte();
    detector.setSmallLandmarkMode(settings & 1);
    detector.setBrightnessNormalization(settings & 2);
    detector.setDecimation(settings & 4 ? 2 : 1);
    detector.setWindow(2 + in.byte() % 127);
    detector.setShortWindow(settings & 8 ? 0u : 2u + 8u * (settings >> 4)); // 0, or 2 to 122
    I.resize(h, w, 0);
    if (in.left() > 0) {
      const size_t n = in.left();
      for (size_t i = 0; i < I.getSize(); ++i) {
        I.bitmap[i] = in.rest()[i % n];
      }
    }
    detect(detector, I);
  } catch (const vpException &) {
  }
  return 0;
}

// libFuzzer target: the detector on arbitrary image bytes and sizes. The first byte picks the mode (and, by its
// second and third bits, turns the equal-ring check and the blurred-ring model off: with both bits clear the
// detector keeps its defaults):
// - even: the rest is an image file (PNG, JPEG, PNM, BMP or anything), read by vpSSLImageIo (headers that
//   declare huge sizes, truncated and corrupt data), then detected, on one thread, in its top-left 320x240 px at
//   most (the committed photograph of ssl3-a3 whole);
// - odd: the next four bytes give a width and a height (1 to kMaxSide each: 1x1, 1xN, Nx1 included) and the rest
//   the pixels, repeated to fill the image, with the detector's settings (small-landmark mode, window, decimation,
//   normalisation, one or two threads) from the following bytes.
// Every path ends in landmarks within the image or a vpException.
//
// kMaxSide is 128, the longest window: windows longer than the image, several of the 16 px tiles of a full search
// and row lengths from 1 px to several SIMD vectors are all reached, while the matching's cost, proportional to the
// area, is about a fifteenth of that of images up to 512 px. Larger images run the same code over more tiles; the
// sanitizer build of the tests runs it on them.
#include <algorithm>
#include <cmath>

#include <visp3/core/vpException.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpImageTools.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl/vpSSLInputLimits.h>
#include <visp3/ssl_io/vpSSLImageIo.h>

#include "fuzz_common.h"

namespace {
const unsigned int kMaxSide = 128;
const unsigned int kMaxFileWidth = 320, kMaxFileHeight = 240;

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
    detector.setEqualRingCheck(!(mode & 2));
    detector.setBlurredRingModel(!(mode & 4));
    if ((mode & 1) == 0) {
      const std::filesystem::path path = sslfuzz::scratch() / "image";
      sslfuzz::writeFile(path, in.rest(), in.left());
      vpSSLImageIo::read(I, path.string());
      detector.setSmallLandmarkMode(false);
      detector.setWindow(40);
      detector.setShortWindow(10);
      detector.setNbThreads(1);
      if (I.getWidth() > kMaxFileWidth || I.getHeight() > kMaxFileHeight) {
        vpImage<unsigned char> crop;
        vpImageTools::crop(I, 0u, 0u, std::min(I.getHeight(), kMaxFileHeight), std::min(I.getWidth(), kMaxFileWidth),
                           crop);
        I = crop;
      }
      detect(detector, I);
      return 0;
    }
    const unsigned int w = 1 + in.u16() % kMaxSide, h = 1 + in.u16() % kMaxSide;
    const uint8_t settings = in.byte();
    detector.setSmallLandmarkMode(settings & 1);
    detector.setBrightnessNormalization(settings & 2);
    detector.setDecimation(settings & 4 ? 2 : 1);
    const uint8_t window = in.byte();
    detector.setWindow(2 + (window & 127) % 127);
    detector.setNbThreads(1 + (window >> 7));
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

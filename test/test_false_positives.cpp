// Nothing but a self-similar landmark is taken for one (paper Sec. 5.3, Fig. 12: a striped fish is not
// segmented out): real photographs from Debian's visp-images-data and synthetic clutter give no landmark
// above the default threshold, hence no target.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include <visp3/core/vpIoTools.h>
#include <visp3/core/vpUniRand.h>
#include <visp3/io/vpImageIo.h>
#include <visp3/ssl/vpSSLDetector.h>

namespace {
void expectNothing(vpSSLDetector &detector, const vpImage<unsigned char> &I, const std::string &what)
{
  detector.detect(I);
  EXPECT_EQ(detector.getLandmarks().size(), 0u) << what;
  EXPECT_FALSE(detector.getTargetMatch().found) << what;
}
} // namespace

TEST(FalsePositives, RealPhotographsOfVispImagesData)
{
  const std::string root = VISP_SSL_IMAGES_DIR;
  const char *images[] = {"Klimt/Klimt.pgm",
                          "Solvay/Solvay_conference_1927_Version2_640x440.png",
                          "faces/1280px-Solvay_conference_1927.png",
                          "mire/mire.pgm",
                          "calibration/grid36-01.pgm",
                          "calibration/grid36-02.pgm",
                          "calibration/grid36-03.pgm",
                          "calibration/grid36-04.pgm",
                          "AprilTag/AprilTag.pgm",
                          "AprilTag/benchmark/640x480/tag36_11_640x480.png",
                          "AprilTag/benchmark/640x480/tag25_09_640x480.png",
                          "cube/image.0000.pgm",
                          "cube/image.0020.pgm",
                          "cube/image.0040.pgm",
                          "cube/image.0060.pgm",
                          "mire-2/image.0001.pgm",
                          "mire-2/image.0250.pgm"};
  vpSSLDetector detector;
  vpSSLDetector small;
  small.setSmallLandmarkMode(true);
  int read = 0;
  for (const char *name : images) {
    const std::string path = root + "/" + name;
    if (!vpIoTools::checkFilename(path)) {
      ADD_FAILURE() << path << " missing: install Debian's visp-images-data";
      continue;
    }
    vpImage<unsigned char> I;
    vpImageIo::read(I, path);
    ++read;
    expectNothing(detector, I, name);
    expectNothing(small, I, std::string(name) + " (small-landmark mode)");
  }
  EXPECT_EQ(read, static_cast<int>(sizeof(images) / sizeof(images[0])));
}

TEST(FalsePositives, RandomBlackAndWhiteTexture)
{
  vpSSLDetector detector;
  vpUniRand rng(3);
  for (int block : {2, 5, 11, 23}) {
    vpImage<unsigned char> I(480, 640);
    for (unsigned int v = 0; v < I.getHeight(); v += block) {
      for (unsigned int u = 0; u < I.getWidth(); u += block) {
        const unsigned char value = rng.uniform(0., 1.) < 0.5 ? 0 : 255;
        for (unsigned int y = v; y < std::min(I.getHeight(), v + block); ++y) {
          for (unsigned int x = u; x < std::min(I.getWidth(), u + block); ++x) {
            I[y][x] = value;
          }
        }
      }
    }
    expectNothing(detector, I, "random blocks of " + std::to_string(block) + " px");
  }
}

TEST(FalsePositives, Chessboards)
{
  vpSSLDetector detector;
  for (double square : {8., 20., 45.}) {
    for (double angle : {0., 17., 45.}) {
      vpImage<unsigned char> I(480, 640);
      const double c = std::cos(angle * M_PI / 180.), s = std::sin(angle * M_PI / 180.);
      for (unsigned int v = 0; v < I.getHeight(); ++v) {
        for (unsigned int u = 0; u < I.getWidth(); ++u) {
          const double x = c * u + s * v, y = -s * u + c * v;
          const long i = static_cast<long>(std::floor(x / square)) + static_cast<long>(std::floor(y / square));
          I[v][u] = (i % 2 == 0) ? 20 : 235;
        }
      }
      expectNothing(detector, I, "chessboard " + std::to_string(square) + " px at " + std::to_string(angle) + " deg");
    }
  }
}

TEST(FalsePositives, StripedFish)
{
  // Fig. 12, last column: a black and white striped fish in blue water. Stripes of equal width (and of
  // widths growing along the body) inside an elongated body, at several sizes.
  vpSSLDetector detector;
  for (double length : {120., 260., 420.}) {
    for (bool growing : {false, true}) {
      vpImage<unsigned char> I(480, 640, 110);
      const double cx = 320., cy = 240., a = 0.5 * length, b = 0.22 * length;
      for (unsigned int v = 0; v < I.getHeight(); ++v) {
        for (unsigned int u = 0; u < I.getWidth(); ++u) {
          const double x = (u - cx) / a, y = (v - cy) / b;
          if (x * x + y * y > 1.) {
            continue;
          }
          // Stripe phase along the body: uniform, or growing geometrically towards the tail.
          const double t = 0.5 * (x + 1.);
          const double phase = growing ? std::log(1. + 6. * t) / std::log(1.5) : 9. * t;
          I[v][u] = (static_cast<int>(std::floor(phase)) % 2 == 0) ? 15 : 240;
        }
      }
      expectNothing(detector, I, "fish " + std::to_string(length) + " px" + (growing ? " with growing stripes" : ""));
    }
  }
}

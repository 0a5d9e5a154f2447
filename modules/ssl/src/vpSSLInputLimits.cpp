/*!
  \file vpSSLInputLimits.cpp
  \brief The checks of image sizes and camera intrinsics against the plugin's input limits.
*/
#include <visp3/ssl/vpSSLInputLimits.h>

#include <cmath>
#include <sstream>

#include <visp3/core/vpException.h>

#include "vpSSLImageCheck.h"

void vpSSLInputLimits::checkImageSize(uint64_t width, uint64_t height, const std::string &what)
{
  std::ostringstream os;
  os << what << ": " << width << " x " << height << " pixels";
  if (width == 0 || height == 0) {
    os << ": empty image";
  } else if (width > maxImageSide() || height > maxImageSide()) {
    os << ": a side exceeds the limit of " << maxImageSide() << " pixels";
  } else if (width * height > maxImagePixels()) {
    os << ": " << width * height << " pixels exceed the limit of " << maxImagePixels();
  } else {
    return;
  }
  throw vpException(vpException::dimensionError, os.str());
}

void vpSSLInputLimits::checkImage(const vpImage<unsigned char> &I, const char *what)
{
  vpSSLImageCheck::input(I, what);
}

void vpSSLInputLimits::checkImage(const vpImage<vpRGBa> &I, const char *what)
{
  vpSSLImageCheck::input(I, what);
}

void vpSSLInputLimits::checkCamera(const vpCameraParameters &cam, const std::string &what)
{
  struct Value
  {
    const char *name;
    double value, low, high;
  };
  const double m = maxFocal();
  const Value values[] = {{"px", cam.get_px(), minFocal(), m},
                          {"py", cam.get_py(), minFocal(), m},
                          {"u0", cam.get_u0(), -m, m},
                          {"v0", cam.get_v0(), -m, m},
                          {"kud", cam.get_kud(), -maxDistortion(), maxDistortion()},
                          {"kdu", cam.get_kdu(), -maxDistortion(), maxDistortion()}};
  for (const Value &v : values) {
    if (!std::isfinite(v.value) || v.value < v.low || v.value > v.high) {
      std::ostringstream os;
      os << what << ": " << v.name << ": must be a finite number in [" << v.low << ", " << v.high << "], got "
         << v.value;
      throw vpException(vpException::badValue, os.str());
    }
  }
}

// libFuzzer target: the camera-file reader (vpSSLCameraFile::load over ViSP's vpXmlParserCamera). Any input
// gives intrinsics within vpSSLInputLimits::checkCamera()'s bounds and a size within vpSSLImageIo's, or a vpException.
#include <cmath>

#include <visp3/core/vpException.h>
#include <visp3/ssl/vpSSLInputLimits.h>
#include <visp3/ssl_io/vpSSLCameraFile.h>
#include <visp3/ssl_io/vpSSLImageIo.h>

#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  const std::filesystem::path path = sslfuzz::scratch() / "camera.xml";
  sslfuzz::writeFile(path, data, size);
  unsigned int w = 0, h = 0;
  vpCameraParameters cam;
  try {
    cam = vpSSLCameraFile::load(path.string(), "Camera", &w, &h);
  } catch (const vpException &) {
    return 0;
  }
  if (!std::isfinite(cam.get_px()) || !(cam.get_px() >= vpSSLInputLimits::minFocal()) || !std::isfinite(cam.get_u0())) {
    std::abort();
  }
  if ((w == 0) != (h == 0) || w > vpSSLInputLimits::maxImageSide() || h > vpSSLInputLimits::maxImageSide()) {
    std::abort();
  }
  return 0;
}

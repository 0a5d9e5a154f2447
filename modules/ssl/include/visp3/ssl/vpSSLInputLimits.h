/*!
  \file vpSSLInputLimits.h
  \brief The bounds the plugin puts on what a user gives it: image sizes, camera intrinsics, camera mount.
*/
#ifndef VP_SSL_INPUT_LIMITS_H
#define VP_SSL_INPUT_LIMITS_H

#include <cstdint>
#include <string>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>
#include <visp3/ssl/vpSSLConfig.h>

/*!
  \class vpSSLInputLimits
  \ingroup group_ssl
  \brief One copy of each input bound (doc/input-limits.md), checked by the detector and the tracker and by
  the file readers of visp_ssl_io alike.

  Images: each side at most maxImageSide() = 16384 pixels, and at most maxImagePixels() = 2^26 (67,108,864)
  pixels in all, e.g. 8192 x 8192 or 16384 x 4096. They bound the memory of one frame (the detector keeps a few
  maps of 4 bytes per pixel, twice the size in the small-landmark mode) and keep every index of the SIMD kernels
  inside 32 bits. vpImage computes width x height in 32 bits: an image of 65537 x 65536 pixels holds 65536
  bytes; checkImage() compares getSize() with the product in 64 bits, so that no code reads rows that were never
  allocated.

  Cameras: px and py in [minFocal(), maxFocal()] pixels, u0 and v0 within +-maxFocal(), kud and kdu within
  +-maxDistortion(). Camera mount (the camera pose in the vehicle frame): translation within
  +-maxMountTranslation() m and theta-u rotation within +-maxMountRotation() rad per element.

  \code
  vpSSLInputLimits::checkImage(I, "my tool");             // vpException: "my tool: 20000 x 20000 pixels: ..."
  vpSSLInputLimits::checkCamera(cam, "my camera");        // vpException: "my camera: px: must be ..."
  \endcode
*/
class VISP_SSL_EXPORT vpSSLInputLimits
{
public:
  //! Largest image side (pixels) the plugin accepts: 16384.
  static constexpr unsigned int maxImageSide() { return 16384u; }
  //! Largest number of pixels the plugin accepts: 2^26.
  static constexpr uint64_t maxImagePixels() { return uint64_t(1) << 26; }

  /*!
    Checks an image size against the limits.
    \param width, height : the size (pixels).
    \param what : names the image in the message (a file, "vpSSLDetector::detect", ...).
    \exception vpException (dimensionError) <tt>WHAT: W x H pixels: ...</tt> naming the bound exceeded, or
    an empty size.
  */
  static void checkImageSize(uint64_t width, uint64_t height, const std::string &what);

  /*!
    Checks an image: not empty, getSize() equal to width x height (computed in 64 bits: vpImage's own product
    wraps at 2^32), and within the limits. Allocates nothing unless it throws (a check per frame).
    \exception vpException (dimensionError) naming \e what, the size and the bound.
  */
  static void checkImage(const vpImage<unsigned char> &I, const char *what);
  //! As checkImage(const vpImage<unsigned char> &, const char *), in colour.
  static void checkImage(const vpImage<vpRGBa> &I, const char *what);

  //! Smallest focal length accepted (pixels): 1.
  static constexpr double minFocal() { return 1.; }
  //! Largest focal length, and largest |u0|, |v0| accepted (pixels): 1e7.
  static constexpr double maxFocal() { return 1e7; }
  //! Largest |kud|, |kdu| accepted: 100.
  static constexpr double maxDistortion() { return 100.; }

  /*!
    Checks intrinsics that come from anywhere (a file, a scaled copy, code): px and py in [minFocal(),
    maxFocal()] pixels, u0 and v0 finite within +-maxFocal(), kud and kdu within +-maxDistortion().
    \param cam : the camera.
    \param what : names it in the message.
    \exception vpException (badValue) <tt>WHAT: FIELD: must be a finite number in [LOW, HIGH], got V</tt>.
  */
  static void checkCamera(const vpCameraParameters &cam, const std::string &what);

  //! Largest |tx|, |ty|, |tz| of the camera mount (m): 100.
  static constexpr double maxMountTranslation() { return 100.; }
  //! Largest |tux|, |tuy|, |tuz| of the camera mount (rad): 2 pi.
  static constexpr double maxMountRotation() { return 6.283185307179586; }
};

#endif

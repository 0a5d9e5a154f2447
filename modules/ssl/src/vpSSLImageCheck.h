/*
  Private image-size checks behind vpSSLInputLimits::checkImage() and the public entry points that read pixels
  (the brightness normaliser, the matching function, the peak detector, the radius estimator, the tracker).

  input(): an image a user gives, against the documented limits (vpSSLInputLimits::maxImageSide(),
  maxImagePixels()). kernel(): an image a SIMD kernel reads, which may be the twice upsampled input of the
  small-landmark mode: sides up to 2 maxImageSide() = 32768 and 4 maxImagePixels() = 2^28 pixels. Every kernel
  states the sizes it supports in terms of that bound (int indices, 32-bit strides, int16 sums); both checks
  first compare getSize() with width x height in 64 bits, since vpImage's own product wraps at 2^32.
*/
#ifndef VP_SSL_IMAGE_CHECK_H
#define VP_SSL_IMAGE_CHECK_H

#include <cstdint>
#include <sstream>
#include <string>

#include <visp3/core/vpException.h>
#include <visp3/core/vpImage.h>
#include <visp3/ssl/vpSSLInputLimits.h>

namespace vpSSLImageCheck {
//! Largest side of an image a kernel reads: the twice upsampled largest input.
constexpr uint64_t kKernelMaxSide = 2 * uint64_t(vpSSLInputLimits::maxImageSide());
//! Largest number of pixels of an image a kernel reads.
constexpr uint64_t kKernelMaxPixels = 4 * vpSSLInputLimits::maxImagePixels();

//! Throws unless I holds exactly width x height pixels (64-bit product); empty images pass.
template <typename Type> void consistent(const vpImage<Type> &I, const char *what)
{
  const uint64_t w = I.getWidth(), h = I.getHeight();
  if (uint64_t(I.getSize()) != w * h || (w * h > 0 && I.bitmap == nullptr)) {
    std::ostringstream os;
    os << what << ": " << w << " x " << h << " pixels = " << w * h << ", but the image holds " << I.getSize()
       << " (vpImage's 32-bit size wrapped): a side exceeds the limit of " << vpSSLInputLimits::maxImageSide()
       << " pixels";
    throw vpException(vpException::dimensionError, os.str());
  }
}

//! An image given by a user: consistent, not empty, within the documented limits. \e what is a C string so that
//! a check per frame allocates nothing (the detector and the tracker allocate nothing in steady state).
template <typename Type> void input(const vpImage<Type> &I, const char *what)
{
  consistent(I, what);
  const uint64_t w = I.getWidth(), h = I.getHeight();
  if (w == 0 || h == 0 || w > vpSSLInputLimits::maxImageSide() || h > vpSSLInputLimits::maxImageSide() ||
      w * h > vpSSLInputLimits::maxImagePixels()) {
    vpSSLInputLimits::checkImageSize(w, h, what);
  }
}

//! An image a kernel reads (the input, or the input upsampled twice); empty images pass (nothing is read).
template <typename Type> void kernel(const vpImage<Type> &I, const char *what)
{
  consistent(I, what);
  const uint64_t w = I.getWidth(), h = I.getHeight();
  if (w > kKernelMaxSide || h > kKernelMaxSide || w * h > kKernelMaxPixels) {
    std::ostringstream os;
    os << what << ": " << w << " x " << h << " pixels exceed the kernels' limit of " << kKernelMaxSide
       << " pixels a side and " << kKernelMaxPixels << " in all (twice the input limit of "
       << vpSSLInputLimits::maxImageSide() << " a side, the small-landmark mode's upsampled image)";
    throw vpException(vpException::dimensionError, os.str());
  }
}
} // namespace vpSSLImageCheck

#endif

/*!
  \file vpSSLImageIo.h
  \brief Image size limits of the plugin, and reading an image file that checks them before decoding.
*/
#ifndef VP_SSL_IMAGE_IO_H
#define VP_SSL_IMAGE_IO_H

#include <cstdint>
#include <string>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>
#include <visp3/ssl/vpSSLConfig.h>

/*!
  \class vpSSLImageIo
  \ingroup group_ssl
  \brief The largest image the plugin accepts, the check of an image against it, and an image file reader
  that never lets a hostile file reach an unchecked decoder.

  Limits (doc/input-limits.md): each side at most maxImageSide() = 16384 pixels, and at most maxImagePixels() =
  2^26 (67,108,864) pixels in all, e.g. 8192 x 8192 or 16384 x 4096. They bound the memory of one frame (the
  detector keeps a few maps of 4 bytes per pixel, twice the size in the small-landmark mode) and keep every
  index of the SIMD kernels inside 32 bits.

  vpImage computes width x height in 32 bits: an image of 65537 x 65536 pixels holds 65536 bytes. check()
  compares getSize() with the product in 64 bits, so that no code reads rows that were never allocated.

  read() reads the size from the file's header (PNG, JPEG, PGM/PPM/PBM, BMP) and checks it before any pixel
  is decoded; it then decodes through OpenCV, whose decoders fail cleanly on truncated or corrupt data (ViSP
  3.5's PNG reader leaks on them, and trusts the header's size). A 16-bit image is scaled to 8 bits
  (value / 257, rounded).

  \code
  vpImage<unsigned char> I;
  vpSSLImageIo::read(I, "image.png");  // vpException: "image.png: PNG header: 20000 x 20000 pixels, ..."
  vpSSLImageIo::check(I, "my tool");    // for an image from elsewhere
  \endcode
*/
class VISP_SSL_EXPORT vpSSLImageIo
{
public:
  //! Largest image side (pixels) the plugin accepts: 16384.
  static constexpr unsigned int maxImageSide() { return 16384u; }
  //! Largest number of pixels the plugin accepts: 2^26.
  static constexpr uint64_t maxImagePixels() { return uint64_t(1) << 26; }

  /*!
    Checks a size against the limits.
    \param width, height : the size (pixels).
    \param what : names the image in the message (a file, "vpSSLDetector::detect", ...).
    \exception vpException (dimensionError) <tt>WHAT: W x H pixels: ...</tt> naming the bound exceeded, or
    an empty size.
  */
  static void checkSize(uint64_t width, uint64_t height, const std::string &what);

  /*!
    Checks an image: not empty, getSize() equal to width x height (computed in 64 bits: vpImage's own product
    wraps at 2^32), and within the limits. Allocates nothing unless it throws (a check per frame).
    \exception vpException (dimensionError) naming \e what, the size and the bound.
  */
  static void check(const vpImage<unsigned char> &I, const char *what);

  /*!
    Reads a grey image (colour files are converted with ViSP's grey conversion).
    \exception vpException (ioError) naming the file and the problem: missing, unknown format, header size
    beyond the limits, truncated or corrupt data.
  */
  static void read(vpImage<unsigned char> &I, const std::string &filename);

  //! As read(vpImage<unsigned char> &, const std::string &), in colour.
  static void read(vpImage<vpRGBa> &I, const std::string &filename);

  /*!
    The size a file's header declares, without decoding it.
    \param filename : a PNG, JPEG, PNM (P1-P6) or BMP file.
    \param width, height : the size.
    \return the format's name ("PNG", "JPEG", "PGM", ...).
    \exception vpException (ioError) when the file cannot be read, its format is not one of these, its header
    is malformed or, for a binary PNM, the pixel data are shorter than the header says.
  */
  static std::string readHeader(const std::string &filename, uint64_t &width, uint64_t &height);
};

#endif

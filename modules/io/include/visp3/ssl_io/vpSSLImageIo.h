/*!
  \file vpSSLImageIo.h
  \brief Reading an image file that checks its size against the plugin's limits before decoding.
*/
#ifndef VP_SSL_IMAGE_IO_H
#define VP_SSL_IMAGE_IO_H

#include <cstdint>
#include <string>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>
#include <visp3/ssl/vpSSLConfig.h>

/*!
  \class vpSSLImageIo
  \ingroup group_ssl_io
  \brief An image file reader that never lets a hostile file reach an unchecked decoder.

  read() reads the size from the file's header (PNG, JPEG, PGM/PPM/PBM, BMP) and checks it against
  vpSSLInputLimits before any pixel is decoded; it then decodes through OpenCV (ViSP 3.5's PNG reader leaks on
  truncated or corrupt data, and trusts the header's size). A truncated or corrupt PNG or JPEG is refused before
  OpenCV sees it, since libpng and libjpeg would print their own line on stderr (and libjpeg decode the missing
  rows as grey): a PNG's chunks and CRCs are walked, a JPEG is decoded once by libjpeg with an error manager that
  prints nothing and turns its warnings into errors. A 16-bit image is scaled to 8 bits (value / 257, rounded).

  \code
  vpImage<unsigned char> I;
  vpSSLImageIo::read(I, "image.png");  // vpException: "image.png: PNG header: 20000 x 20000 pixels, ..."
  \endcode
*/
class VISP_SSL_EXPORT vpSSLImageIo
{
public:
  /*!
    Reads a grey image (colour files are converted with ViSP's grey conversion).
    \exception vpException (ioError) naming the file and the problem: missing, unknown format, header size
    beyond the limits, truncated or corrupt data (for a JPEG, with libjpeg's message).
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

  /*!
    Checks encoded image data in memory (a PNG, JPEG, PNM or BMP file's bytes, e.g. a compressed image message) as
    read() checks a file before it hands it to a decoder: the format and the header's size within the limits, a
    PNG's chunks and CRCs, a JPEG decoded once by libjpeg without a word on stderr. Data that passes decodes through
    OpenCV's cv::imdecode() without a decoder's message on stderr.
    \param data : the encoded image.
    \param name : what the data is, for the messages (e.g. "dive.bag: /camera/image_raw/compressed: image 3").
    \return the format's name ("PNG", "JPEG", "PGM", ...).
    \exception vpException (ioError) "NAME: problem", as read() names the file.
  */
  static std::string checkData(const std::vector<unsigned char> &data, const std::string &name);
};

#endif

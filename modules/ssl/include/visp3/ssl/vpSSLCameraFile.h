/*!
  \file vpSSLCameraFile.h
  \brief Reading a camera from a ViSP XML camera file, whatever its projection model.
*/
#ifndef VP_SSL_CAMERA_FILE_H
#define VP_SSL_CAMERA_FILE_H

#include <string>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/ssl/vpSSLConfig.h>

/*!
  \class vpSSLCameraFile
  \ingroup group_ssl
  \brief Loads a camera from a vpXmlParserCamera file with one call and one clear error.

  vpXmlParserCamera finds a camera only under the projection model it is asked for, and reports on
  standard output (which the tutorials keep for JSON). This reads the model the file holds, quietly, and
  says what is wrong when it cannot: a missing file, no camera of that name, no readable model, an intrinsic
  parameter that is not a finite number in its range (check()), an image size of 0 or beyond
  vpSSLImageIo's limits.

  \code
  unsigned int width, height;
  vpCameraParameters cam = vpSSLCameraFile::load("camera.xml", "Camera", &width, &height);
  \endcode
*/
class VISP_SSL_EXPORT vpSSLCameraFile
{
public:
  /*!
    \param filename : ViSP XML camera file.
    \param name : camera name in the file (the recorded-sequence format uses "Camera").
    \param width, height : if given, the image size the file states (0 when it states none; a file states
    both or neither, each > 0, within vpSSLImageIo::checkSize()).
    \exception vpException naming the file and the field.
  */
  static vpCameraParameters load(const std::string &filename, const std::string &name = "Camera",
                                 unsigned int *width = nullptr, unsigned int *height = nullptr);

  /*!
    Checks intrinsics that come from anywhere (a file, a scaled copy, code): px and py in [minFocal(),
    maxFocal()] pixels, u0 and v0 finite within +-maxFocal(), kud and kdu within +-maxDistortion().
    \param cam : the camera.
    \param what : names it in the message.
    \exception vpException (badValue) <tt>WHAT: FIELD: must be a finite number in [LOW, HIGH], got V</tt>.
  */
  static void check(const vpCameraParameters &cam, const std::string &what);

  //! Smallest focal length accepted (pixels): 1.
  static constexpr double minFocal() { return 1.; }
  //! Largest focal length, and largest |u0|, |v0| accepted (pixels): 1e7.
  static constexpr double maxFocal() { return 1e7; }
  //! Largest |kud|, |kdu| accepted: 100.
  static constexpr double maxDistortion() { return 100.; }
};

#endif

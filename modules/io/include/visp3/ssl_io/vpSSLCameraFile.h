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
  \ingroup group_ssl_io
  \brief Loads a camera from a vpXmlParserCamera file with one call and one clear error.

  vpXmlParserCamera finds a camera only under the projection model it is asked for, and reports on
  standard output (which the tutorials keep for JSON). This reads the model the file holds, quietly, and
  says what is wrong when it cannot: a missing file, no camera of that name, no readable model, an intrinsic
  parameter that is not a finite number in its range (vpSSLInputLimits::checkCamera()), an image size of 0
  or beyond vpSSLInputLimits's limits.

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
    both or neither, each > 0, within vpSSLInputLimits::checkImageSize()).
    \exception vpException naming the file and the field.

    ViSP 3.5's vpXmlParserCamera prints on std::cout whatever the file holds; load() swaps std::cout's buffer
    for the duration of that call, so output written on std::cout by another thread meanwhile is lost.
  */
  static vpCameraParameters load(const std::string &filename, const std::string &name = "Camera",
                                 unsigned int *width = nullptr, unsigned int *height = nullptr);
};

#endif

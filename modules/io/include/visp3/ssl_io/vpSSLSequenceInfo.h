/*!
  \file vpSSLSequenceInfo.h
  \brief What a recorded sequence is: the content of its sequence.json.
*/
#ifndef VP_SSL_SEQUENCE_INFO_H
#define VP_SSL_SEQUENCE_INFO_H

#include <string>

#include <visp3/core/vpPoseVector.h>
#include <visp3/ssl/vpSSLConfig.h>

/*!
  \struct vpSSLSequenceInfo
  \ingroup group_ssl_io
  \brief The content of a sequence's sequence.json (doc/sequence-format.md):

  \code{.json}
  {
    "target": "ssl3-a3",
    "camera_to_vehicle": [0, 0, 0.2, 0, 0, 0],
    "source": "recorded",
    "water": { "turbidity": 0.1 }
  }
  \endcode

  \c water is optional and kept as raw JSON text, verbatim, so that the simulator's parameters survive a
  read-write round trip whatever they are. Other members of the file are ignored. A UTF-8 byte order mark
  at the start is skipped (as in frames.csv).

  Limits (doc/input-limits.md): the file is at most maxFileSize() bytes; \c camera_to_vehicle's translation
  within +-vpSSLInputLimits::maxMountTranslation() m and its theta-u rotation within
  +-vpSSLInputLimits::maxMountRotation() rad per element.

  \code
  vpSSLSequenceInfo info;
  info.target = "ssl3-a3";
  info.vMc = vpPoseVector(0., 0., 0.2, 0., 0., 0.);
  info.source = "simulated";
  info.water = "{\"turbidity\": 0.1}";
  vpSSLSequenceInfo back = vpSSLSequenceInfo::fromJson(info.toJson());
  \endcode
*/
struct VISP_SSL_EXPORT vpSSLSequenceInfo
{
  std::string target;              ///< A built-in target name ("ssl3-a3") or a path to a target file; required.
  vpPoseVector vMc;                ///< \c camera_to_vehicle: the camera pose in the vehicle frame.
  std::string source = "recorded"; ///< "simulated" or "recorded".
  std::string water;               ///< Raw JSON object of the water parameters, or empty when absent.

  /*!
    Parses sequence.json text.
    \param text : the JSON text.
    \param filename : the name used in error messages.
    \exception vpException (badValue) naming the file, the line and the member on any syntax error, missing
    required member (\c target, \c camera_to_vehicle, \c source) or wrong type.
  */
  static vpSSLSequenceInfo fromJson(const std::string &text, const std::string &filename = "sequence.json");

  //! Largest sequence.json file read (bytes): 1 MiB.
  static constexpr size_t maxFileSize() { return size_t(1) << 20; }

  /*!
    Reads a sequence.json file.
    \exception vpException (ioError) when the file cannot be read; (badValue) as fromJson().
  */
  static vpSSLSequenceInfo load(const std::string &filename);

  /*!
    The sequence.json text.
    \exception vpException (badValue) when \c target is empty, \c source is neither "simulated" nor "recorded",
    a pose value is not finite or \c water is neither empty nor a JSON object.
  */
  std::string toJson() const;

  /*!
    Writes toJson() to a file.
    \exception vpException as toJson(), or (ioError) when the file cannot be written.
  */
  void save(const std::string &filename) const;
};

#endif

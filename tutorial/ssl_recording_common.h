/*!
  \file ssl_recording_common.h
  \brief Tutorial-local helpers of the two recording tutorials (tutorial-ssl-record, tutorial-ssl-rosbag): the
  options they share and the output folder they must not overwrite. Header-only, like ssl_tutorial_common.h.
*/
#ifndef SSL_RECORDING_COMMON_H
#define SSL_RECORDING_COMMON_H

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <visp3/core/vpException.h>
#include <visp3/core/vpPoseVector.h>
#include <visp3/ssl/vpSSLInputLimits.h>
#include <visp3/ssl_io/vpSSLSequenceInfo.h>

#include "ssl_tutorial_common.h"

namespace ssltut {

/*!
  The camera's pose on the vehicle, vMc, from "TX TY TZ TUX TUY TUZ" (m, theta-u rad; blanks or commas between),
  value of option \e name.
  \exception UsageError unless it is exactly six finite numbers.
*/
inline vpPoseVector parseMount(const std::string &name, const std::string &text)
{
  std::string spaced = text;
  for (char &c : spaced) {
    if (c == ',') {
      c = ' ';
    }
  }
  std::istringstream in(spaced);
  std::vector<std::string> words;
  for (std::string w; in >> w;) {
    words.push_back(w);
  }
  if (words.size() != 6) {
    throw UsageError(name + ": expected 6 numbers \"TX TY TZ TUX TUY TUZ\", got \"" + text + "\"");
  }
  vpPoseVector vMc;
  for (unsigned int i = 0; i < 6; ++i) {
    vMc[i] = parseNumber(name, words[i],
                         i < 3 ? -vpSSLInputLimits::maxMountTranslation() : -vpSSLInputLimits::maxMountRotation(),
                         i < 3 ? vpSSLInputLimits::maxMountTranslation() : vpSSLInputLimits::maxMountRotation());
  }
  return vMc;
}

/*!
  Refuses an output folder that exists and is not empty, before anything is read or written, so that nothing the
  user has is overwritten.
  \exception vpException (ioError) naming the folder.
*/
inline void checkNewOutput(const std::string &folder)
{
  std::error_code ec;
  if (std::filesystem::exists(folder, ec) &&
      (!std::filesystem::is_directory(folder, ec) || !std::filesystem::is_empty(folder, ec))) {
    throw vpException(vpException::ioError,
                      "%s: exists and is not an empty folder (nothing is overwritten: choose a new folder)",
                      folder.c_str());
  }
}

/*!
  The options both recording tutorials take for the sequence they write: --output, --target (default ssl3-a3) and
  --camera-to-vehicle (default 0 0 0 0 0 0, needed with odometry).
*/
struct RecordingOptions
{
  std::string output;
  std::string target = "ssl3-a3";
  vpPoseVector vMc;
  bool mountGiven = false;

  //! Takes option \e a when it is one of the three, its value from \e value(); false for any other option.
  template <typename Value> bool parse(const std::string &a, Value value)
  {
    if (a == "--output") {
      output = value();
    } else if (a == "--target") {
      target = value();
      if (target.empty()) {
        throw UsageError("option --target: empty name");
      }
    } else if (a == "--camera-to-vehicle") {
      vMc = parseMount("option " + a, value());
      mountGiven = true;
    } else {
      return false;
    }
    return true;
  }

  /*!
    \exception UsageError when \e odometry is set (by option \e odometryOption) without --camera-to-vehicle: the
    tracker needs the camera's pose on the vehicle to use the odometry.
  */
  void checkMount(bool odometry, const std::string &odometryOption) const
  {
    if (odometry && !mountGiven) {
      throw UsageError(odometryOption + " needs --camera-to-vehicle (the camera's pose on the vehicle)");
    }
  }

  //! The sequence.json of the recording: source "recorded".
  vpSSLSequenceInfo info() const
  {
    vpSSLSequenceInfo info;
    info.target = target;
    info.vMc = vMc;
    info.source = "recorded";
    return info;
  }
};

} // namespace ssltut

#endif

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
#include <visp3/ssl/vpSSLSequenceInfo.h>

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
                         i < 3 ? -vpSSLSequenceInfo::maxMountTranslation() : -vpSSLSequenceInfo::maxMountRotation(),
                         i < 3 ? vpSSLSequenceInfo::maxMountTranslation() : vpSSLSequenceInfo::maxMountRotation());
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

//! The sequence.json of a recording: \e target, \e vMc, source "recorded".
inline vpSSLSequenceInfo recordingInfo(const std::string &target, const vpPoseVector &vMc)
{
  vpSSLSequenceInfo info;
  info.target = target;
  info.vMc = vMc;
  info.source = "recorded";
  return info;
}

} // namespace ssltut

#endif

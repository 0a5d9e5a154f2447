/*!
  \file ssl_tutorial_input.h
  \brief Tutorial-local input helpers: the folder of the plugin's data (targets, camera files, sample images) in
  the build tree or an installed tree, and frames from a video file or a camera through OpenCV's cv::VideoCapture.
  Header-only, like ssl_tutorial_common.h.
*/
#ifndef SSL_TUTORIAL_INPUT_H
#define SSL_TUTORIAL_INPUT_H

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

#include <opencv2/core.hpp>
#include <opencv2/core/utils/logger.hpp>
#include <opencv2/videoio.hpp>

#include <visp3/core/vpException.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpImageConvert.h>
#include <visp3/ssl/vpSSLInputLimits.h>
#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/ssl_io/vpSSLCameraFile.h>
#include <visp3/ssl_io/vpSSLImageIo.h>

#include "ssl_tutorial_common.h"

namespace ssltut {

/*!
  The plugin's data folder (data/ of the sources, installed as share/visp_ssl/), the first that exists of:
  - the environment variable VISP_SSL_DATA_DIR;
  - ../share/visp_ssl beside the running program (a tutorial run from an installed tree);
  - the data/ of the source tree the build was configured from (a tutorial run from the build tree).
  When none exists, the last one: a file then fails to open with its full path in the message.
*/
inline std::string dataDir()
{
  namespace fs = std::filesystem;
  std::error_code ec;
  const char *env = std::getenv("VISP_SSL_DATA_DIR");
  if (env != nullptr && *env != '\0' && fs::is_directory(env, ec)) {
    return env;
  }
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = exe.parent_path().parent_path() / "share" / "visp_ssl";
    if (fs::is_directory(installed, ec)) {
      return installed.string();
    }
  }
  return VISP_SSL_DATA_DIR;
}

/*!
  The camera \e cameraName of the ViSP XML file \e cameraFile into \e cam, and the target \e targetName (a built-in
  name or a target file) into \e target.
  \exception UsageError with the reader's message naming the file, line and field (a tutorial's exit status 2).
*/
inline void loadCameraAndTarget(const std::string &cameraFile, const std::string &cameraName,
                                const std::string &targetName, vpCameraParameters &cam, vpSSLTarget &target)
{
  try {
    cam = vpSSLCameraFile::load(cameraFile, cameraName);
    target = vpSSLTarget::fromName(targetName);
  } catch (const vpException &e) {
    throw UsageError(e.getStringMessage());
  }
}

//! Whether \e path names a video file by its extension (.avi, .mp4, .mkv, .mov, .m4v, .mpg, .mpeg, .webm).
inline bool isVideoFile(const std::string &path)
{
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  for (const char *v : {".avi", ".mp4", ".mkv", ".mov", ".m4v", ".mpg", ".mpeg", ".webm"}) {
    if (ext == v) {
      return true;
    }
  }
  return false;
}

/*!
  Grey frames of a video file (OpenCV's FFmpeg backend) or a camera (OpenCV's V4L2 backend, which converts more
  pixel formats than vpV4l2Grabber, e.g. MJPG) through cv::VideoCapture. Every failure is a vpException naming the
  source and, for a file, the frame: a source that cannot be opened, no frame at all, a video that ends two frames or
  more before the number its header announces (truncated, or a frame that cannot be decoded), a frame beyond the limits
  of vpSSLInputLimits::checkImage().
*/
class VideoInput
{
public:
  /*!
    Opens \e source: a camera index ("0", "1", ...) or a video file.
    \exception vpException (ioError) when it cannot be opened.
  */
  void open(const std::string &source)
  {
    m_source = source;
    m_camera = !source.empty() &&
               std::all_of(source.begin(), source.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
    m_index = 0;
    if (!m_camera && !std::filesystem::is_regular_file(source)) {
      throw vpException(vpException::ioError, "%s: cannot open the video: no such file", source.c_str());
    }
    // OpenCV's and FFmpeg's own messages (a camera index that does not exist, a backend that declines, a corrupt
    // frame) would add lines to the one that a failure prints; the user's OPENCV_FFMPEG_LOGLEVEL is kept.
    cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
    setenv("OPENCV_FFMPEG_LOGLEVEL", "-8", 0); // AV_LOG_QUIET
    bool opened = false;
    try {
      // V4L2 for a camera: OpenCV's other backends (GStreamer) leak when they probe a missing device.
      opened =
          m_camera ? m_capture.open(std::atoi(source.c_str()), cv::CAP_V4L2) : m_capture.open(source, cv::CAP_FFMPEG);
    } catch (const cv::Exception &) {
      opened = false;
    }
    if (!opened || !m_capture.isOpened()) {
      throw vpException(vpException::ioError, "%s: cannot open the %s", source.c_str(),
                        m_camera ? "camera (no such device, or busy)"
                                 : "video (not a video, or no decoder for it in OpenCV's FFmpeg)");
    }
    const double count = m_capture.get(cv::CAP_PROP_FRAME_COUNT);
    m_count = (!m_camera && count >= 1. && count < 1e9) ? static_cast<long>(count) : -1;
  }

  /*!
    Reads the next frame into \e I.
    \return false at the end of a video (never for a camera, whose failure throws).
    \exception vpException (ioError) on a video without any frame, a video ending before the frame count of its
    header, a camera that stops delivering, or a frame out of vpSSLImageIo's limits.
  */
  bool read(vpImage<unsigned char> &I)
  {
    bool ok = false;
    try {
      ok = m_capture.read(m_frame) && !m_frame.empty();
    } catch (const cv::Exception &) {
      ok = false;
    }
    if (!ok) {
      if (m_camera) {
        throw vpException(vpException::ioError, "%s: the camera delivered no frame after %ld", m_source.c_str(),
                          m_index);
      }
      if (m_index == 0) {
        throw vpException(vpException::ioError, "%s: no frame can be decoded", m_source.c_str());
      }
      // One frame short is accepted: FFmpeg estimates the count of some containers from their duration.
      if (m_count > 0 && m_index + 1 < m_count) {
        throw vpException(vpException::ioError,
                          "%s: the video ends at frame %ld of the %ld its header announces (truncated, or a frame "
                          "that cannot be decoded)",
                          m_source.c_str(), m_index, m_count);
      }
      return false;
    }
    vpSSLInputLimits::checkImageSize(static_cast<uint64_t>(m_frame.cols), static_cast<uint64_t>(m_frame.rows),
                                     m_source);
    vpImageConvert::convert(m_frame, I);
    ++m_index;
    return true;
  }

  long frameIndex() const { return m_index; } //!< Frames read so far.
  long frameCount() const { return m_count; } //!< Frames the video's header announces, -1 unknown (a camera).
  bool isCamera() const { return m_camera; }  //!< Whether the source is a camera index.
  double fps() const { return m_capture.get(cv::CAP_PROP_FPS); } //!< Frame rate the source announces (0: unknown).

private:
  cv::VideoCapture m_capture;
  cv::Mat m_frame;
  std::string m_source;
  bool m_camera = false;
  long m_index = 0;
  long m_count = -1;
};

} // namespace ssltut

#endif

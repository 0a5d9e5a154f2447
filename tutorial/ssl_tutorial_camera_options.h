/*!
  \file ssl_tutorial_camera_options.h
  \brief Tutorial-local options naming the camera and the target: the ViSP XML camera file, the camera's name in it
  and the target (a built-in name or a target file), shared by tutorial-ssl-detector, tutorial-ssl-tracker,
  tutorial-ssl-detector-live and tutorial-ssl-detector-pose. Header-only and on the standard library alone, like
  ssl_tutorial_options.h.
*/
#ifndef SSL_TUTORIAL_CAMERA_OPTIONS_H
#define SSL_TUTORIAL_CAMERA_OPTIONS_H

#include <string>

namespace ssltut {

/*!
  The camera file, the camera's name in it and the target, as options. Each tutorial keeps the spelling its --help
  documents: --camera and --camera-name by default, --intrinsic and --camera_name in the tutorials written after
  ViSP's own (tutorial-detection-object).
*/
struct CameraTargetOptions
{
  std::string cameraFile;             //!< The ViSP XML camera file (empty: none given and no default).
  std::string cameraName = "Camera";  //!< The camera's name inside the file.
  std::string targetName = "ssl3-a3"; //!< A built-in target name or a target file.
  std::string fileOption;             //!< The option that gives cameraFile.
  std::string nameOption;             //!< The option that gives cameraName.

  //! The camera file \e defaultFile unless the option \e fileOption_ gives another, named by option \e nameOption_.
  explicit CameraTargetOptions(const std::string &defaultFile = "", const std::string &fileOption_ = "--camera",
                               const std::string &nameOption_ = "--camera-name")
      : cameraFile(defaultFile), fileOption(fileOption_), nameOption(nameOption_)
  {
  }

  //! Takes option \e a when it is one of the three (or --target), its value from \e value(); false for any other.
  template <typename Value> bool parseCameraOption(const std::string &a, const Value &value)
  {
    if (a == fileOption) {
      cameraFile = value();
    } else if (a == nameOption) {
      cameraName = value();
    } else if (a == "--target") {
      targetName = value();
    } else {
      return false;
    }
    return true;
  }
};

} // namespace ssltut

#endif

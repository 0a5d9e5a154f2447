/*!
  \file ssl_tutorial_closed_loop_options.h
  \brief Tutorial-local options of the two simulated closed-loop tutorials (tutorial-ssl-servo,
  tutorial-ssl-servo-monte-carlo) on their rendered image and their output: --output-dir, --width, --height, --small
  and --quiet. Header-only and on the standard library alone, like ssl_tutorial_options.h.
*/
#ifndef SSL_TUTORIAL_CLOSED_LOOP_OPTIONS_H
#define SSL_TUTORIAL_CLOSED_LOOP_OPTIONS_H

#include <string>

#include "ssl_tutorial_options.h"

namespace ssltut {

/*!
  The image and output options both closed-loop tutorials take; each tutorial's own options derive from it.
*/
struct ClosedLoopOutputOptions
{
  //! --output-dir: where the files go; each tutorial sets its own default folder, never the working directory.
  std::string outputDir;
  unsigned int width = 640, height = 480; //!< --width, --height: the rendered image (px).
  bool small = false;                     //!< --small: 320x240 whatever --width and --height say.
  bool quiet = false;                     //!< --quiet: no progress on stdout.

  /*!
    Takes option \e a when it is one of the five, its value from \e value(); false for any other option. The image
    is at least 64x48 and at most \e maxSide on each side.
    \exception UsageError for a size that is not an integer in that range, or an empty --output-dir.
  */
  template <typename Value> bool parseOutputOption(const std::string &a, const Value &value, long long maxSide)
  {
    if (a == "--small") {
      small = true;
    } else if (a == "--quiet") {
      quiet = true;
    } else if (a == "--output-dir") {
      outputDir = value();
      if (outputDir.empty()) {
        throw UsageError{"--output-dir: empty folder name"};
      }
    } else if (a == "--width") {
      width = static_cast<unsigned int>(parseInteger(a, value(), 64, maxSide));
    } else if (a == "--height") {
      height = static_cast<unsigned int>(parseInteger(a, value(), 48, maxSide));
    } else {
      return false;
    }
    return true;
  }

  //! After the whole command line: --small sets 320x240 wherever it stood among --width and --height.
  void applySmall()
  {
    if (small) {
      width = 320;
      height = 240;
    }
  }
};

} // namespace ssltut

#endif

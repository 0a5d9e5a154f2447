/*!
  \file ssl_tutorial_option_loop.h
  \brief Tutorial-local loop over a command line: --help, the options' values and the unknown options, in the words
  of each tutorial (OptionStyle). Header-only and on the standard library alone, like ssl_tutorial_options.h.
*/
#ifndef SSL_TUTORIAL_OPTION_LOOP_H
#define SSL_TUTORIAL_OPTION_LOOP_H

#include <iostream>
#include <string>

#include "ssl_tutorial_options.h"

namespace ssltut {

/*!
  When a tutorial acts on --help and how it words a bad option; each keeps what its --help, tests and users know.
*/
enum class OptionStyle
{
  /*!
    --help acted on once the whole command line is read, so that a bad option after it is still an error; "OPTION
    needs a value", "unknown option OPTION (see --help)" (tutorial-ssl-servo, -servo-monte-carlo, -auv-driver, -ibvs).
  */
  ReadAll,
  /*!
    --help acted on where it stands, what follows it unread; "option OPTION needs a value (see --help)", "unknown
    option "OPTION" (see --help)" (tutorial-ssl-detector, -tracker, -detector-live, -detector-pose, -record, -rosbag).
  */
  HelpFirst
};

/*!
  Reads the command line option by option: --help (or -h) as \e style says; every other option \e a goes to
  take(a, value), where value() returns the option's value (optionValue()) and take() returns false for an option it
  does not know.
  \return false when --help (or -h) was given, once \e usage is printed on stdout: the tutorial then stops with
  status 0.
  \exception UsageError for an unknown option or a missing value, worded as \e style says; take()'s own.
*/
template <typename Take> bool readOptions(int argc, char **argv, const char *usage, OptionStyle style, Take take)
{
  const bool helpFirst = style == OptionStyle::HelpFirst;
  bool help = false;
  for (int i = 1; i < argc && !(help && helpFirst); ++i) {
    const std::string a = argv[i];
    const auto value = [&] {
      return optionValue(argc, argv, i, helpFirst ? MissingValue::SeeHelp : MissingValue::Short);
    };
    if (a == "--help" || a == "-h") {
      help = true;
    } else if (!take(a, value)) {
      throw UsageError(helpFirst ? "unknown option \"" + a + "\" (see --help)"
                                 : "unknown option " + a + " (see --help)");
    }
  }
  if (help) {
    std::cout << usage;
  }
  return !help;
}

} // namespace ssltut

#endif

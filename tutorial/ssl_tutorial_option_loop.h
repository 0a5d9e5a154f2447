/*!
  \file ssl_tutorial_option_loop.h
  \brief Tutorial-local loop over a command line, for the tutorials that read every option before acting on --help
  (tutorial-ssl-servo, tutorial-ssl-servo-monte-carlo, tutorial-ssl-auv-driver, tutorial-ssl-ibvs). Header-only and
  on the standard library alone, like ssl_tutorial_options.h.
*/
#ifndef SSL_TUTORIAL_OPTION_LOOP_H
#define SSL_TUTORIAL_OPTION_LOOP_H

#include <iostream>
#include <string>

#include "ssl_tutorial_options.h"

namespace ssltut {

/*!
  Reads the command line option by option: --help (or -h) is noted and the reading goes on, so that a bad option
  after it is still an error; every other option \e a goes to take(a, value), where value() returns the option's
  value (optionValue(), "OPTION needs a value" when it has none) and take() returns false for an option it does
  not know.
  \return false when --help (or -h) was given, once the whole command line is read and \e usage printed on
  stdout: the tutorial then stops with status 0.
  \exception UsageError "unknown option OPTION (see --help)" when take() returns false; take()'s own.
*/
template <typename Take> bool readOptions(int argc, char **argv, const char *usage, Take take)
{
  bool help = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&] { return optionValue(argc, argv, i); };
    if (a == "--help" || a == "-h") {
      help = true;
    } else if (!take(a, value)) {
      throw UsageError("unknown option " + a + " (see --help)");
    }
  }
  if (help) {
    std::cout << usage;
  }
  return !help;
}

} // namespace ssltut

#endif

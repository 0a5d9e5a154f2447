/*!
  \file ssl_tutorial_options.h
  \brief Tutorial-local option parsing every tutorial shares: one error type for a bad command line (exit status 2,
  one line on stderr), option values, integers, numbers and thread counts checked whole. Header-only and on the
  standard library alone, so that the tutorials without a display (tutorial-ssl-detector-recall) include it too.
*/
#ifndef SSL_TUTORIAL_OPTIONS_H
#define SSL_TUTORIAL_OPTIONS_H

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace ssltut {

/*!
  A bad command line or input: the tutorials print its message on one line and exit with status 2. Thrown by
  the parsers below; a tutorial's guard (guardedMain()) turns it into that status wherever it is thrown.
*/
struct UsageError : std::runtime_error
{
  explicit UsageError(const std::string &message) : std::runtime_error(message) {}
};

/*!
  The integer \e text in [minimum, maximum], value of option \e name: digits with an optional leading '-', nothing
  else ("2.5", "1e15", " 3", "+-1" are not integers; 4294967298 is out of range, not wrapped to 2).
  \exception UsageError naming the option, the text and the range.
*/
inline long long parseInteger(const std::string &name, const std::string &text, long long minimum, long long maximum)
{
  long long v = 0;
  const char *b = text.data(), *e = text.data() + text.size();
  const std::from_chars_result r = std::from_chars(b, e, v);
  if (text.empty() || r.ec != std::errc() || r.ptr != e || v < minimum || v > maximum) {
    throw UsageError(name + ": expected an integer in [" + std::to_string(minimum) + ", " + std::to_string(maximum) +
                     "], got \"" + text + "\"");
  }
  return v;
}

/*!
  How a tutorial words an option given without its value; each keeps the words its tests and users know.
*/
enum class MissingValue
{
  Short,   //!< "OPTION needs a value"
  SeeHelp, //!< "option OPTION needs a value (see --help)"
  Colon    //!< "OPTION: missing value"
};

/*!
  The value of the option at argv[i], which is argv[i + 1]; \e i moves on to it.
  \exception UsageError worded as \e words says when the option is the last argument.
*/
inline std::string optionValue(int argc, char **argv, int &i, MissingValue words = MissingValue::Short)
{
  if (i + 1 >= argc) {
    const std::string name = argv[i];
    throw UsageError(words == MissingValue::SeeHelp ? "option " + name + " needs a value (see --help)"
                     : words == MissingValue::Colon ? name + ": missing value"
                                                    : name + " needs a value");
  }
  return argv[++i];
}

/*!
  The finite number \e text in [minimum, maximum], value of option \e name (strtod syntax, the whole text; no
  sign after a sign).
  \exception UsageError otherwise.
*/
inline double parseNumber(const std::string &name, const std::string &text, double minimum = -HUGE_VAL,
                          double maximum = HUGE_VAL)
{
  char *end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  const bool doubleSign = text.size() >= 2 && (text[0] == '+' || text[0] == '-') && (text[1] == '+' || text[1] == '-');
  if (text.empty() || *end != '\0' || !std::isfinite(v) || doubleSign ||
      std::isspace(static_cast<unsigned char>(text[0]))) {
    throw UsageError(name + ": not a number: \"" + text + "\"");
  }
  if (v < minimum || v > maximum) {
    throw UsageError(name + ": expected a number in [" + std::to_string(minimum) + ", " + std::to_string(maximum) +
                     "], got \"" + text + "\"");
  }
  return v;
}

/*!
  The worker-thread count \e text, value of option \e name: an integer in [1, maximum], or in [0, maximum] when
  \e zeroIsAllCores (the tutorial documents 0 as "all cores"). A negative count is never read as a huge unsigned one.
  \exception UsageError naming the option, the text and the range.
*/
inline unsigned int parseThreads(const std::string &name, const std::string &text, bool zeroIsAllCores,
                                 long long maximum)
{
  return static_cast<unsigned int>(parseInteger(name, text, zeroIsAllCores ? 0 : 1, maximum));
}

} // namespace ssltut

#endif

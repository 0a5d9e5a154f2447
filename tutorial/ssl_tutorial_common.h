/*!
  \file ssl_tutorial_common.h
  \brief Tutorial-local helpers every tutorial shares: strict option parsing (ssl_tutorial_options.h), a top-level guard
  so that no exception reaches main's caller, checked output streams, an X display that falls back to files, and
  numbered image patterns. Header-only.
*/
#ifndef SSL_TUTORIAL_COMMON_H
#define SSL_TUTORIAL_COMMON_H

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iostream>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>

#include <visp3/core/vpException.h>
#include <visp3/core/vpImage.h>
#include <visp3/gui/vpDisplayX.h>
#include <visp3/ssl_io/vpSSLCameraFile.h>

#include "ssl_tutorial_options.h"

namespace ssltut {

/*!
  Runs \e run (a tutorial's body) so that no exception reaches main's caller: a UsageError prints its message and
  gives 2, any other exception (vpException, std::bad_alloc, cv::Exception, ...) prints one line and gives 1.
  Every line starts with \e program.
*/
template <typename Run> int guardedMain(const char *program, Run run)
{
  try {
    return run();
  } catch (const UsageError &e) {
    std::cerr << program << ": " << e.what() << std::endl;
    return 2;
  } catch (const vpException &e) {
    std::cerr << program << ": " << e.getStringMessage() << std::endl;
  } catch (const std::bad_alloc &) {
    std::cerr << program << ": out of memory" << std::endl;
  } catch (const std::exception &e) {
    std::cerr << program << ": " << e.what() << std::endl;
  } catch (...) {
    std::cerr << program << ": unknown error" << std::endl;
  }
  return 1;
}

/*!
  The recorded sequence folder (doc/sequence-format.md: a folder holding sequence.json and frames.csv) that is
  \e path or holds it, after resolving "..", symbolic links and the working folder; an empty string when there is
  none. A tutorial writes nothing inside a sequence: its files are a user's recording, read, never written.
*/
inline std::string enclosingSequence(const std::string &path)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path p = fs::absolute(path, ec);
  if (ec) {
    return std::string();
  }
  p = fs::weakly_canonical(p, ec);
  if (ec) {
    return std::string();
  }
  for (;;) {
    if (fs::is_regular_file(p / "sequence.json", ec) && fs::is_regular_file(p / "frames.csv", ec)) {
      return p.string();
    }
    if (!p.has_relative_path()) {
      return std::string();
    }
    p = p.parent_path();
  }
}

/*!
  Throws a UsageError when the output \e path of \e option lies inside a recorded sequence (enclosingSequence()):
  "OPTION: PATH is inside the recorded sequence SEQ, which is read, never written: choose a place outside it".
*/
inline void checkOutsideSequences(const std::string &option, const std::string &path)
{
  const std::string sequence = enclosingSequence(path);
  if (!sequence.empty()) {
    throw UsageError(option + ": " + path + " is inside the recorded sequence " + sequence +
                     ", which is read, never written: choose a place outside it");
  }
}

/*!
  Throws a UsageError when the output \e path of \e option is one of the files in \e inputs (the same file, whatever
  the path that names it): "OPTION: PATH is the input FILE, which is read, never written".
*/
inline void checkNotAnInput(const std::string &option, const std::string &path,
                            std::initializer_list<std::string> inputs)
{
  std::error_code ec;
  for (const std::string &input : inputs) {
    if (!input.empty() && std::filesystem::equivalent(path, input, ec)) {
      throw UsageError(option + ": " + path + " is the input " + input + ", which is read, never written");
    }
  }
}

/*!
  Flushes \e out and, for a file, closes it; throws when any write failed (a full device, a closed pipe), so
  that a tool never reports success on a file it did not write whole.
  \exception vpException (ioError) naming \e path.
*/
inline void finishStream(std::ostream &out, const std::string &path)
{
  out.flush();
  if (std::ofstream *f = dynamic_cast<std::ofstream *>(&out)) {
    if (f->is_open()) {
      f->close();
    }
  }
  if (!out) {
    throw vpException(vpException::ioError, "%s: write error (device full or closed?)", path.c_str());
  }
}

/*!
  A window on \e I when an X display can be opened, else nullptr and a one-line notice on stderr (the caller
  then writes files instead). vpDisplayX throws vpDisplayException without a server; DISPLAY unset is checked
  first so that Xlib prints nothing of its own.
*/
inline std::unique_ptr<vpDisplay> openDisplay(vpImage<vpRGBa> &I, const char *program, const std::string &title,
                                              const std::string &fallback)
{
  const char *display = std::getenv("DISPLAY");
  if (display != nullptr && *display != '\0') {
    try {
      std::unique_ptr<vpDisplay> d(new vpDisplayX(I, vpDisplay::SCALE_AUTO));
      vpDisplay::setTitle(I, title);
      return d;
    } catch (const vpException &) {
    }
  }
  std::cerr << program << ": no X display (DISPLAY "
            << (display != nullptr && *display != '\0' ? "cannot be opened" : "unset") << "): " << fallback
            << std::endl;
  return nullptr;
}

/*!
  The project's default camera, data/camera/camera-640x480.xml, with its image size in \e width and \e height;
  with \e half, the same field of view at half the size (320x240).
  \exception vpException when the file cannot be read.
*/
inline vpCameraParameters defaultCamera(unsigned int &width, unsigned int &height, bool half)
{
  vpCameraParameters cam =
      vpSSLCameraFile::load(std::string(VISP_SSL_DATA_DIR) + "/camera/camera-640x480.xml", "Camera", &width, &height);
  if (half) {
    width /= 2;
    height /= 2;
    cam.initPersProjWithoutDistortion(cam.get_px() / 2., cam.get_py() / 2., cam.get_u0() / 2., cam.get_v0() / 2.);
  }
  return cam;
}

//! Longest path a numbered image pattern may expand to (bytes): ViSP's readers keep names in fixed buffers.
constexpr size_t kMaxPathLength = 1024;

/*!
  Checks a numbered image pattern (e.g. images/%06d.png): exactly one conversion, %d with an optional 0 flag and
  a width of at most 2 digits, and a path that stays below kMaxPathLength for any frame number.
  \exception UsageError naming the option and the problem.
*/
inline void checkPattern(const std::string &option, const std::string &pattern)
{
  int conversions = 0;
  for (size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') {
      continue;
    }
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      ++i;
      continue;
    }
    size_t j = i + 1;
    if (j < pattern.size() && pattern[j] == '0') {
      ++j;
    }
    size_t digits = 0;
    while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j]))) {
      ++j;
      ++digits;
    }
    if (j >= pattern.size() || pattern[j] != 'd' || digits > 2) {
      throw UsageError(option + ": \"" + pattern +
                       "\": the only conversion a pattern may hold is %d, with an optional 0 flag and a width of at "
                       "most 2 digits (e.g. %06d)");
    }
    ++conversions;
    i = j;
  }
  if (conversions != 1) {
    throw UsageError(option + ": \"" + pattern + "\": a pattern holds exactly one %d conversion, got " +
                     std::to_string(conversions));
  }
  // The widest frame number: 99 digits of width or the 10 of an int.
  if (pattern.size() + 110 > kMaxPathLength) {
    throw UsageError(option + ": \"" + pattern.substr(0, 40) + "...\": the pattern is longer than the " +
                     std::to_string(kMaxPathLength - 110) + " bytes a path pattern may have");
  }
}

//! The name of frame \e index of a pattern checkPattern() accepted.
inline std::string expandPattern(const std::string &pattern, long index)
{
  char buf[kMaxPathLength];
  std::snprintf(buf, sizeof(buf), pattern.c_str(), static_cast<int>(index));
  return buf;
}

} // namespace ssltut

#endif

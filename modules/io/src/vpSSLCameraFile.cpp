#include <visp3/ssl_io/vpSSLCameraFile.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>

#include <visp3/core/vpException.h>
#include <visp3/core/vpIoTools.h>
#include <visp3/core/vpXmlParserCamera.h>
#include <visp3/ssl/vpSSLInputLimits.h>

namespace {
std::string trim(const std::string &s)
{
  const size_t b = s.find_first_not_of(" \t\r\n"), e = s.find_last_not_of(" \t\r\n");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

// Text of the first <tag>...</tag> at or after position from, and whether there is one.
bool tagText(const std::string &text, const std::string &tag, size_t from, std::string &value)
{
  const size_t b = text.find("<" + tag + ">", from);
  if (b == std::string::npos) {
    return false;
  }
  const size_t e = text.find("</" + tag + ">", b);
  if (e == std::string::npos) {
    return false;
  }
  value = trim(text.substr(b + tag.size() + 2, e - b - tag.size() - 2));
  return true;
}

// Position of the <camera> element whose <name> is name, or npos.
size_t cameraElement(const std::string &text, const std::string &name)
{
  for (size_t b = text.find("<name>"); b != std::string::npos; b = text.find("<name>", b + 1)) {
    std::string n;
    if (tagText(text, "name", b, n) && n == name) {
      const size_t c = text.rfind("<camera>", b);
      return c == std::string::npos ? b : c;
    }
  }
  return std::string::npos;
}

std::string readText(const std::string &filename)
{
  std::ifstream in(filename, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

// Why vpXmlParserCamera rejected a camera whose element is there: the first intrinsic that is not a
// valid number in its range, or an empty string when none is found wrong.
std::string intrinsicProblem(const std::string &text, size_t camera)
{
  const size_t end = text.find("</camera>", camera);
  for (const char *tag : {"px", "py", "u0", "v0", "kud", "kdu"}) {
    std::string v;
    if (!tagText(text, tag, camera, v) || text.find(std::string("<") + tag + ">", camera) > end) {
      continue;
    }
    double x = 0.;
    const char *b = v.data(), *e = v.data() + v.size();
    const std::from_chars_result r = std::from_chars(b, e, x);
    if (v.empty() || r.ec != std::errc() || r.ptr != e) {
      return std::string(tag) + ": not a number: \"" + v + "\"";
    }
    const std::string t(tag);
    if ((t == "px" || t == "py") && !(x > 0.)) {
      return t + ": must be > 0, got " + v;
    }
  }
  return std::string();
}

// vpXmlParserCamera::parse() with its standard output discarded. ViSP 3.5's parser writes "Found camera with
// name: ..." on std::cout for every <name> it reads, whatever the file holds, so no check made beforehand can
// keep it quiet; and the tutorials keep standard output for JSON. Neither OpenCV (cv::FileStorage wants an
// <opencv_storage> root) nor ViSP offer another reader of this format, and a second pugixml would clash with the
// copy libvisp_core exports.
// This is the one place of the plugin that touches a global stream: std::cout's buffer is swapped for the
// duration of the call and restored on every path, including exceptions. Another thread writing to std::cout
// meanwhile would lose its output, which is why load() says it is not to be called concurrently with output on
// std::cout.
int parseQuietly(vpXmlParserCamera &parser, vpCameraParameters &cam, const std::string &filename,
                 const std::string &name, vpCameraParameters::vpCameraParametersProjType model)
{
  struct CoutSilencer
  {
    std::ostringstream sink;
    std::streambuf *saved = std::cout.rdbuf(sink.rdbuf());
    ~CoutSilencer() { std::cout.rdbuf(saved); }
  } silencer;
  try {
    return parser.parse(cam, filename, name, model);
  } catch (...) {
    return vpXmlParserCamera::SEQUENCE_ERROR;
  }
}
} // namespace

vpCameraParameters vpSSLCameraFile::load(const std::string &filename, const std::string &name, unsigned int *width,
                                         unsigned int *height)
{
  std::error_code ec;
  if (std::filesystem::is_directory(filename, ec)) {
    throw vpException(vpException::ioError, "%s: is a folder, not a camera file", filename.c_str());
  }
  if (!vpIoTools::checkFilename(filename)) {
    throw vpException(vpException::ioError, "%s: missing or unreadable", filename.c_str());
  }
  // The file holds one projection model for the camera; vpXmlParserCamera only finds the one asked for.
  const vpCameraParameters::vpCameraParametersProjType models[] = {
      vpCameraParameters::perspectiveProjWithDistortion, vpCameraParameters::perspectiveProjWithoutDistortion};
  for (auto model : models) {
    vpXmlParserCamera parser;
    vpCameraParameters cam;
    const int status = parseQuietly(parser, cam, filename, name, model);
    if (status != vpXmlParserCamera::SEQUENCE_OK) {
      continue;
    }
    const std::string where = filename + ": camera \"" + name + "\"";
    vpSSLInputLimits::checkCamera(cam, where);
    // vpXmlParserCamera gives 0 for a size the file does not state; a stated 0 is an error, and so is one
    // side without the other.
    const unsigned int w = parser.getWidth(), h = parser.getHeight();
    const std::string text = readText(filename);
    const size_t camera = cameraElement(text, name);
    const std::pair<const char *, unsigned int> sides[] = {{"image_width", w}, {"image_height", h}};
    for (const auto &side : sides) {
      std::string stated;
      const std::string tag = std::string("<") + side.first + ">";
      const bool isStated = camera != std::string::npos && text.find(tag, camera) < text.find("</camera>", camera) &&
                            tagText(text, side.first, camera, stated);
      if (side.second == 0 && isStated) {
        throw vpException(vpException::badValue, where + ": " + side.first + ": must be > 0, got \"" + stated + "\"");
      }
      // vpXmlParserCamera saturates a side of 2^32 - 1 or more to 2^32 - 1: the message gives the file's own text.
      if (isStated && side.second == std::numeric_limits<unsigned int>::max()) {
        throw vpException(vpException::badValue, where + ": " + side.first + ": " + stated +
                                                     " pixels: a side exceeds the limit of " +
                                                     std::to_string(vpSSLInputLimits::maxImageSide()) + " pixels");
      }
    }
    if ((w == 0) != (h == 0)) {
      throw vpException(vpException::badValue, where + ": image_width and image_height: give both or neither, got " +
                                                   std::to_string(w) + " x " + std::to_string(h));
    }
    if (w != 0) {
      try {
        vpSSLInputLimits::checkImageSize(w, h, where + ": image_width x image_height");
      } catch (const vpException &e) {
        throw vpException(vpException::badValue, e.getStringMessage());
      }
    }
    if (width != nullptr) {
      *width = w;
    }
    if (height != nullptr) {
      *height = h;
    }
    return cam;
  }
  // Say whether the name or the model is what is missing.
  const std::string text = readText(filename);
  const size_t camera = cameraElement(text, name);
  if (camera == std::string::npos) {
    throw vpException(vpException::badValue,
                      "%s: name: no camera named \"%s\" (write it with vpXmlParserCamera::save(cam, file, \"%s\", "
                      "width, height))",
                      filename.c_str(), name.c_str(), name.c_str());
  }
  const std::string problem = intrinsicProblem(text, camera);
  if (!problem.empty()) {
    throw vpException(vpException::badValue, "%s: camera \"%s\": %s", filename.c_str(), name.c_str(), problem.c_str());
  }
  throw vpException(vpException::badValue,
                    "%s: camera \"%s\": no readable <model> (type perspectiveProjWithoutDistortion or "
                    "perspectiveProjWithDistortion with px, py, u0, v0), or the file is not valid XML",
                    filename.c_str(), name.c_str());
}

#include <visp3/ssl/vpSSLCameraFile.h>

#include <fstream>
#include <iostream>
#include <sstream>

#include <visp3/core/vpException.h>
#include <visp3/core/vpIoTools.h>
#include <visp3/core/vpXmlParserCamera.h>

namespace {
std::string trim(const std::string &s)
{
  const size_t b = s.find_first_not_of(" \t\r\n"), e = s.find_last_not_of(" \t\r\n");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}
} // namespace

vpCameraParameters vpSSLCameraFile::load(const std::string &filename, const std::string &name, unsigned int *width,
                                         unsigned int *height)
{
  if (!vpIoTools::checkFilename(filename)) {
    throw vpException(vpException::ioError, "%s: missing or unreadable", filename.c_str());
  }
  // The file holds one projection model for the camera; vpXmlParserCamera only finds the one asked for.
  const vpCameraParameters::vpCameraParametersProjType models[] = {
      vpCameraParameters::perspectiveProjWithDistortion, vpCameraParameters::perspectiveProjWithoutDistortion};
  for (auto model : models) {
    vpXmlParserCamera parser;
    vpCameraParameters cam;
    // vpXmlParserCamera prints "Found camera ..." on std::cout, which would corrupt a tool's JSON output.
    std::ostringstream sink;
    std::streambuf *coutBuf = std::cout.rdbuf(sink.rdbuf());
    int status = vpXmlParserCamera::SEQUENCE_ERROR;
    try {
      status = parser.parse(cam, filename, name, model);
    } catch (...) {
      status = vpXmlParserCamera::SEQUENCE_ERROR;
    }
    std::cout.rdbuf(coutBuf);
    if (status != vpXmlParserCamera::SEQUENCE_OK) {
      continue;
    }
    if (!(cam.get_px() > 0.) || !(cam.get_py() > 0.)) {
      throw vpException(vpException::badValue, "%s: camera \"%s\": px and py must be > 0", filename.c_str(),
                        name.c_str());
    }
    if (width != nullptr) {
      *width = parser.getWidth();
    }
    if (height != nullptr) {
      *height = parser.getHeight();
    }
    return cam;
  }
  // Say whether the name or the model is what is missing.
  std::ifstream in(filename);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  bool named = false;
  for (size_t b = text.find("<name>"); b != std::string::npos && !named; b = text.find("<name>", b + 1)) {
    const size_t e = text.find("</name>", b);
    named = e != std::string::npos && trim(text.substr(b + 6, e - b - 6)) == name;
  }
  if (!named) {
    throw vpException(vpException::badValue,
                      "%s: name: no camera named \"%s\" (write it with vpXmlParserCamera::save(cam, file, \"%s\", "
                      "width, height))",
                      filename.c_str(), name.c_str(), name.c_str());
  }
  throw vpException(vpException::badValue,
                    "%s: camera \"%s\": no readable <model> (type perspectiveProjWithoutDistortion or "
                    "perspectiveProjWithDistortion with px, py, u0, v0), or the file is not valid XML",
                    filename.c_str(), name.c_str());
}

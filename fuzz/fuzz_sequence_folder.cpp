// libFuzzer target: the sequence reader on a whole folder. The input is split at the byte sequence "\n--8<--\n"
// into camera.xml, sequence.json, frames.csv and the bytes of images 000000.png, 000001.pgm, 000002.jpg; the
// reader must read it through or throw a vpException, whatever the files hold.
#include <cmath>
#include <string>
#include <vector>

#include <visp3/core/vpException.h>
#include <visp3/core/vpImage.h>
#include <visp3/ssl/vpSSLInputLimits.h>
#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/ssl_io/vpSSLSequenceReader.h>

#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  const std::string input(reinterpret_cast<const char *>(data), size);
  const std::string cut = "\n--8<--\n";
  std::vector<std::string> parts;
  for (size_t b = 0;;) {
    const size_t e = input.find(cut, b);
    parts.push_back(input.substr(b, e == std::string::npos ? std::string::npos : e - b));
    if (e == std::string::npos || parts.size() == 6) {
      break;
    }
    b = e + cut.size();
  }
  parts.resize(6);
  const std::filesystem::path dir = sslfuzz::scratch() / "sequence";
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  std::filesystem::create_directories(dir / "images");
  const char *names[6] = {"camera.xml",        "sequence.json",     "frames.csv",
                          "images/000000.png", "images/000001.pgm", "images/000002.jpg"};
  for (int i = 0; i < 6; ++i) {
    if (i < 3 || !parts[i].empty()) {
      sslfuzz::writeFile(dir / names[i], parts[i]);
    }
  }
  vpSSLSequenceReader reader;
  try {
    reader.open(dir.string());
    // The target named, resolved in the folder: a built-in name or a file there.
    try {
      vpSSLTarget::fromName(reader.getTargetPath());
    } catch (const vpException &) {
    }
    vpSSLSequenceFrame f;
    vpImage<unsigned char> I;
    for (int n = 0; n < 4 && reader.next(f, I); ++n) {
      vpSSLInputLimits::checkImage(I, "frame"); // the reader gives only images within the limits
    }
  } catch (const vpException &) {
  }
  return 0;
}

// libFuzzer target: frames.csv rows (vpSSLSequenceReader). The input is frames.csv after the standard header, in
// a sequence folder whose camera.xml and sequence.json are valid and whose images/ holds frames 0 to 3; every row
// read gives values within the documented bounds, and a bad row a vpException naming frames.csv.
#include <cmath>

#include <visp3/core/vpException.h>
#include <visp3/core/vpImage.h>
#include <visp3/io/vpImageIo.h>
#include <visp3/ssl_io/vpSSLSequenceReader.h>

#include "fuzz_common.h"

namespace {
const char *kCamera = "<?xml version=\"1.0\"?>\n<root><camera><name>Camera</name><image_width>8</image_width>"
                      "<image_height>6</image_height><model><type>perspectiveProjWithoutDistortion</type><px>10</px>"
                      "<py>10</py><u0>4</u0><v0>3</v0></model></camera></root>\n";
const char *kHeader =
    "frame,t,odom_tx,odom_ty,odom_tz,odom_tux,odom_tuy,odom_tuz,gt_tx,gt_ty,gt_tz,gt_tux,gt_tuy,gt_tuz";

const std::filesystem::path &folder()
{
  static const std::filesystem::path dir = [] {
    const std::filesystem::path d = sslfuzz::scratch() / "csv-sequence";
    std::filesystem::create_directories(d / "images");
    sslfuzz::writeFile(d / "camera.xml", kCamera);
    sslfuzz::writeFile(d / "sequence.json",
                       "{\"target\": \"ssl3-a3\", \"camera_to_vehicle\": [0,0,0,0,0,0], \"source\": \"recorded\"}");
    const vpImage<unsigned char> I(6, 8, 128);
    for (int i = 0; i < 4; ++i) {
      vpImageIo::write(I, (d / "images" / ("00000" + std::to_string(i) + ".pgm")).string());
    }
    return d;
  }();
  return dir;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  const std::filesystem::path &dir = folder();
  // The first byte picks whether the input brings its own header line (extra columns, a BOM, ...).
  std::string csv;
  if (size > 0 && data[0] & 1) {
    csv = std::string(kHeader) + "\n";
  }
  if (size > 0) {
    csv.append(reinterpret_cast<const char *>(data) + 1, size - 1);
  }
  sslfuzz::writeFile(dir / "frames.csv", csv);
  vpSSLSequenceReader reader;
  try {
    reader.open(dir.string());
    vpSSLSequenceFrame f;
    vpImage<unsigned char> I;
    for (int n = 0; n < 8; ++n) {
      if (!(n % 2 ? reader.next(f, I) : reader.next(f))) {
        break;
      }
      if (!std::isfinite(f.t) || std::fabs(f.t) > vpSSLSequenceReader::maxTime()) {
        std::abort();
      }
      for (unsigned int i = 0; i < 6; ++i) {
        if (!std::isfinite(f.oMv[i]) || !std::isfinite(f.cMo[i])) {
          std::abort();
        }
      }
    }
  } catch (const vpException &) {
  }
  return 0;
}

// libFuzzer target: the target-file parser (vpSSLTarget::load, doc/target-file.md). Any input gives a target
// within the documented limits or a vpException; a target that loads saves and loads back identically.
#include <visp3/core/vpException.h>
#include <visp3/ssl/vpSSLTarget.h>

#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  const std::filesystem::path path = sslfuzz::scratch() / "target.txt";
  sslfuzz::writeFile(path, data, size);
  vpSSLTarget t;
  try {
    t = vpSSLTarget::load(path.string());
  } catch (const vpException &) {
    return 0;
  }
  if (t.size() == 0 || t.size() > vpSSLTarget::maxLandmarks()) {
    std::abort();
  }
  const double p = t.getP(); // one p for all: never throws on a loaded target
  if (!(p >= vpSSLTarget::minP() && p <= vpSSLTarget::maxP())) {
    std::abort();
  }
  const std::filesystem::path saved = sslfuzz::scratch() / "saved.txt";
  t.save(saved.string());
  const vpSSLTarget back = vpSSLTarget::load(saved.string());
  if (back.size() != t.size() || back.getSheetWidth() != t.getSheetWidth()) {
    std::abort();
  }
  return 0;
}

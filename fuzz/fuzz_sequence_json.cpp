// libFuzzer target: sequence.json (vpSSLSequenceInfo::fromJson). Any text gives an info within the documented
// bounds or a vpException; an info read writes back to JSON that reads back the same.
#include <cmath>
#include <string>

#include <visp3/core/vpException.h>
#include <visp3/ssl/vpSSLInputLimits.h>
#include <visp3/ssl_io/vpSSLSequenceInfo.h>

#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  const std::string text(reinterpret_cast<const char *>(data), size);
  vpSSLSequenceInfo info;
  try {
    info = vpSSLSequenceInfo::fromJson(text);
  } catch (const vpException &) {
    return 0;
  }
  for (unsigned int i = 0; i < 6; ++i) {
    if (!std::isfinite(info.vMc[i]) || std::fabs(info.vMc[i]) > vpSSLInputLimits::maxMountTranslation()) {
      std::abort();
    }
  }
  try {
    const vpSSLSequenceInfo back = vpSSLSequenceInfo::fromJson(info.toJson());
    if (back.target != info.target || back.source != info.source || back.water != info.water) {
      std::abort();
    }
  } catch (const vpException &) {
    std::abort(); // what was read must write back
  }
  return 0;
}

#include "ssl_test_sequences.h"

#include <visp3/ssl_io/vpSSLSequenceReader.h>

namespace sslt {

Sequence readSequence(const std::string &name)
{
  Sequence s;
  vpSSLSequenceReader reader;
  reader.open(std::string(VISP_SSL_DATA_DIR) + "/sequences/" + name);
  s.cam = reader.getCameraParameters();
  s.vMc = vpHomogeneousMatrix(reader.getInfo().vMc);
  s.target = vpSSLTarget::fromName(reader.getInfo().target);
  vpSSLSequenceFrame f;
  vpImage<unsigned char> I;
  while (reader.next(f, I)) {
    s.frames.push_back(f);
    s.images.push_back(I);
  }
  return s;
}

} // namespace sslt

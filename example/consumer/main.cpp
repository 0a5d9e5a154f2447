// Smallest program using the installed plugin: proves that the headers, the libraries visp_ssl and visp_ssl_io
// and their dependencies (ViSP, OpenCV, Highway) are all found through find_package(VISP_SSL).
#include <cstdlib>
#include <iostream>

#include <visp3/core/vpImage.h>
#include <visp3/ssl/vpSSLMatchingFunction.h>
#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/ssl_io/vpSSLSequenceInfo.h>

int main()
{
  try {
    const vpSSLTarget target = vpSSLTarget::ssl3a3();
    const vpSSLMatchingFunction match(40, target.getP());

    // A uniform image has no self-similar structure: its matching map is 0 everywhere.
    vpImage<unsigned char> I(64, 64, 128);
    vpImage<int> M;
    match.compute(I, M);
    const int maxValue = M.getMaxValue();

    // visp_ssl_io: a sequence.json written and read back.
    vpSSLSequenceInfo info;
    info.target = target.getName();
    const vpSSLSequenceInfo back = vpSSLSequenceInfo::fromJson(info.toJson());

    std::cout << "visp-ssl consumer: target " << target.getName() << " with " << target.size()
              << " landmarks, matching window " << match.getWindow() << " (SIMD "
              << vpSSLMatchingFunction::getSimdTarget() << "), max of the map on a uniform image: " << maxValue
              << ", sequence.json target " << back.target << std::endl;
    return maxValue == 0 && back.target == info.target ? EXIT_SUCCESS : EXIT_FAILURE;
  } catch (const vpException &e) {
    std::cerr << "visp-ssl consumer: " << e.getMessage() << std::endl;
    return EXIT_FAILURE;
  }
}

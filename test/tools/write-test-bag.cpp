// Writes the rosbag tests' bag (ssl_test_bag.h) for test/e2e/rosbag.sh:
//   write-test-bag OUT.bag [--compressed] [--no-odometry] [--odometry-end SECONDS] [--frames N] [--size W H]
// (small sizes make the seed bags of fuzz/corpus/fuzz_rosbag/)
#include <cstdlib>
#include <iostream>
#include <string>

#include "ssl_test_bag.h"

int main(int argc, char **argv)
{
  if (argc < 2) {
    std::cerr
        << "usage: write-test-bag OUT.bag [--compressed] [--no-odometry] [--odometry-end S] [--frames N] [--size W H]"
        << std::endl;
    return 2;
  }
  ssltest::TestBagOptions options;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--compressed") {
      options.compressed = true;
    } else if (a == "--no-odometry") {
      options.odometry = false;
    } else if (a == "--odometry-end" && i + 1 < argc) {
      options.odometryEnd = std::atof(argv[++i]);
    } else if (a == "--frames" && i + 1 < argc) {
      options.frames = static_cast<unsigned int>(std::atoi(argv[++i]));
    } else if (a == "--size" && i + 2 < argc) {
      options.width = static_cast<unsigned int>(std::atoi(argv[++i]));
      options.height = static_cast<unsigned int>(std::atoi(argv[++i]));
    } else {
      std::cerr << "write-test-bag: unknown option " << a << std::endl;
      return 2;
    }
  }
  ssltest::writeTestBag(argv[1], options);
  return 0;
}

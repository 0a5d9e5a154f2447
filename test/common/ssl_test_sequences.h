/*!
  \file ssl_test_sequences.h
  \brief The recorded sample sequences of data/sequences/ held in memory whole, for the tracker tests.
*/
#ifndef SSL_TEST_SEQUENCES_H
#define SSL_TEST_SEQUENCES_H

#include <string>
#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/ssl_io/vpSSLSequenceFrame.h>

namespace sslt {

//! A whole sequence: its camera, mount and target, and every frame with its image.
struct Sequence
{
  vpCameraParameters cam;
  vpHomogeneousMatrix vMc;
  vpSSLTarget target;
  std::vector<vpSSLSequenceFrame> frames;
  std::vector<vpImage<unsigned char>> images;
};

//! The sample sequence data/sequences/\e name, read whole. \exception vpException when it cannot be read.
Sequence readSequence(const std::string &name);

} // namespace sslt

#endif

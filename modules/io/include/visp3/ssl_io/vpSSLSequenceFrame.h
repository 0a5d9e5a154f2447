/*!
  \file vpSSLSequenceFrame.h
  \brief One row of a recorded sequence's frames.csv.
*/
#ifndef VP_SSL_SEQUENCE_FRAME_H
#define VP_SSL_SEQUENCE_FRAME_H

#include <map>
#include <string>

#include <visp3/core/vpPoseVector.h>
#include <visp3/ssl/vpSSLConfig.h>

/*!
  \struct vpSSLSequenceFrame
  \ingroup group_ssl_io
  \brief One frame of a recorded sequence: a row of frames.csv (doc/sequence-format.md).

  Odometry and ground truth are optional: a recording without odometry, or a frame where the truth is
  unknown or the target is out of view, has the matching flag false and empty cells in frames.csv.

  \code
  vpSSLSequenceFrame f;
  f.index = 0;
  f.t = 0.04;
  f.hasGroundTruth = true;
  f.cMo = vpPoseVector(0., 0., 1.5, 0., 0., 0.);
  f.extras["depth"] = "12.5";   // only written when "depth" was declared at vpSSLSequenceWriter::open()
  \endcode
  See vpSSLSequenceReader and vpSSLSequenceWriter.
*/
struct VISP_SSL_EXPORT vpSSLSequenceFrame
{
  unsigned int index = 0;      ///< Image index (column \c frame), equal to the row number counted from 0.
  double t = 0.;               ///< Time stamp (s), strictly increasing along the sequence.
  bool hasOdometry = false;    ///< True when the \c odom_* cells hold oMv, false when they are empty.
  vpPoseVector oMv;            ///< Vehicle pose in its odometry frame (m, theta-u rad); valid if hasOdometry.
  bool hasGroundTruth = false; ///< True when the \c gt_* cells hold cMo, false when they are empty.
  vpPoseVector cMo;            ///< Ground-truth target pose in the camera frame; valid if hasGroundTruth.
  std::map<std::string, std::string> extras; ///< Cells of the columns after the 14 standard ones, by column name.
};

#endif

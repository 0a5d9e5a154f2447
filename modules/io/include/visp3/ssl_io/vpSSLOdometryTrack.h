/*!
  \file vpSSLOdometryTrack.h
  \brief Time-stamped vehicle poses, interpolated to any time they cover.
*/

#ifndef VP_SSL_ODOMETRY_TRACK_H
#define VP_SSL_ODOMETRY_TRACK_H

#include <string>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/ssl/vpSSLConfig.h>
#include <visp3/ssl_io/vpSSLSequenceFrame.h>

/*!
  \class vpSSLOdometryTrack
  \ingroup group_ssl_io
  \brief The vehicle poses \c oMv of a recording's odometry, at their own times, interpolated to the times of the
  images (doc/recordings.md).

  Between two samples the translation is interpolated linearly and the rotation along the shortest arc
  (\f$R_0 \exp(\alpha \log(R_0^\top R_1))\f$); a time before the first sample or after the last is refused, never
  extrapolated. load() reads an odometry CSV: a header, then one row per sample,
  <tt>t,tx,ty,tz,tux,tuy,tuz</tt> (theta-u) or <tt>t,tx,ty,tz,qx,qy,qz,qw</tt> (unit quaternion), in the frames
  of doc/sequence-format.md; further columns are ignored. tutorial-ssl-record and vpSSLRosbagReader use it.

  \code
  vpSSLOdometryTrack odometry = vpSSLOdometryTrack::load("dive-odometry.csv");
  if (odometry.covers(t)) {
    vpHomogeneousMatrix oMv = odometry.interpolate(t);
  }
  \endcode
*/
class VISP_SSL_EXPORT vpSSLOdometryTrack
{
public:
  /*!
    Appends a sample.
    \param t : its time (s), finite and greater than the previous sample's.
    \param oMv : the vehicle pose in the odometry frame.
    \exception vpException (badValue) when \e t is not finite or does not increase, or when there are already
    maxSamples() samples.
  */
  void add(double t, const vpHomogeneousMatrix &oMv);

  /*!
    Reads an odometry CSV (see the class description; doc/recordings.md).
    \exception vpException (ioError) when the file cannot be read; (badValue) <tt>FILE:LINE: FIELD: problem</tt> on
    an unknown header, a cell that is not a number, a time that does not increase, a quaternion whose norm is not
    1 within 1e-3, more than maxSamples() rows, or no row at all.
  */
  static vpSSLOdometryTrack load(const std::string &filename);

  //! True when \e t is within [getStartTime(), getEndTime()] (never for an empty track).
  bool covers(double t) const;

  /*!
    The pose at time \e t.
    \exception vpException (badValue) when covers(t) is false.
  */
  vpHomogeneousMatrix interpolate(double t) const;

  /*!
    Stamps a recording's frame for the sequence format's limits (doc/recordings.md): \c frame.t is \e t minus
    \e t0, the time of the recording's first image (Unix times and ROS stamps exceed frames.csv's +-1e9 s); the
    extra column stampColumn() keeps \e t itself (6 decimals); with samples, \c frame.oMv is the pose at \e t
    with its origin moved to the first sample's position, axes kept (UTM coordinates exceed frames.csv's +-1e4 m).
    \exception vpException (badValue) when the track has samples and does not cover \e t.
  */
  void stampFrame(double t, double t0, vpSSLSequenceFrame &frame) const;
  //! The extra column of the absolute image times written by stampFrame(): "stamp".
  static const char *stampColumn() { return "stamp"; }

  //! Number of samples.
  size_t size() const { return m_t.size(); }
  /*!
    Time of sample \e i (s), as read or added.
    \exception vpException (badValue) when \e i >= size().
  */
  double getTime(size_t i) const;
  /*!
    Pose \c oMv of sample \e i, as read or added.
    \exception vpException (badValue) when \e i >= size().
  */
  const vpHomogeneousMatrix &getPose(size_t i) const;
  //! Time of the first sample (s); 0 for an empty track.
  double getStartTime() const { return m_t.empty() ? 0. : m_t.front(); }
  //! Time of the last sample (s); 0 for an empty track.
  double getEndTime() const { return m_t.empty() ? 0. : m_t.back(); }
  //! Most samples a track holds: 4 million (11 hours at 100 Hz).
  static constexpr size_t maxSamples() { return 4000000; }
  //! Largest |t| of a row load() accepts (s): Unix time stamps fit.
  static constexpr double maxTime() { return 1e10; }
  //! Largest |tx|, |ty|, |tz| of a row load() accepts (m).
  static constexpr double maxTranslation() { return 1e7; }
  //! Largest |element| of a row's theta-u vector (rad) or quaternion that load() accepts.
  static constexpr double maxRotation() { return 10.; }

private:
  std::vector<double> m_t;
  std::vector<vpHomogeneousMatrix> m_oMv;
};

#endif

// libFuzzer target: the odometry CSV reader (vpSSLOdometryTrack::load, whose rows are split by vpSSLCsv as those of
// frames.csv). A file it accepts has 1 to maxSamples() rows, each with a finite time within +-maxTime() greater
// than the previous one, a finite translation within +-maxTranslation() and a rotation matrix; interpolation
// between the first and last rows stays finite. A bad file gives a vpException.
#include <cmath>

#include <visp3/core/vpException.h>
#include <visp3/ssl/vpSSLFinite.h>
#include <visp3/ssl_io/vpSSLOdometryTrack.h>

#include "fuzz_common.h"

namespace {
const char *kThetaU = "t,tx,ty,tz,tux,tuy,tuz";
const char *kQuaternion = "t,tx,ty,tz,qx,qy,qz,qw";

// A finite pose whose translation is within the reader's bound and whose rotation is orthonormal with
// determinant 1 (to rounding).
bool validPose(const vpHomogeneousMatrix &M)
{
  if (!vpSSLFinite::isFinite(M))
    return false;
  for (unsigned int r = 0; r < 3; ++r)
    if (std::fabs(M[r][3]) > vpSSLOdometryTrack::maxTranslation())
      return false;
  const vpRotationMatrix R = M.getRotationMatrix();
  const vpMatrix I = static_cast<vpMatrix>(R) * static_cast<vpMatrix>(R.t());
  for (unsigned int r = 0; r < 3; ++r)
    for (unsigned int c = 0; c < 3; ++c)
      if (std::fabs(I[r][c] - (r == c ? 1. : 0.)) > 1e-9)
        return false;
  return std::fabs(static_cast<vpMatrix>(R).det() - 1.) < 1e-9;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  // The first byte picks a header line to prepend (theta-u, quaternion) or none (the input brings its own).
  std::string csv;
  if (size > 0 && (data[0] & 3) != 0) {
    csv = std::string((data[0] & 3) == 1 ? kThetaU : kQuaternion) + "\n";
  }
  if (size > 0) {
    csv.append(reinterpret_cast<const char *>(data) + 1, size - 1);
  }
  const std::filesystem::path path = sslfuzz::scratch() / "odometry.csv";
  sslfuzz::writeFile(path, csv);
  vpSSLOdometryTrack track;
  try {
    track = vpSSLOdometryTrack::load(path.string());
  } catch (const vpException &) {
    return 0;
  }
  if (track.size() < 1 || track.size() > vpSSLOdometryTrack::maxSamples()) {
    std::abort();
  }
  for (size_t i = 0; i < track.size(); ++i) {
    const double t = track.getTime(i);
    if (!std::isfinite(t) || std::fabs(t) > vpSSLOdometryTrack::maxTime() || (i > 0 && !(t > track.getTime(i - 1)))) {
      std::abort();
    }
    if (!validPose(track.getPose(i))) {
      std::abort();
    }
  }
  // Between the first and last rows (the middle, and just after the first row, where alpha is tiny).
  const double t0 = track.getStartTime(), t1 = track.getEndTime();
  for (const double t : {t0, 0.5 * (t0 + t1), std::nextafter(t0, t1), t1}) {
    if (!track.covers(t) || !validPose(track.interpolate(t))) {
      std::abort();
    }
  }
  return 0;
}

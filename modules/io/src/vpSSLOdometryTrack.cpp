#include <visp3/ssl_io/vpSSLOdometryTrack.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <visp3/core/vpException.h>
#include <visp3/core/vpQuaternionVector.h>
#include <visp3/core/vpThetaUVector.h>

#include "vpSSLCsv.h"

using namespace vpSSLCsv;

namespace {
std::string formatTime(double t)
{
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(6);
  os << t;
  return os.str();
}
} // namespace

void vpSSLOdometryTrack::add(double t, const vpHomogeneousMatrix &oMv)
{
  if (!std::isfinite(t))
    throw vpException(vpException::badValue, "odometry: time is not finite");
  if (!m_t.empty() && !(t > m_t.back()))
    throw vpException(vpException::badValue,
                      "odometry: time not increasing (" + formatTime(t) + " after " + formatTime(m_t.back()) + ")");
  if (m_t.size() >= maxSamples())
    throw vpException(vpException::badValue,
                      "odometry: more than " + std::to_string(maxSamples()) + " samples (split the recording)");
  m_t.push_back(t);
  m_oMv.push_back(oMv);
}

vpSSLOdometryTrack vpSSLOdometryTrack::load(const std::string &filename)
{
  std::ifstream in(filename, std::ios::binary);
  if (!in)
    throw vpException(vpException::ioError, filename + ": missing or unreadable");
  static const char *const thetaU[7] = {"t", "tx", "ty", "tz", "tux", "tuy", "tuz"};
  static const char *const quaternion[8] = {"t", "tx", "ty", "tz", "qx", "qy", "qz", "qw"};
  std::string line;
  std::vector<std::string> cells;
  vpSSLCsv::getLine(in, line, filename + ":1: ");
  if (line.compare(0, 3, "\xEF\xBB\xBF") == 0)
    line.erase(0, 3);
  if (!line.empty() && line.back() == '\r')
    line.pop_back();
  checkLineEnd(line, filename + ":1: ");
  if (!splitCsv(line, cells))
    throw vpException(vpException::badValue, filename + ":1: header: unterminated quote");
  auto matches = [&cells](const char *const *names, size_t n) {
    if (cells.size() < n)
      return false;
    for (size_t i = 0; i < n; ++i)
      if (trim(cells[i]) != names[i])
        return false;
    return true;
  };
  const bool isQuaternion = matches(quaternion, 8);
  if (!isQuaternion && !matches(thetaU, 7))
    throw vpException(vpException::badValue,
                      filename +
                          ":1: header: expected t,tx,ty,tz,tux,tuy,tuz or t,tx,ty,tz,qx,qy,qz,qw, "
                          "got \"" +
                          line.substr(0, 80) + "\"");
  const size_t nColumns = cells.size(), nValues = isQuaternion ? 8 : 7;
  vpSSLOdometryTrack track;
  size_t lineNumber = 1;
  bool emptyLine = false;
  while (vpSSLCsv::getLine(in, line, filename + ":" + std::to_string(lineNumber + 1) + ": ")) {
    ++lineNumber;
    const std::string where = filename + ":" + std::to_string(lineNumber) + ": ";
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    checkLineEnd(line, where);
    if (trim(line).empty()) {
      emptyLine = true;
      continue;
    }
    if (emptyLine)
      throw vpException(vpException::badValue, where + "row: a row after an empty line (a hole in the table)");
    if (!splitCsv(line, cells) || cells.size() != nColumns)
      throw vpException(vpException::badValue, where + "row: expected " + std::to_string(nColumns) + " cells, got " +
                                                   std::to_string(cells.size()));
    double v[8];
    for (size_t i = 0; i < nValues; ++i) {
      // The times and positions of a dive, not of an overflow.
      const double bound = i == 0 ? maxTime() : (i < 4 ? maxTranslation() : maxRotation());
      const std::string error = parseNumber(cells[i], v[i], bound, i == 0 ? "s" : (i < 4 ? "m" : "rad"));
      if (!error.empty())
        throw vpException(vpException::badValue, where + (isQuaternion ? quaternion[i] : thetaU[i]) + ": " + error);
    }
    if (!track.m_t.empty() && !(v[0] > track.m_t.back()))
      throw vpException(vpException::badValue, where + "t: not increasing (" + trim(cells[0]) + " after " +
                                                   formatTime(track.m_t.back()) + ")");
    vpRotationMatrix R;
    if (isQuaternion) {
      const double norm = std::sqrt(v[4] * v[4] + v[5] * v[5] + v[6] * v[6] + v[7] * v[7]);
      if (std::fabs(norm - 1.) > 1e-3)
        throw vpException(vpException::badValue,
                          where + "qw: the quaternion's norm is " + formatTime(norm) + ", not 1 within 1e-3");
      R.buildFrom(vpQuaternionVector(v[4] / norm, v[5] / norm, v[6] / norm, v[7] / norm));
    } else {
      R.buildFrom(vpThetaUVector(v[4], v[5], v[6]));
    }
    try {
      track.add(v[0], vpHomogeneousMatrix(vpTranslationVector(v[1], v[2], v[3]), R));
    } catch (const vpException &e) {
      throw vpException(vpException::badValue, where + "row: " + e.getStringMessage());
    }
  }
  if (track.m_t.empty())
    throw vpException(vpException::badValue, filename + ":0: file: no odometry row after the header");
  return track;
}

double vpSSLOdometryTrack::getTime(size_t i) const
{
  if (i >= m_t.size())
    throw vpException(vpException::badValue,
                      "odometry: sample " + std::to_string(i) + " of " + std::to_string(m_t.size()));
  return m_t[i];
}

const vpHomogeneousMatrix &vpSSLOdometryTrack::getPose(size_t i) const
{
  getTime(i);
  return m_oMv[i];
}

bool vpSSLOdometryTrack::covers(double t) const
{
  return !m_t.empty() && t >= m_t.front() && t <= m_t.back();
}

vpHomogeneousMatrix vpSSLOdometryTrack::interpolate(double t) const
{
  if (!covers(t)) {
    throw vpException(vpException::badValue, "odometry: time " + formatTime(t) + " is outside the odometry's [" +
                                                 formatTime(getStartTime()) + ", " + formatTime(getEndTime()) + "]");
  }
  const size_t i1 = static_cast<size_t>(std::lower_bound(m_t.begin(), m_t.end(), t) - m_t.begin());
  if (m_t[i1] == t)
    return m_oMv[i1];
  const size_t i0 = i1 - 1;
  const double alpha = (t - m_t[i0]) / (m_t[i1] - m_t[i0]);
  const vpHomogeneousMatrix &M0 = m_oMv[i0], &M1 = m_oMv[i1];
  const vpTranslationVector t0 = M0.getTranslationVector(), t1 = M1.getTranslationVector();
  const vpRotationMatrix R0 = M0.getRotationMatrix();
  const vpThetaUVector tu(R0.t() * M1.getRotationMatrix());
  const vpRotationMatrix R = R0 * vpRotationMatrix(vpThetaUVector(alpha * tu[0], alpha * tu[1], alpha * tu[2]));
  return vpHomogeneousMatrix(t0 + (t1 - t0) * alpha, R);
}

void vpSSLOdometryTrack::stampFrame(double t, double t0, vpSSLSequenceFrame &frame) const
{
  frame.t = t - t0;
  frame.extras[stampColumn()] = formatTime(t);
  frame.hasOdometry = !m_t.empty();
  if (frame.hasOdometry) {
    vpHomogeneousMatrix oMv = interpolate(t);
    oMv.insert(oMv.getTranslationVector() - m_oMv.front().getTranslationVector());
    frame.oMv.buildFrom(oMv);
  }
}

/*!
  \file vpSSLScenario.cpp
  \brief The scenario trajectories: approach, orbit, spiral, leave-return, left-right (paper Fig. 8) and
  surface reflection (paper Sec. 3.1).
*/
#include <visp3/ssl_sim/vpSSLScenario.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include <visp3/core/vpException.h>
#include <visp3/core/vpMath.h>
#include <visp3/core/vpRzyxVector.h>

namespace {
struct ScenarioInfo
{
  const char *name;
  double startRange, endRange;
  const char *description;
};

const ScenarioInfo kScenarios[] = {
    {"approach", 10., 0.5, "straight approach from 10 m to 0.5 m, slight weave"},
    {"orbit", 3., 3., "arc from 60 deg left to 60 deg right at a constant 3 m"},
    {"spiral", 8., 1.5, "descending spiral around the target's axis, 8 m to 1.5 m"},
    {"leave-return", 4., 3., "turns 80 deg away (target out of view) and back, 4 m to 3 m"},
    {"left-right", 2., 2., "paper Fig. 8: target moved left, right and back at 2 m"},
    {"reflection", 6., 1.5, "paper Sec. 3.1: target below a calm surface, 6 m to 1.5 m"},
};

const ScenarioInfo &findScenario(const std::string &name)
{
  for (const ScenarioInfo &s : kScenarios) {
    if (name == s.name) {
      return s;
    }
  }
  std::ostringstream os;
  os << "vpSSLScenario: unknown scenario \"" << name << "\"; use one of:";
  for (const ScenarioInfo &s : kScenarios) {
    os << " " << s.name;
  }
  throw vpException(vpException::badValue, os.str());
}

// The target floats mid-water in about 4 m of water, as at Peel Island (paper Sec. 5.3); the reflection
// scenario brings it up to 0.45 m, the top of an A3 sheet held landscape 0.30 m under the surface.
const double kTargetDepth = 2.5;
const double kReflectionTargetDepth = 0.45;
const double kSeabedDepth = 4.;

// Orientation of a camera on the default mount (optical axis along the vehicle's x, image x along its y)
// and of the target at home (facing south): both have X east, Y down, Z north when level and heading north.
vpRotationMatrix forwardMount()
{
  vpRotationMatrix R;
  R[0][0] = 0.;
  R[0][1] = 0.;
  R[0][2] = 1.;
  R[1][0] = 1.;
  R[1][1] = 0.;
  R[1][2] = 0.;
  R[2][0] = 0.;
  R[2][1] = 1.;
  R[2][2] = 0.;
  return R;
}

double smoothstep(double a, double b, double s)
{
  const double x = std::min(1., std::max(0., (s - a) / (b - a)));
  return x * x * (3. - 2. * x);
}

// Camera at \e cam pointing at \e look, as a vehicle does by yaw and pitch (NED: pitch up is positive),
// with pointing errors and roll (rad).
vpHomogeneousMatrix cameraLookingAt(const vpTranslationVector &cam, const vpTranslationVector &look, double yawError,
                                    double pitchError, double roll)
{
  const vpTranslationVector d = look - cam;
  const double yaw = std::atan2(d[1], d[0]);
  const double pitch = std::atan2(-d[2], std::hypot(d[0], d[1]));
  const vpRotationMatrix wRv(vpRzyxVector(yaw + yawError, pitch + pitchError, roll));
  return vpHomogeneousMatrix(cam, wRv * forwardMount());
}

// Camera at exactly \e range from \e target, in the direction of \e offset (NED, from the target).
vpTranslationVector atRange(const vpTranslationVector &target, vpTranslationVector offset, double range)
{
  return target + offset * (range / offset.frobeniusNorm());
}

// Direction from the target towards a camera south of it at azimuth alpha (towards east) and elevation beta.
vpTranslationVector bearing(double alpha, double beta)
{
  return vpTranslationVector(-std::cos(beta) * std::cos(alpha), std::cos(beta) * std::sin(alpha), -std::sin(beta));
}

// Offset towards a camera \e east and \e up of the target's axis, the rest of \e range along the axis.
vpTranslationVector lateral(double east, double up, double range)
{
  const double along = std::sqrt(std::max(range * range - east * east - up * up, 0.09));
  return vpTranslationVector(-along, east, -up);
}
} // namespace

vpSSLScenario::vpSSLScenario() : vpSSLScenario("approach") {}

vpSSLScenario::vpSSLScenario(const std::string &name)
    : m_name(name), m_nbFrames(100), m_fps(10.), m_startRange(0.), m_endRange(0.), m_targetDepth(kTargetDepth),
      m_seabedDepth(kSeabedDepth), m_seed(0), m_vMc(getDefaultCameraToVehicle()), m_odometry()
{
  const ScenarioInfo &info = findScenario(name);
  m_startRange = info.startRange;
  m_endRange = info.endRange;
  if (name == "reflection") {
    m_targetDepth = kReflectionTargetDepth;
  }
}

std::vector<std::string> vpSSLScenario::getNames()
{
  std::vector<std::string> names;
  for (const ScenarioInfo &s : kScenarios) {
    names.push_back(s.name);
  }
  return names;
}

std::string vpSSLScenario::getDescription(const std::string &name)
{
  return findScenario(name).description;
}

vpHomogeneousMatrix vpSSLScenario::getDefaultCameraToVehicle()
{
  return vpHomogeneousMatrix(vpTranslationVector(0.5, 0., 0.), forwardMount());
}

vpPlane vpSSLScenario::surfaceInTarget(const vpHomogeneousMatrix &wMo)
{
  // World plane n_w . X_w = 0 with n_w = (0, 0, -1) (up, NED); X_w = wRo X_o + wto.
  const double nw[3] = {0., 0., -1.};
  double n[3];
  for (unsigned int c = 0; c < 3; ++c) {
    n[c] = wMo[0][c] * nw[0] + wMo[1][c] * nw[1] + wMo[2][c] * nw[2];
  }
  const double D = nw[0] * wMo[0][3] + nw[1] * wMo[1][3] + nw[2] * wMo[2][3];
  return vpPlane(n[0], n[1], n[2], D);
}

void vpSSLScenario::setFrames(unsigned int n, double fps)
{
  if (n == 0 || !(fps > 0. && std::isfinite(fps))) {
    throw vpException(vpException::badValue, "vpSSLScenario: %u frames at %g fps: need at least one frame and fps > 0",
                      n, fps);
  }
  m_nbFrames = n;
  m_fps = fps;
}

void vpSSLScenario::setRanges(double startRange, double endRange)
{
  // Closer than 0.3 m the camera's nose would touch the sheet.
  if (!(startRange > 0.3 && endRange > 0.3 && std::isfinite(startRange + endRange))) {
    throw vpException(vpException::badValue, "vpSSLScenario: ranges %g and %g m must be > 0.3 m", startRange, endRange);
  }
  m_startRange = startRange;
  m_endRange = endRange;
}

vpHomogeneousMatrix vpSSLScenario::getTargetHome() const
{
  return vpHomogeneousMatrix(vpTranslationVector(0., 0., m_targetDepth), forwardMount());
}

void vpSSLScenario::poses(double s, vpHomogeneousMatrix &wMc, vpHomogeneousMatrix &wMo) const
{
  const double twoPi = 2. * M_PI;
  const double r = m_startRange + (m_endRange - m_startRange) * s;
  wMo = getTargetHome();
  const vpTranslationVector home = wMo.getTranslationVector();
  if (m_name == "approach") {
    const vpTranslationVector cam = atRange(
        home, bearing(vpMath::rad(4.) * std::sin(twoPi * 1.5 * s), vpMath::rad(3.) * std::sin(twoPi * s + 1.)), r);
    wMc =
        cameraLookingAt(cam, home, vpMath::rad(2.) * std::sin(twoPi * 0.8 * s + 0.3),
                        vpMath::rad(1.5) * std::sin(twoPi * 1.1 * s + 2.), vpMath::rad(2.) * std::sin(twoPi * 0.6 * s));
  } else if (m_name == "orbit") {
    const vpTranslationVector cam =
        atRange(home, bearing(vpMath::rad(-60. + 120. * s), vpMath::rad(5.) * std::sin(twoPi * s)), r);
    wMc = cameraLookingAt(cam, home, vpMath::rad(1.) * std::sin(twoPi * 1.3 * s), vpMath::rad(1.) * std::sin(twoPi * s),
                          vpMath::rad(1.5) * std::sin(twoPi * 0.7 * s + 1.));
  } else if (m_name == "spiral") {
    const double radius = 1.0 - 0.8 * s, height = 1.2 * (1. - s), phase = twoPi * 1.5 * s;
    const vpTranslationVector cam =
        atRange(home, lateral(radius * std::cos(phase), height + radius * std::sin(phase), r), r);
    wMc = cameraLookingAt(cam, home, vpMath::rad(2.) * std::sin(twoPi * 0.9 * s),
                          vpMath::rad(1.5) * std::sin(twoPi * 1.2 * s + 1.), vpMath::rad(3.) * std::sin(twoPi * s));
  } else if (m_name == "leave-return") {
    const vpTranslationVector cam = atRange(home, bearing(vpMath::rad(3.) * std::sin(twoPi * s), vpMath::rad(2.)), r);
    const double away = vpMath::rad(80.) * (smoothstep(0.15, 0.35, s) - smoothstep(0.55, 0.75, s));
    wMc = cameraLookingAt(cam, home, away + vpMath::rad(1.) * std::sin(twoPi * 1.7 * s),
                          vpMath::rad(1.) * std::sin(twoPi * s), vpMath::rad(2.) * std::sin(twoPi * 0.8 * s));
  } else if (m_name == "left-right") {
    // Left (west, -y) first, then right, then back home, over the middle 80 % of the run; the person holding
    // it turns it to face the vehicle as it goes.
    auto excursion = [](double u) { return u < 0.1 || u > 0.9 ? 0. : std::sin(2. * M_PI * (u - 0.1) / 0.8); };
    const double e = excursion(s);
    wMo = vpHomogeneousMatrix(home + vpTranslationVector(0., -0.8 * e, 0.),
                              vpRotationMatrix(vpRzyxVector(vpMath::rad(20.) * e, 0., 0.)) * forwardMount());
    // The vehicle yaws to keep the target ahead, 4 % of the run late.
    const vpTranslationVector seen = home + vpTranslationVector(0., -0.8 * excursion(std::max(0., s - 0.04)), 0.);
    const vpTranslationVector cam =
        home + vpTranslationVector(-r, 0.05 * std::sin(twoPi * 0.5 * s), 0.03 * std::sin(twoPi * 1.5 * s));
    wMc = cameraLookingAt(cam, seen, 0., vpMath::rad(1.) * std::sin(twoPi * s), vpMath::rad(2.) * std::sin(twoPi * s));
  } else { // reflection
    // 0.15 m below the target, so that its mirror image is 0.6 + 0.45 m above the camera's horizon level.
    const vpTranslationVector cam = atRange(home, lateral(0.1 * std::sin(twoPi * s), -0.15, r), r);
    wMc = cameraLookingAt(cam, home, vpMath::rad(1.5) * std::sin(twoPi * 0.9 * s),
                          vpMath::rad(1.) * std::sin(twoPi * 1.3 * s), vpMath::rad(3.) * std::sin(twoPi * 0.7 * s));
  }
}

std::vector<vpSSLScenarioFrame> vpSSLScenario::generate() const
{
  std::vector<vpSSLScenarioFrame> frames(m_nbFrames);
  vpSSLDeadReckoning odometry = m_odometry;
  const vpHomogeneousMatrix cMv = m_vMc.inverse();
  for (unsigned int k = 0; k < m_nbFrames; ++k) {
    vpSSLScenarioFrame &f = frames[k];
    f.index = k;
    f.t = k / m_fps;
    poses(m_nbFrames > 1 ? static_cast<double>(k) / (m_nbFrames - 1) : 0., f.wMc, f.wMo);
    f.wMv = f.wMc * cMv;
    f.cMo = f.wMc.inverse() * f.wMo;
    f.oMv = k == 0 ? odometry.reset(f.wMv, m_seed) : odometry.update(f.wMv, 1. / m_fps);
    f.oMvTrue = odometry.getTrue_oMv();
    f.range = f.cMo.getTranslationVector().frobeniusNorm();
  }
  return frames;
}

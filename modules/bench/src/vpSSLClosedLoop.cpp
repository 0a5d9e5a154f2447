#include <visp3/ssl_harness/vpSSLClosedLoop.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>

#include <visp3/core/vpException.h>
#include <visp3/core/vpMath.h>
#include <visp3/core/vpRxyzVector.h>
#include <visp3/ssl_harness/vpSSLBenchMath.h>
#include <visp3/ssl_io/vpSSLCameraFile.h>
#include <visp3/ssl_servo/vpSSLServoLaw.h>
#include <visp3/ssl_sim/vpSSLScenario.h>

const std::vector<vpSSLClosedLoop::Method> &vpSSLClosedLoop::allMethods()
{
  static const std::vector<Method> methods = {Method::Ssl, Method::AprilTag, Method::Truth, Method::SslRaw,
                                              Method::AprilTagRaw};
  return methods;
}

std::string vpSSLClosedLoop::methodName(Method m)
{
  switch (m) {
  case Method::Ssl:
    return "ssl";
  case Method::AprilTag:
    return "apriltag";
  case Method::Truth:
    return "truth";
  case Method::SslRaw:
    return "ssl-raw";
  case Method::AprilTagRaw:
    return "apriltag-raw";
  }
  return "";
}

bool vpSSLClosedLoop::parseMethod(const std::string &name, Method &m)
{
  for (Method candidate : allMethods()) {
    if (methodName(candidate) == name) {
      m = candidate;
      return true;
    }
  }
  return false;
}

bool vpSSLClosedLoop::isAprilTag(Method m)
{
  return m == Method::AprilTag || m == Method::AprilTagRaw;
}

vpSSLServoInput vpSSLClosedLoop::singleFrameInput(vpSSLDetector &detector, const vpSSLPoseEstimator &estimator,
                                                  const vpCameraParameters &cam, const vpImage<unsigned char> &I)
{
  if (!detector.detect(I) || !detector.getTargetMatch().found) {
    return vpSSLServoInput::none();
  }
  const std::vector<vpSSLPoseHypothesis> hypotheses = estimator.estimate(detector, cam);
  if (hypotheses.empty()) {
    return vpSSLServoInput::none();
  }
  const vpSSLPoseHypothesis &h = hypotheses.front();
  const vpSSLTarget &target = estimator.getTarget();
  if (!h.positionOnly) {
    vpSSLServoInput in = vpSSLServoInput::fromPose(target.getPoints(), h.cMo);
    in.nbPoints = h.nbLandmarks;
    return in;
  }
  const vpSSLTargetLandmark &l = target.getLandmark(static_cast<size_t>(std::max(0, h.landmark)));
  const vpHomogeneousMatrix cMo =
      h.cMo * vpHomogeneousMatrix(vpTranslationVector(-l.x, -l.y, -l.z), vpRotationMatrix());
  vpSSLServoInput in = vpSSLServoInput::fromPose(std::vector<vpPoint>(1, vpPoint(l.x, l.y, l.z)), cMo);
  in.hasPose = false; // the orientation is a placeholder
  in.nbPoints = h.nbLandmarks;
  return in;
}

vpCameraParameters vpSSLClosedLoop::scaledCamera(unsigned int width, unsigned int height)
{
  unsigned int w0 = 0, h0 = 0;
  const vpCameraParameters cam0 =
      vpSSLCameraFile::load(std::string(VISP_SSL_DATA_DIR) + "/camera/camera-640x480.xml", "Camera", &w0, &h0);
  const double sx = static_cast<double>(width) / w0, sy = static_cast<double>(height) / h0;
  vpCameraParameters cam;
  cam.initPersProjWithoutDistortion(cam0.get_px() * sx, cam0.get_py() * sy, cam0.get_u0() * sx, cam0.get_v0() * sy);
  return cam;
}

vpSSLClosedLoop::Scene vpSSLClosedLoop::paperScene(const std::string &scenario, double duration)
{
  Scene s;
  const bool field = scenario == "field";
  s.water = field ? "coastal" : "clear";
  s.standOff = field ? 1.5 : 2.0;
  s.wMoHome = vpSSLScenario("approach").getTargetHome();
  const vpTranslationVector tHome = s.wMoHome.getTranslationVector();
  // In coastal water (4 m visibility) the target can only be seen from about 3 m.
  const double back = field ? 3.0 : 4.5;
  s.wMvStart = vpHomogeneousMatrix(vpTranslationVector(tHome[0] - back, tHome[1] + 0.3, tHome[2] + 0.2),
                                   vpRotationMatrix(vpRxyzVector(0., 0., 0.17)));
  if (scenario == "fig9") {
    s.autoDockHold = std::min(10., 0.1 * duration); // dock after holding the stand-off
  }
  s.scenario = scenario == "fig7" ? "fig7" : scenario == "fig8" ? "fig8" : field ? "field" : "";
  s.duration = duration;
  return s;
}

double vpSSLClosedLoop::standOffRms(const std::vector<Row> &rows, double standOff, size_t &n)
{
  double sum = 0.;
  n = 0;
  bool settled = false;
  for (const Row &r : rows) {
    settled = settled || (r.state == SSL_HOMING_HOME && std::fabs(r.trueRange - standOff) < 0.1);
    if (settled && r.state == SSL_HOMING_HOME && std::isfinite(r.trueRange)) {
      sum += (r.trueRange - standOff) * (r.trueRange - standOff);
      ++n;
    }
  }
  return n ? std::sqrt(sum / n) : std::numeric_limits<double>::quiet_NaN();
}

void vpSSLClosedLoop::writeRows(const std::string &path, const std::vector<Row> &rows)
{
  std::ofstream csv(path);
  if (!csv) {
    throw vpException(vpException::ioError, "%s: cannot write", path.c_str());
  }
  auto num = [](double x, int digits) { return vpSSLBenchMath::csvNumber(x, digits); };
  csv << "t,state,nb_points,est_range,true_range,yaw_rate_demand,yaw_rate,heading_deg,depth,lateral,target_y,"
         "collision,y_rel_est,y_rel_true\n";
  for (const Row &r : rows) {
    csv << num(r.t, 2) << ',' << vpSSLHomingBehaviour::getStateName(r.state) << ',' << num(r.nbPoints, 0) << ','
        << num(r.estRange, 4) << ',' << num(r.trueRange, 4) << ',' << num(r.yawDemand, 4) << ',' << num(r.yawRate, 4)
        << ',' << num(r.heading, 2) << ',' << num(r.depth, 4) << ',' << num(r.lateral, 4) << ',' << num(r.targetY, 4)
        << ',' << num(r.collision, 0) << ',' << num(r.yRelEst, 4) << ',' << num(r.yRelTrue, 4) << '\n';
  }
  csv.close();
  if (!csv) {
    throw vpException(vpException::ioError, "%s: write failed", path.c_str());
  }
}

vpSSLClosedLoop::vpSSLClosedLoop(const Scene &scene, Method method, const vpCameraParameters &cam, unsigned int width,
                                 unsigned int height, unsigned int supersampling, long seed)
    : m_scene(scene), m_method(method), m_cam(cam), m_width(width), m_height(height), m_seed(seed),
      m_water(vpSSLWaterModel::preset(scene.water)), m_renderer(cam, width, height), m_sheet(vpSSLAprilTagSheet::a3(0)),
      m_target(vpSSLTarget::ssl3a3()), m_tracker(m_target, cam, m_auv.getCameraToVehicle()), m_tagFinder(m_sheet, cam),
      m_tagFusion(m_sheet.getTagSize(), cam, m_auv.getCameraToVehicle()), m_rawDetector(m_target),
      m_rawEstimator(m_target)
{
  m_auv.setTimeStep(scene.timeStep);
  m_auv.setTargetPose(scene.wMoHome);
  m_auv.reset(scene.wMvStart, seed);
  m_auv.setCurrent(scene.current);

  m_homing.getServoLaw().setCameraToVehicle(m_auv.getCameraToVehicle());
  m_homing.setStandOff(scene.standOff);
  if (scene.autoDockHold >= 0.) {
    m_homing.setAutoDock(scene.autoDockHold, scene.autoDockRange, vpMath::rad(scene.autoDockAngle));
  }
  // The 0.3 m ssl3-a3 pattern overflows the image within about 1.2 m (0.6 m for the behaviour's default): from
  // there the approach is blind, holding the last surge.
  m_homing.setBlindDock(scene.blindDockRange, scene.blindDockSpeed);
  m_homing.setRangeIntegralGain(scene.rangeIntegralGain);
  m_homing.setDockInTransit(scene.dockInTransit);

  m_renderer.setSupersampling(supersampling);
  if (isAprilTag(method)) {
    m_renderer.setAprilTagSheet(m_sheet);
  } else {
    m_renderer.setTarget(m_target);
  }
  // Nothing is left of the direct signal beyond a 1e5 attenuation: stop the rays there (as
  // tutorial-ssl-simulate-sequence).
  const std::array<double, 3> &betaD = m_water.getAttenuation();
  const double clearest = std::min({betaD[0], betaD[1], betaD[2]});
  if (clearest > 0.) {
    m_renderer.setMaxRange(std::log(1e5) / clearest);
  }
  // The renderer takes the pose of the tag frame for an AprilTag sheet; the simulator the sheet frame.
  m_sMo = isAprilTag(method) ? vpSSLAprilTagSheet::getSheetToTag() : vpHomogeneousMatrix();
  m_tracker.setSeed(seed);
  m_tagFusion.setSeed(seed);
  m_rawDetector.setSmallLandmarkMode(true);
  for (const vpSSLTargetLandmark &l : m_target.getLandmarks()) {
    m_truthPoints.emplace_back(l.x, l.y, l.z);
  }
}

bool vpSSLClosedLoop::tagWindow(const vpSSLServoInput &fused, vpRect &window) const
{
  if (!fused.valid || fused.points.size() != 4) {
    return false;
  }
  double uMin = std::numeric_limits<double>::infinity(), vMin = uMin, uMax = -uMin, vMax = -uMin;
  for (const vpSSLServoPoint &p : fused.points) {
    const double u = m_cam.get_u0() + m_cam.get_px() * p.x, v = m_cam.get_v0() + m_cam.get_py() * p.y;
    if (!std::isfinite(u) || !std::isfinite(v) || !(p.Z > 0.)) {
      return false;
    }
    uMin = std::min(uMin, u);
    uMax = std::max(uMax, u);
    vMin = std::min(vMin, v);
    vMax = std::max(vMax, v);
  }
  const double margin = 0.5 * std::max(uMax - uMin, vMax - vMin) + 48.;
  if (uMax + margin < 0. || vMax + margin < 0. || uMin - margin > m_width || vMin - margin > m_height) {
    return false;
  }
  window = vpRect(vpImagePoint(vMin - margin, uMin - margin), vpImagePoint(vMax + margin, uMax + margin));
  return true;
}

vpSSLClosedLoop::Row vpSSLClosedLoop::step(int k)
{
  const double t = m_auv.getTime();
  stepEvents(t);

  // The camera image at the true pose (open water when the target is out).
  const vpHomogeneousMatrix cMo = m_auv.get_cMo();
  const vpHomogeneousMatrix wMo = m_auv.getTargetPose();
  if (m_method == Method::Truth) {
    // no image needed
  } else if (m_auv.isTargetInWater()) {
    m_renderer.setWaterSurface(vpSSLScenario::surfaceInTarget(wMo * m_sMo));
    m_renderer.render(cMo * m_sMo, m_reflectance, m_range);
  } else {
    m_reflectance.resize(m_height, m_width, 0.f);
    m_range.resize(m_height, m_width, std::numeric_limits<float>::infinity());
  }
  if (m_method != Method::Truth) {
    m_water.apply(m_reflectance, m_range, m_cam, t, m_seed * 1000003L + k, m_I);
  }

  vpSSLServoInput input = vpSSLServoInput::none();
  if (m_method == Method::Truth) {
    if (m_auv.isTargetInWater() && m_renderer.isTargetInView(cMo)) {
      input = vpSSLServoInput::fromPose(m_truthPoints, cMo);
    }
  } else if (isAprilTag(m_method)) {
    // With the fusion the tag is read where the filter last put it, as the SSL tracker reads its landmarks, and
    // in the whole image when that window does not give it: the same detections (vpSSLAprilTagBaseline), a
    // fraction of the time.
    if (m_hasTagWindow ? m_tagFinder.detect(m_I, m_tagWindow) : m_tagFinder.detect(m_I)) {
      input =
          vpSSLServoInput::fromAprilTag(m_tagFinder.getPolygon(), m_tagFinder.getPose(), m_sheet.getTagSize(), m_cam);
    }
    if (m_method == Method::AprilTag) {
      input = m_tagFusion.track(input, m_auv.getOdometry());
      m_hasTagWindow = tagWindow(input, m_tagWindow);
    }
  } else if (m_method == Method::SslRaw) {
    input = singleFrameInput(m_rawDetector, m_rawEstimator, m_cam, m_I);
  } else {
    m_tracker.track(m_I, m_auv.getOdometry());
    input = vpSSLServoInput::fromTracker(m_tracker);
  }

  const vpColVector command =
      m_scene.stationKeeping || m_scene.dockInTransit
          ? m_homing.update(t, input, m_auv.getDepthMeasurement(), m_auv.getCollision(), m_auv.getOdometry())
          : m_homing.update(t, input, m_auv.getDepthMeasurement(), m_auv.getCollision());
  Row r;
  r.t = t;
  r.state = m_homing.getState();
  r.seen = m_homing.getTargetSeen();
  r.nbPoints = input.valid ? input.nbPoints : 0.;
  r.estRange = m_homing.getRange();
  r.trueRange = m_auv.isTargetInWater() ? cMo[2][3] : std::numeric_limits<double>::quiet_NaN();
  r.yawDemand = command[5];
  r.yawRate = m_auv.getBodyVelocity()[5];
  r.heading = vpMath::deg(vpRxyzVector(m_auv.get_wMv().getRotationMatrix())[2]);
  r.depth = m_auv.getDepth();
  r.lateral = m_auv.get_wMv()[1][3] - wMo[1][3];
  r.targetY = wMo[1][3] - m_scene.wMoHome[1][3];
  r.collision = m_auv.getCollision() ? 1. : 0.;
  // The paper's Fig. 8 quantity: where the target centre is relative to the vehicle, as measured and truly (the
  // same object point, the mean of the measured ones, at the true pose).
  r.yRelEst = r.yRelTrue = std::numeric_limits<double>::quiet_NaN();
  double xc, yc, Zc;
  if (vpSSLServoLaw::getTargetCentre(input, xc, yc, Zc)) {
    const vpHomogeneousMatrix vMc = m_auv.getCameraToVehicle();
    r.yRelEst = (vMc * vpTranslationVector(xc * Zc, yc * Zc, Zc))[1];
    vpTranslationVector o;
    for (const vpSSLServoPoint &p : input.points) {
      o = o + vpTranslationVector(p.oX, p.oY, p.oZ) * (1. / static_cast<double>(input.points.size()));
    }
    r.yRelTrue = ((vMc * cMo) * o)[1];
  }
  return r;
}

void vpSSLClosedLoop::stepEvents(double t)
{
  const std::string &scenario = m_scene.scenario;
  const double D = m_scene.duration;
  if (scenario == "fig7") {
    m_auv.setTargetInWater(!(t >= 0.47 * D && t < 0.75 * D));
  } else if (scenario == "fig8") {
    // Moved 0.6 m to port (west, -y) at 0.3 D, then 0.6 m to starboard of home at 0.6 D.
    const double dy = t < 0.3 * D ? 0. : t < 0.6 * D ? -0.6 : 0.6;
    vpHomogeneousMatrix wMo = m_scene.wMoHome;
    wMo[1][3] += dy;
    m_auv.setTargetPose(wMo);
  } else if (scenario == "field") {
    // Swaying on its line: 0.25 m, 12 s period, with a little yaw.
    const double s = std::sin(2. * M_PI * t / 12.);
    vpHomogeneousMatrix wMo = m_scene.wMoHome * vpHomogeneousMatrix(vpTranslationVector(0.25 * s, 0., 0.),
                                                                    vpRotationMatrix(vpRxyzVector(0., 0.1 * s, 0.)));
    m_auv.setTargetPose(wMo);
  }
}

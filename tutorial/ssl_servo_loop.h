/*!
  \file ssl_servo_loop.h
  \brief Tutorial-local closed loop of tutorial-ssl-servo and tutorial-ssl-servo-monte-carlo: the scene (vehicle,
  target, water, behaviour), and one control step (scenario events, rendering, detection, servo input,
  behaviour update, logged row). Header-only.
*/
#ifndef SSL_SERVO_LOOP_H
#define SSL_SERVO_LOOP_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpException.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpMath.h>
#include <visp3/core/vpPoint.h>
#include <visp3/core/vpRxyzVector.h>
#include <visp3/core/vpThetaUVector.h>
#include <visp3/core/vpTranslationVector.h>
#include <visp3/ssl/vpSSLAprilTagBaseline.h>
#include <visp3/ssl/vpSSLAprilTagSheet.h>
#include <visp3/ssl/vpSSLAuvSimulator.h>
#include <visp3/ssl/vpSSLBenchMath.h>
#include <visp3/ssl/vpSSLCameraFile.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl/vpSSLHomingBehaviour.h>
#include <visp3/ssl/vpSSLParticleFilter.h>
#include <visp3/ssl/vpSSLPoseEstimator.h>
#include <visp3/ssl/vpSSLRenderer.h>
#include <visp3/ssl/vpSSLScenario.h>
#include <visp3/ssl/vpSSLServoInput.h>
#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/ssl/vpSSLTracker.h>
#include <visp3/ssl/vpSSLWaterModel.h>

#include "ssl_tutorial_common.h"

namespace sslservo {

//! A bad command line: the tutorials print its message on one line and exit with status 2.
struct UsageError
{
  std::string message;
};

//! The finite number \e text, value of option \e name. \exception UsageError otherwise.
inline double parseDouble(const std::string &name, const std::string &text)
{
  char *end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v)) {
    throw UsageError{name + ": not a number: \"" + text + "\""};
  }
  return v;
}

//! The integer \e text in [minimum, maximum], value of option \e name. \exception UsageError otherwise.
inline long parseInteger(const std::string &name, const std::string &text, long minimum, long maximum)
{
  // The tutorials' one integer parser (ssl_tutorial_common.h), with this header's error type.
  try {
    return static_cast<long>(ssltut::parseInteger(name, text, minimum, maximum));
  } catch (const ssltut::UsageError &e) {
    throw UsageError{e.what()};
  }
}

//! How the target is found at each step. The fused methods run the same particle filter (vpSSLParticleFilter) with
//! the same odometry and keep servoing on its prediction when the target is lost; the raw ones give the single-frame
//! pose of each image and nothing when it shows no target.
enum class Method
{
  Ssl,         ///< vpSSLTracker (detector, single-frame pose, particle filter with odometry) on the ssl3-a3 sheet.
  AprilTag,    ///< The AprilTag baseline (36h11) on the tag sheet, its corners and pose fed to the same filter.
  Truth,       ///< Perfect sensor: the ssl3-a3 landmarks projected at the true pose when in view (no image).
  SslRaw,      ///< vpSSLDetector and vpSSLPoseEstimator alone: the best single-frame pose of each image.
  AprilTagRaw, ///< The AprilTag baseline alone: the tag's corners and pose of each image.
};

//! Every method, in the order of methodName()'s names.
inline const std::vector<Method> &allMethods()
{
  static const std::vector<Method> methods = {Method::Ssl, Method::AprilTag, Method::Truth, Method::SslRaw,
                                              Method::AprilTagRaw};
  return methods;
}

//! "ssl", "apriltag", "truth", "ssl-raw", "apriltag-raw".
inline std::string methodName(Method m)
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

//! \e name as a Method; false when it is none of methodName()'s names.
inline bool parseMethod(const std::string &name, Method &m)
{
  for (Method candidate : allMethods()) {
    if (methodName(candidate) == name) {
      m = candidate;
      return true;
    }
  }
  return false;
}

//! Whether \e m shows the AprilTag sheet (rendered instead of ssl3-a3).
inline bool isAprilTag(Method m)
{
  return m == Method::AprilTag || m == Method::AprilTagRaw;
}

/*!
  The fusion the SSL tracker gives its detections, for the AprilTag baseline: the same particle filter
  (vpSSLParticleFilter with its defaults, as vpSSLTracker) over a target made of the tag's four corners,
  predicted with the vehicle's odometry at each image, updated with the detected corners and re-initialised
  from the tag's pose (vpSSLTracker's paper Sec. 3.3 scheme); the tag's pose is the input when the filter agrees
  with it. While the tag is not seen the prediction stays the input (nbPoints 0) for as many images as
  vpSSLTracker's default setMaxLostFrames() (5), then nothing.
*/
class AprilTagFusion
{
public:
  AprilTagFusion(double tagSize, const vpCameraParameters &cam, const vpHomogeneousMatrix &vMc)
      : m_target(cornerTarget(tagSize)), m_filter(m_target, cam), m_cam(cam), m_cMv(vMc.inverse())
  {
  }

  void setSeed(long seed) { m_filter.setSeed(seed); } //!< Seed of the filter's particles.

  /*!
    One image: \e detection is vpSSLServoInput::fromAprilTag() of the tag (or none()), \e oMv the odometry.
    \return the fused input: measured corners where seen, the filter's pose and projected corners otherwise.
  */
  vpSSLServoInput track(const vpSSLServoInput &detection, const vpHomogeneousMatrix &oMv)
  {
    bool finite = true;
    for (unsigned int i = 0; i < 3; ++i) {
      for (unsigned int j = 0; j < 4; ++j) {
        finite = finite && std::isfinite(oMv[i][j]);
      }
    }
    if (m_active) {
      if (m_hasOdometry && finite) {
        m_filter.predict(m_oMvPrevious.inverse() * oMv, m_cMv); // v1Mv2, as vpSSLTracker::track()
      } else {
        m_filter.predict();
      }
    }
    if (finite) {
      m_oMvPrevious = oMv;
      m_hasOdometry = true;
    }
    const bool seen = detection.valid && detection.points.size() == 4;
    if (seen) {
      std::vector<vpSSLObservation> observations;
      for (size_t k = 0; k < 4; ++k) {
        vpSSLObservation o; // radius unknown (0): the filter weighs the corner positions only
        o.label = static_cast<int>(k);
        o.u = m_cam.get_u0() + m_cam.get_px() * detection.points[k].x;
        o.v = m_cam.get_v0() + m_cam.get_py() * detection.points[k].y;
        observations.push_back(o);
      }
      vpSSLPoseHypothesis h;
      h.cMo = detection.cMo;
      h.nbLandmarks = 4;
      const std::vector<vpSSLPoseHypothesis> hypotheses(1, h);
      if (!m_active) {
        m_filter.init(hypotheses);
        m_filter.update(observations);
        m_active = true;
      } else {
        m_filter.update(observations, hypotheses);
      }
      m_lostInRow = 0;
    } else if (m_active && ++m_lostInRow > 5) {
      m_active = false;
    }
    if (!m_active) {
      return vpSSLServoInput::none();
    }
    // As vpSSLTracker's pose: the image's pose when it lies within the filter's uncertainty (its default gate:
    // 3 sigmas plus 10 % of the range, 3 sigmas plus 30 deg), the filter's mean otherwise.
    const vpHomogeneousMatrix mean = m_filter.getMeanPose();
    if (seen) {
      const vpMatrix C = m_filter.getCovariance();
      const double sigmaT = std::sqrt(std::max(0., C[0][0] + C[1][1] + C[2][2]));
      const double sigmaR = std::sqrt(std::max(0., C[3][3] + C[4][4] + C[5][5]));
      const vpTranslationVector tMean = mean.getTranslationVector();
      const double distance = (detection.cMo.getTranslationVector() - tMean).frobeniusNorm();
      const vpThetaUVector tu(mean.getRotationMatrix().t() * detection.cMo.getRotationMatrix());
      if (distance <= 3. * sigmaT + 0.1 * tMean.frobeniusNorm() &&
          std::sqrt(tu.sumSquare()) <= 3. * sigmaR + vpMath::rad(30.)) {
        return detection;
      }
    }
    vpSSLServoInput in = vpSSLServoInput::fromPose(m_target.getPoints(), mean);
    if (seen) {
      for (size_t k = 0; k < 4; ++k) {
        in.points[k].x = detection.points[k].x;
        in.points[k].y = detection.points[k].y;
      }
    }
    in.nbPoints = seen ? 4 : 0;
    return in;
  }

private:
  // The corners in vpSSLServoInput::fromAprilTag()'s order and frame (X right, Y down, Z into the sheet).
  static vpSSLTarget cornerTarget(double tagSize)
  {
    vpSSLTarget t;
    const double h = tagSize / 2.;
    const double corners[4][2] = {{-h, -h}, {h, -h}, {h, h}, {-h, h}};
    for (int k = 0; k < 4; ++k) {
      vpSSLTargetLandmark l;
      l.name = "C" + std::to_string(k);
      l.x = corners[k][0];
      l.y = corners[k][1];
      l.radius = vpSSLTarget::minRadius();
      t.addLandmark(l);
    }
    return t;
  }

  vpSSLTarget m_target;
  vpSSLParticleFilter m_filter;
  vpCameraParameters m_cam;
  vpHomogeneousMatrix m_cMv, m_oMvPrevious;
  bool m_active = false, m_hasOdometry = false;
  unsigned int m_lostInRow = 0;
};

/*!
  The SSL detections without fusion: the best single-frame pose of vpSSLPoseEstimator (small-landmark mode, which
  finds the large landmarks too), as the target's landmarks at that pose; a position-only pose (one or two
  landmarks) gives the landmark it places. \return none() when the image shows no target.
*/
inline vpSSLServoInput singleFrameInput(vpSSLDetector &detector, const vpSSLPoseEstimator &estimator,
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

//! The camera of the paper's vehicle (data/camera/camera-640x480.xml) scaled to \e width x \e height (same field of
//! view). Reads a file: call it once, before any thread starts.
inline vpCameraParameters scaledCamera(unsigned int width, unsigned int height)
{
  unsigned int w0 = 0, h0 = 0;
  const vpCameraParameters cam0 =
      vpSSLCameraFile::load(std::string(VISP_SSL_DATA_DIR) + "/camera/camera-640x480.xml", "Camera", &w0, &h0);
  const double sx = static_cast<double>(width) / w0, sy = static_cast<double>(height) / h0;
  vpCameraParameters cam;
  cam.initPersProjWithoutDistortion(cam0.get_px() * sx, cam0.get_py() * sy, cam0.get_u0() * sx, cam0.get_v0() * sy);
  return cam;
}

//! Everything that is fixed for one run: the water, the target, the vehicle's start, the current and the behaviour.
struct Scene
{
  std::string water = "clear";  //!< vpSSLWaterModel preset.
  vpHomogeneousMatrix wMoHome;  //!< Target (sheet frame) pose at the start.
  vpHomogeneousMatrix wMvStart; //!< Vehicle pose at the start.
  vpTranslationVector current;  //!< Constant water current (world frame, m/s).
  double standOff = 2.;         //!< Stand-off held in HOME (m).
  double autoDockHold = -1.;    //!< Auto dock after this long at the stand-off (s); < 0: never.
  double autoDockRange = 0.1;   //!< Range tolerance of the auto-dock hold (m), see setAutoDock().
  double autoDockAngle = 5.;    //!< Centring tolerance of the auto-dock hold (deg), see setAutoDock().
  double blindDockRange = 1.3;  //!< See vpSSLHomingBehaviour::setBlindDock().
  double blindDockSpeed = 0.15; //!< See vpSSLHomingBehaviour::setBlindDock().
  double timeStep = 0.2;        //!< Control period (s): vision at 5 Hz, dynamics sub-stepped inside.
  std::string scenario;         //!< tutorial-ssl-servo scenario whose events apply (stepEvents()), "" none.
  double duration = 0.;         //!< Scenario duration (s), for the event times.
};

/*!
  The scenes of tutorial-ssl-servo (paper Sec. 5): fig7, fig8, fig9 (docking), field (coastal, swaying target), all
  from 4.5 m south of the target (camera 3.9 m from it; field 3 m, camera 2.4 m), 0.3 m off its axis, 10 degrees
  off its heading, 0.2 m below it.
*/
inline Scene paperScene(const std::string &scenario, double duration)
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

//! One logged control step.
struct Row
{
  double t, nbPoints, estRange, trueRange, yawDemand, yawRate, heading, depth, lateral, targetY, collision;
  double yRelEst, yRelTrue; //!< Target centre's y (starboard) in the vehicle frame: measured, and true (m).
  vpSSLHomingState state;
  bool seen; //!< The behaviour saw the target at this step (vpSSLHomingBehaviour::getTargetSeen()).
};

/*!
  Stand-off RMS error (m) over the HOME steps (true range) once settled, i.e. after the range first came within
  0.1 m of the stand-off (the approach from the start is not an error); NaN when no step qualifies. \e n gets the
  number of steps.
*/
inline double standOffRms(const std::vector<Row> &rows, double standOff, size_t &n)
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

//! Writes \e rows as the CSV of tutorial-ssl-servo (header included). \exception vpException if it cannot write.
inline void writeRows(const std::string &path, const std::vector<Row> &rows)
{
  std::ofstream csv(path);
  if (!csv) {
    throw vpException(vpException::ioError, "%s: cannot write", path.c_str());
  }
  auto num = [](double x, int digits) { return std::isfinite(x) ? vpSSLBenchMath::fmt(x, digits) : std::string(); };
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

/*!
  The closed loop of one run: the simulated AUV, the renderer and water model, the detector of the method and the
  homing behaviour, each its own instance (two ClosedLoop objects share nothing, so they may run in two threads).

  \code
  sslservo::ClosedLoop loop(scene, sslservo::Method::Ssl, cam, 640, 480, 1, seed);
  for (int k = 0; k <= nbSteps; ++k) {
    const sslservo::Row r = loop.step(k); // events, image, detection, behaviour update
    loop.apply();                         // the command drives the vehicle for one time step
  }
  \endcode
*/
class ClosedLoop
{
public:
  ClosedLoop(const Scene &scene, Method method, const vpCameraParameters &cam, unsigned int width, unsigned int height,
             unsigned int supersampling, long seed)
      : m_scene(scene), m_method(method), m_cam(cam), m_width(width), m_height(height), m_seed(seed),
        m_water(vpSSLWaterModel::preset(scene.water)), m_renderer(cam, width, height),
        m_sheet(vpSSLAprilTagSheet::a3(0)), m_target(vpSSLTarget::ssl3a3()),
        m_tracker(m_target, cam, m_auv.getCameraToVehicle()), m_tagFinder(m_sheet, cam),
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

  vpSSLAuvSimulator &getAuv() { return m_auv; }                  //!< The vehicle.
  vpSSLHomingBehaviour &getHoming() { return m_homing; }         //!< The behaviour.
  const Scene &getScene() const { return m_scene; }              //!< The scene.
  const vpImage<unsigned char> &getImage() const { return m_I; } //!< Last camera image (not with Method::Truth).

  /*!
    Control step \e k (time getAuv().getTime()): the scenario's events, the camera image at the true pose, the
    detection, the behaviour's update. The vehicle does not move: apply() sends the command.
  */
  Row step(int k)
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
      if (m_tagFinder.detect(m_I)) {
        vpDetectorAprilTag &det = m_tagFinder.getDetector();
        const std::vector<int> ids = det.getTagsId();
        for (size_t i = 0; i < ids.size(); ++i) {
          if (ids[i] == m_sheet.getId()) {
            input =
                vpSSLServoInput::fromAprilTag(det.getPolygon(i), m_tagFinder.getPose(), m_sheet.getTagSize(), m_cam);
            break;
          }
        }
      }
      if (m_method == Method::AprilTag) {
        input = m_tagFusion.track(input, m_auv.getOdometry());
      }
    } else if (m_method == Method::SslRaw) {
      input = singleFrameInput(m_rawDetector, m_rawEstimator, m_cam, m_I);
    } else {
      m_tracker.track(m_I, m_auv.getOdometry());
      input = vpSSLServoInput::fromTracker(m_tracker);
    }

    const vpColVector command = m_homing.update(t, input, m_auv.getDepthMeasurement(), m_auv.getCollision());
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

  //! Sends the behaviour's last command to the vehicle: getScene().timeStep seconds of dynamics.
  void apply() { m_homing.apply(m_auv); }

private:
  //! The tutorial-ssl-servo scenario's events at time \e t: the target taken out and put back, moved, swaying.
  void stepEvents(double t)
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

  Scene m_scene;
  Method m_method;
  vpCameraParameters m_cam;
  unsigned int m_width, m_height;
  long m_seed;
  vpSSLAuvSimulator m_auv;
  vpSSLHomingBehaviour m_homing;
  vpSSLWaterModel m_water;
  vpSSLRenderer m_renderer;
  vpSSLAprilTagSheet m_sheet;
  vpSSLTarget m_target; // kept alive: the tracker and the truth points refer to its landmarks
  vpSSLTracker m_tracker;
  vpSSLAprilTagBaseline m_tagFinder;
  AprilTagFusion m_tagFusion;
  vpSSLDetector m_rawDetector;
  vpSSLPoseEstimator m_rawEstimator;
  vpHomogeneousMatrix m_sMo;
  std::vector<vpPoint> m_truthPoints;
  vpImage<float> m_reflectance, m_range;
  vpImage<unsigned char> m_I;
};

} // namespace sslservo

#endif

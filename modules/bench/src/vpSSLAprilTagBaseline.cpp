#include <visp3/ssl_harness/vpSSLAprilTagBaseline.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include <visp3/core/vpException.h>
#include <visp3/core/vpImageTools.h>
#include <visp3/core/vpIoTools.h>
#include <visp3/core/vpPoseVector.h>
#include <visp3/ssl_harness/vpSSLBenchMath.h>
#include <visp3/ssl_io/vpSSLImageIo.h>

vpSSLAprilTagBaseline::vpSSLAprilTagBaseline(const vpSSLAprilTagSheet &sheet, const vpCameraParameters &cam)
    : m_detector(vpDetectorAprilTag::TAG_36h11), m_id(sheet.getId()), m_tagSize(sheet.getTagSize()), m_cam(cam),
      m_found(false), m_nbOthers(0)
{
  m_detector.setAprilTagQuadDecimate(1.f);
  m_detector.setAprilTagNbThreads(1);
  m_detector.setAprilTagRefineEdges(true);
  m_detector.setAprilTagPoseEstimationMethod(vpDetectorAprilTag::HOMOGRAPHY_VIRTUAL_VS);
}

void vpSSLAprilTagBaseline::setQuadDecimate(float d)
{
  m_detector.setAprilTagQuadDecimate(d);
}

bool vpSSLAprilTagBaseline::detect(const vpImage<unsigned char> &I)
{
  m_usedWindow = false;
  m_detector.detect(I);
  collect(vpImagePoint(0., 0.), m_cam);
  return m_found;
}

bool vpSSLAprilTagBaseline::detect(const vpImage<unsigned char> &I, const vpRect &window)
{
  // AprilTag thresholds each pixel against the extremes of its 4x4 tile and the 8 tiles around it: a window
  // on the tile grid, two tiles wider than asked, thresholds the pixels near the tag as the whole image does.
  const int tile = 4;
  const int w = static_cast<int>(I.getWidth()), h = static_cast<int>(I.getHeight());
  auto snapDown = [&](double x, int limit) {
    if (!std::isfinite(x))
      return 0;
    const double v = std::floor(std::max(0., std::min(x, static_cast<double>(limit))) / tile) * tile - 2 * tile;
    return std::max(0, static_cast<int>(v));
  };
  auto snapUp = [&](double x, int limit) {
    if (!std::isfinite(x))
      return limit;
    const double v = std::ceil(std::max(0., std::min(x, static_cast<double>(limit))) / tile) * tile + 2 * tile;
    return std::min(limit, static_cast<int>(v));
  };
  const int left = snapDown(window.getLeft(), w), top = snapDown(window.getTop(), h);
  const int right = snapUp(window.getRight() + 1., w), bottom = snapUp(window.getBottom() + 1., h);
  if (right - left >= w && bottom - top >= h) {
    return detect(I); // the window is the image
  }
  if (right - left > 4 * tile && bottom - top > 4 * tile) {
    vpImageTools::crop(I, top, left, static_cast<unsigned int>(bottom - top), static_cast<unsigned int>(right - left),
                       m_window);
    vpCameraParameters cam = m_cam;
    if (m_cam.get_projModel() == vpCameraParameters::perspectiveProjWithDistortion) {
      cam.initPersProjWithDistortion(m_cam.get_px(), m_cam.get_py(), m_cam.get_u0() - left, m_cam.get_v0() - top,
                                     m_cam.get_kud(), m_cam.get_kdu());
    } else {
      cam.initPersProjWithoutDistortion(m_cam.get_px(), m_cam.get_py(), m_cam.get_u0() - left, m_cam.get_v0() - top);
    }
    m_detector.detect(m_window);
    collect(vpImagePoint(top, left), cam);
    bool inside = m_found;
    const double m = getWindowMargin();
    for (const vpImagePoint &p : m_polygon) {
      inside = inside && (left == 0 || p.get_u() >= left + m) && (top == 0 || p.get_v() >= top + m) &&
               (right == w || p.get_u() <= right - 1 - m) && (bottom == h || p.get_v() <= bottom - 1 - m);
    }
    if (inside) {
      m_usedWindow = true;
      return true;
    }
  }
  return detect(I);
}

void vpSSLAprilTagBaseline::collect(const vpImagePoint &offset, const vpCameraParameters &cam)
{
  m_found = false;
  m_nbOthers = 0;
  m_polygon.clear();
  const std::vector<int> ids = m_detector.getTagsId();
  for (size_t i = 0; i < ids.size(); ++i) {
    if (ids[i] != m_id || m_found) {
      ++m_nbOthers;
      continue;
    }
    m_found = true;
    m_polygon = m_detector.getPolygon(i);
    m_centre = vpImagePoint(0., 0.);
    for (vpImagePoint &q : m_polygon) {
      q += offset;
      m_centre += q * 0.25;
    }
    m_detector.getPose(i, m_tagSize, cam, m_cMo);
  }
}

std::vector<vpSSLAprilTagBaseline::BenchmarkResult> vpSSLAprilTagBaseline::runOnVispBenchmark(const std::string &dir,
                                                                                              float quadDecimate)
{
  const std::string imageName = dir + "/tag36_11_640x480.png";
  if (!vpIoTools::checkFilename(imageName))
    throw vpException(vpException::ioError, "%s: cannot read the image", imageName.c_str());
  vpImage<unsigned char> I;
  vpSSLImageIo::read(I, imageName);
  vpCameraParameters cam;
  cam.initPersProjWithoutDistortion(700., 700., 320., 240.);
  std::vector<BenchmarkResult> results;
  for (int id = 0; id < 5; ++id) {
    const std::string truthName = dir + "/cMo_" + std::to_string(id) + ".txt";
    std::ifstream file(truthName);
    if (!file)
      throw vpException(vpException::ioError, "%s: cannot read the ground-truth pose", truthName.c_str());
    vpHomogeneousMatrix truth;
    truth.load(file);
    // ViSP's test: tag size 0.25 m for the whole 10-cell tag, 8/10 of it for the black square; ids 3, 4 half.
    const double tagSize = (id < 3 ? 0.25 : 0.125) * 8. / 10.;
    vpSSLAprilTagBaseline baseline(vpSSLAprilTagSheet(id, tagSize, 2. * tagSize, 2. * tagSize), cam);
    baseline.setQuadDecimate(quadDecimate);
    BenchmarkResult r;
    if (baseline.detect(I)) {
      r.id = id;
      const vpHomogeneousMatrix &cMo = baseline.getPose();
      r.positionError = vpSSLBenchMath::positionError(cMo, truth);
      r.angleError = vpSSLBenchMath::angleError(cMo, truth);
      const vpPoseVector p(cMo), q(truth);
      double st = 0., sr = 0.;
      for (unsigned int k = 0; k < 3; ++k) {
        st += (p[k] - q[k]) * (p[k] - q[k]);
        sr += (p[k + 3] - q[k + 3]) * (p[k + 3] - q[k + 3]);
      }
      r.rmsTranslation = std::sqrt(st / 3.);
      r.rmsThetaU = std::sqrt(sr / 3.);
    }
    results.push_back(r);
  }
  return results;
}

#include <visp3/ssl_harness/vpSSLAprilTagBaseline.h>

#include <cmath>
#include <fstream>

#include <visp3/core/vpException.h>
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
  m_found = false;
  m_nbOthers = 0;
  m_detector.detect(I);
  const std::vector<int> ids = m_detector.getTagsId();
  for (size_t i = 0; i < ids.size(); ++i) {
    if (ids[i] != m_id || m_found) {
      ++m_nbOthers;
      continue;
    }
    m_found = true;
    std::vector<vpImagePoint> p = m_detector.getPolygon(i);
    m_centre = vpImagePoint(0., 0.);
    for (const vpImagePoint &q : p)
      m_centre += q * 0.25;
    m_detector.getPose(i, m_tagSize, m_cam, m_cMo);
  }
  return m_found;
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

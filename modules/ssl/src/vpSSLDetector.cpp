#include <visp3/ssl/vpSSLDetector.h>

#include <chrono>
#include <cmath>

#include <visp3/core/vpException.h>
#include <visp3/core/vpPixelMeterConversion.h>

#include "vpSSLDetectorImpl.h"

vpSSLDetector::vpSSLDetector(const vpSSLTarget &target) : vpDetectorBase(), m_impl(new Impl(target)) {}

vpSSLDetector::vpSSLDetector(const vpSSLDetector &other) : vpDetectorBase(other), m_impl(new Impl(*other.m_impl)) {}

vpSSLDetector::vpSSLDetector(vpSSLDetector &&other) noexcept = default;

vpSSLDetector &vpSSLDetector::operator=(const vpSSLDetector &other)
{
  if (this != &other) {
    vpDetectorBase::operator=(other);
    m_impl.reset(new Impl(*other.m_impl));
  }
  return *this;
}

vpSSLDetector &vpSSLDetector::operator=(vpSSLDetector &&other) noexcept = default;

vpSSLDetector::~vpSSLDetector() = default;

void vpSSLDetector::setWindow(unsigned int w)
{
  m_impl->setWindow(w);
}
void vpSSLDetector::setThreshold(double threshold)
{
  m_impl->setThreshold(threshold);
}
void vpSSLDetector::setBrightnessNormalization(bool enable)
{
  m_impl->setBrightnessNormalization(enable);
}
void vpSSLDetector::setNbThreads(unsigned int n)
{
  m_impl->setNbThreads(n);
}
void vpSSLDetector::setDecimation(unsigned int decimation)
{
  m_impl->setDecimation(decimation);
}
unsigned int vpSSLDetector::getDecimation() const
{
  return m_impl->getDecimation();
}
void vpSSLDetector::setMaxRadius(double r)
{
  m_impl->setMaxRadius(r);
}
void vpSSLDetector::setRadiusSweep(bool enable)
{
  m_impl->setRadiusSweep(enable);
}
bool vpSSLDetector::getRadiusSweep() const
{
  return m_impl->getRadiusSweep();
}
void vpSSLDetector::setSmallLandmarkMode(bool enable)
{
  m_impl->setSmallLandmarkMode(enable);
}
bool vpSSLDetector::getSmallLandmarkMode() const
{
  return m_impl->getSmallLandmarkMode();
}
void vpSSLDetector::setEqualRingCheck(bool enable)
{
  m_impl->setEqualRingCheck(enable);
}
bool vpSSLDetector::getEqualRingCheck() const
{
  return m_impl->getEqualRingCheck();
}
void vpSSLDetector::setBlurredRingModel(bool enable)
{
  m_impl->setBlurredRingModel(enable);
}
bool vpSSLDetector::getBlurredRingModel() const
{
  return m_impl->getBlurredRingModel();
}
void vpSSLDetector::setTargetCompletion(bool enable)
{
  m_impl->setTargetCompletion(enable);
}
bool vpSSLDetector::getTargetCompletion() const
{
  return m_impl->getTargetCompletion();
}
void vpSSLDetector::setAllAroundBudget(unsigned int candidates)
{
  m_impl->setAllAroundBudget(candidates);
}
unsigned int vpSSLDetector::getAllAroundBudget() const
{
  return m_impl->getAllAroundBudget();
}
void vpSSLDetector::setShortWindow(unsigned int w)
{
  m_impl->setShortWindow(w);
}
unsigned int vpSSLDetector::getShortWindow() const
{
  return m_impl->getShortWindow();
}
void vpSSLDetector::setRegionsOfInterest(const std::vector<vpRect> &rois)
{
  m_impl->setRegionsOfInterest(rois);
}
bool vpSSLDetector::getLastSearchWasFull() const
{
  return m_impl->getLastSearchWasFull();
}
unsigned int vpSSLDetector::getWindow() const
{
  return m_impl->getWindow();
}
double vpSSLDetector::getThreshold() const
{
  return m_impl->getThreshold();
}
bool vpSSLDetector::getBrightnessNormalization() const
{
  return m_impl->getBrightnessNormalization();
}
const vpSSLTarget &vpSSLDetector::getTarget() const
{
  return m_impl->getTarget();
}
const std::vector<vpSSLLandmark> &vpSSLDetector::getLandmarks() const
{
  return m_impl->getLandmarks();
}
const vpSSLTargetMatch &vpSSLDetector::getTargetMatch() const
{
  return m_impl->getTargetMatch();
}
const vpSSLDetectorTimes &vpSSLDetector::getTimes() const
{
  return m_impl->getTimes();
}
const vpImage<int> &vpSSLDetector::getMatchingMap() const
{
  return m_impl->getMatchingMap();
}
const vpSSLMatchingFunction &vpSSLDetector::getMatchingFunction() const
{
  return m_impl->getMatchingFunction();
}

bool vpSSLDetector::detect(const vpImage<unsigned char> &I)
{
  const auto t0 = std::chrono::steady_clock::now();
  m_nb_objects = 0;
  if (I.getSize() == 0) {
    m_polygon.clear();
    m_message.clear();
  }
  m_impl->detect(I);
  fillObjects();
  m_impl->getTimes().total = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return !m_impl->getLandmarks().empty();
}

void vpSSLDetector::fillObjects()
{
  const vpSSLTarget &target = getTarget();
  const std::vector<vpSSLLandmark> &landmarks = m_impl->getLandmarks();
  const vpSSLTargetMatch &targetMatch = m_impl->getTargetMatch();
  // Resized, not rebuilt: the polygons and the short messages keep their storage between frames.
  m_polygon.resize(landmarks.size());
  m_message.resize(landmarks.size());
  for (std::string &m : m_message) {
    m.assign("ssl");
  }
  for (size_t k = 0; k < targetMatch.detection.size(); ++k) {
    if (targetMatch.detection[k] >= 0) {
      std::string &m = m_message[targetMatch.detection[k]];
      m.assign(target.getName());
      m.append(" ");
      m.append(target.getLandmark(k).name);
    }
  }
  const int nbVertices = 16;
  for (size_t i = 0; i < landmarks.size(); ++i) {
    const vpSSLLandmark &l = landmarks[i];
    std::vector<vpImagePoint> &polygon = m_polygon[i];
    polygon.resize(nbVertices);
    const double c = std::cos(l.theta), s = std::sin(l.theta);
    const double b = l.minorRadius > 0. ? l.minorRadius : l.radius;
    for (int k = 0; k < nbVertices; ++k) {
      const double a = 2. * M_PI * k / nbVertices;
      const double x = l.radius * std::cos(a), y = b * std::sin(a);
      polygon[k].set_ij(l.v + s * x + c * y, l.u + c * x - s * y);
    }
  }
  m_nb_objects = landmarks.size();
}

const vpSSLLandmark *vpSSLDetector::getMatchedLandmark(size_t i) const
{
  const std::vector<vpSSLLandmark> &landmarks = m_impl->getLandmarks();
  const vpSSLTargetMatch &targetMatch = m_impl->getTargetMatch();
  if (i >= targetMatch.detection.size() || targetMatch.detection[i] < 0) {
    return nullptr;
  }
  return &landmarks[targetMatch.detection[i]];
}

double vpSSLDetector::range(const vpSSLLandmark &landmark, double radius, const vpCameraParameters &cam)
{
  if (!(landmark.radius > 0.)) {
    throw vpException(vpException::badValue, "vpSSLDetector::range: landmark radius %g px", landmark.radius);
  }
  return cam.get_px() * radius / landmark.radius;
}

std::vector<vpFeaturePoint> vpSSLDetector::getFeaturePoints(const vpCameraParameters &cam) const
{
  const vpSSLTargetMatch &targetMatch = m_impl->getTargetMatch();
  std::vector<vpFeaturePoint> features;
  for (size_t k = 0; k < targetMatch.detection.size(); ++k) {
    const vpSSLLandmark *l = getMatchedLandmark(k);
    if (l == nullptr) {
      continue;
    }
    double x = 0., y = 0.;
    vpPixelMeterConversion::convertPoint(cam, l->u, l->v, x, y);
    vpFeaturePoint s;
    s.buildFrom(x, y, range(*l, getTarget().getLandmark(k).radius, cam));
    features.push_back(s);
  }
  return features;
}

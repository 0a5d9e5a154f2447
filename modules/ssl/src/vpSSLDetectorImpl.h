/*
  Private to vpSSLDetector: the state behind its public interface (vpSSLDetector::m_impl).
*/
#ifndef VP_SSL_DETECTOR_IMPL_H
#define VP_SSL_DETECTOR_IMPL_H

#include <visp3/ssl/vpSSLDetector.h>

#include "vpSSLDetectionPipeline.h"

/*
  The detection pipeline, with its settings, its working storage, the last results and the previous frame's
  landmarks; vpSSLDetector adds the vpDetectorBase objects (polygons, messages) on top.
*/
class vpSSLDetector::Impl : public vpSSLDetectionPipeline
{
public:
  using vpSSLDetectionPipeline::vpSSLDetectionPipeline;
};

#endif

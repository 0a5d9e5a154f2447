/*
  Private to the detector: a vpImage member that copies safely when empty.
*/
#ifndef VP_SSL_IMAGE_BUFFER_H
#define VP_SSL_IMAGE_BUFFER_H

#include <visp3/core/vpImage.h>

/*
  vpImage<T> whose copy and copy assignment leave an empty image empty. ViSP 3.5's vpImage copy constructor passes
  the empty source's null bitmap to memcpy (undefined behaviour, reported by UBSan), so the detector's working images,
  empty until a mode needs them, would make a copy of the detector undefined. Everything else is vpImage's.
*/
template <typename T> class vpSSLImageBuffer : public vpImage<T>
{
public:
  using vpImage<T>::operator=;

  vpSSLImageBuffer() = default;
  vpSSLImageBuffer(const vpSSLImageBuffer &other) : vpImage<T>() { *this = other; }
  vpSSLImageBuffer &operator=(const vpSSLImageBuffer &other)
  {
    if (this != &other) {
      if (other.getSize() == 0) {
        this->destroy();
      } else {
        vpImage<T>::operator=(other);
      }
    }
    return *this;
  }
};

#endif

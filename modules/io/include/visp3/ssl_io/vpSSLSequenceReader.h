/*!
  \file vpSSLSequenceReader.h
  \brief Streaming reader of a recorded sequence folder.
*/
#ifndef VP_SSL_SEQUENCE_READER_H
#define VP_SSL_SEQUENCE_READER_H

#include <fstream>
#include <string>
#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>
#include <visp3/ssl/vpSSLConfig.h>
#include <visp3/ssl_io/vpSSLSequenceFrame.h>
#include <visp3/ssl_io/vpSSLSequenceInfo.h>

/*!
  \defgroup group_ssl_io Files
  Library visp_ssl_io, headers <tt>\<visp3/ssl_io/...\></tt> (CMake: <tt>target_link_libraries(app
  visp_ssl_io)</tt>): recorded sequences read and written (vpSSLSequenceReader, vpSSLSequenceWriter), camera
  files (vpSSLCameraFile), odometry tracks (vpSSLOdometryTrack) and image files read with their size checked
  before decoding (vpSSLImageIo). The bounds it checks are visp_ssl's (vpSSLInputLimits). See
  doc/sequence-format.md.
*/

/*!
  \class vpSSLSequenceReader
  \ingroup group_ssl_io
  \brief Reads a recorded sequence folder (doc/sequence-format.md) one frame at a time.

  open() reads camera.xml (camera "Camera" with the projection model found in the file, the model with
  distortion when both are there), sequence.json and the
  header of frames.csv; next() then reads one row of frames.csv and its image images/%06d.png (or .jpg, .jpeg,
  .pgm, .ppm: the first that exists). Only the current row is held, so sequences of any length stream in
  constant memory.

  Everything read is checked: any problem throws one vpException naming the file, the line and the field,
  for example <tt>frames.csv:17: gt_tz: not a number: "abc"</tt>. Limits (doc/input-limits.md): \c t within
  +-maxTime() s, the translations of the odometry and the ground truth within +-maxTranslation() m, their
  theta-u elements within +-maxRotation() rad; lines end in LF or CRLF (CR alone is an error); a UTF-8 byte
  order mark before the header is skipped; images are read by vpSSLImageIo (its size limits, checked on the
  file's header before decoding). Problems in a row are reported when next()
  reaches that row; after an error, next() throws the same error again until the next open().

  \code
  vpSSLSequenceReader reader;
  reader.open("my-sequence");
  vpSSLSequenceFrame f;
  vpImage<unsigned char> I;
  while (reader.next(f, I)) {
    if (f.hasGroundTruth)
      std::cout << f.index << " " << f.t << " " << f.cMo.t() << std::endl;
  }
  \endcode
*/
class VISP_SSL_EXPORT vpSSLSequenceReader
{
public:
  //! A closed reader; call open().
  vpSSLSequenceReader();

  /*!
    Opens a sequence folder: reads camera.xml, sequence.json and the frames.csv header.
    \exception vpException (ioError) when a file is missing; (badValue) naming the file, the line and the
    field when a file is malformed.
  */
  void open(const std::string &folder);

  /*!
    Reads the next row and its image, converted to grey if needed.
    \return false at the end of the sequence (frame and image unchanged).
    \exception vpException naming the file, the line and the field on a malformed row or a missing, unreadable
    or wrongly sized image.
  */
  bool next(vpSSLSequenceFrame &frame, vpImage<unsigned char> &I);

  //! As next(vpSSLSequenceFrame &, vpImage<unsigned char> &), with a colour image.
  bool next(vpSSLSequenceFrame &frame, vpImage<vpRGBa> &I);

  /*!
    Reads the next row without decoding its image (which must exist; getImagePath() names it): for tools
    that only need the poses.
    \return false at the end of the sequence.
  */
  bool next(vpSSLSequenceFrame &frame);

  //! Closes frames.csv; open() may be called again.
  void close();

  //! True between open() and close().
  bool isOpen() const { return m_csv.is_open(); }
  //! The folder given to open().
  const std::string &getFolder() const { return m_folder; }
  //! Camera intrinsics from camera.xml.
  const vpCameraParameters &getCameraParameters() const { return m_cam; }
  //! Image width from camera.xml; when camera.xml does not give it, the first image's (0 before it is read).
  unsigned int getImageWidth() const { return m_width; }
  //! Image height from camera.xml; when camera.xml does not give it, the first image's (0 before it is read).
  unsigned int getImageHeight() const { return m_height; }
  //! Content of sequence.json.
  const vpSSLSequenceInfo &getInfo() const { return m_info; }
  /*!
    sequence.json's \c target for vpSSLTarget::fromName(): a relative path resolved against the sequence
    folder (never the working folder), an absolute path or a built-in name as is. A target is taken as a
    path when a file of that name is in the folder, or when it contains a '/' or ends in ".txt".
  */
  std::string getTargetPath() const;
  //! Largest |t| in frames.csv (s): 1e9.
  static constexpr double maxTime() { return 1e9; }
  //! Largest |odom_t*|, |gt_t*| in frames.csv (m): 1e4.
  static constexpr double maxTranslation() { return 1e4; }
  //! Largest |odom_tu*|, |gt_tu*| in frames.csv (rad): 2 pi.
  static constexpr double maxRotation() { return 6.283185307179586; }
  //! Names of the frames.csv columns after the 14 standard ones, in file order.
  const std::vector<std::string> &getExtraColumns() const { return m_extraColumns; }
  //! Path of the image of the last row read by next(), empty before the first.
  const std::string &getImagePath() const { return m_imagePath; }

private:
  void readCamera();
  void readHeader();
  bool readRow(vpSSLSequenceFrame &frame);
  std::string where() const;
  template <typename Type> bool nextWithImage(vpSSLSequenceFrame &frame, vpImage<Type> &I);

  std::string m_folder;
  std::string m_csvPath;
  std::ifstream m_csv;
  unsigned int m_lineNumber;
  unsigned int m_rowIndex;
  bool m_ended;
  std::string m_line;               // current line, reused so that rows do not allocate
  std::vector<std::string> m_cells; // cells of the current line, reused
  std::string m_lastTime;           // previous row's t cell, for the "not increasing" message
  double m_lastTimeValue;
  std::vector<std::string> m_extraColumns;
  std::string m_imagePath;
  std::string m_error; // first error of next(), repeated by later calls
  vpCameraParameters m_cam;
  unsigned int m_width;
  unsigned int m_height;
  vpSSLSequenceInfo m_info;
};

#endif

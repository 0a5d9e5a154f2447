/*!
  \file vpSSLSequenceWriter.h
  \brief Writer of a recorded sequence folder.
*/
#ifndef VP_SSL_SEQUENCE_WRITER_H
#define VP_SSL_SEQUENCE_WRITER_H

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
  \class vpSSLSequenceWriter
  \ingroup group_ssl_io
  \brief Writes a recorded sequence folder (doc/sequence-format.md) one frame at a time: what the
  simulator writes and what a user records on a vehicle, read back by vpSSLSequenceReader.

  open() creates the folder, images/, camera.xml, sequence.json and the frames.csv header; write() saves the
  image as images/%06d.png and then appends its row, so an interrupted recording is still a valid sequence up
  to its last row. camera.xml gets the image size from the first image. Poses are written with 9 significant
  digits, time stamps with 6 decimals.

  \code
  vpSSLSequenceInfo info;
  info.target = "ssl3-a3";
  info.source = "recorded";
  vpSSLSequenceWriter writer;
  writer.open("my-sequence", cam, info, {"depth"});
  for (unsigned int i = 0; i < n; ++i) {
    vpSSLSequenceFrame f;
    f.index = i;
    f.t = 0.04 * i;
    f.extras["depth"] = "12.5";
    writer.write(f, I);
  }
  writer.close();
  \endcode
*/
class VISP_SSL_EXPORT vpSSLSequenceWriter
{
public:
  //! A closed writer; call open().
  vpSSLSequenceWriter();
  //! Closes the sequence; errors are not reported here, call close() to see them.
  ~vpSSLSequenceWriter();

  vpSSLSequenceWriter(const vpSSLSequenceWriter &) = delete;
  vpSSLSequenceWriter &operator=(const vpSSLSequenceWriter &) = delete;

  /*!
    By default open() refuses a folder that exists and is not empty, so that nothing a user has is lost.
    With \e overwrite true it replaces the sequence files in it (camera.xml, sequence.json, frames.csv and
    images/NNNNNN.png/jpg/jpeg/pgm/ppm) and leaves any other file alone.
  */
  void setOverwrite(bool overwrite) { m_overwrite = overwrite; }
  //! See setOverwrite().
  bool getOverwrite() const { return m_overwrite; }

  /*!
    Creates the sequence folder and writes camera.xml, sequence.json and the frames.csv header.
    \param folder : the sequence folder, created with its parents if needed.
    \param cam : camera intrinsics, saved as camera "Camera".
    \param info : the sequence.json content (checked before anything is written).
    \param extraColumns : names of the columns written after the 14 standard ones, filled from each frame's
    \c extras (an empty cell for a frame without that name).
    \exception vpException (ioError) when the folder is not empty and getOverwrite() is false, or cannot be
    written; (badValue) on an invalid \e info or column name.
  */
  void open(const std::string &folder, const vpCameraParameters &cam, const vpSSLSequenceInfo &info,
            const std::vector<std::string> &extraColumns = std::vector<std::string>());

  /*!
    Writes images/%06d.png and appends the frame's row.
    \exception vpException (badValue) when \e frame.index is not the number of frames written so far, its time
    stamp does not increase (at the 6 decimals written), a pose is not finite, it has an extra not declared at
    open() or a cell with a line break, or the image size differs from the first one; (ioError) when a file
    cannot be written.
  */
  void write(const vpSSLSequenceFrame &frame, const vpImage<unsigned char> &I);
  //! As write(const vpSSLSequenceFrame &, const vpImage<unsigned char> &), with a colour image.
  void write(const vpSSLSequenceFrame &frame, const vpImage<vpRGBa> &I);

  /*!
    Flushes and closes frames.csv.
    \exception vpException (ioError) when the data could not be written (disk full, ...).
  */
  void close();

  //! True between open() and close().
  bool isOpen() const { return m_csv.is_open(); }
  //! Number of frames written since open().
  unsigned int getFrameCount() const { return m_count; }
  //! The folder given to open().
  const std::string &getFolder() const { return m_folder; }

private:
  void checkRow(const vpSSLSequenceFrame &frame, unsigned int width, unsigned int height);
  void appendRow(const vpSSLSequenceFrame &frame);
  void saveCamera(unsigned int width, unsigned int height);
  template <typename Type> void writeFrame(const vpSSLSequenceFrame &frame, const vpImage<Type> &I);

  bool m_overwrite;
  std::string m_folder;
  std::string m_csvPath;
  std::ofstream m_csv;
  vpCameraParameters m_cam;
  std::vector<std::string> m_extraColumns;
  unsigned int m_count;
  unsigned int m_width;
  unsigned int m_height;
  std::string m_timeCell; // t of the row being written, formatted
  double m_lastTime;
};

#endif

/*!
  \file vpSSLImageIo.cpp
  \brief Header sizes of PNG, JPEG, PNM and BMP files, and decoding through OpenCV.
*/
#include <visp3/ssl_io/vpSSLImageIo.h>

#include <algorithm>
#include <cctype>
#include <csetjmp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <jpeglib.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <visp3/core/vpException.h>
#include <visp3/core/vpImageConvert.h>
#include <visp3/ssl/vpSSLInputLimits.h>

namespace {
[[noreturn]] void fail(const std::string &file, const std::string &problem)
{
  throw vpException(vpException::ioError, file + ": " + problem);
}

uint32_t bigEndian32(const unsigned char *b)
{
  return (uint32_t(b[0]) << 24) | (uint32_t(b[1]) << 16) | (uint32_t(b[2]) << 8) | uint32_t(b[3]);
}

// Reads exactly n bytes at offset; false when the file is shorter.
bool readAt(std::istream &in, uint64_t offset, unsigned char *buf, size_t n)
{
  in.clear();
  in.seekg(static_cast<std::streamoff>(offset));
  in.read(reinterpret_cast<char *>(buf), static_cast<std::streamsize>(n));
  return static_cast<size_t>(in.gcount()) == n;
}

uint32_t crc32(const unsigned char *data, size_t n, uint32_t crc)
{
  // Initialised once, thread-safely (a function-local static).
  static const std::vector<uint32_t> table = [] {
    std::vector<uint32_t> t(256);
    for (uint32_t i = 0; i < 256; ++i) {
      uint32_t c = i;
      for (int k = 0; k < 8; ++k) {
        c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      }
      t[i] = c;
    }
    return t;
  }();
  for (size_t i = 0; i < n; ++i) {
    crc = table[(crc ^ data[i]) & 0xFF] ^ (crc >> 8);
  }
  return crc;
}

// Walks the chunks of a PNG file to IEND, checking that each is whole and its CRC right: libpng reports a
// truncated or corrupt file on stderr before OpenCV returns, and a tool must print one line of its own.
void pngChunks(std::istream &in, const std::string &file, uint64_t fileSize)
{
  static const uint32_t kCrcInit = 0xFFFFFFFFu;
  uint64_t pos = 8;
  std::vector<unsigned char> buf(1 << 16);
  for (;;) {
    unsigned char head[8];
    if (!readAt(in, pos, head, 8)) {
      fail(file, "PNG data truncated: the file ends at byte " + std::to_string(fileSize) + " before the IEND chunk");
    }
    const uint64_t length = bigEndian32(head);
    const std::string type(reinterpret_cast<const char *>(head + 4), 4);
    if (length > 0x7FFFFFFFu || pos + 12 + length > fileSize) {
      fail(file, "PNG data truncated: chunk " + type + " at byte " + std::to_string(pos) + " needs " +
                     std::to_string(length + 12) + " bytes, the file ends at byte " + std::to_string(fileSize));
    }
    uint32_t crc = crc32(head + 4, 4, kCrcInit);
    for (uint64_t done = 0; done < length;) {
      const size_t n = static_cast<size_t>(std::min<uint64_t>(buf.size(), length - done));
      if (!readAt(in, pos + 8 + done, buf.data(), n)) {
        fail(file, "PNG data: read error in chunk " + type);
      }
      crc = crc32(buf.data(), n, crc);
      done += n;
    }
    unsigned char stored[4];
    if (!readAt(in, pos + 8 + length, stored, 4) || bigEndian32(stored) != (crc ^ kCrcInit)) {
      fail(file, "PNG data corrupt: bad CRC of chunk " + type + " at byte " + std::to_string(pos));
    }
    if (type == "IEND") {
      return;
    }
    pos += 12 + length;
  }
}

// libjpeg reports corrupt or truncated data as a warning that its default error manager prints on stderr and
// decodes the rest as grey; OpenCV's decoder keeps that default, so a tool would print a line of libjpeg besides
// its own, or accept a half-grey image. This manager prints nothing, keeps libjpeg's message and makes every
// warning an error.
struct JpegErrors
{
  jpeg_error_mgr pub; // first: libjpeg hands back &pub
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

void jpegFail(j_common_ptr cinfo)
{
  JpegErrors *errors = reinterpret_cast<JpegErrors *>(cinfo->err);
  (*cinfo->err->format_message)(cinfo, errors->message);
  std::longjmp(errors->jump, 1);
}

void jpegMessage(j_common_ptr cinfo, int level)
{
  // Level -1 is a warning (corrupt data); levels 0 and up are trace messages, off by default.
  if (level < 0) {
    jpegFail(cinfo);
  }
}

void jpegSilent(j_common_ptr) {}

// Decodes JPEG data with libjpeg down to its last scanline and its end marker (rows discarded, in the cheapest
// mode: the decode is a check, OpenCV's is the one kept). False with libjpeg's message in \e message on the first
// error or warning. No C++ object is created between setjmp() and a longjmp() to it.
bool jpegDecodes(const unsigned char *data, size_t size, char (&message)[JMSG_LENGTH_MAX])
{
  jpeg_decompress_struct cinfo;
  JpegErrors errors;
  cinfo.err = jpeg_std_error(&errors.pub);
  errors.pub.error_exit = jpegFail;
  errors.pub.emit_message = jpegMessage;
  errors.pub.output_message = jpegSilent;
  errors.message[0] = '\0';
  if (setjmp(errors.jump) != 0) {
    jpeg_destroy_decompress(&cinfo);
    std::snprintf(message, sizeof(message), "%s", errors.message);
    return false;
  }
  jpeg_create_decompress(&cinfo);
  jpeg_mem_src(&cinfo, data, static_cast<unsigned long>(size));
  jpeg_read_header(&cinfo, TRUE);
  cinfo.dct_method = JDCT_IFAST;
  cinfo.do_fancy_upsampling = FALSE;
  if (cinfo.jpeg_color_space == JCS_YCbCr) {
    cinfo.out_color_space = JCS_GRAYSCALE;
  }
  jpeg_start_decompress(&cinfo);
  JSAMPARRAY row = (*cinfo.mem->alloc_sarray)(reinterpret_cast<j_common_ptr>(&cinfo), JPOOL_IMAGE,
                                              cinfo.output_width * cinfo.output_components, 1);
  while (cinfo.output_scanline < cinfo.output_height) {
    jpeg_read_scanlines(&cinfo, row, 1);
  }
  jpeg_finish_decompress(&cinfo);
  jpeg_destroy_decompress(&cinfo);
  return true;
}

// PNM header: magic, width, height and (but for P1, P4) maxval, separated by blanks and comments. Returns the
// offset of the first pixel byte (one blank after the last field).
uint64_t pnmHeader(std::istream &in, const std::string &file, char kind, uint64_t &width, uint64_t &height,
                   uint64_t &maxval)
{
  in.clear();
  in.seekg(2);
  const int nFields = (kind == '1' || kind == '4') ? 2 : 3;
  uint64_t fields[3] = {0, 0, 1};
  const char *names[3] = {"width", "height", "maxval"};
  int c = in.get();
  for (int f = 0; f < nFields; ++f) {
    // Blanks and comments ('#' to the end of the line) before each field.
    for (;;) {
      while (c != EOF && std::isspace(c)) {
        c = in.get();
      }
      if (c != '#') {
        break;
      }
      while (c != EOF && c != '\n' && c != '\r') {
        c = in.get();
      }
    }
    if (c == EOF || !std::isdigit(c)) {
      fail(file, std::string("PNM header: ") + names[f] + ": not a number");
    }
    uint64_t v = 0;
    while (c != EOF && std::isdigit(c)) {
      v = v * 10 + static_cast<uint64_t>(c - '0');
      if (v > (uint64_t(1) << 40)) {
        fail(file, std::string("PNM header: ") + names[f] + ": too large");
      }
      c = in.get();
    }
    fields[f] = v;
  }
  if (c == EOF || !std::isspace(c)) {
    fail(file, "PNM header: expected a blank after the last field");
  }
  width = fields[0];
  height = fields[1];
  maxval = fields[2];
  if (nFields == 3 && (maxval == 0 || maxval > 65535)) {
    fail(file, "PNM header: maxval: must be in [1, 65535], got " + std::to_string(maxval));
  }
  return static_cast<uint64_t>(in.tellg());
}

// JPEG: the size is in the first start-of-frame segment (SOF0-SOF15 but DHT C4, JPG C8, DAC CC).
void jpegHeader(std::istream &in, const std::string &file, uint64_t &width, uint64_t &height)
{
  uint64_t pos = 2;
  unsigned char b[9];
  for (int segments = 0; segments < 4096; ++segments) {
    if (!readAt(in, pos, b, 4)) {
      fail(file, "JPEG header: truncated before the frame header");
    }
    if (b[0] != 0xFF) {
      fail(file, "JPEG header: malformed segment marker");
    }
    if (b[1] == 0xFF) { // fill byte
      ++pos;
      continue;
    }
    const unsigned marker = b[1];
    const uint64_t length = (uint64_t(b[2]) << 8) | b[3];
    if (marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC) {
      if (length < 8 || !readAt(in, pos + 4, b, 5)) {
        fail(file, "JPEG header: truncated frame header");
      }
      height = (uint64_t(b[1]) << 8) | b[2];
      width = (uint64_t(b[3]) << 8) | b[4];
      return;
    }
    if (marker == 0xD9 || marker == 0xDA || length < 2) {
      fail(file, "JPEG header: no frame header before the image data");
    }
    pos += 2 + length;
  }
  fail(file, "JPEG header: no frame header in the first 4096 segments");
}

// The format and size of the image whose \e size bytes \e in holds (see vpSSLImageIo::readHeader()).
std::string formatAndSize(std::istream &in, uint64_t fileSize, const std::string &filename, uint64_t &width,
                          uint64_t &height)
{
  unsigned char b[26] = {0};
  readAt(in, 0, b, 26);
  const unsigned char pngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (fileSize >= 8 && std::equal(pngSignature, pngSignature + 8, b)) {
    if (fileSize < 24 || std::string(reinterpret_cast<const char *>(b + 12), 4) != "IHDR") {
      fail(filename, "PNG header: truncated or missing IHDR chunk");
    }
    width = bigEndian32(b + 16);
    height = bigEndian32(b + 20);
    return "PNG";
  }
  if (fileSize >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF) {
    jpegHeader(in, filename, width, height);
    return "JPEG";
  }
  if (fileSize >= 3 && b[0] == 'P' && b[1] >= '1' && b[1] <= '6') {
    const char kind = static_cast<char>(b[1]);
    uint64_t maxval = 1;
    const uint64_t data = pnmHeader(in, filename, kind, width, height, maxval);
    const std::string format = (kind == '1' || kind == '4') ? "PBM" : (kind == '2' || kind == '5') ? "PGM" : "PPM";
    if (kind >= '4' && width <= vpSSLInputLimits::maxImageSide() && height <= vpSSLInputLimits::maxImageSide()) {
      // Binary data: its length is known, so a truncated file is told as such rather than as "corrupt".
      const uint64_t channels = kind == '6' ? 3 : 1, bytes = maxval > 255 ? 2 : 1;
      const uint64_t expected = kind == '4' ? (width + 7) / 8 * height : width * height * channels * bytes;
      if (fileSize - data < expected) {
        std::ostringstream os;
        os << format << " data truncated: " << fileSize - data << " bytes of pixels, the header (" << width << " x "
           << height << ", maxval " << maxval << ") needs " << expected;
        fail(filename, os.str());
      }
    }
    return format;
  }
  if (fileSize >= 26 && b[0] == 'B' && b[1] == 'M') {
    const int32_t w = static_cast<int32_t>(uint32_t(b[18]) | (uint32_t(b[19]) << 8) | (uint32_t(b[20]) << 16) |
                                           (uint32_t(b[21]) << 24));
    const int32_t h = static_cast<int32_t>(uint32_t(b[22]) | (uint32_t(b[23]) << 8) | (uint32_t(b[24]) << 16) |
                                           (uint32_t(b[25]) << 24));
    width = static_cast<uint64_t>(w < 0 ? -static_cast<int64_t>(w) : w);
    height = static_cast<uint64_t>(h < 0 ? -static_cast<int64_t>(h) : h);
    return "BMP";
  }
  fail(filename, fileSize == 0 ? "empty file" : "unknown image format (PNG, JPEG, PGM/PPM/PBM or BMP expected)");
}

// The checks of data whose header is read: a PNG's chunks walked, a JPEG decoded once silently (libpng and
// libjpeg would print on stderr what OpenCV's decoders ask them).
void checkEncodedData(std::istream &in, uint64_t size, const std::string &name, const std::string &format)
{
  if (format == "PNG") {
    pngChunks(in, name, size);
  } else if (format == "JPEG") {
    std::vector<unsigned char> data(static_cast<size_t>(size));
    if (!readAt(in, 0, data.data(), data.size())) {
      fail(name, "JPEG data: read error");
    }
    char message[JMSG_LENGTH_MAX];
    if (!jpegDecodes(data.data(), data.size(), message)) {
      fail(name, std::string("JPEG data truncated or corrupt: ") + message);
    }
  }
}

template <typename Type> void readImage(vpImage<Type> &I, const std::string &filename)
{
  uint64_t width = 0, height = 0;
  const std::string format = vpSSLImageIo::readHeader(filename, width, height);
  vpSSLInputLimits::checkImageSize(width, height, filename + ": " + format + " header");
  {
    std::ifstream in(filename, std::ios::binary);
    in.seekg(0, std::ios::end);
    checkEncodedData(in, static_cast<uint64_t>(in.tellg()), filename, format);
  }
  cv::Mat m;
  try {
    m = cv::imread(filename, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception &e) {
    fail(filename, "cannot decode the " + format + " data: " + e.what());
  }
  if (m.empty()) {
    fail(filename, "cannot decode the " + format + " data (truncated or corrupt file)");
  }
  if (static_cast<uint64_t>(m.cols) != width || static_cast<uint64_t>(m.rows) != height) {
    std::ostringstream os;
    os << "decoded " << m.cols << " x " << m.rows << " pixels, the " << format << " header says " << width << " x "
       << height;
    fail(filename, os.str());
  }
  if (m.depth() == CV_16U) {
    cv::Mat m8;
    m.convertTo(m8, CV_8U, 1. / 257.);
    m = m8;
  } else if (m.depth() != CV_8U) {
    fail(filename, format + " data of an unsupported depth (8 or 16 bits per sample)");
  }
  if (m.channels() != 1 && m.channels() != 3 && m.channels() != 4) {
    fail(filename, format + " data with " + std::to_string(m.channels()) + " channels (1, 3 or 4)");
  }
  vpImageConvert::convert(m, I);
  vpSSLInputLimits::checkImage(I, filename.c_str());
}
} // namespace

std::string vpSSLImageIo::readHeader(const std::string &filename, uint64_t &width, uint64_t &height)
{
  std::error_code ec;
  if (std::filesystem::is_directory(filename, ec)) {
    fail(filename, "is a folder, not an image");
  }
  std::ifstream in(filename, std::ios::binary);
  if (!in) {
    fail(filename, "missing or unreadable");
  }
  in.seekg(0, std::ios::end);
  const uint64_t fileSize = static_cast<uint64_t>(in.tellg());
  return formatAndSize(in, fileSize, filename, width, height);
}

void vpSSLImageIo::read(vpImage<unsigned char> &I, const std::string &filename)
{
  readImage(I, filename);
}

void vpSSLImageIo::read(vpImage<vpRGBa> &I, const std::string &filename)
{
  readImage(I, filename);
}

std::string vpSSLImageIo::checkData(const std::vector<unsigned char> &data, const std::string &name)
{
  std::istringstream in(std::string(data.begin(), data.end()));
  uint64_t width = 0, height = 0;
  const std::string format = formatAndSize(in, data.size(), name, width, height);
  vpSSLInputLimits::checkImageSize(width, height, name + ": " + format + " header");
  checkEncodedData(in, data.size(), name, format);
  return format;
}

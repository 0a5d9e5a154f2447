// Hostile input to the library: every malformed or absurd file, image or value gives one vpException naming the
// file, the line and the field (and the bound, for a limit), never a crash, an over-read, an allocation bomb or
// a hang (doc/input-limits.md).
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <unistd.h>
#include <vector>

#include <visp3/core/vpException.h>
#include <visp3/io/vpImageIo.h>
#include <visp3/ssl/vpSSLBrightnessNormalizer.h>
#include <visp3/ssl/vpSSLConcentricReader.h>
#include <visp3/ssl/vpSSLInputLimits.h>
#include <visp3/ssl/vpSSLMatchingFunction.h>
#include <visp3/ssl/vpSSLPeakDetector.h>
#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/ssl/vpSSLTracker.h>
#include <visp3/ssl_io/vpSSLCameraFile.h>
#include <visp3/ssl_io/vpSSLImageIo.h>
#include <visp3/ssl_io/vpSSLSequenceInfo.h>
#include <visp3/ssl_io/vpSSLSequenceReader.h>
#include <visp3/ssl_servo/vpSSLHomingBehaviour.h>

namespace fs = std::filesystem;

namespace {
// A fresh folder per test; ctest runs tests in parallel, hence the test name and pid.
class Hostile : public ::testing::Test
{
protected:
  void SetUp() override
  {
    const auto *info = ::testing::UnitTest::GetInstance()->current_test_info();
    m_dir = fs::path(VISP_SSL_BINARY_DIR) / "test-tmp" /
            (std::string("hostile-") + info->name() + "-" + std::to_string(::getpid()));
    fs::remove_all(m_dir);
    fs::create_directories(m_dir);
  }
  void TearDown() override
  {
    std::error_code ec;
    fs::remove_all(m_dir, ec);
  }
  std::string write(const std::string &name, const std::string &bytes) const
  {
    const std::string path = (m_dir / name).string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }
  fs::path m_dir;
};

// The message of the vpException \e f throws, or "no exception".
template <typename F> std::string errorOf(F f)
{
  try {
    f();
  } catch (const vpException &e) {
    return e.getStringMessage();
  }
  return "no exception";
}

#define EXPECT_HAS(message, text) EXPECT_NE((message).find(text), std::string::npos) << (message)

std::string readBytes(const std::string &path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// vpImage's 32-bit width x height wraps: 65537 x 65536 pixels hold 65536 bytes.
vpImage<unsigned char> wrappedImage()
{
  vpImage<unsigned char> I(65536, 65537, 128);
  return I;
}

std::string camera(const std::string &px, const std::string &u0 = "320", const std::string &size = "")
{
  return "<?xml version=\"1.0\"?>\n<root>\n  <camera>\n    <name>Camera</name>\n" + size +
         "    <model>\n      <type>perspectiveProjWithoutDistortion</type>\n      <px>" + px +
         "</px>\n      <py>554.3</py>\n      <u0>" + u0 +
         "</u0>\n      <v0>240</v0>\n    </model>\n  </camera>\n</root>\n";
}
} // namespace

// ---------------------------------------------------------------- images

TEST(HostileImage, WrappedSizeIsRejectedByEveryEntryPoint)
{
  const vpImage<unsigned char> I = wrappedImage();
  ASSERT_EQ(I.getSize(), 65536u); // the wrap this guards against
  EXPECT_HAS(errorOf([&] { vpSSLInputLimits::checkImage(I, "I"); }), "I: 65537 x 65536 pixels");
  unsigned char lut[256];
  EXPECT_HAS(errorOf([&] { vpSSLBrightnessNormalizer().computeLut(I, lut, 4); }),
             "vpSSLBrightnessNormalizer::computeLut: 65537 x 65536 pixels");
  vpImage<unsigned char> O;
  EXPECT_HAS(errorOf([&] { vpSSLBrightnessNormalizer().apply(I, O); }), "wrapped");
  vpImage<int> M;
  EXPECT_HAS(errorOf([&] { vpSSLMatchingFunction().compute(I, M); }), "vpSSLMatchingFunction::compute");
  vpImage<int> map(65536, 65537, 0);
  std::vector<vpSSLPeak> peaks;
  vpSSLPeakDetector peakDetector;
  EXPECT_HAS(errorOf([&] { peakDetector.detect(map, peaks); }), "vpSSLPeakDetector::detect");
  vpSSLLandmark predicted;
  predicted.u = predicted.v = 100.;
  predicted.radius = predicted.minorRadius = 20.;
  vpSSLConcentricReader reader;
  EXPECT_HAS(errorOf([&] { reader.readAt(I, predicted); }), "vpSSLConcentricReader::readAt: 65537 x 65536 pixels");
  vpCameraParameters cam;
  cam.initPersProjWithoutDistortion(554.3, 554.3, 320, 240);
  vpSSLTracker tracker(vpSSLTarget::ssl3a3(), cam);
  EXPECT_HAS(errorOf([&] { tracker.track(I); }), "vpSSLTracker::track: 65537 x 65536 pixels");
  tracker.getDetector().setSmallLandmarkMode(true); // upsampling first: the resample kernel would over-read
  tracker.setAutomaticSmallLandmarkMode(false);
  EXPECT_HAS(errorOf([&] { tracker.track(I, vpHomogeneousMatrix()); }), "vpSSLTracker::track");
}

TEST(HostileImage, KernelsStateAndCheckTheirBound)
{
  // A consistent image wider than the kernels support (65537 px rows: the resample kernel over-read on them).
  const vpImage<unsigned char> wide(1, 65537, 0);
  vpImage<int> M;
  EXPECT_HAS(errorOf([&] { vpSSLMatchingFunction().compute(wide, M); }),
             "vpSSLMatchingFunction::compute: 65537 x 1 pixels exceed the kernels' limit of 32768");
  unsigned char lut[256];
  EXPECT_HAS(errorOf([&] { vpSSLBrightnessNormalizer().computeLut(wide, lut); }), "kernels' limit");
  vpCameraParameters cam;
  cam.initPersProjWithoutDistortion(554.3, 554.3, 320, 240);
  vpSSLTracker tracker(vpSSLTarget::ssl3a3(), cam);
  EXPECT_HAS(errorOf([&] { tracker.track(wide); }), "vpSSLTracker::track: 65537 x 1 pixels: a side exceeds");
  // The smallest images go through every kernel.
  for (unsigned int w : {1u, 2u, 3u, 17u}) {
    for (unsigned int h : {1u, 2u, 5u}) {
      const vpImage<unsigned char> tiny(h, w, 100);
      EXPECT_NO_THROW(vpSSLMatchingFunction().compute(tiny, M));
      EXPECT_NO_THROW(tracker.track(tiny));
    }
  }
}

TEST(HostileImage, SizeLimitsAreStatedInTheMessage)
{
  EXPECT_HAS(errorOf([] { vpSSLInputLimits::checkImageSize(20000, 20000, "x"); }), "exceeds the limit of 16384");
  EXPECT_HAS(errorOf([] { vpSSLInputLimits::checkImageSize(16384, 16384, "x"); }), "exceed the limit of 67108864");
  EXPECT_HAS(errorOf([] { vpSSLInputLimits::checkImageSize(0, 5, "x"); }), "empty image");
  EXPECT_NO_THROW(vpSSLInputLimits::checkImageSize(16384, 4096, "x"));
  EXPECT_NO_THROW(vpSSLInputLimits::checkImageSize(1, 1, "x"));
}

TEST_F(Hostile, PnmHeaderBeyondTheLimitsIsRejectedBeforeDecoding)
{
  const std::string w = write("w.pgm", "P5\n65537 65536\n255\n" + std::string(65536, '\x80'));
  vpImage<unsigned char> I;
  const std::string m = errorOf([&] { vpSSLImageIo::read(I, w); });
  EXPECT_HAS(m, "w.pgm: PGM header: 65537 x 65536 pixels: a side exceeds the limit of 16384");
}

TEST_F(Hostile, PngHeaderBeyondTheLimitsIsRejectedBeforeDecoding)
{
  // A valid 4 x 4 grey PNG whose IHDR is patched to say 65536 x 65537 (ViSP's reader wrote past its buffer).
  vpImage<unsigned char> small(4, 4, 200);
  const std::string path = (m_dir / "small.png").string();
  vpImageIo::write(small, path);
  std::string bytes = readBytes(path);
  const unsigned char size[8] = {0, 1, 0, 0, 0, 1, 0, 1};
  bytes.replace(16, 8, reinterpret_cast<const char *>(size), 8);
  const std::string lie = write("lie.png", bytes);
  vpImage<unsigned char> I;
  EXPECT_HAS(errorOf([&] { vpSSLImageIo::read(I, lie); }), "lie.png: PNG header: 65536 x 65537 pixels");
  // 20000 x 20000 (a few hundred bytes compressed): rejected before any allocation.
  const unsigned char big[8] = {0, 0, 0x4E, 0x20, 0, 0, 0x4E, 0x20};
  bytes.replace(16, 8, reinterpret_cast<const char *>(big), 8);
  const std::string huge = write("huge.png", bytes);
  EXPECT_HAS(errorOf([&] { vpSSLImageIo::read(I, huge); }), "huge.png: PNG header: 20000 x 20000 pixels");
}

TEST_F(Hostile, TruncatedOrCorruptImagesFailCleanlyWithTheReason)
{
  vpImage<unsigned char> I;
  // Truncated PNG (ViSP's reader leaked 311 KB on it).
  const std::string png = readBytes(std::string(VISP_SSL_DATA_DIR) + "/images/ssl3-a3-00.png");
  const std::string t = write("t.png", png.substr(0, 1000));
  EXPECT_HAS(errorOf([&] { vpSSLImageIo::read(I, t); }), "t.png: PNG data truncated: chunk IDAT at byte");
  std::string corrupt = png;
  corrupt[corrupt.size() / 2] ^= 0x55;
  EXPECT_HAS(errorOf([&] { vpSSLImageIo::read(I, write("c.png", corrupt)); }), "c.png: PNG data corrupt: bad CRC");
  // Truncated binary PGM.
  const std::string p5 = write("t.pgm", "P5\n4 4\n255\n" + std::string(10, 'a'));
  EXPECT_HAS(errorOf([&] { vpSSLImageIo::read(I, p5); }), "t.pgm: PGM data truncated: 10 bytes of pixels");
  // Unknown format, empty file, folder, missing file.
  EXPECT_HAS(errorOf([&] { vpSSLImageIo::read(I, write("x.png", "hello")); }), "unknown image format");
  EXPECT_HAS(errorOf([&] { vpSSLImageIo::read(I, write("e.png", "")); }), "empty file");
  EXPECT_HAS(errorOf([&] { vpSSLImageIo::read(I, m_dir.string()); }), "is a folder");
  EXPECT_HAS(errorOf([&] { vpSSLImageIo::read(I, (m_dir / "none.png").string()); }), "missing or unreadable");
  // Bad PNM header fields.
  EXPECT_HAS(errorOf([&] { vpSSLImageIo::read(I, write("m.pgm", "P5\n4 4\n70000\n")); }), "maxval: must be in");
  EXPECT_HAS(errorOf([&] { vpSSLImageIo::read(I, write("n.pgm", "P5\nx 4\n255\n")); }), "width: not a number");
}

TEST_F(Hostile, EncodedDataInMemoryIsCheckedAsAFile)
{
  // The sample photograph passes; cut, corrupt or declaring 20000 x 20000 pixels, it is refused with the name given.
  const std::string png = readBytes(std::string(VISP_SSL_DATA_DIR) + "/images/ssl3-a3-00.png");
  auto data = [](const std::string &bytes) { return std::vector<unsigned char>(bytes.begin(), bytes.end()); };
  EXPECT_EQ(vpSSLImageIo::checkData(data(png), "photo"), "PNG");
  EXPECT_HAS(errorOf([&] { vpSSLImageIo::checkData(data(png.substr(0, 1000)), "cut"); }),
             "cut: PNG data truncated: chunk IDAT at byte");
  std::string corrupt = png;
  corrupt[corrupt.size() / 2] ^= 0x55;
  EXPECT_HAS(errorOf([&] { vpSSLImageIo::checkData(data(corrupt), "corrupt"); }), "corrupt: PNG data corrupt: bad CRC");
  std::string big = png;
  const unsigned char size[8] = {0, 0, 0x4E, 0x20, 0, 0, 0x4E, 0x20};
  big.replace(16, 8, reinterpret_cast<const char *>(size), 8);
  EXPECT_HAS(errorOf([&] { vpSSLImageIo::checkData(data(big), "big"); }), "big: PNG header: 20000 x 20000 pixels");
  EXPECT_HAS(errorOf([&] { vpSSLImageIo::checkData(data("hello"), "text"); }), "text: unknown image format");
}

TEST_F(Hostile, SixteenBitAndAsciiPgmAreRead)
{
  vpImage<unsigned char> I;
  // 16-bit binary PGM, big endian: 0x0000, 0xFFFF, 0x8080 -> 0, 255, 128.
  std::string p5 = "P5\n3 1\n65535\n";
  p5 += std::string("\x00\x00\xFF\xFF\x80\x80", 6);
  vpSSLImageIo::read(I, write("16.pgm", p5));
  ASSERT_EQ(I.getWidth(), 3u);
  EXPECT_EQ(I[0][0], 0);
  EXPECT_EQ(I[0][1], 255);
  EXPECT_EQ(I[0][2], 128);
  vpSSLImageIo::read(I, write("a.pgm", "P2\n2 2\n255\n0 10\n20 255\n"));
  ASSERT_EQ(I.getHeight(), 2u);
  EXPECT_EQ(I[1][0], 20);
}

TEST(HostileImage, ReadGivesViSPsPixelsOnTheSampleImages)
{
  // The sample images, and the photographs of visp-images-data the simulator's backgrounds use (grey and colour
  // PGM, PPM, PNG; JPEG decoders may differ by a grey level, so it is not compared).
  const std::string images = VISP_SSL_IMAGES_DIR;
  for (const std::string &path : {std::string(VISP_SSL_DATA_DIR) + "/images/ssl3-a3-00.png",
                                  std::string(VISP_SSL_DATA_DIR) + "/images/ssl3-a3-03.png",
                                  images + "/Klimt/Klimt.pgm", images + "/Klimt/Klimt.ppm", images + "/Klimt/Klimt.png",
                                  images + "/Solvay/Solvay_conference_1927_Version2_1024x705.png"}) {
    const std::string &name = path;
    vpImage<unsigned char> a, b;
    vpSSLImageIo::read(a, path);
    vpImageIo::read(b, path);
    EXPECT_TRUE(a == b) << name;
    vpImage<vpRGBa> c, d;
    vpSSLImageIo::read(c, path);
    vpImageIo::read(d, path);
    EXPECT_TRUE(c == d) << name;
  }
}

// ---------------------------------------------------------------- camera files

TEST_F(Hostile, CameraFileRejectsNonFiniteAndAbsurdIntrinsics)
{
  struct Case
  {
    std::string px, u0, expected;
  };
  const Case cases[] = {{"inf", "320", "px: must be a finite number in [1, 1e+07], got inf"},
                        {"1e300", "320", "px: must be a finite number in [1, 1e+07], got 1e+300"},
                        {"554.3", "nan", "u0: must be a finite number"},
                        {"554.3", "inf", "u0: must be a finite number"},
                        {"0", "320", "px: must be > 0, got 0"}};
  for (const Case &c : cases) {
    const std::string path = write("cam.xml", camera(c.px, c.u0));
    EXPECT_HAS(errorOf([&] { vpSSLCameraFile::load(path); }), "cam.xml: camera \"Camera\": " + c.expected);
  }
  vpCameraParameters cam;
  cam.initPersProjWithoutDistortion(554.3, 554.3, std::numeric_limits<double>::quiet_NaN(), 240);
  EXPECT_HAS(errorOf([&] { vpSSLTracker(vpSSLTarget::ssl3a3(), cam); }), "vpSSLTracker: camera: u0");
}

TEST_F(Hostile, CameraFileImageSizeIsBoundedAndNotZero)
{
  const auto withSize = [&](const std::string &w, const std::string &h) {
    return write("cam.xml",
                 camera("554.3", "320",
                        "    <image_width>" + w + "</image_width>\n    <image_height>" + h + "</image_height>\n"));
  };
  unsigned int w = 0, h = 0;
  EXPECT_HAS(errorOf([&] { vpSSLCameraFile::load(withSize("0", "480"), "Camera", &w, &h); }),
             "image_width: must be > 0");
  EXPECT_HAS(errorOf([&] { vpSSLCameraFile::load(withSize("20000", "20000"), "Camera", &w, &h); }),
             "20000 x 20000 pixels: a side exceeds the limit of 16384");
  EXPECT_HAS(errorOf([&] { vpSSLCameraFile::load(withSize("4294967295", "480"), "Camera", &w, &h); }),
             "camera \"Camera\": image_width: 4294967295 pixels: a side exceeds the limit of 16384");
  // Beyond 32 bits the file's own text is named, not the parser's saturated value.
  EXPECT_HAS(errorOf([&] { vpSSLCameraFile::load(withSize("640", "8589934597"), "Camera", &w, &h); }),
             "image_height: 8589934597 pixels: a side exceeds the limit of 16384");
  EXPECT_NO_THROW(vpSSLCameraFile::load(withSize("640", "480"), "Camera", &w, &h));
  EXPECT_EQ(w, 640u);
  EXPECT_HAS(errorOf([&] { vpSSLCameraFile::load(m_dir.string()); }), "is a folder");
}

// ---------------------------------------------------------------- target files

TEST_F(Hostile, TargetFileLimits)
{
  const auto loadError = [&](const std::string &text) {
    const std::string path = write("t.txt", text);
    return errorOf([&] { vpSSLTarget::load(path); });
  };
  EXPECT_HAS(loadError("name t\nlandmark A 0 0 0 0.1 0.5\nlandmark B 0.3 0 0 0.1 0.4\n"),
             "t.txt:3: p: 0.4 differs from 0.5 of \"A\" (the landmarks of a target share one p) (line 2)");
  EXPECT_HAS(loadError("name t\nlandmark A 0 0 0 0.1 0.99999999\n"), "t.txt:2: p: must be in [0.2, 0.8]");
  EXPECT_HAS(loadError("name t\nlandmark A 0 0 0 0.1 0.1\n"), "t.txt:2: p: must be in [0.2, 0.8]");
  EXPECT_HAS(loadError("name t\nlandmark B 1.7e308 0 0 1e308\n"), "t.txt:2: centre: each coordinate must be within");
  EXPECT_HAS(loadError("name t\nlandmark B 0 0 0 20\n"), "t.txt:2: radius: must be in [0.001, 10] m");
  EXPECT_HAS(loadError("name t\nlandmark A +-0.1 0 0 0.1\n"), "t.txt:2: x: not a number: \"+-0.1\"");
  EXPECT_HAS(loadError("name t\nsheet 1000 1 0 0\nlandmark A 0 0 0 0.1\n"), "t.txt:2: width: must be at most 100 m");
  std::string many = "name t\n";
  for (int i = 0; i < 65; ++i) {
    many += "landmark L" + std::to_string(i) + " " + std::to_string(i) + " 0 0 0.1\n";
  }
  EXPECT_HAS(loadError(many), "t.txt:66: landmark: more than 64 landmarks in one target");
}

// ---------------------------------------------------------------- sequences

namespace {
// A copy of data/sequences/approach-clear with its first two frames, whose files a test then spoils.
fs::path copySequence(const fs::path &dir)
{
  const fs::path src = fs::path(VISP_SSL_DATA_DIR) / "sequences" / "approach-clear";
  const fs::path dst = dir / "seq";
  fs::create_directories(dst / "images");
  fs::copy_file(src / "camera.xml", dst / "camera.xml");
  fs::copy_file(src / "sequence.json", dst / "sequence.json");
  fs::copy_file(src / "images" / "000000.png", dst / "images" / "000000.png");
  fs::copy_file(src / "images" / "000001.png", dst / "images" / "000001.png");
  std::ifstream in(src / "frames.csv");
  std::ofstream out(dst / "frames.csv");
  std::string line;
  for (int i = 0; i < 3 && std::getline(in, line); ++i) {
    out << line << "\n";
  }
  return dst;
}

std::string readAll(vpSSLSequenceReader &reader, const std::string &folder)
{
  return errorOf([&] {
    reader.open(folder);
    vpSSLSequenceFrame f;
    vpImage<unsigned char> I;
    while (reader.next(f, I)) {
    }
  });
}

void replaceInFile(const fs::path &path, const std::string &from, const std::string &to)
{
  std::string s = readBytes(path.string());
  const size_t at = s.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  s.replace(at, from.size(), to);
  std::ofstream(path, std::ios::binary) << s;
}
} // namespace

TEST_F(Hostile, SequenceJsonBomFolderAndMountBounds)
{
  vpSSLSequenceInfo info;
  EXPECT_NO_THROW(info = vpSSLSequenceInfo::fromJson(
                      "\xEF\xBB\xBF{\"target\": \"ssl3-a3\", \"camera_to_vehicle\": [0,0,0,0,0,0], \"source\": "
                      "\"recorded\", \"water\": {\"a\": 1}}"));
  EXPECT_EQ(info.water, "{\"a\": 1}");
  EXPECT_HAS(errorOf([] {
               vpSSLSequenceInfo::fromJson(
                   "{\"target\": \"ssl3-a3\", \"camera_to_vehicle\": [0,0,0,1e300,0,0], \"source\": \"recorded\"}");
             }),
             "sequence.json:1: camera_to_vehicle: element 4 is 1e+300, beyond +-6.28");
  const fs::path folder = m_dir / "sequence.json";
  fs::create_directories(folder);
  EXPECT_HAS(errorOf([&] { vpSSLSequenceInfo::load(folder.string()); }), "sequence.json: is a folder, not a file");
}

TEST_F(Hostile, FramesCsvValuesAreBoundedAndCrAloneIsNamed)
{
  const fs::path seq = copySequence(m_dir);
  vpSSLSequenceReader reader;
  EXPECT_EQ(readAll(reader, seq.string()), "no exception");
  replaceInFile(seq / "frames.csv", "\n1,1.000000,", "\n1,1e300,");
  EXPECT_HAS(readAll(reader, seq.string()), "frames.csv:3: t: 1e300 is beyond +-1e+09 s");
  replaceInFile(seq / "frames.csv", "\n1,1e300,0.79671105,", "\n1,1.000000,0.79671105e13,");
  EXPECT_HAS(readAll(reader, seq.string()), "frames.csv:3: odom_tx: 0.79671105e13 is beyond +-10000 m");
  std::string s = readBytes((seq / "frames.csv").string());
  for (char &c : s) {
    c = c == '\n' ? '\r' : c;
  }
  std::ofstream(seq / "frames.csv", std::ios::binary) << s;
  EXPECT_HAS(readAll(reader, seq.string()), "frames.csv:1: a carriage return inside the line");
}

TEST_F(Hostile, SequenceImageWithALyingHeaderIsRejected)
{
  const fs::path seq = copySequence(m_dir);
  std::ofstream(seq / "images" / "000001.png", std::ios::binary)
      << std::string("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR\0\1\0\0\0\1\0\0", 24);
  vpSSLSequenceReader reader;
  EXPECT_HAS(readAll(reader, seq.string()), "000001.png: PNG header: 65536 x 65536 pixels");
}

TEST_F(Hostile, RelativeTargetPathResolvesAgainstTheSequenceFolder)
{
  const fs::path seq = copySequence(m_dir);
  fs::copy_file(fs::path(VISP_SSL_DATA_DIR) / "targets" / "ssl3-a3.txt", seq / "my-target.txt");
  replaceInFile(seq / "sequence.json", "\"ssl3-a3\"", "\"my-target.txt\"");
  vpSSLSequenceReader reader;
  reader.open(seq.string());
  EXPECT_EQ(reader.getTargetPath(), (seq / "my-target.txt").string());
  EXPECT_EQ(vpSSLTarget::fromName(reader.getTargetPath()).size(), 3u);
  replaceInFile(seq / "sequence.json", "\"my-target.txt\"", "\"other.txt\"");
  reader.open(seq.string());
  EXPECT_EQ(reader.getTargetPath(), (seq / "other.txt").string()); // never the working folder's
  replaceInFile(seq / "sequence.json", "\"other.txt\"", "\"ssl3-a3\"");
  reader.open(seq.string());
  EXPECT_EQ(reader.getTargetPath(), "ssl3-a3");
}

// ---------------------------------------------------------------- servo

TEST(HostileServo, SearchPatternIsBounded)
{
  vpSSLHomingBehaviour b;
  EXPECT_HAS(errorOf([&] { b.setSearchPattern(0.2, -1e308, 1e308, 40, 0.5); }), "|depthMin|, |depthMax| <= 11000 m");
  EXPECT_HAS(errorOf([&] { b.setSearchPattern(1e9, 1, 3, 40, 0.5); }), "|yawRate| <= 10");
  EXPECT_NO_THROW(b.setSearchPattern(0.2, 1, 3, 40, 0.5));
}

// Recorded-sequence I/O (doc/sequence-format.md): what the writer writes the reader gives back, and
// every malformed input fails with one message naming the file, the line and the field.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include <visp3/core/vpException.h>
#include <visp3/core/vpXmlParserCamera.h>
#include <visp3/io/vpImageIo.h>
#include <visp3/ssl_io/vpSSLSequenceReader.h>
#include <visp3/ssl_io/vpSSLSequenceWriter.h>

namespace fs = std::filesystem;

namespace {
const int nFrames = 20;

// A fresh folder per test, removed afterwards; ctest runs tests in parallel, hence the test name and pid.
class SequenceIo : public ::testing::Test
{
protected:
  void SetUp() override
  {
    const auto *info = ::testing::UnitTest::GetInstance()->current_test_info();
    m_dir = fs::path(VISP_SSL_BINARY_DIR) / "test-tmp" /
            (std::string("seqio-") + info->name() + "-" + std::to_string(::getpid()));
    fs::remove_all(m_dir);
    fs::create_directories(m_dir.parent_path());
  }
  void TearDown() override
  {
    std::error_code ec;
    fs::remove_all(m_dir, ec);
  }
  std::string dir() const { return m_dir.string(); }
  fs::path m_dir;
};

vpCameraParameters camera()
{
  vpCameraParameters cam;
  cam.initPersProjWithoutDistortion(100.5, 101.25, 4.5, 3.75);
  return cam;
}

vpSSLSequenceInfo info()
{
  vpSSLSequenceInfo info;
  info.target = "ssl3-a3";
  info.vMc = vpPoseVector(0.1, -0.2, 0.3, 0.01, -0.02, 1.5707963);
  info.source = "simulated";
  info.water = "{\n    \"turbidity\": 0.25,\n    \"caustics\": [1, 2e-3, {\"a\": null}]\n  }";
  return info;
}

vpImage<unsigned char> greyImage(unsigned int i)
{
  vpImage<unsigned char> I(6, 8);
  for (unsigned int k = 0; k < I.getSize(); ++k)
    I.bitmap[k] = static_cast<unsigned char>((k * 7 + i * 13) % 256);
  return I;
}

vpImage<vpRGBa> colourImage(unsigned int i)
{
  vpImage<vpRGBa> I(6, 8);
  for (unsigned int k = 0; k < I.getSize(); ++k)
    I.bitmap[k] = vpRGBa(static_cast<unsigned char>((k * 7 + i) % 256), static_cast<unsigned char>((k * 3) % 256),
                         static_cast<unsigned char>((255 - k - i) % 256), 255);
  return I;
}

// Frame i has odometry except every 3rd one, ground truth except every 4th, and a "depth" extra on odd ones.
vpSSLSequenceFrame frameNumber(unsigned int i)
{
  vpSSLSequenceFrame f;
  f.index = i;
  f.t = 100.0 + 0.04 * i;
  f.hasOdometry = i % 3 != 0;
  if (f.hasOdometry)
    f.oMv = vpPoseVector(1.0 + i, -2.123456789 * i, 0.5, 0.001 * i, -0.1, 3.0);
  f.hasGroundTruth = i % 4 != 0;
  if (f.hasGroundTruth)
    f.cMo = vpPoseVector(0.01 * i, -0.02, 1.5 + 1e-7 * i, 0.3, -0.2 * i, 1e-5);
  if (i % 2)
    f.extras["depth"] = std::to_string(10 + i) + ".5";
  return f;
}

void writeGreySequence(const std::string &folder, unsigned int n = nFrames)
{
  vpSSLSequenceWriter writer;
  writer.open(folder, camera(), info(), {"depth"});
  for (unsigned int i = 0; i < n; ++i)
    writer.write(frameNumber(i), greyImage(i));
  writer.close();
}

void expectSamePose(const vpPoseVector &a, const vpPoseVector &b)
{
  // 9 significant digits are written.
  for (unsigned int k = 0; k < 6; ++k)
    EXPECT_NEAR(a[k], b[k], 1e-8 * std::max(1.0, std::fabs(b[k])));
}

void expectSameFrame(const vpSSLSequenceFrame &read, const vpSSLSequenceFrame &written)
{
  EXPECT_EQ(read.index, written.index);
  EXPECT_NEAR(read.t, written.t, 1e-6);
  ASSERT_EQ(read.hasOdometry, written.hasOdometry);
  ASSERT_EQ(read.hasGroundTruth, written.hasGroundTruth);
  if (written.hasOdometry)
    expectSamePose(read.oMv, written.oMv);
  if (written.hasGroundTruth)
    expectSamePose(read.cMo, written.cMo);
}

std::vector<std::string> readLines(const fs::path &path)
{
  std::ifstream in(path);
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(in, line))
    lines.push_back(line);
  return lines;
}

void writeText(const fs::path &path, const std::string &text)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

// Replaces line \e number (from 1) of a text file.
void replaceLine(const fs::path &path, size_t number, const std::string &text)
{
  std::vector<std::string> lines = readLines(path);
  ASSERT_LE(number, lines.size());
  lines[number - 1] = text;
  std::string all;
  for (const std::string &l : lines)
    all += l + "\n";
  writeText(path, all);
}

// Reads the whole sequence with images; returns the error message, or "" when it reads fine.
std::string readError(const std::string &folder)
{
  try {
    vpSSLSequenceReader reader;
    reader.open(folder);
    vpSSLSequenceFrame f;
    vpImage<unsigned char> I;
    while (reader.next(f, I)) {
    }
  } catch (const vpException &e) {
    return e.getStringMessage();
  }
  return std::string();
}

#define EXPECT_CONTAINS(text, part) EXPECT_NE((text).find(part), std::string::npos) << "message: " << (text)
} // namespace

TEST_F(SequenceIo, greyRoundTripGivesBackRowsImagesCameraAndInfo)
{
  writeGreySequence(dir());
  vpSSLSequenceReader reader;
  reader.open(dir());
  vpCameraParameters cam = reader.getCameraParameters();
  EXPECT_EQ(cam.get_projModel(), vpCameraParameters::perspectiveProjWithoutDistortion);
  EXPECT_DOUBLE_EQ(cam.get_px(), 100.5);
  EXPECT_DOUBLE_EQ(cam.get_py(), 101.25);
  EXPECT_DOUBLE_EQ(cam.get_u0(), 4.5);
  EXPECT_DOUBLE_EQ(cam.get_v0(), 3.75);
  EXPECT_EQ(reader.getImageWidth(), 8u);
  EXPECT_EQ(reader.getImageHeight(), 6u);
  EXPECT_EQ(reader.getInfo().target, "ssl3-a3");
  EXPECT_EQ(reader.getInfo().source, "simulated");
  EXPECT_EQ(reader.getInfo().water, info().water);
  expectSamePose(reader.getInfo().vMc, info().vMc);
  ASSERT_EQ(reader.getExtraColumns(), std::vector<std::string>{"depth"});

  vpSSLSequenceFrame f;
  vpImage<unsigned char> I;
  unsigned int n = 0;
  while (reader.next(f, I)) {
    expectSameFrame(f, frameNumber(n));
    EXPECT_EQ(f.extras.at("depth"), n % 2 ? std::to_string(10 + n) + ".5" : "");
    EXPECT_TRUE(I == greyImage(n)) << "image " << n;
    ++n;
  }
  EXPECT_EQ(n, static_cast<unsigned int>(nFrames));
  EXPECT_FALSE(reader.next(f, I));
}

TEST_F(SequenceIo, colourRoundTripGivesBackColourImages)
{
  vpSSLSequenceWriter writer;
  writer.open(dir(), camera(), info());
  for (unsigned int i = 0; i < 4; ++i) {
    vpSSLSequenceFrame f = frameNumber(i);
    f.extras.clear(); // no extra column declared
    writer.write(f, colourImage(i));
  }
  writer.close();

  vpSSLSequenceReader reader;
  reader.open(dir());
  vpSSLSequenceFrame f;
  vpImage<vpRGBa> I;
  unsigned int n = 0;
  while (reader.next(f, I)) {
    expectSameFrame(f, frameNumber(n));
    EXPECT_TRUE(f.extras.empty());
    EXPECT_TRUE(I == colourImage(n)) << "image " << n;
    ++n;
  }
  EXPECT_EQ(n, 4u);
}

TEST_F(SequenceIo, absentOdometryAndGroundTruthAreEmptyCellsAndReadBackAsAbsent)
{
  writeGreySequence(dir(), 5);
  std::vector<std::string> lines = readLines(m_dir / "frames.csv");
  ASSERT_EQ(lines.size(), 6u);
  // Frame 0: no odometry, no truth; frame 4: odometry but no truth.
  EXPECT_EQ(lines[1], "0,100.000000,,,,,,,,,,,,,");
  const std::string end4 = ",-0.1,3,,,,,,,";
  EXPECT_EQ(lines[5].substr(0, 13), "4,100.160000,");
  EXPECT_EQ(lines[5].substr(lines[5].size() - end4.size()), end4);

  vpSSLSequenceReader reader;
  reader.open(dir());
  vpSSLSequenceFrame f;
  f.hasOdometry = f.hasGroundTruth = true;
  ASSERT_TRUE(reader.next(f));
  EXPECT_FALSE(f.hasOdometry);
  EXPECT_FALSE(f.hasGroundTruth);
  ASSERT_TRUE(reader.next(f));
  EXPECT_TRUE(f.hasOdometry);
  EXPECT_TRUE(f.hasGroundTruth);
}

TEST_F(SequenceIo, unknownExtraColumnsAreKeptByNameAndOtherwiseIgnored)
{
  writeGreySequence(dir(), 3);
  writeText(m_dir / "frames.csv",
            "frame,t,odom_tx,odom_ty,odom_tz,odom_tux,odom_tuy,odom_tuz,gt_tx,gt_ty,gt_tz,gt_tux,gt_tuy,gt_tuz,"
            "B_u,note\n"
            "0,0.0,,,,,,,0,0,1,0,0,0,12.5,\"a, \"\"quoted\"\" note\"\n"
            "1,0.1,1,2,3,0,0,0,,,,,,,,\n"
            "2,0.2,,,,,,,,,,,,,x,y\n");
  vpSSLSequenceReader reader;
  reader.open(dir());
  EXPECT_EQ(reader.getExtraColumns(), (std::vector<std::string>{"B_u", "note"}));
  vpSSLSequenceFrame f;
  vpImage<unsigned char> I;
  ASSERT_TRUE(reader.next(f, I));
  EXPECT_EQ(f.extras.at("B_u"), "12.5");
  EXPECT_EQ(f.extras.at("note"), "a, \"quoted\" note");
  EXPECT_TRUE(f.hasGroundTruth);
  EXPECT_DOUBLE_EQ(f.cMo[2], 1.0);
  ASSERT_TRUE(reader.next(f, I));
  EXPECT_EQ(f.extras.at("B_u"), "");
  EXPECT_TRUE(f.hasOdometry);
  ASSERT_TRUE(reader.next(f, I));
  EXPECT_EQ(f.extras.at("note"), "y");
  EXPECT_FALSE(reader.next(f, I));
}

// ---------------------------------------------------------------- the checker (tutorial-ssl-check-sequence)

// Runs the project's checker with \e args; returns its exit status and its standard output in \e out.
int runChecker(const std::string &args, std::string &out)
{
  const fs::path file = fs::path(VISP_SSL_BINARY_DIR) / "test-tmp" / ("checker-" + std::to_string(::getpid()) + ".out");
  const std::string cmd = std::string("'") + VISP_SSL_CHECK_SEQUENCE + "' " + args + " > '" + file.string() + "' 2>&1";
  const int status = std::system(cmd.c_str());
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  out = text.str();
  fs::remove(file);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string quoted(const std::string &s)
{
  return "'" + s + "'";
}

// Every line of a failing run is one problem, FILE:LINE: FIELD: problem.
void expectOneProblemPerLine(const std::string &out)
{
  std::istringstream in(out);
  std::string line;
  size_t n = 0;
  while (std::getline(in, line)) {
    ++n;
    const size_t a = line.find(':'), b = line.find(": ", a + 1), c = line.find(": ", b + 2);
    ASSERT_NE(a, std::string::npos) << line;
    ASSERT_NE(b, std::string::npos) << line;
    ASSERT_NE(c, std::string::npos) << line;
    const std::string number = line.substr(a + 1, b - a - 1);
    EXPECT_TRUE(!number.empty() && number.find_first_not_of("0123456789") == std::string::npos) << line;
    EXPECT_GT(c, b + 2) << "empty FIELD: " << line;
    EXPECT_GT(line.size(), c + 2) << "empty problem: " << line;
  }
  EXPECT_GT(n, 0u);
}

TEST_F(SequenceIo, checkerAcceptsEveryShippedSequence)
{
  size_t n = 0;
  for (const auto &entry : fs::directory_iterator(fs::path(VISP_SSL_DATA_DIR) / "sequences")) {
    if (!entry.is_directory())
      continue;
    ++n;
    std::string out;
    EXPECT_EQ(runChecker(quoted(entry.path().string()), out), 0) << out;
    EXPECT_CONTAINS(out, entry.path().string() + ": ok: ");
    EXPECT_EQ(readError(entry.path().string()), "");
  }
  EXPECT_GE(n, 5u) << "data/sequences/ has lost its sample sequences";
}

TEST_F(SequenceIo, checkerAcceptsWhatTheWriterWrites)
{
  writeGreySequence(dir());
  std::string out;
  EXPECT_EQ(runChecker(quoted(dir()), out), 0) << out;
  EXPECT_EQ(out, dir() + ": ok: 20 frames, 15 with ground truth, 13 with odometry, target ssl3-a3\n");
  EXPECT_EQ(runChecker("--quiet --no-images " + quoted(dir()), out), 0) << out;
  EXPECT_EQ(out, "");

  // An interrupted recording (an image written, its row not) is valid up to its last row.
  vpImageIo::write(greyImage(20), (m_dir / "images" / "000020.png").string());
  EXPECT_EQ(runChecker(quoted(dir()), out), 0) << out;
}

TEST_F(SequenceIo, checkerUsageErrorsExitWith2)
{
  std::string out;
  EXPECT_EQ(runChecker("", out), 2) << out;
  EXPECT_EQ(runChecker("--bogus " + quoted(dir()), out), 2) << out;
  EXPECT_EQ(runChecker("--help", out), 0) << out;
  EXPECT_CONTAINS(out, "FILE:LINE: FIELD: problem");
  EXPECT_CONTAINS(out, "Exit status: 0");
}

// Broken folders, each with one known problem: the checker exits with 1 and names it on its line, and the
// reader rejects the folder too.
TEST_F(SequenceIo, checkerRejectsEachBrokenFolderWithOneLinePerProblem)
{
  struct Broken
  {
    std::string name;
    std::string expected; // the problem line, after "FOLDER/"
  };
  const std::vector<Broken> cases = {
      {"missing-image", "frames.csv:9: image: images/000007.png: missing"},
      {"time-not-increasing", "frames.csv:9: t: not increasing (101.2 after 101.300000)"},
      {"bad-header", "frames.csv:1: column 5: expected \"odom_tz\", got \"odom_z\""},
      {"bad-camera", "camera.xml:0: camera: name: no camera named \"Camera\""},
      {"camera-without-model", "camera.xml:0: camera: camera \"Camera\": no readable <model>"},
      {"partial-pose", "frames.csv:8: gt_tuz: empty, but 5 other gt_* cells are set"},
      {"frame-out-of-order", "frames.csv:6: frame: 5, expected 4"},
      {"short-row", "frames.csv:5: row: 10 cells, the header has 15"},
      {"not-a-number", "frames.csv:17: gt_tz: not a number: \"abc\""},
      {"no-frames-csv", "frames.csv:0: file: missing"},
      {"bad-json", "sequence.json:4: json: expected '}' or ','"},
      {"unknown-target", "sequence.json:2: target: \"no-such-target.txt\" is neither"},
      {"image-of-another-size", "frames.csv:6: image: images/000004.png: 3x3 pixels, expected 8x6"},
  };
  for (const Broken &b : cases) {
    SCOPED_TRACE(b.name);
    const fs::path folder = m_dir / b.name;
    writeGreySequence(folder.string());
    const fs::path csv = folder / "frames.csv";
    if (b.name == "missing-image")
      fs::remove(folder / "images" / "000007.png");
    else if (b.name == "time-not-increasing") {
      replaceLine(csv, 8, "6,101.3,,,,,,,,,,,,,");
      replaceLine(csv, 9, "7,101.2,,,,,,,,,,,,,");
    } else if (b.name == "bad-header")
      replaceLine(
          csv, 1,
          "frame,t,odom_tx,odom_ty,odom_z,odom_tux,odom_tuy,odom_tuz,gt_tx,gt_ty,gt_tz,gt_tux,gt_tuy,gt_tuz,depth");
    else if (b.name == "bad-camera") {
      fs::remove(folder / "camera.xml");
      vpXmlParserCamera().save(camera(), (folder / "camera.xml").string(), "Other", 8, 6);
    } else if (b.name == "camera-without-model")
      writeText(folder / "camera.xml", "<?xml version=\"1.0\"?>\n<root><camera><name>Camera</name></camera></root>\n");
    else if (b.name == "partial-pose")
      replaceLine(csv, 8, "6,100.240000,,,,,,,1,2,3,0,0,,");
    else if (b.name == "frame-out-of-order")
      replaceLine(csv, 6, "5,100.160000,,,,,,,,,,,,,");
    else if (b.name == "short-row")
      replaceLine(csv, 5, "3,100.120000,1,2,3,0.1,0.2,0.3,1,2");
    else if (b.name == "not-a-number")
      replaceLine(csv, 17, "15,100.600000,1,2,3,0.1,0.2,0.3,1,2,abc,0,0,0,");
    else if (b.name == "no-frames-csv")
      fs::remove(csv);
    else if (b.name == "bad-json")
      writeText(folder / "sequence.json", "{\n  \"target\": \"ssl3-a3\",\n  \"camera_to_vehicle\": [0, 0, 0, 0, 0, 0]\n"
                                          "  \"source\": \"recorded\"\n}\n");
    else if (b.name == "unknown-target")
      writeText(folder / "sequence.json",
                "{\n  \"target\": \"no-such-target.txt\",\n"
                "  \"camera_to_vehicle\": [0, 0, 0, 0, 0, 0],\n  \"source\": \"recorded\"\n}\n");
    else if (b.name == "image-of-another-size")
      vpImageIo::write(vpImage<unsigned char>(3, 3, 0), (folder / "images" / "000004.png").string());

    std::string out;
    EXPECT_EQ(runChecker(quoted(folder.string()), out), 1) << out;
    EXPECT_CONTAINS(out, folder.string() + "/" + b.expected);
    expectOneProblemPerLine(out);
    if (b.name != "unknown-target") // the reader does not interpret "target"; the programs that build it do
      EXPECT_NE(readError(folder.string()), "") << "the reader reads a folder the checker rejects";
  }
}

TEST_F(SequenceIo, checkerListsEveryProblemOfAFolder)
{
  writeGreySequence(dir());
  const fs::path csv = m_dir / "frames.csv";
  replaceLine(csv, 4, "2,100.080000,1,,3,0,0,0,,,,,,,"); // partial odometry
  replaceLine(csv, 9, "7,100.100000,,,,,,,,,,,,,");      // time stamp going back
  replaceLine(csv, 10, "8,100.320000,,,,,,,,,,,,,");     // compared with 100.24, the last good one: fine
  fs::remove(m_dir / "images" / "000012.png");
  fs::remove(m_dir / "images" / "000015.png");
  std::string out;
  ASSERT_EQ(runChecker("--no-images " + quoted(dir()), out), 1) << out;
  const std::string f = dir() + "/frames.csv:";
  EXPECT_EQ(out,
            f + "4: odom_ty: empty, but 5 other odom_* cells are set (the 6 cells are all numbers or all empty)\n" + f +
                "9: t: not increasing (100.100000 after 100.240000)\n" + f +
                "14: image: images/000012.png: missing (also looked for .jpg, .jpeg, .pgm, .ppm)\n" + f +
                "17: image: images/000015.png: missing (also looked for .jpg, .jpeg, .pgm, .ppm)\n");

  // Two folders: the status is 1 when one of them does not conform, and each is reported.
  const fs::path good = m_dir.string() + "-good";
  writeGreySequence(good.string(), 3);
  EXPECT_EQ(runChecker(quoted(good.string()) + " " + quoted(dir()), out), 1) << out;
  EXPECT_CONTAINS(out, good.string() + ": ok: 3 frames");
  EXPECT_CONTAINS(out, f + "9: t: not increasing");
  fs::remove_all(good);
}

TEST_F(SequenceIo, writerRefusesANonEmptyFolderUnlessToldAndThenKeepsForeignFiles)
{
  writeGreySequence(dir(), 6);
  writeText(m_dir / "notes.txt", "mine");
  writeText(m_dir / "images" / "notes.txt", "mine too");
  vpSSLSequenceWriter writer;
  try {
    writer.open(dir(), camera(), info());
    FAIL() << "open() overwrote a non-empty folder";
  } catch (const vpException &e) {
    EXPECT_CONTAINS(e.getStringMessage(), "not empty");
  }
  EXPECT_TRUE(fs::exists(m_dir / "images" / "000005.png"));

  writer.setOverwrite(true);
  writer.open(dir(), camera(), info());
  writer.write(frameNumber(0), greyImage(0));
  writer.close();
  EXPECT_TRUE(fs::exists(m_dir / "notes.txt"));
  EXPECT_TRUE(fs::exists(m_dir / "images" / "notes.txt"));
  EXPECT_FALSE(fs::exists(m_dir / "images" / "000005.png")); // a stale frame of the old sequence
  EXPECT_EQ(readLines(m_dir / "frames.csv").size(), 2u);
  EXPECT_EQ(readError(dir()), "");
}

TEST_F(SequenceIo, writerRejectsWhatTheReaderWouldReject)
{
  vpSSLSequenceWriter writer;
  writer.open(dir(), camera(), info(), {"depth"});
  writer.write(frameNumber(0), greyImage(0));
  vpSSLSequenceFrame f = frameNumber(1);
  f.index = 2;
  EXPECT_THROW(writer.write(f, greyImage(1)), vpException);
  f = frameNumber(1);
  f.t = frameNumber(0).t + 1e-7; // equal at the 6 decimals written
  EXPECT_THROW(writer.write(f, greyImage(1)), vpException);
  f = frameNumber(1);
  f.extras["undeclared"] = "1";
  EXPECT_THROW(writer.write(f, greyImage(1)), vpException);
  f = frameNumber(1);
  f.cMo[0] = std::nan("");
  EXPECT_THROW(writer.write(f, greyImage(1)), vpException);
  EXPECT_THROW(writer.write(frameNumber(1), vpImage<unsigned char>(3, 3)), vpException);
  writer.write(frameNumber(1), greyImage(1));
  writer.close();
  EXPECT_EQ(readError(dir()), "");

  vpSSLSequenceInfo bad = info();
  bad.water = "{\"unterminated\": ";
  vpSSLSequenceWriter other;
  EXPECT_THROW(other.open((m_dir / "other").string(), camera(), bad), vpException);
  EXPECT_FALSE(fs::exists(m_dir / "other")); // nothing is created when open() refuses
}

TEST_F(SequenceIo, cameraWithDistortionIsReadWithItsModel)
{
  writeGreySequence(dir(), 2);
  vpCameraParameters cam;
  cam.initPersProjWithDistortion(100., 100., 4., 3., 0.1, -0.1);
  fs::remove(m_dir / "camera.xml");
  vpXmlParserCamera().save(cam, (m_dir / "camera.xml").string(), "Camera", 8, 6);
  vpSSLSequenceReader reader;
  reader.open(dir());
  EXPECT_EQ(reader.getCameraParameters().get_projModel(), vpCameraParameters::perspectiveProjWithDistortion);
  EXPECT_DOUBLE_EQ(reader.getCameraParameters().get_kud(), 0.1);
}

TEST_F(SequenceIo, crlfLineEndingsAndATrailingEmptyLineAreTolerated)
{
  writeGreySequence(dir());
  std::string crlf;
  for (const std::string &line : readLines(m_dir / "frames.csv"))
    crlf += line + "\r\n";
  writeText(m_dir / "frames.csv", crlf + "\r\n");
  EXPECT_EQ(readError(dir()), "");
}

TEST_F(SequenceIo, aLineLongerThanOneMebibyteIsAnErrorNamingItsLine)
{
  // doc/input-limits.md: a row of frames.csv is at most 1 MiB, so that a file without line ends is not read whole
  // into one line. A row just under the bound is read as usual (its extra column kept).
  writeGreySequence(dir(), 2);
  std::vector<std::string> lines = readLines(m_dir / "frames.csv");
  ASSERT_EQ(lines.size(), 3u);
  std::string text = lines[0] + ",note\n";
  const size_t room = (size_t(1) << 20) - lines[1].size() - 1;
  text += lines[1] + "," + std::string(room, 'x') + "\n";
  text += lines[2] + "," + std::string(room + 1, 'x') + "\n";
  writeText(m_dir / "frames.csv", text);
  const std::string msg = readError(dir());
  EXPECT_CONTAINS(msg, "frames.csv:3: line longer than 1048576 bytes");
}

TEST_F(SequenceIo, missingCameraXmlIsNamed)
{
  writeGreySequence(dir(), 2);
  fs::remove(m_dir / "camera.xml");
  std::string msg = readError(dir());
  EXPECT_CONTAINS(msg, "camera.xml: missing");
}

TEST_F(SequenceIo, cameraXmlWithoutCameraNamedCameraIsAnError)
{
  writeGreySequence(dir(), 2);
  fs::remove(m_dir / "camera.xml");
  vpXmlParserCamera().save(camera(), (m_dir / "camera.xml").string(), "Other", 8, 6);
  std::string msg = readError(dir());
  EXPECT_CONTAINS(msg, "camera.xml: name: no camera named \"Camera\"");
}

TEST_F(SequenceIo, missingSequenceJsonIsNamed)
{
  writeGreySequence(dir(), 2);
  fs::remove(m_dir / "sequence.json");
  EXPECT_CONTAINS(readError(dir()), "sequence.json: missing");
}

TEST_F(SequenceIo, malformedSequenceJsonNamesTheLine)
{
  writeGreySequence(dir(), 2);
  writeText(m_dir / "sequence.json", "{\n  \"target\": \"ssl3-a3\",\n  \"camera_to_vehicle\": [0, 0, 0, 0, 0, 0]\n"
                                     "  \"source\": \"recorded\"\n}\n");
  EXPECT_CONTAINS(readError(dir()), "sequence.json:4: expected '}' or ',' after an object member");
}

TEST_F(SequenceIo, wrongSequenceJsonFieldNamesTheLineAndField)
{
  writeGreySequence(dir(), 2);
  writeText(m_dir / "sequence.json", "{\n  \"target\": \"ssl3-a3\",\n  \"source\": \"recorded\",\n"
                                     "  \"camera_to_vehicle\": [0, 0, 0, 0, 0]\n}\n");
  EXPECT_CONTAINS(readError(dir()), "sequence.json:4: camera_to_vehicle: expected an array of 6 numbers");
  writeText(m_dir / "sequence.json", "{\n  \"camera_to_vehicle\": [0, 0, 0, 0, 0, 0],\n  \"source\": \"real\"\n}");
  EXPECT_CONTAINS(readError(dir()), "sequence.json:1: target: missing");
  writeText(m_dir / "sequence.json", "{\"target\": \"t\", \"camera_to_vehicle\": [0, 0, 0, 0, 0, 0],\n"
                                     "\"source\": \"real\"}");
  EXPECT_CONTAINS(readError(dir()), "sequence.json:2: source: expected \"simulated\" or \"recorded\"");
}

TEST(SequenceInfo, jsonIsReadStrictlyAndWaterKeptVerbatim)
{
  std::string water = "{ \"attenuation\": [0.1, 0.2, 0.3],\n \"name\": \"caf\\u00e9 \\ud83d\\ude00\", \"x\": -1.5e-3 }";
  vpSSLSequenceInfo i =
      vpSSLSequenceInfo::fromJson("{\"target\": \"targets/my \\\"t\\\".txt\", \"source\": \"recorded\", "
                                  "\"camera_to_vehicle\": [0, 0, 0.2, 0, 0, -1e-2], \"water\": " +
                                  water + ", \"future\": true}");
  EXPECT_EQ(i.target, "targets/my \"t\".txt");
  EXPECT_EQ(i.water, water);
  EXPECT_DOUBLE_EQ(i.vMc[5], -0.01);
  vpSSLSequenceInfo back = vpSSLSequenceInfo::fromJson(i.toJson());
  EXPECT_EQ(back.target, i.target);
  EXPECT_EQ(back.water, water);

  auto error = [](const std::string &text) {
    try {
      vpSSLSequenceInfo::fromJson(text, "s.json");
    } catch (const vpException &e) {
      return e.getStringMessage();
    }
    return std::string();
  };
  const std::string ok = "\"target\": \"t\", \"source\": \"recorded\", \"camera_to_vehicle\": [0,0,0,0,0,0]";
  EXPECT_EQ(error("{" + ok + "}"), "");
  EXPECT_CONTAINS(error("{" + ok + ",\n}"), "s.json:2: expected a member name");
  EXPECT_CONTAINS(error("{\n// comment\n" + ok + "}"), "s.json:2: expected a member name");
  EXPECT_CONTAINS(error("{" + ok + ",\n\"target\": \"u\"}"), "s.json:2: member \"target\" appears twice");
  EXPECT_CONTAINS(error("{" + ok + "} x"), "s.json:1: unexpected 'x'");
  EXPECT_CONTAINS(error("{" + ok + ", \"water\": 01}"), "s.json:1: malformed number");
  EXPECT_CONTAINS(error("{" + ok + ", \"water\": [1]}"), "s.json:1: water: expected a JSON object");
  EXPECT_CONTAINS(error("{" + ok + ", \"water\": " + std::string(100, '[') + std::string(100, ']') + "}"),
                  "nesting deeper than");
  EXPECT_CONTAINS(error("{\"target\": \"t\n\"}"), "s.json:1: control character inside a string");
  EXPECT_CONTAINS(error(""), "s.json:1: expected a value, got end of file");
}

TEST_F(SequenceIo, missingFramesCsvIsNamed)
{
  writeGreySequence(dir(), 2);
  fs::remove(m_dir / "frames.csv");
  EXPECT_CONTAINS(readError(dir()), "frames.csv: missing");
}

TEST_F(SequenceIo, badHeaderNamesTheFirstWrongColumn)
{
  writeGreySequence(dir(), 2);
  replaceLine(m_dir / "frames.csv", 1,
              "frame,t,odom_tx,odom_ty,odom_z,odom_tux,odom_tuy,odom_tuz,gt_tx,gt_ty,gt_tz,gt_tux,gt_tuy,gt_tuz");
  EXPECT_CONTAINS(readError(dir()), "frames.csv:1: column 5: expected \"odom_tz\", got \"odom_z\"");
  replaceLine(m_dir / "frames.csv", 1, "frame,t,odom_tx,odom_ty,odom_tz,odom_tux,odom_tuy,odom_tuz");
  EXPECT_CONTAINS(readError(dir()), "frames.csv:1: column 9 \"gt_tx\": missing");
}

TEST_F(SequenceIo, shortRowNamesTheFirstMissingColumn)
{
  writeGreySequence(dir());
  replaceLine(m_dir / "frames.csv", 5, "3,100.120000,1,2,3,0.1,0.2,0.3,1,2");
  EXPECT_CONTAINS(readError(dir()), "frames.csv:5: gt_tz: missing (row has 10 cells, expected 15)");
}

TEST_F(SequenceIo, nonNumericCellNamesLineAndColumn)
{
  writeGreySequence(dir());
  replaceLine(m_dir / "frames.csv", 17, "15,100.600000,1,2,3,0.1,0.2,0.3,1,2,abc,0,0,0,");
  EXPECT_CONTAINS(readError(dir()), "frames.csv:17: gt_tz: not a number: \"abc\"");
}

TEST_F(SequenceIo, frameIndexMustFollowRowOrder)
{
  writeGreySequence(dir());
  replaceLine(m_dir / "frames.csv", 6, "5,100.160000,,,,,,,,,,,,,");
  EXPECT_CONTAINS(readError(dir()), "frames.csv:6: frame: 5, expected 4");
}

TEST_F(SequenceIo, timeStampsMustIncrease)
{
  writeGreySequence(dir());
  replaceLine(m_dir / "frames.csv", 8, "6,101.3,,,,,,,,,,,,,");
  replaceLine(m_dir / "frames.csv", 9, "7,101.2,,,,,,,,,,,,,");
  EXPECT_CONTAINS(readError(dir()), "frames.csv:9: t: not increasing (101.2 after 101.3)");
}

TEST_F(SequenceIo, partialOdometryIsAnError)
{
  writeGreySequence(dir());
  replaceLine(m_dir / "frames.csv", 7, "5,100.200000,1,2,,0,0,0,,,,,,,");
  EXPECT_CONTAINS(readError(dir()), "frames.csv:7: odom_tz: empty, but 5 other odom_* cells are set");
}

TEST_F(SequenceIo, partialGroundTruthIsAnError)
{
  writeGreySequence(dir());
  replaceLine(m_dir / "frames.csv", 8, "6,100.240000,,,,,,,1,2,3,0,0,,");
  EXPECT_CONTAINS(readError(dir()), "frames.csv:8: gt_tuz: empty, but 5 other gt_* cells are set");
}

TEST_F(SequenceIo, missingImageNamesTheImageAndTheRow)
{
  writeGreySequence(dir());
  fs::remove(m_dir / "images" / "000007.png");
  std::string msg = readError(dir());
  EXPECT_CONTAINS(msg, "images/000007.png: missing");
  EXPECT_CONTAINS(msg, "frames.csv:9");

  // The reader does not read on past an error: it repeats it.
  vpSSLSequenceReader reader;
  reader.open(dir());
  vpSSLSequenceFrame f;
  for (int i = 0; i < 7; ++i)
    ASSERT_TRUE(reader.next(f));
  for (int attempt = 0; attempt < 2; ++attempt) {
    try {
      reader.next(f);
      FAIL() << "frame 7 has no image";
    } catch (const vpException &e) {
      EXPECT_EQ(e.getStringMessage(), msg);
    }
  }
}

TEST_F(SequenceIo, emptyLineInsideTheTableIsAnError)
{
  writeGreySequence(dir());
  replaceLine(m_dir / "frames.csv", 6, "");
  EXPECT_CONTAINS(readError(dir()), "frames.csv:6: empty line inside the table");
}

TEST_F(SequenceIo, imageOfTheWrongSizeIsAnError)
{
  writeGreySequence(dir());
  vpImageIo::write(vpImage<unsigned char>(3, 3, 0), (m_dir / "images" / "000004.png").string());
  std::string msg = readError(dir());
  EXPECT_CONTAINS(msg, "images/000004.png: 3x3 pixels, expected 8x6");
  EXPECT_CONTAINS(msg, "frames.csv:6");
}

// 20,000 rows (a long recording) stream through in constant memory: the reader holds one row and one image.
TEST_F(SequenceIo, longSequenceStreamsRowByRow)
{
  const unsigned int n = 20000;
  writeGreySequence(dir(), 1);
  fs::path image = m_dir / "images" / "000000.png";
  std::ofstream csv(m_dir / "frames.csv", std::ios::trunc);
  csv << "frame,t,odom_tx,odom_ty,odom_tz,odom_tux,odom_tuy,odom_tuz,gt_tx,gt_ty,gt_tz,gt_tux,gt_tuy,gt_tuz\n";
  csv.precision(10);
  char name[32];
  for (unsigned int i = 0; i < n; ++i) {
    csv << i << ',' << i * 0.04 << ",,,,,,";
    if (i % 2 == 0)
      csv << ',' << 0 << ',' << 0 << ',' << 1 + i * 1e-4 << ",0,0,0\n";
    else
      csv << ",,,,,,\n";
    if (i > 0) {
      std::snprintf(name, sizeof(name), "%06u.png", i);
      std::error_code ec;
      fs::create_hard_link(image, m_dir / "images" / name, ec);
      if (ec)
        fs::copy_file(image, m_dir / "images" / name);
    }
  }
  csv.close();

  vpSSLSequenceReader reader;
  reader.open(dir());
  vpSSLSequenceFrame f;
  vpImage<unsigned char> I;
  unsigned int count = 0;
  bool allRight = true;
  while (reader.next(f, I)) {
    allRight = allRight && f.index == count && std::fabs(f.t - count * 0.04) < 1e-9 &&
               f.hasGroundTruth == (count % 2 == 0) && !f.hasOdometry && I.getWidth() == 8;
    if (f.hasGroundTruth)
      allRight = allRight && std::fabs(f.cMo[2] - (1 + count * 1e-4)) < 1e-9;
    ++count;
  }
  EXPECT_EQ(count, n);
  EXPECT_TRUE(allRight);
}

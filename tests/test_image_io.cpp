// SPDX-License-Identifier: Apache-2.0
// Image I/O (docs/algorithm.md sections 1 and 10): gray conversion, input
// errors, output encodings and the atomic PNG writer.
#include "sgm/image_io.hpp"
#include "sgm/params.hpp"

#include "expect_error.hpp"
#include "fuzz/bad_images.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>
#include <set>
#include <stdlib.h>
#include <sys/stat.h>

namespace fs = std::filesystem;

namespace {

// A fresh directory under the gtest temp dir, removed at scope exit.
struct TempDir {
  std::string path;
  TempDir() {
    std::string base = testing::TempDir();
    if (base.empty() || base.back() != '/') base += '/';
    std::string tmpl = base + "sgm_io_XXXXXX";
    if (!::mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed");
    path = tmpl;
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  std::string operator/(const std::string& name) const { return path + "/" + name; }
  std::set<std::string> entries() const {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(path)) names.insert(e.path().filename().string());
    return names;
  }
};

void writeText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

// ------------------------------------------------------------------ toGray

TEST(ToGray, IntegerFormulaOnBgrPixels) {
  // Pixels are (B, G, R) as OpenCV stores them.
  cv::Mat bgr(1, 6, CV_8UC3);
  bgr.at<cv::Vec3b>(0, 0) = {0, 0, 255};      // red:   (77*255 + 128) >> 8 = 19763 >> 8 = 77
  bgr.at<cv::Vec3b>(0, 1) = {0, 255, 0};      // green: (150*255 + 128) >> 8 = 38378 >> 8 = 149
  bgr.at<cv::Vec3b>(0, 2) = {255, 0, 0};      // blue:  (29*255 + 128) >> 8 = 7523 >> 8 = 29
  bgr.at<cv::Vec3b>(0, 3) = {255, 255, 255};  // (256*255 + 128) >> 8 = 255
  bgr.at<cv::Vec3b>(0, 4) = {10, 20, 30};     // R=30 G=20 B=10: (2310 + 3000 + 290 + 128) >> 8 = 22
  bgr.at<cv::Vec3b>(0, 5) = {0, 0, 0};
  const cv::Mat g = sgm::toGray(bgr);
  ASSERT_EQ(g.type(), CV_8UC1);
  ASSERT_EQ(g.size(), bgr.size());
  EXPECT_EQ(g.at<uint8_t>(0, 0), 77);
  EXPECT_EQ(g.at<uint8_t>(0, 1), 149);
  EXPECT_EQ(g.at<uint8_t>(0, 2), 29);
  EXPECT_EQ(g.at<uint8_t>(0, 3), 255);
  EXPECT_EQ(g.at<uint8_t>(0, 4), 22);
  EXPECT_EQ(g.at<uint8_t>(0, 5), 0);
}

TEST(ToGray, GrayInputIsCopiedUnchanged) {
  const cv::Mat gray = (cv::Mat_<uint8_t>(2, 2) << 0, 1, 128, 255);
  const cv::Mat g = sgm::toGray(gray);
  EXPECT_EQ(cv::countNonZero(g != gray), 0);
  EXPECT_NE(g.data, gray.data);  // a copy, not a view
}

TEST(ToGray, RejectsOtherFormats) {
  expectError([] { sgm::toGray(cv::Mat(2, 2, CV_16UC1, cv::Scalar(1))); }, {"depth"});
  expectError([] { sgm::toGray(cv::Mat(2, 2, CV_8UC4, cv::Scalar::all(1))); }, {"4 channels"});
  expectError([] { sgm::toGray(cv::Mat(2, 2, CV_8UC2, cv::Scalar::all(1))); }, {"2 channels"});
}

// ------------------------------------------------------------------ readGray

TEST(ReadGray, ColourAndGrayPng) {
  TempDir dir;
  cv::Mat bgr(2, 2, CV_8UC3);
  bgr.at<cv::Vec3b>(0, 0) = {0, 0, 255};
  bgr.at<cv::Vec3b>(0, 1) = {0, 255, 0};
  bgr.at<cv::Vec3b>(1, 0) = {255, 0, 0};
  bgr.at<cv::Vec3b>(1, 1) = {10, 20, 30};
  ASSERT_TRUE(cv::imwrite(dir / "c.png", bgr));
  const cv::Mat g = sgm::readGray(dir / "c.png");
  ASSERT_EQ(g.type(), CV_8UC1);
  EXPECT_EQ(g.at<uint8_t>(0, 0), 77);
  EXPECT_EQ(g.at<uint8_t>(0, 1), 149);
  EXPECT_EQ(g.at<uint8_t>(1, 0), 29);
  EXPECT_EQ(g.at<uint8_t>(1, 1), 22);

  const cv::Mat gray = (cv::Mat_<uint8_t>(2, 3) << 0, 50, 100, 150, 200, 255);
  ASSERT_TRUE(cv::imwrite(dir / "g.png", gray));
  const cv::Mat g2 = sgm::readGray(dir / "g.png");
  ASSERT_EQ(g2.type(), CV_8UC1);
  EXPECT_EQ(cv::countNonZero(g2 != gray), 0);
}

TEST(ReadGray, MissingFile) {
  TempDir dir;
  const std::string p = dir / "nope.png";
  expectError([&] { sgm::readGray(p); }, {p, "no such file"});
}

TEST(ReadGray, EmptyFile) {
  TempDir dir;
  writeText(dir / "empty.png", "");
  expectError([&] { sgm::readGray(dir / "empty.png"); }, {"empty.png", "empty"});
}

TEST(ReadGray, NonImageFile) {
  TempDir dir;
  writeText(dir / "text.png", "this is not an image\n");
  expectError([&] { sgm::readGray(dir / "text.png"); }, {"text.png", "not a readable image"});
}

TEST(ReadGray, TruncatedPng) {
  TempDir dir;
  cv::Mat img(64, 64, CV_8UC3);
  cv::randu(img, 0, 255);
  std::vector<uchar> buf;
  ASSERT_TRUE(cv::imencode(".png", img, buf));
  writeText(dir / "cut.png", std::string(buf.begin(), buf.begin() + 100));
  expectError([&] { sgm::readGray(dir / "cut.png"); }, {"cut.png"});
}

TEST(ReadGray, DirectoryIsNotAnImage) {
  TempDir dir;
  fs::create_directory(dir / "sub.png");
  expectError([&] { sgm::readGray(dir / "sub.png"); }, {"sub.png"});
}

TEST(ReadGray, SixteenBitImage) {
  TempDir dir;
  ASSERT_TRUE(cv::imwrite(dir / "d16.png", cv::Mat(10, 10, CV_16UC1, cv::Scalar(1000))));
  expectError([&] { sgm::readGray(dir / "d16.png"); }, {"d16.png", "16-bit"});
  ASSERT_TRUE(cv::imwrite(dir / "c16.png", cv::Mat(10, 10, CV_16UC3, cv::Scalar::all(1000))));
  expectError([&] { sgm::readGray(dir / "c16.png"); }, {"c16.png", "16-bit"});
}

TEST(ReadGray, FourChannelImage) {
  TempDir dir;
  ASSERT_TRUE(cv::imwrite(dir / "rgba.png", cv::Mat(10, 10, CV_8UC4, cv::Scalar(1, 2, 3, 4))));
  expectError([&] { sgm::readGray(dir / "rgba.png"); }, {"rgba.png", "4 channels"});
}

TEST(ReadGray, SixteenBitMessageSaysEightBitIsRequired) {
  TempDir dir;
  ASSERT_TRUE(cv::imwrite(dir / "d16.png", cv::Mat(10, 10, CV_16UC1, cv::Scalar(1000))));
  expectError([&] { sgm::readGray(dir / "d16.png"); }, {"'" + (dir / "d16.png") + "': 16-bit samples", "8-bit"});
  ASSERT_TRUE(cv::imwrite(dir / "f.tiff", cv::Mat(10, 10, CV_32FC1, cv::Scalar(0.5))));
  expectError([&] { sgm::readGray(dir / "f.tiff"); }, {"f.tiff", "32-bit float", "8-bit"});
}

TEST(ReadImage, KeepsGrayAndColourAsDecoded) {
  TempDir dir;
  const cv::Mat colour = sgm::test::texture(7, 5, 1, CV_8UC3), gray = sgm::test::texture(7, 5, 2);
  ASSERT_TRUE(cv::imwrite(dir / "c.png", colour));
  ASSERT_TRUE(cv::imwrite(dir / "g.pgm", gray));
  const cv::Mat c = sgm::readImage(dir / "c.png"), g = sgm::readImage(dir / "g.pgm");
  ASSERT_EQ(c.type(), CV_8UC3);
  ASSERT_EQ(g.type(), CV_8UC1);
  EXPECT_EQ(cv::norm(c, colour, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(g, gray, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(sgm::readGray(dir / "c.png"), sgm::toGray(colour), cv::NORM_INF), 0);
}

TEST(ReadImage, FifoAndDeviceAreNotRegularFiles) {
  // Opening a FIFO for reading would block: rejected before any open.
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "pipe.png").c_str(), 0600), 0);
  expectError([&] { sgm::readImage(dir / "pipe.png"); }, {"pipe.png", "not a regular file"});
  expectError([] { sgm::readImage("/dev/zero"); }, {"/dev/zero", "not a regular file"});
}

TEST(ReadImage, HeaderAnnouncingTooLargeAnImage) {
  // Checked from the header, before a decoder allocates the pixels.
  TempDir dir;
  const cv::Mat img = sgm::test::texture(40, 30, 3, CV_8UC3);
  sgm::test::writeBytes(dir / "a.png", sgm::test::withAnnouncedSize(sgm::test::encodeImage(".png", img), 20000, 10));
  sgm::test::writeBytes(dir / "b.jpg", sgm::test::withAnnouncedSize(sgm::test::encodeImage(".jpg", img), 5000, 5000));
  sgm::test::writeBytes(dir / "c.pgm", "P5\n# comment\n100000 3\n255\nabc");
  std::string bmp = sgm::test::encodeImage(".bmp", img);
  bmp[22] = char(0x30), bmp[23] = char(0x75);  // height 30000 (little endian)
  sgm::test::writeBytes(dir / "d.bmp", bmp);
  expectError([&] { sgm::readImage(dir / "a.png"); }, {"a.png", "20000x10: too large"});
  expectError([&] { sgm::readImage(dir / "b.jpg"); }, {"b.jpg", "5000x5000: too large"});
  expectError([&] { sgm::readImage(dir / "c.pgm"); }, {"c.pgm", "100000x3: too large"});
  expectError([&] { sgm::readImage(dir / "d.bmp"); }, {"d.bmp", "40x30000: too large"});
  expectError([&] { sgm::readSingleChannel(dir / "a.png"); }, {"a.png", "too large"});
  // At the limits themselves the header check passes (the decoder then fails on the short data).
  sgm::test::writeBytes(dir / "e.png", sgm::test::withAnnouncedSize(sgm::test::encodeImage(".png", img), 4096, 4096));
  expectError([&] { sgm::readImage(dir / "e.png"); }, {"e.png", "cannot decode"});
}

TEST(ReadImage, JpegCutInsideTheScanIsTruncated) {
  // libjpeg decodes it with a warning and made-up pixels; the I/O layer refuses it.
  TempDir dir;
  const std::string jpeg = sgm::test::encodeImage(".jpg", sgm::test::texture(64, 48, 4, CV_8UC3));
  sgm::test::writeBytes(dir / "whole.jpg", jpeg);
  sgm::test::writeBytes(dir / "cut.jpg", jpeg.substr(0, jpeg.size() * 2 / 3));
  EXPECT_EQ(sgm::readImage(dir / "whole.jpg").size(), cv::Size(64, 48));
  expectError([&] { sgm::readImage(dir / "cut.jpg"); }, {"'" + (dir / "cut.jpg") + "': truncated image data"});
}

TEST(ReadImage, OnlyOneOrThreeChannelsOfEightBits) {
  TempDir dir;
  ASSERT_TRUE(cv::imwrite(dir / "rgba.png", sgm::test::texture(6, 6, 5, CV_8UC4)));
  ASSERT_TRUE(cv::imwrite(dir / "c16.png", sgm::test::texture(6, 6, 5, CV_16UC3)));
  expectError([&] { sgm::readImage(dir / "rgba.png"); }, {"rgba.png", "4 channels", "3-channel colour required"});
  expectError([&] { sgm::readImage(dir / "c16.png"); }, {"c16.png", "16-bit"});
}

TEST(ReadSingleChannel, AcceptsEightAndSixteenBitRejectsColour) {
  TempDir dir;
  const cv::Mat m16(3, 4, CV_16UC1, cv::Scalar(1234));
  ASSERT_TRUE(cv::imwrite(dir / "m16.png", m16));
  const cv::Mat r16 = sgm::readSingleChannel(dir / "m16.png");
  ASSERT_EQ(r16.type(), CV_16UC1);
  EXPECT_EQ(r16.at<uint16_t>(2, 3), 1234);
  const cv::Mat m8(3, 4, CV_8UC1, cv::Scalar(77));
  ASSERT_TRUE(cv::imwrite(dir / "m8.png", m8));
  EXPECT_EQ(sgm::readSingleChannel(dir / "m8.png").type(), CV_8UC1);
  ASSERT_TRUE(cv::imwrite(dir / "c.png", cv::Mat(3, 4, CV_8UC3, cv::Scalar::all(9))));
  expectError([&] { sgm::readSingleChannel(dir / "c.png"); }, {"c.png"});
  expectError([&] { sgm::readSingleChannel(dir / "none.png"); }, {"none.png"});
}

// ------------------------------------------------------------------ encodings

sgm::DisparityMap map2x3(std::initializer_list<int> disp, std::initializer_list<int> valid) {
  sgm::DisparityMap m{cv::Mat(2, 3, CV_16UC1), cv::Mat(2, 3, CV_8UC1)};
  auto d = disp.begin();
  auto v = valid.begin();
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) {
      m.disp.at<uint16_t>(y, x) = uint16_t(*d++);
      m.valid.at<uint8_t>(y, x) = uint8_t(*v++);
    }
  return m;
}

TEST(EncodeDisparity16, TimesTwoFiftySixInvalidZeroValidZeroIsOne) {
  // disp in 1/16 px: 16 = 1 px -> 256; 37 = 2.3125 px -> 592; 4088 = 255.5 px -> 65408.
  const sgm::DisparityMap m = map2x3({16, 0, 37, 0, 4088, 100}, {1, 1, 1, 0, 1, 0});
  const cv::Mat e = sgm::encodeDisparity16(m);
  ASSERT_EQ(e.type(), CV_16UC1);
  EXPECT_EQ(e.at<uint16_t>(0, 0), 256);
  EXPECT_EQ(e.at<uint16_t>(0, 1), 1);  // valid d = 0
  EXPECT_EQ(e.at<uint16_t>(0, 2), 592);
  EXPECT_EQ(e.at<uint16_t>(1, 0), 0);  // invalid d = 0
  EXPECT_EQ(e.at<uint16_t>(1, 1), 65408);
  EXPECT_EQ(e.at<uint16_t>(1, 2), 0);  // invalid d = 100
}

TEST(EncodeDisparity8, PaperScaling) {
  // D = 64: R = 16 * 63 = 1008; v = (disp * 255 + 504) / 1008.
  const sgm::DisparityMap m = map2x3({1008, 0, 512, 1008, 8, 16}, {1, 1, 1, 0, 1, 1});
  const cv::Mat e = sgm::encodeDisparity8(m, 64);
  ASSERT_EQ(e.type(), CV_8UC1);
  EXPECT_EQ(e.at<uint8_t>(0, 0), 255);  // d = 63
  EXPECT_EQ(e.at<uint8_t>(0, 1), 0);    // d = 0
  EXPECT_EQ(e.at<uint8_t>(0, 2), 130);  // 32/63 * 255 = 129.5 -> 130
  EXPECT_EQ(e.at<uint8_t>(1, 0), 0);    // invalid
  EXPECT_EQ(e.at<uint8_t>(1, 1), 2);    // 0.5/63 * 255 = 2.02
  EXPECT_EQ(e.at<uint8_t>(1, 2), 4);    // 1/63 * 255 = 4.05
  // D = 2: R = 16; 8 -> (2040 + 8) / 16 = 128.
  const cv::Mat e2 = sgm::encodeDisparity8(map2x3({16, 8, 0, 0, 0, 0}, {1, 1, 1, 1, 1, 1}), 2);
  EXPECT_EQ(e2.at<uint8_t>(0, 0), 255);
  EXPECT_EQ(e2.at<uint8_t>(0, 1), 128);
}

TEST(EncodeDisparityColor, InvalidIsBlackValidZeroIsNot) {
  const sgm::DisparityMap m = map2x3({0, 0, 1008, 0, 0, 0}, {0, 1, 1, 0, 0, 0});
  const cv::Mat c = sgm::encodeDisparityColor(m, 64);
  ASSERT_EQ(c.type(), CV_8UC3);
  EXPECT_EQ(c.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0));
  EXPECT_NE(c.at<cv::Vec3b>(0, 1), cv::Vec3b(0, 0, 0));
  EXPECT_NE(c.at<cv::Vec3b>(0, 2), cv::Vec3b(0, 0, 0));
}

// ------------------------------------------------------------------ writePng

TEST(WritePng, RoundTripLeavesOnlyTheFile) {
  TempDir dir;
  cv::Mat img(5, 7, CV_16UC1);
  cv::randu(img, 0, 65535);
  sgm::writePng(dir / "out.png", img);
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"out.png"}));
  const cv::Mat back = cv::imread(dir / "out.png", cv::IMREAD_UNCHANGED);
  ASSERT_EQ(back.type(), CV_16UC1);
  EXPECT_EQ(cv::countNonZero(back != img), 0);
  // Overwriting an existing file works and still leaves nothing else behind.
  sgm::writePng(dir / "out.png", cv::Mat(2, 2, CV_8UC1, cv::Scalar(3)));
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"out.png"}));
  EXPECT_EQ(cv::imread(dir / "out.png", cv::IMREAD_UNCHANGED).type(), CV_8UC1);
}

TEST(WritePng, NonExistentDirectoryThrowsAndLeavesNothing) {
  TempDir dir;
  const std::string p = dir / "missing/out.png";
  expectError([&] { sgm::writePng(p, cv::Mat(4, 4, CV_8UC1, cv::Scalar(1))); }, {p});
  EXPECT_TRUE(dir.entries().empty());
}

TEST(WriteFiles, AllOrNothingWithTextAndImages) {
  TempDir dir;
  fs::create_directory(dir / "blocked.json");
  const std::string png = sgm::encodePng(cv::Mat(3, 3, CV_8UC1, cv::Scalar(7)), dir / "a.png");
  expectError(
      [&] {
        sgm::writeFiles({{dir / "a.png", png}, {dir / "b.txt", "text"}, {dir / "blocked.json", "{}"}});
      },
      {"blocked.json"});
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"blocked.json"}));
  sgm::writeFiles({{dir / "a.png", png}, {dir / "b.txt", "text"}});
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"a.png", "b.txt", "blocked.json"}));
  EXPECT_EQ(cv::imread(dir / "a.png", cv::IMREAD_UNCHANGED).at<uint8_t>(2, 2), 7);
  expectError([&] { sgm::encodePng(cv::Mat(), dir / "empty.png"); }, {"empty.png"});
}

TEST(CheckOutputDirectory, ExistingOrCreatableOnly) {
  TempDir dir;
  sgm::checkOutputDirectory(dir.path);
  sgm::checkOutputDirectory(dir / "new/deeper");
  EXPECT_TRUE(dir.entries().empty());  // creates nothing
  std::ofstream(dir / "file") << "x";
  expectError([&] { sgm::checkOutputDirectory(dir / "file"); }, {"file", "is not a directory"});
  expectError([&] { sgm::checkOutputDirectory(dir / "file/sub"); }, {"file/sub", "is not a directory"});
  expectError([] { sgm::checkOutputDirectory(""); }, {"empty output directory"});
  if (::geteuid() != 0) {  // root writes anywhere
    fs::create_directory(dir / "ro");
    fs::permissions(dir / "ro", fs::perms::owner_read | fs::perms::owner_exec);
    expectError([&] { sgm::checkOutputDirectory(dir / "ro/out"); }, {"not writable"});
  }
}

TEST(WritePng, TargetIsADirectoryThrowsAndLeavesNoTemporary) {
  // The encoder succeeds (temporary file next to the target) but the rename
  // onto a directory fails: the temporary must be removed.
  TempDir dir;
  fs::create_directory(dir / "taken.png");
  expectError([&] { sgm::writePng(dir / "taken.png", cv::Mat(4, 4, CV_8UC1, cv::Scalar(1))); }, {"taken.png"});
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"taken.png"}));
  EXPECT_TRUE(fs::is_directory(dir / "taken.png"));
  EXPECT_TRUE(fs::is_empty(dir / "taken.png"));
}

}  // namespace

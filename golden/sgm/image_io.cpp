// SPDX-License-Identifier: Apache-2.0
#include "sgm/image_io.hpp"

#include "sgm/params.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <fcntl.h>
#include <unistd.h>

namespace sgm {

namespace {

namespace fs = std::filesystem;

// Redirects stderr into a temporary file while it lives, so that the image
// libraries' own diagnostics (libpng, libjpeg, OpenCV) stay off the terminal:
// the tools report every failure in one line of their own. text() returns what
// the libraries wrote, for the checks that depend on it.
class CapturedStderr {
 public:
  CapturedStderr() : capture_(std::tmpfile()) {
    std::fflush(stderr);
    saved_ = ::dup(STDERR_FILENO);
    const int target = capture_ ? ::fileno(capture_) : ::open("/dev/null", O_WRONLY);
    if (target >= 0) ::dup2(target, STDERR_FILENO);
    if (!capture_ && target >= 0) ::close(target);
  }
  ~CapturedStderr() {
    restore();
    if (capture_) std::fclose(capture_);
  }
  CapturedStderr(const CapturedStderr&) = delete;
  CapturedStderr& operator=(const CapturedStderr&) = delete;

  std::string text() {
    restore();
    if (!capture_) return {};
    std::string out;
    std::rewind(capture_);
    char buf[512];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, capture_)) > 0 && out.size() < 4096;) out.append(buf, n);
    return out;
  }

 private:
  void restore() {
    std::fflush(stderr);
    if (saved_ >= 0) ::dup2(saved_, STDERR_FILENO), ::close(saved_), saved_ = -1;
  }
  std::FILE* capture_;
  int saved_ = -1;
};

uint32_t bigEndian(const std::string& b, size_t at, int bytes) {
  uint32_t v = 0;
  for (int i = 0; i < bytes; ++i) v = v << 8 | uint8_t(b[at + i]);
  return v;
}
uint32_t littleEndian(const std::string& b, size_t at, int bytes) {
  uint32_t v = 0;
  for (int i = bytes - 1; i >= 0; --i) v = v << 8 | uint8_t(b[at + i]);
  return v;
}

// Width and height a PNG, JPEG, BMP, Sun raster, PNM, PAM or PFM header announces (before any
// decoding allocates them); nullopt for other formats or unreadable headers
// (the decoder then judges the file).
std::optional<std::pair<long, long>> announcedSize(const std::string& b) {
  const size_t n = b.size();
  if (n >= 24 && b.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0 && b.compare(12, 4, "IHDR") == 0)
    return std::make_pair(long(bigEndian(b, 16, 4)), long(bigEndian(b, 20, 4)));
  if (n >= 26 && b[0] == 'B' && b[1] == 'M') {
    const int32_t w = int32_t(littleEndian(b, 18, 4)), h = int32_t(littleEndian(b, 22, 4));
    return std::make_pair(std::labs(long(w)), std::labs(long(h)));
  }
  if (n >= 4 && uint8_t(b[0]) == 0xff && uint8_t(b[1]) == 0xd8) {  // JPEG: walk the markers up to a SOFn
    for (size_t at = 2; at + 4 <= n;) {
      if (uint8_t(b[at]) != 0xff) return std::nullopt;
      const int marker = uint8_t(b[at + 1]);
      if (marker == 0xff) {
        ++at;
        continue;
      }  // fill byte
      if (marker == 0x01 || (marker >= 0xd0 && marker <= 0xd8)) {
        at += 2;
        continue;
      }  // no length
      const bool frame = marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc;
      if (frame && at + 9 <= n) return std::make_pair(long(bigEndian(b, at + 7, 2)), long(bigEndian(b, at + 5, 2)));
      if (marker == 0xda || marker == 0xd9) return std::nullopt;  // scan or end before a frame header
      at += 2 + bigEndian(b, at + 2, 2);
    }
    return std::nullopt;
  }
  if (n >= 12 && bigEndian(b, 0, 4) == 0x59a66a95u)  // Sun raster
    return std::make_pair(long(bigEndian(b, 4, 4)), long(bigEndian(b, 8, 4)));
  if (n >= 3 && b[0] == 'P' && b[1] == '7') {  // PAM: "WIDTH w" and "HEIGHT h" lines
    const auto field = [&](const std::string& name) {
      const size_t at = b.find("\n" + name, 0);
      return at == std::string::npos || at > 4096 ? -1L : std::strtol(b.c_str() + at + 1 + name.size(), nullptr, 10);
    };
    const long w = field("WIDTH"), h = field("HEIGHT");
    if (w >= 0 && h >= 0) return std::make_pair(w, h);
    return std::nullopt;
  }
  if (n >= 3 && b[0] == 'P' && std::strchr("123456fF", b[1])) {  // PNM, PFM: "P5 <w> <h> ..." with # comments
    long values[2] = {0, 0};
    size_t at = 2;
    for (long& v : values) {
      while (at < n && (std::isspace(uint8_t(b[at])) || b[at] == '#')) {
        if (b[at] == '#')
          while (at < n && b[at] != '\n') ++at;
        else
          ++at;
      }
      if (at >= n || !std::isdigit(uint8_t(b[at]))) return std::nullopt;
      for (; at < n && std::isdigit(uint8_t(b[at])); ++at) v = std::min(v * 10 + (b[at] - '0'), 1L << 40);
    }
    return std::make_pair(values[0], values[1]);
  }
  return std::nullopt;
}

// A JPEG whose data ends before its EOI marker. Entropy-coded data never holds
// FF D9 (an FF there is followed by 00 or a restart marker), so the first FF D9
// after the first scan header is the end of the image. OpenCV's in-memory
// decoder pads such data silently with made-up pixels.
bool jpegWithoutEnd(const std::string& b) {
  if (b.size() < 4 || uint8_t(b[0]) != 0xff || uint8_t(b[1]) != 0xd8) return false;
  for (size_t at = 2; at + 4 <= b.size();) {
    if (uint8_t(b[at]) != 0xff) return false;  // broken marker structure: the decoder judges
    const int marker = uint8_t(b[at + 1]);
    if (marker == 0xff) {
      ++at;
      continue;
    }
    if (marker == 0x01 || (marker >= 0xd0 && marker <= 0xd8)) {
      at += 2;
      continue;
    }
    if (marker == 0xd9) return false;
    if (marker == 0xda) return b.find("\xff\xd9", at + 2) == std::string::npos;
    at += 2 + bigEndian(b, at + 2, 2);
  }
  return true;  // cut inside the headers
}

void checkImageSize(const std::string& path, long w, long h) {
  if (w > kMaxImageSide || h > kMaxImageSide || w * h > kMaxImagePixels)
    throw Error("image '" + path + "' is " + std::to_string(w) + "x" + std::to_string(h) + ": too large (at most " +
                std::to_string(kMaxImageSide) + " px a side and " + std::to_string(kMaxImagePixels) + " pixels)");
}

std::string readBytes(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) throw Error("cannot open '" + path + "': no such file or not readable");
  if (fs::is_directory(status)) throw Error("cannot read '" + path + "': is a directory, not an image file");
  if (!fs::is_regular_file(status)) throw Error("cannot read '" + path + "': not a regular file");
  const auto size = fs::file_size(path, ec);
  if (ec) throw Error("cannot read '" + path + "': " + ec.message());
  if (size == 0) throw Error("cannot read '" + path + "': file is empty");
  if (size > uintmax_t(kMaxImageFileBytes))
    throw Error("cannot read '" + path + "': file of " + std::to_string(size) +
                " bytes is too large for an image (at most " + std::to_string(kMaxImageFileBytes) + ")");
  std::ifstream in(path, std::ios::binary);
  std::string bytes(size_t(size), '\0');
  if (!in || !in.read(bytes.data(), std::streamsize(bytes.size())))
    throw Error("cannot open '" + path + "': no such file or not readable");
  return bytes;
}

std::string describeDepth(int depth) {
  switch (depth) {
    case CV_8U: return "8-bit";
    case CV_8S: return "signed 8-bit";
    case CV_16U: return "16-bit";
    case CV_16S: return "signed 16-bit";
    case CV_32S: return "32-bit integer";
    case CV_32F: return "32-bit float";
    case CV_64F: return "64-bit float";
    default: return "unsupported";
  }
}

// Decodes a file as stored (IMREAD_UNCHANGED) after the file and size checks.
cv::Mat decode(const std::string& path) {
  const std::string bytes = readBytes(path);
  if (const auto size = announcedSize(bytes)) checkImageSize(path, size->first, size->second);
  cv::Mat image;
  std::string diagnostics;
  {
    CapturedStderr captured;
    try {
      image = cv::imdecode(cv::Mat(1, int(bytes.size()), CV_8UC1, const_cast<char*>(bytes.data())),
                           cv::IMREAD_UNCHANGED);
    } catch (const cv::Exception&) {
      image.release();
    }
    diagnostics = captured.text();
  }
  if (image.empty()) throw Error("cannot decode '" + path + "': not a readable image file");
  // libjpeg decodes a cut or damaged stream with made-up pixels (and a warning for damage).
  if (jpegWithoutEnd(bytes) || diagnostics.find("Premature end of JPEG") != std::string::npos)
    throw Error("cannot decode '" + path + "': truncated image data");
  if (diagnostics.find("Corrupt JPEG data") != std::string::npos)
    throw Error("cannot decode '" + path + "': corrupt image data");
  checkImageSize(path, image.cols, image.rows);
  return image;
}

}  // namespace

cv::Mat toGray(const cv::Mat& image) {
  if (image.depth() != CV_8U) throw Error("unsupported image depth (8-bit gray or colour required)");
  if (image.channels() == 1) return image.clone();
  if (image.channels() != 3)
    throw Error("unsupported image with " + std::to_string(image.channels()) +
                " channels (8-bit gray or 3-channel colour required)");
  cv::Mat gray(image.rows, image.cols, CV_8UC1);
  for (int y = 0; y < image.rows; ++y) {
    const cv::Vec3b* src = image.ptr<cv::Vec3b>(y);
    uint8_t* dst = gray.ptr<uint8_t>(y);
    for (int x = 0; x < image.cols; ++x) {
      const int b = src[x][0], g = src[x][1], r = src[x][2];
      dst[x] = static_cast<uint8_t>((77 * r + 150 * g + 29 * b + 128) >> 8);
    }
  }
  return gray;
}

cv::Mat readImage(const std::string& path) {
  cv::Mat image = decode(path);
  if (image.depth() != CV_8U)
    throw Error("unsupported image '" + path + "': " + describeDepth(image.depth()) +
                " samples (8-bit gray or colour required)");
  if (image.channels() != 1 && image.channels() != 3)
    throw Error("unsupported image '" + path + "': " + std::to_string(image.channels()) +
                " channels (8-bit gray or 3-channel colour required)");
  return image;
}

cv::Mat readGray(const std::string& path) { return toGray(readImage(path)); }

cv::Mat readSingleChannel(const std::string& path) {
  const cv::Mat image = decode(path);
  if (image.channels() != 1 || (image.depth() != CV_8U && image.depth() != CV_16U))
    throw Error("unsupported image '" + path + "': " + std::to_string(image.channels()) + " channel(s) of " +
                describeDepth(image.depth()) + " samples (one 8- or 16-bit channel required)");
  return image;
}

std::string encodePng(const cv::Mat& image, const std::string& path) {
  std::vector<uchar> buf;
  bool ok = false;
  try {
    const CapturedStderr quiet;
    ok = !image.empty() && cv::imencode(".png", image, buf);
  } catch (const cv::Exception&) {
    ok = false;
  }
  if (!ok) throw Error("cannot write '" + path + "': image cannot be encoded as PNG");
  return std::string(buf.begin(), buf.end());
}

void writeFiles(const std::vector<OutputFile>& files) {
  // Every file is written to a temporary name first; only when all of them
  // are written are they renamed, so a failure leaves none of them behind.
  std::vector<std::string> temporaries;
  const auto removeTemporaries = [&] {
    for (const std::string& t : temporaries) std::remove(t.c_str());
  };
  for (const OutputFile& file : files) {
    const std::string tmp = file.path + ".tmp" + std::to_string(::getpid());
    temporaries.push_back(tmp);
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(file.bytes.data(), std::streamsize(file.bytes.size()));
    out.close();
    if (!out) {
      removeTemporaries();
      throw Error("cannot write '" + file.path + "'");
    }
  }
  for (size_t i = 0; i < files.size(); ++i)
    if (std::rename(temporaries[i].c_str(), files[i].path.c_str()) != 0) {
      for (size_t j = 0; j < i; ++j) std::remove(files[j].path.c_str());
      removeTemporaries();
      throw Error("cannot write '" + files[i].path + "'");
    }
}

void writePngs(const std::vector<std::pair<std::string, cv::Mat>>& files) {
  std::vector<OutputFile> encoded;
  for (const auto& [path, image] : files) encoded.push_back({path, encodePng(image, path)});
  writeFiles(encoded);
}

void writePng(const std::string& path, const cv::Mat& image) { writePngs({{path, image}}); }

void checkOutputDirectory(const std::string& dir) {
  if (dir.empty()) throw Error("empty output directory name");
  std::error_code ec;
  fs::path existing = fs::absolute(dir, ec);
  while (!existing.empty() && !fs::exists(existing, ec) && existing != existing.parent_path())
    existing = existing.parent_path();
  if (!fs::is_directory(existing, ec))
    throw Error("cannot create output directory '" + dir + "': '" + existing.string() + "' is not a directory");
  if (::access(existing.c_str(), W_OK | X_OK) != 0)
    throw Error("cannot create output directory '" + dir + "': '" + existing.string() + "' is not writable");
}

cv::Mat encodeDisparity16(const DisparityMap& map) {
  cv::Mat out(map.disp.size(), CV_16UC1);
  constexpr int kShift = 8 - kSubpixelBits;
  for (int y = 0; y < out.rows; ++y)
    for (int x = 0; x < out.cols; ++x) {
      const int d = map.disp.at<uint16_t>(y, x);
      uint16_t v = 0;
      if (map.valid.at<uint8_t>(y, x)) v = d == 0 ? 1 : static_cast<uint16_t>(d << kShift);
      out.at<uint16_t>(y, x) = v;
    }
  return out;
}

cv::Mat encodeDisparity8(const DisparityMap& map, int disparities) {
  if (disparities < kMinDisparities) throw Error("encodeDisparity8 needs D >= " + std::to_string(kMinDisparities));
  cv::Mat out(map.disp.size(), CV_8UC1);
  const int range = (disparities - 1) * kSubpixelOne;
  for (int y = 0; y < out.rows; ++y)
    for (int x = 0; x < out.cols; ++x) {
      const int d = map.disp.at<uint16_t>(y, x);
      int v = map.valid.at<uint8_t>(y, x) ? (d * 255 + range / 2) / range : 0;
      out.at<uint8_t>(y, x) = static_cast<uint8_t>(std::min(v, 255));
    }
  return out;
}

cv::Mat colorizeDisparity(const cv::Mat& dispFloat, float maxDisparity) {
  cv::Mat scaled(dispFloat.size(), CV_8UC1);
  for (int y = 0; y < scaled.rows; ++y)
    for (int x = 0; x < scaled.cols; ++x) {
      const float d = dispFloat.at<float>(y, x);
      scaled.at<uint8_t>(y, x) = static_cast<uint8_t>(std::clamp(d / maxDisparity * 255.f, 0.f, 255.f));
    }
  cv::Mat color;
  cv::applyColorMap(scaled, color, cv::COLORMAP_JET);
  color.setTo(cv::Scalar::all(0), dispFloat <= 0);
  return color;
}

cv::Mat encodeDisparityColor(const DisparityMap& map, int disparities) {
  cv::Mat f(map.disp.size(), CV_32FC1);
  for (int y = 0; y < f.rows; ++y)
    for (int x = 0; x < f.cols; ++x)
      // valid d = 0 is shown as a tiny positive value so it keeps its colour.
      f.at<float>(y, x) = map.valid.at<uint8_t>(y, x)
                              ? std::max(map.disp.at<uint16_t>(y, x) / float(kSubpixelOne), 1e-3f)
                              : 0.f;
  return colorizeDisparity(f, float(disparities - 1));
}

}  // namespace sgm

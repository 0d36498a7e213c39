#include "sgm/image_io.hpp"

#include "sgm/params.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cstdio>
#include <fstream>
#include <fcntl.h>
#include <unistd.h>

namespace sgm {

namespace {

// Keeps the image libraries' own diagnostics (libpng, libjpeg, OpenCV) off
// stderr while it lives: the tools report every failure in one line of their own.
class QuietStderr {
 public:
  QuietStderr() : saved_(::dup(STDERR_FILENO)) {
    const int devNull = ::open("/dev/null", O_WRONLY);
    if (devNull >= 0) ::dup2(devNull, STDERR_FILENO), ::close(devNull);
  }
  ~QuietStderr() {
    if (saved_ >= 0) ::dup2(saved_, STDERR_FILENO), ::close(saved_);
  }
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

 private:
  int saved_;
};

cv::Mat decode(const std::string& path) {
  std::ifstream probe(path, std::ios::binary);
  if (!probe) throw Error("cannot open '" + path + "': no such file or not readable");
  probe.seekg(0, std::ios::end);
  if (probe.tellg() <= 0) throw Error("cannot read '" + path + "': file is empty");
  cv::Mat image;
  try {
    const QuietStderr quiet;
    image = cv::imread(path, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception&) {
    image.release();
  }
  if (image.empty()) throw Error("cannot decode '" + path + "': not a readable image file");
  return image;
}

}  // namespace

cv::Mat toGray(const cv::Mat& image) {
  if (image.depth() != CV_8U)
    throw Error("unsupported image depth (expected 8-bit gray or colour)");
  if (image.channels() == 1) return image.clone();
  if (image.channels() != 3)
    throw Error("unsupported image with " + std::to_string(image.channels()) +
                " channels (expected 8-bit gray or colour)");
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

cv::Mat readGray(const std::string& path) {
  const cv::Mat image = decode(path);
  if (image.depth() != CV_8U)
    throw Error("unsupported image '" + path + "': " + std::to_string(8 * image.elemSize1()) +
                "-bit samples (expected 8-bit gray or colour)");
  if (image.channels() != 1 && image.channels() != 3)
    throw Error("unsupported image '" + path + "': " + std::to_string(image.channels()) +
                " channels (expected 8-bit gray or colour)");
  return toGray(image);
}

cv::Mat readSingleChannel(const std::string& path) {
  const cv::Mat image = decode(path);
  if (image.channels() != 1 || (image.depth() != CV_8U && image.depth() != CV_16U))
    throw Error("unsupported image '" + path + "' (expected one 8- or 16-bit channel)");
  return image;
}

void writePngs(const std::vector<std::pair<std::string, cv::Mat>>& files) {
  // Every file is encoded to a temporary name first; only when all of them
  // are written are they renamed, so a failure leaves none of them behind.
  std::vector<std::string> temporaries;
  auto removeTemporaries = [&] {
    for (const std::string& t : temporaries) std::remove(t.c_str());
  };
  for (const auto& [path, image] : files) {
    const std::string tmp = path + ".tmp" + std::to_string(::getpid()) + ".png";
    bool ok = false;
    try {
      const QuietStderr quiet;
      ok = cv::imwrite(tmp, image);
    } catch (const cv::Exception&) {
      ok = false;
    }
    temporaries.push_back(tmp);
    if (!ok) {
      removeTemporaries();
      throw Error("cannot write '" + path + "'");
    }
  }
  for (size_t i = 0; i < files.size(); ++i)
    if (std::rename(temporaries[i].c_str(), files[i].first.c_str()) != 0) {
      for (size_t j = 0; j < i; ++j) std::remove(files[j].first.c_str());
      removeTemporaries();
      throw Error("cannot write '" + files[i].first + "'");
    }
}

void writePng(const std::string& path, const cv::Mat& image) { writePngs({{path, image}}); }

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

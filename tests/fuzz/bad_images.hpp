// SPDX-License-Identifier: Apache-2.0
// Test images and the bad files made from them: synthetic textures and stereo
// pairs, encoded files, headers that announce another size. Shared by the CLI
// tests, the image I/O tests and the fuzz driver (its seeds).
#pragma once

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <cstdint>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace sgm::test {

inline cv::Mat texture(int w, int h, unsigned seed, int type = CV_8UC1) {
  std::mt19937 rng(seed);
  cv::Mat img(h, w, type);
  const size_t samples = img.total() * img.channels();
  if (img.depth() == CV_8U)
    for (size_t i = 0; i < samples; ++i) img.ptr<uint8_t>()[i] = uint8_t(rng());
  else if (img.depth() == CV_16U)
    for (size_t i = 0; i < samples; ++i) img.ptr<uint16_t>()[i] = uint16_t(rng());
  else
    throw std::invalid_argument("texture: 8- or 16-bit types only");
  return img;
}

// right(x) = left(x + shift): a pair with constant disparity `shift`.
inline std::pair<cv::Mat, cv::Mat> shiftedPair(int w, int h, int shift, unsigned seed, int type = CV_8UC1) {
  const cv::Mat wide = texture(w + shift, h, seed, type);
  return {wide(cv::Rect(0, 0, w, h)).clone(), wide(cv::Rect(shift, 0, w, h)).clone()};
}

// The bytes of image encoded by OpenCV for the extension (".png", ".jpg", ".pgm", ".bmp", ...).
inline std::string encodeImage(const std::string& ext, const cv::Mat& image) {
  std::vector<uchar> buf;
  if (!cv::imencode(ext, image, buf)) throw std::runtime_error("cannot encode " + ext);
  return std::string(buf.begin(), buf.end());
}

inline void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + path);
}

inline uint32_t crc32(const uint8_t* data, size_t n) {
  uint32_t crc = 0xffffffffu;
  for (size_t i = 0; i < n; ++i) {
    crc ^= data[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

inline void putBigEndian(std::string& b, size_t at, uint32_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) b[at + i] = char((v >> (8 * (bytes - 1 - i))) & 0xff);
}

// A PNG or JPEG file whose header announces w x h (the PNG's IHDR CRC is
// fixed up so the decoder takes it at its word); the pixel data stays as it was.
inline std::string withAnnouncedSize(std::string bytes, uint32_t w, uint32_t h) {
  if (bytes.size() > 33 && bytes.compare(1, 3, "PNG") == 0) {
    putBigEndian(bytes, 16, w, 4);
    putBigEndian(bytes, 20, h, 4);
    putBigEndian(bytes, 29, crc32(reinterpret_cast<const uint8_t*>(bytes.data()) + 12, 17), 4);
    return bytes;
  }
  for (size_t i = 2; i + 9 < bytes.size(); ++i)
    if (uint8_t(bytes[i]) == 0xff && (uint8_t(bytes[i + 1]) == 0xc0 || uint8_t(bytes[i + 1]) == 0xc2)) {
      putBigEndian(bytes, i + 5, h, 2);
      putBigEndian(bytes, i + 7, w, 2);
      return bytes;
    }
  throw std::invalid_argument("withAnnouncedSize: not a PNG or baseline/progressive JPEG");
}

}  // namespace sgm::test

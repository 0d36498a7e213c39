// SPDX-License-Identifier: Apache-2.0
// table1.png: grouped bar chart of the Table I report, drawn with OpenCV.
#pragma once

#include "report_pool.hpp"
#include "report_table.hpp"

#include <opencv2/core.hpp>

#include <string>

namespace sgm::eval {

// Text for the report pictures (Hershey simplex, anti-aliased), baseline at org;
// centred: centred horizontally on x, baseline at y.
void drawText(cv::Mat& img, const std::string& s, cv::Point org, double scale, const cv::Scalar& color,
              int thickness = 1);
void drawCentredText(cv::Mat& img, const std::string& s, int x, int y, double scale, const cv::Scalar& color,
                     int thickness = 1);

// One group per scene, one solid bar per method (err_nonocc, %), the paper's
// figure as a hatched bar right after ours where the paper has one; value
// labels on the bars, axes, legend. BGR 8-bit.
cv::Mat table1Chart(const TableReport& report, const std::string& title = "SGM golden model vs Yao & Cheng, Table I");

// pool.png: one group per scene (sorted by set), bars of the strict figure
// (Middlebury bad-delta nonocc, KITTI D1): ours, today's defaults (when compared),
// OpenCV strict and OpenCV valid only (hatched); value labels, axes, legend,
// set names under the scenes. BGR 8-bit.
cv::Mat poolChart(const PoolReport& report, const std::string& title = "SGM golden model on the scene pool");

}  // namespace sgm::eval

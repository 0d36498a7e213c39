// table1.png: grouped bar chart of the Table I report, drawn with OpenCV.
#pragma once

#include "report_table.hpp"

#include <opencv2/core.hpp>

namespace sgm::eval {

// One group per scene, one solid bar per method (err_nonocc, %), the paper's
// figure as a hatched bar right after ours where the paper has one; value
// labels on the bars, axes, legend. BGR 8-bit.
cv::Mat table1Chart(const TableReport& report,
                    const std::string& title = "SGM golden model vs Yao & Cheng, Table I");

}  // namespace sgm::eval

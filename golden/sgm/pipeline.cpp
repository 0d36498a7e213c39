// SPDX-License-Identifier: Apache-2.0
#include "sgm/pipeline.hpp"

#include "sgm/aggregate.hpp"
#include "sgm/census.hpp"
#include "sgm/cost.hpp"
#include "sgm/disparity.hpp"

namespace sgm {

void checkInput(const cv::Mat& gl, const cv::Mat& gr, const Params& params) {
  params.validate();
  if (gl.type() != CV_8UC1 || gr.type() != CV_8UC1) throw Error("internal: pipeline needs 8-bit gray images");
  if (gl.size() != gr.size())
    throw Error("left/right size mismatch: " + std::to_string(gl.cols) + "x" + std::to_string(gl.rows) + " vs " +
                std::to_string(gr.cols) + "x" + std::to_string(gr.rows));
  if (gl.cols < kMinFrameSide || gl.rows < kMinFrameSide)
    throw Error("image " + std::to_string(gl.cols) + "x" + std::to_string(gl.rows) + " is smaller than the " +
                std::to_string(kMinFrameSide) + "x" + std::to_string(kMinFrameSide) + " minimum frame");
}

PipelineStages runPipelineStages(const cv::Mat& gl, const cv::Mat& gr, const Params& params) {
  checkInput(gl, gr, params);
  PipelineStages st;
  st.cost = computeCost(gl, gr, params.mode, params.disparities, params.census);
  if (params.adWeight)
    for (int y = 0; y < gl.rows; ++y)
      addAdTerm(gl, gr, y, 0, gl.cols, params.disparities, params.adWeight, params.adCap, st.cost.at(0, y));
  st.aggregated = aggregateCost(st.cost, gl, params.p1, params.p2, params.p2Mode, params.weights,
                                params.rightPathWeight, params.mgm, params.rightPathBlock, params.p1PathPercent.data(),
                                params.edgeReset, params.lrStoreBits);
  st.selected = selectDisparity(st.aggregated, params, &st.confidence);
  st.filled = params.fill ? fillHoles(st.selected) : st.selected;
  st.snapped = params.snap ? snapEdges(st.filled, gl, params.snapEdge) : st.filled;
  st.result = params.median ? median5x5(st.snapped, gl, params.medianGate) : st.snapped;
  return st;
}

DisparityMap runPipeline(const cv::Mat& gl, const cv::Mat& gr, const Params& params, cv::Mat* confidence) {
  checkInput(gl, gr, params);
  const int w = gl.cols, h = gl.rows, nd = params.disparities;
  // Hardware modes stream C from the census images row by row; the software
  // modes read rows of a precomputed volume.
  std::vector<Census> censusLeft, censusRight;
  CostVolume volume;
  CostRowFn costRow;
  if (isHardwareMode(params.mode)) {
    censusLeft = censusTransform(gl, params.census);
    censusRight = censusTransform(gr, params.census);
    costRow = [&](int y, int x0, int x1, uint8_t* row) {
      censusCostRow(params.mode, params.census, &censusLeft[size_t(y) * w], &censusRight[size_t(y) * w], w, x0, x1, nd,
                    row);
      if (params.adWeight) addAdTerm(gl, gr, y, x0, x1, nd, params.adWeight, params.adCap, row);
    };
  } else {
    volume = computeCost(gl, gr, params.mode, nd, params.census);
    costRow = [&](int y, int x0, int x1, uint8_t* row) {
      std::copy(volume.at(x0, y), volume.at(x0, y) + size_t(x1 - x0) * nd, row + size_t(x0) * nd);
    };
  }
  DisparityMap selected{cv::Mat(h, w, CV_16UC1), cv::Mat(h, w, CV_8UC1)};
  if (confidence) confidence->create(h, w, CV_8UC1);
  RowSelector selectors[2] = {RowSelector(w, nd, params), RowSelector(w, nd, params)};  // one per worker
  aggregateRows(
      w, h, nd, gl, params.p1, params.p2, params.p2Mode, params.weights, costRow,
      [&](int worker, int y, const uint16_t* sum) {
        selectors[worker].select(sum, selected.disp.ptr<uint16_t>(y), selected.valid.ptr<uint8_t>(y),
                                 confidence ? confidence->ptr<uint8_t>(y) : nullptr);
      },
      params.rightPathWeight, params.mgm, params.rightPathBlock, params.p1PathPercent.data(), params.edgeReset,
      params.lrStoreBits);
  const DisparityMap filled = params.fill ? fillHoles(selected) : selected;
  const DisparityMap snapped = params.snap ? snapEdges(filled, gl, params.snapEdge) : filled;
  return params.median ? median5x5(snapped, gl, params.medianGate) : snapped;
}

}  // namespace sgm
